/* SPDX-License-Identifier: Apache-2.0 */
/*
 * raster.c - rtRasterPos*, rtWindowPos*, rtBitmap: the current raster
 * position and bitmaps drawn at it (GL 1.x, Segal and Akeley, "The OpenGL
 * Graphics System: A Specification, Version 1.5", sec. 2.13 and 3.7).
 *
 * rtRasterPos transforms its point like a vertex: by the modelview and
 * the projection current at the call, clipped against the view volume
 * (a point outside makes the raster position invalid, as in GL), divided
 * by w and mapped through the viewport current at the call.  rtWindowPos
 * gives window coordinates directly and is always valid.  Both latch the
 * current colour as the raster colour.  rtBitmap keeps its bitmap for the
 * frame (render/overlay.h): rtRenderFrame draws it over the traced image,
 * where GL would have drawn it over the scene.  Lighting does not touch
 * the raster colour here (GL lights it when GL_LIGHTING is on).
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "base/alloc.h"

/* Mesa (like SGI's GL before it) adds this to the raster position before
 * flooring it to the bitmap's first pixel, so that a position computed as
 * 9.99999 for 10 by the matrices lands on pixel 10; we do the same to
 * place bitmaps on the pixels GL does. */
#define RASTER_EPSILON 1e-4

/* GL compiles raster positions and bitmaps into display lists: allowed
 * anywhere but between rtBegin and rtEnd. */
static int raster_allowed(struct rt_context *ctx, const char *caller)
{
    return ctx && !rt_check_outside_begin(ctx, caller);
}

static void list_out_of_memory(struct rt_context *ctx, const char *caller)
{
    ctx->recording.out_of_memory = 1;
    rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory recording list %u", caller,
             ctx->recording.name);
}

int rt_raster_record(struct rt_context *ctx, const char *caller, int window, const double p[4])
{
    if (!rt_list_compiling(ctx))
        return 0;
    if (scene_list_state_d(&ctx->recording, window ? LIST_WINDOW_POS : LIST_RASTER_POS, 0, 0, p,
                           4))
        list_out_of_memory(ctx, caller);
    return ctx->list_mode == RT_COMPILE;
}

static void latch_color(struct rt_context *ctx)
{
    memcpy(ctx->raster_color, ctx->current_color, sizeof(ctx->raster_color));
}

static void raster_pos(const char *caller, double x, double y, double z, double w)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!raster_allowed(ctx, caller))
        return;
    const double in[4] = {x, y, z, w};
    if (!rt_check_finite_d(ctx, caller, in, 4))
        return;
    if (rt_raster_record(ctx, caller, 0, in))
        return;
    const double *mv = ctx->modelview.m[ctx->modelview.depth - 1];
    const double *pr = ctx->projection.m[ctx->projection.depth - 1];
    double eye[4], clip[4];
    for (int r = 0; r < 4; r++)
        eye[r] = mv[r] * x + mv[4 + r] * y + mv[8 + r] * z + mv[12 + r] * w;
    for (int r = 0; r < 4; r++)
        clip[r] = pr[r] * eye[0] + pr[4 + r] * eye[1] + pr[8 + r] * eye[2] + pr[12 + r] * eye[3];
    latch_color(ctx);
    const double cw = clip[3];
    /* GL's clip volume -w <= x, y, z <= w: outside it (or w <= 0, where
     * the volume is empty or behind the eye) the position is invalid. */
    if (!(cw > 0.0) || fabs(clip[0]) > cw || fabs(clip[1]) > cw || fabs(clip[2]) > cw) {
        ctx->raster_valid = 0;
        return;
    }
    const int *vp = ctx->render.viewport;
    ctx->raster_pos[0] = (float)(vp[0] + (clip[0] / cw + 1.0) * 0.5 * vp[2]);
    ctx->raster_pos[1] = (float)(vp[1] + (clip[1] / cw + 1.0) * 0.5 * vp[3]);
    ctx->raster_pos[2] = (float)((clip[2] / cw + 1.0) * 0.5);
    ctx->raster_pos[3] = (float)cw;
    ctx->raster_valid = 1;
}

