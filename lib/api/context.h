/* SPDX-License-Identifier: Apache-2.0 */
/*
 * context.h - the rendering context: all mutable state of the library.
 *
 * Every entry point starts with GET_CURRENT_CONTEXT and validates in the
 * order STYLE.md sec. 3 fixes: mode, enums, values, limits, then acquires
 * memory, then changes state.  rt_error() is the one place errors are
 * recorded.  Nothing here is touched by worker threads except through the
 * read-only views the renderer is handed for the duration of a frame.
 */
#ifndef RT_API_CONTEXT_H
#define RT_API_CONTEXT_H

#include <rt/rt.h>
#include <stdint.h>

#include "render/overlay.h"
#include "render/render.h"
#include "scene/recording.h"
#include "scene/scene.h"
#include "trace/kernels.h"

/* The context's texture coordinate generation: the scene's s, t and q
 * (scene/mesh.h, SCENE_TEXGEN_*), then r, which GL keeps and a 2D
 * texture never reads (GL 1.1 sec. 3.8: a 2D lookup uses s and t), so it
 * stays context state and reaches no geometry. */
#define RT_TEXGEN_R SCENE_TEXGEN_COORDS
#define RT_TEXGEN_COORDS (SCENE_TEXGEN_COORDS + 1)

#define API_MAX_MODELVIEW_DEPTH 32 /* OpenGL's minimum, DESIGN.md */
#define API_MAX_PROJECTION_DEPTH 4 /* >= 2 required */
#define API_MAX_THREADS 256
#define API_MAX_VIEWPORT 16384
#define API_MAX_RAY_DEPTH_LIMIT 16
#define API_MAX_ATTRIB_STACK_DEPTH 16        /* GL's minimum for both stacks (attrib.c) */
#define API_MAX_CLIENT_ATTRIB_STACK_DEPTH 16

struct matrix_stack {
    double m[API_MAX_MODELVIEW_DEPTH][16]; /* m[depth-1] is the top */
    int depth;                            /* 1..max_depth */
    int max_depth;
};

struct client_array {
    int enabled;
    int size;
    RTenum type;
    RTsizei stride;
    const void *pointer;
};

/* rtPixelStorei's state for one direction (pixel_store.c): GL's names,
 * GL's defaults (alignment 4, the rest 0). */
struct pixel_store {
    int swap_bytes, lsb_first;
    int row_length, skip_rows, skip_pixels;
    int alignment;
};

/* One entry of the attribute stack (attrib.c): the groups of `mask` as
 * they were at rtPushAttrib.  Everything is copied whatever the mask (a
 * few kilobytes); rtPopAttrib restores only the groups in the mask. */
struct attrib_entry {
    RTbitfield mask;
    float current_color[4], current_normal[3], current_texcoord[4];
    float raster_pos[4], raster_color[4];
    int raster_valid;
    struct scene_material material;
    int color_material;
    RTenum shade_model;
    uint32_t texture_binding;
    int texture_2d;
    RTenum polygon_mode[2];
    int cull_face_enabled;
    RTenum cull_face_mode;
    int normalize_enabled, rescale_normal_enabled;
    int depth_test, dither, polygon_offset_fill;
    int texgen_enabled[RT_TEXGEN_COORDS];
    RTenum texgen_mode[RT_TEXGEN_COORDS];
    float texgen_object_plane[RT_TEXGEN_COORDS][4];
    float texgen_eye_plane[RT_TEXGEN_COORDS][4];
    struct scene_light lights[RENDER_MAX_LIGHTS];
    float global_ambient[4];
    int light_model_two_side, light_model_local_viewer;
    struct scene_fog fog;
    struct render_visibility vis;
    float clear_color[4];
    int viewport[4];
    RTenum matrix_mode;
    RTuint list_base;
    RTenum acceleration_hint; /* RT_HINT_BIT: the one hint with state here */
};

/* One entry of the client attribute stack (attrib.c). */
struct client_attrib_entry {
    RTbitfield mask;
    struct client_array vertex_array, normal_array, color_array, texcoord_array;
    struct pixel_store unpack, pack;
};

