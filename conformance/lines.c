/* SPDX-License-Identifier: Apache-2.0 */
/*
 * lines.c - conformance: RT_POINTS, RT_LINES, RT_LINE_STRIP, RT_LINE_LOOP,
 * rtLineWidth, rtPointSize and rtPolygonMode.  GL's pixel rules for
 * width-1 segments (diamond exit, checked against a brute-force
 * evaluation of the rule), wide segments and points; lines hidden behind
 * surfaces and visible in front; polygon outlines without the
 * triangulation's diagonals; widths recorded in objects; vertex arrays;
 * state queries and errors.
 *
 * The camera is rtOrtho(0, N, 0, N, -1, 1) on an N x N viewport, so one
 * unit is one pixel and pixel (x, y) has its centre at (x + 0.5, y + 0.5).
 *
 * Reference: docs/lines.md.
 */
#include "testutil.h"

#include <math.h>
#include <string.h>

#define N 24
#define OBJ 700u
#define QUAD 701u

static float img[4 * N * N];

static void window_camera(void)
{
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtOrtho(0.0, N, 0.0, N, -1.0, 1.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
}

static void render(void)
{
    rtClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    tu_render_float(N, N, img);
}

static const float *px(int x, int y)
{
    return &img[4 * (y * N + x)];
}

static int lit(int x, int y)
{
    const float *p = px(x, y);
    return p[0] > 0.0f || p[1] > 0.0f || p[2] > 0.0f;
}

static int count_lit(void)
{
    int n = 0;
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++)
            n += lit(x, y);
    return n;
}

/* Renders object OBJ alone. */
static void render_object(void)
{
    rtBeginFrame();
    rtInstantiateObject(OBJ);
    render();
}

static void segment_object(RTenum mode, const float *xy, int n, float width)
{
    rtNewObject(OBJ);
    if (width > 0.0f)
        rtLineWidth(width);
    rtColor3f(1.0f, 1.0f, 1.0f);
    rtBegin(mode);
    for (int i = 0; i < n; i++)
        rtVertex3f(xy[2 * i], xy[2 * i + 1], 0.0f);
    rtEnd();
    rtEndObject();
}

/* The diamond-exit rule by brute force (OpenGL 2.1 sec. 3.4.1): a
 * fragment when the segment, sampled densely, comes within L1 distance
 * 1/2 of the pixel centre and its end point does not. */
static int diamond_fragment(const float a[2], const float b[2], int x, int y)
{
    double cx = x + 0.5, cy = y + 0.5;
    if (fabs(b[0] - cx) + fabs(b[1] - cy) < 0.5)
        return 0;
    for (int i = 0; i <= 20000; i++) {
        double t = i / 20000.0;
        double px_ = a[0] + t * (b[0] - a[0]), py_ = a[1] + t * (b[1] - a[1]);
        if (fabs(px_ - cx) + fabs(py_ - cy) < 0.5 - 1e-6)
            return 1;
    }
    return 0;
}

static void width_one(void)
{
    tu_section("width 1: the diamond-exit rule");
    window_camera();
    /* Segments at several slopes, ends off the pixel grid (never on a
     * diamond's edge, so the brute force needs no perturbation). */
    static const float segs[][4] = {{1.2f, 1.7f, 20.8f, 6.1f},  {3.3f, 21.4f, 7.9f, 2.2f},
                                    {2.6f, 12.3f, 22.1f, 13.9f}, {19.7f, 3.1f, 11.2f, 20.6f},
                                    {5.4f, 5.6f, 17.3f, 17.6f},  {4.5f, 8.5f, 14.5f, 8.5f}};
    for (size_t s = 0; s < sizeof segs / sizeof segs[0]; s++) {
        segment_object(RT_LINES, segs[s], 2, 0.0f);
        render_object();
        int wrong = 0, expected = 0;
        for (int y = 0; y < N; y++)
            for (int x = 0; x < N; x++) {
                int want = diamond_fragment(segs[s], segs[s] + 2, x, y);
                expected += want;
                wrong += want != lit(x, y);
            }
        CHECKF(wrong == 0 && expected > 0, "segment %zu: %d pixels differ from the rule (%d)", s,
               wrong, expected);
    }
    /* Through pixel centres: the first pixel is drawn, the last not. */
    static const float h[4] = {4.5f, 8.5f, 14.5f, 8.5f};
    segment_object(RT_LINES, h, 2, 0.0f);
    render_object();
    CHECK(lit(4, 8) && lit(13, 8) && !lit(14, 8) && !lit(3, 8) && !lit(8, 7) && !lit(8, 9));
    CHECK_INT(count_lit(), 10);
    CHECK_INT(tu_object_triangles(OBJ), 0);
    CHECK_NO_ERR();
}

