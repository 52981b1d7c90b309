/* SPDX-License-Identifier: Apache-2.0 */
/*
 * begin_end.c - conformance: rtBegin/rtEnd, rtVertex*, the current
 * attributes (rtNormal, rtTexCoord, rtColor) and rtShadeModel.
 *
 * Primitive assembly is observed through ray queries: for every expected
 * triangle (a, b, c) a ray aimed at barycentrics (0.2, 0.3) must report the
 * expected primitive id, t and u, v, which pins the vertex order; and
 * RT_OBJECT_TRIANGLES must count exactly the complete primitives.
 * Attributes and shade models are observed in rendered pixels (eye-light
 * shading, colour material, no global ambient: pixel = colour * |cos|).
 *
 * Reference: docs/primitives.md.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>

#define OBJ 100u

/* Vertices of each test, in the plane z = 0 (2D) unless stated. */
typedef float vec3[3];

static void emit(const vec3 *v, int n)
{
    int k;
    for (k = 0; k < n; k++)
        rtVertex3fv(v[k]);
}

static int define_mode(RTuint name, RTenum mode, const vec3 *v, int n)
{
    RTenum e;
    rtNewObject(name);
    rtBegin(mode);
    emit(v, n);
    rtEnd();
    rtEndObject();
    e = rtGetError();
    return tu_check(e == RT_NO_ERROR, __FILE__, __LINE__, "definition without error");
}

/* Checks that `name`, instantiated alone, consists of exactly the triangles
 * tri[i] = (v[idx[3i]], v[idx[3i+1]], v[idx[3i+2]]) with primitive ids i. */
static void check_assembly(const char *what, RTuint name, const vec3 *v, const int *idx,
                           int ntri)
{
    int i, ok = 1;
    ok &= CHECK_INT(tu_object_triangles(name), ntri);
    CHECK(tu_scene1(name));
    for (i = 0; i < ntri; i++)
        ok &= CHECK_TRIANGLE(v[idx[3 * i]], v[idx[3 * i + 1]], v[idx[3 * i + 2]], (RTuint)i,
                             name, 0);
    if (!ok)
        fprintf(stderr, "    in: %s\n", what);
}

static const vec3 tri_v[7] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0},
                              {3, 0, 0}, {2, 1, 0}, {5, 5, 0}};
static const int tri_idx[] = {0, 1, 2, 3, 4, 5};

/* Zigzag: even vertices at y = 0, odd at y = 1. */
static const vec3 strip_v[7] = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1.5f, 1, 0},
                                {2, 0, 0}, {3, 1, 0}, {3.5f, 0, 0}};
static const int strip_idx[] = {0, 1, 2, 2, 1, 3, 2, 3, 4, 4, 3, 5, 4, 5, 6};

/* Fan around the origin, angles strictly increasing. */
static const vec3 fan_v[6] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 2, 0}, {-1, 2, 0}};
static const int fan_idx[] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5};

/* Two quads (the second not a rectangle, so the split diagonal matters)
 * and three leftover vertices. */
static const vec3 quads_v[11] = {{0, 0, 0},    {1, 0, 0},  {1, 1, 0},  {0, 1, 0},
                                 {2, 0, 0},    {3, 0, 0},  {3.5f, 1.5f, 0}, {2, 1, 0},
                                 {9, 9, 0},    {10, 9, 0}, {10, 10, 0}};
static const int quads_idx[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};

/* Quad strip: pairs (bottom, top) left to right, plus one leftover. */
static const vec3 qstrip_v[7] = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1.2f, 1.3f, 0},
                                 {2, 0, 0}, {2, 1, 0}, {7, 7, 0}};
static const int qstrip_idx[] = {0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4};

