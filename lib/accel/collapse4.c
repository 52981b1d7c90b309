/* SPDX-License-Identifier: Apache-2.0 */
/*
 * collapse4.c - the binary BVH collapsed into the wide traversal layout,
 * 4- or 8-wide, with triangle packets for leaves (trace/bvh4_layout.h),
 * and its refit.
 *
 * Three steps: per binary node, the leaf slots its subtree covers (to
 * find subtrees small enough to become one packet leaf); the greedy
 * collapse into a width-generic scratch node; the final nodes (with the
 * per-octant child order) and packets in one 64-byte aligned block.
 */
#include "trace/bvh4_layout.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "base/alloc.h"
#include "trace/intersect.h"

#define MAX_WIDTH 8

/* About what a wide layout takes per triangle with merged leaves (the
 * memory table of rtbench embree: 60-67 bytes on bumpy, soup and the
 * kitchen); only the choice of merging depends on it. */
#define BVH_WIDE_BYTES_PER_TRIANGLE 64

/* A wide node before it is written in its width's layout.  count is the
 * leaf's triangles (0: inner child or unused lane); a leaf's child is its
 * first leaf slot until the packets are made. */
struct scratch_node {
    uint32_t source[MAX_WIDTH];
    uint32_t child[MAX_WIDTH];
    uint32_t count[MAX_WIDTH];
    int lanes;
};

static float node_area(const struct bvh_node *n)
{
    float dx = n->aabb_max[0] - n->aabb_min[0];
    float dy = n->aabb_max[1] - n->aabb_min[1];
    float dz = n->aabb_max[2] - n->aabb_min[2];
    return dx * dy + dy * dz + dz * dx;
}

/* span[i], first[i] from the children's (visited before i). */
static void span_step(const struct bvh *bvh, uint32_t i, uint32_t *first, uint32_t *span)
{
    const struct bvh_node *node = &bvh->nodes[i];
    if (node->count) {
        first[i] = node->first;
        span[i] = node->count;
        return;
    }
    uint32_t l = node->first;
    uint32_t r = l + 1;
    span[i] = 0;
    if (span[l] && span[r] && first[l] + span[l] == first[r]) {
        first[i] = first[l];
        span[i] = span[l] + span[r];
    } else if (span[l] && span[r] && first[r] + span[r] == first[l]) {
        first[i] = first[r];
        span[i] = span[l] + span[r];
    }
}

/* Per binary node, the triangles of its subtree when they occupy
 * consecutive leaf slots (span[n] of them from first[n]), else span 0.
 * Builders partition slots in place, so a subtree's slots are normally
 * consecutive; restructuring can break that, and such a subtree is then
 * simply never merged.  Children are visited before parents: in
 * decreasing index order when every inner node's children come after it
 * (what the builders write, checked here in one sequential pass),
 * otherwise in reverse preorder.  Returns 0 or -1 on allocation failure. */
static int subtree_spans(const struct bvh *bvh, uint32_t *first, uint32_t *span)
{
    int children_after = 1;
    for (uint32_t i = 0; i < bvh->node_count && children_after; i++) {
        const struct bvh_node *node = &bvh->nodes[i];
        children_after = node->count != 0 ||
                         (node->first > i && node->first < bvh->node_count - 1);
    }
    if (children_after) {
        for (uint32_t i = bvh->node_count; i-- > 0;)
            span_step(bvh, i, first, span);
        return 0;
    }
    uint32_t *pre = rt_calloc(bvh->node_count, sizeof(uint32_t));
    uint32_t *stack = rt_calloc(BVH_MAX_DEPTH + 2, sizeof(uint32_t));
    if (!pre || !stack) {
        rt_free(pre);
        rt_free(stack);
        return -1;
    }
    uint32_t n = 0;
    uint32_t sp = 0;
    stack[sp++] = 0;
    while (sp) {
        uint32_t i = stack[--sp];
        pre[n++] = i;
        if (bvh->nodes[i].count == 0) {
            stack[sp++] = bvh->nodes[i].first;
            stack[sp++] = bvh->nodes[i].first + 1;
        }
    }
    while (n)
        span_step(bvh, pre[--n], first, span);
    rt_free(pre);
    rt_free(stack);
    return 0;
}

/* A lane that is a leaf of the wide layout: a binary leaf, or a small
 * subtree in consecutive slots. */
static int is_leaf_lane(const struct bvh *bvh, const uint32_t *span, uint32_t i)
{
    return bvh->nodes[i].count != 0 || (span[i] != 0 && span[i] <= BVH_WIDE_MERGE);
}

