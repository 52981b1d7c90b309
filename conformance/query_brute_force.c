/* SPDX-License-Identifier: Apache-2.0 */
/*
 * query_brute_force.c - rtTraceRays and rtOccludedRays against a
 * double-precision brute-force intersector (brute_force.h).
 *
 * Random scenes of 1, 10, 100, 1k and 10k triangles, three seeds each: up
 * to three objects (a triangle soup, a heightfield whose triangles share
 * vertices, a soup of long thin slivers), each placed one to three times
 * under random affine matrices (rotation, non-uniform scale 0.5..2 with
 * shear and sometimes a mirror, translation).  The test transforms the
 * float vertices it issued by those matrices itself, in double, and checks
 * every closest hit against all world-space triangles (brute_force.h states
 * the rules).  Rays: aimed at random points of random triangles (a tenth
 * exactly on an edge, a twentieth at a vertex), fully random ones, and
 * aimed ones with random [tmin, tmax) intervals including empty ones.
 *
 * rtOccludedRays must agree exactly with rtTraceRays on every batch: both
 * walk the same structures with the same float arithmetic, so "a hit in
 * [tmin, tmax)" cannot differ between them.  Each hit is re-queried with
 * tmax = t (exclusive: never occluded, since a closer hit would have been
 * reported) and with tmax just above t (judged again by the reference).
 *
 * The three seeds of a size use the binned builder with 16 bins, the
 * sweep builder, and the binned builder with 4 bins.
 *
 * Tolerances (see brute_force.h): rel_t = 1e-4 and pos_eps = 1e-5 times
 * the largest coordinate magnitude of the scene and the rays (about 30
 * here, so pos_eps ~ 3e-4).  The library moves each ray into object space
 * and rounds it to float there: the origin, ~30 units out, maps to object
 * coordinates up to ~100 (inverse factors up to 2), where a float ulp is
 * 7.6e-6, times 2 back in world units.  The largest error seen along the
 * normal is printed at the end ("largest position error"): 8e-5 with the
 * ray transformed by a float matrix and t computed as the watertight
 * test's T / det, 4e-6 with both done in double, so pos_eps keeps a
 * margin of at least 3 either way.  Grazing hits get pos_eps / cosine,
 * and barycentrics of thin or grazed triangles a conditioning term
 * (brute_force.h).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "brute_force.h"
#include "testutil.h"

#define MAX_OBJECTS 3
#define REL_T 1e-4
#define POS_EPS_PER_UNIT 1e-5
/* Brute-force budget per scene: rays * world triangles; a quarter of it
 * (at least 500 rays a scene, as always) with RT_TEST_WORKLOAD=small, which
 * scripts/test.sh sets for the sanitizer suites: fewer rays, the same
 * scenes and checks. */
#define BRUTE_FORCE_BUDGET 5.0e7
#define BRUTE_FORCE_BUDGET_SMALL 1.25e7
#define MAX_PRINTED_FAILURES 10

struct object_def {
    RTuint name;
    float *positions; /* 9 floats per triangle */
    uint32_t tri_count;
};

static void push_tri(struct object_def *o, uint32_t *cap, const float a[3], const float b[3],
                     const float c[3])
{
    if (o->tri_count == *cap) {
        *cap = *cap ? 2 * *cap : 16;
        o->positions = bf_xrealloc(o->positions, (size_t)*cap * 9 * sizeof(float));
    }
    float *p = &o->positions[9 * (size_t)o->tri_count++];
    memcpy(p, a, 3 * sizeof(float));
    memcpy(p + 3, b, 3 * sizeof(float));
    memcpy(p + 6, c, 3 * sizeof(float));
}

static void random_point(struct bf_rng *r, float p[3], double lo, double hi)
{
    for (int k = 0; k < 3; k++)
        p[k] = (float)bf_range(r, lo, hi);
}

/* kind 0: soup of random triangles, sizes log-uniform in [0.05, 3]. */
static void make_soup(struct bf_rng *r, struct object_def *o, uint32_t n)
{
    uint32_t cap = 0;
    for (uint32_t i = 0; i < n; i++) {
        float c[3], v[3][3];
        random_point(r, c, -4.0, 4.0);
        double size = exp(bf_range(r, log(0.05), log(3.0)));
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                v[j][k] = c[k] + (float)(size * bf_range(r, -0.5, 0.5));
        push_tri(o, &cap, v[0], v[1], v[2]);
    }
}

