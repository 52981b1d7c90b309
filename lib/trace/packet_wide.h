/* SPDX-License-Identifier: Apache-2.0 */
/*
 * packet_wide.h - the packet walk over the wide layout (packet.h),
 * included by the packet walk's own translation units (packet_kernels.h:
 * packet_sse4.c, packet_avx2.c, packet_avx512.c) after traverse_wide.h,
 * whose per-ray pieces it reuses: each ray of a packet
 * keeps the single-ray walk's state (struct wide_state), every box test
 * of a ray is walk_wide4's or walk_wide8's float operations on that
 * ray's own near and far planes, every leaf is wide_leaf for that ray,
 * and a subtree left with fewer than `hybrid` rays is walked by
 * walk_wide4/walk_wide8 itself from its root, ray by ray.  So each ray
 * gets the single walk's hit bit for bit (traverse_wide.h gives the
 * argument that neither skipped inner nodes nor the order of visits
 * changes it; a packet only visits, for each ray, nodes whose box that
 * ray's own test accepted, in the order of the packet's first ray).
 * Define TRACE_PACKET_CLOSEST and TRACE_PACKET_ANY.
 *
 * A node's children are tested ray by ray (one SIMD test over the
 * children per ray), and the results are transposed into a mask of rays
 * per child with one AND and OR per ray; a pushed child keeps the
 * smallest entry distance of its rays, and is skipped on pop for the
 * rays whose closest hit so far lies in front of it.  With AVX, a
 * leaf's triangles are tested against the rays that share the first
 * ray's kx, ky, kz eight at a time (packet_tri8.h), which gives each ray
 * isect_triangle's answer (see there).
 *
 * Over the 8-wide layout a packet in one octant takes packet_walk8_ia
 * instead: one interval test of a node's children for the whole packet,
 * leaf boxes tested ray by ray unless the beam is narrow against the
 * leaves (see there).
 */
#include "trace/isa_avx512.h"
#include "trace/packet.h"
#if defined(__AVX__)
#include "trace/packet_tri8.h"
#endif

/* A leaf is tested with the eight-ray triangle test (packet_tri8.h) when
 * at least this many of its rays share the first ray's kx, ky, kz;
 * otherwise, and for the other rays, ray by ray (wide_leaf).  Measured
 * (docs/performance-log.md): two rays took fewer instructions in the
 * lanes than each through wide_leaf with its state's set-up and sync
 * (kpk); one ray took more (bumpy +1.5 %) until the first exits by
 * pairs of rays (PACKET_PAIR_MAX) made a one-ray leaf cost one
 * eight-lane test of its four triangles (pk3: bumpy's camera packets
 * -1.4 %, its shadow packets +0.7 %, at 1 against 2). */
#define PACKET_TRI8_MIN 1

/* A leaf reached by at most this many rays of the eight-ray test takes
 * its triangles' first exits by pairs of rays first (tri8_pair_filter:
 * four triangles by two rays in the eight lanes), and tri8_test only for
 * the triangles one of them passes.  Measured (docs/performance-log.md,
 * pk3), instructions a ray of the packet kernel, AVX2: 4 lowest on
 * bumpy's camera packets and level with 6 elsewhere; 8 (every leaf)
 * costs the kitchen's camera packets +8 %. */
#define PACKET_PAIR_MAX 4

/* A closest-hit leaf of more than this many triangles, reached by more
 * than PACKET_PAIR_MAX rays of the interval walk, tests each triangle's
 * box against the packet's interval first (packet_tri_beam) and takes
 * tri8_test only for the triangles whose box passes.  A leaf of one
 * triangle packet takes every triangle's tri8_test as before.  Measured
 * (docs/performance-log.md, pk16 and pk17, AVX2 instructions of the
 * camera packets): with the test in every such leaf (0 here) the
 * kitchen's took 5.6 % fewer instructions, but gears' were 4-8 % slower
 * on the clock for +1.1 % instructions; above 4 the kitchen keeps nearly
 * all of its saving (-5.5 %), gears' leaves of more than four triangles
 * are rare and their count falls below main's (-1.6 %, the copies' code
 * as the compiler lays it out), and gears' clock is level. */
#define PACKET_BEAM_MIN 4

/* A one-origin packet's leaf child takes no test per ray where the beam,
 * this many times over, is narrower than the leaves' mean size
 * (packet_ia_init).  Measured (docs/performance-log.md, pgate): the
 * leaves' mean size over the beam's width at the hit is about 13 on
 * gears and 5.3 on the soup, whose camera packets gain without the
 * test, and 1.5 on the kitchen and 0.6 on bumpy, which need it. */
#define PACKET_LEAF_GATE 3.0f
/* A child of a packet from several origins, inner node or leaf, is
 * entered by all its rays, without a test per ray, where its box's
 * largest extent is at least this many times the packet's width there
 * (the origins' spread plus the directions' spread times the entry
 * bound).  Measured (docs/performance-log.md): for inner children alone
 * (pgate), shadow packets' instructions per ray were lowest at 2 on all
 * four meshes (0.5, 1, 2 and 4 tried); for leaf children too (sgate),
 * a separate factor for leaves of 1, 2, 4, 8 and 16 was tried, and 2
 * was lowest on gears and bumpy. */
#define PACKET_WIDE_BOX_GATE 2.0f

struct packet_entry {
    uint32_t child;
    uint32_t count; /* 0: wide node, else a leaf lane */
    unsigned rays;  /* the rays that enter it */
    float t_entry;  /* the smallest of their entry distances */
};

/* The rays of a packet: the single walk's state per ray, its near and
 * far bound rows per axis and its octant (traverse_wide.h). */
struct packet_state {
    struct wide_state s[TRACE_PACKET];
    int near_row[TRACE_PACKET][3];
    int far_row[TRACE_PACKET][3];
    int octant[TRACE_PACKET];
#if defined(__AVX__)
    struct tri8_rays t8;
    unsigned lanes8; /* the rays t8 holds: those with the first ray's kx, ky, kz */
    int t8_ready;    /* t8 set up (at the first leaf that uses it) */
    /* Each ray's limit for the eight-ray test (wide_leaf's: the next
     * float above its best once it has a hit); kept up to date wherever
     * a ray's best changes (packet_take_hit, packet_sync). */
    float limit[TRACE_PACKET];
    /* Each ray's box_limit beside its state's (-inf for a lane without
     * a ray), kept up to date with limit, so that packet_walk8_ia reads
     * the rays' limits as one vector after a leaf. */
    float box_limit[TRACE_PACKET];
    unsigned found;          /* the closest-hit rays with a hit (s[r].found) */
    /* packet_leaf8 takes a closest hit in the lanes: each ray's best t
     * (s[r].best), and for the rays of `dirty` the hit it took there,
     * not yet written to s[r] (packet_flush). */
    float best[TRACE_PACKET];
    float hit_u[TRACE_PACKET], hit_v[TRACE_PACKET];
    uint32_t hit_prim[TRACE_PACKET];
    unsigned dirty;
    uint64_t triangle_tests; /* those of packet_leaf8, for all its rays */
    /* The interval walk (packet_walk8_ia): the packet's bounds per axis
     * (broadcast), and the rays in the lanes for the leaf boxes. */
    __m256 ia_o_near[3], ia_o_far[3], ia_i_lo[3], ia_i_hi[3], ia_tmin;
    __m256 ia_i_near[3]; /* i_lo (inv > 0) or i_hi (inv < 0): packet_ia_init */
    __m256 lane_f[TRI8_F_COUNT]; /* the rays' fields in the lanes (tri8_lanes_load) */
    int ia_masks; /* rays from more than one origin: see packet_walk8_ia */
    float ia_leaf_t; /* a leaf child entered before this takes no lane test (packet_ia_init) */
    /* Several origins: the largest spread of the origins and of the
     * directions over the axes, times PACKET_WIDE_BOX_GATE, broadcast. */
    __m256 ia_sp_o, ia_sp_d;
    int ia_octant;                  /* the rays' common octant */
    int ia_row_near[3], ia_row_far[3]; /* its near and far rows, byte offsets */
    unsigned r4_ready;              /* packet_walk8_ia: the rays whose s[r].r4 is set up */
    /* The packet's arguments, for a ray's state set up at its first use
     * (packet_ready): the interval walk keeps most rays in the lanes
     * from start to end, and never needs their states. */
    const struct trace_ray *rays;
    const float *t_max;
    /* The first ray's kx, ky, kz (the eight-ray test's permutation). */
    int k0[3];
    /* rays points at the caller's structs, or (the entries from the
     * caller's arrays, packet_run) at ray_buf, which holds the rays only
     * once rays_ready is set (packet_rays_ready): the interval walk of a
     * coherent packet mostly never reads them. */
    int rays_ready;
    struct trace_ray ray_buf[TRACE_PACKET];
    struct trace_hit *hits;
    int any_hit;
    unsigned s_ready;    /* the rays whose s[r] is set up */
    uint64_t node_tests; /* tests not counted in a ray's state (packet_walk8_ia) */
#endif
};

#if defined(__AVX__)
/* The rays' structs, for the per-ray steps that read them (a ray's state,
 * packet_box8_rows): already there (rays_ready), or stored from the
 * lanes into ray_buf once a packet (the entries from the caller's arrays;
 * the lanes of rays left out hold a live ray's fields, stored too). */
#if defined(RT_TRACE_PACKET_INIT_LANES)
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void packet_rays_store(struct packet_state *p)
{
    packet_init_store(p->lane_f, 0xffu, p->ray_buf);
    p->rays_ready = 1;
}
#endif

/* The test inline, the stores out of line (an out-of-line test cost the
 * soup's shadow packets about 5 instructions a ray). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_rays_ready(struct packet_state *p)
{
#if defined(RT_TRACE_PACKET_INIT_LANES)
    if (!p->rays_ready)
        packet_rays_store(p);
#else
    (void)p;
#endif
}

/* Ray r's state, set up as walk_wide sets it (no hit, the limits of its
 * t_max) at its first use; a hit taken in the lanes before that is in
 * the lanes only (dirty: packet_flush writes it). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline struct wide_state *packet_ready(struct packet_state *p, unsigned r)
{
    struct wide_state *s = &p->s[r];
    if (!(p->s_ready >> r & 1u)) {
        packet_rays_ready(p);
        p->s_ready |= 1u << r;
        wide_state_init(s, &p->rays[r], p->t_max[r], p->any_hit,
                        p->any_hit ? NULL : &p->hits[r]);
    }
    return s;
}

/* A packet hits a triangle: walk_leaf's limit and hit rule for ray r
 * (wide_leaf_impl), t, u, v the triangle test's.  Returns 1 when an
 * any-hit ray has its hit. */
