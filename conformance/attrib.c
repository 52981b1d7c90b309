/* SPDX-License-Identifier: Apache-2.0 */
/*
 * attrib.c - rtPushAttrib / rtPopAttrib (docs/attrib.md): every group
 * restores its state exactly and only its state; the stack's depth,
 * RT_STACK_OVERFLOW / RT_STACK_UNDERFLOW and RT_INVALID_OPERATION inside
 * rtBegin/rtEnd as GL; push and pop recorded in display lists and run
 * at the call; a pop restores the material the next geometry is drawn
 * with (an image).
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static RTint geti(RTenum pname)
{
    RTint v[4] = {-12345, -12345, -12345, -12345};
    rtGetIntegerv(pname, v);
    return v[0];
}

static void getf(RTenum pname, float *v)
{
    rtGetFloatv(pname, v);
}

static int same4(const float *a, const float *b)
{
    return memcmp(a, b, 4 * sizeof(float)) == 0;
}

static void depth_and_errors(void)
{
    tu_section("depth 16 (GL's minimum), overflow, underflow, inside rtBegin");
    CHECK_INT(geti(RT_MAX_ATTRIB_STACK_DEPTH), 16);
    CHECK_INT(geti(RT_ATTRIB_STACK_DEPTH), 0);
    rtPopAttrib();
    CHECK_ERR(RT_STACK_UNDERFLOW);
    CHECK_MSG("rtPopAttrib");
    for (int i = 0; i < 16; i++)
        rtPushAttrib(RT_CURRENT_BIT);
    CHECK_NO_ERR();
    CHECK_INT(geti(RT_ATTRIB_STACK_DEPTH), 16);
    rtColor3f(0.5f, 0.25f, 0.125f);
    rtPushAttrib(RT_CURRENT_BIT);
    CHECK_ERR(RT_STACK_OVERFLOW);
    CHECK_MSG("rtPushAttrib");
    CHECK_INT(geti(RT_ATTRIB_STACK_DEPTH), 16);
    rtPopAttrib(); /* the 16th entry, the colour before rtColor3f */
    float c[4];
    getf(RT_CURRENT_COLOR, c);
    CHECK(c[0] == 1.0f && c[1] == 1.0f);
    for (int i = 0; i < 15; i++)
        rtPopAttrib();
    CHECK_NO_ERR();
    CHECK_INT(geti(RT_ATTRIB_STACK_DEPTH), 0);
    rtPopAttrib();
    CHECK_ERR(RT_STACK_UNDERFLOW);

    tu_begin_scratch(RT_TRIANGLES);
    rtPushAttrib(RT_ALL_ATTRIB_BITS);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtPopAttrib();
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    CHECK_INT(geti(RT_ATTRIB_STACK_DEPTH), 0);
    CHECK_NO_ERR();
}

static void current_group(void)
{
    tu_section("RT_CURRENT_BIT: colour, normal, texture coordinates, raster position");
    rtColor4f(0.1f, 0.2f, 0.3f, 0.4f);
    rtNormal3f(0, 1, 0);
    rtTexCoord2f(0.25f, 0.75f);
    rtWindowPos2i(3, 4);
    float c0[4], n0[4], t0[4], r0[4];
    getf(RT_CURRENT_COLOR, c0);
    getf(RT_CURRENT_NORMAL, n0);
    getf(RT_CURRENT_TEXTURE_COORDS, t0);
    getf(RT_CURRENT_RASTER_POSITION, r0);
    CHECK_NO_ERR();
    rtPushAttrib(RT_CURRENT_BIT);
    rtColor3f(1, 0, 0);
    rtNormal3f(1, 0, 0);
    rtTexCoord2f(9, 9);
    rtWindowPos2i(7, 7);
    rtLineWidth(3.0f); /* not in the group */
    rtPopAttrib();
    float c[4], n[4], t[4], r[4], lw;
    getf(RT_CURRENT_COLOR, c);
    getf(RT_CURRENT_NORMAL, n);
    getf(RT_CURRENT_TEXTURE_COORDS, t);
    getf(RT_CURRENT_RASTER_POSITION, r);
    getf(RT_LINE_WIDTH, &lw);
    CHECK(same4(c, c0));
    CHECK(memcmp(n, n0, 3 * sizeof(float)) == 0);
    CHECK(memcmp(t, t0, 2 * sizeof(float)) == 0);
    CHECK(same4(r, r0));
    CHECK(lw == 3.0f);
    rtLineWidth(1.0f);
    rtColor4f(1, 1, 1, 1);
    CHECK_NO_ERR();
}