/* What RT_COMPILE restores at rtEndList (list.c). */
struct list_saved_state {
    float normal[3], color[4], texcoord[4];
    RTenum shade_model;
    int color_material;
    struct scene_material material;
    uint32_t texture_binding;
    int texture_2d;
    struct scene_light lights[RENDER_MAX_LIGHTS];
    float global_ambient[4];
    RTuint list_base;
    int clip_enabled[RENDER_MAX_CLIP_PLANES]; /* rtEnable(RT_CLIP_PLANEi) */
    /* The fixed-function switches a list may record (n-ffstate). */
    int cull_face_enabled;
    RTenum cull_face_mode;
    int normalize_enabled, rescale_normal_enabled;
    int texgen_enabled[RT_TEXGEN_COORDS];
    RTenum texgen_mode[RT_TEXGEN_COORDS];
    float texgen_object_plane[RT_TEXGEN_COORDS][4];
    float texgen_eye_plane[RT_TEXGEN_COORDS][4];
    int light_model_two_side, light_model_local_viewer;
    struct scene_fog fog;
    /* Raster state a list can set (lines.c): RT_BLEND, rtBlendFunc,
     * rtPolygonMode, rtLineWidth, rtPointSize, RT_ALPHA_TEST, rtAlphaFunc,
     * RT_POLYGON_OFFSET_FILL, rtPolygonOffset. */
    struct render_visibility vis;
    RTenum polygon_mode[2];
    int polygon_offset_fill;
    int color_material_current; /* rt_context's (n-light) */
};

/* stream= values (rt_context.stream_mode). */
enum { RT_STREAM_AUTO, RT_STREAM_ON, RT_STREAM_OFF };

struct rt_context {
    int bound; /* current in some thread */

    /* Configuration (rtCreateContext). */
    int threads;
    struct bvh_build_params build_params;
    /* rtHint(RT_ACCELERATION_HINT, mode): RT_DONT_CARE, RT_FASTEST or
     * RT_NICEST; recorded on an object at its rtEndObject (list.c). */
    RTenum acceleration_hint;
    /* The traversal kernels' ISA table (isa=, lib/trace/kernels.h):
     * chosen here once, read by every trace of the context. */
    const struct trace_kernels *kernels;
    char configuration[192];
    /* packets= (docs/context.md): kernels points here after creation, a
     * copy of the chosen table whose packet walks are NULL when off. */
    int packets_off;
    /* stream= (docs/context.md): RT_STREAM_AUTO, _ON or _OFF; off
     * leaves the copy's stream_pair and stream_counted NULL. */
    int stream_mode;
    int flatten_mode; /* flatten= (enum scene_flatten_mode, scene/flatten.h) */
    struct trace_kernels kernel_table;

    /* Errors (error.c). */
    RTenum error;
    RTerrorcallback error_callback;
    void *error_user;
    int debug_print; /* TRACELIST_DEBUG set */
    char last_message[320]; /* "CODE: message", for collapsing repeats */
    unsigned repeat_count;

    /* Matrices (matrix.c). */
    RTenum matrix_mode;
    struct matrix_stack modelview;
    struct matrix_stack projection;

    /* Current vertex attributes and primitive state (begin_end.c). */
    float current_normal[3];
    float current_color[4];
    float current_texcoord[4]; /* s, t, r, q (GL) */
    RTenum shade_model;
    int color_material;
    struct scene_material material;
    struct scene_recording recording; /* rtNewObject .. rtEndObject */
    struct scene_block block;         /* rtBegin .. rtEnd */
    struct scene_recording *target;   /* where the block's vertices go (list or immediate) */

    /* Display lists (list.c). */
    RTenum list_mode;   /* RT_COMPILE or RT_COMPILE_AND_EXECUTE while recording */
    RTuint list_base;   /* rtListBase */
    int call_depth;     /* nesting of the lists being executed (GL's CallDepth) */
    int recording_object; /* rtNewObject (not rtNewList): geometry only, no bare vertices */
    int replaying;      /* > 0: calls come from a list's replay, never recorded */
    struct list_saved_state saved;  /* RT_COMPILE: state rtEndList restores */
    struct list_exec *exec;         /* RT_COMPILE_AND_EXECUTE: segments to instance */
    uint32_t exec_count, exec_capacity;

    /* GL frames (frame.c): rtClear was called once, and a frame was
     * described since the last render, which rtFinish, rtFlush and
     * rtReadPixels then render. */
    int gl_frames;
    int frame_unrendered;
    uint64_t frames_traced; /* RT_FRAMES_TRACED */
    int normal_given; /* the application set a normal outside lists */

    /* Texture state (texture.c); the textures are the scene's.  A
     * triangle records texture_binding when texture_2d is enabled
     * (begin_end.c, triangle_state). */
    uint32_t texture_binding; /* RT_TEXTURE_BINDING_2D; 0: none */
    int texture_2d;           /* rtEnable(RT_TEXTURE_2D) */

    /* Lines and points (lines.c): the polygon mode of front and back
     * faces, and the open block when it gives lines or points. */
    RTenum polygon_mode[2];
    int lines_block;
    struct scene_line_block line_block;

