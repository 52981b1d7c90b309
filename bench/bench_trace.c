/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_trace.c - `rtbench trace`: rays per second, ours directly and
 * through the public API.
 *
 * Per mesh, over one object BVH built with the library's defaults (binned
 * SAH, BVH_DEFAULT_BINS bins), for primary rays (a pinhole camera), random
 * incoherent rays (origins in the bounds, directions on the sphere),
 * shadow rays (primary hit points to a point light, any hit) and the
 * random rays again with any hit:
 *
 *   ours   trace_closest / trace_any called directly in bench_run_parallel
 *          on 1 and 2 threads: the kernel's speed, no API in the way;
 *   API    rtTraceRays / rtOccludedRays on a context created with
 *          threads=1 / threads=2, the mesh defined with rtVertexPointer +
 *          rtDrawArrays in one object instantiated once under the identity.
 *          What an application gets: ray validation, the scene check, the
 *          top level, the instance transform and the library's own thread
 *          pool are all inside the time.
 *
 * The runs of the four paths are interleaved (run 1 of each, then run 2,
 * ...) so a slow phase of a shared machine hits them alike; each figure is
 * the median.  The API's answers are compared with ours ray by ray, and a
 * sample of ours with the brute-force reference intersector
 * (trace_closest_brute_force), so a fast wrong answer cannot pass as a
 * result.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/timer.h"
#include "bench.h"
#include "trace/scene_traverse.h"

/* Brute-force check: at most this many triangle tests per ray set (about
 * a second), at most BRUTE_MAX_RAYS rays. */
#define BRUTE_MAX_TESTS 64000000.0
#define BRUTE_MAX_RAYS 4096

#define PATHS 4

/* What a mesh's run leaves for the notes under the table. */
struct mesh_notes {
    float api_build_ms;    /* the API's on-demand object build */
    double brute_agree[2]; /* primary, random: ours = brute force, percent */
    uint32_t brute_sampled[2];
};

/* One context with the mesh defined as one object and instantiated once. */
struct api_scene {
    RTcontext ctx;
    RTuint object;
    int threads;
    float build_ms;
};

/* Expands the indexed mesh into 9 floats per triangle for rtDrawArrays. */
static float *flatten(const struct bench_mesh *mesh)
{
    float *flat = malloc((size_t)mesh->tri_count * 9 * sizeof(*flat));
    if (!flat)
        return NULL;
    for (size_t j = 0; j < 3 * (size_t)mesh->tri_count; j++)
        memcpy(&flat[3 * j], &mesh->positions[3 * (size_t)mesh->indices[j]], 3 * sizeof(float));
    return flat;
}

static int api_scene_create(struct api_scene *s, const struct bench_mesh *mesh, const float *flat,
                            int threads)
{
    char config[32];
    memset(s, 0, sizeof(*s));
    snprintf(config, sizeof(config), "threads=%d", threads);
    s->threads = threads;
    s->ctx = bench_create_context(config);
    if (!s->ctx || !rtMakeCurrent(s->ctx))
        return -1;
    rtGenObjects(1, &s->object);
    rtNewObject(s->object);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, flat);
    rtDrawArrays(RT_TRIANGLES, 0, (RTsizei)(3 * mesh->tri_count));
    rtDisableClientState(RT_VERTEX_ARRAY);
    rtEndObject();
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtInstantiateObject(s->object);
    /* The object BVH is built on demand when a ray first reaches the
     * instance; shoot one from the camera at the centre of the bounds so
     * that no timed call includes the build. */
    RTray warm_up;
    RThit hit;
    RTint built = RT_FALSE;
    for (int k = 0; k < 3; k++) {
        warm_up.org[k] = mesh->camera.eye[k];
        warm_up.dir[k] = 0.5f * (mesh->bounds.min[k] + mesh->bounds.max[k]) - warm_up.org[k];
    }
    warm_up.tmin = 0.0f;
    warm_up.tmax = INFINITY;
    rtTraceRays(1, &warm_up, &hit);
    rtGetObjectiv(s->object, RT_OBJECT_BUILT, &built);
    rtGetObjectfv(s->object, RT_OBJECT_BUILD_TIME, &s->build_ms);
    RTenum err = rtGetError();
    if (err != RT_NO_ERROR || built != RT_TRUE) {
        report_progress("rtbench: API setup failed (error 0x%x, object built: %d)\n", err,
                        (int)built);
        return -1;
    }
    return 0;
}

