/* SPDX-License-Identifier: Apache-2.0 */
/*
 * matrices.c - conformance: matrix modes, loads, products, the transform
 * entry points against hand-computed matrices (float and double variants),
 * stacks (depths, overflow, underflow), failing calls leaving the matrix
 * unchanged, and matrices inside object definitions.
 *
 * Storage is column-major: element (row r, column c) is m[c*4 + r], and a
 * point transforms as p' = M p; every product post-multiplies (M = M * A).
 * Reference: docs/matrices.md.
 */
#include "testutil.h"

#include <math.h>
#include <string.h>

#define EPS 1e-6

static void set_cols(double m[16], const double c0[4], const double c1[4], const double c2[4],
                     const double c3[4])
{
    memcpy(m, c0, 4 * sizeof(double));
    memcpy(m + 4, c1, 4 * sizeof(double));
    memcpy(m + 8, c2, 4 * sizeof(double));
    memcpy(m + 12, c3, 4 * sizeof(double));
}

static void translation(double m[16], double x, double y, double z)
{
    tu_identity(m);
    m[12] = x;
    m[13] = y;
    m[14] = z;
}

static void scaling(double m[16], double x, double y, double z)
{
    tu_identity(m);
    m[0] = x;
    m[5] = y;
    m[10] = z;
}

static void matrix_mode(void)
{
    RTint mode = -1;
    tu_section("rtMatrixMode");
    rtMatrixMode(RT_PROJECTION);
    rtGetIntegerv(RT_MATRIX_MODE, &mode);
    CHECK_INT(mode, RT_PROJECTION);
    rtMatrixMode(0x1234);
    CHECK_ERR(RT_INVALID_ENUM);
    rtMatrixMode(RT_TEXTURE_COORD_ARRAY);
    CHECK_ERR(RT_INVALID_ENUM);
    rtGetIntegerv(RT_MATRIX_MODE, &mode);
    CHECK_INT(mode, RT_PROJECTION);
    /* Inside rtBegin: RT_INVALID_OPERATION, mode unchanged. */
    tu_begin_scratch(RT_TRIANGLES);
    rtMatrixMode(RT_MODELVIEW);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();
    rtGetIntegerv(RT_MATRIX_MODE, &mode);
    CHECK_INT(mode, RT_PROJECTION);
    rtMatrixMode(RT_MODELVIEW);
    rtGetIntegerv(RT_MATRIX_MODE, &mode);
    CHECK_INT(mode, RT_MODELVIEW);
    CHECK_NO_ERR();
}

