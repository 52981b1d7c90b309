/* SPDX-License-Identifier: Apache-2.0 */
/*
 * textures.c - conformance: rtGenTextures, rtDeleteTextures, rtIsTexture,
 * rtBindTexture, rtTexImage2D, rtTexParameteri, the RT_TEXTURE_2D
 * capability and the texture queries, and what textured triangles look
 * like.
 *
 * Every error of every entry point is checked together with a query or a
 * rendered pixel showing that the failing call changed nothing.
 *
 * Sampling is observed through rendered pixels.  The camera is
 * tu_ortho_camera (rays along -z, x and y in [-1, 1]) on a 16x16 viewport,
 * so pixel (i, j) looks at x = -1 + (i + 0.5) / 8, y = -1 + (j + 0.5) / 8.
 * The quad covering the view has texture coordinates s = (x + 1) / 2,
 * t = (y + 1) / 2, so pixel (i, j) samples s = (i + 0.5) / 16,
 * t = (j + 0.5) / 16.  The material is ambient 0, diffuse 1, emission 0
 * with global ambient 0, and every ray hits head-on (|cos| = 1), so the
 * eye-light colour, emission + global_ambient * ambient + diffuse * |cos|
 * with ambient and diffuse modulated by the texel, is the texel itself.
 *
 * Reference: docs/textures.md.
 */
#include "testutil.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define QUAD 500u
#define OTHER 501u

#define W 16
#define H 16
static float px[W * H * 4];

static const float black[4] = {0, 0, 0, 1};
static const float white[4] = {1, 1, 1, 1};

/* A 2x2 image: row 0 (t = 0, the bottom) red, green; row 1 blue, yellow-ish. */
static const unsigned char image_2x2[16] = {255, 0, 0, 255, 0,   255, 0,   255,
                                            0,   0, 255, 255, 255, 255, 51, 255};
static const float texel_2x2[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0.2f}};

static RTint geti(RTenum pname)
{
    RTint v = -12345;
    rtGetIntegerv(pname, &v);
    return v;
}

static const float *pixel(int i, int j)
{
    return px + 4 * (j * W + i);
}

static int rgb_near(const char *file, int line, const float *p, float r, float g, float b,
                    float tol)
{
    int ok = fabsf(p[0] - r) <= tol && fabsf(p[1] - g) <= tol && fabsf(p[2] - b) <= tol;
    if (!tu_check(ok, file, line, "pixel colour"))
        fprintf(stderr, "    pixel (%.7g, %.7g, %.7g), expected (%.7g, %.7g, %.7g)\n", p[0], p[1],
                p[2], r, g, b);
    return ok;
}
/* Exact up to float rounding: texels are k / 255, weights are exact. */
#define CHECK_RGB(p, r, g, b) rgb_near(__FILE__, __LINE__, (p), (r), (g), (b), 1e-5f)
/* Interpolated texture coordinates are rounded: a looser tolerance. */
#define CHECK_RGB_APPROX(p, r, g, b) rgb_near(__FILE__, __LINE__, (p), (r), (g), (b), 2e-3f)

/* Ambient 0, diffuse 1, emission and specular 0, global ambient 0. */
static void plain_material(void)
{
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, white);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, black);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
}

/* The quad covering the view at z = -5, texture coordinates (s0, t0) at
 * the bottom left to (s1, t1) at the top right. */
/* The texture binding and RT_TEXTURE_2D enable current when QUAD / OTHER
 * were defined by define_quad: render() calls them under that state.  A
 * list's geometry that sets no texture state of its own is drawn with the
 * texture current at the call, as GL (docs/lists.md); until 25814ff it
 * kept the one current at its definition, which these sections were
 * written against. */
static RTint defined_binding[2];
static int defined_enable[2];

static void define_quad(RTuint name, float s0, float t0, float s1, float t1)
{
    if (name == QUAD || name == OTHER) {
        rtGetIntegerv(RT_TEXTURE_BINDING_2D, &defined_binding[name - QUAD]);
        defined_enable[name - QUAD] = rtIsEnabled(RT_TEXTURE_2D);
    }
    rtNewObject(name);
    rtBegin(RT_QUADS);
    rtTexCoord2f(s0, t0);
    rtVertex3f(-1, -1, -5);
    rtTexCoord2f(s1, t0);
    rtVertex3f(1, -1, -5);
    rtTexCoord2f(s1, t1);
    rtVertex3f(1, 1, -5);
    rtTexCoord2f(s0, t1);
    rtVertex3f(-1, 1, -5);
    rtEnd();
    rtEndObject();
}

/* The full quad with one texture coordinate at every vertex. */
static void define_constant_quad(RTuint name, float s, float t)
{
    define_quad(name, s, t, s, t);
}

/* Renders object `name` alone, called under the texture state of its
 * definition (defined_binding), the context's state restored afterwards. */
static void render(RTuint name)
{
    RTint binding = 0;
    const int enabled = rtIsEnabled(RT_TEXTURE_2D);
    rtGetIntegerv(RT_TEXTURE_BINDING_2D, &binding);
    rtBindTexture(RT_TEXTURE_2D, (RTuint)defined_binding[name - QUAD]);
    (defined_enable[name - QUAD] ? rtEnable : rtDisable)(RT_TEXTURE_2D);
    CHECK(tu_scene1(name));
    tu_render_float(W, H, px);
    rtBindTexture(RT_TEXTURE_2D, (RTuint)binding);
    (enabled ? rtEnable : rtDisable)(RT_TEXTURE_2D);
    CHECK_NO_ERR();
}

