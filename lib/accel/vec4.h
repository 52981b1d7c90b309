/* SPDX-License-Identifier: Apache-2.0 */
/*
 * vec4.h - four-float vectors for the builders' inner loops.
 *
 * SSE when the compiler targets it (every x86-64 compiler does), else
 * plain C.  The two give bit-identical results: each operation is the same
 * IEEE single-precision operation lane by lane, and min/max follow the
 * minps/maxps rule (a < b ? a : b, a > b ? a : b: the second operand when
 * the comparison is unordered), so a tree built on any machine is the same
 * tree.  Define RT_NO_SIMD (CMake option RT_NO_SIMD=ON) to force the C
 * path; ctest's internal/builders_nosimd runs the builder tests on that
 * path in every build (conformance/CMakeLists.txt).
 *
 * Boxes are kept as two vec4 (min, max) whose fourth lane is ignored.
 */
#ifndef RT_ACCEL_VEC4_H
#define RT_ACCEL_VEC4_H

#include <stdint.h>
#include <string.h>

#if defined(__SSE2__) && !defined(RT_NO_SIMD)

#include <emmintrin.h>

typedef __m128 vec4;

static inline vec4 vec4_load(const float p[4])
{
    return _mm_loadu_ps(p);
}

static inline void vec4_store(float p[4], vec4 a)
{
    _mm_storeu_ps(p, a);
}

static inline vec4 vec4_set(float x, float y, float z, float w)
{
    return _mm_setr_ps(x, y, z, w);
}

static inline vec4 vec4_splat(float x)
{
    return _mm_set1_ps(x);
}

static inline vec4 vec4_add(vec4 a, vec4 b)
{
    return _mm_add_ps(a, b);
}

static inline vec4 vec4_sub(vec4 a, vec4 b)
{
    return _mm_sub_ps(a, b);
}

static inline vec4 vec4_mul(vec4 a, vec4 b)
{
    return _mm_mul_ps(a, b);
}

static inline vec4 vec4_min(vec4 a, vec4 b)
{
    return _mm_min_ps(a, b);
}

static inline vec4 vec4_max(vec4 a, vec4 b)
{
    return _mm_max_ps(a, b);
}

/* a with lane 3 replaced by +0. */
static inline vec4 vec4_xyz0(vec4 a)
{
    return _mm_and_ps(a, _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0)));
}

/* cond ? a : b, without a branch. */
static inline vec4 vec4_select(int cond, vec4 a, vec4 b)
{
    vec4 mask = _mm_castsi128_ps(_mm_set1_epi32(-(int32_t)(cond != 0)));
    return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}

/* Truncation toward zero of each lane; lanes must be in int range. */
static inline void vec4_trunc(int32_t out[4], vec4 a)
{
    _mm_storeu_si128((__m128i *)(void *)out, _mm_cvttps_epi32(a));
}

/* Bit i set when lane i of a >= lane i of b (clear when either is NaN). */
static inline uint32_t vec4_ge_bits(vec4 a, vec4 b)
{
    return (uint32_t)_mm_movemask_ps(_mm_cmpge_ps(a, b));
}

/* Bit i set when lane i of a < lane i of b (clear when either is NaN). */
static inline uint32_t vec4_lt_bits(vec4 a, vec4 b)
{
    return (uint32_t)_mm_movemask_ps(_mm_cmplt_ps(a, b));
}

/* Bit i set when lane i of a != lane i of b (set when either is NaN). */
static inline uint32_t vec4_ne_bits(vec4 a, vec4 b)
{
    return (uint32_t)_mm_movemask_ps(_mm_cmpneq_ps(a, b));
}

/* Lanes 0..2 of a, b, c as columns: *x = (a0, b0, c0, -), *y = (a1, b1,
 * c1, -), *z = (a2, b2, c2, -); lane 3 unspecified. */
static inline void vec4_transpose3(vec4 a, vec4 b, vec4 c, vec4 *x, vec4 *y, vec4 *z)
{
    __m128 ab_lo = _mm_unpacklo_ps(a, b); /* a0 b0 a1 b1 */
    __m128 ab_hi = _mm_unpackhi_ps(a, b); /* a2 b2 a3 b3 */
    *x = _mm_movelh_ps(ab_lo, c);         /* a0 b0 c0 c1 */
    *y = _mm_shuffle_ps(ab_lo, c, _MM_SHUFFLE(3, 1, 3, 2));
    *z = _mm_shuffle_ps(ab_hi, c, _MM_SHUFFLE(3, 2, 1, 0));
}

