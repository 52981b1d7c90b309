/* SPDX-License-Identifier: Apache-2.0 */
/*
 * rtu.h - the Tracelist utility library (the analogue of GLU).
 *
 * Built only on rt.h: everything here could be written by an application.
 * Camera helpers multiply the current matrix exactly as their GLU
 * namesakes do; image I/O goes through OpenImageIO when the library was
 * built with it and falls back to binary PPM (8 bit) / PFM (float)
 * otherwise.  Compiles as strict C99 and as C++.
 */
#ifndef RT_RTU_H
#define RT_RTU_H

#include <rt/rt.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Multiplies the current matrix by a perspective projection (gluPerspective).
 * fovy in degrees; records RT_INVALID_VALUE against rtuPerspective
 * (rtRecordError) for fovy outside (0, 180), aspect <= 0, zNear <= 0 or
 * zFar <= zNear, and then changes nothing. */
RTAPI void rtuPerspective(RTdouble fovy, RTdouble aspect, RTdouble zNear, RTdouble zFar);

/* The text of an error code from rtGetError (gluErrorString): "invalid
 * value" for RT_INVALID_VALUE, ...; NULL for a value that is not an error
 * code.  Needs no context. */
RTAPI const char *rtuErrorString(RTenum error);

/* Multiplies the current matrix by a viewing transform (gluLookAt).  A
 * degenerate frame (eye == center, or up parallel to the view direction)
 * changes nothing and records RT_INVALID_VALUE against rtuLookAt. */
RTAPI void rtuLookAt(RTdouble eyeX, RTdouble eyeY, RTdouble eyeZ, RTdouble centerX,
                     RTdouble centerY, RTdouble centerZ, RTdouble upX, RTdouble upY,
                     RTdouble upZ);

/*
 * Writes an RGBA image as read by rtReadPixels (rows bottom to top, 4
 * components per pixel), type RT_UNSIGNED_BYTE or RT_FLOAT.  The format
 * follows the file name's extension: .ppm and .pfm are always available;
 * others (.png, .exr, .jpg, ...) need OpenImageIO.  Returns RT_TRUE on
 * success; RT_FALSE on a bad argument, an unsupported extension or an I/O
 * error, with a reason available from rtuImageError().
 */
RTAPI RTboolean rtuSaveImage(const char *path, RTsizei width, RTsizei height, RTenum type,
                             const void *pixels);

/*
 * Reads an image into a newly allocated RGBA buffer of the given type
 * (RT_UNSIGNED_BYTE or RT_FLOAT), rows bottom to top like rtReadPixels.
 * .ppm (P6, maxval 255) and .pfm are always available; other formats need
 * OpenImageIO.  Returns NULL on failure (reason from rtuImageError());
 * release with rtuFreeImage.
 */
RTAPI void *rtuLoadImage(const char *path, RTsizei *width, RTsizei *height, RTenum type);
RTAPI void rtuFreeImage(void *pixels);

/* RT_TRUE when rtuSaveImage can write files with this extension ("png"). */
RTAPI RTboolean rtuImageFormatSupported(const char *extension);

/* The reason the last rtuSaveImage/rtuLoadImage on this thread failed. */
RTAPI const char *rtuImageError(void);


/* ---- GLU: projections (docs/quadrics.md) ------------------------------ */

/* Multiplies the current matrix by rtOrtho(left, right, bottom, top, -1, 1)
 * (gluOrtho2D). */
RTAPI void rtuOrtho2D(RTdouble left, RTdouble right, RTdouble bottom, RTdouble top);

/* Multiplies the current matrix by the picking region of gluPickMatrix: the
 * deltaX x deltaY pixel region centred on window position (x, y) fills the
 * viewport.  deltaX or deltaY <= 0, a NULL viewport or a viewport of zero
 * size records RT_INVALID_VALUE and changes nothing (GLU: silently nothing). */
RTAPI void rtuPickMatrix(RTdouble x, RTdouble y, RTdouble deltaX, RTdouble deltaY,
                         const RTint viewport[4]);