    /* Vertex arrays (array.c). */
    struct client_array vertex_array, normal_array, color_array, texcoord_array;

    /* Configuration the scene was created with (rtCreateContext). */
    int build_threads;      /* K of build_threads=K */
    int toplevel_cellsplit; /* toplevel=cellsplit */

    /* Everything an API-less process could hold: objects, instances,
     * textures, updates (scene/scene.h). */
    struct scene scene;

    /* Rendering (appearance.c, frame.c). */
    struct render_state render;
    /* The frame's light-set index of render.lights (rt_light_set_now):
     * valid while light_set_cached, the frame's table has not restarted
     * (light_set_serial) and the lights equal light_set_lights, so that
     * drawing under unchanged lights costs a comparison. */
    int light_set_cached;
    uint32_t light_set_index;
    uint64_t light_set_serial;
    struct scene_light light_set_lights[RENDER_MAX_LIGHTS];
    /* RT_COLOR_MATERIAL is on and GL has written the current colour into
     * the tracked properties (a colour, the enable, rtColorMaterial), which
     * ctx->material then does not hold yet (rt_color_material_write);
     * 0 after rtPopAttrib restored the material it pushed. */
    int color_material_current;
    struct rt_pool *pool; /* NULL until a frame needs threads */

    /* Statistics of the last frame or query. */
    struct render_stats stats;

    /* The current raster position (raster.c): window coordinates, valid
     * flag, and the colour latched by rtRasterPos / rtWindowPos; and the
     * frame's bitmaps, drawn over its image by rtRenderFrame. */
    float raster_pos[4];
    int raster_valid;
    float raster_color[4];
    struct render_overlay overlay;
    /* GL fixed-function switches (appearance.c, get.c).  Those that GL
     * applies per primitive reach the triangles through ctx->material's
     * appended fields (rt_sync_fixed_function); RT_LIGHTING lives there
     * directly (material.lighting). */
    int cull_face_enabled;  /* RT_CULL_FACE */
    RTenum cull_face_mode;  /* rtCullFace, RT_BACK by default */
    int normalize_enabled;  /* RT_NORMALIZE */
    int rescale_normal_enabled; /* RT_RESCALE_NORMAL */
    /* Accepted capabilities without a ray tracing meaning: remembered
     * for rtIsEnabled only. */
    int depth_test, dither, polygon_offset_fill;
    /* rtTexGen for s (0), t (1), q (2) and r (RT_TEXGEN_R) (fixed_function.c);
     * s, t and q are recorded through ctx->material by
     * rt_sync_fixed_function while enabled, r is state only. */
    int texgen_enabled[RT_TEXGEN_COORDS];  /* RT_TEXTURE_GEN_S, _T, _Q, _R */
    RTenum texgen_mode[RT_TEXGEN_COORDS];  /* RT_EYE_LINEAR initially */
    float texgen_object_plane[RT_TEXGEN_COORDS][4];
    float texgen_eye_plane[RT_TEXGEN_COORDS][4]; /* in eye space */
    /* rtPushAttrib / rtPushClientAttrib (attrib.c).  attrib_list_base:
     * the depth at rtNewList, below which an RT_COMPILE list's
     * rtPopAttrib does not reach while it is recorded; attrib_skipped:
     * the RT_COMPILE pushes recorded but not made (stack full). */
    struct attrib_entry attrib_stack[API_MAX_ATTRIB_STACK_DEPTH];
    int attrib_depth;
    int attrib_list_base, attrib_skipped;
    struct client_attrib_entry client_attrib_stack[API_MAX_CLIENT_ATTRIB_STACK_DEPTH];
    int client_attrib_depth;
    /* rtPixelStorei (pixel_store.c): rtTexImage2D, rtTexSubImage2D and
     * rtBitmap read with unpack, rtReadPixels writes with pack. */
    struct pixel_store unpack, pack;
};

/* Derives ctx->material's culling and normalisation fields from the
 * switches above, re-interning the material when they changed
 * (appearance.c). */
void rt_sync_fixed_function(struct rt_context *ctx);

/* The calling thread's current context, or NULL. */
struct rt_context *rt_current_context(void);

#define GET_CURRENT_CONTEXT(ctx) struct rt_context *ctx = rt_current_context()

/*
 * Records an error: stores code when no error is pending, calls the
 * callback for every error, and prints when TRACELIST_DEBUG is set
 * (collapsing identical repeats).  fmt starts with the entry point name.
 */
