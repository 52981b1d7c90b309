/* SPDX-License-Identifier: Apache-2.0 */
/*
 * restructure.c - the frame driver of selective restructuring (Yoon,
 * Curtis and Manocha, EGSR 2007, Yoon, Curtis and Manocha (2007); restructure.h has the
 * interface and the outline): refit, the hierarchical refinement phase
 * with its pair-queue, the restructuring phase with its pair-heap
 * (Alg. 1), and the state's lifetime.  The metrics are in
 * restructure_metrics.c, the restructuring operation and the re-layout in
 * restructure_apply.c, the machine constants in restructure_calibrate.c.
 *
 * Where this implementation departs from the paper, or fills in what it
 * leaves open:
 *
 * - Accessed nodes (sec. 4.1.1, "Evaluating CM-IQ"): the paper evaluates
 *   CM-IQ only on nodes the previous frame's rays touched, found through
 *   per-node time-stamps written during traversal.  lib/trace's traversal
 *   is read-only, so CM-IQ is evaluated on every node, "the simplest
 *   method" of the same paragraph.  It costs one pass over the nodes,
 *   fused with the refit's order.
 * - Lazy construction (sec. 6.1): the paper builds the new sub-BVHs'
 *   descendants only when a ray reaches them.  The traversal needs a
 *   complete tree, so they are built at once; C_rebuild is measured for
 *   complete builds, so the cost model stays consistent.
 * - The rays per frame (sec. 4.1.1) are a parameter (restructure.h): the
 *   paper omits the factor "for simplicity" in its derivations, but
 *   without it a per-ray benefit could never pay for a per-frame cost.
 * - Refinement of pairs whose boxes do not overlap (sec. 5.2): the paper
 *   refines them into (Left(n1), Right(n1)) and (Left(n2), Right(n2)),
 *   but its stopping criterion ("we refine a pair if its restructuring
 *   benefit is at least bigger than the refinement cost") would stop at
 *   them, since their RM-IQ is 0: read literally, a clean split at the
 *   root would hide every overlap below it.  Here the pair (Left(m),
 *   Right(m)) of a node m of a processed pair is queued, once per frame,
 *   when an upper bound on the RM-IQ of any pair inside sub-BVH(m)
 *   (restructure_metrics.c, rs_refine_bound) exceeds the refinement
 *   cost, and always when m is the node an overlapping pair is refined
 *   by (the paper's rule).  The overlap refinement into (Left(n1), n2)
 *   and (Right(n1), n2) follows the paper's criterion exactly.
 * - The refinement cost "as a function of the number of nodes in the
 *   queue" is C_refine times (pairs waiting in the queue + 1).
 * - A cap on pairs per frame (restructure.h, max_pairs).
 * - Concurrent restructurings: a pair taken from the pair-heap is skipped
 *   when either node lies inside or above a sub-BVH already restructured
 *   this frame; the paper notes that its operations "do not modify the
 *   same region of the BVHs" (sec. 7.1) without saying how.
 * - verify_cost (on by default): after a restructuring is computed, the
 *   exact change of the tree's CM-IQ is known (new sub-BVHs plus the
 *   ancestors below the lca); one that would raise it is dropped.  The
 *   paper applies every restructuring whose estimated benefit exceeds its
 *   cost; its own measurement (sec. 4.3) finds the estimate off by up to
 *   2x for 20% of pairs.
 *
 * Measured behaviour (conformance/internal/restructure.c prints it per
 * frame): the propagated benefit of a pair sums the RM-IQ of every pair
 * refined from it, so overlaps are counted again at each level, and eq.
 * 7 assumes any overlap can be removed, also the overlap adjacent
 * triangles always have.  On a waving cloth of 51k triangles the first
 * pair's sum is 34-114 tests per ray while the whole tree's CM-IQ is
 * 30-45 and a fresh build would save 1-6.  With 512^2 rays per frame that
 * makes the first pair, i.e. a rebuild of everything, win the pair-heap
 * whenever anything deforms: right for an explosion (the refit costs 9-35
 * times a fresh build), wrong for the cloth (the rebuild costs more than
 * it saves).  With about as many rays as triangles (the paper's ratio)
 * restructuring becomes selective: a locally exploding cap of 3.6k of 49k
 * triangles is restructured alone.  rays_per_frame is therefore the knob
 * that matters; callers should pass the real count.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "accel/build_internal.h"
#include "accel/restructure_internal.h"
#include "base/alloc.h"
#include "base/timer.h"

void accel_restructure_state_init(struct accel_restructure_state *state)
{
    memset(state, 0, sizeof(*state));
}

void accel_restructure_state_release(struct accel_restructure_state *state)
{
    rt_free(state->parent);
    rt_free(state->prims);
    rt_free(state->repl);
    rt_free(state->order);
    rt_free(state->cost);
    rt_free(state->flags);
    rt_free(state->depth);
    rt_free(state->pairs);
    rt_free(state->heap);
    rt_free(state->tmp_ids);
    rt_free(state->tmp_boxes);
    /* Replacement trees never outlive a frame: only the array is left. */
    rt_free(state->repl_trees);
    rt_free(state->spare_nodes);
    rt_free(state->spare_prims);
    memset(state, 0, sizeof(*state));
}

