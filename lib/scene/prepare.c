/* SPDX-License-Identifier: Apache-2.0 */
/*
 * prepare.c - getting a scene ready for a frame or query: the top level,
 * object classification (Wald, Benthin and Slusallek (2003) sec. 3), the expected-ray estimates
 * and the per-object structure updates (see scene.h).
 */
#include <rt/rt.h>
#include <math.h>
#include <string.h>

#include "base/timer.h"
#include "scene/scene.h"

/* The class of an object this frame (Wald, Benthin and Slusallek (2003) sec. 3): hints override;
 * otherwise geometry changed since its first definition in this frame
 * means unstructured, an instance moved this frame means affine, and
 * everything else is static. */
static unsigned classify(const struct scene_object *object, uint64_t frame)
{
    if (object->class_hint != RT_AUTOMATIC)
        return object->class_hint;
    if (object->changed_frame == frame && object->serial > 1)
        return RT_UNSTRUCTURED;
    if (object->moved_frame == frame)
        return RT_AFFINE;
    return RT_STATIC;
}

/* Rays expected to reach an object next frame: the last frame's rays (or
 * default_rays before the first) times the largest ratio of an instance
 * box's area to the scene box's area, the SAH's probability of a ray
 * through the scene hitting it. */
static double expected_rays(const struct scene *scene, const struct scene_object *object,
                            double default_rays)
{
    const struct scene_frame *f = &scene->frame;
    double rays = scene->last_frame_rays ? (double)scene->last_frame_rays : default_rays;
    if (!f->top_valid || f->top.node_count == 0)
        return rays;
    struct aabb root;
    memcpy(root.min, f->top.nodes[0].aabb_min, sizeof(root.min));
    memcpy(root.max, f->top.nodes[0].aabb_max, sizeof(root.max));
    double root_area = aabb_half_area(&root), best = 0.0;
    for (uint32_t i = 0; i < f->committed.count; i++) {
        if (f->committed.items[i].object != object)
            continue;
        struct aabb box = scene_instance_box(&f->committed.items[i]);
        double a = aabb_half_area(&box);
        best = a > best ? a : best;
    }
    return root_area > 0.0 ? rays * fmin(1.0, best / root_area) : rays;
}

enum scene_status scene_prepare_toplevel(struct scene *scene)
{
    memset(&scene->stats, 0, sizeof(scene->stats));
    double start = rt_now_ms();
    int built = 0;
    if (scene_frame_prepare(&scene->frame, &scene->build_params, scene->frame_number, &built))
        return SCENE_TOPLEVEL_OUT_OF_MEMORY;
    scene->stats.toplevel_builds += (uint64_t)built;
    scene->stats.toplevel_ms += rt_now_ms() - start;
    if (built)
        scene->changes.toplevel_rebuilt = 1;
    return SCENE_OK;
}

/* Classifies the scene's objects and brings the structures that exist but
 * are stale up to date, in parallel where that pays (structures never
 * built stay lazy: they are built when a ray first needs them). */
enum scene_status scene_prepare_objects(struct scene *scene, struct rt_pool *pool,
                                        double default_rays, struct scene_changes *changes)
{
    struct scene_update_config *config = &scene->update_config;
    config->static_params = &scene->build_params;
    config->default_strategy = scene->default_strategy;
    config->pool = pool;
    config->restructure = &scene->restructure_params;
    config->async = &scene->async;
    config->ms_per_test = scene->ms_per_test;
    config->preempt = scene->preempt.fn ? &scene->preempt : NULL;

    uint64_t stamp = ++scene->prepare_count;
    const struct scene_instance_list *list = &scene->frame.committed;
    int failed = 0;
    /* The objects of traced instances first (pass 0), then those only
     * rasterised this frame (scene_instance.overlay, pass 1): classified,
     * but their stale structures are left for the first ray that needs
     * them, as a structure never built is, since no ray reaches them now
     * (the rasteriser reads the mesh). */
    for (uint32_t pass = 0; pass < 2; pass++) {
        for (uint32_t i = 0; i < list->count; i++) {
            struct scene_object *object = list->items[i].object;
            if (object->visit_stamp == stamp || list->items[i].overlay != pass)
                continue;
            object->visit_stamp = stamp;
            object->current_class = classify(object, scene->frame_number);
            if (object->moved_frame == scene->frame_number)
                scene->changes.moved++;
            /* Rays are counted for the objects whose geometry has changed
             * since their definition (serial > 1, as classify) and whose
             * updates the automatic strategy decides: from its first update
             * on, every later one has the measured rays.  No render runs
             * now: plain reads and writes. */
            int automatic =
                scene_object_strategy(object, scene->default_strategy) == RT_AUTOMATIC;
            int counted = object->count_rays;
            object->count_rays = automatic && object->serial > 1;
            if (!object->accel || object->accel->serial == object->serial || pass)
                continue;
            uint64_t visits = object->ray_visits; /* since its last update */
            object->ray_visits = 0;
            /* Yoon, Curtis and Manocha (2007) sec. 4.1.1: the rays that will
             * reach the object are those that reached it in the previous
             * frame, counted; the SAH estimate (the area of its instance box
             * over the scene's) is only the fallback before any were counted.
             * For the rays of a camera inside the scene that estimate is far
             * off: on the BART museum, 0.4-2% of the primary rays against the
             * 40-75% that actually reach the animated object, so that the
             * rule of update.c saw a thirtieth of the traversal it lost and
             * rebuilt late (docs/performance-log.md). */
            object->expected_rays =
                counted ? (double)visits : expected_rays(scene, object, default_rays);
            if (scene_object_strategy(object, scene->default_strategy) == RT_RESTRUCTURE &&
                !scene->restructure_measured) {
                /* Yoon, Curtis and Manocha (2007) sec. 6.1 measures its
                 * constants at start-up; we do it when the first object
                 * needs them. */
                accel_restructure_measure_constants(&scene->restructure_params);
                scene->restructure_measured = 1;
            }
            /* Only real updates are timed: a static scene's frames report
             * exactly 0 ms of update time. */
            double start = rt_now_ms();
            if (scene_object_update(object, config)) {
                scene->stats.object_updates++;
                scene->changes.updated++;
            } else {
                failed = 1;
            }
            scene->stats.update_ms += rt_now_ms() - start;
        }
    }
    if (changes)
        *changes = scene->changes;
    memset(&scene->changes, 0, sizeof(scene->changes));
    return failed ? SCENE_UPDATE_OUT_OF_MEMORY : SCENE_OK;
}

void scene_end_frame(struct scene *scene, uint64_t rays, uint64_t tests, double trace_ms)
{
    scene_frame_end(&scene->frame);
    scene->frame_number++;
    scene->last_frame_rays = rays;
    /* The exchange rate of the automatic strategy: time per traversal
     * step, measured over the frame's tracing (updates excluded) on the
     * build costs' clock, rt_pool_work_ms (lib/api/frame.c). */
    if (tests > 10000 && trace_ms > 0.0)
        scene->ms_per_test = trace_ms / (double)tests;
}