static void wide_and_points(void)
{
    tu_section("wide lines: columns and rows of width pixels; points");
    window_camera();
    /* x-major, width 3: the segment shifted down by 1, each fragment a
     * column of 3 upwards: rows 7, 8, 9 over x = 2 .. 11. */
    static const float h[4] = {2.5f, 8.5f, 12.5f, 8.5f};
    segment_object(RT_LINES, h, 2, 3.0f);
    render_object();
    int ok = 1;
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++)
            ok &= lit(x, y) == (x >= 2 && x <= 11 && y >= 7 && y <= 9);
    CHECK(ok);
    /* y-major, width 2: shifted left by 1/2 onto the pixel edge x = 10,
     * which the spec's perturbation -(eps, eps^2) puts in column 9; rows
     * of 2 to the right (OSMesa draws columns 9 and 10 too: the overlay
     * oracle's crosshair scene). */
    static const float v[4] = {10.5f, 3.5f, 10.5f, 9.5f};
    segment_object(RT_LINES, v, 2, 2.0f);
    render_object();
    ok = 1;
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++)
            ok &= lit(x, y) == (y >= 3 && y <= 8 && (x == 9 || x == 10));
    CHECK(ok);
    CHECKF(count_lit() == 12, "width 2 y-major: %d pixels (12)", count_lit());
    CHECK(lit(10, 3) && lit(10, 8) && !lit(10, 9) && !lit(10, 2));
    /* Points: size 1 covers the pixel holding it; odd sizes centre there,
     * even sizes on the nearest pixel corner. */
    rtNewObject(OBJ);
    rtColor3f(1.0f, 1.0f, 1.0f);
    rtPointSize(1.0f);
    rtBegin(RT_POINTS);
    rtVertex2f(3.3f, 20.7f);
    rtEnd();
    rtPointSize(4.0f);
    rtBegin(RT_POINTS);
    rtVertex2f(8.2f, 12.6f);
    rtEnd();
    rtPointSize(3.0f);
    rtBegin(RT_POINTS);
    rtVertex2f(17.4f, 3.8f);
    rtEnd();
    rtEndObject();
    render_object();
    ok = 1;
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++) {
            int want = (x == 3 && y == 20) || (x >= 6 && x <= 9 && y >= 11 && y <= 14) ||
                       (x >= 16 && x <= 18 && y >= 2 && y <= 4);
            ok &= lit(x, y) == want;
        }
    CHECK(ok);
    CHECK_INT(count_lit(), 1 + 16 + 9);
    CHECK_NO_ERR();
}

static void quad_object(RTuint name, float z, float r, float g, float b)
{
    const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f}, emission[4] = {r, g, b, 1.0f};
    rtNewObject(name);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, emission);
    rtBegin(RT_QUADS);
    rtVertex3f(0.0f, 0.0f, z);
    rtVertex3f(12.0f, 0.0f, z);
    rtVertex3f(12.0f, (float)N, z);
    rtVertex3f(0.0f, (float)N, z);
    rtEnd();
    rtEndObject();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
}

