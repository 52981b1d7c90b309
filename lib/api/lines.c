/* SPDX-License-Identifier: Apache-2.0 */
/*
 * lines.c - lines, points and the visibility state: rtLineWidth,
 * rtPointSize, rtPolygonMode, rtBlendFunc, rtDepthMask, rtAlphaFunc,
 * rtPolygonOffset, rtClipPlane, rtGetClipPlane, and the recording of
 * blocks that give lines or points (RT_LINES ..., polygons under
 * rtPolygonMode RT_LINE / RT_POINT) into scene/lines.h's storage.
 * Validation follows Mesa (lines.c, points.c, polygon.c, blend.c,
 * depth.c, clip.c, alpha in blend.c, polygon offset in polygon.c).
 *
 * The raster state is per primitive (scene/raster_state.h): geometry takes
 * the state current when it is drawn.  Inside a display list every one of
 * these calls is recorded (and replayed by rtCallList); RT_COMPILE leaves
 * the context's values alone, RT_COMPILE_AND_EXECUTE sets them too.
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "api/enum_names.h"
#include "base/mat4.h"

/* Where the current block's lines go: the list being recorded, or the
 * frame's immediate-mode segment (rt_block_start chose ctx->target). */
static struct scene_lines *lines_target(struct rt_context *ctx)
{
    return &ctx->target->mesh.lines;
}

/*
 * The mode polygons of this block are turned into lines or points in when
 * they are recorded, or RT_FILL when they are recorded as triangles.
 * GL picks the mode per polygon by the face it shows in window space
 * (OpenGL 2.1 sec. 3.5.4, after culling, sec. 3.5.1), which only the
 * frame knows.  Recorded as lines or points here (invisible to rays, as
 * lines are) when both faces are in the same mode other than RT_FILL
 * and culling is known to be off, both known now (not taken from the
 * caller of a list).  Otherwise the polygons are triangles that keep both
 * modes in their material, with their edge flags: camera rays pass the
 * faces not filled (render/gl_shade.c) and render/raster_polygons.c
 * draws the edges or vertices of the others, each polygon in the mode of
 * the face it shows, culled first, by the culling current at the call
 * for a list that leaves RT_CULL_FACE to its caller.
 */
static RTenum polygon_mode(const struct rt_context *ctx)
{
    const RTenum front = ctx->polygon_mode[0], back = ctx->polygon_mode[1];
    if (front == RT_FILL || front != back)
        return RT_FILL;
    const uint32_t set = ctx->recording.active ? ctx->recording.material_set
                                               : SCENE_MATERIAL_ALL_STATE;
    /* In a list or object: what the list has not set comes from the call
     * (scene_material.inherit). */
    const uint32_t modes = SCENE_MATERIAL_POLYGON_MODE_FRONT | SCENE_MATERIAL_POLYGON_MODE_BACK;
    if ((set & modes) != modes)
        return RT_FILL;
    if (ctx->cull_face_enabled || !(set & SCENE_MATERIAL_CULL_ENABLE))
        return RT_FILL;
    return front;
}

/* The width and size the polygons of a triangle block take when a face
 * is drawn as lines or points (scene_material.polygon_line_width): in a
 * list the ones it set (0: the caller's), outside the current ones.  Kept
 * 0 while no face can be drawn so, so that a width change does not split
 * the materials of filled geometry. */
static void polygon_sizes(struct rt_context *ctx)
{
    float width = 0.0f, size = 0.0f;
    const uint32_t modes = SCENE_MATERIAL_POLYGON_MODE_FRONT | SCENE_MATERIAL_POLYGON_MODE_BACK;
    const int inherited = ctx->recording.active && (ctx->recording.material_set & modes) != modes;
    if (inherited || ctx->polygon_mode[0] != RT_FILL || ctx->polygon_mode[1] != RT_FILL) {
        if (ctx->recording.active) {
            width = ctx->recording.mesh.lines.width;
            size = ctx->recording.mesh.lines.size;
        } else {
            width = ctx->render.vis.line_width;
            size = ctx->render.vis.point_size;
        }
    }
    if (ctx->material.polygon_line_width != width || ctx->material.polygon_point_size != size) {
        ctx->material.polygon_line_width = width;
        ctx->material.polygon_point_size = size;
        ctx->recording.material_index = -1;
        if (ctx->target) /* a draw call started its immediate block first */
            ctx->target->material_index = -1;
    }
}

