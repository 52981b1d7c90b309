/* SPDX-License-Identifier: Apache-2.0 */
/*
 * traverse_wide.h - the walk over the wide layout (bvh4_layout.h), 4-wide
 * in every SIMD table and 8-wide where the table has AVX (AVX2,
 * AVX-512), included by the SIMD translation units (kernels.h) after
 * traverse_walk.h.  Define TRACE_WIDE_CLOSEST, TRACE_WIDE_ANY,
 * TRACE_WIDE_CLOSEST1 and TRACE_WIDE_ANY1.
 *
 * The packet walk (packet_wide.h) lives in translation units of its own
 * (packet_sse4.c, packet_avx2.c, packet_avx512.c), so that its changes
 * cannot move the single walk's code (docs/performance-log.md, pk11 and
 * pk12).  Those units define TRACE_WIDE_PACKET_PIECES instead of the
 * names above: they get the per-ray pieces the packet walk reuses and
 * its fallback (walk_wide and the 8-wide walks over walk_wide8_ray), and
 * none of the single-ray entries; the single walk's units get the
 * entries and not the packet walk's fallback.
 *
 * Same answers as the binary walk of traverse_walk.h, bit for bit:
 * - the child boxes are tested with isect_box's float operations lane by
 *   lane: (bound - org) * inv per slab with the same near/far choice, the
 *   entry folded as max(z, max(y, max(x, tmin))) and the exit as
 *   min(z, min(y, min(x, inf))) with maxps/minps, which return their
 *   second operand for a NaN first one exactly as isect_box's
 *   `a > b ? a : b` does, then the far scale and the clamp to box_limit;
 *   the boxes are binary nodes' boxes copied bit for bit;
 * - the closest-hit rule does not depend on the order of visits (the
 *   smallest t, ties to the lower primitive; every box holding a hit at
 *   or below the current best passes the test, intersect.h's
 *   tag-graze-box-limit), so skipping the binary inner nodes the collapse
 *   removed, visiting a small subtree's triangles as one leaf, and
 *   visiting children in another order change the work done (the node
 *   and triangle counts) but not the hit;
 * - the leaves are tested by the packet filter of intersect_tri4.h and,
 *   for the lanes it keeps, the rest of isect_triangle on the filter's
 *   own floats (tri4_lane_test), with walk_leaf's limit and hit rule
 *   (traverse_walk.h).
 *
 * Child order: the hit children are visited in the node's precomputed
 * order for the ray's octant (Fuetterling, Lojewski, Pfreundt and Ebert
 * 2017), with no sort; each pushed child keeps its entry distance, so
 * a subtree behind the closest hit so far is still skipped when popped.
 * An any-hit walk (walk_wide8_ray's, walk_wide4_body's) pushes them in
 * stored order instead (wide8_push_stored says why).
 */
#include <immintrin.h>

#include "trace/intersect_tri4.h"
#include "trace/isa_avx512.h"
#include "trace/node_fused.h"
#include "trace/ray_setup.h"

struct wide_entry {
    uint32_t child;
    uint32_t count; /* 0: wide node child, else a leaf */
    float t_entry;
};

/* The stack: at most width - 1 entries per level left behind on the
 * current path, plus the width pushed at the deepest node; and 8 more,
 * for the writes of missed lanes beyond the last entry (the push). */
#define WIDE_STACK (7 * BVH_MAX_DEPTH + 16)

/* The single-ray walks and their packet calls are functions of their
 * own (walk_wide8_ray says why). */
#if defined(__GNUC__)
#define WIDE_NOINLINE __attribute__((noinline))
#else
#define WIDE_NOINLINE
#endif

/* The per-ray state every wide walk keeps. */
struct wide_state {
    const struct trace_ray *ray;
    struct tri4_ray r4;
    int any_hit;
    struct trace_hit *hit;
    int found;
    float best;
    float box_limit;
    uint64_t node_tests;
    uint64_t triangle_tests;
};

/* The fused node test (node_fused.h) is the node test of the AVX-512
 * table's walks from the set-up's lanes (WIDE8_WALK1) with any_hit 0 or
 * 1; the walks with any_hit == WIDE_ANY_LONGEST, whose push keys are the
 * exits as isect_box computes them, and the walks from a struct
 * trace_ray keep isect_box's test.  The AVX2 table keeps isect_box's
 * test everywhere: with 16 ymm registers GCC spills five of the fused
 * walk's twelve constant vectors, and on a Zen 3 core the AVX2 walks
 * with the fused test were slower than with isect_box's
 * (docs/performance-log.md, round 54, zn1). */
#if TRACE_AVX512_TABLE
#define WIDE8_FUSED_TABLE 1
#define WIDE8_FUSED(any_hit) ((any_hit) == 0 || (any_hit) == 1)
#else
#define WIDE8_FUSED_TABLE 0
#define WIDE8_FUSED(any_hit) 0
#endif

/* The state of a whole single-ray 8-wide walk (WIDE8_WALK, WIDE8_WALK1,
 * TRACE_WIDE_LEAF8): wide_state and the ray's origin and direction in
 * double (tri4_ray_init_double), which walk_wide8_ray sets at a
 * closest-hit ray's first leaf and its closest-hit leaves
 * (WIDE8_LEAF_TEST's ray_double) give the finish.  Apart from wide_state,
 * not in it: the packet walks keep eight wide_states (packet_wide.h),
 * and their layout and code stay as they were. */
struct wide_ray_state {
    struct wide_state s; /* first: the leaves reach d_org_dir from s */
    double d_org_dir[8];
#if WIDE8_FUSED_TABLE
    /* The fused node test's constants (node_fused.h), set by WIDE8_WALK1
     * for the walks that take it (WIDE8_FUSED); not in a table without
     * the test, whose walk frames stay as they were. */
    struct node_fused fused;
#endif
};

/* The fused constants of the wide_ray_state whose s is *s (as
 * wide_ray_doubles); NULL in a table without the fused test. */
static inline const struct node_fused *wide_ray_fused(const struct wide_state *s)
{
#if WIDE8_FUSED_TABLE
    return &((const struct wide_ray_state *)(const void *)s)->fused;
#else
    (void)s; /* never called: no walk of this table is fused */
    return NULL;
#endif
}

/* The doubles of the wide_ray_state whose s is *s: only for a state
 * that is one (C99 6.7.2.1: a pointer to a structure's first member,
 * converted, points to the structure). */
static inline double *wide_ray_doubles(struct wide_state *s)
{
    return ((struct wide_ray_state *)(void *)s)->d_org_dir;
}

/* walk_wide's state for a ray: no hit yet, the limits of t_max. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void wide_state_init(struct wide_state *s, const struct trace_ray *ray, float t_max,
                                   int any_hit, struct trace_hit *hit)
{
    /* s->r4, which only the leaves read, is the caller's to set:
     * walk_wide8_ray sets it at the ray's first leaf. */
    s->ray = ray;
    s->any_hit = any_hit;
    s->hit = hit;
    s->found = 0;
    s->best = t_max;
    s->box_limit = t_max * ISECT_BOX_FAR_SCALE; /* as traverse_walk.h */
    s->node_tests = 0;
    s->triangle_tests = 0;
}

/* wide_state_init for the whole single-ray 8-wide walks (WIDE8_WALK,
 * WIDE8_WALK1): only the fields their leaves and their end read.  Their
 * leaves take any_hit as a constant, never s->any_hit; an any-hit walk's
 * leaves read the limit s->best and write found, and nothing reads hit,
 * found or box_limit (its box limit never shrinks, so walk_wide8_ray
 * keeps it in a register from s->best); a walk without counters never
 * reads the counts: four stores fewer a ray without counters (an any-hit
 * walk: any_hit, hit, found, the counts), two (a closest-hit walk: any_hit,
 * the counts). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void wide_state_init1(struct wide_state *s, const struct trace_ray *ray,
                                    float t_max, int any_hit, int stats, struct trace_hit *hit)
{
    s->ray = ray;
    s->best = t_max;
    if (!any_hit) {
        s->hit = hit;
        s->found = 0;
        s->box_limit = t_max * ISECT_BOX_FAR_SCALE; /* as wide_state_init */
    }
    if (stats) {
        s->node_tests = 0;
        s->triangle_tests = 0;
    }
}

/* The n triangles of packet p: walk_leaf's limit and hit rule; returns
 * 1 when an any-hit walk has its hit. */
/* A closest-hit walk's candidate (t, u, w of triangle prim): taken, and
 * the box limit shrunk to it, when it is the first hit or beats the best
 * by the hit rule of trace.h (closer, or as close with a lower index).
 * Returns 1 when taken.  Shared by the single-ray leaf and the packet
 * walk's (packet_take_hit). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int wide_take_closest(struct wide_state *s, uint32_t prim, float t, float u,
                                    float w)
{
    if (s->found && !(t < s->best || prim < s->hit->prim))
        return 0;
    s->found = 1;
    s->best = t;
    s->box_limit = t * ISECT_BOX_FAR_SCALE;
    s->hit->t = t;
    s->hit->u = u;
    s->hit->v = w;
    s->hit->prim = prim;
    return 1;
}

/* wide_near_refused (the two-packet leaf's refusal of its near lanes)
 * is defined with that leaf, below. */

/* tri4_before_tmin for the near lanes the any-hit filter's own checks
 * left (tri4_filter_lanes_depth with depth_out): rare (2.8 % of the
 * lanes those checks see on gears' shadow rays), so out of line. */
static unsigned wide_near_fallback(const struct wide_state *s, const struct tri4_packet *p,
                                   unsigned near) WIDE_NOINLINE;
static unsigned wide_near_fallback(const struct wide_state *s, const struct tri4_packet *p,
                                   unsigned near)
{
    return tri4_before_tmin(s->ray, p, near);
}

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int wide_packet_test(struct wide_state *s, const struct tri4_packet *p, uint32_t n,
                                   int any_hit, int early_out, int depth_out, int behind_out,
                                   int ray_double)
{
    /* An any-hit walk returns at its first hit: found stays 0. */
    float limit = !any_hit && s->found ? isect_next_up(s->best) : s->best;
    struct tri4_lanes lanes;
    unsigned mask =
        tri4_filter_lanes_depth(&s->r4, p, (1u << n) - 1u, limit, &lanes, any_hit, early_out,
                                depth_out);
    if (any_hit && mask) {
        /* A lane the ray starts on (a shadow ray from a surface: t_lo <
         * tmin) fails only on t, which the finish computes in double;
         * tri4_before_tmin refuses it in float when that is sure.  A near
         * lane whose box interval also ends before tmin (t_hi < tmin: a
         * triangle in a plane of constant kx or ky through the origin, or
         * one the ray leaves behind at once) is refused without it: the
         * finish clamps its t into the box (isect_clamp_to_box returns a
         * value at most t_hi, or t_lo) and refuses a clamped t below
         * tmin.  The kitchen's walls and boxes: 3 % of its shadow rays'
         * instructions.  With depth_out only (the single-ray walks'
         * any-hit leaves, WIDE8_LEAF_TEST below). */
        /* With depth_out the filter has made both refusals above, from
         * its registers (tri4_filter_lanes_depth: the near lanes behind
         * tmin, then those tri4_before_tmin_lanes' checks decide); the
         * near lanes left are those the checks could not decide, for
         * tri4_before_tmin. */
        /* depth_out: the walk set the scalar form (TRI4_CONST). */
        const __m128 tmin = TRI4_CONST(&s->r4, tmin, k_tmin, depth_out);
        const unsigned near =
            (unsigned)_mm_movemask_ps(_mm_cmplt_ps(_mm_loadu_ps(lanes.t_lo), tmin)) & mask;
        if (near && depth_out)
            mask &= ~wide_near_fallback(s, p, near);
        else if (near)
            mask &= ~tri4_before_tmin(s->ray, p, near);
    }
    /* The AVX2 table's closest-hit leaves: the kept lanes' finish in
     * vectors first (tri4_finish_lanes says why it is the same t); the
     * lanes it does not decide keep tri4_lane_test. */
#if TRI4_FINISH_VEC
    unsigned fast = 0, fast_ok = 0;
    float fast_t[4];
    if (ray_double && !any_hit && mask)
        fast = tri4_finish_lanes(p, &lanes, wide_ray_doubles(s), s->ray->tmin, fast_t, &fast_ok);
#endif
    while (mask) {
        const unsigned l = (unsigned)__builtin_ctz(mask);
        mask &= mask - 1u;
        /* behind_out (the single-ray closest-hit leaves): a kept lane
         * whose box interval lies wholly before tmin (t_lo and t_hi <
         * tmin) is refused without the finish.  The edge test is on the
         * ray's line, so a triangle behind the origin that the line
         * crosses passes it; when its depths straddle the origin (z_hi
         * >= tmin, which the filter tests: a wall behind a camera inside
         * a room) only the x and y slabs show that the crossing lies
         * behind.  The finish would refuse it: isect_clamp_to_box takes
         * t < t_hi ? t : t_hi, a value <= t_hi (t_hi for a NaN t), then
         * u > t_lo ? u : t_lo, so t ends as one of two values below tmin
         * and fails t >= tmin; a deferred lane's double edge step returns
         * 0 or leads to that finish.  So the same answer without the
         * finish's double-precision normal, plane distance and division:
         * the BART kitchen's camera rays finished 0.94 such lanes a ray
         * (of 2.29 finishes, 1.30 accepted); random rays 0.05.  Here, per
         * kept lane, rather than in the filter's vectors: there (two more
         * operations on the chain to the mask) gears', the soup's and
         * bumpy's camera rays were 0.01-0.04 of Embree slower. */
        if (behind_out && lanes.t_hi[l] < s->ray->tmin && lanes.t_lo[l] < s->ray->tmin)
            continue;
        float t, u, w;
        /* limit is the limit of the moment (walk_leaf's rule: s->found ?
         * next_up(s->best) : s->best), kept up to date here rather than
         * recomputed from the state each lane: s->best and s->found change
         * during the leaf only in wide_take_closest, which sets them to t
         * and 1 when it takes the hit (an any-hit leaf returns at its
         * first).  The same limit each lane; GCC reloaded s->best and
         * s->found each lane (the hit's stores may alias them). */
#if TRI4_FINISH_VEC
        if (fast >> l & 1u) {
            if (!tri4_finish_lane(&lanes, l, fast_ok, fast_t[l], limit, &t, &u, &w))
                continue;
        } else
#endif
            if (!tri4_lane_test(s->ray, ray_double ? wide_ray_doubles(s) : NULL, p, &lanes, l,
                                any_hit, limit, &t, &u, &w))
            continue;
        if (any_hit) {
            s->found = 1;
            return 1;
        }
        /* The limit after a take is needed only by a lane still to come. */
        if (wide_take_closest(s, p->prim[l], t, u, w) && mask)
            limit = isect_next_up(t);
    }
    return 0;
}

