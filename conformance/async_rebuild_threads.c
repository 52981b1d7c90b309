/* SPDX-License-Identifier: Apache-2.0 */
/*
 * async_rebuild_threads.c - asynchronous rebuilds (Wald, Ize and Parker (2008) sec. 6)
 * through the API: correct hits every frame while builds land in the
 * background, no build thread before an object asks for one, none with
 * build_threads=0, and objects deleted, redefined or abandoned (context
 * destroyed) while their build runs.  Runs under ThreadSanitizer in CI
 * (file name ends in _threads).
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <time.h>

#define GRID 120 /* (GRID+1)^2 vertices, 2 GRID^2 triangles */
#define FRAMES 40
#define RAYS 500
/* Frames played one at a time, 10 ms apart, while no rebuild has landed
 * yet: on a machine loaded enough that the build thread did not run
 * during the FRAMES frames (ctest -j on two cores under CI), it gets up
 * to 10 s more before the test calls it a failure. */
#define EXTRA_FRAMES 1000

static float positions[(GRID + 1) * (GRID + 1) * 3];
static unsigned indices[GRID * GRID * 6];
static RTray rays[RAYS];

/* Height of the waving sheet at (x, y) in frame f; the sheet spans
 * [-1, 1]^2 at z = height. */
static float height(float x, float y, int f)
{
    return 0.2f * sinf(6.0f * x + 0.3f * f) * cosf(4.0f * y - 0.3f * f);
}

static void wave(int f)
{
    for (int i = 0; i <= GRID; i++)
        for (int j = 0; j <= GRID; j++) {
            float *p = &positions[3 * (i * (GRID + 1) + j)];
            p[0] = (float)i / GRID * 2.0f - 1.0f;
            p[1] = (float)j / GRID * 2.0f - 1.0f;
            p[2] = height(p[0], p[1], f);
        }
}

static void define_sheet(RTuint name)
{
    int k = 0;
    for (int i = 0; i < GRID; i++)
        for (int j = 0; j < GRID; j++) {
            unsigned a = (unsigned)(i * (GRID + 1) + j), b = a + 1, c = a + GRID + 1, d = c + 1;
            unsigned quad[6] = {a, c, b, b, c, d};
            for (int q = 0; q < 6; q++)
                indices[k++] = quad[q];
        }
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, positions);
    rtNewObject(name);
    rtDrawElements(RT_TRIANGLES, GRID * GRID * 6, RT_UNSIGNED_INT, indices);
    rtEndObject();
    rtDisableClientState(RT_VERTEX_ARRAY);
}

/* Rays straight down onto grid points' neighbourhood: the sheet is piecewise
 * linear, so a hit must lie within the interpolation error of the exact
 * height (bounded by the curvature over one cell, well under 0.01). */