static void enable_group(void)
{
    tu_section("RT_ENABLE_BIT: every capability, nothing else");
    static const RTenum caps[] = {RT_LIGHTING,      RT_LIGHT0,        RT_LIGHT3,
                                  RT_COLOR_MATERIAL, RT_TEXTURE_2D,   RT_CULL_FACE,
                                  RT_NORMALIZE,     RT_RESCALE_NORMAL, RT_FOG,
                                  RT_TEXTURE_GEN_S, RT_TEXTURE_GEN_T, RT_BLEND,
                                  RT_CLIP_PLANE0,   RT_CLIP_PLANE5,   RT_DEPTH_TEST,
                                  RT_DITHER,        RT_POLYGON_OFFSET_FILL};
    const int n = (int)(sizeof(caps) / sizeof(caps[0]));
    RTboolean before[32];
    /* A mixed starting state: every other capability on. */
    for (int i = 0; i < n; i++) {
        if (i % 2)
            rtEnable(caps[i]);
        else
            rtDisable(caps[i]);
        before[i] = rtIsEnabled(caps[i]);
    }
    CHECK_NO_ERR();
    rtPushAttrib(RT_ENABLE_BIT);
    for (int i = 0; i < n; i++) {
        if (i % 2)
            rtDisable(caps[i]);
        else
            rtEnable(caps[i]);
    }
    rtCullFace(RT_FRONT); /* polygon state, not an enable */
    rtPopAttrib();
    for (int i = 0; i < n; i++)
        CHECKF(rtIsEnabled(caps[i]) == before[i], "capability 0x%x", caps[i]);
    CHECK_INT(geti(RT_CULL_FACE_MODE), RT_FRONT);
    rtCullFace(RT_BACK);

    tu_section("RT_ENABLE_BIT not in the mask: enables keep their new values");
    rtPushAttrib(RT_CURRENT_BIT);
    rtEnable(RT_FOG);
    rtDisable(RT_DITHER);
    rtPopAttrib();
    CHECK(rtIsEnabled(RT_FOG));
    CHECK(!rtIsEnabled(RT_DITHER));
    for (int i = 0; i < n; i++)
        rtDisable(caps[i]);
    rtEnable(RT_DITHER);
    CHECK_NO_ERR();
}

