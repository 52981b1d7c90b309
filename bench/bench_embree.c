/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_embree.c - `rtbench embree`: the same meshes and the same rays
 * through Embree 3 in the same process, side by side with ours (compiled
 * only when CMake found Embree; RT_HAVE_EMBREE).
 *
 * Build: ours is the library default (binned SAH, BVH_DEFAULT_BINS bins),
 * timed from triangles to a traceable structure (accel_build_triangles,
 * whose set-up computes the boxes, + accel_gather_triangles +
 * accel_collapse_wide), on one thread and on two
 * (accel_build_parallel_triangles, the gather and the collapse on a
 * 2-thread pool).
 * Embree: one triangle geometry in one scene, rtcCommitScene timed alone
 * (the buffers are filled before the clock starts), at
 * RTC_BUILD_QUALITY_LOW (Morton builder), RTC_BUILD_QUALITY_MEDIUM
 * (Embree's default) and RTC_BUILD_QUALITY_HIGH (spatial splits), on a
 * device created with "threads=1" or "threads=2" so that both builders
 * use the same number of threads.  A fresh scene per run: committing an
 * unchanged scene does no work.  Under --thread-clock the one-thread
 * builds are timed by the calling thread's CPU clock (Embree's
 * one-thread device builds on the calling thread).
 *
 * Trace: rtcIntersect1 / rtcOccluded1 in a scalar loop, driven by the same
 * bench_run_parallel as our kernels on 1 and 2 threads, over the same ray
 * sets (RTray with tnear = tmin, tfar = tmax).  Ours are the kernels'
 * single-ray entries (bench_kernel_closest / bench_kernel_any): no top
 * level and no counters, which API rays have (bench_trace.c's "API"
 * columns measure those).  Runs are interleaved
 * (ours, Embree MEDIUM, Embree HIGH, for each thread count) and each
 * figure is a median.  Every answer is compared with ours ray by ray
 * (hit/miss and t within BENCH_T_TOLERANCE): a comparison of speeds is
 * only meaningful when the answers agree.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "base/pool.h"
#include "base/timer.h"
#include "bench.h"
#include "bench_embree.h"
#include "scene/accel.h"

/* Embree's default (non-robust) triangle test may legitimately miss or
 * hit a ray that grazes a shared edge where our watertight test does the
 * opposite; anything beyond one ray in a thousand is a real difference. */
#define EMBREE_MIN_AGREEMENT 99.9

#define QUALITIES 2
static const enum RTCBuildQuality qualities[QUALITIES] = {RTC_BUILD_QUALITY_MEDIUM,
                                                          RTC_BUILD_QUALITY_HIGH};
static const char *const quality_names[QUALITIES] = {"MEDIUM", "HIGH"};

const char *bench_embree_version(void)
{
    return RTC_VERSION_STRING;
}

/* Minor page faults of the whole process so far (every thread: ours and
 * Embree's workers).  A build's difference counts the pages it touched
 * for the first time, each one zeroed by the kernel: 4 KB each, or 2 MB
 * where the kernel gave a transparent huge page (a process started with
 * huge pages disabled, prctl PR_SET_THP_DISABLE, counts 4 KB pages only,
 * so faults x 4 KB are then its fresh bytes). */
static long minor_faults(void)
{
    struct rusage ru;
    return getrusage(RUSAGE_SELF, &ru) == 0 ? ru.ru_minflt : 0;
}

/* System CPU ms of the whole process so far (getrusage ru_stime, every
 * thread).  A build's difference is mostly its page faults: the zeroing
 * of fresh pages, and on a virtual machine whose host takes freed guest
 * memory back (free page reporting) the host's faulting it in again,
 * which the guest sees as a slow first write.  Measured on the
 * development machine (a VM with free page reporting): the same 17
 * huge-page faults of bumpy's layout writes took 0 to 95 ms of system
 * time from one build to the next, which no user-space change can see
 * in its instruction counts; this column separates that cost from the
 * builder's own. */
static double system_ms(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru) != 0)
        return 0.0;
    return (double)ru.ru_stime.tv_sec * 1e3 + (double)ru.ru_stime.tv_usec * 1e-3;
}

/* A committed scene over the mesh; *commit_ms gets rtcCommitScene's time
 * on bench_clock_ms(threads), `threads` being the device's.  NULL on
 * failure. */
static RTCScene embree_scene(RTCDevice device, const struct bench_mesh *mesh,
                             enum RTCBuildQuality quality, int threads, double *commit_ms,
                             long *commit_faults, double *commit_sys_ms)
{
    RTCScene scene = rtcNewScene(device);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!scene || !geom)
        goto fail;
    rtcSetSceneBuildQuality(scene, quality);
    rtcSetGeometryBuildQuality(geom, quality);
    /* New (Embree-owned) buffers rather than shared ones: Embree reads
     * vertices with 16-byte loads and needs padding after the last one,
     * which our arrays do not have. */
    float *v = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                       3 * sizeof(float), mesh->vertex_count);
    unsigned *idx = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                            3 * sizeof(unsigned), mesh->tri_count);
    if (!v || !idx)
        goto fail;
    memcpy(v, mesh->positions, (size_t)mesh->vertex_count * 3 * sizeof(float));
    memcpy(idx, mesh->indices, (size_t)mesh->tri_count * 3 * sizeof(unsigned));
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    geom = NULL;
    double cpu_start = bench_cpu_ms();
    double start = rt_now_ms();
    long faults_start = minor_faults();
    double sys_start = system_ms();
    double clock_start = bench_clock_ms(threads);
    rtcCommitScene(scene);
    *commit_ms = bench_clock_ms(threads) - clock_start;
    if (commit_faults)
        *commit_faults = minor_faults() - faults_start;
    if (commit_sys_ms)
        *commit_sys_ms = system_ms() - sys_start;
    bench_share_add(threads, rt_now_ms() - start, bench_cpu_ms() - cpu_start);
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE)
        goto fail;
    return scene;