/* wide_packet_test with the filter's early return (behind_out: the
 * 4-wide single-ray walks' closest-hit leaves, walk_wide4_body). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int wide_packet_body(struct wide_state *s, const struct tri4_packet *p, uint32_t n,
                                   int any_hit, int behind_out)
{
    return wide_packet_test(s, p, n, any_hit, 1, 0, behind_out, 0);
}

/* A leaf lane: count triangles in packets from `first` (wide_packet_body
 * on each); returns 1 when an any-hit walk has its hit. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int wide_leaf_body(struct wide_state *s, const struct tri4_packet *packets,
                                 uint32_t first, uint32_t count, int any_hit, int stats,
                                 int behind_out)
{
    for (uint32_t j = 0; j < count; j += 4) {
        const struct tri4_packet *p = &packets[first + j / 4];
        const uint32_t n = count - j < 4 ? count - j : 4;
        if (stats)
            s->triangle_tests += n;
        if (wide_packet_body(s, p, n, any_hit, behind_out))
            return 1;
    }
    return 0;
}

/* wide_leaf_body with the walk's any_hit from the state. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int wide_leaf_impl(struct wide_state *s, const struct tri4_packet *packets,
                                 uint32_t first, uint32_t count, int stats)
{
    return wide_leaf_body(s, packets, first, count, s->any_hit, stats, 0);
}

/* wide_leaf_impl with the counters (the packet walk's entry). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int wide_leaf(struct wide_state *s, const struct tri4_packet *packets,
                            uint32_t first, uint32_t count)
{
    return wide_leaf_impl(s, packets, first, count, 1);
}

/* The bounds row `offset` bytes into a node's bounds (near_row,
 * far_row: byte offsets per ray, so no index scaling per node). */
static inline const float *wide_row(const void *bounds, int offset)
{
    return (const float *)(const void *)((const char *)bounds + offset);
}

/* The first three or four (`lines`) cache lines at addr requested
 * (_MM_HINT_T0): a node's bounds or a leaf's packet ahead of its test.
 * A macro, not a function: GCC's local-pure-const pass finds a function
 * of prefetches alone "looping const" and drops its calls, so a helper
 * function emitted no prefetch in any walk.  Written out, not as a loop:
 * the walks then compile as with the prefetches spelled at each place. */
#define WIDE_PREFETCH_LINES(addr, lines)                                                       \
    do {                                                                                       \
        const char *wide_pf_ = (const char *)(const void *)(addr);                             \
        _mm_prefetch(wide_pf_, _MM_HINT_T0);                                                   \
        _mm_prefetch(wide_pf_ + 64, _MM_HINT_T0);                                              \
        _mm_prefetch(wide_pf_ + 128, _MM_HINT_T0);                                             \
        if ((lines) > 3)                                                                       \
            _mm_prefetch(wide_pf_ + 192, _MM_HINT_T0);                                         \
    } while (0)

/* Forced inline, as wide_leaf: inlined into walk_wide, the state's
 * address never escapes and its fields live in registers.  The walk
 * starts at `root` (a wide node for root_count 0, else a leaf lane of
 * root_count triangles from packet `root`): 0, 0 for the whole tree; the
 * packet walk (packet_wide.h) hands a subtree to it when few of its rays
 * are left (the hybrid fallback). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int walk_wide4_body(const struct bvh4 *wide, struct wide_state *s, uint32_t root,
                                  uint32_t root_count, int any_hit, int stats, int int_entry)
{
    const struct trace_ray *ray = s->ray;
    const struct bvh4_node *nodes = wide->nodes;
    /* Per ray: which of bounds[0..5] is the near and the far plane of each
     * axis (the max for a negative direction, -0 included), and the
     * octant that picks the child order. */
    int near_row[3], far_row[3];
    int octant = 0;
    /* The origin negated, as in walk_wide8_ray: bound + (-org) is bound
     * - org bit for bit, with the bound as the addition's memory operand. */
    __m128 neg_org[3], inv[3];
    for (int k = 0; k < 3; k++) {
        int neg = signbit(ray->inv_dir[k]) != 0;
        near_row[k] = (neg ? 3 + k : k) * (int)sizeof(nodes[0].bounds[0]);
        far_row[k] = (neg ? k : 3 + k) * (int)sizeof(nodes[0].bounds[0]);
        octant |= neg << k;
        neg_org[k] = _mm_set1_ps(-ray->org[k]);
        inv[k] = _mm_set1_ps(ray->inv_dir[k]);
    }
    const __m128 tmin4 = _mm_set1_ps(ray->tmin);
    /* tmin's bits for int_entry's integer maximum (walk_wide8_ray's node
     * test): only for tmin >= 0, and -0 becomes +0, the same number. */
    const __m128i tmin4i = _mm_max_epi32(_mm_castps_si128(tmin4), _mm_setzero_si128());
    const __m128 inf4 = _mm_set1_ps(INFINITY);
    const __m128 scale4 = _mm_set1_ps(ISECT_BOX_FAR_SCALE);
    struct wide_entry stack[WIDE_STACK];
    uint32_t sp = 0;
    uint32_t cur = root;
    uint32_t cur_count = root_count;
    for (;;) {
        if (cur_count) {
            /* The closest-hit leaves refuse the lanes wholly before tmin
             * (wide_packet_test's behind_out) in the single-ray walks
             * (int_entry): the packet kernels' hybrid fallback
             * (walk_wide4_impl) compiles as before. */
            if (wide_leaf_body(s, wide->packets, cur, cur_count, any_hit, stats,
                               int_entry && !any_hit))
                return 1;
        } else {
            const struct bvh4_node *n = &nodes[cur];
            if (stats)
                s->node_tests += 4;
            __m128 t0 = tmin4;
            unsigned mask;
            if (int_entry) {
                /* walk_wide8_ray's node test on four lanes (its comment
                 * says why it is isect_box's decision bit for bit): the
                 * entry as a signed integer maximum of the bits, in a
                 * tree, and entry <= min(s * min(far x, y, z), limit) as
                 * four comparisons ANDed, instead of three dependent
                 * maxps, three minps, the scale and the clamp. */
                __m128 tn[3], tf[3];
                for (int k = 0; k < 3; k++) {
                    tn[k] = _mm_mul_ps(
                        _mm_add_ps(neg_org[k], _mm_load_ps(wide_row(n->bounds, near_row[k]))),
                        inv[k]);
                    tf[k] = _mm_mul_ps(
                        _mm_add_ps(neg_org[k], _mm_load_ps(wide_row(n->bounds, far_row[k]))),
                        inv[k]);
                }
                t0 = _mm_castsi128_ps(_mm_max_epi32(
                    _mm_max_epi32(_mm_castps_si128(tn[0]), _mm_castps_si128(tn[1])),
                    _mm_max_epi32(_mm_castps_si128(tn[2]), tmin4i)));
                const __m128 hit = _mm_and_ps(
                    _mm_and_ps(_mm_cmple_ps(t0, _mm_set1_ps(s->box_limit)),
                               _mm_cmpngt_ps(t0, _mm_mul_ps(tf[0], scale4))),
                    _mm_and_ps(_mm_cmpngt_ps(t0, _mm_mul_ps(tf[1], scale4)),
                               _mm_cmpngt_ps(t0, _mm_mul_ps(tf[2], scale4))));
                mask = (unsigned)_mm_movemask_ps(hit);
            } else {
                __m128 t1 = inf4;
                for (int k = 0; k < 3; k++) {
                    const __m128 tn = _mm_mul_ps(
                        _mm_add_ps(neg_org[k], _mm_load_ps(wide_row(n->bounds, near_row[k]))),
                        inv[k]);
                    const __m128 tf = _mm_mul_ps(
                        _mm_add_ps(neg_org[k], _mm_load_ps(wide_row(n->bounds, far_row[k]))),
                        inv[k]);
                    t0 = _mm_max_ps(tn, t0);
                    t1 = _mm_min_ps(tf, t1);
                }
                t1 = _mm_mul_ps(t1, scale4);
                t1 = _mm_min_ps(t1, _mm_set1_ps(s->box_limit));
                mask = (unsigned)_mm_movemask_ps(_mm_cmple_ps(t0, t1));
            }
            if (mask) {
                if (!(mask & (mask - 1u))) {
                    const unsigned l = (unsigned)__builtin_ctz(mask);
                    cur = n->child[l];
                    cur_count = n->count[l];
                } else {
                    float te[4];
                    _mm_storeu_ps(te, t0);
                    /* Push the hit children back to front in the
                     * octant's order, then take the front one. */
                    /* An any-hit walk: the stored order, lane 0 first
                     * (wide8_push_stored says why). */
                    const unsigned order = any_hit ? 0xE4u : n->order[octant];
                    /* Every lane is written, a missed one where the
                     * next hit one will overwrite it: no branch on the
                     * mask (the stack has room for the last writes). */
                    for (int p = 3; p >= 0; p--) {
                        const unsigned l = order >> (2 * p) & 3u;
                        stack[sp].child = n->child[l];
                        stack[sp].count = n->count[l];
                        stack[sp].t_entry = te[l];
                        sp += mask >> l & 1u;
                    }
                    sp--;
                    cur = stack[sp].child;
                    cur_count = stack[sp].count;
                }
                continue;
            }
        }
        for (;;) {
            if (sp == 0)
                return 0;
            sp--;
            /* As in walk_wide8_impl: an any-hit walk's box_limit never
             * shrinks. */
            if (any_hit || stack[sp].t_entry <= s->box_limit)
                break;
        }
        cur = stack[sp].child;
        cur_count = stack[sp].count;
    }
}

/* walk_wide4_body with the walk's any_hit from the state. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int walk_wide4_impl(const struct bvh4 *wide, struct wide_state *s, uint32_t root,
                                  uint32_t root_count, int stats)
{
    return walk_wide4_body(wide, s, root, root_count, s->any_hit, stats, 0);
}

/* walk_wide4_impl counting node and triangle tests (the packet walk's
 * hybrid fallback, packet_wide.h). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int walk_wide4(const struct bvh4 *wide, struct wide_state *s, uint32_t root,
                             uint32_t root_count)
{
    return walk_wide4_impl(wide, s, root, root_count, 1);
}

#if defined(__AVX__)
/* The 8 floats `off` bytes into a node (walk_wide8_ray's row offsets). */
static inline __m256 wide8_bound(const char *b, size_t off)
{
    return _mm256_load_ps((const float *)(const void *)(b + off));
}
/* The any-hit walk from the set-up's lanes addresses a node's bounds
 * from the array's start plus the node's byte offset (walk_wide8_ray):
 * the bounds must open the node. */
typedef char bvh8_node_bounds_first[offsetof(struct bvh8_node, bounds) == 0 ? 1 : -1];

/* wide8_compress[m]: the bit positions set in m, highest first, one per
 * byte from the low byte (the rest 0): the left-packing permutation of
 * walk_wide8_impl's push, one 8-byte load instead of a loop. */
