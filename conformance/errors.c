/* SPDX-License-Identifier: Apache-2.0 */
/*
 * errors.c - conformance: error recording across the whole API.
 *
 *   1. A table of (entry point, error, mode) cases: each case must record
 *      exactly one error with the expected code, the callback must receive a
 *      message that starts with the entry point's name, and rtGetError must
 *      return the code once and then RT_NO_ERROR.
 *   2. NaN / +inf / -inf in every argument of every float-taking entry point:
 *      RT_INVALID_VALUE, and the state the call would have changed did not
 *      change.
 *   3. First-error semantics and the callback contract (called for errors
 *      that are not stored, user pointer passed through, NULL removes it).
 *   4. TRACELIST_DEBUG=1 prints errors to stderr with identical repeats
 *      collapsed; without it nothing is printed.  This part re-runs the test
 *      binary as a child ("--debug-child") with a controlled environment.
 *   5. One rule for doubles beyond the float range: draw calls reading
 *      normals, colours or texture coordinates from RT_DOUBLE arrays reject
 *      them as rtUpdateVertices does (docs/arrays.md, docs/dynamic.md).
 *   6. A singular projection renders the clear colour, traces no ray and
 *      records no error (docs/frames.md).
 *
 * Reference: docs/context.md (errors), and each family's page.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* An object that exists throughout the test. */
#define OBJ 1u
/* A name that is never defined. */
#define NOT_AN_OBJECT 4242u

enum mode {
    NONE,   /* outside objects */
    OBJECT, /* inside rtNewObject/rtEndObject, outside rtBegin */
    BEGIN   /* inside rtBegin/rtEnd */
};

static void enter(enum mode m)
{
    if (m == OBJECT || m == BEGIN)
        rtNewObject(TU_SCRATCH_OBJECT);
    if (m == BEGIN)
        rtBegin(RT_TRIANGLES);
    tu_check(rtGetError() == RT_NO_ERROR, __FILE__, __LINE__, "entering the mode");
}

static void leave(enum mode m)
{
    RTuint name = TU_SCRATCH_OBJECT;
    if (m == BEGIN)
        rtEnd();
    if (m == OBJECT || m == BEGIN) {
        rtEndObject();
        rtDeleteObjects(1, &name);
    }
}

/* ---- 1. table of error cases ------------------------------------------------ */

static RTint ibuf[16];
static RTfloat fbuf[16];
static RTuint names[4];
static const RTfloat quad_xyz[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

#define C(fn, body)                                                                           \
    static void fn(void)                                                                      \
    {                                                                                         \
        body;                                                                                 \
    }

C(get_string_enum, (void)rtGetString(0x1234))
C(get_integer_enum, rtGetIntegerv(0x1234, ibuf))
C(get_integer_null, rtGetIntegerv(RT_MATRIX_MODE, NULL))
C(get_integer_matrix, rtGetIntegerv(RT_MODELVIEW_MATRIX, ibuf))
C(get_float_enum, rtGetFloatv(0x1234, fbuf))
C(get_float_null, rtGetFloatv(RT_MATRIX_MODE, NULL))
C(enable_enum, rtEnable(0x1234))
C(enable_light0, rtEnable(RT_LIGHT0))
C(disable_enum, rtDisable(RT_LIGHT0 + 8))
C(disable_light0, rtDisable(RT_LIGHT0))
C(is_enabled_enum, (void)rtIsEnabled(0x1234))
C(is_enabled_light0, (void)rtIsEnabled(RT_LIGHT0))

C(gen_negative, rtGenObjects(-1, names))
C(gen_null, rtGenObjects(1, NULL))
C(new_zero, rtNewObject(0))
C(new_nested, rtNewObject(77))
C(end_object, rtEndObject())
C(delete_negative, rtDeleteObjects(-1, names))
C(delete_null, rtDeleteObjects(1, NULL))
C(delete_inside, rtDeleteObjects(1, &names[3]))
C(is_object_begin, (void)rtIsObject(OBJ))
C(objectiv_name, rtGetObjectiv(NOT_AN_OBJECT, RT_OBJECT_TRIANGLES, ibuf))
C(objectiv_zero, rtGetObjectiv(0, RT_OBJECT_TRIANGLES, ibuf))
C(objectiv_enum, rtGetObjectiv(OBJ, 0x1234, ibuf))
C(objectiv_null, rtGetObjectiv(OBJ, RT_OBJECT_TRIANGLES, NULL))
C(objectfv_name, rtGetObjectfv(NOT_AN_OBJECT, RT_OBJECT_SAH_COST, fbuf))
C(objectfv_enum, rtGetObjectfv(OBJ, 0x1234, fbuf))
C(objectfv_null, rtGetObjectfv(OBJ, RT_OBJECT_BOUNDS, NULL))

C(begin_tri, rtBegin(RT_TRIANGLES))
C(begin_enum, rtBegin(0x1234))
C(begin_points, rtBegin(0x000A)) /* GL_LINES_ADJACENCY is not a Tracelist mode (RT_POINTS, 0, is) */
C(end_plain, rtEnd())
C(vertex2f, rtVertex2f(0, 0))
C(vertex2d, rtVertex2d(0, 0))
C(vertex3f, rtVertex3f(0, 0, 0))
C(vertex3d, rtVertex3d(0, 0, 0))
C(vertex2fv_null, rtVertex2fv(NULL))
C(vertex2dv_null, rtVertex2dv(NULL))
C(vertex3fv_null, rtVertex3fv(NULL))
C(vertex3dv_null, rtVertex3dv(NULL))
C(normal3fv_null, rtNormal3fv(NULL))
C(texcoord2fv_null, rtTexCoord2fv(NULL))
C(color3fv_null, rtColor3fv(NULL))
C(color4fv_null, rtColor4fv(NULL))
C(shade_model_enum, rtShadeModel(0x1234))
C(shade_model_flat, rtShadeModel(RT_FLAT))

C(enable_client_enum, rtEnableClientState(0x1234))
C(enable_client_ok, rtEnableClientState(RT_VERTEX_ARRAY))
C(disable_client_enum, rtDisableClientState(RT_LIGHT0))
C(disable_client_ok, rtDisableClientState(RT_VERTEX_ARRAY))
C(vertex_pointer_size, rtVertexPointer(1, RT_FLOAT, 0, quad_xyz))
C(vertex_pointer_size5, rtVertexPointer(5, RT_FLOAT, 0, quad_xyz))
C(vertex_pointer_type, rtVertexPointer(3, RT_BYTE, 0, quad_xyz))
C(vertex_pointer_stride, rtVertexPointer(3, RT_FLOAT, -4, quad_xyz))
C(vertex_pointer_ok, rtVertexPointer(3, RT_FLOAT, 0, quad_xyz))
C(normal_pointer_type, rtNormalPointer(RT_UNSIGNED_BYTE, 0, quad_xyz))
C(normal_pointer_stride, rtNormalPointer(RT_FLOAT, -1, quad_xyz))
C(normal_pointer_ok, rtNormalPointer(RT_FLOAT, 0, quad_xyz))
C(color_pointer_size, rtColorPointer(2, RT_FLOAT, 0, quad_xyz))
C(color_pointer_type, rtColorPointer(3, RT_INT, 0, quad_xyz))
C(color_pointer_stride, rtColorPointer(3, RT_FLOAT, -1, quad_xyz))
C(color_pointer_ok, rtColorPointer(3, RT_FLOAT, 0, quad_xyz))
C(texcoord_pointer_size0, rtTexCoordPointer(0, RT_FLOAT, 0, quad_xyz))
C(texcoord_pointer_size5, rtTexCoordPointer(5, RT_FLOAT, 0, quad_xyz))
C(texcoord_pointer_type, rtTexCoordPointer(2, RT_UNSIGNED_BYTE, 0, quad_xyz))
C(texcoord_pointer_stride, rtTexCoordPointer(2, RT_FLOAT, -1, quad_xyz))
C(texcoord_pointer_ok, rtTexCoordPointer(2, RT_FLOAT, 0, quad_xyz))
C(draw_arrays_ok, rtDrawArrays(RT_TRIANGLES, 0, 3))
C(draw_arrays_enum, rtDrawArrays(0x1234, 0, 3))
C(draw_arrays_first, rtDrawArrays(RT_TRIANGLES, -1, 3))
C(draw_arrays_count, rtDrawArrays(RT_TRIANGLES, 0, -1))
static const RTuint elems[3] = {0, 1, 2};
C(draw_elements_ok, rtDrawElements(RT_TRIANGLES, 3, RT_UNSIGNED_INT, elems))
C(draw_elements_mode, rtDrawElements(0x1234, 3, RT_UNSIGNED_INT, elems))
C(draw_elements_type, rtDrawElements(RT_TRIANGLES, 3, RT_INT, elems))
C(draw_elements_count, rtDrawElements(RT_TRIANGLES, -3, RT_UNSIGNED_INT, elems))
C(draw_elements_null, rtDrawElements(RT_TRIANGLES, 3, RT_UNSIGNED_INT, NULL))
/* docs/arrays.md: NULL indices are RT_INVALID_VALUE whatever the count,
 * checked before the arrays (the vertex array is off in these cases). */
C(draw_elements_null_empty, rtDrawElements(RT_TRIANGLES, 0, RT_UNSIGNED_INT, NULL))

C(matrix_mode_enum, rtMatrixMode(0x1234))
C(matrix_mode_ok, rtMatrixMode(RT_MODELVIEW))
C(load_identity, rtLoadIdentity())
C(load_matrixf_null, rtLoadMatrixf(NULL))
C(load_matrixd_null, rtLoadMatrixd(NULL))
C(mult_matrixf_null, rtMultMatrixf(NULL))
C(mult_matrixd_null, rtMultMatrixd(NULL))
static const RTfloat identity16[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
C(load_matrixf_ok, rtLoadMatrixf(identity16))
C(translatef, rtTranslatef(1, 0, 0))
C(translated, rtTranslated(1, 0, 0))
C(rotatef, rtRotatef(10, 0, 0, 1))
C(rotated, rtRotated(10, 0, 0, 1))
C(scalef, rtScalef(2, 2, 2))
C(scaled, rtScaled(2, 2, 2))
C(frustum_lr, rtFrustum(1, 1, -1, 1, 1, 10))
C(frustum_near, rtFrustum(-1, 1, -1, 1, 0, 10))
C(frustum_ok, rtFrustum(-1, 1, -1, 1, 1, 10))
C(ortho_bt, rtOrtho(-1, 1, 2, 2, 1, 10))
C(ortho_ok, rtOrtho(-1, 1, -1, 1, 1, 10))
C(push_matrix, rtPushMatrix())
C(pop_matrix, rtPopMatrix())
static void push_overflow(void)
{
    RTint max = 0, depth = 0, i;
    rtGetIntegerv(RT_MAX_MODELVIEW_STACK_DEPTH, &max);
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    for (i = depth; i < max; i++)
        rtPushMatrix();
    tu_reset_captured();
    rtPushMatrix();
}
static void pop_all(void)
{
    RTint depth = 0;
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    while (depth-- > 1)
        rtPopMatrix();
}

C(instantiate_ok, rtInstantiateObject(OBJ))
static void instantiate_singular(void)
{
    rtPushMatrix();
    rtScalef(1, 0, 1);
    rtInstantiateObject(OBJ);
    rtPopMatrix();
}
C(begin_frame, rtBeginFrame())

C(materialf_face, rtMaterialf(0x1234, RT_SHININESS, 1))
C(materialf_pname, rtMaterialf(RT_FRONT, RT_DIFFUSE, 1))
C(materialf_range, rtMaterialf(RT_FRONT, RT_SHININESS, 129))
static const RTfloat rgba_ok[4] = {0.5f, 0.5f, 0.5f, 1.0f};
C(materialfv_face, rtMaterialfv(RT_LIGHT0, RT_DIFFUSE, rgba_ok))
C(materialfv_pname, rtMaterialfv(RT_FRONT, RT_POSITION, rgba_ok))
C(materialfv_null, rtMaterialfv(RT_FRONT, RT_DIFFUSE, NULL))
C(lightf_light, rtLightf(RT_LIGHT0 + 8, RT_CONSTANT_ATTENUATION, 1))
C(lightf_pname, rtLightf(RT_LIGHT0, RT_SHININESS, 1))
C(lightf_range, rtLightf(RT_LIGHT0, RT_LINEAR_ATTENUATION, -1))
C(lightf_ok, rtLightf(RT_LIGHT0, RT_CONSTANT_ATTENUATION, 1))
C(lightfv_light, rtLightfv(RT_FRONT, RT_DIFFUSE, rgba_ok))
C(lightfv_pname, rtLightfv(RT_LIGHT0, RT_EMISSION, rgba_ok))
C(lightfv_null, rtLightfv(RT_LIGHT0, RT_POSITION, NULL))
C(lightfv_ok, rtLightfv(RT_LIGHT0, RT_DIFFUSE, rgba_ok))
C(light_model_pname, rtLightModelfv(RT_AMBIENT, rgba_ok))
C(light_model_null, rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, NULL))
C(shading_mode_enum, rtShadingMode(RT_SMOOTH))
C(render_param_pname, rtRenderParameteri(RT_SHADING_MODE, 1))
C(render_param_range, rtRenderParameteri(RT_MAX_RAY_DEPTH, 17))
C(render_param_negative, rtRenderParameteri(RT_MAX_RAY_DEPTH, -1))

C(gen_ok, rtGenObjects(1, names))
C(objectiv_ok, rtGetObjectiv(OBJ, RT_OBJECT_TRIANGLES, ibuf))
C(objectfv_ok, rtGetObjectfv(OBJ, RT_OBJECT_BOUNDS, fbuf))
C(light_model_ok, rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, rgba_ok))
C(shading_mode_ok, rtShadingMode(RT_WHITTED))
C(render_param_ok, rtRenderParameteri(RT_MAX_RAY_DEPTH, 2))
C(viewport_ok, rtViewport(0, 0, 4, 4))
C(clear_color_ok, rtClearColor(0, 0, 0, 1))
C(viewport_negative, rtViewport(0, -1, 4, 4))
C(viewport_huge, rtViewport(0, 0, 16385, 4))
/* docs/frames.md: x + width and y + height are at most 16384 (the
 * framebuffer is (x + width) x (y + height)). */
