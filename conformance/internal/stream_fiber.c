/* SPDX-License-Identifier: Apache-2.0 */
/*
 * stream_fiber.c - the stream entry (kernels.h, stream_fiber: several
 * rays walked at once on coroutines, lib/trace/stream_fiber.h) against
 * walk1 ray by ray, bit for bit.
 *
 * Each ray's walk in the stream is walk1's walk with yields added, and
 * its answer goes to the caller's arrays at the ray's index; a stream
 * that dropped a ray, gave a ray another's answer or another's hit, or
 * let two coroutines share a ray's state would differ from walk1 here.
 * Every table with the entry, closest and any hit, one to four rays in
 * flight, on camera rays, random rays (some with tmin < 0, which take the
 * float walk without yields) and shadow rays towards a point light from
 * the camera rays' hits, over a random soup, a closed cube-sphere, a
 * height field and a large soup (a layout beyond the L2, whose walks the
 * stream is for); streams of 1, 3 and 5 rays (fewer rays than coroutines,
 * odd counts) as well as long ones.  Compared: the answer, and for a
 * closest hit t, u, v and the primitive.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <rt/rt.h>

#include "accel/bvh_build.h"
#include "accel_testgeo.h"
#include "base/alloc.h"
#include "trace/bvh4_layout.h"
#include "trace/kernels.h"
#include "trace/trace.h"

static int failures;
static int streams_run;

static uint32_t bits(float f)
{
    uint32_t b;
    memcpy(&b, &f, sizeof(b));
    return b;
}

/* Rays of three kinds (0 camera, 1 random, 2 shadow) around the box
 * [lo, hi]; shadow rays need the camera rays' closest hits (walk1's). */
static void make_rays(RTray *rays, uint32_t n, int kind, const float lo[3], const float hi[3],
                      struct tg_rng *r, const RTray *camera, const struct trace_hit *cam_hits,
                      const int *cam_found)
{
    float c[3], e = 0.0f;
    for (int k = 0; k < 3; k++) {
        c[k] = 0.5f * (lo[k] + hi[k]);
        e = fmaxf(e, hi[k] - lo[k]);
    }
    const uint32_t side = (uint32_t)ceil(sqrt((double)n));
    for (uint32_t i = 0; i < n; i++) {
        RTray *ray = &rays[i];
        ray->tmin = 0.0f;
        ray->tmax = INFINITY;
        if (kind == 0) {
            /* A pinhole camera outside the box, looking at its centre. */
            const float eye[3] = {c[0] + 0.3f * e, c[1] + 0.4f * e, c[2] + 1.5f * e};
            const float px = ((float)(i % side) + 0.5f) / (float)side - 0.5f;
            const float py = ((float)(i / side) + 0.5f) / (float)side - 0.5f;
            memcpy(ray->org, eye, sizeof(eye));
            for (int k = 0; k < 3; k++)
                ray->dir[k] = c[k] - eye[k];
            ray->dir[0] += px * e;
            ray->dir[1] += py * e;
        } else if (kind == 1) {
            for (int k = 0; k < 3; k++) {
                ray->org[k] = tg_range(r, lo[k], hi[k]);
                ray->dir[k] = tg_range(r, -1.0f, 1.0f);
            }
            if (ray->dir[0] == 0.0f && ray->dir[1] == 0.0f && ray->dir[2] == 0.0f)
                ray->dir[2] = 1.0f;
            if (i % 97 == 5)
                ray->tmin = -1.0f; /* the float walk (wide8_walk_tmin_other) */
            if (i % 13 == 7)
                ray->tmax = 0.25f * e;
        } else {
            /* From the camera ray's hit (or its origin on a miss) towards
             * a light above the box, up to it. */
            const RTray *cr = &camera[i];
            const float light[3] = {c[0] - 0.2f * e, hi[1] + 0.7f * e, c[2] + 0.1f * e};
            const float t = cam_found[i] ? cam_hits[i].t : 0.0f;
            for (int k = 0; k < 3; k++) {
                ray->org[k] = cr->org[k] + t * cr->dir[k];
                ray->dir[k] = light[k] - ray->org[k];
            }
            ray->tmin = 1e-4f;
            ray->tmax = 1.0f;
        }
    }
}