static void transforms(void)
{
    double e[16], a[16], b[16];
    tu_section("translate / scale / rotate against hand-computed matrices");
    rtMatrixMode(RT_MODELVIEW);

    rtLoadIdentity();
    rtTranslatef(1, 2, 3);
    translation(e, 1, 2, 3);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);
    rtLoadIdentity();
    rtTranslated(-1.5, 0.25, 8);
    translation(e, -1.5, 0.25, 8);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);

    rtLoadIdentity();
    rtScalef(2, 3, 4);
    scaling(e, 2, 3, 4);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);
    rtLoadIdentity();
    rtScaled(-1, 0.5, 0); /* a singular scale is a valid matrix */
    scaling(e, -1, 0.5, 0);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);

    /* 90 degrees about +z: x -> y, y -> -x. */
    {
        static const double c0[4] = {0, 1, 0, 0}, c1[4] = {-1, 0, 0, 0}, c2[4] = {0, 0, 1, 0},
                            c3[4] = {0, 0, 0, 1};
        set_cols(e, c0, c1, c2, c3);
        rtLoadIdentity();
        rtRotatef(90, 0, 0, 1);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);
        /* The axis need not be normalised. */
        rtLoadIdentity();
        rtRotated(90, 0, 0, 2.5);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);
        /* Angle sign: -270 degrees is the same rotation. */
        rtLoadIdentity();
        rtRotatef(-270, 0, 0, 1);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 1e-5);
    }
    /* -90 degrees about +x: y -> -z, z -> y. */
    {
        static const double c0[4] = {1, 0, 0, 0}, c1[4] = {0, 0, -1, 0}, c2[4] = {0, 1, 0, 0},
                            c3[4] = {0, 0, 0, 1};
        set_cols(e, c0, c1, c2, c3);
        rtLoadIdentity();
        rtRotated(-90, 1, 0, 0);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);
    }
    /* 120 degrees about (1,1,1): the cyclic permutation x -> y -> z -> x. */
    {
        static const double c0[4] = {0, 1, 0, 0}, c1[4] = {0, 0, 1, 0}, c2[4] = {1, 0, 0, 0},
                            c3[4] = {0, 0, 0, 1};
        set_cols(e, c0, c1, c2, c3);
        rtLoadIdentity();
        rtRotatef(120, 1, 1, 1);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 1e-5);
        rtLoadIdentity();
        rtRotated(120, 3, 3, 3);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 1e-6);
    }
    /* 30 degrees about +y. */
    {
        double c = cos(30.0 * 3.14159265358979323846 / 180.0);
        double s = sin(30.0 * 3.14159265358979323846 / 180.0);
        tu_identity(e);
        e[0] = c;
        e[2] = -s;
        e[8] = s;
        e[10] = c;
        rtLoadIdentity();
        rtRotatef(30, 0, 1, 0);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 1e-6);
    }
    /* A zero axis leaves the matrix unchanged without an error. */
    rtLoadIdentity();
    rtTranslatef(1, 2, 3);
    rtRotatef(45, 0, 0, 0);
    CHECK_NO_ERR();
    translation(e, 1, 2, 3);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);

    /* Products post-multiply: translate then scale = T * S. */
    rtLoadIdentity();
    rtTranslatef(1, 2, 3);
    rtScalef(2, 2, 2);
    translation(a, 1, 2, 3);
    scaling(b, 2, 2, 2);
    tu_mat_mul(e, a, b);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);
    rtLoadIdentity();
    rtScalef(2, 2, 2);
    rtTranslatef(1, 2, 3);
    tu_mat_mul(e, b, a);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);
    /* Rotate then translate: the translation is rotated. */
    {
        static const double c0[4] = {0, 1, 0, 0}, c1[4] = {-1, 0, 0, 0}, c2[4] = {0, 0, 1, 0},
                            c3[4] = {-2, 1, 0, 1};
        set_cols(e, c0, c1, c2, c3);
        rtLoadIdentity();
        rtRotatef(90, 0, 0, 1);
        rtTranslatef(1, 2, 0);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);
    }
    CHECK_NO_ERR();
}

