/* SPDX-License-Identifier: Apache-2.0 */
/*
 * queries.c - conformance: rtTraceRays and rtOccludedRays.  Argument and
 * per-ray validation (nothing written on error), the RThit conventions
 * (miss values, t in units of dir, closest hit, both faces, u/v), the
 * [tmin, tmax) interval at its exact ends, watertightness on shared edges
 * and vertices, statistics, and identical hits across thread counts and
 * builders.
 *
 * Reference: docs/queries.md.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define QUAD 600u
#define BOX 601u
#define GRIDOBJ 602u

static RTint geti(RTenum pname)
{
    RTint v = -12345;
    rtGetIntegerv(pname, &v);
    return v;
}

static void fill_sentinel(RThit *h, int n)
{
    int k;
    for (k = 0; k < n; k++) {
        h[k].t = -3.0f;
        h[k].u = h[k].v = -3.0f;
        h[k].instance = h[k].object = h[k].primitive = 777u;
    }
}

static int untouched(const RThit *h, int n)
{
    int k;
    for (k = 0; k < n; k++)
        if (h[k].t != -3.0f || h[k].u != -3.0f || h[k].v != -3.0f || h[k].instance != 777u ||
            h[k].object != 777u || h[k].primitive != 777u)
            return 0;
    return 1;
}

static void argument_errors(void)
{
    RTray r[3];
    RThit h[3];
    RTboolean o[3];
    tu_section("argument errors write nothing");
    r[0] = tu_ray(0.5f, 0.5f, 5, 0, 0, -1);
    r[1] = tu_ray(0.25f, 0.25f, 5, 0, 0, -1);
    r[2] = tu_ray(0.75f, 0.25f, 5, 0, 0, -1);
    fill_sentinel(h, 3);
    memset(o, 9, sizeof o);
    rtTraceRays(-1, r, h);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTraceRays(3, NULL, h);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTraceRays(3, r, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtOccludedRays(-1, r, o);
    CHECK_ERR(RT_INVALID_VALUE);
    rtOccludedRays(3, NULL, o);
    CHECK_ERR(RT_INVALID_VALUE);
    rtOccludedRays(3, r, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTraceRays(0, NULL, NULL);
    rtOccludedRays(0, NULL, NULL);
    CHECK_NO_ERR();
    /* Inside an object or rtBegin. */
    rtNewObject(BOX + 10);
    rtTraceRays(3, r, h);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtOccludedRays(3, r, o);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtBegin(RT_TRIANGLES);
    rtTraceRays(3, r, h);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtOccludedRays(3, r, o);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    rtEndObject();
    CHECK(untouched(h, 3));
    CHECK(o[0] == 9 && o[1] == 9 && o[2] == 9);

    tu_section("one bad ray: RT_INVALID_VALUE, nothing written");
    {
        /* field: 0 org, 1 dir, 2 tmin, 3 tmax; kind: the bad value. */
        enum { NAN_V, POS_INF, NEG_INF, ZERO, TINY_NEGATIVE };
        static const struct {
            const char *what;
            int field, comp, kind;
        } bad[] = {{"NaN origin", 0, 1, NAN_V},       {"infinite origin", 0, 2, POS_INF},
                   {"NaN direction", 1, 0, NAN_V},    {"infinite direction", 1, 2, NEG_INF},
                   {"zero direction", 1, 2, ZERO},    {"NaN tmin", 2, 0, NAN_V},
                   {"negative tmin", 2, 0, TINY_NEGATIVE}, {"-inf tmin", 2, 0, NEG_INF},
                   {"NaN tmax", 3, 0, NAN_V}};
        const int n = (int)(sizeof bad / sizeof bad[0]);
        int i;
        for (i = 0; i < n; i++) {
            RTray rr[3];
            float value = bad[i].kind == NAN_V     ? tu_nan()
                          : bad[i].kind == POS_INF ? tu_inf()
                          : bad[i].kind == NEG_INF ? -tu_inf()
                          : bad[i].kind == ZERO    ? 0.0f
                                                   : -1e-30f;
            memcpy(rr, r, sizeof rr);
            switch (bad[i].field) {
            case 0:
                rr[2].org[bad[i].comp] = value;
                break;
            case 1:
                rr[2].dir[bad[i].comp] = value;
                break;
            case 2:
                rr[2].tmin = value;
                break;
            default:
                rr[2].tmax = value;
                break;
            }
            fill_sentinel(h, 3);
            memset(o, 9, sizeof o);
            tu_reset_captured();
            rtTraceRays(3, rr, h);
            if (!CHECK_ERR(RT_INVALID_VALUE) || !CHECK(untouched(h, 3)))
                fprintf(stderr, "    rtTraceRays with a %s\n", bad[i].what);
            CHECK_MSG("rtTraceRays");
            rtOccludedRays(3, rr, o);
            if (!CHECK_ERR(RT_INVALID_VALUE) || !CHECK(o[0] == 9 && o[1] == 9 && o[2] == 9))
                fprintf(stderr, "    rtOccludedRays with a %s\n", bad[i].what);
            CHECK_MSG("rtOccludedRays");
        }
    }
}