static const uint64_t wide8_compress[256] = {
    0x0000000000000000u, 0x0000000000000000u, 0x0000000000000001u, 0x0000000000000001u,
    0x0000000000000002u, 0x0000000000000002u, 0x0000000000000102u, 0x0000000000000102u,
    0x0000000000000003u, 0x0000000000000003u, 0x0000000000000103u, 0x0000000000000103u,
    0x0000000000000203u, 0x0000000000000203u, 0x0000000000010203u, 0x0000000000010203u,
    0x0000000000000004u, 0x0000000000000004u, 0x0000000000000104u, 0x0000000000000104u,
    0x0000000000000204u, 0x0000000000000204u, 0x0000000000010204u, 0x0000000000010204u,
    0x0000000000000304u, 0x0000000000000304u, 0x0000000000010304u, 0x0000000000010304u,
    0x0000000000020304u, 0x0000000000020304u, 0x0000000001020304u, 0x0000000001020304u,
    0x0000000000000005u, 0x0000000000000005u, 0x0000000000000105u, 0x0000000000000105u,
    0x0000000000000205u, 0x0000000000000205u, 0x0000000000010205u, 0x0000000000010205u,
    0x0000000000000305u, 0x0000000000000305u, 0x0000000000010305u, 0x0000000000010305u,
    0x0000000000020305u, 0x0000000000020305u, 0x0000000001020305u, 0x0000000001020305u,
    0x0000000000000405u, 0x0000000000000405u, 0x0000000000010405u, 0x0000000000010405u,
    0x0000000000020405u, 0x0000000000020405u, 0x0000000001020405u, 0x0000000001020405u,
    0x0000000000030405u, 0x0000000000030405u, 0x0000000001030405u, 0x0000000001030405u,
    0x0000000002030405u, 0x0000000002030405u, 0x0000000102030405u, 0x0000000102030405u,
    0x0000000000000006u, 0x0000000000000006u, 0x0000000000000106u, 0x0000000000000106u,
    0x0000000000000206u, 0x0000000000000206u, 0x0000000000010206u, 0x0000000000010206u,
    0x0000000000000306u, 0x0000000000000306u, 0x0000000000010306u, 0x0000000000010306u,
    0x0000000000020306u, 0x0000000000020306u, 0x0000000001020306u, 0x0000000001020306u,
    0x0000000000000406u, 0x0000000000000406u, 0x0000000000010406u, 0x0000000000010406u,
    0x0000000000020406u, 0x0000000000020406u, 0x0000000001020406u, 0x0000000001020406u,
    0x0000000000030406u, 0x0000000000030406u, 0x0000000001030406u, 0x0000000001030406u,
    0x0000000002030406u, 0x0000000002030406u, 0x0000000102030406u, 0x0000000102030406u,
    0x0000000000000506u, 0x0000000000000506u, 0x0000000000010506u, 0x0000000000010506u,
    0x0000000000020506u, 0x0000000000020506u, 0x0000000001020506u, 0x0000000001020506u,
    0x0000000000030506u, 0x0000000000030506u, 0x0000000001030506u, 0x0000000001030506u,
    0x0000000002030506u, 0x0000000002030506u, 0x0000000102030506u, 0x0000000102030506u,
    0x0000000000040506u, 0x0000000000040506u, 0x0000000001040506u, 0x0000000001040506u,
    0x0000000002040506u, 0x0000000002040506u, 0x0000000102040506u, 0x0000000102040506u,
    0x0000000003040506u, 0x0000000003040506u, 0x0000000103040506u, 0x0000000103040506u,
    0x0000000203040506u, 0x0000000203040506u, 0x0000010203040506u, 0x0000010203040506u,
    0x0000000000000007u, 0x0000000000000007u, 0x0000000000000107u, 0x0000000000000107u,
    0x0000000000000207u, 0x0000000000000207u, 0x0000000000010207u, 0x0000000000010207u,
    0x0000000000000307u, 0x0000000000000307u, 0x0000000000010307u, 0x0000000000010307u,
    0x0000000000020307u, 0x0000000000020307u, 0x0000000001020307u, 0x0000000001020307u,
    0x0000000000000407u, 0x0000000000000407u, 0x0000000000010407u, 0x0000000000010407u,
    0x0000000000020407u, 0x0000000000020407u, 0x0000000001020407u, 0x0000000001020407u,
    0x0000000000030407u, 0x0000000000030407u, 0x0000000001030407u, 0x0000000001030407u,
    0x0000000002030407u, 0x0000000002030407u, 0x0000000102030407u, 0x0000000102030407u,
    0x0000000000000507u, 0x0000000000000507u, 0x0000000000010507u, 0x0000000000010507u,
    0x0000000000020507u, 0x0000000000020507u, 0x0000000001020507u, 0x0000000001020507u,
    0x0000000000030507u, 0x0000000000030507u, 0x0000000001030507u, 0x0000000001030507u,
    0x0000000002030507u, 0x0000000002030507u, 0x0000000102030507u, 0x0000000102030507u,
    0x0000000000040507u, 0x0000000000040507u, 0x0000000001040507u, 0x0000000001040507u,
    0x0000000002040507u, 0x0000000002040507u, 0x0000000102040507u, 0x0000000102040507u,
    0x0000000003040507u, 0x0000000003040507u, 0x0000000103040507u, 0x0000000103040507u,
    0x0000000203040507u, 0x0000000203040507u, 0x0000010203040507u, 0x0000010203040507u,
    0x0000000000000607u, 0x0000000000000607u, 0x0000000000010607u, 0x0000000000010607u,
    0x0000000000020607u, 0x0000000000020607u, 0x0000000001020607u, 0x0000000001020607u,
    0x0000000000030607u, 0x0000000000030607u, 0x0000000001030607u, 0x0000000001030607u,
    0x0000000002030607u, 0x0000000002030607u, 0x0000000102030607u, 0x0000000102030607u,
    0x0000000000040607u, 0x0000000000040607u, 0x0000000001040607u, 0x0000000001040607u,
    0x0000000002040607u, 0x0000000002040607u, 0x0000000102040607u, 0x0000000102040607u,
    0x0000000003040607u, 0x0000000003040607u, 0x0000000103040607u, 0x0000000103040607u,
    0x0000000203040607u, 0x0000000203040607u, 0x0000010203040607u, 0x0000010203040607u,
    0x0000000000050607u, 0x0000000000050607u, 0x0000000001050607u, 0x0000000001050607u,
    0x0000000002050607u, 0x0000000002050607u, 0x0000000102050607u, 0x0000000102050607u,
    0x0000000003050607u, 0x0000000003050607u, 0x0000000103050607u, 0x0000000103050607u,
    0x0000000203050607u, 0x0000000203050607u, 0x0000010203050607u, 0x0000010203050607u,
    0x0000000004050607u, 0x0000000004050607u, 0x0000000104050607u, 0x0000000104050607u,
    0x0000000204050607u, 0x0000000204050607u, 0x0000010204050607u, 0x0000010204050607u,
    0x0000000304050607u, 0x0000000304050607u, 0x0000010304050607u, 0x0000010304050607u,
    0x0000020304050607u, 0x0000020304050607u, 0x0001020304050607u, 0x0001020304050607u,
};

/* The stack write of wide8_push and wide8_push_stored: the lanes
 * `gather` picks (children's words, counts and entry distances) into
 * consecutive slots from *sp, all hit lanes but the front one, which the
 * caller continues with. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void wide8_store(const struct bvh8_node *n, __m256i gather, __m256 t0,
                               unsigned pm, uint32_t *st_child, uint32_t *st_count, float *st_t,
                               uint32_t *sp)
{
    const __m256i child = _mm256_load_si256((const __m256i *)(const void *)n->child);
    const __m256i count =
        _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)n->count));
    _mm256_storeu_si256((__m256i *)(void *)&st_child[*sp],
                        _mm256_permutevar8x32_epi32(child, gather));
    _mm256_storeu_si256((__m256i *)(void *)&st_count[*sp],
                        _mm256_permutevar8x32_epi32(count, gather));
    /* An any-hit walk's pushes pass st_t NULL (wide8_push_stored): a
     * constant in each inlined copy, so no test is left. */
    if (st_t)
        _mm256_storeu_ps(&st_t[*sp], _mm256_permutevar8x32_ps(t0, gather));
    *sp += (uint32_t)__builtin_popcount(pm) - 1u;
}

/*
 * A node with two or more hit children: push all but the front one back
 * to front in the octant's order and return the front one (its child
 * word in *cur, its count in *cur_count), without a loop over the lanes.
 * lanes[p]: the lane at position p of the order (position 0 the front);
 * pm: the positions hit; wide8_compress[pm]: those positions back to
 * front, one byte each, which gather the children's words and entry
 * distances into consecutive stack slots (the slots beyond them are
 * written too, and overwritten later: the stack has room).  The entry
 * distances are stored here (closest hit) and not by wide8_push_stored
 * (any hit, whose pops never read them).  Inlined: the walks keep their
 * state in registers around it.  wide8_order_lanes (lanes and the order
 * word) and wide8_store_ordered (the pushes) are shared with
 * wide8_push_compress.
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline __m256i wide8_order_lanes(const struct bvh8_node *n, int octant,
                                        __m256i order_shift, uint32_t *order_out)
{
    /* The octant's three order bytes as one little-endian word: the four
     * bytes ending with them (the first is the last count byte or the
     * previous octant's last order byte, inside the node), shifted down;
     * one load instead of three and two shifts and ors. */
    uint32_t word;
    memcpy(&word, (const char *)n->order[octant] - 1, sizeof(word));
    *order_out = word >> 8;
    /* Position p's lane in bits 0-2 of lanes[p], the higher bits those of
     * the positions after it: not masked off, as every use of lanes is an
     * index of an eight-lane permutation (vpermps, vpermd), which reads
     * the index's low three bits only. */
    return _mm256_srlv_epi32(_mm256_set1_epi32((int)*order_out), order_shift);
}

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void wide8_store_ordered(const struct bvh8_node *n, __m256i lanes, unsigned pm,
                                       __m256 t0, uint32_t *st_child, uint32_t *st_count,
                                       float *st_t, uint32_t *sp)
{
    const __m128i packed = _mm_loadl_epi64((const __m128i *)(const void *)&wide8_compress[pm]);
    const __m256i gather = _mm256_permutevar8x32_epi32(lanes, _mm256_cvtepu8_epi32(packed));
    wide8_store(n, gather, t0, pm, st_child, st_count, st_t, sp);
}

