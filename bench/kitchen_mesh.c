/* SPDX-License-Identifier: Apache-2.0 */
/*
 * kitchen_mesh.c - the BART kitchen (Lext, Assarsson and Moeller 2000) as
 * one more triangle mesh for `rtbench embree` and `rtbench packets`: frame
 * 0 flattened, every instance's triangles in world space, so Embree and our
 * kernels see the same single triangle geometry as for the generated
 * meshes (bench.h's struct bench_mesh).
 *
 * The scene is read with rtuLoadAFF in a throwaway context (the loader
 * wants one: it records the objects and textures `rtbench bart` renders),
 * and the triangles are taken from the parsed scene (aff_internal.h, as
 * bench_bart.c takes the museum's animated triangles) the way rtuBakeAFF
 * places them: each frame of the scene graph under its world matrix at
 * frame 0's time (aff_frame_matrix; hidden frames skipped), each batch
 * under that matrix times its static matrix, points transformed in double
 * and stored as float.  Animated ('tpa') triangles, which the kitchen has
 * none of, are evaluated at the same time.
 *
 * Camera: the file's own camera at frame 0 (rtuAFFCamera, which rtuAFFView
 * puts in front of its rtuPerspective with the 'v' statement's vertical
 * field of view), as the gears mesh uses the camera of gears.c.  The
 * generic camera of mesh_gen.c looks at a mesh's bounding sphere from
 * outside, which for a closed room would show its outer walls only.
 * Light: the scene's first light at frame 0 (rtuAFFLights' RT_LIGHT0),
 * inside the room, where the shadow rays of a frame go; the generated
 * meshes' lights lie outside their bounds, which here would put every
 * shadow ray through a wall.
 *
 * The data folder is the BART section's (--bart-dir, $TRACELIST_BART_DIR,
 * the build's RT_BART_DIR); only kitchen/ is needed, and no path of it is
 * ever printed.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <rt/rtu.h>

#include "base/timer.h"
#include "bench.h"
#include "rtu/aff_internal.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define KITCHEN_FILE "kitchen/kitchen.aff"

/* Copies message into why with every occurrence of dir replaced by
 * "<bart-dir>", so that no path of the machine reaches the report. */
static void without_dir(char *why, size_t why_size, const char *prefix, const char *message,
                        const char *dir)
{
    size_t n = strlen(dir), used = 0;
    int w = snprintf(why, why_size, "%s", prefix);
    used = w > 0 && (size_t)w < why_size ? (size_t)w : 0;
    for (const char *m = message; *m && used + 1 < why_size;) {
        if (n && strncmp(m, dir, n) == 0) {
            w = snprintf(why + used, why_size - used, "<bart-dir>");
            used = w > 0 && used + (size_t)w < why_size ? used + (size_t)w : why_size - 1;
            m += n;
        } else {
            why[used++] = *m++;
            why[used] = '\0';
        }
    }
}

static void transform_point(const double m[16], const float p[3], float out[3])
{
    for (int r = 0; r < 3; r++)
        out[r] = (float)(m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]);
}

/* The triangles of every frame visible at time t, in world space, into an
 * indexed mesh of 3 vertices per triangle.  Returns 0, or -1 on allocation
 * failure. */
static int flatten(const struct aff_data *d, double t, struct bench_mesh *mesh)
{
    const int frames = d->frame_count_nodes;
    double(*cache)[16] = calloc((size_t)(frames ? frames : 1), sizeof(*cache));
    double(*world)[16] = calloc((size_t)(frames ? frames : 1), sizeof(*world));
    int *state = calloc((size_t)(frames ? frames : 1), sizeof(*state));
    int *visible = calloc((size_t)(frames ? frames : 1), sizeof(*visible));
    int rc = -1;
    if (!cache || !world || !state || !visible)
        goto out;
    uint64_t count = 0;
    for (int f = 0; f < frames; f++) {
        const struct aff_group *g = &d->frames[f].group;
        if (!g->tri_count && !g->tpa_count)
            continue;
        visible[f] = aff_frame_matrix(d, f, t, cache, state, world[f]);
        if (visible[f])
            count += (uint64_t)g->tri_count + g->tpa_count;
    }
    /* The loader caps a scene at AFF_TRIANGLES_CAP (2^24) triangles, so
     * 3 * count indices fit in 32 bits. */
    if (count == 0 || count > AFF_TRIANGLES_CAP)
        goto out;
    mesh->positions = malloc((size_t)count * 9 * sizeof(float));
    mesh->indices = malloc((size_t)count * 3 * sizeof(uint32_t));
    if (!mesh->positions || !mesh->indices)
        goto out;
    uint32_t n = 0;
    for (int f = 0; f < frames; f++) {
        const struct aff_group *g = &d->frames[f].group;
        if (!visible[f])
            continue;
        for (uint32_t b = 0; b < g->batch_count; b++) {
            const struct aff_batch *batch = &g->batches[b];
            double m[16];
            aff_matrix_mul(m, world[f], d->matrices[batch->matrix]);
            for (uint32_t i = 0; i < batch->count; i++, n++)
                for (int j = 0; j < 3; j++)
                    transform_point(m, &g->tris[batch->first + i].p[3 * j],
                                    &mesh->positions[9 * (size_t)n + 3 * (size_t)j]);
        }
        /* 'tpa' keys are stored under their static matrix already
         * (aff_internal.h), so only the frame's world matrix applies. */
        for (uint32_t i = 0; i < g->tpa_count; i++, n++) {
            float p[9], nrm[9];
            aff_tpa_eval(g->tpas[i].keys, g->tpas[i].key_count, t, p, nrm);
            for (int j = 0; j < 3; j++)
                transform_point(world[f], &p[3 * j],
                                &mesh->positions[9 * (size_t)n + 3 * (size_t)j]);
        }
    }
    mesh->tri_count = n;
    mesh->vertex_count = 3 * n;
    for (uint32_t i = 0; i < 3 * n; i++)
        mesh->indices[i] = i;
    rc = 0;
out:
    free(cache);
    free(world);
    free(state);
    free(visible);
    return rc;
}

