/* SPDX-License-Identifier: Apache-2.0 */
/*
 * aff_fuzz.c - libFuzzer target over the AFF (BART) loader.
 *
 * One input is the text of one AFF file (FORMAT.md is
 * ../shared/bart/FORMAT.md beside the checkout), optionally followed by
 * more files: a line "%%file NAME" (a comment to the AFF reader) starts
 * the file NAME, which 'i 0 NAME' in any of them includes from memory
 * (struct aff_limits.include_text), so the fuzzer reaches include
 * fan-out, cycles and the read budget without touching the filesystem.
 * The target
 *   1. parses it with aff_parse_text, with no directory: includes name
 *      only the files of the input (lib/rtu/aff_parse.c);
 *   2. if it parses, evaluates the animation at a few times (t0, t1, their
 *      midpoint, -1e30 and 1e30): every frame's world matrix
 *      (aff_frame_matrix), every animated triangle (aff_tpa_eval), every
 *      track, the camera and the animated lights (lib/rtu/aff_anim.c);
 *   3. records the scene into a Tracelist context (aff_scene_create, the
 *      second half of rtuLoadAFF), draws it at two times, bakes it once,
 *      commits, traces a few rays and renders a few pixels, then deletes
 *      everything again (lib/rtu/aff_scene.c and the core library).
 * Texture names resolve against the working directory: the tests run where
 * tex.ppm, the one texture the corpus names, is (CMakeLists.txt); any other
 * name fails cleanly in step 3, which is a path worth running too.
 *
 * Oracles besides the sanitizers: a matrix aff_frame_matrix calls visible
 * is finite; an animated triangle stays inside the range of its keys
 * (FORMAT.md sec. 7.5 interpolates linearly between neighbouring keys);
 * rtOccludedRays agrees with rtTraceRays (docs/queries.md).  A violation
 * aborts, which libFuzzer reports as a crash with the input saved.
 *
 * Work per input is bounded: inputs above AFF_FUZZ_MAX_INPUT bytes are
 * skipped, the parser bounds every count (and the triangles it makes of
 * spheres and cones) by the size of the text, and scenes of more than
 * AFF_FUZZ_MAX_TRIANGLES triangles stop after step 2.  That bound is a
 * property checked here: the triangles and the bytes of a parsed scene
 * are linear in the input (AFF_FUZZ_BYTES_PER_INPUT), and run_fuzz.sh
 * runs libFuzzer with -malloc_limit_mb, -rss_limit_mb and -timeout, so an
 * input that allocates or runs beyond them is a finding too.
 *
 * Built two ways (conformance/fuzz/CMakeLists.txt): aff_fuzz with libFuzzer
 * (clang, RT_FUZZ=ON) and aff_fuzz_replay with replay_main.c, which runs
 * the corpus and the regressions through this function in every build.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <rt/rt.h>
#include <rt/rtu.h>

#include "rtu/aff_internal.h"

/* Larger inputs are skipped (run with -max_len=65536 to match): the BART
 * files that matter as seeds are below it, and small inputs run fast. */
#define AFF_FUZZ_MAX_INPUT 65536
/* Triangles (as instantiated) above which the scene is not recorded: a
 * sphere is 1024 triangles from 9 bytes, so a 64 KiB input could ask for
 * a million, recorded twice (load and bake) and built into BVHs under the
 * sanitizers and the coverage instrumentation.  The corpus drifts towards
 * inputs at the limit: with 100000 they took 1.5 s each and the fuzzer ran
 * at a seventh of its speed.  Four spheres' worth covers every loader
 * path. */
#define AFF_FUZZ_MAX_TRIANGLES 4096
/* The memory-bound property checked on every input that parses: the
 * parsed scene holds at most 64 bytes per input byte plus 16 MiB.  The
 * triangle budget alone allows 24 per byte plus 6 MiB, twice that while an
 * array doubles; matrices, frames and keys add at most a few bytes per
 * byte (each takes at least its own text). */
