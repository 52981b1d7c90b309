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
 * bound, o the origin, i = 1 / d, on one axis), within gamma(2) of the
 * exact T = (b - o) i (Higham, "Accuracy and Stability of Numerical
 * Algorithms", 2nd ed., 2002, sec. 3.1: gamma(n) = n u / (1 - n u),
 * u = 2^-24), and its far distance is then scaled by
 * s = ISECT_BOX_FAR_SCALE = 1 + 8u (Ize, "Robust BVH ray traversal",
 * JCGT 2(2), 2013).  Here, with per-ray constants
 *   q = fl(o i),  D = fl(fl(Q 2^-21) + 2^-100), Q = max_k |q_k|,
 *   is = fl(i S),  c = fl(D - q S) (one fma),  S = NODE_FUSED_SCALE
 *      = 1 + 32u,
 * a node's near distance is M = fl(b i - q) and its far distance
 * G = fl(b is + c), one fma each (one rounding of the exact value), and
 * the entry max(tmin, M_x, M_y, M_z) is compared with each G and with
 * the limit L' = fl(L S + D) (node_fused_limit) instead of s * F and L.
 *
 * Proof that a box isect_box passes (entry t0 <= fl(s F_j) for each axis
 * j and t0 <= L) passes here, for a ray node_fused_init accepts (every
 * |o_k|, |q_k| <= 2^100 and 2^-100 <= |i_k| <= 2^100: no NaN arises,
 * no inverse or scaled inverse is subnormal, b - o never overflows for a
 * finite b).  With tmin >= 0, t0 >= 0, so every F_j >= 0 and T_j >= 0.
 * Write e = q - o i, |e| <= u |o i| <= 1.0001 u Q, and eta for the
 * subnormal range's absolute errors (a few 2^-149 in all, which the
 * 2^-100 in D covers many times over).
 * - Entry: M_k = (T_k - e)(1 + a), |a| <= u.  Where M_k > 0, either
 *   T_k >= 0, T_k <= r_k (1 + 2.01u) + eta, so M_k <= r_k (1 + 3.02u)
 *   + 1.0002 u Q + eta; or T_k < 0 and M_k <= 1.0002 u Q.  The entry is
 *   tmin or a positive M_k (the walk's integer maximum: negatives lose
 *   to tmin >= +0), so t0' <= t0 (1 + 3.02u) + 1.0002 u Q + eta.
 * - Far: X = b is + c = S (b i - q) + D + S b i a + (D - q S) a', with
 *   |a|, |a'| <= u and |b i| <= T + |o i|, so
 *   X >= S T (1 - u) + D (1 - u) - 3.001 u S Q, and G = fl(X)
 *   >= X (1 - u) >= S F (1 - 4u) + D (1 - 2u) - 3.002 u S Q - eta (as
 *   T >= F (1 - 2u)).  isect_box's t0 <= fl(s F) <= F (1 + 9.01u), so
 *   t0' <= F (1 + 12.1u) + 1.0002 u Q + eta, which is below G because
 *   S (1 - 4u) >= 1 + 27u and D (1 - 2u) >= 7.99 u Q + 2^-101 exceeds
 *   3.002 u S Q + 1.0002 u Q + eta.
 * - Limit: L' >= (L S + D)(1 - u) >= L (1 + 30u) + D (1 - u) >= t0'
 *   when t0 <= L (L >= 0).  The walk's pops compare the entries it
 *   stored (t0') with L' too, so they cull no box isect_box's walk keeps.
 * - Overflow: with the bounds above, M or G is infinite only where the
 *   exact distance is within 2^-20 of the float range's end; a +inf
 *   entry then comes with far distances and a limit that are +inf here
 *   too (each is at least (1 + 20u) times a value within 13u of 2^128),
 *   and a far G = -inf means F < 0, a box isect_box refuses.  An empty
 *   lane's inverted infinite bounds give infinities, never NaN (q, is
 *   and c are finite).
 * The margins are about 2 (D is 8 u Q where 4.01 u Q would do; S is
 * 1 + 32u where 1 + 16.2u would do); D is about 2^-21 of the origin's
 * distance in t units, a few boxes a ray more at most.
 * conformance/internal/node_fused.c checks the superset on adversarial
 * pairs and shows that without the widening (S = 1, D = 0) it fails.
 *
 * Rays the constants do not cover (a zero or tiny direction component,
 * an origin beyond 2^100) take a walk with isect_box's own test.  No
 * FMA is contracted anywhere else (the header's functions call fmaf
 * explicitly; the build has -ffp-contract=off).
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
    float neg_q[4]; /* -fl(org_k * inv_k) */
    float inv_s[4]; /* fl(inv_k * S) */
    float far_c[4]; /* fl(D - q_k * S), one rounding */
    float slack;    /* D */
};

