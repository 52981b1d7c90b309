/* SPDX-License-Identifier: Apache-2.0 */
/*
 * restructure_apply.c - the basic restructuring operation of Yoon, Curtis and Manocha (2007)
 * (sec. 3.2, fig. 4): the primitives of sub-BVH(n1) and sub-BVH(n2) are
 * pooled, split in two by the partitioning plane of sec. 5.3, and each
 * side gets a new SAH sub-BVH (sec. 5.4) that takes the place of n1 and
 * of n2.  Also the re-layout that writes all of a frame's restructurings
 * into fresh node and slot arrays.
 *
 * An operation is computed first (rs_build_candidate: new sub-BVHs, new
 * boxes of the ancestors up to the lowest common ancestor, change of the
 * tree's CM-IQ) and only then accepted (rs_commit), which records it
 * without touching the BVH's structure: the BVH keeps the old sub-BVHs
 * and only the boxes of n1, n2 and their ancestors below the lca change.
 * rs_relayout applies everything at the end of the frame, so that an
 * allocation failure anywhere before it can be undone with a refit.
 *
 * Why a re-layout: the new sub-BVHs generally differ in node count and in
 * how many primitives each side holds, so they fit neither the old node
 * slots nor the old leaf slot ranges; and the node numbering must stay
 * parent-first (bvh_layout.h's builders guarantee it, refit walks the array
 * backwards relying on it).  Writing the tree depth first into a second
 * array costs one linear pass per frame with any restructuring, the
 * order of the refit that precedes it, and gives the same numbering as
 * the builders (left subtree first, sibling pairs adjacent, each
 * sub-BVH's leaf slots contiguous).
 */
#include <assert.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "accel/build_internal.h"
#include "accel/restructure_internal.h"
#include "base/alloc.h"

/* A walk stack for sub-BVHs of depth <= BVH_MAX_DEPTH, pushing both
 * children and popping one: at most depth + 1 entries. */
#define WALK_STACK (BVH_MAX_DEPTH + 2)

/* Appends the caller indices of sub-BVH(root)'s primitives to ids[*k..]
 * and returns the sub-BVH's node count. */
static uint32_t gather_prims(const struct bvh *bvh, uint32_t root, uint32_t *ids, uint32_t *k)
{
    uint32_t stack[WALK_STACK];
    uint32_t sp = 0;
    uint32_t nodes = 0;
    stack[sp++] = root;
    while (sp > 0) {
        const struct bvh_node *n = &bvh->nodes[stack[--sp]];
        nodes++;
        if (n->count) {
            memcpy(&ids[*k], &bvh->prim_index[n->first], sizeof(*ids) * n->count);
            *k += n->count;
            continue;
        }
        /* Depth is checked by the caller (rs_metrics_pass), so the stack
         * cannot overflow. */
        stack[sp++] = n->first + 1;
        stack[sp++] = n->first;
    }
    return nodes;
}

/* Sets `flag` on every node of sub-BVH(root). */
static void mark_subtree(const struct bvh *bvh, uint8_t *flags, uint32_t root, uint8_t flag)
{
    uint32_t stack[WALK_STACK];
    uint32_t sp = 0;
    stack[sp++] = root;
    while (sp > 0) {
        uint32_t i = stack[--sp];
        flags[i] |= flag;
        const struct bvh_node *n = &bvh->nodes[i];
        if (!n->count) {
            stack[sp++] = n->first + 1;
            stack[sp++] = n->first;
        }
    }
}

/* Doubled centroid on one axis, the builders' convention. */
static inline float centroid2(const struct aabb *b, int axis)
{
    return b->min[axis] + b->max[axis];
}

/* Total order for the median fallback: centroid, then caller index. */
static inline int prim_less(const struct aabb *boxes, const uint32_t *ids, uint32_t i, uint32_t j,
                            int axis)
{
    uint32_t ki = build_float_order(centroid2(&boxes[i], axis));
    uint32_t kj = build_float_order(centroid2(&boxes[j], axis));
    if (ki != kj)
        return ki < kj;
    return ids[i] < ids[j];
}

static inline void swap_prims(struct aabb *boxes, uint32_t *ids, uint32_t i, uint32_t j)
{
    struct aabb tb = boxes[i];
    boxes[i] = boxes[j];
    boxes[j] = tb;
    uint32_t ti = ids[i];
    ids[i] = ids[j];
    ids[j] = ti;
}

/* Heapsort of the parallel arrays by prim_less: O(k log k) worst case,
 * no allocation (libc's qsort may allocate behind rt_malloc's back). */
