/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_dynamic.c - `rtbench dynamic`: dynamic scenes, error against time
 * (DESIGN.md "The runtime" and "Measurement"; docs/dynamic.md).
 *
 * Four measurements, all through the public API on a context created with
 * DYN_CONFIG (two render threads, one asynchronous build thread):
 *
 *  1. Unstructured soup rebuild time (Wald, Benthin and Slusallek (2003) table 3): N random
 *     triangles morphing (anim_gen.c), N = 64 .. 64k; RT_STAT_UPDATE_TIME
 *     per frame, median over the frames after the first, for RT_REBUILD
 *     and RT_REBUILD_MEDIAN, beside the paper's 2003 figures.
 *  2. Top-level update time (Wald, Benthin and Slusallek (2003) sec. 4.5): 100, 1k, 10k instances
 *     of one small object bouncing in a box, every matrix new each frame;
 *     RT_STAT_TOPLEVEL_TIME per frame, median.
 *  3. Parallel build speedup (Wald, Ize and Parker (2008) table 2): accel_build_parallel_ex
 *     SAH+SAH and grid+BIH on 1 and 2 threads against the serial builders
 *     (binned SAH, median), on the 1M bumpy torus and the exploding
 *     torus's first frame.  The static core directly, not the API.
 *  4. Strategies over animations (Wald, Ize and Parker (2008) fig. 3, Yoon, Curtis and Manocha (2007) table 2):
 *     for the exploding torus, the waving cloth and the 64k soup, every
 *     frame is rtUpdateVertices + rtRenderFrame (eye light), timed as a
 *     whole; "update" is RT_STAT_UPDATE_TIME (+ RT_STAT_BUILD_TIME, the
 *     first frame's lazy build), "render" the rest.  The error measure is
 *     the SAH cost of the object's current tree (RT_OBJECT_SAH_COST) over
 *     that of a fresh sweep SAH build of the same frame's geometry
 *     (accel_build through the static core, computed once per frame).
 *     Where Embree is available, two more lines: a dynamic scene committed
 *     every frame with geometry quality REFIT (refit only) and LOW (rebuild
 *     every frame), each frame timed as vertex copy + commit + tracing the
 *     same number of primary rays on two threads (no shading: Embree's
 *     "render" is a little cheaper than ours by construction).
 *     Runs are interleaved (run 1 of every strategy, then run 2, ...);
 *     per-frame curves are the median over runs frame by frame, totals
 *     the median of the runs' totals.
 *
 * Correctness: on every frame of every strategy a sample of camera rays
 * goes through rtTraceRays (after the timed frame; it does not change the
 * statistics the strategies read) and must give the same hits (hit/miss,
 * t within BENCH_T_TOLERANCE) as the sweep reference; Embree must agree
 * on at least EMBREE_MIN_AGREEMENT percent.  Otherwise rtbench exits 3.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accel/build_parallel.h"
#include "api/context.h"
#include "base/pool.h"
#include "base/timer.h"
#include "bench.h"

#ifdef RT_HAVE_EMBREE
#include "bench_embree.h"
#endif

#define DYN_CONFIG "threads=2 build_threads=1"
#define DYN_THREADS 2
#define DYN_WIDTH 512
#define DYN_HEIGHT 384
#define DYN_WIDTH_QUICK 128
#define DYN_HEIGHT_QUICK 96
#define DYN_TAN_X 0.57735026918962576 /* 60 degrees horizontal field of view */
#define DYN_FRAMES 30
#define DYN_FRAMES_QUICK 5
#define DYN_MAX_RUNS 3
/* Correctness sample: a coarse grid of camera rays per frame. */
#define DYN_SAMPLE_W 64
#define DYN_SAMPLE_H 48
#define DYN_SAMPLE_W_QUICK 16
#define DYN_SAMPLE_H_QUICK 12
#define EMBREE_MIN_AGREEMENT 99.9
/* A strategy whose first run of an animation takes longer than this is
 * not repeated (refitting the explosion: a near standstill, as in Wald, Ize and Parker
 * (2008) fig. 3): its figures are from one run, and the table says so. */
#define DYN_SLOW_RUN_MS 8000.0

/* Sizes (anim_gen.c): explode 2 * S * S/2 triangles, cloth 2 * S * S. */
#define EXPLODE_SIZE 500 /* 250k triangles */
#define EXPLODE_SIZE_QUICK 40
#define CLOTH_SIZE 224 /* 100352 triangles */
#define CLOTH_SIZE_QUICK 30
#define SOUP_BIG 65536
#define SOUP_BIG_QUICK 2048

/* ------------------------------------------------------------ camera */

static void dyn_camera(uint32_t w, uint32_t h)
{
    double tx = DYN_TAN_X, ty = DYN_TAN_X * h / w;
    rtViewport(0, 0, (RTsizei)w, (RTsizei)h);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-tx, tx, -ty, ty, 1.0, 1000.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
}

/* One ray per pixel centre of a w x h image through the camera above. */
static int dyn_rays(struct bench_rays *set, uint32_t w, uint32_t h)
{
    memset(set, 0, sizeof(*set));
    set->rays = malloc((size_t)w * h * sizeof(RTray));
    if (!set->rays)
        return -1;
    set->name = "primary";
    set->count = w * h;
    set->width = w;
    set->height = h;
    double tx = DYN_TAN_X, ty = DYN_TAN_X * h / w;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            RTray *r = &set->rays[y * w + x];
            r->org[0] = r->org[1] = r->org[2] = 0.0f;
            r->tmin = 0.0f;
            r->dir[0] = (float)(tx * (2.0 * (x + 0.5) / w - 1.0));
            r->dir[1] = (float)(ty * (1.0 - 2.0 * (y + 0.5) / h));
            r->dir[2] = -1.0f;
            r->tmax = INFINITY;
        }
    return 0;
}

static void define_object(RTuint obj, const struct bench_anim *a)
{
    rtNewObject(obj);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, a->positions);
    rtDrawElements(RT_TRIANGLES, (RTsizei)(3 * a->tri_count), RT_UNSIGNED_INT, a->indices);
    rtDisableClientState(RT_VERTEX_ARRAY);
    rtEndObject();
}

static float get_f(RTenum pname)
{
    RTfloat v = 0.0f;
    rtGetFloatv(pname, &v);
    return v;
}

/* ------------------------------------------------------------ 1. soup rebuild */

static const uint32_t soup_sizes[] = {64, 256, 1024, 4096, 16384, 65536};
/* Wald, Benthin and Slusallek (2003) table 3, "reconst.time" of the object BSP (2003, one CPU). */
static const char *const soup_paper[] = {"< 1 ms", "2 ms", "8 ms", "34 ms", "0.1 s", "> 1 s"};
#define SOUP_SIZES ((int)(sizeof(soup_sizes) / sizeof(soup_sizes[0])))
#define SOUP_FRAMES 20
#define SOUP_FRAMES_QUICK 4

/* Median RT_STAT_UPDATE_TIME over frames 1 .. frames-1 of the soup with
 * the given strategy; *ok = 0 when the API reported an error. */
static double soup_update_ms(struct bench_anim *a, RTenum strategy, int frames, int *ok)
{
    double ms[SOUP_FRAMES];
    RTcontext ctx = bench_create_context(DYN_CONFIG);
    if (!ctx || !rtMakeCurrent(ctx)) {
        *ok = 0;
        return 0.0;
    }
    RTuint obj;
    rtGenObjects(1, &obj);
    bench_anim_frame(a, 0);
    define_object(obj, a);
    rtObjectParameteri(obj, RT_UPDATE_STRATEGY, (RTint)strategy);
    dyn_camera(64, 48);
    rtInstantiateObject(obj);
    rtRenderFrame();
    for (int f = 1; f < frames; f++) {
        bench_anim_frame(a, f);
        rtUpdateVertices(obj, RT_VERTEX_ARRAY, 0, (RTsizei)a->vertex_count, RT_FLOAT, 0,
                         a->positions);
        rtRenderFrame();
        ms[f - 1] = get_f(RT_STAT_UPDATE_TIME);
    }
    if (rtGetError() != RT_NO_ERROR)
        *ok = 0;
    rtMakeCurrent(NULL);
    rtDestroyContext(ctx);
    return bench_median(ms, frames - 1);
}

