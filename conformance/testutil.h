/* SPDX-License-Identifier: Apache-2.0 */
/*
 * testutil.h - helpers shared by the API conformance tests (conformance/<family>.c).
 *
 * Every test is a plain C program that makes checks with the macros below
 * and ends with `return test_summary("name");`, which prints one line
 * "name: N passed, M failed" and returns non-zero when any check failed.
 * A failing check prints "file:line: [section] expression" (plus the
 * values involved) to stderr and the program carries on, so one run shows
 * every failure.
 *
 * Conventions the helpers rely on:
 *   - The current context is the one tu_make_context() made current.
 *   - Geometry helpers define objects under the current modelview matrix,
 *     exactly as the equivalent rtBegin/rtVertex calls would.
 *   - Ray helpers trace one ray with tmin = 0 and tmax = +infinity unless
 *     they say otherwise; rays are in world space.
 *   - Barycentric pins: a ray aimed at the point (1-u-v) a + u b + v c of an
 *     expected triangle (a, b, c) must report exactly that u, v, which pins
 *     the vertex order; TU_PIN_U/TU_PIN_V are distinct and unequal to
 *     1-u-v, so every permutation of the three vertices is detected.
 */
#ifndef RT_CONFORMANCE_TESTUTIL_H
#define RT_CONFORMANCE_TESTUTIL_H

#include <stddef.h>

#include <rt/rt.h>

#include "check.h"

/* ---- checks: check.h (CHECK, CHECK_INT, CHECK_NEAR, CHECK_MSG) ------- */

int tu_expect_error(RTenum code, const char *file, int line, const char *expr);

/*
 * CHECK_ERR(code) / expect_error(code): rtGetError() must return `code`
 * and a second rtGetError() must return RT_NO_ERROR (the slot was cleared).
 */
#define CHECK_ERR(code) tu_expect_error((code), __FILE__, __LINE__, #code)
#define expect_error(code) CHECK_ERR(code)
#define CHECK_NO_ERR() CHECK_ERR(RT_NO_ERROR)


/* "RT_INVALID_VALUE" etc.; "0x...." for anything else (static buffer). */
const char *tu_error_name(RTenum code);

/* ---- contexts ------------------------------------------------------------ */

/*
 * Creates a context with `config` and makes it current.  A test cannot go on
 * without its context, so on failure this prints why and exits with status 1.
 */
RTcontext tu_make_context(const char *config);
/* Unbinds and destroys `ctx` (rtDestroyContext). */
void tu_destroy_context(RTcontext ctx);
/*
 * 1 when rtCreateContext(config) succeeds (the context is destroyed
 * again), 0 when it returns NULL: an isa= this build lacks (RT_NO_SIMD,
 * another architecture) or this CPU cannot run.  The current context is
 * left as it was.
 */
int tu_config_available(const char *config);

/* ---- error callback capture -------------------------------------------- */

/*
 * Installs a callback on the current context that counts the errors it is
 * given and keeps a copy of the last code and message.  tu_reset_captured()
 * clears the count and the copies.
 */
void tu_capture_errors(void);
void tu_reset_captured(void);
int tu_captured_count(void);
RTenum tu_captured_code(void);
const char *tu_captured_message(void);
/* True when `message` starts with `entry` followed by a character that cannot
 * continue a C identifier (so "rtVertex3f" does not match "rtVertex3fv: ..."). */
int tu_message_names(const char *message, const char *entry);
/* The last captured message must name `entry`. */
#define CHECK_MSG(entry)                                                                      \
    tu_check(tu_message_names(tu_captured_message(), (entry)), __FILE__, __LINE__,            \
             "last error message names " entry)

/* ---- recording modes ------------------------------------------------------ */

/* Name of the scratch object that tu_begin_scratch records into. */
#define TU_SCRATCH_OBJECT 0x7FFFFF00u

/* rtNewObject(TU_SCRATCH_OBJECT); rtBegin(mode): puts the context "inside
 * rtBegin" for tests of calls that are not allowed there. */
void tu_begin_scratch(RTenum mode);
/* rtEnd(); rtEndObject(); rtDeleteObjects(1, TU_SCRATCH_OBJECT). */
void tu_end_scratch(void);

/* ---- geometry ---------------------------------------------------------- */

/* Axis-aligned quad in the plane z, vertices (x_lo,y_lo) (x_hi,y_lo) (x_hi,y_hi)
 * (x_lo,y_hi) as one RT_QUADS quad: triangles (0,1,2), (0,2,3); counter-
 * clockwise seen from +z.  Returns 1 when no error was recorded. */
