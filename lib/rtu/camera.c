/* SPDX-License-Identifier: Apache-2.0 */
/*
 * camera.c - rtuPerspective and rtuLookAt, the camera helpers of GLU.
 *
 * Each builds the matrix of its GLU namesake (gluPerspective, gluLookAt as
 * in Mesa's libGLU, src/libutil/project.c) in double precision and
 * multiplies it onto the current matrix with ONE rtMultMatrixd call.  So
 * the matrix mode, the checks for "inside rtBegin" and "no current
 * context", and the overflow check of the product are the core's, and a
 * failing call changes nothing.  (gluLookAt issues glMultMatrixf and then
 * glTranslated; we fold the translation into the one matrix so the call
 * cannot half-succeed.)
 *
 * Matrices are column-major as in rt.h: element (row r, column c) is
 * m[c*4 + r].
 *
 * Invalid arguments are reported against the rtu function itself, through
 * rtRecordError (rtu uses only rt.h): RT_INVALID_VALUE with a message that
 * starts with "rtuPerspective" or "rtuLookAt", and nothing changes.  Inside
 * rtBegin, rtRecordError records RT_INVALID_OPERATION instead, the order of
 * checks of every core entry point.  A matrix whose elements overflow is
 * refused here too, before the core sees it.  GLU's own versions return
 * silently on such input.
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include <math.h>
#include <stdio.h>

/*
 * Smallest sine of the angle between the view direction and the up vector
 * that rtuLookAt accepts.  The side vector is their cross product; below
 * this its direction is dominated by rounding (double epsilon is 1.1e-16,
 * so at 1e-12 rounding is still under 1e-4 of its length).
 */
#define RTU_LOOKAT_MIN_SINE 1e-12

/* Records RT_INVALID_VALUE against `function` with a formatted reason. */
static void invalid_value(const char *function, const char *what, const RTdouble *args, int n)
{
    char message[200];
    int used = snprintf(message, sizeof message, "%s (", what);
    for (int i = 0; i < n && used > 0 && (size_t)used < sizeof message; i++)
        used += snprintf(message + used, sizeof message - (size_t)used, "%s%g", i ? ", " : "",
                         args[i]);
    if (used > 0 && (size_t)used < sizeof message)
        snprintf(message + used, sizeof message - (size_t)used, ")");
    rtRecordError(RT_INVALID_VALUE, function, message);
}

/* RT_TRUE when all 16 elements are finite (an overflowing product is not). */
static int finite_matrix(const RTdouble m[16])
{
    for (int i = 0; i < 16; i++)
        if (!isfinite(m[i]))
            return 0;
    return 1;
}

/*
 * Scales v to unit length, safely for any finite input (it divides by the
 * largest component first, so the squares cannot overflow).  Returns 0 and
 * leaves v unspecified when v is zero or not finite.
 */
static int normalize3(RTdouble v[3])
{
    RTdouble largest = 0.0;
    RTdouble length;
    int i;
    for (i = 0; i < 3; i++) {
        if (!isfinite(v[i]))
            return 0;
        if (fabs(v[i]) > largest)
            largest = fabs(v[i]);
    }
    if (largest == 0.0)
        return 0;
    for (i = 0; i < 3; i++)
        v[i] /= largest;
    length = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (i = 0; i < 3; i++)
        v[i] /= length;
    return 1;
}

static void cross3(const RTdouble a[3], const RTdouble b[3], RTdouble out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static RTdouble dot3(const RTdouble a[3], const RTdouble b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void rtuPerspective(RTdouble fovy, RTdouble aspect, RTdouble zNear, RTdouble zFar)
{
    RTdouble m[16] = {0};
    RTdouble half_angle;
    RTdouble cotangent;
    RTdouble depth;
    /* Written so that NaN fails every test. */
    if (!(fovy > 0.0 && fovy < 180.0) || !(aspect > 0.0) || !(zNear > 0.0) ||
        !(zFar > zNear) || !isfinite(aspect) || !isfinite(zFar)) {
        const RTdouble args[4] = {fovy, aspect, zNear, zFar};
        invalid_value("rtuPerspective",
                      "needs 0 < fovy < 180, aspect > 0, 0 < zNear < zFar, all finite", args, 4);
        return;
    }
    half_angle = fovy * 0.5 * (3.14159265358979323846 / 180.0);
    cotangent = cos(half_angle) / sin(half_angle);
    depth = zFar - zNear;
    m[0] = cotangent / aspect;
    m[5] = cotangent;
    m[10] = -(zFar + zNear) / depth;
    m[11] = -1.0;
    m[14] = -2.0 * zNear * zFar / depth;
    if (!finite_matrix(m)) {
        const RTdouble args[4] = {fovy, aspect, zNear, zFar};
        invalid_value("rtuPerspective", "the projection matrix overflows", args, 4);
        return;
    }
    rtMultMatrixd(m);
}

void rtuLookAt(RTdouble eyeX, RTdouble eyeY, RTdouble eyeZ, RTdouble centerX,
               RTdouble centerY, RTdouble centerZ, RTdouble upX, RTdouble upY, RTdouble upZ)
{
    RTdouble eye[3];
    RTdouble forward[3];
    RTdouble up[3];
    RTdouble side[3];
    RTdouble true_up[3];
    RTdouble m[16];
    eye[0] = eyeX;
    eye[1] = eyeY;
    eye[2] = eyeZ;
    forward[0] = centerX - eyeX;
    forward[1] = centerY - eyeY;
    forward[2] = centerZ - eyeZ;
    up[0] = upX;
    up[1] = upY;
    up[2] = upZ;
    if (!isfinite(eyeX) || !isfinite(eyeY) || !isfinite(eyeZ) || !normalize3(forward) ||
        !normalize3(up)) {
        const RTdouble args[9] = {eyeX, eyeY, eyeZ, centerX, centerY, centerZ, upX, upY, upZ};
        invalid_value("rtuLookAt", "needs finite arguments, eye != center and up != 0", args, 9);
        return;
    }
    cross3(forward, up, side);
    if (!(sqrt(dot3(side, side)) >= RTU_LOOKAT_MIN_SINE) || !normalize3(side)) {
        const RTdouble args[9] = {eyeX, eyeY, eyeZ, centerX, centerY, centerZ, upX, upY, upZ};
        invalid_value("rtuLookAt", "up is parallel to the view direction", args, 9);
        return;
    }
    cross3(side, forward, true_up);

    /* Rows: side, up, -forward; then the translation by -eye folded in. */
    m[0] = side[0];
    m[4] = side[1];
    m[8] = side[2];
    m[1] = true_up[0];
    m[5] = true_up[1];
    m[9] = true_up[2];
    m[2] = -forward[0];
    m[6] = -forward[1];
    m[10] = -forward[2];
    m[3] = 0.0;
    m[7] = 0.0;
    m[11] = 0.0;
    m[12] = -dot3(side, eye);
    m[13] = -dot3(true_up, eye);
    m[14] = dot3(forward, eye);
    m[15] = 1.0;
    if (!finite_matrix(m)) {
        const RTdouble args[9] = {eyeX, eyeY, eyeZ, centerX, centerY, centerZ, upX, upY, upZ};
        invalid_value("rtuLookAt", "the viewing matrix overflows", args, 9);
        return;
    }
    rtMultMatrixd(m);
}