static void window_pos(const char *caller, double x, double y, double z)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!raster_allowed(ctx, caller))
        return;
    const double in[3] = {x, y, z};
    if (!rt_check_finite_d(ctx, caller, in, 3))
        return;
    const double rec[4] = {x, y, z, 1.0};
    if (rt_raster_record(ctx, caller, 1, rec))
        return;
    latch_color(ctx);
    ctx->raster_pos[0] = (float)x;
    ctx->raster_pos[1] = (float)y;
    ctx->raster_pos[2] = (float)fmin(fmax(z, 0.0), 1.0); /* GL 1.4: clamped to [0, 1] */
    ctx->raster_pos[3] = 1.0f;
    ctx->raster_valid = 1;
}

void rtRasterPos2i(RTint x, RTint y) { raster_pos("rtRasterPos2i", x, y, 0.0, 1.0); }
void rtRasterPos2f(RTfloat x, RTfloat y) { raster_pos("rtRasterPos2f", x, y, 0.0, 1.0); }
void rtRasterPos2d(RTdouble x, RTdouble y) { raster_pos("rtRasterPos2d", x, y, 0.0, 1.0); }
void rtRasterPos3i(RTint x, RTint y, RTint z) { raster_pos("rtRasterPos3i", x, y, z, 1.0); }
void rtRasterPos3f(RTfloat x, RTfloat y, RTfloat z) { raster_pos("rtRasterPos3f", x, y, z, 1.0); }
void rtRasterPos3d(RTdouble x, RTdouble y, RTdouble z)
{
    raster_pos("rtRasterPos3d", x, y, z, 1.0);
}
void rtRasterPos4i(RTint x, RTint y, RTint z, RTint w) { raster_pos("rtRasterPos4i", x, y, z, w); }
void rtRasterPos4f(RTfloat x, RTfloat y, RTfloat z, RTfloat w)
{
    raster_pos("rtRasterPos4f", x, y, z, w);
}
void rtRasterPos4d(RTdouble x, RTdouble y, RTdouble z, RTdouble w)
{
    raster_pos("rtRasterPos4d", x, y, z, w);
}

/* The vector forms: a NULL pointer records RT_INVALID_VALUE (GL leaves it
 * undefined). */
static int vector_ok(const void *v, const char *caller)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return 0;
    if (!v) {
        if (!rt_check_outside_begin(ctx, caller))
            rt_error(ctx, RT_INVALID_VALUE, "%s(v=NULL)", caller);
        return 0;
    }
    return 1;
}

