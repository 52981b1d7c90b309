/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_bart.c - `rtbench bart`: the BART scenes (Lext, Assarsson and
 * Moeller 2000: kitchen, robots, museum) played through the public API the
 * way Wald, Benthin and Slusallek (2003, sec. 5) played them
 * through OpenRT, with the paper's figures printed beside ours.
 *
 * The data is third-party and only read at run time, from --bart-dir, else
 * $TRACELIST_BART_DIR, else the build's RT_BART_DIR (the CMake cache
 * variable); no path of it is ever printed.  The AFF loader (lib/rtu/aff_*.c
 * and what it needs of rtu) is compiled into rtbench, which links the
 * static core only (bench/CMakeLists.txt).
 *
 * A frame is what demos/bart/bart.c does: projection = rtuAFFView,
 * modelview identity, rtuAFFLights, rtuDrawAFF, rtRenderFrame.  Its wall
 * time is split in three:
 *   describe  the calls before rtRenderFrame (for the museum this includes
 *             evaluating its animated triangles and rtUpdateVertices);
 *   update    RT_STAT_UPDATE_TIME + RT_STAT_TOPLEVEL_TIME: what
 *             rtRenderFrame spent bringing the structures up to date
 *             before tracing (changed objects, then the top level);
 *   render    the rest of rtRenderFrame: tracing and shading, and the lazy
 *             builds of objects that rays reach for the first time, which
 *             happen on the render threads while others trace
 *             (RT_STAT_BUILD_TIME is their time summed over threads, so it
 *             is reported beside the frame time, never subtracted from it).
 *
 * Measurements, in the order of the report:
 *  1. the scenes: objects by class, instances, triangles, load time, the
 *     first frame and its lazy builds;
 *  2. RT_STAT_TOPLEVEL_TIME over every frame of each animation (Wald, Benthin and Slusallek (2003)
 *     secs. 4.5, 5.2 and 5.4);
 *  3. the museum's unstructured update time per frame with RT_REBUILD and
 *     RT_REBUILD_MEDIAN (Wald, Benthin and Slusallek (2003) table 3);
 *  4. frames per second, eye light and Whitted, on contexts threads=1 and
 *     threads=2, over frames spread through each animation (Wald, Benthin and Slusallek (2003)
 *     tables 1, 2 and 4);
 *  5. the update strategies over the whole museum animation, with the
 *     SAH-cost ratio of the unstructured object's tree against a fresh
 *     sweep SAH build of the same frame (Wald, Ize and Parker (2008) fig. 3; the measure of
 *     `rtbench dynamic`), and a short robots run showing that rigid motion
 *     gives the strategies nothing to do;
 *  6. the two-level overhead: the same frames rendered through the
 *     instances and as one flattened static object (rtuBakeAFF), structures
 *     built before timing (Wald, Benthin and Slusallek (2003) sec. 6, "Total Overhead").
 *
 * Correctness checks (rtbench exits with status 3 when one fails): a
 * frame's image must be bit-identical on threads=1 and threads=2 (4) and
 * under every update strategy (5), as docs/frames.md promises; and after
 * an RT_REBUILD frame, RT_OBJECT_SAH_COST must equal the SAH cost the
 * harness measures on a fresh binned build of the same triangles, which
 * shows that both sides of the SAH ratio are measured alike.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <rt/rtu.h>

#include "base/mat4.h"
#include "base/timer.h"
#include "bench.h"
#include "rtu/aff_internal.h"

#ifndef RT_BART_DIR
#define RT_BART_DIR ""
#endif

/* Wald, Benthin and Slusallek (2003) sec. 5: "All examples are rendered at video resolution of
 * 640x480 pixels"; sec. 5.1: "a reflection depth of 3". */
#define BART_WIDTH 640
#define BART_HEIGHT 480
#define BART_RAY_DEPTH 3
#define BART_QUICK_WIDTH 80
#define BART_QUICK_HEIGHT 60
/* Timed frames of the fps and overhead tables, evenly spaced through the
 * animation after the untimed frame 0; runs capped to keep `rtbench bart`
 * near 15 minutes on two cores. */
#define BART_FPS_FRAMES 8
#define BART_FPS_FRAMES_QUICK 2
#define BART_OVERHEAD_FRAMES 4
#define BART_OVERHEAD_FRAMES_QUICK 1
#define BART_MAX_RUNS 3
/* Every frame of each animation, for the top level and the museum's
 * update times, which do not depend on the image size. */
#define BART_PLAY_WIDTH 160
#define BART_PLAY_HEIGHT 120
#define BART_PLAY_FRAMES_QUICK 6
/* Strategies over the museum: all 300 frames at a quarter of the pixels,
 * so that seven strategies fit twice in about four minutes. */
#define BART_STRATEGY_WIDTH 320
#define BART_STRATEGY_HEIGHT 240
#define BART_STRATEGY_RUNS 2
#define BART_STRATEGY_FRAMES_QUICK 6
#define BART_ROBOT_FRAMES 50
#define BART_ROBOT_FRAMES_QUICK 3
/* A strategy whose first run over the museum takes longer than this is
 * not repeated (as in bench_dynamic.c). */
#define BART_SLOW_RUN_MS 60000.0
/* Renders of one frame allowed before its structures must have settled
 * (nothing built or updated) in the overhead measurement. */
#define BART_SETTLE_TRIES 4
/* RT_OBJECT_SAH_COST is a float; the harness's cost a double. */
#define BART_SAH_TOLERANCE 1e-5

#define SHADINGS 2 /* 0 eye light, 1 Whitted */
#define THREAD_COUNTS 2
#define MAX_FRAMES 8 /* of the fps and overhead tables */
#define MAX_UNSTRUCTURED 16

static const char *const shading_label[SHADINGS] = {"eye light", "Whitted"};
static const char *const shading_key[SHADINGS] = {"eye", "whitted"};

/* The scenes and Wald, Benthin and Slusallek's (2003) figures for them.  The fps are for "2 CPUs",
 * i.e. one dual-CPU client (table 4's column "1"); the paper gives no
 * one-CPU figure. */
struct bart_scene_info {
    const char *name; /* table and csv key */
    const char *file; /* under the data folder */
    const char *paper_source;
    double paper_fps[SHADINGS];
    const char *paper_scene;    /* how Wald, Benthin and Slusallek (2003) describes it */
    const char *paper_toplevel; /* its top-level build time */
};

static const struct bart_scene_info scene_info[] = {
    {"kitchen",
     "kitchen/kitchen.aff",
     "table 1",
     {3.2, 0.47},
     "110,000 triangles in 5 objects",
     "negligible"},
    {"robots", "robots/Robot.aff", "table 2", {2.8, 0.54}, "16 robots, 161 objects", "< 1 ms"},
    {"museum",
     "museum/museum5.aff",
     "table 4, Museum/1k",
     {2.7, 0.6},
     "1k triangles in unstructured motion",
     "n/r"},
};
#define SCENES ((int)(sizeof(scene_info) / sizeof(scene_info[0])))
#define KITCHEN 0
#define ROBOTS 1
#define MUSEUM 2

/* Wald, Benthin and Slusallek (2003) sec. 5.1: rays per frame in the kitchen at reflection depth 3. */
#define PAPER_KITCHEN_RAYS 3867661.0

struct strategy {
    const char *label;
    const char *key;
    RTenum value;
};

static const struct strategy museum_strategies[] = {
    {"RT_REFIT", "refit", RT_REFIT},
    {"RT_REBUILD", "rebuild", RT_REBUILD},
    {"RT_REBUILD_MEDIAN", "median", RT_REBUILD_MEDIAN},
    {"RT_REBUILD_HEURISTIC", "heuristic", RT_REBUILD_HEURISTIC},
    {"RT_RESTRUCTURE", "restructure", RT_RESTRUCTURE},
    {"RT_ASYNC_REBUILD", "async", RT_ASYNC_REBUILD},
    {"RT_AUTOMATIC", "automatic", RT_AUTOMATIC},
};
#define MUSEUM_STRATEGIES ((int)(sizeof(museum_strategies) / sizeof(museum_strategies[0])))

static const struct strategy robot_strategies[] = {
    {"RT_REFIT", "refit", RT_REFIT},
    {"RT_REBUILD", "rebuild", RT_REBUILD},
    {"RT_AUTOMATIC", "automatic", RT_AUTOMATIC},
};
#define ROBOT_STRATEGIES ((int)(sizeof(robot_strategies) / sizeof(robot_strategies[0])))

/* ------------------------------------------------------------ data */

const char *bench_bart_data_dir(const struct bench_options *opts, const char **source)
{
    const char *env = getenv("TRACELIST_BART_DIR");
    if (opts->bart_dir) {
        *source = "--bart-dir";
        return opts->bart_dir;
    }
    if (env && env[0]) {
        *source = "$TRACELIST_BART_DIR";
        return env;
    }
    *source = "the build's RT_BART_DIR";
    return RT_BART_DIR;
}

int bench_bart_find_data(const struct bench_options *opts, char *why, size_t why_size)
{
    const char *source;
    const char *dir = bench_bart_data_dir(opts, &source);
    if (!dir[0]) {
        snprintf(why, why_size,
                 "no BART data folder given: set TRACELIST_BART_DIR to the folder holding "
                 "kitchen/, robots/ and museum/, or pass --bart-dir DIR");
        return -1;
    }
    for (int i = 0; i < SCENES; i++) {
        char path[4096];
        snprintf(path, sizeof(path), "%s/%s", dir, scene_info[i].file);
        FILE *f = fopen(path, "r");
        if (!f) {
            snprintf(why, why_size,
                     "the BART scenes are not in the folder named by %s (no %s there): set "
                     "TRACELIST_BART_DIR to the folder holding kitchen/, robots/ and museum/, "
                     "or pass --bart-dir DIR",
                     source, scene_info[i].file);
            return -1;
        }
        fclose(f);
    }
    return 0;
}

/* Prints a loader message with the data folder replaced by a name, so
 * that no path of the machine reaches the output. */
static void print_without_dir(const char *scene, const char *message, const char *dir)
{
    size_t n = strlen(dir);
    report_progress("rtbench: bart: %s: ", scene);
    for (const char *m = message; *m;) {
        if (n && strncmp(m, dir, n) == 0) {
            report_progress("<bart-dir>");
            m += n;
        } else {
            report_progress("%c", *m++);
        }
    }
    report_progress("\n");
}

/* ------------------------------------------------------------ a context */

/* One scene loaded into one context of its own. */
struct bart_ctx {
    const struct bart_scene_info *info;
    RTcontext ctx;
    RTUaffscene *aff;
    int threads; /* render threads, for the CPU share */
    int frames;
    double load_ms;
};

static void ctx_close(struct bart_ctx *c)
{
    if (c->ctx) {
        rtMakeCurrent(c->ctx);
        rtuDeleteAFF(c->aff);
        rtMakeCurrent(NULL);
        rtDestroyContext(c->ctx);
    }
    memset(c, 0, sizeof(*c));
}

