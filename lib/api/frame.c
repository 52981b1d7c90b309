/* SPDX-License-Identifier: Apache-2.0 */
/*
 * frame.c - rtViewport, rtClearColor, rtClear, rtRenderFrame, rtFinish,
 * rtFlush, rtReadPixels, and the error reporting around the scene
 * preparation (scene/prepare.c) shared with the ray queries.
 *
 * GL frames: a GL program starts each frame with glClear and never asks
 * for a render; it reads the image with glReadPixels or ends with
 * glFinish / glFlush / a buffer swap.  rtClear starts a new frame
 * description (as rtBeginFrame) and, from then on, a frame described and
 * not rendered yet is rendered by rtFinish, rtFlush and rtReadPixels.  A
 * context in which rtClear was never called keeps rtFinish's meaning of
 * preparing the scene without rendering, and rtReadPixels reads the last
 * rtRenderFrame.  rtReadPixels writes its rows as the pack state of
 * rtPixelStorei lays them out (RT_PACK_ALIGNMENT 4 by default, which
 * RGBA rows always meet).
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "base/timer.h"

void rtViewport(RTint x, RTint y, RTsizei width, RTsizei height)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtViewport"))
        return;
    if (x < 0 || y < 0 || width < 0 || height < 0 || width > API_MAX_VIEWPORT ||
        height > API_MAX_VIEWPORT || x > API_MAX_VIEWPORT - width ||
        y > API_MAX_VIEWPORT - height) {
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

/* The scene's work of the preparation goes into the frame's statistics. */
static void add_scene_stats(struct render_stats *stats, const struct scene_stats *s)
{
    stats->toplevel_builds += s->toplevel_builds;
    stats->toplevel_ms += s->toplevel_ms;
    stats->object_updates += s->object_updates;
    stats->update_ms += s->update_ms;
}

int rt_prepare_scene(struct rt_context *ctx, const char *caller)
{
    struct scene *scene = &ctx->scene;
    /* The frame is traced through the viewport current now and, outside
     * GL frames, the projection current now (render_frame_now).  A GL
     * frame's projection is chosen from what was drawn, the projection of
     * most depth-tested triangles (scene_frame_prepare: a HUD whose
     * gluOrtho2D was loaded without a push is still current at the swap);
     * what was drawn under others (a heads-up display, an inset viewport)
     * is rasterised as GL draws it instead (render/raster.h). */
    struct scene_frame *frame = &scene->frame;
    frame->overlay_enabled = ctx->gl_frames;
    memcpy(frame->trace_projection, ctx->projection.m[ctx->projection.depth - 1],
           sizeof(frame->trace_projection));
    for (int i = 0; i < 4; i++)
        frame->trace_viewport[i] = ctx->render.viewport[i];
    if (scene_prepare_toplevel(scene) != SCENE_OK) {
        rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory building the top level", caller);
        return -1;
    }
    /* Before the first frame, one ray per viewport pixel. */
    double pixels = (double)ctx->render.viewport[2] * (double)ctx->render.viewport[3];
    enum scene_status status =
        scene_prepare_objects(scene, rt_context_pool(ctx), pixels, NULL);
    add_scene_stats(&ctx->stats, &scene->stats);
    if (status != SCENE_OK) {
        rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory updating an object", caller);
        return -1;
    }
    return 0;
}

void rt_render_job(struct rt_context *ctx, struct render_job *job)
{
    job->state = &ctx->render;
    job->frame = &ctx->scene.frame;
    job->update = &ctx->scene.update_config;
    job->textures = &ctx->scene.textures;
    job->pool = rt_context_pool(ctx);
    job->threads = rt_pool_threads(job->pool);
    job->kernels = ctx->kernels;
    job->stream_always = ctx->stream_mode == RT_STREAM_ON;
    job->overlay = NULL;
}

void rt_frame_described(struct rt_context *ctx)
{
    if (ctx->gl_frames)
        ctx->frame_unrendered = 1;
}

static void render_frame_now(struct rt_context *ctx);

void rt_render_if_described(struct rt_context *ctx)
{
    if (ctx->frame_unrendered && !ctx->recording.active && !ctx->block.active)
        render_frame_now(ctx);
}

int rt_clear_record(struct rt_context *ctx, RTbitfield mask)
{
    if (!rt_list_compiling(ctx))
        return 0;
    /* Recorded as GL records it, its mask checked when it runs. */
    if (scene_list_state(&ctx->recording, LIST_CLEAR, mask, 0, NULL, 0)) {
        ctx->recording.out_of_memory = 1;
        rt_error(ctx, RT_OUT_OF_MEMORY, "rtClear: out of memory recording list %u",
                 ctx->recording.name);
    }
    return ctx->list_mode == RT_COMPILE;
}

