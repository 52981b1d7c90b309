/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_nested.c - rtbench nested: a nested static hierarchy flattened
 * into one BVH against the same hierarchy kept as instances
 * (flatten=on|off, docs/instances.md), and what flatten=auto chose.
 *
 * Scene: ROBOT calls BODY twice, BODY calls ARM four times (a star around
 * y), ARM calls BALL four times along a chain and has a plate; ROBOT adds
 * a BALL head: 41 segments in four levels per robot call, the robot
 * placed on a 3 x 3 grid (every call shares one flattened BVH).  Three
 * variants by the spacing of the balls of a chain (radius 0.5):
 * "stacked" (0.08: the four balls nearly coincide, every ray meets all
 * their boxes, the worst of the overlap of Wald, Benthin and Slusallek
 * (2003) sec. 6), "dense" (0.7: neighbours overlap) and "sparse" (3:
 * apart).  Rays: the primary rays of a 320 x 240 camera
 * (--quick: 64 x 48) through rtTraceRays on one thread.
 *
 * Reported per mode: node, triangle and instance tests per ray (the
 * flattened walk counts a ray transformation per member whose triangles
 * it tests as an instance test), the lazy builds of the first trace
 * (object BVHs or flattened BVHs, ms), and process CPU time per ray
 * (median of --runs traces; CPU time, not wall time, because the machine
 * may be shared).  Every mode's hits must equal flatten=off's bit for bit
 * (exit status 3 otherwise).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <rt/rt.h>

#include "bench.h"

enum { BALL = 1, PLATE = 2, ARM = 3, BODY = 4, ROBOT = 5 };

static void ball_vertex(double theta, double phi)
{
    const double x = sin(theta) * cos(phi), y = cos(theta), z = sin(theta) * sin(phi);
    rtNormal3f((float)x, (float)y, (float)z);
    rtVertex3f((float)(0.5 * x), (float)(0.5 * y), (float)(0.5 * z));
}

static void define_scene(int rings, float spacing)
{
    const double pi = 3.14159265358979323846;
    const int sectors = rings * 3 / 2;
    rtNewObject(BALL);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < rings; i++)
        for (int j = 0; j < sectors; j++) {
            const double t0 = pi * i / rings, t1 = pi * (i + 1) / rings;
            const double p0 = 2 * pi * j / sectors, p1 = 2 * pi * (j + 1) / sectors;
            ball_vertex(t0, p0);
            ball_vertex(t1, p0);
            ball_vertex(t1, p1);
            ball_vertex(t0, p0);
            ball_vertex(t1, p1);
            ball_vertex(t0, p1);
        }
    rtEnd();
    rtEndObject();

    rtNewObject(PLATE);
    rtNormal3f(0.0f, 1.0f, 0.0f);
    rtBegin(RT_QUADS);
    rtVertex3f(-0.6f, -0.55f, -0.6f);
    rtVertex3f(-0.6f, -0.55f, 0.6f);
    rtVertex3f(0.6f + 3.0f * spacing, -0.55f, 0.6f);
    rtVertex3f(0.6f + 3.0f * spacing, -0.55f, -0.6f);
    rtEnd();
    rtEndObject();

    rtNewObject(ARM);
    rtCallList(PLATE);
    for (int k = 0; k < 4; k++) {
        rtCallList(BALL);
        rtTranslatef(spacing, 0.05f, 0.0f);
    }
    rtEndObject();

    rtNewObject(BODY);
    for (int k = 0; k < 4; k++) {
        rtPushMatrix();
        rtRotatef(90.0f * (float)k + 10.0f, 0.0f, 1.0f, 0.0f);
        rtCallList(ARM);
        rtPopMatrix();
    }
    rtEndObject();

    rtNewObject(ROBOT);
    rtCallList(BODY);
    rtPushMatrix();
    rtTranslatef(0.0f, 1.2f, 0.0f);
    rtRotatef(45.0f, 0.0f, 1.0f, 0.0f);
    rtScalef(-0.8f, 0.8f, 0.8f); /* mirrored */
    rtCallList(BODY);
    rtPopMatrix();
    rtTranslatef(0.0f, 2.4f, 0.0f);
    rtCallList(BALL);
    rtEndObject();
}

