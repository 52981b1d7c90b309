/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_packets.c - `rtbench packets`: the packet walks (lib/trace/packet.h)
 * against the single-ray walk of the same ISA table and layout, on the
 * trace section's ray sets, and against Embree's packets where rtbench
 * has Embree.
 *
 * "single": the table's closest4/any4 per ray (what `rtbench trace`
 * times); "packets": closest_packet/any_packet over groups of eight
 * consecutive rays (a row of eight pixels for primary rays; the shadow
 * rays of consecutive primary hits, sharing the point light), the hybrid
 * threshold at TRACE_PACKET_HYBRID, each group's rays taken from their
 * arrays by the table's closest_packet_arrays/any_packet_arrays (the
 * set-up and the walk in one call), or set up by its packet_init as
 * the library's packet path does and then walked.  Embree: rtcIntersect1/rtcOccluded1
 * and rtcIntersect8/rtcOccluded8 (coherent flag) over the same groups, a
 * MEDIUM scene.  Runs are interleaved (single, packets, Embree 1, Embree
 * 8, for each thread count) and each figure is the median; the packets'
 * answers must equal the single walk's bit for bit (t and primitive).
 *
 * The third table is the same through the API: rtTraceRays on the
 * primary rays, rtOccludedRays on the shadow rays and whole frames
 * (rtRenderFrame, eye light: camera rays only; Whitted: plus a shadow ray
 * per hit to a point light, traced one at a time from inside shading) of
 * the mesh from its camera, and a Whitted frame of the mesh cut in two by
 * a clip plane (its shadow rays through the hit filter), on contexts with
 * packets=on and packets=off (the answers and images must be equal,
 * memcmp).
 *
 * The second table is the hybrid threshold: packets of the same rays
 * with every threshold from 0 (packets to the leaves) to 9 (each ray
 * alone from the root: the packet set-up's overhead over single rays),
 * one thread.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <rt/rtu.h>

#include "base/timer.h"
#include "bench.h"

struct packet_ctx {
    const struct bench_accel *acc;
    unsigned hybrid;
};

/* A group's rays in the arrays a packet entry takes (org, dir, tmin,
 * t_max: the caller's layout, as packet_scene.c holds a packet). */
struct packet_group {
    float org[TRACE_PACKET][3], dir[TRACE_PACKET][3], tmin[TRACE_PACKET], t_max[TRACE_PACKET];
};

static void group_load(const RTray *rays, uint32_t g, uint32_t n, struct packet_group *q)
{
    for (uint32_t j = 0; j < n; j++) {
        const RTray *r = &rays[g + j];
        memcpy(q->org[j], r->org, sizeof(q->org[j]));
        memcpy(q->dir[j], r->dir, sizeof(q->dir[j]));
        q->tmin[j] = r->tmin;
        q->t_max[j] = r->tmax;
    }
}

/* The rays of a group set up for closest_packet/any_packet: by the
 * table's packet_init (packet_scene.c's set-up, the same bits as
 * trace_ray_init's), or ray by ray in a table without it. */
static void set_up(const struct trace_kernels *k, const struct packet_group *q, uint32_t n,
                   struct trace_ray *ray)
{
    if (k->packet_init) {
        struct trace_top_rays top;
        /* No masks: only the two-level walk's identity instances use them. */
        k->packet_init((const float(*)[3])q->org, (const float(*)[3])q->dir, q->tmin,
                       (1u << n) - 1u, ray, &top, NULL);
        return;
    }
    for (uint32_t j = 0; j < n; j++)
        trace_ray_init(&ray[j], q->org[j], q->dir[j], q->tmin[j]);
}

/* The groups' packets: the table's entries from the arrays where it has
 * them (the set-up and the walk in one call), else set_up and the walk. */
static void kernel_closest_packets(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                                   struct bench_hit *hits)
{
    const struct packet_ctx *pc = ctx;
    const struct bench_accel *acc = pc->acc;
    const struct trace_kernels *k = bench_kernels();
    for (uint32_t g = begin; g < end; g += TRACE_PACKET) {
        const uint32_t n = end - g < TRACE_PACKET ? end - g : TRACE_PACKET;
        struct packet_group q;
        struct trace_hit h[TRACE_PACKET];
        unsigned found;
        group_load(rays, g, n, &q);
        if (k->closest_packet_arrays) {
            found = k->closest_packet_arrays(&acc->wide, &acc->bvh, acc->tri,
                                             (const float(*)[3])q.org, (const float(*)[3])q.dir,
                                             q.tmin, q.t_max, (1u << n) - 1u, pc->hybrid, h,
                                             NULL);
        } else {
            struct trace_ray ray[TRACE_PACKET];
            set_up(k, &q, n, ray);
            found = k->closest_packet(&acc->wide, &acc->bvh, acc->tri, ray, q.t_max,
                                      (1u << n) - 1u, pc->hybrid, h, NULL);
        }
        for (uint32_t j = 0; j < n; j++) {
            hits[g + j].t = found >> j & 1u ? h[j].t : INFINITY;
            hits[g + j].prim = found >> j & 1u ? h[j].prim : BENCH_MISS;
        }
    }
}

static void kernel_any_packets(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                               struct bench_hit *hits)
{
    const struct packet_ctx *pc = ctx;
    const struct bench_accel *acc = pc->acc;
    const struct trace_kernels *k = bench_kernels();
    for (uint32_t g = begin; g < end; g += TRACE_PACKET) {
        const uint32_t n = end - g < TRACE_PACKET ? end - g : TRACE_PACKET;
        struct packet_group q;
        unsigned occ;
        group_load(rays, g, n, &q);
        if (k->any_packet_arrays) {
            occ = k->any_packet_arrays(&acc->wide, &acc->bvh, acc->tri, (const float(*)[3])q.org,
                                       (const float(*)[3])q.dir, q.tmin, q.t_max,
                                       (1u << n) - 1u, pc->hybrid, NULL);
        } else {
            struct trace_ray ray[TRACE_PACKET];
            set_up(k, &q, n, ray);
            occ = k->any_packet(&acc->wide, &acc->bvh, acc->tri, ray, q.t_max, (1u << n) - 1u,
                                pc->hybrid, NULL);
        }
        for (uint32_t j = 0; j < n; j++) {
            hits[g + j].t = occ >> j & 1u ? 0.0f : INFINITY;
            hits[g + j].prim = occ >> j & 1u ? 0 : BENCH_MISS;
        }
    }
}

/* One run of kernel over set on `threads` threads: its process CPU time
 * in ms (or -1 on failure).  CPU time rather than wall time: this
 * machine is shared, and a run that waits for a core it does not get
 * counts only the work it did (the report gives the CPU share of the
 * wall time beside it). */
static double cpu_run(bench_kernel_fn kernel, void *ctx, const struct bench_rays *set,
                      struct bench_hit *hits, int threads)
{
    const double cpu = bench_cpu_ms();
    const double wall = bench_run_parallel(kernel, ctx, set, hits, threads);
    return wall < 0.0 ? -1.0 : bench_cpu_ms() - cpu;
}

/* Rays whose answers differ bit for bit (t and primitive). */
static uint32_t differ(const struct bench_hit *a, const struct bench_hit *b, uint32_t n)
{
    uint32_t d = 0;
    for (uint32_t i = 0; i < n; i++)
        d += memcmp(&a[i].t, &b[i].t, sizeof(float)) != 0 || a[i].prim != b[i].prim;
    return d;
}

#define PATHS 4 /* single, packets, Embree 1, Embree 8 */
static const unsigned hybrids[] = {0, 2, 3, 4, 6, 9};
#define HYBRIDS (sizeof(hybrids) / sizeof(hybrids[0]))

/* --only KEYS: the packets section's parts to run, by key: the first
 * table's ray sets (primary, shadow, random), the hybrid threshold table
 * (hybrid) and the API table (api); all without --only.  With --threads
 * 1 or 2 the first and the API tables run that thread count only.  A
 * comparison of two binaries or tables then takes seconds, not a minute,
 * and can be repeated A B B A (docs/performance-log.md, round 62, zr2). */
static int packets_selected(const struct bench_options *opts, const char *key)
{
    return !opts->only || bench_strategy_selected(opts->only, key);
}

static int packets_mesh(const struct bench_options *opts, const struct bench_mesh *mesh)
{
    struct bench_accel acc;
    struct bench_rays sets[3];
    struct bench_hit *single = NULL, *packed = NULL, *theirs = NULL;
    double *times = NULL;
#ifdef RT_HAVE_EMBREE
    void *embree = NULL;
#endif
    int rc = -1;
    memset(sets, 0, sizeof(sets));
    memset(&acc, 0, sizeof(acc));
    if (bench_accel_build(&acc, mesh, NULL) || bench_rays_trace_sets(sets, mesh, &acc, opts->quick))
        goto out;
#ifdef RT_HAVE_EMBREE
    embree = bench_embree_packets_new(mesh);
#endif
    uint32_t max_rays = 0;
    for (int s = 0; s < 3; s++)
        max_rays = sets[s].count > max_rays ? sets[s].count : max_rays;
    single = malloc((size_t)max_rays * sizeof(*single));
    packed = malloc((size_t)max_rays * sizeof(*packed));
    theirs = malloc((size_t)max_rays * sizeof(*theirs));
    times = malloc((size_t)2 * PATHS * opts->runs * sizeof(*times));
    if (!single || !packed || !theirs || !times)
        goto out;
    /* Primary, shadow, random (the incoherent control). */
    static const int order[3] = {0, 2, 1};
    for (int o = 0; o < 3; o++) {
        const struct bench_rays *set = &sets[order[o]];
        const int any_hit = order[o] == 2;
        if (set->count == 0 || !packets_selected(opts, set->name))
            continue;
        report_progress("packets: %s: %s rays (%u)\n", mesh->name, set->name, set->count);
        struct packet_ctx pc = {&acc, TRACE_PACKET_HYBRID};
        uint32_t wrong = 0;
        for (int run = 0; run < opts->runs; run++) {
            for (int t = 0; t < 2; t++) {
                if (!bench_threads_selected(opts, t + 1))
                    continue;
                for (int p = 0; p < PATHS; p++) {
                    double ms = 0.0;
                    if (p == 0)
                        ms = cpu_run(any_hit ? bench_kernel_any : bench_kernel_closest,
                                                &acc, set, single, t + 1);
                    else if (p == 1)
                        ms = cpu_run(any_hit ? kernel_any_packets
                                                        : kernel_closest_packets,
                                                &pc, set, packed, t + 1);
#ifdef RT_HAVE_EMBREE
                    else if (embree && p == 2)
                        ms = cpu_run(any_hit ? bench_embree_kernel_any1
                                                        : bench_embree_kernel_closest1,
                                                embree, set, theirs, t + 1);
                    else if (embree && p == 3)
                        ms = cpu_run(any_hit ? bench_embree_kernel_any8
                                                        : bench_embree_kernel_closest8,
                                                embree, set, theirs, t + 1);
#endif
                    if (ms < 0.0)
                        goto out;
                    times[(t * PATHS + p) * opts->runs + run] = ms;
                }
                if (run == 0 && t == (opts->threads == 2))
                    wrong = differ(single, packed, set->count);
            }
        }
        double m[2][PATHS];
        memset(m, 0, sizeof(m));
        for (int t = 0; t < 2; t++) {
            if (!bench_threads_selected(opts, t + 1))
                continue;
            for (int p = 0; p < PATHS; p++) {
                double ms = bench_median(&times[(t * PATHS + p) * opts->runs], opts->runs);
                m[t][p] = ms > 0.0 ? set->count / (ms * 1e3) : 0.0;
            }
        }
        for (int t = 0; t < 2; t++) {
            if (!bench_threads_selected(opts, t + 1))
                continue;
            report_row("%s|%s%s|%d|%.3f|%.3f|%.2f|%.3f|%.3f|%.2f|%.2f|%.2f|%u", mesh->name,
                       set->name, any_hit ? " (any hit)" : "", t + 1, m[t][0], m[t][1],
                       m[t][0] > 0 ? m[t][1] / m[t][0] : 0.0, m[t][2], m[t][3],
                       m[t][2] > 0 ? m[t][0] / m[t][2] : 0.0,
                       m[t][3] > 0 ? m[t][1] / m[t][3] : 0.0,
                       m[t][2] > 0 ? m[t][3] / m[t][2] : 0.0, wrong);
            char key[96];
            snprintf(key, sizeof(key), "packets.%s.%s.%dt.packets_over_single", mesh->name,
                     set->name, t + 1);
            report_metric(key, m[t][0] > 0 ? m[t][1] / m[t][0] : 0.0, 1);
        }
        if (wrong) {
            report_check_failed();
            report_progress("packets: WARNING: %s/%s: %u rays differ between packets and "
                            "single rays\n",
                            mesh->name, set->name, wrong);
        }
    }
    rc = 0;
out:
    if (rc)
        report_progress("rtbench: packets: %s failed\n", mesh->name);
#ifdef RT_HAVE_EMBREE
    bench_embree_packets_release(embree);
#endif
    for (int s = 0; s < 3; s++)
        bench_rays_release(&sets[s]);
    free(single);
    free(packed);
    free(theirs);
    free(times);
    bench_accel_release(&acc);
    return rc;
}

/* The hybrid threshold table: one thread, the coherent sets. */
static int hybrid_mesh(const struct bench_options *opts, const struct bench_mesh *mesh)
{
    struct bench_accel acc;
    struct bench_rays sets[3];
    struct bench_hit *hits = NULL;
    double *times = NULL;
    int rc = -1;
    memset(sets, 0, sizeof(sets));
    memset(&acc, 0, sizeof(acc));
    if (bench_accel_build(&acc, mesh, NULL) || bench_rays_trace_sets(sets, mesh, &acc, opts->quick))
        goto out;
    uint32_t max_rays = sets[0].count > sets[2].count ? sets[0].count : sets[2].count;
    hits = malloc((size_t)max_rays * sizeof(*hits));
    times = malloc((HYBRIDS + 1) * (size_t)opts->runs * sizeof(*times));
    if (!hits || !times)
        goto out;
    for (int s = 0; s < 3; s += 2) {
        const struct bench_rays *set = &sets[s];
        const int any_hit = s == 2;
        if (set->count == 0)
            continue;
        for (int run = 0; run < opts->runs; run++) {
            for (size_t h = 0; h <= HYBRIDS; h++) {
                struct packet_ctx pc = {&acc, h < HYBRIDS ? hybrids[h] : 0};
                double ms;
                if (h == HYBRIDS)
                    ms = cpu_run(any_hit ? bench_kernel_any : bench_kernel_closest,
                                            &acc, set, hits, 1);
                else
                    ms = cpu_run(any_hit ? kernel_any_packets
                                                    : kernel_closest_packets,
                                            &pc, set, hits, 1);
                if (ms < 0.0)
                    goto out;
                times[h * (size_t)opts->runs + (size_t)run] = ms;
            }
        }
        double m[HYBRIDS + 1];
        for (size_t h = 0; h <= HYBRIDS; h++) {
            double ms = bench_median(&times[h * (size_t)opts->runs], opts->runs);
            m[h] = ms > 0.0 ? set->count / (ms * 1e3) : 0.0;
        }
        report_row("%s|%s%s|%.3f|%.3f|%.3f|%.3f|%.3f|%.3f|%.3f", mesh->name, set->name,
                   any_hit ? " (any hit)" : "", m[HYBRIDS], m[0], m[1], m[2], m[3], m[4], m[5]);
    }
    rc = 0;
out:
    for (int s = 0; s < 3; s++)
        bench_rays_release(&sets[s]);
    free(hits);
    free(times);
    bench_accel_release(&acc);
    return rc;
}

static void api_frame(const struct bench_mesh *mesh, const float *flat, RTuint object,
                      int clipped);

/* The API table: a context over the mesh, one instance (name 1), its
 * camera. */
static RTcontext api_context(const struct bench_mesh *mesh, const float *flat, int threads,
                             int packets)
{
    char config[64];
    snprintf(config, sizeof(config), "threads=%d packets=%s", threads, packets ? "on" : "off");
    RTcontext ctx = bench_create_context(config);
    if (!ctx || !rtMakeCurrent(ctx))
        return NULL;
    const RTuint object = 1;
    rtNewObject(object);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, flat);
    rtDrawArrays(RT_TRIANGLES, 0, (RTsizei)(3 * mesh->tri_count));
    rtDisableClientState(RT_VERTEX_ARRAY);
    rtEndObject();
    const struct bench_camera *c = &mesh->camera;
    const double w = BENCH_PRIMARY_WIDTH, h = BENCH_PRIMARY_HEIGHT;
    rtViewport(0, 0, (RTsizei)w, (RTsizei)h);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtuPerspective(2.0 * atan(c->tan_x * h / w) * (180.0 / 3.14159265358979323846), w / h, 0.01, 1e4);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtuLookAt(c->eye[0], c->eye[1], c->eye[2], c->eye[0] + c->forward[0],
              c->eye[1] + c->forward[1], c->eye[2] + c->forward[2], c->up[0], c->up[1], c->up[2]);
    const float light[4] = {mesh->light[0], mesh->light[1], mesh->light[2], 1.0f};
    rtLightfv(RT_LIGHT0, RT_POSITION, light); /* through the modelview, as GL */
    rtEnable(RT_LIGHT0);
    rtLoadIdentity();
    api_frame(mesh, flat, object, 0);
    return ctx;
}

