/* SPDX-License-Identifier: Apache-2.0 */
/*
 * binary_walk.h - the depth-first walk of a binary BVH (bvh_layout.h)
 * that the scalar side walks share: the filtered object walk
 * (scene_filter.c) and both levels of the walk for the hits at one
 * distance (scene_ties.c).  It hands out, one at a time, the leaves whose
 * boxes trace_box accepts; what a leaf holds (triangles, instances) and
 * what the caller does with it is the caller's.
 *
 * The order is fixed (a node's second child before its first), so the
 * counters come out the same on every run; neither caller's answer
 * depends on it.  The kernels' walks (traverse_walk.h, traverse_wide.h)
 * keep their own loops: they carry entry distances and order children
 * front to back.
 */
#ifndef RT_TRACE_BINARY_WALK_H
#define RT_TRACE_BINARY_WALK_H

#include <stdint.h>

#include "trace/bvh_layout.h"
#include "trace/trace.h"

/* A walk in progress: stack[0 .. sp) are the nodes still to visit. */
struct trace_binary_walk {
    const struct bvh *bvh;
    int sp;
    uint32_t stack[BVH_MAX_DEPTH + 1];
};

/* Starts a walk at the root of bvh, which has at least one node. */
static inline void trace_binary_walk_init(struct trace_binary_walk *w, const struct bvh *bvh)
{
    w->bvh = bvh;
    w->stack[0] = 0;
    w->sp = 1;
}

/*
 * The next leaf whose box trace_box accepts for ray up to t_max (the
 * caller's bound of the moment: it may shrink between calls), or NULL when
 * the walk is over.  Adds one to *node_tests per box tested.
 */
static inline const struct bvh_node *trace_binary_walk_next(struct trace_binary_walk *w,
                                                            const struct trace_ray *ray,
                                                            float t_max, uint64_t *node_tests)
{
    while (w->sp > 0) {
        const struct bvh_node *node = &w->bvh->nodes[w->stack[--w->sp]];
        float t_entry;
        (*node_tests)++;
        if (!trace_box(ray, node->aabb_min, node->aabb_max, t_max, &t_entry))
            continue;
        if (node->count)
            return node;
        w->stack[w->sp++] = node->first;
        w->stack[w->sp++] = node->first + 1;
    }
    return NULL;
}

#endif
