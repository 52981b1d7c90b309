/* SPDX-License-Identifier: Apache-2.0 */
/*
 * quotient_known.h - correctly rounded double quotients x / y by a
 * divisor y known in advance, without the divider: two constants zh and
 * zl prepared once for y, then q = RN(x zh + RN(x zl)), one product and
 * one fused multiply-add (Brisebarre, Muller and Raina 2004,
 * "Accelerating correctly rounded floating-point division when the
 * divisor is known in advance", IEEE Trans. Computers 53(8), their
 * division with one multiplication and one fused multiply-add; Muller et
 * al., Handbook of Floating-Point Arithmetic, 2nd ed. 2018, the section
 * on division by a constant).  The frame's row of unprojected points
 * divides every coordinate by the same two w under the usual projections
 * (render/render.c), and the divider bounds that code
 * (docs/performance-log.md, round 63, zs2).
 *
 * The result equals RN(x / y) for every x only for some y, so
 * quotient_known_prepare checks the divisor and refuses it otherwise
 * (the caller then divides).  The check and its argument, written out
 * here (the bounds are this file's own, in the spirit of the paper: only
 * dividends whose quotient lies within a few 2^-106 of a rounding
 * midpoint can fail, and a modular inverse finds them all):
 *
 * Scale x and y to [1, 2) (powers of two change nothing while every
 * value stays normal) with integer significands X = x 2^52, Y = y 2^52;
 * y a power of two is exact (zl = 0).  zh is the double next below 1/y
 * (RN(1/y), or its predecessor when RN(1/y) > 1/y), so 0 < 1/y - zh <
 * 2^-53 and zl = RN(1/y - zh) has zh's sign: 0 < zl <= 2^-53, and 1/y =
 * zh + zl + e with |e| <= 2^-53 zl <= 2^-106.  r = 1 - y zh is a multiple
 * of 2^-105 below 2^-52, a double, which fma(-y, zh, 1) gives exactly,
 * and zl = RN(r / y).  Let Q = x / y and u = x zh + RN(x zl): |u - Q| <=
 * |RN(x zl) - x zl| + x |e| <= x 2^-106 + x 2^-106 = x 2^-105, and q =
 * RN(u) (the FMA's one rounding) equals RN(Q) unless a midpoint m lies
 * within x 2^-105 of Q (Q itself is never a midpoint).
 * - Q in [1, 2) (x >= y): m = (2K + 1) 2^-53, Q - m = N 2^-105 / y with
 *   the integer N = 2^53 X - (2K + 1) Y, so a failure needs |N| <= x y <
 *   4;
 * - Q in (1/2, 1): m = (2K + 1) 2^-54, Q - m = N 2^-106 / y with N =
 *   2^54 X - (2K + 1) Y, so a failure needs |N| <= 2 x y < 8.
 * So x can fail only if 2^s X = N (mod Y) for s = 53 and 0 < |N| <= 3 or
 * s = 54 and 0 < |N| <= 7.  With Y = 2^j Yo, Yo odd, that needs 2^j | N
 * and X = (N / 2^j) 2^-(s - j) (mod Yo): none when j >= 3, else Yo >=
 * 2^50 and each of the (at most 20) classes holds at most five X in
 * [2^52, 2^53).  The check runs the quotient on each of them (against
 * the division, bit for bit); if all agree, every x agrees.  Signs: RN
 * is symmetric, and a zero x gives x zh and RN(x zl) zeros of the same
 * sign (zh and zl share y's sign), whose sum is the zero x / y gives.
 *
 * Range (the caller's part): the divisor 2^-300 <= |y| <= 2^300 (the
 * check refuses others); the dividend x = +-0 or 2^-450 <= |x| <= 2^450.
 * Then zh, zl (|zl| >= 2^-107 |zh|, as r >= 2^-105), x zl, u and q are
 * normal and finite, which the bounds above assume.  Nothing here tests
 * the dividends: the caller proves their range once (render.c does so
 * per frame from the matrix).
 *
 * The scalar form (fma from math.h, the same single rounding as the
 * instruction) serves the check and the tests; the vector forms exist
 * in units compiled with FMA (QUOTIENT_KNOWN_FMA), where -ffp-contract=off
 * stays so that no other product and sum is fused.
 */
