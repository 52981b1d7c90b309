/* SPDX-License-Identifier: Apache-2.0 */
/*
 * top_lanes.h - the top level's wide-node tests for the AVX2 and AVX-512
 * tables (kernels.h top_lanes, top_lanes1), included by their
 * translation units with TRACE_TOP_LANES and TRACE_TOP_LANES1 naming the
 * functions.
 *
 * TRACE_TOP_LANES: a packet's test (packet.h, trace_top_lanes_fn) with
 * eight rays in one 256-bit register.
 * Per lane of the node that holds a box, the eight rays' slab test in
 * the order of trace_scene_wide_lanes (scene_traverse.c): entry
 * max(tn, t0) from tmin over x, y, z, exit min(tf, t1) from +inf, the
 * exit times ISECT_BOX_FAR_SCALE (Ize 2013's robust bound), clamped to
 * the ray's box limit, and entry <= exit.  Each ray's floats are the
 * ones its own test computes, so its bit is the same; what changes is
 * the work: one broadcast of a box's planes for all eight rays, where
 * the ray-by-ray test loads the node's planes once per ray.
 *
 * TRACE_TOP_LANES1: one ray against the eight lanes of an 8-wide node in
 * one register (trace_scene_wide_lanes' contract and operations, which
 * take two 128-bit halves); a 4-wide node takes that function itself.
 */
#if !defined(TRACE_TOP_LANES) || !defined(TRACE_TOP_LANES1)
#error "define TRACE_TOP_LANES and TRACE_TOP_LANES1 before including top_lanes.h"
#endif

#include <immintrin.h>

#include "trace/intersect.h"
#include "trace/packet.h"
#include "trace/scene_traverse.h"

static void TRACE_TOP_LANES(const struct trace_top_rays *q, const float *bounds, uint32_t width,
                            unsigned rays, unsigned lane_rays[8], float t_min[8])
{
    unsigned used = trace_top_used_lanes(bounds, width);
    const __m256 tmin = _mm256_load_ps(q->tmin);
    const __m256 limit = _mm256_load_ps(q->box_limit);
    const __m256 scale = _mm256_set1_ps(ISECT_BOX_FAR_SCALE);
    const __m256 inf = _mm256_set1_ps(INFINITY);
    __m256 org[3], inv[3];
    const float *near[3], *far[3];
    for (int k = 0; k < 3; k++) {
        org[k] = _mm256_load_ps(q->org[k]);
        inv[k] = _mm256_load_ps(q->inv_dir[k]);
        near[k] = bounds + q->near_row[k] * width;
        far[k] = bounds + q->far_row[k] * width;
    }
    for (; used; used &= used - 1u) {
        const int l = __builtin_ctz(used);
        __m256 t0 = tmin, t1 = inf;
        for (int k = 0; k < 3; k++) {
            const __m256 tn = _mm256_mul_ps(_mm256_sub_ps(_mm256_broadcast_ss(near[k] + l), org[k]),
                                            inv[k]);
            const __m256 tf = _mm256_mul_ps(_mm256_sub_ps(_mm256_broadcast_ss(far[k] + l), org[k]),
                                            inv[k]);
            t0 = _mm256_max_ps(tn, t0);
            t1 = _mm256_min_ps(tf, t1);
        }
        t1 = _mm256_min_ps(_mm256_mul_ps(t1, scale), limit);
        unsigned in = (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(t0, t1, _CMP_LE_OS)) & rays;
        if (!in)
            continue;
        lane_rays[l] |= in;
        float te[8];
        _mm256_storeu_ps(te, t0);
        float m = t_min[l];
        for (; in; in &= in - 1u) {
            const float t = te[__builtin_ctz(in)];
            m = t < m ? t : m;
        }
        t_min[l] = m;
    }
}

static unsigned TRACE_TOP_LANES1(const float *bounds, uint32_t width, const int near_row[3],
                                 const int far_row[3], const struct trace_ray *ray, float t_max,
                                 float t_entry[8])
{
    if (width != 8)
        return trace_scene_wide_lanes(bounds, width, near_row, far_row, ray, t_max, t_entry);
    __m256 t0 = _mm256_set1_ps(ray->tmin);
    __m256 t1 = _mm256_set1_ps(INFINITY);
    for (int k = 0; k < 3; k++) {
        const __m256 o = _mm256_set1_ps(ray->org[k]);
        const __m256 inv = _mm256_set1_ps(ray->inv_dir[k]);
        const __m256 tn = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(bounds + near_row[k] * 8), o),
                                        inv);
        const __m256 tf = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(bounds + far_row[k] * 8), o),
                                        inv);
        t0 = _mm256_max_ps(tn, t0);
        t1 = _mm256_min_ps(tf, t1);
    }
    t1 = _mm256_min_ps(_mm256_mul_ps(t1, _mm256_set1_ps(ISECT_BOX_FAR_SCALE)),
                       _mm256_set1_ps(t_max));
    _mm256_storeu_ps(t_entry, t0);
    return (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(t0, t1, _CMP_LE_OS));
}