static int ctx_open(struct bart_ctx *c, const char *dir, const struct bart_scene_info *info,
                    const char *config, int threads)
{
    char path[4096];
    memset(c, 0, sizeof(*c));
    c->info = info;
    c->threads = threads;
    snprintf(path, sizeof(path), "%s/%s", dir, info->file);
    c->ctx = bench_create_context(config);
    if (!c->ctx || !rtMakeCurrent(c->ctx)) {
        report_progress("rtbench: bart: cannot create a context \"%s\"\n", config);
        ctx_close(c);
        return -1;
    }
    /* --collapse optimal: the scenes' objects as an application asking
     * for the optimal collapse would define them. */
    if (bench_collapse() == BVH_COLLAPSE_OPTIMAL)
        rtHint(RT_ACCELERATION_HINT, RT_NICEST);
    double t0 = rt_now_ms();
    c->aff = rtuLoadAFF(path);
    c->load_ms = rt_now_ms() - t0;
    if (!c->aff) {
        print_without_dir(info->name, rtuAFFError(), dir);
        ctx_close(c);
        return -1;
    }
    rtuGetAFFiv(c->aff, RTU_AFF_FRAMES, &c->frames);
    if (c->frames < 1) {
        report_progress("rtbench: bart: %s has no frames\n", info->name);
        ctx_close(c);
        return -1;
    }
    return 0;
}

static void ctx_use(const struct bart_ctx *c)
{
    rtMakeCurrent(c->ctx);
}

/* Returns -1 (and says so) when the API recorded an error. */
static int ctx_check(const struct bart_ctx *c, const char *what)
{
    RTenum e = rtGetError();
    if (e == RT_NO_ERROR)
        return 0;
    report_progress("rtbench: bart: %s: %s: the API recorded error 0x%04x\n", c->info->name, what,
                    (unsigned)e);
    return -1;
}

/* The loader's objects of every class; returns how many (at most max). */
static int all_objects(const struct bart_ctx *c, RTuint *names, int max)
{
    static const RTenum kinds[3] = {RT_STATIC, RT_AFFINE, RT_UNSTRUCTURED};
    int n = 0;
    for (int k = 0; k < 3; k++) {
        RTsizei got = rtuAFFObjects(c->aff, kinds[k], (RTsizei)(max - n), names + n);
        n += got < (RTsizei)(max - n) ? (int)got : max - n;
    }
    return n;
}

/* ------------------------------------------------------------ one frame */

struct frame {
    double total_ms;    /* wall clock, describe + rtRenderFrame */
    double describe_ms; /* before rtRenderFrame */
    double call_ms;     /* rtRenderFrame */
    double update_ms;   /* RT_STAT_UPDATE_TIME + RT_STAT_TOPLEVEL_TIME */
    double render_ms;   /* call_ms - update_ms, lazy builds included */
    double toplevel_ms, build_ms, object_update_ms;
    double rays, node_tests, triangle_tests, instance_tests;
    double cpu_ms; /* process CPU time of describe + rtRenderFrame */
    int object_builds, toplevel_builds, object_updates;
};

static float get_f(RTenum pname)
{
    RTfloat v = 0.0f;
    rtGetFloatv(pname, &v);
    return v;
}

static int get_i(RTenum pname)
{
    RTint v = 0;
    rtGetIntegerv(pname, &v);
    return v;
}

static void set_shading(int whitted)
{
    rtShadingMode(whitted ? RT_WHITTED : RT_EYE_LIGHT);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, BART_RAY_DEPTH);
}

/* Describes frame f of the current context's scene, dynamically
 * (rtuDrawAFF) or as the flattened object `flat` when it is not 0, and
 * renders it at w x h. */
static void render_frame(const struct bart_ctx *c, int f, int w, int h, RTuint flat,
                         struct frame *out)
{
    double t = rtuAFFFrameTime(c->aff, f);
    double cpu0 = bench_cpu_ms(), t0 = rt_now_ms();
    rtViewport(0, 0, w, h);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtuAFFView(c->aff, t, (double)w / (double)h);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtuAFFLights(c->aff, t);
    if (flat)
        rtInstantiateObject(flat);
    else
        rtuDrawAFF(c->aff, t);
    double t1 = rt_now_ms();
    rtRenderFrame();
    double t2 = rt_now_ms();
    out->cpu_ms = bench_cpu_ms() - cpu0;
    bench_share_add(c->threads, t2 - t0, out->cpu_ms);
    out->total_ms = t2 - t0;
    out->describe_ms = t1 - t0;
    out->call_ms = t2 - t1;
    out->toplevel_ms = get_f(RT_STAT_TOPLEVEL_TIME);
    out->build_ms = get_f(RT_STAT_BUILD_TIME);
    out->object_update_ms = get_f(RT_STAT_UPDATE_TIME);
    out->update_ms = out->object_update_ms + out->toplevel_ms;
    out->render_ms = out->call_ms > out->update_ms ? out->call_ms - out->update_ms : 0.0;
    out->rays = get_f(RT_STAT_RAYS);
    out->node_tests = get_f(RT_STAT_NODE_TESTS);
    out->triangle_tests = get_f(RT_STAT_TRIANGLE_TESTS);
    out->instance_tests = get_f(RT_STAT_INSTANCE_TESTS);
    out->object_builds = get_i(RT_STAT_OBJECT_BUILDS);
    out->toplevel_builds = get_i(RT_STAT_TOPLEVEL_BUILDS);
    out->object_updates = get_i(RT_STAT_OBJECT_UPDATES);
}

/* FNV-1a over the framebuffer: images are compared by hash. */
static uint64_t image_hash(int w, int h, unsigned char *pixels)
{
    rtReadPixels(0, 0, w, h, RT_RGBA, RT_UNSIGNED_BYTE, pixels);
    uint64_t x = 14695981039346656037ull;
    for (size_t i = 0; i < (size_t)w * (size_t)h * 4; i++) {
        x ^= pixels[i];
        x *= 1099511628211ull;
    }
    return x;
}

/* Frame i of n spread evenly over frames 1 .. frames-1 (the last one
 * included): round((i + 1) (frames - 1) / n). */
static int spread_frame(int i, int n, int frames)
{
    return (int)floor((double)(i + 1) * (frames - 1) / n + 0.5);
}

static double max_of(const double *x, int n)
{
    double m = 0.0;
    for (int i = 0; i < n; i++)
        m = x[i] > m ? x[i] : m;
    return m;
}

static double mean_of(const double *x, int n)
{
    double s = 0.0;
    for (int i = 0; i < n; i++)
        s += x[i];
    return n ? s / n : 0.0;
}

/* The largest of n positive values over the smallest: 1 when the runs
 * agree; 0 when a value is not positive. */
static double spread_of(const double *x, int n)
{
    double lo = x[0], hi = x[0];
    for (int i = 1; i < n; i++) {
        lo = x[i] < lo ? x[i] : lo;
        hi = x[i] > hi ? x[i] : hi;
    }
    return lo > 0.0 ? hi / lo : 0.0;
}

/* ------------------------------------------------------------ results */

struct scene_result {
    /* 1. scene */
    RTint frames, static_objects, rigid_objects, unstructured_objects, instances, triangles,
        animated_triangles, lights, textures;
    double load_ms;     /* the threads=2 context's rtuLoadAFF */
    struct frame first; /* frame 0, eye light, threads=2, fresh context */
    int objects, built_after_first;
    /* 2. top level, frames 1 .. played */
    int played, toplevel_rebuilds;
    double toplevel_median, toplevel_max, describe_median;
    /* 4. fps: [shading][threads - 1] */
    int fps_frames, fps_runs;
    double fps[SHADINGS][THREAD_COUNTS];
    double describe_ms[SHADINGS][THREAD_COUNTS], update_ms[SHADINGS][THREAD_COUNTS],
        render_ms[SHADINGS][THREAD_COUNTS];
    double rays[SHADINGS];
    int image_mismatches[SHADINGS];
    /* 4, by the CPU clock: process CPU ms per frame (median over runs),
     * and each run's wall and CPU ms per frame, in run order */
    double cpu_ms[SHADINGS][THREAD_COUNTS];
    double run_wall_ms[SHADINGS][THREAD_COUNTS][BART_MAX_RUNS];
    double run_cpu_ms[SHADINGS][THREAD_COUNTS][BART_MAX_RUNS];
    /* 6. overhead: [shading][0 dynamic, 1 flat] */
    int overhead_frames, overhead_runs, unsettled;
    double overhead_ms[SHADINGS][2];
    double per_ray_nodes[SHADINGS][2], per_ray_tris[SHADINGS][2], per_ray_instances[SHADINGS][2];
    double overhead_rays[SHADINGS][2];
};

/* ------------------------------------------------------------ 1 and 4 */

/* Frame 0 on fresh contexts (the lazy builds), then, interleaved over
 * runs and thread counts, each shading over the spread frames, each
 * sequence starting from an untimed eye-light frame 0 so that every run
 * plays the same updates. */
static int fps_measure(const struct bench_options *opts, struct bart_ctx c[THREAD_COUNTS],
                       struct scene_result *r)
{
    const int w = opts->quick ? BART_QUICK_WIDTH : BART_WIDTH;
    const int h = opts->quick ? BART_QUICK_HEIGHT : BART_HEIGHT;
    const int n = opts->quick ? BART_FPS_FRAMES_QUICK : BART_FPS_FRAMES;
    const int runs = opts->runs < BART_MAX_RUNS ? opts->runs : BART_MAX_RUNS;
    int frames[MAX_FRAMES];
    uint64_t reference[SHADINGS][MAX_FRAMES];
    /* per [shading][threads][run]: sums over the timed frames */
    double total[SHADINGS][THREAD_COUNTS][BART_MAX_RUNS];
    double describe[SHADINGS][THREAD_COUNTS][BART_MAX_RUNS];
    double update[SHADINGS][THREAD_COUNTS][BART_MAX_RUNS];
    double render[SHADINGS][THREAD_COUNTS][BART_MAX_RUNS];
    double cpu[SHADINGS][THREAD_COUNTS][BART_MAX_RUNS];
    unsigned char *pixels = malloc((size_t)w * (size_t)h * 4);
    struct frame fr;
    if (!pixels)
        return -1;
    for (int i = 0; i < n; i++)
        frames[i] = spread_frame(i, n, c[0].frames);
    memset(r->image_mismatches, 0, sizeof(r->image_mismatches));
    memset(r->rays, 0, sizeof(r->rays));

