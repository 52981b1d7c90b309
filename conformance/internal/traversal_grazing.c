/* SPDX-License-Identifier: Apache-2.0 */
/*
 * traversal_grazing.c - closest hits through every builder's BVH against
 * the brute-force reference, for rays that pass exactly through, or
 * within a few ulps of, mesh vertices and edges, many of them at a
 * grazing angle to the surface or along a coordinate axis.
 *
 * Such rays are where the triangle test and the box test can disagree.
 * The watertight test (Woop, Benthin and Wald 2013) decides hit or miss
 * from rounded sheared coordinates, so it may accept a ray that passes a
 * rounding error outside the triangle, and the distance t it reports is
 * computed separately.  Traversal culls a box whose entry distance lies
 * beyond the closest hit so far (Ize 2013's robust slab test, against
 * best * ISECT_BOX_FAR_SCALE so that boxes touching a hit at exactly that
 * distance are still visited for the tie rule).  That is only sound when
 * the point org + t dir of every hit lies in its triangle's box as the
 * slab test sees it: if a grazing hit's plane distance lands before the
 * box, the box of the truly closest triangle is skipped and traversal
 * returns a farther hit (the bug this file was written for, found on
 * tg_cube_sphere(60): t = 0.999995 reported for a box entered at t = 1).
 *
 * Two checks, both exact (no tolerance):
 * - kernel: for every triangle a ray hits, trace_box on that triangle's
 *   own box accepts the ray with an entry distance <= t, as trace.h
 *   promises; every ancestor box then does too (its bounds are wider and
 *   rounding is monotone);
 * - traversal: trace_closest agrees with trace_closest_brute_force on
 *   whether there is a hit, on the primitive and bit for bit on t, u, v.
 *   The tie rule (equal t: lower primitive index, trace.h and
 *   traverse.c) makes the answer independent of the tree, so no
 *   tolerance is due; traversal.c's looser rule (another primitive within
 *   1e-6) is reported alongside.  trace_any agrees on whether there is a
 *   hit.
 *
 * Rays: the reported one; aimed at vertices (exactly or moved by up to 3
 * ulps per coordinate) and edge points from random origins and along
 * tangents of the surface tilted by 1e-5 to 0.3 radians; and axis-parallel
 * ones through vertices, whose origins lie on a vertex's coordinate planes
 * or a few ulps off them (denormals off a plane through 0) and sometimes
 * on the surface itself, so that several triangles tie at t = 0 or -0.
 * Meshes from accel_testgeo.h: the cube-sphere of the report (g = 60,
 * unit radius), a smaller cube-sphere, the flat cube (axis-aligned faces:
 * flat boxes) and a height field.  Every builder of lib/accel: binned
 * SAH, sweep SAH, median, the parallel builds (pool NULL) and Wald, Benthin and Slusallek's (2003)
 * top-level builder, with leaves of 1 (leaf box = triangle box, the most
 * sensitive) up to 8.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/build_parallel.h"
#include "accel/build_toplevel.h"
#include "accel/bvh_build.h"
#include "accel_testgeo.h"
#include "base/alloc.h"
#include "base/timer.h"
#include "trace/trace.h"

static int failures;

enum build_kind {
    BUILD_BINNED,
    BUILD_SWEEP,
    BUILD_MEDIAN,
    BUILD_PARALLEL_SAH,
    BUILD_PARALLEL_GRID_SAH,
    BUILD_PARALLEL_GRID_BIH,
    BUILD_TOPLEVEL
};

struct build_case {
    const char *name;
    enum build_kind kind;
    int bins;
    int max_leaf;
};

static const struct build_case builds[] = {
    {"binned16/leaf1", BUILD_BINNED, 16, 1},
    {"binned16/leaf8", BUILD_BINNED, 16, 8},
    {"binned4/leaf4", BUILD_BINNED, 4, 4},
    {"sweep/leaf1", BUILD_SWEEP, 0, 1},
    {"sweep/leaf8", BUILD_SWEEP, 0, 8},
    {"median/leaf1", BUILD_MEDIAN, 0, 1},
    {"median/leaf8", BUILD_MEDIAN, 0, 8},
    {"parallel-sah/leaf2", BUILD_PARALLEL_SAH, 16, 2},
    {"grid+sah/leaf1", BUILD_PARALLEL_GRID_SAH, 16, 1},
    {"grid+bih/leaf4", BUILD_PARALLEL_GRID_BIH, 0, 4},
    {"toplevel004", BUILD_TOPLEVEL, 0, 0},
};
#define BUILD_COUNT (sizeof(builds) / sizeof(builds[0]))

static int build(const struct build_case *bc, struct bvh *out, const struct aabb *boxes,
                 uint32_t n)
{
    struct bvh_build_params p;
    bvh_build_params_default(&p);
    if (bc->bins)
        p.bins = bc->bins;
    if (bc->max_leaf)
        p.max_leaf_size = bc->max_leaf;
    struct bvh_parallel_params pp;
    bvh_parallel_params_default(&pp);
    switch (bc->kind) {
    case BUILD_BINNED:
        return accel_build_binned_sah(out, boxes, n, &p);
    case BUILD_SWEEP:
        return accel_build_sweep_sah(out, boxes, n, &p);
    case BUILD_MEDIAN:
        return accel_build_median(out, boxes, n, &p);
    case BUILD_PARALLEL_SAH:
        return accel_build_parallel_ex(out, boxes, n, &p, &pp, NULL);
    case BUILD_PARALLEL_GRID_SAH:
        pp.partition = BVH_PARTITION_GRID;
        return accel_build_parallel_ex(out, boxes, n, &p, &pp, NULL);
    case BUILD_PARALLEL_GRID_BIH:
        pp.partition = BVH_PARTITION_GRID;
        pp.subtree = BVH_SUBTREE_MEDIAN;
        return accel_build_parallel_ex(out, boxes, n, &p, &pp, NULL);
    case BUILD_TOPLEVEL:
        return accel_build_toplevel_cellsplit(out, boxes, n);
    }
    return -1;
}

struct test_ray {
    float org[3];
    float dir[3];
    float tmax;
};

struct reference {
    int found;
    struct trace_hit hit;
};

/* A mesh with its trees, built once per builder. */
struct scene {
    const char *name;
    struct tg_mesh mesh;
    struct aabb *boxes;
    struct bvh bvh[BUILD_COUNT];
    float *tri[BUILD_COUNT];
    int built[BUILD_COUNT];
};

