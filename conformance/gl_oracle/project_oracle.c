/* SPDX-License-Identifier: Apache-2.0 */
/*
 * project_oracle.c - rtuProject, rtuUnProject, rtuPickMatrix and
 * rtuOrtho2D against Mesa's libGLU (gluProject, gluUnProject,
 * gluPickMatrix, gluOrtho2D) on seeded random inputs.
 *
 * Tolerances (docs/quadrics.md):
 *   rtuProject     bit for bit: the same doubles as gluProject.
 *   rtuUnProject   each coordinate within UNPROJECT_REL_TOL of GLU's,
 *                  relative to max(1, |GLU's|): the two invert proj*model
 *                  by different cofactor expansions, which round
 *                  differently.  Both fail (RT_FALSE / GL_FALSE) on the same
 *                  inputs: a singular matrix, w = 0.
 *   rtuPickMatrix, rtuOrtho2D  GLU's formulas, checked on both sides:
 *                  Tracelist's matrix within 8 float epsilons (of the summed
 *                  magnitudes of each element's terms) of the product in
 *                  double; Mesa's within the same of the product of what
 *                  Mesa receives (GLU passes float arguments to glTranslatef
 *                  and glScalef, Mesa's glOrtho stores its bounds as floats;
 *                  that rounding alone moves some elements by 1e-5).
 */
#include "testutil.h"

#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glu.h>

#include <rt/rtu.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TRIALS 20000
#define UNPROJECT_REL_TOL 1e-11
#define PI 3.14159265358979323846

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;

/* Uniform in [lo, hi) (xorshift64*). */
static double uniform(double lo, double hi)
{
    uint64_t x;
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    x = rng_state * 0x2545F4914F6CDD1Dull;
    return lo + (hi - lo) * (double)(x >> 11) / 9007199254740992.0;
}

/* A modelview as applications build them: rotation about a random axis,
 * non-uniform scale, translation (column-major). */
static void random_model(double m[16])
{
    double axis[3] = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
    double len = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]) + 1e-3;
    double a = uniform(-PI, PI), c = cos(a), s = sin(a), t = 1 - c;
    double x = axis[0] / len, y = axis[1] / len, z = axis[2] / len;
    double sc[3] = {uniform(0.2, 3), uniform(0.2, 3), uniform(0.2, 3)};
    double r[9] = {t * x * x + c,     t * x * y + s * z, t * x * z - s * y,
                   t * x * y - s * z, t * y * y + c,     t * y * z + s * x,
                   t * x * z + s * y, t * y * z - s * x, t * z * z + c};
    int col, row;
    for (col = 0; col < 3; col++)
        for (row = 0; row < 3; row++)
            m[col * 4 + row] = r[col * 3 + row] * sc[col];
    m[3] = m[7] = m[11] = 0.0;
    m[12] = uniform(-10, 10);
    m[13] = uniform(-10, 10);
    m[14] = uniform(-30, -1);
    m[15] = 1.0;
}

/* A perspective (gluPerspective's matrix) or an orthographic projection. */
static void random_projection(double p[16])
{
    memset(p, 0, 16 * sizeof p[0]);
    if (uniform(0, 1) < 0.7) {
        double f = 1.0 / tan(uniform(10, 120) * PI / 360.0);
        double n = uniform(0.01, 2), fa = n + uniform(1, 1000);
        p[0] = f / uniform(0.5, 2.5);
        p[5] = f;
        p[10] = (fa + n) / (n - fa);
        p[11] = -1.0;
        p[14] = 2 * fa * n / (n - fa);
    } else {
        double l = uniform(-20, 0), r = uniform(1, 20), b = uniform(-20, 0), t = uniform(1, 20);
        double n = uniform(-10, 0), fa = uniform(1, 100);
        p[0] = 2 / (r - l);
        p[5] = 2 / (t - b);
        p[10] = -2 / (fa - n);
        p[12] = -(r + l) / (r - l);
        p[13] = -(t + b) / (t - b);
        p[14] = -(fa + n) / (fa - n);
        p[15] = 1.0;
    }
}

static void random_viewport(int v[4])
{
    v[0] = (int)uniform(-100, 100);
    v[1] = (int)uniform(-100, 100);
    v[2] = (int)uniform(1, 4000);
    v[3] = (int)uniform(1, 4000);
}