static int gather(const struct bvh *bvh, const uint32_t *span, uint32_t inner, uint32_t width,
                  uint32_t out[MAX_WIDTH]);

/* The expected cost of binary subtree i as a lane, in packet tests, by
 * the surface area heuristic (MacDonald and Booth 1990): a leaf lane
 * tests its packets; otherwise it is a wide node, one node test
 * (BVH_WIDE_NODE_COST) plus each of its lanes' costs weighted by the
 * lane's share of its area (the chance that a ray through the node's box
 * enters the lane's). */
static double lane_cost(const struct bvh *bvh, const uint32_t *span, uint32_t i, uint32_t width)
{
    if (is_leaf_lane(bvh, span, i)) {
        const uint32_t n = bvh->nodes[i].count ? bvh->nodes[i].count : span[i];
        return (double)((n + 3) / 4);
    }
    uint32_t lanes[MAX_WIDTH];
    const int n = gather(bvh, span, i, width, lanes);
    const double area = node_area(&bvh->nodes[i]);
    double cost = BVH_WIDE_NODE_COST;
    for (int l = 0; l < n; l++) {
        const double share = area > 0.0 ? node_area(&bvh->nodes[lanes[l]]) / area : 1.0;
        cost += share * lane_cost(bvh, span, lanes[l], width);
    }
    return cost;
}

/* A lane that gather left closed (the wide node above it is full) and
 * that is no leaf lane would become a wide node of its own.  When its
 * subtree holds at most BVH_WIDE_MERGE_LEFT triangles in consecutive
 * slots (two packets) it becomes one leaf instead if that costs no more
 * by the area heuristic.  Such a node holds only leaf lanes, often two
 * (soup: 3235 of 8190 8-wide nodes had two), a 256-byte node and a
 * visit spent on what a second packet holds; without them the 8-wide
 * layout is 10-11 % smaller (soup, kitchen, bumpy: the memory table of
 * rtbench embree) and a ray visits fewer nodes and tests more
 * triangles.  The lane's box is the subtree root's,
 * a binary node's box bit for bit, so the answers are the same. */
static int is_final_leaf(const struct bvh *bvh, const uint32_t *span, uint32_t i, uint32_t width,
                         int merge_left)
{
    if (is_leaf_lane(bvh, span, i))
        return 1;
    if (!merge_left || span[i] == 0 || span[i] > BVH_WIDE_MERGE_LEFT)
        return 0;
    return (double)((span[i] + 3) / 4) <= lane_cost(bvh, span, i, width);
}

/* The binary nodes a wide node over binary inner node `inner` holds:
 * starting from its two children, the openable (inner, not merged) one
 * of largest area is replaced by its children until there are `width`
 * (ties: the first). */
