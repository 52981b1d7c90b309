/* SPDX-License-Identifier: Apache-2.0 */
/*
 * stream_queries.c - conformance: rtTraceRays and rtOccludedRays give the
 * same answers and the same statistics with the stream walk on and off
 * (stream=on|off, docs/context.md; lib/trace/scene_stream.h).  With
 * stream=on a query's rays that do not go as packets walk through the
 * table's stream walk (several rays in flight, each with its own limit)
 * wherever the scene's top level is one leaf of plain instances; with
 * stream=off each ray walks alone.  Every RThit field must be the same
 * bit for bit, every occlusion flag the same, and RT_STAT_RAYS,
 * RT_STAT_NODE_TESTS, RT_STAT_TRIANGLE_TESTS and RT_STAT_INSTANCE_TESTS
 * the same after each call.
 *
 * Scene: a soup of SOUP_TRIS random triangles in [-1, 1]^3 (many leaves),
 * instanced four times, all boxes centred on the origin so that the
 * top-level builder keeps them in one leaf: the identity (instance 0), a
 * rotation about z by 30 degrees (instance 1, the transformed ray's
 * floats), the identity again (instance 2: coincident with 0, every hit
 * a tie at equal t, which instance 0 must win) and the rotation again
 * (instance 3, a tie with 1).  Rays: random origins and directions, some
 * with tmin > 0, some with a short tmax, some with -0.0 or 0.0
 * components (the single-ray walk's other paths), and aligned groups of
 * eight parallel rays (packets with packets=on, the runs between them
 * through the stream).  Under isa=avx2 and under the context's default
 * table (the AVX-512 table's stream is the AVX2 one, whose node tests
 * are isect_box's where that table's own single walk takes a fused test
 * that visits a few more nodes: the counts are compared under isa=avx2,
 * the answers under both).
 *
 * Reference: docs/queries.md, docs/context.md, docs/statistics.md.
 */
#include "testutil.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define SOUP 700u
#define SOUP_TRIS 3000
#define RAYS 4096

static uint32_t lcg(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

/* Uniform in [lo, hi). */
static float uniform(uint32_t *s, float lo, float hi)
{
    return lo + (hi - lo) * (float)lcg(s) / 16777216.0f;
}

static void define_soup(void)
{
    uint32_t s = 12345u;
    rtNewObject(SOUP);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < SOUP_TRIS; i++) {
        float c[3];
        for (int k = 0; k < 3; k++)
            c[k] = uniform(&s, -0.95f, 0.95f);
        for (int v = 0; v < 3; v++)
            rtVertex3f(c[0] + uniform(&s, -0.15f, 0.15f), c[1] + uniform(&s, -0.15f, 0.15f),
                       c[2] + uniform(&s, -0.15f, 0.15f));
    }
    rtEnd();
    rtEndObject();
}

static void build_scene(void)
{
    define_soup();
    rtBeginFrame();
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtInstantiateObject(SOUP); /* 0: identity */
    rtPushMatrix();
    rtRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    rtInstantiateObject(SOUP); /* 1: transformed */
    rtPopMatrix();
    rtInstantiateObject(SOUP); /* 2: coincident with 0 */
    rtPushMatrix();
    rtRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    rtInstantiateObject(SOUP); /* 3: coincident with 1 */
    rtPopMatrix();
    rtFinish();
}

static void make_rays(RTray *rays, int n)
{
    uint32_t s = 777u;
    for (int i = 0; i < n; i++) {
        RTray *r = &rays[i];
        for (int k = 0; k < 3; k++) {
            r->org[k] = uniform(&s, -1.5f, 1.5f);
            r->dir[k] = uniform(&s, -1.0f, 1.0f);
        }
        r->tmin = 0.0f;
        r->tmax = INFINITY;
        switch (i % 7) {
        case 1:
            r->tmin = uniform(&s, 0.0f, 0.5f); /* tmin > 0 */
            break;
        case 2:
            r->tmax = uniform(&s, 0.05f, 0.6f); /* short */
            break;
        case 3:
            r->org[1] = -0.0f; /* not the plain class: the world set-up */
            break;
        case 4:
            r->dir[2] = 0.0f; /* a +0.0 direction component */
            break;
        default:
            break;
        }
    }
    /* Aligned groups of eight parallel rays (packets where packets=on). */
    for (int g = 0; g + 8 <= n; g += 64)
        for (int j = 0; j < 8; j++) {
            RTray *r = &rays[g + j];
            r->org[0] = -1.5f;
            r->org[1] = -0.5f + 0.1f * (float)j;
            r->org[2] = 0.25f;
            r->dir[0] = 1.0f;
            r->dir[1] = 0.01f;
            r->dir[2] = -0.02f;
            r->tmin = 0.0f;
            r->tmax = INFINITY;
        }
}

struct answers {
    RThit hits[RAYS];
    RTboolean occluded[RAYS];
    RTint stats_trace[4];
    RTint stats_occluded[4];
    int hit_count;
};

static void read_stats(RTint out[4])
{
    static const RTenum names[4] = {RT_STAT_RAYS, RT_STAT_NODE_TESTS, RT_STAT_TRIANGLE_TESTS,
                                    RT_STAT_INSTANCE_TESTS};
    for (int k = 0; k < 4; k++) {
        out[k] = -1;
        rtGetIntegerv(names[k], &out[k]);
    }
}

