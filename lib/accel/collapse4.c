/* SPDX-License-Identifier: Apache-2.0 */
/*
 * collapse4.c - the binary BVH collapsed into the wide traversal layout,
 * 4- or 8-wide, with triangle packets for leaves (trace/bvh4_layout.h),
 * and its refit.
 *
 * Two steps: the greedy collapse into width-generic scratch nodes, level
 * by level at the top and per wide subtree (an item) below (a lane whose
 * binary subtree is small enough, in consecutive leaf slots, becomes a
 * packet leaf: small_span; in a large layout, so does a somewhat larger
 * one left closed under a full node when the area heuristic prefers it:
 * close_small_lanes); then the final nodes (with the per-octant child
 * order) and packets in one 64-byte aligned block.  Given a pool, both
 * share the items between its threads, with the same bytes as on one
 * thread (struct collapse).
 * A layout with many zero-area triangles is collapsed a second time
 * leaving them out of its leaves (collapse_wide_dropping,
 * drop_zero_area).
 * collapse4_avx2.c compiles this file again for AVX2 (the octant orders
 * and the packets' zero-area test four lanes of doubles at a time), with
 * the same bytes; accel_collapse_wide_reuse takes it where the CPU runs
 * it.
 */
#include "trace/bvh4_layout.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "accel/bvh_build.h"
#include "accel/collapse4_avx2.h"
#include "base/alloc.h"
#include "base/atomic.h"
#include "base/pool.h"
#include "trace/intersect.h"

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
#include <immintrin.h>
#elif defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <emmintrin.h>
#endif

#define MAX_WIDTH 8

/* A leaf lane of triangles is one or two packets: the 8-wide walks with
 * leaf8 test two as one 8-lane call (traverse_wide.h, wide_leaf8_test). */
typedef char wide_leaf_is_two_packets[BVH_WIDE_MAX_LEAF <= 8 ? 1 : -1];

/* About what a wide layout takes per triangle with merged leaves (the
 * memory table of rtbench embree: 60-67 bytes on bumpy, soup and the
 * kitchen); only the choice of merging depends on it. */
#define BVH_WIDE_BYTES_PER_TRIANGLE 64

/* A wide node before it is written in its width's layout: per lane the
 * binary node, the child (wide node or first packet, once numbered), and
 * for a leaf lane its triangles (or slots) from leaf slot first. */
struct scratch_node {
    uint32_t source[MAX_WIDTH];
    uint32_t child[MAX_WIDTH];
    uint32_t count[MAX_WIDTH];
    uint32_t first[MAX_WIDTH];
    /* A leaf lane's triangles in the layout (drop_zero_area): count[l]
     * less the zero-area ones left out, whose slots are the clear bits of
     * kept[l] (bit j: slot first[l] + j). */
    uint32_t live[MAX_WIDTH];
    uint32_t kept[MAX_WIDTH];
    /* bit l: leaf lane l's kept triangles are known to have an area (the
     * packets' fill leaves out its zero-area test) */
    uint32_t known;
    int lanes;
    uint32_t inner; /* bit l: lane l is an inner child */
};

static float node_area(const struct bvh_node *n)
{
    float dx = n->aabb_max[0] - n->aabb_min[0];
    float dy = n->aabb_max[1] - n->aabb_min[1];
    float dz = n->aabb_max[2] - n->aabb_min[2];
    return dx * dy + dy * dz + dz * dx;
}

/* Two sibling subtrees' slot spans as one: their total with the first
 * slot in *first when they are consecutive in either order, else 0. */
static inline uint32_t joined_span(uint32_t first_l, uint32_t span_l, uint32_t first_r,
                                   uint32_t span_r, uint32_t *first)
{
    if (first_l + span_l == first_r) {
        *first = first_l;
        return span_l + span_r;
    }
    if (first_r + span_r == first_l) {
        *first = first_r;
        return span_l + span_r;
    }
    return 0;
}

/* The triangles of binary subtree i when they are at most `budget` and
 * occupy consecutive leaf slots (returned, the first in *first), else 0.
 * Consecutive means: a leaf's slots, or the children's runs adjacent in
 * either order.  Builders partition slots in place, so a subtree's slots
 * are normally consecutive; restructuring can break that, and such a
 * subtree is then simply never merged.  The budget cuts the walk short:
 * the left child gets what the right one leaves at least (an inner node
 * holds at least two triangles, a leaf its count), the right child what
 * the left one left, so a large subtree is rejected after a few nodes
 * near its root.  Called with budget BVH_WIDE_MERGE this is the per-node
 * span of a bottom-up pass over every binary node, where that span is
 * at most BVH_WIDE_MERGE, and 0 where it is larger (same answers, but
 * only for the nodes the collapse looks at, and on any thread). */
static uint32_t small_span(const struct bvh *bvh, uint32_t i, uint32_t budget, uint32_t *first)
{
    const struct bvh_node *node = &bvh->nodes[i];
    if (node->count) {
        *first = node->first;
        return node->count <= budget ? node->count : 0;
    }
    if (budget < 2)
        return 0;
    const struct bvh_node *right = &bvh->nodes[node->first + 1];
    uint32_t right_least = right->count ? right->count : 2;
    if (right_least >= budget)
        return 0;
    uint32_t first_l, first_r;
    uint32_t span_l = small_span(bvh, node->first, budget - right_least, &first_l);
    if (!span_l)
        return 0;
    uint32_t span_r = small_span(bvh, node->first + 1, budget - span_l, &first_r);
    if (!span_r)
        return 0;
    return joined_span(first_l, span_l, first_r, span_r, first);
}

/* small_span counting only the triangles of non-zero area (zero[slot] 0)
 * against `budget`, and all of them against `cap` (the slots a lane can
 * hold, BVH_WIDE_MAX_LEAF): the slots' span (0: not such a subtree), the
 * first in *first, the triangles with an area in *live.  A subtree whose
 * zero-area triangles the collapse leaves out (drop_zero_area) is then
 * one packet when its other triangles fit one, as a subtree of that many
 * triangles would be; where zero is 0 throughout, the same spans as
 * small_span(budget) (every live count is its span, and cap >= budget).
 * The cap cuts the walk short as small_span's budget does. */
static uint32_t small_span_live(const struct bvh *bvh, const uint8_t *zero, uint32_t i,
                                uint32_t budget, uint32_t cap, uint32_t *first, uint32_t *live)
{
    const struct bvh_node *node = &bvh->nodes[i];
    if (node->count) {
        if (node->count > cap)
            return 0;
        uint32_t n = 0;
        for (uint32_t j = 0; j < node->count; j++)
            n += zero[node->first + j] == 0;
        if (n > budget)
            return 0;
        *first = node->first;
        *live = n;
        return node->count;
    }
    if (cap < 2)
        return 0;
    const struct bvh_node *right = &bvh->nodes[node->first + 1];
    uint32_t right_least = right->count ? right->count : 2;
    if (right_least >= cap)
        return 0;
    uint32_t first_l, first_r, live_l, live_r;
    uint32_t span_l =
        small_span_live(bvh, zero, node->first, budget, cap - right_least, &first_l, &live_l);
    if (!span_l)
        return 0;
    uint32_t span_r = small_span_live(bvh, zero, node->first + 1, budget - live_l, cap - span_l,
                                      &first_r, &live_r);
    if (!span_r)
        return 0;
    *live = live_l + live_r;
    return joined_span(first_l, span_l, first_r, span_r, first);
}

/* leaf_lane's merge by the triangles of non-zero area: small_span_live
 * of one packet in at most BVH_WIDE_MAX_LEAF slots.  Out of line, with
 * its live count local: in set_lane, which every collapse calls once a
 * lane, the count's stack slot gave every call a frame (bumpy's
 * collapse, without a zero-area triangle, +2 % instructions). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static uint32_t leaf_span_live(const struct bvh *bvh, const uint8_t *zero, uint32_t i,
                               uint32_t *first)
{
    uint32_t live;
    return small_span_live(bvh, zero, i, BVH_WIDE_MERGE, BVH_WIDE_MAX_LEAF, first, &live);
}

/* Whether binary node i is a leaf of the wide layout (a binary leaf, or,
 * with triangles, a small subtree in consecutive slots), and then its
 * triangles or slots (*count) from *first.  Range leaves (no triangles)
 * are the binary leaves only: a merged subtree would visit (transform,
 * set up and enter) every instance under it, where the binary subtree's
 * boxes cull most of them. */
static int leaf_lane(const struct bvh *bvh, const float *tri, const uint8_t *zero, uint32_t i,
                     uint32_t *first, uint32_t *count)
{
    const struct bvh_node *node = &bvh->nodes[i];
    if (node->count) {
        *first = node->first;
        *count = node->count;
        return 1;
    }
    *count = !tri ? 0 : zero ? leaf_span_live(bvh, zero, i, first)
                             : small_span(bvh, i, BVH_WIDE_MERGE, first);
    return *count != 0;
}

/* Lane l of s is binary node i: whether it is inner (then
 * count 0) or a leaf (count and first its slots); returns its area. */
static float set_lane(const struct bvh *bvh, const float *tri, const uint8_t *zero,
                      struct scratch_node *s, int l, uint32_t i)
{
    s->source[l] = i;
    if (leaf_lane(bvh, tri, zero, i, &s->first[l], &s->count[l]))
        s->inner &= ~(1u << l);
    else
        s->inner |= 1u << l;
    return node_area(&bvh->nodes[i]);
}

/* The binary nodes wide node s over binary inner node `inner` holds:
 * starting from its two children, the openable (inner, not merged) one
 * of largest area is replaced by its children until there are `width`
 * (ties: the first). */
static void gather(const struct bvh *bvh, const float *tri, const uint8_t *zero, uint32_t inner,
                   uint32_t width, struct scratch_node *s)
{
    /* Each lane's area and openness, computed once when the lane is
     * added rather than at every step (the same values, so the same
     * picks). */
    float area[MAX_WIDTH];
    s->inner = 0;
    area[0] = set_lane(bvh, tri, zero, s, 0, bvh->nodes[inner].first);
    area[1] = set_lane(bvh, tri, zero, s, 1, bvh->nodes[inner].first + 1);
    uint32_t n = 2;
    while (n < width) {
        int pick = -1;
        float best = -1.0f;
        for (uint32_t i = 0; i < n; i++) {
            if ((s->inner >> i & 1u) && (pick < 0 || area[i] > best)) {
                pick = (int)i;
                best = area[i];
            }
        }
        if (pick < 0)
            break;
        uint32_t first = bvh->nodes[s->source[pick]].first;
        area[pick] = set_lane(bvh, tri, zero, s, pick, first);
        area[n] = set_lane(bvh, tri, zero, s, (int)n, first + 1);
        n++;
    }
    s->lanes = (int)n;
}

/* The cost of a leaf lane of n triangles for the greedy merge below, in
 * wide node tests (BVH_WIDE_NODE_COST): a leaf call, then each of its
 * ceil(n / 4) packets.  From the instructions a kitchen camera ray spends
 * (performance-log, round 39 rr3, AVX2, the finish left out as a hit's
 * cost whatever the tree): a one-packet leaf call about 196, a
 * two-packet (8-lane) call about 244, so the second packet about 48 and
 * the call about 148, against about 102 a wide node visit (the walk's
 * 750 over 7.36 visits): 1.45 and 0.47 node tests, rounded to 1.5 and
 * 0.5.  Counting a leaf as its packets alone (1 a packet, a node test as
 * one packet, Embree's SAH weights) priced the call at nothing and the
 * second packet at a node: it left closed many wide nodes of two or
 * three small leaf lanes that cost a node visit and a leaf call each
 * where one leaf lane of two packets costs one call (round 40, lv1: the
 * bumpy 8-wide layout 68,807 -> 45,535 nodes).  A heuristic only: the
 * answers do not depend on it. */
#define COLLAPSE_LEAF_CALL_COST 1.5
#define COLLAPSE_LEAF_PACKET_COST 0.5

static double leaf_lane_cost(uint32_t n)
{
    return COLLAPSE_LEAF_CALL_COST + COLLAPSE_LEAF_PACKET_COST * (double)((n + 3) / 4);
}

