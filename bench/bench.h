/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench.h - what the pieces of rtbench share: meshes, ray sets, our
 * acceleration structure, the parallel ray loop, statistics and the
 * report.
 *
 * Conventions:
 *   - A mesh is indexed: triangle j has vertex indices indices[3j..3j+2]
 *     into positions (xyz per vertex), exactly what accel_gather_triangles
 *     and Embree's UINT3 index buffer take.
 *   - Rays are RTray (rt.h) in every path, ours and Embree's: org, tmin,
 *     dir, tmax, dir not normalised, hits accepted for tmin <= t < tmax.
 *   - A hit record is struct bench_hit: t = +inf and prim = BENCH_MISS on a
 *     miss, so two paths are compared record by record (bench_compare_hits).
 *   - Times are milliseconds (rt_now_ms), reported as the median of runs.
 *
 * Nothing here is part of the library; rtbench may use its internals
 * (lib/accel, lib/trace) because it links the static core.
 */
#ifndef RT_BENCH_BENCH_H
#define RT_BENCH_BENCH_H

#include <rt/rt.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "trace/bvh4_layout.h"
#include "accel/bvh_build.h"
#include "base/aabb.h"
#include "trace/kernels.h"
#include "trace/trace.h"

/* ------------------------------------------------------------ options */

struct bench_options {
    int quick;            /* --quick: toy sizes, a smoke test, numbers mean nothing */
    int runs;             /* --runs N: timings are the median of N runs */
    const char *out_dir;  /* --out DIR: results.md, results.csv, plots; NULL = stdout only */
    const char *mesh;     /* --mesh NAME: only this workload; NULL = all */
    const char *baseline; /* --baseline FILE: an earlier results.csv to compare with */
    const char *bart_dir; /* --bart-dir DIR: the BART scenes; NULL = environment, build */
    double tolerance;     /* --tolerance PCT: a drop beyond it is flagged */
    const char *isa;      /* --isa NAME: our kernels' ISA table; NULL = the best */
    int bart_strategies_only; /* `bart-strategies`: only the museum's update strategies */
    int threads; /* --threads N: render threads of the strategy tables; 0 = their default */
    const char *only; /* --only KEYS: bart-strategies runs only these strategies;
                       * embree: `ours` or `embree` runs only that path */
    int bart_frame_overhead_only; /* `frame-overhead`: only the kitchen frame against bare rays */
    int bart_fps_only; /* `bart-fps`: only the frames-per-second tables of the three scenes */
    /* Why the BART kitchen is not among the meshes of `embree` and
     * `packets` (no data, a load error); NULL when it is there or was not
     * asked for (--mesh names another mesh).  Those sections print it. */
    const char *kitchen_skipped;
    int argc;
    char **argv;
};

/* ------------------------------------------------------------ meshes */

/* A pinhole camera: primary ray (x, y) of a w x h image goes from eye
 * through eye + forward + (2(x+.5)/w - 1) tan_x right + (1 - 2(y+.5)/h)
 * tan_y up; forward, right, up orthonormal. */
struct bench_camera {
    float eye[3];
    float forward[3];
    float right[3];
    float up[3];
    float tan_x; /* tan of half the horizontal field of view */
};

struct bench_mesh {
    const char *name;        /* "bumpy", "gears", "soup", "kitchen": table and csv key */
    const char *description; /* one line for the report */
    float *positions;        /* 3 floats per vertex */
    uint32_t *indices;       /* 3 per triangle */
    uint32_t vertex_count;
    uint32_t tri_count;
    struct aabb bounds;
    struct bench_camera camera;
    float light[3]; /* point light for shadow rays, outside the bounds */
};

enum bench_mesh_kind { BENCH_MESH_BUMPY, BENCH_MESH_GEARS, BENCH_MESH_SOUP, BENCH_MESH_COUNT };

/* Generates a workload (mesh_gen.c); quick selects the smoke-test size.
 * Deterministic: the same kind and size give the same floats every run;
 * across machines only libm's sin/cos rounding (bumpy, gears) can differ
 * in the last bit.  Returns 0, or -1 on allocation failure with *mesh
 * zeroed. */
