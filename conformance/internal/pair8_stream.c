/* SPDX-License-Identifier: Apache-2.0 */
/*
 * pair8_stream.c - the stream walk that walks two rays at once
 * (lib/trace/traverse_pair8.h, kernels.h's stream_pair) against walk1,
 * ray by ray, bit for bit.
 *
 * The pair walk steps two rays in turn, each with its own state in a
 * slot, and a slot takes the stream's next ray when its ray ends; every
 * ray's walk must stay walk1's, so every answer must be walk1's (found
 * or occluded, and t, u, v, prim of a closest hit).  A pair walk that
 * mixed up two slots' states (a stack, a limit, a hit, the index its
 * answer goes to) would give some ray another ray's answer; one that lost
 * a ray at a refill would leave its answer unwritten.  Checked on random
 * rays, camera rays and shadow rays (from the camera rays' hits toward a
 * light, tmin > 0, t_max 1) over a large random soup (a layout beyond
 * the caches), a cube-sphere and a terrain, with the layout's
 * prefetch_top and any_longest each 0 and 1 (the four walk copies), in
 * streams of 1, 2, 3, 7, 64, 1023 and 1024 rays; some rays with a finite
 * t_max, tmin 0.5, tmin -0, and a negative tmin (the stream hands such a
 * ray to walk1 itself).
 *
 * The counted streams (kernels.h's stream_counted, for the two-level
 * batch walk, trace/scene_stream.h) likewise, and each ray's node tests
 * and the stream's node and triangle totals against the AVX2 table's
 * walk1_counted ray by ray (the stream is the AVX2 walk in every table
 * that has it): a counted stream that lost a step's count, counted a ray
 * twice or stored a count at another ray's place fails.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh_build.h"
#include "accel_testgeo.h"
#include "base/alloc.h"
#include "trace/bvh4_layout.h"
#include "trace/kernels.h"
#include "trace/trace.h"

static int failures;

/* A ray in RTray's layout (org[3], tmin, dir[3], tmax): trace_stream1_fn's. */
struct stream_ray {
    float v[8];
};

static void set_ray(struct stream_ray *r, const float org[3], const float dir[3], float tmin,
                    float tmax)
{
    r->v[0] = org[0];
    r->v[1] = org[1];
    r->v[2] = org[2];
    r->v[3] = tmin;
    r->v[4] = dir[0];
    r->v[5] = dir[1];
    r->v[6] = dir[2];
    r->v[7] = tmax;
}

/* The mesh's bounds. */
static void mesh_bounds(const struct tg_mesh *m, float lo[3], float hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (uint32_t i = 0; i < m->vertex_count; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], m->pos[3 * i + k]);
            hi[k] = fmaxf(hi[k], m->pos[3 * i + k]);
        }
}

/* n random rays (origins in the bounds widened by a quarter, directions
 * uniform on the cube's surface scaled), then n camera rays (a grid from
 * a point outside the bounds toward them), then up to n shadow rays from
 * the camera rays' hits (walk1's) toward a light; returns the count. */
static uint32_t make_rays(const struct tg_mesh *m, const struct bvh4 *wide, trace_walk1_fn closest,
                          uint32_t n, struct tg_rng *r, struct stream_ray *rays)
{
    float lo[3], hi[3];
    mesh_bounds(m, lo, hi);
    uint32_t c = 0;
    for (uint32_t i = 0; i < n; i++) {
        float org[3], dir[3];
        for (int k = 0; k < 3; k++) {
            const float e = 0.25f * (hi[k] - lo[k]);
            org[k] = tg_range(r, lo[k] - e, hi[k] + e);
            dir[k] = tg_range(r, -1.0f, 1.0f);
        }
        if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f)
            dir[0] = 1.0f;
        /* Now and then an axis-parallel direction (zero components). */
        if (i % 17 == 0)
            dir[1] = dir[2] = 0.0f;
        const float tmin = i % 7 == 0   ? 0.5f
                           : i % 13 == 0 ? -0.0f
                           : i % 101 == 0 ? -1.0f
                                          : 0.0f;
        const float tmax = i % 11 == 0 ? 1.0f : INFINITY;
        set_ray(&rays[c++], org, dir, tmin, tmax);
    }
    const float eye[3] = {0.5f * (lo[0] + hi[0]), 0.5f * (lo[1] + hi[1]) + 0.3f * (hi[1] - lo[1]),
                          lo[2] - 1.5f * (hi[2] - lo[2])};
    const uint32_t side = (uint32_t)sqrt((double)n);
    const uint32_t camera0 = c;
    for (uint32_t y = 0; y < side; y++)
        for (uint32_t x = 0; x < side; x++) {
            const float target[3] = {lo[0] + (hi[0] - lo[0]) * ((float)x + 0.5f) / (float)side,
                                     lo[1] + (hi[1] - lo[1]) * ((float)y + 0.5f) / (float)side,
                                     0.5f * (lo[2] + hi[2])};
            const float dir[3] = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
            set_ray(&rays[c++], eye, dir, 0.0f, INFINITY);
        }
    const uint32_t camera1 = c;
    const float light[3] = {hi[0] + (hi[0] - lo[0]), hi[1] + (hi[1] - lo[1]), lo[2]};
    for (uint32_t i = camera0; i < camera1; i++) {
        struct trace_hit h;
        const float *v = rays[i].v;
        if (!closest(wide, v, v + 4, v[3], v[7], &h, NULL))
            continue;
        const float p[3] = {v[0] + h.t * v[4], v[1] + h.t * v[5], v[2] + h.t * v[6]};
        const float dir[3] = {light[0] - p[0], light[1] - p[1], light[2] - p[2]};
        set_ray(&rays[c++], p, dir, 1e-4f, 1.0f);
    }
    return c;
}

