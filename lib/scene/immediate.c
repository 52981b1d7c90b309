/* SPDX-License-Identifier: Apache-2.0 */
/*
 * immediate.c - immediate-mode geometry of a frame: segments, their slots
 * and the comparison with the previous frame (see frame.h).
 */
#include <string.h>

#include "base/alloc.h"
#include "base/mat4.h"
#include "scene/frame.h"

/* 1 when the two line stores hold the same lines and points. */
static int same_lines(const struct scene_lines *a, const struct scene_lines *b)
{
    if (a->vertex_count != b->vertex_count || a->segment_count != b->segment_count ||
        a->point_count != b->point_count || a->width != b->width || a->size != b->size)
        return 0;
    size_t v = a->vertex_count;
    return (v == 0 || (memcmp(a->positions, b->positions, 3 * v * sizeof(float)) == 0 &&
                       memcmp(a->colors, b->colors, 4 * v * sizeof(float)) == 0)) &&
           (a->segment_count == 0 ||
            memcmp(a->segments, b->segments, a->segment_count * sizeof(*a->segments)) == 0) &&
           (a->point_count == 0 ||
            memcmp(a->points, b->points, a->point_count * sizeof(*a->points)) == 0);
}

/* 1 when the two meshes are the same definition, array by array. */
static int same_mesh(const struct scene_mesh *a, const struct scene_mesh *b)
{
    if (a->vertex_count != b->vertex_count || a->tri_count != b->tri_count ||
        a->material_count != b->material_count || a->has_normals != b->has_normals ||
        !same_lines(&a->lines, &b->lines))
        return 0;
    size_t v = a->vertex_count, t = a->tri_count;
    if (v == 0 || t == 0)
        return 1;
    return memcmp(a->positions, b->positions, 3 * v * sizeof(float)) == 0 &&
           memcmp(a->indices, b->indices, 3 * t * sizeof(uint32_t)) == 0 &&
           memcmp(a->normals, b->normals, 3 * v * sizeof(float)) == 0 &&
           memcmp(a->colors, b->colors, 4 * v * sizeof(float)) == 0 &&
           memcmp(a->texcoords, b->texcoords, 2 * v * sizeof(float)) == 0 &&
           !a->texcoord_q == !b->texcoord_q &&
           (!a->texcoord_q || memcmp(a->texcoord_q, b->texcoord_q, v * sizeof(float)) == 0) &&
           memcmp(a->tri_provoking, b->tri_provoking, t * sizeof(uint32_t)) == 0 &&
           memcmp(a->tri_material, b->tri_material, t * sizeof(uint16_t)) == 0 &&
           memcmp(a->tri_flags, b->tri_flags, t * sizeof(uint8_t)) == 0 &&
           memcmp(a->tri_edges, b->tri_edges, t * sizeof(uint8_t)) == 0 &&
           memcmp(a->materials, b->materials, a->material_count * sizeof(*a->materials)) == 0;
}

/* Moves the open segment's mesh to its slot's staging place. */
static void stage_open(struct scene_immediate *im)
{
    if (!im->open)
        return;
    im->open = 0;
    uint32_t i = im->used - 1;
    scene_mesh_release(&im->staged[i]);
    if (im->rec.out_of_memory)
        scene_mesh_release(&im->rec.mesh); /* recorded as an error: empty */
    im->staged[i] = im->rec.mesh;
    memset(&im->rec.mesh, 0, sizeof(im->rec.mesh));
    im->is_staged[i] = 1;
}

void scene_immediate_close(struct scene_frame *frame)
{
    stage_open(&frame->immediate);
}

void scene_immediate_commit(struct scene_frame *frame, uint64_t frame_number)
{
    struct scene_immediate *im = &frame->immediate;
    stage_open(im);
    for (uint32_t i = 0; i < im->used; i++) {
        if (!im->is_staged[i])
            continue;
        im->is_staged[i] = 0;
        struct scene_object *slot = im->slots[i];
        struct scene_mesh *mesh = &im->staged[i];
        scene_mesh_compute_bounds(mesh);
        if (slot->defined && same_mesh(&slot->mesh, mesh)) {
            /* Re-sent unchanged: a comparison, no change, no build. */
            scene_mesh_release(mesh);
            im->kept++;
            continue;
        }
        /* Same connectivity keeps the structure for a refit (object.c). */
        scene_object_define(NULL, slot, mesh, frame_number);
        im->redefined++;
    }
}