#define RASTER_POS_V(name, type, n)                                                          \
    void name(const type *v)                                                                 \
    {                                                                                        \
        if (vector_ok(v, #name))                                                             \
            raster_pos(#name, v[0], v[1], (n) > 2 ? v[(n) > 2 ? 2 : 0] : 0.0,                \
                       (n) > 3 ? v[(n) > 3 ? 3 : 0] : 1.0);                                  \
    }
RASTER_POS_V(rtRasterPos2iv, RTint, 2)
RASTER_POS_V(rtRasterPos2fv, RTfloat, 2)
RASTER_POS_V(rtRasterPos2dv, RTdouble, 2)
RASTER_POS_V(rtRasterPos3iv, RTint, 3)
RASTER_POS_V(rtRasterPos3fv, RTfloat, 3)
RASTER_POS_V(rtRasterPos3dv, RTdouble, 3)
RASTER_POS_V(rtRasterPos4iv, RTint, 4)
RASTER_POS_V(rtRasterPos4fv, RTfloat, 4)
RASTER_POS_V(rtRasterPos4dv, RTdouble, 4)

void rtWindowPos2i(RTint x, RTint y) { window_pos("rtWindowPos2i", x, y, 0.0); }
void rtWindowPos2f(RTfloat x, RTfloat y) { window_pos("rtWindowPos2f", x, y, 0.0); }
void rtWindowPos2d(RTdouble x, RTdouble y) { window_pos("rtWindowPos2d", x, y, 0.0); }
void rtWindowPos3i(RTint x, RTint y, RTint z) { window_pos("rtWindowPos3i", x, y, z); }
void rtWindowPos3f(RTfloat x, RTfloat y, RTfloat z) { window_pos("rtWindowPos3f", x, y, z); }
void rtWindowPos3d(RTdouble x, RTdouble y, RTdouble z) { window_pos("rtWindowPos3d", x, y, z); }

#define WINDOW_POS_V(name, type, n)                                                          \
    void name(const type *v)                                                                 \
    {                                                                                        \
        if (vector_ok(v, #name))                                                             \
            window_pos(#name, v[0], v[1], (n) > 2 ? v[(n) > 2 ? 2 : 0] : 0.0);               \
    }
WINDOW_POS_V(rtWindowPos2iv, RTint, 2)
WINDOW_POS_V(rtWindowPos2fv, RTfloat, 2)
WINDOW_POS_V(rtWindowPos2dv, RTdouble, 2)
WINDOW_POS_V(rtWindowPos3iv, RTint, 3)
WINDOW_POS_V(rtWindowPos3fv, RTfloat, 3)
WINDOW_POS_V(rtWindowPos3dv, RTdouble, 3)

/* Largest bitmap side accepted: the framebuffer's bound (a larger bitmap
 * could only draw its first 16384 rows or columns anyway). */
#define MAX_BITMAP_SIDE (1 << 20)

/* Draws a bitmap of MSB-first rows `stride` bytes apart (NULL: none) at
 * the raster position and moves it, as glBitmap after unpacking. */
static void draw_bitmap(struct rt_context *ctx, int width, int height, const float f[4],
                        const unsigned char *rows, size_t stride)
{
    if (!ctx->raster_valid)
        return; /* GL: nothing drawn, the position does not move */
    if (rows && width > 0 && height > 0) {
        const int x = (int)floor((double)ctx->raster_pos[0] + RASTER_EPSILON - f[0]);
        const int y = (int)floor((double)ctx->raster_pos[1] + RASTER_EPSILON - f[1]);
        /* Its place in the draw order: after the instances drawn so far.
         * The open immediate segment ends here, so that geometry drawn
         * after the bitmap is a later instance (render.c draws the bitmap
         * under rasterised instances from `order` on). */
        struct scene_frame *frame = &ctx->scene.frame;
        scene_immediate_close(frame);
        const uint32_t order = frame->open ? frame->pending.count : 0;
        if (render_overlay_add(&ctx->overlay, order, x, y, width, height, stride, rows,
                               ctx->raster_color)) {
            rt_error(ctx, RT_OUT_OF_MEMORY, "rtBitmap: out of memory");
            return;
        }
    }
    ctx->raster_pos[0] += f[2];
    ctx->raster_pos[1] += f[3];
}

/* Bytes of bitmap rows one LIST_BITMAP_DATA operation carries. */
#define BITMAP_OP_BYTES sizeof(((struct scene_list_op *)0)->v)

/* rtBitmap compiled into a list: a LIST_BITMAP operation (b, c: the
 * size; v: origin and move) and the unpacked rows, MSB first and
 * (width + 7) / 8 bytes apart, in the LIST_BITMAP_DATA operations after
 * it.  GL unpacks a bitmap when the list is compiled (with the pixel
 * store of that moment), so a list keeps its own copy. */
static int record_bitmap(struct rt_context *ctx, int width, int height, const float f[4],
                         const unsigned char *rows, size_t stride)
{
    struct scene_recording *rec = &ctx->recording;
    const double v[4] = {f[0], f[1], f[2], f[3]};
    const int empty = !rows || width == 0 || height == 0;
    if (scene_list_state_d(rec, LIST_BITMAP, empty ? 0 : (uint32_t)width,
                           empty ? 0 : (uint32_t)height, v, 4))
        return -1;
    if (empty)
        return 0;
    const size_t out_stride = ((size_t)width + 7) / 8;
    const size_t bytes = out_stride * (size_t)height;
    for (size_t at = 0; at < bytes; at += BITMAP_OP_BYTES) {
        unsigned char chunk[BITMAP_OP_BYTES];
        memset(chunk, 0, sizeof(chunk));
        for (size_t k = 0; k < BITMAP_OP_BYTES && at + k < bytes; k++) {
            const size_t row = (at + k) / out_stride, col = (at + k) % out_stride;
            chunk[k] = rows[row * stride + col];
        }
        if (scene_list_state_d(rec, LIST_BITMAP_DATA, 0, 0, NULL, 0))
            return -1;
        /* Bytes, not numbers: copied, never converted. */
        memcpy(rec->ops[rec->op_count - 1].v, chunk, sizeof(chunk));
    }
    return 0;
}

uint32_t rt_bitmap_replay(struct rt_context *ctx, const struct scene_list_op *ops,
                          uint32_t count)
{
    const int width = (int)ops[0].b, height = (int)ops[0].c;
    const size_t stride = ((size_t)width + 7) / 8;
    const size_t bytes = stride * (size_t)height;
    const uint32_t data = (uint32_t)((bytes + BITMAP_OP_BYTES - 1) / BITMAP_OP_BYTES);
    if (data >= count)
        return count; /* cannot happen: the recording wrote them together */
    const float f[4] = {(float)ops[0].v[0], (float)ops[0].v[1], (float)ops[0].v[2],
                        (float)ops[0].v[3]};
    if (rt_check_outside_begin(ctx, "rtBitmap"))
        return 1 + data;
    unsigned char *rows = NULL;
    if (bytes) {
        rows = rt_malloc(data * BITMAP_OP_BYTES);
        if (!rows) {
            rt_error(ctx, RT_OUT_OF_MEMORY, "rtBitmap: out of memory");
            return 1 + data;
        }
        for (uint32_t k = 0; k < data; k++)
            memcpy(rows + k * BITMAP_OP_BYTES, ops[1 + k].v, BITMAP_OP_BYTES);
    }
    draw_bitmap(ctx, width, height, f, rows, stride);
    rt_free(rows);
    return 1 + data;
}

void rtBitmap(RTsizei width, RTsizei height, RTfloat xorig, RTfloat yorig, RTfloat xmove,
              RTfloat ymove, const RTubyte *bitmap)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!raster_allowed(ctx, "rtBitmap"))
        return;
    if (width < 0 || height < 0 || width > MAX_BITMAP_SIDE || height > MAX_BITMAP_SIDE) {
        rt_error(ctx, RT_INVALID_VALUE, "rtBitmap(width=%d, height=%d)", width, height);
        return;
    }
    const float f[4] = {xorig, yorig, xmove, ymove};
    if (!rt_check_finite(ctx, "rtBitmap", f, 4))
        return;
    const int compiling = rt_list_compiling(ctx);
    if (!compiling && !ctx->raster_valid)
        return; /* GL: nothing drawn, the position does not move */
    const unsigned char *rows = NULL;
    unsigned char *packed = NULL;
    size_t stride = 0;
    if (bitmap && width > 0 && height > 0) {
        /* GL's unpacking under the pixel store (pixel_store.c): one bit a
         * pixel, rows bottom to top, each row RT_UNPACK_ALIGNMENT-padded
         * (4 by default), the most significant bit first unless
         * RT_UNPACK_LSB_FIRST.  The overlay takes MSB-first rows starting
         * at bit 0: other layouts are repacked into that. */
        size_t first;
        rt_pixel_layout(&ctx->unpack, width, 1, 0, &first, &stride);
        rows = bitmap + first;
        const size_t skip = (size_t)ctx->unpack.skip_pixels;
        if (skip || ctx->unpack.lsb_first) {
            const size_t out_stride = ((size_t)width + 7) / 8;
            packed = rt_calloc((size_t)height, out_stride);
            if (!packed) {
                rt_error(ctx, RT_OUT_OF_MEMORY, "rtBitmap: out of memory");
                return;
            }
            for (size_t j = 0; j < (size_t)height; j++)
                for (size_t i = 0; i < (size_t)width; i++) {
                    const size_t b = skip + i;
                    const unsigned byte = rows[j * stride + b / 8];
                    const unsigned bit = ctx->unpack.lsb_first ? (byte >> (b % 8)) & 1u
                                                               : (byte >> (7 - b % 8)) & 1u;
                    if (bit)
                        packed[j * out_stride + i / 8] |= (unsigned char)(0x80u >> (i % 8));
                }
            rows = packed;
            stride = out_stride;
        }
    }
    if (compiling) {
        if (record_bitmap(ctx, width, height, f, rows, stride))
            list_out_of_memory(ctx, "rtBitmap");
        if (ctx->list_mode == RT_COMPILE) {
            rt_free(packed);
            return;
        }
    }
    draw_bitmap(ctx, width, height, f, rows, stride);
    rt_free(packed);
}