/* Window coordinates of an object-space point under the given column-major
 * modelview and projection matrices and viewport (gluProject).  Returns
 * RT_FALSE, leaving the outputs unchanged, when the clip-space w is 0 or an
 * argument is NULL.  Needs no context. */
RTAPI RTboolean rtuProject(RTdouble objX, RTdouble objY, RTdouble objZ, const RTdouble model[16],
                           const RTdouble proj[16], const RTint viewport[4], RTdouble *winX,
                           RTdouble *winY, RTdouble *winZ);

/* The inverse of rtuProject (gluUnProject).  Returns RT_FALSE, leaving the
 * outputs unchanged, when proj * model is singular, the result's w is 0 or
 * an argument is NULL.  Needs no context. */
RTAPI RTboolean rtuUnProject(RTdouble winX, RTdouble winY, RTdouble winZ, const RTdouble model[16],
                             const RTdouble proj[16], const RTint viewport[4], RTdouble *objX,
                             RTdouble *objY, RTdouble *objZ);

/* ---- GLU: quadrics (docs/quadrics.md) --------------------------------- */

/* A quadric's drawing options (GLUquadric).  Opaque; holds no context
 * state, so one quadric may be used with any context. */
typedef struct rtu_quadric RTUquadric;

/* rtuQuadricNormals (values follow GLU). */
#define RTU_SMOOTH 100000
#define RTU_FLAT 100001
#define RTU_NONE 100002
/* rtuQuadricDrawStyle.  Only RTU_FILL draws today: the others need line and
 * point primitives, and drawing in them records RT_INVALID_OPERATION. */
#define RTU_POINT 100010
#define RTU_LINE 100011
#define RTU_FILL 100012
#define RTU_SILHOUETTE 100013
/* rtuQuadricOrientation. */
#define RTU_OUTSIDE 100020
#define RTU_INSIDE 100021

/* A new quadric: RTU_SMOOTH normals, RTU_OUTSIDE, no texture coordinates,
 * RTU_FILL.  NULL when out of memory. */
RTAPI RTUquadric *rtuNewQuadric(void);
/* Frees a quadric; NULL is ignored. */
RTAPI void rtuDeleteQuadric(RTUquadric *quadric);
RTAPI void rtuQuadricNormals(RTUquadric *quadric, RTenum normals);
RTAPI void rtuQuadricOrientation(RTUquadric *quadric, RTenum orientation);
RTAPI void rtuQuadricTexture(RTUquadric *quadric, RTboolean textureCoords);
RTAPI void rtuQuadricDrawStyle(RTUquadric *quadric, RTenum drawStyle);

/* The quadrics emit rtBegin/rtNormal3f/rtTexCoord2f/rtVertex3f exactly as
 * GLU emits gl calls, so they are called where rtBegin is allowed (inside
 * rtNewObject .. rtEndObject), like a GLU call compiled into a display
 * list.  Tessellation, orientation, normals and texture coordinates are
 * those of GLU 1.3 as Mesa's libGLU implements it (docs/quadrics.md). */
RTAPI void rtuSphere(RTUquadric *quadric, RTdouble radius, RTint slices, RTint stacks);
RTAPI void rtuCylinder(RTUquadric *quadric, RTdouble baseRadius, RTdouble topRadius,
                       RTdouble height, RTint slices, RTint stacks);
RTAPI void rtuDisk(RTUquadric *quadric, RTdouble innerRadius, RTdouble outerRadius, RTint slices,
                   RTint loops);
RTAPI void rtuPartialDisk(RTUquadric *quadric, RTdouble innerRadius, RTdouble outerRadius,
                          RTint slices, RTint loops, RTdouble startAngle, RTdouble sweepAngle);

/* ---- GLUT solid shapes (docs/quadrics.md) ----------------------------- */

