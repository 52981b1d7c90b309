/* SPDX-License-Identifier: Apache-2.0 */
/*
 * aff_anim.c - the AFF keyframe maths (lib/rtu/aff_anim.c) against hand-
 * computed values and against the test vectors of FORMAT.md sec. 9.
 *
 * FORMAT.md is the BART format description, ../shared/bart/FORMAT.md next
 * to the checkout.  The test is compiled together with lib/rtu/aff_anim.c
 * alone (the module depends on nothing else).
 *
 *  1. Translation splines (sec. 7.2, 7.3): Catmull-Rom values for TCB 0,
 *     a hand-evaluated TCB case, unequal key spacing (the adj factors),
 *     clamping, the "first segment in file order" rule for non-monotonic
 *     times, duplicate times, and times that would make adj divide by zero.
 *  2. Rotation (sec. 7.4): keys about one axis (exact angles at keys and a
 *     linear angle in between), the sign rewrite of the key array with a
 *     hand-derived squad value that depends on q3 being the un-rewritten key,
 *     non-unit axes, conj used as the inverse, the 0.001 thresholds of log
 *     and slerp, and the clamp of sec. 7.6.1 on grip_rot2-like keys.
 *  3. Visibility, frame times, node matrices and the camera with NULL
 *     tracks; a fuzzer over arbitrary keys (finite results for ordinary
 *     inputs, and no undefined behaviour under the sanitizers for absurd
 *     ones).
 *  4. The camera and node-matrix tables of sec. 9, every row, from the `k`
 *     blocks of the BART files, read by a small reader below; plus every
 *     animated node of the three scenes at every frame (finite, rotations
 *     orthonormal; where the raw squad w exceeds 1, sec. 7.6.1).
 *  5. Animated triangles (sec. 7.5): the example of sec. 7.5 from
 *     museum/animart5.aff and hand-written keys.
 *
 * The BART folder comes from the environment variable TRACELIST_BART_DIR,
 * else from RT_BART_DIR given by the build (conformance/CMakeLists.txt).
 * Missing data is a failure, never a skip.
 */
#include "rtu/aff_anim.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

static int failures;


#define EXPECT_NEAR(got, want, tol, what)                                                  \
    (failures += !CHECKF(fabs((double)(got) - (double)(want)) <= (tol),                  \
                            "%s: got %.17g, want %.17g", what, (double)(got), (double)(want)))

static const double pi = 3.14159265358979323846;

/* ------------------------------------------------------------ helpers */

static struct aff_key *alloc_keys(int n)
{
    struct aff_key *k = calloc((size_t)n, sizeof(*k));
    if (!k) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    return k;
}

static void set_key(struct aff_key *k, double time, double x, double y, double z, double w,
                    double tension, double continuity, double bias)
{
    k->time = time;
    k->v[0] = x;
    k->v[1] = y;
    k->v[2] = z;
    k->v[3] = w;
    k->tension = tension;
    k->continuity = continuity;
    k->bias = bias;
}

static void init_track(struct aff_track *track, int kind, struct aff_key *keys, int n)
{
    int rc = aff_track_init(track, kind, keys, n);
    failures += !CHECKF(rc == 0, "aff_track_init(kind=%d, n=%d) = %d", kind, n, rc);
    if (rc) {
        fprintf(stderr, "cannot continue without the track\n");
        exit(1);
    }
}

/* A 1-component transl track (x = values[i], y = z = 0) with TCB 0. */
static void scalar_track(struct aff_track *track, const double *times, const double *values,
                         int n)
{
    struct aff_key *k = alloc_keys(n);
    for (int i = 0; i < n; i++)
        set_key(&k[i], times[i], values[i], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    init_track(track, AFF_TRACK_TRANSL, k, n);
}

static double eval_x(const struct aff_track *track, double t)
{
    double out[3];
    aff_track_eval(track, t, out);
    return out[0];
}

/* Rotation by angle (radians) about a unit axis, row-major:
 * R = cos I + sin [n]x + (1 - cos) n n^T (FORMAT.md sec. 4). */
static void axis_angle_matrix(const double n[3], double angle, double r[9])
{
    double c = cos(angle);
    double s = sin(angle);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r[i * 3 + j] = (i == j ? c : 0.0) + (1.0 - c) * n[i] * n[j];
    r[1] -= s * n[2];
    r[2] += s * n[1];
    r[3] += s * n[2];
    r[5] -= s * n[0];
    r[6] -= s * n[1];
    r[7] += s * n[0];
}

static double max_diff9(const double *a, const double *b)
{
    double d = 0.0;
    for (int i = 0; i < 9; i++) {
        double e = fabs(a[i] - b[i]);
        if (!(e <= d))
            d = e; /* NaN propagates */
    }
    return d;
}

static void rot_z(double degrees, double r[9])
{
    const double z[3] = {0.0, 0.0, 1.0};
    axis_angle_matrix(z, degrees * pi / 180.0, r);
}

/* Largest |R R^T - I| entry and |det R - 1|; NaN if R is not finite. */
static double orthonormal_error(const double r[9])
{
    double e = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double d = 0.0;
            for (int k = 0; k < 3; k++)
                d += r[i * 3 + k] * r[j * 3 + k];
            d = fabs(d - (i == j ? 1.0 : 0.0));
            if (!(d <= e))
                e = d;
        }
    double det = r[0] * (r[4] * r[8] - r[5] * r[7]) - r[1] * (r[3] * r[8] - r[5] * r[6]) +
                 r[2] * (r[3] * r[7] - r[4] * r[6]);
    double d = fabs(det - 1.0);
    return d <= e ? e : d;
}

