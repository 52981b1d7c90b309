/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dynamic.c - conformance: dynamic scenes.  rtObjectParameteri (class and
 * strategy hints), rtUpdateVertices, rtRenderParameteri(RT_UPDATE_STRATEGY),
 * the automatic classification (Wald, Benthin and Slusallek (2003) sec. 3) and the update
 * statistics.
 *
 *   - every error of the three calls, each followed by a check that the
 *     failing call changed nothing;
 *   - classification over frames: unchanged -> RT_STATIC, a moved instance
 *     -> RT_AFFINE, redefined or updated geometry -> RT_UNSTRUCTURED, hints
 *     override, RT_OBJECT_CLASS is the class of the last prepared frame;
 *   - a static scene costs nothing after its first frame (no update, no
 *     update time, no top-level build) and a threads=1 context never starts
 *     a thread;
 *   - rtUpdateVertices moves hits where hand computation says (object space,
 *     modelview ignored, partial updates, float and double, strides), in the
 *     recording-order vertex numbering (rtDrawElements: vertex k is element
 *     min + k), and a normal update changes eye-light shading only;
 *   - structures are updated when a frame is prepared, only if they exist
 *     and are stale; RT_OBJECT_BUILT, RT_OBJECT_REFITS/REBUILDS and
 *     RT_UPDATE_STRATEGY follow (same-topology redefinition refits under
 *     RT_REFIT, a topology change rebuilds).
 *
 * Reference: docs/dynamic.md, docs/statistics.md, docs/arrays.md.
 */
#include "testutil.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static RTint geti(RTenum pname)
{
    RTint v = -12345;
    rtGetIntegerv(pname, &v);
    return v;
}

static RTfloat getf(RTenum pname)
{
    RTfloat v = -12345.0f;
    rtGetFloatv(pname, &v);
    return v;
}

static RTint obji(RTuint name, RTenum pname)
{
    RTint v = -12345;
    rtGetObjectiv(name, pname, &v);
    return v;
}

static void object_bounds(RTuint name, float b[6])
{
    for (int k = 0; k < 6; k++)
        b[k] = -12345.0f;
    rtGetObjectfv(name, RT_OBJECT_BOUNDS, b);
}

/* The unit quad's corners at height z, in RT_QUADS order. */
static void quad_at(float v[12], float z)
{
    static const float xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; k++) {
        v[3 * k] = xy[k][0];
        v[3 * k + 1] = xy[k][1];
        v[3 * k + 2] = z;
    }
}

/* ---- rtObjectParameteri ------------------------------------------------- */

static void object_parameter_errors(RTcontext ctx)
{
    const RTuint O = 100;
    RTuint generated = 0, deleted = 104;
    tu_section("rtObjectParameteri errors change nothing");
    CHECK(tu_define_quad(O, 0, 0, 1, 1, 0));
    CHECK(tu_define_quad(deleted, 0, 0, 1, 1, 0));
    rtDeleteObjects(1, &deleted);
    rtGenObjects(1, &generated);
    /* No hint and no update yet: the hint, RT_AUTOMATIC, is reported. */
    CHECK_INT(obji(O, RT_UPDATE_STRATEGY), RT_AUTOMATIC);
    rtObjectParameteri(O, RT_UPDATE_STRATEGY, RT_REBUILD_MEDIAN);
    CHECK_NO_ERR();
    CHECK_INT(obji(O, RT_UPDATE_STRATEGY), RT_REBUILD_MEDIAN);

    /* Inside rtBegin: the mode is checked first. */
    tu_begin_scratch(RT_TRIANGLES);
    rtObjectParameteri(O, RT_UPDATE_STRATEGY, RT_REFIT);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtObjectParameteri(O, 0x1234, RT_REFIT);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtObjectParameteri(0, RT_OBJECT_CLASS, RT_STATIC);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    CHECK_INT(obji(O, RT_UPDATE_STRATEGY), RT_REBUILD_MEDIAN);

    /* pname: checked before param and name. */
    rtObjectParameteri(O, RT_OBJECT_TRIANGLES, RT_STATIC);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtObjectParameteri");
    rtObjectParameteri(O, 0, RT_REFIT);
    CHECK_ERR(RT_INVALID_ENUM);
    rtObjectParameteri(O, RT_MAX_RAY_DEPTH, 2);
    CHECK_ERR(RT_INVALID_ENUM);
    rtObjectParameteri(9999, 0x1234, RT_STATIC);
    CHECK_ERR(RT_INVALID_ENUM);

    /* param not valid for pname: checked before the name. */
    rtObjectParameteri(O, RT_OBJECT_CLASS, RT_REFIT);
    CHECK_ERR(RT_INVALID_ENUM);
    rtObjectParameteri(O, RT_OBJECT_CLASS, RT_REBUILD_HEURISTIC);
    CHECK_ERR(RT_INVALID_ENUM);
    rtObjectParameteri(O, RT_OBJECT_CLASS, 0);
    CHECK_ERR(RT_INVALID_ENUM);
    rtObjectParameteri(O, RT_OBJECT_CLASS, -1);
    CHECK_ERR(RT_INVALID_ENUM);
    rtObjectParameteri(O, RT_UPDATE_STRATEGY, RT_STATIC);
    CHECK_ERR(RT_INVALID_ENUM);
    rtObjectParameteri(O, RT_UPDATE_STRATEGY, RT_AFFINE);
    CHECK_ERR(RT_INVALID_ENUM);
    rtObjectParameteri(O, RT_UPDATE_STRATEGY, RT_UNSTRUCTURED);
    CHECK_ERR(RT_INVALID_ENUM);
    rtObjectParameteri(O, RT_UPDATE_STRATEGY, RT_MAX_RAY_DEPTH);
    CHECK_ERR(RT_INVALID_ENUM);
    rtObjectParameteri(O, RT_UPDATE_STRATEGY, INT_MIN);
    CHECK_ERR(RT_INVALID_ENUM);
    rtObjectParameteri(9999, RT_UPDATE_STRATEGY, RT_STATIC);
    CHECK_ERR(RT_INVALID_ENUM);

    /* Not a defined object. */
    rtObjectParameteri(0, RT_OBJECT_CLASS, RT_STATIC);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtObjectParameteri");
    rtObjectParameteri(9999, RT_UPDATE_STRATEGY, RT_REFIT);
    CHECK_ERR(RT_INVALID_VALUE);
    rtObjectParameteri(generated, RT_UPDATE_STRATEGY, RT_REFIT);
    CHECK_ERR(RT_INVALID_VALUE);
    rtObjectParameteri(deleted, RT_OBJECT_CLASS, RT_AFFINE);
    CHECK_ERR(RT_INVALID_VALUE);
    /* An object whose first definition is being recorded is not one yet. */
    rtNewObject(105);
    rtObjectParameteri(105, RT_OBJECT_CLASS, RT_STATIC);
    CHECK_ERR(RT_INVALID_VALUE);
    /* ... but hints on other objects may be given while recording. */
    rtObjectParameteri(O, RT_UPDATE_STRATEGY, RT_REFIT);
    CHECK_NO_ERR();
    rtEndObject();
    CHECK_INT(obji(O, RT_UPDATE_STRATEGY), RT_REFIT);
    rtObjectParameteri(O, RT_UPDATE_STRATEGY, RT_REBUILD_MEDIAN);
    CHECK(rtIsObject(generated) == RT_FALSE);
    CHECK(rtIsObject(deleted) == RT_FALSE);
    CHECK_INT(obji(O, RT_UPDATE_STRATEGY), RT_REBUILD_MEDIAN);

    /* The first error is kept. */
    rtObjectParameteri(O, 0x1234, 0);
    rtObjectParameteri(0, RT_OBJECT_CLASS, RT_STATIC);
    CHECK_ERR(RT_INVALID_ENUM);

    /* Without a current context nothing happens. */
    rtMakeCurrent(NULL);
    rtObjectParameteri(O, RT_UPDATE_STRATEGY, RT_REFIT);
    rtObjectParameteri(0, 0, 0);
    rtMakeCurrent(ctx);
    CHECK_NO_ERR();
    CHECK_INT(obji(O, RT_UPDATE_STRATEGY), RT_REBUILD_MEDIAN);

    /* Every valid value is accepted. */
    {
        static const RTenum classes[] = {RT_STATIC, RT_AFFINE, RT_UNSTRUCTURED, RT_AUTOMATIC};
        static const RTenum strategies[] = {RT_REFIT,       RT_REBUILD,     RT_REBUILD_MEDIAN,
                                            RT_REBUILD_HEURISTIC, RT_RESTRUCTURE,
#ifdef RT_ASYNC_REBUILD
                                            RT_ASYNC_REBUILD,
#endif
                                            RT_AUTOMATIC};
        for (int i = 0; i < 4; i++) {
            rtObjectParameteri(O, RT_OBJECT_CLASS, (RTint)classes[i]);
            CHECK_NO_ERR();
        }
        for (int i = 0; i < (int)(sizeof strategies / sizeof strategies[0]); i++) {
            rtObjectParameteri(O, RT_UPDATE_STRATEGY, (RTint)strategies[i]);
            CHECK_NO_ERR();
            CHECK_INT(obji(O, RT_UPDATE_STRATEGY), strategies[i]);
        }
    }
    rtDeleteObjects(1, &generated);
    CHECK_NO_ERR();
}

