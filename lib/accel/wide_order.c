/* SPDX-License-Identifier: Apache-2.0 */
/*
 * wide_order.c - the wide layout's nodes and packets renumbered in depth
 * first order (bvh4_layout.h, accel_wide_reorder): a pass after the
 * collapse, which numbers them breadth first.
 *
 * Why: a ray walks a path from the root down, so in preorder the nodes of
 * a subtree, and with them the packets of its leaves, are consecutive in
 * memory, and a subtree small enough shares its cache lines and pages
 * with nothing else; breadth first, siblings are adjacent but a node's
 * children are far from it below the top levels.  (Embree's builders
 * allocate a node's children as the recursion reaches them, which gives
 * a depth-first layout too.)  Only memory addresses change: every node
 * keeps its lanes, boxes, counts and octant orders, every packet its
 * bytes, so every walk visits the same boxes and triangles in the same
 * order and gives the same answers.
 */
#include <string.h>

#include "base/alloc.h"
#include "trace/bvh4_layout.h"

/* Where a node's child indices and counts are, for either width. */
static uint32_t *node_child(const struct bvh4 *w, char *nodes, uint32_t i)
{
    return w->width == 8 ? ((struct bvh8_node *)(void *)nodes)[i].child
                         : ((struct bvh4_node *)(void *)nodes)[i].child;
}

static const uint8_t *node_count(const struct bvh4 *w, const char *nodes, uint32_t i)
{
    return w->width == 8 ? ((const struct bvh8_node *)(const void *)nodes)[i].count
                         : ((const struct bvh4_node *)(const void *)nodes)[i].count;
}

/* Half the surface area of lane l's box in node i. */
static float lane_area(const struct bvh4 *w, uint32_t i, uint32_t l)
{
    float d[3];
    for (int k = 0; k < 3; k++)
        d[k] = w->width == 8 ? w->nodes8[i].bounds[3 + k][l] - w->nodes8[i].bounds[k][l]
                             : w->nodes[i].bounds[3 + k][l] - w->nodes[i].bounds[k][l];
    return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
}

int accel_wide_reorder(struct bvh4 *w, int area_first)
{
    if (w->node_count == 0 || w->packet_count == 0)
        return 0;
    const uint32_t width = w->width;
    const uint32_t n = w->node_count;
    const size_t node_size = width == 8 ? sizeof(struct bvh8_node) : sizeof(struct bvh4_node);
    const size_t node_bytes = (size_t)n * node_size;
    const size_t packet_bytes = (size_t)w->packet_count * sizeof(struct tri4_packet);
    char *nodes = width == 8 ? (char *)(void *)w->nodes8 : (char *)(void *)w->nodes;
    /* old[k]: the node numbered k in preorder; fresh[i]: node i's new number. */
    uint32_t *old = rt_realloc_array(NULL, n, sizeof(uint32_t));
    uint32_t *fresh = rt_realloc_array(NULL, n, sizeof(uint32_t));
    /* A pop pushes at most width - 1 more entries than it takes. */
    uint32_t *stack = rt_realloc_array(NULL, (size_t)n * (width - 1) + 1, sizeof(uint32_t));
    uint32_t *source = rt_realloc_array(NULL, (size_t)n * width, sizeof(uint32_t));
    uint32_t *packet_slot = rt_realloc_array(NULL, w->packet_count, sizeof(uint32_t));
    char *copy = rt_malloc(node_bytes + packet_bytes);
    if (!old || !fresh || !stack || !source || !packet_slot || !copy) {
        rt_free(old);
        rt_free(fresh);
        rt_free(stack);
        rt_free(source);
        rt_free(packet_slot);
        rt_free(copy);
        return -1;
    }
    uint32_t top = 0, k = 0;
    stack[top++] = 0;
    while (top) {
        const uint32_t i = stack[--top];
        fresh[i] = k;
        old[k++] = i;
        const uint32_t *child = node_child(w, nodes, i);
        const uint8_t *count = node_count(w, nodes, i);
        uint32_t lanes[8];
        float area[8];
        uint32_t m = 0;
        for (uint32_t l = 0; l < width; l++) {
            if (w->source[width * i + l] == UINT32_MAX || count[l])
                continue;
            /* Insertion by area, largest first (ties: lane order). */
            const float a = area_first ? lane_area(w, i, l) : 0.0f;
            uint32_t j = m++;
            while (j > 0 && area[j - 1] < a) {
                lanes[j] = lanes[j - 1];
                area[j] = area[j - 1];
                j--;
            }
            lanes[j] = child[l];
            area[j] = a;
        }
        /* The first to visit on top. */
        while (m)
            stack[top++] = lanes[--m];
    }
    /* The packets in the order the preorder reaches their lanes. */
    char *pk = copy + node_bytes;
    uint32_t p = 0;
    for (uint32_t q = 0; q < n; q++) {
        const uint32_t i = old[q];
        char *dst = copy + (size_t)q * node_size;
        memcpy(dst, nodes + (size_t)i * node_size, node_size);
        memcpy(source + (size_t)width * q, w->source + (size_t)width * i, width * sizeof(uint32_t));
        uint32_t *child = node_child(w, copy, q);
        const uint8_t *count = node_count(w, copy, q);
        for (uint32_t l = 0; l < width; l++) {
            if (w->source[width * i + l] == UINT32_MAX)
                continue;
            if (!count[l]) {
                child[l] = fresh[child[l]];
                continue;
            }
            const uint32_t first = child[l];
            const uint32_t packets = (count[l] + 3u) / 4u;
            memcpy(pk + (size_t)p * sizeof(struct tri4_packet), &w->packets[first],
                   packets * sizeof(struct tri4_packet));
            memcpy(packet_slot + p, w->packet_slot + first, packets * sizeof(uint32_t));
            child[l] = p;
            p += packets;
        }
    }
    memcpy(nodes, copy, node_bytes + packet_bytes);
    rt_free(w->source);
    rt_free(w->packet_slot);
    w->source = source;
    w->packet_slot = packet_slot;
    rt_free(old);
    rt_free(fresh);
    rt_free(stack);
    rt_free(copy);
    return 0;
}
