/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fixed_function.c - the RT_FIXED_FUNCTION shading mode and GL's
 * fixed-function state through the API (issue 10 item 3 and the fog,
 * texture environment and no-op names of item 4): the default mode and
 * its unlit colour, RT_LIGHTING recorded per primitive, one- and two-sided
 * lighting with back materials, face culling of camera rays (queries
 * unchanged), RT_NORMALIZE against GL's unnormalised transformed normal,
 * fog along the eye's z, the state queries, error messages that name the
 * enums, and the accepted no-ops.  The colours against Mesa are the
 * oracle's (gl_oracle/shade_oracle.c).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "testutil.h"

#define W 4
#define H 4
#define OBJ 1u

static float px[4 * W * H];

/* Renders object OBJ under the identity (ortho camera looking down -z). */
static void render_obj(void)
{
    rtBeginFrame();
    rtInstantiateObject(OBJ);
    tu_render_float(W, H, px);
}

static const float *pixel(int x, int y)
{
    return &px[4 * (y * W + x)];
}

#define CHECK_RGB(p, r, g, b)                                                                 \
    CHECKF(fabsf((p)[0] - (r)) < 2e-3f && fabsf((p)[1] - (g)) < 2e-3f &&                      \
               fabsf((p)[2] - (b)) < 2e-3f,                                                   \
           "pixel (%g, %g, %g), expected (%g, %g, %g)", (double)(p)[0], (double)(p)[1],      \
           (double)(p)[2], (double)(r), (double)(g), (double)(b))

/* A square over the whole view at z, its front (counter-clockwise side)
 * towards the camera or away from it. */
static void square(float z, int facing_camera)
{
    rtBegin(RT_QUADS);
    if (facing_camera) {
        rtVertex3f(-2, -2, z);
        rtVertex3f(2, -2, z);
        rtVertex3f(2, 2, z);
        rtVertex3f(-2, 2, z);
    } else {
        rtVertex3f(-2, -2, z);
        rtVertex3f(-2, 2, z);
        rtVertex3f(2, 2, z);
        rtVertex3f(2, -2, z);
    }
    rtEnd();
}

static void reset(void)
{
    static const float ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f}, diffuse[4] = {0.8f, 0.8f, 0.8f, 1};
    rtDeleteObjects(1, &(RTuint){OBJ});
    rtDisable(RT_LIGHTING);
    rtDisable(RT_CULL_FACE);
    rtDisable(RT_NORMALIZE);
    rtDisable(RT_FOG);
    rtCullFace(RT_BACK);
    rtFrontFace(RT_CCW);
    rtLightModeli(RT_LIGHT_MODEL_TWO_SIDE, 0);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, ambient);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, diffuse);
    rtColor4f(1, 1, 1, 1);
    rtNormal3f(0, 0, 1);
    rtEnable(RT_LIGHT0);
    tu_ortho_camera();
    CHECK_NO_ERR();
}

static void defaults(void)
{
    tu_section("defaults: GL's look, GL's state");
    RTint v[4];
    rtGetIntegerv(RT_SHADING_MODE, v);
    CHECK_INT(v[0], RT_FIXED_FUNCTION);
    CHECK(!rtIsEnabled(RT_LIGHTING));
    CHECK(!rtIsEnabled(RT_CULL_FACE));
    CHECK(!rtIsEnabled(RT_NORMALIZE));
    CHECK(!rtIsEnabled(RT_RESCALE_NORMAL));
    CHECK(!rtIsEnabled(RT_FOG));
    CHECK(!rtIsEnabled(RT_DEPTH_TEST));
    CHECK(rtIsEnabled(RT_DITHER));
    for (RTenum l = RT_LIGHT0; l <= RT_LIGHT7; l++)
        CHECK(!rtIsEnabled(l));
    rtGetIntegerv(RT_COLOR_MATERIAL_FACE, v);
    CHECK_INT(v[0], RT_FRONT_AND_BACK);
    rtGetIntegerv(RT_COLOR_MATERIAL_PARAMETER, v);
    CHECK_INT(v[0], RT_AMBIENT_AND_DIFFUSE);
    rtGetIntegerv(RT_CULL_FACE_MODE, v);
    CHECK_INT(v[0], RT_BACK);
    rtGetIntegerv(RT_FRONT_FACE, v);
    CHECK_INT(v[0], RT_CCW);
    rtGetIntegerv(RT_FOG_MODE, v);
    CHECK_INT(v[0], RT_EXP);
    float f[4];
    rtGetFloatv(RT_FOG_END, f);
    CHECK_NEAR(f[0], 1.0, 0);
    rtGetLightfv(RT_LIGHT0, RT_SPOT_CUTOFF, f);
    CHECK_NEAR(f[0], 180.0, 0);
    rtGetLightfv(RT_LIGHT3, RT_SPOT_DIRECTION, f);
    CHECK(f[0] == 0.0f && f[1] == 0.0f && f[2] == -1.0f);
    rtGetMaterialfv(RT_BACK, RT_DIFFUSE, f);
    CHECK_NEAR(f[0], 0.8, 1e-6);
    RTboolean b[4] = {RT_TRUE, RT_TRUE, RT_TRUE, RT_TRUE};
    rtGetBooleanv(RT_LIGHTING, b);
    CHECK(b[0] == RT_FALSE);
    rtGetBooleanv(RT_DITHER, b);
    CHECK(b[0] == RT_TRUE);
    CHECK_NO_ERR();
}