/* ---- rtUpdateVertices errors ------------------------------------------------ */

/* The quad U (4 vertices at z = 0, instantiated at the identity) is
 * unchanged: same hit, same bounds, structure still up to date. */
static void check_quad_unchanged(const char *file, int line, RTuint U)
{
    RThit h = tu_trace_down(0.5f, 0.5f);
    float b[6];
    object_bounds(U, b);
    tu_check(h.object == U && h.t == 10.0f, file, line, "quad still hit at t = 10");
    tu_check(b[0] == 0 && b[1] == 0 && b[2] == 0 && b[3] == 1 && b[4] == 1 && b[5] == 0, file,
             line, "quad bounds unchanged");
    tu_check(obji(U, RT_OBJECT_VERTICES) == 4, file, line, "RT_OBJECT_VERTICES == 4");
    tu_check(obji(U, RT_OBJECT_BUILT) == RT_TRUE, file, line, "RT_OBJECT_BUILT stays RT_TRUE");
    tu_check(rtGetError() == RT_NO_ERROR, file, line, "no error checking the quad");
}
#define CHECK_QUAD_UNCHANGED(U) check_quad_unchanged(__FILE__, __LINE__, (U))

static void update_vertices_errors(RTcontext ctx)
{
    const RTuint U = 110;
    RTuint generated = 0, deleted = 111;
    float moved[12], bad[12];
    double moved_d[12];
    tu_section("rtUpdateVertices errors change nothing");
    quad_at(moved, 1.0f);
    for (int k = 0; k < 12; k++)
        moved_d[k] = moved[k];
    CHECK(tu_define_quad(U, 0, 0, 1, 1, 0));
    CHECK(tu_define_quad(deleted, 0, 0, 1, 1, 0));
    rtDeleteObjects(1, &deleted);
    rtGenObjects(1, &generated);
    CHECK(tu_scene1(U));
    CHECK_QUAD_UNCHANGED(U);

    /* Inside an object definition (even of another object) or rtBegin. */
    rtNewObject(112);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK_MSG("rtUpdateVertices");
    rtEndObject();
    rtNewObject(U);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtBegin(RT_QUADS);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtUpdateVertices(U, RT_COLOR_ARRAY, -1, 4, RT_INT, 0, NULL); /* the mode first */
    CHECK_ERR(RT_INVALID_OPERATION);
    rtVertex3f(0, 0, 0); /* the recording continues */
    rtVertex3f(1, 0, 0);
    rtVertex3f(1, 1, 0);
    rtVertex3f(0, 1, 0);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
    rtFinish();
    CHECK_QUAD_UNCHANGED(U);

    /* array, then type: RT_INVALID_ENUM, before any value or name check. */
    rtUpdateVertices(U, RT_COLOR_ARRAY, 0, 4, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtUpdateVertices");
    rtUpdateVertices(U, RT_TEXTURE_COORD_ARRAY, 0, 4, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_ENUM);
    rtUpdateVertices(U, 0, 0, 4, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_ENUM);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, RT_INT, 0, moved);
    CHECK_ERR(RT_INVALID_ENUM);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, RT_SHORT, 0, moved);
    CHECK_ERR(RT_INVALID_ENUM);
    rtUpdateVertices(U, RT_NORMAL_ARRAY, 0, 4, RT_BYTE, 0, moved);
    CHECK_ERR(RT_INVALID_ENUM);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, 0, 0, moved);
    CHECK_ERR(RT_INVALID_ENUM);
    rtUpdateVertices(9999, RT_COLOR_ARRAY, -1, -1, RT_FLOAT, -1, NULL);
    CHECK_ERR(RT_INVALID_ENUM);
    rtUpdateVertices(0, RT_VERTEX_ARRAY, -1, -1, RT_UNSIGNED_INT, -1, NULL);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_QUAD_UNCHANGED(U);

    /* Names. */
    rtUpdateVertices(0, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(9999, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(generated, RT_VERTEX_ARRAY, 0, 0, RT_FLOAT, 0, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(deleted, RT_NORMAL_ARRAY, 0, 0, RT_FLOAT, 0, NULL);
    CHECK_ERR(RT_INVALID_VALUE);

    /* Ranges, stride, data. */
    rtUpdateVertices(U, RT_VERTEX_ARRAY, -1, 1, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, -1, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, -12, moved);
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 1, RT_FLOAT, 0, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(U, RT_NORMAL_ARRAY, 0, 4, RT_DOUBLE, 0, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 5, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 1, 4, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 4, 1, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(U, RT_NORMAL_ARRAY, 3, 2, RT_DOUBLE, 0, moved_d);
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 5, 0, RT_FLOAT, 0, NULL); /* starts past the end */
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, INT_MAX, INT_MAX, RT_FLOAT, 0, moved); /* no wrap */
    CHECK_ERR(RT_INVALID_VALUE);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 2, INT_MAX, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_QUAD_UNCHANGED(U);

    /* A value that is not finite as a float, anywhere in the batch:
     * nothing of the batch is stored. */
    {
        static const int where[] = {0, 5, 11};
        for (int w = 0; w < 3; w++) {
            memcpy(bad, moved, sizeof bad);
            bad[where[w]] = tu_nan();
            rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, bad);
            CHECK_ERR(RT_INVALID_VALUE);
            bad[where[w]] = tu_inf();
            rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, bad);
            CHECK_ERR(RT_INVALID_VALUE);
            bad[where[w]] = -tu_inf();
            rtUpdateVertices(U, RT_NORMAL_ARRAY, 0, 4, RT_FLOAT, 0, bad);
            CHECK_ERR(RT_INVALID_VALUE);
        }
        double bad_d[12];
        memcpy(bad_d, moved_d, sizeof bad_d);
        bad_d[11] = 1e39; /* finite as a double, infinite as a float */
        rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, RT_DOUBLE, 0, bad_d);
        CHECK_ERR(RT_INVALID_VALUE);
        bad_d[11] = -1e300;
        rtUpdateVertices(U, RT_NORMAL_ARRAY, 0, 4, RT_DOUBLE, 0, bad_d);
        CHECK_ERR(RT_INVALID_VALUE);
        bad_d[11] = tu_nan_d();
        rtUpdateVertices(U, RT_VERTEX_ARRAY, 3, 1, RT_DOUBLE, 0, bad_d + 9);
        CHECK_ERR(RT_INVALID_VALUE);
        /* ... but a value the stride skips is never read. */
        bad_d[11] = 0.0;
        bad_d[3] = tu_nan_d();
        rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 2, RT_DOUBLE, 6 * sizeof(double), bad_d);
        CHECK_NO_ERR();
        /* That moved vertices 0 and 1 to elements 0 and 2 of bad_d: (0,0,1)
         * and (1,1,1).  Put the quad back. */
        float flat[12];
        quad_at(flat, 0.0f);
        rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, flat);
        CHECK_NO_ERR();
        rtFinish();
    }
    CHECK_QUAD_UNCHANGED(U);

    /* The first error is kept. */
    rtUpdateVertices(U, RT_COLOR_ARRAY, 0, 4, RT_FLOAT, 0, moved);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, -1, 4, RT_FLOAT, 0, moved);
    CHECK_ERR(RT_INVALID_ENUM);

    /* Without a current context nothing happens. */
    rtMakeCurrent(NULL);
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, moved);
    rtMakeCurrent(ctx);
    CHECK_NO_ERR();
    CHECK_QUAD_UNCHANGED(U);

    /* A valid update after all that: the quad is at z = 1. */
    rtUpdateVertices(U, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, moved);
    CHECK_NO_ERR();
    CHECK_NEAR(tu_trace_down(0.5f, 0.5f).t, 9.0f, 0.0);
    rtDeleteObjects(1, &generated);
    CHECK_NO_ERR();
}

