/* SPDX-License-Identifier: Apache-2.0 */
/*
 * project.c - rtuOrtho2D, rtuPickMatrix, rtuProject, rtuUnProject: the
 * projection helpers of GLU 1.3.
 *
 * Matrices are column-major (rt.h): element (row r, column c) is m[c*4 + r].
 *
 * rtuProject follows the arithmetic of the GLU reference pages in the order
 * Mesa's libGLU evaluates it (matrix times column vector, each row summed
 * left to right, then the divide by w, then the maps to [0, 1] and to the
 * viewport), so on hardware without fused multiply-add (the library is
 * built with -ffp-contract=off) its results are the same doubles as
 * gluProject's.  rtuUnProject inverts proj * model with its own cofactor
 * expansion, so it agrees with gluUnProject to rounding, not bit for bit
 * (conformance/gl_oracle/project_oracle.c states the tolerance).
 *
 * rtuOrtho2D and rtuPickMatrix multiply the current matrix with ONE core
 * call each (rtOrtho; rtMultMatrixd), so the core's checks apply and a
 * failing call changes nothing.  GLU's gluPickMatrix returns silently on
 * a non-positive region; rtu records RT_INVALID_VALUE (report.h).
 */
#include "report.h"

#include <rt/rtu.h>

#include <math.h>
#include <stddef.h>

void rtuOrtho2D(RTdouble left, RTdouble right, RTdouble bottom, RTdouble top)
{
    rtOrtho(left, right, bottom, top, -1.0, 1.0);
}

void rtuPickMatrix(RTdouble x, RTdouble y, RTdouble deltaX, RTdouble deltaY,
                   const RTint viewport[4])
{
    RTdouble m[16] = {0};
    if (!viewport || !(deltaX > 0.0) || !(deltaY > 0.0) || viewport[2] <= 0 || viewport[3] <= 0) {
        rtu_record_error(RT_INVALID_VALUE, "rtuPickMatrix",
                         "viewport must be non-NULL with a positive size, deltas > 0");
        return;
    }
    /* gluPickMatrix: translate the region's centre to the centre of the
     * viewport, then scale the region to fill it (GLU issues glTranslatef
     * and glScalef; one matrix here, so the call cannot half-succeed).
     * A non-finite element is refused by the core. */
    m[0] = viewport[2] / deltaX;
    m[5] = viewport[3] / deltaY;
    m[10] = 1.0;
    m[12] = (viewport[2] - 2 * (x - viewport[0])) / deltaX;
    m[13] = (viewport[3] - 2 * (y - viewport[1])) / deltaY;
    m[15] = 1.0;
    rtMultMatrixd(m);
}

/* out = m * in for a column-major m, each row summed left to right. */
static void mult_matrix_vec(const RTdouble m[16], const RTdouble in[4], RTdouble out[4])
{
    int r;
    for (r = 0; r < 4; r++)
        out[r] = in[0] * m[0 * 4 + r] + in[1] * m[1 * 4 + r] + in[2] * m[2 * 4 + r] +
                 in[3] * m[3 * 4 + r];
}

/* out = a * b (column-major); out may not alias a or b. */
static void mult_matrices(const RTdouble a[16], const RTdouble b[16], RTdouble out[16])
{
    int r, c;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++)
            out[c * 4 + r] = a[0 * 4 + r] * b[c * 4 + 0] + a[1 * 4 + r] * b[c * 4 + 1] +
                             a[2 * 4 + r] * b[c * 4 + 2] + a[3 * 4 + r] * b[c * 4 + 3];
}

/*
 * inv = m^-1 by cofactors (the adjugate over the determinant), with the
 * 2x2 minors of the lower two rows and of the upper two rows shared
 * (Laplace expansion along row pairs).  Returns 0 when the determinant is
 * 0 or not finite, as gluUnProject fails when its inverse does.
 */