#define AFF_FUZZ_BYTES_PER_INPUT 64
#define AFF_FUZZ_BYTES_BASE ((uint64_t)16 << 20)
/* Rays traced per commit; pixels of the rendered frame. */
#define AFF_FUZZ_RAYS 16
#define AFF_FUZZ_WIDTH 4
#define AFF_FUZZ_HEIGHT 3

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/*
 * The one Tracelist context, created at the first input that needs it
 * (threads=1: libFuzzer calls the target from one thread, and no worker
 * threads means none to leak or to race with) and current from then on.
 * It is the only global mutable state: a fuzz target is a process of its
 * own, and creating a context per input would cost more than most inputs.
 * Every input leaves it as it found it (no objects, an empty frame, no
 * pending error); it is never destroyed, and stays reachable from here, so
 * LeakSanitizer does not count it.
 */
static RTcontext fuzz_context(void)
{
    static RTcontext context;
    if (!context) {
        context = rtCreateContext("threads=1");
        if (context)
            rtMakeCurrent(context);
    }
    return context;
}

static void check(int condition)
{
    if (!condition)
        abort();
}

/* ------------------------------------------------------------ animation */

static int all_finite(const double *v, int n)
{
    for (int k = 0; k < n; k++)
        if (!isfinite(v[k]))
            return 0;
    return 1;
}

/* FORMAT.md sec. 7.5: every value of an animated triangle is a key's value
 * or lies between two neighbouring keys', so within the range of its keys
 * whenever those are finite. */
static void check_tpa(const struct aff_tpa *tpa, const float p[9], const float n[9])
{
    for (int i = 0; i < 18; i++) {
        float lo = INFINITY, hi = -INFINITY;
        int finite = 1;
        for (int k = 0; k < tpa->key_count; k++) {
            float v = i < 9 ? tpa->keys[k].p[i] : tpa->keys[k].n[i - 9];
            finite = finite && isfinite(v);
            lo = v < lo ? v : lo;
            hi = v > hi ? v : hi;
        }
        float got = i < 9 ? p[i] : n[i - 9];
        if (finite)
            check(got >= lo && got <= hi);
    }
}

static void eval_animation(const struct aff_animation *a, double t)
{
    double v[9], q[4], m[16];
    if (a->has_transl)
        aff_track_eval(&a->transl, t, v);
    if (a->has_rot) {
        aff_track_eval(&a->rot, t, v);
        aff_track_eval_quat(&a->rot, t, q);
    }
    if (a->has_scale)
        aff_track_eval(&a->scale, t, v);
    if (a->has_visibility)
        (void)aff_visibility_eval(&a->visibility, t);
    aff_node_matrix(a->has_transl ? &a->transl : NULL, a->has_rot ? &a->rot : NULL,
                    a->has_scale ? &a->scale : NULL, t, m);
}

/* Step 2 at time t; cache and state hold one entry per frame. */
static void eval_data(const struct aff_data *d, double t, double (*cache)[16], int *state)
{
    memset(state, 0, (size_t)d->frame_count_nodes * sizeof *state);
    for (int f = 0; f < d->frame_count_nodes; f++) {
        double m[16];
        if (aff_frame_matrix(d, f, t, cache, state, m))
            check(all_finite(m, 16));
        const struct aff_group *g = &d->frames[f].group;
        for (uint32_t i = 0; i < g->tpa_count; i++) {
            float p[9], n[9];
            aff_tpa_eval(g->tpas[i].keys, g->tpas[i].key_count, t, p, n);
            check_tpa(&g->tpas[i], p, n);
        }
    }
    for (int a = 0; a < d->animation_count; a++)
        eval_animation(&d->animations[a], t);
    if (d->camera >= 0) {
        const struct aff_animation *cam = &d->animations[d->camera];
        double eye[3], dir[3], up[3];
        aff_camera_eval(cam->has_transl ? &cam->transl : NULL, cam->has_rot ? &cam->rot : NULL,
                        t, eye, dir, up);
    }
    for (int l = 0; l < d->light_count; l++)
        if (d->lights[l].animation >= 0) {
            double p[3];
            aff_track_eval(&d->animations[d->lights[l].animation].transl, t, p);
        }
}

