/*
 * rt.h - the Tracelist API: an OpenGL-like, immediate-mode ray tracing API.
 *
 * This header declares every entry point, enum and type of the core
 * library and nothing internal.  It compiles as strict C99 and as C++.
 *
 * Conventions (as in OpenGL):
 *   - Matrices are column-major: element (row r, column c) is m[c*4 + r];
 *     a point is transformed as p' = M p.
 *   - Errors are recorded, never returned: a failing call changes nothing
 *     and leaves its code in the current context's error slot, which keeps
 *     the first error until rtGetError() reads it.
 *   - Objects (the analogue of display lists) are named by RTuint names
 *     chosen by the application or handed out by rtGenObjects.
 *   - Calls made with no current context do nothing and return 0/RT_FALSE.
 *
 * Reference pages: docs/ (one page per entry-point family).
 */
#ifndef RT_RT_H
#define RT_RT_H

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32) && defined(RT_SHARED_BUILD)
#define RTAPI __declspec(dllexport)
#elif defined(__GNUC__)
#define RTAPI __attribute__((visibility("default")))
#else
#define RTAPI
#endif

typedef unsigned int RTenum;
typedef unsigned char RTboolean;
typedef unsigned int RTbitfield;
typedef signed char RTbyte;
typedef unsigned char RTubyte;
typedef short RTshort;
typedef unsigned short RTushort;
typedef int RTint;
typedef unsigned int RTuint;
typedef int RTsizei;
typedef float RTfloat;
typedef double RTdouble;
typedef void RTvoid;

/* An opaque rendering context.  The current context is per thread. */
typedef struct rt_context *RTcontext;

#define RT_FALSE 0
#define RT_TRUE 1

/* Sentinel id reported for "no hit" / "no such object" in query results. */
#define RT_INVALID_ID 0xFFFFFFFFu

/* ---- Errors (values follow OpenGL) ---------------------------------- */
#define RT_NO_ERROR 0
#define RT_INVALID_ENUM 0x0500
#define RT_INVALID_VALUE 0x0501
#define RT_INVALID_OPERATION 0x0502
#define RT_STACK_OVERFLOW 0x0503
#define RT_STACK_UNDERFLOW 0x0504
#define RT_OUT_OF_MEMORY 0x0505

/* ---- Data types ------------------------------------------------------ */
#define RT_BYTE 0x1400
#define RT_UNSIGNED_BYTE 0x1401
#define RT_SHORT 0x1402
#define RT_UNSIGNED_SHORT 0x1403
#define RT_INT 0x1404
#define RT_UNSIGNED_INT 0x1405
#define RT_FLOAT 0x1406
#define RT_DOUBLE 0x140A

/* ---- Primitive modes ------------------------------------------------- */
#define RT_TRIANGLES 0x0004
#define RT_TRIANGLE_STRIP 0x0005
#define RT_TRIANGLE_FAN 0x0006
#define RT_QUADS 0x0007
#define RT_QUAD_STRIP 0x0008
#define RT_POLYGON 0x0009

/* ---- Matrices -------------------------------------------------------- */
#define RT_MATRIX_MODE 0x0BA0
#define RT_MODELVIEW 0x1700
#define RT_PROJECTION 0x1701
#define RT_MODELVIEW_STACK_DEPTH 0x0BA3
#define RT_PROJECTION_STACK_DEPTH 0x0BA4
#define RT_MODELVIEW_MATRIX 0x0BA6
#define RT_PROJECTION_MATRIX 0x0BA7
#define RT_MAX_MODELVIEW_STACK_DEPTH 0x0D36
#define RT_MAX_PROJECTION_STACK_DEPTH 0x0D38

/* ---- Strings --------------------------------------------------------- */
#define RT_VENDOR 0x1F00
#define RT_RENDERER 0x1F01
#define RT_VERSION 0x1F02
#define RT_EXTENSIONS 0x1F03
#define RT_CONFIGURATION 0x8F00 /* the context's effective configuration */

/* ---- Vertex arrays --------------------------------------------------- */
#define RT_VERTEX_ARRAY 0x8074
#define RT_NORMAL_ARRAY 0x8075
#define RT_COLOR_ARRAY 0x8076
#define RT_TEXTURE_COORD_ARRAY 0x8078

