/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bvh4_layout.h - the wide traversal layout of an object's BVH: 4-wide
 * (struct bvh4_node) or 8-wide (struct bvh8_node) nodes over leaves of
 * triangle packets (struct tri4_packet).  `struct bvh4` is the layout
 * of either width (the name is from when there was only the 4-wide one).
 *
 * Collapsed from the binary tree after every build and restructure
 * (lib/scene/accel.c) and refitted from it after a refit; the binary
 * tree stays the build and update representation.  Each wide node holds
 * up to four (eight) children in structure-of-arrays form, so that one
 * SIMD test covers all their boxes (Wald, Benthin and Boulos 2008;
 * Dammertz et al. 2008): the child boxes are copied bit for bit from
 * binary nodes, which is what lets the wide walk give the same answers
 * as the binary one (traverse_wide.h).
 *
 * 4-wide node (128 bytes, two 64-byte cache lines, 64-byte aligned):
 *
 *   byte   0.. 95  bounds[0..5][4]  min x, min y, min z, max x, max y,
 *                  max z of the four children (float); an unused lane
 *                  holds the empty box min = +inf, max = -inf, which
 *                  every ray misses.
 *   byte  96..111  child[4]  inner child: index of its wide node; leaf
 *                  child: its first packet.
 *   byte 112..115  count[4]  0 for an inner child (or an unused lane),
 *                  else the triangles of the leaf (1..BVH_WIDE_MAX_LEAF).
 *   byte 116..123  order[8]  per ray octant (bit 0: x direction negative,
 *                  bit 1: y, bit 2: z), the lanes front to back, 2 bits
 *                  each, first lane in the low bits (Fuetterling,
 *                  Lojewski, Pfreundt and Ebert 2017: precomputed
 *                  per-octant child order instead of a sort).
 *   byte 124..127  padding
 *
 * 8-wide node (256 bytes, four cache lines, 64-byte aligned; Embree's
 * BVH8 node is 256 bytes too):
 *
 *   byte   0..191  bounds[0..5][8]
 *   byte 192..223  child[8]
 *   byte 224..231  count[8]
 *   byte 232..255  order[8][3]  per octant the lanes front to back,
 *                  3 bits each in 24 bits, little-endian
 *
 * Triangle packet (160 bytes, 32-byte aligned; Embree's Triangle4 is 176:
 * v0, e1, e2 and geometry and primitive ids of four triangles): the
 * vertices themselves rather than edges, because the watertight test of
 * Woop, Benthin and Wald 2013 subtracts the origin from each vertex, and
 * the SIMD leaf test must compute its floats exactly as the scalar one
 * (intersect_tri4.h):
 *
 *   byte   0..143  v[3][3][4]  vertex 0..2, axis x..z, lane (float);
 *                  all nine NaN for a zero-area triangle
 *                  (isect_triangle_zero_area, intersect.h), which no
 *                  ray hits: the packet filter rejects a NaN lane, so a
 *                  lane it keeps is known to have an area and the
 *                  finish skips that test (accel_set_packet_lane)
 *   byte 144..159  prim[4]     the caller's primitive index per lane
 *
 * A leaf of n triangles is ceil(n / 4) consecutive packets; the lanes of
 * the last one beyond n repeat its last triangle and are never tested.
 * Where at least 1 in 32 triangles has zero area (and the caller does not
 * keep them for a refit), the collapse leaves them out of the leaves (n
 * counts the others, in slot order; a subtree merges into a lane by
 * them: up to BVH_WIDE_MERGE others in up to BVH_WIDE_MAX_LEAF slots)
 * and a leaf of only such triangles out of its node (collapse4.c,
 * collapse_wide_dropping, drop_zero_area); elsewhere they stay as NaN
 * lanes.
 * A leaf lane is a binary leaf, or a binary subtree of at most
 * BVH_WIDE_MERGE triangles in consecutive leaf slots, or one of at most
 * BVH_WIDE_MERGE_LEFT under a full wide node where the area heuristic
 * prefers its packets to a wide node of its own (its box is the subtree
 * root's box, again a binary node's box bit for bit).
 *
 * Wide node 0 is the root; it covers the binary root's children (or the
 * binary root itself when that is a leaf).
 */