static int soup_table(const struct bench_options *opts)
{
    const int frames = opts->quick ? SOUP_FRAMES_QUICK : SOUP_FRAMES;
    report_printf("\n### Unstructured motion: rebuild time per frame (Wald, Benthin and Slusallek (2003) table 3)\n\n");
    report_printf("N random triangles morphing between random configurations (a new one every "
                  "%d frames), one object updated with rtUpdateVertices; RT_STAT_UPDATE_TIME per "
                  "frame, median over frames 1..%d, context `%s`. RT_REBUILD: binned SAH "
                  "(two-stage parallel build on both threads for large objects); "
                  "RT_REBUILD_MEDIAN: spatial-median (BIH-like) build. Paper: the 2003 "
                  "object-BSP reconstruction time of the BART museum (Wald et al., Wald, Benthin and Slusallek (2003) "
                  "table 3; 2003 hardware, one CPU, and a BSP, not a BVH).\n\n",
                  BENCH_SOUP_KEY_FRAMES, frames - 1, DYN_CONFIG);
    report_table_header("triangles|RT_REBUILD ms|RT_REBUILD_MEDIAN ms|Wald, Benthin and Slusallek (2003) (2003)");
    for (int i = 0; i < SOUP_SIZES; i++) {
        uint32_t n = soup_sizes[i];
        if (opts->quick && n > 4096)
            break;
        struct bench_anim a;
        if (bench_anim_create(&a, BENCH_ANIM_SOUP, n, frames))
            return -1;
        int ok = 1;
        report_progress("dynamic: soup rebuild, %u triangles\n", n);
        double sah = soup_update_ms(&a, RT_REBUILD, frames, &ok);
        double med = soup_update_ms(&a, RT_REBUILD_MEDIAN, frames, &ok);
        bench_anim_release(&a);
        if (!ok) {
            report_progress("rtbench: dynamic: the API reported an error (soup %u)\n", n);
            return -1;
        }
        report_row("%u|%.3f|%.3f|%s", n, sah, med, soup_paper[i]);
        char key[64];
        snprintf(key, sizeof(key), "dynamic.soup%u.rebuild_ms", n);
        report_metric(key, sah, 0);
        snprintf(key, sizeof(key), "dynamic.soup%u.rebuild_median_ms", n);
        report_metric(key, med, 0);
    }
    return 0;
}

/* ------------------------------------------------------------ 2. top level */

static const int instance_counts[] = {100, 1000, 10000};
#define INSTANCE_SIZES ((int)(sizeof(instance_counts) / sizeof(instance_counts[0])))
#define INSTANCE_FRAMES 20
#define INSTANCE_FRAMES_QUICK 4

/* A coordinate bouncing between -1 and 1 (a triangle wave). */
static double bounce(double x)
{
    double m = fmod(x + 1.0, 4.0);
    if (m < 0.0)
        m += 4.0;
    return m < 2.0 ? m - 1.0 : 3.0 - m;
}

/* A number in [0, 1) that depends only on x. */
static double unit_hash(uint64_t x)
{
    struct bench_rng rng;
    bench_rng_seed(&rng, x);
    return bench_rng_float(&rng);
}

static void define_ball(RTuint obj)
{
    const int stacks = 6, slices = 8; /* 96 triangles */
    rtNewObject(obj);
    rtBegin(RT_TRIANGLES);
    for (int j = 0; j < stacks; j++)
        for (int i = 0; i < slices; i++) {
            double p[4][3];
            for (int k = 0; k < 4; k++) {
                int jj = j + (k >= 2), ii = i + (k == 1 || k == 2);
                double th = 3.141592653589793 * jj / stacks, ph = 6.283185307179586 * ii / slices;
                p[k][0] = sin(th) * cos(ph);
                p[k][1] = cos(th);
                p[k][2] = sin(th) * sin(ph);
            }
            rtVertex3d(p[0][0], p[0][1], p[0][2]);
            rtVertex3d(p[1][0], p[1][1], p[1][2]);
            rtVertex3d(p[2][0], p[2][1], p[2][2]);
            rtVertex3d(p[0][0], p[0][1], p[0][2]);
            rtVertex3d(p[2][0], p[2][1], p[2][2]);
            rtVertex3d(p[3][0], p[3][1], p[3][2]);
        }
    rtEnd();
    rtEndObject();
}

static int toplevel_table(const struct bench_options *opts)
{
    const int frames = opts->quick ? INSTANCE_FRAMES_QUICK : INSTANCE_FRAMES;
    const uint32_t w = opts->quick ? DYN_WIDTH_QUICK : DYN_WIDTH;
    const uint32_t h = opts->quick ? DYN_HEIGHT_QUICK : DYN_HEIGHT;
    report_printf("\n### Rigid bodies: top-level update time (Wald, Benthin and Slusallek (2003) sec. 4.5)\n\n");
    report_printf("N instances of one 96-triangle ball bouncing in a box, every matrix new in "
                  "every frame (rtLoadIdentity, rtTranslatef, rtScalef, rtInstantiateObject), "
                  "rendered at %ux%u with eye-light shading on a context `%s`. Median over "
                  "frames 1..%d of RT_STAT_TOPLEVEL_TIME (top-level build over the instance "
                  "boxes), of the time to issue the N instances, and of the whole "
                  "rtRenderFrame. Wald, Benthin and Slusallek (2003) reports under 1 ms for the 161 objects of BART "
                  "Robots (2003).\n\n",
                  w, h, DYN_CONFIG, frames - 1);
    report_table_header("instances|top level ms|issue instances ms|rtRenderFrame ms|"
                        "top level / frame");
    double *top = malloc(3 * (size_t)frames * sizeof(double));
    if (!top)
        return -1;
    double *issue = top + frames, *render = top + 2 * frames;
    for (int s = 0; s < INSTANCE_SIZES; s++) {
        int n = opts->quick ? instance_counts[s] / 10 : instance_counts[s];
        report_progress("dynamic: top level, %d instances\n", n);
        RTcontext ctx = bench_create_context(DYN_CONFIG);
        if (!ctx || !rtMakeCurrent(ctx)) {
            free(top);
            return -1;
        }
        RTuint ball;
        rtGenObjects(1, &ball);
        define_ball(ball);
        dyn_camera(w, h);
        double radius = 1.2 / cbrt((double)n);
        for (int f = 0; f < frames; f++) {
            double t0 = rt_now_ms();
            for (int i = 0; i < n; i++) {
                double p[3];
                for (int c = 0; c < 3; c++) {
                    double x0 = 2.0 * unit_hash((uint64_t)(3 * i + c)) - 1.0;
                    double v = 0.06 * (unit_hash((uint64_t)(3 * i + c) + 0x10000000u) - 0.5);
                    p[c] = bounce(x0 + v * f);
                }
                rtLoadIdentity();
                rtTranslatef((float)(2.2 * p[0]), (float)(1.6 * p[1]), (float)(1.6 * p[2] - 7.0));
                rtScalef((float)radius, (float)radius, (float)radius);
                rtInstantiateObject(ball);
            }
            double t1 = rt_now_ms();
            rtRenderFrame();
            double t2 = rt_now_ms();
            if (f > 0) {
                top[f - 1] = get_f(RT_STAT_TOPLEVEL_TIME);
                issue[f - 1] = t1 - t0;
                render[f - 1] = t2 - t1;
            }
        }
        int ok = rtGetError() == RT_NO_ERROR;
        rtMakeCurrent(NULL);
        rtDestroyContext(ctx);
        if (!ok) {
            free(top);
            return -1;
        }
        double tm = bench_median(top, frames - 1), im = bench_median(issue, frames - 1),
               rm = bench_median(render, frames - 1);
        report_row("%d|%.3f|%.3f|%.2f|%.1f%%", n, tm, im, rm, rm > 0.0 ? 100.0 * tm / rm : 0.0);
        char key[64];
        snprintf(key, sizeof(key), "dynamic.instances%d.toplevel_ms", n);
        report_metric(key, tm, 0);
    }
    free(top);
    return 0;
}

/* ------------------------------------------------------------ 3. parallel build */