/* An update of zero vertices is valid and changes nothing: no stale
 * structure, no class change, no shading change. */
static void empty_updates(void)
{
    const RTuint E = 115;
    float rgba[4 * 4 * 4], before[4 * 4 * 4];
    tu_section("updates of zero vertices change nothing");
    tu_ortho_camera();
    rtShadingMode(RT_EYE_LIGHT);
    /* A tilted quad recorded without normals: shading uses its geometric
     * normal, not the (0, 0, 1) current normal stored with its vertices. */
    rtNewObject(E);
    rtBegin(RT_QUADS);
    rtVertex3f(-2, -2, -4);
    rtVertex3f(2, -2, -4);
    rtVertex3f(2, 2, -6);
    rtVertex3f(-2, 2, -6);
    rtEnd();
    rtEndObject();
    rtBeginFrame();
    rtInstantiateObject(E);
    tu_render_float(4, 4, before);
    rtInstantiateObject(E);
    tu_render_float(4, 4, before);
    CHECK_INT(obji(E, RT_OBJECT_BUILT), RT_TRUE);
    CHECK_INT(obji(E, RT_OBJECT_CLASS), RT_STATIC);
    rtUpdateVertices(E, RT_VERTEX_ARRAY, 0, 0, RT_FLOAT, 0, NULL);
    rtUpdateVertices(E, RT_VERTEX_ARRAY, 4, 0, RT_DOUBLE, 0, NULL);
    rtUpdateVertices(E, RT_NORMAL_ARRAY, 2, 0, RT_FLOAT, 0, NULL);
    CHECK_NO_ERR();
    CHECK_INT(obji(E, RT_OBJECT_BUILT), RT_TRUE);
    rtInstantiateObject(E);
    tu_render_float(4, 4, rgba);
    CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);
    CHECK_INT(obji(E, RT_OBJECT_CLASS), RT_STATIC);
    CHECK(memcmp(rgba, before, sizeof rgba) == 0);
    CHECK_NO_ERR();
}

/* ---- rtRenderParameteri(RT_UPDATE_STRATEGY) --------------------------------- */

static void render_parameter_errors(void)
{
    const RTuint P = 120, Q = 121;
    float z1[12], z2[12];
    RTint rebuilds;
    tu_section("rtRenderParameteri(RT_UPDATE_STRATEGY) errors change nothing");
    quad_at(z1, 1.0f);
    quad_at(z2, 2.0f);
    CHECK(tu_define_quad(P, 0, 0, 1, 1, 0));
    CHECK(tu_define_quad(Q, 0, 0, 1, 1, 0));
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 4);
    /* Every strategy, RT_AUTOMATIC included, is a valid default. */
    {
        static const RTenum strategies[] = {RT_AUTOMATIC, RT_REFIT, RT_REBUILD,
                                            RT_REBUILD_HEURISTIC, RT_RESTRUCTURE,
#ifdef RT_ASYNC_REBUILD
                                            RT_ASYNC_REBUILD,
#endif
                                            RT_REBUILD_MEDIAN};
        for (int i = 0; i < (int)(sizeof strategies / sizeof strategies[0]); i++) {
            rtRenderParameteri(RT_UPDATE_STRATEGY, (RTint)strategies[i]);
            CHECK_NO_ERR();
        }
    }
    /* The default is now RT_REBUILD_MEDIAN.  Failing calls: */
    rtRenderParameteri(RT_UPDATE_STRATEGY, RT_STATIC);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtRenderParameteri");
    rtRenderParameteri(RT_UPDATE_STRATEGY, RT_UNSTRUCTURED);
    CHECK_ERR(RT_INVALID_ENUM);
    rtRenderParameteri(RT_UPDATE_STRATEGY, 0);
    CHECK_ERR(RT_INVALID_ENUM);
    rtRenderParameteri(RT_UPDATE_STRATEGY, -1);
    CHECK_ERR(RT_INVALID_ENUM);
    rtRenderParameteri(RT_UPDATE_STRATEGY, 4); /* a valid ray depth, not a strategy */
    CHECK_ERR(RT_INVALID_ENUM);
    tu_begin_scratch(RT_TRIANGLES);
    rtRenderParameteri(RT_UPDATE_STRATEGY, RT_REFIT);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtRenderParameteri(RT_UPDATE_STRATEGY, RT_STATIC);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    CHECK_INT(geti(RT_MAX_RAY_DEPTH), 4);

    /* P (no hint) uses the default, Q its hint. */
    rtObjectParameteri(Q, RT_UPDATE_STRATEGY, RT_REBUILD);
    rtBeginFrame();
    rtInstantiateObject(P);
    rtPushMatrix();
    rtTranslatef(3, 0, 0);
    rtInstantiateObject(Q);
    rtPopMatrix();
    CHECK_NEAR(tu_trace_down(0.5f, 0.5f).t, 10.0f, 0.0); /* builds both */
    CHECK_NEAR(tu_trace_down(3.5f, 0.5f).t, 10.0f, 0.0);
    rebuilds = obji(P, RT_OBJECT_REBUILDS);
    rtUpdateVertices(P, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, z1);
    rtUpdateVertices(Q, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, z1);
    rtFinish();
    CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 2);
    CHECK_INT(obji(P, RT_UPDATE_STRATEGY), RT_REBUILD_MEDIAN);
    CHECK_INT(obji(P, RT_OBJECT_REBUILDS), rebuilds + 1);
    CHECK_INT(obji(Q, RT_UPDATE_STRATEGY), RT_REBUILD);
    CHECK_NEAR(tu_trace_down(0.5f, 0.5f).t, 9.0f, 0.0);
    CHECK_NEAR(tu_trace_down(3.5f, 0.5f).t, 9.0f, 0.0);

    /* Back to RT_AUTOMATIC: the runtime picks a concrete strategy. */
    rtRenderParameteri(RT_UPDATE_STRATEGY, RT_AUTOMATIC);
    rtUpdateVertices(P, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, z2);
    rtFinish();
    {
        RTint s = obji(P, RT_UPDATE_STRATEGY);
        int concrete = s == RT_REFIT || s == RT_REBUILD || s == RT_REBUILD_MEDIAN ||
                       s == RT_REBUILD_HEURISTIC || s == RT_RESTRUCTURE;
#ifdef RT_ASYNC_REBUILD
        concrete = concrete || s == RT_ASYNC_REBUILD;
#endif
        CHECK(concrete);
    }
    CHECK_NEAR(tu_trace_down(0.5f, 0.5f).t, 8.0f, 0.0);
    CHECK_NO_ERR();
}

/* ---- classification ------------------------------------------------------------ */

enum { CS = 130, CM, CU, CR, CT, CH, CLASS_OBJECTS = 6 };

/* Issues the classification scene: S, M twice (the second instance at
 * x = 4 + m_shift), U, R, T, H in a row along x. */