static void api_scene_destroy(struct api_scene *s)
{
    if (s->ctx) {
        rtMakeCurrent(NULL);
        rtDestroyContext(s->ctx);
    }
    memset(s, 0, sizeof(*s));
}

/* Times one API call over the whole set and converts its answers. */
static double api_run(struct api_scene *s, const struct bench_rays *set, int any_hit, void *scratch,
                      struct bench_hit *hits)
{
    rtMakeCurrent(s->ctx);
    double cpu_start = bench_cpu_ms();
    double start = rt_now_ms();
    if (any_hit)
        rtOccludedRays((RTsizei)set->count, set->rays, scratch);
    else
        rtTraceRays((RTsizei)set->count, set->rays, scratch);
    double ms = rt_now_ms() - start;
    bench_share_add(s->threads, ms, bench_cpu_ms() - cpu_start);
    /* The timed call must be pure tracing: an object or top-level build
     * inside it would be measured as API overhead. */
    RTint object_builds = -1, toplevel_builds = -1;
    rtGetIntegerv(RT_STAT_OBJECT_BUILDS, &object_builds);
    rtGetIntegerv(RT_STAT_TOPLEVEL_BUILDS, &toplevel_builds);
    if (rtGetError() != RT_NO_ERROR)
        return -1.0;
    if (object_builds != 0 || toplevel_builds != 0) {
        report_check_failed();
        report_progress("trace: WARNING: a timed API call built %d object(s) and %d top "
                        "level(s)\n",
                        (int)object_builds, (int)toplevel_builds);
    }
    for (uint32_t i = 0; i < set->count; i++) {
        if (any_hit) {
            int occluded = ((const RTboolean *)scratch)[i] != RT_FALSE;
            hits[i].t = occluded ? 0.0f : INFINITY;
            hits[i].prim = occluded ? 0 : BENCH_MISS;
        } else {
            const RThit *h = &((const RThit *)scratch)[i];
            hits[i].t = h->t;
            hits[i].prim = h->primitive == RT_INVALID_ID ? BENCH_MISS : h->primitive;
        }
    }
    return ms;
}

struct bench_hit bench_brute_force_hit(const struct bench_mesh *mesh, const RTray *r)
{
    struct trace_ray ray;
    struct trace_hit h;
    struct bench_hit ref = {INFINITY, BENCH_MISS};
    trace_ray_init(&ray, r->org, r->dir, r->tmin);
    if (trace_closest_brute_force(mesh->positions, mesh->indices, mesh->tri_count, &ray, r->tmax,
                                  &h)) {
        ref.t = h.t;
        ref.prim = h.prim;
    }
    return ref;
}

/* Our closest hits on a sample of the set against the brute-force
 * reference; returns the agreement in percent and the sample size. */
static double brute_force_check(const struct bench_mesh *mesh, const struct bench_rays *set,
                                const struct bench_hit *hits, uint32_t *sampled)
{
    double budget = BRUTE_MAX_TESTS / (mesh->tri_count ? mesh->tri_count : 1);
    uint32_t n = budget < BRUTE_MAX_RAYS ? (uint32_t)budget : BRUTE_MAX_RAYS;
    if (n < 16)
        n = 16;
    if (n > set->count)
        n = set->count;
    uint32_t stride = n ? set->count / n : 1;
    struct bench_agreement a;
    memset(&a, 0, sizeof(a));
    for (uint32_t k = 0; k < n; k++) {
        uint32_t i = k * stride;
        const struct bench_hit ref = bench_brute_force_hit(mesh, &set->rays[i]);
        bench_compare_hits(&a, &hits[i], &ref, 1, 1);
    }
    *sampled = n;
    return bench_agreement_percent(&a);
}

struct set_result {
    double mrays[PATHS];
    double hit_percent;
    struct bench_agreement api_vs_ours;
};

/* Measures the four paths on one set.  hits[0] ends up holding ours (1
 * thread).  Returns 0, -1 on failure. */