struct pbuild_row {
    const char *label;
    int kind; /* 0 serial binned, 1 serial median, 2 SAH+SAH, 3 grid+BIH */
    int threads;
};
static const struct pbuild_row pbuild_rows[] = {
    {"serial binned SAH", 0, 1}, {"serial median (BIH)", 1, 1}, {"SAH+SAH", 2, 1},
    {"SAH+SAH", 2, 2},           {"grid+BIH", 3, 1},            {"grid+BIH", 3, 2},
};
#define PBUILD_ROWS ((int)(sizeof(pbuild_rows) / sizeof(pbuild_rows[0])))

static int pbuild_mesh(const struct bench_options *opts, const struct bench_mesh *mesh,
                       struct rt_pool *pool2)
{
    const int runs = opts->runs < DYN_MAX_RUNS ? opts->runs : DYN_MAX_RUNS;
    struct aabb *boxes = bench_mesh_boxes(mesh);
    double times[PBUILD_ROWS][DYN_MAX_RUNS], sah[PBUILD_ROWS];
    if (!boxes)
        return -1;
    struct bvh_build_params params;
    bvh_build_params_default(&params);
    for (int run = 0; run < runs; run++) {
        report_progress("dynamic: parallel build, %s, run %d of %d\n", mesh->name, run + 1, runs);
        for (int r = 0; r < PBUILD_ROWS; r++) {
            const struct pbuild_row *row = &pbuild_rows[r];
            struct bvh bvh;
            struct bvh_parallel_params pp;
            bvh_parallel_params_default(&pp);
            if (row->kind == 3) {
                pp.partition = BVH_PARTITION_GRID;
                pp.subtree = BVH_SUBTREE_MEDIAN;
            }
            double cpu0 = bench_cpu_ms(), t0 = rt_now_ms();
            int rc = row->kind == 0   ? accel_build(&bvh, boxes, mesh->tri_count, &params)
                     : row->kind == 1 ? accel_build_median(&bvh, boxes, mesh->tri_count, &params)
                                      : accel_build_parallel_ex(&bvh, boxes, mesh->tri_count,
                                                                &params, &pp,
                                                                row->threads > 1 ? pool2 : NULL);
            times[r][run] = rt_now_ms() - t0;
            bench_share_add(row->threads, times[r][run], bench_cpu_ms() - cpu0);
            if (rc) {
                free(boxes);
                return -1;
            }
            sah[r] = accel_sah_cost(&bvh, BVH_C_TRAV, BVH_C_ISECT);
            bvh_release(&bvh);
        }
    }
    free(boxes);
    double med[PBUILD_ROWS];
    for (int r = 0; r < PBUILD_ROWS; r++)
        med[r] = bench_median(times[r], runs);
    for (int r = 0; r < PBUILD_ROWS; r++) {
        const struct pbuild_row *row = &pbuild_rows[r];
        /* Wald, Ize and Parker (2008) table 2's speedup: over the single-threaded build of the
         * same kind (binned SAH for SAH+SAH, median for grid+BIH). */
        double serial = row->kind == 3 || row->kind == 1 ? med[1] : med[0];
        double one = row->kind == 2 ? med[2] : row->kind == 3 ? med[4] : med[r];
        report_row("%s|%u|%s|%d|%.1f|%.2fx|%.2fx|%.1f", mesh->name, mesh->tri_count, row->label,
                   row->threads, med[r], med[r] > 0.0 ? serial / med[r] : 0.0,
                   med[r] > 0.0 ? one / med[r] : 0.0, sah[r]);
        char key[96];
        snprintf(key, sizeof(key), "dynamic.pbuild.%s.%d.%dt.ms", mesh->name, row->kind,
                 row->threads);
        report_metric(key, med[r], 0);
    }
    return 0;
}

static int pbuild_table(const struct bench_options *opts, struct bench_mesh *meshes, int mesh_count)
{
    const int runs = opts->runs < DYN_MAX_RUNS ? opts->runs : DYN_MAX_RUNS;
    report_printf("\n### Parallel build (Wald, Ize and Parker (2008) table 2)\n\n");
    report_printf("accel_build_parallel_ex through the static core, over precomputed triangle "
                  "boxes, median of %d interleaved runs. SAH+SAH: parallel binning at the top, "
                  "binned SAH subtrees; grid+BIH: grid partition, median subtrees. 1 thread: "
                  "no pool (the same code on the calling thread). \"vs serial\": the serial "
                  "builder of the same kind (binned SAH, median) / this, Wald, Ize and Parker (2008) table 2's "
                  "speedup; \"vs 1 thread\": the same parallel builder on 1 thread / this. "
                  "Wald, Ize and Parker (2008) table 2, 2 threads (2008 Opteron): grid+BIH 2.4-2.9x, SAH+SAH "
                  "1.9-2.3x (exploding dragon: 29 ms, 2.4x and 97 ms, 1.9x for 252k "
                  "triangles).\n\n",
                  runs);
    report_table_header("mesh|triangles|builder|threads|ms|vs serial|vs 1 thread|SAH cost");
    struct rt_pool *pool2 = rt_pool_create(2);
    if (!pool2) {
        report_printf("Skipped: no second thread.\n");
        return 0;
    }
    int failed = 0;
    for (int m = 0; m < mesh_count; m++)
        if (!strcmp(meshes[m].name, "bumpy"))
            failed |= pbuild_mesh(opts, &meshes[m], pool2) != 0;
    struct bench_anim a;
    if (bench_anim_create(&a, BENCH_ANIM_EXPLODE, opts->quick ? EXPLODE_SIZE_QUICK : EXPLODE_SIZE,
                          1) == 0) {
        struct bench_mesh m = bench_anim_mesh(&a);
        failed |= pbuild_mesh(opts, &m, pool2) != 0;
        bench_anim_release(&a);
    } else {
        failed = 1;
    }
    rt_pool_destroy(pool2);
    return failed ? -1 : 0;
}

/* ------------------------------------------------------------ 4. strategies */

enum { BACKEND_OURS, BACKEND_EMBREE_REFIT, BACKEND_EMBREE_REBUILD };

struct strategy {
    const char *label; /* table and plot */
    const char *key;   /* results.csv */
    RTenum value;
    int backend;
};

static const struct strategy strategies[] = {
    {"RT_REFIT", "refit", RT_REFIT, BACKEND_OURS},
    {"RT_REBUILD", "rebuild", RT_REBUILD, BACKEND_OURS},
    {"RT_REBUILD_HEURISTIC", "heuristic", RT_REBUILD_HEURISTIC, BACKEND_OURS},
    {"RT_RESTRUCTURE", "restructure", RT_RESTRUCTURE, BACKEND_OURS},
    {"RT_ASYNC_REBUILD", "async", RT_ASYNC_REBUILD, BACKEND_OURS},
    {"RT_AUTOMATIC", "automatic", RT_AUTOMATIC, BACKEND_OURS},
#ifdef RT_HAVE_EMBREE
    {"Embree refit", "embree_refit", 0, BACKEND_EMBREE_REFIT},
    {"Embree rebuild", "embree_rebuild", 0, BACKEND_EMBREE_REBUILD},
#endif
};
#define STRATEGIES ((int)(sizeof(strategies) / sizeof(strategies[0])))
#define AUTOMATIC_INDEX 5
#define FIXED_OURS 5 /* strategies[0..4]: the fixed strategies of ours */

/* The sweep SAH reference of every frame. */
struct dyn_reference {
    double *sah;           /* per frame */
    struct bench_hit *hit; /* frames x sample count */
};

/* One run of one strategy: per-frame arrays; collapse_ms and
 * wide_refit_ms are totals over the run (ours only). */
struct dyn_series {
    double *frame_ms, *update_ms, *sah_ratio;
    int rebuilds;
    double collapse_ms, wide_refit_ms;
};

/* The wide-layout work the updates of object `name` have done so far
 * (scene_object's collapse_ms_total and wide_refit_ms_total, timed in
 * lib/scene/accel.c): not in the public API, so read through the
 * context, which rtbench may do since it links the static core. */
static void wide_layout_totals(RTuint name, double *collapse_ms, double *wide_refit_ms)
{
    struct rt_context *ctx = rt_current_context();
    const struct scene_object *o = ctx ? scene_objects_lookup(&ctx->scene.objects, name) : NULL;
    *collapse_ms = o ? o->collapse_ms_total : 0.0;
    *wide_refit_ms = o ? o->wide_refit_ms_total : 0.0;
}

