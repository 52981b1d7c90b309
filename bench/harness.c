/* SPDX-License-Identifier: Apache-2.0 */
/*
 * harness.c - the measuring machinery every section shares (bench.h): our
 * BVH over a mesh, the closest-hit and any-hit kernels over it, the
 * parallel ray loop, work counters and the median.
 *
 * The parallel loop is deliberately plain: the calling thread plus
 * threads - 1 pthreads created per run (about 50 us, well under 1% of the
 * shortest timed run of a full benchmark) pull chunks of BENCH_CHUNK rays
 * from one atomic counter.  The same loop drives our kernels and Embree's,
 * so neither path gets a better scheduler than the other.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "accel/build_parallel.h"
#include "accel/collapse_mesh.h"
#include "base/alloc.h"
#include "base/timer.h"
#include "bench.h"

/* The benchmark's choice of ISA table, made once from the command line
 * before any section runs (the benchmark is an application, not the
 * library, so a file-scope choice is fine here). */
static const struct trace_kernels *chosen_kernels;
/* Its name as the configuration key takes it (isa=), NULL for the best. */
static const char *chosen_isa;

/* --layout binary: the binary walk even where the table has a wide one. */
static int binary_layout;
/* --layout bvh4 / bvh8: that width; 0 = the table's own (wide_width). */
static uint32_t chosen_width;

int bench_select_layout(const char *name)
{
    if (!strcmp(name, "binary") || !strcmp(name, "bvh4") || !strcmp(name, "bvh8")) {
        binary_layout = !strcmp(name, "binary");
        chosen_width = !strcmp(name, "bvh8") ? 8 : !strcmp(name, "bvh4") ? 4 : 0;
        return 0;
    }
    return -1;
}

/* --collapse greedy / optimal: the collapse every wide layout the
 * benchmark builds takes (bench_accel_build_pool, the tests-per-ray
 * table), as an object with rtHint(RT_ACCELERATION_HINT) RT_FASTEST /
 * RT_NICEST does. */
static enum bvh_collapse chosen_collapse = BVH_COLLAPSE_GREEDY;

int bench_select_collapse(const char *name)
{
    if (!strcmp(name, "greedy") || !strcmp(name, "optimal")) {
        chosen_collapse = !strcmp(name, "optimal") ? BVH_COLLAPSE_OPTIMAL : BVH_COLLAPSE_GREEDY;
        return 0;
    }
    return -1;
}

enum bvh_collapse bench_collapse(void)
{
    return chosen_collapse;
}

const char *bench_collapse_name(void)
{
    return chosen_collapse == BVH_COLLAPSE_OPTIMAL ? "optimal" : "greedy";
}

uint32_t bench_layout_width(void)
{
    if (chosen_width)
        return chosen_width;
    uint32_t w = bench_kernels()->wide_width;
    return w ? w : 4;
}

const char *bench_layout_name(void)
{
    if (binary_layout || !bench_kernels()->closest4)
        return "binary";
    return bench_layout_width() == 8 ? "bvh8" : "bvh4";
}

const struct trace_kernels *bench_kernels(void)
{
    return chosen_kernels ? chosen_kernels : trace_kernels_best();
}

int bench_select_isa(const char *name)
{
    enum trace_isa isa;
    if (trace_isa_parse(name, strlen(name), &isa))
        return -1;
    chosen_kernels = trace_kernels_get(isa);
    if (!chosen_kernels)
        return -1;
    chosen_isa = name;
    return 0;
}

/* --config's item (bench_select_config), "" without one. */
static char chosen_config[64];

int bench_select_config(const char *item)
{
    if (!strchr(item, '=') || strlen(item) >= sizeof(chosen_config))
        return -1;
    strcpy(chosen_config, item);
    return 0;
}

RTcontext bench_create_context(const char *config)
{
    if (!chosen_isa && !chosen_config[0])
        return rtCreateContext(config);
    char full[256];
    const int n = snprintf(full, sizeof(full), "%s%s%s %s", config, chosen_isa ? " isa=" : "",
                           chosen_isa ? chosen_isa : "", chosen_config);
    if (n < 0 || (size_t)n >= sizeof(full))
        return NULL;
    return rtCreateContext(full);
}

int bench_accel_build(struct bench_accel *acc, const struct bench_mesh *mesh,
                      const struct bvh_build_params *params)
{
    return bench_accel_build_pool(acc, mesh, params, NULL);
}

