/* SPDX-License-Identifier: Apache-2.0 */
/*
 * raster_state.c - conformance: the raster-side GL state in display lists
 * and per primitive (docs/lists.md "Raster state per primitive"):
 * RT_BLEND, rtBlendFunc, rtPolygonMode, rtLineWidth, rtPointSize,
 * RT_ALPHA_TEST with rtAlphaFunc, RT_POLYGON_OFFSET_FILL with
 * rtPolygonOffset.  A list compiled with RT_COMPILE leaves the context's
 * state as it was; RT_COMPILE_AND_EXECUTE and rtCallList leave it as the
 * list set it, as glEndList and glCallList do.  rtAlphaFunc's validation,
 * clamping and queries; a render check that blending is per primitive.
 *
 * Reference: docs/lists.md, docs/alpha_test.md, docs/polygon_offset.md,
 * docs/blending.md, docs/lines.md.
 */
#include "testutil.h"

#include <string.h>

#define LIST 900u
#define N 8

/* Every raster call a list records, with values differing from the
 * initial state. */
static void raster_calls(void)
{
    rtEnable(RT_BLEND);
    rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
    rtPolygonMode(RT_FRONT, RT_LINE);
    rtPolygonMode(RT_BACK, RT_POINT);
    rtLineWidth(3.0f);
    rtPointSize(5.0f);
    rtEnable(RT_ALPHA_TEST);
    rtAlphaFunc(RT_GREATER, 0.25f);
    rtEnable(RT_POLYGON_OFFSET_FILL);
    rtPolygonOffset(2.0f, 4.0f);
}

static void reset(void)
{
    rtDisable(RT_BLEND);
    rtBlendFunc(RT_ONE, RT_ZERO);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    rtLineWidth(1.0f);
    rtPointSize(1.0f);
    rtDisable(RT_ALPHA_TEST);
    rtAlphaFunc(RT_ALWAYS, 0.0f);
    rtDisable(RT_POLYGON_OFFSET_FILL);
    rtPolygonOffset(0.0f, 0.0f);
}

/* 1: the state raster_calls sets; 0: the initial state. */
static void check_state(int set, const char *when)
{
    RTint i[2];
    RTfloat f;
    CHECKF(rtIsEnabled(RT_BLEND) == (set ? RT_TRUE : RT_FALSE), "%s: RT_BLEND", when);
    rtGetIntegerv(RT_BLEND_SRC, i);
    CHECKF(i[0] == (set ? RT_SRC_ALPHA : RT_ONE), "%s: RT_BLEND_SRC 0x%x", when, i[0]);
    rtGetIntegerv(RT_BLEND_DST, i);
    CHECKF(i[0] == (set ? RT_ONE_MINUS_SRC_ALPHA : RT_ZERO), "%s: RT_BLEND_DST 0x%x", when,
           i[0]);
    rtGetIntegerv(RT_POLYGON_MODE, i);
    CHECKF(i[0] == (set ? RT_LINE : RT_FILL) && i[1] == (set ? RT_POINT : RT_FILL),
           "%s: RT_POLYGON_MODE 0x%x 0x%x", when, i[0], i[1]);
    rtGetFloatv(RT_LINE_WIDTH, &f);
    CHECKF(f == (set ? 3.0f : 1.0f), "%s: RT_LINE_WIDTH %g", when, (double)f);
    rtGetFloatv(RT_POINT_SIZE, &f);
    CHECKF(f == (set ? 5.0f : 1.0f), "%s: RT_POINT_SIZE %g", when, (double)f);
    CHECKF(rtIsEnabled(RT_ALPHA_TEST) == (set ? RT_TRUE : RT_FALSE), "%s: RT_ALPHA_TEST", when);
    rtGetIntegerv(RT_ALPHA_TEST_FUNC, i);
    CHECKF(i[0] == (set ? RT_GREATER : RT_ALWAYS), "%s: RT_ALPHA_TEST_FUNC 0x%x", when, i[0]);
    rtGetFloatv(RT_ALPHA_TEST_REF, &f);
    CHECKF(f == (set ? 0.25f : 0.0f), "%s: RT_ALPHA_TEST_REF %g", when, (double)f);
    CHECKF(rtIsEnabled(RT_POLYGON_OFFSET_FILL) == (set ? RT_TRUE : RT_FALSE),
           "%s: RT_POLYGON_OFFSET_FILL", when);
    rtGetFloatv(RT_POLYGON_OFFSET_FACTOR, &f);
    CHECKF(f == (set ? 2.0f : 0.0f), "%s: RT_POLYGON_OFFSET_FACTOR %g", when, (double)f);
    rtGetFloatv(RT_POLYGON_OFFSET_UNITS, &f);
    CHECKF(f == (set ? 4.0f : 0.0f), "%s: RT_POLYGON_OFFSET_UNITS %g", when, (double)f);
    CHECK_NO_ERR();
}

static void list_recording(void)
{
    RTuint list = LIST;
    reset();
    check_state(0, "initial");
    /* RT_COMPILE: recorded, not executed. */
    rtNewList(LIST, RT_COMPILE);
    raster_calls();
    rtEndList();
    check_state(0, "after rtEndList (RT_COMPILE)");
    /* rtCallList executes what was recorded. */
    rtCallList(LIST);
    check_state(1, "after rtCallList");
    reset();
    /* RT_COMPILE_AND_EXECUTE: executed while recorded. */
    rtNewList(LIST, RT_COMPILE_AND_EXECUTE);
    raster_calls();
    rtEndList();
    check_state(1, "after rtEndList (RT_COMPILE_AND_EXECUTE)");
    reset();
    rtCallList(LIST);
    check_state(1, "after rtCallList of the RT_COMPILE_AND_EXECUTE list");
    reset();
    rtDeleteLists(list, 1);
    CHECK_NO_ERR();
}