static void class_scene(float m_shift)
{
    rtBeginFrame();
    rtLoadIdentity();
    rtInstantiateObject(CS);
    rtTranslatef(2, 0, 0);
    rtInstantiateObject(CM);
    rtPushMatrix();
    rtTranslatef(2 + m_shift, 0, 0);
    rtInstantiateObject(CM);
    rtPopMatrix();
    for (RTuint o = CU; o <= CH; o++) {
        rtTranslatef(4, 0, 0);
        rtInstantiateObject(o);
    }
    rtLoadIdentity();
}

static void check_classes(const char *file, int line, const RTint expected[CLASS_OBJECTS])
{
    static const char *const names[CLASS_OBJECTS] = {"S", "M", "U", "R", "T", "H"};
    for (int i = 0; i < CLASS_OBJECTS; i++) {
        RTint c = obji(CS + (RTuint)i, RT_OBJECT_CLASS);
        if (!tu_check_int(c, expected[i], file, line, names[i], "expected class"))
            fprintf(stderr, "    (object %s: RT_STATIC 0x%x, RT_AFFINE 0x%x, RT_UNSTRUCTURED 0x%x)\n",
                    names[i], RT_STATIC, RT_AFFINE, RT_UNSTRUCTURED);
    }
}
#define CHECK_CLASSES(...)                                                                    \
    do {                                                                                      \
        const RTint expected_[CLASS_OBJECTS] = {__VA_ARGS__};                                 \
        check_classes(__FILE__, __LINE__, expected_);                                         \
    } while (0)

static void classification(void)
{
    const RTint S = RT_STATIC, A = RT_AFFINE, X = RT_UNSTRUCTURED;
    float z1[12], z2[12];
    quad_at(z1, 1.0f);
    quad_at(z2, 2.0f);
    tu_section("classification: static, affine, unstructured");
    tu_ortho_camera();
    rtViewport(0, 0, 8, 8);
    for (RTuint o = CS; o <= CH; o++)
        CHECK(tu_define_quad(o, 0, 0, 1, 1, 0));
    class_scene(0);
    rtRenderFrame();
    CHECK_NO_ERR();
    /* (The first frame is not checked: docs/dynamic.md leaves the class of a
     * brand-new instance to the implementation.) */

    /* An unchanged frame: everything is static. */
    class_scene(0);
    rtRenderFrame();
    CHECK_CLASSES(S, S, S, S, S, S);
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);

    /* One of M's two instances moves; U is updated, R redefined with the same
     * topology, T with another. */
    class_scene(0.5f);
    rtUpdateVertices(CU, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, z1);
    CHECK(tu_define_quad(CR, 0, 0, 1, 1, 1));
    CHECK(tu_define_grid(CT, 2, 2, 0, 0, 1, 1, 1));
    rtRenderFrame();
    CHECK_CLASSES(S, A, X, X, X, S);
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1);
    /* The moved instance is where it was put (x in [4.5, 5.5]). */
    CHECK_INT(tu_trace_down(5.3f, 0.5f).instance, 2);
    CHECK_NEAR(tu_trace_down(6.5f, 0.5f).t, 9.0f, 0.0);  /* U at z = 1 */
    CHECK_NEAR(tu_trace_down(10.5f, 0.5f).t, 9.0f, 0.0); /* R at z = 1 */
    CHECK_NEAR(tu_trace_down(14.5f, 0.5f).t, 9.0f, 0.0); /* T at z = 1 */

    /* The same list again, nothing changed: static again. */
    class_scene(0.5f);
    rtRenderFrame();
    CHECK_CLASSES(S, S, S, S, S, S);
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);

    /* M moves back and its geometry changes too: unstructured wins. */
    class_scene(0);
    rtUpdateVertices(CM, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, z1);
    rtRenderFrame();
    CHECK_CLASSES(S, X, S, S, S, S);

    /* No instance issued at all: the scene stays and nothing moved. */
    rtRenderFrame();
    CHECK_CLASSES(S, S, S, S, S, S);

    /* Hints override. */
    rtObjectParameteri(CH, RT_OBJECT_CLASS, RT_UNSTRUCTURED);
    rtObjectParameteri(CS, RT_OBJECT_CLASS, RT_AFFINE);
    rtObjectParameteri(CU, RT_OBJECT_CLASS, RT_STATIC);
    rtObjectParameteri(CM, RT_OBJECT_CLASS, RT_STATIC);
    rtObjectParameteri(CR, RT_OBJECT_CLASS, RT_AUTOMATIC);
    /* Hints show from the next prepared frame on. */
    CHECK_CLASSES(S, S, S, S, S, S);
    class_scene(1.0f); /* M moves */
    rtUpdateVertices(CU, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, z2);
    rtUpdateVertices(CR, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, z1);
    rtRenderFrame();
    CHECK_CLASSES(A, S, S, X, S, X);
    CHECK_NO_ERR();
    /* A hinted object is still updated: U's hits follow its vertices. */
    CHECK_NEAR(tu_trace_down(6.5f, 0.5f).t, 8.0f, 0.0);
    for (RTuint o = CS; o <= CH; o++)
        rtObjectParameteri(o, RT_OBJECT_CLASS, RT_AUTOMATIC);
    rtRenderFrame();
    CHECK_CLASSES(S, S, S, S, S, S);

    /* RT_OBJECT_CLASS is the class of the last prepared frame: rtFinish
     * and queries prepare the frame being described, rtRenderFrame ends
     * it. */
    rtUpdateVertices(CU, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, z1);
    CHECK_INT(obji(CU, RT_OBJECT_CLASS), S); /* not prepared yet */
    rtFinish();
    CHECK_INT(obji(CU, RT_OBJECT_CLASS), X);
    tu_trace_down(0.5f, 0.5f);
    CHECK_INT(obji(CU, RT_OBJECT_CLASS), X);
    rtRenderFrame();
    CHECK_INT(obji(CU, RT_OBJECT_CLASS), X);
    rtFinish(); /* the next frame: nothing changed in it */
    CHECK_INT(obji(CU, RT_OBJECT_CLASS), S);
    rtRenderFrame();
    CHECK_CLASSES(S, S, S, S, S, S);
    /* A redefinition with the same geometry is still a redefinition. */
    CHECK(tu_define_quad(CS, 0, 0, 1, 1, 0));
    rtRenderFrame();
    CHECK_CLASSES(X, S, S, S, S, S);
    CHECK_NO_ERR();
    rtViewport(0, 0, 0, 0);
}

/* The vertices of tu_define_grid(name, n, n, x_lo, y_lo, x_lo + size,
 * y_lo + size, z): 4 per cell, cells row by row, corners in RT_QUADS order
 * (0,0) (1,0) (1,1) (0,1); with `strips`, in the order of a 4-vertex
 * RT_TRIANGLE_STRIP per cell, (0,0) (0,1) (1,0) (1,1). */
