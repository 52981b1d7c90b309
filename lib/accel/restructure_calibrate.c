/* SPDX-License-Identifier: Apache-2.0 */
/*
 * restructure_calibrate.c - the machine constants of selective
 * restructuring, measured at start-up as Yoon, Curtis and Manocha (2007) sec. 6.1 does: "We
 * automatically compute these costs by running those routines a few
 * times without any manual intervention during the ray tracing system's
 * initialization.  Then, we use their average values".
 *
 * Every constant is a time relative to one ray/AABB test (sec. 6.1):
 *   C_leaf     ray/triangle test / ray/AABB test, both with the kernels
 *              the traversal runs (trace/intersect.h);
 *   C_rebuild  one restructuring operation (rs_build_candidate: gather,
 *              partitioning plane, two SAH builds, cost change) on k
 *              synthetic boxes, per k log2 k;
 *   C_refine   one pair through the pair-queue (rs_refine_pairs with
 *              every gate open), per pair.
 * Each routine runs once to warm caches and allocations, then
 * CALIBRATE_RUNS times; the fastest run is kept rather than the paper's
 * average, because on a time-shared machine the noise only ever adds
 * time.  Inputs come from a fixed-seed generator, so the work is the same
 * on every call; only the clock readings vary.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "accel/build_internal.h"
#include "accel/restructure_internal.h"
#include "base/alloc.h"
#include "base/timer.h"
#include "trace/intersect.h"

/* Timed runs per measurement (after one warm-up run). */
#define CALIBRATE_RUNS 3
/* Ray/box and ray/triangle work: rays x primitives tests per run, about
 * 0.1-0.3 ms each on the development machine. */
#define CALIBRATE_RAYS 64
#define CALIBRATE_BOXES 512
#define CALIBRATE_TRIANGLES 256
/* Restructuring sizes: the range of sub-BVH pairs restructured in the
 * exploding and morphing tests (conformance/internal/restructure.c). */
static const uint32_t calibrate_rebuild_sizes[] = {256, 1024, 4096};
/* The pair-queue run: a tree over this many jittered boxes, and at most
 * this many pairs. */
#define CALIBRATE_REFINE_PRIMS 4096
#define CALIBRATE_REFINE_PAIRS 8192

/* xorshift32: deterministic synthetic data without the tests' helpers. */
static uint32_t next_random(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *s = x;
    return x;
}

static float unit_random(uint32_t *s)
{
    return (float)(next_random(s) >> 8) * (1.0f / 16777216.0f);
}

/* Random boxes of edge up to `size` in the unit cube. */
static void random_boxes(struct aabb *boxes, uint32_t n, float size, uint32_t *s)
{
    for (uint32_t i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++) {
            boxes[i].min[k] = unit_random(s);
            boxes[i].max[k] = boxes[i].min[k] + size * unit_random(s);
        }
    }
}

/* Rays from outside the unit cube towards a random point inside it. */
static void random_rays(struct trace_ray *rays, uint32_t n, uint32_t *s)
{
    for (uint32_t i = 0; i < n; i++) {
        float org[3];
        float dir[3];
        for (int k = 0; k < 3; k++) {
            org[k] = 3.0f * unit_random(s) - 1.0f;
            dir[k] = unit_random(s) - org[k];
        }
        org[i % 3] = (i & 4) ? -1.0f : 2.0f;
        dir[i % 3] = unit_random(s) - org[i % 3];
        trace_ray_init(&rays[i], org, dir, 0.0f);
    }
}

/* Milliseconds per ray/box test, or 0 when the clock did not advance. */
static double time_box_tests(const struct trace_ray *rays, const struct bvh_node *nodes)
{
    double best = INFINITY;
    unsigned hits = 0;
    for (int run = 0; run <= CALIBRATE_RUNS; run++) {
        double t0 = rt_now_ms();
        for (uint32_t r = 0; r < CALIBRATE_RAYS; r++) {
            struct isect_box_ray br;
            isect_box_ray_init(&br, &rays[r]);
            for (uint32_t b = 0; b < CALIBRATE_BOXES; b++) {
                float t;
                hits += (unsigned)isect_box(&br, &nodes[b], INFINITY, &t);
            }
        }
        double ms = rt_now_ms() - t0;
        if (run > 0 && ms < best)
            best = ms;
    }
    /* The hit count keeps the loop from being optimized away. */
    volatile unsigned sink = hits;
    (void)sink;
    double per = best / ((double)CALIBRATE_RAYS * CALIBRATE_BOXES);
    return per > 0.0 && isfinite(per) ? per : 0.0;
}

