/* SPDX-License-Identifier: Apache-2.0 */
/*
 * secondary_rays.c - conformance: what GL's per-primitive state removes
 * from the picture is not there for Whitted shading's shadow rays and for
 * the ray queries either: a clipped-away occluder casts no shadow, a
 * cutout (alpha test) casts the shadow of its cutout shape, a blended
 * surface that shows what lies behind it lets the light through; queries
 * skip what clip planes remove and see alpha-tested surfaces whole.  A
 * coincident unclipped copy still shadows (the filter keeps the other
 * hits at the rejected distance).  Images are bit-identical across ISAs
 * and thread counts.
 *
 * Scene: rtOrtho(0, N, 0, N, -10, 10), the eye looking down -z; a white
 * floor at z = 0; an occluder at z = 4 over x in [8, 12]; a directional
 * light along (1, 0, 1), so the occluder shadows the floor's pixels
 * 4 .. 7 (x + 4 in [8, 12]), which the camera sees; lit floor shows
 * cos 45 deg.
 *
 * Reference: docs/clip_planes.md, docs/alpha_test.md, docs/blending.md,
 * docs/queries.md.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define N 16
#define FLOOR 900u
#define OCC 901u
#define CUTOUT 902u

static float img[4 * N * N];

static const float *px(int x, int y)
{
    return &img[4 * (y * N + x)];
}

static void quad(float x0, float x1, float z)
{
    rtBegin(RT_QUADS);
    rtNormal3f(0.0f, 0.0f, 1.0f);
    rtVertex3f(x0, 0.0f, z);
    rtVertex3f(x1, 0.0f, z);
    rtVertex3f(x1, (float)N, z);
    rtVertex3f(x0, (float)N, z);
    rtEnd();
}

/* The occluder with diffuse alpha a. */
static void occluder(RTuint name, float a)
{
    const float diffuse[4] = {1.0f, 1.0f, 1.0f, a};
    rtNewObject(name);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, diffuse);
    quad(8.0f, 12.0f, 4.0f);
    rtEndObject();
}

static void setup(void)
{
    static const float black[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1};
    static const float light_dir[4] = {1, 0, 1, 0};
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtOrtho(0.0, N, 0.0, N, -10.0, 10.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtShadingMode(RT_WHITTED);
    rtClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
    rtLightfv(RT_LIGHT0, RT_POSITION, light_dir);
    rtEnable(RT_LIGHT0);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, white);
    rtNewObject(FLOOR);
    quad(-8.0f, 24.0f, 0.0f);
    rtEndObject();
    occluder(OCC, 1.0f);
    /* The cutout: its left half of alpha 0, its right half of alpha 1
     * (the eye-light and Whitted modes take the diffuse material's
     * alpha, docs/alpha_test.md). */
    const float clear[4] = {1, 1, 1, 0};
    rtNewObject(CUTOUT);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, clear);
    quad(8.0f, 10.0f, 4.0f);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, white);
    quad(10.0f, 12.0f, 4.0f);
    rtEndObject();
    CHECK_NO_ERR();
}

static int lit(int x)
{
    return fabsf(px(x, 8)[0] - 0.70710677f) < 1e-3f;
}

static int dark(int x)
{
    return px(x, 8)[0] < 1e-6f;
}

/* The floor pixels 4 .. 7: 1 when all are lit, 0 when all dark, -1 mixed. */
static int shadow_band(void)
{
    int l = 0, d = 0;
    for (int x = 4; x < 8; x++) {
        l += lit(x);
        d += dark(x);
    }
    return l == 4 ? 1 : d == 4 ? 0 : -1;
}

static const double keep_below_2[4] = {0.0, 0.0, -1.0, 2.0};

