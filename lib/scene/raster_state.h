/* SPDX-License-Identifier: Apache-2.0 */
/*
 * raster_state.h - the raster-side GL state a primitive was drawn under:
 * RT_BLEND and rtBlendFunc, RT_ALPHA_TEST and rtAlphaFunc,
 * RT_POLYGON_OFFSET_FILL and rtPolygonOffset, the line width and point
 * size that its lines and points without their own take, RT_DEPTH_TEST,
 * and the viewport and projection it was drawn under.  GL applies
 * these per fragment with the values current when the primitive is drawn
 * (OpenGL 1.5 sec. 4.1.4 alpha test, 4.1.8 blending, 3.5.5 polygon
 * offset), so they travel with the instance of the geometry
 * (scene_appearance, frame.h) as the clip planes do (clip.h): a program
 * that draws opaque geometry, enables blending and draws transparent
 * geometry keeps the first part opaque.
 *
 * Enums are stored as GL's values in 16 bits (all are below 0x10000) to
 * keep the block small; equal states compare equal with memcmp (the
 * constructor zeroes the padding).
 */
#ifndef RT_SCENE_RASTER_STATE_H
#define RT_SCENE_RASTER_STATE_H

#include <stdint.h>

struct scene_raster {
    uint8_t blend;          /* RT_BLEND enabled */
    uint8_t alpha_test;     /* RT_ALPHA_TEST enabled */
    uint8_t offset_fill;    /* RT_POLYGON_OFFSET_FILL enabled */
    uint8_t depth_test;     /* RT_DEPTH_TEST enabled (rasterised instances only) */
    uint16_t blend_src, blend_dst; /* rtBlendFunc */
    uint16_t alpha_func;    /* rtAlphaFunc: RT_NEVER .. RT_ALWAYS */
    uint16_t reserved2;
    float alpha_ref;        /* clamped to [0, 1] */
    float offset_factor, offset_units; /* rtPolygonOffset */
    float line_width, point_size;      /* pixels, for primitives without their own */
    /* The viewport and projection matrix current when the primitive was
     * drawn.  An instance whose projection is not the one the frame is
     * traced through (a heads-up display under a pushed rtuOrtho2D) is
     * not traced but rasterised with these, as GL draws it
     * (render/raster_triangles.c, docs/overlay_geometry.md). */
    int32_t viewport[4];
    double projection[16]; /* column-major */
};

/* 1 when the state changes what a ray sees past the nearest hit (the
 * primary path of render/blend.c has to look at the hit's instance). */
static inline int scene_raster_see_through(const struct scene_raster *r)
{
    return r->blend || r->alpha_test;
}

/* GL's alpha test (OpenGL 1.5 sec. 4.1.4): 1 when a fragment of alpha a
 * passes, func being RT_NEVER (0x0200) .. RT_ALWAYS (0x0207) in GL's
 * order (NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS). */
static inline int scene_alpha_passes(unsigned func, float a, float ref)
{
    switch (func) {
    case 0x0200:
        return 0;
    case 0x0201:
        return a < ref;
    case 0x0202:
        return a == ref;
    case 0x0203:
        return a <= ref;
    case 0x0204:
        return a > ref;
    case 0x0205:
        return a != ref;
    case 0x0206:
        return a >= ref;
    default:
        return 1;
    }
}

#endif
