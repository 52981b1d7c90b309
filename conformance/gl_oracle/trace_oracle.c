/* SPDX-License-Identifier: Apache-2.0 */
/*
 * trace_oracle.c - the quadrics call for call: rtuSphere, rtuCylinder,
 * rtuDisk, rtuPartialDisk (and rtuSolidSphere, rtuSolidCone) must emit
 * exactly the calls Mesa's libGLU emits for gluSphere ... (and GLUT's
 * gluSphere / gluCylinder solids): the same primitive modes, and the same
 * normals, texture coordinates and vertices, bit for bit, in the same
 * order.
 *
 * How: this program defines glBegin, glEnd, glNormal3f, glTexCoord2f,
 * glVertex3f and their rt namesakes itself and exports them, so libGLU's
 * and rtu's calls land here (an executable's definitions come first in
 * the dynamic linker's search) and are recorded instead of drawn.  No GL
 * or Tracelist context is involved.
 *
 * The GLUT shapes that GLU does not draw (cube, torus, teapot, regular
 * solids) are checked for their normals instead: unit, outward, and (for
 * the flat-faced solids) with counter-clockwise faces.
 *
 * The cases cover every draw style (fill, line, point, silhouette), every
 * normal mode, both orientations, with and without texture coordinates, the slice clamp (GLU's 240-entry tables), the
 * smallest tessellations and GLU's treatment of sweep angles.  Spheres
 * keep stacks <= slices: for more stacks than slices gluSphere reads an
 * uninitialised table entry for the normal before its lower fan (its x
 * and y are multiplied by sin(pi), below 1e-7).
 */
#include <GL/gl.h>
#include <GL/glu.h>

#include <rt/rt.h>
#include <rt/rtu.h>

#include "glut_gl.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EXPORT __attribute__((visibility("default")))
#define MAX_EVENTS 400000

enum { EV_BEGIN, EV_END, EV_NORMAL, EV_TEXCOORD, EV_VERTEX };

struct event {
    int type;
    uint32_t bits[3]; /* the float arguments' bit patterns, or the mode */
};

struct trace {
    struct event *events;
    int count;
};

static struct trace gl_trace, rt_trace;

static void record(struct trace *t, int type, float a, float b, float c)
{
    struct event *e;
    if (t->count >= MAX_EVENTS)
        return;
    e = &t->events[t->count++];
    memset(e, 0, sizeof *e);
    e->type = type;
    memcpy(&e->bits[0], &a, 4);
    memcpy(&e->bits[1], &b, 4);
    memcpy(&e->bits[2], &c, 4);
}

static void record_mode(struct trace *t, unsigned mode)
{
    if (t->count >= MAX_EVENTS)
        return;
    memset(&t->events[t->count], 0, sizeof t->events[0]);
    t->events[t->count].type = EV_BEGIN;
    t->events[t->count].bits[0] = mode;
    t->count++;
}

/* ---- the interposed entry points ---------------------------------------- */

EXPORT void glBegin(GLenum mode) { record_mode(&gl_trace, mode); }
EXPORT void glEnd(void) { record(&gl_trace, EV_END, 0, 0, 0); }
EXPORT void glNormal3f(GLfloat x, GLfloat y, GLfloat z) { record(&gl_trace, EV_NORMAL, x, y, z); }
EXPORT void glTexCoord2f(GLfloat s, GLfloat t) { record(&gl_trace, EV_TEXCOORD, s, t, 0); }
EXPORT void glVertex3f(GLfloat x, GLfloat y, GLfloat z) { record(&gl_trace, EV_VERTEX, x, y, z); }

EXPORT void rtBegin(RTenum mode) { record_mode(&rt_trace, mode); }
EXPORT void rtEnd(void) { record(&rt_trace, EV_END, 0, 0, 0); }
EXPORT void rtNormal3f(RTfloat x, RTfloat y, RTfloat z) { record(&rt_trace, EV_NORMAL, x, y, z); }
EXPORT void rtTexCoord2f(RTfloat s, RTfloat t) { record(&rt_trace, EV_TEXCOORD, s, t, 0); }
EXPORT void rtVertex3f(RTfloat x, RTfloat y, RTfloat z) { record(&rt_trace, EV_VERTEX, x, y, z); }
EXPORT void rtNormal3fv(const RTfloat *v) { record(&rt_trace, EV_NORMAL, v[0], v[1], v[2]); }
EXPORT void rtVertex3fv(const RTfloat *v) { record(&rt_trace, EV_VERTEX, v[0], v[1], v[2]); }

