/* SPDX-License-Identifier: Apache-2.0 */
/*
 * update.c - per-object acceleration structure updates (see update.h).
 */
#include "scene/update.h"

#include <rt/rt.h>
#include <string.h>

#include "base/atomic.h"
#include "base/timer.h"
#include "scene/accel.h"

/* Rebuild once refitting has made the SAH cost this many times the cost
 * right after the last build.  Lauterbach et al.'s RT-DEFORM rebuild
 * heuristic (Wald, Ize and Parker (2008) sec. 2 names it, without a value); 1.5 is our
 * starting point, to be tuned against the benchmark animations. */
#define REBUILD_HEURISTIC_THRESHOLD 1.5

/* Objects below this many triangles are refit and built on the calling
 * thread: waking the pool costs more than the work. */
#define PARALLEL_UPDATE_MIN_TRIANGLES 20000u

unsigned scene_object_strategy(const struct scene_object *object, unsigned default_strategy)
{
    return object->strategy_hint != RT_AUTOMATIC ? object->strategy_hint : default_strategy;
}

static struct rt_pool *pool_for(const struct scene_mesh *mesh, struct rt_pool *pool)
{
    return mesh->tri_count >= PARALLEL_UPDATE_MIN_TRIANGLES ? pool : NULL;
}

static struct scene_accel_geometry geometry(const struct scene_object *object)
{
    struct scene_accel_geometry g = {object->mesh.positions, object->mesh.indices,
                                     object->mesh.tri_count};
    return g;
}

/* Replaces the object's structure by a fresh build (median or, with a
 * pool worth waking, the parallel binned build); 0 or -1. */
static int rebuild(struct scene_object *object, const struct bvh_build_params *params,
                   int median, struct rt_pool *pool, const struct scene_preempt_hook *hook)
{
    enum scene_accel_builder builder = SCENE_ACCEL_SERIAL;
    if (median)
        builder = SCENE_ACCEL_MEDIAN;
    else if (pool_for(&object->mesh, pool) && params->builder == BVH_BUILDER_BINNED_SAH)
        builder = SCENE_ACCEL_PARALLEL;
    struct scene_accel_geometry g = geometry(object);
    /* The old structure is replaced and freed below, and nothing walks it
     * meanwhile (scene_object_acquire: only a structure of the object's
     * current serial is used, and this one is not): its layout's block
     * may hold the new one. */
    struct scene_accel *fresh =
        scene_accel_rebuild(&g, params, builder, pool, hook, object->accel);
    if (!fresh)
        return -1;
    fresh->serial = object->serial;
    fresh->topology = object->topology_serial;
    object->collapse_ms_total += fresh->collapse_ms;
    scene_accel_install(object, fresh);
    return 0;
}

/* 0, or -1 when the structure's first refit cannot have its
 * leaf-ordered triangles (scene_accel_refit; the structure is unchanged,
 * stale, and the next update tries again). */
static int refit(struct scene_object *object, const struct bvh_build_params *params,
                 struct rt_pool *pool)
{
    struct scene_accel_geometry g = geometry(object);
    if (scene_accel_refit(object->accel, &g, params, pool_for(&object->mesh, pool)))
        return -1;
    object->wide_refit_ms_total += object->accel->wide_refit_ms;
    object->refits++;
    return 0;
}

static int restructure(struct scene_object *object, const struct bvh_build_params *params,
                       const struct accel_restructure_params *measured)
{
    struct scene_accel_geometry g = geometry(object);
    if (scene_accel_restructure(object->accel, &g, params, measured, object->expected_rays))
        return -1;
    object->collapse_ms_total += object->accel->collapse_ms;
    object->refits++;
    return 0;
}

/* The RT-DEFORM rebuild heuristic (REBUILD_HEURISTIC_THRESHOLD): refit,
 * and rebuild once the refit tree's SAH cost has grown past the
 * threshold.  0 or -1. */
static int refit_or_rebuild(struct scene_object *object, const struct bvh_build_params *params,
                            const struct scene_update_config *config)
{
    if (refit(object, params, config->pool))
        return -1;
    if (object->accel->sah_cost > REBUILD_HEURISTIC_THRESHOLD * object->accel->built_sah_cost)
        return rebuild(object, params, 0, config->pool, config->preempt);
    return 0;
}

