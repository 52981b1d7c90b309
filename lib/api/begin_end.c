/* SPDX-License-Identifier: Apache-2.0 */
/*
 * begin_end.c - rtBegin/rtEnd, rtVertex*, current attributes and
 * rtShadeModel: the checks, then scene/recording.c, which transforms,
 * stores and assembles (recording.h states the conventions).  The
 * rt_*_vertex wrappers serve the vertex arrays (array.c) too.
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "scene/assembly.h"

int rt_block_start(struct rt_context *ctx, RTenum mode)
{
    /* The texture state as the material records it for inheritance
     * (scene_material.texture_bound); it cannot change inside a block. */
    if (ctx->material.texture_bound != ctx->texture_binding ||
        ctx->material.texture_enabled != (uint32_t)ctx->texture_2d) {
        ctx->material.texture_bound = ctx->texture_binding;
        ctx->material.texture_enabled = (uint32_t)ctx->texture_2d;
        ctx->recording.material_index = -1;
    }
    if (ctx->recording.active) {
        /* A display list: relative to the list's own matrix (list.c). */
        ctx->target = &ctx->recording;
        scene_block_start(&ctx->block, ctx->target, mode, scene_list_matrix(ctx->target));
        return 0;
    }
    /* Immediate mode: into the frame under the current modelview. */
    struct scene_clip clip;
    struct scene_gl_state gl;
    rt_clip_now(ctx, &clip);
    rt_gl_state_now(ctx, &gl);
    if (gl.light_set == UINT32_MAX)
        return -1; /* no room for its light set (recorded) */
    /* Lines and points carry their width and size (lines.c): a change of
     * width alone does not start a segment. */
    struct scene_raster raster;
    rt_raster_now(ctx, &raster);
    raster.line_width = 0.0f;
    raster.point_size = 0.0f;
    ctx->target = scene_immediate_segment(
        &ctx->scene.frame, ctx->modelview.m[ctx->modelview.depth - 1], &clip, &gl, &raster);
    if (!ctx->target)
        return -1;
    /* The state calls mark only the list recording's material stale
     * (ctx->recording.material_index): a block of the open immediate
     * segment re-interns the material current now. */
    ctx->target->material_index = -1;
    rt_frame_described(ctx);
    if (ctx->normal_given)
        ctx->target->mesh.has_normals = 1;
    scene_block_start(&ctx->block, ctx->target, mode, ctx->scene.frame.immediate.block_matrix);
    return 0;
}

int rt_vertex_is_finite(const struct rt_context *ctx, const double position[3])
{
    return scene_block_vertex_is_finite(&ctx->block, position);
}

/* What the current state gives the triangles: the material, the bound
 * texture while RT_TEXTURE_2D is enabled (else 0), the shading flags. */
static struct scene_triangle_state triangle_state(const struct rt_context *ctx)
{
    struct scene_triangle_state ts;
    ts.material = &ctx->material;
    ts.texture = ctx->texture_2d ? ctx->texture_binding : 0;
    ts.flags = (uint8_t)((ctx->shade_model == RT_FLAT ? TRI_FLAT : 0u) |
                         (ctx->color_material ? TRI_COLOR_MATERIAL : 0u));
    /* In a list, what the list did not set yet comes from the caller. */
    ts.inherit = 0;
    if (ctx->target == &ctx->recording) {
        ts.inherit = SCENE_MATERIAL_ALL_STATE & ~ctx->recording.material_set;
        if (!ctx->recording.color_set)
            ts.flags |= TRI_INHERIT_COLOR;
        if (!ctx->recording.color_material_set)
            ts.flags |= TRI_INHERIT_COLOR_MATERIAL;
        if (!ctx->recording.shade_model_set)
            ts.flags |= TRI_INHERIT_SHADE;
    }
    return ts;
}

