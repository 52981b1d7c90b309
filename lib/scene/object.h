/*
 * object.h - objects (the display lists of Tracelist) and their table.
 *
 * An object owns its committed definition (a scene_mesh) and, once a ray
 * has needed it, the acceleration structure over it.  Construction is
 * lazy (paper 004 sec. 3, "on demand"): scene_object_acquire builds the
 * BVH the first time any thread asks, under the object's lock, and
 * publishes it with a release store so later readers take no lock.
 *
 * Threading: the table and definitions change only on the API thread,
 * between frames; during a frame render threads only call
 * scene_object_acquire.
 */
#ifndef RT_SCENE_OBJECT_H
#define RT_SCENE_OBJECT_H

#include <pthread.h>
#include <stdint.h>

#include "accel/bvh.h"
#include "scene/mesh.h"

struct scene_accel {
    struct bvh bvh;
    float *tri; /* leaf-ordered vertices, accel_gather_triangles */
    double sah_cost;
    double build_ms;
};

struct scene_object {
    uint32_t name;
    int defined;            /* has a committed definition (rtIsObject) */
    struct scene_mesh mesh; /* the committed definition */
    uint32_t serial;        /* bumped by every rtEndObject of this name */
    pthread_mutex_t build_lock;
    struct scene_accel *accel; /* NULL until built; read with acquire loads */
};

struct scene_objects {
    struct scene_object **slots; /* open addressing on name, NULL = free */
    uint32_t capacity;           /* power of two */
    uint32_t used;               /* occupied slots (defined or reserved) */
    uint32_t defined;            /* objects with a definition */
    uint32_t next_name;          /* rtGenObjects search start */
};

void scene_objects_init(struct scene_objects *table);
/* Frees every object, its mesh and acceleration structure. */
void scene_objects_release(struct scene_objects *table);

/* The entry for name, or NULL.  Reserved-but-undefined names have an
 * entry with defined == 0. */
struct scene_object *scene_objects_lookup(const struct scene_objects *table, uint32_t name);

/* The entry for name, created (undefined) if absent; NULL on allocation
 * failure. */
struct scene_object *scene_objects_get_or_create(struct scene_objects *table, uint32_t name);

/* Writes n unused names, reserving each.  Returns 0, or -1 on allocation
 * failure having reserved nothing. */
int scene_objects_generate(struct scene_objects *table, uint32_t n, uint32_t *names);

/* Removes and frees the entry for name; no-op if absent. */
void scene_objects_remove(struct scene_objects *table, uint32_t name);

/* Replaces the object's definition by *mesh (ownership moves; *mesh is
 * zeroed) and drops the old acceleration structure. */
void scene_object_define(struct scene_objects *table, struct scene_object *object,
                         struct scene_mesh *mesh);

/*
 * The object's acceleration structure, built now if this is the first
 * request (params select the builder).  Thread-safe.  Returns NULL on
 * allocation failure (the next request tries again).  *built_now is set
 * to 1 when this call performed the build.
 */
const struct scene_accel *scene_object_acquire(struct scene_object *object,
                                               const struct bvh_build_params *params,
                                               int *built_now);

/* The acceleration structure if already built, else NULL (no build). */
const struct scene_accel *scene_object_peek(const struct scene_object *object);

#endif
