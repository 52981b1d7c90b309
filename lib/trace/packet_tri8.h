/* SPDX-License-Identifier: Apache-2.0 */
/*
 * packet_tri8.h - the watertight triangle test (intersect.h's
 * isect_triangle) of one triangle against the eight rays of a packet,
 * ray r in AVX lane r (Wald, Slusallek, Benthin and Wagner 2001 sec. 4;
 * Benthin, Wald, Woop, Ernst and Mark 2012), for the packet walk's
 * leaves (packet_wide.h); included by the AVX translation units only.
 *
 * Same answers as isect_triangle ray by ray, bit for bit.  The float part
 * is intersect_tri4.h's filter with the lanes over rays instead of over
 * triangles: per lane the same IEEE single operations in the same order
 * (-ffp-contract=off, separate multiplies and adds), minps/maxps where
 * isect_triangle has isect_min/isect_max, and isect_slab's choice of the
 * near end by `inv < 0` as a blend on that comparison per lane.  A lane
 * it rejects is one isect_triangle rejects.  The rest of
 * isect_triangle_finish is carried on in the lanes too for the common
 * case, in double where it is double: the squared normal and longest
 * edge depend on the triangle only (computed once per triangle, with
 * finish's own expressions, and only when a lane needs them; the
 * zero-area test is the packet's NaN lane, bvh4_layout.h); per lane, the
 * sliver test, the plane distance num / den (two halves of four doubles,
 * only those with a candidate lane; the same
 * operations in the same order; a correctly rounded division and
 * conversion to float are the same in a lane as in a scalar register),
 * the clamp into the box interval, the range test and the barycentrics.
 * A lane that needs anything else goes to the scalar isect_triangle with
 * the same limit, which decides it itself: an edge function of exactly 0
 * (the paper's sec. 4 double fallback), a sliver (closest approach to an
 * edge), a plane parallel to the ray or a NaN distance (the float t).
 *
 * The rays of a packet share the triangle's vertex permutation only when
 * they share kx, ky, kz (the dominant axis of the direction and its
 * sign); the packet walk gives this test the rays that share the first
 * ray's, and tests the others with the single walk's leaf.
 */
#ifndef RT_TRACE_PACKET_TRI8_H
#define RT_TRACE_PACKET_TRI8_H

#include <immintrin.h>
#include <stddef.h>

#include "trace/bvh4_layout.h"
#include "trace/intersect.h"
#include "trace/tri8_shear.h"

/* The per-lane ray constants of the eight-ray test; a lane outside the
 * test's rays holds values never read into an answer. */
struct tri8_rays {
    __m256 org_x, org_y, org_z; /* org[kx], org[ky], org[kz] */
    __m256 sx, sy, sz;
    __m256 inv_x, inv_y;        /* inv_dir[kx], inv_dir[ky] */
    __m256 neg_x, neg_y;        /* all ones where inv_x < 0, inv_y < 0 (isect_slab) */
    __m256 tmin;
    __m256d org_d[3][2];        /* org[0..2] in double, lanes 0-3 and 4-7 */
    __m256d dir_d[3][2];        /* dir[0..2] in double */
    int kx, ky, kz;
};

/* A struct trace_ray is 16 floats (kx, ky, kz as int bits): the index of
 * each field among them, for the rays' fields in the lanes
 * (tri8_lanes_load). */
enum {
    TRI8_F_ORG = 0,  /* org[0..2] */
    TRI8_F_DIR = 3,  /* dir[0..2] */
    TRI8_F_INV = 6,  /* inv_dir[0..2] */
    TRI8_F_TMIN = 9,
    TRI8_F_K = 10,   /* kx, ky, kz */
    TRI8_F_S = 13,   /* sx, sy, sz */
    TRI8_F_COUNT = 16
};
typedef char tri8_ray_is_16_floats[sizeof(struct trace_ray) == TRI8_F_COUNT * sizeof(float) &&
                                           offsetof(struct trace_ray, dir) == TRI8_F_DIR * 4 &&
                                           offsetof(struct trace_ray, inv_dir) == TRI8_F_INV * 4 &&
                                           offsetof(struct trace_ray, tmin) == TRI8_F_TMIN * 4 &&
                                           offsetof(struct trace_ray, kx) == TRI8_F_K * 4 &&
                                           offsetof(struct trace_ray, kz) == (TRI8_F_K + 2) * 4 &&
                                           offsetof(struct trace_ray, sx) == TRI8_F_S * 4 &&
                                           offsetof(struct trace_ray, sz) == (TRI8_F_S + 2) * 4
                                       ? 1
                                       : -1];