C(viewport_x_plus_width, rtViewport(100, 0, 16384, 1))
C(viewport_y_plus_height, rtViewport(0, 16384, 1, 1))
C(viewport_corner, rtViewport(16384, 16384, 1, 1))
C(clear_color_nan, rtClearColor(0, tu_nan(), 0, 1))
C(render_frame, rtRenderFrame())
C(finish, rtFinish())
static unsigned char pixels[64];
C(read_format, rtReadPixels(0, 0, 1, 1, 0x1907 /* GL_RGB */, RT_UNSIGNED_BYTE, pixels))
C(read_type, rtReadPixels(0, 0, 1, 1, RT_RGBA, RT_INT, pixels))
C(read_null, rtReadPixels(0, 0, 1, 1, RT_RGBA, RT_UNSIGNED_BYTE, NULL))
C(read_size, rtReadPixels(0, 0, -1, 1, RT_RGBA, RT_UNSIGNED_BYTE, pixels))
C(read_outside, rtReadPixels(0, 0, 100, 1, RT_RGBA, RT_UNSIGNED_BYTE, pixels))
C(read_ok, rtReadPixels(0, 0, 0, 0, RT_RGBA, RT_UNSIGNED_BYTE, pixels))

static RTray one_ray = {{0, 0, 5}, 0, {0, 0, -1}, 100};
static RThit one_hit;
static RTboolean one_occ;
C(trace_negative, rtTraceRays(-1, &one_ray, &one_hit))
C(trace_null_rays, rtTraceRays(1, NULL, &one_hit))
C(trace_null_hits, rtTraceRays(1, &one_ray, NULL))
C(trace_ok, rtTraceRays(1, &one_ray, &one_hit))
C(occluded_negative, rtOccludedRays(-1, &one_ray, &one_occ))
C(occluded_null_rays, rtOccludedRays(1, NULL, &one_occ))
C(occluded_null_out, rtOccludedRays(1, &one_ray, NULL))
C(occluded_ok, rtOccludedRays(1, &one_ray, &one_occ))
#undef C

struct error_case {
    const char *entry;
    RTenum code;
    enum mode mode;
    void (*call)(void);
    void (*cleanup)(void); /* run after the checks, may be NULL */
};

