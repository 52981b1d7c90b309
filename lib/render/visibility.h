/* SPDX-License-Identifier: Apache-2.0 */
/*
 * visibility.h - the GL state that decides what a pixel shows besides the
 * nearest hit: blending (see-through surfaces, render/blend.c), user clip
 * planes (primary rays and rasterised primitives), and the line width and
 * point size that lines and points without their own take
 * (render/raster.h).  Part of struct render_state, read by the renderer.
 */
#ifndef RT_RENDER_VISIBILITY_H
#define RT_RENDER_VISIBILITY_H

#define RENDER_MAX_CLIP_PLANES 6
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
};

/* 1 when a clip plane is enabled. */
static inline int visibility_any_clip(const struct render_visibility *vis)
{
    for (int i = 0; i < RENDER_MAX_CLIP_PLANES; i++)
        if (vis->clip_enabled[i])
            return 1;
    return 0;
}

/* 1 when the eye-space point p is removed by an enabled clip plane. */
static inline int visibility_clipped(const struct render_visibility *vis, const double p[3])
{
    for (int i = 0; i < RENDER_MAX_CLIP_PLANES; i++) {
        const double *e = vis->clip_plane[i];
        if (vis->clip_enabled[i] && e[0] * p[0] + e[1] * p[1] + e[2] * p[2] + e[3] < 0.0)
            return 1;
    }
    return 0;
}

#endif
