/* SPDX-License-Identifier: Apache-2.0 */
/*
 * thread_invariance_threads.c - results do not depend on the thread count.
 *
 * One scene (a floor with a mipmapped checkerboard texture, a sphere
 * object placed five times - one instance a mirror, one glass -, boxes, a
 * 4000-triangle random soup; two lights; Whitted shading with shadows,
 * reflection and refraction, which carry the texture's ray cones) is built in
 * separate contexts created with threads=1, 2 and 8 (and threads=2
 * packets=off, which traces every ray alone), and rendered at
 * 256x192.  Every pixel and every query ray is computed independently by
 * the same float operations (render.h), so:
 *   - the RGBA float framebuffers are identical bit for bit (memcmp);
 *   - rtTraceRays and rtOccludedRays answers for 100k rays are identical
 *     bit for bit with 1 and 8 threads;
 *   - rendering again from the same context (with the instance list
 *     re-issued unchanged, and without re-issuing it) gives the same bits;
 *   - three application threads, each with its own context (threads=1, 2
 *     and 8), building and rendering the scene at the same time get the
 *     same bits too (contexts share no mutable state).
 * Object BVHs are built lazily by whichever render thread reaches them
 * first, so this also checks that the build does not depend on the thread
 * that runs it.  Named *_threads.c: ctest label "threads", run under
 * ThreadSanitizer by the CI.
 */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "brute_force.h"
#include "testutil.h"

#define WIDTH 256
#define HEIGHT 192
#define RAY_COUNT 100000
#define PIXELS ((size_t)WIDTH * HEIGHT * 4)

enum { FLOOR = 1, SPHERE, BOX, SOUP, MIRROR_SPHERE, GLASS_SPHERE };

static void quad(const float a[3], const float b[3], const float c[3], const float d[3])
{
    rtVertex3fv(a);
    rtVertex3fv(b);
    rtVertex3fv(c);
    rtVertex3fv(d);
}

static void define_sphere(RTuint name, const float diffuse[4], float reflectivity,
                          float transparency)
{
    const int slices = 24, stacks = 12;
    const float spec[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    rtNewObject(name);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, diffuse);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, spec);
    rtMaterialf(RT_FRONT_AND_BACK, RT_SHININESS, 40.0f);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, reflectivity);
    rtMaterialf(RT_FRONT_AND_BACK, RT_TRANSPARENCY, transparency);
    rtMaterialf(RT_FRONT_AND_BACK, RT_INDEX_OF_REFRACTION, 1.5f);
    for (int j = 0; j < stacks; j++) {
        rtBegin(RT_QUAD_STRIP);
        for (int i = 0; i <= slices; i++)
            for (int k = 1; k >= 0; k--) {
                double theta = 3.141592653589793 * (j + k) / stacks;
                double phi = 6.283185307179586 * i / slices;
                float p[3] = {(float)(sin(theta) * cos(phi)), (float)cos(theta),
                              (float)(sin(theta) * sin(phi))};
                rtNormal3fv(p);
                rtVertex3fv(p);
            }
        rtEnd();
    }
    rtEndObject();
}

enum { FLOOR_TEXTURE = 1 };