/* ---- comparison ----------------------------------------------------------- */

static int failures, cases;

static const char *event_name(int type)
{
    static const char *names[] = {"Begin", "End", "Normal3f", "TexCoord2f", "Vertex3f"};
    return names[type];
}

static void print_event(const char *who, const struct event *e)
{
    float v[3];
    memcpy(v, e->bits, sizeof v);
    if (e->type == EV_BEGIN)
        fprintf(stderr, "    %s: Begin(0x%x)\n", who, (unsigned)e->bits[0]);
    else
        fprintf(stderr, "    %s: %s(%.9g, %.9g, %.9g)\n", who, event_name(e->type), v[0], v[1],
                v[2]);
}

static void compare(const char *what)
{
    int i, n = gl_trace.count < rt_trace.count ? gl_trace.count : rt_trace.count;
    cases++;
    for (i = 0; i < n; i++)
        if (memcmp(&gl_trace.events[i], &rt_trace.events[i], sizeof(struct event)) != 0)
            break;
    if (i == n && gl_trace.count == rt_trace.count && gl_trace.count > 0 &&
        gl_trace.count < MAX_EVENTS) {
        gl_trace.count = rt_trace.count = 0;
        return;
    }
    failures++;
    fprintf(stderr, "%s: calls differ at call %d (GLU made %d, rtu %d)\n", what, i,
            gl_trace.count, rt_trace.count);
    if (i < gl_trace.count)
        print_event("GLU", &gl_trace.events[i]);
    if (i < rt_trace.count)
        print_event("rtu", &rt_trace.events[i]);
    gl_trace.count = rt_trace.count = 0;
}

/* ---- GLUT shapes without a GLU counterpart: their normals ---------------- */

static void event_floats(const struct event *e, float v[3])
{
    memcpy(v, e->bits, 3 * sizeof(float));
}

/*
 * Checks the polyhedra rtu just emitted (rt_trace): every face's normal is
 * a unit vector pointing away from the origin, and the face's vertices
 * wind counter-clockwise about it (the first triangle of each primitive).
 */
static void check_polyhedron(const char *what)
{
    int i, bad = 0, faces = 0;
    float n[3] = {0, 0, 0};
    for (i = 0; i < rt_trace.count; i++) {
        const struct event *e = &rt_trace.events[i];
        if (e->type == EV_NORMAL)
            event_floats(e, n);
        if (e->type == EV_BEGIN && i + 4 < rt_trace.count) {
            float a[3], b[3], c[3], g[3];
            double len, out, wind;
            int k = i + 1;
            while (k < rt_trace.count && rt_trace.events[k].type == EV_NORMAL)
                event_floats(&rt_trace.events[k++], n);
            if (k + 2 >= rt_trace.count)
                break;
            event_floats(&rt_trace.events[k], a);
            event_floats(&rt_trace.events[k + 1], b);
            event_floats(&rt_trace.events[k + 2], c);
            g[0] = (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]);
            g[1] = (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]);
            g[2] = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
            len = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
            out = n[0] * a[0] + n[1] * a[1] + n[2] * a[2];
            wind = n[0] * g[0] + n[1] * g[1] + n[2] * g[2];
            faces++;
            if (fabs(len - 1.0) > 1e-6 || !(out > 0) || !(wind > 0))
                bad++;
        }
    }
    cases++;
    if (bad || faces == 0) {
        failures++;
        fprintf(stderr, "%s: %d of %d faces with a bad normal or winding\n", what, bad, faces);
    }
    gl_trace.count = rt_trace.count = 0;
}

/* Smooth shapes: the normal given before each vertex must be a unit vector
 * and point along `expected(vertex)` (dot product above 0.99 for the torus,
 * above 0 for the teapot, whose normal is not radial). */
