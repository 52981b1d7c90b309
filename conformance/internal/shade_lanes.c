/* SPDX-License-Identifier: Apache-2.0 */
/*
 * shade_lanes.c - the lanes of the shading's AVX2 copy
 * (render/shade_eye_avx2.c) against their scalar references.
 *
 * The four-lane log2 of the levels of detail (lanes_log2_4, through
 * shade_log2_quad_avx2_unit) within 2^-48 of log2l over every 13th float
 * of [1, 2^32] (lod_fast takes it of squared footprints) and a million
 * random doubles there, 2^-48 also where the sum's rounding alone is up to
 * 2^-49 (results from 16 to 32): half the
 * bound (LANES_LOG2_BOUND, 2^-47) that lod_ray_quad's argument uses; and
 * its halved form (lanes_log2_4_half) bit for bit its half there.  The
 * AVX-512 copy's halved log2 (lanes_log2_8_half, through
 * shade_log2_oct_half_avx512_unit) within 2^-49 of log2l / 2 over the
 * same grid and random doubles, and bit for bit the four-lane half.
 *
 * The eight-lane texture lookup (scene_texture_sample_lod8, through
 * shade_texture_lod8_avx2_unit) against scene_texture_sample_lod, bit
 * for bit: textures of odd and
 * power-of-two sizes down to 1x1, REPEAT and CLAMP_TO_EDGE on each axis,
 * levels of detail at and around every level boundary, the last level,
 * magnifications, zeros, infinities and NaN, coordinates near texel
 * edges, negative, large and non-finite; half the blocks with every
 * lane on one level (or one level pair) and coordinates as a frame's
 * (frame_coord), as most of a frame's lookups.  A block it refuses (a
 * coordinate of 2^31 or more, other filters) must be refused whole.
 * The same lookups in the frame pipeline's two steps
 * (scene_texture_prefetch_lod8 and scene_texture_finish_lod8, through
 * shade_texture_lod8_steps_avx2_unit): the same refusals and the same
 * floats bit for bit.
 *
 * The levels of detail of a block on one triangle by its texel map
 * (surface.c's lod_fast_quad, through shade_lod_fast_avx2_unit) against
 * lod_ray, bit for bit in every lane it decides: triangles of every shape
 * from right to slivers, textures stretched up to 1000:1, directions
 * from head-on to grazing, widths putting lambda on and next to every
 * level boundary and anywhere in between; at least half the lanes must
 * be decided (the frame's common case, not only its fallback).  The
 * same for the AVX-512 copy's eight-lane form (lod_fast_oct, through
 * shade_lod_fast_avx512_unit) where that unit and the CPU are there.
 * Skipped where the unit is absent or the CPU has no AVX2.
 *
 * Internal test (links the static library).  Non-zero exit on failure.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "base/alloc.h"
#include "check.h"
#include "render/shade.h"
#include "render/surface.h"
#include "scene/texture.h"

static uint32_t rng = 2463534242u;

static uint32_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}

static float uniform(float lo, float hi)
{
    return lo + (hi - lo) * (float)(next() >> 8) / 16777216.0f;
}

static int set_random_image(struct scene_texture *tex, int w, int h)
{
    uint8_t *chain = rt_malloc(4 * scene_texture_chain_texels(w, h));
    if (!chain)
        return 0;
    for (size_t k = 0; k < 4 * (size_t)w * (size_t)h; k++)
        chain[k] = (uint8_t)next();
    if (scene_texture_build_mipmaps(chain, w, h) != 0) {
        rt_free(chain);
        return 0;
    }
    scene_texture_set_image(tex, w, h, chain);
    return 1;
}

/* A level of detail: special values, level boundaries and their float
 * neighbours, or anything in [-2, q + 3]. */