void bench_current_projection(double m[16])
{
    struct rt_context *ctx = rt_current_context();
    memcpy(m, ctx->projection.m[ctx->projection.depth - 1], 16 * sizeof(double));
}

int bench_automatic_state(unsigned name, struct bench_automatic_state *out)
{
    struct rt_context *ctx = rt_current_context();
    const struct scene_object *o = ctx ? scene_objects_lookup(&ctx->scene.objects, name) : NULL;
    if (!o || !o->accel)
        return -1;
    out->rebuilds = (int)o->rebuilds;
    out->ms_per_test = ctx->scene.ms_per_test;
    out->expected_rays = o->expected_rays;
    out->lost_ms = o->automatic_lost_ms;
    out->build_ms = o->accel->build_ms;
    out->sah_cost = o->accel->sah_cost;
    out->built_sah_cost = o->accel->built_sah_cost;
    return 0;
}

struct dyn_setup {
    struct bench_anim *anim;
    const struct bench_rays *sample;
    const struct bench_rays *primary; /* Embree's render rays */
    struct bench_hit *scratch;        /* primary.count */
    const struct dyn_reference *ref;
    uint32_t width, height;
    struct bench_agreement *agree; /* per strategy */
#ifdef RT_HAVE_EMBREE
    RTCDevice device;
#endif
};

static int reference_compute(struct dyn_setup *s, struct dyn_reference *ref)
{
    struct bench_anim *a = s->anim;
    const uint32_t n = s->sample->count;
    ref->sah = malloc((size_t)a->frames * sizeof(double));
    ref->hit = malloc((size_t)a->frames * n * sizeof(struct bench_hit));
    if (!ref->sah || !ref->hit)
        return -1;
    for (int f = 0; f < a->frames; f++) {
        bench_anim_frame(a, f);
        struct bench_mesh m = bench_anim_mesh(a);
        struct bench_accel acc;
        ref->sah[f] = bench_fresh_sah(&m, BVH_BUILDER_SWEEP_SAH, &acc);
        if (ref->sah[f] < 0.0)
            return -1;
        bench_kernel_closest(&acc, s->sample->rays, 0, n, &ref->hit[(size_t)f * n]);
        bench_accel_release(&acc);
    }
    return 0;
}

static int run_ours(struct dyn_setup *s, int si, struct dyn_series *out)
{
    struct bench_anim *a = s->anim;
    const uint32_t n = s->sample->count;
    RThit *hits = malloc((size_t)n * sizeof(RThit));
    struct bench_hit *mine = malloc((size_t)n * sizeof(struct bench_hit));
    RTcontext ctx = bench_create_context(DYN_CONFIG);
    int rc = -1;
    if (!hits || !mine || !ctx || !rtMakeCurrent(ctx))
        goto out;
    RTuint obj;
    rtGenObjects(1, &obj);
    bench_anim_frame(a, 0);
    define_object(obj, a);
    rtObjectParameteri(obj, RT_UPDATE_STRATEGY, (RTint)strategies[si].value);
    dyn_camera(s->width, s->height);
    rtInstantiateObject(obj);
    for (int f = 0; f < a->frames; f++) {
        if (f > 0)
            bench_anim_frame(a, f);
        double cpu0 = bench_cpu_ms(), t0 = rt_now_ms();
        if (f > 0)
            rtUpdateVertices(obj, RT_VERTEX_ARRAY, 0, (RTsizei)a->vertex_count, RT_FLOAT, 0,
                             a->positions);
        rtRenderFrame();
        double ms = rt_now_ms() - t0;
        bench_share_add(DYN_THREADS, ms, bench_cpu_ms() - cpu0);
        out->frame_ms[f] = ms;
        out->update_ms[f] = get_f(RT_STAT_UPDATE_TIME) + get_f(RT_STAT_BUILD_TIME);
        RTfloat sah = 0.0f;
        rtGetObjectfv(obj, RT_OBJECT_SAH_COST, &sah);
        out->sah_ratio[f] = s->ref->sah[f] > 0.0 ? sah / s->ref->sah[f] : 0.0;
        rtTraceRays((RTsizei)n, s->sample->rays, hits);
        for (uint32_t i = 0; i < n; i++) {
            mine[i].t = hits[i].t;
            mine[i].prim = hits[i].primitive == RT_INVALID_ID ? BENCH_MISS : hits[i].primitive;
        }
        bench_compare_hits(&s->agree[si], mine, &s->ref->hit[(size_t)f * n], n, 1);
    }
    RTint rebuilds = 0;
    rtGetObjectiv(obj, RT_OBJECT_REBUILDS, &rebuilds);
    out->rebuilds = rebuilds;
    wide_layout_totals(obj, &out->collapse_ms, &out->wide_refit_ms);
    rc = rtGetError() == RT_NO_ERROR ? 0 : -1;
out:
    if (ctx) {
        rtMakeCurrent(NULL);
        rtDestroyContext(ctx);
    }
    free(hits);
    free(mine);
    return rc;
}

#ifdef RT_HAVE_EMBREE
static void dyn_embree_closest(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                               struct bench_hit *hits)
{
    RTCScene scene = ctx;
    struct RTCIntersectContext ic;
    rtcInitIntersectContext(&ic);
    for (uint32_t i = begin; i < end; i++) {
        const RTray *r = &rays[i];
        struct RTCRayHit rh;
        bench_embree_ray_hit(r, &rh);
        rtcIntersect1(scene, &ic, &rh);
        hits[i].t = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? rh.ray.tfar : INFINITY;
        hits[i].prim = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? rh.hit.primID : BENCH_MISS;
    }
}

/* Embree's lines: a dynamic scene, one triangle geometry with its own
 * (padded) vertex buffer; geometry build quality REFIT (refit only after
 * the first build) or LOW (rebuild every commit, Embree's choice for
 * deforming geometry).  Frame: copy the vertices, commit, trace. */
static int run_embree(struct dyn_setup *s, int si, struct dyn_series *out)
{
    struct bench_anim *a = s->anim;
    const int refit = strategies[si].backend == BACKEND_EMBREE_REFIT;
    const uint32_t n = s->sample->count;
    struct bench_hit *mine = malloc((size_t)n * sizeof(struct bench_hit));
    RTCScene scene = rtcNewScene(s->device);
    RTCGeometry geom = rtcNewGeometry(s->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    int rc = -1;
    if (!mine || !scene || !geom)
        goto out;
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_DYNAMIC);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_LOW);
    rtcSetGeometryBuildQuality(geom, refit ? RTC_BUILD_QUALITY_REFIT : RTC_BUILD_QUALITY_LOW);
    /* One spare vertex: Embree reads vertices with 16-byte loads. */
    float *v = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                       3 * sizeof(float), a->vertex_count + 1);
    unsigned *idx = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                            3 * sizeof(unsigned), a->tri_count);
    if (!v || !idx)
        goto out;
    memcpy(idx, a->indices, (size_t)a->tri_count * 3 * sizeof(unsigned));
    rtcAttachGeometry(scene, geom);
    for (int f = 0; f < a->frames; f++) {
        bench_anim_frame(a, f);
        double cpu0 = bench_cpu_ms(), t0 = rt_now_ms();
        memcpy(v, a->positions, (size_t)a->vertex_count * 3 * sizeof(float));
        rtcUpdateGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0);
        rtcCommitGeometry(geom);
        rtcCommitScene(scene);
        double t1 = rt_now_ms();
        double cpu1 = bench_cpu_ms();
        /* The commit runs on Embree's own threads: its share is counted
         * as two threads. */
        bench_share_add(DYN_THREADS, t1 - t0, cpu1 - cpu0);
        if (bench_run_parallel(dyn_embree_closest, scene, s->primary, s->scratch, DYN_THREADS) <
            0.0)
            goto out;
        out->frame_ms[f] = rt_now_ms() - t0;
        out->update_ms[f] = t1 - t0;
        out->sah_ratio[f] = 0.0;
        dyn_embree_closest(scene, s->sample->rays, 0, n, mine);
        bench_compare_hits(&s->agree[si], mine, &s->ref->hit[(size_t)f * n], n, 1);
    }
    out->rebuilds = refit ? 1 : a->frames;
    out->collapse_ms = out->wide_refit_ms = 0.0;
    rc = rtcGetDeviceError(s->device) == RTC_ERROR_NONE ? 0 : -1;
