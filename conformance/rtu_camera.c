/* SPDX-License-Identifier: Apache-2.0 */
/*
 * rtu_camera.c - conformance: rtuPerspective and rtuLookAt.
 *
 * Pins: the GLU matrices (the perspective matrix element by element from
 * the gluPerspective reference page; the look-at matrix by what it must do
 * to the eye, the centre and the up vector, and for one case element by
 * element); that both multiply the current matrix (of the current mode)
 * rather than load it; the documented failures: invalid arguments record
 * RT_INVALID_VALUE against the rtu function itself (rtRecordError, not the
 * core call it makes) and change nothing, a call inside
 * rtBegin records RT_INVALID_OPERATION first, no current context is a
 * silent no-op.
 *
 * Reference: docs/rtu.md.
 */
#include "testutil.h"

#include <rt/rtu.h>

#include <math.h>
#include <stdio.h>

#define TOL 1e-5

/* p' = M p for a column-major M (w = 1 for points, 0 for vectors). */
static void transform(const float m[16], const double p[3], double w, double out[3])
{
    int r;
    for (r = 0; r < 3; r++)
        out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r] * w;
}

static void perspective_matrix(double m[16], double fovy, double aspect, double n, double f)
{
    double cot = 1.0 / tan(fovy * 0.5 * 3.14159265358979323846 / 180.0);
    int k;
    for (k = 0; k < 16; k++)
        m[k] = 0.0;
    m[0] = cot / aspect;
    m[5] = cot;
    m[10] = (f + n) / (n - f);
    m[11] = -1.0;
    m[14] = 2.0 * f * n / (n - f);
}

static void perspective(void)
{
    double expected[16];
    double t[16];
    double product[16];
    tu_section("rtuPerspective");
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtuPerspective(60.0, 4.0 / 3.0, 1.0, 100.0);
    CHECK_NO_ERR();
    perspective_matrix(expected, 60.0, 4.0 / 3.0, 1.0, 100.0);
    CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, expected, TOL);

    /* It multiplies: translate first, then T * P. */
    rtLoadIdentity();
    rtTranslated(1.0, 2.0, 3.0);
    rtuPerspective(90.0, 0.5, 0.25, 8.0);
    CHECK_NO_ERR();
    tu_identity(t);
    t[12] = 1.0;
    t[13] = 2.0;
    t[14] = 3.0;
    perspective_matrix(expected, 90.0, 0.5, 0.25, 8.0);
    tu_mat_mul(product, t, expected);
    CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, product, TOL);

    /* The same as the symmetric rtFrustum. */
    {
        float a[16];
        float f[16];
        double b[16];
        int k;
        double ymax = 2.0 * tan(35.0 * 3.14159265358979323846 / 180.0);
        rtLoadIdentity();
        rtuPerspective(70.0, 1.6, 2.0, 50.0);
        tu_get_matrix(RT_PROJECTION_MATRIX, a);
        rtLoadIdentity();
        rtFrustum(-ymax * 1.6, ymax * 1.6, -ymax, ymax, 2.0, 50.0);
        tu_get_matrix(RT_PROJECTION_MATRIX, f);
        for (k = 0; k < 16; k++)
            b[k] = f[k];
        CHECK_MATRIX(a, b, TOL);
        CHECK_NO_ERR();
    }

    /* The modelview works the same way (GLU does not care about the mode). */
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtuPerspective(45.0, 1.0, 1.0, 10.0);
    perspective_matrix(expected, 45.0, 1.0, 1.0, 10.0);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, expected, TOL);
    rtLoadIdentity();
    CHECK_NO_ERR();
}

