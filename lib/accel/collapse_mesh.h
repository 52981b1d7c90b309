/* SPDX-License-Identifier: Apache-2.0 */
/*
 * collapse_mesh.h - the collapse into the wide layout (bvh4_layout.h)
 * with its packets' triangles read from the mesh through the tree's
 * prim_index, so that the layout can be made before (or without) the
 * leaf-ordered copy of the triangles (accel_gather_triangles).
 *
 * The gather copies slot s's triangle, the three vertices
 * indices[3 * prim_index[s] ..] of positions, float for float into its
 * nine floats; reading those same vertices in place gives the packets
 * the same floats, so the layout is the same byte for byte as
 * accel_collapse_wide_quality's from the gathered copy (checked by
 * internal/collapse_threads).
 */
#ifndef RT_ACCEL_COLLAPSE_MESH_H
#define RT_ACCEL_COLLAPSE_MESH_H

#include <stdint.h>

#include "trace/bvh_collapse.h"

struct bvh4;
struct bvh;
struct rt_pool;
struct rt_large_block;

/* Where the collapse reads the leaves' triangles: tri (the leaf-ordered
 * copy), else positions and indices (the mesh the tree was built over);
 * all NULL for a tree without triangles (the top level over instances). */
struct collapse_triangles {
    const float *tri;
    const float *positions;
    const uint32_t *indices;
    /* 1: zero-area triangles stay in the leaves (as NaN lanes), so that
     * the layout can be refit in place (accel_refit4); 0: they are left
     * out where they are many (collapse4.c, collapse_wide_dropping). */
    int keep_zero_area;
};

/* accel_collapse_wide_quality (bvh4_layout.h) reading the triangles from
 * tris. */
int accel_collapse_wide_source(struct bvh4 *out, const struct bvh *bvh,
                               const struct collapse_triangles *tris, uint32_t width,
                               struct rt_pool *pool, struct rt_large_block *spare,
                               enum bvh_collapse collapse);

/* accel_collapse_wide_quality reading the triangles from the mesh:
 * positions (xyz per vertex) and indices (three per triangle), the
 * arrays bvh was built over.  The same layout as from
 * accel_gather_triangles(bvh, positions, indices). */
int accel_collapse_wide_mesh(struct bvh4 *out, const struct bvh *bvh, const float *positions,
                             const uint32_t *indices, uint32_t width, struct rt_pool *pool,
                             struct rt_large_block *spare, enum bvh_collapse collapse);

#endif
