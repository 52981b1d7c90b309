/* SPDX-License-Identifier: Apache-2.0 */
/*
 * overlay_geometry.c - geometry drawn under a projection or an inset
 * viewport other than the frame's (docs/overlay_geometry.md): a heads-up
 * display under a pushed rtuOrtho2D, blended, with the depth test off,
 * shows over the traced scene; a background drawn first goes under it; a
 * HUD with the depth test on is hidden where the scene is nearer in
 * window depth; a minimap in an inset viewport; a HUD projection loaded
 * without a push (the scene still traced, o-proj); an object only
 * rasterised gets no structure work (o-proj); a textured HUD (o-proj);
 * and frames that never
 * called rtClear keep tracing everything through the projection current
 * at rtRenderFrame.  Every section but the last fails against main before
 * o-overlay, which traced the HUD through the frame's perspective.
 * (The OSMesa comparison of the same cases is gl_oracle/overlay.)
 */
#include <math.h>

#include <rt/rtu.h>

#include "testutil.h"

#define W 16
#define H 16

static float px[4 * W * H];

static const float *pixel(int x, int y)
{
    return &px[4 * (y * W + x)];
}

#define CHECK_RGB(p, r, g, b)                                                                 \
    CHECKF(fabsf((p)[0] - (r)) < 2e-3f && fabsf((p)[1] - (g)) < 2e-3f &&                      \
               fabsf((p)[2] - (b)) < 2e-3f,                                                   \
           "pixel (%g, %g, %g), expected (%g, %g, %g)", (double)(p)[0], (double)(p)[1],      \
           (double)(p)[2], (double)(r), (double)(g), (double)(b))

