/* SPDX-License-Identifier: Apache-2.0 */
/*
 * blend.h - the primary-ray path: user clip planes and blending
 * (non-refractive see-through surfaces, GL's RT_BLEND).
 *
 * A primary ray takes the nearest hit that no enabled clip plane removes;
 * with RT_BLEND enabled it continues past a surface whose blend needs
 * what lies behind it (a source alpha below 1 under
 * RT_SRC_ALPHA / RT_ONE_MINUS_SRC_ALPHA), and the layers it found are
 * composited from the back (the clear colour) to the front with
 * rtBlendFunc's factors, as GL composites a program that draws back to
 * front.  docs/blending.md says where that agrees with GL's draw order.
 */
#ifndef RT_RENDER_BLEND_H
#define RT_RENDER_BLEND_H

#include "render/shade.h"

/* Layers and coincident fragments a primary ray keeps without
 * allocating; a pixel with more takes heap arrays, grown as needed (no
 * fixed cap: bounded by memory, the first drawn kept when it runs out). */
#define BLEND_MAX_LAYERS 32

/* out = src * F_src + dst * F_dst per channel with GL's factors (OpenGL
 * 1.1 sec. 4.1.6, table 4.1 and 4.2), src and dst clamped to [0, 1]
 * first and the result clamped, as in a fixed-point framebuffer. */
void blend_combine(unsigned src_factor, unsigned dst_factor, const float src[4],
                   const float dst[4], float out[4]);

/* 1 when blend_combine's result for this source depends on dst. */
int blend_needs_destination(unsigned src_factor, unsigned dst_factor, const float src[4]);

/* 1 when a clip plane the camera ray's hit `hit` was drawn under removes
 * it (the point org + t dir as the primary path computes it): such a hit
 * is not the one blend_trace_primary shades. */
int blend_hit_clipped(const struct shade_context *sc, const float org[3], const float dir[3],
                      const struct trace_scene_hit *hit);

/*
 * The colour of primary ray (org, dir, tmax) with the pass's clip planes
 * and blend state; *t_first is the distance of the nearest kept hit
 * (+infinity when none), the surface that decides depth for rasterised
 * lines.  Without blending and clip planes this is exactly shade_ray.
 */
void blend_trace_primary(const struct shade_context *sc, const float org[3], const float dir[3],
                         float tmax, struct shade_cone cone, float rgba[4], float *t_first);

/* The same, also giving the raster state (scene/raster_state.h) of the
 * nearest kept hit's instance in *first_state (NULL when none): its
 * polygon offset applies to the depth lines are tested against. */
void blend_trace_primary_state(const struct shade_context *sc, const float org[3],
                               const float dir[3], float tmax, struct shade_cone cone,
                               float rgba[4], float *t_first,
                               const struct scene_raster **first_state);

#endif
