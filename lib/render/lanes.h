/* SPDX-License-Identifier: Apache-2.0 */
/*
 * lanes.h - eight-lane float steps shared by the eye light's shading
 * (shade.c) and the surface fetch (surface.c) in their AVX2 copy
 * (shade_eye_avx2.c).  Each is the scalar operation of base/vec3.h in
 * its order, lane by lane, so the same floats: one definition, so that
 * the two files cannot drift apart in the order of their additions.
 */
#ifndef RT_RENDER_LANES_H
#define RT_RENDER_LANES_H

#if defined(__AVX__) && !defined(RT_NO_SIMD)
#include <immintrin.h>

/* vec3_dot of eight lanes: (a0 b0 + a1 b1) + a2 b2. */
static inline __m256 lanes_dot8(const __m256 a[3], const __m256 b[3])
{
    return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(a[0], b[0]), _mm256_mul_ps(a[1], b[1])),
                         _mm256_mul_ps(a[2], b[2]));
}
#endif

#endif
