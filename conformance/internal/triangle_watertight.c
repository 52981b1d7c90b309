/* SPDX-License-Identifier: Apache-2.0 */
/*
 * triangle_watertight.c - the ray/triangle kernel (trace_triangle, Woop,
 * Benthin and Wald 2013) and the traversal above it on closed meshes.
 *
 * - No cracks: rays aimed exactly at shared vertices and at points of
 *   shared edges of closed meshes (a subdivided cube with flat,
 *   axis-aligned faces and a cube-sphere), at the origin and translated to
 *   1e5, scaled by 1e-4 and 1e4, from inside and from outside: about 1M
 *   rays, and every one must hit, both when only the triangles around the
 *   target are tested and through the BVH (trace_closest and trace_any).
 *   Axis-parallel rays (zero direction components, both signs of zero)
 *   along the cube's faces and to the sphere's vertices likewise.
 * - Exact edge decisions: for axis-parallel rays on exactly representable
 *   data, hit or miss matches the exact orientation, within an ulp of an
 *   edge too (what the double-precision fallback of sec. 4 is for).
 * - Degenerate triangles (a point, repeated vertices, collinear distinct
 *   vertices) are never hit, by rays aimed right at them, from any side.
 * - Hit points: t agrees with a double-precision plane intersection on
 *   proper triangles, and hits on accidental slivers (collinear vertices
 *   rotated and rounded apart) lie on their segment.
 * - Thin slivers, coplanar (edge-on) rays and huge coordinates never give
 *   a NaN: a hit has finite t, and u, v in [0, 1] with u + v <= 1.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh_build.h"
#include "accel_testgeo.h"
#include "base/alloc.h"
#include "base/timer.h"
#include "trace/trace.h"

static int failures;
static uint64_t rays_total;

/* Triangles around each vertex and the two triangles of each edge. */
struct adjacency {
    uint32_t *vertex_first; /* CSR over vertices */
    uint32_t *vertex_tris;
    uint32_t (*edge_verts)[2];
    uint32_t (*edge_tris)[2];
    uint32_t edge_count;
};

struct half_edge {
    uint32_t lo, hi, tri;
};

static int by_edge(const void *pa, const void *pb)
{
    const struct half_edge *a = pa;
    const struct half_edge *b = pb;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    return a->tri < b->tri ? -1 : a->tri > b->tri;
}

static void build_adjacency(const struct tg_mesh *m, struct adjacency *adj)
{
    adj->vertex_first = calloc(m->vertex_count + 1, sizeof(uint32_t));
    adj->vertex_tris = tg_alloc(sizeof(uint32_t) * 3 * m->tri_count);
    for (uint32_t i = 0; i < 3 * m->tri_count; i++)
        adj->vertex_first[m->idx[i] + 1]++;
    for (uint32_t v = 0; v < m->vertex_count; v++) {
        failures += !CHECKF(adj->vertex_first[v + 1] <= 32, "valence %u > 32",
                 adj->vertex_first[v + 1]);
        adj->vertex_first[v + 1] += adj->vertex_first[v];
    }
    uint32_t *fill = tg_alloc(sizeof(uint32_t) * (m->vertex_count + 1));
    memcpy(fill, adj->vertex_first, sizeof(uint32_t) * (m->vertex_count + 1));
    for (uint32_t i = 0; i < 3 * m->tri_count; i++)
        adj->vertex_tris[fill[m->idx[i]]++] = i / 3;
    free(fill);

    struct half_edge *he = tg_alloc(sizeof(*he) * 3 * m->tri_count);
    for (uint32_t t = 0; t < m->tri_count; t++) {
        for (int e = 0; e < 3; e++) {
            uint32_t a = m->idx[3 * t + e];
            uint32_t b = m->idx[3 * t + (e + 1) % 3];
            he[3 * t + e].lo = a < b ? a : b;
            he[3 * t + e].hi = a < b ? b : a;
            he[3 * t + e].tri = t;
        }
    }
    qsort(he, 3 * m->tri_count, sizeof(*he), by_edge);
    adj->edge_count = 3 * m->tri_count / 2;
    adj->edge_verts = tg_alloc(sizeof(*adj->edge_verts) * adj->edge_count);
    adj->edge_tris = tg_alloc(sizeof(*adj->edge_tris) * adj->edge_count);
    for (uint32_t e = 0; e < adj->edge_count; e++) {
        const struct half_edge *a = &he[2 * e];
        const struct half_edge *b = &he[2 * e + 1];
        /* Closed and manifold: every edge exactly twice. */
        failures += !CHECKF(a->lo == b->lo && a->hi == b->hi &&
                               (2 * e + 2 == 3 * m->tri_count || he[2 * e + 2].lo != a->lo ||
                                he[2 * e + 2].hi != a->hi),
                 "test mesh not closed at edge %u", e);
        adj->edge_verts[e][0] = a->lo;
        adj->edge_verts[e][1] = a->hi;
        adj->edge_tris[e][0] = a->tri;
        adj->edge_tris[e][1] = b->tri;
    }
    free(he);
}

