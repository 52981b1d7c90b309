/* SPDX-License-Identifier: Apache-2.0 */
/*
 * mesh.c - storage of object definitions (see mesh.h).
 */
#include "scene/mesh.h"

#include <string.h>

#include <rt/rt.h>

#include "base/alloc.h"

void scene_material_default(struct scene_material *m)
{
    static const float ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f};
    static const float diffuse[4] = {0.8f, 0.8f, 0.8f, 1.0f};
    static const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    memset(m, 0, sizeof(*m));
    memcpy(m->ambient, ambient, sizeof(ambient));
    memcpy(m->diffuse, diffuse, sizeof(diffuse));
    memcpy(m->specular, black, sizeof(black));
    memcpy(m->emission, black, sizeof(black));
    m->shininess = 0.0f;
    m->reflectivity = 0.0f;
    m->transparency = 0.0f;
    m->ior = 1.0f;
    m->texture = 0;
    memcpy(m->back_ambient, ambient, sizeof(ambient));
    memcpy(m->back_diffuse, diffuse, sizeof(diffuse));
    memcpy(m->back_specular, black, sizeof(black));
    memcpy(m->back_emission, black, sizeof(black));
    m->back_shininess = 0.0f;
    /* GL's defaults: RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, RT_MODULATE. */
    m->color_material_face = RT_FRONT_AND_BACK;
    m->color_material_mode = RT_AMBIENT_AND_DIFFUSE;
    m->tex_env_mode = RT_MODULATE;
}

void scene_mesh_release(struct scene_mesh *mesh)
{
    rt_free(mesh->positions);
    rt_free(mesh->normals);
    rt_free(mesh->colors);
    rt_free(mesh->texcoords);
    rt_free(mesh->texcoord_q);
    rt_free(mesh->indices);
    rt_free(mesh->tri_provoking);
    rt_free(mesh->tri_material);
    rt_free(mesh->tri_flags);
    rt_free(mesh->tri_edges);
    rt_free(mesh->materials);
    scene_lines_release(&mesh->lines);
    memset(mesh, 0, sizeof(*mesh));
    mesh->bounds = aabb_empty();
}

/* Grows one array to `capacity` elements; on failure the old array stays. */
static int grow(void **array, uint32_t capacity, size_t element_size)
{
    void *p = rt_realloc_array(*array, capacity, element_size);
    if (!p)
        return -1;
    *array = p;
    return 0;
}

static uint32_t next_capacity(uint32_t current, uint32_t needed)
{
    uint64_t c = current ? current : 64;
    while (c < needed)
        c *= 2;
    return c > UINT32_MAX ? UINT32_MAX : (uint32_t)c;
}

int scene_mesh_reserve_vertices(struct scene_mesh *mesh, uint32_t extra)
{
    if (extra > UINT32_MAX - mesh->vertex_count)
        return -1;
    uint32_t needed = mesh->vertex_count + extra;
    if (needed <= mesh->vertex_capacity)
        return 0;
    uint32_t cap = next_capacity(mesh->vertex_capacity, needed);
    /* Each array is grown independently; a partial failure leaves the
     * grown ones larger than vertex_capacity says, which is harmless. */
    if (grow((void **)&mesh->positions, cap, 3 * sizeof(float)) ||
        grow((void **)&mesh->normals, cap, 3 * sizeof(float)) ||
        grow((void **)&mesh->colors, cap, 4 * sizeof(float)) ||
        grow((void **)&mesh->texcoords, cap, 2 * sizeof(float)) ||
        (mesh->texcoord_q && grow((void **)&mesh->texcoord_q, cap, sizeof(float))))
        return -1;
    mesh->vertex_capacity = cap;
    return 0;
}

int scene_mesh_reserve_triangles(struct scene_mesh *mesh, uint32_t extra)
{
    if (extra > UINT32_MAX / 3 - mesh->tri_count)
        return -1;
    uint32_t needed = mesh->tri_count + extra;
    if (needed <= mesh->tri_capacity)
        return 0;
    uint32_t cap = next_capacity(mesh->tri_capacity, needed);
    if (grow((void **)&mesh->indices, cap, 3 * sizeof(uint32_t)) ||
        grow((void **)&mesh->tri_provoking, cap, sizeof(uint32_t)) ||
        grow((void **)&mesh->tri_material, cap, sizeof(uint16_t)) ||
        grow((void **)&mesh->tri_flags, cap, sizeof(uint8_t)) ||
        grow((void **)&mesh->tri_edges, cap, sizeof(uint8_t)))
        return -1;
    mesh->tri_capacity = cap;
    return 0;
}

int scene_mesh_intern_material(struct scene_mesh *mesh, const struct scene_material *m)
{
    /* Objects use few materials; the last one is by far the most likely
     * match, so search backwards. */
    for (uint32_t i = mesh->material_count; i-- > 0;)
        if (memcmp(&mesh->materials[i], m, sizeof(*m)) == 0)
            return (int)i;
    if (mesh->material_count >= UINT16_MAX)
        return -1;
    if (mesh->material_count == mesh->material_capacity) {
        uint32_t cap = mesh->material_capacity ? 2 * mesh->material_capacity : 4;
        if (grow((void **)&mesh->materials, cap, sizeof(*m)))
            return -1;
        mesh->material_capacity = cap;
    }
    mesh->materials[mesh->material_count] = *m;
    return (int)mesh->material_count++;
}

void scene_mesh_compute_bounds(struct scene_mesh *mesh)
{
    mesh->bounds = aabb_empty();
    for (uint32_t i = 0; i < 3 * mesh->tri_count; i++)
        aabb_grow_point(&mesh->bounds, &mesh->positions[3 * mesh->indices[i]]);
}