static float any_lambda(int q)
{
    switch (next() % 8) {
    case 0: {
        const float special[] = {NAN, -INFINITY, INFINITY, 0.0f, -0.0f, 1e-30f, -1e-30f};
        return special[next() % 7];
    }
    case 1:
    case 2: {
        const float b = (float)(int)(next() % (unsigned)(q + 2));
        const int step = (int)(next() % 3) - 1;
        return step < 0 ? nextafterf(b, -INFINITY) : step > 0 ? nextafterf(b, INFINITY) : b;
    }
    default:
        return uniform(-2.0f, (float)q + 3.0f);
    }
}

/* A coordinate: near texel edges of some level, in [-3, 3], large or
 * special. */
static float any_coord(int n)
{
    switch (next() % 10) {
    case 0: {
        const float special[] = {NAN, -INFINITY, INFINITY, 0.0f, -0.0f, 1.0f, -1.0f, 1e-30f,
                                 -1e-30f, 2.0f, 1e7f, -1e9f};
        return special[next() % 12];
    }
    case 1:
    case 2: {
        const float e = (float)(int)(next() % (unsigned)(2 * n + 1)) / (float)n;
        return (next() & 1) ? nextafterf(e, -INFINITY) : e;
    }
    default:
        return uniform(-3.0f, 3.0f);
    }
}

/* A coordinate of the kind most of a frame's blocks have: in [0, 1],
 * texel edges of any level and their neighbours, tiny ones, values of
 * [-3, -1], and now and then one in (-1, 0).  With every lane on one
 * level (half of main()'s blocks), these take texture.c's one-level branch
 * of bilinear8_offsets (the level's fields broadcast, not gathered),
 * which any_coord's blocks with a level a lane seldom reach. */
static float frame_coord(int n)
{
    switch (next() % 16) {
    case 0:
        return uniform(-0.999f, -0.001f);
    case 1:
    case 2:
        return ldexpf(1.0f, -(int)(next() % 40)) * ((next() & 1) ? 1.0f : 3.0f);
    case 3:
    case 4:
    case 5: {
        const float e = (float)(int)(next() % (unsigned)(2 * n + 1)) / (float)n;
        const int step = (int)(next() % 3) - 1;
        return step < 0 ? nextafterf(e, -INFINITY) : step > 0 ? nextafterf(e, INFINITY) : e;
    }
    case 6:
        return uniform(-3.0f, -1.0f);
    default:
        return uniform(0.0f, 1.0f);
    }
}

/* The log2 tests' inputs: every 13th float of [1, 2^32] (the grid),
 * then a million random doubles of [1, 2^32) (2^e times a random
 * mantissa). */
struct log2_inputs {
    uint32_t bits;   /* the grid's next float */
    long randoms;    /* random doubles given so far */
};

#define LOG2_GRID_FIRST 0x3f800000u /* 1.0f */
#define LOG2_GRID_END 0x4f800000u   /* 2^32 */
#define LOG2_RANDOMS 1000000L

/* The next n inputs into xs, 1.0 (an input like any other) after the
 * last; returns 0 once every input has been given. */
static int log2_inputs_next(struct log2_inputs *in, double *xs, int n)
{
    int k = 0;
    for (; k < n; k++) {
        if (in->bits <= LOG2_GRID_END) {
            float f;
            memcpy(&f, &in->bits, sizeof(f));
            xs[k] = (double)f;
            in->bits += 13;
        } else if (in->randoms < LOG2_RANDOMS) {
            const uint64_t m = ((uint64_t)next() << 32 | next()) & 0x000fffffffffffffull;
            const uint64_t e = 1023u + next() % 32u;
            const uint64_t b = e << 52 | m;
            memcpy(&xs[k], &b, sizeof(double));
            in->randoms++;
        } else
            break;
    }
    const int given = k;
    for (; k < n; k++)
        xs[k] = 1.0;
    return given > 0;
}

/* The largest |lanes_log2_4(x) - log2l(x)| over the log2 inputs; the
 * failures counted against 2^-48. */
