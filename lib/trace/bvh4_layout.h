/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bvh4_layout.h - the 4-wide traversal layout of an object's BVH.
 *
 * Collapsed from the binary tree after every build, refit and
 * restructure (lib/scene/accel.c); the binary tree stays the build and
 * update representation.  Each wide node holds up to four children in
 * structure-of-arrays form, so that one SIMD test covers all four boxes
 * (Wald, Benthin and Boulos 2008; Dammertz et al. 2008): the child boxes
 * are copied bit for bit from binary nodes, which is what lets the wide
 * walk give the same answers as the binary one (traverse_wide.h).
 *
 * Node layout (128 bytes, two 64-byte cache lines, 64-byte aligned):
 *
 *   bounds[0..5][4]  min x, min y, min z, max x, max y, max z of the four
 *                    children (float); an unused lane holds the empty
 *                    box min = +inf, max = -inf, which every ray misses.
 *   child[4]         inner child: index of its wide node; leaf child:
 *                    first slot in the binary tree's prim_index.
 *   count[4]         0 for an inner child (or an unused lane), else the
 *                    primitives of the leaf.
 *
 * Wide node 0 is the root; it covers the binary root's children (or the
 * binary root itself when that is a leaf).
 */
#ifndef RT_TRACE_BVH4_LAYOUT_H
#define RT_TRACE_BVH4_LAYOUT_H

#include <stdint.h>

#include "trace/bvh_layout.h"

struct bvh4_node {
    float bounds[6][4];
    uint32_t child[4];
    uint32_t count[4];
};
typedef char bvh4_node_is_128_bytes[sizeof(struct bvh4_node) == 128 ? 1 : -1];

struct bvh4 {
    struct bvh4_node *nodes; /* 64-byte aligned inside raw */
    uint32_t node_count;     /* 0: no wide layout (empty tree) */
    uint32_t *source;        /* 4 per node: the binary node of each lane (refit) */
    void *raw;
};

/*
 * Collapses bvh into *out (greedy surface-area collapse: a wide node
 * starts from a binary inner node's two children and repeatedly replaces
 * the inner child of largest surface area by its two children until it
 * has four, as in Wald, Benthin and Boulos 2008 and the MBVH
 * conversion of tinybvh).  *out is output only.  Returns 0, or -1 on
 * allocation failure with *out zeroed.  Implemented in lib/accel.
 */
int accel_collapse4(struct bvh4 *out, const struct bvh *bvh);

/* Copies the refitted binary boxes into the wide layout (same topology:
 * accel_refit keeps it); no allocation. */
void accel_refit4(struct bvh4 *wide, const struct bvh *bvh);

/* Frees *wide and zeroes it; safe on a zeroed one. */
void bvh4_release(struct bvh4 *wide);

#endif