/* wide8_push's work, also returning the hit lanes' mask in the octant's
 * order (bit i: the i-th child front to back was hit) and that order in
 * *order, for a caller that wants more than the front child (the
 * stream's pair8_push). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned wide8_push_order(const struct bvh8_node *n, int octant, __m256 hit,
                                        __m256 t0, __m256i order_shift, uint32_t *st_child,
                                        uint32_t *st_count, float *st_t, uint32_t *sp,
                                        uint32_t *cur, uint32_t *cur_count, uint32_t *order)
{
    const __m256i lanes = wide8_order_lanes(n, octant, order_shift, order);
    const unsigned pm = (unsigned)_mm256_movemask_ps(_mm256_permutevar8x32_ps(hit, lanes));
    wide8_store_ordered(n, lanes, pm, t0, st_child, st_count, st_t, sp);
    const unsigned l = *order >> (3 * (unsigned)__builtin_ctz(pm)) & 7u;
    *cur = n->child[l];
    *cur_count = n->count[l];
    return pm;
}

/* The closest-hit push in the octant's order: the hit children stored
 * back to front, the front one taken as the current entry. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void wide8_push(const struct bvh8_node *n, int octant, __m256 hit, __m256 t0,
                              __m256i order_shift, uint32_t *st_child, uint32_t *st_count,
                              float *st_t, uint32_t *sp, uint32_t *cur, uint32_t *cur_count)
{
    uint32_t order;
    wide8_push_order(n, octant, hit, t0, order_shift, st_child, st_count, st_t, sp, cur,
                     cur_count, &order);
}

/* wide8_push_stored's gather: the hit lanes highest first. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline __m256i wide8_gather_stored(unsigned pm)
{
    return _mm256_cvtepu8_epi32(
        _mm_loadl_epi64((const __m128i *)(const void *)&wide8_compress[pm]));
}

#if TRACE_AVX512_TABLE
/*
 * The node's eight child words as byte offsets into the nodes' array
 * (child * 256: bvh4_layout.h asserts a bvh8_node's 256 bytes), shifted
 * while the node test runs (their address does not wait for the mask),
 * so that the front child compressed out of them
 * (wide8_front_compress, wide8_push_compress) is the next node's offset
 * itself, one address operand with a row's base, without the shift the
 * child word needed after its compression.  Within 32-bit lanes: exact
 * for indices below 2^24, which WIDE8_WALK1_FAR sends every larger layout
 * around.  (In 64-bit lanes, a zmm register, the walks were 0.05-0.2 of
 * Embree slower on this project's Xeon: performance-log.md, round 48.)
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline __m256i wide8_child_offsets(__m256i child)
{
    return _mm256_slli_epi32(child, 8);
}

/*
 * The front child of a walk in the stored order (the lowest hit lane, as
 * wide8_push_stored takes it, and a node's only hit child in any walk)
 * from the node test's mask register: the node's child offsets
 * (wide8_child_offsets) and counts compressed by the mask, lane 0 of
 * each.  Without the mask's move to a general register, its trailing-zero
 * count and the child's load after them, which the next node's loads
 * waited for.  *cur_off: the child's byte offset in the nodes' array (the
 * walk's leaf takes its packet index as cur_off >> 8).  The same child and
 * count, so the same walk.
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void wide8_front_compress(const struct bvh8_node *n, __mmask8 k, size_t *cur_off,
                                        uint32_t *cur_count)
{
    const __m256i off =
        wide8_child_offsets(_mm256_load_si256((const __m256i *)(const void *)n->child));
    const __m256i count =
        _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)n->count));
    *cur_off = (uint32_t)_mm256_cvtsi256_si32(_mm256_maskz_compress_epi32(k, off));
    *cur_count = (uint32_t)_mm256_cvtsi256_si32(_mm256_maskz_compress_epi32(k, count));
}
#endif

#if TRACE_AVX512_TABLE
/*
 * wide8_push with the front child taken by compression (AVX-512): the
 * node's child words and counts permuted into the octant's order (lanes:
 * their loads and the permutation wait for the node and the order word,
 * not for the node test), then compressed by the hit lanes in that order
 * (a mask register from the permuted hit vector), lane 0 of each.  That is
 * the hit child at the lowest position of the order, the one wide8_push
 * takes by the trailing-zero count of the positions' movemask, the shift
 * of the order word and the child's load after them; so the next node's
 * address waits on vpermps -> vpmovd2m -> vpcompressd -> vmovd instead of
 * vpermps -> vmovmskps -> tzcnt -> lea -> shrx -> and -> load.  The child
 * comes out as its byte offset (*cur_off, wide8_child_offsets, from the
 * permuted words).  The pushes are wide8_push's (wide8_store_ordered).
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void wide8_push_compress(const struct bvh8_node *n, int octant, __m256 hit,
                                       __m256 t0, __m256i order_shift, uint32_t *st_child,
                                       uint32_t *st_count, float *st_t, uint32_t *sp,
                                       size_t *cur_off, uint32_t *cur_count)
{
    uint32_t order;
    const __m256i lanes = wide8_order_lanes(n, octant, order_shift, &order);
    const __m256 hit_ord = _mm256_permutevar8x32_ps(hit, lanes);
    const unsigned pm = (unsigned)_mm256_movemask_ps(hit_ord);
    const __mmask8 km = _mm256_movepi32_mask(_mm256_castps_si256(hit_ord));
    wide8_store_ordered(n, lanes, pm, t0, st_child, st_count, st_t, sp);
    const __m256i child = _mm256_load_si256((const __m256i *)(const void *)n->child);
    const __m256i count =
        _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)n->count));
    const __m256i off = wide8_child_offsets(_mm256_permutevar8x32_epi32(child, lanes));
    *cur_off = (uint32_t)_mm256_cvtsi256_si32(_mm256_maskz_compress_epi32(km, off));
    *cur_count = (uint32_t)_mm256_cvtsi256_si32(
        _mm256_maskz_compress_epi32(km, _mm256_permutevar8x32_epi32(count, lanes)));
}
#endif

/*
 * wide8_push for an any-hit walk: the hit children in the node's stored
 * order (lowest lane first), not the octant's.  pm: the hit lanes' mask
 * as the node test has it (on AVX-512 a mask register's: no round trip
 * through a vector and a movemask before the next child is known).  An
 * any-hit walk ends at its first hit and, until then, visits every box
 * its interval reaches whatever the order (its box limit never shrinks),
 * so the order changes only how soon an occluded ray stops, never the
 * answer; nearest-first buys little there (SATO, Nah and Manocha 2014,
 * orders any-hit children by surface area instead), and the stored order
 * saves the octant's permutation (about a dozen instructions per push).
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void wide8_push_stored(const struct bvh8_node *n, unsigned pm, __m256 t0,
                                     uint32_t *st_child, uint32_t *st_count, uint32_t *sp,
                                     uint32_t *cur, uint32_t *cur_count)
{
    const __m256i gather = wide8_gather_stored(pm);
    /* No entry distances: an any-hit walk's pops never read them (its box
     * limit never shrinks), so the permutation and the store of the
     * distances are left out (two instructions a push). */
    wide8_store(n, gather, t0, pm, st_child, st_count, NULL, sp);
    const unsigned l = (unsigned)__builtin_ctz(pm);
    *cur = n->child[l];
    *cur_count = n->count[l];
}

/* any_hit's value for the 8-wide single-ray walk's copies that order an
 * any-hit push by wide8_push_any (the layouts with any_longest); 1: the
 * stored order (wide8_push_stored).  Any non-zero any_hit is an any-hit
 * walk everywhere else. */
#define WIDE_ANY_LONGEST 2

/*
 * The child an any-hit walk goes to first when a node has two or more
 * hit children: the one where the ray's segment inside the box, exit -
 * entry, is longest; lowest lane on a tie.
 *
 * Why: for triangles spread through a box (a volume of them, the soup),
 * the expected number a ray crosses grows with the length of the ray
 * inside the box (the argument of the surface-area heuristic's ray
 * distribution, MacDonald and Booth 1990, sec. 3, applied to one ray),
 * so the longest segment is the likeliest to end an occluded ray soonest.
 * Embree's occluded walk goes on with its last hit lane (it orders by
 * nothing); SATO (Nah and Manocha 2014) orders any-hit children by their
 * boxes' surface area at build time.  Counted per shadow ray (rtbench
 * embree, node lanes / triangles; round 39, sr6's rules): the soup 83.5 /
 * 19.4 in the stored order, 71.3 / 16.0 with the box holding the ray's
 * start last (rule 28), 64.5 / 15.4 with it treated as any other (rule
 * 25, this one); AVX2 instructions a soup shadow ray (callgrind) 1582.0,
 * 1412.8, 1315.2.  On the surfaces measured it pays less than it costs:
 * the kitchen 41.4 / 7.24 -> 41.8 / 7.38 (its occluders lie near the
 * start, but not in the start's own box), gears 39.4 / 9.07 -> 39.0 /
 * 8.88, for the reduction's instructions and latency at every push
 * (sr6: slower on the clock in every pair), so only the layouts with
 * any_longest (bvh4_layout.h) take it: the walk's copy is chosen per
 * layout (WIDE_ANY_LONGEST), and the other layouts' walk is the stored
 * order's as before, without a test.
 *
 * The key of a lane: the segment's bits with the low four replaced by 8
 * and 7 - lane (a tie within 16 ulps goes to the lowest lane); missed
 * lanes 0.  Exit and entry are never NaN here (t0 is an integer maximum
 * with tmin's non-negative bits, t1 a minimum whose NaN operands give
 * way, WIDE8_RAY), and a hit lane has entry <= exit, but both may be
 * +inf (a zero direction component, with t_max infinite), and inf - inf
 * is NaN, whose default bits (sign set) are a negative integer: the
 * segment's bits are clamped at 0, so that a hit lane's key is always 8
 * or more and the front lane a hit one (unclamped, such a node sent the
 * walk to a missed lane's child: conformance/internal/kernel_bits).
 * Otherwise the segment is a non-negative float, whose bits order as the
 * floats do; the integer maximum names the lane.
 * Which child comes first changes only how soon an occluded ray stops:
 * the walk still pushes every other hit child and visits every box its
 * interval reaches until its first hit (its box limit never shrinks), so
 * the answer (occluded or not) is the same in any order.  Even a front
 * lane that missed would only add a visit: every hit lane but the front
 * one is pushed (wide8_push_any counts the pushed lanes, not the hits).
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned wide8_any_front(__m256 t0, __m256 t1, __m256 hit)
{
    /* The segment's bits, those of a negative number or NaN as 0 (its
     * lane then ranks by lane alone, still above every missed lane). */
    const __m256i seg = _mm256_max_epi32(_mm256_castps_si256(_mm256_sub_ps(t1, t0)),
                                         _mm256_setzero_si256());
    __m256i key =
        _mm256_or_si256(_mm256_and_si256(seg, _mm256_set1_epi32(~15)), _mm256_set1_epi32(8));
    key = _mm256_and_si256(_mm256_or_si256(key, _mm256_setr_epi32(7, 6, 5, 4, 3, 2, 1, 0)),
                           _mm256_castps_si256(hit));
    __m128i k = _mm_max_epi32(_mm256_castsi256_si128(key), _mm256_extracti128_si256(key, 1));
    k = _mm_max_epi32(k, _mm_shuffle_epi32(k, 0x4E));
    k = _mm_max_epi32(k, _mm_shuffle_epi32(k, 0xB1));
    return 7u - ((unsigned)_mm_cvtsi128_si32(k) & 7u);
}

/*
 * wide8_push for an any-hit walk on a layout with any_longest:
 * wide8_any_front's lane next, the other hit lanes pushed in the node's
 * stored order (lowest lane on top).  pm: the hit lanes' mask as the
 * node test has it (two or more lanes); hit: the same lanes as a vector;
 * t1: the scaled exits clamped to the box limit.  No entry distances: an
 * any-hit walk's pops never read them (its box limit never shrinks).
 * (Rule 28's form, the start's box last with the reduction only where
 * two or more lanes lie beyond the start, round 39's v4, was slower on
 * the soup's clock: 0.92-0.93 of Embree against 0.99.)
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void wide8_push_any(const struct bvh8_node *n, unsigned pm, __m256 hit, __m256 t0,
                                  __m256 t1, uint32_t *st_child, uint32_t *st_count, uint32_t *sp,
                                  uint32_t *cur, uint32_t *cur_count)
{
    const unsigned front = wide8_any_front(t0, t1, hit);
    const unsigned rest = pm & ~(1u << front);
    /* wide8_compress[rest]: the rest's lanes back to front, so that the
     * lowest ends on top; all of them kept (sp moves by their number).
     * The stores are wide8_store's with st_t NULL (popcount(rest) is
     * popcount(pm) - 1), written out: with the call GCC schedules these
     * walks differently (1,825 lines of their objdump differ) and the
     * soup's figures were measured on this form (performance-log.md,
     * round 40's merge). */
    const __m256i gather = _mm256_cvtepu8_epi32(
        _mm_loadl_epi64((const __m128i *)(const void *)&wide8_compress[rest]));
    const __m256i child = _mm256_load_si256((const __m256i *)(const void *)n->child);
    const __m256i count =
        _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)n->count));
    _mm256_storeu_si256((__m256i *)(void *)&st_child[*sp],
                        _mm256_permutevar8x32_epi32(child, gather));
    _mm256_storeu_si256((__m256i *)(void *)&st_count[*sp],
                        _mm256_permutevar8x32_epi32(count, gather));
    *sp += (uint32_t)__builtin_popcount(rest);
    *cur = n->child[front];
    *cur_count = n->count[front];
}

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int walk_wide8_impl(const struct bvh4 *wide, struct wide_state *s, uint32_t root,
                                  uint32_t root_count, int stats)
{
    const struct trace_ray *ray = s->ray;
    const struct bvh8_node *nodes = wide->nodes8;
    int near_row[3], far_row[3];
    int octant = 0;
    __m256 neg_org[3], inv[3]; /* -org: as in walk_wide8_ray */
    for (int k = 0; k < 3; k++) {
        int neg = signbit(ray->inv_dir[k]) != 0;
        near_row[k] = (neg ? 3 + k : k) * (int)sizeof(nodes[0].bounds[0]);
        far_row[k] = (neg ? k : 3 + k) * (int)sizeof(nodes[0].bounds[0]);
        octant |= neg << k;
        neg_org[k] = _mm256_set1_ps(-ray->org[k]);
        inv[k] = _mm256_set1_ps(ray->inv_dir[k]);
    }
    const __m256 tmin8 = _mm256_set1_ps(ray->tmin);
    const __m256 inf8 = _mm256_set1_ps(INFINITY);
    const __m256 scale8 = _mm256_set1_ps(ISECT_BOX_FAR_SCALE);
    const __m256i order_shift = _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21);
    /* The stack as three arrays, so that one node's hit children are
     * pushed with one vector store per field (wide8_push). */
    uint32_t st_child[WIDE_STACK];
    uint32_t st_count[WIDE_STACK];
    float st_t[WIDE_STACK];
    uint32_t sp = 0;
    uint32_t cur = root;
    uint32_t cur_count = root_count;
    for (;;) {
        if (cur_count) {
            if (wide_leaf_impl(s, wide->packets, cur, cur_count, stats))
                return 1;
        } else {
            const struct bvh8_node *n = &nodes[cur];
            if (stats)
                s->node_tests += 8;
            __m256 t0 = tmin8;
            __m256 t1 = inf8;
            for (int k = 0; k < 3; k++) {
                const __m256 tn = _mm256_mul_ps(
                    _mm256_add_ps(neg_org[k], _mm256_load_ps(wide_row(n->bounds, near_row[k]))),
                    inv[k]);
                const __m256 tf = _mm256_mul_ps(
                    _mm256_add_ps(neg_org[k], _mm256_load_ps(wide_row(n->bounds, far_row[k]))),
                    inv[k]);
                t0 = _mm256_max_ps(tn, t0);
                t1 = _mm256_min_ps(tf, t1);
            }
            t1 = _mm256_mul_ps(t1, scale8);
            t1 = _mm256_min_ps(t1, _mm256_set1_ps(s->box_limit));
            const __m256 hit = _mm256_cmp_ps(t0, t1, _CMP_LE_OQ);
            unsigned mask = (unsigned)_mm256_movemask_ps(hit);
            if (mask) {
                if (!(mask & (mask - 1u))) {
                    const unsigned l = (unsigned)__builtin_ctz(mask);
                    cur = n->child[l];
                    cur_count = n->count[l];
                } else {
                    wide8_push(n, octant, hit, t0, order_shift, st_child, st_count, st_t,
                               &sp, &cur, &cur_count);
                }
                continue;
            }
        }
        for (;;) {
            if (sp == 0)
                return 0;
            sp--;
            /* An any-hit walk ends at its first hit, so its box_limit
             * never shrinks and every pushed child (entry <= exit <=
             * box_limit) passes: neither the entry distance nor the
             * test is needed. */
            if (s->any_hit || st_t[sp] <= s->box_limit)
                break;
        }
        cur = st_child[sp];
        cur_count = st_count[sp];
    }
}

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int walk_wide8(const struct bvh4 *wide, struct wide_state *s, uint32_t root,
                             uint32_t root_count)
{
    return walk_wide8_impl(wide, s, root, root_count, 1);
}

