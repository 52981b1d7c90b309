/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dynamic_stiff.c - dynamic scenes at their extremes: every update strategy
 * still gives the hits of a freshly defined object, and nothing records an
 * error.
 *
 *   - vertices jumping by 1e6 between frames (and back);
 *   - an object collapsing to a point (every vertex equal), flattening to a
 *     plane, and re-expanding;
 *   - an object going from 10 to 200k triangles and back by redefinition,
 *     with a same-topology update of the 200k version in between (large
 *     enough for the parallel update path with threads=2);
 *   - redefinition to zero triangles (no vertex, and two vertices that make
 *     no triangle) and back;
 *   - deleting an object right after updating or redefining it;
 *   - rtUpdateVertices twice (whole and partial) with no frame in between.
 *
 * Each case is a sequence of steps.  A step changes the object (redefinition
 * or rtUpdateVertices), prepares a frame and traces RAY_COUNT rays aimed at
 * the step's geometry; the hits are compared with those of a reference
 * context ("builder=sweep threads=1") in which the object is deleted and
 * defined afresh with the step's vertices (dynamic_anim.h, da_compare_hits).
 * Every case runs under each strategy (as an object hint) in a new context.
 *
 * Reference: docs/dynamic.md.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dynamic_anim.h"
#include "testutil.h"

#define OBJ 900u
#define OTHER 901u
#define RAY_COUNT 2000
#define BIG_TRIS 200000

/* How a step changes the object. */
enum via {
    VIA_DEFINE,       /* rtNewObject .. rtEndObject */
    VIA_UPDATE,       /* rtUpdateVertices of every vertex */
    VIA_UPDATE_TWICE, /* rtUpdateVertices of other positions first, then of these */
    VIA_UPDATE_HALF   /* rtUpdateVertices of the second half only (the first is unchanged) */
};

struct step {
    const char *what;
    enum via via;
    float *v; /* vertices (3 floats each); NULL when nv == 0 */
    int nv;
    double centre[3], radius; /* where the rays look */
    RThit *ref;               /* reference hits, RAY_COUNT */
    RTray *rays;
};

static RTcontext ref_ctx;

/* ---- geometry ---------------------------------------------------------------- */

/* n random triangles (3n vertices) of size about `size` in a cube of half
 * width `half` around centre. */
static float *soup(int n, uint64_t seed, const double centre[3], double half, double size)
{
    float *v = (float *)malloc(9 * sizeof(float) * (size_t)(n > 0 ? n : 1));
    for (int t = 0; t < n; t++) {
        double c[3];
        for (int a = 0; a < 3; a++)
            c[a] = centre[a] + half * (2.0 * da_hash01(seed, (uint64_t)t, (uint64_t)a) - 1.0);
        for (int k = 0; k < 3; k++)
            for (int a = 0; a < 3; a++)
                v[9 * t + 3 * k + a] =
                    (float)(c[a] + size * (da_hash01(seed + 1, (uint64_t)(3 * t + k), (uint64_t)a) -
                                           0.5));
    }
    return v;
}

static float *copy_of(const float *v, int nv)
{
    size_t n = nv > 0 ? 3 * (size_t)nv : 3;
    float *c = (float *)calloc(n, sizeof(float));
    if (nv > 0)
        memcpy(c, v, n * sizeof(float));
    return c;
}

/* Defines name as the triangles of v[0..nv) (rtDrawArrays, RT_TRIANGLES:
 * a trailing incomplete triangle's vertices are stored, unused). */
static void define_tris(RTuint name, const float *v, int nv)
{
    rtNewObject(name);
    if (nv > 0) {
        rtVertexPointer(3, RT_FLOAT, 0, v);
        rtEnableClientState(RT_VERTEX_ARRAY);
        rtDrawArrays(RT_TRIANGLES, 0, nv);
        rtDisableClientState(RT_VERTEX_ARRAY);
        rtVertexPointer(3, RT_FLOAT, 0, NULL);
    }
    rtEndObject();
}

