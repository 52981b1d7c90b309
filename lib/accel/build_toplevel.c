/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_toplevel.c - Wald, Benthin and Slusallek (2003) sec. 4.5 top-level construction (see
 * build_toplevel.h).
 */
#include "accel/build_toplevel.h"

#include <string.h>

#include "accel/build_internal.h"
#include "base/alloc.h"

struct task {
    uint32_t begin, end; /* range of order[] */
    uint32_t node;
    uint32_t depth;
    struct aabb cell; /* the node's cell: its side of the parent's plane */
};

static float centroid(const struct aabb *b, int d)
{
    return 0.5f * (b->min[d] + b->max[d]);
}

/* Box of boxes[order[begin..end)]. */
static struct aabb bounds_of(const struct aabb *boxes, const uint32_t *order, uint32_t begin,
                             uint32_t end)
{
    struct aabb b = aabb_empty();
    for (uint32_t i = begin; i < end; i++)
        aabb_grow(&b, &boxes[order[i]]);
    return b;
}

/* Moves the boxes whose centroid lies below p on axis d to the front of
 * the range; returns the first index of the rest. */
static uint32_t partition(const struct aabb *boxes, uint32_t *order, uint32_t begin, uint32_t end,
                          int d, float p)
{
    uint32_t mid = begin;
    for (uint32_t i = begin; i < end; i++)
        if (centroid(&boxes[order[i]], d) < p) {
            uint32_t t = order[i];
            order[i] = order[mid];
            order[mid] = t;
            mid++;
        }
    return mid;
}

/*
 * The paper's plane on axis d: c = cell centre; if more boxes lie left of
 * c, the largest border below c, else the smallest border at or above c
 * (observations 2 and 3 of sec. 4.5).  Returns 0 when there is none.
 */
static int paper_plane(const struct aabb *boxes, const uint32_t *order, uint32_t begin,
                       uint32_t end, const struct aabb *cell, int d, float *plane)
{
    float c = 0.5f * (cell->min[d] + cell->max[d]);
    uint32_t left = 0;
    for (uint32_t i = begin; i < end; i++)
        left += centroid(&boxes[order[i]], d) < c;
    int more_left = left > (end - begin) - left;
    int found = 0;
    float best = 0.0f;
    for (uint32_t i = begin; i < end; i++) {
        const struct aabb *b = &boxes[order[i]];
        float borders[2] = {b->min[d], b->max[d]};
        for (int k = 0; k < 2; k++) {
            float p = borders[k];
            if (more_left ? !(p < c) : !(p >= c))
                continue;
            if (!found || (more_left ? p > best : p < best)) {
                best = p;
                found = 1;
            }
        }
    }
    *plane = best;
    return found;
}

/* Axes by decreasing extent of the cell (observation 1). */
static void axes_by_extent(const struct aabb *cell, int axes[3])
{
    float e[3];
    for (int k = 0; k < 3; k++) {
        axes[k] = k;
        e[k] = cell->max[k] - cell->min[k];
    }
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (e[axes[j]] > e[axes[i]]) {
                int t = axes[i];
                axes[i] = axes[j];
                axes[j] = t;
            }
}

int accel_build_toplevel_cellsplit(struct bvh *out, const struct aabb *boxes, uint32_t count)
{
    memset(out, 0, sizeof(*out));
    if (count == 0)
        return 0;
    if (accel_build_alloc(out, count))
        return -1;
    uint32_t *order = out->prim_index;
    for (uint32_t i = 0; i < count; i++)
        order[i] = i;
    struct task stack[BUILD_STACK_SIZE];
    uint32_t sp = 0, node_count = 1, max_depth = 0;
    struct aabb root = bounds_of(boxes, order, 0, count);
    stack[sp++] = (struct task){0, count, 0, 0, root};
    while (sp > 0) {
        struct task t = stack[--sp];
        struct bvh_node *node = &out->nodes[t.node];
        struct aabb box = bounds_of(boxes, order, t.begin, t.end);
        build_set_box(node, &box);
        max_depth = t.depth > max_depth ? t.depth : max_depth;
        uint32_t n = t.end - t.begin;
        uint32_t mid = t.begin;
        int split_axis = -1;
        float plane = 0.0f;
        if (n > 1 && !build_must_split_median(t.depth, n)) {
            int axes[3];
            axes_by_extent(&t.cell, axes);
            for (int a = 0; a < 3 && split_axis < 0; a++) {
                if (!paper_plane(boxes, order, t.begin, t.end, &t.cell, axes[a], &plane))
                    continue;
                mid = partition(boxes, order, t.begin, t.end, axes[a], plane);
                if (mid > t.begin && mid < t.end)
                    split_axis = axes[a];
            }
            if (split_axis < 0) {
                build_set_leaf(node, t.begin, n); /* "no valid splitting plane found" */
                continue;
            }
        } else if (n > 1) {
            /* Depth guard: halve the range (any split keeps correctness). */
            mid = t.begin + n / 2;
        } else {
            build_set_leaf(node, t.begin, n);
            continue;
        }
        uint32_t left = node_count;
        node_count += 2;
        build_set_inner(node, left);
        struct aabb left_cell = t.cell, right_cell = t.cell;
        if (split_axis >= 0) {
            left_cell.max[split_axis] = plane;
            right_cell.min[split_axis] = plane;
        }
        stack[sp++] = (struct task){mid, t.end, left + 1, t.depth + 1, right_cell};
        stack[sp++] = (struct task){t.begin, mid, left, t.depth + 1, left_cell};
    }
    accel_build_finish(out, node_count, max_depth);
    return 0;
}
