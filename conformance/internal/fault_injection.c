/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fault_injection.c - every allocation failure is an RT_OUT_OF_MEMORY or
 * harmless, never a crash, a leak or a corrupted context.
 *
 * Internal test (links the static library): it uses the allocation
 * wrapper's test hook, rt_alloc_fail_after (base/alloc.h), the idea of
 * SQLite's sqlite3FaultSim.  For N = 0, 1, 2, ... the Nth allocation from
 * the start of a fixed sequence fails, and every allocation after it fails
 * too, until rt_alloc_fail_reset():
 *   rtCreateContext (may return NULL: then there is nothing more to do),
 *   rtGenObjects, rtGenTextures, a mipmapped texture (rtBindTexture,
 *   rtTexImage2D, which also allocates the mip chain's working rows),
 *   three object definitions (rtBegin/rtVertex with normals and several
 *   materials, rtDrawElements from vertex arrays, textured quads),
 *   rtEndObject, instances (rtInstantiateObject), rtRenderFrame in eye-light
 *   and then Whitted mode, rtReadPixels, rtTraceRays and rtOccludedRays.
 * After every call rtGetError must be RT_NO_ERROR or RT_OUT_OF_MEMORY
 * (rtInstantiateObject of an object whose definition ran out of memory:
 * RT_INVALID_VALUE, as for any name that is not an object).  When the
 * Whitted frame fails, the framebuffer must still hold the eye-light frame.
 * When no call reported RT_OUT_OF_MEMORY although an allocation failed
 * (failures the library absorbs, like a worker pool with fewer threads),
 * the results must be exactly those of a run without failures.
 * Then the allocator is reset and the same context must define, render and
 * trace the scene again with results identical bit for bit to those of a
 * context that never saw a failure.  The loop ends at the first N for which
 * the sequence completes without an injected failure.
 *
 * A texture whose rtBindTexture reported RT_OUT_OF_MEMORY does not exist
 * (rtIsTexture); one whose rtTexImage2D did has no image, and object C is
 * drawn untextured (a reported failure: the image may differ).
 *
 * A definition that reported RT_OUT_OF_MEMORY leaves its object undefined;
 * one that did not is complete (its triangle count); an instance that
 * reported it is not in the list (RT_INSTANCE_COUNT), one that did not is.
 *
 * Three modes: every allocation from the Nth on fails (the sequence then
 * mostly fails to its end); one failing call (the allocator is reset
 * right after the first call that saw an injected failure, so the rest of
 * the sequence runs on the state that call left: a failure a call absorbs
 * without reporting it must then leave every result unchanged); and one
 * failing allocation (rt_alloc_fail_once: only the Nth fails, the call
 * goes on with the next ones), which reaches the optional allocations
 * docs/errors.md lists: at least one failure must be absorbed, and every
 * absorbed one must leave the frame rendered exactly as without it.  The sweeps
 * run with threads=1, where the allocation order is fixed, and with
 * threads=2, where builds run on worker threads and the failing allocation
 * is not always the same one (the invariants still hold).
 * Under AddressSanitizer the leak checker runs at exit, so a leak on any
 * failure path fails the test.
 */
#include <math.h>
#include <rt/rt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "check.h"

#define WIDTH 32
#define HEIGHT 24
#define RAY_COUNT 1500 /* more than one query chunk: worker threads help */
#define MAX_PRINTED 20
#define MAX_N 100000

static int checks_failed;


/* The N of the iteration, for messages. */
static long current_n;
static int failures_seen; /* calls that reported RT_OUT_OF_MEMORY */
/* 1: one failing call, the allocator is reset after the first call that
 * saw an injected failure, so only that call fails and the sequence goes
 * on; 2: one failing allocation (and the reset too); 0: neither. */
static int one_shot;
static int injected; /* an injected failure happened in this pass */
/* Passes in which an injected failure was absorbed: no call reported it
 * (docs/errors.md lists the allocations that may be), so the frame must
 * have rendered exactly as without it. */
static int absorbed;

static void note_injection(void)
{
    if (rt_alloc_failures() > 0) {
        injected = 1;
        if (one_shot)
            rt_alloc_fail_reset();
    }
}

/* After a call that may run out of memory. */
static void after(const char *call)
{
    RTenum e = rtGetError();
    if (e == RT_OUT_OF_MEMORY)
        failures_seen++;
    checks_failed += !CHECKF(e == RT_NO_ERROR || e == RT_OUT_OF_MEMORY, "N=%ld: %s recorded 0x%x", current_n, call,
           e);
    note_injection();
}

/* After an object definition: a definition that ran out of memory anywhere
 * leaves the object undefined (these are first definitions); one that did
 * not is complete. */
static void check_definition(RTuint name, int reported_before, RTint triangles)
{
    RTboolean defined = rtIsObject(name);
    if (failures_seen != reported_before) {
        checks_failed += !CHECKF(!defined, "N=%ld: object %u is defined although its definition ran out of memory",
               current_n, name);
        return;
    }
    checks_failed += !CHECKF(defined, "N=%ld: object %u is not defined, and no call reported an error", current_n,
           name);
    RTint n = -1;
    rtGetObjectiv(name, RT_OBJECT_TRIANGLES, &n);
    checks_failed += !CHECKF(n == triangles, "N=%ld: object %u has %d triangles, expected %d", current_n, name, n,
           triangles);
}

/* ---- the scene --------------------------------------------------------------- */

enum { OBJ_A = 10, OBJ_B = 20, OBJ_C = 30 };
enum { TEXTURE = 40 };

static float array_positions[3 * 400];
static float array_normals[3 * 400];
static unsigned array_indices[3 * 300];

static void make_arrays(void)
{
    unsigned s = 12345u;
    for (int i = 0; i < 3 * 400; i++) {
        s = s * 1103515245u + 12345u;
        array_positions[i] = (float)((s >> 8) % 2000) / 1000.0f - 1.0f;
        array_normals[i] = (float)((s >> 4) % 7) - 3.0f;
    }
    for (int i = 0; i < 3 * 300; i++) {
        s = s * 1103515245u + 12345u;
        array_indices[i] = (s >> 8) % 400;
    }
}

/* The texture object C uses: 8x8 texels, two tones in a checkerboard. */
static void define_texture(int check)
{
    static unsigned char image[8 * 8 * 3];
    for (int i = 0; i < 8 * 8; i++) {
        int odd = (i % 8 + i / 8) % 2;
        image[3 * i] = (unsigned char)(odd ? 230 : 40);
        image[3 * i + 1] = (unsigned char)(odd ? 200 : 90);
        image[3 * i + 2] = 120;
    }
    RTuint generated[3];
    rtGenTextures(3, generated);
    if (check)
        after("rtGenTextures");
    int before = failures_seen;
    rtBindTexture(RT_TEXTURE_2D, TEXTURE);
    if (check) {
        after("rtBindTexture");
        if (failures_seen != before) {
            checks_failed += !CHECKF(!rtIsTexture(TEXTURE), "N=%ld: a failed rtBindTexture created the texture",
                   current_n);
            return; /* with 0 bound, rtTexImage2D would be RT_INVALID_OPERATION */
        }
        checks_failed += !CHECKF(rtIsTexture(TEXTURE), "N=%ld: rtBindTexture did not create the texture",
               current_n);
    }
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 8, 8, 0, RT_RGB, RT_UNSIGNED_BYTE, image);
    if (check)
        after("rtTexImage2D");
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_NEAREST);
    if (check)
        after("rtTexParameteri");
    /* Mipmapped: frames read the chain rtTexImage2D generated. */
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_LINEAR_MIPMAP_LINEAR);
    if (check)
        after("rtTexParameteri");
}