static const struct error_case cases[] = {
    {"rtGetString", RT_INVALID_ENUM, NONE, get_string_enum, NULL},
    {"rtGetIntegerv", RT_INVALID_ENUM, NONE, get_integer_enum, NULL},
    {"rtGetIntegerv", RT_INVALID_VALUE, NONE, get_integer_null, NULL},
    {"rtGetIntegerv", RT_INVALID_ENUM, NONE, get_integer_matrix, NULL},
    {"rtGetFloatv", RT_INVALID_ENUM, NONE, get_float_enum, NULL},
    {"rtGetFloatv", RT_INVALID_VALUE, NONE, get_float_null, NULL},
    {"rtEnable", RT_INVALID_ENUM, NONE, enable_enum, NULL},
    {"rtEnable", RT_INVALID_OPERATION, BEGIN, enable_light0, NULL},
    {"rtDisable", RT_INVALID_ENUM, NONE, disable_enum, NULL},
    {"rtDisable", RT_INVALID_OPERATION, BEGIN, disable_light0, NULL},
    {"rtIsEnabled", RT_INVALID_ENUM, NONE, is_enabled_enum, NULL},
    {"rtIsEnabled", RT_INVALID_OPERATION, BEGIN, is_enabled_light0, NULL},

    {"rtGenObjects", RT_INVALID_VALUE, NONE, gen_negative, NULL},
    {"rtGenObjects", RT_INVALID_VALUE, NONE, gen_null, NULL},
    {"rtGenObjects", RT_INVALID_OPERATION, BEGIN, gen_ok, NULL},
    {"rtNewObject", RT_INVALID_VALUE, NONE, new_zero, NULL},
    {"rtNewObject", RT_INVALID_OPERATION, OBJECT, new_nested, NULL},
    {"rtNewObject", RT_INVALID_OPERATION, BEGIN, new_nested, NULL},
    {"rtEndObject", RT_INVALID_OPERATION, NONE, end_object, NULL},
    {"rtEndObject", RT_INVALID_OPERATION, BEGIN, end_object, NULL},
    {"rtDeleteObjects", RT_INVALID_VALUE, NONE, delete_negative, NULL},
    {"rtDeleteObjects", RT_INVALID_VALUE, NONE, delete_null, NULL},
    {"rtDeleteObjects", RT_INVALID_OPERATION, OBJECT, delete_inside, NULL},
    {"rtDeleteObjects", RT_INVALID_OPERATION, BEGIN, delete_inside, NULL},
    {"rtIsObject", RT_INVALID_OPERATION, BEGIN, is_object_begin, NULL},
    {"rtGetObjectiv", RT_INVALID_VALUE, NONE, objectiv_name, NULL},
    {"rtGetObjectiv", RT_INVALID_VALUE, NONE, objectiv_zero, NULL},
    {"rtGetObjectiv", RT_INVALID_ENUM, NONE, objectiv_enum, NULL},
    {"rtGetObjectiv", RT_INVALID_VALUE, NONE, objectiv_null, NULL},
    {"rtGetObjectiv", RT_INVALID_OPERATION, BEGIN, objectiv_ok, NULL},
    {"rtGetObjectfv", RT_INVALID_VALUE, NONE, objectfv_name, NULL},
    {"rtGetObjectfv", RT_INVALID_ENUM, NONE, objectfv_enum, NULL},
    {"rtGetObjectfv", RT_INVALID_VALUE, NONE, objectfv_null, NULL},
    {"rtGetObjectfv", RT_INVALID_OPERATION, BEGIN, objectfv_ok, NULL},

    {"rtBegin", RT_INVALID_ENUM, OBJECT, begin_enum, NULL},
    {"rtBegin", RT_INVALID_ENUM, OBJECT, begin_points, NULL},
    {"rtBegin", RT_INVALID_OPERATION, BEGIN, begin_tri, NULL},
    {"rtEnd", RT_INVALID_OPERATION, NONE, end_plain, NULL},
    {"rtEnd", RT_INVALID_OPERATION, OBJECT, end_plain, NULL},
    {"rtVertex2f", RT_INVALID_OPERATION, NONE, vertex2f, NULL},
    {"rtVertex2d", RT_INVALID_OPERATION, OBJECT, vertex2d, NULL},
    {"rtVertex3f", RT_INVALID_OPERATION, OBJECT, vertex3f, NULL},
    {"rtVertex3d", RT_INVALID_OPERATION, NONE, vertex3d, NULL},
    {"rtVertex2fv", RT_INVALID_VALUE, BEGIN, vertex2fv_null, NULL},
    {"rtVertex2dv", RT_INVALID_VALUE, BEGIN, vertex2dv_null, NULL},
    {"rtVertex3fv", RT_INVALID_VALUE, BEGIN, vertex3fv_null, NULL},
    {"rtVertex3dv", RT_INVALID_VALUE, BEGIN, vertex3dv_null, NULL},
    {"rtNormal3fv", RT_INVALID_VALUE, NONE, normal3fv_null, NULL},
    {"rtNormal3fv", RT_INVALID_VALUE, BEGIN, normal3fv_null, NULL},
    {"rtTexCoord2fv", RT_INVALID_VALUE, NONE, texcoord2fv_null, NULL},
    {"rtColor3fv", RT_INVALID_VALUE, OBJECT, color3fv_null, NULL},
    {"rtColor4fv", RT_INVALID_VALUE, BEGIN, color4fv_null, NULL},
    {"rtShadeModel", RT_INVALID_ENUM, NONE, shade_model_enum, NULL},
    {"rtShadeModel", RT_INVALID_OPERATION, BEGIN, shade_model_flat, NULL},

    {"rtEnableClientState", RT_INVALID_ENUM, NONE, enable_client_enum, NULL},
    {"rtEnableClientState", RT_INVALID_OPERATION, BEGIN, enable_client_ok, NULL},
    {"rtDisableClientState", RT_INVALID_ENUM, NONE, disable_client_enum, NULL},
    {"rtDisableClientState", RT_INVALID_OPERATION, BEGIN, disable_client_ok, NULL},
    {"rtVertexPointer", RT_INVALID_VALUE, NONE, vertex_pointer_size, NULL},
    {"rtVertexPointer", RT_INVALID_VALUE, NONE, vertex_pointer_size5, NULL},
    {"rtVertexPointer", RT_INVALID_ENUM, NONE, vertex_pointer_type, NULL},
    {"rtVertexPointer", RT_INVALID_VALUE, NONE, vertex_pointer_stride, NULL},
    {"rtVertexPointer", RT_INVALID_OPERATION, BEGIN, vertex_pointer_ok, NULL},
    {"rtNormalPointer", RT_INVALID_ENUM, NONE, normal_pointer_type, NULL},
    {"rtNormalPointer", RT_INVALID_VALUE, NONE, normal_pointer_stride, NULL},
    {"rtNormalPointer", RT_INVALID_OPERATION, BEGIN, normal_pointer_ok, NULL},
    {"rtColorPointer", RT_INVALID_VALUE, NONE, color_pointer_size, NULL},
    {"rtColorPointer", RT_INVALID_ENUM, NONE, color_pointer_type, NULL},
    {"rtColorPointer", RT_INVALID_VALUE, NONE, color_pointer_stride, NULL},
    {"rtColorPointer", RT_INVALID_OPERATION, BEGIN, color_pointer_ok, NULL},
    {"rtTexCoordPointer", RT_INVALID_VALUE, NONE, texcoord_pointer_size0, NULL},
    {"rtTexCoordPointer", RT_INVALID_VALUE, NONE, texcoord_pointer_size5, NULL},
    {"rtTexCoordPointer", RT_INVALID_ENUM, NONE, texcoord_pointer_type, NULL},
    {"rtTexCoordPointer", RT_INVALID_VALUE, NONE, texcoord_pointer_stride, NULL},
    {"rtTexCoordPointer", RT_INVALID_OPERATION, BEGIN, texcoord_pointer_ok, NULL},
    {"rtDrawArrays", RT_INVALID_OPERATION, NONE, draw_arrays_ok, NULL},
    {"rtDrawArrays", RT_INVALID_OPERATION, BEGIN, draw_arrays_ok, NULL},
    {"rtDrawArrays", RT_INVALID_ENUM, OBJECT, draw_arrays_enum, NULL},
    {"rtDrawArrays", RT_INVALID_VALUE, OBJECT, draw_arrays_first, NULL},
    {"rtDrawArrays", RT_INVALID_VALUE, OBJECT, draw_arrays_count, NULL},
    /* The vertex array is disabled (the default) at this point. */
    {"rtDrawArrays", RT_INVALID_OPERATION, OBJECT, draw_arrays_ok, NULL},
    {"rtDrawElements", RT_INVALID_OPERATION, NONE, draw_elements_ok, NULL},
    {"rtDrawElements", RT_INVALID_OPERATION, BEGIN, draw_elements_ok, NULL},
    {"rtDrawElements", RT_INVALID_ENUM, OBJECT, draw_elements_mode, NULL},
    {"rtDrawElements", RT_INVALID_ENUM, OBJECT, draw_elements_type, NULL},
    {"rtDrawElements", RT_INVALID_VALUE, OBJECT, draw_elements_count, NULL},
    {"rtDrawElements", RT_INVALID_VALUE, OBJECT, draw_elements_null, NULL},
    {"rtDrawElements", RT_INVALID_VALUE, OBJECT, draw_elements_null_empty, NULL},
    {"rtDrawElements", RT_INVALID_OPERATION, OBJECT, draw_elements_ok, NULL},

    {"rtMatrixMode", RT_INVALID_ENUM, NONE, matrix_mode_enum, NULL},
    {"rtMatrixMode", RT_INVALID_OPERATION, BEGIN, matrix_mode_ok, NULL},
    {"rtLoadIdentity", RT_INVALID_OPERATION, BEGIN, load_identity, NULL},
    {"rtLoadMatrixf", RT_INVALID_VALUE, NONE, load_matrixf_null, NULL},
    {"rtLoadMatrixf", RT_INVALID_OPERATION, BEGIN, load_matrixf_ok, NULL},
    {"rtLoadMatrixd", RT_INVALID_VALUE, NONE, load_matrixd_null, NULL},
    {"rtMultMatrixf", RT_INVALID_VALUE, NONE, mult_matrixf_null, NULL},
    {"rtMultMatrixd", RT_INVALID_VALUE, NONE, mult_matrixd_null, NULL},
    {"rtTranslatef", RT_INVALID_OPERATION, BEGIN, translatef, NULL},
    {"rtTranslated", RT_INVALID_OPERATION, BEGIN, translated, NULL},
    {"rtRotatef", RT_INVALID_OPERATION, BEGIN, rotatef, NULL},
    {"rtRotated", RT_INVALID_OPERATION, BEGIN, rotated, NULL},
    {"rtScalef", RT_INVALID_OPERATION, BEGIN, scalef, NULL},
    {"rtScaled", RT_INVALID_OPERATION, BEGIN, scaled, NULL},
    {"rtFrustum", RT_INVALID_VALUE, NONE, frustum_lr, NULL},
    {"rtFrustum", RT_INVALID_VALUE, NONE, frustum_near, NULL},
    {"rtFrustum", RT_INVALID_OPERATION, BEGIN, frustum_ok, NULL},
    {"rtOrtho", RT_INVALID_VALUE, NONE, ortho_bt, NULL},
    {"rtOrtho", RT_INVALID_OPERATION, BEGIN, ortho_ok, NULL},
    {"rtPushMatrix", RT_STACK_OVERFLOW, NONE, push_overflow, pop_all},
    {"rtPushMatrix", RT_INVALID_OPERATION, BEGIN, push_matrix, NULL},
    {"rtPopMatrix", RT_STACK_UNDERFLOW, NONE, pop_matrix, NULL},
    {"rtPopMatrix", RT_INVALID_OPERATION, BEGIN, pop_matrix, NULL},

    {"rtInstantiateObject", RT_INVALID_VALUE, NONE, instantiate_singular, NULL},
    {"rtInstantiateObject", RT_INVALID_OPERATION, BEGIN, instantiate_ok, NULL},
    {"rtBeginFrame", RT_INVALID_OPERATION, OBJECT, begin_frame, NULL},
    {"rtBeginFrame", RT_INVALID_OPERATION, BEGIN, begin_frame, NULL},

    {"rtMaterialf", RT_INVALID_ENUM, NONE, materialf_face, NULL},
    {"rtMaterialf", RT_INVALID_ENUM, NONE, materialf_pname, NULL},
    {"rtMaterialf", RT_INVALID_VALUE, BEGIN, materialf_range, NULL},
    {"rtMaterialfv", RT_INVALID_ENUM, NONE, materialfv_face, NULL},
    {"rtMaterialfv", RT_INVALID_ENUM, OBJECT, materialfv_pname, NULL},
    {"rtMaterialfv", RT_INVALID_VALUE, NONE, materialfv_null, NULL},
    {"rtLightf", RT_INVALID_ENUM, NONE, lightf_light, NULL},
    {"rtLightf", RT_INVALID_ENUM, NONE, lightf_pname, NULL},
    {"rtLightf", RT_INVALID_VALUE, NONE, lightf_range, NULL},
    {"rtLightf", RT_INVALID_OPERATION, BEGIN, lightf_ok, NULL},
    {"rtLightfv", RT_INVALID_ENUM, NONE, lightfv_light, NULL},
    {"rtLightfv", RT_INVALID_ENUM, NONE, lightfv_pname, NULL},
    {"rtLightfv", RT_INVALID_VALUE, NONE, lightfv_null, NULL},
    {"rtLightfv", RT_INVALID_OPERATION, BEGIN, lightfv_ok, NULL},
    {"rtLightModelfv", RT_INVALID_ENUM, NONE, light_model_pname, NULL},
    {"rtLightModelfv", RT_INVALID_VALUE, NONE, light_model_null, NULL},
    {"rtLightModelfv", RT_INVALID_OPERATION, BEGIN, light_model_ok, NULL},
    {"rtShadingMode", RT_INVALID_ENUM, NONE, shading_mode_enum, NULL},
    {"rtShadingMode", RT_INVALID_OPERATION, BEGIN, shading_mode_ok, NULL},
    {"rtRenderParameteri", RT_INVALID_ENUM, NONE, render_param_pname, NULL},
    {"rtRenderParameteri", RT_INVALID_OPERATION, BEGIN, render_param_ok, NULL},
    {"rtRenderParameteri", RT_INVALID_VALUE, NONE, render_param_range, NULL},
    {"rtRenderParameteri", RT_INVALID_VALUE, NONE, render_param_negative, NULL},

    {"rtViewport", RT_INVALID_VALUE, NONE, viewport_negative, NULL},
    {"rtViewport", RT_INVALID_VALUE, NONE, viewport_huge, NULL},
    {"rtViewport", RT_INVALID_VALUE, NONE, viewport_x_plus_width, NULL},
    {"rtViewport", RT_INVALID_VALUE, NONE, viewport_y_plus_height, NULL},
    {"rtViewport", RT_INVALID_VALUE, NONE, viewport_corner, NULL},
    {"rtViewport", RT_INVALID_OPERATION, BEGIN, viewport_ok, NULL},
    {"rtClearColor", RT_INVALID_VALUE, NONE, clear_color_nan, NULL},
    {"rtClearColor", RT_INVALID_OPERATION, BEGIN, clear_color_ok, NULL},
    {"rtRenderFrame", RT_INVALID_OPERATION, OBJECT, render_frame, NULL},
    {"rtRenderFrame", RT_INVALID_OPERATION, BEGIN, render_frame, NULL},
    {"rtFinish", RT_INVALID_OPERATION, OBJECT, finish, NULL},
    {"rtFinish", RT_INVALID_OPERATION, BEGIN, finish, NULL},
    {"rtReadPixels", RT_INVALID_ENUM, NONE, read_format, NULL},
    {"rtReadPixels", RT_INVALID_ENUM, NONE, read_type, NULL},
    {"rtReadPixels", RT_INVALID_VALUE, NONE, read_null, NULL},
    {"rtReadPixels", RT_INVALID_VALUE, NONE, read_size, NULL},
    {"rtReadPixels", RT_INVALID_VALUE, NONE, read_outside, NULL},
    {"rtReadPixels", RT_INVALID_OPERATION, BEGIN, read_ok, NULL},

    {"rtTraceRays", RT_INVALID_VALUE, NONE, trace_negative, NULL},
    {"rtTraceRays", RT_INVALID_VALUE, NONE, trace_null_rays, NULL},
    {"rtTraceRays", RT_INVALID_VALUE, NONE, trace_null_hits, NULL},
    {"rtTraceRays", RT_INVALID_OPERATION, OBJECT, trace_ok, NULL},
    {"rtTraceRays", RT_INVALID_OPERATION, BEGIN, trace_ok, NULL},
    {"rtOccludedRays", RT_INVALID_VALUE, NONE, occluded_negative, NULL},
    {"rtOccludedRays", RT_INVALID_VALUE, NONE, occluded_null_rays, NULL},
    {"rtOccludedRays", RT_INVALID_VALUE, NONE, occluded_null_out, NULL},
    {"rtOccludedRays", RT_INVALID_OPERATION, OBJECT, occluded_ok, NULL},
    {"rtOccludedRays", RT_INVALID_OPERATION, BEGIN, occluded_ok, NULL},
};

