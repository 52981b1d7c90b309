/* SPDX-License-Identifier: Apache-2.0 */
/*
 * lists.c - conformance: GL display-list semantics and immediate mode.
 *
 * Recording independent of the modelview at compile time; recorded
 * matrix calls and their effect on the caller (relative, absolute,
 * unbalanced push and pop, stack errors at call time); recorded state
 * and where it is after the call; call-time material and colour
 * inheritance with two instances that differ; nested calls by name and
 * redefinition; the nesting limit; rtCallLists with every type and
 * rtListBase; RT_COMPILE_AND_EXECUTE; the GL-named entry points' errors
 * and queries; immediate-mode frames (unchanged, moved, new topology);
 * rtClear and the render rtReadPixels does for a described frame.
 *
 * Reference: docs/lists.md.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define W 16
#define H 16

static float px[W * H * 4];

static RTint geti(RTenum pname)
{
    RTint v = -12345;
    rtGetIntegerv(pname, &v);
    return v;
}

static double modelview(int k)
{
    float m[16];
    rtGetFloatv(RT_MODELVIEW_MATRIX, m);
    return m[k];
}

/* A unit quad [0,1]^2 at z = 0, no state of its own. */
static void quad(void)
{
    rtBegin(RT_QUADS);
    rtVertex3f(0, 0, 0);
    rtVertex3f(1, 0, 0);
    rtVertex3f(1, 1, 0);
    rtVertex3f(0, 1, 0);
    rtEnd();
}

/* Distance along -z from (x, y, 10) to the first hit, or -1. */
static float hit_t(float x, float y)
{
    RTray r = tu_ray(x, y, 10, 0, 0, -1);
    RThit h;
    rtTraceRays(1, &r, &h);
    return h.primitive == RT_INVALID_ID ? -1.0f : h.t;
}

static void compile_independent(void)
{
    tu_section("vertices do not depend on the modelview at rtNewList");
    rtLoadIdentity();
    rtTranslatef(0, 0, -5); /* a "view" matrix current while compiling */
    rtNewList(1, RT_COMPILE);
    quad();
    rtEndList();
    CHECK_NO_ERR();
    /* GL_COMPILE executes nothing: the matrix is still the view. */
    CHECK_NEAR(modelview(14), -5, 0);
    rtBeginFrame();
    rtCallList(1); /* under the view: z = -5, once */
    rtLoadIdentity();
    CHECK_NEAR(hit_t(0.5f, 0.5f), 15, 1e-5);
}

