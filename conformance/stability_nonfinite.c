/* SPDX-License-Identifier: Apache-2.0 */
/*
 * stability_nonfinite.c - NaN and infinity are rejected wherever they can be
 * given, and a rejected call leaves the scene exactly as it was.
 *
 * The same script of valid calls (objects with normals, colours, texture
 * coordinates and materials, recorded with rtBegin/rtVertex and with vertex
 * arrays; instances; lights; a light model; a clear colour; a camera) runs
 * in two contexts.  In the second, before and between the valid calls, the
 * script also makes every call it can with a NaN, +inf or -inf in each
 * argument position - vertices (all rtVertex forms), normals, texture
 * coordinates, colours, every matrix call in both matrix modes (and
 * products that overflow), materials, lights (and a position that
 * overflows under the modelview), the light model, the clear colour,
 * vertex arrays (one bad element in a batch of 30000, in float, double and
 * homogeneous w = 0 form, and a bad normal, colour or texture coordinate
 * element), rays (one bad ray among 1000: origin, direction, tmin, tmax,
 * and a zero direction) - and checks that each records RT_INVALID_VALUE.
 * Matrix calls must leave the matrix unchanged (read back); ray calls must
 * not write their output array.
 *
 * At the end both contexts must agree bit for bit: triangle counts of every
 * object, rtTraceRays results for 10k rays, and a Whitted image (RGBA
 * float) in which all of the poisoned state (material, lights, clear
 * colour, matrices) shows.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brute_force.h"
#include "testutil.h"

#define WIDTH 96
#define HEIGHT 72
#define RAY_COUNT 10000
#define ARRAY_VERTICES 30000

enum { OBJ_IMMEDIATE = 1, OBJ_ARRAYS, OBJ_ELEMENTS };

static int poison; /* the script runs its bad calls too */
static float bad_f[3];
static double bad_d[3];