    for (int k = 0; k < THREAD_COUNTS; k++) {
        ctx_use(&c[k]);
        set_shading(0);
        render_frame(&c[k], 0, w, h, 0, &fr);
        if (k == 1) {
            r->first = fr;
            RTuint names[1024];
            int count = all_objects(&c[k], names, 1024);
            r->objects = count;
            r->built_after_first = 0;
            for (int i = 0; i < count; i++) {
                RTint built = 0;
                rtGetObjectiv(names[i], RT_OBJECT_BUILT, &built);
                r->built_after_first += built == RT_TRUE;
            }
        }
    }
    for (int run = 0; run < runs; run++)
        for (int k = 0; k < THREAD_COUNTS; k++) {
            ctx_use(&c[k]);
            for (int s = 0; s < SHADINGS; s++) {
                report_progress("bart: %s: %s, threads=%d, run %d of %d\n", c[k].info->name,
                                shading_label[s], k + 1, run + 1, runs);
                set_shading(0); /* the restart is cheap in eye light */
                render_frame(&c[k], 0, w, h, 0, &fr);
                set_shading(s);
                total[s][k][run] = describe[s][k][run] = update[s][k][run] = render[s][k][run] =
                    cpu[s][k][run] = 0.0;
                for (int i = 0; i < n; i++) {
                    render_frame(&c[k], frames[i], w, h, 0, &fr);
                    total[s][k][run] += fr.total_ms;
                    describe[s][k][run] += fr.describe_ms;
                    update[s][k][run] += fr.update_ms;
                    render[s][k][run] += fr.render_ms;
                    cpu[s][k][run] += fr.cpu_ms;
                    if (run == 0 && k == 0)
                        r->rays[s] += fr.rays / n;
                    uint64_t hash = image_hash(w, h, pixels);
                    if (run == 0 && k == 0)
                        reference[s][i] = hash;
                    else if (hash != reference[s][i])
                        r->image_mismatches[s]++;
                }
            }
            if (ctx_check(&c[k], "frames per second"))
                goto fail;
        }
    for (int s = 0; s < SHADINGS; s++)
        for (int k = 0; k < THREAD_COUNTS; k++) {
            /* per run, before bench_median reorders the sums */
            for (int run = 0; run < runs; run++) {
                r->run_wall_ms[s][k][run] = total[s][k][run] / n;
                r->run_cpu_ms[s][k][run] = cpu[s][k][run] / n;
            }
            r->cpu_ms[s][k] = bench_median(cpu[s][k], runs) / n;
            double med = bench_median(total[s][k], runs);
            r->fps[s][k] = med > 0.0 ? 1e3 * n / med : 0.0;
            r->describe_ms[s][k] = bench_median(describe[s][k], runs) / n;
            r->update_ms[s][k] = bench_median(update[s][k], runs) / n;
            r->render_ms[s][k] = bench_median(render[s][k], runs) / n;
        }
    r->fps_frames = n;
    r->fps_runs = runs;
    free(pixels);
    return 0;
fail:
    free(pixels);
    return -1;
}

/* ------------------------------------------------------------ 2 */

static int toplevel_measure(const struct bench_options *opts, const struct bart_ctx *c,
                            struct scene_result *r)
{
    const int w = opts->quick ? BART_QUICK_WIDTH : BART_PLAY_WIDTH;
    const int h = opts->quick ? BART_QUICK_HEIGHT : BART_PLAY_HEIGHT;
    const int frames =
        opts->quick && c->frames > BART_PLAY_FRAMES_QUICK ? BART_PLAY_FRAMES_QUICK : c->frames;
    double *top = malloc(2 * (size_t)frames * sizeof(double));
    if (!top)
        return -1;
    double *describe = top + frames;
    int n = 0;
    struct frame fr;
    report_progress("bart: %s: top level, %d frames\n", c->info->name, frames);
    ctx_use(c);
    set_shading(0);
    r->toplevel_rebuilds = 0;
    for (int f = 0; f < frames; f++) {
        render_frame(c, f, w, h, 0, &fr);
        if (f == 0)
            continue; /* follows the fps table's last frame */
        top[n] = fr.toplevel_ms;
        describe[n] = fr.describe_ms;
        r->toplevel_rebuilds += fr.toplevel_builds;
        n++;
    }
    r->played = n;
    r->toplevel_max = max_of(top, n);
    r->toplevel_median = n ? bench_median(top, n) : 0.0;
    r->describe_median = n ? bench_median(describe, n) : 0.0;
    free(top);
    return ctx_check(c, "top level");
}

/* ------------------------------------------------------------ 6 */

/*
 * Renders frame f until a render builds and updates nothing, and returns
 * that render: the time of a frame whose structures were already built.
 * A new frame of the dynamic configuration always takes two renders (the
 * first rebuilds the top level), the flattened object two (the first
 * builds it); a second shading of the same frame is timed at once unless
 * its secondary rays reach an object not yet built.
 */
static int render_settled(const struct bart_ctx *c, int f, int w, int h, RTuint flat,
                          struct frame *out)
{
    for (int i = 0; i < BART_SETTLE_TRIES; i++) {
        render_frame(c, f, w, h, flat, out);
        if (out->object_builds == 0 && out->toplevel_builds == 0 && out->object_updates == 0)
            return 0;
    }
    return -1;
}

static int overhead_measure(const struct bench_options *opts, const struct bart_ctx *c,
                            struct scene_result *r)
{
    const int w = opts->quick ? BART_QUICK_WIDTH : BART_WIDTH;
    const int h = opts->quick ? BART_QUICK_HEIGHT : BART_HEIGHT;
    const int n = opts->quick ? BART_OVERHEAD_FRAMES_QUICK : BART_OVERHEAD_FRAMES;
    const int runs = opts->runs < BART_MAX_RUNS ? opts->runs : BART_MAX_RUNS;
    double ms[SHADINGS][2][BART_MAX_RUNS];
    double nodes[SHADINGS][2], tris[SHADINGS][2], instances[SHADINGS][2], rays[SHADINGS][2];
    struct frame fr;
    memset(ms, 0, sizeof(ms));
    memset(nodes, 0, sizeof(nodes));
    memset(tris, 0, sizeof(tris));
    memset(instances, 0, sizeof(instances));
    memset(rays, 0, sizeof(rays));
    r->unsettled = 0;
    ctx_use(c);
    for (int run = 0; run < runs; run++) {
        report_progress("bart: %s: overhead, run %d of %d\n", c->info->name, run + 1, runs);
        for (int i = 0; i < n; i++) {
            int f = spread_frame(i, n, c->frames);
            for (int flat = 0; flat < 2; flat++) {
                RTuint object = 0;
                if (flat) {
                    object = rtuBakeAFF(c->aff, rtuAFFFrameTime(c->aff, f));
                    if (!object) {
                        report_progress("rtbench: bart: %s: rtuBakeAFF failed\n", c->info->name);
                        return -1;
                    }
                }
                for (int s = 0; s < SHADINGS; s++) {
                    set_shading(s);
                    r->unsettled += render_settled(c, f, w, h, object, &fr) != 0;
                    ms[s][flat][run] += fr.call_ms;
                    if (run == 0) {
                        nodes[s][flat] += fr.node_tests;
                        tris[s][flat] += fr.triangle_tests;
                        instances[s][flat] += fr.instance_tests;
                        rays[s][flat] += fr.rays;
                    }
                }
                if (object)
                    rtDeleteObjects(1, &object);
            }
        }
        if (ctx_check(c, "overhead"))
            return -1;
    }
    for (int s = 0; s < SHADINGS; s++)
        for (int flat = 0; flat < 2; flat++) {
            double rr = rays[s][flat] > 0.0 ? rays[s][flat] : 1.0;
            r->overhead_ms[s][flat] = bench_median(ms[s][flat], runs) / n;
            r->per_ray_nodes[s][flat] = nodes[s][flat] / rr;
            r->per_ray_tris[s][flat] = tris[s][flat] / rr;
            r->per_ray_instances[s][flat] = instances[s][flat] / rr;
            r->overhead_rays[s][flat] = rays[s][flat] / n;
        }
    r->overhead_frames = n;
    r->overhead_runs = runs;
    return 0;
}

/* ------------------------------------------------------------ 3 */

struct museum_update {
    double median, mean, max; /* RT_OBJECT_UPDATE_TIME, ms */
    double stat_median;       /* RT_STAT_UPDATE_TIME, ms */
    int frames;
};

static int unstructured_names(const struct bart_ctx *c, RTuint *names)
{
    RTsizei n = rtuAFFObjects(c->aff, RT_UNSTRUCTURED, MAX_UNSTRUCTURED, names);
    return n < MAX_UNSTRUCTURED ? (int)n : MAX_UNSTRUCTURED;
}

static int museum_update_measure(const struct bench_options *opts, const char *dir,
                                 struct museum_update out[2])
{
    static const RTenum rebuilds[2] = {RT_REBUILD, RT_REBUILD_MEDIAN};
    const int w = opts->quick ? BART_QUICK_WIDTH : BART_PLAY_WIDTH;
    const int h = opts->quick ? BART_QUICK_HEIGHT : BART_PLAY_HEIGHT;
    for (int k = 0; k < 2; k++) {
        struct bart_ctx c;
        RTuint names[MAX_UNSTRUCTURED];
        if (ctx_open(&c, dir, &scene_info[MUSEUM], "threads=2", 2))
            return -1;
        const int frames =
            opts->quick && c.frames > BART_PLAY_FRAMES_QUICK ? BART_PLAY_FRAMES_QUICK : c.frames;
        report_progress("bart: museum: %s, %d frames\n", museum_strategies[k + 1].label, frames);
        double *obj = malloc(2 * (size_t)frames * sizeof(double));
        if (!obj) {
            ctx_close(&c);
            return -1;
        }
        double *stat = obj + frames;
        int un = unstructured_names(&c, names);
        for (int i = 0; i < un; i++)
            rtObjectParameteri(names[i], RT_UPDATE_STRATEGY, (RTint)rebuilds[k]);
        set_shading(0);
        int n = 0;
        for (int f = 0; f < frames; f++) {
            struct frame fr;
            render_frame(&c, f, w, h, 0, &fr);
            if (f == 0)
                continue; /* the first build, not an update */
            obj[n] = 0.0;
            for (int i = 0; i < un; i++) {
                RTfloat v = 0.0f;
                rtGetObjectfv(names[i], RT_OBJECT_UPDATE_TIME, &v);
                obj[n] += v;
            }
            stat[n] = fr.object_update_ms;
            n++;
        }
        int rc = ctx_check(&c, "unstructured update");
        out[k].frames = n;
        out[k].mean = mean_of(obj, n);
        out[k].max = max_of(obj, n);
        out[k].median = n ? bench_median(obj, n) : 0.0;
        out[k].stat_median = n ? bench_median(stat, n) : 0.0;
        free(obj);
        ctx_close(&c);
        if (rc)
            return -1;
    }
    return 0;
}

/* ------------------------------------------------------------ 5: museum */

/* The unstructured object's triangles at any frame, from the parsed
 * scene (aff_scene_data): the first frame group with animated triangles,
 * which is the object rtuAFFObjects(RT_UNSTRUCTURED) names first.  The
 * loader records them under the identity, so these are object-space
 * positions, vertex 3i + j of triangle i, as the object holds them. */