/* Turns a recording status into the error it means; 0 or -1. */
static int recorded(struct rt_context *ctx, const char *caller, enum scene_record_status status,
                    const double position[3])
{
    switch (status) {
    case SCENE_RECORD_OK:
        return 0;
    case SCENE_RECORD_NOT_FINITE:
        rt_error(ctx, RT_INVALID_VALUE,
                 "%s: vertex (%g, %g, %g) is not finite under the modelview matrix", caller,
                 position[0], position[1], position[2]);
        return -1;
    default:
        rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory recording %s", caller,
                 ctx->target == &ctx->recording ? "a list" : "immediate-mode geometry");
        return -1;
    }
}

int rt_record_vertex(struct rt_context *ctx, const char *caller, const double position[3],
                     const float normal[3], const float color[4], const float texcoord[4])
{
    struct scene_triangle_state ts = triangle_state(ctx);
    return recorded(ctx, caller,
                    scene_record_vertex(ctx->target, &ctx->block, &ts, position, normal,
                                        color, texcoord),
                    position);
}

int rt_store_vertex(struct rt_context *ctx, const char *caller, const double position[3],
                    const float normal[3], const float color[4], const float texcoord[4])
{
    return recorded(ctx, caller,
                    scene_store_vertex(ctx->target, &ctx->block, position, normal, color,
                                       texcoord),
                    position);
}

int rt_assemble_indexed(struct rt_context *ctx, const char *caller, uint32_t k,
                        const uint32_t *map)
{
    struct scene_triangle_state ts = triangle_state(ctx);
    return recorded(ctx, caller,
                    scene_assemble_indexed(ctx->target, &ctx->block, &ts, k, map), NULL);
}

void rtBegin(RTenum mode)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    if (ctx->block.active) {
        rt_error(ctx, RT_INVALID_OPERATION, "rtBegin(mode=0x%x): already inside rtBegin", mode);
        return;
    }
    if (!scene_mode_is_valid(mode) && !scene_lines_mode_is_valid(mode)) {
        rt_error(ctx, RT_INVALID_ENUM, "rtBegin(mode=0x%x)", mode);
        return;
    }
    /* Lines, points and polygons drawn as either go to lines.c; both
     * start the block in the list or in the frame (rt_block_start). */
    int started = rt_lines_block_start(ctx, mode);
    if (started == 0)
        started = rt_block_start(ctx, mode) ? -1 : 1;
    if (started < 0) {
        rt_error(ctx, RT_OUT_OF_MEMORY, "rtBegin(mode=0x%x): out of memory", mode);
        return;
    }
    ctx->block.active = 1;
}

void rtEnd(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    if (!ctx->block.active) {
        rt_error(ctx, RT_INVALID_OPERATION, "rtEnd: no matching rtBegin");
        return;
    }
    /* Vertices of an incomplete last primitive stay unused (GL drops
     * them); they are not referenced by any triangle. */
    ctx->block.active = 0;
    if (ctx->lines_block)
        rt_lines_block_end(ctx, "rtEnd");
    else
        scene_block_close_polygon(ctx->target, &ctx->block, ctx->block.count);
}

static void vertex(const char *caller, double x, double y, double z)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    double p[3] = {x, y, z};
    if (!ctx->block.active) {
        /* A display list records a vertex outside its own rtBegin/rtEnd
         * (list.c): it continues the primitive open where the list is
         * called, as GL's.  Replayed where no primitive is open, GL
         * leaves it undefined; Mesa ignores it, and so do we. */
        if (rt_list_compiling(ctx) && !ctx->recording_object) {
            const double rec[3] = {x, y, z};
            if (rt_check_finite_d(ctx, caller, p, 3) &&
                scene_list_state_d(&ctx->recording, LIST_VERTEX, 0, 0, rec, 3)) {
                ctx->recording.out_of_memory = 1;
                rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory recording list %u", caller,
                         ctx->recording.name);
            }
            return;
        }
        if (ctx->replaying == 0)
            rt_error(ctx, RT_INVALID_OPERATION, "%s: only allowed between rtBegin and rtEnd",
                     caller);
        return;
    }
    if (!rt_check_finite_d(ctx, caller, p, 3))
        return;
    if (ctx->lines_block) {
        rt_lines_vertex(ctx, caller, p, ctx->current_color);
        return;
    }
    rt_record_vertex(ctx, caller, p, ctx->current_normal, ctx->current_color,
                     ctx->current_texcoord);
}

