/* SPDX-License-Identifier: Apache-2.0 */
/*
 * recording.c - vertex recording and primitive assembly into the
 * recording mesh (see recording.h).
 */
#include "scene/recording.h"

#include <math.h>
#include <string.h>

#include <rt/rt.h>

#include "base/alloc.h"
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

void scene_block_start(struct scene_block *block, const struct scene_recording *rec,
                       unsigned mode, const double modelview[16])
{
    block->mode = mode;
    block->base = rec->mesh.vertex_count;
    block->count = 0;
    memcpy(block->position_matrix, modelview, sizeof(block->position_matrix));
    cofactor3(block->position_matrix, block->normal_matrix);
}

/* The vertex as stored: transformed, then rounded to float.  A finite
 * double beyond the float range does not fit either. */
static int transform(const struct scene_block *block, const double position[3], float out[3])
{
    double p[3];
    mat4_transform_point(block->position_matrix, position, p);
    for (int k = 0; k < 3; k++)
        out[k] = (float)p[k];
    return isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2]);
}

int scene_block_vertex_is_finite(const struct scene_block *block, const double position[3])
{
    float p[3];
    return transform(block, position, p);
}

/* The interned index of the current material together with the texture
 * triangles take now.  The texture is compared here rather than marked
 * stale by rtBindTexture, rtEnable and rtDeleteTextures, so no path can
 * forget it.  -1 on allocation failure (the next call tries again). */
static int current_material(struct scene_recording *rec, const struct scene_triangle_state *ts)
{
    if (rec->material_index < 0 || rec->material_texture != ts->texture ||
        rec->material_inherit != ts->inherit) {
        struct scene_material m = *ts->material;
        m.texture = ts->texture;
        m.inherit = ts->inherit;
        rec->material_index = scene_mesh_intern_material(&rec->mesh, &m);
        rec->material_texture = ts->texture;
        rec->material_inherit = ts->inherit;
    }
    return rec->material_index;
}

static enum scene_record_status out_of_memory(struct scene_recording *rec)
{
    rec->out_of_memory = 1;
    return SCENE_RECORD_OUT_OF_MEMORY;
}

/* Stores one vertex; the caller has reserved room. */
static enum scene_record_status store(struct scene_recording *rec,
                                      const struct scene_block *block, const double position[3],
                                      const float normal[3], const float color[4],
                                      const float texcoord[4])
{
    struct scene_mesh *mesh = &rec->mesh;
    float pf[3];
    if (!transform(block, position, pf))
        return SCENE_RECORD_NOT_FINITE;
    /* The first q other than 1: from here on the mesh keeps q, the
     * vertices before it having GL's default q = 1. */
    if (texcoord[3] != 1.0f && !mesh->texcoord_q) {
        float *q = rt_realloc_array(NULL, mesh->vertex_capacity, sizeof(float));
        if (!q)
            return out_of_memory(rec);
        for (uint32_t i = 0; i < mesh->vertex_count; i++)
            q[i] = 1.0f;
        mesh->texcoord_q = q;
    }
    uint32_t v = mesh->vertex_count++;
    memcpy(&mesh->positions[3 * v], pf, sizeof(pf));
    const double *nm = block->normal_matrix;
    for (int r = 0; r < 3; r++)
        mesh->normals[3 * v + r] =
            (float)(nm[r] * normal[0] + nm[3 + r] * normal[1] + nm[6 + r] * normal[2]);
    memcpy(&mesh->colors[4 * v], color, 4 * sizeof(float));
    memcpy(&mesh->texcoords[2 * v], texcoord, 2 * sizeof(float));
    if (mesh->texcoord_q)
        mesh->texcoord_q[v] = texcoord[3];
    return SCENE_RECORD_OK;
}

/* Appends the n assembled triangles; room and material were acquired.
 * With map, stream position j is mesh vertex map[j]. */
