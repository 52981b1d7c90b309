/* SPDX-License-Identifier: Apache-2.0 */
/*
 * frames.c - conformance: rtViewport, rtClearColor, rtRenderFrame, rtFinish
 * and rtReadPixels.  Framebuffer size and read-back bounds, the clear colour
 * outside the viewport, the alpha convention, row order, byte vs float
 * read-back, camera clipping at near/far, determinism across runs, thread
 * counts and builders, and frame statistics.
 *
 * Reference: docs/frames.md, docs/matrices.md (camera), docs/statistics.md.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define OBJ 500u
#define FAR_OBJ 501u
#define NEAR_OBJ 502u

static RTint geti(RTenum pname)
{
    RTint v = -12345;
    rtGetIntegerv(pname, &v);
    return v;
}

static void viewport_and_clear(void)
{
    RTint vp[4];
    float c[4];
    tu_section("rtViewport / rtClearColor state");
    rtViewport(1, 2, 30, 40);
    rtGetIntegerv(RT_VIEWPORT, vp);
    CHECK(vp[0] == 1 && vp[1] == 2 && vp[2] == 30 && vp[3] == 40);
    rtViewport(-1, 0, 4, 4);
    CHECK_ERR(RT_INVALID_VALUE);
    rtViewport(0, -1, 4, 4);
    CHECK_ERR(RT_INVALID_VALUE);
    rtViewport(0, 0, -4, 4);
    CHECK_ERR(RT_INVALID_VALUE);
    rtViewport(0, 0, 4, -4);
    CHECK_ERR(RT_INVALID_VALUE);
    rtViewport(0, 0, 16385, 4);
    CHECK_ERR(RT_INVALID_VALUE);
    rtViewport(0, 0, 4, 16385);
    CHECK_ERR(RT_INVALID_VALUE);
    rtGetIntegerv(RT_VIEWPORT, vp);
    CHECK(vp[0] == 1 && vp[1] == 2 && vp[2] == 30 && vp[3] == 40);
    rtViewport(0, 0, 16384, 1); /* the limit itself is valid */
    CHECK_NO_ERR();
    rtViewport(0, 0, 0, 0);
    CHECK_NO_ERR();

    rtClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    rtGetFloatv(RT_COLOR_CLEAR_VALUE, c);
    CHECK(c[0] == 0.1f && c[1] == 0.2f && c[2] == 0.3f && c[3] == 0.4f);
    rtClearColor(2.0f, -1.0f, 0.5f, 7.0f);
    rtGetFloatv(RT_COLOR_CLEAR_VALUE, c);
    CHECK(c[0] == 1.0f && c[1] == 0.0f && c[2] == 0.5f && c[3] == 1.0f);
    rtClearColor(tu_nan(), 0, 0, 0);
    CHECK_ERR(RT_INVALID_VALUE);
    rtClearColor(0, 0, 0, -tu_inf());
    CHECK_ERR(RT_INVALID_VALUE);
    rtGetFloatv(RT_COLOR_CLEAR_VALUE, c);
    CHECK(c[0] == 1.0f && c[1] == 0.0f && c[2] == 0.5f && c[3] == 1.0f);
}

static void empty_frames(void)
{
    tu_section("0x0 frames and commands inside objects");
    rtViewport(0, 0, 0, 0);
    rtRenderFrame();
    rtFinish();
    CHECK_NO_ERR();
    rtNewObject(OBJ);
    rtRenderFrame();
    CHECK_ERR(RT_INVALID_OPERATION);
    rtFinish();
    CHECK_ERR(RT_INVALID_OPERATION);
    rtBegin(RT_TRIANGLES);
    rtRenderFrame();
    CHECK_ERR(RT_INVALID_OPERATION);
    rtFinish();
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
}

/* Quad covering y in [-1.5, 0] of the ortho view (x in [-1.5, 1.5]) at z = -5. */
static void lower_half_scene(void)
{
    tu_ortho_camera();
    CHECK(tu_define_quad(OBJ, -1.5f, -1.5f, 1.5f, 0.0f, -5));
    rtBeginFrame();
    rtInstantiateObject(OBJ);
}