static void upload_2x2(void)
{
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 2, 2, 0, RT_RGBA, RT_UNSIGNED_BYTE, image_2x2);
}

static void set_filter(RTint filter)
{
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, filter);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, filter);
}

static void set_wrap(RTint wrap)
{
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_WRAP_S, wrap);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_WRAP_T, wrap);
}

/* Every pixel shows the texel of its quadrant (NEAREST, 2x2 image). */
static int quadrants_ok(const float texel[4][3])
{
    int ok = 1;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            const float *e = texel[(j >= H / 2) * 2 + (i >= W / 2)];
            const float *p = pixel(i, j);
            if (fabsf(p[0] - e[0]) > 1e-5f || fabsf(p[1] - e[1]) > 1e-5f ||
                fabsf(p[2] - e[2]) > 1e-5f) {
                if (ok)
                    fprintf(stderr, "    pixel (%d, %d) is (%g, %g, %g), expected (%g, %g, %g)\n",
                            i, j, p[0], p[1], p[2], e[0], e[1], e[2]);
                ok = 0;
            }
        }
    return ok;
}

/* The quadrants of the 2x2 image scaled by (r, g, b). */
static int quadrants_scaled_ok(float r, float g, float b)
{
    float scaled[4][3];
    for (int k = 0; k < 4; k++) {
        scaled[k][0] = texel_2x2[k][0] * r;
        scaled[k][1] = texel_2x2[k][1] * g;
        scaled[k][2] = texel_2x2[k][2] * b;
    }
    return quadrants_ok(scaled);
}

/* ---- names, binding, queries ----------------------------------------------- */

static void names_and_binding(void)
{
    tu_section("initial state and limits");
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), 0);
    CHECK_INT(geti(RT_MAX_TEXTURE_SIZE), 16384);
    CHECK(rtIsEnabled(RT_TEXTURE_2D) == RT_FALSE);
    {
        RTfloat f = -1;
        rtGetFloatv(RT_MAX_TEXTURE_SIZE, &f);
        CHECK(f == 16384.0f);
    }
    CHECK(rtIsTexture(0) == RT_FALSE);
    CHECK(rtIsTexture(77) == RT_FALSE);
    CHECK_NO_ERR();

    tu_section("rtEnable(RT_TEXTURE_2D)");
    rtEnable(RT_TEXTURE_2D);
    CHECK(rtIsEnabled(RT_TEXTURE_2D) == RT_TRUE);
    tu_begin_scratch(RT_TRIANGLES);
    rtDisable(RT_TEXTURE_2D);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    CHECK(rtIsEnabled(RT_TEXTURE_2D) == RT_TRUE);
    rtDisable(RT_TEXTURE_2D);
    CHECK(rtIsEnabled(RT_TEXTURE_2D) == RT_FALSE);
    CHECK_NO_ERR();

    tu_section("rtGenTextures");
    RTuint names[3] = {0, 0, 0};
    rtGenTextures(3, names);
    CHECK_NO_ERR();
    CHECK(names[0] != 0 && names[1] != 0 && names[2] != 0);
    CHECK(names[0] != names[1] && names[1] != names[2] && names[0] != names[2]);
    /* A generated name is not a texture until bound (GL 1.1). */
    CHECK(rtIsTexture(names[0]) == RT_FALSE);
    rtGenTextures(0, NULL);
    CHECK_NO_ERR();
    {
        RTuint out[2] = {12345, 12345};
        rtGenTextures(-1, out);
        CHECK_ERR(RT_INVALID_VALUE);
        CHECK_MSG("rtGenTextures");
        rtGenTextures(2, NULL);
        CHECK_ERR(RT_INVALID_VALUE);
        tu_begin_scratch(RT_TRIANGLES);
        rtGenTextures(2, out);
        CHECK_ERR(RT_INVALID_OPERATION);
        CHECK_MSG("rtGenTextures");
        tu_end_scratch();
        CHECK(out[0] == 12345 && out[1] == 12345);
    }
    /* Names in use are not handed out again: one just past the last
     * generated name is taken by binding it. */
    const RTuint taken = names[2] + 2;
    rtBindTexture(RT_TEXTURE_2D, taken);
    {
        RTuint more[64];
        rtGenTextures(64, more);
        CHECK_NO_ERR();
        int clash = 0;
        for (int i = 0; i < 64; i++)
            clash |= more[i] == taken || more[i] == names[0] || more[i] == names[1] ||
                     more[i] == names[2] || more[i] == 0;
        CHECK(!clash);
        rtDeleteTextures(64, more);
    }

    tu_section("rtBindTexture");
    rtBindTexture(RT_TEXTURE_2D, names[1]);
    CHECK_NO_ERR();
    CHECK(rtIsTexture(names[1]) == RT_TRUE);
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), names[1]);
    /* An unused name becomes a texture when bound. */
    rtBindTexture(RT_TEXTURE_2D, 4242);
    CHECK(rtIsTexture(4242) == RT_TRUE);
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), 4242);
    rtBindTexture(0x0DE0 /* GL_TEXTURE_1D */, names[1]);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtBindTexture");
    rtBindTexture(RT_RGBA, 7);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), 4242);
    CHECK(rtIsTexture(7) == RT_FALSE);
    tu_begin_scratch(RT_TRIANGLES);
    rtBindTexture(RT_TEXTURE_2D, names[1]);
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK_MSG("rtBindTexture");
    /* Queries stay allowed between rtBegin and rtEnd. */
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), 4242);
    rtBindTexture(RT_TEXTURE_2D, 8);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    CHECK(rtIsTexture(8) == RT_FALSE);
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), 4242);
    /* Allowed inside an object definition: recorded, and bound when the
     * object is called (GL's display lists, docs/lists.md). */
    rtNewObject(TU_SCRATCH_OBJECT);
    rtBindTexture(RT_TEXTURE_2D, names[2]);
    CHECK_NO_ERR();
    rtEndObject();
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), 4242);
    rtInstantiateObject(TU_SCRATCH_OBJECT);
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), names[2]);
    rtBindTexture(RT_TEXTURE_2D, 0);
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), 0);
    CHECK_NO_ERR();

    tu_section("rtIsTexture");
    tu_begin_scratch(RT_TRIANGLES);
    CHECK(rtIsTexture(names[1]) == RT_FALSE);
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK_MSG("rtIsTexture");
    tu_end_scratch();
    CHECK(rtIsTexture(names[1]) == RT_TRUE);

    tu_section("rtDeleteTextures");
    rtBindTexture(RT_TEXTURE_2D, names[1]);
    rtDeleteTextures(-1, names);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtDeleteTextures");
    rtDeleteTextures(1, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    tu_begin_scratch(RT_TRIANGLES);
    rtDeleteTextures(3, names);
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK_MSG("rtDeleteTextures");
    tu_end_scratch();
    CHECK(rtIsTexture(names[1]) == RT_TRUE);
    CHECK(rtIsTexture(names[2]) == RT_TRUE);
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), names[1]);
    rtDeleteTextures(0, NULL);
    CHECK_NO_ERR();
    /* 0 and unused names are ignored; deleting the bound texture binds 0. */
    {
        RTuint victims[4] = {0, 31337, names[1], names[2]};
        rtDeleteTextures(4, victims);
        CHECK_NO_ERR();
    }
    CHECK(rtIsTexture(names[1]) == RT_FALSE);
    CHECK(rtIsTexture(names[2]) == RT_FALSE);
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), 0);
    /* Deleting a texture that is not bound leaves the binding. */
    rtBindTexture(RT_TEXTURE_2D, 4242);
    rtDeleteTextures(1, &names[0]);
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), 4242);
    /* Allowed inside an object definition. */
    rtNewObject(TU_SCRATCH_OBJECT);
    rtDeleteTextures(1, &taken);
    CHECK_NO_ERR();
    rtEndObject();
    CHECK(rtIsTexture(taken) == RT_FALSE);
    {
        RTuint doomed = 4242;
        rtDeleteTextures(1, &doomed);
    }
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), 0);
    CHECK_NO_ERR();
}