/* An 8 x 8 transpose of floats: row r of in becomes lane r of every out
 * (unpack, shuffle and 128-bit permute, three rounds of eight). */
static inline void tri8_transpose8(const __m256 in[8], __m256 out[8])
{
    const __m256 t0 = _mm256_unpacklo_ps(in[0], in[1]), t1 = _mm256_unpackhi_ps(in[0], in[1]);
    const __m256 t2 = _mm256_unpacklo_ps(in[2], in[3]), t3 = _mm256_unpackhi_ps(in[2], in[3]);
    const __m256 t4 = _mm256_unpacklo_ps(in[4], in[5]), t5 = _mm256_unpackhi_ps(in[4], in[5]);
    const __m256 t6 = _mm256_unpacklo_ps(in[6], in[7]), t7 = _mm256_unpackhi_ps(in[6], in[7]);
    const __m256 s0 = _mm256_shuffle_ps(t0, t2, 0x44), s1 = _mm256_shuffle_ps(t0, t2, 0xee);
    const __m256 s2 = _mm256_shuffle_ps(t1, t3, 0x44), s3 = _mm256_shuffle_ps(t1, t3, 0xee);
    const __m256 s4 = _mm256_shuffle_ps(t4, t6, 0x44), s5 = _mm256_shuffle_ps(t4, t6, 0xee);
    const __m256 s6 = _mm256_shuffle_ps(t5, t7, 0x44), s7 = _mm256_shuffle_ps(t5, t7, 0xee);
    out[0] = _mm256_permute2f128_ps(s0, s4, 0x20);
    out[1] = _mm256_permute2f128_ps(s1, s5, 0x20);
    out[2] = _mm256_permute2f128_ps(s2, s6, 0x20);
    out[3] = _mm256_permute2f128_ps(s3, s7, 0x20);
    out[4] = _mm256_permute2f128_ps(s0, s4, 0x31);
    out[5] = _mm256_permute2f128_ps(s1, s5, 0x31);
    out[6] = _mm256_permute2f128_ps(s2, s6, 0x31);
    out[7] = _mm256_permute2f128_ps(s3, s7, 0x31);
}

/* Half h of the rays' fields in the lanes (fields 8h to 8h + 7, ray r's
 * in in[r], loaded by the caller): folded into f_min[h] and f_max[h] and
 * transposed into f[8h..8h + 7].  Each branch of tri8_lanes_load loads
 * and folds a half whole, so that no row is live across the branches
 * (where the rows were loaded in two branches and used after them, GCC
 * kept all sixteen rows on the stack: 32 vector moves a packet). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void tri8_lanes_half(const __m256 in[8], int h, __m256 f[TRI8_F_COUNT],
                                   __m256 f_min[2], __m256 f_max[2])
{
    __m256 lo = in[0], hi = in[0];
    for (int r = 1; r < 8; r++) {
        lo = _mm256_min_ps(lo, in[r]);
        hi = _mm256_max_ps(hi, in[r]);
    }
    f_min[h] = lo;
    f_max[h] = hi;
    tri8_transpose8(in, f + 8 * h);
}

/* The fields of the rays of `active` in the lanes: f[TRI8_F_...][r] is
 * rays[r]'s field, copied bit for bit (two loads per ray and a
 * transpose instead of one gather per field); a lane without a ray holds
 * the lowest active ray's fields.  f_min[h] and f_max[h]: lane j holds
 * minps / maxps over the rays of field 8h + j, from the rays as loaded
 * (a field's least and greatest over the rays when none is NaN; the
 * integer fields kx, ky, kz are meaningless there). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void tri8_lanes_load(const struct trace_ray *rays, unsigned active,
                                   __m256 f[TRI8_F_COUNT], __m256 f_min[2], __m256 f_max[2])
{
    const float *base = (const float *)(const void *)rays;
    __m256 in[8];
    if (active == 0xffu) {
        /* A full packet (the common case): no choice per ray, each row
         * at a constant offset. */
        for (int h = 0; h < 2; h++) {
            for (int r = 0; r < 8; r++)
                in[r] = _mm256_loadu_ps(base + TRI8_F_COUNT * r + 8 * h);
            tri8_lanes_half(in, h, f, f_min, f_max);
        }
    } else {
        const unsigned first = (unsigned)__builtin_ctz(active);
        for (int h = 0; h < 2; h++) {
            for (int r = 0; r < 8; r++) {
                const unsigned src = active >> r & 1u ? (unsigned)r : first;
                in[r] = _mm256_loadu_ps(base + TRI8_F_COUNT * src + 8 * h);
            }
            tri8_lanes_half(in, h, f, f_min, f_max);
        }
    }
}