static void hidden(void)
{
    tu_section("lines hidden behind surfaces, visible in front");
    window_camera();
    quad_object(QUAD, 0.0f, 0.0f, 0.0f, 1.0f); /* blue, left half, z = 0 */
    rtNewObject(OBJ);
    rtColor3f(1.0f, 0.0f, 0.0f);
    rtBegin(RT_LINES);
    rtVertex3f(0.5f, 5.5f, -0.5f); /* behind the quad */
    rtVertex3f(23.5f, 5.5f, -0.5f);
    rtEnd();
    rtColor3f(0.0f, 1.0f, 0.0f);
    rtBegin(RT_LINE_STRIP);
    rtVertex3f(0.5f, 15.5f, 0.5f); /* in front */
    rtVertex3f(23.5f, 15.5f, 0.5f);
    rtEnd();
    rtColor3f(1.0f, 1.0f, 0.0f);
    rtBegin(RT_LINES);
    rtVertex3f(0.5f, 10.5f, -0.5f); /* through it */
    rtVertex3f(23.5f, 10.5f, 0.5f);
    rtEnd();
    rtEndObject();
    rtBeginFrame();
    rtInstantiateObject(QUAD);
    rtInstantiateObject(OBJ);
    render();
    CHECK(px(5, 5)[2] == 1.0f && px(5, 5)[0] == 0.0f);   /* hidden: the quad */
    CHECK(px(18, 5)[0] == 1.0f && px(18, 5)[2] == 0.0f); /* beside it: the line */
    CHECK(px(5, 15)[1] == 1.0f && px(5, 15)[2] == 0.0f); /* in front */
    /* The piercing line crosses z = 0 at x = 12: the quad's edge. */
    CHECK(px(6, 10)[2] == 1.0f && px(6, 10)[0] == 0.0f);
    CHECK(px(14, 10)[0] == 1.0f && px(14, 10)[1] == 1.0f);
    /* Without the quad the hidden line shows everywhere. */
    render_object();
    CHECK(px(5, 5)[0] == 1.0f);
    CHECK_NO_ERR();
}

static void outline_quad(RTenum mode)
{
    rtNewObject(OBJ);
    rtPolygonMode(RT_FRONT_AND_BACK, mode);
    rtPointSize(1.0f);
    rtColor3f(1.0f, 1.0f, 1.0f);
    rtBegin(RT_QUADS);
    rtVertex2f(2.5f, 2.5f);
    rtVertex2f(12.5f, 2.5f);
    rtVertex2f(12.5f, 12.5f);
    rtVertex2f(2.5f, 12.5f);
    rtEnd();
    rtEndObject();
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
}

static void polygon_modes(void)
{
    tu_section("rtPolygonMode: outlines with GL's edges, vertices as points");
    window_camera();
    /* Instancing the objects above executed their rtLineWidth (as
     * glCallList does): back to width 1. */
    rtLineWidth(1.0f);
    outline_quad(RT_LINE);
    render_object();
    /* The boundary, not the diagonal (2.5, 2.5)-(12.5, 12.5). */
    CHECK(lit(2, 2) && lit(7, 2) && lit(12, 7) && lit(7, 12) && lit(2, 7));
    CHECK(!lit(7, 7) && !lit(5, 5));
    CHECK_INT(count_lit(), 40);
    /* Triangles that keep the mode: the object leaves RT_CULL_FACE to its
     * call (polygon_modes_call_culling). */
    CHECK_INT(tu_object_triangles(OBJ), 2);
    /* The same two triangles as RT_TRIANGLES draw the diagonal too. */
    rtNewObject(OBJ);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_LINE);
    rtColor3f(1.0f, 1.0f, 1.0f);
    rtBegin(RT_TRIANGLES);
    rtVertex2f(2.5f, 2.5f);
    rtVertex2f(12.5f, 2.5f);
    rtVertex2f(12.5f, 12.5f);
    rtVertex2f(2.5f, 2.5f);
    rtVertex2f(12.5f, 12.5f);
    rtVertex2f(2.5f, 12.5f);
    rtEnd();
    rtEndObject();
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    render_object();
    CHECK(lit(7, 7) && lit(5, 5));
    /* A quad strip outlines each quad: the rung between them, no
     * diagonals. */
    rtNewObject(OBJ);
    rtPolygonMode(RT_FRONT, RT_LINE);
    rtPolygonMode(RT_BACK, RT_LINE);
    rtColor3f(1.0f, 1.0f, 1.0f);
    rtBegin(RT_QUAD_STRIP);
    for (int i = 0; i < 3; i++) {
        rtVertex2f(2.5f + 8.0f * (float)i, 2.5f);
        rtVertex2f(2.5f + 8.0f * (float)i, 10.5f);
    }
    rtEnd();
    rtEndObject();
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    render_object();
    CHECK(lit(10, 6) && !lit(6, 6) && !lit(14, 6) && !lit(8, 8));
    /* Points: the four vertices. */
    outline_quad(RT_POINT);
    render_object();
    CHECK(lit(2, 2) && lit(12, 2) && lit(12, 12) && lit(2, 12));
    CHECK_INT(count_lit(), 4);
    /* Fill is triangles again. */
    outline_quad(RT_FILL);
    CHECK_INT(tu_object_triangles(OBJ), 2);
    CHECK_NO_ERR();
}

