/* SPDX-License-Identifier: Apache-2.0 */
/*
 * sah_cost.c - the SAH cost of a finished tree (MacDonald and Booth 1990),
 * the quality measure that Wald, Ize and Parker (2008) table 1 and rtbench compare builders
 * by.  See bvh_layout.h for the formula.
 */
#include "accel/bvh_build.h"

static double node_half_area(const struct bvh_node *n)
{
    struct aabb b;
    for (int k = 0; k < 3; k++) {
        b.min[k] = n->aabb_min[k];
        b.max[k] = n->aabb_max[k];
    }
    if (aabb_is_empty(&b))
        return 0.0;
    /* In double: the sum runs over millions of nodes and the ratio to the
     * root is what is reported. */
    double dx = (double)b.max[0] - b.min[0];
    double dy = (double)b.max[1] - b.min[1];
    double dz = (double)b.max[2] - b.min[2];
    return dx * dy + dy * dz + dz * dx;
}

double accel_sah_cost(const struct bvh *bvh, float c_trav, float c_isect)
{
    if (bvh->node_count == 0)
        return 0.0;
    double inner = 0.0;
    double leaves = 0.0;
    for (uint32_t i = 0; i < bvh->node_count; i++) {
        const struct bvh_node *n = &bvh->nodes[i];
        double a = node_half_area(n);
        if (n->count)
            leaves += a * (double)n->count;
        else
            inner += a;
    }
    double cost = (double)c_trav * inner + (double)c_isect * leaves;
    double root = node_half_area(&bvh->nodes[0]);
    /* A root of zero area (every primitive on one line or point) makes all
     * areas zero; the cost is then 0 rather than 0/0. */
    return root > 0.0 ? cost / root : 0.0;
}