int bench_accel_build_pool(struct bench_accel *acc, const struct bench_mesh *mesh,
                           const struct bvh_build_params *params, struct rt_pool *pool)
{
    return bench_accel_build_wide(acc, mesh, params, pool, 1);
}

int bench_accel_build_wide(struct bench_accel *acc, const struct bench_mesh *mesh,
                           const struct bvh_build_params *params, struct rt_pool *pool,
                           int with_tri)
{
    memset(acc, 0, sizeof(*acc));
    int rc;
    /* A large parallel build's scratch mapping, for the collapse. */
    struct rt_large_block spare = {0};
    if (pool) {
        /* The parallel builder takes the triangles (as the library's
         * objects do, scene/accel.c): no box array. */
        rc = accel_build_parallel_triangles(&acc->bvh, mesh->positions, mesh->indices,
                                            mesh->tri_count, params, pool, &spare);
    } else {
        /* The serial builder from the triangles too (no box array), its
         * refs' mapping for the collapse when large. */
        rc = accel_build_triangles(&acc->bvh, mesh->positions, mesh->indices, mesh->tri_count,
                                   params, &spare);
    }
    if (rc)
        return -1;
    /* Without the leaf-ordered copy the collapse reads the mesh
     * (collapse_mesh.h): the same layout byte for byte. */
    if (with_tri)
        acc->tri = accel_gather_triangles_pool(&acc->bvh, mesh->positions, mesh->indices, pool);
    const struct collapse_triangles tris = {acc->tri, acc->tri ? NULL : mesh->positions,
                                            acc->tri ? NULL : mesh->indices, 0};
    if ((with_tri && !acc->tri) ||
        accel_collapse_wide_source(&acc->wide, &acc->bvh, &tris, bench_layout_width(), pool,
                                   &spare, chosen_collapse)) {
        rt_free_large(&spare);
        rt_free(acc->tri);
        bvh_release(&acc->bvh);
        memset(acc, 0, sizeof(*acc));
        return -1;
    }
    rt_free_large(&spare); /* zeroed when the layout took it */
    return 0;
}

void bench_accel_release(struct bench_accel *acc)
{
    bvh_release(&acc->bvh);
    rt_free(acc->tri);
    bvh4_release(&acc->wide);
    memset(acc, 0, sizeof(*acc));
}

double bench_fresh_sah(const struct bench_mesh *mesh, enum bvh_builder builder,
                       struct bench_accel *keep)
{
    struct bvh_build_params params;
    struct bench_accel local;
    struct bench_accel *acc = keep ? keep : &local;
    bvh_build_params_default(&params);
    params.builder = builder;
    if (bench_accel_build(acc, mesh, &params))
        return -1.0;
    double sah = accel_sah_cost(&acc->bvh, BVH_C_TRAV, BVH_C_ISECT);
    if (!keep)
        bench_accel_release(acc);
    return sah;
}

/* --stream ours: our single-ray rows through the stream entry
 * (kernels.h, stream_pair) where the table has one; --stream embree:
 * Embree's through rtcIntersect1M / rtcOccluded1M (bench_embree.c).  So
 * that one binary times walk1 and the stream on the same rays (the
 * answers are the same; the agreement columns check it), and a stream is
 * compared with Embree's stream as well as with its scalar loop. */
static int stream_ours;
static int stream_embree;

int bench_select_stream(const char *keys)
{
    int ours = 0, embree = 0;
    const char *k = keys;
    while (*k) {
        const size_t len = strcspn(k, ",");
        if (len == 4 && !strncmp(k, "ours", 4))
            ours = 1;
        else if (len == 6 && !strncmp(k, "embree", 6))
            embree = 1;
        else
            return -1;
        k += len;
        if (*k == ',' && *++k == '\0')
            return -1;
    }
    if (!ours && !embree)
        return -1;
    stream_ours = ours;
    stream_embree = embree;
    return 0;
}

int bench_embree_stream(void)
{
    return stream_embree;
}

/* The stream entry for the layout when --stream ours chose it, or NULL. */
static trace_stream1_fn bench_stream(const struct trace_kernels *k, const struct bvh4 *wide,
                                     int any_hit)
{
    if (!stream_ours || !k->stream_pair)
        return NULL;
    return k->stream_pair(wide, any_hit);
}