static void unlit_and_lit(void)
{
    tu_section("RT_LIGHTING disabled: the colour as is");
    reset();
    rtNewObject(OBJ);
    rtColor4f(0.25f, 0.5f, 0.75f, 1.0f);
    square(-5, 1);
    rtEndObject();
    render_obj();
    CHECK_RGB(pixel(1, 1), 0.25f, 0.5f, 0.75f);

    tu_section("RT_LIGHTING recorded per primitive");
    reset();
    rtNewObject(OBJ);
    rtEnable(RT_LIGHTING);
    rtBegin(RT_QUADS); /* left half: lit, 0.2 * 0.2 + 0.8 */
    rtVertex3f(-2, -2, -5);
    rtVertex3f(0, -2, -5);
    rtVertex3f(0, 2, -5);
    rtVertex3f(-2, 2, -5);
    rtEnd();
    rtDisable(RT_LIGHTING);
    rtColor3f(1, 0, 0);
    rtBegin(RT_QUADS); /* right half: unlit red */
    rtVertex3f(0, -2, -5);
    rtVertex3f(2, -2, -5);
    rtVertex3f(2, 2, -5);
    rtVertex3f(0, 2, -5);
    rtEnd();
    rtEndObject();
    CHECK(!rtIsEnabled(RT_LIGHTING));
    render_obj();
    CHECK_RGB(pixel(0, 1), 0.84f, 0.84f, 0.84f);
    CHECK_RGB(pixel(3, 1), 1, 0, 0);
    /* The eye light honours RT_LIGHTING too once the program has enabled
     * it (docs/appearance.md): the unlit half shows its colour. */
    rtShadingMode(RT_EYE_LIGHT);
    render_obj();
    CHECK_RGB(pixel(3, 1), 1, 0, 0);
    rtShadingMode(RT_FIXED_FUNCTION);
}

static void faces(void)
{
    static const float green[4] = {0.0f, 1.0f, 0.0f, 1.0f}, blue[4] = {0.0f, 0.0f, 0.5f, 1.0f};
    tu_section("one-sided lighting: a back face lit with the front material and normal");
    reset();
    rtNewObject(OBJ);
    rtEnable(RT_LIGHTING);
    rtMaterialfv(RT_BACK, RT_DIFFUSE, green);
    rtMaterialfv(RT_BACK, RT_AMBIENT, blue);
    rtNormal3f(0, 0, 1); /* towards the camera and the light */
    square(-5, 0);
    rtEndObject();
    render_obj();
    CHECK_RGB(pixel(1, 1), 0.84f, 0.84f, 0.84f);
    tu_section("two-sided lighting: the back material and the reversed normal");
    rtLightModeli(RT_LIGHT_MODEL_TWO_SIDE, 1);
    render_obj();
    /* The reversed normal faces away from the light: ambient only,
     * 0.2 * (0, 0, 0.5). */
    CHECK_RGB(pixel(1, 1), 0.0f, 0.0f, 0.1f);
    rtNormal3f(0, 0, -1);
    rtNewObject(OBJ);
    square(-5, 0);
    rtEndObject();
    render_obj();
    CHECK_RGB(pixel(1, 1), 0.0f, 1.0f, 0.1f);
    float f[4];
    rtGetMaterialfv(RT_BACK, RT_DIFFUSE, f);
    CHECK(f[1] == 1.0f && f[0] == 0.0f);
    rtGetMaterialfv(RT_FRONT, RT_DIFFUSE, f);
    CHECK_NEAR(f[0], 0.8, 1e-6);

    tu_section("RT_CULL_FACE: camera rays pass culled faces, queries do not");
    reset();
    rtNewObject(OBJ);
    rtEnable(RT_CULL_FACE);
    square(-5, 0); /* a back face, culled */
    rtColor3f(1, 0, 0);
    square(-8, 1); /* a front face behind it */
    rtEndObject();
    render_obj();
    CHECK_RGB(pixel(1, 1), 1, 0, 0);
    RThit hit = tu_trace(0.1f, 0.2f, 0.0f, 0.0f, 0.0f, -1.0f);
    CHECK_NEAR(hit.t, 5.0, 1e-5);
    rtCullFace(RT_FRONT_AND_BACK);
    CHECK(rtIsEnabled(RT_CULL_FACE)); /* the call executed the list's rtEnable */
    /* The list enables culling but sets no rtCullFace: its geometry takes
     * the mode current at the call, as glCallList (until 25814ff the mode
     * at recording counted, which is not GL): both faces culled. */
    render_obj();
    CHECK_RGB(pixel(1, 1), 0, 0, 0);
    rtCullFace(RT_BACK);
    render_obj();
    CHECK_RGB(pixel(1, 1), 1, 0, 0);
    rtCullFace(RT_FRONT_AND_BACK);
    rtNewObject(OBJ);
    square(-5, 0);
    square(-8, 1);
    rtEndObject();
    render_obj();
    CHECK_RGB(pixel(1, 1), 0, 0, 0); /* both culled: the clear colour */
    rtCullFace(RT_BACK);
    rtFrontFace(RT_CW);
    rtNewObject(OBJ);
    rtColor3f(0, 1, 0);
    square(-5, 1); /* now a back face */
    rtColor3f(0, 0, 1);
    square(-8, 0); /* now a front face */
    rtEndObject();
    render_obj();
    CHECK_RGB(pixel(1, 1), 0, 0, 1);
    CHECK_NO_ERR();
}