static int measure_set(const struct bench_options *opts, struct bench_accel *acc,
                       struct api_scene api[2], const struct bench_rays *set, int any_hit,
                       struct bench_hit *hits[2], void *scratch, struct set_result *res)
{
    double *times = malloc((size_t)PATHS * opts->runs * sizeof(*times));
    if (!times)
        return -1;
    bench_kernel_fn kernel = any_hit ? bench_kernel_any : bench_kernel_closest;
    memset(res, 0, sizeof(*res));
    for (int run = 0; run < opts->runs; run++) {
        for (int p = 0; p < PATHS; p++) {
            double ms;
            if (p < 2)
                ms = bench_run_parallel(kernel, acc, set, hits[0], p + 1);
            else
                ms = api_run(&api[p - 2], set, any_hit, scratch, hits[1]);
            if (ms < 0.0) {
                free(times);
                return -1;
            }
            times[p * opts->runs + run] = ms;
            if (p >= 2)
                bench_compare_hits(&res->api_vs_ours, hits[0], hits[1], set->count, 1);
        }
    }
    for (int p = 0; p < PATHS; p++) {
        double ms = bench_median(&times[p * opts->runs], opts->runs);
        res->mrays[p] = ms > 0.0 ? set->count / (ms * 1e3) : 0.0;
    }
    uint64_t hit_count = 0;
    for (uint32_t i = 0; i < set->count; i++)
        hit_count += hits[0][i].prim != BENCH_MISS;
    res->hit_percent = set->count ? 100.0 * (double)hit_count / set->count : 0.0;
    free(times);
    return 0;
}

/* What the primary rays see, as a depth image (near is bright, misses
 * black) subsampled to at most VIEW_MAX_WIDTH columns: a check that each
 * camera frames its mesh, and a picture of the workload for the docs. */
#define VIEW_MAX_WIDTH 256

static void write_view(const struct bench_mesh *mesh, const struct bench_rays *set,
                       const struct bench_hit *hits)
{
    char name[64], script[1024];
    uint32_t step = (set->width + VIEW_MAX_WIDTH - 1) / VIEW_MAX_WIDTH;
    float t_lo = INFINITY, t_hi = 0.0f;
    snprintf(name, sizeof(name), "view_%s.dat", mesh->name);
    FILE *f = report_data_file(name);
    if (!f || step == 0) {
        if (f)
            fclose(f);
        return;
    }
    for (uint32_t i = 0; i < set->count; i++) {
        if (hits[i].prim != BENCH_MISS) {
            t_lo = fminf(t_lo, hits[i].t);
            t_hi = fmaxf(t_hi, hits[i].t);
        }
    }
    float range = t_hi > t_lo ? t_hi - t_lo : 1.0f;
    for (uint32_t y = 0; y < set->height; y += step) {
        for (uint32_t x = 0; x < set->width; x += step) {
            const struct bench_hit *h = &hits[(size_t)y * set->width + x];
            double v = h->prim == BENCH_MISS ? 0.0 : 1.0 - 0.75 * (h->t - t_lo) / range;
            fprintf(f, "%s%.3f", x ? " " : "", v);
        }
        fputc('\n', f);
    }
    fclose(f);
    snprintf(script, sizeof(script),
             "set terminal pngcairo size %u,%u\n"
             "set output 'view_%s.png'\n"
             "unset key\nunset colorbox\nunset border\nunset tics\n"
             "set margins 0,0,0,0\n"
             "set palette gray\n"
             "set cbrange [0:1]\n"
             "set yrange [*:*] reverse\n"
             "set autoscale fix\n"
             "plot 'view_%s.dat' matrix with image\n",
             (set->width + step - 1) / step * 2, (set->height + step - 1) / step * 2, mesh->name,
             mesh->name);
    snprintf(name, sizeof(name), "view_%s", mesh->name);
    report_plot(name, script);
}

static int trace_mesh(const struct bench_options *opts, struct bench_mesh *mesh, FILE *plot_data,
                      struct mesh_notes *notes)
{
    struct bench_accel acc;
    struct bench_rays sets[3];
    struct api_scene api[2];
    struct bench_hit *hits[2] = {NULL, NULL};
    void *scratch = NULL;
    float *flat = NULL;
    int rc = -1;
    memset(sets, 0, sizeof(sets));
    memset(api, 0, sizeof(api));
    memset(&acc, 0, sizeof(acc));