static const uint32_t chunk_sizes[] = {1, 2, 3, 7, 64, 1023, 1024};

/* The stream entry against walk1 on every ray, in streams cycling
 * through chunk_sizes. */
static void compare_stream(const char *name, const char *tname, const struct bvh4 *wide,
                           trace_walk1_fn walk1, trace_stream1_fn stream, int any_hit,
                           const struct stream_ray *rays, uint32_t count);

/* The counted stream against walk1_counted (`counted`, the AVX2 table's
 * walk for the layout) on every ray: answers, each ray's node tests, and
 * the totals. */
static void compare_counted(const char *name, const char *tname, const struct bvh4 *wide,
                            trace_walk1_fn counted, trace_stream1_counted_fn stream, int any_hit,
                            const struct stream_ray *rays, uint32_t count)
{
    struct trace_hit *hits = tg_alloc(sizeof(*hits) * 1024);
    uint32_t *nodes = tg_alloc(sizeof(*nodes) * 1024);
    unsigned char got[1024];
    uint32_t differ = 0;
    struct trace_counters total = {0, 0}, want_total = {0, 0};
    uint32_t s = 0;
    for (uint32_t b = 0; b < count; s++) {
        uint32_t n = chunk_sizes[s % (sizeof(chunk_sizes) / sizeof(chunk_sizes[0]))];
        if (n > count - b)
            n = count - b;
        memset(hits, 0xA5, sizeof(*hits) * n);
        memset(nodes, 0xA5, sizeof(*nodes) * n);
        memset(got, 0xA5, n);
        stream(wide, rays[b].v, 8, n, any_hit ? NULL : hits, got, &total, nodes);
        for (uint32_t i = 0; i < n; i++) {
            const float *v = rays[b + i].v;
            struct trace_hit h;
            memset(&h, 0, sizeof(h));
            struct trace_counters c = {0, 0};
            const int want = counted(wide, v, v + 4, v[3], v[7], any_hit ? NULL : &h, &c);
            want_total.node_tests += c.node_tests;
            want_total.triangle_tests += c.triangle_tests;
            int bad = got[i] != (unsigned char)want || nodes[i] != c.node_tests;
            if (!bad && want && !any_hit)
                bad = memcmp(&h, &hits[i], sizeof(h)) != 0;
            if (bad) {
                if (differ < 5)
                    printf("    %s %s %s counted ray %u (stream of %u): got %d/%d nodes %u/%u\n",
                           name, tname, any_hit ? "any" : "closest", b + i, n, got[i], want,
                           nodes[i], (unsigned)c.node_tests);
                differ++;
            }
        }
        b += n;
    }
    printf("  %s %s %s counted: %u rays, %u differ, node tests %llu/%llu, triangle tests "
           "%llu/%llu\n",
           name, tname, any_hit ? "any" : "closest", count, differ,
           (unsigned long long)total.node_tests, (unsigned long long)want_total.node_tests,
           (unsigned long long)total.triangle_tests,
           (unsigned long long)want_total.triangle_tests);
    failures += !CHECKF(differ == 0 && total.node_tests == want_total.node_tests &&
                            total.triangle_tests == want_total.triangle_tests,
                        "%s %s: the counted stream differs from walk1_counted (%u rays)", name,
                        tname, differ);
    free(nodes);
    free(hits);
}

