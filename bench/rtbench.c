/* SPDX-License-Identifier: Apache-2.0 */
/*
 * rtbench.c - the benchmark driver: options, workloads, sections.
 *
 *   rtbench build   BVH quality against build time (bench_build.c)
 *   rtbench trace   rays per second, direct and through the API (bench_trace.c)
 *   rtbench embree  the same work through Embree 3 (bench_embree.c; needs Embree)
 *   rtbench dynamic dynamic scenes: update strategies over animations, soup
 *                   rebuild, top level, parallel build (bench_dynamic.c)
 *   rtbench error   intersection error against time per kernel, layout and
 *                   ISA on the stability workloads (bench_error.c)
 *   rtbench bart    the BART scenes against Wald, Benthin and Slusallek (2003) sec. 5 (bench_bart.c;
 *                   needs the BART data, fails without it)
 *   rtbench immediate  immediate mode against objects (bench_immediate.c)
 *   rtbench nested  nested static hierarchies flattened against instanced
 *                   (bench_nested.c)
 *   rtbench all     all of the above (default); bart only when its data is
 *                   found, otherwise the report says it was skipped and why
 *
 * Options: --quick (toy sizes, for the smoke test), --runs N (median of N,
 * default 5), --out DIR (results.md, results.csv, PNG plots), --mesh NAME
 * (bumpy, gears, soup or kitchen only; the BART kitchen, frame 0
 * flattened, is a fourth mesh of embree and packets only, when its data is
 * found), --baseline FILE (an earlier results.csv; metrics that got worse
 * by more than --tolerance PCT, default 10, are flagged and the exit
 * status is 2), --bart-dir DIR (the BART scenes;
 * else $TRACELIST_BART_DIR, else the build's RT_BART_DIR).
 *
 * Exit status: 0 done, 1 usage error or a section failed, 2 regressions
 * flagged against the baseline, 3 a correctness check failed (two paths
 * that must give the same answers did not: the API against the direct
 * kernel, the BVH against brute force, Embree against ours).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define DEFAULT_RUNS 5
#define DEFAULT_TOLERANCE 10.0
#define MAX_RUNS 101

enum section {
    SECTION_BUILD = 1,
    SECTION_TRACE = 2,
    SECTION_EMBREE = 4,
    SECTION_DYNAMIC = 8,
    SECTION_BART = 16,
    SECTION_IMMEDIATE = 32,
    SECTION_ERROR = 64,
    SECTION_PACKETS = 128,
    SECTION_NESTED = 256
};
/* `error` takes about 20 s on the development machine: in `all`. */
#define SECTION_ALL                                                                                \
    (SECTION_BUILD | SECTION_TRACE | SECTION_EMBREE | SECTION_DYNAMIC | SECTION_BART |           \
     SECTION_IMMEDIATE | SECTION_ERROR | SECTION_PACKETS | SECTION_NESTED)
/* The sections that run on the generated meshes. */
#define SECTION_MESHES                                                                             \
    (SECTION_BUILD | SECTION_TRACE | SECTION_EMBREE | SECTION_DYNAMIC | SECTION_PACKETS)