void accel_restructure_params_default(struct accel_restructure_params *out)
{
    out->c_leaf = ACCEL_RESTRUCTURE_DEFAULT_C_LEAF;
    out->c_rebuild = ACCEL_RESTRUCTURE_DEFAULT_C_REBUILD;
    out->c_refine = ACCEL_RESTRUCTURE_DEFAULT_C_REFINE;
    out->rays_per_frame = ACCEL_RESTRUCTURE_DEFAULT_RAYS;
    out->max_lifetime = ACCEL_RESTRUCTURE_DEFAULT_MAX_LIFETIME;
    out->max_pairs = 0;
    out->verify_cost = 1;
    bvh_build_params_default(&out->build);
}

static void normalize_params(struct accel_restructure_params *out,
                             const struct accel_restructure_params *params)
{
    struct accel_restructure_params d;
    accel_restructure_params_default(&d);
    if (!params) {
        *out = d;
        return;
    }
    *out = *params;
    if (!isfinite(out->c_leaf) || !(out->c_leaf > 0.0f))
        out->c_leaf = d.c_leaf;
    if (!isfinite(out->c_rebuild) || !(out->c_rebuild >= 0.0f))
        out->c_rebuild = d.c_rebuild;
    if (!isfinite(out->c_refine) || !(out->c_refine >= 0.0f))
        out->c_refine = d.c_refine;
    if (!isfinite(out->rays_per_frame) || !(out->rays_per_frame >= 0.0))
        out->rays_per_frame = d.rays_per_frame;
    if (!isfinite(out->max_lifetime) || !(out->max_lifetime >= 1.0f))
        out->max_lifetime = d.max_lifetime;
    accel_build_params_normalize(&out->build, &params->build);
}

/* Grows array `ptr` to `count` elements or makes the enclosing function
 * return -1, leaving it as it was (rt_realloc_array keeps the old block on
 * failure).  A macro so that each array keeps its own pointer type. */
#define RS_GROW(ptr, count)                                                                    \
    do {                                                                                       \
        void *grown_ = rt_realloc_array((ptr), (count), sizeof(*(ptr)));                       \
        if (!grown_)                                                                           \
            return -1;                                                                         \
        (ptr) = grown_;                                                                        \
    } while (0)

int rs_reserve_nodes(struct accel_restructure_state *st, uint32_t node_count)
{
    if (st->node_cap >= node_count)
        return 0;
    /* Each array keeps whatever it got; node_cap only moves when all did. */
    RS_GROW(st->parent, node_count);
    RS_GROW(st->prims, node_count);
    RS_GROW(st->repl, node_count);
    RS_GROW(st->order, node_count);
    RS_GROW(st->cost, node_count);
    RS_GROW(st->flags, node_count);
    RS_GROW(st->depth, node_count);
    st->node_cap = node_count;
    return 0;
}

