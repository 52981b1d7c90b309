/* SPDX-License-Identifier: Apache-2.0 */
/*
 * wire_calls.c - the GLUT wire shapes call by call: rtuWireSphere ...
 * rtuWireIcosahedron must emit line primitives only (RT_LINE_LOOP,
 * RT_LINE_STRIP), as many as GLUT draws, through the vertices of their
 * solid namesakes and no others (the same floats), and the polyhedra's and
 * the cube's loops must run along edges of their faces.
 *
 * How: this program defines rtBegin, rtEnd, rtVertex3f(v), rtNormal3f(v),
 * rtTexCoord2f and rtRecordError itself and exports them, so rtu's calls
 * land here (an executable's definitions come first in the dynamic
 * linker's search) and are recorded instead of drawn; no context and no
 * line rendering are needed (the core's lines come from another branch).
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include "check.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EXPORT __attribute__((visibility("default")))
#define MAX_VERTICES 200000
#define MAX_BLOCKS 20000

struct trace {
    float (*v)[3];
    int count;
    int block_start[MAX_BLOCKS];
    int block_size[MAX_BLOCKS];
    RTenum block_mode[MAX_BLOCKS];
    int blocks;
    int errors;
    int open;
};

static struct trace *current;

EXPORT void rtBegin(RTenum mode)
{
    if (current->open || current->blocks >= MAX_BLOCKS) {
        current->errors++;
        return;
    }
    current->open = 1;
    current->block_mode[current->blocks] = mode;
    current->block_start[current->blocks] = current->count;
    current->block_size[current->blocks] = 0;
}

EXPORT void rtEnd(void)
{
    if (!current->open) {
        current->errors++;
        return;
    }
    current->open = 0;
    current->blocks++;
}

EXPORT void rtVertex3f(RTfloat x, RTfloat y, RTfloat z)
{
    if (!current->open || current->count >= MAX_VERTICES) {
        current->errors++;
        return;
    }
    current->v[current->count][0] = x;
    current->v[current->count][1] = y;
    current->v[current->count][2] = z;
    current->count++;
    current->block_size[current->blocks]++;
}

EXPORT void rtVertex3fv(const RTfloat *v)
{
    rtVertex3f(v[0], v[1], v[2]);
}

EXPORT void rtNormal3f(RTfloat x, RTfloat y, RTfloat z)
{
    (void)x;
    (void)y;
    (void)z;
}

EXPORT void rtNormal3fv(const RTfloat *v)
{
    (void)v;
}

EXPORT void rtTexCoord2f(RTfloat s, RTfloat t)
{
    (void)s;
    (void)t;
}

EXPORT void rtRecordError(RTenum error, const char *function, const char *message)
{
    fprintf(stderr, "recorded 0x%x by %s: %s\n", error, function, message);
    current->errors++;
}

static struct trace *trace_new(void)
{
    struct trace *t = calloc(1, sizeof *t);
    if (t)
        t->v = malloc(sizeof(float[3]) * MAX_VERTICES);
    if (!t || !t->v)
        exit(2);
    return t;
}

static void trace_free(struct trace *t)
{
    free(t->v);
    free(t);
}

/* Equal coordinates (by value: a pole may be +0 in one and -0 in the
 * other, the same point). */
static int same_point(const float a[3], const float b[3])
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* 1 when v is one of t's vertices, bit for bit. */
static int contains(const struct trace *t, const float v[3])
{
    int i;
    for (i = 0; i < t->count; i++)
        if (same_point(t->v[i], v))
            return 1;
    return 0;
}

/* Runs solid() and wire() into two traces and checks the wire trace:
 * lines only, `blocks` of them, vertices exactly the solid's set (every
 * solid vertex on some line, no other point; compared by value).  Returns the wire trace. */
static struct trace *check_shape(const char *name, void (*solid)(void), void (*wire)(void),
                                 int blocks)
{
    struct trace *s = trace_new(), *w = trace_new();
    int i, lines_only = 1, outside = 0, missing = 0;
    current = s;
    solid();
    current = w;
    wire();
    for (i = 0; i < w->blocks; i++)
        lines_only &= w->block_mode[i] == RT_LINE_LOOP || w->block_mode[i] == RT_LINE_STRIP;
    for (i = 0; i < w->count; i++)
        outside += !contains(s, w->v[i]);
    for (i = 0; i < s->count; i++)
        missing += !contains(w, s->v[i]);
    CHECKF(s->errors == 0 && w->errors == 0 && !w->open, "%s: %d/%d errors", name, s->errors,
           w->errors);
    CHECKF(lines_only, "%s: a block that is not a line loop or strip", name);
    CHECKF(w->blocks == blocks, "%s: %d line blocks, GLUT draws %d", name, w->blocks, blocks);
    CHECKF(outside == 0, "%s: %d wire vertices are not vertices of the solid", name, outside);
    CHECKF(missing == 0, "%s: %d solid vertices are on no line", name, missing);
    trace_free(s);
    return w;
}