    report_progress("trace: %s: building and generating rays\n", mesh->name);
    if (bench_accel_build(&acc, mesh, NULL) || bench_rays_trace_sets(sets, mesh, &acc, opts->quick))
        goto out;
    uint32_t max_rays = sets[0].count > sets[1].count ? sets[0].count : sets[1].count;
    hits[0] = malloc((size_t)max_rays * sizeof(struct bench_hit));
    hits[1] = malloc((size_t)max_rays * sizeof(struct bench_hit));
    scratch = malloc((size_t)max_rays * sizeof(RThit));
    flat = flatten(mesh);
    if (!hits[0] || !hits[1] || !scratch || !flat)
        goto out;
    for (int t = 0; t < 2; t++) {
        if (api_scene_create(&api[t], mesh, flat, t + 1))
            goto out;
    }
    free(flat);
    flat = NULL;
    notes->api_build_ms = api[0].build_ms;

    /* The passes: primary, random and shadow rays as the sets say, then
     * the random rays again with any hit (incoherent occlusion queries:
     * rtOccludedRays' stream path, lib/trace/scene_stream.h, and the
     * single-ray any-hit walk on rays that are not shadow rays). */
    static const int pass_set[4] = {0, 1, 2, 1};
    for (int pass = 0; pass < 4; pass++) {
        struct set_result res;
        const int s = pass_set[pass];
        const int any_hit = pass >= 2;
        const char *any_tag = any_hit && s != 2 ? " (any hit)" : "";
        report_progress("trace: %s: %s rays%s (%u)\n", mesh->name, sets[s].name, any_tag,
                        sets[s].count);
        if (sets[s].count == 0) {
            report_row("%s|%s%s|0|-|-|-|-|-|-|-|-|-", mesh->name, sets[s].name, any_tag);
            continue;
        }
        if (measure_set(opts, &acc, api, &sets[s], any_hit, hits, scratch, &res))
            goto out;
        if (s == 0)
            write_view(mesh, &sets[s], hits[0]);
        double api_agree = bench_agreement_percent(&res.api_vs_ours);
        report_row("%s|%s%s|%u|%.1f|%.3f|%.3f|%.2f|%.3f|%.3f|%.2f|%.2f|%.2f%%", mesh->name,
                   sets[s].name, any_hit ? " (any hit)" : "", sets[s].count, res.hit_percent,
                   res.mrays[0], res.mrays[1], res.mrays[0] > 0 ? res.mrays[1] / res.mrays[0] : 0.0,
                   res.mrays[2], res.mrays[3], res.mrays[0] > 0 ? res.mrays[2] / res.mrays[0] : 0.0,
                   res.mrays[1] > 0 ? res.mrays[3] / res.mrays[1] : 0.0, api_agree);
        for (int p = 0; p < PATHS; p++) {
            char key[96];
            snprintf(key, sizeof(key), "trace.%s.%s%s.%s", mesh->name, sets[s].name,
                     *any_tag ? "_any" : "",
                     p == 0   ? "ours_1t"
                     : p == 1 ? "ours_2t"
                     : p == 2 ? "api_1t"
                              : "api_2t");
            report_metric(key, res.mrays[p], 1);
        }
        if (plot_data)
            fprintf(plot_data, "\"%s/%s%s\" %.4f %.4f %.4f %.4f\n", mesh->name, sets[s].name,
                    *any_tag ? " (any)" : "", res.mrays[0], res.mrays[1], res.mrays[2],
                    res.mrays[3]);
        if (api_agree < 100.0) {
            report_check_failed();
            report_progress("trace: WARNING: %s/%s%s: the API disagrees with the direct path on "
                            "%.4f%% of rays\n",
                            mesh->name, sets[s].name, any_tag, 100.0 - api_agree);
        }
        if (!any_hit) {
            uint32_t sampled;
            /* hits[0] holds ours from the last run. */
            double agree = brute_force_check(mesh, &sets[s], hits[0], &sampled);
            notes->brute_agree[s] = agree;
            notes->brute_sampled[s] = sampled;
            char key[96];
            snprintf(key, sizeof(key), "check.%s.%s.brute_force_agree_pct", mesh->name,
                     sets[s].name);
            report_metric(key, agree, -1);
            report_progress("trace: %s/%s: ours = brute force on %.2f%% of %u sampled rays\n",
                            mesh->name, sets[s].name, agree, sampled);
            if (agree < 100.0) {
                report_check_failed();
                report_progress("trace: WARNING: %s/%s: BVH traversal differs from the "
                                "brute-force reference\n",
                                mesh->name, sets[s].name);
            }
        }
    }
    rc = 0;
out:
    if (rc)
        report_progress("rtbench: trace: %s failed (out of memory or API error)\n", mesh->name);
    for (int t = 0; t < 2; t++)
        api_scene_destroy(&api[t]);
    for (int s = 0; s < 3; s++)
        bench_rays_release(&sets[s]);
    free(hits[0]);
    free(hits[1]);
    free(scratch);
    free(flat);
    bench_accel_release(&acc);
    return rc;
}

