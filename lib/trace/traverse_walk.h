/* SPDX-License-Identifier: Apache-2.0 */
/*
 * traverse_walk.h - the body of the single-BVH walk (traverse.c has its
 * description), included once per ISA translation unit: traverse.c (the
 * scalar baseline) and traverse_sse4.c, traverse_avx2.c, traverse_avx512.c,
 * each compiled with its own instruction-set flags (kernels.h).  The same
 * C source gives the same answers under every flag set: the float
 * operations are IEEE single operations in the same order, contraction
 * into fused multiply-adds is off for the whole library (-ffp-contract=off,
 * which Woop, Benthin and Wald 2013 sec. 4's edge functions need), and the
 * SIMD box test (intersect.h's isect_box_pair) computes what the scalar
 * one does lane by lane.  conformance/internal/kernel_bits checks every
 * table against the scalar one bit for bit.
 *
 * Define TRACE_WALK_CLOSEST and TRACE_WALK_ANY to the names of the two
 * functions to generate before including this file; without them (the
 * packet walk's units, packet_wide.h's fallback) only the walk itself.
 */
#include <math.h>
#include <stddef.h>

#include "trace/intersect.h"
#include "trace/trace.h"

struct stack_entry {
    uint32_t node;
    float t_entry;
};

/*
 * The leaf test and the hit rule, shared by the binary walk below and the
 * wide walk (traverse_wide.h): tests the triangles of leaf slots
 * [first, first + count) against the current best.  Once a hit is known,
 * hits at the same distance are tested too, and the lower primitive index
 * wins: the answer is then the same for every tree over the same
 * triangles (builder, layout, strategy, thread count).  Returns 1 when an
 * any-hit walk has its hit and can stop.  Forced inline: called from two
 * walks, GCC would otherwise emit it once and pass found, best and
 * box_limit through memory on every leaf.
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int walk_leaf(const struct bvh *bvh, const float *tri, const struct trace_ray *ray,
                            uint32_t first, uint32_t count, int any_hit, struct trace_hit *hit,
                            int *found, float *best, float *box_limit, uint64_t *triangle_tests)
{
    for (uint32_t slot = first; slot < first + count; slot++) {
        const float *v = &tri[9 * (size_t)slot];
        float t, u, w;
        (*triangle_tests)++;
        float limit = *found ? isect_next_up(*best) : *best;
        if (!isect_triangle(ray, v, v + 3, v + 6, limit, &t, &u, &w))
            continue;
        if (any_hit) {
            *found = 1;
            return 1;
        }
        uint32_t prim = bvh->prim_index[slot];
        if (*found && !(t < *best || prim < hit->prim))
            continue;
        *found = 1;
        *best = t;
        *box_limit = t * ISECT_BOX_FAR_SCALE;
        hit->t = t;
        hit->u = u;
        hit->v = w;
        hit->prim = prim;
    }
    return 0;
}

/* Shared walk; any_hit ends it at the first hit. */
static inline int walk(const struct bvh *bvh, const float *tri, const struct trace_ray *ray,
                       float t_max, int any_hit, struct trace_hit *hit,
                       struct trace_counters *counters)
{
    if (bvh->node_count == 0)
        return 0;
    const struct bvh_node *nodes = bvh->nodes;
    struct isect_box_ray br;
    isect_box_ray_init(&br, ray);
    uint64_t node_tests = 1;
    uint64_t triangle_tests = 0;
    float best = t_max;
    /* Boxes are tested against box_limit, best widened by the slab
     * test's rounding bound, and popped subtrees are compared with it:
     * every box holding a hit at or below best must be visited, for the
     * closest hit and for the tie rule below.  What makes that hold is
     * on the triangle side: isect_triangle clamps every t into its
     * triangle's box as isect_box computes it, so isect_box's entry for
     * any box holding a hit at t is at most t (tag-graze-box-limit;
     * tag-graze-t-in-box in intersect.h).  Without the clamp a grazing
     * ray's plane distance can lie far before the box, and no constant
     * widening here would cover it; the widening is kept as a margin. */
    float box_limit = t_max * ISECT_BOX_FAR_SCALE; /* t_max may itself be a tie bound */
    int found = 0;
    struct stack_entry stack[BVH_MAX_DEPTH + 1];
    uint32_t sp = 0;
    uint32_t current = 0;
    float t_entry;
    if (!isect_box(&br, &nodes[0], box_limit, &t_entry))
        goto done;
    for (;;) {
        const struct bvh_node *node = &nodes[current];
        if (node->count) {
            if (walk_leaf(bvh, tri, ray, node->first, node->count, any_hit, hit, &found, &best,
                          &box_limit, &triangle_tests))
                goto done;
        } else {
            uint32_t left = node->first;
            uint32_t right = left + 1;
            node_tests += 2;
#if ISECT_PAIR_SSE
            float t_pair[2];
            const unsigned mask = isect_box_pair(&br, &nodes[left], box_limit, t_pair);
            const int hit_left = mask & 1u;
            const int hit_right = mask >> 1;
            const float t_left = t_pair[0];
            const float t_right = t_pair[1];
#else
            float t_left;
            float t_right;
            int hit_left = isect_box(&br, &nodes[left], box_limit, &t_left);
            int hit_right = isect_box(&br, &nodes[right], box_limit, &t_right);
#endif
            if (hit_left && hit_right) {
                if (t_right < t_left) {
                    stack[sp].node = left;
                    stack[sp].t_entry = t_left;
                    current = right;
                } else {
                    stack[sp].node = right;
                    stack[sp].t_entry = t_right;
                    current = left;
                }
                sp++;
                continue;
            }
            if (hit_left || hit_right) {
                current = hit_left ? left : right;
                continue;
            }
        }
        /* Pop the next subtree that can still hold a closer hit; the
         * comparison matches isect_box's closed interval. */
        for (;;) {
            if (sp == 0)
                goto done;
            sp--;
            if (stack[sp].t_entry <= box_limit)
                break;
        }
        current = stack[sp].node;
    }
done:
    if (counters) {
        counters->node_tests += node_tests;
        counters->triangle_tests += triangle_tests;
    }
    return found;
}

#if defined(TRACE_WALK_CLOSEST)
int TRACE_WALK_CLOSEST(const struct bvh *bvh, const float *tri, const struct trace_ray *ray,
                       float t_max, struct trace_hit *hit, struct trace_counters *counters);
int TRACE_WALK_CLOSEST(const struct bvh *bvh, const float *tri, const struct trace_ray *ray,
                       float t_max, struct trace_hit *hit, struct trace_counters *counters)
{
    return walk(bvh, tri, ray, t_max, 0, hit, counters);
}

int TRACE_WALK_ANY(const struct bvh *bvh, const float *tri, const struct trace_ray *ray,
                   float t_max, struct trace_counters *counters);
int TRACE_WALK_ANY(const struct bvh *bvh, const float *tri, const struct trace_ray *ray,
                   float t_max, struct trace_counters *counters)
{
    return walk(bvh, tri, ray, t_max, 1, NULL, counters);
}
#endif