static inline int packet_take_hit(struct packet_state *p, unsigned r, uint32_t prim, float t,
                                  float u, float w)
{
    struct wide_state *s = &p->s[r];
    if (s->any_hit) {
        s->found = 1;
        return 1;
    }
    if (wide_take_closest(s, prim, t, u, w)) {
        p->limit[r] = isect_next_up(t);
        p->box_limit[r] = s->box_limit;
        p->best[r] = t;
        p->found |= 1u << r;
    }
    return 0;
}

/* Writes ray r's hit taken in the lanes (packet_leaf8) to its state, as
 * wide_take_closest would have: found, best, box_limit and the hit. */
static inline void packet_flush(struct packet_state *p, unsigned r)
{
    struct wide_state *s = &p->s[r];
    s->found = 1;
    s->best = p->best[r];
    s->box_limit = p->box_limit[r];
    s->hit->t = p->best[r];
    s->hit->u = p->hit_u[r];
    s->hit->v = p->hit_v[r];
    s->hit->prim = p->hit_prim[r];
    p->dirty &= ~(1u << r);
}

static inline void packet_flush_all(struct packet_state *p)
{
    for (unsigned m = p->dirty; m; m &= m - 1u)
        packet_flush(p, (unsigned)__builtin_ctz(m));
}

/* struct trace_hit is t, u, v, prim: four 4-byte fields in this order
 * (packet_store_hits writes it as one 16-byte lane group). */
typedef char packet_hit_is_16_bytes[sizeof(struct trace_hit) == 16 &&
                                            offsetof(struct trace_hit, u) == 4 &&
                                            offsetof(struct trace_hit, v) == 8 &&
                                            offsetof(struct trace_hit, prim) == 12
                                        ? 1
                                        : -1];

/* Writes the hits taken in the lanes (the rays of p->dirty) to the
 * caller's hits, as packet_flush's four field stores per ray would: t,
 * u, v and prim of the eight rays transposed into a 16-byte group per ray
 * (a 4 x 4 transpose in each 128-bit half, then the halves paired), and
 * stored two rays at a time with a mask of the dirty rays' lanes, so the
 * same bytes are written and no others (vmaskmovps leaves masked lanes'
 * memory alone).  A pair is stored only when one of its rays is dirty:
 * its first entry is then one of the caller's hits.  Measured
 * (docs/performance-log.md, pkouter): 2.7 instructions a gears camera
 * ray against 6.6 for a loop of four field stores per dirty ray. */
static inline void packet_store_hits(const struct packet_state *p)
{
    const unsigned dirty = p->dirty;
    if (!dirty)
        return;
    const __m256 t = _mm256_loadu_ps(p->best);
    const __m256 u = _mm256_loadu_ps(p->hit_u);
    const __m256 v = _mm256_loadu_ps(p->hit_v);
    const __m256 w = _mm256_loadu_ps((const float *)p->hit_prim);
    const __m256 tu_lo = _mm256_unpacklo_ps(t, u), tu_hi = _mm256_unpackhi_ps(t, u);
    const __m256 vw_lo = _mm256_unpacklo_ps(v, w), vw_hi = _mm256_unpackhi_ps(v, w);
    /* h[r]: ray r in its low half, ray r + 4 in its high half. */
    const __m256 h0 = _mm256_shuffle_ps(tu_lo, vw_lo, 0x44);
    const __m256 h1 = _mm256_shuffle_ps(tu_lo, vw_lo, 0xee);
    const __m256 h2 = _mm256_shuffle_ps(tu_hi, vw_hi, 0x44);
    const __m256 h3 = _mm256_shuffle_ps(tu_hi, vw_hi, 0xee);
    const __m256 pair[4] = {
        _mm256_permute2f128_ps(h0, h1, 0x20), _mm256_permute2f128_ps(h2, h3, 0x20),
        _mm256_permute2f128_ps(h0, h1, 0x31), _mm256_permute2f128_ps(h2, h3, 0x31)};
    /* A pair whose two rays are dirty is written whole by a plain
     * store (the same 32 bytes the masked store would write); only a
     * pair with one dirty ray needs a mask.  VEX vmaskmovps to memory is
     * microcoded on AMD's cores (Agner Fog's instruction tables, Zen 2-4:
     * a dozen cycles or more a store) and a camera packet of the kitchen
     * has all eight rays dirty; AVX-512VL's masked store (a k mask) is
     * an ordinary store there.  Masked lanes' memory is left alone either
     * way, so the bytes written are the same as before. */
#if !defined(__AVX512VL__)
    const __m256i bit = _mm256_setr_epi32(1, 1, 1, 1, 2, 2, 2, 2);
#endif
    for (int k = 0; k < 4; k++) {
        const unsigned two = dirty >> (2 * k) & 3u;
        if (!two)
            continue;
        float *out = (float *)(void *)&p->hits[2 * k];
        if (two == 3u) {
            _mm256_storeu_ps(out, pair[k]);
            continue;
        }
#if defined(__AVX512VL__)
        _mm256_mask_storeu_ps(out, (__mmask8)(two == 1u ? 0x0fu : 0xf0u), pair[k]);
#else
        const __m256i mask = _mm256_cmpeq_epi32(
            _mm256_and_si256(_mm256_set1_epi32((int)two), bit), bit);
        _mm256_maskstore_ps(out, mask, pair[k]);
#endif
    }
}

/* Ray r's limit after its best changed outside packet_leaf8 (a per-ray
 * leaf or walk). */
static inline void packet_sync(struct packet_state *p, unsigned r)
{
    p->limit[r] = p->s[r].found ? isect_next_up(p->s[r].best) : p->s[r].best;
    p->box_limit[r] = p->s[r].box_limit;
    p->best[r] = p->s[r].best;
    p->found |= (unsigned)(p->s[r].found != 0) << r;
}

/*
 * The triangles of packets q and q + 1 (bit l: triangle l of q; bit 4 + l:
 * triangle l of q + 1), a leaf of more than four triangles (at most
 * eight, BVH_WIDE_MAX_LEAF, asserted in collapse4.c: two triangle
 * packets), whose own box passes the
 * interval walk's test (packet_walk8_ia, packet_ia_init) with exit bound
 * limit_hi (at least every ray's box_limit).  The box is the least and
 * greatest of the triangle's three vertices per axis (exact: min and max
 * round nothing), so it holds the whole triangle.  A triangle whose box
 * fails has no hit for any ray of the packet at or below the ray's
 * limit: the interval test passes every box that one ray's own slab test
 * (walk_wide8's, with its box_limit) enters (packet_ia_init), and a ray
 * whose own test refuses a box has no hit at or below its best on
 * anything the box holds: the property every box of the walk relies on
 * (the single walk skips such a box, whatever triangles it holds; here
 * the box is one triangle's).  So the triangle needs no tri8_test, which
 * would find no hit for any lane: the leaf's triangles are tested as the
 * walk tests a node's children (Wald, Boulos and Shirley 2007 sec. 4.2,
 * the packet's interval bounds against a box).  A zero-area triangle's
 * lane (NaNs) may pass or fail: tri8_test refuses it for every lane
 * either way.  Float max and min fold the bounds here (the walk's
 * integer maximum gives the same number, packet_walk8_ia; only a
 * triangle that no ray can hit may fail, so no bound needs to be the
 * walk's to the bit).
 */
static inline unsigned packet_tri_beam(const struct packet_state *p, const struct tri4_packet *q,
                                       __m256 limit_hi)
{
    const __m256 scale = _mm256_set1_ps(ISECT_BOX_FAR_SCALE);
    __m256 t0 = p->ia_tmin;
    __m256 t1 = limit_hi;
    for (int k = 0; k < 3; k++) {
        /* Lanes 0-3 the triangles of q, lanes 4-7 those of q + 1: the
         * leaf's two triangle packets in one pass, each lane the same
         * operations as a four-lane pass would give it. */
        const __m256 a = _mm256_loadu2_m128(q[1].v[0][k], q[0].v[0][k]);
        const __m256 b = _mm256_loadu2_m128(q[1].v[1][k], q[0].v[1][k]);
        const __m256 c = _mm256_loadu2_m128(q[1].v[2][k], q[0].v[2][k]);
        const __m256 lo = _mm256_min_ps(_mm256_min_ps(a, b), c);
        const __m256 hi = _mm256_max_ps(_mm256_max_ps(a, b), c);
        const int neg = p->ia_octant >> k & 1;
        const __m256 dn = _mm256_sub_ps(neg ? hi : lo, p->ia_o_near[k]);
        const __m256 df = _mm256_sub_ps(neg ? lo : hi, p->ia_o_far[k]);
        t0 = _mm256_max_ps(_mm256_mul_ps(dn, p->ia_i_near[k]), t0);
        t1 = _mm256_min_ps(_mm256_mul_ps(_mm256_max_ps(_mm256_mul_ps(df, p->ia_i_lo[k]),
                                                       _mm256_mul_ps(df, p->ia_i_hi[k])),
                                         scale),
                           t1);
    }
    return (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(t0, t1, _CMP_LE_OQ));
}