/* Sets up the lanes from the rays' fields in the lanes (tri8_lanes_load)
 * for the rays sharing kx, ky, kz; the other lanes hold their own rays'
 * values under that permutation, never read into an answer (every
 * result of tri8_test is masked by its lanes).  Always inlined: called
 * out of line (GCC's choice once the table held the packet walk's
 * arrays entries too) it cost the kitchen's shadow packets about 5
 * instructions a ray. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void tri8_rays_init(struct tri8_rays *t, const __m256 f[TRI8_F_COUNT], int kx,
                                  int ky, int kz)
{
    t->kx = kx;
    t->ky = ky;
    t->kz = kz;
    t->org_x = f[TRI8_F_ORG + kx];
    t->org_y = f[TRI8_F_ORG + ky];
    t->org_z = f[TRI8_F_ORG + kz];
    t->sx = f[TRI8_F_S];
    t->sy = f[TRI8_F_S + 1];
    t->sz = f[TRI8_F_S + 2];
    t->inv_x = f[TRI8_F_INV + kx];
    t->inv_y = f[TRI8_F_INV + ky];
    t->neg_x = _mm256_cmp_ps(t->inv_x, _mm256_setzero_ps(), _CMP_LT_OQ);
    t->neg_y = _mm256_cmp_ps(t->inv_y, _mm256_setzero_ps(), _CMP_LT_OQ);
    t->tmin = f[TRI8_F_TMIN];
    for (int k = 0; k < 3; k++) {
        t->org_d[k][0] = _mm256_cvtps_pd(_mm256_castps256_ps128(f[TRI8_F_ORG + k]));
        t->org_d[k][1] = _mm256_cvtps_pd(_mm256_extractf128_ps(f[TRI8_F_ORG + k], 1));
        t->dir_d[k][0] = _mm256_cvtps_pd(_mm256_castps256_ps128(f[TRI8_F_DIR + k]));
        t->dir_d[k][1] = _mm256_cvtps_pd(_mm256_extractf128_ps(f[TRI8_F_DIR + k], 1));
    }
}

/* isect_slab in the lanes: `neg` selects the near end as `inv < 0 ? hi :
 * lo` does. */
static inline void tri8_slab(__m256 d0, __m256 d1, __m256 d2, __m256 inv, __m256 neg,
                             __m256 *t_lo, __m256 *t_hi)
{
    __m256 lo = _mm256_min_ps(d0, d1);
    __m256 hi = _mm256_max_ps(d1, d0);
    lo = _mm256_min_ps(lo, d2);
    hi = _mm256_max_ps(hi, d2);
    const __m256 t_near = _mm256_mul_ps(_mm256_blendv_ps(lo, hi, neg), inv);
    const __m256 t_far = _mm256_mul_ps(_mm256_blendv_ps(hi, lo, neg), inv);
    *t_lo = _mm256_max_ps(t_near, *t_lo);
    *t_hi = _mm256_min_ps(t_far, *t_hi);
}

/* The lanes' answers for one triangle: `hit` the lanes decided here with
 * a hit (t, u, v filled for them), `scalar` the lanes isect_triangle
 * must decide itself. */
struct tri8_result {
    unsigned hit;
    unsigned scalar;
    __m256 t, u, v; /* read in the lanes of hit only */
};

