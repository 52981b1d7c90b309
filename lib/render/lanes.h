/* SPDX-License-Identifier: Apache-2.0 */
/*
 * lanes.h - eight-lane float steps shared by the eye light's shading
 * (shade.c) and the surface fetch (surface.c) in their AVX2 copy
 * (shade_eye_avx2.c).  Each is the scalar operation of base/vec3.h in
 * its order, lane by lane, so the same floats: one definition, so that
 * the two files cannot drift apart in the order of their additions.
 */
#ifndef RT_RENDER_LANES_H
#define RT_RENDER_LANES_H

#if defined(__AVX__) && !defined(RT_NO_SIMD)
#include <immintrin.h>

/* vec3_dot of eight lanes: (a0 b0 + a1 b1) + a2 b2. */
static inline __m256 lanes_dot8(const __m256 a[3], const __m256 b[3])
{
    return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(a[0], b[0]), _mm256_mul_ps(a[1], b[1])),
                         _mm256_mul_ps(a[2], b[2]));
}
#endif

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
/* Bound of lanes_log2_4 on [1, 2^32] (see there), absolute. */
#define LANES_LOG2_BOUND 0x1p-47

/*
 * log2 of four doubles x in [1, 2^32] (positive and normal), for the
 * levels of detail's footprints: not glibc's log2 (a call a lane, the
 * largest part of the levels of detail's tail), so not its bits, only
 * within LANES_LOG2_BOUND of the exact value, which is all lod_ray_quad
 * asks of it (it keeps a result only when every value that close rounds
 * to the same float).  x = 2^e m with m in [sqrt(1/2), sqrt(2)] (the
 * exponent and mantissa fields; m / 2 and e + 1 above sqrt(2), exact),
 * and ln m = 2 atanh(z) = 2 (z + z^3 / 3 + ... + z^17 / 17 + ...) with
 * z = (m - 1) / (m + 1), |z| <= 0.1716 (the series of Abramowitz and
 * Stegun 1964, 4.1.27).  The error in log2 units: the terms left out,
 * 2 |z|^19 / 19 / (1 - z^2) / ln 2 < 2^-50; z's two roundings (m - 1 is
 * exact by Sterbenz's lemma), 2^-52 of |z| relative, and the series'
 * other roundings, in all below 0.6 2^-52 of ln m, and the product by
 * 1 / ln 2 (itself rounded), below 0.9 2^-52 together; the sum with e,
 * half an ulp of a result below 32, 2^-49: below 2^-48 in all, half the
 * bound (2^32 for the squared footprints of lod_fast, whose last level
 * is below 2^16).  conformance/internal/shade_lanes checks
 * |lanes_log2_4(x) - log2(x)| <= 2^-48 against long double over every
 * 13th float of [1, 2^32] and random doubles there.
 */
static inline __m256d lanes_log2_4_scaled(__m256d x, int half)
{
    const __m256d one = _mm256_set1_pd(1.0);
    const __m256i bits = _mm256_castpd_si256(x);
    __m256d m = _mm256_or_pd(
        _mm256_and_pd(x, _mm256_castsi256_pd(_mm256_set1_epi64x(0x000fffffffffffffLL))), one);
    /* The biased exponent as the low bits of 2^52, less 2^52 + 1023:
     * exactly e, as a double (with `half`, as the low bits of 2^51, whose
     * ulp is 1/2, less 2^51 + 1023 / 2: exactly e / 2). */
    const double base = half ? 0x1p51 : 0x1p52;
    __m256d e = _mm256_sub_pd(
        _mm256_castsi256_pd(_mm256_or_si256(_mm256_srli_epi64(bits, 52),
                                            _mm256_castpd_si256(_mm256_set1_pd(base)))),
        _mm256_set1_pd(base + (half ? 511.5 : 1023.0)));
    const __m256d big = _mm256_cmp_pd(m, _mm256_set1_pd(0x1.6a09e667f3bcdp+0), _CMP_GT_OQ);
    m = _mm256_blendv_pd(m, _mm256_mul_pd(m, _mm256_set1_pd(0.5)), big);
    e = _mm256_add_pd(e, _mm256_and_pd(big, _mm256_set1_pd(half ? 0.5 : 1.0)));
    const __m256d z = _mm256_div_pd(_mm256_sub_pd(m, one), _mm256_add_pd(m, one));
    const __m256d w = _mm256_mul_pd(z, z);
    /* p = 1/3 + w / 5 + ... + w^7 / 17 by Estrin's scheme (Estrin 1960;
     * pairs, then pairs of pairs by w^2 and w^4): four dependent steps
     * after w where Horner's rule takes seven multiplications and
     * additions, on the chain of divisions and square roots that bounds
     * lod_quad.  p's roundings do not reach the bound in either order: p
     * is about 1/3 and enters ln m only through z w p, at most 0.0099 of
     * z (|w| <= 0.0295), so they stay below 2^-56 of ln m. */
#define C(k) _mm256_set1_pd(1.0 / (double)(k))
    const __m256d w2 = _mm256_mul_pd(w, w);
    const __m256d w4 = _mm256_mul_pd(w2, w2);
    const __m256d p01 = _mm256_add_pd(C(3), _mm256_mul_pd(C(5), w));
    const __m256d p23 = _mm256_add_pd(C(7), _mm256_mul_pd(C(9), w));
    const __m256d p45 = _mm256_add_pd(C(11), _mm256_mul_pd(C(13), w));
    const __m256d p67 = _mm256_add_pd(C(15), _mm256_mul_pd(C(17), w));
#undef C
    const __m256d p = _mm256_add_pd(_mm256_add_pd(p01, _mm256_mul_pd(p23, w2)),
                                    _mm256_mul_pd(_mm256_add_pd(p45, _mm256_mul_pd(p67, w2)), w4));
    /* ln m = 2 (z + z w p); log2 = e + ln m / ln 2. */
    const __m256d ln = _mm256_mul_pd(
        _mm256_set1_pd(2.0), _mm256_add_pd(z, _mm256_mul_pd(_mm256_mul_pd(z, w), p)));
    return _mm256_add_pd(
        e, _mm256_mul_pd(ln, _mm256_set1_pd(half ? 0x1.71547652b82fep-1 : 0x1.71547652b82fep+0)));
}

