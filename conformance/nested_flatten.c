/* SPDX-License-Identifier: Apache-2.0 */
/*
 * nested_flatten.c - a nested static hierarchy flattened into one BVH
 * (flatten=on) answers exactly as the same hierarchy kept as instances
 * (flatten=off): every rtTraceRays hit bit for bit (t, u, v, instance,
 * object, primitive), every rtOccludedRays answer, and rendered images
 * (RGBA float, bit for bit), before and after a shared child is redefined
 * by name (docs/instances.md, "Nested static hierarchies").
 *
 * The scene: four levels (ROBOT calls BODY calls ARM calls BALL, and
 * ROBOT calls BALL directly), shared children (ARM twice in BODY, BALL
 * twice in ARM), mirrored matrices (negative determinants, at two levels,
 * so that a mirrored child of a mirrored parent is direct again), matrix
 * and state calls between the calls (so lists are cut into segments), and
 * the whole robot placed twice; a floor outside any nesting.  The meshes
 * are tessellated with shared edges and vertices, and one BALL is placed
 * exactly on top of another and PLATE holds its grid twice (coincident
 * triangles), so rays meet exact ties in t, which the hit rule settles by
 * instance, then primitive: a
 * flattened walk that mapped a slot to the wrong instance or primitive,
 * or settled ties differently, fails here.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

enum { BALL = 1, PLATE = 2, ARM = 3, BODY = 4, ROBOT = 5, FLOOR = 6, CHAIN = 7, TOWER = 8 };

#define WIDTH 96
#define HEIGHT 72
#define RAYS 20000

static void vertex(double r, double theta, double phi)
{
    const double x = sin(theta) * cos(phi), y = cos(theta), z = sin(theta) * sin(phi);
    rtNormal3f((float)x, (float)y, (float)z);
    rtVertex3d(r * x, r * y, r * z);
}

/* A sphere of radius r, rings x sectors quads of two triangles. */
static void define_ball(double r, int rings, int sectors)
{
    const double pi = 3.14159265358979323846;
    rtNewObject(BALL);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < rings; i++)
        for (int j = 0; j < sectors; j++) {
            const double t0 = pi * i / rings, t1 = pi * (i + 1) / rings;
            const double p0 = 2 * pi * j / sectors, p1 = 2 * pi * (j + 1) / sectors;
            vertex(r, t0, p0);
            vertex(r, t1, p0);
            vertex(r, t1, p1);
            vertex(r, t0, p0);
            vertex(r, t1, p1);
            vertex(r, t0, p1);
        }
    rtEnd();
    rtEndObject();
}

static void grid(float size, int n, float y)
{
    rtNormal3f(0.0f, 1.0f, 0.0f);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            const float x0 = -size + 2 * size * i / n, x1 = -size + 2 * size * (i + 1) / n;
            const float z0 = -size + 2 * size * j / n, z1 = -size + 2 * size * (j + 1) / n;
            rtVertex3f(x0, y, z0);
            rtVertex3f(x0, y, z1);
            rtVertex3f(x1, y, z1);
            rtVertex3f(x0, y, z0);
            rtVertex3f(x1, y, z1);
            rtVertex3f(x1, y, z0);
        }
    rtEnd();
}

