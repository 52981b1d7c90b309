/* SPDX-License-Identifier: Apache-2.0 */
/*
 * restructure.h - selective restructuring of a BVH over deforming
 * geometry: Yoon, Curtis and Manocha, "Ray Tracing Dynamic Scenes using
 * Selective Restructuring", EGSR 2007 (Yoon, Curtis and Manocha (2007)).
 *
 * Each frame the primitive boxes move (same primitives, same indices) and
 * accel_restructure
 *   1. refits every box bottom-up (Yoon, Curtis and Manocha (2007) sec. 5.1),
 *   2. evaluates the culling-efficiency metric CM-IQ (sec. 4.1, eq. 1) of
 *      every node,
 *   3. walks a FIFO pair-queue top-down from (Left(root), Right(root)),
 *      evaluating the restructuring-benefit metric RM-IQ (sec. 4.2-4.3,
 *      eq. 7, times the expected life time of sec. 5.4) of each node pair
 *      and refining pairs while the benefit exceeds the refinement cost
 *      (sec. 5.2, Alg. 1 lines 1-11), propagating each pair's benefit to
 *      the pairs it was refined from,
 *   4. takes the pairs out of a pair-heap, largest benefit minus
 *      restructuring cost first, and restructures every pair whose benefit
 *      exceeds its cost C_rebuild * k log2 k (sec. 4.3, 5.3; Alg. 1 lines
 *      12-21): the union of the two sub-BVHs' primitives is split by the
 *      plane of sec. 5.3 and each side gets a fresh SAH sub-BVH (sec. 5.4).
 * The result is an ordinary BVH in bvh_layout.h's layout that satisfies
 * accel_build's contract, so the traversal of lib/trace runs on it
 * unchanged.  Where this implementation departs from the paper (no
 * per-node access time-stamps, no lazy construction, a few bounds the
 * paper leaves open) restructure.c's header comment says so.
 *
 * Units: every cost and benefit is in ray/AABB tests (Yoon, Curtis and Manocha (2007) sec. 6.1:
 * "We also measure C_refine and C_rebuild as the relative cost to the
 * cost of ray-AABB intersection cost"), per frame.
 *
 * Ownership: a state belongs to one BVH (one object) across its frames and
 * owns only its scratch arrays; the BVH stays owned by the caller.
 */
#ifndef RT_ACCEL_RESTRUCTURE_H
#define RT_ACCEL_RESTRUCTURE_H

#include <stdint.h>

#include "accel/bvh_build.h"
#include "base/aabb.h"

/* A node pair of the pair-queue and an entry of the pair-heap; defined
 * in restructure_internal.h. */
struct accel_restructure_pair;
struct accel_restructure_heap_entry;

/*
 * Machine constants: the median of 15 runs of
 * accel_restructure_measure_constants on the development machine (AMD
 * EPYC, 2 cores shared with other jobs, gcc 12 -O2 Release); each is a
 * cost relative to one ray/AABB test of the traversal's kernel
 * (trace/intersect.h).  Yoon, Curtis and Manocha (2007) sec. 6.1 measures them at start-up;
 * these are the fallback when the caller does not, and what the tests use
 * so that their decisions do not depend on the clock.
 */
/* Ray/triangle test over ray/AABB test (sec. 4.1.1, eq. 1; sec. 6.1).
 * Measured range over the 15 runs: 4.0-5.5. */
#define ACCEL_RESTRUCTURE_DEFAULT_C_LEAF 4.9f
/* Restructuring two sub-BVHs of k primitives in all costs
 * C_rebuild * k log2 k (sec. 4.3, f_rebuild; sec. 6.1).  Range 7.2-9.9. */
#define ACCEL_RESTRUCTURE_DEFAULT_C_REBUILD 8.7f
/* Taking one pair from the pair-queue, evaluating it and refining it
 * (sec. 5.2, "Stopping Criteria"; sec. 6.1).  Range 9.9-14.0. */
#define ACCEL_RESTRUCTURE_DEFAULT_C_REFINE 10.4f