static void perspective(void)
{
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtuPerspective(60.0, 1.0, 1.0, 20.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
}

/* A quad at z (eye space) over x, y in [x0, x1] x [y0, y1]. */
static void quad(float x0, float y0, float x1, float y1, float z)
{
    rtBegin(RT_QUADS);
    rtVertex3f(x0, y0, z);
    rtVertex3f(x1, y0, z);
    rtVertex3f(x1, y1, z);
    rtVertex3f(x0, y1, z);
    rtEnd();
}

/* The scene: a red wall filling the view at z = -5 (traced). */
static void red_wall(void)
{
    rtEnable(RT_DEPTH_TEST);
    rtColor3f(1, 0, 0);
    quad(-10, -10, 10, 10, -5);
}

static void hud_begin(void)
{
    rtMatrixMode(RT_PROJECTION);
    rtPushMatrix();
    rtLoadIdentity();
    rtuOrtho2D(0.0, W, 0.0, H);
    rtMatrixMode(RT_MODELVIEW);
    rtPushMatrix();
    rtLoadIdentity();
}

static void hud_end(void)
{
    rtPopMatrix();
    rtMatrixMode(RT_PROJECTION);
    rtPopMatrix();
    rtMatrixMode(RT_MODELVIEW);
}

static void render(void)
{
    rtReadPixels(0, 0, W, H, RT_RGBA, RT_FLOAT, px);
}

static void hud_over_scene(void)
{
    tu_section("a blended HUD panel and a crosshair over the traced scene");
    rtViewport(0, 0, W, H);
    rtClearColor(0, 0, 1, 1);
    rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
    perspective();
    red_wall();
    hud_begin();
    rtDisable(RT_DEPTH_TEST);
    rtEnable(RT_BLEND);
    rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
    rtColor4f(0, 0, 0, 0.5f);
    quad(0, 0, 8, 16, 0); /* the left half */
    rtDisable(RT_BLEND);
    rtColor3f(0, 1, 0);
    rtBegin(RT_LINES); /* row 12, over the right half */
    rtVertex2f(8.0f, 12.5f);
    rtVertex2f(16.0f, 12.5f);
    rtEnd();
    hud_end();
    render();
    CHECK_RGB(pixel(2, 4), 0.5f, 0, 0);
    CHECK_RGB(pixel(7, 4), 0.5f, 0, 0);
    CHECK_RGB(pixel(8, 4), 1, 0, 0);
    CHECK_RGB(pixel(12, 12), 0, 1, 0);
    CHECK_RGB(pixel(12, 11), 1, 0, 0);
    /* The projection is the scene's again. */
    RTfloat p[16];
    rtGetFloatv(RT_PROJECTION_MATRIX, p);
    CHECK(p[11] == -1.0f);
    CHECK_NO_ERR();
}

static void background_first(void)
{
    tu_section("a background quad drawn first goes under the scene");
    rtViewport(0, 0, W, H);
    rtClearColor(0, 0, 0, 1);
    rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtDisable(RT_DEPTH_TEST);
    rtColor3f(0, 0, 1);
    quad(-1, -1, 1, 1, 0);
    perspective();
    rtEnable(RT_DEPTH_TEST);
    rtColor3f(1, 0, 0);
    quad(-1, -1, 1, 1, -5); /* the middle of the view */
    render();
    CHECK_RGB(pixel(8, 8), 1, 0, 0);
    CHECK_RGB(pixel(0, 0), 0, 0, 1);
    CHECK_RGB(pixel(15, 15), 0, 0, 1);
    CHECK_NO_ERR();
}

static void hud_depth_tested(void)
{
    tu_section("a HUD with the depth test on: window depths compared");
    rtViewport(0, 0, W, H);
    rtClearColor(0, 0, 1, 1);
    rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
    perspective();
    red_wall();
    /* Under glOrtho(near 0, far 1) the quad's window depth is -z: 0.2 in
     * front of the wall (window depth about 0.84), 0.95 behind it. */
    rtMatrixMode(RT_PROJECTION);
    rtPushMatrix();
    rtLoadIdentity();
    rtOrtho(0.0, W, 0.0, H, 0.0, 1.0);
    rtMatrixMode(RT_MODELVIEW);
    rtPushMatrix();
    rtLoadIdentity();
    rtColor3f(0, 1, 0);
    quad(0, 0, 8, 16, -0.2f);
    rtColor3f(1, 1, 0);
    quad(8, 0, 16, 16, -0.95f);
    hud_end();
    render();
    CHECK_RGB(pixel(3, 8), 0, 1, 0);
    CHECK_RGB(pixel(12, 8), 1, 0, 0);
    CHECK_NO_ERR();
}

static void minimap(void)
{
    tu_section("an inset viewport: a minimap drawn under its own viewport");
    rtViewport(0, 0, W, H);
    rtClearColor(0, 0, 1, 1);
    rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
    perspective();
    red_wall();
    rtViewport(12, 12, 4, 4);
    hud_begin(); /* rtuOrtho2D(0, 16, 0, 16) mapped onto the 4 x 4 inset */
    rtDisable(RT_DEPTH_TEST);
    rtColor3f(1, 1, 1);
    quad(0, 0, 8, 8, 0); /* its lower-left quarter: pixels 12, 13 */
    hud_end();
    rtViewport(0, 0, W, H);
    render();
    CHECK_RGB(pixel(12, 12), 1, 1, 1);
    CHECK_RGB(pixel(13, 13), 1, 1, 1);
    CHECK_RGB(pixel(14, 14), 1, 0, 0);
    CHECK_RGB(pixel(4, 4), 1, 0, 0);
    CHECK_NO_ERR();
}

/* The closest hit along -z from (x, y, z) in eye space (the modelview
 * was the identity at every draw). */
static float trace_down_z(float x, float y, float z)
{
    RTray ray = {{x, y, z}, 0.0f, {0.0f, 0.0f, -1.0f}, INFINITY};
    RThit hit;
    rtTraceRays(1, &ray, &hit);
    return hit.t;
}

/* The display callback of many GLUT programs: the HUD's gluOrtho2D loaded
 * over the scene's perspective without a push, left current at the
 * swap.  The frame is traced through the perspective the depth-tested
 * scene was drawn under, and the HUD rasterised. */
static void unpushed_hud(void)
{
    tu_section("a HUD projection loaded without a push: the scene is still traced");
    rtViewport(0, 0, W, H);
    rtClearColor(0, 0, 1, 1);
    rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
    perspective();
    red_wall();
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtuOrtho2D(0.0, W, 0.0, H);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtDisable(RT_DEPTH_TEST);
    rtEnable(RT_BLEND);
    rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
    rtColor4f(0, 0, 0, 0.5f);
    quad(0, 0, 8, 16, 0); /* the left half, blended over the wall */
    rtDisable(RT_BLEND);
    render();
    CHECK_RGB(pixel(2, 4), 0.5f, 0, 0);
    CHECK_RGB(pixel(7, 12), 0.5f, 0, 0);
    CHECK_RGB(pixel(8, 4), 1, 0, 0);
    CHECK_RGB(pixel(15, 15), 1, 0, 0);
    /* Rays see the traced wall, not the rasterised HUD (which lies at
     * eye z = 0 over x in [0, 8]); before, the wall was rasterised and
     * the HUD traced. */
    CHECK_NEAR(trace_down_z(-3.0f, -3.0f, 0.0f), 5.0f, 0.0);
    CHECK_NEAR(trace_down_z(4.0f, 8.0f, 1.0f), 6.0f, 0.0);
    /* The HUD's projection stays current, as in GL. */
    RTfloat p[16];
    rtGetFloatv(RT_PROJECTION_MATRIX, p);
    CHECK(p[11] == 0.0f && p[15] == 1.0f);
    CHECK_NO_ERR();
}

static RTint geti(RTenum pname)
{
    RTint v = -1;
    rtGetIntegerv(pname, &v);
    return v;
}

/* An object whose instances are all rasterised gets no structure built
 * or updated: no ray reaches it. */
static void rasterised_not_built(void)
{
    tu_section("objects only rasterised get no acceleration structure work");
    static const float z0[12] = {0, 0, 0, 8, 0, 0, 8, 8, 0, 0, 8, 0};
    static const float z1[12] = {0, 0, 0, 6, 0, 0, 6, 6, 0, 0, 6, 0};
    RTuint hud, panel;
    rtGenObjects(1, &hud);
    rtGenObjects(1, &panel);
    rtNewObject(hud);
    rtColor3f(0, 1, 0);
    quad(0, 0, 4, 4, 0);
    rtEndObject();
    rtNewObject(panel);
    rtBegin(RT_QUADS);
    for (int k = 0; k < 4; k++)
        rtVertex3fv(&z0[3 * k]);
    rtEnd();
    rtEndObject();
    RTint n;
    /* Frame 1: the panel drawn under the scene's projection, traced and
     * built; the HUD under a pushed rtuOrtho2D, rasterised. */
    rtViewport(0, 0, W, H);
    rtClearColor(0, 0, 1, 1);
    rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
    perspective();
    red_wall();
    rtTranslatef(-8, -8, -4);
    rtInstantiateObject(panel);
    rtLoadIdentity();
    hud_begin();
    rtDisable(RT_DEPTH_TEST);
    rtInstantiateObject(hud);
    hud_end();
    render();
    CHECK_RGB(pixel(1, 1), 0, 1, 0);
    rtGetObjectiv(hud, RT_OBJECT_BVH_NODES, &n);
    CHECK_INT(n, 0);
    rtGetObjectiv(panel, RT_OBJECT_BVH_NODES, &n);
    CHECK(n > 0);
    /* Frame 2: the panel's vertices change (its structure goes stale) and
     * it is drawn under the HUD's projection only: rasterised, so the
     * preparation leaves its structure stale instead of updating it. */
    rtUpdateVertices(panel, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, z1);
    rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
    perspective();
    red_wall();
    hud_begin();
    rtDisable(RT_DEPTH_TEST);
    rtColor3f(1, 1, 1);
    rtInstantiateObject(panel);
    rtInstantiateObject(hud);
    hud_end();
    render();
    CHECK_RGB(pixel(5, 5), 1, 1, 1);
    CHECK_RGB(pixel(1, 1), 0, 1, 0);
    CHECK_RGB(pixel(7, 7), 1, 0, 0);
    CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
    CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 0);
    rtGetObjectiv(hud, RT_OBJECT_BVH_NODES, &n);
    CHECK_INT(n, 0);
    CHECK_NO_ERR();
    rtDeleteObjects(1, &hud);
    rtDeleteObjects(1, &panel);
}