/* walk1's answers for rays[0, n). */
static void walk1_all(trace_walk1_fn walk1, const struct bvh4 *wide, const RTray *rays,
                      uint32_t n, int any_hit, struct trace_hit *hits, int *found)
{
    for (uint32_t i = 0; i < n; i++) {
        const RTray *ray = &rays[i];
        memset(&hits[i], 0, sizeof(hits[i]));
        found[i] = walk1(wide, ray->org, ray->dir, ray->tmin, ray->tmax,
                         any_hit ? NULL : &hits[i], NULL);
    }
}

/* The stream over rays[0, n) in pieces of `piece` rays, fibers in flight,
 * against walk1's answers; returns the rays that differ. */
static uint32_t compare_stream(trace_stream_fn stream, const struct bvh4 *wide,
                               const RTray *rays, uint32_t n, int any_hit, unsigned fibers,
                               uint32_t piece, const struct trace_hit *want_hits,
                               const int *want_found, struct trace_hit *hits, int *found)
{
    /* Left over from no walk: a ray the stream skipped keeps them. */
    for (uint32_t i = 0; i < n; i++) {
        found[i] = -1;
        hits[i].t = -7.0f;
        hits[i].u = hits[i].v = -7.0f;
        hits[i].prim = 0xdeadbeefu;
    }
    for (uint32_t b = 0; b < n; b += piece) {
        const uint32_t m = n - b < piece ? n - b : piece;
        stream(wide, rays + b, m, fibers, any_hit ? NULL : hits + b, found + b);
        streams_run++;
    }
    uint32_t bad = 0;
    for (uint32_t i = 0; i < n; i++) {
        int same = found[i] == want_found[i];
        if (same && !any_hit && want_found[i])
            same = bits(hits[i].t) == bits(want_hits[i].t) &&
                   bits(hits[i].u) == bits(want_hits[i].u) &&
                   bits(hits[i].v) == bits(want_hits[i].v) && hits[i].prim == want_hits[i].prim;
        if (!same && bad++ < 3)
            fprintf(stderr,
                    "    ray %u: stream found %d t %a prim %u, walk1 found %d t %a prim %u\n", i,
                    found[i], hits[i].t, hits[i].prim, want_found[i], want_hits[i].t,
                    want_hits[i].prim);
    }
    return bad;
}