static int all_finite(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

/* ------------------------------------------------ 1. translation splines */

static void test_catmull_rom(void)
{
    /*
     * TCB 0 and unit key spacing: adj0 = adj1 = 1, out0 = out1 = in0 =
     * in1 = 1/2, so Tout = (P2 - P0)/2 and Tin = (P3 - P1)/2: Catmull-Rom.
     * At u = 1/2 the Hermite form gives P = (-P0 + 9 P1 + 9 P2 - P3) / 16.
     *   x = t^2 (keys 0 1 4 9 16): Catmull-Rom reproduces quadratics, so
     *       x(1.5) = (-0 + 9 + 36 - 9)/16 = 2.25 and x(2.5) = (-1 + 36 + 81
     *       - 16)/16 = 6.25;
     *   y = 0 1 0 -1 0:  y(1.5) = (0 + 9 + 0 + 1)/16 = 0.625,
     *                    y(2.5) = (-1 + 0 - 9 - 0)/16 = -0.625;
     *   z = 7 everywhere.
     * At u = 1/4 (t = 1.25), Hermite basis h00 = 27/32, h10 = 9/64,
     * h01 = 5/32, h11 = -3/64: x = 27/32 + 4*5/32 + (9/64)(4/2) -
     * (3/64)(8/2) = 27/32 + 20/32 + 18/64 - 12/64 = 1.5625 = 1.25^2.
     */
    struct aff_key *k = alloc_keys(5);
    const double ys[5] = {0.0, 1.0, 0.0, -1.0, 0.0};
    for (int i = 0; i < 5; i++)
        set_key(&k[i], i, (double)(i * i), ys[i], 7.0, 0.0, 0.0, 0.0, 0.0);
    struct aff_track tr;
    init_track(&tr, AFF_TRACK_TRANSL, k, 5);
    double out[3];
    for (int i = 1; i <= 3; i++) {
        aff_track_eval(&tr, i, out);
        EXPECT_NEAR(out[0], i * i, 1e-12, "catmull-rom x at key");
        EXPECT_NEAR(out[1], ys[i], 1e-12, "catmull-rom y at key");
        EXPECT_NEAR(out[2], 7.0, 1e-12, "catmull-rom z at key");
    }
    /* Interior keys are hit exactly (u = 0 of the next segment). */
    aff_track_eval(&tr, 2.0, out);
    failures += !CHECKF(out[0] == 4.0 && out[1] == 0.0 && out[2] == 7.0, "key 2 exactly: %g %g %g", out[0],
          out[1], out[2]);
    aff_track_eval(&tr, 1.5, out);
    EXPECT_NEAR(out[0], 2.25, 1e-12, "catmull-rom x(1.5)");
    EXPECT_NEAR(out[1], 0.625, 1e-12, "catmull-rom y(1.5)");
    EXPECT_NEAR(out[2], 7.0, 1e-12, "catmull-rom z(1.5)");
    aff_track_eval(&tr, 2.5, out);
    EXPECT_NEAR(out[0], 6.25, 1e-12, "catmull-rom x(2.5)");
    EXPECT_NEAR(out[1], -0.625, 1e-12, "catmull-rom y(2.5)");
    aff_track_eval(&tr, 1.25, out);
    EXPECT_NEAR(out[0], 1.5625, 1e-12, "catmull-rom x(1.25)");
    aff_track_release(&tr);
    failures += !CHECKF(tr.keys == NULL && tr.segments == NULL && tr.key_count == 0, "release zeroes");
}

static void test_tcb(void)
{
    /*
     * Keys t = 0 1 2 3, x = 0 1 3 6; key 1 (T, C, B) = (0.5, -0.5, 0),
     * key 2 (T, C, B) = (0, 0.5, -0.5).  adj0 = 2(2-1)/(2-0) = 1,
     * adj1 = 2(2-1)/(3-1) = 1.
     *   out0 = 1/2 (1-0.5)(1-0.5)(1+0) = 0.125
     *   out1 = 1/2 (1-0.5)(1+0.5)(1-0) = 0.375
     *   in0  = 1/2 (1-0)(1-0.5)(1-0.5) = 0.125
     *   in1  = 1/2 (1-0)(1+0.5)(1+0.5) = 1.125
     *   D = 2, Tout = 0.125*1 + 0.375*2 = 0.875, Tin = 0.125*2 + 1.125*3
     *   = 3.625.
     *   P(1/2) = 1 + 0.875/2 + (6 - 1.75 - 3.625)/4 + (-4 + 0.875 + 3.625)/8
     *          = 1 + 0.4375 + 0.15625 + 0.0625 = 1.65625.
     * (Swapping in0 and in1 would give Tin = 2.625 and 1.78125.)
     */
    struct aff_key *k = alloc_keys(4);
    set_key(&k[0], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    set_key(&k[1], 1.0, 1.0, 0.0, 0.0, 0.0, 0.5, -0.5, 0.0);
    set_key(&k[2], 2.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.5, -0.5);
    set_key(&k[3], 3.0, 6.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    struct aff_track tr;
    init_track(&tr, AFF_TRACK_TRANSL, k, 4);
    EXPECT_NEAR(eval_x(&tr, 1.5), 1.65625, 1e-12, "TCB P(1/2)");
    EXPECT_NEAR(eval_x(&tr, 1.0), 1.0, 0.0, "TCB at key 1");
    EXPECT_NEAR(eval_x(&tr, 2.0), 3.0, 1e-12, "TCB at key 2 (clamped, u = 1)");
    /* Transl keys are not modified by setup. */
    failures += !CHECKF(tr.keys[1].v[0] == 1.0 && tr.keys[1].tension == 0.5 && tr.keys[2].bias == -0.5,
          "transl keys untouched");
    aff_track_release(&tr);

    /* Bias 1 at key 1 makes the outgoing tangent follow P1 - P0 only:
     * out0 = 1/2 (1)(1)(2) = 1, out1 = 0; with x = 0 1 3 6, Tout = 1,
     * Tin = 1/2 (2 + 3) = 2.5, P(1/2) = 1 + 0.5 + (6 - 2 - 2.5)/4 +
     * (-4 + 1 + 2.5)/8 = 1.5 + 0.375 - 0.0625 = 1.8125. */
    k = alloc_keys(4);
    set_key(&k[0], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    set_key(&k[1], 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0);
    set_key(&k[2], 2.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    set_key(&k[3], 3.0, 6.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    init_track(&tr, AFF_TRACK_TRANSL, k, 4);
    EXPECT_NEAR(eval_x(&tr, 1.5), 1.8125, 1e-12, "bias 1 P(1/2)");
    aff_track_release(&tr);
}

static void test_unequal_spacing(void)
{
    /*
     * Keys t = 0 1 3 7, x = 0 1 3 6, TCB 0.  adj0 = 2(3-1)/(3-0) = 4/3,
     * adj1 = 2(3-1)/(7-1) = 2/3, so out0 = out1 = 2/3, in0 = in1 = 1/3.
     * D = 2, Tout = 2/3 (1 + 2) = 2, Tin = 1/3 (2 + 3) = 5/3.
     * t = 2 is u = 1/2: P = 1 + 1 + (6 - 4 - 5/3)/4 + (-4 + 2 + 5/3)/8
     *                     = 2 + 1/12 - 1/24 = 49/24.
     * Without the adj factors (Catmull-Rom) it would be 2.0625.
     * t = 1.5 is u = 1/4, where the Hermite basis is h00 = 27/32,
     * h10 = 9/64, h01 = 5/32, h11 = -3/64:
     *   P = 27/32 * 1 + 9/64 * 2 + 5/32 * 3 - 3/64 * 5/3
     *     = 42/32 + 18/64 - 5/64 = 97/64.
     */
    const double times[4] = {0.0, 1.0, 3.0, 7.0};
    const double xs[4] = {0.0, 1.0, 3.0, 6.0};
    struct aff_track tr;
    scalar_track(&tr, times, xs, 4);
    EXPECT_NEAR(eval_x(&tr, 2.0), 49.0 / 24.0, 1e-12, "unequal spacing P(u=1/2)");
    EXPECT_NEAR(eval_x(&tr, 1.5), 97.0 / 64.0, 1e-12, "unequal spacing P(u=1/4)");
    aff_track_release(&tr);
}

static void test_clamping(void)
{
    /* FORMAT.md sec. 7.2: frozen outside [t_1, t_{n-2}]. */
    const double times[6] = {-1.0, 0.0, 1.0, 2.0, 3.0, 4.0};
    const double xs[6] = {5.0, 10.0, 20.0, 15.0, 30.0, 99.0};
    struct aff_track tr;
    scalar_track(&tr, times, xs, 6);
    const double before[] = {0.0, -0.5, -1.0, -1e30, -HUGE_VAL};
    for (size_t i = 0; i < sizeof(before) / sizeof(before[0]); i++)
        failures += !CHECKF(eval_x(&tr, before[i]) == 10.0, "clamp before t_1 at t=%g: %.17g", before[i],
              eval_x(&tr, before[i]));
    const double after[] = {3.0, 3.5, 4.0, 1e30, HUGE_VAL};
    for (size_t i = 0; i < sizeof(after) / sizeof(after[0]); i++)
        EXPECT_NEAR(eval_x(&tr, after[i]), 30.0, 1e-12, "clamp after t_{n-2}");
    /* A NaN time evaluates as t <= t_1 (no comparison holds). */
    failures += !CHECKF(eval_x(&tr, NAN) == 10.0, "NaN t gives key 1: %g", eval_x(&tr, NAN));
    aff_track_release(&tr);

    /* The kitchen toy car example of sec. 7.6.4 with hand keys: scale
     * x = 1 1 0.5 0.1 at t = -1 19.75 19.81 21: 0.5 from 19.81 on. */
    struct aff_key *k = alloc_keys(4);
    set_key(&k[0], -1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0);
    set_key(&k[1], 19.75, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0);
    set_key(&k[2], 19.81, 0.5, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0);
    set_key(&k[3], 21.0, 0.1, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0);
    init_track(&tr, AFF_TRACK_SCALE, k, 4);
    double s[3];
    aff_track_eval(&tr, 20.0, s);
    EXPECT_NEAR(s[0], 0.5, 1e-12, "scale clamped at 0.5");
    EXPECT_NEAR(s[1], 1.0, 1e-12, "scale y");
    aff_track_eval(&tr, 5.0, s);
    failures += !CHECKF(s[0] == 1.0, "scale before 19.75: %g", s[0]);
    aff_track_release(&tr);
}

static void test_non_monotonic(void)
{
    /*
     * Times 0 1 3 2 4 5: segments [1,3], [3,2], [2,4].  t = 2.5 lies in
     * both [1,3] and [2,4]; the rule "first segment in file order with
     * t < t_{j+2}" picks segment 0 (u = 0.75), which is what a track of
     * keys 0..3 alone gives.  t = 3.5 skips segments 0 and 1 and uses
     * segment 2 (u = 0.75), which is what a track of keys 2..5 gives.
     */
    const double times[6] = {0.0, 1.0, 3.0, 2.0, 4.0, 5.0};
    const double xs[6] = {0.0, 2.0, -1.0, 5.0, 3.0, 8.0};
    struct aff_track full, head, tail;
    scalar_track(&full, times, xs, 6);
    scalar_track(&head, times, xs, 4);
    scalar_track(&tail, times + 2, xs + 2, 4);
    failures += !CHECKF(eval_x(&full, 2.5) == eval_x(&head, 2.5), "t=2.5 in segment 0: %.17g vs %.17g",
          eval_x(&full, 2.5), eval_x(&head, 2.5));
    failures += !CHECKF(eval_x(&full, 2.5) != eval_x(&tail, 2.5), "t=2.5 not in segment 2");
    failures += !CHECKF(eval_x(&full, 3.5) == eval_x(&tail, 3.5), "t=3.5 in segment 2: %.17g vs %.17g",
          eval_x(&full, 3.5), eval_x(&tail, 3.5));
    /* Clamping still uses t_1 = 1 and t_{n-2} = 4. */
    failures += !CHECKF(eval_x(&full, 0.5) == 2.0, "clamp low");
    EXPECT_NEAR(eval_x(&full, 4.5), 3.0, 1e-12, "clamp high");
    aff_track_release(&full);
    aff_track_release(&head);
    aff_track_release(&tail);
}

static void test_duplicate_times(void)
{
    /* First and last key repeated (robots style): adj = 2 at the ends. */
    {
        const double times[5] = {0.0, 0.0, 1.0, 2.0, 2.0};
        const double xs[5] = {1.0, 1.0, 3.0, 2.0, 2.0};
        struct aff_track tr;
        scalar_track(&tr, times, xs, 5);
        /* Segment 0 (keys 0..3, t 0 0 1 2): adj0 = 2(1-0)/(1-0) = 2,
         * adj1 = 2(1)/(2-0) = 1; Tout = (0*1 + 2) = 2 (out0 = out1 = 1),
         * Tin = 1/2 (2 + -1) = 0.5, D = 2.
         * P(1/2) = 1 + 1 + (6 - 4 - 0.5)/4 + (-4 + 2 + 0.5)/8 = 2.1875. */
        EXPECT_NEAR(eval_x(&tr, 0.5), 2.1875, 1e-12, "duplicate first key, u=1/2");
        failures += !CHECKF(eval_x(&tr, 0.0) == 1.0, "at t_1");
        failures += !CHECKF(eval_x(&tr, 1.0) == 3.0, "at t_2");
        EXPECT_NEAR(eval_x(&tr, 2.0), 2.0, 1e-12, "at t_3");
        aff_track_release(&tr);
    }
    /* A zero-length interior segment (times 0 1 2 2 3 4): it is never
     * selected; at t = 2 the first segment ending after 2 is [2,3], so the
     * value is key 3's, while t -> 2 from below approaches key 2's. */
    {
        const double times[6] = {0.0, 1.0, 2.0, 2.0, 3.0, 4.0};
        const double xs[6] = {0.0, 1.0, 2.0, 5.0, 6.0, 7.0};
        struct aff_track tr;
        scalar_track(&tr, times, xs, 6);
        failures += !CHECKF(eval_x(&tr, 2.0) == 5.0, "jump: key 3 at t=2, got %.17g", eval_x(&tr, 2.0));
        EXPECT_NEAR(eval_x(&tr, nextafter(2.0, 0.0)), 2.0, 1e-9, "key 2 from below");
        for (int i = 0; i <= 500; i++) {
            double t = -1.0 + i * 0.012;
            failures += !CHECKF(isfinite(eval_x(&tr, t)), "finite at t=%g", t);
        }
        aff_track_release(&tr);
    }
    /* The same time three times in a row (t0 == t1 == t2) and times going
     * back and forth (t0 == t2 != t1): adj would divide by zero.  The module
     * uses adj = 0 there (a zero tangent); the result stays finite and
     * still interpolates the keys. */
    {
        const double times[7] = {0.0, 1.0, 1.0, 1.0, 2.0, 1.0, 3.0};
        const double xs[7] = {0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0};
        struct aff_track tr;
        scalar_track(&tr, times, xs, 7);
        for (int i = 0; i <= 400; i++) {
            double t = -1.0 + i * 0.0125;
            double x = eval_x(&tr, t);
            failures += !CHECKF(isfinite(x), "finite at t=%g: %g", t, x);
        }
        failures += !CHECKF(eval_x(&tr, 1.0) == 1.0, "clamped to key 1");
        aff_track_release(&tr);
    }
    {
        /* Segment 0: t0 = 5, t1 = 3, t2 = 5 -> adj0 = 2*2/0; keys 0 1 2 3
         * only: segment [3,5], adj0 := 0 so Tout = 0; adj1 = 2*2/(6-3).
         * in0 = in1 = 2/3, D = 2, Tin = 2/3 (2 + 3) = 10/3.
         * P(1/2) = 1 + 0 + (6 - 0 - 10/3)/4 + (-4 + 0 + 10/3)/8
         *        = 1 + 2/3 - 1/12 = 19/12. */
        const double times[4] = {5.0, 3.0, 5.0, 6.0};
        const double xs[4] = {0.0, 1.0, 3.0, 6.0};
        struct aff_track tr;
        scalar_track(&tr, times, xs, 4);
        EXPECT_NEAR(eval_x(&tr, 4.0), 19.0 / 12.0, 1e-12, "adj0 with zero denominator");
        aff_track_release(&tr);
    }
}

static void test_init_errors(void)
{
    struct aff_track tr;
    memset(&tr, 0xab, sizeof(tr));
    /* keys are freed on failure (LeakSanitizer would see it otherwise). */
    failures += !CHECKF(aff_track_init(&tr, AFF_TRACK_TRANSL, alloc_keys(3), 3) == -1, "3 keys rejected");
    failures += !CHECKF(tr.keys == NULL && tr.segments == NULL && tr.key_count == 0 && tr.kind == 0,
          "zeroed after failure");
    failures += !CHECKF(aff_track_init(&tr, AFF_TRACK_ROT, alloc_keys(2), 0) == -1, "0 keys rejected");
    failures += !CHECKF(aff_track_init(&tr, AFF_TRACK_ROT, NULL, 5) == -1, "NULL keys rejected");
    failures += !CHECKF(aff_track_init(&tr, 7, alloc_keys(4), 4) == -1, "bad kind rejected");
    failures += !CHECKF(aff_track_init(&tr, AFF_TRACK_SCALE, alloc_keys(1), -5) == -1, "negative count");
    aff_track_release(&tr);
    aff_track_release(NULL);
    /* A zeroed track evaluates as the identity of its kind. */
    double out[9];
    aff_track_eval(&tr, 1.0, out);
    failures += !CHECKF(out[0] == 0.0 && out[1] == 0.0 && out[2] == 0.0, "zeroed transl track");
    tr.kind = AFF_TRACK_SCALE;
    aff_track_eval(&tr, 1.0, out);
    failures += !CHECKF(out[0] == 1.0 && out[1] == 1.0 && out[2] == 1.0, "zeroed scale track");
    tr.kind = AFF_TRACK_ROT;
    aff_track_eval(&tr, 1.0, out);
    double id[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    failures += !CHECKF(max_diff9(out, id) == 0.0, "zeroed rot track");
}

/* ------------------------------------------------------------ 2. rotation */

static void rot_key(struct aff_key *k, double time, double ax, double ay, double az, double deg)
{
    set_key(k, time, ax, ay, az, deg, 0.0, 0.0, 0.0);
}

static void test_rotation_one_axis(void)
{
    /*
     * Keys about +z at t = 0..5 with angles 0 30 60 90 120 150, TCB 0.
     * With equal steps every log(conj(q_i) q_{i+1}) is the same D, so
     * Tout = Tin = D, A = q1, B = q2 and squad reduces to slerp(q1, q2, s):
     * the angle is linear in t.  At keys the matrix is the key rotation.
     */
    struct aff_key *k = alloc_keys(6);
    for (int i = 0; i < 6; i++)
        rot_key(&k[i], i, 0.0, 0.0, 1.0, 30.0 * i);
    struct aff_track tr;
    init_track(&tr, AFF_TRACK_ROT, k, 6);
    double r[9], want[9];
    for (int i = 1; i <= 4; i++) {
        aff_track_eval(&tr, i, r);
        rot_z(30.0 * i, want);
        failures += !CHECKF(max_diff9(r, want) <= 1e-12, "key %d: off by %g", i, max_diff9(r, want));
    }
    const double ts[] = {1.5, 2.25, 3.9};
    for (size_t i = 0; i < sizeof(ts) / sizeof(ts[0]); i++) {
        aff_track_eval(&tr, ts[i], r);
        rot_z(30.0 * ts[i], want);
        failures += !CHECKF(max_diff9(r, want) <= 1e-12, "t=%g: off by %g", ts[i], max_diff9(r, want));
    }
    /* Clamped: before t_1 the key-1 rotation, after t_4 the key-4 one. */
    aff_track_eval(&tr, -3.0, r);
    rot_z(30.0, want);
    failures += !CHECKF(max_diff9(r, want) <= 1e-12, "clamp low");
    aff_track_eval(&tr, 9.0, r);
    rot_z(120.0, want);
    failures += !CHECKF(max_diff9(r, want) <= 1e-12, "clamp high");
    /* No key was rewritten (all q_i . q_{i+1} > 0). */
    for (int i = 0; i < 6; i++)
        failures += !CHECKF(tr.keys[i].v[2] == 1.0 && tr.keys[i].v[3] == 30.0 * i, "key %d untouched", i);
    aff_track_release(&tr);

    /* Dense 90 degree steps (the wheels of sec. 7.4 "Multiple turns"):
     * the spline turns the short way through every step, so the angle keeps
     * increasing past 360 degrees. */
    k = alloc_keys(8);
    for (int i = 0; i < 8; i++)
        rot_key(&k[i], i, 0.0, 0.0, -1.0, 90.0 * i);
    init_track(&tr, AFF_TRACK_ROT, k, 8);
    for (int i = 10; i <= 60; i++) {
        double t = i * 0.1;
        aff_track_eval(&tr, t, r);
        rot_z(-90.0 * t, want);
        failures += !CHECKF(max_diff9(r, want) <= 1e-9, "wheel t=%g: off by %g", t, max_diff9(r, want));
    }
    aff_track_release(&tr);
}

static void test_rotation_rewrite(void)
{
    /*
     * Keys about +z at t = 0..4, angles 240 90 300 150 0 (degrees), TCB 0.
     * All quaternions lie in the (w, z) plane: q(a) = (cos a/2, sin a/2 z),
     * so work with half-angles h: 120 45 150 75 0.
     *
     * Setup, segment 0 (keys 0..3):
     *   q1.q2 = cos(150 - 45) = cos 105 < 0, so q2 := -q2 (half-angle
     *   150 - 180 = -30) and key 2 becomes angle 2 acos(cos 30) = 60 about
     *   (0, 0, -1).  For these in-plane quaternions,
     *   log(conj(qa) qb) = wrap(hb - ha) z, wrapped to [-180, 180]:
     *     D  = log(conj(q1) q2) = -30 - 45 = -75
     *     L0 = log(conj(q0) q1) =  45 - 120 = -75
     *     L2 = log(conj(q2) q3) =  75 - (-30) = 105   (q3 un-rewritten!)
     *   out0 = out1 = in0 = in1 = 1/2 (unit spacing):
     *     Tout = -75, Tin = (-75 + 105)/2 = 15
     *     A = q1 exp((Tout - D)/2) -> 45 + 0 = 45
     *     B = q2 exp((D - Tin)/2)  -> -30 + (-90)/2 = -75
     * Segment 1 (keys 1..4) starts from the rewritten key 2 (half -30) and
     * q3 = key 3 (half 75): cos(105) < 0, so key 3 becomes half-angle
     * 75 - 180 = -105, i.e. angle 210 about (0, 0, -1).
     *
     * Evaluation at t = 1.5 (segment 0, s = 1/2), slerp moving the
     * half-angle by h * wrap(difference) (no sign test):
     *   slerp(q1, q2, 1/2) = 45 + (-75)/2 = 7.5
     *   slerp(A, B, 1/2)   = 45 + (-120)/2 = -15
     *   slerp(7.5, -15, 2 s (1 - s) = 1/2) = 7.5 - 11.25 = -3.75
     * so R(1.5) is a rotation by -7.5 degrees about z.  Had q3 been taken
     * as the rewritten key (-105), L2 would be -75, the spline would be
     * linear in the half-angle and R(1.5) = Rz(15).
     */
    struct aff_key *k = alloc_keys(5);
    const double deg[5] = {240.0, 90.0, 300.0, 150.0, 0.0};
    for (int i = 0; i < 5; i++)
        rot_key(&k[i], i, 0.0, 0.0, 1.0, deg[i]);
    struct aff_track tr;
    init_track(&tr, AFF_TRACK_ROT, k, 5);
    failures += !CHECKF(tr.keys[0].v[2] == 1.0 && tr.keys[0].v[3] == 240.0, "key 0 untouched");
    failures += !CHECKF(tr.keys[1].v[2] == 1.0 && tr.keys[1].v[3] == 90.0, "key 1 untouched");
    EXPECT_NEAR(tr.keys[2].v[0], 0.0, 1e-15, "key 2 axis x");
    EXPECT_NEAR(tr.keys[2].v[1], 0.0, 1e-15, "key 2 axis y");
    EXPECT_NEAR(tr.keys[2].v[2], -1.0, 1e-15, "key 2 rewritten axis");
    EXPECT_NEAR(tr.keys[2].v[3], 60.0, 1e-12, "key 2 rewritten angle");
    EXPECT_NEAR(tr.keys[3].v[2], -1.0, 1e-15, "key 3 rewritten axis");
    EXPECT_NEAR(tr.keys[3].v[3], 210.0, 1e-12, "key 3 rewritten angle");
    failures += !CHECKF(tr.keys[4].v[2] == 1.0 && tr.keys[4].v[3] == 0.0, "key 4 untouched");
    double r[9], want[9];
    aff_track_eval(&tr, 1.5, r);
    rot_z(-7.5, want);
    failures += !CHECKF(max_diff9(r, want) <= 1e-12, "squad with un-rewritten q3: off by %g",
          max_diff9(r, want));
    /* At the keys: the key rotations (a rewritten key is the same rotation). */
    for (int i = 1; i <= 3; i++) {
        aff_track_eval(&tr, i, r);
        rot_z(deg[i], want);
        failures += !CHECKF(max_diff9(r, want) <= 1e-12, "key %d: off by %g", i, max_diff9(r, want));
    }
    aff_track_release(&tr);
}

static void test_rotation_non_unit_axis(void)
{
    /*
     * FORMAT.md sec. 7.4: the axis is not normalised, so the quaternions
     * are not unit; the axis-angle round trip keeps w and rescales the
     * vector part.  At a key, Q = q_key = (cos a/2, sin a/2 axis), so R is
     * the rotation by a about axis/|axis|.  In between, R must still be a
     * rotation.
     *
     * At the clamped end (t >= t_{n-2} = 4, u = 1) non-unit keys meet the
     * slerp rule of sec. 7.4 "if sin(theta) < 0.001 return p, even when
     * h = 1": slerp(q3, q4, 1) returns q3 when q3.q4 >= 1 (clamped to 1,
     * theta = 0).  With half-angles 50 and 85 degrees and |axis|^2 = L2,
     * q3.q4 = cos 50 cos 85 + L2 sin 50 sin 85 = 0.0560 + 0.7631 L2, which
     * is >= 1 for the axis (0,0,2) (L2 = 4): that track freezes at key 3's
     * 100 degrees, not key 4's 170 (as the reference does).  For the other
     * axes (L2 = 1.16, 0.94, 0.5) it is below 1 and the end is key 4.
     */
    const double axes[4][3] = {
        {0.0, 0.0, 2.0}, {0.6 * 1.077, 0.0, 0.8 * 1.077}, {0.0, 0.97, 0.0}, {0.3, -0.5, 0.4}};
    const double deg[6] = {-20.0, 10.0, 60.0, 100.0, 170.0, 200.0};
    for (int a = 0; a < 4; a++) {
        struct aff_key *k = alloc_keys(6);
        for (int i = 0; i < 6; i++)
            rot_key(&k[i], i, axes[a][0], axes[a][1], axes[a][2], deg[i]);
        struct aff_track tr;
        init_track(&tr, AFF_TRACK_ROT, k, 6);
        double len = sqrt(axes[a][0] * axes[a][0] + axes[a][1] * axes[a][1] +
                          axes[a][2] * axes[a][2]);
        double unit[3] = {axes[a][0] / len, axes[a][1] / len, axes[a][2] / len};
        double r[9], want[9];
        for (int i = 1; i <= 3; i++) {
            aff_track_eval(&tr, i, r);
            axis_angle_matrix(unit, deg[i] * pi / 180.0, want);
            failures += !CHECKF(max_diff9(r, want) <= 1e-12, "axis %d key %d: off by %g", a, i,
                  max_diff9(r, want));
        }
        double h3 = deg[3] * pi / 360.0;
        double h4 = deg[4] * pi / 360.0;
        double dot34 = cos(h3) * cos(h4) + len * len * sin(h3) * sin(h4);
        int end_key = dot34 >= 1.0 ? 3 : 4;
        failures += !CHECKF(end_key == (a == 0 ? 3 : 4), "axis %d: q3.q4 = %g", a, dot34);
        for (int i = 0; i < 2; i++) {
            aff_track_eval(&tr, i == 0 ? 4.0 : 100.0, r);
            axis_angle_matrix(unit, deg[end_key] * pi / 180.0, want);
            failures += !CHECKF(max_diff9(r, want) <= 1e-12, "axis %d clamped end: key %d expected, off by %g",
                  a, end_key, max_diff9(r, want));
        }
        for (int i = 0; i <= 200; i++) {
            double t = 0.5 + i * 0.02;
            aff_track_eval(&tr, t, r);
            failures += !CHECKF(orthonormal_error(r) <= 1e-12, "axis %d t=%g: not a rotation (%g)", a, t,
                  orthonormal_error(r));
        }
        aff_track_release(&tr);
    }
}

static void test_rotation_conj(void)
{
    /*
     * conj as the inverse (FORMAT.md sec. 7.4), which differs from the true
     * inverse for non-unit keys.  Keys about (0,0,2) at t = 0..3 with angles
     * 120 0 0 0.  In the (w, z) plane q0 = (cos 60, 2 sin 60 z) =
     * (0.5, 1.732 z), non-unit; q1 = q2 = q3 = (1, 0).
     *   D = L2 = 0.  L0 = log(conj(q0) q1) = log(0.5, -1.732 z):
     *   theta = acos 0.5 = 60 deg, s = sin 60, so L0 = (theta/s)(-1.732) z
     *   = -120 deg z (-2.094 rad).  (With the true inverse, dividing by
     *   |q0|^2 = 3.25, it would be -43.8 deg.)
     *   Tout = L0/2, Tin = 0, A = exp(Tout/2): half-angle phi = L0/4 = -30,
     *   B = (1, 0).
     * Squad at s: slerp(q1, q2, s) = (1, 0); slerp(A, B, s) has half-angle
     * phi (1 - s); the outer slerp takes h = 2 s (1 - s) of that:
     *   s = 1/2: half-angle -30 * 1/2 * 1/2 = -7.5, R(1.5) = Rz(-15);
     *   s = 1/4: half-angle -30 * 3/4 * 3/8 = -8.4375, R(1.25) = Rz(-16.875).
     */
    struct aff_key *k = alloc_keys(4);
    for (int i = 0; i < 4; i++)
        rot_key(&k[i], i, 0.0, 0.0, 2.0, i == 0 ? 120.0 : 0.0);
    struct aff_track tr;
    init_track(&tr, AFF_TRACK_ROT, k, 4);
    double r[9], want[9];
    aff_track_eval(&tr, 1.5, r);
    rot_z(-15.0, want);
    failures += !CHECKF(max_diff9(r, want) <= 1e-12, "conj: R(1.5) off by %g", max_diff9(r, want));
    aff_track_eval(&tr, 1.25, r);
    rot_z(-16.875, want);
    failures += !CHECKF(max_diff9(r, want) <= 1e-12, "conj: R(1.25) off by %g", max_diff9(r, want));
    aff_track_release(&tr);

    /* The rewrite of sec. 7.4 step 2 stores a unit axis even when the key's
     * axis was not: keys about (0,0,0.5), angles 240 90 300 150 (as in
     * test_rotation_rewrite): q1.q2 = cos 45 cos 150 + 0.25 sin 45 sin 150
     * < 0, so key 2 becomes 60 degrees about (0,0,-1). */
    k = alloc_keys(4);
    const double deg[4] = {240.0, 90.0, 300.0, 150.0};
    for (int i = 0; i < 4; i++)
        rot_key(&k[i], i, 0.0, 0.0, 0.5, deg[i]);
    init_track(&tr, AFF_TRACK_ROT, k, 4);
    failures += !CHECKF(tr.keys[2].v[0] == 0.0 && tr.keys[2].v[1] == 0.0 && tr.keys[2].v[2] == -1.0,
          "rewritten axis is unit: %g %g %g", tr.keys[2].v[0], tr.keys[2].v[1], tr.keys[2].v[2]);
    EXPECT_NEAR(tr.keys[2].v[3], 60.0, 1e-12, "rewritten angle");
    failures += !CHECKF(tr.keys[3].v[2] == 0.5 && tr.keys[3].v[3] == 150.0, "key 3 (n-1) never rewritten");
    aff_track_release(&tr);
}

static void test_rotation_thresholds(void)
{
    double r[9], want[9];
    /*
     * slerp threshold (FORMAT.md sec. 7.4: "if sin(theta) < 0.001, return
     * p, even when h = 1").  Keys about +z at t = 0..4 with angles 0 0.05
     * 0.1 0.15 0.2 degrees: neighbouring quaternions are 0.025 degrees =
     * 4.4e-4 rad apart, so every slerp between them returns its first
     * argument.  Tout = Tin = D (equal steps), A = q1, B = q2, and squad
     * is slerp(slerp(q1,q2,s), slerp(A,B,s), .) = q1 on the whole segment:
     * R(1.5) = Rz(0.05), R(2.5) = R(2.99) = Rz(0.1), and at the clamped
     * end (t >= t_3 = 3, u = 1) still Rz(0.1), not Rz(0.15).  A true slerp
     * would give Rz(0.075) at t = 1.5.
     */
    {
        struct aff_key *k = alloc_keys(5);
        for (int i = 0; i < 5; i++)
            rot_key(&k[i], i, 0.0, 0.0, 1.0, 0.05 * i);
        struct aff_track tr;
        init_track(&tr, AFF_TRACK_ROT, k, 5);
        const double ts[5] = {1.5, 2.0, 2.5, 2.99, 3.0};
        const double deg[5] = {0.05, 0.1, 0.1, 0.1, 0.1};
        for (int i = 0; i < 5; i++) {
            aff_track_eval(&tr, ts[i], r);
            rot_z(deg[i], want);
            failures += !CHECKF(max_diff9(r, want) <= 1e-12, "slerp threshold t=%g: off by %g", ts[i],
                  max_diff9(r, want));
        }
        aff_track_release(&tr);
    }
    /*
     * log threshold (FORMAT.md sec. 7.4: "if |s| >= 0.001 return
     * (0, (theta/s) v); in every other case (0, v)").  Keys about +z at
     * t = 0..3 with angles 0 0 0 359.98: q0 = q1 = q2 = (1, 0), so D = L0 =
     * 0, and q3 (not rewritten, q2.q3 is only compared in a later segment)
     * has half-angle 179.99 degrees: w = cos 179.99 > -1, theta = 179.99
     * degrees, s = sin theta = 1.7e-4 < 0.001, so L2 = v = 1.7e-4 z instead
     * of the true logarithm 3.1414 z.  Tin = L2/2, B = exp(-Tin/2) is a
     * rotation by 8.7e-5 rad, and every slerp in squad is then below the
     * slerp threshold: R = I for all t.  (With the true logarithm B would
     * be a rotation by -90 degrees and R(1.5) about -22 degrees.)
     */
    {
        struct aff_key *k = alloc_keys(4);
        for (int i = 0; i < 4; i++)
            rot_key(&k[i], i, 0.0, 0.0, 1.0, i == 3 ? 359.98 : 0.0);
        struct aff_track tr;
        init_track(&tr, AFF_TRACK_ROT, k, 4);
        const double id[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        for (int i = 0; i <= 20; i++) {
            double t = 0.9 + 0.06 * i;
            aff_track_eval(&tr, t, r);
            failures += !CHECKF(max_diff9(r, id) <= 1e-12, "log threshold t=%g: off by %g", t,
                  max_diff9(r, id));
        }
        aff_track_release(&tr);
    }
    /*
     * exp threshold (FORMAT.md sec. 7.4: "(cos theta, (s/theta) v) if
     * |s| >= 0.001, else (cos theta, v)"), which matters at theta = pi.
     * Keys about +z at t = 0..3, angles -202.5 0 90 180, key 1 with
     * (T, C, B) = (-1, 1, 1) (out0 = 1/2 * 2 * 2 * 2 = 4, out1 = 0), the
     * others TCB 0.  Half-angles -101.25 0 45 90, all unit, no rewrite.
     *   D = log(conj(q1) q2) = pi/4 z; L0 = log(conj(q0)) = 101.25 deg =
     *   9 pi/16 z; L2 = log(conj(q2) q3) = pi/4 z = D.
     *   Tout = 4 L0 = 9 pi/4 z, Tin = D, so B = q2 and
     *   A = q1 exp((Tout - D)/2) = exp(pi z): sin(pi) < 0.001, so
     *   A = (cos pi, pi z) = (-1, pi z), not (-1, 0).
     * At t = 1.5 (s = 1/2): pq = slerp(q1, q2, 1/2) = (cos pi/8, sin pi/8 z);
     *   A.B = -cos(pi/4) + pi sin(pi/4) > 1, clamped: slerp(A, B, 1/2) = A;
     *   outer slerp with h = 1/2: c = pq.A = pi sin(pi/8) - cos(pi/8),
     *   theta = acos c, both weights sin(theta/2)/sin(theta), so
     *   Q = (pq + A) / (2 cos(theta/2)), Q.w = (cos(pi/8) - 1) /
     *   (2 cos(theta/2)) = -0.0476, Q.z > 0: R(1.5) = Rz(2 acos Q.w),
     *   185.46 degrees.
     */
    {
        const double deg[4] = {-202.5, 0.0, 90.0, 180.0};
        struct aff_key *k = alloc_keys(4);
        for (int i = 0; i < 4; i++)
            rot_key(&k[i], i, 0.0, 0.0, 1.0, deg[i]);
        k[1].tension = -1.0;
        k[1].continuity = 1.0;
        k[1].bias = 1.0;
        struct aff_track tr;
        init_track(&tr, AFF_TRACK_ROT, k, 4);
        double c = pi * sin(pi / 8.0) - cos(pi / 8.0);
        double qw = (cos(pi / 8.0) - 1.0) / (2.0 * cos(0.5 * acos(c)));
        double angle = 2.0 * acos(qw);
        aff_track_eval(&tr, 1.5, r);
        rot_z(angle * 180.0 / pi, want);
        failures += !CHECKF(max_diff9(r, want) <= 1e-9, "exp threshold: R(1.5) off by %g (want %.4f deg)",
              max_diff9(r, want), angle * 180.0 / pi);
        aff_track_release(&tr);
    }
}

/* Keys shaped like robots grip_rot2 (Robot2.aff): axis of length 1.077,
 * 90 degree steps to 720, a long pause, again.  Returns the number of
 * sampled times with raw squad w > 1 and checks that every matrix is a
 * finite rotation. */
static int sweep_for_clamp(const struct aff_track *tr, double t0, double t1, int samples,
                           const char *what)
{
    int above = 0;
    for (int i = 0; i <= samples; i++) {
        double t = t0 + (t1 - t0) * i / samples;
        double q[4], r[9];
        aff_track_eval_quat(tr, t, q);
        if (fabs(q[0]) > 1.0)
            above++;
        aff_track_eval(tr, t, r);
        failures += !CHECKF(all_finite(r, 9) && orthonormal_error(r) <= 1e-9, "%s t=%.17g: w=%.17g", what, t,
              q[0]);
    }
    return above;
}

static void test_rotation_clamp(void)
{
    struct aff_key *k = alloc_keys(20);
    int n = 0;
    rot_key(&k[n++], 0.0, 0.76, -0.62, -0.445, 0.0);
    for (int i = 0; i <= 8; i++)
        rot_key(&k[n++], 0.75 * i, 0.76, -0.62, -0.445, 90.0 * i);
    for (int i = 0; i <= 8; i++)
        rot_key(&k[n++], 42.0 + 1.25 * i, 0.76, -0.62, -0.445, 90.0 * i);
    rot_key(&k[n++], 52.0, 0.76, -0.62, -0.445, 720.0);
    struct aff_track tr;
    init_track(&tr, AFF_TRACK_ROT, k, n);
    int above = sweep_for_clamp(&tr, 0.0, 52.0, 20000, "grip_rot2-like");
    /* The test is only meaningful if the clamp was needed somewhere. */
    failures += !CHECKF(above > 0, "no sample with w > 1: the clamp was not exercised");
    printf("  grip_rot2-like keys: %d of 20001 samples have raw w > 1, all clamped\n", above);
    aff_track_release(&tr);
}

/* ------------------------------------- 3. visibility, frames, composition */

static void test_visibility(void)
{
    double times[3] = {1.0, 2.0, 2.0};
    int flags[3] = {0, 5, 0};
    struct aff_visibility vis = {3, times, flags};
    failures += !CHECKF(aff_visibility_eval(&vis, 0.5) == 1, "visible before the first key");
    failures += !CHECKF(aff_visibility_eval(&vis, 1.0) == 0, "hidden at the first key");
    failures += !CHECKF(aff_visibility_eval(&vis, 1.5) == 0, "hidden between");
    /* Equal times: the later key (flag 0) wins. */
    failures += !CHECKF(aff_visibility_eval(&vis, 2.0) == 0, "later of equal times");
    failures += !CHECKF(aff_visibility_eval(&vis, 9.0) == 0, "last key onwards");
    flags[2] = 3;
    failures += !CHECKF(aff_visibility_eval(&vis, 9.0) == 1, "non-zero flag is visible, returned as 1");
    failures += !CHECKF(aff_visibility_eval(NULL, 0.0) == 1, "NULL visible");
    struct aff_visibility none = {0, NULL, NULL};
    failures += !CHECKF(aff_visibility_eval(&none, 0.0) == 1, "no keys visible");
    failures += !CHECKF(aff_visibility_eval(&vis, NAN) == 1, "NaN time: visible (no key applies)");
}

static void test_frame_time(void)
{
    /* FORMAT.md sec. 5 and the t column of sec. 9. */
    failures += !CHECKF(aff_frame_time(0.0, 20.0, 800, 0) == 0.0, "first frame");
    failures += !CHECKF(aff_frame_time(0.0, 20.0, 800, 799) == 20.0, "last frame");
    failures += !CHECKF(aff_frame_time(-1.0, 5.0, 300, 299) == 5.0, "museum last frame");
    EXPECT_NEAR(aff_frame_time(0.0, 20.0, 800, 199), 4.981227, 1e-6, "kitchen 199");
    EXPECT_NEAR(aff_frame_time(0.0, 50.0, 800, 599), 37.484355, 1e-6, "robots 599");
    EXPECT_NEAR(aff_frame_time(-1.0, 5.0, 300, 74), 0.484950, 1e-6, "museum 74");
    failures += !CHECKF(aff_frame_time(3.0, 7.0, 1, 0) == 3.0, "one frame");
    failures += !CHECKF(aff_frame_time(3.0, 7.0, 0, 5) == 3.0, "no frames");
}

static void test_node_matrix_and_camera(void)
{
    double m[16];
    aff_node_matrix(NULL, NULL, NULL, 1.0, m);
    for (int i = 0; i < 16; i++)
        failures += !CHECKF(m[i] == (i % 5 == 0 ? 1.0 : 0.0), "identity m[%d] = %g", i, m[i]);

    /* T = (1,2,3) constant, R = 90 degrees about z, S = (2,3,4):
     * M = [[0 -3 0 1] [2 0 0 2] [0 0 4 3]], column-major. */
    struct aff_key *kt = alloc_keys(4);
    struct aff_key *kr = alloc_keys(4);
    struct aff_key *ks = alloc_keys(4);
    for (int i = 0; i < 4; i++) {
        set_key(&kt[i], i, 1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 0.0);
        rot_key(&kr[i], i, 0.0, 0.0, 1.0, 90.0);
        set_key(&ks[i], i, 2.0, 3.0, 4.0, 0.0, 0.0, 0.0, 0.0);
    }
    struct aff_track t, r, s;
    init_track(&t, AFF_TRACK_TRANSL, kt, 4);
    init_track(&r, AFF_TRACK_ROT, kr, 4);
    init_track(&s, AFF_TRACK_SCALE, ks, 4);
    aff_node_matrix(&t, &r, &s, 1.5, m);
    const double want[16] = {0, 2, 0, 0, -3, 0, 0, 0, 0, 0, 4, 0, 1, 2, 3, 1};
    for (int i = 0; i < 16; i++)
        EXPECT_NEAR(m[i], want[i], 1e-12, "T R S column-major");

    double eye[3], dir[3], up[3];
    aff_camera_eval(NULL, NULL, 0.0, eye, dir, up);
    failures += !CHECKF(eye[0] == 0 && eye[1] == 0 && eye[2] == 0, "camera eye default");
    failures += !CHECKF(dir[0] == 0 && dir[1] == 0 && dir[2] == -1, "camera looks down -z");
    failures += !CHECKF(up[0] == 0 && up[1] == 1 && up[2] == 0, "camera up +y");
    /* R = 90 degrees about z: dir = R(0,0,-1) = (0,0,-1), up = R(0,1,0) =
     * (-1,0,0). */
    aff_camera_eval(&t, &r, 2.0, eye, dir, up);
    EXPECT_NEAR(eye[1], 2.0, 1e-12, "camera eye");
    EXPECT_NEAR(dir[2], -1.0, 1e-12, "camera dir");
    EXPECT_NEAR(up[0], -1.0, 1e-12, "camera up x");
    EXPECT_NEAR(up[1], 0.0, 1e-12, "camera up y");
    aff_track_release(&t);
    aff_track_release(&r);
    aff_track_release(&s);
}

/* ------------------------------------------------------------ fuzzing */

static unsigned long long rng_state = 0x9e3779b97f4a7c15ull;

static double rnd(void) /* [0, 1) */
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);
}

static double rnd_range(double lo, double hi)
{
    return lo + (hi - lo) * rnd();
}

/* Arbitrary finite doubles, from tiny to near the overflow threshold. */
static double rnd_wild(void)
{
    double mag = pow(10.0, rnd_range(-310.0, 308.0));
    switch ((int)(rnd() * 6.0)) {
    case 0:
        return 0.0;
    case 1:
        return rnd() < 0.5 ? -1.7976931348623157e308 : 1.7976931348623157e308;
    default:
        return rnd() < 0.5 ? -mag : mag;
    }
}

static void fuzz_track(int wild)
{
    int n = 4 + (int)(rnd() * 9.0);
    int kind = (int)(rnd() * 3.0);
    int time_mode = (int)(rnd() * 3.0);
    struct aff_key *k = alloc_keys(n);
    double t_lo = HUGE_VAL, t_hi = -HUGE_VAL;
    for (int i = 0; i < n; i++) {
        double time;
        if (wild)
            time = rnd_wild();
        else if (time_mode == 0)
            time = i + 0.25 * (int)(rnd() * 4.0); /* increasing with duplicates */
        else if (time_mode == 1)
            time = (int)(rnd() * 5.0); /* small integers: repeats, back and forth */
        else
            time = rnd_range(-100.0, 100.0); /* arbitrary order */
        k[i].time = time;
        for (int c = 0; c < 3; c++)
            k[i].v[c] = wild ? rnd_wild() : (kind == AFF_TRACK_ROT ? rnd_range(-2.0, 2.0)
                                                                   : rnd_range(-1e3, 1e3));
        if (kind == AFF_TRACK_ROT && !wild && rnd() < 0.1)
            k[i].v[0] = k[i].v[1] = k[i].v[2] = 0.0; /* zero axis */
        k[i].v[3] = wild ? rnd_wild() : rnd_range(-1e4, 1e4);
        k[i].tension = wild ? rnd_wild() : rnd_range(-2.0, 2.0);
        k[i].continuity = wild ? rnd_wild() : rnd_range(-2.0, 2.0);
        k[i].bias = wild ? rnd_wild() : rnd_range(-2.0, 2.0);
        if (time < t_lo)
            t_lo = time;
        if (time > t_hi)
            t_hi = time;
    }
    struct aff_track tr;
    if (aff_track_init(&tr, kind, k, n) != 0) {
        failures += !CHECKF(0, "init failed for a valid key count");
        return;
    }
    for (int i = 0; i < 40 + n; i++) {
        double t;
        if (i < n)
            t = tr.keys[i].time;
        else if (i == n)
            t = HUGE_VAL;
        else if (i == n + 1)
            t = -HUGE_VAL;
        else if (i == n + 2)
            t = NAN;
        else
            t = wild ? rnd_wild() : rnd_range(t_lo - 10.0, t_hi + 10.0);
        double out[9], q[4];
        aff_track_eval(&tr, t, out);
        aff_track_eval_quat(&tr, t, q);
        if (wild)
            continue; /* only "no crash, no UB" is required */
        if (kind == AFF_TRACK_ROT)
            failures += !CHECKF(all_finite(out, 9) && orthonormal_error(out) <= 1e-9,
                  "fuzz rot n=%d mode=%d t=%g: not a finite rotation", n, time_mode, t);
        else
            failures += !CHECKF(all_finite(out, 3), "fuzz kind=%d n=%d mode=%d t=%g: %g %g %g", kind, n,
                  time_mode, t, out[0], out[1], out[2]);
    }
    double m[16], eye[3], dir[3], up[3];
    aff_node_matrix(&tr, &tr, &tr, 0.5, m);
    aff_camera_eval(&tr, &tr, 0.5, eye, dir, up);
    aff_track_release(&tr);
}

static void fuzz_tpa(void)
{
    int n = 1 + (int)(rnd() * 5.0);
    struct aff_tpa_key keys[6];
    for (int i = 0; i < n; i++) {
        keys[i].time = rnd() < 0.3 ? (int)(rnd() * 3.0) : rnd_wild();
        for (int c = 0; c < 9; c++) {
            keys[i].p[c] = rnd() < 0.1 ? 3.4028235e38f : (float)rnd_range(-1e3, 1e3);
            keys[i].n[c] = rnd() < 0.1 ? -3.4028235e38f : (float)rnd_range(-1.0, 1.0);
        }
    }
    for (int i = 0; i < 20; i++) {
        double t = i == 0 ? NAN : (rnd() < 0.5 ? rnd_wild() : (int)(rnd() * 3.0));
        float p[9], nn[9];
        aff_tpa_eval(keys, n, t, p, nn);
        for (int c = 0; c < 9; c++)
            failures += !CHECKF(isfinite(p[c]) && isfinite(nn[c]), "tpa fuzz t=%g: not finite", t);
    }
}

static void test_fuzz(void)
{
    for (int i = 0; i < 3000; i++)
        fuzz_track(0);
    for (int i = 0; i < 3000; i++)
        fuzz_track(1);
    for (int i = 0; i < 2000; i++)
        fuzz_tpa();
}

/* ------------------------------------------------------------ 5. tpa */

static void tpa_fill(struct aff_tpa_key *k, double time, float base)
{
    k->time = time;
    for (int i = 0; i < 9; i++) {
        k->p[i] = base + (float)i;
        k->n[i] = -base - (float)i;
    }
}

static void test_tpa_hand(void)
{
    struct aff_tpa_key k[4];
    tpa_fill(&k[0], 0.0, 0.0f);
    tpa_fill(&k[1], 1.0, 10.0f);
    tpa_fill(&k[2], 1.0, 20.0f);
    tpa_fill(&k[3], 3.0, 40.0f);
    float p[9], n[9];
    aff_tpa_eval(k, 4, -5.0, p, n);
    failures += !CHECKF(p[0] == 0.0f && p[8] == 8.0f && n[3] == -3.0f, "before the first key: key 0");
    aff_tpa_eval(k, 4, 7.0, p, n);
    failures += !CHECKF(p[0] == 40.0f && n[8] == -48.0f, "after the last key: last key");
    aff_tpa_eval(k, 4, 0.25, p, n);
    failures += !CHECKF(p[0] == 2.5f && p[4] == 6.5f && n[4] == -6.5f, "linear: %g %g %g", p[0], p[4], n[4]);
    /* t = 1 is in [t_0, t_1] first (r = 1): key 1, not key 2. */
    aff_tpa_eval(k, 4, 1.0, p, n);
    failures += !CHECKF(p[0] == 10.0f, "first bracketing pair at a duplicate time: %g", p[0]);
    aff_tpa_eval(k, 4, 2.0, p, n);
    failures += !CHECKF(p[0] == 30.0f && n[1] == -31.0f, "after the duplicate: %g", p[0]);
    aff_tpa_eval(k, 4, NAN, p, n);
    failures += !CHECKF(p[0] == 0.0f, "NaN time: key 0");
    /* Zero-length interval at t: key k (no division by zero). */
    aff_tpa_eval(k + 1, 2, 1.0, p, n);
    failures += !CHECKF(p[0] == 10.0f, "zero-length interval: %g", p[0]);
    aff_tpa_eval(k, 1, 0.0, p, n);
    failures += !CHECKF(p[0] == 0.0f, "one key");
    aff_tpa_eval(NULL, 0, 0.0, p, n);
    failures += !CHECKF(p[0] == 0.0f && n[8] == 0.0f, "no keys: zeros");
    /* Normals are interpolated, not normalised. */
    tpa_fill(&k[0], 0.0, 0.0f);
    k[0].n[0] = 1e-5f;
    k[1].n[0] = 1.0f;
    aff_tpa_eval(k, 2, 0.5, p, n);
    EXPECT_NEAR(n[0], 0.500005, 1e-7, "normal not normalised");
}

/* ---------------------------------------------- BART files (sec. 9, 7.5) */

static const char *bart_dir(void)
{
    const char *env = getenv("TRACELIST_BART_DIR");
    if (env && *env)
        return env;
#ifdef RT_BART_DIR
    return RT_BART_DIR;
#else
    return NULL;
#endif
}

static int bart_missing_reported;

static void report_missing(const char *path)
{
    failures++;
    if (bart_missing_reported++)
        return;
    const char *env = getenv("TRACELIST_BART_DIR");
    fprintf(stderr,
            "\n*** FAIL: cannot read the BART scene file %s\n"
            "*** The BART folder (holding kitchen/, robots/, museum/ and FORMAT.md) was taken\n"
            "*** from %s.\n"
            "*** Set the environment variable TRACELIST_BART_DIR to that folder, or configure\n"
            "*** with -DRT_BART_DIR=<folder>. This test never skips the BART checks.\n\n",
            path ? path : "(no folder)",
            env && *env ? "the environment variable TRACELIST_BART_DIR"
                        : "RT_BART_DIR, the default compiled in by CMake");
}

/* Reads "<bart_dir>/<rel>" whole; NULL (and a failure reported) if absent. */
static char *read_bart_file(const char *rel, size_t *size)
{
    const char *dir = bart_dir();
    if (!dir) {
        report_missing(NULL);
        return NULL;
    }
    size_t len = strlen(dir) + strlen(rel) + 2;
    char *path = malloc(len);
    if (!path)
        return NULL;
    snprintf(path, len, "%s/%s", dir, rel);
    FILE *f = fopen(path, "rb");
    char *data = NULL;
    if (f) {
        size_t cap = 1 << 16;
        size_t n = 0;
        data = malloc(cap + 1);
        while (data) {
            size_t got = fread(data + n, 1, cap - n, f);
            n += got;
            if (n < cap)
                break;
            char *bigger = realloc(data, cap * 2 + 1);
            if (!bigger) {
                free(data);
                data = NULL;
                break;
            }
            data = bigger;
            cap *= 2;
        }
        fclose(f);
        if (data) {
            data[n] = '\0';
            *size = n;
        }
    }
    if (!data)
        report_missing(path);
    free(path);
    return data;
}

/*
 * A tokenizer just good enough for `k` blocks and `tpa` rows: tokens are
 * separated by whitespace, '{' and '}' are tokens of their own, and a token
 * starting with '#' or '%' starts a comment to the end of the line.  In AFF
 * comments are only legal at statement level (FORMAT.md sec. 2) and the data
 * has none inside operand lists, so this is enough for these files.
 */
struct lexer {
    const char *p;
    const char *end;
};

static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

static int next_token(struct lexer *lx, char *buf, size_t cap)
{
    for (;;) {
        while (lx->p < lx->end && is_space((unsigned char)*lx->p))
            lx->p++;
        if (lx->p >= lx->end)
            return 0;
        if (*lx->p != '#' && *lx->p != '%')
            break;
        while (lx->p < lx->end && *lx->p != '\n' && *lx->p != '\r')
            lx->p++;
    }
    size_t len = 0;
    if (*lx->p == '{' || *lx->p == '}') {
        buf[len++] = *lx->p++;
    } else {
        while (lx->p < lx->end && !is_space((unsigned char)*lx->p) && *lx->p != '{' &&
               *lx->p != '}') {
            if (len + 1 < cap)
                buf[len++] = *lx->p;
            lx->p++;
        }
    }
    buf[len] = '\0';
    return 1;
}

/* Next token as a float32 widened to double (FORMAT.md sec. 1). */
static int next_float(struct lexer *lx, double *out)
{
    char tok[64];
    char *end;
    if (!next_token(lx, tok, sizeof(tok)))
        return 0;
    float v = strtof(tok, &end);
    if (end == tok || *end != '\0')
        return 0;
    *out = v;
    return 1;
}

static int next_int(struct lexer *lx, int *out)
{
    char tok[64];
    char *end;
    if (!next_token(lx, tok, sizeof(tok)))
        return 0;
    long v = strtol(tok, &end, 10);
    if (end == tok || *end != '\0' || v < 0 || v > 1000000)
        return 0;
    *out = (int)v;
    return 1;
}

/* One `k` block as read; tracks are indexed by AFF_TRACK_* kind. */
struct k_block {
    char name[64];
    struct aff_key *keys[3];
    int count[3];
};

static void k_block_free(struct k_block *b)
{
    for (int i = 0; i < 3; i++)
        free(b->keys[i]);
    memset(b, 0, sizeof(*b));
}

/* Parses the body of a k block after its '{'.  Returns 0 on success. */
static int parse_k_body(struct lexer *lx, struct k_block *b)
{
    char tok[64];
    while (next_token(lx, tok, sizeof(tok))) {
        if (strcmp(tok, "}") == 0)
            return 0;
        int kind;
        if (strcmp(tok, "transl") == 0)
            kind = AFF_TRACK_TRANSL;
        else if (strcmp(tok, "rot") == 0)
            kind = AFF_TRACK_ROT;
        else if (strcmp(tok, "scale") == 0)
            kind = AFF_TRACK_SCALE;
        else if (strcmp(tok, "visibility") == 0)
            kind = -1;
        else
            return -1;
        int n;
        if (!next_int(lx, &n))
            return -1;
        if (kind < 0) {
            for (int i = 0; i < 2 * n; i++) {
                double skip;
                if (!next_float(lx, &skip))
                    return -1;
            }
            continue;
        }
        if (b->keys[kind] || n < 1)
            return -1;
        b->keys[kind] = alloc_keys(n);
        b->count[kind] = n;
        for (int i = 0; i < n; i++) {
            struct aff_key *k = &b->keys[kind][i];
            int ok = next_float(lx, &k->time);
            for (int c = 0; c < (kind == AFF_TRACK_ROT ? 4 : 3); c++)
                ok = ok && next_float(lx, &k->v[c]);
            ok = ok && next_float(lx, &k->tension) && next_float(lx, &k->continuity) &&
                 next_float(lx, &k->bias);
            if (!ok)
                return -1;
        }
    }
    return -1;
}

/* Reads every k block of "<bart_dir>/<rel>", appending to *blocks.  Returns
 * the number read, or -1 (with a failure reported) on a missing file or a
 * syntax error. */
static int read_k_blocks(const char *rel, struct k_block **blocks, int *count)
{
    size_t size;
    char *text = read_bart_file(rel, &size);
    if (!text)
        return -1;
    struct lexer lx = {text, text + size};
    char tok[64];
    int read = 0;
    int error = 0;
    while (!error && next_token(&lx, tok, sizeof(tok))) {
        if (strcmp(tok, "k") != 0)
            continue;
        struct k_block b;
        memset(&b, 0, sizeof(b));
        char brace[8];
        if (!next_token(&lx, b.name, sizeof(b.name)) || !next_token(&lx, brace, sizeof(brace)) ||
            strcmp(brace, "{") != 0 || parse_k_body(&lx, &b) != 0) {
            failures += !CHECKF(0, "%s: cannot read k block '%s'", rel, b.name);
            k_block_free(&b);
            error = 1;
            break;
        }
        struct k_block *grown = realloc(*blocks, (size_t)(*count + 1) * sizeof(**blocks));
        if (!grown) {
            k_block_free(&b);
            error = 1;
            break;
        }
        *blocks = grown;
        (*blocks)[(*count)++] = b;
        read++;
    }
    free(text);
    return error ? -1 : read;
}

/* The tracks of one k block, set up (each NULL when absent). */
struct node {
    struct aff_track track[3];
    int has[3];
};

static void node_init(struct node *nd, const struct k_block *b)
{
    memset(nd, 0, sizeof(*nd));
    for (int kind = 0; kind < 3; kind++) {
        if (!b->keys[kind])
            continue;
        struct aff_key *copy = alloc_keys(b->count[kind]);
        memcpy(copy, b->keys[kind], (size_t)b->count[kind] * sizeof(*copy));
        nd->has[kind] = aff_track_init(&nd->track[kind], kind, copy, b->count[kind]) == 0;
        failures += !CHECKF(nd->has[kind], "%s: track %d did not set up", b->name, kind);
    }
}

static void node_release(struct node *nd)
{
    for (int kind = 0; kind < 3; kind++)
        aff_track_release(&nd->track[kind]);
}

static const struct aff_track *node_track(const struct node *nd, int kind)
{
    return nd->has[kind] ? &nd->track[kind] : NULL;
}

/* Finds k block `name` in "<bart_dir>/<rel>" (the last one, as the
 * reference's lookup returns the most recently read definition) and sets up
 * its tracks.  Returns 0, or -1 with a failure reported. */
static int load_node(const char *rel, const char *name, struct node *nd)
{
    struct k_block *blocks = NULL;
    int count = 0;
    int found = -1;
    if (read_k_blocks(rel, &blocks, &count) >= 0) {
        for (int i = 0; i < count; i++)
            if (strcmp(blocks[i].name, name) == 0)
                found = i;
        failures += !CHECKF(found >= 0, "no 'k %s' block in %s", name, rel);
        if (found >= 0)
            node_init(nd, &blocks[found]);
    }
    for (int i = 0; i < count; i++)
        k_block_free(&blocks[i]);
    free(blocks);
    return found >= 0 ? 0 : -1;
}

struct scene {
    const char *folder;
    double t0, t1;
    int frames;
};

static const struct scene kitchen = {"kitchen", 0.0, 20.0, 800};
static const struct scene robots = {"robots", 0.0, 50.0, 800};
static const struct scene museum = {"museum", -1.0, 5.0, 300};

/* FORMAT.md sec. 9, camera table: every row. */
struct camera_row {
    const struct scene *scene;
    const char *file;
    int f;
    double t;
    double eye[3], dir[3], up[3];
};

static const struct camera_row camera_rows[] = {
    {&kitchen, "kitchen/kitchen.aff", 0, 0.000000, {3.750000, 2.300000, 3.600000},
     {-0.313464, -0.419814, -0.851761}, {-0.127003, 0.907444, -0.400520}},
    {&kitchen, "kitchen/kitchen.aff", 199, 4.981227, {3.500703, 0.205904, 0.108172},
     {-0.007200, -0.000234, 0.999974}, {-0.001705, 0.999999, 0.000222}},
    {&kitchen, "kitchen/kitchen.aff", 399, 9.987484, {3.117500, 0.488489, 1.050000},
     {-0.614232, -0.580518, -0.534526}, {-0.450436, 0.814098, -0.366541}},
    {&kitchen, "kitchen/kitchen.aff", 599, 14.993742, {0.726407, 0.217559, 1.009291},
     {0.904812, -0.171723, 0.389650}, {0.148621, 0.984887, 0.088936}},
    {&kitchen, "kitchen/kitchen.aff", 799, 20.000000, {3.274880, 0.334545, 2.980280},
     {-0.717361, -0.462546, 0.521003}, {-0.359727, 0.886328, 0.291580}},
    {&robots, "robots/Robot.aff", 0, 0.000000, {-3.500000, 2.000000, -203.000000},
     {0.058812, 0.098707, -0.993377}, {-0.005843, 0.995116, 0.098534}},
    {&robots, "robots/Robot.aff", 199, 12.453066, {1.001138, 12.935702, -165.876776},
     {-0.988521, -0.150549, -0.012691}, {-0.148202, 0.982570, -0.112218}},
    {&robots, "robots/Robot.aff", 399, 24.968711, {-2.979783, 26.001560, -26.546987},
     {0.052773, -0.000113, 0.998607}, {0.000024, 1.000000, 0.000112}},
    {&robots, "robots/Robot.aff", 599, 37.484355, {0.000000, 9.157873, 36.064409},
     {0.109461, 0.042639, -0.993076}, {0.009308, 0.998992, 0.043919}},
    {&robots, "robots/Robot.aff", 799, 50.000000, {0.000000, 80.000000, 0.000000},
     {-0.141450, -0.985054, 0.098288}, {-0.936723, 0.165301, 0.308585}},
    {&museum, "museum/camera.aff", 0, -1.000000, {0.000000, 1.800000, -9.000000},
     {0.000000, 0.000000, 1.000000}, {0.000000, 1.000000, 0.000000}},
    {&museum, "museum/camera.aff", 74, 0.484950, {2.998428, 2.392520, -1.065801},
     {-0.999715, 0.001914, 0.023815}, {0.001959, 0.999996, 0.001868}},
    {&museum, "museum/camera.aff", 149, 1.989967, {-2.328376, 2.477847, 3.078259},
     {0.714475, -0.188956, -0.673662}, {0.095549, 0.980172, -0.173591}},
    {&museum, "museum/camera.aff", 224, 3.494983, {-0.953215, 1.398820, -3.098405},
     {0.273556, 0.304964, 0.912230}, {-0.099315, 0.952292, -0.288575}},
    {&museum, "museum/camera.aff", 299, 5.000000, {0.095173, 1.749330, -5.988240},
     {0.190347, -0.101337, -0.976473}, {-0.013312, 0.994300, -0.105782}},
};

/* FORMAT.md sec. 9, node table: every row (top 3x4 of M, row-major). */
struct node_row {
    const struct scene *scene;
    const char *file;
    const char *name;
    int f;
    double t;
    double m[3][4];
};

static const struct node_row node_rows[] = {
    {&kitchen, "kitchen/kitchen.aff", "toycar", 199, 4.981227,
     {{-0.991024, 0, 0.133684, 3.756173}, {0, 1, 0, 0}, {-0.133684, 0, -0.991024, 2.750843}}},
    {&kitchen, "kitchen/kitchen.aff", "toycar", 399, 9.987484,
     {{-0.276094, 0, -0.961131, 2.679892}, {0, 1, 0, 0}, {0.961131, 0, -0.276094, 0.599832}}},
    {&kitchen, "kitchen/kitchen.aff", "toycar", 799, 20.000000,
     {{-0.000003, 0, -1.000000, 2.750000}, {0, 1, 0, 0}, {0.500000, 0, -0.000006, 3.400000}}},
    {&kitchen, "kitchen/car_rotating_wheel_left.aff", "rotating_wheel_left", 199, 4.981227,
     {{0.256202, 0.966623, 0, 0}, {-0.966623, 0.256202, 0, 0}, {0, 0, 1, 0}}},
    {&kitchen, "kitchen/car_rotating_wheel_left.aff", "rotating_wheel_left", 299, 7.484355,
     {{-0.999170, 0.040743, 0, 0}, {-0.040743, -0.999170, 0, 0}, {0, 0, 1, 0}}},
    {&robots, "robots/Robot1.aff", "robot_transl1", 399, 24.968711,
     {{1, 0, 0, -7.597478}, {0, 1, 0, 0}, {0, 0, 1, -111.235556}}},
    {&robots, "robots/Robot1.aff", "lo_leg_rot1", 99, 6.195244,
     {{1, 0, 0, 0}, {0, 0.943335, 0.331843, 0}, {0, -0.331843, 0.943335, 0}}},
    {&robots, "robots/Robot1.aff", "lo_leg_rot1", 399, 24.968711,
     {{1, 0, 0, 0}, {0, 0.843099, -0.537758, 0}, {0, 0.537758, 0.843099, 0}}},
    {&robots, "robots/Robot1.aff", "gun_rot1", 499, 31.226533,
     {{-0.757269, 0.653103, 0, 0}, {-0.653103, -0.757269, 0, 0}, {0, 0, 1, 0}}},
};

#define TABLE_TOL 1e-5

/* Largest |computed - table| over all entries checked, for the log. */
static double table_worst;

static double table_diff(double got, double want)
{
    double d = fabs(got - want);
    if (!(d <= table_worst))
        table_worst = d;
    return d;
}

static void test_camera_table(void)
{
    int rows = (int)(sizeof(camera_rows) / sizeof(camera_rows[0]));
    int passed = 0;
    for (int i = 0; i < rows; i++) {
        const struct camera_row *row = &camera_rows[i];
        struct node nd;
        if (load_node(row->file, "camera", &nd) != 0)
            continue;
        int before = failures;
        double t = aff_frame_time(row->scene->t0, row->scene->t1, row->scene->frames, row->f);
        failures += !CHECKF(fabs(t - row->t) <= 1e-6, "%s f=%d: t = %.9f, table %.6f", row->scene->folder,
              row->f, t, row->t);
        double eye[3], dir[3], up[3];
        aff_camera_eval(node_track(&nd, AFF_TRACK_TRANSL), node_track(&nd, AFF_TRACK_ROT), t, eye,
                        dir, up);
        for (int c = 0; c < 3; c++) {
            failures += !CHECKF(table_diff(eye[c], row->eye[c]) <= TABLE_TOL, "%s camera f=%d eye[%d] = %.6f, table %.6f",
                  row->scene->folder, row->f, c, eye[c], row->eye[c]);
            failures += !CHECKF(table_diff(dir[c], row->dir[c]) <= TABLE_TOL, "%s camera f=%d dir[%d] = %.6f, table %.6f",
                  row->scene->folder, row->f, c, dir[c], row->dir[c]);
            failures += !CHECKF(table_diff(up[c], row->up[c]) <= TABLE_TOL, "%s camera f=%d up[%d] = %.6f, table %.6f",
                  row->scene->folder, row->f, c, up[c], row->up[c]);
        }
        if (failures == before)
            passed++;
        node_release(&nd);
    }
    printf("  FORMAT.md sec. 9 camera table: %d of %d rows match to %g\n", passed, rows,
           TABLE_TOL);
}

static void test_node_table(void)
{
    int rows = (int)(sizeof(node_rows) / sizeof(node_rows[0]));
    int passed = 0;
    for (int i = 0; i < rows; i++) {
        const struct node_row *row = &node_rows[i];
        struct node nd;
        if (load_node(row->file, row->name, &nd) != 0)
            continue;
        int before = failures;
        double t = aff_frame_time(row->scene->t0, row->scene->t1, row->scene->frames, row->f);
        failures += !CHECKF(fabs(t - row->t) <= 1e-6, "%s f=%d: t = %.9f, table %.6f", row->name, row->f, t,
              row->t);
        double m[16];
        aff_node_matrix(node_track(&nd, AFF_TRACK_TRANSL), node_track(&nd, AFF_TRACK_ROT),
                        node_track(&nd, AFF_TRACK_SCALE), t, m);
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 4; c++)
                failures += !CHECKF(table_diff(m[c * 4 + r], row->m[r][c]) <= TABLE_TOL,
                      "%s f=%d M[%d][%d] = %.6f, table %.6f", row->name, row->f, r, c,
                      m[c * 4 + r], row->m[r][c]);
        failures += !CHECKF(m[3] == 0.0 && m[7] == 0.0 && m[11] == 0.0 && m[15] == 1.0, "%s: bottom row",
              row->name);
        if (failures == before)
            passed++;
        node_release(&nd);
    }
    printf("  FORMAT.md sec. 9 node table: %d of %d rows match to %g\n", passed, rows,
           TABLE_TOL);
    printf("  largest deviation from the printed sec. 9 values: %.3g\n", table_worst);
}

/* Other statements of FORMAT.md checked on the data: the toy car stands
 * still until t = 3 (sec. 7.6.4), the robot camera is still from t = 45 on
 * (sec. 7.2), and grip_rot2 has raw w > 1 at 0-based frames 95, 672, 673,
 * 674 (sec. 7.6.1), where the clamp gives the identity. */
static void test_data_statements(void)
{
    struct node nd;
    if (load_node("kitchen/kitchen.aff", "toycar", &nd) == 0) {
        double m0[16], m1[16];
        aff_node_matrix(node_track(&nd, 0), node_track(&nd, 1), node_track(&nd, 2), 0.0, m0);
        aff_node_matrix(node_track(&nd, 0), node_track(&nd, 1), node_track(&nd, 2), 3.0, m1);
        for (int i = 0; i < 16; i++)
            failures += !CHECKF(fabs(m0[i] - m1[i]) <= 1e-12, "toycar moves before t=3 (m[%d])", i);
        failures += !CHECKF(fabs(m0[12] - 4.45f) <= 1e-12 && fabs(m0[14] - 2.75f) <= 1e-12,
              "toycar starts at (4.45, 0, 2.75): %g %g", m0[12], m0[14]);
        double s[3];
        aff_track_eval(&nd.track[AFF_TRACK_SCALE], 19.81f, s);
        failures += !CHECKF(fabs(s[0] - 0.5) <= 1e-6, "toycar x-scale 0.5 at 19.81: %g", s[0]);
        node_release(&nd);
    }
    if (load_node("robots/Robot.aff", "camera", &nd) == 0) {
        double e0[3], d0[3], u0[3], e1[3], d1[3], u1[3];
        aff_camera_eval(&nd.track[0], &nd.track[1], 45.0, e0, d0, u0);
        aff_camera_eval(&nd.track[0], &nd.track[1], 48.7, e1, d1, u1);
        for (int c = 0; c < 3; c++)
            failures += !CHECKF(e0[c] == e1[c] && d0[c] == d1[c] && u0[c] == u1[c],
                  "robot camera moves after t=45");
        node_release(&nd);
    }
    if (load_node("robots/Robot2.aff", "grip_rot2", &nd) == 0) {
        const int frames[4] = {95, 672, 673, 674};
        for (int i = 0; i < 4; i++) {
            double t = aff_frame_time(0.0, 50.0, 800, frames[i]);
            double q[4], r[9];
            aff_track_eval_quat(&nd.track[AFF_TRACK_ROT], t, q);
            aff_track_eval(&nd.track[AFF_TRACK_ROT], t, r);
            const double id[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
            failures += !CHECKF(q[0] > 1.0, "grip_rot2 frame %d (t=%.6f): raw w = %.17g, FORMAT.md 7.6.1 says > 1",
                  frames[i], t, q[0]);
            failures += !CHECKF(max_diff9(r, id) <= 1e-12, "grip_rot2 frame %d: clamped R is not I (%g)",
                  frames[i], max_diff9(r, id));
        }
        node_release(&nd);
    }
}

/* Every distinct k block of the three scenes (the files below hold all of
 * them, FORMAT.md sec. 10: 6 + 187 + 1) at every frame: matrices finite,
 * rotations orthonormal; count the evaluations where the raw squad w is
 * outside [-1, 1] (the reference's NaNs, sec. 7.6.1: 4, all grip_rot2). */
static void test_all_data(void)
{
    static const char *const kitchen_files[] = {
        "kitchen/kitchen.aff", "kitchen/car_front_wheel_left.aff",
        "kitchen/car_front_wheel_right.aff", "kitchen/car_rotating_wheel_left.aff",
        "kitchen/car_rotating_wheel_right.aff"};
    static const char *const robot_files[] = {
        "robots/Robot.aff",   "robots/Robot1.aff", "robots/Robot2.aff", "robots/Robot3.aff",
        "robots/Robot4.aff",  "robots/Robot5.aff", "robots/Robot6.aff", "robots/Robot7.aff",
        "robots/Robot8.aff",  "robots/Robot9.aff", "robots/Robot10.aff"};
    static const char *const museum_files[] = {"museum/camera.aff"};
    const struct {
        const struct scene *scene;
        const char *const *files;
        int file_count;
        int blocks, tracks, keys; /* FORMAT.md sec. 10 */
    } scenes[3] = {{&kitchen, kitchen_files, 5, 6, 9, 528},
                   {&robots, robot_files, 11, 187, 189, 14017},
                   {&museum, museum_files, 1, 1, 2, 22}};
    long evaluations = 0;
    int outside = 0;
    for (int s = 0; s < 3; s++) {
        struct k_block *blocks = NULL;
        int count = 0;
        int ok = 1;
        for (int i = 0; i < scenes[s].file_count; i++)
            ok = read_k_blocks(scenes[s].files[i], &blocks, &count) >= 0 && ok;
        if (ok) {
            int tracks = 0;
            int keys = 0;
            for (int b = 0; b < count; b++)
                for (int kind = 0; kind < 3; kind++)
                    if (blocks[b].keys[kind]) {
                        tracks++;
                        keys += blocks[b].count[kind];
                    }
            failures += !CHECKF(count == scenes[s].blocks && tracks == scenes[s].tracks &&
                      keys == scenes[s].keys,
                  "%s: %d k blocks, %d tracks, %d keys; FORMAT.md sec. 10 says %d, %d, %d",
                  scenes[s].scene->folder, count, tracks, keys, scenes[s].blocks,
                  scenes[s].tracks, scenes[s].keys);
        }
        for (int b = 0; b < count; b++) {
            struct node nd;
            node_init(&nd, &blocks[b]);
            const struct scene *sc = scenes[s].scene;
            for (int f = 0; f < sc->frames; f++) {
                double t = aff_frame_time(sc->t0, sc->t1, sc->frames, f);
                double m[16];
                aff_node_matrix(node_track(&nd, 0), node_track(&nd, 1), node_track(&nd, 2), t,
                                m);
                evaluations++;
                failures += !CHECKF(all_finite(m, 16), "%s frame %d: matrix not finite", blocks[b].name, f);
                if (nd.has[AFF_TRACK_ROT]) {
                    double q[4], r[9];
                    aff_track_eval_quat(&nd.track[AFF_TRACK_ROT], t, q);
                    aff_track_eval(&nd.track[AFF_TRACK_ROT], t, r);
                    failures += !CHECKF(orthonormal_error(r) <= 1e-12, "%s frame %d: R not orthonormal",
                          blocks[b].name, f);
                    if (!(fabs(q[0]) <= 1.0)) {
                        outside++;
                        printf("  raw squad |w| > 1: %s/%s frame %d (t=%.6f), w - 1 = %.3g\n",
                               sc->folder, blocks[b].name, f, t, fabs(q[0]) - 1.0);
                        failures += !CHECKF(strcmp(blocks[b].name, "grip_rot2") == 0 &&
                                  (f == 95 || f == 672 || f == 673 || f == 674),
                              "|w| > 1 for %s frame %d, FORMAT.md 7.6.1 lists grip_rot2 only",
                              blocks[b].name, f);
                    }
                }
            }
            node_release(&nd);
            k_block_free(&blocks[b]);
        }
        free(blocks);
    }
    failures += !CHECKF(evaluations == 154700, "%ld node evaluations, FORMAT.md says 154,700", evaluations);
    failures += !CHECKF(outside == 4, "%d evaluations with |w| > 1, FORMAT.md 7.6.1 says 4", outside);
    printf("  all animated nodes at all frames: %ld evaluations, %d clamped\n", evaluations,
           outside);
}

/* FORMAT.md sec. 7.5 example: triangle 0, vertex 0 of animart5.aff. */
static void test_tpa_museum(void)
{
    size_t size;
    char *text = read_bart_file("museum/animart5.aff", &size);
    if (!text)
        return;
    struct lexer lx = {text, text + size};
    char tok[64];
    int n = 0;
    int ok = next_token(&lx, tok, sizeof(tok)) && strcmp(tok, "tpa") == 0 && next_int(&lx, &n) &&
             n == 5;
    failures += !CHECKF(ok, "animart5.aff does not start with 'tpa 5'");
    struct aff_tpa_key keys[5];
    for (int k = 0; ok && k < n; k++) {
        ok = next_float(&lx, &keys[k].time);
        for (int v = 0; ok && v < 3; v++) {
            double x = 0.0;
            for (int c = 0; ok && c < 3; c++) {
                ok = next_float(&lx, &x);
                keys[k].p[v * 3 + c] = (float)x;
            }
            for (int c = 0; ok && c < 3; c++) {
                ok = next_float(&lx, &x);
                keys[k].n[v * 3 + c] = (float)x;
            }
        }
    }
    failures += !CHECKF(ok, "cannot read the first tpa of animart5.aff");
    free(text);
    if (!ok)
        return;
    float p[9], nn[9];
    aff_tpa_eval(keys, n, 2.5, p, nn);
    EXPECT_NEAR(p[0], 0.48094, 1e-5, "tpa 0 vertex 0 x at t=2.5");
    EXPECT_NEAR(p[1], 2.98094, 1e-5, "tpa 0 vertex 0 y at t=2.5");
    EXPECT_NEAR(p[2], 0.48094, 1e-5, "tpa 0 vertex 0 z at t=2.5");
    for (int i = 0; i < 9; i++)
        EXPECT_NEAR(nn[i], 0.5 * ((double)keys[2].n[i] + keys[3].n[i]), 1e-7, "tpa normal");
    /* The scene runs from t = -1 to 5: key 0 before 0, key 4 after 4. */
    aff_tpa_eval(keys, n, -1.0, p, nn);
    failures += !CHECKF(memcmp(p, keys[0].p, sizeof(p)) == 0 && memcmp(nn, keys[0].n, sizeof(nn)) == 0,
          "tpa before t_0");
    aff_tpa_eval(keys, n, 5.0, p, nn);
    failures += !CHECKF(memcmp(p, keys[4].p, sizeof(p)) == 0 && memcmp(nn, keys[4].n, sizeof(nn)) == 0,
          "tpa after t_4");
    aff_tpa_eval(keys, n, 3.0, p, nn);
    failures += !CHECKF(memcmp(p, keys[3].p, sizeof(p)) == 0, "tpa at t_3");
}

int main(void)
{
    printf("aff_anim:\n");
    test_catmull_rom();
    test_tcb();
    test_unequal_spacing();
    test_clamping();
    test_non_monotonic();
    test_duplicate_times();
    test_init_errors();
    test_rotation_one_axis();
    test_rotation_rewrite();
    test_rotation_non_unit_axis();
    test_rotation_conj();
    test_rotation_thresholds();
    test_rotation_clamp();
    test_visibility();
    test_frame_time();
    test_node_matrix_and_camera();
    test_fuzz();
    test_tpa_hand();
    const char *dir = bart_dir();
    printf("  BART folder: %s\n", dir ? dir : "(none)");
    test_camera_table();
    test_node_table();
    test_data_statements();
    test_all_data();
    test_tpa_museum();
    printf("aff_anim: %s (%d failures)\n", failures ? "FAIL" : "ok", failures);
    return failures ? 1 : 0;
}