static void project(void)
{
    long exact = 0, differ = 0, agree_fail = 0;
    int trial;
    tu_section("rtuProject vs gluProject, bit for bit");
    for (trial = 0; trial < TRIALS; trial++) {
        double model[16], proj[16], a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
        double obj[3] = {uniform(-50, 50), uniform(-50, 50), uniform(-50, 50)};
        int view[4];
        RTboolean ok_rt;
        GLint ok_gl;
        random_model(model);
        random_projection(proj);
        random_viewport(view);
        ok_rt = rtuProject(obj[0], obj[1], obj[2], model, proj, view, &a[0], &a[1], &a[2]);
        ok_gl = gluProject(obj[0], obj[1], obj[2], model, proj, view, &b[0], &b[1], &b[2]);
        if (ok_rt != (RTboolean)ok_gl)
            differ++;
        else if (!ok_rt)
            agree_fail++;
        else if (memcmp(a, b, sizeof a) == 0)
            exact++;
        else
            differ++;
    }
    printf("rtuProject: %ld of %d bit-identical, %ld differ, %ld both failed\n", exact, TRIALS,
           differ, agree_fail);
    CHECK_INT(differ, 0);
    CHECK(exact > TRIALS * 9 / 10);

    /* w = 0: a point in the eye's plane under a perspective projection. */
    {
        double model[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        double proj[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, -1, 0, 0, -0.2, 0};
        int view[4] = {0, 0, 100, 100};
        double x = 7, y = 8, z = 9;
        CHECK_INT(gluProject(1, 2, 0, model, proj, view, &x, &y, &z), GL_FALSE);
        CHECK_INT(rtuProject(1, 2, 0, model, proj, view, &x, &y, &z), RT_FALSE);
        CHECK(x == 7 && y == 8 && z == 9);
        CHECK_INT(rtuProject(1, 2, 3, NULL, proj, view, &x, &y, &z), RT_FALSE);
        CHECK_INT(rtuProject(1, 2, 3, model, proj, view, NULL, &y, &z), RT_FALSE);
    }
}

static void unproject(void)
{
    double worst = 0.0;
    long compared = 0, disagree = 0;
    int trial;
    tu_section("rtuUnProject vs gluUnProject");
    for (trial = 0; trial < TRIALS; trial++) {
        double model[16], proj[16], a[3], b[3];
        double win[3];
        int view[4], k;
        RTboolean ok_rt;
        GLint ok_gl;
        random_model(model);
        random_projection(proj);
        random_viewport(view);
        win[0] = uniform(view[0], view[0] + view[2]);
        win[1] = uniform(view[1], view[1] + view[3]);
        win[2] = uniform(0, 1);
        ok_rt = rtuUnProject(win[0], win[1], win[2], model, proj, view, &a[0], &a[1], &a[2]);
        ok_gl = gluUnProject(win[0], win[1], win[2], model, proj, view, &b[0], &b[1], &b[2]);
        if (ok_rt != (RTboolean)ok_gl) {
            disagree++;
            continue;
        }
        if (!ok_rt)
            continue;
        compared++;
        for (k = 0; k < 3; k++) {
            double rel = fabs(a[k] - b[k]) / fmax(1.0, fabs(b[k]));
            worst = fmax(worst, rel);
        }
    }
    printf("rtuUnProject: %ld compared, worst relative difference %.3g (tolerance %.0g)\n",
           compared, worst, UNPROJECT_REL_TOL);
    CHECK_INT(disagree, 0);
    CHECK_INT(compared, TRIALS);
    CHECK(worst <= UNPROJECT_REL_TOL);

    /* A singular product fails in both and leaves the outputs alone. */
    {
        double model[16] = {0};
        double proj[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        int view[4] = {0, 0, 100, 100};
        double x = 7, y = 8, z = 9;
        CHECK_INT(gluUnProject(5, 5, 0.5, model, proj, view, &x, &y, &z), GL_FALSE);
        CHECK_INT(rtuUnProject(5, 5, 0.5, model, proj, view, &x, &y, &z), RT_FALSE);
        CHECK(x == 7 && y == 8 && z == 9);
        CHECK_INT(rtuUnProject(5, 5, 0.5, proj, proj, NULL, &x, &y, &z), RT_FALSE);
    }
}

/* v rounded to float.  Through a volatile: GCC 12 at -O2 was seen to
 * drop the rounding of a parameter assigned its own float cast. */
static double to_float(double v)
{
    volatile float f = (float)v;
    return f;
}

/* The matrices of gluPickMatrix and gluOrtho2D (column-major).  With
 * `as_gl` they are formed the way Mesa receives them: the pick translation
 * and scale as the floats GLU passes to glTranslatef and glScalef, the
 * ortho bounds rounded to float as Mesa's glOrtho stores them. */
static void pick_ortho_matrices(const int view[4], double x, double y, double dx, double dy,
                                double l, double r, double b, double t, int as_gl,
                                double pick[16], double ortho[16])
{
    memset(pick, 0, 16 * sizeof pick[0]);
    memset(ortho, 0, 16 * sizeof ortho[0]);
    pick[0] = view[2] / dx;
    pick[5] = view[3] / dy;
    pick[12] = (view[2] - 2 * (x - view[0])) / dx;
    pick[13] = (view[3] - 2 * (y - view[1])) / dy;
    if (as_gl) {
        pick[0] = to_float(pick[0]);
        pick[5] = to_float(pick[5]);
        pick[12] = to_float(pick[12]);
        pick[13] = to_float(pick[13]);
        l = to_float(l);
        r = to_float(r);
        b = to_float(b);
        t = to_float(t);
    }
    pick[10] = pick[15] = 1.0;
    ortho[0] = 2 / (r - l);
    ortho[5] = 2 / (t - b);
    ortho[10] = -1.0;
    ortho[12] = -(r + l) / (r - l);
    ortho[13] = -(t + b) / (t - b);
    ortho[15] = 1.0;
}

/*
 * Checks a float matrix against the product pick * ortho: each element
 * within FLOAT_ROUNDINGS float epsilons of the summed magnitudes of its
 * terms (the float arithmetic and storage of either library).
 */
#define FLOAT_ROUNDINGS 8
static int matrix_close(const char *who, const float m[16], const double pick[16],
                        const double ortho[16])
{
    int r, c, j, close = 1;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) {
            double exact = 0.0, bound = 0.0, tol;
            for (j = 0; j < 4; j++) {
                exact += pick[j * 4 + r] * ortho[c * 4 + j];
                bound += fabs(pick[j * 4 + r] * ortho[c * 4 + j]);
            }
            tol = FLOAT_ROUNDINGS * FLT_EPSILON * bound;
            if (fabs(m[c * 4 + r] - exact) > tol) {
                printf("%s: element %d: %.9g, expected %.9g, tolerance %.3g\n", who, c * 4 + r,
                       m[c * 4 + r], exact, tol);
                close = 0;
            }
        }
    return close;
}

static void pick_and_ortho(void)
{
    int trial;
    tu_section("rtuPickMatrix, rtuOrtho2D vs GLU (through OSMesa)");
    for (trial = 0; trial < 500; trial++) {
        int view[4];
        double x, y, dx, dy, l, r, b, t;
        random_viewport(view);
        x = uniform(view[0], view[0] + view[2]);
        y = uniform(view[1], view[1] + view[3]);
        dx = uniform(1, 50);
        dy = uniform(1, 50);
        l = uniform(-100, 0);
        r = l + uniform(0.5, 200);
        b = uniform(-100, 0);
        t = b + uniform(0.5, 200);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        gluPickMatrix(x, y, dx, dy, view);
        gluOrtho2D(l, r, b, t);
        rtMatrixMode(RT_PROJECTION);
        rtLoadIdentity();
        rtuPickMatrix(x, y, dx, dy, view);
        rtuOrtho2D(l, r, b, t);
        CHECK_NO_ERR();
        {
            double pick[16], ortho[16];
            GLfloat gl[16];
            RTfloat rt[16];
            glGetFloatv(GL_PROJECTION_MATRIX, gl);
            rtGetFloatv(RT_PROJECTION_MATRIX, rt);
            pick_ortho_matrices(view, x, y, dx, dy, l, r, b, t, 0, pick, ortho);
            CHECK(matrix_close("rtuPickMatrix + rtuOrtho2D", rt, pick, ortho));
            pick_ortho_matrices(view, x, y, dx, dy, l, r, b, t, 1, pick, ortho);
            CHECK(matrix_close("gluPickMatrix + gluOrtho2D", gl, pick, ortho));
        }
    }

    tu_section("rtuPickMatrix errors");
    {
        int view[4] = {0, 0, 100, 100};
        int empty[4] = {0, 0, 0, 100};
        double identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        rtLoadIdentity();
        tu_capture_errors();
        rtuPickMatrix(10, 10, 0.0, 5.0, view);
        CHECK_ERR(RT_INVALID_VALUE);
        rtuPickMatrix(10, 10, 5.0, -1.0, view);
        CHECK_ERR(RT_INVALID_VALUE);
        rtuPickMatrix(10, 10, NAN, 5.0, view);
        CHECK_ERR(RT_INVALID_VALUE);
        rtuPickMatrix(10, 10, 5.0, 5.0, NULL);
        CHECK_ERR(RT_INVALID_VALUE);
        rtuPickMatrix(10, 10, 5.0, 5.0, empty);
        CHECK_ERR(RT_INVALID_VALUE);
        CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, identity, 0.0);
        /* Inside rtBegin the core's check comes first, as for rtMultMatrixd. */
        tu_begin_scratch(RT_TRIANGLES);
        rtuPickMatrix(10, 10, 5.0, 5.0, view);
        CHECK_ERR(RT_INVALID_OPERATION);
        rtuOrtho2D(0, 1, 0, 1);
        CHECK_ERR(RT_INVALID_OPERATION);
        tu_end_scratch();
        rtuOrtho2D(1, 1, 0, 1);
        CHECK_ERR(RT_INVALID_VALUE);
        CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, identity, 0.0);
    }
}

int main(void)
{
    unsigned char *buffer = malloc(16 * 16 * 4);
    OSMesaContext gl = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    RTcontext ctx;
    if (!buffer || !gl || !OSMesaMakeCurrent(gl, buffer, GL_UNSIGNED_BYTE, 16, 16)) {
        fprintf(stderr, "project_oracle: no OSMesa context\n");
        return 1;
    }
    ctx = tu_make_context(NULL);
    project();
    unproject();
    pick_and_ortho();
    tu_destroy_context(ctx);
    OSMesaDestroyContext(gl);
    free(buffer);
    return test_summary("gl_oracle/project");
}