/* The expected cost, in wide node tests, of inner binary node i as a
 * wide node of its own, by the surface area heuristic (MacDonald and
 * Booth 1990): one node test (BVH_WIDE_NODE_COST) plus each lane's cost
 * weighted by the lane's share of the node's area (the chance that a ray
 * through the node's box enters the lane's); a leaf lane costs
 * leaf_lane_cost, an inner one its own wide node.  Called on subtrees of
 * at most BVH_WIDE_MERGE_LEFT triangles only, so the recursion is
 * shallow. */
static double wide_node_cost(const struct bvh *bvh, const float *tri, const uint8_t *zero,
                             uint32_t i, uint32_t width)
{
    struct scratch_node t;
    gather(bvh, tri, zero, i, width, &t);
    const double area = node_area(&bvh->nodes[i]);
    double cost = BVH_WIDE_NODE_COST;
    for (int l = 0; l < t.lanes; l++) {
        const double share = area > 0.0 ? node_area(&bvh->nodes[t.source[l]]) / area : 1.0;
        const double lane = (t.inner >> l & 1u) ? wide_node_cost(bvh, tri, zero, t.source[l], width)
                                                : leaf_lane_cost(t.count[l]);
        cost += share * lane;
    }
    return cost;
}

/*
 * The optimal collapse (Ylitie, Karras and Laine 2017, sec. 3.1): which
 * binary nodes become a wide node's lanes and which subtrees become leaf
 * lanes, chosen bottom-up by dynamic programming on the surface area
 * heuristic (MacDonald and Booth 1990) instead of greedily.  For binary
 * node n and j = 1..width, cost[j - 1] = C(n, j) is the least expected
 * cost of n's subtree as at most j lanes of a wide node:
 *   C(n, 1) = min(leaf(n), A(n) c_node + D(n, width))
 *   C(n, j) = min(C(n, j - 1), D(n, j)),  j > 1
 *   D(n, j) = min over 0 < k < j of C(left, k) + C(right, j - k)
 * where leaf(n) = A(n) c_packet ceil(t / 4) when n's t triangles may be
 * one leaf lane (a binary leaf, or a subtree of at most the merge limit
 * in consecutive slots, as small_span), else infinite; a binary leaf,
 * and a subtree of one packet (BVH_WIDE_MERGE, the layout's definition
 * of a leaf lane, bvh4_layout.h), is not opened: C(n, j) = leaf(n).
 * (Opened, the soup of internal/collapse_threads took 52 % more bytes,
 * its packets holding 1.8 triangles on average.)  The costs are absolute
 * (areas not divided by the parent's), as in the paper.  gather_dp reads
 * the choices back top-down; it recomputes each minimum with the same
 * float operations in the same order (-ffp-contract=off), so it finds
 * the same choice the costs were made of.  Ties take the fewer lanes,
 * the lower k and the leaf.  Only the layout depends on this: every
 * lane's box is still a binary node's box, and the walks' answers do not
 * depend on which nodes are lanes (traverse_wide.h).
 */
/* A wide node's test against a packet's, the DP's cost ratio.  2 rather
 * than the greedy merge's BVH_WIDE_NODE_COST of 1: with 1 the DP gives
 * a ray 1-4 % more node tests than the greedy collapse on the soup, bumpy
 * and the kitchen (for fewer triangle tests) and no faster rays there;
 * with 2 it makes 18-41 % fewer wide nodes, 2-5 % fewer node tests per
 * ray on the soup and bumpy, 7-10 % on the gears (docs/performance-log.md,
 * round 35, cl1).  A heuristic only. */
#define DP_NODE_COST 2.0f
#define DP_PACKET_COST 1.0f

struct dp_node {
    float cost[MAX_WIDTH];
    uint32_t first; /* the leaf lane's first slot (count > 0) */
    uint8_t count;  /* triangles as one leaf lane, 0: it cannot be one */
    uint8_t leaf;   /* C(n, 1) is the leaf's */
    uint8_t lanes;  /* the fewest j with C(n, j) = C(n, width) */
};

struct dp {
    const struct bvh *bvh;
    struct dp_node *node;
    uint32_t width;
    uint32_t max_leaf; /* triangles a merged subtree may hold */
    const uint32_t *roots; /* the subtrees below the top, for the pool */
};

/* D(n, j) of inner node n from its children's costs; *split the k.
 * Only k with k <= l->lanes and j - k <= r->lanes are tried: a child's
 * cost does not fall beyond its lanes, and float addition is monotonic,
 * so a larger k (or j - k) never sums lower than the bound's; the same
 * minimum, in a fraction of the sums near the leaves (where most nodes
 * are: two one-lane children take one sum). */
static float dp_split(const struct dp_node *l, const struct dp_node *r, uint32_t j,
                      uint32_t *split)
{
    const uint32_t lo = j > r->lanes + 1u ? j - r->lanes : 1u;
    const uint32_t hi = l->lanes < j - 1u ? l->lanes : j - 1u;
    float best = l->cost[lo - 1] + r->cost[j - lo - 1];
    uint32_t k_best = lo;
    for (uint32_t k = lo + 1; k <= hi; k++) {
        const float c = l->cost[k - 1] + r->cost[j - k - 1];
        if (c < best) {
            best = c;
            k_best = k;
        }
    }
    *split = k_best;
    return best;
}

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
/* dp_split for every j = 2..8 at once (D(n, j) in lane j - 1), the min-plus
 * step in one register: lane m holds j = m + 1, and for each k the sum
 * C(left, k) + C(right, j - k) of all eight j is one broadcast, one
 * permute (right's costs moved up k lanes), one blend (+inf where j <= k)
 * and one add.  Only k <= left's lanes are tried, all j - k.  The same
 * values as dp_split's, bit for bit: a minimum of the same finite sums is
 * exact in any order, and the sums dp_split leaves out (k beyond left's
 * lanes, j - k beyond right's) are never below one it takes (a child's
 * cost is non-increasing in its lanes and constant beyond them, and float
 * addition is monotonic), so for j beyond the lanes together D(n, j) is
 * D(n, lanes together), as dp_one's scalar path copies it.  Only the
 * minimum's value is used here; the k that reaches it is found again by
 * dp_split when the lanes are read back (dp_emit), so the layout is the
 * portable unit's byte for byte (internal/collapse_threads).  Lane m of
 * the result is D(n, m + 1), lane 0 +inf. */
static __m256 dp_split8(const struct dp_node *l, const struct dp_node *r)
{
    /* shift[k]: lane m takes right's cost m - k (a don't-care index where
     * m < k, blended to +inf by below[k]). */
    static const int32_t shift[8][8] = {
        {0, 1, 2, 3, 4, 5, 6, 7}, {0, 0, 1, 2, 3, 4, 5, 6}, {0, 0, 0, 1, 2, 3, 4, 5},
        {0, 0, 0, 0, 1, 2, 3, 4}, {0, 0, 0, 0, 0, 1, 2, 3}, {0, 0, 0, 0, 0, 0, 1, 2},
        {0, 0, 0, 0, 0, 0, 0, 1}, {0, 0, 0, 0, 0, 0, 0, 0}};
    static const int32_t below[8][8] = {
        {0, 0, 0, 0, 0, 0, 0, 0},         {-1, 0, 0, 0, 0, 0, 0, 0},
        {-1, -1, 0, 0, 0, 0, 0, 0},       {-1, -1, -1, 0, 0, 0, 0, 0},
        {-1, -1, -1, -1, 0, 0, 0, 0},     {-1, -1, -1, -1, -1, 0, 0, 0},
        {-1, -1, -1, -1, -1, -1, 0, 0},   {-1, -1, -1, -1, -1, -1, -1, 0}};
    const __m256 inf = _mm256_set1_ps(INFINITY);
    const __m256 right = _mm256_loadu_ps(r->cost);
    const uint32_t k_max = l->lanes < 7u ? l->lanes : 7u;
    __m256 best = inf;
    for (uint32_t k = 1; k <= k_max; k++) {
        const __m256 moved = _mm256_permutevar8x32_ps(
            right, _mm256_loadu_si256((const __m256i *)(const void *)shift[k]));
        const __m256 masked = _mm256_blendv_ps(
            moved, inf,
            _mm256_castsi256_ps(_mm256_loadu_si256((const __m256i *)(const void *)below[k])));
        best = _mm256_min_ps(best, _mm256_add_ps(_mm256_broadcast_ss(&l->cost[k - 1]), masked));
    }
    return best; /* lane 0 (j = 1) +inf */
}

/* Lane m of x moved to lane m + k, +inf into lanes 0..k-1 (k = 1, 2, 4). */
#define DP_SHIFT_UP(x, k, index) \
    _mm256_blend_ps(_mm256_permutevar8x32_ps((x), (index)), _mm256_set1_ps(INFINITY), (1 << (k)) - 1)

/* The 8-wide entry of inner node e from D(n, j) (dp_split8) and C(n, 1):
 * C(n, j) = min(C(n, 1), D(n, 2..j)), a prefix minimum in three steps
 * (exact, so dp_one's scalar recurrence's values), and its lanes the
 * first j whose cost equals C(n, 8) (costs do not rise with j, so every
 * cost from there on equals it, as dp_one's scalar count finds). */
static void dp_costs8(struct dp_node *e, __m256 split, float c1)
{
    __m256 x = _mm256_blend_ps(split, _mm256_set1_ps(c1), 1);
    x = _mm256_min_ps(x, DP_SHIFT_UP(x, 1, _mm256_setr_epi32(0, 0, 1, 2, 3, 4, 5, 6)));
    x = _mm256_min_ps(x, DP_SHIFT_UP(x, 2, _mm256_setr_epi32(0, 0, 0, 1, 2, 3, 4, 5)));
    x = _mm256_min_ps(x, DP_SHIFT_UP(x, 4, _mm256_setr_epi32(0, 0, 0, 0, 0, 1, 2, 3)));
    _mm256_storeu_ps(e->cost, x);
    const int equal = _mm256_movemask_ps(_mm256_cmp_ps(x, _mm256_set1_ps(e->cost[7]), _CMP_EQ_OQ));
    e->lanes = (uint8_t)(__builtin_ctz((unsigned)equal) + 1);
}
#endif

/* Node i's entry from its children's (already computed). */
static void dp_one(const struct dp *d, uint32_t i)
{
    const struct bvh_node *n = &d->bvh->nodes[i];
    struct dp_node *e = &d->node[i];
    const float area = node_area(n);
    if (n->count) {
        e->first = n->first;
        e->count = (uint8_t)n->count;
        e->leaf = 1;
        e->lanes = 1;
        const float leaf = area * (DP_PACKET_COST * (float)((n->count + 3) / 4));
        for (uint32_t j = 0; j < MAX_WIDTH; j++) /* all 8: two stores */
            e->cost[j] = leaf;
        return;
    }
    const struct dp_node *l = &d->node[n->first];
    const struct dp_node *r = &d->node[n->first + 1];
    e->count = 0;
    e->first = 0;
    if (l->count && r->count && l->count + r->count <= d->max_leaf) {
        if (l->first + l->count == r->first) {
            e->first = l->first;
            e->count = (uint8_t)(l->count + r->count);
        } else if (r->first + r->count == l->first) {
            e->first = r->first;
            e->count = (uint8_t)(l->count + r->count);
        }
    }
    if (e->count && e->count <= BVH_WIDE_MERGE) {
        /* One packet: a leaf lane, as a binary leaf (the layout's
         * definition, bvh4_layout.h). */
        e->leaf = 1;
        e->lanes = 1;
        const float leaf = area * DP_PACKET_COST;
        for (uint32_t j = 0; j < MAX_WIDTH; j++) /* all 8: two stores */
            e->cost[j] = leaf;
        return;
    }
    const float leaf_cost =
        e->count ? area * (DP_PACKET_COST * (float)((e->count + 3u) / 4u)) : INFINITY;
#if defined(__AVX2__) && !defined(RT_NO_SIMD)
    if (d->width == 8) {
        const __m256 split8 = dp_split8(l, r);
        const float inner8 =
            area * DP_NODE_COST +
            _mm256_cvtss_f32(_mm256_permutevar8x32_ps(split8, _mm256_set1_epi32(7)));
        e->leaf = e->count && leaf_cost <= inner8;
        dp_costs8(e, split8, e->leaf ? leaf_cost : inner8);
        return;
    }
#endif
    float split[MAX_WIDTH + 1] = {0}; /* [2, width] written (width 4 or 8) */
    uint32_t k;
    /* Beyond the children's lanes together D(n, j) stays (dp_split). */
    const uint32_t most = l->lanes + r->lanes < d->width ? l->lanes + r->lanes : d->width;
    for (uint32_t j = 2; j <= most; j++)
        split[j] = dp_split(l, r, j, &k);
    for (uint32_t j = most + 1; j <= d->width; j++)
        split[j] = split[most];
    const float inner = area * DP_NODE_COST + split[d->width];
    e->leaf = e->count && leaf_cost <= inner;
    e->cost[0] = e->leaf ? leaf_cost : inner;
    for (uint32_t j = 2; j <= d->width; j++)
        e->cost[j - 1] = split[j] < e->cost[j - 2] ? split[j] : e->cost[j - 2];
    uint32_t lanes = d->width;
    while (lanes > 1 && e->cost[lanes - 2] == e->cost[d->width - 1])
        lanes--;
    e->lanes = (uint8_t)lanes;
}