/* RTray's floats as trace_stream1_fn reads them: org, tmin, dir, tmax. */
typedef char bench_rtray_layout[offsetof(RTray, tmin) == 3 * sizeof(float) &&
                                        offsetof(RTray, dir) == 4 * sizeof(float) &&
                                        offsetof(RTray, tmax) == 7 * sizeof(float) &&
                                        sizeof(RTray) == 8 * sizeof(float)
                                    ? 1
                                    : -1];

/* rays[begin, end) through a stream entry, BENCH_CHUNK at a time. */
static void bench_stream_run(trace_stream1_fn stream, const struct bvh4 *wide, const RTray *rays,
                             uint32_t begin, uint32_t end, struct bench_hit *hits, int any_hit)
{
    struct trace_hit h[BENCH_CHUNK];
    unsigned char got[BENCH_CHUNK];
    for (uint32_t b = begin; b < end; b += BENCH_CHUNK) {
        const uint32_t n = end - b < BENCH_CHUNK ? end - b : BENCH_CHUNK;
        stream(wide, (const float *)(const void *)&rays[b], sizeof(RTray) / sizeof(float), n,
               any_hit ? NULL : h, got);
        for (uint32_t i = 0; i < n; i++) {
            if (any_hit) {
                hits[b + i].t = got[i] ? 0.0f : INFINITY;
                hits[b + i].prim = got[i] ? 0 : BENCH_MISS;
            } else {
                hits[b + i].t = got[i] ? h[i].t : INFINITY;
                hits[b + i].prim = got[i] ? h[i].prim : BENCH_MISS;
            }
        }
    }
}

void bench_kernel_closest(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                          struct bench_hit *hits)
{
    const struct bench_accel *acc = ctx;
    const struct trace_kernels *k = bench_kernels();
    const int wide = k->closest1 && !binary_layout && acc->wide.node_count;
    const trace_stream1_fn stream = wide ? bench_stream(k, &acc->wide, 0) : NULL;
    if (stream) {
        bench_stream_run(stream, &acc->wide, rays, begin, end, hits, 0);
        return;
    }
    /* The layout's walk, chosen once (kernels.h, walk1), as a caller
     * tracing many rays over one layout would. */
    const trace_walk1_fn walk1 = wide && k->walk1 ? k->walk1(&acc->wide, 0) : NULL;
    for (uint32_t i = begin; i < end; i++) {
        const RTray *r = &rays[i];
        struct trace_hit h;
        int got;
        /* The wide walk sets the ray up itself (kernels.h, closest1). */
        if (walk1) {
            got = walk1(&acc->wide, r->org, r->dir, r->tmin, r->tmax, &h, NULL);
        } else if (wide) {
            got = k->closest1(&acc->wide, &acc->bvh, acc->tri, r->org, r->dir, r->tmin, r->tmax,
                              &h, NULL);
        } else {
            struct trace_ray ray;
            trace_ray_init_single(&ray, r->org, r->dir, r->tmin);
            got = k->closest(&acc->bvh, acc->tri, &ray, r->tmax, &h, NULL);
        }
        if (got) {
            hits[i].t = h.t;
            hits[i].prim = h.prim;
        } else {
            hits[i].t = INFINITY;
            hits[i].prim = BENCH_MISS;
        }
    }
}

void bench_kernel_any(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                      struct bench_hit *hits)
{
    const struct bench_accel *acc = ctx;
    const struct trace_kernels *k = bench_kernels();
    const int wide = k->any1 && !binary_layout && acc->wide.node_count;
    const trace_stream1_fn stream = wide ? bench_stream(k, &acc->wide, 1) : NULL;
    if (stream) {
        bench_stream_run(stream, &acc->wide, rays, begin, end, hits, 1);
        return;
    }
    const trace_walk1_fn walk1 = wide && k->walk1 ? k->walk1(&acc->wide, 1) : NULL;
    for (uint32_t i = begin; i < end; i++) {
        const RTray *r = &rays[i];
        int occluded;
        if (walk1) {
            occluded = walk1(&acc->wide, r->org, r->dir, r->tmin, r->tmax, NULL, NULL);
        } else if (wide) {
            occluded = k->any1(&acc->wide, &acc->bvh, acc->tri, r->org, r->dir, r->tmin, r->tmax,
                               NULL);
        } else {
            struct trace_ray ray;
            trace_ray_init_single(&ray, r->org, r->dir, r->tmin);
            occluded = k->any(&acc->bvh, acc->tri, &ray, r->tmax, NULL);
        }
        hits[i].t = occluded ? 0.0f : INFINITY;
        hits[i].prim = occluded ? 0 : BENCH_MISS;
    }
}