/* A counter-clockwise quad on the left, a clockwise one on the right. */
static void two_windings(void)
{
    rtColor3f(1.0f, 1.0f, 1.0f);
    rtBegin(RT_QUADS);
    rtVertex2f(2.5f, 2.5f);
    rtVertex2f(10.5f, 2.5f);
    rtVertex2f(10.5f, 10.5f);
    rtVertex2f(2.5f, 10.5f);
    rtVertex2f(13.5f, 2.5f);
    rtVertex2f(13.5f, 10.5f);
    rtVertex2f(21.5f, 10.5f);
    rtVertex2f(21.5f, 2.5f);
    rtEnd();
}

static void per_face_object(RTenum cull)
{
    rtNewObject(OBJ);
    rtPolygonMode(RT_FRONT, RT_FILL);
    rtPolygonMode(RT_BACK, RT_LINE);
    if (cull) {
        rtEnable(RT_CULL_FACE);
        rtCullFace(cull);
    }
    two_windings();
    rtDisable(RT_CULL_FACE);
    rtCullFace(RT_BACK);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    rtEndObject();
}

static void polygon_modes_per_face(void)
{
    tu_section("rtPolygonMode per face in window space, culling, the mode at the call");
    window_camera();
    rtLineWidth(1.0f);
    /* Front filled, back outlined: each quad by its own winding. */
    per_face_object(0);
    render_object();
    CHECK(lit(6, 6) && lit(3, 9));            /* the front quad's inside */
    CHECK(!lit(17, 6) && !lit(15, 8));        /* the back quad's inside ... */
    CHECK(lit(13, 6) && lit(17, 2) && lit(21, 6)); /* ... and its outline */
    /* Seen from behind (the x axis mirrored) the faces swap. */
    rtBeginFrame();
    rtTranslatef(24.0f, 0.0f, 0.0f);
    rtScalef(-1.0f, 1.0f, 1.0f);
    rtInstantiateObject(OBJ);
    render();
    rtLoadIdentity();
    CHECK(!lit(17, 6) && lit(13, 6)); /* the first quad, now on the right, outlined */
    CHECK(lit(6, 6));                 /* the second, now on the left, filled */
    /* Culling comes first: back faces culled leave the front quad only;
     * both culled leave nothing. */
    per_face_object(RT_BACK);
    render_object();
    CHECK(lit(6, 6) && !lit(13, 6) && !lit(17, 2));
    per_face_object(RT_FRONT);
    render_object();
    CHECK(!lit(6, 6) && !lit(2, 6) && lit(13, 6) && !lit(17, 6));
    per_face_object(RT_FRONT_AND_BACK);
    render_object();
    CHECK_INT(count_lit(), 0);
    /* An object that sets no mode takes the caller's at the call. */
    rtNewObject(OBJ);
    two_windings();
    rtEndObject();
    CHECK_INT(tu_object_triangles(OBJ), 4);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_LINE);
    render_object();
    CHECK(!lit(6, 6) && lit(2, 6) && !lit(17, 6) && lit(13, 6));
    CHECK(!lit(6, 6) && !lit(5, 5)); /* no diagonal */
    rtPolygonMode(RT_BACK, RT_FILL);
    render_object();
    CHECK(!lit(6, 6) && lit(2, 6) && lit(17, 6));
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    render_object();
    CHECK(lit(6, 6) && lit(17, 6));
    CHECK_NO_ERR();
}

