/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bvh_collapse.h - the choice of collapse from the binary tree to the
 * wide layout (bvh4_layout.h), apart so that the collapse's per-ISA
 * units (lib/accel/collapse4_avx2.h) can name it before they rename the
 * layout's functions.
 */
#ifndef RT_TRACE_BVH_COLLAPSE_H
#define RT_TRACE_BVH_COLLAPSE_H

/* Which collapse makes the wide layout from the binary tree.
 * BVH_COLLAPSE_GREEDY: accel_collapse_wide's greedy one (bvh4_layout.h; the
 * default).  BVH_COLLAPSE_OPTIMAL: Ylitie, Karras and Laine (2017, sec.
 * 3.1)'s collapse by dynamic programming on the SAH cost (node cost 2
 * against a packet's 1; collapse4.c), with the same leaf limits; it
 * takes more of the build (a pass over every binary node) for fewer wide
 * nodes, the choice of rtHint(RT_ACCELERATION_HINT, RT_NICEST).  Either
 * way every lane is a binary node (its box bit for bit) and a leaf lane
 * a run of leaf-ordered triangles, so the answers are the same; only the
 * layout differs.  Triangle layouts only: tri NULL is always greedy. */
enum bvh_collapse { BVH_COLLAPSE_GREEDY = 0, BVH_COLLAPSE_OPTIMAL = 1 };

#endif