/* The frame of api_context's instance `object`; with `clipped`, drawn
 * under a clip plane x <= the middle of the mesh's box (mesh space),
 * which cuts it in two: Whitted's shadow rays then go through the hit
 * filter (render/secondary.h). */
static void api_frame(const struct bench_mesh *mesh, const float *flat, RTuint object,
                      int clipped)
{
    const struct bench_camera *c = &mesh->camera;
    rtLoadIdentity();
    rtBeginFrame();
    rtuLookAt(c->eye[0], c->eye[1], c->eye[2], c->eye[0] + c->forward[0],
              c->eye[1] + c->forward[1], c->eye[2] + c->forward[2], c->up[0], c->up[1], c->up[2]);
    if (clipped) {
        float lo = INFINITY, hi = -INFINITY;
        for (size_t j = 0; j < 3 * (size_t)mesh->tri_count; j++) {
            lo = flat[3 * j] < lo ? flat[3 * j] : lo;
            hi = flat[3 * j] > hi ? flat[3 * j] : hi;
        }
        const double plane[4] = {-1.0, 0.0, 0.0, 0.5 * ((double)lo + (double)hi)};
        rtClipPlane(RT_CLIP_PLANE0, plane);
        rtEnable(RT_CLIP_PLANE0);
    }
    rtInstantiateObject(object);
    rtDisable(RT_CLIP_PLANE0);
    rtLoadIdentity();
}

