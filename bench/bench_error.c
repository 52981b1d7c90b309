/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bench_error.c - `rtbench error`: intersection error against time
 * (DESIGN.md "Measurement", its last item).
 *
 * Per kernel - every ISA table this CPU runs (lib/trace/kernels.h) times
 * every object layout that table walks (the `layouts` table below: the
 * binary walk, the 4-wide walk; a new layout is one more row there), the
 * brute-force reference intersector, and Embree where rtbench is built
 * with it - on the stability workloads (a sphere at 1e3 .. 1e6 from the
 * origin, at 1e-5 and 1e5 scale, slivers of aspect 4096, grazing rays at
 * 1e-4 .. 1e-2 radians), one table of:
 *
 *   ns per ray  closest-hit queries on one thread (bench_run_parallel),
 *               median of --runs interleaved runs;
 *   t error     |t - t*| / t*, where t* is the hit distance of the same
 *               ray with the same triangle (the one the kernel reports)
 *               computed here in long double by Moeller and Trumbore's
 *               (1997) formulas from the float inputs, which are exact in
 *               long double: so t* is the exact answer to the question
 *               the kernel was asked, up to about 1e-19;
 *   u/v error   max(|u - u*|, |v - v*|), the barycentric weights of the
 *               second and third vertex against the same reference;
 *   agreement   hit/miss and t (BENCH_T_TOLERANCE) against the closest
 *               hit over all triangles found in double precision, on a
 *               sample of the rays (the brute-force row is measured on
 *               that sample only, and timed on ERR_BRUTE_TIMED of its
 *               rays).
 *
 * Our BVH kernels must return the scalar binary walk's hits bit for bit
 * (t, u, v and primitive; docs/performance.md); a difference is a failed
 * correctness check (exit status 3).  Plot: error.png, the largest t
 * error of each kernel over the workloads against its mean ns per ray.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/timer.h"
#include "bench.h"

#ifdef RT_HAVE_EMBREE
#include "bench_embree.h"
#endif

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define ERR_SIDE 128 /* primary rays per workload: ERR_SIDE^2 */
#define ERR_SIDE_QUICK 24
#define ERR_SAMPLE 2048 /* rays checked against the double-precision brute force */
#define ERR_SAMPLE_QUICK 128
#define ERR_REPEAT 4 /* passes over the rays per timed run */
#define ERR_BRUTE_TIMED 256 /* rays of the sample the brute force is timed on, one pass */
#define ERR_SPHERE_SLICES 64 /* x 32 stacks: 4032 triangles */
#define ERR_SPHERE_SLICES_QUICK 16
#define ERR_SLIVERS 4096 /* strips of one quad: 8192 triangles */
#define ERR_SLIVERS_QUICK 256
#define ERR_GRID 64 /* grazing plane: ERR_GRID^2 quads */
#define ERR_GRID_QUICK 16
#define ERR_MAX_ROWS 16 /* kernels */
#define ERR_SEED 0x6572726Fu

/* ------------------------------------------------------------ workloads */

enum err_shape { SHAPE_SPHERE, SHAPE_SLIVERS, SHAPE_GRAZING };

static const struct err_workload_info {
    const char *name;
    enum err_shape shape;
    double offset; /* sphere centre (o, o, o) */
    double scale;  /* sphere radius */
    const char *what;
} workloads[] = {
    {"unit", SHAPE_SPHERE, 0.0, 1.0, "unit sphere at the origin (control)"},
    {"far 1e3", SHAPE_SPHERE, 1e3, 1.0, "unit sphere and camera at (1e3, 1e3, 1e3)"},
    {"far 1e4", SHAPE_SPHERE, 1e4, 1.0, "the same at 1e4"},
    {"far 1e5", SHAPE_SPHERE, 1e5, 1.0, "the same at 1e5"},
    {"far 1e6", SHAPE_SPHERE, 1e6, 1.0,
     "the same at 1e6 (float spacing 1/16 there: a coarse sphere, exact inputs)"},
    {"tiny 1e-5", SHAPE_SPHERE, 0.0, 1e-5, "sphere of radius 1e-5 at the origin"},
    {"huge 1e5", SHAPE_SPHERE, 0.0, 1e5, "sphere of radius 1e5 at the origin"},
    {"slivers", SHAPE_SLIVERS, 0.0, 1.0,
     "a curved sheet of 1 x 1/4096 strips, two triangles each (aspect 4096)"},
    {"grazing", SHAPE_GRAZING, 0.0, 1.0,
     "a rippled plane, rays at 1e-4 .. 1e-2 radians to it"},
};
#define WORKLOADS ((int)(sizeof(workloads) / sizeof(workloads[0])))