int rt_lines_block_start(struct rt_context *ctx, RTenum mode)
{
    int line_mode = scene_lines_mode_is_valid(mode);
    RTenum pmode = line_mode ? RT_FILL : polygon_mode(ctx);
    if (!line_mode && pmode == RT_FILL) {
        polygon_sizes(ctx);
        ctx->lines_block = 0;
        return 0;
    }
    if (rt_block_start(ctx, mode))
        return -1;
    struct scene_lines *lines = lines_target(ctx);
    /* In a list, the width the list set (0 until it sets one: the
     * primitives then take the caller's at rtCallList, through the
     * instance's scene_raster); in immediate mode, the current one. */
    float width = lines->width, size = lines->size;
    if (ctx->target != &ctx->recording) {
        width = ctx->render.vis.line_width;
        size = ctx->render.vis.point_size;
    }
    scene_line_block_start(&ctx->line_block, lines, mode, line_mode ? 0u : pmode, width, size,
                           ctx->shade_model == RT_FLAT ? SCENE_LINE_FLAT : 0u);
    ctx->lines_block = 1;
    return 1;
}

int rt_lines_vertex(struct rt_context *ctx, const char *caller, const double position[3],
                    const float color[4])
{
    double p[3];
    mat4_transform_point(ctx->block.position_matrix, position, p);
    float pf[3] = {(float)p[0], (float)p[1], (float)p[2]};
    if (!isfinite(pf[0]) || !isfinite(pf[1]) || !isfinite(pf[2])) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "%s: vertex (%g, %g, %g) is not finite under the modelview matrix", caller,
                 position[0], position[1], position[2]);
        return -1;
    }
    if (scene_lines_vertex(lines_target(ctx), &ctx->line_block, pf, color)) {
        ctx->target->out_of_memory = 1;
        rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory recording lines", caller);
        return -1;
    }
    return 0;
}

void rt_lines_block_end(struct rt_context *ctx, const char *caller)
{
    if (!ctx->lines_block)
        return;
    ctx->lines_block = 0;
    if (scene_lines_end(lines_target(ctx), &ctx->line_block)) {
        ctx->target->out_of_memory = 1;
        rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory recording lines", caller);
    }
}

/* Records a raster-state call in the list being compiled.  Returns 1
 * when the call must not change the context (RT_COMPILE), 0 when it must
 * (RT_COMPILE_AND_EXECUTE, or no list being compiled).  split: the call
 * changes the state triangles take (blend, alpha test, polygon offset),
 * so the list's later geometry gets a segment (and an instance) of its
 * own, as clip planes do. */
static int record(struct rt_context *ctx, enum list_state_call what, RTenum b, RTenum c,
                  const float *v, int n, int split)
{
    if (!rt_list_compiling(ctx))
        return 0;
    rt_list_state(ctx, what, b, c, v, n);
    if (ctx->list_mode != RT_COMPILE_AND_EXECUTE) {
        if (split)
            rt_list_state_changed(ctx, "raster state");
        return 1;
    }
    return 0;
}

/* rtLineWidth and rtPointSize: outside a list they set the current value,
 * which the lines and points drawn later take; inside one they are
 * recorded, and the list's later primitives take the value (a display
 * list compiled with GL_COMPILE records glLineWidth without executing
 * it). */
static void set_size(const char *caller, float value, int is_width)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    if (!(value > 0.0f) || !isfinite(value)) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(%g): not positive", caller, (double)value);
        return;
    }
    if (rt_list_compiling(ctx)) {
        struct scene_lines *lines = &ctx->recording.mesh.lines;
        if (is_width)
            lines->width = value;
        else
            lines->size = value;
    }
    if (record(ctx, is_width ? LIST_LINE_WIDTH : LIST_POINT_SIZE, 0, 0, &value, 1, 0))
        return;
    if (is_width)
        ctx->render.vis.line_width = value;
    else
        ctx->render.vis.point_size = value;
}

void rtLineWidth(RTfloat width)
{
    set_size("rtLineWidth", width, 1);
}

void rtPointSize(RTfloat size)
{
    set_size("rtPointSize", size, 0);
}