/* The entries of binary subtree i, children first (depth at most
 * BVH_MAX_DEPTH, so the recursion is bounded). */
static void dp_subtree(const struct dp *d, uint32_t i)
{
    const struct bvh_node *n = &d->bvh->nodes[i];
    if (!n->count) {
        dp_subtree(d, n->first);
        dp_subtree(d, n->first + 1);
    }
    dp_one(d, i);
}

static void dp_subtrees(void *arg, uint32_t lo, uint32_t hi)
{
    const struct dp *d = arg;
    for (uint32_t f = lo; f < hi; f++)
        dp_subtree(d, d->roots[f]);
}

/* Subtrees below the top handed to the pool: enough for its threads to
 * balance them. */
#define DP_SUBTREES 64u

/* Every binary node's entry (d->node has node_count entries): the top
 * opened breadth first until DP_SUBTREES subtrees remain below it, those
 * on the pool, then the top's nodes children first (each entry depends
 * on nothing but its subtree, so the same on any pool). */
static void dp_run(struct dp *d, struct rt_pool *pool)
{
    const struct bvh *bvh = d->bvh;
    /* queue[0, top) the opened nodes, queue[top, end) the frontier. */
    uint32_t queue[4 * DP_SUBTREES];
    uint32_t top = 0, end = 1;
    queue[0] = 0;
    while (end - top < DP_SUBTREES && end + 2 <= 4 * DP_SUBTREES) {
        /* Open the frontier's first inner node (leaves stay). */
        uint32_t f = top;
        while (f < end && bvh->nodes[queue[f]].count)
            f++;
        if (f == end)
            break;
        const uint32_t i = queue[f];
        queue[f] = queue[top];
        queue[top++] = i;
        queue[end++] = bvh->nodes[i].first;
        queue[end++] = bvh->nodes[i].first + 1;
    }
    d->roots = &queue[top];
    rt_pool_run_range(pool, 0, end - top, 1, 2, dp_subtrees, d);
    for (uint32_t f = top; f-- > 0;)
        dp_one(d, queue[f]);
}

/* The lanes of subtree i in at most j lanes, appended to s (gather_dp). */
static void dp_emit(const struct dp *d, uint32_t i, uint32_t j, struct scratch_node *s)
{
    const struct dp_node *e = &d->node[i];
    /* The fewest lanes of the same cost (C(n, j) was only lowered by a
     * split strictly cheaper than fewer lanes). */
    uint32_t jj = 1;
    while (jj < j && !(e->cost[jj - 1] == e->cost[j - 1]))
        jj++;
    const struct bvh_node *n = &d->bvh->nodes[i];
    if (jj == 1 || n->count) {
        const int l = s->lanes++;
        s->source[l] = i;
        if (e->leaf) {
            s->first[l] = e->first;
            s->count[l] = e->count;
            s->inner &= ~(1u << l);
        } else {
            s->count[l] = 0;
            s->first[l] = 0;
            s->inner |= 1u << l;
        }
        return;
    }
    uint32_t k;
    (void)dp_split(&d->node[n->first], &d->node[n->first + 1], jj, &k);
    dp_emit(d, n->first, k, s);
    dp_emit(d, n->first + 1, jj - k, s);
}

/* The lanes of the wide node over binary inner node `inner` by the
 * costs: its children split as D(inner, width) chose. */
static void gather_dp(const struct dp *d, uint32_t inner, struct scratch_node *s)
{
    const struct bvh_node *n = &d->bvh->nodes[inner];
    uint32_t k;
    (void)dp_split(&d->node[n->first], &d->node[n->first + 1], d->width, &k);
    s->lanes = 0;
    s->inner = 0;
    dp_emit(d, n->first, k, s);
    dp_emit(d, n->first + 1, d->width - k, s);
}

/* A lane that gather left closed (the wide node is full) and that is no
 * leaf lane would become a wide node of its own.  When its subtree holds
 * at most BVH_WIDE_MERGE_LEFT triangles in consecutive slots (two
 * packets) it becomes one leaf instead if that costs no more by the area
 * heuristic (leaf_lane_cost against wide_node_cost).  Such a node holds only leaf lanes, often two (soup: 3235
 * of 8190 8-wide nodes had two), a 256-byte node and a visit spent on
 * what a second packet holds; without them the 8-wide layout is 10-11 %
 * smaller (soup, kitchen, bumpy: the memory table of rtbench embree) and
 * a ray visits fewer nodes and tests more triangles.  The lane's box is
 * the subtree root's, a binary node's box bit for bit, so the answers
 * are the same.  Depends on nothing but the node, as gather. */
static void close_small_lanes(const struct bvh *bvh, const float *tri, const uint8_t *zero,
                              uint32_t width, struct scratch_node *s)
{
    for (int l = 0; l < s->lanes; l++) {
        if (!(s->inner >> l & 1u))
            continue;
        uint32_t first;
        const uint32_t n = small_span(bvh, s->source[l], BVH_WIDE_MERGE_LEFT, &first);
        if (n && leaf_lane_cost(n) <= wide_node_cost(bvh, tri, zero, s->source[l], width)) {
            s->inner &= ~(1u << l);
            s->first[l] = first;
            s->count[l] = n;
        }
    }
}

/* Per octant, the used lanes sorted front to back by the projection of
 * their box centres on the octant's diagonal (ties: lower lane first),
 * unused lanes last.  A heuristic only: the walk's answers do not
 * depend on the order of visits (traverse_wide.h).
 *
 * By rank counting, without a data-dependent branch (the insertion sort
 * this replaces spent most of its time in mispredictions), and for two
 * octants at once: octant 7 - oct negates every term of oct's projection,
 * so its key is exactly -key (IEEE negation commutes with rounding), and
 * for j < l lane j goes first in oct when key[j] <= key[l] and in 7 - oct
 * when key[j] >= key[l].  The keys are compared as ordered integers, a
 * total order (after -0 is made +0, which compares equal to it), so the
 * ranks are a permutation for any input, NaN included. */
static uint64_t order_key(double k)
{
    k += 0.0; /* -0 -> +0 */
    uint64_t u;
    memcpy(&u, &k, sizeof(u));
    return u ^ ((u >> 63) ? ~(uint64_t)0 : (uint64_t)1 << 63);
}

/* The eight octants' orders packed at bits_per_lane bits per position:
 * the four octants 0..3 and their opposites in one pass over the lane
 * pairs, each lane's keys computed once (the same keys and comparisons
 * as one octant at a time).  A lane of rank r goes to position r, so its
 * index is shifted by bits_per_lane * r; unused lanes keep their place. */
static void octant_orders(const double centre[MAX_WIDTH][3], int lanes, int width,
                          int bits_per_lane, uint32_t order_bits[8])
{
    uint64_t key[MAX_WIDTH][4];
    int rank[MAX_WIDTH][8];
    memset(rank, 0, sizeof(rank));
    for (int l = 0; l < lanes; l++) {
        for (int oct = 0; oct < 4; oct++) {
            double k = 0.0;
            for (int a = 0; a < 3; a++)
                k += (oct >> a & 1) ? -centre[l][a] : centre[l][a];
            key[l][oct] = order_key(k);
        }
    }
    for (int l = 1; l < lanes; l++) {
        for (int j = 0; j < l; j++) {
            for (int oct = 0; oct < 4; oct++) {
                int j_first = key[j][oct] <= key[l][oct];
                int j_first_opposite = key[j][oct] >= key[l][oct];
                rank[l][oct] += j_first;
                rank[j][oct] += 1 - j_first;
                rank[l][7 - oct] += j_first_opposite;
                rank[j][7 - oct] += 1 - j_first_opposite;
            }
        }
    }
    for (int oct = 0; oct < 8; oct++) {
        uint32_t bits = 0;
        for (int l = 0; l < lanes; l++)
            bits |= (uint32_t)l << (bits_per_lane * rank[l][oct]);
        for (int l = lanes; l < width; l++)
            bits |= (uint32_t)l << (bits_per_lane * l);
        order_bits[oct] = bits;
    }
}

#if defined(__SSE2__) && !defined(__AVX2__) && !defined(RT_NO_SIMD)
/*
 * octant_orders for the usual case, two octants per SSE2 register: the
 * same keys (the same sums, in the same order, of the same centres with
 * the same signs) and the same comparisons.  Without a NaN among the
 * keys, key[j] <= key[l] exactly when the doubles compare so (order_key
 * is monotonic in the value and maps -0 and +0 to one key, which a double
 * comparison also takes as equal); with a NaN this returns 0 and the
 * caller takes the portable form, whose order keys order NaNs too.  The
 * rank counts are 64-bit lanes, a comparison's mask (-1 when true)
 * subtracted for the later lane and added for the earlier, whose "1 -"
 * is added once at the end (lane j is the earlier of lanes - 1 - j
 * pairs).  882 instructions a wide node against the portable form's
 * 1,924 (that form was 7.5 % of a build of 880 triangles).
 */
static int octant_orders_sse2(const double centre[MAX_WIDTH][3], int lanes, int width,
                              int bits_per_lane, uint32_t order_bits[8])
{
    /* k[l][0]: octants 0 and 1, k[l][1]: octants 2 and 3 (lane 0 the
     * even one); octant bit a negates axis a. */
    __m128d k[MAX_WIDTH][2];
    const __m128d flip_x = _mm_set_pd(-0.0, 0.0);
    const __m128d sign = _mm_set1_pd(-0.0);
    const __m128d zero = _mm_setzero_pd();
    int nan = 0;
    for (int l = 0; l < lanes; l++) {
        const __m128d x = _mm_xor_pd(_mm_set1_pd(centre[l][0]), flip_x);
        const __m128d y = _mm_set1_pd(centre[l][1]);
        const __m128d z = _mm_set1_pd(centre[l][2]);
        const __m128d x0 = _mm_add_pd(zero, x);
        k[l][0] = _mm_add_pd(_mm_add_pd(x0, y), z);
        k[l][1] = _mm_add_pd(_mm_add_pd(x0, _mm_xor_pd(y, sign)), z);
        nan |= _mm_movemask_pd(_mm_cmpunord_pd(k[l][0], k[l][1]));
    }
    if (nan)
        return 0;
    __m128i up[MAX_WIDTH][2];   /* octants 0-3 */
    __m128i down[MAX_WIDTH][2]; /* their opposites 7-4 */
    for (int l = 0; l < lanes; l++) {
        up[l][0] = up[l][1] = down[l][0] = down[l][1] = _mm_setzero_si128();
    }
    for (int l = 1; l < lanes; l++) {
        for (int j = 0; j < l; j++) {
            for (int v = 0; v < 2; v++) {
                const __m128i le = _mm_castpd_si128(_mm_cmple_pd(k[j][v], k[l][v]));
                const __m128i ge = _mm_castpd_si128(_mm_cmpge_pd(k[j][v], k[l][v]));
                up[l][v] = _mm_sub_epi64(up[l][v], le);
                up[j][v] = _mm_add_epi64(up[j][v], le);
                down[l][v] = _mm_sub_epi64(down[l][v], ge);
                down[j][v] = _mm_add_epi64(down[j][v], ge);
            }
        }
    }
    /* Unused lanes keep their place in every octant. */
    uint32_t pad = 0;
    for (int l = lanes; l < width; l++)
        pad |= (uint32_t)l << (bits_per_lane * l);
    for (int oct = 0; oct < 8; oct++)
        order_bits[oct] = pad;
    for (int l = 0; l < lanes; l++) {
        int64_t u[4], d[4];
        _mm_storeu_si128((__m128i *)(void *)&u[0], up[l][0]);
        _mm_storeu_si128((__m128i *)(void *)&u[2], up[l][1]);
        _mm_storeu_si128((__m128i *)(void *)&d[0], down[l][0]);
        _mm_storeu_si128((__m128i *)(void *)&d[2], down[l][1]);
        const int earlier = lanes - 1 - l;
        for (int oct = 0; oct < 4; oct++) {
            order_bits[oct] |= (uint32_t)l << (bits_per_lane * ((int)u[oct] + earlier));
            order_bits[7 - oct] |= (uint32_t)l << (bits_per_lane * ((int)d[oct] + earlier));
        }
    }
    return 1;
}
#endif

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
/*
 * octant_orders_sse2 with the four octants 0..3 in one AVX register
 * (collapse4_avx2.c): the same keys (the same sums in the same order of
 * the same centres with the same signs), the same comparisons and counts,
 * half the operations per lane pair.
 */