static void cross3d(double out[3], const double a[3], const double b[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static void normalize3d(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0.0)
        for (int k = 0; k < 3; k++)
            v[k] /= l;
}

/* Camera and light of frame 0 at time t (see the file comment). */
static void camera_and_light(const RTUaffscene *s, const struct aff_data *d, double t,
                             struct bench_mesh *mesh)
{
    double eye[3], dir[3], up[3], right[3], up2[3];
    rtuAFFCamera(s, t, eye, dir, up);
    cross3d(right, dir, up);
    normalize3d(right);
    cross3d(up2, right, dir);
    struct bench_camera *c = &mesh->camera;
    for (int k = 0; k < 3; k++) {
        c->eye[k] = (float)eye[k];
        c->forward[k] = (float)dir[k];
        c->right[k] = (float)right[k];
        c->up[k] = (float)up2[k];
    }
    /* rtuAFFView: rtuPerspective(fov, w / h, ...), fov vertical (FORMAT.md
     * sec. 3.1 'angle'); every primary set of the bench is 4:3. */
    const double tan_y = tan(0.5 * (double)d->fov_degrees * M_PI / 180.0);
    c->tan_x = (float)(tan_y * (double)BENCH_PRIMARY_WIDTH / (double)BENCH_PRIMARY_HEIGHT);
    if (d->light_count > 0) {
        const struct aff_light *l = &d->lights[0];
        double p[3] = {l->position[0], l->position[1], l->position[2]};
        if (l->animation >= 0)
            aff_track_eval(&d->animations[l->animation].transl, t, p);
        for (int k = 0; k < 3; k++)
            mesh->light[k] = (float)p[k];
    } else {
        for (int k = 0; k < 3; k++)
            mesh->light[k] = 0.5f * (mesh->bounds.min[k] + mesh->bounds.max[k]);
    }
}

int bench_kitchen_mesh(const struct bench_options *opts, struct bench_mesh *mesh, char *why,
                       size_t why_size)
{
    const char *source;
    const char *dir = bench_bart_data_dir(opts, &source);
    char path[4096];
    memset(mesh, 0, sizeof(*mesh));
    if (!dir[0]) {
        snprintf(why, why_size,
                 "no BART data folder given (set TRACELIST_BART_DIR to the folder holding "
                 "kitchen/, or pass --bart-dir DIR)");
        return -1;
    }
    snprintf(path, sizeof(path), "%s/%s", dir, KITCHEN_FILE);
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(why, why_size, "no %s in the folder named by %s", KITCHEN_FILE, source);
        return -1;
    }
    fclose(f);

    RTcontext ctx = bench_create_context("threads=1");
    if (!ctx || !rtMakeCurrent(ctx)) {
        snprintf(why, why_size, "cannot create a context to load the kitchen");
        if (ctx)
            rtDestroyContext(ctx);
        return -1;
    }
    double start = rt_now_ms();
    RTUaffscene *s = rtuLoadAFF(path);
    int rc = -1;
    if (!s) {
        without_dir(why, why_size, "the AFF loader failed: ", rtuAFFError(), dir);
        goto out;
    }
    const struct aff_data *d = aff_scene_data(s);
    const double t = rtuAFFFrameTime(s, 0);
    if (flatten(d, t, mesh)) {
        snprintf(why, why_size, "out of memory, or no visible triangle at frame 0");
        bench_mesh_release(mesh);
        goto out;
    }
    mesh->name = "kitchen";
    mesh->description = "BART kitchen, frame 0 flattened: every instance's triangles in world "
                        "space; the file's camera and first light at frame 0";
    mesh->bounds = aabb_empty();
    for (uint32_t i = 0; i < mesh->vertex_count; i++)
        aabb_grow_point(&mesh->bounds, &mesh->positions[3 * (size_t)i]);
    camera_and_light(s, d, t, mesh);
    report_progress("kitchen: %u triangles, loaded and flattened in %.0f ms\n", mesh->tri_count,
                    rt_now_ms() - start);
    rc = 0;
out:
    if (s)
        rtuDeleteAFF(s);
    rtMakeCurrent(NULL);
    rtDestroyContext(ctx);
    return rc;
}
