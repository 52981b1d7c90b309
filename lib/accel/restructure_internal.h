/* SPDX-License-Identifier: Apache-2.0 */
/*
 * restructure_internal.h - pieces shared by the selective restructuring
 * files (Yoon, Curtis and Manocha (2007); restructure.h has the interface):
 *   restructure.c            the frame driver: refit, pair-queue, pair-heap
 *   restructure_metrics.c    CM-IQ, RM-IQ, the refinement bound, life time
 *   restructure_apply.c      one restructuring operation and the re-layout
 *   restructure_calibrate.c  the machine constants
 * Not part of the accel interface.
 *
 * Conventions: node areas are half surface areas (aabb_half_area), as
 * everywhere in accel/; the paper's metrics only use ratios of areas, and
 * where an absolute area enters (the reduced area of eq. 7) it is halved
 * too.  "Mass" S(n) = A(n) C(n) is a node's CM-IQ times its area: it is
 * the sum over the sub-BVH of A(m) for inner nodes and A(m) |m|_tri
 * C_leaf for leaves, so the tree's CM-IQ changes by delta S / A(root) when
 * a sub-BVH is replaced.
 */
#ifndef RT_ACCEL_RESTRUCTURE_INTERNAL_H
#define RT_ACCEL_RESTRUCTURE_INTERNAL_H

#include <stdint.h>

#include "accel/bvh_build.h"
#include "accel/restructure.h"

#define RS_NONE UINT32_MAX

/* Per-node flags (state->flags), cleared each frame. */
#define RS_SEEDED 1u /* the pair (Left(n), Right(n)) was put in the pair-queue */
#define RS_LOCKED 2u /* inside a sub-BVH restructured this frame */
#define RS_ABOVE 4u  /* an ancestor of a sub-BVH restructured this frame */

/*
 * A node pair (Yoon, Curtis and Manocha (2007) sec. 3.2 and 5.2).  n1 lies in the sub-BVH of
 * Left(lca) and n2 in that of Right(lca), lca their lowest common
 * ancestor; neither is an ancestor of the other.  parent is the pair it
 * was refined from (RS_NONE for the first pair), always at a lower index
 * in the pair array, which is also the FIFO pair-queue.
 */
struct accel_restructure_pair {
    uint32_t n1;
    uint32_t n2;
    uint32_t lca;
    uint32_t parent;
    double benefit; /* RM-IQ of the pair, then plus its descendants' (propagation) */
};

/* An entry of the pair-heap (sec. 5.3), its key inline so that sifting
 * does not chase pair indices. */
struct accel_restructure_heap_entry {
    double net; /* benefit - f_rebuild */
    uint32_t pair;
};

/* One frame's working set. */
struct rs_frame {
    struct bvh *bvh;
    const struct aabb *boxes;
    struct accel_restructure_state *st;
    struct accel_restructure_params p; /* normalized */
    struct accel_restructure_stats *stats; /* never NULL */
    const uint32_t *order; /* pre-order of the nodes, or NULL for 0..n-1 */
    double factor;         /* rays per frame times expected life time */
    double root_area;
    uint32_t pair_count;
    uint32_t pair_limit;
    /* Accepted restructurings, applied by rs_relayout. */
    uint32_t repl_count;
    uint32_t nodes_removed;
    uint32_t nodes_added;
    double mass_delta;
};

/* A restructuring computed but not yet applied (restructure_apply.c). */
struct rs_candidate {
    struct bvh tree[2]; /* the new sub-BVHs of n1 and n2; prim_index holds caller indices */
    uint32_t old_nodes[2];
    uint32_t prims;
    uint32_t path_len[2];
    uint32_t path_node[2][BVH_MAX_DEPTH + 1];
    struct aabb path_box[2][BVH_MAX_DEPTH + 1];
    double mass_delta;
};

static inline float rs_node_area(const struct bvh_node *n)
{
    struct aabb b;
    for (int k = 0; k < 3; k++) {
        b.min[k] = n->aabb_min[k];
        b.max[k] = n->aabb_max[k];
    }
    return aabb_half_area(&b);
}

static inline struct aabb rs_node_box(const struct bvh_node *n)
{
    struct aabb b;
    for (int k = 0; k < 3; k++) {
        b.min[k] = n->aabb_min[k];
        b.max[k] = n->aabb_max[k];
    }
    return b;
}

/* restructure.c */

/* Grows the per-node scratch arrays to at least node_count entries; 0,
 * or -1 leaving the arrays that could not grow as they were. */
int rs_reserve_nodes(struct accel_restructure_state *st, uint32_t node_count);
/* Grows the per-primitive scratch arrays; 0 or -1. */
int rs_reserve_prims(struct accel_restructure_state *st, uint32_t prim_count);
/* Recomputes every box from prim_boxes, children before parents. */
void rs_refit(struct bvh *bvh, const struct aabb *prim_boxes, const uint32_t *order);
/* The hierarchical refinement phase (sec. 5.2, Alg. 1 lines 1-11):
 * fills f->st->pairs[0, f->pair_count) with benefits propagated.
 * Needs rs_metrics_pass and f->factor, f->root_area, f->pair_limit.
 * 0, or -1 when the pair array cannot grow (the pairs so far are kept). */
int rs_refine_pairs(struct rs_frame *f);

/* restructure_metrics.c */

/* CM-IQ (eq. 1) of every node, bottom-up, plus parent, |n|_tri and depth;
 * clears the flags.  Returns the largest depth. */
uint32_t rs_metrics_pass(struct rs_frame *f);
/* RM-IQ of a pair per ray (eq. 7 for both nodes), before the life time. */
double rs_rm_iq(const struct rs_frame *f, const struct accel_restructure_pair *pair);
/* Upper bound on the per-ray RM-IQ of any pair inside sub-BVH(n). */
double rs_refine_bound(const struct rs_frame *f, uint32_t n);
/* f_rebuild(n1, n2) = C_rebuild k log2 k (sec. 4.3). */
double rs_rebuild_cost(const struct rs_frame *f, uint32_t k);
/* Expected life time (sec. 5.4) after counting this frame. */
double rs_lifetime(struct accel_restructure_state *st, uint32_t node_count, float max_lifetime);
/* Mass S of a finished tree (the sum in the header comment). */
double rs_tree_mass(const struct bvh *t, float c_leaf);

/* restructure_apply.c */

/* Computes the restructuring of pair (sec. 3.2 and 5.3) into *c.
 * Returns 0, 1 when it would exceed BVH_MAX_DEPTH (nothing held), or -1
 * on allocation failure (nothing held). */
int rs_build_candidate(struct rs_frame *f, const struct accel_restructure_pair *pair,
                       struct rs_candidate *c);
void rs_candidate_release(struct rs_candidate *c);
/* Accepts *c (its trees move to the frame); 0 or -1 (then *c is
 * released and nothing changed). */
int rs_commit(struct rs_frame *f, const struct accel_restructure_pair *pair,
              struct rs_candidate *c);
/* Frees the accepted sub-BVHs without applying them. */
void rs_drop_replacements(struct rs_frame *f);
/* Rebuilds the node and slot arrays with every accepted sub-BVH in
 * place, depth first; 0 or -1 (nothing changed, replacements kept). */
int rs_relayout(struct rs_frame *f);

#endif