static inline __m256d lanes_log2_4(__m256d x)
{
    return lanes_log2_4_scaled(x, 0);
}

/* lanes_log2_4(x) / 2 without a multiplication: e / 2 from the exponent
 * field as above, 1 / 2 for big's 1, and the halved 1 / ln 2 (exact), so
 * every step is lanes_log2_4's step of halved operands, whose rounding
 * is the halved rounding (no result is subnormal): bit for bit
 * lanes_log2_4(x) * 0.5, which conformance/internal/shade_lanes checks
 * over its range. */
static inline __m256d lanes_log2_4_half(__m256d x)
{
    return lanes_log2_4_scaled(x, 1);
}
#endif

#if defined(__AVX512F__) && defined(__AVX512DQ__) && !defined(RT_NO_SIMD)
/* lanes_log2_4_half in eight lanes (the AVX-512 copy; lod_fast_oct's
 * squared footprints): the same operations lane by lane, so the same
 * doubles; the blend by a mask register, and big's 1 / 2 or +0 added to
 * e / 2 as there (e / 2 + 0 is e / 2). */
static inline __m512d lanes_log2_8_half(__m512d x)
{
    const __m512d one = _mm512_set1_pd(1.0);
    const __m512i bits = _mm512_castpd_si512(x);
    __m512d m = _mm512_or_pd(
        _mm512_and_pd(x, _mm512_castsi512_pd(_mm512_set1_epi64(0x000fffffffffffffLL))), one);
    __m512d e = _mm512_sub_pd(
        _mm512_castsi512_pd(_mm512_or_si512(_mm512_srli_epi64(bits, 52),
                                            _mm512_castpd_si512(_mm512_set1_pd(0x1p51)))),
        _mm512_set1_pd(0x1p51 + 511.5));
    const __mmask8 big = _mm512_cmp_pd_mask(m, _mm512_set1_pd(0x1.6a09e667f3bcdp+0), _CMP_GT_OQ);
    m = _mm512_mask_blend_pd(big, m, _mm512_mul_pd(m, _mm512_set1_pd(0.5)));
    e = _mm512_add_pd(e, _mm512_maskz_mov_pd(big, _mm512_set1_pd(0.5)));
    const __m512d z = _mm512_div_pd(_mm512_sub_pd(m, one), _mm512_add_pd(m, one));
    const __m512d w = _mm512_mul_pd(z, z);
#define C(k) _mm512_set1_pd(1.0 / (double)(k))
    const __m512d w2 = _mm512_mul_pd(w, w);
    const __m512d w4 = _mm512_mul_pd(w2, w2);
    const __m512d p01 = _mm512_add_pd(C(3), _mm512_mul_pd(C(5), w));
    const __m512d p23 = _mm512_add_pd(C(7), _mm512_mul_pd(C(9), w));
    const __m512d p45 = _mm512_add_pd(C(11), _mm512_mul_pd(C(13), w));
    const __m512d p67 = _mm512_add_pd(C(15), _mm512_mul_pd(C(17), w));
#undef C
    const __m512d p = _mm512_add_pd(_mm512_add_pd(p01, _mm512_mul_pd(p23, w2)),
                                    _mm512_mul_pd(_mm512_add_pd(p45, _mm512_mul_pd(p67, w2)), w4));
    const __m512d ln = _mm512_mul_pd(
        _mm512_set1_pd(2.0), _mm512_add_pd(z, _mm512_mul_pd(_mm512_mul_pd(z, w), p)));
    return _mm512_add_pd(e, _mm512_mul_pd(ln, _mm512_set1_pd(0x1.71547652b82fep-1)));
}
#endif

#endif
