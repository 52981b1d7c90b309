/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_build.c - `rtbench build`: BVH quality against build time, per
 * builder and bin count (Wald, Ize and Parker (2008) sec. 4 and table 1; DESIGN.md
 * "Measurement").
 *
 * For each mesh, the sweep SAH build (the quality reference), the
 * spatial-median build (table 1's "BIH" row) and the binned SAH build with
 * 4, 8, 16 and 32 bins:
 *   - build time: the builder alone, over triangle boxes computed once
 *     beforehand (the boxes and the gather into leaf order are the same
 *     for every builder); median of --runs; and triangles per second;
 *   - quality: the SAH cost (MacDonald and Booth 1990, accel_sah_cost with
 *     the library's constants) and its ratio to the sweep build's;
 *   - measured traversal cost: node (ray/box) and triangle tests per ray
 *     of trace_closest for a fixed set of primary-like rays (a 256x192
 *     camera) and of random rays, from trace_counters;
 *   - render speed relative to the sweep build: the single-thread time of
 *     the primary-like set, sweep time / this time, which is the quantity
 *     Wald, Ize and Parker's (2008) table 1 gives as a percentage.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accel/build_median.h"
#include "base/timer.h"
#include "bench.h"

#define COUNT_WIDTH 256
#define COUNT_HEIGHT 192
#define COUNT_RANDOM 65536
#define COUNT_WIDTH_QUICK 64
#define COUNT_HEIGHT_QUICK 48
#define COUNT_RANDOM_QUICK 8192
#define COUNT_SEED 0x636f756eu
/* The relative speed is timed over the primary-like set repeated this
 * often per run, so that one sample lasts tens of milliseconds and
 * scheduler noise on a shared machine stays small against it. */
#define SPEED_REPEATS 4

struct builder_row {
    const char *label;
    const char *key; /* results.csv */
    int median;      /* accel_build_median (build_median.h) instead of accel_build */
    enum bvh_builder builder;
    int bins;
};

/* Sweep first: the others are reported relative to it.  The spatial-median
 * ("BIH-style") builder is Wald, Ize and Parker (2008) table 1's middle row. */
static const struct builder_row builders[] = {
    {"sweep SAH", "sweep", 0, BVH_BUILDER_SWEEP_SAH, 0},
    {"median (BIH)", "median", 1, BVH_BUILDER_BINNED_SAH, 0},
    {"binned 4", "binned4", 0, BVH_BUILDER_BINNED_SAH, 4},
    {"binned 8", "binned8", 0, BVH_BUILDER_BINNED_SAH, 8},
    {"binned 16", "binned16", 0, BVH_BUILDER_BINNED_SAH, 16},
    {"binned 32", "binned32", 0, BVH_BUILDER_BINNED_SAH, 32},
};
#define BUILDER_COUNT ((int)(sizeof(builders) / sizeof(builders[0])))

struct build_result {
    double build_ms;
    uint32_t nodes;
    uint32_t depth;
    double sah;
    double primary_nodes, primary_tris;
    double random_nodes, random_tris;
    double trace_ms;
    /* The 4- and 8-wide layouts collapsed from this tree (first builder
     * only), [0] 4-wide, [1] 8-wide. */
    double node_bytes[2], leaf_bytes[2];
    double collapse_ms[2];
    double primary_nodes4[2], primary_tris4[2];
    double random_nodes4[2], random_tris4[2];
};

/* Measures every builder on one mesh.  The runs are interleaved (run 1 of
 * each builder, then run 2, ...) for the build times and again for the
 * trace times, so that a busy phase of a shared machine falls on all
 * builders alike rather than on whichever ran then; all trees stay alive
 * between the two phases. */
static int measure_builders(const struct bench_options *opts, const struct bench_mesh *mesh,
                            const struct aabb *boxes, const struct bench_rays *primary,
                            const struct bench_rays *random, struct bench_hit *hits,
                            struct build_result res[BUILDER_COUNT])
{
    struct bench_accel acc[BUILDER_COUNT];
    struct bvh_build_params params[BUILDER_COUNT];
    const int runs = opts->runs;
    double *times = malloc((size_t)BUILDER_COUNT * runs * sizeof(*times));
    int rc = -1;
    memset(acc, 0, sizeof(acc));
    if (!times)
        return -1;
    for (int b = 0; b < BUILDER_COUNT; b++) {
        bvh_build_params_default(&params[b]);
        params[b].builder = builders[b].builder;
        if (builders[b].bins)
            params[b].bins = builders[b].bins;
    }
    for (int run = 0; run < runs; run++) {
        report_progress("build: %s: build run %d of %d\n", mesh->name, run + 1, runs);
        for (int b = 0; b < BUILDER_COUNT; b++) {
            bench_accel_release(&acc[b]);
            double cpu_start = bench_cpu_ms();
            double start = rt_now_ms();
            int failed = builders[b].median
                             ? accel_build_median(&acc[b].bvh, boxes, mesh->tri_count, &params[b])
                             : accel_build(&acc[b].bvh, boxes, mesh->tri_count, &params[b]);
            times[b * runs + run] = rt_now_ms() - start;
            bench_share_add(1, times[b * runs + run], bench_cpu_ms() - cpu_start);
            if (failed)
                goto out;
        }
    }
    for (int b = 0; b < BUILDER_COUNT; b++) {
        struct build_result *r = &res[b];
        r->build_ms = bench_median(&times[b * runs], runs);
        acc[b].tri = accel_gather_triangles(&acc[b].bvh, mesh->positions, mesh->indices);
        if (!acc[b].tri)
            goto out;
        r->nodes = acc[b].bvh.node_count;
        r->depth = acc[b].bvh.depth;
        r->sah = accel_sah_cost(&acc[b].bvh, BVH_C_TRAV, BVH_C_ISECT);
        bench_count_tests(&acc[b], primary, &r->primary_nodes, &r->primary_tris);
        bench_count_tests(&acc[b], random, &r->random_nodes, &r->random_tris);
        for (int w = 0; b == 0 && w < 2; w++) {
            double start = rt_now_ms();
            if (accel_collapse_wide(&acc[b].wide, &acc[b].bvh, acc[b].tri, w ? 8 : 4))
                goto out;
            r->collapse_ms[w] = rt_now_ms() - start;
            r->node_bytes[w] = (double)bvh4_node_bytes(&acc[b].wide);
            r->leaf_bytes[w] = (double)bvh4_leaf_bytes(&acc[b].wide);
            bench_count_tests_wide(&acc[b], primary, &r->primary_nodes4[w], &r->primary_tris4[w]);
            bench_count_tests_wide(&acc[b], random, &r->random_nodes4[w], &r->random_tris4[w]);
            bench_accel_release_wide(&acc[b]);
        }
    }
    report_progress("build: %s: trace timings\n", mesh->name);
    for (int run = 0; run < runs; run++) {
        for (int b = 0; b < BUILDER_COUNT; b++) {
            double ms = 0.0;
            for (int rep = 0; rep < (opts->quick ? 1 : SPEED_REPEATS); rep++)
                ms += bench_run_parallel(bench_kernel_closest, &acc[b], primary, hits, 1);
            times[b * runs + run] = ms;
        }
    }
    for (int b = 0; b < BUILDER_COUNT; b++)
        res[b].trace_ms = bench_median(&times[b * runs], runs);
    rc = 0;
out:
    for (int b = 0; b < BUILDER_COUNT; b++)
        bench_accel_release(&acc[b]);
    free(times);
    return rc;
}

static int build_mesh(const struct bench_options *opts, const struct bench_mesh *mesh,
                      char *plot_script, size_t script_size, int first_plot,
                      struct build_result *first)
{
    struct bench_rays primary, random;
    struct build_result res[BUILDER_COUNT];
    struct aabb *boxes = bench_mesh_boxes(mesh);
    struct bench_hit *hits = NULL;
    int rc = -1;
    memset(&primary, 0, sizeof(primary));
    memset(&random, 0, sizeof(random));
    if (!boxes ||
        bench_rays_primary(&primary, mesh, opts->quick ? COUNT_WIDTH_QUICK : COUNT_WIDTH,
                           opts->quick ? COUNT_HEIGHT_QUICK : COUNT_HEIGHT) ||
        bench_rays_random(&random, mesh, opts->quick ? COUNT_RANDOM_QUICK : COUNT_RANDOM,
                          COUNT_SEED))
        goto out;
    hits = malloc((size_t)primary.count * sizeof(*hits));
    if (!hits)
        goto out;
    if (measure_builders(opts, mesh, boxes, &primary, &random, hits, res))
        goto out;
    *first = res[0];
    char file[64];
    snprintf(file, sizeof(file), "build_%s.dat", mesh->name);
    FILE *data = report_data_file(file);
    for (int b = 0; b < BUILDER_COUNT; b++) {
        const struct build_result *r = &res[b];
        double sah_ratio = res[0].sah > 0.0 ? r->sah / res[0].sah : 0.0;
        double speed = r->trace_ms > 0.0 ? res[0].trace_ms / r->trace_ms : 0.0;
        report_row("%s|%s|%.2f|%.2f|%u|%u|%.2f|%.3f|%.1f|%.2f|%.1f|%.2f|%.0f%%", mesh->name,
                   builders[b].label, r->build_ms,
                   r->build_ms > 0.0 ? mesh->tri_count / (r->build_ms * 1e3) : 0.0, r->nodes,
                   r->depth, r->sah, sah_ratio, r->primary_nodes, r->primary_tris, r->random_nodes,
                   r->random_tris, 100.0 * speed);
        char key[96];
        snprintf(key, sizeof(key), "build.%s.%s.ms", mesh->name, builders[b].key);
        report_metric(key, r->build_ms, 0);
        snprintf(key, sizeof(key), "build.%s.%s.sah", mesh->name, builders[b].key);
        report_metric(key, r->sah, 0);
        snprintf(key, sizeof(key), "build.%s.%s.primary_tests", mesh->name, builders[b].key);
        report_metric(key, r->primary_nodes + r->primary_tris, 0);
        if (data)
            fprintf(data, "\"%s\" %.4f %.5f %.4f\n", builders[b].label, r->build_ms, sah_ratio,
                    speed);
    }
    if (data) {
        fclose(data);
        size_t used = strlen(plot_script);
        snprintf(plot_script + used, script_size - used,
                 "%s'%s' using 2:3 with linespoints "
                 "pt 7 title '%s', '' using 2:3:1 with labels offset 0,1 font ',8' notitle",
                 first_plot ? "plot " : ", \\\n     ", file, mesh->name);
    }
    rc = 0;
out:
    if (rc)
        report_progress("rtbench: build: %s failed (out of memory)\n", mesh->name);
    free(boxes);
    free(hits);
    bench_rays_release(&primary);
    bench_rays_release(&random);
    return rc;
}

int bench_build_section(const struct bench_options *opts, struct bench_mesh *meshes, int mesh_count)
{
    char script[4096];
    report_printf("\n## Build: quality against build time (Wald, Ize and Parker (2008) table 1)\n\n");
    report_printf("One thread. \"build ms\": the builder alone (median of %d runs) over "
                  "precomputed triangle boxes. SAH cost: MacDonald-Booth with c_trav = %g, "
                  "c_isect = %g, leaves of at most %d triangles; \"SAH/sweep\": relative to the "
                  "sweep build (lower is better). Tests per ray: ray/box and ray/triangle tests "
                  "of trace_closest for %ux%u primary rays and %u random rays. \"speed vs "
                  "sweep\": single-thread time of the primary set, sweep / this (Wald, Ize and Parker (2008) "
                  "table 1's relative render performance).\n\n",
                  opts->runs, (double)BVH_C_TRAV, (double)BVH_C_ISECT, BVH_MAX_LEAF_SIZE,
                  opts->quick ? COUNT_WIDTH_QUICK : COUNT_WIDTH,
                  opts->quick ? COUNT_HEIGHT_QUICK : COUNT_HEIGHT,
                  opts->quick ? COUNT_RANDOM_QUICK : COUNT_RANDOM);
    report_table_header("mesh|builder|build ms|Mtris/s|nodes|depth|SAH cost|SAH/sweep|"
                        "primary nodes/ray|primary tris/ray|random nodes/ray|random tris/ray|"
                        "speed vs sweep");
    snprintf(script, sizeof(script),
             "set terminal pngcairo size 900,560 font ',10'\n"
             "set output 'build.png'\n"
             "set title 'BVH quality against build time (one thread)'\n"
             "set xlabel 'build time, ms (log)'\n"
             "set ylabel 'SAH cost / sweep SAH cost'\n"
             "set logscale x\n"
             "set grid\n"
             "set key top center\n");
    int failed = 0;
    struct build_result first[8];
    memset(first, 0, sizeof(first));
    bench_share_reset();
    for (int m = 0; m < mesh_count && m < 8; m++)
        failed |= build_mesh(opts, &meshes[m], script, sizeof(script), m == 0, &first[m]) != 0;
    bench_share_report();
    report_printf("\nLayouts of the %s tree: bytes per triangle of the nodes and of the "
                  "leaves (binary: 32-byte nodes, leaves the 36-byte leaf-ordered triangles "
                  "plus the 4-byte primitive index; bvh4/bvh8: 128/256-byte nodes, leaves "
                  "160-byte packets of four triangles, trace/bvh4_layout.h; Embree 3's "
                  "BVH8 node is 256 bytes and its Triangle4 leaf block 176), the "
                  "collapse's time (one thread), and box and triangle tests per ray of the "
                  "binary walk (scalar table) and of the wide walks (best table; a box test "
                  "is one child box: four or eight per wide node visited; a triangle test "
                  "one packet lane). Same hits.\n\n",
                  builders[0].label);
    report_table_header("mesh|binary node B/tri|leaf|bvh4 node B/tri|leaf|bvh8 node B/tri|leaf|"
                        "collapse ms bvh4|bvh8|"
                        "primary boxes/ray binary|bvh4|bvh8|primary tris/ray binary|bvh4|bvh8|"
                        "random boxes/ray binary|bvh4|bvh8|random tris/ray binary|bvh4|bvh8");
    for (int m = 0; m < mesh_count && m < 8; m++) {
        const struct build_result *r = &first[m];
        double n = meshes[m].tri_count ? (double)meshes[m].tri_count : 1.0;
        report_row("%s|%.1f|%.1f|%.1f|%.1f|%.1f|%.1f|%.2f|%.2f|%.1f|%.1f|%.1f|%.2f|%.2f|%.2f|"
                   "%.1f|%.1f|%.1f|%.2f|%.2f|%.2f",
                   meshes[m].name, 32.0 * r->nodes / n, 40.0, r->node_bytes[0] / n,
                   r->leaf_bytes[0] / n, r->node_bytes[1] / n, r->leaf_bytes[1] / n,
                   r->collapse_ms[0], r->collapse_ms[1], r->primary_nodes, r->primary_nodes4[0],
                   r->primary_nodes4[1], r->primary_tris, r->primary_tris4[0],
                   r->primary_tris4[1], r->random_nodes, r->random_nodes4[0],
                   r->random_nodes4[1], r->random_tris, r->random_tris4[0], r->random_tris4[1]);
    }
    strncat(script, "\n", sizeof(script) - strlen(script) - 1);
    if (!failed)
        report_plot("build", script);
    return failed ? -1 : 0;
}