static void assembly(void)
{
    tu_section("assembly of every mode");
    CHECK(define_mode(OBJ, RT_TRIANGLES, tri_v, 7));
    check_assembly("RT_TRIANGLES, 7 vertices", OBJ, tri_v, tri_idx, 2);
    CHECK(define_mode(OBJ, RT_TRIANGLE_STRIP, strip_v, 7));
    check_assembly("RT_TRIANGLE_STRIP, 7 vertices", OBJ, strip_v, strip_idx, 5);
    CHECK(define_mode(OBJ, RT_TRIANGLE_FAN, fan_v, 6));
    check_assembly("RT_TRIANGLE_FAN, 6 vertices", OBJ, fan_v, fan_idx, 4);
    CHECK(define_mode(OBJ, RT_POLYGON, fan_v, 6));
    check_assembly("RT_POLYGON, 6 vertices", OBJ, fan_v, fan_idx, 4);
    CHECK(define_mode(OBJ, RT_QUADS, quads_v, 11));
    check_assembly("RT_QUADS, 11 vertices", OBJ, quads_v, quads_idx, 4);
    CHECK(define_mode(OBJ, RT_QUAD_STRIP, qstrip_v, 7));
    check_assembly("RT_QUAD_STRIP, 7 vertices", OBJ, qstrip_v, qstrip_idx, 4);

    tu_section("incomplete primitives are dropped");
    CHECK(define_mode(OBJ, RT_TRIANGLES, tri_v, 2));
    CHECK_INT(tu_object_triangles(OBJ), 0);
    CHECK(define_mode(OBJ, RT_TRIANGLES, tri_v, 5));
    CHECK_INT(tu_object_triangles(OBJ), 1);
    CHECK(define_mode(OBJ, RT_TRIANGLE_STRIP, strip_v, 2));
    CHECK_INT(tu_object_triangles(OBJ), 0);
    CHECK(define_mode(OBJ, RT_TRIANGLE_STRIP, strip_v, 3));
    CHECK_INT(tu_object_triangles(OBJ), 1);
    CHECK(define_mode(OBJ, RT_TRIANGLE_FAN, fan_v, 2));
    CHECK_INT(tu_object_triangles(OBJ), 0);
    CHECK(define_mode(OBJ, RT_POLYGON, fan_v, 3));
    CHECK_INT(tu_object_triangles(OBJ), 1);
    CHECK(define_mode(OBJ, RT_POLYGON, fan_v, 1));
    CHECK_INT(tu_object_triangles(OBJ), 0);
    CHECK(define_mode(OBJ, RT_QUADS, quads_v, 3));
    CHECK_INT(tu_object_triangles(OBJ), 0);
    CHECK(define_mode(OBJ, RT_QUADS, quads_v, 7));
    CHECK_INT(tu_object_triangles(OBJ), 2);
    CHECK(define_mode(OBJ, RT_QUAD_STRIP, qstrip_v, 3));
    CHECK_INT(tu_object_triangles(OBJ), 0);
    CHECK(define_mode(OBJ, RT_QUAD_STRIP, qstrip_v, 5));
    CHECK_INT(tu_object_triangles(OBJ), 2);
    CHECK(define_mode(OBJ, RT_QUAD_STRIP, qstrip_v, 0));
    CHECK_INT(tu_object_triangles(OBJ), 0);

    tu_section("triangle ids continue across rtBegin blocks");
    rtNewObject(OBJ);
    rtBegin(RT_TRIANGLES);
    emit(tri_v, 7); /* 2 triangles, one leftover vertex dropped at rtEnd */
    rtEnd();
    rtBegin(RT_QUADS);
    rtVertex3f(10, 0, 0);
    rtVertex3f(11, 0, 0);
    rtVertex3f(11, 1, 0);
    rtVertex3f(10, 1, 0);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
    CHECK_INT(tu_object_triangles(OBJ), 4);
    CHECK(tu_scene1(OBJ));
    {
        static const vec3 q[4] = {{10, 0, 0}, {11, 0, 0}, {11, 1, 0}, {10, 1, 0}};
        CHECK_TRIANGLE(tri_v[0], tri_v[1], tri_v[2], 0, OBJ, 0);
        CHECK_TRIANGLE(tri_v[3], tri_v[4], tri_v[5], 1, OBJ, 0);
        CHECK_TRIANGLE(q[0], q[1], q[2], 2, OBJ, 0);
        CHECK_TRIANGLE(q[0], q[2], q[3], 3, OBJ, 0);
    }

    tu_section("degenerate triangles count but are never hit");
    rtNewObject(OBJ);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(0, 0, 0);
    rtVertex3f(1, 1, 0);
    rtVertex3f(2, 2, 0); /* collinear */
    rtVertex3f(0, 0, 0);
    rtVertex3f(0, 0, 0);
    rtVertex3f(0, 0, 0); /* a point */
    rtEnd();
    rtEndObject();
    CHECK_INT(tu_object_triangles(OBJ), 2);
    CHECK(tu_scene1(OBJ));
    {
        RThit h = tu_trace_down(1, 1);
        CHECK(h.t == tu_inf());
        CHECK(h.primitive == RT_INVALID_ID);
        h = tu_trace_down(0, 0);
        CHECK(h.t == tu_inf());
    }
    CHECK_NO_ERR();
}