out:
    if (geom)
        rtcReleaseGeometry(geom);
    if (scene)
        rtcReleaseScene(scene);
    free(mine);
    return rc;
}
#endif

static double sum(const double *x, int n, int from)
{
    double s = 0.0;
    for (int i = from; i < n; i++)
        s += x[i];
    return s;
}

static int animation_section(const struct bench_options *opts, struct dyn_setup *s,
                             const char *title, char *summary, size_t summary_size)
{
    struct bench_anim *a = s->anim;
    const int frames = a->frames;
    const int runs = opts->runs < DYN_MAX_RUNS ? opts->runs : DYN_MAX_RUNS;
    struct dyn_reference ref = {NULL, NULL};
    struct bench_agreement agree[STRATEGIES];
    const size_t per = (size_t)STRATEGIES * runs * frames;
    double *buf = calloc(3 * per, sizeof(double));
    int rebuilds[STRATEGIES], done[STRATEGIES];
    double collapse[STRATEGIES][DYN_MAX_RUNS], wide_refit[STRATEGIES][DYN_MAX_RUNS];
    int rc = -1;
    memset(done, 0, sizeof(done));
    memset(agree, 0, sizeof(agree));
    memset(rebuilds, 0, sizeof(rebuilds));
    s->agree = agree;
    if (!buf)
        goto out;
    report_progress("dynamic: %s: sweep reference, %d frames\n", a->name, frames);
    if (reference_compute(s, &ref))
        goto out;
    s->ref = &ref;
    for (int run = 0; run < runs; run++)
        for (int si = 0; si < STRATEGIES; si++) {
            size_t o = ((size_t)si * runs + run) * frames;
            struct dyn_series series = {buf + o, buf + per + o, buf + 2 * per + o, 0, 0.0, 0.0};
            if (run > 0 && sum(buf + ((size_t)si * runs) * frames, frames, 0) > DYN_SLOW_RUN_MS)
                continue;
            report_progress("dynamic: %s: %s, run %d of %d\n", a->name, strategies[si].label,
                            run + 1, runs);
            int r = strategies[si].backend == BACKEND_OURS ? run_ours(s, si, &series) :
#ifdef RT_HAVE_EMBREE
                                                           run_embree(s, si, &series);
#else
                                                           -1;
#endif
            if (r) {
                report_progress("rtbench: dynamic: %s: %s failed\n", a->name,
                                strategies[si].label);
                goto out;
            }
            rebuilds[si] = series.rebuilds;
            collapse[si][run] = series.collapse_ms;
            wide_refit[si][run] = series.wide_refit_ms;
            done[si] = run + 1;
        }

    /* Per-frame medians over runs (plots) and medians of per-run totals. */
    double *col = malloc((size_t)runs * sizeof(double));
    double tot_frame[STRATEGIES], tot_update[STRATEGIES], mean_sah[STRATEGIES],
        max_sah[STRATEGIES], tot_collapse[STRATEGIES], tot_wide_refit[STRATEGIES];
    char file[64];
    snprintf(file, sizeof(file), "dynamic_%s.dat", a->name);
    FILE *data = report_data_file(file);
    if (!col) {
        if (data)
            fclose(data);
        goto out;
    }
    if (data) {
        fprintf(data, "# frame, then per strategy: frame ms, SAH ratio (medians over runs)\n");
        for (int f = 0; f < frames; f++) {
            fprintf(data, "%d", f);
            for (int si = 0; si < STRATEGIES; si++) {
                for (int k = 0; k < 2; k++) {
                    for (int run = 0; run < done[si]; run++)
                        col[run] = buf[(size_t)k * 2 * per +
                                       ((size_t)si * runs + run) * frames + (size_t)f];
                    fprintf(data, " %.4f", bench_median(col, done[si]));
                }
            }
            fprintf(data, "\n");
        }
        fclose(data);
    }
    for (int si = 0; si < STRATEGIES; si++) {
        double ft[DYN_MAX_RUNS], ut[DYN_MAX_RUNS];
        double ms = 0.0, mx = 0.0;
        for (int run = 0; run < done[si]; run++) {
            size_t o = ((size_t)si * runs + run) * frames;
            ft[run] = sum(buf + o, frames, 0);
            ut[run] = sum(buf + per + o, frames, 0);
            for (int f = 0; f < frames; f++) {
                double r = buf[2 * per + o + (size_t)f];
                ms += r;
                mx = r > mx ? r : mx;
            }
        }
        tot_frame[si] = bench_median(ft, done[si]);
        tot_update[si] = bench_median(ut, done[si]);
        tot_collapse[si] = bench_median(collapse[si], done[si]);
        tot_wide_refit[si] = bench_median(wide_refit[si], done[si]);
        mean_sah[si] = ms / ((double)done[si] * frames);
        max_sah[si] = mx;
    }
    free(col);

    report_printf("\n#### %s\n\n", title);
    report_table_header("strategy|update ms|render ms|total ms|ms/frame|vs best fixed|"
                        "mean SAH ratio|max SAH ratio|rebuilds|collapse ms/frame|"
                        "wide refit ms/frame|runs|hits = reference");
    int best = 0;
    for (int si = 1; si < FIXED_OURS; si++)
        if (tot_frame[si] < tot_frame[best])
            best = si;
    for (int si = 0; si < STRATEGIES; si++) {
        char sah_mean[32], sah_max[32];
        if (strategies[si].backend == BACKEND_OURS) {
            snprintf(sah_mean, sizeof(sah_mean), "%.3f", mean_sah[si]);
            snprintf(sah_max, sizeof(sah_max), "%.3f", max_sah[si]);
        } else {
            snprintf(sah_mean, sizeof(sah_mean), "n/a");
            snprintf(sah_max, sizeof(sah_max), "n/a");
        }
        double pct = bench_agreement_percent(&agree[si]);
        char collapse_cell[32], wide_refit_cell[32];
        if (strategies[si].backend == BACKEND_OURS) {
            snprintf(collapse_cell, sizeof(collapse_cell), "%.3f", tot_collapse[si] / frames);
            snprintf(wide_refit_cell, sizeof(wide_refit_cell), "%.3f",
                     tot_wide_refit[si] / frames);
        } else {
            snprintf(collapse_cell, sizeof(collapse_cell), "n/a");
            snprintf(wide_refit_cell, sizeof(wide_refit_cell), "n/a");
        }
        report_row("%s|%.1f|%.1f|%.1f|%.2f|%+.1f%%|%s|%s|%d|%s|%s|%d|%.2f%%",
                   strategies[si].label, tot_update[si], tot_frame[si] - tot_update[si],
                   tot_frame[si], tot_frame[si] / frames,
                   100.0 * (tot_frame[si] / tot_frame[best] - 1.0), sah_mean, sah_max,
                   rebuilds[si], collapse_cell, wide_refit_cell, done[si], pct);
        char key[96];
        snprintf(key, sizeof(key), "dynamic.%s.%s.total_ms", a->name, strategies[si].key);
        report_metric(key, tot_frame[si], 0);
        if (strategies[si].backend == BACKEND_OURS) {
            snprintf(key, sizeof(key), "dynamic.%s.%s.mean_sah_ratio", a->name,
                     strategies[si].key);
            report_metric(key, mean_sah[si], -1);
            snprintf(key, sizeof(key), "dynamic.%s.%s.collapse_ms_per_frame", a->name,
                     strategies[si].key);
            report_metric(key, tot_collapse[si] / frames, 0);
            snprintf(key, sizeof(key), "dynamic.%s.%s.wide_refit_ms_per_frame", a->name,
                     strategies[si].key);
            report_metric(key, tot_wide_refit[si] / frames, 0);
            if (agree[si].agree != agree[si].compared) {
                report_progress("rtbench: dynamic: %s: %s: %llu of %llu sample rays differ from "
                                "the sweep reference\n",
                                a->name, strategies[si].label,
                                (unsigned long long)(agree[si].compared - agree[si].agree),
                                (unsigned long long)agree[si].compared);
                report_check_failed();
            }
        } else if (pct < EMBREE_MIN_AGREEMENT) {
            report_progress("rtbench: dynamic: %s: %s agrees with the reference on only %.2f%% "
                            "of the sample\n",
                            a->name, strategies[si].label, pct);
            report_check_failed();
        }
    }
    double ratio = tot_frame[AUTOMATIC_INDEX] / tot_frame[best];
    report_printf("\nBest fixed strategy: %s (%.1f ms). RT_AUTOMATIC: %.1f ms, %s (%+.1f%%).\n",
                  strategies[best].label, tot_frame[best], tot_frame[AUTOMATIC_INDEX],
                  ratio <= 1.10 ? "within 10% of it" : "NOT within 10% of it",
                  100.0 * (ratio - 1.0));
    /* Embree's rebuild every frame against our best strategy, automatic
     * included (the issue's "today Embree is 3.1x faster"). */
    int ours_best = best;
    if (tot_frame[AUTOMATIC_INDEX] < tot_frame[ours_best])
        ours_best = AUTOMATIC_INDEX;
    char embree_cells[96] = " n/a | n/a |";
    for (int si = 0; si < STRATEGIES; si++)
        if (strategies[si].backend == BACKEND_EMBREE_REBUILD && tot_frame[si] > 0.0) {
            snprintf(embree_cells, sizeof(embree_cells), " %.1f | %.2fx |", tot_frame[si],
                     tot_frame[ours_best] / tot_frame[si]);
            report_printf("Embree rebuilding every frame: %.1f ms; our best (%s) takes %.2fx "
                          "its time.\n",
                          tot_frame[si], strategies[ours_best].label,
                          tot_frame[ours_best] / tot_frame[si]);
            char key[96];
            snprintf(key, sizeof(key), "dynamic.%s.ours_best_over_embree_rebuild", a->name);
            report_metric(key, tot_frame[ours_best] / tot_frame[si], 0);
        }
    size_t used = strlen(summary);
    snprintf(summary + used, summary_size - used,
             "| %s | %s | %.1f | %.1f | %+.1f%% | %s |%s\n", a->name, strategies[best].label,
             tot_frame[best], tot_frame[AUTOMATIC_INDEX], 100.0 * (ratio - 1.0),
             ratio <= 1.10 ? "yes" : "no", embree_cells);

    /* Plots: frame time (log) and SAH ratio over frames. */
    const char *labels[STRATEGIES];
    int has_sah[STRATEGIES];
    for (int si = 0; si < STRATEGIES; si++) {
        labels[si] = strategies[si].label;
        has_sah[si] = strategies[si].backend == BACKEND_OURS;
    }
    char name[64], time_title[256], sah_title[256];
    snprintf(name, sizeof(name), "dynamic_%s", a->name);
    snprintf(time_title, sizeof(time_title),
             "%s: update + render time per frame (%ux%u, 2 threads)", title, s->width, s->height);
    snprintf(sah_title, sizeof(sah_title),
             "%s: SAH cost of the current tree / fresh sweep SAH build", title);
    report_strategy_plots(name, file, time_title, sah_title, STRATEGIES, labels, has_sah);
    rc = 0;
out:
    free(buf);
    free(ref.sah);
    free(ref.hit);
    s->agree = NULL;
    s->ref = NULL;
    return rc;
}

