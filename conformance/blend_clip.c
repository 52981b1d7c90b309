/* SPDX-License-Identifier: Apache-2.0 */
/*
 * blend_clip.c - conformance: RT_BLEND with rtBlendFunc (see-through
 * surfaces composited as GL composites a back-to-front program),
 * rtDepthMask, and the user clip planes rtClipPlane / rtGetClipPlane
 * (the plane transformed by the modelview at the call; primary rays
 * continue past a clipped hit; lines clipped too; ray queries
 * skip clipped hits).  State queries and errors.
 *
 * Camera: rtOrtho(0, N, 0, N, -1, 1) on N x N pixels, eye looking down
 * -z; surfaces are emissive (the eye light then shows the emission
 * exactly) with the alpha in the diffuse material.
 *
 * Reference: docs/blending.md, docs/clip_planes.md.
 */
#include "testutil.h"

#include <math.h>
#include <string.h>

#define N 16
#define BACK 800u
#define FRONT 801u
#define LINES 802u
#define CLIPPED 803u
#define CLIPPED_EXEC 804u

static float img[4 * N * N];

static void window_camera(void)
{
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtOrtho(0.0, N, 0.0, N, -1.0, 1.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
}

static const float *px(int x, int y)
{
    return &img[4 * (y * N + x)];
}

/* A square over x in [x0, x1] (all of y) at depth z, emissive colour c
 * with alpha a. */
static void square(RTuint name, float x0, float x1, float z, const float c[3], float a)
{
    const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f}, diffuse[4] = {0.0f, 0.0f, 0.0f, a};
    const float emission[4] = {c[0], c[1], c[2], 1.0f};
    rtNewObject(name);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, diffuse);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, emission);
    rtBegin(RT_QUADS);
    rtVertex3f(x0, 0.0f, z);
    rtVertex3f(x1, 0.0f, z);
    rtVertex3f(x1, (float)N, z);
    rtVertex3f(x0, (float)N, z);
    rtEnd();
    rtEndObject();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
}

static void render_both(void)
{
    rtClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    rtBeginFrame();
    rtInstantiateObject(BACK);
    rtInstantiateObject(FRONT);
    tu_render_float(N, N, img);
}

static int near3(const float *p, double r, double g, double b)
{
    return fabs(p[0] - r) < 1e-5 && fabs(p[1] - g) < 1e-5 && fabs(p[2] - b) < 1e-5;
}

static void blending(void)
{
    static const float red[3] = {0.9f, 0.2f, 0.1f}, green[3] = {0.1f, 0.8f, 0.3f};
    tu_section("RT_BLEND: two quads, back to front");
    window_camera();
    square(BACK, 0.0f, 10.0f, -0.5f, red, 1.0f);
    square(FRONT, 6.0f, 16.0f, 0.5f, green, 0.25f);
    render_both();
    /* Blending off: the nearest surface, whatever its alpha. */
    CHECK(near3(px(8, 8), 0.1, 0.8, 0.3));
    CHECK(px(8, 8)[3] == 1.0f);
    rtEnable(RT_BLEND);
    rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
    render_both();
    /* GL: the red quad drawn first, then the green one over it. */
    CHECK(near3(px(8, 8), 0.25 * 0.1 + 0.75 * 0.9, 0.25 * 0.8 + 0.75 * 0.2,
                0.25 * 0.3 + 0.75 * 0.1));
    CHECK_NEAR(px(8, 8)[3], 0.25 * 0.25 + 0.75 * 1.0, 1e-6);
    CHECK(near3(px(3, 8), 0.9, 0.2, 0.1));       /* red alone */
    CHECK(near3(px(13, 8), 0.025, 0.2, 0.075));  /* green over the black clear colour */
    /* The order of instances does not matter: depth order does. */
    rtBeginFrame();
    rtInstantiateObject(FRONT);
    rtInstantiateObject(BACK);
    rtClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    float again[4 * N * N];
    tu_render_float(N, N, again);
    CHECK(memcmp(again, img, sizeof(again)) == 0);
    /* Additive. */
    rtBlendFunc(RT_ONE, RT_ONE);
    render_both();
    CHECK(near3(px(8, 8), 1.0, 1.0, 0.4));
    /* A destination factor: DST_COLOR, ZERO multiplies, down to the
     * clear colour (white here, so the red quad stays red). */
    rtBlendFunc(RT_DST_COLOR, RT_ZERO);
    rtBeginFrame();
    rtInstantiateObject(BACK);
    rtInstantiateObject(FRONT);
    rtClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    tu_render_float(N, N, img);
    CHECK(near3(px(8, 8), 0.09, 0.16, 0.03));
    CHECK(near3(px(3, 8), 0.9, 0.2, 0.1));
    /* An opaque front surface hides what is behind. */
    square(FRONT, 6.0f, 16.0f, 0.5f, green, 1.0f);
    rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
    render_both();
    CHECK(near3(px(8, 8), 0.1, 0.8, 0.3));
    rtDisable(RT_BLEND);
    rtBlendFunc(RT_ONE, RT_ZERO);
    CHECK_NO_ERR();
}