static void define_scene(void)
{
    define_ball(0.5, 8, 12);
    /* PLATE: the same grid twice, so every hit on it is a tie in t inside
     * one object, settled by the lower primitive. */
    rtNewObject(PLATE);
    grid(0.6f, 3, 0.0f);
    grid(0.6f, 3, 0.0f);
    rtEndObject();

    /* ARM: BALL twice (the second mirrored in x), its own plate between. */
    rtNewObject(ARM);
    rtPushMatrix();
    rtTranslatef(0.0f, 0.6f, 0.0f);
    rtCallList(BALL);
    rtPopMatrix();
    rtColor3f(0.9f, 0.3f, 0.2f);
    rtPushMatrix();
    rtRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    rtCallList(PLATE);
    rtPushMatrix();
    rtScalef(-1.0f, 1.0f, 1.0f); /* mirrored: determinant < 0 */
    rtTranslatef(0.7f, -0.4f, 0.1f);
    rtCallList(BALL);
    rtPopMatrix();
    rtPopMatrix();
    /* The same BALL again exactly where the first one is (the same
     * matrix calls from the same level): coincident triangles, every hit
     * on them a tie in t settled by the lower instance. */
    rtPushMatrix();
    rtTranslatef(0.0f, 0.6f, 0.0f);
    rtCallList(BALL);
    rtPopMatrix();
    rtEndObject();

    /* BODY: ARM twice, one mirrored in y, a plate of its own. */
    rtNewObject(BODY);
    grid(1.0f, 4, -1.0f);
    rtPushMatrix();
    rtTranslatef(-1.2f, 0.0f, 0.0f);
    rtRotatef(35.0f, 0.0f, 1.0f, 0.0f);
    rtCallList(ARM);
    rtPopMatrix();
    rtPushMatrix();
    rtTranslatef(1.2f, 0.2f, 0.3f);
    rtScalef(1.0f, -1.0f, 1.0f); /* mirrored at a second level */
    rtCallList(ARM);
    rtPopMatrix();
    rtEndObject();

    /* ROBOT: BODY under a general matrix, BALL directly (level 2 and 4
     * children of one root). */
    rtNewObject(ROBOT);
    const float shear[16] = {1.0f, 0.0f, 0.1f, 0.0f, 0.2f, 0.9f, 0.0f, 0.0f,
                             0.0f, 0.15f, 1.1f, 0.0f, 0.1f, 0.3f, -0.2f, 1.0f};
    rtPushMatrix();
    rtMultMatrixf(shear);
    rtCallList(BODY);
    rtPopMatrix();
    rtTranslatef(0.0f, 1.6f, 0.0f);
    rtScalef(0.6f, 0.6f, 0.6f);
    rtCallList(BALL);
    rtEndObject();

    rtNewObject(FLOOR);
    grid(8.0f, 8, -2.5f);
    rtEndObject();
}

static void issue_frame(void)
{
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 100.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    const float light[4] = {-0.4f, 1.0f, 0.6f, 0.0f};
    rtLightfv(RT_LIGHT0, RT_POSITION, light);
    rtEnable(RT_LIGHT0);
    rtEnable(RT_LIGHTING);
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtPushMatrix();
    rtTranslatef(-1.5f, 0.0f, -7.0f);
    rtRotatef(25.0f, 0.0f, 1.0f, 0.0f);
    rtInstantiateObject(ROBOT);
    rtPopMatrix();
    rtPushMatrix();
    rtTranslatef(1.8f, -0.3f, -8.0f);
    rtScalef(-1.0f, 1.0f, 1.0f); /* the whole robot mirrored */
    rtRotatef(-40.0f, 0.0f, 1.0f, 0.0f);
    rtInstantiateObject(ROBOT);
    rtPopMatrix();
}

/* Deterministic rays: primary rays through a grid and random rays from
 * random points near the robots in random directions. */
static void make_rays(RTray *rays)
{
    uint32_t s = 12345u;
    for (int i = 0; i < RAYS; i++) {
        RTray *r = &rays[i];
        if (i < RAYS / 2) {
            const int x = i % 100, y = i / 100;
            r->org[0] = r->org[1] = r->org[2] = 0.0f;
            r->dir[0] = -0.6f + 1.2f * (float)x / 99.0f;
            r->dir[1] = -0.45f + 0.9f * (float)y / 99.0f;
            r->dir[2] = -1.0f;
        } else {
            float v[6];
            for (int k = 0; k < 6; k++) {
                s = s * 1664525u + 1013904223u;
                v[k] = (float)(s >> 8) / 16777216.0f * 2.0f - 1.0f;
            }
            r->org[0] = 4.0f * v[0];
            r->org[1] = 2.0f * v[1];
            r->org[2] = -7.5f + 3.0f * v[2];
            r->dir[0] = v[3];
            r->dir[1] = v[4];
            r->dir[2] = v[5] == 0.0f ? 0.5f : v[5];
        }
        r->tmin = 0.0f;
        r->tmax = INFINITY;
    }
}

struct result {
    RThit *hits;
    RTboolean *occluded;
    float *image;
    RTint groups, flattened;
};

static void run(struct result *out, const RTray *rays)
{
    out->hits = calloc(RAYS, sizeof(*out->hits));
    out->occluded = calloc(RAYS, sizeof(*out->occluded));
    out->image = calloc(4 * (size_t)WIDTH * HEIGHT, sizeof(float));
    if (!out->hits || !out->occluded || !out->image) {
        fprintf(stderr, "fatal: out of memory\n");
        exit(1);
    }
    issue_frame();
    rtTraceRays(RAYS, rays, out->hits);
    rtOccludedRays(RAYS, rays, out->occluded);
    rtGetIntegerv(RT_NESTED_GROUPS, &out->groups);
    rtGetIntegerv(RT_FLATTENED_GROUPS, &out->flattened);
    issue_frame();
    rtShadingMode(RT_WHITTED);
    rtViewport(0, 0, WIDTH, HEIGHT);
    rtRenderFrame();
    rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, out->image);
    CHECK_NO_ERR();
}