/*
 * Wald, Ize and Parker (2008) sec. 6: swap in a build that has landed, refit whatever
 * structure is current to the current vertices, and keep the build
 * threads busy with the newest snapshot.  Without build threads this is
 * the rebuild heuristic.
 */
static int async_rebuild(struct scene_object *object, const struct bvh_build_params *params,
                         const struct scene_update_config *config)
{
    struct scene_async_builder *async = config->async;
    if (!async || async->threads == 0) {
        object->last_strategy = RT_REBUILD_HEURISTIC;
        return refit_or_rebuild(object, params, config);
    }
    struct scene_accel *landed = scene_async_collect(async, object);
    if (landed && landed->topology == object->topology_serial) {
        scene_accel_install(object, landed);
    } else {
        scene_accel_release(landed); /* built for an old connectivity */
    }
    /* A landed tree was built from vertices one or more frames old. */
    if (object->accel->serial != object->serial && refit(object, params, config->pool))
        return -1;
    /* Failing to queue only delays the next rebuild. */
    scene_async_request(async, object);
    return 0;
}

/*
 * RT_AUTOMATIC: the choice Wald, Ize and Parker (2008) (sec. 7.5) leaves open, made from
 * measured costs.  Refit first (it is needed to know how far the tree has
 * degraded and costs O(n)); then rebuild once the traversal time lost to
 * the degraded tree since the last build has added up to what a rebuild
 * costs:
 *
 *   sum over frames since the last build of
 *       expected_rays * time_per_test * (SAH_refit - SAH_fresh)  >  build_cost
 *
 * This is the rent-or-buy rule: it never spends more than twice what the
 * best offline schedule of rebuilds would, whatever the animation, where a
 * rule comparing one frame's loss with the build cost rebuilds too late
 * (a new tree pays off over every later frame; measured by rtbench's
 * exploding mesh, docs/performance.md).
 *
 * SAH costs are in traversal steps per ray reaching the object (our SAH
 * is normalised by the root area, so a fresh build's cost after the last
 * rebuild estimates the next one's); time_per_test is measured from the
 * last frame (tracing time over node and triangle tests); build_cost is
 * the object's last build.  Both are times on the same clock,
 * rt_pool_work_ms (base/pool.h): CPU time, what ran on the pool's threads
 * counted as the share of the frame it takes.  Yoon, Curtis and Manocha
 * (2007) sec. 4.1 and Wald, Ize and Parker (2008) sec. 7.5 weigh work
 * (traversal cost against rebuild cost), not the wall clock: a build that
 * lost time slices to another process measured by the wall clock looked
 * many times dearer than it is and held back the next rebuilds for as
 * many frames, so the same animation was handled differently on a loaded
 * machine (docs/performance-log.md, "Issue 11: dynamic strategies and
 * RT_AUTOMATIC").  A mildly deforming object (cloth) never pays for
 * a rebuild and stays refit-only; an exploding one rebuilds as soon as
 * its rays make the rebuild worth it.  Restructuring and asynchronous
 * rebuilds stay explicit choices: their cost depends on the K threads the
 * application sets aside, which the model cannot see.
 */
static int automatic(struct scene_object *object, const struct bvh_build_params *params,
                     const struct scene_update_config *config)
{
    if (refit(object, params, config->pool))
        return -1;
    const struct scene_accel *accel = object->accel;
    double lost_ms = object->expected_rays * config->ms_per_test *
                     (accel->sah_cost - accel->built_sah_cost);
    object->automatic_lost_ms += lost_ms > 0.0 ? lost_ms : 0.0;
    if (object->automatic_lost_ms > accel->build_cost_ms) {
        object->last_strategy = RT_REBUILD;
        object->automatic_lost_ms = 0.0;
        return rebuild(object, params, 0, config->pool, config->preempt);
    }
    object->last_strategy = RT_REFIT;
    return 0;
}