struct tpa_mesh {
    const struct aff_group *group;
    struct bench_mesh mesh;
};

static int tpa_mesh_init(struct tpa_mesh *m, const RTUaffscene *aff)
{
    const struct aff_data *d = aff_scene_data(aff);
    memset(m, 0, sizeof(*m));
    for (int f = 0; d && f < d->frame_count_nodes && !m->group; f++)
        if (d->frames[f].group.tpa_count)
            m->group = &d->frames[f].group;
    if (!m->group)
        return -1;
    uint32_t n = m->group->tpa_count;
    m->mesh.name = "tpa";
    m->mesh.tri_count = n;
    m->mesh.vertex_count = 3 * n;
    m->mesh.positions = malloc((size_t)9 * n * sizeof(float));
    m->mesh.indices = malloc((size_t)3 * n * sizeof(uint32_t));
    if (!m->mesh.positions || !m->mesh.indices)
        return -1;
    for (uint32_t i = 0; i < 3 * n; i++)
        m->mesh.indices[i] = i;
    return 0;
}

static void tpa_mesh_eval(struct tpa_mesh *m, double t)
{
    float normals[9];
    for (uint32_t i = 0; i < m->group->tpa_count; i++)
        aff_tpa_eval(m->group->tpas[i].keys, m->group->tpas[i].key_count, t,
                     &m->mesh.positions[9 * i], normals);
}

static void tpa_mesh_release(struct tpa_mesh *m)
{
    free(m->mesh.positions);
    free(m->mesh.indices);
    memset(m, 0, sizeof(*m));
}

/* One run of one strategy over the museum; per-frame arrays. */
struct museum_series {
    double *frame_ms, *update_ms, *sah_ratio;
    double *cpu_ms, *tests; /* process CPU time; node + triangle tests */
    int rebuilds, refits;
};

struct museum_setup {
    const char *dir;
    int frames, w, h;
    const double *sweep_sah, *binned_sah; /* per frame */
    uint64_t *reference;                  /* per frame: the first strategy's image */
    unsigned char *pixels;
    int image_mismatches[MUSEUM_STRATEGIES];
    int sah_mismatches; /* RT_REBUILD frames whose cost differs from the harness's */
    int has_reference;  /* reference[] holds the first strategy's images */
    const char *config;  /* the strategy contexts' configuration */
    int threads;
    FILE *decisions;     /* per-frame log of the first run, or NULL */
};

/* One line of the per-frame decision log (bart_museum_decisions.dat):
 * what the update of the unstructured object did and the inputs of
 * RT_AUTOMATIC's rule (lib/scene/update.c), read through the context as
 * rtbench may (it links the static core). */
static void log_decision(FILE *log, const char *key, int f, RTuint name, const struct frame *fr,
                         double sah_ratio)
{
    struct bench_automatic_state a;
    if (bench_automatic_state(name, &a))
        return;
    fprintf(log, "%s %d %d %.4f %.0f %.0f %.3f %.4f %.3g %.0f %.4f %.4f %.4f %.4f\n", key, f,
            a.rebuilds, sah_ratio, fr->rays, fr->node_tests + fr->triangle_tests, fr->cpu_ms,
            fr->update_ms, a.ms_per_test, a.expected_rays, a.lost_ms, a.build_ms, a.sah_cost,
            a.built_sah_cost);
}

static int museum_run(struct museum_setup *m, int si, int first, struct museum_series *out)
{
    struct bart_ctx c;
    RTuint names[MAX_UNSTRUCTURED];
    if (ctx_open(&c, m->dir, &scene_info[MUSEUM], m->config, m->threads))
        return -1;
    int un = unstructured_names(&c, names);
    if (un < 1) {
        report_progress("rtbench: bart: museum: no unstructured object\n");
        ctx_close(&c);
        return -1;
    }
    for (int i = 0; i < un; i++)
        rtObjectParameteri(names[i], RT_UPDATE_STRATEGY, (RTint)museum_strategies[si].value);
    set_shading(0);
    for (int f = 0; f < m->frames; f++) {
        struct frame fr;
        render_frame(&c, f, m->w, m->h, 0, &fr);
        out->frame_ms[f] = fr.total_ms;
        out->update_ms[f] = fr.update_ms;
        out->cpu_ms[f] = fr.cpu_ms;
        out->tests[f] = fr.node_tests + fr.triangle_tests;
        RTfloat sah = 0.0f;
        rtGetObjectfv(names[0], RT_OBJECT_SAH_COST, &sah);
        out->sah_ratio[f] = m->sweep_sah[f] > 0.0 ? sah / m->sweep_sah[f] : 0.0;
        if (m->decisions)
            log_decision(m->decisions, museum_strategies[si].key, f, names[0], &fr,
                         out->sah_ratio[f]);
        if (museum_strategies[si].value == RT_REBUILD &&
            fabs(sah - m->binned_sah[f]) > BART_SAH_TOLERANCE * m->binned_sah[f])
            m->sah_mismatches++;
        uint64_t hash = image_hash(m->w, m->h, m->pixels);
        if (first)
            m->reference[f] = hash;
        else if (hash != m->reference[f])
            m->image_mismatches[si]++;
    }
    RTint rebuilds = 0, refits = 0;
    rtGetObjectiv(names[0], RT_OBJECT_REBUILDS, &rebuilds);
    rtGetObjectiv(names[0], RT_OBJECT_REFITS, &refits);
    out->rebuilds = rebuilds;
    out->refits = refits;
    int rc = ctx_check(&c, museum_strategies[si].label);
    ctx_close(&c);
    return rc;
}

static double sum_of(const double *x, int n)
{
    double s = 0.0;
    for (int i = 0; i < n; i++)
        s += x[i];
    return s;
}