/* Coplanar translucent surfaces: GL blends each over the earlier ones in
 * draw order (instances, then triangles); a ray meets them at one t. */
static void coplanar(void)
{
    static const float red[3] = {0.9f, 0.2f, 0.1f}, green[3] = {0.1f, 0.8f, 0.3f};
    tu_section("RT_BLEND: coplanar translucent surfaces in draw order");
    window_camera();
    rtEnable(RT_BLEND);
    rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
    /* One quad of two triangles: the pixels on its diagonal (x = y, where
     * the ray meets both triangles at one t) are blended once. */
    square(BACK, 0.0f, 16.0f, 0.0f, red, 0.5f);
    rtBeginFrame();
    rtInstantiateObject(BACK);
    tu_render_float(N, N, img);
    for (int i = 0; i < N; i++)
        CHECK(near3(px(i, i), 0.45, 0.1, 0.05) && near3(px(i, (i + 5) % N), 0.45, 0.1, 0.05));
    /* Two instances in one plane: the second drawn lies over the first. */
    square(FRONT, 0.0f, 16.0f, 0.0f, green, 0.5f);
    render_both();
    CHECK(near3(px(8, 8), 0.5 * 0.1 + 0.25 * 0.9, 0.5 * 0.8 + 0.25 * 0.2, 0.5 * 0.3 + 0.25 * 0.1));
    CHECK(near3(px(3, 3), 0.5 * 0.1 + 0.25 * 0.9, 0.5 * 0.8 + 0.25 * 0.2, 0.5 * 0.3 + 0.25 * 0.1));
    rtBeginFrame();
    rtInstantiateObject(FRONT);
    rtInstantiateObject(BACK);
    tu_render_float(N, N, img);
    CHECK(near3(px(8, 8), 0.5 * 0.9 + 0.25 * 0.1, 0.5 * 0.2 + 0.25 * 0.8, 0.5 * 0.1 + 0.25 * 0.3));
    /* Two instances meeting along an edge (x = 8.5, through the centres
     * of the pixels of column 8): GL gives each such pixel to one of the
     * two triangles, so it is blended once, as inside one mesh. */
    square(BACK, 0.0f, 8.5f, 0.0f, red, 0.5f);
    square(FRONT, 8.5f, 16.0f, 0.0f, red, 0.5f);
    render_both();
    CHECK(near3(px(8, 5), 0.45, 0.1, 0.05) && near3(px(8, 12), 0.45, 0.1, 0.05));
    CHECK(near3(px(3, 5), 0.45, 0.1, 0.05) && near3(px(12, 5), 0.45, 0.1, 0.05));
    /* More than 32 coincident surfaces: every one is blended (no fixed
     * cap), 32 red ones drawn first, 8 green ones over them. */
    const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    rtNewObject(BACK);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    for (int k = 0; k < 40; k++) {
        const float *c = k < 32 ? red : green;
        const float diffuse[4] = {0.0f, 0.0f, 0.0f, 0.5f}, emission[4] = {c[0], c[1], c[2], 1};
        rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, diffuse);
        rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, emission);
        rtBegin(RT_QUADS);
        rtVertex3f(0.0f, 0.0f, 0.0f);
        rtVertex3f(16.0f, 0.0f, 0.0f);
        rtVertex3f(16.0f, 16.0f, 0.0f);
        rtVertex3f(0.0f, 16.0f, 0.0f);
        rtEnd();
    }
    rtEndObject();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
    rtBeginFrame();
    rtInstantiateObject(BACK);
    tu_render_float(N, N, img);
    /* Red (to 2^-32) under 8 halvings towards green. */
    const double w8 = 1.0 / 256.0;
    CHECK(near3(px(5, 9), 0.1 + 0.8 * w8, 0.8 - 0.6 * w8, 0.3 - 0.2 * w8));
    /* Thousands of coincident quads in one object (a stability case):
     * all composited, alternating red and green at alpha 1/2: the last
     * of them (green) on top. */
    rtNewObject(BACK);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    for (int k = 0; k < 3000; k++) {
        const float *c = k % 2 ? green : red;
        const float diffuse[4] = {0.0f, 0.0f, 0.0f, 0.5f}, emission[4] = {c[0], c[1], c[2], 1};
        rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, diffuse);
        rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, emission);
        rtBegin(RT_QUADS);
        rtVertex3f(0.0f, 0.0f, 0.0f);
        rtVertex3f(16.0f, 0.0f, 0.0f);
        rtVertex3f(16.0f, 16.0f, 0.0f);
        rtVertex3f(0.0f, 16.0f, 0.0f);
        rtEnd();
    }
    rtEndObject();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
    rtBeginFrame();
    rtInstantiateObject(BACK);
    tu_render_float(N, N, img);
    /* Green over red repeated: g = (G + R / 2) / (1 - 1/4) in the limit. */
    const double r = (0.5 * 0.1 + 0.25 * 0.9) / 0.75, g = (0.5 * 0.8 + 0.25 * 0.2) / 0.75,
                 b = (0.5 * 0.3 + 0.25 * 0.1) / 0.75;
    CHECK(near3(px(5, 9), r, g, b));
    CHECK(near3(px(12, 3), r, g, b));
    /* On the quads' diagonal each copy counts once (its two triangles
     * share the edge). */
    CHECK(fabs(px(8, 8)[0] - r) < 1e-4 && fabs(px(8, 8)[1] - g) < 1e-4 &&
          fabs(px(8, 8)[2] - b) < 1e-4);
    rtDisable(RT_BLEND);
    rtBlendFunc(RT_ONE, RT_ZERO);
    CHECK_NO_ERR();
}

