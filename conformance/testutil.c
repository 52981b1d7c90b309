/* SPDX-License-Identifier: Apache-2.0 */
/*
 * testutil.c - helpers shared by the API conformance tests (see testutil.h).
 *
 * The checks themselves are check.c's.  Single-threaded by design: the
 * captured error copy is a plain global.  Tests that start threads make their checks on
 * the main thread.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *tu_error_name(RTenum code)
{
    static char buffer[32];
    switch (code) {
    case RT_NO_ERROR:
        return "RT_NO_ERROR";
    case RT_INVALID_ENUM:
        return "RT_INVALID_ENUM";
    case RT_INVALID_VALUE:
        return "RT_INVALID_VALUE";
    case RT_INVALID_OPERATION:
        return "RT_INVALID_OPERATION";
    case RT_STACK_OVERFLOW:
        return "RT_STACK_OVERFLOW";
    case RT_STACK_UNDERFLOW:
        return "RT_STACK_UNDERFLOW";
    case RT_OUT_OF_MEMORY:
        return "RT_OUT_OF_MEMORY";
    default:
        snprintf(buffer, sizeof buffer, "0x%04x", code);
        return buffer;
    }
}

int tu_expect_error(RTenum code, const char *file, int line, const char *expr)
{
    RTenum first = rtGetError();
    RTenum second = rtGetError();
    int ok = 1;
    if (first != code) {
        tu_report_failure(file, line);
        fprintf(stderr, "rtGetError() == %s, expected %s", tu_error_name(first), expr);
        if (tu_captured_count() > 0)
            fprintf(stderr, " (last callback message: \"%s\")", tu_captured_message());
        fprintf(stderr, "\n");
        ok = 0;
    }
    if (second != RT_NO_ERROR) {
        tu_report_failure(file, line);
        fprintf(stderr, "second rtGetError() == %s, expected RT_NO_ERROR (slot not cleared)\n",
                tu_error_name(second));
        ok = 0;
    }
    if (ok)
        tu_report_pass();
    return ok;
}

/* ---- contexts -------------------------------------------------------------- */

RTcontext tu_make_context(const char *config)
{
    /* RT_TEST_ISA=scalar|sse4|avx2|avx512|auto appends isa= to every
     * configuration: the CI hook that runs the query and stability tests
     * under each traversal ISA table (conformance/CMakeLists.txt).  A
     * test that names its own table (secondary_rays compares isa=scalar
     * with the best one) keeps it: a key given twice is an error. */
    char with_isa[512];
    const char *isa = getenv("RT_TEST_ISA");
    if (isa && *isa && !(config && strstr(config, "isa="))) {
        snprintf(with_isa, sizeof(with_isa), "%s isa=%s", config ? config : "", isa);
        config = with_isa;
    }
    RTcontext ctx = rtCreateContext(config);
    if (!ctx) {
        fprintf(stderr, "fatal: rtCreateContext(\"%s\") returned NULL\n", config ? config : "(null)");
        exit(1);
    }
    if (!rtMakeCurrent(ctx)) {
        fprintf(stderr, "fatal: rtMakeCurrent failed for a new context\n");
        exit(1);
    }
    return ctx;
}

void tu_destroy_context(RTcontext ctx)
{
    if (rtGetCurrentContext() == ctx)
        rtMakeCurrent(NULL);
    rtDestroyContext(ctx);
}

int tu_config_available(const char *config)
{
    RTcontext ctx = rtCreateContext(config);
    if (!ctx)
        return 0;
    rtDestroyContext(ctx);
    return 1;
}

/* ---- error capture -------------------------------------------------------- */

static int captured_count;
static RTenum captured_code;
static char captured_message[512];

static void capture_callback(RTenum error, const char *message, void *user)
{
    (void)user;
    captured_count++;
    captured_code = error;
    if (message) {
        strncpy(captured_message, message, sizeof captured_message - 1);
        captured_message[sizeof captured_message - 1] = '\0';
    } else {
        strcpy(captured_message, "(null message)");
    }
}

void tu_capture_errors(void)
{
    tu_reset_captured();
    rtErrorCallback(capture_callback, NULL);
}

void tu_reset_captured(void)
{
    captured_count = 0;
    captured_code = RT_NO_ERROR;
    captured_message[0] = '\0';
}

int tu_captured_count(void)
{
    return captured_count;
}

RTenum tu_captured_code(void)
{
    return captured_code;
}

const char *tu_captured_message(void)
{
    return captured_message;
}

int tu_message_names(const char *message, const char *entry)
{
    size_t n = strlen(entry);
    char next;
    if (!message || strncmp(message, entry, n) != 0)
        return 0;
    next = message[n];
    return !((next >= 'a' && next <= 'z') || (next >= 'A' && next <= 'Z') ||
             (next >= '0' && next <= '9') || next == '_');
}

/* ---- recording modes -------------------------------------------------------- */