static void scene_init(struct scene *sc, const char *name)
{
    sc->name = name;
    sc->boxes = tg_boxes(&sc->mesh);
    for (size_t b = 0; b < BUILD_COUNT; b++) {
        sc->built[b] = build(&builds[b], &sc->bvh[b], sc->boxes, sc->mesh.tri_count) == 0;
        failures += !CHECKF(sc->built[b], "%s/%s: build failed", name, builds[b].name);
        sc->tri[b] = sc->built[b] ? accel_gather_triangles(&sc->bvh[b], sc->mesh.pos,
                                                           sc->mesh.idx)
                                  : NULL;
    }
}

static void scene_release(struct scene *sc)
{
    for (size_t b = 0; b < BUILD_COUNT; b++) {
        if (sc->built[b]) {
            rt_free(sc->tri[b]);
            bvh_release(&sc->bvh[b]);
        }
    }
    free(sc->boxes);
    tg_mesh_free(&sc->mesh);
}

/* Tallies for the summary line and the failure report. */
struct tally {
    uint32_t rays;
    uint32_t hits_checked;      /* kernel: triangle hits whose box was tested */
    uint32_t kernel_bad_hits;   /* ... whose own box refused them */
    uint32_t kernel_bad_rays;
    uint32_t traversal_bad_rays; /* rays where some build disagrees */
    uint32_t traversal_bad_pairs;
    uint32_t loose_bad_pairs; /* disagreements the 1e-6 rule of traversal.c also sees */
};

static void print_ray(const char *what, const struct test_ray *tr)
{
    fprintf(stderr, "  %s org (%.9g, %.9g, %.9g) dir (%.9g, %.9g, %.9g) tmax %g\n", what,
            tr->org[0], tr->org[1], tr->org[2], tr->dir[0], tr->dir[1], tr->dir[2], tr->tmax);
}

/*
 * The kernel check for one ray: every hit's point lies in its
 * triangle's box as far as the slab test can tell, entry <= t (traverse.c
 * needs only entry <= best * ISECT_BOX_FAR_SCALE; tag-graze-box-limit).
 */