fail:
    if (geom)
        rtcReleaseGeometry(geom);
    if (scene)
        rtcReleaseScene(scene);
    return NULL;
}

/* Embree's stream entries (rtcIntersect1M / rtcOccluded1M, the context
 * flagged RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT) instead of the scalar
 * loop over rtcIntersect1 / rtcOccluded1, with `--stream embree`
 * (bench_embree_stream): the "Embree" columns then time Embree's stream
 * on the same rays, beside ours with `--stream ours` (harness.c: our
 * stream entry), so that a stream is compared with a stream
 * (docs/performance-log.md, round 60). */
/* The stream's rays in pieces of this many (RTCRayHit arrays on the
 * stack). */
#define EMBREE_STREAM_PIECE 256u

static void embree_stream_closest(RTCScene scene, const RTray *rays, uint32_t begin,
                                  uint32_t end, struct bench_hit *hits)
{
    struct RTCIntersectContext ic;
    rtcInitIntersectContext(&ic);
    ic.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    struct RTCRayHit rh[EMBREE_STREAM_PIECE];
    for (uint32_t b = begin; b < end; b += EMBREE_STREAM_PIECE) {
        const uint32_t n = end - b < EMBREE_STREAM_PIECE ? end - b : EMBREE_STREAM_PIECE;
        for (uint32_t i = 0; i < n; i++)
            bench_embree_ray_hit(&rays[b + i], &rh[i]);
        rtcIntersect1M(scene, &ic, rh, n, sizeof(rh[0]));
        for (uint32_t i = 0; i < n; i++) {
            if (rh[i].hit.geomID != RTC_INVALID_GEOMETRY_ID) {
                hits[b + i].t = rh[i].ray.tfar;
                hits[b + i].prim = rh[i].hit.primID;
            } else {
                hits[b + i].t = INFINITY;
                hits[b + i].prim = BENCH_MISS;
            }
        }
    }
}

static void embree_stream_any(RTCScene scene, const RTray *rays, uint32_t begin, uint32_t end,
                              struct bench_hit *hits)
{
    struct RTCIntersectContext ic;
    rtcInitIntersectContext(&ic);
    ic.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    struct RTCRay ray[EMBREE_STREAM_PIECE];
    for (uint32_t b = begin; b < end; b += EMBREE_STREAM_PIECE) {
        const uint32_t n = end - b < EMBREE_STREAM_PIECE ? end - b : EMBREE_STREAM_PIECE;
        for (uint32_t i = 0; i < n; i++)
            bench_embree_ray(&rays[b + i], &ray[i]);
        rtcOccluded1M(scene, &ic, ray, n, sizeof(ray[0]));
        for (uint32_t i = 0; i < n; i++) {
            const int occluded = ray[i].tfar == -INFINITY;
            hits[b + i].t = occluded ? 0.0f : INFINITY;
            hits[b + i].prim = occluded ? 0 : BENCH_MISS;
        }
    }
}

static void embree_kernel_closest(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                                  struct bench_hit *hits)
{
    RTCScene scene = ctx;
    if (bench_embree_stream()) {
        embree_stream_closest(scene, rays, begin, end, hits);
        return;
    }
    struct RTCIntersectContext ic;
    rtcInitIntersectContext(&ic);
    for (uint32_t i = begin; i < end; i++) {
        const RTray *r = &rays[i];
        struct RTCRayHit rh;
        bench_embree_ray_hit(r, &rh);
        rtcIntersect1(scene, &ic, &rh);
        if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
            hits[i].t = rh.ray.tfar;
            hits[i].prim = rh.hit.primID;
        } else {
            hits[i].t = INFINITY;
            hits[i].prim = BENCH_MISS;
        }
    }
}

static void embree_kernel_any(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                              struct bench_hit *hits)
{
    RTCScene scene = ctx;
    if (bench_embree_stream()) {
        embree_stream_any(scene, rays, begin, end, hits);
        return;
    }
    struct RTCIntersectContext ic;
    rtcInitIntersectContext(&ic);
    for (uint32_t i = begin; i < end; i++) {
        const RTray *r = &rays[i];
        struct RTCRay ray;
        bench_embree_ray(r, &ray);
        rtcOccluded1(scene, &ic, &ray);
        /* Embree marks an occluded ray by setting tfar to -inf. */
        int occluded = ray.tfar == -INFINITY;
        hits[i].t = occluded ? 0.0f : INFINITY;
        hits[i].prim = occluded ? 0 : BENCH_MISS;
    }
}

/* The build table's Embree qualities: LOW (Embree's fastest builder,
 * Morton codes), MEDIUM (its default, binned SAH) and HIGH (binned SAH
 * with spatial splits). */
#define BUILD_QUALITIES 3
static const enum RTCBuildQuality build_qualities[BUILD_QUALITIES] = {
    RTC_BUILD_QUALITY_LOW, RTC_BUILD_QUALITY_MEDIUM, RTC_BUILD_QUALITY_HIGH};
static const char *const build_quality_names[BUILD_QUALITIES] = {"LOW", "MEDIUM", "HIGH"};
static const char *const build_quality_keys[BUILD_QUALITIES] = {"low", "medium", "high"};

/* One row of the build table's page-fault table: the medians of each
 * path's minor faults and system ms per build (-1: path not run). */
struct build_faults {
    const char *mesh;
    int threads;
    double faults[1 + BUILD_QUALITIES];
    double sys_ms[1 + BUILD_QUALITIES];
};

/* Build times on `threads` threads: ours (serial binned SAH on one
 * thread, accel_build_triangles, accel_build_parallel_triangles on pool
 * otherwise, and the collapse to the wide layout, through
 * bench_accel_build_wide with the leaf-ordered triangles where a library
 * object's fresh build makes them (scene_accel_triangles_at_build): what
 * the wide walk reads, as Embree's commit builds what its walk reads) and Embree's qualities
 * on a device of that many threads, interleaved runs; --only picks the
 * paths (ours, low, medium, high).  *row_faults receives the medians of
 * the minor page faults around the same timed calls. */