static void clip_planes(void)
{
    tu_section("a clipped-away occluder casts no shadow");
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtInstantiateObject(OCC);
    tu_render_float(N, N, img);
    CHECK(lit(2));
    CHECK_INT(shadow_band(), 0);
    rtClipPlane(RT_CLIP_PLANE0, keep_below_2);
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtEnable(RT_CLIP_PLANE0);
    rtInstantiateObject(OCC);
    rtDisable(RT_CLIP_PLANE0);
    tu_render_float(N, N, img);
    CHECK(lit(2));
    CHECK(lit(9)); /* the camera sees the floor where the occluder was */
    CHECK_INT(shadow_band(), 1);

    tu_section("a coincident unclipped copy still shadows");
    for (int order = 0; order < 2; order++) {
        rtBeginFrame();
        rtInstantiateObject(FLOOR);
        if (order == 1)
            rtInstantiateObject(OCC);
        rtEnable(RT_CLIP_PLANE0);
        rtInstantiateObject(OCC);
        rtDisable(RT_CLIP_PLANE0);
        if (order == 0)
            rtInstantiateObject(OCC);
        tu_render_float(N, N, img);
        CHECK_INT(shadow_band(), 0);
    }

    tu_section("queries skip what clip planes remove");
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtEnable(RT_CLIP_PLANE0);
    rtInstantiateObject(OCC);
    rtDisable(RT_CLIP_PLANE0);
    RTray r[2] = {{{9.5f, 5.0f, 8.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, INFINITY},
                  {{9.5f, 5.0f, 8.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, 6.0f}};
    RThit h[2];
    RTboolean o[2] = {9, 9};
    rtTraceRays(2, r, h);
    rtOccludedRays(2, r, o);
    CHECK_INT((int)h[0].object, (int)FLOOR);
    CHECK(h[0].t == 8.0f);
    CHECK_INT((int)h[0].instance, 0);
    CHECK((int)h[1].instance == (int)RT_INVALID_ID);
    CHECK(o[0] == RT_TRUE && o[1] == RT_FALSE);
    /* Unclipped, the occluder is hit first. */
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtInstantiateObject(OCC);
    rtTraceRays(2, r, h);
    rtOccludedRays(2, r, o);
    CHECK_INT((int)h[0].object, (int)OCC);
    CHECK(h[0].t == 4.0f && h[1].t == 4.0f);
    CHECK(o[0] == RT_TRUE && o[1] == RT_TRUE);
    CHECK_NO_ERR();
}

static void alpha_test(void)
{
    tu_section("a cutout's shadow has the cutout's shape");
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtInstantiateObject(CUTOUT);
    tu_render_float(N, N, img);
    CHECK_INT(shadow_band(), 0); /* no alpha test: the whole polygon */
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtEnable(RT_ALPHA_TEST);
    rtAlphaFunc(RT_GREATER, 0.5f);
    rtInstantiateObject(CUTOUT);
    rtDisable(RT_ALPHA_TEST);
    tu_render_float(N, N, img);
    /* Pixels 4, 5 look through the transparent half (x + 4 in [8, 10]),
     * 6, 7 at the opaque one; the camera sees the lit floor through the
     * cutout at pixel 9. */
    CHECK(lit(4) && lit(5));
    CHECK(dark(6) && dark(7));
    CHECK(lit(9));
    rtAlphaFunc(RT_ALWAYS, 0.0f);

    tu_section("queries see an alpha-tested surface whole");
    RTray r = {{9.5f, 5.0f, 8.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, INFINITY};
    RThit h;
    rtTraceRays(1, &r, &h);
    CHECK_INT((int)h.object, (int)CUTOUT);
    CHECK_NO_ERR();
}

static void blending(void)
{
    tu_section("a blended occluder lets the light through");
    occluder(OCC + 10, 0.3f);
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtEnable(RT_BLEND);
    rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
    rtInstantiateObject(OCC + 10);
    rtDisable(RT_BLEND);
    tu_render_float(N, N, img);
    CHECK_INT(shadow_band(), 1);
    /* Factors that hide what lies behind: opaque, it shadows. */
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtEnable(RT_BLEND);
    rtBlendFunc(RT_ONE, RT_ZERO);
    rtInstantiateObject(OCC + 10);
    rtDisable(RT_BLEND);
    tu_render_float(N, N, img);
    CHECK_INT(shadow_band(), 0);
    /* Blending off: opaque whatever the alpha. */
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtInstantiateObject(OCC + 10);
    tu_render_float(N, N, img);
    CHECK_INT(shadow_band(), 0);
    CHECK_NO_ERR();
}

/* Every state at once, rendered in several configurations. */
static void render_all(const char *config, float *out)
{
    RTcontext ctx = tu_make_context(config);
    setup();
    occluder(OCC + 10, 0.3f);
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtClipPlane(RT_CLIP_PLANE0, keep_below_2);
    rtEnable(RT_CLIP_PLANE0);
    rtPushMatrix();
    rtTranslatef(0.0f, 0.0f, -2.0f);
    rtInstantiateObject(OCC); /* at z = 2: kept */
    rtPopMatrix();
    rtInstantiateObject(OCC);
    rtDisable(RT_CLIP_PLANE0);
    rtEnable(RT_ALPHA_TEST);
    rtAlphaFunc(RT_GREATER, 0.5f);
    rtPushMatrix();
    rtTranslatef(-6.0f, 0.0f, 1.0f);
    rtInstantiateObject(CUTOUT);
    rtPopMatrix();
    rtDisable(RT_ALPHA_TEST);
    rtEnable(RT_BLEND);
    rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
    rtPushMatrix();
    rtTranslatef(-3.0f, 0.0f, 0.5f);
    rtInstantiateObject(OCC + 10);
    rtPopMatrix();
    rtDisable(RT_BLEND);
    tu_render_float(N, N, out);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
}

static void invariance(void)
{
    tu_section("bit-identical across ISAs and threads");
    static float ref[4 * N * N], other[4 * N * N];
    static const char *configs[] = {"threads=2 isa=sse4", "threads=3 isa=avx2",
                                    "threads=1 isa=avx2 packets=off", "threads=2 isa=avx512"};
    render_all("threads=1 isa=scalar", ref);
    for (size_t i = 0; i < sizeof(configs) / sizeof(configs[0]); i++) {
        /* A table this build or CPU lacks (no AVX-512, RT_NO_SIMD)
         * makes rtCreateContext return NULL (docs/context.md). */
        if (!tu_config_available(configs[i])) {
            printf("  skipped (not in this build or on this CPU): %s\n", configs[i]);
            continue;
        }
        render_all(configs[i], other);
        if (memcmp(ref, other, sizeof(ref)) != 0)
            printf("  differs: %s\n", configs[i]);
        CHECK(memcmp(ref, other, sizeof(ref)) == 0);
    }
}

/* A nested group (a list calling OCC twice) drawn under the plane, as
 * one flattened top-level entry and as instances: the same image, no
 * shadow from the clipped occluders, and queries pass them. */
static void nested(const char *config, float *out, int *band, RTuint *hit_object)
{
    RTcontext ctx = tu_make_context(config);
    setup();
    rtNewObject(OCC + 20);
    rtInstantiateObject(OCC);
    rtPushMatrix();
    rtTranslatef(0.0f, 0.0f, 1.0f);
    rtInstantiateObject(OCC);
    rtPopMatrix();
    rtEndObject();
    rtClipPlane(RT_CLIP_PLANE0, keep_below_2);
    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtEnable(RT_CLIP_PLANE0);
    rtInstantiateObject(OCC + 20);
    rtDisable(RT_CLIP_PLANE0);
    tu_render_float(N, N, out);
    memcpy(img, out, sizeof(img));
    *band = shadow_band();
    RTray r = {{9.5f, 5.0f, 8.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, INFINITY};
    RThit h;
    rtTraceRays(1, &r, &h);
    *hit_object = h.object;
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
}

static void nested_groups(void)
{
    tu_section("a flattened nested group is clipped for shadow rays and queries");
    static float flat[4 * N * N], inst[4 * N * N];
    int band_flat, band_inst;
    RTuint obj_flat, obj_inst;
    nested("threads=2 flatten=on", flat, &band_flat, &obj_flat);
    nested("threads=2 flatten=off", inst, &band_inst, &obj_inst);
    CHECK_INT(band_flat, 1);
    CHECK_INT(band_inst, 1);
    CHECK_INT((int)obj_flat, (int)FLOOR);
    CHECK_INT((int)obj_inst, (int)FLOOR);
    CHECK(memcmp(flat, inst, sizeof(flat)) == 0);
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    setup();
    clip_planes();
    alpha_test();
    blending();
    tu_destroy_context(ctx);
    invariance();
    nested_groups();
    return test_summary("secondary_rays");
}