static void compare_stream(const char *name, const char *tname, const struct bvh4 *wide,
                           trace_walk1_fn walk1, trace_stream1_fn stream, int any_hit,
                           const struct stream_ray *rays, uint32_t count)
{
    struct trace_hit *hits = tg_alloc(sizeof(*hits) * 1024);
    unsigned char got[1024];
    uint32_t differ = 0, found = 0;
    uint32_t s = 0;
    for (uint32_t b = 0; b < count; s++) {
        uint32_t n = chunk_sizes[s % (sizeof(chunk_sizes) / sizeof(chunk_sizes[0]))];
        if (n > count - b)
            n = count - b;
        /* Poisoned: a ray whose answer the stream does not write fails. */
        memset(hits, 0xA5, sizeof(*hits) * n);
        memset(got, 0xA5, n);
        stream(wide, rays[b].v, 8, n, any_hit ? NULL : hits, got);
        for (uint32_t i = 0; i < n; i++) {
            const float *v = rays[b + i].v;
            struct trace_hit h;
            memset(&h, 0, sizeof(h));
            const int want = walk1(wide, v, v + 4, v[3], v[7], any_hit ? NULL : &h, NULL);
            int bad = got[i] != (unsigned char)want;
            if (!bad && want && !any_hit)
                bad = memcmp(&h, &hits[i], sizeof(h)) != 0;
            found += want != 0;
            if (bad) {
                if (differ < 5)
                    printf("    %s %s %s ray %u (stream of %u): got %d/%d t %a/%a prim %u/%u\n",
                           name, tname, any_hit ? "any" : "closest", b + i, n, got[i], want,
                           hits[i].t, h.t, hits[i].prim, h.prim);
                differ++;
            }
        }
        b += n;
    }
    printf("  %s %s %s: %u rays, %u answered, %u differ\n", name, tname,
           any_hit ? "any" : "closest", count, found, differ);
    failures += !CHECKF(differ == 0, "%s %s: the pair walk differs from walk1 on %u rays", name,
                        tname, differ);
    free(hits);
}

static void compare_mesh(const char *name, const struct tg_mesh *m, uint32_t n, uint64_t seed)
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
    struct stream_ray *rays = tg_alloc(sizeof(*rays) * 3 * (size_t)n);
    int tables = 0;
    for (int isa = TRACE_ISA_SCALAR; isa < TRACE_ISA_COUNT; isa++) {
        const struct trace_kernels *k = trace_kernels_get((enum trace_isa)isa);
        if (!k || !k->stream_pair || !k->walk1)
            continue;
        tables++;
        for (int flags = 0; flags < 4; flags++) {
            struct bvh4 wp = wide; /* shallow: the walks read the flags only */
            wp.prefetch_top = (uint32_t)(flags & 1);
            wp.any_longest = (uint32_t)(flags >> 1);
            const trace_walk1_fn closest = k->walk1(&wp, 0);
            if (!closest) {
                failures += !CHECKF(!k->stream_pair(&wp, 0) && !k->stream_pair(&wp, 1),
                                    "%s: stream_pair without walk1", k->name);
                continue;
            }
            struct tg_rng r;
            tg_seed(&r, seed);
            const uint32_t count = make_rays(m, &wp, closest, n, &r, rays);
            char tname[64];
            snprintf(tname, sizeof(tname), "%s prefetch_top %d any_longest %d", k->name,
                     flags & 1, flags >> 1);
            for (int any_hit = 0; any_hit < 2; any_hit++)
                compare_stream(name, tname, &wp, k->walk1(&wp, any_hit),
                               k->stream_pair(&wp, any_hit), any_hit, rays, count);
            const struct trace_kernels *avx2 = trace_kernels_get(TRACE_ISA_AVX2);
            failures += !CHECKF(k->stream_counted && avx2 && avx2->walk1_counted,
                                "%s: stream_pair without stream_counted", k->name);
            if (!k->stream_counted || !avx2 || !avx2->walk1_counted)
                continue;
            for (int any_hit = 0; any_hit < 2; any_hit++)
                compare_counted(name, tname, &wp,
                                avx2->walk1_counted[2 * any_hit +
                                                    ((any_hit ? wp.any_longest
                                                              : wp.prefetch_top) != 0)],
                                k->stream_counted(&wp, any_hit), any_hit, rays, count);
        }
    }
    if (!tables)
        printf("  %s: no table of this CPU has the pair walk\n", name);
    free(rays);
    rt_free(tri);
    bvh4_release(&wide);
    bvh_release(&bvh);
    free(boxes);
}

int main(void)
{
    printf("pair8_stream:\n");
    struct tg_rng r;
    struct tg_mesh m;
    tg_seed(&r, 60);
    tg_soup(&m, 200000, 4.0f, 0.05f, &r);
    compare_mesh("soup 200k", &m, 6000, 61);
    tg_mesh_free(&m);
    const double zero[3] = {0.0, 0.0, 0.0};
    tg_cube_sphere(&m, 24, 1, 1.0, zero);
    compare_mesh("sphere", &m, 6000, 62);
    tg_mesh_free(&m);
    tg_terrain(&m, 64, &r);
    compare_mesh("terrain", &m, 6000, 63);
    tg_mesh_free(&m);
    return failures ? 1 : 0;
}