static int museum_strategies_table(const struct bench_options *opts, const char *dir)
{
    const int runs = opts->runs < BART_STRATEGY_RUNS ? opts->runs : BART_STRATEGY_RUNS;
    struct museum_setup m;
    struct tpa_mesh tpa;
    struct bart_ctx probe;
    double *buf = NULL, *ref = NULL;
    FILE *decisions = NULL;
    int done[MUSEUM_STRATEGIES], rebuilds[MUSEUM_STRATEGIES], refits[MUSEUM_STRATEGIES];
    int rc = -1;
    memset(&m, 0, sizeof(m));
    memset(&tpa, 0, sizeof(tpa));
    memset(done, 0, sizeof(done));
    m.dir = dir;
    /* --threads N: the strategies' contexts on N render threads (one
     * build thread for RT_ASYNC_REBUILD either way). */
    char config[64];
    m.threads = opts->threads > 0 ? opts->threads : 2;
    snprintf(config, sizeof(config), "threads=%d build_threads=1", m.threads);
    m.config = config;
    m.w = opts->quick ? BART_QUICK_WIDTH : BART_STRATEGY_WIDTH;
    m.h = opts->quick ? BART_QUICK_HEIGHT : BART_STRATEGY_HEIGHT;

    /* The reference costs of every frame, from a context of its own. */
    if (ctx_open(&probe, dir, &scene_info[MUSEUM], "threads=1", 1))
        return -1;
    m.frames = opts->quick && probe.frames > BART_STRATEGY_FRAMES_QUICK ? BART_STRATEGY_FRAMES_QUICK
                                                                        : probe.frames;
    const int frames = m.frames;
    const size_t per = (size_t)MUSEUM_STRATEGIES * runs * frames;
    buf = calloc(5 * per, sizeof(double));
    ref = malloc(2 * (size_t)frames * sizeof(double));
    m.reference = malloc((size_t)frames * sizeof(uint64_t));
    m.pixels = malloc((size_t)m.w * (size_t)m.h * 4);
    if (!buf || !ref || !m.reference || !m.pixels || tpa_mesh_init(&tpa, probe.aff)) {
        ctx_close(&probe);
        goto out;
    }
    report_progress("bart: museum: sweep SAH reference, %d frames\n", frames);
    for (int f = 0; f < frames; f++) {
        tpa_mesh_eval(&tpa, rtuAFFFrameTime(probe.aff, f));
        ref[f] = bench_fresh_sah(&tpa.mesh, BVH_BUILDER_SWEEP_SAH, NULL);
        ref[frames + f] = bench_fresh_sah(&tpa.mesh, BVH_BUILDER_BINNED_SAH, NULL);
        if (ref[f] < 0.0 || ref[frames + f] < 0.0) {
            ctx_close(&probe);
            goto out;
        }
    }
    const uint32_t tpa_triangles = tpa.mesh.tri_count;
    ctx_close(&probe);
    m.sweep_sah = ref;
    m.binned_sah = ref + frames;

    decisions = report_data_file("bart_museum_decisions.dat");
    if (decisions)
        fprintf(decisions, "# strategy frame rebuilds sah_ratio rays tests cpu_ms update_ms "
                           "ms_per_test expected_rays lost_ms build_ms sah built_sah\n");
    for (int run = 0; run < runs; run++)
        for (int si = 0; si < MUSEUM_STRATEGIES; si++) {
            size_t o = ((size_t)si * runs + run) * frames;
            struct museum_series series = {buf + o,           buf + per + o,
                                           buf + 2 * per + o, buf + 3 * per + o,
                                           buf + 4 * per + o, 0,
                                           0};
            if (run > 0 && sum_of(buf + (size_t)si * runs * frames, frames) > BART_SLOW_RUN_MS)
                continue;
            if (opts->only && !bench_strategy_selected(opts->only, museum_strategies[si].key))
                continue;
            report_progress("bart: museum: %s, run %d of %d\n", museum_strategies[si].label,
                            run + 1, runs);
            m.decisions = run == 0 ? decisions : NULL;
            if (museum_run(&m, si, run == 0 && !m.has_reference, &series))
                goto out;
            m.has_reference = 1;
            rebuilds[si] = series.rebuilds;
            refits[si] = series.refits;
            done[si] = run + 1;
        }

    /* Per-frame medians over runs for the plots, medians of run totals for
     * the table (as in bench_dynamic.c). */
    FILE *data = report_data_file("bart_museum.dat");
    if (data) {
        fprintf(data, "# frame, then per strategy: frame ms, SAH ratio (medians over runs)\n");
        for (int f = 0; f < frames; f++) {
            fprintf(data, "%d", f);
            for (int si = 0; si < MUSEUM_STRATEGIES; si++)
                for (int k = 0; k < 2; k++) {
                    double col[BART_STRATEGY_RUNS];
                    for (int run = 0; run < done[si]; run++)
                        col[run] = buf[(size_t)k * 2 * per + ((size_t)si * runs + run) * frames +
                                       (size_t)f];
                    fprintf(data, " %.4f", bench_median(col, done[si]));
                }
            fprintf(data, "\n");
        }
        fclose(data);
    }
    report_printf("\n### Update strategies over the museum animation (Wald, Ize and Parker (2008) fig. 3)\n\n");
    report_printf(
        "All %d frames of the museum, consecutive, eye light at %dx%d (a quarter of the "
        "paper's pixels, so that the seven strategies fit in the run time), on a context `%s`; "
        "the unstructured object (%u animated triangles) gets the strategy with "
        "rtObjectParameteri, the static museum is built once. Frame = describe + update + render "
        "(wall clock); \"update\": RT_STAT_UPDATE_TIME + RT_STAT_TOPLEVEL_TIME, before tracing; "
        "\"render\": the rest (frame 0's lazy builds included, the same for all). Totals over "
        "the frames, median of %d interleaved run%s (a strategy whose first run took over "
        "%.0f s is not repeated). SAH ratio: RT_OBJECT_SAH_COST of the unstructured object "
        "after each frame / SAH cost of a fresh sweep SAH build of that frame's triangles "
        "(the measure of `rtbench dynamic`; mean and max over frames and runs). Rebuilds and "
        "refits: RT_OBJECT_REBUILDS and RT_OBJECT_REFITS at the end (the first build "
        "included). Images: every frame's image against RT_REFIT's, bit for bit. Wald, Ize and Parker (2008) "
        "fig. 3 has no museum; its point, that refitting alone degrades under unstructured "
        "motion, is what the SAH column tests.\n\n",
        frames, m.w, m.h, m.config, tpa_triangles, runs, runs == 1 ? "" : "s",
        BART_SLOW_RUN_MS / 1000.0);
    report_printf("CPU ms: the process's CPU time over the same frames (median of the run "
                  "totals; it does not count the time other processes took from us, so it is "
                  "the figure to compare on a loaded machine, and \"CPU vs best\" compares it). "
                  "Mtests: node + triangle tests over the frames, millions (RT_STAT_NODE_TESTS + "
                  "RT_STAT_TRIANGLE_TESTS): the traversal work, independent of the load.\n\n");
    report_table_header("strategy|update ms|render ms|total ms|ms/frame|vs best|CPU ms|CPU vs "
                        "best|Mtests|median update "
                        "ms/frame|mean SAH ratio|max SAH ratio|rebuilds|refits|runs|images "
                        "= RT_REFIT's");
    double total[MUSEUM_STRATEGIES], update[MUSEUM_STRATEGIES], describe_render[MUSEUM_STRATEGIES];
    double median_update[MUSEUM_STRATEGIES], mean_sah[MUSEUM_STRATEGIES],
        max_sah[MUSEUM_STRATEGIES], cpu[MUSEUM_STRATEGIES], tests[MUSEUM_STRATEGIES];
    int best_cpu;
    double *col = malloc((size_t)frames * BART_STRATEGY_RUNS * sizeof(double));
    if (!col)
        goto out;
    int best = -1;
    best_cpu = -1;
    for (int si = 0; si < MUSEUM_STRATEGIES; si++) {
        if (!done[si])
            continue;
        double t[BART_STRATEGY_RUNS], u[BART_STRATEGY_RUNS], cp[BART_STRATEGY_RUNS],
            ts[BART_STRATEGY_RUNS];
        double ms = 0.0, mx = 0.0;
        int nu = 0;
        for (int run = 0; run < done[si]; run++) {
            size_t o = ((size_t)si * runs + run) * frames;
            t[run] = sum_of(buf + o, frames);
            u[run] = sum_of(buf + per + o, frames);
            cp[run] = sum_of(buf + 3 * per + o, frames);
            ts[run] = sum_of(buf + 4 * per + o, frames);
            for (int f = 0; f < frames; f++) {
                double r = buf[2 * per + o + (size_t)f];
                ms += r;
                mx = r > mx ? r : mx;
                if (f > 0)
                    col[nu++] = buf[per + o + (size_t)f];
            }
        }
        total[si] = bench_median(t, done[si]);
        update[si] = bench_median(u, done[si]);
        describe_render[si] = total[si] - update[si];
        median_update[si] = nu ? bench_median(col, nu) : 0.0;
        mean_sah[si] = ms / ((double)done[si] * frames);
        max_sah[si] = mx;
        cpu[si] = bench_median(cp, done[si]);
        tests[si] = bench_median(ts, done[si]);
        if (best < 0 || total[si] < total[best])
            best = si;
        if (museum_strategies[si].value != RT_AUTOMATIC &&
            (best_cpu < 0 || cpu[si] < cpu[best_cpu]))
            best_cpu = si;
    }
    free(col);
    for (int si = 0; si < MUSEUM_STRATEGIES; si++) {
        if (!done[si])
            continue;
        report_row("%s|%.1f|%.1f|%.1f|%.2f|%+.1f%%|%.1f|%+.1f%%|%.2f|%.3f|%.3f|%.3f|%d|%d|%d|%s",
                   museum_strategies[si].label, update[si], describe_render[si], total[si],
                   total[si] / frames, 100.0 * (total[si] / total[best] - 1.0), cpu[si],
                   100.0 * (cpu[si] / cpu[best_cpu] - 1.0), tests[si] / 1e6, median_update[si],
                   mean_sah[si], max_sah[si], rebuilds[si], refits[si], done[si],
                   m.image_mismatches[si] ? "**NO**" : "yes");
        char key[96];
        snprintf(key, sizeof(key), "bart.museum.%s.total_ms", museum_strategies[si].key);
        report_metric(key, total[si], 0);
        snprintf(key, sizeof(key), "bart.museum.%s.cpu_ms", museum_strategies[si].key);
        report_metric(key, cpu[si], 0);
        snprintf(key, sizeof(key), "bart.museum.%s.mtests", museum_strategies[si].key);
        report_metric(key, tests[si] / 1e6, 0);
        snprintf(key, sizeof(key), "bart.museum.%s.mean_sah_ratio", museum_strategies[si].key);
        report_metric(key, mean_sah[si], -1);
        if (m.image_mismatches[si]) {
            report_progress("rtbench: bart: museum: %s: %d frame images differ from "
                            "RT_REFIT's\n",
                            museum_strategies[si].label, m.image_mismatches[si]);
            report_check_failed();
        }
    }
    for (int si = 0; si < MUSEUM_STRATEGIES; si++)
        if (museum_strategies[si].value == RT_AUTOMATIC && done[si] && best_cpu >= 0)
            report_printf("\nBest fixed strategy by CPU time: %s (%.1f ms). RT_AUTOMATIC: %.1f "
                          "ms, %s of it (%+.1f%%); node + triangle tests %+.1f%% against it.\n",
                          museum_strategies[best_cpu].label, cpu[best_cpu], cpu[si],
                          cpu[si] <= 1.1 * cpu[best_cpu] ? "within 10%" : "NOT within 10%",
                          100.0 * (cpu[si] / cpu[best_cpu] - 1.0),
                          100.0 * (tests[si] / tests[best_cpu] - 1.0));
    report_printf("\n(\"render\" here is describe + render: everything but the update.) "
                  "RT_OBJECT_SAH_COST after each RT_REBUILD frame against the harness's SAH "
                  "cost of a fresh binned build of the same triangles: %s.\n",
                  m.sah_mismatches ? "**DIFFERENT**" : "equal on every frame");
    if (m.sah_mismatches) {
        report_progress("rtbench: bart: museum: RT_OBJECT_SAH_COST differs from the harness's "
                        "measure on %d RT_REBUILD frames\n",
                        m.sah_mismatches);
        report_check_failed();
    }
    const char *labels[MUSEUM_STRATEGIES];
    int has_sah[MUSEUM_STRATEGIES];
    for (int si = 0; si < MUSEUM_STRATEGIES; si++) {
        labels[si] = museum_strategies[si].label;
        has_sah[si] = 1;
    }
    char time_title[160], sah_title[160];
    snprintf(time_title, sizeof(time_title),
             "BART museum: describe + update + render per frame (%dx%d, eye light, %d threads)", m.w,
             m.h, m.threads);
    snprintf(sah_title, sizeof(sah_title),
             "BART museum: SAH cost of the unstructured object / fresh sweep SAH build");
    report_strategy_plots("bart_museum", "bart_museum.dat", time_title, sah_title,
                          MUSEUM_STRATEGIES, labels, has_sah);
    rc = 0;
out:
    if (decisions)
        fclose(decisions);
    free(buf);
    free(ref);
    free(m.reference);
    free(m.pixels);
    tpa_mesh_release(&tpa);
    return rc;
}

/* ------------------------------------------------------------ 5: robots */

static int robots_strategies_table(const struct bench_options *opts, const char *dir)
{
    const int w = opts->quick ? BART_QUICK_WIDTH : BART_STRATEGY_WIDTH;
    const int h = opts->quick ? BART_QUICK_HEIGHT : BART_STRATEGY_HEIGHT;
    uint64_t *reference = NULL;
    unsigned char *pixels = malloc((size_t)w * (size_t)h * 4);
    int frames = 0, rc = -1;
    if (!pixels)
        return -1;
    frames = opts->quick ? BART_ROBOT_FRAMES_QUICK : BART_ROBOT_FRAMES;
    reference = malloc((size_t)frames * sizeof(uint64_t));
    if (!reference)
        goto out;
    report_printf("\n#### Robots: rigid motion only\n\n");
    report_printf("Frames 0..%d, consecutive, eye light at %dx%d on a context `threads=2`, "
                  "under %d strategies set as the context's default "
                  "(rtRenderParameteri(RT_UPDATE_STRATEGY)); one run each: the point is the "
                  "counts, not the times. The robots move only under animated transforms, so "
                  "every object is static or RT_AFFINE: no object is ever updated, only the "
                  "top level is rebuilt. Rebuilds: RT_OBJECT_REBUILDS summed over all objects "
                  "(each object built once, lazily, when first seen); refits likewise.\n\n",
                  frames - 1, w, h, ROBOT_STRATEGIES);
    report_table_header("strategy|frames|total ms|RT_STAT_UPDATE_TIME ms|RT_STAT_OBJECT_UPDATES|"
                        "top level ms|objects|rebuilds|refits|images = RT_REFIT's");
    for (int si = 0; si < ROBOT_STRATEGIES; si++) {
        struct bart_ctx c;
        RTuint names[1024];
        if (ctx_open(&c, dir, &scene_info[ROBOTS], "threads=2", 2))
            goto out;
        if (frames > c.frames)
            frames = c.frames;
        report_progress("bart: robots: %s, %d frames\n", robot_strategies[si].label, frames);
        rtRenderParameteri(RT_UPDATE_STRATEGY, (RTint)robot_strategies[si].value);
        set_shading(0);
        double total = 0.0, update = 0.0, top = 0.0;
        int updates = 0, mismatches = 0;
        for (int f = 0; f < frames; f++) {
            struct frame fr;
            render_frame(&c, f, w, h, 0, &fr);
            total += fr.total_ms;
            update += fr.object_update_ms;
            top += fr.toplevel_ms;
            updates += fr.object_updates;
            uint64_t hash = image_hash(w, h, pixels);
            if (si == 0)
                reference[f] = hash;
            else
                mismatches += hash != reference[f];
        }
        int count = all_objects(&c, names, 1024);
        long rebuilds = 0, refits = 0;
        for (int i = 0; i < count; i++) {
            RTint v = 0;
            rtGetObjectiv(names[i], RT_OBJECT_REBUILDS, &v);
            rebuilds += v;
            rtGetObjectiv(names[i], RT_OBJECT_REFITS, &v);
            refits += v;
        }
        int bad = ctx_check(&c, robot_strategies[si].label);
        ctx_close(&c);
        if (bad)
            goto out;
        report_row("%s|%d|%.1f|%.3f|%d|%.2f|%d|%ld|%ld|%s", robot_strategies[si].label, frames,
                   total, update, updates, top, count, rebuilds, refits,
                   mismatches ? "**NO**" : "yes");
        char key[96];
        snprintf(key, sizeof(key), "bart.robots.%s.total_ms", robot_strategies[si].key);
        report_metric(key, total, 0);
        if (mismatches) {
            report_progress("rtbench: bart: robots: %s: %d frame images differ from "
                            "RT_REFIT's\n",
                            robot_strategies[si].label, mismatches);
            report_check_failed();
        }
    }
    rc = 0;
out:
    free(reference);
    free(pixels);
    return rc;
}