/*
 * Rays expected to hit the root's box in a frame.  Yoon, Curtis and Manocha (2007) sec. 4.1.1
 * multiplies CM-IQ by this count ("we estimate it with that of the
 * previous frame") and then omits it from its derivations; the comparison
 * of a per-ray benefit with a per-frame cost needs it.  The default is
 * the paper's measurement set-up (table 2: 512 x 512 pixels, one ray per
 * pixel) with every primary ray hitting the object.
 */
#define ACCEL_RESTRUCTURE_DEFAULT_RAYS (512.0 * 512.0)

/*
 * Cap on the expected life time of sec. 5.4, in frames.  The paper's
 * estimate grows without bound while nothing is restructured (after 1000
 * quiet frames a benefit would count 1000 times); its benchmarks ran
 * 40-130 frames (table 1), so 100 keeps the estimate inside the range
 * the paper exercised.
 */
#define ACCEL_RESTRUCTURE_DEFAULT_MAX_LIFETIME 100.0f

struct accel_restructure_params {
    float c_leaf;    /* ray/triangle cost over ray/AABB cost (sec. 4.1.1) */
    float c_rebuild; /* restructuring cost per k log2 k primitives (sec. 4.3) */
    float c_refine;  /* cost of refining one pair (sec. 5.2) */
    /* Rays that hit the root's box per frame (sec. 4.1.1); set it to the
     * previous frame's count when known: it scales every benefit, so it
     * decides between restructuring little and rebuilding everything
     * (restructure.c, "Measured behaviour").  0 means no rays: nothing is
     * worth restructuring and only the refit is done. */
    double rays_per_frame;
    /* Cap on the life-time factor (sec. 5.4), >= 1. */
    float max_lifetime;
    /* Cap on pairs taken from the pair-queue per frame; 0 means the node
     * count, which keeps the refinement phase linear like the refit.  The
     * paper's stopping criterion alone reports 200-1000 pairs (sec. 7.1);
     * the cap is a guard for scenes where every box overlaps. */
    uint32_t max_pairs;
    /* Non-zero: a restructuring whose new sub-BVHs would raise the
     * tree's CM-IQ is undone (not in the paper, which trusts the
     * estimate of eq. 7; restructure.c explains).  0: the paper's rule. */
    int verify_cost;
    /* Builder of the new sub-BVHs: the SAH builders of bvh_layout.h (Yoon, Curtis and Manocha (2007)
     * sec. 5.4 uses an SAH build, [WH06]). */
    struct bvh_build_params build;
};

/* Per-frame figures; times in milliseconds of wall clock. */
struct accel_restructure_stats {
    uint32_t pairs_examined;     /* pairs taken from the pair-queue */
    uint32_t pairs_candidates;   /* pairs in the pair-heap: benefit > cost */
    uint32_t restructures;       /* node pairs restructured */
    uint32_t nodes_restructured; /* nodes of the new sub-BVHs */
    uint32_t prims_restructured; /* primitives re-partitioned */
    uint32_t rejected_overlap;   /* heap pairs inside or above a restructured region */
    uint32_t rejected_depth;     /* would have exceeded BVH_MAX_DEPTH */
    uint32_t rejected_cost;      /* undone by verify_cost */
    double lifetime;             /* expected life time of sec. 5.4 used, frames */
    /* CM-IQ of the root (eq. 1) after the refit and after restructuring:
     * equal to accel_sah_cost(bvh, 1, c_leaf), computed in double. */
    double sah_before;
    double sah_after;
    double ms_refit;
    double ms_refine;      /* CM-IQ, pair-queue and pair-heap */
    double ms_restructure; /* the restructurings and the re-layout */
    double ms_total;
};

/*
 * Per-BVH state across frames.  The fields are private to
 * restructure*.c; callers only init and release it.  Life-time
 * accounting (sec. 5.4) plus scratch arrays kept between frames so that a
 * frame allocates nothing once sizes settle.
 */
struct accel_restructure_state {
    uint64_t frames;
    double node_frames;   /* sum over frames of the node count */
    double nodes_created; /* nodes of the first frame plus every rebuilt node */

    uint32_t node_cap; /* capacity of the per-node arrays */
    uint32_t *parent;
    uint32_t *prims;   /* |n|_tri: primitives below each node */
    uint32_t *repl;    /* replacement sub-BVH of a node, or UINT32_MAX */
    uint32_t *order;   /* pre-order, for BVHs not numbered parent-first */
    double *cost;      /* C(n), CM-IQ (eq. 1) */
    uint8_t *flags;
    uint8_t *depth;

