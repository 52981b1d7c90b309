/* SPDX-License-Identifier: Apache-2.0 */
/*
 * traverse.c - closest-hit and any-hit traversal of one BVH (trace.h).
 *
 * Iterative, depth first, with a fixed stack: the builders guarantee
 * depth <= BVH_MAX_DEPTH and at most one entry per level is pushed (the
 * farther child of each inner node on the current path), so BVH_MAX_DEPTH
 * + 1 entries always suffice.  At an inner node both children are tested
 * and the nearer one (smaller entry distance) is visited first.  A pushed
 * child carries its entry distance; when it is popped after the closest
 * hit has moved in front of it, it is skipped without another box test.
 *
 * Hits are accepted with ray->tmin <= t < t_max; of two triangles at
 * exactly the same distance the one with the lower primitive index wins,
 * whatever the tree (popped subtrees whose entry equals the best distance
 * are still visited for that reason).
 * Leaf slot i's triangle is tri[9i .. 9i+8] (accel_gather_triangles).
 */
/* The scalar baseline: plain C, no SIMD intrinsics, whatever the
 * compiler's default instruction set; the reference every ISA table of
 * kernels.h is checked against. */
#define RT_NO_SIMD 1
#define TRACE_WALK_CLOSEST trace_closest
#define TRACE_WALK_ANY trace_any
#include "trace/traverse_walk.h"