static int octant_orders_avx2(const double centre[MAX_WIDTH][3], int lanes, int width,
                              int bits_per_lane, uint32_t order_bits[8])
{
    /* Octant bit a negates axis a; lane o of k[l] is octant o. */
    __m256d k[MAX_WIDTH];
    const __m256d flip_x = _mm256_set_pd(-0.0, 0.0, -0.0, 0.0);
    const __m256d flip_y = _mm256_set_pd(-0.0, -0.0, 0.0, 0.0);
    const __m256d zero = _mm256_setzero_pd();
    int nan = 0;
    for (int l = 0; l < lanes; l++) {
        const __m256d x = _mm256_xor_pd(_mm256_set1_pd(centre[l][0]), flip_x);
        const __m256d y = _mm256_xor_pd(_mm256_set1_pd(centre[l][1]), flip_y);
        const __m256d z = _mm256_set1_pd(centre[l][2]);
        k[l] = _mm256_add_pd(_mm256_add_pd(_mm256_add_pd(zero, x), y), z);
        nan |= _mm256_movemask_pd(_mm256_cmp_pd(k[l], k[l], _CMP_UNORD_Q));
    }
    if (nan)
        return 0;
    __m256i up[MAX_WIDTH];   /* octants 0-3 */
    __m256i down[MAX_WIDTH]; /* their opposites 7-4 */
    for (int l = 0; l < lanes; l++)
        up[l] = down[l] = _mm256_setzero_si256();
    for (int l = 1; l < lanes; l++) {
        for (int j = 0; j < l; j++) {
            const __m256i le = _mm256_castpd_si256(_mm256_cmp_pd(k[j], k[l], _CMP_LE_OQ));
            const __m256i ge = _mm256_castpd_si256(_mm256_cmp_pd(k[j], k[l], _CMP_GE_OQ));
            up[l] = _mm256_sub_epi64(up[l], le);
            up[j] = _mm256_add_epi64(up[j], le);
            down[l] = _mm256_sub_epi64(down[l], ge);
            down[j] = _mm256_add_epi64(down[j], ge);
        }
    }
    uint32_t pad = 0;
    for (int l = lanes; l < width; l++)
        pad |= (uint32_t)l << (bits_per_lane * l);
    for (int oct = 0; oct < 8; oct++)
        order_bits[oct] = pad;
    for (int l = 0; l < lanes; l++) {
        int64_t u[4], d[4];
        _mm256_storeu_si256((__m256i *)(void *)u, up[l]);
        _mm256_storeu_si256((__m256i *)(void *)d, down[l]);
        const int earlier = lanes - 1 - l;
        for (int oct = 0; oct < 4; oct++) {
            order_bits[oct] |= (uint32_t)l << (bits_per_lane * ((int)u[oct] + earlier));
            order_bits[7 - oct] |= (uint32_t)l << (bits_per_lane * ((int)d[oct] + earlier));
        }
    }
    return 1;
}
#endif

/* Twice the lanes' box centres (the order only compares them). */
static void lane_centres(const struct bvh *bvh, const struct scratch_node *s,
                         double centre[MAX_WIDTH][3])
{
    for (int l = 0; l < s->lanes; l++) {
        const struct bvh_node *b = &bvh->nodes[s->source[l]];
        for (int a = 0; a < 3; a++)
            centre[l][a] = (double)b->aabb_min[a] + (double)b->aabb_max[a];
    }
}

/* The lanes of a width-wide node (4 or 8): bounds as rows of `width`
 * floats (empty lanes inverted), children and counts, and per ray octant
 * the lanes front to back packed at bits_per_lane bits each (2 for 4-wide,
 * 3 for 8-wide). */
static void write_lanes(const struct bvh *bvh, const struct scratch_node *s, int width,
                        const uint32_t child_base[2], float *bounds, uint32_t *child,
                        uint8_t *count, uint32_t order_bits[8])
{
    for (int l = 0; l < width; l++) {
        for (int k = 0; k < 3; k++) {
            bounds[k * width + l] = l < s->lanes ? bvh->nodes[s->source[l]].aabb_min[k] : INFINITY;
            bounds[(3 + k) * width + l] =
                l < s->lanes ? bvh->nodes[s->source[l]].aabb_max[k] : -INFINITY;
        }
        child[l] = l < s->lanes ? s->child[l] + child_base[s->inner >> l & 1u] : 0;
        count[l] = (uint8_t)(l < s->lanes ? s->live[l] : 0);
    }
    const int bits_per_lane = width == 4 ? 2 : 3;
    double centre[MAX_WIDTH][3];
    lane_centres(bvh, s, centre);
#if defined(__AVX2__) && !defined(RT_NO_SIMD)
    if (octant_orders_avx2(centre, s->lanes, width, bits_per_lane, order_bits))
        return;
#elif defined(__SSE2__) && !defined(RT_NO_SIMD)
    if (octant_orders_sse2(centre, s->lanes, width, bits_per_lane, order_bits))
        return;
#endif
    octant_orders(centre, s->lanes, width, bits_per_lane, order_bits);
}

static void write_node4(struct bvh4_node *w, const struct bvh *bvh, const struct scratch_node *s,
                        const uint32_t child_base[2])
{
    uint32_t bits[8];
    memset(w, 0, sizeof(*w));
    write_lanes(bvh, s, 4, child_base, &w->bounds[0][0], w->child, w->count, bits);
    for (int oct = 0; oct < 8; oct++)
        w->order[oct] = (uint8_t)bits[oct];
}

static void write_node8(struct bvh8_node *w, const struct bvh *bvh, const struct scratch_node *s,
                        const uint32_t child_base[2])
{
    uint32_t bits[8];
    memset(w, 0, sizeof(*w));
    write_lanes(bvh, s, 8, child_base, &w->bounds[0][0], w->child, w->count, bits);
    for (int oct = 0; oct < 8; oct++) {
        w->order[oct][0] = (uint8_t)bits[oct];
        w->order[oct][1] = (uint8_t)(bits[oct] >> 8);
        w->order[oct][2] = (uint8_t)(bits[oct] >> 16);
    }
}

void accel_set_packet_lane(struct tri4_packet *p, uint32_t lane, const float v[9])
{
    /* A zero-area triangle (isect_triangle_zero_area: the finish's own
     * doubles) is never hit by any ray, so its lane holds NaN, which the
     * packet filter always rejects. */
    const int zero = isect_triangle_zero_area(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7],
                                              v[8]);
    for (int j = 0; j < 3; j++) {
        for (int k = 0; k < 3; k++)
            p->v[j][k][lane] = zero ? NAN : v[3 * j + k];
    }
}

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
/* zero_area_pair below for four lanes in one AVX register
 * (collapse4_avx2.c): the same operations on each lane. */
static int zero_area_quad(__m128 x0, __m128 y0, __m128 z0, __m128 x1, __m128 y1, __m128 z1,
                          __m128 x2, __m128 y2, __m128 z2)
{
    const __m256d e1x = _mm256_sub_pd(_mm256_cvtps_pd(x1), _mm256_cvtps_pd(x0));
    const __m256d e1y = _mm256_sub_pd(_mm256_cvtps_pd(y1), _mm256_cvtps_pd(y0));
    const __m256d e1z = _mm256_sub_pd(_mm256_cvtps_pd(z1), _mm256_cvtps_pd(z0));
    const __m256d e2x = _mm256_sub_pd(_mm256_cvtps_pd(x2), _mm256_cvtps_pd(x0));
    const __m256d e2y = _mm256_sub_pd(_mm256_cvtps_pd(y2), _mm256_cvtps_pd(y0));
    const __m256d e2z = _mm256_sub_pd(_mm256_cvtps_pd(z2), _mm256_cvtps_pd(z0));
    const __m256d nx = _mm256_sub_pd(_mm256_mul_pd(e1y, e2z), _mm256_mul_pd(e1z, e2y));
    const __m256d ny = _mm256_sub_pd(_mm256_mul_pd(e1z, e2x), _mm256_mul_pd(e1x, e2z));
    const __m256d nz = _mm256_sub_pd(_mm256_mul_pd(e1x, e2y), _mm256_mul_pd(e1y, e2x));
    const __m256d zero = _mm256_setzero_pd();
    return _mm256_movemask_pd(_mm256_and_pd(
        _mm256_and_pd(_mm256_cmp_pd(nx, zero, _CMP_EQ_OQ), _mm256_cmp_pd(ny, zero, _CMP_EQ_OQ)),
        _mm256_cmp_pd(nz, zero, _CMP_EQ_OQ)));
}
#elif defined(__SSE2__) && !defined(RT_NO_SIMD)
/* The zero-area test of isect_triangle_zero_area for two lanes: the same
 * conversions, differences, products and comparisons in doubles, in the
 * same order, so the same answers; bit l of the result is lane l's. */
static int zero_area_pair(__m128 x0, __m128 y0, __m128 z0, __m128 x1, __m128 y1, __m128 z1,
                          __m128 x2, __m128 y2, __m128 z2)
{
    const __m128d e1x = _mm_sub_pd(_mm_cvtps_pd(x1), _mm_cvtps_pd(x0));
    const __m128d e1y = _mm_sub_pd(_mm_cvtps_pd(y1), _mm_cvtps_pd(y0));
    const __m128d e1z = _mm_sub_pd(_mm_cvtps_pd(z1), _mm_cvtps_pd(z0));
    const __m128d e2x = _mm_sub_pd(_mm_cvtps_pd(x2), _mm_cvtps_pd(x0));
    const __m128d e2y = _mm_sub_pd(_mm_cvtps_pd(y2), _mm_cvtps_pd(y0));
    const __m128d e2z = _mm_sub_pd(_mm_cvtps_pd(z2), _mm_cvtps_pd(z0));
    const __m128d nx = _mm_sub_pd(_mm_mul_pd(e1y, e2z), _mm_mul_pd(e1z, e2y));
    const __m128d ny = _mm_sub_pd(_mm_mul_pd(e1z, e2x), _mm_mul_pd(e1x, e2z));
    const __m128d nz = _mm_sub_pd(_mm_mul_pd(e1x, e2y), _mm_mul_pd(e1y, e2x));
    const __m128d zero = _mm_setzero_pd();
    return _mm_movemask_pd(_mm_and_pd(_mm_and_pd(_mm_cmpeq_pd(nx, zero), _mm_cmpeq_pd(ny, zero)),
                                      _mm_cmpeq_pd(nz, zero)));
}

/* The upper two lanes of v in the lower two. */
static __m128 upper_pair(__m128 v)
{
    return _mm_movehl_ps(v, v);
}
#endif

#if defined(__SSE2__) && !defined(RT_NO_SIMD)
/* The nine components x0 y0 z0 x1 y1 z1 x2 y2 z2 (floats 0-8) of the
 * triangles of row[0 .. 4), one register each, lane l row[l]'s: each
 * triangle's nine floats are three overlapping rows of four (floats 0-3,
 * 4-7, 5-8), transposed.  (Up to 64 instructions a triangle in the
 * scalar form, a fifth of the collapse's.) */