int rs_reserve_prims(struct accel_restructure_state *st, uint32_t prim_count)
{
    if (st->prim_cap >= prim_count)
        return 0;
    RS_GROW(st->tmp_ids, prim_count);
    RS_GROW(st->tmp_boxes, prim_count);
    st->prim_cap = prim_count;
    return 0;
}

/* 1 when every inner node's children come after it and inside the array,
 * the numbering all of bvh_layout.h's builders produce (build_internal.h,
 * build_median.h: children are allocated after their parent).  Then index
 * order is a pre-order and its reverse is bottom-up. */
static int parent_first(const struct bvh *bvh)
{
    for (uint32_t i = 0; i < bvh->node_count; i++) {
        const struct bvh_node *n = &bvh->nodes[i];
        if (!n->count && (n->first <= i || n->first >= bvh->node_count - 1))
            return 0;
    }
    return 1;
}

/* A pre-order of the nodes for any other numbering; 0, or -1 when the
 * structure breaks the contract (child out of range, a node reached
 * twice, or deeper than BVH_MAX_DEPTH). */
static int pre_order(const struct bvh *bvh, uint32_t *order)
{
    uint32_t stack[BVH_MAX_DEPTH + 2];
    uint32_t depth[BVH_MAX_DEPTH + 2];
    uint32_t sp = 0;
    uint32_t count = 0;
    stack[sp] = 0;
    depth[sp++] = 0;
    while (sp > 0) {
        sp--;
        uint32_t i = stack[sp];
        uint32_t d = depth[sp];
        if (count == bvh->node_count)
            return -1;
        order[count++] = i;
        const struct bvh_node *n = &bvh->nodes[i];
        if (n->count)
            continue;
        if (d >= BVH_MAX_DEPTH || n->first >= bvh->node_count - 1)
            return -1;
        stack[sp] = n->first + 1;
        depth[sp++] = d + 1;
        stack[sp] = n->first;
        depth[sp++] = d + 1;
    }
    return count == bvh->node_count ? 0 : -1;
}

/* Yoon, Curtis and Manocha (2007) sec. 5.1: "We first perform BV refitting by updating the BVs
 * in a bottom-up manner".  The unions are refit.h's (build_min/build_max,
 * left child then right, slots in order), so the boxes equal
 * accel_refit's bit for bit; this copy walks a given pre-order, which the
 * metrics pass shares, and keeps this file independent of refit.c. */
void rs_refit(struct bvh *bvh, const struct aabb *prim_boxes, const uint32_t *order)
{
    struct bvh_node *nodes = bvh->nodes;
    for (uint32_t j = bvh->node_count; j-- > 0;) {
        uint32_t i = order ? order[j] : j;
        struct bvh_node *n = &nodes[i];
        struct aabb box;
        if (n->count) {
            box = prim_boxes[bvh->prim_index[n->first]];
            for (uint32_t s = n->first + 1; s < n->first + n->count; s++) {
                const struct aabb *b = &prim_boxes[bvh->prim_index[s]];
                for (int k = 0; k < 3; k++) {
                    box.min[k] = build_min(box.min[k], b->min[k]);
                    box.max[k] = build_max(box.max[k], b->max[k]);
                }
            }
        } else {
            const struct bvh_node *l = &nodes[n->first];
            const struct bvh_node *r = &nodes[n->first + 1];
            for (int k = 0; k < 3; k++) {
                box.min[k] = build_min(l->aabb_min[k], r->aabb_min[k]);
                box.max[k] = build_max(l->aabb_max[k], r->aabb_max[k]);
            }
        }
        build_set_box(n, &box);
    }
}

/* Appends a pair to the pair array (which is also the FIFO pair-queue);
 * 0, or -1 when the array cannot grow. */