/* ---- Appearance ------------------------------------------------------ */
#define RT_FRONT 0x0404
#define RT_BACK 0x0405
#define RT_FRONT_AND_BACK 0x0408
#define RT_AMBIENT 0x1200
#define RT_DIFFUSE 0x1201
#define RT_SPECULAR 0x1202
#define RT_POSITION 0x1203
#define RT_CONSTANT_ATTENUATION 0x1207
#define RT_LINEAR_ATTENUATION 0x1208
#define RT_QUADRATIC_ATTENUATION 0x1209
#define RT_EMISSION 0x1600
#define RT_SHININESS 0x1601
#define RT_AMBIENT_AND_DIFFUSE 0x1602
#define RT_REFLECTIVITY 0x8F10 /* mirror weight, 0..1 */
#define RT_TRANSPARENCY 0x8F11 /* refracted weight, 0..1 */
#define RT_INDEX_OF_REFRACTION 0x8F12
#define RT_LIGHT_MODEL_AMBIENT 0x0B53
#define RT_COLOR_MATERIAL 0x0B57
#define RT_LIGHT0 0x4000 /* RT_LIGHT0 + i, i < RT_MAX_LIGHTS */
#define RT_MAX_LIGHTS 0x0D31
#define RT_FLAT 0x1D00
#define RT_SMOOTH 0x1D01
#define RT_SHADE_MODEL 0x0B54

/* Shading modes for rtShadingMode. */
#define RT_SHADING_MODE 0x8F20
#define RT_EYE_LIGHT 0x8F21 /* headlight, no shadows: "OpenGL-like ray casting" */
#define RT_WHITTED 0x8F22   /* Phong + hard shadows + reflection/refraction */
#define RT_MAX_RAY_DEPTH 0x8F23 /* rtRenderParameteri: Whitted recursion depth */
/* rtRenderParameteri(RT_UPDATE_STRATEGY, s): the strategy of objects
 * without their own hint (RT_UPDATE_STRATEGY is defined below). */

/* ---- Frame ----------------------------------------------------------- */
#define RT_VIEWPORT 0x0BA2
#define RT_COLOR_CLEAR_VALUE 0x0C22
#define RT_RGBA 0x1908

/* ---- Textures -------------------------------------------------------- */
#define RT_TEXTURE_2D 0x0DE1         /* target, and rtEnable capability */
#define RT_TEXTURE_BINDING_2D 0x8069 /* rtGetIntegerv */
#define RT_MAX_TEXTURE_SIZE 0x0D33   /* rtGetIntegerv, 16384 */
#define RT_TEXTURE_MAG_FILTER 0x2800
#define RT_TEXTURE_MIN_FILTER 0x2801
#define RT_TEXTURE_WRAP_S 0x2802
#define RT_TEXTURE_WRAP_T 0x2803
#define RT_NEAREST 0x2600
#define RT_LINEAR 0x2601
/* RT_TEXTURE_MIN_FILTER only: mipmapped filters (docs/textures.md). */
#define RT_NEAREST_MIPMAP_NEAREST 0x2700
#define RT_LINEAR_MIPMAP_NEAREST 0x2701
#define RT_NEAREST_MIPMAP_LINEAR 0x2702
#define RT_LINEAR_MIPMAP_LINEAR 0x2703
#define RT_REPEAT 0x2901
#define RT_CLAMP_TO_EDGE 0x812F
#define RT_RGB 0x1907
/* RT_RGBA (0x1908) is defined with the frame constants above. */

/* ---- Context state and statistics (rtGetIntegerv / rtGetFloatv) ------ */
#define RT_THREADS 0x8F30            /* render threads (caller included) */
#define RT_BVH_BINS 0x8F31           /* bins of the binned SAH builder */
#define RT_OBJECT_COUNT 0x8F32       /* live objects */
#define RT_INSTANCE_COUNT 0x8F33     /* instances in the current scene */
#define RT_WORKER_THREADS_RUNNING 0x8F34 /* threads the context has started */
#define RT_BUILD_THREADS 0x8F35      /* K of "build_threads=K" */
#define RT_BUILD_THREADS_RUNNING 0x8F36 /* asynchronous build threads started */
/* Per-frame statistics: counters are for the last rtRenderFrame /
 * rtTraceRays / rtOccludedRays call, times in milliseconds. */
