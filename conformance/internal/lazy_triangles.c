/* SPDX-License-Identifier: Apache-2.0 */
/*
 * lazy_triangles.c - the leaf-ordered triangles an object's fresh build
 * leaves out (scene/accel.c, finish_layout: from 32 MiB of them, here
 * from 0) and a frame gathers on first need (scene_object_triangles, from
 * lib/render's acquire_object): the
 * frames that read them give the images of the scalar table, which
 * walks the binary tree of a structure that has them from its build.
 *
 * Scene: a wavy grid (a few thousand triangles) behind a see-through
 * quad.  Per context, the first frame is opaque (every object built, no
 * binary walk: the triangles are left out), then a blended frame (the
 * ties walk), a frame with a clip plane in Whitted shading (primary
 * rays past the clipped hits, secondary rays through the hit filter's
 * walk) and rtTraceRays under the clip plane (the filter walk of
 * queries).  "threads=1 isa=scalar" is the reference; the best table on
 * one and two threads (two threads: the frame's threads ask for the
 * array together) must give the same floats and hits.  A missing array
 * where a walk needs it is a NULL read: the test crashes.
 *
 * Allocation failure: for N = 0, 1, ... the Nth allocation of the first
 * blended frame fails (rt_alloc_fail_once) in a fresh context whose
 * objects the opaque frame built: the frame reports RT_NO_ERROR or
 * RT_OUT_OF_MEMORY, and the next blended frame gives the reference
 * image (the object stays usable).  The first blended frame must make
 * more allocations than a second one (the lazy array is one of them).
 */
#include <math.h>
#include <rt/rt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/context.h"
#include "base/alloc.h"
#include "check.h"

#define WIDTH 64
#define HEIGHT 48
#define GRID 40
#define RAY_COUNT 2000
#define OBJ_GRID 1u
#define OBJ_QUAD 2u

static int failed_checks;

struct images {
    float opaque[4 * WIDTH * HEIGHT];
    float blended[4 * WIDTH * HEIGHT];
    float clipped[4 * WIDTH * HEIGHT];
    RThit hits[RAY_COUNT];
};

static RTray rays[RAY_COUNT];

static void define_objects(void)
{
    rtNewObject(OBJ_GRID);
    rtBegin(RT_TRIANGLES);
    for (int j = 0; j < GRID; j++)
        for (int i = 0; i < GRID; i++) {
            float x0 = -2.0f + 4.0f * (float)i / GRID, x1 = -2.0f + 4.0f * (float)(i + 1) / GRID;
            float y0 = -1.5f + 3.0f * (float)j / GRID, y1 = -1.5f + 3.0f * (float)(j + 1) / GRID;
            float z00 = 0.2f * sinf(3.0f * x0) * cosf(2.0f * y0);
            float z10 = 0.2f * sinf(3.0f * x1) * cosf(2.0f * y0);
            float z01 = 0.2f * sinf(3.0f * x0) * cosf(2.0f * y1);
            float z11 = 0.2f * sinf(3.0f * x1) * cosf(2.0f * y1);
            rtNormal3f(0.0f, 0.0f, 1.0f);
            rtVertex3f(x0, y0, z00);
            rtVertex3f(x1, y0, z10);
            rtVertex3f(x1, y1, z11);
            rtVertex3f(x0, y0, z00);
            rtVertex3f(x1, y1, z11);
            rtVertex3f(x0, y1, z01);
        }
    rtEnd();
    rtEndObject();
    const float half[4] = {0.2f, 0.7f, 0.3f, 0.5f};
    rtNewObject(OBJ_QUAD);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, half);
    rtBegin(RT_QUADS);
    rtNormal3f(0.0f, 0.0f, 1.0f);
    rtVertex3f(-1.0f, -1.0f, 0.0f);
    rtVertex3f(1.0f, -1.0f, 0.0f);
    rtVertex3f(1.0f, 1.0f, 0.0f);
    rtVertex3f(-1.0f, 1.0f, 0.0f);
    rtEnd();
    rtEndObject();
}

static void camera(void)
{
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 50.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    const float sun[4] = {0.3f, 1.0f, 0.5f, 0.0f};
    rtLightfv(RT_LIGHT0, RT_POSITION, sun);
    rtEnable(RT_LIGHT0);
    rtViewport(0, 0, WIDTH, HEIGHT);
    rtClearColor(0.1f, 0.1f, 0.2f, 0.0f);
}

/* The grid, and the quad in front of it with blending `blend` and the
 * clip plane x <= 0.3 (eye space) when `clip`. */
static void place(int blend, int clip)
{
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtBeginFrame();
    if (clip) {
        static const double plane[4] = {-1.0, 0.0, 0.0, 0.3};
        rtClipPlane(RT_CLIP_PLANE0, plane);
        rtEnable(RT_CLIP_PLANE0);
    }
    rtPushMatrix();
    rtTranslatef(0.0f, 0.0f, -6.0f);
    rtRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    rtInstantiateObject(OBJ_GRID);
    rtPopMatrix();
    if (blend) {
        rtEnable(RT_BLEND);
        rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
    }
    rtPushMatrix();
    rtTranslatef(0.2f, 0.1f, -4.5f);
    rtRotatef(15.0f, 0.0f, 1.0f, 0.0f);
    rtInstantiateObject(OBJ_QUAD);
    rtPopMatrix();
    rtDisable(RT_BLEND);
    rtDisable(RT_CLIP_PLANE0);
}

static void frame(int blend, int clip, RTenum shading, float *image)
{
    place(blend, clip);
    rtShadingMode(shading);
    rtRenderFrame();
    rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, image);
}

/* A context whose fresh builds leave the leaf-ordered triangles out
 * however small the object (the default keeps them below 32 MiB of
 * them, BVH_REBUILD_REUSE_MIN_BYTES). */
