/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dynamic_strategies.c - every update strategy gives the same hits and the
 * same images.
 *
 * Three short procedural animations (dynamic_anim.h: an exploding sphere,
 * a waving cloth drawn with rtDrawElements, a morphing random soup) are
 * played for FRAMES frames under each strategy - RT_REFIT, RT_REBUILD,
 * RT_REBUILD_MEDIAN, RT_REBUILD_HEURISTIC, RT_RESTRUCTURE, RT_ASYNC_REBUILD
 * (whose background builds land whenever they finish, so its tree shapes
 * vary from run to run), RT_AUTOMATIC - and each strategy twice: animated by rtUpdateVertices with the strategy
 * given as a per-object hint (rtObjectParameteri), and animated by
 * redefinition with the same topology with the strategy given as the
 * context default (rtRenderParameteri).  Each run has its own context
 * (threads=1), so every object is built at frame 0 and updated from then on.
 *
 * Per frame:
 *   - the closest hits of RAY_COUNT fixed rays agree with a reference
 *     context in which the objects are deleted and defined afresh every
 *     frame with the sweep SAH builder (same primitive with t within 1e-5
 *     relative; where two triangles are equally close, either);
 *   - the eye-light image (64x48, RGBA float) is identical bit for bit to
 *     the reference context's image, hence across strategies and methods:
 *     a pixel depends only on the hit (DESIGN.md, "Correctness does not
 *     depend on the strategy");
 *   - the bookkeeping is that of an update: each object is classified
 *     RT_UNSTRUCTURED, RT_STAT_OBJECT_UPDATES is 3 for the call that
 *     prepares the frame and 0 for the next call, RT_OBJECT_BUILT is
 *     RT_TRUE, RT_UPDATE_STRATEGY names the strategy used (a concrete one
 *     for RT_AUTOMATIC), and each update counts once in RT_OBJECT_REFITS or
 *     RT_OBJECT_REBUILDS (a rebuild strategy only in RT_OBJECT_REBUILDS;
 *     the rebuild heuristic and the asynchronous rebuild may count a refit
 *     and a rebuild).
 *
 * Reference: docs/dynamic.md.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dynamic_anim.h"
#include "testutil.h"

#define FRAMES 10
#define RAY_COUNT 3000

enum method { BY_UPDATE, BY_REDEFINITION };

static const int kinds[] = {DA_SPHERE, DA_CLOTH, DA_SOUP};
#define KIND_COUNT 3

static RTint geti(RTenum pname)
{
    RTint v = -12345;
    rtGetIntegerv(pname, &v);
    return v;
}

static RTint object_int(RTuint name, RTenum pname)
{
    RTint v = -12345;
    rtGetObjectiv(name, pname, &v);
    return v;
}

static int is_concrete_strategy(RTint s)
{
#ifdef RT_ASYNC_REBUILD
    if (s == RT_ASYNC_REBUILD)
        return 1;
#endif
    return s == RT_REFIT || s == RT_REBUILD || s == RT_REBUILD_MEDIAN ||
           s == RT_REBUILD_HEURISTIC || s == RT_RESTRUCTURE;
}

/* Checks, after the frame's updates, the class, state and counters of
 * each object; before[] holds refits + rebuilds (as pairs) before them. */
static void check_bookkeeping(RTenum strategy, const RTint before[][2])
{
    for (int i = 0; i < KIND_COUNT; i++) {
        RTuint name = DA_NAME_BASE + (RTuint)kinds[i];
        RTint used = object_int(name, RT_UPDATE_STRATEGY);
        RTint refits = object_int(name, RT_OBJECT_REFITS) - before[i][0];
        RTint rebuilds = object_int(name, RT_OBJECT_REBUILDS) - before[i][1];
        CHECK_INT(object_int(name, RT_OBJECT_CLASS), RT_UNSTRUCTURED);
        CHECK_INT(object_int(name, RT_OBJECT_BUILT), RT_TRUE);
        if (strategy == RT_AUTOMATIC)
            CHECK(is_concrete_strategy(used));
        else
            CHECK_INT(used, strategy);
        if ((used == RT_REBUILD || used == RT_REBUILD_MEDIAN) && strategy != RT_AUTOMATIC) {
            CHECK_INT(rebuilds, 1);
            CHECK_INT(refits, 0);
        } else if (strategy == RT_AUTOMATIC || (used != RT_REFIT && used != RT_RESTRUCTURE)) {
            /* The automatic strategy refits first and rebuilds when the
             * measured costs say so, reporting the rebuild. */
            /* The rebuild heuristic: a refit, and a rebuild when the SAH
             * cost degraded; the asynchronous rebuild: a refit, and the
             * swap of a tree built in the background when one landed. */
            CHECK(refits + rebuilds >= 1 && refits <= 1 && rebuilds <= 1);
        } else {
            CHECK_INT(refits + rebuilds, 1);
        }
    }
}

/* Runs one strategy with one method against the reference; returns the
 * number of mismatching rays and pixels. */
static long run(RTenum strategy, enum method method, const struct da_reference *ref,
                const RTray *rays, RThit *hits, float *image, struct da_compare_stats *st)
{
    char label[128];
    long bad = 0;
    RTint before[KIND_COUNT][2];
    RTcontext ctx = tu_make_context("threads=1");
    tu_capture_errors();
    da_camera();
    if (method == BY_REDEFINITION)
        rtRenderParameteri(RT_UPDATE_STRATEGY, (RTint)strategy);
    for (int f = 0; f < FRAMES; f++) {
        for (int i = 0; i < KIND_COUNT; i++) {
            RTuint name = DA_NAME_BASE + (RTuint)kinds[i];
            before[i][0] = f ? object_int(name, RT_OBJECT_REFITS) : 0;
            before[i][1] = f ? object_int(name, RT_OBJECT_REBUILDS) : 0;
            if (f == 0 || method == BY_REDEFINITION)
                da_define(name, kinds[i], f);
            else
                da_update(name, kinds[i], f);
            if (f == 0 && method == BY_UPDATE)
                rtObjectParameteri(name, RT_UPDATE_STRATEGY, (RTint)strategy);
            if (f > 0)
                CHECK_INT(object_int(name, RT_OBJECT_BUILT), RT_FALSE); /* stale */
        }
        da_instantiate(kinds, KIND_COUNT);
        CHECK_NO_ERR();
        /* Alternate which call prepares the frame: a query or a render. */
        if (f % 2 == 0) {
            rtTraceRays(RAY_COUNT, rays, hits);
            CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), f ? KIND_COUNT : 0);
            if (f)
                check_bookkeeping(strategy, before);
            da_render(image);
            CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
        } else {
            da_render(image);
            CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), KIND_COUNT);
            check_bookkeeping(strategy, before);
            rtTraceRays(RAY_COUNT, rays, hits);
            CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
        }
        CHECK_NO_ERR();
        snprintf(label, sizeof label, "%s by %s, frame %d", da_strategy_name(strategy),
                 method == BY_UPDATE ? "rtUpdateVertices" : "redefinition", f);
        long rays_bad = da_compare_hits(hits, &ref->hits[(size_t)f * RAY_COUNT], RAY_COUNT,
                                        label, st);
        long pixels_bad = da_compare_images(image, &ref->images[(size_t)f * DA_PIXELS], label);
        CHECK_INT(rays_bad, 0);
        CHECK_INT(pixels_bad, 0);
        bad += rays_bad + pixels_bad;
    }
    tu_destroy_context(ctx);
    return bad;
}