#ifndef RT_TRACE_BVH4_LAYOUT_H
#define RT_TRACE_BVH4_LAYOUT_H

#include <stdint.h>

#include "base/alloc.h"
#include "trace/bvh_collapse.h"
#include "trace/bvh_layout.h"

/* A binary subtree of at most this many triangles in consecutive slots
 * becomes one leaf lane: one packet (Embree's builders make leaves of
 * Triangle4 blocks the same way). */
#define BVH_WIDE_MERGE 4
/* A subtree the collapse leaves closed under a full wide node becomes
 * one leaf lane of up to this many triangles (two packets) instead of a
 * wide node, when the area heuristic says the packets cost no more than
 * the node (collapse4.c, is_final_leaf). */
#define BVH_WIDE_MERGE_LEFT 8
/* A wide node's test against one packet's, the ratio of the collapse's
 * area heuristic: 1, as Embree's SAH builders weigh a node's traversal
 * and a 4-triangle block's intersection alike (traversal and
 * intersection cost 1.0).  A heuristic only: the answers do not depend
 * on it. */
#define BVH_WIDE_NODE_COST 1.0
/* A leaf lane's triangles: a binary leaf holds up to BVH_MAX_LEAF_SIZE. */
#define BVH_WIDE_MAX_LEAF (BVH_MAX_LEAF_SIZE > BVH_WIDE_MERGE_LEFT ? BVH_MAX_LEAF_SIZE : BVH_WIDE_MERGE_LEFT)

/* The layout size from which the walk prefetches the stack top: about
 * one core's L2 cache (0.5-2 MB on current x86 cores).  A heuristic
 * only: the answers do not depend on it. */
#define BVH_WIDE_PREFETCH_BYTES ((uint64_t)1 << 20)

/* The children a ray crossing a wide node crosses, on average over the
 * layout (accel_wide_child_crossings), from which the any-hit walk
 * orders a node's children by the ray's segment inside each box
 * (any_longest): between the meshes measured, whose layouts read bumpy
 * 1.23, the kitchen 1.20, gears 1.19 (surfaces: the stored order is the
 * faster there, round 39, sr6) and the soup 1.83 (a volume: the
 * segment's order is).  A heuristic only: the answers do not depend on
 * it. */
#define BVH_WIDE_ANY_LONGEST_CROSSINGS 1.6

/* The layout size from which the two-level batch walk (scene_stream.h)
 * sends incoherent rays through the table's stream walk (kernels.h,
 * stream_pair; stream_pays below).  The stream overlaps one ray's cache
 * misses with the others' work, which pays only when most node and leaf
 * loads miss the caches: on a Zen 4 core with a 32 MB L3 (ours/Embree,
 * random rays, walk1 -> stream) bumpy's 60 MB layout went 0.97 -> 1.65
 * while the soup's 6.5 MB stayed level (0.93 -> 0.94) and the kitchen's
 * 7.0 MB and gears' 62 KB lost (0.95 -> 0.79, 0.99 -> 0.78); camera and
 * shadow rays lost on all four (docs/performance-log.md, round 60 and
 * round 61, zq1).  Size alone cannot tell the soup (a volume) from the
 * kitchen (surfaces).  16 MB: above the largest layout measured where it
 * does not pay, half this machine's L3, so that a layout above it rarely
 * stays cached.  A heuristic only: the answers do not depend on
 * it. */
#define BVH_WIDE_STREAM_BYTES ((uint64_t)16 << 20)

struct bvh4_node {
    float bounds[6][4];
    uint32_t child[4];
    uint8_t count[4];
    uint8_t order[8];
    uint32_t pad;
};
typedef char bvh4_node_is_128_bytes[sizeof(struct bvh4_node) == 128 ? 1 : -1];

struct bvh8_node {
    float bounds[6][8];
    uint32_t child[8];
    uint8_t count[8];
    uint8_t order[8][3];
};
typedef char bvh8_node_is_256_bytes[sizeof(struct bvh8_node) == 256 ? 1 : -1];