/* ---- image and parameter errors ----------------------------------------------- */

static void image_errors(void)
{
    static const unsigned char red[4] = {255, 0, 0, 255};
    const RTuint tex = 10;
    tu_section("rtTexImage2D / rtTexParameteri errors change nothing");
    tu_ortho_camera();
    plain_material();
    /* No texture bound (0): there is no default texture object. */
    rtBindTexture(RT_TEXTURE_2D, 0);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK_MSG("rtTexImage2D");
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_NEAREST);
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK_MSG("rtTexParameteri");
    /* The mode is checked before the enums. */
    rtTexImage2D(0x0DE0, 0, RT_RGBA, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtTexParameteri(0x0DE0, 0x1234, 0x5678);
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK(rtIsTexture(tex) == RT_FALSE);

    rtBindTexture(RT_TEXTURE_2D, tex);
    upload_2x2();
    set_filter(RT_NEAREST);
    CHECK_NO_ERR();
    rtEnable(RT_TEXTURE_2D);
    define_quad(QUAD, 0, 0, 1, 1);
    rtDisable(RT_TEXTURE_2D);
    render(QUAD);
    CHECK(quadrants_ok(texel_2x2));

    /* Each failing upload would have made the whole quad red. */
    tu_begin_scratch(RT_TRIANGLES);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    rtTexImage2D(0x0DE0, 0, RT_RGBA, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 1, 0, 0x1909 /* GL_LUMINANCE */,
                 RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 1, 0, RT_RGBA, RT_UNSIGNED_SHORT, red);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 1, 0, RT_RGBA, RT_DOUBLE, red);
    CHECK_ERR(RT_INVALID_ENUM);
    /* Level 1 of this 2x2 image is 1x1: 2x2 there is refused. */
    rtTexImage2D(RT_TEXTURE_2D, 1, RT_RGBA, 2, 2, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtTexImage2D");
    rtTexImage2D(RT_TEXTURE_2D, 15, RT_RGBA, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexImage2D(RT_TEXTURE_2D, -1, RT_RGBA, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexImage2D(RT_TEXTURE_2D, 0, 1, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexImage2D(RT_TEXTURE_2D, 0, 2, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexImage2D(RT_TEXTURE_2D, 0, 0x1909, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 0, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 0, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, -1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, -4, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 16385, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 16385, 0, RT_RGBA, RT_UNSIGNED_BYTE, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 1, 1, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_VALUE);
    /* Checks in order: mode, enums, values (docs/textures.md). */
    rtTexImage2D(0x0DE0, 1, 1, 0, 0, 1, RT_RGBA, RT_UNSIGNED_BYTE, red);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexImage2D(RT_TEXTURE_2D, 1, 1, 0, 0, 1, RT_RGBA, RT_BYTE, red);
    CHECK_ERR(RT_INVALID_ENUM);

    /* Each failing parameter call would have made the quad LINEAR (the
     * quadrants would blend) or changed nothing visible for wrap, which
     * the next section observes. */
    tu_begin_scratch(RT_TRIANGLES);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_LINEAR);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    rtTexParameteri(0x0DE0, RT_TEXTURE_MAG_FILTER, RT_LINEAR);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtTexParameteri");
    rtTexParameteri(RT_TEXTURE_2D, 0x2804 /* GL_TEXTURE_BORDER_COLOR */, RT_LINEAR);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, 0x2703 /* LINEAR_MIPMAP_LINEAR */);
    CHECK_ERR(RT_INVALID_ENUM);
    /* The mipmapped filters are MIN_FILTER values only (texture_mipmap.c). */
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_NEAREST_MIPMAP_NEAREST);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, 0x2704 /* past the mipmap filters */);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_REPEAT);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_WRAP_S, 0x2900 /* GL_CLAMP */);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_WRAP_T, RT_LINEAR);
    CHECK_ERR(RT_INVALID_ENUM);
    render(QUAD);
    CHECK(quadrants_ok(texel_2x2));
    CHECK_NO_ERR();

    tu_section("no current context");
    {
        RTcontext ctx = rtGetCurrentContext();
        RTuint out = 12345;
        rtMakeCurrent(NULL);
        rtGenTextures(1, &out);
        rtDeleteTextures(1, &tex);
        rtBindTexture(RT_TEXTURE_2D, 0);
        rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
        rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_LINEAR);
        CHECK(rtIsTexture(tex) == RT_FALSE);
        CHECK(out == 12345);
        rtMakeCurrent(ctx);
        CHECK_NO_ERR();
        CHECK(rtIsTexture(tex) == RT_TRUE);
        CHECK_INT(geti(RT_TEXTURE_BINDING_2D), tex);
        render(QUAD);
        CHECK(quadrants_ok(texel_2x2));
    }
}

