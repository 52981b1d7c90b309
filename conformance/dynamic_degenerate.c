/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dynamic_degenerate.c - zero-area triangles: left out of the wide
 * layout's leaves where no refit can give them an area, kept or put back
 * where one can.
 *
 * A triangle whose edge vectors' cross product is exactly zero in double
 * is never hit (the finish's zero-area test), so the collapse leaves it
 * out of the wide layout's packets (lib/accel/collapse4.c,
 * drop_zero_area).  A deforming object's refit moves vertices in place:
 * a triangle degenerate at one frame can have an area at the next, and
 * must then be hit.
 *
 * Part 1 (dynamic): an object of GRID_N x GRID_N separate triangles in
 * z = 0, each in its own cell, where at frame f the triangles with
 * (k + f) % 3 == 0 are collinear (the third vertex at the midpoint of the
 * first edge: exact in float and in double) and the others right
 * triangles of legs 1.  Animated by rtUpdateVertices for FRAMES frames
 * under every update strategy (a per-object hint, each run its own
 * context, threads=1, so the object is built at frame 0 and updated from
 * then on).  Per frame, one ray straight down through the point (0.25,
 * 0.25) of each cell (inside the right triangle, off the collinear
 * one's segment): rtTraceRays must hit exactly the cells' triangles that
 * have an area (primitive k, t = 1, u = v = 0.25) and miss the others,
 * and rtOccludedRays must agree.  The frames alternate which call
 * prepares them (the queries, or a render of the eye-light image, whose
 * every value must be finite).  A layout that lost a triangle
 * degenerate at frame 0 fails at frame 1 (RT_REFIT: the refit's new
 * collapse, lib/scene/accel.c scene_accel_refit, is what passes it).
 *
 * Part 2 (static): a random soup of which a third is zero-area
 * (a repeated vertex, one point three times, or three collinear points
 * on a grid of 1/64, exact in float), with rays aimed at points of the
 * proper triangles and of the degenerate ones; every closest hit judged
 * against the double-precision brute force (brute_force.h), rtOccludedRays
 * equal to "the closest hit is a hit", and no hit on a zero-area
 * triangle.
 *
 * Both parts run on the default ISA's layout (8-wide where the CPU runs
 * AVX2) and, by CMake's reruns with RT_TEST_ISA, on sse4's 4-wide layout
 * and the scalar table's binary walk.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brute_force.h"
#include "dynamic_anim.h"
#include "testutil.h"

#define GRID_N 24
#define CELLS (GRID_N * GRID_N)
#define FRAMES 7
#define OBJECT 1

#define SOUP_COUNT 3000
#define SOUP_RAYS 20000

static int degenerate_at(int k, int f)
{
    return (k + f) % 3 == 0;
}

/* Frame f's vertices: three per cell, nine floats. */
static void grid_frame(int f, float *p)
{
    for (int k = 0; k < CELLS; k++) {
        const float x = (float)(2 * (k % GRID_N)), y = (float)(2 * (k / GRID_N));
        float *v = &p[9 * k];
        v[0] = x, v[1] = y, v[2] = 0.0f;
        v[3] = x + 1.0f, v[4] = y, v[5] = 0.0f;
        if (degenerate_at(k, f))
            v[6] = x + 0.5f, v[7] = y, v[8] = 0.0f;
        else
            v[6] = x, v[7] = y + 1.0f, v[8] = 0.0f;
    }
}

static void instantiate(RTuint name)
{
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtBeginFrame();
    rtInstantiateObject(name);
}

static void camera(void)
{
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 200.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtShadingMode(RT_EYE_LIGHT);
    rtViewport(0, 0, 32, 32);
}

/* The eye-light image (32x32 RGBA float): finite everywhere. */
static void render_finite(const char *label)
{
    static float rgba[32 * 32 * 4];
    rtRenderFrame();
    rtReadPixels(0, 0, 32, 32, RT_RGBA, RT_FLOAT, rgba);
    int bad = 0;
    for (int i = 0; i < 32 * 32 * 4; i++)
        bad += !isfinite(rgba[i]);
    if (bad)
        printf("  %s: %d non-finite values in the image\n", label, bad);
    CHECK_INT(bad, 0);
}