static RTcontext make_context(const char *config)
{
    RTcontext ctx = rtCreateContext(config);
    if (ctx)
        ctx->scene.build_params.rebuild_reuse_min_bytes = 0;
    if (ctx && !rtMakeCurrent(ctx)) {
        rtDestroyContext(ctx);
        return NULL;
    }
    return ctx;
}

static void end_context(RTcontext ctx)
{
    rtMakeCurrent(NULL);
    rtDestroyContext(ctx);
}

/* The whole sequence in a new context; 0 when config cannot run here. */
static int run(const char *config, struct images *out)
{
    RTcontext ctx = make_context(config);
    if (!ctx)
        return 0;
    camera();
    define_objects();
    frame(0, 0, RT_EYE_LIGHT, out->opaque);
    frame(1, 0, RT_EYE_LIGHT, out->blended);
    frame(0, 1, RT_WHITTED, out->clipped);
    place(0, 1);
    rtTraceRays(RAY_COUNT, rays, out->hits);
    failed_checks += !CHECKF(rtGetError() == RT_NO_ERROR, "%s: an error was recorded", config);
    end_context(ctx);
    return 1;
}

/* Allocations the blended frame makes (the smallest N whose single
 * failure is not reached), in a fresh context after the opaque frame,
 * and, with `second`, after one blended frame already; with `check`
 * every failure must be RT_NO_ERROR or RT_OUT_OF_MEMORY, and the next
 * blended frame the reference image. */
static long blended_allocations(const char *config, int second, const float *reference)
{
    static float image[4 * WIDTH * HEIGHT];
    int reported = 0;
    for (long n = 0; n < 10000; n++) {
        RTcontext ctx = make_context(config);
        if (!ctx)
            return -1;
        camera();
        define_objects();
        frame(0, 0, RT_EYE_LIGHT, image);
        if (second)
            frame(1, 0, RT_EYE_LIGHT, image);
        place(1, 0);
        rt_alloc_fail_once(n);
        rtRenderFrame();
        const long injected = rt_alloc_failures();
        rt_alloc_fail_reset();
        const RTenum e = rtGetError();
        failed_checks += !CHECKF(e == RT_NO_ERROR || e == RT_OUT_OF_MEMORY,
                                 "%s: N=%ld: the blended frame recorded 0x%x", config, n, e);
        reported += e == RT_OUT_OF_MEMORY;
        /* The object is still usable: the same frame again. */
        frame(1, 0, RT_EYE_LIGHT, image);
        failed_checks += !CHECKF(rtGetError() == RT_NO_ERROR &&
                                     memcmp(image, reference, sizeof(image)) == 0,
                                 "%s: N=%ld: the blended frame after a failure differs", config,
                                 n);
        end_context(ctx);
        if (!injected) {
            printf("  %s, %s blended frame: %ld allocations, %d reported RT_OUT_OF_MEMORY\n",
                   config, second ? "second" : "first", n, reported);
            return n;
        }
    }
    return -1;
}

int main(void)
{
    for (int i = 0; i < RAY_COUNT; i++) {
        float a = 0.37f * (float)i, b = 0.011f * (float)i;
        rays[i].org[0] = 0.0f;
        rays[i].org[1] = 0.0f;
        rays[i].org[2] = 0.0f;
        rays[i].dir[0] = 0.25f * sinf(a) * cosf(b);
        rays[i].dir[1] = 0.2f * cosf(a);
        rays[i].dir[2] = -1.0f;
        rays[i].tmin = 0.0f;
        rays[i].tmax = INFINITY;
    }
    static struct images ref, got;
    if (!run("threads=1 isa=scalar", &ref)) {
        fprintf(stderr, "lazy_triangles: no scalar context\n");
        return 1;
    }
    int hits = 0;
    for (int i = 0; i < RAY_COUNT; i++)
        hits += ref.hits[i].t < INFINITY;
    failed_checks += !CHECKF(hits > RAY_COUNT / 4, "the scene is nearly empty (%d hits)", hits);
    failed_checks += !CHECKF(memcmp(ref.opaque, ref.blended, sizeof(ref.opaque)) != 0 &&
                                 memcmp(ref.opaque, ref.clipped, sizeof(ref.opaque)) != 0,
                             "blending or the clip plane changed nothing");
    static const char *const configs[] = {"threads=1", "threads=2", "threads=1 isa=avx2",
                                          "threads=2 isa=avx512"};
    for (size_t c = 0; c < sizeof(configs) / sizeof(configs[0]); c++) {
        if (!run(configs[c], &got)) {
            printf("  %s: not on this machine\n", configs[c]);
            continue;
        }
        failed_checks += !CHECKF(memcmp(got.opaque, ref.opaque, sizeof(got.opaque)) == 0 &&
                                     memcmp(got.blended, ref.blended, sizeof(got.blended)) == 0 &&
                                     memcmp(got.clipped, ref.clipped, sizeof(got.clipped)) == 0 &&
                                     memcmp(got.hits, ref.hits, sizeof(got.hits)) == 0,
                                 "%s: an image or a hit differs from isa=scalar's", configs[c]);
        printf("  %s: opaque, blended, clipped frames and queries as isa=scalar's\n",
               configs[c]);
    }
    const long first = blended_allocations("threads=1", 0, ref.blended);
    const long second = blended_allocations("threads=1", 1, ref.blended);
    failed_checks += !CHECKF(first > second && second >= 0,
                             "the first blended frame made no more allocations (%ld) than the "
                             "second (%ld): no lazy array",
                             first, second);
    printf("lazy_triangles: %s (%d failed checks)\n", failed_checks ? "FAILED" : "ok",
           failed_checks);
    return failed_checks != 0;
}
