/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene.h - a scene that exists without an API context: objects, the
 * frame's instances and top level, textures, the per-object update
 * configuration, the asynchronous builder and the scene's statistics.
 *
 * The API context (api/context.h) holds one and delegates to it after its
 * checks, as Mesa's entry points delegate to their state; an MPI worker
 * can hold one alone and apply the same calls to replay a change set.
 * Nothing here records errors: functions that can fail return a status.
 *
 * Lights and the current material are not here: lights are render state
 * (render.h) and the current material is API state that recording copies
 * into the object's mesh (recording.h), as OpenGL's current state.
 *
 * Threading: the API thread owns it; render threads reach only what a
 * render job hands them (render.h) during a frame or query.
 */
#ifndef RT_SCENE_SCENE_H
#define RT_SCENE_SCENE_H

#include <stdint.h>

#include "accel/restructure.h"
#include "base/pool.h"
#include "scene/async_build.h"
#include "scene/frame.h"
#include "scene/object.h"
#include "scene/texture.h"
#include "scene/update.h"
#include "accel/bvh_build.h"

/* What changed in the scene since the last preparation: what an MPI
 * master will broadcast and what an accumulating renderer resets on.
 * Counts for now (the names follow from the objects' change stamps). */
struct scene_changes {
    uint32_t defined;   /* objects defined for the first time */
    uint32_t redefined; /* objects given a new definition */
    uint32_t deleted;   /* objects deleted */
    uint32_t touched;   /* objects whose vertices changed (rtUpdateVertices) */
    uint32_t moved;     /* objects with an instance that moved or appeared */
    uint32_t updated;   /* acceleration structures brought up to date */
    int toplevel_rebuilt;
};

/* Work of the last preparation. */
struct scene_stats {
    uint64_t toplevel_builds;
    uint64_t object_updates;
    double toplevel_ms;
    double update_ms;
};

struct scene {
    struct bvh_build_params build_params; /* first builds, static objects */
    struct scene_objects objects;
    struct scene_frame frame;
    struct scene_textures textures;
    struct scene_async_builder async; /* thread started by the first async object */
    int build_threads;                /* K of build_threads=K */

    /* frame_number counts ended frames; classification compares change
     * stamps to it. */
    uint64_t frame_number;
    unsigned default_strategy; /* rtRenderParameteri(RT_UPDATE_STRATEGY) */
    uint64_t prepare_count;    /* preparations so far (visit stamps) */
    struct scene_update_config update_config; /* valid during a frame or query */
    struct accel_restructure_params restructure_params; /* measured on first use */
    int restructure_measured;
    uint64_t last_frame_rays; /* rays of the last frame */
    double ms_per_test;       /* traversal step time, measured per frame */
    struct scene_preempt_hook preempt; /* test hook (accel.h); fn NULL normally */

    struct scene_changes changes; /* since the last preparation */
    struct scene_stats stats;     /* of the last preparation */
};

enum scene_status {
    SCENE_OK = 0,
    SCENE_TOPLEVEL_OUT_OF_MEMORY, /* the top level could not be built */
    SCENE_UPDATE_OUT_OF_MEMORY    /* an object's structure could not be updated */
};

/* An empty scene; params are the object builder's, build_threads the K of
 * asynchronous rebuilds, toplevel_cellsplit selects the top-level rule. */
void scene_init(struct scene *scene, const struct bvh_build_params *params, int build_threads,
                int toplevel_cellsplit);
/* Cancels background builds and frees everything. */
void scene_release(struct scene *scene);

/* Swaps in a recorded definition for object (ownership of *mesh moves,
 * see scene_object_define) and notes the change. */
void scene_define_object(struct scene *scene, struct scene_object *object,
                         struct scene_mesh *mesh);
/* Drops the object, its instances and its background build; unknown
 * names are ignored. */
void scene_delete_object(struct scene *scene, uint32_t name);

/* Component c of element i of an array of float (is_double 0) or double
 * triples, elements `stride` bytes apart. */
double scene_array_component(const void *data, int is_double, size_t stride, size_t i, int c);
/* Overwrites positions (normals 0) or normals (normals 1) first ..
 * first + count - 1 of a defined object's mesh from such an array (the
 * caller checked the range and that every value is finite as a float).
 * New positions make the object's structure stale; normals are shading
 * data only. */
void scene_update_vertices(struct scene *scene, struct scene_object *object, int normals,
                           uint32_t first, uint32_t count, const void *data, int is_double,
                           size_t stride);

/*
 * Preparation before a frame or a query, in two steps so that the caller
 * can start its worker pool between them (only if the first succeeded):
 * scene_prepare_toplevel commits the frame's instances and rebuilds the
 * top level if they or their objects changed; scene_prepare_objects
 * classifies the instanced objects (Wald, Benthin and Slusallek (2003) sec. 3) and brings their
 * stale structures up to date, on pool where that pays.  default_rays is
 * the expected ray count before any frame was traced (viewport pixels).
 * Both reset scene->stats at their start (the first) and add to them.
 * scene_prepare_objects hands the change set since the last preparation
 * to *changes (may be NULL) and clears it.
 */
enum scene_status scene_prepare_toplevel(struct scene *scene);
enum scene_status scene_prepare_objects(struct scene *scene, struct rt_pool *pool,
                                        double default_rays, struct scene_changes *changes);

/* Ends a frame: the next instance starts a new list, the frame counter
 * advances, and the frame's rays and traversal steps (with the time spent
 * tracing them) calibrate the automatic strategy. */
void scene_end_frame(struct scene *scene, uint64_t rays, uint64_t tests, double trace_ms);

#endif