static void check_torus(const char *what, double tube, double ring)
{
    int i, bad = 0, vertices = 0;
    float n[3] = {0, 0, 0};
    for (i = 0; i < rt_trace.count; i++) {
        const struct event *e = &rt_trace.events[i];
        if (e->type == EV_NORMAL)
            event_floats(e, n);
        if (e->type == EV_VERTEX) {
            float v[3];
            double r, c[3], d[3], dl, dot;
            event_floats(e, v);
            r = sqrt((double)v[0] * v[0] + (double)v[1] * v[1]);
            /* The tube's centre line is the circle of radius `ring` in z = 0. */
            c[0] = v[0] * ring / r;
            c[1] = v[1] * ring / r;
            c[2] = 0.0;
            d[0] = v[0] - c[0];
            d[1] = v[1] - c[1];
            d[2] = v[2] - c[2];
            dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            dot = (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / dl;
            vertices++;
            bad += !(dot > 0.99999) || fabs(dl - tube) > 1e-5;
        }
    }
    cases++;
    if (bad || vertices == 0) {
        failures++;
        fprintf(stderr, "%s: %d of %d vertices off the tube or with a bad normal\n", what, bad,
                vertices);
    }
    gl_trace.count = rt_trace.count = 0;
}

/* The teapot's body (radius below `size`, away from the handle and spout in
 * the x-y plane of the data, i.e. |z| large here): normals point outwards. */
static void check_teapot(const char *what, double size)
{
    int i, bad = 0, body = 0, zero = 0;
    float n[3] = {0, 0, 0};
    for (i = 0; i < rt_trace.count; i++) {
        const struct event *e = &rt_trace.events[i];
        if (e->type == EV_NORMAL)
            event_floats(e, n);
        if (e->type == EV_VERTEX) {
            float v[3];
            double r;
            event_floats(e, v);
            zero += n[0] == 0.0f && n[1] == 0.0f && n[2] == 0.0f;
            r = sqrt((double)v[0] * v[0] + (double)v[2] * v[2]);
            if (r > 0.7 * size && r < 1.001 * size && fabs(v[1]) < 0.6 * size &&
                fabs(v[2]) > 0.7 * size) {
                body++;
                bad += !(n[0] * v[0] + n[2] * v[2] > 0);
            }
        }
    }
    cases++;
    if (bad || zero || body < 100) {
        failures++;
        fprintf(stderr, "%s: %d of %d body normals inward, %d zero normals\n", what, bad, body,
                zero);
    }
    gl_trace.count = rt_trace.count = 0;
}

/* ---- cases ---------------------------------------------------------------- */

static const GLenum normal_modes[3] = {GLU_SMOOTH, GLU_FLAT, GLU_NONE};
static const RTenum rt_normal_modes[3] = {RTU_SMOOTH, RTU_FLAT, RTU_NONE};
static const GLenum draw_styles[4] = {GLU_FILL, GLU_LINE, GLU_POINT, GLU_SILHOUETTE};
static const RTenum rt_draw_styles[4] = {RTU_FILL, RTU_LINE, RTU_POINT, RTU_SILHOUETTE};
static const char *const style_names[4] = {"fill", "line", "point", "silhouette"};

/*
 * Where libGLU's output is undefined: with GLU_FLAT it draws points, and a
 * sphere's or cylinder's silhouette, from normal tables it fills only for
 * other styles (uninitialised reads; NaNs here).  rtu defines them
 * (lib/rtu/quadric_wire.c): points take the smooth normals, a silhouette
 * the flat GLU_LINE normals of its edges.  The reference is then GLU's
 * own output for those settings: GLU_SMOOTH points; GLU_LINE with the
 * first `inner_rings` line strips (a cylinder's inner rings, which a
 * silhouette leaves out) dropped.  Disks (inner_rings -1) give one normal
 * and are compared as they are.
 */
static void gl_reference(GLUquadric *gq, int style, int normals, int inner_rings)
{
    if (normals != 1)
        return;
    if (draw_styles[style] == GLU_POINT)
        gluQuadricNormals(gq, GLU_SMOOTH);
    if (draw_styles[style] == GLU_SILHOUETTE && inner_rings >= 0)
        gluQuadricDrawStyle(gq, GLU_LINE);
}

static void gl_reference_done(int style, int normals, int inner_rings)
{
    int i, blocks = 0;
    if (normals != 1 || draw_styles[style] != GLU_SILHOUETTE || inner_rings <= 0)
        return;
    for (i = 0; i < gl_trace.count && blocks < inner_rings; i++)
        blocks += gl_trace.events[i].type == EV_END;
    memmove(gl_trace.events, gl_trace.events + i, (size_t)(gl_trace.count - i) *
            sizeof gl_trace.events[0]);
    gl_trace.count -= i;
}

/* Calls `draw` on a GLU and an rtu quadric set up alike, for every draw
 * style, normal mode, orientation and texture setting, and compares each
 * pair. */
#define FOR_EACH_SETUP(label, gl_call, rt_call)                                               \
    do {                                                                                      \
        int ds_, nm_, o_, tex_;                                                               \
        for (ds_ = 0; ds_ < 4; ds_++)                                                         \
        for (nm_ = 0; nm_ < 3; nm_++)                                                         \
            for (o_ = 0; o_ < 2; o_++)                                                        \
                for (tex_ = 0; tex_ < 2; tex_++) {                                            \
                    char what_[256];                                                          \
                    gluQuadricDrawStyle(gq, draw_styles[ds_]);                                \
                    rtuQuadricDrawStyle(rq, rt_draw_styles[ds_]);                             \
                    gluQuadricNormals(gq, normal_modes[nm_]);                                 \
                    gluQuadricOrientation(gq, o_ ? GLU_INSIDE : GLU_OUTSIDE);                 \
                    gluQuadricTexture(gq, (GLboolean)tex_);                                   \
                    rtuQuadricNormals(rq, rt_normal_modes[nm_]);                              \
                    rtuQuadricOrientation(rq, o_ ? RTU_INSIDE : RTU_OUTSIDE);                 \
                    rtuQuadricTexture(rq, (RTboolean)tex_);                                   \
                    gl_reference(gq, ds_, nm_, gl_inner_rings);                               \
                    gl_call;                                                                  \
                    gl_reference_done(ds_, nm_, gl_inner_rings);                              \
                    rt_call;                                                                  \
                    snprintf(what_, sizeof what_, "%s [%s, normals %d, %s, texture %d]",      \
                             label, style_names[ds_], nm_, o_ ? "inside" : "outside", tex_);  \
                    compare(what_);                                                           \
                }                                                                             \
    } while (0)

int main(void)
{
    GLUquadric *gq = gluNewQuadric();
    RTUquadric *rq = rtuNewQuadric();
    char label[128];
    int gl_inner_rings = 0; /* see gl_reference */
    static const int sphere_sizes[][2] = {{2, 1}, {2, 2}, {3, 2}, {5, 3}, {16, 8}, {24, 16},
                                          {31, 31}, {100, 60}, {300, 200}};
    static const double cylinders[][3] = {{1.0, 1.0, 2.0}, {1.5, 0.5, 1.0}, {0.0, 1.0, 1.0},
                                          {1.0, 0.0, 3.0}, {1.0, 2.0, 0.0}, {0.3, 0.7, 1e-3}};
    static const int cylinder_sizes[][2] = {{2, 1}, {3, 4}, {17, 5}, {250, 2}};
    static const double disks[][2] = {{0.0, 1.0}, {0.5, 2.0}, {1.0, 1.0}, {0.25, 0.5}};
    static const int disk_sizes[][2] = {{2, 1}, {7, 3}, {32, 4}, {400, 1}};
    static const double sweeps[][2] = {{0.0, 360.0}, {30.0, 240.0}, {100.0, -135.0},
                                       {-45.0, 500.0}, {10.0, -400.0}, {0.0, 0.0},
                                       {270.0, 90.0}};
    size_t i, j, k;
    gl_trace.events = malloc(MAX_EVENTS * sizeof(struct event));
    rt_trace.events = malloc(MAX_EVENTS * sizeof(struct event));
    if (!gq || !rq || !gl_trace.events || !rt_trace.events)
        return 1;

    for (i = 0; i < sizeof sphere_sizes / sizeof sphere_sizes[0]; i++) {
        const int sl = sphere_sizes[i][0], st = sphere_sizes[i][1];
        snprintf(label, sizeof label, "sphere(1.25, %d, %d)", sl, st);
        FOR_EACH_SETUP(label, gluSphere(gq, 1.25, sl, st), rtuSphere(rq, 1.25, sl, st));
    }
    for (i = 0; i < sizeof cylinders / sizeof cylinders[0]; i++)
        for (j = 0; j < sizeof cylinder_sizes / sizeof cylinder_sizes[0]; j++) {
            const double *c = cylinders[i];
            const int sl = cylinder_sizes[j][0], st = cylinder_sizes[j][1];
            snprintf(label, sizeof label, "cylinder(%g, %g, %g, %d, %d)", c[0], c[1], c[2], sl,
                     st);
            gl_inner_rings = st - 1;
            FOR_EACH_SETUP(label, gluCylinder(gq, c[0], c[1], c[2], sl, st),
                           rtuCylinder(rq, c[0], c[1], c[2], sl, st));
        }
    gl_inner_rings = -1;
    for (i = 0; i < sizeof disks / sizeof disks[0]; i++)
        for (j = 0; j < sizeof disk_sizes / sizeof disk_sizes[0]; j++) {
            const double *d = disks[i];
            const int sl = disk_sizes[j][0], lo = disk_sizes[j][1];
            snprintf(label, sizeof label, "disk(%g, %g, %d, %d)", d[0], d[1], sl, lo);
            FOR_EACH_SETUP(label, gluDisk(gq, d[0], d[1], sl, lo), rtuDisk(rq, d[0], d[1], sl, lo));
            for (k = 0; k < sizeof sweeps / sizeof sweeps[0]; k++) {
                const double *s = sweeps[k];
                snprintf(label, sizeof label, "partial_disk(%g, %g, %d, %d, %g, %g)", d[0], d[1],
                         sl, lo, s[0], s[1]);
                FOR_EACH_SETUP(label, gluPartialDisk(gq, d[0], d[1], sl, lo, s[0], s[1]),
                               rtuPartialDisk(rq, d[0], d[1], sl, lo, s[0], s[1]));
            }
        }
    gluQuadricDrawStyle(gq, GLU_FILL);
    rtuQuadricDrawStyle(rq, RTU_FILL);
    /* GLUT's quadric solids. */
    oracle_glutSolidSphere(1.5, 12, 8);
    rtuSolidSphere(1.5, 12, 8);
    compare("glutSolidSphere(1.5, 12, 8)");
    oracle_glutSolidCone(1.0, 2.0, 9, 3);
    rtuSolidCone(1.0, 2.0, 9, 3);
    compare("glutSolidCone(1, 2, 9, 3)");

    /* GLUT's quadric wire shapes: gluSphere / gluCylinder in GLU_LINE. */
    gluQuadricDrawStyle(gq, GLU_LINE);
    gluQuadricNormals(gq, GLU_SMOOTH);
    gluQuadricOrientation(gq, GLU_OUTSIDE);
    gluQuadricTexture(gq, GL_FALSE);
    gluSphere(gq, 1.5, 12, 8);
    rtuWireSphere(1.5, 12, 8);
    compare("glutWireSphere(1.5, 12, 8)");
    gluCylinder(gq, 1.0, 0.0, 2.0, 9, 3);
    rtuWireCone(1.0, 2.0, 9, 3);
    compare("glutWireCone(1, 2, 9, 3)");

    /* The other GLUT shapes: their normals and winding. */
    rtuSolidCube(1.5);
    check_polyhedron("rtuSolidCube");
    rtuSolidTetrahedron();
    check_polyhedron("rtuSolidTetrahedron");
    rtuSolidOctahedron();
    check_polyhedron("rtuSolidOctahedron");
    rtuSolidDodecahedron();
    check_polyhedron("rtuSolidDodecahedron");
    rtuSolidIcosahedron();
    check_polyhedron("rtuSolidIcosahedron");
    rtuSolidTorus(0.3, 1.2, 9, 14);
    check_torus("rtuSolidTorus", 0.3, 1.2);
    rtuSolidTeapot(1.5);
    check_teapot("rtuSolidTeapot", 1.5);

    gluDeleteQuadric(gq);
    rtuDeleteQuadric(rq);
    free(gl_trace.events);
    free(rt_trace.events);
    printf("gl_oracle/trace: %d cases, %d passed, %d failed\n", cases, cases - failures,
           failures);
    return failures != 0;
}