/* The solid shapes of GLUT 3 with its geometry and normals, emitted like
 * the quadrics (call them inside rtNewObject).  The wire variants emit
 * RT_LINE_LOOP / RT_LINE_STRIP blocks through the solids' vertices. */
RTAPI void rtuSolidSphere(RTdouble radius, RTint slices, RTint stacks);
RTAPI void rtuSolidCube(RTdouble size);
RTAPI void rtuSolidCone(RTdouble base, RTdouble height, RTint slices, RTint stacks);
RTAPI void rtuSolidTorus(RTdouble innerRadius, RTdouble outerRadius, RTint sides, RTint rings);
RTAPI void rtuSolidTeapot(RTdouble size);
RTAPI void rtuSolidDodecahedron(void);
RTAPI void rtuSolidOctahedron(void);
RTAPI void rtuSolidTetrahedron(void);
RTAPI void rtuSolidIcosahedron(void);
RTAPI void rtuWireSphere(RTdouble radius, RTint slices, RTint stacks);
RTAPI void rtuWireCube(RTdouble size);
RTAPI void rtuWireCone(RTdouble base, RTdouble height, RTint slices, RTint stacks);
RTAPI void rtuWireTorus(RTdouble innerRadius, RTdouble outerRadius, RTint sides, RTint rings);
RTAPI void rtuWireTeapot(RTdouble size);
RTAPI void rtuWireDodecahedron(void);
RTAPI void rtuWireOctahedron(void);
RTAPI void rtuWireTetrahedron(void);
RTAPI void rtuWireIcosahedron(void);


/* ---- AFF scenes (BART; docs/aff.md) ----------------------------------- */

/* An AFF scene loaded into the current context: its objects, textures and
 * animation.  Opaque. */
typedef struct rtu_aff_scene RTUaffscene;

/* rtuGetAFFiv names. */
#define RTU_AFF_FRAMES 0x9A00            /* frames of the 'a' statement */
#define RTU_AFF_RESOLUTION 0x9A01        /* 2 ints: the 'v' resolution */
#define RTU_AFF_OBJECTS 0x9A02           /* objects created by the loader */
#define RTU_AFF_STATIC_OBJECTS 0x9A03    /* objects under no animated transform */
#define RTU_AFF_ANIMATED_OBJECTS 0x9A04  /* rigid objects under an 'x' chain */
#define RTU_AFF_UNSTRUCTURED_OBJECTS 0x9A05 /* objects of animated triangles */
#define RTU_AFF_INSTANCES 0x9A06         /* instances per frame (all visible) */
#define RTU_AFF_TRIANGLES 0x9A07         /* triangles as instantiated */
#define RTU_AFF_ANIMATED_TRIANGLES 0x9A08 /* 'tpa' triangles */
#define RTU_AFF_LIGHTS 0x9A09
#define RTU_AFF_TEXTURES 0x9A0A
#define RTU_AFF_MATERIALS 0x9A0B
#define RTU_AFF_TRANSFORM_NODES 0x9A0C   /* instantiated 'x' blocks */

/*
 * Reads an AFF file (and everything it includes, resolved against its
 * directory) and records it in the current context: one static object for
 * everything under no animated transform, one object per animated
 * transform ('x' block) that owns geometry, one object of the animated
 * triangles ('tpa') of each such frame, and the textures (through
 * rtuLoadImage).  Leaves the matrix mode, the modelview matrix and the
 * texture binding and enable as it found them; changes the current
 * material, normal and texture coordinate (rt.h cannot read them back), and
 * reads (clears) the error flag first: any API error while recording fails
 * the load.  Needs one free level on the modelview stack.  Includes and
 * textures must be regular files inside the top file's directory tree, and
 * the whole load stays within budgets linear in the input (docs/aff.md,
 * "Files and resource limits"; rtuLoadAFFv changes them).  Returns NULL on
 * failure with the reason ("file:line: reason", line 0 for the file as a
 * whole) in rtuAFFError(); a failed load leaves no object or texture
 * behind.  Needs a current context.
 */