/* A leaf lane (count triangles in packets from `first`) for the rays of
 * `rays`, all in p->lanes8: each triangle against all of them at once
 * (tri8_test), in wide_leaf's order of triangles, each ray with
 * wide_leaf's limit (the next float above its best once it has a hit)
 * and hit rule, and the triangle counts wide_leaf keeps.  The hit a ray
 * keeps does not depend on the order of its tests (traverse_walk.h), and
 * each test is isect_triangle's answer for that ray and limit.  Returns
 * the any-hit rays that found their hit. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned packet_leaf8_body(struct packet_state *p,
                                         const struct tri4_packet *packets, uint32_t first,
                                         uint32_t count, unsigned rays, int any_hit, int pair,
                                         int beam, __m256 limit_hi)
{
    if (!p->t8_ready) {
        /* lanes8 holds the first ray: its kx, ky, kz. */
        tri8_rays_init(&p->t8, p->lane_f, p->k0[0], p->k0[1], p->k0[2]);
        p->t8_ready = 1;
    }
    float *limit = p->limit;
    const int kx = p->t8.kx, ky = p->t8.ky, kz = p->t8.kz;
    unsigned done = 0;
    /* The beam copy: the leaf's two triangle packets' boxes in one pass
     * before the first tri8_test (packet_tri_beam).  limit_hi does not
     * change during the leaf, so the second packet's bits are those a
     * test after the first packet's triangles would give. */
    const unsigned beam_tris = beam ? packet_tri_beam(p, &packets[first], limit_hi) : 0u;
    /* Only an any-hit ray leaves `rays` (packet_take_hit returns 1 for
     * it alone); a closest-hit leaf keeps all its rays, so its loops do
     * not test for an empty packet (measured, docs/performance-log.md,
     * kpk: -0.5 to -1.8 % of the kernel's instructions a ray). */
    for (uint32_t j = 0; j < count && (!any_hit || rays); j += 4) {
        const struct tri4_packet *q = &packets[first + j / 4];
        const uint32_t n = count - j < 4 ? count - j : 4;
        p->triangle_tests += n * (unsigned)__builtin_popcount(rays);
        const float *const vk[3] = {q->v[0][kx], q->v[0][ky], q->v[0][kz]};
        /* The triangles to test: all, or for few rays those whose
         * first exit passes one of them (tri8_pair_filter). */
        unsigned tris = (1u << n) - 1u;
        if (beam) {
            /* The interval walk's packet: the triangles whose box its
             * interval test passes (packet_tri_beam). */
            tris &= beam_tris >> j;
            if (!tris)
                continue;
        }
        if (pair) {
            unsigned pass = 0;
            for (unsigned m = rays; m;) {
                const unsigned a = (unsigned)__builtin_ctz(m);
                m &= m - 1u;
                const unsigned b = m ? (unsigned)__builtin_ctz(m) : a;
                m &= m - 1u;
                pass |= tri8_pair_filter(&p->t8, vk, a, b);
            }
            tris &= (pass | pass >> 4);
        }
        for (uint32_t l = 0; l < n && (!any_hit || rays); l++) {
            if (pair || beam) {
                /* The next triangle to test (pair and beam are
                 * constants: the other copies keep the plain loop). */
                if (!tris)
                    break;
                l = (uint32_t)__builtin_ctz(tris);
                tris &= tris - 1u;
            }
            struct tri8_result res;
            if (!tri8_test(&p->t8, q, vk, l, rays, _mm256_loadu_ps(limit), any_hit, &res))
                continue;
            unsigned lanes = res.hit | res.scalar;
            if (any_hit) {
                /* An any-hit ray with a hit in the lanes is done, as
                 * packet_take_hit would return it, without the per-ray
                 * step: its state is never read again (the walk drops
                 * done rays; the answer is the mask).  Measured
                 * (docs/performance-log.md, pk5): kitchen shadow
                 * packets -22.7 instructions a ray, gears -9.7, bumpy
                 * -16.3 (AVX2). */
                done |= res.hit;
                rays &= ~res.hit;
                lanes &= ~res.hit;
            } else if (res.hit) {
                /* wide_take_closest in the lanes for the rays without a
                 * hit or with t < best (t <= best, as t < limit, the
                 * next float above best); a tie t == best, decided by
                 * the primitive, takes the scalar rule below. */
                const __m256 t = res.t;
                const __m256 best = _mm256_loadu_ps(p->best);
                const unsigned below =
                    (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(t, best, _CMP_NEQ_UQ));
                const unsigned take = res.hit & (~p->found | below);
                if (take) {
                    const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
                    const __m256 m8 = _mm256_castsi256_ps(_mm256_cmpeq_epi32(
                        _mm256_and_si256(_mm256_set1_epi32((int)take), bit), bit));
                    /* isect_next_up: the bits + 1, or the least
                     * denormal for t == 0. */
                    const __m256 up = _mm256_blendv_ps(
                        _mm256_castsi256_ps(
                            _mm256_add_epi32(_mm256_castps_si256(t), _mm256_set1_epi32(1))),
                        _mm256_set1_ps(0x1p-149f),
                        _mm256_cmp_ps(t, _mm256_setzero_ps(), _CMP_EQ_OQ));
                    _mm256_storeu_ps(p->best, _mm256_blendv_ps(best, t, m8));
                    _mm256_storeu_ps(limit, _mm256_blendv_ps(_mm256_loadu_ps(limit), up, m8));
                    _mm256_storeu_ps(
                        p->box_limit,
                        _mm256_blendv_ps(_mm256_loadu_ps(p->box_limit),
                                         _mm256_mul_ps(t, _mm256_set1_ps(ISECT_BOX_FAR_SCALE)),
                                         m8));
                    _mm256_storeu_ps(p->hit_u, _mm256_blendv_ps(_mm256_loadu_ps(p->hit_u),
                                                                res.u, m8));
                    _mm256_storeu_ps(p->hit_v, _mm256_blendv_ps(_mm256_loadu_ps(p->hit_v),
                                                                res.v, m8));
                    _mm256_storeu_ps((float *)p->hit_prim,
                                     _mm256_blendv_ps(_mm256_loadu_ps((const float *)p->hit_prim),
                                                      _mm256_castsi256_ps(_mm256_set1_epi32(
                                                          (int)q->prim[l])),
                                                      m8));
                    p->found |= take;
                    p->dirty |= take;
                    lanes &= ~take;
                }
            }
            float res_t[8], res_u[8], res_v[8];
            if (lanes & res.hit) {
                _mm256_storeu_ps(res_t, res.t);
                _mm256_storeu_ps(res_u, res.u);
                _mm256_storeu_ps(res_v, res.v);
            }
            for (unsigned m = lanes; m; m &= m - 1u) {
                const unsigned r = (unsigned)__builtin_ctz(m);
                struct wide_state *s = packet_ready(p, r);
                float t, u, w;
                if (res.hit >> r & 1u) {
                    t = res_t[r];
                    u = res_u[r];
                    w = res_v[r];
                } else {
                    float v[3][3];
                    for (int a = 0; a < 3; a++) {
                        for (int k = 0; k < 3; k++)
                            v[a][k] = q->v[a][k][l];
                    }
                    if (!isect_triangle(s->ray, v[0], v[1], v[2], limit[r], &t, &u, &w))
                        continue;
                }
                if (p->dirty >> r & 1u)
                    packet_flush(p, r);
                if (packet_take_hit(p, r, q->prim[l], t, u, w)) {
                    done |= 1u << r;
                    rays &= ~(1u << r);
                }
            }
        }
    }
    return done;
}

/* packet_leaf8_body for `rays`: with few rays, their triangles' first
 * exits by pairs of rays first (tri8_pair_filter), and tri8_test only for
 * the triangles one of them passes (the others tri8_test would leave at
 * its first exit without effects); otherwise each triangle against all
 * of them, or, beam (the interval walk's packets, limit_hi its exit
 * bound), each triangle whose box the packet's interval test passes
 * (packet_tri_beam) when the leaf holds more than PACKET_BEAM_MIN
 * triangles.  Three copies, so that the common cases keep their plain
 * loop (the copy with the box test loops over its mask). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned packet_leaf8(struct packet_state *p, const struct tri4_packet *packets,
                                    uint32_t first, uint32_t count, unsigned rays, int any_hit,
                                    int beam, __m256 limit_hi)
{
    /* The triangles' boxes against the packet's interval test
     * (packet_tri_beam) only with more rays than the pair filter takes:
     * few rays of a packet pass the first exits of few triangles, which
     * the pair filter finds for less, and the whole packet's interval
     * bounds are loose around them (measured, docs/performance-log.md,
     * pk16: at most four rays, 56-98 % of the triangles passed the box
     * test; eight rays of a kitchen camera packet, 22 %). */
    if ((unsigned)__builtin_popcount(rays) <= PACKET_PAIR_MAX)
        return packet_leaf8_body(p, packets, first, count, rays, any_hit, 1, 0, limit_hi);
    if (beam && count > PACKET_BEAM_MIN)
        return packet_leaf8_body(p, packets, first, count, rays, any_hit, 0, 1, limit_hi);
    return packet_leaf8_body(p, packets, first, count, rays, any_hit, 0, 0, limit_hi);
}
#endif

