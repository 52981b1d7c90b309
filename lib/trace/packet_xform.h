/* SPDX-License-Identifier: Apache-2.0 */
/*
 * packet_xform.h - a packet's rays in a transformed instance's object
 * space, set up, for the AVX2 and AVX-512 tables (kernels.h
 * packet_xform), included by their translation units after
 * packet_init.h with TRACE_PACKET_XFORM naming the function.
 *
 * Each ray is trace_scene_object_ray's (scene_traverse.c) bit for bit:
 * the origin and direction converted to double (exact), each component
 * the same products and sums in the same order as to_object_space,
 * ((m0 * x + m1 * y) + m2 * z) + m3, every operation an IEEE double
 * operation (this file's translation units are built with
 * -ffp-contract=off, so no product is fused into an add), rounded to
 * float once as the (float) cast rounds (cvtpd2ps, the same MXCSR
 * rounding as cvtsd2ss); the direction refused where usable_direction
 * refuses it (a component infinite or NaN, or all three zero); and the
 * set-up packet_init_lanes gives, which is trace_ray_init's.  Where
 * trace_scene_object_ray hands the world ray on (the transformed ray
 * equal to the world ray bit for bit), that world ray is trace_ray_init
 * of the same origin, direction and tmin: the same struct.
 *
 * The twelve products and nine sums are done four rays a 256-bit
 * register instead of ray by ray: on the BART robots, whose every moving
 * part is a transformed instance, trace_scene_object_ray was about 180
 * instructions a ray and instance, this about 50.  The AVX-512 table
 * runs the same 256-bit code (with its 32 registers, fewer spills): no
 * other kernel uses 512-bit registers, and on Intel's AVX-512 cores
 * 512-bit floating-point work lowers the core's clock for a while after
 * it (Intel 64 and IA-32 Architectures Optimization Reference Manual,
 * on the AVX-512 frequency licences), which could cost more than the
 * few instructions a packet 512-bit lanes would save (not measured here;
 * the first version of this file took eight rays a 512-bit register).
 */
#if !defined(TRACE_PACKET_XFORM)
#error "define TRACE_PACKET_XFORM before including packet_xform.h"
#endif
#if !defined(RT_TRACE_PACKET_INIT_LANES)
#error "include packet_init.h (packet_init_lanes) before packet_xform.h"
#endif

#include <immintrin.h>

#include "trace/packet.h"

/*
 * The rays of mask `rays` (org[r], dir[r], tmin[r]; all TRACE_PACKET
 * entries of each array are read, those of the other rays ignored) in
 * the object space of the row-major 3x4 world-to-object matrix m
 * (trace_instance.world_to_object), set up into o_ray[r] for each ray
 * whose transformed direction can be traced; returns the mask of those
 * rays, as trace_scene_object_ray's returns ray by ray.
 */
unsigned TRACE_PACKET_XFORM(const double m[12], const float (*org)[3], const float (*dir)[3],
                            const float *tmin, unsigned rays,
                            struct trace_ray o_ray[TRACE_PACKET]);
unsigned TRACE_PACKET_XFORM(const double m[12], const float (*org)[3], const float (*dir)[3],
                            const float *tmin, unsigned rays,
                            struct trace_ray o_ray[TRACE_PACKET])
{
    __m256 o[3], d[3], ov[3], dv[3];
    /* Across lanes as packet_init_soa3 (packet_init.h) puts them. */
    packet_init_soa3(org, o);
    packet_init_soa3(dir, d);
    /* Four rays a register, the low and high halves in turn. */
    __m128 oh[2][3], dh[2][3];
    for (int h = 0; h < 2; h++) {
        __m256d ok[3], dk[3];
        for (int k = 0; k < 3; k++) {
            ok[k] = _mm256_cvtps_pd(h ? _mm256_extractf128_ps(o[k], 1)
                                      : _mm256_castps256_ps128(o[k]));
            dk[k] = _mm256_cvtps_pd(h ? _mm256_extractf128_ps(d[k], 1)
                                      : _mm256_castps256_ps128(d[k]));
        }
        for (int r = 0; r < 3; r++) {
            const __m256d m0 = _mm256_set1_pd(m[4 * r]), m1 = _mm256_set1_pd(m[4 * r + 1]);
            const __m256d m2 = _mm256_set1_pd(m[4 * r + 2]), m3 = _mm256_set1_pd(m[4 * r + 3]);
            const __m256d po = _mm256_add_pd(
                _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(m0, ok[0]), _mm256_mul_pd(m1, ok[1])),
                              _mm256_mul_pd(m2, ok[2])),
                m3);
            const __m256d pd = _mm256_add_pd(
                _mm256_add_pd(_mm256_mul_pd(m0, dk[0]), _mm256_mul_pd(m1, dk[1])),
                _mm256_mul_pd(m2, dk[2]));
            oh[h][r] = _mm256_cvtpd_ps(po);
            dh[h][r] = _mm256_cvtpd_ps(pd);
        }
    }
    for (int r = 0; r < 3; r++) {
        ov[r] = _mm256_insertf128_ps(_mm256_castps128_ps256(oh[0][r]), oh[1][r], 1);
        dv[r] = _mm256_insertf128_ps(_mm256_castps128_ps256(dh[0][r]), dh[1][r], 1);
    }
    /* usable_direction: every component finite (|d| < inf, which a NaN
     * fails) and one of them not zero. */
    const __m256 sign = _mm256_set1_ps(-0.0f);
    const __m256 inf = _mm256_set1_ps(INFINITY);
    const __m256 zero = _mm256_setzero_ps();
    __m256 finite = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
    __m256 nonzero = zero;
    for (int k = 0; k < 3; k++) {
        const __m256 a = _mm256_andnot_ps(sign, dv[k]);
        finite = _mm256_and_ps(finite, _mm256_cmp_ps(a, inf, _CMP_LT_OQ));
        nonzero = _mm256_or_ps(nonzero, _mm256_cmp_ps(a, zero, _CMP_NEQ_UQ));
    }
    const unsigned live =
        (unsigned)_mm256_movemask_ps(_mm256_and_ps(finite, nonzero)) & rays;
    if (live)
        packet_init_lanes(ov[0], ov[1], ov[2], dv[0], dv[1], dv[2], _mm256_loadu_ps(tmin), live,
                          o_ray, NULL);
    return live;
}
