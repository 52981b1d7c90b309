/*
 * shade.h - surface shading: eye light and Whitted-style ray tracing.
 */
#ifndef RT_RENDER_SHADE_H
#define RT_RENDER_SHADE_H

#include "render/render.h"

/* Per-thread context for shading one ray tree. */
struct shade_context {
    const struct render_state *state;
    const struct scene_frame *frame;
    const struct trace_scene *scene;
    struct trace_scene_counters *counters;
};

/*
 * Colour seen along a world-space ray (dir need not be normalised) with
 * tmin <= t < tmax; depth counts the recursion of Whitted shading.
 * Writes RGBA to rgba; alpha is 1 on a hit and the clear alpha on a miss.
 */
void shade_ray(const struct shade_context *sc, const float org[3], const float dir[3],
               float tmax, int depth, float rgba[4]);

/*
 * Moves a point off a surface along n so that a ray leaving it does not hit
 * the surface it started on, at any distance from the origin: offsets are
 * integer ULPs away from the origin and absolute close to it (Wächter and
 * Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray
 * Tracing Gems ch. 6).
 */
void shade_offset_point(const float p[3], const float n[3], float out[3]);

#endif