/* Runs `call` only in the poisoned context and expects RT_INVALID_VALUE. */
#define BAD(call)                                                                                  \
    do {                                                                                           \
        if (poison) {                                                                              \
            call;                                                                                  \
            if (!CHECK_ERR(RT_INVALID_VALUE))                                                      \
                fprintf(stderr, "  the call was: %s\n", #call);                                    \
        }                                                                                          \
    } while (0)

/* A float vector of n values with bad value x at position i. */
static const float *with_bad_f(const float *base, int n, int i, float x)
{
    static float v[16];
    memcpy(v, base, (size_t)n * sizeof(float));
    v[i] = x;
    return v;
}

static const double *with_bad_d(const double *base, int n, int i, double x)
{
    static double v[16];
    memcpy(v, base, (size_t)n * sizeof(double));
    v[i] = x;
    return v;
}

/* ---- matrices ----------------------------------------------------------------- */

static void read_matrix(RTenum mode, float m[16])
{
    rtGetFloatv(mode == RT_MODELVIEW ? RT_MODELVIEW_MATRIX : RT_PROJECTION_MATRIX, m);
}

static void poison_matrices(RTenum mode)
{
    if (!poison)
        return;
    rtMatrixMode(mode);
    float before[16], after[16];
    read_matrix(mode, before);
    static const float ident_f[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    static const double ident_d[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    for (int b = 0; b < 3; b++) {
        float x = bad_f[b];
        double y = bad_d[b];
        for (int i = 0; i < 16; i++) {
            BAD(rtLoadMatrixf(with_bad_f(ident_f, 16, i, x)));
            BAD(rtLoadMatrixd(with_bad_d(ident_d, 16, i, y)));
            BAD(rtMultMatrixf(with_bad_f(ident_f, 16, i, x)));
            BAD(rtMultMatrixd(with_bad_d(ident_d, 16, i, y)));
        }
        BAD(rtTranslatef(x, 0, 0));
        BAD(rtTranslatef(0, x, 0));
        BAD(rtTranslatef(0, 0, x));
        BAD(rtTranslated(y, 0, 0));
        BAD(rtTranslated(0, y, 0));
        BAD(rtTranslated(0, 0, y));
        BAD(rtScalef(x, 1, 1));
        BAD(rtScalef(1, x, 1));
        BAD(rtScalef(1, 1, x));
        BAD(rtScaled(y, 1, 1));
        BAD(rtScaled(1, y, 1));
        BAD(rtScaled(1, 1, y));
        BAD(rtRotatef(x, 0, 0, 1));
        BAD(rtRotatef(30, x, 0, 1));
        BAD(rtRotatef(30, 0, x, 1));
        BAD(rtRotatef(30, 0, 0, x));
        BAD(rtRotated(y, 0, 0, 1));
        BAD(rtRotated(30, y, 0, 1));
        BAD(rtRotated(30, 0, y, 1));
        BAD(rtRotated(30, 0, 0, y));
        const double f[6] = {-1, 1, -1, 1, 1, 10};
        for (int i = 0; i < 6; i++) {
            const double *g = with_bad_d(f, 6, i, y);
            BAD(rtFrustum(g[0], g[1], g[2], g[3], g[4], g[5]));
            g = with_bad_d(f, 6, i, y);
            BAD(rtOrtho(g[0], g[1], g[2], g[3], g[4], g[5]));
        }
    }
    /* Finite arguments whose product overflows. */
    rtPushMatrix();
    rtScaled(1e200, 1.0, 1.0);
    CHECK_NO_ERR();
    float scaled[16];
    read_matrix(mode, scaled);
    BAD(rtScaled(1e200, 1.0, 1.0));
    BAD(rtTranslated(1e300, 0.0, 0.0)); /* 1e200 * 1e300 */
    read_matrix(mode, after);
    CHECK(memcmp(scaled, after, sizeof(after)) == 0);
    rtPopMatrix();
    read_matrix(mode, after);
    CHECK(memcmp(before, after, sizeof(after)) == 0);
    rtMatrixMode(RT_MODELVIEW);
}

/* ---- attributes, materials, lights ------------------------------------------- */

static void poison_attributes(void)
{
    const float one[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    for (int b = 0; b < 3 && poison; b++) {
        float x = bad_f[b];
        for (int i = 0; i < 3; i++) {
            const float *n = with_bad_f(one, 3, i, x);
            BAD(rtNormal3f(n[0], n[1], n[2]));
            BAD(rtNormal3fv(with_bad_f(one, 3, i, x)));
            n = with_bad_f(one, 3, i, x);
            BAD(rtColor3f(n[0], n[1], n[2]));
            BAD(rtColor3fv(with_bad_f(one, 3, i, x)));
        }
        for (int i = 0; i < 4; i++) {
            const float *c = with_bad_f(one, 4, i, x);
            BAD(rtColor4f(c[0], c[1], c[2], c[3]));
            BAD(rtColor4fv(with_bad_f(one, 4, i, x)));
        }
        for (int i = 0; i < 2; i++) {
            const float *t = with_bad_f(one, 2, i, x);
            BAD(rtTexCoord2f(t[0], t[1]));
            BAD(rtTexCoord2fv(with_bad_f(one, 2, i, x)));
        }
    }
}

static void poison_materials(void)
{
    static const RTenum vec[5] = {RT_AMBIENT, RT_DIFFUSE, RT_SPECULAR, RT_EMISSION,
                                  RT_AMBIENT_AND_DIFFUSE};
    static const RTenum scalar[4] = {RT_SHININESS, RT_REFLECTIVITY, RT_TRANSPARENCY,
                                     RT_INDEX_OF_REFRACTION};
    const float base[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    for (int b = 0; b < 3 && poison; b++) {
        for (int p = 0; p < 5; p++)
            for (int i = 0; i < 4; i++)
                BAD(rtMaterialfv(RT_FRONT_AND_BACK, vec[p], with_bad_f(base, 4, i, bad_f[b])));
        for (int p = 0; p < 4; p++) {
            BAD(rtMaterialf(RT_FRONT, scalar[p], bad_f[b]));
            BAD(rtMaterialfv(RT_BACK, scalar[p], with_bad_f(base, 1, 0, bad_f[b])));
        }
    }
}

static void poison_lights(void)
{
    static const RTenum vec[4] = {RT_AMBIENT, RT_DIFFUSE, RT_SPECULAR, RT_POSITION};
    static const RTenum scalar[3] = {RT_CONSTANT_ATTENUATION, RT_LINEAR_ATTENUATION,
                                     RT_QUADRATIC_ATTENUATION};
    const float base[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    for (int b = 0; b < 3 && poison; b++)
        for (int light = 0; light < 2; light++) {
            for (int p = 0; p < 4; p++)
                for (int i = 0; i < 4; i++)
                    BAD(rtLightfv(RT_LIGHT0 + light, vec[p], with_bad_f(base, 4, i, bad_f[b])));
            for (int p = 0; p < 3; p++) {
                BAD(rtLightf(RT_LIGHT0 + light, scalar[p], bad_f[b]));
                BAD(rtLightfv(RT_LIGHT0 + light, scalar[p], with_bad_f(base, 1, 0, bad_f[b])));
            }
            for (int i = 0; i < 4; i++)
                BAD(rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, with_bad_f(base, 4, i, bad_f[b])));
            for (int i = 0; i < 4; i++) {
                const float *c = with_bad_f(base, 4, i, bad_f[b]);
                BAD(rtClearColor(c[0], c[1], c[2], c[3]));
            }
        }
    if (poison) {
        /* A finite position that overflows under the modelview. */
        const float far_away[4] = {1e10f, 1e10f, 1e10f, 1.0f};
        rtPushMatrix();
        rtScaled(1e30, 1e30, 1e30);
        BAD(rtLightfv(RT_LIGHT0 + 1, RT_POSITION, far_away));
        rtPopMatrix();
    }
}

/* ---- geometry ---------------------------------------------------------------- */

/* Bad rtVertex calls of every form (inside rtBegin). */
static void poison_vertices(void)
{
    const float base[3] = {0.25f, 0.5f, 0.75f};
    const double based[3] = {0.25, 0.5, 0.75};
    for (int b = 0; b < 3 && poison; b++) {
        float x = bad_f[b];
        double y = bad_d[b];
        for (int i = 0; i < 3; i++) {
            const float *v = with_bad_f(base, 3, i, x);
            BAD(rtVertex3f(v[0], v[1], v[2]));
            BAD(rtVertex3fv(with_bad_f(base, 3, i, x)));
            const double *w = with_bad_d(based, 3, i, y);
            BAD(rtVertex3d(w[0], w[1], w[2]));
            BAD(rtVertex3dv(with_bad_d(based, 3, i, y)));
        }
        for (int i = 0; i < 2; i++) {
            const float *v = with_bad_f(base, 2, i, x);
            BAD(rtVertex2f(v[0], v[1]));
            BAD(rtVertex2fv(with_bad_f(base, 2, i, x)));
            const double *w = with_bad_d(based, 2, i, y);
            BAD(rtVertex2d(w[0], w[1]));
            BAD(rtVertex2dv(with_bad_d(based, 2, i, y)));
        }
    }
    /* Finite, but not representable as a float vertex. */
    BAD(rtVertex3d(1e39, 0.0, 0.0));
    BAD(rtVertex2d(0.0, -1e300));
}

static void immediate_object(void)
{
    struct bf_rng r;
    bf_seed(&r, 3u);
    const float red[4] = {0.9f, 0.2f, 0.1f, 1.0f}, spec[4] = {0.7f, 0.7f, 0.7f, 1.0f};
    rtNewObject(OBJ_IMMEDIATE);
    poison_materials();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, red);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, spec);
    rtMaterialf(RT_FRONT_AND_BACK, RT_SHININESS, 20.0f);
    poison_matrices(RT_MODELVIEW);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < 300; i++) {
        poison_attributes();
        if (i % 97 == 0) {
            poison_vertices();
            poison_materials();
        }
        rtNormal3f((float)bf_range(&r, -1, 1), (float)bf_range(&r, -1, 1), 1.0f);
        rtColor3f((float)bf_uniform(&r), (float)bf_uniform(&r), (float)bf_uniform(&r));
        rtTexCoord2f((float)bf_uniform(&r), (float)bf_uniform(&r));
        rtVertex3f((float)bf_range(&r, -3, 3), (float)bf_range(&r, -2, 2),
                   (float)bf_range(&r, -1, 1));
    }
    rtEnd();
    rtEndObject();
}

/* Vertex array data: ARRAY_VERTICES float and double vertices with normals,
 * colours and texture coordinates. */
struct arrays {
    float *vf;  /* 3 per vertex */
    double *vd; /* 4 per vertex (homogeneous, w = 1) */
    float *nf;
    float *cf; /* 4 per vertex */
    float *tf; /* 2 per vertex */
    unsigned *idx;
};

static void make_arrays(struct arrays *a)
{
    struct bf_rng r;
    bf_seed(&r, 4u);
    a->vf = malloc(ARRAY_VERTICES * 3 * sizeof(float));
    a->vd = malloc(ARRAY_VERTICES * 4 * sizeof(double));
    a->nf = malloc(ARRAY_VERTICES * 3 * sizeof(float));
    a->cf = malloc(ARRAY_VERTICES * 4 * sizeof(float));
    a->tf = malloc(ARRAY_VERTICES * 2 * sizeof(float));
    a->idx = malloc(ARRAY_VERTICES * sizeof(unsigned));
    for (int i = 0; i < ARRAY_VERTICES; i++) {
        double c[3] = {bf_range(&r, -6, 6), bf_range(&r, -4, 4), bf_range(&r, -8, -2)};
        for (int k = 0; k < 3; k++) {
            a->vf[3 * i + k] = (float)(c[k] + bf_range(&r, -0.2, 0.2));
            a->vd[4 * i + k] = c[k] + bf_range(&r, -0.2, 0.2);
            a->nf[3 * i + k] = (float)bf_range(&r, -1, 1);
        }
        a->vd[4 * i + 3] = 1.0;
        for (int k = 0; k < 4; k++)
            a->cf[4 * i + k] = (float)bf_uniform(&r);
        a->tf[2 * i] = (float)bf_uniform(&r);
        a->tf[2 * i + 1] = (float)bf_uniform(&r);
        a->idx[i] = (unsigned)(ARRAY_VERTICES - 1 - i);
    }
}

static void free_arrays(struct arrays *a)
{
    free(a->vf);
    free(a->vd);
    free(a->nf);
    free(a->cf);
    free(a->tf);
    free(a->idx);
}

static void array_objects(struct arrays *a)
{
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtEnableClientState(RT_NORMAL_ARRAY);
    rtEnableClientState(RT_COLOR_ARRAY);
    rtEnableClientState(RT_TEXTURE_COORD_ARRAY);
    rtNormalPointer(RT_FLOAT, 0, a->nf);
    rtColorPointer(4, RT_FLOAT, 0, a->cf);
    rtTexCoordPointer(2, RT_FLOAT, 0, a->tf);

    rtNewObject(OBJ_ARRAYS);
    rtEnable(RT_COLOR_MATERIAL);
    rtVertexPointer(3, RT_FLOAT, 0, a->vf);
    int mid = 3 * (ARRAY_VERTICES / 2) + 1;
    for (int b = 0; b < 3 && poison; b++) {
        float saved = a->vf[mid];
        a->vf[mid] = bad_f[b];
        BAD(rtDrawArrays(RT_TRIANGLES, 0, ARRAY_VERTICES));
        BAD(rtDrawElements(RT_TRIANGLES, ARRAY_VERTICES, RT_UNSIGNED_INT, a->idx));
        a->vf[mid] = saved;
        /* The other attribute arrays, one bad component each. */
        float *attr[3] = {a->nf, a->cf, a->tf};
        const int attr_at[3] = {3 * 1234 + 2, 4 * 20000 + 1, 2 * 29999};
        for (int k = 0; k < 3; k++) {
            saved = attr[k][attr_at[k]];
            attr[k][attr_at[k]] = bad_f[b];
            BAD(rtDrawArrays(RT_TRIANGLES, 0, ARRAY_VERTICES));
            attr[k][attr_at[k]] = saved;
        }
    }
    rtDrawArrays(RT_TRIANGLES, 0, ARRAY_VERTICES);
    rtDisable(RT_COLOR_MATERIAL);
    rtEndObject();

    /* Homogeneous double vertices through rtDrawElements. */
    rtNewObject(OBJ_ELEMENTS);
    rtDisableClientState(RT_COLOR_ARRAY);
    rtVertexPointer(4, RT_DOUBLE, 0, a->vd);
    int mid_d = 4 * 777;
    for (int b = 0; b < 3 && poison; b++) {
        double saved = a->vd[mid_d];
        a->vd[mid_d] = bad_d[b];
        BAD(rtDrawElements(RT_TRIANGLES, ARRAY_VERTICES, RT_UNSIGNED_INT, a->idx));
        a->vd[mid_d] = saved;
    }
    if (poison) {
        a->vd[4 * 4321 + 3] = 0.0; /* w = 0: a point at infinity */
        BAD(rtDrawElements(RT_TRIANGLES, ARRAY_VERTICES, RT_UNSIGNED_INT, a->idx));
        a->vd[4 * 4321 + 3] = 1.0;
        a->vd[4 * 4322] = 1e300; /* finite, overflows the float vertex */
        BAD(rtDrawElements(RT_TRIANGLES, ARRAY_VERTICES, RT_UNSIGNED_INT, a->idx));
        a->vd[4 * 4322] = 0.0;
    }
    rtDrawElements(RT_TRIANGLES, ARRAY_VERTICES, RT_UNSIGNED_INT, a->idx);
    rtEndObject();
    rtDisableClientState(RT_VERTEX_ARRAY);
    rtDisableClientState(RT_NORMAL_ARRAY);
    rtDisableClientState(RT_TEXTURE_COORD_ARRAY);
}

/* ---- the script ----------------------------------------------------------------- */

static void script(struct arrays *a)
{
    poison_lights();
    poison_materials();
    poison_attributes();
    poison_matrices(RT_MODELVIEW);
    poison_matrices(RT_PROJECTION);
    immediate_object();
    array_objects(a);
    CHECK_NO_ERR();

    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 50.0);
    poison_matrices(RT_PROJECTION);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    poison_lights();
    const float sun[4] = {0.3f, 1.0f, 0.8f, 0.0f}, lamp[4] = {2.0f, 3.0f, 1.0f, 1.0f};
    const float warm[4] = {0.8f, 0.6f, 0.4f, 1.0f}, amb[4] = {0.1f, 0.1f, 0.15f, 1.0f};
    rtLightfv(RT_LIGHT0, RT_POSITION, sun);
    rtLightfv(RT_LIGHT0 + 1, RT_POSITION, lamp);
    rtLightfv(RT_LIGHT0 + 1, RT_DIFFUSE, warm);
    rtLightfv(RT_LIGHT0 + 1, RT_SPECULAR, warm);
    rtLightf(RT_LIGHT0 + 1, RT_LINEAR_ATTENUATION, 0.1f);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, amb);
    rtEnable(RT_LIGHT0);
    rtEnable(RT_LIGHT0 + 1);
    rtClearColor(0.2f, 0.3f, 0.4f, 0.5f);
    poison_lights();

    rtBeginFrame();
    poison_matrices(RT_MODELVIEW);
    rtPushMatrix();
    rtTranslatef(0.0f, 0.0f, -8.0f);
    rtRotatef(20.0f, 1.0f, 1.0f, 0.0f);
    rtInstantiateObject(OBJ_IMMEDIATE);
    rtPopMatrix();
    rtInstantiateObject(OBJ_ARRAYS);
    rtPushMatrix();
    rtTranslatef(1.0f, -1.0f, -6.0f);
    rtScalef(0.5f, 0.5f, 0.5f);
    rtInstantiateObject(OBJ_ELEMENTS);
    rtPopMatrix();
    rtShadingMode(RT_WHITTED);
    CHECK_NO_ERR();
}

