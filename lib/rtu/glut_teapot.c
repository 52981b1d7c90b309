/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_teapot.c - rtuSolidTeapot, rtuWireTeapot: Newell's teapot as GLUT 3
 * draws it.
 *
 * GLUT 3 (Kilgard 1996, sec. 11.9) draws the teapot with OpenGL
 * evaluators: each of the 10 bicubic Bezier patches of teapot_data.h is
 * evaluated on a 7 x 7 grid (glMapGrid2f(7, 0, 1, 7, 0, 1); glEvalMesh2)
 * with GL_AUTO_NORMAL and GL_NORMALIZE, and drawn again reflected: rim,
 * body, lid and bottom in x, in y and in both (four quadrants), handle and
 * spout in y (two halves).  A reflection in one axis also reverses the
 * patch's u direction, so every copy keeps the orientation of its
 * original.  The teapot is then placed by glRotatef(270, 1, 0, 0),
 * glScalef(size / 2) and glTranslatef(0, 0, -1.5): z up becomes y up and
 * the body, of radius 2 in the data, gets radius `size`.
 *
 * We evaluate the same Bezier patches ourselves (Bernstein form, Farin,
 * "Curves and Surfaces for CAGD", sec. 5) and emit what the evaluator
 * emits in Mesa: per row of the grid one triangle strip of the points
 * (u_i, v_j), (u_i, v_j+1) for i = 0..7; the normal is the unit
 * dP/du x dP/dv (GL_AUTO_NORMAL), the texture coordinate (u, v).  The
 * placing transform is applied to the vertices and normals here rather
 * than through the matrix stack, so the call leaves every matrix alone.
 * Where dP/du x dP/dv vanishes (the lid's knob and the bottom's centre,
 * whose patch rows collapse to a point) the normal is taken a little way
 * into the patch, its limit.
 */
#include "report.h"
#include "teapot_data.h"

#include <rt/rtu.h>

#include <math.h>

/* Grid of glutSolidTeapot (GLUT 3.7's teapot(7, size, GL_FILL)). */
#define TEAPOT_GRID 7
/* Parameter step towards the inside of the patch where the normal is
 * degenerate: far below a grid cell (1/7), far above rounding. */
#define TEAPOT_NORMAL_NUDGE 1e-3

/* The cubic Bernstein polynomials at t and their derivatives. */
static void bernstein(double t, double b[4], double d[4])
{
    const double s = 1.0 - t;
    b[0] = s * s * s;
    b[1] = 3.0 * t * s * s;
    b[2] = 3.0 * t * t * s;
    b[3] = t * t * t;
    d[0] = -3.0 * s * s;
    d[1] = 3.0 * s * s - 6.0 * t * s;
    d[2] = 6.0 * t * s - 3.0 * t * t;
    d[3] = 3.0 * t * t;
}

/* Point and tangents of the patch net[v][u] at (u, v). */
static void eval_patch(const double net[4][4][3], double u, double v, double p[3],
                       double pu[3], double pv[3])
{
    double bu[4], du[4], bv[4], dv[4];
    int j, k, c;
    bernstein(u, bu, du);
    bernstein(v, bv, dv);
    for (c = 0; c < 3; c++) {
        p[c] = pu[c] = pv[c] = 0.0;
        for (j = 0; j < 4; j++)
            for (k = 0; k < 4; k++) {
                p[c] += bv[j] * bu[k] * net[j][k][c];
                pu[c] += bv[j] * du[k] * net[j][k][c];
                pv[c] += dv[j] * bu[k] * net[j][k][c];
            }
    }
}

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Emits the vertex (u, v) of a patch, placed as GLUT places the teapot. */
static void emit_vertex(const double net[4][4][3], double u, double v, double half_size)
{
    double p[3], pu[3], pv[3], n[3], len;
    eval_patch(net, u, v, p, pu, pv);
    cross(pu, pv, n);
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 1e-9)) {
        double q[3];
        double uu = u + (u < 0.5 ? TEAPOT_NORMAL_NUDGE : -TEAPOT_NORMAL_NUDGE);
        double vv = v + (v < 0.5 ? TEAPOT_NORMAL_NUDGE : -TEAPOT_NORMAL_NUDGE);
        eval_patch(net, uu, vv, q, pu, pv);
        cross(pu, pv, n);
        len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    if (len > 0.0)
        rtNormal3f((float)(n[0] / len), (float)(n[2] / len), (float)(-n[1] / len));
    rtTexCoord2f((float)u, (float)v);
    /* Translate by -1.5 in z, scale, rotate 270 degrees about x. */
    rtVertex3f((float)(half_size * p[0]), (float)(half_size * (p[2] - 1.5)),
               (float)(half_size * -p[1]));
}