static int invert(const RTdouble m[16], RTdouble inv[16])
{
    /* a[r][c] = element (r, c). */
#define A(r, c) m[(c) * 4 + (r)]
    const double s0 = A(0, 0) * A(1, 1) - A(1, 0) * A(0, 1);
    const double s1 = A(0, 0) * A(1, 2) - A(1, 0) * A(0, 2);
    const double s2 = A(0, 0) * A(1, 3) - A(1, 0) * A(0, 3);
    const double s3 = A(0, 1) * A(1, 2) - A(1, 1) * A(0, 2);
    const double s4 = A(0, 1) * A(1, 3) - A(1, 1) * A(0, 3);
    const double s5 = A(0, 2) * A(1, 3) - A(1, 2) * A(0, 3);
    const double c5 = A(2, 2) * A(3, 3) - A(3, 2) * A(2, 3);
    const double c4 = A(2, 1) * A(3, 3) - A(3, 1) * A(2, 3);
    const double c3 = A(2, 1) * A(3, 2) - A(3, 1) * A(2, 2);
    const double c2 = A(2, 0) * A(3, 3) - A(3, 0) * A(2, 3);
    const double c1 = A(2, 0) * A(3, 2) - A(3, 0) * A(2, 2);
    const double c0 = A(2, 0) * A(3, 1) - A(3, 0) * A(2, 1);
    const double det = s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
    double r;
    if (det == 0.0 || !isfinite(det))
        return 0;
    r = 1.0 / det;
#define INV(row, col) inv[(col) * 4 + (row)]
    INV(0, 0) = (A(1, 1) * c5 - A(1, 2) * c4 + A(1, 3) * c3) * r;
    INV(0, 1) = (-A(0, 1) * c5 + A(0, 2) * c4 - A(0, 3) * c3) * r;
    INV(0, 2) = (A(3, 1) * s5 - A(3, 2) * s4 + A(3, 3) * s3) * r;
    INV(0, 3) = (-A(2, 1) * s5 + A(2, 2) * s4 - A(2, 3) * s3) * r;
    INV(1, 0) = (-A(1, 0) * c5 + A(1, 2) * c2 - A(1, 3) * c1) * r;
    INV(1, 1) = (A(0, 0) * c5 - A(0, 2) * c2 + A(0, 3) * c1) * r;
    INV(1, 2) = (-A(3, 0) * s5 + A(3, 2) * s2 - A(3, 3) * s1) * r;
    INV(1, 3) = (A(2, 0) * s5 - A(2, 2) * s2 + A(2, 3) * s1) * r;
    INV(2, 0) = (A(1, 0) * c4 - A(1, 1) * c2 + A(1, 3) * c0) * r;
    INV(2, 1) = (-A(0, 0) * c4 + A(0, 1) * c2 - A(0, 3) * c0) * r;
    INV(2, 2) = (A(3, 0) * s4 - A(3, 1) * s2 + A(3, 3) * s0) * r;
    INV(2, 3) = (-A(2, 0) * s4 + A(2, 1) * s2 - A(2, 3) * s0) * r;
    INV(3, 0) = (-A(1, 0) * c3 + A(1, 1) * c1 - A(1, 2) * c0) * r;
    INV(3, 1) = (A(0, 0) * c3 - A(0, 1) * c1 + A(0, 2) * c0) * r;
    INV(3, 2) = (-A(3, 0) * s3 + A(3, 1) * s1 - A(3, 2) * s0) * r;
    INV(3, 3) = (A(2, 0) * s3 - A(2, 1) * s1 + A(2, 2) * s0) * r;
#undef INV
#undef A
    return 1;
}

RTboolean rtuProject(RTdouble objX, RTdouble objY, RTdouble objZ, const RTdouble model[16],
                     const RTdouble proj[16], const RTint viewport[4], RTdouble *winX,
                     RTdouble *winY, RTdouble *winZ)
{
    RTdouble in[4] = {objX, objY, objZ, 1.0};
    RTdouble eye[4];
    RTdouble clip[4];
    if (!model || !proj || !viewport || !winX || !winY || !winZ)
        return RT_FALSE;
    mult_matrix_vec(model, in, eye);
    mult_matrix_vec(proj, eye, clip);
    if (clip[3] == 0.0)
        return RT_FALSE;
    clip[0] /= clip[3];
    clip[1] /= clip[3];
    clip[2] /= clip[3];
    /* [-1, 1] to [0, 1], then x and y to the viewport. */
    clip[0] = clip[0] * 0.5 + 0.5;
    clip[1] = clip[1] * 0.5 + 0.5;
    clip[2] = clip[2] * 0.5 + 0.5;
    *winX = clip[0] * viewport[2] + viewport[0];
    *winY = clip[1] * viewport[3] + viewport[1];
    *winZ = clip[2];
    return RT_TRUE;
}

RTboolean rtuUnProject(RTdouble winX, RTdouble winY, RTdouble winZ, const RTdouble model[16],
                       const RTdouble proj[16], const RTint viewport[4], RTdouble *objX,
                       RTdouble *objY, RTdouble *objZ)
{
    RTdouble pm[16];
    RTdouble inverse[16];
    RTdouble in[4];
    RTdouble out[4];
    if (!model || !proj || !viewport || !objX || !objY || !objZ)
        return RT_FALSE;
    mult_matrices(proj, model, pm);
    if (!invert(pm, inverse))
        return RT_FALSE;
    /* The viewport to [0, 1], then to [-1, 1]. */
    in[0] = (winX - viewport[0]) / viewport[2];
    in[1] = (winY - viewport[1]) / viewport[3];
    in[2] = winZ;
    in[0] = in[0] * 2 - 1;
    in[1] = in[1] * 2 - 1;
    in[2] = in[2] * 2 - 1;
    in[3] = 1.0;
    mult_matrix_vec(inverse, in, out);
    if (out[3] == 0.0)
        return RT_FALSE;
    *objX = out[0] / out[3];
    *objY = out[1] / out[3];
    *objZ = out[2] / out[3];
    return RT_TRUE;
}