/*
 * Triangle l of packet q (vertex a's coordinate k at q->v[a][k][l], read
 * in place; the float part reads the rows of the packet's kx, ky, kz at
 * vk[0], vk[1], vk[2], each &q->v[0][k][0], which the caller takes once
 * per packet rather than once per triangle) against the rays of `lanes`, ray r below
 * limit[r] (isect_triangle's t_max).  any_hit: t, u, v are not needed
 * (isect_triangle_occludes' short way where it applies).  Returns the
 * lanes with a hit or sent to the scalar test (res->hit | res->scalar).
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned tri8_test(const struct tri8_rays *r, const struct tri4_packet *q,
                                 const float *const vk[3], unsigned l, unsigned lanes,
                                 __m256 limit, int any_hit, struct tri8_result *res)
{
    res->t = res->u = res->v = _mm256_setzero_ps();
    /* Vertex a's coordinate kx, ky, kz: vk[.][12 a + l] (v[a][k][l]). */
    const __m256 ax = _mm256_sub_ps(_mm256_broadcast_ss(&vk[0][0 + l]), r->org_x);
    const __m256 ay = _mm256_sub_ps(_mm256_broadcast_ss(&vk[1][0 + l]), r->org_y);
    const __m256 az = _mm256_sub_ps(_mm256_broadcast_ss(&vk[2][0 + l]), r->org_z);
    const __m256 bx = _mm256_sub_ps(_mm256_broadcast_ss(&vk[0][12 + l]), r->org_x);
    const __m256 by = _mm256_sub_ps(_mm256_broadcast_ss(&vk[1][12 + l]), r->org_y);
    const __m256 bz = _mm256_sub_ps(_mm256_broadcast_ss(&vk[2][12 + l]), r->org_z);
    const __m256 cx = _mm256_sub_ps(_mm256_broadcast_ss(&vk[0][24 + l]), r->org_x);
    const __m256 cy = _mm256_sub_ps(_mm256_broadcast_ss(&vk[1][24 + l]), r->org_y);
    const __m256 cz = _mm256_sub_ps(_mm256_broadcast_ss(&vk[2][24 + l]), r->org_z);

    struct tri8_sheared sh;
    tri8_shear(ax, ay, az, bx, by, bz, cx, cy, cz, r->sx, r->sy, &sh);

    const __m256 on_edge = tri8_on_edge(&sh);
    const unsigned deferred = (unsigned)_mm256_movemask_ps(on_edge) & lanes;
    /* isect_triangle's sign test for the lanes not deferred, where U, V
     * and W are all non-zero: "outside when the signs differ" is a sign
     * bit of U ^ V or U ^ W.  There, the signs being equal, det = U + V
     * + W is not 0 (a sum of non-zero values of one sign rounds away from
     * 0), so det == 0 needs no test; a NaN among them makes det NaN,
     * which |det| < inf refuses as isfinite(det) does.  Only the sign
     * bit of keep is meaningful (every use ends in a movemask). */
    const __m256 mixed = _mm256_or_ps(_mm256_xor_ps(sh.U, sh.V), _mm256_xor_ps(sh.U, sh.W));
    const __m256 det = _mm256_add_ps(_mm256_add_ps(sh.U, sh.V), sh.W);
    const __m256 abs_det = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), det);
    __m256 keep =
        _mm256_andnot_ps(mixed, _mm256_cmp_ps(abs_det, _mm256_set1_ps(INFINITY), _CMP_LT_OQ));
    if (!(((unsigned)_mm256_movemask_ps(keep) | deferred) & lanes)) {
        /* No ray passes the edge test, none is deferred: the depth
         * range and the slabs can only reject more. */
        res->hit = 0;
        res->scalar = 0;
        return 0;
    }

    const __m256 Az = _mm256_mul_ps(r->sz, az);
    const __m256 Bz = _mm256_mul_ps(r->sz, bz);
    const __m256 Cz = _mm256_mul_ps(r->sz, cz);
    const __m256 z_lo = _mm256_min_ps(Az, _mm256_min_ps(Bz, Cz));
    const __m256 z_hi = _mm256_max_ps(Az, _mm256_max_ps(Bz, Cz));
    keep = _mm256_and_ps(keep, _mm256_cmp_ps(z_hi, r->tmin, _CMP_GE_OQ));
    keep = _mm256_and_ps(keep, _mm256_cmp_ps(z_lo, limit, _CMP_LT_OQ));

    __m256 t_lo = z_lo;
    __m256 t_hi = z_hi;
    tri8_slab(ax, bx, cx, r->inv_x, r->neg_x, &t_lo, &t_hi);
    tri8_slab(ay, by, cy, r->inv_y, r->neg_y, &t_lo, &t_hi);
    keep = _mm256_and_ps(keep, _mm256_cmp_ps(t_lo, limit, _CMP_LT_OQ));
    unsigned cand = (unsigned)_mm256_movemask_ps(keep) & lanes & ~deferred;
    res->hit = 0;
    res->scalar = 0;
    if (!(cand | deferred))
        return 0;

    /* A triangle of zero area (edge vectors' cross product exactly 0 in
     * double, isect_triangle_finish's refusal) is held as NaNs in its
     * packet lane (accel_set_packet_lane), which the filter above
     * rejects for every lane, the deferred ones too: no double test of
     * the area here.  A lane of a zero-area triangle the filter keeps
     * anyway reaches the plane distance with den == 0 and goes to the
     * scalar test, which refuses it itself. */
    res->scalar = deferred;
    if (!cand)
        return deferred;

    if (any_hit) {
        /* isect_triangle_occludes' short way: the clamped t lies in
         * [tmin, t_max) whatever it is. */
        const __m256 inf = _mm256_set1_ps(INFINITY);
        const __m256 sign = _mm256_set1_ps(-0.0f);
        __m256 s = _mm256_cmp_ps(t_lo, r->tmin, _CMP_GE_OQ);
        s = _mm256_and_ps(s, _mm256_cmp_ps(t_lo, t_hi, _CMP_LE_OQ));
        s = _mm256_and_ps(s, _mm256_cmp_ps(t_hi, limit, _CMP_LT_OQ));
        s = _mm256_and_ps(s, _mm256_cmp_ps(_mm256_andnot_ps(sign, t_lo), inf, _CMP_LT_OQ));
        s = _mm256_and_ps(s, _mm256_cmp_ps(_mm256_andnot_ps(sign, t_hi), inf, _CMP_LT_OQ));
        const unsigned short_way = (unsigned)_mm256_movemask_ps(s) & cand;
        res->hit = short_way;
        cand &= ~short_way;
        if (!cand)
            return res->hit | deferred;
    }

    if (!any_hit) {
        /* The lanes whose box interval lies wholly before tmin (t_lo,
         * t_hi < tmin; t_lo is ordered in a candidate, which passed
         * t_lo < limit, and maxps returns t_hi where it is NaN, which
         * then fails the comparison) take no hit: the finish clamps t
         * into [t_lo, t_hi] by min then max, a value that is t_lo or at
         * most t_hi, both below tmin, and refuses t < tmin.  A lane the
         * finish would send to isect_triangle (a sliver, den == 0, a NaN
         * distance) is refused there as well: its float part gives the
         * same t_lo and t_hi, and every way to a hit ends in
         * isect_clamp_to_box and the same t >= tmin test (pk9's
         * argument).  Deferred lanes (an edge function of 0) are not
         * candidates and still go to it.  A half of four lanes left
         * without candidates skips its double step below
         * (docs/performance-log.md, pk9 and pk10). */
        cand &= ~(unsigned)_mm256_movemask_ps(
            _mm256_cmp_ps(_mm256_max_ps(t_lo, t_hi), r->tmin, _CMP_LT_OQ));
        if (!cand)
            return deferred;
    }

    const double e1x = (double)q->v[1][0][l] - q->v[0][0][l];
    const double e1y = (double)q->v[1][1][l] - q->v[0][1][l];
    const double e1z = (double)q->v[1][2][l] - q->v[0][2][l];
    const double e2x = (double)q->v[2][0][l] - q->v[0][0][l];
    const double e2y = (double)q->v[2][1][l] - q->v[0][1][l];
    const double e2z = (double)q->v[2][2][l] - q->v[0][2][l];
    const double nx = e1y * e2z - e1z * e2y;
    const double ny = e1z * e2x - e1x * e2z;
    const double nz = e1x * e2y - e1y * e2x;
    const double n2 = nx * nx + ny * ny + nz * nz;
    const double e3x = e2x - e1x;
    const double e3y = e2y - e1y;
    const double e3z = e2z - e1z;
    const double l1 = e1x * e1x + e1y * e1y + e1z * e1z;
    const double l2 = e2x * e2x + e2y * e2y + e2z * e2z;
    const double l3 = e3x * e3x + e3y * e3y + e3z * e3z;
    const double lmax = l1 >= l2 && l1 >= l3 ? l1 : (l2 >= l3 ? l2 : l3);

    /* isect_triangle's size: max(max(|Ax|, |Ay|), max(|Bx|, |By|)), then
     * max with max(|Cx|, |Cy|). */
    const __m256 sign = _mm256_set1_ps(-0.0f);
    __m256 size = _mm256_max_ps(
        _mm256_max_ps(_mm256_andnot_ps(sign, sh.Ax), _mm256_andnot_ps(sign, sh.Ay)),
        _mm256_max_ps(_mm256_andnot_ps(sign, sh.Bx), _mm256_andnot_ps(sign, sh.By)));
    size = _mm256_max_ps(
        size, _mm256_max_ps(_mm256_andnot_ps(sign, sh.Cx), _mm256_andnot_ps(sign, sh.Cy)));

    const __m256d n_x = _mm256_set1_pd(nx), n_y = _mm256_set1_pd(ny), n_z = _mm256_set1_pd(nz);
    const __m256d p_x = _mm256_set1_pd((double)q->v[0][0][l]);
    const __m256d p_y = _mm256_set1_pd((double)q->v[0][1][l]);
    const __m256d p_z = _mm256_set1_pd((double)q->v[0][2][l]);
    const __m256d rounding_scale = _mm256_set1_pd(ISECT_SLIVER_ROUNDINGS * 0x1p-24);
    const __m256d lmax_d = _mm256_set1_pd(lmax);
    const __m256d n2_d = _mm256_set1_pd(n2);
    /* Only the halves (four lanes each) with a candidate: a packet's
     * candidates are often all among four neighbouring rays. */
    __m128 t_half[2] = {_mm_setzero_ps(), _mm_setzero_ps()};
    unsigned ok = 0;
    for (int h = 0; h < 2; h++) {
        if (!(cand >> (4 * h) & 0xfu))
            continue;
        const __m128 size_h = h ? _mm256_extractf128_ps(size, 1) : _mm256_castps256_ps128(size);
        const __m256d rounding = _mm256_mul_pd(rounding_scale, _mm256_cvtps_pd(size_h));
        const __m256d proper = _mm256_cmp_pd(
            n2_d, _mm256_mul_pd(_mm256_mul_pd(rounding, rounding), lmax_d), _CMP_GE_OQ);
        const __m256d den = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(n_x, r->dir_d[0][h]),
                                                        _mm256_mul_pd(n_y, r->dir_d[1][h])),
                                          _mm256_mul_pd(n_z, r->dir_d[2][h]));
        const __m256d num = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(n_x, _mm256_sub_pd(p_x, r->org_d[0][h])),
                          _mm256_mul_pd(n_y, _mm256_sub_pd(p_y, r->org_d[1][h]))),
            _mm256_mul_pd(n_z, _mm256_sub_pd(p_z, r->org_d[2][h])));
        const __m256d tp = _mm256_div_pd(num, den);
        __m256d good = _mm256_and_pd(proper, _mm256_cmp_pd(den, _mm256_setzero_pd(), _CMP_NEQ_UQ));
        good = _mm256_and_pd(good, _mm256_cmp_pd(tp, tp, _CMP_ORD_Q));
        ok |= (unsigned)_mm256_movemask_pd(good) << (4 * h);
        t_half[h] = _mm256_cvtpd_ps(tp);
    }
    res->scalar |= cand & ~ok;
    cand &= ok;
    if (!cand)
        return res->hit | res->scalar;

    __m256 t = _mm256_set_m128(t_half[1], t_half[0]);
    t = _mm256_min_ps(t, t_hi);
    t = _mm256_max_ps(t, t_lo);
    __m256 acc = _mm256_cmp_ps(t, r->tmin, _CMP_GE_OQ);
    acc = _mm256_and_ps(acc, _mm256_cmp_ps(t, limit, _CMP_LT_OQ));
    acc = _mm256_and_ps(
        acc, _mm256_cmp_ps(_mm256_andnot_ps(sign, t), _mm256_set1_ps(INFINITY), _CMP_LT_OQ));
    const unsigned hit = (unsigned)_mm256_movemask_ps(acc) & cand;
    res->hit |= hit;
    if (hit && !any_hit) {
        const __m256 rcp_det = _mm256_div_ps(_mm256_set1_ps(1.0f), det);
        res->t = t;
        res->u = _mm256_mul_ps(sh.V, rcp_det);
        res->v = _mm256_mul_ps(sh.W, rcp_det);
    }
    return res->hit | res->scalar;
}