/* kind 1: heightfield over [-4,4]^2 whose triangles share float vertices. */
static void make_heightfield(struct bf_rng *r, struct object_def *o, uint32_t n)
{
    uint32_t cells = n / 2 ? n / 2 : 1;
    uint32_t nx = (uint32_t)sqrt((double)cells);
    if (nx == 0)
        nx = 1;
    uint32_t ny = cells / nx;
    float *h = bf_xrealloc(NULL, (size_t)(nx + 1) * (ny + 1) * sizeof(float));
    for (size_t i = 0; i < (size_t)(nx + 1) * (ny + 1); i++)
        h[i] = (float)bf_range(r, -0.5, 0.5);
    uint32_t cap = 0;
    for (uint32_t j = 0; j < ny; j++)
        for (uint32_t i = 0; i < nx; i++) {
            float p[4][3];
            for (int c = 0; c < 4; c++) {
                uint32_t x = i + (c & 1), y = j + (c >> 1);
                p[c][0] = -4.0f + 8.0f * (float)x / (float)nx;
                p[c][1] = -4.0f + 8.0f * (float)y / (float)ny;
                p[c][2] = h[y * (nx + 1) + x];
            }
            push_tri(o, &cap, p[0], p[1], p[3]);
            push_tri(o, &cap, p[0], p[3], p[2]);
        }
    /* Top up with soup so the object has exactly n triangles. */
    while (o->tri_count < n) {
        float a[3], b[3], c[3];
        random_point(r, a, -4.0, 4.0);
        random_point(r, b, -4.0, 4.0);
        random_point(r, c, -4.0, 4.0);
        push_tri(o, &cap, a, b, c);
    }
    free(h);
}

/* kind 2: long thin slivers (length up to 6, width 1e-3 .. 1e-1). */
static void make_slivers(struct bf_rng *r, struct object_def *o, uint32_t n)
{
    uint32_t cap = 0;
    for (uint32_t i = 0; i < n; i++) {
        float a[3], b[3], c[3];
        random_point(r, a, -4.0, 4.0);
        double d[3], e[3];
        bf_unit_vector(r, d);
        bf_unit_vector(r, e);
        double len = bf_range(r, 1.0, 6.0);
        double width = exp(bf_range(r, log(1e-3), log(1e-1)));
        for (int k = 0; k < 3; k++) {
            b[k] = a[k] + (float)(len * d[k]);
            c[k] = a[k] + (float)(0.5 * len * d[k] + width * e[k]);
        }
        push_tri(o, &cap, a, b, c);
    }
}

static void define_object(const struct object_def *o)
{
    rtNewObject(o->name);
    rtBegin(RT_TRIANGLES);
    for (uint32_t i = 0; i < 3 * o->tri_count; i++)
        rtVertex3fv(&o->positions[3 * (size_t)i]);
    rtEnd();
    rtEndObject();
}

struct scene {
    struct object_def objects[MAX_OBJECTS];
    int object_count;
    struct bf_scene ref;
    double extent; /* largest coordinate magnitude of the world triangles */
};

static void build_scene(struct scene *sc, struct bf_rng *r, uint32_t n)
{
    memset(sc, 0, sizeof(*sc));
    sc->object_count = n >= MAX_OBJECTS ? MAX_OBJECTS : (int)n;
    RTuint names[MAX_OBJECTS];
    rtGenObjects(sc->object_count, names);
    for (int k = 0; k < sc->object_count; k++) {
        struct object_def *o = &sc->objects[k];
        o->name = names[k];
        uint32_t share = n / (uint32_t)sc->object_count + (k == 0 ? n % sc->object_count : 0);
        if (k == 0)
            make_soup(r, o, share);
        else if (k == 1)
            make_heightfield(r, o, share);
        else
            make_slivers(r, o, share);
        define_object(o);
    }
    rtBeginFrame();
    rtMatrixMode(RT_MODELVIEW);
    for (int k = 0; k < sc->object_count; k++) {
        int copies = 1 + (int)bf_below(r, 3);
        for (int c = 0; c < copies; c++) {
            double m[16];
            if (k == 0 && c == 0)
                bf_identity(m); /* one instance exactly in place */
            else
                bf_random_affine(r, m, 0.5, 2.0, 6.0);
            rtLoadMatrixd(m);
            rtInstantiateObject(sc->objects[k].name);
            bf_scene_add_instance(&sc->ref, sc->objects[k].positions, sc->objects[k].tri_count, m,
                                  sc->objects[k].name);
        }
    }
    rtLoadIdentity();
    sc->extent = 0.0;
    for (size_t i = 0; i < sc->ref.count; i++)
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < 3; k++)
                if (fabs(sc->ref.tris[i].v[c][k]) > sc->extent)
                    sc->extent = fabs(sc->ref.tris[i].v[c][k]);
}