void rtClear(RTbitfield mask)
{
    GET_CURRENT_CONTEXT(ctx);
    /* GL compiles glClear into display lists: it runs when the list is
     * called (list.c), and starts the frame there. */
    if (!ctx || rt_check_outside_begin(ctx, "rtClear") || rt_clear_record(ctx, mask))
        return;
    /* Mesa's glClear: any bit beyond the four buffers is INVALID_VALUE. */
    if (mask & ~(RTbitfield)(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT | RT_STENCIL_BUFFER_BIT |
                             RT_ACCUM_BUFFER_BIT)) {
        rt_error(ctx, RT_INVALID_VALUE, "rtClear(mask=0x%x)", mask);
        return;
    }
    /* Every frame is rendered whole on the clear colour: clearing starts
     * the description of the next one. */
    scene_frame_begin(&ctx->scene.frame);
    render_overlay_clear(&ctx->overlay); /* the last GL frame's bitmaps */
    ctx->gl_frames = 1;
    ctx->frame_unrendered = 1;
}

void rtFlush(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_object(ctx, "rtFlush"))
        return;
    rt_render_if_described(ctx);
}

void rtRenderFrame(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_object(ctx, "rtRenderFrame"))
        return;
    render_frame_now(ctx);
}

static void render_frame_now(struct rt_context *ctx)
{
    ctx->frame_unrendered = 0;
    double start = rt_now_ms();
    memset(&ctx->stats, 0, sizeof(ctx->stats));
    if (rt_prepare_scene(ctx, "rtRenderFrame"))
        return;
    const int *vp = ctx->render.viewport;
    int fb_width = vp[0] + vp[2], fb_height = vp[1] + vp[3];
    /* The projection the frame's rays and traced depths use: the one
     * rt_prepare_scene chose, so that the traced instances are exactly
     * those drawn under it. */
    memcpy(ctx->render.projection, ctx->scene.frame.trace_projection,
           sizeof(ctx->render.projection));
    struct render_job job;
    rt_render_job(ctx, &job);
    /* RT_AUTOMATIC's time per traversal step is this frame's tracing
     * time on the clock its build costs are measured with
     * (rt_pool_work_ms: CPU time, the pool's share of the frame), which
     * a loaded machine does not inflate; the updates before tracing are
     * outside it (internal/automatic_cost). */
    double trace_work = rt_pool_work_ms(job.pool);
    if (ctx->scene.preempt.fn)
        ctx->scene.preempt.fn(ctx->scene.preempt.user);
    /* The frame's bitmaps go over its image, as GL's glBitmap over the
     * scene drawn before it (render/overlay.h), in draw order among the
     * geometry rasterised over it (a HUD panel drawn after the text covers
     * it); they end with the frame. */
    job.overlay = &ctx->overlay;
    if (render_frame(&job, fb_width, fb_height, &ctx->render.fb, &ctx->stats)) {
        rt_error(ctx, RT_OUT_OF_MEMORY, "rtRenderFrame: out of memory");
        return;
    }
    trace_work = rt_pool_work_ms(job.pool) - trace_work;
    ctx->frames_traced++;
    /* The bitmaps end with the frame.  A GL frame ends at the next rtClear
     * instead: GL's framebuffer keeps the text until it is cleared, so a
     * frame rendered again (glFlush, then the buffer swap that renders
     * once more) shows it again. */
    if (!ctx->gl_frames)
        render_overlay_clear(&ctx->overlay);
    scene_end_frame(&ctx->scene, ctx->stats.rays, ctx->stats.node_tests + ctx->stats.triangle_tests,
                    trace_work);
    /* A GL frame ends at the next rtClear: drawing after glFlush adds to
     * it, and the swap that follows shows both (glut/flush_swap). */
    if (ctx->gl_frames)
        scene_frame_continue(&ctx->scene.frame);
    ctx->stats.render_ms = rt_now_ms() - start;
}

void rtFinish(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_object(ctx, "rtFinish"))
        return;
    if (ctx->frame_unrendered) {
        render_frame_now(ctx);
        return;
    }
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
    rt_render_if_described(ctx);
    const struct render_framebuffer *fb = &ctx->render.fb;
    if (!pixels || x < 0 || y < 0 || width < 0 || height < 0 || x > fb->width - width ||
        y > fb->height - height) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "rtReadPixels(x=%d, y=%d, width=%d, height=%d, pixels=%p): framebuffer is "
                 "%dx%d",
                 x, y, width, height, pixels, fb->width, fb->height);
        return;
    }
    /* Rows laid out as the pack state says (GL 1.5 sec. 4.3.2). */
    size_t first, stride;
    rt_pixel_layout(&ctx->pack, width, 4, type == RT_FLOAT ? (int)sizeof(float) : 1, &first,
                    &stride);
    for (int row = 0; row < height; row++) {
        const float *src = &fb->rgba[4 * ((size_t)(y + row) * fb->width + x)];
        size_t n = 4 * (size_t)width;
        unsigned char *dst = (unsigned char *)pixels + first + (size_t)row * stride;
        if (type == RT_FLOAT) {
            memcpy(dst, src, n * sizeof(float));
            if (ctx->pack.swap_bytes)
                for (size_t i = 0; i < n * sizeof(float); i += sizeof(float)) {
                    unsigned char t = dst[i];
                    dst[i] = dst[i + 3];
                    dst[i + 3] = t;
                    t = dst[i + 1];
                    dst[i + 1] = dst[i + 2];
                    dst[i + 2] = t;
                }
            continue;
        }
        for (size_t i = 0; i < n; i++) {
            float c = fminf(fmaxf(src[i], 0.0f), 1.0f);
            dst[i] = (unsigned char)lrintf(c * 255.0f);
        }
    }
}