static void vertex_forms(void)
{
    static const float f2[2] = {2, 0};
    static const double d2[2] = {0, 2};
    static const float f3[3] = {2, 0, 0};
    static const double d3[3] = {0, 2, 0};
    tu_section("rtVertex forms: 2D sets z = 0; f and d agree");
    rtNewObject(OBJ);
    rtBegin(RT_TRIANGLES);
    rtVertex2f(0, 0);
    rtVertex2fv(f2);
    rtVertex2dv(d2);
    rtVertex2d(0, 0);
    rtVertex3fv(f3);
    rtVertex3dv(d3);
    rtVertex3d(0, 0, 0);
    rtVertex3f(2, 0, 0);
    rtVertex3d(0, 2, 0);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
    CHECK_INT(tu_object_triangles(OBJ), 3);
    CHECK(tu_scene1(OBJ));
    /* Three coincident triangles: whichever id wins, the pinned u, v and t hold. */
    {
        RThit h = tu_trace(0.4f, 0.6f, 2, 0, 0, -1);
        CHECK(h.primitive < 3);
        CHECK_NEAR(h.t, 2, 1e-6);
        CHECK_NEAR(h.u, 0.2, 1e-6);
        CHECK_NEAR(h.v, 0.3, 1e-6);
    }

    tu_section("vertices are transformed by the modelview at rtVertex");
    rtLoadIdentity();
    rtNewObject(OBJ);
    rtTranslatef(0, 0, -3);
    rtRotatef(90, 0, 0, 1); /* x -> y, y -> -x */
    rtBegin(RT_TRIANGLES);
    rtVertex3f(1, 0, 0);
    rtVertex3f(2, 0, 0);
    rtVertex3f(1, 1, 0);
    rtEnd();
    rtScalef(2, 2, 2);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(1, 0, 0);
    rtVertex3f(2, 0, 0);
    rtVertex3f(1, 1, 0);
    rtEnd();
    rtEndObject();
    rtLoadIdentity();
    CHECK_NO_ERR();
    CHECK(tu_scene1(OBJ));
    {
        static const vec3 a0 = {0, 1, -3}, b0 = {0, 2, -3}, c0 = {-1, 1, -3};
        static const vec3 a1 = {0, 2, -3}, b1 = {0, 4, -3}, c1 = {-2, 2, -3};
        CHECK_TRIANGLE(a0, b0, c0, 0, OBJ, 0);
        CHECK_TRIANGLE(a1, b1, c1, 1, OBJ, 0);
    }

    tu_section("a rejected vertex is not recorded");
    rtLoadIdentity(); /* calling the last list left its matrix calls' effect (GL) */
    rtNewObject(OBJ);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(0, 0, 0);
    rtVertex3f(1, 0, 0);
    rtVertex3f(tu_nan(), 0, 0);
    CHECK_ERR(RT_INVALID_VALUE);
    rtVertex3fv(NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtVertex2d(tu_inf_d(), 1);
    CHECK_ERR(RT_INVALID_VALUE);
    rtVertex3f(0, 1, 0);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
    CHECK_INT(tu_object_triangles(OBJ), 1);
    CHECK(tu_scene1(OBJ));
    {
        static const vec3 a = {0, 0, 0}, b = {1, 0, 0}, c = {0, 1, 0};
        CHECK_TRIANGLE(a, b, c, 0, OBJ, 0);
    }
}

static void begin_end_errors(void)
{
    RTint tris;
    tu_section("rtBegin / rtEnd errors");
    /* Outside an object rtBegin draws in immediate mode (docs/lists.md);
     * a vertex outside rtBegin and an unmatched rtEnd are errors. */
    rtVertex3f(0, 0, 0);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    CHECK_ERR(RT_INVALID_OPERATION);
    rtBegin(0x1234);
    CHECK_ERR(RT_INVALID_ENUM);

    rtNewObject(OBJ);
    rtBegin(0x1234);
    CHECK_ERR(RT_INVALID_ENUM);
    /* Not inside rtBegin after a failed rtBegin. */
    rtVertex3f(0, 0, 0);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEnd();
    CHECK_ERR(RT_INVALID_OPERATION);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(0, 0, 0);
    rtVertex3f(1, 0, 0);
    /* Nested rtBegin: error, the open block is unaffected (mode stays
     * RT_TRIANGLES, vertices so far are kept). */
    rtBegin(RT_QUADS);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtVertex3f(0, 1, 0); /* completes triangle 0 */
    rtVertex3f(5, 5, 0);
    rtVertex3f(6, 5, 0); /* leftovers: a restarted RT_QUADS block would make 0
                          * triangles, one that kept its vertices 2 */
    rtEnd();
    rtEnd();
    CHECK_ERR(RT_INVALID_OPERATION);
    rtEndObject();
    CHECK_NO_ERR();
    tris = tu_object_triangles(OBJ);
    CHECK_INT(tris, 1);
}

/* ---- attributes and shade model, seen in pixels -------------------------------- */

#define W 16
#define H 16
static float px[W * H * 4];

static void setup_render(void)
{
    static const float no_ambient[4] = {0, 0, 0, 1};
    tu_ortho_camera();
    rtShadingMode(RT_EYE_LIGHT);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, no_ambient);
    rtEnable(RT_COLOR_MATERIAL);
    rtClearColor(0, 0, 0, 0);
    CHECK_NO_ERR();
}

