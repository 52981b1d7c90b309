/* SPDX-License-Identifier: Apache-2.0 */
/*
 * quotient_known.c - base/quotient_known.h's quotients by a prepared
 * divisor against the hardware division, bit for bit, and the frame's
 * row of unprojected points (render/render.c, through the test hook
 * render_unproject_rows of each unit) against mat4_project.
 *
 * The helper (scalar form, and the four- and two-lane FMA forms where
 * the CPU has AVX2 and FMA): divisors random over the whole admitted
 * exponent range, near 1 and 2, with trailing zero bits, and the w that
 * real projections give (frustum and gluPerspective near/far pairs, the
 * inverse by mat4_invert as render.c takes it); for each divisor the
 * check accepts, dividends random over the admitted range, significands
 * all ones and near powers of two, zeros of both signs (the sign of the
 * zero quotient), the bounds of the range, and the dividends whose
 * quotient lies closest to a rounding midpoint: 2^s X = N (mod Y) for
 * s = 53, 54 and 0 < |N| <= 24 (wider than the helper's argument needs),
 * found here by the extended Euclidean algorithm (the helper halves
 * modulo Y instead), at several scales and both signs.  For each divisor
 * the check refuses, the test looks for a dividend that fails among the
 * same near-midpoint ones; a refusal it cannot justify fails the test.  The check must refuse
 * zero, subnormal, infinite, NaN and out-of-range divisors and accept
 * both bounds.
 *
 * The rows: projections from glFrustum, gluPerspective and glOrtho
 * (random bounds, near/far ratios up to 1e9, viewports of odd and even
 * sizes, tiles anywhere, also beyond the viewport's edge), whose row
 * fill must take the constant-w path in most cases; oblique ones whose
 * inverse has x and y terms in its w row (the path must not be taken);
 * and frustums whose w the check refuses.  Every point each unit
 * unprojects must equal mat4_project of its pixel centre bit for bit,
 * with the same state.
 *
 * Compiled with -mavx2 -mfma (CMakeLists.txt) for the vector forms;
 * main runs nothing wider than SSE2 before asking the CPU, and the
 * vector parts are skipped where it has no AVX2 and FMA.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "base/mat4.h"
#include "base/quotient_known.h"
#include "brute_force.h"
#include "check.h"
#include "render/render.h"

/* brute_force.h's fixed-seed generator, one stream for the whole test. */
static struct bf_rng rng = {0x2545f4914f6cdd1dull};

static uint64_t next64(void)
{
    return bf_next(&rng);
}

static double uniform(void)
{
    return bf_uniform(&rng);
}

static double from_bits(uint64_t b)
{
    double d;
    memcpy(&d, &b, sizeof(d));
    return d;
}

/* A random significand in [1, 2) scaled by 2^e, random sign. */
static double random_scaled(int e)
{
    const uint64_t b = (next64() & 0x800fffffffffffffull) | ((uint64_t)(1023 + e) << 52);
    return from_bits(b);
}

static int vector_forms; /* the CPU runs the AVX2 and FMA forms */

struct tally {
    long long pairs, wrong;
};

static void wrong(struct tally *t, double x, double y, double want, double got, const char *form)
{
    if (t->wrong < 8)
        printf("  wrong (%s): %a / %a = %a, helper %a\n", form, x, y, want, got);
    t->wrong++;
}