static void layout_and_alpha(void)
{
    float f[6 * 4 * 4];
    unsigned char b[6 * 4 * 4];
    int i, j, k;
    tu_section("framebuffer layout, row order, alpha, clear colour outside the viewport");
    rtShadingMode(RT_EYE_LIGHT);
    lower_half_scene();
    rtClearColor(0.25f, 0.5f, 0.75f, 0.25f);
    /* Viewport (2, 1, 4, 3): framebuffer 6 x 4. */
    rtViewport(2, 1, 4, 3);
    rtRenderFrame();
    CHECK_NO_ERR();
    for (k = 0; k < 6 * 4 * 4; k++)
        f[k] = -1.0f;
    rtReadPixels(0, 0, 6, 4, RT_RGBA, RT_FLOAT, f);
    CHECK_NO_ERR();
    for (j = 0; j < 4; j++) {
        for (i = 0; i < 6; i++) {
            const float *p = f + 4 * (j * 6 + i);
            int inside = i >= 2 && j >= 1;
            /* Inside the viewport, row j - 1 of 3 has its centre at ndc
             * y = (j - 1 + 0.5) / 1.5 - 1: rows j = 1 (y = -0.667) hit; j = 2
             * (y = 0) is on the quad's edge; j = 3 (y = 0.667) misses. */
            if (inside && j == 1) {
                CHECK_NEAR(p[3], 1.0, 0);
                CHECK_NEAR(p[0], 0.84, 0.01); /* default material, eye light */
            } else if (!inside || j == 3) {
                if (!tu_check(p[0] == 0.25f && p[1] == 0.5f && p[2] == 0.75f && p[3] == 0.25f,
                              __FILE__, __LINE__, "clear colour where nothing is hit"))
                    fprintf(stderr, "    pixel (%d, %d) = (%g, %g, %g, %g)\n", i, j, p[0], p[1],
                            p[2], p[3]);
            }
        }
    }
    /* Bytes agree with floats: round to nearest. */
    memset(b, 7, sizeof b);
    rtReadPixels(0, 0, 6, 4, RT_RGBA, RT_UNSIGNED_BYTE, b);
    CHECK_NO_ERR();
    {
        int bad = 0;
        for (k = 0; k < 6 * 4 * 4; k++) {
            float v = f[k] < 0 ? 0 : f[k] > 1 ? 1 : f[k];
            if (b[k] != (unsigned char)floorf(v * 255.0f + 0.5f))
                bad++;
        }
        CHECK_INT(bad, 0);
        CHECK_INT(b[3], 64); /* 0.25 * 255 = 63.75 */
        CHECK_INT(b[0], 64);
        CHECK_INT(b[1], 128); /* 127.5 rounds up */
    }
    /* A sub-rectangle is the same pixels. */
    {
        float sub[2 * 3 * 4];
        rtReadPixels(3, 1, 2, 3, RT_RGBA, RT_FLOAT, sub);
        CHECK_NO_ERR();
        for (j = 0; j < 3; j++)
            for (i = 0; i < 2; i++)
                CHECK(memcmp(sub + 4 * (j * 2 + i), f + 4 * ((j + 1) * 6 + i + 3),
                             4 * sizeof(float)) == 0);
    }

    tu_section("rtReadPixels bounds and errors");
    {
        float one[4 * 8];
        for (k = 0; k < 4 * 8; k++)
            one[k] = -9.0f;
        rtReadPixels(5, 3, 1, 1, RT_RGBA, RT_FLOAT, one); /* last pixel */
        CHECK_NO_ERR();
        rtReadPixels(0, 0, 0, 0, RT_RGBA, RT_FLOAT, one); /* empty */
        CHECK_NO_ERR();
        one[0] = -9.0f;
        rtReadPixels(6, 0, 1, 1, RT_RGBA, RT_FLOAT, one);
        CHECK_ERR(RT_INVALID_VALUE);
        rtReadPixels(0, 4, 1, 1, RT_RGBA, RT_FLOAT, one);
        CHECK_ERR(RT_INVALID_VALUE);
        rtReadPixels(5, 0, 2, 1, RT_RGBA, RT_FLOAT, one);
        CHECK_ERR(RT_INVALID_VALUE);
        rtReadPixels(0, 2, 1, 3, RT_RGBA, RT_FLOAT, one);
        CHECK_ERR(RT_INVALID_VALUE);
        rtReadPixels(-1, 0, 1, 1, RT_RGBA, RT_FLOAT, one);
        CHECK_ERR(RT_INVALID_VALUE);
        rtReadPixels(0, -1, 1, 1, RT_RGBA, RT_FLOAT, one);
        CHECK_ERR(RT_INVALID_VALUE);
        rtReadPixels(0, 0, -1, 1, RT_RGBA, RT_FLOAT, one);
        CHECK_ERR(RT_INVALID_VALUE);
        rtReadPixels(0, 0, 1, -1, RT_RGBA, RT_FLOAT, one);
        CHECK_ERR(RT_INVALID_VALUE);
        rtReadPixels(0x7FFFFFFF, 0, 2, 1, RT_RGBA, RT_FLOAT, one); /* x + w overflows */
        CHECK_ERR(RT_INVALID_VALUE);
        rtReadPixels(0, 0, 1, 1, RT_RGBA, RT_FLOAT, NULL);
        CHECK_ERR(RT_INVALID_VALUE);
        rtReadPixels(0, 0, 1, 1, 0x1907 /* GL_RGB */, RT_FLOAT, one);
        CHECK_ERR(RT_INVALID_ENUM);
        rtReadPixels(0, 0, 1, 1, RT_RGBA, RT_DOUBLE, one);
        CHECK_ERR(RT_INVALID_ENUM);
        rtReadPixels(0, 0, 1, 1, RT_RGBA, RT_BYTE, one);
        CHECK_ERR(RT_INVALID_ENUM);
        CHECK(one[0] == -9.0f);
    }

    tu_section("a failing render leaves the framebuffer");
    {
        float again[6 * 4 * 4];
        rtNewObject(FAR_OBJ);
        rtRenderFrame();
        CHECK_ERR(RT_INVALID_OPERATION);
        rtEndObject();
        rtReadPixels(0, 0, 6, 4, RT_RGBA, RT_FLOAT, again);
        CHECK(memcmp(again, f, sizeof again) == 0);
    }

    tu_section("row order: rows bottom to top");
    rtViewport(0, 0, 4, 4);
    rtClearColor(0, 0, 0, 0);
    rtRenderFrame();
    rtReadPixels(0, 0, 4, 4, RT_RGBA, RT_FLOAT, f);
    CHECK_NO_ERR();
    for (j = 0; j < 4; j++)
        for (i = 0; i < 4; i++)
            CHECK_NEAR(f[4 * (j * 4 + i) + 3], j < 2 ? 1.0 : 0.0, 0);
    /* A smaller viewport shrinks the framebuffer. */
    rtViewport(0, 0, 2, 2);
    rtRenderFrame();
    rtReadPixels(0, 0, 2, 2, RT_RGBA, RT_FLOAT, f);
    CHECK_NO_ERR();
    rtReadPixels(0, 0, 3, 3, RT_RGBA, RT_FLOAT, f);
    CHECK_ERR(RT_INVALID_VALUE);
}