static double time_triangle_tests(const struct trace_ray *rays, const float *tri)
{
    double best = INFINITY;
    unsigned hits = 0;
    for (int run = 0; run <= CALIBRATE_RUNS; run++) {
        double t0 = rt_now_ms();
        for (uint32_t r = 0; r < CALIBRATE_RAYS; r++) {
            for (uint32_t i = 0; i < CALIBRATE_TRIANGLES; i++) {
                const float *v = &tri[9 * i];
                float t, u, w;
                hits += (unsigned)isect_triangle(&rays[r], v, v + 3, v + 6, INFINITY, &t, &u, &w);
            }
        }
        double ms = rt_now_ms() - t0;
        if (run > 0 && ms < best)
            best = ms;
    }
    volatile unsigned sink = hits;
    (void)sink;
    double per = best / ((double)CALIBRATE_RAYS * CALIBRATE_TRIANGLES);
    return per > 0.0 && isfinite(per) ? per : 0.0;
}

/* A frame over a fresh build of boxes[0, n), metrics evaluated; 0 or -1. */
static int synthetic_frame(struct rs_frame *f, struct bvh *bvh, const struct aabb *boxes,
                           uint32_t n, struct accel_restructure_state *st,
                           struct accel_restructure_stats *stats)
{
    memset(f, 0, sizeof(*f));
    accel_restructure_params_default(&f->p);
    if (accel_build(bvh, boxes, n, &f->p.build))
        return -1;
    if (rs_reserve_nodes(st, bvh->node_count) || rs_reserve_prims(st, n)) {
        bvh_release(bvh);
        return -1;
    }
    f->bvh = bvh;
    f->boxes = boxes;
    f->st = st;
    f->stats = stats;
    rs_metrics_pass(f);
    f->root_area = rs_node_area(&bvh->nodes[0]);
    return 0;
}

/* Milliseconds per k log2 k of a restructuring operation, or 0. */
static double time_rebuild(struct aabb *boxes, struct accel_restructure_state *st)
{
    double total_ms = 0.0;
    double total_units = 0.0;
    uint32_t seed = 0x2545f491u;
    for (size_t i = 0; i < sizeof(calibrate_rebuild_sizes) / sizeof(calibrate_rebuild_sizes[0]);
         i++) {
        uint32_t k = calibrate_rebuild_sizes[i];
        random_boxes(boxes, k, 0.05f, &seed);
        struct accel_restructure_stats stats;
        struct rs_frame f;
        struct bvh bvh;
        if (synthetic_frame(&f, &bvh, boxes, k, st, &stats) || bvh.nodes[0].count) {
            if (f.bvh)
                bvh_release(&bvh);
            return 0.0;
        }
        struct accel_restructure_pair root_pair = {bvh.nodes[0].first, bvh.nodes[0].first + 1,
                                                   0, RS_NONE, 0.0};
        double best = INFINITY;
        for (int run = 0; run <= CALIBRATE_RUNS; run++) {
            struct rs_candidate c;
            double t0 = rt_now_ms();
            int r = rs_build_candidate(&f, &root_pair, &c);
            double ms = rt_now_ms() - t0;
            if (r != 0) {
                bvh_release(&bvh);
                return 0.0;
            }
            rs_candidate_release(&c);
            if (run > 0 && ms < best)
                best = ms;
        }
        bvh_release(&bvh);
        total_ms += best;
        total_units += (double)k * log2((double)k);
    }
    double per = total_ms / total_units;
    return per > 0.0 && isfinite(per) ? per : 0.0;
}