/*
 * The first exit of tri8_test for the four triangles of packet q against
 * two rays a and b of the test's lanes (r: the rays' constants, lane r
 * holding ray r), the triangles across the lanes instead of the rays:
 * lane l (l < 4) is triangle l against ray a, lane 4 + l triangle l
 * against ray b.  Every lane does tri8_test's float operations up to its
 * first exit in the same order on the same operands (the vertex's
 * coordinate minus the ray's origin, the shear, the three edge
 * functions, the sign and determinant test), so a lane's decision there
 * is bit for bit the one tri8_test takes for that triangle and ray.
 * Returns the lanes that tri8_test's first exit keeps or defers: bit l
 * (ray a) and bit 4 + l (ray b) for triangle l.  tri8_test returns 0
 * without effects for a triangle none of whose rays passes its first
 * exit, so such a triangle needs no tri8_test.  A leaf reached by few rays then takes one
 * eight-lane test of its four triangles per two rays instead of one per
 * triangle (kpk's "four triangles by two rays", docs/performance-log.md,
 * pk3).
 */
static inline unsigned tri8_pair_filter(const struct tri8_rays *r, const float *const vk[3],
                                        unsigned a, unsigned b)
{
    const __m256i at = _mm256_setr_epi32((int)a, (int)a, (int)a, (int)a, (int)b, (int)b,
                                         (int)b, (int)b);
    const __m256 ox = _mm256_permutevar8x32_ps(r->org_x, at);
    const __m256 oy = _mm256_permutevar8x32_ps(r->org_y, at);
    const __m256 oz = _mm256_permutevar8x32_ps(r->org_z, at);
    const __m256 sx = _mm256_permutevar8x32_ps(r->sx, at);
    const __m256 sy = _mm256_permutevar8x32_ps(r->sy, at);
    /* Vertex a's coordinate k of the four triangles, in both halves. */
#define TRI8_ROW4(k, v) _mm256_broadcast_ps((const __m128 *)(const void *)&vk[k][12 * (v)])
    const __m256 ax = _mm256_sub_ps(TRI8_ROW4(0, 0), ox);
    const __m256 ay = _mm256_sub_ps(TRI8_ROW4(1, 0), oy);
    const __m256 az = _mm256_sub_ps(TRI8_ROW4(2, 0), oz);
    const __m256 bx = _mm256_sub_ps(TRI8_ROW4(0, 1), ox);
    const __m256 by = _mm256_sub_ps(TRI8_ROW4(1, 1), oy);
    const __m256 bz = _mm256_sub_ps(TRI8_ROW4(2, 1), oz);
    const __m256 cx = _mm256_sub_ps(TRI8_ROW4(0, 2), ox);
    const __m256 cy = _mm256_sub_ps(TRI8_ROW4(1, 2), oy);
    const __m256 cz = _mm256_sub_ps(TRI8_ROW4(2, 2), oz);
#undef TRI8_ROW4
    struct tri8_sheared sh;
    tri8_shear(ax, ay, az, bx, by, bz, cx, cy, cz, sx, sy, &sh);
    const __m256 on_edge = tri8_on_edge(&sh);
    const __m256 mixed = _mm256_or_ps(_mm256_xor_ps(sh.U, sh.V), _mm256_xor_ps(sh.U, sh.W));
    const __m256 det = _mm256_add_ps(_mm256_add_ps(sh.U, sh.V), sh.W);
    const __m256 abs_det = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), det);
    const __m256 keep =
        _mm256_andnot_ps(mixed, _mm256_cmp_ps(abs_det, _mm256_set1_ps(INFINITY), _CMP_LT_OQ));
    return (unsigned)_mm256_movemask_ps(_mm256_or_ps(keep, on_edge));
}

#endif
