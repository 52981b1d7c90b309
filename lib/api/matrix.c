/* SPDX-License-Identifier: Apache-2.0 */
/*
 * matrix.c - the matrix stacks: rtMatrixMode, load/mult, translate,
 * rotate, scale, rtFrustum, rtOrtho, push/pop.
 *
 * Storage is column-major double, p' = M p (as Mesa's matrix.c).  Each
 * operation builds its matrix, multiplies into a temporary, checks the
 * result is finite, and only then stores it: a failing call changes
 * nothing.  A call that would not change the matrix (e.g. rtRotate about
 * a zero axis) stores nothing.
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "base/mat4.h"

static struct matrix_stack *current_stack(struct rt_context *ctx)
{
    return ctx->matrix_mode == RT_PROJECTION ? &ctx->projection : &ctx->modelview;
}

double *rt_current_matrix(struct rt_context *ctx)
{
    struct matrix_stack *s = current_stack(ctx);
    return s->m[s->depth - 1];
}

/* Replaces the current matrix by m if m is finite. */
static void store(struct rt_context *ctx, const char *caller, const double m[16])
{
    if (!mat4_is_finite(m)) {
        rt_error(ctx, RT_INVALID_VALUE, "%s: the resulting matrix is not finite", caller);
        return;
    }
    memcpy(rt_current_matrix(ctx), m, 16 * sizeof(double));
}

/* current = current * m, checked; recorded inside a display list. */
static void multiply(struct rt_context *ctx, const char *caller, const double m[16])
{
    if (rt_list_matrix(ctx, caller, SCENE_OP_MULT, 0, m))
        return;
    double r[16];
    mat4_mul(r, rt_current_matrix(ctx), m);
    store(ctx, caller, r);
}

void rtMatrixMode(RTenum mode)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtMatrixMode"))
        return;
    if (mode != RT_MODELVIEW && mode != RT_PROJECTION) {
        rt_error(ctx, RT_INVALID_ENUM, "rtMatrixMode(mode=0x%x)", mode);
        return;
    }
    if (rt_list_matrix(ctx, "rtMatrixMode", SCENE_OP_MATRIX_MODE, mode, NULL))
        return;
    ctx->matrix_mode = mode;
}

void rtLoadIdentity(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtLoadIdentity"))
        return;
    double m[16];
    mat4_identity(m);
    if (rt_list_matrix(ctx, "rtLoadIdentity", SCENE_OP_LOAD, 0, m))
        return;
    mat4_identity(rt_current_matrix(ctx));
}

static void load_or_mult(const char *caller, const float *mf, const double *md, int mult)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    if (!mf && !md) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(m=NULL)", caller);
        return;
    }
    double m[16];
    for (int i = 0; i < 16; i++)
        m[i] = mf ? (double)mf[i] : md[i];
    if (!rt_check_finite_d(ctx, caller, m, 16))
        return;
    if (mult)
        multiply(ctx, caller, m);
    else if (!rt_list_matrix(ctx, caller, SCENE_OP_LOAD, 0, m))
        store(ctx, caller, m);
}

void rtLoadMatrixf(const RTfloat *m)
{
    load_or_mult("rtLoadMatrixf", m, NULL, 0);
}

void rtLoadMatrixd(const RTdouble *m)
{
    load_or_mult("rtLoadMatrixd", NULL, m, 0);
}

void rtMultMatrixf(const RTfloat *m)
{
    load_or_mult("rtMultMatrixf", m, NULL, 1);
}

void rtMultMatrixd(const RTdouble *m)
{
    load_or_mult("rtMultMatrixd", NULL, m, 1);
}

enum simple_transform { TRANSLATE, SCALE };

/* Multiplies the current matrix by a translation or a scale. */
static void simple_transform(const char *caller, enum simple_transform kind, double x, double y,
                             double z)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    double v[3] = {x, y, z};
    if (!rt_check_finite_d(ctx, caller, v, 3))
        return;
    double m[16];
    mat4_identity(m);
    for (int k = 0; k < 3; k++) {
        if (kind == TRANSLATE)
            m[12 + k] = v[k];
        else
            m[5 * k] = v[k];
    }
    multiply(ctx, caller, m);
}

void rtTranslatef(RTfloat x, RTfloat y, RTfloat z)
{
    simple_transform("rtTranslatef", TRANSLATE, x, y, z);
}

void rtTranslated(RTdouble x, RTdouble y, RTdouble z)
{
    simple_transform("rtTranslated", TRANSLATE, x, y, z);
}

void rtScalef(RTfloat x, RTfloat y, RTfloat z)
{
    simple_transform("rtScalef", SCALE, x, y, z);
}

void rtScaled(RTdouble x, RTdouble y, RTdouble z)
{
    simple_transform("rtScaled", SCALE, x, y, z);
}