static void free_adjacency(struct adjacency *adj)
{
    free(adj->vertex_first);
    free(adj->vertex_tris);
    free(adj->edge_verts);
    free(adj->edge_tris);
}

static int hit_is_sane(float t, float u, float v)
{
    return isfinite(t) && isfinite(u) && isfinite(v) && u >= 0.0f && v >= 0.0f &&
           u <= 1.0f && v <= 1.0f && u + v <= 1.0f + 1e-6f;
}

/* Kernel alone: does any of the listed triangles report a hit? */
static int hits_any_of(const struct tg_mesh *m, const struct trace_ray *ray, const uint32_t *tris,
                       uint32_t count)
{
    int hit = 0;
    for (uint32_t i = 0; i < count; i++) {
        float t, u, v;
        if (trace_triangle(ray, tg_vertex(m, tris[i], 0), tg_vertex(m, tris[i], 1),
                           tg_vertex(m, tris[i], 2), INFINITY, &t, &u, &v)) {
            failures += !CHECKF(hit_is_sane(t, u, v), "insane hit t=%g u=%g v=%g", t, u, v);
            hit = 1;
        }
    }
    return hit;
}

struct scene {
    struct tg_mesh mesh;
    struct adjacency adj;
    struct bvh bvh;
    float *tri;
    double center[3];
    double radius;
};

/* One ray: trace it through the kernel (candidates) and the BVH. */
static void shoot(const struct scene *sc, const char *name, const float org[3], const float dir[3],
                  const uint32_t *candidates, uint32_t candidate_count, uint64_t *leaks)
{
    if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f)
        return;
    struct trace_ray ray;
    trace_ray_init(&ray, org, dir, 0.0f);
    rays_total++;
    int direct = hits_any_of(&sc->mesh, &ray, candidates, candidate_count);
    struct trace_hit h;
    int closest = trace_closest(&sc->bvh, sc->tri, &ray, INFINITY, &h, NULL);
    int any = trace_any(&sc->bvh, sc->tri, &ray, INFINITY, NULL);
    if (closest)
        failures += !CHECKF(hit_is_sane(h.t, h.u, h.v), "%s: insane closest hit", name);
    if (!direct || !closest || !any) {
        if ((*leaks)++ < 5)
            fprintf(stderr,
                    "%s: leak (direct %d closest %d any %d) org %.9g %.9g %.9g dir %.9g %.9g "
                    "%.9g\n",
                    name, direct, closest, any, org[0], org[1], org[2], dir[0], dir[1], dir[2]);
    }
}

static void random_unit(struct tg_rng *r, double d[3])
{
    double len;
    do {
        for (int k = 0; k < 3; k++)
            d[k] = 2.0 * tg_unit(r) - 1.0;
        len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    } while (len < 0.1 || len > 1.0);
    for (int k = 0; k < 3; k++)
        d[k] /= len;
}

/* Rays at vertices and edge points, from inside and from outside.  Valence
 * is at most 6 on these meshes, so two rings fit in 64 entries. */