static void conventions(void)
{
    RThit h;
    RTray r;
    static const float lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    tu_section("miss, closest hit, both faces, t in units of dir");
    /* Empty scene: everything misses. */
    rtBeginFrame();
    rtFinish();
    h = tu_trace(0, 0, 5, 0, 0, -1);
    CHECK(h.t == tu_inf() && h.t > 0);
    CHECK(h.u == 0.0f && h.v == 0.0f);
    CHECK(h.instance == RT_INVALID_ID && h.object == RT_INVALID_ID &&
          h.primitive == RT_INVALID_ID);
    CHECK_INT(tu_occluded(0, 0, 5, 0, 0, -1), RT_FALSE);

    CHECK(tu_define_box(BOX, lo, hi));
    CHECK(tu_scene1(BOX));
    /* From outside: the near face; dir length 2 halves t. */
    h = tu_trace(0.1f, 0.2f, 5, 0, 0, -1);
    CHECK_NEAR(h.t, 4, 1e-6);
    CHECK_INT(h.object, BOX);
    CHECK_INT(h.instance, 0);
    CHECK(h.primitive < 12);
    h = tu_trace(0.1f, 0.2f, 5, 0, 0, -2);
    CHECK_NEAR(h.t, 2, 1e-6);
    h = tu_trace(0.1f, 0.2f, 5, 0, 0, -0.25f);
    CHECK_NEAR(h.t, 16, 1e-5);
    /* From inside: the far face (no back-face culling). */
    h = tu_trace(0.1f, 0.2f, 0, 0, 0, -1);
    CHECK_NEAR(h.t, 1, 1e-6);
    CHECK_INT(h.object, BOX);
    /* Diagonal. */
    h = tu_trace(-5, 0.1f, 0.2f, 1, 0, 0);
    CHECK_NEAR(h.t, 4, 1e-6);
    h = tu_trace(5, 4.9f, 4.8f, -1, -1, -1); /* enters the face x = 1 at (1, 0.9, 0.8) */
    CHECK_NEAR(h.t, 4, 1e-5);
    /* Missing to the side. */
    h = tu_trace(1.5f, 0, 5, 0, 0, -1);
    CHECK(h.t == tu_inf());
    CHECK(h.primitive == RT_INVALID_ID);
    CHECK_INT(tu_occluded(1.5f, 0, 5, 0, 0, -1), RT_FALSE);
    CHECK_INT(tu_occluded(0.5f, 0, 5, 0, 0, -1), RT_TRUE);
    /* Pointing away. */
    h = tu_trace(0, 0, 5, 0, 0, 1);
    CHECK(h.t == tu_inf());

    /* Closest of three stacked quads; the order of instantiation does not matter. */
    CHECK(tu_define_quad(QUAD, 0, 0, 1, 1, 0));
    rtBeginFrame();
    rtPushMatrix();
    rtTranslatef(0, 0, -1);
    rtInstantiateObject(QUAD);
    rtTranslatef(0, 0, 2);
    rtInstantiateObject(QUAD);
    rtTranslatef(0, 0, -1);
    rtInstantiateObject(QUAD);
    rtPopMatrix();
    rtFinish();
    h = tu_trace(0.5f, 0.5f, 5, 0, 0, -1);
    CHECK_NEAR(h.t, 4, 1e-6);
    CHECK_INT(h.instance, 1);
    h = tu_trace(0.5f, 0.5f, -5, 0, 0, 1);
    CHECK_NEAR(h.t, 4, 1e-6);
    CHECK_INT(h.instance, 0);
    r = tu_ray(0.5f, 0.5f, 5, 0, 0, -1);
    r.tmin = 4.5f; /* skips the first */
    rtTraceRays(1, &r, &h);
    CHECK_NEAR(h.t, 5, 1e-6);
    CHECK_INT(h.instance, 2);
    CHECK_NO_ERR();
}