static void grid_vertices(float *v, int n, float x_lo, float y_lo, float size, int strips,
                          float z)
{
    static const int quad_corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    static const int strip_corner[4][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
    for (int k = 0; k < 4 * n * n; k++) {
        int cell = k / 4;
        const int *c = strips ? strip_corner[k % 4] : quad_corner[k % 4];
        v[3 * k] = x_lo + size * (float)(cell % n + c[0]) / (float)n;
        v[3 * k + 1] = y_lo + size * (float)(cell / n + c[1]) / (float)n;
        v[3 * k + 2] = z;
    }
}

/* ---- a static scene costs nothing ---------------------------------------------- */

static void check_nothing_done(const char *file, int line)
{
    tu_check_int(geti(RT_STAT_OBJECT_UPDATES), 0, file, line, "RT_STAT_OBJECT_UPDATES", "0");
    tu_check(getf(RT_STAT_UPDATE_TIME) == 0.0f, file, line, "RT_STAT_UPDATE_TIME == 0");
    tu_check_int(geti(RT_STAT_TOPLEVEL_BUILDS), 0, file, line, "RT_STAT_TOPLEVEL_BUILDS", "0");
    tu_check_int(geti(RT_STAT_OBJECT_BUILDS), 0, file, line, "RT_STAT_OBJECT_BUILDS", "0");
    tu_check_int(geti(RT_WORKER_THREADS_RUNNING), 0, file, line, "RT_WORKER_THREADS_RUNNING",
                 "0");
}
#define CHECK_NOTHING_DONE() check_nothing_done(__FILE__, __LINE__)

static void static_scene(void)
{
    const RTuint A = 140, B = 141, C = 142;
    tu_section("a static scene costs nothing after its first frame");
    tu_ortho_camera();
    rtViewport(0, 0, 16, 16);
    CHECK(tu_define_grid(A, 16, 16, -1, -1, 0, 0, -3));
    CHECK(tu_define_box(B, (const float[3]){0, 0, -4}, (const float[3]){0.8f, 0.8f, -3}));
    CHECK(tu_define_quad(C, -1, 0, 0, 1, -5));
    for (int f = 0; f < 6; f++) {
        rtBeginFrame();
        rtInstantiateObject(A);
        rtInstantiateObject(B);
        rtPushMatrix();
        rtRotatef(10, 0, 0, 1);
        rtInstantiateObject(C);
        rtInstantiateObject(A); /* A twice */
        rtPopMatrix();
        rtRenderFrame();
        CHECK_NO_ERR();
        CHECK_INT(geti(RT_WORKER_THREADS_RUNNING), 0);
        if (f == 0) {
            CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1);
            CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 3);
            continue;
        }
        CHECK_NOTHING_DONE();
        CHECK_INT(obji(A, RT_OBJECT_CLASS), RT_STATIC);
        CHECK_INT(obji(B, RT_OBJECT_CLASS), RT_STATIC);
        CHECK_INT(obji(C, RT_OBJECT_CLASS), RT_STATIC);
        /* Queries and rtFinish in between cost nothing either. */
        tu_trace_down(-0.5f, -0.5f);
        CHECK_NOTHING_DONE();
        rtFinish();
        CHECK_NOTHING_DONE();
    }
    /* Frames with no instance issued keep the scene, also for free. */
    for (int f = 0; f < 3; f++) {
        rtRenderFrame();
        CHECK_NOTHING_DONE();
    }
    /* A moved instance costs a top-level build and no object update. */
    rtBeginFrame();
    rtInstantiateObject(A);
    rtInstantiateObject(B);
    rtTranslatef(0.25f, 0, 0);
    rtInstantiateObject(C);
    rtInstantiateObject(A);
    rtLoadIdentity();
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1);
    CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
    CHECK(getf(RT_STAT_UPDATE_TIME) == 0.0f);
    CHECK_INT(obji(C, RT_OBJECT_CLASS), RT_AFFINE);
    CHECK_INT(obji(A, RT_OBJECT_CLASS), RT_AFFINE); /* its second instance moved */
    CHECK_INT(obji(B, RT_OBJECT_CLASS), RT_STATIC);
    /* An update is counted, and its time, once per object. */
    {
        float g[3 * 4 * 16 * 16];
        grid_vertices(g, 16, -1, -1, 1, 0, -2.5f);
        CHECK_INT(obji(A, RT_OBJECT_VERTICES), 4 * 16 * 16);
        rtUpdateVertices(A, RT_VERTEX_ARRAY, 0, 4 * 16 * 16, RT_FLOAT, 0, g);
        rtRenderFrame();
        CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 1);
        CHECK(getf(RT_STAT_UPDATE_TIME) >= 0.0f);
        CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1);
        CHECK_INT(obji(A, RT_OBJECT_CLASS), RT_UNSTRUCTURED);
        {
            RTfloat ms = -1.0f;
            rtGetObjectfv(A, RT_OBJECT_UPDATE_TIME, &ms);
            CHECK(ms >= 0.0f);
        }
        /* Both instances of A are at z = -2.5 now. */
        RThit h = tu_trace(-0.53f, -0.97f, 0, 0, 0, -1);
        CHECK_INT(h.object, A);
        CHECK_NEAR(h.t, 2.5f, 1e-6);
        rtRenderFrame();
        CHECK_NOTHING_DONE();
    }
    CHECK_NO_ERR();
    rtViewport(0, 0, 0, 0);
}

/* ---- rtUpdateVertices moves hits -------------------------------------------------- */

static void update_moves_hits(void)
{
    const RTuint Q = 150;
    float v[12];
    RThit h;
    float b[6];
    tu_section("rtUpdateVertices moves hits (object space, partial, double, stride)");
    /* Defined under a modelview: the stored vertices are x in [5, 6]. */
    rtLoadIdentity();
    rtNewObject(Q);
    rtTranslatef(5, 0, 0);
    rtBegin(RT_QUADS);
    rtVertex3f(0, 0, 0);
    rtVertex3f(1, 0, 0);
    rtVertex3f(1, 1, 0);
    rtVertex3f(0, 1, 0);
    rtEnd();
    rtEndObject();
    rtLoadIdentity();
    rtBeginFrame();
    rtPushMatrix();
    rtTranslatef(0, 0, 1);
    rtInstantiateObject(Q); /* instance 0: z + 1 */
    rtPopMatrix();
    rtPushMatrix();
    rtTranslatef(20, 0, 0);
    rtScalef(1, 1, 2);
    rtInstantiateObject(Q); /* instance 1: x + 20, z * 2 */
    rtPopMatrix();
    h = tu_trace_down(5.5f, 0.5f);
    CHECK_INT(h.object, Q);
    CHECK_NEAR(h.t, 9.0f, 0.0);
    CHECK_INT(obji(Q, RT_OBJECT_VERTICES), 4);

    /* New positions are object space: neither the modelview of the
     * definition nor the current one applies. */
    rtTranslatef(100, 100, 100);
    quad_at(v, 2.0f);
    rtUpdateVertices(Q, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, v);
    rtLoadIdentity();
    CHECK_NO_ERR();
    object_bounds(Q, b);
    CHECK(b[0] == 0 && b[1] == 0 && b[2] == 2 && b[3] == 1 && b[4] == 1 && b[5] == 2);
    CHECK_INT(obji(Q, RT_OBJECT_BUILT), RT_FALSE); /* stale until prepared */
    h = tu_trace_down(0.5f, 0.5f);
    CHECK_INT(h.object, Q);
    CHECK_INT(h.instance, 0);
    CHECK_NEAR(h.t, 7.0f, 0.0); /* 10 - (2 + 1) */
    CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 1);
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 1); /* the object's box changed */
    CHECK_INT(obji(Q, RT_OBJECT_BUILT), RT_TRUE);
    h = tu_trace_down(5.5f, 0.5f);
    CHECK(h.t == tu_inf());
    CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
    CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);
    h = tu_trace_down(20.5f, 0.5f);
    CHECK_INT(h.instance, 1);
    CHECK_NEAR(h.t, 6.0f, 0.0); /* 10 - 2 * 2 */
    h = tu_trace(0.5f, 0.5f, -10, 0, 0, 1); /* from below */
    CHECK_NEAR(h.t, 13.0f, 0.0);
    {
        static const float a[3] = {0, 0, 3}, bb[3] = {1, 0, 3}, c[3] = {1, 1, 3}, d[3] = {0, 1, 3};
        CHECK_TRIANGLE(a, bb, c, 0, Q, 0);
        CHECK_TRIANGLE(a, c, d, 1, Q, 0);
    }

    /* A partial update: vertex 2 alone goes up to (1, 1, 3).  Triangle 0
     * (0,0,2) (1,0,2) (1,1,3) is the plane z = 2 + y, triangle 1 (0,0,2)
     * (1,1,3) (0,1,2) the plane z = 2 + x. */
    {
        const float v2[3] = {1, 1, 3};
        rtUpdateVertices(Q, RT_VERTEX_ARRAY, 2, 1, RT_FLOAT, 0, v2);
        h = tu_trace_down(0.5f, 0.25f);
        CHECK_INT(h.primitive, 0);
        CHECK_NEAR(h.t, 10.0f - 3.25f, 1e-6);
        h = tu_trace_down(0.25f, 0.5f);
        CHECK_INT(h.primitive, 1);
        CHECK_NEAR(h.t, 10.0f - 3.25f, 1e-6);
        h = tu_trace_down(20.5f, 0.25f);
        CHECK_NEAR(h.t, 10.0f - 2 * 2.25f, 1e-6);
    }

    /* Beyond the old bounds: vertex 1 to (2, 0, 2).  The ray at x = 1.8
     * is outside the box the object had, so this needs the top level and
     * the object BVH both refreshed. */
    {
        const double v1[3] = {2, 0, 2};
        rtUpdateVertices(Q, RT_VERTEX_ARRAY, 1, 1, RT_DOUBLE, 0, v1);
        h = tu_trace_down(1.8f, 0.05f);
        CHECK_INT(h.object, Q);
        CHECK_INT(h.primitive, 0);
        CHECK_NEAR(h.t, 10.0f - 3.05f, 1e-5);
        object_bounds(Q, b);
        CHECK(b[3] == 2 && b[5] == 3);
    }

    /* Doubles with a stride: {tag, x, y, z} records. */
    {
        double rec[4][4];
        for (int k = 0; k < 4; k++) {
            rec[k][0] = tu_nan_d(); /* never read */
            rec[k][1] = (k == 1 || k == 2) ? 1.0 : 0.0;
            rec[k][2] = (k >= 2) ? 1.0 : 0.0;
            rec[k][3] = -0.5;
        }
        rtUpdateVertices(Q, RT_VERTEX_ARRAY, 0, 4, RT_DOUBLE, sizeof rec[0], &rec[0][1]);
        CHECK_NO_ERR();
        h = tu_trace_down(0.5f, 0.5f);
        CHECK_NEAR(h.t, 9.5f, 0.0); /* z = -0.5 + 1 */
        h = tu_trace_down(20.7f, 0.2f);
        CHECK_NEAR(h.t, 11.0f, 0.0); /* z = -0.5 * 2 */
    }
    /* Floats with a stride larger than an element. */
    {
        float rec[4][5];
        for (int k = 0; k < 4; k++) {
            rec[k][0] = (k == 1 || k == 2) ? 1.0f : 0.0f;
            rec[k][1] = (k >= 2) ? 1.0f : 0.0f;
            rec[k][2] = 4.0f;
            rec[k][3] = tu_inf(); /* never read */
            rec[k][4] = tu_nan();
        }
        rtUpdateVertices(Q, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, sizeof rec[0], rec);
        CHECK_NO_ERR();
        CHECK_NEAR(tu_trace_down(0.5f, 0.5f).t, 5.0f, 0.0);
    }
    /* Two updates without a frame in between: the last one counts, one
     * update is made. */
    quad_at(v, 1.0f);
    rtUpdateVertices(Q, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, v);
    quad_at(v, 0.5f);
    rtUpdateVertices(Q, RT_VERTEX_ARRAY, 0, 3, RT_FLOAT, 0, v);
    rtFinish();
    CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 1);
    h = tu_trace_down(0.7f, 0.2f); /* triangle 0: all at 0.5 */
    CHECK_NEAR(h.t, 8.5f, 0.0);
    h = tu_trace_down(0.02f, 0.9f); /* triangle 1: vertex 3 still at z = 1 */
    CHECK_INT(h.primitive, 1);
    CHECK(h.t < 8.5f && h.t > 8.0f);
    CHECK_NO_ERR();
}

