/* SPDX-License-Identifier: Apache-2.0 */
/*
 * recording.h - recording an object's definition: vertices transformed by
 * the modelview of their block, stored in the recording mesh, and the
 * triangles they complete assembled with OpenGL's order and provoking
 * vertex (assembly.h).
 *
 * A vertex goes from the entry point to the mesh in one call,
 * scene_record_vertex, which assembles once, acquires every byte the
 * vertex needs, then stores it: a failed call stores nothing.  Nothing
 * here records an error: the entry points turn the returned status into
 * one (STYLE.md sec. 3), so a process without an API context (an MPI
 * worker replaying a change set) records with the same code.
 *
 * As in OpenGL, a vertex is transformed by the modelview current at the
 * call and its normal by the inverse transpose; the modelview cannot
 * change inside rtBegin/rtEnd, so both matrices are fixed per block.  We
 * transform normals by the cofactor matrix (det * inverse transpose):
 * same direction up to sign, and defined for singular matrices too;
 * shading normalises and faces normals towards the ray anyway.
 */
#ifndef RT_SCENE_RECORDING_H
#define RT_SCENE_RECORDING_H

#include <stdint.h>

#include "scene/mesh.h"

/* Recording state between rtNewObject and rtEndObject. */
struct scene_recording {
    int active;
    uint32_t name;
    struct scene_mesh mesh;
    int out_of_memory; /* an allocation failed: rtEndObject keeps the old definition */
    int material_index; /* interned index of the current material, -1 when stale */
    uint32_t material_texture; /* the texture material_index was interned with */
};

/* One block of vertices (rtBegin/rtEnd, or one draw call). */
struct scene_block {
    int active;
    unsigned mode;
    uint32_t base;  /* mesh index of the block's first vertex */
    uint32_t count; /* vertices recorded in this block */
    double position_matrix[16]; /* the modelview, fixed inside the block */
    double normal_matrix[9];    /* its cofactor matrix, for normals */
};

/* What the current state gives the triangles a vertex completes. */
struct scene_triangle_state {
    const struct scene_material *material;
    uint32_t texture; /* 0: untextured */
    uint8_t flags;    /* TRI_FLAT, TRI_COLOR_MATERIAL */
};

enum scene_record_status {
    SCENE_RECORD_OK = 0,
    SCENE_RECORD_NOT_FINITE,     /* the vertex is not finite under the modelview */
    SCENE_RECORD_OUT_OF_MEMORY   /* rec->out_of_memory is set as well */
};

/* Starts a block of primitives of `mode` whose vertices are transformed by
 * modelview (copied). */
void scene_block_start(struct scene_block *block, const struct scene_recording *rec,
                       unsigned mode, const double modelview[16]);

/* 1 when position transforms to a finite float vertex (the test
 * scene_record_vertex makes), without storing anything. */
int scene_block_vertex_is_finite(const struct scene_block *block, const double position[3]);

/* Transforms, stores and assembles the next vertex of the block. */
enum scene_record_status scene_record_vertex(struct scene_recording *rec,
                                             struct scene_block *block,
                                             const struct scene_triangle_state *ts,
                                             const double position[3], const float normal[3],
                                             const float color[4], const float texcoord[2]);

/* Indexed drawing: scene_store_vertex stores a vertex without assembling;
 * scene_assemble_indexed stores the triangles completed by stream
 * position k of the block, stream position j being mesh vertex map[j]. */
enum scene_record_status scene_store_vertex(struct scene_recording *rec,
                                            const struct scene_block *block,
                                            const double position[3], const float normal[3],
                                            const float color[4], const float texcoord[2]);
enum scene_record_status scene_assemble_indexed(struct scene_recording *rec,
                                                const struct scene_block *block,
                                                const struct scene_triangle_state *ts,
                                                uint32_t k, const uint32_t *map);

#endif
