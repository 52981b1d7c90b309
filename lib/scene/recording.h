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
 * Inside a display list (rtNewList .. rtEndList) a vertex is transformed
 * by the list's own recording matrix, which starts at identity: as in GL,
 * the caller's modelview at compile time does not matter.  Matrix calls
 * in the list are recorded as operations (struct scene_list_op) that the
 * API replays on the caller's stacks at rtCallList, and change the
 * recording matrix of later vertices.  A list's geometry is cut into
 * segments: one segment's vertices are relative to the modelview the
 * replay holds where the segment starts (SCENE_OP_SEGMENT).  A new segment
 * starts where that relation is not known when compiling: after an
 * absolute load (rtLoadMatrix, rtLoadIdentity), after a pop back to a
 * level pushed before the segment (or below the list's entry level), and
 * after a nested call, whose side effects are the callee's at call time.
 * Outside lists (immediate mode, frame.h) the block matrix is the identity
 * and the segment matrix the modelview.
 *
 * As in OpenGL, a vertex is transformed by the matrix current at the
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

/* A recorded operation of a display list, replayed in order at call time. */
enum scene_list_op_kind {
    SCENE_OP_SEGMENT,     /* a = segment: instance it under the current modelview */
    SCENE_OP_CALL,        /* a = list name; b = 1: add the list base at call time */
    SCENE_OP_MATRIX_MODE, /* a = mode */
    SCENE_OP_LOAD,        /* v = matrix (column-major) */
    SCENE_OP_MULT,        /* v = matrix */
    SCENE_OP_PUSH,
    SCENE_OP_POP,
    SCENE_OP_STATE        /* a = API state call, b and c its enums, v its values */
};

struct scene_list_op {
    uint32_t kind;
    uint32_t a, b, c;
    double v[16];
};

#define SCENE_LIST_MAX_PUSH 64 /* levels a list can push; deeper overflows anyway */

/* Recording state between rtNewObject and rtEndObject. */
struct scene_recording {
    int active;
    uint32_t name;
    struct scene_mesh mesh;
    int out_of_memory; /* an allocation failed: rtEndObject keeps the old definition */
    int material_index; /* interned index of the current material, -1 when stale */
    uint32_t material_texture; /* the texture material_index was interned with */

    /* Display lists only (scene_list_begin). */
    struct scene_list_op *ops;
    uint32_t op_count, op_capacity;
    struct scene_mesh *segments; /* finished segments; `mesh` is segment segment_count */
    uint32_t segment_count, segment_capacity;
    unsigned matrix_mode; /* RT_MODELVIEW or RT_PROJECTION as the list leaves it */
    /* The recording modelview stack: each level's matrix relative to the
     * start of segment `segment`; level 0 is the list's entry level. */
    struct {
        double m[16];
        uint32_t segment;
    } stack[SCENE_LIST_MAX_PUSH];
    int depth;
    /* Since the start (or the last nested call): the material properties
     * (SCENE_MATERIAL_* bits) and whether a colour the list set; what it
     * did not set, its triangles take from the caller. */
    uint32_t material_set;
    int color_set;
    int color_material_set; /* the list enabled or disabled RT_COLOR_MATERIAL */
    uint32_t material_inherit; /* the inherit mask material_index was interned with */
    int shade_model_set; /* the list called rtShadeModel (TRI_INHERIT_SHADE) */
};

/* Starts recording a display list (the recording matrix is the identity;
 * matrix_mode is the mode assumed current at call time).  Returns 0, -1
 * on allocation failure. */
int scene_list_begin(struct scene_recording *rec, uint32_t name, unsigned matrix_mode);
/* Frees what a list recording holds (safe at any time). */
void scene_list_release(struct scene_recording *rec);
/* The recording matrix of the current level (what a block starts with). */
const double *scene_list_matrix(const struct scene_recording *rec);
/* Records a matrix operation (SCENE_OP_MATRIX_MODE .. SCENE_OP_POP; m for
 * LOAD and MULT) and applies it to the recording matrix.  0, -1 on
 * allocation failure (rec->out_of_memory set), -2 when a product with
 * the recording modelview is not finite (nothing recorded). */
int scene_list_matrix_op(struct scene_recording *rec, enum scene_list_op_kind kind,
                         unsigned mode, const double m[16]);
/* Ends the segment: the following geometry is instanced where the replay
 * is then, with the state current there (a clip-plane change: clip.h).
 * 0, -1 on allocation failure. */
int scene_list_split(struct scene_recording *rec);
/* Records a nested call of `name` (ends the segment). */
int scene_list_call(struct scene_recording *rec, uint32_t name, int add_base);
/* Records a state call for the API to replay. */
int scene_list_state(struct scene_recording *rec, uint32_t what, uint32_t b, uint32_t c,
                     const float *v, int n);
/* The same with double values (rtClipPlane's equation). */
int scene_list_state_d(struct scene_recording *rec, uint32_t what, uint32_t b, uint32_t c,
                       const double *v, int n);
/* Ends a list recording: moves the non-empty segments (in order) into
 * *meshes (count in *mesh_count; may be 0) and the operations into *ops,
 * renumbering the SCENE_OP_SEGMENT operations and dropping those of empty
 * segments; map[i] (if not NULL, one per recorded segment, see
 * scene_list_segment_count) receives the new index of segment i or
 * UINT32_MAX.  Ownership moves to the caller (free with rt_free and
 * scene_mesh_release).  0, -1 on allocation failure. */
uint32_t scene_list_segment_count(const struct scene_recording *rec);
int scene_list_finish(struct scene_recording *rec, struct scene_mesh **meshes,
                      uint32_t *mesh_count, struct scene_list_op **ops, uint32_t *op_count,
                      uint32_t *map);

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
    uint8_t flags;    /* TRI_FLAT, TRI_COLOR_MATERIAL, TRI_INHERIT_COLOR */
    uint32_t inherit; /* material properties taken from the caller (mesh.h) */
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
                                             const float color[4], const float texcoord[4]);

/* Indexed drawing: scene_store_vertex stores a vertex without assembling;
 * scene_assemble_indexed stores the triangles completed by stream
 * position k of the block, stream position j being mesh vertex map[j]. */
enum scene_record_status scene_store_vertex(struct scene_recording *rec,
                                            const struct scene_block *block,
                                            const double position[3], const float normal[3],
                                            const float color[4], const float texcoord[4]);
enum scene_record_status scene_assemble_indexed(struct scene_recording *rec,
                                                const struct scene_block *block,
                                                const struct scene_triangle_state *ts,
                                                uint32_t k, const uint32_t *map);

/* Ends a block of `count` vertices: an RT_POLYGON's last triangle gets
 * the closing edge's flag (the fan's edge back to the first vertex,
 * scene_tri.edges), which assembly cannot know before the end. */
void scene_block_close_polygon(struct scene_recording *rec, const struct scene_block *block,
                               uint32_t count);

#endif
