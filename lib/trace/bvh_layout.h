/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bvh_layout.h - the binary bounding volume hierarchy's memory layout.
 *
 * The layout sits below both layers that use it: trace/ reads it, the
 * builders of accel/ (accel/bvh_build.h) write it.
 *
 * Node layout (32 bytes, two nodes per 64-byte cache line):
 *
 *   byte  0..11  aabb_min[3]  float
 *   byte 12..15  first        inner: index of the left child; the right
 *                             child is first + 1 (siblings are adjacent).
 *                             leaf: first slot in prim_index.
 *   byte 16..27  aabb_max[3]  float
 *   byte 28..31  count        0 for an inner node, else primitives in leaf
 *
 * Node 0 is the root.  A BVH over zero primitives has node_count == 0 and
 * nodes == NULL; traversal treats it as empty.
 */
#ifndef RT_TRACE_BVH_LAYOUT_H
#define RT_TRACE_BVH_LAYOUT_H

#include <stdint.h>

#include "base/aabb.h"

struct bvh_node {
    float aabb_min[3];
    uint32_t first;
    float aabb_max[3];
    uint32_t count;
};
typedef char bvh_node_is_32_bytes[sizeof(struct bvh_node) == 32 ? 1 : -1];

struct bvh {
    struct bvh_node *nodes;
    uint32_t node_count;
    uint32_t *prim_index; /* leaf slot -> caller's primitive index */
    uint32_t prim_count;
    uint32_t depth; /* edges on the longest root-to-leaf path; <= BVH_MAX_DEPTH */
};

/* The builders guarantee depth <= BVH_MAX_DEPTH so that traversal can use
 * a fixed stack of BVH_MAX_DEPTH + 1 entries. */
#define BVH_MAX_DEPTH 64

#endif