static void sort_prims(struct aabb *boxes, uint32_t *ids, uint32_t k, int axis)
{
    for (uint32_t start = k / 2; start-- > 0;) {
        uint32_t root = start;
        for (;;) {
            uint32_t child = 2 * root + 1;
            if (child >= k)
                break;
            if (child + 1 < k && prim_less(boxes, ids, child, child + 1, axis))
                child++;
            if (!prim_less(boxes, ids, root, child, axis))
                break;
            swap_prims(boxes, ids, root, child);
            root = child;
        }
    }
    for (uint32_t end = k; end-- > 1;) {
        swap_prims(boxes, ids, 0, end);
        uint32_t root = 0;
        for (;;) {
            uint32_t child = 2 * root + 1;
            if (child >= end)
                break;
            if (child + 1 < end && prim_less(boxes, ids, child, child + 1, axis))
                child++;
            if (!prim_less(boxes, ids, root, child, axis))
                break;
            swap_prims(boxes, ids, root, child);
            root = child;
        }
    }
}

/*
 * The partitioning plane of Yoon, Curtis and Manocha (2007) sec. 5.3: "We set the partitioning
 * plane to pass the centroid of the overlapping area between
 * BV(Left(n_A)) and BV(Right(n_A)) and the normal of the plane is
 * parallel to a direction that has longest extent of BV(n_A)", n_A the
 * lowest common ancestor of n1 and n2, so that the ancestors' overlap
 * shrinks too.  When the two boxes do not overlap on that axis (a pair
 * whose benefit comes only from its descendants, see propagation in
 * restructure.c) the same formula gives the middle of the gap between
 * them.  n1 lies under Left(n_A) and takes the side of the plane where
 * Left(n_A)'s centre is.  Moves n1's share to the front of
 * boxes/ids[0, k) and returns its size, which is in [1, k - 1]: when the
 * plane leaves a side empty the pool is split at the median centroid
 * along the same axis instead (every node needs a primitive).
 */
static uint32_t partition_by_plane(const struct bvh *bvh, uint32_t lca, struct aabb *boxes,
                                   uint32_t *ids, uint32_t k)
{
    const struct bvh_node *a = &bvh->nodes[lca];
    const struct bvh_node *left = &bvh->nodes[a->first];
    const struct bvh_node *right = &bvh->nodes[a->first + 1];
    int axis = 0;
    for (int d = 1; d < 3; d++) {
        if (a->aabb_max[d] - a->aabb_min[d] > a->aabb_max[axis] - a->aabb_min[axis])
            axis = d;
    }
    float lo = build_max(left->aabb_min[axis], right->aabb_min[axis]);
    float hi = build_min(left->aabb_max[axis], right->aabb_max[axis]);
    float plane2 = lo + hi; /* doubled, like centroid2 */
    int n1_below = left->aabb_min[axis] + left->aabb_max[axis] <=
                   right->aabb_min[axis] + right->aabb_max[axis];
    uint32_t first_other = 0;
    for (uint32_t i = 0; i < k; i++) {
        float c = centroid2(&boxes[i], axis);
        int to_n1 = n1_below ? c < plane2 : c > plane2;
        if (to_n1) {
            swap_prims(boxes, ids, i, first_other);
            first_other++;
        }
    }
    if (first_other > 0 && first_other < k)
        return first_other;
    sort_prims(boxes, ids, k, axis);
    if (!n1_below) {
        /* n1 takes the upper half: reverse into descending order. */
        for (uint32_t i = 0; i < k / 2; i++)
            swap_prims(boxes, ids, i, k - 1 - i);
    }
    return k / 2;
}

void rs_candidate_release(struct rs_candidate *c)
{
    bvh_release(&c->tree[0]);
    bvh_release(&c->tree[1]);
}

/*
 * New boxes of the ancestors of `node` strictly below `lca` when node's
 * box becomes *box, and the change of their summed area.
 */
static double path_boxes(const struct rs_frame *f, uint32_t node, uint32_t lca,
                         const struct aabb *box, uint32_t *len, uint32_t *path_node,
                         struct aabb *path_box)
{
    const struct bvh_node *nodes = f->bvh->nodes;
    const uint32_t *parent = f->st->parent;
    double delta = 0.0;
    struct aabb child_box = *box;
    uint32_t child = node;
    uint32_t n = 0;
    for (uint32_t m = parent[node]; m != lca; m = parent[m]) {
        uint32_t sibling = nodes[m].first + (nodes[m].first == child ? 1u : 0u);
        struct aabb sb = rs_node_box(&nodes[sibling]);
        struct aabb nb = child_box;
        aabb_grow(&nb, &sb);
        delta += (double)aabb_half_area(&nb) - (double)rs_node_area(&nodes[m]);
        path_node[n] = m;
        path_box[n] = nb;
        n++;
        child_box = nb;
        child = m;
    }
    *len = n;
    return delta;
}

