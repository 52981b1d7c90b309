/*
 * update.c - per-object acceleration structure updates (see update.h).
 */
#include "scene/update.h"

#include <rt/rt.h>
#include <string.h>

#include "accel/build_more.h"
#include "accel/build_parallel.h"
#include "accel/refit.h"
#include "accel/restructure.h"
#include "base/alloc.h"
#include "base/timer.h"

/* Rebuild once refitting has made the SAH cost this many times the cost
 * right after the last build.  Lauterbach et al.'s RT-DEFORM rebuild
 * heuristic (paper 000 sec. 2 names it, without a value); 1.5 is our
 * starting point, to be tuned against the benchmark animations. */
#define REBUILD_HEURISTIC_THRESHOLD 1.5

/* Objects below this many triangles are refit and built on the calling
 * thread: waking the pool costs more than the work. */
#define PARALLEL_UPDATE_MIN_TRIANGLES 20000u

unsigned scene_object_strategy(const struct scene_object *object, unsigned default_strategy)
{
    return object->strategy_hint != RT_AUTOMATIC ? object->strategy_hint : default_strategy;
}

static struct aabb *triangle_boxes(const struct scene_mesh *mesh)
{
    struct aabb *boxes = rt_calloc(mesh->tri_count, sizeof(*boxes));
    if (!boxes)
        return NULL;
    for (uint32_t j = 0; j < mesh->tri_count; j++) {
        boxes[j] = aabb_empty();
        for (int k = 0; k < 3; k++)
            aabb_grow_point(&boxes[j], &mesh->positions[3 * mesh->indices[3 * j + k]]);
    }
    return boxes;
}

static struct rt_pool *pool_for(const struct scene_mesh *mesh, struct rt_pool *pool)
{
    return mesh->tri_count >= PARALLEL_UPDATE_MIN_TRIANGLES ? pool : NULL;
}

/* A fresh structure with `builder` (BVH_BUILDER_* or median); NULL on
 * allocation failure. */
static struct scene_accel *build_fresh(const struct scene_object *object,
                                       const struct bvh_build_params *params, int median,
                                       struct rt_pool *pool)
{
    const struct scene_mesh *mesh = &object->mesh;
    double start = rt_now_ms();
    struct scene_accel *accel = rt_calloc(1, sizeof(*accel));
    struct aabb *boxes = triangle_boxes(mesh);
    if (!accel || !boxes)
        goto fail;
    int status;
    if (median)
        status = accel_build_median(&accel->bvh, boxes, mesh->tri_count, params);
    else if (pool_for(mesh, pool) && params->builder == BVH_BUILDER_BINNED_SAH)
        status = accel_build_parallel(&accel->bvh, boxes, mesh->tri_count, params, pool);
    else
        status = accel_build(&accel->bvh, boxes, mesh->tri_count, params);
    if (status)
        goto fail;
    accel->tri = accel_gather_triangles(&accel->bvh, mesh->positions, mesh->indices);
    if (!accel->tri)
        goto fail;
    rt_free(boxes);
    accel->serial = object->serial;
    accel->topology = object->topology_serial;
    accel->sah_cost = accel_sah_cost(&accel->bvh, params->c_trav, params->c_isect);
    accel->built_sah_cost = accel->sah_cost;
    accel->build_ms = rt_now_ms() - start;
    return accel;
fail:
    rt_free(boxes);
    scene_accel_release(accel);
    return NULL;
}

/* Replaces the object's structure by a fresh build; 0 or -1. */
static int rebuild(struct scene_object *object, const struct bvh_build_params *params,
                   int median, struct rt_pool *pool)
{
    struct scene_accel *fresh = build_fresh(object, params, median, pool);
    if (!fresh)
        return -1;
    struct scene_accel *old = object->accel;
    __atomic_store_n(&object->accel, fresh, __ATOMIC_RELEASE);
    scene_accel_release(old);
    object->rebuilds++;
    return 0;
}

/* Refits the boxes and the leaf-ordered triangles in place, in one pass
 * over the leaves (paper 000 sec. 6 interleaves the two the same way).
 * Allocates nothing, so it cannot fail. */
static void refit(struct scene_object *object, const struct bvh_build_params *params,
                  struct rt_pool *pool)
{
    const struct scene_mesh *mesh = &object->mesh;
    struct scene_accel *accel = object->accel;
    accel_refit_mesh(&accel->bvh, accel->tri, mesh->positions, mesh->indices,
                     pool_for(mesh, pool));
    accel->sah_cost = accel_sah_cost(&accel->bvh, params->c_trav, params->c_isect);
    object->refits++;
}