#define RT_STAT_RAYS 0x8F40
#define RT_STAT_NODE_TESTS 0x8F41
#define RT_STAT_TRIANGLE_TESTS 0x8F42
#define RT_STAT_INSTANCE_TESTS 0x8F43
#define RT_STAT_OBJECT_BUILDS 0x8F44    /* object BVHs built during the call */
#define RT_STAT_TOPLEVEL_BUILDS 0x8F45  /* 0 when the instance list was unchanged */
#define RT_STAT_OBJECT_UPDATES 0x8F46   /* stale object structures updated */
#define RT_STAT_BUILD_TIME 0x8F48       /* float, ms spent in object builds */
#define RT_STAT_TOPLEVEL_TIME 0x8F49    /* float, ms spent on the top level */
#define RT_STAT_RENDER_TIME 0x8F4A      /* float, ms for the whole call */
#define RT_STAT_UPDATE_TIME 0x8F4B      /* float, ms updating changed objects */

/* Per-object queries (rtGetObjectiv / rtGetObjectfv). */
#define RT_OBJECT_TRIANGLES 0x8F50
#define RT_OBJECT_BUILT 0x8F51       /* RT_TRUE once its BVH exists */
#define RT_OBJECT_BVH_NODES 0x8F52
#define RT_OBJECT_SAH_COST 0x8F53    /* float; 0 before the build */
#define RT_OBJECT_BUILD_TIME 0x8F54  /* float, ms of the last build */
#define RT_OBJECT_BOUNDS 0x8F55      /* float[6]: min xyz, max xyz */
#define RT_OBJECT_CLASS 0x8F56       /* the class this frame (and a hint) */
#define RT_UPDATE_STRATEGY 0x8F57    /* the update strategy (and a hint) */
#define RT_OBJECT_UPDATE_TIME 0x8F58 /* float, ms of the last update */
#define RT_OBJECT_REBUILDS 0x8F59    /* full builds so far */
#define RT_OBJECT_REFITS 0x8F5A      /* refits so far */
#define RT_OBJECT_VERTICES 0x8F5B    /* vertices, in recording order */

/* Object classes (paper 004 sec. 3).  As hints, RT_AUTOMATIC lets the
 * runtime classify from what changed each frame. */
#define RT_AUTOMATIC 0x8F60
#define RT_STATIC 0x8F61
#define RT_AFFINE 0x8F62
#define RT_UNSTRUCTURED 0x8F63
/* Update strategies for unstructured objects (papers 000 and 001). */
#define RT_REFIT 0x8F64               /* refit the bounds only */
#define RT_REBUILD 0x8F65             /* binned SAH rebuild every frame */
#define RT_REBUILD_MEDIAN 0x8F66      /* spatial-median (BIH-like) rebuild every frame */
#define RT_REBUILD_HEURISTIC 0x8F67   /* refit; rebuild when SAH cost degraded */
#define RT_RESTRUCTURE 0x8F68         /* selective restructuring (paper 001) */
#define RT_ASYNC_REBUILD 0x8F69       /* refit while K threads rebuild (paper 000 sec. 6) */

/* ---- Ray queries ----------------------------------------------------- */
/* A ray: points org + t*dir for t in [tmin, tmax].  dir need not be
 * normalised; t is measured in units of dir. */
typedef struct RTray {
    RTfloat org[3];
    RTfloat tmin;
    RTfloat dir[3];
    RTfloat tmax;
} RTray;

/* The closest hit of a ray.  On a miss t is +infinity and the three ids
 * are RT_INVALID_ID.  u, v are the barycentrics of the hit point with
 * respect to the triangle's second and third vertex:
 * p = (1-u-v) v0 + u v1 + v v2.  instance is the index of the instance in
 * the scene (order of rtInstantiateObject), object its object's name,
 * primitive the triangle's index inside the object (assembly order). */
