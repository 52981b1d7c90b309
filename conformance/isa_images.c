/* SPDX-License-Identifier: Apache-2.0 */
/*
 * isa_images.c - images and ray answers bit for bit across the traversal
 * ISA tables, hence across layouts (scalar: the binary walk; sse4: the
 * 4-wide walk; avx2, avx512: the 8-wide walk; lib/trace/kernels.h), and
 * across thread counts.
 *
 * One scene (a sphere with smooth normals, a grid-snapped triangle soup
 * with shared planes and slivers, a floor, under four instance matrices)
 * is rendered with eye light and Whitted shading (RGBA float) and
 * queried with 20,000 rays (rtTraceRays and rtOccludedRays) in a context
 * per configuration: "threads=1 isa=scalar" is the reference, every other
 * ISA this machine runs is tried with threads=1 and threads=3.  Every
 * float of every image and every hit record must equal the reference's
 * (memcmp); an ISA the CPU cannot run is skipped (rtCreateContext gives
 * NULL), so on an AVX2 machine the 4- and 8-wide layouts are both
 * compared with the binary one.
 */
#include <rt/rt.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "testutil.h"

#define WIDTH 96
#define HEIGHT 72
#define RAYS 20000

static uint64_t rng_state = 12345;

static float unit(void)
{
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return (float)(rng_state >> 40) * (1.0f / 16777216.0f);
}

static void define_scene(void)
{
    rng_state = 777; /* the same soup in every context */
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    /* 1: a sphere, smooth normals. */
    rtNewObject(1);
    rtBegin(RT_TRIANGLES);
    const int slices = 24, stacks = 12;
    for (int i = 0; i < stacks; i++) {
        for (int j = 0; j < slices; j++) {
            float p[4][3];
            for (int c = 0; c < 4; c++) {
                int a = i + (c >> 1), b = j + (c & 1);
                float th = 3.14159265f * (float)a / (float)stacks;
                float ph = 6.2831853f * (float)b / (float)slices;
                p[c][0] = sinf(th) * cosf(ph);
                p[c][1] = cosf(th);
                p[c][2] = sinf(th) * sinf(ph);
            }
            static const int tri[6] = {0, 1, 2, 1, 3, 2};
            for (int k = 0; k < 6; k++) {
                rtNormal3fv(p[tri[k]]);
                rtVertex3fv(p[tri[k]]);
            }
        }
    }
    rtEnd();
    rtEndObject();
    /* 2: a grid-snapped soup: shared planes, coincident edges, slivers. */
    rtNewObject(2);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 0.5f);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < 3 * 600; i++) {
        float v[3];
        for (int k = 0; k < 3; k++)
            v[k] = roundf((unit() * 4.0f - 2.0f) * 4.0f) / 4.0f;
        rtVertex3fv(v);
    }
    rtEnd();
    rtEndObject();
    /* 3: a floor. */
    rtNewObject(3);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(-20, -2, -20);
    rtVertex3f(20, -2, 20);
    rtVertex3f(20, -2, -20);
    rtVertex3f(-20, -2, -20);
    rtVertex3f(-20, -2, 20);
    rtVertex3f(20, -2, 20);
    rtEnd();
    rtEndObject();

    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 100.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    const float sun[4] = {0.4f, 1.0f, 0.6f, 0.0f};
    rtLightfv(RT_LIGHT0, RT_POSITION, sun);
    rtEnable(RT_LIGHT0);
    rtViewport(0, 0, WIDTH, HEIGHT);
    rtBeginFrame();
    rtTranslatef(0.0f, 0.0f, -8.0f);
    rtPushMatrix();
    rtTranslatef(-2.0f, 0.0f, 0.0f);
    rtInstantiateObject(1);
    rtPopMatrix();
    rtPushMatrix();
    rtTranslatef(2.0f, 0.5f, -1.0f);
    rtRotatef(30.0f, 0.3f, 1.0f, 0.2f);
    rtScalef(1.0f, 2.0f, 0.5f);
    rtInstantiateObject(1);
    rtPopMatrix();
    rtPushMatrix();
    rtRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    rtInstantiateObject(2);
    rtPopMatrix();
    rtInstantiateObject(3);
    rtLoadIdentity();
}