static int gather(const struct bvh *bvh, const uint32_t *span, uint32_t inner, uint32_t width,
                  uint32_t out[MAX_WIDTH])
{
    /* Each lane's area and openness, computed once when the lane is
     * added rather than at every step (the same values, so the same
     * picks). */
    float area[MAX_WIDTH];
    int openable[MAX_WIDTH];
    uint32_t n = 2;
    out[0] = bvh->nodes[inner].first;
    out[1] = out[0] + 1;
    for (uint32_t i = 0; i < 2; i++) {
        area[i] = node_area(&bvh->nodes[out[i]]);
        openable[i] = !is_leaf_lane(bvh, span, out[i]);
    }
    while (n < width) {
        int pick = -1;
        float best = -1.0f;
        for (uint32_t i = 0; i < n; i++) {
            if (openable[i] && (pick < 0 || area[i] > best)) {
                pick = (int)i;
                best = area[i];
            }
        }
        if (pick < 0)
            break;
        uint32_t first = bvh->nodes[out[pick]].first;
        out[pick] = first;
        out[n] = first + 1;
        area[pick] = node_area(&bvh->nodes[first]);
        openable[pick] = !is_leaf_lane(bvh, span, first);
        area[n] = node_area(&bvh->nodes[first + 1]);
        openable[n] = !is_leaf_lane(bvh, span, first + 1);
        n++;
    }
    return (int)n;
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

static void octant_orders(const double centre[MAX_WIDTH][3], int lanes, int oct,
                          int order[MAX_WIDTH], int order_opposite[MAX_WIDTH])
{
    uint64_t key[MAX_WIDTH];
    int rank[MAX_WIDTH] = {0};
    int rank_opposite[MAX_WIDTH] = {0};
    for (int l = 0; l < lanes; l++) {
        double k = 0.0;
        for (int a = 0; a < 3; a++)
            k += (oct >> a & 1) ? -centre[l][a] : centre[l][a];
        key[l] = order_key(k);
    }
    for (int l = 1; l < lanes; l++) {
        for (int j = 0; j < l; j++) {
            int j_first = key[j] <= key[l];
            int j_first_opposite = key[j] >= key[l];
            rank[l] += j_first;
            rank[j] += 1 - j_first;
            rank_opposite[l] += j_first_opposite;
            rank_opposite[j] += 1 - j_first_opposite;
        }
    }
    for (int l = 0; l < lanes; l++) {
        order[rank[l]] = l;
        order_opposite[rank_opposite[l]] = l;
    }
    for (int l = lanes; l < MAX_WIDTH; l++) {
        order[l] = l;
        order_opposite[l] = l;
    }
}

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
                        float *bounds, uint32_t *child, uint8_t *count, uint32_t order_bits[8])
{
    for (int l = 0; l < width; l++) {
        for (int k = 0; k < 3; k++) {
            bounds[k * width + l] = l < s->lanes ? bvh->nodes[s->source[l]].aabb_min[k] : INFINITY;
            bounds[(3 + k) * width + l] =
                l < s->lanes ? bvh->nodes[s->source[l]].aabb_max[k] : -INFINITY;
        }
        child[l] = l < s->lanes ? s->child[l] : 0;
        count[l] = (uint8_t)(l < s->lanes ? s->count[l] : 0);
    }
    const int bits_per_lane = width == 4 ? 2 : 3;
    double centre[MAX_WIDTH][3];
    lane_centres(bvh, s, centre);
    for (int oct = 0; oct < 4; oct++) {
        int order[2][MAX_WIDTH];
        octant_orders(centre, s->lanes, oct, order[0], order[1]);
        order_bits[oct] = 0;
        order_bits[7 - oct] = 0;
        for (int p = 0; p < width; p++) {
            order_bits[oct] |= (uint32_t)order[0][p] << (bits_per_lane * p);
            order_bits[7 - oct] |= (uint32_t)order[1][p] << (bits_per_lane * p);
        }
    }
}

static void write_node4(struct bvh4_node *w, const struct bvh *bvh, const struct scratch_node *s)
{
    uint32_t bits[8];
    memset(w, 0, sizeof(*w));
    write_lanes(bvh, s, 4, &w->bounds[0][0], w->child, w->count, bits);
    for (int oct = 0; oct < 8; oct++)
        w->order[oct] = (uint8_t)bits[oct];
}