struct tri4_packet {
    float v[3][3][4];
    uint32_t prim[4];
};
typedef char tri4_packet_is_160_bytes[sizeof(struct tri4_packet) == 160 ? 1 : -1];

struct bvh4 {
    uint32_t width;          /* 4 or 8; 0 when there is no layout */
    uint32_t node_count;     /* 0: no wide layout (empty tree) */
    struct bvh4_node *nodes; /* width 4: 64-byte aligned inside raw; else NULL */
    struct bvh8_node *nodes8; /* width 8: likewise */
    struct tri4_packet *packets; /* 64-byte aligned inside raw */
    uint32_t packet_count;
    uint32_t *source;        /* width per node: the binary node of each lane (refit) */
    uint32_t *packet_slot;   /* per packet: its first leaf slot (refit) */
    /* 1 when nodes and packets take BVH_WIDE_PREFETCH_BYTES or more: the
     * 8-wide single-ray closest-hit walk then prefetches the stack top
     * after each push (traverse_wide.h; the any-hit walk does not, on
     * any layout: traverse_wide8_ray.h); a smaller layout stays in the
     * caches and the prefetch would only cost instructions. */
    uint32_t prefetch_top;
    /* 1 when accel_wide_child_crossings reaches
     * BVH_WIDE_ANY_LONGEST_CROSSINGS: the 8-wide single-ray any-hit walk
     * then goes on at a node with the hit child whose box holds the
     * longest stretch of the ray beyond its start (traverse_wide.h,
     * wide8_push_any) instead of the stored order.  Set by the collapse
     * from the built boxes and kept by a refit (the topology it orders
     * is the same).  Only the visit order changes, never an answer. */
    uint32_t any_longest;
    /* The leaves' size: the mean over the leaf lanes of the largest
     * extent of a lane's box (collapse4.c, leaf_extent_mean; a sample);
     * 0 without leaves.  The 8-wide packet walk compares it with its
     * beam's width to choose whether a leaf child takes a test per ray
     * (packet_wide.h, packet_ia_init); the answers are the same either
     * way. */
    float leaf_extent;
    /* 1 when an 8-wide layout with triangles takes BVH_WIDE_STREAM_BYTES
     * or more: the batch walk of a query (scene_stream.h) then sends its
     * rays through the stream walk where the configuration says
     * stream=auto.  Set by the collapse, kept by a refit (the size is
     * the same).  Never changes an answer. */
    uint32_t stream_pays;
    /* The zero-area triangles the collapse left out of the leaves
     * (collapse4.c, drop_zero_area; never hit by any ray); 0 when it kept
     * them (struct collapse_triangles, keep_zero_area; or they were
     * fewer than 1 in 32 triangles) or there were none.  Such a layout cannot be refit in place (accel_refit4). */
    uint32_t dropped;
    /* The nodes and packets in one block (rt_malloc_large: 2 MB huge
     * pages where the OS offers them). */
    struct rt_large_block raw;
};

/*
 * Collapses bvh into *out, `width` 4 or 8 (greedy surface-area collapse:
 * a wide node starts from a binary inner node's two children and
 * repeatedly replaces the inner child of largest surface area by its two
 * children until it has `width`, as in Wald, Benthin and Boulos 2008 and
 * the MBVH conversion of tinybvh; subtrees of at most BVH_WIDE_MERGE
 * triangles stay closed and become leaves, and so do those of at most
 * BVH_WIDE_MERGE_LEFT left closed under a full node when their packets
 * cost no more than a node by the area heuristic), and copies the triangles of
 * tri (accel_gather_triangles' leaf order) into packets, leaving out the
 * zero-area triangles, which no ray hits, where they are many (the layout
 * above; out->dropped counts them).  *out is output only.  Returns 0, or -1 on
 * allocation failure (or another width) with *out zeroed.  Implemented
 * in lib/accel.
 */
int accel_collapse_wide(struct bvh4 *out, const struct bvh *bvh, const float *tri,
                        uint32_t width);