struct err_workload {
    struct bench_mesh mesh;
    struct bench_rays rays;
    struct bench_rays sample; /* every k-th ray */
};

static int mesh_alloc(struct bench_mesh *m, uint32_t vertices, uint32_t triangles)
{
    memset(m, 0, sizeof(*m));
    m->positions = malloc((size_t)vertices * 3 * sizeof(float));
    m->indices = malloc((size_t)triangles * 3 * sizeof(uint32_t));
    m->vertex_count = vertices;
    m->tri_count = triangles;
    return m->positions && m->indices ? 0 : -1;
}

static void mesh_bounds(struct bench_mesh *m)
{
    m->bounds = aabb_empty();
    for (uint32_t i = 0; i < m->vertex_count; i++)
        aabb_grow_point(&m->bounds, &m->positions[3 * (size_t)i]);
}

/* A camera at eye (double, rounded to float) looking at target. */
static void camera(struct bench_mesh *m, const double eye[3], const double target[3],
                   double tan_x)
{
    double f[3], len = 0.0;
    for (int k = 0; k < 3; k++) {
        f[k] = target[k] - eye[k];
        len += f[k] * f[k];
    }
    len = sqrt(len);
    for (int k = 0; k < 3; k++)
        f[k] /= len;
    /* right = f x (0, 1, 0) normalised, up = right x f */
    double r[3] = {-f[2], 0.0, f[0]};
    double rl = sqrt(r[0] * r[0] + r[2] * r[2]);
    r[0] /= rl;
    r[2] /= rl;
    double u[3] = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2],
                   r[0] * f[1] - r[1] * f[0]};
    for (int k = 0; k < 3; k++) {
        m->camera.eye[k] = (float)eye[k];
        m->camera.forward[k] = (float)f[k];
        m->camera.right[k] = (float)r[k];
        m->camera.up[k] = (float)u[k];
    }
    m->camera.tan_x = (float)tan_x;
}

static int make_sphere(struct err_workload *w, const struct err_workload_info *info, int quick,
                       uint32_t side)
{
    const uint32_t slices = quick ? ERR_SPHERE_SLICES_QUICK : ERR_SPHERE_SLICES;
    const uint32_t stacks = slices / 2;
    const uint32_t nv = (slices + 1) * (stacks + 1);
    /* Quads between stacks, minus the degenerate halves at the poles. */
    const uint32_t nt = slices * (stacks - 1) * 2;
    struct bench_mesh *m = &w->mesh;
    if (mesh_alloc(m, nv, nt))
        return -1;
    const double o = info->offset, r = info->scale;
    for (uint32_t j = 0; j <= stacks; j++)
        for (uint32_t i = 0; i <= slices; i++) {
            double theta = M_PI * j / stacks, phi = 2.0 * M_PI * i / slices;
            float *p = &m->positions[3 * (size_t)(j * (slices + 1) + i)];
            /* A slight bump, so that no two triangles are coplanar. */
            double rr = r * (1.0 + 0.02 * sin(5.0 * phi) * sin(3.0 * theta));
            p[0] = (float)(o + rr * sin(theta) * cos(phi));
            p[1] = (float)(o + rr * cos(theta));
            p[2] = (float)(o + rr * sin(theta) * sin(phi));
        }
    uint32_t t = 0;
    for (uint32_t j = 0; j < stacks; j++)
        for (uint32_t i = 0; i < slices; i++) {
            uint32_t a = j * (slices + 1) + i, b = a + 1, c = a + slices + 1, d = c + 1;
            if (j > 0) {
                uint32_t *q = &m->indices[3 * (size_t)t++];
                q[0] = a, q[1] = c, q[2] = b;
            }
            if (j + 1 < stacks) {
                uint32_t *q = &m->indices[3 * (size_t)t++];
                q[0] = b, q[1] = c, q[2] = d;
            }
        }
    m->tri_count = t;
    mesh_bounds(m);
    const double eye[3] = {o + 0.7 * r, o + 0.9 * r, o + 3.5 * r};
    const double target[3] = {o, o, o};
    camera(m, eye, target, 0.32);
    return bench_rays_primary(&w->rays, m, side, side);
}

