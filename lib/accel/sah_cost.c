/* SPDX-License-Identifier: Apache-2.0 */
/*
 * sah_cost.c - the SAH cost of a finished tree (MacDonald and Booth 1990),
 * the quality measure that Wald, Ize and Parker (2008) table 1 and rtbench compare builders
 * by.  See bvh_layout.h for the formula.
 */
#include <math.h>

#include "accel/bvh_build.h"
#include "trace/bvh4_layout.h"

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

/* Half the surface of lane l's box in rows of `width` floats (0 when
 * empty). */
static double lane_half_area(const float *bounds, uint32_t width, uint32_t l)
{
    double d[3];
    for (int k = 0; k < 3; k++) {
        d[k] = (double)bounds[(3 + k) * width + l] - (double)bounds[k * width + l];
        if (!(d[k] >= 0.0))
            return 0.0;
    }
    return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
}

double accel_wide_sah_cost(const struct bvh4 *wide, double c_node, double c_packet)
{
    const uint32_t width = wide->width;
    double nodes = 0.0, leaves = 0.0, root = 0.0;
    for (uint32_t w = 0; w < wide->node_count; w++) {
        const float *b = width == 8 ? &wide->nodes8[w].bounds[0][0] : &wide->nodes[w].bounds[0][0];
        const uint8_t *count = width == 8 ? wide->nodes8[w].count : wide->nodes[w].count;
        float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (uint32_t l = 0; l < width; l++) {
            if (!(b[l] <= b[3 * width + l]))
                continue; /* unused */
            for (int k = 0; k < 3; k++) {
                lo[k] = b[k * width + l] < lo[k] ? b[k * width + l] : lo[k];
                hi[k] = b[(3 + k) * width + l] > hi[k] ? b[(3 + k) * width + l] : hi[k];
            }
            if (count[l])
                leaves += lane_half_area(b, width, l) * (double)((count[l] + 3) / 4);
        }
        double d[3];
        for (int k = 0; k < 3; k++)
            d[k] = hi[k] >= lo[k] ? (double)hi[k] - (double)lo[k] : 0.0;
        const double a = d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
        nodes += a;
        if (w == 0)
            root = a;
    }
    const double cost = c_node * nodes + c_packet * leaves;
    return root > 0.0 ? cost / root : 0.0;
}