static void lighting_group(void)
{
    tu_section("RT_LIGHTING_BIT: materials, lights, light model, shade model, colour material");
    const float amb[4] = {0.1f, 0.2f, 0.3f, 1}, dif[4] = {0.4f, 0.5f, 0.6f, 1};
    const float spec[4] = {0.7f, 0.7f, 0.7f, 1}, back[4] = {0.9f, 0.1f, 0.1f, 1};
    const float ldif[4] = {0.3f, 0.3f, 0.9f, 1}, lpos[4] = {1, 2, 3, 0};
    const float gamb[4] = {0.05f, 0.05f, 0.05f, 1};
    rtMaterialfv(RT_FRONT, RT_AMBIENT, amb);
    rtMaterialfv(RT_FRONT, RT_DIFFUSE, dif);
    rtMaterialfv(RT_FRONT, RT_SPECULAR, spec);
    rtMaterialf(RT_FRONT, RT_SHININESS, 17.0f);
    rtMaterialfv(RT_BACK, RT_DIFFUSE, back);
    rtLightfv(RT_LIGHT1, RT_DIFFUSE, ldif);
    rtLightfv(RT_LIGHT1, RT_POSITION, lpos);
    rtLightf(RT_LIGHT1, RT_SPOT_CUTOFF, 30.0f);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, gamb);
    rtLightModeli(RT_LIGHT_MODEL_TWO_SIDE, 1);
    rtShadeModel(RT_FLAT);
    rtColorMaterial(RT_FRONT, RT_SPECULAR);
    rtEnable(RT_LIGHTING);
    rtEnable(RT_LIGHT1);
    /* GL writes the current colour into the tracked specular at the enable
     * (OpenGL 2.1 sec. 2.14.3): the colour is the specular set above. */
    rtColor4fv(spec);
    rtEnable(RT_COLOR_MATERIAL);
    rtFogf(RT_FOG_DENSITY, 0.5f);
    CHECK_NO_ERR();

    rtPushAttrib(RT_LIGHTING_BIT);
    const float red[4] = {1, 0, 0, 1};
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, red);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, red);
    rtMaterialf(RT_FRONT_AND_BACK, RT_SHININESS, 100.0f);
    rtLightfv(RT_LIGHT1, RT_DIFFUSE, red);
    rtLightfv(RT_LIGHT1, RT_POSITION, red);
    rtLightf(RT_LIGHT1, RT_SPOT_CUTOFF, 180.0f);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, red);
    rtLightModeli(RT_LIGHT_MODEL_TWO_SIDE, 0);
    rtShadeModel(RT_SMOOTH);
    rtColorMaterial(RT_BACK, RT_EMISSION);
    rtDisable(RT_LIGHTING);
    rtDisable(RT_LIGHT1);
    rtDisable(RT_COLOR_MATERIAL);
    rtFogf(RT_FOG_DENSITY, 2.0f); /* fog: not in the group */
    rtPopAttrib();
    CHECK_NO_ERR();

    float v[4];
    rtGetMaterialfv(RT_FRONT, RT_AMBIENT, v);
    CHECK(same4(v, amb));
    rtGetMaterialfv(RT_FRONT, RT_DIFFUSE, v);
    CHECK(same4(v, dif));
    rtGetMaterialfv(RT_FRONT, RT_SPECULAR, v);
    CHECK(same4(v, spec));
    rtGetMaterialfv(RT_FRONT, RT_SHININESS, v);
    CHECK(v[0] == 17.0f);
    rtGetMaterialfv(RT_BACK, RT_DIFFUSE, v);
    CHECK(same4(v, back));
    rtGetLightfv(RT_LIGHT1, RT_DIFFUSE, v);
    CHECK(same4(v, ldif));
    rtGetLightfv(RT_LIGHT1, RT_POSITION, v);
    CHECK(same4(v, lpos));
    rtGetLightfv(RT_LIGHT1, RT_SPOT_CUTOFF, v);
    CHECK(v[0] == 30.0f);
    getf(RT_LIGHT_MODEL_AMBIENT, v);
    CHECK(same4(v, gamb));
    CHECK_INT(geti(RT_LIGHT_MODEL_TWO_SIDE), 1);
    CHECK_INT(geti(RT_SHADE_MODEL), RT_FLAT);
    CHECK_INT(geti(RT_COLOR_MATERIAL_FACE), RT_FRONT);
    CHECK_INT(geti(RT_COLOR_MATERIAL_PARAMETER), RT_SPECULAR);
    CHECK(rtIsEnabled(RT_LIGHTING));
    CHECK(rtIsEnabled(RT_LIGHT1));
    CHECK(rtIsEnabled(RT_COLOR_MATERIAL));
    getf(RT_FOG_DENSITY, v);
    CHECK(v[0] == 2.0f);
    rtDisable(RT_LIGHTING);
    rtDisable(RT_LIGHT1);
    rtDisable(RT_COLOR_MATERIAL);
    rtShadeModel(RT_SMOOTH);
    rtLightModeli(RT_LIGHT_MODEL_TWO_SIDE, 0);
    CHECK_NO_ERR();
}