/* ------------------------------------------------------------ report */

static void paper_fps(char *buf, size_t size, double fps)
{
    snprintf(buf, size, "%.2f", fps);
}

static void print_tables(const struct bench_options *opts, struct scene_result *res,
                         const struct museum_update mu[2])
{
    const int w = opts->quick ? BART_QUICK_WIDTH : BART_WIDTH;
    const int h = opts->quick ? BART_QUICK_HEIGHT : BART_HEIGHT;
    char key[96];

    report_printf("\n### Scenes\n\n");
    report_printf("Objects as rtuLoadAFF records them (Wald, Benthin and Slusallek (2003) sec. 4.1's grouping: one "
                  "static object, one object per animated transform that owns geometry, one "
                  "unstructured object of the animated triangles); instances per frame; "
                  "triangles as instantiated (animated ones in brackets). Load: rtuLoadAFF "
                  "(parse, textures, recording; no build: builds are lazy). First frame: frame "
                  "0, eye light, %dx%d, context `threads=2`, wall clock; its lazy builds: "
                  "RT_STAT_BUILD_TIME (summed over the threads that built, while others "
                  "traced) and the objects built after it (RT_OBJECT_BUILT), only those its "
                  "rays reached.\n\n",
                  w, h);
    report_table_header("scene|frames|static / rigid / unstructured objects|instances|"
                        "triangles|lights|textures|load ms|first frame ms|lazy builds ms|"
                        "objects built|Wald, Benthin and Slusallek (2003)");
    for (int i = 0; i < SCENES; i++) {
        const struct scene_result *r = &res[i];
        report_row("%s|%d|%d / %d / %d|%d|%d (%d)|%d|%d|%.1f|%.1f|%.1f|%d of %d|%s",
                   scene_info[i].name, r->frames, r->static_objects, r->rigid_objects,
                   r->unstructured_objects, r->instances, r->triangles, r->animated_triangles,
                   r->lights, r->textures, r->load_ms, r->first.total_ms, r->first.build_ms,
                   r->built_after_first, r->objects, scene_info[i].paper_scene);
        snprintf(key, sizeof(key), "bart.%s.load_ms", scene_info[i].name);
        report_metric(key, r->load_ms, 0);
        snprintf(key, sizeof(key), "bart.%s.first_frame_ms", scene_info[i].name);
        report_metric(key, r->first.total_ms, 0);
        snprintf(key, sizeof(key), "bart.%s.first_build_ms", scene_info[i].name);
        report_metric(key, r->first.build_ms, 0);
    }

    report_printf("\n### Top-level update per frame (Wald, Benthin and Slusallek (2003) secs. 4.5 and 5.2)\n\n");
    report_printf("Every frame of each animation in order (frames 1..N-1 counted), eye light "
                  "at %dx%d, context `threads=2`, one pass: RT_STAT_TOPLEVEL_TIME (the "
                  "top-level build over the instance boxes; near 0 when the instance list did "
                  "not change), its median and maximum; frames whose top level was rebuilt "
                  "(RT_STAT_TOPLEVEL_BUILDS); and the median time to describe a frame "
                  "(rtuAFFView, rtuAFFLights, rtuDrawAFF: issuing the instances, and for the "
                  "museum evaluating and sending its animated triangles). Wald, Benthin and Slusallek (2003): under "
                  "1 ms for the robots' 161 objects, up to 4 ms for its Terrain scene's 661 "
                  "instances (not BART).\n\n",
                  opts->quick ? BART_QUICK_WIDTH : BART_PLAY_WIDTH,
                  opts->quick ? BART_QUICK_HEIGHT : BART_PLAY_HEIGHT);
    report_table_header("scene|instances|frames|top level median ms|top level max ms|"
                        "rebuilt in frames|describe median ms|Wald, Benthin and Slusallek (2003)");
    for (int i = 0; i < SCENES; i++) {
        const struct scene_result *r = &res[i];
        report_row("%s|%d|%d|%.3f|%.3f|%d|%.3f|%s", scene_info[i].name, r->instances, r->played,
                   r->toplevel_median, r->toplevel_max, r->toplevel_rebuilds, r->describe_median,
                   scene_info[i].paper_toplevel);
        snprintf(key, sizeof(key), "bart.%s.toplevel_median_ms", scene_info[i].name);
        report_metric(key, r->toplevel_median, 0);
        snprintf(key, sizeof(key), "bart.%s.toplevel_max_ms", scene_info[i].name);
        report_metric(key, r->toplevel_max, -1);
    }

    report_printf("\n### Museum: unstructured update per frame (Wald, Benthin and Slusallek (2003) table 3)\n\n");
    report_printf("The museum's unstructured object (%d animated triangles) with the strategy "
                  "hint RT_REBUILD (binned SAH) or RT_REBUILD_MEDIAN (spatial median), every "
                  "frame in order at %dx%d, eye light, context `threads=2` (at this size the "
                  "build runs on the calling thread); RT_OBJECT_UPDATE_TIME of the object over "
                  "frames 1..%d, and the median RT_STAT_UPDATE_TIME. Wald, Benthin and Slusallek (2003) table 3: the "
                  "object BSP's reconstruction for museum/1k (2003, one CPU); its other sizes "
                  "(64 to 64k) are not in the BART data here, the dynamic section's soup "
                  "covers them.\n\n",
                  res[MUSEUM].animated_triangles, opts->quick ? BART_QUICK_WIDTH : BART_PLAY_WIDTH,
                  opts->quick ? BART_QUICK_HEIGHT : BART_PLAY_HEIGHT, mu[0].frames);
    report_table_header("strategy|median ms|mean ms|max ms|RT_STAT_UPDATE_TIME median ms|"
                        "Wald, Benthin and Slusallek (2003) (1k)");
    for (int k = 0; k < 2; k++) {
        report_row("%s|%.3f|%.3f|%.3f|%.3f|8 ms", museum_strategies[k + 1].label, mu[k].median,
                   mu[k].mean, mu[k].max, mu[k].stat_median);
        snprintf(key, sizeof(key), "bart.museum.%s", k ? "rebuild_median_ms" : "rebuild_ms");
        report_metric(key, mu[k].median, 0);
    }

}

/*
 * The frames-per-second runs by the CPU clock, as `rtbench dynamic-cpu`
 * measures the update strategies: the process's CPU time
 * (CLOCK_PROCESS_CPUTIME_ID, every thread of the process summed) over the
 * same timed calls as the wall clock.  Time slices that other processes
 * take from our cores do not count, so on a shared machine it varies far
 * less between runs than the wall clock; what is left is the slowdown
 * contention causes in our own instructions (shared caches, a sibling
 * hyperthread).  The render pool's idle threads sleep on a condition
 * variable, so waiting costs no CPU time: at threads=2 the figure is the
 * work of both threads, not a speedup, and its ratio to threads=1 is the
 * work the second thread adds.  With --out, every run's figures go to
 * bart_fps_runs.dat for comparisons run by run.
 */
static void print_fps_cpu(const struct scene_result *res)
{
    const int runs = res[0].fps_runs;
    char key[96];
    FILE *data = report_data_file("bart_fps_runs.dat");
    report_printf("\nThe same runs by the CPU clock (as `rtbench dynamic-cpu` measures): CPU ms "
                  "= process CPU time per frame, every thread summed, over the same calls as "
                  "the wall clock (describe + update + render), median of %d run%s; frames per "
                  "CPU-s = 1000 / CPU ms, the fps the frames would reach with all their work on "
                  "one core that nothing else used; time slices other processes take are not "
                  "counted, so this figure is the one to compare between builds on a shared "
                  "machine. At threads=2 it counts both threads' work (idle render threads "
                  "sleep), so it is not a speedup: \"CPU vs threads=1\" is the work the second "
                  "thread adds. CPU share of each run (in run order) = CPU time / (wall time x "
                  "threads): below 100%% when other processes took our cores, or at threads=2 "
                  "when a thread waited (describe and update run on the calling thread alone). "
                  "Spread = the slowest run's ms per frame / the fastest's, wall and CPU.\n\n",
                  runs, runs == 1 ? "" : "s");
    report_table_header("scene|shading|threads|fps (wall)|CPU ms/frame|frames per CPU-s|"
                        "CPU vs threads=1|CPU share of each run|spread wall|spread CPU");
    if (data)
        fprintf(data, "# scene shading threads run wall_ms_per_frame cpu_ms_per_frame "
                      "share_percent\n");
    for (int i = 0; i < SCENES; i++)
        for (int s = 0; s < SHADINGS; s++)
            for (int k = 0; k < THREAD_COUNTS; k++) {
                const struct scene_result *r = &res[i];
                const double *wall = r->run_wall_ms[s][k], *cpu = r->run_cpu_ms[s][k];
                char shares[16 * BART_MAX_RUNS], vs1[16], spread_wall[16], spread_cpu[16];
                size_t used = 0;
                shares[0] = '\0';
                for (int run = 0; run < runs; run++) {
                    double share = wall[run] > 0.0 ? 100.0 * cpu[run] / (wall[run] * (k + 1)) : 0.0;
                    used += (size_t)snprintf(shares + used, sizeof(shares) - used, "%s%.0f%%",
                                             run ? ", " : "", share);
                    if (used >= sizeof(shares))
                        used = sizeof(shares) - 1;
                    if (data)
                        fprintf(data, "%s %s %d %d %.3f %.3f %.1f\n", scene_info[i].name,
                                shading_key[s], k + 1, run + 1, wall[run], cpu[run], share);
                }
                if (k > 0 && r->cpu_ms[s][0] > 0.0)
                    snprintf(vs1, sizeof(vs1), "%.2fx", r->cpu_ms[s][k] / r->cpu_ms[s][0]);
                else
                    snprintf(vs1, sizeof(vs1), "-");
                if (runs > 1) {
                    snprintf(spread_wall, sizeof(spread_wall), "%.2fx", spread_of(wall, runs));
                    snprintf(spread_cpu, sizeof(spread_cpu), "%.2fx", spread_of(cpu, runs));
                } else {
                    snprintf(spread_wall, sizeof(spread_wall), "-");
                    snprintf(spread_cpu, sizeof(spread_cpu), "-");
                }
                double cpu_fps = r->cpu_ms[s][k] > 0.0 ? 1e3 / r->cpu_ms[s][k] : 0.0;
                report_row("%s|%s|%d|%.2f|%.1f|%.2f|%s|%s|%s|%s", scene_info[i].name,
                           shading_label[s], k + 1, r->fps[s][k], r->cpu_ms[s][k], cpu_fps, vs1,
                           shares, spread_wall, spread_cpu);
                snprintf(key, sizeof(key), "bart.%s.%s.t%d.cpu_fps", scene_info[i].name,
                         shading_key[s], k + 1);
                report_metric(key, cpu_fps, 1);
            }
    if (data)
        fclose(data);
}