static void usage(FILE *f)
{
    fprintf(f,
            "usage: rtbench [build|trace|embree|packets|dynamic|immediate|nested|error|bart|\n"
            "                bart-strategies|bart-fps|frame-overhead|dynamic-cpu|all]\n"
            "               [--quick] [--runs N]"
            " [--out DIR] [--mesh bumpy|gears|soup|kitchen]\n"
            "               [--baseline FILE] [--tolerance PCT] [--bart-dir DIR]\n"
            "               [--isa NAME] [--layout L] [--stream KEYS]\n"
            "\n"
            "  build      BVH quality against build time per builder and bin count\n"
            "  trace      Mrays/s, trace_closest/trace_any directly and through rtTraceRays\n"
            "  embree     the same meshes and rays through Embree 3%s;\n"
            "             plus the BART kitchen (frame 0 flattened) when its data is found\n"
            "  packets    8-ray packets against single rays (and Embree's rtcIntersect8)\n"
            "             on the trace section's coherent sets (and the kitchen's); the\n"
            "             hybrid threshold\n"
            "  dynamic    dynamic scenes: update strategies over animations (error\n"
            "             against time), soup rebuild, top level, parallel build\n"
            "  error      intersection error against ns per ray per kernel, layout and\n"
            "             ISA on the stability workloads (far, tiny, huge, slivers, grazing)\n"
            "  bart       the BART scenes (kitchen, robots, museum) against Wald, Benthin and Slusallek (2003)\n"
            "             sec. 5: fps, top level, updates, strategies, two-level overhead\n"
            "  immediate  immediate-mode re-send against objects (bench_immediate.c)\n"
            "  nested     nested static hierarchies flattened against instanced\n"
            "  bart-strategies  only the BART section's update strategies over the museum\n"
            "  bart-fps         only the BART section's frames per second (three scenes):\n"
            "             wall-clock fps, and by the CPU clock per scene, shading and\n"
            "             threads=1|2: process CPU ms per frame, frames per CPU-second,\n"
            "             the CPU share of each run and the wall and CPU spread over runs\n"
            "             (median of min(--runs, 3) runs; with --out, bart_fps_runs.dat)\n"
            "  frame-overhead   only a kitchen eye-light frame against its bare primary rays\n"
            "             (max(--runs, 5) interleaved pairs, at most 31: medians and the\n"
            "             fastest of each)\n"
            "  dynamic-cpu      the dynamic strategies by CPU time and tests (threads=1)\n"
            "             (RT_AUTOMATIC against the fixed strategies, about a third of bart)\n"
            "  all        everything (default); bart only when its data is found\n"
            "  --quick    toy sizes and 1 run unless --runs is given: a smoke test\n"
            "  --runs N   timings are the median of N runs (default %d)\n"
            "  --threads N  render threads of bart-strategies' contexts (default 2)\n"
            "  --only KEYS  bart-strategies: only these strategies (refit,rebuild,median,\n"
            "             heuristic,restructure,async,automatic); embree: only these\n"
            "             paths (ours,medium,high; the build table also low), with\n"
            "             --threads 1|2 one thread count; `build`: the build table only;\n"
            "             packets: only these parts (primary,shadow,random: the first\n"
            "             table's ray sets; hybrid, api: the other tables), with\n"
            "             --threads 1|2 one thread count\n"
            "  --thread-clock  one-thread trace runs and builds timed by the thread's CPU\n"
            "             clock\n"
            "  --out DIR  write results.md, results.csv and PNG plots (gnuplot) to DIR\n"
            "  --baseline FILE  compare with an earlier results.csv; flag drops beyond\n"
            "             --tolerance PCT (default %.0f) and exit with status 2\n"
            "  --isa NAME  our kernels' ISA table: scalar, sse4, avx2, avx512; default the\n"
            "             best this CPU runs (the API contexts too, by their isa= key)\n"
            "  --layout L  our object walk's layout: bvh8 (AVX2, AVX-512), bvh4 (SSE4.2\n"
            "             up), binary (the walk before the collapse); default the\n"
            "             widest the ISA table walks\n"
            "  --stream KEYS  ours: our single-ray rows (embree, trace, packets) through\n"
            "             the stream entry (several rays in flight; walk1 where the\n"
            "             table has none); embree: Embree's through rtcIntersect1M /\n"
            "             rtcOccluded1M (incoherent); or ours,embree\n"
            "  --config KEY=VALUE  added to every API context's configuration\n"
            "             (rtCreateContext), e.g. stream=off\n"
            "  --collapse C  the wide layout's collapse: greedy (the default) or optimal\n"
            "             (Ylitie, Karras and Laine 2017, an object's\n"
            "             rtHint(RT_ACCELERATION_HINT, RT_NICEST)): rtbench's own\n"
            "             layouts, and the BART scenes' objects through the hint\n"
            "  --mesh NAME  only this mesh: bumpy, gears, soup, or kitchen (embree and\n"
            "             packets only)\n"
            "  --bart-dir DIR  the BART folder (kitchen/, robots/, museum/); default\n"
            "             $TRACELIST_BART_DIR, else the build's RT_BART_DIR\n",
#ifdef RT_HAVE_EMBREE
            "",
#else
            " (not available: built without Embree)",
#endif
            DEFAULT_RUNS, DEFAULT_TOLERANCE);
}

static int parse_int(const char *s, int lo, int hi, int *out)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (!*s || *end || v < lo || v > hi)
        return -1;
    *out = (int)v;
    return 0;
}