/* ------------------------------------------------------------ scene */

/* Rays from the camera at time t, fanned around its view direction; the
 * answers of the two query entry points must agree. */
static void trace(const RTUaffscene *s, double t)
{
    double eye[3], dir[3], up[3];
    rtuAFFCamera(s, t, eye, dir, up);
    double right[3] = {dir[1] * up[2] - dir[2] * up[1], dir[2] * up[0] - dir[0] * up[2],
                       dir[0] * up[1] - dir[1] * up[0]};
    RTray rays[AFF_FUZZ_RAYS];
    RThit hits[AFF_FUZZ_RAYS];
    RTboolean occluded[AFF_FUZZ_RAYS];
    for (int i = 0; i < AFF_FUZZ_RAYS; i++) {
        double x = (i % 4) / 3.0 - 0.5, y = (i / 4) / 3.0 - 0.5;
        for (int k = 0; k < 3; k++) {
            rays[i].org[k] = (float)eye[k];
            rays[i].dir[k] = (float)(dir[k] + x * right[k] + y * up[k]);
        }
        rays[i].tmin = 0.0f;
        rays[i].tmax = INFINITY;
    }
    rtTraceRays(AFF_FUZZ_RAYS, rays, hits);
    rtOccludedRays(AFF_FUZZ_RAYS, rays, occluded);
    for (int i = 0; i < AFF_FUZZ_RAYS; i++)
        check((hits[i].object != RT_INVALID_ID) == (occluded[i] == RT_TRUE));
}