static void free_scene(struct scene *sc)
{
    RTuint names[MAX_OBJECTS];
    for (int k = 0; k < sc->object_count; k++) {
        names[k] = sc->objects[k].name;
        free(sc->objects[k].positions);
    }
    rtDeleteObjects(sc->object_count, names);
    bf_scene_free(&sc->ref);
}

/* Ray kinds, for the statistics. */
enum ray_kind { RAY_AIMED_INSIDE, RAY_AIMED_BOUNDARY, RAY_RANDOM, RAY_INTERVAL };

/* A point of world triangle i: random inside, on an edge, or a vertex.
 * Returns 1 for a point on the boundary. */
static int aim_point(struct bf_rng *r, const struct bf_tri *t, double p[3])
{
    double b[3];
    double kind = bf_uniform(r);
    int boundary = kind < 0.15;
    if (kind < 0.05) {
        b[0] = b[1] = b[2] = 0.0;
        b[bf_below(r, 3)] = 1.0;
    } else if (kind < 0.15) {
        int zero = (int)bf_below(r, 3);
        double s = bf_uniform(r);
        b[zero] = 0.0;
        b[(zero + 1) % 3] = s;
        b[(zero + 2) % 3] = 1.0 - s;
    } else {
        double s = bf_uniform(r), u = bf_uniform(r);
        if (s + u > 1.0) {
            s = 1.0 - s;
            u = 1.0 - u;
        }
        b[0] = 1.0 - s - u;
        b[1] = s;
        b[2] = u;
    }
    for (int k = 0; k < 3; k++)
        p[k] = b[0] * t->v[0][k] + b[1] * t->v[1][k] + b[2] * t->v[2][k];
    return boundary;
}

static void make_rays(struct bf_rng *r, const struct scene *sc, RTray *rays, unsigned char *kinds,
                      int count, double radius)
{
    for (int i = 0; i < count; i++) {
        RTray *ray = &rays[i];
        double kind = bf_uniform(r);
        double org[3], dir[3];
        double t_target = 1.0;
        if (kind < 0.75 && sc->ref.count > 0) {
            double target[3], u[3];
            int boundary =
                aim_point(r, &sc->ref.tris[bf_below(r, (uint32_t)sc->ref.count)], target);
            kinds[i] = boundary ? RAY_AIMED_BOUNDARY : RAY_AIMED_INSIDE;
            bf_unit_vector(r, u);
            for (int k = 0; k < 3; k++)
                org[k] = radius * u[k];
            double scale = bf_uniform(r) < 0.5 ? 1.0 : exp(bf_range(r, log(0.1), log(10.0)));
            for (int k = 0; k < 3; k++)
                dir[k] = (target[k] - org[k]) * scale;
            t_target = 1.0 / scale;
        } else {
            kinds[i] = RAY_RANDOM;
            for (int k = 0; k < 3; k++)
                org[k] = bf_range(r, -0.5 * radius, 0.5 * radius);
            bf_unit_vector(r, dir);
            double len = bf_range(r, 0.5, 2.0);
            for (int k = 0; k < 3; k++)
                dir[k] *= len;
        }
        for (int k = 0; k < 3; k++) {
            ray->org[k] = (float)org[k];
            ray->dir[k] = (float)dir[k];
        }
        ray->tmin = 0.0f;
        ray->tmax = INFINITY;
        if (kind >= 0.5 && kind < 0.75) {
            /* A random interval around the aimed point, some of them empty. */
            kinds[i] = RAY_INTERVAL;
            double c = bf_uniform(r);
            double lo = bf_range(r, 0.0, 1.2) * t_target;
            double hi = lo + bf_range(r, 0.0, 1.0) * t_target;
            if (c < 0.05)
                hi = lo;
            else if (c < 0.10)
                hi = lo * 0.5;
            else if (c < 0.15)
                lo = hi = 0.0;
            ray->tmin = (float)lo;
            ray->tmax = (float)hi;
        }
        /* Directions that round to zero cannot occur: |dir| >= ~0.1. */
    }
}