/* One strategy: FRAMES frames, the hits checked per frame; returns the
 * number of wrong rays. */
static long run_strategy(RTenum strategy)
{
    static float pos[9 * CELLS];
    static RTray rays[CELLS];
    static RThit hits[CELLS];
    static RTboolean occluded[CELLS];
    long wrong = 0;
    RTcontext ctx = tu_make_context("threads=1");
    tu_capture_errors();
    camera();
    for (int k = 0; k < CELLS; k++) {
        RTray *r = &rays[k];
        r->org[0] = (float)(2 * (k % GRID_N)) + 0.25f;
        r->org[1] = (float)(2 * (k / GRID_N)) + 0.25f;
        r->org[2] = 1.0f;
        r->dir[0] = 0.0f, r->dir[1] = 0.0f, r->dir[2] = -1.0f;
        r->tmin = 0.0f;
        r->tmax = INFINITY;
    }
    for (int f = 0; f < FRAMES; f++) {
        grid_frame(f, pos);
        if (f == 0) {
            rtNewObject(OBJECT);
            rtBegin(RT_TRIANGLES);
            for (int v = 0; v < 3 * CELLS; v++)
                rtVertex3fv(&pos[3 * v]);
            rtEnd();
            rtEndObject();
            rtObjectParameteri(OBJECT, RT_UPDATE_STRATEGY, (RTint)strategy);
        } else {
            rtUpdateVertices(OBJECT, RT_VERTEX_ARRAY, 0, 3 * CELLS, RT_FLOAT, 0, pos);
        }
        instantiate(OBJECT);
        CHECK_NO_ERR();
        char label[96];
        snprintf(label, sizeof label, "%s, frame %d", da_strategy_name(strategy), f);
        if (f % 2)
            render_finite(label);
        rtTraceRays(CELLS, rays, hits);
        rtOccludedRays(CELLS, rays, occluded);
        if (f % 2 == 0)
            render_finite(label);
        CHECK_NO_ERR();
        long bad = 0;
        for (int k = 0; k < CELLS; k++) {
            const RThit *h = &hits[k];
            const int ok = degenerate_at(k, f)
                               ? h->t == INFINITY && h->primitive == RT_INVALID_ID && !occluded[k]
                               : h->t == 1.0f && h->primitive == (RTuint)k && h->u == 0.25f &&
                                     h->v == 0.25f && occluded[k];
            if (!ok && bad < 4)
                printf("  %s: cell %d (%s): t=%.9g primitive %u u=%.9g v=%.9g occluded %d\n",
                       label, k, degenerate_at(k, f) ? "zero area" : "an area", h->t,
                       h->primitive, h->u, h->v, (int)occluded[k]);
            bad += !ok;
        }
        CHECK_INT(bad, 0);
        wrong += bad;
    }
    tu_destroy_context(ctx);
    return wrong;
}

/* A grid coordinate in [-4, 4], a multiple of 1/64: differences and
 * doublings below are exact in float. */
static float grid(struct bf_rng *r)
{
    return (float)((int)bf_below(r, 513) - 256) / 64.0f;
}

static int zero_area(const float *v)
{
    double e1[3], e2[3], n[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = (double)v[3 + k] - v[k];
        e2[k] = (double)v[6 + k] - v[k];
    }
    bf_cross(n, e1, e2);
    return n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0;
}

