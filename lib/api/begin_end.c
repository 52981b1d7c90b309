/*
 * begin_end.c - rtBegin/rtEnd, rtVertex*, current attributes, rtShadeModel
 * and the recording of vertices into the object being defined.
 *
 * As in OpenGL, a vertex is transformed by the modelview current at the
 * call and its normal by the inverse transpose; the modelview cannot
 * change inside rtBegin/rtEnd, so both matrices are fixed per block.  We
 * transform normals by the cofactor matrix (det * inverse transpose):
 * same direction up to sign, and defined for singular matrices too;
 * shading normalises and faces normals towards the ray anyway.
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "base/mat4.h"
#include "scene/assembly.h"

/* Cofactor matrix of the upper 3x3 of m (column-major 3x3 out). */
static void cofactor3(const double m[16], double out[9])
{
    const double a = m[0], b = m[4], c = m[8];
    const double d = m[1], e = m[5], f = m[9];
    const double g = m[2], h = m[6], i = m[10];
    /* out maps an object-space normal to eye space: n' = C n, C = cof(M). */
    double C[3][3] = {{e * i - f * h, -(d * i - f * g), d * h - e * g},
                      {-(b * i - c * h), a * i - c * g, -(a * h - b * g)},
                      {b * f - c * e, -(a * f - c * d), a * e - b * d}};
    /* C[r][c] is the cofactor of element (r, c); n'_r = sum_c C[r][c] n_c. */
    for (int r = 0; r < 3; r++)
        for (int col = 0; col < 3; col++)
            out[col * 3 + r] = C[r][col];
}

void rt_block_start(struct rt_context *ctx, RTenum mode)
{
    struct primitive_block *b = &ctx->block;
    b->mode = mode;
    b->base = ctx->recording.mesh.vertex_count;
    b->count = 0;
    memcpy(b->position_matrix, ctx->modelview.m[ctx->modelview.depth - 1],
           sizeof(b->position_matrix));
    cofactor3(b->position_matrix, b->normal_matrix);
}

int rt_vertex_is_finite(const struct rt_context *ctx, const double position[3])
{
    /* The same test rt_record_vertex makes: the vertex is stored as float,
     * so a finite double beyond the float range does not fit either. */
    double p[3];
    mat4_transform_point(ctx->block.position_matrix, position, p);
    return isfinite((float)p[0]) && isfinite((float)p[1]) && isfinite((float)p[2]);
}

/* The interned index of the current material together with the texture
 * triangles take now: the bound texture while RT_TEXTURE_2D is enabled,
 * else 0.  The texture is compared here rather than marked stale by
 * rtBindTexture, rtEnable and rtDeleteTextures, so no path can forget it.
 * -1 on allocation failure (the next call tries again). */
static int current_material(struct rt_context *ctx)
{
    struct object_recording *rec = &ctx->recording;
    uint32_t texture = ctx->texture_2d ? ctx->texture_binding : 0;
    if (rec->material_index < 0 || rec->material_texture != texture) {
        struct scene_material m = ctx->material;
        m.texture = texture;
        rec->material_index = scene_mesh_intern_material(&rec->mesh, &m);
        rec->material_texture = texture;
    }
    return rec->material_index;
}

/* Stores one vertex (transformed) without assembling; the caller has
 * reserved room.  Returns 0, or -1 after recording RT_INVALID_VALUE. */
static int store_vertex(struct rt_context *ctx, const char *caller, const double position[3],
                        const float normal[3], const float color[4], const float texcoord[2])
{
    struct primitive_block *b = &ctx->block;
    struct scene_mesh *mesh = &ctx->recording.mesh;
    double p[3];
    mat4_transform_point(b->position_matrix, position, p);
    float pf[3] = {(float)p[0], (float)p[1], (float)p[2]};
    if (!isfinite(pf[0]) || !isfinite(pf[1]) || !isfinite(pf[2])) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "%s: vertex (%g, %g, %g) is not finite under the modelview matrix", caller,
                 position[0], position[1], position[2]);
        return -1;
    }
    uint32_t v = mesh->vertex_count++;
    memcpy(&mesh->positions[3 * v], pf, sizeof(pf));
    const double *nm = b->normal_matrix;
    for (int r = 0; r < 3; r++)
        mesh->normals[3 * v + r] =
            (float)(nm[r] * normal[0] + nm[3 + r] * normal[1] + nm[6 + r] * normal[2]);
    memcpy(&mesh->colors[4 * v], color, 4 * sizeof(float));
    memcpy(&mesh->texcoords[2 * v], texcoord, 2 * sizeof(float));
    return 0;
}