/* A HUD quad textured with a 2 x 2 texture (NEAREST, magnified 8 times):
 * each quarter of the view takes its texel, modulated by the colour. */
static void textured_hud(void)
{
    tu_section("a textured HUD quad: texels, MODULATE, then REPLACE");
    static const unsigned char texels[16] = {255, 0,   0,   255, 0,   255, 0,   255,
                                             0,   0,   255, 255, 255, 255, 255, 255};
    RTuint tex;
    rtGenTextures(1, &tex);
    rtBindTexture(RT_TEXTURE_2D, tex);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_NEAREST);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_NEAREST);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 2, 2, 0, RT_RGBA, RT_UNSIGNED_BYTE, texels);
    for (int replace = 0; replace < 2; replace++) {
        rtViewport(0, 0, W, H);
        rtClearColor(0, 0, 0, 1);
        rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
        perspective();
        red_wall();
        hud_begin();
        rtDisable(RT_DEPTH_TEST);
        rtEnable(RT_TEXTURE_2D);
        rtTexEnvi(RT_TEXTURE_ENV, RT_TEXTURE_ENV_MODE, replace ? RT_REPLACE : RT_MODULATE);
        rtColor3f(0.5f, 0.5f, 0.5f);
        rtBegin(RT_QUADS);
        rtTexCoord2f(0, 0);
        rtVertex2f(0, 0);
        rtTexCoord2f(1, 0);
        rtVertex2f(W, 0);
        rtTexCoord2f(1, 1);
        rtVertex2f(W, H);
        rtTexCoord2f(0, 1);
        rtVertex2f(0, H);
        rtEnd();
        rtDisable(RT_TEXTURE_2D);
        hud_end();
        render();
        const float k = replace ? 1.0f : 0.5f;
        CHECK_RGB(pixel(3, 3), k, 0, 0);
        CHECK_RGB(pixel(12, 3), 0, k, 0);
        CHECK_RGB(pixel(3, 12), 0, 0, k);
        CHECK_RGB(pixel(12, 12), k, k, k);
    }
    rtTexEnvi(RT_TEXTURE_ENV, RT_TEXTURE_ENV_MODE, RT_MODULATE);
    rtDeleteTextures(1, &tex);
    CHECK_NO_ERR();
}

static void own_frames_unchanged(void)
{
    tu_section("rtBeginFrame / rtRenderFrame: the projection at the render");
    RTcontext ctx = tu_make_context(NULL);
    rtViewport(0, 0, W, H);
    rtClearColor(0, 0, 1, 1);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtBeginFrame();
    rtColor3f(1, 0, 0);
    quad(-1, -1, 1, 1, -5);
    /* The camera set after the drawing, as Tracelist's frames allow. */
    perspective();
    rtRenderFrame();
    render();
    CHECK_RGB(pixel(8, 8), 1, 0, 0);
    CHECK_RGB(pixel(0, 0), 0, 0, 1);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    hud_over_scene();
    background_first();
    hud_depth_tested();
    minimap();
    unpushed_hud();
    rasterised_not_built();
    textured_hud();
    tu_destroy_context(ctx);
    own_frames_unchanged();
    return test_summary("overlay_geometry");
}