static void normalize(void)
{
    static const float dim[4] = {0.2f, 0.2f, 0.2f, 1.0f};
    tu_section("RT_NORMALIZE: GL lights with the transformed, unnormalised normal");
    reset();
    rtNewObject(OBJ);
    rtEnable(RT_LIGHTING);
    rtMaterialfv(RT_FRONT, RT_DIFFUSE, dim);
    square(-5, 1);
    rtEndObject();
    rtBeginFrame();
    rtScalef(0.5f, 0.5f, 0.5f); /* the normal doubles under the inverse transpose */
    rtInstantiateObject(OBJ);
    rtLoadIdentity();
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(2, 2), 0.44f, 0.44f, 0.44f); /* 0.04 + 0.2 * 2 */
    rtEnable(RT_NORMALIZE);
    rtNewObject(OBJ);
    rtEnable(RT_LIGHTING);
    square(-5, 1);
    rtEndObject();
    rtBeginFrame();
    rtScalef(0.5f, 0.5f, 0.5f);
    rtInstantiateObject(OBJ);
    rtLoadIdentity();
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(2, 2), 0.24f, 0.24f, 0.24f); /* 0.04 + 0.2 * 1 */
    CHECK_NO_ERR();
}

static void fog(void)
{
    static const float black[4] = {0, 0, 0, 1};
    tu_section("fog: coordinate |z| in eye space");
    reset();
    rtNewObject(OBJ);
    square(-5, 1);
    rtEndObject();
    rtEnable(RT_FOG);
    rtFogi(RT_FOG_MODE, RT_LINEAR);
    rtFogf(RT_FOG_START, 0.0f);
    rtFogf(RT_FOG_END, 10.0f);
    rtFogfv(RT_FOG_COLOR, black);
    render_obj();
    CHECK_RGB(pixel(1, 2), 0.5f, 0.5f, 0.5f);
    rtFogi(RT_FOG_MODE, RT_EXP);
    rtFogf(RT_FOG_DENSITY, 0.1f);
    render_obj();
    float e = expf(-0.5f);
    CHECK_RGB(pixel(1, 2), e, e, e);
    rtFogi(RT_FOG_MODE, RT_EXP2);
    render_obj();
    e = expf(-0.25f);
    CHECK_RGB(pixel(1, 2), e, e, e);
    rtDisable(RT_FOG);
    render_obj();
    CHECK_RGB(pixel(1, 2), 1, 1, 1);
    CHECK_NO_ERR();
}

/* The last error message contains `text`. */
static int message_has(const char *text)
{
    const char *m = tu_captured_message();
    int ok = m && strstr(m, text) != NULL;
    if (!ok)
        fprintf(stderr, "    message \"%s\" lacks \"%s\"\n", m ? m : "(none)", text);
    return ok;
}