int main(void)
{
    RTray *rays = (RTray *)malloc(RAY_COUNT * sizeof(RTray));
    RThit *hits = (RThit *)malloc(RAY_COUNT * sizeof(RThit));
    float *image = (float *)malloc(DA_PIXELS * sizeof(float));
    struct da_reference ref;
    struct da_compare_stats st;
    memset(&st, 0, sizeof st);
    da_rays(rays, RAY_COUNT, 12345u);

    tu_section("reference: fresh sweep SAH definition every frame");
    CHECK_INT(da_reference_compute(&ref, kinds, KIND_COUNT, FRAMES, rays, RAY_COUNT),
              RT_NO_ERROR);
    {
        /* The rays must mostly hit something, or the comparison is empty. */
        long hit = 0;
        for (int i = 0; i < FRAMES * RAY_COUNT; i++)
            hit += ref.hits[i].t != INFINITY;
        printf("reference: %ld of %d rays hit\n", hit, FRAMES * RAY_COUNT);
        CHECK(hit > FRAMES * RAY_COUNT / 4);
    }

    for (int m = 0; m < 2; m++)
        for (int s = 0; s < DA_STRATEGY_COUNT; s++) {
            char section[96];
            snprintf(section, sizeof section, "%s, animated by %s", da_strategy_name(da_strategies[s]),
                     m == BY_UPDATE ? "rtUpdateVertices (object hint)"
                                    : "redefinition (context default)");
            tu_section(section);
            long bad = run(da_strategies[s], (enum method)m, &ref, rays, hits, image, &st);
            if (bad)
                printf("  %ld mismatching rays and pixels\n", bad);
        }
    printf("compared %ld rays (%ld hits): %ld ties at equal distance, %ld same-primitive hits "
           "with t not bit-identical, %ld mismatches\n",
           st.rays, st.hits, st.ties, st.same_prim_t_not_bitwise, st.mismatches);

    da_reference_free(&ref);
    free(rays);
    free(hits);
    free(image);
    return test_summary("dynamic_strategies");
}
