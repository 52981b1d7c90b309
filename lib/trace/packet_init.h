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

/* The set-up's sixteen fields from the rays across lanes (o0-o2 the
 * origins' x, y, z, d0-d2 the directions', tv the tmins: ray r in lane
 * r): f[TRI8_F_...] lane r is the field of trace_ray_init's ray r, bit for
 * bit (kx, ky, kz as integer bits), the layout the eight-ray test and the
 * packet walk read (packet_tri8.h, tri8_lanes_load).  A lane of a ray left
 * out may hold any direction (a zero or a NaN divides without trapping).
 * For packet_init_lanes, and for the packet walk's entries that take the
 * caller's arrays (packet_wide.h, packet_run), which keep the fields in
 * the lanes and never store the rays' structs unless a per-ray step asks
 * for them. */
#if !defined(RT_TRACE_PACKET_INIT_LANES)
#define RT_TRACE_PACKET_INIT_LANES
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_init_fields(__m256 o0, __m256 o1, __m256 o2, __m256 d0, __m256 d1,
                                      __m256 d2, __m256 tv, __m256 f[TRI8_F_COUNT])
{
    /* The rows by value, not as arrays: GCC copied arrays passed to this
     * function through the stack, 21 instructions more a packet. */
    const __m256 dv[3] = {d0, d1, d2};
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
    f[TRI8_F_ORG] = o0;
    f[TRI8_F_ORG + 1] = o1;
    f[TRI8_F_ORG + 2] = o2;
    f[TRI8_F_DIR] = d0;
    f[TRI8_F_DIR + 1] = d1;
    f[TRI8_F_DIR + 2] = d2;
    f[TRI8_F_INV] = inv[0];
    f[TRI8_F_INV + 1] = inv[1];
    f[TRI8_F_INV + 2] = inv[2];
    f[TRI8_F_TMIN] = tv;
    f[TRI8_F_K] = _mm256_castsi256_ps(kx);
    f[TRI8_F_K + 1] = _mm256_castsi256_ps(ky);
    f[TRI8_F_K + 2] = _mm256_castsi256_ps(kz);
    f[TRI8_F_S] = sx;
    f[TRI8_F_S + 1] = sy;
    f[TRI8_F_S + 2] = sz;
}

/* The set-up's fields (packet_init_fields) as the rays' structs: rays[r]
 * for each ray of `live` (all eight with live 0xff), by two 8 x 8
 * transposes (packet_tri8.h's tri8_transpose8, whose layout check is the
 * struct's: sixteen floats, fields 0-7 org, dir, inv_dir[0..1], fields
 * 8-15 inv_dir[2], tmin, kx, ky, kz, sx, sy, sz) and each ray stored as
 * two 32-byte halves. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_init_store(const __m256 f[TRI8_F_COUNT], unsigned live,
                                     struct trace_ray rays[TRACE_PACKET])
{
    /* The rows as fresh arrays of values (GCC split f itself into
     * 64-bit pieces through the stack when handed f + 8). */
    const __m256 lo_rows[8] = {f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7]};
    const __m256 hi_rows[8] = {f[8], f[9], f[10], f[11], f[12], f[13], f[14], f[15]};
    __m256 lo[8], hi[8];
    tri8_transpose8(lo_rows, lo);
    tri8_transpose8(hi_rows, hi);
    if (live == 0xffu) {
        /* A full packet: each ray's two halves at constant offsets (no
         * loop over the bits, no transposed rows through the stack). */
        float *out = (float *)(void *)rays;
        for (int r = 0; r < 8; r++) {
            _mm256_storeu_ps(out + 16 * r, lo[r]);
            _mm256_storeu_ps(out + 16 * r + 8, hi[r]);
        }
        return;
    }
    for (unsigned m = live; m; m &= m - 1u) {
        const int r = __builtin_ctz(m);
        float *out = (float *)(void *)&rays[r];
        _mm256_storeu_ps(out, lo[r]);
        _mm256_storeu_ps(out + 8, hi[r]);
    }
}

/* The set-up from the rays across lanes, for TRACE_PACKET_INIT and the
 * object-space rays of packet_xform.h: rays[r] for each ray of `live`
 * (packet_init_fields, packet_init_store), and, when top is not NULL,
 * top's tmin, org and inv_dir lanes. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_init_lanes(__m256 o0, __m256 o1, __m256 o2, __m256 d0, __m256 d1,
                                     __m256 d2, __m256 tv, unsigned live,
                                     struct trace_ray rays[TRACE_PACKET],
                                     struct trace_top_rays *top)
{
    __m256 f[TRI8_F_COUNT];
    packet_init_fields(o0, o1, o2, d0, d1, d2, tv, f);
    /* The arrays across lanes for the top level's box tests (zeros in the
     * lanes of the rays left out, as packet.h asks). */
    if (top) {
        const __m256 keep = _mm256_castsi256_ps(_mm256_cmpgt_epi32(
            _mm256_and_si256(_mm256_set1_epi32((int)live),
                             _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128)),
            _mm256_setzero_si256()));
        _mm256_store_ps(top->tmin, tv);
        for (int k = 0; k < 3; k++) {
            _mm256_store_ps(top->org[k], f[TRI8_F_ORG + k]);
            _mm256_store_ps(top->inv_dir[k], _mm256_and_ps(f[TRI8_F_INV + k], keep));
        }
    }
    packet_init_store(f, live, rays);
}