int bench_mesh_generate(struct bench_mesh *mesh, enum bench_mesh_kind kind, int quick);
void bench_mesh_release(struct bench_mesh *mesh);

/* The BART kitchen, frame 0, flattened into one mesh (kitchen_mesh.c):
 * every visible instance's triangles in world space, 3 vertices each, the
 * file's camera and first light at frame 0.  The fourth mesh of `rtbench
 * embree` and `rtbench packets`, when the data is found.  Returns 0, or
 * -1 with *mesh zeroed and a one-line reason in why (no path in it). */
int bench_kitchen_mesh(const struct bench_options *opts, struct bench_mesh *mesh, char *why,
                       size_t why_size);

/* The triangles' boxes, as a builder takes them; NULL on failure
 * (free()). */
struct aabb *bench_mesh_boxes(const struct bench_mesh *mesh);

/* ------------------------------------------------------------ animations */

/* Procedural animations for `rtbench dynamic` (anim_gen.c): frame f is a
 * pure function of (kind, size, f), placed in front of a camera at the
 * origin looking down -z, so the API needs no matrix. */
enum bench_anim_kind { BENCH_ANIM_EXPLODE, BENCH_ANIM_CLOTH, BENCH_ANIM_SOUP };

/* The soup reaches its next random configuration every this many frames. */
#define BENCH_SOUP_KEY_FRAMES 10

struct bench_anim {
    enum bench_anim_kind kind;
    const char *name;  /* "explode", "cloth", "soup" */
    uint32_t size;     /* explode: quads around the torus (size x size/2); cloth:
                        * grid size x size; soup: triangles */
    int frames;
    float *positions;  /* the current frame, 3 floats per vertex */
    uint32_t *indices; /* 3 per triangle, fixed over the animation */
    uint32_t vertex_count;
    uint32_t tri_count;
};

/* Allocates and fills frame 0.  Returns 0, or -1 on allocation failure. */
int bench_anim_create(struct bench_anim *a, enum bench_anim_kind kind, uint32_t size, int frames);
/* Overwrites a->positions with frame `frame`. */
void bench_anim_frame(struct bench_anim *a, int frame);
void bench_anim_release(struct bench_anim *a);
/* A bench_mesh view of the current frame (no camera, no bounds; shares
 * the arrays). */
struct bench_mesh bench_anim_mesh(const struct bench_anim *a);

/* ------------------------------------------------------------ rays */

struct bench_rays {
    const char *name; /* "primary", "random", "shadow" */
    RTray *rays;
    uint32_t count;
    uint32_t width, height; /* primary: image size; else 0 */
};

/* The trace ray sets (bench_trace.c and bench_embree.c use the same):
 * full run and --quick. */
#define BENCH_PRIMARY_WIDTH 1024
#define BENCH_PRIMARY_HEIGHT 768
#define BENCH_PRIMARY_WIDTH_QUICK 160
#define BENCH_PRIMARY_HEIGHT_QUICK 120
#define BENCH_RANDOM_RAYS 500000
#define BENCH_RANDOM_RAYS_QUICK 20000
#define BENCH_RANDOM_SEED 0x7261793Bu

/* Generates the three trace sets of a mesh: primary, random, and shadow
 * rays from the primary hits of `acc` (closest hits, one thread).
 * Returns 0, or -1 on allocation failure with all three released. */
struct bench_accel;
int bench_rays_trace_sets(struct bench_rays sets[3], const struct bench_mesh *mesh,
                          const struct bench_accel *acc, int quick);

/* Splitmix64 (Steele, Lea and Flood 2014): a small, seedable generator,
 * identical everywhere, so ray sets and meshes are reproducible. */
struct bench_rng {
    uint64_t state;
};
void bench_rng_seed(struct bench_rng *rng, uint64_t seed);
uint64_t bench_rng_next(struct bench_rng *rng);
float bench_rng_float(struct bench_rng *rng); /* uniform in [0, 1) */

/* The generators return 0, or -1 on allocation failure (set zeroed).
 * Primary rays: one per pixel, row by row, tmin 0, tmax +inf. */