static void loads_and_products(void)
{
    static const float mf[16] = {1, 2, 3, 0, 4, 5, 6, 0, 7, 8, 10, 0, 11, 12, 13, 1};
    static const double md[16] = {0, 1, 0, 0, 2, 0, 0, 0, 0, 0, 3, 0, 1, 1, 1, 1};
    double e[16], a[16], t[16];
    int k;
    tu_section("rtLoadMatrix / rtMultMatrix");
    for (k = 0; k < 16; k++)
        a[k] = mf[k];
    rtLoadMatrixf(mf);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, a, 0.0);
    rtLoadMatrixd(md);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, md, 0.0);
    /* A projective (non-affine) matrix loads as given. */
    {
        static const double p[16] = {1, 0, 0, 0.5, 0, 1, 0, 0.25, 0, 0, 1, -1, 0, 0, 2, 0};
        rtLoadMatrixd(p);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, p, 0.0);
    }
    /* M = md * mf. */
    rtLoadMatrixd(md);
    rtMultMatrixf(mf);
    tu_mat_mul(e, md, a);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 1e-5);
    /* M = T * md. */
    rtLoadIdentity();
    rtTranslated(5, 6, 7);
    rtMultMatrixd(md);
    translation(t, 5, 6, 7);
    tu_mat_mul(e, t, md);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);
    CHECK_NO_ERR();

    /* NULL: RT_INVALID_VALUE, unchanged. */
    rtLoadMatrixf(NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtLoadMatrixd(NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtMultMatrixf(NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtMultMatrixd(NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);
    /* A NaN in a loaded matrix: unchanged. */
    {
        float bad[16];
        memcpy(bad, mf, sizeof bad);
        bad[7] = tu_nan();
        rtLoadMatrixf(bad);
        CHECK_ERR(RT_INVALID_VALUE);
        rtMultMatrixf(bad);
        CHECK_ERR(RT_INVALID_VALUE);
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, EPS);
    }
}

static void projections(void)
{
    double e[16], m0[16], f[16];
    tu_section("rtFrustum / rtOrtho");
    rtMatrixMode(RT_PROJECTION);
    /* Frustum(-1, 3, -2, 2, 1, 5). */
    {
        static const double c0[4] = {0.5, 0, 0, 0}, c1[4] = {0, 0.5, 0, 0},
                            c2[4] = {0.5, 0, -1.5, -1}, c3[4] = {0, 0, -2.5, 0};
        set_cols(f, c0, c1, c2, c3);
    }
    rtLoadIdentity();
    rtFrustum(-1, 3, -2, 2, 1, 5);
    CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, f, EPS);
    /* It multiplies the current matrix. */
    rtLoadIdentity();
    rtTranslatef(0, 0, 1);
    rtFrustum(-1, 3, -2, 2, 1, 5);
    translation(m0, 0, 0, 1);
    tu_mat_mul(e, m0, f);
    CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, e, EPS);
    /* Ortho(-1, 3, -2, 2, 1, 5). */
    {
        static const double c0[4] = {0.5, 0, 0, 0}, c1[4] = {0, 0.5, 0, 0},
                            c2[4] = {0, 0, -0.5, 0}, c3[4] = {-0.5, 0, -1.5, 1};
        set_cols(e, c0, c1, c2, c3);
    }
    rtLoadIdentity();
    rtOrtho(-1, 3, -2, 2, 1, 5);
    CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, e, EPS);
    /* Ortho accepts a negative near plane and near > far. */
    rtLoadIdentity();
    rtOrtho(-1, 1, -1, 1, -1, 1);
    CHECK_NO_ERR();
    rtLoadIdentity();
    rtOrtho(-1, 1, -1, 1, 5, 1);
    CHECK_NO_ERR();
    /* Frustum accepts near > far > 0. */
    rtLoadIdentity();
    rtFrustum(-1, 1, -1, 1, 2, 1);
    CHECK_NO_ERR();

    /* Error cases leave the matrix unchanged. */
    rtLoadIdentity();
    rtFrustum(-1, 3, -2, 2, 1, 5);
    rtFrustum(1, 1, -1, 1, 1, 10);
    CHECK_ERR(RT_INVALID_VALUE);
    rtFrustum(-1, 1, 2, 2, 1, 10);
    CHECK_ERR(RT_INVALID_VALUE);
    rtFrustum(-1, 1, -1, 1, 0, 10);
    CHECK_ERR(RT_INVALID_VALUE);
    rtFrustum(-1, 1, -1, 1, -1, 10);
    CHECK_ERR(RT_INVALID_VALUE);
    rtFrustum(-1, 1, -1, 1, 1, 0);
    CHECK_ERR(RT_INVALID_VALUE);
    rtFrustum(-1, 1, -1, 1, 1, -5);
    CHECK_ERR(RT_INVALID_VALUE);
    rtFrustum(-1, 1, -1, 1, 3, 3);
    CHECK_ERR(RT_INVALID_VALUE);
    rtOrtho(2, 2, -1, 1, 1, 10);
    CHECK_ERR(RT_INVALID_VALUE);
    rtOrtho(-1, 1, 0, 0, 1, 10);
    CHECK_ERR(RT_INVALID_VALUE);
    rtOrtho(-1, 1, -1, 1, 4, 4);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, f, EPS);
    /* The projection mode did not touch the modelview. */
    tu_identity(e);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 0.0);
    CHECK_CURRENT_MATRIX(RT_PROJECTION_MATRIX, f, EPS);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtMatrixMode(RT_MODELVIEW);
    CHECK_NO_ERR();
}