void rtVertex2f(RTfloat x, RTfloat y)
{
    vertex("rtVertex2f", x, y, 0.0);
}

void rtVertex2d(RTdouble x, RTdouble y)
{
    vertex("rtVertex2d", x, y, 0.0);
}

void rtVertex3f(RTfloat x, RTfloat y, RTfloat z)
{
    vertex("rtVertex3f", x, y, z);
}

void rtVertex3d(RTdouble x, RTdouble y, RTdouble z)
{
    vertex("rtVertex3d", x, y, z);
}

/* The pointer forms check the mode before the pointer, in the order of
 * STYLE.md sec. 3. */
static int vertex_pointer_ok(const void *v, const char *caller)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return 0;
    if (!ctx->block.active && (!rt_list_compiling(ctx) || ctx->recording_object)) {
        if (ctx->replaying == 0)
            rt_error(ctx, RT_INVALID_OPERATION, "%s: only allowed between rtBegin and rtEnd",
                     caller);
        return 0;
    }
    if (!v) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(v=NULL)", caller);
        return 0;
    }
    return 1;
}

void rtVertex2fv(const RTfloat *v)
{
    if (vertex_pointer_ok(v, "rtVertex2fv"))
        vertex("rtVertex2fv", v[0], v[1], 0.0);
}

void rtVertex2dv(const RTdouble *v)
{
    if (vertex_pointer_ok(v, "rtVertex2dv"))
        vertex("rtVertex2dv", v[0], v[1], 0.0);
}

void rtVertex3fv(const RTfloat *v)
{
    if (vertex_pointer_ok(v, "rtVertex3fv"))
        vertex("rtVertex3fv", v[0], v[1], v[2]);
}

void rtVertex3dv(const RTdouble *v)
{
    if (vertex_pointer_ok(v, "rtVertex3dv"))
        vertex("rtVertex3dv", v[0], v[1], v[2]);
}

enum attribute { ATTR_NORMAL, ATTR_TEXCOORD, ATTR_COLOR };

/* Sets a current attribute from n floats if all are finite.  Colours are
 * clamped to [0, 1] as OpenGL clamps glColor*f. */
static void set_attribute(const char *caller, enum attribute which, const float *src, int n)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    if (!src) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(v=NULL)", caller);
        return;
    }
    if (!rt_check_finite(ctx, caller, src, n))
        return;
    switch (which) {
    case ATTR_NORMAL:
        memcpy(ctx->current_normal, src, 3 * sizeof(float));
        rt_list_state(ctx, LIST_NORMAL, 0, 0, ctx->current_normal, 3);
        /* An object that never sets a normal is shaded with geometric
         * normals instead of GL's default (0, 0, 1); so is immediate-mode
         * geometry drawn with no normal in its frame. */
        if (rt_list_compiling(ctx)) {
            ctx->recording.mesh.has_normals = 1;
        } else {
            ctx->normal_given = 1;
            if (ctx->block.active && ctx->target == &ctx->scene.frame.immediate.rec)
                ctx->target->mesh.has_normals = 1;
        }
        break;
    case ATTR_TEXCOORD:
        /* GL: rtTexCoord2 sets r = 0, q = 1; rtTexCoord4 all four. */
        for (int i = 0; i < 4; i++)
            ctx->current_texcoord[i] = i < n ? src[i] : (i == 3 ? 1.0f : 0.0f);
        rt_list_state(ctx, LIST_TEXCOORD, 0, 0, ctx->current_texcoord, 4);
        break;
    case ATTR_COLOR:
        for (int i = 0; i < 4; i++)
            ctx->current_color[i] = i < n ? fminf(fmaxf(src[i], 0.0f), 1.0f) : 1.0f;
        rt_list_state(ctx, LIST_COLOR, 0, 0, ctx->current_color, 4);
        /* RT_COLOR_MATERIAL: GL writes it into the tracked properties
         * (appearance.c, rt_color_material_write). */
        ctx->color_material_current = ctx->color_material;
        break;
    }
}

