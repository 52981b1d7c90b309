/* SPDX-License-Identifier: Apache-2.0 */
/*
 * collapse4.c - the binary BVH collapsed into the 4-wide traversal layout
 * (trace/bvh4_layout.h).
 */
#include "trace/bvh4_layout.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "base/alloc.h"

static float node_area(const struct bvh_node *n)
{
    float dx = n->aabb_max[0] - n->aabb_min[0];
    float dy = n->aabb_max[1] - n->aabb_min[1];
    float dz = n->aabb_max[2] - n->aabb_min[2];
    return dx * dy + dy * dz + dz * dx;
}

static void set_lane(struct bvh4_node *w, int lane, const struct bvh_node *n)
{
    for (int k = 0; k < 3; k++) {
        w->bounds[k][lane] = n->aabb_min[k];
        w->bounds[3 + k][lane] = n->aabb_max[k];
    }
}

static void clear_lane(struct bvh4_node *w, int lane)
{
    for (int k = 0; k < 3; k++) {
        w->bounds[k][lane] = INFINITY;
        w->bounds[3 + k][lane] = -INFINITY;
    }
    w->child[lane] = 0;
    w->count[lane] = 0;
}

/* The binary nodes a wide node over binary inner node `inner` holds:
 * starting from its two children, the inner one of largest area is
 * replaced by its children until there are four (ties: the first). */
static int gather(const struct bvh *bvh, uint32_t inner, uint32_t out[4])
{
    int n = 2;
    out[0] = bvh->nodes[inner].first;
    out[1] = out[0] + 1;
    while (n < 4) {
        int pick = -1;
        float best = -1.0f;
        for (int i = 0; i < n; i++) {
            const struct bvh_node *c = &bvh->nodes[out[i]];
            float a = node_area(c);
            if (c->count == 0 && (pick < 0 || a > best)) {
                pick = i;
                best = a;
            }
        }
        if (pick < 0)
            break;
        uint32_t first = bvh->nodes[out[pick]].first;
        out[pick] = first;
        out[n++] = first + 1;
    }
    return n;
}

int accel_collapse4(struct bvh4 *out, const struct bvh *bvh)
{
    memset(out, 0, sizeof(*out));
    if (bvh->node_count == 0)
        return 0;
    /* Every wide node but the root consumes a binary inner node, so
     * there are at most (node_count - 1) / 2 + 1 of them. */
    uint32_t cap = (bvh->node_count - 1) / 2 + 1;
    void *raw = rt_malloc((size_t)cap * sizeof(struct bvh4_node) + 63);
    uint32_t *source = rt_calloc((size_t)cap * 4, sizeof(uint32_t));
    /* Work list of (wide node, binary inner node) pairs still to fill. */
    uint32_t *todo = rt_calloc((size_t)cap, sizeof(uint32_t));
    if (!raw || !source || !todo) {
        rt_free(raw);
        rt_free(source);
        rt_free(todo);
        return -1;
    }
    struct bvh4_node *nodes =
        (struct bvh4_node *)(void *)(((uintptr_t)raw + 63) & ~(uintptr_t)63);
    uint32_t count = 1;
    if (bvh->nodes[0].count) {
        /* A single leaf: the root's one lane. */
        for (int l = 0; l < 4; l++)
            clear_lane(&nodes[0], l);
        set_lane(&nodes[0], 0, &bvh->nodes[0]);
        nodes[0].child[0] = bvh->nodes[0].first;
        nodes[0].count[0] = bvh->nodes[0].count;
        source[0] = 0;
        source[1] = source[2] = source[3] = UINT32_MAX;
    } else {
        todo[0] = 0;
        for (uint32_t w = 0; w < count; w++) {
            uint32_t lanes[4];
            int n = gather(bvh, todo[w], lanes);
            struct bvh4_node *wn = &nodes[w];
            for (int l = 0; l < 4; l++) {
                clear_lane(wn, l);
                source[4 * w + l] = l < n ? lanes[l] : UINT32_MAX;
                if (l >= n)
                    continue;
                const struct bvh_node *c = &bvh->nodes[lanes[l]];
                set_lane(wn, l, c);
                if (c->count) {
                    wn->child[l] = c->first;
                    wn->count[l] = c->count;
                } else {
                    todo[count] = lanes[l];
                    wn->child[l] = count++;
                    wn->count[l] = 0;
                }
            }
        }
    }
    rt_free(todo);
    out->nodes = nodes;
    out->node_count = count;
    out->source = source;
    out->raw = raw;
    return 0;
}

void accel_refit4(struct bvh4 *wide, const struct bvh *bvh)
{
    for (uint32_t w = 0; w < wide->node_count; w++) {
        struct bvh4_node *wn = &wide->nodes[w];
        for (int l = 0; l < 4; l++) {
            /* Unused lanes keep their empty box. */
            if (wide->source[4 * w + l] == UINT32_MAX)
                continue;
            set_lane(wn, l, &bvh->nodes[wide->source[4 * w + l]]);
        }
    }
}

void bvh4_release(struct bvh4 *wide)
{
    rt_free(wide->raw);
    rt_free(wide->source);
    memset(wide, 0, sizeof(*wide));
}