/* ---- sampling ----------------------------------------------------------------- */

static void nearest_and_linear(void)
{
    const RTuint tex = 20;
    tu_section("NEAREST: the four texels in the four quadrants (row 0 is t = 0)");
    tu_ortho_camera();
    plain_material();
    rtBindTexture(RT_TEXTURE_2D, tex);
    upload_2x2();
    set_filter(RT_NEAREST);
    rtEnable(RT_TEXTURE_2D);
    define_quad(QUAD, 0, 0, 1, 1);
    rtDisable(RT_TEXTURE_2D);
    render(QUAD);
    CHECK(quadrants_ok(texel_2x2));

    tu_section("untextured when RT_TEXTURE_2D is disabled at definition");
    define_quad(OTHER, 0, 0, 1, 1);
    render(OTHER);
    CHECK_RGB(pixel(2, 2), 1, 1, 1);
    CHECK_RGB(pixel(13, 13), 1, 1, 1);
    /* Enabled at the call, the object (which sets no texture state of its
     * own) is drawn textured, as GL draws a list's geometry. */
    rtEnable(RT_TEXTURE_2D);
    CHECK(tu_scene1(OTHER));
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(2, 2), 1, 0, 0);
    rtDisable(RT_TEXTURE_2D);

    tu_section("MAG filter RT_LINEAR: bilinear mix (GL 1.1 eq. 3.17)");
    /* Parameters belong to the texture and are read when rendering. */
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_LINEAR);
    render(QUAD);
    /* Pixel (5, 10): s = 5.5/16, u = 2s - 1/2 = 0.1875: texels 0 and 1,
     * alpha = 0.1875; t = 10.5/16, v = 0.8125: rows 0 and 1, beta = 0.8125.
     * Weights: (0,0) 0.8125*0.1875 = 0.15234375, (1,0) 0.1875^2 =
     * 0.03515625, (0,1) 0.8125^2 = 0.66015625, (1,1) 0.15234375.
     * R = 0.15234375 + 0.15234375 = 0.3046875; G = 0.03515625 + 0.15234375
     * = 0.1875; B = 0.66015625 + 0.2 * 0.15234375 = 0.690625. */
    CHECK_RGB_APPROX(pixel(5, 10), 0.3046875f, 0.1875f, 0.690625f);
    /* Pixel (0, 0): s = t = 1/32, u = v = -0.4375: with REPEAT (the
     * default) texel -1 is texel 1; alpha = beta = 0.5625.  Weights: (1,1)
     * 0.4375^2 = 0.19140625, (0,1) and (1,0) 0.5625*0.4375 = 0.24609375,
     * (0,0) 0.5625^2 = 0.31640625.  R = 0.19140625 + 0.31640625 =
     * 0.5078125; G = 0.19140625 + 0.24609375 = 0.4375; B = 0.2 *
     * 0.19140625 + 0.24609375 = 0.284375. */
    CHECK_RGB_APPROX(pixel(0, 0), 0.5078125f, 0.4375f, 0.284375f);

    tu_section("CLAMP_TO_EDGE");
    set_wrap(RT_CLAMP_TO_EDGE);
    render(QUAD);
    /* u = v = -0.4375 clamps to texel (0, 0). */
    CHECK_RGB_APPROX(pixel(0, 0), 1, 0, 0);
    CHECK_RGB_APPROX(pixel(15, 15), 1, 1, 0.2f);
    CHECK_RGB_APPROX(pixel(5, 10), 0.3046875f, 0.1875f, 0.690625f); /* inside: unchanged */
    /* Per coordinate: REPEAT in s, CLAMP in t.  Pixel (0, 0): s wraps to
     * texels 1 and 0 (weights 0.4375, 0.5625), t clamps to row 0:
     * 0.4375 * green + 0.5625 * red. */
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_WRAP_S, RT_REPEAT);
    render(QUAD);
    CHECK_RGB_APPROX(pixel(0, 0), 0.5625f, 0.4375f, 0);
    set_wrap(RT_REPEAT);
    set_filter(RT_NEAREST);
    CHECK_NO_ERR();
}

