/* SPDX-License-Identifier: Apache-2.0 */
/*
 * gl_state.c - GL's fixed-function state per primitive and in display
 * lists (issue 10, docs/lists.md "State in lists"): fog, culling, the
 * front face and the light model change between two objects of one frame
 * and each object is drawn with the state current at its draw; the state
 * calls compiled into a list under RT_COMPILE leave the context as it was
 * and take effect at rtCallList, under RT_COMPILE_AND_EXECUTE at once; a
 * list's geometry without its own rtShadeModel / rtBindTexture takes the
 * call's.  Every section fails against 25814ff, which took fog and the
 * light model at the end of the frame, culling, the front face, the shade
 * model and the texture at the recording, and neither recorded rtCullFace,
 * rtFrontFace, rtColorMaterial, rtTexEnv, rtTexGen and rtFog in lists nor
 * restored them after RT_COMPILE.  gl_oracle/shading's "per_primitive"
 * scenes compare the same against Mesa.
 */
#include <math.h>
#include <string.h>

#include "testutil.h"

#define W 4
#define H 4
#define LEFT 1u
#define RIGHT 2u
#define L3 3u

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

/* A square at depth z over x in [x0, x0 + 1] (the ortho camera sees
 * [-1, 1]), counter-clockwise seen from the camera when facing. */
static void square(float x0, float z, int facing_camera)
{
    rtBegin(RT_QUADS);
    rtTexCoord2f(0.5f, 0.5f);
    if (facing_camera) {
        rtVertex3f(x0, -1, z);
        rtVertex3f(x0 + 1, -1, z);
        rtVertex3f(x0 + 1, 1, z);
        rtVertex3f(x0, 1, z);
    } else {
        rtVertex3f(x0, -1, z);
        rtVertex3f(x0, 1, z);
        rtVertex3f(x0 + 1, 1, z);
        rtVertex3f(x0 + 1, -1, z);
    }
    rtEnd();
}

static void reset_state(void)
{
    static const float zero[4] = {0, 0, 0, 1};
    rtDisable(RT_LIGHTING);
    rtDisable(RT_CULL_FACE);
    rtDisable(RT_FOG);
    rtDisable(RT_TEXTURE_2D);
    rtDisable(RT_TEXTURE_GEN_S);
    rtCullFace(RT_BACK);
    rtFrontFace(RT_CCW);
    rtShadeModel(RT_SMOOTH);
    rtLightModeli(RT_LIGHT_MODEL_TWO_SIDE, 0);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, zero);
    rtTexEnvi(RT_TEXTURE_ENV, RT_TEXTURE_ENV_MODE, RT_MODULATE);
    rtColorMaterial(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE);
    rtFogi(RT_FOG_MODE, RT_LINEAR);
    rtFogf(RT_FOG_START, 0.0f);
    rtFogf(RT_FOG_END, 10.0f);
    rtFogfv(RT_FOG_COLOR, (const float[4]){0, 0, 1, 1});
    rtColor4f(1, 1, 1, 1);
    rtNormal3f(0, 0, 1);
    rtEnable(RT_LIGHT0);
    tu_ortho_camera();
    CHECK_NO_ERR();
}

static void reset(void)
{
    RTuint names[3] = {LEFT, RIGHT, L3};
    rtDeleteObjects(3, names);
    reset_state();
}

/* Objects LEFT (x in [-1, 0]) and RIGHT (x in [0, 1]), unlit white
 * squares at z = -5 facing the camera (or facing away). */
static void two_objects(int facing_camera)
{
    rtNewObject(LEFT);
    square(-1, -5, facing_camera);
    rtEndObject();
    rtNewObject(RIGHT);
    square(0, -5, facing_camera);
    rtEndObject();
}

static void fog_between_objects(void)
{
    tu_section("fog: enabled between two objects of one frame");
    reset();
    two_objects(1);
    rtBeginFrame();
    rtInstantiateObject(LEFT);
    rtEnable(RT_FOG); /* f = (10 - 5) / 10 = 0.5 towards blue */
    rtInstantiateObject(RIGHT);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 1, 1, 1);
    CHECK_RGB(pixel(3, 1), 0.5f, 0.5f, 1);
    /* The same in immediate mode, with the parameters changed between. */
    rtBeginFrame();
    square(-1, -5, 1);
    rtFogf(RT_FOG_END, 5.0f); /* f = 0: the fog colour */
    square(0, -5, 1);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 0.5f, 0.5f, 1);
    CHECK_RGB(pixel(3, 1), 0, 0, 1);
    CHECK_NO_ERR();
}