void rt_error(struct rt_context *ctx, RTenum code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Records RT_INVALID_OPERATION and returns 1 when inside rtBegin/rtEnd. */
int rt_check_outside_begin(struct rt_context *ctx, const char *caller);
/* Records RT_INVALID_OPERATION and returns 1 inside an object definition
 * or inside rtBegin/rtEnd. */
int rt_check_outside_object(struct rt_context *ctx, const char *caller);
/* Returns 1 when every value is finite, else records RT_INVALID_VALUE. */
int rt_check_finite(struct rt_context *ctx, const char *caller, const float *v, int n);
int rt_check_finite_d(struct rt_context *ctx, const char *caller, const double *v, int n);

/*
 * Primitive recording shared by rtBegin/rtVertex and the vertex arrays
 * (begin_end.c).  rt_block_start fixes the matrices for a block of
 * vertices; rt_record_vertex transforms one vertex and its normal, stores
 * it and assembles the triangles it completes.  Returns 0, or -1 after
 * recording RT_INVALID_VALUE (non-finite result) or RT_OUT_OF_MEMORY, in
 * which case nothing was stored.
 */
/* Returns 0, -1 on allocation failure (immediate mode). */
int rt_block_start(struct rt_context *ctx, RTenum mode);
int rt_record_vertex(struct rt_context *ctx, const char *caller, const double position[3],
                     const float normal[3], const float color[4], const float texcoord[4]);
/* Indexed drawing: rt_store_vertex stores a vertex without assembling;
 * rt_assemble_indexed stores the triangles completed by stream position k
 * of the block, stream position j being mesh vertex map[j].  Same return
 * convention as rt_record_vertex. */
int rt_store_vertex(struct rt_context *ctx, const char *caller, const double position[3],
                    const float normal[3], const float color[4], const float texcoord[4]);
int rt_assemble_indexed(struct rt_context *ctx, const char *caller, uint32_t k,
                        const uint32_t *map);
/* Checks that a vertex would transform to finite values without storing. */
int rt_vertex_is_finite(const struct rt_context *ctx, const double position[3]);

/*
 * Blocks that give lines or points (lines.c): rt_lines_block_start starts
 * the block (rt_block_start included) and returns 1 when mode is a line
 * mode or a polygon mode under rtPolygonMode RT_LINE / RT_POINT, else 0
 * (the block gives triangles), -1 when the block could not start (out of
 * memory, nothing recorded); rt_lines_vertex stores a vertex (0, or -1
 * after recording the error); rt_lines_block_end closes the block.
 */
int rt_lines_block_start(struct rt_context *ctx, RTenum mode);
int rt_lines_vertex(struct rt_context *ctx, const char *caller, const double position[3],
                    const float color[4]);
void rt_lines_block_end(struct rt_context *ctx, const char *caller);
/* The clip planes geometry drawn now is clipped by (lines.c): the enabled
 * planes and their eye-space equations, the others zero. */
void rt_clip_now(const struct rt_context *ctx, struct scene_clip *clip);
/* The fog and light model geometry drawn now is drawn under
 * (fixed_function.c), zero-filled so that equal states compare equal. */
void rt_gl_state_now(struct rt_context *ctx, struct scene_gl_state *gl);
/* The index of the lights current now in the frame's table of light sets
 * (scene_frame_light_set), for an instance about to be added
 * (fixed_function.c); UINT32_MAX when out of memory (the caller records
 * the error and draws nothing). */
uint32_t rt_light_set_now(struct rt_context *ctx);
/* RT_COLOR_MATERIAL's write-back (appearance.c): rt_color_material_write
 * puts the current colour into m's tracked properties while the enable
 * is on; rt_color_material_settle does it to the context's material
 * where the tracking ends (and, in a list, starts a segment). */
void rt_color_material_write(const struct rt_context *ctx, struct scene_material *m);
void rt_color_material_settle(struct rt_context *ctx, const char *caller);
/* The raster state geometry drawn now takes (lines.c, raster_state.h). */
void rt_raster_now(const struct rt_context *ctx, struct scene_raster *raster);
/* Display lists (list.c).  rt_list_compiling: a list is being recorded
 * and the call comes from the application (not a replay).  The record
 * functions add an operation; they return 1 when the call must not take
 * effect now (RT_COMPILE), 0 when it must (RT_COMPILE_AND_EXECUTE, or
 * not compiling). */
enum list_state_call {
    LIST_COLOR, LIST_NORMAL, LIST_TEXCOORD, LIST_MATERIAL, LIST_SHADE_MODEL, LIST_ENABLE,
    LIST_DISABLE, LIST_BIND_TEXTURE, LIST_LIGHT, LIST_LIGHT_MODEL, LIST_LIST_BASE,
    LIST_CLIP_PLANE,
    /* Fixed-function state (appearance.c, fixed_function.c). */
    LIST_CULL_FACE, LIST_FRONT_FACE, LIST_COLOR_MATERIAL, LIST_TEX_ENV, LIST_TEX_GEN, LIST_FOG,
    LIST_BLEND_FUNC, LIST_POLYGON_MODE, LIST_LINE_WIDTH, LIST_POINT_SIZE,
    LIST_ALPHA_FUNC, LIST_POLYGON_OFFSET,
    LIST_PUSH_ATTRIB, LIST_POP_ATTRIB, LIST_CLEAR, LIST_RASTER_POS,
    LIST_WINDOW_POS, LIST_BITMAP, LIST_BITMAP_DATA, LIST_VERTEX
};
int rt_list_compiling(const struct rt_context *ctx);
int rt_list_matrix(struct rt_context *ctx, const char *caller, enum scene_list_op_kind kind,
                   RTenum mode, const double m[16]);
void rt_list_state(struct rt_context *ctx, enum list_state_call what, RTenum b, RTenum c,
                   const float *v, int n);
/* After a call changed state that is per primitive and carried by the
 * instance (clip planes, scene/clip.h; fog, light model and texture
 * generation, scene/gl_state.h; blend, alpha test and polygon offset,
 * scene/raster_state.h) while a list is compiled: the list's later
 * geometry starts a segment of its own, so that its instance carries the
 * state current there at the call. */
void rt_list_state_changed(struct rt_context *ctx, const char *caller);
/* Applies a matrix operation to the context's stacks as the entry point
 * would (errors named after caller) (matrix.c). */
void rt_matrix_apply(struct rt_context *ctx, const char *caller, enum scene_list_op_kind kind,
                     RTenum mode, const double m[16]);
/* rtCallList's work: replays list `name` (ignored when undefined or
 * nested too deep, as GL) (list.c). */
void rt_call_list(struct rt_context *ctx, const char *caller, RTuint name);
/* Marks the frame described (frame.c's implicit render). */
void rt_frame_described(struct rt_context *ctx);
/* Renders a frame described since rtClear and not rendered yet. */
void rt_render_if_described(struct rt_context *ctx);

/* The layout of a width x height image of `components` components of
 * `size` bytes in client memory under pixel store `ps` (GL 1.5 sec.
 * 3.6.4, "Unpacking"): the offset of its first pixel and the bytes from
 * one row to the next.  For bitmaps (size 0) one bit a pixel, the offset
 * excluding skip_pixels' bits (pixel_store.c). */
void rt_pixel_layout(const struct pixel_store *ps, int width, int components, int size,
                     size_t *first, size_t *row_stride);
/* Raster calls compiled into display lists (raster.c): rt_raster_record
 * records rtRasterPos (window 0) or rtWindowPos (window 1) when a list is
 * being compiled and returns 1 when the call must not take effect now;
 * rt_bitmap_replay draws the bitmap recorded at ops[0] (LIST_BITMAP, its
 * MSB-first rows in the LIST_BITMAP_DATA operations after it) and
 * returns the number of operations it took. */
int rt_raster_record(struct rt_context *ctx, const char *caller, int window, const double p[4]);
uint32_t rt_bitmap_replay(struct rt_context *ctx, const struct scene_list_op *ops,
                          uint32_t count);
/* rtClear compiled into a display list (frame.c): 1 when the call must
 * not take effect now (RT_COMPILE). */
int rt_clear_record(struct rt_context *ctx, RTbitfield mask);

/* rtEndList's clean-up of the attribute stack for an RT_COMPILE list
 * (attrib.c). */
void rt_attrib_list_end(struct rt_context *ctx);

/* 1 when s is RT_AUTOMATIC or an update strategy (object.c). */
int rt_strategy_is_valid(RTenum s);

/* The top of the current matrix stack. */
double *rt_current_matrix(struct rt_context *ctx);

/* Prepares the scene for a frame or query (scene_prepare_toplevel and
 * scene_prepare_objects, starting the pool between them) and adds the
 * scene's statistics to ctx->stats (frame.c).  Returns 0, or -1 after
 * recording RT_OUT_OF_MEMORY. */
int rt_prepare_scene(struct rt_context *ctx, const char *caller);

/* Describes the committed scene and the render state for the renderer,
 * starting the worker pool if needed (frame.c). */
void rt_render_job(struct rt_context *ctx, struct render_job *job);

/* Starts the worker pool if needed; NULL if threads == 1 or on failure. */
struct rt_pool *rt_context_pool(struct rt_context *ctx);

#endif