/* x / y through every form of the helper against the division. */
static void check_pair(const struct quotient_known *k, double x, struct tally *t)
{
    const double want = x / k->y;
    t->pairs++;
    const double got = quotient_known(k, x);
    if (quotient_known_bits(got) != quotient_known_bits(want)) {
        wrong(t, x, k->y, want, got, "scalar");
        return;
    }
#if QUOTIENT_KNOWN_FMA
    if (vector_forms) {
        double g4[4], g2[2];
        _mm256_storeu_pd(g4, quotient_known4(_mm256_set_pd(1.0, x, -x, x),
                                             _mm256_set1_pd(k->zh), _mm256_set1_pd(k->zl)));
        _mm_storeu_pd(g2, quotient_known2(_mm_set_pd(x, -x), _mm_set1_pd(k->zh),
                                          _mm_set1_pd(k->zl)));
        if (quotient_known_bits(g4[0]) != quotient_known_bits(want) || quotient_known_bits(g4[2]) != quotient_known_bits(want))
            wrong(t, x, k->y, want, g4[0], "four lanes");
        else if (quotient_known_bits(g4[1]) != quotient_known_bits(-x / k->y) || quotient_known_bits(g2[0]) != quotient_known_bits(-x / k->y))
            wrong(t, -x, k->y, -x / k->y, g4[1], "lanes");
        else if (quotient_known_bits(g2[1]) != quotient_known_bits(want))
            wrong(t, x, k->y, want, g2[1], "two lanes");
    }
#endif
}

/* a^-1 mod m (m odd, a odd or coprime) by the extended Euclidean
 * algorithm. */
static uint64_t inverse_mod(uint64_t a, uint64_t m)
{
    int64_t r0 = (int64_t)m, r1 = (int64_t)(a % m), t0 = 0, t1 = 1;
    while (r1 != 0) {
        const int64_t q = r0 / r1;
        int64_t tmp = r0 - q * r1;
        r0 = r1;
        r1 = tmp;
        tmp = t0 - q * t1;
        t0 = t1;
        t1 = tmp;
    }
    if (t0 < 0)
        t0 += (int64_t)m;
    return (uint64_t)t0;
}

/* (a b) mod m for a, b < m < 2^53, by doubling. */
static uint64_t mul_mod(uint64_t a, uint64_t b, uint64_t m)
{
    uint64_t r = 0;
    a %= m;
    while (b) {
        if (b & 1)
            r = (r + a) % m;
        a = (a + a) % m;
        b >>= 1;
    }
    return r;
}

/* The dividends x (significands X in [2^52, 2^53), scaled to [1, 2))
 * with 2^s X = n (mod Y) for s = 53, 54 and 0 < |n| <= 24: the quotients
 * closest to a rounding midpoint, into out (at most limit); returns
 * their count. */
static int near_midpoint(double y, double *out, int limit)
{
    int e;
    const uint64_t Y = (uint64_t)ldexp(frexp(fabs(y), &e), 53);
    int count = 0;
    for (int s = 53; s <= 54; s++) {
        for (int n = -24; n <= 24; n++) {
            if (n == 0)
                continue;
            /* 2^s X = n (mod Y): with g = 2^j the power of two in Y, g
             * must divide n; then X = (n / g) (2^(s - j))^-1 mod Y / g. */
            int j = 0;
            while (((Y >> j) & 1) == 0)
                j++;
            if (j > 4 || n % (1 << j) != 0)
                continue; /* |n| < 2^5 */
            const uint64_t m = Y >> j;
            if (m == 1)
                continue;
            uint64_t p = 1 % m; /* 2^(s - j) mod m */
            for (int h = 0; h < s - j; h++)
                p = (p * 2) % m;
            const int64_t nn = n / (1 << j);
            const uint64_t nm = nn >= 0 ? (uint64_t)nn % m : (m - (uint64_t)(-nn) % m) % m;
            const uint64_t c = mul_mod(nm, inverse_mod(p, m), m);
            const uint64_t lo = (uint64_t)1 << 52, hi = (uint64_t)1 << 53;
            uint64_t X = c >= lo ? c : c + m * ((lo - c + m - 1) / m);
            for (int guard = 0; X < hi && guard < 64; X += m, guard++) {
                if (count < limit)
                    out[count++] = ldexp((double)X, -52);
            }
        }
    }
    return count;
}

