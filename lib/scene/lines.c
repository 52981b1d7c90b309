/* SPDX-License-Identifier: Apache-2.0 */
/*
 * lines.c - storage and assembly of line segments and points (lines.h).
 * Assembly follows OpenGL 2.1 sec. 2.6.1 (line strips, loops, separate
 * lines, points) and sec. 3.6.4 (polygons drawn as lines or points), with
 * the provoking vertices of table 2.12.
 */
#include "scene/lines.h"

#include <rt/rt.h>
#include <string.h>

#include "base/alloc.h"

int scene_lines_mode_is_valid(unsigned mode)
{
    return mode == RT_POINTS || mode == RT_LINES || mode == RT_LINE_LOOP ||
           mode == RT_LINE_STRIP;
}

void scene_lines_release(struct scene_lines *lines)
{
    rt_free(lines->positions);
    rt_free(lines->colors);
    rt_free(lines->segments);
    rt_free(lines->points);
    memset(lines, 0, sizeof(*lines));
}

int scene_lines_nonempty(const struct scene_lines *lines)
{
    return lines->segment_count > 0 || lines->point_count > 0;
}

static int grow(void **array, uint32_t *capacity, uint32_t needed, size_t element_size)
{
    if (needed <= *capacity)
        return 0;
    uint64_t c = *capacity ? *capacity : 64;
    while (c < needed)
        c *= 2;
    if (c > UINT32_MAX)
        c = UINT32_MAX;
    void *p = rt_realloc_array(*array, (size_t)c, element_size);
    if (!p)
        return -1;
    *array = p;
    *capacity = (uint32_t)c;
    return 0;
}

/* Room for one vertex and up to 4 segments and 4 points; the arrays are
 * grown independently, a partial failure only leaves one larger. */
static int reserve(struct scene_lines *l)
{
    if (l->vertex_count > UINT32_MAX - 1 || l->segment_count > UINT32_MAX - 4 ||
        l->point_count > UINT32_MAX - 4)
        return -1;
    uint32_t vcap = l->vertex_capacity;
    if (grow((void **)&l->positions, &vcap, l->vertex_count + 1, 3 * sizeof(float)))
        return -1;
    vcap = l->vertex_capacity;
    if (grow((void **)&l->colors, &vcap, l->vertex_count + 1, 4 * sizeof(float)))
        return -1;
    l->vertex_capacity = vcap;
    if (grow((void **)&l->segments, &l->segment_capacity, l->segment_count + 4,
             sizeof(*l->segments)) ||
        grow((void **)&l->points, &l->point_capacity, l->point_count + 4, sizeof(*l->points)))
        return -1;
    return 0;
}

void scene_line_block_start(struct scene_line_block *block, const struct scene_lines *lines,
                            unsigned mode, unsigned polygon_mode, float width, float size,
                            uint32_t flags)
{
    block->mode = mode;
    block->polygon_mode = polygon_mode;
    block->base = lines->vertex_count;
    block->count = 0;
    block->width = width;
    block->size = size;
    block->flags = flags;
}

static void segment(struct scene_lines *l, const struct scene_line_block *b, uint32_t a,
                    uint32_t c, uint32_t provoking)
{
    struct scene_line_segment *s = &l->segments[l->segment_count++];
    s->v[0] = b->base + a;
    s->v[1] = b->base + c;
    s->provoking = b->base + provoking;
    s->width = b->width;
    s->flags = b->flags;
}

static void point(struct scene_lines *l, const struct scene_line_block *b, uint32_t v)
{
    struct scene_line_point *p = &l->points[l->point_count++];
    p->v = b->base + v;
    p->size = b->size;
}

/* A polygon's boundary, n vertices in boundary order, drawn as lines or
 * points. */
static void outline(struct scene_lines *l, const struct scene_line_block *b, const uint32_t *v,
                    int n, uint32_t provoking)
{
    for (int i = 0; i < n; i++) {
        if (b->polygon_mode == RT_POINT)
            point(l, b, v[i]);
        else
            segment(l, b, v[i], v[(i + 1) % n], provoking);
    }
}

/* The primitives vertex k of the block completes. */
static void assemble(struct scene_lines *l, const struct scene_line_block *b, uint32_t k)
{
    const int as_points = b->polygon_mode == RT_POINT;
    switch (b->mode) {
    case RT_POINTS:
        point(l, b, k);
        return;
    case RT_LINES:
        if (k % 2 == 1)
            segment(l, b, k - 1, k, k);
        return;
    case RT_LINE_STRIP:
    case RT_LINE_LOOP:
        if (k >= 1)
            segment(l, b, k - 1, k, k);
        return;
    case RT_TRIANGLES:
        if (k % 3 == 2) {
            uint32_t v[3] = {k - 2, k - 1, k};
            outline(l, b, v, 3, k);
        }
        return;
    case RT_TRIANGLE_STRIP:
    case RT_TRIANGLE_FAN:
        if (k < 2)
            return;
        if (as_points) {
            /* Every vertex of a complete triangle, once. */
            for (uint32_t i = k == 2 ? 0 : k; i <= k; i++)
                point(l, b, i);
            return;
        }
        {
            uint32_t first = b->mode == RT_TRIANGLE_FAN ? 0 : k - 2;
            uint32_t v[3] = {first, k - 1, k};
            outline(l, b, v, 3, k);
        }
        return;
    case RT_QUADS:
        if (k % 4 == 3) {
            uint32_t v[4] = {k - 3, k - 2, k - 1, k};
            outline(l, b, v, 4, k);
        }
        return;
    case RT_QUAD_STRIP:
        if (k < 3 || k % 2 == 0)
            return;
        if (as_points) {
            for (uint32_t i = k == 3 ? 0 : k - 1; i <= k; i++)
                point(l, b, i);
            return;
        }
        {
            /* Quad (k-3, k-2, k, k-1) in boundary order: its outline, not
             * the diagonal its triangles share. */
            uint32_t v[4] = {k - 3, k - 2, k, k - 1};
            outline(l, b, v, 4, k);
        }
        return;
    case RT_POLYGON:
        /* The outline is drawn once the polygon has 3 vertices; the closing
         * edge at scene_lines_end. */
        if (k < 2)
            return;
        if (as_points) {
            for (uint32_t i = k == 2 ? 0 : k; i <= k; i++)
                point(l, b, i);
            return;
        }
        if (k == 2)
            segment(l, b, 0, 1, 0);
        segment(l, b, k - 1, k, 0);
        return;
    default:
        return;
    }
}

int scene_lines_vertex(struct scene_lines *lines, struct scene_line_block *block,
                       const float position[3], const float color[4])
{
    if (reserve(lines))
        return -1;
    uint32_t v = lines->vertex_count++;
    memcpy(&lines->positions[3 * v], position, 3 * sizeof(float));
    memcpy(&lines->colors[4 * v], color, 4 * sizeof(float));
    assemble(lines, block, block->count);
    block->count++;
    return 0;
}

int scene_lines_end(struct scene_lines *lines, struct scene_line_block *block)
{
    uint32_t n = block->count;
    int closes = (block->mode == RT_LINE_LOOP && n >= 2) ||
                 (block->mode == RT_POLYGON && block->polygon_mode == RT_LINE && n >= 3);
    if (!closes)
        return 0;
    if (grow((void **)&lines->segments, &lines->segment_capacity, lines->segment_count + 1,
             sizeof(*lines->segments)))
        return -1;
    /* The closing segment's provoking vertex is the first (table 2.12). */
    segment(lines, block, n - 1, 0, 0);
    return 0;
}