void rtNormal3f(RTfloat nx, RTfloat ny, RTfloat nz)
{
    const float v[3] = {nx, ny, nz};
    set_attribute("rtNormal3f", ATTR_NORMAL, v, 3);
}

void rtNormal3fv(const RTfloat *v)
{
    set_attribute("rtNormal3fv", ATTR_NORMAL, v, 3);
}

void rtTexCoord2f(RTfloat s, RTfloat t)
{
    const float v[2] = {s, t};
    set_attribute("rtTexCoord2f", ATTR_TEXCOORD, v, 2);
}

void rtTexCoord2fv(const RTfloat *v)
{
    set_attribute("rtTexCoord2fv", ATTR_TEXCOORD, v, 2);
}

/* Projective texture coordinates (s, t, r, q): GL interpolates all four
 * and divides s and t by q per fragment (OpenGL 1.1 sec. 3.8). */
void rtTexCoord4f(RTfloat s, RTfloat t, RTfloat r, RTfloat q)
{
    const float v[4] = {s, t, r, q};
    set_attribute("rtTexCoord4f", ATTR_TEXCOORD, v, 4);
}

void rtTexCoord4fv(const RTfloat *v)
{
    set_attribute("rtTexCoord4fv", ATTR_TEXCOORD, v, 4);
}

void rtTexCoord4d(RTdouble s, RTdouble t, RTdouble r, RTdouble q)
{
    const float v[4] = {(float)s, (float)t, (float)r, (float)q};
    set_attribute("rtTexCoord4d", ATTR_TEXCOORD, v, 4);
}

void rtTexCoord4dv(const RTdouble *v)
{
    float f[4];
    if (v)
        for (int i = 0; i < 4; i++)
            f[i] = (float)v[i];
    set_attribute("rtTexCoord4dv", ATTR_TEXCOORD, v ? f : NULL, 4);
}

void rtTexCoord4i(RTint s, RTint t, RTint r, RTint q)
{
    const float v[4] = {(float)s, (float)t, (float)r, (float)q};
    set_attribute("rtTexCoord4i", ATTR_TEXCOORD, v, 4);
}

void rtTexCoord4iv(const RTint *v)
{
    float f[4];
    if (v)
        for (int i = 0; i < 4; i++)
            f[i] = (float)v[i];
    set_attribute("rtTexCoord4iv", ATTR_TEXCOORD, v ? f : NULL, 4);
}

void rtTexCoord4s(RTshort s, RTshort t, RTshort r, RTshort q)
{
    const float v[4] = {s, t, r, q};
    set_attribute("rtTexCoord4s", ATTR_TEXCOORD, v, 4);
}

void rtTexCoord4sv(const RTshort *v)
{
    float f[4];
    if (v)
        for (int i = 0; i < 4; i++)
            f[i] = v[i];
    set_attribute("rtTexCoord4sv", ATTR_TEXCOORD, v ? f : NULL, 4);
}

void rtColor3f(RTfloat r, RTfloat g, RTfloat b)
{
    const float v[3] = {r, g, b};
    set_attribute("rtColor3f", ATTR_COLOR, v, 3);
}

void rtColor3fv(const RTfloat *v)
{
    set_attribute("rtColor3fv", ATTR_COLOR, v, 3);
}

void rtColor4f(RTfloat r, RTfloat g, RTfloat b, RTfloat a)
{
    const float v[4] = {r, g, b, a};
    set_attribute("rtColor4f", ATTR_COLOR, v, 4);
}

void rtColor4fv(const RTfloat *v)
{
    set_attribute("rtColor4fv", ATTR_COLOR, v, 4);
}

void rtShadeModel(RTenum mode)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtShadeModel"))
        return;
    if (mode != RT_FLAT && mode != RT_SMOOTH) {
        rt_error(ctx, RT_INVALID_ENUM, "rtShadeModel(mode=0x%x)", mode);
        return;
    }
    rt_list_state(ctx, LIST_SHADE_MODEL, mode, 0, NULL, 0);
    ctx->shade_model = mode;
}