static int log2_bound(shade_log2_quad_fn log2_quad)
{
    int failures = 0;
    long double worst = 0.0L;
    double xs[4], got[4], half[4];
    struct log2_inputs in = {LOG2_GRID_FIRST, 0};
    while (log2_inputs_next(&in, xs, 4)) {
        log2_quad(xs, got, half);
        for (int k = 0; k < 4; k++) {
            /* The halved form (lod_fast's squared footprints) bit for bit
             * the half of the log2. */
            const double want = got[k] * 0.5;
            if (memcmp(&half[k], &want, sizeof(double)) != 0)
                failures += !CHECKF(0, "log2(%a) / 2: %a, not %a", xs[k], half[k], want);
            const long double err = fabsl((long double)got[k] - log2l((long double)xs[k]));
            if (err > worst)
                worst = err;
            if (!(err <= 0x1p-48L))
                failures += !CHECKF(0, "log2(%a): %a, off by %Lg", xs[k], got[k], err);
        }
    }
    printf("shade_lanes: log2's largest error %Lg (2^%.2f)\n", worst,
           worst > 0.0L ? (double)log2l(worst) : -INFINITY);
    return failures;
}

/* The AVX-512 copy's halved log2 (lanes_log2_8_half, which the frame's
 * AVX-512 shading runs) within 2^-49 of log2l / 2, half the four-lane
 * form's bound, over the log2 inputs (a million random doubles of its
 * own), and bit for bit the four-lane half (the same operations). */
static int log2_bound8(shade_log2_oct_half_fn log2_oct_half, shade_log2_quad_fn log2_quad)
{
    int failures = 0;
    long double worst = 0.0L;
    double xs[8], half[8];
    struct log2_inputs in = {LOG2_GRID_FIRST, 0};
    while (log2_inputs_next(&in, xs, 8)) {
        log2_oct_half(xs, half);
        for (int h = 0; h < 8; h += 4) {
            double full4[4], half4[4];
            log2_quad(xs + h, full4, half4);
            if (memcmp(half4, half + h, sizeof(half4)) != 0)
                failures += !CHECKF(0, "log2 / 2 of %a..%a: eight lanes differ from four",
                                    xs[h], xs[h + 3]);
        }
        for (int k = 0; k < 8; k++) {
            const long double err = fabsl((long double)half[k] - 0.5L * log2l((long double)xs[k]));
            if (err > worst)
                worst = err;
            if (!(err <= 0x1p-49L))
                failures += !CHECKF(0, "log2(%a) / 2, eight lanes: %a, off by %Lg", xs[k], half[k],
                                    err);
        }
    }
    printf("shade_lanes: the eight-lane half log2's largest error %Lg (2^%.2f)\n", worst,
           worst > 0.0L ? (double)log2l(worst) : -INFINITY);
    return failures;
}

/* A random direction component of [-1, 1]. */
static double any_unit(void)
{
    return (double)uniform(-1.0f, 1.0f);
}

/* lod_fast_quad's decided lanes against lod_ray over random triangles,
 * directions and widths. */
