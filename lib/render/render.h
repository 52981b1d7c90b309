/* SPDX-License-Identifier: Apache-2.0 */
/*
 * render.h - frames and ray queries over a prepared scene.
 *
 * The renderer reads the committed frame (instances, top level), the
 * objects' meshes for shading and builds object BVHs on demand through
 * scene_object_acquire.  It never records errors: it returns a status the
 * API thread turns into RT_OUT_OF_MEMORY (STYLE.md sec. 3, "threads").
 *
 * Determinism: every pixel and every query ray is computed independently
 * by the same sequence of float operations, so images are bit-identical
 * for any thread count and tile order.
 */
#ifndef RT_RENDER_RENDER_H
#define RT_RENDER_RENDER_H

#include <rt/rt.h>
#include <stdint.h>

#include "trace/bvh_layout.h"
#include "base/pool.h"
#include "base/quotient_known.h"
#include "render/visibility.h"
#include "scene/frame.h"
#include "scene/texture.h"
#include "scene/update.h"
#include "trace/scene_traverse.h"

#define RENDER_MAX_LIGHTS SCENE_MAX_LIGHTS /* scene/gl_state.h */
/* 32x32 pixel tiles: small enough to balance two to eight threads on
 * 640x480 (300 tiles), large enough that the atomic counter is noise.
 * Why not 16x16 (1200 tiles there): the eye-light frame walks a whole
 * tile's blocks before it shades them (render.c,
 * render_tile_eye_traced_first), so the walk's and the shading's code and
 * data come back into the first-level caches once a tile; 128 blocks a
 * tile pay that a quarter as often as 32, and the unprojection's shared
 * rows and columns are 10 % of a tile's points instead of 20 % (round 65,
 * zu1: a second shading pass over a tile costs about 5 ms a frame less
 * than its first; the kitchen eye-light frame on a Zen 4 runs about
 * 1-1.5 ms faster under the AVX-512 table, 0.6-2.4 ms under AVX2, of
 * about 67 ms, roughly half of it the batch).  Round 48 measured 32x32
 * before the traced-first tile, on another core: level.  The price: the
 * traced-first tile's 85 KB of stack (21 KB at 16x16). */
#define RENDER_TILE_SIZE 32

enum render_shading { RENDER_EYE_LIGHT, RENDER_WHITTED, RENDER_FIXED_FUNCTION };

/*
 * The framebuffer, which outlives frames: the last finished image, which
 * the next frame can read (accumulation) while it renders a new one; a
 * frame that fails leaves it as it was.
 */
struct render_framebuffer {
    int width, height;
    float *rgba;     /* width x height RGBA floats, row 0 at the bottom */
    uint64_t frames; /* frames finished at this size (accumulation restarts at 1) */
    /* The image before rgba, kept for the next frame of the same size to
     * render into, as GL's back buffer is drawn while the front one is
     * shown: a frame then allocates nothing and takes no page faults
     * (12.6 MB, 3,072 pages, at 1024 x 768: their faults were 3-4 % of
     * a kitchen eye-light frame's samples); NULL when there is none. */
    float *spare;
    size_t spare_pixels;
};

/* Frees the image and the spare one and zeroes *fb. */
void render_framebuffer_release(struct render_framebuffer *fb);

struct render_state {
    enum render_shading shading;
    int max_depth;
    float clear_color[4];
    float global_ambient[4];
    /* The lights as current now (struct scene_light, scene/gl_state.h):
     * what eye-light and Whitted frames light with and what the next
     * primitive is drawn with; RT_FIXED_FUNCTION lights each primitive
     * by its own set (scene_appearance.gl.light_set). */
    struct scene_light lights[RENDER_MAX_LIGHTS];
    int viewport[4]; /* x, y, width, height */
    double projection[16];
    struct render_framebuffer fb;
    /* Blending, clip planes, line width and point size (visibility.h). */
    struct render_visibility vis;
    /* rtLightModel and rtFog as current now (RT_FIXED_FUNCTION mode):
     * what the next primitive is drawn with.  Each instance keeps the
     * values current at its draw (scene_appearance.gl, scene/gl_state.h),
     * which the mode reads; these are the context's. */
    int light_model_two_side;
    int light_model_local_viewer;
    struct scene_fog fog;
    /* rtEnable(RT_LIGHTING) was called in this context: from then on the
     * eye-light and Whitted modes honour each primitive's RT_LIGHTING as
     * GL does (unlit: its colour); before, they light every surface, the
     * ray tracer's look (docs/appearance.md). */
    int lighting_used;
};