static int make_slivers(struct err_workload *w, int quick, uint32_t side)
{
    const uint32_t strips = quick ? ERR_SLIVERS_QUICK : ERR_SLIVERS;
    struct bench_mesh *m = &w->mesh;
    if (mesh_alloc(m, 2 * (strips + 1), 2 * strips))
        return -1;
    /* z linear in x along each strip edge, curved across the strips. */
    for (uint32_t k = 0; k <= strips; k++) {
        double y = (double)k / strips;
        for (int e = 0; e < 2; e++) {
            float *p = &m->positions[3 * (size_t)(2 * k + e)];
            p[0] = (float)e;
            p[1] = (float)y;
            p[2] = (float)(0.1 * sin(6.0 * y) + 0.2 * e * cos(5.0 * y));
        }
    }
    for (uint32_t k = 0; k < strips; k++) {
        uint32_t a0 = 2 * k, a1 = a0 + 1, b0 = a0 + 2, b1 = a0 + 3;
        uint32_t *q = &m->indices[6 * (size_t)k];
        q[0] = a0, q[1] = a1, q[2] = b0;
        q[3] = a1, q[4] = b1, q[5] = b0;
    }
    mesh_bounds(m);
    const double eye[3] = {0.45, 0.55, 2.5}, target[3] = {0.5, 0.5, 0.0};
    camera(m, eye, target, 0.18);
    return bench_rays_primary(&w->rays, m, side, side);
}

static int make_grazing(struct err_workload *w, int quick, uint32_t side)
{
    const uint32_t n = quick ? ERR_GRID_QUICK : ERR_GRID;
    struct bench_mesh *m = &w->mesh;
    if (mesh_alloc(m, (n + 1) * (n + 1), 2 * n * n))
        return -1;
    for (uint32_t j = 0; j <= n; j++)
        for (uint32_t i = 0; i <= n; i++) {
            double x = -1.0 + 2.0 * i / n, y = -1.0 + 2.0 * j / n;
            float *p = &m->positions[3 * (size_t)(j * (n + 1) + i)];
            p[0] = (float)x;
            p[1] = (float)y;
            p[2] = (float)(0.002 * sin(9.0 * x) * cos(7.0 * y));
        }
    for (uint32_t j = 0; j < n; j++)
        for (uint32_t i = 0; i < n; i++) {
            uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            uint32_t *q = &m->indices[6 * (size_t)(j * n + i)];
            q[0] = a, q[1] = b, q[2] = c;
            q[3] = b, q[4] = d, q[5] = c;
        }
    mesh_bounds(m);
    /* Rays from x = -1.5 along +x, descending at a slope of 1e-4 .. 1e-2
     * to reach the plane at x in [-1, 1]. */
    struct bench_rays *set = &w->rays;
    set->name = "grazing";
    set->count = side * side;
    set->width = set->height = 0;
    set->rays = malloc((size_t)set->count * sizeof(RTray));
    if (!set->rays)
        return -1;
    struct bench_rng rng;
    bench_rng_seed(&rng, ERR_SEED);
    for (uint32_t i = 0; i < set->count; i++) {
        double slope = pow(10.0, -4.0 + 2.0 * bench_rng_float(&rng));
        double reach = 0.5 + 2.0 * bench_rng_float(&rng);
        double y = -0.9 + 1.8 * bench_rng_float(&rng);
        double yaw = 0.2 * (bench_rng_float(&rng) - 0.5);
        RTray *r = &set->rays[i];
        r->org[0] = -1.5f;
        r->org[1] = (float)y;
        r->org[2] = (float)(slope * reach);
        r->dir[0] = 1.0f;
        r->dir[1] = (float)yaw;
        r->dir[2] = (float)-slope;
        r->tmin = 0.0f;
        r->tmax = INFINITY;
    }
    return 0;
}

static int workload_make(struct err_workload *w, int i, int quick)
{
    const uint32_t side = quick ? ERR_SIDE_QUICK : ERR_SIDE;
    const uint32_t want = quick ? ERR_SAMPLE_QUICK : ERR_SAMPLE;
    memset(w, 0, sizeof(*w));
    int rc;
    switch (workloads[i].shape) {
    case SHAPE_SLIVERS:
        rc = make_slivers(w, quick, side);
        break;
    case SHAPE_GRAZING:
        rc = make_grazing(w, quick, side);
        break;
    default:
        rc = make_sphere(w, &workloads[i], quick, side);
        break;
    }
    if (rc)
        return -1;
    w->mesh.name = workloads[i].name;
    w->mesh.description = workloads[i].what;
    uint32_t n = want < w->rays.count ? want : w->rays.count;
    uint32_t stride = w->rays.count / n;
    w->sample.name = "sample";
    w->sample.count = n;
    w->sample.rays = malloc((size_t)n * sizeof(RTray));
    if (!w->sample.rays)
        return -1;
    for (uint32_t k = 0; k < n; k++)
        w->sample.rays[k] = w->rays.rays[(size_t)k * stride];
    return 0;
}

static void workload_release(struct err_workload *w)
{
    bench_mesh_release(&w->mesh);
    bench_rays_release(&w->rays);
    bench_rays_release(&w->sample);
}

/* ------------------------------------------------------------ references */