static int kernel_check(const struct scene *sc, const struct test_ray *tr,
                        const struct trace_ray *ray, struct tally *ty)
{
    const struct tg_mesh *m = &sc->mesh;
    int bad = 0;
    for (uint32_t i = 0; i < m->tri_count; i++) {
        float t, u, v;
        if (!trace_triangle(ray, tg_vertex(m, i, 0), tg_vertex(m, i, 1), tg_vertex(m, i, 2),
                            tr->tmax, &t, &u, &v))
            continue;
        ty->hits_checked++;
        float entry = NAN;
        int in_box = trace_box(ray, sc->boxes[i].min, sc->boxes[i].max, INFINITY, &entry);
        if (in_box && entry <= t)
            continue;
        ty->kernel_bad_hits++;
        if (!bad && ty->kernel_bad_rays < 3) {
            fprintf(stderr, "%s: triangle %u hit at t=%.9g, its box %s (entry %.9g)\n",
                    sc->name, i, t, in_box ? "starts later" : "is missed", entry);
            print_ray("ray", tr);
        }
        bad = 1;
    }
    return bad;
}

/* The traversal check for one ray over every build. */
static int traversal_check(const struct scene *sc, const struct test_ray *tr,
                           const struct trace_ray *ray, const struct reference *ref,
                           struct tally *ty)
{
    int bad = 0;
    for (size_t b = 0; b < BUILD_COUNT; b++) {
        if (!sc->built[b])
            continue;
        struct trace_hit h;
        int found = trace_closest(&sc->bvh[b], sc->tri[b], ray, tr->tmax, &h, NULL);
        int any = trace_any(&sc->bvh[b], sc->tri[b], ray, tr->tmax, NULL);
        int same = found == ref->found && any == ref->found;
        if (same && found)
            same = h.prim == ref->hit.prim && h.t == ref->hit.t && h.u == ref->hit.u &&
                   h.v == ref->hit.v;
        if (same)
            continue;
        ty->traversal_bad_pairs++;
        /* traversal.c's rule: another primitive is fine within 1e-6. */
        int loose_ok = found == ref->found && any == ref->found &&
                       (!found || (h.prim != ref->hit.prim && h.t >= ref->hit.t &&
                                   h.t - ref->hit.t <= 1e-6f * fabsf(ref->hit.t)));
        ty->loose_bad_pairs += !loose_ok;
        if (!bad && ty->traversal_bad_rays < 5) {
            fprintf(stderr,
                    "%s/%s: traversal %d (prim %u t=%.9g) any %d, brute force %d (prim %u "
                    "t=%.9g)\n",
                    sc->name, builds[b].name, found, found ? h.prim : 0u,
                    found ? h.t : 0.0f, any, ref->found, ref->found ? ref->hit.prim : 0u,
                    ref->found ? ref->hit.t : 0.0f);
            print_ray("ray", tr);
        }
        bad = 1;
    }
    return bad;
}

static void check_ray(const struct scene *sc, const struct test_ray *tr, struct tally *ty)
{
    struct trace_ray ray;
    trace_ray_init(&ray, tr->org, tr->dir, 0.0f);
    struct reference ref;
    ref.found = trace_closest_brute_force(sc->mesh.pos, sc->mesh.idx, sc->mesh.tri_count, &ray,
                                          tr->tmax, &ref.hit);
    ty->rays++;
    ty->kernel_bad_rays += (uint32_t)kernel_check(sc, tr, &ray, ty);
    ty->traversal_bad_rays += (uint32_t)traversal_check(sc, tr, &ray, &ref, ty);
}

/* Area-weighted vertex normals, in double. */
static double *vertex_normals(const struct tg_mesh *m)
{
    double *n = tg_alloc(sizeof(double) * 3 * m->vertex_count);
    memset(n, 0, sizeof(double) * 3 * m->vertex_count);
    for (uint32_t t = 0; t < m->tri_count; t++) {
        const float *a = tg_vertex(m, t, 0);
        const float *b = tg_vertex(m, t, 1);
        const float *c = tg_vertex(m, t, 2);
        double e1[3], e2[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = (double)b[k] - a[k];
            e2[k] = (double)c[k] - a[k];
        }
        double fn[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                        e1[0] * e2[1] - e1[1] * e2[0]};
        for (int corner = 0; corner < 3; corner++) {
            uint32_t v = m->idx[3 * t + corner];
            for (int k = 0; k < 3; k++)
                n[3 * v + k] += fn[k];
        }
    }
    return n;
}

static void normalize3(double v[3])
{
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (len > 0.0) {
        for (int k = 0; k < 3; k++)
            v[k] /= len;
    }
}

/* f moved by steps ulps (either sign). */
static float nudge(float f, int steps)
{
    for (; steps > 0; steps--)
        f = nextafterf(f, INFINITY);
    for (; steps < 0; steps++)
        f = nextafterf(f, -INFINITY);
    return f;
}