static void errors(void)
{
    tu_section("errors name the enums");
    rtEnable(RT_TRIANGLES);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK(message_has("rtEnable(cap=RT_TRIANGLES)"));
    rtIsEnabled(0x7777);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK(message_has("0x7777"));
    rtCullFace(RT_CW);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK(message_has("RT_CW"));
    rtFrontFace(RT_BACK);
    CHECK_ERR(RT_INVALID_ENUM);
    rtColorMaterial(RT_FRONT, RT_SHININESS);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK(message_has("RT_SHININESS"));
    rtLightf(RT_LIGHT0, RT_SPOT_CUTOFF, 95.0f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtLightf(RT_LIGHT0, RT_SPOT_EXPONENT, 129.0f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtLightf(RT_LIGHT0 + 8, RT_SPOT_EXPONENT, 1.0f);
    CHECK_ERR(RT_INVALID_ENUM);
    rtLightModelf(RT_LIGHT_MODEL_AMBIENT, 1.0f);
    CHECK_ERR(RT_INVALID_ENUM);
    rtFogi(RT_FOG_MODE, RT_NEAREST);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK(message_has("RT_NEAREST"));
    rtFogf(RT_FOG_DENSITY, -1.0f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexEnvi(RT_TEXTURE_ENV, RT_TEXTURE_ENV_MODE, 0x0104 /* GL_ADD: GL 1.3, not taken */);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexEnvi(RT_TEXTURE_2D, RT_TEXTURE_ENV_MODE, RT_MODULATE);
    CHECK_ERR(RT_INVALID_ENUM);
    rtShadingMode(RT_LIGHTING);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK(message_has("RT_LIGHTING"));
    tu_begin_scratch(RT_TRIANGLES);
    rtEnable(RT_LIGHTING);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtCullFace(RT_FRONT);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    CHECK_NO_ERR();

    tu_section("spot direction under the modelview; light model");
    rtPushMatrix();
    rtRotatef(90.0f, 1, 0, 0);
    rtLightfv(RT_LIGHT2, RT_SPOT_DIRECTION, (const float[3]){0, 0, -1});
    rtPopMatrix();
    float f[4];
    rtGetLightfv(RT_LIGHT2, RT_SPOT_DIRECTION, f);
    CHECK(fabsf(f[0]) < 1e-6f && fabsf(f[1] - 1.0f) < 1e-6f && fabsf(f[2]) < 1e-6f);
    rtLightModeli(RT_LIGHT_MODEL_LOCAL_VIEWER, 1);
    RTint v = 0;
    rtGetIntegerv(RT_LIGHT_MODEL_LOCAL_VIEWER, &v);
    CHECK_INT(v, 1);
    rtLightModelf(RT_LIGHT_MODEL_LOCAL_VIEWER, 0.0f);
    rtGetIntegerv(RT_LIGHT_MODEL_LOCAL_VIEWER, &v);
    CHECK_INT(v, 0);
    CHECK_NO_ERR();
}

static void no_ops(void)
{
    tu_section("accepted no-ops");
    rtHint(RT_PERSPECTIVE_CORRECTION_HINT, RT_NICEST);
    rtHint(RT_FOG_HINT, RT_DONT_CARE);
    rtDrawBuffer(RT_BACK);
    rtReadBuffer(RT_FRONT);
    rtDepthFunc(RT_LEQUAL);
    rtDepthRange(0.0, 1.0);
    rtClearDepth(1.0);
    rtPolygonOffset(1.0f, 1.0f);
    rtLockArraysEXT(0, 3);
    rtUnlockArraysEXT();
    rtEnable(RT_DEPTH_TEST);
    CHECK(rtIsEnabled(RT_DEPTH_TEST));
    rtDisable(RT_DITHER);
    CHECK(!rtIsEnabled(RT_DITHER));
    rtEnable(RT_POLYGON_OFFSET_FILL);
    CHECK_NO_ERR();
    rtHint(RT_NICEST, RT_NICEST);
    CHECK_ERR(RT_INVALID_ENUM);
    rtHint(RT_FOG_HINT, RT_FOG);
    CHECK_ERR(RT_INVALID_ENUM);
    rtDepthFunc(RT_FOG);
    CHECK_ERR(RT_INVALID_ENUM);
    rtDrawBuffer(RT_FOG);
    CHECK_ERR(RT_INVALID_ENUM);
    rtReadBuffer(RT_NONE);
    CHECK_ERR(RT_INVALID_ENUM);
    rtLockArraysEXT(0, 0);
    CHECK_ERR(RT_INVALID_VALUE);
}

static void interleaved(void)
{
    tu_section("rtInterleavedArrays: RT_C4UB_V3F and RT_T2F_C4F_N3F_V3F");
    struct {
        unsigned char c[4];
        float v[3];
    } ub[4] = {{{64, 128, 255, 255}, {-2, -2, -5}},
               {{64, 128, 255, 255}, {2, -2, -5}},
               {{64, 128, 255, 255}, {2, 2, -5}},
               {{64, 128, 255, 255}, {-2, 2, -5}}};
    CHECK_INT(sizeof ub[0], 16); /* the format's own stride: c = 4 bytes */
    reset();
    rtInterleavedArrays(RT_C4UB_V3F, 0, ub);
    rtNewObject(OBJ);
    rtDrawArrays(RT_QUADS, 0, 4);
    rtEndObject();
    render_obj();
    CHECK_RGB(pixel(1, 1), 64.0f / 255.0f, 128.0f / 255.0f, 1.0f);
    /* t2 c4 n3 v3, lit: the colour through RT_COLOR_MATERIAL, the normal
     * (0, 0, 1) from the array, towards the light. */
    float big[4][12];
    for (int i = 0; i < 4; i++) {
        const float t[12] = {0, 0, 0.5f, 0.25f, 1.0f, 1.0f, 0, 0, 1,
                             ub[i].v[0], ub[i].v[1], ub[i].v[2]};
        memcpy(big[i], t, sizeof t);
    }
    rtInterleavedArrays(RT_T2F_C4F_N3F_V3F, 0, big);
    rtNewObject(OBJ);
    rtEnable(RT_LIGHTING);
    rtEnable(RT_COLOR_MATERIAL);
    rtDrawArrays(RT_QUADS, 0, 4);
    rtDisable(RT_COLOR_MATERIAL);
    rtEndObject();
    render_obj();
    /* 0.2 * 0.5 + 0.5 (red); 0.2 * 0.25 + 0.25 (green); blue clamped. */
    CHECK_RGB(pixel(1, 1), 0.6f, 0.3f, 1.0f);
    /* t4 c4 n3 v4: the same quad with homogeneous vertices (w = 2, the
     * coordinates doubled) and q = 1: the same colour. */
    float t4[4][15];
    for (int i = 0; i < 4; i++) {
        const float t[15] = {0, 0, 0, 1, 0.5f, 0.25f, 1.0f, 1.0f, 0, 0, 1,
                             2 * ub[i].v[0], 2 * ub[i].v[1], 2 * ub[i].v[2], 2};
        memcpy(t4[i], t, sizeof t);
    }
    rtInterleavedArrays(RT_T4F_C4F_N3F_V4F, 0, t4);
    CHECK_ERR(RT_NO_ERROR);
    rtNewObject(OBJ);
    rtEnable(RT_LIGHTING);
    rtEnable(RT_COLOR_MATERIAL);
    rtDrawArrays(RT_QUADS, 0, 4);
    rtDisable(RT_COLOR_MATERIAL);
    rtEndObject();
    render_obj();
    CHECK_RGB(pixel(1, 1), 0.6f, 0.3f, 1.0f);
    rtInterleavedArrays(RT_T4F_V4F, 0, t4);
    CHECK_ERR(RT_NO_ERROR);
    rtInterleavedArrays(RT_FLOAT, 0, big);
    CHECK_ERR(RT_INVALID_ENUM);
    rtInterleavedArrays(RT_V3F, -4, big);
    CHECK_ERR(RT_INVALID_VALUE);
    rtDisableClientState(RT_VERTEX_ARRAY);
    rtDisableClientState(RT_COLOR_ARRAY);
    rtDisableClientState(RT_NORMAL_ARRAY);
    rtDisableClientState(RT_TEXTURE_COORD_ARRAY);
    CHECK_NO_ERR();
}

static void texgen(void)
{
    tu_section("rtTexGen: object-linear s, recorded per primitive");
    static const unsigned char texels[8] = {255, 0, 0, 255, 0, 255, 0, 255}; /* red, green */
    static const float s_plane[4] = {0.25f, 0.0f, 0.0f, 0.5f}; /* x = -2 .. 2 -> s = 0 .. 1 */
    RTuint tex = 0;
    reset();
    rtGenTextures(1, &tex);
    rtBindTexture(RT_TEXTURE_2D, tex);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_NEAREST);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_NEAREST);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 2, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, texels);
    rtTexCoord2f(0.0f, 0.0f);
    rtTexGeni(RT_S, RT_TEXTURE_GEN_MODE, RT_OBJECT_LINEAR);
    rtTexGenfv(RT_S, RT_OBJECT_PLANE, s_plane);
    rtEnable(RT_TEXTURE_GEN_S);
    CHECK(rtIsEnabled(RT_TEXTURE_GEN_S) && !rtIsEnabled(RT_TEXTURE_GEN_T));
    rtEnable(RT_TEXTURE_2D);
    rtNewObject(OBJ);
    square(-5, 1);
    rtEndObject();
    render_obj();
    CHECK_RGB(pixel(0, 1), 1, 0, 0);
    CHECK_RGB(pixel(3, 1), 0, 1, 0);
    /* The object sets no texture generation: the call's applies, as GL's
     * list geometry takes the state at glCallList (until 25814ff the
     * state at recording did).  Without it, the recorded s = 0. */
    rtDisable(RT_TEXTURE_GEN_S);
    render_obj();
    CHECK_RGB(pixel(3, 1), 1, 0, 0);
    rtNewObject(OBJ); /* recorded without generation, called with it */
    square(-5, 1);
    rtEndObject();
    rtEnable(RT_TEXTURE_GEN_S);
    render_obj();
    CHECK_RGB(pixel(3, 1), 0, 1, 0);
    rtDisable(RT_TEXTURE_GEN_S);
    /* Immediate mode: the state at the draw, per primitive. */
    rtBeginFrame();
    rtEnable(RT_TEXTURE_GEN_S);
    square(-5, 1);
    rtDisable(RT_TEXTURE_GEN_S);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(3, 1), 0, 1, 0);
    rtDisable(RT_TEXTURE_2D);
    rtDeleteTextures(1, &tex);
    CHECK_NO_ERR();
    rtTexGenf(RT_S, RT_OBJECT_PLANE, 1.0f);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexGeni(RT_T, RT_TEXTURE_GEN_MODE, RT_LINEAR);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexGenfv(RT_T, RT_EYE_PLANE, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
}