static void cull_between_objects(void)
{
    tu_section("culling and the front face: per call of an object");
    reset();
    two_objects(0); /* back faces, recorded with culling off */
    rtBeginFrame();
    rtInstantiateObject(LEFT);
    rtEnable(RT_CULL_FACE);
    rtInstantiateObject(RIGHT); /* culled: the background */
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 1, 1, 1);
    CHECK_RGB(pixel(3, 1), 0, 0, 0);
    /* rtFrontFace(RT_CW) around one call, as around glutSolidTeapot. */
    rtBeginFrame();
    rtInstantiateObject(LEFT); /* culled */
    rtFrontFace(RT_CW);
    rtInstantiateObject(RIGHT); /* its front now */
    rtFrontFace(RT_CCW);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 0, 0, 0);
    CHECK_RGB(pixel(3, 1), 1, 1, 1);
    /* rtCullFace(RT_FRONT) at the call. */
    rtDisable(RT_CULL_FACE);
    two_objects(1);
    rtEnable(RT_CULL_FACE);
    rtBeginFrame();
    rtInstantiateObject(LEFT);
    rtCullFace(RT_FRONT);
    rtInstantiateObject(RIGHT);
    rtCullFace(RT_BACK);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 1, 1, 1);
    CHECK_RGB(pixel(3, 1), 0, 0, 0);
    CHECK_NO_ERR();
}

static void two_side_between_objects(void)
{
    tu_section("two-sided lighting: per call of an object");
    static const float red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1}, zero[4] = {0, 0, 0, 1};
    reset();
    rtEnable(RT_LIGHTING);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, zero);
    rtMaterialfv(RT_FRONT, RT_DIFFUSE, red);
    rtMaterialfv(RT_BACK, RT_DIFFUSE, green);
    two_objects(0); /* back faces, normal (0, 0, 1) towards the light */
    rtBeginFrame();
    rtInstantiateObject(LEFT); /* one-sided: the front material, lit */
    rtLightModeli(RT_LIGHT_MODEL_TWO_SIDE, 1);
    rtInstantiateObject(RIGHT); /* the back material, reversed normal: dark */
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 1, 0, 0);
    CHECK_RGB(pixel(3, 1), 0, 0, 0);
    /* The global ambient likewise. */
    rtLightModeli(RT_LIGHT_MODEL_TWO_SIDE, 0);
    rtDisable(RT_LIGHT0);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, green);
    two_objects(1);
    rtBeginFrame();
    rtInstantiateObject(LEFT);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, (const float[4]){0.5f, 0.5f, 0.5f, 1});
    rtInstantiateObject(RIGHT);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 0, 0, 0);
    CHECK_RGB(pixel(3, 1), 0, 0.5f, 0);
    rtEnable(RT_LIGHT0);
    CHECK_NO_ERR();
}

static void color_material_at_call(void)
{
    tu_section("rtColorMaterial: the mode at the call for a list that sets none");
    static const float zero[4] = {0, 0, 0, 1};
    reset();
    rtEnable(RT_LIGHTING);
    rtDisable(RT_LIGHT0); /* unlit but for emission and the global ambient (0) */
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, zero);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, zero);
    rtEnable(RT_COLOR_MATERIAL);
    rtColor3f(1, 0, 0);
    two_objects(1);
    rtBeginFrame();
    rtInstantiateObject(LEFT); /* red ambient and diffuse: black */
    rtColorMaterial(RT_FRONT_AND_BACK, RT_EMISSION);
    rtInstantiateObject(RIGHT); /* red emission */
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 0, 0, 0);
    CHECK_RGB(pixel(3, 1), 1, 0, 0);
    rtColorMaterial(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE);
    rtDisable(RT_COLOR_MATERIAL);
    rtEnable(RT_LIGHT0);
    CHECK_NO_ERR();
}