static void make_rays(struct step *s, uint64_t seed)
{
    s->rays = (RTray *)malloc(RAY_COUNT * sizeof(RTray));
    for (int i = 0; i < RAY_COUNT; i++) {
        double h[5], org[3], target[3];
        for (int k = 0; k < 5; k++)
            h[k] = da_hash01(seed, (uint64_t)i, (uint64_t)k);
        double z = 2.0 * h[0] - 1.0, phi = 6.283185307179586 * h[1], r = sqrt(1.0 - z * z);
        double dir[3] = {r * cos(phi), r * sin(phi), z};
        for (int a = 0; a < 3; a++) {
            org[a] = s->centre[a] + 3.0 * s->radius * dir[a];
            target[a] = s->centre[a] + s->radius * (2.0 * h[2 + a] - 1.0);
        }
        for (int a = 0; a < 3; a++) {
            s->rays[i].org[a] = (float)org[a];
            s->rays[i].dir[a] = (float)(target[a] - org[a]);
        }
        s->rays[i].tmin = 0.0f;
        s->rays[i].tmax = INFINITY;
    }
}

/* The reference hits of a step: the object alone, defined afresh. */
static void compute_reference(struct step *s)
{
    RTcontext saved = rtGetCurrentContext();
    RTuint name = OBJ;
    rtMakeCurrent(ref_ctx);
    rtDeleteObjects(1, &name);
    define_tris(OBJ, s->v, s->nv);
    rtBeginFrame();
    rtLoadIdentity();
    rtInstantiateObject(OBJ);
    s->ref = (RThit *)malloc(RAY_COUNT * sizeof(RThit));
    rtTraceRays(RAY_COUNT, s->rays, s->ref);
    CHECK_NO_ERR();
    rtMakeCurrent(saved);
}

/* Object-space bounds of the triangles' vertices (all 0 without one). */
static void expected_bounds(const struct step *s, float b[6])
{
    int used = s->nv / 3 * 3;
    for (int a = 0; a < 3; a++) {
        b[a] = used ? INFINITY : 0.0f;
        b[3 + a] = used ? -INFINITY : 0.0f;
    }
    for (int k = 0; k < used; k++)
        for (int a = 0; a < 3; a++) {
            b[a] = fminf(b[a], s->v[3 * k + a]);
            b[3 + a] = fmaxf(b[3 + a], s->v[3 * k + a]);
        }
}

static void free_steps(struct step *steps, int n)
{
    for (int i = 0; i < n; i++) {
        free(steps[i].v);
        free(steps[i].ref);
        free(steps[i].rays);
    }
}

/* ---- running a case ---------------------------------------------------------------- */

/* Applies step i to OBJ in the current (test) context. */
static void apply(const struct step *steps, int i)
{
    const struct step *s = &steps[i];
    switch (s->via) {
    case VIA_DEFINE:
        define_tris(OBJ, s->v, s->nv);
        break;
    case VIA_UPDATE_TWICE: {
        /* Something else first: the positions scaled by 3 about the origin. */
        float *junk = copy_of(s->v, s->nv);
        for (int k = 0; k < 3 * s->nv; k++)
            junk[k] *= 3.0f;
        rtUpdateVertices(OBJ, RT_VERTEX_ARRAY, 0, s->nv, RT_FLOAT, 0, junk);
        free(junk);
        rtUpdateVertices(OBJ, RT_VERTEX_ARRAY, 0, s->nv, RT_FLOAT, 0, s->v);
        break;
    }
    case VIA_UPDATE_HALF: {
        int half = s->nv / 2;
        rtUpdateVertices(OBJ, RT_VERTEX_ARRAY, half, s->nv - half, RT_FLOAT, 0, s->v + 3 * half);
        break;
    }
    default:
        rtUpdateVertices(OBJ, RT_VERTEX_ARRAY, 0, s->nv, RT_FLOAT, 0, s->v);
        break;
    }
}