/* rtTraceRays, rtOccludedRays, eye-light frame, Whitted frame, Whitted
 * frame with the mesh cut in two by a clip plane (api_frame) */
#define API_WORK 5

/* The rays of set in the camera's eye space (rtuLookAt's matrix, in
 * double): api_context puts the mesh there, as a GL program draws under
 * its viewing transform, and queries take eye-space rays. */
static RTray *eye_rays(const struct bench_mesh *mesh, const struct bench_rays *set)
{
    const struct bench_camera *c = &mesh->camera;
    double f[3], s[3], u[3], len = 0.0, sl = 0.0;
    for (int k = 0; k < 3; k++)
        len += (double)c->forward[k] * c->forward[k];
    for (int k = 0; k < 3; k++)
        f[k] = c->forward[k] / sqrt(len);
    s[0] = f[1] * c->up[2] - f[2] * c->up[1];
    s[1] = f[2] * c->up[0] - f[0] * c->up[2];
    s[2] = f[0] * c->up[1] - f[1] * c->up[0];
    for (int k = 0; k < 3; k++)
        sl += s[k] * s[k];
    for (int k = 0; k < 3; k++)
        s[k] /= sqrt(sl);
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    const double *rows[3] = {s, u, f};
    const double sign[3] = {1.0, 1.0, -1.0};
    RTray *out = malloc((size_t)set->count * sizeof(*out));
    if (!out)
        return NULL;
    for (uint32_t i = 0; i < set->count; i++) {
        const RTray *r = &set->rays[i];
        out[i] = *r;
        for (int a = 0; a < 3; a++) {
            double o = 0.0, d = 0.0;
            for (int k = 0; k < 3; k++) {
                o += rows[a][k] * ((double)r->org[k] - c->eye[k]);
                d += rows[a][k] * r->dir[k];
            }
            out[i].org[a] = (float)(sign[a] * o);
            out[i].dir[a] = (float)(sign[a] * d);
        }
    }
    return out;
}

