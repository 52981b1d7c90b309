/* SPDX-License-Identifier: Apache-2.0 */
/*
 * brute_force.c - the reference intersector (trace.h): every triangle,
 * no acceleration structure.  The differential tests and rtbench's error
 * measurements compare everything faster against it.
 */
#include "trace/trace.h"

#include <stddef.h>

#include "trace/intersect.h"

int trace_closest_brute_force(const float *positions, const uint32_t *indices,
                              uint32_t tri_count, const struct trace_ray *ray, float t_max,
                              struct trace_hit *hit)
{
    float best = t_max;
    int found = 0;
    for (uint32_t i = 0; i < tri_count; i++) {
        const uint32_t *vi = &indices[3 * (size_t)i];
        float t, u, v;
        /* Strictly closer only, so an equal distance keeps the lower
         * index (the tie rule of trace.h). */
        if (!isect_triangle(ray, &positions[3 * (size_t)vi[0]], &positions[3 * (size_t)vi[1]],
                            &positions[3 * (size_t)vi[2]], best, &t, &u, &v))
            continue;
        found = 1;
        best = t;
        hit->t = t;
        hit->u = u;
        hit->v = v;
        hit->prim = i;
    }
    return found;
}
