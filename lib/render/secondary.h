/* SPDX-License-Identifier: Apache-2.0 */
/*
 * secondary.h - what shadow, reflection and refraction rays (Whitted
 * shading) and the ray queries see of the surfaces that GL's
 * per-primitive state takes out of the picture (docs/clip_planes.md,
 * docs/alpha_test.md, docs/blending.md):
 *
 * - a hit that a clip plane of its primitive removes is not there, for
 *   every ray, queries included (GL's selection and feedback report
 *   primitives after user clipping too);
 * - a hit whose alpha fails its primitive's alpha test is not there for
 *   shadow, reflection and refraction rays;
 * - a blended surface whose blend shows what lies behind it does not
 *   stop a shadow ray (light passes, as the eye sees through it);
 * - the face of a polygon that rtPolygonMode draws as lines or points
 *   is no surface, for every ray, queries included (render/filled.h).
 *
 * The trace layer walks the marked instances triangle by triangle and
 * asks here about each hit it would keep (trace_scene.accept,
 * trace/scene_filter.h); a frame without clip planes, alpha test and
 * blending marks none and pays nothing.
 */
#ifndef RT_RENDER_SECONDARY_H
#define RT_RENDER_SECONDARY_H

#include <stdint.h>

#include "render/shade.h"

/* Per instance (indexed by instance id): what its hits are checked for. */
#define SECONDARY_CLIP 1u  /* drawn under a user clip plane */
#define SECONDARY_ALPHA 2u /* drawn with RT_ALPHA_TEST */
#define SECONDARY_BLEND 4u /* drawn with RT_BLEND */
#define SECONDARY_UNFILLED 8u /* may show a face drawn as lines or points (render/filled.h) */

/* The marks of the frame's instances for the kinds in `kinds` (a mask of
 * the above): *out is NULL when no instance has one (nothing to filter),
 * else an array of frame->committed.count bytes for rt_free.  Returns 0,
 * or -1 on allocation failure. */
int secondary_marks(const struct scene_frame *frame, unsigned kinds, uint8_t **out);

/* The scenes of one shading context: shadow rays and reflected or
 * refracted rays, each `base` with its filter, or base itself when marks
 * is NULL.  sc->shadows and sc->rays are pointed at them (or at base);
 * the struct must outlive sc's use. */
struct secondary_scenes {
    struct trace_scene shadow;
    struct trace_scene ray;
};
void secondary_scenes_init(struct secondary_scenes *s, struct shade_context *sc,
                           const struct trace_scene *base, const uint8_t *marks);

/* The filter of the ray queries (clip planes and unfilled faces): user
 * is the render pass. */
int secondary_accept_query(void *user, const float org[3], const float dir[3],
                           const struct trace_scene_hit *hit);

#endif