/* Every block has `size` vertices and every segment of it (closing one
 * included) is an edge of one of the solid's faces: its length is the
 * solid's edge length (all edges of a regular solid are equal). */
static void check_loops(const char *name, const struct trace *w, int size, double edge)
{
    int b, k, bad_size = 0, bad_edge = 0;
    for (b = 0; b < w->blocks; b++) {
        const int first = w->block_start[b], n = w->block_size[b];
        bad_size += n != size || w->block_mode[b] != RT_LINE_LOOP;
        for (k = 0; k < n; k++) {
            const float *p = w->v[first + k], *q = w->v[first + (k + 1) % n];
            double d = sqrt((double)(p[0] - q[0]) * (p[0] - q[0]) +
                            (double)(p[1] - q[1]) * (p[1] - q[1]) +
                            (double)(p[2] - q[2]) * (p[2] - q[2]));
            bad_edge += fabs(d - edge) > 1e-5;
        }
    }
    CHECKF(bad_size == 0, "%s: %d blocks are not line loops of %d vertices", name, bad_size, size);
    CHECKF(bad_edge == 0, "%s: %d segments are not edges (length %g)", name, bad_edge, edge);
}

static void solid_sphere(void) { rtuSolidSphere(1.5, 12, 7); }
static void wire_sphere(void) { rtuWireSphere(1.5, 12, 7); }
static void solid_cone(void) { rtuSolidCone(1.2, 2.5, 10, 4); }
static void wire_cone(void) { rtuWireCone(1.2, 2.5, 10, 4); }
static void solid_cube(void) { rtuSolidCube(2.0); }
static void wire_cube(void) { rtuWireCube(2.0); }
static void solid_torus(void) { rtuSolidTorus(0.5, 1.4, 10, 16); }
static void wire_torus(void) { rtuWireTorus(0.5, 1.4, 10, 16); }
static void solid_teapot(void) { rtuSolidTeapot(1.3); }
static void wire_teapot(void) { rtuWireTeapot(1.3); }

int main(void)
{
    struct trace *w;
    const double phi = (1.0 + sqrt(5.0)) / 2.0;
    /* Sphere: stacks - 1 circles and one meridian per slice. */
    trace_free(check_shape("sphere", solid_sphere, wire_sphere, 6 + 12));
    /* Cone: stacks + 1 circles (apex included) and one line per slice. */
    trace_free(check_shape("cone", solid_cone, wire_cone, 5 + 10));
    /* Torus: the tube circles at the rings + 1 ring boundaries and the
     * ring circles at the sides + 1 tube points of the solid's strips. */
    trace_free(check_shape("torus", solid_torus, wire_torus, 17 + 11));
    /* Teapot: 32 patches, each 8 rows and 8 columns of its 7 x 7 grid. */
    trace_free(check_shape("teapot", solid_teapot, wire_teapot, 32 * 16));
    w = check_shape("cube", solid_cube, wire_cube, 6);
    check_loops("cube", w, 4, 2.0);
    trace_free(w);
    w = check_shape("tetrahedron", rtuSolidTetrahedron, rtuWireTetrahedron, 4);
    check_loops("tetrahedron", w, 3, 2.0 * sqrt(2.0));
    trace_free(w);
    w = check_shape("octahedron", rtuSolidOctahedron, rtuWireOctahedron, 8);
    check_loops("octahedron", w, 3, sqrt(2.0));
    trace_free(w);
    w = check_shape("icosahedron", rtuSolidIcosahedron, rtuWireIcosahedron, 20);
    check_loops("icosahedron", w, 3, 2.0 / sqrt(1.0 + phi * phi));
    trace_free(w);
    w = check_shape("dodecahedron", rtuSolidDodecahedron, rtuWireDodecahedron, 12);
    check_loops("dodecahedron", w, 5, 2.0 / phi);
    trace_free(w);
    /* Bad arguments are reported, nothing drawn. */
    w = trace_new();
    current = w;
    rtuWireSphere(-1.0, 8, 8);
    rtuWireCone(1.0, 1.0, 1, 1);
    rtuWireTorus(0.5, 1.0, 0, 4);
    rtuWireCube(NAN);
    rtuWireTeapot(-2.0);
    CHECK_INT(w->errors, 5);
    CHECK_INT(w->count, 0);
    trace_free(w);
    return test_summary("glut/wire_calls");
}