static int lod_fast_bound(shade_lod_fast_fn lod_fast, shade_lod_quad_fn lod_quad)
{
    int failures = 0;
    long lanes = 0, decided = 0;
    for (int tri = 0; tri < 20000 && failures <= 20; tri++) {
        /* World edges: a random pair, a long thin one, a sliver (w2
         * nearly along w1), scaled by 2^-8 .. 2^8. */
        double w1[3], w2[3];
        const double scale = ldexp(1.0, (int)(next() % 17u) - 8);
        for (int k = 0; k < 3; k++) {
            w1[k] = any_unit() * scale;
            w2[k] = any_unit() * scale;
        }
        if (tri % 5 == 1)
            for (int k = 0; k < 3; k++)
                w2[k] *= 1e-3;
        if (tri % 5 == 2)
            for (int k = 0; k < 3; k++)
                w2[k] = w1[k] * 0.7 + w2[k] * 1e-3;
        /* Texture coordinates, one axis stretched up to 1000 times. */
        const float stretch = (tri % 3 == 0) ? uniform(1.0f, 1000.0f) : 1.0f;
        float st[3][2];
        for (int v = 0; v < 3; v++) {
            st[v][0] = uniform(-2.0f, 2.0f) * stretch;
            st[v][1] = uniform(-2.0f, 2.0f);
        }
        const int tw = 1 << (next() % 11u), th = 1 << (next() % 11u);
        const int level_count = scene_texture_level_count(tw, th);
        /* lod_triangle's operations. */
        struct surface_lod l;
        memcpy(l.w1, w1, sizeof(w1));
        memcpy(l.w2, w2, sizeof(w2));
        l.nn[0] = w1[1] * w2[2] - w1[2] * w2[1];
        l.nn[1] = w1[2] * w2[0] - w1[0] * w2[2];
        l.nn[2] = w1[0] * w2[1] - w1[1] * w2[0];
        l.nn2 = l.nn[0] * l.nn[0] + l.nn[1] * l.nn[1] + l.nn[2] * l.nn[2];
        l.p_a = sqrt(l.nn2);
        for (int k = 0; k < 3; k++)
            l.n[k] = l.nn[k] / l.p_a;
        l.a1[0] = ((double)st[1][0] - (double)st[0][0]) * tw;
        l.a1[1] = ((double)st[1][1] - (double)st[0][1]) * th;
        l.a2[0] = ((double)st[2][0] - (double)st[0][0]) * tw;
        l.a2[1] = ((double)st[2][1] - (double)st[0][1]) * th;
        l.t_a = fabs(l.a1[0] * l.a2[1] - l.a2[0] * l.a1[1]);
        /* One triangle in seven with a conformal texture map (a rotation
         * and scale of the plane's own coordinates) and its first two
         * lanes along the normal: the footprint's two axes then tie
         * within LOD_AXIS_MARGIN, which lod_quad leaves to lod_quad_axes
         * (a fault there passed every test, round 58). */
        const int conformal = tri % 7 == 3 && tri % 5 != 2;
        if (conformal) {
            const double len1 = sqrt(w1[0] * w1[0] + w1[1] * w1[1] + w1[2] * w1[2]);
            const double u[3] = {w1[0] / len1, w1[1] / len1, w1[2] / len1};
            const double v[3] = {l.n[1] * u[2] - l.n[2] * u[1], l.n[2] * u[0] - l.n[0] * u[2],
                                 l.n[0] * u[1] - l.n[1] * u[0]};
            const double texels = ldexp(1.0, (int)(next() % 13u)) / scale;
            const double angle = uniform(0.0f, 6.2831853f);
            const double c = texels * cos(angle), sn = texels * sin(angle);
            const double *const e[2] = {w1, w2};
            double *const a[2] = {l.a1, l.a2};
            for (int m = 0; m < 2; m++) {
                const double x = e[m][0] * u[0] + e[m][1] * u[1] + e[m][2] * u[2];
                const double y = e[m][0] * v[0] + e[m][1] * v[1] + e[m][2] * v[2];
                a[m][0] = c * x - sn * y;
                a[m][1] = sn * x + c * y;
            }
            l.t_a = fabs(l.a1[0] * l.a2[1] - l.a2[0] * l.a1[1]);
        }
        float ng[4][3], dir[4][3], width[4], fast[4], ref[4];
        for (int i = 0; i < 4; i++) {
            /* Unit float directions: random, within a few degrees of the
             * normal, or grazing. */
            double d[3];
            const int kind = conformal && i < 2 ? 4 : (int)(next() % 4u);
            for (int k = 0; k < 3; k++)
                d[k] = any_unit();
            const double along = l.n[0] * d[0] + l.n[1] * d[1] + l.n[2] * d[2];
            for (int k = 0; k < 3; k++) {
                if (kind == 1)
                    d[k] = l.n[k] + 0.05 * d[k];
                if (kind == 2)
                    d[k] -= 0.999 * l.n[k] * along;
                if (kind == 4)
                    d[k] = l.n[k];
            }
            const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            const double side = l.n[0] * d[0] + l.n[1] * d[1] + l.n[2] * d[2] < 0.0 ? 1.0 : -1.0;
            for (int k = 0; k < 3; k++) {
                dir[i][k] = (float)(d[k] / len);
                ng[i][k] = (float)(side * l.n[k]);
            }
            width[i] = 1.0f;
        }
        /* Widths putting lambda anywhere in [-3, q + 3], or on a level
         * boundary, or 2^-k of a level from it. */
        lod_fast(&l, level_count, dir, ng, width, fast, ref);
        for (int i = 0; i < 4; i++) {
            if (!isfinite(ref[i]))
                continue;
            float target = uniform(-3.0f, (float)level_count + 3.0f);
            if (next() % 2u) {
                target = (float)(int)(next() % (unsigned)(level_count + 2));
                if (next() % 2u)
                    target += ldexpf((next() & 1) ? 1.0f : -1.0f, -(int)(next() % 30u));
            }
            width[i] = (float)exp2((double)target - (double)ref[i]);
        }
        const int mask = lod_fast(&l, level_count, dir, ng, width, fast, ref);
        /* The blocks' chain (lod_quad_lanes), with the part shared as a
         * one-triangle block gives it and not as a mixed block's: every
         * lane lod_ray's lambda bit for bit (NaN for NaN), the lanes
         * left near 1, the last level and a tie of the axes included. */
        for (int shared = 0; lod_quad && shared < 2; shared++) {
            float quad[4];
            lod_quad(&l, shared, level_count, dir, ng, width, quad);
            for (int i = 0; i < 4; i++)
                failures += !CHECKF(memcmp(&quad[i], &ref[i], sizeof(float)) == 0 ||
                                        (isnan(quad[i]) && isnan(ref[i])),
                                    "triangle %d lane %d (shared %d): lod_quad_lanes %a, "
                                    "lod_ray %a",
                                    tri, i, shared, (double)quad[i], (double)ref[i]);
        }
        /* The bound's kappa (surface.c, before LOD_FAST_RELATIVE): 2 K /
         * |M|, K = (|w2| |a1| + |w1| |a2|) / |nn|, M = (a1 (w2 x nn)^T +
         * a2 (nn x w1)^T) / nn2, at least 1. */
        double m2 = 0.0;
        for (int r = 0; r < 2; r++) {
            const double a1r = l.a1[r], a2r = l.a2[r];
            double row[3];
            row[0] = (a1r * (w2[1] * l.nn[2] - w2[2] * l.nn[1]) +
                      a2r * (l.nn[1] * w1[2] - l.nn[2] * w1[1])) / l.nn2;
            row[1] = (a1r * (w2[2] * l.nn[0] - w2[0] * l.nn[2]) +
                      a2r * (l.nn[2] * w1[0] - l.nn[0] * w1[2])) / l.nn2;
            row[2] = (a1r * (w2[0] * l.nn[1] - w2[1] * l.nn[0]) +
                      a2r * (l.nn[0] * w1[1] - l.nn[1] * w1[0])) / l.nn2;
            m2 += row[0] * row[0] + row[1] * row[1] + row[2] * row[2];
        }
        const double k_sum =
            sqrt((w2[0] * w2[0] + w2[1] * w2[1] + w2[2] * w2[2]) *
                 (l.a1[0] * l.a1[0] + l.a1[1] * l.a1[1])) +
            sqrt((w1[0] * w1[0] + w1[1] * w1[1] + w1[2] * w1[2]) *
                 (l.a2[0] * l.a2[0] + l.a2[1] * l.a2[1]));
        const double kappa = fmax(2.0 * k_sum / sqrt(l.nn2 * m2), 1.0);
        for (int i = 0; i < 4; i++) {
            lanes++;
            if (!(mask >> i & 1))
                continue;
            decided++;
            failures += !CHECKF(memcmp(&fast[i], &ref[i], sizeof(float)) == 0,
                                "triangle %d lane %d: lod_fast %a, lod_ray %a", tri, i,
                                (double)fast[i], (double)ref[i]);
            /* A decided lane must be within the proof's bound, kappa /
             * (sin cos) <= 64 (0.1 % over for this check's own
             * roundings), whether or not its answer happens to be
             * right: a fault that dropped that condition gave right
             * answers in every lane here and passed (round 58). */
            const double d[3] = {dir[i][0], dir[i][1], dir[i][2]};
            const double c[3] = {l.n[1] * d[2] - l.n[2] * d[1], l.n[2] * d[0] - l.n[0] * d[2],
                                 l.n[0] * d[1] - l.n[1] * d[0]};
            const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            const double sin_cos =
                sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) *
                fabs(ng[i][0] * d[0] + ng[i][1] * d[1] + ng[i][2] * d[2]) / dd;
            failures += !CHECKF(kappa <= 64.0 * 1.001 * sin_cos,
                                "triangle %d lane %d: decided with kappa / (sin cos) = %g", tri,
                                i, kappa / sin_cos);
        }
    }
    printf("shade_lanes: lod_fast decided %ld of %ld lanes\n", decided, lanes);
    failures += !CHECKF(2 * decided >= lanes, "lod_fast decided %ld of %ld lanes", decided, lanes);
    return failures;
}