/* ---- vertex numbering ---------------------------------------------------------------- */

static void vertex_numbering(void)
{
    tu_section("vertex numbering: recording order; rtDrawElements element min + k");
    /* rtBegin: every vertex counts, those of an incomplete primitive too. */
    {
        const RTuint T = 160;
        rtNewObject(T);
        rtBegin(RT_TRIANGLES);
        rtVertex3f(0, 0, 0);
        rtVertex3f(1, 0, 0);
        rtVertex3f(0, 1, 0);
        rtVertex3f(5, 5, 5); /* incomplete: stored, used by no triangle */
        rtVertex3f(6, 6, 6);
        rtEnd();
        rtBegin(RT_TRIANGLE_STRIP); /* 5 vertices, 3 triangles */
        for (int k = 0; k < 5; k++)
            rtVertex3f(2.0f + (float)(k / 2), (float)(k % 2), 0);
        rtEnd();
        rtEndObject();
        CHECK_INT(obji(T, RT_OBJECT_VERTICES), 10);
        CHECK_INT(obji(T, RT_OBJECT_TRIANGLES), 4);
        CHECK(tu_scene1(T));
        {
            const float unused[6] = {7, 7, 7, 9, 9, 9};
            float b[6];
            rtUpdateVertices(T, RT_VERTEX_ARRAY, 3, 2, RT_FLOAT, 0, unused);
            CHECK_NO_ERR();
            object_bounds(T, b); /* unused vertices do not count */
            CHECK(b[3] == 4 && b[4] == 1 && b[5] == 0);
        }
        /* Strip vertex k is object vertex 5 + k; strip vertex 2, (3, 0, 0),
         * goes up to (3, 0, 1): the strip's first triangle (2,0,0) (2,1,0)
         * (3,0,1), object triangle 1, is the plane z = x - 2. */
        {
            const float up[3] = {3, 0, 1};
            RThit h;
            rtUpdateVertices(T, RT_VERTEX_ARRAY, 7, 1, RT_FLOAT, 0, up);
            h = tu_trace_down(2.5f, 0.2f);
            CHECK_INT(h.primitive, 1);
            CHECK_NEAR(h.t, 9.5f, 1e-6);
        }
        rtUpdateVertices(T, RT_VERTEX_ARRAY, 10, 1, RT_FLOAT, 0, (const float[3]){0, 0, 0});
        CHECK_ERR(RT_INVALID_VALUE);
    }
    /* rtDrawElements: vertex k is element min + k; unused elements in the
     * range count, as the origin, and are used by no triangle. */
    {
        const RTuint D = 161;
        static const float elements[9][3] = {
            {9, 9, 9}, {9, 9, 9}, {9, 9, 9}, {9, 9, 9}, /* 0..3: below the range */
            {0, 0, 0},                                  /* 4 -> vertex 0 */
            {9, 9, 9},                                  /* 5 -> vertex 1, unused */
            {0, 1, 0},                                  /* 6 -> vertex 2 */
            {1, 0, 0},                                  /* 7 -> vertex 3 */
            {9, 9, 9}};                                 /* 8: above the range */
        static const RTubyte idx[3] = {4, 7, 6};
        static const RTushort idx2[3] = {1, 0, 2};
        rtVertexPointer(3, RT_FLOAT, 0, elements);
        rtEnableClientState(RT_VERTEX_ARRAY);
        rtNewObject(D);
        rtDrawElements(RT_TRIANGLES, 3, RT_UNSIGNED_BYTE, idx);
        rtTranslatef(10, 0, 0);
        rtDrawElements(RT_TRIANGLES, 3, RT_UNSIGNED_SHORT, idx2); /* vertices 4..6 */
        rtLoadIdentity();
        rtEndObject();
        rtDisableClientState(RT_VERTEX_ARRAY);
        CHECK_NO_ERR();
        CHECK_INT(obji(D, RT_OBJECT_VERTICES), 4 + 3);
        CHECK_INT(obji(D, RT_OBJECT_TRIANGLES), 2);
        CHECK(tu_scene1(D));
        {
            const float a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0};
            CHECK_TRIANGLE(a, b, c, 0, D, 0);
        }
        /* Vertex 3 is element 7, (1, 0, 0): to (2, 0, 0). */
        {
            const float v3[3] = {2, 0, 0};
            const float a[3] = {0, 0, 0}, b[3] = {2, 0, 0}, c[3] = {0, 1, 0};
            rtUpdateVertices(D, RT_VERTEX_ARRAY, 3, 1, RT_FLOAT, 0, v3);
            CHECK_TRIANGLE(a, b, c, 0, D, 0);
        }
        /* Vertex 1 (element 5, unused) moves nothing. */
        {
            const float v1[3] = {-5, -5, 3};
            float bb[6];
            rtUpdateVertices(D, RT_VERTEX_ARRAY, 1, 1, RT_FLOAT, 0, v1);
            object_bounds(D, bb);
            CHECK(bb[0] == 0 && bb[1] == 0 && bb[2] == 0);
            CHECK_NEAR(tu_trace_down(0.3f, 0.3f).t, 10.0f, 0.0);
        }
        /* The second call's elements 0, 1, 2 are vertices 4, 5, 6, stored
         * under its modelview (x + 10); its triangle is (5, 4, 6). */
        {
            const float v[9] = {10, 0, 1, 11, 0, 1, 10, 1, 1};
            const float a[3] = {11, 0, 1}, b[3] = {10, 0, 1}, c[3] = {10, 1, 1};
            rtUpdateVertices(D, RT_VERTEX_ARRAY, 4, 3, RT_FLOAT, 0, v);
            CHECK_TRIANGLE(a, b, c, 1, D, 0);
        }
        CHECK_NO_ERR();
    }
    /* rtDrawArrays: vertex k is element first + k. */
    {
        const RTuint R = 162;
        static const float elements[6][3] = {{9, 9, 9}, {9, 9, 9}, {0, 0, 0},
                                             {1, 0, 0}, {0, 1, 0}, {9, 9, 9}};
        rtVertexPointer(3, RT_FLOAT, 0, elements);
        rtEnableClientState(RT_VERTEX_ARRAY);
        rtNewObject(R);
        rtDrawArrays(RT_TRIANGLES, 2, 3);
        rtEndObject();
        rtDisableClientState(RT_VERTEX_ARRAY);
        rtVertexPointer(3, RT_FLOAT, 0, NULL);
        CHECK_INT(obji(R, RT_OBJECT_VERTICES), 3);
        CHECK(tu_scene1(R));
        {
            const float v0[3] = {0, 0, 1};
            const float a[3] = {0, 0, 1}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0};
            rtUpdateVertices(R, RT_VERTEX_ARRAY, 0, 1, RT_FLOAT, 0, v0);
            CHECK_TRIANGLE(a, b, c, 0, R, 0);
        }
    }
    CHECK_NO_ERR();
}

