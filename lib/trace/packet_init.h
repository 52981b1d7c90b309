/* SPDX-License-Identifier: Apache-2.0 */
/*
 * packet_init.h - a packet's rays set up eight at a time for the AVX2 and
 * AVX-512 tables (kernels.h packet_init, packet.h trace_packet_init_fn),
 * included by their translation units with TRACE_PACKET_INIT naming the
 * function.
 *
 * Each ray is trace_ray_init's ray bit for bit: the same comparisons
 * choose kz (the axis of the largest |dir|, the first on ties: |d1| >
 * |d0|, then |d2| against the larger), kx and ky follow it cyclically
 * and swap for a negative d[kz] (Woop, Benthin and Wald 2013, sec. 3);
 * 1 / dir, -d[kx] / d[kz] and -d[ky] / d[kz] are the same IEEE divisions,
 * eight lanes a divps instead of four and one divss a ray.  The two-level
 * packet walk (packet_scene.c) set its rays up one by one, about 120
 * instructions a ray with the arrays across lanes; here the fields are
 * computed across the rays and turned into the rays' structs by two 8 x 8
 * transposes.
 */
#if !defined(TRACE_PACKET_INIT)
#error "define TRACE_PACKET_INIT before including packet_init.h"
#endif

#include <immintrin.h>

#include "trace/packet.h"
#include "trace/packet_tri8.h"

#if !defined(RT_TRACE_PACKET_INIT_SOA3)
#define RT_TRACE_PACKET_INIT_SOA3
/* Eight rays' 3-vectors (v[r][k], 24 consecutive floats) across lanes:
 * out[k] lane r = v[r][k], bit for bit.  Float 3r + k lies in row
 * (3r + k) / 8 at position (3r + k) % 8; for one k the three rows' sets
 * of positions are disjoint, so two blends gather the eight values into
 * one register and a lane permutation puts ray r in lane r. */
static inline void packet_init_soa3(const float (*v)[3], __m256 out[3])
{
    const float *f = &v[0][0];
    const __m256 r0 = _mm256_loadu_ps(f), r1 = _mm256_loadu_ps(f + 8),
                 r2 = _mm256_loadu_ps(f + 16);
    /* x: rows 0, 1, 2 at positions {0, 3, 6}, {1, 4, 7}, {2, 5}. */
    const __m256 x = _mm256_blend_ps(_mm256_blend_ps(r0, r1, 0x92), r2, 0x24);
    /* y: {1, 4, 7}, {2, 5}, {0, 3, 6}. */
    const __m256 y = _mm256_blend_ps(_mm256_blend_ps(r0, r1, 0x24), r2, 0x49);
    /* z: {2, 5}, {0, 3, 6}, {1, 4, 7}. */
    const __m256 z = _mm256_blend_ps(_mm256_blend_ps(r0, r1, 0x49), r2, 0x92);
    out[0] = _mm256_permutevar8x32_ps(x, _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5));
    out[1] = _mm256_permutevar8x32_ps(y, _mm256_setr_epi32(1, 4, 7, 2, 5, 0, 3, 6));
    out[2] = _mm256_permutevar8x32_ps(z, _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7));
}
#endif

/* The set-up from the rays across lanes (o0-o2 the origins' x, y, z,
 * d0-d2 the directions', tv the tmins: ray r in lane r), for
 * TRACE_PACKET_INIT and the object-space rays of packet_xform.h:
 * rays[r] for each ray of `live`, and, when top is not NULL, top's tmin,
 * org and inv_dir lanes.  A lane of a ray left out may hold any
 * direction (a zero or a NaN divides without trapping: the lane is not
 * stored).  The two transposes (packet_tri8.h's tri8_transpose8, whose
 * layout check is the struct's: sixteen floats, fields 0-7 org, dir,
 * inv_dir[0..1], fields 8-15 inv_dir[2], tmin, kx, ky, kz, sx, sy, sz)
 * store each ray as two 32-byte halves. */