/* ------------------------------------------------------------ wide top level */

/* Issue 11 item 2: the top level over instances binary against wide, the
 * same scene, kernels and rays in one run.  The scene: a grid of
 * instances of one mesh, scaled to overlap their neighbours, with
 * trace_scene_closest/any called directly (lib/trace/scene_traverse.h). */
struct top_bench {
    struct trace_scene scene;
    struct trace_object_view view;
};

static int top_acquire(void *user, void *object, struct trace_object_view *view)
{
    (void)object;
    *view = ((const struct top_bench *)user)->view;
    return 1;
}

static double top_run(const struct trace_scene *sc, const struct bench_rays *set, int any_hit,
                      double *checksum, struct trace_scene_counters *counters)
{
    struct trace_scene_counters c;
    memset(&c, 0, sizeof(c));
    double sum = 0.0;
    double start = rt_now_ms();
    for (uint32_t i = 0; i < set->count; i++) {
        const RTray *r = &set->rays[i];
        struct trace_scene_hit h;
        if (any_hit)
            sum += trace_scene_any(sc, r->org, r->dir, r->tmin, r->tmax, &c);
        else if (trace_scene_closest(sc, r->org, r->dir, r->tmin, r->tmax, &h, &c))
            sum += (double)h.t + (double)h.instance;
    }
    double ms = rt_now_ms() - start;
    *checksum = sum;
    *counters = c;
    return ms;
}