static void perspective_errors(void)
{
    static const double bad[][4] = {
        {0.0, 1.0, 1.0, 10.0},   {180.0, 1.0, 1.0, 10.0}, {-30.0, 1.0, 1.0, 10.0},
        {200.0, 1.0, 1.0, 10.0}, {60.0, 0.0, 1.0, 10.0},  {60.0, -1.0, 1.0, 10.0},
        {60.0, 1.0, 0.0, 10.0},  {60.0, 1.0, -1.0, 10.0}, {60.0, 1.0, 5.0, 5.0},
        {60.0, 1.0, 5.0, 4.0},
    };
    double before[16];
    size_t i;
    int k;
    tu_section("rtuPerspective errors");
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtTranslated(0.5, -0.5, 2.0);
    {
        float f[16];
        tu_get_matrix(RT_PROJECTION_MATRIX, f);
        for (k = 0; k < 16; k++)
            before[k] = f[k];
    }
    tu_capture_errors();
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        tu_reset_captured();
        rtuPerspective(bad[i][0], bad[i][1], bad[i][2], bad[i][3]);
        if (!CHECK_ERR(RT_INVALID_VALUE))
            fprintf(stderr, "    case %d\n", (int)i);
        CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, before, 0.0);
        /* Documented: the error names the rtu function, not rtMultMatrixd. */
        CHECK_MSG("rtuPerspective");
    }
    /* Non-finite arguments. */
    rtuPerspective(tu_nan_d(), 1.0, 1.0, 10.0);
    CHECK_ERR(RT_INVALID_VALUE);
    rtuPerspective(60.0, tu_inf_d(), 1.0, 10.0);
    CHECK_ERR(RT_INVALID_VALUE);
    rtuPerspective(60.0, 1.0, tu_nan_d(), 10.0);
    CHECK_ERR(RT_INVALID_VALUE);
    rtuPerspective(60.0, 1.0, 1.0, tu_inf_d());
    CHECK_ERR(RT_INVALID_VALUE);
    rtuPerspective(60.0, 1.0, 1.0, tu_nan_d());
    CHECK_ERR(RT_INVALID_VALUE);
    /* A valid call whose matrix overflows is refused, against rtuPerspective. */
    rtuPerspective(1e-310, 1.0, 1.0, 10.0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtuPerspective");
    CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, before, 0.0);

    /* The first error sticks: a later rtu error does not replace it. */
    rtPopMatrix(); /* depth 1: RT_STACK_UNDERFLOW */
    rtuPerspective(0.0, 1.0, 1.0, 10.0);
    CHECK_ERR(RT_STACK_UNDERFLOW);

    /* Inside rtBegin the mode check comes first, also with bad arguments. */
    tu_begin_scratch(RT_TRIANGLES);
    rtuPerspective(60.0, 1.0, 1.0, 10.0);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtuPerspective(0.0, 1.0, 1.0, 10.0);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    CHECK_NO_ERR();
    CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, before, 0.0);
    rtErrorCallback(NULL, NULL);
    rtMatrixMode(RT_MODELVIEW);
}

/* Checks what a look-at matrix must do, whatever its construction. */
static void check_look_at(const double eye[3], const double center[3], const double up[3])
{
    float m[16];
    double p[3], q[3];
    double distance = sqrt((center[0] - eye[0]) * (center[0] - eye[0]) +
                           (center[1] - eye[1]) * (center[1] - eye[1]) +
                           (center[2] - eye[2]) * (center[2] - eye[2]));
    double scale = distance + sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
    int r, c;
    rtLoadIdentity();
    rtuLookAt(eye[0], eye[1], eye[2], center[0], center[1], center[2], up[0], up[1], up[2]);
    CHECK_NO_ERR();
    tu_get_matrix(RT_MODELVIEW_MATRIX, m);
    /* The eye goes to the origin ... */
    transform(m, eye, 1.0, p);
    CHECK_NEAR(p[0], 0.0, TOL * scale);
    CHECK_NEAR(p[1], 0.0, TOL * scale);
    CHECK_NEAR(p[2], 0.0, TOL * scale);
    /* ... the centre onto the -z axis at its distance ... */
    transform(m, center, 1.0, p);
    CHECK_NEAR(p[0], 0.0, TOL * scale);
    CHECK_NEAR(p[1], 0.0, TOL * scale);
    CHECK_NEAR(p[2], -distance, TOL * scale);
    /* ... up into the upper half of the y-z plane ... */
    transform(m, up, 0.0, q);
    CHECK_NEAR(q[0], 0.0, TOL * sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]));
    CHECK(q[1] > 0.0);
    /* ... and the upper 3x3 is a rotation (orthonormal, determinant +1). */
    for (r = 0; r < 3; r++) {
        for (c = 0; c < 3; c++) {
            double dot = m[4 * r] * m[4 * c] + m[4 * r + 1] * m[4 * c + 1] +
                         m[4 * r + 2] * m[4 * c + 2];
            CHECK_NEAR(dot, r == c ? 1.0 : 0.0, TOL);
        }
    }
    CHECK_NEAR(m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
                   m[8] * (m[1] * m[6] - m[5] * m[2]),
               1.0, TOL);
    CHECK_NEAR(m[3], 0.0, 0.0);
    CHECK_NEAR(m[7], 0.0, 0.0);
    CHECK_NEAR(m[11], 0.0, 0.0);
    CHECK_NEAR(m[15], 1.0, 0.0);
}