/* A list that sets its own colour and the RT_COLOR_MATERIAL enable, then
 * disables it (writing the colour into the material) and draws: the
 * properties written are those rtColorMaterial names at the call (GL
 * 2.1 sec. 2.14.3 writes with the mode current then), not at the
 * recording.  Each call writes the properties its caller names, so one
 * list gives an unlit square (ambient and diffuse written, no light) and
 * a red one (emission written). */
static void color_material_list_own_colour(void)
{
    tu_section("rtColorMaterial: a list with its own colour and enable writes the call's mode");
    static const float zero[4] = {0, 0, 0, 1};
    reset();
    rtEnable(RT_LIGHTING);
    rtDisable(RT_LIGHT0);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, zero);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, zero);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, zero);
    rtNewList(L3, RT_COMPILE); /* recorded under AMBIENT_AND_DIFFUSE */
    rtColor3f(1, 0, 0);
    rtEnable(RT_COLOR_MATERIAL);
    rtDisable(RT_COLOR_MATERIAL);
    square(0, -5, 1);
    rtEndList();
    rtBeginFrame();
    rtColorMaterial(RT_FRONT_AND_BACK, RT_EMISSION);
    rtCallList(L3); /* red emission */
    CHECK(rtIsEnabled(RT_COLOR_MATERIAL) == RT_FALSE);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, zero);
    rtColorMaterial(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE);
    rtTranslatef(-1, 0, 0);
    rtCallList(L3); /* red ambient and diffuse, no light: black */
    rtLoadIdentity();
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(3, 1), 1, 0, 0);
    CHECK_RGB(pixel(0, 1), 0, 0, 0);
    /* The same list naming rtColorMaterial itself writes its own mode. */
    rtNewList(L3, RT_COMPILE);
    rtColor3f(0, 1, 0);
    rtColorMaterial(RT_FRONT_AND_BACK, RT_EMISSION);
    rtEnable(RT_COLOR_MATERIAL);
    rtDisable(RT_COLOR_MATERIAL);
    square(0, -5, 1);
    rtEndList();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, zero);
    rtColorMaterial(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE);
    rtBeginFrame();
    rtCallList(L3);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(3, 1), 0, 1, 0);
    rtColorMaterial(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, zero);
    rtEnable(RT_LIGHT0);
    rtDisable(RT_LIGHTING);
    CHECK_NO_ERR();
}

static RTint get_int(RTenum pname)
{
    RTint v[4] = {0, 0, 0, 0};
    rtGetIntegerv(pname, v);
    return v[0];
}

static float get_float(RTenum pname)
{
    RTfloat v[4] = {0, 0, 0, 0};
    rtGetFloatv(pname, v);
    return v[0];
}

/* Compiles list L3 with `calls` under `mode`. */
static void compile(RTenum mode, void (*calls)(void))
{
    rtNewList(L3, mode);
    calls();
    rtEndList();
}

static void set_state(void)
{
    rtCullFace(RT_FRONT);
    rtFrontFace(RT_CW);
    rtColorMaterial(RT_BACK, RT_EMISSION);
    rtEnable(RT_CULL_FACE);
    rtEnable(RT_FOG);
    rtFogf(RT_FOG_DENSITY, 0.25f);
    rtFogi(RT_FOG_MODE, RT_EXP2);
    rtFogfv(RT_FOG_COLOR, (const float[4]){1, 0, 0, 1});
    rtLightModeli(RT_LIGHT_MODEL_LOCAL_VIEWER, 1);
    rtEnable(RT_TEXTURE_GEN_S);
}

static int state_is_set(void)
{
    RTfloat c[4];
    rtGetFloatv(RT_FOG_COLOR, c);
    return get_int(RT_CULL_FACE_MODE) == RT_FRONT && get_int(RT_FRONT_FACE) == RT_CW &&
           get_int(RT_COLOR_MATERIAL_FACE) == RT_BACK &&
           get_int(RT_COLOR_MATERIAL_PARAMETER) == RT_EMISSION && rtIsEnabled(RT_CULL_FACE) &&
           rtIsEnabled(RT_FOG) && get_float(RT_FOG_DENSITY) == 0.25f &&
           get_int(RT_FOG_MODE) == RT_EXP2 && c[0] == 1.0f && c[2] == 0.0f &&
           get_int(RT_LIGHT_MODEL_LOCAL_VIEWER) == 1 && rtIsEnabled(RT_TEXTURE_GEN_S);
}