/* Pixel whose centre is at world (x, y) under the ortho camera. */
static const float *pixel_at(float x, float y)
{
    int i = (int)floorf((x + 1.0f) * 0.5f * W);
    int j = (int)floorf((y + 1.0f) * 0.5f * H);
    return px + 4 * (j * W + i);
}

static void check_rgb(const char *file, int line, const float *p, float r, float g, float b,
                      float tol)
{
    if (!tu_check(fabsf(p[0] - r) <= tol && fabsf(p[1] - g) <= tol && fabsf(p[2] - b) <= tol,
                  file, line, "pixel colour"))
        fprintf(stderr, "    pixel (%g, %g, %g), expected (%g, %g, %g)\n", p[0], p[1], p[2], r,
                g, b);
}
#define CHECK_RGB(p, r, g, b, tol) check_rgb(__FILE__, __LINE__, (p), (r), (g), (b), (tol))

static void render_object(RTuint name)
{
    CHECK(tu_scene1(name));
    tu_render_float(W, H, px);
    CHECK_NO_ERR();
}

/* A vertex of the shade-model cases: its colour, then its position in
 * the plane z = -5. */
struct coloured_vertex {
    float rgb[3];
    float x, y;
};

/* The big triangle and the square of the cases: red, green, blue (and
 * yellow) counter-clockwise from the lower left corner. */
static const struct coloured_vertex triangle[3] = {
    {{1, 0, 0}, -0.9f, -0.9f}, {{0, 1, 0}, 0.9f, -0.9f}, {{0, 0, 1}, -0.9f, 0.9f}};
static const struct coloured_vertex quad[4] = {{{1, 0, 0}, -0.9f, -0.9f},
                                               {{0, 1, 0}, 0.9f, -0.9f},
                                               {{0, 0, 1}, 0.9f, 0.9f},
                                               {{1, 1, 0}, -0.9f, 0.9f}};
/* The square as a strip: blue provokes triangle 0, white triangle 1. */
static const struct coloured_vertex strip[4] = {{{1, 0, 0}, -0.9f, -0.9f},
                                                {{0, 1, 0}, -0.9f, 0.9f},
                                                {{0, 0, 1}, 0.9f, -0.9f},
                                                {{1, 1, 1}, 0.9f, 0.9f}};

/* The square's corners at depth z, counter-clockwise from the lower
 * left, without attributes: inside an rtBegin(RT_QUADS). */
static void square_vertices(float z)
{
    rtVertex3f(-0.9f, -0.9f, z);
    rtVertex3f(0.9f, -0.9f, z);
    rtVertex3f(0.9f, 0.9f, z);
    rtVertex3f(-0.9f, 0.9f, z);
}

/* OBJ as one rtBegin(mode) .. rtEnd() of v[0 .. n), each vertex after its
 * rtColor3f, rendered into px. */