/* Milliseconds per pair of the pair-queue, or 0. */
static double time_refine(struct aabb *boxes, struct accel_restructure_state *st)
{
    uint32_t seed = 0x9e3779b9u;
    const uint32_t n = CALIBRATE_REFINE_PRIMS;
    random_boxes(boxes, n, 0.02f, &seed);
    struct accel_restructure_stats stats;
    struct rs_frame f;
    struct bvh bvh;
    if (synthetic_frame(&f, &bvh, boxes, n, st, &stats))
        return 0.0;
    /* Jitter and refit: the boxes of a deformed frame, which overlap. */
    for (uint32_t i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++) {
            float d = 0.2f * (unit_random(&seed) - 0.5f);
            boxes[i].min[k] += d;
            boxes[i].max[k] += d;
        }
    }
    rs_refit(&bvh, boxes, NULL);
    rs_metrics_pass(&f);
    f.root_area = rs_node_area(&bvh.nodes[0]);
    /* Every gate open: each pair's work is done in full. */
    f.factor = 1e30;
    f.pair_limit = CALIBRATE_REFINE_PAIRS;
    double best = INFINITY;
    uint32_t pairs = 0;
    for (int run = 0; run <= CALIBRATE_RUNS; run++) {
        for (uint32_t i = 0; i < bvh.node_count; i++)
            st->flags[i] = 0;
        stats.pairs_examined = 0;
        double t0 = rt_now_ms();
        int r = rs_refine_pairs(&f);
        double ms = rt_now_ms() - t0;
        if (r != 0 || stats.pairs_examined == 0) {
            bvh_release(&bvh);
            return 0.0;
        }
        pairs = stats.pairs_examined;
        if (run > 0 && ms < best)
            best = ms;
    }
    bvh_release(&bvh);
    double per = best / (double)pairs;
    return per > 0.0 && isfinite(per) ? per : 0.0;
}

void accel_restructure_measure_constants(struct accel_restructure_params *out)
{
    accel_restructure_params_default(out);
    uint32_t seed = 0x12345678u;
    struct trace_ray rays[CALIBRATE_RAYS];
    random_rays(rays, CALIBRATE_RAYS, &seed);
    uint32_t box_count = CALIBRATE_REFINE_PRIMS;
    for (size_t i = 0; i < sizeof(calibrate_rebuild_sizes) / sizeof(calibrate_rebuild_sizes[0]);
         i++) {
        if (calibrate_rebuild_sizes[i] > box_count)
            box_count = calibrate_rebuild_sizes[i];
    }
    struct bvh_node *nodes = rt_malloc(sizeof(*nodes) * CALIBRATE_BOXES);
    float *tri = rt_malloc(sizeof(*tri) * 9 * CALIBRATE_TRIANGLES);
    struct aabb *boxes = rt_malloc(sizeof(*boxes) * box_count);
    if (!nodes || !tri || !boxes) {
        rt_free(nodes);
        rt_free(tri);
        rt_free(boxes);
        return;
    }
    /* Boxes and triangles of the sizes a traversal meets near leaves. */
    random_boxes(boxes, CALIBRATE_BOXES, 0.2f, &seed);
    for (uint32_t i = 0; i < CALIBRATE_BOXES; i++) {
        build_set_box(&nodes[i], &boxes[i]);
        nodes[i].first = 0;
        nodes[i].count = 0;
    }
    for (uint32_t i = 0; i < CALIBRATE_TRIANGLES; i++) {
        float c[3];
        for (int k = 0; k < 3; k++)
            c[k] = unit_random(&seed);
        for (int v = 0; v < 3; v++) {
            for (int k = 0; k < 3; k++)
                tri[9 * i + 3 * v + k] = c[k] + 0.2f * (unit_random(&seed) - 0.5f);
        }
    }
    double box_ms = time_box_tests(rays, nodes);
    if (box_ms > 0.0) {
        double tri_ms = time_triangle_tests(rays, tri);
        if (tri_ms > 0.0)
            out->c_leaf = (float)(tri_ms / box_ms);
        struct accel_restructure_state st;
        accel_restructure_state_init(&st);
        double rebuild_ms = time_rebuild(boxes, &st);
        if (rebuild_ms > 0.0)
            out->c_rebuild = (float)(rebuild_ms / box_ms);
        double refine_ms = time_refine(boxes, &st);
        if (refine_ms > 0.0)
            out->c_refine = (float)(refine_ms / box_ms);
        accel_restructure_state_release(&st);
    }
    rt_free(nodes);
    rt_free(tri);
    rt_free(boxes);
}