static void aimed_rays(const struct scene *sc, const char *name, uint32_t count,
                       struct tg_rng *r, uint64_t *leaks)
{
    const struct tg_mesh *m = &sc->mesh;
    uint32_t ring[64];
    for (uint32_t i = 0; i < count; i++) {
        float target[3];
        const uint32_t *cand;
        uint32_t cand_count;
        if (i & 1) {
            uint32_t v = tg_below(r, m->vertex_count);
            memcpy(target, &m->pos[3 * v], sizeof(target));
            cand = &sc->adj.vertex_tris[sc->adj.vertex_first[v]];
            cand_count = sc->adj.vertex_first[v + 1] - sc->adj.vertex_first[v];
        } else {
            uint32_t e = tg_below(r, sc->adj.edge_count);
            uint32_t va = sc->adj.edge_verts[e][0];
            uint32_t vb = sc->adj.edge_verts[e][1];
            const float *a = &m->pos[3 * va];
            const float *b = &m->pos[3 * vb];
            float s = tg_range(r, 0.001f, 0.999f);
            if (i % 8 == 0)
                s = 0.5f;
            for (int k = 0; k < 3; k++)
                target[k] = a[k] + s * (b[k] - a[k]);
            /* The rounded target can lie off the edge by more than its
             * distance to an end (at 1e5, floats are 1/128 apart), so
             * the candidates are the triangles around both ends, which
             * cover a neighbourhood of the whole edge. */
            uint32_t na = sc->adj.vertex_first[va + 1] - sc->adj.vertex_first[va];
            uint32_t nb = sc->adj.vertex_first[vb + 1] - sc->adj.vertex_first[vb];
            memcpy(ring, &sc->adj.vertex_tris[sc->adj.vertex_first[va]], na * sizeof(uint32_t));
            memcpy(ring + na, &sc->adj.vertex_tris[sc->adj.vertex_first[vb]],
                   nb * sizeof(uint32_t));
            cand = ring;
            cand_count = na + nb;
        }
        /* A point well inside (within half the radius of the centre). */
        double d[3];
        random_unit(r, d);
        double f = 0.5 * sc->radius * tg_unit(r);
        double q[3];
        for (int k = 0; k < 3; k++)
            q[k] = sc->center[k] + f * d[k];
        float org[3];
        if (i % 4 < 2) {
            for (int k = 0; k < 3; k++)
                org[k] = (float)q[k];
        } else {
            /* Outside, on the line from the target through q: the ray
             * crosses the interior and leaves through the target, so it
             * cannot merely graze the surface there. */
            double len = 0.0;
            for (int k = 0; k < 3; k++)
                len += (q[k] - target[k]) * (q[k] - target[k]);
            double back = 4.0 * sc->radius / sqrt(len);
            for (int k = 0; k < 3; k++)
                org[k] = (float)(q[k] + back * (q[k] - target[k]));
        }
        float dir[3];
        for (int k = 0; k < 3; k++)
            dir[k] = target[k] - org[k];
        shoot(sc, name, org, dir, cand, cand_count, leaks);
    }
}

/* Axis-parallel rays: from inside, along the axis where the target vertex
 * is furthest from the centre, with the other two direction components
 * zero of either sign.  On the cube, a vertex on a cube edge makes the
 * ray run inside the plane of the adjacent face and leave exactly through
 * the edge: every edge function involved is zero. */
static void axis_rays(const struct scene *sc, const char *name, uint32_t count,
                      struct tg_rng *r, uint64_t *leaks)
{
    const struct tg_mesh *m = &sc->mesh;
    for (uint32_t i = 0; i < count; i++) {
        uint32_t v = tg_below(r, m->vertex_count);
        const float *p = &m->pos[3 * v];
        int axis = 0;
        double best = -1.0;
        for (int k = 0; k < 3; k++) {
            double d = fabs(p[k] - sc->center[k]);
            if (d > best) {
                best = d;
                axis = k;
            }
        }
        float org[3];
        float dir[3];
        memcpy(org, p, sizeof(org));
        double sgn = p[axis] > sc->center[axis] ? 1.0 : -1.0;
        org[axis] = (float)(p[axis] - sgn * tg_range(r, 0.1f, 0.5f) * sc->radius);
        for (int k = 0; k < 3; k++)
            dir[k] = (tg_next(r) & 1) ? -0.0f : 0.0f;
        dir[axis] = (float)sgn * tg_range(r, 0.5f, 2.0f);
        shoot(sc, name, org, dir, &sc->adj.vertex_tris[sc->adj.vertex_first[v]],
              sc->adj.vertex_first[v + 1] - sc->adj.vertex_first[v], leaks);
    }
}