static int strategies_table(const struct bench_options *opts)
{
    const int frames = opts->quick ? DYN_FRAMES_QUICK : DYN_FRAMES;
    const int runs = opts->runs < DYN_MAX_RUNS ? opts->runs : DYN_MAX_RUNS;
    const uint32_t w = opts->quick ? DYN_WIDTH_QUICK : DYN_WIDTH;
    const uint32_t h = opts->quick ? DYN_HEIGHT_QUICK : DYN_HEIGHT;
    const uint32_t sw = opts->quick ? DYN_SAMPLE_W_QUICK : DYN_SAMPLE_W;
    const uint32_t sh = opts->quick ? DYN_SAMPLE_H_QUICK : DYN_SAMPLE_H;
    struct bench_rays primary, sample;
    struct dyn_setup s;
    int rc = -1;
    memset(&s, 0, sizeof(s));
    memset(&primary, 0, sizeof(primary));
    memset(&sample, 0, sizeof(sample));
    if (dyn_rays(&primary, w, h) || dyn_rays(&sample, sw, sh))
        goto out;
    s.scratch = malloc((size_t)primary.count * sizeof(struct bench_hit));
    if (!s.scratch)
        goto out;
    s.primary = &primary;
    s.sample = &sample;
    s.width = w;
    s.height = h;
#ifdef RT_HAVE_EMBREE
    s.device = rtcNewDevice("threads=2");
    if (!s.device)
        goto out;
    rtcSetDeviceErrorFunction(s.device, bench_embree_error, NULL);
#endif
    report_printf("\n### Update strategies over animations (Wald, Ize and Parker (2008) fig. 3, Yoon, Curtis and Manocha (2007) "
                  "table 2)\n\n");
    report_printf(
        "%d frames per animation, %ux%u eye-light frames on a context `%s`. A frame is "
        "rtUpdateVertices (all positions) + rtRenderFrame, timed as a whole; \"update\": "
        "RT_STAT_UPDATE_TIME + RT_STAT_BUILD_TIME (frame 0's lazy first build), \"render\": the "
        "rest. Totals over all frames, median of %d interleaved runs. SAH ratio: "
        "RT_OBJECT_SAH_COST after the frame / SAH cost of a fresh sweep SAH build of the same "
        "frame's geometry (mean and max over frames and runs). \"vs best fixed\": total against "
        "the best of our five fixed strategies. \"runs\": a strategy whose first run took over "
        "%.0f s is not repeated. Rebuilds: RT_OBJECT_REBUILDS at the end "
        "(the first build included). Collapse and wide refit ms/frame: the wall time of "
        "making the 4-wide layout from the binary tree (the collapse after every build and "
        "restructure, the first build included) and of refitting it (after every refit), "
        "timed around those calls (lib/scene/accel.c), summed over the run and divided by "
        "the frames; trees built on the asynchronous build thread are not counted (their "
        "collapse is off the frame).%s Correctness: %ux%u camera rays per frame through "
        "rtTraceRays against the sweep reference.\n",
        frames, w, h, DYN_CONFIG, runs, DYN_SLOW_RUN_MS / 1000.0,
#ifdef RT_HAVE_EMBREE
        " Embree: a dynamic scene with geometry build quality REFIT (\"refit\") or LOW "
        "(\"rebuild\"), a frame = vertex copy + rtcCommitScene (\"update\") + rtcIntersect1 "
        "of the same number of primary rays on two threads (\"render\": tracing only, no "
        "shading); Embree's device has 2 threads.",
#else
        " (Embree lines skipped: built without Embree.)",
#endif
        sw, sh);
    char summary[2048];
    snprintf(summary, sizeof(summary),
             "| animation | best fixed strategy | its total ms | RT_AUTOMATIC total ms | "
             "difference | within 10%% | Embree rebuild total ms | our best / Embree rebuild "
             "|\n|---|---|---|---|---|---|---|---|\n");
    static const struct {
        enum bench_anim_kind kind;
        uint32_t size, size_quick;
        const char *title;
    } anims[] = {
        {BENCH_ANIM_EXPLODE, EXPLODE_SIZE, EXPLODE_SIZE_QUICK, "explode"},
        {BENCH_ANIM_CLOTH, CLOTH_SIZE, CLOTH_SIZE_QUICK, "cloth"},
        {BENCH_ANIM_SOUP, SOUP_BIG, SOUP_BIG_QUICK, "soup"},
    };
    for (int k = 0; k < 3; k++) {
        struct bench_anim a;
        char title[160];
        if (bench_anim_create(&a, anims[k].kind, opts->quick ? anims[k].size_quick : anims[k].size,
                              frames))
            goto out;
        snprintf(title, sizeof(title), "%s, %u triangles", anims[k].title, a.tri_count);
        s.anim = &a;
        int r = animation_section(opts, &s, title, summary, sizeof(summary));
        bench_anim_release(&a);
        if (r)
            goto out;
    }
    report_printf("\n#### RT_AUTOMATIC against the best fixed strategy\n\n%s", summary);
    rc = 0;
out:
#ifdef RT_HAVE_EMBREE
    if (s.device)
        rtcReleaseDevice(s.device);
#endif
    free(s.scratch);
    bench_rays_release(&primary);
    bench_rays_release(&sample);
    return rc;
}