static void interval_ends(void)
{
    /* Exact arithmetic: triangle (0,0,0) (4,0,0) (0,4,0), ray from z = 5 at
     * (1, 1) straight down: t = 5 exactly, u = v = 0.25 exactly. */
    static const float a[3] = {0, 0, 0}, b[3] = {4, 0, 0}, c[3] = {0, 4, 0};
    RTray r;
    RThit h;
    RTboolean o;
    tu_section("hits count for tmin <= t < tmax");
    CHECK(tu_define_triangle(QUAD, a, b, c));
    CHECK(tu_scene1(QUAD));
    r = tu_ray(1, 1, 5, 0, 0, -1);
    rtTraceRays(1, &r, &h);
    CHECK(h.t == 5.0f);
    CHECK(h.u == 0.25f && h.v == 0.25f);
    CHECK_INT(h.primitive, 0);
    /* tmax == t: a miss. */
    r.tmax = 5.0f;
    rtTraceRays(1, &r, &h);
    CHECK(h.t == tu_inf());
    CHECK(h.primitive == RT_INVALID_ID);
    rtOccludedRays(1, &r, &o);
    CHECK_INT(o, RT_FALSE);
    /* tmax just above t: a hit. */
    r.tmax = nextafterf(5.0f, 6.0f);
    rtTraceRays(1, &r, &h);
    CHECK(h.t == 5.0f);
    rtOccludedRays(1, &r, &o);
    CHECK_INT(o, RT_TRUE);
    /* tmin == t: a hit; tmin just above: a miss. */
    r.tmax = tu_inf();
    r.tmin = 5.0f;
    rtTraceRays(1, &r, &h);
    CHECK(h.t == 5.0f);
    rtOccludedRays(1, &r, &o);
    CHECK_INT(o, RT_TRUE);
    r.tmin = nextafterf(5.0f, 6.0f);
    rtTraceRays(1, &r, &h);
    CHECK(h.t == tu_inf());
    rtOccludedRays(1, &r, &o);
    CHECK_INT(o, RT_FALSE);
    /* tmin > tmax: a miss, not an error; also with tmin = +inf. */
    r.tmin = 3;
    r.tmax = 2;
    rtTraceRays(1, &r, &h);
    CHECK(h.t == tu_inf());
    r.tmin = tu_inf();
    r.tmax = tu_inf();
    rtTraceRays(1, &r, &h);
    CHECK(h.t == tu_inf());
    r.tmin = 0;
    r.tmax = -tu_inf();
    rtTraceRays(1, &r, &h);
    CHECK(h.t == tu_inf());
    CHECK_NO_ERR();
    /* The barycentric convention: p = (1-u-v) v0 + u v1 + v v2. */
    r = tu_ray(3, 0.5f, 5, 0, 0, -1); /* near v1 */
    rtTraceRays(1, &r, &h);
    CHECK_NEAR(h.u, 0.75, 1e-6);
    CHECK_NEAR(h.v, 0.125, 1e-6);
    CHECK_TRIANGLE(a, b, c, 0, QUAD, 0);
}