int bench_rays_primary(struct bench_rays *set, const struct bench_mesh *mesh, uint32_t width,
                       uint32_t height);
/* Incoherent rays: origins uniform in the mesh bounds, directions uniform
 * on the sphere, tmin 0, tmax +inf. */
int bench_rays_random(struct bench_rays *set, const struct bench_mesh *mesh, uint32_t count,
                      uint64_t seed);
/* Shadow rays from the hit points of `primary` (hits from any correct
 * closest-hit path) to mesh->light: dir = light - p, tmin a small epsilon
 * against self-hits, tmax 1 (the light itself is never hit).  Rays that
 * missed produce no shadow ray. */
struct bench_hit;
int bench_rays_shadow(struct bench_rays *set, const struct bench_mesh *mesh,
                      const struct bench_rays *primary, const struct bench_hit *hits);
void bench_rays_release(struct bench_rays *set);

/* ------------------------------------------------------------ hits */

#define BENCH_MISS 0xFFFFFFFFu

struct bench_hit {
    float t;       /* +inf on a miss */
    uint32_t prim; /* BENCH_MISS on a miss; any-hit paths store 0 for "occluded" */
};

/* Agreement of two hit arrays (bench_compare_hits): a pair agrees when
 * both miss, or both hit with |t_a - t_b| <= BENCH_T_TOLERANCE * max(1, |t_a|).
 * Tolerance: Embree's Moeller-Trumbore-style test and our watertight
 * test round differently, a few ulp of t; 1e-4 relative is far above
 * that and far below any real disagreement (a different surface). */
#define BENCH_T_TOLERANCE 1e-4f

struct bench_agreement {
    uint64_t compared;
    uint64_t agree;         /* hit/miss and t agree */
    uint64_t same_prim;     /* agree and the same primitive */
    uint64_t hit_miss_diff; /* one hits, the other misses */
};
void bench_compare_hits(struct bench_agreement *a, const struct bench_hit *x,
                        const struct bench_hit *y, uint32_t count, uint32_t stride);
double bench_agreement_percent(const struct bench_agreement *a);
/* The brute-force reference's answer (trace_closest_brute_force: every
 * triangle of the mesh, the exact test) for one ray of a set. */
struct bench_hit bench_brute_force_hit(const struct bench_mesh *mesh, const RTray *r);

/* ------------------------------------------------------------ our BVH */

struct bench_accel {
    struct bvh bvh;
    float *tri; /* accel_gather_triangles */
    struct bvh4 wide; /* accel_collapse_wide, bench_layout_width() wide */
};

/* Builds with the given parameters (boxes + build + gather).  Returns 0
 * or -1 on allocation failure. */
int bench_accel_build(struct bench_accel *acc, const struct bench_mesh *mesh,
                      const struct bvh_build_params *params);
/* The same with the tree built by accel_build_parallel (binned SAH at the
 * top, binned SAH subtrees) on the threads of pool (base/pool.h), as a
 * context builds large objects; pool NULL: bench_accel_build. */
struct rt_pool;
int bench_accel_build_pool(struct bench_accel *acc, const struct bench_mesh *mesh,
                           const struct bvh_build_params *params, struct rt_pool *pool);
/* bench_accel_build_pool, with the leaf-ordered triangles (tri, for the
 * binary walks) only when with_tri: without them, the binary tree and the
 * wide layout, what the wide walk reads and what a library object's
 * fresh build makes (scene/accel.c). */
int bench_accel_build_wide(struct bench_accel *acc, const struct bench_mesh *mesh,
                           const struct bvh_build_params *params, struct rt_pool *pool,
                           int with_tri);
void bench_accel_release(struct bench_accel *acc);

/*
 * The reference of the SAH-cost ratio that `rtbench dynamic` and `rtbench
 * bart` report for an object's tree (Wald, Ize and Parker (2008) fig. 3's quality measure):
 * builds mesh afresh with `builder` (otherwise bvh_build_params_default,
 * the parameters a context's objects are built with) and returns the
 * tree's SAH cost as RT_OBJECT_SAH_COST measures an object's tree,
 * accel_sah_cost with BVH_C_TRAV and BVH_C_ISECT (lib/scene/update.c).
 * With keep != NULL the build is left in *keep for tracing (release with
 * bench_accel_release); with NULL it is freed.  Returns a negative value
 * on allocation failure (*keep zeroed).
 */