static void release(struct result *r)
{
    free(r->hits);
    free(r->occluded);
    free(r->image);
}

/* Every answer of a equals b's, bit for bit. */
static void compare(const struct result *a, const struct result *b, const char *what)
{
    int hit_diff = 0, occl_diff = 0, first = -1;
    for (int i = 0; i < RAYS; i++) {
        if (memcmp(&a->hits[i], &b->hits[i], sizeof(RThit)) != 0) {
            if (first < 0)
                first = i;
            hit_diff++;
        }
        occl_diff += a->occluded[i] != b->occluded[i];
    }
    if (first >= 0)
        fprintf(stderr,
                "%s: ray %d: t %.9g/%.9g u %.9g/%.9g v %.9g/%.9g instance %u/%u object %u/%u "
                "primitive %u/%u\n",
                what, first, a->hits[first].t, b->hits[first].t, a->hits[first].u,
                b->hits[first].u, a->hits[first].v, b->hits[first].v, a->hits[first].instance,
                b->hits[first].instance, a->hits[first].object, b->hits[first].object,
                a->hits[first].primitive, b->hits[first].primitive);
    CHECK_INT(hit_diff, 0);
    CHECK_INT(occl_diff, 0);
    CHECK(memcmp(a->image, b->image, 4 * (size_t)WIDTH * HEIGHT * sizeof(float)) == 0);
}

/* The hits name many instances and primitives, coincident ties among
 * them (otherwise the comparison would prove little). */
static void check_coverage(const struct result *r)
{
    unsigned char seen[256] = {0};
    int instances = 0, hits = 0, high_prim = 0;
    for (int i = 0; i < RAYS; i++) {
        if (r->hits[i].instance == RT_INVALID_ID)
            continue;
        hits++;
        high_prim += r->hits[i].primitive > 50;
        if (r->hits[i].instance < 256 && !seen[r->hits[i].instance]++)
            instances++;
    }
    CHECK(hits > RAYS / 4);
    CHECK(instances >= 10);
    CHECK(high_prim > 100);
}

/* One context per mode, the same calls in each. */
static void scene_in(const char *config, const RTray *rays, struct result *before,
                     struct result *after, char *configuration, size_t size)
{
    RTcontext ctx = tu_make_context(config);
    snprintf(configuration, size, "%s", rtGetString(RT_CONFIGURATION));
    define_scene();
    run(before, rays);
    /* Redefine the shared leaf by name: every parent shows it, and a
     * flattened parent must be rebuilt. */
    define_ball(0.45, 6, 10);
    run(after, rays);
    tu_destroy_context(ctx);
}

/*
 * Laziness, sharing and the static rule: with flatten=on nothing is built
 * before a ray needs it, the two calls of ROBOT share one flattened BVH,
 * and BALL's own BVH is never built (its triangles are reached through
 * the flattened one).  With flatten=auto a group whose child was just
 * redefined is not static: it stays instanced for that top level, and is
 * flattened again once unchanged (when auto flattens it at all).
 */