/* Ray r against the four children of n: walk_wide4's operations.  Adds
 * r's bit to rays[l] for each child l it enters and folds its entry
 * distances into *t_min. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_box4(const struct bvh4_node *n, struct packet_state *p, unsigned r,
                               __m128 *rays, __m128 *t_min)
{
    const struct trace_ray *ray = p->s[r].ray;
    __m128 t0 = _mm_set1_ps(ray->tmin);
    __m128 t1 = _mm_set1_ps(INFINITY);
    for (int k = 0; k < 3; k++) {
        const __m128 o = _mm_set1_ps(ray->org[k]);
        const __m128 inv = _mm_set1_ps(ray->inv_dir[k]);
        const __m128 tn = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n->bounds[p->near_row[r][k]]), o), inv);
        const __m128 tf = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n->bounds[p->far_row[r][k]]), o), inv);
        t0 = _mm_max_ps(tn, t0);
        t1 = _mm_min_ps(tf, t1);
    }
    t1 = _mm_mul_ps(t1, _mm_set1_ps(ISECT_BOX_FAR_SCALE));
    t1 = _mm_min_ps(t1, _mm_set1_ps(p->s[r].box_limit));
    const __m128 in = _mm_cmple_ps(t0, t1);
    p->s[r].node_tests += 4;
    *rays = _mm_or_ps(*rays, _mm_and_ps(in, _mm_castsi128_ps(_mm_set1_epi32((int)(1u << r)))));
    *t_min = _mm_min_ps(*t_min, _mm_blendv_ps(_mm_set1_ps(INFINITY), t0, in));
}

#if defined(__AVX__)
/* Ray r against the eight children of n: walk_wide8's operations (the
 * caller counts the tests). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_box8_rows(const struct bvh8_node *n, struct packet_state *p,
                                    unsigned r, const int near_row[3], const int far_row[3],
                                    __m256 *rays, __m256 *t_min)
{
    const struct trace_ray *ray = &p->rays[r];
    __m256 t0 = _mm256_set1_ps(ray->tmin);
    __m256 t1 = _mm256_set1_ps(INFINITY);
    for (int k = 0; k < 3; k++) {
        const __m256 o = _mm256_set1_ps(ray->org[k]);
        const __m256 inv = _mm256_set1_ps(ray->inv_dir[k]);
        const __m256 tn =
            _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(wide_row(n->bounds, near_row[k])), o), inv);
        const __m256 tf =
            _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(wide_row(n->bounds, far_row[k])), o), inv);
        t0 = _mm256_max_ps(tn, t0);
        t1 = _mm256_min_ps(tf, t1);
    }
    t1 = _mm256_mul_ps(t1, _mm256_set1_ps(ISECT_BOX_FAR_SCALE));
    t1 = _mm256_min_ps(t1, _mm256_set1_ps(p->box_limit[r]));
    const __m256 in = _mm256_cmp_ps(t0, t1, _CMP_LE_OQ);
    *rays = _mm256_or_ps(*rays,
                         _mm256_and_ps(in, _mm256_castsi256_ps(_mm256_set1_epi32((int)(1u << r)))));
    *t_min = _mm256_min_ps(*t_min, _mm256_blendv_ps(_mm256_set1_ps(INFINITY), t0, in));
}

/* Ray r against the eight children of n: walk_wide8's operations on its
 * own near and far rows. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_box8(const struct bvh8_node *n, struct packet_state *p, unsigned r,
                               __m256 *rays, __m256 *t_min)
{
    const int size = (int)sizeof(n->bounds[0]);
    const int near_row[3] = {p->near_row[r][0] * size, p->near_row[r][1] * size,
                             p->near_row[r][2] * size};
    const int far_row[3] = {p->far_row[r][0] * size, p->far_row[r][1] * size,
                            p->far_row[r][2] * size};
    p->s[r].node_tests += 8;
    packet_box8_rows(n, p, r, near_row, far_row, rays, t_min);
}
#endif

/* The packet walk of a `width`-wide layout (4, or 8 with AVX); returns
 * the rays an any-hit walk found a hit for (0 for closest hit, whose
 * hits are in the states). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned packet_walk(const struct bvh4 *wide, struct packet_state *p,
                                   unsigned active, unsigned hybrid, const uint32_t width)
{
    struct packet_entry stack[WIDE_STACK];
    uint32_t sp = 0;
    uint32_t cur = 0, cur_count = 0;
    unsigned rays = active;
    unsigned done = 0;
    for (;;) {
        if ((unsigned)__builtin_popcount(rays) < hybrid) {
            /* Hybrid: the few rays left take the single walk from here. */
            for (unsigned m = rays; m; m &= m - 1u) {
                const unsigned r = (unsigned)__builtin_ctz(m);
                int found;
#if defined(__AVX__)
                if (width == 8)
                    found = walk_wide8(wide, &p->s[r], cur, cur_count);
                else
#endif
                    found = walk_wide4(wide, &p->s[r], cur, cur_count);
#if defined(__AVX__)
                packet_sync(p, r);
#endif
                if (found)
                    done |= 1u << r;
            }
        } else if (cur_count) {
            unsigned single = rays;
#if defined(__AVX__)
            const unsigned r8 = rays & p->lanes8;
            if ((unsigned)__builtin_popcount(r8) >= PACKET_TRI8_MIN) {
                done |= packet_leaf8(p, wide->packets, cur, cur_count, r8,
                                     p->s[__builtin_ctz(r8)].any_hit, 0, _mm256_setzero_ps());
                packet_flush_all(p);
                single &= ~r8;
            }
#endif
            for (unsigned m = single; m; m &= m - 1u) {
                const unsigned r = (unsigned)__builtin_ctz(m);
                if (wide_leaf(&p->s[r], wide->packets, cur, cur_count))
                    done |= 1u << r;
#if defined(__AVX__)
                packet_sync(p, r);
#endif
            }
        } else {
            uint32_t lane_rays[8];
            float t_min[8];
            const uint32_t *child;
            const uint8_t *count;
            uint32_t order; /* 3 bits per position */
            const int octant = p->octant[__builtin_ctz(rays)];
#if defined(__AVX__)
            if (width == 8) {
                const struct bvh8_node *n = &wide->nodes8[cur];
                __m256 tm = _mm256_set1_ps(INFINITY);
                __m256 in = _mm256_setzero_ps();
                for (unsigned m = rays; m; m &= m - 1u)
                    packet_box8(n, p, (unsigned)__builtin_ctz(m), &in, &tm);
                _mm256_storeu_ps((float *)lane_rays, in);
                _mm256_storeu_ps(t_min, tm);
                child = n->child;
                count = n->count;
                order = (uint32_t)n->order[octant][0] | (uint32_t)n->order[octant][1] << 8 |
                        (uint32_t)n->order[octant][2] << 16;
            } else
#endif
            {
                const struct bvh4_node *n = &wide->nodes[cur];
                __m128 in = _mm_setzero_ps();
                __m128 tm = _mm_set1_ps(INFINITY);
                for (unsigned m = rays; m; m &= m - 1u)
                    packet_box4(n, p, (unsigned)__builtin_ctz(m), &in, &tm);
                _mm_storeu_ps((float *)lane_rays, in);
                _mm_storeu_ps(t_min, tm);
                child = n->child;
                count = n->count;
                order = 0;
                for (int q = 0; q < 4; q++)
                    order |= (uint32_t)(n->order[octant] >> (2 * q) & 3u) << (3 * q);
            }
            const uint32_t sp0 = sp;
            for (int q = (int)width - 1; q >= 0; q--) {
                const unsigned l = order >> (3 * q) & 7u;
                if (!lane_rays[l])
                    continue;
                stack[sp].child = child[l];
                stack[sp].count = count[l];
                stack[sp].rays = lane_rays[l];
                stack[sp].t_entry = t_min[l];
                sp++;
            }
            if (sp != sp0) {
                sp--;
                cur = stack[sp].child;
                cur_count = stack[sp].count;
                rays = stack[sp].rays;
                continue;
            }
        }
        for (;;) {
            if (sp == 0)
                return done;
            sp--;
            rays = stack[sp].rays & ~done;
            /* The rays whose closest hit lies in front of the subtree
             * leave it, as the single walk's pop skips it. */
            const float t_entry = stack[sp].t_entry;
            for (unsigned m = rays; m; m &= m - 1u) {
                const unsigned r = (unsigned)__builtin_ctz(m);
                if (!(t_entry <= p->s[r].box_limit))
                    rays &= ~(1u << r);
            }
            if (rays)
                break;
        }
        cur = stack[sp].child;
        cur_count = stack[sp].count;
    }
}

#if defined(__AVX__)
static inline float packet_hmin(__m256 v)
{
    __m128 m = _mm_min_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    m = _mm_min_ps(m, _mm_movehl_ps(m, m));
    m = _mm_min_ss(m, _mm_shuffle_ps(m, m, 1));
    return _mm_cvtss_f32(m);
}

static inline float packet_hmax(__m256 v)
{
    __m128 m = _mm_max_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    m = _mm_max_ps(m, _mm_movehl_ps(m, m));
    m = _mm_max_ss(m, _mm_shuffle_ps(m, m, 1));
    return _mm_cvtss_f32(m);
}

/*
 * Sets up the interval walk when it applies: every active ray in one
 * octant, with finite non-zero inverse directions, finite origins and
 * tmin >= 0 (not NaN).  Returns 0 otherwise (the packet takes
 * packet_walk).
 *
 * Per axis k, with the octant's near and far rows shared by all rays,
 * the interval test bounds every ray's own slab distances
 * fl(fl(b - o) * inv) (Wald, Boulos and Shirley 2007 sec. 4.2; Boulos et
 * al.'s interval arithmetic; Reshetov, Soupikov and Hurley 2005): in
 * round-to-nearest, fl(b - o) does not increase with o, and fl(d * i),
 * for i of one sign, is monotone in d and, for fixed d, in i; so over
 * the packet's ranges o in [o_lo, o_hi], i in [i_lo, i_hi] the least near
 * distance is min(fl(d * i_lo), fl(d * i_hi)) with d = fl(b - o_hi) (inv >
 * 0) or fl(b - o_lo) (inv < 0), and the greatest far distance the max of
 * the same two products with the other end of the origin range.  No
 * value is NaN (finite origins and inverses; the empty box of an unused
 * child gives +-inf), and max, min and the far scale are monotone, so the
 * packet's entry bound is at most each ray's entry, its exit bound at
 * least each ray's exit: a child that one ray's own test enters passes.
 *
 * The near distance takes one product, fl(d * i_lo) (inv > 0) or
 * fl(d * i_hi) (inv < 0), instead of the smaller of the two: that is the
 * smaller where d * inv >= 0, and where d * inv < 0 (the origins past
 * the child's near plane) both products are <= 0 <= tmin <= the entry
 * bound it is folded into by max, which returns that bound either way
 * (the walk's maximum of the bits as integers, packet_walk8_ia: a
 * product -0 or below is a negative integer and +0 is 0, neither above
 * tmin's bits, made >= +0 here).  So the entry bound is the same number as with both products
 * (the walk visits the same nodes), for one multiply and one min fewer
 * per axis.  Measured (docs/performance-log.md, kpk): the
 * packet kernel's instructions a ray -1.0 % on the kitchen's and bumpy's
 * camera packets.
 */