static inline void rows_transpose(const float *const row[4], __m128 v[9])
{
    __m128 a0 = _mm_loadu_ps(row[0]), a1 = _mm_loadu_ps(row[1]);
    __m128 a2 = _mm_loadu_ps(row[2]), a3 = _mm_loadu_ps(row[3]);
    _MM_TRANSPOSE4_PS(a0, a1, a2, a3);
    __m128 b0 = _mm_loadu_ps(row[0] + 4), b1 = _mm_loadu_ps(row[1] + 4);
    __m128 b2 = _mm_loadu_ps(row[2] + 4), b3 = _mm_loadu_ps(row[3] + 4);
    _MM_TRANSPOSE4_PS(b0, b1, b2, b3);
    __m128 c0 = _mm_loadu_ps(row[0] + 5), c1 = _mm_loadu_ps(row[1] + 5);
    __m128 c2 = _mm_loadu_ps(row[2] + 5), c3 = _mm_loadu_ps(row[3] + 5);
    _MM_TRANSPOSE4_PS(c0, c1, c2, c3);
    (void)c0, (void)c1, (void)c2;
    v[0] = a0, v[1] = a1, v[2] = a2, v[3] = a3;
    v[4] = b0, v[5] = b1, v[6] = b2, v[7] = b3, v[8] = c3;
}

/* Bit l: lane l of the components v (rows_transpose) is a zero-area
 * triangle, by isect_triangle_zero_area's doubles. */
static inline int components_zero_mask(const __m128 v[9])
{
#if defined(__AVX2__)
    return zero_area_quad(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
#else
    return zero_area_pair(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]) |
           zero_area_pair(upper_pair(v[0]), upper_pair(v[1]), upper_pair(v[2]),
                          upper_pair(v[3]), upper_pair(v[4]), upper_pair(v[5]),
                          upper_pair(v[6]), upper_pair(v[7]), upper_pair(v[8]))
               << 2;
#endif
}
#endif

/* Bit l: row[l]'s triangle (nine floats) has zero area
 * (isect_triangle_zero_area), for l < 4. */
static inline int rows_zero_mask(const float *const row[4])
{
#if defined(__SSE2__) && !defined(RT_NO_SIMD)
    __m128 v[9];
    rows_transpose(row, v);
    return components_zero_mask(v);
#else
    int mask = 0;
    for (int l = 0; l < 4; l++) {
        const float *v = row[l];
        mask |= isect_triangle_zero_area(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8])
                << l;
    }
    return mask;
#endif
}

/* Packet p's lanes from the nine floats of row[0 .. 4) (leaf slots
 * [slot, slot + n), n <= 4: lanes past n repeat the last triangle, row[l]
 * = row[n - 1] there); with prim_index, the lanes' primitives from it
 * too.  test 0: the caller knows that every row has an area
 * (drop_zero_area tested them), so the zero-area test is left out (its
 * answer would be 0 for every lane: the same bytes).  Returns the lanes
 * below n found of zero area (bit l; 0 without the test). */
static inline int fill_packet_rows(struct tri4_packet *p, const float *const row[4],
                                   const uint32_t *prim_index, uint32_t slot, uint32_t n,
                                   int test)
{
#if defined(__SSE2__) && !defined(RT_NO_SIMD)
    /* The four lanes at once, the same values as accel_set_packet_lane
     * and the repeats below: a repeated lane is lane n - 1's triangle
     * loaded again, whose zero-area test gives the same answer. */
    __m128 v[9];
    rows_transpose(row, v);
    const int zero = test ? components_zero_mask(v) : 0;
    if (zero) {
        const __m128 mask = _mm_castsi128_ps(_mm_set_epi32(-(zero >> 3 & 1), -(zero >> 2 & 1),
                                                           -(zero >> 1 & 1), -(zero & 1)));
        const __m128 nan = _mm_set1_ps(NAN);
        for (int c = 0; c < 9; c++)
            v[c] = _mm_or_ps(_mm_and_ps(mask, nan), _mm_andnot_ps(mask, v[c]));
    }
    for (int c = 0; c < 9; c++)
        _mm_storeu_ps(p->v[c / 3][c % 3], v[c]);
    if (prim_index) {
        for (uint32_t l = 0; l < 4; l++)
            p->prim[l] = prim_index[slot + (l < n ? l : n - 1)];
    }
    return zero & ((1 << n) - 1);
#else
    int zero = 0;
    for (uint32_t l = 0; l < n; l++) {
        if (test) {
            const float *v = row[l];
            zero |= isect_triangle_zero_area(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7],
                                             v[8])
                    << l;
            accel_set_packet_lane(p, l, row[l]);
        } else {
            for (int j = 0; j < 3; j++) {
                for (int k = 0; k < 3; k++)
                    p->v[j][k][l] = row[l][3 * j + k];
            }
        }
        if (prim_index)
            p->prim[l] = prim_index[slot + l];
    }
    /* The repeats are copies of lane n - 1 (its zero-area test is not
     * redone). */
    for (uint32_t l = n; l < 4; l++) {
        for (int j = 0; j < 3; j++) {
            for (int k = 0; k < 3; k++)
                p->v[j][k][l] = p->v[j][k][n - 1];
        }
        if (prim_index)
            p->prim[l] = p->prim[n - 1];
    }
    return zero;
#endif
}

/* Packet p's lanes from leaf slots [slot, slot + n), n <= 4, of tri
 * (accel_gather_triangles' leaf order); lanes past n repeat the last
 * triangle. */
static int fill_packet(struct tri4_packet *p, const float *tri, const uint32_t *prim_index,
                       uint32_t slot, uint32_t n, int test)
{
    const float *row[4];
    for (uint32_t l = 0; l < 4; l++)
        row[l] = &tri[9 * (size_t)(slot + (l < n ? l : n - 1))];
    return fill_packet_rows(p, row, prim_index, slot, n, test);
}

/* fill_packet with the triangles read from the mesh (src's positions and
 * indices): slot s's nine floats copied as the gather copies them
 * (accel_gather_triangle), so the same lanes (fill_packet_rows reads
 * floats 0-8 of each row). */
static int fill_packet_mesh(struct tri4_packet *p, const struct collapse_triangles *src,
                            const uint32_t *prim_index, uint32_t slot, uint32_t n, int test)
{
    float buf[4][9];
    const float *row[4];
    for (uint32_t l = 0; l < 4; l++) {
        if (l >= n) {
            row[l] = row[n - 1];
            continue;
        }
        accel_gather_triangle(buf[l], src->positions, src->indices, prim_index[slot + l]);
        row[l] = buf[l];
    }
    return fill_packet_rows(p, row, prim_index, slot, n, test);
}

/*
 * A wide subtree below the cut (struct collapse): its wide nodes in its
 * own breadth-first order, gathered and numbered on one thread.  A node's
 * child is, for an inner lane, its index in the next of the item's levels
 * and, for a leaf lane with triangles, its first packet counted from the
 * first packet of the node's level in the item; the global numbers are
 * the levels' bases added (node_base, packet_base), which the calling
 * thread sets once every item is gathered.
 */
struct item_level {
    uint32_t begin;       /* the level's first node in nodes[] */
    uint32_t packets;     /* packets of the level's nodes */
    uint32_t node_base;   /* global number of the level's first node */
    uint32_t packet_base; /* global number of the level's first packet */
};

struct collapse_item {
    uint32_t root; /* binary inner node of the item's root */
    /* Node w of the item is in the item pool at slot
     * chunk[w / COLLAPSE_ITEM_CHUNK] + w % COLLAPSE_ITEM_CHUNK. */
    uint32_t *chunk;
    uint32_t chunks, chunk_cap;
    uint32_t count;
    struct item_level *level;
    uint32_t levels, level_cap;
    int failed;
};

/* The collapse's shared state.  The wide nodes are numbered breadth
 * first (a node's inner lanes get the next numbers, in lane order) and
 * the packets in node order, then lane order: the serial queue's order.
 * The top levels are numbered level by level on the calling thread, down
 * to the first level of at least COLLAPSE_ITEM_LEVEL nodes (the cut);
 * each node of that level is the root of an item (struct
 * collapse_item), which one thread gathers and numbers in its own
 * breadth-first order, depth after depth, while its binary nodes are in
 * that thread's caches.  Below the cut the global breadth-first order is,
 * level by level, the items' same levels one after the other in item
 * order (by induction: the roots are the cut level in that order, and
 * the children of a run of nodes are a run of the next level, in the
 * same order), so a node's global number is its level's base plus its
 * index in the level, and likewise for packets (the top's packets first,
 * then level by level).  The work per node (the greedy gather, the node
 * and its packets) depends on nothing but the node, so the bytes written
 * are the same on any number of threads and with or without the cut. */
struct collapse {
    const struct bvh *bvh;
    /* Non-NULL when the leaves hold triangles (packets are written), NULL
     * for the top level over instances; the packets read src.tri (the
     * gathered copy) or, without it, src's mesh. */
    const float *tri;
    struct collapse_triangles src;
    uint32_t width;
    int merge_left; /* close_small_lanes applies */
    /* drop_zero_area applies (triangles, and not src.keep_zero_area). */
    int drop;
    /* With drop, per leaf slot 1 when its triangle has zero area; NULL
     * when no slot's has (zero_slots). */
    const uint8_t *zero;
    const struct dp *dp; /* the optimal collapse's costs (triangles), else greedy */
    struct scratch_node *scratch;
    uint32_t *todo;
    char *base;
    struct tri4_packet *packets;
    uint32_t *source;
    uint32_t *packet_slot;
    struct collapse_item *items;
    /* The item pool: the items' nodes and their binary inner nodes, in
     * chunks taken from *item_next, of item_cap slots in all. */
    struct scratch_node *item_nodes;
    uint32_t *item_todo;
    uint32_t item_cap;
    uint32_t *item_next;
    /* The zero-area triangles the packets' fill found (and marked NaN). */
    uint32_t *zero_found;
};

/* The rows of leaf slots slots[0 .. m), m <= 4, as the packets read
 * them (fill_packet, fill_packet_mesh): in the leaf-ordered triangles,
 * or gathered from the mesh into buf (accel_gather_triangle); rows past
 * m repeat the last one, as fill_packet_rows expects. */
static void slot_rows(const struct collapse *c, const uint32_t *slots, uint32_t m,
                      float buf[4][9], const float *row[4])
{
    for (uint32_t k = 0; k < 4; k++) {
        if (k >= m) {
            row[k] = row[m - 1];
        } else if (c->src.tri) {
            row[k] = &c->src.tri[9 * (size_t)slots[k]];
        } else {
            accel_gather_triangle(buf[k], c->src.positions, c->src.indices,
                                  c->bvh->prim_index[slots[k]]);
            row[k] = buf[k];
        }
    }
}

/* Bit j: leaf slot first + j's triangle has zero area
 * (isect_triangle_zero_area), for the n <= BVH_WIDE_MAX_LEAF slots from
 * first; read as the packets read them (slot_rows), four at a time as
 * the fill tests them. */
static uint32_t slots_zero_mask(const struct collapse *c, uint32_t first, uint32_t n)
{
    uint32_t mask = 0;
    for (uint32_t j = 0; j < n; j += 4) {
        float buf[4][9];
        const float *row[4];
        const uint32_t m = n - j < 4 ? n - j : 4;
        const uint32_t slots[4] = {first + j, first + j + 1, first + j + 2, first + j + 3};
        slot_rows(c, slots, m, buf, row);
        mask |= ((uint32_t)rows_zero_mask(row) & ((1u << m) - 1u)) << j;
    }
    return mask;
}

/*
 * The zero-area triangles left out of wide node s's leaf lanes, and a
 * leaf lane left with none removed from the node.  No ray hits such a
 * triangle: isect_triangle refuses it in its finish (the zero-area test
 * of isect_triangle_finish), the packets hold it as NaN, which every
 * packet test refuses (accel_set_packet_lane), and the binary walk, the
 * brute force and the double-precision refinement all end in that
 * finish.  So every answer is the same without it, while a walk no
 * longer tests it in each visit of its leaf (gears: 80 of 880
 * triangles, collinear vertices).  The other triangles keep their slot
 * order in the lane (the tie rules see the same order), the lane keeps
 * its box (a binary node's, bit for bit), and its count is the
 * triangles left (live).  A node keeps at least one lane: when every
 * lane would go (a subtree of zero-area triangles only), the first stays
 * whole, its triangles as NaN lanes.  Which triangles have zero area
 * is c->zero's (zero_slots: the packets' own test), so the packets of a
 * lane are filled without the test (known).  Depends on nothing but the
 * node, as gather, so the bytes are the same on any pool.  A layout that
 * left triangles out cannot be refit in place (accel_refit4): a moved
 * vertex can give such a triangle an area.  Only the second collapse of
 * collapse_wide_dropping leaves triangles out (c->drop).
 */