static void matrix_side_effects(void)
{
    tu_section("recorded matrix calls act on the caller");
    rtNewList(2, RT_COMPILE);
    rtTranslatef(1, 0, 0);
    rtEndList();
    CHECK_NEAR(modelview(12), 0, 0);
    rtCallList(2);
    rtCallList(2);
    CHECK_NEAR(modelview(12), 2, 0);
    /* Absolute: the caller's matrix does not matter afterwards. */
    rtNewList(3, RT_COMPILE);
    rtLoadIdentity();
    rtTranslatef(0, 0, -3);
    rtEndList();
    rtLoadIdentity();
    rtTranslatef(7, 7, 7);
    rtCallList(3);
    CHECK_NEAR(modelview(12), 0, 0);
    CHECK_NEAR(modelview(14), -3, 0);
    /* Geometry after an absolute load ignores the caller's matrix, the
     * geometry before it follows it. */
    rtNewList(4, RT_COMPILE);
    quad(); /* relative: at z = 0 under the caller's matrix */
    {
        static const double at[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 3, 0, -4, 1};
        rtLoadMatrixd(at);
    }
    quad(); /* absolute: x in [3, 4], z = -4 */
    rtEndList();
    rtLoadIdentity();
    rtBeginFrame();
    rtTranslatef(0, 0, -2);
    rtCallList(4);
    rtLoadIdentity();
    CHECK_NEAR(hit_t(0.5f, 0.5f), 12, 1e-5);
    CHECK_NEAR(hit_t(3.5f, 0.5f), 14, 1e-5);
    /* Unbalanced push and pop change the caller's depth. */
    rtNewList(5, RT_COMPILE);
    rtPushMatrix();
    rtTranslatef(0, 1, 0);
    rtEndList();
    rtNewList(6, RT_COMPILE);
    rtPopMatrix();
    rtEndList();
    CHECK_NO_ERR(); /* stack errors happen at call time */
    rtLoadIdentity();
    CHECK_INT(geti(RT_MODELVIEW_STACK_DEPTH), 1);
    rtCallList(5);
    CHECK_INT(geti(RT_MODELVIEW_STACK_DEPTH), 2);
    CHECK_NEAR(modelview(13), 1, 0);
    rtCallList(6);
    CHECK_INT(geti(RT_MODELVIEW_STACK_DEPTH), 1);
    CHECK_NEAR(modelview(13), 0, 0);
    CHECK_NO_ERR();
    rtCallList(6);
    CHECK_ERR(RT_STACK_UNDERFLOW);
    CHECK_INT(geti(RT_MODELVIEW_STACK_DEPTH), 1);
    for (int i = 1; i < geti(RT_MAX_MODELVIEW_STACK_DEPTH); i++)
        rtCallList(5);
    CHECK_NO_ERR();
    rtCallList(5);
    CHECK_ERR(RT_STACK_OVERFLOW);
    while (geti(RT_MODELVIEW_STACK_DEPTH) > 1)
        rtPopMatrix();
    rtLoadIdentity();
    /* A pop inside the list back to a level it pushed keeps its geometry
     * relative: one segment, placed by the caller's matrix. */
    rtNewList(7, RT_COMPILE);
    rtPushMatrix();
    rtTranslatef(0, 0, -1);
    quad();
    rtPopMatrix();
    quad();
    rtEndList();
    rtBeginFrame();
    rtTranslatef(5, 0, 0);
    rtCallList(7);
    rtLoadIdentity();
    CHECK_INT(geti(RT_INSTANCE_COUNT), 1);
    CHECK_NEAR(hit_t(5.5f, 0.5f), 10, 1e-5);
    CHECK_NO_ERR();
}

static void state_side_effects(void)
{
    tu_section("recorded state applies to the list and stays after the call");
    CHECK_INT(geti(RT_SHADE_MODEL), RT_SMOOTH);
    rtNewList(10, RT_COMPILE);
    rtShadeModel(RT_FLAT);
    rtEnable(RT_COLOR_MATERIAL);
    rtEnable(RT_LIGHT0 + 3);
    rtListBase(40);
    rtEndList();
    /* Compiled, not executed. */
    CHECK_INT(geti(RT_SHADE_MODEL), RT_SMOOTH);
    CHECK(rtIsEnabled(RT_COLOR_MATERIAL) == RT_FALSE);
    CHECK(rtIsEnabled(RT_LIGHT0 + 3) == RT_FALSE);
    CHECK_INT(geti(RT_LIST_BASE), 0);
    rtCallList(10);
    CHECK_INT(geti(RT_SHADE_MODEL), RT_FLAT);
    CHECK(rtIsEnabled(RT_COLOR_MATERIAL) == RT_TRUE);
    CHECK(rtIsEnabled(RT_LIGHT0 + 3) == RT_TRUE);
    CHECK_INT(geti(RT_LIST_BASE), 40);
    rtShadeModel(RT_SMOOTH);
    rtDisable(RT_COLOR_MATERIAL);
    rtDisable(RT_LIGHT0 + 3);
    rtListBase(0);
    CHECK_NO_ERR();
}

static const float *pixel(int i, int j)
{
    return px + 4 * (j * W + i);
}