double bench_fresh_sah(const struct bench_mesh *mesh, enum bvh_builder builder,
                       struct bench_accel *keep);

/* ------------------------------------------------------------ ray loops */

/*
 * A kernel traces rays [begin, end) of a set and writes their hits.  It
 * runs on `threads` threads (the caller plus threads - 1 pthreads) that
 * take chunks of BENCH_CHUNK rays from a shared counter, so the split
 * adapts to rays of uneven cost.  Returns the wall time in ms, or a
 * negative value when a thread could not be started.
 */
#define BENCH_CHUNK 1024
typedef void (*bench_kernel_fn)(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                                struct bench_hit *hits);
/* --thread-clock: bench_run_parallel times one-thread runs by the
 * thread's CPU clock instead of the wall clock. */
void bench_use_thread_clock(void);
/* The clock a timed step of `threads` threads that runs on the calling
 * thread reads: the calling thread's CPU clock (ms) under --thread-clock
 * when threads is 1, else rt_now_ms. */
double bench_clock_ms(int threads);
/* 1 under --thread-clock. */
int bench_thread_clock(void);
double bench_run_parallel(bench_kernel_fn kernel, void *ctx, const struct bench_rays *set,
                          struct bench_hit *hits, int threads);

/* Kernels over our BVH (bench_trace.c).  ctx: const struct bench_accel *. */
/* The ISA table (lib/trace/kernels.h) "ours" runs: the best this CPU
 * runs unless bench_select_isa chose one (--isa).  Returns -1 when name
 * is unknown or not runnable here. */
const struct trace_kernels *bench_kernels(void);
int bench_select_isa(const char *name);
/* rtCreateContext(config) with " isa=NAME" after config when --isa chose
 * a table, so that the API sections (the frame, the BART scenes, the
 * dynamic and packet API tables) run the table the kernel sections run.
 * NULL where rtCreateContext gives NULL (or config is too long). */
RTcontext bench_create_context(const char *config);
/* --config KEY=VALUE: added after config (and isa=) by
 * bench_create_context; -1 when too long or without '='. */
int bench_select_config(const char *item);
/* "bvh8", "bvh4" (default: the table's widest walk, wide_width) or
 * "binary" (--layout); -1 for another name. */
int bench_select_layout(const char *name);
/* The width bench_accel_build collapses to: --layout's, else the
 * table's wide_width (4 for the scalar table, which walks none). */
uint32_t bench_layout_width(void);
/* The layout the kernels of "ours" walk: "binary", "bvh4" or "bvh8". */
const char *bench_layout_name(void);
/* --stream KEYS (bench_select_stream, -1 for an unknown or empty key):
 * "ours" times our single-ray rows through the stream entry (kernels.h,
 * stream_pair; walk1 where the table has none), "embree" Embree's
 * through rtcIntersect1M / rtcOccluded1M (bench_embree_stream). */
int bench_select_stream(const char *keys);
int bench_embree_stream(void);

/* --collapse greedy|optimal (bench_select_collapse, -1 for another
 * name): the collapse of the benchmark's wide layouts; its name for the
 * tables' headers. */
int bench_select_collapse(const char *name);
enum bvh_collapse bench_collapse(void);
const char *bench_collapse_name(void);

void bench_kernel_closest(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                          struct bench_hit *hits);
void bench_kernel_any(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                      struct bench_hit *hits);

/* Average node and triangle tests per ray of trace_closest over a set,
 * single-threaded. */
void bench_count_tests(const struct bench_accel *acc, const struct bench_rays *set,
                       double *nodes_per_ray, double *tris_per_ray);
/* The same counts for the wide walk of the best table (0 without one);
 * acc->wide must be collapsed. */