static void camera(void)
{
    static const float green[4] = {0, 1, 0, 1}, red[4] = {1, 0, 0, 1}, black[4] = {0, 0, 0, 1};
    float f[8 * 8 * 4];
    int i;
    tu_section("perspective camera and near/far clipping");
    rtShadingMode(RT_EYE_LIGHT);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
    rtClearColor(0, 0, 0, 0);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-1, 1, -1, 1, 1, 100);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    /* At z = -5 the view spans x in [-5, 5]; a quad over x in [1, 5] covers
     * ndc x > 0.2: columns 5..7 of 8 (centres 0.375, 0.625, 0.875). */
    CHECK(tu_define_quad(OBJ, 1, -5, 5, 5, -5));
    CHECK(tu_scene1(OBJ));
    rtViewport(0, 0, 8, 8);
    rtRenderFrame();
    rtReadPixels(0, 0, 8, 8, RT_RGBA, RT_FLOAT, f);
    CHECK_NO_ERR();
    for (i = 0; i < 8; i++)
        CHECK_NEAR(f[4 * (3 * 8 + i) + 3], i >= 5 ? 1.0 : 0.0, 0);
    /* The modelview current at rtRenderFrame plays no part (world = eye space). */
    rtTranslatef(3, 0, 0);
    rtRenderFrame();
    rtReadPixels(0, 0, 8, 8, RT_RGBA, RT_FLOAT, f);
    for (i = 0; i < 8; i++)
        CHECK_NEAR(f[4 * (3 * 8 + i) + 3], i >= 5 ? 1.0 : 0.0, 0);
    rtLoadIdentity();
    CHECK_NO_ERR();

    /* Ortho, near 1, far 100: a red quad at z = -0.5 (in front of the near
     * plane) and one at z = -200 (beyond far) are clipped; the green one at
     * z = -5 shows. */
    tu_ortho_camera();
    /* The quads set no material: each takes the one current at its
     * rtInstantiateObject, as GL's lists take the one at glCallList. */
    CHECK(tu_define_quad(NEAR_OBJ, -2, -2, 2, 2, -0.5f));
    CHECK(tu_define_quad(OBJ, -2, -2, 2, 2, -5));
    CHECK(tu_define_quad(FAR_OBJ, -2, -2, 2, 2, -200));
    rtBeginFrame();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, red);
    rtInstantiateObject(NEAR_OBJ);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, green);
    rtInstantiateObject(OBJ);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, red);
    rtRenderFrame();
    rtReadPixels(0, 0, 8, 8, RT_RGBA, RT_FLOAT, f);
    CHECK_NEAR(f[4 * 27 + 0], 0, 0.01);
    CHECK_NEAR(f[4 * 27 + 1], 1, 0.01);
    rtBeginFrame();
    rtInstantiateObject(FAR_OBJ);
    rtRenderFrame();
    rtReadPixels(0, 0, 8, 8, RT_RGBA, RT_FLOAT, f);
    CHECK_NEAR(f[4 * 27 + 3], 0, 0);
    /* The same quad at z = -99 is inside. */
    rtBeginFrame();
    rtPushMatrix();
    rtTranslatef(0, 0, 101);
    rtInstantiateObject(FAR_OBJ);
    rtPopMatrix();
    rtRenderFrame();
    rtReadPixels(0, 0, 8, 8, RT_RGBA, RT_FLOAT, f);
    CHECK_NEAR(f[4 * 27 + 3], 1, 0);
    CHECK_NEAR(f[4 * 27 + 0], 1, 0.01);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, (const float[4]){0.8f, 0.8f, 0.8f, 1});
    {
        static const float amb[4] = {0.2f, 0.2f, 0.2f, 1};
        rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, amb);
    }
    CHECK_NO_ERR();
}