static void emit(struct scene_recording *rec, const struct scene_triangle_state *ts,
                 const struct scene_tri *tris, int n, const uint32_t *map)
{
    struct scene_mesh *mesh = &rec->mesh;
    for (int i = 0; i < n; i++) {
        uint32_t t = mesh->tri_count++;
        for (int c = 0; c < 3; c++)
            mesh->indices[3 * t + c] = map ? map[tris[i].v[c]] : tris[i].v[c];
        mesh->tri_provoking[t] = map ? map[tris[i].provoking] : tris[i].provoking;
        mesh->tri_material[t] = (uint16_t)rec->material_index;
        mesh->tri_flags[t] = ts->flags;
        mesh->tri_edges[t] = tris[i].edges;
    }
}

enum scene_record_status scene_record_vertex(struct scene_recording *rec,
                                             struct scene_block *block,
                                             const struct scene_triangle_state *ts,
                                             const double position[3], const float normal[3],
                                             const float color[4], const float texcoord[4])
{
    struct scene_mesh *mesh = &rec->mesh;
    /* Acquire everything this vertex can need before storing anything. */
    struct scene_tri tris[2];
    int n = scene_assemble(block->mode, block->base, block->count, tris);
    if (scene_mesh_reserve_vertices(mesh, 1) || scene_mesh_reserve_triangles(mesh, (uint32_t)n) ||
        (n && current_material(rec, ts) < 0))
        return out_of_memory(rec);
    enum scene_record_status status = store(rec, block, position, normal, color, texcoord);
    if (status != SCENE_RECORD_OK)
        return status;
    emit(rec, ts, tris, n, NULL);
    block->count++;
    return SCENE_RECORD_OK;
}

enum scene_record_status scene_store_vertex(struct scene_recording *rec,
                                            const struct scene_block *block,
                                            const double position[3], const float normal[3],
                                            const float color[4], const float texcoord[4])
{
    if (scene_mesh_reserve_vertices(&rec->mesh, 1))
        return out_of_memory(rec);
    return store(rec, block, position, normal, color, texcoord);
}

enum scene_record_status scene_assemble_indexed(struct scene_recording *rec,
                                                const struct scene_block *block,
                                                const struct scene_triangle_state *ts,
                                                uint32_t k, const uint32_t *map)
{
    struct scene_tri tris[2];
    int n = scene_assemble(block->mode, 0, k, tris);
    if (n == 0)
        return SCENE_RECORD_OK;
    if (current_material(rec, ts) < 0 ||
        scene_mesh_reserve_triangles(&rec->mesh, (uint32_t)n))
        return out_of_memory(rec);
    emit(rec, ts, tris, n, map);
    return SCENE_RECORD_OK;
}

void scene_block_close_polygon(struct scene_recording *rec, const struct scene_block *block,
                               uint32_t count)
{
    /* The block's triangles are the mesh's last ones: its last is the
     * polygon's last (fan triangle (0, count - 2, count - 1)). */
    if (block->mode == RT_POLYGON && count >= 3 && rec->mesh.tri_count > 0)
        rec->mesh.tri_edges[rec->mesh.tri_count - 1] |= SCENE_TRI_EDGE_2;
}

/* Display lists (see recording.h). */

static int push_op(struct scene_recording *rec, const struct scene_list_op *op)
{
    if (rec->op_count == rec->op_capacity) {
        uint32_t cap = rec->op_capacity ? 2 * rec->op_capacity : 16;
        if (cap < rec->op_capacity)
            return out_of_memory(rec), -1;
        void *p = rt_realloc_array(rec->ops, cap, sizeof(*rec->ops));
        if (!p)
            return out_of_memory(rec), -1;
        rec->ops = p;
        rec->op_capacity = cap;
    }
    rec->ops[rec->op_count++] = *op;
    return 0;
}

static int segment_op(struct scene_recording *rec)
{
    struct scene_list_op op;
    memset(&op, 0, sizeof(op));
    op.kind = SCENE_OP_SEGMENT;
    op.a = rec->segment_count;
    return push_op(rec, &op);
}

/* Ends the current segment and starts the next at the current operation:
 * the current level's matrix becomes the identity relative to it. */
/* 1 when a segment holds geometry: triangles' vertices, or lines and
 * points (a segment can hold only those, e.g. after RT_BLEND is enabled
 * in a list). */
static int segment_has_geometry(const struct scene_mesh *mesh)
{
    return mesh->vertex_count > 0 || mesh->lines.vertex_count > 0;
}

