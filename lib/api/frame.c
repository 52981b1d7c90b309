/*
 * frame.c - rtViewport, rtClearColor, rtRenderFrame, rtFinish,
 * rtReadPixels, and the scene preparation shared with the ray queries.
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "base/alloc.h"
#include "base/timer.h"

void rtViewport(RTint x, RTint y, RTsizei width, RTsizei height)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtViewport"))
        return;
    if (x < 0 || y < 0 || width < 0 || height < 0 || width > RT_MAX_VIEWPORT ||
        height > RT_MAX_VIEWPORT || x > RT_MAX_VIEWPORT - width ||
        y > RT_MAX_VIEWPORT - height) {
        rt_error(ctx, RT_INVALID_VALUE, "rtViewport(x=%d, y=%d, width=%d, height=%d)", x, y,
                 width, height);
        return;
    }
    int *vp = ctx->render.viewport;
    vp[0] = x;
    vp[1] = y;
    vp[2] = width;
    vp[3] = height;
}

void rtClearColor(RTfloat r, RTfloat g, RTfloat b, RTfloat a)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtClearColor"))
        return;
    const float c[4] = {r, g, b, a};
    if (!rt_check_finite(ctx, "rtClearColor", c, 4))
        return;
    for (int i = 0; i < 4; i++)
        ctx->render.clear_color[i] = fminf(fmaxf(c[i], 0.0f), 1.0f);
}

/* The class of an object this frame (paper 004 sec. 3): hints override;
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
 * one per viewport pixel before the first) times the largest ratio of an
 * instance box's area to the scene box's area, the SAH's probability of
 * a ray through the scene hitting it. */
static double expected_rays(const struct rt_context *ctx, const struct scene_object *object)
{
    const struct scene_frame *f = &ctx->frame;
    double rays = ctx->last_frame_rays
                      ? (double)ctx->last_frame_rays
                      : (double)ctx->render.viewport[2] * (double)ctx->render.viewport[3];
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

/* Classifies the scene's objects and brings the structures that exist but
 * are stale up to date, in parallel where that pays (structures never
 * built stay lazy: they are built when a ray first needs them).  Returns
 * 0, or -1 after recording RT_OUT_OF_MEMORY. */
static int update_objects(struct rt_context *ctx, const char *caller)
{
    uint64_t stamp = ++ctx->prepare_count;
    const struct scene_instance_list *list = &ctx->frame.committed;
    int failed = 0;
    for (uint32_t i = 0; i < list->count; i++) {
        struct scene_object *object = list->items[i].object;
        if (object->visit_stamp == stamp)
            continue;
        object->visit_stamp = stamp;
        object->current_class = classify(object, ctx->frame_number);
        if (!object->accel || object->accel->serial == object->serial)
            continue;
        object->expected_rays = expected_rays(ctx, object);
        if (scene_object_strategy(object, ctx->default_strategy) == RT_RESTRUCTURE &&
            !ctx->restructure_measured) {
            /* Paper 001 sec. 6.1 measures its constants at start-up; we
             * do it when the first object needs them. */
            accel_restructure_measure_constants(&ctx->restructure_params);
            ctx->restructure_measured = 1;
        }
        /* Only real updates are timed: a static scene's frames report
         * exactly 0 ms of update time. */
        double start = rt_now_ms();
        if (scene_object_update(object, &ctx->update_config))
            ctx->stats.object_updates++;
        else
            failed = 1;
        ctx->stats.update_ms += rt_now_ms() - start;
    }
    if (failed) {
        rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory updating an object", caller);
        return -1;
    }
    return 0;
}

int rt_prepare_scene(struct rt_context *ctx, const char *caller)
{
    double start = rt_now_ms();
    int built = 0;
    if (scene_frame_prepare(&ctx->frame, &ctx->build_params, ctx->frame_number, &built)) {
        rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory building the top level", caller);
        return -1;
    }
    ctx->stats.toplevel_builds += (uint64_t)built;
    ctx->stats.toplevel_ms += rt_now_ms() - start;
    ctx->update_config.static_params = &ctx->build_params;
    ctx->update_config.default_strategy = ctx->default_strategy;
    ctx->update_config.pool = rt_context_pool(ctx);
    ctx->update_config.restructure = &ctx->restructure_params;
    ctx->update_config.async = &ctx->async;
    ctx->update_config.ms_per_test = ctx->ms_per_test;
    return update_objects(ctx, caller);
}

void rt_render_job(struct rt_context *ctx, struct render_job *job)
{
    job->state = &ctx->render;
    job->frame = &ctx->frame;
    job->update = &ctx->update_config;
    job->textures = &ctx->textures;
    job->pool = rt_context_pool(ctx);
    job->threads = rt_pool_threads(job->pool);
    job->kernels = ctx->kernels;
}

void rtRenderFrame(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_object(ctx, "rtRenderFrame"))
        return;
    double start = rt_now_ms();
    memset(&ctx->stats, 0, sizeof(ctx->stats));
    if (rt_prepare_scene(ctx, "rtRenderFrame"))
        return;
    const int *vp = ctx->render.viewport;
    int fb_width = vp[0] + vp[2], fb_height = vp[1] + vp[3];
    memcpy(ctx->render.projection, ctx->projection.m[ctx->projection.depth - 1],
           sizeof(ctx->render.projection));
    struct render_job job;
    rt_render_job(ctx, &job);
    float *fb = NULL;
    if (render_frame(&job, fb_width, fb_height, &fb, &ctx->stats)) {
        rt_error(ctx, RT_OUT_OF_MEMORY, "rtRenderFrame: out of memory");
        return;
    }
    rt_free(ctx->render.framebuffer);
    ctx->render.framebuffer = fb;
    ctx->render.fb_width = fb_width;
    ctx->render.fb_height = fb_height;
    scene_frame_end(&ctx->frame);
    ctx->frame_number++;
    ctx->last_frame_rays = ctx->stats.rays;
    /* The exchange rate of the automatic strategy: time per traversal
     * step, measured over the frame's tracing (updates excluded). */
    uint64_t tests = ctx->stats.node_tests + ctx->stats.triangle_tests;
    double trace_ms = ctx->stats.render_ms - ctx->stats.update_ms - ctx->stats.toplevel_ms;
    if (tests > 10000 && trace_ms > 0.0)
        ctx->ms_per_test = trace_ms / (double)tests;
    ctx->stats.render_ms = rt_now_ms() - start;
}