static inline int packet_ia_init(struct packet_state *p, unsigned active,
                                 const __m256 f_min[2], const __m256 f_max[2],
                                 float leaf_extent)
{
    /* The rays' fields in the lanes (packet_run: a lane without a ray
     * holds the first ray's, never read into an answer: masked by the
     * packet's rays). */
    const unsigned first = (unsigned)__builtin_ctz(active);
    const __m256 sign = _mm256_set1_ps(-0.0f);
    const __m256 inf = _mm256_set1_ps(INFINITY);
    __m256 ok = _mm256_cmp_ps(_mm256_setzero_ps(), _mm256_setzero_ps(), _CMP_EQ_OQ);
    int octant = 0;
    for (int k = 0; k < 3; k++) {
        const __m256 o = p->lane_f[TRI8_F_ORG + k];
        const __m256 i = p->lane_f[TRI8_F_INV + k];
        const __m256 abs_i = _mm256_andnot_ps(sign, i);
        ok = _mm256_and_ps(ok, _mm256_cmp_ps(_mm256_andnot_ps(sign, o), inf, _CMP_LT_OQ));
        ok = _mm256_and_ps(ok, _mm256_cmp_ps(abs_i, inf, _CMP_LT_OQ));
        ok = _mm256_and_ps(ok, _mm256_cmp_ps(abs_i, _mm256_setzero_ps(), _CMP_GT_OQ));
        /* One octant: every lane's sign bit as the first ray's (the bit
         * signbit() reads, as the single walk's near/far choice). */
        const unsigned signs = (unsigned)_mm256_movemask_ps(i);
        const int neg = (int)(signs >> first & 1u);
        if (signs != (neg ? 0xffu : 0u))
            return 0;
        octant |= neg << k;
        /* The least and greatest over the rays, broadcast
         * (tri8_lanes_load's f_min, f_max: field F in lane F % 8 of
         * half F / 8).  Only read when every value is finite (ok), where
         * min and max do not depend on the order of the rays but for
         * the sign of a zero, which no comparison sees. */
        const int fi = TRI8_F_INV + k;
        const __m256i at_o = _mm256_set1_epi32(TRI8_F_ORG + k);
        const __m256i at_i = _mm256_set1_epi32(fi % 8);
        const __m256 o_lo = _mm256_permutevar8x32_ps(f_min[0], at_o);
        const __m256 o_hi = _mm256_permutevar8x32_ps(f_max[0], at_o);
        p->ia_o_near[k] = neg ? o_lo : o_hi;
        p->ia_o_far[k] = neg ? o_hi : o_lo;
        p->ia_i_lo[k] = _mm256_permutevar8x32_ps(f_min[fi / 8], at_i);
        p->ia_i_hi[k] = _mm256_permutevar8x32_ps(f_max[fi / 8], at_i);
        p->ia_i_near[k] = neg ? p->ia_i_hi[k] : p->ia_i_lo[k];
        p->ia_row_near[k] = (neg ? 3 + k : k) * (int)sizeof(((struct bvh8_node *)0)->bounds[0]);
        p->ia_row_far[k] = (neg ? k : 3 + k) * (int)sizeof(((struct bvh8_node *)0)->bounds[0]);
    }
    const __m256 tmin = p->lane_f[TRI8_F_TMIN];
    ok = _mm256_and_ps(ok, _mm256_cmp_ps(tmin, _mm256_setzero_ps(), _CMP_GE_OQ));
    if ((unsigned)_mm256_movemask_ps(ok) != 0xffu)
        return 0;
    /* Rays from more than one origin: o_lo != o_hi on an axis. */
    p->ia_masks =
        (_mm256_movemask_ps(_mm256_cmp_ps(f_min[0], f_max[0], _CMP_NEQ_UQ)) & 7) != 0;
    /* One origin: the distance up to which the beam is narrow against
     * the leaves, by the largest spread s of the rays' directions over
     * the axes (the beam's width grows by s per unit of t) and the
     * leaves' mean size L (bvh4_layout.h, leaf_extent): t * s *
     * PACKET_LEAF_GATE <= L.  Where the leaves are small against the
     * beam, the interval test passes leaf children between the rays that
     * no ray enters (bumpy), and testing each ray costs less than the
     * leaf's triangles; where they are wide, the rays enter every leaf
     * the interval passes, and the test only costs.  It chooses work,
     * never an answer (packet_walk8_ia). */
    p->ia_leaf_t = -INFINITY;
    if (!p->ia_masks && leaf_extent > 0.0f) {
        /* The directions' ranges (fields TRI8_F_DIR + 0..2 of f_min[0]
         * and f_max[0]) in lanes 0-3 (the first twice). */
        const __m256i dir = _mm256_setr_epi32(TRI8_F_DIR, TRI8_F_DIR + 1, TRI8_F_DIR + 2,
                                              TRI8_F_DIR, 0, 0, 0, 0);
        __m128 s = _mm256_castps256_ps128(
            _mm256_permutevar8x32_ps(_mm256_sub_ps(f_max[0], f_min[0]), dir));
        s = _mm_max_ps(s, _mm_movehl_ps(s, s));
        s = _mm_max_ss(s, _mm_shuffle_ps(s, s, 1));
        const float m = _mm_cvtss_f32(s) * PACKET_LEAF_GATE;
        p->ia_leaf_t = m > 0.0f ? leaf_extent / m : INFINITY;
    }
    if (p->ia_masks) {
        /* The directions' ranges in lanes 0-3 and the origins' in lanes
         * 4-7 (the first of each twice). */
        const __m256i dir = _mm256_setr_epi32(TRI8_F_DIR, TRI8_F_DIR + 1, TRI8_F_DIR + 2,
                                              TRI8_F_DIR, TRI8_F_ORG, TRI8_F_ORG + 1,
                                              TRI8_F_ORG + 2, TRI8_F_ORG);
        __m256 sp = _mm256_permutevar8x32_ps(_mm256_sub_ps(f_max[0], f_min[0]), dir);
        __m128 a = _mm256_castps256_ps128(sp), b = _mm256_extractf128_ps(sp, 1);
        a = _mm_max_ps(a, _mm_movehl_ps(a, a));
        a = _mm_max_ss(a, _mm_shuffle_ps(a, a, 1));
        b = _mm_max_ps(b, _mm_movehl_ps(b, b));
        b = _mm_max_ss(b, _mm_shuffle_ps(b, b, 1));
        p->ia_sp_d = _mm256_set1_ps(_mm_cvtss_f32(a) * PACKET_WIDE_BOX_GATE);
        p->ia_sp_o = _mm256_set1_ps(_mm_cvtss_f32(b) * PACKET_WIDE_BOX_GATE);
    }
    p->ia_octant = octant;
    /* The least tmin, -0 made +0 (maxps returns its second operand on
     * equal values) for the walk's integer maximum of the entry's bits. */
    p->ia_tmin = _mm256_max_ps(_mm256_permutevar8x32_ps(f_min[TRI8_F_TMIN / 8],
                                                        _mm256_set1_epi32(TRI8_F_TMIN % 8)),
                               _mm256_setzero_ps());
    return 1;
}

