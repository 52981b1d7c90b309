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
 * threshold at TRACE_PACKET_HYBRID.  Embree: rtcIntersect1/rtcOccluded1
 * and rtcIntersect8/rtcOccluded8 (coherent flag) over the same groups, a
 * MEDIUM scene.  Runs are interleaved (single, packets, Embree 1, Embree
 * 8, for each thread count) and each figure is the median; the packets'
 * answers must equal the single walk's bit for bit (t and primitive).
 *
 * The second table is the hybrid threshold: packets of the same rays
 * with every threshold from 0 (packets to the leaves) to 9 (each ray
 * alone from the root: the packet set-up's overhead over single rays),
 * one thread.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

struct packet_ctx {
    const struct bench_accel *acc;
    unsigned hybrid;
};

static void set_up(const RTray *rays, uint32_t g, uint32_t n, struct trace_ray *ray,
                   float *t_max)
{
    for (uint32_t j = 0; j < n; j++) {
        const RTray *r = &rays[g + j];
        trace_ray_init(&ray[j], r->org, r->dir, r->tmin);
        t_max[j] = r->tmax;
    }
}

static void kernel_closest_packets(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                                   struct bench_hit *hits)
{
    const struct packet_ctx *pc = ctx;
    const struct bench_accel *acc = pc->acc;
    const struct trace_kernels *k = bench_kernels();
    for (uint32_t g = begin; g < end; g += TRACE_PACKET) {
        const uint32_t n = end - g < TRACE_PACKET ? end - g : TRACE_PACKET;
        struct trace_ray ray[TRACE_PACKET];
        float t_max[TRACE_PACKET];
        struct trace_hit h[TRACE_PACKET];
        set_up(rays, g, n, ray, t_max);
        const unsigned found = k->closest_packet(&acc->wide, &acc->bvh, acc->tri, ray, t_max,
                                                 (1u << n) - 1u, pc->hybrid, h, NULL);
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
        struct trace_ray ray[TRACE_PACKET];
        float t_max[TRACE_PACKET];
        set_up(rays, g, n, ray, t_max);
        const unsigned occ = k->any_packet(&acc->wide, &acc->bvh, acc->tri, ray, t_max,
                                           (1u << n) - 1u, pc->hybrid, NULL);
        for (uint32_t j = 0; j < n; j++) {
            hits[g + j].t = occ >> j & 1u ? 0.0f : INFINITY;
            hits[g + j].prim = occ >> j & 1u ? 0 : BENCH_MISS;
        }
    }
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

static int packets_mesh(const struct bench_options *opts, const struct bench_mesh *mesh)
{
    struct bench_accel acc;
    struct bench_rays sets[3];
    struct bench_hit *single = NULL, *packed = NULL, *theirs = NULL;
    double *times = NULL;
    void *embree = NULL;
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
        if (set->count == 0)
            continue;
        report_progress("packets: %s: %s rays (%u)\n", mesh->name, set->name, set->count);
        struct packet_ctx pc = {&acc, TRACE_PACKET_HYBRID};
        uint32_t wrong = 0;
        for (int run = 0; run < opts->runs; run++) {
            for (int t = 0; t < 2; t++) {
                for (int p = 0; p < PATHS; p++) {
                    double ms = 0.0;
                    if (p == 0)
                        ms = bench_run_parallel(any_hit ? bench_kernel_any : bench_kernel_closest,
                                                &acc, set, single, t + 1);
                    else if (p == 1)
                        ms = bench_run_parallel(any_hit ? kernel_any_packets
                                                        : kernel_closest_packets,
                                                &pc, set, packed, t + 1);
#ifdef RT_HAVE_EMBREE
                    else if (embree && p == 2)
                        ms = bench_run_parallel(any_hit ? bench_embree_kernel_any1
                                                        : bench_embree_kernel_closest1,
                                                embree, set, theirs, t + 1);
                    else if (embree && p == 3)
                        ms = bench_run_parallel(any_hit ? bench_embree_kernel_any8
                                                        : bench_embree_kernel_closest8,
                                                embree, set, theirs, t + 1);
#endif
                    if (ms < 0.0)
                        goto out;
                    times[(t * PATHS + p) * opts->runs + run] = ms;
                }
                if (run == 0 && t == 0)
                    wrong = differ(single, packed, set->count);
            }
        }
        double m[2][PATHS];
        for (int t = 0; t < 2; t++)
            for (int p = 0; p < PATHS; p++) {
                double ms = bench_median(&times[(t * PATHS + p) * opts->runs], opts->runs);
                m[t][p] = ms > 0.0 ? set->count / (ms * 1e3) : 0.0;
            }
        for (int t = 0; t < 2; t++) {
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
                    ms = bench_run_parallel(any_hit ? bench_kernel_any : bench_kernel_closest,
                                            &acc, set, hits, 1);
                else
                    ms = bench_run_parallel(any_hit ? kernel_any_packets
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

int bench_packets_section(const struct bench_options *opts, struct bench_mesh *meshes,
                          int mesh_count)
{
    const struct trace_kernels *k = bench_kernels();
    report_printf("\n## Packets\n\n");
    if (!k->closest_packet || bench_layout_width() == 0) {
        report_printf("The kernels (%s) or the layout have no packet walk: nothing to "
                      "compare.\n",
                      k->name);
        return 0;
    }
    report_printf("Mrays/s (median of %d runs), kernels %s, %u-wide layout. \"single\": the "
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
    report_printf("\nHybrid threshold (packet.h): Mrays/s, one thread, median of %d runs; "
                  "packets continue ray by ray below the threshold's number of active rays (0: "
                  "never, 9: always, from the root).\n\n",
                  opts->runs);
    report_table_header("mesh|rays|single|0|2|3|4|6|9");
    for (int m = 0; m < mesh_count; m++)
        failed |= hybrid_mesh(opts, &meshes[m]) != 0;
    return failed ? -1 : 0;
}