static void clip_planes(void)
{
    static const float red[3] = {1.0f, 0.0f, 0.0f}, blue[3] = {0.0f, 0.0f, 1.0f};
    tu_section("rtClipPlane: eye space, primary rays continue, lines clipped");
    window_camera();
    square(BACK, 0.0f, 16.0f, -0.5f, red, 1.0f);
    square(FRONT, 0.0f, 16.0f, 0.5f, blue, 1.0f);
    /* Keep x >= 8 of the front quad's space; given under a translation
     * by (4, 0, 0) the plane is x >= 12 in eye space. */
    static const double plane[4] = {1.0, 0.0, 0.0, -8.0};
    rtPushMatrix();
    rtTranslatef(4.0f, 0.0f, 0.0f);
    rtClipPlane(RT_CLIP_PLANE3, plane);
    rtPopMatrix();
    double eq[4];
    rtGetClipPlane(RT_CLIP_PLANE3, eq);
    CHECK(eq[0] == 1.0 && eq[1] == 0.0 && eq[2] == 0.0 && eq[3] == -12.0);
    render_both();
    CHECK(near3(px(5, 5), 0.0, 0.0, 1.0)); /* not enabled yet */
    rtEnable(RT_CLIP_PLANE3);
    CHECK(rtIsEnabled(RT_CLIP_PLANE3) == RT_TRUE);
    render_both();
    /* Both quads are cut at x = 12: nothing left of it. */
    CHECK(near3(px(5, 5), 0.0, 0.0, 0.0) && px(5, 5)[3] == 0.0f);
    CHECK(near3(px(11, 5), 0.0, 0.0, 0.0));
    CHECK(near3(px(12, 5), 0.0, 0.0, 1.0));
    /* A plane in z removes the front quad only: the ray goes on to the
     * red one behind it. */
    rtDisable(RT_CLIP_PLANE3);
    static const double below[4] = {0.0, 0.0, -1.0, 0.0}; /* keep z <= 0 */
    rtClipPlane(RT_CLIP_PLANE0, below);
    rtEnable(RT_CLIP_PLANE0);
    render_both();
    CHECK(near3(px(5, 5), 1.0, 0.0, 0.0) && near3(px(14, 14), 1.0, 0.0, 0.0));
    /* A coincident copy of the front quad drawn after the plane is
     * disabled is there: the ray does not step past the clipped copy's
     * distance and lose it. */
    rtBeginFrame();
    rtInstantiateObject(BACK);
    rtInstantiateObject(FRONT);
    rtDisable(RT_CLIP_PLANE0);
    rtInstantiateObject(FRONT);
    rtEnable(RT_CLIP_PLANE0);
    rtClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    tu_render_float(N, N, img);
    CHECK(near3(px(5, 5), 0.0, 0.0, 1.0) && near3(px(14, 14), 0.0, 0.0, 1.0));
    render_both();
    /* Ray queries are clipped too (docs/clip_planes.md): the front quad,
     * drawn under the plane, is not there. */
    RTray ray = {{5.5f, 5.5f, 1.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, INFINITY};
    RThit hit;
    rtTraceRays(1, &ray, &hit);
    CHECK(hit.object == BACK && hit.t == 1.5f);
    /* Lines: a segment crossing z = 0 is cut there. */
    rtNewObject(LINES);
    rtColor3f(0.0f, 1.0f, 0.0f);
    rtBegin(RT_LINES);
    rtVertex3f(0.5f, 12.5f, -0.9f);
    rtVertex3f(15.5f, 12.5f, 0.9f);
    rtEnd();
    rtPointSize(3.0f);
    rtBegin(RT_POINTS);
    rtVertex3f(3.5f, 3.5f, -0.1f); /* kept */
    rtVertex3f(10.5f, 3.5f, 0.8f); /* clipped */
    rtEnd();
    rtEndObject();
    rtPointSize(1.0f);
    rtDisable(RT_CLIP_PLANE0);
    square(BACK, 0.0f, 0.0f, -0.5f, red, 1.0f); /* empty: nothing behind */
    rtBeginFrame();
    rtInstantiateObject(LINES);
    rtClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    tu_render_float(N, N, img);
    CHECK(px(3, 12)[1] == 1.0f && px(12, 12)[1] == 1.0f && px(10, 3)[1] == 1.0f);
    rtEnable(RT_CLIP_PLANE0);
    rtBeginFrame();
    rtInstantiateObject(LINES);
    tu_render_float(N, N, img);
    CHECK(px(3, 12)[1] == 1.0f && px(12, 12)[1] == 0.0f);
    CHECK(px(3, 3)[1] == 1.0f && px(10, 3)[1] == 0.0f);
    rtDisable(RT_CLIP_PLANE0);
    CHECK_NO_ERR();
}

/* An emissive quad over x in [x0, x1], y in [y0, y1] at z = 0, drawn now
 * (immediate mode, or into the list being recorded). */
static void quad_now(float x0, float x1, float y0, float y1, const float c[3])
{
    const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    const float emission[4] = {c[0], c[1], c[2], 1.0f};
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, emission);
    rtBegin(RT_QUADS);
    rtVertex3f(x0, y0, 0.0f);
    rtVertex3f(x1, y0, 0.0f);
    rtVertex3f(x1, y1, 0.0f);
    rtVertex3f(x0, y1, 0.0f);
    rtEnd();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
}