struct render_stats {
    uint64_t rays;
    uint64_t node_tests;
    uint64_t triangle_tests;
    uint64_t instance_tests;
    uint64_t object_builds;
    uint64_t toplevel_builds;
    uint64_t object_updates;
    double update_ms;
    double build_ms;
    double toplevel_ms;
    double render_ms;
};

/* What a frame or query needs; built by the API layer. */
struct render_overlay;

struct render_job {
    const struct render_state *state;
    const struct scene_frame *frame; /* prepared: top level valid */
    const struct scene_update_config *update; /* builds and updates on demand */
    /* Textures, looked up by the name a triangle's material keeps.  Read
     * only: textures change on the API thread, never during a job. */
    const struct scene_textures *textures;
    struct rt_pool *pool;
    int threads;
    const struct trace_kernels *kernels; /* the context's ISA table; NULL: scalar */
    /* stream=on (docs/context.md): a query's incoherent rays go through
     * the stream walk on every qualifying scene, not only where the
     * layouts say it pays (trace_scene.stream_always). */
    int stream_always;
    /* The frame's bitmaps (render/overlay.h), drawn after the trace in
     * draw order among the rasterised instances; NULL: none. */
    const struct render_overlay *overlay;
};

/* Per-worker counters on their own cache lines. */
struct render_worker_counters {
    struct trace_scene_counters c;
    char pad[64];
};

/*
 * One frame (or query batch) in flight: the state its tiles share.  A
 * frame is render_pass_begin, render_tile for every tile on any threads
 * (each tile once, any order: pixels do not depend on it), then
 * render_pass_end.  render_frame does all three on the job's pool; a
 * distributed renderer runs render_tile for the tiles it is given.
 */
struct render_pass {
    const struct render_job *job;
    struct trace_scene scene;
    struct render_worker_counters *counters; /* one per thread of job->pool */
    /* Worker w's eye-light cache (shade_context.eye) at
     * w * SHADE_EYE_CACHES, in the counters' allocation: it lives for the
     * pass, over all the tiles the worker renders, as the instances and
     * meshes it remembers do not change while a pass renders. */
    struct surface_cache *eye_caches;
    uint64_t builds;     /* atomic */
    uint64_t build_us;   /* atomic */
    int failed;          /* atomic: an object could not be built */
    uint32_t next_item;  /* atomic work counter */
    /* The pass may walk an object's binary tree (a table without a wide
     * walk, the ties walk, the hit filter's walk): acquire_object then
     * has the leaf-ordered triangles gathered (scene_object_triangles). */
    int reads_binary;
    /* Frames. */
    int projectable;     /* the projection could be inverted */
    int clipping;        /* some instance has clip planes (frame_has_clip) */
    int see_through;     /* some instance blends or alpha-tests (frame_has_see_through) */
    int all_drawn;       /* every hit is drawn, gl_hit_drawn needs no call (gl_frame_all_drawn) */
    double inv_projection[16];
    /* 1 when every unprojected point's w is the same two numbers for the
     * whole frame, near and far, and the quotients by them are exact
     * (render.c, unproject_w_known): the row fill's SIMD copies then
     * multiply instead of dividing. */
    int w_known;
    struct quotient_known wn, wf;
    float *fb;           /* the image being rendered, fb_width x fb_height */
    int fb_width, fb_height;
    int tiles_x, tiles_y;
    /* Window depth of each pixel's primary hit (1 for none), kept only
     * when the frame has lines or points to rasterise (raster.h); else
     * NULL. */
    double *depth;
    /* With depth, when some instance has RT_POLYGON_OFFSET_FILL: the
     * raster state of each pixel's primary hit (NULL for none), whose
     * offset raster_depth_offset applies; else NULL. */
    const struct scene_raster **depth_state;
    /* NULL, or the instances whose hits secondary rays (frames) or
     * queries check (render/secondary.h). */
    uint8_t *secondary;
    /* Queries. */
    int count;
    const RTray *rays;
    RThit *hits;
    RTboolean *occluded;
};