/* Defines the three objects; `check` runs after() after each call. */
static void define_objects(int check)
{
    RTuint generated[4];
    rtGenObjects(4, generated);
    if (check)
        after("rtGenObjects");
    define_texture(check);

    int before = failures_seen;
    rtNewObject(OBJ_A);
    for (int block = 0; block < 4; block++) {
        const float diffuse[4] = {0.2f * (float)block, 0.5f, 0.9f - 0.2f * (float)block, 1.0f};
        rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, diffuse);
        rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, block == 2 ? 0.5f : 0.0f);
        rtBegin(RT_TRIANGLES);
        for (int i = 0; i < 150; i++) {
            float a = 0.1f * (float)i + (float)block;
            rtNormal3f(cosf(a), sinf(a), 1.0f);
            rtVertex3f(cosf(a) * (1.0f + 0.1f * (float)(i % 3)), sinf(a), 0.3f * (float)block);
            if (check)
                after("rtVertex3f");
        }
        rtEnd();
    }
    rtEndObject();
    if (check) {
        after("rtEndObject (A)");
        check_definition(OBJ_A, before, 200);
        before = failures_seen;
    }

    rtNewObject(OBJ_B);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtEnableClientState(RT_NORMAL_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, array_positions);
    rtNormalPointer(RT_FLOAT, 0, array_normals);
    rtDrawElements(RT_TRIANGLES, 3 * 300, RT_UNSIGNED_INT, array_indices);
    if (check)
        after("rtDrawElements");
    rtDrawArrays(RT_TRIANGLE_STRIP, 0, 400);
    if (check)
        after("rtDrawArrays");
    rtDisableClientState(RT_VERTEX_ARRAY);
    rtDisableClientState(RT_NORMAL_ARRAY);
    rtEndObject();
    if (check) {
        after("rtEndObject (B)");
        check_definition(OBJ_B, before, 300 + 398);
        before = failures_seen;
    }

    rtNewObject(OBJ_C);
    const float grey[4] = {0.6f, 0.6f, 0.6f, 1.0f};
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, grey);
    rtEnable(RT_TEXTURE_2D);
    rtBegin(RT_QUADS);
    for (int j = 0; j < 10; j++)
        for (int i = 0; i < 10; i++) {
            float x = -5.0f + (float)i, y = -5.0f + (float)j;
            rtTexCoord2f(0.3f * x, 0.3f * y);
            rtVertex3f(x, y, 0.0f);
            rtTexCoord2f(0.3f * (x + 1.0f), 0.3f * y);
            rtVertex3f(x + 1.0f, y, 0.0f);
            rtTexCoord2f(0.3f * (x + 1.0f), 0.3f * (y + 1.0f));
            rtVertex3f(x + 1.0f, y + 1.0f, 0.0f);
            rtTexCoord2f(0.3f * x, 0.3f * (y + 1.0f));
            rtVertex3f(x, y + 1.0f, 0.0f);
            if (check)
                after("rtVertex3f (quads)");
        }
    rtEnd();
    rtDisable(RT_TEXTURE_2D);
    rtEndObject();
    if (check) {
        after("rtEndObject (C)");
        check_definition(OBJ_C, before, 200);
    }
}