static void write_node8(struct bvh8_node *w, const struct bvh *bvh, const struct scratch_node *s)
{
    uint32_t bits[8];
    memset(w, 0, sizeof(*w));
    write_lanes(bvh, s, 8, &w->bounds[0][0], w->child, w->count, bits);
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

/* Packet p's lanes from leaf slots [slot, slot + n), n <= 4; lanes past n
 * repeat the last triangle. */
static void fill_packet(struct tri4_packet *p, const float *tri, const uint32_t *prim_index,
                        uint32_t slot, uint32_t n)
{
    for (uint32_t l = 0; l < n; l++) {
        accel_set_packet_lane(p, l, &tri[9 * (size_t)(slot + l)]);
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
}

int accel_collapse_wide(struct bvh4 *out, const struct bvh *bvh, const float *tri,
                        uint32_t width)
{
    memset(out, 0, sizeof(*out));
    if (width != 4 && width != 8)
        return -1;
    if (bvh->node_count == 0)
        return 0;
    /* Every wide node but the root consumes a binary inner node, so
     * there are at most (node_count - 1) / 2 + 1 of them. */
    uint32_t cap = (bvh->node_count - 1) / 2 + 1;
    uint32_t *first = rt_calloc(bvh->node_count, sizeof(uint32_t));
    uint32_t *span = rt_calloc(bvh->node_count, sizeof(uint32_t));
    struct scratch_node *scratch = rt_calloc(cap, sizeof(*scratch));
    uint32_t *todo = rt_calloc(cap, sizeof(uint32_t));
    struct rt_large_block raw = {NULL, 0};
    char *base = NULL;
    uint32_t *source = NULL;
    uint32_t *packet_slot = NULL;
    if (!first || !span || !scratch || !todo || subtree_spans(bvh, first, span))
        goto fail;
    /* Range leaves are the binary leaves only: a merged subtree would
     * visit (transform, set up and enter) every instance under it, where
     * the binary subtree's boxes cull most of them. */
    if (!tri)
        memset(span, 0, bvh->node_count * sizeof(uint32_t));
    /* Only a layout beyond the caches gains from the smaller layout of
     * the merged leaves (fewer cache lines per ray); a small one, which
     * stays in the caches, would only pay their extra triangle tests
     * (gears: +1.4 % instructions per ray).  The layout's size is
     * estimated before it is made at BVH_WIDE_BYTES_PER_TRIANGLE; the
     * walk's prefetch (prefetch_top below) has the same threshold. */
    const int merge_left =
        tri && (uint64_t)bvh->prim_count * BVH_WIDE_BYTES_PER_TRIANGLE >= BVH_WIDE_PREFETCH_BYTES;
    uint32_t count = 1;
    uint32_t packets = 0;
    if (is_leaf_lane(bvh, span, 0)) {
        /* One leaf under the root: the root's one lane. */
        scratch[0].lanes = 1;
        scratch[0].source[0] = 0;
    } else {
        todo[0] = 0;
        for (uint32_t w = 0; w < count; w++) {
            struct scratch_node *s = &scratch[w];
            s->lanes = gather(bvh, span, todo[w], width, s->source);
            for (int l = 0; l < s->lanes; l++) {
                if (!is_final_leaf(bvh, span, s->source[l], width, merge_left)) {
                    todo[count] = s->source[l];
                    s->child[l] = count++;
                }
            }
        }
    }
    for (uint32_t w = 0; w < count; w++) {
        struct scratch_node *s = &scratch[w];
        for (int l = 0; l < s->lanes; l++) {
            uint32_t i = s->source[l];
            if (!is_final_leaf(bvh, span, i, width, merge_left))
                continue;
            s->count[l] = bvh->nodes[i].count ? bvh->nodes[i].count : span[i];
            if (!tri) {
                /* Range leaves (the top level): the first leaf slot. */
                s->child[l] = first[i];
                continue;
            }
            s->child[l] = packets; /* first packet; slots from first[i] */
            packets += (s->count[l] + 3) / 4;
        }
    }
    size_t node_size = width == 4 ? sizeof(struct bvh4_node) : sizeof(struct bvh8_node);
    size_t node_bytes = (size_t)count * node_size;
    base = rt_malloc_large(node_bytes + (size_t)packets * sizeof(struct tri4_packet), &raw);
    source = rt_calloc((size_t)count * width, sizeof(uint32_t));
    packet_slot = rt_calloc(packets ? packets : 1, sizeof(uint32_t));
    if (!base || !source || !packet_slot)
        goto fail;
    struct tri4_packet *pk = (struct tri4_packet *)(void *)(base + node_bytes);
    for (uint32_t w = 0; w < count; w++) {
        struct scratch_node *s = &scratch[w];
        for (uint32_t l = 0; l < width; l++)
            source[width * w + l] = (int)l < s->lanes ? s->source[l] : UINT32_MAX;
        for (int l = 0; l < s->lanes; l++) {
            if (!s->count[l] || !tri)
                continue;
            uint32_t slot = first[s->source[l]];
            for (uint32_t j = 0; j < s->count[l]; j += 4) {
                uint32_t p = s->child[l] + j / 4;
                uint32_t n = s->count[l] - j < 4 ? s->count[l] - j : 4;
                packet_slot[p] = slot + j;
                fill_packet(&pk[p], tri, bvh->prim_index, slot + j, n);
            }
        }
        if (width == 4)
            write_node4((struct bvh4_node *)(void *)base + w, bvh, s);
        else
            write_node8((struct bvh8_node *)(void *)base + w, bvh, s);
    }
    rt_free(first);
    rt_free(span);
    rt_free(scratch);
    rt_free(todo);
    out->width = width;
    out->node_count = count;
    out->nodes = width == 4 ? (struct bvh4_node *)(void *)base : NULL;
    out->nodes8 = width == 8 ? (struct bvh8_node *)(void *)base : NULL;
    out->packets = pk;
    out->packet_count = packets;
    out->prefetch_top =
        bvh4_node_bytes(out) + bvh4_leaf_bytes(out) >= BVH_WIDE_PREFETCH_BYTES ? 1u : 0u;
    out->source = source;
    out->packet_slot = packet_slot;
    out->raw = raw;
    return 0;
fail:
    rt_free(first);
    rt_free(span);
    rt_free(scratch);
    rt_free(todo);
    rt_free_large(&raw);
    rt_free(source);
    rt_free(packet_slot);
    return -1;
}

int accel_collapse4(struct bvh4 *out, const struct bvh *bvh, const float *tri)
{
    return accel_collapse_wide(out, bvh, tri, 4);
}

void accel_refit4(struct bvh4 *wide, const struct bvh *bvh, const float *tri)
{
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
        fill_packet(&wide->packets[p], tri, NULL, slot, n);
    }
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
