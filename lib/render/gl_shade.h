/* SPDX-License-Identifier: Apache-2.0 */
/*
 * gl_shade.h - the RT_FIXED_FUNCTION shading mode: what OpenGL 1.x's
 * fixed-function pipeline draws at a camera ray's hit (lighting at the
 * vertices, texture environment, fog), and GL's face culling of camera
 * rays.  docs/appearance.md describes the mode.
 */
#ifndef RT_RENDER_GL_SHADE_H
#define RT_RENDER_GL_SHADE_H

#include "render/shade.h"

/*
 * The closest hit of a camera ray along dir (0 <= t < tmax) that GL would
 * draw: triangles whose face RT_CULL_FACE removed when they were drawn,
 * or whose face is drawn as lines or points, are passed through, as GL
 * rasterises no inside of them; another triangle at exactly the passed
 * one's t (a coplanar filled surface) is tried before the ray moves on.
 * Only camera rays cull; shadow, reflected and refracted rays and
 * rtTraceRays see every filled face (render/filled.h).  The search covers
 * [tmin, tmax); returns 0 on a miss.
 */
int gl_closest_drawn(const struct shade_context *sc, const float org[3], const float dir[3],
                     float tmin, float tmax, struct trace_scene_hit *hit);

/*
 * The first triangle after `hit` at exactly its t, in (instance, prim)
 * order, that GL draws (gl_hit_drawn) and that `reject`, when not NULL,
 * does not turn down: 1 with it in *hit, else 0 (*hit unchanged).  The
 * ties are fetched GL_SHADE_TIES at a time (trace_scene_ties gives
 * exactly the t the closest-hit walk computes); at most `max_walks`
 * fetches, or no limit when max_walks < 0.  Both callers take it:
 * gl_closest_drawn for a hit GL does not draw (limited as its own search
 * is) and blend.c for a clipped one (unlimited, as its search is).
 */
int gl_drawn_tie(const struct shade_context *sc, const float org[3], const float dir[3],
                 int max_walks,
                 int (*reject)(const struct shade_context *sc, const float org[3],
                               const float dir[3], const struct trace_scene_hit *tie),
                 struct trace_scene_hit *hit);

/* 1 when every triangle of the frame's committed instances is drawn
 * whatever side a ray sees (no RT_CULL_FACE, no face drawn as lines or
 * points): gl_hit_drawn is then 1 for every hit of the frame, and a
 * frame checks this once instead of per pixel.  Reads every instance's
 * materials; 0 when some triangle may not be drawn. */
int gl_frame_all_drawn(const struct scene_frame *frame);

/* 1 when GL draws the camera ray's hit `hit` (travelling along dir):
 * RT_CULL_FACE, as its triangle was drawn, does not remove its face. */
int gl_hit_drawn(const struct shade_context *sc, const float dir[3],
                 const struct trace_scene_hit *hit);

/* The colour GL's fixed-function pipeline gives the hit `hit` of the ray
 * org + t dir whose cone is `width` wide there (shade.h), RGBA. */
void gl_shade_hit(const struct shade_context *sc, const struct trace_scene_hit *hit,
                  const float org[3], const float dir[3], float width, float rgba[4]);

/* The colours GL's pipeline gives the three vertices of triangle `prim`
 * of `inst` before rasterisation (render/raster_triangles.c): lit per
 * vertex with `lights` when lighting is on, with the back material and
 * the reversed normal when `front` is 0 under RT_LIGHT_MODEL_TWO_SIDE,
 * else the vertex colours; under RT_FLAT all three the provoking
 * vertex's (OpenGL 2.1 sec. 2.14.7).  Clamped to [0, 1]. */
void gl_triangle_colors(const struct scene_instance *inst, uint32_t prim,
                        const struct scene_light *lights, int front, float rgba[3][4]);

/* The texture GL applies to triangle `prim` of `inst` (render/
 * raster_triangles.c): its name, 0 when none is enabled and bound; then
 * the texture coordinates of its vertices, recorded or generated
 * (rtTexGen), their q (1 unless rtTexCoord4 or RT_Q's generation gave
 * one), and the texture environment. */
uint32_t gl_triangle_texture(const struct scene_instance *inst, uint32_t prim, float st[3][2],
                             float q[3], uint32_t *env_mode, float env_color[4]);

/* GL's texture environment `mode` (OpenGL 1.1 sec. 3.8.6, table 3.19:
 * RT_MODULATE, RT_REPLACE, RT_DECAL, RT_BLEND with env_color) applied by
 * the texel tex to the fragment colour c. */
void gl_texture_env_apply(uint32_t mode, const float env_color[4], const float tex[4], float c[4]);

#endif