/* The frames-per-second tables (4): the whole section prints them after
 * the scenes, top level and museum update; `rtbench bart-fps` alone. */
static void print_fps(const struct bench_options *opts, const struct scene_result *res)
{
    const int w = opts->quick ? BART_QUICK_WIDTH : BART_WIDTH;
    const int h = opts->quick ? BART_QUICK_HEIGHT : BART_HEIGHT;
    char key[96];

    report_printf("\n### Frames per second (Wald, Benthin and Slusallek (2003) tables 1, 2 and 4)\n\n");
    report_printf(
        "%d frames spread evenly through each animation (frame round(i (N-1) / %d), "
        "i = 1..%d), played in order after an untimed eye-light frame 0, so that "
        "every update happens; %dx%d; eye light (RT_EYE_LIGHT: \"OpenGL-like\") and Whitted "
        "(RT_WHITTED: shadows from every light, reflection and refraction, "
        "RT_MAX_RAY_DEPTH %d, \"Ray Tracing\"); contexts `threads=1` and `threads=2`. "
        "fps = frames / total wall clock (describe + update + render), median of %d "
        "interleaved runs; the first frame (lazy builds) is in the Scenes table. "
        "Wald, Benthin and Slusallek (2003): 2 CPUs = one dual AthlonMP 1800+ client (tables 1 and 2, column 2; "
        "table 4, column 1); it gives no 1-CPU figure (n/r). Its shading is "
        "programmable shaders with texturing; ours is fixed-function Phong with "
        "textures.\n\n",
        res[0].fps_frames, res[0].fps_frames, res[0].fps_frames, w, h, BART_RAY_DEPTH,
        res[0].fps_runs);
    report_table_header("scene|shading|fps threads=1|paper 1 CPU|fps threads=2|paper 2 CPUs|"
                        "2 threads / paper|speedup 2/1 threads|rays/frame|Mrays/s threads=2|"
                        "images 1 = 2 threads");
    for (int i = 0; i < SCENES; i++)
        for (int s = 0; s < SHADINGS; s++) {
            const struct scene_result *r = &res[i];
            char paper[32], rays[64];
            paper_fps(paper, sizeof(paper), scene_info[i].paper_fps[s]);
            if (i == KITCHEN && s == 1)
                snprintf(rays, sizeof(rays), "%.0f (paper: %.0f)", r->rays[s], PAPER_KITCHEN_RAYS);
            else
                snprintf(rays, sizeof(rays), "%.0f", r->rays[s]);
            report_row("%s|%s|%.2f|n/r|%.2f|%s (%s)|%.2fx|%.2fx|%s|%.2f|%s", scene_info[i].name,
                       shading_label[s], r->fps[s][0], r->fps[s][1], paper,
                       scene_info[i].paper_source, r->fps[s][1] / scene_info[i].paper_fps[s],
                       r->fps[s][0] > 0.0 ? r->fps[s][1] / r->fps[s][0] : 0.0, rays,
                       r->rays[s] * r->fps[s][1] * 1e-6, r->image_mismatches[s] ? "**NO**" : "yes");
            for (int k = 0; k < THREAD_COUNTS; k++) {
                snprintf(key, sizeof(key), "bart.%s.%s.t%d.fps", scene_info[i].name, shading_key[s],
                         k + 1);
                report_metric(key, r->fps[s][k], 1);
            }
            if (r->image_mismatches[s]) {
                report_progress("rtbench: bart: %s: %s: %d frame images differ between "
                                "threads=1 and threads=2 or between runs\n",
                                scene_info[i].name, shading_label[s], r->image_mismatches[s]);
                report_check_failed();
            }
        }
    report_printf("\nPer frame on `threads=2` (medians over runs of the means over the "
                  "frames): describe (the calls before rtRenderFrame), update "
                  "(RT_STAT_UPDATE_TIME + RT_STAT_TOPLEVEL_TIME, before tracing) and render (the "
                  "rest of rtRenderFrame, including the lazy builds of objects first reached in "
                  "that frame).\n\n");
    report_table_header("scene|shading|describe ms|update ms|render ms|total ms|"
                        "threads=1 total ms");
    for (int i = 0; i < SCENES; i++)
        for (int s = 0; s < SHADINGS; s++) {
            const struct scene_result *r = &res[i];
            report_row("%s|%s|%.2f|%.3f|%.1f|%.1f|%.1f", scene_info[i].name, shading_label[s],
                       r->describe_ms[s][1], r->update_ms[s][1], r->render_ms[s][1],
                       r->fps[s][1] > 0.0 ? 1e3 / r->fps[s][1] : 0.0,
                       r->fps[s][0] > 0.0 ? 1e3 / r->fps[s][0] : 0.0);
        }
    print_fps_cpu(res);
}

static void print_overhead(const struct bench_options *opts, const struct scene_result *res)
{
    const int w = opts->quick ? BART_QUICK_WIDTH : BART_WIDTH;
    const int h = opts->quick ? BART_QUICK_HEIGHT : BART_HEIGHT;
    char key[96];
    int unsettled = 0;
    report_printf("\n### Two-level overhead: dynamic against flattened (Wald, Benthin and Slusallek (2003) sec. 6, "
                  "\"Total Overhead\")\n\n");
    report_printf("The same %d frames (spread as above, round(i (N-1) / %d)) rendered (a) as "
                  "the application describes them, instances of the scene's objects "
                  "(rtuDrawAFF), and (b) flattened: the whole frame baked into one static "
                  "object (rtuBakeAFF) and instanced once. %dx%d, context `threads=2`. Only "
                  "rtRenderFrame of a render that built and updated nothing is timed: each "
                  "configuration of a frame is rendered until a render builds nothing (the "
                  "first render of a new frame rebuilds the top level, or builds the baked "
                  "object), so times are render only, structures built. ms per frame, median of "
                  "%d runs; tests per ray over the frames (RT_STAT_NODE_TESTS: top-level and "
                  "object BVH nodes, RT_STAT_TRIANGLE_TESTS, RT_STAT_INSTANCE_TESTS: instances "
                  "entered, each a ray transformation). Wald, Benthin and Slusallek (2003) found 10-20%% on static test "
                  "scenes split into objects (it had no flattened BART).\n\n",
                  res[0].overhead_frames, res[0].overhead_frames, w, h, res[0].overhead_runs);
    report_table_header("scene|shading|dynamic ms|flat ms|dynamic / flat|rays/frame|"
                        "nodes/ray dynamic|nodes/ray flat|triangles/ray dynamic|"
                        "triangles/ray flat|instances/ray dynamic|Wald, Benthin and Slusallek (2003)");
    for (int i = 0; i < SCENES; i++)
        for (int s = 0; s < SHADINGS; s++) {
            const struct scene_result *r = &res[i];
            double ratio =
                r->overhead_ms[s][1] > 0.0 ? r->overhead_ms[s][0] / r->overhead_ms[s][1] : 0.0;
            report_row("%s|%s|%.1f|%.1f|%.2f|%.0f|%.1f|%.1f|%.2f|%.2f|%.2f|1.10-1.20",
                       scene_info[i].name, shading_label[s], r->overhead_ms[s][0],
                       r->overhead_ms[s][1], ratio, r->overhead_rays[s][0], r->per_ray_nodes[s][0],
                       r->per_ray_nodes[s][1], r->per_ray_tris[s][0], r->per_ray_tris[s][1],
                       r->per_ray_instances[s][0]);
            snprintf(key, sizeof(key), "bart.%s.%s.overhead_ratio", scene_info[i].name,
                     shading_key[s]);
            report_metric(key, ratio, 0);
            unsettled += r->unsettled;
        }
    if (unsettled)
        report_printf("\n%d render%s still built or updated something after %d tries; "
                      "those times include it.\n",
                      unsettled, unsettled == 1 ? "" : "s", BART_SETTLE_TRIES);
}

/* ------------------------------------------------------------ section */

static int scene_measure(const struct bench_options *opts, const char *dir, int i,
                         struct scene_result *r)
{
    struct bart_ctx c[THREAD_COUNTS];
    int rc = -1;
    memset(c, 0, sizeof(c));
    report_progress("bart: %s: loading\n", scene_info[i].name);
    if (ctx_open(&c[0], dir, &scene_info[i], "threads=1", 1) ||
        ctx_open(&c[1], dir, &scene_info[i], "threads=2", 2))
        goto out;
    RTUaffscene *aff = c[1].aff;
    r->frames = c[1].frames;
    rtuGetAFFiv(aff, RTU_AFF_STATIC_OBJECTS, &r->static_objects);
    rtuGetAFFiv(aff, RTU_AFF_ANIMATED_OBJECTS, &r->rigid_objects);
    rtuGetAFFiv(aff, RTU_AFF_UNSTRUCTURED_OBJECTS, &r->unstructured_objects);
    rtuGetAFFiv(aff, RTU_AFF_INSTANCES, &r->instances);
    rtuGetAFFiv(aff, RTU_AFF_TRIANGLES, &r->triangles);
    rtuGetAFFiv(aff, RTU_AFF_ANIMATED_TRIANGLES, &r->animated_triangles);
    rtuGetAFFiv(aff, RTU_AFF_LIGHTS, &r->lights);
    rtuGetAFFiv(aff, RTU_AFF_TEXTURES, &r->textures);
    r->load_ms = c[1].load_ms;
    if (fps_measure(opts, c, r))
        goto out;
    if (!opts->bart_fps_only &&
        (toplevel_measure(opts, &c[1], r) || overhead_measure(opts, &c[1], r)))
        goto out;
    rc = 0;
out:
    ctx_close(&c[0]);
    ctx_close(&c[1]);
    return rc;
}