/*
 * The packet walk of the 8-wide layout by interval tests (Wald, Boulos
 * and Shirley 2007 sec. 4.2; Embree's coherent packet traversal does the
 * same with a packet frustum): an inner node's eight children are tested
 * once for the whole packet (packet_ia_init), and a child that passes is
 * entered by all the rays still in the walk; a leaf child that passes is
 * then tested ray by ray, the rays in the lanes, with walk_wide8's float
 * operations on each ray's own near and far planes, origin, inverse,
 * tmin and box_limit, so a leaf's triangles meet exactly the rays whose
 * own test enters its box, as in packet_walk.  An inner node a ray's own
 * test would not enter is visited with it anyway: that changes the node
 * counts, never a hit (traverse_wide.h: the hit rule does not depend on
 * which inner nodes are skipped or the order of visits, and every box
 * holding a hit at or below a ray's best passes its test).  By the same
 * argument a leaf may meet rays whose own test would not enter it: such
 * a ray finds no hit at or below its best there, so its triangle tests
 * change the counts only.  A one-origin packet uses this for the leaf
 * children the beam meets while it is narrow against the leaves
 * (packet_ia_init, ia_leaf_t): every ray enters them without a lane
 * test, as Embree's coherent walk has no test per ray of a leaf box.  A pushed
 * child keeps a lower bound of its rays' entry distances (the interval
 * test's, or the least of the rays' own for a lane-tested child of a
 * closest-hit packet); on pop, the rays whose box_limit lies before it
 * leave it, as the single walk's pop skips it.  A leaf's closest hits
 * are taken in the lanes (packet_leaf8) and written to a ray's state
 * only where a per-ray step reads it (packet_flush), and to the caller's
 * hits at the end.  A ray's state itself is set up only at its first
 * per-ray step (packet_ready): until then p->s[r] is not read.
 *
 * Rays from several origins (shadow rays from a row of hit points) make
 * the interval wide, and entering inner nodes with every ray then costs
 * more than it saves (measured: 3-6x the node tests per ray of the
 * per-ray walk on the soup and bumpy shadow rays), so such a packet
 * keeps exact ray masks (ia_masks): the interval test only culls, every
 * child that passes is tested ray by ray in the lanes like a leaf (but
 * a child, inner node or leaf, whose box is wide against the packet's
 * width there, PACKET_WIDE_BOX_GATE, which all the rays enter), and where
 * more children pass than there are rays, the rays' own tests over the
 * eight children (packet_box8_rows) take the node instead.  Measured in
 * docs/performance-log.md (k-packet, pgate, sgate).
 *
 * An inner node that only one ray enters (several-origin packets after
 * the lane tests, any packet after the pop cull) is left to that ray's
 * single walk (walk_wide8), as packet_walk does below its hybrid
 * threshold.
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned packet_walk8_ia(const struct bvh4 *wide, struct packet_state *p,
                                       unsigned active, int any_hit)
{
    struct packet_entry stack[WIDE_STACK];
    const struct bvh8_node *nodes = wide->nodes8;
    const int octant = p->ia_octant;
    const int *near_row = p->ia_row_near, *far_row = p->ia_row_far;
    const __m256 inf8 = _mm256_set1_ps(INFINITY);
    const __m256 scale8 = _mm256_set1_ps(ISECT_BOX_FAR_SCALE);
    /* The rays' box_limit in the lanes (unused lanes -inf, packet_run)
     * and their greatest, refreshed after each leaf (only hits shrink
     * them). */
    const __m256 leaf_t = _mm256_set1_ps(p->ia_leaf_t);
    __m256 bl = _mm256_loadu_ps(p->box_limit);
    __m256 limit_hi = _mm256_set1_ps(packet_hmax(bl));
    uint64_t node_tests = 0; /* the interval and lane tests and the rays' own */
    uint32_t sp = 0;
    uint32_t cur = 0, cur_count = 0;
    unsigned rays = active;
    unsigned done = 0;
    for (;;) {
        if (!cur_count && !(rays & (rays - 1u))) {
            /* One ray left at an inner node: the single walk from here
             * with the ray's own state, as packet_walk's hybrid step
             * (traverse_wide.h: the same hit).  Its own test of the
             * eight children costs less than the interval test over the
             * whole packet's ranges plus a lane test per passing child,
             * and its stack holds only its own entries.  A leaf with one
             * ray stays with the per-ray leaf below (the single walk's
             * set-up costs more there: bumpy, 2 rays per leaf). */
            const unsigned r = (unsigned)__builtin_ctz(rays);
            packet_ready(p, r);
            if (p->dirty >> r & 1u)
                packet_flush(p, r);
            if (!(p->r4_ready >> r & 1u)) {
                tri4_ray_init(&p->s[r].r4, p->s[r].ray);
                p->r4_ready |= 1u << r;
            }
            if (walk_wide8(wide, &p->s[r], cur, cur_count))
                done |= rays;
            packet_sync(p, r);
            if (!any_hit) {
                bl = _mm256_loadu_ps(p->box_limit);
                limit_hi = _mm256_set1_ps(packet_hmax(bl));
            }
        } else if (cur_count) {
            unsigned single = rays;
            const unsigned r8 = rays & p->lanes8;
            if ((unsigned)__builtin_popcount(r8) >= PACKET_TRI8_MIN) {
                /* The triangles' box test for closest-hit and any-hit
                 * packets alike, in leaves of more than PACKET_BEAM_MIN
                 * triangles, two triangle packets in one pass: the
                 * kitchen's shadow packets -8.4 % instructions, gears'
                 * -1.5 % but up to 2 % slower on the clock (their rays
                 * pass the boxes of about 80 % of the triangles they
                 * meet; pk16's one-packet form was 10-12 % slower there).
                 * docs/performance-log.md, pk16, pk18. */
                done |= packet_leaf8(p, wide->packets, cur, cur_count, r8, any_hit, 1, limit_hi);
                single &= ~r8;
            }
            for (unsigned m = single; m; m &= m - 1u) {
                const unsigned r = (unsigned)__builtin_ctz(m);
                packet_ready(p, r);
                if (p->dirty >> r & 1u)
                    packet_flush(p, r);
                if (!(p->r4_ready >> r & 1u)) {
                    tri4_ray_init(&p->s[r].r4, p->s[r].ray);
                    p->r4_ready |= 1u << r;
                }
                if (wide_leaf(&p->s[r], wide->packets, cur, cur_count))
                    done |= 1u << r;
                packet_sync(p, r);
            }
            if (!any_hit) {
                /* An any-hit ray's box_limit never shrinks: it ends at
                 * its first hit. */
                bl = _mm256_loadu_ps(p->box_limit);
                limit_hi = _mm256_set1_ps(packet_hmax(bl));
            }
        } else {
            const struct bvh8_node *n = &nodes[cur];
            /* The node's last cache line (child, count, order), read
             * only after the pass mask, requested beside the bounds'
             * three: otherwise a node that misses the cache waits for
             * two misses one after the other.  One line per node, not
             * the next node's four and the pushed children's (pk6, not
             * kept).  Measured (docs/performance-log.md, pk8): AVX2
             * instructions +0.02-0.04 %; camera and shadow packets up
             * in every alternated pair but one per set (gears' shadow
             * packets in all), the losing pairs runs whose Embree
             * figures fell as well. */
            _mm_prefetch((const char *)(const void *)n->child, _MM_HINT_T0);
            unsigned lane_rays[8];
            float t_min[8];
            node_tests += 8;
            /* The packet's entry bound max(z, max(y, max(x, tmin))) and
             * exit bound min(s * min(z, min(y, min(x, inf))), limit) were
             * four and five dependent operations of 4 cycles each between
             * the rows' loads and the pass mask, which the choice of the
             * next node waits for.  The same decision in fewer steps, as
             * the single walk's node test (traverse_wide8_ray.h):
             * - the entry as a signed integer maximum of the bits, a tree
             *   of 1-cycle operations: no value here is NaN
             *   (packet_ia_init) and ia_tmin >= +0, so the maximum is >=
             *   +0, where the integer order of the bits is the float
             *   order, and a negative product loses as it does to tmin
             *   in the float fold; a -0 entry may come out +0, the same
             *   number for every comparison made with it (the pass mask,
             *   the leaf gate, the stacked entry's cull);
             * - entry <= min(s * min(far x, y, z), limit) as four
             *   comparisons ANDed: rounding s * t is monotonic, so
             *   s * min(a, b) = min(s * a, s * b), and entry <= min holds
             *   exactly when it holds against each operand.
             * Measured (docs/performance-log.md, pk7): AVX2 instructions
             * +0.1-0.2 %; the kitchen's camera and shadow packets up
             * 0.2-7.3 % in every alternated pair, the camera packets of
             * gears and bumpy up in all pairs but one, their shadow
             * packets level. */
            __m256 ne[3], fa[3];
            for (int k = 0; k < 3; k++) {
                const __m256 dn = _mm256_sub_ps(_mm256_load_ps(wide_row(n->bounds, near_row[k])),
                                                p->ia_o_near[k]);
                const __m256 df = _mm256_sub_ps(_mm256_load_ps(wide_row(n->bounds, far_row[k])),
                                                p->ia_o_far[k]);
                /* One product for the near end (packet_ia_init). */
                ne[k] = _mm256_mul_ps(dn, p->ia_i_near[k]);
                fa[k] = _mm256_mul_ps(_mm256_max_ps(_mm256_mul_ps(df, p->ia_i_lo[k]),
                                                    _mm256_mul_ps(df, p->ia_i_hi[k])),
                                      scale8);
            }
            const __m256 t0 = _mm256_castsi256_ps(_mm256_max_epi32(
                _mm256_max_epi32(_mm256_castps_si256(ne[0]), _mm256_castps_si256(ne[1])),
                _mm256_max_epi32(_mm256_castps_si256(ne[2]), _mm256_castps_si256(p->ia_tmin))));
#if TRACE_AVX512_TABLE
            /* AVX-512: the comparisons into mask registers, ANDed as a
             * tree; the empty asm keeps GCC from chaining them as masked
             * compares (traverse_wide8_ray.h's note). */
            __mmask8 k0 = _mm256_cmp_ps_mask(t0, limit_hi, _CMP_LE_OQ);
            __mmask8 k1 = _mm256_cmp_ps_mask(t0, fa[0], _CMP_LE_OQ);
            __mmask8 k2 = _mm256_cmp_ps_mask(t0, fa[1], _CMP_LE_OQ);
            __mmask8 k3 = _mm256_cmp_ps_mask(t0, fa[2], _CMP_LE_OQ);
#if defined(__GNUC__)
            __asm__("" : "+k"(k0), "+k"(k1), "+k"(k2), "+k"(k3));
#endif
            const unsigned pass =
                (unsigned)_kand_mask8(_kand_mask8(k0, k1), _kand_mask8(k2, k3));
#else
            const unsigned pass = (unsigned)_mm256_movemask_ps(
                _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(t0, limit_hi, _CMP_LE_OQ),
                                            _mm256_cmp_ps(t0, fa[0], _CMP_LE_OQ)),
                              _mm256_and_ps(_mm256_cmp_ps(t0, fa[1], _CMP_LE_OQ),
                                            _mm256_cmp_ps(t0, fa[2], _CMP_LE_OQ))));