static void make_rays(RTray *rays)
{
    struct bf_rng r;
    bf_seed(&r, 8u);
    for (int i = 0; i < RAY_COUNT; i++) {
        double d[3];
        bf_unit_vector(&r, d);
        d[2] = -fabs(d[2]) - 0.5;
        for (int k = 0; k < 3; k++) {
            rays[i].org[k] = (float)bf_range(&r, -0.5, 0.5);
            rays[i].dir[k] = (float)d[k];
        }
        rays[i].tmin = 0.0f;
        rays[i].tmax = INFINITY;
    }
}

/* Bad rays in a valid batch: nothing may be written. */
static void poison_rays(const RTray *rays)
{
    static RTray batch[1000];
    static RThit hits[1000];
    static RTboolean occluded[1000];
    for (int kind = 0; kind < 12; kind++) {
        memcpy(batch, rays, sizeof(batch));
        RTray *r = &batch[500];
        if (kind < 3)
            r->org[kind] = bad_f[(kind + 1) % 3];
        else if (kind < 6)
            r->dir[kind - 3] = bad_f[(kind + 2) % 3];
        else if (kind == 6)
            r->tmin = bad_f[0];
        else if (kind == 7)
            r->tmin = bad_f[2]; /* -inf: tmin < 0 */
        else if (kind == 8)
            r->tmin = -1.0f;
        else if (kind == 9)
            r->tmax = bad_f[0];
        else
            r->dir[0] = r->dir[1] = r->dir[2] = kind == 10 ? 0.0f : -0.0f;
        memset(hits, 0x5A, sizeof(hits));
        memset(occluded, 0x5A, sizeof(occluded));
        BAD(rtTraceRays(1000, batch, hits));
        BAD(rtOccludedRays(1000, batch, occluded));
        int untouched = 1;
        const unsigned char *h = (const unsigned char *)hits;
        for (size_t i = 0; i < sizeof(hits); i++)
            untouched &= h[i] == 0x5A;
        for (size_t i = 0; i < sizeof(occluded); i++)
            untouched &= occluded[i] == 0x5A;
        if (!CHECK(untouched))
            fprintf(stderr, "  bad ray kind %d: the output was written\n", kind);
    }
    /* tmin = +inf (with tmax = +inf or less) is no error, just a miss. */
    if (poison) {
        memcpy(batch, rays, sizeof(batch));
        batch[500].tmin = bad_f[1];
        rtTraceRays(1000, batch, hits);
        CHECK_NO_ERR();
        CHECK(hits[500].t == INFINITY && hits[500].primitive == RT_INVALID_ID);
        /* tmin = -0.0 is not below 0: no error, the ray of tmin 0. */
        batch[500].tmin = -0.0f;
        rtTraceRays(1000, batch, hits);
        CHECK_NO_ERR();
        batch[500].tmin = 0.0f;
        RThit ref;
        rtTraceRays(1, &batch[500], &ref);
        CHECK_NO_ERR();
        CHECK(memcmp(&ref, &hits[500], sizeof(ref)) == 0);
    }
}