int main(int argc, char **argv)
{
    struct bench_options opts;
    int sections = 0;
    int runs_given = 0;
    int dynamic_cpu = 0;   /* `dynamic-cpu`: the strategies by CPU time alone */
    int bart_required = 0; /* `bart` named: no data is an error, not a skip */
    memset(&opts, 0, sizeof(opts));
    opts.runs = DEFAULT_RUNS;
    opts.tolerance = DEFAULT_TOLERANCE;
    opts.argc = argc;
    opts.argv = argv;

    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *value = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "build")) {
            sections |= SECTION_BUILD;
        } else if (!strcmp(a, "trace")) {
            sections |= SECTION_TRACE;
        } else if (!strcmp(a, "embree")) {
            sections |= SECTION_EMBREE;
        } else if (!strcmp(a, "packets")) {
            sections |= SECTION_PACKETS;
        } else if (!strcmp(a, "dynamic")) {
            sections |= SECTION_DYNAMIC;
        } else if (!strcmp(a, "immediate")) {
            sections |= SECTION_IMMEDIATE;
        } else if (!strcmp(a, "nested")) {
            sections |= SECTION_NESTED;
        } else if (!strcmp(a, "error")) {
            sections |= SECTION_ERROR;
        } else if (!strcmp(a, "bart")) {
            sections |= SECTION_BART;
            bart_required = 1;
        } else if (!strcmp(a, "bart-strategies")) {
            sections |= SECTION_BART;
            bart_required = 1;
            opts.bart_strategies_only = 1;
        } else if (!strcmp(a, "dynamic-cpu")) {
            dynamic_cpu = 1;
        } else if (!strcmp(a, "bart-fps")) {
            sections |= SECTION_BART;
            bart_required = 1;
            opts.bart_fps_only = 1;
        } else if (!strcmp(a, "frame-overhead")) {
            sections |= SECTION_BART;
            bart_required = 1;
            opts.bart_frame_overhead_only = 1;
        } else if (!strcmp(a, "all")) {
            sections |= SECTION_ALL;
        } else if (!strcmp(a, "--quick")) {
            opts.quick = 1;
        } else if (!strcmp(a, "--runs") && value) {
            if (parse_int(value, 1, MAX_RUNS, &opts.runs)) {
                fprintf(stderr, "rtbench: --runs takes 1..%d\n", MAX_RUNS);
                return 1;
            }
            runs_given = 1;
            i++;
        } else if (!strcmp(a, "--threads") && value) {
            if (parse_int(value, 1, 64, &opts.threads)) {
                fprintf(stderr, "rtbench: --threads takes 1..64\n");
                return 1;
            }
            i++;
        } else if (!strcmp(a, "--thread-clock")) {
            bench_use_thread_clock();
        } else if (!strcmp(a, "--only") && value) {
            opts.only = value;
            i++;
        } else if (!strcmp(a, "--out") && value) {
            opts.out_dir = value;
            i++;
        } else if (!strcmp(a, "--isa") && value) {
            if (bench_select_isa(value)) {
                fprintf(stderr, "rtbench: --isa takes scalar, sse4, avx2 or avx512, one this "
                                "CPU runs\n");
                return 1;
            }
            opts.isa = value;
            i++;
        } else if (!strcmp(a, "--layout") && value) {
            if (bench_select_layout(value)) {
                fprintf(stderr, "rtbench: --layout takes bvh8, bvh4 or binary\n");
                return 1;
            }
            i++;
        } else if (!strcmp(a, "--stream") && value) {
            if (bench_select_stream(value)) {
                fprintf(stderr, "rtbench: --stream takes ours, embree or ours,embree\n");
                return 1;
            }
            i++;
        } else if (!strcmp(a, "--config") && value) {
            if (bench_select_config(value)) {
                fprintf(stderr, "rtbench: --config takes KEY=VALUE (at most 63 characters)\n");
                return 1;
            }
            i++;
        } else if (!strcmp(a, "--collapse") && value) {
            if (bench_select_collapse(value)) {
                fprintf(stderr, "rtbench: --collapse takes greedy or optimal\n");
                return 1;
            }
            i++;
        } else if (!strcmp(a, "--mesh") && value) {
            opts.mesh = value;
            i++;
        } else if (!strcmp(a, "--bart-dir") && value) {
            opts.bart_dir = value;
            i++;
        } else if (!strcmp(a, "--baseline") && value) {
            opts.baseline = value;
            i++;
        } else if (!strcmp(a, "--tolerance") && value) {
            char *end;
            opts.tolerance = strtod(value, &end);
            if (!*value || *end || !(opts.tolerance >= 0.0)) {
                fprintf(stderr, "rtbench: --tolerance takes a percentage >= 0\n");
                return 1;
            }
            i++;
        } else if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return 0;
        } else {
            fprintf(stderr, "rtbench: unknown or incomplete argument '%s'\n", a);
            usage(stderr);
            return 1;
        }
    }
    if (!sections && !dynamic_cpu)
        sections = SECTION_ALL;
    if (opts.quick && !runs_given)
        opts.runs = 1;

    if (bart_required) {
        char why[512];
        if (bench_bart_find_data(&opts, why, sizeof(why))) {
            fprintf(stderr, "rtbench: bart: %s\n", why);
            return 1;
        }
    }

    /* meshes[0..mesh_count) are the generated meshes every mesh section
     * runs; the kitchen, when loaded, follows them in the same array and
     * only embree and packets get it (kitchen_count). */
    struct bench_mesh meshes[BENCH_MESH_COUNT + 1];
    int mesh_count = 0, kitchen_count = 0;
    const int kitchen_only = opts.mesh && !strcmp(opts.mesh, "kitchen");
    if ((sections & SECTION_MESHES) && !kitchen_only) {
        for (int k = 0; k < BENCH_MESH_COUNT; k++) {
            struct bench_mesh *m = &meshes[mesh_count];
            if (bench_mesh_generate(m, (enum bench_mesh_kind)k, opts.quick)) {
                fprintf(stderr, "rtbench: out of memory generating the workloads\n");
                return 1;
            }
            if (opts.mesh && strcmp(opts.mesh, m->name) != 0) {
                bench_mesh_release(m);
                continue;
            }
            mesh_count++;
        }
        if (mesh_count == 0) {
            fprintf(stderr, "rtbench: no workload named '%s' (bumpy, gears, soup, kitchen)\n",
                    opts.mesh);
            return 1;
        }
    }
    /* The BART kitchen: a fourth mesh of embree and packets when its data
     * is found; without it those sections say why in one line and run the
     * other meshes (no failure: the data is third-party and optional). */
    char kitchen_why[512];
    if ((sections & (SECTION_EMBREE | SECTION_PACKETS)) && (!opts.mesh || kitchen_only)) {
        if (bench_kitchen_mesh(&opts, &meshes[mesh_count], kitchen_why, sizeof(kitchen_why))) {
            opts.kitchen_skipped = kitchen_why;
            report_progress("rtbench: kitchen skipped: %s\n", kitchen_why);
        } else {
            kitchen_count = 1;
        }
    }

    if (report_open(&opts))
        return 1;
    if (mesh_count + kitchen_count > 0) {
        report_printf("\n## Workloads\n\n");
        report_table_header("mesh|triangles|vertices|bounds (min .. max)|what");
    }
    for (int m = 0; m < mesh_count + kitchen_count; m++) {
        const struct bench_mesh *b = &meshes[m];
        report_row("%s|%u|%u|(%.2f, %.2f, %.2f) .. (%.2f, %.2f, %.2f)|%s", b->name, b->tri_count,
                   b->vertex_count, (double)b->bounds.min[0], (double)b->bounds.min[1],
                   (double)b->bounds.min[2], (double)b->bounds.max[0], (double)b->bounds.max[1],
                   (double)b->bounds.max[2], b->description);
    }
    /* build and trace measure the generated meshes only: with --mesh
     * kitchen they have nothing to do (dynamic still plays its own
     * animations, as with any --mesh). */
    if (kitchen_only && (sections & (SECTION_BUILD | SECTION_TRACE))) {
        report_printf("\n--mesh kitchen: the build and trace sections are skipped (they do "
                      "not take the kitchen).\n");
        sections &= ~(SECTION_BUILD | SECTION_TRACE);
    }

    int failed = 0;
    if (sections & SECTION_BUILD)
        failed |= bench_build_section(&opts, meshes, mesh_count) != 0;
    if (sections & SECTION_TRACE)
        failed |= bench_trace_section(&opts, meshes, mesh_count) != 0;
    if (sections & SECTION_EMBREE) {
#ifdef RT_HAVE_EMBREE
        failed |= bench_embree_section(&opts, meshes, mesh_count + kitchen_count) != 0;
#else
        report_printf("\n## Against Embree\n\nSkipped: rtbench was built without Embree "
                      "(CMake did not find embree 3, or RT_WITH_EMBREE=OFF).\n");
#endif
    }
    if (sections & SECTION_PACKETS)
        failed |= bench_packets_section(&opts, meshes, mesh_count + kitchen_count) != 0;
    if (sections & SECTION_DYNAMIC)
        failed |= bench_dynamic_section(&opts, meshes, mesh_count) != 0;
    if (dynamic_cpu)
        failed |= bench_dynamic_cpu_section(&opts) != 0;
    if (sections & SECTION_IMMEDIATE)
        failed |= bench_immediate_section(&opts) != 0;
    if (sections & SECTION_NESTED)
        failed |= bench_nested_section(&opts) != 0;
    if (sections & SECTION_ERROR)
        failed |= bench_error_section(&opts) != 0;
    if (sections & SECTION_BART)
        failed |= bench_bart_section(&opts) != 0;
    int flagged = report_close();
    for (int m = 0; m < mesh_count + kitchen_count; m++)
        bench_mesh_release(&meshes[m]);
    if (failed) {
        fprintf(stderr, "rtbench: a section failed; see the messages above\n");
        return 1;
    }
    if (report_check_failures()) {
        fprintf(stderr, "rtbench: %d correctness check(s) failed\n", report_check_failures());
        return 3;
    }
    return flagged ? 2 : 0;
}