typedef struct RThit {
    RTfloat t;
    RTfloat u;
    RTfloat v;
    RTuint instance;
    RTuint object;
    RTuint primitive;
} RThit;

typedef void (*RTerrorcallback)(RTenum error, const char *message, void *user);

/* ---- Context and errors (docs/context.md, docs/errors.md) ------------ */
RTAPI RTcontext rtCreateContext(const char *configuration);
/* rtCreateContext that says why it returned NULL: a bad configuration
 * (which item, and why) or "out of memory", written to `reason` (at most
 * bufSize bytes, always terminated; "" on success).  Nothing is kept for a
 * later call to read.  RT_REASON_SIZE bytes hold every reason whole but
 * one quoting a very long key or value (docs/context.md). */
#define RT_REASON_SIZE 256
RTAPI RTcontext rtCreateContextWithReason(const char *configuration, RTsizei bufSize,
                                          char *reason);
RTAPI void rtDestroyContext(RTcontext context);
RTAPI RTboolean rtMakeCurrent(RTcontext context);
RTAPI RTcontext rtGetCurrentContext(void);
RTAPI RTenum rtGetError(void);
RTAPI void rtErrorCallback(RTerrorcallback callback, void *user);
RTAPI const char *rtGetString(RTenum name);
RTAPI void rtGetIntegerv(RTenum pname, RTint *params);
RTAPI void rtGetFloatv(RTenum pname, RTfloat *params);
RTAPI void rtEnable(RTenum cap);
RTAPI void rtDisable(RTenum cap);
RTAPI RTboolean rtIsEnabled(RTenum cap);

/* ---- Objects (docs/objects.md) ---------------------------------------- */
RTAPI void rtGenObjects(RTsizei n, RTuint *objects);
RTAPI void rtNewObject(RTuint object);
RTAPI void rtEndObject(void);
RTAPI void rtDeleteObjects(RTsizei n, const RTuint *objects);
RTAPI RTboolean rtIsObject(RTuint object);
RTAPI void rtGetObjectiv(RTuint object, RTenum pname, RTint *params);
RTAPI void rtGetObjectfv(RTuint object, RTenum pname, RTfloat *params);
RTAPI void rtObjectParameteri(RTuint object, RTenum pname, RTint param);
RTAPI void rtUpdateVertices(RTuint object, RTenum array, RTint first, RTsizei count, RTenum type,
                            RTsizei stride, const void *data);

/* ---- Primitives (docs/primitives.md) ---------------------------------- */
RTAPI void rtBegin(RTenum mode);
RTAPI void rtEnd(void);
RTAPI void rtVertex2f(RTfloat x, RTfloat y);
RTAPI void rtVertex2d(RTdouble x, RTdouble y);
RTAPI void rtVertex3f(RTfloat x, RTfloat y, RTfloat z);
RTAPI void rtVertex3d(RTdouble x, RTdouble y, RTdouble z);
RTAPI void rtVertex2fv(const RTfloat *v);
RTAPI void rtVertex2dv(const RTdouble *v);
RTAPI void rtVertex3fv(const RTfloat *v);
RTAPI void rtVertex3dv(const RTdouble *v);
RTAPI void rtNormal3f(RTfloat nx, RTfloat ny, RTfloat nz);
RTAPI void rtNormal3fv(const RTfloat *v);
RTAPI void rtTexCoord2f(RTfloat s, RTfloat t);
RTAPI void rtTexCoord2fv(const RTfloat *v);
RTAPI void rtColor3f(RTfloat r, RTfloat g, RTfloat b);
RTAPI void rtColor3fv(const RTfloat *v);
RTAPI void rtColor4f(RTfloat r, RTfloat g, RTfloat b, RTfloat a);
RTAPI void rtColor4fv(const RTfloat *v);
RTAPI void rtShadeModel(RTenum mode);

