/* SPDX-License-Identifier: Apache-2.0 */
/*
 * intersect.c - the exported ray/triangle and ray/box tests (trace.h),
 * thin wrappers around the kernels of intersect.h.
 */
#include "trace/intersect.h"

int trace_triangle(const struct trace_ray *ray, const float v0[3], const float v1[3],
                   const float v2[3], float t_max, float *t, float *u, float *v)
{
    return isect_triangle(ray, v0, v1, v2, t_max, t, u, v);
}

int trace_box(const struct trace_ray *ray, const float aabb_min[3], const float aabb_max[3],
              float t_max, float *t_entry)
{
    struct isect_box_ray br;
    struct bvh_node node;
    isect_box_ray_init(&br, ray);
    for (int k = 0; k < 3; k++) {
        node.aabb_min[k] = aabb_min[k];
        node.aabb_max[k] = aabb_max[k];
    }
    return isect_box(&br, &node, t_max, t_entry);
}
