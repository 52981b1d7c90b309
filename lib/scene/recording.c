/* SPDX-License-Identifier: Apache-2.0 */
/*
 * recording.c - vertex recording and primitive assembly into the
 * recording mesh (see recording.h).
 */
#include "scene/recording.h"

#include <math.h>
#include <string.h>

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
    if (rec->material_index < 0 || rec->material_texture != ts->texture) {
        struct scene_material m = *ts->material;
        m.texture = ts->texture;
        rec->material_index = scene_mesh_intern_material(&rec->mesh, &m);
        rec->material_texture = ts->texture;
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
                                      const float texcoord[2])
{
    struct scene_mesh *mesh = &rec->mesh;
    float pf[3];
    if (!transform(block, position, pf))
        return SCENE_RECORD_NOT_FINITE;
    uint32_t v = mesh->vertex_count++;
    memcpy(&mesh->positions[3 * v], pf, sizeof(pf));
    const double *nm = block->normal_matrix;
    for (int r = 0; r < 3; r++)
        mesh->normals[3 * v + r] =
            (float)(nm[r] * normal[0] + nm[3 + r] * normal[1] + nm[6 + r] * normal[2]);
    memcpy(&mesh->colors[4 * v], color, 4 * sizeof(float));
    memcpy(&mesh->texcoords[2 * v], texcoord, 2 * sizeof(float));
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
    }
}

enum scene_record_status scene_record_vertex(struct scene_recording *rec,
                                             struct scene_block *block,
                                             const struct scene_triangle_state *ts,
                                             const double position[3], const float normal[3],
                                             const float color[4], const float texcoord[2])
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
                                            const float color[4], const float texcoord[2])
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
