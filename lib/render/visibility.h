/* SPDX-License-Identifier: Apache-2.0 */
/*
 * visibility.h - the GL state that decides what a pixel shows besides the
 * nearest hit: blending (see-through surfaces, render/blend.c), user clip
 * planes (the current ones; primitives keep theirs, scene/clip.h), and the line width and
 * point size that lines and points without their own take
 * (render/raster.h).  Part of struct render_state, read by the renderer.
 */
#ifndef RT_RENDER_VISIBILITY_H
#define RT_RENDER_VISIBILITY_H

#include "scene/clip.h"

#define RENDER_MAX_CLIP_PLANES SCENE_MAX_CLIP_PLANES
/* Largest line width and point size (RT_ALIASED_*_RANGE); larger values
 * are clamped, as GL clamps to its implementation range. */
#define RENDER_MAX_LINE_WIDTH 64.0f
#define RENDER_MAX_POINT_SIZE 64.0f

struct render_visibility {
    float line_width; /* rtLineWidth, pixels */
    float point_size; /* rtPointSize, pixels */
    int blend;        /* RT_BLEND enabled */
    unsigned blend_src, blend_dst; /* rtBlendFunc factors (RT_ZERO ...) */
    int depth_mask;   /* rtDepthMask */
    int clip_enabled[RENDER_MAX_CLIP_PLANES]; /* RT_CLIP_PLANE0 + i enabled */
    /* Plane i in eye space (rtClipPlane transformed by the inverse of the
     * modelview at the call): p is kept where plane . (x, y, z, 1) >= 0. */
    double clip_plane[RENDER_MAX_CLIP_PLANES][4];
    /* Current values only, taken by the primitives drawn
     * (scene_appearance.raster, scene/raster_state.h). */
    int alpha_test;        /* RT_ALPHA_TEST enabled */
    unsigned alpha_func;   /* rtAlphaFunc, RT_ALWAYS initially */
    float alpha_ref;       /* clamped to [0, 1] */
    float offset_factor, offset_units; /* rtPolygonOffset */
};

/* The planes a primitive is clipped by travel with its instance
 * (scene_appearance.clip, scene/clip.h); clip_enabled / clip_plane above
 * are the context's current state, which geometry takes when drawn. */
#endif