void rtPolygonMode(RTenum face, RTenum mode)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtPolygonMode"))
        return;
    if (mode != RT_POINT && mode != RT_LINE && mode != RT_FILL) {
        rt_error(ctx, RT_INVALID_ENUM, "rtPolygonMode(mode=0x%x)", mode);
        return;
    }
    if (face != RT_FRONT && face != RT_BACK && face != RT_FRONT_AND_BACK) {
        rt_error(ctx, RT_INVALID_ENUM, "rtPolygonMode(face=0x%x)", face);
        return;
    }
    /* Applied even under RT_COMPILE: the list's later polygons record
     * the mode it set (rtEndList restores the caller's, list.c); the ones
     * before take the caller's at rtCallList (SCENE_MATERIAL_POLYGON_MODE_*
     * bits, list.c state_bit). */
    record(ctx, LIST_POLYGON_MODE, face, mode, NULL, 0, 0);
    if (face != RT_BACK)
        ctx->polygon_mode[0] = mode;
    if (face != RT_FRONT)
        ctx->polygon_mode[1] = mode;
    rt_sync_fixed_function(ctx);
}

static int blend_factor_is_valid(RTenum f, int is_source)
{
    switch (f) {
    case RT_ZERO:
    case RT_ONE:
    case RT_SRC_COLOR:
    case RT_ONE_MINUS_SRC_COLOR:
    case RT_DST_COLOR:
    case RT_ONE_MINUS_DST_COLOR:
    case RT_SRC_ALPHA:
    case RT_ONE_MINUS_SRC_ALPHA:
    case RT_DST_ALPHA:
    case RT_ONE_MINUS_DST_ALPHA:
        return 1;
    case RT_SRC_ALPHA_SATURATE:
        return is_source; /* a destination factor only with dual-source blending */
    default:
        return 0;
    }
}

void rtBlendFunc(RTenum sfactor, RTenum dfactor)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtBlendFunc"))
        return;
    if (!blend_factor_is_valid(sfactor, 1) || !blend_factor_is_valid(dfactor, 0)) {
        rt_error(ctx, RT_INVALID_ENUM, "rtBlendFunc(sfactor=0x%x, dfactor=0x%x)", sfactor,
                 dfactor);
        return;
    }
    if (record(ctx, LIST_BLEND_FUNC, sfactor, dfactor, NULL, 0, 1))
        return;
    ctx->render.vis.blend_src = sfactor;
    ctx->render.vis.blend_dst = dfactor;
    rt_list_state_changed(ctx, "rtBlendFunc"); /* RT_COMPILE_AND_EXECUTE: a segment of its own */
}

void rtAlphaFunc(RTenum func, RTfloat ref)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtAlphaFunc"))
        return;
    if (func < RT_NEVER || func > RT_ALWAYS) {
        char b1[RT_ENUM_STRING_SIZE];
        rt_error(ctx, RT_INVALID_ENUM, "rtAlphaFunc(func=%s)", rt_enum_string(func, b1));
        return;
    }
    /* GL clamps ref to [0, 1] (Mesa's _mesa_AlphaFunc: CLAMP); NaN as 0. */
    float r = ref >= 0.0f ? fminf(ref, 1.0f) : 0.0f;
    if (record(ctx, LIST_ALPHA_FUNC, func, 0, &r, 1, 1))
        return;
    ctx->render.vis.alpha_func = func;
    ctx->render.vis.alpha_ref = r;
    rt_list_state_changed(ctx, "rtAlphaFunc");
}

void rtPolygonOffset(RTfloat factor, RTfloat units)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtPolygonOffset"))
        return;
    /* GL accepts any value (Mesa's _mesa_PolygonOffset checks nothing). */
    const float v[2] = {factor, units};
    if (record(ctx, LIST_POLYGON_OFFSET, 0, 0, v, 2, 1))
        return;
    ctx->render.vis.offset_factor = factor;
    ctx->render.vis.offset_units = units;
    rt_list_state_changed(ctx, "rtPolygonOffset");
}

void rtDepthMask(RTboolean flag)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtDepthMask"))
        return;
    ctx->render.vis.depth_mask = flag != RT_FALSE;
}

/* The plane index of RT_CLIP_PLANEi, or -1 (recording RT_INVALID_ENUM). */
static int clip_plane_index(struct rt_context *ctx, const char *caller, RTenum plane)
{
    if (plane < RT_CLIP_PLANE0 || plane >= RT_CLIP_PLANE0 + RENDER_MAX_CLIP_PLANES) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(plane=0x%x)", caller, plane);
        return -1;
    }
    return (int)(plane - RT_CLIP_PLANE0);
}