/* Runs steps[0..n) under `strategy` in a new threads=2 context; returns the
 * number of mismatching rays. */
static long run_case(const char *name, struct step *steps, int n, RTenum strategy,
                     struct da_compare_stats *st)
{
    long bad = 0;
    RTcontext ctx = tu_make_context("threads=2");
    RThit *hits = (RThit *)malloc(RAY_COUNT * sizeof(RThit));
    tu_capture_errors();
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 1000.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtViewport(0, 0, 16, 16);
    for (int i = 0; i < n; i++) {
        char label[160];
        float b[6], e[6];
        apply(steps, i);
        if (i == 0 || steps[i].via == VIA_DEFINE)
            rtObjectParameteri(OBJ, RT_UPDATE_STRATEGY, (RTint)strategy);
        rtBeginFrame();
        rtLoadIdentity();
        rtInstantiateObject(OBJ);
        /* Alternate between preparing the frame with a query and with a
         * render (the render looks down -z from the origin; the rays come
         * from every side). */
        if (i % 2)
            rtRenderFrame();
        rtTraceRays(RAY_COUNT, steps[i].rays, hits);
        if (i % 2 == 0)
            rtRenderFrame();
        CHECK_NO_ERR();
        snprintf(label, sizeof label, "%s, %s, step %d (%s)", name, da_strategy_name(strategy),
                 i, steps[i].what);
        long k = da_compare_hits(hits, steps[i].ref, RAY_COUNT, label, st);
        CHECK_INT(k, 0);
        bad += k;
        CHECK_INT(tu_object_triangles(OBJ), steps[i].nv / 3);
        {
            RTint nv = -1;
            rtGetObjectiv(OBJ, RT_OBJECT_VERTICES, &nv);
            CHECK_INT(nv, steps[i].nv);
        }
        rtGetObjectfv(OBJ, RT_OBJECT_BOUNDS, b);
        expected_bounds(&steps[i], e);
        CHECK(memcmp(b, e, sizeof b) == 0);
    }
    free(hits);
    tu_destroy_context(ctx);
    return bad;
}

static void run_all(const char *name, struct step *steps, int n, struct da_compare_stats *st)
{
    for (int i = 0; i < n; i++) {
        if (!steps[i].rays)
            make_rays(&steps[i], 1000u + (uint64_t)i);
        compute_reference(&steps[i]);
    }
    for (int s = 0; s < DA_STRATEGY_COUNT; s++) {
        char section[128];
        snprintf(section, sizeof section, "%s: %s", name, da_strategy_name(da_strategies[s]));
        tu_section(section);
        run_case(name, steps, n, da_strategies[s], st);
    }
}

static void set_region(struct step *s, double x, double y, double z, double radius)
{
    s->centre[0] = x;
    s->centre[1] = y;
    s->centre[2] = z;
    s->radius = radius;
}

/* ---- the cases ------------------------------------------------------------------------ */

static void jumps(struct da_compare_stats *st)
{
    static const double at[5][3] = {
        {0, 0, 0}, {1e6, 0, 0}, {1e6, -1e6, 1e6}, {0, 0, 0}, {-1e6, 0, 3e6}};
    struct step steps[6];
    memset(steps, 0, sizeof steps);
    for (int i = 0; i < 5; i++) {
        steps[i].what = i ? "jump by 1e6" : "defined";
        steps[i].via = i ? VIA_UPDATE : VIA_DEFINE;
        steps[i].v = soup(400, 50u + (uint64_t)i, at[i], 8.0, 3.0);
        steps[i].nv = 3 * 400;
        set_region(&steps[i], at[i][0], at[i][1], at[i][2], 10.0);
    }
    /* Half the triangles stay at -1e6, the others come back to 0: one
     * object spanning 3e6 with two clusters. */
    steps[5].what = "half back (partial update)";
    steps[5].via = VIA_UPDATE_HALF;
    {
        float *back = soup(400, 99u, at[0], 8.0, 3.0);
        steps[5].v = copy_of(steps[4].v, 3 * 400);
        memcpy(steps[5].v + 3 * 600, back + 3 * 600, 3 * sizeof(float) * 600);
        free(back);
    }
    steps[5].nv = 3 * 400;
    set_region(&steps[5], 0, 0, 0, 10.0);
    run_all("jumps of 1e6", steps, 6, st);
    free_steps(steps, 6);
}