static void closed_mesh(const char *name, int sphere, int g, double scale, double ox, double oy,
                        double oz, enum bvh_builder builder, uint32_t rays, uint64_t seed)
{
    struct scene sc;
    const double offset[3] = {ox, oy, oz};
    tg_cube_sphere(&sc.mesh, g, sphere, scale, offset);
    memcpy(sc.center, offset, sizeof(offset));
    sc.radius = scale;
    build_adjacency(&sc.mesh, &sc.adj);
    for (uint32_t t = 0; t < sc.mesh.tri_count; t++)
        failures += !CHECKF(
                 !tg_zero_area(tg_vertex(&sc.mesh, t, 0), tg_vertex(&sc.mesh, t, 1),
                               tg_vertex(&sc.mesh, t, 2)),
                 "%s: test mesh has a zero-area triangle %u", name, t);
    struct aabb *boxes = tg_boxes(&sc.mesh);
    struct bvh_build_params p;
    bvh_build_params_default(&p);
    p.builder = builder;
    if (accel_build(&sc.bvh, boxes, sc.mesh.tri_count, &p) != 0) {
        fprintf(stderr, "build failed\n");
        exit(2);
    }
    free(boxes);
    sc.tri = accel_gather_triangles(&sc.bvh, sc.mesh.pos, sc.mesh.idx);

    struct tg_rng r;
    tg_seed(&r, seed);
    uint64_t leaks = 0;
    aimed_rays(&sc, name, rays, &r, &leaks);
    axis_rays(&sc, name, rays / 8, &r, &leaks);
    failures += !CHECKF(leaks == 0, "%s: %llu of %u rays leaked", name, (unsigned long long)leaks,
             rays + rays / 8);
    printf("  %-14s %5u triangles, %7u rays, %llu leaks\n", name, sc.mesh.tri_count,
           rays + rays / 8, (unsigned long long)leaks);
    rt_free(sc.tri);
    bvh_release(&sc.bvh);
    free_adjacency(&sc.adj);
    tg_mesh_free(&sc.mesh);
}