/* One quad drawn twice at the same place, first in a way GL rasterises
 * no interior of (its shown face outlined, or culled), then filled: GL
 * fills it.  The camera ray meets both at exactly one t; the one not
 * drawn is skipped by identity (render/gl_shade.c), where stepping past
 * its t lost the filled one too. */
static void coplanar_unfilled_then_filled(RTenum how)
{
    rtNewObject(OBJ);
    rtColor3f(1.0f, 1.0f, 1.0f);
    if (how == RT_CULL_FACE) {
        rtEnable(RT_CULL_FACE);
        rtCullFace(RT_FRONT);
    } else {
        rtPolygonMode(RT_FRONT, how);  /* the face shown */
        rtPolygonMode(RT_BACK, RT_FILL); /* stored as triangles */
    }
    two_windings();
    rtDisable(RT_CULL_FACE);
    rtCullFace(RT_BACK);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    two_windings();
    rtEndObject();
}

static void coplanar_filled(void)
{
    tu_section("a filled surface in the plane of an outlined or culled one is drawn");
    window_camera();
    rtLineWidth(1.0f);
    const RTenum hows[3] = {RT_LINE, RT_POINT, RT_CULL_FACE};
    for (int i = 0; i < 3; i++) {
        coplanar_unfilled_then_filled(hows[i]);
        render_object();
        CHECKF(lit(6, 6) && lit(4, 8) && lit(17, 6) && lit(15, 8), "case %d", i);
    }
    CHECK_NO_ERR();
}

/* An object that sets its own line (point) mode but not RT_CULL_FACE:
 * GL culls its polygons by the culling current at the call, before the
 * mode applies, so the caller's culling removes the outline of a face it
 * culls.  Until o-limits such objects kept their polygons as lines only,
 * which no culling reached.  An object that disables culling itself is
 * still stored as lines (no triangles). */
static void polygon_modes_call_culling(void)
{
    tu_section("rtPolygonMode in an object: the caller's culling removes its outlines");
    window_camera();
    rtLineWidth(1.0f);
    const RTenum modes[2] = {RT_LINE, RT_POINT};
    for (int i = 0; i < 2; i++) {
        outline_quad(modes[i]); /* counter-clockwise: its front shows */
        render_object();
        CHECKF(count_lit() > 0, "mode %d, no culling", i);
        rtEnable(RT_CULL_FACE);
        render_object(); /* back faces culled: the front stays */
        CHECKF(count_lit() > 0, "mode %d, back culled", i);
        rtCullFace(RT_FRONT);
        render_object();
        CHECKF(count_lit() == 0, "mode %d, front culled: %d pixels", i, count_lit());
        rtCullFace(RT_BACK);
        rtDisable(RT_CULL_FACE);
    }
    rtNewObject(OBJ);
    rtDisable(RT_CULL_FACE);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_LINE);
    rtBegin(RT_QUADS);
    rtVertex2f(2.5f, 2.5f);
    rtVertex2f(12.5f, 2.5f);
    rtVertex2f(12.5f, 12.5f);
    rtVertex2f(2.5f, 12.5f);
    rtEnd();
    rtEndObject();
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    CHECK_INT(tu_object_triangles(OBJ), 0);
    rtEnable(RT_CULL_FACE);
    rtCullFace(RT_FRONT);
    render_object(); /* its own RT_CULL_FACE (off) wins */
    CHECK_INT(count_lit(), 40);
    rtCullFace(RT_BACK);
    rtDisable(RT_CULL_FACE);
    CHECK_NO_ERR();
}

/* Faces drawn as lines or points are no surface for rtTraceRays and
 * rtOccludedRays either, whichever way the polygons were stored (lines
 * only, or triangles for a per-face mode or culling), at the face the ray
 * meets; a culled face that is filled is met (culling is for camera rays
 * only).  Until o-limits the triangles kept for a per-face mode answered
 * queries on both faces. */