static void watertight(void)
{
    RTray *rays;
    RThit *hits;
    RTboolean *occ;
    int n = 0, i, j, missed = 0, occ_missed = 0;
    tu_section("watertight: rays through shared edges and vertices hit");
    /* 16 x 16 cells over [0, 16]^2: edges at integers. */
    CHECK(tu_define_grid(GRIDOBJ, 16, 16, 0, 0, 16, 16, 0));
    CHECK(tu_scene1(GRIDOBJ));
    rays = (RTray *)malloc(sizeof(RTray) * 33 * 33 * 2);
    hits = (RThit *)malloc(sizeof(RThit) * 33 * 33 * 2);
    occ = (RTboolean *)malloc(sizeof(RTboolean) * 33 * 33 * 2);
    for (j = 0; j < 33; j++) {
        for (i = 0; i < 33; i++) {
            float x = 0.5f * (float)i, y = 0.5f * (float)j;
            if (x <= 0 || y <= 0 || x >= 16 || y >= 16)
                continue; /* the outer border is allowed to go either way */
            rays[n++] = tu_ray(x, y, 3, 0, 0, -1);
            /* Oblique rays through the same point. */
            rays[n++] = tu_ray(x - 0.3f, y - 0.7f, 1, 0.3f, 0.7f, -1);
        }
    }
    rtTraceRays(n, rays, hits);
    rtOccludedRays(n, rays, occ);
    CHECK_NO_ERR();
    for (i = 0; i < n; i++) {
        if (hits[i].primitive == RT_INVALID_ID)
            missed++;
        else if (i % 2 == 0)
            CHECK_NEAR(hits[i].t, 3, 1e-5);
        else
            CHECK_NEAR(hits[i].t, 1, 1e-5);
        if (occ[i] != RT_TRUE)
            occ_missed++;
    }
    CHECK_INT(missed, 0);
    CHECK_INT(occ_missed, 0);
    CHECK_INT(geti(RT_STAT_RAYS), n);
    free(rays);
    free(hits);
    free(occ);
}

static void statistics(void)
{
    RTray r[10];
    RThit h[10];
    RTboolean o[10];
    int k;
    tu_section("query statistics");
    CHECK(tu_define_grid(GRIDOBJ, 4, 4, 0, 0, 1, 1, 0));
    CHECK(tu_scene1(GRIDOBJ));
    for (k = 0; k < 10; k++)
        r[k] = tu_ray(0.05f + 0.09f * (float)k, 0.5f, 1, 0, 0, -1);
    rtTraceRays(10, r, h);
    CHECK_INT(geti(RT_STAT_RAYS), 10);
    CHECK(geti(RT_STAT_NODE_TESTS) > 0);
    CHECK(geti(RT_STAT_TRIANGLE_TESTS) >= 10);
    CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 1); /* the grid, lazily, on first use */
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);
    rtOccludedRays(7, r, o);
    CHECK_INT(geti(RT_STAT_RAYS), 7);
    CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 0);
    rtTraceRays(0, NULL, NULL);
    CHECK_INT(geti(RT_STAT_RAYS), 0);
    /* A failing call does not replace the statistics. */
    rtTraceRays(3, r, h);
    rtTraceRays(-1, r, h);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(geti(RT_STAT_RAYS), 3);
}

/* ---- identical hits across configurations ------------------------------------------ */

#define NRAYS 4096