static const char *mode_name(enum mode m)
{
    return m == NONE ? "outside objects" : m == OBJECT ? "inside an object" : "inside rtBegin";
}

static void run_error_table(void)
{
    size_t i;
    tu_section("error table: code, message, first error only");
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const struct error_case *c = &cases[i];
        RTenum got, again;
        int ok = 1;
        enter(c->mode);
        tu_reset_captured();
        c->call();
        got = rtGetError();
        again = rtGetError();
        ok &= tu_check(got == c->code, __FILE__, __LINE__, "expected error code");
        ok &= tu_check(again == RT_NO_ERROR, __FILE__, __LINE__, "error slot cleared");
        ok &= tu_check(tu_captured_count() == 1, __FILE__, __LINE__, "callback called once");
        ok &= tu_check(tu_captured_code() == c->code, __FILE__, __LINE__, "callback code");
        ok &= tu_check(tu_message_names(tu_captured_message(), c->entry), __FILE__, __LINE__,
                       "message names the entry point");
        if (!ok)
            fprintf(stderr,
                    "    case %u: %s %s, expected %s; got %s, callback %d x %s \"%s\"\n",
                    (unsigned)i, c->entry, mode_name(c->mode), tu_error_name(c->code),
                    tu_error_name(got), tu_captured_count(), tu_error_name(tu_captured_code()),
                    tu_captured_message());
        if (c->cleanup)
            c->cleanup();
        leave(c->mode);
        /* The mode is left cleanly: a pending error here means the failing call
         * changed the recording state (e.g. ended the object or rtBegin). */
        if (!tu_check(rtGetError() == RT_NO_ERROR, __FILE__, __LINE__,
                      "failing call left the recording mode intact"))
            fprintf(stderr, "    case %u: %s %s\n", (unsigned)i, c->entry, mode_name(c->mode));
    }
}