/* ---- normals ----------------------------------------------------------------------- */

static void normal_updates(void)
{
    const RTuint N = 170;
    float rgba[4 * 4 * 4];
    tu_section("a normal update changes eye-light shading and nothing else");
    tu_ortho_camera();
    rtShadingMode(RT_EYE_LIGHT);
    rtNewObject(N);
    rtNormal3f(0, 0, 1);
    rtBegin(RT_QUADS);
    rtVertex3f(-2, -2, -5);
    rtVertex3f(2, -2, -5);
    rtVertex3f(2, 2, -5);
    rtVertex3f(-2, 2, -5);
    rtEnd();
    rtEndObject();
    rtBeginFrame();
    rtInstantiateObject(N);
    tu_render_float(4, 4, rgba);
    /* Eye light: emission + ambient * global ambient + diffuse * |n . d|,
     * defaults 0 + 0.2 * 0.2 + 0.8 * 1. */
    CHECK_NEAR(rgba[4 * 5], 0.84f, 1e-6);
    rtRenderFrame();
    CHECK_INT(obji(N, RT_OBJECT_CLASS), RT_STATIC);

    /* Tilt every normal 45 degrees: 0.04 + 0.8 * cos 45. */
    {
        const float n[12] = {1, 0, 1, 1, 0, 1, 1, 0, 1, 1, 0, 1};
        rtUpdateVertices(N, RT_NORMAL_ARRAY, 0, 4, RT_FLOAT, 0, n);
        CHECK_NO_ERR();
        /* Shading data only: the structure stays up to date. */
        CHECK_INT(obji(N, RT_OBJECT_BUILT), RT_TRUE);
        tu_render_float(4, 4, rgba);
        CHECK_NEAR(rgba[4 * 5], 0.04 + 0.8 * sqrt(0.5), 1e-6);
        CHECK_NEAR(rgba[4 * 10 + 2], 0.04 + 0.8 * sqrt(0.5), 1e-6);
        CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
        CHECK_INT(geti(RT_STAT_TOPLEVEL_BUILDS), 0);
        CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 0);
        CHECK_INT(obji(N, RT_OBJECT_CLASS), RT_STATIC);
        CHECK_NEAR(tu_trace(0, 0, 0, 0, 0, -1).t, 5.0f, 0.0);
    }
    /* Doubles with a stride; a normal is not normalised when stored, only
     * its direction matters: (0, 3, 4) gives |n . d| = 0.8. */
    {
        double n[4][4];
        for (int k = 0; k < 4; k++) {
            n[k][0] = 0;
            n[k][1] = 3;
            n[k][2] = 4;
            n[k][3] = tu_nan_d();
        }
        rtUpdateVertices(N, RT_NORMAL_ARRAY, 0, 4, RT_DOUBLE, sizeof n[0], n);
        CHECK_NO_ERR();
        tu_render_float(4, 4, rgba);
        CHECK_NEAR(rgba[4 * 5 + 1], 0.04 + 0.8 * 0.8, 1e-6);
    }
    /* A rejected normal batch changes nothing. */
    {
        const float n[12] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0};
        float bad[12];
        memcpy(bad, n, sizeof bad);
        bad[11] = tu_nan();
        rtUpdateVertices(N, RT_NORMAL_ARRAY, 0, 4, RT_FLOAT, 0, bad);
        CHECK_ERR(RT_INVALID_VALUE);
        tu_render_float(4, 4, rgba);
        CHECK_NEAR(rgba[4 * 5 + 1], 0.04 + 0.8 * 0.8, 1e-6);
    }
    CHECK_NO_ERR();
}

/* ---- when updates happen; the per-object counters --------------------------------- */

static RTint refits(RTuint o)
{
    return obji(o, RT_OBJECT_REFITS);
}

static RTint rebuilds(RTuint o)
{
    return obji(o, RT_OBJECT_REBUILDS);
}