static void alpha_func_calls(void)
{
    RTfloat f;
    RTint i;
    rtAlphaFunc(RT_LESS, 2.0f);
    rtGetFloatv(RT_ALPHA_TEST_REF, &f);
    CHECK_NEAR(f, 1.0f, 0.0f); /* clamped */
    rtAlphaFunc(RT_LESS, -1.0f);
    rtGetFloatv(RT_ALPHA_TEST_REF, &f);
    CHECK_NEAR(f, 0.0f, 0.0f);
    rtAlphaFunc(RT_ONE, 0.5f); /* not a function */
    CHECK_ERR(RT_INVALID_ENUM);
    rtAlphaFunc(RT_ALWAYS + 1, 0.5f);
    CHECK_ERR(RT_INVALID_ENUM);
    rtGetIntegerv(RT_ALPHA_TEST_FUNC, &i);
    CHECK_INT(i, RT_LESS); /* the failed calls changed nothing */
    rtBegin(RT_TRIANGLES);
    rtAlphaFunc(RT_GREATER, 0.5f);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtPolygonOffset(1.0f, 1.0f);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    rtGetIntegerv(RT_ALPHA_TEST_FUNC, &i);
    CHECK_INT(i, RT_LESS);
    rtAlphaFunc(RT_ALWAYS, 0.0f);
    CHECK_NO_ERR();
}

static float img[4 * N * N];

/* A quad over the whole window at depth z with colour c (alpha a). */
static void quad(float z, float r, float g, float b, float a)
{
    rtColor4f(r, g, b, a);
    rtBegin(RT_QUADS);
    rtVertex3f(0.0f, 0.0f, z);
    rtVertex3f((float)N, 0.0f, z);
    rtVertex3f((float)N, (float)N, z);
    rtVertex3f(0.0f, (float)N, z);
    rtEnd();
}

/* The Red Book pattern in immediate mode and in a list: an opaque quad of
 * alpha 0.5 drawn with blending off stays opaque though blending is on
 * when the frame ends; the quad drawn with blending on in front of it is
 * blended over it.  And the alpha test: a quad whose alpha fails is not
 * seen, the one behind it is. */
static void render_per_primitive(int in_list)
{
    rtViewport(0, 0, N, N);
    rtClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtOrtho(0.0, N, 0.0, N, -1.0, 1.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    reset();
    rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
    if (in_list)
        rtNewList(LIST, RT_COMPILE);
    else
        rtBeginFrame();
    quad(-0.5f, 1.0f, 0.0f, 0.0f, 0.5f); /* opaque red, alpha 0.5 */
    rtEnable(RT_BLEND);
    quad(0.5f, 0.0f, 1.0f, 0.0f, 0.5f); /* green, blended */
    if (in_list) {
        rtEndList();
        CHECK(rtIsEnabled(RT_BLEND) == RT_FALSE);
        rtBeginFrame();
        rtCallList(LIST);
        CHECK(rtIsEnabled(RT_BLEND) == RT_TRUE);
    }
    rtRenderFrame();
    rtReadPixels(0, 0, N, N, RT_RGBA, RT_FLOAT, img);
    CHECK_NO_ERR();
    /* Green at half over opaque red; the clear colour's blue not seen. */
    CHECKF(img[0] > 0.45f && img[0] < 0.55f && img[1] > 0.45f && img[1] < 0.55f && img[2] < 0.05f,
           "%s: blended over opaque: (%g, %g, %g)", in_list ? "list" : "immediate",
           (double)img[0], (double)img[1], (double)img[2]);
    /* The alpha test per primitive: the front quad's alpha 0.3 fails
     * RT_GREATER 0.5, the back one (drawn with the test off) is seen. */
    reset();
    if (in_list)
        rtNewList(LIST, RT_COMPILE);
    else
        rtBeginFrame();
    quad(-0.5f, 1.0f, 1.0f, 0.0f, 0.1f);
    rtEnable(RT_ALPHA_TEST);
    rtAlphaFunc(RT_GREATER, 0.5f);
    quad(0.5f, 0.0f, 1.0f, 1.0f, 0.3f);
    rtDisable(RT_ALPHA_TEST);
    if (in_list) {
        rtEndList();
        rtBeginFrame();
        rtCallList(LIST);
    }
    rtRenderFrame();
    rtReadPixels(0, 0, N, N, RT_RGBA, RT_FLOAT, img);
    CHECK_NO_ERR();
    CHECKF(img[0] > 0.95f && img[1] > 0.95f && img[2] < 0.05f,
           "%s: cut out: (%g, %g, %g)", in_list ? "list" : "immediate", (double)img[0],
           (double)img[1], (double)img[2]);
    if (in_list) {
        RTuint list = LIST;
        rtDeleteLists(list, 1);
    }
    reset();
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    list_recording();
    alpha_func_calls();
    render_per_primitive(0);
    render_per_primitive(1);
    tu_destroy_context(ctx);
    return test_summary("raster_state");
}
