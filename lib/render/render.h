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

#include "accel/bvh.h"
#include "base/pool.h"
#include "scene/frame.h"
#include "scene/texture.h"
#include "scene/update.h"
#include "trace/scene_traverse.h"

#define RENDER_MAX_LIGHTS 8

enum render_shading { RENDER_EYE_LIGHT, RENDER_WHITTED };

struct render_light {
    int enabled;
    float ambient[4];
    float diffuse[4];
    float specular[4];
    float position[4]; /* world (eye) space; w = 0: direction towards the light */
    float attenuation[3]; /* constant, linear, quadratic */
};

struct render_state {
    enum render_shading shading;
    int max_depth;
    float clear_color[4];
    float global_ambient[4];
    struct render_light lights[RENDER_MAX_LIGHTS];
    int viewport[4]; /* x, y, width, height */
    double projection[16];
    /* Framebuffer: width x height RGBA floats, row 0 at the bottom. */
    int fb_width, fb_height;
    float *framebuffer;
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
};

/*
 * Renders state->viewport into a new framebuffer of fb_width x fb_height.
 * On success returns 0 and hands the buffer to *out (caller frees with
 * rt_free); -1 on allocation failure (nothing changed).  stats are
 * accumulated.
 */
int render_frame(const struct render_job *job, int fb_width, int fb_height, float **out,
                 struct render_stats *stats);

/* Closest hits for count rays (world space), as rtTraceRays reports them.
 * Returns 0, or -1 when an object could not be built (out of memory). */
int render_trace_rays(const struct render_job *job, int count, const RTray *rays, RThit *hits,
                      struct render_stats *stats);
int render_occluded_rays(const struct render_job *job, int count, const RTray *rays,
                         RTboolean *occluded, struct render_stats *stats);

#endif
