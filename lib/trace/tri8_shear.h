/* SPDX-License-Identifier: Apache-2.0 */
/*
 * tri8_shear.h - the first steps of the watertight triangle test
 * (intersect.h's isect_triangle; Woop, Benthin and Wald 2013, sec. 3) in
 * eight AVX lanes: the vertices relative to the ray's origin sheared in
 * x and y, and the three edge functions, with isect_triangle's
 * operations in its order (-ffp-contract=off; separate multiplies and
 * adds).  One copy for the 8-lane filters that run them over triangles
 * (intersect_tri4.h's tri4_pair_filter_lanes), over rays (packet_tri8.h's
 * tri8_test) and over both (tri8_pair_filter), whose lanes must give the
 * scalar test's bits.
 */
#ifndef RT_TRACE_TRI8_SHEAR_H
#define RT_TRACE_TRI8_SHEAR_H

#if defined(__AVX__)
#include <immintrin.h>

/* Vertex a, b, c minus the origin, sheared (A = a + s a_z in x and y),
 * and the edge functions U, V, W of the sheared triangle. */
struct tri8_sheared {
    __m256 Ax, Ay, Bx, By, Cx, Cy;
    __m256 U, V, W;
};

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void tri8_shear(__m256 ax, __m256 ay, __m256 az, __m256 bx, __m256 by, __m256 bz,
                              __m256 cx, __m256 cy, __m256 cz, __m256 sx, __m256 sy,
                              struct tri8_sheared *s)
{
    s->Ax = _mm256_add_ps(ax, _mm256_mul_ps(sx, az));
    s->Ay = _mm256_add_ps(ay, _mm256_mul_ps(sy, az));
    s->Bx = _mm256_add_ps(bx, _mm256_mul_ps(sx, bz));
    s->By = _mm256_add_ps(by, _mm256_mul_ps(sy, bz));
    s->Cx = _mm256_add_ps(cx, _mm256_mul_ps(sx, cz));
    s->Cy = _mm256_add_ps(cy, _mm256_mul_ps(sy, cz));
    s->U = _mm256_sub_ps(_mm256_mul_ps(s->Cx, s->By), _mm256_mul_ps(s->Cy, s->Bx));
    s->V = _mm256_sub_ps(_mm256_mul_ps(s->Ax, s->Cy), _mm256_mul_ps(s->Ay, s->Cx));
    s->W = _mm256_sub_ps(_mm256_mul_ps(s->Bx, s->Ay), _mm256_mul_ps(s->By, s->Ax));
}

/* The lanes with an edge function of exactly 0: the paper's sec. 4 case,
 * which isect_triangle decides in double. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline __m256 tri8_on_edge(const struct tri8_sheared *s)
{
    const __m256 zero = _mm256_setzero_ps();
    return _mm256_or_ps(
        _mm256_or_ps(_mm256_cmp_ps(s->U, zero, _CMP_EQ_OQ), _mm256_cmp_ps(s->V, zero, _CMP_EQ_OQ)),
        _mm256_cmp_ps(s->W, zero, _CMP_EQ_OQ));
}
#endif

#endif