/* A 4x1 image: red, green, blue, dark red (0.4, 0, 0). */
static void upload_4x1(RTuint tex)
{
    static const unsigned char image[16] = {255, 0, 0, 255, 0, 255, 0, 255,
                                            0,   0, 255, 255, 102, 0, 0, 255};
    rtBindTexture(RT_TEXTURE_2D, tex);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 4, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, image);
}

static void repeat_and_clamp(void)
{
    const RTuint tex = 30;
    tu_section("REPEAT: huge and negative coordinates");
    tu_ortho_camera();
    plain_material();
    upload_4x1(tex);
    rtEnable(RT_TEXTURE_2D);
    /* LINEAR at s = 0.75: u = 3 - 1/2 = 2.5, half blue, half dark red. */
    define_constant_quad(QUAD, 0.75f, 0.5f);
    render(QUAD);
    CHECK_RGB_APPROX(pixel(8, 8), 0.2f, 0, 0.5f);
    /* s = -196.25 repeats to 0.75. */
    define_constant_quad(QUAD, -196.25f, 0.5f);
    render(QUAD);
    CHECK_RGB_APPROX(pixel(8, 8), 0.2f, 0, 0.5f);
    CHECK_RGB_APPROX(pixel(0, 15), 0.2f, 0, 0.5f);
    /* s = 1e7 repeats to 0: u = -1/2, half dark red (texel -1 = 3), half red. */
    define_constant_quad(QUAD, 1e7f, 0.5f);
    render(QUAD);
    CHECK_RGB_APPROX(pixel(8, 8), 0.7f, 0, 0);
    /* t far outside [0, 1] on a one-row image: still that row. */
    define_constant_quad(QUAD, 0.75f, -12345.6f);
    render(QUAD);
    CHECK_RGB_APPROX(pixel(8, 8), 0.2f, 0, 0.5f);
    /* NEAREST: s = 0.8 and s = -196.2 are in texel 3. */
    set_filter(RT_NEAREST);
    define_constant_quad(QUAD, -196.2f, 0.5f);
    render(QUAD);
    CHECK_RGB(pixel(8, 8), 0.4f, 0, 0);
    define_constant_quad(QUAD, 0.8f, 0.5f);
    render(QUAD);
    CHECK_RGB(pixel(8, 8), 0.4f, 0, 0);
    /* s from -2 to 2 across the view: the image four times. */
    define_quad(QUAD, -2, 0, 2, 1);
    render(QUAD);
    /* Pixel i samples s = -2 + 4 (i + 0.5) / 16, texel floor(4 s) mod 4. */
    CHECK_RGB(pixel(0, 8), 1, 0, 0);   /* s = -1.875: texel 0 */
    CHECK_RGB(pixel(1, 8), 0, 1, 0);   /* s = -1.625: texel 1 */
    CHECK_RGB(pixel(6, 8), 0, 0, 1);   /* s = -0.375: texel 2 */
    CHECK_RGB(pixel(15, 8), 0.4f, 0, 0); /* s = 1.875: texel 3 */

    tu_section("CLAMP_TO_EDGE: the edge texels");
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_WRAP_S, RT_CLAMP_TO_EDGE);
    render(QUAD);
    CHECK_RGB(pixel(0, 8), 1, 0, 0);    /* s < 0: texel 0 */
    CHECK_RGB(pixel(6, 8), 1, 0, 0);    /* s = -0.375: texel 0 */
    CHECK_RGB(pixel(9, 8), 0, 1, 0);    /* s = 0.375: texel 1 */
    CHECK_RGB(pixel(15, 8), 0.4f, 0, 0); /* s > 1: texel 3 */
    set_filter(RT_LINEAR);
    define_constant_quad(QUAD, -196.25f, 0.5f);
    render(QUAD);
    CHECK_RGB_APPROX(pixel(8, 8), 1, 0, 0);
    define_constant_quad(QUAD, 1e7f, 0.5f);
    render(QUAD);
    CHECK_RGB_APPROX(pixel(8, 8), 0.4f, 0, 0);
    rtDisable(RT_TEXTURE_2D);
    CHECK_NO_ERR();
}

