/* SPDX-License-Identifier: Apache-2.0 */
/*
 * update.h - keeping an object's acceleration structure in step with its
 * geometry: the per-object update strategies of Wald, Ize and Parker (2008) and Yoon, Curtis and Manocha (2007).
 *
 * An object whose geometry changed (redefined with the same connectivity,
 * or rtUpdateVertices) has a stale structure.  scene_object_update brings
 * it up to date with the strategy the object's class and hints select:
 *
 *   RT_REFIT               refit the boxes bottom-up (Wald, Ize and Parker (2008) sec. 6)
 *   RT_REBUILD             binned SAH rebuild, two-stage parallel with a
 *                          pool (Wald, Ize and Parker (2008) secs. 4, 5)
 *   RT_REBUILD_MEDIAN      spatial-median (BIH-like) rebuild (Wald, Ize and Parker (2008)
 *                          table 1)
 *   RT_REBUILD_HEURISTIC   refit, rebuild once the SAH cost has grown past
 *                          REBUILD_HEURISTIC_THRESHOLD times the cost
 *                          after the last build (the RT-DEFORM rebuild
 *                          heuristic, Wald, Ize and Parker (2008) sec. 2)
 *   RT_RESTRUCTURE         selective restructuring (Yoon, Curtis and Manocha (2007))
 *   RT_ASYNC_REBUILD       refit while build threads rebuild (Wald, Ize and Parker (2008)
 *                          sec. 6; async_build.h)
 *   RT_AUTOMATIC           refit, or rebuild when the measured traversal
 *                          time it saves exceeds its measured cost
 *
 * A changed connectivity always means a full rebuild.  Objects hinted
 * RT_STATIC or RT_AFFINE are rebuilt with the high-quality static builder.
 * Every strategy gives the same hits; only time and tree quality differ.
 */
#ifndef RT_SCENE_UPDATE_H
#define RT_SCENE_UPDATE_H

#include "base/pool.h"
#include "scene/async_build.h"
#include "scene/object.h"

struct scene_update_config {
    const struct bvh_build_params *static_params; /* first builds, static objects */
    unsigned default_strategy; /* for objects without a hint; RT_AUTOMATIC allowed */
    struct rt_pool *pool;      /* parallel builds and refits; NULL = caller only */
    /* Selective restructuring's machine constants (Yoon, Curtis and Manocha (2007) sec. 6.1),
     * measured by the context the first time an object restructures. */
    const struct accel_restructure_params *restructure;
    /* Asynchronous rebuilds (Wald, Ize and Parker (2008) sec. 6); threads == 0 disables
     * them and RT_ASYNC_REBUILD then behaves as RT_REBUILD_HEURISTIC. */
    struct scene_async_builder *async;
    /* Measured time of one traversal step (node or triangle test), ms of
     * rt_pool_work_ms (CPU time as a share of the frame): the automatic
     * strategy's exchange rate between tree quality and time. */
    double ms_per_test;
    const struct scene_preempt_hook *preempt; /* test hook, NULL (accel.h) */
};

/*
 * Builds the object's structure if it has none, or updates it if stale.
 * Returns the structure, or NULL on allocation failure (the object keeps
 * a valid but stale structure, or none; the next call tries again).
 * Not thread-safe for one object: call with its build_lock held, or from
 * the API thread between frames.
 */
const struct scene_accel *scene_object_update(struct scene_object *object,
                                              const struct scene_update_config *config);

/*
 * The object's acceleration structure, built now if this is the first
 * request or brought up to date if the geometry changed since (config
 * selects builder and strategy; see update.h).  Thread-safe: the work is
 * done under the object's lock, by the first thread that needs it.
 * Returns NULL on allocation failure (the next request tries again).
 * *built_now is set to 1 when this call built or updated.
 */
const struct scene_accel *scene_object_acquire(struct scene_object *object,
                                               const struct scene_update_config *config,
                                               int *built_now);

/*
 * The leaf-ordered triangles of accel, the object's current structure
 * (from scene_object_acquire or scene_object_peek, of the object's
 * serial), gathered on first need and kept (scene_accel_triangles): what
 * a frame's binary walks read (the hit filter's, the ties walk, a table
 * without a wide walk).  Thread-safe: the gather runs under the object's
 * lock, once.  NULL on allocation failure (the structure stays usable;
 * the next call tries again).
 */
const float *scene_object_triangles(struct scene_object *object,
                                    const struct scene_accel *accel);

/* The strategy an update of this object would use now (resolving
 * RT_AUTOMATIC), for statistics. */
unsigned scene_object_strategy(const struct scene_object *object, unsigned default_strategy);

#endif
