/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glcompat.h - OpenGL 1.x, GLU and GLUT names for Tracelist.
 *
 * A GL 1.x program whose #include <GL/gl.h>, <GL/glu.h> and <GL/glut.h>
 * lines are replaced by #include <rt/glcompat.h> compiles against
 * Tracelist: every GL 1.0/1.1 name (and the GL 1.2 and 1.4 names 1.x
 * programs commonly use), every GLU 1.3 name and every GLUT 3 name is
 * defined here by the renaming rule
 * (glFoo -> rtFoo, gluFoo / glutFoo -> rtuFoo, GL_FOO -> RT_FOO,
 * GLU_FOO / GLUT_FOO -> RTU_FOO, GLfloat -> RTfloat), with GL's
 * signatures.  Each name is one of (docs/glcompat.md lists them):
 *
 *   mapped    a macro to the Tracelist entry point or enum of the same
 *             meaning: #define glNewList rtNewList;
 *   adapted   a static inline function with GL's signature that converts
 *             its arguments as GL does and calls Tracelist (glColor3ub);
 *   no-op     accepted and ignored, for names with no meaning for a ray
 *             tracer (glHint, glDepthFunc, glEnable(GL_DEPTH_TEST));
 *   pending   mapped only when rt.h / rtu.h have the entry point (its
 *             feature's enum is defined); before that a use stops the
 *             compilation with "glFoo: needs ..., not in this Tracelist";
 *   absent    a use stops the compilation with "glFoo: no ..." (glAccum).
 *
 * So a program never compiles into something silently different: what
 * Tracelist cannot do is a compile-time error at the line that asks for
 * it (with GCC and Clang through #pragma GCC error; other compilers see an
 * undeclared rt_glcompat_* identifier).  GL extension names are not
 * defined, so a program's #ifdef GL_EXT_... takes its fallback path.
 *
 * Include it instead of the GL headers, not with them.  C99 and C++.
 */
#ifndef RT_GLCOMPAT_H
#define RT_GLCOMPAT_H

#include <rt/rt.h>
#include <rt/rtu.h>

#if defined(__gl_h_) || defined(__GL_H__) || defined(__glu_h__) || defined(__GLU_H__) || \
    defined(__glut_h__) || defined(__FREEGLUT_STD_H__)
#error "rt/glcompat.h replaces <GL/gl.h>, <GL/glu.h> and <GL/glut.h>: include it instead of them"
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- GL types ----------------------------------------------------------- */
typedef RTenum GLenum;
typedef RTboolean GLboolean;
typedef RTbitfield GLbitfield;
typedef RTbyte GLbyte;
typedef RTshort GLshort;
typedef RTint GLint;
typedef RTsizei GLsizei;
typedef RTubyte GLubyte;
typedef RTushort GLushort;
typedef RTuint GLuint;
typedef RTfloat GLfloat;
typedef RTfloat GLclampf;
typedef RTdouble GLdouble;
typedef RTdouble GLclampd;
typedef void GLvoid;

/* The calling-convention macros programs put in callback casts
 * ((void (APIENTRY *)(void)) ...): empty, as on every non-Windows GL. */
#ifndef APIENTRY
#define APIENTRY
#endif
#ifndef APIENTRYP
#define APIENTRYP APIENTRY *
#endif
#ifndef GLAPIENTRY
#define GLAPIENTRY APIENTRY
#endif
#ifndef GLAPIENTRYP
#define GLAPIENTRYP GLAPIENTRY *
#endif

/* ---- How an unsupported name fails -------------------------------------- */
#define RTGLC_PRAGMA(x) _Pragma(#x)
#if defined(__GNUC__) || defined(__clang__)
#define RTGLC_FAIL(message) RTGLC_PRAGMA(GCC error message)
#else
#define RTGLC_FAIL(message)
#endif
/* A name Tracelist does not have, and one whose entry point another part of
 * Tracelist provides once it is there (see the feature tests below). */
#define RTGLC_ABSENT(name, message) RTGLC_FAIL(message) rt_glcompat_absent_##name
#define RTGLC_PENDING(name, message) RTGLC_FAIL(message) rt_glcompat_pending_##name


/* ---- Adapters: GL variants with GL's signatures over Tracelist calls ----
 * GL accepts many argument types for one call; Tracelist has the float
 * (and some double) forms.  These convert exactly as the GL 1.1 spec,
 * section 2.13 (table 2.6), converts: unsigned integers c to c / (2^b - 1),
 * signed integers to (2c + 1) / (2^b - 1), integer vertices, normals of
 * glNormal3d and texture coordinates as plain values. */
#define RTGLC_UB(c) ((GLfloat)(c) / 255.0f)
#define RTGLC_US(c) ((GLfloat)(c) / 65535.0f)
#define RTGLC_UI(c) ((GLfloat)((GLdouble)(c) / 4294967295.0))
#define RTGLC_B(c) ((2.0f * (GLfloat)(c) + 1.0f) / 255.0f)
#define RTGLC_S(c) ((2.0f * (GLfloat)(c) + 1.0f) / 65535.0f)
#define RTGLC_I(c) ((GLfloat)((2.0 * (GLdouble)(c) + 1.0) / 4294967295.0))

static inline void rtglc_Vertex2i(GLint x, GLint y) { rtVertex2f((GLfloat)x, (GLfloat)y); }
static inline void rtglc_Vertex2s(GLshort x, GLshort y) { rtVertex2f(x, y); }
static inline void rtglc_Vertex3i(GLint x, GLint y, GLint z) { rtVertex3f((GLfloat)x, (GLfloat)y, (GLfloat)z); }
static inline void rtglc_Vertex3s(GLshort x, GLshort y, GLshort z) { rtVertex3f(x, y, z); }
static inline void rtglc_Vertex2iv(const GLint *v) { rtglc_Vertex2i(v[0], v[1]); }
static inline void rtglc_Vertex2sv(const GLshort *v) { rtglc_Vertex2s(v[0], v[1]); }
static inline void rtglc_Vertex3iv(const GLint *v) { rtglc_Vertex3i(v[0], v[1], v[2]); }
static inline void rtglc_Vertex3sv(const GLshort *v) { rtglc_Vertex3s(v[0], v[1], v[2]); }

static inline void rtglc_Normal3d(GLdouble x, GLdouble y, GLdouble z) { rtNormal3f((GLfloat)x, (GLfloat)y, (GLfloat)z); }
static inline void rtglc_Normal3b(GLbyte x, GLbyte y, GLbyte z) { rtNormal3f(RTGLC_B(x), RTGLC_B(y), RTGLC_B(z)); }
static inline void rtglc_Normal3s(GLshort x, GLshort y, GLshort z) { rtNormal3f(RTGLC_S(x), RTGLC_S(y), RTGLC_S(z)); }
static inline void rtglc_Normal3i(GLint x, GLint y, GLint z) { rtNormal3f(RTGLC_I(x), RTGLC_I(y), RTGLC_I(z)); }
static inline void rtglc_Normal3dv(const GLdouble *v) { rtglc_Normal3d(v[0], v[1], v[2]); }
static inline void rtglc_Normal3bv(const GLbyte *v) { rtglc_Normal3b(v[0], v[1], v[2]); }
static inline void rtglc_Normal3sv(const GLshort *v) { rtglc_Normal3s(v[0], v[1], v[2]); }
static inline void rtglc_Normal3iv(const GLint *v) { rtglc_Normal3i(v[0], v[1], v[2]); }

static inline void rtglc_Color3d(GLdouble r, GLdouble g, GLdouble b) { rtColor3f((GLfloat)r, (GLfloat)g, (GLfloat)b); }
static inline void rtglc_Color4d(GLdouble r, GLdouble g, GLdouble b, GLdouble a) { rtColor4f((GLfloat)r, (GLfloat)g, (GLfloat)b, (GLfloat)a); }
static inline void rtglc_Color3ub(GLubyte r, GLubyte g, GLubyte b) { rtColor3f(RTGLC_UB(r), RTGLC_UB(g), RTGLC_UB(b)); }
static inline void rtglc_Color4ub(GLubyte r, GLubyte g, GLubyte b, GLubyte a) { rtColor4f(RTGLC_UB(r), RTGLC_UB(g), RTGLC_UB(b), RTGLC_UB(a)); }
static inline void rtglc_Color3us(GLushort r, GLushort g, GLushort b) { rtColor3f(RTGLC_US(r), RTGLC_US(g), RTGLC_US(b)); }
static inline void rtglc_Color4us(GLushort r, GLushort g, GLushort b, GLushort a) { rtColor4f(RTGLC_US(r), RTGLC_US(g), RTGLC_US(b), RTGLC_US(a)); }
static inline void rtglc_Color3ui(GLuint r, GLuint g, GLuint b) { rtColor3f(RTGLC_UI(r), RTGLC_UI(g), RTGLC_UI(b)); }
static inline void rtglc_Color4ui(GLuint r, GLuint g, GLuint b, GLuint a) { rtColor4f(RTGLC_UI(r), RTGLC_UI(g), RTGLC_UI(b), RTGLC_UI(a)); }
static inline void rtglc_Color3b(GLbyte r, GLbyte g, GLbyte b) { rtColor3f(RTGLC_B(r), RTGLC_B(g), RTGLC_B(b)); }
static inline void rtglc_Color4b(GLbyte r, GLbyte g, GLbyte b, GLbyte a) { rtColor4f(RTGLC_B(r), RTGLC_B(g), RTGLC_B(b), RTGLC_B(a)); }
static inline void rtglc_Color3s(GLshort r, GLshort g, GLshort b) { rtColor3f(RTGLC_S(r), RTGLC_S(g), RTGLC_S(b)); }
static inline void rtglc_Color4s(GLshort r, GLshort g, GLshort b, GLshort a) { rtColor4f(RTGLC_S(r), RTGLC_S(g), RTGLC_S(b), RTGLC_S(a)); }
static inline void rtglc_Color3i(GLint r, GLint g, GLint b) { rtColor3f(RTGLC_I(r), RTGLC_I(g), RTGLC_I(b)); }
static inline void rtglc_Color4i(GLint r, GLint g, GLint b, GLint a) { rtColor4f(RTGLC_I(r), RTGLC_I(g), RTGLC_I(b), RTGLC_I(a)); }
static inline void rtglc_Color3dv(const GLdouble *v) { rtglc_Color3d(v[0], v[1], v[2]); }
static inline void rtglc_Color4dv(const GLdouble *v) { rtglc_Color4d(v[0], v[1], v[2], v[3]); }
static inline void rtglc_Color3ubv(const GLubyte *v) { rtglc_Color3ub(v[0], v[1], v[2]); }
static inline void rtglc_Color4ubv(const GLubyte *v) { rtglc_Color4ub(v[0], v[1], v[2], v[3]); }
static inline void rtglc_Color3usv(const GLushort *v) { rtglc_Color3us(v[0], v[1], v[2]); }
static inline void rtglc_Color4usv(const GLushort *v) { rtglc_Color4us(v[0], v[1], v[2], v[3]); }
static inline void rtglc_Color3uiv(const GLuint *v) { rtglc_Color3ui(v[0], v[1], v[2]); }
static inline void rtglc_Color4uiv(const GLuint *v) { rtglc_Color4ui(v[0], v[1], v[2], v[3]); }
static inline void rtglc_Color3bv(const GLbyte *v) { rtglc_Color3b(v[0], v[1], v[2]); }
static inline void rtglc_Color4bv(const GLbyte *v) { rtglc_Color4b(v[0], v[1], v[2], v[3]); }
static inline void rtglc_Color3sv(const GLshort *v) { rtglc_Color3s(v[0], v[1], v[2]); }
static inline void rtglc_Color4sv(const GLshort *v) { rtglc_Color4s(v[0], v[1], v[2], v[3]); }
static inline void rtglc_Color3iv(const GLint *v) { rtglc_Color3i(v[0], v[1], v[2]); }
static inline void rtglc_Color4iv(const GLint *v) { rtglc_Color4i(v[0], v[1], v[2], v[3]); }

/* glTexCoord1: t = 0; glTexCoord3: r is unused by 2D textures (no texture
 * matrix), as in GL with a 2D texture and the identity texture matrix. */
static inline void rtglc_TexCoord1f(GLfloat s) { rtTexCoord2f(s, 0.0f); }
static inline void rtglc_TexCoord1d(GLdouble s) { rtTexCoord2f((GLfloat)s, 0.0f); }
static inline void rtglc_TexCoord1i(GLint s) { rtTexCoord2f((GLfloat)s, 0.0f); }
static inline void rtglc_TexCoord1s(GLshort s) { rtTexCoord2f(s, 0.0f); }
static inline void rtglc_TexCoord2d(GLdouble s, GLdouble t) { rtTexCoord2f((GLfloat)s, (GLfloat)t); }
static inline void rtglc_TexCoord2i(GLint s, GLint t) { rtTexCoord2f((GLfloat)s, (GLfloat)t); }
static inline void rtglc_TexCoord2s(GLshort s, GLshort t) { rtTexCoord2f(s, t); }
static inline void rtglc_TexCoord3f(GLfloat s, GLfloat t, GLfloat r) { (void)r; rtTexCoord2f(s, t); }
static inline void rtglc_TexCoord3d(GLdouble s, GLdouble t, GLdouble r) { (void)r; rtTexCoord2f((GLfloat)s, (GLfloat)t); }
static inline void rtglc_TexCoord3i(GLint s, GLint t, GLint r) { (void)r; rtTexCoord2f((GLfloat)s, (GLfloat)t); }
static inline void rtglc_TexCoord3s(GLshort s, GLshort t, GLshort r) { (void)r; rtTexCoord2f(s, t); }
static inline void rtglc_TexCoord1fv(const GLfloat *v) { rtglc_TexCoord1f(v[0]); }
static inline void rtglc_TexCoord1dv(const GLdouble *v) { rtglc_TexCoord1d(v[0]); }
static inline void rtglc_TexCoord1iv(const GLint *v) { rtglc_TexCoord1i(v[0]); }
static inline void rtglc_TexCoord1sv(const GLshort *v) { rtglc_TexCoord1s(v[0]); }
static inline void rtglc_TexCoord2dv(const GLdouble *v) { rtglc_TexCoord2d(v[0], v[1]); }
static inline void rtglc_TexCoord2iv(const GLint *v) { rtglc_TexCoord2i(v[0], v[1]); }
static inline void rtglc_TexCoord2sv(const GLshort *v) { rtglc_TexCoord2s(v[0], v[1]); }
static inline void rtglc_TexCoord3fv(const GLfloat *v) { rtTexCoord2f(v[0], v[1]); }
static inline void rtglc_TexCoord3dv(const GLdouble *v) { rtglc_TexCoord2d(v[0], v[1]); }
static inline void rtglc_TexCoord3iv(const GLint *v) { rtglc_TexCoord2i(v[0], v[1]); }
static inline void rtglc_TexCoord3sv(const GLshort *v) { rtglc_TexCoord2s(v[0], v[1]); }

/* glRect: "exactly equivalent to" a GL_POLYGON of its four corners in
 * this order (GL 1.1, section 2.10). */
static inline void rtglc_Rectf(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2)
{
    rtBegin(RT_POLYGON);
    rtVertex2f(x1, y1);
    rtVertex2f(x2, y1);
    rtVertex2f(x2, y2);
    rtVertex2f(x1, y2);
    rtEnd();
}
static inline void rtglc_Rectd(GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2) { rtglc_Rectf((GLfloat)x1, (GLfloat)y1, (GLfloat)x2, (GLfloat)y2); }
static inline void rtglc_Recti(GLint x1, GLint y1, GLint x2, GLint y2) { rtglc_Rectf((GLfloat)x1, (GLfloat)y1, (GLfloat)x2, (GLfloat)y2); }
static inline void rtglc_Rects(GLshort x1, GLshort y1, GLshort x2, GLshort y2) { rtglc_Rectf(x1, y1, x2, y2); }
static inline void rtglc_Rectfv(const GLfloat *a, const GLfloat *b) { rtglc_Rectf(a[0], a[1], b[0], b[1]); }
static inline void rtglc_Rectdv(const GLdouble *a, const GLdouble *b) { rtglc_Rectd(a[0], a[1], b[0], b[1]); }
static inline void rtglc_Rectiv(const GLint *a, const GLint *b) { rtglc_Recti(a[0], a[1], b[0], b[1]); }
static inline void rtglc_Rectsv(const GLshort *a, const GLshort *b) { rtglc_Rects(a[0], a[1], b[0], b[1]); }

/* Capabilities with no meaning for a ray tracer (nearest hit is the depth
 * test; no dithering or polygon offset) that the core does not know yet:
 * accepted and ignored, as GL accepts them.  Every other capability goes
 * to rtEnable/rtDisable, which records RT_INVALID_ENUM for one it does
 * not have (a run-time error, never a silent difference). */
static inline int rtglc_ignored_capability(GLenum cap)
{
    switch (cap) {
#ifndef RT_DEPTH_TEST
    case 0x0B71: /* GL_DEPTH_TEST */
#endif
#ifndef RT_DITHER
    case 0x0BD0: /* GL_DITHER */
#endif
#ifndef RT_POINT_SMOOTH
    case 0x0B10: /* GL_POINT_SMOOTH */
#endif
#ifndef RT_LINE_SMOOTH
    case 0x0B20: /* GL_LINE_SMOOTH */
#endif
#ifndef RT_POLYGON_SMOOTH
    case 0x0B41: /* GL_POLYGON_SMOOTH */
#endif
#ifndef RT_POLYGON_OFFSET_FILL
    case 0x8037: /* GL_POLYGON_OFFSET_FILL */
#endif
#ifndef RT_POLYGON_OFFSET_LINE
    case 0x2A02: /* GL_POLYGON_OFFSET_LINE */
#endif
#ifndef RT_POLYGON_OFFSET_POINT
    case 0x2A01: /* GL_POLYGON_OFFSET_POINT */
#endif
        return 1;
    default:
        return 0;
    }
}
static inline void rtglc_Enable(GLenum cap)
{
    if (!rtglc_ignored_capability(cap))
        rtEnable(cap);
}
static inline void rtglc_Disable(GLenum cap)
{
    if (!rtglc_ignored_capability(cap))
        rtDisable(cap);
}

/* glGetString, gluErrorString: GL's const GLubyte * return type. */
static inline const GLubyte *rtglc_GetString(GLenum name) { return (const GLubyte *)rtGetString(name); }
static inline const GLubyte *rtglc_uErrorString(GLenum error) { return (const GLubyte *)rtuErrorString(error); }
static inline const GLubyte *rtglc_uGetString(GLenum name)
{
    /* GLU_VERSION, GLU_EXTENSIONS: the GLU subset rtu implements. */
    return (const GLubyte *)(name == 100800 ? "1.3 Tracelist rtu" : name == 100801 ? "" : (const char *)0);
}

/* How many values a GL 1.1 query returns (GL 1.1, section 6.2, tables
 * 6.4-6.26), for glGetDoublev and glGetBooleanv, which go through the
 * float / integer queries and must not write more than GL would. */
static inline int rtglc_query_count(GLenum pname)
{
    switch (pname) {
    case 0x0BA6: case 0x0BA7: case 0x0BA8: /* MODELVIEW, PROJECTION, TEXTURE_MATRIX */
        return 16;
    case 0x0B00: case 0x0B03: case 0x0B04: case 0x0B06: case 0x0B07: /* CURRENT_COLOR, _TEXTURE_COORDS, _RASTER_COLOR, _RASTER_TEXTURE_COORDS, _RASTER_POSITION */
    case 0x0B53: case 0x0B66: case 0x0BA2: case 0x0C10: case 0x0C22: case 0x0C23: case 0x0B80: /* LIGHT_MODEL_AMBIENT FOG_COLOR VIEWPORT SCISSOR_BOX COLOR_CLEAR_VALUE COLOR_WRITEMASK ACCUM_CLEAR_VALUE */
        return 4;
    case 0x0B02: /* CURRENT_NORMAL */
        return 3;
    case 0x0B70: case 0x0D3A: case 0x0B12: case 0x0B22: case 0x0B40: /* DEPTH_RANGE MAX_VIEWPORT_DIMS POINT_SIZE_RANGE LINE_WIDTH_RANGE POLYGON_MODE */
        return 2;
    default:
        return 1;
    }
}
static inline void rtglc_GetDoublev(GLenum pname, GLdouble *params)
{
    GLfloat f[16];
    int i, n = rtglc_query_count(pname);
    for (i = 0; i < 16; i++)
        f[i] = 0.0f;
    rtGetFloatv(pname, f);
    for (i = 0; i < n; i++)
        params[i] = f[i];
}
static inline void rtglc_GetBooleanv(GLenum pname, GLboolean *params)
{
    GLint v[16];
    int i, n = rtglc_query_count(pname);
    for (i = 0; i < 16; i++)
        v[i] = 0;
    rtGetIntegerv(pname, v);
    for (i = 0; i < n; i++)
        params[i] = v[i] != 0 ? RT_TRUE : RT_FALSE;
}

/* Integer light and material parameters: colours map linearly so that the
 * largest integer is 1.0, the others (position, direction, exponents,
 * cut-off, attenuation, shininess) convert as they are (GL 1.1, section
 * 2.13.2). */
static inline int rtglc_is_colour_parameter(GLenum pname)
{
    return pname == 0x1200 || pname == 0x1201 || pname == 0x1202 || pname == 0x1600 ||
           pname == 0x1602 || pname == 0x0B53;
}
static inline int rtglc_parameter_count(GLenum pname)
{
    if (rtglc_is_colour_parameter(pname) || pname == 0x1203) /* ..., POSITION */
        return 4;
    return pname == 0x1204 ? 3 : 1; /* SPOT_DIRECTION */
}
static inline void rtglc_int_parameters(GLenum pname, const GLint *in, GLfloat *out)
{
    int i, n = rtglc_parameter_count(pname);
    for (i = 0; i < n; i++)
        out[i] = rtglc_is_colour_parameter(pname) ? (GLfloat)((GLdouble)in[i] / 2147483647.0)
                                                  : (GLfloat)in[i];
}
static inline void rtglc_Lighti(GLenum light, GLenum pname, GLint param) { rtLightf(light, pname, (GLfloat)param); }
static inline void rtglc_Lightiv(GLenum light, GLenum pname, const GLint *params)
{
    GLfloat f[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    rtglc_int_parameters(pname, params, f);
    rtLightfv(light, pname, f);
}
static inline void rtglc_Materiali(GLenum face, GLenum pname, GLint param) { rtMaterialf(face, pname, (GLfloat)param); }
static inline void rtglc_Materialiv(GLenum face, GLenum pname, const GLint *params)
{
    GLfloat f[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    rtglc_int_parameters(pname, params, f);
    rtMaterialfv(face, pname, f);
}
static inline void rtglc_LightModeliv(GLenum pname, const GLint *params)
{
    GLfloat f[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    rtglc_int_parameters(pname, params, f);
    rtLightModelfv(pname, f);
}

/* Texture parameters are all scalar enums or integers in Tracelist; the
 * vector one (GL_TEXTURE_BORDER_COLOR) reaches rtTexParameteri, which
 * records RT_INVALID_ENUM for it. */
static inline void rtglc_TexParameterf(GLenum target, GLenum pname, GLfloat param) { rtTexParameteri(target, pname, (GLint)param); }
static inline void rtglc_TexParameterfv(GLenum target, GLenum pname, const GLfloat *params) { rtTexParameteri(target, pname, (GLint)params[0]); }
static inline void rtglc_TexParameteriv(GLenum target, GLenum pname, const GLint *params) { rtTexParameteri(target, pname, params[0]); }

/* gluBuild2DMipmaps: Tracelist makes the mipmap levels from level 0 (as
 * GL_GENERATE_MIPMAP does), so level 0 is the whole call.  GLU first
 * scales the image to powers of two; Tracelist textures take any size. */
static inline GLint rtglc_uBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width,
                                          GLsizei height, GLenum format, GLenum type,
                                          const void *data)
{
    rtTexImage2D(target, 0, internalFormat, width, height, 0, format, type, data);
    return 0;
}

/* ---- GL functions: the same call under the Tracelist name ------------- */
#define glClearColor rtClearColor
#define glIsEnabled rtIsEnabled
#define glEnableClientState rtEnableClientState
#define glDisableClientState rtDisableClientState
#define glGetFloatv rtGetFloatv
#define glGetIntegerv rtGetIntegerv
#define glGetError rtGetError
#define glFinish rtFinish
#define glMatrixMode rtMatrixMode
#define glOrtho rtOrtho
#define glFrustum rtFrustum
#define glViewport rtViewport
#define glPushMatrix rtPushMatrix
#define glPopMatrix rtPopMatrix
#define glLoadIdentity rtLoadIdentity
#define glLoadMatrixd rtLoadMatrixd
#define glLoadMatrixf rtLoadMatrixf
#define glMultMatrixd rtMultMatrixd
#define glMultMatrixf rtMultMatrixf
#define glRotated rtRotated
#define glRotatef rtRotatef
#define glScaled rtScaled
#define glScalef rtScalef
#define glTranslated rtTranslated
#define glTranslatef rtTranslatef
#define glBegin rtBegin
#define glEnd rtEnd
#define glVertex2d rtVertex2d
#define glVertex2f rtVertex2f
#define glVertex3d rtVertex3d
#define glVertex3f rtVertex3f
#define glVertex2dv rtVertex2dv
#define glVertex2fv rtVertex2fv
#define glVertex3dv rtVertex3dv
#define glVertex3fv rtVertex3fv
#define glNormal3f rtNormal3f
#define glNormal3fv rtNormal3fv
#define glColor3f rtColor3f
#define glColor4f rtColor4f
#define glColor3fv rtColor3fv
#define glColor4fv rtColor4fv
#define glTexCoord2f rtTexCoord2f
#define glTexCoord2fv rtTexCoord2fv
#define glVertexPointer rtVertexPointer
#define glNormalPointer rtNormalPointer
#define glColorPointer rtColorPointer
#define glTexCoordPointer rtTexCoordPointer
#define glDrawArrays rtDrawArrays
#define glDrawElements rtDrawElements
#define glShadeModel rtShadeModel
#define glLightf rtLightf
#define glLightfv rtLightfv
#define glLightModelfv rtLightModelfv
#define glMaterialf rtMaterialf
#define glMaterialfv rtMaterialfv
#define glReadPixels rtReadPixels
#define glTexParameteri rtTexParameteri
#define glTexImage2D rtTexImage2D
#define glGenTextures rtGenTextures
#define glDeleteTextures rtDeleteTextures
#define glBindTexture rtBindTexture
#define glIsTexture rtIsTexture

/* ---- GL functions through the adapters above ------------------------- */
#define glEnable rtglc_Enable
#define glDisable rtglc_Disable
#define glGetBooleanv rtglc_GetBooleanv
#define glGetDoublev rtglc_GetDoublev
#define glGetString rtglc_GetString
#define glVertex2i rtglc_Vertex2i
#define glVertex2s rtglc_Vertex2s
#define glVertex3i rtglc_Vertex3i
#define glVertex3s rtglc_Vertex3s
#define glVertex2iv rtglc_Vertex2iv
#define glVertex2sv rtglc_Vertex2sv
#define glVertex3iv rtglc_Vertex3iv
#define glVertex3sv rtglc_Vertex3sv
#define glNormal3b rtglc_Normal3b
#define glNormal3d rtglc_Normal3d
#define glNormal3i rtglc_Normal3i
#define glNormal3s rtglc_Normal3s
#define glNormal3bv rtglc_Normal3bv
#define glNormal3dv rtglc_Normal3dv
#define glNormal3iv rtglc_Normal3iv
#define glNormal3sv rtglc_Normal3sv
#define glColor3b rtglc_Color3b
#define glColor3d rtglc_Color3d
#define glColor3i rtglc_Color3i
#define glColor3s rtglc_Color3s
#define glColor3ub rtglc_Color3ub
#define glColor3ui rtglc_Color3ui
#define glColor3us rtglc_Color3us
#define glColor4b rtglc_Color4b
#define glColor4d rtglc_Color4d
#define glColor4i rtglc_Color4i
#define glColor4s rtglc_Color4s
#define glColor4ub rtglc_Color4ub
#define glColor4ui rtglc_Color4ui
#define glColor4us rtglc_Color4us
#define glColor3bv rtglc_Color3bv
#define glColor3dv rtglc_Color3dv
#define glColor3iv rtglc_Color3iv
#define glColor3sv rtglc_Color3sv
#define glColor3ubv rtglc_Color3ubv
#define glColor3uiv rtglc_Color3uiv
#define glColor3usv rtglc_Color3usv
#define glColor4bv rtglc_Color4bv
#define glColor4dv rtglc_Color4dv
#define glColor4iv rtglc_Color4iv
#define glColor4sv rtglc_Color4sv
#define glColor4ubv rtglc_Color4ubv
#define glColor4uiv rtglc_Color4uiv
#define glColor4usv rtglc_Color4usv
#define glTexCoord1d rtglc_TexCoord1d
#define glTexCoord1f rtglc_TexCoord1f
#define glTexCoord1i rtglc_TexCoord1i
#define glTexCoord1s rtglc_TexCoord1s
#define glTexCoord2d rtglc_TexCoord2d
#define glTexCoord2i rtglc_TexCoord2i
#define glTexCoord2s rtglc_TexCoord2s
#define glTexCoord3d rtglc_TexCoord3d
#define glTexCoord3f rtglc_TexCoord3f
#define glTexCoord3i rtglc_TexCoord3i
#define glTexCoord3s rtglc_TexCoord3s
#define glTexCoord1dv rtglc_TexCoord1dv
#define glTexCoord1fv rtglc_TexCoord1fv
#define glTexCoord1iv rtglc_TexCoord1iv
#define glTexCoord1sv rtglc_TexCoord1sv
#define glTexCoord2dv rtglc_TexCoord2dv
#define glTexCoord2iv rtglc_TexCoord2iv
#define glTexCoord2sv rtglc_TexCoord2sv
#define glTexCoord3dv rtglc_TexCoord3dv
#define glTexCoord3fv rtglc_TexCoord3fv
#define glTexCoord3iv rtglc_TexCoord3iv
#define glTexCoord3sv rtglc_TexCoord3sv
#define glRectd rtglc_Rectd
#define glRectf rtglc_Rectf
#define glRecti rtglc_Recti
#define glRects rtglc_Rects
#define glRectdv rtglc_Rectdv
#define glRectfv rtglc_Rectfv
#define glRectiv rtglc_Rectiv
#define glRectsv rtglc_Rectsv
#define glLighti rtglc_Lighti
#define glLightiv rtglc_Lightiv
#define glLightModeliv rtglc_LightModeliv
#define glMateriali rtglc_Materiali
#define glMaterialiv rtglc_Materialiv
#define glTexParameterf rtglc_TexParameterf
#define glTexParameterfv rtglc_TexParameterfv
#define glTexParameteriv rtglc_TexParameteriv

/* ---- GL functions with no meaning for a ray tracer: accepted no-ops ----
 * The core's entry point when it has one (it validates the enums as GL
 * does), else an inline function with GL's signature that does nothing. */
static inline void rtglc_PolygonOffset(GLfloat factor, GLfloat units) { (void)factor; (void)units; }
static inline void rtglc_EdgeFlag(GLboolean flag) { (void)flag; }
static inline void rtglc_EdgeFlagv(const GLboolean *flag) { (void)flag; }
static inline void rtglc_DrawBuffer(GLenum mode) { (void)mode; }
static inline void rtglc_ReadBuffer(GLenum mode) { (void)mode; }
static inline void rtglc_Hint(GLenum target, GLenum mode) { (void)target; (void)mode; }
static inline void rtglc_ClearDepth(GLclampd depth) { (void)depth; }
static inline void rtglc_DepthFunc(GLenum func) { (void)func; }
static inline void rtglc_DepthMask(GLboolean flag) { (void)flag; }
static inline void rtglc_DepthRange(GLclampd zNear, GLclampd zFar) { (void)zNear; (void)zFar; }
static inline void rtglc_ClearStencil(GLint s) { (void)s; }
static inline void rtglc_PrioritizeTextures(GLsizei n, const GLuint *textures, const GLclampf *priorities) { (void)n; (void)textures; (void)priorities; }
#ifdef RT_POLYGON_OFFSET_FILL
#define glPolygonOffset rtPolygonOffset
#else
#define glPolygonOffset rtglc_PolygonOffset
#endif
#define glEdgeFlag rtglc_EdgeFlag
#define glEdgeFlagv rtglc_EdgeFlagv
#ifdef RT_FRONT_LEFT
#define glDrawBuffer rtDrawBuffer
#else
#define glDrawBuffer rtglc_DrawBuffer
#endif
#ifdef RT_FRONT_LEFT
#define glReadBuffer rtReadBuffer
#else
#define glReadBuffer rtglc_ReadBuffer
#endif
#ifdef RT_NICEST
#define glHint rtHint
#else
#define glHint rtglc_Hint
#endif
#ifdef RT_LEQUAL
#define glClearDepth rtClearDepth
#else
#define glClearDepth rtglc_ClearDepth
#endif
#ifdef RT_LEQUAL
#define glDepthFunc rtDepthFunc
#else
#define glDepthFunc rtglc_DepthFunc
#endif
#ifdef RT_DEPTH_WRITEMASK
#define glDepthMask rtDepthMask
#else
#define glDepthMask rtglc_DepthMask
#endif
#ifdef RT_LEQUAL
#define glDepthRange rtDepthRange
#else
#define glDepthRange rtglc_DepthRange
#endif
#define glPixelStoref rtPixelStoref
#define glPixelStorei rtPixelStorei
#define glClearStencil rtglc_ClearStencil
#define glPrioritizeTextures rtglc_PrioritizeTextures
/* GL_EXT_compiled_vertex_array: locking the arrays is only a promise. */
#define GL_EXT_compiled_vertex_array 1
static inline void rtglc_LockArraysEXT(GLint first, GLsizei count) { (void)first; (void)count; }
static inline void rtglc_UnlockArraysEXT(void) { }
#ifdef RT_LEQUAL
#define glLockArraysEXT rtLockArraysEXT
#define glUnlockArraysEXT rtUnlockArraysEXT
#else
#define glLockArraysEXT rtglc_LockArraysEXT
#define glUnlockArraysEXT rtglc_UnlockArraysEXT
#endif

/* ---- GL functions whose Tracelist entry point comes with a feature -----
 * A feature is present when rt.h / rtu.h define the enum named here; a
 * program may also define RT_GLCOMPAT_HAVE_<FEATURE> itself.  Without it
 * a use stops the compilation with a message naming the call. */
#if !defined(RT_GLCOMPAT_HAVE_LISTS) && (defined(RT_COMPILE))
#define RT_GLCOMPAT_HAVE_LISTS 1
#endif
#ifdef RT_GLCOMPAT_HAVE_LISTS
#define glNewList rtNewList
#define glEndList rtEndList
#define glCallList rtCallList
#define glCallLists rtCallLists
#define glListBase rtListBase
#define glGenLists rtGenLists
#define glDeleteLists rtDeleteLists
#define glIsList rtIsList
#define glFlush rtFlush
#define glArrayElement rtArrayElement
#else
#define glNewList RTGLC_PENDING(glNewList, "glNewList: needs the GL-named display-list calls (rtNewList ... rtIsList, rtFlush, rtArrayElement), not in this Tracelist (docs/glcompat.md)")
#define glEndList RTGLC_PENDING(glEndList, "glEndList: needs the GL-named display-list calls (rtNewList ... rtIsList, rtFlush, rtArrayElement), not in this Tracelist (docs/glcompat.md)")
#define glCallList RTGLC_PENDING(glCallList, "glCallList: needs the GL-named display-list calls (rtNewList ... rtIsList, rtFlush, rtArrayElement), not in this Tracelist (docs/glcompat.md)")
#define glCallLists RTGLC_PENDING(glCallLists, "glCallLists: needs the GL-named display-list calls (rtNewList ... rtIsList, rtFlush, rtArrayElement), not in this Tracelist (docs/glcompat.md)")
#define glListBase RTGLC_PENDING(glListBase, "glListBase: needs the GL-named display-list calls (rtNewList ... rtIsList, rtFlush, rtArrayElement), not in this Tracelist (docs/glcompat.md)")
#define glGenLists RTGLC_PENDING(glGenLists, "glGenLists: needs the GL-named display-list calls (rtNewList ... rtIsList, rtFlush, rtArrayElement), not in this Tracelist (docs/glcompat.md)")
#define glDeleteLists RTGLC_PENDING(glDeleteLists, "glDeleteLists: needs the GL-named display-list calls (rtNewList ... rtIsList, rtFlush, rtArrayElement), not in this Tracelist (docs/glcompat.md)")
#define glIsList RTGLC_PENDING(glIsList, "glIsList: needs the GL-named display-list calls (rtNewList ... rtIsList, rtFlush, rtArrayElement), not in this Tracelist (docs/glcompat.md)")
#define glFlush RTGLC_PENDING(glFlush, "glFlush: needs the GL-named display-list calls (rtNewList ... rtIsList, rtFlush, rtArrayElement), not in this Tracelist (docs/glcompat.md)")
#define glArrayElement RTGLC_PENDING(glArrayElement, "glArrayElement: needs the GL-named display-list calls (rtNewList ... rtIsList, rtFlush, rtArrayElement), not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_CLEAR) && (defined(RT_COLOR_BUFFER_BIT))
#define RT_GLCOMPAT_HAVE_CLEAR 1
#endif
#ifdef RT_GLCOMPAT_HAVE_CLEAR
#define glClear rtClear
#else
#define glClear RTGLC_PENDING(glClear, "glClear: needs rtClear, not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_LIGHT_MODEL) && (defined(RT_LIGHT_MODEL_TWO_SIDE))
#define RT_GLCOMPAT_HAVE_LIGHT_MODEL 1
#endif
#ifdef RT_GLCOMPAT_HAVE_LIGHT_MODEL
#define glLightModelf rtLightModelf
#define glLightModeli rtLightModeli
#define glColorMaterial rtColorMaterial
#define glGetMaterialfv rtGetMaterialfv
#define glGetLightfv rtGetLightfv
#else
#define glLightModelf RTGLC_PENDING(glLightModelf, "glLightModelf: needs GL lighting state (rtLightModelf/i, rtColorMaterial), not in this Tracelist (docs/glcompat.md)")
#define glLightModeli RTGLC_PENDING(glLightModeli, "glLightModeli: needs GL lighting state (rtLightModelf/i, rtColorMaterial), not in this Tracelist (docs/glcompat.md)")
#define glColorMaterial RTGLC_PENDING(glColorMaterial, "glColorMaterial: needs GL lighting state (rtLightModelf/i, rtColorMaterial), not in this Tracelist (docs/glcompat.md)")
#define glGetMaterialfv RTGLC_PENDING(glGetMaterialfv, "glGetMaterialfv: needs GL lighting state (rtLightModelf/i, rtColorMaterial), not in this Tracelist (docs/glcompat.md)")
#define glGetLightfv RTGLC_PENDING(glGetLightfv, "glGetLightfv: needs GL lighting state (rtLightModelf/i, rtColorMaterial), not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_CULL_FACE) && (defined(RT_CULL_FACE))
#define RT_GLCOMPAT_HAVE_CULL_FACE 1
#endif
#ifdef RT_GLCOMPAT_HAVE_CULL_FACE
#define glCullFace rtCullFace
#else
#define glCullFace RTGLC_PENDING(glCullFace, "glCullFace: needs rtCullFace, not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_FRONT_FACE) && (defined(RT_CCW))
#define RT_GLCOMPAT_HAVE_FRONT_FACE 1
#endif
#ifdef RT_GLCOMPAT_HAVE_FRONT_FACE
#define glFrontFace rtFrontFace
#else
#define glFrontFace RTGLC_PENDING(glFrontFace, "glFrontFace: needs rtFrontFace, not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_FOG) && (defined(RT_FOG_MODE))
#define RT_GLCOMPAT_HAVE_FOG 1
#endif
#ifdef RT_GLCOMPAT_HAVE_FOG
#define glFogf rtFogf
#define glFogi rtFogi
#define glFogfv rtFogfv
static inline void rtglc_Fogiv(GLenum pname, const GLint *params)
{
    GLfloat f[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    int i;
    for (i = 0; i < (pname == RT_FOG_COLOR ? 4 : 1); i++)
        f[i] = pname == RT_FOG_COLOR ? (GLfloat)((GLdouble)params[i] / 2147483647.0) : (GLfloat)params[i];
    rtFogfv(pname, f);
}
#define glFogiv rtglc_Fogiv
#else
#define glFogf RTGLC_PENDING(glFogf, "glFogf: needs fog (rtFog*), not in this Tracelist (docs/glcompat.md)")
#define glFogi RTGLC_PENDING(glFogi, "glFogi: needs fog (rtFog*), not in this Tracelist (docs/glcompat.md)")
#define glFogfv RTGLC_PENDING(glFogfv, "glFogfv: needs fog (rtFog*), not in this Tracelist (docs/glcompat.md)")
#define glFogiv RTGLC_PENDING(glFogiv, "glFogiv: needs fog (rtFog*), not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_TEXGEN) && (defined(RT_TEXTURE_GEN_MODE))
#define RT_GLCOMPAT_HAVE_TEXGEN 1
#endif
#ifdef RT_GLCOMPAT_HAVE_TEXGEN
static inline void rtglc_TexGend(GLenum coord, GLenum pname, GLdouble param) { rtTexGenf(coord, pname, (GLfloat)param); }
#define glTexGend rtglc_TexGend
#define glTexGenf rtTexGenf
#define glTexGeni rtTexGeni
static inline void rtglc_TexGendv(GLenum coord, GLenum pname, const GLdouble *params)
{
    GLfloat f[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    int i;
    for (i = 0; i < (pname == RT_TEXTURE_GEN_MODE ? 1 : 4); i++)
        f[i] = (GLfloat)params[i];
    rtTexGenfv(coord, pname, f);
}
#define glTexGendv rtglc_TexGendv
#define glTexGenfv rtTexGenfv
static inline void rtglc_TexGeniv(GLenum coord, GLenum pname, const GLint *params)
{
    GLfloat f[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    int i;
    if (pname == RT_TEXTURE_GEN_MODE) {
        rtTexGeni(coord, pname, params[0]);
        return;
    }
    for (i = 0; i < 4; i++)
        f[i] = (GLfloat)params[i];
    rtTexGenfv(coord, pname, f);
}
#define glTexGeniv rtglc_TexGeniv
#else
#define glTexGend RTGLC_PENDING(glTexGend, "glTexGend: needs texture coordinate generation (rtTexGen*), not in this Tracelist (docs/glcompat.md)")
#define glTexGenf RTGLC_PENDING(glTexGenf, "glTexGenf: needs texture coordinate generation (rtTexGen*), not in this Tracelist (docs/glcompat.md)")
#define glTexGeni RTGLC_PENDING(glTexGeni, "glTexGeni: needs texture coordinate generation (rtTexGen*), not in this Tracelist (docs/glcompat.md)")
#define glTexGendv RTGLC_PENDING(glTexGendv, "glTexGendv: needs texture coordinate generation (rtTexGen*), not in this Tracelist (docs/glcompat.md)")
#define glTexGenfv RTGLC_PENDING(glTexGenfv, "glTexGenfv: needs texture coordinate generation (rtTexGen*), not in this Tracelist (docs/glcompat.md)")
#define glTexGeniv RTGLC_PENDING(glTexGeniv, "glTexGeniv: needs texture coordinate generation (rtTexGen*), not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_TEXENV) && (defined(RT_TEXTURE_ENV_MODE))
#define RT_GLCOMPAT_HAVE_TEXENV 1
#endif
#ifdef RT_GLCOMPAT_HAVE_TEXENV
#define glTexEnvf rtTexEnvf
#define glTexEnvi rtTexEnvi
#define glTexEnvfv rtTexEnvfv
static inline void rtglc_TexEnviv(GLenum target, GLenum pname, const GLint *params)
{
    GLfloat f[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    int i;
    if (pname != RT_TEXTURE_ENV_COLOR) {
        rtTexEnvi(target, pname, params[0]);
        return;
    }
    for (i = 0; i < 4; i++)
        f[i] = (GLfloat)((GLdouble)params[i] / 2147483647.0);
    rtTexEnvfv(target, pname, f);
}
#define glTexEnviv rtglc_TexEnviv
#else
#define glTexEnvf RTGLC_PENDING(glTexEnvf, "glTexEnvf: needs texture environments (rtTexEnv*), not in this Tracelist (docs/glcompat.md)")
#define glTexEnvi RTGLC_PENDING(glTexEnvi, "glTexEnvi: needs texture environments (rtTexEnv*), not in this Tracelist (docs/glcompat.md)")
#define glTexEnvfv RTGLC_PENDING(glTexEnvfv, "glTexEnvfv: needs texture environments (rtTexEnv*), not in this Tracelist (docs/glcompat.md)")
#define glTexEnviv RTGLC_PENDING(glTexEnviv, "glTexEnviv: needs texture environments (rtTexEnv*), not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_INTERLEAVED) && (defined(RT_T2F_N3F_V3F))
#define RT_GLCOMPAT_HAVE_INTERLEAVED 1
#endif
#ifdef RT_GLCOMPAT_HAVE_INTERLEAVED
#define glInterleavedArrays rtInterleavedArrays
#else
#define glInterleavedArrays RTGLC_PENDING(glInterleavedArrays, "glInterleavedArrays: needs rtInterleavedArrays, not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_LINE_WIDTH) && (defined(RT_LINE_WIDTH))
#define RT_GLCOMPAT_HAVE_LINE_WIDTH 1
#endif
#ifdef RT_GLCOMPAT_HAVE_LINE_WIDTH
#define glLineWidth rtLineWidth
#else
#define glLineWidth RTGLC_PENDING(glLineWidth, "glLineWidth: needs rtLineWidth, not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_POINT_SIZE) && (defined(RT_POINT_SIZE))
#define RT_GLCOMPAT_HAVE_POINT_SIZE 1
#endif
#ifdef RT_GLCOMPAT_HAVE_POINT_SIZE
#define glPointSize rtPointSize
#else
#define glPointSize RTGLC_PENDING(glPointSize, "glPointSize: needs rtPointSize, not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_POLYGON_MODE) && (defined(RT_POLYGON_MODE))
#define RT_GLCOMPAT_HAVE_POLYGON_MODE 1
#endif
#ifdef RT_GLCOMPAT_HAVE_POLYGON_MODE
#define glPolygonMode rtPolygonMode
#else
#define glPolygonMode RTGLC_PENDING(glPolygonMode, "glPolygonMode: needs rtPolygonMode, not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_BLEND_FUNC) && (defined(RT_SRC_ALPHA))
#define RT_GLCOMPAT_HAVE_BLEND_FUNC 1
#endif
#ifdef RT_GLCOMPAT_HAVE_BLEND_FUNC
#define glBlendFunc rtBlendFunc
#else
#define glBlendFunc RTGLC_PENDING(glBlendFunc, "glBlendFunc: needs blending (rtBlendFunc), not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_CLIP_PLANE) && (defined(RT_CLIP_PLANE0))
#define RT_GLCOMPAT_HAVE_CLIP_PLANE 1
#endif
#ifdef RT_GLCOMPAT_HAVE_CLIP_PLANE
#define glClipPlane rtClipPlane
#define glGetClipPlane rtGetClipPlane
#else
#define glGetClipPlane RTGLC_PENDING(glGetClipPlane, "glGetClipPlane: needs user clip planes (rtClipPlane), not in this Tracelist (docs/glcompat.md)")
#define glClipPlane RTGLC_PENDING(glClipPlane, "glClipPlane: needs user clip planes (rtClipPlane), not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_RASTER_POS) && (defined(RT_CURRENT_RASTER_POSITION))
#define RT_GLCOMPAT_HAVE_RASTER_POS 1
#endif
#ifdef RT_GLCOMPAT_HAVE_RASTER_POS
#define glRasterPos2d rtRasterPos2d
#define glRasterPos2f rtRasterPos2f
#define glRasterPos2i rtRasterPos2i
#define glRasterPos3d rtRasterPos3d
#define glRasterPos3f rtRasterPos3f
#define glRasterPos3i rtRasterPos3i
#define glRasterPos2dv rtRasterPos2dv
#define glRasterPos2fv rtRasterPos2fv
#define glRasterPos2iv rtRasterPos2iv
#define glRasterPos3dv rtRasterPos3dv
#define glRasterPos3fv rtRasterPos3fv
#define glRasterPos3iv rtRasterPos3iv
#define glWindowPos2i rtWindowPos2i
#define glWindowPos2f rtWindowPos2f
#define glWindowPos2d rtWindowPos2d
#define glWindowPos3i rtWindowPos3i
#define glWindowPos3f rtWindowPos3f
#define glWindowPos3d rtWindowPos3d
#define glRasterPos4d rtRasterPos4d
#define glRasterPos4f rtRasterPos4f
#define glRasterPos4i rtRasterPos4i
#define glRasterPos4dv rtRasterPos4dv
#define glRasterPos4fv rtRasterPos4fv
#define glRasterPos4iv rtRasterPos4iv
static inline void rtglc_RasterPos2s(GLshort x, GLshort y) { rtRasterPos2i(x, y); }
static inline void rtglc_RasterPos3s(GLshort x, GLshort y, GLshort z) { rtRasterPos3i(x, y, z); }
static inline void rtglc_RasterPos4s(GLshort x, GLshort y, GLshort z, GLshort w) { rtRasterPos4i(x, y, z, w); }
static inline void rtglc_RasterPos2sv(const GLshort *v) { rtRasterPos2i(v[0], v[1]); }
static inline void rtglc_RasterPos3sv(const GLshort *v) { rtRasterPos3i(v[0], v[1], v[2]); }
static inline void rtglc_RasterPos4sv(const GLshort *v) { rtRasterPos4i(v[0], v[1], v[2], v[3]); }
#define glRasterPos2s rtglc_RasterPos2s
#define glRasterPos3s rtglc_RasterPos3s
#define glRasterPos4s rtglc_RasterPos4s
#define glRasterPos2sv rtglc_RasterPos2sv
#define glRasterPos3sv rtglc_RasterPos3sv
#define glRasterPos4sv rtglc_RasterPos4sv
#define glWindowPos2iv rtWindowPos2iv
#define glWindowPos2fv rtWindowPos2fv
#define glWindowPos2dv rtWindowPos2dv
#define glWindowPos3iv rtWindowPos3iv
#define glWindowPos3fv rtWindowPos3fv
#define glWindowPos3dv rtWindowPos3dv
#define glBitmap rtBitmap
#else
#define glRasterPos4d RTGLC_PENDING(glRasterPos4d, "glRasterPos4d: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos4f RTGLC_PENDING(glRasterPos4f, "glRasterPos4f: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos4i RTGLC_PENDING(glRasterPos4i, "glRasterPos4i: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos4s RTGLC_PENDING(glRasterPos4s, "glRasterPos4s: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos4dv RTGLC_PENDING(glRasterPos4dv, "glRasterPos4dv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos4fv RTGLC_PENDING(glRasterPos4fv, "glRasterPos4fv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos4iv RTGLC_PENDING(glRasterPos4iv, "glRasterPos4iv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos4sv RTGLC_PENDING(glRasterPos4sv, "glRasterPos4sv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glWindowPos2iv RTGLC_PENDING(glWindowPos2iv, "glWindowPos2iv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glWindowPos2fv RTGLC_PENDING(glWindowPos2fv, "glWindowPos2fv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glWindowPos2dv RTGLC_PENDING(glWindowPos2dv, "glWindowPos2dv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glWindowPos3iv RTGLC_PENDING(glWindowPos3iv, "glWindowPos3iv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glWindowPos3fv RTGLC_PENDING(glWindowPos3fv, "glWindowPos3fv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glWindowPos3dv RTGLC_PENDING(glWindowPos3dv, "glWindowPos3dv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos2d RTGLC_PENDING(glRasterPos2d, "glRasterPos2d: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos2f RTGLC_PENDING(glRasterPos2f, "glRasterPos2f: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos2i RTGLC_PENDING(glRasterPos2i, "glRasterPos2i: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos2s RTGLC_PENDING(glRasterPos2s, "glRasterPos2s: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos3d RTGLC_PENDING(glRasterPos3d, "glRasterPos3d: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos3f RTGLC_PENDING(glRasterPos3f, "glRasterPos3f: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos3i RTGLC_PENDING(glRasterPos3i, "glRasterPos3i: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos3s RTGLC_PENDING(glRasterPos3s, "glRasterPos3s: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos2dv RTGLC_PENDING(glRasterPos2dv, "glRasterPos2dv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos2fv RTGLC_PENDING(glRasterPos2fv, "glRasterPos2fv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos2iv RTGLC_PENDING(glRasterPos2iv, "glRasterPos2iv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos2sv RTGLC_PENDING(glRasterPos2sv, "glRasterPos2sv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos3dv RTGLC_PENDING(glRasterPos3dv, "glRasterPos3dv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos3fv RTGLC_PENDING(glRasterPos3fv, "glRasterPos3fv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos3iv RTGLC_PENDING(glRasterPos3iv, "glRasterPos3iv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glRasterPos3sv RTGLC_PENDING(glRasterPos3sv, "glRasterPos3sv: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glWindowPos2i RTGLC_PENDING(glWindowPos2i, "glWindowPos2i: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glWindowPos2f RTGLC_PENDING(glWindowPos2f, "glWindowPos2f: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glWindowPos2d RTGLC_PENDING(glWindowPos2d, "glWindowPos2d: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glWindowPos3i RTGLC_PENDING(glWindowPos3i, "glWindowPos3i: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glWindowPos3f RTGLC_PENDING(glWindowPos3f, "glWindowPos3f: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glWindowPos3d RTGLC_PENDING(glWindowPos3d, "glWindowPos3d: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#define glBitmap RTGLC_PENDING(glBitmap, "glBitmap: needs bitmap text (rtRasterPos*, rtWindowPos*, rtBitmap), not in this Tracelist (docs/glcompat.md)")
#endif

/* The alpha test (docs/alpha_test.md): GL's signature, glAlphaFunc(GLenum,
 * GLclampf). */
#define glAlphaFunc rtAlphaFunc

/* ---- GL functions Tracelist does not have ----------------------------- */
#define glClearIndex RTGLC_ABSENT(glClearIndex, "glClearIndex: colour-index mode (docs/glcompat.md)")
#define glIndexMask RTGLC_ABSENT(glIndexMask, "glIndexMask: colour-index mode (docs/glcompat.md)")
#define glColorMask RTGLC_ABSENT(glColorMask, "glColorMask: no per-channel write mask (docs/glcompat.md)")
#define glLogicOp RTGLC_ABSENT(glLogicOp, "glLogicOp: no logic ops (docs/glcompat.md)")
#define glLineStipple RTGLC_ABSENT(glLineStipple, "glLineStipple: no stipple patterns (docs/glcompat.md)")
#define glPolygonStipple RTGLC_ABSENT(glPolygonStipple, "glPolygonStipple: no stipple patterns (docs/glcompat.md)")
#define glGetPolygonStipple RTGLC_ABSENT(glGetPolygonStipple, "glGetPolygonStipple: no stipple patterns (docs/glcompat.md)")
#define glScissor RTGLC_ABSENT(glScissor, "glScissor: no scissor rectangle (docs/glcompat.md)")
#define glPushAttrib rtPushAttrib
#define glPopAttrib rtPopAttrib
#define glPushClientAttrib rtPushClientAttrib
#define glPopClientAttrib rtPopClientAttrib
#define glRenderMode RTGLC_ABSENT(glRenderMode, "glRenderMode: no selection or feedback mode (pick with rtTraceRays) (docs/glcompat.md)")
#define glClearAccum RTGLC_ABSENT(glClearAccum, "glClearAccum: no accumulation buffer (docs/glcompat.md)")
#define glAccum RTGLC_ABSENT(glAccum, "glAccum: no accumulation buffer (docs/glcompat.md)")
#define glVertex4d RTGLC_ABSENT(glVertex4d, "glVertex4d: no homogeneous (w) vertices (docs/glcompat.md)")
#define glVertex4f RTGLC_ABSENT(glVertex4f, "glVertex4f: no homogeneous (w) vertices (docs/glcompat.md)")
#define glVertex4i RTGLC_ABSENT(glVertex4i, "glVertex4i: no homogeneous (w) vertices (docs/glcompat.md)")
#define glVertex4s RTGLC_ABSENT(glVertex4s, "glVertex4s: no homogeneous (w) vertices (docs/glcompat.md)")
#define glVertex4dv RTGLC_ABSENT(glVertex4dv, "glVertex4dv: no homogeneous (w) vertices (docs/glcompat.md)")
#define glVertex4fv RTGLC_ABSENT(glVertex4fv, "glVertex4fv: no homogeneous (w) vertices (docs/glcompat.md)")
#define glVertex4iv RTGLC_ABSENT(glVertex4iv, "glVertex4iv: no homogeneous (w) vertices (docs/glcompat.md)")
#define glVertex4sv RTGLC_ABSENT(glVertex4sv, "glVertex4sv: no homogeneous (w) vertices (docs/glcompat.md)")
#define glIndexd RTGLC_ABSENT(glIndexd, "glIndexd: colour-index mode (docs/glcompat.md)")
#define glIndexf RTGLC_ABSENT(glIndexf, "glIndexf: colour-index mode (docs/glcompat.md)")
#define glIndexi RTGLC_ABSENT(glIndexi, "glIndexi: colour-index mode (docs/glcompat.md)")
#define glIndexs RTGLC_ABSENT(glIndexs, "glIndexs: colour-index mode (docs/glcompat.md)")
#define glIndexub RTGLC_ABSENT(glIndexub, "glIndexub: colour-index mode (docs/glcompat.md)")
#define glIndexdv RTGLC_ABSENT(glIndexdv, "glIndexdv: colour-index mode (docs/glcompat.md)")
#define glIndexfv RTGLC_ABSENT(glIndexfv, "glIndexfv: colour-index mode (docs/glcompat.md)")
#define glIndexiv RTGLC_ABSENT(glIndexiv, "glIndexiv: colour-index mode (docs/glcompat.md)")
#define glIndexsv RTGLC_ABSENT(glIndexsv, "glIndexsv: colour-index mode (docs/glcompat.md)")
#define glIndexubv RTGLC_ABSENT(glIndexubv, "glIndexubv: colour-index mode (docs/glcompat.md)")
#define glTexCoord4d rtTexCoord4d
#define glTexCoord4f rtTexCoord4f
#define glTexCoord4i rtTexCoord4i
#define glTexCoord4s rtTexCoord4s
#define glTexCoord4dv rtTexCoord4dv
#define glTexCoord4fv rtTexCoord4fv
#define glTexCoord4iv rtTexCoord4iv
#define glTexCoord4sv rtTexCoord4sv
#define glIndexPointer RTGLC_ABSENT(glIndexPointer, "glIndexPointer: colour-index mode (docs/glcompat.md)")
#define glEdgeFlagPointer RTGLC_ABSENT(glEdgeFlagPointer, "glEdgeFlagPointer: no edge-flag array (docs/glcompat.md)")
#define glGetPointerv RTGLC_ABSENT(glGetPointerv, "glGetPointerv: state is not read back by this query (docs/glcompat.md)")
#define glGetLightiv RTGLC_ABSENT(glGetLightiv, "glGetLightiv: state is not read back by this query (docs/glcompat.md)")
#define glGetMaterialiv RTGLC_ABSENT(glGetMaterialiv, "glGetMaterialiv: state is not read back by this query (docs/glcompat.md)")
#define glPixelZoom RTGLC_ABSENT(glPixelZoom, "glPixelZoom: no pixel drawing into the frame (docs/glcompat.md)")
#define glPixelTransferf RTGLC_ABSENT(glPixelTransferf, "glPixelTransferf: no pixel drawing into the frame (docs/glcompat.md)")
#define glPixelTransferi RTGLC_ABSENT(glPixelTransferi, "glPixelTransferi: no pixel drawing into the frame (docs/glcompat.md)")
#define glPixelMapfv RTGLC_ABSENT(glPixelMapfv, "glPixelMapfv: no pixel drawing into the frame (docs/glcompat.md)")
#define glPixelMapuiv RTGLC_ABSENT(glPixelMapuiv, "glPixelMapuiv: no pixel drawing into the frame (docs/glcompat.md)")
#define glPixelMapusv RTGLC_ABSENT(glPixelMapusv, "glPixelMapusv: no pixel drawing into the frame (docs/glcompat.md)")
#define glGetPixelMapfv RTGLC_ABSENT(glGetPixelMapfv, "glGetPixelMapfv: state is not read back by this query (docs/glcompat.md)")
#define glGetPixelMapuiv RTGLC_ABSENT(glGetPixelMapuiv, "glGetPixelMapuiv: state is not read back by this query (docs/glcompat.md)")
#define glGetPixelMapusv RTGLC_ABSENT(glGetPixelMapusv, "glGetPixelMapusv: state is not read back by this query (docs/glcompat.md)")
#define glDrawPixels RTGLC_ABSENT(glDrawPixels, "glDrawPixels: no pixel drawing into the frame (docs/glcompat.md)")
#define glCopyPixels RTGLC_ABSENT(glCopyPixels, "glCopyPixels: no pixel drawing into the frame (docs/glcompat.md)")
#define glStencilFunc RTGLC_ABSENT(glStencilFunc, "glStencilFunc: no stencil buffer (docs/glcompat.md)")
#define glStencilMask RTGLC_ABSENT(glStencilMask, "glStencilMask: no stencil buffer (docs/glcompat.md)")
#define glStencilOp RTGLC_ABSENT(glStencilOp, "glStencilOp: no stencil buffer (docs/glcompat.md)")
#define glGetTexGendv RTGLC_ABSENT(glGetTexGendv, "glGetTexGendv: state is not read back by this query (docs/glcompat.md)")
#define glGetTexGenfv RTGLC_ABSENT(glGetTexGenfv, "glGetTexGenfv: state is not read back by this query (docs/glcompat.md)")
#define glGetTexGeniv RTGLC_ABSENT(glGetTexGeniv, "glGetTexGeniv: state is not read back by this query (docs/glcompat.md)")
#define glGetTexEnvfv RTGLC_ABSENT(glGetTexEnvfv, "glGetTexEnvfv: state is not read back by this query (docs/glcompat.md)")
#define glGetTexEnviv RTGLC_ABSENT(glGetTexEnviv, "glGetTexEnviv: state is not read back by this query (docs/glcompat.md)")
#define glGetTexParameterfv RTGLC_ABSENT(glGetTexParameterfv, "glGetTexParameterfv: state is not read back by this query (docs/glcompat.md)")
#define glGetTexParameteriv RTGLC_ABSENT(glGetTexParameteriv, "glGetTexParameteriv: state is not read back by this query (docs/glcompat.md)")
#define glGetTexLevelParameterfv RTGLC_ABSENT(glGetTexLevelParameterfv, "glGetTexLevelParameterfv: state is not read back by this query (docs/glcompat.md)")
#define glGetTexLevelParameteriv RTGLC_ABSENT(glGetTexLevelParameteriv, "glGetTexLevelParameteriv: state is not read back by this query (docs/glcompat.md)")
#define glTexImage1D RTGLC_ABSENT(glTexImage1D, "glTexImage1D: 2D textures are loaded whole with glTexImage2D (docs/glcompat.md)")
#define glGetTexImage RTGLC_ABSENT(glGetTexImage, "glGetTexImage: state is not read back by this query (docs/glcompat.md)")
#define glAreTexturesResident RTGLC_ABSENT(glAreTexturesResident, "glAreTexturesResident: 2D textures are loaded whole with glTexImage2D (docs/glcompat.md)")
#define glTexSubImage1D RTGLC_ABSENT(glTexSubImage1D, "glTexSubImage1D: 2D textures are loaded whole with glTexImage2D (docs/glcompat.md)")
#define glTexSubImage2D rtTexSubImage2D
#define glCopyTexImage1D RTGLC_ABSENT(glCopyTexImage1D, "glCopyTexImage1D: 2D textures are loaded whole with glTexImage2D (docs/glcompat.md)")
#define glCopyTexImage2D RTGLC_ABSENT(glCopyTexImage2D, "glCopyTexImage2D: 2D textures are loaded whole with glTexImage2D (docs/glcompat.md)")
#define glCopyTexSubImage1D RTGLC_ABSENT(glCopyTexSubImage1D, "glCopyTexSubImage1D: 2D textures are loaded whole with glTexImage2D (docs/glcompat.md)")
#define glCopyTexSubImage2D RTGLC_ABSENT(glCopyTexSubImage2D, "glCopyTexSubImage2D: 2D textures are loaded whole with glTexImage2D (docs/glcompat.md)")
#define glMap1d RTGLC_ABSENT(glMap1d, "glMap1d: no evaluators (docs/glcompat.md)")
#define glMap1f RTGLC_ABSENT(glMap1f, "glMap1f: no evaluators (docs/glcompat.md)")
#define glMap2d RTGLC_ABSENT(glMap2d, "glMap2d: no evaluators (docs/glcompat.md)")
#define glMap2f RTGLC_ABSENT(glMap2f, "glMap2f: no evaluators (docs/glcompat.md)")
#define glGetMapdv RTGLC_ABSENT(glGetMapdv, "glGetMapdv: state is not read back by this query (docs/glcompat.md)")
#define glGetMapfv RTGLC_ABSENT(glGetMapfv, "glGetMapfv: state is not read back by this query (docs/glcompat.md)")
#define glGetMapiv RTGLC_ABSENT(glGetMapiv, "glGetMapiv: state is not read back by this query (docs/glcompat.md)")
#define glEvalCoord1d RTGLC_ABSENT(glEvalCoord1d, "glEvalCoord1d: no evaluators (docs/glcompat.md)")
#define glEvalCoord1f RTGLC_ABSENT(glEvalCoord1f, "glEvalCoord1f: no evaluators (docs/glcompat.md)")
#define glEvalCoord1dv RTGLC_ABSENT(glEvalCoord1dv, "glEvalCoord1dv: no evaluators (docs/glcompat.md)")
#define glEvalCoord1fv RTGLC_ABSENT(glEvalCoord1fv, "glEvalCoord1fv: no evaluators (docs/glcompat.md)")
#define glEvalCoord2d RTGLC_ABSENT(glEvalCoord2d, "glEvalCoord2d: no evaluators (docs/glcompat.md)")
#define glEvalCoord2f RTGLC_ABSENT(glEvalCoord2f, "glEvalCoord2f: no evaluators (docs/glcompat.md)")
#define glEvalCoord2dv RTGLC_ABSENT(glEvalCoord2dv, "glEvalCoord2dv: no evaluators (docs/glcompat.md)")
#define glEvalCoord2fv RTGLC_ABSENT(glEvalCoord2fv, "glEvalCoord2fv: no evaluators (docs/glcompat.md)")
#define glMapGrid1d RTGLC_ABSENT(glMapGrid1d, "glMapGrid1d: no evaluators (docs/glcompat.md)")
#define glMapGrid1f RTGLC_ABSENT(glMapGrid1f, "glMapGrid1f: no evaluators (docs/glcompat.md)")
#define glMapGrid2d RTGLC_ABSENT(glMapGrid2d, "glMapGrid2d: no evaluators (docs/glcompat.md)")
#define glMapGrid2f RTGLC_ABSENT(glMapGrid2f, "glMapGrid2f: no evaluators (docs/glcompat.md)")
#define glEvalPoint1 RTGLC_ABSENT(glEvalPoint1, "glEvalPoint1: no evaluators (docs/glcompat.md)")
#define glEvalPoint2 RTGLC_ABSENT(glEvalPoint2, "glEvalPoint2: no evaluators (docs/glcompat.md)")
#define glEvalMesh1 RTGLC_ABSENT(glEvalMesh1, "glEvalMesh1: no evaluators (docs/glcompat.md)")
#define glEvalMesh2 RTGLC_ABSENT(glEvalMesh2, "glEvalMesh2: no evaluators (docs/glcompat.md)")
#define glFeedbackBuffer RTGLC_ABSENT(glFeedbackBuffer, "glFeedbackBuffer: no selection or feedback mode (pick with rtTraceRays) (docs/glcompat.md)")
#define glPassThrough RTGLC_ABSENT(glPassThrough, "glPassThrough: no selection or feedback mode (pick with rtTraceRays) (docs/glcompat.md)")
#define glSelectBuffer RTGLC_ABSENT(glSelectBuffer, "glSelectBuffer: no selection or feedback mode (pick with rtTraceRays) (docs/glcompat.md)")
#define glInitNames RTGLC_ABSENT(glInitNames, "glInitNames: no selection or feedback mode (pick with rtTraceRays) (docs/glcompat.md)")
#define glLoadName RTGLC_ABSENT(glLoadName, "glLoadName: no selection or feedback mode (pick with rtTraceRays) (docs/glcompat.md)")
#define glPushName RTGLC_ABSENT(glPushName, "glPushName: no selection or feedback mode (pick with rtTraceRays) (docs/glcompat.md)")
#define glPopName RTGLC_ABSENT(glPopName, "glPopName: no selection or feedback mode (pick with rtTraceRays) (docs/glcompat.md)")

/* ---- GL enums --------------------------------------------------------- */
#define GL_VERSION_1_0 1
#define GL_VERSION_1_1 1
#define GL_FALSE RT_FALSE
#define GL_TRUE RT_TRUE
#define GL_BYTE RT_BYTE
#define GL_UNSIGNED_BYTE RT_UNSIGNED_BYTE
#define GL_SHORT RT_SHORT
#define GL_UNSIGNED_SHORT RT_UNSIGNED_SHORT
#define GL_INT RT_INT
#define GL_UNSIGNED_INT RT_UNSIGNED_INT
#define GL_FLOAT RT_FLOAT
#define GL_DOUBLE RT_DOUBLE
#define GL_TRIANGLES RT_TRIANGLES
#define GL_TRIANGLE_STRIP RT_TRIANGLE_STRIP
#define GL_TRIANGLE_FAN RT_TRIANGLE_FAN
#define GL_QUADS RT_QUADS
#define GL_QUAD_STRIP RT_QUAD_STRIP
#define GL_POLYGON RT_POLYGON
#define GL_VERTEX_ARRAY RT_VERTEX_ARRAY
#define GL_NORMAL_ARRAY RT_NORMAL_ARRAY
#define GL_COLOR_ARRAY RT_COLOR_ARRAY
#define GL_TEXTURE_COORD_ARRAY RT_TEXTURE_COORD_ARRAY
#define GL_MATRIX_MODE RT_MATRIX_MODE
#define GL_MODELVIEW RT_MODELVIEW
#define GL_PROJECTION RT_PROJECTION
#define GL_FRONT RT_FRONT
#define GL_BACK RT_BACK
#define GL_LIGHT0 RT_LIGHT0
#define GL_CONSTANT_ATTENUATION RT_CONSTANT_ATTENUATION
#define GL_LINEAR_ATTENUATION RT_LINEAR_ATTENUATION
#define GL_QUADRATIC_ATTENUATION RT_QUADRATIC_ATTENUATION
#define GL_AMBIENT RT_AMBIENT
#define GL_DIFFUSE RT_DIFFUSE
#define GL_SPECULAR RT_SPECULAR
#define GL_SHININESS RT_SHININESS
#define GL_EMISSION RT_EMISSION
#define GL_POSITION RT_POSITION
#define GL_AMBIENT_AND_DIFFUSE RT_AMBIENT_AND_DIFFUSE
#define GL_LIGHT_MODEL_AMBIENT RT_LIGHT_MODEL_AMBIENT
#define GL_FRONT_AND_BACK RT_FRONT_AND_BACK
#define GL_SHADE_MODEL RT_SHADE_MODEL
#define GL_FLAT RT_FLAT
#define GL_SMOOTH RT_SMOOTH
#define GL_COLOR_MATERIAL RT_COLOR_MATERIAL
#define GL_LINEAR RT_LINEAR
#define GL_RGB RT_RGB
#define GL_RGBA RT_RGBA
#define GL_MAX_LIGHTS RT_MAX_LIGHTS
#define GL_MAX_TEXTURE_SIZE RT_MAX_TEXTURE_SIZE
#define GL_MAX_MODELVIEW_STACK_DEPTH RT_MAX_MODELVIEW_STACK_DEPTH
#define GL_MAX_PROJECTION_STACK_DEPTH RT_MAX_PROJECTION_STACK_DEPTH
#define GL_COLOR_CLEAR_VALUE RT_COLOR_CLEAR_VALUE
#define GL_MODELVIEW_MATRIX RT_MODELVIEW_MATRIX
#define GL_MODELVIEW_STACK_DEPTH RT_MODELVIEW_STACK_DEPTH
#define GL_PROJECTION_MATRIX RT_PROJECTION_MATRIX
#define GL_PROJECTION_STACK_DEPTH RT_PROJECTION_STACK_DEPTH
#define GL_VIEWPORT RT_VIEWPORT
#define GL_TEXTURE_2D RT_TEXTURE_2D
#define GL_TEXTURE_WRAP_S RT_TEXTURE_WRAP_S
#define GL_TEXTURE_WRAP_T RT_TEXTURE_WRAP_T
#define GL_TEXTURE_MAG_FILTER RT_TEXTURE_MAG_FILTER
#define GL_TEXTURE_MIN_FILTER RT_TEXTURE_MIN_FILTER
#define GL_NEAREST_MIPMAP_NEAREST RT_NEAREST_MIPMAP_NEAREST
#define GL_NEAREST_MIPMAP_LINEAR RT_NEAREST_MIPMAP_LINEAR
#define GL_LINEAR_MIPMAP_NEAREST RT_LINEAR_MIPMAP_NEAREST
#define GL_LINEAR_MIPMAP_LINEAR RT_LINEAR_MIPMAP_LINEAR
#define GL_NEAREST RT_NEAREST
#define GL_REPEAT RT_REPEAT
#define GL_VENDOR RT_VENDOR
#define GL_RENDERER RT_RENDERER
#define GL_VERSION RT_VERSION
#define GL_EXTENSIONS RT_EXTENSIONS
#define GL_NO_ERROR RT_NO_ERROR
#define GL_INVALID_ENUM RT_INVALID_ENUM
#define GL_INVALID_VALUE RT_INVALID_VALUE
#define GL_INVALID_OPERATION RT_INVALID_OPERATION
#define GL_STACK_OVERFLOW RT_STACK_OVERFLOW
#define GL_STACK_UNDERFLOW RT_STACK_UNDERFLOW
#define GL_OUT_OF_MEMORY RT_OUT_OF_MEMORY
#define GL_TEXTURE_BINDING_2D RT_TEXTURE_BINDING_2D

/* Values of no-op calls and ignored capabilities: the core's name when it
 * has one, else GL's value (the no-op or rtglc_Enable accepts it). */
#ifdef RT_POINT_SMOOTH
#define GL_POINT_SMOOTH RT_POINT_SMOOTH
#else
#define GL_POINT_SMOOTH 0x0B10
#endif
#ifdef RT_LINE_SMOOTH
#define GL_LINE_SMOOTH RT_LINE_SMOOTH
#else
#define GL_LINE_SMOOTH 0x0B20
#endif
#ifdef RT_POLYGON_SMOOTH
#define GL_POLYGON_SMOOTH RT_POLYGON_SMOOTH
#else
#define GL_POLYGON_SMOOTH 0x0B41
#endif
#ifdef RT_POLYGON_OFFSET_POINT
#define GL_POLYGON_OFFSET_POINT RT_POLYGON_OFFSET_POINT
#else
#define GL_POLYGON_OFFSET_POINT 0x2A01
#endif
#ifdef RT_POLYGON_OFFSET_LINE
#define GL_POLYGON_OFFSET_LINE RT_POLYGON_OFFSET_LINE
#else
#define GL_POLYGON_OFFSET_LINE 0x2A02
#endif
#ifdef RT_POLYGON_OFFSET_FILL
#define GL_POLYGON_OFFSET_FILL RT_POLYGON_OFFSET_FILL
#else
#define GL_POLYGON_OFFSET_FILL 0x8037
#endif
#ifdef RT_NEVER
#define GL_NEVER RT_NEVER
#else
#define GL_NEVER 0x0200
#endif
#ifdef RT_LESS
#define GL_LESS RT_LESS
#else
#define GL_LESS 0x0201
#endif
#ifdef RT_EQUAL
#define GL_EQUAL RT_EQUAL
#else
#define GL_EQUAL 0x0202
#endif
#ifdef RT_LEQUAL
#define GL_LEQUAL RT_LEQUAL
#else
#define GL_LEQUAL 0x0203
#endif
#ifdef RT_GREATER
#define GL_GREATER RT_GREATER
#else
#define GL_GREATER 0x0204
#endif
#ifdef RT_NOTEQUAL
#define GL_NOTEQUAL RT_NOTEQUAL
#else
#define GL_NOTEQUAL 0x0205
#endif
#ifdef RT_GEQUAL
#define GL_GEQUAL RT_GEQUAL
#else
#define GL_GEQUAL 0x0206
#endif
#ifdef RT_ALWAYS
#define GL_ALWAYS RT_ALWAYS
#else
#define GL_ALWAYS 0x0207
#endif
#ifdef RT_DEPTH_TEST
#define GL_DEPTH_TEST RT_DEPTH_TEST
#else
#define GL_DEPTH_TEST 0x0B71
#endif
#ifdef RT_NONE
#define GL_NONE RT_NONE
#else
#define GL_NONE 0
#endif
#ifdef RT_LEFT
#define GL_LEFT RT_LEFT
#else
#define GL_LEFT 0x0406
#endif
#ifdef RT_RIGHT
#define GL_RIGHT RT_RIGHT
#else
#define GL_RIGHT 0x0407
#endif
#ifdef RT_FRONT_LEFT
#define GL_FRONT_LEFT RT_FRONT_LEFT
#else
#define GL_FRONT_LEFT 0x0400
#endif
#ifdef RT_FRONT_RIGHT
#define GL_FRONT_RIGHT RT_FRONT_RIGHT
#else
#define GL_FRONT_RIGHT 0x0401
#endif
#ifdef RT_BACK_LEFT
#define GL_BACK_LEFT RT_BACK_LEFT
#else
#define GL_BACK_LEFT 0x0402
#endif
#ifdef RT_BACK_RIGHT
#define GL_BACK_RIGHT RT_BACK_RIGHT
#else
#define GL_BACK_RIGHT 0x0403
#endif
#ifdef RT_AUX0
#define GL_AUX0 RT_AUX0
#else
#define GL_AUX0 0x0409
#endif
#ifdef RT_AUX1
#define GL_AUX1 RT_AUX1
#else
#define GL_AUX1 0x040A
#endif
#ifdef RT_AUX2
#define GL_AUX2 RT_AUX2
#else
#define GL_AUX2 0x040B
#endif
#ifdef RT_AUX3
#define GL_AUX3 RT_AUX3
#else
#define GL_AUX3 0x040C
#endif
#ifdef RT_DITHER
#define GL_DITHER RT_DITHER
#else
#define GL_DITHER 0x0BD0
#endif
#ifdef RT_PERSPECTIVE_CORRECTION_HINT
#define GL_PERSPECTIVE_CORRECTION_HINT RT_PERSPECTIVE_CORRECTION_HINT
#else
#define GL_PERSPECTIVE_CORRECTION_HINT 0x0C50
#endif
#ifdef RT_POINT_SMOOTH_HINT
#define GL_POINT_SMOOTH_HINT RT_POINT_SMOOTH_HINT
#else
#define GL_POINT_SMOOTH_HINT 0x0C51
#endif
#ifdef RT_LINE_SMOOTH_HINT
#define GL_LINE_SMOOTH_HINT RT_LINE_SMOOTH_HINT
#else
#define GL_LINE_SMOOTH_HINT 0x0C52
#endif
#ifdef RT_POLYGON_SMOOTH_HINT
#define GL_POLYGON_SMOOTH_HINT RT_POLYGON_SMOOTH_HINT
#else
#define GL_POLYGON_SMOOTH_HINT 0x0C53
#endif
#ifdef RT_FOG_HINT
#define GL_FOG_HINT RT_FOG_HINT
#else
#define GL_FOG_HINT 0x0C54
#endif
#ifdef RT_DONT_CARE
#define GL_DONT_CARE RT_DONT_CARE
#else
#define GL_DONT_CARE 0x1100
#endif
#ifdef RT_FASTEST
#define GL_FASTEST RT_FASTEST
#else
#define GL_FASTEST 0x1101
#endif
#ifdef RT_NICEST
#define GL_NICEST RT_NICEST
#else
#define GL_NICEST 0x1102
#endif
#ifdef RT_PACK_ALIGNMENT
#define GL_PACK_ALIGNMENT RT_PACK_ALIGNMENT
#else
#define GL_PACK_ALIGNMENT 0x0D05
#endif
#ifdef RT_PACK_LSB_FIRST
#define GL_PACK_LSB_FIRST RT_PACK_LSB_FIRST
#else
#define GL_PACK_LSB_FIRST 0x0D01
#endif
#ifdef RT_PACK_ROW_LENGTH
#define GL_PACK_ROW_LENGTH RT_PACK_ROW_LENGTH
#else
#define GL_PACK_ROW_LENGTH 0x0D02
#endif
#ifdef RT_PACK_SKIP_PIXELS
#define GL_PACK_SKIP_PIXELS RT_PACK_SKIP_PIXELS
#else
#define GL_PACK_SKIP_PIXELS 0x0D04
#endif
#ifdef RT_PACK_SKIP_ROWS
#define GL_PACK_SKIP_ROWS RT_PACK_SKIP_ROWS
#else
#define GL_PACK_SKIP_ROWS 0x0D03
#endif
#ifdef RT_PACK_SWAP_BYTES
#define GL_PACK_SWAP_BYTES RT_PACK_SWAP_BYTES
#else
#define GL_PACK_SWAP_BYTES 0x0D00
#endif
#ifdef RT_UNPACK_ALIGNMENT
#define GL_UNPACK_ALIGNMENT RT_UNPACK_ALIGNMENT
#else
#define GL_UNPACK_ALIGNMENT 0x0CF5
#endif
#ifdef RT_UNPACK_LSB_FIRST
#define GL_UNPACK_LSB_FIRST RT_UNPACK_LSB_FIRST
#else
#define GL_UNPACK_LSB_FIRST 0x0CF1
#endif
#ifdef RT_UNPACK_ROW_LENGTH
#define GL_UNPACK_ROW_LENGTH RT_UNPACK_ROW_LENGTH
#else
#define GL_UNPACK_ROW_LENGTH 0x0CF2
#endif
#ifdef RT_UNPACK_SKIP_PIXELS
#define GL_UNPACK_SKIP_PIXELS RT_UNPACK_SKIP_PIXELS
#else
#define GL_UNPACK_SKIP_PIXELS 0x0CF4
#endif
#ifdef RT_UNPACK_SKIP_ROWS
#define GL_UNPACK_SKIP_ROWS RT_UNPACK_SKIP_ROWS
#else
#define GL_UNPACK_SKIP_ROWS 0x0CF3
#endif
#ifdef RT_UNPACK_SWAP_BYTES
#define GL_UNPACK_SWAP_BYTES RT_UNPACK_SWAP_BYTES
#else
#define GL_UNPACK_SWAP_BYTES 0x0CF0
#endif
#ifdef RT_DEPTH_BUFFER_BIT
#define GL_DEPTH_BUFFER_BIT RT_DEPTH_BUFFER_BIT
#else
#define GL_DEPTH_BUFFER_BIT 0x00000100
#endif
#ifdef RT_ACCUM_BUFFER_BIT
#define GL_ACCUM_BUFFER_BIT RT_ACCUM_BUFFER_BIT
#else
#define GL_ACCUM_BUFFER_BIT 0x00000200
#endif
#ifdef RT_STENCIL_BUFFER_BIT
#define GL_STENCIL_BUFFER_BIT RT_STENCIL_BUFFER_BIT
#else
#define GL_STENCIL_BUFFER_BIT 0x00000400
#endif
#ifdef RT_COLOR_BUFFER_BIT
#define GL_COLOR_BUFFER_BIT RT_COLOR_BUFFER_BIT
#else
#define GL_COLOR_BUFFER_BIT 0x00004000
#endif

/* Enums of features other branches add (or none yet): the RT_ name, so a
 * use before the feature exists fails as an undeclared RT_ identifier. */
#define GL_2_BYTES RT_2_BYTES
#define GL_3_BYTES RT_3_BYTES
#define GL_4_BYTES RT_4_BYTES
#define GL_POINTS RT_POINTS
#define GL_LINES RT_LINES
#define GL_LINE_LOOP RT_LINE_LOOP
#define GL_LINE_STRIP RT_LINE_STRIP
#define GL_VERTEX_ARRAY_SIZE RT_VERTEX_ARRAY_SIZE
#define GL_VERTEX_ARRAY_TYPE RT_VERTEX_ARRAY_TYPE
#define GL_VERTEX_ARRAY_STRIDE RT_VERTEX_ARRAY_STRIDE
#define GL_NORMAL_ARRAY_TYPE RT_NORMAL_ARRAY_TYPE
#define GL_NORMAL_ARRAY_STRIDE RT_NORMAL_ARRAY_STRIDE
#define GL_COLOR_ARRAY_SIZE RT_COLOR_ARRAY_SIZE
#define GL_COLOR_ARRAY_TYPE RT_COLOR_ARRAY_TYPE
#define GL_COLOR_ARRAY_STRIDE RT_COLOR_ARRAY_STRIDE
#define GL_TEXTURE_COORD_ARRAY_SIZE RT_TEXTURE_COORD_ARRAY_SIZE
#define GL_TEXTURE_COORD_ARRAY_TYPE RT_TEXTURE_COORD_ARRAY_TYPE
#define GL_TEXTURE_COORD_ARRAY_STRIDE RT_TEXTURE_COORD_ARRAY_STRIDE
#define GL_VERTEX_ARRAY_POINTER RT_VERTEX_ARRAY_POINTER
#define GL_NORMAL_ARRAY_POINTER RT_NORMAL_ARRAY_POINTER
#define GL_COLOR_ARRAY_POINTER RT_COLOR_ARRAY_POINTER
#define GL_TEXTURE_COORD_ARRAY_POINTER RT_TEXTURE_COORD_ARRAY_POINTER
#define GL_V2F RT_V2F
#define GL_V3F RT_V3F
#define GL_C4UB_V2F RT_C4UB_V2F
#define GL_C4UB_V3F RT_C4UB_V3F
#define GL_C3F_V3F RT_C3F_V3F
#define GL_N3F_V3F RT_N3F_V3F
#define GL_C4F_N3F_V3F RT_C4F_N3F_V3F
#define GL_T2F_V3F RT_T2F_V3F
#define GL_T4F_V4F RT_T4F_V4F
#define GL_T2F_C4UB_V3F RT_T2F_C4UB_V3F
#define GL_T2F_C3F_V3F RT_T2F_C3F_V3F
#define GL_T2F_N3F_V3F RT_T2F_N3F_V3F
#define GL_T2F_C4F_N3F_V3F RT_T2F_C4F_N3F_V3F
#define GL_T4F_C4F_N3F_V4F RT_T4F_C4F_N3F_V4F
#define GL_TEXTURE RT_TEXTURE
#define GL_POINT_SIZE RT_POINT_SIZE
#define GL_POINT_SIZE_GRANULARITY RT_POINT_SIZE_GRANULARITY
#define GL_POINT_SIZE_RANGE RT_POINT_SIZE_RANGE
#define GL_LINE_WIDTH RT_LINE_WIDTH
#define GL_LINE_WIDTH_GRANULARITY RT_LINE_WIDTH_GRANULARITY
#define GL_LINE_WIDTH_RANGE RT_LINE_WIDTH_RANGE
#define GL_POINT RT_POINT
#define GL_LINE RT_LINE
#define GL_FILL RT_FILL
#define GL_CW RT_CW
#define GL_CCW RT_CCW
#define GL_POLYGON_MODE RT_POLYGON_MODE
#define GL_CULL_FACE RT_CULL_FACE
#define GL_CULL_FACE_MODE RT_CULL_FACE_MODE
#define GL_FRONT_FACE RT_FRONT_FACE
#define GL_POLYGON_OFFSET_FACTOR RT_POLYGON_OFFSET_FACTOR
#define GL_POLYGON_OFFSET_UNITS RT_POLYGON_OFFSET_UNITS
#define GL_COMPILE RT_COMPILE
#define GL_COMPILE_AND_EXECUTE RT_COMPILE_AND_EXECUTE
#define GL_LIGHTING RT_LIGHTING
#ifdef RT_LIGHT1
#define GL_LIGHT1 RT_LIGHT1
#else
#define GL_LIGHT1 (RT_LIGHT0 + 1) /* rt.h: RT_LIGHT0 + i */
#endif
#ifdef RT_LIGHT2
#define GL_LIGHT2 RT_LIGHT2
#else
#define GL_LIGHT2 (RT_LIGHT0 + 2) /* rt.h: RT_LIGHT0 + i */
#endif
#ifdef RT_LIGHT3
#define GL_LIGHT3 RT_LIGHT3
#else
#define GL_LIGHT3 (RT_LIGHT0 + 3) /* rt.h: RT_LIGHT0 + i */
#endif
#ifdef RT_LIGHT4
#define GL_LIGHT4 RT_LIGHT4
#else
#define GL_LIGHT4 (RT_LIGHT0 + 4) /* rt.h: RT_LIGHT0 + i */
#endif
#ifdef RT_LIGHT5
#define GL_LIGHT5 RT_LIGHT5
#else
#define GL_LIGHT5 (RT_LIGHT0 + 5) /* rt.h: RT_LIGHT0 + i */
#endif
#ifdef RT_LIGHT6
#define GL_LIGHT6 RT_LIGHT6
#else
#define GL_LIGHT6 (RT_LIGHT0 + 6) /* rt.h: RT_LIGHT0 + i */
#endif
#ifdef RT_LIGHT7
#define GL_LIGHT7 RT_LIGHT7
#else
#define GL_LIGHT7 (RT_LIGHT0 + 7) /* rt.h: RT_LIGHT0 + i */
#endif
#define GL_SPOT_EXPONENT RT_SPOT_EXPONENT
#define GL_SPOT_CUTOFF RT_SPOT_CUTOFF
#define GL_SPOT_DIRECTION RT_SPOT_DIRECTION
#define GL_LIGHT_MODEL_TWO_SIDE RT_LIGHT_MODEL_TWO_SIDE
#define GL_LIGHT_MODEL_LOCAL_VIEWER RT_LIGHT_MODEL_LOCAL_VIEWER
#define GL_COLOR_MATERIAL_FACE RT_COLOR_MATERIAL_FACE
#define GL_COLOR_MATERIAL_PARAMETER RT_COLOR_MATERIAL_PARAMETER
#define GL_NORMALIZE RT_NORMALIZE
#define GL_CLIP_PLANE0 RT_CLIP_PLANE0
#define GL_CLIP_PLANE1 RT_CLIP_PLANE1
#define GL_CLIP_PLANE2 RT_CLIP_PLANE2
#define GL_CLIP_PLANE3 RT_CLIP_PLANE3
#define GL_CLIP_PLANE4 RT_CLIP_PLANE4
#define GL_CLIP_PLANE5 RT_CLIP_PLANE5
#define GL_BLEND RT_BLEND
#define GL_BLEND_SRC RT_BLEND_SRC
#define GL_BLEND_DST RT_BLEND_DST
#define GL_ZERO RT_ZERO
#define GL_ONE RT_ONE
#define GL_SRC_COLOR RT_SRC_COLOR
#define GL_ONE_MINUS_SRC_COLOR RT_ONE_MINUS_SRC_COLOR
#define GL_SRC_ALPHA RT_SRC_ALPHA
#define GL_ONE_MINUS_SRC_ALPHA RT_ONE_MINUS_SRC_ALPHA
#define GL_DST_ALPHA RT_DST_ALPHA
#define GL_ONE_MINUS_DST_ALPHA RT_ONE_MINUS_DST_ALPHA
#define GL_DST_COLOR RT_DST_COLOR
#define GL_ONE_MINUS_DST_COLOR RT_ONE_MINUS_DST_COLOR
#define GL_SRC_ALPHA_SATURATE RT_SRC_ALPHA_SATURATE
#define GL_FOG RT_FOG
#define GL_FOG_MODE RT_FOG_MODE
#define GL_FOG_DENSITY RT_FOG_DENSITY
#define GL_FOG_COLOR RT_FOG_COLOR
#define GL_FOG_START RT_FOG_START
#define GL_FOG_END RT_FOG_END
#define GL_EXP RT_EXP
#define GL_EXP2 RT_EXP2
#define GL_REPLACE RT_REPLACE
#define GL_RED RT_RED
#define GL_GREEN RT_GREEN
#define GL_BLUE RT_BLUE
#define GL_ALPHA RT_ALPHA
#define GL_LUMINANCE RT_LUMINANCE
#define GL_LUMINANCE_ALPHA RT_LUMINANCE_ALPHA
#define GL_READ_BUFFER RT_READ_BUFFER
#define GL_DRAW_BUFFER RT_DRAW_BUFFER
#define GL_COLOR RT_COLOR
#define GL_DEPTH RT_DEPTH
#define GL_MAX_TEXTURE_STACK_DEPTH RT_MAX_TEXTURE_STACK_DEPTH
#define GL_MAX_VIEWPORT_DIMS RT_MAX_VIEWPORT_DIMS
#define GL_CURRENT_COLOR RT_CURRENT_COLOR
#define GL_CURRENT_NORMAL RT_CURRENT_NORMAL
#define GL_CURRENT_RASTER_COLOR RT_CURRENT_RASTER_COLOR
#define GL_CURRENT_RASTER_POSITION RT_CURRENT_RASTER_POSITION
#define GL_CURRENT_RASTER_TEXTURE_COORDS RT_CURRENT_RASTER_TEXTURE_COORDS
#define GL_CURRENT_TEXTURE_COORDS RT_CURRENT_TEXTURE_COORDS
#define GL_TEXTURE_MATRIX RT_TEXTURE_MATRIX
#define GL_TEXTURE_STACK_DEPTH RT_TEXTURE_STACK_DEPTH
#define GL_TEXTURE_ENV RT_TEXTURE_ENV
#define GL_TEXTURE_ENV_MODE RT_TEXTURE_ENV_MODE
#define GL_TEXTURE_ENV_COLOR RT_TEXTURE_ENV_COLOR
#define GL_TEXTURE_GEN_S RT_TEXTURE_GEN_S
#define GL_TEXTURE_GEN_T RT_TEXTURE_GEN_T
#define GL_TEXTURE_GEN_R RT_TEXTURE_GEN_R
#define GL_TEXTURE_GEN_Q RT_TEXTURE_GEN_Q
#define GL_TEXTURE_GEN_MODE RT_TEXTURE_GEN_MODE
#define GL_OBJECT_LINEAR RT_OBJECT_LINEAR
#define GL_OBJECT_PLANE RT_OBJECT_PLANE
#define GL_EYE_LINEAR RT_EYE_LINEAR
#define GL_EYE_PLANE RT_EYE_PLANE
#define GL_SPHERE_MAP RT_SPHERE_MAP
#define GL_DECAL RT_DECAL
#define GL_MODULATE RT_MODULATE
#define GL_CLAMP RT_CLAMP
#define GL_S RT_S
#define GL_T RT_T
#define GL_R RT_R
#define GL_Q RT_Q
#define GL_INTENSITY RT_INTENSITY

/* Enums of what Tracelist does not have. */
#ifdef RT_INDEX_ARRAY
#define GL_INDEX_ARRAY RT_INDEX_ARRAY
#else
#define GL_INDEX_ARRAY RTGLC_ABSENT(GL_INDEX_ARRAY, "GL_INDEX_ARRAY: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_EDGE_FLAG_ARRAY
#define GL_EDGE_FLAG_ARRAY RT_EDGE_FLAG_ARRAY
#else
#define GL_EDGE_FLAG_ARRAY RTGLC_ABSENT(GL_EDGE_FLAG_ARRAY, "GL_EDGE_FLAG_ARRAY: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INDEX_ARRAY_TYPE
#define GL_INDEX_ARRAY_TYPE RT_INDEX_ARRAY_TYPE
#else
#define GL_INDEX_ARRAY_TYPE RTGLC_ABSENT(GL_INDEX_ARRAY_TYPE, "GL_INDEX_ARRAY_TYPE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INDEX_ARRAY_STRIDE
#define GL_INDEX_ARRAY_STRIDE RT_INDEX_ARRAY_STRIDE
#else
#define GL_INDEX_ARRAY_STRIDE RTGLC_ABSENT(GL_INDEX_ARRAY_STRIDE, "GL_INDEX_ARRAY_STRIDE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_EDGE_FLAG_ARRAY_STRIDE
#define GL_EDGE_FLAG_ARRAY_STRIDE RT_EDGE_FLAG_ARRAY_STRIDE
#else
#define GL_EDGE_FLAG_ARRAY_STRIDE RTGLC_ABSENT(GL_EDGE_FLAG_ARRAY_STRIDE, "GL_EDGE_FLAG_ARRAY_STRIDE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INDEX_ARRAY_POINTER
#define GL_INDEX_ARRAY_POINTER RT_INDEX_ARRAY_POINTER
#else
#define GL_INDEX_ARRAY_POINTER RTGLC_ABSENT(GL_INDEX_ARRAY_POINTER, "GL_INDEX_ARRAY_POINTER: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_EDGE_FLAG_ARRAY_POINTER
#define GL_EDGE_FLAG_ARRAY_POINTER RT_EDGE_FLAG_ARRAY_POINTER
#else
#define GL_EDGE_FLAG_ARRAY_POINTER RTGLC_ABSENT(GL_EDGE_FLAG_ARRAY_POINTER, "GL_EDGE_FLAG_ARRAY_POINTER: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LINE_STIPPLE
#define GL_LINE_STIPPLE RT_LINE_STIPPLE
#else
#define GL_LINE_STIPPLE RTGLC_ABSENT(GL_LINE_STIPPLE, "GL_LINE_STIPPLE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LINE_STIPPLE_PATTERN
#define GL_LINE_STIPPLE_PATTERN RT_LINE_STIPPLE_PATTERN
#else
#define GL_LINE_STIPPLE_PATTERN RTGLC_ABSENT(GL_LINE_STIPPLE_PATTERN, "GL_LINE_STIPPLE_PATTERN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LINE_STIPPLE_REPEAT
#define GL_LINE_STIPPLE_REPEAT RT_LINE_STIPPLE_REPEAT
#else
#define GL_LINE_STIPPLE_REPEAT RTGLC_ABSENT(GL_LINE_STIPPLE_REPEAT, "GL_LINE_STIPPLE_REPEAT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_POLYGON_STIPPLE
#define GL_POLYGON_STIPPLE RT_POLYGON_STIPPLE
#else
#define GL_POLYGON_STIPPLE RTGLC_ABSENT(GL_POLYGON_STIPPLE, "GL_POLYGON_STIPPLE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_EDGE_FLAG
#define GL_EDGE_FLAG RT_EDGE_FLAG
#else
#define GL_EDGE_FLAG RTGLC_ABSENT(GL_EDGE_FLAG, "GL_EDGE_FLAG: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LIST_BASE
#define GL_LIST_BASE RT_LIST_BASE
#else
#define GL_LIST_BASE RTGLC_ABSENT(GL_LIST_BASE, "GL_LIST_BASE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LIST_INDEX
#define GL_LIST_INDEX RT_LIST_INDEX
#else
#define GL_LIST_INDEX RTGLC_ABSENT(GL_LIST_INDEX, "GL_LIST_INDEX: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LIST_MODE
#define GL_LIST_MODE RT_LIST_MODE
#else
#define GL_LIST_MODE RTGLC_ABSENT(GL_LIST_MODE, "GL_LIST_MODE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_DEPTH_BITS
#define GL_DEPTH_BITS RT_DEPTH_BITS
#else
#define GL_DEPTH_BITS RTGLC_ABSENT(GL_DEPTH_BITS, "GL_DEPTH_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_DEPTH_CLEAR_VALUE
#define GL_DEPTH_CLEAR_VALUE RT_DEPTH_CLEAR_VALUE
#else
#define GL_DEPTH_CLEAR_VALUE RTGLC_ABSENT(GL_DEPTH_CLEAR_VALUE, "GL_DEPTH_CLEAR_VALUE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_DEPTH_FUNC
#define GL_DEPTH_FUNC RT_DEPTH_FUNC
#else
#define GL_DEPTH_FUNC RTGLC_ABSENT(GL_DEPTH_FUNC, "GL_DEPTH_FUNC: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_DEPTH_RANGE
#define GL_DEPTH_RANGE RT_DEPTH_RANGE
#else
#define GL_DEPTH_RANGE RTGLC_ABSENT(GL_DEPTH_RANGE, "GL_DEPTH_RANGE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_DEPTH_WRITEMASK
#define GL_DEPTH_WRITEMASK RT_DEPTH_WRITEMASK
#else
#define GL_DEPTH_WRITEMASK RTGLC_ABSENT(GL_DEPTH_WRITEMASK, "GL_DEPTH_WRITEMASK: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_DEPTH_COMPONENT
#define GL_DEPTH_COMPONENT RT_DEPTH_COMPONENT
#else
#define GL_DEPTH_COMPONENT RTGLC_ABSENT(GL_DEPTH_COMPONENT, "GL_DEPTH_COMPONENT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_COLOR_INDEXES
#define GL_COLOR_INDEXES RT_COLOR_INDEXES
#else
#define GL_COLOR_INDEXES RTGLC_ABSENT(GL_COLOR_INDEXES, "GL_COLOR_INDEXES: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ACCUM_RED_BITS
#define GL_ACCUM_RED_BITS RT_ACCUM_RED_BITS
#else
#define GL_ACCUM_RED_BITS RTGLC_ABSENT(GL_ACCUM_RED_BITS, "GL_ACCUM_RED_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ACCUM_GREEN_BITS
#define GL_ACCUM_GREEN_BITS RT_ACCUM_GREEN_BITS
#else
#define GL_ACCUM_GREEN_BITS RTGLC_ABSENT(GL_ACCUM_GREEN_BITS, "GL_ACCUM_GREEN_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ACCUM_BLUE_BITS
#define GL_ACCUM_BLUE_BITS RT_ACCUM_BLUE_BITS
#else
#define GL_ACCUM_BLUE_BITS RTGLC_ABSENT(GL_ACCUM_BLUE_BITS, "GL_ACCUM_BLUE_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ACCUM_ALPHA_BITS
#define GL_ACCUM_ALPHA_BITS RT_ACCUM_ALPHA_BITS
#else
#define GL_ACCUM_ALPHA_BITS RTGLC_ABSENT(GL_ACCUM_ALPHA_BITS, "GL_ACCUM_ALPHA_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ACCUM_CLEAR_VALUE
#define GL_ACCUM_CLEAR_VALUE RT_ACCUM_CLEAR_VALUE
#else
#define GL_ACCUM_CLEAR_VALUE RTGLC_ABSENT(GL_ACCUM_CLEAR_VALUE, "GL_ACCUM_CLEAR_VALUE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ACCUM
#define GL_ACCUM RT_ACCUM
#else
#define GL_ACCUM RTGLC_ABSENT(GL_ACCUM, "GL_ACCUM: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ADD
#define GL_ADD RT_ADD
#else
#define GL_ADD RTGLC_ABSENT(GL_ADD, "GL_ADD: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LOAD
#define GL_LOAD RT_LOAD
#else
#define GL_LOAD RTGLC_ABSENT(GL_LOAD, "GL_LOAD: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MULT
#define GL_MULT RT_MULT
#else
#define GL_MULT RTGLC_ABSENT(GL_MULT, "GL_MULT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RETURN
#define GL_RETURN RT_RETURN
#else
#define GL_RETURN RTGLC_ABSENT(GL_RETURN, "GL_RETURN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ALPHA_TEST
#define GL_ALPHA_TEST RT_ALPHA_TEST
#else
#define GL_ALPHA_TEST RTGLC_ABSENT(GL_ALPHA_TEST, "GL_ALPHA_TEST: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ALPHA_TEST_REF
#define GL_ALPHA_TEST_REF RT_ALPHA_TEST_REF
#else
#define GL_ALPHA_TEST_REF RTGLC_ABSENT(GL_ALPHA_TEST_REF, "GL_ALPHA_TEST_REF: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ALPHA_TEST_FUNC
#define GL_ALPHA_TEST_FUNC RT_ALPHA_TEST_FUNC
#else
#define GL_ALPHA_TEST_FUNC RTGLC_ABSENT(GL_ALPHA_TEST_FUNC, "GL_ALPHA_TEST_FUNC: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_FEEDBACK
#define GL_FEEDBACK RT_FEEDBACK
#else
#define GL_FEEDBACK RTGLC_ABSENT(GL_FEEDBACK, "GL_FEEDBACK: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RENDER
#define GL_RENDER RT_RENDER
#else
#define GL_RENDER RTGLC_ABSENT(GL_RENDER, "GL_RENDER: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_SELECT
#define GL_SELECT RT_SELECT
#else
#define GL_SELECT RTGLC_ABSENT(GL_SELECT, "GL_SELECT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_2D
#define GL_2D RT_2D
#else
#define GL_2D RTGLC_ABSENT(GL_2D, "GL_2D: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_3D
#define GL_3D RT_3D
#else
#define GL_3D RTGLC_ABSENT(GL_3D, "GL_3D: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_3D_COLOR
#define GL_3D_COLOR RT_3D_COLOR
#else
#define GL_3D_COLOR RTGLC_ABSENT(GL_3D_COLOR, "GL_3D_COLOR: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_3D_COLOR_TEXTURE
#define GL_3D_COLOR_TEXTURE RT_3D_COLOR_TEXTURE
#else
#define GL_3D_COLOR_TEXTURE RTGLC_ABSENT(GL_3D_COLOR_TEXTURE, "GL_3D_COLOR_TEXTURE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_4D_COLOR_TEXTURE
#define GL_4D_COLOR_TEXTURE RT_4D_COLOR_TEXTURE
#else
#define GL_4D_COLOR_TEXTURE RTGLC_ABSENT(GL_4D_COLOR_TEXTURE, "GL_4D_COLOR_TEXTURE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_POINT_TOKEN
#define GL_POINT_TOKEN RT_POINT_TOKEN
#else
#define GL_POINT_TOKEN RTGLC_ABSENT(GL_POINT_TOKEN, "GL_POINT_TOKEN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LINE_TOKEN
#define GL_LINE_TOKEN RT_LINE_TOKEN
#else
#define GL_LINE_TOKEN RTGLC_ABSENT(GL_LINE_TOKEN, "GL_LINE_TOKEN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LINE_RESET_TOKEN
#define GL_LINE_RESET_TOKEN RT_LINE_RESET_TOKEN
#else
#define GL_LINE_RESET_TOKEN RTGLC_ABSENT(GL_LINE_RESET_TOKEN, "GL_LINE_RESET_TOKEN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_POLYGON_TOKEN
#define GL_POLYGON_TOKEN RT_POLYGON_TOKEN
#else
#define GL_POLYGON_TOKEN RTGLC_ABSENT(GL_POLYGON_TOKEN, "GL_POLYGON_TOKEN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_BITMAP_TOKEN
#define GL_BITMAP_TOKEN RT_BITMAP_TOKEN
#else
#define GL_BITMAP_TOKEN RTGLC_ABSENT(GL_BITMAP_TOKEN, "GL_BITMAP_TOKEN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_DRAW_PIXEL_TOKEN
#define GL_DRAW_PIXEL_TOKEN RT_DRAW_PIXEL_TOKEN
#else
#define GL_DRAW_PIXEL_TOKEN RTGLC_ABSENT(GL_DRAW_PIXEL_TOKEN, "GL_DRAW_PIXEL_TOKEN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_COPY_PIXEL_TOKEN
#define GL_COPY_PIXEL_TOKEN RT_COPY_PIXEL_TOKEN
#else
#define GL_COPY_PIXEL_TOKEN RTGLC_ABSENT(GL_COPY_PIXEL_TOKEN, "GL_COPY_PIXEL_TOKEN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PASS_THROUGH_TOKEN
#define GL_PASS_THROUGH_TOKEN RT_PASS_THROUGH_TOKEN
#else
#define GL_PASS_THROUGH_TOKEN RTGLC_ABSENT(GL_PASS_THROUGH_TOKEN, "GL_PASS_THROUGH_TOKEN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_FEEDBACK_BUFFER_POINTER
#define GL_FEEDBACK_BUFFER_POINTER RT_FEEDBACK_BUFFER_POINTER
#else
#define GL_FEEDBACK_BUFFER_POINTER RTGLC_ABSENT(GL_FEEDBACK_BUFFER_POINTER, "GL_FEEDBACK_BUFFER_POINTER: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_FEEDBACK_BUFFER_SIZE
#define GL_FEEDBACK_BUFFER_SIZE RT_FEEDBACK_BUFFER_SIZE
#else
#define GL_FEEDBACK_BUFFER_SIZE RTGLC_ABSENT(GL_FEEDBACK_BUFFER_SIZE, "GL_FEEDBACK_BUFFER_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_FEEDBACK_BUFFER_TYPE
#define GL_FEEDBACK_BUFFER_TYPE RT_FEEDBACK_BUFFER_TYPE
#else
#define GL_FEEDBACK_BUFFER_TYPE RTGLC_ABSENT(GL_FEEDBACK_BUFFER_TYPE, "GL_FEEDBACK_BUFFER_TYPE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_SELECTION_BUFFER_POINTER
#define GL_SELECTION_BUFFER_POINTER RT_SELECTION_BUFFER_POINTER
#else
#define GL_SELECTION_BUFFER_POINTER RTGLC_ABSENT(GL_SELECTION_BUFFER_POINTER, "GL_SELECTION_BUFFER_POINTER: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_SELECTION_BUFFER_SIZE
#define GL_SELECTION_BUFFER_SIZE RT_SELECTION_BUFFER_SIZE
#else
#define GL_SELECTION_BUFFER_SIZE RTGLC_ABSENT(GL_SELECTION_BUFFER_SIZE, "GL_SELECTION_BUFFER_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_FOG_INDEX
#define GL_FOG_INDEX RT_FOG_INDEX
#else
#define GL_FOG_INDEX RTGLC_ABSENT(GL_FOG_INDEX, "GL_FOG_INDEX: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LOGIC_OP
#define GL_LOGIC_OP RT_LOGIC_OP
#else
#define GL_LOGIC_OP RTGLC_ABSENT(GL_LOGIC_OP, "GL_LOGIC_OP: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INDEX_LOGIC_OP
#define GL_INDEX_LOGIC_OP RT_INDEX_LOGIC_OP
#else
#define GL_INDEX_LOGIC_OP RTGLC_ABSENT(GL_INDEX_LOGIC_OP, "GL_INDEX_LOGIC_OP: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_COLOR_LOGIC_OP
#define GL_COLOR_LOGIC_OP RT_COLOR_LOGIC_OP
#else
#define GL_COLOR_LOGIC_OP RTGLC_ABSENT(GL_COLOR_LOGIC_OP, "GL_COLOR_LOGIC_OP: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LOGIC_OP_MODE
#define GL_LOGIC_OP_MODE RT_LOGIC_OP_MODE
#else
#define GL_LOGIC_OP_MODE RTGLC_ABSENT(GL_LOGIC_OP_MODE, "GL_LOGIC_OP_MODE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_CLEAR
#define GL_CLEAR RT_CLEAR
#else
#define GL_CLEAR RTGLC_ABSENT(GL_CLEAR, "GL_CLEAR: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_SET
#define GL_SET RT_SET
#else
#define GL_SET RTGLC_ABSENT(GL_SET, "GL_SET: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_COPY
#define GL_COPY RT_COPY
#else
#define GL_COPY RTGLC_ABSENT(GL_COPY, "GL_COPY: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_COPY_INVERTED
#define GL_COPY_INVERTED RT_COPY_INVERTED
#else
#define GL_COPY_INVERTED RTGLC_ABSENT(GL_COPY_INVERTED, "GL_COPY_INVERTED: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_NOOP
#define GL_NOOP RT_NOOP
#else
#define GL_NOOP RTGLC_ABSENT(GL_NOOP, "GL_NOOP: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INVERT
#define GL_INVERT RT_INVERT
#else
#define GL_INVERT RTGLC_ABSENT(GL_INVERT, "GL_INVERT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_AND
#define GL_AND RT_AND
#else
#define GL_AND RTGLC_ABSENT(GL_AND, "GL_AND: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_NAND
#define GL_NAND RT_NAND
#else
#define GL_NAND RTGLC_ABSENT(GL_NAND, "GL_NAND: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_OR
#define GL_OR RT_OR
#else
#define GL_OR RTGLC_ABSENT(GL_OR, "GL_OR: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_NOR
#define GL_NOR RT_NOR
#else
#define GL_NOR RTGLC_ABSENT(GL_NOR, "GL_NOR: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_XOR
#define GL_XOR RT_XOR
#else
#define GL_XOR RTGLC_ABSENT(GL_XOR, "GL_XOR: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_EQUIV
#define GL_EQUIV RT_EQUIV
#else
#define GL_EQUIV RTGLC_ABSENT(GL_EQUIV, "GL_EQUIV: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_AND_REVERSE
#define GL_AND_REVERSE RT_AND_REVERSE
#else
#define GL_AND_REVERSE RTGLC_ABSENT(GL_AND_REVERSE, "GL_AND_REVERSE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_AND_INVERTED
#define GL_AND_INVERTED RT_AND_INVERTED
#else
#define GL_AND_INVERTED RTGLC_ABSENT(GL_AND_INVERTED, "GL_AND_INVERTED: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_OR_REVERSE
#define GL_OR_REVERSE RT_OR_REVERSE
#else
#define GL_OR_REVERSE RTGLC_ABSENT(GL_OR_REVERSE, "GL_OR_REVERSE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_OR_INVERTED
#define GL_OR_INVERTED RT_OR_INVERTED
#else
#define GL_OR_INVERTED RTGLC_ABSENT(GL_OR_INVERTED, "GL_OR_INVERTED: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STENCIL_BITS
#define GL_STENCIL_BITS RT_STENCIL_BITS
#else
#define GL_STENCIL_BITS RTGLC_ABSENT(GL_STENCIL_BITS, "GL_STENCIL_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STENCIL_TEST
#define GL_STENCIL_TEST RT_STENCIL_TEST
#else
#define GL_STENCIL_TEST RTGLC_ABSENT(GL_STENCIL_TEST, "GL_STENCIL_TEST: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STENCIL_CLEAR_VALUE
#define GL_STENCIL_CLEAR_VALUE RT_STENCIL_CLEAR_VALUE
#else
#define GL_STENCIL_CLEAR_VALUE RTGLC_ABSENT(GL_STENCIL_CLEAR_VALUE, "GL_STENCIL_CLEAR_VALUE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STENCIL_FUNC
#define GL_STENCIL_FUNC RT_STENCIL_FUNC
#else
#define GL_STENCIL_FUNC RTGLC_ABSENT(GL_STENCIL_FUNC, "GL_STENCIL_FUNC: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STENCIL_VALUE_MASK
#define GL_STENCIL_VALUE_MASK RT_STENCIL_VALUE_MASK
#else
#define GL_STENCIL_VALUE_MASK RTGLC_ABSENT(GL_STENCIL_VALUE_MASK, "GL_STENCIL_VALUE_MASK: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STENCIL_FAIL
#define GL_STENCIL_FAIL RT_STENCIL_FAIL
#else
#define GL_STENCIL_FAIL RTGLC_ABSENT(GL_STENCIL_FAIL, "GL_STENCIL_FAIL: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STENCIL_PASS_DEPTH_FAIL
#define GL_STENCIL_PASS_DEPTH_FAIL RT_STENCIL_PASS_DEPTH_FAIL
#else
#define GL_STENCIL_PASS_DEPTH_FAIL RTGLC_ABSENT(GL_STENCIL_PASS_DEPTH_FAIL, "GL_STENCIL_PASS_DEPTH_FAIL: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STENCIL_PASS_DEPTH_PASS
#define GL_STENCIL_PASS_DEPTH_PASS RT_STENCIL_PASS_DEPTH_PASS
#else
#define GL_STENCIL_PASS_DEPTH_PASS RTGLC_ABSENT(GL_STENCIL_PASS_DEPTH_PASS, "GL_STENCIL_PASS_DEPTH_PASS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STENCIL_REF
#define GL_STENCIL_REF RT_STENCIL_REF
#else
#define GL_STENCIL_REF RTGLC_ABSENT(GL_STENCIL_REF, "GL_STENCIL_REF: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STENCIL_WRITEMASK
#define GL_STENCIL_WRITEMASK RT_STENCIL_WRITEMASK
#else
#define GL_STENCIL_WRITEMASK RTGLC_ABSENT(GL_STENCIL_WRITEMASK, "GL_STENCIL_WRITEMASK: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STENCIL_INDEX
#define GL_STENCIL_INDEX RT_STENCIL_INDEX
#else
#define GL_STENCIL_INDEX RTGLC_ABSENT(GL_STENCIL_INDEX, "GL_STENCIL_INDEX: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_KEEP
#define GL_KEEP RT_KEEP
#else
#define GL_KEEP RTGLC_ABSENT(GL_KEEP, "GL_KEEP: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INCR
#define GL_INCR RT_INCR
#else
#define GL_INCR RTGLC_ABSENT(GL_INCR, "GL_INCR: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_DECR
#define GL_DECR RT_DECR
#else
#define GL_DECR RTGLC_ABSENT(GL_DECR, "GL_DECR: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_COLOR_INDEX
#define GL_COLOR_INDEX RT_COLOR_INDEX
#else
#define GL_COLOR_INDEX RTGLC_ABSENT(GL_COLOR_INDEX, "GL_COLOR_INDEX: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ALPHA_BITS
#define GL_ALPHA_BITS RT_ALPHA_BITS
#else
#define GL_ALPHA_BITS RTGLC_ABSENT(GL_ALPHA_BITS, "GL_ALPHA_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RED_BITS
#define GL_RED_BITS RT_RED_BITS
#else
#define GL_RED_BITS RTGLC_ABSENT(GL_RED_BITS, "GL_RED_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_GREEN_BITS
#define GL_GREEN_BITS RT_GREEN_BITS
#else
#define GL_GREEN_BITS RTGLC_ABSENT(GL_GREEN_BITS, "GL_GREEN_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_BLUE_BITS
#define GL_BLUE_BITS RT_BLUE_BITS
#else
#define GL_BLUE_BITS RTGLC_ABSENT(GL_BLUE_BITS, "GL_BLUE_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INDEX_BITS
#define GL_INDEX_BITS RT_INDEX_BITS
#else
#define GL_INDEX_BITS RTGLC_ABSENT(GL_INDEX_BITS, "GL_INDEX_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_SUBPIXEL_BITS
#define GL_SUBPIXEL_BITS RT_SUBPIXEL_BITS
#else
#define GL_SUBPIXEL_BITS RTGLC_ABSENT(GL_SUBPIXEL_BITS, "GL_SUBPIXEL_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_AUX_BUFFERS
#define GL_AUX_BUFFERS RT_AUX_BUFFERS
#else
#define GL_AUX_BUFFERS RTGLC_ABSENT(GL_AUX_BUFFERS, "GL_AUX_BUFFERS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_DOUBLEBUFFER
#define GL_DOUBLEBUFFER RT_DOUBLEBUFFER
#else
#define GL_DOUBLEBUFFER RTGLC_ABSENT(GL_DOUBLEBUFFER, "GL_DOUBLEBUFFER: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STEREO
#define GL_STEREO RT_STEREO
#else
#define GL_STEREO RTGLC_ABSENT(GL_STEREO, "GL_STEREO: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_BITMAP
#define GL_BITMAP RT_BITMAP
#else
#define GL_BITMAP RTGLC_ABSENT(GL_BITMAP, "GL_BITMAP: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_STENCIL
#define GL_STENCIL RT_STENCIL
#else
#define GL_STENCIL RTGLC_ABSENT(GL_STENCIL, "GL_STENCIL: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAX_LIST_NESTING
#define GL_MAX_LIST_NESTING RT_MAX_LIST_NESTING
#else
#define GL_MAX_LIST_NESTING RTGLC_ABSENT(GL_MAX_LIST_NESTING, "GL_MAX_LIST_NESTING: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAX_EVAL_ORDER
#define GL_MAX_EVAL_ORDER RT_MAX_EVAL_ORDER
#else
#define GL_MAX_EVAL_ORDER RTGLC_ABSENT(GL_MAX_EVAL_ORDER, "GL_MAX_EVAL_ORDER: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAX_CLIP_PLANES
#define GL_MAX_CLIP_PLANES RT_MAX_CLIP_PLANES
#else
#define GL_MAX_CLIP_PLANES RTGLC_ABSENT(GL_MAX_CLIP_PLANES, "GL_MAX_CLIP_PLANES: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAX_PIXEL_MAP_TABLE
#define GL_MAX_PIXEL_MAP_TABLE RT_MAX_PIXEL_MAP_TABLE
#else
#define GL_MAX_PIXEL_MAP_TABLE RTGLC_ABSENT(GL_MAX_PIXEL_MAP_TABLE, "GL_MAX_PIXEL_MAP_TABLE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAX_ATTRIB_STACK_DEPTH
#define GL_MAX_ATTRIB_STACK_DEPTH RT_MAX_ATTRIB_STACK_DEPTH
#else
#define GL_MAX_ATTRIB_STACK_DEPTH RTGLC_ABSENT(GL_MAX_ATTRIB_STACK_DEPTH, "GL_MAX_ATTRIB_STACK_DEPTH: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAX_NAME_STACK_DEPTH
#define GL_MAX_NAME_STACK_DEPTH RT_MAX_NAME_STACK_DEPTH
#else
#define GL_MAX_NAME_STACK_DEPTH RTGLC_ABSENT(GL_MAX_NAME_STACK_DEPTH, "GL_MAX_NAME_STACK_DEPTH: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAX_CLIENT_ATTRIB_STACK_DEPTH
#define GL_MAX_CLIENT_ATTRIB_STACK_DEPTH RT_MAX_CLIENT_ATTRIB_STACK_DEPTH
#else
#define GL_MAX_CLIENT_ATTRIB_STACK_DEPTH RTGLC_ABSENT(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, "GL_MAX_CLIENT_ATTRIB_STACK_DEPTH: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ATTRIB_STACK_DEPTH
#define GL_ATTRIB_STACK_DEPTH RT_ATTRIB_STACK_DEPTH
#else
#define GL_ATTRIB_STACK_DEPTH RTGLC_ABSENT(GL_ATTRIB_STACK_DEPTH, "GL_ATTRIB_STACK_DEPTH: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_CLIENT_ATTRIB_STACK_DEPTH
#define GL_CLIENT_ATTRIB_STACK_DEPTH RT_CLIENT_ATTRIB_STACK_DEPTH
#else
#define GL_CLIENT_ATTRIB_STACK_DEPTH RTGLC_ABSENT(GL_CLIENT_ATTRIB_STACK_DEPTH, "GL_CLIENT_ATTRIB_STACK_DEPTH: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_COLOR_WRITEMASK
#define GL_COLOR_WRITEMASK RT_COLOR_WRITEMASK
#else
#define GL_COLOR_WRITEMASK RTGLC_ABSENT(GL_COLOR_WRITEMASK, "GL_COLOR_WRITEMASK: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_CURRENT_INDEX
#define GL_CURRENT_INDEX RT_CURRENT_INDEX
#else
#define GL_CURRENT_INDEX RTGLC_ABSENT(GL_CURRENT_INDEX, "GL_CURRENT_INDEX: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_CURRENT_RASTER_DISTANCE
#define GL_CURRENT_RASTER_DISTANCE RT_CURRENT_RASTER_DISTANCE
#else
#define GL_CURRENT_RASTER_DISTANCE RTGLC_ABSENT(GL_CURRENT_RASTER_DISTANCE, "GL_CURRENT_RASTER_DISTANCE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_CURRENT_RASTER_INDEX
#define GL_CURRENT_RASTER_INDEX RT_CURRENT_RASTER_INDEX
#else
#define GL_CURRENT_RASTER_INDEX RTGLC_ABSENT(GL_CURRENT_RASTER_INDEX, "GL_CURRENT_RASTER_INDEX: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_CURRENT_RASTER_POSITION_VALID
#define GL_CURRENT_RASTER_POSITION_VALID RT_CURRENT_RASTER_POSITION_VALID
#else
#define GL_CURRENT_RASTER_POSITION_VALID RTGLC_ABSENT(GL_CURRENT_RASTER_POSITION_VALID, "GL_CURRENT_RASTER_POSITION_VALID: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INDEX_CLEAR_VALUE
#define GL_INDEX_CLEAR_VALUE RT_INDEX_CLEAR_VALUE
#else
#define GL_INDEX_CLEAR_VALUE RTGLC_ABSENT(GL_INDEX_CLEAR_VALUE, "GL_INDEX_CLEAR_VALUE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INDEX_MODE
#define GL_INDEX_MODE RT_INDEX_MODE
#else
#define GL_INDEX_MODE RTGLC_ABSENT(GL_INDEX_MODE, "GL_INDEX_MODE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INDEX_WRITEMASK
#define GL_INDEX_WRITEMASK RT_INDEX_WRITEMASK
#else
#define GL_INDEX_WRITEMASK RTGLC_ABSENT(GL_INDEX_WRITEMASK, "GL_INDEX_WRITEMASK: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_NAME_STACK_DEPTH
#define GL_NAME_STACK_DEPTH RT_NAME_STACK_DEPTH
#else
#define GL_NAME_STACK_DEPTH RTGLC_ABSENT(GL_NAME_STACK_DEPTH, "GL_NAME_STACK_DEPTH: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RENDER_MODE
#define GL_RENDER_MODE RT_RENDER_MODE
#else
#define GL_RENDER_MODE RTGLC_ABSENT(GL_RENDER_MODE, "GL_RENDER_MODE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGBA_MODE
#define GL_RGBA_MODE RT_RGBA_MODE
#else
#define GL_RGBA_MODE RTGLC_ABSENT(GL_RGBA_MODE, "GL_RGBA_MODE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_AUTO_NORMAL
#define GL_AUTO_NORMAL RT_AUTO_NORMAL
#else
#define GL_AUTO_NORMAL RTGLC_ABSENT(GL_AUTO_NORMAL, "GL_AUTO_NORMAL: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP1_COLOR_4
#define GL_MAP1_COLOR_4 RT_MAP1_COLOR_4
#else
#define GL_MAP1_COLOR_4 RTGLC_ABSENT(GL_MAP1_COLOR_4, "GL_MAP1_COLOR_4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP1_INDEX
#define GL_MAP1_INDEX RT_MAP1_INDEX
#else
#define GL_MAP1_INDEX RTGLC_ABSENT(GL_MAP1_INDEX, "GL_MAP1_INDEX: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP1_NORMAL
#define GL_MAP1_NORMAL RT_MAP1_NORMAL
#else
#define GL_MAP1_NORMAL RTGLC_ABSENT(GL_MAP1_NORMAL, "GL_MAP1_NORMAL: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP1_TEXTURE_COORD_1
#define GL_MAP1_TEXTURE_COORD_1 RT_MAP1_TEXTURE_COORD_1
#else
#define GL_MAP1_TEXTURE_COORD_1 RTGLC_ABSENT(GL_MAP1_TEXTURE_COORD_1, "GL_MAP1_TEXTURE_COORD_1: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP1_TEXTURE_COORD_2
#define GL_MAP1_TEXTURE_COORD_2 RT_MAP1_TEXTURE_COORD_2
#else
#define GL_MAP1_TEXTURE_COORD_2 RTGLC_ABSENT(GL_MAP1_TEXTURE_COORD_2, "GL_MAP1_TEXTURE_COORD_2: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP1_TEXTURE_COORD_3
#define GL_MAP1_TEXTURE_COORD_3 RT_MAP1_TEXTURE_COORD_3
#else
#define GL_MAP1_TEXTURE_COORD_3 RTGLC_ABSENT(GL_MAP1_TEXTURE_COORD_3, "GL_MAP1_TEXTURE_COORD_3: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP1_TEXTURE_COORD_4
#define GL_MAP1_TEXTURE_COORD_4 RT_MAP1_TEXTURE_COORD_4
#else
#define GL_MAP1_TEXTURE_COORD_4 RTGLC_ABSENT(GL_MAP1_TEXTURE_COORD_4, "GL_MAP1_TEXTURE_COORD_4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP1_VERTEX_3
#define GL_MAP1_VERTEX_3 RT_MAP1_VERTEX_3
#else
#define GL_MAP1_VERTEX_3 RTGLC_ABSENT(GL_MAP1_VERTEX_3, "GL_MAP1_VERTEX_3: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP1_VERTEX_4
#define GL_MAP1_VERTEX_4 RT_MAP1_VERTEX_4
#else
#define GL_MAP1_VERTEX_4 RTGLC_ABSENT(GL_MAP1_VERTEX_4, "GL_MAP1_VERTEX_4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP2_COLOR_4
#define GL_MAP2_COLOR_4 RT_MAP2_COLOR_4
#else
#define GL_MAP2_COLOR_4 RTGLC_ABSENT(GL_MAP2_COLOR_4, "GL_MAP2_COLOR_4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP2_INDEX
#define GL_MAP2_INDEX RT_MAP2_INDEX
#else
#define GL_MAP2_INDEX RTGLC_ABSENT(GL_MAP2_INDEX, "GL_MAP2_INDEX: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP2_NORMAL
#define GL_MAP2_NORMAL RT_MAP2_NORMAL
#else
#define GL_MAP2_NORMAL RTGLC_ABSENT(GL_MAP2_NORMAL, "GL_MAP2_NORMAL: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP2_TEXTURE_COORD_1
#define GL_MAP2_TEXTURE_COORD_1 RT_MAP2_TEXTURE_COORD_1
#else
#define GL_MAP2_TEXTURE_COORD_1 RTGLC_ABSENT(GL_MAP2_TEXTURE_COORD_1, "GL_MAP2_TEXTURE_COORD_1: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP2_TEXTURE_COORD_2
#define GL_MAP2_TEXTURE_COORD_2 RT_MAP2_TEXTURE_COORD_2
#else
#define GL_MAP2_TEXTURE_COORD_2 RTGLC_ABSENT(GL_MAP2_TEXTURE_COORD_2, "GL_MAP2_TEXTURE_COORD_2: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP2_TEXTURE_COORD_3
#define GL_MAP2_TEXTURE_COORD_3 RT_MAP2_TEXTURE_COORD_3
#else
#define GL_MAP2_TEXTURE_COORD_3 RTGLC_ABSENT(GL_MAP2_TEXTURE_COORD_3, "GL_MAP2_TEXTURE_COORD_3: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP2_TEXTURE_COORD_4
#define GL_MAP2_TEXTURE_COORD_4 RT_MAP2_TEXTURE_COORD_4
#else
#define GL_MAP2_TEXTURE_COORD_4 RTGLC_ABSENT(GL_MAP2_TEXTURE_COORD_4, "GL_MAP2_TEXTURE_COORD_4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP2_VERTEX_3
#define GL_MAP2_VERTEX_3 RT_MAP2_VERTEX_3
#else
#define GL_MAP2_VERTEX_3 RTGLC_ABSENT(GL_MAP2_VERTEX_3, "GL_MAP2_VERTEX_3: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP2_VERTEX_4
#define GL_MAP2_VERTEX_4 RT_MAP2_VERTEX_4
#else
#define GL_MAP2_VERTEX_4 RTGLC_ABSENT(GL_MAP2_VERTEX_4, "GL_MAP2_VERTEX_4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP1_GRID_DOMAIN
#define GL_MAP1_GRID_DOMAIN RT_MAP1_GRID_DOMAIN
#else
#define GL_MAP1_GRID_DOMAIN RTGLC_ABSENT(GL_MAP1_GRID_DOMAIN, "GL_MAP1_GRID_DOMAIN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP1_GRID_SEGMENTS
#define GL_MAP1_GRID_SEGMENTS RT_MAP1_GRID_SEGMENTS
#else
#define GL_MAP1_GRID_SEGMENTS RTGLC_ABSENT(GL_MAP1_GRID_SEGMENTS, "GL_MAP1_GRID_SEGMENTS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP2_GRID_DOMAIN
#define GL_MAP2_GRID_DOMAIN RT_MAP2_GRID_DOMAIN
#else
#define GL_MAP2_GRID_DOMAIN RTGLC_ABSENT(GL_MAP2_GRID_DOMAIN, "GL_MAP2_GRID_DOMAIN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP2_GRID_SEGMENTS
#define GL_MAP2_GRID_SEGMENTS RT_MAP2_GRID_SEGMENTS
#else
#define GL_MAP2_GRID_SEGMENTS RTGLC_ABSENT(GL_MAP2_GRID_SEGMENTS, "GL_MAP2_GRID_SEGMENTS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_COEFF
#define GL_COEFF RT_COEFF
#else
#define GL_COEFF RTGLC_ABSENT(GL_COEFF, "GL_COEFF: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ORDER
#define GL_ORDER RT_ORDER
#else
#define GL_ORDER RTGLC_ABSENT(GL_ORDER, "GL_ORDER: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_DOMAIN
#define GL_DOMAIN RT_DOMAIN
#else
#define GL_DOMAIN RTGLC_ABSENT(GL_DOMAIN, "GL_DOMAIN: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_SCISSOR_BOX
#define GL_SCISSOR_BOX RT_SCISSOR_BOX
#else
#define GL_SCISSOR_BOX RTGLC_ABSENT(GL_SCISSOR_BOX, "GL_SCISSOR_BOX: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_SCISSOR_TEST
#define GL_SCISSOR_TEST RT_SCISSOR_TEST
#else
#define GL_SCISSOR_TEST RTGLC_ABSENT(GL_SCISSOR_TEST, "GL_SCISSOR_TEST: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP_COLOR
#define GL_MAP_COLOR RT_MAP_COLOR
#else
#define GL_MAP_COLOR RTGLC_ABSENT(GL_MAP_COLOR, "GL_MAP_COLOR: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_MAP_STENCIL
#define GL_MAP_STENCIL RT_MAP_STENCIL
#else
#define GL_MAP_STENCIL RTGLC_ABSENT(GL_MAP_STENCIL, "GL_MAP_STENCIL: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INDEX_SHIFT
#define GL_INDEX_SHIFT RT_INDEX_SHIFT
#else
#define GL_INDEX_SHIFT RTGLC_ABSENT(GL_INDEX_SHIFT, "GL_INDEX_SHIFT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INDEX_OFFSET
#define GL_INDEX_OFFSET RT_INDEX_OFFSET
#else
#define GL_INDEX_OFFSET RTGLC_ABSENT(GL_INDEX_OFFSET, "GL_INDEX_OFFSET: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RED_SCALE
#define GL_RED_SCALE RT_RED_SCALE
#else
#define GL_RED_SCALE RTGLC_ABSENT(GL_RED_SCALE, "GL_RED_SCALE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RED_BIAS
#define GL_RED_BIAS RT_RED_BIAS
#else
#define GL_RED_BIAS RTGLC_ABSENT(GL_RED_BIAS, "GL_RED_BIAS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_GREEN_SCALE
#define GL_GREEN_SCALE RT_GREEN_SCALE
#else
#define GL_GREEN_SCALE RTGLC_ABSENT(GL_GREEN_SCALE, "GL_GREEN_SCALE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_GREEN_BIAS
#define GL_GREEN_BIAS RT_GREEN_BIAS
#else
#define GL_GREEN_BIAS RTGLC_ABSENT(GL_GREEN_BIAS, "GL_GREEN_BIAS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_BLUE_SCALE
#define GL_BLUE_SCALE RT_BLUE_SCALE
#else
#define GL_BLUE_SCALE RTGLC_ABSENT(GL_BLUE_SCALE, "GL_BLUE_SCALE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_BLUE_BIAS
#define GL_BLUE_BIAS RT_BLUE_BIAS
#else
#define GL_BLUE_BIAS RTGLC_ABSENT(GL_BLUE_BIAS, "GL_BLUE_BIAS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ALPHA_SCALE
#define GL_ALPHA_SCALE RT_ALPHA_SCALE
#else
#define GL_ALPHA_SCALE RTGLC_ABSENT(GL_ALPHA_SCALE, "GL_ALPHA_SCALE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ALPHA_BIAS
#define GL_ALPHA_BIAS RT_ALPHA_BIAS
#else
#define GL_ALPHA_BIAS RTGLC_ABSENT(GL_ALPHA_BIAS, "GL_ALPHA_BIAS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_DEPTH_SCALE
#define GL_DEPTH_SCALE RT_DEPTH_SCALE
#else
#define GL_DEPTH_SCALE RTGLC_ABSENT(GL_DEPTH_SCALE, "GL_DEPTH_SCALE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_DEPTH_BIAS
#define GL_DEPTH_BIAS RT_DEPTH_BIAS
#else
#define GL_DEPTH_BIAS RTGLC_ABSENT(GL_DEPTH_BIAS, "GL_DEPTH_BIAS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_S_TO_S_SIZE
#define GL_PIXEL_MAP_S_TO_S_SIZE RT_PIXEL_MAP_S_TO_S_SIZE
#else
#define GL_PIXEL_MAP_S_TO_S_SIZE RTGLC_ABSENT(GL_PIXEL_MAP_S_TO_S_SIZE, "GL_PIXEL_MAP_S_TO_S_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_I_TO_I_SIZE
#define GL_PIXEL_MAP_I_TO_I_SIZE RT_PIXEL_MAP_I_TO_I_SIZE
#else
#define GL_PIXEL_MAP_I_TO_I_SIZE RTGLC_ABSENT(GL_PIXEL_MAP_I_TO_I_SIZE, "GL_PIXEL_MAP_I_TO_I_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_I_TO_R_SIZE
#define GL_PIXEL_MAP_I_TO_R_SIZE RT_PIXEL_MAP_I_TO_R_SIZE
#else
#define GL_PIXEL_MAP_I_TO_R_SIZE RTGLC_ABSENT(GL_PIXEL_MAP_I_TO_R_SIZE, "GL_PIXEL_MAP_I_TO_R_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_I_TO_G_SIZE
#define GL_PIXEL_MAP_I_TO_G_SIZE RT_PIXEL_MAP_I_TO_G_SIZE
#else
#define GL_PIXEL_MAP_I_TO_G_SIZE RTGLC_ABSENT(GL_PIXEL_MAP_I_TO_G_SIZE, "GL_PIXEL_MAP_I_TO_G_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_I_TO_B_SIZE
#define GL_PIXEL_MAP_I_TO_B_SIZE RT_PIXEL_MAP_I_TO_B_SIZE
#else
#define GL_PIXEL_MAP_I_TO_B_SIZE RTGLC_ABSENT(GL_PIXEL_MAP_I_TO_B_SIZE, "GL_PIXEL_MAP_I_TO_B_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_I_TO_A_SIZE
#define GL_PIXEL_MAP_I_TO_A_SIZE RT_PIXEL_MAP_I_TO_A_SIZE
#else
#define GL_PIXEL_MAP_I_TO_A_SIZE RTGLC_ABSENT(GL_PIXEL_MAP_I_TO_A_SIZE, "GL_PIXEL_MAP_I_TO_A_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_R_TO_R_SIZE
#define GL_PIXEL_MAP_R_TO_R_SIZE RT_PIXEL_MAP_R_TO_R_SIZE
#else
#define GL_PIXEL_MAP_R_TO_R_SIZE RTGLC_ABSENT(GL_PIXEL_MAP_R_TO_R_SIZE, "GL_PIXEL_MAP_R_TO_R_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_G_TO_G_SIZE
#define GL_PIXEL_MAP_G_TO_G_SIZE RT_PIXEL_MAP_G_TO_G_SIZE
#else
#define GL_PIXEL_MAP_G_TO_G_SIZE RTGLC_ABSENT(GL_PIXEL_MAP_G_TO_G_SIZE, "GL_PIXEL_MAP_G_TO_G_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_B_TO_B_SIZE
#define GL_PIXEL_MAP_B_TO_B_SIZE RT_PIXEL_MAP_B_TO_B_SIZE
#else
#define GL_PIXEL_MAP_B_TO_B_SIZE RTGLC_ABSENT(GL_PIXEL_MAP_B_TO_B_SIZE, "GL_PIXEL_MAP_B_TO_B_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_A_TO_A_SIZE
#define GL_PIXEL_MAP_A_TO_A_SIZE RT_PIXEL_MAP_A_TO_A_SIZE
#else
#define GL_PIXEL_MAP_A_TO_A_SIZE RTGLC_ABSENT(GL_PIXEL_MAP_A_TO_A_SIZE, "GL_PIXEL_MAP_A_TO_A_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_S_TO_S
#define GL_PIXEL_MAP_S_TO_S RT_PIXEL_MAP_S_TO_S
#else
#define GL_PIXEL_MAP_S_TO_S RTGLC_ABSENT(GL_PIXEL_MAP_S_TO_S, "GL_PIXEL_MAP_S_TO_S: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_I_TO_I
#define GL_PIXEL_MAP_I_TO_I RT_PIXEL_MAP_I_TO_I
#else
#define GL_PIXEL_MAP_I_TO_I RTGLC_ABSENT(GL_PIXEL_MAP_I_TO_I, "GL_PIXEL_MAP_I_TO_I: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_I_TO_R
#define GL_PIXEL_MAP_I_TO_R RT_PIXEL_MAP_I_TO_R
#else
#define GL_PIXEL_MAP_I_TO_R RTGLC_ABSENT(GL_PIXEL_MAP_I_TO_R, "GL_PIXEL_MAP_I_TO_R: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_I_TO_G
#define GL_PIXEL_MAP_I_TO_G RT_PIXEL_MAP_I_TO_G
#else
#define GL_PIXEL_MAP_I_TO_G RTGLC_ABSENT(GL_PIXEL_MAP_I_TO_G, "GL_PIXEL_MAP_I_TO_G: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_I_TO_B
#define GL_PIXEL_MAP_I_TO_B RT_PIXEL_MAP_I_TO_B
#else
#define GL_PIXEL_MAP_I_TO_B RTGLC_ABSENT(GL_PIXEL_MAP_I_TO_B, "GL_PIXEL_MAP_I_TO_B: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_I_TO_A
#define GL_PIXEL_MAP_I_TO_A RT_PIXEL_MAP_I_TO_A
#else
#define GL_PIXEL_MAP_I_TO_A RTGLC_ABSENT(GL_PIXEL_MAP_I_TO_A, "GL_PIXEL_MAP_I_TO_A: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_R_TO_R
#define GL_PIXEL_MAP_R_TO_R RT_PIXEL_MAP_R_TO_R
#else
#define GL_PIXEL_MAP_R_TO_R RTGLC_ABSENT(GL_PIXEL_MAP_R_TO_R, "GL_PIXEL_MAP_R_TO_R: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_G_TO_G
#define GL_PIXEL_MAP_G_TO_G RT_PIXEL_MAP_G_TO_G
#else
#define GL_PIXEL_MAP_G_TO_G RTGLC_ABSENT(GL_PIXEL_MAP_G_TO_G, "GL_PIXEL_MAP_G_TO_G: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_B_TO_B
#define GL_PIXEL_MAP_B_TO_B RT_PIXEL_MAP_B_TO_B
#else
#define GL_PIXEL_MAP_B_TO_B RTGLC_ABSENT(GL_PIXEL_MAP_B_TO_B, "GL_PIXEL_MAP_B_TO_B: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MAP_A_TO_A
#define GL_PIXEL_MAP_A_TO_A RT_PIXEL_MAP_A_TO_A
#else
#define GL_PIXEL_MAP_A_TO_A RTGLC_ABSENT(GL_PIXEL_MAP_A_TO_A, "GL_PIXEL_MAP_A_TO_A: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ZOOM_X
#define GL_ZOOM_X RT_ZOOM_X
#else
#define GL_ZOOM_X RTGLC_ABSENT(GL_ZOOM_X, "GL_ZOOM_X: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ZOOM_Y
#define GL_ZOOM_Y RT_ZOOM_Y
#else
#define GL_ZOOM_Y RTGLC_ABSENT(GL_ZOOM_Y, "GL_ZOOM_Y: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_1D
#define GL_TEXTURE_1D RT_TEXTURE_1D
#else
#define GL_TEXTURE_1D RTGLC_ABSENT(GL_TEXTURE_1D, "GL_TEXTURE_1D: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_BORDER_COLOR
#define GL_TEXTURE_BORDER_COLOR RT_TEXTURE_BORDER_COLOR
#else
#define GL_TEXTURE_BORDER_COLOR RTGLC_ABSENT(GL_TEXTURE_BORDER_COLOR, "GL_TEXTURE_BORDER_COLOR: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_WIDTH
#define GL_TEXTURE_WIDTH RT_TEXTURE_WIDTH
#else
#define GL_TEXTURE_WIDTH RTGLC_ABSENT(GL_TEXTURE_WIDTH, "GL_TEXTURE_WIDTH: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_HEIGHT
#define GL_TEXTURE_HEIGHT RT_TEXTURE_HEIGHT
#else
#define GL_TEXTURE_HEIGHT RTGLC_ABSENT(GL_TEXTURE_HEIGHT, "GL_TEXTURE_HEIGHT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_BORDER
#define GL_TEXTURE_BORDER RT_TEXTURE_BORDER
#else
#define GL_TEXTURE_BORDER RTGLC_ABSENT(GL_TEXTURE_BORDER, "GL_TEXTURE_BORDER: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_COMPONENTS
#define GL_TEXTURE_COMPONENTS RT_TEXTURE_COMPONENTS
#else
#define GL_TEXTURE_COMPONENTS RTGLC_ABSENT(GL_TEXTURE_COMPONENTS, "GL_TEXTURE_COMPONENTS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_RED_SIZE
#define GL_TEXTURE_RED_SIZE RT_TEXTURE_RED_SIZE
#else
#define GL_TEXTURE_RED_SIZE RTGLC_ABSENT(GL_TEXTURE_RED_SIZE, "GL_TEXTURE_RED_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_GREEN_SIZE
#define GL_TEXTURE_GREEN_SIZE RT_TEXTURE_GREEN_SIZE
#else
#define GL_TEXTURE_GREEN_SIZE RTGLC_ABSENT(GL_TEXTURE_GREEN_SIZE, "GL_TEXTURE_GREEN_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_BLUE_SIZE
#define GL_TEXTURE_BLUE_SIZE RT_TEXTURE_BLUE_SIZE
#else
#define GL_TEXTURE_BLUE_SIZE RTGLC_ABSENT(GL_TEXTURE_BLUE_SIZE, "GL_TEXTURE_BLUE_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_ALPHA_SIZE
#define GL_TEXTURE_ALPHA_SIZE RT_TEXTURE_ALPHA_SIZE
#else
#define GL_TEXTURE_ALPHA_SIZE RTGLC_ABSENT(GL_TEXTURE_ALPHA_SIZE, "GL_TEXTURE_ALPHA_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_LUMINANCE_SIZE
#define GL_TEXTURE_LUMINANCE_SIZE RT_TEXTURE_LUMINANCE_SIZE
#else
#define GL_TEXTURE_LUMINANCE_SIZE RTGLC_ABSENT(GL_TEXTURE_LUMINANCE_SIZE, "GL_TEXTURE_LUMINANCE_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_INTENSITY_SIZE
#define GL_TEXTURE_INTENSITY_SIZE RT_TEXTURE_INTENSITY_SIZE
#else
#define GL_TEXTURE_INTENSITY_SIZE RTGLC_ABSENT(GL_TEXTURE_INTENSITY_SIZE, "GL_TEXTURE_INTENSITY_SIZE: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_CURRENT_BIT
#define GL_CURRENT_BIT RT_CURRENT_BIT
#else
#define GL_CURRENT_BIT RTGLC_ABSENT(GL_CURRENT_BIT, "GL_CURRENT_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_POINT_BIT
#define GL_POINT_BIT RT_POINT_BIT
#else
#define GL_POINT_BIT RTGLC_ABSENT(GL_POINT_BIT, "GL_POINT_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LINE_BIT
#define GL_LINE_BIT RT_LINE_BIT
#else
#define GL_LINE_BIT RTGLC_ABSENT(GL_LINE_BIT, "GL_LINE_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_POLYGON_BIT
#define GL_POLYGON_BIT RT_POLYGON_BIT
#else
#define GL_POLYGON_BIT RTGLC_ABSENT(GL_POLYGON_BIT, "GL_POLYGON_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_POLYGON_STIPPLE_BIT
#define GL_POLYGON_STIPPLE_BIT RT_POLYGON_STIPPLE_BIT
#else
#define GL_POLYGON_STIPPLE_BIT RTGLC_ABSENT(GL_POLYGON_STIPPLE_BIT, "GL_POLYGON_STIPPLE_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PIXEL_MODE_BIT
#define GL_PIXEL_MODE_BIT RT_PIXEL_MODE_BIT
#else
#define GL_PIXEL_MODE_BIT RTGLC_ABSENT(GL_PIXEL_MODE_BIT, "GL_PIXEL_MODE_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LIGHTING_BIT
#define GL_LIGHTING_BIT RT_LIGHTING_BIT
#else
#define GL_LIGHTING_BIT RTGLC_ABSENT(GL_LIGHTING_BIT, "GL_LIGHTING_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_FOG_BIT
#define GL_FOG_BIT RT_FOG_BIT
#else
#define GL_FOG_BIT RTGLC_ABSENT(GL_FOG_BIT, "GL_FOG_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_VIEWPORT_BIT
#define GL_VIEWPORT_BIT RT_VIEWPORT_BIT
#else
#define GL_VIEWPORT_BIT RTGLC_ABSENT(GL_VIEWPORT_BIT, "GL_VIEWPORT_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TRANSFORM_BIT
#define GL_TRANSFORM_BIT RT_TRANSFORM_BIT
#else
#define GL_TRANSFORM_BIT RTGLC_ABSENT(GL_TRANSFORM_BIT, "GL_TRANSFORM_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ENABLE_BIT
#define GL_ENABLE_BIT RT_ENABLE_BIT
#else
#define GL_ENABLE_BIT RTGLC_ABSENT(GL_ENABLE_BIT, "GL_ENABLE_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_HINT_BIT
#define GL_HINT_BIT RT_HINT_BIT
#else
#define GL_HINT_BIT RTGLC_ABSENT(GL_HINT_BIT, "GL_HINT_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_EVAL_BIT
#define GL_EVAL_BIT RT_EVAL_BIT
#else
#define GL_EVAL_BIT RTGLC_ABSENT(GL_EVAL_BIT, "GL_EVAL_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LIST_BIT
#define GL_LIST_BIT RT_LIST_BIT
#else
#define GL_LIST_BIT RTGLC_ABSENT(GL_LIST_BIT, "GL_LIST_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_BIT
#define GL_TEXTURE_BIT RT_TEXTURE_BIT
#else
#define GL_TEXTURE_BIT RTGLC_ABSENT(GL_TEXTURE_BIT, "GL_TEXTURE_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_SCISSOR_BIT
#define GL_SCISSOR_BIT RT_SCISSOR_BIT
#else
#define GL_SCISSOR_BIT RTGLC_ABSENT(GL_SCISSOR_BIT, "GL_SCISSOR_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ALL_ATTRIB_BITS
#define GL_ALL_ATTRIB_BITS RT_ALL_ATTRIB_BITS
#else
#define GL_ALL_ATTRIB_BITS RTGLC_ABSENT(GL_ALL_ATTRIB_BITS, "GL_ALL_ATTRIB_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PROXY_TEXTURE_1D
#define GL_PROXY_TEXTURE_1D RT_PROXY_TEXTURE_1D
#else
#define GL_PROXY_TEXTURE_1D RTGLC_ABSENT(GL_PROXY_TEXTURE_1D, "GL_PROXY_TEXTURE_1D: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_PROXY_TEXTURE_2D
#define GL_PROXY_TEXTURE_2D RT_PROXY_TEXTURE_2D
#else
#define GL_PROXY_TEXTURE_2D RTGLC_ABSENT(GL_PROXY_TEXTURE_2D, "GL_PROXY_TEXTURE_2D: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_PRIORITY
#define GL_TEXTURE_PRIORITY RT_TEXTURE_PRIORITY
#else
#define GL_TEXTURE_PRIORITY RTGLC_ABSENT(GL_TEXTURE_PRIORITY, "GL_TEXTURE_PRIORITY: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_RESIDENT
#define GL_TEXTURE_RESIDENT RT_TEXTURE_RESIDENT
#else
#define GL_TEXTURE_RESIDENT RTGLC_ABSENT(GL_TEXTURE_RESIDENT, "GL_TEXTURE_RESIDENT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_BINDING_1D
#define GL_TEXTURE_BINDING_1D RT_TEXTURE_BINDING_1D
#else
#define GL_TEXTURE_BINDING_1D RTGLC_ABSENT(GL_TEXTURE_BINDING_1D, "GL_TEXTURE_BINDING_1D: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_TEXTURE_INTERNAL_FORMAT
#define GL_TEXTURE_INTERNAL_FORMAT RT_TEXTURE_INTERNAL_FORMAT
#else
#define GL_TEXTURE_INTERNAL_FORMAT RTGLC_ABSENT(GL_TEXTURE_INTERNAL_FORMAT, "GL_TEXTURE_INTERNAL_FORMAT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ALPHA4
#define GL_ALPHA4 RT_ALPHA4
#else
#define GL_ALPHA4 RTGLC_ABSENT(GL_ALPHA4, "GL_ALPHA4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ALPHA8
#define GL_ALPHA8 RT_ALPHA8
#else
#define GL_ALPHA8 RTGLC_ABSENT(GL_ALPHA8, "GL_ALPHA8: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ALPHA12
#define GL_ALPHA12 RT_ALPHA12
#else
#define GL_ALPHA12 RTGLC_ABSENT(GL_ALPHA12, "GL_ALPHA12: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ALPHA16
#define GL_ALPHA16 RT_ALPHA16
#else
#define GL_ALPHA16 RTGLC_ABSENT(GL_ALPHA16, "GL_ALPHA16: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LUMINANCE4
#define GL_LUMINANCE4 RT_LUMINANCE4
#else
#define GL_LUMINANCE4 RTGLC_ABSENT(GL_LUMINANCE4, "GL_LUMINANCE4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LUMINANCE8
#define GL_LUMINANCE8 RT_LUMINANCE8
#else
#define GL_LUMINANCE8 RTGLC_ABSENT(GL_LUMINANCE8, "GL_LUMINANCE8: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LUMINANCE12
#define GL_LUMINANCE12 RT_LUMINANCE12
#else
#define GL_LUMINANCE12 RTGLC_ABSENT(GL_LUMINANCE12, "GL_LUMINANCE12: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LUMINANCE16
#define GL_LUMINANCE16 RT_LUMINANCE16
#else
#define GL_LUMINANCE16 RTGLC_ABSENT(GL_LUMINANCE16, "GL_LUMINANCE16: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LUMINANCE4_ALPHA4
#define GL_LUMINANCE4_ALPHA4 RT_LUMINANCE4_ALPHA4
#else
#define GL_LUMINANCE4_ALPHA4 RTGLC_ABSENT(GL_LUMINANCE4_ALPHA4, "GL_LUMINANCE4_ALPHA4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LUMINANCE6_ALPHA2
#define GL_LUMINANCE6_ALPHA2 RT_LUMINANCE6_ALPHA2
#else
#define GL_LUMINANCE6_ALPHA2 RTGLC_ABSENT(GL_LUMINANCE6_ALPHA2, "GL_LUMINANCE6_ALPHA2: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LUMINANCE8_ALPHA8
#define GL_LUMINANCE8_ALPHA8 RT_LUMINANCE8_ALPHA8
#else
#define GL_LUMINANCE8_ALPHA8 RTGLC_ABSENT(GL_LUMINANCE8_ALPHA8, "GL_LUMINANCE8_ALPHA8: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LUMINANCE12_ALPHA4
#define GL_LUMINANCE12_ALPHA4 RT_LUMINANCE12_ALPHA4
#else
#define GL_LUMINANCE12_ALPHA4 RTGLC_ABSENT(GL_LUMINANCE12_ALPHA4, "GL_LUMINANCE12_ALPHA4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LUMINANCE12_ALPHA12
#define GL_LUMINANCE12_ALPHA12 RT_LUMINANCE12_ALPHA12
#else
#define GL_LUMINANCE12_ALPHA12 RTGLC_ABSENT(GL_LUMINANCE12_ALPHA12, "GL_LUMINANCE12_ALPHA12: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_LUMINANCE16_ALPHA16
#define GL_LUMINANCE16_ALPHA16 RT_LUMINANCE16_ALPHA16
#else
#define GL_LUMINANCE16_ALPHA16 RTGLC_ABSENT(GL_LUMINANCE16_ALPHA16, "GL_LUMINANCE16_ALPHA16: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INTENSITY4
#define GL_INTENSITY4 RT_INTENSITY4
#else
#define GL_INTENSITY4 RTGLC_ABSENT(GL_INTENSITY4, "GL_INTENSITY4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INTENSITY8
#define GL_INTENSITY8 RT_INTENSITY8
#else
#define GL_INTENSITY8 RTGLC_ABSENT(GL_INTENSITY8, "GL_INTENSITY8: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INTENSITY12
#define GL_INTENSITY12 RT_INTENSITY12
#else
#define GL_INTENSITY12 RTGLC_ABSENT(GL_INTENSITY12, "GL_INTENSITY12: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_INTENSITY16
#define GL_INTENSITY16 RT_INTENSITY16
#else
#define GL_INTENSITY16 RTGLC_ABSENT(GL_INTENSITY16, "GL_INTENSITY16: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_R3_G3_B2
#define GL_R3_G3_B2 RT_R3_G3_B2
#else
#define GL_R3_G3_B2 RTGLC_ABSENT(GL_R3_G3_B2, "GL_R3_G3_B2: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGB4
#define GL_RGB4 RT_RGB4
#else
#define GL_RGB4 RTGLC_ABSENT(GL_RGB4, "GL_RGB4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGB5
#define GL_RGB5 RT_RGB5
#else
#define GL_RGB5 RTGLC_ABSENT(GL_RGB5, "GL_RGB5: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGB8
#define GL_RGB8 RT_RGB8
#else
#define GL_RGB8 RTGLC_ABSENT(GL_RGB8, "GL_RGB8: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGB10
#define GL_RGB10 RT_RGB10
#else
#define GL_RGB10 RTGLC_ABSENT(GL_RGB10, "GL_RGB10: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGB12
#define GL_RGB12 RT_RGB12
#else
#define GL_RGB12 RTGLC_ABSENT(GL_RGB12, "GL_RGB12: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGB16
#define GL_RGB16 RT_RGB16
#else
#define GL_RGB16 RTGLC_ABSENT(GL_RGB16, "GL_RGB16: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGBA2
#define GL_RGBA2 RT_RGBA2
#else
#define GL_RGBA2 RTGLC_ABSENT(GL_RGBA2, "GL_RGBA2: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGBA4
#define GL_RGBA4 RT_RGBA4
#else
#define GL_RGBA4 RTGLC_ABSENT(GL_RGBA4, "GL_RGBA4: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGB5_A1
#define GL_RGB5_A1 RT_RGB5_A1
#else
#define GL_RGB5_A1 RTGLC_ABSENT(GL_RGB5_A1, "GL_RGB5_A1: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGBA8
#define GL_RGBA8 RT_RGBA8
#else
#define GL_RGBA8 RTGLC_ABSENT(GL_RGBA8, "GL_RGBA8: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGB10_A2
#define GL_RGB10_A2 RT_RGB10_A2
#else
#define GL_RGB10_A2 RTGLC_ABSENT(GL_RGB10_A2, "GL_RGB10_A2: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGBA12
#define GL_RGBA12 RT_RGBA12
#else
#define GL_RGBA12 RTGLC_ABSENT(GL_RGBA12, "GL_RGBA12: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_RGBA16
#define GL_RGBA16 RT_RGBA16
#else
#define GL_RGBA16 RTGLC_ABSENT(GL_RGBA16, "GL_RGBA16: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_CLIENT_PIXEL_STORE_BIT
#define GL_CLIENT_PIXEL_STORE_BIT RT_CLIENT_PIXEL_STORE_BIT
#else
#define GL_CLIENT_PIXEL_STORE_BIT RTGLC_ABSENT(GL_CLIENT_PIXEL_STORE_BIT, "GL_CLIENT_PIXEL_STORE_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_CLIENT_VERTEX_ARRAY_BIT
#define GL_CLIENT_VERTEX_ARRAY_BIT RT_CLIENT_VERTEX_ARRAY_BIT
#else
#define GL_CLIENT_VERTEX_ARRAY_BIT RTGLC_ABSENT(GL_CLIENT_VERTEX_ARRAY_BIT, "GL_CLIENT_VERTEX_ARRAY_BIT: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_ALL_CLIENT_ATTRIB_BITS
#define GL_ALL_CLIENT_ATTRIB_BITS RT_ALL_CLIENT_ATTRIB_BITS
#else
#define GL_ALL_CLIENT_ATTRIB_BITS RTGLC_ABSENT(GL_ALL_CLIENT_ATTRIB_BITS, "GL_ALL_CLIENT_ATTRIB_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif
#ifdef RT_CLIENT_ALL_ATTRIB_BITS
#define GL_CLIENT_ALL_ATTRIB_BITS RT_CLIENT_ALL_ATTRIB_BITS
#else
#define GL_CLIENT_ALL_ATTRIB_BITS RTGLC_ABSENT(GL_CLIENT_ALL_ATTRIB_BITS, "GL_CLIENT_ALL_ATTRIB_BITS: no Tracelist equivalent (docs/glcompat.md)")
#endif

/* ---- The GL 1.2 names GL 1.x programs commonly use ------------------- */
#define GL_CLAMP_TO_EDGE RT_CLAMP_TO_EDGE
#define GL_RESCALE_NORMAL RT_RESCALE_NORMAL
#define GL_LIGHT_MODEL_COLOR_CONTROL RT_LIGHT_MODEL_COLOR_CONTROL
#define GL_SINGLE_COLOR RT_SINGLE_COLOR
#define GL_SEPARATE_SPECULAR_COLOR RT_SEPARATE_SPECULAR_COLOR
/* glDrawRangeElements: start and end only promise the index range. */
static inline void rtglc_DrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                           GLenum type, const GLvoid *indices)
{
    (void)start;
    (void)end;
    rtDrawElements(mode, count, type, indices);
}
#define glDrawRangeElements rtglc_DrawRangeElements

/* ---- GLU -------------------------------------------------------------- */
typedef RTUquadric GLUquadric;
typedef RTUquadric GLUquadricObj;
#define gluCylinder rtuCylinder
#define gluDeleteQuadric rtuDeleteQuadric
#define gluDisk rtuDisk
#define gluLookAt rtuLookAt
#define gluNewQuadric rtuNewQuadric
#define gluOrtho2D rtuOrtho2D
#define gluPartialDisk rtuPartialDisk
#define gluPerspective rtuPerspective
#define gluPickMatrix rtuPickMatrix
#define gluProject rtuProject
#define gluQuadricDrawStyle rtuQuadricDrawStyle
#define gluQuadricNormals rtuQuadricNormals
#define gluQuadricOrientation rtuQuadricOrientation
#define gluQuadricTexture rtuQuadricTexture
#define gluSphere rtuSphere
#define gluUnProject rtuUnProject
#define gluErrorString rtglc_uErrorString
#define gluGetString rtglc_uGetString
#define gluBuild2DMipmaps rtglc_uBuild2DMipmaps
#define gluBeginCurve RTGLC_ABSENT(gluBeginCurve, "gluBeginCurve: no NURBS (docs/glcompat.md)")
#define gluBeginPolygon RTGLC_ABSENT(gluBeginPolygon, "gluBeginPolygon: no tessellator (docs/glcompat.md)")
#define gluBeginSurface RTGLC_ABSENT(gluBeginSurface, "gluBeginSurface: no NURBS (docs/glcompat.md)")
#define gluBeginTrim RTGLC_ABSENT(gluBeginTrim, "gluBeginTrim: no NURBS (docs/glcompat.md)")
#define gluBuild1DMipmapLevels RTGLC_ABSENT(gluBuild1DMipmapLevels, "gluBuild1DMipmapLevels: not in rtu (docs/glcompat.md)")
#define gluBuild1DMipmaps RTGLC_ABSENT(gluBuild1DMipmaps, "gluBuild1DMipmaps: not in rtu (docs/glcompat.md)")
#define gluBuild2DMipmapLevels RTGLC_ABSENT(gluBuild2DMipmapLevels, "gluBuild2DMipmapLevels: not in rtu (docs/glcompat.md)")
#define gluBuild3DMipmapLevels RTGLC_ABSENT(gluBuild3DMipmapLevels, "gluBuild3DMipmapLevels: not in rtu (docs/glcompat.md)")
#define gluBuild3DMipmaps RTGLC_ABSENT(gluBuild3DMipmaps, "gluBuild3DMipmaps: not in rtu (docs/glcompat.md)")
#define gluCheckExtension RTGLC_ABSENT(gluCheckExtension, "gluCheckExtension: not in rtu (docs/glcompat.md)")
#define gluDeleteNurbsRenderer RTGLC_ABSENT(gluDeleteNurbsRenderer, "gluDeleteNurbsRenderer: no NURBS (docs/glcompat.md)")
#define gluDeleteTess RTGLC_ABSENT(gluDeleteTess, "gluDeleteTess: no tessellator (docs/glcompat.md)")
#define gluEndCurve RTGLC_ABSENT(gluEndCurve, "gluEndCurve: no NURBS (docs/glcompat.md)")
#define gluEndPolygon RTGLC_ABSENT(gluEndPolygon, "gluEndPolygon: no tessellator (docs/glcompat.md)")
#define gluEndSurface RTGLC_ABSENT(gluEndSurface, "gluEndSurface: no NURBS (docs/glcompat.md)")
#define gluEndTrim RTGLC_ABSENT(gluEndTrim, "gluEndTrim: no NURBS (docs/glcompat.md)")
#define gluGetNurbsProperty RTGLC_ABSENT(gluGetNurbsProperty, "gluGetNurbsProperty: no NURBS (docs/glcompat.md)")
#define gluGetTessProperty RTGLC_ABSENT(gluGetTessProperty, "gluGetTessProperty: no tessellator (docs/glcompat.md)")
#define gluLoadSamplingMatrices RTGLC_ABSENT(gluLoadSamplingMatrices, "gluLoadSamplingMatrices: no NURBS (docs/glcompat.md)")
#define gluNewNurbsRenderer RTGLC_ABSENT(gluNewNurbsRenderer, "gluNewNurbsRenderer: no NURBS (docs/glcompat.md)")
#define gluNewTess RTGLC_ABSENT(gluNewTess, "gluNewTess: no tessellator (docs/glcompat.md)")
#define gluNextContour RTGLC_ABSENT(gluNextContour, "gluNextContour: no tessellator (docs/glcompat.md)")
#define gluNurbsCallback RTGLC_ABSENT(gluNurbsCallback, "gluNurbsCallback: no NURBS (docs/glcompat.md)")
#define gluNurbsCallbackData RTGLC_ABSENT(gluNurbsCallbackData, "gluNurbsCallbackData: no NURBS (docs/glcompat.md)")
#define gluNurbsCallbackDataEXT RTGLC_ABSENT(gluNurbsCallbackDataEXT, "gluNurbsCallbackDataEXT: no NURBS (docs/glcompat.md)")
#define gluNurbsCurve RTGLC_ABSENT(gluNurbsCurve, "gluNurbsCurve: no NURBS (docs/glcompat.md)")
#define gluNurbsProperty RTGLC_ABSENT(gluNurbsProperty, "gluNurbsProperty: no NURBS (docs/glcompat.md)")
#define gluNurbsSurface RTGLC_ABSENT(gluNurbsSurface, "gluNurbsSurface: no NURBS (docs/glcompat.md)")
#define gluPwlCurve RTGLC_ABSENT(gluPwlCurve, "gluPwlCurve: no NURBS (docs/glcompat.md)")
#define gluQuadricCallback RTGLC_ABSENT(gluQuadricCallback, "gluQuadricCallback: not in rtu (docs/glcompat.md)")
#define gluScaleImage RTGLC_ABSENT(gluScaleImage, "gluScaleImage: not in rtu (docs/glcompat.md)")
#define gluTessBeginContour RTGLC_ABSENT(gluTessBeginContour, "gluTessBeginContour: no tessellator (docs/glcompat.md)")
#define gluTessBeginPolygon RTGLC_ABSENT(gluTessBeginPolygon, "gluTessBeginPolygon: no tessellator (docs/glcompat.md)")
#define gluTessCallback RTGLC_ABSENT(gluTessCallback, "gluTessCallback: no tessellator (docs/glcompat.md)")
#define gluTessEndContour RTGLC_ABSENT(gluTessEndContour, "gluTessEndContour: no tessellator (docs/glcompat.md)")
#define gluTessEndPolygon RTGLC_ABSENT(gluTessEndPolygon, "gluTessEndPolygon: no tessellator (docs/glcompat.md)")
#define gluTessNormal RTGLC_ABSENT(gluTessNormal, "gluTessNormal: no tessellator (docs/glcompat.md)")
#define gluTessProperty RTGLC_ABSENT(gluTessProperty, "gluTessProperty: no tessellator (docs/glcompat.md)")
#define gluTessVertex RTGLC_ABSENT(gluTessVertex, "gluTessVertex: no tessellator (docs/glcompat.md)")
#define gluUnProject4 RTGLC_ABSENT(gluUnProject4, "gluUnProject4: not in rtu (docs/glcompat.md)")
#define GLU_FALSE RT_FALSE
#define GLU_TRUE RT_TRUE
#define GLU_VERSION 100800
#define GLU_EXTENSIONS 100801
#ifdef RTU_INVALID_ENUM
#define GLU_INVALID_ENUM RTU_INVALID_ENUM
#else
#define GLU_INVALID_ENUM RTGLC_ABSENT(GLU_INVALID_ENUM, "GLU_INVALID_ENUM: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_INVALID_VALUE
#define GLU_INVALID_VALUE RTU_INVALID_VALUE
#else
#define GLU_INVALID_VALUE RTGLC_ABSENT(GLU_INVALID_VALUE, "GLU_INVALID_VALUE: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_OUT_OF_MEMORY
#define GLU_OUT_OF_MEMORY RTU_OUT_OF_MEMORY
#else
#define GLU_OUT_OF_MEMORY RTGLC_ABSENT(GLU_OUT_OF_MEMORY, "GLU_OUT_OF_MEMORY: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_INCOMPATIBLE_GL_VERSION
#define GLU_INCOMPATIBLE_GL_VERSION RTU_INCOMPATIBLE_GL_VERSION
#else
#define GLU_INCOMPATIBLE_GL_VERSION RTGLC_ABSENT(GLU_INCOMPATIBLE_GL_VERSION, "GLU_INCOMPATIBLE_GL_VERSION: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_INVALID_OPERATION
#define GLU_INVALID_OPERATION RTU_INVALID_OPERATION
#else
#define GLU_INVALID_OPERATION RTGLC_ABSENT(GLU_INVALID_OPERATION, "GLU_INVALID_OPERATION: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_OUTLINE_POLYGON
#define GLU_OUTLINE_POLYGON RTU_OUTLINE_POLYGON
#else
#define GLU_OUTLINE_POLYGON RTGLC_ABSENT(GLU_OUTLINE_POLYGON, "GLU_OUTLINE_POLYGON: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_OUTLINE_PATCH
#define GLU_OUTLINE_PATCH RTU_OUTLINE_PATCH
#else
#define GLU_OUTLINE_PATCH RTGLC_ABSENT(GLU_OUTLINE_PATCH, "GLU_OUTLINE_PATCH: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR
#define GLU_NURBS_ERROR RTU_NURBS_ERROR
#else
#define GLU_NURBS_ERROR RTGLC_ABSENT(GLU_NURBS_ERROR, "GLU_NURBS_ERROR: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_ERROR
#define GLU_ERROR RTU_ERROR
#else
#define GLU_ERROR RTGLC_ABSENT(GLU_ERROR, "GLU_ERROR: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_BEGIN
#define GLU_NURBS_BEGIN RTU_NURBS_BEGIN
#else
#define GLU_NURBS_BEGIN RTGLC_ABSENT(GLU_NURBS_BEGIN, "GLU_NURBS_BEGIN: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_BEGIN_EXT
#define GLU_NURBS_BEGIN_EXT RTU_NURBS_BEGIN_EXT
#else
#define GLU_NURBS_BEGIN_EXT RTGLC_ABSENT(GLU_NURBS_BEGIN_EXT, "GLU_NURBS_BEGIN_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_VERTEX
#define GLU_NURBS_VERTEX RTU_NURBS_VERTEX
#else
#define GLU_NURBS_VERTEX RTGLC_ABSENT(GLU_NURBS_VERTEX, "GLU_NURBS_VERTEX: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_VERTEX_EXT
#define GLU_NURBS_VERTEX_EXT RTU_NURBS_VERTEX_EXT
#else
#define GLU_NURBS_VERTEX_EXT RTGLC_ABSENT(GLU_NURBS_VERTEX_EXT, "GLU_NURBS_VERTEX_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_NORMAL
#define GLU_NURBS_NORMAL RTU_NURBS_NORMAL
#else
#define GLU_NURBS_NORMAL RTGLC_ABSENT(GLU_NURBS_NORMAL, "GLU_NURBS_NORMAL: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_NORMAL_EXT
#define GLU_NURBS_NORMAL_EXT RTU_NURBS_NORMAL_EXT
#else
#define GLU_NURBS_NORMAL_EXT RTGLC_ABSENT(GLU_NURBS_NORMAL_EXT, "GLU_NURBS_NORMAL_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_COLOR
#define GLU_NURBS_COLOR RTU_NURBS_COLOR
#else
#define GLU_NURBS_COLOR RTGLC_ABSENT(GLU_NURBS_COLOR, "GLU_NURBS_COLOR: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_COLOR_EXT
#define GLU_NURBS_COLOR_EXT RTU_NURBS_COLOR_EXT
#else
#define GLU_NURBS_COLOR_EXT RTGLC_ABSENT(GLU_NURBS_COLOR_EXT, "GLU_NURBS_COLOR_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_TEXTURE_COORD
#define GLU_NURBS_TEXTURE_COORD RTU_NURBS_TEXTURE_COORD
#else
#define GLU_NURBS_TEXTURE_COORD RTGLC_ABSENT(GLU_NURBS_TEXTURE_COORD, "GLU_NURBS_TEXTURE_COORD: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_TEX_COORD_EXT
#define GLU_NURBS_TEX_COORD_EXT RTU_NURBS_TEX_COORD_EXT
#else
#define GLU_NURBS_TEX_COORD_EXT RTGLC_ABSENT(GLU_NURBS_TEX_COORD_EXT, "GLU_NURBS_TEX_COORD_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_END
#define GLU_NURBS_END RTU_NURBS_END
#else
#define GLU_NURBS_END RTGLC_ABSENT(GLU_NURBS_END, "GLU_NURBS_END: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_END_EXT
#define GLU_NURBS_END_EXT RTU_NURBS_END_EXT
#else
#define GLU_NURBS_END_EXT RTGLC_ABSENT(GLU_NURBS_END_EXT, "GLU_NURBS_END_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_BEGIN_DATA
#define GLU_NURBS_BEGIN_DATA RTU_NURBS_BEGIN_DATA
#else
#define GLU_NURBS_BEGIN_DATA RTGLC_ABSENT(GLU_NURBS_BEGIN_DATA, "GLU_NURBS_BEGIN_DATA: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_BEGIN_DATA_EXT
#define GLU_NURBS_BEGIN_DATA_EXT RTU_NURBS_BEGIN_DATA_EXT
#else
#define GLU_NURBS_BEGIN_DATA_EXT RTGLC_ABSENT(GLU_NURBS_BEGIN_DATA_EXT, "GLU_NURBS_BEGIN_DATA_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_VERTEX_DATA
#define GLU_NURBS_VERTEX_DATA RTU_NURBS_VERTEX_DATA
#else
#define GLU_NURBS_VERTEX_DATA RTGLC_ABSENT(GLU_NURBS_VERTEX_DATA, "GLU_NURBS_VERTEX_DATA: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_VERTEX_DATA_EXT
#define GLU_NURBS_VERTEX_DATA_EXT RTU_NURBS_VERTEX_DATA_EXT
#else
#define GLU_NURBS_VERTEX_DATA_EXT RTGLC_ABSENT(GLU_NURBS_VERTEX_DATA_EXT, "GLU_NURBS_VERTEX_DATA_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_NORMAL_DATA
#define GLU_NURBS_NORMAL_DATA RTU_NURBS_NORMAL_DATA
#else
#define GLU_NURBS_NORMAL_DATA RTGLC_ABSENT(GLU_NURBS_NORMAL_DATA, "GLU_NURBS_NORMAL_DATA: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_NORMAL_DATA_EXT
#define GLU_NURBS_NORMAL_DATA_EXT RTU_NURBS_NORMAL_DATA_EXT
#else
#define GLU_NURBS_NORMAL_DATA_EXT RTGLC_ABSENT(GLU_NURBS_NORMAL_DATA_EXT, "GLU_NURBS_NORMAL_DATA_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_COLOR_DATA
#define GLU_NURBS_COLOR_DATA RTU_NURBS_COLOR_DATA
#else
#define GLU_NURBS_COLOR_DATA RTGLC_ABSENT(GLU_NURBS_COLOR_DATA, "GLU_NURBS_COLOR_DATA: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_COLOR_DATA_EXT
#define GLU_NURBS_COLOR_DATA_EXT RTU_NURBS_COLOR_DATA_EXT
#else
#define GLU_NURBS_COLOR_DATA_EXT RTGLC_ABSENT(GLU_NURBS_COLOR_DATA_EXT, "GLU_NURBS_COLOR_DATA_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_TEXTURE_COORD_DATA
#define GLU_NURBS_TEXTURE_COORD_DATA RTU_NURBS_TEXTURE_COORD_DATA
#else
#define GLU_NURBS_TEXTURE_COORD_DATA RTGLC_ABSENT(GLU_NURBS_TEXTURE_COORD_DATA, "GLU_NURBS_TEXTURE_COORD_DATA: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_TEX_COORD_DATA_EXT
#define GLU_NURBS_TEX_COORD_DATA_EXT RTU_NURBS_TEX_COORD_DATA_EXT
#else
#define GLU_NURBS_TEX_COORD_DATA_EXT RTGLC_ABSENT(GLU_NURBS_TEX_COORD_DATA_EXT, "GLU_NURBS_TEX_COORD_DATA_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_END_DATA
#define GLU_NURBS_END_DATA RTU_NURBS_END_DATA
#else
#define GLU_NURBS_END_DATA RTGLC_ABSENT(GLU_NURBS_END_DATA, "GLU_NURBS_END_DATA: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_END_DATA_EXT
#define GLU_NURBS_END_DATA_EXT RTU_NURBS_END_DATA_EXT
#else
#define GLU_NURBS_END_DATA_EXT RTGLC_ABSENT(GLU_NURBS_END_DATA_EXT, "GLU_NURBS_END_DATA_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR1
#define GLU_NURBS_ERROR1 RTU_NURBS_ERROR1
#else
#define GLU_NURBS_ERROR1 RTGLC_ABSENT(GLU_NURBS_ERROR1, "GLU_NURBS_ERROR1: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR2
#define GLU_NURBS_ERROR2 RTU_NURBS_ERROR2
#else
#define GLU_NURBS_ERROR2 RTGLC_ABSENT(GLU_NURBS_ERROR2, "GLU_NURBS_ERROR2: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR3
#define GLU_NURBS_ERROR3 RTU_NURBS_ERROR3
#else
#define GLU_NURBS_ERROR3 RTGLC_ABSENT(GLU_NURBS_ERROR3, "GLU_NURBS_ERROR3: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR4
#define GLU_NURBS_ERROR4 RTU_NURBS_ERROR4
#else
#define GLU_NURBS_ERROR4 RTGLC_ABSENT(GLU_NURBS_ERROR4, "GLU_NURBS_ERROR4: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR5
#define GLU_NURBS_ERROR5 RTU_NURBS_ERROR5
#else
#define GLU_NURBS_ERROR5 RTGLC_ABSENT(GLU_NURBS_ERROR5, "GLU_NURBS_ERROR5: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR6
#define GLU_NURBS_ERROR6 RTU_NURBS_ERROR6
#else
#define GLU_NURBS_ERROR6 RTGLC_ABSENT(GLU_NURBS_ERROR6, "GLU_NURBS_ERROR6: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR7
#define GLU_NURBS_ERROR7 RTU_NURBS_ERROR7
#else
#define GLU_NURBS_ERROR7 RTGLC_ABSENT(GLU_NURBS_ERROR7, "GLU_NURBS_ERROR7: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR8
#define GLU_NURBS_ERROR8 RTU_NURBS_ERROR8
#else
#define GLU_NURBS_ERROR8 RTGLC_ABSENT(GLU_NURBS_ERROR8, "GLU_NURBS_ERROR8: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR9
#define GLU_NURBS_ERROR9 RTU_NURBS_ERROR9
#else
#define GLU_NURBS_ERROR9 RTGLC_ABSENT(GLU_NURBS_ERROR9, "GLU_NURBS_ERROR9: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR10
#define GLU_NURBS_ERROR10 RTU_NURBS_ERROR10
#else
#define GLU_NURBS_ERROR10 RTGLC_ABSENT(GLU_NURBS_ERROR10, "GLU_NURBS_ERROR10: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR11
#define GLU_NURBS_ERROR11 RTU_NURBS_ERROR11
#else
#define GLU_NURBS_ERROR11 RTGLC_ABSENT(GLU_NURBS_ERROR11, "GLU_NURBS_ERROR11: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR12
#define GLU_NURBS_ERROR12 RTU_NURBS_ERROR12
#else
#define GLU_NURBS_ERROR12 RTGLC_ABSENT(GLU_NURBS_ERROR12, "GLU_NURBS_ERROR12: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR13
#define GLU_NURBS_ERROR13 RTU_NURBS_ERROR13
#else
#define GLU_NURBS_ERROR13 RTGLC_ABSENT(GLU_NURBS_ERROR13, "GLU_NURBS_ERROR13: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR14
#define GLU_NURBS_ERROR14 RTU_NURBS_ERROR14
#else
#define GLU_NURBS_ERROR14 RTGLC_ABSENT(GLU_NURBS_ERROR14, "GLU_NURBS_ERROR14: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR15
#define GLU_NURBS_ERROR15 RTU_NURBS_ERROR15
#else
#define GLU_NURBS_ERROR15 RTGLC_ABSENT(GLU_NURBS_ERROR15, "GLU_NURBS_ERROR15: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR16
#define GLU_NURBS_ERROR16 RTU_NURBS_ERROR16
#else
#define GLU_NURBS_ERROR16 RTGLC_ABSENT(GLU_NURBS_ERROR16, "GLU_NURBS_ERROR16: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR17
#define GLU_NURBS_ERROR17 RTU_NURBS_ERROR17
#else
#define GLU_NURBS_ERROR17 RTGLC_ABSENT(GLU_NURBS_ERROR17, "GLU_NURBS_ERROR17: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR18
#define GLU_NURBS_ERROR18 RTU_NURBS_ERROR18
#else
#define GLU_NURBS_ERROR18 RTGLC_ABSENT(GLU_NURBS_ERROR18, "GLU_NURBS_ERROR18: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR19
#define GLU_NURBS_ERROR19 RTU_NURBS_ERROR19
#else
#define GLU_NURBS_ERROR19 RTGLC_ABSENT(GLU_NURBS_ERROR19, "GLU_NURBS_ERROR19: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR20
#define GLU_NURBS_ERROR20 RTU_NURBS_ERROR20
#else
#define GLU_NURBS_ERROR20 RTGLC_ABSENT(GLU_NURBS_ERROR20, "GLU_NURBS_ERROR20: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR21
#define GLU_NURBS_ERROR21 RTU_NURBS_ERROR21
#else
#define GLU_NURBS_ERROR21 RTGLC_ABSENT(GLU_NURBS_ERROR21, "GLU_NURBS_ERROR21: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR22
#define GLU_NURBS_ERROR22 RTU_NURBS_ERROR22
#else
#define GLU_NURBS_ERROR22 RTGLC_ABSENT(GLU_NURBS_ERROR22, "GLU_NURBS_ERROR22: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR23
#define GLU_NURBS_ERROR23 RTU_NURBS_ERROR23
#else
#define GLU_NURBS_ERROR23 RTGLC_ABSENT(GLU_NURBS_ERROR23, "GLU_NURBS_ERROR23: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR24
#define GLU_NURBS_ERROR24 RTU_NURBS_ERROR24
#else
#define GLU_NURBS_ERROR24 RTGLC_ABSENT(GLU_NURBS_ERROR24, "GLU_NURBS_ERROR24: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR25
#define GLU_NURBS_ERROR25 RTU_NURBS_ERROR25
#else
#define GLU_NURBS_ERROR25 RTGLC_ABSENT(GLU_NURBS_ERROR25, "GLU_NURBS_ERROR25: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR26
#define GLU_NURBS_ERROR26 RTU_NURBS_ERROR26
#else
#define GLU_NURBS_ERROR26 RTGLC_ABSENT(GLU_NURBS_ERROR26, "GLU_NURBS_ERROR26: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR27
#define GLU_NURBS_ERROR27 RTU_NURBS_ERROR27
#else
#define GLU_NURBS_ERROR27 RTGLC_ABSENT(GLU_NURBS_ERROR27, "GLU_NURBS_ERROR27: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR28
#define GLU_NURBS_ERROR28 RTU_NURBS_ERROR28
#else
#define GLU_NURBS_ERROR28 RTGLC_ABSENT(GLU_NURBS_ERROR28, "GLU_NURBS_ERROR28: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR29
#define GLU_NURBS_ERROR29 RTU_NURBS_ERROR29
#else
#define GLU_NURBS_ERROR29 RTGLC_ABSENT(GLU_NURBS_ERROR29, "GLU_NURBS_ERROR29: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR30
#define GLU_NURBS_ERROR30 RTU_NURBS_ERROR30
#else
#define GLU_NURBS_ERROR30 RTGLC_ABSENT(GLU_NURBS_ERROR30, "GLU_NURBS_ERROR30: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR31
#define GLU_NURBS_ERROR31 RTU_NURBS_ERROR31
#else
#define GLU_NURBS_ERROR31 RTGLC_ABSENT(GLU_NURBS_ERROR31, "GLU_NURBS_ERROR31: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR32
#define GLU_NURBS_ERROR32 RTU_NURBS_ERROR32
#else
#define GLU_NURBS_ERROR32 RTGLC_ABSENT(GLU_NURBS_ERROR32, "GLU_NURBS_ERROR32: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR33
#define GLU_NURBS_ERROR33 RTU_NURBS_ERROR33
#else
#define GLU_NURBS_ERROR33 RTGLC_ABSENT(GLU_NURBS_ERROR33, "GLU_NURBS_ERROR33: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR34
#define GLU_NURBS_ERROR34 RTU_NURBS_ERROR34
#else
#define GLU_NURBS_ERROR34 RTGLC_ABSENT(GLU_NURBS_ERROR34, "GLU_NURBS_ERROR34: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR35
#define GLU_NURBS_ERROR35 RTU_NURBS_ERROR35
#else
#define GLU_NURBS_ERROR35 RTGLC_ABSENT(GLU_NURBS_ERROR35, "GLU_NURBS_ERROR35: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR36
#define GLU_NURBS_ERROR36 RTU_NURBS_ERROR36
#else
#define GLU_NURBS_ERROR36 RTGLC_ABSENT(GLU_NURBS_ERROR36, "GLU_NURBS_ERROR36: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_ERROR37
#define GLU_NURBS_ERROR37 RTU_NURBS_ERROR37
#else
#define GLU_NURBS_ERROR37 RTGLC_ABSENT(GLU_NURBS_ERROR37, "GLU_NURBS_ERROR37: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_AUTO_LOAD_MATRIX
#define GLU_AUTO_LOAD_MATRIX RTU_AUTO_LOAD_MATRIX
#else
#define GLU_AUTO_LOAD_MATRIX RTGLC_ABSENT(GLU_AUTO_LOAD_MATRIX, "GLU_AUTO_LOAD_MATRIX: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_CULLING
#define GLU_CULLING RTU_CULLING
#else
#define GLU_CULLING RTGLC_ABSENT(GLU_CULLING, "GLU_CULLING: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_SAMPLING_TOLERANCE
#define GLU_SAMPLING_TOLERANCE RTU_SAMPLING_TOLERANCE
#else
#define GLU_SAMPLING_TOLERANCE RTGLC_ABSENT(GLU_SAMPLING_TOLERANCE, "GLU_SAMPLING_TOLERANCE: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_DISPLAY_MODE
#define GLU_DISPLAY_MODE RTU_DISPLAY_MODE
#else
#define GLU_DISPLAY_MODE RTGLC_ABSENT(GLU_DISPLAY_MODE, "GLU_DISPLAY_MODE: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_PARAMETRIC_TOLERANCE
#define GLU_PARAMETRIC_TOLERANCE RTU_PARAMETRIC_TOLERANCE
#else
#define GLU_PARAMETRIC_TOLERANCE RTGLC_ABSENT(GLU_PARAMETRIC_TOLERANCE, "GLU_PARAMETRIC_TOLERANCE: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_SAMPLING_METHOD
#define GLU_SAMPLING_METHOD RTU_SAMPLING_METHOD
#else
#define GLU_SAMPLING_METHOD RTGLC_ABSENT(GLU_SAMPLING_METHOD, "GLU_SAMPLING_METHOD: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_U_STEP
#define GLU_U_STEP RTU_U_STEP
#else
#define GLU_U_STEP RTGLC_ABSENT(GLU_U_STEP, "GLU_U_STEP: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_V_STEP
#define GLU_V_STEP RTU_V_STEP
#else
#define GLU_V_STEP RTGLC_ABSENT(GLU_V_STEP, "GLU_V_STEP: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_MODE
#define GLU_NURBS_MODE RTU_NURBS_MODE
#else
#define GLU_NURBS_MODE RTGLC_ABSENT(GLU_NURBS_MODE, "GLU_NURBS_MODE: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_MODE_EXT
#define GLU_NURBS_MODE_EXT RTU_NURBS_MODE_EXT
#else
#define GLU_NURBS_MODE_EXT RTGLC_ABSENT(GLU_NURBS_MODE_EXT, "GLU_NURBS_MODE_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_TESSELLATOR
#define GLU_NURBS_TESSELLATOR RTU_NURBS_TESSELLATOR
#else
#define GLU_NURBS_TESSELLATOR RTGLC_ABSENT(GLU_NURBS_TESSELLATOR, "GLU_NURBS_TESSELLATOR: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_TESSELLATOR_EXT
#define GLU_NURBS_TESSELLATOR_EXT RTU_NURBS_TESSELLATOR_EXT
#else
#define GLU_NURBS_TESSELLATOR_EXT RTGLC_ABSENT(GLU_NURBS_TESSELLATOR_EXT, "GLU_NURBS_TESSELLATOR_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_RENDERER
#define GLU_NURBS_RENDERER RTU_NURBS_RENDERER
#else
#define GLU_NURBS_RENDERER RTGLC_ABSENT(GLU_NURBS_RENDERER, "GLU_NURBS_RENDERER: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_NURBS_RENDERER_EXT
#define GLU_NURBS_RENDERER_EXT RTU_NURBS_RENDERER_EXT
#else
#define GLU_NURBS_RENDERER_EXT RTGLC_ABSENT(GLU_NURBS_RENDERER_EXT, "GLU_NURBS_RENDERER_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_OBJECT_PARAMETRIC_ERROR
#define GLU_OBJECT_PARAMETRIC_ERROR RTU_OBJECT_PARAMETRIC_ERROR
#else
#define GLU_OBJECT_PARAMETRIC_ERROR RTGLC_ABSENT(GLU_OBJECT_PARAMETRIC_ERROR, "GLU_OBJECT_PARAMETRIC_ERROR: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_OBJECT_PARAMETRIC_ERROR_EXT
#define GLU_OBJECT_PARAMETRIC_ERROR_EXT RTU_OBJECT_PARAMETRIC_ERROR_EXT
#else
#define GLU_OBJECT_PARAMETRIC_ERROR_EXT RTGLC_ABSENT(GLU_OBJECT_PARAMETRIC_ERROR_EXT, "GLU_OBJECT_PARAMETRIC_ERROR_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_OBJECT_PATH_LENGTH
#define GLU_OBJECT_PATH_LENGTH RTU_OBJECT_PATH_LENGTH
#else
#define GLU_OBJECT_PATH_LENGTH RTGLC_ABSENT(GLU_OBJECT_PATH_LENGTH, "GLU_OBJECT_PATH_LENGTH: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_OBJECT_PATH_LENGTH_EXT
#define GLU_OBJECT_PATH_LENGTH_EXT RTU_OBJECT_PATH_LENGTH_EXT
#else
#define GLU_OBJECT_PATH_LENGTH_EXT RTGLC_ABSENT(GLU_OBJECT_PATH_LENGTH_EXT, "GLU_OBJECT_PATH_LENGTH_EXT: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_PATH_LENGTH
#define GLU_PATH_LENGTH RTU_PATH_LENGTH
#else
#define GLU_PATH_LENGTH RTGLC_ABSENT(GLU_PATH_LENGTH, "GLU_PATH_LENGTH: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_PARAMETRIC_ERROR
#define GLU_PARAMETRIC_ERROR RTU_PARAMETRIC_ERROR
#else
#define GLU_PARAMETRIC_ERROR RTGLC_ABSENT(GLU_PARAMETRIC_ERROR, "GLU_PARAMETRIC_ERROR: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_DOMAIN_DISTANCE
#define GLU_DOMAIN_DISTANCE RTU_DOMAIN_DISTANCE
#else
#define GLU_DOMAIN_DISTANCE RTGLC_ABSENT(GLU_DOMAIN_DISTANCE, "GLU_DOMAIN_DISTANCE: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_MAP1_TRIM_2
#define GLU_MAP1_TRIM_2 RTU_MAP1_TRIM_2
#else
#define GLU_MAP1_TRIM_2 RTGLC_ABSENT(GLU_MAP1_TRIM_2, "GLU_MAP1_TRIM_2: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_MAP1_TRIM_3
#define GLU_MAP1_TRIM_3 RTU_MAP1_TRIM_3
#else
#define GLU_MAP1_TRIM_3 RTGLC_ABSENT(GLU_MAP1_TRIM_3, "GLU_MAP1_TRIM_3: no rtu equivalent (docs/glcompat.md)")
#endif
#define GLU_POINT RTU_POINT
#define GLU_LINE RTU_LINE
#define GLU_FILL RTU_FILL
#define GLU_SILHOUETTE RTU_SILHOUETTE
#define GLU_SMOOTH RTU_SMOOTH
#define GLU_FLAT RTU_FLAT
#define GLU_NONE RTU_NONE
#define GLU_OUTSIDE RTU_OUTSIDE
#define GLU_INSIDE RTU_INSIDE
#ifdef RTU_TESS_BEGIN
#define GLU_TESS_BEGIN RTU_TESS_BEGIN
#else
#define GLU_TESS_BEGIN RTGLC_ABSENT(GLU_TESS_BEGIN, "GLU_TESS_BEGIN: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_BEGIN
#define GLU_BEGIN RTU_BEGIN
#else
#define GLU_BEGIN RTGLC_ABSENT(GLU_BEGIN, "GLU_BEGIN: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_VERTEX
#define GLU_TESS_VERTEX RTU_TESS_VERTEX
#else
#define GLU_TESS_VERTEX RTGLC_ABSENT(GLU_TESS_VERTEX, "GLU_TESS_VERTEX: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_VERTEX
#define GLU_VERTEX RTU_VERTEX
#else
#define GLU_VERTEX RTGLC_ABSENT(GLU_VERTEX, "GLU_VERTEX: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_END
#define GLU_TESS_END RTU_TESS_END
#else
#define GLU_TESS_END RTGLC_ABSENT(GLU_TESS_END, "GLU_TESS_END: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_END
#define GLU_END RTU_END
#else
#define GLU_END RTGLC_ABSENT(GLU_END, "GLU_END: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_ERROR
#define GLU_TESS_ERROR RTU_TESS_ERROR
#else
#define GLU_TESS_ERROR RTGLC_ABSENT(GLU_TESS_ERROR, "GLU_TESS_ERROR: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_EDGE_FLAG
#define GLU_TESS_EDGE_FLAG RTU_TESS_EDGE_FLAG
#else
#define GLU_TESS_EDGE_FLAG RTGLC_ABSENT(GLU_TESS_EDGE_FLAG, "GLU_TESS_EDGE_FLAG: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_EDGE_FLAG
#define GLU_EDGE_FLAG RTU_EDGE_FLAG
#else
#define GLU_EDGE_FLAG RTGLC_ABSENT(GLU_EDGE_FLAG, "GLU_EDGE_FLAG: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_COMBINE
#define GLU_TESS_COMBINE RTU_TESS_COMBINE
#else
#define GLU_TESS_COMBINE RTGLC_ABSENT(GLU_TESS_COMBINE, "GLU_TESS_COMBINE: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_BEGIN_DATA
#define GLU_TESS_BEGIN_DATA RTU_TESS_BEGIN_DATA
#else
#define GLU_TESS_BEGIN_DATA RTGLC_ABSENT(GLU_TESS_BEGIN_DATA, "GLU_TESS_BEGIN_DATA: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_VERTEX_DATA
#define GLU_TESS_VERTEX_DATA RTU_TESS_VERTEX_DATA
#else
#define GLU_TESS_VERTEX_DATA RTGLC_ABSENT(GLU_TESS_VERTEX_DATA, "GLU_TESS_VERTEX_DATA: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_END_DATA
#define GLU_TESS_END_DATA RTU_TESS_END_DATA
#else
#define GLU_TESS_END_DATA RTGLC_ABSENT(GLU_TESS_END_DATA, "GLU_TESS_END_DATA: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_ERROR_DATA
#define GLU_TESS_ERROR_DATA RTU_TESS_ERROR_DATA
#else
#define GLU_TESS_ERROR_DATA RTGLC_ABSENT(GLU_TESS_ERROR_DATA, "GLU_TESS_ERROR_DATA: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_EDGE_FLAG_DATA
#define GLU_TESS_EDGE_FLAG_DATA RTU_TESS_EDGE_FLAG_DATA
#else
#define GLU_TESS_EDGE_FLAG_DATA RTGLC_ABSENT(GLU_TESS_EDGE_FLAG_DATA, "GLU_TESS_EDGE_FLAG_DATA: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_COMBINE_DATA
#define GLU_TESS_COMBINE_DATA RTU_TESS_COMBINE_DATA
#else
#define GLU_TESS_COMBINE_DATA RTGLC_ABSENT(GLU_TESS_COMBINE_DATA, "GLU_TESS_COMBINE_DATA: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_CW
#define GLU_CW RTU_CW
#else
#define GLU_CW RTGLC_ABSENT(GLU_CW, "GLU_CW: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_CCW
#define GLU_CCW RTU_CCW
#else
#define GLU_CCW RTGLC_ABSENT(GLU_CCW, "GLU_CCW: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_INTERIOR
#define GLU_INTERIOR RTU_INTERIOR
#else
#define GLU_INTERIOR RTGLC_ABSENT(GLU_INTERIOR, "GLU_INTERIOR: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_EXTERIOR
#define GLU_EXTERIOR RTU_EXTERIOR
#else
#define GLU_EXTERIOR RTGLC_ABSENT(GLU_EXTERIOR, "GLU_EXTERIOR: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_UNKNOWN
#define GLU_UNKNOWN RTU_UNKNOWN
#else
#define GLU_UNKNOWN RTGLC_ABSENT(GLU_UNKNOWN, "GLU_UNKNOWN: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_WINDING_RULE
#define GLU_TESS_WINDING_RULE RTU_TESS_WINDING_RULE
#else
#define GLU_TESS_WINDING_RULE RTGLC_ABSENT(GLU_TESS_WINDING_RULE, "GLU_TESS_WINDING_RULE: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_BOUNDARY_ONLY
#define GLU_TESS_BOUNDARY_ONLY RTU_TESS_BOUNDARY_ONLY
#else
#define GLU_TESS_BOUNDARY_ONLY RTGLC_ABSENT(GLU_TESS_BOUNDARY_ONLY, "GLU_TESS_BOUNDARY_ONLY: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_TOLERANCE
#define GLU_TESS_TOLERANCE RTU_TESS_TOLERANCE
#else
#define GLU_TESS_TOLERANCE RTGLC_ABSENT(GLU_TESS_TOLERANCE, "GLU_TESS_TOLERANCE: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_ERROR1
#define GLU_TESS_ERROR1 RTU_TESS_ERROR1
#else
#define GLU_TESS_ERROR1 RTGLC_ABSENT(GLU_TESS_ERROR1, "GLU_TESS_ERROR1: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_ERROR2
#define GLU_TESS_ERROR2 RTU_TESS_ERROR2
#else
#define GLU_TESS_ERROR2 RTGLC_ABSENT(GLU_TESS_ERROR2, "GLU_TESS_ERROR2: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_ERROR3
#define GLU_TESS_ERROR3 RTU_TESS_ERROR3
#else
#define GLU_TESS_ERROR3 RTGLC_ABSENT(GLU_TESS_ERROR3, "GLU_TESS_ERROR3: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_ERROR4
#define GLU_TESS_ERROR4 RTU_TESS_ERROR4
#else
#define GLU_TESS_ERROR4 RTGLC_ABSENT(GLU_TESS_ERROR4, "GLU_TESS_ERROR4: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_ERROR5
#define GLU_TESS_ERROR5 RTU_TESS_ERROR5
#else
#define GLU_TESS_ERROR5 RTGLC_ABSENT(GLU_TESS_ERROR5, "GLU_TESS_ERROR5: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_ERROR6
#define GLU_TESS_ERROR6 RTU_TESS_ERROR6
#else
#define GLU_TESS_ERROR6 RTGLC_ABSENT(GLU_TESS_ERROR6, "GLU_TESS_ERROR6: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_ERROR7
#define GLU_TESS_ERROR7 RTU_TESS_ERROR7
#else
#define GLU_TESS_ERROR7 RTGLC_ABSENT(GLU_TESS_ERROR7, "GLU_TESS_ERROR7: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_ERROR8
#define GLU_TESS_ERROR8 RTU_TESS_ERROR8
#else
#define GLU_TESS_ERROR8 RTGLC_ABSENT(GLU_TESS_ERROR8, "GLU_TESS_ERROR8: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_MISSING_BEGIN_POLYGON
#define GLU_TESS_MISSING_BEGIN_POLYGON RTU_TESS_MISSING_BEGIN_POLYGON
#else
#define GLU_TESS_MISSING_BEGIN_POLYGON RTGLC_ABSENT(GLU_TESS_MISSING_BEGIN_POLYGON, "GLU_TESS_MISSING_BEGIN_POLYGON: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_MISSING_BEGIN_CONTOUR
#define GLU_TESS_MISSING_BEGIN_CONTOUR RTU_TESS_MISSING_BEGIN_CONTOUR
#else
#define GLU_TESS_MISSING_BEGIN_CONTOUR RTGLC_ABSENT(GLU_TESS_MISSING_BEGIN_CONTOUR, "GLU_TESS_MISSING_BEGIN_CONTOUR: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_MISSING_END_POLYGON
#define GLU_TESS_MISSING_END_POLYGON RTU_TESS_MISSING_END_POLYGON
#else
#define GLU_TESS_MISSING_END_POLYGON RTGLC_ABSENT(GLU_TESS_MISSING_END_POLYGON, "GLU_TESS_MISSING_END_POLYGON: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_MISSING_END_CONTOUR
#define GLU_TESS_MISSING_END_CONTOUR RTU_TESS_MISSING_END_CONTOUR
#else
#define GLU_TESS_MISSING_END_CONTOUR RTGLC_ABSENT(GLU_TESS_MISSING_END_CONTOUR, "GLU_TESS_MISSING_END_CONTOUR: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_COORD_TOO_LARGE
#define GLU_TESS_COORD_TOO_LARGE RTU_TESS_COORD_TOO_LARGE
#else
#define GLU_TESS_COORD_TOO_LARGE RTGLC_ABSENT(GLU_TESS_COORD_TOO_LARGE, "GLU_TESS_COORD_TOO_LARGE: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_NEED_COMBINE_CALLBACK
#define GLU_TESS_NEED_COMBINE_CALLBACK RTU_TESS_NEED_COMBINE_CALLBACK
#else
#define GLU_TESS_NEED_COMBINE_CALLBACK RTGLC_ABSENT(GLU_TESS_NEED_COMBINE_CALLBACK, "GLU_TESS_NEED_COMBINE_CALLBACK: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_WINDING_ODD
#define GLU_TESS_WINDING_ODD RTU_TESS_WINDING_ODD
#else
#define GLU_TESS_WINDING_ODD RTGLC_ABSENT(GLU_TESS_WINDING_ODD, "GLU_TESS_WINDING_ODD: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_WINDING_NONZERO
#define GLU_TESS_WINDING_NONZERO RTU_TESS_WINDING_NONZERO
#else
#define GLU_TESS_WINDING_NONZERO RTGLC_ABSENT(GLU_TESS_WINDING_NONZERO, "GLU_TESS_WINDING_NONZERO: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_WINDING_POSITIVE
#define GLU_TESS_WINDING_POSITIVE RTU_TESS_WINDING_POSITIVE
#else
#define GLU_TESS_WINDING_POSITIVE RTGLC_ABSENT(GLU_TESS_WINDING_POSITIVE, "GLU_TESS_WINDING_POSITIVE: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_WINDING_NEGATIVE
#define GLU_TESS_WINDING_NEGATIVE RTU_TESS_WINDING_NEGATIVE
#else
#define GLU_TESS_WINDING_NEGATIVE RTGLC_ABSENT(GLU_TESS_WINDING_NEGATIVE, "GLU_TESS_WINDING_NEGATIVE: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_WINDING_ABS_GEQ_TWO
#define GLU_TESS_WINDING_ABS_GEQ_TWO RTU_TESS_WINDING_ABS_GEQ_TWO
#else
#define GLU_TESS_WINDING_ABS_GEQ_TWO RTGLC_ABSENT(GLU_TESS_WINDING_ABS_GEQ_TWO, "GLU_TESS_WINDING_ABS_GEQ_TWO: no rtu equivalent (docs/glcompat.md)")
#endif
#ifdef RTU_TESS_MAX_COORD
#define GLU_TESS_MAX_COORD RTU_TESS_MAX_COORD
#else
#define GLU_TESS_MAX_COORD RTGLC_ABSENT(GLU_TESS_MAX_COORD, "GLU_TESS_MAX_COORD: no rtu equivalent (docs/glcompat.md)")
#endif

/* ---- GLUT ------------------------------------------------------------- */
#define glutSolidCube rtuSolidCube
#define glutSolidSphere rtuSolidSphere
#define glutSolidCone rtuSolidCone
#define glutSolidTorus rtuSolidTorus
#define glutSolidDodecahedron rtuSolidDodecahedron
#define glutSolidOctahedron rtuSolidOctahedron
#define glutSolidTetrahedron rtuSolidTetrahedron
#define glutSolidIcosahedron rtuSolidIcosahedron
#define glutSolidTeapot rtuSolidTeapot
/* Window-manager requests with no meaning headless or for the image. */
static inline void rtglc_utSetIconTitle(const char *title) { (void)title; }
#define glutSetIconTitle rtglc_utSetIconTitle
static inline void rtglc_utShowWindow(void) { }
#define glutShowWindow rtglc_utShowWindow
static inline void rtglc_utHideWindow(void) { }
#define glutHideWindow rtglc_utHideWindow
static inline void rtglc_utIconifyWindow(void) { }
#define glutIconifyWindow rtglc_utIconifyWindow
static inline void rtglc_utPositionWindow(int x, int y) { (void)x; (void)y; }
#define glutPositionWindow rtglc_utPositionWindow
static inline void rtglc_utPushWindow(void) { }
#define glutPushWindow rtglc_utPushWindow
static inline void rtglc_utPopWindow(void) { }
#define glutPopWindow rtglc_utPopWindow
static inline void rtglc_utSetCursor(int cursor) { (void)cursor; }
#define glutSetCursor rtglc_utSetCursor
static inline void rtglc_utWarpPointer(int x, int y) { (void)x; (void)y; }
#define glutWarpPointer rtglc_utWarpPointer
static inline void rtglc_utIgnoreKeyRepeat(int ignore) { (void)ignore; }
#define glutIgnoreKeyRepeat rtglc_utIgnoreKeyRepeat
static inline void rtglc_utSetKeyRepeat(int repeatMode) { (void)repeatMode; }
#define glutSetKeyRepeat rtglc_utSetKeyRepeat
static inline void rtglc_utReportErrors(void) { }
#define glutReportErrors rtglc_utReportErrors
#if !defined(RT_GLCOMPAT_HAVE_GLUT) && (defined(RTU_DOUBLE))
#define RT_GLCOMPAT_HAVE_GLUT 1
#endif
#ifdef RT_GLCOMPAT_HAVE_GLUT
#define glutInit rtuInit
#define glutInitWindowPosition rtuInitWindowPosition
#define glutInitWindowSize rtuInitWindowSize
#define glutInitDisplayMode rtuInitDisplayMode
#define glutMainLoop rtuMainLoop
#define glutCreateWindow rtuCreateWindow
#define glutDestroyWindow rtuDestroyWindow
#define glutGetWindow rtuGetWindow
#define glutSetWindowTitle rtuSetWindowTitle
#define glutReshapeWindow rtuReshapeWindow
#define glutFullScreen rtuFullScreen
#define glutPostRedisplay rtuPostRedisplay
#define glutSwapBuffers rtuSwapBuffers
#define glutCreateMenu rtuCreateMenu
#define glutDestroyMenu rtuDestroyMenu
#define glutGetMenu rtuGetMenu
#define glutSetMenu rtuSetMenu
#define glutAddMenuEntry rtuAddMenuEntry
#define glutAddSubMenu rtuAddSubMenu
#define glutAttachMenu rtuAttachMenu
#define glutDetachMenu rtuDetachMenu
#define glutTimerFunc rtuTimerFunc
#define glutIdleFunc rtuIdleFunc
#define glutKeyboardFunc rtuKeyboardFunc
#define glutSpecialFunc rtuSpecialFunc
#define glutReshapeFunc rtuReshapeFunc
#define glutVisibilityFunc rtuVisibilityFunc
#define glutDisplayFunc rtuDisplayFunc
#define glutMouseFunc rtuMouseFunc
#define glutMotionFunc rtuMotionFunc
#define glutPassiveMotionFunc rtuPassiveMotionFunc
#define glutKeyboardUpFunc rtuKeyboardUpFunc
#define glutSpecialUpFunc rtuSpecialUpFunc
#define glutGet rtuGet
#define glutGetModifiers rtuGetModifiers
#define GLUT_API_VERSION 3
#else
#define glutInit RTGLC_PENDING(glutInit, "glutInit: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutInitWindowPosition RTGLC_PENDING(glutInitWindowPosition, "glutInitWindowPosition: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutInitWindowSize RTGLC_PENDING(glutInitWindowSize, "glutInitWindowSize: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutInitDisplayMode RTGLC_PENDING(glutInitDisplayMode, "glutInitDisplayMode: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutMainLoop RTGLC_PENDING(glutMainLoop, "glutMainLoop: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutCreateWindow RTGLC_PENDING(glutCreateWindow, "glutCreateWindow: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutDestroyWindow RTGLC_PENDING(glutDestroyWindow, "glutDestroyWindow: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutGetWindow RTGLC_PENDING(glutGetWindow, "glutGetWindow: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutSetWindowTitle RTGLC_PENDING(glutSetWindowTitle, "glutSetWindowTitle: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutReshapeWindow RTGLC_PENDING(glutReshapeWindow, "glutReshapeWindow: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutFullScreen RTGLC_PENDING(glutFullScreen, "glutFullScreen: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutPostRedisplay RTGLC_PENDING(glutPostRedisplay, "glutPostRedisplay: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutSwapBuffers RTGLC_PENDING(glutSwapBuffers, "glutSwapBuffers: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutCreateMenu RTGLC_PENDING(glutCreateMenu, "glutCreateMenu: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutDestroyMenu RTGLC_PENDING(glutDestroyMenu, "glutDestroyMenu: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutGetMenu RTGLC_PENDING(glutGetMenu, "glutGetMenu: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutSetMenu RTGLC_PENDING(glutSetMenu, "glutSetMenu: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutAddMenuEntry RTGLC_PENDING(glutAddMenuEntry, "glutAddMenuEntry: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutAddSubMenu RTGLC_PENDING(glutAddSubMenu, "glutAddSubMenu: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutAttachMenu RTGLC_PENDING(glutAttachMenu, "glutAttachMenu: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutDetachMenu RTGLC_PENDING(glutDetachMenu, "glutDetachMenu: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutTimerFunc RTGLC_PENDING(glutTimerFunc, "glutTimerFunc: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutIdleFunc RTGLC_PENDING(glutIdleFunc, "glutIdleFunc: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutKeyboardFunc RTGLC_PENDING(glutKeyboardFunc, "glutKeyboardFunc: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutSpecialFunc RTGLC_PENDING(glutSpecialFunc, "glutSpecialFunc: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutReshapeFunc RTGLC_PENDING(glutReshapeFunc, "glutReshapeFunc: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutVisibilityFunc RTGLC_PENDING(glutVisibilityFunc, "glutVisibilityFunc: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutDisplayFunc RTGLC_PENDING(glutDisplayFunc, "glutDisplayFunc: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutMouseFunc RTGLC_PENDING(glutMouseFunc, "glutMouseFunc: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutMotionFunc RTGLC_PENDING(glutMotionFunc, "glutMotionFunc: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutPassiveMotionFunc RTGLC_PENDING(glutPassiveMotionFunc, "glutPassiveMotionFunc: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutKeyboardUpFunc RTGLC_PENDING(glutKeyboardUpFunc, "glutKeyboardUpFunc: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutSpecialUpFunc RTGLC_PENDING(glutSpecialUpFunc, "glutSpecialUpFunc: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutGet RTGLC_PENDING(glutGet, "glutGet: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#define glutGetModifiers RTGLC_PENDING(glutGetModifiers, "glutGetModifiers: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#endif
/* One window, and callbacks of events the shell does not produce: accepted,
 * never called. */
static inline void rtglc_utSetWindow(int window) { (void)window; }
#define glutSetWindow rtglc_utSetWindow
static inline void rtglc_utEntryFunc(void (*func)(int state)) { (void)func; }
#define glutEntryFunc rtglc_utEntryFunc
static inline void rtglc_utMenuStateFunc(void (*func)(int state)) { (void)func; }
#define glutMenuStateFunc rtglc_utMenuStateFunc
static inline void rtglc_utMenuStatusFunc(void (*func)(int status, int x, int y)) { (void)func; }
#define glutMenuStatusFunc rtglc_utMenuStatusFunc
static inline void rtglc_utWindowStatusFunc(void (*func)(int state)) { (void)func; }
#define glutWindowStatusFunc rtglc_utWindowStatusFunc
#ifdef RT_GLCOMPAT_HAVE_GLUT
static inline void rtglc_utPostWindowRedisplay(int window) { (void)window; rtuPostRedisplay(); }
#define glutPostWindowRedisplay rtglc_utPostWindowRedisplay
#else
#define glutPostWindowRedisplay RTGLC_PENDING(glutPostWindowRedisplay, "glutPostWindowRedisplay: needs the rtu GLUT shell, not in this Tracelist (docs/glcompat.md)")
#endif
#define glutChangeToMenuEntry RTGLC_ABSENT(glutChangeToMenuEntry, "glutChangeToMenuEntry: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutChangeToSubMenu RTGLC_ABSENT(glutChangeToSubMenu, "glutChangeToSubMenu: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutRemoveMenuItem RTGLC_ABSENT(glutRemoveMenuItem, "glutRemoveMenuItem: not in the rtu GLUT shell (docs/glcompat.md)")
#if !defined(RT_GLCOMPAT_HAVE_GLUT_FONTS) && (defined(RTU_BITMAP_8_BY_13))
#define RT_GLCOMPAT_HAVE_GLUT_FONTS 1
#endif
#ifdef RT_GLCOMPAT_HAVE_GLUT_FONTS
#define glutBitmapCharacter rtuBitmapCharacter
#define glutBitmapWidth rtuBitmapWidth
#define glutBitmapLength rtuBitmapLength
#else
#define glutBitmapCharacter RTGLC_PENDING(glutBitmapCharacter, "glutBitmapCharacter: needs rtu bitmap fonts, not in this Tracelist (docs/glcompat.md)")
#define glutBitmapWidth RTGLC_PENDING(glutBitmapWidth, "glutBitmapWidth: needs rtu bitmap fonts, not in this Tracelist (docs/glcompat.md)")
#define glutBitmapLength RTGLC_PENDING(glutBitmapLength, "glutBitmapLength: needs rtu bitmap fonts, not in this Tracelist (docs/glcompat.md)")
#endif
#if !defined(RT_GLCOMPAT_HAVE_GLUT_WIRE) && (defined(RTU_DOUBLE) && defined(RT_LINES))
#define RT_GLCOMPAT_HAVE_GLUT_WIRE 1
#endif
#ifdef RT_GLCOMPAT_HAVE_GLUT_WIRE
#define glutWireCube rtuWireCube
#define glutWireSphere rtuWireSphere
#define glutWireCone rtuWireCone
#define glutWireTorus rtuWireTorus
#define glutWireDodecahedron rtuWireDodecahedron
#define glutWireOctahedron rtuWireOctahedron
#define glutWireTetrahedron rtuWireTetrahedron
#define glutWireIcosahedron rtuWireIcosahedron
#define glutWireTeapot rtuWireTeapot
#else
#define glutWireCube RTGLC_PENDING(glutWireCube, "glutWireCube: needs the rtu wire shapes, not in this Tracelist (docs/glcompat.md)")
#define glutWireSphere RTGLC_PENDING(glutWireSphere, "glutWireSphere: needs the rtu wire shapes, not in this Tracelist (docs/glcompat.md)")
#define glutWireCone RTGLC_PENDING(glutWireCone, "glutWireCone: needs the rtu wire shapes, not in this Tracelist (docs/glcompat.md)")
#define glutWireTorus RTGLC_PENDING(glutWireTorus, "glutWireTorus: needs the rtu wire shapes, not in this Tracelist (docs/glcompat.md)")
#define glutWireDodecahedron RTGLC_PENDING(glutWireDodecahedron, "glutWireDodecahedron: needs the rtu wire shapes, not in this Tracelist (docs/glcompat.md)")
#define glutWireOctahedron RTGLC_PENDING(glutWireOctahedron, "glutWireOctahedron: needs the rtu wire shapes, not in this Tracelist (docs/glcompat.md)")
#define glutWireTetrahedron RTGLC_PENDING(glutWireTetrahedron, "glutWireTetrahedron: needs the rtu wire shapes, not in this Tracelist (docs/glcompat.md)")
#define glutWireIcosahedron RTGLC_PENDING(glutWireIcosahedron, "glutWireIcosahedron: needs the rtu wire shapes, not in this Tracelist (docs/glcompat.md)")
#define glutWireTeapot RTGLC_PENDING(glutWireTeapot, "glutWireTeapot: needs the rtu wire shapes, not in this Tracelist (docs/glcompat.md)")
#endif
#define glutInitDisplayString RTGLC_ABSENT(glutInitDisplayString, "glutInitDisplayString: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutCreateSubWindow RTGLC_ABSENT(glutCreateSubWindow, "glutCreateSubWindow: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutEstablishOverlay RTGLC_ABSENT(glutEstablishOverlay, "glutEstablishOverlay: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutRemoveOverlay RTGLC_ABSENT(glutRemoveOverlay, "glutRemoveOverlay: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutUseLayer RTGLC_ABSENT(glutUseLayer, "glutUseLayer: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutPostOverlayRedisplay RTGLC_ABSENT(glutPostOverlayRedisplay, "glutPostOverlayRedisplay: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutPostWindowOverlayRedisplay RTGLC_ABSENT(glutPostWindowOverlayRedisplay, "glutPostWindowOverlayRedisplay: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutShowOverlay RTGLC_ABSENT(glutShowOverlay, "glutShowOverlay: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutHideOverlay RTGLC_ABSENT(glutHideOverlay, "glutHideOverlay: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutJoystickFunc RTGLC_ABSENT(glutJoystickFunc, "glutJoystickFunc: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutOverlayDisplayFunc RTGLC_ABSENT(glutOverlayDisplayFunc, "glutOverlayDisplayFunc: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutSpaceballMotionFunc RTGLC_ABSENT(glutSpaceballMotionFunc, "glutSpaceballMotionFunc: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutSpaceballRotateFunc RTGLC_ABSENT(glutSpaceballRotateFunc, "glutSpaceballRotateFunc: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutSpaceballButtonFunc RTGLC_ABSENT(glutSpaceballButtonFunc, "glutSpaceballButtonFunc: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutButtonBoxFunc RTGLC_ABSENT(glutButtonBoxFunc, "glutButtonBoxFunc: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutDialsFunc RTGLC_ABSENT(glutDialsFunc, "glutDialsFunc: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutTabletMotionFunc RTGLC_ABSENT(glutTabletMotionFunc, "glutTabletMotionFunc: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutTabletButtonFunc RTGLC_ABSENT(glutTabletButtonFunc, "glutTabletButtonFunc: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutDeviceGet RTGLC_ABSENT(glutDeviceGet, "glutDeviceGet: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutLayerGet RTGLC_ABSENT(glutLayerGet, "glutLayerGet: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutStrokeCharacter RTGLC_ABSENT(glutStrokeCharacter, "glutStrokeCharacter: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutStrokeWidth RTGLC_ABSENT(glutStrokeWidth, "glutStrokeWidth: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutStrokeWidthf RTGLC_ABSENT(glutStrokeWidthf, "glutStrokeWidthf: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutStrokeLength RTGLC_ABSENT(glutStrokeLength, "glutStrokeLength: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutStrokeLengthf RTGLC_ABSENT(glutStrokeLengthf, "glutStrokeLengthf: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutGameModeString RTGLC_ABSENT(glutGameModeString, "glutGameModeString: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutEnterGameMode RTGLC_ABSENT(glutEnterGameMode, "glutEnterGameMode: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutLeaveGameMode RTGLC_ABSENT(glutLeaveGameMode, "glutLeaveGameMode: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutGameModeGet RTGLC_ABSENT(glutGameModeGet, "glutGameModeGet: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutVideoResizeGet RTGLC_ABSENT(glutVideoResizeGet, "glutVideoResizeGet: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutSetupVideoResizing RTGLC_ABSENT(glutSetupVideoResizing, "glutSetupVideoResizing: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutStopVideoResizing RTGLC_ABSENT(glutStopVideoResizing, "glutStopVideoResizing: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutVideoResize RTGLC_ABSENT(glutVideoResize, "glutVideoResize: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutVideoPan RTGLC_ABSENT(glutVideoPan, "glutVideoPan: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutSetColor RTGLC_ABSENT(glutSetColor, "glutSetColor: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutGetColor RTGLC_ABSENT(glutGetColor, "glutGetColor: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutCopyColormap RTGLC_ABSENT(glutCopyColormap, "glutCopyColormap: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutForceJoystickFunc RTGLC_ABSENT(glutForceJoystickFunc, "glutForceJoystickFunc: not in the rtu GLUT shell (docs/glcompat.md)")
#define glutExtensionSupported RTGLC_ABSENT(glutExtensionSupported, "glutExtensionSupported: not in the rtu GLUT shell (docs/glcompat.md)")
#define GLUT_KEY_F1 RTU_KEY_F1
#define GLUT_KEY_F2 RTU_KEY_F2
#define GLUT_KEY_F3 RTU_KEY_F3
#define GLUT_KEY_F4 RTU_KEY_F4
#define GLUT_KEY_F5 RTU_KEY_F5
#define GLUT_KEY_F6 RTU_KEY_F6
#define GLUT_KEY_F7 RTU_KEY_F7
#define GLUT_KEY_F8 RTU_KEY_F8
#define GLUT_KEY_F9 RTU_KEY_F9
#define GLUT_KEY_F10 RTU_KEY_F10
#define GLUT_KEY_F11 RTU_KEY_F11
#define GLUT_KEY_F12 RTU_KEY_F12
#define GLUT_KEY_LEFT RTU_KEY_LEFT
#define GLUT_KEY_UP RTU_KEY_UP
#define GLUT_KEY_RIGHT RTU_KEY_RIGHT
#define GLUT_KEY_DOWN RTU_KEY_DOWN
#define GLUT_KEY_PAGE_UP RTU_KEY_PAGE_UP
#define GLUT_KEY_PAGE_DOWN RTU_KEY_PAGE_DOWN
#define GLUT_KEY_HOME RTU_KEY_HOME
#define GLUT_KEY_END RTU_KEY_END
#define GLUT_KEY_INSERT RTU_KEY_INSERT
#define GLUT_LEFT_BUTTON RTU_LEFT_BUTTON
#define GLUT_MIDDLE_BUTTON RTU_MIDDLE_BUTTON
#define GLUT_RIGHT_BUTTON RTU_RIGHT_BUTTON
#define GLUT_DOWN RTU_DOWN
#define GLUT_UP RTU_UP
#define GLUT_LEFT RTU_LEFT
#define GLUT_ENTERED RTU_ENTERED
#define GLUT_RGB RTU_RGB
#define GLUT_RGBA RTU_RGBA
#ifdef RTU_INDEX
#define GLUT_INDEX RTU_INDEX
#else
#define GLUT_INDEX RTGLC_ABSENT(GLUT_INDEX, "GLUT_INDEX: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#define GLUT_SINGLE RTU_SINGLE
#define GLUT_DOUBLE RTU_DOUBLE
#define GLUT_ACCUM RTU_ACCUM
#define GLUT_ALPHA RTU_ALPHA
#define GLUT_DEPTH RTU_DEPTH
#define GLUT_STENCIL RTU_STENCIL
#define GLUT_MULTISAMPLE RTU_MULTISAMPLE
#define GLUT_STEREO RTU_STEREO
#define GLUT_LUMINANCE RTU_LUMINANCE
#define GLUT_MENU_NOT_IN_USE RTU_MENU_NOT_IN_USE
#define GLUT_MENU_IN_USE RTU_MENU_IN_USE
#define GLUT_NOT_VISIBLE RTU_NOT_VISIBLE
#define GLUT_VISIBLE RTU_VISIBLE
#define GLUT_HIDDEN RTU_HIDDEN
#define GLUT_FULLY_RETAINED RTU_FULLY_RETAINED
#define GLUT_PARTIALLY_RETAINED RTU_PARTIALLY_RETAINED
#define GLUT_FULLY_COVERED RTU_FULLY_COVERED
#define GLUT_WINDOW_X RTU_WINDOW_X
#define GLUT_WINDOW_Y RTU_WINDOW_Y
#define GLUT_WINDOW_WIDTH RTU_WINDOW_WIDTH
#define GLUT_WINDOW_HEIGHT RTU_WINDOW_HEIGHT
#define GLUT_WINDOW_BUFFER_SIZE RTU_WINDOW_BUFFER_SIZE
#define GLUT_WINDOW_STENCIL_SIZE RTU_WINDOW_STENCIL_SIZE
#define GLUT_WINDOW_DEPTH_SIZE RTU_WINDOW_DEPTH_SIZE
#define GLUT_WINDOW_RED_SIZE RTU_WINDOW_RED_SIZE
#define GLUT_WINDOW_GREEN_SIZE RTU_WINDOW_GREEN_SIZE
#define GLUT_WINDOW_BLUE_SIZE RTU_WINDOW_BLUE_SIZE
#define GLUT_WINDOW_ALPHA_SIZE RTU_WINDOW_ALPHA_SIZE
#define GLUT_WINDOW_ACCUM_RED_SIZE RTU_WINDOW_ACCUM_RED_SIZE
#define GLUT_WINDOW_ACCUM_GREEN_SIZE RTU_WINDOW_ACCUM_GREEN_SIZE
#define GLUT_WINDOW_ACCUM_BLUE_SIZE RTU_WINDOW_ACCUM_BLUE_SIZE
#define GLUT_WINDOW_ACCUM_ALPHA_SIZE RTU_WINDOW_ACCUM_ALPHA_SIZE
#define GLUT_WINDOW_DOUBLEBUFFER RTU_WINDOW_DOUBLEBUFFER
#define GLUT_WINDOW_RGBA RTU_WINDOW_RGBA
#define GLUT_WINDOW_PARENT RTU_WINDOW_PARENT
#define GLUT_WINDOW_NUM_CHILDREN RTU_WINDOW_NUM_CHILDREN
#ifdef RTU_WINDOW_COLORMAP_SIZE
#define GLUT_WINDOW_COLORMAP_SIZE RTU_WINDOW_COLORMAP_SIZE
#else
#define GLUT_WINDOW_COLORMAP_SIZE RTGLC_ABSENT(GLUT_WINDOW_COLORMAP_SIZE, "GLUT_WINDOW_COLORMAP_SIZE: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#define GLUT_WINDOW_NUM_SAMPLES RTU_WINDOW_NUM_SAMPLES
#define GLUT_WINDOW_STEREO RTU_WINDOW_STEREO
#define GLUT_WINDOW_CURSOR RTU_WINDOW_CURSOR
#define GLUT_SCREEN_WIDTH RTU_SCREEN_WIDTH
#define GLUT_SCREEN_HEIGHT RTU_SCREEN_HEIGHT
#define GLUT_SCREEN_WIDTH_MM RTU_SCREEN_WIDTH_MM
#define GLUT_SCREEN_HEIGHT_MM RTU_SCREEN_HEIGHT_MM
#define GLUT_MENU_NUM_ITEMS RTU_MENU_NUM_ITEMS
#define GLUT_DISPLAY_MODE_POSSIBLE RTU_DISPLAY_MODE_POSSIBLE
#define GLUT_INIT_WINDOW_X RTU_INIT_WINDOW_X
#define GLUT_INIT_WINDOW_Y RTU_INIT_WINDOW_Y
#define GLUT_INIT_WINDOW_WIDTH RTU_INIT_WINDOW_WIDTH
#define GLUT_INIT_WINDOW_HEIGHT RTU_INIT_WINDOW_HEIGHT
#define GLUT_INIT_DISPLAY_MODE RTU_INIT_DISPLAY_MODE
#define GLUT_ELAPSED_TIME RTU_ELAPSED_TIME
#ifdef RTU_WINDOW_FORMAT_ID
#define GLUT_WINDOW_FORMAT_ID RTU_WINDOW_FORMAT_ID
#else
#define GLUT_WINDOW_FORMAT_ID RTGLC_ABSENT(GLUT_WINDOW_FORMAT_ID, "GLUT_WINDOW_FORMAT_ID: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_HAS_KEYBOARD
#define GLUT_HAS_KEYBOARD RTU_HAS_KEYBOARD
#else
#define GLUT_HAS_KEYBOARD RTGLC_ABSENT(GLUT_HAS_KEYBOARD, "GLUT_HAS_KEYBOARD: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_HAS_MOUSE
#define GLUT_HAS_MOUSE RTU_HAS_MOUSE
#else
#define GLUT_HAS_MOUSE RTGLC_ABSENT(GLUT_HAS_MOUSE, "GLUT_HAS_MOUSE: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_HAS_SPACEBALL
#define GLUT_HAS_SPACEBALL RTU_HAS_SPACEBALL
#else
#define GLUT_HAS_SPACEBALL RTGLC_ABSENT(GLUT_HAS_SPACEBALL, "GLUT_HAS_SPACEBALL: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_HAS_DIAL_AND_BUTTON_BOX
#define GLUT_HAS_DIAL_AND_BUTTON_BOX RTU_HAS_DIAL_AND_BUTTON_BOX
#else
#define GLUT_HAS_DIAL_AND_BUTTON_BOX RTGLC_ABSENT(GLUT_HAS_DIAL_AND_BUTTON_BOX, "GLUT_HAS_DIAL_AND_BUTTON_BOX: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_HAS_TABLET
#define GLUT_HAS_TABLET RTU_HAS_TABLET
#else
#define GLUT_HAS_TABLET RTGLC_ABSENT(GLUT_HAS_TABLET, "GLUT_HAS_TABLET: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_NUM_MOUSE_BUTTONS
#define GLUT_NUM_MOUSE_BUTTONS RTU_NUM_MOUSE_BUTTONS
#else
#define GLUT_NUM_MOUSE_BUTTONS RTGLC_ABSENT(GLUT_NUM_MOUSE_BUTTONS, "GLUT_NUM_MOUSE_BUTTONS: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_NUM_SPACEBALL_BUTTONS
#define GLUT_NUM_SPACEBALL_BUTTONS RTU_NUM_SPACEBALL_BUTTONS
#else
#define GLUT_NUM_SPACEBALL_BUTTONS RTGLC_ABSENT(GLUT_NUM_SPACEBALL_BUTTONS, "GLUT_NUM_SPACEBALL_BUTTONS: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_NUM_BUTTON_BOX_BUTTONS
#define GLUT_NUM_BUTTON_BOX_BUTTONS RTU_NUM_BUTTON_BOX_BUTTONS
#else
#define GLUT_NUM_BUTTON_BOX_BUTTONS RTGLC_ABSENT(GLUT_NUM_BUTTON_BOX_BUTTONS, "GLUT_NUM_BUTTON_BOX_BUTTONS: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_NUM_DIALS
#define GLUT_NUM_DIALS RTU_NUM_DIALS
#else
#define GLUT_NUM_DIALS RTGLC_ABSENT(GLUT_NUM_DIALS, "GLUT_NUM_DIALS: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_NUM_TABLET_BUTTONS
#define GLUT_NUM_TABLET_BUTTONS RTU_NUM_TABLET_BUTTONS
#else
#define GLUT_NUM_TABLET_BUTTONS RTGLC_ABSENT(GLUT_NUM_TABLET_BUTTONS, "GLUT_NUM_TABLET_BUTTONS: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_DEVICE_IGNORE_KEY_REPEAT
#define GLUT_DEVICE_IGNORE_KEY_REPEAT RTU_DEVICE_IGNORE_KEY_REPEAT
#else
#define GLUT_DEVICE_IGNORE_KEY_REPEAT RTGLC_ABSENT(GLUT_DEVICE_IGNORE_KEY_REPEAT, "GLUT_DEVICE_IGNORE_KEY_REPEAT: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_DEVICE_KEY_REPEAT
#define GLUT_DEVICE_KEY_REPEAT RTU_DEVICE_KEY_REPEAT
#else
#define GLUT_DEVICE_KEY_REPEAT RTGLC_ABSENT(GLUT_DEVICE_KEY_REPEAT, "GLUT_DEVICE_KEY_REPEAT: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_HAS_JOYSTICK
#define GLUT_HAS_JOYSTICK RTU_HAS_JOYSTICK
#else
#define GLUT_HAS_JOYSTICK RTGLC_ABSENT(GLUT_HAS_JOYSTICK, "GLUT_HAS_JOYSTICK: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_OWNS_JOYSTICK
#define GLUT_OWNS_JOYSTICK RTU_OWNS_JOYSTICK
#else
#define GLUT_OWNS_JOYSTICK RTGLC_ABSENT(GLUT_OWNS_JOYSTICK, "GLUT_OWNS_JOYSTICK: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_JOYSTICK_BUTTONS
#define GLUT_JOYSTICK_BUTTONS RTU_JOYSTICK_BUTTONS
#else
#define GLUT_JOYSTICK_BUTTONS RTGLC_ABSENT(GLUT_JOYSTICK_BUTTONS, "GLUT_JOYSTICK_BUTTONS: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_JOYSTICK_AXES
#define GLUT_JOYSTICK_AXES RTU_JOYSTICK_AXES
#else
#define GLUT_JOYSTICK_AXES RTGLC_ABSENT(GLUT_JOYSTICK_AXES, "GLUT_JOYSTICK_AXES: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_JOYSTICK_POLL_RATE
#define GLUT_JOYSTICK_POLL_RATE RTU_JOYSTICK_POLL_RATE
#else
#define GLUT_JOYSTICK_POLL_RATE RTGLC_ABSENT(GLUT_JOYSTICK_POLL_RATE, "GLUT_JOYSTICK_POLL_RATE: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_OVERLAY_POSSIBLE
#define GLUT_OVERLAY_POSSIBLE RTU_OVERLAY_POSSIBLE
#else
#define GLUT_OVERLAY_POSSIBLE RTGLC_ABSENT(GLUT_OVERLAY_POSSIBLE, "GLUT_OVERLAY_POSSIBLE: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_LAYER_IN_USE
#define GLUT_LAYER_IN_USE RTU_LAYER_IN_USE
#else
#define GLUT_LAYER_IN_USE RTGLC_ABSENT(GLUT_LAYER_IN_USE, "GLUT_LAYER_IN_USE: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_HAS_OVERLAY
#define GLUT_HAS_OVERLAY RTU_HAS_OVERLAY
#else
#define GLUT_HAS_OVERLAY RTGLC_ABSENT(GLUT_HAS_OVERLAY, "GLUT_HAS_OVERLAY: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_TRANSPARENT_INDEX
#define GLUT_TRANSPARENT_INDEX RTU_TRANSPARENT_INDEX
#else
#define GLUT_TRANSPARENT_INDEX RTGLC_ABSENT(GLUT_TRANSPARENT_INDEX, "GLUT_TRANSPARENT_INDEX: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_NORMAL_DAMAGED
#define GLUT_NORMAL_DAMAGED RTU_NORMAL_DAMAGED
#else
#define GLUT_NORMAL_DAMAGED RTGLC_ABSENT(GLUT_NORMAL_DAMAGED, "GLUT_NORMAL_DAMAGED: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_OVERLAY_DAMAGED
#define GLUT_OVERLAY_DAMAGED RTU_OVERLAY_DAMAGED
#else
#define GLUT_OVERLAY_DAMAGED RTGLC_ABSENT(GLUT_OVERLAY_DAMAGED, "GLUT_OVERLAY_DAMAGED: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_VIDEO_RESIZE_POSSIBLE
#define GLUT_VIDEO_RESIZE_POSSIBLE RTU_VIDEO_RESIZE_POSSIBLE
#else
#define GLUT_VIDEO_RESIZE_POSSIBLE RTGLC_ABSENT(GLUT_VIDEO_RESIZE_POSSIBLE, "GLUT_VIDEO_RESIZE_POSSIBLE: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_VIDEO_RESIZE_IN_USE
#define GLUT_VIDEO_RESIZE_IN_USE RTU_VIDEO_RESIZE_IN_USE
#else
#define GLUT_VIDEO_RESIZE_IN_USE RTGLC_ABSENT(GLUT_VIDEO_RESIZE_IN_USE, "GLUT_VIDEO_RESIZE_IN_USE: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_VIDEO_RESIZE_X_DELTA
#define GLUT_VIDEO_RESIZE_X_DELTA RTU_VIDEO_RESIZE_X_DELTA
#else
#define GLUT_VIDEO_RESIZE_X_DELTA RTGLC_ABSENT(GLUT_VIDEO_RESIZE_X_DELTA, "GLUT_VIDEO_RESIZE_X_DELTA: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_VIDEO_RESIZE_Y_DELTA
#define GLUT_VIDEO_RESIZE_Y_DELTA RTU_VIDEO_RESIZE_Y_DELTA
#else
#define GLUT_VIDEO_RESIZE_Y_DELTA RTGLC_ABSENT(GLUT_VIDEO_RESIZE_Y_DELTA, "GLUT_VIDEO_RESIZE_Y_DELTA: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_VIDEO_RESIZE_WIDTH_DELTA
#define GLUT_VIDEO_RESIZE_WIDTH_DELTA RTU_VIDEO_RESIZE_WIDTH_DELTA
#else
#define GLUT_VIDEO_RESIZE_WIDTH_DELTA RTGLC_ABSENT(GLUT_VIDEO_RESIZE_WIDTH_DELTA, "GLUT_VIDEO_RESIZE_WIDTH_DELTA: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_VIDEO_RESIZE_HEIGHT_DELTA
#define GLUT_VIDEO_RESIZE_HEIGHT_DELTA RTU_VIDEO_RESIZE_HEIGHT_DELTA
#else
#define GLUT_VIDEO_RESIZE_HEIGHT_DELTA RTGLC_ABSENT(GLUT_VIDEO_RESIZE_HEIGHT_DELTA, "GLUT_VIDEO_RESIZE_HEIGHT_DELTA: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_VIDEO_RESIZE_X
#define GLUT_VIDEO_RESIZE_X RTU_VIDEO_RESIZE_X
#else
#define GLUT_VIDEO_RESIZE_X RTGLC_ABSENT(GLUT_VIDEO_RESIZE_X, "GLUT_VIDEO_RESIZE_X: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_VIDEO_RESIZE_Y
#define GLUT_VIDEO_RESIZE_Y RTU_VIDEO_RESIZE_Y
#else
#define GLUT_VIDEO_RESIZE_Y RTGLC_ABSENT(GLUT_VIDEO_RESIZE_Y, "GLUT_VIDEO_RESIZE_Y: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_VIDEO_RESIZE_WIDTH
#define GLUT_VIDEO_RESIZE_WIDTH RTU_VIDEO_RESIZE_WIDTH
#else
#define GLUT_VIDEO_RESIZE_WIDTH RTGLC_ABSENT(GLUT_VIDEO_RESIZE_WIDTH, "GLUT_VIDEO_RESIZE_WIDTH: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_VIDEO_RESIZE_HEIGHT
#define GLUT_VIDEO_RESIZE_HEIGHT RTU_VIDEO_RESIZE_HEIGHT
#else
#define GLUT_VIDEO_RESIZE_HEIGHT RTGLC_ABSENT(GLUT_VIDEO_RESIZE_HEIGHT, "GLUT_VIDEO_RESIZE_HEIGHT: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_NORMAL
#define GLUT_NORMAL RTU_NORMAL
#else
#define GLUT_NORMAL RTGLC_ABSENT(GLUT_NORMAL, "GLUT_NORMAL: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_OVERLAY
#define GLUT_OVERLAY RTU_OVERLAY
#else
#define GLUT_OVERLAY RTGLC_ABSENT(GLUT_OVERLAY, "GLUT_OVERLAY: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#define GLUT_ACTIVE_SHIFT RTU_ACTIVE_SHIFT
#define GLUT_ACTIVE_CTRL RTU_ACTIVE_CTRL
#define GLUT_ACTIVE_ALT RTU_ACTIVE_ALT
#ifdef RTU_CURSOR_RIGHT_ARROW
#define GLUT_CURSOR_RIGHT_ARROW RTU_CURSOR_RIGHT_ARROW
#else
#define GLUT_CURSOR_RIGHT_ARROW 0x0000
#endif
#ifdef RTU_CURSOR_LEFT_ARROW
#define GLUT_CURSOR_LEFT_ARROW RTU_CURSOR_LEFT_ARROW
#else
#define GLUT_CURSOR_LEFT_ARROW 0x0001
#endif
#ifdef RTU_CURSOR_INFO
#define GLUT_CURSOR_INFO RTU_CURSOR_INFO
#else
#define GLUT_CURSOR_INFO 0x0002
#endif
#ifdef RTU_CURSOR_DESTROY
#define GLUT_CURSOR_DESTROY RTU_CURSOR_DESTROY
#else
#define GLUT_CURSOR_DESTROY 0x0003
#endif
#ifdef RTU_CURSOR_HELP
#define GLUT_CURSOR_HELP RTU_CURSOR_HELP
#else
#define GLUT_CURSOR_HELP 0x0004
#endif
#ifdef RTU_CURSOR_CYCLE
#define GLUT_CURSOR_CYCLE RTU_CURSOR_CYCLE
#else
#define GLUT_CURSOR_CYCLE 0x0005
#endif
#ifdef RTU_CURSOR_SPRAY
#define GLUT_CURSOR_SPRAY RTU_CURSOR_SPRAY
#else
#define GLUT_CURSOR_SPRAY 0x0006
#endif
#ifdef RTU_CURSOR_WAIT
#define GLUT_CURSOR_WAIT RTU_CURSOR_WAIT
#else
#define GLUT_CURSOR_WAIT 0x0007
#endif
#ifdef RTU_CURSOR_TEXT
#define GLUT_CURSOR_TEXT RTU_CURSOR_TEXT
#else
#define GLUT_CURSOR_TEXT 0x0008
#endif
#ifdef RTU_CURSOR_CROSSHAIR
#define GLUT_CURSOR_CROSSHAIR RTU_CURSOR_CROSSHAIR
#else
#define GLUT_CURSOR_CROSSHAIR 0x0009
#endif
#ifdef RTU_CURSOR_UP_DOWN
#define GLUT_CURSOR_UP_DOWN RTU_CURSOR_UP_DOWN
#else
#define GLUT_CURSOR_UP_DOWN 0x000A
#endif
#ifdef RTU_CURSOR_LEFT_RIGHT
#define GLUT_CURSOR_LEFT_RIGHT RTU_CURSOR_LEFT_RIGHT
#else
#define GLUT_CURSOR_LEFT_RIGHT 0x000B
#endif
#ifdef RTU_CURSOR_TOP_SIDE
#define GLUT_CURSOR_TOP_SIDE RTU_CURSOR_TOP_SIDE
#else
#define GLUT_CURSOR_TOP_SIDE 0x000C
#endif
#ifdef RTU_CURSOR_BOTTOM_SIDE
#define GLUT_CURSOR_BOTTOM_SIDE RTU_CURSOR_BOTTOM_SIDE
#else
#define GLUT_CURSOR_BOTTOM_SIDE 0x000D
#endif
#ifdef RTU_CURSOR_LEFT_SIDE
#define GLUT_CURSOR_LEFT_SIDE RTU_CURSOR_LEFT_SIDE
#else
#define GLUT_CURSOR_LEFT_SIDE 0x000E
#endif
#ifdef RTU_CURSOR_RIGHT_SIDE
#define GLUT_CURSOR_RIGHT_SIDE RTU_CURSOR_RIGHT_SIDE
#else
#define GLUT_CURSOR_RIGHT_SIDE 0x000F
#endif
#ifdef RTU_CURSOR_TOP_LEFT_CORNER
#define GLUT_CURSOR_TOP_LEFT_CORNER RTU_CURSOR_TOP_LEFT_CORNER
#else
#define GLUT_CURSOR_TOP_LEFT_CORNER 0x0010
#endif
#ifdef RTU_CURSOR_TOP_RIGHT_CORNER
#define GLUT_CURSOR_TOP_RIGHT_CORNER RTU_CURSOR_TOP_RIGHT_CORNER
#else
#define GLUT_CURSOR_TOP_RIGHT_CORNER 0x0011
#endif
#ifdef RTU_CURSOR_BOTTOM_RIGHT_CORNER
#define GLUT_CURSOR_BOTTOM_RIGHT_CORNER RTU_CURSOR_BOTTOM_RIGHT_CORNER
#else
#define GLUT_CURSOR_BOTTOM_RIGHT_CORNER 0x0012
#endif
#ifdef RTU_CURSOR_BOTTOM_LEFT_CORNER
#define GLUT_CURSOR_BOTTOM_LEFT_CORNER RTU_CURSOR_BOTTOM_LEFT_CORNER
#else
#define GLUT_CURSOR_BOTTOM_LEFT_CORNER 0x0013
#endif
#ifdef RTU_CURSOR_INHERIT
#define GLUT_CURSOR_INHERIT RTU_CURSOR_INHERIT
#else
#define GLUT_CURSOR_INHERIT 0x0064
#endif
#ifdef RTU_CURSOR_NONE
#define GLUT_CURSOR_NONE RTU_CURSOR_NONE
#else
#define GLUT_CURSOR_NONE 0x0065
#endif
#ifdef RTU_CURSOR_FULL_CROSSHAIR
#define GLUT_CURSOR_FULL_CROSSHAIR RTU_CURSOR_FULL_CROSSHAIR
#else
#define GLUT_CURSOR_FULL_CROSSHAIR 0x0066
#endif
#ifdef RTU_RED
#define GLUT_RED RTU_RED
#else
#define GLUT_RED RTGLC_ABSENT(GLUT_RED, "GLUT_RED: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_GREEN
#define GLUT_GREEN RTU_GREEN
#else
#define GLUT_GREEN RTGLC_ABSENT(GLUT_GREEN, "GLUT_GREEN: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_BLUE
#define GLUT_BLUE RTU_BLUE
#else
#define GLUT_BLUE RTGLC_ABSENT(GLUT_BLUE, "GLUT_BLUE: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_KEY_REPEAT_OFF
#define GLUT_KEY_REPEAT_OFF RTU_KEY_REPEAT_OFF
#else
#define GLUT_KEY_REPEAT_OFF 0x0000
#endif
#ifdef RTU_KEY_REPEAT_ON
#define GLUT_KEY_REPEAT_ON RTU_KEY_REPEAT_ON
#else
#define GLUT_KEY_REPEAT_ON 0x0001
#endif
#ifdef RTU_KEY_REPEAT_DEFAULT
#define GLUT_KEY_REPEAT_DEFAULT RTU_KEY_REPEAT_DEFAULT
#else
#define GLUT_KEY_REPEAT_DEFAULT 0x0002
#endif
#ifdef RTU_JOYSTICK_BUTTON_A
#define GLUT_JOYSTICK_BUTTON_A RTU_JOYSTICK_BUTTON_A
#else
#define GLUT_JOYSTICK_BUTTON_A RTGLC_ABSENT(GLUT_JOYSTICK_BUTTON_A, "GLUT_JOYSTICK_BUTTON_A: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_JOYSTICK_BUTTON_B
#define GLUT_JOYSTICK_BUTTON_B RTU_JOYSTICK_BUTTON_B
#else
#define GLUT_JOYSTICK_BUTTON_B RTGLC_ABSENT(GLUT_JOYSTICK_BUTTON_B, "GLUT_JOYSTICK_BUTTON_B: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_JOYSTICK_BUTTON_C
#define GLUT_JOYSTICK_BUTTON_C RTU_JOYSTICK_BUTTON_C
#else
#define GLUT_JOYSTICK_BUTTON_C RTGLC_ABSENT(GLUT_JOYSTICK_BUTTON_C, "GLUT_JOYSTICK_BUTTON_C: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_JOYSTICK_BUTTON_D
#define GLUT_JOYSTICK_BUTTON_D RTU_JOYSTICK_BUTTON_D
#else
#define GLUT_JOYSTICK_BUTTON_D RTGLC_ABSENT(GLUT_JOYSTICK_BUTTON_D, "GLUT_JOYSTICK_BUTTON_D: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_GAME_MODE_ACTIVE
#define GLUT_GAME_MODE_ACTIVE RTU_GAME_MODE_ACTIVE
#else
#define GLUT_GAME_MODE_ACTIVE RTGLC_ABSENT(GLUT_GAME_MODE_ACTIVE, "GLUT_GAME_MODE_ACTIVE: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_GAME_MODE_POSSIBLE
#define GLUT_GAME_MODE_POSSIBLE RTU_GAME_MODE_POSSIBLE
#else
#define GLUT_GAME_MODE_POSSIBLE RTGLC_ABSENT(GLUT_GAME_MODE_POSSIBLE, "GLUT_GAME_MODE_POSSIBLE: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_GAME_MODE_WIDTH
#define GLUT_GAME_MODE_WIDTH RTU_GAME_MODE_WIDTH
#else
#define GLUT_GAME_MODE_WIDTH RTGLC_ABSENT(GLUT_GAME_MODE_WIDTH, "GLUT_GAME_MODE_WIDTH: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_GAME_MODE_HEIGHT
#define GLUT_GAME_MODE_HEIGHT RTU_GAME_MODE_HEIGHT
#else
#define GLUT_GAME_MODE_HEIGHT RTGLC_ABSENT(GLUT_GAME_MODE_HEIGHT, "GLUT_GAME_MODE_HEIGHT: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_GAME_MODE_PIXEL_DEPTH
#define GLUT_GAME_MODE_PIXEL_DEPTH RTU_GAME_MODE_PIXEL_DEPTH
#else
#define GLUT_GAME_MODE_PIXEL_DEPTH RTGLC_ABSENT(GLUT_GAME_MODE_PIXEL_DEPTH, "GLUT_GAME_MODE_PIXEL_DEPTH: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_GAME_MODE_REFRESH_RATE
#define GLUT_GAME_MODE_REFRESH_RATE RTU_GAME_MODE_REFRESH_RATE
#else
#define GLUT_GAME_MODE_REFRESH_RATE RTGLC_ABSENT(GLUT_GAME_MODE_REFRESH_RATE, "GLUT_GAME_MODE_REFRESH_RATE: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#ifdef RTU_GAME_MODE_DISPLAY_CHANGED
#define GLUT_GAME_MODE_DISPLAY_CHANGED RTU_GAME_MODE_DISPLAY_CHANGED
#else
#define GLUT_GAME_MODE_DISPLAY_CHANGED RTGLC_ABSENT(GLUT_GAME_MODE_DISPLAY_CHANGED, "GLUT_GAME_MODE_DISPLAY_CHANGED: not in the rtu GLUT shell (docs/glcompat.md)")
#endif
#define GLUT_BITMAP_9_BY_15 RTU_BITMAP_9_BY_15
#define GLUT_BITMAP_8_BY_13 RTU_BITMAP_8_BY_13
#define GLUT_BITMAP_TIMES_ROMAN_10 RTU_BITMAP_TIMES_ROMAN_10
#define GLUT_BITMAP_TIMES_ROMAN_24 RTU_BITMAP_TIMES_ROMAN_24
#define GLUT_BITMAP_HELVETICA_10 RTU_BITMAP_HELVETICA_10
#define GLUT_BITMAP_HELVETICA_12 RTU_BITMAP_HELVETICA_12
#define GLUT_BITMAP_HELVETICA_18 RTU_BITMAP_HELVETICA_18
#ifdef RTU_STROKE_ROMAN
#define GLUT_STROKE_ROMAN RTU_STROKE_ROMAN
#else
#define GLUT_STROKE_ROMAN RTGLC_ABSENT(GLUT_STROKE_ROMAN, "GLUT_STROKE_ROMAN: no stroke fonts (docs/glcompat.md)")
#endif
#ifdef RTU_STROKE_MONO_ROMAN
#define GLUT_STROKE_MONO_ROMAN RTU_STROKE_MONO_ROMAN
#else
#define GLUT_STROKE_MONO_ROMAN RTGLC_ABSENT(GLUT_STROKE_MONO_ROMAN, "GLUT_STROKE_MONO_ROMAN: no stroke fonts (docs/glcompat.md)")
#endif

#ifdef __cplusplus
}
#endif

#endif /* RT_GLCOMPAT_H */