static int embree_build_row(const struct bench_options *opts, RTCDevice device, int threads,
                            struct rt_pool *pool, const struct bench_mesh *mesh,
                            struct build_faults *row_faults)
{
    row_faults->mesh = mesh->name;
    row_faults->threads = threads;
    for (int i = 0; i < 1 + BUILD_QUALITIES; i++) {
        row_faults->faults[i] = -1.0;
        row_faults->sys_ms[i] = -1.0;
    }
    double *times = calloc((size_t)3 * (1 + BUILD_QUALITIES) * opts->runs, sizeof(*times));
    if (!times)
        return -1;
    double *fault_runs = times + (size_t)(1 + BUILD_QUALITIES) * opts->runs;
    double *sys_runs = fault_runs + (size_t)(1 + BUILD_QUALITIES) * opts->runs;
    int run_path[1 + BUILD_QUALITIES];
    for (int p = 0; p < 1 + BUILD_QUALITIES; p++)
        run_path[p] = !opts->only ||
                      bench_strategy_selected(opts->only, p ? build_quality_keys[p - 1] : "ours");
    /* The leaf-ordered copy only where a library object's fresh build
     * makes it (scene_accel_triangles_at_build: below 32 MiB of it). */
    struct bvh_build_params lib_params;
    bvh_build_params_default(&lib_params);
    lib_params.wide_layout = (int)bench_layout_width();
    const int with_tri = scene_accel_triangles_at_build(&lib_params, mesh->tri_count);
    for (int run = 0; run < opts->runs; run++) {
        if (run_path[0]) {
            struct bench_accel acc;
            double cpu_start = bench_cpu_ms();
            double start = rt_now_ms();
            long faults_start = minor_faults();
            double sys_start = system_ms();
            double clock_start = bench_clock_ms(threads);
            int rc = bench_accel_build_wide(&acc, mesh, NULL, threads > 1 ? pool : NULL,
                                            with_tri);
            times[run] = bench_clock_ms(threads) - clock_start;
            fault_runs[run] = (double)(minor_faults() - faults_start);
            sys_runs[run] = system_ms() - sys_start;
            bench_share_add(threads, rt_now_ms() - start, bench_cpu_ms() - cpu_start);
            if (rc) {
                free(times);
                return -1;
            }
            bench_accel_release(&acc);
        }
        for (int q = 0; q < BUILD_QUALITIES; q++) {
            double ms;
            if (!run_path[1 + q])
                continue;
            long faults = 0;
            double sys = 0.0;
            RTCScene scene =
                embree_scene(device, mesh, build_qualities[q], threads, &ms, &faults, &sys);
            if (!scene) {
                free(times);
                return -1;
            }
            rtcReleaseScene(scene);
            times[(1 + q) * opts->runs + run] = ms;
            fault_runs[(1 + q) * opts->runs + run] = (double)faults;
            sys_runs[(1 + q) * opts->runs + run] = sys;
        }
    }
    double med[1 + BUILD_QUALITIES];
    char cell[1 + BUILD_QUALITIES][24];
    char ratio[BUILD_QUALITIES][24];
    for (int i = 0; i < 1 + BUILD_QUALITIES; i++) {
        row_faults->faults[i] =
            run_path[i] ? bench_median(&fault_runs[i * opts->runs], opts->runs) : -1.0;
        row_faults->sys_ms[i] =
            run_path[i] ? bench_median(&sys_runs[i * opts->runs], opts->runs) : -1.0;
        med[i] = run_path[i] ? bench_median(&times[i * opts->runs], opts->runs) : 0.0;
        snprintf(cell[i], sizeof(cell[i]), run_path[i] ? "%.2f" : "-", med[i]);
    }
    for (int q = 0; q < BUILD_QUALITIES; q++)
        snprintf(ratio[q], sizeof(ratio[q]), run_path[0] && med[1 + q] > 0 ? "%.2f" : "-",
                 med[1 + q] > 0 ? med[0] / med[1 + q] : 0.0);
    report_row("%s|%u|%d|%s|%s|%s|%s|%s|%s|%s", mesh->name, mesh->tri_count, threads, cell[0],
               cell[1], cell[2], cell[3], ratio[0], ratio[1], ratio[2]);
    /* One thread keeps the keys earlier results.csv files have. */
    const char *suffix = threads == 1 ? "" : "_2t";
    char key[96];
    if (run_path[0]) {
        snprintf(key, sizeof(key), "embree.%s.build%s.ours_ms", mesh->name, suffix);
        report_metric(key, med[0], 0);
    }
    for (int q = 0; q < BUILD_QUALITIES; q++) {
        if (!run_path[1 + q])
            continue;
        snprintf(key, sizeof(key), "embree.%s.build%s.embree_%s_ms", mesh->name, suffix,
                 build_quality_names[q]);
        report_metric(key, med[1 + q], -1);
    }
    free(times);
    return 0;
}

struct trace_row {
    double mrays[2][1 + QUALITIES]; /* [threads - 1][ours, MEDIUM, HIGH] */
    struct bench_agreement agree[QUALITIES];
    /* Of the rays where Embree's answer is not ours: how many the
     * brute-force reference (trace_closest_brute_force, the exact test
     * over every triangle) was asked about, at most REFEREE_MAX, and on
     * how many of those its answer is ours. */
    uint32_t refereed[QUALITIES];
    uint32_t ours_right[QUALITIES];
};

/* Rays a disagreement is refereed on, per set and quality: each costs a
 * pass over every triangle (a million on bumpy). */
#define REFEREE_MAX 64

/* Where ours and theirs differ, which one the brute-force reference
 * agrees with: ours (counted in *right) or not.  An any-hit record says
 * only occluded or not, so the reference's closest hit within the ray's
 * interval decides it. */