/* Step 3: takes ownership of *d. */
static void run_scene(struct aff_data *d, double ta, double tb, double tm)
{
    if (!fuzz_context()) {
        aff_data_release(d);
        return;
    }
    rtBeginFrame();
    RTUaffscene *s = aff_scene_create(d, "fuzz.aff");
    if (!s) {
        (void)rtGetError();
        return;
    }
    /* The queries: every name (and one past them), every object kind. */
    for (RTenum pname = RTU_AFF_FRAMES; pname <= RTU_AFF_TRANSFORM_NODES + 1; pname++) {
        RTint info[2];
        rtuGetAFFiv(s, pname, info);
    }
    const RTenum kinds[] = {RT_STATIC, RT_AFFINE, RT_UNSTRUCTURED};
    for (int k = 0; k < 3; k++) {
        RTuint names[4];
        (void)rtuAFFObjects(s, kinds[k], 4, names);
    }
    (void)rtuAFFFrameTime(s, 1);

    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtuAFFView(s, ta, 0.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtuAFFLights(s, ta);

    /* A frame at ta, committed and queried (which builds the BVHs the rays
     * reach), then one at tb with the baked scene beside it, rendered:
     * the second frame updates what moved. */
    rtuDrawAFF(s, ta);
    rtFinish();
    trace(s, ta);
    rtBeginFrame();
    rtuDrawAFF(s, tb);
    RTuint baked = rtuBakeAFF(s, tm);
    if (baked)
        rtInstantiateObject(baked);
    rtFinish();
    trace(s, tb);
    rtViewport(0, 0, AFF_FUZZ_WIDTH, AFF_FUZZ_HEIGHT);
    rtRenderFrame();

    rtuDeleteAFF(s);
    if (baked)
        rtDeleteObjects(1, &baked);
    rtBeginFrame();
    /* Scenes the API rejects parts of (a singular instance matrix, say)
     * are expected; the error slot must be clear for the next input. */
    (void)rtGetError();
}

/* ------------------------------------------------------------ files */

#define AFF_FUZZ_MAX_FILES 16
#define AFF_FUZZ_MARKER "%%file "

/* The files of one input after the first: name and text. */
struct fuzz_files {
    int count;
    struct {
        const char *name, *text;
        size_t name_length, length;
    } file[AFF_FUZZ_MAX_FILES];
};

/* Splits the input at lines "%%file NAME"; returns the length of the
 * first file (the top file). */
static size_t split_files(const char *text, size_t size, struct fuzz_files *files)
{
    const size_t marker = sizeof AFF_FUZZ_MARKER - 1;
    size_t top = size;
    files->count = 0;
    for (size_t pos = 0; pos + marker <= size; pos++) {
        if ((pos > 0 && text[pos - 1] != '\n') || memcmp(text + pos, AFF_FUZZ_MARKER, marker))
            continue;
        if (files->count == 0)
            top = pos;
        else
            files->file[files->count - 1].length =
                pos - (size_t)(files->file[files->count - 1].text - text);
        if (files->count == AFF_FUZZ_MAX_FILES)
            return top;
        size_t name = pos + marker, end = name;
        while (end < size && text[end] != '\n')
            end++;
        files->file[files->count].name = text + name;
        files->file[files->count].name_length = end - name;
        files->file[files->count].text = text + (end < size ? end + 1 : end);
        files->file[files->count].length = 0;
        files->count++;
        pos = end;
    }
    if (files->count > 0)
        files->file[files->count - 1].length =
            size - (size_t)(files->file[files->count - 1].text - text);
    return top;
}

static int include_text(void *user, const char *name, const char **text, size_t *length,
                        uint64_t *id)
{
    const struct fuzz_files *files = user;
    for (int i = 0; i < files->count; i++)
        if (files->file[i].name_length == strlen(name) &&
            memcmp(files->file[i].name, name, strlen(name)) == 0) {
            *text = files->file[i].text;
            *length = files->file[i].length;
            *id = (uint64_t)i;
            return 0;
        }
    return -1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > AFF_FUZZ_MAX_INPUT)
        return 0;
    struct aff_data d;
    char error[AFF_ERROR_SIZE];
    struct fuzz_files files;
    struct aff_limits limits;
    aff_limits_default(&limits);
    size_t top = split_files((const char *)data, size, &files);
    limits.include_text = include_text;
    limits.include_user = &files;
    if (aff_parse_text("fuzz.aff", (const char *)data, top, NULL, &limits, &d, error,
                       sizeof error))
        return 0;
    /* The resource bound (docs/aff.md): the parsed scene of n input bytes
     * holds less than AFF_FUZZ_BYTES_PER_INPUT n + AFF_FUZZ_BYTES_BASE
     * bytes, the triangle budget of the defaults plus the arrays around
     * it.  libFuzzer's -malloc_limit_mb and -rss_limit_mb (run_fuzz.sh)
     * catch what escapes the count, a failed load included. */
    check(d.static_triangles + d.animated_triangles + d.tpa_triangles <=
          size / AFF_INPUT_PER_TRIANGLE + AFF_TRIANGLES_BASE);
    check(aff_data_bytes(&d) <= AFF_FUZZ_BYTES_PER_INPUT * (uint64_t)size + AFF_FUZZ_BYTES_BASE);

    double ta = d.t0, tb = d.t1, tm = 0.5 * ((double)d.t0 + (double)d.t1);
    const double times[] = {ta, tb, tm, -1e30, 1e30};
    size_t frames = (size_t)d.frame_count_nodes;
    double(*cache)[16] = malloc(frames * sizeof *cache);
    int *state = malloc(frames * sizeof *state);
    if (cache && state)
        for (size_t i = 0; i < sizeof times / sizeof times[0]; i++)
            eval_data(&d, times[i], cache, state);
    free(cache);
    free(state);

    if (d.static_triangles + d.animated_triangles + d.tpa_triangles > AFF_FUZZ_MAX_TRIANGLES) {
        aff_data_release(&d);
        return 0;
    }
    run_scene(&d, ta, tb, tm);
    return 0;
}