static void make_rays(void)
{
    unsigned s = 12345;
    for (int r = 0; r < RAYS; r++) {
        s = s * 1103515245u + 12345u;
        float x = (float)((s >> 8) % 1000) / 1000.0f * 1.8f - 0.9f;
        s = s * 1103515245u + 12345u;
        float y = (float)((s >> 8) % 1000) / 1000.0f * 1.8f - 0.9f;
        RTray ray = {{x, y, 5.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, 100.0f};
        rays[r] = ray;
    }
}

static int count_bad_hits(int f)
{
    RThit hits[RAYS];
    rtTraceRays(RAYS, rays, hits);
    int bad = 0;
    for (int r = 0; r < RAYS; r++) {
        float z = 5.0f - hits[r].t;
        if (hits[r].object != 1 || fabsf(z - height(rays[r].org[0], rays[r].org[1], f)) > 0.01f)
            bad++;
    }
    return bad;
}

static RTint geti(RTenum pname)
{
    RTint v = -1;
    rtGetIntegerv(pname, &v);
    return v;
}

static RTint obji(RTuint name, RTenum pname)
{
    RTint v = -1;
    rtGetObjectiv(name, pname, &v);
    return v;
}

/* Plays the animation; returns the rebuilds that landed after the first
 * build. */
static int play(int frames, int render)
{
    int bad = 0;
    for (int f = 0; f < frames; f++) {
        wave(f);
        rtUpdateVertices(1, RT_VERTEX_ARRAY, 0, (GRID + 1) * (GRID + 1), RT_FLOAT, 0, positions);
        rtInstantiateObject(1);
        bad += count_bad_hits(f);
        if (render)
            rtRenderFrame();
        else
            rtBeginFrame();
    }
    CHECK_INT(bad, 0);
    CHECK_NO_ERR();
    return obji(1, RT_OBJECT_REBUILDS) - 1;
}

static void lands_and_stays_correct(int threads, int build_threads)
{
    char config[64];
    snprintf(config, sizeof(config), "threads=%d build_threads=%d", threads, build_threads);
    tu_section(config);
    RTcontext ctx = tu_make_context(config);
    wave(0);
    define_sheet(1);
    rtViewport(0, 0, 24, 24);
    CHECK_INT(geti(RT_BUILD_THREADS_RUNNING), 0);
    rtObjectParameteri(1, RT_UPDATE_STRATEGY, RT_ASYNC_REBUILD);
    /* One frame with a static object: no build thread yet. */
    rtInstantiateObject(1);
    rtRenderFrame();
    CHECK_INT(geti(RT_BUILD_THREADS_RUNNING), 0);
    int landed = play(FRAMES, 1);
    for (int i = 0; build_threads > 0 && landed < 1 && i < EXTRA_FRAMES; i++) {
        const struct timespec pause = {0, 10 * 1000 * 1000};
        nanosleep(&pause, NULL);
        landed = play(1, 0);
    }
    if (build_threads > 0) {
        CHECK_INT(geti(RT_BUILD_THREADS_RUNNING), build_threads);
        CHECK_INT(obji(1, RT_UPDATE_STRATEGY), RT_ASYNC_REBUILD);
        /* 40 frames of a 29k-triangle sheet: builds take milliseconds, so
         * several land (not a timing claim: one is enough to pass, and a
         * loaded machine gets EXTRA_FRAMES more). */
        CHECK(landed >= 1);
    } else {
        CHECK_INT(geti(RT_BUILD_THREADS_RUNNING), 0);
        CHECK_INT(obji(1, RT_UPDATE_STRATEGY), RT_REBUILD_HEURISTIC);
    }
    tu_destroy_context(ctx);
}

/* Deleting, redefining with a new connectivity and destroying the context
 * while a build is queued or running must neither crash, leak (ASan) nor
 * race (TSan). */
static void abandoned_builds(void)
{
    tu_section("abandoned builds");
    for (int round = 0; round < 6; round++) {
        RTcontext ctx = tu_make_context("threads=2 build_threads=2");
        wave(0);
        define_sheet(1);
        rtObjectParameteri(1, RT_UPDATE_STRATEGY, RT_ASYNC_REBUILD);
        rtInstantiateObject(1);
        count_bad_hits(0);
        play(3, 0);
        switch (round % 3) {
        case 0: {
            RTuint name = 1;
            rtDeleteObjects(1, &name);
            break;
        }
        case 1:
            /* A different connectivity: the running build is for the old
             * one and must be discarded when it lands. */
            rtNewObject(1);
            rtBegin(RT_TRIANGLES);
            rtVertex3f(-1, -1, 0);
            rtVertex3f(1, -1, 0);
            rtVertex3f(0, 1, 0);
            rtEnd();
            rtEndObject();
            rtInstantiateObject(1);
            {
                RThit h;
                RTray down = {{0.0f, 0.0f, 5.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, 100.0f};
                rtTraceRays(1, &down, &h);
                CHECK_NEAR(h.t, 5.0f, 1e-6);
                CHECK_INT(h.primitive, 0);
            }
            break;
        default:
            break; /* destroyed with the build in flight */
        }
        CHECK_NO_ERR();
        tu_destroy_context(ctx);
    }
}

int main(void)
{
    make_rays();
    lands_and_stays_correct(1, 1);
    lands_and_stays_correct(2, 2);
    lands_and_stays_correct(2, 0);
    abandoned_builds();
    return test_summary("async_rebuild_threads");
}