static void upload_formats(void)
{
    const RTuint tex = 40;
    tu_section("RT_RGB uploads: rows tightly packed under RT_UNPACK_ALIGNMENT 1");
    tu_ortho_camera();
    plain_material();
    rtBindTexture(RT_TEXTURE_2D, tex);
    set_filter(RT_NEAREST);
    rtEnable(RT_TEXTURE_2D);
    define_quad(QUAD, 0, 0, 1, 1);
    rtDisable(RT_TEXTURE_2D);
    {
        /* 3x2, 9 bytes a row (GL's default 4-byte alignment would pad to
         * 12: conformance/pixel_store.c tests that default). */
        static const unsigned char rgb[18] = {255, 0,   0,   0,  255, 0,   0,   0,   255,
                                              51,  102, 153, 204, 255, 0,  0,   51,  102};
        rtPixelStorei(RT_UNPACK_ALIGNMENT, 1);
        rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 3, 2, 0, RT_RGB, RT_UNSIGNED_BYTE, rgb);
        rtPixelStorei(RT_UNPACK_ALIGNMENT, 4);
        CHECK_NO_ERR();
        render(QUAD);
        /* Column i samples texel floor(3 (i + 0.5) / 16): 2 -> 0, 8 -> 1,
         * 13 -> 2; row 3 -> row 0, row 12 -> row 1. */
        CHECK_RGB(pixel(2, 3), 1, 0, 0);
        CHECK_RGB(pixel(8, 3), 0, 1, 0);
        CHECK_RGB(pixel(13, 3), 0, 0, 1);
        CHECK_RGB(pixel(2, 12), 0.2f, 0.4f, 0.6f);
        CHECK_RGB(pixel(8, 12), 0.8f, 1, 0);
        CHECK_RGB(pixel(13, 12), 0, 0.2f, 0.4f);
    }
    /* Component counts 3 and 4 as internalformat, RGBA data into RGB. */
    rtTexImage2D(RT_TEXTURE_2D, 0, 3, 2, 2, 0, RT_RGBA, RT_UNSIGNED_BYTE, image_2x2);
    CHECK_NO_ERR();
    render(QUAD);
    CHECK(quadrants_ok(texel_2x2));
    rtTexImage2D(RT_TEXTURE_2D, 0, 4, 2, 2, 0, RT_RGBA, RT_UNSIGNED_BYTE, image_2x2);
    CHECK_NO_ERR();
    render(QUAD);
    CHECK(quadrants_ok(texel_2x2));

    tu_section("RT_FLOAT uploads: clamped to [0, 1]");
    {
        float rgba[8] = {0.2f, 0.6f, 1.5f, 1, -1, 0, 0.4f, 0};
        rgba[5] = tu_nan(); /* taken as 0 */
        rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 2, 1, 0, RT_RGBA, RT_FLOAT, rgba);
        CHECK_NO_ERR();
        render(QUAD);
        CHECK_RGB(pixel(2, 8), 0.2f, 0.6f, 1);
        CHECK_RGB(pixel(13, 8), 0, 0, 0.4f);
    }
    {
        static const float rgb[3] = {0.2f, 0.4f, 0.6f};
        rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 1, 1, 0, RT_RGB, RT_FLOAT, rgb);
        CHECK_NO_ERR();
        render(QUAD);
        CHECK_RGB(pixel(2, 8), 0.2f, 0.4f, 0.6f);
        CHECK_RGB(pixel(13, 3), 0.2f, 0.4f, 0.6f);
    }
    tu_section("pixels NULL: a black image");
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 5, 3, 0, RT_RGBA, RT_UNSIGNED_BYTE, NULL);
    CHECK_NO_ERR();
    render(QUAD);
    CHECK_RGB(pixel(2, 8), 0, 0, 0);
    CHECK_RGB(pixel(13, 13), 0, 0, 0);
    /* A miss is still the clear colour, not black-textured. */
    CHECK_NO_ERR();
}

static void texture_lifetime(void)
{
    static const unsigned char green[4] = {0, 255, 0, 255};
    const RTuint tex = 50;
    tu_section("re-upload after rtEndObject changes later frames");
    tu_ortho_camera();
    plain_material();
    rtBindTexture(RT_TEXTURE_2D, tex);
    upload_2x2();
    set_filter(RT_NEAREST);
    rtEnable(RT_TEXTURE_2D);
    define_quad(QUAD, 0, 0, 1, 1);
    rtDisable(RT_TEXTURE_2D);
    render(QUAD);
    CHECK(quadrants_ok(texel_2x2));
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, green);
    render(QUAD);
    CHECK_RGB(pixel(2, 2), 0, 1, 0);
    CHECK_RGB(pixel(13, 13), 0, 1, 0);
    /* Also with another texture bound at the time. */
    rtBindTexture(RT_TEXTURE_2D, tex + 1);
    render(QUAD);
    CHECK_RGB(pixel(13, 13), 0, 1, 0);
    rtBindTexture(RT_TEXTURE_2D, tex);
    upload_2x2();
    render(QUAD);
    CHECK(quadrants_ok(texel_2x2));

    tu_section("deleted texture: untextured");
    rtDeleteTextures(1, &tex);
    render(QUAD);
    CHECK_RGB(pixel(2, 2), 1, 1, 1);
    CHECK_RGB(pixel(13, 13), 1, 1, 1);
    /* The name bound again is a new texture without an image: untextured. */
    rtBindTexture(RT_TEXTURE_2D, tex);
    render(QUAD);
    CHECK_RGB(pixel(13, 13), 1, 1, 1);
    /* Given an image, the recorded name shows it again. */
    set_filter(RT_NEAREST);
    upload_2x2();
    render(QUAD);
    CHECK(quadrants_ok(texel_2x2));
    CHECK_NO_ERR();

    tu_section("RT_TEXTURE_2D enabled with 0 bound: untextured");
    rtBindTexture(RT_TEXTURE_2D, 0);
    rtEnable(RT_TEXTURE_2D);
    define_quad(OTHER, 0, 0, 1, 1);
    rtDisable(RT_TEXTURE_2D);
    render(OTHER);
    CHECK_RGB(pixel(2, 2), 1, 1, 1);
    CHECK_NO_ERR();
}

