/* SPDX-License-Identifier: Apache-2.0 */
/*
 * triangle_box.h - the bounds of one indexed triangle, shared by
 * accel_triangle_boxes_pool (build.c), which stores them in a box array,
 * and the parallel builder's set-up (build_parallel.c), which builds from
 * the triangles directly and writes them into its refs without the array
 * (fewer fresh pages a build: the boxes of a million triangles are 24 MB
 * written once and read once).  One function, so that both give the very
 * same floats and so the same trees; and a build ref from it
 * (triangle_ref_set), for both builders' set-ups.
 */
#ifndef RT_ACCEL_TRIANGLE_BOX_H
#define RT_ACCEL_TRIANGLE_BOX_H

#include <stddef.h>
#include <stdint.h>

#include "accel/build_median.h"
#include "accel/vec4.h"
#include "base/aabb.h"

#if defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <emmintrin.h>

/* lo and hi grown by the point p (lane 3 unused) as aabb_grow_point grows
 * them, bit for bit: aabb_fminf(x, y) is x < y ? x : y unless y is NaN
 * (then x) or x is; x here never is (the box starts at +-inf, and
 * every step keeps a non-NaN x or takes a non-NaN y), so it is minps(x,
 * y) (x < y ? x : y, y on equal zeros, as aabb_fminf) with the lanes
 * where y is NaN kept, and likewise for the maximum. */
static inline void triangle_box_grow4(__m128 *lo, __m128 *hi, const float p[3])
{
    const __m128 y = _mm_setr_ps(p[0], p[1], p[2], 0.0f);
    const __m128 number = _mm_cmpord_ps(y, y);
    *lo = _mm_or_ps(_mm_and_ps(number, _mm_min_ps(*lo, y)), _mm_andnot_ps(number, *lo));
    *hi = _mm_or_ps(_mm_and_ps(number, _mm_max_ps(*hi, y)), _mm_andnot_ps(number, *hi));
}

/* Triangle j's box in lanes 0-2 of *lo and *hi (lane 3: +inf, -inf):
 * the same floats as aabb_empty grown by its three corners in order with
 * aabb_grow_point (the portable triangle_box below).  The SSE2 form does
 * the three axes at once: 77 instructions a triangle instead of 114 (the
 * scalar compares and blends of six aabb_fminf/aabb_fmaxf per corner;
 * those were 5 % of a build of 880 triangles). */
static inline void triangle_box4(const float *positions, const uint32_t *indices, uint32_t j,
                                 __m128 *lo, __m128 *hi)
{
    const uint32_t *vi = &indices[3 * (size_t)j];
    *lo = _mm_set1_ps(INFINITY);
    *hi = _mm_set1_ps(-INFINITY);
    for (int k = 0; k < 3; k++)
        triangle_box_grow4(lo, hi, &positions[3 * (size_t)vi[k]]);
}
#endif

/* Triangle j's box, aabb_empty grown by its three corners in order. */
static inline struct aabb triangle_box(const float *positions, const uint32_t *indices,
                                       uint32_t j)
{
    struct aabb box = aabb_empty();
    for (int k = 0; k < 3; k++)
        aabb_grow_point(&box, &positions[3 * (size_t)indices[3 * (size_t)j + k]]);
    return box;
}

/*
 * triangle_ref_set: triangle i's build ref written to *r (its box, the
 * id's bits in lo's lane 3, +0 in hi's), as build_ref_set of
 * triangle_box writes it, and the box's lo and hi (lane 3 zero) returned
 * for the caller's bounds.  Both builders' set-ups from the triangles
 * (build_binned_sah.c serial, build_parallel.c per task) call it, so
 * their refs are the same floats.  With SSE2 the two vectors stay in
 * registers: loading them back right after the stores would read a
 * 16-byte lane from a 16-byte and a 4-byte store (no store forwarding).
 */
static inline void triangle_ref_set(struct build_ref *r, const float *positions,
                                    const uint32_t *indices, uint32_t i, vec4 *l, vec4 *h)
{
#if defined(__SSE2__) && !defined(RT_NO_SIMD)
    __m128 tlo, thi;
    triangle_box4(positions, indices, i, &tlo, &thi);
    *l = vec4_xyz0(tlo);
    *h = vec4_xyz0(thi);
    const __m128 id = _mm_castsi128_ps(_mm_slli_si128(_mm_cvtsi32_si128((int)i), 12));
    _mm_storeu_ps(r->lo, _mm_or_ps(*l, id));
    _mm_storeu_ps(r->hi, *h);
#else
    const struct aabb box = triangle_box(positions, indices, i);
    build_ref_set(r, &box, i);
    *l = vec4_xyz0(vec4_load(r->lo));
    *h = vec4_load(r->hi);
#endif
}

#endif