static void run(const char *config, const RTray *rays, struct answers *a)
{
    RTcontext ctx = tu_make_context(config);
    build_scene();
    /* The objects are built on demand by the first trace: one warm-up
     * query, so that the statistics compared are the walk's alone. */
    RThit warm;
    rtTraceRays(1, rays, &warm);
    rtTraceRays(RAYS, rays, a->hits);
    read_stats(a->stats_trace);
    rtOccludedRays(RAYS, rays, a->occluded);
    read_stats(a->stats_occluded);
    CHECK_NO_ERR();
    a->hit_count = 0;
    for (int i = 0; i < RAYS; i++)
        a->hit_count += a->hits[i].instance != RT_INVALID_ID;
    tu_destroy_context(ctx);
}

static struct answers on_answers, off_answers;
static RTray query_rays[RAYS];

static void compare(const char *isa, int counts)
{
    char on_config[96], off_config[96];
    const char *isa_item = isa ? " isa=" : "";
    snprintf(on_config, sizeof(on_config), "threads=2 stream=on%s%s", isa_item, isa ? isa : "");
    snprintf(off_config, sizeof(off_config), "threads=2 stream=off%s%s", isa_item,
             isa ? isa : "");
    run(on_config, query_rays, &on_answers);
    run(off_config, query_rays, &off_answers);
    /* A scene the rays mostly hit, with ties: every instance-0/1 hit has
     * a coincident one in instance 2/3. */
    CHECKF(on_answers.hit_count > RAYS / 4, "%s: %d of %d rays hit",
           isa ? isa : "default", on_answers.hit_count, RAYS);
    int differ = 0, wrong_tie = 0;
    for (int i = 0; i < RAYS; i++) {
        differ += memcmp(&on_answers.hits[i], &off_answers.hits[i], sizeof(RThit)) != 0;
        differ += on_answers.occluded[i] != off_answers.occluded[i];
        wrong_tie += on_answers.hits[i].instance == 2u || on_answers.hits[i].instance == 3u;
    }
    CHECKF(differ == 0, "%s: %d answers differ between stream=on and stream=off",
              isa ? isa : "default", differ);
    CHECKF(wrong_tie == 0, "%s: %d hits went to the higher of two coincident instances",
              isa ? isa : "default", wrong_tie);
    CHECK_INT(on_answers.stats_trace[0], off_answers.stats_trace[0]);
    CHECK_INT(on_answers.stats_occluded[0], off_answers.stats_occluded[0]);
    CHECK_INT(on_answers.stats_trace[3], off_answers.stats_trace[3]);
    CHECK_INT(on_answers.stats_occluded[3], off_answers.stats_occluded[3]);
    printf("  %s: %d hits; closest: node tests %d / %d, triangle tests %d / %d; any: node "
           "tests %d / %d, triangle tests %d / %d (stream on / off)\n",
           isa ? isa : "default", on_answers.hit_count, on_answers.stats_trace[1],
           off_answers.stats_trace[1], on_answers.stats_trace[2], off_answers.stats_trace[2],
           on_answers.stats_occluded[1], off_answers.stats_occluded[1],
           on_answers.stats_occluded[2], off_answers.stats_occluded[2]);
    if (counts) {
        for (int k = 1; k < 3; k++) {
            CHECK_INT(on_answers.stats_trace[k], off_answers.stats_trace[k]);
            CHECK_INT(on_answers.stats_occluded[k], off_answers.stats_occluded[k]);
        }
    }
}

int main(void)
{
    make_rays(query_rays, RAYS);
    tu_section("configuration");
    {
        RTcontext ctx = tu_make_context("stream=off");
        const char *c = (const char *)rtGetString(RT_CONFIGURATION);
        CHECK(c && strstr(c, "stream=off"));
        tu_destroy_context(ctx);
        CHECK(!tu_config_available("stream=maybe"));
        CHECK(!tu_config_available("stream=on stream=off"));
    }
    if (tu_config_available("isa=avx2 stream=on")) {
        tu_section("isa=avx2: answers and statistics");
        {
            RTcontext ctx = tu_make_context("isa=avx2 stream=on");
            const char *c = (const char *)rtGetString(RT_CONFIGURATION);
            CHECK(c && strstr(c, "stream=on"));
            tu_destroy_context(ctx);
        }
        compare("avx2", 1);
    }
    tu_section("default table: answers");
    {
        /* Every table with 256-bit lanes has the stream (the AVX-512
         * table's two forms included, kernels.c): a form without it
         * would report off here, and the comparison below would pass
         * without ever walking a stream. */
        RTcontext ctx = tu_make_context("stream=on");
        const char *c = (const char *)rtGetString(RT_CONFIGURATION);
        if (c && (strstr(c, "isa=avx2") || strstr(c, "isa=avx512")))
            CHECKF(strstr(c, "stream=on") != NULL, "the default table has no stream: %s", c);
        tu_destroy_context(ctx);
    }
    compare(NULL, 0);
    return test_summary("stream_queries");
}