struct answers {
    float image[2][WIDTH * HEIGHT * 4];
    RThit hits[RAYS];
    RTboolean occluded[RAYS];
};

static int run(const char *config, const RTray *rays, struct answers *out)
{
    RTcontext ctx = rtCreateContext(config);
    if (!ctx)
        return 0;
    rtMakeCurrent(ctx);
    define_scene();
    static const RTenum modes[2] = {RT_EYE_LIGHT, RT_WHITTED};
    for (int m = 0; m < 2; m++) {
        rtShadingMode(modes[m]);
        rtRenderFrame();
        rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, out->image[m]);
    }
    rtTraceRays(RAYS, rays, out->hits);
    rtOccludedRays(RAYS, rays, out->occluded);
    CHECK_NO_ERR();
    rtMakeCurrent(NULL);
    rtDestroyContext(ctx);
    return 1;
}

int main(void)
{
    tu_section("isa_images");
    RTray *rays = malloc(RAYS * sizeof(*rays));
    struct answers *ref = malloc(sizeof(*ref));
    struct answers *got = malloc(sizeof(*got));
    if (!rays || !ref || !got)
        return 1;
    for (int i = 0; i < RAYS; i++) {
        for (int k = 0; k < 3; k++) {
            rays[i].org[k] = unit() * 6.0f - 3.0f;
            rays[i].dir[k] = unit() * 2.0f - 1.0f;
        }
        rays[i].org[2] += (i & 1) ? 0.0f : -8.0f;
        if (i % 5 == 0)
            rays[i].dir[i % 3] = 0.0f; /* axis-parallel components */
        if (rays[i].dir[0] == 0.0f && rays[i].dir[1] == 0.0f && rays[i].dir[2] == 0.0f)
            rays[i].dir[2] = -1.0f;
        rays[i].tmin = 0.0f;
        rays[i].tmax = (i % 7 == 0) ? 3.0f : INFINITY;
    }
    CHECK(run("threads=1 isa=scalar", rays, ref));
    /* The comparison means something only if the scene is hit. */
    int hit_count = 0;
    for (int i = 0; i < RAYS; i++)
        hit_count += ref->hits[i].t < INFINITY;
    printf("  reference: %d of %d rays hit\n", hit_count, RAYS);
    CHECK(hit_count > RAYS / 10);
    static const char *const configs[] = {"threads=1 isa=sse4", "threads=3 isa=sse4",
                                          "threads=1 isa=avx2", "threads=3 isa=avx2",
                                          "threads=1 isa=avx512", "threads=3 isa=avx512",
                                          "threads=3 isa=scalar"};
    for (size_t c = 0; c < sizeof(configs) / sizeof(configs[0]); c++) {
        if (!run(configs[c], rays, got)) {
            printf("  %s: not runnable here, skipped\n", configs[c]);
            continue;
        }
        int same_images = memcmp(ref->image, got->image, sizeof(ref->image)) == 0;
        int same_hits = memcmp(ref->hits, got->hits, sizeof(ref->hits)) == 0;
        int same_occ = memcmp(ref->occluded, got->occluded, sizeof(ref->occluded)) == 0;
        CHECKF(same_images && same_hits && same_occ,
               "%s: images %s, hits %s, occlusion %s (against threads=1 isa=scalar)", configs[c],
               same_images ? "same" : "DIFFER", same_hits ? "same" : "DIFFER",
               same_occ ? "same" : "DIFFER");
        printf("  %s: images, hits and occlusion bit-identical to threads=1 isa=scalar\n",
               configs[c]);
    }
    free(rays);
    free(ref);
    free(got);
    return test_summary("isa_images");
}