static int new_segment(struct scene_recording *rec)
{
    struct scene_list_op *last = rec->op_count ? &rec->ops[rec->op_count - 1] : NULL;
    if (!segment_has_geometry(&rec->mesh) && last && last->kind == SCENE_OP_SEGMENT &&
        last->a == rec->segment_count) {
        /* Nothing recorded since the segment started: restart it here. */
        rec->op_count--;
    } else {
        if (rec->segment_count == rec->segment_capacity) {
            uint32_t cap = rec->segment_capacity ? 2 * rec->segment_capacity : 4;
            void *p = rt_realloc_array(rec->segments, cap, sizeof(*rec->segments));
            if (!p)
                return out_of_memory(rec), -1;
            rec->segments = p;
            rec->segment_capacity = cap;
        }
        int has_normals = rec->mesh.has_normals;
        /* The width and size the list set go on applying to its later
         * lines and points (scene/lines.h). */
        float width = rec->mesh.lines.width, size = rec->mesh.lines.size;
        rec->segments[rec->segment_count++] = rec->mesh;
        memset(&rec->mesh, 0, sizeof(rec->mesh));
        rec->mesh.bounds = aabb_empty();
        rec->mesh.has_normals = has_normals;
        rec->mesh.lines.width = width;
        rec->mesh.lines.size = size;
        rec->material_index = -1;
    }
    mat4_identity(rec->stack[rec->depth - 1].m);
    rec->stack[rec->depth - 1].segment = rec->segment_count;
    return segment_op(rec);
}

int scene_list_split(struct scene_recording *rec)
{
    return new_segment(rec);
}

void scene_list_release(struct scene_recording *rec)
{
    for (uint32_t i = 0; i < rec->segment_count; i++)
        scene_mesh_release(&rec->segments[i]);
    rt_free(rec->segments);
    rt_free(rec->ops);
    rec->segments = NULL;
    rec->ops = NULL;
    rec->segment_count = rec->segment_capacity = 0;
    rec->op_count = rec->op_capacity = 0;
}

int scene_list_begin(struct scene_recording *rec, uint32_t name, unsigned matrix_mode)
{
    scene_list_release(rec);
    scene_mesh_release(&rec->mesh);
    rec->active = 1;
    rec->name = name;
    rec->out_of_memory = 0;
    rec->material_index = -1;
    rec->matrix_mode = matrix_mode;
    rec->depth = 1;
    mat4_identity(rec->stack[0].m);
    rec->stack[0].segment = 0;
    rec->material_set = 0;
    rec->color_set = rec->color_material_set = 0;
    rec->shade_model_set = 0;
    /* Keeps the operations' memory of the last list: no allocation for
     * lists of one segment after the first. */
    return segment_op(rec);
}

const double *scene_list_matrix(const struct scene_recording *rec)
{
    return rec->stack[rec->depth - 1].m;
}

int scene_list_matrix_op(struct scene_recording *rec, enum scene_list_op_kind kind,
                         unsigned mode, const double m[16])
{
    struct scene_list_op op;
    memset(&op, 0, sizeof(op));
    op.kind = (uint32_t)kind;
    op.a = mode;
    if (m)
        memcpy(op.v, m, sizeof(op.v));
    if (kind == SCENE_OP_MULT && rec->matrix_mode == RT_MODELVIEW) {
        /* A product that overflows is rejected as outside lists. */
        double r[16];
        mat4_mul(r, rec->stack[rec->depth - 1].m, m);
        if (!mat4_is_finite(r))
            return -2;
    }
    if (push_op(rec, &op))
        return -1;
    if (kind == SCENE_OP_MATRIX_MODE) {
        rec->matrix_mode = mode;
        return 0;
    }
    if (rec->matrix_mode != RT_MODELVIEW)
        return 0; /* the projection does not move vertices */
    switch (kind) {
    case SCENE_OP_LOAD:
        /* The replay holds exactly m from here: a segment of its own. */
        return new_segment(rec);
    case SCENE_OP_MULT: {
        double r[16];
        mat4_mul(r, rec->stack[rec->depth - 1].m, m);
        memcpy(rec->stack[rec->depth - 1].m, r, sizeof(r));
        return 0;
    }
    case SCENE_OP_PUSH:
        if (rec->depth < SCENE_LIST_MAX_PUSH) {
            rec->stack[rec->depth] = rec->stack[rec->depth - 1];
            rec->depth++;
        }
        return 0;
    case SCENE_OP_POP:
        if (rec->depth > 1) {
            rec->depth--;
            if (rec->stack[rec->depth - 1].segment == rec->segment_count)
                return 0; /* back to a level of this segment: known */
        }
        /* A level of an earlier segment, or the caller's: start anew. */
        return new_segment(rec);
    default:
        return 0;
    }
}