#ifndef RT_BASE_QUOTIENT_KNOWN_H
#define RT_BASE_QUOTIENT_KNOWN_H

#include <math.h>
#include <stdint.h>
#include <string.h>

/* A divisor prepared by quotient_known_prepare. */
struct quotient_known {
    double y, zh, zl;
};

/* RN(x zh + RN(x zl)): x / y where the check and the range hold. */
static inline double quotient_known(const struct quotient_known *k, double x)
{
    return fma(x, k->zh, x * k->zl);
}

static inline uint64_t quotient_known_bits(double d)
{
    uint64_t b;
    memcpy(&b, &d, sizeof(b));
    return b;
}

/* 1 when the quotient by y gives x / y bit for bit for every x of the
 * range above (k then holds y's constants); 0 when the caller must
 * divide (y outside the range, NaN, or a failing dividend found). */
static inline int quotient_known_prepare(struct quotient_known *k, double y)
{
    const double a = fabs(y);
    if (!(a >= 0x1p-300 && a <= 0x1p300))
        return 0;
    int e;
    const uint64_t Y = (uint64_t)ldexp(frexp(a, &e), 53); /* [2^52, 2^53) */
    k->y = y;
    if ((Y & (Y - 1)) == 0) {
        /* A power of two: 1 / y exact, and zl a zero of y's sign. */
        k->zh = 1.0 / y;
        k->zl = copysign(0.0, y);
        return 1;
    }
    double zh = 1.0 / y;
    double r = fma(-y, zh, 1.0); /* 1 - y zh, exact */
    if (r < 0.0) {
        /* RN(1/y) lies beyond 1/y: the next double toward zero. */
        zh = nextafter(zh, 0.0);
        r = fma(-y, zh, 1.0);
    }
    if (!(r > 0.0))
        return 0; /* not reached for y not a power of two */
    k->zh = zh;
    k->zl = r / y;
    /* The dividends that can fail (the classes above), each tried. */
    int j = 0;
    while (((Y >> j) & 1) == 0)
        j++;
    const uint64_t yo = Y >> j;
    if (j >= 3)
        return 1;
    for (int s = 53; s <= 54; s++) {
        const int nmax = s == 53 ? 3 : 7;
        for (int n = -nmax; n <= nmax; n++) {
            if (n == 0 || n % (1 << j) != 0)
                continue;
            /* c = (n / 2^j) 2^-(s - j) mod yo: halving modulo an odd yo. */
            const int64_t m = n / (1 << j);
            uint64_t c = m >= 0 ? (uint64_t)m % yo : yo - ((uint64_t)(-m) % yo);
            c %= yo;
            for (int h = 0; h < s - j; h++)
                c = (c & 1) ? (c + yo) >> 1 : c >> 1;
            const uint64_t lo = (uint64_t)1 << 52, hi = (uint64_t)1 << 53;
            uint64_t X = c >= lo ? c : c + yo * ((lo - c + yo - 1) / yo);
            for (; X < hi; X += yo) {
                const double x = ldexp((double)X, -52);
                if (quotient_known_bits(quotient_known(k, x)) != quotient_known_bits(x / y) ||
                    quotient_known_bits(quotient_known(k, -x)) != quotient_known_bits(-x / y))
                    return 0;
            }
        }
    }
    return 1;
}

#if defined(__AVX2__) && defined(__FMA__) && !defined(RT_NO_SIMD)
#include <immintrin.h>

#define QUOTIENT_KNOWN_FMA 1

/* quotient_known in four lanes, zh and zl broadcast. */
static inline __m256d quotient_known4(__m256d x, __m256d zh, __m256d zl)
{
    return _mm256_fmadd_pd(x, zh, _mm256_mul_pd(x, zl));
}

/* quotient_known in two lanes. */
static inline __m128d quotient_known2(__m128d x, __m128d zh, __m128d zl)
{
    return _mm_fmadd_pd(x, zh, _mm_mul_pd(x, zl));
}
#else
#define QUOTIENT_KNOWN_FMA 0
#endif

#endif