/* Every kind of dividend against a divisor the check accepted. */
static void check_divisor(const struct quotient_known *k, int random_pairs, struct tally *t)
{
    double hard[512];
    const int nh = near_midpoint(k->y, hard, 512);
    static const int scales[] = {0, 1, -1, 7, -13, 100, -200, 300, -440, 449};
    for (int i = 0; i < nh; i++)
        for (size_t s = 0; s < sizeof(scales) / sizeof(scales[0]); s++)
            check_pair(k, ldexp(hard[i], scales[s]), t);
    for (int i = 0; i < random_pairs; i++) {
        const int e = (int)(next64() % 900) - 450;
        check_pair(k, random_scaled(e), t);
    }
    /* Significands all ones, powers of two and neighbours, the bounds,
     * zeros. */
    const double special[] = {0x1.fffffffffffffp0, 0x1p0, 0x1.0000000000001p0, 0x1.fffffffffffffp-1,
                              0x1p-450, 0x1.fffffffffffffp449, 0x1p449, 3.0, 0.1, 1e300 * 1e-200};
    for (size_t i = 0; i < sizeof(special) / sizeof(special[0]); i++) {
        check_pair(k, special[i], t);
        check_pair(k, -special[i], t);
    }
    for (int i = 0; i < 8; i++)
        check_pair(k, ldexp(1.0 + uniform(), (int)(next64() % 40) - 20), t);
    /* A zero quotient keeps its sign (check_pair compares bits). */
    check_pair(k, 0.0, t);
    check_pair(k, -0.0, t);
}

/* For a refused divisor: 1 when some near-midpoint dividend's quotient
 * (with the constants the check computed) differs from the division. */
static int refusal_justified(double y)
{
    /* Recompute the constants as quotient_known_prepare does. */
    struct quotient_known k;
    k.y = y;
    double zh = 1.0 / y;
    double r = fma(-y, zh, 1.0);
    if (r < 0.0) {
        zh = nextafter(zh, 0.0);
        r = fma(-y, zh, 1.0);
    }
    k.zh = zh;
    k.zl = r / y;
    double hard[512];
    const int nh = near_midpoint(y, hard, 512);
    for (int i = 0; i < nh; i++)
        if (quotient_known_bits(quotient_known(&k, hard[i])) != quotient_known_bits(hard[i] / y) ||
            quotient_known_bits(quotient_known(&k, -hard[i])) != quotient_known_bits(-hard[i] / y))
            return 1;
    return 0;
}

struct divisors {
    long long accepted, refused, unjustified;
};

static void try_divisor(double y, int random_pairs, struct divisors *d, struct tally *t)
{
    struct quotient_known k;
    if (quotient_known_prepare(&k, y)) {
        d->accepted++;
        check_divisor(&k, random_pairs, t);
    } else {
        d->refused++;
        if (!refusal_justified(y)) {
            if (d->unjustified < 4)
                printf("  refused without a failing dividend found: %a\n", y);
            d->unjustified++;
        }
    }
}

/* A projection's w for the near and far planes as render.c's
 * unproject_w_known computes them (m3 = m7 = 0). */
static void projection_w(const double proj[16], double *wn, double *wf)
{
    double inv[16];
    *wn = *wf = 0.0;
    if (!mat4_invert(inv, proj))
        return;
    *wn = (0.0 + inv[11] * -1.0) + inv[15];
    *wf = (0.0 + inv[11] * 1.0) + inv[15];
}

/* gluPerspective's matrix: glFrustum's with top = n tan(fovy / 2). */
static void perspective(double fovy_deg, double aspect, double n, double f, double m[16])
{
    const double top = n * tan(fovy_deg * 3.14159265358979323846 / 360.0);
    bf_frustum(m, -top * aspect, top * aspect, -top, top, n, f);
}

static double near_far_ratio(void)
{
    return pow(10.0, 9.0 * uniform()) + uniform();
}

/* A random frustum, perspective or orthographic projection. */
static void random_projection(int kind, double m[16])
{
    const double n = pow(10.0, -3.0 + 5.0 * uniform());
    const double f = n * near_far_ratio();
    if (kind == 0) {
        const double w = n * (0.1 + 2.0 * uniform()), h = n * (0.1 + 2.0 * uniform());
        const double cx = (uniform() - 0.5) * w, cy = (uniform() - 0.5) * h;
        bf_frustum(m, cx - w, cx + w, cy - h, cy + h, n, f);
    } else if (kind == 1) {
        perspective(10.0 + 150.0 * uniform(), 0.3 + 3.0 * uniform(), n, f, m);
    } else {
        const double w = pow(10.0, -2.0 + 4.0 * uniform()), h = w * (0.3 + 3.0 * uniform());
        const double c = (uniform() - 0.5) * w;
        bf_ortho(m, c - w, c + w, -h, h, n - 1.0, f);
    }
}