/* The rays of `live` across lanes from the caller's arrays (org[r],
 * dir[r], tmin[r]): ov, dv and *tv, ray r in lane r.  A lane of a ray
 * left out holds, with copy_first, the lowest live ray's values (the
 * packet walk's lanes: tri8_lanes_load's rule, so that no range over the
 * lanes widens), else an origin of zeros, a direction of ones and a tmin
 * of 0 (the top level's lanes of rays not in the walk hold zeros). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_init_load(const float (*org)[3], const float (*dir)[3],
                                    const float *tmin, unsigned live, int copy_first,
                                    __m256 ov[3], __m256 dv[3], __m256 *tv)
{
    if (live == 0xffu) {
        /* A full packet (every camera packet of a tile): the same bits
         * by three loads and a 3 x 8 transpose per array. */
        packet_init_soa3(org, ov);
        packet_init_soa3(dir, dv);
        *tv = _mm256_loadu_ps(tmin);
        return;
    }
    float o[3][8] __attribute__((aligned(32)));
    float d[3][8] __attribute__((aligned(32)));
    float t[8] __attribute__((aligned(32)));
    const unsigned first = live ? (unsigned)__builtin_ctz(live) : 0u;
    for (unsigned r = 0; r < 8; r++) {
        const int in = live >> r & 1u;
        const unsigned src = in ? r : first;
        for (int k = 0; k < 3; k++) {
            o[k][r] = in || copy_first ? org[src][k] : 0.0f;
            d[k][r] = in || copy_first ? dir[src][k] : 1.0f;
        }
        t[r] = in || copy_first ? tmin[src] : 0.0f;
    }
    for (int k = 0; k < 3; k++) {
        ov[k] = _mm256_load_ps(o[k]);
        dv[k] = _mm256_load_ps(d[k]);
    }
    *tv = _mm256_load_ps(t);
}

/* trace_scene_plain_class's tests on the bits for the rays of `live`,
 * eight a register (packet.h, struct trace_packet_plain), by reductions
 * over the six components instead of a test per component.  The
 * magnitudes m (the sign bit cleared) are non-negative as signed
 * integers, so their greatest says whether all are finite (below the
 * infinity's bits) and their least whether none is zero (above 0); a
 * -0.0, the bits 0x80000000, is the least signed integer there is, so the
 * least of the components' own bits says whether one is -0.0; the
 * direction is zero when the greatest of its magnitudes is 0.  The same
 * classes as the tests one by one: about 49 instructions a packet
 * instead of 96 (AVX2, callgrind: docs/performance-log.md, pk5). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_plain_masks(const __m256 ov[3], const __m256 dv[3], unsigned live,
                                      struct trace_packet_plain *plain)
{
    const __m256i magnitude = _mm256_set1_epi32(0x7fffffff);
    __m256i m[6], v[6];
    for (int k = 0; k < 3; k++) {
        v[k] = _mm256_castps_si256(ov[k]);
        v[k + 3] = _mm256_castps_si256(dv[k]);
    }
    for (int k = 0; k < 6; k++)
        m[k] = _mm256_and_si256(v[k], magnitude);
    const __m256i max_o = _mm256_max_epi32(_mm256_max_epi32(m[0], m[1]), m[2]);
    const __m256i max_d = _mm256_max_epi32(_mm256_max_epi32(m[3], m[4]), m[5]);
    __m256i min_m = m[0], min_v = v[0];
    for (int k = 1; k < 6; k++) {
        min_m = _mm256_min_epi32(min_m, m[k]);
        min_v = _mm256_min_epi32(min_v, v[k]);
    }
    const __m256i inf = _mm256_set1_epi32(0x7f800000);
    const __m256i zero = _mm256_setzero_si256();
    const __m256i finite_org = _mm256_cmpgt_epi32(inf, max_o);
    const __m256i finite = _mm256_cmpgt_epi32(inf, _mm256_max_epi32(max_o, max_d));
    const __m256i nonzero = _mm256_and_si256(finite, _mm256_cmpgt_epi32(min_m, zero));
    const __m256i neg_zero = _mm256_cmpeq_epi32(min_v, _mm256_set1_epi32((int)0x80000000u));
    const __m256i dir_zero = _mm256_cmpeq_epi32(max_d, zero);
    const __m256i exact = _mm256_andnot_si256(_mm256_or_si256(neg_zero, dir_zero), finite);
    plain->zeros = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(nonzero)) & live;
    plain->exact = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(exact)) & live;
    plain->finite_org = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(finite_org)) & live;
}
#endif

void TRACE_PACKET_INIT(const float (*org)[3], const float (*dir)[3], const float *tmin,
                       unsigned live, struct trace_ray rays[TRACE_PACKET],
                       struct trace_top_rays *top, struct trace_packet_plain *plain);
void TRACE_PACKET_INIT(const float (*org)[3], const float (*dir)[3], const float *tmin,
                       unsigned live, struct trace_ray rays[TRACE_PACKET],
                       struct trace_top_rays *top, struct trace_packet_plain *plain)
{
    /* The live rays across lanes; the others hold an origin of zeros and
     * a direction of ones, so that nothing below divides by zero. */
    __m256 ov[3], dv[3], tv;
    packet_init_load(org, dir, tmin, live, 0, ov, dv, &tv);
    if (plain)
        packet_plain_masks(ov, dv, live, plain);
    packet_init_lanes(ov[0], ov[1], ov[2], dv[0], dv[1], dv[2], tv, live, rays, top);
}