static void double_precision(void)
{
    double e[16];
    tu_section("matrices are stored in double precision");
    /* In float, 1e8 + (1 - 1e8) rounds to 0; in double it is 1. */
    rtLoadIdentity();
    rtTranslated(1e8, 0, 0);
    rtTranslated(1.0 - 1e8, 0, 0);
    translation(e, 1, 0, 0);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 1e-6);
    rtLoadIdentity();
    rtScaled(1e-30, 1, 1);
    rtScaled(1e30, 1, 1);
    tu_identity(e);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 1e-6);
    rtLoadIdentity();
    CHECK_NO_ERR();
}

static void stacks(void)
{
    RTint max_mv = 0, max_pr = 0, depth = 0, i;
    double e[16], t[16];
    tu_section("matrix stacks");
    rtGetIntegerv(RT_MAX_MODELVIEW_STACK_DEPTH, &max_mv);
    rtGetIntegerv(RT_MAX_PROJECTION_STACK_DEPTH, &max_pr);
    CHECK(max_mv >= 32);
    CHECK(max_pr >= 2);
    CHECK_INT(max_mv, 32);
    CHECK_INT(max_pr, 4);

    /* Push copies the top; pop restores. */
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtTranslatef(1, 0, 0);
    rtPushMatrix();
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    CHECK_INT(depth, 2);
    translation(e, 1, 0, 0);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 0.0);
    rtTranslatef(0, 5, 0);
    translation(t, 1, 5, 0);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, t, 0.0);
    rtPopMatrix();
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    CHECK_INT(depth, 1);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 0.0);
    CHECK_NO_ERR();

    /* Fill the modelview stack to its maximum, each level distinct. */
    for (i = 1; i < max_mv; i++) {
        rtPushMatrix();
        rtTranslatef(1, 0, 0);
    }
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    CHECK_INT(depth, max_mv);
    CHECK_NO_ERR();
    translation(e, max_mv, 0, 0);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 0.0);
    rtPushMatrix();
    CHECK_ERR(RT_STACK_OVERFLOW);
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    CHECK_INT(depth, max_mv);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 0.0);
    /* The overflowing push did not overwrite the level below. */
    rtPopMatrix();
    translation(e, max_mv - 1, 0, 0);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 0.0);
    for (i = 2; i < max_mv; i++)
        rtPopMatrix();
    translation(e, 1, 0, 0);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 0.0);
    CHECK_NO_ERR();
    rtPopMatrix();
    CHECK_ERR(RT_STACK_UNDERFLOW);
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    CHECK_INT(depth, 1);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 0.0);

    /* The projection stack is separate and shallower. */
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    for (i = 1; i < max_pr; i++)
        rtPushMatrix();
    rtGetIntegerv(RT_PROJECTION_STACK_DEPTH, &depth);
    CHECK_INT(depth, max_pr);
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    CHECK_INT(depth, 1);
    CHECK_NO_ERR();
    rtPushMatrix();
    CHECK_ERR(RT_STACK_OVERFLOW);
    rtGetIntegerv(RT_PROJECTION_STACK_DEPTH, &depth);
    CHECK_INT(depth, max_pr);
    for (i = 1; i < max_pr; i++)
        rtPopMatrix();
    CHECK_NO_ERR();
    rtPopMatrix();
    CHECK_ERR(RT_STACK_UNDERFLOW);
    rtGetIntegerv(RT_PROJECTION_STACK_DEPTH, &depth);
    CHECK_INT(depth, 1);
    /* Pop in projection mode does not pop the modelview. */
    rtMatrixMode(RT_MODELVIEW);
    rtPushMatrix();
    rtMatrixMode(RT_PROJECTION);
    rtPopMatrix();
    CHECK_ERR(RT_STACK_UNDERFLOW);
    rtMatrixMode(RT_MODELVIEW);
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    CHECK_INT(depth, 2);
    rtPopMatrix();
    rtLoadIdentity();
    CHECK_NO_ERR();
}