struct outcome {
    RTint triangles[3];
    RThit *hits;
    float *image;
};

static void run(struct arrays *a, const RTray *rays, struct outcome *out)
{
    RTcontext ctx = tu_make_context(NULL);
    script(a);
    for (int i = 0; i < 3; i++)
        rtGetObjectiv(OBJ_IMMEDIATE + (RTuint)i, RT_OBJECT_TRIANGLES, &out->triangles[i]);
    out->hits = malloc(RAY_COUNT * sizeof(RThit));
    rtTraceRays(RAY_COUNT, rays, out->hits);
    if (poison)
        poison_rays(rays);
    out->image = malloc(sizeof(float) * 4 * WIDTH * HEIGHT);
    tu_render_float(WIDTH, HEIGHT, out->image);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
}

int main(void)
{
    bad_f[0] = tu_nan();
    bad_f[1] = tu_inf();
    bad_f[2] = -tu_inf();
    bad_d[0] = tu_nan_d();
    bad_d[1] = tu_inf_d();
    bad_d[2] = -tu_inf_d();
    struct arrays a;
    make_arrays(&a);
    RTray *rays = malloc(RAY_COUNT * sizeof(RTray));
    make_rays(rays);

    tu_section("clean context");
    struct outcome clean, poisoned;
    poison = 0;
    run(&a, rays, &clean);
    tu_section("poisoned context");
    poison = 1;
    run(&a, rays, &poisoned);

    tu_section("both contexts agree");
    for (int i = 0; i < 3; i++)
        CHECK_INT(poisoned.triangles[i], clean.triangles[i]);
    CHECK_INT(clean.triangles[0], 100);
    CHECK_INT(clean.triangles[1], ARRAY_VERTICES / 3);
    CHECK_INT(clean.triangles[2], ARRAY_VERTICES / 3);
    int hits = 0;
    for (int i = 0; i < RAY_COUNT; i++)
        hits += clean.hits[i].t < INFINITY;
    printf("   %d of %d rays hit\n", hits, RAY_COUNT);
    CHECK(hits > RAY_COUNT / 4);
    CHECK(memcmp(clean.hits, poisoned.hits, RAY_COUNT * sizeof(RThit)) == 0);
    CHECK(memcmp(clean.image, poisoned.image, sizeof(float) * 4 * WIDTH * HEIGHT) == 0);
    int finite = 1;
    for (int i = 0; i < 4 * WIDTH * HEIGHT; i++)
        finite &= isfinite(clean.image[i]) != 0;
    CHECK(finite);

    free(clean.hits);
    free(clean.image);
    free(poisoned.hits);
    free(poisoned.image);
    free(rays);
    free_arrays(&a);
    return test_summary("stability_nonfinite");
}