static void referee(const struct bench_mesh *mesh, const struct bench_rays *set, int any_hit,
                    const struct bench_hit *ours, const struct bench_hit *theirs,
                    uint32_t *refereed, uint32_t *right)
{
    *refereed = *right = 0;
    for (uint32_t i = 0; i < set->count && *refereed < REFEREE_MAX; i++) {
        struct bench_agreement a;
        memset(&a, 0, sizeof(a));
        bench_compare_hits(&a, &ours[i], &theirs[i], 1, 1);
        if (a.agree)
            continue;
        const struct bench_hit ref = bench_brute_force_hit(mesh, &set->rays[i]);
        (*refereed)++;
        if (any_hit) {
            *right += (ours[i].prim != BENCH_MISS) == (ref.prim != BENCH_MISS);
        } else {
            memset(&a, 0, sizeof(a));
            bench_compare_hits(&a, &ours[i], &ref, 1, 1);
            *right += a.agree == 1;
        }
    }
}

static int embree_trace_set(const struct bench_options *opts, const struct bench_mesh *mesh,
                            struct bench_accel *acc, RTCScene scenes[QUALITIES],
                            const struct bench_rays *set, int any_hit,
                            struct bench_hit *ours, struct bench_hit *theirs, struct trace_row *row)
{
    const int paths = 2 * (1 + QUALITIES);
    double *times = malloc((size_t)paths * opts->runs * sizeof(*times));
    if (!times)
        return -1;
    memset(row, 0, sizeof(*row));
    /* --only ours,medium,high: only these paths (e.g. one path alone under
     * perf stat); --threads 1 or 2: only that thread count. */
    int run_path[1 + QUALITIES];
    for (int p = 0; p < 1 + QUALITIES; p++)
        run_path[p] = !opts->only ||
                      bench_strategy_selected(opts->only, p == 0   ? "ours"
                                                          : p == 1 ? "medium"
                                                                   : "high");
    memset(times, 0, (size_t)paths * opts->runs * sizeof(*times));
    for (int run = 0; run < opts->runs; run++) {
        for (int t = 0; t < 2; t++) {
            if (!bench_threads_selected(opts, t + 1))
                continue;
            for (int p = 0; p < 1 + QUALITIES; p++) {
                double ms;
                if (!run_path[p])
                    continue;
                if (p == 0)
                    ms = bench_run_parallel(any_hit ? bench_kernel_any : bench_kernel_closest, acc,
                                            set, ours, t + 1);
                else
                    ms = bench_run_parallel(any_hit ? embree_kernel_any : embree_kernel_closest,
                                            scenes[p - 1], set, theirs, t + 1);
                if (ms < 0.0) {
                    free(times);
                    return -1;
                }
                times[(t * (1 + QUALITIES) + p) * opts->runs + run] = ms;
                /* Compare once per quality: the answers do not change
                 * from run to run. */
                if (p > 0 && run == 0 && t == (opts->threads == 2) && run_path[0]) {
                    bench_compare_hits(&row->agree[p - 1], ours, theirs, set->count, 1);
                    referee(mesh, set, any_hit, ours, theirs, &row->refereed[p - 1],
                            &row->ours_right[p - 1]);
                }
            }
        }
    }
    for (int t = 0; t < 2; t++) {
        for (int p = 0; p < 1 + QUALITIES; p++) {
            double ms = bench_median(&times[(t * (1 + QUALITIES) + p) * opts->runs], opts->runs);
            row->mrays[t][p] = ms > 0.0 ? set->count / (ms * 1e3) : 0.0;
        }
    }
    free(times);
    return 0;
}

/* Tests per ray of ours on one ray set, for the table under the trace
 * table (counted once, untimed). */
struct tests_row {
    const char *mesh, *set;
    int any_hit;
    uint32_t rays;
    double nodes, tris, answered;
    double wide_sah;
    uint32_t wide_nodes, packets;
    double lanes_per_node, tris_per_leaf;
};

/* The wide layout's fill: lanes in use per wide node, and triangles per
 * leaf lane (the collapses differ in both: round 36, cl2). */
static void wide_fill(const struct bvh4 *wide, double *lanes_per_node, double *tris_per_leaf)
{
    const uint32_t width = wide->width;
    uint64_t lanes = 0, leaves = 0, tris = 0;
    for (uint32_t w = 0; w < wide->node_count; w++) {
        const float *b = width == 8 ? &wide->nodes8[w].bounds[0][0] : &wide->nodes[w].bounds[0][0];
        const uint8_t *count = width == 8 ? wide->nodes8[w].count : wide->nodes[w].count;
        for (uint32_t l = 0; l < width; l++) {
            if (!(b[l] <= b[3 * width + l]))
                continue; /* unused */
            lanes++;
            leaves += count[l] != 0;
            tris += count[l];
        }
    }
    *lanes_per_node = wide->node_count ? (double)lanes / wide->node_count : 0.0;
    *tris_per_leaf = leaves ? (double)tris / (double)leaves : 0.0;
}

