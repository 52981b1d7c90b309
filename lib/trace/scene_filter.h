/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene_filter.h - the object walk of an instance whose hits the scene
 * filters (trace_scene.accept, scene_traverse.h).
 *
 * A hit the filter rejects is not there: the walk goes on to the
 * triangles behind it, and to a triangle at the same distance (a
 * coincident copy, a neighbour on a shared edge), which a restart of the
 * search just above the rejected distance would lose.
 */
#ifndef RT_TRACE_SCENE_FILTER_H
#define RT_TRACE_SCENE_FILTER_H

#include "trace/scene_traverse.h"

struct trace_filter_ray {
    const struct trace_scene *scene; /* accept, accept_user */
    const float *org;                /* the world ray, handed to accept */
    const float *dir;
    uint32_t index;                  /* the instance's slot */
    int any_hit;
};

/*
 * The closest hit with o_ray->tmin <= t < t_max that the filter accepts,
 * of equal t the lowest primitive (the kernels' rule, trace.h), or with
 * any_hit the first accepted one found.  Each triangle's t, u, v are
 * trace_triangle's, which every kernel gives (kernels.h), so the answer
 * does not depend on the ISA, the layout nor the order of visits: the
 * filter is asked only about a hit that comes before the best accepted
 * so far, and the best accepted is the same whatever the order.  The
 * binary BVH, box culling at the best accepted distance.  Returns 1 and
 * fills *hit when there is one.
 */
int trace_filter_object(const struct trace_object_view *view, const struct trace_ray *o_ray,
                        float t_max, const struct trace_filter_ray *r, struct trace_hit *hit,
                        struct trace_counters *counters);

#endif