void scene_immediate_restart(struct scene_immediate *im)
{
    scene_mesh_release(&im->rec.mesh);
    im->open = 0;
    for (uint32_t i = 0; i < im->capacity; i++)
        if (im->is_staged[i]) {
            scene_mesh_release(&im->staged[i]);
            im->is_staged[i] = 0;
        }
    im->used = 0;
}

void scene_immediate_release(struct scene_immediate *im)
{
    scene_immediate_restart(im);
    for (uint32_t i = 0; i < im->capacity; i++)
        scene_object_free(im->slots[i]);
    rt_free(im->slots);
    rt_free(im->staged);
    rt_free(im->is_staged);
    memset(im, 0, sizeof(*im));
}

static int slot_reserve(struct scene_immediate *im)
{
    if (im->used < im->capacity)
        return 0;
    uint32_t cap = im->capacity ? 2 * im->capacity : 8;
    if (cap < im->capacity)
        return -1;
    struct scene_object **slots = rt_calloc(cap, sizeof(*slots));
    struct scene_mesh *staged = rt_calloc(cap, sizeof(*staged));
    uint8_t *is_staged = rt_calloc(cap, 1);
    if (!slots || !staged || !is_staged) {
        rt_free(slots);
        rt_free(staged);
        rt_free(is_staged);
        return -1;
    }
    if (im->capacity) {
        memcpy(slots, im->slots, im->capacity * sizeof(*slots));
        memcpy(staged, im->staged, im->capacity * sizeof(*staged));
        memcpy(is_staged, im->is_staged, im->capacity);
    }
    rt_free(im->slots);
    rt_free(im->staged);
    rt_free(im->is_staged);
    im->slots = slots;
    im->staged = staged;
    im->is_staged = is_staged;
    im->capacity = cap;
    return 0;
}

struct scene_recording *scene_immediate_segment(struct scene_frame *frame,
                                                const double modelview[16],
                                                const struct scene_clip *clip,
                                                const struct scene_gl_state *gl,
                                                const struct scene_raster *raster)
{
    struct scene_immediate *im = &frame->immediate;
    /* A change of clip planes starts a segment too: the planes are its
     * instance's (clip.h), as GL clips by those current at the draw;
     * so does a change of fog or light model (gl_state.h) or of blend or
     * alpha-test state (raster_state.h). */
    if (frame->open && im->open && memcmp(im->matrix, modelview, sizeof(im->matrix)) == 0 &&
        memcmp(&im->clip, clip, sizeof(*clip)) == 0 && memcmp(&im->gl, gl, sizeof(*gl)) == 0 &&
        memcmp(&im->raster, raster, sizeof(*raster)) == 0)
        return &im->rec;
    if (!frame->open)
        scene_frame_begin(frame); /* the first geometry of a new frame */
    if (slot_reserve(im) ||
        (!im->slots[im->used] && !(im->slots[im->used] = scene_object_create_hidden())))
        return NULL;
    double inverse[16], normal[16], identity[16];
    mat4_identity(identity);
    const double *instance = modelview;
    memcpy(im->block_matrix, identity, sizeof(identity));
    if (modelview[3] != 0.0 || modelview[7] != 0.0 || modelview[11] != 0.0 ||
        modelview[15] != 1.0 || !mat4_invert(inverse, modelview) ||
        !mat4_normal_matrix(normal, modelview)) {
        /* Not an instance matrix: transform the vertices themselves. */
        instance = identity;
        memcpy(im->block_matrix, modelview, sizeof(im->block_matrix));
        memcpy(inverse, identity, sizeof(identity));
        memcpy(normal, identity, sizeof(identity));
    }
    struct scene_appearance appearance;
    memset(&appearance, 0, sizeof(appearance));
    appearance.clip = *clip;
    appearance.gl = *gl;
    appearance.raster = *raster;
    if (scene_frame_add_instance_appearance(frame, im->slots[im->used], instance, inverse,
                                            normal, &appearance))
        return NULL;
    stage_open(im);
    im->used++;
    memcpy(im->matrix, modelview, sizeof(im->matrix));
    im->clip = *clip;
    im->gl = *gl;
    im->raster = *raster;
    scene_mesh_release(&im->rec.mesh);
    im->rec.mesh.bounds = aabb_empty();
    im->rec.active = 0;
    im->rec.out_of_memory = 0;
    im->rec.material_index = -1;
    im->open = 1;
    return &im->rec;
}