static void issue_frame(float spacing)
{
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtBeginFrame();
    const float step = 2.0f * (3.0f * spacing + 1.0f);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            rtPushMatrix();
            rtTranslatef(step * (float)(i - 1), -1.0f, -2.5f * step - step * (float)j);
            rtInstantiateObject(ROBOT);
            rtPopMatrix();
        }
}

struct mode_result {
    double node, tri, inst; /* per ray */
    double build_ms;
    int builds;
    double cpu_us; /* per ray */
    RTint groups, flattened;
    RTcontext ctx;
    double *cpu;
};

/* A fresh single-threaded context in `mode` with the scene; its first
 * trace (which builds what its rays need, lazily) into hits. */
static int open_mode(const char *mode, int rings, float spacing, const RTray *rays, int n,
                     int runs, RThit *hits, struct mode_result *r)
{
    char config[64];
    snprintf(config, sizeof(config), "threads=1 flatten=%s", mode);
    r->ctx = bench_create_context(config);
    r->cpu = malloc((size_t)runs * sizeof(double));
    if (!r->ctx || !r->cpu)
        return -1;
    rtMakeCurrent(r->ctx);
    define_scene(rings, spacing);
    issue_frame(spacing);
    rtTraceRays(n, rays, hits);
    float build_ms = 0.0f;
    RTint builds = 0;
    rtGetFloatv(RT_STAT_BUILD_TIME, &build_ms);
    rtGetIntegerv(RT_STAT_OBJECT_BUILDS, &builds);
    r->build_ms = build_ms;
    r->builds = builds;
    rtGetIntegerv(RT_NESTED_GROUPS, &r->groups);
    rtGetIntegerv(RT_FLATTENED_GROUPS, &r->flattened);
    return rtGetError() != RT_NO_ERROR ? -1 : 0;
}

/* Timed trace `k` of the mode (the modes' traces are interleaved, so
 * that a change in the machine's load falls on all of them alike). */
static void time_mode(struct mode_result *r, const RTray *rays, int n, RThit *hits, int k)
{
    rtMakeCurrent(r->ctx);
    double c0 = bench_cpu_ms();
    rtTraceRays(n, rays, hits);
    r->cpu[k] = bench_cpu_ms() - c0;
}

static void close_mode(struct mode_result *r, int n, int runs)
{
    if (r->ctx) {
        rtMakeCurrent(r->ctx);
        RTint rays_traced = 0, node = 0, tri = 0, inst = 0;
        rtGetIntegerv(RT_STAT_RAYS, &rays_traced);
        rtGetIntegerv(RT_STAT_NODE_TESTS, &node);
        rtGetIntegerv(RT_STAT_TRIANGLE_TESTS, &tri);
        rtGetIntegerv(RT_STAT_INSTANCE_TESTS, &inst);
        const double per = rays_traced > 0 ? 1.0 / rays_traced : 0.0;
        r->node = node * per;
        r->tri = tri * per;
        r->inst = inst * per;
        if (r->cpu)
            r->cpu_us = bench_median(r->cpu, runs) * 1000.0 / n;
        rtMakeCurrent(NULL);
        rtDestroyContext(r->ctx);
    }
    free(r->cpu);
    r->ctx = NULL;
    r->cpu = NULL;
}

static void make_rays(RTray *rays, int w, int h)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            RTray *r = &rays[y * w + x];
            r->org[0] = r->org[1] = r->org[2] = 0.0f;
            r->org[1] = 3.0f;
            r->dir[0] = (2.0f * ((float)x + 0.5f) / (float)w - 1.0f) * 0.6f;
            r->dir[1] = (1.0f - 2.0f * ((float)y + 0.5f) / (float)h) * 0.45f - 0.25f;
            r->dir[2] = -1.0f;
            r->tmin = 0.0f;
            r->tmax = INFINITY;
        }
}