/* Moeller and Trumbore (1997) in long double on the float inputs: the
 * plane-crossing t, u, v of the ray with the triangle (no inside test:
 * the kernel already said it hits).  Returns 0 when the ray is parallel
 * to the triangle's plane. */
static int exact_tuv(const RTray *r, const float *v0f, const float *v1f, const float *v2f,
                     long double *t, long double *u, long double *v)
{
    long double o[3], d[3], e1[3], e2[3], s[3], p[3], q[3];
    for (int k = 0; k < 3; k++) {
        o[k] = r->org[k];
        d[k] = r->dir[k];
        e1[k] = (long double)v1f[k] - v0f[k];
        e2[k] = (long double)v2f[k] - v0f[k];
        s[k] = o[k] - v0f[k];
    }
    p[0] = d[1] * e2[2] - d[2] * e2[1];
    p[1] = d[2] * e2[0] - d[0] * e2[2];
    p[2] = d[0] * e2[1] - d[1] * e2[0];
    long double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (det == 0.0L)
        return 0;
    q[0] = s[1] * e1[2] - s[2] * e1[1];
    q[1] = s[2] * e1[0] - s[0] * e1[2];
    q[2] = s[0] * e1[1] - s[1] * e1[0];
    *u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
    *v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    *t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
    return 1;
}

/* The closest hit over all triangles in double precision (edges and
 * vertices inclusive): the hit/miss reference. */
static struct bench_hit closest_double(const struct bench_mesh *m, const RTray *r)
{
    struct bench_hit best = {INFINITY, BENCH_MISS};
    double best_t = (double)r->tmax;
    for (uint32_t j = 0; j < m->tri_count; j++) {
        const float *v0 = &m->positions[3 * (size_t)m->indices[3 * (size_t)j]];
        const float *v1 = &m->positions[3 * (size_t)m->indices[3 * (size_t)j + 1]];
        const float *v2 = &m->positions[3 * (size_t)m->indices[3 * (size_t)j + 2]];
        double e1[3], e2[3], s[3], d[3], p[3], q[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = (double)v1[k] - v0[k];
            e2[k] = (double)v2[k] - v0[k];
            s[k] = (double)r->org[k] - v0[k];
            d[k] = r->dir[k];
        }
        p[0] = d[1] * e2[2] - d[2] * e2[1];
        p[1] = d[2] * e2[0] - d[0] * e2[2];
        p[2] = d[0] * e2[1] - d[1] * e2[0];
        double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
        if (det == 0.0)
            continue;
        double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
        if (u < 0.0 || u > 1.0)
            continue;
        q[0] = s[1] * e1[2] - s[2] * e1[1];
        q[1] = s[2] * e1[0] - s[0] * e1[2];
        q[2] = s[0] * e1[1] - s[1] * e1[0];
        double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
        if (v < 0.0 || u + v > 1.0)
            continue;
        double t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
        if (t < (double)r->tmin || t >= best_t)
            continue;
        best_t = t;
        best.t = (float)t;
        best.prim = j;
    }
    return best;
}

/* ------------------------------------------------------------ kernels */

/* An object layout our kernels walk: whether an ISA table walks it, and
 * its closest-hit walk.  A new layout (BVH8) is one more row of
 * `layouts`, and then appears in the table for every ISA that has it. */
struct err_layout {
    const char *name;
    int (*available)(const struct trace_kernels *k, const struct bench_accel *acc);
    int (*closest)(const struct trace_kernels *k, const struct bench_accel *acc,
                   const struct trace_ray *ray, float t_max, struct trace_hit *hit);
};

static int binary_available(const struct trace_kernels *k, const struct bench_accel *acc)
{
    (void)acc;
    return k->closest != NULL;
}

static int binary_closest(const struct trace_kernels *k, const struct bench_accel *acc,
                          const struct trace_ray *ray, float t_max, struct trace_hit *hit)
{
    return k->closest(&acc->bvh, acc->tri, ray, t_max, hit, NULL);
}

static int bvh4_available(const struct trace_kernels *k, const struct bench_accel *acc)
{
    return k->closest4 != NULL && acc->wide.node_count > 0;
}

static int bvh4_closest(const struct trace_kernels *k, const struct bench_accel *acc,
                        const struct trace_ray *ray, float t_max, struct trace_hit *hit)
{
    return k->closest4(&acc->wide, &acc->bvh, acc->tri, ray, t_max, hit, NULL);
}

static const struct err_layout layouts[] = {
    {"binary", binary_available, binary_closest},
    {"bvh4", bvh4_available, bvh4_closest},
};
#define LAYOUTS ((int)(sizeof(layouts) / sizeof(layouts[0])))