static void drop_zero_area(const struct collapse *c, struct scratch_node *s)
{
    for (int l = 0; l < s->lanes; l++)
        s->live[l] = s->count[l];
    s->known = 0;
    if (!c->drop)
        return; /* (kept is read only where live differs from count) */
    for (int l = 0; l < s->lanes; l++)
        s->kept[l] = (1u << s->count[l]) - 1u; /* leaf lanes: at most 8 */
    if (!c->zero) {
        /* No zero-area triangle anywhere (zero_slots): every leaf lane
         * whole, its packets filled without the test. */
        s->known = ~s->inner & ((1u << s->lanes) - 1u);
        return;
    }
    struct scratch_node t = *s;
    int lanes = 0;
    uint32_t inner = 0;
    for (int l = 0; l < s->lanes; l++) {
        if (!(s->inner >> l & 1u)) {
            uint32_t zero = 0;
            for (uint32_t j = 0; j < s->count[l]; j++)
                zero |= (uint32_t)c->zero[s->first[l] + j] << j;
            if (zero == t.kept[l])
                continue;
            t.kept[l] &= ~zero;
            t.live[l] = 0;
            for (uint32_t j = 0; j < s->count[l]; j++)
                t.live[l] += t.kept[l] >> j & 1u;
            s->known |= 1u << lanes;
        } else {
            inner |= 1u << lanes;
        }
        s->source[lanes] = t.source[l];
        s->child[lanes] = t.child[l];
        s->count[lanes] = t.count[l];
        s->first[lanes] = t.first[l];
        s->live[lanes] = t.live[l];
        s->kept[lanes] = t.kept[l];
        lanes++;
    }
    if (!lanes) {
        /* Every lane a leaf of zero-area triangles: the first one whole
         * (its packets' fill marks them). */
        *s = t;
        s->lanes = 1;
        s->live[0] = s->count[0];
        s->kept[0] = (1u << s->count[0]) - 1u;
        s->known = 0;
        return;
    }
    s->lanes = lanes;
    s->inner = inner;
}

/* zero_slots' work: slots [lo, hi). */
struct zero_slots_task {
    const struct collapse *c;
    uint8_t *zero;
};

static void zero_slots_range(void *arg, uint32_t lo, uint32_t hi)
{
    const struct zero_slots_task *t = arg;
    for (uint32_t j = lo; j < hi; j += 8) {
        const uint32_t n = hi - j < 8 ? hi - j : 8;
        const uint32_t mask = slots_zero_mask(t->c, j, n);
        for (uint32_t k = 0; k < n; k++)
            t->zero[j + k] = (uint8_t)(mask >> k & 1u);
    }
}

/* Per leaf slot of c's tree, 1 when its triangle has zero area (the
 * packets' test, slots_zero_mask), shared between the pool's threads; in
 * *out, or NULL when no slot's has (then the collapse leaves nothing
 * out and its packets are filled without the test).  0, or -1 on
 * allocation failure. */
static int zero_slots(const struct collapse *c, struct rt_pool *pool, uint8_t **out)
{
    const uint32_t n = c->bvh->prim_count;
    *out = NULL;
    uint8_t *zero = rt_realloc_array(NULL, n ? n : 1, 1);
    if (!zero)
        return -1;
    struct zero_slots_task task = {c, zero};
    rt_pool_run_range(pool, 0, n, 4096, 16384, zero_slots_range, &task);
    uint32_t any = 0;
    for (uint32_t j = 0; j < n; j++)
        any |= zero[j];
    if (any)
        *out = zero;
    else
        rt_free(zero);
    return 0;
}

/* The write of the nodes above the cut (fewer than COLLAPSE_ITEM_LEVEL a
 * level, so few but in a deep narrow tree) takes the pool from this
 * many nodes; fewer cost less than waking the workers. */
#define COLLAPSE_PARALLEL_MIN 512u
/* Nodes per chunk handed out: large enough that the atomic counter is
 * not contended, small enough that the chunks balance between threads. */
#define COLLAPSE_CHUNK 256u
/* The cut (struct collapse): the first level of at least this many wide
 * nodes makes the items, enough for the pool's threads to balance them
 * (an 8-wide tree reaches it at its third or fourth level); a smaller
 * tree is collapsed level by level only. */
#define COLLAPSE_ITEM_LEVEL 64u
/* An item's nodes are held in chunks of this many consecutive slots of
 * the item pool, taken from a shared counter as the item grows: no copy
 * of nodes already gathered, and at most two chunks an item unused. */
#define COLLAPSE_ITEM_CHUNK 64u

/*
 * The item pool's first size, in bytes of scratch nodes: the pool is
 * sized for the worst case, (node_count - 1) / 2 + 1 wide nodes, about
 * eight times what a tree uses (rtbench's bumpy, a million triangles:
 * 75 MB asked, 9.6 MB touched), and a block that large is a fresh
 * mapping of the C library every build (glibc maps every block above its
 * mmap threshold, at most 32 MiB), whose pages the kernel zeroes at their
 * first write: 2,337 faults of 4 KB a bumpy build, and on a virtual
 * machine whose host takes freed memory back, up to 27 ms of system time
 * (docs/performance-log.md, round 38, b11).  A pool of at most 24 MiB
 * comes from the heap instead, where a build's freed arenas
 * (build_parallel.c, 31.5 MiB each on bumpy) leave warm memory.  So
 * when the worst case is larger and the tree is small enough that its
 * wide nodes should fit (at most COLLAPSE_POOL_TRIANGLES triangles a
 * slot: a wide node over leaves of one triangle each holds eight, so six
 * leaves a little margin for partly filled nodes), the items are first
 * gathered in the smaller pool, and only if it runs out, gathered again
 * in the worst case's.  The pool is scratch: where an item's nodes sit in
 * it changes neither the numbering (number_items) nor the bytes written
 * (write_items), so the layout is the same either way.
 */
#define COLLAPSE_POOL_FIRST_BYTES ((size_t)24 << 20)
#define COLLAPSE_POOL_TRIANGLES 6u

/* Scratch nodes [lo, hi)'s lanes from binary inner nodes todo[w] (a
 * level above the cut). */
static void gather_nodes(void *arg, uint32_t lo, uint32_t hi)
{
    const struct collapse *c = arg;
    for (uint32_t w = lo; w < hi; w++) {
        if (c->dp) {
            gather_dp(c->dp, c->todo[w], &c->scratch[w]);
        } else {
            gather(c->bvh, c->tri, c->zero, c->todo[w], c->width, &c->scratch[w]);
            if (c->merge_left)
                close_small_lanes(c->bvh, c->tri, c->zero, c->width, &c->scratch[w]);
        }
        drop_zero_area(c, &c->scratch[w]);
    }
}

/* Numbers the children of level [begin, end): inner lanes get the next
 * wide nodes (appended to todo), leaf lanes the next packets (or, for
 * range leaves, their first leaf slot). */
static void number_level(const struct collapse *c, uint32_t begin, uint32_t end,
                         uint32_t *todo, uint32_t *count, uint32_t *packets)
{
    for (uint32_t w = begin; w < end; w++) {
        struct scratch_node *s = &c->scratch[w];
        for (int l = 0; l < s->lanes; l++) {
            if (s->inner >> l & 1u) {
                todo[*count] = s->source[l];
                s->child[l] = (*count)++;
            } else if (!c->tri) {
                s->child[l] = s->first[l];
            } else {
                s->child[l] = *packets; /* first packet; slots from first[l] */
                *packets += (s->live[l] + 3) / 4;
            }
        }
    }
}

/* Leaf lane l of s with zero-area triangles left out (drop_zero_area):
 * its packets from the kept slots in slot order, packed four a packet
 * (the last one's lanes past the leaf's end repeat its last triangle, as
 * fill_packet's); a packet's slot is its first triangle's. */
static void write_kept(const struct collapse *c, const struct scratch_node *s, int l,
                       uint32_t packet_base)
{
    uint32_t slots[BVH_WIDE_MAX_LEAF];
    uint32_t n = 0;
    for (uint32_t j = 0; j < s->count[l]; j++) {
        if (s->kept[l] >> j & 1u)
            slots[n++] = s->first[l] + j;
    }
    for (uint32_t j = 0; j < n; j += 4) {
        const uint32_t p = s->child[l] + packet_base + j / 4;
        const uint32_t m = n - j < 4 ? n - j : 4;
        float buf[4][9];
        const float *row[4];
        slot_rows(c, slots + j, m, buf, row);
        uint32_t prim[4];
        for (uint32_t k = 0; k < 4; k++)
            prim[k] = c->bvh->prim_index[slots[j + (k < m ? k : m - 1)]];
        c->packet_slot[p] = slots[j];
        fill_packet_rows(&c->packets[p], row, NULL, 0, m, 0);
        memcpy(c->packets[p].prim, prim, sizeof(prim));
    }
}

/* Wide node w (scratch s) in its layout, its packets and its binary
 * sources; child_base[1] is added to its inner lanes' children,
 * child_base[0] to its leaf lanes' (0 for range leaves). */
static void write_scratch(const struct collapse *c, const struct scratch_node *s, uint32_t w,
                          const uint32_t child_base[2])
{
    const uint32_t width = c->width;
    for (uint32_t l = 0; l < width; l++)
        c->source[width * w + l] = (int)l < s->lanes ? s->source[l] : UINT32_MAX;
    for (int l = 0; l < s->lanes && c->tri; l++) {
        if (s->inner >> l & 1u)
            continue;
        uint32_t slot = s->first[l];
        if (s->live[l] != s->count[l]) {
            write_kept(c, s, l, child_base[0]);
            continue;
        }
        const int test = !(s->known >> l & 1u);
        for (uint32_t j = 0; j < s->count[l]; j += 4) {
            uint32_t p = s->child[l] + child_base[0] + j / 4;
            uint32_t n = s->count[l] - j < 4 ? s->count[l] - j : 4;
            c->packet_slot[p] = slot + j;
            const int zero =
                c->src.tri
                    ? fill_packet(&c->packets[p], c->src.tri, c->bvh->prim_index, slot + j, n, test)
                    : fill_packet_mesh(&c->packets[p], &c->src, c->bvh->prim_index, slot + j, n,
                                       test);
            if (zero) {
                /* Rare (gears: 80 of 880 triangles; the kitchen 41 of
                 * 110,561): an atomic add per such packet. */
                uint32_t found = 0;
                for (int k = 0; k < 4; k++)
                    found += (uint32_t)zero >> k & 1u;
                rt_atomic_fetch_add_relaxed(c->zero_found, found);
            }
        }
    }
    if (width == 4)
        write_node4((struct bvh4_node *)(void *)c->base + w, c->bvh, s, child_base);
    else
        write_node8((struct bvh8_node *)(void *)c->base + w, c->bvh, s, child_base);
}

/* Wide nodes [lo, hi) above the cut with write_scratch (their children
 * numbered globally). */
static void write_nodes(void *arg, uint32_t lo, uint32_t hi)
{
    const struct collapse *c = arg;
    const uint32_t none[2] = {0, 0};
    for (uint32_t w = lo; w < hi; w++)
        write_scratch(c, &c->scratch[w], w, none);
}

/* The item pool's slot of item it's node w. */
static inline uint32_t item_slot(const struct collapse_item *it, uint32_t w)
{
    return it->chunk[w / COLLAPSE_ITEM_CHUNK] + w % COLLAPSE_ITEM_CHUNK;
}

/* Slots in the item pool for item it's nodes [0, need); 0, or -1 on
 * allocation failure. */