static void compare_mesh(const char *name, struct tg_mesh *m, uint32_t rays_per_kind, uint64_t seed)
{
    struct aabb *boxes = tg_boxes(m);
    struct bvh bvh;
    if (accel_build(&bvh, boxes, m->tri_count, NULL)) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    float *tri = accel_gather_triangles(&bvh, m->pos, m->idx);
    struct bvh4 wide;
    if (!tri || accel_collapse_wide(&wide, &bvh, tri, 8)) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (uint32_t i = 0; i < m->vertex_count; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], m->pos[3 * i + k]);
            hi[k] = fmaxf(hi[k], m->pos[3 * i + k]);
        }
    const uint32_t n = rays_per_kind;
    RTray *rays[3];
    struct trace_hit *want_hits[3], *hits = tg_alloc(n * sizeof(*hits));
    int *want_found[3], *found = tg_alloc(n * sizeof(*found));
    for (int kind = 0; kind < 3; kind++) {
        rays[kind] = tg_alloc(n * sizeof(RTray));
        want_hits[kind] = tg_alloc(n * sizeof(struct trace_hit));
        want_found[kind] = tg_alloc(n * sizeof(int));
    }
    printf("  %s: %u triangles, layout %.1f MB\n", name, m->tri_count,
           (double)(bvh4_node_bytes(&wide) + bvh4_leaf_bytes(&wide)) / (1 << 20));
    int tables = 0;
    for (int isa = 0; isa < TRACE_ISA_COUNT; isa++) {
        const struct trace_kernels *k = trace_kernels_get((enum trace_isa)isa);
        if (!k || !k->walk1 || !k->stream_fiber)
            continue;
        tables++;
        struct tg_rng r;
        tg_seed(&r, seed);
        for (int kind = 0; kind < 3; kind++) {
            const int any_hit = kind == 2;
            const trace_walk1_fn walk1 = k->walk1(&wide, any_hit);
            const trace_stream_fn stream = k->stream_fiber(&wide, any_hit);
            if (!walk1 || !stream) {
                failures += !CHECKF(0, "%s %s: walk1 %p, stream %s", name, k->name,
                                    (void *)(uintptr_t)(walk1 != NULL),
                                    stream ? "present" : "absent");
                continue;
            }
            /* The camera rays' closest hits, for the shadow rays. */
            make_rays(rays[kind], n, kind, lo, hi, &r, rays[0], want_hits[0], want_found[0]);
            walk1_all(walk1, &wide, rays[kind], n, any_hit, want_hits[kind], want_found[kind]);
            uint32_t answered = 0;
            for (uint32_t i = 0; i < n; i++)
                answered += want_found[kind][i] != 0;
            static const uint32_t pieces[] = {1, 3, 5, 256, 1u << 30};
            for (unsigned fibers = 1; fibers <= 4; fibers++)
                for (size_t p = 0; p < sizeof(pieces) / sizeof(pieces[0]); p++) {
                    /* The short pieces on the first rays only. */
                    const uint32_t count = pieces[p] < 16 ? (n < 600 ? n : 600) : n;
                    const uint32_t bad =
                        compare_stream(stream, &wide, rays[kind], count, any_hit, fibers,
                                       pieces[p], want_hits[kind], want_found[kind], hits, found);
                    failures += !CHECKF(bad == 0, "%s %s kind %d, %u in flight, pieces of %u: "
                                                  "%u of %u rays differ",
                                        name, k->name, kind, fibers, pieces[p], bad, count);
                }
            printf("    %s %s rays: %u, %u %s\n", k->name,
                   kind == 0 ? "camera" : kind == 1 ? "random" : "shadow", n, answered,
                   any_hit ? "occluded" : "hit");
        }
    }
    if (!tables)
        printf("    no table with a stream entry in this build\n");
    for (int kind = 0; kind < 3; kind++) {
        free(rays[kind]);
        free(want_hits[kind]);
        free(want_found[kind]);
    }
    free(hits);
    free(found);
    bvh4_release(&wide);
    rt_free(tri);
    bvh_release(&bvh);
    free(boxes);
}

int main(void)
{
    printf("stream_fiber:\n");
    struct tg_rng r;
    struct tg_mesh m;
    tg_seed(&r, 60);
    tg_soup(&m, 20000, 2.0f, 0.1f, &r);
    compare_mesh("soup", &m, 20000, 1);
    tg_mesh_free(&m);
    const double zero[3] = {0.0, 0.0, 0.0};
    tg_cube_sphere(&m, 24, 1, 1.0, zero);
    compare_mesh("cube-sphere", &m, 20000, 2);
    tg_mesh_free(&m);
    tg_terrain(&m, 64, &r);
    compare_mesh("terrain", &m, 20000, 3);
    tg_mesh_free(&m);
    tg_soup(&m, 400000, 2.0f, 0.02f, &r);
    compare_mesh("large soup", &m, 40000, 4);
    tg_mesh_free(&m);
    printf("  %d streams\n", streams_run);
    printf("  %s (%d failures)\n", failures ? "FAIL" : "ok", failures);
    return failures ? 1 : 0;
}