enum err_kind { KIND_BVH, KIND_BRUTE, KIND_EMBREE, KIND_EMBREE_ROBUST };

/* One row of the table. */
struct err_kernel {
    enum err_kind kind;
    const struct trace_kernels *k; /* KIND_BVH */
    const struct err_layout *layout;
    char label[48];
    char isa[16];
    char layout_name[24];
};

/* What a kernel traces against in one workload. */
struct err_target {
    const struct err_kernel *kernel;
    const struct bench_mesh *mesh;
    const struct bench_accel *acc;
#ifdef RT_HAVE_EMBREE
    RTCScene embree;
#endif
};

/* One closest-hit query through the kernel; 1 and *h on a hit. */
static int err_trace(const struct err_target *g, const RTray *r, struct trace_hit *h)
{
    const struct err_kernel *kn = g->kernel;
    if (kn->kind == KIND_EMBREE || kn->kind == KIND_EMBREE_ROBUST) {
#ifdef RT_HAVE_EMBREE
        struct RTCIntersectContext ic;
        rtcInitIntersectContext(&ic);
        struct RTCRayHit rh;
        bench_embree_ray_hit(r, &rh);
        rtcIntersect1(g->embree, &ic, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
            return 0;
        h->t = rh.ray.tfar;
        h->u = rh.hit.u;
        h->v = rh.hit.v;
        h->prim = rh.hit.primID;
        return 1;
#else
        return 0;
#endif
    }
    struct trace_ray ray;
    trace_ray_init(&ray, r->org, r->dir, r->tmin);
    if (kn->kind == KIND_BRUTE)
        return trace_closest_brute_force(g->mesh->positions, g->mesh->indices,
                                         g->mesh->tri_count, &ray, r->tmax, h);
    return kn->layout->closest(kn->k, g->acc, &ray, r->tmax, h);
}

/* bench_kernel_fn over err_trace, for the timed runs. */
static void err_kernel_fn(void *ctx, const RTray *rays, uint32_t begin, uint32_t end,
                          struct bench_hit *hits)
{
    const struct err_target *g = ctx;
    for (uint32_t i = begin; i < end; i++) {
        struct trace_hit h;
        if (err_trace(g, &rays[i], &h)) {
            hits[i].t = h.t;
            hits[i].prim = h.prim;
        } else {
            hits[i].t = INFINITY;
            hits[i].prim = BENCH_MISS;
        }
    }
}

static int kernel_list(struct err_kernel *list, const struct bench_accel *probe)
{
    int n = 0;
    for (int isa = 0; isa < TRACE_ISA_COUNT; isa++) {
        const struct trace_kernels *k = trace_kernels_get((enum trace_isa)isa);
        if (!k)
            continue;
        for (int l = 0; l < LAYOUTS && n < ERR_MAX_ROWS - 3; l++) {
            if (!layouts[l].available(k, probe))
                continue;
            struct err_kernel *e = &list[n++];
            memset(e, 0, sizeof(*e));
            e->kind = KIND_BVH;
            e->k = k;
            e->layout = &layouts[l];
            snprintf(e->label, sizeof(e->label), "%s %s", k->name, layouts[l].name);
            snprintf(e->isa, sizeof(e->isa), "%s", k->name);
            snprintf(e->layout_name, sizeof(e->layout_name), "%s", layouts[l].name);
        }
    }
    struct err_kernel *b = &list[n++];
    memset(b, 0, sizeof(*b));
    b->kind = KIND_BRUTE;
    snprintf(b->label, sizeof(b->label), "brute force");
    snprintf(b->isa, sizeof(b->isa), "scalar");
    snprintf(b->layout_name, sizeof(b->layout_name), "none");
#ifdef RT_HAVE_EMBREE
    for (int robust = 0; robust < 2; robust++) {
        struct err_kernel *e = &list[n++];
        memset(e, 0, sizeof(*e));
        e->kind = robust ? KIND_EMBREE_ROBUST : KIND_EMBREE;
        snprintf(e->label, sizeof(e->label), "Embree%s", robust ? " robust" : "");
        snprintf(e->isa, sizeof(e->isa), "Embree's");
        snprintf(e->layout_name, sizeof(e->layout_name), "%s",
                 robust ? "MEDIUM, ROBUST flag" : "MEDIUM");
    }
#endif
    return n;
}

#ifdef RT_HAVE_EMBREE
static RTCScene err_embree_scene(RTCDevice device, const struct bench_mesh *m, int robust)
{
    RTCScene scene = rtcNewScene(device);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!scene || !geom)
        goto fail;
    if (robust)
        rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
    /* One spare vertex: Embree reads vertices with 16-byte loads. */
    float *v = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                       3 * sizeof(float), m->vertex_count + 1);
    unsigned *idx = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                            3 * sizeof(unsigned), m->tri_count);
    if (!v || !idx)
        goto fail;
    memcpy(v, m->positions, (size_t)m->vertex_count * 3 * sizeof(float));
    memcpy(idx, m->indices, (size_t)m->tri_count * 3 * sizeof(unsigned));
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    geom = NULL;
    rtcCommitScene(scene);
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE)
        goto fail;
    return scene;
