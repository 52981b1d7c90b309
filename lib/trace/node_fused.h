/* SPDX-License-Identifier: Apache-2.0 */
/*
 * node_fused.h - a widened slab test for the single-ray 8-wide walks'
 * nodes (traverse_wide8_ray.h), one fused multiply-add a slab, which
 * passes every box isect_box passes (a superset), not the same boxes.
 *
 * Why a superset is enough.  The answers do not depend on which boxes a
 * walk visits beyond the ones that hold the answer: a closest-hit walk
 * keeps the smallest t, ties to the lower primitive (wide_take_closest),
 * a rule that does not depend on the order or the number of triangles
 * tested; the triangle test clamps t into the triangle's box as
 * isect_box computes it (isect_clamp_interval, unchanged), so every box
 * holding the answer's triangle passes isect_box with the limit
 * best * ISECT_BOX_FAR_SCALE of any best >= the answer's t, and passes
 * this test too; an any-hit walk needs some hit, and a box isect_box
 * passes on the way to one passes here.  Extra boxes cost visits only.
 *
 * The test.  isect_box's slab distance is r = fl(fl(b - o) * i) (b a
 * bound, o the origin, d the direction, i = fl(1 / d), on one axis),
 * within gamma(2) of T = (b - o) i, computed exactly (Higham, "Accuracy
 * and Stability of Numerical Algorithms", 2nd ed., 2002, sec. 3.1:
 * gamma(n) = n u / (1 - n u), u = 2^-24); its far distance is then
 * scaled by s = ISECT_BOX_FAR_SCALE = 1 + 8u (Ize, "Robust BVH ray
 * traversal", JCGT 2(2), 2013) and compared with its entry
 * t0 = max(tmin, near distances) and the limit L.  Here, per ray and
 * axis, with S = NODE_FUSED_SCALE = 1 + 32u:
 *   D = fl(|i| fl(|o| + 2^-20) 2^-20),   is = fl(i S),
 *   cn = fl(-o i - D),   cf = fl(D - o is)   (one rounding each, fma),
 * a node's near distance is M = fl(b i + cn) and its far distance
 * G = fl(b is + cf), one fma each; the entry max(tmin, M_x, M_y, M_z) is
 * compared with each G (no scale) and with L' = fl(L S + 2^-100)
 * (node_fused_limit).  Every constant is a lane operation on the ray's
 * origin and i: one multiplication after i (is, D; fl(|o| + 2^-20) 2^-20
 * is ready before i), then the fma, so the first node's test waits about
 * eight cycles longer for them than for i alone.
 *
 * Proof that a box isect_box passes (t0 <= fl(s F_j) for each axis j,
 * t0 <= L) passes here, for a ray node_fused_init accepts: every
 * |o_k| <= 2^60 and 2^-60 <= |d_k| <= 2^60, so |o i| <= 2^121, no
 * constant overflows or is NaN, the scalings by 2^-20 are exact, b - o
 * is finite for a finite b.  With tmin >= 0, t0 >= 0, so every F_j >= 0 and T_j >= 0.
 * eta stands for the subnormal range's absolute errors (a few 2^-149).
 * D >= |i| (|o| + 2^-20)(1 - u)^2 2^-20 >= 16u |o i| (1 - 2u)
 * + 2^-101 (|i| >= 2^-61).
 * - Entry: b i + cn = T - D + e, |e| <= u (|o i| + D) < D, so
 *   b i + cn < T and M_k <= T_k (1 + u) where positive (M_k <= 0 where
 *   T_k <= 0: it loses to tmin >= +0 in the walk's integer maximum).
 *   T_k <= r_k (1 + 2.01u) + eta, so t0' <= t0 (1 + 3.02u) + eta.
 * - Far: is = S i (1 + th), |th| <= u, and X = b is + cf =
 *   (b - o) is + D + a (D - o is), |a| <= u, so X >= S T (1 - u)
 *   + D (1 - u) - 1.01u S |o i|, and G = fl(X) >= X (1 - u)
 *   >= S F (1 - 4.02u) + 2^-102 (T >= F (1 - 2u); D's 16u |o i| covers
 *   the 1.01u S |o i|).  isect_box's t0 <= fl(s F) <= F (1 + 9.01u), so
 *   t0' <= F (1 + 12.1u) + eta < G, as S (1 - 4.02u) >= 1 + 27.9u.
 * - Limit: L' >= (L S + 2^-100)(1 - u) >= L (1 + 30u) + 2^-101 > t0'
 *   when t0 <= L (L >= 0).  The walk's pops compare the entries it
 *   stored (t0') with L' too, so they cull no box isect_box's walk keeps.
 * - Overflow: M or G is infinite only where the exact value is beyond
 *   the float range: a +inf entry comes with T_k >= 2^128 (1 - 2u), so
 *   every F_j s and L isect_box passes it with are within 4u of 2^128
 *   or more, and G_j and L' are +inf too (each at least (1 + 20u) times
 *   such a value); G = -inf means T < 0, a box isect_box refuses.  An
 *   empty lane's inverted infinite bounds give infinities, never NaN
 *   (the constants are finite).
 * The margins: D is 16u |o i| where about 1.02u would do (both sides
 * need D > 1.01u S |o i|), S is 1 + 32u where 1 + 16.2u would do, a
 * factor 2 for the rounding of the constants; D is about 2^-20 of the origin's
 * distance from the coordinate origin in t units (and 2^-40 |i| at
 * least), a few boxes a ray more at most.
 * conformance/internal/node_fused.c checks the superset on adversarial
 * pairs and shows that without the widening (S = 1, D = 0) it fails.
 *
 * Rays the constants do not cover (a zero or tiny direction component,
 * an origin beyond 2^60) take a walk with isect_box's own test.  No FMA
 * is contracted anywhere else (-ffp-contract=off): the fmas here are
 * explicit.
 */