RTAPI RTUaffscene *rtuLoadAFF(const char *path);

/* rtuLoadAFFv attributes: a list of (name, value) pairs ended by 0, like
 * EGL's attribute lists (docs/aff.md, "Files and resource limits"). */
#define RTU_AFF_MAX_TRIANGLES 0x9A20 /* triangles made in all, every inclusion
                                        counted; replaces the derived budget */
#define RTU_AFF_MAX_READ_MIB 0x9A21  /* MiB read in all, every inclusion counted;
                                        replaces the derived budget */
#define RTU_AFF_MAX_FILE_MIB 0x9A22  /* MiB of one file (default 256) */
#define RTU_AFF_ANY_DIRECTORY 0x9A23 /* RT_TRUE: includes and textures may lie
                                        outside the top file's directory tree */

/* rtuLoadAFF with limits and file policy other than the defaults; attribs
 * may be NULL (then it is rtuLoadAFF).  An unknown name or a value out of
 * range (budgets < 1, a flag not RT_TRUE or RT_FALSE) fails the load with
 * the reason in rtuAFFError(). */
RTAPI RTUaffscene *rtuLoadAFFv(const char *path, const RTint *attribs);

/* Deletes the scene's objects and textures (in the current context, which
 * must be the one it was loaded into) and frees it.  NULL is ignored. */
RTAPI void rtuDeleteAFF(RTUaffscene *scene);

/* The reason the last rtuLoadAFF on this thread failed ("" after a success). */
RTAPI const char *rtuAFFError(void);

RTAPI void rtuGetAFFiv(const RTUaffscene *scene, RTenum pname, RTint *params);

/* Time of frame f (0-based) of the 'a' statement: t0 + (t1 - t0) f / (N - 1). */
RTAPI RTdouble rtuAFFFrameTime(const RTUaffscene *scene, RTint frame);

/* The camera at time t (animated by 'k camera', else the 'v' view): eye,
 * unit view direction and unit up vector in world space. */
RTAPI void rtuAFFCamera(const RTUaffscene *scene, RTdouble t, RTdouble eye[3], RTdouble dir[3],
                        RTdouble up[3]);

/* Multiplies the current matrix by the camera's projection and viewing
 * transform at time t, like rtuPerspective followed by rtuLookAt (apply to
 * the projection matrix so that world space is the space lights and
 * instances are given in).  aspect <= 0 takes the scene's resolution. */
RTAPI void rtuAFFView(const RTUaffscene *scene, RTdouble t, RTdouble aspect);

/* Sets the clear colour, the global ambient light and lights RT_LIGHT0 ..
 * RT_LIGHT0 + n - 1 (n <= RT_MAX_LIGHTS) at time t, positions through the
 * current modelview matrix (identity: world space); disables other lights. */
RTAPI void rtuAFFLights(const RTUaffscene *scene, RTdouble t);

/* Describes the scene at time t into the frame being built: updates the
 * animated triangles (rtUpdateVertices, only when t changed) and
 * instantiates every visible object under the current modelview matrix
 * times its transform at t. */
RTAPI void rtuDrawAFF(RTUaffscene *scene, RTdouble t);

/* Records the whole scene at time t as one new static object (instances
 * and animated triangles baked into world space, same materials and
 * textures) and returns its name, 0 on failure: the flattened reference
 * of the two-level configuration. */
RTAPI RTuint rtuBakeAFF(RTUaffscene *scene, RTdouble t);

/* Names of the loader's objects of one kind (RT_STATIC, RT_AFFINE or
 * RT_UNSTRUCTURED); writes at most max names, returns how many exist. */
RTAPI RTsizei rtuAFFObjects(const RTUaffscene *scene, RTenum kind, RTsizei max, RTuint *names);

#ifdef __cplusplus
}
#endif

/* The GLUT-style window shell and bitmap fonts (docs/glut.md, docs/text.md). */
#include <rt/rtu_glut.h>

#endif /* RT_RTU_H */
