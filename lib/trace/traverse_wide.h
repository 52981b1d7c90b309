/* SPDX-License-Identifier: Apache-2.0 */
/*
 * traverse_wide.h - the walk over the 4-wide layout (bvh4_layout.h),
 * included by the SIMD translation units (kernels.h) after
 * traverse_walk.h.  Define TRACE_WIDE_CLOSEST and TRACE_WIDE_ANY.
 *
 * Same answers as the binary walk of traverse_walk.h, bit for bit:
 * - the four child boxes are tested with isect_box's float operations
 *   lane by lane: (bound - org) * inv per slab with the same near/far
 *   choice, the entry folded as max(z, max(y, max(x, tmin))) and the exit
 *   as min(z, min(y, min(x, inf))) with maxps/minps, which return their
 *   second operand for a NaN first one exactly as isect_box's
 *   `a > b ? a : b` does, then the far scale and the clamp to box_limit;
 *   the boxes are the binary nodes' boxes copied bit for bit;
 * - the closest-hit rule does not depend on the order of visits (the
 *   smallest t, ties to the lower primitive; every box holding a hit at
 *   or below the current best passes the test, intersect.h's
 *   tag-graze-box-limit), so skipping the binary inner nodes the collapse
 *   removed and visiting children in another order change the work done
 *   (the node and triangle counts) but not the hit;
 * - the leaves go through the binary walk's walk_leaf (traverse_walk.h):
 *   the same triangle test, limit and hit rule.
 */
#include <immintrin.h>

struct wide_entry {
    uint32_t child;
    uint32_t count; /* 0: wide node child, else a leaf */
    float t_entry;
};

static inline int walk_wide(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                            const struct trace_ray *ray, float t_max, int any_hit,
                            struct trace_hit *hit, struct trace_counters *counters)
{
    if (wide->node_count == 0)
        return 0;
    const struct bvh4_node *nodes = wide->nodes;
    /* Per ray: which of bounds[0..5] is the near and the far plane of each
     * axis (the max for a negative direction, -0 included). */
    int near_row[3], far_row[3];
    __m128 org[3], inv[3];
    for (int k = 0; k < 3; k++) {
        int neg = signbit(ray->inv_dir[k]) != 0;
        near_row[k] = neg ? 3 + k : k;
        far_row[k] = neg ? k : 3 + k;
        org[k] = _mm_set1_ps(ray->org[k]);
        inv[k] = _mm_set1_ps(ray->inv_dir[k]);
    }
    const __m128 tmin4 = _mm_set1_ps(ray->tmin);
    const __m128 inf4 = _mm_set1_ps(INFINITY);
    const __m128 scale4 = _mm_set1_ps(ISECT_BOX_FAR_SCALE);
    uint64_t node_tests = 0;
    uint64_t triangle_tests = 0;
    float best = t_max;
    float box_limit = t_max * ISECT_BOX_FAR_SCALE; /* as traverse_walk.h */
    int found = 0;
    struct wide_entry stack[3 * BVH_MAX_DEPTH + 4];
    uint32_t sp = 0;
    uint32_t cur = 0;
    uint32_t cur_count = 0;
    for (;;) {
        if (cur_count) {
            if (walk_leaf(bvh, tri, ray, cur, cur_count, any_hit, hit, &found, &best, &box_limit,
                          &triangle_tests))
                goto done;
        } else {
            const struct bvh4_node *n = &nodes[cur];
            node_tests += 4;
            __m128 t0 = tmin4;
            __m128 t1 = inf4;
            for (int k = 0; k < 3; k++) {
                const __m128 tn = _mm_mul_ps(
                    _mm_sub_ps(_mm_load_ps(n->bounds[near_row[k]]), org[k]), inv[k]);
                const __m128 tf = _mm_mul_ps(
                    _mm_sub_ps(_mm_load_ps(n->bounds[far_row[k]]), org[k]), inv[k]);
                t0 = _mm_max_ps(tn, t0);
                t1 = _mm_min_ps(tf, t1);
            }
            t1 = _mm_mul_ps(t1, scale4);
            t1 = _mm_min_ps(t1, _mm_set1_ps(box_limit));
            unsigned mask = (unsigned)_mm_movemask_ps(_mm_cmple_ps(t0, t1));
            if (mask) {
                float te[4];
                _mm_storeu_ps(te, t0);
                /* The hit children nearest first: push all but the
                 * nearest, farthest first. */
                int order[4];
                int m = 0;
                for (int l = 0; l < 4; l++) {
                    if (!(mask >> l & 1u))
                        continue;
                    int j = m++;
                    while (j > 0 && te[order[j - 1]] > te[l]) {
                        order[j] = order[j - 1];
                        j--;
                    }
                    order[j] = l;
                }
                for (int j = m - 1; j > 0; j--) {
                    int l = order[j];
                    stack[sp].child = n->child[l];
                    stack[sp].count = n->count[l];
                    stack[sp].t_entry = te[l];
                    sp++;
                }
                cur = n->child[order[0]];
                cur_count = n->count[order[0]];
                continue;
            }
        }
        for (;;) {
            if (sp == 0)
                goto done;
            sp--;
            if (stack[sp].t_entry <= box_limit)
                break;
        }
        cur = stack[sp].child;
        cur_count = stack[sp].count;
    }
done:
    if (counters) {
        counters->node_tests += node_tests;
        counters->triangle_tests += triangle_tests;
    }
    return found;
}

int TRACE_WIDE_CLOSEST(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                       const struct trace_ray *ray, float t_max, struct trace_hit *hit,
                       struct trace_counters *counters);
int TRACE_WIDE_CLOSEST(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                       const struct trace_ray *ray, float t_max, struct trace_hit *hit,
                       struct trace_counters *counters)
{
    return walk_wide(wide, bvh, tri, ray, t_max, 0, hit, counters);
}

int TRACE_WIDE_ANY(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                   const struct trace_ray *ray, float t_max, struct trace_counters *counters);
int TRACE_WIDE_ANY(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                   const struct trace_ray *ray, float t_max, struct trace_counters *counters)
{
    return walk_wide(wide, bvh, tri, ray, t_max, 1, NULL, counters);
}