#ifndef RT_TRACE_NODE_FUSED_H
#define RT_TRACE_NODE_FUSED_H

#include <math.h>

#include <immintrin.h>

/* S above: 1 + 2^-19 = 1 + 32u. */
#define NODE_FUSED_SCALE (1.0f + 0x1p-19f)

/* The per-ray constants, axis order x, y, z (lane 3 unused: room for a
 * 16-byte store of each). */
struct node_fused {
    float near_c[4]; /* cn: fl(-o_k i_k - D_k), one rounding */
    float inv_s[4];  /* is: fl(i_k S) */
    float far_c[4];  /* cf: fl(D_k - o_k is_k), one rounding */
};

/* 1 when the fused test covers the ray (its constants then set), else 0
 * (the ray takes isect_box's test).  org, dir, inv: the origin, the
 * direction and the inverse direction isect_box uses (fl(1 / d)) in
 * lanes 0-2, axis order; lane 3 is not tested and its constants, stored
 * with the others, are never read.  In SSE2 lanes, as the 8-wide walks' set-up has them: the
 * coverage test on the magnitudes' bits as integers (a NaN, above +inf,
 * fails), the constants lane by lane as the formulas above. */
static inline int node_fused_init(struct node_fused *f, __m128 org, __m128 dir, __m128 inv)
{
    const __m128 magnitude = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
    const __m128 a_org = _mm_and_ps(org, magnitude);
    const __m128 a_dir = _mm_and_ps(dir, magnitude);
    const __m128i hi = _mm_castps_si128(_mm_set1_ps(0x1p60f));
    const __m128i lo = _mm_castps_si128(_mm_set1_ps(0x1p-60f));
    const __m128i bo = _mm_castps_si128(a_org), bd = _mm_castps_si128(a_dir);
    const __m128i bad =
        _mm_or_si128(_mm_cmpgt_epi32(bo, hi),
                     _mm_or_si128(_mm_cmpgt_epi32(bd, hi), _mm_cmpgt_epi32(lo, bd)));
    if (_mm_movemask_ps(_mm_castsi128_ps(bad)) & 7)
        return 0;
    const __m128 slack =
        _mm_mul_ps(_mm_and_ps(inv, magnitude),
                   _mm_mul_ps(_mm_add_ps(a_org, _mm_set1_ps(0x1p-20f)), _mm_set1_ps(0x1p-20f)));
    const __m128 inv_s = _mm_mul_ps(inv, _mm_set1_ps(NODE_FUSED_SCALE));
    _mm_storeu_ps(f->inv_s, inv_s);
#if defined(__FMA__)
    _mm_storeu_ps(f->near_c, _mm_fnmsub_ps(org, inv, slack));
    _mm_storeu_ps(f->far_c, _mm_fnmadd_ps(org, inv_s, slack));
#else
    float o[4], i[4], d[4];
    _mm_storeu_ps(o, org);
    _mm_storeu_ps(i, inv);
    _mm_storeu_ps(d, slack);
    for (int k = 0; k < 4; k++) {
        f->near_c[k] = fmaf(-o[k], i[k], -d[k]);
        f->far_c[k] = fmaf(-o[k], f->inv_s[k], d[k]);
    }
#endif
    return 1;
}

/* L' above: the limit the fused entries are compared with, for a walk
 * whose isect_box limit is limit (>= 0). */
static inline float node_fused_limit(float limit)
{
    return fmaf(limit, NODE_FUSED_SCALE, 0x1p-100f);
}

/* The fused test of one box (lo, hi: its min and max corners) for a ray
 * with tmin >= 0, as the walk computes it lane by lane: 1 when it
 * passes, its entry in *t_entry.  limit_fused is node_fused_limit's. */
static inline int node_fused_box(const struct node_fused *f, const float inv[3], float tmin,
                                 float limit_fused, const float lo[3], const float hi[3],
                                 float *t_entry)
{
    float t0 = tmin > 0.0f ? tmin : 0.0f;
    float far[3];
    for (int k = 0; k < 3; k++) {
        const int neg = signbit(inv[k]) != 0;
        const float near = fmaf(neg ? hi[k] : lo[k], inv[k], f->near_c[k]);
        far[k] = fmaf(neg ? lo[k] : hi[k], f->inv_s[k], f->far_c[k]);
        t0 = near > t0 ? near : t0;
    }
    *t_entry = t0;
    return t0 <= far[0] && t0 <= far[1] && t0 <= far[2] && t0 <= limit_fused;
}

#endif