static int embree_trace_mesh(const struct bench_options *opts, RTCDevice device,
                             const struct bench_mesh *mesh, FILE *plot_data,
                             struct tests_row tests[3])
{
    struct bench_accel acc;
    struct bench_rays sets[3];
    RTCScene scenes[QUALITIES] = {NULL, NULL};
    struct bench_hit *ours = NULL, *theirs = NULL;
    int rc = -1;
    memset(sets, 0, sizeof(sets));
    memset(&acc, 0, sizeof(acc));
    if (bench_accel_build(&acc, mesh, NULL) || bench_rays_trace_sets(sets, mesh, &acc, opts->quick))
        goto out;
    for (int q = 0; q < QUALITIES; q++) {
        double ms;
        if (!(scenes[q] = embree_scene(device, mesh, qualities[q], 1, &ms, NULL, NULL)))
            goto out;
    }
    uint32_t max_rays = sets[0].count > sets[1].count ? sets[0].count : sets[1].count;
    ours = malloc((size_t)max_rays * sizeof(*ours));
    theirs = malloc((size_t)max_rays * sizeof(*theirs));
    if (!ours || !theirs)
        goto out;
    for (int s = 0; s < 3; s++) {
        struct trace_row row;
        int any_hit = s == 2;
        if (sets[s].count == 0)
            continue;
        report_progress("embree: %s: %s rays (%u)\n", mesh->name, sets[s].name, sets[s].count);
        tests[s].mesh = mesh->name;
        tests[s].set = sets[s].name;
        tests[s].any_hit = any_hit;
        tests[s].rays = sets[s].count;
        bench_count_tests_ours(&acc, &sets[s], any_hit, &tests[s].nodes, &tests[s].tris,
                               &tests[s].answered);
        tests[s].wide_nodes = acc.wide.node_count;
        tests[s].packets = acc.wide.packet_count;
        tests[s].wide_sah = acc.wide.node_count
                                ? accel_wide_sah_cost(&acc.wide, BVH_WIDE_NODE_COST, 1.0)
                                : 0.0;
        wide_fill(&acc.wide, &tests[s].lanes_per_node, &tests[s].tris_per_leaf);
        if (embree_trace_set(opts, mesh, &acc, scenes, &sets[s], any_hit, ours, theirs, &row))
            goto out;
        for (int t = 0; t < 2; t++) {
            const double *m = row.mrays[t];
            if (!bench_threads_selected(opts, t + 1))
                continue;
            report_row("%s|%s%s|%d|%.3f|%.3f|%.3f|%.2f|%.2f|%.2f%% (%llu, %u/%u)|%.2f%% (%llu, "
                       "%u/%u)|%.2f%%",
                       mesh->name,
                       sets[s].name, any_hit ? " (any hit)" : "", t + 1, m[0], m[1], m[2],
                       m[1] > 0 ? m[0] / m[1] : 0.0, m[2] > 0 ? m[0] / m[2] : 0.0,
                       bench_agreement_percent(&row.agree[0]),
                       (unsigned long long)(row.agree[0].compared - row.agree[0].agree),
                       row.ours_right[0], row.refereed[0], bench_agreement_percent(&row.agree[1]),
                       (unsigned long long)(row.agree[1].compared - row.agree[1].agree),
                       row.ours_right[1], row.refereed[1],
                       row.agree[0].compared
                           ? 100.0 * (double)row.agree[0].same_prim / row.agree[0].compared
                           : 100.0);
            char key[96];
            snprintf(key, sizeof(key), "embree.%s.%s.%dt.ours_over_medium", mesh->name,
                     sets[s].name, t + 1);
            report_metric(key, m[1] > 0 ? m[0] / m[1] : 0.0, 1);
            for (int q = 0; q < QUALITIES; q++) {
                snprintf(key, sizeof(key), "embree.%s.%s.%dt.embree_%s", mesh->name, sets[s].name,
                         t + 1, quality_names[q]);
                report_metric(key, m[1 + q], -1);
            }
            if (plot_data)
                fprintf(plot_data, "\"%s/%s %dT\" %.4f %.4f %.4f\n", mesh->name, sets[s].name,
                        t + 1, m[0], m[1], m[2]);
        }
        for (int q = 0; q < QUALITIES; q++) {
            char key[96];
            snprintf(key, sizeof(key), "check.%s.%s.embree_%s_agree_pct", mesh->name, sets[s].name,
                     quality_names[q]);
            report_metric(key, bench_agreement_percent(&row.agree[q]), -1);
            if (bench_agreement_percent(&row.agree[q]) < EMBREE_MIN_AGREEMENT) {
                report_check_failed();
                report_progress("embree: WARNING: %s/%s: Embree %s agrees with ours on only "
                                "%.3f%% of rays (%llu hit/miss differences)\n",
                                mesh->name, sets[s].name, quality_names[q],
                                bench_agreement_percent(&row.agree[q]),
                                (unsigned long long)row.agree[q].hit_miss_diff);
            }
            /* Where the two differ, ours must be the reference's answer. */
            if (row.ours_right[q] != row.refereed[q]) {
                report_check_failed();
                report_progress("embree: WARNING: %s/%s: of %u rays where Embree %s differs, "
                                "the brute-force reference gives our answer on only %u\n",
                                mesh->name, sets[s].name, row.refereed[q], quality_names[q],
                                row.ours_right[q]);
            }
        }
    }
    rc = 0;
out:
    if (rc)
        report_progress("rtbench: embree: %s failed\n", mesh->name);
    for (int q = 0; q < QUALITIES; q++) {
        if (scenes[q])
            rtcReleaseScene(scenes[q]);
    }
    for (int s = 0; s < 3; s++)
        bench_rays_release(&sets[s]);
    free(ours);
    free(theirs);
    bench_accel_release(&acc);
    return rc;
}

/* Embree's memory, through the device's memory monitor: every
 * allocation and release of its allocator (whole blocks, so slack
 * included).  The sum over one embree_scene call, less the vertex and
 * index buffers filled before the commit, is what the built scene holds. */
static bool embree_memory(void *user, ssize_t bytes, bool post)
{
    (void)post;
    *(int64_t *)user += (int64_t)bytes;
    return true;
}

/* One row of the memory table: bytes per triangle of ours per layout
 * (nodes + leaves; the binary layout's leaves are the 36-byte
 * leaf-ordered triangles and the 4-byte primitive index) and of Embree's
 * scene at each quality. */