/* ------------------------------------------------------------ frame overhead */

#define OVERHEAD_WIDTH 1024
#define OVERHEAD_HEIGHT 768
/* Interleaved frame and bare runs: at least OVERHEAD_REPS, more with
 * --runs N (up to OVERHEAD_MAX_REPS).  On a shared machine a median of
 * five moved the ratio by 0.3 between processes (performance-log.md,
 * round 48, fr16), while the ratio of the two kinds' fastest runs, which
 * other processes can only lengthen, stayed within 0.04 over 15 pairs:
 * the table gives both. */
#define OVERHEAD_REPS 5
#define OVERHEAD_MAX_REPS 31

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* render.c's primary rays, bit for bit: pixel centre (x + 0.5, y + 0.5)
 * from the near to the far plane through the inverse projection.
 * Returns how many were made (pixels that cannot be unprojected make
 * none, as they trace none). */
static size_t primary_rays(int w, int h, RTray *rays)
{
    double proj[16], inv[16];
    bench_current_projection(proj);
    size_t count = 0;
    if (!mat4_invert(inv, proj))
        return 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double nn[3] = {2.0 * (x + 0.5) / w - 1.0, 2.0 * (y + 0.5) / h - 1.0, -1.0};
            double nf[3] = {nn[0], nn[1], 1.0}, pn[3], pf[3];
            if (!mat4_project(inv, nn, pn) || !mat4_project(inv, nf, pf))
                continue;
            double d[3] = {pf[0] - pn[0], pf[1] - pn[1], pf[2] - pn[2]};
            double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (!(len > 0.0) || !isfinite(len))
                continue;
            RTray *r = &rays[count++];
            for (int k = 0; k < 3; k++) {
                r->org[k] = (float)pn[k];
                r->dir[k] = (float)(d[k] / len);
            }
            r->tmin = 0.0f;
            r->tmax = (float)len;
        }
    return count;
}

/*
 * The issue 11 figure "the whole eye-light frame within 1.3x of the bare
 * ray cost": frame 0 of the kitchen at 1024x768, eye light, threads=1,
 * rendered whole (describe + rtRenderFrame: ray generation, trace, shade,
 * write, frame set-up, tile scheduling) against the same primary rays
 * (primary_rays) traced bare with rtTraceRays on the same context.
 * Process CPU time, median of OVERHEAD_REPS runs interleaved frame, rays,
 * frame, rays...; node and triangle tests per ray of both, which must
 * agree for the comparison to mean anything.
 */
static int frame_overhead_table(const struct bench_options *opts, const char *dir)
{
    const int w = opts->quick ? BART_QUICK_WIDTH : OVERHEAD_WIDTH;
    const int h = opts->quick ? BART_QUICK_HEIGHT : OVERHEAD_HEIGHT;
    int reps = opts->runs > OVERHEAD_REPS ? opts->runs : OVERHEAD_REPS;
    if (reps > OVERHEAD_MAX_REPS)
        reps = OVERHEAD_MAX_REPS;
    if (opts->quick)
        reps = 1;
    struct bart_ctx c;
    if (ctx_open(&c, dir, &scene_info[KITCHEN], "threads=1", 1))
        return -1;
    set_shading(0);
    struct frame fr;
    render_frame(&c, 0, w, h, 0, &fr); /* the lazy builds */
    size_t n = (size_t)w * (size_t)h;
    RTray *rays = malloc(n * sizeof(*rays));
    RThit *hits = malloc(n * sizeof(*hits));
    if (!rays || !hits) {
        free(rays);
        free(hits);
        ctx_close(&c);
        return -1;
    }
    size_t count = primary_rays(w, h, rays);
    unsigned char *pixels = malloc(n * 4);
    uint64_t hash = pixels ? image_hash(w, h, pixels) : 0;
    free(pixels);
    double frame_cpu[OVERHEAD_MAX_REPS], frame_wall[OVERHEAD_MAX_REPS];
    double bare_cpu[OVERHEAD_MAX_REPS], bare_wall[OVERHEAD_MAX_REPS];
    double frame_tests = 0.0, frame_rays = 0.0, bare_tests = 0.0;
    for (int r = 0; r < reps; r++) {
        render_frame(&c, 0, w, h, 0, &fr);
        frame_cpu[r] = fr.cpu_ms;
        frame_wall[r] = fr.total_ms;
        frame_tests = fr.node_tests + fr.triangle_tests;
        frame_rays = fr.rays;
        double cpu0 = bench_cpu_ms(), t0 = rt_now_ms();
        rtTraceRays((RTsizei)count, rays, hits);
        bare_wall[r] = rt_now_ms() - t0;
        bare_cpu[r] = bench_cpu_ms() - cpu0;
        bench_share_add(1, bare_wall[r], bare_cpu[r]);
        bare_tests = (double)get_f(RT_STAT_NODE_TESTS) + (double)get_f(RT_STAT_TRIANGLE_TESTS);
    }
    int rc = ctx_check(&c, "frame-overhead");
    ctx_close(&c);
    free(rays);
    free(hits);
    qsort(frame_cpu, (size_t)reps, sizeof(double), cmp_double);
    qsort(frame_wall, (size_t)reps, sizeof(double), cmp_double);
    qsort(bare_cpu, (size_t)reps, sizeof(double), cmp_double);
    qsort(bare_wall, (size_t)reps, sizeof(double), cmp_double);
    double fc = frame_cpu[reps / 2], bc = bare_cpu[reps / 2];
    report_printf("\n### Eye-light frame against its bare primary rays\n\n");
    report_printf("Frame 0 of the kitchen at %dx%d, eye light, context `threads=1`: the whole "
                  "frame (describe + rtRenderFrame, structures already built) against the same "
                  "%zu primary rays, made as the renderer makes them, traced with rtTraceRays "
                  "on the same context. Process CPU time, median of %d interleaved runs; fastest: "
                  "each kind's fastest run, which other processes on the machine can only "
                  "lengthen (the steadier ratio on a shared machine).\n\n",
                  w, h, count, reps);
    report_table_header("what|CPU ms|wall ms|rays|tests/ray|frame / bare (CPU)");
    report_row("eye-light frame|%.1f|%.1f|%.0f|%.2f|%.2fx", fc, frame_wall[reps / 2], frame_rays,
               frame_rays > 0 ? frame_tests / frame_rays : 0.0, bc > 0.0 ? fc / bc : 0.0);
    report_row("rtTraceRays, same rays|%.1f|%.1f|%zu|%.2f|1.00x", bc, bare_wall[reps / 2], count,
               count ? bare_tests / (double)count : 0.0);
    report_row("eye-light frame, fastest|%.1f|%.1f|%.0f|%.2f|%.2fx", frame_cpu[0], frame_wall[0],
               frame_rays, frame_rays > 0 ? frame_tests / frame_rays : 0.0,
               bare_cpu[0] > 0.0 ? frame_cpu[0] / bare_cpu[0] : 0.0);
    report_row("rtTraceRays, fastest|%.1f|%.1f|%zu|%.2f|1.00x", bare_cpu[0], bare_wall[0], count,
               count ? bare_tests / (double)count : 0.0);
    report_metric("frame_overhead.kitchen.frame_cpu_ms", fc, 0);
    report_metric("frame_overhead.kitchen.bare_cpu_ms", bc, 0);
    report_metric("frame_overhead.kitchen.ratio", bc > 0.0 ? fc / bc : 0.0, 0);
    report_metric("frame_overhead.kitchen.ratio_fastest",
                  bare_cpu[0] > 0.0 ? frame_cpu[0] / bare_cpu[0] : 0.0, 0);
    report_printf("\nThe frame's image (FNV-1a of rtReadPixels RGBA8): %016llx.\n",
                  (unsigned long long)hash);
    bench_share_report();
    return rc;
}

int bench_bart_section(const struct bench_options *opts)
{
    char why[512];
    const char *source;
    const char *dir = bench_bart_data_dir(opts, &source);
    report_printf("\n## BART (Wald, Benthin and Slusallek (2003) sec. 5)\n\n");
    if (bench_bart_find_data(opts, why, sizeof(why))) {
        report_printf("Skipped: %s.\n", why);
        return 0;
    }
    double start = rt_now_ms();
    report_printf("The BART scenes (Lext, Assarsson and Moeller 2000; kitchen.aff, Robot.aff, "
                  "museum5.aff, read from %s) played through the public API as "
                  "demos/bart/bart.c plays them: per frame, projection = rtuAFFView, modelview "
                  "identity, rtuAFFLights, rtuDrawAFF (instances, and rtUpdateVertices for the "
                  "museum's animated triangles), rtRenderFrame. Wald, Benthin and Slusallek's (2003) figures are from "
                  "2003 (dual AthlonMP 1800+ clients, a BSP per object, OpenRT's programmable "
                  "shaders); ours from the machine in the header.%s\n",
                  source, opts->quick ? " --quick: tiny images and few frames." : "");
    struct scene_result res[SCENES];
    struct museum_update mu[2];
    memset(res, 0, sizeof(res));
    memset(mu, 0, sizeof(mu));
    bench_share_reset();
    if (opts->bart_frame_overhead_only) {
        /* `rtbench frame-overhead`: a whole eye-light frame against its
         * primary rays traced bare. */
        if (frame_overhead_table(opts, dir))
            return -1;
        report_printf("\nThe frame-overhead section took %.0f s.\n", (rt_now_ms() - start) / 1e3);
        return 0;
    }
    if (opts->bart_strategies_only) {
        /* `rtbench bart-strategies`: RT_AUTOMATIC against the fixed
         * strategies without the rest of the section. */
        if (museum_strategies_table(opts, dir))
            return -1;
        bench_share_report();
        report_printf("\nThe BART strategies took %.0f s.\n", (rt_now_ms() - start) / 1e3);
        return 0;
    }
    for (int i = 0; i < SCENES; i++)
        if (scene_measure(opts, dir, i, &res[i]))
            return -1;
    if (opts->bart_fps_only) {
        /* `rtbench bart-fps`: the frames per second alone, for before and
         * after comparisons (the whole section takes about 15 minutes). */
        print_fps(opts, res);
        bench_share_report();
        report_printf("\nThe BART fps took %.0f s.\n", (rt_now_ms() - start) / 1e3);
        return 0;
    }
    if (museum_update_measure(opts, dir, mu))
        return -1;
    print_tables(opts, res, mu);
    print_fps(opts, res);
    if (museum_strategies_table(opts, dir) || robots_strategies_table(opts, dir))
        return -1;
    print_overhead(opts, res);
    bench_share_report();
    report_printf("\nThe BART section took %.0f s.\n", (rt_now_ms() - start) / 1e3);
    return 0;
}