static void inheritance(void)
{
    static const float red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1}, blue[4] = {0, 0, 1, 1};
    tu_section("material and colour current at the call; two instances differ");
    tu_ortho_camera();
    rtShadingMode(RT_EYE_LIGHT);
    rtClearColor(0, 0, 0, 0);
    /* A list with no material of its own. */
    rtNewList(20, RT_COMPILE);
    rtBegin(RT_QUADS);
    rtVertex3f(-1, -1, -5);
    rtVertex3f(0, -1, -5);
    rtVertex3f(0, 1, -5);
    rtVertex3f(-1, 1, -5);
    rtEnd();
    rtEndList();
    rtBeginFrame();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, red);
    rtCallList(20);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, green);
    rtTranslatef(1, 0, 0);
    rtCallList(20);
    rtLoadIdentity();
    tu_render_float(W, H, px);
    CHECK(pixel(3, 8)[0] > 0.5f && pixel(3, 8)[1] < 0.1f);
    CHECK(pixel(12, 8)[1] > 0.5f && pixel(12, 8)[0] < 0.1f);
    /* A list that sets its own diffuse keeps it whatever the caller's. */
    rtNewList(21, RT_COMPILE);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, blue);
    rtBegin(RT_QUADS);
    rtVertex3f(-1, -1, -5);
    rtVertex3f(1, -1, -5);
    rtVertex3f(1, 1, -5);
    rtVertex3f(-1, 1, -5);
    rtEnd();
    rtEndList();
    rtBeginFrame();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, red);
    rtCallList(21);
    tu_render_float(W, H, px);
    CHECK(pixel(8, 8)[2] > 0.5f && pixel(8, 8)[0] < 0.1f);
    /* ... and leaves it current after the call, as GL. */
    rtBeginFrame();
    rtCallList(20);
    tu_render_float(W, H, px);
    CHECK(pixel(3, 8)[2] > 0.5f && pixel(3, 8)[0] < 0.1f);
    /* Colour with RT_COLOR_MATERIAL: the caller's current colour. */
    rtEnable(RT_COLOR_MATERIAL);
    rtBeginFrame();
    rtColor3f(1, 0, 0);
    rtCallList(20);
    rtColor3f(0, 1, 0);
    rtTranslatef(1, 0, 0);
    rtCallList(20);
    rtLoadIdentity();
    rtColor3f(1, 1, 1);
    rtDisable(RT_COLOR_MATERIAL);
    tu_render_float(W, H, px);
    CHECK(pixel(3, 8)[0] > 0.5f && pixel(3, 8)[1] < 0.1f);
    CHECK(pixel(12, 8)[1] > 0.5f && pixel(12, 8)[0] < 0.1f);
    {
        static const float grey[4] = {0.8f, 0.8f, 0.8f, 1}, amb[4] = {0.2f, 0.2f, 0.2f, 1};
        rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, grey);
        rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, amb);
    }
    CHECK_NO_ERR();
}

static void nested(void)
{
    tu_section("nested calls by name; redefinition shows in the caller");
    rtLoadIdentity();
    rtNewList(31, RT_COMPILE);
    rtTranslatef(2, 0, 0);
    rtCallList(30); /* not defined yet: by name */
    rtEndList();
    rtNewList(30, RT_COMPILE);
    quad();
    rtEndList();
    rtBeginFrame();
    rtCallList(31);
    rtLoadIdentity();
    CHECK_NEAR(hit_t(2.5f, 0.5f), 10, 1e-5);
    CHECK_NEAR(hit_t(0.5f, 0.5f), -1, 0);
    rtNewList(30, RT_COMPILE); /* redefined: moved up by 5 */
    rtTranslatef(0, 5, 0);
    quad();
    rtEndList();
    rtBeginFrame();
    rtCallList(31);
    CHECK_NEAR(modelview(12), 2, 0);
    CHECK_NEAR(modelview(13), 5, 0);
    rtLoadIdentity();
    CHECK_NEAR(hit_t(2.5f, 0.5f), -1, 0);
    CHECK_NEAR(hit_t(2.5f, 5.5f), 10, 1e-5);
    /* A call of an undefined name does nothing and is no error. */
    rtCallList(999);
    CHECK_NO_ERR();

    tu_section("nesting limit 64; a list calling itself ends there");
    CHECK_INT(geti(RT_MAX_LIST_NESTING), 64);
    for (RTuint k = 0; k < 100; k++) {
        rtNewList(1000 + k, RT_COMPILE);
        rtTranslatef(1, 0, 0);
        rtCallList(1001 + k);
        rtEndList();
    }
    rtLoadIdentity();
    rtCallList(1000);
    CHECK_NEAR(modelview(12), 64, 0);
    rtNewList(33, RT_COMPILE);
    rtTranslatef(1, 0, 0);
    rtCallList(33);
    rtEndList();
    rtLoadIdentity();
    rtCallList(33);
    CHECK_NEAR(modelview(12), 64, 0);
    rtLoadIdentity();
    CHECK_NO_ERR();
}