static RTint instance_count(void)
{
    RTint n = -1;
    rtGetIntegerv(RT_INSTANCE_COUNT, &n);
    return n;
}

/* An instance that did not fail is in the list; one that failed is not. */
static void instantiate(const char *what, RTuint name, int check)
{
    RTboolean defined = rtIsObject(name);
    RTint count = instance_count();
    rtInstantiateObject(name);
    if (!check)
        return;
    if (defined) {
        int reported_before = failures_seen;
        after(what);
        RTint expected = count + (failures_seen == reported_before);
        checks_failed += !CHECKF(instance_count() == expected, "N=%ld: %s: %d instances, expected %d", current_n,
               what, instance_count(), expected);
    } else {
        RTenum e = rtGetError();
        /* Ignored without an error, as glCallList (docs/lists.md). */
        checks_failed += !CHECKF(e == RT_NO_ERROR, "N=%ld: %s of an undefined object recorded 0x%x", current_n,
               what, e);
        checks_failed += !CHECKF(instance_count() == count, "N=%ld: %s of an undefined object added an instance",
               current_n, what);
        note_injection();
    }
}

static void place_instances(int check)
{
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtBeginFrame();
    for (int i = 0; i < 3; i++) {
        rtPushMatrix();
        rtTranslatef(-3.0f + 3.0f * (float)i, 0.0f, -8.0f);
        rtRotatef(30.0f * (float)i, 0.0f, 1.0f, 1.0f);
        instantiate("rtInstantiateObject (A)", OBJ_A, check);
        rtPopMatrix();
    }
    rtPushMatrix();
    rtTranslatef(0.0f, 2.0f, -7.0f);
    instantiate("rtInstantiateObject (B)", OBJ_B, check);
    rtPopMatrix();
    rtPushMatrix();
    rtTranslatef(0.0f, -2.0f, -10.0f);
    rtRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
    instantiate("rtInstantiateObject (C)", OBJ_C, check);
    rtPopMatrix();
}