/* ------------------------------------------------------------ CPU time per strategy */

#define DYN_CPU_CONFIG "threads=1 build_threads=1"

#ifdef RT_HAVE_EMBREE
/* Embree's rebuild-every-frame policy by CPU time, for dynamic-cpu: a
 * device of one thread, geometry quality LOW (rebuilt every commit), a
 * frame = vertex copy + commit + rtcIntersect1 of the w x h primary rays
 * on this thread (tracing only, no shading: ours includes the eye-light
 * frame).  Process CPU ms over the frames, or < 0 on failure. */
static double embree_rebuild_cpu(RTCDevice device, struct bench_anim *a,
                                 const struct bench_rays *primary, struct bench_hit *hits,
                                 uint64_t *hit_count)
{
    RTCScene scene = rtcNewScene(device);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    double cpu = -1.0;
    if (!scene || !geom)
        goto out;
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_DYNAMIC);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_LOW);
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_LOW);
    /* One spare vertex: Embree reads vertices with 16-byte loads. */
    float *v = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                       3 * sizeof(float), a->vertex_count + 1);
    unsigned *idx = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                            3 * sizeof(unsigned), a->tri_count);
    if (!v || !idx)
        goto out;
    memcpy(idx, a->indices, (size_t)a->tri_count * 3 * sizeof(unsigned));
    rtcAttachGeometry(scene, geom);
    cpu = 0.0;
    for (int f = 0; f < a->frames; f++) {
        bench_anim_frame(a, f);
        double cpu0 = bench_cpu_ms();
        memcpy(v, a->positions, (size_t)a->vertex_count * 3 * sizeof(float));
        rtcUpdateGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0);
        rtcCommitGeometry(geom);
        rtcCommitScene(scene);
        dyn_embree_closest(scene, primary->rays, 0, primary->count, hits);
        cpu += bench_cpu_ms() - cpu0;
    }
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE)
        cpu = -1.0;
    *hit_count = 0;
    for (uint32_t i = 0; i < primary->count; i++)
        *hit_count += hits[i].prim != BENCH_MISS;
out:
    if (geom)
        rtcReleaseGeometry(geom);
    if (scene)
        rtcReleaseScene(scene);
    return cpu;
}

/* The same bare frames through our API, for the comparison with Embree
 * on equal terms: a fixed strategy (its decisions do not depend on the
 * frame), a frame = rtUpdateVertices + rtTraceRays of the same primary
 * rays on a context `threads=1` (no shading, no framebuffer).  Process
 * CPU ms over the frames; *hit_count: hits of the last frame. */
static double ours_rays_cpu(RTenum strategy, struct bench_anim *a, const struct bench_rays *primary,
                            RThit *hits, uint64_t *hit_count)
{
    RTcontext ctx = bench_create_context(DYN_CPU_CONFIG);
    if (!ctx || !rtMakeCurrent(ctx))
        return -1.0;
    RTuint obj;
    rtGenObjects(1, &obj);
    bench_anim_frame(a, 0);
    define_object(obj, a);
    rtObjectParameteri(obj, RT_UPDATE_STRATEGY, (RTint)strategy);
    dyn_camera(primary->width, primary->height);
    rtInstantiateObject(obj);
    double cpu = 0.0;
    for (int f = 0; f < a->frames; f++) {
        if (f > 0)
            bench_anim_frame(a, f);
        double cpu0 = bench_cpu_ms();
        if (f > 0)
            rtUpdateVertices(obj, RT_VERTEX_ARRAY, 0, (RTsizei)a->vertex_count, RT_FLOAT, 0,
                             a->positions);
        rtTraceRays((RTsizei)primary->count, primary->rays, hits);
        cpu += bench_cpu_ms() - cpu0;
    }
    *hit_count = 0;
    for (uint32_t i = 0; i < primary->count; i++)
        *hit_count += hits[i].t < INFINITY;
    if (rtGetError() != RT_NO_ERROR)
        cpu = -1.0;
    rtMakeCurrent(NULL);
    rtDestroyContext(ctx);
    return cpu;
}
#endif

/*
 * `rtbench dynamic-cpu`: the strategy table's animations, measured by
 * what does not depend on the machine's load: the process's CPU time
 * (one render thread; RT_ASYNC_REBUILD's build thread is counted, it is
 * CPU the strategy spends), and the node + triangle tests of the frames
 * (RT_STAT_NODE_TESTS + RT_STAT_TRIANGLE_TESTS), beside the decisions
 * (rebuilds, mean SAH cost).  Runs interleaved strategy by strategy,
 * median of the run totals.  RT_REFIT is left out of the explosion and
 * the soup unless --only names it: there its tree degrades 10-30x (the
 * strategy table's SAH ratios) and one run takes minutes.
 */