/* Starts a frame of fb_width x fb_height pixels rendering the job's
 * viewport: allocates the new image (clear colour) and the counters.
 * Returns 0, or -1 on allocation failure (nothing to end). */
int render_pass_begin(struct render_pass *pass, const struct render_job *job, int fb_width,
                      int fb_height);
/* Tiles of the pass (RENDER_TILE_SIZE square, row-major over the viewport). */
uint32_t render_pass_tiles(const struct render_pass *pass);
/* Renders tile `tile` into the pass's image on behalf of worker `worker`
 * (0 .. threads - 1, the index of its counters). */
void render_tile(struct render_pass *pass, uint32_t tile, int worker);
/* render_tile's packet loop compiled for AVX2 (render_avx2.c: the same
 * source, so the same pixels bit for bit, with a row's unprojection and
 * a block row's camera rays four at a time), which render_tile calls
 * when the scene's traversal table is AVX2 or AVX-512; NULL where that
 * unit is absent (no AVX2 compiler target, RT_NO_SIMD). */
struct shade_context;
typedef void (*render_tile_packets_fn)(struct render_pass *pass, struct shade_context *sc,
                                       int x0, int y0);
render_tile_packets_fn render_tile_packets_avx2_unit(void);
/* The same loop compiled for AVX-512 (render_avx512.c: the same
 * source, calling the AVX-512 copy of the eye light's shading), which
 * render_tile calls when the scene's traversal table is AVX-512; NULL
 * where that unit is absent. */
render_tile_packets_fn render_tile_packets_avx512_unit(void);
/* Test hook (conformance/internal/quotient_known.c): the unprojected
 * pixel centres of the rows y, y + 1 and y + 2 from column x0, as the
 * tile loops cache them (render.c, unproject_row_fill), under the given
 * projection and viewport: RENDER_UNPROJECT_COLS points a row, row by
 * row, with state 1 where a point is unprojected and -1 where it cannot
 * be.  Returns -1 for a singular projection, else 1 when the row fill's
 * w are frame constants with exact quotients (render_pass.w_known), 0
 * when it divides.  render_unproject_rows is this file's copy, the
 * _avx2 and _avx512 ones the units' (NULL where absent). */
#define RENDER_UNPROJECT_ROWS 3
#define RENDER_UNPROJECT_COLS (RENDER_TILE_SIZE + 2)
typedef int (*render_unproject_rows_fn)(const double projection[16], const int viewport[4],
                                        int x0, int y, double near_pt[][3], double far_pt[][3],
                                        signed char *state);
int render_unproject_rows(const double projection[16], const int viewport[4], int x0, int y,
                          double near_pt[][3], double far_pt[][3], signed char *state);
render_unproject_rows_fn render_unproject_rows_avx2_unit(void);
render_unproject_rows_fn render_unproject_rows_avx512_unit(void);
/* After every tile: rasterises the lines and points of the committed
 * instances over the image (raster.h), on the calling thread. */
void render_pass_raster(struct render_pass *pass);
/* Adds the pass's work to stats and, if every object could be built,
 * hands the new image to fb (freeing the old); returns 0, or -1 (fb
 * unchanged) when one could not. */
int render_pass_end(struct render_pass *pass, struct render_framebuffer *fb,
                    struct render_stats *stats);

/*
 * Renders state->viewport into fb, resized to fb_width x fb_height, on
 * the job's pool.  Returns 0, or -1 on allocation failure (fb unchanged).
 * stats are accumulated.
 */
int render_frame(const struct render_job *job, int fb_width, int fb_height,
                 struct render_framebuffer *fb, struct render_stats *stats);

/* Closest hits for count rays (world space), as rtTraceRays reports them.
 * Returns 0, or -1 when an object could not be built (out of memory). */
int render_trace_rays(const struct render_job *job, int count, const RTray *rays, RThit *hits,
                      struct render_stats *stats);
int render_occluded_rays(const struct render_job *job, int count, const RTray *rays,
                         RTboolean *occluded, struct render_stats *stats);

#endif
