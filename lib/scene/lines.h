/* SPDX-License-Identifier: Apache-2.0 */
/*
 * lines.h - line segments and points: what RT_LINES, RT_LINE_STRIP,
 * RT_LINE_LOOP, RT_POINTS and polygons in rtPolygonMode RT_LINE / RT_POINT
 * give.  They are not ray traced: the renderer rasterises them over the
 * ray-traced image, as GL draws them (render/raster.h).
 *
 * The storage knows nothing of objects or frames: vertices are stored in
 * whatever space the owner keeps them (an object's definition keeps
 * object space, as its triangles), so an object and a frame's immediate
 * geometry fill it with the same calls.  A block (one rtBegin/rtEnd or one
 * draw call) is assembled incrementally like the triangles (assembly.h):
 * scene_lines_vertex stores a vertex and the primitives it completes,
 * scene_lines_end closes a line loop or a polygon's outline.
 *
 * Polygons drawn as lines give their boundary edges (OpenGL 2.1 sec.
 * 3.6.4): a quad, a quad-strip quad or a polygon its outline, never the
 * diagonals the triangulation adds; triangles of a strip or fan their
 * three edges each.  Drawn as points they give the vertices of every
 * complete polygon.  Vertices of an incomplete primitive give nothing.
 */
#ifndef RT_SCENE_LINES_H
#define RT_SCENE_LINES_H

#include <stdint.h>

#define SCENE_LINE_FLAT 1u /* coloured by its provoking vertex (RT_FLAT) */

struct scene_line_segment {
    uint32_t v[2];
    uint32_t provoking; /* GL's provoking vertex, for flat shading */
    float width;        /* pixels; 0: the width current when rendered */
    uint32_t flags;     /* SCENE_LINE_* */
};

struct scene_line_point {
    uint32_t v;
    float size; /* pixels; 0: the size current when rendered */
};

struct scene_lines {
    uint32_t vertex_count, vertex_capacity;
    float *positions; /* 3 per vertex, in the owner's space */
    float *colors;    /* 4 per vertex, RGBA in [0, 1] */
    uint32_t segment_count, segment_capacity;
    struct scene_line_segment *segments;
    uint32_t point_count, point_capacity;
    struct scene_line_point *points;
    /* The width and size set while these lines were recorded (rtLineWidth
     * inside an object, as a display list records glLineWidth); 0 until
     * set: the primitives then take the current value when rendered. */
    float width, size;
};

/* One block of vertices feeding lines or points. */
struct scene_line_block {
    unsigned mode;         /* RT_POINTS .. RT_POLYGON */
    unsigned polygon_mode; /* polygons: RT_LINE or RT_POINT; ignored for line modes */
    uint32_t base;         /* index of the block's first vertex */
    uint32_t count;        /* vertices stored in this block */
    float width, size;     /* for the block's primitives; 0: inherit */
    uint32_t flags;        /* SCENE_LINE_FLAT */
};

/* 1 when mode is RT_POINTS, RT_LINES, RT_LINE_LOOP or RT_LINE_STRIP. */
int scene_lines_mode_is_valid(unsigned mode);

/* Frees the arrays and zeroes *lines; safe on a zeroed one. */
void scene_lines_release(struct scene_lines *lines);

/* 1 when there is anything to draw. */
int scene_lines_nonempty(const struct scene_lines *lines);

/* Starts a block of `mode` (a line mode, or a polygon mode drawn with
 * polygon_mode RT_LINE / RT_POINT). */
void scene_line_block_start(struct scene_line_block *block, const struct scene_lines *lines,
                            unsigned mode, unsigned polygon_mode, float width, float size,
                            uint32_t flags);

/* Stores the next vertex of the block (position already in the lines'
 * space) and the segments or points it completes.  Returns 0, or -1 on
 * allocation failure having stored nothing. */
int scene_lines_vertex(struct scene_lines *lines, struct scene_line_block *block,
                       const float position[3], const float color[4]);

/* Ends the block: the closing segment of a line loop or of a polygon's
 * outline.  Returns 0, or -1 on allocation failure (nothing stored). */
int scene_lines_end(struct scene_lines *lines, struct scene_line_block *block);

#endif