/* 1 when the fused test covers the ray (its constants then set), else 0
 * (the ray takes isect_box's test).  org and inv: the origin and the
 * inverse direction in lanes 0-2 (axis order); lane 3 is not read.  In
 * SSE2 lanes (the 8-wide walks' set-up has them in registers): the
 * coverage test on the floats' magnitudes as integers (a NaN, above
 * +inf, fails; none arises from finite org and dir but q = 0 * inf, where
 * the inverse fails anyway), the largest |q| by exact maxima, the
 * products and the fma lane by lane as the scalar formulas above. */
static inline int node_fused_init(struct node_fused *f, __m128 org, __m128 inv)
{
    const __m128i magnitude = _mm_set1_epi32(0x7fffffff);
    const __m128 q = _mm_mul_ps(org, inv);
    const __m128i a_org = _mm_and_si128(_mm_castps_si128(org), magnitude);
    const __m128i a_inv = _mm_and_si128(_mm_castps_si128(inv), magnitude);
    const __m128i a_q = _mm_and_si128(_mm_castps_si128(q), magnitude);
    const __m128i hi = _mm_castps_si128(_mm_set1_ps(0x1p100f));
    const __m128i lo = _mm_castps_si128(_mm_set1_ps(0x1p-100f));
    const __m128i bad =
        _mm_or_si128(_mm_or_si128(_mm_cmpgt_epi32(a_org, hi), _mm_cmpgt_epi32(a_q, hi)),
                     _mm_or_si128(_mm_cmpgt_epi32(a_inv, hi), _mm_cmpgt_epi32(lo, a_inv)));
    if (_mm_movemask_ps(_mm_castsi128_ps(bad)) & 7)
        return 0;
    /* max(|q_0|, |q_1|, |q_2|): lane 3 replaced by lane 0. */
    __m128 m = _mm_castsi128_ps(a_q);
    m = _mm_shuffle_ps(m, m, _MM_SHUFFLE(0, 2, 1, 0));
    m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(2, 3, 0, 1)));
    m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2)));
    const __m128 slack =
        _mm_add_ps(_mm_mul_ps(m, _mm_set1_ps(0x1p-21f)), _mm_set1_ps(0x1p-100f));
    const __m128 neg_q = _mm_xor_ps(q, _mm_set1_ps(-0.0f));
    const __m128 scale = _mm_set1_ps(NODE_FUSED_SCALE);
    _mm_storeu_ps(f->neg_q, neg_q);
    _mm_storeu_ps(f->inv_s, _mm_mul_ps(inv, scale));
#if defined(__FMA__)
    _mm_storeu_ps(f->far_c, _mm_fmadd_ps(neg_q, scale, slack));
#else
    for (int k = 0; k < 4; k++)
        f->far_c[k] = fmaf(f->neg_q[k], NODE_FUSED_SCALE, _mm_cvtss_f32(slack));
#endif
    f->slack = _mm_cvtss_f32(slack);
    return 1;
}

/* L' above: the limit the fused entries are compared with, for a walk
 * whose isect_box limit is limit (>= 0). */
static inline float node_fused_limit(const struct node_fused *f, float limit)
{
    return fmaf(limit, NODE_FUSED_SCALE, f->slack);
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
        const float near = fmaf(neg ? hi[k] : lo[k], inv[k], f->neg_q[k]);
        far[k] = fmaf(neg ? lo[k] : hi[k], f->inv_s[k], f->far_c[k]);
        t0 = near > t0 ? near : t0;
    }
    *t_entry = t0;
    return t0 <= far[0] && t0 <= far[1] && t0 <= far[2] && t0 <= limit_fused;
}

#endif
