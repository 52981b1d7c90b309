/* SPDX-License-Identifier: Apache-2.0 */
/*
 * restructure_metrics.c - the two metrics of Yoon, Curtis and Manocha (2007) sec. 4 (CM-IQ,
 * the culling efficiency of a sub-BVH; RM-IQ, the benefit of
 * restructuring a node pair), the bound that lets the pair-queue descend
 * (restructure.c), the restructuring cost f_rebuild and the expected life
 * time of sec. 5.4.
 *
 * Costs are counted in ray/AABB tests and areas are half surface areas
 * (restructure_internal.h).  CM-IQ is kept per node in double: the sums
 * run over whole trees and their differences decide restructurings.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "accel/restructure_internal.h"

/* P(c) of eq. 2, the probability that child c is hit given that its
 * parent is.  A parent of zero area (primitives on a line or at a point)
 * has children of zero area that every ray through it meets: 1 then,
 * where eq. 2 would give 0/0. */
static double hit_probability(float child_area, float parent_area)
{
    return parent_area > 0.0f ? (double)child_area / (double)parent_area : 1.0;
}

uint32_t rs_metrics_pass(struct rs_frame *f)
{
    struct accel_restructure_state *st = f->st;
    const struct bvh_node *nodes = f->bvh->nodes;
    const uint32_t n = f->bvh->node_count;
    const double c_leaf = f->p.c_leaf;
    /* Children before parents: the reverse of a pre-order. */
    for (uint32_t j = n; j-- > 0;) {
        uint32_t i = f->order ? f->order[j] : j;
        const struct bvh_node *node = &nodes[i];
        st->flags[i] = 0;
        st->repl[i] = RS_NONE;
        if (node->count) {
            /* Eq. 1, leaf: |n|_tri * C_leaf. */
            st->prims[i] = node->count;
            st->cost[i] = (double)node->count * c_leaf;
            continue;
        }
        uint32_t l = node->first;
        uint32_t r = l + 1;
        float area = rs_node_area(node);
        st->parent[l] = i;
        st->parent[r] = i;
        st->prims[i] = st->prims[l] + st->prims[r];
        /* Eq. 1, inner: 1 + P(Left) C(Left) + P(Right) C(Right), with
         * P from eq. 2 (the surface-area heuristic). */
        st->cost[i] = 1.0 + hit_probability(rs_node_area(&nodes[l]), area) * st->cost[l] +
                      hit_probability(rs_node_area(&nodes[r]), area) * st->cost[r];
    }
    st->parent[0] = RS_NONE;
    /* Depths, parents before children. */
    uint32_t max_depth = 0;
    st->depth[0] = 0;
    for (uint32_t j = 0; j < n; j++) {
        uint32_t i = f->order ? f->order[j] : j;
        const struct bvh_node *node = &nodes[i];
        if (node->count)
            continue;
        uint32_t d = (uint32_t)st->depth[i] + 1;
        if (d > max_depth)
            max_depth = d;
        /* Saturates: a deeper tree breaks the contract and is only
         * refitted (the caller checks max_depth). */
        uint8_t stored = d > BVH_MAX_DEPTH ? (uint8_t)(BVH_MAX_DEPTH + 1) : (uint8_t)d;
        st->depth[node->first] = stored;
        st->depth[node->first + 1] = stored;
    }
    return max_depth;
}

/*
 * RM-IQ of a pair (n1, n2), per ray: R(n1, ^n1, n2) + R(n2, ^n2, n1) with
 * eq. 7, R(n1, ^n1, n2) = C(n1) Area(n1^r) / Area(n1) P(n1).
 *
 * Area(n1^r) (sec. 4.3, "Complete Removal of BV Overlap"): "if we use
 * AABB as BVs, half of the surface areas of faces of the overlapping
 * region, except for faces parallel to the dividing plane, will be
 * reduced from Area(n1)".  With the overlap's extents o and the dividing
 * plane normal to axis d, those faces have total area 2 o_d (o_a + o_b);
 * half of it is o_d (o_a + o_b), and in half-area units o_d (o_a + o_b) / 2.
 * The dividing plane is the one the restructuring will use (sec. 5.3):
 * normal to the longest axis of BV(lca).  The reduction cannot exceed the
 * node's own area (ratio clamped to 1).
 *
 * P(n1) stands for P(^n1) (sec. 4.2.1).  It is the probability that a
 * ray hitting the root reaches n1, Area(n1) / Area(root): the chain of
 * eq. 2's conditional probabilities from the root down, which is what
 * puts every pair's benefit in the same unit (per ray hitting the root,
 * sec. 4.1.1) as the costs it is compared with.  So each term is
 * C(n1) min(Area(n1^r), Area(n1)) / Area(root).
 */