/*
 * The battery.  Targets: a vertex exactly, a vertex moved by up to 3 ulps
 * per coordinate, or a point of an edge (exactly as rounded, or moved).
 * Origins: uniform in the mesh's box grown by half its size, or (two
 * rays in three) on a line through the target that grazes the surface
 * there: the tangent plane of the vertex normal tilted by 1e-5 to 0.3
 * radians either way.  Every seventh ray ends at its target (t_max = 1,
 * a shadow ray towards a point): hits there are within rounding of t_max.
 */
static void battery(const struct scene *sc, uint32_t count, uint64_t seed, struct tally *ty)
{
    const struct tg_mesh *m = &sc->mesh;
    double *normals = vertex_normals(m);
    struct aabb box = aabb_empty();
    for (uint32_t v = 0; v < m->vertex_count; v++)
        aabb_grow_point(&box, &m->pos[3 * v]);
    float lo[3], hi[3];
    double extent = 0.0;
    for (int k = 0; k < 3; k++) {
        float size = box.max[k] - box.min[k];
        lo[k] = box.min[k] - 0.5f * size;
        hi[k] = box.max[k] + 0.5f * size;
        extent = fmax(extent, size);
    }
    struct tg_rng r;
    tg_seed(&r, seed);
    for (uint32_t i = 0; i < count; i++) {
        uint32_t tri = tg_below(&r, m->tri_count);
        int corner = (int)tg_below(&r, 3);
        uint32_t vi = m->idx[3 * tri + corner];
        const float *a = &m->pos[3 * vi];
        const float *b = tg_vertex(m, tri, (corner + 1) % 3);
        int target_kind = (int)(i % 4);
        float target[3];
        float s = (i & 4) ? 0.5f : tg_unit(&r);
        for (int k = 0; k < 3; k++)
            target[k] = target_kind >= 2 ? a[k] + s * (b[k] - a[k]) : a[k];
        if (target_kind & 1) {
            for (int k = 0; k < 3; k++)
                target[k] = nudge(target[k], (int)tg_below(&r, 7) - 3);
        }
        struct test_ray tr;
        if (i % 3 == 0) {
            for (int k = 0; k < 3; k++)
                tr.org[k] = tg_range(&r, lo[k], hi[k]);
        } else {
            /* Grazing: along a tangent of the surface at the vertex. */
            double n[3] = {normals[3 * vi], normals[3 * vi + 1], normals[3 * vi + 2]};
            normalize3(n);
            double g[3];
            double dn;
            do {
                for (int k = 0; k < 3; k++)
                    g[k] = 2.0 * tg_unit(&r) - 1.0;
                dn = g[0] * n[0] + g[1] * n[1] + g[2] * n[2];
                for (int k = 0; k < 3; k++)
                    g[k] -= dn * n[k];
            } while (g[0] * g[0] + g[1] * g[1] + g[2] * g[2] < 1e-4);
            normalize3(g);
            double tilt = pow(10.0, -5.0 + 4.5 * tg_unit(&r));
            if (tg_next(&r) & 1)
                tilt = -tilt;
            double len = extent * tg_range(&r, 0.05f, 2.0f);
            for (int k = 0; k < 3; k++)
                tr.org[k] = (float)(target[k] - len * (g[k] + tilt * n[k]));
        }
        for (int k = 0; k < 3; k++)
            tr.dir[k] = target[k] - tr.org[k];
        if (tr.dir[0] == 0.0f && tr.dir[1] == 0.0f && tr.dir[2] == 0.0f)
            continue;
        tr.tmax = i % 7 == 6 ? 1.0f : INFINITY;
        check_ray(sc, &tr, ty);
    }
    free(normals);
}

/*
 * Axis-parallel rays at vertices: one or two zero direction components
 * (either sign of zero), the origin on a vertex's coordinate planes or
 * moved off them by up to 2 ulps (a zero coordinate becomes a denormal:
 * an origin 1e-45 beside a plane through 0), and either 0.75 direction
 * lengths before the vertex or on it, so that hits at t = 0 (or -0) from
 * several triangles tie.  Every fifth ray ends at t_max = 0.75, at the
 * vertex.  Here the box test's 0 * inf and the triangle test's underflow
 * meet.
 */