static void unfilled_queries(void)
{
    tu_section("rtTraceRays, rtOccludedRays: faces drawn as lines or points are passed");
    window_camera();
    per_face_object(0); /* front filled, back outlined */
    rtBeginFrame();
    rtInstantiateObject(OBJ);
    rtFinish();
    /* From +z: the left quad shows its front, the right one its back. */
    CHECK_NEAR(tu_trace(6.0f, 6.0f, 5.0f, 0, 0, -1).t, 5.0f, 1e-6);
    CHECK_INT(tu_occluded(6.0f, 6.0f, 5.0f, 0, 0, -1), RT_TRUE);
    CHECK(tu_trace(17.0f, 6.0f, 5.0f, 0, 0, -1).t == tu_inf());
    CHECK_INT(tu_occluded(17.0f, 6.0f, 5.0f, 0, 0, -1), RT_FALSE);
    /* From -z the faces swap. */
    CHECK(tu_trace(6.0f, 6.0f, -5.0f, 0, 0, 1).t == tu_inf());
    CHECK_NEAR(tu_trace(17.0f, 6.0f, -5.0f, 0, 0, 1).t, 5.0f, 1e-6);
    /* Both faces outlined, stored as triangles (culling on in the
     * object): nothing answers. */
    rtNewObject(OBJ);
    rtEnable(RT_CULL_FACE);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_POINT);
    two_windings();
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    rtDisable(RT_CULL_FACE);
    rtEndObject();
    CHECK_INT(tu_object_triangles(OBJ), 4);
    rtBeginFrame();
    rtInstantiateObject(OBJ);
    rtFinish();
    CHECK(tu_trace(6.0f, 6.0f, 5.0f, 0, 0, -1).t == tu_inf());
    CHECK(tu_trace(17.0f, 6.0f, -5.0f, 0, 0, 1).t == tu_inf());
    CHECK_INT(tu_occluded(17.0f, 6.0f, 5.0f, 0, 0, -1), RT_FALSE);
    /* Culled but filled: met; culled and outlined: passed. */
    per_face_object(RT_FRONT_AND_BACK);
    rtBeginFrame();
    rtInstantiateObject(OBJ);
    rtFinish();
    CHECK_NEAR(tu_trace(6.0f, 6.0f, 5.0f, 0, 0, -1).t, 5.0f, 1e-6);
    CHECK(tu_trace(17.0f, 6.0f, 5.0f, 0, 0, -1).t == tu_inf());
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    rtNewObject(OBJ);
    rtEnable(RT_CULL_FACE);
    two_windings();
    rtDisable(RT_CULL_FACE);
    rtEndObject();
    rtBeginFrame();
    rtInstantiateObject(OBJ);
    rtFinish();
    CHECK_NEAR(tu_trace(6.0f, 6.0f, 5.0f, 0, 0, -1).t, 5.0f, 1e-6);
    CHECK_NEAR(tu_trace(17.0f, 6.0f, 5.0f, 0, 0, -1).t, 5.0f, 1e-6);
    CHECK_NO_ERR();
}

/* Whitted shadow rays pass a face drawn as lines: a floor at z = -0.5,
 * a quad at z = 0.5 over its left part lit from (-2, 0, 1), which the
 * camera sees filled (its front) while the shadow rays from the floor
 * meet its back, outlined.  Pixel 15 shows floor the quad would shadow;
 * pixel 20 floor no quad shadows: equal when the back face casts no
 * shadow, as with the quad filled on both faces they are not. */
static void unfilled_shadow_floor(RTenum back_mode)
{
    static const float white[4] = {1, 1, 1, 1}, black[4] = {0, 0, 0, 1};
    rtNewObject(OBJ);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, white);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
    rtBegin(RT_QUADS); /* the floor */
    rtVertex3f(0.0f, 0.0f, -0.5f);
    rtVertex3f(24.0f, 0.0f, -0.5f);
    rtVertex3f(24.0f, 24.0f, -0.5f);
    rtVertex3f(0.0f, 24.0f, -0.5f);
    rtEnd();
    rtPolygonMode(RT_FRONT, RT_FILL);
    rtPolygonMode(RT_BACK, back_mode);
    rtBegin(RT_QUADS); /* the occluder, its front towards the camera */
    rtVertex3f(2.0f, 2.0f, 0.5f);
    rtVertex3f(14.0f, 2.0f, 0.5f);
    rtVertex3f(14.0f, 20.0f, 0.5f);
    rtVertex3f(2.0f, 20.0f, 0.5f);
    rtEnd();
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    rtEndObject();
}