static int item_reserve(const struct collapse *c, struct collapse_item *it, uint32_t need)
{
    while ((uint64_t)it->chunks * COLLAPSE_ITEM_CHUNK < need) {
        if (it->chunks == it->chunk_cap) {
            const uint32_t cap = it->chunk_cap ? 2 * it->chunk_cap : 8;
            uint32_t *chunk = rt_realloc_array(it->chunk, cap, sizeof(*chunk));
            if (!chunk)
                return -1;
            it->chunk = chunk;
            it->chunk_cap = cap;
        }
        const uint32_t slot = rt_atomic_fetch_add_relaxed(c->item_next, COLLAPSE_ITEM_CHUNK);
        /* Never taken: the pool is sized for every item's worst case
         * (collapse_wide). */
        if (slot > c->item_cap - COLLAPSE_ITEM_CHUNK)
            return -1;
        it->chunk[it->chunks++] = slot;
    }
    return 0;
}

/* Item it: its wide nodes gathered and numbered in its breadth-first
 * order (struct collapse_item); 0, or -1 on allocation failure. */
static int item_gather(const struct collapse *c, struct collapse_item *it)
{
    if (item_reserve(c, it, 1))
        return -1;
    c->item_todo[item_slot(it, 0)] = it->root;
    it->count = 1;
    for (uint32_t begin = 0; begin < it->count;) {
        const uint32_t end = it->count;
        if (it->levels == it->level_cap) {
            const uint32_t cap = it->level_cap ? 2 * it->level_cap : 16;
            struct item_level *level = rt_realloc_array(it->level, cap, sizeof(*level));
            if (!level)
                return -1;
            it->level = level;
            it->level_cap = cap;
        }
        struct item_level *lv = &it->level[it->levels++];
        lv->begin = begin;
        lv->packets = 0;
        for (uint32_t w = begin; w < end; w++) {
            /* Room for the node's children first (inner lanes append). */
            if (item_reserve(c, it, it->count + c->width))
                return -1;
            struct scratch_node *s = &c->item_nodes[item_slot(it, w)];
            if (c->dp) {
                gather_dp(c->dp, c->item_todo[item_slot(it, w)], s);
            } else {
                gather(c->bvh, c->tri, c->zero, c->item_todo[item_slot(it, w)], c->width, s);
                if (c->merge_left)
                    close_small_lanes(c->bvh, c->tri, c->zero, c->width, s);
            }
            drop_zero_area(c, s);
            for (int l = 0; l < s->lanes; l++) {
                if (s->inner >> l & 1u) {
                    c->item_todo[item_slot(it, it->count)] = s->source[l];
                    s->child[l] = it->count++ - end;
                } else if (!c->tri) {
                    s->child[l] = s->first[l];
                } else {
                    s->child[l] = lv->packets;
                    lv->packets += (s->live[l] + 3) / 4;
                }
            }
        }
        begin = end;
    }
    return 0;
}

/* Items [lo, hi) with item_gather. */
static void gather_items(void *arg, uint32_t lo, uint32_t hi)
{
    const struct collapse *c = arg;
    for (uint32_t f = lo; f < hi; f++)
        c->items[f].failed = item_gather(c, &c->items[f]) != 0;
}

/* Items [lo, hi)'s nodes with write_scratch, their children numbered
 * globally. */
static void write_items(void *arg, uint32_t lo, uint32_t hi)
{
    const struct collapse *c = arg;
    for (uint32_t f = lo; f < hi; f++) {
        const struct collapse_item *it = &c->items[f];
        for (uint32_t k = 0; k < it->levels; k++) {
            const struct item_level *lv = &it->level[k];
            const uint32_t end = k + 1 < it->levels ? it->level[k + 1].begin : it->count;
            /* Inner lanes' children are in the item's next level; leaf
             * lanes' packets are counted from the level's first. */
            const uint32_t base[2] = {c->tri ? lv->packet_base : 0,
                                      k + 1 < it->levels ? it->level[k + 1].node_base : 0};
            for (uint32_t w = lv->begin; w < end; w++)
                write_scratch(c, &c->item_nodes[item_slot(it, w)], lv->node_base + (w - lv->begin),
                              base);
        }
    }
}

/* The items' levels' global numbers (struct collapse), level by level
 * and in item order within a level, after the *count nodes and *packets
 * packets above the cut; returns the totals in *count and *packets. */
static void number_items(struct collapse_item *items, uint32_t n, uint32_t *count,
                         uint32_t *packets)
{
    uint32_t node = *count;
    uint32_t packet = *packets;
    int more = 1;
    for (uint32_t k = 0; more; k++) {
        more = 0;
        for (uint32_t f = 0; f < n; f++) {
            struct collapse_item *it = &items[f];
            if (k >= it->levels)
                continue;
            struct item_level *lv = &it->level[k];
            const uint32_t end = k + 1 < it->levels ? it->level[k + 1].begin : it->count;
            lv->node_base = node;
            node += end - lv->begin;
            lv->packet_base = packet;
            packet += lv->packets;
            more |= k + 1 < it->levels;
        }
    }
    *count = node;
    *packets = packet;
}

static void release_items(struct collapse_item *items, uint32_t n)
{
    for (uint32_t f = 0; items && f < n; f++) {
        rt_free(items[f].chunk);
        rt_free(items[f].level);
    }
    rt_free(items);
}

/* Room above the cut for `need` wide nodes and their binary nodes (the
 * arrays grow as the top levels are numbered: a tree that reaches the
 * cut keeps only its top in them); 0, or -1 on allocation failure. */
static int top_reserve(struct collapse *c, uint32_t need, uint32_t *cap)
{
    if (need <= *cap)
        return 0;
    uint32_t n = *cap < 128 ? 256 : 2 * *cap;
    if (n < need)
        n = need;
    struct scratch_node *scratch = rt_realloc_array(c->scratch, n, sizeof(*scratch));
    if (!scratch)
        return -1;
    c->scratch = scratch;
    uint32_t *todo = rt_realloc_array(c->todo, n, sizeof(*todo));
    if (!todo)
        return -1;
    c->todo = todo;
    *cap = n;
    return 0;
}

/*
 * The leaves' size (bvh4_layout.h, leaf_extent): the mean over the leaf
 * lanes of every fourth node of the largest extent of a lane's box.  An
 * unweighted mean: weighted by surface (as a ray meets the boxes) the
 * kitchen's few large leaves of walls and floor would set it (4.9
 * against a mean of 0.037 and a median of 0.017).  Only a choice of walk
 * depends on it, so the sample need not be exact.
 */
static float leaf_extent_mean(const struct bvh4 *w)
{
    double sum = 0.0;
    uint32_t lanes = 0;
    for (uint32_t i = 0; i < w->node_count; i += 4) {
        const struct bvh8_node *n = &w->nodes8[i];
        for (uint32_t l = 0; l < 8; l++) {
            if (!n->count[l])
                continue;
            const float dx = n->bounds[3][l] - n->bounds[0][l];
            const float dy = n->bounds[4][l] - n->bounds[1][l];
            const float dz = n->bounds[5][l] - n->bounds[2][l];
            float e = dx > dy ? dx : dy;
            e = e > dz ? e : dz;
            if (!(e >= 0.0f && e < INFINITY))
                continue;
            sum += e;
            lanes++;
        }
    }
    return lanes ? (float)(sum / lanes) : 0.0f;
}

/* The triangles in w's leaf lanes (their counts). */
static uint32_t layout_triangles(const struct bvh4 *w)
{
    uint32_t sum = 0;
    for (uint32_t i = 0; i < w->node_count; i++) {
        const uint8_t *count = w->width == 8 ? w->nodes8[i].count : w->nodes[i].count;
        for (uint32_t l = 0; l < w->width; l++)
            sum += count[l];
    }
    return sum;
}