static void other_groups(void)
{
    tu_section("RT_POLYGON_BIT, RT_LINE_BIT, RT_POINT_BIT");
    rtCullFace(RT_FRONT_AND_BACK);
    rtFrontFace(RT_CW);
    rtPolygonMode(RT_FRONT, RT_LINE);
    rtEnable(RT_CULL_FACE);
    rtLineWidth(2.0f);
    rtPointSize(5.0f);
    rtPushAttrib(RT_POLYGON_BIT | RT_LINE_BIT | RT_POINT_BIT);
    rtCullFace(RT_BACK);
    rtFrontFace(RT_CCW);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_POINT);
    rtDisable(RT_CULL_FACE);
    rtLineWidth(7.0f);
    rtPointSize(9.0f);
    rtPopAttrib();
    CHECK_INT(geti(RT_CULL_FACE_MODE), RT_FRONT_AND_BACK);
    CHECK_INT(geti(RT_FRONT_FACE), RT_CW);
    RTint pm[2] = {0, 0};
    rtGetIntegerv(RT_POLYGON_MODE, pm);
    CHECK_INT(pm[0], RT_LINE);
    CHECK_INT(pm[1], RT_FILL);
    CHECK(rtIsEnabled(RT_CULL_FACE));
    float f;
    getf(RT_LINE_WIDTH, &f);
    CHECK(f == 2.0f);
    getf(RT_POINT_SIZE, &f);
    CHECK(f == 5.0f);
    rtCullFace(RT_BACK);
    rtFrontFace(RT_CCW);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    rtDisable(RT_CULL_FACE);
    rtLineWidth(1.0f);
    rtPointSize(1.0f);
    CHECK_NO_ERR();

    tu_section("RT_FOG_BIT");
    const float fc[4] = {0.2f, 0.3f, 0.4f, 1};
    rtFogi(RT_FOG_MODE, RT_LINEAR);
    rtFogf(RT_FOG_START, 2.0f);
    rtFogf(RT_FOG_END, 9.0f);
    rtFogfv(RT_FOG_COLOR, fc);
    rtEnable(RT_FOG);
    rtPushAttrib(RT_FOG_BIT);
    const float other[4] = {1, 1, 1, 1};
    rtFogi(RT_FOG_MODE, RT_EXP2);
    rtFogf(RT_FOG_START, 0.0f);
    rtFogf(RT_FOG_END, 1.0f);
    rtFogfv(RT_FOG_COLOR, other);
    rtDisable(RT_FOG);
    rtPopAttrib();
    CHECK_INT(geti(RT_FOG_MODE), RT_LINEAR);
    float v[4];
    getf(RT_FOG_START, v);
    CHECK(v[0] == 2.0f);
    getf(RT_FOG_END, v);
    CHECK(v[0] == 9.0f);
    getf(RT_FOG_COLOR, v);
    CHECK(same4(v, fc));
    CHECK(rtIsEnabled(RT_FOG));
    rtDisable(RT_FOG);

    tu_section("RT_TEXTURE_BIT: enable, binding, texgen");
    rtBindTexture(RT_TEXTURE_2D, 5);
    rtEnable(RT_TEXTURE_2D);
    rtTexGeni(RT_S, RT_TEXTURE_GEN_MODE, RT_OBJECT_LINEAR);
    rtEnable(RT_TEXTURE_GEN_S);
    rtPushAttrib(RT_TEXTURE_BIT);
    rtBindTexture(RT_TEXTURE_2D, 6);
    rtDisable(RT_TEXTURE_2D);
    rtTexGeni(RT_S, RT_TEXTURE_GEN_MODE, RT_SPHERE_MAP);
    rtDisable(RT_TEXTURE_GEN_S);
    rtPopAttrib();
    CHECK_INT(geti(RT_TEXTURE_BINDING_2D), 5);
    CHECK(rtIsEnabled(RT_TEXTURE_2D));
    CHECK(rtIsEnabled(RT_TEXTURE_GEN_S));
    rtDisable(RT_TEXTURE_2D);
    rtDisable(RT_TEXTURE_GEN_S);
    rtBindTexture(RT_TEXTURE_2D, 0);
    CHECK_NO_ERR();

    tu_section("RT_TRANSFORM_BIT: matrix mode, clip planes, normalize (not the matrices)");
    const double plane[4] = {1, 0, 0, 0.5};
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtClipPlane(RT_CLIP_PLANE2, plane);
    rtEnable(RT_CLIP_PLANE2);
    rtEnable(RT_NORMALIZE);
    rtPushAttrib(RT_TRANSFORM_BIT);
    const double other_plane[4] = {0, 1, 0, 0};
    rtMatrixMode(RT_PROJECTION);
    rtClipPlane(RT_CLIP_PLANE2, other_plane);
    rtDisable(RT_CLIP_PLANE2);
    rtDisable(RT_NORMALIZE);
    rtMatrixMode(RT_MODELVIEW);
    rtTranslatef(1, 2, 3);
    rtMatrixMode(RT_PROJECTION);
    rtPopAttrib();
    CHECK_INT(geti(RT_MATRIX_MODE), RT_MODELVIEW);
    double eq[4] = {0, 0, 0, 0};
    rtGetClipPlane(RT_CLIP_PLANE2, eq);
    CHECK(eq[0] == 1.0 && eq[1] == 0.0 && eq[3] == 0.5);
    CHECK(rtIsEnabled(RT_CLIP_PLANE2));
    CHECK(rtIsEnabled(RT_NORMALIZE));
    float mv[16];
    getf(RT_MODELVIEW_MATRIX, mv);
    CHECK(mv[12] == 1.0f && mv[13] == 2.0f); /* matrices are not attribute state */
    rtLoadIdentity();
    rtDisable(RT_CLIP_PLANE2);
    rtDisable(RT_NORMALIZE);
    CHECK_NO_ERR();

    tu_section("RT_COLOR_BUFFER_BIT, RT_DEPTH_BUFFER_BIT, RT_VIEWPORT_BIT, RT_LIST_BIT");
    rtClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    rtEnable(RT_BLEND);
    rtBlendFunc(RT_SRC_ALPHA, RT_ONE_MINUS_SRC_ALPHA);
    rtEnable(RT_DEPTH_TEST);
    rtDepthMask(RT_FALSE);
    rtViewport(1, 2, 30, 40);
    rtListBase(100);
    rtPushAttrib(RT_COLOR_BUFFER_BIT | RT_DEPTH_BUFFER_BIT | RT_VIEWPORT_BIT | RT_LIST_BIT);
    rtClearColor(1, 1, 1, 1);
    rtDisable(RT_BLEND);
    rtBlendFunc(RT_ONE, RT_ZERO);
    rtDisable(RT_DEPTH_TEST);
    rtDepthMask(RT_TRUE);
    rtViewport(0, 0, 8, 8);
    rtListBase(7);
    rtPopAttrib();
    getf(RT_COLOR_CLEAR_VALUE, v);
    CHECK(v[0] == 0.1f && v[3] == 0.4f);
    CHECK(rtIsEnabled(RT_BLEND));
    CHECK_INT(geti(RT_BLEND_SRC), RT_SRC_ALPHA);
    CHECK_INT(geti(RT_BLEND_DST), RT_ONE_MINUS_SRC_ALPHA);
    CHECK(rtIsEnabled(RT_DEPTH_TEST));
    CHECK_INT(geti(RT_DEPTH_WRITEMASK), 0);
    RTint vp[4];
    rtGetIntegerv(RT_VIEWPORT, vp);
    CHECK(vp[0] == 1 && vp[1] == 2 && vp[2] == 30 && vp[3] == 40);
    CHECK_INT(geti(RT_LIST_BASE), 100);
    rtClearColor(0, 0, 0, 0);
    rtDisable(RT_BLEND);
    rtBlendFunc(RT_ONE, RT_ZERO);
    rtDisable(RT_DEPTH_TEST);
    rtDepthMask(RT_TRUE);
    rtListBase(0);
    CHECK_NO_ERR();

    tu_section("RT_HINT_BIT: the acceleration hint");
    rtHint(RT_ACCELERATION_HINT, RT_NICEST);
    rtPushAttrib(RT_LIST_BIT); /* another group: the hint is not restored */
    rtHint(RT_ACCELERATION_HINT, RT_FASTEST);
    rtPopAttrib();
    CHECK_INT(geti(RT_ACCELERATION_HINT), RT_FASTEST);
    rtHint(RT_ACCELERATION_HINT, RT_NICEST);
    rtPushAttrib(RT_HINT_BIT);
    rtHint(RT_ACCELERATION_HINT, RT_FASTEST);
    CHECK_INT(geti(RT_ACCELERATION_HINT), RT_FASTEST);
    rtPopAttrib();
    CHECK_INT(geti(RT_ACCELERATION_HINT), RT_NICEST);
    rtHint(RT_ACCELERATION_HINT, RT_DONT_CARE);
    CHECK_NO_ERR();

    tu_section("nested pushes restore in order; RT_ALL_ATTRIB_BITS");
    rtLineWidth(2.0f);
    rtPushAttrib(RT_ALL_ATTRIB_BITS);
    rtLineWidth(3.0f);
    rtEnable(RT_FOG);
    rtPushAttrib(RT_LINE_BIT);
    rtLineWidth(4.0f);
    rtPopAttrib();
    getf(RT_LINE_WIDTH, &f);
    CHECK(f == 3.0f);
    CHECK(rtIsEnabled(RT_FOG));
    rtPopAttrib();
    getf(RT_LINE_WIDTH, &f);
    CHECK(f == 2.0f);
    CHECK(!rtIsEnabled(RT_FOG));
    rtLineWidth(1.0f);
    CHECK_NO_ERR();
}

