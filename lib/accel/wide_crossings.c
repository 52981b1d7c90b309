/* SPDX-License-Identifier: Apache-2.0 */
/*
 * wide_crossings.c - how many children of a wide node a ray crossing the
 * node crosses, on average over the layout (bvh4_layout.h,
 * accel_wide_child_crossings): the measure that chooses the any-hit
 * walk's child order per layout (any_longest).
 */
#include <math.h>

#include "trace/bvh4_layout.h"

/* Half the surface area of a box of extents d, in double (the sums run
 * over every node and only their ratio is used). */
static double half_area(const double d[3])
{
    return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
}

/*
 * For a random line crossing a convex box B, the chance that it also
 * crosses a convex box C inside B is area(C) / area(B) (Santalo 1976,
 * the Cauchy-Crofton formula; MacDonald and Booth 1990, sec. 3, the
 * surface-area heuristic's ray distribution), so the number of a node's
 * children such a line crosses is, in expectation, the sum of the
 * children's areas over the node's.  Averaged over the nodes a line
 * visits (a node is visited in proportion to its area under the same
 * distribution): the sum over the nodes of their children's areas over
 * the sum of their own areas.  A surface cut into patches gives about 1
 * (flat boxes side by side), a volume filled with small triangles about
 * 2 and more (boxes stacked along every axis and overlapping by a
 * triangle's size).  A node's area is that of its lanes' union (the
 * wide node has no box of its own); empty lanes (min > max) count for
 * nothing.  Serial and in a fixed order: the same number for the same
 * layout on every thread count.
 */
double accel_wide_child_crossings(const struct bvh4 *wide)
{
    if (wide->width != 8 || !wide->node_count)
        return 0.0;
    double children = 0.0, nodes = 0.0;
    /* Every fourth node (as collapse4.c's leaf_extent_mean samples the
     * leaves): the full sum cost 0.7 % of bumpy's one-thread build (17
     * million instructions, callgrind).  The sample moves the ratios of
     * the layouts measured (all nodes -> every fourth): the soup 1.81 ->
     * 1.83, bumpy 1.18 -> 1.23, the kitchen 1.19 -> 1.20, gears (77
     * nodes) 1.44 -> 1.19; the soup stays far above the others. */
    for (uint32_t w = 0; w < wide->node_count; w += 4) {
        const struct bvh8_node *n = &wide->nodes8[w];
        float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        double sum = 0.0;
        for (uint32_t l = 0; l < 8; l++) {
            if (!(n->bounds[0][l] <= n->bounds[3][l]))
                continue; /* unused lane */
            double d[3];
            for (int k = 0; k < 3; k++) {
                lo[k] = n->bounds[k][l] < lo[k] ? n->bounds[k][l] : lo[k];
                hi[k] = n->bounds[3 + k][l] > hi[k] ? n->bounds[3 + k][l] : hi[k];
                d[k] = (double)n->bounds[3 + k][l] - (double)n->bounds[k][l];
            }
            sum += half_area(d);
        }
        double d[3];
        for (int k = 0; k < 3; k++)
            d[k] = hi[k] >= lo[k] ? (double)hi[k] - (double)lo[k] : 0.0;
        children += sum;
        nodes += half_area(d);
    }
    return nodes > 0.0 && isfinite(children) ? children / nodes : 0.0;
}