static void statistics(void)
{
    float t = -1;
    tu_section("frame statistics");
    lower_half_scene();
    rtViewport(0, 0, 16, 8);
    rtRenderFrame();
    CHECK_NO_ERR();
    CHECK_INT(geti(RT_STAT_RAYS), 16 * 8); /* eye light: primary rays only */
    CHECK(geti(RT_STAT_NODE_TESTS) > 0);
    CHECK(geti(RT_STAT_TRIANGLE_TESTS) > 0);
    CHECK(geti(RT_STAT_INSTANCE_TESTS) > 0);
    rtGetFloatv(RT_STAT_RENDER_TIME, &t);
    CHECK(t >= 0.0f);
    {
        float fr = -1;
        rtGetFloatv(RT_STAT_RAYS, &fr);
        CHECK_NEAR(fr, geti(RT_STAT_RAYS), 0);
    }
    /* Rendering the unchanged scene again builds nothing. */
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 0);
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);
    /* Whitted with one light: a shadow ray per pixel whose primary ray hits
     * a lit surface (rows 0..3 of 8: the quad covers y < 0). */
    rtShadingMode(RT_WHITTED);
    rtEnable(RT_LIGHT0);
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_RAYS), 16 * 8 + 16 * 4);
    rtDisable(RT_LIGHT0);
    rtShadingMode(RT_EYE_LIGHT);
    /* An empty viewport traces no ray. */
    rtViewport(0, 0, 0, 0);
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_RAYS), 0);
    CHECK_NO_ERR();
}

/* ---- determinism ----------------------------------------------------------------- */

#define DW 48
#define DH 32