/*
 * The single-ray 8-wide walk (walk_wide's): the same box tests, visit
 * order, pushes and pops as walk_wide8_impl from the root (so the same
 * answers and the same node and triangle counts), arranged for the
 * register allocator, which inlined into one loop with the leaf kept
 * the row offsets and the ray's vectors on the stack and reloaded them
 * at every node:
 * - each leaf packet is a call (wide8_packet_*), not inlined; every
 *   vector register is the callee's to clobber across a call (System V
 *   x86-64 ABI), so the walk broadcasts the ray's vectors again after
 *   the leaf, once per leaf visit;
 * - the node test runs in an inner loop without calls, which leaves it
 *   the registers for the six row offsets, origin and inverse;
 * - the row offsets are pointer-sized (no sign extension per load);
 * - any_hit, stats and leave_early (the packet filter's early return,
 *   WIDE8_WALK's copies say when) are compile-time constants of each
 *   copy, and each copy is its own function with its own stack, which
 *   also sets up the ray's state (walk_wide no longer pays for four
 *   inlined walks' frames and a second copy of the packet test's
 *   constants).
 */
/* depth_out: the any-hit leaves' extra refusals (the filter's second
 * early return on depth, tri4_filter_lanes_depth, and the near lanes
 * behind tmin, wide_packet_test); only the single-ray any-hit leaves
 * take them, so that the closest-hit leaves, the packet kernels and the
 * 4-wide walks compile as before. */
/* behind_out: the closest-hit leaves' refusal of the kept lanes wholly
 * before tmin (wide_packet_test says why it is exact); only the
 * single-ray closest-hit leaves take it.  The any-hit leaves refuse
 * those lanes with depth_out (wide_packet_test's near lanes). */
/* ray_double: s is a struct wide_ray_state's, and the finish takes the
 * ray's origin and direction in double from its d_org_dir (set at a
 * ray's first leaf: walk_wide8_ray, TRACE_WIDE_LEAF8) instead of
 * converting them each finish: the same doubles (intersect.h,
 * isect_triangle_finish_impl). */
#define WIDE8_LEAF_TEST(name, test, any_hit, early_out, depth_out, behind_out, ray_double)       \
    static int name(struct wide_state *s, const struct tri4_packet *p, uint32_t n) WIDE_NOINLINE; \
    static int name(struct wide_state *s, const struct tri4_packet *p, uint32_t n)                \
    {                                                                                              \
        return test(s, p, n, any_hit, early_out, depth_out, behind_out, ray_double);               \
    }

WIDE8_LEAF_TEST(wide8_packet_closest, wide_packet_test, 0, 1, 0, 1, 1)
WIDE8_LEAF_TEST(wide8_packet_full, wide_packet_test, 0, 0, 0, 1, 1)
WIDE8_LEAF_TEST(wide8_packet_any, wide_packet_test, 1, 1, 1, 0, 0)

/* The byte offsets of the near x, y, z and far x, y, z rows of a
 * bvh8_node's bounds per ray octant (bit k: dir[k] negative, whose near
 * plane is then the max, row 3 + k): walk_wide8_ray's arithmetic on the
 * sign bits, as a table for the walks from the set-up's lanes. */
#define WIDE8_ROW (sizeof(((const struct bvh8_node *)NULL)->bounds[0]))
#define WIDE8_ROWS(nx, ny, nz)                                                                   \
    {(nx)*3 * WIDE8_ROW, (1 + (ny)*3) * WIDE8_ROW, (2 + (nz)*3) * WIDE8_ROW,                     \
     (3 - (nx)*3) * WIDE8_ROW, (4 - (ny)*3) * WIDE8_ROW, (5 - (nz)*3) * WIDE8_ROW}
static const uint8_t wide8_rows[8][6] = {WIDE8_ROWS(0, 0, 0), WIDE8_ROWS(1, 0, 0),
                                         WIDE8_ROWS(0, 1, 0), WIDE8_ROWS(1, 1, 0),
                                         WIDE8_ROWS(0, 0, 1), WIDE8_ROWS(1, 0, 1),
                                         WIDE8_ROWS(0, 1, 1), WIDE8_ROWS(1, 1, 1)};
#undef WIDE8_ROWS
#undef WIDE8_ROW

/* off_x .. neg_y of struct tri4_ray in one store (tri4_ray_init_scalar_lanes
 * says how) from inv_k (inv_dir in kx, ky, kz order) and order (kx, ky,
 * kz as lane indices; lane 3 is replaced by the blend): the set-up's
 * lanes or, at a closest-hit ray's first leaf, tri4_ray_init_vec's. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void tri4_ray_init_offsets(struct tri4_ray *r, __m128 inv_k, __m128i order)
{
    const __m128i neg01 = _mm_srli_epi32(
        _mm_castps_si128(_mm_cmplt_ps(inv_k, _mm_setzero_ps())), 31); /* nx, ny, nz, 0 */
    const __m256i offs = _mm256_cvtepu32_epi64(_mm_slli_epi32(order, 4));
    const __m256i block = _mm256_blend_epi32(
        offs, _mm256_inserti128_si256(_mm256_setzero_si256(), _mm_slli_si128(neg01, 8), 1), 0xC0);
    _mm256_storeu_si256((__m256i *)(void *)((char *)(void *)r + offsetof(struct tri4_ray, off_x)),
                        block);
}

/* tri4_ray_init in vectors (AVX2), for the 8-wide closest-hit walks at a
 * ray's first leaf: the same floats in the same fields, where
 * tri4_ray_init loads kx, ky and kz and then each float by an index.
 * kx, ky, kz are consecutive ints of struct trace_ray, loaded as one
 * vector of lane indices (lane 3, sx's bits, is not used); org and
 * inv_dir are each followed by another float in the struct, so each is
 * one 16-byte load, permuted into kx, ky, kz order.  -org by the sign bit
 * (C's unary minus), inv_dir[kx] < 0 by a comparison of the same float,
 * sx, sy, sz and tmin broadcast from the struct. */
#if defined(__AVX2__)
typedef char tri4_ray_init_vec_layout
    [offsetof(struct trace_ray, ky) == offsetof(struct trace_ray, kx) + sizeof(int) &&
             offsetof(struct trace_ray, kz) == offsetof(struct trace_ray, kx) + 2 * sizeof(int) &&
             offsetof(struct trace_ray, sx) == offsetof(struct trace_ray, kx) + 3 * sizeof(int) &&
             offsetof(struct trace_ray, dir) == offsetof(struct trace_ray, org) + 3 * sizeof(float) &&
             offsetof(struct trace_ray, tmin) ==
                 offsetof(struct trace_ray, inv_dir) + 3 * sizeof(float) &&
             sizeof(int) == 4
         ? 1
         : -1];
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void tri4_ray_init_vec(struct tri4_ray *r, const struct trace_ray *ray)
{
    const char *b = (const char *)(const void *)ray;
    const __m128i idx =
        _mm_loadu_si128((const __m128i *)(const void *)(b + offsetof(struct trace_ray, kx)));
    const __m128 org_k = _mm_permutevar_ps(
        _mm_loadu_ps((const float *)(const void *)(b + offsetof(struct trace_ray, org))), idx);
    const __m128 inv_k = _mm_permutevar_ps(
        _mm_loadu_ps((const float *)(const void *)(b + offsetof(struct trace_ray, inv_dir))), idx);
    tri4_ray_init_offsets(r, inv_k, idx);
    const __m128 neg_org = _mm_xor_ps(org_k, _mm_set1_ps(-0.0f));
    r->neg_org_x = _mm_permute_ps(neg_org, 0x00);
    r->neg_org_y = _mm_permute_ps(neg_org, 0x55);
    r->neg_org_z = _mm_permute_ps(neg_org, 0xAA);
    r->sx = _mm_set1_ps(ray->sx);
    r->sy = _mm_set1_ps(ray->sy);
    r->sz = _mm_set1_ps(ray->sz);
    r->inv_x = _mm_permute_ps(inv_k, 0x00);
    r->inv_y = _mm_permute_ps(inv_k, 0x55);
    r->tmin = _mm_set1_ps(ray->tmin);
}
#endif

#define WIDE8_RAY walk_wide8_ray
#define WIDE8_RAY_LEAF8 0
#define WIDE8_RAY_COMPRESS 1
#include "trace/traverse_wide8_ray.h"
#undef WIDE8_RAY
#undef WIDE8_RAY_LEAF8
#undef WIDE8_RAY_COMPRESS

/* A whole single-ray walk for a ray whose tmin is not >= 0 (negative or
 * NaN; rtTraceRays refuses both, query.c): walk_wide8_impl, whose node
 * test folds the entry with tmin in floats.  walk_wide8_ray's integer
 * maximum of the entry needs tmin >= +0.  The same answers and node and
 * triangle counts as walk_wide8_ray (its comment says why); s as
 * wide_state_init1 left it, r4 not yet set. */
static int wide8_walk_tmin_other(const struct bvh4 *wide, struct wide_state *s, int any_hit,
                                 int stats) WIDE_NOINLINE;
#if defined(__GNUC__) && !defined(__clang__)
/* One body for every walk copy's call (a cold path): with the any-hit
 * copies per prefetch_top, GCC otherwise makes a clone for the calls
 * with constant flags and rearranges the callers' registers around it. */
static int wide8_walk_tmin_other(const struct bvh4 *wide, struct wide_state *s, int any_hit,
                                 int stats) __attribute__((noclone));
#endif
static int wide8_walk_tmin_other(const struct bvh4 *wide, struct wide_state *s, int any_hit,
                                 int stats)
{
    s->any_hit = any_hit;
    s->box_limit = s->best * ISECT_BOX_FAR_SCALE;
    tri4_ray_init(&s->r4, s->ray);
    return stats ? walk_wide8_impl(wide, s, 0, 0, 1) : walk_wide8_impl(wide, s, 0, 0, 0);
}

/* The end of a whole single-ray walk (WIDE8_WALK, WIDE8_WALK1): its
 * counts added to the caller's when the copy counts, and its answer. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int wide8_walk_end(const struct wide_state *s, int done, int any_hit, int stats,
                                 struct trace_counters *counters)
{
    if (stats) {
        counters->node_tests += s->node_tests;
        counters->triangle_tests += s->triangle_tests;
    }
    return any_hit ? done : s->found;
}

/* The whole single-ray trace over an 8-wide layout, the state set up
 * here: the entry (walk_wide) is then a dispatch and a jump. */
#define WIDE8_WALK(name, walk, any_hit, stats, leave_early)                                     \
    static int name(const struct bvh4 *wide, const struct trace_ray *ray, float t_max,          \
                    struct trace_hit *hit, struct trace_counters *counters) WIDE_NOINLINE;      \
    static int name(const struct bvh4 *wide, const struct trace_ray *ray, float t_max,          \
                    struct trace_hit *hit, struct trace_counters *counters)                     \
    {                                                                                           \
        struct wide_ray_state rs;                                                               \
        struct wide_state *const s = &rs.s;                                                     \
        /* 1 for either any-hit copy (WIDE_ANY_LONGEST): the state's and the                    \
         * float walk's flag. */                                                                \
        const int any_walk = (any_hit) != 0;                                                    \
        wide_state_init1(s, ray, t_max, any_walk, stats, hit);                                  \
        if (!(ray->tmin >= 0.0f))                                                               \
            return wide8_walk_end(s, wide8_walk_tmin_other(wide, s, any_walk, stats),           \
                                  any_hit, stats, counters);                                    \
        if (any_hit)                                                                            \
            tri4_ray_init_scalar(&s->r4, ray);                                                  \
        const int done = walk(wide, s, any_hit, stats, leave_early, NULL);                      \
        return wide8_walk_end(s, done, any_hit, stats, counters);                               \
    }