static void collapse(struct da_compare_stats *st)
{
    const double origin[3] = {0, 0, 0};
    struct step steps[7];
    memset(steps, 0, sizeof steps);
    steps[0].what = "defined";
    steps[0].via = VIA_DEFINE;
    steps[0].v = soup(300, 60u, origin, 1.0, 0.5);
    steps[1].what = "collapsed to a point";
    steps[1].via = VIA_UPDATE;
    steps[1].v = copy_of(steps[0].v, 900);
    for (int k = 0; k < 900; k++) {
        steps[1].v[3 * k] = 0.5f;
        steps[1].v[3 * k + 1] = 0.25f;
        steps[1].v[3 * k + 2] = -0.125f;
    }
    steps[2].what = "re-expanded";
    steps[2].via = VIA_UPDATE;
    steps[2].v = soup(300, 61u, origin, 1.0, 0.5);
    steps[3].what = "flattened to z = 0 (coincident triangles)";
    steps[3].via = VIA_UPDATE;
    steps[3].v = copy_of(steps[2].v, 900);
    for (int k = 0; k < 900; k++)
        steps[3].v[3 * k + 2] = 0.0f;
    steps[4].what = "collapsed to the origin";
    steps[4].via = VIA_UPDATE_TWICE;
    steps[4].v = (float *)calloc(3 * 900, sizeof(float));
    steps[5].what = "re-expanded, larger";
    steps[5].via = VIA_UPDATE;
    steps[5].v = soup(300, 62u, origin, 1.0, 1.5);
    steps[6].what = "redefined as the point";
    steps[6].via = VIA_DEFINE;
    steps[6].v = copy_of(steps[1].v, 900);
    for (int i = 0; i < 7; i++) {
        steps[i].nv = 900;
        set_region(&steps[i], 0, 0, 0, 1.5);
    }
    run_all("collapse and re-expansion", steps, 7, st);
    free_steps(steps, 7);
}

static void grow_and_shrink(struct da_compare_stats *st)
{
    const double origin[3] = {0, 0, 0}, moved[3] = {0.5, -0.25, 0.1};
    struct step steps[5];
    memset(steps, 0, sizeof steps);
    steps[0].what = "10 triangles";
    steps[0].v = soup(10, 70u, origin, 1.0, 0.8);
    steps[0].nv = 30;
    steps[1].what = "200k triangles";
    steps[1].v = soup(BIG_TRIS, 71u, origin, 1.0, 0.02);
    steps[1].nv = 3 * BIG_TRIS;
    /* A coherent deformation: refitting a 200k-triangle soup whose
     * triangles all jump somewhere else would make a tree that every ray
     * traverses whole (correct, but seconds per frame). */
    steps[2].what = "200k triangles moved and bent (same topology)";
    steps[2].v = copy_of(steps[1].v, 3 * BIG_TRIS);
    for (int k = 0; k < 3 * BIG_TRIS; k++) {
        float *p = &steps[2].v[3 * k];
        p[2] += (float)(0.2 * sin(3.0 * p[0]));
        for (int a = 0; a < 3; a++)
            p[a] += (float)moved[a];
    }
    steps[2].nv = 3 * BIG_TRIS;
    steps[2].via = VIA_UPDATE;
    steps[3].what = "200k triangles redefined moved back";
    steps[3].v = copy_of(steps[1].v, 3 * BIG_TRIS);
    steps[3].nv = 3 * BIG_TRIS;
    steps[4].what = "10 triangles again";
    steps[4].v = copy_of(steps[0].v, 30);
    steps[4].nv = 30;
    for (int i = 0; i < 5; i++)
        set_region(&steps[i], 0.25, -0.1, 0.05, 1.2);
    run_all("10 -> 200k -> 10 triangles", steps, 5, st);
    free_steps(steps, 5);
}