/* Calls that are allowed inside an object (outside rtBegin) and take effect
 * at once (docs/errors.md, "Calls and modes"). */
static void allowed_inside_objects(void)
{
    RTuint g = 0;
    RTint iv[4];
    float fv[16];
    unsigned char px[4];
    tu_section("calls allowed inside an object");
    enter(OBJECT);
    tu_reset_captured();
    rtGenObjects(1, &g);
    CHECK(rtIsObject(OBJ) == RT_TRUE);
    rtGetObjectiv(OBJ, RT_OBJECT_TRIANGLES, iv);
    rtGetObjectfv(OBJ, RT_OBJECT_BOUNDS, fv);
    CHECK(rtGetString(RT_VERSION) != NULL);
    rtGetIntegerv(RT_MATRIX_MODE, iv);
    rtGetFloatv(RT_MODELVIEW_MATRIX, fv);
    rtEnable(RT_LIGHT0);
    rtDisable(RT_LIGHT0);
    CHECK(rtIsEnabled(RT_LIGHT0) == RT_FALSE);
    rtEnableClientState(RT_NORMAL_ARRAY);
    rtDisableClientState(RT_NORMAL_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, quad_xyz);
    rtNormalPointer(RT_FLOAT, 0, quad_xyz);
    rtColorPointer(3, RT_FLOAT, 0, quad_xyz);
    rtTexCoordPointer(2, RT_FLOAT, 0, quad_xyz);
    rtShadeModel(RT_SMOOTH);
    rtMatrixMode(RT_MODELVIEW);
    rtPushMatrix();
    rtLoadIdentity();
    rtPopMatrix();
    rtNormal3f(0, 0, 1);
    rtTexCoord2f(0, 0);
    rtColor4f(1, 1, 1, 1);
    rtMaterialf(RT_FRONT, RT_SHININESS, 0);
    rtLightfv(RT_LIGHT0, RT_AMBIENT, rgba_ok);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, rgba_ok);
    rtShadingMode(RT_EYE_LIGHT);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 3);
    rtViewport(0, 0, 0, 0);
    rtClearColor(0, 0, 0, 0);
    rtReadPixels(0, 0, 0, 0, RT_RGBA, RT_UNSIGNED_BYTE, px);
    CHECK_INT(tu_captured_count(), 0);
    if (tu_captured_count() > 0)
        fprintf(stderr, "    last: \"%s\"\n", tu_captured_message());
    CHECK_NO_ERR();
    leave(OBJECT);
    rtDeleteObjects(1, &g);
    {
        static const float dflt[4] = {0.2f, 0.2f, 0.2f, 1};
        rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, dflt);
    }
    CHECK_NO_ERR();
}

/* ---- 2. NaN / inf in every float-taking entry point ---------------------------- */

/* Each sweep function issues its entry point with valid arguments except
 * argument `arg`, which is `bad`. */
typedef void (*sweep_fn)(int arg, double bad);

#define SET(n)                                                                                \
    double a[n];                                                                              \
    int k;                                                                                    \
    for (k = 0; k < (n); k++)                                                                 \
        a[k] = valid[k];                                                                      \
    a[arg] = bad