/* The closest-hit walk in two copies: with the packet filter's early
 * return (tri4_filter_lanes) on a layout beyond the caches, without it on
 * a smaller one (the same threshold as the stack top's prefetch).  On a
 * large layout most packets a random ray tests are misses that the sign
 * test alone refuses (soup: 84 %); on a small one (gears: 40 %) the
 * branch cost more in mispredictions than it saved (gears random rays
 * 0.81 -> 0.75 of Embree with it, primary rays 1.02 -> 1.07).  A copy per
 * choice, not a test per packet. */
#if defined(TRACE_WIDE_PACKET_PIECES)
WIDE8_WALK(wide8_walk_closest, walk_wide8_ray, 0, 0, 0)
WIDE8_WALK(wide8_walk_closest_stats, walk_wide8_ray, 0, 1, 0)
WIDE8_WALK(wide8_walk_closest_early, walk_wide8_ray, 0, 0, 1)
WIDE8_WALK(wide8_walk_closest_early_stats, walk_wide8_ray, 0, 1, 1)
WIDE8_WALK(wide8_walk_any, walk_wide8_ray, 1, 0, 1)
WIDE8_WALK(wide8_walk_any_stats, walk_wide8_ray, 1, 1, 1)
#else

/*
 * A leaf of n = 5..8 triangles (two packets, p[0] and p[1]) with one
 * 8-lane filter (tri4_pair_filter_lanes) instead of two wide_packet_test
 * calls; the kept lanes in order, lane l of the mask being lane l % 4 of
 * p[l / 4], each with the limit of the moment (walk_leaf's rule), so the
 * hit is that of the two calls bit for bit (tri4_pair_filter_lanes says
 * why).  Only the walk copies over walk_wide8_ray_leaf8 call it.
 */
/* The kept lanes of packet p (the two-packet any-hit leaf,
 * wide_leaf8_test), among `near` (t_lo < tmin), that the finish surely
 * refuses on t: tri4_before_tmin_lanes from the filter's
 * floats, then tri4_before_tmin for the lanes it cannot decide.  A
 * function of its own, called for the near lanes only: inlined, its
 * vectors changed GCC's register allocation of the filter before it
 * (measured: 4 to 7 more instructions, spills, on every any-hit leaf
 * call, more than its call costs). */
static unsigned wide_near_refused(const struct wide_state *s, const struct tri4_packet *p,
                                  const struct tri4_lanes *lanes, unsigned near) WIDE_NOINLINE;
static unsigned wide_near_refused(const struct wide_state *s, const struct tri4_packet *p,
                                  const struct tri4_lanes *lanes, unsigned near)
{
    /* Only with depth_out, whose walks set r4's scalar form (TRI4_CONST). */
    const unsigned sure = tri4_before_tmin_lanes(&s->r4, p, lanes, near, 1);
    if (near & ~sure)
        return sure | tri4_before_tmin(s->ray, p, near & ~sure);
    return sure;
}

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int wide_leaf8_test(struct wide_state *s, const struct tri4_packet *p, uint32_t n,
                                  int any_hit, int early_out, int depth_out, int behind_out,
                                  int ray_double)
{
    float limit = !any_hit && s->found ? isect_next_up(s->best) : s->best;
    struct tri4_lanes lanes[2];
    unsigned mask =
        tri4_pair_filter_lanes(&s->r4, p, (1u << n) - 1u, limit, lanes, any_hit, early_out,
                               depth_out, behind_out);
    if (any_hit && mask) {
        /* As wide_packet_test, per packet (the near lanes refused on t_hi
         * with depth_out). */
        const __m128 tmin = TRI4_CONST(&s->r4, tmin, k_tmin, depth_out);
        unsigned near =
            ((unsigned)_mm_movemask_ps(_mm_cmplt_ps(_mm_loadu_ps(lanes[0].t_lo), tmin)) |
             (unsigned)_mm_movemask_ps(_mm_cmplt_ps(_mm_loadu_ps(lanes[1].t_lo), tmin)) << 4) &
            mask;
        const unsigned behind =
            ((unsigned)_mm_movemask_ps(_mm_cmplt_ps(_mm_loadu_ps(lanes[0].t_hi), tmin)) |
             (unsigned)_mm_movemask_ps(_mm_cmplt_ps(_mm_loadu_ps(lanes[1].t_hi), tmin)) << 4) &
            near;
        if (depth_out) {
            mask &= ~behind;
            near &= ~behind;
            if (near & 15u)
                mask &= ~wide_near_refused(s, p, &lanes[0], near & 15u);
            if (near >> 4)
                mask &= ~(wide_near_refused(s, p + 1, &lanes[1], near >> 4) << 4);
        } else {
            if (near & 15u)
                mask &= ~tri4_before_tmin(s->ray, p, near & 15u);
            if (near >> 4)
                mask &= ~(tri4_before_tmin(s->ray, p + 1, near >> 4) << 4);
        }
    }
    /* As wide_packet_test: each packet's kept lanes finished in vectors
     * first (TRI4_FINISH_VEC), a packet only when it has one. */
#if TRI4_FINISH_VEC
    unsigned fast = 0, fast_ok = 0;
    float fast_t[8];
    if (ray_double && !any_hit) {
        if (mask & 15u)
            fast = tri4_finish_lanes(p, &lanes[0], wide_ray_doubles(s), s->ray->tmin, fast_t,
                                     &fast_ok);
        if (mask >> 4) {
            unsigned ok_hi;
            fast |= tri4_finish_lanes(p + 1, &lanes[1], wide_ray_doubles(s), s->ray->tmin,
                                      fast_t + 4, &ok_hi)
                    << 4;
            fast_ok |= ok_hi << 4;
        }
    }
#endif
    while (mask) {
        const unsigned l = (unsigned)__builtin_ctz(mask);
        mask &= mask - 1u;
        const unsigned k = l >> 2;
        const struct tri4_packet *q = p + k;
        /* behind_out: the lanes wholly before tmin are out of the mask
         * already (tri4_pair_filter_lanes). */
        float t, u, w;
        /* limit kept up to date as in wide_packet_test. */
#if TRI4_FINISH_VEC
        if (fast >> l & 1u) {
            if (!tri4_finish_lane(&lanes[k], l & 3u, fast_ok >> 4u * k, fast_t[l], limit, &t,
                                  &u, &w))
                continue;
        } else
#endif
            if (!tri4_lane_test(s->ray, ray_double ? wide_ray_doubles(s) : NULL, q, &lanes[k],
                                l & 3u, any_hit, limit, &t, &u, &w))
            continue;
        if (any_hit) {
            s->found = 1;
            return 1;
        }
        if (wide_take_closest(s, q->prim[l & 3u], t, u, w) && mask)
            limit = isect_next_up(t);
    }
    return 0;
}

WIDE8_LEAF_TEST(wide8_leaf8_closest, wide_leaf8_test, 0, 1, 0, 1, 1)
WIDE8_LEAF_TEST(wide8_leaf8_full, wide_leaf8_test, 0, 0, 0, 1, 1)
/* The closest-hit walk's first 8-lane leaf of a ray: the filter refuses
 * a leaf whose lanes are all missed by the line, outside the depth and
 * box tests, or wholly before tmin right after the signs
 * (TRI4_BEHIND_FIRST), with the same answers (tri4_pair_filter_lanes
 * says why; traverse_wide8_ray.h why only there). */
WIDE8_LEAF_TEST(wide8_leaf8_closest_first, wide_leaf8_test, 0, 1, 0, TRI4_BEHIND_FIRST, 1)
WIDE8_LEAF_TEST(wide8_leaf8_full_first, wide_leaf8_test, 0, 0, 0, TRI4_BEHIND_FIRST, 1)
WIDE8_LEAF_TEST(wide8_leaf8_any, wide_leaf8_test, 1, 1, 1, 0, 0)

#define WIDE8_RAY walk_wide8_ray_leaf8
#define WIDE8_RAY_LEAF8 1
#define WIDE8_RAY_COMPRESS 1
#include "trace/traverse_wide8_ray.h"
#undef WIDE8_RAY
#undef WIDE8_RAY_LEAF8
#undef WIDE8_RAY_COMPRESS

#if TRACE_AVX512_TABLE
/* The AVX-512 table's second form of the walk from the set-up's lanes:
 * the front child by the trailing-zero count of the node test's mask and
 * the child's load (as the AVX2 table takes it), not by compression
 * (wide8_front_compress, wide8_push_compress).  The same child, so the
 * same walk, answers and counts.  On an AMD Zen 4 core (family 25) the
 * compression was 0.05-0.1 of Embree slower on most closest-hit rows
 * and level to slower on shadow rays; on the Emerald Rapids core that
 * chose it, it was faster (performance-log.md, rounds 46-48, and round
 * 61, zq2).  trace_kernels_get (kernels.c) picks the form by the CPU's
 * vendor. */
#define WIDE8_RAY walk_wide8_ray_leaf8_ctz
#define WIDE8_RAY_LEAF8 1
#define WIDE8_RAY_COMPRESS 0
#include "trace/traverse_wide8_ray.h"
#undef WIDE8_RAY
#undef WIDE8_RAY_LEAF8
#undef WIDE8_RAY_COMPRESS
#endif

/* The single-ray walks with one 8-lane test for a leaf of two packets
 * (walk_wide8_ray_leaf8): one 8-lane pass instead of two 4-lane passes
 * with their own early returns; and their copies with counters, which
 * count what the walks above count (a leaf's triangles before its test,
 * whichever test it is).  The two-level walk (scene_traverse.c) always
 * passes counters (rtGet's statistics and RT_AUTOMATIC's model read
 * them): before the copies with counters its rays took the 4-lane
 * leaves. */
WIDE8_WALK(wide8_walk_closest_leaf8, walk_wide8_ray_leaf8, 0, 0, 0)
WIDE8_WALK(wide8_walk_closest_early_leaf8, walk_wide8_ray_leaf8, 0, 0, 1)
WIDE8_WALK(wide8_walk_any_leaf8, walk_wide8_ray_leaf8, 1, 0, 1)
WIDE8_WALK(wide8_walk_closest_leaf8_stats, walk_wide8_ray_leaf8, 0, 1, 0)
WIDE8_WALK(wide8_walk_closest_early_leaf8_stats, walk_wide8_ray_leaf8, 0, 1, 1)
WIDE8_WALK(wide8_walk_any_leaf8_stats, walk_wide8_ray_leaf8, 1, 1, 1)
/* The any-hit walks for the layouts with any_longest (WIDE_ANY_LONGEST). */
WIDE8_WALK(wide8_walk_any_longest_leaf8, walk_wide8_ray_leaf8, WIDE_ANY_LONGEST, 0, 1)
WIDE8_WALK(wide8_walk_any_longest_leaf8_stats, walk_wide8_ray_leaf8, WIDE_ANY_LONGEST, 1, 1)

/* The same three walks for the entries that take the ray's origin and
 * direction (TRACE_WIDE_CLOSEST1, TRACE_WIDE_ANY1): the ray is set up
 * here, in the walk's own frame (ray_setup.h), so the walk's first
 * vectors and the leaf's constants come from the set-up's registers, not
 * from a struct another function has just stored; one call and its
 * stores and loads fewer a ray. */
/* k_tmin and node_neg_org[0..2] in one store: tmin, then the origin
 * (org's lanes 0-2, its lane 3 not kept) with its sign bits flipped, -org
 * as C's unary minus gives it (the node test's bound + (-org),
 * walk_wide8_ray).  Every walk from the set-up's lanes (WIDE8_WALK1):
 * the any-hit walks with the leaves' scalar constants, the closest-hit
 * walks alone (their node test broadcasts -org from here after each leaf
 * call; their leaves' constants are set at the first leaf). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void tri4_ray_init_node_org(struct tri4_ray *r, const struct ray_lanes *l,
                                          float tmin)
{
    const __m128 neg_org = _mm_xor_ps(l->org, _mm_set1_ps(-0.0f));
    _mm_storeu_ps((float *)(void *)((char *)(void *)r + offsetof(struct tri4_ray, k_tmin)),
                  _mm_move_ss(_mm_permute_ps(neg_org, _MM_SHUFFLE(2, 1, 0, 3)), _mm_set_ss(tmin)));
}

/* tri4_ray_init_scalar's constants from the set-up's lanes (ray_setup.h):
 * the same floats, stored as the lanes hold them (org_k with its sign
 * bits flipped, inv_k, shear: three 16-byte stores) for the any-hit
 * leaves to broadcast from memory (struct tri4_ray's scalar form), where
 * the vector form took nine broadcasts and nine stores a ray. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void tri4_ray_init_scalar_lanes(struct tri4_ray *r, const struct ray_lanes *l,
                                              float tmin)
{
    /* off_x, off_y, off_z (kx, ky, kz times a row's 16 bytes, as
     * size_t) and neg_x, neg_y (inv_dir[kx] < 0, inv_dir[ky] < 0, as 0/1
     * ints) are 32 consecutive bytes (tri4_ray_init_scalar_layout): built
     * in one vector from the set-up's lane order and the comparison's
     * lanes, one store, where the scalar form took about 16 instructions
     * (loads, shifts, a movemask and its bits, five stores).  The same
     * values: the order's indices shifted by 4, zero-extended; the
     * comparison's all-ones lanes shifted right by 31. */
    tri4_ray_init_offsets(r, l->inv_k, l->order);
    _mm_storeu_ps(r->k_neg_org, _mm_xor_ps(l->org_k, _mm_set1_ps(-0.0f)));
    _mm_storeu_ps(r->k_inv, l->inv_k);
    _mm_storeu_ps(r->k_shear, l->shear);
    tri4_ray_init_node_org(r, l, tmin);
}