static int api_mesh(const struct bench_options *opts, const struct bench_mesh *mesh)
{
    struct bench_accel acc;
    struct bench_rays sets[3];
    float *flat = NULL;
    RThit *hits[2] = {NULL, NULL};
    RTboolean *occ[2] = {NULL, NULL};
    float *image[2] = {NULL, NULL};
    RTray *eye[2] = {NULL, NULL};
    double *times = NULL;
    int rc = -1;
    const size_t pixels = (size_t)BENCH_PRIMARY_WIDTH * BENCH_PRIMARY_HEIGHT;
    memset(sets, 0, sizeof(sets));
    memset(&acc, 0, sizeof(acc));
    if (opts->quick)
        return 0; /* whole frames: not a smoke test */
    if (bench_accel_build(&acc, mesh, NULL) || bench_rays_trace_sets(sets, mesh, &acc, 0))
        goto out;
    flat = malloc((size_t)mesh->tri_count * 9 * sizeof(*flat));
    times = malloc((size_t)2 * 2 * API_WORK * opts->runs * sizeof(*times));
    for (int p = 0; p < 2; p++) {
        hits[p] = malloc((size_t)sets[0].count * sizeof(RThit));
        occ[p] = malloc((size_t)sets[2].count * sizeof(RTboolean) + 1);
        image[p] = malloc(pixels * 4 * sizeof(float));
        if (!hits[p] || !occ[p] || !image[p])
            goto out;
    }
    eye[0] = eye_rays(mesh, &sets[0]);
    eye[1] = eye_rays(mesh, &sets[2]);
    if (!flat || !times || !eye[0] || !eye[1])
        goto out;
    for (size_t j = 0; j < 3 * (size_t)mesh->tri_count; j++)
        memcpy(&flat[3 * j], &mesh->positions[3 * (size_t)mesh->indices[j]], 3 * sizeof(float));
    int same = 1;
    for (int t = 0; t < 2; t++) {
        if (!bench_threads_selected(opts, t + 1))
            continue;
        RTcontext ctx[2];
        for (int p = 0; p < 2; p++) {
            ctx[p] = api_context(mesh, flat, t + 1, p);
            if (!ctx[p])
                goto out;
            /* Build the object outside the timed calls. */
            rtShadingMode(RT_EYE_LIGHT);
            rtRenderFrame();
        }
        for (int run = 0; run < opts->runs; run++)
            for (int w = 0; w < API_WORK; w++)
                for (int p = 0; p < 2; p++) {
                    rtMakeCurrent(ctx[p]);
                    /* The clipped frame for its row only, recorded
                     * outside the timed call (its first frame builds the
                     * small top level of one instance). */
                    if (w == 4 || (w == 0 && run > 0)) {
                        api_frame(mesh, flat, 1, w == 4);
                        rtShadingMode(RT_EYE_LIGHT);
                        rtRenderFrame();
                    }
                    double cpu = bench_cpu_ms();
                    double start = rt_now_ms();
                    if (w == 0)
                        rtTraceRays((RTsizei)sets[0].count, eye[0], hits[p]);
                    else if (w == 1)
                        rtOccludedRays((RTsizei)sets[2].count, eye[1], occ[p]);
                    else {
                        rtShadingMode(w == 2 ? RT_EYE_LIGHT : RT_WHITTED);
                        rtRenderFrame();
                    }
                    double ms = rt_now_ms() - start;
                    bench_share_add(t + 1, ms, bench_cpu_ms() - cpu);
                    times[((t * API_WORK + w) * 2 + p) * opts->runs + run] =
                        bench_cpu_ms() - cpu;
                    if (w >= 2 && run == 0)
                        rtReadPixels(0, 0, BENCH_PRIMARY_WIDTH, BENCH_PRIMARY_HEIGHT, RT_RGBA,
                                     RT_FLOAT, image[p]);
                    if (rtGetError() != RT_NO_ERROR)
                        same = 0;
                    if (run == 0 && p == 1) {
                        if (w == 0)
                            same &= memcmp(hits[0], hits[1],
                                           sets[0].count * sizeof(RThit)) == 0;
                        else if (w == 1)
                            same &= memcmp(occ[0], occ[1],
                                           sets[2].count * sizeof(RTboolean)) == 0;
                        else
                            same &= memcmp(image[0], image[1], pixels * 4 * sizeof(float)) == 0;
                    }
                }
        for (int p = 0; p < 2; p++) {
            rtMakeCurrent(NULL);
            rtDestroyContext(ctx[p]);
        }
    }
    uint32_t hit_count = 0;
    for (uint32_t i = 0; i < sets[0].count; i++)
        hit_count += hits[0][i].t < INFINITY;
    report_progress("packets: %s: API primary rays hitting: %u of %u\n", mesh->name, hit_count,
                    sets[0].count);
    static const char *const work[API_WORK] = {"rtTraceRays primary", "rtOccludedRays shadow",
                                               "frame, eye light", "frame, Whitted",
                                               "frame, Whitted, clip plane"};
    for (int w = 0; w < API_WORK; w++)
        for (int t = 0; t < 2; t++) {
            if (!bench_threads_selected(opts, t + 1))
                continue;
            double ms[2];
            for (int p = 0; p < 2; p++)
                ms[p] = bench_median(&times[((t * API_WORK + w) * 2 + p) * opts->runs],
                                     opts->runs);
            report_row("%s|%s|%d|%.1f|%.1f|%.2f|%s", mesh->name, work[w], t + 1, ms[0], ms[1],
                       ms[1] > 0 ? ms[0] / ms[1] : 0.0, same ? "yes" : "NO");
        }
    if (!same) {
        report_check_failed();
        report_progress("packets: WARNING: %s: packets=on and off answer differently\n",
                        mesh->name);
    }
    rc = 0;
out:
    for (int s = 0; s < 3; s++)
        bench_rays_release(&sets[s]);
    for (int p = 0; p < 2; p++) {
        free(hits[p]);
        free(occ[p]);
        free(image[p]);
        free(eye[p]);
    }
    free(flat);
    free(times);
    bench_accel_release(&acc);
    return rc;
}