    uint32_t pair_cap;
    struct accel_restructure_pair *pairs;
    uint32_t heap_cap;
    struct accel_restructure_heap_entry *heap;

    uint32_t prim_cap;
    uint32_t *tmp_ids;
    struct aabb *tmp_boxes;

    uint32_t repl_cap;
    struct bvh *repl_trees;

    uint32_t spare_node_cap;
    struct bvh_node *spare_nodes;
    uint32_t spare_prim_cap;
    uint32_t *spare_prims;
};

/* Zeroes *state: no allocation, never fails. */
void accel_restructure_state_init(struct accel_restructure_state *state);

/* Frees the scratch arrays and zeroes *state; safe on a zeroed state. */
void accel_restructure_state_release(struct accel_restructure_state *state);

/*
 * Fills *out with the defaults above: the ACCEL_RESTRUCTURE_DEFAULT_*
 * constants, max_pairs 0, verify_cost 1 and bvh_build_params_default for
 * the builder.
 */
void accel_restructure_params_default(struct accel_restructure_params *out);

/*
 * Fills *out with the defaults and replaces c_leaf, c_rebuild and
 * c_refine by values measured now on this machine (Yoon, Curtis and Manocha (2007) sec. 6.1:
 * "We automatically compute these costs by running those routines a few
 * times ... during the ray tracing system's initialization"): ray/AABB
 * and ray/triangle tests of the traversal's kernels, restructurings of
 * synthetic sub-BVHs of 256..4096 boxes and a pair-queue run on a
 * synthetic tree, each repeated and the fastest run kept.  Fixed seeds
 * and iteration counts; 10-25 ms in a Release build on the development
 * machine.  A
 * measurement that fails (allocation failure, a clock that does not
 * advance) keeps its default.  Not thread-safe with respect to *out
 * only; otherwise safe to call from any thread.
 */
void accel_restructure_measure_constants(struct accel_restructure_params *out);

/*
 * One frame of selective restructuring.  bvh must satisfy accel_build's
 * contract (bvh_layout.h) for bvh->prim_count primitives, which keep their
 * indices; prim_boxes[i] is primitive i's new box, finite and non-empty
 * (boxes that break this give a structurally valid tree with meaningless
 * bounds, as for accel_build).  state must have been initialized and be
 * used with this BVH only (it may be used with a fresh build of the same
 * object after accel_restructure_state_release + init).  params NULL
 * means the defaults; out-of-range fields are replaced by their defaults
 * (non-finite or negative costs, max_lifetime below 1, non-finite or
 * negative rays) and params->build is normalized as accel_build does.
 * stats may be NULL.
 *
 * The boxes are refitted, then node pairs are restructured as described
 * at the top of this file.  On return 0 the BVH satisfies accel_build's
 * contract for prim_boxes: every primitive in exactly one leaf, every box
 * containing its children's boxes and its primitives' boxes, depth <=
 * BVH_MAX_DEPTH (a restructuring that would go deeper is skipped), child
 * indices greater than their parent's, leaves of at most
 * params->build.max_leaf_size primitives where restructured.  bvh->nodes
 * and bvh->prim_index may have been replaced by other arrays (the old
 * ones go to the state's scratch), so pointers into them and triangles
 * gathered in leaf order (accel_gather_triangles) must be refreshed.
 *
 * Returns -1 on allocation failure; the BVH is then the plain refit of
 * prim_boxes (valid, no restructuring), or unchanged when it is not
 * numbered parent-first (then the refit itself needs scratch memory).
 * Also -1 when the BVH detectably breaks the contract (a cycle, a child
 * index out of range, a depth beyond BVH_MAX_DEPTH): it is then at most
 * refitted.  Deterministic apart from the timings in stats.  Not
 * thread-safe for one state or one BVH; distinct ones may run in
 * parallel.
 */
int accel_restructure(struct bvh *bvh, const struct aabb *prim_boxes,
                      struct accel_restructure_state *state,
                      const struct accel_restructure_params *params,
                      struct accel_restructure_stats *stats);

#endif