void tu_begin_scratch(RTenum mode)
{
    rtNewObject(TU_SCRATCH_OBJECT);
    rtBegin(mode);
    tu_check(rtGetError() == RT_NO_ERROR, __FILE__, __LINE__,
             "tu_begin_scratch: rtNewObject + rtBegin without error");
}

void tu_end_scratch(void)
{
    RTuint name = TU_SCRATCH_OBJECT;
    rtEnd();
    rtEndObject();
    rtDeleteObjects(1, &name);
    tu_check(rtGetError() == RT_NO_ERROR, __FILE__, __LINE__,
             "tu_end_scratch: rtEnd + rtEndObject without error");
}

/* ---- geometry ----------------------------------------------------------------- */

static int no_error(const char *what)
{
    RTenum e = rtGetError();
    if (e == RT_NO_ERROR)
        return 1;
    tu_report_failure(__FILE__, __LINE__);
    fprintf(stderr, "%s recorded %s\n", what, tu_error_name(e));
    return 0;
}

int tu_define_quad(RTuint name, float x_lo, float y_lo, float x_hi, float y_hi, float z)
{
    rtNewObject(name);
    rtBegin(RT_QUADS);
    rtVertex3f(x_lo, y_lo, z);
    rtVertex3f(x_hi, y_lo, z);
    rtVertex3f(x_hi, y_hi, z);
    rtVertex3f(x_lo, y_hi, z);
    rtEnd();
    rtEndObject();
    return no_error("tu_define_quad");
}

int tu_define_triangle(RTuint name, const float a[3], const float b[3], const float c[3])
{
    rtNewObject(name);
    rtBegin(RT_TRIANGLES);
    rtVertex3fv(a);
    rtVertex3fv(b);
    rtVertex3fv(c);
    rtEnd();
    rtEndObject();
    return no_error("tu_define_triangle");
}