static void lazy_and_counters(void)
{
    const RTuint G = 180, L = 181, N = 182;
    float z[3 * 4 * 8 * 8];
    tu_section("updates when prepared, only of stale structures; refit and rebuild counts");
    /* G: an 8 x 8 grid (256 vertices) with the RT_REFIT hint. */
    CHECK(tu_define_grid(G, 8, 8, 0, 0, 1, 1, 0));
    CHECK(tu_define_quad(L, 0, 0, 1, 1, 0));
    CHECK(tu_define_quad(N, 0, 0, 1, 1, 0));
    rtObjectParameteri(G, RT_UPDATE_STRATEGY, RT_REFIT);
    CHECK_INT(obji(G, RT_OBJECT_VERTICES), 256);
    rtBeginFrame();
    rtInstantiateObject(G);
    rtTranslatef(2, 0, 0);
    rtInstantiateObject(G); /* twice */
    rtTranslatef(2, 0, 0);
    rtInstantiateObject(L);
    rtTranslatef(2, 0, 0);
    rtInstantiateObject(N);
    rtLoadIdentity();
    rtFinish();
    /* Nothing was built: construction is lazy. */
    CHECK_INT(obji(G, RT_OBJECT_BUILT), RT_FALSE);
    CHECK_INT(obji(G, RT_OBJECT_REBUILDS), 0);
    CHECK_INT(obji(G, RT_OBJECT_REFITS), 0);
    CHECK_NEAR(tu_trace_down(0.5f, 0.5f).t, 10.0f, 0.0);
    CHECK_NEAR(tu_trace_down(6.5f, 0.5f).t, 10.0f, 0.0);
    CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 1);
    CHECK_INT(obji(G, RT_OBJECT_BUILT), RT_TRUE);
    CHECK_INT(obji(N, RT_OBJECT_BUILT), RT_TRUE);
    CHECK_INT(obji(L, RT_OBJECT_BUILT), RT_FALSE);
    CHECK_INT(rebuilds(G), 1); /* the first build */
    CHECK_INT(refits(G), 0);

    /* A never-built object that is updated stays lazy; built when a ray
     * needs it. */
    {
        float v[12];
        quad_at(v, 1.0f);
        rtUpdateVertices(L, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, v);
        rtFinish();
        CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
        CHECK_INT(obji(L, RT_OBJECT_BUILT), RT_FALSE);
        CHECK_NEAR(tu_trace_down(4.5f, 0.5f).t, 9.0f, 0.0);
        CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 1);
        CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
        CHECK_INT(obji(L, RT_OBJECT_BUILT), RT_TRUE);
        CHECK_INT(rebuilds(L), 1);
    }

    /* Same-topology redefinition under RT_REFIT: kept, refit when prepared;
     * two instances, one update. */
    CHECK(tu_define_grid(G, 8, 8, 0, 0, 1, 1, 0.5f));
    CHECK_INT(obji(G, RT_OBJECT_BUILT), RT_FALSE);
    rtFinish();
    CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 1);
    CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 0);
    CHECK_INT(obji(G, RT_OBJECT_BUILT), RT_TRUE);
    CHECK_INT(obji(G, RT_UPDATE_STRATEGY), RT_REFIT);
    CHECK_INT(refits(G), 1);
    CHECK_INT(rebuilds(G), 1);
    CHECK_NEAR(tu_trace_down(0.5f, 0.5f).t, 9.5f, 0.0);
    CHECK_NEAR(tu_trace_down(2.5f, 0.5f).t, 9.5f, 0.0);

    /* rtUpdateVertices under RT_REFIT: a refit too. */
    grid_vertices(z, 8, 0, 0, 1, 0, 1.0f);
    rtUpdateVertices(G, RT_VERTEX_ARRAY, 0, 4 * 8 * 8, RT_FLOAT, 0, z);
    rtRenderFrame();
    CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 1);
    CHECK_INT(refits(G), 2);
    CHECK_INT(rebuilds(G), 1);
    CHECK_NEAR(tu_trace_down(0.5f, 0.5f).t, 9.0f, 0.0);

    /* Same vertex count, other triangles (a strip instead of quads): a
     * topology change, so a rebuild, lazily. */
    grid_vertices(z, 8, 0, 0, 1, 1, 0.25f);
    rtNewObject(G);
    for (int c = 0; c < 64; c++) {
        rtBegin(RT_TRIANGLE_STRIP);
        for (int k = 0; k < 4; k++)
            rtVertex3fv(&z[3 * (4 * c + k)]);
        rtEnd();
    }
    rtEndObject();
    CHECK_INT(obji(G, RT_OBJECT_VERTICES), 256);
    rtFinish();
    CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
    CHECK_INT(obji(G, RT_OBJECT_BUILT), RT_FALSE);
    CHECK_NEAR(tu_trace_down(0.5f, 0.5f).t, 9.75f, 0.0);
    CHECK_INT(geti(RT_STAT_OBJECT_BUILDS), 1);
    CHECK_INT(rebuilds(G), 2);
    CHECK_INT(refits(G), 2);

    /* The other strategies, through rtUpdateVertices. */
    {
        static const RTenum rebuild_strategies[] = {RT_REBUILD, RT_REBUILD_MEDIAN};
        for (int i = 0; i < 2; i++) {
            RTint r0 = rebuilds(G), f0 = refits(G);
            rtObjectParameteri(G, RT_UPDATE_STRATEGY, (RTint)rebuild_strategies[i]);
            grid_vertices(z, 8, 0, 0, 1, 1, (float)i);
            rtUpdateVertices(G, RT_VERTEX_ARRAY, 0, 4 * 8 * 8, RT_FLOAT, 0, z);
            rtFinish();
            CHECK_INT(obji(G, RT_UPDATE_STRATEGY), rebuild_strategies[i]);
            CHECK_INT(rebuilds(G), r0 + 1);
            CHECK_INT(refits(G), f0);
            CHECK_NEAR(tu_trace_down(0.3f, 0.6f).t, 10.0f - (float)i, 0.0);
        }
    }
    {
        RTint r0 = rebuilds(G), f0 = refits(G);
        rtObjectParameteri(G, RT_UPDATE_STRATEGY, RT_RESTRUCTURE);
        grid_vertices(z, 8, 0, 0, 1, 1, 2.0f);
        rtUpdateVertices(G, RT_VERTEX_ARRAY, 0, 4 * 8 * 8, RT_FLOAT, 0, z);
        rtFinish();
        CHECK_INT(obji(G, RT_UPDATE_STRATEGY), RT_RESTRUCTURE);
        CHECK_INT(refits(G), f0 + 1); /* restructuring counts as a refit */
        CHECK_INT(rebuilds(G), r0);
        CHECK_NEAR(tu_trace_down(0.3f, 0.6f).t, 8.0f, 0.0);
    }
    {
        RTint r0 = rebuilds(G), f0 = refits(G);
        rtObjectParameteri(G, RT_UPDATE_STRATEGY, RT_REBUILD_HEURISTIC);
        grid_vertices(z, 8, 0, 0, 1, 1, 3.0f);
        rtUpdateVertices(G, RT_VERTEX_ARRAY, 0, 4 * 8 * 8, RT_FLOAT, 0, z);
        rtFinish();
        CHECK_INT(obji(G, RT_UPDATE_STRATEGY), RT_REBUILD_HEURISTIC);
        /* A rigid move keeps the SAH cost: refit only. */
        CHECK_INT(refits(G), f0 + 1);
        CHECK_INT(rebuilds(G), r0);
        CHECK_NEAR(tu_trace_down(0.3f, 0.6f).t, 7.0f, 0.0);
    }

    /* An updated object that is not in the scene is not updated ... */
    {
        float v[12];
        quad_at(v, 2.0f);
        rtUpdateVertices(N, RT_VERTEX_ARRAY, 0, 4, RT_FLOAT, 0, v);
        rtBeginFrame();
        rtInstantiateObject(G);
        rtRenderFrame();
        CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 0);
        CHECK_INT(obji(N, RT_OBJECT_BUILT), RT_FALSE);
        /* ... until it is back. */
        rtBeginFrame();
        rtInstantiateObject(G);
        rtTranslatef(6, 0, 0);
        rtInstantiateObject(N);
        rtLoadIdentity();
        rtRenderFrame();
        CHECK_INT(geti(RT_STAT_OBJECT_UPDATES), 1);
        CHECK_INT(obji(N, RT_OBJECT_BUILT), RT_TRUE);
        CHECK_NEAR(tu_trace_down(6.5f, 0.5f).t, 8.0f, 0.0);
    }

    /* The per-object times and counts are read as documented. */
    {
        RTfloat ms = -1.0f, fv = -1.0f;
        RTint iv = -7;
        rtGetObjectfv(G, RT_OBJECT_UPDATE_TIME, &ms);
        CHECK(ms >= 0.0f);
        rtGetObjectiv(G, RT_OBJECT_UPDATE_TIME, &iv);
        CHECK_ERR(RT_INVALID_ENUM);
        CHECK_INT(iv, -7);
        rtGetObjectfv(G, RT_OBJECT_REFITS, &fv);
        CHECK_NEAR(fv, (float)refits(G), 0.0);
        rtGetIntegerv(RT_STAT_UPDATE_TIME, &iv);
        CHECK_ERR(RT_INVALID_ENUM);
        CHECK_INT(iv, -7);
        CHECK_NEAR(getf(RT_STAT_OBJECT_UPDATES), 0.0f, 0.0);
        rtGetObjectiv(G, RT_OBJECT_VERTICES, NULL);
        CHECK_ERR(RT_INVALID_VALUE);
    }
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=1");
    tu_capture_errors();
    object_parameter_errors(ctx);
    update_vertices_errors(ctx);
    empty_updates();
    render_parameter_errors();
    classification();
    static_scene();
    update_moves_hits();
    vertex_numbering();
    normal_updates();
    lazy_and_counters();
    tu_section("a threads=1 context never starts a thread");
    CHECK_INT(geti(RT_WORKER_THREADS_RUNNING), 0);
    tu_destroy_context(ctx);
    return test_summary("dynamic");
}