static void unfilled_shadows(void)
{
    tu_section("Whitted: a face drawn as lines casts no shadow");
    static const float light[4] = {-2.0f, 0.0f, 1.0f, 0.0f};
    window_camera();
    rtShadingMode(RT_WHITTED);
    rtLightfv(RT_LIGHT0, RT_POSITION, light);
    rtEnable(RT_LIGHT0);
    unfilled_shadow_floor(RT_FILL);
    render_object();
    CHECKF(px(15, 10)[0] < px(20, 10)[0] - 0.1f, "filled: %g against %g", (double)px(15, 10)[0],
           (double)px(20, 10)[0]);
    unfilled_shadow_floor(RT_LINE);
    render_object();
    CHECKF(fabsf(px(15, 10)[0] - px(20, 10)[0]) < 1e-4f && px(20, 10)[0] > 0.1f,
           "outlined: %g against %g", (double)px(15, 10)[0], (double)px(20, 10)[0]);
    rtDisable(RT_LIGHT0);
    rtShadingMode(RT_EYE_LIGHT);
    CHECK_NO_ERR();
}

static void strips_loops_arrays(void)
{
    tu_section("strips, loops, colours, vertex arrays, widths recorded in objects");
    window_camera();
    static const float tri[6] = {3.5f, 3.5f, 19.5f, 3.5f, 3.5f, 19.5f};
    segment_object(RT_LINE_STRIP, tri, 3, 0.0f);
    render_object();
    int strip = count_lit();
    CHECK(!lit(3, 11)); /* the strip does not close */
    segment_object(RT_LINE_LOOP, tri, 3, 0.0f);
    render_object();
    CHECK(lit(3, 11) && count_lit() > strip);
    int loop = count_lit();
    /* The same loop from an array and from indices. */
    rtNewObject(OBJ);
    rtColor3f(1.0f, 1.0f, 1.0f);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(2, RT_FLOAT, 0, tri);
    rtDrawArrays(RT_LINE_LOOP, 0, 3);
    rtEndObject();
    render_object();
    CHECK_INT(count_lit(), loop);
    static const unsigned short idx[6] = {0, 1, 1, 2, 2, 0};
    rtNewObject(OBJ);
    rtDrawElements(RT_LINES, 6, RT_UNSIGNED_SHORT, idx);
    rtEndObject();
    rtDisableClientState(RT_VERTEX_ARRAY);
    render_object();
    CHECK_INT(count_lit(), loop);
    /* Smooth colours along a segment (no perspective: linear). */
    rtNewObject(OBJ);
    rtBegin(RT_LINES);
    rtColor3f(1.0f, 0.0f, 0.0f);
    rtVertex2f(2.0f, 8.5f);
    rtColor3f(0.0f, 0.0f, 1.0f);
    rtVertex2f(22.0f, 8.5f);
    rtEnd();
    rtEndObject();
    render_object();
    CHECK_NEAR(px(11, 8)[0], 0.525, 1e-5);
    CHECK_NEAR(px(11, 8)[2], 0.475, 1e-5);
    /* Flat: the provoking vertex (the second) colours the segment. */
    rtShadeModel(RT_FLAT);
    rtNewObject(OBJ);
    rtBegin(RT_LINES);
    rtColor3f(1.0f, 0.0f, 0.0f);
    rtVertex2f(2.0f, 8.5f);
    rtColor3f(0.0f, 0.0f, 1.0f);
    rtVertex2f(22.0f, 8.5f);
    rtEnd();
    rtEndObject();
    rtShadeModel(RT_SMOOTH);
    render_object();
    CHECK(px(3, 8)[2] == 1.0f && px(3, 8)[0] == 0.0f);
    /* rtLineWidth inside an object is recorded, not executed (it is at
     * rtInstantiateObject, as glCallList executes glLineWidth); an object
     * without one takes the width current at rtInstantiateObject. */
    static const float h[4] = {2.5f, 8.5f, 12.5f, 8.5f};
    rtLineWidth(1.0f);
    segment_object(RT_LINES, h, 2, 3.0f);
    float w = 0.0f;
    rtGetFloatv(RT_LINE_WIDTH, &w);
    CHECK(w == 1.0f);
    render_object();
    CHECK_INT(count_lit(), 30);
    segment_object(RT_LINES, h, 2, 0.0f);
    rtLineWidth(5.0f);
    render_object();
    CHECK_INT(count_lit(), 50);
    rtLineWidth(1.0f);
    render_object();
    CHECK_INT(count_lit(), 10);
    CHECK_NO_ERR();
}