/* Three vertical strips x in [-1, -1/3], [-1/3, 1/3], [1/3, 1] in one object. */
static void strip(float x0, float x1)
{
    rtBegin(RT_QUADS);
    rtTexCoord2f(0.5f, 0.5f);
    rtVertex3f(x0, -1, -5);
    rtVertex3f(x1, -1, -5);
    rtVertex3f(x1, 1, -5);
    rtVertex3f(x0, 1, -5);
    rtEnd();
}

static void recording(void)
{
    static const unsigned char red[4] = {255, 0, 0, 255}, blue[4] = {0, 0, 255, 255};
    const RTuint a = 60, b = 61;
    tu_section("binding and enable recorded per triangle");
    tu_ortho_camera();
    plain_material();
    rtBindTexture(RT_TEXTURE_2D, a);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, red);
    rtBindTexture(RT_TEXTURE_2D, b);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, blue);
    rtNewObject(QUAD);
    rtEnable(RT_TEXTURE_2D);
    rtBindTexture(RT_TEXTURE_2D, a);
    strip(-1, -1.0f / 3);
    rtBindTexture(RT_TEXTURE_2D, b);
    strip(-1.0f / 3, 1.0f / 3);
    rtDisable(RT_TEXTURE_2D);
    strip(1.0f / 3, 1);
    rtEndObject();
    CHECK_NO_ERR();
    render(QUAD);
    /* Columns 2, 8, 13 look at x = -0.6875, 0.0625, 0.6875. */
    CHECK_RGB(pixel(2, 8), 1, 0, 0);
    CHECK_RGB(pixel(8, 8), 0, 0, 1);
    CHECK_RGB(pixel(13, 8), 1, 1, 1);

    /* A material change keeps the texture; the same material with two
     * textures gives two recorded materials. */
    rtNewObject(QUAD);
    rtEnable(RT_TEXTURE_2D);
    rtBindTexture(RT_TEXTURE_2D, a);
    strip(-1, -1.0f / 3);
    {
        static const float half[4] = {0.5f, 0.5f, 0.5f, 1};
        rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, half);
    }
    strip(-1.0f / 3, 1.0f / 3);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, white);
    rtBindTexture(RT_TEXTURE_2D, b);
    strip(1.0f / 3, 1);
    rtDisable(RT_TEXTURE_2D);
    rtEndObject();
    render(QUAD);
    CHECK_RGB(pixel(2, 8), 1, 0, 0);
    CHECK_RGB(pixel(8, 8), 0.5f, 0, 0);
    CHECK_RGB(pixel(13, 8), 0, 0, 1);

    tu_section("a failed bind inside rtBegin keeps the block's texture");
    rtNewObject(QUAD);
    rtEnable(RT_TEXTURE_2D);
    rtBindTexture(RT_TEXTURE_2D, a);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(-1, -1, -5);
    rtVertex3f(1, -1, -5);
    rtBindTexture(RT_TEXTURE_2D, b);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtVertex3f(1, 1, -5);
    rtEnd();
    rtDisable(RT_TEXTURE_2D);
    rtEndObject();
    render(QUAD);
    CHECK_RGB(pixel(13, 2), 1, 0, 0);

    tu_section("texture coordinates from a vertex array");
    {
        static const float pos[12] = {-1, -1, -5, 1, -1, -5, 1, 1, -5, -1, 1, -5};
        static const float st[8] = {0, 0, 1, 0, 1, 1, 0, 1};
        static const double st_d[8] = {0, 0, 1, 0, 1, 1, 0, 1};
        static const unsigned char idx[6] = {0, 1, 2, 0, 2, 3};
        rtBindTexture(RT_TEXTURE_2D, a);
        upload_2x2();
        set_filter(RT_NEAREST);
        rtEnable(RT_TEXTURE_2D);
        rtEnableClientState(RT_VERTEX_ARRAY);
        rtEnableClientState(RT_TEXTURE_COORD_ARRAY);
        rtVertexPointer(3, RT_FLOAT, 0, pos);
        rtTexCoordPointer(2, RT_FLOAT, 0, st);
        rtNewObject(QUAD);
        rtDrawArrays(RT_QUADS, 0, 4);
        rtEndObject();
        render(QUAD);
        CHECK(quadrants_ok(texel_2x2));
        rtTexCoordPointer(2, RT_DOUBLE, 0, st_d);
        rtNewObject(QUAD);
        rtDrawElements(RT_TRIANGLES, 6, RT_UNSIGNED_BYTE, idx);
        rtEndObject();
        render(QUAD);
        CHECK(quadrants_ok(texel_2x2));
        rtDisableClientState(RT_VERTEX_ARRAY);
        rtDisableClientState(RT_TEXTURE_COORD_ARRAY);
        rtDisable(RT_TEXTURE_2D);
    }
    CHECK_NO_ERR();
}