static void render_coloured(RTenum mode, const struct coloured_vertex *v, int n)
{
    rtNewObject(OBJ);
    rtBegin(mode);
    for (int i = 0; i < n; i++) {
        rtColor3f(v[i].rgb[0], v[i].rgb[1], v[i].rgb[2]);
        rtVertex3f(v[i].x, v[i].y, -5);
    }
    rtEnd();
    rtEndObject();
    render_object(OBJ);
}

static void shade_model(void)
{
    RTint v = -1;
    /* Pixel centres used below: (-0.8125, -0.8125) lies near v0 of the big
     * triangle (-0.9,-0.9) (0.9,-0.9) (-0.9,0.9), with weights 0.903, 0.049,
     * 0.049. */
    const float x = -0.8125f, y = -0.8125f;
    const float w1 = (x + 0.9f) / 1.8f, w2 = (y + 0.9f) / 1.8f, w0 = 1.0f - w1 - w2;
    tu_section("rtShadeModel");
    rtGetIntegerv(RT_SHADE_MODEL, &v);
    CHECK_INT(v, RT_SMOOTH);
    rtShadeModel(0x1234);
    CHECK_ERR(RT_INVALID_ENUM);
    rtShadeModel(RT_FLAT);
    rtGetIntegerv(RT_SHADE_MODEL, &v);
    CHECK_INT(v, RT_FLAT);
    tu_begin_scratch(RT_TRIANGLES);
    rtShadeModel(RT_SMOOTH);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    rtGetIntegerv(RT_SHADE_MODEL, &v);
    CHECK_INT(v, RT_FLAT);
    rtShadeModel(0x1234);
    CHECK_ERR(RT_INVALID_ENUM);
    rtGetIntegerv(RT_SHADE_MODEL, &v);
    CHECK_INT(v, RT_FLAT);

    setup_render();
    /* Smooth: colours interpolated with the barycentrics. */
    rtShadeModel(RT_SMOOTH);
    render_coloured(RT_TRIANGLES, triangle, 3);
    CHECK_RGB(pixel_at(x, y), w0, w1, w2, 0.01f);

    /* Flat, RT_TRIANGLES: the last vertex provokes. */
    rtShadeModel(RT_FLAT);
    render_coloured(RT_TRIANGLES, triangle, 3);
    CHECK_RGB(pixel_at(x, y), 0, 0, 1, 0.01f);
    /* The object sets no shade model of its own: as a GL list's geometry,
     * it takes the one current at the call (until 25814ff the one at the
     * recording counted, which is not GL). */
    rtShadeModel(RT_SMOOTH);
    render_object(OBJ);
    CHECK_RGB(pixel_at(x, y), w0, w1, w2, 0.01f);
    rtShadeModel(RT_FLAT);

    /* Flat, RT_POLYGON: the first vertex provokes. */
    render_coloured(RT_POLYGON, quad, 4);
    CHECK_RGB(pixel_at(0.5f, -0.6f), 1, 0, 0, 0.01f);
    CHECK_RGB(pixel_at(-0.6f, 0.5f), 1, 0, 0, 0.01f);

    /* Flat, RT_QUADS: the quad's last vertex, for both triangles. */
    render_coloured(RT_QUADS, quad, 4);
    CHECK_RGB(pixel_at(0.5f, -0.6f), 1, 1, 0, 0.01f);
    CHECK_RGB(pixel_at(-0.6f, 0.5f), 1, 1, 0, 0.01f);

    /* Flat, RT_TRIANGLE_STRIP: the last vertex of each triangle. */
    render_coloured(RT_TRIANGLE_STRIP, strip, 4);
    CHECK_RGB(pixel_at(-0.6f, -0.6f), 0, 0, 1, 0.01f);
    CHECK_RGB(pixel_at(0.6f, 0.6f), 1, 1, 1, 0.01f);
    rtShadeModel(RT_SMOOTH);
    rtDisable(RT_COLOR_MATERIAL);
}