/* After reset(): a 2 x 1 texture, red then green (nearest), bound and
 * enabled; object-linear s = `s` everywhere; OBJ the square at z = -5.
 * Returns the texture for rtDeleteTextures. */
static RTuint red_green_square(float s)
{
    static const unsigned char texels[8] = {255, 0, 0, 255, 0, 255, 0, 255};
    const float s_plane[4] = {0.0f, 0.0f, 0.0f, s};
    RTuint tex = 0;
    reset();
    rtGenTextures(1, &tex);
    rtBindTexture(RT_TEXTURE_2D, tex);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_NEAREST);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_NEAREST);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 2, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, texels);
    rtEnable(RT_TEXTURE_2D);
    rtTexGeni(RT_S, RT_TEXTURE_GEN_MODE, RT_OBJECT_LINEAR);
    rtTexGenfv(RT_S, RT_OBJECT_PLANE, s_plane);
    rtEnable(RT_TEXTURE_GEN_S);
    rtNewObject(OBJ);
    square(-5, 1);
    rtEndObject();
    return tex;
}

/* rtTexGen(RT_Q): GL divides the generated (or recorded) s and t by the
 * interpolated q per fragment.  s = 0.375 everywhere (red texel) becomes
 * s / q = 0.75 (green) with q generated as 0.5, object- or eye-linear;
 * the sphere map is refused for q, as Mesa refuses it. */