static void define_scene(void)
{
    const float grey[4] = {0.7f, 0.7f, 0.65f, 1.0f};
    /* 32x32 checks of one texel, 8 times over the floor in each direction:
     * minified towards the back, so the level of detail matters. */
    static unsigned char checks[32 * 32 * 3];
    for (int i = 0; i < 32 * 32; i++)
        memset(&checks[3 * i], (i % 32 + i / 32) % 2 ? 60 : 230, 3);
    rtBindTexture(RT_TEXTURE_2D, FLOOR_TEXTURE);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 32, 32, 0, RT_RGB, RT_UNSIGNED_BYTE, checks);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_LINEAR_MIPMAP_LINEAR);
    rtNewObject(FLOOR);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, grey);
    rtEnable(RT_TEXTURE_2D);
    rtBegin(RT_QUADS);
    rtTexCoord2f(0, 8);
    rtVertex3f(-20, 0, -40);
    rtTexCoord2f(0, 0);
    rtVertex3f(-20, 0, 0);
    rtTexCoord2f(8, 0);
    rtVertex3f(20, 0, 0);
    rtTexCoord2f(8, 8);
    rtVertex3f(20, 0, -40);
    rtEnd();
    rtDisable(RT_TEXTURE_2D);
    rtEndObject();

    const float red[4] = {0.8f, 0.15f, 0.1f, 1.0f};
    const float silver[4] = {0.1f, 0.1f, 0.1f, 1.0f};
    const float glass[4] = {0.05f, 0.05f, 0.05f, 1.0f};
    define_sphere(SPHERE, red, 0.0f, 0.0f);
    define_sphere(MIRROR_SPHERE, silver, 0.9f, 0.0f);
    define_sphere(GLASS_SPHERE, glass, 0.1f, 0.85f);

    const float blue[4] = {0.2f, 0.3f, 0.8f, 1.0f};
    rtNewObject(BOX);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, blue);
    rtShadeModel(RT_FLAT);
    rtBegin(RT_QUADS);
    for (int axis = 0; axis < 3; axis++)
        for (int side = 0; side < 2; side++) {
            float q[4][3];
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            static const int su[4] = {0, 1, 1, 0}, sv[4] = {0, 0, 1, 1};
            for (int c = 0; c < 4; c++) {
                q[c][axis] = (float)side;
                q[c][u] = (float)(side ? su[c] : sv[c]);
                q[c][v] = (float)(side ? sv[c] : su[c]);
            }
            quad(q[0], q[1], q[2], q[3]);
        }
    rtEnd();
    rtShadeModel(RT_SMOOTH);
    rtEndObject();

    /* A cloud of small random triangles with per-vertex colours. */
    struct bf_rng r;
    bf_seed(&r, 4242u);
    rtNewObject(SOUP);
    rtEnable(RT_COLOR_MATERIAL);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < 4000; i++) {
        double c[3] = {bf_range(&r, -2, 2), bf_range(&r, 0, 3), bf_range(&r, -2, 2)};
        for (int k = 0; k < 3; k++) {
            rtColor3f((float)bf_uniform(&r), (float)bf_uniform(&r), (float)bf_uniform(&r));
            rtVertex3f((float)(c[0] + bf_range(&r, -0.3, 0.3)),
                       (float)(c[1] + bf_range(&r, -0.3, 0.3)),
                       (float)(c[2] + bf_range(&r, -0.3, 0.3)));
        }
    }
    rtEnd();
    rtDisable(RT_COLOR_MATERIAL);
    rtColor3f(1, 1, 1);
    rtEndObject();
}

static void instantiate_scene(void)
{
    /* The lists set only some material properties; the others are the
     * ones current at the call (GL's display lists), which the last
     * frame's calls changed: start every frame from GL's defaults. */
    static const float amb[4] = {0.2f, 0.2f, 0.2f, 1}, dif[4] = {0.8f, 0.8f, 0.8f, 1},
                       black[4] = {0, 0, 0, 1};
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, amb);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, dif);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
    rtMaterialf(RT_FRONT_AND_BACK, RT_SHININESS, 0);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 0);
    rtMaterialf(RT_FRONT_AND_BACK, RT_TRANSPARENCY, 0);
    rtMaterialf(RT_FRONT_AND_BACK, RT_INDEX_OF_REFRACTION, 1);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtTranslatef(0.0f, -2.0f, 0.0f);
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    static const float spheres[5][4] = {{-4, 1.5f, -14, 1.5f},
                                        {0, 2, -18, 2},
                                        {4.5f, 1, -12, 1},
                                        {-1.5f, 1, -9, 1},
                                        {6, 2.5f, -20, 2.5f}};
    for (int i = 0; i < 5; i++) {
        rtPushMatrix();
        rtTranslatef(spheres[i][0], spheres[i][1], spheres[i][2]);
        rtScalef(spheres[i][3], spheres[i][3], spheres[i][3]);
        rtInstantiateObject(i == 1 ? MIRROR_SPHERE : i == 3 ? GLASS_SPHERE : SPHERE);
        rtPopMatrix();
    }
    for (int i = 0; i < 3; i++) {
        rtPushMatrix();
        rtTranslatef(-8.0f + 5.0f * (float)i, 0.0f, -24.0f + 2.0f * (float)i);
        rtRotatef(25.0f * (float)i + 10.0f, 0.0f, 1.0f, 0.0f);
        rtScalef(2.0f, 1.0f + (float)i, 1.5f);
        rtInstantiateObject(BOX);
        rtPopMatrix();
    }
    rtPushMatrix();
    rtTranslatef(1.0f, 0.0f, -28.0f);
    rtRotatef(30.0f, 1.0f, 1.0f, 0.0f);
    rtInstantiateObject(SOUP);
    rtPopMatrix();
    rtLoadIdentity();
}