/* ---- Vertex arrays (docs/arrays.md) ----------------------------------- */
RTAPI void rtEnableClientState(RTenum array);
RTAPI void rtDisableClientState(RTenum array);
RTAPI void rtVertexPointer(RTint size, RTenum type, RTsizei stride, const void *pointer);
RTAPI void rtNormalPointer(RTenum type, RTsizei stride, const void *pointer);
RTAPI void rtColorPointer(RTint size, RTenum type, RTsizei stride, const void *pointer);
RTAPI void rtTexCoordPointer(RTint size, RTenum type, RTsizei stride, const void *pointer);
RTAPI void rtDrawArrays(RTenum mode, RTint first, RTsizei count);
RTAPI void rtDrawElements(RTenum mode, RTsizei count, RTenum type, const void *indices);

/* ---- Matrices (docs/matrices.md) -------------------------------------- */
RTAPI void rtMatrixMode(RTenum mode);
RTAPI void rtLoadIdentity(void);
RTAPI void rtLoadMatrixf(const RTfloat *m);
RTAPI void rtLoadMatrixd(const RTdouble *m);
RTAPI void rtMultMatrixf(const RTfloat *m);
RTAPI void rtMultMatrixd(const RTdouble *m);
RTAPI void rtTranslatef(RTfloat x, RTfloat y, RTfloat z);
RTAPI void rtTranslated(RTdouble x, RTdouble y, RTdouble z);
RTAPI void rtRotatef(RTfloat angle, RTfloat x, RTfloat y, RTfloat z);
RTAPI void rtRotated(RTdouble angle, RTdouble x, RTdouble y, RTdouble z);
RTAPI void rtScalef(RTfloat x, RTfloat y, RTfloat z);
RTAPI void rtScaled(RTdouble x, RTdouble y, RTdouble z);
RTAPI void rtFrustum(RTdouble left, RTdouble right, RTdouble bottom, RTdouble top,
                     RTdouble near_val, RTdouble far_val);
RTAPI void rtOrtho(RTdouble left, RTdouble right, RTdouble bottom, RTdouble top,
                   RTdouble near_val, RTdouble far_val);
RTAPI void rtPushMatrix(void);
RTAPI void rtPopMatrix(void);

/* ---- Instances and frames (docs/instances.md) ------------------------- */
RTAPI void rtInstantiateObject(RTuint object);
RTAPI void rtBeginFrame(void);

/* ---- Appearance (docs/appearance.md) ---------------------------------- */
RTAPI void rtMaterialf(RTenum face, RTenum pname, RTfloat param);
RTAPI void rtMaterialfv(RTenum face, RTenum pname, const RTfloat *params);
RTAPI void rtLightf(RTenum light, RTenum pname, RTfloat param);
RTAPI void rtLightfv(RTenum light, RTenum pname, const RTfloat *params);
RTAPI void rtLightModelfv(RTenum pname, const RTfloat *params);
RTAPI void rtShadingMode(RTenum mode);
RTAPI void rtRenderParameteri(RTenum pname, RTint param);

/* ---- Textures (docs/textures.md) -------------------------------------- */
RTAPI void rtGenTextures(RTsizei n, RTuint *textures);
RTAPI void rtDeleteTextures(RTsizei n, const RTuint *textures);
RTAPI RTboolean rtIsTexture(RTuint texture);
RTAPI void rtBindTexture(RTenum target, RTuint texture);
RTAPI void rtTexImage2D(RTenum target, RTint level, RTint internalformat, RTsizei width,
                        RTsizei height, RTint border, RTenum format, RTenum type,
                        const void *pixels);
RTAPI void rtTexParameteri(RTenum target, RTenum pname, RTint param);

/* ---- Frames (docs/frames.md) ------------------------------------------ */
RTAPI void rtViewport(RTint x, RTint y, RTsizei width, RTsizei height);
RTAPI void rtClearColor(RTfloat red, RTfloat green, RTfloat blue, RTfloat alpha);
RTAPI void rtRenderFrame(void);
RTAPI void rtFinish(void);
RTAPI void rtReadPixels(RTint x, RTint y, RTsizei width, RTsizei height, RTenum format,
                        RTenum type, void *pixels);

/* ---- Ray queries (docs/queries.md) ------------------------------------ */
RTAPI void rtTraceRays(RTsizei count, const RTray *rays, RThit *hits);
RTAPI void rtOccludedRays(RTsizei count, const RTray *rays, RTboolean *occluded);

#ifdef __cplusplus
}
#endif

#endif /* RT_RT_H */