int scene_list_call(struct scene_recording *rec, uint32_t name, int add_base)
{
    struct scene_list_op op;
    memset(&op, 0, sizeof(op));
    op.kind = SCENE_OP_CALL;
    op.a = name;
    op.b = add_base ? 1u : 0u;
    if (push_op(rec, &op))
        return -1;
    /* The callee may change the matrix, the material and the colour. */
    rec->material_set = 0;
    rec->color_set = rec->color_material_set = 0;
    rec->shade_model_set = 0;
    return new_segment(rec);
}

int scene_list_state(struct scene_recording *rec, uint32_t what, uint32_t b, uint32_t c,
                     const float *v, int n)
{
    /* The op keeps doubles: every float converts exactly. */
    double d[16];
    for (int i = 0; i < n && i < 16; i++)
        d[i] = v[i];
    return scene_list_state_d(rec, what, b, c, d, n);
}

int scene_list_state_d(struct scene_recording *rec, uint32_t what, uint32_t b, uint32_t c,
                       const double *v, int n)
{
    struct scene_list_op op;
    memset(&op, 0, sizeof(op));
    op.kind = SCENE_OP_STATE;
    op.a = what;
    op.b = b;
    op.c = c;
    for (int i = 0; i < n && i < 16; i++)
        op.v[i] = v[i];
    return push_op(rec, &op);
}

uint32_t scene_list_segment_count(const struct scene_recording *rec)
{
    return rec->segment_count + 1;
}

int scene_list_finish(struct scene_recording *rec, struct scene_mesh **meshes,
                      uint32_t *mesh_count, struct scene_list_op **ops, uint32_t *op_count,
                      uint32_t *map)
{
    /* The current segment joins the finished ones. */
    uint32_t total = rec->segment_count + 1;
    struct scene_mesh *all = rt_realloc_array(rec->segments, total, sizeof(*all));
    if (!all)
        return out_of_memory(rec), -1;
    rec->segments = all;
    rec->segment_capacity = total;
    all[rec->segment_count++] = rec->mesh;
    memset(&rec->mesh, 0, sizeof(rec->mesh));
    rec->mesh.bounds = aabb_empty();
    uint32_t kept = 0, with_vertices = 0;
    for (uint32_t i = 0; i < total; i++)
        with_vertices += segment_has_geometry(&all[i]);
    for (uint32_t i = 0; i < total; i++) {
        uint32_t to = UINT32_MAX;
        /* Empty segments go; the first stays the object's mesh when no
         * segment has vertices (rtUpdateVertices numbers a mesh's vertices
         * even without triangles, an empty list is still an object). */
        if (segment_has_geometry(&all[i]) || (i == 0 && with_vertices == 0)) {
            to = kept;
            all[kept++] = all[i];
        } else {
            scene_mesh_release(&all[i]);
        }
        if (map)
            map[i] = to;
        /* Renumber in place: segment ops are in increasing order. */
        for (uint32_t k = 0; k < rec->op_count; k++)
            if (rec->ops[k].kind == SCENE_OP_SEGMENT && rec->ops[k].a == i)
                rec->ops[k].a = to;
    }
    uint32_t n = 0;
    for (uint32_t k = 0; k < rec->op_count; k++)
        if (rec->ops[k].kind != SCENE_OP_SEGMENT || rec->ops[k].a != UINT32_MAX)
            rec->ops[n++] = rec->ops[k];
    *meshes = all;
    *mesh_count = kept;
    *ops = rec->ops;
    *op_count = n;
    rec->segments = NULL;
    rec->segment_count = rec->segment_capacity = 0;
    rec->ops = NULL;
    rec->op_count = rec->op_capacity = 0;
    return 0;
}
