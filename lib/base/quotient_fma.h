/* SPDX-License-Identifier: Apache-2.0 */
/*
 * quotient_fma.h - correctly rounded double quotients a / b in four
 * 256-bit lanes from one reciprocal y = RN(1 / b) and fused multiply-adds,
 * so that several quotients by the same b (a direction's components and
 * the cone's spread by the ray's length; a row's points by the same w)
 * take one division instead of one each: the divider (vdivpd, vsqrtpd)
 * bounds the frame's camera rays (docs/performance-log.md, "The divider
 * is.").
 *
 * The method (Markstein 1990, "Computation of elementary functions on the
 * IBM RISC System/6000 processor", IBM J. Res. Develop. 34(1), the
 * theorem on the final rounding of a quotient; Muller et al., Handbook of
 * Floating-Point Arithmetic, 2nd ed. 2018, the section on Newton-Raphson
 * division with an FMA, Markstein's theorem): in binary with rounding to
 * nearest, if y approximates 1/b within half an ulp and q approximates
 * a/b within one ulp, then r = a - b q is a floating-point number (an FMA
 * computes it exactly) and RN(q + r y) = RN(a / b), when nothing
 * underflows or overflows.
 *
 * The first approximation q0 = RN(a y) is not always within one ulp: its
 * error is |a/b| |b y - 1| < (A/2) ulp(a/b) for a's significand A < b's
 * (|b y - 1| <= B 2^-54, B b's significand), plus q0's own half ulp.  So
 * one correction q1 = RN(q0 + r0 y) first, r0 = RN(a - b q0): q0 + r0 y
 * = a/b + (a/b - q0)(b y - 1)(1 + e) with |e| <= 2^-53, within 2^-51
 * ulps of a/b, so q1 is within half an ulp plus that, inside one ulp;
 * then the theorem's step on q1 gives RN(a / b).  Five FMA-unit
 * operations and a blend.
 *
 * The operands the lanes may take (quotient_fma_divisor_ok and
 * quotient_fma_dividend_ok; the caller divides as before where a lane
 * fails): 2^-200 <= |b| <= 2^200, and a = +-0 or 2^-600 <= |a| <= 2^600.
 * Then y, q0, q1 and the result are normal (2^-801 <= |a/b| <= 2^801),
 * b q is far from overflowing, and the exact residual a - b q, a
 * multiple of ulp(b) ulp(q) >= 2^(e_a - 106), is no finer than the
 * smallest subnormal (e_a >= -600), so the theorem's conditions hold.
 * NaNs, infinities, zero and subnormal divisors and huge or tiny operands
 * fail the tests.  A zero dividend gives q0 = a y, the signed zero that a
 * / b gives (y has b's sign); the correction steps would turn -0 into +0,
 * so the zero lanes take q0.
 *
 * Only for units compiled with AVX2 and FMA (quotient_fma is absent
 * elsewhere, QUOTIENT_FMA 0); -ffp-contract=off stays, so that no other
 * product or sum of those units is fused.
 */
#ifndef RT_BASE_QUOTIENT_FMA_H
#define RT_BASE_QUOTIENT_FMA_H

#if defined(__AVX2__) && defined(__FMA__) && !defined(RT_NO_SIMD)
#include <immintrin.h>

#define QUOTIENT_FMA 1

static inline __m256d quotient_fma_abs(__m256d v)
{
    return _mm256_andnot_pd(_mm256_set1_pd(-0.0), v);
}

/* All ones in the lanes whose divisor the quotients take: 2^-200 <= |b|
 * <= 2^200 (false for NaN). */
static inline __m256d quotient_fma_divisor_ok(__m256d b)
{
    const __m256d m = quotient_fma_abs(b);
    return _mm256_and_pd(_mm256_cmp_pd(m, _mm256_set1_pd(0x1p-200), _CMP_GE_OQ),
                         _mm256_cmp_pd(m, _mm256_set1_pd(0x1p200), _CMP_LE_OQ));
}

/* All ones in the lanes whose dividend the quotients take: a = +-0 or
 * 2^-600 <= |a| <= 2^600 (false for NaN). */
static inline __m256d quotient_fma_dividend_ok(__m256d a)
{
    const __m256d m = quotient_fma_abs(a);
    const __m256d in = _mm256_and_pd(_mm256_cmp_pd(m, _mm256_set1_pd(0x1p-600), _CMP_GE_OQ),
                                     _mm256_cmp_pd(m, _mm256_set1_pd(0x1p600), _CMP_LE_OQ));
    return _mm256_or_pd(in, _mm256_cmp_pd(a, _mm256_setzero_pd(), _CMP_EQ_OQ));
}

/* The reciprocals y = RN(1 / b) (one division for every quotient by b). */
static inline __m256d quotient_fma_reciprocal(__m256d b)
{
    return _mm256_div_pd(_mm256_set1_pd(1.0), b);
}

/* RN(a / b) lane by lane, bit for bit the division's, given y =
 * quotient_fma_reciprocal(b), in the lanes where
 * quotient_fma_divisor_ok(b) and quotient_fma_dividend_ok(a) hold. */
static inline __m256d quotient_fma(__m256d a, __m256d b, __m256d y)
{
    const __m256d q0 = _mm256_mul_pd(a, y);
    const __m256d r0 = _mm256_fnmadd_pd(q0, b, a); /* a - b q0 */
    const __m256d q1 = _mm256_fmadd_pd(r0, y, q0);
    const __m256d r1 = _mm256_fnmadd_pd(q1, b, a); /* exact */
    const __m256d q2 = _mm256_fmadd_pd(r1, y, q1);
    return _mm256_blendv_pd(q2, q0, _mm256_cmp_pd(a, _mm256_setzero_pd(), _CMP_EQ_OQ));
}
#else
#define QUOTIENT_FMA 0
#endif

#endif