static void camera_and_lights(void)
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

static void make_rays(RTray *rays)
{
    for (int i = 0; i < RAY_COUNT; i++) {
        float a = 0.37f * (float)i, b = 0.011f * (float)i;
        rays[i].org[0] = 0.0f;
        rays[i].org[1] = 0.0f;
        rays[i].org[2] = 0.0f;
        rays[i].dir[0] = 0.5f * sinf(a) * cosf(b);
        rays[i].dir[1] = 0.4f * cosf(a);
        rays[i].dir[2] = -1.0f;
        rays[i].tmin = 0.0f;
        rays[i].tmax = INFINITY;
    }
}

/* What a complete, failure-free pass produces. */
struct outcome {
    float image[4 * WIDTH * HEIGHT];
    RThit hits[RAY_COUNT];
    RTboolean occluded[RAY_COUNT];
};

static RTray rays[RAY_COUNT];

/* A full pass without checks, for the baseline and the recovery. */
static void clean_pass(struct outcome *out)
{
    camera_and_lights();
    define_objects(0);
    place_instances(0);
    rtShadingMode(RT_WHITTED);
    rtRenderFrame();
    rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, out->image);
    rtTraceRays(RAY_COUNT, rays, out->hits);
    rtOccludedRays(RAY_COUNT, rays, out->occluded);
}

/* The pass under fault injection, with checks after every call; its
 * results go to *out (the Whitted frame, if there is one). */
static void faulty_pass(struct outcome *out)
{
    static float first[4 * WIDTH * HEIGHT], now[4 * WIDTH * HEIGHT];
    RThit *hits = out->hits;
    RTboolean *occluded = out->occluded;
    memset(out, 0, sizeof(*out));
    camera_and_lights();
    define_objects(1);
    place_instances(1);
    rtShadingMode(RT_EYE_LIGHT);
    rtRenderFrame();
    RTenum e = rtGetError();
    checks_failed += !CHECKF(e == RT_NO_ERROR || e == RT_OUT_OF_MEMORY, "N=%ld: rtRenderFrame recorded 0x%x",
           current_n, e);
    int have_frame = e == RT_NO_ERROR;
    failures_seen += e == RT_OUT_OF_MEMORY;
    note_injection();
    if (have_frame) {
        rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, first);
        after("rtReadPixels");
    }
    rtShadingMode(RT_WHITTED);
    rtRenderFrame();
    e = rtGetError();
    checks_failed += !CHECKF(e == RT_NO_ERROR || e == RT_OUT_OF_MEMORY, "N=%ld: rtRenderFrame recorded 0x%x",
           current_n, e);
    failures_seen += e == RT_OUT_OF_MEMORY;
    note_injection();
    if (e == RT_OUT_OF_MEMORY && have_frame) {
        /* The failed frame left the previous one in place. */
        rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, now);
        after("rtReadPixels");
        checks_failed += !CHECKF(memcmp(first, now, sizeof(now)) == 0,
               "N=%ld: a failed rtRenderFrame changed the framebuffer", current_n);
    }
    if (e == RT_NO_ERROR) {
        rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, out->image);
        after("rtReadPixels");
    }
    rtTraceRays(RAY_COUNT, rays, hits);
    after("rtTraceRays");
    rtOccludedRays(RAY_COUNT, rays, occluded);
    after("rtOccludedRays");
    rtFinish();
    after("rtFinish");
}

/* Runs the sweep for one configuration and mode; returns the number of N
 * tried.
 * baseline[0] and [1]: the results of the faulty and the clean pass in a
 * context that never ran out of memory. */