/* A list that sets its own plane (x <= 4 in the list's space), enables
 * it, draws a quad over x in [0, 16], y in [0, 8], and disables it: what
 * varray.c does. */
static void clipped_list(RTuint name, RTenum mode, const float c[3])
{
    static const double keep_left[4] = {-1.0, 0.0, 0.0, 4.0};
    rtNewList(name, mode);
    rtClipPlane(RT_CLIP_PLANE2, keep_left);
    rtEnable(RT_CLIP_PLANE2);
    quad_now(0.0f, 16.0f, 0.0f, 8.0f, c);
    rtDisable(RT_CLIP_PLANE2);
    rtEndList();
}

/* GL clips each primitive by the planes enabled when it is drawn, with
 * the equations of that moment; a list's rtClipPlane is executed at the
 * call under the modelview then current (OpenGL 2.1 sec. 2.12, 5.4). */
static void per_primitive_clip(void)
{
    static const float red[3] = {1.0f, 0.0f, 0.0f}, blue[3] = {0.0f, 0.0f, 1.0f};
    static const float green[3] = {0.0f, 1.0f, 0.0f};
    static const double keep_top[4] = {0.0, 1.0, 0.0, -8.0}; /* y >= 8 */
    tu_section("clip planes per primitive: the planes current at the draw or the call");
    window_camera();
    rtClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    square(BACK, 0.0f, 8.0f, -0.5f, red, 1.0f);
    square(FRONT, 8.0f, 16.0f, 0.5f, blue, 1.0f);
    rtClipPlane(RT_CLIP_PLANE1, keep_top);

    /* Objects: enable, draw A, disable, draw B: A clipped, B whole. */
    rtBeginFrame();
    rtEnable(RT_CLIP_PLANE1);
    rtInstantiateObject(BACK);
    rtDisable(RT_CLIP_PLANE1);
    rtInstantiateObject(FRONT);
    tu_render_float(N, N, img);
    CHECK(near3(px(3, 3), 0.0, 0.0, 0.0) && px(3, 3)[3] == 0.0f);
    CHECK(near3(px(3, 12), 1.0, 0.0, 0.0));
    CHECK(near3(px(12, 3), 0.0, 0.0, 1.0) && near3(px(12, 12), 0.0, 0.0, 1.0));

    /* Immediate mode, surfaces and points alike. */
    rtBeginFrame();
    rtEnable(RT_CLIP_PLANE1);
    quad_now(0.0f, 8.0f, 0.0f, 16.0f, red);
    rtColor3f(0.0f, 1.0f, 0.0f);
    rtBegin(RT_POINTS);
    rtVertex3f(12.5f, 3.5f, 0.9f); /* clipped */
    rtEnd();
    rtDisable(RT_CLIP_PLANE1);
    quad_now(8.0f, 16.0f, 0.0f, 16.0f, blue);
    rtBegin(RT_POINTS);
    rtVertex3f(14.5f, 3.5f, 0.9f); /* drawn after the disable: kept */
    rtEnd();
    tu_render_float(N, N, img);
    CHECK(near3(px(3, 3), 0.0, 0.0, 0.0) && near3(px(3, 12), 1.0, 0.0, 0.0));
    CHECK(near3(px(12, 3), 0.0, 0.0, 1.0) && near3(px(12, 12), 0.0, 0.0, 1.0));
    CHECK(near3(px(14, 3), 0.0, 1.0, 0.0));

    /* A list with its own plane, called under two modelviews: two
     * instances cut at x = 4 and at x = 12 (the plane moved by the
     * translation at each call). */
    clipped_list(CLIPPED, RT_COMPILE, green);
    CHECK(rtIsEnabled(RT_CLIP_PLANE2) == RT_FALSE); /* RT_COMPILE executed nothing */
    rtBeginFrame();
    rtCallList(CLIPPED);
    rtPushMatrix();
    rtTranslatef(8.0f, 8.0f, 0.0f);
    rtCallList(CLIPPED);
    rtPopMatrix();
    CHECK(rtIsEnabled(RT_CLIP_PLANE2) == RT_FALSE);
    double eq[4];
    rtGetClipPlane(RT_CLIP_PLANE2, eq); /* the last call's: x <= 12 */
    CHECK(eq[0] == -1.0 && eq[1] == 0.0 && eq[2] == 0.0 && eq[3] == 12.0);
    tu_render_float(N, N, img);
    CHECK(near3(px(2, 3), 0.0, 1.0, 0.0) && near3(px(6, 3), 0.0, 0.0, 0.0));
    CHECK(near3(px(10, 12), 0.0, 1.0, 0.0) && near3(px(14, 12), 0.0, 0.0, 0.0));
    CHECK(near3(px(2, 12), 0.0, 0.0, 0.0));

    /* RT_COMPILE_AND_EXECUTE: the executed instance is clipped too. */
    rtBeginFrame();
    rtPushMatrix();
    rtTranslatef(4.0f, 0.0f, 0.0f);
    clipped_list(CLIPPED_EXEC, RT_COMPILE_AND_EXECUTE, blue);
    rtPopMatrix();
    tu_render_float(N, N, img);
    CHECK(near3(px(6, 3), 0.0, 0.0, 1.0) && near3(px(10, 3), 0.0, 0.0, 0.0));
    CHECK(near3(px(6, 12), 0.0, 0.0, 0.0));
    CHECK(rtIsEnabled(RT_CLIP_PLANE2) == RT_FALSE);
    CHECK_NO_ERR();
}