static int out_of_memory(struct rt_context *ctx, const char *caller)
{
    ctx->recording.out_of_memory = 1;
    rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory recording object %u", caller,
             ctx->recording.name);
    return -1;
}

/* Stores the triangles completed by stream position k of the block; with
 * map, stream position j is mesh vertex map[j] (indexed drawing), else
 * block base + j.  Acquires its memory first: -1 (recorded) changes
 * nothing. */
static int assemble(struct rt_context *ctx, const char *caller, uint32_t k, const uint32_t *map)
{
    struct primitive_block *b = &ctx->block;
    struct scene_mesh *mesh = &ctx->recording.mesh;
    struct scene_tri tris[2];
    int n = scene_assemble(b->mode, map ? 0 : b->base, k, tris);
    if (n == 0)
        return 0;
    int material = current_material(ctx);
    if (material < 0 || scene_mesh_reserve_triangles(mesh, (uint32_t)n))
        return out_of_memory(ctx, caller);
    uint8_t flags = (uint8_t)((ctx->shade_model == RT_FLAT ? TRI_FLAT : 0u) |
                              (ctx->color_material ? TRI_COLOR_MATERIAL : 0u));
    for (int i = 0; i < n; i++) {
        uint32_t t = mesh->tri_count++;
        for (int c = 0; c < 3; c++)
            mesh->indices[3 * t + c] = map ? map[tris[i].v[c]] : tris[i].v[c];
        mesh->tri_provoking[t] = map ? map[tris[i].provoking] : tris[i].provoking;
        mesh->tri_material[t] = (uint16_t)material;
        mesh->tri_flags[t] = flags;
    }
    return 0;
}

int rt_record_vertex(struct rt_context *ctx, const char *caller, const double position[3],
                     const float normal[3], const float color[4], const float texcoord[2])
{
    struct primitive_block *b = &ctx->block;
    struct scene_mesh *mesh = &ctx->recording.mesh;
    /* Acquire everything this vertex can need before storing anything. */
    struct scene_tri tris[2];
    int n = scene_assemble(b->mode, b->base, b->count, tris);
    if (scene_mesh_reserve_vertices(mesh, 1) || scene_mesh_reserve_triangles(mesh, (uint32_t)n) ||
        (n && current_material(ctx) < 0))
        return out_of_memory(ctx, caller);
    if (store_vertex(ctx, caller, position, normal, color, texcoord))
        return -1;
    /* Cannot fail now: room and material were acquired above. */
    assemble(ctx, caller, b->count, NULL);
    b->count++;
    return 0;
}

int rt_store_vertex(struct rt_context *ctx, const char *caller, const double position[3],
                    const float normal[3], const float color[4], const float texcoord[2])
{
    if (scene_mesh_reserve_vertices(&ctx->recording.mesh, 1))
        return out_of_memory(ctx, caller);
    return store_vertex(ctx, caller, position, normal, color, texcoord);
}

int rt_assemble_indexed(struct rt_context *ctx, const char *caller, uint32_t k,
                        const uint32_t *map)
{
    return assemble(ctx, caller, k, map);
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
    if (!ctx->recording.active) {
        rt_error(ctx, RT_INVALID_OPERATION,
                 "rtBegin(mode=0x%x): primitives are only recorded inside rtNewObject", mode);
        return;
    }
    if (!scene_mode_is_valid(mode)) {
        rt_error(ctx, RT_INVALID_ENUM, "rtBegin(mode=0x%x)", mode);
        return;
    }
    rt_block_start(ctx, mode);
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
}

static void vertex(const char *caller, double x, double y, double z)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    if (!ctx->block.active) {
        rt_error(ctx, RT_INVALID_OPERATION, "%s: only allowed between rtBegin and rtEnd", caller);
        return;
    }
    double p[3] = {x, y, z};
    if (!rt_check_finite_d(ctx, caller, p, 3))
        return;
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
    if (!ctx->block.active) {
        rt_error(ctx, RT_INVALID_OPERATION, "%s: only allowed between rtBegin and rtEnd", caller);
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
        /* An object that never sets a normal is shaded with geometric
         * normals instead of GL's default (0, 0, 1). */
        if (ctx->recording.active)
            ctx->recording.mesh.has_normals = 1;
        break;
    case ATTR_TEXCOORD:
        memcpy(ctx->current_texcoord, src, 2 * sizeof(float));
        break;
    case ATTR_COLOR:
        for (int i = 0; i < 4; i++)
            ctx->current_color[i] = i < n ? fminf(fmaxf(src[i], 0.0f), 1.0f) : 1.0f;
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
    ctx->shade_model = mode;
}