int tu_define_quad(RTuint name, float x_lo, float y_lo, float x_hi, float y_hi, float z);
/* One triangle (a, b, c). */
int tu_define_triangle(RTuint name, const float a[3], const float b[3], const float c[3]);
/* Closed box [lo, hi]: 6 RT_QUADS faces, 12 triangles. */
int tu_define_box(RTuint name, const float lo[3], const float hi[3]);
/* Grid over [x_lo,x_hi] x [y_lo,y_hi] in plane z: nx*ny cells, 2*nx*ny triangles,
 * cell (i, j) gives triangles 2*(j*nx+i) and 2*(j*nx+i)+1. */
int tu_define_grid(RTuint name, int nx, int ny, float x_lo, float y_lo, float x_hi,
                   float y_hi, float z);

/* rtGetObjectiv(name, RT_OBJECT_TRIANGLES) or -1 if the query recorded an error
 * (the error is left pending). */
int tu_object_triangles(RTuint name);

/* ---- scenes and rays ------------------------------------------------------ */

/* rtBeginFrame(); rtInstantiateObject(name) under the current modelview;
 * rtFinish().  Returns 1 when no error was recorded. */
int tu_scene1(RTuint name);

RTray tu_ray(float ox, float oy, float oz, float dx, float dy, float dz);
/* Traces one ray (tmin 0, tmax +inf). */
RThit tu_trace(float ox, float oy, float oz, float dx, float dy, float dz);
/* Traces from (x, y, 10) along (0, 0, -1). */
RThit tu_trace_down(float x, float y);
/* rtOccludedRays for one ray (tmin 0, tmax +inf). */
int tu_occluded(float ox, float oy, float oz, float dx, float dy, float dz);

#define TU_PIN_U 0.2f
#define TU_PIN_V 0.3f
/*
 * Aims a ray at barycentrics (TU_PIN_U, TU_PIN_V) of world-space triangle
 * (a, b, c) from distance 2 along its normal and checks that it reports
 * primitive `prim`, object `object`, instance `instance`, t = 2 and the pinned
 * u, v.  Returns 1 when all of that holds.
 */
int tu_check_triangle(const char *file, int line, const float a[3], const float b[3],
                      const float c[3], RTuint prim, RTuint object, RTuint instance);
#define CHECK_TRIANGLE(a, b, c, prim, object, instance)                                       \
    tu_check_triangle(__FILE__, __LINE__, (a), (b), (c), (prim), (object), (instance))

/* ---- matrices ------------------------------------------------------------- */

/* Reads RT_MODELVIEW_MATRIX or RT_PROJECTION_MATRIX into m[16]. */
void tu_get_matrix(RTenum pname, float m[16]);
/* Checks m[16] against expected[16] (column-major) element by element. */
int tu_check_matrix(const char *file, int line, const float m[16], const double expected[16],
                    double tol);
#define CHECK_MATRIX(m, expected, tol) tu_check_matrix(__FILE__, __LINE__, (m), (expected), (tol))
/* Reads the current matrix of `pname` and checks it. */
#define CHECK_CURRENT_MATRIX(pname, expected, tol)                                            \
    do {                                                                                      \
        float tu_m_[16];                                                                      \
        tu_get_matrix((pname), tu_m_);                                                        \
        tu_check_matrix(__FILE__, __LINE__, tu_m_, (expected), (tol));                        \
    } while (0)
void tu_identity(double m[16]);
/* r = a * b (column-major, r may not alias a or b). */
void tu_mat_mul(double r[16], const double a[16], const double b[16]);

/* ---- rendering -------------------------------------------------------------- */

/* Projection = rtOrtho(-1, 1, -1, 1, 1, 100) (rays along -z from z = -1 to
 * z = -100), modelview = identity, matrix mode RT_MODELVIEW. */
void tu_ortho_camera(void);
/* rtViewport(0, 0, w, h); rtRenderFrame(); rtReadPixels(0, 0, w, h, RT_RGBA,
 * RT_FLOAT, rgba).  rgba holds 4*w*h floats. */
void tu_render_float(int w, int h, float *rgba);

/* Floats that the compiler cannot fold: NaN, +inf, -inf. */
float tu_nan(void);
float tu_inf(void);
double tu_nan_d(void);
double tu_inf_d(void);

/* ---- workload size ---------------------------------------------------------- */

/*
 * 1 when RT_TEST_WORKLOAD=small: scripts/test.sh sets it for the sanitizer
 * suites, where the longest tests then run fewer rays or frames with the same
 * assertions (the Release suite runs them at full size).  0 otherwise.
 */
int tu_small_workload(void);

#endif