static void sw_vertex2f(int arg, double bad)
{
    static const double valid[2] = {1, 2};
    SET(2);
    rtVertex2f((float)a[0], (float)a[1]);
}
static void sw_vertex2d(int arg, double bad)
{
    static const double valid[2] = {1, 2};
    SET(2);
    rtVertex2d(a[0], a[1]);
}
static void sw_vertex3f(int arg, double bad)
{
    static const double valid[3] = {1, 2, 3};
    SET(3);
    rtVertex3f((float)a[0], (float)a[1], (float)a[2]);
}
static void sw_vertex3d(int arg, double bad)
{
    static const double valid[3] = {1, 2, 3};
    SET(3);
    rtVertex3d(a[0], a[1], a[2]);
}
static void sw_vertex2fv(int arg, double bad)
{
    static const double valid[2] = {1, 2};
    float f[2];
    SET(2);
    f[0] = (float)a[0];
    f[1] = (float)a[1];
    rtVertex2fv(f);
}
static void sw_vertex2dv(int arg, double bad)
{
    static const double valid[2] = {1, 2};
    SET(2);
    rtVertex2dv(a);
}
static void sw_vertex3fv(int arg, double bad)
{
    static const double valid[3] = {1, 2, 3};
    float f[3];
    SET(3);
    for (k = 0; k < 3; k++)
        f[k] = (float)a[k];
    rtVertex3fv(f);
}
static void sw_vertex3dv(int arg, double bad)
{
    static const double valid[3] = {1, 2, 3};
    SET(3);
    rtVertex3dv(a);
}
static void sw_normal3f(int arg, double bad)
{
    static const double valid[3] = {0, 0, 1};
    SET(3);
    rtNormal3f((float)a[0], (float)a[1], (float)a[2]);
}
static void sw_normal3fv(int arg, double bad)
{
    static const double valid[3] = {0, 0, 1};
    float f[3];
    SET(3);
    for (k = 0; k < 3; k++)
        f[k] = (float)a[k];
    rtNormal3fv(f);
}
static void sw_texcoord2f(int arg, double bad)
{
    static const double valid[2] = {0.5, 0.5};
    SET(2);
    rtTexCoord2f((float)a[0], (float)a[1]);
}
static void sw_texcoord2fv(int arg, double bad)
{
    static const double valid[2] = {0.5, 0.5};
    float f[2];
    SET(2);
    f[0] = (float)a[0];
    f[1] = (float)a[1];
    rtTexCoord2fv(f);
}
static void sw_color3f(int arg, double bad)
{
    static const double valid[3] = {0.5, 0.5, 0.5};
    SET(3);
    rtColor3f((float)a[0], (float)a[1], (float)a[2]);
}
static void sw_color3fv(int arg, double bad)
{
    static const double valid[3] = {0.5, 0.5, 0.5};
    float f[3];
    SET(3);
    for (k = 0; k < 3; k++)
        f[k] = (float)a[k];
    rtColor3fv(f);
}
static void sw_color4f(int arg, double bad)
{
    static const double valid[4] = {0.5, 0.5, 0.5, 1};
    SET(4);
    rtColor4f((float)a[0], (float)a[1], (float)a[2], (float)a[3]);
}
static void sw_color4fv(int arg, double bad)
{
    static const double valid[4] = {0.5, 0.5, 0.5, 1};
    float f[4];
    SET(4);
    for (k = 0; k < 4; k++)
        f[k] = (float)a[k];
    rtColor4fv(f);
}
static const double valid_matrix[16] = {2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 1, 2, 3, 1};
static void sw_load_matrixf(int arg, double bad)
{
    const double *valid = valid_matrix;
    float f[16];
    SET(16);
    for (k = 0; k < 16; k++)
        f[k] = (float)a[k];
    rtLoadMatrixf(f);
}
static void sw_load_matrixd(int arg, double bad)
{
    const double *valid = valid_matrix;
    SET(16);
    rtLoadMatrixd(a);
}
static void sw_mult_matrixf(int arg, double bad)
{
    const double *valid = valid_matrix;
    float f[16];
    SET(16);
    for (k = 0; k < 16; k++)
        f[k] = (float)a[k];
    rtMultMatrixf(f);
}
static void sw_mult_matrixd(int arg, double bad)
{
    const double *valid = valid_matrix;
    SET(16);
    rtMultMatrixd(a);
}
static void sw_translatef(int arg, double bad)
{
    static const double valid[3] = {1, 2, 3};
    SET(3);
    rtTranslatef((float)a[0], (float)a[1], (float)a[2]);
}
static void sw_translated(int arg, double bad)
{
    static const double valid[3] = {1, 2, 3};
    SET(3);
    rtTranslated(a[0], a[1], a[2]);
}
static void sw_rotatef(int arg, double bad)
{
    static const double valid[4] = {30, 1, 2, 3};
    SET(4);
    rtRotatef((float)a[0], (float)a[1], (float)a[2], (float)a[3]);
}
static void sw_rotated(int arg, double bad)
{
    static const double valid[4] = {30, 1, 2, 3};
    SET(4);
    rtRotated(a[0], a[1], a[2], a[3]);
}
static void sw_scalef(int arg, double bad)
{
    static const double valid[3] = {2, 3, 4};
    SET(3);
    rtScalef((float)a[0], (float)a[1], (float)a[2]);
}
static void sw_scaled(int arg, double bad)
{
    static const double valid[3] = {2, 3, 4};
    SET(3);
    rtScaled(a[0], a[1], a[2]);
}
static void sw_frustum(int arg, double bad)
{
    static const double valid[6] = {-1, 1, -1, 1, 1, 10};
    SET(6);
    rtFrustum(a[0], a[1], a[2], a[3], a[4], a[5]);
}
static void sw_ortho(int arg, double bad)
{
    static const double valid[6] = {-1, 1, -1, 1, 1, 10};
    SET(6);
    rtOrtho(a[0], a[1], a[2], a[3], a[4], a[5]);
}
static void sw_materialf(int arg, double bad)
{
    static const double valid[1] = {10};
    SET(1);
    rtMaterialf(RT_FRONT_AND_BACK, RT_SHININESS, (float)a[0]);
}
static void sw_materialfv_diffuse(int arg, double bad)
{
    static const double valid[4] = {0.5, 0.5, 0.5, 1};
    float f[4];
    SET(4);
    for (k = 0; k < 4; k++)
        f[k] = (float)a[k];
    rtMaterialfv(RT_FRONT, RT_DIFFUSE, f);
}
static void sw_materialfv_ior(int arg, double bad)
{
    static const double valid[1] = {1.5};
    float f[1];
    SET(1);
    f[0] = (float)a[0];
    rtMaterialfv(RT_BACK, RT_INDEX_OF_REFRACTION, f);
}
static void sw_lightf(int arg, double bad)
{
    static const double valid[1] = {1};
    SET(1);
    rtLightf(RT_LIGHT0 + 2, RT_QUADRATIC_ATTENUATION, (float)a[0]);
}
static void sw_lightfv_position(int arg, double bad)
{
    static const double valid[4] = {1, 2, 3, 1};
    float f[4];
    SET(4);
    for (k = 0; k < 4; k++)
        f[k] = (float)a[k];
    rtLightfv(RT_LIGHT0, RT_POSITION, f);
}
static void sw_lightfv_specular(int arg, double bad)
{
    static const double valid[4] = {1, 1, 1, 1};
    float f[4];
    SET(4);
    for (k = 0; k < 4; k++)
        f[k] = (float)a[k];
    rtLightfv(RT_LIGHT0 + 7, RT_SPECULAR, f);
}
static void sw_light_model(int arg, double bad)
{
    static const double valid[4] = {0.1, 0.1, 0.1, 1};
    float f[4];
    SET(4);
    for (k = 0; k < 4; k++)
        f[k] = (float)a[k];
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, f);
}
static void sw_clear_color(int arg, double bad)
{
    static const double valid[4] = {0.1, 0.2, 0.3, 0.4};
    SET(4);
    rtClearColor((float)a[0], (float)a[1], (float)a[2], (float)a[3]);
}
/* Rays: argument 0..2 origin, 3..5 direction, 6 tmin, 7 tmax.  The second
 * ray of a batch of two is the bad one; nothing may be written. */
static int rays_written;
static void sweep_rays(int arg, double bad, int occluded)
{
    static const double valid[8] = {0.5, 0.5, 5, 0, 0, -1, 0, 100};
    RTray r[2];
    RThit h[2];
    RTboolean o[2] = {77, 77};
    SET(8);
    for (k = 0; k < 2; k++) {
        r[k].org[0] = r[k].org[1] = 0.5f;
        r[k].org[2] = 5.0f;
        r[k].dir[0] = r[k].dir[1] = 0.0f;
        r[k].dir[2] = -1.0f;
        r[k].tmin = 0.0f;
        r[k].tmax = 100.0f;
        h[k].t = -5.0f;
        h[k].object = h[k].instance = h[k].primitive = 12345u;
    }
    if (arg < 3)
        r[1].org[arg] = (float)a[arg];
    else if (arg < 6)
        r[1].dir[arg - 3] = (float)a[arg];
    else if (arg == 6)
        r[1].tmin = (float)a[arg];
    else
        r[1].tmax = (float)a[arg];
    if (occluded) {
        rtOccludedRays(2, r, o);
        rays_written = o[0] != 77 || o[1] != 77;
    } else {
        rtTraceRays(2, r, h);
        rays_written = h[0].t != -5.0f || h[1].t != -5.0f || h[0].object != 12345u;
    }
}
static void sw_trace(int arg, double bad)
{
    sweep_rays(arg, bad, 0);
}
static void sw_occluded(int arg, double bad)
{
    sweep_rays(arg, bad, 1);
}
#undef SET

struct sweep_case {
    const char *entry;
    int nargs;
    enum mode mode;
    sweep_fn fn;
    int vertex; /* 1: a vertex call, check it was not recorded */
};

static const struct sweep_case sweeps[] = {
    {"rtVertex2f", 2, BEGIN, sw_vertex2f, 1},
    {"rtVertex2d", 2, BEGIN, sw_vertex2d, 1},
    {"rtVertex3f", 3, BEGIN, sw_vertex3f, 1},
    {"rtVertex3d", 3, BEGIN, sw_vertex3d, 1},
    {"rtVertex2fv", 2, BEGIN, sw_vertex2fv, 1},
    {"rtVertex2dv", 2, BEGIN, sw_vertex2dv, 1},
    {"rtVertex3fv", 3, BEGIN, sw_vertex3fv, 1},
    {"rtVertex3dv", 3, BEGIN, sw_vertex3dv, 1},
    {"rtNormal3f", 3, NONE, sw_normal3f, 0},
    {"rtNormal3fv", 3, BEGIN, sw_normal3fv, 0},
    {"rtTexCoord2f", 2, OBJECT, sw_texcoord2f, 0},
    {"rtTexCoord2fv", 2, NONE, sw_texcoord2fv, 0},
    {"rtColor3f", 3, NONE, sw_color3f, 0},
    {"rtColor3fv", 3, BEGIN, sw_color3fv, 0},
    {"rtColor4f", 4, NONE, sw_color4f, 0},
    {"rtColor4fv", 4, OBJECT, sw_color4fv, 0},
    {"rtLoadMatrixf", 16, NONE, sw_load_matrixf, 0},
    {"rtLoadMatrixd", 16, NONE, sw_load_matrixd, 0},
    {"rtMultMatrixf", 16, NONE, sw_mult_matrixf, 0},
    {"rtMultMatrixd", 16, OBJECT, sw_mult_matrixd, 0},
    {"rtTranslatef", 3, NONE, sw_translatef, 0},
    {"rtTranslated", 3, NONE, sw_translated, 0},
    {"rtRotatef", 4, NONE, sw_rotatef, 0},
    {"rtRotated", 4, OBJECT, sw_rotated, 0},
    {"rtScalef", 3, NONE, sw_scalef, 0},
    {"rtScaled", 3, NONE, sw_scaled, 0},
    {"rtFrustum", 6, NONE, sw_frustum, 0},
    {"rtOrtho", 6, NONE, sw_ortho, 0},
    {"rtMaterialf", 1, NONE, sw_materialf, 0},
    {"rtMaterialfv", 4, BEGIN, sw_materialfv_diffuse, 0},
    {"rtMaterialfv", 1, NONE, sw_materialfv_ior, 0},
    {"rtLightf", 1, NONE, sw_lightf, 0},
    {"rtLightfv", 4, NONE, sw_lightfv_position, 0},
    {"rtLightfv", 4, OBJECT, sw_lightfv_specular, 0},
    {"rtLightModelfv", 4, NONE, sw_light_model, 0},
    {"rtClearColor", 4, NONE, sw_clear_color, 0},
    {"rtTraceRays", 8, NONE, sw_trace, 0},
    {"rtOccludedRays", 8, NONE, sw_occluded, 0},
};