static int embree_memory_row(RTCDevice device, int64_t *counter, const struct bench_mesh *mesh)
{
    double n = mesh->tri_count ? (double)mesh->tri_count : 1.0;
    double embree[QUALITIES];
    for (int q = 0; q < QUALITIES; q++) {
        double ms;
        int64_t before = *counter;
        RTCScene scene = embree_scene(device, mesh, qualities[q], 1, &ms, NULL, NULL);
        if (!scene)
            return -1;
        int64_t buffers = (int64_t)mesh->vertex_count * 12 + (int64_t)mesh->tri_count * 12;
        embree[q] = (double)(*counter - before - buffers) / n;
        rtcReleaseScene(scene);
    }
    struct bench_accel acc;
    if (bench_accel_build(&acc, mesh, NULL))
        return -1;
    double binary = (32.0 * acc.bvh.node_count + 40.0 * acc.bvh.prim_count) / n;
    double wide[2], leaves[2];
    for (int w = 0; w < 2; w++) {
        bvh4_release(&acc.wide);
        if (accel_collapse_wide_quality(&acc.wide, &acc.bvh, acc.tri, w ? 8 : 4, NULL, NULL,
                                        bench_collapse())) {
            bench_accel_release(&acc);
            return -1;
        }
        wide[w] = (double)(bvh4_node_bytes(&acc.wide) + bvh4_leaf_bytes(&acc.wide)) / n;
        leaves[w] = (double)bvh4_leaf_bytes(&acc.wide) / n;
    }
    bench_accel_release(&acc);
    report_row("%s|%.1f|%.1f|%.1f|%.1f|%.1f|%.1f|%.1f", mesh->name, binary, wide[0], wide[1],
               leaves[0], leaves[1], embree[0], embree[1]);
    return 0;
}