/* Four 32-bit integers (the sorting keys of the small-node sweeps). */
typedef __m128i vec4i;

/* Per lane an integer whose signed order is the order of the floats
 * (build_float_order's key with its top bit flipped, so that signed
 * comparisons order it): u ^ 0x7fffffff for a negative float's bits u,
 * u otherwise. */
static inline vec4i vec4_order_key(vec4 a)
{
    __m128i u = _mm_castps_si128(a);
    __m128i neg = _mm_srai_epi32(u, 31);
    return _mm_xor_si128(u, _mm_and_si128(neg, _mm_set1_epi32(0x7fffffff)));
}

/* -1 in the lanes where a > b (signed), else 0. */
static inline vec4i vec4i_gt(vec4i a, vec4i b)
{
    return _mm_cmpgt_epi32(a, b);
}

static inline vec4i vec4i_add(vec4i a, vec4i b)
{
    return _mm_add_epi32(a, b);
}

static inline vec4i vec4i_sub(vec4i a, vec4i b)
{
    return _mm_sub_epi32(a, b);
}

static inline vec4i vec4i_splat(int32_t x)
{
    return _mm_set1_epi32(x);
}

static inline void vec4i_store(int32_t out[4], vec4i a)
{
    _mm_storeu_si128((__m128i *)(void *)out, a);
}

/* Per lane trunc(a) * 32 + base: the byte offset of entry trunc(a) of an
 * array of 32-byte records starting at byte base (the builders' bins).
 * Lanes must be in [0, 2^26) after truncation, base small. */
static inline void vec4_trunc_offset32(uint32_t out[4], vec4 a, const uint32_t base[4])
{
    __m128i i = _mm_slli_epi32(_mm_cvttps_epi32(a), 5);
    i = _mm_add_epi32(i, _mm_loadu_si128((const __m128i *)(const void *)base));
    _mm_storeu_si128((__m128i *)(void *)out, i);
}

/* Half the surface area of the box [lo, hi] (lanes 0..2), summed in the
 * order of aabb_half_area: (dx dy + dy dz) + dz dx. */
static inline float vec4_half_area(vec4 lo, vec4 hi)
{
    vec4 d = _mm_sub_ps(hi, lo);
    vec4 d_yzx = _mm_shuffle_ps(d, d, _MM_SHUFFLE(3, 0, 2, 1));
    vec4 p = _mm_mul_ps(d, d_yzx); /* dx dy, dy dz, dz dx, - */
    vec4 s = _mm_add_ss(p, _mm_shuffle_ps(p, p, _MM_SHUFFLE(1, 1, 1, 1)));
    s = _mm_add_ss(s, _mm_movehl_ps(p, p));
    return _mm_cvtss_f32(s);
}

#else

typedef struct {
    float v[4];
} vec4;

static inline vec4 vec4_load(const float p[4])
{
    vec4 r = {{p[0], p[1], p[2], p[3]}};
    return r;
}

static inline void vec4_store(float p[4], vec4 a)
{
    for (int i = 0; i < 4; i++)
        p[i] = a.v[i];
}

static inline vec4 vec4_set(float x, float y, float z, float w)
{
    vec4 r = {{x, y, z, w}};
    return r;
}

static inline vec4 vec4_splat(float x)
{
    vec4 r = {{x, x, x, x}};
    return r;
}

static inline vec4 vec4_add(vec4 a, vec4 b)
{
    for (int i = 0; i < 4; i++)
        a.v[i] = a.v[i] + b.v[i];
    return a;
}

static inline vec4 vec4_sub(vec4 a, vec4 b)
{
    for (int i = 0; i < 4; i++)
        a.v[i] = a.v[i] - b.v[i];
    return a;
}

static inline vec4 vec4_mul(vec4 a, vec4 b)
{
    for (int i = 0; i < 4; i++)
        a.v[i] = a.v[i] * b.v[i];
    return a;
}

static inline vec4 vec4_min(vec4 a, vec4 b)
{
    for (int i = 0; i < 4; i++)
        a.v[i] = a.v[i] < b.v[i] ? a.v[i] : b.v[i];
    return a;
}

static inline vec4 vec4_max(vec4 a, vec4 b)
{
    for (int i = 0; i < 4; i++)
        a.v[i] = a.v[i] > b.v[i] ? a.v[i] : b.v[i];
    return a;
}