static void texgen_q(void)
{
    tu_section("rtTexGen(RT_Q): object- and eye-linear q divide s and t");
    static const float q_plane[4] = {0.0f, 0.0f, 0.0f, 0.5f};
    const RTuint tex = red_green_square(0.375f);
    render_obj();
    CHECK_RGB(pixel(1, 1), 1, 0, 0); /* q = 1 */
    CHECK(!rtIsEnabled(RT_TEXTURE_GEN_Q));
    rtTexGeni(RT_Q, RT_TEXTURE_GEN_MODE, RT_OBJECT_LINEAR);
    rtTexGenfv(RT_Q, RT_OBJECT_PLANE, q_plane);
    rtEnable(RT_TEXTURE_GEN_Q);
    CHECK_NO_ERR();
    CHECK(rtIsEnabled(RT_TEXTURE_GEN_Q));
    render_obj(); /* the object takes the generation at the call */
    CHECK_RGB(pixel(1, 1), 0, 1, 0);
    CHECK_RGB(pixel(3, 3), 0, 1, 0);
    /* Eye-linear: the plane through the modelview's inverse at the call
     * (a translation leaves the constant term). */
    rtTexGeni(RT_Q, RT_TEXTURE_GEN_MODE, RT_EYE_LINEAR);
    rtTranslatef(0.0f, 0.0f, -3.0f);
    rtTexGenfv(RT_Q, RT_EYE_PLANE, q_plane);
    rtLoadIdentity();
    render_obj();
    CHECK_RGB(pixel(1, 1), 0, 1, 0);
    /* q from the z of the eye position: -z / 10 = 0.5 at z = -5. */
    static const float q_depth[4] = {0.0f, 0.0f, -0.1f, 0.0f};
    rtTexGenfv(RT_Q, RT_EYE_PLANE, q_depth);
    render_obj();
    CHECK_RGB(pixel(2, 2), 0, 1, 0);
    rtDisable(RT_TEXTURE_GEN_Q);
    render_obj();
    CHECK_RGB(pixel(1, 1), 1, 0, 0);
    /* The attribute stack keeps q's enable and mode (the object plane
     * q = 1 would draw red). */
    static const float q_one[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    rtTexGenfv(RT_Q, RT_OBJECT_PLANE, q_one);
    rtEnable(RT_TEXTURE_GEN_Q);
    rtPushAttrib(RT_ENABLE_BIT | RT_TEXTURE_BIT);
    rtDisable(RT_TEXTURE_GEN_Q);
    rtTexGeni(RT_Q, RT_TEXTURE_GEN_MODE, RT_OBJECT_LINEAR);
    rtPopAttrib();
    CHECK(rtIsEnabled(RT_TEXTURE_GEN_Q));
    render_obj(); /* eye-linear q again */
    CHECK_RGB(pixel(2, 2), 0, 1, 0);
    rtDisable(RT_TEXTURE_GEN_Q);
    rtDisable(RT_TEXTURE_GEN_S);
    rtDisable(RT_TEXTURE_2D);
    rtDeleteTextures(1, &tex);
    CHECK_NO_ERR();
    rtTexGeni(RT_Q, RT_TEXTURE_GEN_MODE, RT_SPHERE_MAP);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK(message_has("RT_Q"));
}

/* rtTexGen(RT_R): GL keeps r's generation (mode, planes, enable) as it
 * keeps s's, and a 2D texture never reads r (GL 1.1 sec. 3.8), so a
 * program that sets it up (for a 3D or cube-map texture GL 1.x programs
 * fall back from) draws as without it; the sphere map is refused for r,
 * as Mesa refuses it. */
static void texgen_r(void)
{
    tu_section("rtTexGen(RT_R): kept, enabled, stacked; a 2D texture does not read r");
    static const float r_plane[4] = {0.3f, -0.2f, 0.1f, 0.5f};
    const RTuint tex = red_green_square(0.75f);
    render_obj();
    CHECK_RGB(pixel(1, 1), 0, 1, 0);
    CHECK(!rtIsEnabled(RT_TEXTURE_GEN_R));
    rtTexGeni(RT_R, RT_TEXTURE_GEN_MODE, RT_OBJECT_LINEAR);
    rtTexGenfv(RT_R, RT_OBJECT_PLANE, r_plane);
    rtTexGeni(RT_R, RT_TEXTURE_GEN_MODE, RT_EYE_LINEAR);
    rtTexGenfv(RT_R, RT_EYE_PLANE, r_plane);
    rtEnable(RT_TEXTURE_GEN_R);
    CHECK_NO_ERR();
    CHECK(rtIsEnabled(RT_TEXTURE_GEN_R));
    render_obj();
    CHECK_RGB(pixel(1, 1), 0, 1, 0);
    CHECK_RGB(pixel(3, 3), 0, 1, 0);
    /* Recorded in a list, and kept by the attribute stack. */
    rtDisable(RT_TEXTURE_GEN_R);
    rtNewObject(OBJ + 1);
    rtEnable(RT_TEXTURE_GEN_R);
    rtEndObject();
    CHECK(!rtIsEnabled(RT_TEXTURE_GEN_R));
    rtPushAttrib(RT_ENABLE_BIT);
    rtInstantiateObject(OBJ + 1);
    CHECK(rtIsEnabled(RT_TEXTURE_GEN_R));
    rtPopAttrib();
    CHECK(!rtIsEnabled(RT_TEXTURE_GEN_R));
    rtDeleteObjects(1, &(RTuint){OBJ + 1});
    rtDisable(RT_TEXTURE_GEN_S);
    rtDisable(RT_TEXTURE_2D);
    rtDeleteTextures(1, &tex);
    CHECK_NO_ERR();
    rtTexGeni(RT_R, RT_TEXTURE_GEN_MODE, RT_SPHERE_MAP);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK(message_has("RT_R"));
    rtTexGeni(RT_TEXTURE_GEN_R, RT_TEXTURE_GEN_MODE, RT_EYE_LINEAR);
    CHECK_ERR(RT_INVALID_ENUM);
}

static void whitted_spot(void)
{
    tu_section("Whitted: spot lights cut the light's terms outside the cone");
    static const float at_eye[4] = {0, 0, 0, 1}, down[3] = {0, 0, -1};
    reset();
    rtNewObject(OBJ);
    /* Lit: this context has used RT_LIGHTING, which Whitted then honours. */
    rtEnable(RT_LIGHTING);
    square(-5, 1);
    rtDisable(RT_LIGHTING);
    rtEndObject();
    rtLightfv(RT_LIGHT0, RT_POSITION, at_eye);
    rtLightfv(RT_LIGHT0, RT_SPOT_DIRECTION, down);
    rtShadingMode(RT_WHITTED);
    render_obj();
    float centre = pixel(2, 2)[0], corner = pixel(3, 3)[0];
    CHECKF(centre > 0.8f && corner > 0.8f, "no spot: %g %g", (double)centre, (double)corner);
    rtLightf(RT_LIGHT0, RT_SPOT_CUTOFF, 10.0f); /* the corner pixel is 12 degrees off */
    render_obj();
    CHECKF(fabsf(pixel(2, 2)[0] - centre) < 1e-6f, "inside the cone: %g", (double)pixel(2, 2)[0]);
    CHECK_RGB(pixel(3, 3), 0.04f, 0.04f, 0.04f);
    rtLightf(RT_LIGHT0, RT_SPOT_CUTOFF, 180.0f);
    rtShadingMode(RT_FIXED_FUNCTION);
    static const float sky[4] = {0, 0, 1, 0};
    rtLightfv(RT_LIGHT0, RT_POSITION, sky);
    CHECK_NO_ERR();
}

/* rtTexCoord4*: GL's current (s, t, r, q), kept through lists. */
static void texcoord4(void)
{
    tu_section("rtTexCoord4: the current (s, t, r, q)");
    RTfloat v[4];
    reset();
    rtTexCoord4f(1, 2, 3, 4);
    rtGetFloatv(RT_CURRENT_TEXTURE_COORDS, v);
    CHECK(v[0] == 1 && v[1] == 2 && v[2] == 3 && v[3] == 4);
    rtTexCoord2f(5, 6); /* GL: r = 0, q = 1 */
    rtGetFloatv(RT_CURRENT_TEXTURE_COORDS, v);
    CHECK(v[0] == 5 && v[1] == 6 && v[2] == 0 && v[3] == 1);
    const RTdouble d[4] = {0.5, 0.25, 0, 2};
    const RTint iv[4] = {1, 2, 0, 3};
    const RTshort sv[4] = {4, 5, 0, 6};
    rtTexCoord4dv(d);
    rtGetFloatv(RT_CURRENT_TEXTURE_COORDS, v);
    CHECK(v[0] == 0.5f && v[1] == 0.25f && v[3] == 2);
    rtTexCoord4iv(iv);
    rtGetFloatv(RT_CURRENT_TEXTURE_COORDS, v);
    CHECK(v[0] == 1 && v[1] == 2 && v[3] == 3);
    rtTexCoord4sv(sv);
    rtGetFloatv(RT_CURRENT_TEXTURE_COORDS, v);
    CHECK(v[0] == 4 && v[1] == 5 && v[3] == 6);
    rtTexCoord4i(7, 8, 9, 10);
    rtTexCoord4s(1, 1, 1, 1);
    rtTexCoord4d(2, 2, 2, 2);
    rtGetFloatv(RT_CURRENT_TEXTURE_COORDS, v);
    CHECK(v[0] == 2 && v[3] == 2);
    CHECK_NO_ERR();
    rtTexCoord4fv(NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexCoord4f(0, 0, 0, NAN);
    CHECK_ERR(RT_INVALID_VALUE);
    /* Compiled (RT_COMPILE leaves the current value), replayed at the call. */
    rtTexCoord2f(0, 0);
    rtNewObject(OBJ);
    rtTexCoord4f(1, 2, 3, 4);
    rtEndObject();
    rtGetFloatv(RT_CURRENT_TEXTURE_COORDS, v);
    CHECK(v[0] == 0 && v[3] == 1);
    rtBeginFrame();
    rtInstantiateObject(OBJ);
    rtGetFloatv(RT_CURRENT_TEXTURE_COORDS, v);
    CHECK(v[0] == 1 && v[1] == 2 && v[2] == 3 && v[3] == 4);
    rtTexCoord2f(0, 0);
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    defaults();
    unlit_and_lit();
    faces();
    normalize();
    fog();
    errors();
    no_ops();
    interleaved();
    texcoord4();
    texgen();
    texgen_q();
    texgen_r();
    whitted_spot();
    tu_destroy_context(ctx);
    return test_summary("fixed_function");
}