static void modulate(void)
{
    const RTuint tex = 70;
    tu_section("MODULATE: ambient and diffuse times the texel");
    tu_ortho_camera();
    plain_material();
    rtBindTexture(RT_TEXTURE_2D, tex);
    upload_2x2();
    set_filter(RT_NEAREST);
    {
        /* 0.5 * 0.4 * texel (ambient) + 0.5 * texel (diffuse) + emission
         * (0, 0, 0.25) unmodulated: 0.7 * texel + (0, 0, 0.25). */
        static const float amb[4] = {0.4f, 0.4f, 0.4f, 1}, dif[4] = {0.5f, 0.5f, 0.5f, 1},
                           emi[4] = {0, 0, 0.25f, 1}, model[4] = {0.5f, 0.5f, 0.5f, 1};
        rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, amb);
        rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, dif);
        rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, emi);
        rtEnable(RT_TEXTURE_2D);
        define_quad(QUAD, 0, 0, 1, 1);
        rtDisable(RT_TEXTURE_2D);
        rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, model);
        render(QUAD);
        CHECK_RGB(pixel(2, 2), 0.7f, 0, 0.25f);
        CHECK_RGB(pixel(13, 2), 0, 0.7f, 0.25f);
        CHECK_RGB(pixel(13, 13), 0.7f, 0.7f, 0.14f + 0.25f);
        plain_material();
    }

    tu_section("MODULATE with RT_COLOR_MATERIAL");
    rtEnable(RT_COLOR_MATERIAL);
    rtEnable(RT_TEXTURE_2D);
    define_quad(QUAD, 0, 0, 1, 1);
    rtDisable(RT_TEXTURE_2D);
    /* The quad sets no colour and leaves RT_COLOR_MATERIAL alone: both
     * are the ones current at the call (GL's display lists). */
    rtColor3f(0.5f, 1, 0.25f);
    render(QUAD);
    rtColor3f(1, 1, 1);
    rtDisable(RT_COLOR_MATERIAL);
    CHECK(quadrants_scaled_ok(0.5f, 1, 0.25f));

    tu_section("MODULATE in Whitted shading");
    rtEnable(RT_TEXTURE_2D);
    define_quad(QUAD, 0, 0, 1, 1);
    rtDisable(RT_TEXTURE_2D);
    rtShadingMode(RT_WHITTED);
    rtEnable(RT_LIGHT0); /* white, directional from +z: N.L = 1 */
    render(QUAD);
    CHECK(quadrants_ok(texel_2x2));
    {
        /* Light ambient 0.5 adds 0.5 * ambient * texel: ambient 1 here. */
        static const float la[4] = {0.5f, 0.5f, 0.5f, 1};
        rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, white);
        rtEnable(RT_TEXTURE_2D);
        define_quad(QUAD, 0, 0, 1, 1);
        rtDisable(RT_TEXTURE_2D);
        rtLightfv(RT_LIGHT0, RT_AMBIENT, la);
        render(QUAD);
        CHECK(quadrants_scaled_ok(1.5f, 1.5f, 1.5f));
        rtLightfv(RT_LIGHT0, RT_AMBIENT, black);
        plain_material();
    }
    rtDisable(RT_LIGHT0);
    rtShadingMode(RT_EYE_LIGHT);
    CHECK_NO_ERR();
}

static void non_finite(void)
{
    const RTuint tex = 80;
    tu_section("NaN texture coordinates are rejected; huge ones render");
    tu_ortho_camera();
    plain_material();
    rtBindTexture(RT_TEXTURE_2D, tex);
    upload_2x2();
    set_filter(RT_LINEAR);
    rtEnable(RT_TEXTURE_2D);
    /* A rejected rtTexCoord2f leaves the current coordinate, (0.75, 0.75):
     * the centre of texel (1, 1) under LINEAR. */
    rtTexCoord2f(0.75f, 0.75f);
    rtTexCoord2f(tu_nan(), 0.5f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexCoord2f(0.5f, tu_inf());
    CHECK_ERR(RT_INVALID_VALUE);
    rtNewObject(QUAD);
    rtBegin(RT_QUADS);
    rtVertex3f(-1, -1, -5);
    rtVertex3f(1, -1, -5);
    rtVertex3f(1, 1, -5);
    rtVertex3f(-1, 1, -5);
    rtEnd();
    rtEndObject();
    render(QUAD);
    CHECK_RGB_APPROX(pixel(8, 8), 1, 1, 0.2f);
    /* Coordinates at the float limits: interpolation may overflow to
     * infinity or NaN; the renderer samples something valid. */
    define_quad(QUAD, -FLT_MAX, FLT_MAX, FLT_MAX, -FLT_MAX);
    render(QUAD);
    {
        int ok = 1;
        for (int i = 0; i < 4 * W * H; i++)
            ok &= px[i] >= 0.0f && px[i] <= 1.0f;
        CHECK(ok);
    }
    rtNewObject(QUAD);
    rtBegin(RT_TRIANGLES);
    rtTexCoord2f(FLT_MAX, FLT_MAX);
    rtVertex3f(-1, -1, -5);
    rtTexCoord2f(FLT_MAX, -FLT_MAX);
    rtVertex3f(3, -1, -5);
    rtTexCoord2f(-FLT_MAX, FLT_MAX);
    rtVertex3f(-1, 3, -5);
    rtEnd();
    rtEndObject();
    set_wrap(RT_CLAMP_TO_EDGE);
    render(QUAD);
    {
        int ok = 1;
        for (int i = 0; i < 4 * W * H; i++)
            ok &= px[i] >= 0.0f && px[i] <= 1.0f;
        CHECK(ok);
    }
    set_wrap(RT_REPEAT);
    rtTexCoord2f(0, 0);
    rtDisable(RT_TEXTURE_2D);
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    /* The expected colours are the eye light's (MODULATE on the material). */
    rtShadingMode(RT_EYE_LIGHT);
    names_and_binding();
    image_errors();
    nearest_and_linear();
    repeat_and_clamp();
    upload_formats();
    texture_lifetime();
    recording();
    modulate();
    non_finite();
    tu_destroy_context(ctx);
    return test_summary("textures");
}