void rtFinish(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_object(ctx, "rtFinish"))
        return;
    memset(&ctx->stats, 0, sizeof(ctx->stats));
    rt_prepare_scene(ctx, "rtFinish");
}

void rtReadPixels(RTint x, RTint y, RTsizei width, RTsizei height, RTenum format, RTenum type,
                  void *pixels)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtReadPixels"))
        return;
    if (format != RT_RGBA) {
        rt_error(ctx, RT_INVALID_ENUM, "rtReadPixels(format=0x%x)", format);
        return;
    }
    if (type != RT_UNSIGNED_BYTE && type != RT_FLOAT) {
        rt_error(ctx, RT_INVALID_ENUM, "rtReadPixels(type=0x%x)", type);
        return;
    }
    const struct render_state *r = &ctx->render;
    if (!pixels || x < 0 || y < 0 || width < 0 || height < 0 || x > r->fb_width - width ||
        y > r->fb_height - height) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "rtReadPixels(x=%d, y=%d, width=%d, height=%d, pixels=%p): framebuffer is "
                 "%dx%d",
                 x, y, width, height, pixels, r->fb_width, r->fb_height);
        return;
    }
    for (int row = 0; row < height; row++) {
        const float *src = &r->framebuffer[4 * ((size_t)(y + row) * r->fb_width + x)];
        size_t n = 4 * (size_t)width;
        size_t offset = (size_t)row * n;
        if (type == RT_FLOAT) {
            memcpy((float *)pixels + offset, src, n * sizeof(float));
            continue;
        }
        unsigned char *dst = (unsigned char *)pixels + offset;
        for (size_t i = 0; i < n; i++) {
            float c = fminf(fmaxf(src[i], 0.0f), 1.0f);
            dst[i] = (unsigned char)lrintf(c * 255.0f);
        }
    }
}