int bench_embree_section(const struct bench_options *opts, struct bench_mesh *meshes,
                         int mesh_count)
{
    if (mesh_count == 0) {
        /* --mesh kitchen without the BART data: nothing to measure, which
         * is not a failure (the data is optional). */
        report_printf("\n## Against Embree %s\n\nThe BART kitchen is skipped: %s.\n",
                      RTC_VERSION_STRING,
                      opts->kitchen_skipped ? opts->kitchen_skipped : "no mesh selected");
        return 0;
    }
    RTCDevice device = rtcNewDevice("threads=1");
    if (!device) {
        report_printf("\n## Embree\n\nrtcNewDevice failed (error %d); section skipped.\n",
                      (int)rtcGetDeviceError(NULL));
        return -1;
    }
    rtcSetDeviceErrorFunction(device, bench_embree_error, NULL);
    int failed = 0;

    report_printf("\n## Against Embree %s\n\n", RTC_VERSION_STRING);
    report_printf("Build, median of %d runs, ms, on 1 and 2 threads (Embree: a device created "
                  "with \"threads=1\" or \"threads=2\"). Ours: binned SAH %d bins, the "
                  "triangles' boxes + build + the %s %s collapse, as a library object's "
                  "fresh build (everything before the first ray of a frame that walks the "
                  "wide layout only): from 32 MiB of leaf-ordered triangles (bumpy) the "
                  "collapse reads the mesh and the copy the binary walks read is left to "
                  "their first need, not timed; below, the triangles are gathered into leaf "
                  "order and the collapse reads the copy; the builders compute the boxes as "
                  "they set up their refs); on 2 threads the build is accel_build_parallel "
                  "(binned SAH at the top, binned SAH subtrees) and the collapse on the same "
                  "pool. Embree: rtcCommitScene alone "
                  "at build quality LOW (Morton), MEDIUM (binned SAH, its default) and HIGH "
                  "(spatial splits). %s \"ours/Embree\" is a time ratio: above 1 means we "
                  "build slower.\n\n",
                  opts->runs, BVH_DEFAULT_BINS, bench_layout_name(), bench_collapse_name(),
                  bench_thread_clock() ? "One thread: the calling thread's CPU clock "
                                         "(--thread-clock); 2 threads: wall clock."
                                       : "Wall clock.");
    report_table_header("mesh|triangles|threads|ours ms|Embree LOW ms|Embree MEDIUM ms|"
                        "Embree HIGH ms|ours/LOW|ours/MEDIUM|ours/HIGH");
    bench_share_reset();
    struct build_faults *faults = calloc(2 * (size_t)mesh_count, sizeof(*faults));
    int fault_rows = 0;
    if (!faults) {
        rtcReleaseDevice(device);
        return -1;
    }
    /* Every one-thread row before the "threads=2" device exists: Embree's
     * TBB thread limit is process-wide, so once a two-thread device is
     * created, a "threads=1" device's commits may run on two threads too
     * (measured: Embree MEDIUM on bumpy in half its one-thread time, and a
     * CPU share above 100 %, when the rows were interleaved per mesh). */
    if (opts->threads != 2)
        for (int m = 0; m < mesh_count; m++) {
            report_progress("embree: %s: builds, 1 thread\n", meshes[m].name);
            failed |= embree_build_row(opts, device, 1, NULL, &meshes[m], &faults[fault_rows++]) != 0;
        }
    if (opts->threads != 1) {
        RTCDevice device2 = rtcNewDevice("threads=2");
        struct rt_pool *pool2 = rt_pool_create(2);
        if (device2 && pool2) {
            rtcSetDeviceErrorFunction(device2, bench_embree_error, NULL);
            for (int m = 0; m < mesh_count; m++) {
                report_progress("embree: %s: builds, 2 threads\n", meshes[m].name);
                failed |=
                    embree_build_row(opts, device2, 2, pool2, &meshes[m], &faults[fault_rows++]) !=
                    0;
            }
        } else {
            failed = 1;
        }
        if (device2)
            rtcReleaseDevice(device2);
        rt_pool_destroy(pool2);
    }
    report_printf("\nMinor page faults per build (median of the runs above; getrusage "
                  "ru_minflt of the process around the same timed call, every thread): each "
                  "is a page the build touched for the first time and the kernel zeroed, 4 KB, "
                  "or 2 MB where it gave a transparent huge page (run rtbench with huge pages "
                  "disabled, prctl PR_SET_THP_DISABLE, to read faults x 4 KB as fresh "
                  "bytes). In parentheses: the median system CPU ms per build (getrusage "
                  "ru_stime, every thread), mostly those faults; on a virtual machine whose "
                  "host takes back freed memory it moves from build to build with the host's "
                  "load, not with the builder.\n\n");
    report_table_header("mesh|threads|ours|Embree LOW|Embree MEDIUM|Embree HIGH");
    for (int r = 0; r < fault_rows; r++) {
        char cell[1 + BUILD_QUALITIES][48];
        for (int i = 0; i < 1 + BUILD_QUALITIES; i++) {
            if (faults[r].faults[i] >= 0)
                snprintf(cell[i], sizeof(cell[i]), "%.0f (%.1f)", faults[r].faults[i],
                         faults[r].sys_ms[i]);
            else
                snprintf(cell[i], sizeof(cell[i]), "-");
        }
        report_row("%s|%d|%s|%s|%s|%s", faults[r].mesh, faults[r].threads, cell[0], cell[1],
                   cell[2], cell[3]);
    }
    free(faults);

    /* --only ...,build: the build table alone (A/B runs of a builder). */
    if (opts->only && bench_strategy_selected(opts->only, "build")) {
        bench_share_report();
        rtcReleaseDevice(device);
        return failed ? -1 : 0;
    }

    int64_t embree_bytes = 0;
    rtcSetDeviceMemoryMonitorFunction(device, embree_memory, &embree_bytes);
    report_printf("\nMemory, bytes per triangle of the acceleration structure: ours, nodes "
                  "and leaves per layout (binary: 32-byte nodes, 36 bytes of leaf-ordered "
                  "vertices and a 4-byte primitive index per triangle; bvh4/bvh8: 128/256-byte "
                  "nodes and 160-byte packets of four triangles; \"leaves\": the packets "
                  "alone, 40 bytes a triangle in full packets, more where leaves leave lanes "
                  "empty); Embree: what its allocator "
                  "holds after rtcCommitScene (device memory monitor, whole blocks; BVH8 "
                  "nodes of 256 bytes and Triangle4 leaf blocks of 176 on AVX2, 44 bytes a "
                  "triangle in full blocks), less the vertex and index buffers.\n\n");
    report_table_header("mesh|binary|bvh4|bvh8|bvh4 leaves|bvh8 leaves|Embree MEDIUM|Embree HIGH");
    for (int m = 0; m < mesh_count; m++)
        failed |= embree_memory_row(device, &embree_bytes, &meshes[m]) != 0;
    rtcSetDeviceMemoryMonitorFunction(device, NULL, NULL);

    report_printf("\nTrace, Mrays/s (median of %d runs), the trace section's ray sets; Embree "
                  "through rtcIntersect1 / rtcOccluded1 in a scalar loop, both driven by the "
                  "same thread split. Ours: the object kernels' single-ray entries "
                  "(closest1 / any1 on a wide layout: the ray set up inside the walk), without "
                  "the top level and without counting, as Embree's one-geometry scene; API rays "
                  "(rtTraceRays, through the top level, counted) are the trace section's "
                  "\"API\" columns. \"ours/Embree\" is a throughput ratio: below 1 means we "
                  "are slower. \"agree\": rays where Embree's answer equals ours (hit/miss and "
                  "t within %g relative) over all rays of the set, in brackets the number of "
                  "rays that differ (the percentage rounds one ray in a million to 100.00%%) "
                  "and, of up to %d of them, on how many the brute-force reference (every "
                  "triangle, the exact watertight test) gives our answer; "
                  "\"same prim\": of those, the same triangle (MEDIUM).\n\n",
                  opts->runs, (double)BENCH_T_TOLERANCE, REFEREE_MAX);
    report_table_header("mesh|rays|threads|ours|Embree MEDIUM|Embree HIGH|ours/MEDIUM|"
                        "ours/HIGH|agree MEDIUM|agree HIGH|same prim");
    FILE *plot_data = report_data_file("embree.dat");
    struct tests_row *tests = calloc(3 * (size_t)(unsigned)mesh_count, sizeof(*tests));
    if (!tests)
        failed = 1;
    for (int m = 0; m < mesh_count && tests; m++)
        failed |= embree_trace_mesh(opts, device, &meshes[m], plot_data, &tests[3 * m]) != 0;
    bench_share_report();
    if (opts->kitchen_skipped)
        report_printf("\nThe BART kitchen (the fourth mesh) is skipped: %s.\n",
                      opts->kitchen_skipped);
    if (tests) {
        report_printf("\nTests per ray of ours (the walk \"ours\" times: kernels %s, %s layout), "
                      "%s collapse, counted once on one thread; \"answered\": rays that hit (closest hit) or "
                      "are occluded (any hit).\n\n",
                      bench_kernels()->name, bench_layout_name(), bench_collapse_name());
        report_table_header("mesh|rays|count|node tests/ray|triangle tests/ray|answered|wide "
                            "nodes|packets|wide SAH|lanes/node|triangles/leaf lane");
        for (int i = 0; i < 3 * mesh_count; i++) {
            const struct tests_row *t = &tests[i];
            if (!t->mesh)
                continue;
            report_row("%s|%s%s|%u|%.2f|%.2f|%.1f%%|%u|%u|%.3f|%.2f|%.2f", t->mesh, t->set,
                       t->any_hit ? " (any hit)" : "", t->rays, t->nodes, t->tris, t->answered,
                       t->wide_nodes, t->packets, t->wide_sah, t->lanes_per_node,
                       t->tris_per_leaf);
            char key[96];
            snprintf(key, sizeof(key), "embree.%s.%s.ours_node_tests_per_ray", t->mesh, t->set);
            report_metric(key, t->nodes, -1);
            snprintf(key, sizeof(key), "embree.%s.%s.ours_triangle_tests_per_ray", t->mesh,
                     t->set);
            report_metric(key, t->tris, -1);
        }
        free(tests);
    }
    if (plot_data) {
        fclose(plot_data);
        report_plot("embree", "set terminal pngcairo size 1100,520 font ',10'\n"
                              "set output 'embree.png'\n"
                              "set title 'Ours against Embree (median), Mrays/s'\n"
                              "set style data histograms\n"
                              "set style histogram clustered gap 1\n"
                              "set style fill solid 0.85 border -1\n"
                              "set ylabel 'Mrays/s'\n"
                              "set yrange [0:*]\n"
                              "set xtics rotate by -35\n"
                              "set bmargin 7\n"
                              "set rmargin 8\n"
                              "set key top right\n"
                              "set grid ytics\n"
                              "plot 'embree.dat' using 2:xtic(1) title 'ours', '' using 3 title "
                              "'Embree MEDIUM', '' using 4 title 'Embree HIGH'\n");
    }
    rtcReleaseDevice(device);
    return failed ? -1 : 0;
}