static void call_lists(void)
{
    tu_section("rtCallLists with every type, rtListBase");
    /* List 50 + k translates x by 10^k. */
    for (int k = 0; k < 3; k++) {
        rtNewList(50 + (RTuint)k, RT_COMPILE);
        rtTranslatef((float)pow(10, k), 0, 0);
        rtEndList();
    }
    rtListBase(50);
    CHECK_INT(geti(RT_LIST_BASE), 50);
    static const signed char b[3] = {0, 1, 2};
    static const unsigned char ub[3] = {0, 1, 2};
    static const short s[3] = {0, 1, 2};
    static const unsigned short us[3] = {0, 1, 2};
    static const int i[3] = {0, 1, 2};
    static const unsigned int ui[3] = {0, 1, 2};
    static const float f[3] = {0, 1, 2};
    static const unsigned char b2[6] = {0, 0, 0, 1, 0, 2};
    static const unsigned char b3[9] = {0, 0, 0, 0, 0, 1, 0, 0, 2};
    static const unsigned char b4[12] = {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 2};
    const struct {
        RTenum type;
        const void *ids;
    } cases[] = {{RT_BYTE, b},           {RT_UNSIGNED_BYTE, ub}, {RT_SHORT, s},
                 {RT_UNSIGNED_SHORT, us}, {RT_INT, i},            {RT_UNSIGNED_INT, ui},
                 {RT_FLOAT, f},           {RT_2_BYTES, b2},       {RT_3_BYTES, b3},
                 {RT_4_BYTES, b4}};
    for (size_t c = 0; c < sizeof(cases) / sizeof(cases[0]); c++) {
        rtLoadIdentity();
        rtCallLists(3, cases[c].type, cases[c].ids);
        if (!CHECK_NEAR(modelview(12), 111, 0))
            fprintf(stderr, "    type 0x%x\n", cases[c].type);
    }
    /* Big-endian byte groups: {1, 0} is list base + 256, not defined. */
    {
        static const unsigned char hi[2] = {1, 0};
        rtLoadIdentity();
        rtCallLists(1, RT_2_BYTES, hi);
        CHECK_NEAR(modelview(12), 0, 0);
    }
    rtCallLists(1, RT_DOUBLE, f);
    CHECK_ERR(RT_INVALID_ENUM);
    rtCallLists(-1, RT_INT, i);
    CHECK_ERR(RT_INVALID_VALUE);
    rtCallLists(3, RT_INT, NULL);
    CHECK_NO_ERR();
    /* Recorded rtCallLists adds the base current at call time. */
    rtNewList(60, RT_COMPILE);
    rtCallLists(1, RT_INT, &i[2]);
    rtEndList();
    rtListBase(49);
    rtLoadIdentity();
    rtCallList(60); /* 49 + 2: list 51 */
    CHECK_NEAR(modelview(12), 10, 0);
    rtListBase(0);
    rtLoadIdentity();
    CHECK_NO_ERR();
}