static void print_ray(const RTray *ray, const RThit *hit)
{
    fprintf(stderr,
            "    ray org (%.9g, %.9g, %.9g) dir (%.9g, %.9g, %.9g) tmin %.9g tmax %.9g\n"
            "    hit t %.9g u %.9g v %.9g instance %u object %u primitive %u\n",
            ray->org[0], ray->org[1], ray->org[2], ray->dir[0], ray->dir[1], ray->dir[2], ray->tmin,
            ray->tmax, hit->t, hit->u, hit->v, hit->instance, hit->object, hit->primitive);
}

/* Judges a batch; returns the number of failures.  With kinds, counts
 * the rays aimed inside a triangle (*inside) and how many of them were
 * tolerated rather than exact (*inside_tolerated). */
static long judge(const struct scene *sc, const RTray *rays, const RThit *hits, int count,
                  const struct bf_tolerance *tol, struct bf_stats *stats, const char *what,
                  double *largest_error, const unsigned char *kinds, long *inside,
                  long *inside_tolerated)
{
    long failures = 0;
    char why[256];
    for (int i = 0; i < count; i++) {
        long tolerated_before = stats->tolerated;
        int ok = bf_check_hit(&sc->ref, &rays[i], &hits[i], tol, stats, why, sizeof(why));
        if (kinds && kinds[i] == RAY_AIMED_INSIDE) {
            ++*inside;
            *inside_tolerated += stats->tolerated - tolerated_before;
        }
        if (!ok) {
            if (failures++ < MAX_PRINTED_FAILURES) {
                fprintf(stderr, "  %s ray %d: %s\n", what, i, why);
                print_ray(&rays[i], &hits[i]);
            }
            continue;
        }
        if (hits[i].t < INFINITY) {
            /* Position error along the normal of the reported triangle. */
            const struct bf_tri *t =
                &sc->ref.tris[sc->ref.base[hits[i].instance] + hits[i].primitive];
            double org[3] = {rays[i].org[0], rays[i].org[1], rays[i].org[2]};
            double dir[3] = {rays[i].dir[0], rays[i].dir[1], rays[i].dir[2]};
            struct bf_isect x = bf_intersect(t, org, dir);
            double e = fabs(hits[i].t - x.t) * x.cosine * bf_length(dir);
            if (e > *largest_error)
                *largest_error = e;
        }
    }
    return failures;
}

/* rtOccludedRays must equal "rtTraceRays found a hit", ray by ray. */
static long occlusion_mismatches(const RTray *rays, const RThit *hits, int count,
                                 RTboolean *occluded, const char *what)
{
    memset(occluded, 0x55, (size_t)count);
    rtOccludedRays(count, rays, occluded);
    long bad = 0;
    for (int i = 0; i < count; i++) {
        int expected = hits[i].t < INFINITY;
        if (occluded[i] != (RTboolean)expected) {
            if (bad++ < MAX_PRINTED_FAILURES) {
                fprintf(stderr, "  %s ray %d: occluded=%d but rtTraceRays %s\n", what, i,
                        occluded[i], expected ? "hit" : "missed");
                print_ray(&rays[i], &hits[i]);
            }
        }
    }
    return bad;
}