/* ------------------------------------------------------------------ packets
 * `rtbench packets` (bench_packets.c) against Embree's packet interface:
 * rtcIntersect8 / rtcOccluded8 over groups of eight consecutive rays of a
 * set (a row of eight pixels for primary rays), valid lanes beyond the end
 * of a chunk off, beside rtcIntersect1 / rtcOccluded1 on the same scene
 * (MEDIUM, Embree's default). */

struct bench_embree_packets {
    RTCDevice device;
    RTCScene scene;
};

void *bench_embree_packets_new(const struct bench_mesh *mesh)
{
    struct bench_embree_packets *e = calloc(1, sizeof(*e));
    double ms;
    if (!e)
        return NULL;
    e->device = rtcNewDevice("threads=1");
    if (!e->device) {
        free(e);
        return NULL;
    }
    rtcSetDeviceErrorFunction(e->device, bench_embree_error, NULL);
    e->scene = embree_scene(e->device, mesh, RTC_BUILD_QUALITY_MEDIUM, 1, &ms, NULL, NULL);
    if (!e->scene) {
        rtcReleaseDevice(e->device);
        free(e);
        return NULL;
    }
    return e;
}

void bench_embree_packets_release(void *ctx)
{
    struct bench_embree_packets *e = ctx;
    if (!e)
        return;
    rtcReleaseScene(e->scene);
    rtcReleaseDevice(e->device);
    free(e);
}

void bench_embree_kernel_closest1(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                                  struct bench_hit *hits)
{
    embree_kernel_closest(((struct bench_embree_packets *)ctx)->scene, rays, begin, end, hits);
}

void bench_embree_kernel_any1(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                              struct bench_hit *hits)
{
    embree_kernel_any(((struct bench_embree_packets *)ctx)->scene, rays, begin, end, hits);
}

void bench_embree_kernel_closest8(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                                  struct bench_hit *hits)
{
    RTCScene scene = ((struct bench_embree_packets *)ctx)->scene;
    struct RTCIntersectContext ic;
    rtcInitIntersectContext(&ic);
    ic.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    for (uint32_t g = begin; g < end; g += 8) {
        RTC_ALIGN(32) int valid[8];
        RTC_ALIGN(32) struct RTCRayHit8 rh;
        for (int j = 0; j < 8; j++) {
            const uint32_t i = g + (uint32_t)j;
            valid[j] = i < end ? -1 : 0;
            const RTray *r = &rays[i < end ? i : g];
            rh.ray.org_x[j] = r->org[0];
            rh.ray.org_y[j] = r->org[1];
            rh.ray.org_z[j] = r->org[2];
            rh.ray.tnear[j] = r->tmin;
            rh.ray.dir_x[j] = r->dir[0];
            rh.ray.dir_y[j] = r->dir[1];
            rh.ray.dir_z[j] = r->dir[2];
            rh.ray.time[j] = 0.0f;
            rh.ray.tfar[j] = r->tmax;
            rh.ray.mask[j] = 0xFFFFFFFFu;
            rh.ray.id[j] = 0;
            rh.ray.flags[j] = 0;
            rh.hit.geomID[j] = RTC_INVALID_GEOMETRY_ID;
            rh.hit.primID[j] = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0][j] = RTC_INVALID_GEOMETRY_ID;
        }
        rtcIntersect8(valid, scene, &ic, &rh);
        for (int j = 0; j < 8 && g + (uint32_t)j < end; j++) {
            struct bench_hit *h = &hits[g + (uint32_t)j];
            if (rh.hit.geomID[j] != RTC_INVALID_GEOMETRY_ID) {
                h->t = rh.ray.tfar[j];
                h->prim = rh.hit.primID[j];
            } else {
                h->t = INFINITY;
                h->prim = BENCH_MISS;
            }
        }
    }
}

void bench_embree_kernel_any8(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                              struct bench_hit *hits)
{
    RTCScene scene = ((struct bench_embree_packets *)ctx)->scene;
    struct RTCIntersectContext ic;
    rtcInitIntersectContext(&ic);
    ic.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    for (uint32_t g = begin; g < end; g += 8) {
        RTC_ALIGN(32) int valid[8];
        RTC_ALIGN(32) struct RTCRay8 ray;
        for (int j = 0; j < 8; j++) {
            const uint32_t i = g + (uint32_t)j;
            valid[j] = i < end ? -1 : 0;
            const RTray *r = &rays[i < end ? i : g];
            ray.org_x[j] = r->org[0];
            ray.org_y[j] = r->org[1];
            ray.org_z[j] = r->org[2];
            ray.tnear[j] = r->tmin;
            ray.dir_x[j] = r->dir[0];
            ray.dir_y[j] = r->dir[1];
            ray.dir_z[j] = r->dir[2];
            ray.time[j] = 0.0f;
            ray.tfar[j] = r->tmax;
            ray.mask[j] = 0xFFFFFFFFu;
            ray.id[j] = 0;
            ray.flags[j] = 0;
        }
        rtcOccluded8(valid, scene, &ic, &ray);
        for (int j = 0; j < 8 && g + (uint32_t)j < end; j++) {
            const int occluded = ray.tfar[j] == -INFINITY;
            hits[g + (uint32_t)j].t = occluded ? 0.0f : INFINITY;
            hits[g + (uint32_t)j].prim = occluded ? 0 : BENCH_MISS;
        }
    }
}
