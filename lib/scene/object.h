/* SPDX-License-Identifier: Apache-2.0 */
/*
 * object.h - objects (the display lists of Tracelist) and their table.
 *
 * An object owns its committed definition (a scene_mesh) and, once a ray
 * has needed it, the acceleration structure over it.  Construction is
 * lazy (Wald, Benthin and Slusallek (2003) sec. 3, "on demand"): scene_object_acquire (update.h) builds the
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

#include "base/name_table.h"
#include "scene/accel.h"
#include "scene/mesh.h"

struct scene_object {
    uint32_t name;
    int defined;            /* has a committed definition (rtIsObject) */
    struct scene_mesh mesh; /* the committed definition */
    uint32_t serial;          /* bumped by every change of the geometry */
    uint32_t topology_serial; /* bumped when the triangles' connectivity changes */
    uint64_t changed_frame;   /* frame of the last geometry change */
    uint64_t moved_frame;     /* frame in which an instance of it last moved */
    uint64_t visit_stamp;     /* scene preparation that last classified it */
    struct scene_async_job *async_job; /* asynchronous rebuild in flight (async_build.h) */
    /* Rays expected to reach it per frame: the last frame's rays times the
     * SAH probability of hitting its largest instance box (MacDonald and
     * Booth 1990); Yoon, Curtis and Manocha (2007) sec. 4.1.1 scales its benefits by this. */
    double expected_rays;
    /* RT_AUTOMATIC: traversal time lost to refitting since the last build
     * (update.c). */
    double automatic_lost_ms;
    /* RT_AUTOMATIC: the rays that reached inside the object since its
     * last update (the render threads count them per thread and add them
     * here, trace/scene_traverse.h), counted only while count_rays is
     * set, i.e. for objects whose updates the automatic strategy decides;
     * the next update takes it as expected_rays (Yoon, Curtis and Manocha
     * (2007) sec. 4.1.1: the previous frame's rays intersecting the
     * root).  Kept apart from the fields every ray reads. */
    char ray_visits_pad_before[64];
    uint64_t ray_visits;
    char ray_visits_pad_after[64];
    int count_rays;

    /* Hints (rtObjectParameteri); RT_AUTOMATIC when none was given. */
    unsigned class_hint;
    unsigned strategy_hint;
    /* rtHint(RT_ACCELERATION_HINT)'s mode when the definition was ended
     * (rtEndObject), for it and its segments: RT_NICEST makes the quality
     * builds take the optimal collapse (update.c); 0 (an object made by
     * the scene itself) or another mode the greedy one. */
    unsigned acceleration_hint;
    /* What the runtime did, for rtGetObject* (Wald, Benthin and Slusallek (2003) sec. 3 classes,
     * Wald, Ize and Parker (2008) and Yoon, Curtis and Manocha (2007) strategies). */
    unsigned current_class;
    unsigned last_strategy;
    double update_ms;
    uint64_t rebuilds;
    uint64_t refits;
    /* Wide-layout work of the updates so far, ms (scene_accel's
     * collapse_ms and wide_refit_ms summed; builds that landed from the
     * asynchronous builder are not counted, they ran off the frame). */
    double collapse_ms_total;
    double wide_refit_ms_total;
    pthread_mutex_t build_lock;
    struct scene_accel *accel; /* NULL until built; read with acquire loads */

    /* A display list's operations (recording.h), replayed at call time;
     * NULL when the list is its own geometry alone (op_count 0).  Segment
     * 0 is this object's mesh, segment i > 0 the hidden object
     * segments[i - 1], which is never in the table. */
    struct scene_list_op *ops;
    uint32_t op_count;
    struct scene_object **segments;
    uint32_t segment_count;
};

struct scene_async_job;

struct scene_objects {
    struct name_table table; /* name -> struct scene_object (defined or reserved) */
    uint32_t defined;        /* objects with a definition */
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
 * failure having reserved and written nothing. */
int scene_objects_generate(struct scene_objects *table, uint32_t n, uint32_t *names);

/* Removes and frees the entry for name; no-op if absent. */
void scene_objects_remove(struct scene_objects *table, uint32_t name);

/* A hidden object (segments of lists, immediate-mode geometry) outside
 * any table, and its release.  NULL on allocation failure. */
struct scene_object *scene_object_create_hidden(void);
void scene_object_free(struct scene_object *object);

/* Replaces the object's definition by *mesh (ownership moves; *mesh is
 * zeroed) in frame `frame`.  When the new definition has the same
 * connectivity (same vertex count and triangle indices) the acceleration
 * structure is kept, stale, so an update strategy can refit it; otherwise
 * it is dropped.  table may be NULL (hidden objects). */
void scene_object_define(struct scene_objects *table, struct scene_object *object,
                         struct scene_mesh *mesh, uint64_t frame);

/* Marks the geometry changed in place (rtUpdateVertices) in `frame`:
 * recomputes the bounds, keeps the topology. */
void scene_object_touch(struct scene_object *object, uint64_t frame);

/* The acceleration structure if already built, else NULL (no build). */
const struct scene_accel *scene_object_peek(const struct scene_object *object);

/* The value of a per-object query (rtGetObject*; pname one of the
 * RT_OBJECT_* names or RT_UPDATE_STRATEGY, already validated) as
 * doubles; returns how many were written (1, or 6 for the bounds, 0 for
 * an unknown pname). */
int scene_object_values(const struct scene_object *object, unsigned pname, double v[6]);

#endif