static inline vec4 vec4_xyz0(vec4 a)
{
    a.v[3] = 0.0f;
    return a;
}

static inline vec4 vec4_select(int cond, vec4 a, vec4 b)
{
    return cond ? a : b;
}

static inline void vec4_trunc(int32_t out[4], vec4 a)
{
    for (int i = 0; i < 4; i++)
        out[i] = (int32_t)a.v[i];
}

typedef struct {
    int32_t v[4];
} vec4i;

static inline vec4i vec4_order_key(vec4 a)
{
    vec4i r;
    for (int i = 0; i < 4; i++) {
        uint32_t u;
        memcpy(&u, &a.v[i], sizeof(u));
        u ^= (u >> 31) ? 0x7fffffffu : 0u;
        memcpy(&r.v[i], &u, sizeof(u));
    }
    return r;
}

static inline vec4i vec4i_gt(vec4i a, vec4i b)
{
    for (int i = 0; i < 4; i++)
        a.v[i] = a.v[i] > b.v[i] ? -1 : 0;
    return a;
}

static inline vec4i vec4i_add(vec4i a, vec4i b)
{
    for (int i = 0; i < 4; i++)
        a.v[i] = (int32_t)((uint32_t)a.v[i] + (uint32_t)b.v[i]);
    return a;
}

static inline vec4i vec4i_sub(vec4i a, vec4i b)
{
    for (int i = 0; i < 4; i++)
        a.v[i] = (int32_t)((uint32_t)a.v[i] - (uint32_t)b.v[i]);
    return a;
}

static inline vec4i vec4i_splat(int32_t x)
{
    vec4i r = {{x, x, x, x}};
    return r;
}

static inline void vec4i_store(int32_t out[4], vec4i a)
{
    for (int i = 0; i < 4; i++)
        out[i] = a.v[i];
}

static inline uint32_t vec4_lt_bits(vec4 a, vec4 b)
{
    uint32_t bits = 0;
    for (int i = 0; i < 4; i++)
        bits |= (uint32_t)(a.v[i] < b.v[i]) << i;
    return bits;
}

static inline uint32_t vec4_ne_bits(vec4 a, vec4 b)
{
    uint32_t bits = 0;
    for (int i = 0; i < 4; i++)
        bits |= (uint32_t)(a.v[i] != b.v[i]) << i;
    return bits;
}

static inline void vec4_transpose3(vec4 a, vec4 b, vec4 c, vec4 *x, vec4 *y, vec4 *z)
{
    vec4 r[3];
    for (int i = 0; i < 3; i++) {
        r[i].v[0] = a.v[i];
        r[i].v[1] = b.v[i];
        r[i].v[2] = c.v[i];
        r[i].v[3] = 0.0f;
    }
    *x = r[0];
    *y = r[1];
    *z = r[2];
}

static inline uint32_t vec4_ge_bits(vec4 a, vec4 b)
{
    uint32_t bits = 0;
    for (int i = 0; i < 4; i++)
        bits |= (uint32_t)(a.v[i] >= b.v[i]) << i;
    return bits;
}

static inline void vec4_trunc_offset32(uint32_t out[4], vec4 a, const uint32_t base[4])
{
    for (int i = 0; i < 4; i++)
        out[i] = (uint32_t)(int32_t)a.v[i] * 32u + base[i];
}

static inline float vec4_half_area(vec4 lo, vec4 hi)
{
    float dx = hi.v[0] - lo.v[0];
    float dy = hi.v[1] - lo.v[1];
    float dz = hi.v[2] - lo.v[2];
    return dx * dy + dy * dz + dz * dx;
}

#endif

/* Half the surface areas of three boxes at once, box j in lane j of the
 * coordinate columns: (dx dy + dy dz) + dz dx per lane, vec4_half_area's
 * operations in its order. */
static inline vec4 vec4_half_area3(vec4 lox, vec4 loy, vec4 loz, vec4 hix, vec4 hiy, vec4 hiz)
{
    vec4 dx = vec4_sub(hix, lox);
    vec4 dy = vec4_sub(hiy, loy);
    vec4 dz = vec4_sub(hiz, loz);
    return vec4_add(vec4_add(vec4_mul(dx, dy), vec4_mul(dy, dz)), vec4_mul(dz, dx));
}

#endif