/* accel_collapse_wide_source in this unit's instruction set. */
static int collapse_wide(struct bvh4 *out, const struct bvh *bvh,
                         const struct collapse_triangles *tris, uint32_t width,
                         struct rt_pool *pool, struct rt_large_block *spare,
                         enum bvh_collapse collapse, int drop, uint32_t *zero_found)
{
    /* Whether the leaves hold triangles: the rest of the collapse asks
     * only that (the nodes do not depend on where the triangles are
     * read). */
    const float *tri = tris->tri ? tris->tri : tris->positions;
    memset(out, 0, sizeof(*out));
    if (width != 4 && width != 8)
        return -1;
    if (bvh->node_count == 0)
        return 0;
    /* Every wide node but the root consumes a binary inner node, so
     * there are at most (node_count - 1) / 2 + 1 of them. */
    const uint32_t cap = (bvh->node_count - 1) / 2 + 1;
    struct rt_large_block raw = {NULL, 0};
    int taken = 0; /* raw is *spare's block */
    char *base = NULL;
    uint32_t *source = NULL;
    uint32_t *packet_slot = NULL;
    struct collapse_item *items = NULL;
    uint32_t item_count = 0;
    uint32_t item_next = 0;
    uint32_t top_cap = 0;
    struct collapse c;
    memset(&c, 0, sizeof(c));
    struct dp dp;
    memset(&dp, 0, sizeof(dp));
    c.bvh = bvh;
    c.tri = tri;
    c.src = *tris;
    c.width = width;
    c.drop = tri && drop;
    c.item_next = &item_next;
    *zero_found = 0;
    c.zero_found = zero_found;
    uint8_t *zero = NULL;
    if (c.drop && zero_slots(&c, pool, &zero))
        goto fail;
    c.zero = zero;
    /* Not zeroed: each entry is written in full (gather, number_level)
     * before it is read. */
    if (top_reserve(&c, 1, &top_cap))
        goto fail;
    /* Only a layout beyond the caches gains from the smaller layout of
     * the merged leaves (fewer cache lines per ray); a small one, which
     * stays in the caches, would only pay their extra triangle tests
     * (gears: +1.4 % instructions per ray).  The layout's size is
     * estimated before it is made at BVH_WIDE_BYTES_PER_TRIANGLE; the
     * walk's prefetch (prefetch_top below) has the same threshold. */
    c.merge_left =
        tri && (uint64_t)bvh->prim_count * BVH_WIDE_BYTES_PER_TRIANGLE >= BVH_WIDE_PREFETCH_BYTES;
    if (collapse == BVH_COLLAPSE_OPTIMAL && tri) {
        dp.bvh = bvh;
        dp.width = width;
        dp.max_leaf = c.merge_left ? BVH_WIDE_MERGE_LEFT : BVH_WIDE_MERGE;
        dp.node = rt_realloc_array(NULL, bvh->node_count, sizeof(*dp.node));
        if (!dp.node)
            goto fail;
        dp_run(&dp, pool);
        c.dp = &dp;
    }
    uint32_t count = 1;
    uint32_t packets = 0;
    if (leaf_lane(bvh, tri, c.zero, 0, &c.scratch[0].first[0], &c.scratch[0].count[0])) {
        /* One leaf under the root: the root's one lane. */
        c.scratch[0].lanes = 1;
        c.scratch[0].source[0] = 0;
        c.scratch[0].inner = 0;
        drop_zero_area(&c, &c.scratch[0]);
        number_level(&c, 0, 1, c.todo, &count, &packets);
    } else {
        c.todo[0] = 0;
        for (uint32_t begin = 0; begin < count;) {
            const uint32_t end = count;
            if (end - begin >= COLLAPSE_ITEM_LEVEL) {
                /* The cut: every node of this level is an item. */
                item_count = end - begin;
                count = begin;
                break;
            }
            /* The level's nodes and their children's binary nodes. */
            if (top_reserve(&c, end + width * (end - begin), &top_cap))
                goto fail;
            /* Fewer than COLLAPSE_ITEM_LEVEL nodes: on this thread. */
            gather_nodes(&c, begin, end);
            number_level(&c, begin, end, c.todo, &count, &packets);
            begin = end;
        }
    }
    const uint32_t top = count; /* wide nodes above the cut */
    if (item_count) {
        items = rt_realloc_array(NULL, item_count, sizeof(*items));
        if (!items)
            goto fail;
        memset(items, 0, (size_t)item_count * sizeof(*items));
        for (uint32_t f = 0; f < item_count; f++)
            items[f].root = c.todo[top + f];
        /* The items' nodes are at most the cap less the top's; an item
         * of n nodes takes at most n + 2 COLLAPSE_ITEM_CHUNK slots
         * (item_reserve asks for its count plus a node's children). */
        const uint32_t worst = (cap - top) + (2 * item_count + 1) * COLLAPSE_ITEM_CHUNK;
        /* First a pool of at most COLLAPSE_POOL_FIRST_BYTES when the tree
         * should fit it (COLLAPSE_POOL_FIRST_BYTES' comment). */
        const uint32_t first =
            (uint32_t)(COLLAPSE_POOL_FIRST_BYTES / sizeof(struct scratch_node));
        c.item_cap = worst > first && (uint64_t)first * COLLAPSE_POOL_TRIANGLES >=
                                          (uint64_t)bvh->prim_count + COLLAPSE_POOL_TRIANGLES
                         ? first
                         : worst;
        c.items = items;
        for (;;) {
            c.item_nodes = rt_realloc_array(NULL, c.item_cap, sizeof(*c.item_nodes));
            c.item_todo = rt_realloc_array(NULL, c.item_cap, sizeof(*c.item_todo));
            if (!c.item_nodes || !c.item_todo)
                goto fail;
            rt_pool_run_range(pool, 0, item_count, 1, 2, gather_items, &c);
            int failed = 0;
            for (uint32_t f = 0; f < item_count; f++)
                failed |= items[f].failed;
            if (!failed)
                break;
            if (c.item_cap == worst)
                goto fail;
            /* The smaller pool ran out (or an item's own arrays could not
             * grow): every item again, from its root, in the worst case's
             * pool. */
            for (uint32_t f = 0; f < item_count; f++) {
                rt_free(items[f].chunk);
                rt_free(items[f].level);
                memset(&items[f], 0, sizeof(items[f]));
                items[f].root = c.todo[top + f];
            }
            rt_free(c.item_nodes);
            rt_free(c.item_todo);
            c.item_nodes = NULL;
            c.item_todo = NULL;
            item_next = 0;
            c.item_cap = worst;
        }
        number_items(items, item_count, &count, &packets);
    }
    size_t node_size = width == 4 ? sizeof(struct bvh4_node) : sizeof(struct bvh8_node);
    size_t node_bytes = (size_t)count * node_size;
    /* Every byte of the block's used part is written by write_node
     * (nodes in full, packets' every lane and primitive), so a reused
     * block holds the same bytes as a fresh one. */
    const size_t spare_bytes = spare ? spare->bytes : 0;
    base = rt_malloc_large_reuse(node_bytes + (size_t)packets * sizeof(struct tri4_packet), &raw,
                                 spare);
    taken = base && spare_bytes && !spare->bytes;
    /* Both written in full by write_node. */
    source = rt_realloc_array(NULL, (size_t)count * width, sizeof(uint32_t));
    packet_slot = rt_realloc_array(NULL, packets ? packets : 1, sizeof(uint32_t));
    if (!base || !source || !packet_slot)
        goto fail;
    struct tri4_packet *pk = (struct tri4_packet *)(void *)(base + node_bytes);
    c.base = base;
    c.packets = pk;
    c.source = source;
    c.packet_slot = packet_slot;
    rt_pool_run_range(pool, 0, top, COLLAPSE_CHUNK, COLLAPSE_PARALLEL_MIN, write_nodes, &c);
    if (item_count)
        rt_pool_run_range(pool, 0, item_count, 1, 2, write_items, &c);
    release_items(items, item_count);
    rt_free(c.item_nodes);
    rt_free(c.item_todo);
    rt_free(c.scratch);
    rt_free(c.todo);
    rt_free(dp.node);
    rt_free(zero);
    out->width = width;
    out->node_count = count;
    out->nodes = width == 4 ? (struct bvh4_node *)(void *)base : NULL;
    out->nodes8 = width == 8 ? (struct bvh8_node *)(void *)base : NULL;
    out->packets = pk;
    out->packet_count = packets;
    out->prefetch_top =
        bvh4_node_bytes(out) + bvh4_leaf_bytes(out) >= BVH_WIDE_PREFETCH_BYTES ? 1u : 0u;
    out->leaf_extent = width == 8 && tri && packets ? leaf_extent_mean(out) : 0.0f;
    out->stream_pays = width == 8 && tri && packets && bvh4_node_bytes(out) +
                                                           bvh4_leaf_bytes(out) >=
                                                       BVH_WIDE_STREAM_BYTES
                           ? 1u
                           : 0u;
    out->any_longest = width == 8 && tri && packets && accel_wide_child_crossings(out) >=
                                                           BVH_WIDE_ANY_LONGEST_CROSSINGS
                           ? 1u
                           : 0u;
    out->source = source;
    out->packet_slot = packet_slot;
    out->raw = raw;
    out->dropped = c.drop ? bvh->prim_count - layout_triangles(out) : 0;
    /* A taken block may be larger than the layout and written past it
     * (a parallel build's refs, accel_build_parallel_triangles): pages
     * the layout would otherwise hold for its lifetime. */
    if (taken)
        rt_large_release_tail(&raw, base, node_bytes + (size_t)packets * sizeof(struct tri4_packet));
    return 0;
fail:
    release_items(items, item_count);
    rt_free(c.item_nodes);
    rt_free(c.item_todo);
    rt_free(c.scratch);
    rt_free(c.todo);
    rt_free(dp.node);
    rt_free(zero);
    /* A spare taken goes back untouched: nothing is written before every
     * allocation has succeeded. */
    if (taken)
        *spare = raw;
    else
        rt_free_large(&raw);
    rt_free(source);
    rt_free(packet_slot);
    return -1;
}

/* A layout whose zero-area triangles are at least this share of the
 * triangles (1 / COLLAPSE_ZERO_AREA_SHARE) is collapsed again leaving
 * them out (collapse_wide_dropping).  A heuristic only: the answers do
 * not depend on it. */
#define COLLAPSE_ZERO_AREA_SHARE 32u

/*
 * collapse_wide, then, when the packets' fill found zero-area triangles
 * among at least 1 / COLLAPSE_ZERO_AREA_SHARE of the triangles (gears: 80
 * of 880) and the caller does not keep them for a refit (struct
 * collapse_triangles), collapsed again leaving them out (drop_zero_area,
 * with the merge counting the others, small_span_live).  Only a fill
 * finds them without a pass of its own over the triangles (the test
 * before the gather costs the collapse about 30 % more instructions on
 * a mesh without any, bumpy), so a layout with fewer keeps them as NaN
 * lanes (the kitchen: 41 of 110,561), which costs its walks little, and
 * its collapse is the first one's alone.  Should the second collapse
 * fail, the first one's layout stays (the same answers).
 */
static int collapse_wide_dropping(struct bvh4 *out, const struct bvh *bvh,
                                  const struct collapse_triangles *tris, uint32_t width,
                                  struct rt_pool *pool, struct rt_large_block *spare,
                                  enum bvh_collapse collapse)
{
    uint32_t found = 0;
    if (collapse_wide(out, bvh, tris, width, pool, spare, collapse, 0, &found))
        return -1;
    if (tris->keep_zero_area || !found ||
        (uint64_t)found * COLLAPSE_ZERO_AREA_SHARE < bvh->prim_count)
        return 0;
    struct bvh4 dropped;
    uint32_t again = 0;
    if (collapse_wide(&dropped, bvh, tris, width, pool, NULL, collapse, 1, &again))
        return 0;
    bvh4_release(out);
    *out = dropped;
    return 0;
}

int accel_collapse_wide_source(struct bvh4 *out, const struct bvh *bvh,
                               const struct collapse_triangles *tris, uint32_t width,
                               struct rt_pool *pool, struct rt_large_block *spare,
                               enum bvh_collapse collapse)
{
#if !defined(COLLAPSE_UNIT_AVX2)
    /* The same source compiled for AVX2, where it runs
     * (collapse4_avx2.c): the same bytes in fewer instructions. */
    const collapse_wide_fn avx2 = accel_collapse_wide_avx2_unit();
    if (avx2)
        return avx2(out, bvh, tris, width, pool, spare, collapse);
#endif
    return collapse_wide_dropping(out, bvh, tris, width, pool, spare, collapse);
}

int accel_collapse_wide_quality(struct bvh4 *out, const struct bvh *bvh, const float *tri,
                                uint32_t width, struct rt_pool *pool,
                                struct rt_large_block *spare, enum bvh_collapse collapse)
{
    const struct collapse_triangles tris = {tri, NULL, NULL, 0};
    return accel_collapse_wide_source(out, bvh, &tris, width, pool, spare, collapse);
}

int accel_collapse_wide_mesh(struct bvh4 *out, const struct bvh *bvh, const float *positions,
                             const uint32_t *indices, uint32_t width, struct rt_pool *pool,
                             struct rt_large_block *spare, enum bvh_collapse collapse)
{
    const struct collapse_triangles tris = {NULL, positions, indices, 0};
    return accel_collapse_wide_source(out, bvh, &tris, width, pool, spare, collapse);
}

int accel_collapse_wide_reuse(struct bvh4 *out, const struct bvh *bvh, const float *tri,
                              uint32_t width, struct rt_pool *pool, struct rt_large_block *spare)
{
    return accel_collapse_wide_quality(out, bvh, tri, width, pool, spare, BVH_COLLAPSE_GREEDY);
}

int accel_collapse_wide_portable(struct bvh4 *out, const struct bvh *bvh,
                                 const struct collapse_triangles *tris, uint32_t width,
                                 struct rt_pool *pool, struct rt_large_block *spare,
                                 enum bvh_collapse collapse)
{
    return collapse_wide_dropping(out, bvh, tris, width, pool, spare, collapse);
}

int accel_collapse_wide_pool(struct bvh4 *out, const struct bvh *bvh, const float *tri,
                             uint32_t width, struct rt_pool *pool)
{
    return accel_collapse_wide_reuse(out, bvh, tri, width, pool, NULL);
}

int accel_collapse_wide(struct bvh4 *out, const struct bvh *bvh, const float *tri,
                        uint32_t width)
{
    return accel_collapse_wide_pool(out, bvh, tri, width, NULL);
}

int accel_collapse4(struct bvh4 *out, const struct bvh *bvh, const float *tri)
{
    return accel_collapse_wide(out, bvh, tri, 4);
}

int accel_refit4(struct bvh4 *wide, const struct bvh *bvh, const float *tri)
{
    /* Triangles left out by the collapse (drop_zero_area) may have gained
     * an area: only a new collapse can put them back. */
    if (wide->dropped)
        return -1;
    const uint32_t width = wide->width;
    for (uint32_t w = 0; w < wide->node_count; w++) {
        for (uint32_t l = 0; l < width; l++) {
            /* Unused lanes keep their empty box. */
            uint32_t i = wide->source[width * w + l];
            if (i == UINT32_MAX)
                continue;
            for (int k = 0; k < 3; k++) {
                float lo = bvh->nodes[i].aabb_min[k];
                float hi = bvh->nodes[i].aabb_max[k];
                if (width == 4) {
                    wide->nodes[w].bounds[k][l] = lo;
                    wide->nodes[w].bounds[3 + k][l] = hi;
                } else {
                    wide->nodes8[w].bounds[k][l] = lo;
                    wide->nodes8[w].bounds[3 + k][l] = hi;
                }
            }
        }
    }
    /* The packets' vertices; the primitives and their slots are unchanged. */
    for (uint32_t p = 0; p < wide->packet_count; p++) {
        uint32_t slot = wide->packet_slot[p];
        /* Lanes past the leaf's end repeat its last triangle, and a
         * primitive is in one slot only: the triangles are the lanes up to
         * the first repeated primitive. */
        uint32_t n = 1;
        while (n < 4 && (wide->packets[p].prim[n] != wide->packets[p].prim[n - 1]))
            n++;
        fill_packet(&wide->packets[p], tri, NULL, slot, n, 1);
    }
    return 0;
}

uint64_t bvh4_node_bytes(const struct bvh4 *wide)
{
    size_t size = wide->width == 8 ? sizeof(struct bvh8_node) : sizeof(struct bvh4_node);
    return (uint64_t)wide->node_count * size;
}

uint64_t bvh4_leaf_bytes(const struct bvh4 *wide)
{
    return (uint64_t)wide->packet_count * sizeof(struct tri4_packet);
}

void bvh4_release(struct bvh4 *wide)
{
    rt_free_large(&wide->raw);
    rt_free(wide->source);
    rt_free(wide->packet_slot);
    memset(wide, 0, sizeof(*wide));
}