static void entry_points(void)
{
    tu_section("rtNewList, rtEndList, rtGenLists, rtDeleteLists, rtIsList: errors, queries");
    rtNewList(0, RT_COMPILE);
    CHECK_ERR(RT_INVALID_VALUE);
    rtNewList(70, 0x1302);
    CHECK_ERR(RT_INVALID_ENUM);
    rtEndList();
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK_INT(geti(RT_LIST_INDEX), 0);
    CHECK_INT(geti(RT_LIST_MODE), 0);
    rtNewList(70, RT_COMPILE);
    CHECK_INT(geti(RT_LIST_INDEX), 70);
    CHECK_INT(geti(RT_LIST_MODE), RT_COMPILE);
    rtNewList(71, RT_COMPILE);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEndList();
    CHECK_NO_ERR();
    CHECK(rtIsList(70) == RT_TRUE);
    CHECK(rtIsObject(70) == RT_TRUE);
    CHECK(rtIsList(71) == RT_FALSE);
    RTuint base = rtGenLists(5);
    CHECK(base != 0);
    for (RTuint k = 0; k < 5; k++)
        CHECK(rtIsList(base + k) == RT_TRUE); /* reserved: empty lists (Mesa) */
    CHECK_INT((RTint)rtGenLists(0), 0);
    CHECK_INT((RTint)rtGenLists(-1), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    RTuint next = rtGenLists(3);
    CHECK(next >= base + 5 || next + 3 <= base);
    rtDeleteLists(base, 5);
    for (RTuint k = 0; k < 5; k++)
        CHECK(rtIsList(base + k) == RT_FALSE);
    rtDeleteLists(1, -1);
    CHECK_ERR(RT_INVALID_VALUE);
    rtDeleteLists(next, 3);
    rtDeleteLists(70, 1);
    CHECK(rtIsList(70) == RT_FALSE);
    rtBegin(RT_TRIANGLES);
    rtNewList(72, RT_COMPILE);
    CHECK_ERR(RT_INVALID_OPERATION);
    /* GL allows glCallList between glBegin and glEnd (list_raster.c);
     * list 70 no longer exists: nothing happens. */
    rtCallList(70);
    CHECK_ERR(RT_NO_ERROR);
    rtEnd();
    CHECK_NO_ERR();
}

static void compile_and_execute(void)
{
    tu_section("RT_COMPILE_AND_EXECUTE");
    rtLoadIdentity();
    rtBeginFrame();
    rtNewList(80, RT_COMPILE_AND_EXECUTE);
    CHECK_INT(geti(RT_LIST_MODE), RT_COMPILE_AND_EXECUTE);
    rtTranslatef(3, 0, 0);
    CHECK_NEAR(modelview(12), 3, 0); /* executed at once */
    rtShadeModel(RT_FLAT);
    quad();
    rtEndList();
    CHECK_NO_ERR();
    CHECK_INT(geti(RT_SHADE_MODEL), RT_FLAT); /* kept */
    CHECK_INT(geti(RT_INSTANCE_COUNT), 1);    /* drawn now */
    rtLoadIdentity();
    CHECK_NEAR(hit_t(3.5f, 0.5f), 10, 1e-5);
    /* And compiled: called again, it translates once more. */
    rtCallList(80);
    CHECK_NEAR(modelview(12), 3, 0);
    rtShadeModel(RT_SMOOTH);
    rtLoadIdentity();
    CHECK_NO_ERR();
}

/* A grid of n x n quads in [-1, 1]^2 at z = -5 + dz, drawn in immediate
 * mode; `split` adds one more quad (a new topology). */
static void draw_grid(int n, float dz, int split)
{
    rtBegin(RT_TRIANGLES);
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            float x0 = -1 + 2.0f * i / n, x1 = -1 + 2.0f * (i + 1) / n;
            float y0 = -1 + 2.0f * j / n, y1 = -1 + 2.0f * (j + 1) / n;
            float z = -5 + dz * (float)((i + j) % 2);
            rtVertex3f(x0, y0, z);
            rtVertex3f(x1, y0, z);
            rtVertex3f(x1, y1, z);
            rtVertex3f(x0, y0, z);
            rtVertex3f(x1, y1, z);
            rtVertex3f(x0, y1, z);
        }
    if (split) {
        rtVertex3f(0, 0, -4);
        rtVertex3f(0.1f, 0, -4);
        rtVertex3f(0, 0.1f, -4);
    }
    rtEnd();
}