/* m = m v for a random camera v (a rotation about a random axis and a
 * translation, as look-at cameras give): the projection with the camera
 * multiplied in, as BART's scenes load it, whose inverse has w-row x and
 * y terms of rounding size. */
static void with_camera(double m[16])
{
    double ax[3] = {uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};
    const double len = sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]) + 1e-9;
    for (int k = 0; k < 3; k++)
        ax[k] /= len;
    double v[16];
    bf_rotation(v, 6.283185307179586 * uniform(), ax);
    for (int k = 0; k < 3; k++)
        v[12 + k] = (uniform() - 0.5) * pow(10.0, 3.0 * uniform());
    bf_mul(m, m, v);
}

/* The projection P premultiplied by a clip-space map adding a x + b y to
 * w: its inverse's w row has x and y terms, so w varies by point. */
static void oblique(double m[16], double a, double b)
{
    const double s[16] = {1, 0, 0, a, 0, 1, 0, b, 0, 0, 1, 0, 0, 0, 0, 1}; /* column-major */
    bf_mul(m, s, m);
}

struct rows_tally {
    long long projections, known, points, wrong, state_wrong;
};

/* Each unit's rows against mat4_project, point by point. */
static void check_rows(render_unproject_rows_fn fn, const char *unit, const double proj[16],
                       const int vp[4], int x0, int y, struct rows_tally *t, int *known)
{
    enum { N = RENDER_UNPROJECT_ROWS * RENDER_UNPROJECT_COLS };
    double near_pt[N][3], far_pt[N][3];
    signed char state[N];
    double inv[16];
    const int w = fn(proj, vp, x0, y, near_pt, far_pt, state);
    *known = w;
    if (w < 0 || !mat4_invert(inv, proj))
        return;
    t->projections++;
    t->known += w;
    for (int r = 0; r < RENDER_UNPROJECT_ROWS; r++) {
        /* The columns a tile reads: its RENDER_TILE_SIZE and the next. */
        for (int i = 0; i <= RENDER_TILE_SIZE; i++) {
            const int p = r * RENDER_UNPROJECT_COLS + i;
            const double px = x0 + i + 0.5, py = y + r + 0.5;
            double ndc_near[3] = {2.0 * px / vp[2] - 1.0, 2.0 * py / vp[3] - 1.0, -1.0};
            double ndc_far[3] = {ndc_near[0], ndc_near[1], 1.0};
            double n3[3], f3[3];
            const int ok = mat4_project(inv, ndc_near, n3) && mat4_project(inv, ndc_far, f3);
            t->points++;
            if (ok != (state[p] > 0)) {
                if (t->state_wrong < 4)
                    printf("  %s: state %d where mat4_project says %d\n", unit, state[p], ok);
                t->state_wrong++;
                continue;
            }
            if (!ok)
                continue;
            for (int k = 0; k < 3; k++)
                if (quotient_known_bits(n3[k]) != quotient_known_bits(near_pt[p][k]) ||
                    quotient_known_bits(f3[k]) != quotient_known_bits(far_pt[p][k])) {
                    if (t->wrong < 4)
                        printf("  %s: point (%d, %d) coordinate %d: %a %a, mat4_project %a %a\n",
                               unit, x0 + i, y + r, k, near_pt[p][k], far_pt[p][k], n3[k], f3[k]);
                    t->wrong++;
                    break;
                }
        }
    }
}

static int cpu_avx2_fma(void)
{
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
    return 0;
#endif
}

static int cpu_avx512(void)
{
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
    __builtin_cpu_init();
    return cpu_avx2_fma() && __builtin_cpu_supports("avx512f") &&
           __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw") &&
           __builtin_cpu_supports("avx512dq");
#else
    return 0;
#endif
}