static int state_is_reset(void)
{
    RTfloat c[4];
    rtGetFloatv(RT_FOG_COLOR, c);
    return get_int(RT_CULL_FACE_MODE) == RT_BACK && get_int(RT_FRONT_FACE) == RT_CCW &&
           get_int(RT_COLOR_MATERIAL_FACE) == RT_FRONT_AND_BACK &&
           get_int(RT_COLOR_MATERIAL_PARAMETER) == RT_AMBIENT_AND_DIFFUSE &&
           !rtIsEnabled(RT_CULL_FACE) && !rtIsEnabled(RT_FOG) &&
           get_float(RT_FOG_DENSITY) == 1.0f && get_int(RT_FOG_MODE) == RT_LINEAR &&
           c[0] == 0.0f && c[2] == 1.0f && get_int(RT_LIGHT_MODEL_LOCAL_VIEWER) == 0 &&
           !rtIsEnabled(RT_TEXTURE_GEN_S);
}

static void lists_compile(void)
{
    tu_section("state calls in lists: RT_COMPILE leaves the context, rtCallList applies");
    reset();
    rtFogf(RT_FOG_DENSITY, 1.0f);
    rtLightModeli(RT_LIGHT_MODEL_LOCAL_VIEWER, 0);
    CHECK(state_is_reset());
    compile(RT_COMPILE, set_state);
    CHECK(state_is_reset());
    rtCallList(L3);
    CHECK(state_is_set());
    CHECK_NO_ERR();

    tu_section("state calls in lists: RT_COMPILE_AND_EXECUTE applies at once");
    reset();
    rtFogf(RT_FOG_DENSITY, 1.0f);
    rtLightModeli(RT_LIGHT_MODEL_LOCAL_VIEWER, 0);
    compile(RT_COMPILE_AND_EXECUTE, set_state);
    CHECK(state_is_set());
    reset_state();
    rtFogf(RT_FOG_DENSITY, 1.0f);
    rtLightModeli(RT_LIGHT_MODEL_LOCAL_VIEWER, 0);
    CHECK(state_is_reset());
    rtCallList(L3); /* recorded too */
    CHECK(state_is_set());
    rtDisable(RT_TEXTURE_GEN_S);
    rtLightModeli(RT_LIGHT_MODEL_LOCAL_VIEWER, 0);
    CHECK_NO_ERR();
}

/* A list that fogs its own geometry: the square before the rtFog is
 * drawn as the state at the call, the square after it fogged. */
static void fogged_right(void)
{
    square(-1, -5, 1);
    rtEnable(RT_FOG);
    rtFogf(RT_FOG_END, 5.0f);
    square(0, -5, 1);
}

static void lists_fog_render(void)
{
    tu_section("rtFog in a list: its later geometry fogged, at the call");
    reset();
    compile(RT_COMPILE, fogged_right);
    CHECK(!rtIsEnabled(RT_FOG) && get_float(RT_FOG_END) == 10.0f);
    rtBeginFrame();
    rtCallList(L3);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 1, 1, 1);
    CHECK_RGB(pixel(3, 1), 0, 0, 1);
    CHECK(rtIsEnabled(RT_FOG) && get_float(RT_FOG_END) == 5.0f);
    /* RT_COMPILE_AND_EXECUTE draws it at once the same way. */
    reset();
    rtBeginFrame();
    compile(RT_COMPILE_AND_EXECUTE, fogged_right);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 1, 1, 1);
    CHECK_RGB(pixel(3, 1), 0, 0, 1);
    CHECK_NO_ERR();
}

static void tex_env_replace(void)
{
    rtTexEnvi(RT_TEXTURE_ENV, RT_TEXTURE_ENV_MODE, RT_REPLACE);
}