void bench_count_tests_wide(const struct bench_accel *acc, const struct bench_rays *set,
                            double *nodes_per_ray, double *tris_per_ray);
void bench_accel_release_wide(struct bench_accel *acc);
/* Node and triangle tests per ray of the walk "ours" runs
 * (bench_kernel_closest, or bench_kernel_any when any_hit), single-threaded;
 * *answered_percent: rays that hit (closest) or are occluded (any). */
void bench_count_tests_ours(const struct bench_accel *acc, const struct bench_rays *set,
                            int any_hit, double *nodes_per_ray, double *tris_per_ray,
                            double *answered_percent);

/* ------------------------------------------------------------ statistics */

/* CPU time of the whole process (all threads), ms. */
double bench_cpu_ms(void);
/* How much of the machine the timed runs got: each timed run adds its
 * wall time, thread count and process CPU time; the share is CPU time /
 * (wall time x threads), 100% when no other process took our cores (a
 * 2-thread figure on a 2-core machine shared with a compiler is worth
 * little, and this says so).  bench_run_parallel records its runs itself.
 * bench_share_percent returns -1 when no run of that thread count was
 * recorded since bench_share_reset; bench_share_report prints one line. */
void bench_share_reset(void);
void bench_share_add(int threads, double wall_ms, double cpu_ms);
double bench_share_percent(int threads);
void bench_share_report(void);

/* Median of n values (n >= 1); reorders values. */
double bench_median(double *values, int n);

/* ------------------------------------------------------------ report */

/* Opens the report: prints the header (machine, date, compiler, build
 * type, commit, command line) to stdout and, with --out, to
 * DIR/results.md.  Returns 0, or -1 when the output directory or file
 * cannot be created (with a message on stderr). */
