/* SPDX-License-Identifier: Apache-2.0 */
/*
 * filled.h - what secondary rays and rtTraceRays / rtOccludedRays see of
 * polygons drawn as lines or points (rtPolygonMode, docs/lines.md).
 *
 * GL draws a face in RT_LINE or RT_POINT mode as its edges or vertices;
 * its inside is no surface.  Camera rays pass such faces (gl_shade.c) and
 * polygons with both faces so are stored as lines only, which no ray
 * meets; the triangles kept for a per-face mode are passed here too by
 * every other ray at the face it meets (render/secondary.h's hit filter,
 * SECONDARY_UNFILLED), so that a polygon drawn as lines casts no shadow,
 * reflects nothing and answers no query whichever way it was stored.
 * Culling is not applied: RT_CULL_FACE is for camera rays only
 * (docs/appearance.md), so a culled face that is filled is seen.
 */
#ifndef RT_RENDER_FILLED_H
#define RT_RENDER_FILLED_H

#include "scene/frame.h"
#include "trace/scene_traverse.h"

/* 1 when some instance of the frame has triangles that may show a face
 * not filled (raster_polygons_present): only then do the rays below need
 * the filtered walks. */
int filled_frame_has_unfilled(const struct scene_frame *frame);

/* 1 when the face of the hit's triangle that a ray along dir meets is
 * filled, with the modes the triangle records or takes from its call. */
int filled_face(const struct scene_frame *frame, const struct trace_scene *scene,
                const float dir[3], const struct trace_scene_hit *hit);

#endif