static void inside_begin(void)
{
    double e[16];
    RTint depth = 0;
    tu_section("matrix calls inside rtBegin change nothing");
    rtLoadIdentity();
    rtTranslatef(3, 4, 5);
    translation(e, 3, 4, 5);
    tu_begin_scratch(RT_TRIANGLES);
    rtLoadIdentity();
    CHECK_ERR(RT_INVALID_OPERATION);
    rtTranslatef(1, 1, 1);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtScaled(2, 2, 2);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtRotatef(10, 0, 0, 1);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtLoadMatrixd(e);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtMultMatrixd(e);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtFrustum(-1, 1, -1, 1, 1, 2);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtOrtho(-1, 1, -1, 1, 1, 2);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtPushMatrix();
    CHECK_ERR(RT_INVALID_OPERATION);
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    CHECK_INT(depth, 1);
    rtPopMatrix();
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 0.0);
    tu_end_scratch();
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 0.0);
    rtLoadIdentity();
}

static void inside_objects(void)
{
    float bounds[6];
    double e[16];
    RTint depth = 0;
    tu_section("matrix calls inside an object transform later vertices");
    rtLoadIdentity();
    rtNewObject(7);
    rtPushMatrix();
    rtTranslatef(10, 0, 0);
    /* Recorded, not executed (GL_COMPILE): the context's matrix stays. */
    translation(e, 0, 0, 0);
    CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, e, 0.0);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(0, 0, 0);
    rtVertex3f(1, 0, 0);
    rtVertex3f(0, 1, 0);
    rtEnd();
    rtScalef(1, 1, 2);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(0, 0, 1);
    rtVertex3f(1, 0, 1);
    rtVertex3f(0, 1, 1);
    rtEnd();
    rtPopMatrix();
    rtEndObject();
    CHECK_NO_ERR();
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    CHECK_INT(depth, 1);
    rtGetObjectfv(7, RT_OBJECT_BOUNDS, bounds);
    CHECK_NEAR(bounds[0], 10, EPS);
    CHECK_NEAR(bounds[1], 0, EPS);
    CHECK_NEAR(bounds[2], 0, EPS);
    CHECK_NEAR(bounds[3], 11, EPS);
    CHECK_NEAR(bounds[4], 1, EPS);
    CHECK_NEAR(bounds[5], 2, EPS);
    /* Changing the matrix afterwards does not move the recorded vertices. */
    rtTranslatef(100, 0, 0);
    rtGetObjectfv(7, RT_OBJECT_BOUNDS, bounds);
    CHECK_NEAR(bounds[0], 10, EPS);
    rtLoadIdentity();
    /* Stack errors of a list happen when it is called, as in GL; the
     * recording goes on. */
    rtNewObject(8);
    rtPopMatrix();
    CHECK_NO_ERR();
    rtBegin(RT_TRIANGLES);
    rtVertex3f(0, 0, 0);
    rtVertex3f(1, 0, 0);
    rtVertex3f(0, 1, 0);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
    CHECK_INT(tu_object_triangles(8), 1);
    rtInstantiateObject(8);
    CHECK_ERR(RT_STACK_UNDERFLOW);
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=1");
    tu_capture_errors();
    matrix_mode();
    transforms();
    loads_and_products();
    projections();
    double_precision();
    stacks();
    inside_begin();
    inside_objects();
    tu_destroy_context(ctx);
    return test_summary("matrices");
}
