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
 * The cases cover every normal mode, both orientations, with and without
 * texture coordinates, the slice clamp (GLU's 240-entry tables), the
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

/* ---- cases ---------------------------------------------------------------- */

static const GLenum normal_modes[3] = {GLU_SMOOTH, GLU_FLAT, GLU_NONE};
static const RTenum rt_normal_modes[3] = {RTU_SMOOTH, RTU_FLAT, RTU_NONE};

/* Calls `draw` on a GLU and an rtu quadric set up alike, for every normal
 * mode, orientation and texture setting, and compares each pair. */
#define FOR_EACH_SETUP(label, gl_call, rt_call)                                               \
    do {                                                                                      \
        int nm_, o_, tex_;                                                                    \
        for (nm_ = 0; nm_ < 3; nm_++)                                                         \
            for (o_ = 0; o_ < 2; o_++)                                                        \
                for (tex_ = 0; tex_ < 2; tex_++) {                                            \
                    char what_[256];                                                          \
                    gluQuadricNormals(gq, normal_modes[nm_]);                                 \
                    gluQuadricOrientation(gq, o_ ? GLU_INSIDE : GLU_OUTSIDE);                 \
                    gluQuadricTexture(gq, (GLboolean)tex_);                                   \
                    rtuQuadricNormals(rq, rt_normal_modes[nm_]);                              \
                    rtuQuadricOrientation(rq, o_ ? RTU_INSIDE : RTU_OUTSIDE);                 \
                    rtuQuadricTexture(rq, (RTboolean)tex_);                                   \
                    gl_call;                                                                  \
                    rt_call;                                                                  \
                    snprintf(what_, sizeof what_, "%s [normals %d, %s, texture %d]", label,   \
                             nm_, o_ ? "inside" : "outside", tex_);                           \
                    compare(what_);                                                           \
                }                                                                             \
    } while (0)

int main(void)
{
    GLUquadric *gq = gluNewQuadric();
    RTUquadric *rq = rtuNewQuadric();
    char label[128];
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
            FOR_EACH_SETUP(label, gluCylinder(gq, c[0], c[1], c[2], sl, st),
                           rtuCylinder(rq, c[0], c[1], c[2], sl, st));
        }
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
    /* GLUT's quadric solids. */
    oracle_glutSolidSphere(1.5, 12, 8);
    rtuSolidSphere(1.5, 12, 8);
    compare("glutSolidSphere(1.5, 12, 8)");
    oracle_glutSolidCone(1.0, 2.0, 9, 3);
    rtuSolidCone(1.0, 2.0, 9, 3);
    compare("glutSolidCone(1, 2, 9, 3)");

    gluDeleteQuadric(gq);
    rtuDeleteQuadric(rq);
    free(gl_trace.events);
    free(rt_trace.events);
    printf("gl_oracle/trace: %d cases, %d passed, %d failed\n", cases, cases - failures,
           failures);
    return failures != 0;
}