static int push_pair(struct rs_frame *f, uint32_t n1, uint32_t n2, uint32_t lca, uint32_t parent)
{
    struct accel_restructure_state *st = f->st;
    if (f->pair_count == st->pair_cap) {
        uint64_t want = st->pair_cap ? 2 * (uint64_t)st->pair_cap : 256;
        uint32_t cap = want < f->pair_limit ? (uint32_t)want : f->pair_limit;
        RS_GROW(st->pairs, cap);
        st->pair_cap = cap;
    }
    struct accel_restructure_pair *p = &st->pairs[f->pair_count++];
    p->n1 = n1;
    p->n2 = n2;
    p->lca = lca;
    p->parent = parent;
    p->benefit = 0.0;
    return 0;
}

/* Volume of a node's box, for the choice of the node to refine. */
static double node_volume(const struct bvh_node *n)
{
    double v = 1.0;
    for (int k = 0; k < 3; k++)
        v *= (double)n->aabb_max[k] - (double)n->aabb_min[k];
    return v;
}

int rs_refine_pairs(struct rs_frame *f)
{
    struct accel_restructure_state *st = f->st;
    const struct bvh_node *nodes = f->bvh->nodes;
    const double c_refine = f->p.c_refine;
    f->pair_count = 0;
    if (nodes[0].count || f->pair_limit == 0)
        return 0;
    /* Alg. 1 line 2: "PairQ <- (Left(n_Root), Right(n_Root))". */
    if (push_pair(f, nodes[0].first, nodes[0].first + 1, 0, RS_NONE))
        return -1;
    st->flags[0] |= RS_SEEDED;
    int status = 0;
    for (uint32_t head = 0; head < f->pair_count && status == 0; head++) {
        /* Copied: push_pair may move the array. */
        struct accel_restructure_pair pair = st->pairs[head];
        f->stats->pairs_examined++;
        /* Line 5, "EvaluateRM-IQ (Pair)": eq. 7 for both nodes, times the
         * rays per frame (sec. 4.1.1) and the life time (sec. 5.4). */
        double benefit = rs_rm_iq(f, &pair) * f->factor;
        st->pairs[head].benefit = benefit;
        /* Line 7, "WorthRefine(Pair)": the restructuring benefit against
         * the refinement cost, C_refine per pair still in the queue. */
        double refine_cost = c_refine * (double)(f->pair_count - head);
        uint32_t refined = RS_NONE;
        if (benefit > refine_cost) {
            /* Sec. 5.2: "We compare the volumes of both the BVs and select
             * the node with the larger volume, say n1.  We refine this
             * node with its children, and create two new pairs,
             * (Left(n1), n2) and (Right(n1), n2)".  A leaf cannot be
             * refined; then the other node is. */
            int leaf1 = nodes[pair.n1].count != 0;
            int leaf2 = nodes[pair.n2].count != 0;
            if (!leaf1 || !leaf2) {
                int first = leaf2 || (!leaf1 && node_volume(&nodes[pair.n1]) >=
                                                    node_volume(&nodes[pair.n2]));
                refined = first ? pair.n1 : pair.n2;
                uint32_t c = nodes[refined].first;
                /* n1 stays the node under Left(lca). */
                if (f->pair_count + 2 <= f->pair_limit) {
                    if (first)
                        status = push_pair(f, c, pair.n2, pair.lca, head) ||
                                 push_pair(f, c + 1, pair.n2, pair.lca, head);
                    else
                        status = push_pair(f, pair.n1, c, pair.lca, head) ||
                                 push_pair(f, pair.n1, c + 1, pair.lca, head);
                }
            }
        }
        /* Sibling pairs: "At the same time, we also add another pair
         * (Left(n1), Right(n1))" for the refined node, and the pairs of
         * the children of a non-overlapping pair, gated by the bound (see
         * the header comment). */
        const uint32_t members[2] = {pair.n1, pair.n2};
        for (int s = 0; s < 2 && status == 0; s++) {
            uint32_t m = members[s];
            if (nodes[m].count || (st->flags[m] & RS_SEEDED))
                continue;
            if (m != refined && !(rs_refine_bound(f, m) * f->factor > refine_cost))
                continue;
            if (f->pair_count >= f->pair_limit)
                break;
            status = push_pair(f, nodes[m].first, nodes[m].first + 1, m, head);
            st->flags[m] |= RS_SEEDED;
        }
    }
    /* Line 10, "Propagate (Pair)": each pair's RM-IQ is added to the pair
     * it was refined from, recursively up to the first pair (sec. 5.2,
     * "Propagation").  Done in one backward sweep after the loop: a pair
     * always follows its parent in the array and the refinement never
     * reads the propagated values, so the sums are the same. */
    for (uint32_t j = f->pair_count; j-- > 1;)
        st->pairs[st->pairs[j].parent].benefit += st->pairs[j].benefit;
    return status ? -1 : 0;
}