static void check_lazy(const RTray *rays)
{
    RThit *hits = calloc(RAYS, sizeof(*hits));
    if (!hits)
        exit(1);
    RTcontext ctx = tu_make_context("flatten=on");
    define_scene();
    issue_frame();
    rtFinish();
    RTint builds = -1, built = -1, flattened = -1;
    rtGetIntegerv(RT_STAT_OBJECT_BUILDS, &builds);
    CHECK_INT(builds, 0);
    rtGetIntegerv(RT_FLATTENED_GROUPS, &flattened);
    CHECK_INT(flattened, 2);
    rtTraceRays(RAYS, rays, hits);
    rtGetIntegerv(RT_STAT_OBJECT_BUILDS, &builds);
    CHECK_INT(builds, 2); /* FLOOR, and one flattened BVH for both robots */
    rtGetObjectiv(BALL, RT_OBJECT_BUILT, &built);
    CHECK_INT(built, RT_FALSE);
    rtGetObjectiv(FLOOR, RT_OBJECT_BUILT, &built);
    CHECK_INT(built, RT_TRUE);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);

    /* A hierarchy whose members overlap heavily (twelve balls nearly on
     * top of each other), which flatten=auto flattens. */
    ctx = tu_make_context("flatten=auto");
    define_ball(0.5, 8, 12);
    rtNewObject(CHAIN);
    for (int k = 0; k < 6; k++) {
        rtCallList(BALL);
        rtTranslatef(0.02f, 0.0f, 0.0f);
    }
    rtEndObject();
    rtNewObject(TOWER);
    rtCallList(CHAIN);
    rtTranslatef(0.0f, 0.03f, 0.0f);
    rtCallList(CHAIN);
    rtEndObject();
    /* Frames as an application renders them (rtRenderFrame ends each):
     * the redefinition at frame 1 makes the group not static (its
     * structure changed; at frame 2 BALL is still classified as just
     * changed), and it is flattened again at frame 3. */
    RTint flat[4];
    rtViewport(0, 0, 8, 8);
    for (int f = 0; f < 4; f++) {
        if (f == 1)
            define_ball(0.45, 6, 10);
        rtBeginFrame();
        rtPushMatrix();
        rtTranslatef(0.0f, 0.0f, -5.0f);
        rtInstantiateObject(TOWER);
        rtPopMatrix();
        rtRenderFrame();
        rtGetIntegerv(RT_FLATTENED_GROUPS, &flat[f]);
    }
    CHECK_INT(flat[0], 1);
    CHECK_INT(flat[1], 0);
    CHECK_INT(flat[2], 0);
    CHECK_INT(flat[3], 1);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
    free(hits);
}

int main(void)
{
    RTray *rays = calloc(RAYS, sizeof(*rays));
    if (!rays)
        return 1;
    make_rays(rays);
    struct result off[2], on[2], automatic[2], single[2];
    char conf_off[256], conf_on[256], conf_auto[256], conf_single[256];
    scene_in("flatten=off", rays, &off[0], &off[1], conf_off, sizeof(conf_off));
    scene_in("flatten=on", rays, &on[0], &on[1], conf_on, sizeof(conf_on));
    scene_in("", rays, &automatic[0], &automatic[1], conf_auto, sizeof(conf_auto));
    /* The flat walk ray by ray (packets=off) against the packet walk's. */
    scene_in("flatten=on packets=off", rays, &single[0], &single[1], conf_single,
             sizeof(conf_single));

    CHECK(strstr(conf_off, "flatten=off") != NULL);
    CHECK(strstr(conf_on, "flatten=on") != NULL);
    CHECK(strstr(conf_auto, "flatten=auto") != NULL);
    /* Two robot calls, each one group; flattened only with flatten=on. */
    for (int k = 0; k < 2; k++) {
        CHECK_INT(off[k].groups, 2);
        CHECK_INT(off[k].flattened, 0);
        CHECK_INT(on[k].groups, 2);
        CHECK_INT(on[k].flattened, 2);
        CHECK_INT(automatic[k].groups, 2);
    }
    check_coverage(&off[0]);
    compare(&on[0], &off[0], "flatten=on vs off");
    compare(&on[1], &off[1], "flatten=on vs off, BALL redefined");
    compare(&automatic[0], &off[0], "flatten=auto vs off");
    compare(&automatic[1], &off[1], "flatten=auto vs off, BALL redefined");
    compare(&single[0], &off[0], "flatten=on packets=off vs flatten=off");
    compare(&single[1], &off[1], "flatten=on packets=off vs flatten=off, BALL redefined");
    /* The redefinition shows (a stale flattened BVH would keep the old
     * ball, and the comparison above would catch it). */
    int changed = 0;
    for (int i = 0; i < RAYS; i++)
        changed += memcmp(&off[0].hits[i], &off[1].hits[i], sizeof(RThit)) != 0;
    CHECK(changed > 100);

    check_lazy(rays);

    /* The key is validated. */
    char reason[256];
    CHECK(rtCreateContextWithReason("flatten=maybe", sizeof(reason), reason) == NULL);
    CHECK(strstr(reason, "flatten") != NULL);

    for (int k = 0; k < 2; k++) {
        release(&off[k]);
        release(&on[k]);
        release(&automatic[k]);
        release(&single[k]);
    }
    free(rays);
    return test_summary("nested_flatten");
}