/* Zero-area triangles: never hit, whatever the ray. */
static void degenerate_triangles(void)
{
    const float a[3] = {0.5f, 0.25f, 1.0f};
    const float d[3] = {0.125f, 0.375f, -0.25f};
    float b[3], c[3], mid[3], far[3];
    for (int k = 0; k < 3; k++) {
        b[k] = a[k] + d[k];
        mid[k] = a[k] + 0.5f * d[k];
        far[k] = a[k] + 3.0f * d[k];
        c[k] = a[k] + 2.0f * d[k];
    }
    const float x0[3] = {-1.0f, 0.0f, 0.0f};
    const float x1[3] = {1.0f, 0.0f, 0.0f};
    const float x2[3] = {0.0f, 0.0f, 0.0f};
    const float *tris[][3] = {
        {a, a, a},   {a, a, b},   {a, b, a},   {b, a, a},   {a, b, mid},
        {a, mid, b}, {mid, a, b}, {a, b, far}, {a, far, c}, {x0, x1, x2},
        {x1, x0, x2}, {x0, x2, x1},
    };
    const size_t tri_count = sizeof(tris) / sizeof(tris[0]);
    struct tg_rng r;
    tg_seed(&r, 77);
    uint32_t hits = 0;
    uint32_t tested = 0;
    for (size_t t = 0; t < tri_count; t++) {
        failures += !CHECKF(tg_zero_area(tris[t][0], tris[t][1], tris[t][2]), "fixture %zu", t);
        for (int i = 0; i < 20000; i++) {
            /* Aim at a vertex, the midpoint of an edge, or a random point
             * of the segment; from a random origin, sometimes along an
             * axis, sometimes along the segment itself. */
            float target[3];
            int corner = i % 3;
            float s = (i % 5 == 0) ? 0.5f : tg_unit(&r);
            const float *p = tris[t][corner];
            const float *q = tris[t][(corner + 1) % 3];
            for (int k = 0; k < 3; k++)
                target[k] = (i % 4 == 0) ? p[k] : p[k] + s * (q[k] - p[k]);
            float org[3], dir[3];
            double u[3];
            random_unit(&r, u);
            for (int k = 0; k < 3; k++)
                org[k] = target[k] + (float)(2.0 * u[k]);
            if (i % 7 == 0) {
                int axis = i % 3;
                memcpy(org, target, sizeof(org));
                org[axis] -= 1.0f;
            }
            if (i % 11 == 0) {
                for (int k = 0; k < 3; k++)
                    org[k] = q[k] + (q[k] - p[k]);
            }
            for (int k = 0; k < 3; k++)
                dir[k] = target[k] - org[k];
            if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f)
                continue;
            struct trace_ray ray;
            trace_ray_init(&ray, org, dir, -INFINITY);
            float th = NAN, uh = NAN, vh = NAN;
            tested++;
            if (trace_triangle(&ray, tris[t][0], tris[t][1], tris[t][2], INFINITY, &th, &uh,
                               &vh)) {
                if (hits++ < 5)
                    fprintf(stderr, "degenerate fixture %zu hit at t=%g\n", t, th);
            }
        }
    }
    failures += !CHECKF(hits == 0, "%u of %u rays hit zero-area triangles", hits, tested);
    printf("  zero-area triangles: %u rays, %u hits\n", tested, hits);

    /* The same through a BVH: a mesh of degenerate triangles only. */
    struct tg_mesh m;
    tg_mesh_alloc(&m, (uint32_t)(3 * tri_count), (uint32_t)tri_count);
    for (size_t t = 0; t < tri_count; t++) {
        for (int v = 0; v < 3; v++) {
            memcpy(&m.pos[9 * t + 3 * v], tris[t][v], 3 * sizeof(float));
            m.idx[3 * t + v] = (uint32_t)(3 * t + v);
        }
    }
    struct aabb *boxes = tg_boxes(&m);
    struct bvh bvh;
    if (accel_build(&bvh, boxes, m.tri_count, NULL) == 0) {
        float *tri = accel_gather_triangles(&bvh, m.pos, m.idx);
        for (int i = 0; i < 20000; i++) {
            float org[3], dir[3];
            double u[3];
            random_unit(&r, u);
            const float *target = tris[i % tri_count][i % 3];
            for (int k = 0; k < 3; k++) {
                org[k] = target[k] + (float)u[k];
                dir[k] = target[k] - org[k];
            }
            struct trace_ray ray;
            struct trace_hit h;
            trace_ray_init(&ray, org, dir, 0.0f);
            failures += !CHECKF(!trace_closest(&bvh, tri, &ray, INFINITY, &h, NULL),
                     "degenerate mesh hit through the BVH");
            failures += !CHECKF(!trace_any(&bvh, tri, &ray, INFINITY, NULL),
                     "degenerate mesh any-hit through the BVH");
        }
        rt_free(tri);
        bvh_release(&bvh);
    }
    free(boxes);
    tg_mesh_free(&m);
}

/*
 * Exact edge decisions.  For an axis-parallel ray and coordinates whose
 * differences are exact (Sterbenz: all in [0.5, 1]), the sheared vertices
 * are exact, so the kernel's inside test must match the exact orientation
 * of the ray's origin against each edge.  Rounded float products can only
 * collapse a sign to zero, never flip it (rounding is monotonic), and the
 * double-precision recomputation of sec. 4 restores the sign when they
 * do: without it, points just outside an edge would count as on it.
 * Origins are placed within an ulp of an edge, where that happens.
 */
static double orient(const float p[2], const float q[2], const float o[2])
{
    /* Differences of floats in [0.5, 1] and their products are exact in
     * double; the final difference rounds once, monotonically. */
    return ((double)q[0] - p[0]) * ((double)o[1] - p[1]) -
           ((double)q[1] - p[1]) * ((double)o[0] - p[0]);
}