static int restructure(struct scene_object *object, const struct bvh_build_params *params,
                       const struct accel_restructure_params *measured)
{
    const struct scene_mesh *mesh = &object->mesh;
    struct scene_accel *accel = object->accel;
    struct aabb *boxes = triangle_boxes(mesh);
    if (!boxes)
        return -1;
    if (!accel->restructure_state_ready) {
        accel_restructure_state_init(&accel->restructure_state);
        accel->restructure_state_ready = 1;
    }
    struct accel_restructure_params rp = *measured;
    rp.rays_per_frame = object->expected_rays;
    struct accel_restructure_stats stats;
    int status =
        accel_restructure(&accel->bvh, boxes, &accel->restructure_state, &rp, &stats);
    rt_free(boxes);
    if (status)
        return -1;
    /* Restructuring moves primitives between leaves: regather. */
    float *tri = accel_gather_triangles(&accel->bvh, mesh->positions, mesh->indices);
    if (!tri)
        return -1;
    rt_free(accel->tri);
    accel->tri = tri;
    accel->sah_cost = accel_sah_cost(&accel->bvh, params->c_trav, params->c_isect);
    object->refits++;
    return 0;
}


/*
 * Paper 000 sec. 6: swap in a build that has landed, refit whatever
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
        refit(object, params, config->pool);
        if (object->accel->sah_cost > REBUILD_HEURISTIC_THRESHOLD * object->accel->built_sah_cost)
            return rebuild(object, params, 0, config->pool);
        return 0;
    }
    struct scene_accel *landed = scene_async_collect(async, object);
    if (landed && landed->topology == object->topology_serial) {
        struct scene_accel *old = object->accel;
        __atomic_store_n(&object->accel, landed, __ATOMIC_RELEASE);
        scene_accel_release(old);
        object->rebuilds++;
    } else {
        scene_accel_release(landed); /* built for an old connectivity */
    }
    /* A landed tree was built from vertices one or more frames old. */
    if (object->accel->serial != object->serial)
        refit(object, params, config->pool);
    /* Failing to queue only delays the next rebuild. */
    scene_async_request(async, object);
    return 0;
}

/*
 * RT_AUTOMATIC: the choice paper 000 (sec. 7.5) leaves open, made from
 * measured costs.  Refit first (it is needed to know how far the tree has
 * degraded and costs O(n)); then rebuild once the traversal time lost to
 * the degraded tree since the last build has added up to what a rebuild
 * costs:
 *
 *   sum over frames since the last build of
 *       expected_rays * time_per_test * (SAH_refit - SAH_fresh)  >  build_ms
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
 * last frame (render time over node and triangle tests); build_ms is the
 * object's last build.  A mildly deforming object (cloth) never pays for
 * a rebuild and stays refit-only; an exploding one rebuilds as soon as
 * its rays make the rebuild worth it.  Restructuring and asynchronous
 * rebuilds stay explicit choices: their cost depends on the K threads the
 * application sets aside, which the model cannot see.
 */
static int automatic(struct scene_object *object, const struct bvh_build_params *params,
                     const struct scene_update_config *config)
{
    refit(object, params, config->pool);
    const struct scene_accel *accel = object->accel;
    double lost_ms = object->expected_rays * config->ms_per_test *
                     (accel->sah_cost - accel->built_sah_cost);
    object->automatic_lost_ms += lost_ms > 0.0 ? lost_ms : 0.0;
    if (object->automatic_lost_ms > accel->build_ms) {
        object->last_strategy = RT_REBUILD;
        object->automatic_lost_ms = 0.0;
        return rebuild(object, params, 0, config->pool);
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
    const struct bvh_build_params *quality = config->static_params;
    struct bvh_build_params dynamic = *quality;
    dynamic.builder = BVH_BUILDER_BINNED_SAH;
    int status;
    if (!accel) {
        /* First build: the high-quality static build, lazily (paper 004
         * sec. 3), unless the object is known to be unstructured. */
        int unstructured = object->class_hint == RT_UNSTRUCTURED;
        status = rebuild(object, unstructured ? &dynamic : quality, 0,
                         unstructured ? config->pool : NULL);
        object->last_strategy = 0;
    } else if (accel->topology != object->topology_serial || object->class_hint == RT_STATIC ||
               object->class_hint == RT_AFFINE) {
        /* New connectivity, or hinted rigid: a full build, with the fast
         * builder for what changes every frame. */
        int unstructured = object->current_class == RT_UNSTRUCTURED;
        status = rebuild(object, unstructured ? &dynamic : quality, 0, config->pool);
        object->last_strategy = RT_REBUILD;
    } else {
        unsigned strategy = scene_object_strategy(object, config->default_strategy);
        object->last_strategy = strategy;
        switch (strategy) {
        case RT_REFIT:
            refit(object, &dynamic, config->pool);
            status = 0;
            break;
        case RT_REBUILD_MEDIAN:
            status = rebuild(object, &dynamic, 1, config->pool);
            break;
        case RT_REBUILD_HEURISTIC:
            refit(object, &dynamic, config->pool);
            status = 0;
            if (object->accel->sah_cost > REBUILD_HEURISTIC_THRESHOLD * object->accel->built_sah_cost)
                status = rebuild(object, &dynamic, 0, config->pool);
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
            status = rebuild(object, &dynamic, 0, config->pool);
            break;
        }
        if (status == 0)
            object->accel->serial = object->serial;
    }
    object->update_ms = rt_now_ms() - start;
    return status == 0 ? object->accel : NULL;
}