#endif
            unsigned push = 0; /* the children entered by at least one ray */
            if (p->ia_masks &&
                (unsigned)__builtin_popcount(pass) >= (unsigned)__builtin_popcount(rays)) {
                /* Rays from several origins, and more children pass
                 * than there are rays: the rays' own tests (one over
                 * the eight children per ray) cost less than one per
                 * child. */
                __m256 in = _mm256_setzero_ps();
                __m256 tm = inf8;
                packet_rays_ready(p);
                for (unsigned m = rays; m; m &= m - 1u)
                    packet_box8_rows(n, p, (unsigned)__builtin_ctz(m), near_row, far_row, &in,
                                     &tm);
                node_tests += 8u * (unsigned)__builtin_popcount(rays);
                _mm256_storeu_ps((float *)lane_rays, in);
                _mm256_storeu_ps(t_min, tm);
                push = (unsigned)_mm256_movemask_ps(
                    _mm256_cmp_ps(in, _mm256_setzero_ps(), _CMP_NEQ_UQ));
            } else if (pass) {
                _mm256_storeu_ps(t_min, t0);
                unsigned test = pass; /* the children tested ray by ray */
                if (!p->ia_masks) {
                    /* One origin: the interval test is tight, and an
                     * inner child is entered by every ray; so is a leaf
                     * child the beam meets before ia_leaf_t, where the
                     * leaves are wide against the beam (packet_ia_init),
                     * without a test per ray. */
                    const unsigned inner = (unsigned)_mm_movemask_epi8(_mm_cmpeq_epi8(
                        _mm_loadl_epi64((const __m128i *)(const void *)n->count),
                        _mm_setzero_si128()));
                    const unsigned near =
                        (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(t0, leaf_t, _CMP_LE_OQ));
                    test = pass & ~inner & ~near & 0xffu;
                    push = pass & ~test;
                    _mm256_storeu_si256((__m256i *)(void *)lane_rays,
                                        _mm256_set1_epi32((int)rays));
                } else {
                    /* Several origins: a child, inner node or leaf,
                     * whose box is wide against the packet's width
                     * where the interval meets it (the origins' spread
                     * plus the directions' spread times its entry
                     * bound, times PACKET_WIDE_BOX_GATE) is entered by
                     * every ray, as a one-origin packet's inner
                     * children: a ray whose own test would not enter
                     * it finds no hit in it at or below its best, and
                     * most rays enter such a box anyway.  For a leaf
                     * this trades the lane test for the triangle tests
                     * of the rays that miss its box. */
                    __m256 ext = _mm256_sub_ps(_mm256_load_ps(n->bounds[3]),
                                               _mm256_load_ps(n->bounds[0]));
                    ext = _mm256_max_ps(ext, _mm256_sub_ps(_mm256_load_ps(n->bounds[4]),
                                                           _mm256_load_ps(n->bounds[1])));
                    ext = _mm256_max_ps(ext, _mm256_sub_ps(_mm256_load_ps(n->bounds[5]),
                                                           _mm256_load_ps(n->bounds[2])));
                    const __m256 beam = _mm256_add_ps(
                        p->ia_sp_o,
                        _mm256_mul_ps(_mm256_max_ps(t0, _mm256_setzero_ps()), p->ia_sp_d));
                    const unsigned big =
                        (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(beam, ext, _CMP_LE_OQ));
                    const unsigned all = pass & big;
                    test = pass & ~all;
                    push = all;
                    _mm256_storeu_si256((__m256i *)(void *)lane_rays,
                                        _mm256_set1_epi32((int)rays));
                }
                for (unsigned m = test; m; m &= m - 1u) {
                    const unsigned l = (unsigned)__builtin_ctz(m);
                    /* The child's box against each ray, walk_wide8's
                     * operations with the ray in the lanes. */
                    __m256 u0 = p->lane_f[TRI8_F_TMIN];
                    __m256 u1 = inf8;
                    for (int k = 0; k < 3; k++) {
                        const __m256 tn = _mm256_mul_ps(
                            _mm256_sub_ps(_mm256_broadcast_ss(&wide_row(n->bounds, near_row[k])[l]),
                                          p->lane_f[TRI8_F_ORG + k]),
                            p->lane_f[TRI8_F_INV + k]);
                        const __m256 tf = _mm256_mul_ps(
                            _mm256_sub_ps(_mm256_broadcast_ss(&wide_row(n->bounds, far_row[k])[l]),
                                          p->lane_f[TRI8_F_ORG + k]),
                            p->lane_f[TRI8_F_INV + k]);
                        u0 = _mm256_max_ps(tn, u0);
                        u1 = _mm256_min_ps(tf, u1);
                    }
                    u1 = _mm256_mul_ps(u1, scale8);
                    u1 = _mm256_min_ps(u1, bl);
                    const __m256 in = _mm256_cmp_ps(u0, u1, _CMP_LE_OQ);
                    lane_rays[l] = (unsigned)_mm256_movemask_ps(in) & rays;
                    push |= (unsigned)(lane_rays[l] != 0) << l;
                    node_tests += (unsigned)__builtin_popcount(rays);
                    /* The least entry of its rays, for the cull on pop
                     * by a ray's box_limit; an any-hit ray's never
                     * shrinks, so the rays here, which passed it
                     * already, would all stay: the interval test's
                     * bound (t_min, stored above) does as well. */
                    if (!any_hit)
                        t_min[l] = packet_hmin(_mm256_blendv_ps(inf8, u0, in));
                }
            }
            if (push) {
                if (!(push & (push - 1u))) {
                    /* One child (most nodes of a camera packet): walked
                     * next, with no order to follow. */
                    const unsigned l = (unsigned)__builtin_ctz(push);
                    cur = n->child[l];
                    cur_count = n->count[l];
                    rays = lane_rays[l];
                } else if (any_hit) {
                    /* An any-hit packet: the children in the node's slot
                     * order, the last one walked next, without the
                     * octant's near-first order.  Any hit ends an any-hit
                     * ray and its box_limit never shrinks, so the order
                     * decides only which hit is found first, never the
                     * answer (found or not).  Measured
                     * (docs/performance-log.md, pk6): AVX2 instructions
                     * a ray of rtbench's shadow packets -3.7 % (gears)
                     * to -14.6 % (the soup): the order's decoding gone,
                     * and fewer inner nodes visited (kitchen -4.8 %);
                     * shadow packets 3-32 % faster on the clock. */
                    unsigned m = push;
                    for (;;) {
                        const unsigned l = (unsigned)__builtin_ctz(m);
                        m &= m - 1u;
                        if (!m) {
                            cur = n->child[l];
                            cur_count = n->count[l];
                            rays = lane_rays[l];
                            break;
                        }
                        stack[sp].child = n->child[l];
                        stack[sp].count = n->count[l];
                        stack[sp].rays = lane_rays[l];
                        stack[sp].t_entry = t_min[l];
                        sp++;
                    }
                } else {
                    /* The children to push by their position in the
                     * octant's order (3 bits per position): bit q of pos is
                     * set when the child at position q is pushed, so the
                     * loop runs once per pushed child, the last position
                     * first (the nearest ends on top of the stack, as
                     * packet_walk's scan of all eight). */
                    const uint32_t order = (uint32_t)n->order[octant][0] |
                                           (uint32_t)n->order[octant][1] << 8 |
                                           (uint32_t)n->order[octant][2] << 16;
                    const __m256i slot = _mm256_and_si256(
                        _mm256_srlv_epi32(_mm256_set1_epi32((int)order),
                                          _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21)),
                        _mm256_set1_epi32(7));
                    const __m256i bit = _mm256_srlv_epi32(_mm256_set1_epi32((int)push), slot);
                    unsigned pos = (unsigned)_mm256_movemask_ps(
                        _mm256_castsi256_ps(_mm256_slli_epi32(bit, 31)));
                    for (;;) {
                        const unsigned q = 31u - (unsigned)__builtin_clz(pos);
                        const unsigned l = order >> (3 * q) & 7u;
                        pos &= ~(1u << q);
                        if (!pos) {
                            /* The nearest: walked next, not stacked. */
                            cur = n->child[l];
                            cur_count = n->count[l];
                            rays = lane_rays[l];
                            break;
                        }
                        stack[sp].child = n->child[l];
                        stack[sp].count = n->count[l];
                        stack[sp].rays = lane_rays[l];
                        stack[sp].t_entry = t_min[l];
                        sp++;
                    }
                }
                continue;
            }
        }
        for (;;) {
            if (sp == 0) {
                p->node_tests += node_tests;
                /* The hits taken in the lanes, straight to the caller's
                 * hits: no state reads them after the walk. */
                packet_store_hits(p);
                return done;
            }
            sp--;
            /* The rays whose box_limit lies before the subtree's entry
             * bound leave it, as the single walk's pop skips it. */
            rays = stack[sp].rays & ~done &
                   (unsigned)_mm256_movemask_ps(
                       _mm256_cmp_ps(_mm256_set1_ps(stack[sp].t_entry), bl, _CMP_LE_OQ));
            if (rays)
                break;
        }
        cur = stack[sp].child;
        cur_count = stack[sp].count;
    }
}
#endif

/* The caller's arrays of a packet for the entries that take them
 * (TRACE_PACKET_CLOSEST_ARRAYS): org[r], dir[r], tmin[r] as packet_init
 * reads them (packet.h). */
struct packet_arrays {
    const float (*org)[3];
    const float (*dir)[3];
    const float *tmin;
};

#if defined(__AVX2__) && defined(RT_TRACE_PACKET_INIT_LANES)
/* The least (f_min[0]) and greatest (f_max[0]) of fields 0-7 over the
 * eight lanes, field j in lane j, as tri8_lanes_load gives them, without
 * the transpose: pairs of fields are reduced together (unpack, then
 * 64-bit shuffles, then the 128-bit halves), 20 shuffles and 14 min/max
 * for both.  Fields 8 (inv_dir[2]) and 9 (tmin), the other two that
 * packet_ia_init reads, in lanes 0 and 1 of f_min[1] and f_max[1] (the
 * other lanes hold copies of them; the kx, ky, kz, sx, sy, sz ranges
 * are not read).  The order of the operations differs from
 * tri8_lanes_half's, which changes at most the sign of a zero where both
 * signs occur; packet_ia_init reads the ranges only when all are finite,
 * and only through comparisons and the interval bounds, where the sign
 * of a zero decides nothing (see there). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_lanes_bounds(const __m256 f[TRI8_F_COUNT], __m256 f_min[2],
                                       __m256 f_max[2])
{
    __m256 lo[4], hi[4];
    for (int j = 0; j < 4; j++) {
        /* Fields 2j and 2j + 1: lanes (0, 2), (1, 3) of each half. */
        const __m256 a = _mm256_unpacklo_ps(f[2 * j], f[2 * j + 1]);
        const __m256 b = _mm256_unpackhi_ps(f[2 * j], f[2 * j + 1]);
        lo[j] = _mm256_min_ps(a, b);
        hi[j] = _mm256_max_ps(a, b);
    }
    __m256 lo2[2], hi2[2];
    for (int j = 0; j < 2; j++) {
        /* Fields 4j .. 4j + 3, one a lane of each half. */
        lo2[j] = _mm256_min_ps(_mm256_shuffle_ps(lo[2 * j], lo[2 * j + 1], 0x44),
                               _mm256_shuffle_ps(lo[2 * j], lo[2 * j + 1], 0xee));
        hi2[j] = _mm256_max_ps(_mm256_shuffle_ps(hi[2 * j], hi[2 * j + 1], 0x44),
                               _mm256_shuffle_ps(hi[2 * j], hi[2 * j + 1], 0xee));
    }
    f_min[0] = _mm256_min_ps(_mm256_permute2f128_ps(lo2[0], lo2[1], 0x20),
                             _mm256_permute2f128_ps(lo2[0], lo2[1], 0x31));
    f_max[0] = _mm256_max_ps(_mm256_permute2f128_ps(hi2[0], hi2[1], 0x20),
                             _mm256_permute2f128_ps(hi2[0], hi2[1], 0x31));
    /* Fields 8 and 9 the same way, in lanes 0 and 1 (and 2, 3). */
    const __m256 a = _mm256_unpacklo_ps(f[8], f[9]), b = _mm256_unpackhi_ps(f[8], f[9]);
    __m256 l = _mm256_min_ps(a, b), h = _mm256_max_ps(a, b);
    l = _mm256_min_ps(l, _mm256_shuffle_ps(l, l, 0x4e));
    h = _mm256_max_ps(h, _mm256_shuffle_ps(h, h, 0x4e));
    f_min[1] = _mm256_min_ps(l, _mm256_permute2f128_ps(l, l, 0x01));
    f_max[1] = _mm256_max_ps(h, _mm256_permute2f128_ps(h, h, 0x01));
}
#endif

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned packet_run(const struct bvh4 *wide, const struct bvh *bvh,
                                  const float *tri, const struct trace_ray *rays,
                                  const struct packet_arrays *arr, const float *t_max,
                                  unsigned active, unsigned hybrid, int any_hit,
                                  struct trace_hit *hits, struct trace_counters *counters)
{
    (void)arr; /* read only with AVX2 (and packet_init.h) */
    active &= (1u << TRACE_PACKET) - 1u;
    unsigned result = 0;
    int packet = active && wide->node_count && wide->width == 4;
#if defined(__AVX__)
    packet |= active && wide->node_count && wide->width == 8;
#endif
    if (!packet) {
        /* A layout this table does not walk: ray by ray (walk_wide
         * takes the binary walk). */
        for (unsigned m = active; m; m &= m - 1u) {
            const unsigned r = (unsigned)__builtin_ctz(m);
            if (walk_wide(wide, bvh, tri, &rays[r], t_max[r], any_hit, any_hit ? NULL : &hits[r],
                          counters))
                result |= 1u << r;
        }
        return result;
    }
    struct packet_state p;
    unsigned done;
    int ia = 0;
#if defined(__AVX__)
    if (wide->width == 8) {
        /* The root's four lines requested before the set-up: every
         * packet's walk starts with the root's test, whose loads issue
         * only once the set-up (the rays' loads, five divisions, the
         * ranges, packet_ia_init) has passed; requested here, the fetch
         * runs beside the set-up.  A prefetch changes no answer.
         * Measured (docs/performance-log.md, round 38's merge): kitchen
         * camera packets +0.9 and +0.4 % in two quiet alternated pairs,
         * gears' +2.0 and +1.6 %, bumpy and the soup mixed within the
         * spread. */
        WIDE_PREFETCH_LINES(wide->nodes8, 4);
    }
    {
        /* Each ray's limit, best and box_limit in the lanes, as
         * packet_ready sets its state (a lane without a ray: best +inf,
         * box_limit -inf, limit 0). */
        const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
        const __m256i lanes =
            _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32((int)active), bit), bit);
        const __m256 t = _mm256_maskload_ps(t_max, lanes);
        const __m256 in = _mm256_castsi256_ps(lanes);
        _mm256_storeu_ps(p.limit, t);
        _mm256_storeu_ps(p.best, _mm256_blendv_ps(_mm256_set1_ps(INFINITY), t, in));
        _mm256_storeu_ps(p.box_limit,
                         _mm256_blendv_ps(_mm256_set1_ps(-INFINITY),
                                          _mm256_mul_ps(t, _mm256_set1_ps(ISECT_BOX_FAR_SCALE)),
                                          in));
        _mm256_storeu_ps(p.hit_u, _mm256_setzero_ps());
        _mm256_storeu_ps(p.hit_v, _mm256_setzero_ps());
        _mm256_storeu_ps((float *)p.hit_prim, _mm256_setzero_ps());
        p.found = 0;
        p.dirty = 0;
        p.rays = rays;
        p.t_max = t_max;
        p.hits = hits;
        p.any_hit = any_hit;
        p.s_ready = 0;
        p.node_tests = 0;

        /* The rays' fields in the lanes, and those with the first
         * ray's kx, ky, kz (a lane without a ray copies the first ray:
         * masked by active). */
        __m256 f_min[2], f_max[2];
        const unsigned first = (unsigned)__builtin_ctz(active);
