/* SPDX-License-Identifier: Apache-2.0 */
/*
 * quotient_fma.c - base/quotient_fma.h's quotients against the hardware
 * division, bit for bit.
 *
 * The camera rays of the frame's AVX2 and AVX-512 copies
 * (render/render.c under QUOTIENT_FMA) divide by the FMA quotient where
 * the helper's operand tests pass; an image must not change by one bit,
 * so every quotient the tests admit must be the division's.  Operand
 * pairs (about 40 million, four to a vector):
 * - random doubles with exponents over the whole range, both signs, and
 *   over the range the tests admit;
 * - pairs whose quotient is at or next to a rounding midpoint: b random,
 *   q a chosen double (random or with a significand of all ones or
 *   ending in 1), a = RN(q b) and its neighbours, and a = RN(m b) for the
 *   midpoint m between q and its successor (a/b then lies within an ulp
 *   of a of m), the hardest cases for a quotient's rounding;
 * - significands near 1 and 2 (b with all ones: y = RN(1/b) then errs
 *   most), powers of two, +-0 dividends (the sign of a zero quotient),
 *   subnormals, huge values, infinities and NaNs.
 * Where the tests refuse a lane nothing is compared (the caller divides);
 * the test checks that they refuse the operands outside the range
 * (zero, subnormal, infinite, NaN and huge divisors; subnormal and
 * huge dividends) and that they admit most of the in-range pairs, so
 * that the comparison cannot pass by refusing everything.
 *
 * Compiled with -mavx2 -mfma (CMakeLists.txt); main runs nothing wider
 * than SSE2 before asking the CPU, and the test is skipped (passes with
 * a message) where the CPU has no AVX2 and FMA or the build has no such
 * unit.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "base/quotient_fma.h"
#include "check.h"

#if QUOTIENT_FMA
static uint64_t rng = 0x9e3779b97f4a7c15ull;

static uint64_t next64(void)
{
    /* xorshift64* (Vigna 2016). */
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return rng * 2685821657736338717ull;
}

static double from_bits(uint64_t b)
{
    double d;
    memcpy(&d, &b, sizeof(d));
    return d;
}

static uint64_t to_bits(double d)
{
    uint64_t b;
    memcpy(&b, &d, sizeof(b));
    return b;
}

/* A random double with a random sign, a random significand and a
 * biased exponent in [lo, hi]. */
static double random_double(int lo, int hi)
{
    const uint64_t r = next64();
    const uint64_t e = (uint64_t)(lo + (int)((r >> 11) % (uint64_t)(hi - lo + 1)));
    const uint64_t b = (next64() & 0x800fffffffffffffull) | (e << 52);
    return from_bits(b);
}

/* Counts over all pairs. */
struct tally {
    long long pairs, admitted, wrong;
};

/* Four pairs through the helper: every admitted lane must equal a / b
 * bit for bit. */
static void check4(const double a[4], const double b[4], struct tally *t)
{
    const __m256d va = _mm256_loadu_pd(a), vb = _mm256_loadu_pd(b);
    const __m256d ok = _mm256_and_pd(quotient_fma_divisor_ok(vb), quotient_fma_dividend_ok(va));
    const __m256d q = quotient_fma(va, vb, quotient_fma_reciprocal(vb));
    double got[4], okd[4];
    _mm256_storeu_pd(got, q);
    _mm256_storeu_pd(okd, ok);
    for (int i = 0; i < 4; i++) {
        t->pairs++;
        if (to_bits(okd[i]) == 0)
            continue;
        t->admitted++;
        const double want = a[i] / b[i];
        if (to_bits(got[i]) != to_bits(want)) {
            if (t->wrong < 10)
                printf("  wrong: %a / %a = %a, helper %a\n", a[i], b[i], want, got[i]);
            t->wrong++;
        }
    }
}

/* A lane the tests must refuse (a / b outside the helper's range). */
static int refused(double a, double b)
{
    const __m256d va = _mm256_set1_pd(a), vb = _mm256_set1_pd(b);
    const __m256d ok = _mm256_and_pd(quotient_fma_divisor_ok(vb), quotient_fma_dividend_ok(va));
    return _mm256_movemask_pd(ok) == 0;
}

/* The pairs by kind; buffers of four. */
struct batch {
    double a[4], b[4];
    int n;
};

static void add(struct batch *bt, double a, double b, struct tally *t)
{
    bt->a[bt->n] = a;
    bt->b[bt->n] = b;
    if (++bt->n == 4) {
        check4(bt->a, bt->b, t);
        bt->n = 0;
    }
}