static void state_and_errors(void)
{
    tu_section("state queries and errors");
    RTint v = -1;
    CHECK(rtIsEnabled(RT_BLEND) == RT_FALSE);
    rtEnable(RT_BLEND);
    CHECK(rtIsEnabled(RT_BLEND) == RT_TRUE);
    rtDisable(RT_BLEND);
    rtGetIntegerv(RT_BLEND_SRC, &v);
    CHECK_INT(v, RT_ONE);
    rtGetIntegerv(RT_BLEND_DST, &v);
    CHECK_INT(v, RT_ZERO);
    rtBlendFunc(RT_SRC_ALPHA_SATURATE, RT_ONE_MINUS_DST_ALPHA);
    rtGetIntegerv(RT_BLEND_SRC, &v);
    CHECK_INT(v, RT_SRC_ALPHA_SATURATE);
    rtGetIntegerv(RT_BLEND_DST, &v);
    CHECK_INT(v, RT_ONE_MINUS_DST_ALPHA);
    rtGetIntegerv(RT_DEPTH_WRITEMASK, &v);
    CHECK_INT(v, RT_TRUE);
    rtDepthMask(RT_FALSE);
    rtGetIntegerv(RT_DEPTH_WRITEMASK, &v);
    CHECK_INT(v, RT_FALSE);
    rtDepthMask(RT_TRUE);
    rtGetIntegerv(RT_MAX_CLIP_PLANES, &v);
    CHECK_INT(v, 6);
    for (int i = 0; i < 6; i++) {
        double eq[4] = {1, 1, 1, 1};
        CHECK(rtIsEnabled(RT_CLIP_PLANE0 + (RTenum)i) == RT_FALSE);
        rtGetClipPlane(RT_CLIP_PLANE0 + (RTenum)i, eq);
        (void)eq;
    }
    double eq[4] = {9, 9, 9, 9};
    rtGetClipPlane(RT_CLIP_PLANE5, eq);
    CHECK(eq[0] == 0.0 && eq[1] == 0.0 && eq[2] == 0.0 && eq[3] == 0.0);
    CHECK_NO_ERR();

    rtBlendFunc(0x1234, RT_ONE);
    CHECK_ERR(RT_INVALID_ENUM);
    rtBlendFunc(RT_ONE, RT_SRC_ALPHA_SATURATE);
    CHECK_ERR(RT_INVALID_ENUM);
    rtGetIntegerv(RT_BLEND_SRC, &v);
    CHECK_INT(v, RT_SRC_ALPHA_SATURATE); /* unchanged */
    rtClipPlane(RT_CLIP_PLANE0 + 6, eq);
    CHECK_ERR(RT_INVALID_ENUM);
    rtClipPlane(RT_CLIP_PLANE0, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    double bad[4] = {1.0, tu_nan_d(), 0.0, 0.0};
    rtClipPlane(RT_CLIP_PLANE0, bad);
    CHECK_ERR(RT_INVALID_VALUE);
    rtGetClipPlane(0x2FFF, eq);
    CHECK_ERR(RT_INVALID_ENUM);
    rtGetClipPlane(RT_CLIP_PLANE1, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtEnable(RT_CLIP_PLANE0 + 6);
    CHECK_ERR(RT_INVALID_ENUM);
    rtIsEnabled(RT_CLIP_PLANE0 + 6);
    CHECK_ERR(RT_INVALID_ENUM);
    rtNewObject(LINES);
    rtBegin(RT_TRIANGLES);
    rtBlendFunc(RT_ONE, RT_ONE);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtDepthMask(RT_FALSE);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtClipPlane(RT_CLIP_PLANE0, eq);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtGetClipPlane(RT_CLIP_PLANE0, eq);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    rtEndObject();
    rtGetIntegerv(RT_DEPTH_WRITEMASK, &v);
    CHECK_INT(v, RT_TRUE);
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    /* Surfaces here are given their colour as emission, which the eye
     * light shows as is (the fixed-function default would show the
     * vertex colour, white). */
    rtShadingMode(RT_EYE_LIGHT);
    blending();
    coplanar();
    clip_planes();
    per_primitive_clip();
    state_and_errors();
    tu_destroy_context(ctx);
    return test_summary("blend_clip");
}