static void attributes(void)
{
    static const float red[3] = {1, 0, 0};
    static const float n45[3] = {0.70710678f, 0, 0.70710678f};
    static const float tc[2] = {0.5f, 0.5f};
    tu_section("current attributes");
    /* Allowed outside objects, inside objects and inside rtBegin. */
    rtNormal3f(0, 0, 1);
    rtNormal3fv(n45);
    rtTexCoord2f(0.25f, 0.75f);
    rtTexCoord2fv(tc);
    rtColor3f(1, 1, 1);
    rtColor3fv(red);
    rtColor4f(1, 1, 1, 1);
    CHECK_NO_ERR();
    tu_begin_scratch(RT_TRIANGLES);
    rtNormal3fv(n45);
    rtTexCoord2fv(tc);
    rtColor4f(0, 0, 0, 1);
    CHECK_NO_ERR();
    tu_end_scratch();
    /* NULL and non-finite values. */
    rtNormal3f(0, tu_inf(), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexCoord2f(tu_nan(), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    rtColor4f(0, 0, 0, tu_nan());
    CHECK_ERR(RT_INVALID_VALUE);
    rtColor3fv(NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtTexCoord2fv(NULL);
    CHECK_ERR(RT_INVALID_VALUE);

    setup_render();
    /* The normal set above outside any object does not apply to the quad
     * below, whose definition never calls rtNormal: it is shaded with its
     * geometric normal (|cos| = 1 head-on; n45 would give 0.7071). */
    tu_section("colour: clamped; a rejected colour leaves the current one");
    rtColor3f(2.0f, -1.0f, 0.5f); /* clamps to (1, 0, 0.5) */
    rtColor3f(0.0f, tu_nan(), 0.0f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtColor4fv(NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtNewObject(OBJ);
    rtBegin(RT_QUADS);
    square_vertices(-5.0f);
    rtEnd();
    rtEndObject();
    render_object(OBJ);
    CHECK_RGB(pixel_at(0.1f, 0.1f), 1, 0, 0.5f, 0.01f);

    tu_section("normals: given, transformed by the inverse transpose, or geometric");
    rtColor3f(1, 1, 1);
    /* A normal at 45 degrees to the view direction: |cos| = 0.7071. */
    rtNewObject(OBJ);
    rtNormal3fv(n45);
    rtBegin(RT_QUADS);
    square_vertices(-5.0f);
    rtEnd();
    rtEndObject();
    render_object(OBJ);
    CHECK_RGB(pixel_at(0.1f, 0.1f), 0.7071f, 0.7071f, 0.7071f, 0.01f);
    /* Under scale(1, 1, 4) the same normal becomes (1, 0, 1/4) normalised:
     * |cos| = 0.2425 (transforming by M itself would give 0.9701). */
    rtNewObject(OBJ);
    rtPushMatrix();
    rtScalef(1, 1, 4);
    rtNormal3fv(n45);
    rtBegin(RT_QUADS);
    square_vertices(-1.25f);
    rtEnd();
    rtPopMatrix();
    rtEndObject();
    render_object(OBJ);
    CHECK_RGB(pixel_at(0.1f, 0.1f), 0.2425f, 0.2425f, 0.2425f, 0.01f);
    /* No rtNormal in the definition: the geometric normal.  A quad tilted
     * 60 degrees from facing the camera gives |cos| = 0.5 (the default
     * normal (0, 0, 1) would give 1). */
    rtNewObject(OBJ);
    rtBegin(RT_QUADS);
    rtVertex3f(-0.4f, -0.9f, -5.0f);
    rtVertex3f(0.4f, -0.9f, -5.0f - 0.8f * 1.7320508f);
    rtVertex3f(0.4f, 0.9f, -5.0f - 0.8f * 1.7320508f);
    rtVertex3f(-0.4f, 0.9f, -5.0f);
    rtEnd();
    rtEndObject();
    render_object(OBJ);
    CHECK_RGB(pixel_at(0.1f, 0.1f), 0.5f, 0.5f, 0.5f, 0.01f);
    /* A rejected normal leaves the current one (n45). */
    rtNewObject(OBJ);
    rtNormal3fv(n45);
    rtNormal3f(tu_nan(), 0, 1);
    CHECK_ERR(RT_INVALID_VALUE);
    rtBegin(RT_QUADS);
    rtNormal3fv(NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    square_vertices(-5.0f);
    rtEnd();
    rtEndObject();
    render_object(OBJ);
    CHECK_RGB(pixel_at(0.1f, 0.1f), 0.7071f, 0.7071f, 0.7071f, 0.01f);
    rtDisable(RT_COLOR_MATERIAL);
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    assembly();
    vertex_forms();
    begin_end_errors();
    shade_model();
    attributes();
    tu_destroy_context(ctx);
    return test_summary("begin_end");
}