static void exact_edges(void)
{
    struct tg_rng r;
    tg_seed(&r, 2013);
    uint32_t mismatches = 0;
    uint32_t rays = 0;
    uint32_t hits = 0;
    for (int i = 0; i < 200000; i++) {
        float tri2[3][2];
        for (int v = 0; v < 3; v++) {
            tri2[v][0] = tg_range(&r, 0.5f, 1.0f);
            tri2[v][1] = tg_range(&r, 0.5f, 1.0f);
        }
        double area = orient(tri2[0], tri2[1], tri2[2]);
        if (area == 0.0)
            continue;
        /* A point of an edge, rounded, then nudged by up to 2 ulps. */
        int e = (int)tg_below(&r, 3);
        double s = tg_unit(&r);
        float o2[2];
        for (int k = 0; k < 2; k++) {
            double x = tri2[e][k] + s * ((double)tri2[(e + 1) % 3][k] - tri2[e][k]);
            o2[k] = (float)x;
            for (int step = (int)tg_below(&r, 5) - 2; step != 0; step += step > 0 ? -1 : 1)
                o2[k] = nextafterf(o2[k], step > 0 ? 2.0f : 0.0f);
            if (o2[k] < 0.5f || o2[k] > 1.0f)
                o2[k] = (float)x;
        }
        double e0 = orient(tri2[1], tri2[2], o2);
        double e1 = orient(tri2[2], tri2[0], o2);
        double e2 = orient(tri2[0], tri2[1], o2);
        int inside = (e0 >= 0.0 && e1 >= 0.0 && e2 >= 0.0) || (e0 <= 0.0 && e1 <= 0.0 && e2 <= 0.0);
        /* Embed the 2D problem with the free axis a: the plane a = 0.75,
         * the ray along a from either side, zeros of either sign. */
        int a = i % 3;
        int ax = (a + 1) % 3;
        int ay = (a + 2) % 3;
        float v[3][3];
        for (int t = 0; t < 3; t++) {
            v[t][a] = 0.75f;
            v[t][ax] = tri2[t][0];
            v[t][ay] = tri2[t][1];
        }
        float org[3], dir[3];
        int from_below = (i / 3) & 1;
        org[a] = from_below ? 0.5f : 1.0f;
        org[ax] = o2[0];
        org[ay] = o2[1];
        dir[a] = from_below ? 0.25f : -0.25f;
        dir[ax] = (i & 8) ? -0.0f : 0.0f;
        dir[ay] = (i & 16) ? -0.0f : 0.0f;
        struct trace_ray ray;
        trace_ray_init(&ray, org, dir, 0.0f);
        float t, u, w;
        int hit = trace_triangle(&ray, v[0], v[1], v[2], INFINITY, &t, &u, &w);
        rays++;
        hits += (uint32_t)hit;
        if (hit != inside) {
            if (mismatches++ < 5)
                fprintf(stderr, "exact edges: hit %d, exact inside %d (%.3g %.3g %.3g)\n", hit,
                        inside, e0, e1, e2);
        } else if (hit) {
            failures += !CHECKF(fabsf(t - 1.0f) <= 1e-6f && hit_is_sane(t, u, w), "exact edges: t=%.9g u=%.9g v=%.9g", t, u, w);
        }
    }
    failures += !CHECKF(mismatches == 0, "%u of %u edge decisions differ from exact", mismatches,
             rays);
    printf("  exact edge decisions: %u rays within 2 ulps of an edge, %u inside, %u wrong\n", rays,
           hits, mismatches);
}

/*
 * Where the hits are.  Proper triangles: t matches a double-precision
 * plane intersection to 1e-6 relative.  Accidental slivers (collinear
 * triples rotated, then rounded to float, so a hair of area remains):
 * a hit may happen, but its point must lie on the segment, within 1e-5 of
 * its length; t from the rounded barycentric weights alone lands anywhere
 * along it.
 */