struct parallel_job {
    bench_kernel_fn kernel;
    void *ctx;
    const RTray *rays;
    uint32_t count;
    struct bench_hit *hits;
    uint64_t next; /* next unclaimed ray; atomic */
};

static void *parallel_worker(void *arg)
{
    struct parallel_job *job = arg;
    for (;;) {
        uint64_t begin = __atomic_fetch_add(&job->next, BENCH_CHUNK, __ATOMIC_RELAXED);
        if (begin >= job->count)
            break;
        uint64_t end = begin + BENCH_CHUNK < job->count ? begin + BENCH_CHUNK : job->count;
        job->kernel(job->ctx, job->rays, (uint32_t)begin, (uint32_t)end, job->hits);
    }
    return NULL;
}

#define BENCH_MAX_THREADS 64
#define SHARE_SLOTS 3 /* 1 thread, 2 threads, more */

/* CPU share bookkeeping (bench_share_*): main thread only. */
static struct {
    double cpu_ms[SHARE_SLOTS];
    double core_ms[SHARE_SLOTS]; /* wall time x threads */
} share;

static int share_slot(int threads)
{
    return threads <= 1 ? 0 : threads == 2 ? 1 : 2;
}

double bench_cpu_ms(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0)
        return 0.0;
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

void bench_share_reset(void)
{
    memset(&share, 0, sizeof(share));
}

void bench_share_add(int threads, double wall_ms, double cpu_ms)
{
    int s = share_slot(threads);
    share.cpu_ms[s] += cpu_ms;
    share.core_ms[s] += wall_ms * (threads < 1 ? 1 : threads);
}

double bench_share_percent(int threads)
{
    int s = share_slot(threads);
    return share.core_ms[s] > 0.0 ? 100.0 * share.cpu_ms[s] / share.core_ms[s] : -1.0;
}

void bench_share_report(void)
{
    double one = bench_share_percent(1), two = bench_share_percent(2);
    report_printf("\nCPU share of the timed runs (process CPU time / (wall time x threads); "
                  "below 100%% when other processes took our cores or a thread idled waiting "
                  "for the last chunk):");
    if (one >= 0.0)
        report_printf(" 1 thread %.0f%%", one);
    if (two >= 0.0)
        report_printf("%s 2 threads %.0f%%", one >= 0.0 ? "," : "", two);
    report_printf(".\n");
}

/* --thread-clock: one-thread runs are timed by the calling thread's CPU
 * clock, so that time slices other processes take do not count. */
static int thread_clock;

void bench_use_thread_clock(void)
{
    thread_clock = 1;
}

static double thread_cpu_ms(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0)
        return 0.0;
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

int bench_thread_clock(void)
{
    return thread_clock;
}

double bench_clock_ms(int threads)
{
    return threads <= 1 && thread_clock ? thread_cpu_ms() : rt_now_ms();
}

double bench_run_parallel(bench_kernel_fn kernel, void *ctx, const struct bench_rays *set,
                          struct bench_hit *hits, int threads)
{
    if (threads <= 1 && thread_clock) {
        double cpu_start = bench_cpu_ms();
        double start = rt_now_ms();
        double thread_start = thread_cpu_ms();
        struct parallel_job job = {kernel, ctx, set->rays, set->count, hits, 0};
        parallel_worker(&job);
        double ms = thread_cpu_ms() - thread_start;
        bench_share_add(1, rt_now_ms() - start, bench_cpu_ms() - cpu_start);
        return ms;
    }

    struct parallel_job job = {kernel, ctx, set->rays, set->count, hits, 0};
    pthread_t tid[BENCH_MAX_THREADS];
    int started = 0;
    if (threads > BENCH_MAX_THREADS)
        threads = BENCH_MAX_THREADS;
    double cpu_start = bench_cpu_ms();
    double start = rt_now_ms();
    for (int i = 1; i < threads; i++) {
        if (pthread_create(&tid[started], NULL, parallel_worker, &job) != 0)
            break;
        started++;
    }
    parallel_worker(&job);
    for (int i = 0; i < started; i++)
        pthread_join(tid[i], NULL);
    double ms = rt_now_ms() - start;
    bench_share_add(threads, ms, bench_cpu_ms() - cpu_start);
    /* A thread that could not start would make the figure a lie about the
     * thread count, though every ray was traced. */
    return started == threads - 1 ? ms : -1.0;
}