int rs_build_candidate(struct rs_frame *f, const struct accel_restructure_pair *pair,
                       struct rs_candidate *c)
{
    struct accel_restructure_state *st = f->st;
    const struct bvh *bvh = f->bvh;
    memset(c->tree, 0, sizeof(c->tree));
    /* Sec. 3.2: "we take the union of all the primitives in sub-BVH(n1)
     * and sub-BVH(n2)". */
    uint32_t k = 0;
    c->old_nodes[0] = gather_prims(bvh, pair->n1, st->tmp_ids, &k);
    c->old_nodes[1] = gather_prims(bvh, pair->n2, st->tmp_ids, &k);
    c->prims = k;
    for (uint32_t i = 0; i < k; i++)
        st->tmp_boxes[i] = f->boxes[st->tmp_ids[i]];
    /* Sec. 3.2: "re-partition the primitives in that union into new nodes
     * ^n1 and ^n2" with the plane of sec. 5.3. */
    uint32_t k1 = partition_by_plane(bvh, pair->lca, st->tmp_boxes, st->tmp_ids, k);
    /* Sec. 5.4: "employ a surface-area heuristic [WH06] within our basic
     * selective restructuring operations": each side is an SAH build. */
    const uint32_t begin[2] = {0, k1};
    const uint32_t count[2] = {k1, k - k1};
    for (int s = 0; s < 2; s++) {
        if (accel_build(&c->tree[s], &st->tmp_boxes[begin[s]], count[s], &f->p.build)) {
            rs_candidate_release(c);
            return -1;
        }
        struct bvh *t = &c->tree[s];
        for (uint32_t i = 0; i < t->prim_count; i++)
            t->prim_index[i] = st->tmp_ids[begin[s] + t->prim_index[i]];
    }
    /* The new sub-BVHs hang where n1 and n2 were. */
    if ((uint32_t)st->depth[pair->n1] + c->tree[0].depth > BVH_MAX_DEPTH ||
        (uint32_t)st->depth[pair->n2] + c->tree[1].depth > BVH_MAX_DEPTH) {
        rs_candidate_release(c);
        return 1;
    }
    /* Change of the tree's mass: the two sub-BVHs, plus the ancestors
     * below the lca whose boxes change with their primitive sets (the
     * lca's own box does not: it holds the same primitives). */
    const uint32_t old_root[2] = {pair->n1, pair->n2};
    double delta = 0.0;
    for (int s = 0; s < 2; s++) {
        const struct bvh_node *old = &bvh->nodes[old_root[s]];
        delta += rs_tree_mass(&c->tree[s], f->p.c_leaf) -
                 st->cost[old_root[s]] * (double)rs_node_area(old);
        struct aabb nb = rs_node_box(&c->tree[s].nodes[0]);
        delta += path_boxes(f, old_root[s], pair->lca, &nb, &c->path_len[s], c->path_node[s],
                            c->path_box[s]);
    }
    c->mass_delta = delta;
    return 0;
}

int rs_commit(struct rs_frame *f, const struct accel_restructure_pair *pair,
              struct rs_candidate *c)
{
    struct accel_restructure_state *st = f->st;
    struct bvh *bvh = f->bvh;
    if (f->repl_count + 2 > st->repl_cap) {
        uint32_t cap = st->repl_cap ? 2 * st->repl_cap : 16;
        struct bvh *grown = rt_realloc_array(st->repl_trees, cap, sizeof(*grown));
        if (!grown) {
            rs_candidate_release(c);
            return -1;
        }
        st->repl_trees = grown;
        st->repl_cap = cap;
    }
    const uint32_t old_root[2] = {pair->n1, pair->n2};
    for (int s = 0; s < 2; s++) {
        uint32_t n = old_root[s];
        const struct bvh *t = &c->tree[s];
        /* Locks first: they walk the old sub-BVH, which stays in the
         * array until the re-layout. */
        mark_subtree(bvh, st->flags, n, RS_LOCKED);
        for (uint32_t m = st->parent[n]; m != RS_NONE && !(st->flags[m] & RS_ABOVE);
             m = st->parent[m])
            st->flags[m] |= RS_ABOVE;
        /* Current boxes for later operations' ancestor boxes and for the
         * re-layout: n's box and its ancestors' below the lca. */
        struct aabb root_box = rs_node_box(&t->nodes[0]);
        build_set_box(&bvh->nodes[n], &root_box);
        for (uint32_t i = 0; i < c->path_len[s]; i++)
            build_set_box(&bvh->nodes[c->path_node[s][i]], &c->path_box[s][i]);
        st->repl[n] = f->repl_count;
        st->repl_trees[f->repl_count++] = *t;
        f->nodes_removed += c->old_nodes[s] - 1;
        f->nodes_added += t->node_count - 1;
        f->stats->nodes_restructured += t->node_count;
    }
    memset(c->tree, 0, sizeof(c->tree));
    f->mass_delta += c->mass_delta;
    f->stats->restructures++;
    f->stats->prims_restructured += c->prims;
    return 0;
}