static void trace_toplevel_wide(const struct bench_options *opts, const struct bench_mesh *mesh)
{
    const struct trace_kernels *kernels = bench_kernels();
    const uint32_t width = kernels->wide_width;
    report_printf("\n### Wide top level over instances (binary vs %u-wide)\n\n", width);
    if (!width) {
        report_printf("The kernels (%s) walk no wide layout: nothing to compare.\n",
                      kernels->name);
        return;
    }
    struct bvh_build_params params;
    bvh_build_params_default(&params);
    struct bench_accel acc;
    memset(&acc, 0, sizeof(acc));
    const int side = opts->quick ? 16 : 32, layers = 4;
    const uint32_t n = (uint32_t)(side * side * layers);
    struct trace_instance *inst = calloc(n, sizeof(*inst));
    struct aabb *boxes = calloc(n, sizeof(*boxes));
    struct bvh top;
    struct bvh4 top_wide;
    memset(&top, 0, sizeof(top));
    memset(&top_wide, 0, sizeof(top_wide));
    struct bench_rays set;
    memset(&set, 0, sizeof(set));
    /* The object: the mesh's first triangles only, so that the top level
     * is a visible share of the work (many small instances). */
    struct bench_mesh part = *mesh;
    part.tri_count = mesh->tri_count < 256 ? mesh->tri_count : 256;
    part.bounds = aabb_empty();
    for (uint32_t i = 0; i < 3 * part.tri_count; i++) {
        const float *p = &mesh->positions[3 * (size_t)mesh->indices[i]];
        for (int k = 0; k < 3; k++) {
            part.bounds.min[k] = p[k] < part.bounds.min[k] ? p[k] : part.bounds.min[k];
            part.bounds.max[k] = p[k] > part.bounds.max[k] ? p[k] : part.bounds.max[k];
        }
    }
    mesh = &part;
    if (!inst || !boxes || bench_accel_build(&acc, mesh, &params)) {
        report_printf("allocation failed\n");
        goto done;
    }
    /* Each instance: the mesh scaled to a cell of 1 (times 1.5, so that
     * boxes overlap), at a grid point with a jitter of a quarter cell. */
    float ext = 0.0f;
    for (int k = 0; k < 3; k++) {
        float e = mesh->bounds.max[k] - mesh->bounds.min[k];
        ext = e > ext ? e : ext;
    }
    const double sc = 1.5 / (double)ext;
    struct bench_rng rng;
    bench_rng_seed(&rng, 2026);
    for (uint32_t i = 0; i < n; i++) {
        double t[3] = {(double)(i % (uint32_t)side), (double)(i / (uint32_t)side % (uint32_t)side),
                       (double)(i / (uint32_t)(side * side))};
        for (int k = 0; k < 3; k++)
            t[k] += 0.25 * (double)bench_rng_float(&rng);
        /* world = sc * (p - min) + t; object = (world - t) / sc + min. */
        for (int k = 0; k < 3; k++) {
            inst[i].world_to_object[4 * k + k] = 1.0 / sc;
            inst[i].world_to_object[4 * k + 3] = (double)mesh->bounds.min[k] - t[k] / sc;
            double lo = t[k], hi = t[k] + sc * (double)(mesh->bounds.max[k] - mesh->bounds.min[k]);
            boxes[i].min[k] = nextafterf((float)lo, -INFINITY);
            boxes[i].max[k] = nextafterf((float)hi, INFINITY);
        }
        inst[i].instance_id = i;
    }
    if (accel_build(&top, boxes, n, &params) ||
        accel_collapse_wide(&top_wide, &top, NULL, width)) {
        report_printf("allocation failed\n");
        goto done;
    }
    /* Random rays over the grid's box (the bench's random set over a
     * mesh with these bounds). */
    struct bench_mesh grid = part;
    grid.bounds = top.node_count ? (struct aabb){{top.nodes[0].aabb_min[0], top.nodes[0].aabb_min[1],
                                                 top.nodes[0].aabb_min[2]},
                                                {top.nodes[0].aabb_max[0], top.nodes[0].aabb_max[1],
                                                 top.nodes[0].aabb_max[2]}}
                                 : mesh->bounds;
    if (bench_rays_random(&set, &grid, opts->quick ? 20000u : 200000u, 7)) {
        report_printf("allocation failed\n");
        goto done;
    }
    struct top_bench tb;
    memset(&tb, 0, sizeof(tb));
    tb.view.bvh = &acc.bvh;
    tb.view.tri = acc.tri;
    tb.view.wide = &acc.wide;
    tb.scene.top = &top;
    tb.scene.instances = inst;
    tb.scene.acquire = top_acquire;
    tb.scene.user = &tb;
    tb.scene.kernels = kernels;
    report_printf("%u instances of the first %u triangles of %s on a %dx%dx%d grid, boxes "
                  "overlapping; %u random rays; one thread; kernels %s (object walk %u-wide in "
                  "both columns); binary top level (2-wide walk) and the same tree collapsed to "
                  "%u-wide (%u nodes vs %u), run alternately, median of %d. Mrays/s.\n\n",
                  n, mesh->tri_count, mesh->name, side, side, layers, set.count, kernels->name,
                  acc.wide.width, width, top_wide.node_count, top.node_count, opts->runs);
    report_table_header("rays|binary top|wide top|wide/binary|same answers|top node tests/ray "
                        "binary / wide|instances/ray binary / wide|CPU share|load");
    for (int any_hit = 0; any_hit < 2; any_hit++) {
        double t_bin[16], t_wide[16];
        double sum_bin = 0.0, sum_wide = 0.0;
        struct trace_scene_counters c_bin, c_wide;
        int runs = opts->runs < 16 ? opts->runs : 16;
        double wall = 0.0, cpu0 = bench_cpu_ms();
        for (int r = 0; r < runs; r++) {
            tb.scene.top_wide = NULL;
            t_bin[r] = top_run(&tb.scene, &set, any_hit, &sum_bin, &c_bin);
            tb.scene.top_wide = &top_wide;
            t_wide[r] = top_run(&tb.scene, &set, any_hit, &sum_wide, &c_wide);
            wall += t_bin[r] + t_wide[r];
        }
        double cpu = bench_cpu_ms() - cpu0;
        double mb = (double)set.count / (bench_median(t_bin, runs) * 1e3);
        double mw = (double)set.count / (bench_median(t_wide, runs) * 1e3);
        const double rays = (double)set.count;
        report_row("%s|%.2f|%.2f|%.2f|%s|%.1f / %.1f|%.2f / %.2f|%.0f%%|%s",
                   any_hit ? "random, any hit" : "random, closest", mb, mw, mw / mb,
                   sum_bin == sum_wide ? "yes" : "NO", (double)c_bin.top_node_tests / rays,
                   (double)c_wide.top_node_tests / rays, (double)c_bin.instance_tests / rays,
                   (double)c_wide.instance_tests / rays,
                   wall > 0.0 ? 100.0 * cpu / wall : 0.0, sysinfo_loadavg());
        if (sum_bin != sum_wide)
            report_check_failed();
    }
done:
    bench_rays_release(&set);
    bvh4_release(&top_wide);
    bvh_release(&top);
    bench_accel_release(&acc);
    free(inst);
    free(boxes);
}