static long sweep(const char *config, const struct outcome baseline[2])
{
    static struct outcome recovered;
    long n;
    for (n = 0; n < MAX_N; n++) {
        current_n = n;
        if (one_shot == 2)
            rt_alloc_fail_once(n);
        else
            rt_alloc_fail_after(n);
        RTcontext ctx = rtCreateContext(config);
        if (!ctx) {
            rt_alloc_fail_reset();
            continue;
        }
        checks_failed += !CHECKF(rtMakeCurrent(ctx) == RT_TRUE, "N=%ld: rtMakeCurrent failed", n);
        int reported_before = failures_seen;
        injected = rt_alloc_failures() > 0; /* rtCreateContext absorbed one */
        note_injection();
        faulty_pass(&recovered);
        note_injection();
        rt_alloc_fail_reset();
        /* A failure nobody reported (a pool with fewer threads, a shrink
         * that did not happen) must not change any result. */
        if (failures_seen == reported_before) {
            checks_failed += !CHECKF(memcmp(&recovered, &baseline[0], sizeof(recovered)) == 0,
                   "N=%ld (%s): no call reported RT_OUT_OF_MEMORY, yet the results differ", n,
                   config);
            absorbed += injected;
        }

        /* The context must still work, and work exactly. */
        clean_pass(&recovered);
        RTenum e = rtGetError();
        checks_failed += !CHECKF(e == RT_NO_ERROR, "N=%ld: after the reset the clean pass recorded 0x%x", n, e);
        int same = memcmp(&recovered, &baseline[1], sizeof(recovered)) == 0;
        checks_failed += !CHECKF(same, "N=%ld (%s): after the reset the results differ from a fresh context", n,
               config);
        rtMakeCurrent(NULL);
        rtDestroyContext(ctx);
        if (injected == 0)
            break; /* the whole sequence ran without an injected failure */
    }
    checks_failed += !CHECKF(n < MAX_N, "%s: the sequence still failed at N=%ld", config, n);
    return n;
}

int main(void)
{
    make_arrays();
    make_rays(rays);

    static struct outcome baseline[2];
    RTcontext ctx = rtCreateContext("threads=1");
    if (!ctx || !rtMakeCurrent(ctx)) {
        fprintf(stderr, "cannot create the baseline context\n");
        return 1;
    }
    /* The baseline runs the same two passes as each iteration. */
    current_n = -1;
    faulty_pass(&baseline[0]);
    clean_pass(&baseline[1]);
    checks_failed += !CHECKF(rtGetError() == RT_NO_ERROR, "the baseline recorded an error");
    checks_failed += !CHECKF(failures_seen == 0, "the baseline ran out of memory");
    int hit_count = 0;
    for (int i = 0; i < RAY_COUNT; i++)
        hit_count += baseline[1].hits[i].t < INFINITY;
    checks_failed += !CHECKF(hit_count > RAY_COUNT / 4, "the scene is nearly empty (%d hits)", hit_count);
    rtMakeCurrent(NULL);
    rtDestroyContext(ctx);

    static const char *const configs[2] = {"threads=1", "threads=2"};
    for (int c = 0; c < 2; c++)
        for (one_shot = 0; one_shot < 3; one_shot++) {
            failures_seen = 0;
            absorbed = 0;
            long n = sweep(configs[c], baseline);
            printf("%s, %s: %ld allocations in the sequence, %d calls reported "
                   "RT_OUT_OF_MEMORY, %d failures absorbed with the frame rendered\n",
                   configs[c],
                   one_shot == 2 ? "one failing allocation"
                   : one_shot    ? "one failing call"
                                 : "every allocation from N on",
                   n, failures_seen, absorbed);
            checks_failed += !CHECKF(failures_seen > 0, "%s: no call ever reported RT_OUT_OF_MEMORY", configs[c]);
            /* A single failing allocation reaches the optional ones
             * (docs/errors.md: at least the BVH shrink; with threads=2 the
             * worker pool), and each of those passes rendered the frame
             * exactly as without the failure (checked in sweep). */
            if (one_shot == 2)
                checks_failed += !CHECKF(absorbed > 0, "%s: no failure was absorbed", configs[c]);
        }
    printf("fault_injection: %s (%d failed checks)\n", checks_failed ? "FAILED" : "passed",
           checks_failed);
    return checks_failed != 0;
}