static void in_lists(void)
{
    tu_section("push and pop recorded in a list, run at the call");
    rtShadeModel(RT_SMOOTH);
    rtNewList(300, RT_COMPILE);
    rtPushAttrib(RT_LIGHTING_BIT);
    rtShadeModel(RT_FLAT);
    rtPopAttrib();
    rtPushAttrib(RT_LINE_BIT); /* left pushed: the call leaves depth + 1 */
    rtEndList();
    CHECK_NO_ERR();
    CHECK_INT(geti(RT_ATTRIB_STACK_DEPTH), 0);
    CHECK_INT(geti(RT_SHADE_MODEL), RT_SMOOTH);
    rtCallList(300);
    CHECK_NO_ERR();
    CHECK_INT(geti(RT_ATTRIB_STACK_DEPTH), 1);
    CHECK_INT(geti(RT_SHADE_MODEL), RT_SMOOTH);
    rtPopAttrib();

    tu_section("a list popping the caller's push restores the caller's state");
    rtNewList(301, RT_COMPILE);
    rtShadeModel(RT_FLAT);
    rtPopAttrib();
    rtEndList();
    CHECK_NO_ERR(); /* nothing popped at compile time */
    rtShadeModel(RT_SMOOTH);
    rtPushAttrib(RT_LIGHTING_BIT);
    rtShadeModel(RT_FLAT);
    rtCallList(301);
    CHECK_NO_ERR();
    CHECK_INT(geti(RT_SHADE_MODEL), RT_SMOOTH);
    CHECK_INT(geti(RT_ATTRIB_STACK_DEPTH), 0);
    rtCallList(301);
    CHECK_ERR(RT_STACK_UNDERFLOW); /* reported when the list runs */

    tu_section("RT_COMPILE_AND_EXECUTE runs them at once");
    rtShadeModel(RT_SMOOTH);
    rtNewList(302, RT_COMPILE_AND_EXECUTE);
    rtPushAttrib(RT_LIGHTING_BIT);
    rtShadeModel(RT_FLAT);
    CHECK_INT(geti(RT_ATTRIB_STACK_DEPTH), 1);
    rtPopAttrib();
    rtEndList();
    CHECK_INT(geti(RT_ATTRIB_STACK_DEPTH), 0);
    CHECK_INT(geti(RT_SHADE_MODEL), RT_SMOOTH);
    CHECK_NO_ERR();
    rtDeleteLists(300, 3);
}

