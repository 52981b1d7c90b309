/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene_filter.c - the filtered object walk (scene_filter.h).
 *
 * A depth-first walk of the object's binary BVH; each leaf triangle is
 * tested with trace_triangle below the best accepted distance (one ulp
 * above it once there is one, so that a lower primitive at that same t
 * still counts), and a hit that would become the best is handed to the
 * filter (the role of the intersection filter callbacks of ray tracing
 * kernels such as Embree, Wald, Woop, Benthin, Johnson and Ernst 2014):
 * rejecting a hit inside the walk keeps the other hits at its distance,
 * which stepping the ray's tmin past it would skip.
 */
#include "trace/scene_filter.h"

#include <math.h>

#include "trace/binary_walk.h"
#include "trace/intersect.h"

int trace_filter_object(const struct trace_object_view *view, const struct trace_ray *o_ray,
                        float t_max, const struct trace_filter_ray *r, struct trace_hit *hit,
                        struct trace_counters *counters)
{
    const struct bvh *bvh = view->bvh;
    if (!bvh || bvh->node_count == 0)
        return 0;
    const struct trace_scene *scene = r->scene;
    int found = 0;
    float best = t_max;
    struct trace_binary_walk walk;
    trace_binary_walk_init(&walk, bvh);
    const struct bvh_node *leaf;
    while ((leaf = trace_binary_walk_next(&walk, o_ray, best, &counters->node_tests))) {
        for (uint32_t i = 0; i < leaf->count; i++) {
            const uint32_t slot = leaf->first + i;
            const float *v = &view->tri[9 * (size_t)slot];
            const float limit = found ? isect_next_up(best) : best;
            struct trace_scene_hit h;
            counters->triangle_tests++;
            if (!trace_triangle(o_ray, v, v + 3, v + 6, limit, &h.t, &h.u, &h.v))
                continue;
            h.prim = bvh->prim_index[slot];
            h.instance = r->index;
            /* At the best distance: the lower primitive wins. */
            if (found && !(h.t < best) && h.prim >= hit->prim)
                continue;
            if (!scene->accept(scene->accept_user, r->org, r->dir, &h))
                continue;
            hit->t = h.t;
            hit->u = h.u;
            hit->v = h.v;
            hit->prim = h.prim;
            found = 1;
            best = h.t;
            if (r->any_hit)
                return 1;
        }
    }
    return found;
}
