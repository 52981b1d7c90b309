/* SPDX-License-Identifier: Apache-2.0 */
/*
 * stability_coincident.c - 100k identical triangles in one object.
 *
 * Every primitive box and centroid is the same, so no SAH split separates
 * anything: a builder must fall back to splitting by count and stay within
 * its depth limit.  For the binned builder and the sweep builder:
 *   - the lazy build, triggered by one rtTraceRays ray, completes within
 *     10 s (a hang guard only, not a performance claim: the time is printed);
 *   - RT_OBJECT_BUILT becomes RT_TRUE, RT_OBJECT_BVH_NODES is between n / 8
 *     (leaves stay small) and 2n - 1 (a binary tree over n primitives) and
 *     RT_OBJECT_SAH_COST is finite and positive;
 *   - rays aimed at known barycentrics report t exactly, the pinned u, v, a
 *     primitive in [0, n), and rtOccludedRays agrees; a ray beside the
 *     triangle and one with tmax before it miss;
 *   - a small eye-light frame shows the triangle where it is.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "testutil.h"

#define COUNT 100000
#define OBJECT 1
#define HANG_GUARD_MS 10000.0

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

static const float a[3] = {-1.0f, -1.0f, 0.0f}, b[3] = {1.0f, -1.0f, 0.0f},
                   c[3] = {0.0f, 1.0f, 0.0f};

static void run(const char *config)
{
    tu_section(config);
    RTcontext ctx = tu_make_context(config);
    rtNewObject(OBJECT);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < COUNT; i++) {
        rtVertex3fv(a);
        rtVertex3fv(b);
        rtVertex3fv(c);
    }
    rtEnd();
    rtEndObject();
    CHECK_INT(tu_object_triangles(OBJECT), COUNT);
    RTint built = -1;
    rtGetObjectiv(OBJECT, RT_OBJECT_BUILT, &built);
    CHECK_INT(built, RT_FALSE);
    rtBeginFrame();
    rtInstantiateObject(OBJECT);
    CHECK_NO_ERR();

    /* The first ray builds the object. */
    const float u = TU_PIN_U, v = TU_PIN_V;
    float target[3];
    for (int k = 0; k < 3; k++)
        target[k] = (1.0f - u - v) * a[k] + u * b[k] + v * c[k];
    double start = now_ms();
    RThit h = tu_trace(target[0], target[1], 2.0f, 0.0f, 0.0f, -1.0f);
    double ms = now_ms() - start;
    CHECK_NO_ERR();
    printf("   first ray (build included) took %.1f ms\n", ms);
    CHECK(ms < HANG_GUARD_MS);
    rtGetObjectiv(OBJECT, RT_OBJECT_BUILT, &built);
    CHECK_INT(built, RT_TRUE);
    RTint nodes = -1;
    rtGetObjectiv(OBJECT, RT_OBJECT_BVH_NODES, &nodes);
    RTfloat cost = -1.0f;
    rtGetObjectfv(OBJECT, RT_OBJECT_SAH_COST, &cost);
    printf("   %d BVH nodes, SAH cost %g\n", nodes, cost);
    /* At most 2n - 1 nodes in a binary tree over n primitives; at least
     * n / 8, i.e. leaves of 16 triangles or fewer on average (the builders
     * cap leaves at 8): identical boxes must not end in one huge leaf. */
    CHECK(nodes >= COUNT / 8 && nodes <= 2 * COUNT - 1);
    CHECK(isfinite(cost) && cost > 0.0f);
    CHECK_NO_ERR();

    CHECK_NEAR(h.t, 2.0, 0.0);
    CHECK(h.primitive < COUNT);
    CHECK_INT(h.object, OBJECT);
    CHECK_INT(h.instance, 0);
    CHECK_NEAR(h.u, u, 1e-6);
    CHECK_NEAR(h.v, v, 1e-6);
    CHECK_INT(tu_occluded(target[0], target[1], 2.0f, 0.0f, 0.0f, -1.0f), RT_TRUE);

    /* From the other side, obliquely, and with scaled directions. */
    RThit back = tu_trace(target[0], target[1], -3.0f, 0.0f, 0.0f, 0.5f);
    CHECK_NEAR(back.t, 6.0, 0.0);
    CHECK(back.primitive < COUNT);
    RThit oblique = tu_trace(target[0] - 1.0f, target[1] + 0.5f, 1.0f, 1.0f, -0.5f, -1.0f);
    CHECK_NEAR(oblique.t, 1.0, 1e-6);
    CHECK_NEAR(oblique.u, u, 1e-5);
    CHECK_NEAR(oblique.v, v, 1e-5);

    /* Misses: beside the triangle, and tmax before it. */
    RThit beside = tu_trace(1.5f, 1.5f, 2.0f, 0.0f, 0.0f, -1.0f);
    CHECK(beside.t == INFINITY && beside.primitive == RT_INVALID_ID);
    RTray r = tu_ray(target[0], target[1], 2.0f, 0.0f, 0.0f, -1.0f);
    r.tmax = 2.0f;
    RThit before;
    rtTraceRays(1, &r, &before);
    CHECK(before.t == INFINITY);
    RTboolean occluded = 7;
    rtOccludedRays(1, &r, &occluded);
    CHECK_INT(occluded, RT_FALSE);
    CHECK_NO_ERR();

    /* A 16x16 frame through an orthographic camera over [-1,1]^2: the
     * pixel centres inside the triangle show it, the others the clear
     * colour (alpha tells them apart). */
    tu_ortho_camera();
    rtTranslatef(0.0f, 0.0f, -5.0f);
    rtBeginFrame();
    rtInstantiateObject(OBJECT);
    rtLoadIdentity();
    float rgba[16 * 16 * 4];
    tu_render_float(16, 16, rgba);
    CHECK_NO_ERR();
    int wrong = 0;
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            double px = -1.0 + (x + 0.5) / 8.0, py = -1.0 + (y + 0.5) / 8.0;
            /* Inside: above y = -1 and below the two slanted edges. */
            int inside = py > -1.0 && py < 1.0 - 2.0 * fabs(px);
            int shown = rgba[4 * (y * 16 + x) + 3] == 1.0f;
            wrong += inside != shown;
        }
    CHECK_INT(wrong, 0);
    tu_destroy_context(ctx);
}

int main(void)
{
    run("builder=binned");
    run("builder=sweep");
    run("builder=binned bins=2");
    return test_summary("stability_coincident");
}