static void look_at(void)
{
    static const double cases[][9] = {
        {0, 0, 5, 0, 0, 0, 0, 1, 0},        {5, 0, 0, 0, 0, 0, 0, 1, 0},
        {1, 2, 3, 4, 6, 3, 0, 0, 1},        {-3, 7, 2, 1, -1, -4, 0.3, 1, -0.2},
        {10, 10, 10, 0, 0, 0, 0, 0, 3},     {0, 0, 0, 0, 0, -1, 0, 1, 0.999},
        {1e3, -2e3, 5e2, 0, 0, 0, 1, 1, 1}, {0, 0, 0, 1e-3, 0, 0, 0, 1e-3, 0},
    };
    double expected[16];
    size_t i;
    tu_section("rtuLookAt");
    rtMatrixMode(RT_MODELVIEW);
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
        check_look_at(cases[i], cases[i] + 3, cases[i] + 6);

    /* Element by element (gluLookAt): eye (5,0,0) looking at the origin, y up:
     * rows side = (0,0,-1), up = (0,1,0), -forward = (1,0,0), translation (0,0,-5). */
    tu_identity(expected);
    expected[0] = 0.0;
    expected[2] = 1.0;
    expected[8] = -1.0;
    expected[10] = 0.0;
    expected[14] = -5.0;
    rtLoadIdentity();
    rtuLookAt(5, 0, 0, 0, 0, 0, 0, 1, 0);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, expected, TOL);

    /* It multiplies: scale first, then S * L. */
    {
        double s[16], product[16];
        tu_identity(s);
        s[0] = 2.0;
        s[5] = 3.0;
        s[10] = 4.0;
        rtLoadIdentity();
        rtScaled(2.0, 3.0, 4.0);
        rtuLookAt(5, 0, 0, 0, 0, 0, 0, 1, 0);
        tu_mat_mul(product, s, expected);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, product, TOL);
    }
    rtLoadIdentity();
    CHECK_NO_ERR();
}

static void look_at_errors(void)
{
    static const double bad[][9] = {
        {1, 2, 3, 1, 2, 3, 0, 1, 0}, /* eye == center */
        {0, 0, 5, 0, 0, 0, 0, 0, 0}, /* up == 0 */
        {0, 0, 5, 0, 0, 0, 0, 0, 1}, /* up parallel to the view direction */
        {0, 0, 5, 0, 0, 0, 0, 0, -7},
        {0, 0, 0, 1, 1, 1, 2, 2, 2},
    };
    double before[16];
    size_t i;
    int k, arg;
    tu_section("rtuLookAt errors");
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtRotated(30.0, 1.0, 2.0, 3.0);
    {
        float f[16];
        tu_get_matrix(RT_MODELVIEW_MATRIX, f);
        for (k = 0; k < 16; k++)
            before[k] = f[k];
    }
    tu_capture_errors();
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const double *a = bad[i];
        tu_reset_captured();
        rtuLookAt(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8]);
        if (!CHECK_ERR(RT_INVALID_VALUE))
            fprintf(stderr, "    case %d\n", (int)i);
        CHECK_MSG("rtuLookAt");
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, before, 0.0);
    }
    /* A NaN or an infinity in any of the nine arguments. */
    for (arg = 0; arg < 9; arg++) {
        double a[9] = {1, 2, 3, 0, 0, 0, 0, 1, 0};
        int kind;
        for (kind = 0; kind < 2; kind++) {
            a[arg] = kind ? tu_inf_d() : tu_nan_d();
            rtuLookAt(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8]);
            if (!CHECK_ERR(RT_INVALID_VALUE))
                fprintf(stderr, "    argument %d, %s\n", arg, kind ? "inf" : "NaN");
        }
    }
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, before, 0.0);

    tu_begin_scratch(RT_TRIANGLES);
    rtuLookAt(0, 0, 5, 0, 0, 0, 0, 1, 0);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtuLookAt(0, 0, 0, 0, 0, 0, 0, 1, 0);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    CHECK_NO_ERR();
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, before, 0.0);
    rtErrorCallback(NULL, NULL);
}

static void no_context(RTcontext ctx)
{
    double before[16];
    int k;
    tu_section("no current context");
    {
        float f[16];
        tu_get_matrix(RT_MODELVIEW_MATRIX, f);
        for (k = 0; k < 16; k++)
            before[k] = f[k];
    }
    CHECK(rtMakeCurrent(NULL) == RT_TRUE);
    rtuPerspective(60.0, 1.0, 1.0, 10.0);
    rtuPerspective(0.0, 1.0, 1.0, 10.0);
    rtuLookAt(0, 0, 5, 0, 0, 0, 0, 1, 0);
    rtuLookAt(0, 0, 0, 0, 0, 0, 0, 0, 0);
    CHECK(rtMakeCurrent(ctx) == RT_TRUE);
    CHECK_NO_ERR();
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, before, 0.0);
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=1");
    perspective();
    perspective_errors();
    look_at();
    look_at_errors();
    no_context(ctx);
    tu_destroy_context(ctx);
    return test_summary("rtu_camera");
}