/* The pair-heap (sec. 5.3): a binary max-heap keyed by benefit - cost. */
static int heap_above(const struct accel_restructure_heap_entry *a,
                      const struct accel_restructure_heap_entry *b)
{
    if (a->net != b->net)
        return a->net > b->net;
    return a->pair < b->pair; /* deterministic ties: the earlier (higher) pair first */
}

static void heap_down(struct accel_restructure_heap_entry *heap, uint32_t n, uint32_t i)
{
    for (;;) {
        uint32_t best = i;
        uint32_t l = 2 * i + 1;
        uint32_t r = l + 1;
        if (l < n && heap_above(&heap[l], &heap[best]))
            best = l;
        if (r < n && heap_above(&heap[r], &heap[best]))
            best = r;
        if (best == i)
            return;
        struct accel_restructure_heap_entry t = heap[i];
        heap[i] = heap[best];
        heap[best] = t;
        i = best;
    }
}

static int reserve_heap(struct accel_restructure_state *st, uint32_t count)
{
    if (st->heap_cap < count) {
        RS_GROW(st->heap, count);
        st->heap_cap = count;
    }
    return 0;
}

/* Fills the heap with the pairs worth restructuring; returns their count
 * or RS_NONE when the heap array cannot grow. */
static uint32_t build_heap(struct rs_frame *f)
{
    struct accel_restructure_state *st = f->st;
    if (reserve_heap(st, f->pair_count))
        return RS_NONE;
    uint32_t n = 0;
    for (uint32_t j = 0; j < f->pair_count; j++) {
        const struct accel_restructure_pair *p = &st->pairs[j];
        /* Line 17, "WorthRebuild (Pair)": benefit larger than f_rebuild.
         * Pairs that fail it now fail it when popped too (keys do not
         * change), so they stay out. */
        double net = p->benefit - rs_rebuild_cost(f, st->prims[p->n1] + st->prims[p->n2]);
        if (net > 0.0) {
            st->heap[n].net = net;
            st->heap[n].pair = j;
            n++;
        }
    }
    for (uint32_t i = n / 2; i-- > 0;)
        heap_down(st->heap, n, i);
    return n;
}

/* The restructuring phase (sec. 5.3, Alg. 1 lines 12-21); 0 or -1. */
static int restructure_pairs(struct rs_frame *f, uint32_t heap_size)
{
    struct accel_restructure_state *st = f->st;
    const uint8_t busy = RS_LOCKED | RS_ABOVE;
    const uint32_t root_left = f->bvh->nodes[0].first;
    while (heap_size > 0) {
        /* Once both children of the root are restructured, every node
         * but the root is locked: the rest of the heap would be skipped
         * one by one. */
        if ((st->flags[root_left] & RS_LOCKED) && (st->flags[root_left + 1] & RS_LOCKED)) {
            f->stats->rejected_overlap += heap_size;
            break;
        }
        uint32_t j = st->heap[0].pair;
        st->heap[0] = st->heap[--heap_size];
        heap_down(st->heap, heap_size, 0);
        const struct accel_restructure_pair pair = st->pairs[j];
        if ((st->flags[pair.n1] & busy) || (st->flags[pair.n2] & busy)) {
            f->stats->rejected_overlap++;
            continue;
        }
        struct rs_candidate c;
        int r = rs_build_candidate(f, &pair, &c);
        if (r < 0)
            return -1;
        if (r > 0) {
            f->stats->rejected_depth++;
            continue;
        }
        if (f->p.verify_cost && !(c.mass_delta < 0.0)) {
            f->stats->rejected_cost++;
            rs_candidate_release(&c);
            continue;
        }
        if (rs_commit(f, &pair, &c))
            return -1;
    }
    return 0;
}