#if !defined(RT_TRACE_PACKET_INIT_LANES)
#define RT_TRACE_PACKET_INIT_LANES
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_init_lanes(__m256 o0, __m256 o1, __m256 o2, __m256 d0, __m256 d1,
                                     __m256 d2, __m256 tv, unsigned live,
                                     struct trace_ray rays[TRACE_PACKET],
                                     struct trace_top_rays *top)
{
    /* The rows by value, not as arrays: GCC copied arrays passed to this
     * function through the stack, 21 instructions more a packet. */
    const __m256 ov[3] = {o0, o1, o2}, dv[3] = {d0, d1, d2};
    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256 sign = _mm256_set1_ps(-0.0f);
    __m256 inv[3], a[3];
    for (int k = 0; k < 3; k++) {
        inv[k] = _mm256_div_ps(one, dv[k]);
        a[k] = _mm256_andnot_ps(sign, dv[k]);
    }
    /* kz as trace_ray_init chooses it: 1 when |d1| > |d0|, then 2 when
     * |d2| exceeds the larger of those. */
    const __m256 c1 = _mm256_cmp_ps(a[1], a[0], _CMP_GT_OQ);
    const __m256 c2 = _mm256_cmp_ps(a[2], _mm256_blendv_ps(a[0], a[1], c1), _CMP_GT_OQ);
    const __m256 z1 = _mm256_andnot_ps(c2, c1); /* kz == 1 */
    const __m256 z0 = _mm256_andnot_ps(_mm256_or_ps(c1, c2), _mm256_castsi256_ps(
                                                                  _mm256_set1_epi32(-1)));
#define PACKET_INIT_SEL3(v0, v1, v2) _mm256_blendv_ps(_mm256_blendv_ps(v2, v1, z1), v0, z0)
    const __m256 dz = PACKET_INIT_SEL3(dv[0], dv[1], dv[2]);
    const __m256 next = PACKET_INIT_SEL3(dv[1], dv[2], dv[0]); /* d[(kz + 1) % 3] */
    const __m256 after = PACKET_INIT_SEL3(dv[2], dv[0], dv[1]); /* d[(kz + 2) % 3] */
    const __m256 sz = PACKET_INIT_SEL3(inv[0], inv[1], inv[2]);
#undef PACKET_INIT_SEL3
    const __m256 neg = _mm256_cmp_ps(dz, _mm256_setzero_ps(), _CMP_LT_OQ);
    const __m256 dkx = _mm256_blendv_ps(next, after, neg);
    const __m256 dky = _mm256_blendv_ps(after, next, neg);
    const __m256 sx = _mm256_div_ps(_mm256_xor_ps(dkx, sign), dz);
    const __m256 sy = _mm256_div_ps(_mm256_xor_ps(dky, sign), dz);
    /* kx, ky, kz as integers: kz = 2 c2 + (c1 and not c2); kx, ky from
     * trace_ray_init_single's tables, indexed by 2 (2 kz + negative). */
    const __m256i kz = _mm256_sub_epi32(
        _mm256_setzero_si256(),
        _mm256_add_epi32(_mm256_add_epi32(_mm256_castps_si256(c2), _mm256_castps_si256(c2)),
                         _mm256_castps_si256(z1)));
    const __m256i i = _mm256_slli_epi32(
        _mm256_sub_epi32(_mm256_slli_epi32(kz, 1), _mm256_castps_si256(neg)), 1);
    const __m256i kx = _mm256_and_si256(_mm256_srlv_epi32(_mm256_set1_epi32(0x429), i),
                                        _mm256_set1_epi32(3));
    const __m256i ky = _mm256_and_si256(_mm256_srlv_epi32(_mm256_set1_epi32(0x186), i),
                                        _mm256_set1_epi32(3));
    /* The arrays across lanes for the top level's box tests (zeros in the
     * lanes of the rays left out, as packet.h asks). */
    if (top) {
        const __m256 keep = _mm256_castsi256_ps(_mm256_cmpgt_epi32(
            _mm256_and_si256(_mm256_set1_epi32((int)live),
                             _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128)),
            _mm256_setzero_si256()));
        _mm256_store_ps(top->tmin, tv);
        for (int k = 0; k < 3; k++) {
            _mm256_store_ps(top->org[k], ov[k]);
            _mm256_store_ps(top->inv_dir[k], _mm256_and_ps(inv[k], keep));
        }
    }
    const __m256 lo_rows[8] = {ov[0], ov[1], ov[2], dv[0], dv[1], dv[2], inv[0], inv[1]};
    const __m256 hi_rows[8] = {inv[2],
                    tv,
                    _mm256_castsi256_ps(kx),
                    _mm256_castsi256_ps(ky),
                    _mm256_castsi256_ps(kz),
                    sx,
                    sy,
                    sz};
    __m256 lo[8], hi[8];
    tri8_transpose8(lo_rows, lo);
    tri8_transpose8(hi_rows, hi);
    if (live == 0xffu) {
        /* A full packet: each ray's two halves at constant offsets (no
         * loop over the bits, no transposed rows through the stack). */
        float *f = (float *)(void *)rays;
        for (int r = 0; r < 8; r++) {
            _mm256_storeu_ps(f + 16 * r, lo[r]);
            _mm256_storeu_ps(f + 16 * r + 8, hi[r]);
        }
        return;
    }
    for (unsigned m = live; m; m &= m - 1u) {
        const int r = __builtin_ctz(m);
        float *f = (float *)(void *)&rays[r];
        _mm256_storeu_ps(f, lo[r]);
        _mm256_storeu_ps(f + 8, hi[r]);
    }
}