static void hit_points(void)
{
    struct tg_rng r;
    tg_seed(&r, 90210);
    uint32_t bad_t = 0, proper_hits = 0, sliver_hits = 0, off_segment = 0, rays = 0;
    for (int i = 0; i < 100000; i++) {
        /* A random orientation: two orthonormal directions (Gram-Schmidt
         * on two random ones) span the triangle's plane. */
        double a[3], b[3];
        random_unit(&r, a);
        random_unit(&r, b);
        double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        for (int k = 0; k < 3; k++)
            b[k] -= ab * a[k];
        double bl = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
        if (bl < 1e-3)
            continue;
        for (int k = 0; k < 3; k++)
            b[k] /= bl;
        int sliver = i & 1;
        /* Local triangle: (0,0), (L,0), (s L, h) with h = 0 for a sliver. */
        double len = tg_range(&r, 0.5f, 4.0f);
        double s = tg_range(&r, 0.1f, 0.9f);
        double h = sliver ? 0.0 : tg_range(&r, 0.2f, 2.0f);
        double local[3][2] = {{0.0, 0.0}, {len, 0.0}, {s * len, h}};
        double off[3] = {tg_range(&r, -3.0f, 3.0f), tg_range(&r, -3.0f, 3.0f),
                         tg_range(&r, -3.0f, 3.0f)};
        float v[3][3];
        for (int t = 0; t < 3; t++)
            for (int k = 0; k < 3; k++)
                v[t][k] = (float)(off[k] + local[t][0] * a[k] + local[t][1] * b[k]);
        if (tg_zero_area(v[0], v[1], v[2]))
            continue; /* rounding left it exactly collinear: never hit */
        /* Aim at a point of the triangle (for slivers: of the segment). */
        double wu = tg_unit(&r), wv = sliver ? 0.0 : tg_unit(&r) * (1.0 - wu);
        double target[3], dir_d[3];
        double oc[3];
        random_unit(&r, oc);
        float org[3], dir[3];
        for (int k = 0; k < 3; k++) {
            target[k] = (1.0 - wu - wv) * v[0][k] + wu * v[1][k] + wv * v[2][k];
            org[k] = (float)(target[k] + 5.0 * oc[k]);
            dir[k] = (float)(target[k] - org[k]);
        }
        struct trace_ray ray;
        trace_ray_init(&ray, org, dir, 0.0f);
        float t, u, w;
        rays++;
        if (!trace_triangle(&ray, v[0], v[1], v[2], INFINITY, &t, &u, &w))
            continue;
        for (int k = 0; k < 3; k++)
            dir_d[k] = dir[k];
        double p[3];
        for (int k = 0; k < 3; k++)
            p[k] = org[k] + (double)t * dir_d[k];
        if (sliver) {
            /* Distance from p to the segment v0 v1. */
            double e[3], q[3], ee = 0.0, eq = 0.0;
            for (int k = 0; k < 3; k++) {
                e[k] = (double)v[1][k] - v[0][k];
                q[k] = p[k] - v[0][k];
                ee += e[k] * e[k];
                eq += e[k] * q[k];
            }
            double f = eq / ee;
            f = f < 0.0 ? 0.0 : (f > 1.0 ? 1.0 : f);
            double d2 = 0.0;
            for (int k = 0; k < 3; k++)
                d2 += (q[k] - f * e[k]) * (q[k] - f * e[k]);
            sliver_hits++;
            if (sqrt(d2) > 1e-5 * len && off_segment++ < 5)
                fprintf(stderr, "sliver hit %.3g off its segment (t=%.9g)\n", sqrt(d2), t);
        } else {
            /* Reference: the plane of the float vertices, in double. */
            double e1[3], e2[3], n[3], num = 0.0, den = 0.0;
            for (int k = 0; k < 3; k++) {
                e1[k] = (double)v[1][k] - v[0][k];
                e2[k] = (double)v[2][k] - v[0][k];
            }
            n[0] = e1[1] * e2[2] - e1[2] * e2[1];
            n[1] = e1[2] * e2[0] - e1[0] * e2[2];
            n[2] = e1[0] * e2[1] - e1[1] * e2[0];
            for (int k = 0; k < 3; k++) {
                num += n[k] * ((double)v[0][k] - org[k]);
                den += n[k] * dir_d[k];
            }
            double t_ref = num / den;
            proper_hits++;
            if (fabs(t - t_ref) > 1e-6 * fabs(t_ref) && bad_t++ < 5)
                fprintf(stderr, "t %.9g, plane says %.9g\n", t, t_ref);
        }
    }
    failures += !CHECKF(off_segment == 0, "%u of %u sliver hits off their segment", off_segment,
             sliver_hits);
    failures += !CHECKF(bad_t == 0 && proper_hits > rays / 3, "%u of %u proper hits with a bad t",
             bad_t, proper_hits);
    printf("  hit points: %u rays, %u proper hits (t within 1e-6), %u sliver hits (on the "
           "segment)\n",
           rays, proper_hits, sliver_hits);
}

