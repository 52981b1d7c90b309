/* SPDX-License-Identifier: Apache-2.0 */
/*
 * mat4.h - 4x4 double matrices, column-major as in OpenGL.
 *
 * Element (row r, column c) is m[c*4 + r]; points transform as p' = M p.
 * Matrices are kept in double so that long chains of rtRotate/rtTranslate
 * and near-singular instance transforms lose as little as possible before
 * they are rounded to float for traversal.
 */
#ifndef RT_BASE_MAT4_H
#define RT_BASE_MAT4_H

#include <math.h>
#include <string.h>

/* fmax without the library call (GCC calls libm's fmax, through the
 * PLT, for its NaN rule), for a left operand that is never NaN: the same
 * result as fmax, a NaN on the right giving the left. */
static inline double mat4_fmax_left(double x, double y)
{
    return y > x ? y : x;
}

static inline void mat4_identity(double m[16])
{
    memset(m, 0, 16 * sizeof(double));
    m[0] = m[5] = m[10] = m[15] = 1.0;
}

/* out = a * b; out may alias a or b. */
static inline void mat4_mul(double out[16], const double a[16], const double b[16])
{
    double r[16];
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++) {
            double s = 0.0;
            for (int k = 0; k < 4; k++)
                s += a[k * 4 + row] * b[c * 4 + k];
            r[c * 4 + row] = s;
        }
    memcpy(out, r, sizeof(r));
}

static inline int mat4_is_finite(const double m[16])
{
    for (int i = 0; i < 16; i++)
        if (!isfinite(m[i]))
            return 0;
    return 1;
}

/* p' = M (p, 1), homogeneous divide omitted (affine use). */
static inline void mat4_transform_point(const double m[16], const double p[3], double out[3])
{
    for (int r = 0; r < 3; r++)
        out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
}

/* v' = M (v, 0). */
static inline void mat4_transform_vector(const double m[16], const double v[3], double out[3])
{
    for (int r = 0; r < 3; r++)
        out[r] = m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2];
}

/* Full 4x4 transform with homogeneous divide; returns 0 when w is 0 or
 * the result is not finite. */
static inline int mat4_project(const double m[16], const double p[3], double out[3])
{
    double w = m[3] * p[0] + m[7] * p[1] + m[11] * p[2] + m[15];
    if (w == 0.0)
        return 0;
    for (int r = 0; r < 3; r++)
        out[r] = (m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]) / w;
    return isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2]);
}

/*
 * General inverse by cofactors (the formulation of Mesa's
 * invert_matrix_general).  Returns 0 and leaves out untouched when the
 * matrix is singular or the inverse is not finite; the test is exact
 * (det == 0) plus finiteness, so near-singular but invertible matrices
 * are accepted and their (large) inverse is used.
 */
int mat4_invert(double out[16], const double m[16]);

/* Inverse of the upper 3x3, transposed (the normal matrix), as a 4x4 with
 * no translation.  Returns 0 when singular. */
int mat4_normal_matrix(double out[16], const double m[16]);

#endif