/* The rotation matrix of the glRotate man page, angle in degrees. */
static void rotate(const char *caller, double angle, double x, double y, double z)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    double v[4] = {angle, x, y, z};
    if (!rt_check_finite_d(ctx, caller, v, 4))
        return;
    double len = sqrt(x * x + y * y + z * z);
    if (len == 0.0 || !isfinite(len))
        return; /* zero axis: no rotation (Mesa's _math_matrix_rotate) */
    x /= len;
    y /= len;
    z /= len;
    /* Reduce the angle first so that multiples of 90 degrees give exact
     * zeros and ones, as hand-computed matrices expect. */
    double a = fmod(angle, 360.0);
    double s, c;
    if (a == 0.0) {
        s = 0.0;
        c = 1.0;
    } else if (fabs(a) == 90.0 || fabs(a) == 270.0) {
        s = (a == 90.0 || a == -270.0) ? 1.0 : -1.0;
        c = 0.0;
    } else if (fabs(a) == 180.0) {
        s = 0.0;
        c = -1.0;
    } else {
        double rad = a * (3.14159265358979323846 / 180.0);
        s = sin(rad);
        c = cos(rad);
    }
    double t = 1.0 - c;
    double m[16] = {x * x * t + c,     y * x * t + z * s, z * x * t - y * s, 0.0,
                    x * y * t - z * s, y * y * t + c,     z * y * t + x * s, 0.0,
                    x * z * t + y * s, y * z * t - x * s, z * z * t + c,     0.0,
                    0.0,               0.0,               0.0,               1.0};
    multiply(ctx, caller, m);
}

void rtRotatef(RTfloat angle, RTfloat x, RTfloat y, RTfloat z)
{
    rotate("rtRotatef", angle, x, y, z);
}

void rtRotated(RTdouble angle, RTdouble x, RTdouble y, RTdouble z)
{
    rotate("rtRotated", angle, x, y, z);
}

void rtFrustum(RTdouble l, RTdouble r, RTdouble b, RTdouble t, RTdouble n, RTdouble f)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtFrustum"))
        return;
    double v[6] = {l, r, b, t, n, f};
    if (!rt_check_finite_d(ctx, "rtFrustum", v, 6))
        return;
    if (n <= 0.0 || f <= 0.0 || l == r || b == t || n == f) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "rtFrustum(left=%g, right=%g, bottom=%g, top=%g, near=%g, far=%g)", l, r, b, t,
                 n, f);
        return;
    }
    double m[16] = {0};
    m[0] = 2.0 * n / (r - l);
    m[5] = 2.0 * n / (t - b);
    m[8] = (r + l) / (r - l);
    m[9] = (t + b) / (t - b);
    m[10] = -(f + n) / (f - n);
    m[11] = -1.0;
    m[14] = -2.0 * f * n / (f - n);
    multiply(ctx, "rtFrustum", m);
}

void rtOrtho(RTdouble l, RTdouble r, RTdouble b, RTdouble t, RTdouble n, RTdouble f)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtOrtho"))
        return;
    double v[6] = {l, r, b, t, n, f};
    if (!rt_check_finite_d(ctx, "rtOrtho", v, 6))
        return;
    if (l == r || b == t || n == f) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "rtOrtho(left=%g, right=%g, bottom=%g, top=%g, near=%g, far=%g)", l, r, b, t, n,
                 f);
        return;
    }
    double m[16] = {0};
    m[0] = 2.0 / (r - l);
    m[5] = 2.0 / (t - b);
    m[10] = -2.0 / (f - n);
    m[12] = -(r + l) / (r - l);
    m[13] = -(t + b) / (t - b);
    m[14] = -(f + n) / (f - n);
    m[15] = 1.0;
    multiply(ctx, "rtOrtho", m);
}

static void push(struct rt_context *ctx, const char *caller)
{
    struct matrix_stack *s = current_stack(ctx);
    if (s->depth >= s->max_depth) {
        rt_error(ctx, RT_STACK_OVERFLOW, "%s: %s stack overflow (depth %d)", caller,
                 ctx->matrix_mode == RT_PROJECTION ? "projection" : "modelview", s->depth);
        return;
    }
    memcpy(s->m[s->depth], s->m[s->depth - 1], 16 * sizeof(double));
    s->depth++;
}

static void pop(struct rt_context *ctx, const char *caller)
{
    struct matrix_stack *s = current_stack(ctx);
    if (s->depth <= 1) {
        rt_error(ctx, RT_STACK_UNDERFLOW, "%s: %s stack underflow", caller,
                 ctx->matrix_mode == RT_PROJECTION ? "projection" : "modelview");
        return;
    }
    s->depth--;
}

void rtPushMatrix(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtPushMatrix"))
        return;
    if (!rt_list_matrix(ctx, "rtPushMatrix", SCENE_OP_PUSH, 0, NULL))
        push(ctx, "rtPushMatrix");
}

void rtPopMatrix(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtPopMatrix"))
        return;
    if (!rt_list_matrix(ctx, "rtPopMatrix", SCENE_OP_POP, 0, NULL))
        pop(ctx, "rtPopMatrix");
}

void rt_matrix_apply(struct rt_context *ctx, const char *caller, enum scene_list_op_kind kind,
                     RTenum mode, const double m[16])
{
    double r[16];
    switch (kind) {
    case SCENE_OP_MATRIX_MODE:
        ctx->matrix_mode = mode;
        break;
    case SCENE_OP_LOAD:
        store(ctx, caller, m);
        break;
    case SCENE_OP_MULT:
        mat4_mul(r, rt_current_matrix(ctx), m);
        store(ctx, caller, r);
        break;
    case SCENE_OP_PUSH:
        push(ctx, caller);
        break;
    case SCENE_OP_POP:
        pop(ctx, caller);
        break;
    default:
        break;
    }
}