void rtClipPlane(RTenum plane, const RTdouble *equation)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtClipPlane"))
        return;
    int i = clip_plane_index(ctx, "rtClipPlane", plane);
    if (i < 0)
        return;
    if (!equation) {
        rt_error(ctx, RT_INVALID_VALUE, "rtClipPlane(equation=NULL)");
        return;
    }
    if (!rt_check_finite_d(ctx, "rtClipPlane", equation, 4))
        return;
    /* Inside a list, recorded (in double) and executed at the call under
     * the modelview then current; RT_COMPILE_AND_EXECUTE also executes it
     * now. */
    const int compiling = rt_list_compiling(ctx);
    if (compiling) {
        if (scene_list_state_d(&ctx->recording, LIST_CLIP_PLANE, plane, 0, equation, 4)) {
            ctx->recording.out_of_memory = 1;
            rt_error(ctx, RT_OUT_OF_MEMORY, "rtClipPlane: out of memory recording list %u",
                     ctx->recording.name);
            return;
        }
        if (ctx->list_mode != RT_COMPILE_AND_EXECUTE) {
            rt_list_state_changed(ctx, "rtClipPlane");
            return;
        }
    }
    /* Into eye space as GL (OpenGL 2.1 sec. 2.12): the row vector times
     * the inverse of the modelview at the call; a singular modelview
     * counts as the identity, as Mesa's matrix inverse falls back to. */
    double inv[16], e[4];
    if (!mat4_invert(inv, ctx->modelview.m[ctx->modelview.depth - 1]))
        mat4_identity(inv);
    for (int j = 0; j < 4; j++)
        e[j] = equation[0] * inv[4 * j] + equation[1] * inv[4 * j + 1] +
               equation[2] * inv[4 * j + 2] + equation[3] * inv[4 * j + 3];
    if (!isfinite(e[0]) || !isfinite(e[1]) || !isfinite(e[2]) || !isfinite(e[3])) {
        rt_error(ctx, RT_INVALID_VALUE, "rtClipPlane: the equation is not finite in eye space");
        return;
    }
    memcpy(ctx->render.vis.clip_plane[i], e, sizeof(e));
    if (compiling)
        rt_list_state_changed(ctx, "rtClipPlane");
}

void rt_clip_now(const struct rt_context *ctx, struct scene_clip *clip)
{
    memset(clip, 0, sizeof(*clip));
    for (int i = 0; i < RENDER_MAX_CLIP_PLANES; i++)
        if (ctx->render.vis.clip_enabled[i]) {
            clip->enabled |= 1u << i;
            memcpy(clip->plane[i], ctx->render.vis.clip_plane[i], sizeof(clip->plane[i]));
        }
}

void rt_raster_now(const struct rt_context *ctx, struct scene_raster *raster)
{
    const struct render_visibility *vis = &ctx->render.vis;
    memset(raster, 0, sizeof(*raster));
    raster->blend = vis->blend != 0;
    raster->alpha_test = vis->alpha_test != 0;
    raster->offset_fill = ctx->polygon_offset_fill != 0;
    raster->blend_src = (uint16_t)vis->blend_src;
    raster->blend_dst = (uint16_t)vis->blend_dst;
    raster->alpha_func = (uint16_t)vis->alpha_func;
    raster->alpha_ref = vis->alpha_ref;
    raster->offset_factor = vis->offset_factor;
    raster->offset_units = vis->offset_units;
    raster->line_width = vis->line_width;
    raster->point_size = vis->point_size;
    raster->depth_test = ctx->depth_test != 0;
    for (int i = 0; i < 4; i++)
        raster->viewport[i] = ctx->render.viewport[i];
    memcpy(raster->projection, ctx->projection.m[ctx->projection.depth - 1],
           sizeof(raster->projection));
}

void rtGetClipPlane(RTenum plane, RTdouble *equation)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtGetClipPlane"))
        return;
    int i = clip_plane_index(ctx, "rtGetClipPlane", plane);
    if (i < 0)
        return;
    if (!equation) {
        rt_error(ctx, RT_INVALID_VALUE, "rtGetClipPlane(equation=NULL)");
        return;
    }
    memcpy(equation, ctx->render.vis.clip_plane[i], 4 * sizeof(double));
}