int bench_trace_section(const struct bench_options *opts, struct bench_mesh *meshes, int mesh_count)
{
    report_printf("\n## Trace: rays per second\n\n");
    report_printf("Object BVH: binned SAH, %d bins (the library default). Primary rays: "
                  "%ux%u pinhole camera; random: %u rays, origins uniform in the bounds, "
                  "directions uniform on the sphere; shadow: from each primary hit to a point "
                  "light, any hit; random (any hit): the random rays again, any hit. Median "
                  "of %d runs. \"ours\": trace_closest/trace_any called "
                  "directly (own pthread split, chunks of %d rays); \"API\": "
                  "rtTraceRays/rtOccludedRays on a context with threads=1/2. Mrays/s. "
                  "\"API = ours\": rays where the API's answer equals ours.\n\n",
                  BVH_DEFAULT_BINS, opts->quick ? BENCH_PRIMARY_WIDTH_QUICK : BENCH_PRIMARY_WIDTH,
                  opts->quick ? BENCH_PRIMARY_HEIGHT_QUICK : BENCH_PRIMARY_HEIGHT,
                  opts->quick ? BENCH_RANDOM_RAYS_QUICK : BENCH_RANDOM_RAYS, opts->runs,
                  BENCH_CHUNK);
    report_table_header("mesh|rays|count|hit %|ours 1T|ours 2T|2T/1T|API 1T|API 2T|API/ours 1T|"
                        "API/ours 2T|API = ours");
    FILE *plot_data = report_data_file("trace.dat");
    bench_share_reset();
    struct mesh_notes *notes = calloc((size_t)mesh_count + 1, sizeof(*notes));
    if (!notes) {
        if (plot_data)
            fclose(plot_data);
        return -1;
    }
    int failed = 0;
    for (int m = 0; m < mesh_count; m++)
        failed |= trace_mesh(opts, &meshes[m], plot_data, &notes[m]) != 0;
    bench_share_report();
    if (mesh_count > 0)
        trace_toplevel_wide(opts, &meshes[0]);
    report_printf("\nCorrectness: ours (binned SAH BVH) against the brute-force reference "
                  "intersector on a sample of rays (hit/miss and t within %g relative):\n\n",
                  (double)BENCH_T_TOLERANCE);
    report_table_header("mesh|rays|sampled|ours = brute force|API object build ms (on demand)");
    for (int m = 0; m < mesh_count; m++) {
        for (int s = 0; s < 2; s++)
            report_row("%s|%s|%u|%.2f%%|%.1f", meshes[m].name, s ? "random" : "primary",
                       notes[m].brute_sampled[s], notes[m].brute_agree[s],
                       (double)notes[m].api_build_ms);
    }
    free(notes);
    if (plot_data) {
        fclose(plot_data);
        report_plot("trace", "set terminal pngcairo size 1000,520 font ',10'\n"
                             "set output 'trace.png'\n"
                             "set title 'Trace throughput (median), Mrays/s'\n"
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
                             "plot 'trace.dat' using 2:xtic(1) title 'ours 1T', '' using 3 title "
                             "'ours 2T', '' using 4 title 'API 1T', '' using 5 title 'API 2T'\n");
    }
    return failed ? -1 : 0;
}