/* Two quads side by side in one list: the left one red by a material
 * the list pushes and pops; the right one drawn after the pop takes the
 * caller's blue material, in the image. */
static void image_after_pop(void)
{
    tu_section("the material a pop restores is the one later geometry is drawn with");
    enum { IW = 32, IH = 16 };
    static float img[IW * IH * 4];
    const float blue[4] = {0, 0, 1, 1}, red[4] = {1, 0, 0, 1}, black[4] = {0, 0, 0, 1};
    const float white[4] = {1, 1, 1, 1};
    rtShadingMode(RT_FIXED_FUNCTION);
    tu_ortho_camera();
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
    rtLightfv(RT_LIGHT0, RT_DIFFUSE, white);
    const float dir[4] = {0, 0, 1, 0};
    rtLightfv(RT_LIGHT0, RT_POSITION, dir);
    rtEnable(RT_LIGHT0);
    rtEnable(RT_LIGHTING);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, blue);
    rtNewList(310, RT_COMPILE);
    rtPushAttrib(RT_LIGHTING_BIT);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, red);
    rtBegin(RT_QUADS);
    rtNormal3f(0, 0, 1);
    rtVertex3f(-1, -1, -5);
    rtVertex3f(0, -1, -5);
    rtVertex3f(0, 1, -5);
    rtVertex3f(-1, 1, -5);
    rtEnd();
    rtPopAttrib();
    rtBegin(RT_QUADS);
    rtNormal3f(0, 0, 1);
    rtVertex3f(0, -1, -5);
    rtVertex3f(1, -1, -5);
    rtVertex3f(1, 1, -5);
    rtVertex3f(0, 1, -5);
    rtEnd();
    rtEndList();
    CHECK_NO_ERR();
    rtBeginFrame();
    rtCallList(310);
    tu_render_float(IW, IH, img);
    CHECK_NO_ERR();
    const float *l = &img[4 * (8 * IW + 8)], *r = &img[4 * (8 * IW + 24)];
    CHECKF(l[0] > 0.9f && l[2] < 0.1f, "left (%g, %g, %g) should be red", l[0], l[1], l[2]);
    CHECKF(r[2] > 0.9f && r[0] < 0.1f, "right (%g, %g, %g) should be blue", r[0], r[1], r[2]);
    float v[4];
    rtGetMaterialfv(RT_FRONT, RT_DIFFUSE, v);
    CHECK(same4(v, blue));
    rtDisable(RT_LIGHTING);
    rtDisable(RT_LIGHT0);
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    depth_and_errors();
    current_group();
    enable_group();
    lighting_group();
    other_groups();
    in_lists();
    image_after_pop();
    tu_destroy_context(ctx);
    return test_summary("attrib");
}