/* tri4_ray_init_scalar_lanes' one 32-byte store over off_x .. neg_y. */
typedef char tri4_ray_init_scalar_layout
    [offsetof(struct tri4_ray, off_y) == offsetof(struct tri4_ray, off_x) + 8 &&
             offsetof(struct tri4_ray, off_z) == offsetof(struct tri4_ray, off_x) + 16 &&
             offsetof(struct tri4_ray, neg_x) == offsetof(struct tri4_ray, off_x) + 24 &&
             offsetof(struct tri4_ray, neg_y) == offsetof(struct tri4_ray, off_x) + 28 &&
             sizeof(size_t) == 8 && sizeof(int) == 4 &&
             sizeof(((const struct tri4_packet *)NULL)->v[0][0]) == 16
         ? 1
         : -1];

/* tri4_ray_init_scalar_lanes' one store over k_tmin and node_neg_org. */
typedef char tri4_ray_tmin_org_layout[offsetof(struct tri4_ray, node_neg_org) ==
                                              offsetof(struct tri4_ray, k_tmin) + sizeof(float)
                                          ? 1
                                          : -1];

/* walk_wide8_ray's walks that take the front child by compression as a
 * byte offset (AVX-512: cur_off, wide8_child_offsets) shift the child
 * words within 32-bit lanes: child * 256 must stay below 2^32, so every
 * node and packet index below 2^24.  A layout with more nodes or packets
 * (over 4 GB of nodes or 16 M packets) takes the float walk
 * (wide8_walk_tmin_other: the same answers and counts) instead. */
#if TRACE_AVX512_TABLE
#define WIDE8_WALK1_FAR(wide, any_hit)                                                          \
    (((any_hit) == 0 || (any_hit) == 1) &&                                                      \
     ((wide)->node_count | (wide)->packet_count) > 0xffffffu)
#else
#define WIDE8_WALK1_FAR(wide, any_hit) 0
#endif

/* 1 when a walk with the fused node test (WIDE8_FUSED) gets a ray its
 * constants do not cover (node_fused_init: a zero or tiny direction
 * component, an origin beyond 2^60), else 0 with the constants set in
 * rs.fused.  A table without the test (the AVX2 table) neither sets
 * them nor checks the cover. */
#if WIDE8_FUSED_TABLE
#define WIDE8_FUSED_UNCOVERED(rs, lanes, any_hit)                                               \
    (WIDE8_FUSED(any_hit) &&                                                                    \
     !node_fused_init(&(rs).fused, (lanes).org, (lanes).dir, (lanes).inv))
#else
#define WIDE8_FUSED_UNCOVERED(rs, lanes, any_hit) 0
#endif

#define WIDE8_WALK1(name, walk, any_hit, stats, leave_early)                                    \
    static int name(const struct bvh4 *wide, const float org[3], const float dir[3],            \
                    float tmin, float t_max, struct trace_hit *hit,                             \
                    struct trace_counters *counters) WIDE_NOINLINE;                             \
    static int name(const struct bvh4 *wide, const float org[3], const float dir[3],            \
                    float tmin, float t_max, struct trace_hit *hit,                             \
                    struct trace_counters *counters)                                            \
    {                                                                                           \
        struct trace_ray ray;                                                                   \
        struct ray_lanes lanes;                                                                 \
        trace_ray_setup_lanes(&ray, &lanes, org, dir, tmin);                                    \
        struct wide_ray_state rs;                                                               \
        struct wide_state *const s = &rs.s;                                                     \
        /* 1 for either any-hit copy (WIDE_ANY_LONGEST): the state's and the                    \
         * float walk's flag. */                                                                \
        const int any_walk = (any_hit) != 0;                                                    \
        wide_state_init1(s, &ray, t_max, any_walk, stats, hit);                                 \
        /* A ray the fused node test does not cover takes the float walk                        \
         * with isect_box's test, as a negative tmin does                                       \
         * (WIDE8_FUSED_UNCOVERED). */                                                          \
        if (!(tmin >= 0.0f) || WIDE8_WALK1_FAR(wide, any_hit) ||                                \
            WIDE8_FUSED_UNCOVERED(rs, lanes, any_hit))                                          \
            return wide8_walk_end(s, wide8_walk_tmin_other(wide, s, any_walk, stats),           \
                                  any_hit, stats, counters);                                    \
        if (any_hit)                                                                            \
            tri4_ray_init_scalar_lanes(&s->r4, &lanes, tmin);                                   \
        else                                                                                    \
            tri4_ray_init_node_org(&s->r4, &lanes, tmin);                                       \
        const int done = walk(wide, s, any_hit, stats, leave_early, &lanes);                    \
        return wide8_walk_end(s, done, any_hit, stats, counters);                               \
    }

WIDE8_WALK1(wide8_walk1_closest_leaf8, walk_wide8_ray_leaf8, 0, 0, 0)
WIDE8_WALK1(wide8_walk1_closest_early_leaf8, walk_wide8_ray_leaf8, 0, 0, 1)
WIDE8_WALK1(wide8_walk1_any_leaf8, walk_wide8_ray_leaf8, 1, 0, 1)
/* With counters: the two-level walk's rays that reach an identity
 * instance's object without a world set-up (scene_traverse.c, a top
 * level of one leaf), counted as the walks above count. */
WIDE8_WALK1(wide8_walk1_closest_leaf8_stats, walk_wide8_ray_leaf8, 0, 1, 0)
WIDE8_WALK1(wide8_walk1_closest_early_leaf8_stats, walk_wide8_ray_leaf8, 0, 1, 1)
WIDE8_WALK1(wide8_walk1_any_leaf8_stats, walk_wide8_ray_leaf8, 1, 1, 1)
/* The any-hit walks for the layouts with any_longest (WIDE_ANY_LONGEST). */
WIDE8_WALK1(wide8_walk1_any_longest_leaf8, walk_wide8_ray_leaf8, WIDE_ANY_LONGEST, 0, 1)
WIDE8_WALK1(wide8_walk1_any_longest_leaf8_stats, walk_wide8_ray_leaf8, WIDE_ANY_LONGEST, 1, 1)
#if TRACE_AVX512_TABLE
/* The same walks with the front child by the trailing-zero count
 * (walk_wide8_ray_leaf8_ctz); the any_longest walks take it so in both
 * forms. */
WIDE8_WALK1(wide8_walk1_closest_leaf8_ctz, walk_wide8_ray_leaf8_ctz, 0, 0, 0)
WIDE8_WALK1(wide8_walk1_closest_early_leaf8_ctz, walk_wide8_ray_leaf8_ctz, 0, 0, 1)
WIDE8_WALK1(wide8_walk1_any_leaf8_ctz, walk_wide8_ray_leaf8_ctz, 1, 0, 1)
WIDE8_WALK1(wide8_walk1_closest_leaf8_stats_ctz, walk_wide8_ray_leaf8_ctz, 0, 1, 0)
WIDE8_WALK1(wide8_walk1_closest_early_leaf8_stats_ctz, walk_wide8_ray_leaf8_ctz, 0, 1, 1)
WIDE8_WALK1(wide8_walk1_any_leaf8_stats_ctz, walk_wide8_ray_leaf8_ctz, 1, 1, 1)
#endif

/* kernels.h's walk1: the walk walk_wide_single1 below takes without
 * counters, chosen once for a layout.  A caller that traces many rays
 * over one layout (rtbench's loops) calls it directly, without the
 * entries' tests of the layout every ray (10-19 instructions a ray on
 * AVX2, callgrind). */
static trace_walk1_fn TRACE_WIDE_WALK1(const struct bvh4 *wide, int any_hit)
{
    if (wide->width != 8 || !wide->node_count)
        return NULL;
    if (any_hit)
        return wide->any_longest ? wide8_walk1_any_longest_leaf8 : wide8_walk1_any_leaf8;
    return wide->prefetch_top ? wide8_walk1_closest_early_leaf8 : wide8_walk1_closest_leaf8;
}

#if TRACE_AVX512_TABLE
/* TRACE_WIDE_WALK1 for the walks of walk_wide8_ray_leaf8_ctz. */
static trace_walk1_fn TRACE_WIDE_WALK1_CTZ(const struct bvh4 *wide, int any_hit)
{
    if (wide->width != 8 || !wide->node_count)
        return NULL;
    if (any_hit)
        return wide->any_longest ? wide8_walk1_any_longest_leaf8 : wide8_walk1_any_leaf8_ctz;
    return wide->prefetch_top ? wide8_walk1_closest_early_leaf8_ctz
                              : wide8_walk1_closest_leaf8_ctz;
}
#endif

/* kernels.h's walk1_counted: walk_wide_single1's counting walks by index
 * 2 any_hit + (any_hit ? any_longest : prefetch_top) != 0, the choice its
 * entries make every ray (the any-hit walk does not depend on
 * prefetch_top, the closest-hit walk not on any_longest). */
static const trace_walk1_fn TRACE_WIDE_WALK1_COUNTED[4] = {
    wide8_walk1_closest_leaf8_stats, wide8_walk1_closest_early_leaf8_stats,
    wide8_walk1_any_leaf8_stats, wide8_walk1_any_longest_leaf8_stats};

#if TRACE_AVX512_TABLE
static const trace_walk1_fn TRACE_WIDE_WALK1_COUNTED_CTZ[4] = {
    wide8_walk1_closest_leaf8_stats_ctz, wide8_walk1_closest_early_leaf8_stats_ctz,
    wide8_walk1_any_leaf8_stats_ctz, wide8_walk1_any_longest_leaf8_stats};
#endif

/*
 * The leaf of the 8-wide walks on its own, for
 * conformance/internal/tri4_differential: the n triangles of p[0], p[1]
 * (n up to 8), eight 1 with the 8-lane call of the leaf8 walks for
 * 5-8 triangles, 2 with the closest-hit walk's call at a ray's first
 * leaf (wide8_leaf8_closest_first or _full_first; an any-hit leaf as 1),
 * 0 with the 4-lane calls on each packet in turn; early_out
 * picks the closest-hit copy (wide8_leaf8_closest or _full).  found 1:
 * *hit is an earlier leaf's hit, whose t is the limit (walk_leaf's rule).
 * Returns found (closest) or occluded (any hit).
 */
static int TRACE_WIDE_LEAF8(const struct trace_ray *ray, const struct tri4_packet *p, uint32_t n,
                     float t_max, int any_hit, int early_out, int eight, int found,
                     struct trace_hit *hit)
{
    struct wide_ray_state rs;
    struct wide_state *const s = &rs.s;
    wide_state_init(s, ray, t_max, any_hit, hit);
    if (!any_hit && found) {
        s->found = 1;
        s->best = hit->t;
        s->box_limit = hit->t * ISECT_BOX_FAR_SCALE;
    }
    /* The constants' form each walk sets: the any-hit leaves read only
     * the scalar form (TRI4_CONST), the closest-hit leaves the vectors. */
    if (any_hit) {
        tri4_ray_init_scalar(&s->r4, ray);
    } else {
        tri4_ray_init(&s->r4, ray);
        tri4_ray_init_double(rs.d_org_dir, ray);
    }
    int stop = 0;
    if (eight) {
        if (any_hit)
            stop = wide8_leaf8_any(s, p, n);
        else if (early_out)
            stop = eight == 2 ? wide8_leaf8_closest_first(s, p, n) : wide8_leaf8_closest(s, p, n);
        else
            stop = eight == 2 ? wide8_leaf8_full_first(s, p, n) : wide8_leaf8_full(s, p, n);
    } else {
        for (uint32_t j = 0; j < n && !stop; j += 4) {
            const uint32_t m = n - j < 4 ? n - j : 4;
            if (any_hit)
                stop = wide8_packet_any(s, p + j / 4, m);
            else if (early_out)
                stop = wide8_packet_closest(s, p + j / 4, m);
            else
                stop = wide8_packet_full(s, p + j / 4, m);
        }
    }
    return any_hit ? stop : s->found;
}
#endif /* TRACE_WIDE_PACKET_PIECES */
#endif