int bench_packets_section(const struct bench_options *opts, struct bench_mesh *meshes,
                          int mesh_count)
{
    const struct trace_kernels *k = bench_kernels();
    report_printf("\n## Packets\n\n");
    if (mesh_count == 0) {
        /* --mesh kitchen without the BART data (see bench_embree.c). */
        report_printf("The BART kitchen is skipped: %s.\n",
                      opts->kitchen_skipped ? opts->kitchen_skipped : "no mesh selected");
        return 0;
    }
    if (!k->closest_packet || bench_layout_width() == 0) {
        report_printf("The kernels (%s) or the layout have no packet walk: nothing to "
                      "compare.\n",
                      k->name);
        return 0;
    }
    report_printf("Mrays per CPU second (process CPU time of each run, median of %d runs: "
                  "the machine is shared; 1 thread: Mrays/s at 100%% CPU share), kernels %s, "
                  "%u-wide layout. \"single\": the "
                  "table's wide walk per ray; \"packets\": its packet walk over groups of %d "
                  "consecutive rays (a row of pixels; the shadow rays of consecutive primary "
                  "hits), hybrid threshold %d. Embree (MEDIUM): rtcIntersect1/rtcOccluded1 "
                  "(\"E1\") and rtcIntersect8/rtcOccluded8 over the same groups (\"E8\"). "
                  "Runs interleaved. \"differ\": rays whose packet answer is not the single "
                  "walk's bit for bit (must be 0).\n\n",
                  opts->runs, k->name, bench_layout_width(), TRACE_PACKET, TRACE_PACKET_HYBRID);
    report_table_header("mesh|rays|threads|single|packets|packets/single|E1|E8|single/E1|"
                        "packets/E8|E8/E1|differ");
    bench_share_reset();
    int failed = 0;
    for (int m = 0; m < mesh_count; m++)
        failed |= packets_mesh(opts, &meshes[m]) != 0;
    bench_share_report();
    if (opts->kitchen_skipped)
        report_printf("\nThe BART kitchen (the fourth mesh) is skipped: %s.\n",
                      opts->kitchen_skipped);
    if (!packets_selected(opts, "hybrid"))
        return failed ? -1 : 0;
    report_printf("\nHybrid threshold (packet.h): Mrays per CPU second, one thread, median "
                  "of %d runs; "
                  "packets continue ray by ray below the threshold's number of active rays (0: "
                  "never, 9: always, from the root).\n\n",
                  opts->runs);
    report_table_header("mesh|rays|single|0|2|3|4|6|9");
    for (int m = 0; m < mesh_count; m++)
        failed |= hybrid_mesh(opts, &meshes[m]) != 0;
    if (!opts->quick && packets_selected(opts, "api")) {
        report_printf("\nThrough the API, %dx%d: CPU ms per call (process CPU time, all "
                      "threads; median of %d runs, on and off "
                      "interleaved), contexts \"threads=N packets=off|on\" with their default "
                      "ISA; \"same\": answers and images of on and off equal (memcmp).\n\n",
                      BENCH_PRIMARY_WIDTH, BENCH_PRIMARY_HEIGHT, opts->runs);
        report_table_header("mesh|work|threads|packets=off ms|packets=on ms|off/on|same");
        bench_share_reset();
        for (int m = 0; m < mesh_count; m++)
            failed |= api_mesh(opts, &meshes[m]) != 0;
        bench_share_report();
    }
    return failed ? -1 : 0;
}