int bench_nested_section(const struct bench_options *opts)
{
    const int w = opts->quick ? 64 : 320, h = opts->quick ? 48 : 240, n = w * h;
    const int rings = opts->quick ? 8 : 24;
    const int runs = opts->runs > 0 ? opts->runs : 1;
    RTray *rays = malloc((size_t)n * sizeof(*rays));
    RThit *ref = malloc((size_t)n * sizeof(*ref));
    RThit *hits = malloc((size_t)n * sizeof(*hits));
    if (!rays || !ref || !hits) {
        free(rays);
        free(ref);
        free(hits);
        return -1;
    }
    make_rays(rays, w, h);
    report_printf("\n## Nested static hierarchies: flattened against instanced\n\n"
                  "Nine calls of a four-level robot (41 segments, balls of %d triangles), "
                  "%d primary rays through rtTraceRays on one thread; per mode: tests per ray, "
                  "the lazy builds of the first trace, process CPU time per ray (median of %d "
                  "traces, the modes' traces interleaved).  Hits of every mode equal flatten=off's bit for bit "
                  "(docs/instances.md).\n\n",
                  rings * rings * 3, n, runs);
    report_table_header("scene|flatten|groups flattened|node tests/ray|triangle tests/ray|"
                        "instance tests/ray|first-trace builds|build ms|CPU us/ray");
    static const char *const modes[] = {"off", "on", "auto"};
    static const struct {
        const char *name;
        float spacing;
    } scenes[] = {{"stacked", 0.08f}, {"dense", 0.7f}, {"sparse", 3.0f}};
    int failed = 0;
    char note[512] = "";
    int notes = 0;
    for (int s = 0; s < 3; s++) {
        struct mode_result r[3];
        memset(r, 0, sizeof(r));
        int ok = 1;
        for (int m = 0; m < 3 && ok; m++) {
            ok = !open_mode(modes[m], rings, scenes[s].spacing, rays, n, runs, m ? hits : ref,
                            &r[m]);
            if (ok && m && memcmp(hits, ref, (size_t)n * sizeof(*ref)) != 0) {
                report_printf("\nCHECK FAILED: %s flatten=%s hits differ from flatten=off.\n",
                              scenes[s].name, modes[m]);
                report_check_failed();
            }
        }
        for (int k = 0; k < runs && ok; k++)
            for (int m = 0; m < 3; m++)
                time_mode(&r[m], rays, n, hits, k);
        for (int m = 0; m < 3; m++)
            close_mode(&r[m], n, runs);
        if (!ok) {
            failed = 1;
            continue;
        }
        for (int m = 0; m < 3; m++) {
            report_row("%s|%s|%d of %d|%.1f|%.1f|%.2f|%d|%.2f|%.3f", scenes[s].name, modes[m],
                       r[m].flattened, r[m].groups, r[m].node, r[m].tri, r[m].inst, r[m].builds,
                       r[m].build_ms, r[m].cpu_us);
            char key[64];
            snprintf(key, sizeof(key), "nested_%s_%s_cpu_us_per_ray", scenes[s].name, modes[m]);
            report_metric(key, r[m].cpu_us, 0);
        }
        if (r[0].cpu_us > 0.0) {
            const double best = r[1].cpu_us < r[0].cpu_us ? r[1].cpu_us : r[0].cpu_us;
            notes += snprintf(note + notes, sizeof(note) - (size_t)notes,
                              "%s: flattened / instanced CPU time per ray %.2f, auto / best "
                              "%.2f\n",
                              scenes[s].name, r[1].cpu_us / r[0].cpu_us, r[2].cpu_us / best);
        }
    }
    report_printf("\n%s", note);
    free(rays);
    free(ref);
    free(hits);
    return failed ? -1 : 0;
}