static void state_and_errors(void)
{
    tu_section("state queries and errors");
    RTint iv[2] = {0, 0};
    float fv[2] = {0.0f, 0.0f};
    rtGetIntegerv(RT_POLYGON_MODE, iv);
    CHECK(iv[0] == RT_FILL && iv[1] == RT_FILL);
    rtPolygonMode(RT_BACK, RT_POINT);
    rtGetIntegerv(RT_POLYGON_MODE, iv);
    CHECK(iv[0] == RT_FILL && iv[1] == RT_POINT);
    rtPolygonMode(RT_FRONT, RT_LINE);
    rtGetIntegerv(RT_POLYGON_MODE, iv);
    CHECK(iv[0] == RT_LINE && iv[1] == RT_POINT);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_FILL);
    rtLineWidth(2.5f);
    rtGetFloatv(RT_LINE_WIDTH, fv);
    CHECK(fv[0] == 2.5f);
    rtLineWidth(1.0f);
    rtPointSize(7.0f);
    rtGetFloatv(RT_POINT_SIZE, fv);
    CHECK(fv[0] == 7.0f);
    rtPointSize(1.0f);
    rtGetFloatv(RT_ALIASED_LINE_WIDTH_RANGE, fv);
    CHECK(fv[0] == 1.0f && fv[1] == 64.0f);
    rtGetFloatv(RT_ALIASED_POINT_SIZE_RANGE, fv);
    CHECK(fv[0] == 1.0f && fv[1] == 64.0f);
    CHECK_NO_ERR();

    rtLineWidth(0.0f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtLineWidth(-1.0f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtLineWidth(tu_nan());
    CHECK_ERR(RT_INVALID_VALUE);
    rtPointSize(0.0f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtPointSize(tu_inf());
    CHECK_ERR(RT_INVALID_VALUE);
    rtGetFloatv(RT_LINE_WIDTH, fv);
    CHECK(fv[0] == 1.0f);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_POLYGON);
    CHECK_ERR(RT_INVALID_ENUM);
    rtPolygonMode(RT_LINE, RT_LINE);
    CHECK_ERR(RT_INVALID_ENUM);
    rtGetIntegerv(RT_POLYGON_MODE, iv);
    CHECK(iv[0] == RT_FILL && iv[1] == RT_FILL);
    rtNewObject(OBJ);
    rtBegin(RT_LINES);
    rtLineWidth(2.0f);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtPointSize(2.0f);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtPolygonMode(RT_FRONT_AND_BACK, RT_LINE);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtVertex3f(0.0f, 0.0f, tu_inf());
    CHECK_ERR(RT_INVALID_VALUE);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    /* Surfaces here are given their colour as emission, which the eye
     * light shows as is (the fixed-function default would show the
     * vertex colour, white). */
    rtShadingMode(RT_EYE_LIGHT);
    width_one();
    wide_and_points();
    hidden();
    polygon_modes();
    polygon_modes_per_face();
    coplanar_filled();
    polygon_modes_call_culling();
    unfilled_queries();
    unfilled_shadows();
    strips_loops_arrays();
    state_and_errors();
    tu_destroy_context(ctx);
    return test_summary("lines");
}