double rs_rm_iq(const struct rs_frame *f, const struct accel_restructure_pair *pair)
{
    const struct bvh_node *nodes = f->bvh->nodes;
    const struct bvh_node *a = &nodes[pair->n1];
    const struct bvh_node *b = &nodes[pair->n2];
    if (!(f->root_area > 0.0))
        return 0.0;
    double o[3];
    for (int k = 0; k < 3; k++) {
        float lo = a->aabb_min[k] > b->aabb_min[k] ? a->aabb_min[k] : b->aabb_min[k];
        float hi = a->aabb_max[k] < b->aabb_max[k] ? a->aabb_max[k] : b->aabb_max[k];
        o[k] = (double)hi - (double)lo;
        /* Written so that a NaN also means "no overlap". */
        if (!(o[k] >= 0.0))
            return 0.0;
    }
    const struct bvh_node *lca = &nodes[pair->lca];
    int d = 0;
    for (int k = 1; k < 3; k++) {
        if (lca->aabb_max[k] - lca->aabb_min[k] > lca->aabb_max[d] - lca->aabb_min[d])
            d = k;
    }
    double reduced = 0.5 * o[d] * (o[(d + 1) % 3] + o[(d + 2) % 3]);
    double area_a = rs_node_area(a);
    double area_b = rs_node_area(b);
    double r1 = f->st->cost[pair->n1] * (reduced < area_a ? reduced : area_a);
    double r2 = f->st->cost[pair->n2] * (reduced < area_b ? reduced : area_b);
    return (r1 + r2) / f->root_area;
}

/*
 * An upper bound on the per-ray RM-IQ of any pair (a, b) of disjoint
 * nodes inside sub-BVH(n), for the pair-queue's descent (restructure.c,
 * rs_refine_pairs).  Each term of eq. 7 is at most C(a) P(a) = S(a) /
 * Area(root) (the area ratio is at most 1), and S(a) + S(b) <= S(n) -
 * A(n) for disjoint sub-BVHs strictly inside n, so the bound is
 * (C(n) - 1) Area(n) / Area(root).
 */
double rs_refine_bound(const struct rs_frame *f, uint32_t n)
{
    if (!(f->root_area > 0.0))
        return 0.0;
    double area = rs_node_area(&f->bvh->nodes[n]);
    double c = f->st->cost[n] - 1.0;
    return c > 0.0 ? c * area / f->root_area : 0.0;
}

/* Sec. 4.3: "f_rebuild(n1, n2) = C_rebuild * (k log k), where k =
 * (|n1|_tri + |n2|_tri)", log base 2 (the constant absorbs the base). */
double rs_rebuild_cost(const struct rs_frame *f, uint32_t k)
{
    double kk = (double)k;
    return (double)f->p.c_rebuild * kk * (k > 1 ? log2(kk) : 1.0);
}

/*
 * Sec. 5.4: "This expected life time is simply computed as an average
 * life time of all nodes by considering the number of rebuilt nodes and
 * the number of nodes in the BVH from the first frame to the current
 * frame."  Read as node-frames lived so far over nodes ever created (the
 * first frame's nodes plus every rebuilt node): F frames without a
 * rebuild give F; rebuilding every node each frame gives about 1.
 * Capped by max_lifetime (restructure.h) and at least 1.
 */
double rs_lifetime(struct accel_restructure_state *st, uint32_t node_count, float max_lifetime)
{
    if (st->frames == 0)
        st->nodes_created = (double)node_count;
    st->frames++;
    st->node_frames += (double)node_count;
    double life = st->nodes_created > 0.0 ? st->node_frames / st->nodes_created : 1.0;
    if (!(life >= 1.0))
        life = 1.0;
    if (life > (double)max_lifetime)
        life = (double)max_lifetime;
    return life;
}

double rs_tree_mass(const struct bvh *t, float c_leaf)
{
    double mass = 0.0;
    for (uint32_t i = 0; i < t->node_count; i++) {
        const struct bvh_node *n = &t->nodes[i];
        double area = rs_node_area(n);
        mass += n->count ? area * (double)n->count * (double)c_leaf : area;
    }
    return mass;
}