/* Records the total time and returns status. */
static int finish(struct accel_restructure_stats *stats, double t0, int status)
{
    stats->ms_total = rt_now_ms() - t0;
    return status;
}

int accel_restructure(struct bvh *bvh, const struct aabb *prim_boxes,
                      struct accel_restructure_state *state,
                      const struct accel_restructure_params *params,
                      struct accel_restructure_stats *stats)
{
    double t0 = rt_now_ms();
    struct accel_restructure_stats local;
    if (!stats)
        stats = &local;
    memset(stats, 0, sizeof(*stats));
    struct rs_frame f;
    memset(&f, 0, sizeof(f));
    f.bvh = bvh;
    f.boxes = prim_boxes;
    f.st = state;
    f.stats = stats;
    normalize_params(&f.p, params);
    if (bvh->node_count == 0)
        return finish(stats, t0, 0);

    /* Sec. 5.1: "We first perform BV refitting by updating the BVs in a
     * bottom-up manner".  A BVH numbered otherwise than parent-first
     * needs the order array for that, hence the scratch first. */
    int scratch_ok = rs_reserve_nodes(state, bvh->node_count) == 0;
    if (!parent_first(bvh)) {
        if (!scratch_ok || pre_order(bvh, state->order))
            return finish(stats, t0, -1);
        f.order = state->order;
    }
    rs_refit(bvh, prim_boxes, f.order);
    stats->lifetime = rs_lifetime(state, bvh->node_count, f.p.max_lifetime);
    double t1 = rt_now_ms();
    stats->ms_refit = t1 - t0;
    if (!scratch_ok)
        return finish(stats, t0, -1);

    /* Sec. 5.1: "we evaluate the culling efficiency metric for each node
     * of the BVH". */
    uint32_t max_depth = rs_metrics_pass(&f);
    f.root_area = rs_node_area(&bvh->nodes[0]);
    double before = f.root_area > 0.0 ? state->cost[0] : 0.0;
    stats->sah_before = before;
    stats->sah_after = before;
    if (max_depth > BVH_MAX_DEPTH)
        return finish(stats, t0, -1);
    f.factor = f.p.rays_per_frame * stats->lifetime;
    f.pair_limit = f.p.max_pairs ? f.p.max_pairs : bvh->node_count;

    /* Alg. 1: the hierarchical refinement phase, then the restructuring
     * phase; the re-layout applies what the latter accepted. */
    int status = rs_refine_pairs(&f);
    uint32_t heap_size = 0;
    if (status == 0) {
        heap_size = build_heap(&f);
        if (heap_size == RS_NONE)
            status = -1;
    }
    stats->pairs_candidates = status == 0 ? heap_size : 0;
    double t2 = rt_now_ms();
    stats->ms_refine = t2 - t1;
    if (status == 0 && heap_size > 0) {
        status = rs_reserve_prims(state, bvh->prim_count);
        if (status == 0)
            status = restructure_pairs(&f, heap_size);
        if (status == 0 && f.repl_count > 0)
            status = rs_relayout(&f);
    }
    if (status != 0) {
        /* Back to the plain refit: the structure is untouched until the
         * re-layout, which fails before changing anything, and only boxes
         * of restructured nodes and their ancestors have moved. */
        rs_drop_replacements(&f);
        rs_refit(bvh, prim_boxes, f.order);
        stats->restructures = 0;
        stats->nodes_restructured = 0;
        stats->prims_restructured = 0;
        stats->ms_restructure = rt_now_ms() - t2;
        return finish(stats, t0, -1);
    }
    /* Sec. 5.4's life time counts rebuilt nodes. */
    state->nodes_created += (double)stats->nodes_restructured;
    if (f.root_area > 0.0)
        stats->sah_after = before + f.mass_delta / f.root_area;
    stats->ms_restructure = rt_now_ms() - t2;
    return finish(stats, t0, 0);
}