static void lists_tex_env_render(void)
{
    tu_section("rtTexEnv in a list: not at RT_COMPILE, at the call");
    static const unsigned char green[4] = {0, 255, 0, 128};
    RTuint tex = 0;
    reset();
    rtGenTextures(1, &tex);
    rtBindTexture(RT_TEXTURE_2D, tex);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_NEAREST);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, 1, 1, 0, RT_RGBA, RT_UNSIGNED_BYTE, green);
    rtEnable(RT_TEXTURE_2D);
    rtColor4f(0.5f, 0.5f, 0.5f, 1);
    compile(RT_COMPILE, tex_env_replace);
    rtBeginFrame();
    square(-1, -5, 1); /* MODULATE: (0, 0.5, 0) */
    rtCallList(L3);
    square(0, -5, 1); /* REPLACE: (0, 1, 0) */
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 0, 0.5f, 0);
    CHECK_RGB(pixel(3, 1), 0, 1, 0);

    tu_section("the texture and the shade model: a list's geometry takes the call's");
    rtTexEnvi(RT_TEXTURE_ENV, RT_TEXTURE_ENV_MODE, RT_MODULATE);
    rtColor4f(1, 1, 1, 1);
    rtDisable(RT_TEXTURE_2D);
    rtBindTexture(RT_TEXTURE_2D, 0);
    two_objects(1); /* recorded untextured */
    rtBindTexture(RT_TEXTURE_2D, tex);
    rtBeginFrame();
    rtInstantiateObject(LEFT);
    rtEnable(RT_TEXTURE_2D);
    rtInstantiateObject(RIGHT);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 1, 1, 1);
    CHECK_RGB(pixel(3, 1), 0, 1, 0);
    /* A list that binds its own texture keeps it: texture 0 (none). */
    rtNewObject(RIGHT);
    rtBindTexture(RT_TEXTURE_2D, 0);
    square(0, -5, 1);
    rtEndObject();
    CHECK_INT(get_int(RT_TEXTURE_BINDING_2D), (RTint)tex);
    rtBeginFrame();
    rtInstantiateObject(RIGHT);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(3, 1), 1, 1, 1);
    /* A list that binds its texture and leaves RT_TEXTURE_2D to the caller
     * (compiled with it disabled): textured exactly when called with it
     * enabled. */
    rtDisable(RT_TEXTURE_2D);
    rtNewObject(RIGHT);
    rtBindTexture(RT_TEXTURE_2D, tex);
    square(0, -5, 1);
    rtEndObject();
    rtEnable(RT_TEXTURE_2D);
    rtBeginFrame();
    rtInstantiateObject(RIGHT);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(3, 1), 0, 1, 0);
    rtDisable(RT_TEXTURE_2D);
    rtBeginFrame();
    rtInstantiateObject(RIGHT);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(3, 1), 1, 1, 1);
    rtDeleteTextures(1, &tex);

    /* One triangle over the view, red, green and blue at its corners;
     * GL's provoking vertex of RT_TRIANGLES is the last (blue). */
    rtNewObject(LEFT);
    rtBegin(RT_TRIANGLES);
    rtColor3f(1, 0, 0);
    rtVertex3f(-3, -3, -5);
    rtColor3f(0, 1, 0);
    rtVertex3f(5, -3, -5);
    rtColor3f(0, 0, 1);
    rtVertex3f(-3, 5, -5);
    rtEnd();
    rtEndObject();
    rtShadeModel(RT_FLAT);
    rtBeginFrame();
    rtInstantiateObject(LEFT);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 0), 0, 0, 1);
    CHECK_RGB(pixel(3, 3), 0, 0, 1);
    rtShadeModel(RT_SMOOTH);
    rtBeginFrame();
    rtInstantiateObject(LEFT);
    tu_render_float(W, H, px);
    CHECKF(pixel(0, 0)[0] > 0.3f, "smooth: red %g", (double)pixel(0, 0)[0]);
    /* The list's own rtShadeModel wins over the call's. */
    rtNewObject(RIGHT);
    rtShadeModel(RT_SMOOTH);
    rtCallList(LEFT);
    rtEndObject();
    rtShadeModel(RT_FLAT);
    rtBeginFrame();
    rtInstantiateObject(RIGHT);
    tu_render_float(W, H, px);
    CHECKF(pixel(0, 0)[0] > 0.3f, "the list's smooth: red %g", (double)pixel(0, 0)[0]);
    CHECK_INT(get_int(RT_SHADE_MODEL), RT_SMOOTH); /* the list left it */
    rtShadeModel(RT_SMOOTH);
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    fog_between_objects();
    cull_between_objects();
    two_side_between_objects();
    color_material_at_call();
    color_material_list_own_colour();
    lists_compile();
    lists_fog_render();
    lists_tex_env_render();
    tu_destroy_context(ctx);
    return test_summary("gl_state");
}