int main(void)
{
    const shade_log2_quad_fn log2_quad = shade_log2_quad_avx2_unit();
    const shade_lod_fast_fn lod_fast = shade_lod_fast_avx2_unit();
    const shade_texture_lod8_fn lod8 = shade_texture_lod8_avx2_unit();
    const shade_texture_lod8_fn steps = shade_texture_lod8_steps_avx2_unit();
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    const int cpu = __builtin_cpu_supports("avx2");
#else
    const int cpu = 0;
#endif
    if (!lod8 || !steps || !log2_quad || !lod_fast || !cpu) {
        printf("shade_lanes: skipped (no AVX2 unit or CPU)\n");
        return 0;
    }
    int failures = log2_bound(log2_quad);
    failures += lod_fast_bound(lod_fast, shade_lod_quad_avx2_unit());
    /* The AVX-512 copy's eight-lane form (lod_fast_oct, the four hits in
     * both halves) where the unit and the CPU have it. */
    const shade_lod_fast_fn lod_fast8 = shade_lod_fast_avx512_unit();
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    const int cpu512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                       __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
#else
    const int cpu512 = 0;
#endif
    if (lod_fast8 && cpu512)
        failures += lod_fast_bound(lod_fast8, NULL);
    else
        printf("shade_lanes: lod_fast_oct skipped (no AVX-512 unit or CPU)\n");
    struct scene_textures tab;
    scene_textures_init(&tab);
    struct scene_texture *tex = scene_textures_get_or_create(&tab, 1);
    const int sizes[][2] = {{1, 1}, {1, 7}, {5, 3}, {4, 4}, {64, 16}, {37, 129}, {128, 128},
                            {300, 5}};
    int lanes = 0, refused = 0;
    for (size_t z = 0; z < sizeof(sizes) / sizeof(sizes[0]); z++) {
        if (!tex || !set_random_image(tex, sizes[z][0], sizes[z][1])) {
            fprintf(stderr, "no memory for a texture\n");
            return 1;
        }
        const int q = tex->level_count - 1;
        const int n = sizes[z][0] > sizes[z][1] ? sizes[z][0] : sizes[z][1];
        for (int block = 0; block < 20000; block++) {
            tex->min_filter = SCENE_FILTER_LINEAR_MIPMAP_LINEAR;
            tex->mag_filter = SCENE_FILTER_LINEAR;
            if (block % 97 == 0)
                tex->min_filter = SCENE_FILTER_NEAREST_MIPMAP_LINEAR; /* refused */
            tex->wrap_s = (next() & 1) ? SCENE_WRAP_CLAMP_TO_EDGE : SCENE_WRAP_REPEAT;
            tex->wrap_t = (next() & 1) ? SCENE_WRAP_CLAMP_TO_EDGE : SCENE_WRAP_REPEAT;
            float lambda[8], s[8], t[8], rgb[3][8], want[8][4];
            for (int i = 0; i < 8; i++) {
                lambda[i] = any_lambda(q);
                s[i] = any_coord(n);
                t[i] = any_coord(n);
            }
            if (block & 1) {
                /* Half the blocks as a frame's: every lane on one level
                 * (or one level pair) and frame_coord's coordinates. */
                const int level = (int)(next() % (unsigned)(q + 2)) - 1;
                for (int i = 0; i < 8; i++) {
                    lambda[i] = level < 0 ? -uniform(0.0f, 2.0f)
                                          : (float)level + uniform(0.0f, 0.999f);
                    s[i] = frame_coord(n);
                    t[i] = frame_coord(n);
                }
            }
            memset(rgb, 0x7f, sizeof(rgb));
            const int took = lod8(tex, lambda, s, t, rgb);
            float rgb_steps[3][8];
            memset(rgb_steps, 0x7f, sizeof(rgb_steps));
            const int took_steps = steps(tex, lambda, s, t, rgb_steps);
            failures += !CHECKF(took_steps == took &&
                                    (!took || memcmp(rgb_steps, rgb, sizeof(rgb)) == 0),
                                "size %dx%d block %d: the two steps took %d against %d or "
                                "differ",
                                sizes[z][0], sizes[z][1], block, took_steps, took);
            int big = 0;
            for (int i = 0; i < 8; i++)
                big |= (isfinite(s[i]) && fabsf(s[i]) >= 0x1p31f) ||
                       (isfinite(t[i]) && fabsf(t[i]) >= 0x1p31f);
            const int should = !big && tex->min_filter == SCENE_FILTER_LINEAR_MIPMAP_LINEAR;
            failures += !CHECKF(took == should, "size %dx%d block %d: took %d, expected %d",
                                sizes[z][0], sizes[z][1], block, took, should);
            if (!took) {
                refused++;
                continue;
            }
            for (int i = 0; i < 8; i++) {
                scene_texture_sample_lod(tex, lambda[i], s[i], t[i], want[i]);
                int same = 1;
                for (int k = 0; k < 3; k++)
                    same &= memcmp(&rgb[k][i], &want[i][k], sizeof(float)) == 0;
                lanes++;
                failures += !CHECKF(same,
                                    "size %dx%d lane %d: lambda %a s %a t %a wrap %d %d: "
                                    "(%a %a %a) against (%a %a %a)",
                                    sizes[z][0], sizes[z][1], i, (double)lambda[i], (double)s[i],
                                    (double)t[i], (int)tex->wrap_s, (int)tex->wrap_t,
                                    (double)rgb[0][i], (double)rgb[1][i], (double)rgb[2][i],
                                    (double)want[i][0], (double)want[i][1], (double)want[i][2]);
                if (failures > 20)
                    break;
            }
            if (failures > 20)
                break;
        }
    }
    scene_textures_release(&tab);
    printf("shade_lanes: %d lanes compared, %d blocks refused\n", lanes, refused);
    /* The AVX-512 copy's log2, last: its random doubles leave the other
     * checks' as they were. */
    const shade_log2_oct_half_fn log2_oct_half = shade_log2_oct_half_avx512_unit();
    if (log2_oct_half && cpu512)
        failures += log2_bound8(log2_oct_half, log2_quad);
    else
        printf("shade_lanes: the eight-lane log2 skipped (no AVX-512 unit or CPU)\n");
    printf("shade_lanes: %s (%d failed checks)\n", failures ? "FAILED" : "passed", failures);
    return failures != 0;
}