/* The wire teapot (glutWireTeapot: glEvalMesh2(GL_LINE)) draws the grid's
 * lines through the same points: a line strip along u for every row v_j
 * (j = 0 .. 7), then one along v for every column u_i. */
static void draw_patch_lines(const double net[4][4][3], double half_size)
{
    int i, j;
    for (j = 0; j <= TEAPOT_GRID; j++) {
        rtBegin(RT_LINE_STRIP);
        for (i = 0; i <= TEAPOT_GRID; i++)
            emit_vertex(net, (double)i / TEAPOT_GRID, (double)j / TEAPOT_GRID, half_size);
        rtEnd();
    }
    for (i = 0; i <= TEAPOT_GRID; i++) {
        rtBegin(RT_LINE_STRIP);
        for (j = 0; j <= TEAPOT_GRID; j++)
            emit_vertex(net, (double)i / TEAPOT_GRID, (double)j / TEAPOT_GRID, half_size);
        rtEnd();
    }
}

static void draw_patch(const double net[4][4][3], double half_size)
{
    int i, j;
    for (j = 0; j < TEAPOT_GRID; j++) {
        const double v0 = (double)j / TEAPOT_GRID;
        const double v1 = (double)(j + 1) / TEAPOT_GRID;
        rtBegin(RT_TRIANGLE_STRIP);
        for (i = 0; i <= TEAPOT_GRID; i++) {
            const double u = (double)i / TEAPOT_GRID;
            emit_vertex(net, u, v0, half_size);
            emit_vertex(net, u, v1, half_size);
        }
        rtEnd();
    }
}

static void draw_teapot(RTdouble size, int wire, const char *caller)
{
    const double half_size = 0.5 * size;
    int patch, copy, j, k, c;
    if (!(size >= 0.0) || !isfinite(size)) {
        rtu_record_error(RT_INVALID_VALUE, caller, "size must be finite and >= 0");
        return;
    }
    for (patch = 0; patch < RTU_TEAPOT_PATCHES; patch++) {
        const int copies = patch < RTU_TEAPOT_FOUR_FOLD ? 4 : 2;
        for (copy = 0; copy < copies; copy++) {
            /* Copy 0 as given; 1 mirrored in y, 2 in x (both with u
             * reversed); 3 mirrored in x and y (a half turn, u kept). */
            const int reverse_u = copy == 1 || copy == 2;
            const double sx = (copy == 2 || copy == 3) ? -1.0 : 1.0;
            const double sy = (copy == 1 || copy == 3) ? -1.0 : 1.0;
            double net[4][4][3];
            for (j = 0; j < 4; j++)
                for (k = 0; k < 4; k++) {
                    const int index = rtu_teapot_patches[patch][j * 4 + (reverse_u ? 3 - k : k)];
                    for (c = 0; c < 3; c++)
                        net[j][k][c] = rtu_teapot_points[index][c];
                    net[j][k][0] *= sx;
                    net[j][k][1] *= sy;
                }
            if (wire)
                draw_patch_lines((const double(*)[4][3])net, half_size);
            else
                draw_patch((const double(*)[4][3])net, half_size);
        }
    }
}

void rtuSolidTeapot(RTdouble size)
{
    draw_teapot(size, 0, "rtuSolidTeapot");
}

void rtuWireTeapot(RTdouble size)
{
    draw_teapot(size, 1, "rtuWireTeapot");
}