void rs_drop_replacements(struct rs_frame *f)
{
    for (uint32_t i = 0; i < f->repl_count; i++)
        bvh_release(&f->st->repl_trees[i]);
    f->repl_count = 0;
}

/* A node waiting to be written by rs_relayout: node `src` of tree `tree`
 * (RS_NONE: the BVH itself, else a replacement) goes to slot `dst`. */
struct relayout_task {
    uint32_t tree;
    uint32_t src;
    uint32_t dst;
};

int rs_relayout(struct rs_frame *f)
{
    struct accel_restructure_state *st = f->st;
    struct bvh *bvh = f->bvh;
    uint32_t new_count = bvh->node_count - f->nodes_removed + f->nodes_added;
    if (st->spare_node_cap < new_count) {
        struct bvh_node *grown = rt_realloc_array(st->spare_nodes, new_count, sizeof(*grown));
        if (!grown)
            return -1;
        st->spare_nodes = grown;
        st->spare_node_cap = new_count;
    }
    if (st->spare_prim_cap < bvh->prim_count) {
        uint32_t *grown = rt_realloc_array(st->spare_prims, bvh->prim_count, sizeof(*grown));
        if (!grown)
            return -1;
        st->spare_prims = grown;
        st->spare_prim_cap = bvh->prim_count;
    }
    struct bvh_node *out = st->spare_nodes;
    uint32_t *slots = st->spare_prims;
    /* Depth first, right child pushed first so that the left subtree is
     * numbered first (the builders' order).  Every node of the result is
     * at depth <= BVH_MAX_DEPTH (rs_build_candidate), so the stack holds
     * at most BVH_MAX_DEPTH + 1 tasks. */
    struct relayout_task stack[BVH_MAX_DEPTH + 2];
    uint32_t sp = 0;
    uint32_t next = 1;
    uint32_t next_slot = 0;
    uint32_t depth_of[BVH_MAX_DEPTH + 2];
    uint32_t max_depth = 0;
    stack[sp].tree = RS_NONE;
    stack[sp].src = 0;
    stack[sp].dst = 0;
    depth_of[sp] = 0;
    sp++;
    while (sp > 0) {
        sp--;
        struct relayout_task t = stack[sp];
        uint32_t d = depth_of[sp];
        if (t.tree == RS_NONE && st->repl[t.src] != RS_NONE) {
            t.tree = st->repl[t.src];
            t.src = 0;
        }
        const struct bvh *from = t.tree == RS_NONE ? bvh : &st->repl_trees[t.tree];
        const struct bvh_node *node = &from->nodes[t.src];
        struct bvh_node *dst = &out[t.dst];
        *dst = *node;
        if (d > max_depth)
            max_depth = d;
        assert(t.dst < new_count);
        if (node->count) {
            /* Replacement trees already hold caller indices. */
            memcpy(&slots[next_slot], &from->prim_index[node->first],
                   sizeof(*slots) * node->count);
            dst->first = next_slot;
            next_slot += node->count;
            continue;
        }
        dst->first = next;
        stack[sp].tree = t.tree;
        stack[sp].src = node->first + 1;
        stack[sp].dst = next + 1;
        depth_of[sp] = d + 1;
        sp++;
        stack[sp].tree = t.tree;
        stack[sp].src = node->first;
        stack[sp].dst = next;
        depth_of[sp] = d + 1;
        sp++;
        next += 2;
    }
    assert(next == new_count && next_slot == bvh->prim_count);
    /* Swap: the BVH takes the new arrays, the state keeps the old ones
     * as next frame's spares. */
    struct bvh_node *old_nodes = bvh->nodes;
    uint32_t *old_slots = bvh->prim_index;
    uint32_t old_count = bvh->node_count;
    bvh->nodes = out;
    bvh->prim_index = slots;
    bvh->node_count = next;
    bvh->depth = max_depth;
    st->spare_nodes = old_nodes;
    st->spare_node_cap = old_count;
    st->spare_prims = old_slots;
    st->spare_prim_cap = bvh->prim_count;
    rs_drop_replacements(f);
    return 0;
}