int report_open(const struct bench_options *opts);
/* Text for both stdout and results.md. */
void report_printf(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* A markdown table row from cells separated by '|' in fmt's output:
 * report_row("%s|%.1f", a, b) prints "| a | 1.0 |". */
void report_row(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* A header row plus the separator line; cells as for report_row. */
void report_table_header(const char *cells);
/* Progress and notes for the person watching: stderr only. */
void report_progress(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* Records a named metric for results.csv and the --baseline comparison.
 * higher_is_better: 1 for throughput, 0 for times and costs; -1 for
 * values that are reported but never flagged. */
void report_metric(const char *key, double value, int higher_is_better);

/* Opens DIR/name for writing (a data file for a plot); NULL without --out
 * or on error.  Close with fclose. */
FILE *report_data_file(const char *name);

/* RT_AUTOMATIC's inputs for object `name` of the current context
 * (lib/scene/update.c), read through the context (bench_dynamic.c): for
 * per-frame decision logs.  0, or -1 when the object has no structure. */
struct bench_automatic_state {
    int rebuilds;
    double ms_per_test, expected_rays, lost_ms, build_ms, sah_cost, built_sah_cost;
};
int bench_automatic_state(unsigned name, struct bench_automatic_state *out);
/* The current context's projection matrix, in the doubles the renderer
 * uses (rtGetFloatv would round it). */
void bench_current_projection(double m[16]);

/* 1 when `key` is one of the comma-separated keys of `only` (--only). */
int bench_strategy_selected(const char *only, const char *key);
/* 1 when a section that runs one and two threads runs `threads` (1 or 2)
 * under --threads (opts->threads 0: both). */
int bench_threads_selected(const struct bench_options *opts, int threads);
/* `rtbench dynamic-cpu` (bench_dynamic.c). */
int bench_dynamic_cpu_section(const struct bench_options *opts);
/* Registers a gnuplot script (written to DIR/name.gp, run at the end to
 * make DIR/name.png). */
void report_plot(const char *name, const char *script);
/*
 * Registers the two plots of an update-strategy comparison over an
 * animation (`rtbench dynamic`, `rtbench bart`).  data_file holds one line
 * per frame: the frame number, then for each strategy k its frame time in
 * ms and its SAH-cost ratio (columns 2 + 2k and 3 + 2k).  Plots
 * NAME_time.png, the frame times of all `count` strategies on a log scale,
 * and NAME_sah.png, the SAH ratios of the strategies with has_sah[k] != 0;
 * labels[k] names strategy k in the key.
 */
void report_strategy_plots(const char *name, const char *data_file, const char *time_title,
                           const char *sah_title, int count, const char *const *labels,
                           const int *has_sah);

/* Counts a failed correctness check (answers that should agree do not);
 * rtbench then exits with status 3, which fails the smoke test. */
void report_check_failed(void);
int report_check_failures(void);

/* Finishes: compares with the baseline if any, writes results.csv, runs
 * gnuplot (or says why plots were skipped), closes results.md.  Returns
 * the number of metrics flagged against the baseline. */
int report_close(void);

/* sysinfo.c: one-line descriptions for the header. */
void sysinfo_cpu(char *buf, size_t size);
int sysinfo_cores(void);
void sysinfo_date(char *buf, size_t size);
void sysinfo_compiler(char *buf, size_t size);
void sysinfo_commit(char *buf, size_t size);
/* The command line without any directory part of argv[0], and with
 * absolute paths shortened to ".../last-component", so a report never
 * carries a path of the machine it ran on. */
void sysinfo_command(char *buf, size_t size, int argc, char **argv);
int sysinfo_have_program(const char *name);
/* The three load averages of /proc/loadavg, or "unknown". */
const char *sysinfo_loadavg(void);

/* ------------------------------------------------------------ sections */

int bench_build_section(const struct bench_options *opts, struct bench_mesh *meshes,
                        int mesh_count);
int bench_trace_section(const struct bench_options *opts, struct bench_mesh *meshes,
                        int mesh_count);
int bench_dynamic_section(const struct bench_options *opts, struct bench_mesh *meshes,
                          int mesh_count);
/* `rtbench error` (bench_error.c): intersection error against time on
 * workloads of its own. */
int bench_error_section(const struct bench_options *opts);
/* `rtbench bart` (bench_bart.c): the BART scenes, Wald, Benthin and Slusallek (2003) sec. 5.
 * bench_bart_find_data returns 0 when the three scenes are readable under
 * the data folder opts selects (--bart-dir, $TRACELIST_BART_DIR, the build's
 * RT_BART_DIR), else -1 with the reason in why (no path in it). */
int bench_bart_find_data(const struct bench_options *opts, char *why, size_t why_size);
/* The BART data folder opts selects ("" when none is given) and in *source
 * what named it ("--bart-dir", "$TRACELIST_BART_DIR", "the build's
 * RT_BART_DIR"), for messages that must not print the path. */
const char *bench_bart_data_dir(const struct bench_options *opts, const char **source);
int bench_bart_section(const struct bench_options *opts);
int bench_immediate_section(const struct bench_options *opts);
/* `rtbench nested` (bench_nested.c): flattened against instanced nested
 * static hierarchies, and what flatten=auto chose. */
int bench_nested_section(const struct bench_options *opts);
#ifdef RT_HAVE_EMBREE
int bench_embree_section(const struct bench_options *opts, struct bench_mesh *meshes,
                         int mesh_count);
/* "3.13.5" etc., from the headers rtbench was compiled with. */
const char *bench_embree_version(void);
/* `rtbench packets`: an Embree MEDIUM scene over mesh (NULL on failure)
 * and kernels over it: rtcIntersect1/rtcOccluded1 in a loop, and
 * rtcIntersect8/rtcOccluded8 over groups of eight consecutive rays. */
void *bench_embree_packets_new(const struct bench_mesh *mesh);
void bench_embree_packets_release(void *ctx);
void bench_embree_kernel_closest1(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                                  struct bench_hit *hits);
void bench_embree_kernel_any1(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                              struct bench_hit *hits);
void bench_embree_kernel_closest8(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                                  struct bench_hit *hits);
void bench_embree_kernel_any8(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                              struct bench_hit *hits);
#endif
/* `rtbench packets` (bench_packets.c): our packet walks against the
 * single-ray walk (and Embree's packets) on coherent rays. */
int bench_packets_section(const struct bench_options *opts, struct bench_mesh *meshes,
                          int mesh_count);

#endif