/* A reproducible scene: a bumpy grid (fixed-seed heights) and boxes, under a
 * perspective camera, Whitted shading with a shadowing light and a mirror. */
static void build_scene(void)
{
    static const float lo[3] = {-0.5f, -0.5f, -0.5f}, hi[3] = {0.5f, 0.5f, 0.5f};
    static const float pos[4] = {1, 2, 1.5f, 0}, refl_diffuse[4] = {0.3f, 0.3f, 0.4f, 1};
    unsigned seed = 12345u;
    int i, j;
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-0.6, 0.6, -0.4, 0.4, 1, 50);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtNewObject(OBJ);
    rtBegin(RT_TRIANGLES);
    for (j = 0; j < 24; j++) {
        for (i = 0; i < 24; i++) {
            float h[4];
            int k;
            for (k = 0; k < 4; k++) {
                seed = seed * 1664525u + 1013904223u;
                h[k] = (float)(seed >> 8) / 16777216.0f * 0.3f;
            }
            rtVertex3f((float)i - 12, h[0], (float)j - 24);
            rtVertex3f((float)i - 11, h[1], (float)j - 24);
            rtVertex3f((float)i - 11, h[2], (float)j - 23);
            rtVertex3f((float)i - 12, h[0], (float)j - 24);
            rtVertex3f((float)i - 11, h[2], (float)j - 23);
            rtVertex3f((float)i - 12, h[3], (float)j - 23);
        }
    }
    rtEnd();
    rtEndObject();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, refl_diffuse);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 0.5f);
    CHECK(tu_define_box(FAR_OBJ, lo, hi));
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 0);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, (const float[4]){0.8f, 0.8f, 0.8f, 1});
    rtShadingMode(RT_WHITTED);
    rtEnable(RT_LIGHT0);
    rtLightfv(RT_LIGHT0, RT_POSITION, pos);
    rtBeginFrame();
    rtPushMatrix();
    rtTranslatef(0, -1.5f, 0);
    rtInstantiateObject(OBJ);
    rtPopMatrix();
    for (i = 0; i < 5; i++) {
        rtPushMatrix();
        rtTranslatef((float)i - 2.0f, -0.8f, -6.0f - (float)i);
        rtRotatef(17.0f * (float)i, 0.3f, 1, 0.1f);
        rtInstantiateObject(FAR_OBJ);
        rtPopMatrix();
    }
    rtViewport(0, 0, DW, DH);
    rtClearColor(0.1f, 0.1f, 0.2f, 0);
    CHECK_NO_ERR();
}

static float *render_with(const char *config)
{
    RTcontext previous = rtGetCurrentContext();
    RTcontext ctx = tu_make_context(config);
    float *img = (float *)malloc(sizeof(float) * 4 * DW * DH);
    tu_capture_errors();
    build_scene();
    rtRenderFrame();
    rtReadPixels(0, 0, DW, DH, RT_RGBA, RT_FLOAT, img);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
    rtMakeCurrent(previous);
    return img;
}

static void determinism(void)
{
    static const char *const configs[] = {"threads=2 builder=sweep", "threads=4",
                                          "threads=3 bins=2", "threads=1 bins=256"};
    float *ref, *img;
    size_t c;
    int k, hits = 0;
    tu_section("images are bit-identical across runs, thread counts and builders");
    ref = render_with("threads=1");
    for (k = 0; k < DW * DH; k++)
        if (ref[4 * k + 3] == 1.0f)
            hits++;
    CHECK(hits > DW * DH / 4); /* the scene is actually in view */
    img = render_with("threads=1");
    CHECK(memcmp(ref, img, sizeof(float) * 4 * DW * DH) == 0);
    free(img);
    for (c = 0; c < sizeof configs / sizeof configs[0]; c++) {
        img = render_with(configs[c]);
        if (!tu_check(memcmp(ref, img, sizeof(float) * 4 * DW * DH) == 0, __FILE__, __LINE__,
                      "image identical to threads=1"))
            fprintf(stderr, "    configuration \"%s\"\n", configs[c]);
        free(img);
    }
    free(ref);
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    viewport_and_clear();
    empty_frames();
    layout_and_alpha();
    camera();
    statistics();
    determinism();
    tu_destroy_context(ctx);
    return test_summary("frames");
}
