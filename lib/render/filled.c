/* SPDX-License-Identifier: Apache-2.0 */
/*
 * filled.c - which face of a hit a ray meets, and whether it is filled
 * (filled.h).  The walk that passes the faces not filled is the hit
 * filter of the trace layer (render/secondary.c, trace/scene_filter.h):
 * it skips a rejected triangle inside the walk, so a filled surface in
 * the plane of an outlined one is met.
 */
#include "render/filled.h"

#include "render/raster.h"

int filled_frame_has_unfilled(const struct scene_frame *frame)
{
    for (uint32_t i = 0; i < frame->committed.count; i++)
        if (raster_polygons_present(&frame->committed.items[i]))
            return 1;
    return 0;
}

int filled_face(const struct scene_frame *frame, const struct trace_scene *scene,
                const float dir[3], const struct trace_scene_hit *hit)
{
    const struct scene_instance *inst =
        &frame->committed.items[scene->instances[hit->instance].instance_id];
    const struct scene_mesh *mesh = &inst->object->mesh;
    const struct scene_material *m = &mesh->materials[mesh->tri_material[hit->prim]];
    const struct scene_material *c = &inst->appearance.material;
    /* The modes as surface_resolve_material resolves them: a list's
     * triangles that set none take the call's. */
    const unsigned front_mode =
        (m->inherit & SCENE_MATERIAL_POLYGON_MODE_FRONT) ? c->polygon_mode[0] : m->polygon_mode[0];
    const unsigned back_mode =
        (m->inherit & SCENE_MATERIAL_POLYGON_MODE_BACK) ? c->polygon_mode[1] : m->polygon_mode[1];
    if ((front_mode | back_mode) == 0)
        return 1;
    const int front_cw = (m->inherit & SCENE_MATERIAL_FRONT_FACE) ? c->front_cw : m->front_cw;
    /* The side the ray comes from, in world (eye) space as gl_shade.c's
     * is_front decides it for camera rays. */
    double p[3][3];
    scene_instance_world_triangle(inst, hit->prim, p);
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = p[1][k] - p[0][k];
        e2[k] = p[2][k] - p[0][k];
    }
    const double ng[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                          e1[0] * e2[1] - e1[1] * e2[0]};
    const int counter_clockwise = ng[0] * dir[0] + ng[1] * dir[1] + ng[2] * dir[2] < 0.0;
    const int front = front_cw ? !counter_clockwise : counter_clockwise;
    return (front ? front_mode : back_mode) == 0;
}