/* Slivers, edge-on rays and huge coordinates: any hit must be sane. */
static void no_nan(void)
{
    struct tg_rng r;
    tg_seed(&r, 4242);
    uint32_t sliver_hits = 0;
    uint32_t rays = 0;
    for (int i = 0; i < 200000; i++) {
        float v0[3], v1[3], v2[3], org[3], dir[3];
        int kind = i % 4;
        float big = kind == 3 ? 1e18f : 1.0f;
        for (int k = 0; k < 3; k++) {
            v0[k] = tg_range(&r, -1.0f, 1.0f) * big;
            v1[k] = tg_range(&r, -1.0f, 1.0f) * big;
        }
        for (int k = 0; k < 3; k++) {
            /* A sliver: the third vertex almost on the first edge. */
            float off = kind == 0 ? 1e-6f : (kind == 1 ? 1e-30f : 0.5f);
            v2[k] = 0.5f * (v0[k] + v1[k]) + off * tg_range(&r, -1.0f, 1.0f) * big;
        }
        float s = tg_unit(&r);
        for (int k = 0; k < 3; k++) {
            float target = v0[k] + s * (v2[k] - v0[k]);
            org[k] = tg_range(&r, -3.0f, 3.0f) * big;
            dir[k] = target - org[k];
        }
        if (kind == 2) {
            /* Edge-on: the ray runs inside the triangle's plane. */
            for (int k = 0; k < 3; k++) {
                org[k] = v0[k] - (v1[k] - v0[k]);
                dir[k] = v1[k] - v0[k];
            }
        }
        if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f)
            continue;
        struct trace_ray ray;
        trace_ray_init(&ray, org, dir, 0.0f);
        float t, u, v;
        rays++;
        if (trace_triangle(&ray, v0, v1, v2, INFINITY, &t, &u, &v)) {
            sliver_hits += kind <= 1;
            failures += !CHECKF(hit_is_sane(t, u, v) && t >= 0.0f,
                     "kind %d: hit t=%g u=%g v=%g", kind, t, u, v);
        }
        float t_entry = NAN;
        float lo[3], hi[3];
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(v0[k], fminf(v1[k], v2[k]));
            hi[k] = fmaxf(v0[k], fmaxf(v1[k], v2[k]));
        }
        if (trace_box(&ray, lo, hi, INFINITY, &t_entry))
            failures += !CHECKF(!isnan(t_entry) && t_entry >= 0.0f, "box entry %g", t_entry);
    }
    printf("  slivers, edge-on, 1e18: %u rays, %u sliver hits, all sane\n", rays, sliver_hits);
}

int main(void)
{
    double t0 = rt_now_ms();
    printf("triangle_watertight:\n");
    /* ~1M aimed rays in total, plus 1/8 as many axis-parallel ones. */
    const uint32_t n = 125000;
    closed_mesh("sphere", 1, 24, 1.0, 0.0, 0.0, 0.0, BVH_BUILDER_BINNED_SAH, n, 1);
    closed_mesh("cube", 0, 12, 1.0, 0.0, 0.0, 0.0, BVH_BUILDER_SWEEP_SAH, n, 2);
    closed_mesh("sphere@1e5", 1, 24, 4.0, 1e5, -1e5, 1e5, BVH_BUILDER_BINNED_SAH, n, 3);
    closed_mesh("cube@1e5", 0, 12, 4.0, -1e5, 1e5, 1e5, BVH_BUILDER_BINNED_SAH, n, 4);
    closed_mesh("sphere*1e-4", 1, 24, 1e-4, 0.0, 0.0, 0.0, BVH_BUILDER_SWEEP_SAH, n, 5);
    closed_mesh("cube*1e-4", 0, 12, 1e-4, 3e-4, 0.0, 0.0, BVH_BUILDER_BINNED_SAH, n, 6);
    closed_mesh("sphere*1e4", 1, 24, 1e4, 0.0, 0.0, 0.0, BVH_BUILDER_BINNED_SAH, n, 7);
    closed_mesh("cube*1e4", 0, 12, 1e4, 0.0, 2e4, 0.0, BVH_BUILDER_SWEEP_SAH, n, 8);
    exact_edges();
    hit_points();
    degenerate_triangles();
    no_nan();
    printf("triangle_watertight: %s (%d failures, %llu closed-mesh rays, %.0f ms)\n",
           failures ? "FAIL" : "ok", failures, (unsigned long long)rays_total, rt_now_ms() - t0);
    return failures ? 1 : 0;
}
