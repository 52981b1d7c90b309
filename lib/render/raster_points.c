/* SPDX-License-Identifier: Apache-2.0 */
/*
 * raster_points.c - points over the ray-traced image (raster.h): GL's
 * non-antialiased points (OpenGL 2.1 sec. 3.3.1), a square of size x size
 * fragments centred on the projected point.
 */
#include "render/raster.h"

#include <math.h>

void raster_points(const struct raster_target *target, const struct scene_lines *lines,
                   const double object_to_eye[16])
{
    for (uint32_t i = 0; i < lines->point_count; i++) {
        const struct scene_line_point *pt = &lines->points[i];
        double eye[3], clip[4];
        raster_vertex(target, lines, pt->v, object_to_eye, eye, clip);
        raster_point(target, eye, clip, &lines->colors[4 * pt->v],
                     raster_pixels(pt->size, target->raster->point_size, RENDER_MAX_POINT_SIZE));
    }
}

void raster_point(const struct raster_target *target, const double eye[3], const double clip[4],
                  const float color[4], long size)
{
    /* A point outside the view volume or a clip plane is discarded
     * whole (GL clips points by their vertex). */
    const double w = clip[3];
    if (!(w > 0.0) || !(fabs(clip[0]) <= w) || !(fabs(clip[1]) <= w) ||
        !(fabs(clip[2]) <= w) || scene_clip_removes(target->clip, eye))
        return;
    double win[3];
    raster_to_window(target, clip, win);
    /* GL's rule (OpenGL 2.1 sec. 3.3.1): odd sizes centre on the pixel
     * holding the point, even ones on the pixel corner nearest to it;
     * decided on the window position snapped to the sub-pixel grid
     * first, as GL implementations rasterise (RASTER_SUBPIXEL_STEPS): a
     * point projecting a rounding error left of a pixel edge is on
     * the edge, not in the pixel to its left. */
    const double xs = raster_snap(win[0]), ys = raster_snap(win[1]);
    long x0 = size % 2 ? (long)floor(xs) - (size - 1) / 2 : (long)floor(xs + 0.5) - size / 2;
    long y0 = size % 2 ? (long)floor(ys) - (size - 1) / 2 : (long)floor(ys + 0.5) - size / 2;
    for (long y = y0; y < y0 + size; y++)
        for (long x = x0; x < x0 + size; x++)
            raster_fragment(target, x, y, win[2], color);
}