static void run(void)
{
    struct tally t = {0, 0, 0};
    struct batch bt = {{0}, {0}, 0};
    const int bias = 1023;

    tu_section("random pairs");
    /* Whole exponent range (subnormals, huge values), then the admitted
     * range and a little beyond it. */
    for (long i = 0; i < 4000000; i++)
        add(&bt, random_double(0, 2046), random_double(0, 2046), &t);
    for (long i = 0; i < 8000000; i++)
        add(&bt, random_double(bias - 620, bias + 620), random_double(bias - 210, bias + 210), &t);
    /* Geometry's magnitudes: coordinates and lengths near 1. */
    for (long i = 0; i < 8000000; i++)
        add(&bt, random_double(bias - 40, bias + 40), random_double(bias - 20, bias + 20), &t);
    CHECKF(t.wrong == 0, "%lld of %lld admitted random quotients differ", t.wrong, t.admitted);
    printf("  random: %lld pairs, %lld admitted, %lld differ\n", t.pairs, t.admitted, t.wrong);
    CHECK(t.admitted > t.pairs / 2);

    tu_section("near midpoints");
    struct tally m = {0, 0, 0};
    for (long i = 0; i < 2500000; i++) {
        double b = random_double(bias - 150, bias + 150);
        /* Significands of b near 2 (all ones, y = RN(1/b) errs most) and
         * near 1, a quarter each. */
        if (i % 4 == 1)
            b = from_bits(to_bits(b) | 0x000ffffffffff000ull | (next64() & 0xfffull));
        else if (i % 4 == 2)
            b = from_bits(to_bits(b) & ~0x000ffffffffff000ull);
        double q = random_double(bias - 150, bias + 150);
        if (i % 3 == 1)
            q = from_bits(to_bits(q) | 0x000fffffffffff00ull); /* significand near 2 */
        else if (i % 3 == 2)
            q = from_bits(to_bits(q) | 1ull); /* odd last bit */
        const double a = q * b;
        add(&bt, a, b, &m);
        add(&bt, nextafter(a, INFINITY), b, &m);
        add(&bt, nextafter(a, -INFINITY), b, &m);
        /* The midpoint between q and its successor times b. */
        const double qn = nextafter(q, INFINITY);
        const long double mid = ((long double)q + (long double)qn) / 2.0L;
        const double am = (double)(mid * (long double)b);
        add(&bt, am, b, &m);
        add(&bt, nextafter(am, INFINITY), b, &m);
        add(&bt, nextafter(am, -INFINITY), b, &m);
    }
    CHECKF(m.wrong == 0, "%lld of %lld admitted near-midpoint quotients differ", m.wrong,
           m.admitted);
    printf("  near midpoints: %lld pairs, %lld admitted, %lld differ\n", m.pairs, m.admitted,
           m.wrong);
    CHECK(m.admitted > m.pairs * 9 / 10);

    tu_section("special operands");
    struct tally s = {0, 0, 0};
    static const double specials[] = {0.0,      -0.0,      1.0,       -1.0,     2.0,
                                      0.5,      3.0,       0x1p-200,  0x1p200,  -0x1p-200,
                                      0x1p-600, -0x1p600,  0x1p-601,  0x1p601,  0x1.fffffffffffffp-1,
                                      0x1.0000000000001p0, 0x1p-1074, -0x1p-1022, 0x1p1023,
                                      INFINITY, -INFINITY, NAN,       1e-310,   DBL_MAX};
    const int count = (int)(sizeof(specials) / sizeof(specials[0]));
    for (int i = 0; i < count; i++)
        for (int j = 0; j < count; j++)
            for (int k = 0; k < 4; k++)
                add(&bt, specials[i] * (k < 2 ? 1.0 : -1.0), specials[j], &s);
    /* Powers of two and their neighbours against random divisors and
     * back. */
    for (int e = -620; e <= 620; e++) {
        const double p = ldexp(1.0, e);
        for (int k = 0; k < 50; k++) {
            const double r = random_double(bias - 200, bias + 200);
            add(&bt, p, r, &s);
            add(&bt, nextafter(p, 0.0), r, &s);
            add(&bt, r, e >= -200 && e <= 200 ? p : 1.0, &s);
            add(&bt, -r, e >= -200 && e <= 200 ? nextafter(p, INFINITY) : 3.0, &s);
        }
    }
    /* Zero dividends of both signs over divisors of both signs: the
     * zero's sign as the division's. */
    for (int k = 0; k < 100000; k++) {
        const double r = random_double(bias - 200, bias + 200);
        add(&bt, 0.0, r, &s);
        add(&bt, -0.0, r, &s);
    }
    while (bt.n)
        add(&bt, 1.0, 3.0, &s);
    CHECKF(s.wrong == 0, "%lld of %lld admitted special quotients differ", s.wrong, s.admitted);
    printf("  special: %lld pairs, %lld admitted, %lld differ\n", s.pairs, s.admitted, s.wrong);

    tu_section("refused operands");
    CHECK(refused(1.0, 0.0));
    CHECK(refused(1.0, -0.0));
    CHECK(refused(0.0, 0.0));
    CHECK(refused(1.0, INFINITY));
    CHECK(refused(1.0, NAN));
    CHECK(refused(NAN, 1.0));
    CHECK(refused(INFINITY, 1.0));
    CHECK(refused(-INFINITY, 2.0));
    CHECK(refused(1.0, 1e-310));   /* subnormal divisor */
    CHECK(refused(1e-310, 1.0));   /* subnormal dividend */
    CHECK(refused(1.0, 0x1p201));  /* huge divisor */
    CHECK(refused(1.0, 0x1p-201)); /* tiny divisor */
    CHECK(refused(0x1p601, 1.0));  /* huge dividend */
    CHECK(refused(0x1p-601, 1.0)); /* tiny dividend */
    CHECK(!refused(0.0, 1.0));
    CHECK(!refused(-0.0, -3.0));
    CHECK(!refused(0x1p600, 0x1p-200));
    CHECK(!refused(-0x1p-600, 0x1p200));
}
#endif

int main(void)
{
#if QUOTIENT_FMA
    __builtin_cpu_init();
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) {
        printf("quotient_fma: the CPU has no AVX2 and FMA, skipped\n");
        return 0;
    }
    run();
    return test_summary("quotient_fma");
#else
    printf("quotient_fma: no AVX2 and FMA unit in this build, skipped\n");
    return 0;
#endif
}