void bench_count_tests(const struct bench_accel *acc, const struct bench_rays *set,
                       double *nodes_per_ray, double *tris_per_ray)
{
    struct trace_counters c = {0, 0};
    for (uint32_t i = 0; i < set->count; i++) {
        const RTray *r = &set->rays[i];
        struct trace_ray ray;
        struct trace_hit h;
        trace_ray_init(&ray, r->org, r->dir, r->tmin);
        trace_closest(&acc->bvh, acc->tri, &ray, r->tmax, &h, &c);
    }
    double n = set->count ? (double)set->count : 1.0;
    *nodes_per_ray = (double)c.node_tests / n;
    *tris_per_ray = (double)c.triangle_tests / n;
}

void bench_count_tests_wide(const struct bench_accel *acc, const struct bench_rays *set,
                            double *nodes_per_ray, double *tris_per_ray)
{
    const struct trace_kernels *k = trace_kernels_best();
    struct trace_counters c = {0, 0};
    for (uint32_t i = 0; i < set->count && k->closest4; i++) {
        const RTray *r = &set->rays[i];
        struct trace_ray ray;
        struct trace_hit h;
        trace_ray_init(&ray, r->org, r->dir, r->tmin);
        k->closest4(&acc->wide, &acc->bvh, acc->tri, &ray, r->tmax, &h, &c);
    }
    double n = set->count ? (double)set->count : 1.0;
    *nodes_per_ray = (double)c.node_tests / n;
    *tris_per_ray = (double)c.triangle_tests / n;
}

void bench_count_tests_ours(const struct bench_accel *acc, const struct bench_rays *set,
                            int any_hit, double *nodes_per_ray, double *tris_per_ray,
                            double *answered_percent)
{
    /* The same walk as bench_kernel_closest / bench_kernel_any pick. */
    const struct trace_kernels *k = bench_kernels();
    const int wide = (any_hit ? k->any4 != NULL : k->closest4 != NULL) && !binary_layout &&
                     acc->wide.node_count;
    struct trace_counters c = {0, 0};
    uint64_t answered = 0;
    for (uint32_t i = 0; i < set->count; i++) {
        const RTray *r = &set->rays[i];
        struct trace_ray ray;
        struct trace_hit h;
        trace_ray_init(&ray, r->org, r->dir, r->tmin);
        /* closest1 / any1 where the table has them, as the timed loops:
         * their 8-wide walks test nodes by the fused test (node_fused.h),
         * which visits a few boxes more than closest4 / any4's. */
        if (any_hit)
            answered += (wide && k->any1 ? k->any1(&acc->wide, &acc->bvh, acc->tri, r->org,
                                                   r->dir, r->tmin, r->tmax, &c)
                         : wide ? k->any4(&acc->wide, &acc->bvh, acc->tri, &ray, r->tmax, &c)
                                : k->any(&acc->bvh, acc->tri, &ray, r->tmax, &c)) != 0;
        else
            answered += (wide && k->closest1
                             ? k->closest1(&acc->wide, &acc->bvh, acc->tri, r->org, r->dir,
                                           r->tmin, r->tmax, &h, &c)
                         : wide ? k->closest4(&acc->wide, &acc->bvh, acc->tri, &ray, r->tmax, &h,
                                              &c)
                                : k->closest(&acc->bvh, acc->tri, &ray, r->tmax, &h, &c)) != 0;
    }
    double n = set->count ? (double)set->count : 1.0;
    *nodes_per_ray = (double)c.node_tests / n;
    *tris_per_ray = (double)c.triangle_tests / n;
    *answered_percent = 100.0 * (double)answered / n;
}

void bench_accel_release_wide(struct bench_accel *acc)
{
    bvh4_release(&acc->wide);
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double bench_median(double *values, int n)
{
    qsort(values, (size_t)n, sizeof(*values), compare_double);
    if (n % 2)
        return values[n / 2];
    return 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

int bench_strategy_selected(const char *only, const char *key)
{
    size_t n = strlen(key);
    for (const char *p = only; (p = strstr(p, key)) != NULL; p += n)
        if ((p == only || p[-1] == ',') && (p[n] == ',' || p[n] == '\0'))
            return 1;
    return 0;
}

int bench_threads_selected(const struct bench_options *opts, int threads)
{
    return !opts->threads || opts->threads == threads;
}