static unsigned lcg(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

static float frand(unsigned *s)
{
    return (float)lcg(s) / 16777216.0f;
}

static void run_config(const char *config, RTray *rays, RThit *hits, RTboolean *occ)
{
    RTcontext previous = rtGetCurrentContext();
    RTcontext ctx = tu_make_context(config);
    unsigned seed = 99u;
    int k;
    tu_capture_errors();
    /* 2000 random triangles in [-2, 2]^3, instanced three times. */
    rtNewObject(BOX);
    rtBegin(RT_TRIANGLES);
    for (k = 0; k < 2000; k++) {
        float cx = 4 * frand(&seed) - 2, cy = 4 * frand(&seed) - 2, cz = 4 * frand(&seed) - 2;
        int v;
        for (v = 0; v < 3; v++)
            rtVertex3f(cx + 0.4f * frand(&seed) - 0.2f, cy + 0.4f * frand(&seed) - 0.2f,
                       cz + 0.4f * frand(&seed) - 0.2f);
    }
    rtEnd();
    rtEndObject();
    rtBeginFrame();
    rtInstantiateObject(BOX);
    rtPushMatrix();
    rtTranslatef(3, 0, 0);
    rtRotatef(30, 1, 1, 0);
    rtInstantiateObject(BOX);
    rtPopMatrix();
    rtPushMatrix();
    rtTranslatef(-3, 1, -1);
    rtScalef(0.5f, 2, 1);
    rtInstantiateObject(BOX);
    rtPopMatrix();
    rtFinish();
    rtTraceRays(NRAYS, rays, hits);
    rtOccludedRays(NRAYS, rays, occ);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
    rtMakeCurrent(previous);
}

static void configurations(void)
{
    static const char *const configs[] = {"threads=4",          "threads=2 builder=sweep",
                                          "threads=1 bins=2",   "threads=3 bins=256",
                                          "threads=8 bins=5 builder=binned"};
    RTray *rays = (RTray *)malloc(sizeof(RTray) * NRAYS);
    RThit *ref = (RThit *)malloc(sizeof(RThit) * NRAYS);
    RThit *hits = (RThit *)malloc(sizeof(RThit) * NRAYS);
    RTboolean *ref_occ = (RTboolean *)malloc(NRAYS);
    RTboolean *occ = (RTboolean *)malloc(NRAYS);
    unsigned seed = 7u;
    size_t c;
    int k, hit_count = 0, consistent = 1;
    tu_section("identical hits across thread counts and builders");
    for (k = 0; k < NRAYS; k++) {
        float ox = 12 * frand(&seed) - 6, oy = 8 * frand(&seed) - 4, oz = 8;
        float tx = 10 * frand(&seed) - 5, ty = 6 * frand(&seed) - 3, tz = -2 * frand(&seed);
        rays[k] = tu_ray(ox, oy, oz, tx - ox, ty - oy, tz - oz);
        rays[k].tmin = (k % 7 == 0) ? 0.3f : 0.0f;
        rays[k].tmax = (k % 5 == 0) ? 1.0f : tu_inf();
    }
    run_config("threads=1", rays, ref, ref_occ);
    for (k = 0; k < NRAYS; k++) {
        if (ref[k].primitive != RT_INVALID_ID)
            hit_count++;
        /* occluded agrees with trace */
        if ((ref[k].primitive != RT_INVALID_ID) != (ref_occ[k] == RT_TRUE))
            consistent = 0;
    }
    CHECK(hit_count > NRAYS / 10);
    CHECK(consistent);
    for (c = 0; c < sizeof configs / sizeof configs[0]; c++) {
        int diff = -1;
        run_config(configs[c], rays, hits, occ);
        for (k = 0; k < NRAYS; k++) {
            if (memcmp(&ref[k], &hits[k], sizeof(RThit)) != 0 || ref_occ[k] != occ[k]) {
                diff = k;
                break;
            }
        }
        if (!tu_check(diff < 0, __FILE__, __LINE__, "hits identical to threads=1"))
            fprintf(stderr,
                    "    \"%s\", ray %d: prim %u inst %u t %.9g u %.9g v %.9g vs reference prim %u "
                    "inst %u t %.9g u %.9g v %.9g\n",
                    configs[c], diff, hits[diff].primitive, hits[diff].instance, hits[diff].t,
                    hits[diff].u, hits[diff].v, ref[diff].primitive, ref[diff].instance,
                    ref[diff].t, ref[diff].u, ref[diff].v);
    }
    free(rays);
    free(ref);
    free(hits);
    free(ref_occ);
    free(occ);
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    argument_errors();
    conventions();
    interval_ends();
    watertight();
    statistics();
    configurations();
    tu_destroy_context(ctx);
    return test_summary("queries");
}