/*
 * tri NULL (the top level over instances, which has no triangles): the
 * same nodes without merging small subtrees (a leaf lane is a binary
 * leaf), no packets; a leaf lane's child is its first leaf slot and
 * its count the slots it covers, so its primitives are
 * bvh->prim_index[child .. child + count).  The caller keeps the binary
 * leaves at most UINT8_MAX primitives (count is a byte).
 */
/*
 * accel_collapse_wide with the per-node work (the greedy gather of each
 * level of wide nodes, and the nodes and packets written) shared between
 * the threads of pool (base/pool.h; NULL or a one-thread pool: the
 * calling thread alone).  The result is byte for byte the one of
 * accel_collapse_wide on any pool.  Uses the pool for the duration of
 * the call (one task at a time per pool).
 */
struct rt_pool;
int accel_collapse_wide_pool(struct bvh4 *out, const struct bvh *bvh, const float *tri,
                             uint32_t width, struct rt_pool *pool);
/* accel_collapse_wide_pool writing the layout into *spare's block (a
 * layout's raw, base/alloc.h rt_malloc_large_reuse) when it fits: then
 * out->raw takes it over and *spare is zeroed, so that the layout the new
 * one replaces must not be walked after this call (release it; its
 * source and packet_slot are still its own).  On failure, or when the
 * block does not fit, *spare is as it was (its bytes too); spare may be
 * NULL.  Same bytes as a fresh block. */
int accel_collapse_wide_reuse(struct bvh4 *out, const struct bvh *bvh, const float *tri,
                              uint32_t width, struct rt_pool *pool, struct rt_large_block *spare);

/* The collapse's choice: enum bvh_collapse (trace/bvh_collapse.h). */

/* accel_collapse_wide_reuse with the collapse chosen. */
int accel_collapse_wide_quality(struct bvh4 *out, const struct bvh *bvh, const float *tri,
                                uint32_t width, struct rt_pool *pool,
                                struct rt_large_block *spare, enum bvh_collapse collapse);

/* The wide layout's SAH cost (MacDonald and Booth 1990), the measure the
 * optimal collapse minimises (Ylitie, Karras and Laine 2017, sec. 3.1):
 * c_node times the area of every wide node's box (its lanes' union) plus
 * c_packet times every leaf lane's area times its packets, over the
 * root's area.  Triangle layouts only (a leaf lane's count its
 * triangles).  Implemented in lib/accel/sah_cost.c. */
double accel_wide_sah_cost(const struct bvh4 *wide, double c_node, double c_packet);

/* The mean number of a wide node's children that a random line crossing
 * the node crosses, over the nodes such lines visit: the sum over the
 * nodes of their lanes' box areas over the sum of the nodes' own (their
 * lanes' union); 0 for a layout other than 8 wide or without nodes.
 * Implemented in lib/accel/wide_crossings.c. */
double accel_wide_child_crossings(const struct bvh4 *wide);

/* accel_collapse_wide with width 4. */
int accel_collapse4(struct bvh4 *out, const struct bvh *bvh, const float *tri);

/* Copies the refitted binary boxes and the refitted leaf-ordered
 * triangles tri into the wide layout (same topology: accel_refit keeps
 * it); no allocation.  Safe on a zeroed layout.  Returns 0, or -1 with
 * the layout untouched when the collapse left zero-area triangles out
 * of it (wide->dropped): moved vertices can give one of them an area,
 * so the caller must collapse again (keeping them, collapse_mesh.h, if
 * more refits are to follow). */
int accel_refit4(struct bvh4 *wide, const struct bvh *bvh, const float *tri);

/* Lane `lane` of p: the triangle v (v0, v1, v2, each xyz), or NaN in all
 * nine coordinates when it has zero area (the layout above).  Every
 * packet lane is written by this; implemented in lib/accel. */
void accel_set_packet_lane(struct tri4_packet *p, uint32_t lane, const float v[9]);

/* Node and packet bytes of a layout (the memory table). */
uint64_t bvh4_node_bytes(const struct bvh4 *wide);
uint64_t bvh4_leaf_bytes(const struct bvh4 *wide);

/* Frees *wide and zeroes it; safe on a zeroed one. */
void bvh4_release(struct bvh4 *wide);

#endif
