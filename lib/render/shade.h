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
    const struct scene_textures *textures; /* read only */
};

/*
 * Colour seen along a world-space ray (dir need not be normalised) with
 * tmin <= t < tmax; depth counts the recursion of Whitted shading.
 * Writes RGBA to rgba; alpha is 1 on a hit and the clear alpha on a miss.
 */
void shade_ray(const struct shade_context *sc, const float org[3], const float dir[3],
               float tmax, int depth, float rgba[4]);

/*
 * Moves a point off a surface along the unit normal n by
 * OFFSET_ERROR_SCALE times `error`, the bound on the point's distance from
 * the exact surface, rounding each coordinate away from the surface so a
 * ray leaving it cannot hit the surface it starts on (the bound-based
 * offset of PBRT 3rd ed. sec. 3.9.5).  Scale-invariant: the bound is
 * relative to the coordinates' magnitude, so it works 1e5 from the origin
 * and for scenes 1e-4 across alike.
 */
void shade_offset_point(const float p[3], const float n[3], float error, float out[3]);

#endif