static int dynamic_cpu_table(const struct bench_options *opts)
{
    const int frames = opts->quick ? DYN_FRAMES_QUICK : DYN_FRAMES;
    const int runs = opts->runs < DYN_MAX_RUNS ? opts->runs : DYN_MAX_RUNS;
    const uint32_t w = opts->quick ? DYN_WIDTH_QUICK : DYN_WIDTH;
    const uint32_t h = opts->quick ? DYN_HEIGHT_QUICK : DYN_HEIGHT;
    static const struct {
        enum bench_anim_kind kind;
        uint32_t size, size_quick;
        const char *title;
    } anims[] = {
        {BENCH_ANIM_EXPLODE, EXPLODE_SIZE, EXPLODE_SIZE_QUICK, "explode"},
        {BENCH_ANIM_CLOTH, CLOTH_SIZE, CLOTH_SIZE_QUICK, "cloth"},
        {BENCH_ANIM_SOUP, SOUP_BIG, SOUP_BIG_QUICK, "soup"},
    };
    report_printf("\n### Update strategies by CPU time and traversal work\n\n");
    report_printf("The animations of the strategy table, %d frames at %ux%u, eye light, on a "
                  "context `%s`. CPU ms: process CPU time of rtUpdateVertices + rtRenderFrame "
                  "over the frames (the build thread's included), median of %d interleaved "
                  "run%s; Mtests: node + triangle tests over the frames, millions; mean SAH: "
                  "RT_OBJECT_SAH_COST after each frame, mean over the frames; rebuilds: "
                  "RT_OBJECT_REBUILDS at the end. \"vs best fixed\": CPU time against the "
                  "fixed strategy with the least.\n\n",
                  frames, w, h, DYN_CPU_CONFIG, runs, runs == 1 ? "" : "s");
#ifdef RT_HAVE_EMBREE
    report_printf("Embree rebuild: Embree 3's rebuild-every-frame policy on a device of one "
                  "thread (geometry quality LOW), a frame = vertex copy + rtcCommitScene + "
                  "rtcIntersect1 of the same %ux%u primary rays on one thread (tracing only: "
                  "ours is the whole eye-light frame), process CPU time, interleaved with "
                  "ours run by run.\n\n",
                  w, h);
    struct bench_rays primary;
    struct bench_hit *hits = NULL;
    RThit *rt_hits = NULL;
    RTCDevice device = NULL;
    const int with_embree = !opts->only || bench_strategy_selected(opts->only, "embree_rebuild");
    if (dyn_rays(&primary, w, h))
        return -1;
    hits = malloc((size_t)primary.count * sizeof(*hits));
    rt_hits = malloc((size_t)primary.count * sizeof(*rt_hits));
    if (with_embree)
        device = rtcNewDevice("threads=1");
    if (!hits || !rt_hits || (with_embree && !device)) {
        free(hits);
        free(rt_hits);
        free(primary.rays);
        if (device)
            rtcReleaseDevice(device);
        return -1;
    }
#endif
    report_table_header("animation|strategy|CPU ms|vs best fixed|Mtests|tests vs best "
                        "fixed|mean SAH|rebuilds|runs");
    for (int k = 0; k < 3; k++) {
        struct bench_anim a;
        if (bench_anim_create(&a, anims[k].kind, opts->quick ? anims[k].size_quick : anims[k].size,
                              frames))
            return -1;
        double cpu[STRATEGIES][DYN_MAX_RUNS], tests[STRATEGIES][DYN_MAX_RUNS];
        double sah[STRATEGIES];
        int rebuilds[STRATEGIES], done[STRATEGIES];
        memset(done, 0, sizeof(done));
#ifdef RT_HAVE_EMBREE
        /* Embree's rebuild, then ours bare (rtTraceRays) under the two
         * fixed strategies that rebuild: the comparison on equal terms. */
        static const RTenum bare_strategy[2] = {RT_REBUILD_HEURISTIC, RT_REBUILD};
        static const char *const bare_label[2] = {"RT_REBUILD_HEURISTIC", "RT_REBUILD"};
        double embree_cpu[DYN_MAX_RUNS], bare_cpu[2][DYN_MAX_RUNS];
        int embree_done = 0, bare_done[2] = {0, 0};
        uint64_t embree_hits = 0, bare_hits[2] = {0, 0};
#endif
        for (int run = 0; run < runs; run++) {
#ifdef RT_HAVE_EMBREE
            if (with_embree) {
                report_progress("dynamic-cpu: %s: Embree rebuild, run %d of %d\n",
                                anims[k].title, run + 1, runs);
                double c = embree_rebuild_cpu(device, &a, &primary, hits, &embree_hits);
                if (c >= 0.0)
                    embree_cpu[embree_done++] = c;
                for (int b = 0; b < 2; b++) {
                    report_progress("dynamic-cpu: %s: %s bare rays, run %d of %d\n",
                                    anims[k].title, bare_label[b], run + 1, runs);
                    c = ours_rays_cpu(bare_strategy[b], &a, &primary, rt_hits, &bare_hits[b]);
                    if (c >= 0.0)
                        bare_cpu[b][bare_done[b]++] = c;
                }
            }
#endif
            for (int si = 0; si < STRATEGIES; si++) {
                if (strategies[si].backend != BACKEND_OURS)
                    continue;
                if (opts->only ? !bench_strategy_selected(opts->only, strategies[si].key)
                               : strategies[si].value == RT_REFIT &&
                                     anims[k].kind != BENCH_ANIM_CLOTH)
                    continue;
                report_progress("dynamic-cpu: %s: %s, run %d of %d\n", anims[k].title,
                                strategies[si].label, run + 1, runs);
                RTcontext ctx = bench_create_context(DYN_CPU_CONFIG);
                if (!ctx || !rtMakeCurrent(ctx)) {
                    bench_anim_release(&a);
                    return -1;
                }
                RTuint obj;
                rtGenObjects(1, &obj);
                bench_anim_frame(&a, 0);
                define_object(obj, &a);
                rtObjectParameteri(obj, RT_UPDATE_STRATEGY, (RTint)strategies[si].value);
                dyn_camera(w, h);
                rtInstantiateObject(obj);
                double c = 0.0, t = 0.0, sum_sah = 0.0;
                for (int f = 0; f < frames; f++) {
                    if (f > 0)
                        bench_anim_frame(&a, f);
                    double cpu0 = bench_cpu_ms();
                    if (f > 0)
                        rtUpdateVertices(obj, RT_VERTEX_ARRAY, 0, (RTsizei)a.vertex_count,
                                         RT_FLOAT, 0, a.positions);
                    rtRenderFrame();
                    c += bench_cpu_ms() - cpu0;
                    t += (double)get_f(RT_STAT_NODE_TESTS) + (double)get_f(RT_STAT_TRIANGLE_TESTS);
                    RTfloat s = 0.0f;
                    rtGetObjectfv(obj, RT_OBJECT_SAH_COST, &s);
                    sum_sah += s;
                }
                RTint rb = 0;
                rtGetObjectiv(obj, RT_OBJECT_REBUILDS, &rb);
                rtMakeCurrent(NULL);
                rtDestroyContext(ctx);
                cpu[si][run] = c;
                tests[si][run] = t;
                sah[si] = sum_sah / frames;
                rebuilds[si] = rb;
                done[si] = run + 1;
            }
        }
        double mc[STRATEGIES], mt[STRATEGIES];
        int best = -1;
        for (int si = 0; si < STRATEGIES; si++) {
            if (!done[si])
                continue;
            mc[si] = bench_median(cpu[si], done[si]);
            mt[si] = bench_median(tests[si], done[si]);
            if (strategies[si].value != RT_AUTOMATIC && (best < 0 || mc[si] < mc[best]))
                best = si;
        }
        for (int si = 0; si < STRATEGIES; si++) {
            if (!done[si] || best < 0)
                continue;
            report_row("%s|%s|%.1f|%+.1f%%|%.1f|%+.1f%%|%.2f|%d|%d", anims[k].title,
                       strategies[si].label, mc[si], 100.0 * (mc[si] / mc[best] - 1.0),
                       mt[si] / 1e6, 100.0 * (mt[si] / mt[best] - 1.0), sah[si], rebuilds[si],
                       done[si]);
            char key[96];
            snprintf(key, sizeof(key), "dynamic_cpu.%s.%s.cpu_ms", anims[k].title,
                     strategies[si].key);
            report_metric(key, mc[si], 0);
        }
#ifdef RT_HAVE_EMBREE
        if (embree_done) {
            double e = bench_median(embree_cpu, embree_done);
            char key[96];
            if (best >= 0) {
                /* Our best of all, RT_AUTOMATIC included, against it. */
                int ours = best;
                if (done[AUTOMATIC_INDEX] && mc[AUTOMATIC_INDEX] < mc[ours])
                    ours = AUTOMATIC_INDEX;
                report_row("%s|Embree rebuild (trace only)|%.1f|%+.1f%%|n/a|n/a|n/a|%d|%d",
                           anims[k].title, e, 100.0 * (e / mc[best] - 1.0), a.frames,
                           embree_done);
                report_printf("\n%s: our best (%s, eye-light frames) / Embree rebuild every "
                              "frame (bare primary rays), CPU time: %.2fx\n\n",
                              anims[k].title, strategies[ours].label, mc[ours] / e);
                snprintf(key, sizeof(key), "dynamic_cpu.%s.ours_best_over_embree_rebuild",
                         anims[k].title);
                report_metric(key, mc[ours] / e, 0);
            }
            for (int b = 0; b < 2; b++) {
                if (!bare_done[b])
                    continue;
                double o = bench_median(bare_cpu[b], bare_done[b]);
                report_printf("%s: %s bare (rtUpdateVertices + rtTraceRays of the same rays, "
                              "%llu hits in the last frame) / Embree rebuild every frame (%llu "
                              "hits), CPU time: %.1f / %.1f ms = %.2fx\n\n",
                              anims[k].title, bare_label[b], (unsigned long long)bare_hits[b],
                              (unsigned long long)embree_hits, o, e, o / e);
                snprintf(key, sizeof(key), "dynamic_cpu.%s.%s_bare_over_embree_rebuild",
                         anims[k].title, b ? "rebuild" : "heuristic");
                report_metric(key, o / e, 0);
            }
        }
#endif
        bench_anim_release(&a);
    }
#ifdef RT_HAVE_EMBREE
    free(hits);
    free(rt_hits);
    free(primary.rays);
    if (device)
        rtcReleaseDevice(device);
#endif
    return 0;
}

int bench_dynamic_cpu_section(const struct bench_options *opts)
{
    report_printf("\n## Dynamic scenes: CPU time\n");
    return dynamic_cpu_table(opts);
}

int bench_dynamic_section(const struct bench_options *opts, struct bench_mesh *meshes,
                          int mesh_count)
{
    report_printf("\n## Dynamic scenes\n\n");
    report_printf("Animations (bench/anim_gen.c, deterministic): \"explode\", a torus whose "
                  "triangles fly apart along their normals with random extra velocity; "
                  "\"cloth\", a waving grid; \"soup\", random triangles morphing to a new "
                  "random configuration every %d frames. Context `%s`.\n",
                  BENCH_SOUP_KEY_FRAMES, DYN_CONFIG);
    bench_share_reset();
    int failed = 0;
    failed |= strategies_table(opts) != 0;
    failed |= soup_table(opts) != 0;
    failed |= toplevel_table(opts) != 0;
    failed |= pbuild_table(opts, meshes, mesh_count) != 0;
    bench_share_report();
    return failed ? -1 : 0;
}