static void empty_and_back(struct da_compare_stats *st)
{
    const double origin[3] = {0, 0, 0};
    struct step steps[8];
    memset(steps, 0, sizeof steps);
    steps[0].what = "100 triangles";
    steps[0].v = soup(100, 80u, origin, 1.0, 0.6);
    steps[0].nv = 300;
    steps[1].what = "redefined empty";
    steps[1].nv = 0;
    steps[2].what = "back";
    steps[2].v = copy_of(steps[0].v, 300);
    steps[2].nv = 300;
    steps[3].what = "updated";
    steps[3].via = VIA_UPDATE;
    steps[3].v = soup(100, 81u, origin, 1.0, 0.6);
    steps[3].nv = 300;
    steps[4].what = "two vertices, no triangle";
    steps[4].v = copy_of(steps[3].v, 2);
    steps[4].nv = 2;
    steps[5].what = "its two vertices updated";
    steps[5].via = VIA_UPDATE;
    steps[5].v = copy_of(steps[0].v, 2);
    steps[5].nv = 2;
    steps[6].what = "empty again";
    steps[6].nv = 0;
    steps[7].what = "back again";
    steps[7].v = copy_of(steps[3].v, 300);
    steps[7].nv = 300;
    for (int i = 0; i < 8; i++)
        set_region(&steps[i], 0, 0, 0, 1.2);
    run_all("zero triangles and back", steps, 8, st);
    free_steps(steps, 8);
}

/* Deleting OBJ right after an update or a redefinition: the frame shows
 * only OTHER, and a new object under the old name starts afresh. */