struct snapshot {
    float modelview[16], projection[16], clear[4], ambient[4];
    RTint depth;
};

static void take_snapshot(struct snapshot *s)
{
    rtGetFloatv(RT_MODELVIEW_MATRIX, s->modelview);
    rtGetFloatv(RT_PROJECTION_MATRIX, s->projection);
    rtGetFloatv(RT_COLOR_CLEAR_VALUE, s->clear);
    rtGetFloatv(RT_LIGHT_MODEL_AMBIENT, s->ambient);
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &s->depth);
}

static void run_sweeps(void)
{
    size_t i;
    int arg, b;
    tu_section("NaN and infinity in every float argument");
    /* Non-trivial state, so that "unchanged" is a real comparison. */
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-1, 2, -1, 1, 1, 50);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtTranslatef(0.25f, -0.5f, 0.75f);
    rtRotatef(20, 0, 1, 0);
    rtClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    CHECK_NO_ERR();
    for (i = 0; i < sizeof sweeps / sizeof sweeps[0]; i++) {
        const struct sweep_case *c = &sweeps[i];
        for (arg = 0; arg < c->nargs; arg++) {
            for (b = 0; b < 3; b++) {
                double bad = b == 0 ? tu_nan_d() : b == 1 ? tu_inf_d() : -tu_inf_d();
                struct snapshot before, after;
                RTenum got;
                int ok = 1;
                /* Only NaN is invalid for tmax (+inf is the usual value, -inf
                 * an empty interval); for tmin NaN and -inf (< 0) are, +inf
                 * is an empty interval. */
                if ((c->fn == sw_trace || c->fn == sw_occluded) &&
                    ((arg == 7 && b != 0) || (arg == 6 && b == 1)))
                    continue;
                enter(c->mode);
                if (c->vertex) {
                    rtVertex3f(0, 0, 0);
                    rtVertex3f(1, 0, 0);
                }
                take_snapshot(&before);
                tu_reset_captured();
                rays_written = 0;
                c->fn(arg, bad);
                got = rtGetError();
                take_snapshot(&after);
                ok &= tu_check(got == RT_INVALID_VALUE, __FILE__, __LINE__,
                               "non-finite argument -> RT_INVALID_VALUE");
                ok &= tu_check(tu_message_names(tu_captured_message(), c->entry), __FILE__,
                               __LINE__, "message names the entry point");
                ok &= tu_check(memcmp(&before, &after, sizeof before) == 0, __FILE__, __LINE__,
                               "state unchanged");
                ok &= tu_check(!rays_written, __FILE__, __LINE__, "nothing written");
                if (c->vertex) {
                    /* Two good vertices and a rejected one: no triangle. */
                    RTint tris = -1;
                    rtEnd();
                    rtEndObject();
                    rtGetObjectiv(TU_SCRATCH_OBJECT, RT_OBJECT_TRIANGLES, &tris);
                    ok &= tu_check(tris == 0, __FILE__, __LINE__, "bad vertex not recorded");
                    rtNewObject(TU_SCRATCH_OBJECT);
                    rtBegin(RT_TRIANGLES);
                }
                if (!ok)
                    fprintf(stderr, "    %s argument %d = %g %s: got %s, message \"%s\"\n",
                            c->entry, arg, bad, mode_name(c->mode), tu_error_name(got),
                            tu_captured_message());
                leave(c->mode);
                CHECK_NO_ERR();
            }
        }
    }
    /* Overflow to a non-finite product: RT_INVALID_VALUE, matrix unchanged
     * (a later inverse scale gets back to the identity). */
    {
        double id[16];
        tu_identity(id);
        rtLoadIdentity();
        rtScaled(1e200, 1, 1);
        rtScaled(1e200, 1, 1);
        CHECK_ERR(RT_INVALID_VALUE);
        rtScaled(1e-200, 1, 1);
        CHECK_NO_ERR();
        CHECK_CURRENT_MATRIX(RT_MODELVIEW_MATRIX, id, 1e-6);
        /* A vertex overflowing to infinity under the modelview is rejected. */
        rtLoadIdentity();
        rtNewObject(TU_SCRATCH_OBJECT);
        rtScaled(1e300, 1, 1); /* the list's own matrix (docs/lists.md) */
        rtBegin(RT_TRIANGLES);
        rtVertex3d(0, 0, 0);
        rtVertex3d(0, 1, 0);
        tu_reset_captured();
        rtVertex3d(1e10, 0, 0);
        CHECK_ERR(RT_INVALID_VALUE);
        CHECK_MSG("rtVertex3d");
        rtEnd();
        rtEndObject();
        CHECK_INT(tu_object_triangles(TU_SCRATCH_OBJECT), 0);
        rtLoadIdentity();
        CHECK_NO_ERR();
    }
}

/* ---- 3. first error and callback contract ------------------------------------- */

static int user_calls;
static void *user_seen;
static RTenum user_codes[8];

static void user_callback(RTenum error, const char *message, void *user)
{
    (void)message;
    if (user_calls < 8)
        user_codes[user_calls] = error;
    user_calls++;
    user_seen = user;
}
/* ---- 5. one rule for doubles beyond the float range -------------------------- */

/* docs/arrays.md and docs/dynamic.md: values are stored as float, so a
 * finite RT_DOUBLE beyond the float range counts as infinite.  A draw call
 * reading such a normal, colour or texture coordinate from an array records
 * RT_INVALID_VALUE and stores nothing, as rtUpdateVertices does for the
 * same value. */
static void double_arrays_beyond_float(void)
{
    static const double xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    static const RTuint idx[3] = {0, 1, 2};
    const RTuint name = 77;
    tu_section("draw calls and rtUpdateVertices: doubles beyond the float range");
    for (int which = 0; which < 3; which++)
        for (int indexed = 0; indexed < 2; indexed++) {
            double attr[12] = {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1};
            attr[which == 0 ? 3 : 4] = 1e300; /* element 1, component 0 */
            RTenum array = which == 0 ? RT_NORMAL_ARRAY : which == 1 ? RT_COLOR_ARRAY
                                                                      : RT_TEXTURE_COORD_ARRAY;
            rtNewObject(name);
            rtEnableClientState(RT_VERTEX_ARRAY);
            rtVertexPointer(3, RT_DOUBLE, 0, xyz);
            rtEnableClientState(array);
            if (which == 0)
                rtNormalPointer(RT_DOUBLE, 0, attr);
            else if (which == 1)
                rtColorPointer(4, RT_DOUBLE, 0, attr);
            else
                rtTexCoordPointer(4, RT_DOUBLE, 0, attr);
            CHECK_NO_ERR();
            if (indexed)
                rtDrawElements(RT_TRIANGLES, 3, RT_UNSIGNED_INT, idx);
            else
                rtDrawArrays(RT_TRIANGLES, 0, 3);
            CHECK_ERR(RT_INVALID_VALUE);
            rtDisableClientState(array);
            rtDrawArrays(RT_TRIANGLES, 0, 3); /* the same batch without it */
            CHECK_NO_ERR();
            rtDisableClientState(RT_VERTEX_ARRAY);
            rtEndObject();
            CHECK_NO_ERR();
            /* Only the second batch was stored. */
            CHECK_INT(tu_object_triangles(name), 1);
            RTint vertices = -1;
            rtGetObjectiv(name, RT_OBJECT_VERTICES, &vertices);
            CHECK_INT(vertices, 3);
            rtDeleteObjects(1, &name);
        }
    /* rtUpdateVertices applies the same rule to the same value. */
    CHECK(tu_define_quad(name, 0, 0, 1, 1, 0));
    const double big_normal[3] = {0.0, 0.0, 1e300};
    rtUpdateVertices(name, RT_NORMAL_ARRAY, 0, 1, RT_DOUBLE, 0, big_normal);
    CHECK_ERR(RT_INVALID_VALUE);
    rtDeleteObjects(1, &name);
    CHECK_NO_ERR();
}