static void run_scene(uint32_t n, int seed_index, double *largest_error)
{
    static const char *const configs[3] = {"builder=binned bins=16", "builder=sweep",
                                           "builder=binned bins=4"};
    char label[96];
    snprintf(label, sizeof(label), "%u triangles, seed %d, %s", n, seed_index,
             configs[seed_index % 3]);
    tu_section(label);
    RTcontext ctx = tu_make_context(configs[seed_index % 3]);
    struct bf_rng r;
    bf_seed(&r, 1000u * n + (uint64_t)seed_index);
    struct scene sc;
    build_scene(&sc, &r, n);
    CHECK_NO_ERR();

    double radius = 1.5 * (sc.extent > 1.0 ? sc.extent : 1.0);
    double magnitude = radius > sc.extent ? radius : sc.extent;
    struct bf_tolerance tol = {REL_T, POS_EPS_PER_UNIT * magnitude};
    double budget = (tu_small_workload() ? BRUTE_FORCE_BUDGET_SMALL : BRUTE_FORCE_BUDGET) /
                    (double)(sc.ref.count ? sc.ref.count : 1);
    int count = budget > 20000 ? 20000 : budget < 500 ? 500 : (int)budget;

    RTray *rays = bf_xrealloc(NULL, (size_t)count * sizeof(*rays));
    RThit *hits = bf_xrealloc(NULL, (size_t)count * sizeof(*hits));
    RTray *again = bf_xrealloc(NULL, (size_t)count * sizeof(*again));
    RThit *again_hits = bf_xrealloc(NULL, (size_t)count * sizeof(*again_hits));
    RTboolean *occluded = bf_xrealloc(NULL, (size_t)count);
    unsigned char *kinds = bf_xrealloc(NULL, (size_t)count);
    make_rays(&r, &sc, rays, kinds, count, radius);

    memset(hits, 0x55, (size_t)count * sizeof(*hits));
    rtTraceRays(count, rays, hits);
    CHECK_NO_ERR();
    struct bf_stats stats = {0, 0, 0, 0, 0, 0.0};
    long inside = 0, inside_tolerated = 0;
    long failures = judge(&sc, rays, hits, count, &tol, &stats, "closest", largest_error, kinds,
                          &inside, &inside_tolerated);
    CHECK_INT(failures, 0);
    CHECK_INT(occlusion_mismatches(rays, hits, count, occluded, "occluded"), 0);
    CHECK_NO_ERR();

    /* tmax = t: the hit itself is excluded and nothing closer exists. */
    int hit_count = 0;
    for (int i = 0; i < count; i++)
        if (hits[i].t < INFINITY) {
            again[hit_count] = rays[i];
            again[hit_count].tmax = hits[i].t;
            hit_count++;
        }
    memset(occluded, 0x55, (size_t)count);
    rtOccludedRays(hit_count, again, occluded);
    long leaked = 0;
    for (int i = 0; i < hit_count; i++)
        if (occluded[i] != RT_FALSE && leaked++ < MAX_PRINTED_FAILURES)
            fprintf(stderr, "  ray %d occluded in [tmin, t) of its own closest hit\n", i);
    CHECK_INT(leaked, 0);

    /* tmax just above t: judged again, and occlusion must agree. */
    for (int i = 0; i < hit_count; i++)
        again[i].tmax = nextafterf(again[i].tmax * (1.0f + 1e-5f), INFINITY);
    rtTraceRays(hit_count, again, again_hits);
    struct bf_stats stats2 = {0, 0, 0, 0, 0, 0.0};
    CHECK_INT(judge(&sc, again, again_hits, hit_count, &tol, &stats2, "tmax above hit",
                    largest_error, NULL, NULL, NULL),
              0);
    CHECK_INT(occlusion_mismatches(again, again_hits, hit_count, occluded, "tmax above hit"), 0);
    CHECK_NO_ERR();

    /* Rays aimed inside a triangle rarely pass within the tolerance of an
     * edge or silhouette: differences from the exact closest triangle must
     * stay rare there, or the tolerances are hiding a systematic error. */
    CHECK(inside_tolerated * 100 <= inside);
    printf("   %d rays against %zu world triangles: %ld hits, %ld exact, %ld tolerated "
           "(%ld of %ld aimed inside), %ld failed; pos_eps %.3g, worst barycentric ratio %.3g\n",
           count, sc.ref.count, stats.hits, stats.exact, stats.tolerated, inside_tolerated, inside,
           stats.failures, tol.pos_eps, stats.worst_bary_ratio);

    free(rays);
    free(hits);
    free(again);
    free(again_hits);
    free(occluded);
    free(kinds);
    free_scene(&sc);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
}

int main(void)
{
    static const uint32_t sizes[] = {1, 10, 100, 1000, 10000};
    clock_t start = clock();
    double largest_error = 0.0;
    for (size_t s = 0; s < sizeof(sizes) / sizeof(sizes[0]); s++)
        for (int seed = 0; seed < 3; seed++)
            run_scene(sizes[s], seed, &largest_error);
    printf("largest position error along the normal: %.3g world units\n", largest_error);
    printf("cpu time %.2f s\n", (double)(clock() - start) / CLOCKS_PER_SEC);
    return test_summary("query_brute_force");
}