fail:
    if (geom)
        rtcReleaseGeometry(geom);
    if (scene)
        rtcReleaseScene(scene);
    return NULL;
}
#endif

/* ------------------------------------------------------------ measurement */

struct err_result {
    double ns_per_ray;
    double t_max, t_mean;   /* relative t error */
    double uv_max, uv_mean; /* barycentric error */
    uint32_t hits;          /* over the measured rays */
    double agree;           /* percent of the sample agreeing with the double reference */
    uint32_t measured;      /* rays measured (all, or the sample for brute force) */
    uint32_t bit_diff;      /* BVH kernels: rays not bit-identical to the first row */
};

/* Errors of one kernel over a set; full hits go to out (count entries). */
static void measure_errors(const struct err_target *g, const struct bench_rays *set,
                           struct trace_hit *out, int *hit, struct err_result *res)
{
    const struct bench_mesh *m = g->mesh;
    double t_sum = 0.0, uv_sum = 0.0;
    uint32_t n_err = 0;
    res->t_max = res->uv_max = 0.0;
    res->hits = 0;
    for (uint32_t i = 0; i < set->count; i++) {
        const RTray *r = &set->rays[i];
        hit[i] = err_trace(g, r, &out[i]);
        if (!hit[i])
            continue;
        res->hits++;
        const uint32_t *vi = &m->indices[3 * (size_t)out[i].prim];
        long double t, u, v;
        if (out[i].prim >= m->tri_count ||
            !exact_tuv(r, &m->positions[3 * (size_t)vi[0]], &m->positions[3 * (size_t)vi[1]],
                       &m->positions[3 * (size_t)vi[2]], &t, &u, &v) ||
            t == 0.0L)
            continue;
        double et = (double)fabsl(((long double)out[i].t - t) / t);
        double eu = (double)fabsl((long double)out[i].u - u);
        double ev = (double)fabsl((long double)out[i].v - v);
        double euv = eu > ev ? eu : ev;
        t_sum += et;
        uv_sum += euv;
        n_err++;
        res->t_max = et > res->t_max ? et : res->t_max;
        res->uv_max = euv > res->uv_max ? euv : res->uv_max;
    }
    res->t_mean = n_err ? t_sum / n_err : 0.0;
    res->uv_mean = n_err ? uv_sum / n_err : 0.0;
    res->measured = set->count;
}