/* ---- 6. a singular projection ---------------------------------------------- */

/* docs/frames.md: a singular projection matrix (no inverse, so no primary
 * ray) is not an error; the frame is the clear colour and traces no ray. */
static void singular_projection(void)
{
    static const RTfloat zero[16] = {0};
    const RTuint name = 78;
    float px[4 * 4 * 4];
    tu_section("rtRenderFrame with a singular projection");
    CHECK(tu_define_quad(name, -1, -1, 1, 1, -3));
    rtBeginFrame();
    rtInstantiateObject(name);
    rtViewport(0, 0, 4, 4);
    rtClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    rtMatrixMode(RT_PROJECTION);
    rtPushMatrix();
    rtLoadMatrixf(zero);
    rtMatrixMode(RT_MODELVIEW);
    CHECK_NO_ERR();
    rtRenderFrame();
    CHECK_NO_ERR();
    RTint rays = -1;
    rtGetIntegerv(RT_STAT_RAYS, &rays);
    CHECK_INT(rays, 0);
    rtReadPixels(0, 0, 4, 4, RT_RGBA, RT_FLOAT, px);
    int clear = 1;
    for (int i = 0; i < 16; i++)
        clear &= px[4 * i] == 0.25f && px[4 * i + 1] == 0.5f && px[4 * i + 2] == 0.75f &&
                 px[4 * i + 3] == 1.0f;
    CHECK(clear);
    /* The same frame with the identity projection does trace. */
    rtMatrixMode(RT_PROJECTION);
    rtPopMatrix();
    rtMatrixMode(RT_MODELVIEW);
    rtRenderFrame();
    rtGetIntegerv(RT_STAT_RAYS, &rays);
    CHECK(rays >= 16);
    rtBeginFrame();
    rtViewport(0, 0, 0, 0);
    rtDeleteObjects(1, &name);
    CHECK_NO_ERR();
}


static void first_error_and_callback(void)
{
    int token;
    RTint depth = -1;
    tu_section("first error sticks; callback sees every error");
    rtErrorCallback(user_callback, &token);
    user_calls = 0;
    rtPopMatrix();               /* STACK_UNDERFLOW: stored */
    rtMatrixMode(0x1234);        /* INVALID_ENUM: reported, not stored */
    rtTranslatef(0, tu_nan(), 0); /* INVALID_VALUE: reported, not stored */
    rtEndObject();               /* INVALID_OPERATION: reported, not stored */
    CHECK_INT(user_calls, 4);
    CHECK(user_seen == &token);
    CHECK_INT(user_codes[0], RT_STACK_UNDERFLOW);
    CHECK_INT(user_codes[1], RT_INVALID_ENUM);
    CHECK_INT(user_codes[2], RT_INVALID_VALUE);
    CHECK_INT(user_codes[3], RT_INVALID_OPERATION);
    CHECK_INT(rtGetError(), RT_STACK_UNDERFLOW);
    CHECK_INT(rtGetError(), RT_NO_ERROR);
    /* The next error is stored again. */
    rtMatrixMode(0x1234);
    CHECK_ERR(RT_INVALID_ENUM);
    /* Successful calls do not call the callback. */
    user_calls = 0;
    rtPushMatrix();
    rtPopMatrix();
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    CHECK_INT(depth, 1);
    CHECK_INT(user_calls, 0);
    /* NULL removes the callback; errors are still recorded. */
    rtErrorCallback(NULL, NULL);
    rtPopMatrix();
    CHECK_INT(user_calls, 0);
    CHECK_ERR(RT_STACK_UNDERFLOW);
    /* The callback belongs to the context: a second context does not call it. */
    {
        RTcontext mine = rtGetCurrentContext();
        RTcontext other;
        rtErrorCallback(user_callback, &token);
        other = tu_make_context("threads=1");
        user_calls = 0;
        rtPopMatrix();
        CHECK_INT(user_calls, 0);
        CHECK_ERR(RT_STACK_UNDERFLOW);
        tu_destroy_context(other);
        rtMakeCurrent(mine);
        rtPopMatrix();
        CHECK_INT(user_calls, 1);
        CHECK_ERR(RT_STACK_UNDERFLOW);
    }
    tu_capture_errors();
}

/* ---- 4. TRACELIST_DEBUG ---------------------------------------------------------- */

static int debug_child(void)
{
    RTcontext ctx = rtCreateContext("threads=1");
    int i;
    rtMakeCurrent(ctx);
    for (i = 0; i < 100; i++)
        rtPopMatrix();
    rtMatrixMode(0x1234);
    rtMakeCurrent(NULL);
    rtDestroyContext(ctx);
    return 0;
}

static int count_occurrences(const char *text, const char *word)
{
    int n = 0;
    const char *p = text;
    while ((p = strstr(p, word)) != NULL) {
        n++;
        p += strlen(word);
    }
    return n;
}

static void debug_output(char *self)
{
    int pass;
    tu_section("TRACELIST_DEBUG prints errors, repeats collapsed");
    for (pass = 0; pass < 2; pass++) {
        static char text[4096];
        char *args[3];
        char *no_env[1] = {NULL};
        char *debug_env[2] = {"TRACELIST_DEBUG=1", NULL};
        FILE *out = tmpfile();
        size_t len;
        int status = -1;
        pid_t pid;
        if (!tu_check(out != NULL, __FILE__, __LINE__, "tmpfile()"))
            return;
        args[0] = self;
        args[1] = "--debug-child";
        args[2] = NULL;
        fflush(stdout);
        fflush(stderr);
        pid = fork();
        if (pid == 0) {
            dup2(fileno(out), 2);
            execve(self, args, pass ? debug_env : no_env);
            _exit(127);
        }
        if (!tu_check(pid > 0, __FILE__, __LINE__, "fork()")) {
            fclose(out);
            return;
        }
        waitpid(pid, &status, 0);
        CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
        rewind(out);
        len = fread(text, 1, sizeof text - 1, out);
        text[len] = '\0';
        fclose(out);
        if (pass == 0) {
            if (!CHECK_INT(len, 0))
                fprintf(stderr, "    printed without TRACELIST_DEBUG: \"%s\"\n", text);
        } else {
            int ok = 1;
            ok &= CHECK(count_occurrences(text, "rtMatrixMode") == 1);
            /* 100 identical errors: printed once, then a count. */
            ok &= CHECK(count_occurrences(text, "rtPopMatrix") >= 1);
            ok &= CHECK(count_occurrences(text, "rtPopMatrix") <= 2);
            ok &= CHECK(strstr(text, "99") != NULL || strstr(text, "100") != NULL);
            if (!ok)
                fprintf(stderr, "    TRACELIST_DEBUG=1 output: \"%s\"\n", text);
        }
    }
}

int main(int argc, char **argv)
{
    RTcontext ctx;
    if (argc > 1 && strcmp(argv[1], "--debug-child") == 0)
        return debug_child();
    ctx = tu_make_context("threads=1");
    tu_capture_errors();
    CHECK(tu_define_quad(OBJ, 0, 0, 1, 1, 0));
    names[3] = OBJ;
    run_error_table();
    allowed_inside_objects();
    /* None of the failing calls above deleted or changed OBJ. */
    CHECK(rtIsObject(OBJ) == RT_TRUE);
    CHECK_INT(tu_object_triangles(OBJ), 2);
    run_sweeps();
    double_arrays_beyond_float();
    singular_projection();
    first_error_and_callback();
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
    debug_output(argv[0]);
    return test_summary("errors");
}