#if defined(__AVX2__) && defined(RT_TRACE_PACKET_INIT_LANES)
        if (arr) {
            /* From the caller's arrays straight into the lanes: the
             * set-up in the lanes (packet_init.h), no rays' structs
             * until a per-ray step asks for them (packet_rays_ready). */
            __m256 ov[3], dv[3], tv;
            packet_init_load(arr->org, arr->dir, arr->tmin, active, 1, ov, dv, &tv);
            packet_init_fields(ov[0], ov[1], ov[2], dv[0], dv[1], dv[2], tv, p.lane_f);
            packet_lanes_bounds(p.lane_f, f_min, f_max);
            p.rays = p.ray_buf;
            p.rays_ready = 0;
            const __m256i at = _mm256_set1_epi32((int)first);
            for (int k = 0; k < 3; k++)
                p.k0[k] = _mm256_cvtsi256_si32(_mm256_permutevar8x32_epi32(
                    _mm256_castps_si256(p.lane_f[TRI8_F_K + k]), at));
        } else
#endif
        {
            tri8_lanes_load(rays, active, p.lane_f, f_min, f_max);
            p.rays_ready = 1;
            p.k0[0] = rays[first].kx;
            p.k0[1] = rays[first].ky;
            p.k0[2] = rays[first].kz;
        }
        const __m256i same = _mm256_and_si256(
            _mm256_and_si256(
                _mm256_cmpeq_epi32(_mm256_castps_si256(p.lane_f[TRI8_F_K]),
                                   _mm256_set1_epi32(p.k0[0])),
                _mm256_cmpeq_epi32(_mm256_castps_si256(p.lane_f[TRI8_F_K + 1]),
                                   _mm256_set1_epi32(p.k0[1]))),
            _mm256_cmpeq_epi32(_mm256_castps_si256(p.lane_f[TRI8_F_K + 2]),
                               _mm256_set1_epi32(p.k0[2])));
        p.lanes8 = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(same)) & active;
        if ((unsigned)__builtin_popcount(p.lanes8) < PACKET_TRI8_MIN)
            p.lanes8 = 0;
        p.t8_ready = 0;
        p.triangle_tests = 0;
        /* The interval walk sets up a ray's leaf constants (r4) at its
         * first leaf outside the eight-ray test. */
        p.r4_ready = 0;
        ia = wide->width == 8 && hybrid == 0 && packet_ia_init(&p, active, f_min, f_max,
                                                                     wide->leaf_extent);
        if (!ia) {
            /* packet_walk reads the rays' structs. */
            packet_rays_ready(&p);
            rays = p.rays;
        }
    }
#endif
    if (!ia) {
        /* Lane by lane with a constant count (unrolled: each state's
         * fields at fixed offsets) rather than over the bits of active. */
        for (unsigned r = 0; r < TRACE_PACKET; r++) {
            if (!(active >> r & 1u))
                continue;
            wide_state_init(&p.s[r], &rays[r], t_max[r], any_hit, any_hit ? NULL : &hits[r]);
        }
#if defined(__AVX__)
        p.s_ready = active;
#endif
        for (unsigned m = active; m; m &= m - 1u) {
            const unsigned r = (unsigned)__builtin_ctz(m);
            const struct trace_ray *ray = &rays[r];
            tri4_ray_init(&p.s[r].r4, ray);
            int octant = 0;
            for (int k = 0; k < 3; k++) {
                const int neg = signbit(ray->inv_dir[k]) != 0;
                p.near_row[r][k] = neg ? 3 + k : k;
                p.far_row[r][k] = neg ? k : 3 + k;
                octant |= neg << k;
            }
            p.octant[r] = octant;
        }
    }
#if defined(__AVX__)
    if (ia)
        done = packet_walk8_ia(wide, &p, active, any_hit);
    else if (wide->width == 8)
        done = packet_walk(wide, &p, active, hybrid, 8);
    else
#endif
        done = packet_walk(wide, &p, active, hybrid, 4);
    unsigned counted = active;
#if defined(__AVX__)
    counted = p.s_ready;
    if (counters) {
        counters->triangle_tests += p.triangle_tests;
        counters->node_tests += p.node_tests;
    }
#endif
    if (counters) {
        for (unsigned m = counted; m; m &= m - 1u) {
            const unsigned r = (unsigned)__builtin_ctz(m);
            counters->node_tests += p.s[r].node_tests;
            counters->triangle_tests += p.s[r].triangle_tests;
        }
    }
    if (any_hit)
        return done;
#if defined(__AVX__)
    return p.found;
#else
    for (unsigned m = active; m; m &= m - 1u) {
        const unsigned r = (unsigned)__builtin_ctz(m);
        if (p.s[r].found)
            result |= 1u << r;
    }
    return result;
#endif
}

unsigned TRACE_PACKET_CLOSEST(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                              const struct trace_ray *rays, const float *t_max, unsigned active,
                              unsigned hybrid, struct trace_hit *hits,
                              struct trace_counters *counters);
unsigned TRACE_PACKET_CLOSEST(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                              const struct trace_ray *rays, const float *t_max, unsigned active,
                              unsigned hybrid, struct trace_hit *hits,
                              struct trace_counters *counters)
{
    return packet_run(wide, bvh, tri, rays, NULL, t_max, active, hybrid, 0, hits, counters);
}

unsigned TRACE_PACKET_ANY(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                          const struct trace_ray *rays, const float *t_max, unsigned active,
                          unsigned hybrid, struct trace_counters *counters);
unsigned TRACE_PACKET_ANY(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                          const struct trace_ray *rays, const float *t_max, unsigned active,
                          unsigned hybrid, struct trace_counters *counters)
{
    return packet_run(wide, bvh, tri, rays, NULL, t_max, active, hybrid, 1, NULL, counters);
}

#if defined(TRACE_PACKET_CLOSEST_ARRAYS)
#if !defined(__AVX2__) || !defined(RT_TRACE_PACKET_INIT_LANES)
#error "the arrays entries need AVX2 and packet_init.h included before packet_wide.h"
#endif
/* The entries from the caller's arrays (packet.h, trace_packet_closest_arrays_fn):
 * over the 8-wide layout without the hybrid fallback, packet_run from
 * the lanes; otherwise the rays' structs set up here (packet_init.h, as
 * the table's packet_init) and packet_run from them. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned packet_run_arrays(const struct bvh4 *wide, const struct bvh *bvh,
                                         const float *tri, const float (*org)[3],
                                         const float (*dir)[3], const float *tmin,
                                         const float *t_max, unsigned active, unsigned hybrid,
                                         int any_hit, struct trace_hit *hits,
                                         struct trace_counters *counters)
{
    active &= (1u << TRACE_PACKET) - 1u;
    if (active && wide->node_count && wide->width == 8 && hybrid == 0) {
        const struct packet_arrays arr = {org, dir, tmin};
        return packet_run(wide, bvh, tri, NULL, &arr, t_max, active, hybrid, any_hit, hits,
                          counters);
    }
    /* The entries from the rays' structs, called rather than inlined: a
     * second copy of the walk here made GCC stop inlining the leaf's
     * set-up into the first (kitchen shadow packets +5 instructions a
     * ray). */
    struct trace_ray rays[TRACE_PACKET];
    if (active) {
        __m256 ov[3], dv[3], tv;
        packet_init_load(org, dir, tmin, active, 0, ov, dv, &tv);
        packet_init_lanes(ov[0], ov[1], ov[2], dv[0], dv[1], dv[2], tv, active, rays, NULL);
    }
    if (any_hit)
        return TRACE_PACKET_ANY(wide, bvh, tri, rays, t_max, active, hybrid, counters);
    return TRACE_PACKET_CLOSEST(wide, bvh, tri, rays, t_max, active, hybrid, hits, counters);
}

unsigned TRACE_PACKET_CLOSEST_ARRAYS(const struct bvh4 *wide, const struct bvh *bvh,
                                     const float *tri, const float (*org)[3],
                                     const float (*dir)[3], const float *tmin,
                                     const float *t_max, unsigned active, unsigned hybrid,
                                     struct trace_hit *hits, struct trace_counters *counters);
unsigned TRACE_PACKET_CLOSEST_ARRAYS(const struct bvh4 *wide, const struct bvh *bvh,
                                     const float *tri, const float (*org)[3],
                                     const float (*dir)[3], const float *tmin,
                                     const float *t_max, unsigned active, unsigned hybrid,
                                     struct trace_hit *hits, struct trace_counters *counters)
{
    return packet_run_arrays(wide, bvh, tri, org, dir, tmin, t_max, active, hybrid, 0, hits,
                             counters);
}

unsigned TRACE_PACKET_ANY_ARRAYS(const struct bvh4 *wide, const struct bvh *bvh,
                                 const float *tri, const float (*org)[3], const float (*dir)[3],
                                 const float *tmin, const float *t_max, unsigned active,
                                 unsigned hybrid, struct trace_counters *counters);
unsigned TRACE_PACKET_ANY_ARRAYS(const struct bvh4 *wide, const struct bvh *bvh,
                                 const float *tri, const float (*org)[3], const float (*dir)[3],
                                 const float *tmin, const float *t_max, unsigned active,
                                 unsigned hybrid, struct trace_counters *counters)
{
    return packet_run_arrays(wide, bvh, tri, org, dir, tmin, t_max, active, hybrid, 1, NULL,
                             counters);
}
#endif
