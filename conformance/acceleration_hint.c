/* SPDX-License-Identifier: Apache-2.0 */
/*
 * acceleration_hint.c - rtHint(RT_ACCELERATION_HINT, mode): validated as
 * GL validates glHint (RT_INVALID_ENUM for an unknown target or mode,
 * nothing changed), read back with rtGetIntegerv, recorded on an object
 * at its rtEndObject (rtGetObjectiv), and the same answers either way.
 *
 * The same triangle soup is defined twice, once under RT_FASTEST (the
 * greedy collapse) and once under RT_NICEST (the optimal collapse of
 * Ylitie, Karras and Laine 2017), and the same random rays are traced
 * against each alone: every hit must be equal bit for bit (the collapse
 * changes which binary nodes are a wide node's lanes, never a box or a
 * triangle, docs/objects.md).  Where the context walks a wide layout,
 * the two walks' node tests (RT_STAT_NODE_TESTS) must differ: the two
 * objects have different layouts, so the test fails if the hint does not
 * reach the collapse.  isa=scalar walks only the binary tree (no wide
 * layout): there the counts are equal and only the answers are compared.
 */
#include "testutil.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TRIANGLES 20000
#define RAYS 4096

static const RTuint GREEDY = 1, OPTIMAL = 2;

/* A small deterministic generator (the test must not depend on rand()). */
static float next_unit(unsigned *state)
{
    *state = *state * 1664525u + 1013904223u;
    return (float)(*state >> 8) * (1.0f / 16777216.0f);
}

/* Small triangles scattered through the cube [-1, 1]^3: many leaves, so
 * the two collapses choose differently. */
static void define_soup(RTuint name)
{
    unsigned s = 12345u;
    rtNewObject(name);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < TRIANGLES; i++) {
        const float cx = 2.0f * next_unit(&s) - 1.0f, cy = 2.0f * next_unit(&s) - 1.0f,
                    cz = 2.0f * next_unit(&s) - 1.0f;
        for (int v = 0; v < 3; v++)
            rtVertex3f(cx + 0.05f * (next_unit(&s) - 0.5f), cy + 0.05f * (next_unit(&s) - 0.5f),
                       cz + 0.05f * (next_unit(&s) - 0.5f));
    }
    rtEnd();
    rtEndObject();
}

static void hint_state(void)
{
    RTint v = 0;
    tu_section("hint state and errors");
    rtGetIntegerv(RT_ACCELERATION_HINT, &v);
    CHECK_INT(v, RT_DONT_CARE);
    rtHint(RT_ACCELERATION_HINT, RT_NICEST);
    CHECK_NO_ERR();
    rtGetIntegerv(RT_ACCELERATION_HINT, &v);
    CHECK_INT(v, RT_NICEST);
    /* An unknown mode, or a mode that is another enum: RT_INVALID_ENUM,
     * the hint unchanged. */
    rtHint(RT_ACCELERATION_HINT, 0x1234);
    CHECK_ERR(RT_INVALID_ENUM);
    rtHint(RT_ACCELERATION_HINT, RT_ACCELERATION_HINT);
    CHECK_ERR(RT_INVALID_ENUM);
    rtGetIntegerv(RT_ACCELERATION_HINT, &v);
    CHECK_INT(v, RT_NICEST);
    /* An unknown target. */
    rtHint(0x8F5D, RT_FASTEST);
    CHECK_ERR(RT_INVALID_ENUM);
    rtGetIntegerv(RT_ACCELERATION_HINT, &v);
    CHECK_INT(v, RT_NICEST);
    /* The GL targets stay accepted. */
    rtHint(RT_FOG_HINT, RT_FASTEST);
    CHECK_NO_ERR();
    rtHint(RT_ACCELERATION_HINT, RT_DONT_CARE);
    rtGetIntegerv(RT_ACCELERATION_HINT, &v);
    CHECK_INT(v, RT_DONT_CARE);
    /* Inside rtBegin/rtEnd: RT_INVALID_OPERATION, unchanged. */
    rtBegin(RT_TRIANGLES);
    rtHint(RT_ACCELERATION_HINT, RT_NICEST);
    rtEnd();
    CHECK_ERR(RT_INVALID_OPERATION);
    rtGetIntegerv(RT_ACCELERATION_HINT, &v);
    CHECK_INT(v, RT_DONT_CARE);
}

static int wide_layout(void)
{
    const char *config = (const char *)rtGetString(RT_CONFIGURATION);
    return config && !strstr(config, "isa=scalar");
}

static RTint trace(RTuint name, const RTray *rays, RThit *hits)
{
    RTint nodes = 0;
    CHECK(tu_scene1(name));
    rtTraceRays(RAYS, rays, hits);
    rtGetIntegerv(RT_STAT_NODE_TESTS, &nodes);
    return nodes;
}

static void same_answers(void)
{
    static RTray rays[RAYS];
    static RThit greedy[RAYS], optimal[RAYS];
    RTint v = 0;
    tu_section("recorded at rtEndObject, same answers");
    rtHint(RT_ACCELERATION_HINT, RT_FASTEST);
    define_soup(GREEDY);
    rtHint(RT_ACCELERATION_HINT, RT_NICEST);
    define_soup(OPTIMAL);
    /* Read at rtEndObject: a later change does not reach the objects. */
    rtHint(RT_ACCELERATION_HINT, RT_DONT_CARE);
    CHECK_NO_ERR();
    rtGetObjectiv(GREEDY, RT_ACCELERATION_HINT, &v);
    CHECK_INT(v, RT_FASTEST);
    rtGetObjectiv(OPTIMAL, RT_ACCELERATION_HINT, &v);
    CHECK_INT(v, RT_NICEST);

    unsigned s = 777u;
    for (int i = 0; i < RAYS; i++) {
        float o[3], d[3];
        for (int k = 0; k < 3; k++) {
            o[k] = 6.0f * next_unit(&s) - 3.0f;
            d[k] = 1.6f * next_unit(&s) - 0.8f - o[k]; /* towards the cube */
        }
        rays[i] = tu_ray(o[0], o[1], o[2], d[0], d[1], d[2]);
    }
    const RTint nodes_greedy = trace(GREEDY, rays, greedy);
    const RTint nodes_optimal = trace(OPTIMAL, rays, optimal);
    CHECK_NO_ERR();
    int hits = 0, differ = 0;
    for (int i = 0; i < RAYS; i++) {
        hits += greedy[i].primitive != RT_INVALID_ID;
        if (memcmp(&greedy[i].t, &optimal[i].t, sizeof(float)) ||
            memcmp(&greedy[i].u, &optimal[i].u, sizeof(float)) ||
            memcmp(&greedy[i].v, &optimal[i].v, sizeof(float)) ||
            greedy[i].primitive != optimal[i].primitive) {
            if (differ++ < 5)
                fprintf(stderr, "    ray %d: greedy prim %u t %.9g, optimal prim %u t %.9g\n", i,
                        greedy[i].primitive, greedy[i].t, optimal[i].primitive, optimal[i].t);
        }
    }
    CHECK_INT(differ, 0);
    CHECK(hits > RAYS / 4); /* not vacuous */
    CHECK(nodes_greedy > 0 && nodes_optimal > 0);
    if (wide_layout()) {
        /* Different layouts: different node tests for the same rays. */
        CHECK(nodes_greedy != nodes_optimal);
    } else {
        CHECK_INT(nodes_optimal, nodes_greedy);
    }
    printf("node tests: greedy %d, optimal %d\n", nodes_greedy, nodes_optimal);
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    hint_state();
    same_answers();
    tu_destroy_context(ctx);
    return test_summary("acceleration_hint");
}
