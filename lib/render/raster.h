/* SPDX-License-Identifier: Apache-2.0 */
/*
 * raster.h - lines and points rasterised over the ray-traced image, with
 * GL's rules for non-antialiased primitives (OpenGL 2.1 sec. 3.3 and
 * 3.4): width-1 segments by the diamond-exit rule, wide segments as
 * columns (x-major) or rows (y-major) of `width` fragments, points as a
 * square of `size` fragments centred on the projected point.
 *
 * Primitives are projected by their owner's object-to-eye matrix and the
 * projection, clipped (in homogeneous coordinates) by the view volume and
 * the enabled user clip planes, and depth-tested with GL's default
 * RT_LESS against a depth buffer that starts as the window depth of each
 * pixel's primary hit (1 where the primary ray hit nothing), plus the
 * tolerance raster_depth_prepare documents; fragments that pass write
 * their depth (unless rtDepthMask(RT_FALSE)), so lines also hide each
 * other as GL's do.  Colours are the vertices' (GL with lighting
 * disabled); blending applies as to any GL fragment.
 */
#ifndef RT_RENDER_RASTER_H
#define RT_RENDER_RASTER_H

#include <math.h>
#include <stddef.h>

#include "render/visibility.h"
#include "scene/raster_state.h"
#include "scene/lines.h"

/* Depth tolerance of lines against surfaces: one step of a 24-bit depth
 * buffer. */
#define RASTER_DEPTH_EPSILON (1.0 / 16777216.0)

struct raster_target {
    float *rgba;   /* width x height RGBA, row 0 at the bottom */
    double *depth; /* width x height window depths, the test (LESS) and write buffer */
    int width, height;
    const int *viewport;      /* x, y, width, height */
    const double *projection; /* column-major */
    const struct render_visibility *vis;
    const struct scene_clip *clip; /* the planes of the instance being drawn */
    /* Its blend state, and the width and size its lines and points
     * without their own take (scene/raster_state.h). */
    const struct scene_raster *raster;
    /* 1: GL's RT_LESS test against `depth` and writes under rtDepthMask;
     * 0: RT_DEPTH_TEST disabled, no test and no write (GL). */
    int depth_test;
    /* The context's textures, for textured triangles (NULL: untextured). */
    const struct scene_textures *textures;
};

/* The window depth (GL's depth range [0, 1]) of the eye-space point
 * org + t dir under the projection; 1 when t is not finite. */
double raster_window_depth(const double projection[16], const float org[3], const float dir[3],
                           float t);

/*
 * Turns the primary hits' window depths (1 where none) into the buffer
 * lines are tested against, in place: a pixel showing a surface gets its
 * depth plus RASTER_DEPTH_EPSILON, one step of a 24-bit depth buffer, so
 * a fragment within the buffer's resolution of the surface is in front.
 * No slope term: a line lying on a surface (a wireframe over its own
 * filled polygons) samples its depth up to half a pixel away from where
 * the surface is sampled and shows where it comes out nearer, the
 * stitched look GL's RT_LESS gives it (docs/lines.md: 99.67% of the
 * pixels as OSMesa's).
 */
void raster_depth_prepare(double *depth, int width, int height);

/*
 * GL's polygon offset on the primary hits' window depths, in place, before
 * raster_depth_prepare: a pixel whose surface was drawn under
 * RT_POLYGON_OFFSET_FILL (state[i]->offset_fill) moves back by
 * m * factor + r * units (OpenGL 1.5 sec. 3.5.5), r being
 * RASTER_DEPTH_EPSILON and m the surface's depth slope max(|dz/dx|,
 * |dz/dy|), which GL computes from the polygon and we take from the
 * neighbouring pixels of the same instance (per axis, the smaller
 * one-sided difference, which is the surface's own at a silhouette).
 * Lines and points are tested against the result, so a wireframe drawn
 * over its offset fill shows whole, as in GL's hidden-line drawing.
 */
void raster_depth_offset(double *depth, const struct scene_raster *const *state, int width,
                         int height);

struct scene_instance;

/* Draws the instance's triangles whose face in window space is in
 * rtPolygonMode RT_LINE or RT_POINT (after RT_CULL_FACE): their boundary
 * edges or vertices (raster_polygons.c).  Filled faces are traced. */
void raster_polygons(const struct raster_target *target, const struct scene_instance *inst);
/* 1 when raster_polygons may draw something of the instance. */
int raster_polygons_present(const struct scene_instance *inst);

/* Rasterises the segments and points of `lines`, whose vertices are
 * mapped to eye space by object_to_eye. */
void raster_lines(const struct raster_target *target, const struct scene_lines *lines,
                  const double object_to_eye[16]);

struct scene_light;

/*
 * Draws an instance drawn under a projection or viewport other than the
 * frame's (scene_instance.overlay) as GL draws it, through target's
 * projection and viewport (the instance's): its filled triangles by
 * raster_triangles.c, its unfilled faces, lines and points as
 * raster_polygons and raster_lines draw them.  `lights`: the light set
 * it was drawn under.
 */
void raster_instance(const struct raster_target *target, const struct scene_instance *inst,
                     const struct scene_light *lights);

/* ---- shared by raster_lines.c and raster_points.c ---------------------- */

/* One fragment at window pixel (x, y): depth test, blend, write. */
void raster_fragment(const struct raster_target *target, long x, long y, double z,
                     const float color[4]);

/* Clip coordinates -> window x, y, z. */
void raster_to_window(const struct raster_target *target, const double clip[4], double win[3]);

/* Vertex v of lines in eye and clip coordinates. */
void raster_vertex(const struct raster_target *target, const struct scene_lines *lines,
                   uint32_t v, const double object_to_eye[16], double eye[3], double clip[4]);

void raster_points(const struct raster_target *target, const struct scene_lines *lines,
                   const double object_to_eye[16]);

/* One segment, its ends in eye (ea, eb) and clip (ca, cb) coordinates with
 * their colours (flat: col_a throughout), `width` whole pixels: clipped,
 * rasterised and depth-tested as the segments of raster_lines. */
void raster_segment(const struct raster_target *target, const double ea[3], const double eb[3],
                    const double ca[4], const double cb[4], const float col_a[4],
                    const float col_b[4], int flat, long width);

/* One point of `size` whole pixels at eye / clip position, as those of
 * raster_points. */
void raster_point(const struct raster_target *target, const double eye[3], const double clip[4],
                  const float color[4], long size);

/* Sub-pixel positions per pixel that window coordinates are snapped to
 * before points are placed: GL leaves the precision to the implementation
 * (OpenGL 2.1 sec. 3.3.1 computes in window coordinates of finite
 * precision); Mesa's rasterisers, which the OSMesa oracle runs, use 8
 * fractional bits. */
#define RASTER_SUBPIXEL_STEPS 256.0

/* x rounded to the nearest sub-pixel position. */
static inline double raster_snap(double x)
{
    return floor(x * RASTER_SUBPIXEL_STEPS + 0.5) / RASTER_SUBPIXEL_STEPS;
}

/* Width or size in whole pixels: rounded, at least 1, at most max. */
long raster_pixels(float value, float current, float max);

#endif