static void delete_after_update(struct da_compare_stats *st)
{
    const double origin[3] = {0, 0, 0}, aside[3] = {3, 0, 0};
    float *a0 = soup(200, 90u, origin, 1.0, 0.6);
    float *a1 = soup(200, 91u, origin, 1.0, 0.6);
    float *other = soup(200, 92u, aside, 1.0, 0.6);
    float *fresh = soup(100, 93u, origin, 1.0, 0.6);
    struct step probe;
    RThit *hits = (RThit *)malloc(RAY_COUNT * sizeof(RThit));
    RThit *ref_other = (RThit *)malloc(RAY_COUNT * sizeof(RThit));
    RThit *ref_fresh = (RThit *)malloc(RAY_COUNT * sizeof(RThit));
    memset(&probe, 0, sizeof probe);
    set_region(&probe, 1.5, 0, 0, 3.0);
    make_rays(&probe, 4242u);

    /* References: OTHER alone; OTHER and a fresh OBJ. */
    {
        RTcontext saved = rtGetCurrentContext();
        RTuint names[2] = {OBJ, OTHER};
        rtMakeCurrent(ref_ctx);
        rtDeleteObjects(2, names);
        define_tris(OTHER, other, 600);
        rtBeginFrame();
        rtLoadIdentity();
        rtInstantiateObject(OTHER);
        rtTraceRays(RAY_COUNT, probe.rays, ref_other);
        define_tris(OBJ, fresh, 300);
        rtBeginFrame();
        rtInstantiateObject(OTHER);
        rtInstantiateObject(OBJ);
        rtTraceRays(RAY_COUNT, probe.rays, ref_fresh);
        rtDeleteObjects(2, names);
        CHECK_NO_ERR();
        rtMakeCurrent(saved);
    }

    for (int s = 0; s < DA_STRATEGY_COUNT; s++) {
        char section[128], label[128];
        snprintf(section, sizeof section, "delete right after an update: %s",
                 da_strategy_name(da_strategies[s]));
        tu_section(section);
        snprintf(label, sizeof label, "delete, %s", da_strategy_name(da_strategies[s]));
        RTcontext ctx = tu_make_context("threads=2");
        RTuint name = OBJ;
        tu_capture_errors();
        rtRenderParameteri(RT_UPDATE_STRATEGY, (RTint)da_strategies[s]);
        for (int how = 0; how < 4; how++) {
            define_tris(OBJ, a0, 600);
            define_tris(OTHER, other, 600);
            rtBeginFrame();
            rtLoadIdentity();
            rtInstantiateObject(OBJ);
            rtInstantiateObject(OTHER);
            rtTraceRays(RAY_COUNT, probe.rays, hits); /* builds both */
            rtRenderFrame();
            rtInstantiateObject(OBJ);
            rtInstantiateObject(OTHER);
            if (how == 0) {
                rtUpdateVertices(OBJ, RT_VERTEX_ARRAY, 0, 600, RT_FLOAT, 0, a1);
            } else if (how == 1) {
                define_tris(OBJ, a1, 600); /* same topology: kept, stale */
            } else if (how == 2) {
                rtUpdateVertices(OBJ, RT_VERTEX_ARRAY, 0, 600, RT_FLOAT, 0, a1);
                rtFinish(); /* updated, then deleted */
            } else {
                rtUpdateVertices(OBJ, RT_VERTEX_ARRAY, 0, 300, RT_FLOAT, 0, a1);
                rtUpdateVertices(OBJ, RT_VERTEX_ARRAY, 300, 300, RT_FLOAT, 0, a0);
            }
            rtDeleteObjects(1, &name);
            CHECK_NO_ERR();
            CHECK_INT(rtIsObject(OBJ), RT_FALSE);
            if (how % 2)
                rtRenderFrame();
            rtTraceRays(RAY_COUNT, probe.rays, hits);
            CHECK_INT(da_compare_hits(hits, ref_other, RAY_COUNT, label, st), 0);
            {
                RTint instances = -1;
                rtGetIntegerv(RT_INSTANCE_COUNT, &instances);
                CHECK_INT(instances, 1);
            }
            /* A new object under the same name, with other geometry. */
            define_tris(OBJ, fresh, 300);
            rtBeginFrame();
            rtInstantiateObject(OTHER);
            rtInstantiateObject(OBJ);
            rtRenderFrame();
            rtTraceRays(RAY_COUNT, probe.rays, hits);
            CHECK_INT(da_compare_hits(hits, ref_fresh, RAY_COUNT, label, st), 0);
            CHECK_NO_ERR();
            rtDeleteObjects(1, &name);
        }
        tu_destroy_context(ctx);
    }
    free(a0);
    free(a1);
    free(other);
    free(fresh);
    free(hits);
    free(ref_other);
    free(ref_fresh);
    free(probe.rays);
}

int main(void)
{
    struct da_compare_stats st;
    memset(&st, 0, sizeof st);
    ref_ctx = rtCreateContext("builder=sweep threads=1");
    if (!ref_ctx) {
        fprintf(stderr, "fatal: no reference context\n");
        return 1;
    }
    jumps(&st);
    collapse(&st);
    grow_and_shrink(&st);
    empty_and_back(&st);
    delete_after_update(&st);
    rtDestroyContext(ref_ctx);
    printf("compared %ld rays (%ld hits): %ld ties at equal distance, %ld same-primitive hits "
           "with t not bit-identical, %ld mismatches\n",
           st.rays, st.hits, st.ties, st.same_prim_t_not_bitwise, st.mismatches);
    return test_summary("dynamic_stiff");
}