static void camera_and_lights(void)
{
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 100.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    const float sun[4] = {-0.3f, 1.0f, 0.5f, 0.0f};
    const float lamp[4] = {5.0f, 8.0f, -6.0f, 1.0f};
    const float dim[4] = {0.6f, 0.55f, 0.5f, 1.0f};
    rtLightfv(RT_LIGHT0, RT_POSITION, sun);
    rtLightfv(RT_LIGHT0 + 1, RT_POSITION, lamp);
    rtLightfv(RT_LIGHT0 + 1, RT_DIFFUSE, dim);
    rtLightfv(RT_LIGHT0 + 1, RT_SPECULAR, dim);
    rtLightf(RT_LIGHT0 + 1, RT_LINEAR_ATTENUATION, 0.02f);
    rtEnable(RT_LIGHT0);
    rtEnable(RT_LIGHT0 + 1);
    rtShadingMode(RT_WHITTED);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 5);
    rtClearColor(0.2f, 0.3f, 0.5f, 0.0f);
    rtViewport(0, 0, WIDTH, HEIGHT);
}

static void make_rays(RTray *rays)
{
    struct bf_rng r;
    bf_seed(&r, 99u);
    for (int i = 0; i < RAY_COUNT; i++) {
        double target[3] = {bf_range(&r, -10, 10), bf_range(&r, -2, 4), bf_range(&r, -30, -8)};
        double org[3] = {bf_range(&r, -3, 3), bf_range(&r, 0, 6), bf_range(&r, 0, 5)};
        for (int k = 0; k < 3; k++) {
            rays[i].org[k] = (float)org[k];
            rays[i].dir[k] = (float)(target[k] - org[k]);
        }
        rays[i].tmin = (float)bf_range(&r, 0.0, 0.2);
        rays[i].tmax = bf_uniform(&r) < 0.5 ? INFINITY : (float)bf_range(&r, 0.5, 1.5);
    }
}

/* Everything one context produces. */
struct results {
    const char *config;
    int with_queries;
    float *image;
    float *image_again;
    float *image_reissued;
    RThit *hits;
    RTboolean *occluded;
    RTenum error;
    RTint threads;
};

/* Builds the scene in a new context and renders; no checks here (this
 * runs on application threads too), only results and the first error. */
static void produce(struct results *res, const RTray *rays)
{
    RTcontext ctx = rtCreateContext(res->config);
    if (!ctx || !rtMakeCurrent(ctx)) {
        res->error = 0xFFFF;
        return;
    }
    res->image = malloc(PIXELS * sizeof(float));
    res->image_again = malloc(PIXELS * sizeof(float));
    res->image_reissued = malloc(PIXELS * sizeof(float));
    camera_and_lights();
    define_scene();
    instantiate_scene();
    rtRenderFrame();
    rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, res->image);
    rtRenderFrame();
    rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, res->image_again);
    instantiate_scene();
    rtRenderFrame();
    rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, res->image_reissued);
    if (res->with_queries) {
        res->hits = malloc(RAY_COUNT * sizeof(*res->hits));
        res->occluded = malloc(RAY_COUNT);
        rtTraceRays(RAY_COUNT, rays, res->hits);
        rtOccludedRays(RAY_COUNT, rays, res->occluded);
    }
    rtGetIntegerv(RT_THREADS, &res->threads);
    res->error = rtGetError();
    rtMakeCurrent(NULL);
    rtDestroyContext(ctx);
}

static void free_results(struct results *res)
{
    free(res->image);
    free(res->image_again);
    free(res->image_reissued);
    free(res->hits);
    free(res->occluded);
}

struct job {
    struct results res;
    const RTray *rays;
};

static void *run_job(void *arg)
{
    struct job *job = arg;
    produce(&job->res, job->rays);
    return NULL;
}

static int images_equal(const float *a, const float *b)
{
    return a && b && memcmp(a, b, PIXELS * sizeof(float)) == 0;
}

/* Number of pixels that differ in any bit, for the failure message. */
static int differing_pixels(const float *a, const float *b)
{
    int n = 0;
    if (!a || !b)
        return -1;
    for (size_t p = 0; p < PIXELS; p += 4)
        n += memcmp(&a[p], &b[p], 4 * sizeof(float)) != 0;
    return n;
}

