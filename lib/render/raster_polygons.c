/* SPDX-License-Identifier: Apache-2.0 */
/*
 * raster_polygons.c - triangles drawn in rtPolygonMode RT_LINE or
 * RT_POINT by the face they show (raster.h, scene/mesh.h).
 *
 * GL decides per polygon whether it is front or back facing from the
 * sign of its area in window coordinates and the rtFrontFace winding
 * (OpenGL 2.1 sec. 2.14.1, eq. 2.6), culls it by that face (sec. 3.5.1),
 * and only then rasterises it in the polygon mode of that face: filled,
 * its boundary edges as lines, or its vertices as points (sec. 3.5.4).
 * The filled faces are the ray tracer's: camera rays pass the faces that
 * are not filled (render/gl_shade.c).  This file draws the others, after
 * the image is traced, as the lines of raster_lines are drawn.  The
 * boundary is the one of the polygon the triangle came from: the
 * triangle's edge flags (scene_mesh.tri_edges) leave out the diagonals
 * of quads and polygons, as GL's edge flags do (sec. 2.6.2).
 *
 * The sign of the window-space area is taken from the clip coordinates
 * without the division: for the triangle (x_i, y_i, w_i) the determinant
 * of the rows (x_i, y_i, w_i) is w_0 w_1 w_2 times twice the area in
 * normalised device coordinates (Olano and Greer 1997, sec. 3), and the
 * part of the triangle that survives clipping (w > 0) keeps its sign, so
 * a triangle crossing the eye plane gets the face of its visible part.
 */
#include "render/raster.h"

#include <string.h>

#include "base/mat4.h"
#include "render/surface.h"
#include "scene/frame.h"

#define POLYGON_MODE_BITS (SCENE_MATERIAL_POLYGON_MODE_FRONT | SCENE_MATERIAL_POLYGON_MODE_BACK)

/* 1 when some triangle of the mesh may show a face not filled under the
 * call's state `call`: a recorded mode other than RT_FILL, or an
 * inherited one while the call's is not RT_FILL. */
static int has_unfilled(const struct scene_mesh *mesh, const struct scene_material *call)
{
    const int call_unfilled = (call->polygon_mode[0] | call->polygon_mode[1]) != 0;
    for (uint32_t i = 0; i < mesh->material_count; i++) {
        const struct scene_material *m = &mesh->materials[i];
        if ((m->polygon_mode[0] | m->polygon_mode[1]) != 0 ||
            (call_unfilled && (m->inherit & POLYGON_MODE_BITS)))
            return 1;
    }
    return 0;
}

int raster_polygons_present(const struct scene_instance *inst)
{
    return inst->object->mesh.tri_count &&
           has_unfilled(&inst->object->mesh, &inst->appearance.material);
}

struct polygon_vertex {
    double eye[3], clip[4];
    const float *color;
};

static void vertex_of(const struct raster_target *target, const struct scene_mesh *mesh,
                      uint32_t v, const double object_to_eye[16], struct polygon_vertex *out)
{
    const float *p = &mesh->positions[3 * v];
    const double po[3] = {p[0], p[1], p[2]};
    mat4_transform_point(object_to_eye, po, out->eye);
    const double *m = target->projection;
    for (int r = 0; r < 4; r++)
        out->clip[r] = m[r] * out->eye[0] + m[4 + r] * out->eye[1] + m[8 + r] * out->eye[2] +
                       m[12 + r];
}

/* 1 when the triangle is counter-clockwise in window coordinates; a
 * degenerate one counts as counter-clockwise (Mesa: facing from the sign
 * bit of the area). */
static int counter_clockwise(const struct polygon_vertex v[3])
{
    const double *a = v[0].clip, *b = v[1].clip, *c = v[2].clip;
    const double det = a[0] * (b[1] * c[3] - b[3] * c[1]) - a[1] * (b[0] * c[3] - b[3] * c[0]) +
                       a[3] * (b[0] * c[1] - b[1] * c[0]);
    return !(det < 0.0);
}

void raster_polygons(const struct raster_target *target, const struct scene_instance *inst)
{
    const struct scene_mesh *mesh = &inst->object->mesh;
    const struct scene_appearance *call = &inst->appearance;
    if (!raster_polygons_present(inst))
        return;
    /* Triangles come in runs of one material: resolve it once per run. */
    uint32_t resolved_index = UINT32_MAX;
    struct scene_material m;
    for (uint32_t t = 0; t < mesh->tri_count; t++) {
        const uint32_t mi = mesh->tri_material[t];
        if (mi != resolved_index) {
            m = mesh->materials[mi];
            surface_resolve_material(call, &m);
            resolved_index = mi;
        }
        if ((m.polygon_mode[0] | m.polygon_mode[1]) == 0)
            continue; /* filled either way: traced */
        const uint32_t *idx = &mesh->indices[3 * t];
        struct polygon_vertex v[3];
        for (int i = 0; i < 3; i++)
            vertex_of(target, mesh, idx[i], inst->object_to_world, &v[i]);
        const int front = counter_clockwise(v) != (m.front_cw != 0);
        if (m.cull_face & (front ? SCENE_CULL_FRONT : SCENE_CULL_BACK))
            continue;
        const unsigned mode = m.polygon_mode[front ? 0 : 1];
        if (mode == 0)
            continue; /* this face is filled: traced */
        /* Colours as lines have them (raster.h): the vertices', or the
         * colour at the call for a list's triangles recorded before it set
         * one; under RT_FLAT the provoking vertex's. */
        uint8_t flags = mesh->tri_flags[t];
        if (flags & TRI_INHERIT_SHADE)
            flags = (uint8_t)((flags & ~TRI_FLAT) | (call->flat ? TRI_FLAT : 0u));
        const int flat = (flags & TRI_FLAT) != 0;
        const float *provoking = &mesh->colors[4 * mesh->tri_provoking[t]];
        for (int i = 0; i < 3; i++)
            v[i].color = (flags & TRI_INHERIT_COLOR) ? call->color
                         : flat                      ? provoking
                                                     : &mesh->colors[4 * idx[i]];
        const long width = raster_pixels(m.polygon_line_width, target->raster->line_width,
                                         RENDER_MAX_LINE_WIDTH);
        const long size = raster_pixels(m.polygon_point_size, target->raster->point_size,
                                        RENDER_MAX_POINT_SIZE);
        const unsigned edges = mesh->tri_edges[t];
        for (int i = 0; i < 3; i++) {
            if (!(edges >> i & 1u))
                continue;
            const struct polygon_vertex *a = &v[i], *b = &v[(i + 1) % 3];
            if (mode == RT_POINT)
                raster_point(target, a->eye, a->clip, a->color, size);
            else
                raster_segment(target, a->eye, b->eye, a->clip, b->clip, a->color, b->color,
                               flat, width);
        }
    }
}