int main(void)
{
    vector_forms = QUOTIENT_KNOWN_FMA && cpu_avx2_fma();
    printf("quotient_known: vector forms %s\n", vector_forms ? "tested" : "skipped");

    /* The range: refused and accepted divisors. */
    struct quotient_known k;
    const double refuse[] = {0.0, -0.0, 0x1p-1074, 0x1.fffffffffffffp-1023, 0x1p-1022, 0x1p-301,
                             0x1.fffffffffffffp-302, 0x1.0000000000001p300, 0x1p301, DBL_MAX,
                             INFINITY, -INFINITY, NAN, -0x1p-301, -0x1p301};
    for (size_t i = 0; i < sizeof(refuse) / sizeof(refuse[0]); i++)
        CHECKF(!quotient_known_prepare(&k, refuse[i]), "divisor %a refused", refuse[i]);
    const double accept[] = {0x1p-300, 0x1p300, -0x1p-300, -0x1p300, 1.0, -1.0, 0.5, 4096.0};
    for (size_t i = 0; i < sizeof(accept) / sizeof(accept[0]); i++)
        CHECKF(quotient_known_prepare(&k, accept[i]), "divisor %a accepted", accept[i]);

    struct tally t = {0, 0};
    struct divisors random_d = {0, 0, 0}, shaped_d = {0, 0, 0}, proj_d = {0, 0, 0};
    /* Random divisors over the whole range, a few thousand pairs each. */
    for (int i = 0; i < 6000; i++)
        try_divisor(random_scaled((int)(next64() % 600) - 300), 3000, &random_d, &t);
    /* Divisors near 1 and 2, with trailing zeros, few bits. */
    for (int i = 0; i < 3000; i++) {
        const uint64_t sig = next64() & 0x000fffffffffffffull;
        double y;
        switch (i % 6) {
        case 0: y = from_bits(0x3ff0000000000000ull | (sig & 0xffff)); break;
        case 1: y = from_bits(0x3fffffffffff0000ull | (sig & 0xffff)); break;
        case 2: y = from_bits(0x3ff0000000000000ull | (sig & ~1ull) | 2); break; /* j = 1 */
        case 3: y = from_bits(0x3ff0000000000000ull | (sig & ~3ull) | 4); break; /* j = 2 */
        case 4: y = from_bits(0x3ff0000000000000ull | (sig & ~7ull) | 8); break; /* j = 3 */
        default: y = (double)(next64() % 1000 + 3) * (i & 1 ? -1.0 : 1.0); break;
        }
        try_divisor(y, 500, &shaped_d, &t);
    }
    /* The w of real projections. */
    for (int i = 0; i < 6000; i++) {
        double m[16], wn, wf;
        random_projection(i % 3, m);
        projection_w(m, &wn, &wf);
        try_divisor(wn, 300, &proj_d, &t);
        try_divisor(wf, 300, &proj_d, &t);
    }
    printf("  %lld pairs, %lld wrong\n", t.pairs, t.wrong);
    printf("  divisors accepted / refused (unjustified): random %lld / %lld (%lld), shaped %lld / "
           "%lld (%lld), projections' w %lld / %lld (%lld)\n",
           random_d.accepted, random_d.refused, random_d.unjustified, shaped_d.accepted,
           shaped_d.refused, shaped_d.unjustified, proj_d.accepted, proj_d.refused,
           proj_d.unjustified);
    CHECKF(t.wrong == 0, "every admitted quotient is the division's (%lld wrong)", t.wrong);
    CHECKF(t.pairs > 20000000, "enough pairs (%lld)", t.pairs);
    CHECKF(random_d.unjustified + shaped_d.unjustified + proj_d.unjustified == 0,
          "every refused divisor has a failing dividend");
    CHECKF(random_d.accepted > random_d.refused && proj_d.accepted > proj_d.refused,
          "most divisors accepted");

    /* The rows of each unit. */
    struct {
        const char *name;
        render_unproject_rows_fn fn;
    } units[3] = {{"render.c", render_unproject_rows}, {"avx2", NULL}, {"avx512", NULL}};
    if (cpu_avx2_fma())
        units[1].fn = render_unproject_rows_avx2_unit();
    if (cpu_avx512())
        units[2].fn = render_unproject_rows_avx512_unit();
    for (int u = 0; u < 3; u++) {
        if (!units[u].fn) {
            printf("  rows %s: skipped (absent or the CPU cannot run it)\n", units[u].name);
            continue;
        }
        struct rows_tally plain = {0, 0, 0, 0, 0}, skew = {0, 0, 0, 0, 0}, refused = {0, 0, 0, 0, 0};
        struct rows_tally camera = {0, 0, 0, 0, 0};
        long long refused_found = 0;
        for (int i = 0; i < 3000; i++) {
            double m[16];
            random_projection(i % 3, m);
            const int vp[4] = {0, 0, 1 + (int)(next64() % 2000), 1 + (int)(next64() % 1500)};
            const int x0 = (int)(next64() % (uint64_t)(vp[2] + 16)) - 8;
            const int y = (int)(next64() % (uint64_t)(vp[3] + 16)) - 8;
            int known;
            check_rows(units[u].fn, units[u].name, m, vp, x0, y, &plain, &known);
            /* The middle column of an odd viewport: zero dividends. */
            check_rows(units[u].fn, units[u].name, m, (const int[4]){0, 0, 2 * (i % 500) + 1, 9},
                       i % 500 - 8, 3, &plain, &known);
            /* The camera multiplied in (most of these keep w constant
             * bit for bit through the second case of
             * unproject_w_known). */
            double mv[16];
            memcpy(mv, m, sizeof(mv));
            with_camera(mv);
            check_rows(units[u].fn, units[u].name, mv, vp, x0, y, &camera, &known);
            check_rows(units[u].fn, units[u].name, mv, (const int[4]){0, 0, 1024, 768},
                       (int)(next64() % 64) * 16, (int)(next64() % 48) * 16, &camera, &known);
            oblique(m, (uniform() - 0.5) * 0.2, (uniform() - 0.5) * 0.2);
            check_rows(units[u].fn, units[u].name, m, vp, x0, y, &skew, &known);
        }
        /* Frustums whose w the check refuses (searched for). */
        for (int i = 0; i < 200000 && refused_found < 50; i++) {
            double m[16], wn, wf;
            random_projection(i % 2, m);
            projection_w(m, &wn, &wf);
            struct quotient_known a, b;
            if (quotient_known_prepare(&a, wn) && quotient_known_prepare(&b, wf))
                continue;
            refused_found++;
            const int vp[4] = {0, 0, 640, 480};
            int known;
            check_rows(units[u].fn, units[u].name, m, vp, (int)(next64() % 640),
                       (int)(next64() % 480), &refused, &known);
            CHECKF(known == 0, "%s: the refused w take the division", units[u].name);
        }
        printf("  rows %s: w known in %lld of %lld projections (%lld points, %lld differ, %lld "
               "states); oblique %lld known of %lld (%lld points, %lld differ); refused w %lld "
               "projections (%lld differ); with a camera %lld known of %lld (%lld points, "
               "%lld differ)\n",
               units[u].name, plain.known, plain.projections, plain.points, plain.wrong,
               plain.state_wrong, skew.known, skew.projections, skew.points, skew.wrong,
               refused.projections, refused.wrong, camera.known, camera.projections,
               camera.points, camera.wrong);
        CHECKF(plain.wrong + plain.state_wrong + skew.wrong + skew.state_wrong + refused.wrong +
                       refused.state_wrong + camera.wrong + camera.state_wrong ==
                   0,
              "%s: every unprojected point is mat4_project's", units[u].name);
        CHECKF(plain.known * 10 > plain.projections * 8, "%s: the constant w taken for most",
              units[u].name);
        CHECKF(skew.known == 0, "%s: no constant w under oblique projections", units[u].name);
        CHECKF(refused_found > 0, "%s: refused projections found", units[u].name);
    }
    return test_summary("quotient_known");
}