static void immediate_frames(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_section("immediate mode: unchanged, moved, new topology");
    tu_ortho_camera();
    rtViewport(0, 0, W, H);
    rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
    draw_grid(8, 0, 0);
    rtFinish(); /* a described frame: rendered */
    CHECK_NO_ERR();
    CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 1);
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1);
    /* Re-sent unchanged: no build, no update, no top level. */
    for (int f = 0; f < 3; f++) {
        rtClear(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT);
        draw_grid(8, 0, 0);
        rtFinish();
        CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 0);
        CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
        CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);
    }
    /* Moved vertices, same topology: the update path (refit/rebuild). */
    rtClear(RT_COLOR_BUFFER_BIT);
    draw_grid(8, 0.5f, 0);
    rtFinish();
    CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 1);
    CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 0);
    /* A new topology: built anew. */
    rtClear(RT_COLOR_BUFFER_BIT);
    draw_grid(8, 0.5f, 1);
    rtFinish();
    CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 1);
    /* The same geometry under a new modelview: an instance that moved
     * (top level rebuilt), the object unchanged. */
    rtClear(RT_COLOR_BUFFER_BIT);
    rtTranslatef(0.25f, 0, 0);
    draw_grid(8, 0.5f, 1);
    rtLoadIdentity();
    rtFinish();
    CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 0);
    CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1);
    CHECK_NO_ERR();

    tu_section("rtClear starts a frame; rtReadPixels renders it");
    rtClear(0x1);
    CHECK_ERR(RT_INVALID_VALUE);
    rtClearColor(0, 0, 0, 0);
    rtClear(RT_COLOR_BUFFER_BIT);
    rtFlush(); /* an empty frame */
    rtReadPixels(0, 0, W, H, RT_RGBA, RT_FLOAT, px);
    CHECK_NEAR(pixel(8, 8)[3], 0, 0);
    rtClear(RT_COLOR_BUFFER_BIT);
    draw_grid(2, 0, 0);
    rtReadPixels(0, 0, W, H, RT_RGBA, RT_FLOAT, px); /* no rtRenderFrame */
    CHECK_NEAR(pixel(8, 8)[3], 1, 0);
    /* rtArrayElement in immediate mode and its errors. */
    {
        static const float v[3][3] = {{-1, -1, -5}, {1, -1, -5}, {1, 1, -5}};
        rtVertexPointer(3, RT_FLOAT, 0, v);
        rtEnableClientState(RT_VERTEX_ARRAY);
        rtArrayElement(0);
        CHECK_ERR(RT_INVALID_OPERATION);
        rtClear(RT_COLOR_BUFFER_BIT);
        rtBegin(RT_TRIANGLES);
        rtArrayElement(-1);
        CHECK_ERR(RT_INVALID_VALUE);
        for (int k = 0; k < 3; k++)
            rtArrayElement(k);
        rtEnd();
        rtReadPixels(0, 0, W, H, RT_RGBA, RT_FLOAT, px);
        CHECK_NEAR(pixel(12, 4)[3], 1, 0);
        CHECK_NEAR(pixel(3, 12)[3], 0, 0);
        rtDisableClientState(RT_VERTEX_ARRAY);
    }
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    compile_independent();
    matrix_side_effects();
    state_side_effects();
    inheritance();
    nested();
    call_lists();
    entry_points();
    compile_and_execute();
    tu_destroy_context(ctx);
    immediate_frames();
    return test_summary("lists");
}
