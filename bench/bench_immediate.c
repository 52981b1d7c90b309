/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_immediate.c - rtbench immediate: what a GL program that re-sends
 * its geometry every frame outside display lists pays (docs/lists.md).
 *
 * One grid mesh (about 1M triangles; --quick: a toy size), drawn each
 * frame with rtDrawElements outside any object (immediate mode), against
 * the same mesh defined once as an object and instanced every frame.  A
 * frame here is its description plus the preparation rtFinish makes (no
 * rays are traced): for the unchanged mesh, immediate mode re-records the
 * triangles and compares them with the last frame's, the object costs an
 * instance; for moved vertices (same topology), immediate mode re-records
 * and updates the structure (RT_AUTOMATIC: refit or rebuild), the object
 * takes rtUpdateVertices and the same update.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <rt/rt.h>

#include "base/timer.h"
#include "bench.h"

#define OBJ 77u

struct grid {
    uint32_t n; /* quads per side */
    float *pos; /* (n+1)^2 vertices */
    uint32_t *idx;
    uint32_t vcount, icount;
};

static int grid_make(struct grid *g, uint32_t n)
{
    g->n = n;
    g->vcount = (n + 1) * (n + 1);
    g->icount = 6 * n * n;
    g->pos = malloc((size_t)g->vcount * 3 * sizeof(float));
    g->idx = malloc((size_t)g->icount * sizeof(uint32_t));
    if (!g->pos || !g->idx)
        return -1;
    uint32_t k = 0;
    for (uint32_t j = 0; j < n; j++)
        for (uint32_t i = 0; i < n; i++) {
            uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            uint32_t q[6] = {a, b, d, a, d, c};
            for (int t = 0; t < 6; t++)
                g->idx[k++] = q[t];
        }
    return 0;
}

/* Vertex positions of frame f: a height wave whose phase moves. */
static void grid_wave(struct grid *g, int f)
{
    uint32_t n = g->n;
    for (uint32_t j = 0; j <= n; j++)
        for (uint32_t i = 0; i <= n; i++) {
            float *p = &g->pos[3 * (j * (n + 1) + i)];
            p[0] = -1.0f + 2.0f * (float)i / (float)n;
            p[1] = -1.0f + 2.0f * (float)j / (float)n;
            p[2] = -5.0f + 0.05f * sinf(6.0f * p[0] + 0.3f * (float)f);
        }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof(*v), cmp_double);
    return v[n / 2];
}

enum mode { IMMEDIATE_UNCHANGED, OBJECT_UNCHANGED, IMMEDIATE_MOVED, OBJECT_MOVED };

/* Median ms per frame over `frames` frames after one warm-up frame; the
 * statistics of the last frame go to *updates / *builds. */
static double run(struct grid *g, enum mode mode, int frames, RTint *updates, RTint *builds)
{
    RTcontext ctx = bench_create_context("threads=2");
    rtMakeCurrent(ctx);
    rtViewport(0, 0, 64, 64);
    rtVertexPointer(3, RT_FLOAT, 0, g->pos);
    rtEnableClientState(RT_VERTEX_ARRAY);
    grid_wave(g, 0);
    if (mode == OBJECT_UNCHANGED || mode == OBJECT_MOVED) {
        rtNewObject(OBJ);
        rtDrawElements(RT_TRIANGLES, (RTsizei)g->icount, RT_UNSIGNED_INT, g->idx);
        rtEndObject();
    }
    double *ms = malloc((size_t)(frames + 1) * sizeof(double));
    for (int f = 0; f <= frames; f++) {
        int moved = mode == IMMEDIATE_MOVED || mode == OBJECT_MOVED;
        if (moved)
            grid_wave(g, f);
        double start = rt_now_ms();
        rtBeginFrame();
        if (mode == IMMEDIATE_UNCHANGED || mode == IMMEDIATE_MOVED) {
            rtDrawElements(RT_TRIANGLES, (RTsizei)g->icount, RT_UNSIGNED_INT, g->idx);
        } else {
            if (moved && f > 0)
                rtUpdateVertices(OBJ, RT_VERTEX_ARRAY, 0, (RTsizei)g->vcount, RT_FLOAT, 0, g->pos);
            rtInstantiateObject(OBJ);
        }
        rtFinish();
        ms[f] = rt_now_ms() - start;
        if (f == 0) {
            /* The first frame builds: force it now, outside the timing. */
            RThit h;
            RTray r = {{0, 0, 0}, 0, {0, 0, -1}, INFINITY};
            rtTraceRays(1, &r, &h);
        }
    }
    rtGetIntegerv(RT_STAT_OBJECT_UPDATES, updates);
    rtGetIntegerv(RT_STAT_OBJECT_BUILDS, builds);
    double m = median(ms + 1, frames);
    free(ms);
    rtMakeCurrent(NULL);
    rtDestroyContext(ctx);
    return m;
}

int bench_immediate_section(const struct bench_options *opts)
{
    struct grid g = {0};
    uint32_t n = opts->quick ? 32 : 708; /* 2 n^2 triangles: 1,002,528 */
    int frames = opts->quick ? 3 : (opts->runs > 5 ? opts->runs : 5);
    if (grid_make(&g, n)) {
        free(g.pos);
        free(g.idx);
        return -1;
    }
    report_printf("\n## Immediate mode against objects\n\n"
                  "A %u-triangle grid per frame: drawn with rtDrawElements outside objects "
                  "(immediate mode, compared with the last frame) or defined once as an object "
                  "and instanced; a frame is its description and rtFinish's preparation, no "
                  "rays (median of %d frames; docs/lists.md).\n\n",
                  2 * n * n, frames);
    report_table_header("frames|immediate ms/frame|object ms/frame|immediate updates, builds|"
                        "object updates, builds");
    RTint iu, ib, ou, ob;
    double im = run(&g, IMMEDIATE_UNCHANGED, frames, &iu, &ib);
    double om = run(&g, OBJECT_UNCHANGED, frames, &ou, &ob);
    report_row("unchanged|%.2f|%.3f|%d, %d|%d, %d", im, om, iu, ib, ou, ob);
    if (iu != 0 || ib != 0) {
        report_printf("\nCHECK FAILED: an unchanged immediate frame updated or built.\n");
        report_check_failed();
    }
    im = run(&g, IMMEDIATE_MOVED, frames, &iu, &ib);
    om = run(&g, OBJECT_MOVED, frames, &ou, &ob);
    report_row("moved vertices|%.2f|%.2f|%d, %d|%d, %d", im, om, iu, ib, ou, ob);
    if (iu != 1) {
        report_printf("\nCHECK FAILED: a moved immediate frame did not take the update path.\n");
        report_check_failed();
    }
    free(g.pos);
    free(g.idx);
    return 0;
}