int main(void)
{
    clock_t start = clock();
    RTray *rays = malloc(RAY_COUNT * sizeof(*rays));
    make_rays(rays);

    tu_section("threads=1, 2, 8 in turn, and 2 without packets");
    /* The last: packets=off (docs/context.md) traces every camera and
     * query ray alone, the others trace coherent ones in packets. */
    static const char *const configs[4] = {"threads=1", "threads=2", "threads=8",
                                           "threads=2 packets=off"};
    static const int thread_counts[4] = {1, 2, 8, 2};
    struct results seq[4];
    memset(seq, 0, sizeof(seq));
    for (int i = 0; i < 4; i++) {
        seq[i].config = configs[i];
        seq[i].with_queries = i != 1;
        produce(&seq[i], rays);
        CHECK_INT(seq[i].error, RT_NO_ERROR);
        CHECK_INT(seq[i].threads, thread_counts[i]);
    }
    /* The image is not trivial: most pixels hit something and vary. */
    int background = 0;
    for (size_t p = 0; p < PIXELS; p += 4)
        background += seq[0].image[p + 3] == 0.0f;
    CHECK(background < WIDTH * HEIGHT / 2);
    for (int i = 1; i < 4; i++) {
        if (!CHECK(images_equal(seq[0].image, seq[i].image)))
            fprintf(stderr, "  threads=1 vs %s: %d pixels differ\n", configs[i],
                    differing_pixels(seq[0].image, seq[i].image));
    }
    for (int i = 0; i < 4; i++) {
        if (!CHECK(images_equal(seq[i].image, seq[i].image_again)))
            fprintf(stderr, "  %s rendered twice: %d pixels differ\n", configs[i],
                    differing_pixels(seq[i].image, seq[i].image_again));
        if (!CHECK(images_equal(seq[i].image, seq[i].image_reissued)))
            fprintf(stderr, "  %s with the instances re-issued: %d pixels differ\n", configs[i],
                    differing_pixels(seq[i].image, seq[i].image_reissued));
    }
    CHECK(memcmp(seq[0].hits, seq[2].hits, RAY_COUNT * sizeof(RThit)) == 0);
    CHECK(memcmp(seq[0].occluded, seq[2].occluded, RAY_COUNT) == 0);
    CHECK(memcmp(seq[0].hits, seq[3].hits, RAY_COUNT * sizeof(RThit)) == 0);
    CHECK(memcmp(seq[0].occluded, seq[3].occluded, RAY_COUNT) == 0);
    int hit_count = 0;
    for (int i = 0; i < RAY_COUNT; i++)
        hit_count += seq[0].hits[i].t < INFINITY;
    printf("   %d of %d rays hit; %d background pixels\n", hit_count, RAY_COUNT, background);
    CHECK(hit_count > RAY_COUNT / 10);

    tu_section("three contexts rendering at once");
    struct job jobs[3];
    pthread_t tids[3];
    memset(jobs, 0, sizeof(jobs));
    for (int i = 0; i < 3; i++) {
        jobs[i].res.config = configs[i];
        jobs[i].res.with_queries = 1;
        jobs[i].rays = rays;
        CHECK_INT(pthread_create(&tids[i], NULL, run_job, &jobs[i]), 0);
    }
    for (int i = 0; i < 3; i++)
        pthread_join(tids[i], NULL);
    for (int i = 0; i < 3; i++) {
        CHECK_INT(jobs[i].res.error, RT_NO_ERROR);
        if (!CHECK(images_equal(seq[0].image, jobs[i].res.image)))
            fprintf(stderr, "  concurrent %s: %d pixels differ\n", configs[i],
                    differing_pixels(seq[0].image, jobs[i].res.image));
        CHECK(images_equal(seq[0].image, jobs[i].res.image_again));
        CHECK(jobs[i].res.hits &&
              memcmp(seq[0].hits, jobs[i].res.hits, RAY_COUNT * sizeof(RThit)) == 0);
        CHECK(jobs[i].res.occluded &&
              memcmp(seq[0].occluded, jobs[i].res.occluded, RAY_COUNT) == 0);
        free_results(&jobs[i].res);
    }
    for (int i = 0; i < 4; i++)
        free_results(&seq[i]);
    free(rays);
    printf("cpu time %.2f s\n", (double)(clock() - start) / CLOCKS_PER_SEC);
    return test_summary("thread_invariance_threads");
}