/* trace_scene_plain_class's tests on the bits for the rays of `live`,
 * eight a register (packet.h, struct trace_packet_plain): a magnitude m
 * is finite when below the infinity's bits and also not zero when m - 1
 * is below FLT_MAX's, unsigned (the sign bit flipped for the signed
 * compare). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_plain_masks(const __m256 ov[3], const __m256 dv[3], unsigned live,
                                      struct trace_packet_plain *plain)
{
    const __m256i magnitude = _mm256_set1_epi32(0x7fffffff);
    const __m256i sign_bit = _mm256_set1_epi32((int)0x80000000u);
    const __m256i inf = _mm256_set1_epi32(0x7f800000);
    const __m256i below = _mm256_set1_epi32((int)(0x7f7fffffu ^ 0x80000000u));
    const __m256i ones = _mm256_set1_epi32(1);
    __m256i finite_org = _mm256_set1_epi32(-1), finite = finite_org, nonzero = finite_org;
    __m256i neg_zero = _mm256_setzero_si256(), dir_zero = finite_org;
    for (int k = 0; k < 6; k++) {
        const __m256i v = _mm256_castps_si256(k < 3 ? ov[k] : dv[k - 3]);
        const __m256i m = _mm256_and_si256(v, magnitude);
        const __m256i fin = _mm256_cmpgt_epi32(inf, m);
        if (k < 3)
            finite_org = _mm256_and_si256(finite_org, fin);
        else
            dir_zero = _mm256_and_si256(dir_zero, _mm256_cmpeq_epi32(m, _mm256_setzero_si256()));
        finite = _mm256_and_si256(finite, fin);
        nonzero = _mm256_and_si256(
            nonzero,
            _mm256_cmpgt_epi32(below, _mm256_xor_si256(_mm256_sub_epi32(m, ones), sign_bit)));
        neg_zero = _mm256_or_si256(neg_zero, _mm256_cmpeq_epi32(v, sign_bit));
    }
    const __m256i exact = _mm256_andnot_si256(_mm256_or_si256(neg_zero, dir_zero), finite);
    plain->zeros = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(nonzero)) & live;
    plain->exact = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(exact)) & live;
    plain->finite_org = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(finite_org)) & live;
}
#endif

static void TRACE_PACKET_INIT(const float (*org)[3], const float (*dir)[3], const float *tmin,
                              unsigned live, struct trace_ray rays[TRACE_PACKET],
                              struct trace_top_rays *top, struct trace_packet_plain *plain)
{
    /* The live rays across lanes; the others hold an origin of zeros and
     * a direction of ones, so that nothing below divides by zero. */
    __m256 ov[3], dv[3], tv;
    if (live == 0xffu) {
        /* A full packet (every camera packet of a tile): the same bits
         * by three loads and a 3 x 8 transpose per array. */
        packet_init_soa3(org, ov);
        packet_init_soa3(dir, dv);
        tv = _mm256_loadu_ps(tmin);
    } else {
        float o[3][8] __attribute__((aligned(32)));
        float d[3][8] __attribute__((aligned(32)));
        float t[8] __attribute__((aligned(32)));
        for (int r = 0; r < 8; r++) {
            const int in = live >> r & 1u;
            for (int k = 0; k < 3; k++) {
                o[k][r] = in ? org[r][k] : 0.0f;
                d[k][r] = in ? dir[r][k] : 1.0f;
            }
            t[r] = in ? tmin[r] : 0.0f;
        }
        for (int k = 0; k < 3; k++) {
            ov[k] = _mm256_load_ps(o[k]);
            dv[k] = _mm256_load_ps(d[k]);
        }
        tv = _mm256_load_ps(t);
    }
    packet_plain_masks(ov, dv, live, plain);
    packet_init_lanes(ov[0], ov[1], ov[2], dv[0], dv[1], dv[2], tv, live, rays, top);
}