static void axis_battery(const struct scene *sc, uint32_t count, uint64_t seed, struct tally *ty)
{
    const struct tg_mesh *m = &sc->mesh;
    struct tg_rng r;
    tg_seed(&r, seed);
    for (uint32_t i = 0; i < count; i++) {
        const float *v = &m->pos[3 * tg_below(&r, m->vertex_count)];
        const float *w = &m->pos[3 * tg_below(&r, m->vertex_count)];
        struct test_ray tr;
        int keep = (int)tg_below(&r, 3);
        for (int k = 0; k < 3; k++) {
            tr.org[k] = (i & 1) ? v[k] : nudge(v[k], (int)tg_below(&r, 5) - 2);
            tr.dir[k] = (i & 8) ? -0.0f : 0.0f;
        }
        if (i & 2) {
            /* One zero component: the ray runs in a coordinate plane of
             * the vertex towards another vertex's projection. */
            for (int k = 0; k < 3; k++) {
                if (k != keep)
                    tr.dir[k] = w[k] - v[k];
            }
        } else {
            tr.dir[keep] = (i & 4) ? -1.0f : 1.0f;
        }
        if (tr.dir[0] == 0.0f && tr.dir[1] == 0.0f && tr.dir[2] == 0.0f)
            continue;
        if (i % 3 != 0) {
            for (int k = 0; k < 3; k++)
                tr.org[k] -= 0.75f * tr.dir[k];
        }
        tr.tmax = i % 5 == 4 ? 0.75f : INFINITY;
        check_ray(sc, &tr, ty);
    }
}

static void report(const struct scene *sc, const struct tally *ty, double ms)
{
    printf("  %-12s %6u triangles, %5u rays x %zu builds: %u rays with a hit outside its box "
           "(%u of %u hits), %u rays where traversal differs (%u ray/build pairs, %u beyond "
           "1e-6), %.0f ms\n",
           sc->name, sc->mesh.tri_count, ty->rays, BUILD_COUNT, ty->kernel_bad_rays,
           ty->kernel_bad_hits, ty->hits_checked, ty->traversal_bad_rays,
           ty->traversal_bad_pairs, ty->loose_bad_pairs, ms);
    failures += !CHECKF(ty->kernel_bad_rays == 0, "%s: %u of %u rays hit outside the box",
             sc->name, ty->kernel_bad_rays, ty->rays);
    failures += !CHECKF(ty->traversal_bad_rays == 0, "%s: traversal differs on %u of %u rays",
             sc->name, ty->traversal_bad_rays, ty->rays);
}

static void run(struct scene *sc, const char *name, uint32_t rays, uint32_t axis_rays,
                uint64_t seed, const struct test_ray *extra, struct tally *total)
{
    double t0 = rt_now_ms();
    struct tally ty;
    memset(&ty, 0, sizeof(ty));
    scene_init(sc, name);
    if (extra)
        check_ray(sc, extra, &ty);
    battery(sc, rays, seed, &ty);
    axis_battery(sc, axis_rays, seed + 1000, &ty);
    report(sc, &ty, rt_now_ms() - t0);
    total->rays += ty.rays;
    total->kernel_bad_rays += ty.kernel_bad_rays;
    total->traversal_bad_rays += ty.traversal_bad_rays;
    scene_release(sc);
}

int main(void)
{
    double t0 = rt_now_ms();
    printf("traversal_grazing:\n");
    struct tally total;
    memset(&total, 0, sizeof(total));
    const double zero[3] = {0.0, 0.0, 0.0};
    struct scene sc;

    /* The reported ray: aimed at a vertex of the g = 60 sphere, it hits
     * four triangles within 5e-6 of t = 1; the brute force's closest,
     * triangle 37236, was reported at t = 0.999995172, 2.5e-6 outside its
     * box, whose entry distance is 1. */
    const struct test_ray reported = {
        {0.20929122f, 0.204615593f, 1.46899199f}, {-0.501098156f, -0.735173702f, -0.673154831f},
        INFINITY};
    tg_cube_sphere(&sc.mesh, 60, 1, 1.0, zero);
    run(&sc, "sphere60", 600, 0, 1, &reported, &total);

    tg_cube_sphere(&sc.mesh, 24, 1, 1.0, zero);
    run(&sc, "sphere24", 3000, 1500, 2, NULL, &total);

    const double offset[3] = {3.0, -1.0, 0.5};
    tg_cube_sphere(&sc.mesh, 12, 0, 2.0, offset);
    run(&sc, "cube12", 3000, 3000, 3, NULL, &total);

    struct tg_rng r;
    tg_seed(&r, 31);
    tg_terrain(&sc.mesh, 40, &r);
    run(&sc, "terrain40", 3000, 1500, 4, NULL, &total);

    printf("traversal_grazing: %s (%d failures; %u rays, %u with a hit outside its box, %u "
           "where traversal differs; %.0f ms)\n",
           failures ? "FAIL" : "ok", failures, total.rays, total.kernel_bad_rays,
           total.traversal_bad_rays, rt_now_ms() - t0);
    return failures ? 1 : 0;
}