/* A whole 4-wide walk for a ray whose tmin is not >= 0 (negative or NaN;
 * rtTraceRays refuses both, query.c): walk_wide4_body with the float
 * fold of the entry, as wide8_walk_tmin_other.  s and r4 as WIDE4_WALK
 * set them. */
static int wide4_walk_tmin_other(const struct bvh4 *wide, struct wide_state *s, int any_hit,
                                 int stats) WIDE_NOINLINE;
static int wide4_walk_tmin_other(const struct bvh4 *wide, struct wide_state *s, int any_hit,
                                 int stats)
{
    return stats ? walk_wide4_body(wide, s, 0, 0, any_hit, 1, 0)
                 : walk_wide4_body(wide, s, 0, 0, any_hit, 0, 0);
}

/* walk_wide's 4-wide walks, each its own function with the ray's state
 * set up inside (as WIDE8_WALK); the state does not escape (the leaf is
 * inlined), so it can live in registers.  Rays with tmin >= 0 (every
 * ray rtTraceRays takes) get the integer entry (walk_wide4_body). */
#define WIDE4_WALK(name, any_hit, stats)                                                        \
    static int name(const struct bvh4 *wide, const struct trace_ray *ray, float t_max,         \
                    struct trace_hit *hit, struct trace_counters *counters) WIDE_NOINLINE;      \
    static int name(const struct bvh4 *wide, const struct trace_ray *ray, float t_max,         \
                    struct trace_hit *hit, struct trace_counters *counters)                     \
    {                                                                                           \
        struct wide_state s;                                                                    \
        wide_state_init(&s, ray, t_max, any_hit, hit);                                          \
        tri4_ray_init(&s.r4, ray);                                                              \
        const int done = ray->tmin >= 0.0f                                                      \
                             ? walk_wide4_body(wide, &s, 0, 0, any_hit, stats, 1)               \
                             : wide4_walk_tmin_other(wide, &s, any_hit, stats);                 \
        if (stats) {                                                                            \
            counters->node_tests += s.node_tests;                                               \
            counters->triangle_tests += s.triangle_tests;                                       \
        }                                                                                       \
        (void)counters;                                                                         \
        return any_hit ? done : s.found;                                                        \
    }

WIDE4_WALK(wide4_walk_closest, 0, 0)
WIDE4_WALK(wide4_walk_closest_stats, 0, 1)
WIDE4_WALK(wide4_walk_any, 1, 0)
WIDE4_WALK(wide4_walk_any_stats, 1, 1)

#if defined(TRACE_WIDE_PACKET_PIECES)
/* The walk of the layout's width; a width this table does not walk
 * (8 without AVX) takes the binary walk, which gives the same answers. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int walk_wide(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                            const struct trace_ray *ray, float t_max, int any_hit,
                            struct trace_hit *hit, struct trace_counters *counters)
{
    if (wide->node_count == 0)
        return walk(bvh, tri, ray, t_max, any_hit, hit, counters);
#if defined(__AVX__)
    if (wide->width == 8) {
        if (any_hit)
            return counters ? wide8_walk_any_stats(wide, ray, t_max, hit, counters)
                            : wide8_walk_any(wide, ray, t_max, hit, counters);
        if (wide->prefetch_top)
            return counters ? wide8_walk_closest_early_stats(wide, ray, t_max, hit, counters)
                            : wide8_walk_closest_early(wide, ray, t_max, hit, counters);
        return counters ? wide8_walk_closest_stats(wide, ray, t_max, hit, counters)
                        : wide8_walk_closest(wide, ray, t_max, hit, counters);
    }
#endif
    /* Two copies of each walk: without counters (the caller passed
     * none, the common case) the hot loop does not count. */
    if (wide->width == 4) {
        if (any_hit)
            return counters ? wide4_walk_any_stats(wide, ray, t_max, hit, counters)
                            : wide4_walk_any(wide, ray, t_max, hit, counters);
        return counters ? wide4_walk_closest_stats(wide, ray, t_max, hit, counters)
                        : wide4_walk_closest(wide, ray, t_max, hit, counters);
    }
    return walk(bvh, tri, ray, t_max, any_hit, hit, counters);
}

#else
/* walk_wide for the single-ray entries below, whose 8-wide walks test a
 * leaf of two packets with one 8-lane call (walk_wide8_ray_leaf8; sleaf
 * found it nowhere slower than two 4-lane calls).  walk_wide above, as
 * it was, stays the packet kernels' fallback (packet_wide.h): with the
 * choice inlined there, their code changed too. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int walk_wide_single(const struct bvh4 *wide, const struct bvh *bvh,
                                   const float *tri, const struct trace_ray *ray, float t_max,
                                   int any_hit, struct trace_hit *hit,
                                   struct trace_counters *counters)
{
    if (wide->node_count == 0)
        return walk(bvh, tri, ray, t_max, any_hit, hit, counters);
#if defined(__AVX__)
    if (wide->width == 8) {
        if (any_hit && wide->any_longest)
            return counters ? wide8_walk_any_longest_leaf8_stats(wide, ray, t_max, hit, counters)
                            : wide8_walk_any_longest_leaf8(wide, ray, t_max, hit, counters);
        if (any_hit)
            return counters ? wide8_walk_any_leaf8_stats(wide, ray, t_max, hit, counters)
                            : wide8_walk_any_leaf8(wide, ray, t_max, hit, counters);
        if (wide->prefetch_top)
            return counters
                       ? wide8_walk_closest_early_leaf8_stats(wide, ray, t_max, hit, counters)
                       : wide8_walk_closest_early_leaf8(wide, ray, t_max, hit, counters);
        return counters ? wide8_walk_closest_leaf8_stats(wide, ray, t_max, hit, counters)
                        : wide8_walk_closest_leaf8(wide, ray, t_max, hit, counters);
    }
#endif
    /* Two copies of each walk: without counters (the caller passed
     * none, the common case) the hot loop does not count. */
    if (wide->width == 4) {
        if (any_hit)
            return counters ? wide4_walk_any_stats(wide, ray, t_max, hit, counters)
                            : wide4_walk_any(wide, ray, t_max, hit, counters);
        return counters ? wide4_walk_closest_stats(wide, ray, t_max, hit, counters)
                        : wide4_walk_closest(wide, ray, t_max, hit, counters);
    }
    return walk(bvh, tri, ray, t_max, any_hit, hit, counters);
}

int TRACE_WIDE_CLOSEST(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                       const struct trace_ray *ray, float t_max, struct trace_hit *hit,
                       struct trace_counters *counters);
int TRACE_WIDE_CLOSEST(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                       const struct trace_ray *ray, float t_max, struct trace_hit *hit,
                       struct trace_counters *counters)
{
    return walk_wide_single(wide, bvh, tri, ray, t_max, 0, hit, counters);
}

int TRACE_WIDE_ANY(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                   const struct trace_ray *ray, float t_max, struct trace_counters *counters);
int TRACE_WIDE_ANY(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                   const struct trace_ray *ray, float t_max, struct trace_counters *counters)
{
    return walk_wide_single(wide, bvh, tri, ray, t_max, 1, NULL, counters);
}

/* closest4/any4 from the ray's origin, direction and tmin (kernels.h's
 * closest1/any1): trace_ray_init_single's ray, set up inside the 8-wide
 * walk where the layout has one (WIDE8_WALK1), else here before the walk
 * of walk_wide_single.  Same answers as trace_ray_init_single followed by
 * closest4/any4, bit for bit (the same set-up text, ray_setup.h). */
static int walk_wide_single1_other(const struct bvh4 *wide, const struct bvh *bvh,
                                   const float *tri, const float org[3], const float dir[3],
                                   float tmin, float t_max, int any_hit, struct trace_hit *hit,
                                   struct trace_counters *counters) WIDE_NOINLINE;
static int walk_wide_single1_other(const struct bvh4 *wide, const struct bvh *bvh,
                                   const float *tri, const float org[3], const float dir[3],
                                   float tmin, float t_max, int any_hit, struct trace_hit *hit,
                                   struct trace_counters *counters)
{
    struct trace_ray ray;
    trace_ray_setup_single(&ray, org, dir, tmin);
    return walk_wide_single(wide, bvh, tri, &ray, t_max, any_hit, hit, counters);
}

/* The entries' choice of walk.  The cases without an 8-wide walk of
 * their own (a 4-wide or binary layout) are a function apart
 * (walk_wide_single1_other): with their set-up inlined here, the entry
 * had a frame of its own (its trace_ray, 32-byte aligned), 31
 * instructions a ray before and after the walk's call instead of a
 * jump.  ctz (a constant): the AVX-512 table's walks of
 * walk_wide8_ray_leaf8_ctz (WIDE8_WALK1_PICK); 0 on the other tables. */
#if TRACE_AVX512_TABLE
#define WIDE8_WALK1_PICK(ctz, name) ((ctz) ? name##_ctz : name)
#else
#define WIDE8_WALK1_PICK(ctz, name) name
#endif
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int walk_wide_single1(const struct bvh4 *wide, const struct bvh *bvh,
                                    const float *tri, const float org[3], const float dir[3],
                                    float tmin, float t_max, int any_hit, struct trace_hit *hit,
                                    struct trace_counters *counters, int ctz)
{
    (void)ctz; /* unused where WIDE8_WALK1_PICK ignores it */
#if defined(__AVX__)
    if (wide->width == 8 && wide->node_count) {
        if (counters) {
            if (any_hit)
                return wide->any_longest
                           ? wide8_walk1_any_longest_leaf8_stats(wide, org, dir, tmin, t_max,
                                                                 hit, counters)
                           : WIDE8_WALK1_PICK(ctz, wide8_walk1_any_leaf8_stats)(
                                 wide, org, dir, tmin, t_max, hit, counters);
            if (wide->prefetch_top)
                return WIDE8_WALK1_PICK(ctz, wide8_walk1_closest_early_leaf8_stats)(
                    wide, org, dir, tmin, t_max, hit, counters);
            return WIDE8_WALK1_PICK(ctz, wide8_walk1_closest_leaf8_stats)(wide, org, dir, tmin,
                                                                          t_max, hit, counters);
        }
        if (any_hit)
            return wide->any_longest
                       ? wide8_walk1_any_longest_leaf8(wide, org, dir, tmin, t_max, hit, NULL)
                       : WIDE8_WALK1_PICK(ctz, wide8_walk1_any_leaf8)(wide, org, dir, tmin,
                                                                      t_max, hit, NULL);
        if (wide->prefetch_top)
            return WIDE8_WALK1_PICK(ctz, wide8_walk1_closest_early_leaf8)(wide, org, dir, tmin,
                                                                          t_max, hit, NULL);
        return WIDE8_WALK1_PICK(ctz, wide8_walk1_closest_leaf8)(wide, org, dir, tmin, t_max, hit,
                                                                NULL);
    }
#endif
    return walk_wide_single1_other(wide, bvh, tri, org, dir, tmin, t_max, any_hit, hit,
                                   counters);
}

int TRACE_WIDE_CLOSEST1(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                        const float org[3], const float dir[3], float tmin, float t_max,
                        struct trace_hit *hit, struct trace_counters *counters);
int TRACE_WIDE_CLOSEST1(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                        const float org[3], const float dir[3], float tmin, float t_max,
                        struct trace_hit *hit, struct trace_counters *counters)
{
    return walk_wide_single1(wide, bvh, tri, org, dir, tmin, t_max, 0, hit, counters, 0);
}

int TRACE_WIDE_ANY1(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                    const float org[3], const float dir[3], float tmin, float t_max,
                    struct trace_counters *counters);
int TRACE_WIDE_ANY1(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                    const float org[3], const float dir[3], float tmin, float t_max,
                    struct trace_counters *counters)
{
    return walk_wide_single1(wide, bvh, tri, org, dir, tmin, t_max, 1, NULL, counters, 0);
}

#if TRACE_AVX512_TABLE
/* closest1 and any1 with the walks of walk_wide8_ray_leaf8_ctz. */
int TRACE_WIDE_CLOSEST1_CTZ(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                            const float org[3], const float dir[3], float tmin, float t_max,
                            struct trace_hit *hit, struct trace_counters *counters);
int TRACE_WIDE_CLOSEST1_CTZ(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                            const float org[3], const float dir[3], float tmin, float t_max,
                            struct trace_hit *hit, struct trace_counters *counters)
{
    return walk_wide_single1(wide, bvh, tri, org, dir, tmin, t_max, 0, hit, counters, 1);
}

int TRACE_WIDE_ANY1_CTZ(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                        const float org[3], const float dir[3], float tmin, float t_max,
                        struct trace_counters *counters);
int TRACE_WIDE_ANY1_CTZ(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                        const float org[3], const float dir[3], float tmin, float t_max,
                        struct trace_counters *counters)
{
    return walk_wide_single1(wide, bvh, tri, org, dir, tmin, t_max, 1, NULL, counters, 1);
}
#endif
#endif /* TRACE_WIDE_PACKET_PIECES */