int tu_define_box(RTuint name, const float lo[3], const float hi[3])
{
    /* Corner k has x from bit 0, y from bit 1, z from bit 2; faces listed
     * counter-clockwise seen from outside. */
    static const int faces[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                    {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    int f, k;
    rtNewObject(name);
    rtBegin(RT_QUADS);
    for (f = 0; f < 6; f++) {
        for (k = 0; k < 4; k++) {
            int c = faces[f][k];
            rtVertex3f((c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2]);
        }
    }
    rtEnd();
    rtEndObject();
    return no_error("tu_define_box");
}

int tu_define_grid(RTuint name, int nx, int ny, float x_lo, float y_lo, float x_hi,
                   float y_hi, float z)
{
    int i, j;
    rtNewObject(name);
    rtBegin(RT_QUADS);
    for (j = 0; j < ny; j++) {
        for (i = 0; i < nx; i++) {
            float xa = x_lo + (x_hi - x_lo) * (float)i / (float)nx;
            float xb = x_lo + (x_hi - x_lo) * (float)(i + 1) / (float)nx;
            float ya = y_lo + (y_hi - y_lo) * (float)j / (float)ny;
            float yb = y_lo + (y_hi - y_lo) * (float)(j + 1) / (float)ny;
            rtVertex3f(xa, ya, z);
            rtVertex3f(xb, ya, z);
            rtVertex3f(xb, yb, z);
            rtVertex3f(xa, yb, z);
        }
    }
    rtEnd();
    rtEndObject();
    return no_error("tu_define_grid");
}

int tu_object_triangles(RTuint name)
{
    RTint n = -12345;
    rtGetObjectiv(name, RT_OBJECT_TRIANGLES, &n);
    return n == -12345 ? -1 : n;
}

/* ---- scenes and rays ---------------------------------------------------------- */

int tu_scene1(RTuint name)
{
    rtBeginFrame();
    rtInstantiateObject(name);
    rtFinish();
    return no_error("tu_scene1");
}

RTray tu_ray(float ox, float oy, float oz, float dx, float dy, float dz)
{
    RTray r;
    r.org[0] = ox;
    r.org[1] = oy;
    r.org[2] = oz;
    r.dir[0] = dx;
    r.dir[1] = dy;
    r.dir[2] = dz;
    r.tmin = 0.0f;
    r.tmax = tu_inf();
    return r;
}

RThit tu_trace(float ox, float oy, float oz, float dx, float dy, float dz)
{
    RTray r = tu_ray(ox, oy, oz, dx, dy, dz);
    RThit h;
    h.t = -1.0f;
    h.u = h.v = -1.0f;
    h.instance = h.object = h.primitive = 0xDEADBEEFu;
    rtTraceRays(1, &r, &h);
    return h;
}

RThit tu_trace_down(float x, float y)
{
    return tu_trace(x, y, 10.0f, 0.0f, 0.0f, -1.0f);
}

int tu_occluded(float ox, float oy, float oz, float dx, float dy, float dz)
{
    RTray r = tu_ray(ox, oy, oz, dx, dy, dz);
    RTboolean occluded = 77;
    rtOccludedRays(1, &r, &occluded);
    return occluded;
}

int tu_check_triangle(const char *file, int line, const float a[3], const float b[3],
                      const float c[3], RTuint prim, RTuint object, RTuint instance)
{
    const float u = TU_PIN_U, v = TU_PIN_V, w = 1.0f - TU_PIN_U - TU_PIN_V;
    float e1[3], e2[3], n[3], p[3], len;
    RThit h;
    RTenum err;
    int k, ok = 1;
    for (k = 0; k < 3; k++) {
        e1[k] = b[k] - a[k];
        e2[k] = c[k] - a[k];
        p[k] = w * a[k] + u * b[k] + v * c[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0.0f)) {
        tu_report_failure(file, line);
        fprintf(stderr, "tu_check_triangle: expected triangle is degenerate (test bug)\n");
        return 0;
    }
    for (k = 0; k < 3; k++)
        n[k] /= len;
    h = tu_trace(p[0] + 2.0f * n[0], p[1] + 2.0f * n[1], p[2] + 2.0f * n[2], -n[0], -n[1],
                 -n[2]);
    err = rtGetError();
    if (err != RT_NO_ERROR) {
        tu_report_failure(file, line);
        fprintf(stderr, "rtTraceRays recorded %s\n", tu_error_name(err));
        return 0;
    }
    if (h.primitive != prim || h.object != object || h.instance != instance ||
        !(fabsf(h.t - 2.0f) <= 1e-4f) || !(fabsf(h.u - u) <= 1e-4f) ||
        !(fabsf(h.v - v) <= 1e-4f)) {
        tu_report_failure(file, line);
        fprintf(stderr,
                "triangle (%g,%g,%g)(%g,%g,%g)(%g,%g,%g): hit prim %u object %u instance %u "
                "t %g u %g v %g; expected prim %u object %u instance %u t 2 u %g v %g\n",
                a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], h.primitive, h.object,
                h.instance, h.t, h.u, h.v, prim, object, instance, u, v);
        ok = 0;
    }
    if (ok)
        tu_report_pass();
    return ok;
}

/* ---- matrices ------------------------------------------------------------------ */

void tu_get_matrix(RTenum pname, float m[16])
{
    int k;
    for (k = 0; k < 16; k++)
        m[k] = -999.0f;
    rtGetFloatv(pname, m);
}

int tu_check_matrix(const char *file, int line, const float m[16], const double expected[16],
                    double tol)
{
    int k;
    for (k = 0; k < 16; k++) {
        double d = (double)m[k] - expected[k];
        if (!(fabs(d) <= tol)) {
            tu_report_failure(file, line);
            fprintf(stderr, "matrix element %d (row %d, column %d) == %.9g, expected %.9g\n", k,
                    k % 4, k / 4, (double)m[k], expected[k]);
            fprintf(stderr, "    got      [");
            for (k = 0; k < 16; k++)
                fprintf(stderr, " %g", (double)m[k]);
            fprintf(stderr, " ]\n    expected [");
            for (k = 0; k < 16; k++)
                fprintf(stderr, " %g", expected[k]);
            fprintf(stderr, " ]\n");
            return 0;
        }
    }
    tu_report_pass();
    return 1;
}

void tu_identity(double m[16])
{
    int k;
    for (k = 0; k < 16; k++)
        m[k] = (k % 5 == 0) ? 1.0 : 0.0;
}

void tu_mat_mul(double r[16], const double a[16], const double b[16])
{
    int row, col, k;
    for (col = 0; col < 4; col++) {
        for (row = 0; row < 4; row++) {
            double s = 0.0;
            for (k = 0; k < 4; k++)
                s += a[k * 4 + row] * b[col * 4 + k];
            r[col * 4 + row] = s;
        }
    }
}

/* ---- rendering ------------------------------------------------------------------ */

void tu_ortho_camera(void)
{
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtOrtho(-1.0, 1.0, -1.0, 1.0, 1.0, 100.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
}

void tu_render_float(int w, int h, float *rgba)
{
    rtViewport(0, 0, w, h);
    rtRenderFrame();
    rtReadPixels(0, 0, w, h, RT_RGBA, RT_FLOAT, rgba);
}

/* volatile keeps the compiler from folding (and warning about) the values. */
static volatile float zero_f = 0.0f;
static volatile double zero_d = 0.0;

float tu_nan(void)
{
    return zero_f / zero_f;
}

float tu_inf(void)
{
    return 1.0f / zero_f;
}

double tu_nan_d(void)
{
    return zero_d / zero_d;
}

double tu_inf_d(void)
{
    return 1.0 / zero_d;
}

/* ---- workload size ---------------------------------------------------------- */

int tu_small_workload(void)
{
    const char *w = getenv("RT_TEST_WORKLOAD");
    return w && strcmp(w, "small") == 0;
}