const struct scene_accel *scene_object_update(struct scene_object *object,
                                              const struct scene_update_config *config)
{
    struct scene_accel *accel = object->accel;
    if (accel && accel->serial == object->serial)
        return accel;
    double start = rt_now_ms();
    /* The quality builds take the collapse of the object's acceleration
     * hint (rtHint(RT_ACCELERATION_HINT), recorded at rtEndObject); the
     * per-frame ones (dynamic) the greedy collapse, whose cost is a small
     * part of a build that is repeated. */
    struct bvh_build_params quality_params = *config->static_params;
    quality_params.collapse =
        object->acceleration_hint == RT_NICEST ? BVH_COLLAPSE_OPTIMAL : BVH_COLLAPSE_GREEDY;
    const struct bvh_build_params *quality = &quality_params;
    struct bvh_build_params dynamic = *config->static_params;
    dynamic.builder = BVH_BUILDER_BINNED_SAH;
    dynamic.collapse = BVH_COLLAPSE_GREEDY;
    int status;
    if (!accel) {
        /* First build: the high-quality static build, lazily (Wald, Benthin and Slusallek (2003)
         * sec. 3), unless the object is known to be unstructured. */
        int unstructured = object->class_hint == RT_UNSTRUCTURED;
        status = rebuild(object, unstructured ? &dynamic : quality, 0,
                         unstructured ? config->pool : NULL, config->preempt);
        object->last_strategy = 0;
    } else if (accel->topology != object->topology_serial || object->class_hint == RT_STATIC ||
               object->class_hint == RT_AFFINE) {
        /* New connectivity, or hinted rigid: a full build, with the fast
         * builder for what changes every frame. */
        int unstructured = object->current_class == RT_UNSTRUCTURED;
        status = rebuild(object, unstructured ? &dynamic : quality, 0, config->pool,
                         config->preempt);
        object->last_strategy = RT_REBUILD;
    } else {
        unsigned strategy = scene_object_strategy(object, config->default_strategy);
        object->last_strategy = strategy;
        switch (strategy) {
        case RT_REFIT:
            status = refit(object, &dynamic, config->pool);
            break;
        case RT_REBUILD_MEDIAN:
            status = rebuild(object, &dynamic, 1, config->pool, config->preempt);
            break;
        case RT_REBUILD_HEURISTIC:
            status = refit_or_rebuild(object, &dynamic, config);
            break;
        case RT_RESTRUCTURE:
            status = restructure(object, &dynamic, config->restructure);
            break;
        case RT_ASYNC_REBUILD:
            status = async_rebuild(object, &dynamic, config);
            break;
        case RT_AUTOMATIC:
            status = automatic(object, &dynamic, config);
            break;
        default: /* RT_REBUILD */
            status = rebuild(object, &dynamic, 0, config->pool, config->preempt);
            break;
        }
        if (status == 0)
            object->accel->serial = object->serial;
    }
    object->update_ms = rt_now_ms() - start;
    return status == 0 ? object->accel : NULL;
}

const float *scene_object_triangles(struct scene_object *object,
                                    const struct scene_accel *accel)
{
    const float *tri = rt_atomic_load_acquire(&accel->tri);
    if (tri)
        return tri;
    /* The render threads of a frame may ask together: one gathers under
     * the object's lock, the others find the array published.  accel is
     * the object's current structure (its serial is the object's), so
     * the mesh's positions are the ones it reflects, and nothing replaces
     * it during the frame (scene_object_acquire). */
    pthread_mutex_lock(&object->build_lock);
    struct scene_accel_geometry g = geometry(object);
    tri = scene_accel_triangles((struct scene_accel *)accel, &g);
    pthread_mutex_unlock(&object->build_lock);
    return tri;
}

const struct scene_accel *scene_object_acquire(struct scene_object *object,
                                               const struct scene_update_config *config,
                                               int *built_now)
{
    *built_now = 0;
    struct scene_accel *accel = rt_atomic_load_acquire(&object->accel);
    /* object->serial changes only on the API thread between frames. */
    if (accel && accel->serial == object->serial)
        return accel;
    pthread_mutex_lock(&object->build_lock);
    const struct scene_accel *current = object->accel;
    if (!current || current->serial != object->serial) {
        /* Inside a frame: no pool (it is running this very task). */
        struct scene_update_config serial_config = *config;
        serial_config.pool = NULL;
        current = scene_object_update(object, &serial_config);
        *built_now = current != NULL;
    }
    pthread_mutex_unlock(&object->build_lock);
    return current;
}