static void static_soup(void)
{
    static float pos[9 * SOUP_COUNT];
    static RTray rays[SOUP_RAYS];
    static RThit hits[SOUP_RAYS];
    static RTboolean occluded[SOUP_RAYS];
    struct bf_rng r;
    bf_seed(&r, 77u);
    int zero = 0;
    for (int t = 0; t < SOUP_COUNT; t++) {
        float *v = &pos[9 * t];
        const float c[3] = {grid(&r), grid(&r), grid(&r)};
        for (int k = 0; k < 9; k++)
            v[k] = c[k % 3] + (float)((int)bf_below(&r, 33) - 16) / 64.0f;
        switch (t % 6) {
        case 0: /* a repeated vertex */
            memcpy(&v[6], &v[3], 3 * sizeof(float));
            break;
        case 1: /* one point three times */
            memcpy(&v[3], &v[0], 3 * sizeof(float));
            memcpy(&v[6], &v[0], 3 * sizeof(float));
            break;
        case 2: /* collinear: v2 = v0 + 2 (v1 - v0) */
            for (int k = 0; k < 3; k++)
                v[6 + k] = v[k] + 2.0f * (v[3 + k] - v[k]);
            break;
        default:
            break;
        }
        zero += zero_area(v);
    }
    printf("static soup: %d triangles, %d of zero area\n", SOUP_COUNT, zero);
    CHECK(zero >= SOUP_COUNT / 2 - 10);

    for (int i = 0; i < SOUP_RAYS; i++) {
        /* Aimed at a point of a random triangle (b0, b1, b2 >= 0), from a
         * random origin outside the soup. */
        const float *v = &pos[9 * bf_below(&r, SOUP_COUNT)];
        double b1 = bf_uniform(&r), b2 = bf_uniform(&r);
        if (b1 + b2 > 1.0)
            b1 = 1.0 - b1, b2 = 1.0 - b2;
        double dir[3];
        bf_unit_vector(&r, dir);
        RTray *ray = &rays[i];
        for (int k = 0; k < 3; k++) {
            const double p = v[k] + b1 * (v[3 + k] - v[k]) + b2 * (v[6 + k] - v[k]);
            ray->org[k] = (float)(p - 12.0 * dir[k]);
            ray->dir[k] = (float)dir[k];
        }
        ray->tmin = 0.0f;
        ray->tmax = INFINITY;
    }

    RTcontext ctx = tu_make_context("threads=1");
    tu_capture_errors();
    rtNewObject(OBJECT);
    rtBegin(RT_TRIANGLES);
    for (int k = 0; k < 3 * SOUP_COUNT; k++)
        rtVertex3fv(&pos[3 * k]);
    rtEnd();
    rtEndObject();
    instantiate(OBJECT);
    rtTraceRays(SOUP_RAYS, rays, hits);
    rtOccludedRays(SOUP_RAYS, rays, occluded);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);

    struct bf_scene scene;
    memset(&scene, 0, sizeof scene);
    double m[16];
    bf_identity(m);
    bf_scene_add_instance(&scene, pos, SOUP_COUNT, m, OBJECT);
    const struct bf_tolerance tol = {1e-5, 1e-5};
    struct bf_stats stats = {0, 0, 0, 0, 0, 0.0};
    long bad = 0, on_zero = 0, occlusion = 0;
    for (int i = 0; i < SOUP_RAYS; i++) {
        char why[256];
        if (!bf_check_hit(&scene, &rays[i], &hits[i], &tol, &stats, why, sizeof why)) {
            if (bad < 5)
                printf("  ray %d: %s\n", i, why);
            bad++;
        }
        if (hits[i].t < INFINITY && hits[i].primitive < SOUP_COUNT)
            on_zero += zero_area(&pos[9 * hits[i].primitive]);
        occlusion += (occluded[i] != 0) != (hits[i].t < INFINITY);
    }
    printf("static soup: %ld rays, %ld hits, %ld exact, %ld tolerated, %ld wrong, %ld on a "
           "zero-area triangle, %ld occlusion mismatches\n",
           stats.rays, stats.hits, stats.exact, stats.tolerated, bad, on_zero, occlusion);
    CHECK_INT(bad, 0);
    CHECK_INT(on_zero, 0);
    CHECK_INT(occlusion, 0);
    CHECK(stats.hits > SOUP_RAYS / 4);
    bf_scene_free(&scene);
}

int main(void)
{
    for (int s = 0; s < DA_STRATEGY_COUNT; s++) {
        tu_section(da_strategy_name(da_strategies[s]));
        long wrong = run_strategy(da_strategies[s]);
        if (wrong)
            printf("  %ld wrong rays\n", wrong);
    }
    tu_section("static soup against the brute force");
    static_soup();
    return test_summary("dynamic_degenerate");
}