int bench_error_section(const struct bench_options *opts)
{
    report_printf("\n## Intersection error against time\n\n");
    report_printf(
        "DESIGN.md's last measurement. Per kernel (every ISA table this CPU runs, times every "
        "object layout it walks; the brute-force reference intersector; Embree%s) on the "
        "stability workloads below: closest-hit ns per ray on one thread (median of %d "
        "interleaved runs of %d passes over the rays), the relative hit-distance error "
        "|t - t*| / t* and the barycentric error max(|u - u*|, |v - v*|), where t*, u*, v* "
        "are the same ray's intersection with the triangle the kernel reports, computed here "
        "in long double (Moeller and Trumbore 1997) from the float inputs, which it "
        "represents exactly (mean and max over the rays that hit); \"= double ref\": hit/miss "
        "and t (within %.0e relative) against the closest hit over all triangles in double "
        "precision, on a sample of %d rays (the brute-force row is measured on that sample "
        "only, and timed on %d of its rays in one pass). \"bits = first row\": rays whose t, u, v and primitive differ "
        "from the first row's in any bit (our kernels must give none).\n\n",
#ifdef RT_HAVE_EMBREE
        " MEDIUM quality, without and with RTC_SCENE_FLAG_ROBUST",
#else
        " skipped: built without Embree",
#endif
        opts->runs, ERR_REPEAT, (double)BENCH_T_TOLERANCE,
        opts->quick ? ERR_SAMPLE_QUICK : ERR_SAMPLE, ERR_BRUTE_TIMED);
    report_table_header("workload|what|triangles|rays");
    bench_share_reset();
    double start = rt_now_ms();
#ifdef RT_HAVE_EMBREE
    RTCDevice device = rtcNewDevice("threads=1");
    if (!device)
        return -1;
    rtcSetDeviceErrorFunction(device, bench_embree_error, NULL);
#endif
    struct err_workload w[WORKLOADS];
    memset(w, 0, sizeof(w));
    int rc = -1;
    for (int i = 0; i < WORKLOADS; i++) {
        if (workload_make(&w[i], i, opts->quick))
            goto out;
        report_row("%s|%s|%u|%u", workloads[i].name, workloads[i].what, w[i].mesh.tri_count,
                   w[i].rays.count);
    }

    struct err_kernel kernels[ERR_MAX_ROWS];
    int nk = 0;
    struct err_result res[WORKLOADS][ERR_MAX_ROWS];
    memset(res, 0, sizeof(res));
    for (int i = 0; i < WORKLOADS; i++) {
        struct bench_accel acc;
        struct bvh_build_params params;
        bvh_build_params_default(&params);
        if (bench_accel_build(&acc, &w[i].mesh, &params))
            goto out;
        if (i == 0)
            nk = kernel_list(kernels, &acc);
        report_progress("error: %s, %d kernels\n", workloads[i].name, nk);
        struct err_target targets[ERR_MAX_ROWS];
        const uint32_t n = w[i].rays.count, ns = w[i].sample.count;
        struct trace_hit *full = malloc((size_t)n * sizeof(*full));
        struct trace_hit *first = malloc((size_t)n * sizeof(*first));
        int *hit = malloc((size_t)n * sizeof(*hit));
        int *first_hit = malloc((size_t)n * sizeof(*first_hit));
        struct bench_hit *scratch = malloc((size_t)n * sizeof(*scratch));
        struct bench_hit *ref = malloc((size_t)ns * sizeof(*ref));
        int ok = full && first && hit && first_hit && scratch && ref;
        for (int k = 0; k < nk; k++) {
            memset(&targets[k], 0, sizeof(targets[k]));
            targets[k].kernel = &kernels[k];
            targets[k].mesh = &w[i].mesh;
            targets[k].acc = &acc;
#ifdef RT_HAVE_EMBREE
            if (ok && (kernels[k].kind == KIND_EMBREE || kernels[k].kind == KIND_EMBREE_ROBUST)) {
                targets[k].embree = err_embree_scene(device, &w[i].mesh,
                                                     kernels[k].kind == KIND_EMBREE_ROBUST);
                ok = targets[k].embree != NULL;
            }
#endif
        }
        if (ok) {
            for (uint32_t s = 0; s < ns; s++)
                ref[s] = closest_double(&w[i].mesh, &w[i].sample.rays[s]);
            /* Errors, agreement with the double reference, bits. */
            for (int k = 0; k < nk; k++) {
                const int brute = kernels[k].kind == KIND_BRUTE;
                const struct bench_rays *set = brute ? &w[i].sample : &w[i].rays;
                measure_errors(&targets[k], set, full, hit, &res[i][k]);
                struct bench_agreement a;
                memset(&a, 0, sizeof(a));
                for (uint32_t s = 0; s < ns; s++) {
                    uint32_t idx = brute ? s : s * (n / ns);
                    struct bench_hit mine = {hit[idx] ? full[idx].t : INFINITY,
                                             hit[idx] ? full[idx].prim : BENCH_MISS};
                    bench_compare_hits(&a, &mine, &ref[s], 1, 1);
                }
                res[i][k].agree = bench_agreement_percent(&a);
                if (k == 0) {
                    memcpy(first, full, (size_t)n * sizeof(*first));
                    memcpy(first_hit, hit, (size_t)n * sizeof(*first_hit));
                } else if (kernels[k].kind == KIND_BVH) {
                    uint32_t diff = 0;
                    for (uint32_t r = 0; r < n; r++)
                        diff += hit[r] != first_hit[r] ||
                                (hit[r] && memcmp(&full[r], &first[r], sizeof(full[r])) != 0);
                    res[i][k].bit_diff = diff;
                    if (diff) {
                        report_check_failed();
                        report_progress("rtbench: error: %s: %s differs from %s on %u rays\n",
                                        workloads[i].name, kernels[k].label, kernels[0].label,
                                        diff);
                    }
                }
            }
            /* Timing: interleaved runs. */
            double times[ERR_MAX_ROWS][101];
            struct bench_rays brute_set = w[i].sample;
            if (brute_set.count > ERR_BRUTE_TIMED)
                brute_set.count = ERR_BRUTE_TIMED;
            for (int run = 0; run < opts->runs && ok; run++)
                for (int k = 0; k < nk && ok; k++) {
                    const int brute = kernels[k].kind == KIND_BRUTE;
                    const struct bench_rays *set = brute ? &brute_set : &w[i].rays;
                    const int passes = brute ? 1 : ERR_REPEAT;
                    double ms = 0.0;
                    for (int p = 0; p < passes && ok; p++) {
                        double t = bench_run_parallel(err_kernel_fn, &targets[k], set, scratch, 1);
                        ok = t >= 0.0;
                        ms += t;
                    }
                    times[k][run] = ms * 1e6 / ((double)passes * set->count);
                }
            for (int k = 0; k < nk && ok; k++)
                res[i][k].ns_per_ray = bench_median(times[k], opts->runs);
        }
#ifdef RT_HAVE_EMBREE
        for (int k = 0; k < nk; k++)
            if (targets[k].embree)
                rtcReleaseScene(targets[k].embree);
#endif
        free(full);
        free(first);
        free(hit);
        free(first_hit);
        free(scratch);
        free(ref);
        bench_accel_release(&acc);
        if (!ok)
            goto out;
    }

    report_printf("\n");
    report_table_header("workload|kernel|ISA|layout|ns/ray|hits|t error mean|t error max|"
                        "u/v error mean|u/v error max|= double ref|bits = first row");
    for (int i = 0; i < WORKLOADS; i++)
        for (int k = 0; k < nk; k++) {
            const struct err_result *r = &res[i][k];
            char bits[24];
            if (kernels[k].kind == KIND_BVH)
                snprintf(bits, sizeof(bits), "%u differ", r->bit_diff);
            else
                snprintf(bits, sizeof(bits), "n/a");
            report_row("%s|%s|%s|%s|%.1f|%u of %u|%.2e|%.2e|%.2e|%.2e|%.2f%%|%s",
                       workloads[i].name, kernels[k].label, kernels[k].isa,
                       kernels[k].layout_name, r->ns_per_ray, r->hits, r->measured, r->t_mean,
                       r->t_max, r->uv_mean, r->uv_max, r->agree, bits);
            char key[128];
            snprintf(key, sizeof(key), "error.%s.%s.ns_per_ray", workloads[i].name,
                     kernels[k].label);
            for (char *c = key; *c; c++)
                if (*c == ' ')
                    *c = '_';
            report_metric(key, r->ns_per_ray, 0);
        }

    /* Summary per kernel: the plot's points. */
    report_printf("\nPer kernel over the %d workloads: mean ns per ray, largest errors.\n\n",
                  WORKLOADS);
    report_table_header("kernel|mean ns/ray|t error max|u/v error max|lowest = double ref");
    FILE *data = report_data_file("error.dat");
    if (data)
        fprintf(data, "# kernel, mean ns/ray, max relative t error, max u/v error\n");
    for (int k = 0; k < nk; k++) {
        double ns = 0.0, tm = 0.0, uvm = 0.0, agree = 100.0;
        for (int i = 0; i < WORKLOADS; i++) {
            ns += res[i][k].ns_per_ray / WORKLOADS;
            tm = res[i][k].t_max > tm ? res[i][k].t_max : tm;
            uvm = res[i][k].uv_max > uvm ? res[i][k].uv_max : uvm;
            agree = res[i][k].agree < agree ? res[i][k].agree : agree;
        }
        report_row("%s|%.1f|%.2e|%.2e|%.2f%%", kernels[k].label, ns, tm, uvm, agree);
        if (data)
            fprintf(data, "\"%s\" %.4f %.6e %.6e\n", kernels[k].label, ns,
                    tm > 1e-12 ? tm : 1e-12, uvm > 1e-12 ? uvm : 1e-12);
    }
    if (data) {
        fclose(data);
        report_plot("error",
                    "set terminal pngcairo size 900,560 font ',10'\n"
                    "set output 'error.png'\n"
                    "set title 'Intersection error against time (stability workloads, one "
                    "thread)'\n"
                    "set xlabel 'mean ns per ray (closest hit)'\n"
                    "set ylabel 'largest error (log)'\n"
                    "set logscale xy\n"
                    "set format y '10^{%L}'\n"
                    "set grid\n"
                    "set key top right\n"
                    "plot 'error.dat' using 2:3 with points pt 7 ps 1.5 title 'relative t "
                    "error', \\\n"
                    "     'error.dat' using 2:4 with points pt 5 ps 1.2 title 'u/v error', \\\n"
                    "     'error.dat' using 2:3:1 with labels rotate by 40 offset char 0.5,0.8 left "
                    "font ',8' notitle\n");
    }
    report_printf("\n");
    bench_share_report();
    report_printf("\nThe error section took %.1f s.\n", (rt_now_ms() - start) / 1e3);
    rc = 0;
out:
    for (int i = 0; i < WORKLOADS; i++)
        workload_release(&w[i]);
#ifdef RT_HAVE_EMBREE
    rtcReleaseDevice(device);
#endif
    return rc;
}
