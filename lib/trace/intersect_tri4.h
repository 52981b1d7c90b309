/* SPDX-License-Identifier: Apache-2.0 */
/*
 * intersect_tri4.h - the watertight triangle test (intersect.h's
 * isect_triangle) on the four triangles of a packet (bvh4_layout.h's
 * struct tri4_packet) at once, with SSE; included by the SIMD traversal
 * units only.
 *
 * Same hits as the scalar test, by construction.  The packet test is a
 * filter in front of it: for each lane it computes, with one SSE
 * operation per scalar one, the float values isect_triangle computes
 * before its first double-precision step, in the same order (the
 * vertices minus the origin, the shear, the three edge functions, the
 * sign test, det, the sheared depths and their range, the ray's
 * interval through the triangle's box), and rejects a lane exactly where
 * isect_triangle returns 0 on those values.  Every other lane is decided
 * by the rest of isect_triangle on the filter's floats (tri4_lane_test):
 * its double-precision fallback, t, clamp and tie rule.  A lane with an
 * edge function of exactly 0 (the paper's sec. 4 fallback case) is kept
 * unless its signs differ strictly or its depth range or box interval
 * rejects it, which decide it whatever the double step gives.  So a lane
 * the filter rejects is one isect_triangle rejects.  Bit for bit because
 * - addition, subtraction and multiplication are IEEE single operations
 *   lane by lane, never fused (-ffp-contract=off, and the intrinsics are
 *   separate multiplies and adds);
 * - isect_min(a, b) = a < b ? a : b is minps(a, b) and
 *   isect_max(a, b) = a > b ? a : b is maxps(a, b), NaN rule included;
 *   isect_slab's `d0 < d1 ? d1 : d0` is maxps(d1, d0);
 * - isfinite(det) is |det| < inf, false for NaN as for the infinities.
 * A zero-area triangle's lane holds NaN (bvh4_layout.h,
 * accel_set_packet_lane): its det is NaN, so the filter rejects it, as
 * isect_triangle rejects every zero-area triangle; a kept lane therefore
 * has an area, and tri4_lane_test's finish leaves that test out.
 * The rejections on t_max (z_lo < t_max, t_lo < t_max) are monotone in
 * t_max, so a packet filtered once with the limit at its start rejects
 * only lanes that the scalar test, run later with a limit no larger,
 * would reject too.  conformance/internal/tri4_differential checks the
 * filter against isect_triangle lane by lane.
 */
#ifndef RT_TRACE_INTERSECT_TRI4_H
#define RT_TRACE_INTERSECT_TRI4_H

#include <immintrin.h>
#include <stddef.h>

#include "trace/bvh4_layout.h"
#include "trace/intersect.h"
#include "trace/isa_avx512.h"
#include "trace/tri8_shear.h"

/* The per-ray constants of the packet test, set once per ray.  The
 * origin is held negated: v + (-org) is v - org bit for bit (IEEE 754
 * defines x - y as x + (-y), zeros and NaN included), and an addition
 * takes the packet's coordinates as its memory operand, which a
 * subtraction can only do for the subtrahend: nine loads fewer per
 * packet in the VEX encoding.  kx, ky, kz are also kept as byte offsets
 * of the rows of struct tri4_packet's v[i]. */
struct tri4_ray {
    __m128 neg_org_x, neg_org_y, neg_org_z; /* -org[kx], -org[ky], -org[kz] */
    __m128 sx, sy, sz;
    __m128 inv_x, inv_y;        /* inv_dir[kx], inv_dir[ky] */
    __m128 tmin;
    size_t off_x, off_y, off_z; /* kx, ky, kz times sizeof p->v[0][0] */
    int neg_x, neg_y;           /* inv_dir[kx] < 0, inv_dir[ky] < 0 (isect_slab) */
    /* The same constants as plain floats (`scalar` form), which only the
     * single-ray any-hit leaves read (the filters with depth_out,
     * TRI4_CONST): set by tri4_ray_init_scalar, or by the walk from its
     * set-up's lanes with three 16-byte stores, where the vectors above
     * cost nine broadcasts and nine stores a ray; the leaves broadcast
     * them from memory (vbroadcastss), one load each as the vectors'
     * loads are.  The vectors above are then left unset. */
    float k_neg_org[4]; /* -org[kx], -org[ky], -org[kz], - */
    float k_inv[4];     /* inv_dir[kx], inv_dir[ky], sz (= inv_dir[kz]), - */
    float k_shear[4];   /* sx, sy, -, - */
    float k_tmin;
    /* -org[0], -org[1], -org[2] in axis order: not a leaf constant but
     * the 8-wide any-hit walk's node test (walk_wide8_ray, from the
     * set-up's lanes only), broadcast from here after each leaf call
     * instead of loaded from the ray and negated again (three loads,
     * three sign flips and three register broadcasts a leaf visit).
     * Written with k_tmin by one 16-byte store
     * (tri4_ray_init_scalar_lanes), so it follows k_tmin; it fills what
     * was the struct's tail padding, so struct tri4_ray and struct
     * wide_state keep their sizes and every other field its offset. */
    float node_neg_org[3];
};

static inline void tri4_ray_init(struct tri4_ray *r, const struct trace_ray *ray)
{
    const size_t row = sizeof(((const struct tri4_packet *)NULL)->v[0][0]);
    r->off_x = (size_t)ray->kx * row;
    r->off_y = (size_t)ray->ky * row;
    r->off_z = (size_t)ray->kz * row;
    r->neg_org_x = _mm_set1_ps(-ray->org[ray->kx]);
    r->neg_org_y = _mm_set1_ps(-ray->org[ray->ky]);
    r->neg_org_z = _mm_set1_ps(-ray->org[ray->kz]);
    r->sx = _mm_set1_ps(ray->sx);
    r->sy = _mm_set1_ps(ray->sy);
    r->sz = _mm_set1_ps(ray->sz);
    r->inv_x = _mm_set1_ps(ray->inv_dir[ray->kx]);
    r->inv_y = _mm_set1_ps(ray->inv_dir[ray->ky]);
    r->tmin = _mm_set1_ps(ray->tmin);
    r->neg_x = ray->inv_dir[ray->kx] < 0.0f;
    r->neg_y = ray->inv_dir[ray->ky] < 0.0f;
}

/* The ray's origin (d[0..2]) and direction (d[4..6]) converted to
 * double for the finish (isect_triangle_finish_impl's ray_d), each
 * coordinate as the finish converts it (a float converts to double
 * exactly: the same doubles, converted once a ray instead of six
 * conversions a finish).  Four floats at a time from struct trace_ray,
 * whose org and dir are followed by more floats (dir, inv_dir: asserted
 * below): d[3] and d[7] (dir[0], inv_dir[0]) are converted too and never
 * read. */
typedef char tri4_ray_double_loads
    [offsetof(struct trace_ray, dir) == offsetof(struct trace_ray, org) + 3 * sizeof(float) &&
             offsetof(struct trace_ray, inv_dir) ==
                 offsetof(struct trace_ray, dir) + 3 * sizeof(float)
         ? 1
         : -1];
static inline void tri4_ray_init_double(double d[8], const struct trace_ray *ray)
{
    const float *org = (const float *)(const void *)((const char *)ray +
                                                     offsetof(struct trace_ray, org));
    const float *dir = (const float *)(const void *)((const char *)ray +
                                                     offsetof(struct trace_ray, dir));
#if defined(__AVX__)
    _mm256_storeu_pd(d, _mm256_cvtps_pd(_mm_loadu_ps(org)));
    _mm256_storeu_pd(d + 4, _mm256_cvtps_pd(_mm_loadu_ps(dir)));
#else
    const __m128 o4 = _mm_loadu_ps(org);
    const __m128 d4 = _mm_loadu_ps(dir);
    _mm_storeu_pd(d, _mm_cvtps_pd(o4));
    _mm_storeu_pd(d + 2, _mm_cvtps_pd(_mm_movehl_ps(o4, o4)));
    _mm_storeu_pd(d + 4, _mm_cvtps_pd(d4));
    _mm_storeu_pd(d + 6, _mm_cvtps_pd(_mm_movehl_ps(d4, d4)));
#endif
}

/* tri4_ray_init's constants in the scalar form only (struct tri4_ray's
 * k_ fields, with off_x.. and neg_x, neg_y), for the single-ray any-hit
 * leaves: the same floats (-org by C's unary minus, the sign bit, as
 * _mm_xor_ps with -0 in the walk's form).  Lane 3 of the k_ arrays (and
 * lane 2 of k_shear) is never read, so not written. */
static inline void tri4_ray_init_scalar(struct tri4_ray *r, const struct trace_ray *ray)
{
    const size_t row = sizeof(((const struct tri4_packet *)NULL)->v[0][0]);
    r->off_x = (size_t)ray->kx * row;
    r->off_y = (size_t)ray->ky * row;
    r->off_z = (size_t)ray->kz * row;
    r->k_neg_org[0] = -ray->org[ray->kx];
    r->k_neg_org[1] = -ray->org[ray->ky];
    r->k_neg_org[2] = -ray->org[ray->kz];
    r->k_inv[0] = ray->inv_dir[ray->kx];
    r->k_inv[1] = ray->inv_dir[ray->ky];
    r->k_inv[2] = ray->sz;
    r->k_shear[0] = ray->sx;
    r->k_shear[1] = ray->sy;
    r->k_tmin = ray->tmin;
    r->neg_x = ray->inv_dir[ray->kx] < 0.0f;
    r->neg_y = ray->inv_dir[ray->ky] < 0.0f;
}

/* One per-ray constant of r as four lanes: the vector field `vec` (the
 * closest-hit leaves, the packet kernels, the 4-wide walks: tri4_ray_init)
 * or, with scalar (the single-ray any-hit leaves, whose walks set only the
 * k_ fields), the float `k` broadcast from memory.  The same float in
 * every lane either way.  A macro, not an inline function: with scalar 0
 * it is the field access the filters had, and the closest-hit leaves
 * compile to the same instructions as before (objdump; through an inline
 * function taking the field's address GCC allocated their registers
 * otherwise). */
#define TRI4_CONST(r, vec, k, scalar) ((scalar) ? _mm_set1_ps((r)->k) : (r)->vec)

/* Row `off` bytes into vertex i's coordinates of p (tri4_ray's off_x..):
 * the four lanes' coordinate on one axis. */
static inline __m128 tri4_row(const struct tri4_packet *p, int i, size_t off)
{
    return _mm_loadu_ps((const float *)(const void *)((const char *)p->v[i] + off));
}

/* isect_slab on four lanes: the near and far ends of one slab, folded
 * into *t_lo, *t_hi. */
static inline void tri4_slab(__m128 d0, __m128 d1, __m128 d2, __m128 inv, int neg, __m128 *t_lo,
                             __m128 *t_hi)
{
    __m128 lo = _mm_min_ps(d0, d1);
    __m128 hi = _mm_max_ps(d1, d0);
    lo = _mm_min_ps(lo, d2);
    hi = _mm_max_ps(hi, d2);
    const __m128 t_near = _mm_mul_ps(neg ? hi : lo, inv);
    const __m128 t_far = _mm_mul_ps(neg ? lo : hi, inv);
    *t_lo = _mm_max_ps(t_near, *t_lo);
    *t_hi = _mm_min_ps(t_far, *t_hi);
}

/* The float values of the four lanes that isect_triangle_finish takes
 * (tri4_candidates_lanes), and the lanes with an edge function of
 * exactly 0, which only isect_triangle itself may decide. */
struct tri4_lanes {
    float U[4], V[4], W[4], det[4];
    float Az[4], Bz[4], Cz[4];
    float size[4], t_lo[4], t_hi[4];
    /* The sheared x, y of the vertices, written only when a lane is
     * deferred: its double-precision edge functions are computed from
     * them (tri4_lane_test). */
    float Ax[4], Ay[4], Bx[4], By[4], Cx[4], Cy[4];
    unsigned deferred;
};

/* max(|a|, |b|) lane by lane, the near-lane proof's S folded from the
 * a_i (tri4_before_tmin_vectors).  With AVX-512 DQ and VL one vrangeps
 * (imm 0x0B: the operand of larger magnitude, its sign bit cleared;
 * Intel SDM vol. 2, VRANGEPS) where the SSE form takes two andnot and a
 * max.  Without NaN both give the larger magnitude, the same float; with
 * a NaN operand they may give different values (maxps returns its second
 * operand, vrangeps a quiet NaN), which does not change a refusal: a NaN
 * coordinate makes det NaN, and check 1 (|det| >= 2^-13 S^2) then fails
 * whatever S is. */
#if TRACE_AVX512_TABLE
static inline __m128 tri4_max_abs(__m128 a, __m128 b)
{
    return _mm_range_ps(a, b, 0x0B);
}
#endif

/* Defined with tri4_before_tmin_lanes below, whose proof it carries. */
static inline unsigned tri4_before_tmin_vectors(const struct tri4_ray *r, __m128 sc, __m128 U,
                                                __m128 V, __m128 W, __m128 det, __m128 Az,
                                                __m128 Bz, __m128 Cz, int scalar);

/*
 * The lanes of p (among `valid`, bit l for lane l) that isect_triangle
 * with this t_max might accept; every other lane it rejects.  With out
 * not NULL, also the lanes' float values for isect_triangle_finish.
 * any_hit (the any-hit walk's leaf, with tri4_lane_test's any_hit): the
 * early return below, and size, Ax..Cy are not written: the any-hit
 * lane test computes them for the lane that needs them
 * (tri4_lane_sheared), so the six sheared vectors die at the edge
 * functions instead of being spilled around the early return (measured:
 * six stores per packet) for the rare lane that reaches the finish.
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned tri4_filter_lanes_depth(const struct tri4_ray *r,
                                               const struct tri4_packet *p, unsigned valid,
                                               float t_max, struct tri4_lanes *out, int any_hit,
                                               int early_out, int depth_out)
{
    /* depth_out's walks (the single-ray any-hit leaves) set the per-ray
     * constants' scalar form only (struct tri4_ray's k_ fields). */
    const int scalar = depth_out;
    /* Unaligned loads: a layout's packets are 32-byte aligned, but a
     * packet elsewhere (a test's, on the stack) need not be; on aligned
     * data they cost what aligned loads do. */
    const __m128 ax = _mm_add_ps(TRI4_CONST(r, neg_org_x, k_neg_org[0], scalar),
                                 tri4_row(p, 0, r->off_x));
    const __m128 ay = _mm_add_ps(TRI4_CONST(r, neg_org_y, k_neg_org[1], scalar),
                                 tri4_row(p, 0, r->off_y));
    const __m128 az = _mm_add_ps(TRI4_CONST(r, neg_org_z, k_neg_org[2], scalar),
                                 tri4_row(p, 0, r->off_z));
    const __m128 bx = _mm_add_ps(TRI4_CONST(r, neg_org_x, k_neg_org[0], scalar),
                                 tri4_row(p, 1, r->off_x));
    const __m128 by = _mm_add_ps(TRI4_CONST(r, neg_org_y, k_neg_org[1], scalar),
                                 tri4_row(p, 1, r->off_y));
    const __m128 bz = _mm_add_ps(TRI4_CONST(r, neg_org_z, k_neg_org[2], scalar),
                                 tri4_row(p, 1, r->off_z));
    const __m128 cx = _mm_add_ps(TRI4_CONST(r, neg_org_x, k_neg_org[0], scalar),
                                 tri4_row(p, 2, r->off_x));
    const __m128 cy = _mm_add_ps(TRI4_CONST(r, neg_org_y, k_neg_org[1], scalar),
                                 tri4_row(p, 2, r->off_y));
    const __m128 cz = _mm_add_ps(TRI4_CONST(r, neg_org_z, k_neg_org[2], scalar),
                                 tri4_row(p, 2, r->off_z));

    const __m128 Ax = _mm_add_ps(ax, _mm_mul_ps(TRI4_CONST(r, sx, k_shear[0], scalar), az));
    const __m128 Ay = _mm_add_ps(ay, _mm_mul_ps(TRI4_CONST(r, sy, k_shear[1], scalar), az));
    const __m128 Bx = _mm_add_ps(bx, _mm_mul_ps(TRI4_CONST(r, sx, k_shear[0], scalar), bz));
    const __m128 By = _mm_add_ps(by, _mm_mul_ps(TRI4_CONST(r, sy, k_shear[1], scalar), bz));
    const __m128 Cx = _mm_add_ps(cx, _mm_mul_ps(TRI4_CONST(r, sx, k_shear[0], scalar), cz));
    const __m128 Cy = _mm_add_ps(cy, _mm_mul_ps(TRI4_CONST(r, sy, k_shear[1], scalar), cz));

    const __m128 U = _mm_sub_ps(_mm_mul_ps(Cx, By), _mm_mul_ps(Cy, Bx));
    const __m128 V = _mm_sub_ps(_mm_mul_ps(Ax, Cy), _mm_mul_ps(Ay, Cx));
    const __m128 W = _mm_sub_ps(_mm_mul_ps(Bx, Ay), _mm_mul_ps(By, Ax));

    const __m128 zero = _mm_setzero_ps();
    /* Some edge function below 0, some above: min(U, V, W) < 0 and
     * max(U, V, W) > 0, two folds and two compares instead of six
     * compares and four ors.  minps/maxps return one of their operands,
     * so a min below 0 is an operand below 0 and a max above 0 one above
     * 0: a lane found mixed is mixed, NaN operands or not.  Without NaN
     * the folds are exact, so a lane not found mixed is not mixed; a
     * lane with a NaN edge function has a NaN det and is kept only when
     * deferred (below), where tri4_lane_test redoes the signs in double
     * as isect_triangle does. */
    const __m128 any_neg = _mm_cmplt_ps(_mm_min_ps(U, _mm_min_ps(V, W)), zero);
    const __m128 any_pos = _mm_cmpgt_ps(_mm_max_ps(U, _mm_max_ps(V, W)), zero);
    /* Signs that differ strictly: outside, deferred lanes too.  A
     * non-zero float edge function has the sign of its double
     * recomputation: fl(fl(a) - fl(b)) > 0 needs fl(a) > fl(b), hence
     * a > b (rounding is monotone), and the double difference of the
     * exact products a - b > 0 rounds to a positive double (a
     * subtraction that underflows is exact).  So the scalar test's
     * double signs differ as well and it returns 0. */
    const __m128 mixed = _mm_and_ps(any_neg, any_pos);
    /* With early_out: when every lane's signs differ, every lane is
     * refused (a mixed lane is neither kept nor deferred below), and the
     * rest is not computed.  Most packets a shadow ray tests are such
     * misses, and most a random ray tests on a large mesh (soup: 84 %);
     * where fewer are (gears' random rays: 40 %) the branch is hard to
     * predict, and the 8-wide closest-hit walk on a small layout keeps
     * the branch-free filter (traverse_wide.h, wide8_packet_full). */
    if (early_out && ((unsigned)_mm_movemask_ps(mixed) & valid) == valid)
        return 0;

    /* Lanes with an edge function of exactly 0: the scalar test's
     * double-precision fallback decides their signs. */
    const __m128 on_edge =
        _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(U, zero), _mm_cmpeq_ps(V, zero)), _mm_cmpeq_ps(W, zero));

    /* The rejections that do not depend on U, V, W: the sheared depths'
     * range and the ray's interval through the triangle's box.  They
     * hold for deferred lanes too (the scalar test rejects on them after
     * its double step, and every rejection returns the same 0). */
    const __m128 Az = _mm_mul_ps(TRI4_CONST(r, sz, k_inv[2], scalar), az);
    const __m128 Bz = _mm_mul_ps(TRI4_CONST(r, sz, k_inv[2], scalar), bz);
    const __m128 Cz = _mm_mul_ps(TRI4_CONST(r, sz, k_inv[2], scalar), cz);
    const __m128 z_lo = _mm_min_ps(Az, _mm_min_ps(Bz, Cz));
    const __m128 z_hi = _mm_max_ps(Az, _mm_max_ps(Bz, Cz));
    const __m128 limit = _mm_set1_ps(t_max);
    /* depth_out (the single-ray any-hit leaves, with any_hit and
     * early_out): a second early return.  When every lane with
     * unmixed signs lies wholly behind tmin or beyond the limit in depth
     * (a shadow ray's line passes through the surfaces behind its
     * origin: in the kitchen 39 % of the 8-lane any-hit leaves that pass
     * the sign test end here), every lane is refused (geom below, the
     * same comparisons) and the slabs and det are not computed.  Not in the
     * closest-hit copies: there GCC scheduled the filter differently
     * (gears' random rays +3 instructions a ray); not in the packet
     * kernels' and the 4-wide walks' leaves, whose code stays as it was. */
    if (depth_out &&
        ((unsigned)_mm_movemask_ps(_mm_andnot_ps(
             mixed, _mm_and_ps(_mm_cmpge_ps(z_hi, TRI4_CONST(r, tmin, k_tmin, scalar)),
                               _mm_cmplt_ps(z_lo, limit)))) &
         valid) == 0)
        return 0;
    __m128 t_lo = z_lo;
    __m128 t_hi = z_hi;
    tri4_slab(ax, bx, cx, TRI4_CONST(r, inv_x, k_inv[0], scalar), r->neg_x, &t_lo, &t_hi);
    tri4_slab(ay, by, cy, TRI4_CONST(r, inv_y, k_inv[1], scalar), r->neg_y, &t_lo, &t_hi);
    const __m128 geom = _mm_andnot_ps(
        mixed, _mm_and_ps(_mm_and_ps(_mm_cmpge_ps(z_hi, TRI4_CONST(r, tmin, k_tmin, scalar)),
                                     _mm_cmplt_ps(z_lo, limit)),
                          _mm_cmplt_ps(t_lo, limit)));
    const unsigned deferred = (unsigned)_mm_movemask_ps(_mm_and_ps(on_edge, geom)) & valid;

    const __m128 det = _mm_add_ps(_mm_add_ps(U, V), W);
    const __m128 abs_det = _mm_andnot_ps(_mm_set1_ps(-0.0f), det);
    __m128 keep = _mm_and_ps(geom, _mm_cmpneq_ps(det, zero));
    keep = _mm_and_ps(keep, _mm_cmplt_ps(abs_det, _mm_set1_ps(INFINITY)));
    unsigned mask = ((unsigned)_mm_movemask_ps(keep) & valid) | deferred;
    if (depth_out && mask) {
        /* depth_out (the single-ray any-hit leaves): the kept lanes the
         * ray starts on (t_lo < tmin: a shadow ray's own triangle and
         * its neighbours) refused here, from the filter's registers,
         * before anything is stored: those wholly before tmin (t_hi <
         * tmin, which the finish clamps below tmin: wide_packet_test
         * says why) and those tri4_before_tmin_lanes' checks refuse
         * (tri4_before_tmin_vectors, the same checks on the same
         * floats: its a_i are this filter's ax..cz, v_i + (-org) in
         * the same operand order).  A shadow ray's leaves mostly end
         * here with no lane left, so the nine lane vectors are not
         * stored and reloaded and no function is called.  The near lanes
         * these checks cannot decide stay in the mask; the caller
         * refuses them with tri4_before_tmin (their t_lo, stored below,
         * is still below tmin).  S is folded as a tree here: without NaN
         * the maximum of the nine magnitudes is the same float in any
         * order; with a NaN coordinate det is NaN and check 1 fails
         * whatever S is (tri4_before_tmin_lanes' comment). */
        const __m128 tmin = TRI4_CONST(r, tmin, k_tmin, scalar);
        const unsigned near = (unsigned)_mm_movemask_ps(_mm_cmplt_ps(t_lo, tmin)) & mask;
        if (near) {
            const unsigned behind = (unsigned)_mm_movemask_ps(_mm_cmplt_ps(t_hi, tmin)) & near;
            mask &= ~behind;
            if (near & ~behind) {
#if TRACE_AVX512_TABLE
                /* vrangeps (tri4_max_abs): eight instructions for the
                 * nine magnitudes' maximum, where the SSE form below
                 * takes seventeen. */
                const __m128 sa = tri4_max_abs(tri4_max_abs(ax, ay), az);
                const __m128 sb = tri4_max_abs(tri4_max_abs(bx, by), bz);
                const __m128 scc = tri4_max_abs(tri4_max_abs(cx, cy), cz);
                const __m128 sc = tri4_max_abs(tri4_max_abs(sa, sb), scc);
#else
                const __m128 sign = _mm_set1_ps(-0.0f);
                const __m128 sa = _mm_max_ps(_mm_max_ps(_mm_andnot_ps(sign, ax),
                                                        _mm_andnot_ps(sign, ay)),
                                             _mm_andnot_ps(sign, az));
                const __m128 sb = _mm_max_ps(_mm_max_ps(_mm_andnot_ps(sign, bx),
                                                        _mm_andnot_ps(sign, by)),
                                             _mm_andnot_ps(sign, bz));
                const __m128 scc = _mm_max_ps(_mm_max_ps(_mm_andnot_ps(sign, cx),
                                                         _mm_andnot_ps(sign, cy)),
                                              _mm_andnot_ps(sign, cz));
                const __m128 sc = _mm_max_ps(_mm_max_ps(sa, sb), scc);
#endif
                mask &= ~(tri4_before_tmin_vectors(r, sc, U, V, W, det, Az, Bz, Cz, scalar) & near &
                          ~behind);
            }
            if (!mask)
                return 0;
        }
    }
    if (out && mask) {
        _mm_storeu_ps(out->U, U);
        _mm_storeu_ps(out->V, V);
        _mm_storeu_ps(out->W, W);
        _mm_storeu_ps(out->det, det);
        _mm_storeu_ps(out->Az, Az);
        _mm_storeu_ps(out->Bz, Bz);
        _mm_storeu_ps(out->Cz, Cz);
        _mm_storeu_ps(out->t_lo, t_lo);
        _mm_storeu_ps(out->t_hi, t_hi);
        out->deferred = deferred;
        if (!any_hit) {
            /* isect_triangle's size: max(max(|Ax|, |Ay|), max(|Bx|,
             * |By|)), then max with max(|Cx|, |Cy|); maxps(a, b) is a > b
             * ? a : b. */
            const __m128 sign = _mm_set1_ps(-0.0f);
            __m128 size =
                _mm_max_ps(_mm_max_ps(_mm_andnot_ps(sign, Ax), _mm_andnot_ps(sign, Ay)),
                           _mm_max_ps(_mm_andnot_ps(sign, Bx), _mm_andnot_ps(sign, By)));
            size = _mm_max_ps(size, _mm_max_ps(_mm_andnot_ps(sign, Cx), _mm_andnot_ps(sign, Cy)));
            _mm_storeu_ps(out->size, size);
            if (deferred) {
                _mm_storeu_ps(out->Ax, Ax);
                _mm_storeu_ps(out->Ay, Ay);
                _mm_storeu_ps(out->Bx, Bx);
                _mm_storeu_ps(out->By, By);
                _mm_storeu_ps(out->Cx, Cx);
                _mm_storeu_ps(out->Cy, Cy);
            }
        }
    }
    return mask;
}

/* tri4_filter_lanes_depth without the depth return: the filter of the
 * packet kernels, the 4-wide walks and the tests. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned tri4_filter_lanes(const struct tri4_ray *r, const struct tri4_packet *p,
                                         unsigned valid, float t_max, struct tri4_lanes *out,
                                         int any_hit, int early_out)
{
    return tri4_filter_lanes_depth(r, p, valid, t_max, out, any_hit, early_out, 0);
}

#if defined(__AVX__)
/* Row `off` bytes into vertex i's coordinates of p[0] (lanes 0-3) and of
 * p[1] (lanes 4-7): two 128-bit loads into one 256-bit vector. */
static inline __m256 tri4_pair_row(const struct tri4_packet *p, int i, size_t off)
{
    const char *lo = (const char *)p[0].v[i] + off;
    const char *hi = (const char *)p[1].v[i] + off;
    return _mm256_insertf128_ps(
        _mm256_castps128_ps256(_mm_loadu_ps((const float *)(const void *)lo)),
        _mm_loadu_ps((const float *)(const void *)hi), 1);
}

/* TRI4_CONST on eight lanes (both packets' halves). */
#define TRI4_CONST8(r, vec, k, scalar)                                                          \
    ((scalar) ? _mm256_set1_ps((r)->k) : _mm256_broadcast_ps(&(r)->vec))

/* tri4_slab on the eight lanes of two packets. */
static inline void tri4_pair_slab(__m256 d0, __m256 d1, __m256 d2, __m256 inv, int neg,
                                  __m256 *t_lo, __m256 *t_hi)
{
    __m256 lo = _mm256_min_ps(d0, d1);
    __m256 hi = _mm256_max_ps(d1, d0);
    lo = _mm256_min_ps(lo, d2);
    hi = _mm256_max_ps(hi, d2);
    const __m256 t_near = _mm256_mul_ps(neg ? hi : lo, inv);
    const __m256 t_far = _mm256_mul_ps(neg ? lo : hi, inv);
    *t_lo = _mm256_max_ps(t_near, *t_lo);
    *t_hi = _mm256_min_ps(t_far, *t_hi);
}

/* Lanes 0-3 of v to lo, lanes 4-7 to hi: each packet's lanes go to its
 * own 4-lane struct, which tri4_lane_test reads as the 4-lane filter's. */
static inline void tri4_pair_store(float *lo, float *hi, __m256 v)
{
    _mm_storeu_ps(lo, _mm256_castps256_ps128(v));
    _mm_storeu_ps(hi, _mm256_extractf128_ps(v, 1));
}

/* behind_out's value for the 8-lane filter that refuses a leaf whose
 * lanes are all missed or wholly before tmin right after the signs
 * (tri4_pair_filter_lanes; the closest-hit walk's first 8-lane leaf of
 * a ray, traverse_wide8_ray.h). */
#define TRI4_BEHIND_FIRST 2

/* The 8-lane filter's depths (sz times the z differences) and their
 * range, as tri4_filter_lanes computes them. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void tri4_pair_depths(__m256 sz, __m256 az, __m256 bz, __m256 cz, __m256 *Az,
                                    __m256 *Bz, __m256 *Cz, __m256 *z_lo, __m256 *z_hi)
{
    *Az = _mm256_mul_ps(sz, az);
    *Bz = _mm256_mul_ps(sz, bz);
    *Cz = _mm256_mul_ps(sz, cz);
    *z_lo = _mm256_min_ps(*Az, _mm256_min_ps(*Bz, *Cz));
    *z_hi = _mm256_max_ps(*Az, _mm256_max_ps(*Bz, *Cz));
}

/* The triangles' boxes along the ray: the depth range [z_lo, z_hi]
 * narrowed by the x and y slabs, in the 8-lane filter's order. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void tri4_pair_box_interval(const struct tri4_ray *r, int scalar, __m256 ax,
                                          __m256 bx, __m256 cx, __m256 ay, __m256 by, __m256 cy,
                                          __m256 z_lo, __m256 z_hi, __m256 *t_lo, __m256 *t_hi)
{
    *t_lo = z_lo;
    *t_hi = z_hi;
    tri4_pair_slab(ax, bx, cx, TRI4_CONST8(r, inv_x, k_inv[0], scalar), r->neg_x, t_lo, t_hi);
    tri4_pair_slab(ay, by, cy, TRI4_CONST8(r, inv_y, k_inv[1], scalar), r->neg_y, t_lo, t_hi);
}

/*
 * tri4_filter_lanes on the two consecutive packets p[0], p[1] of a leaf
 * of 5-8 triangles at once (lanes 0-3: p[0]'s, lanes 4-7: p[1]'s), with
 * AVX's 256-bit vectors: the same float operations lane by lane, in the
 * same order, so each lane's values and verdict are those of the 4-lane
 * filter on its own packet with the same t_max.  The leaf's second
 * packet is filtered with the limit at the leaf's start instead of the
 * limit after the first packet's lanes; the rejections on t_max are
 * monotone in it and tri4_lane_test applies them again with the current
 * limit (see the file's head), so the lanes accepted and their t, u, v
 * are the same as two 4-lane calls'.  Packet k's lanes are written to
 * out[k] exactly as the 4-lane filter writes them (bit k of the mask's
 * upper half is lane k of p[1]), so the lane test is the 4-lane one.
 * The early return leaves only when all eight lanes are refused by their
 * signs.  behind_out (the single-ray closest-hit leaves,
 * wide_leaf8_test): the kept lanes whose box interval lies wholly before
 * tmin (t_lo < tmin and t_hi < tmin) are taken out of the mask here,
 * before the lanes are stored; wide_packet_test says why the finish
 * refuses every such lane (its t is clamped to t_hi or t_lo, both below
 * tmin), so the leaf's answer is the same.  Computed only once some lane
 * is kept, off the chain to the filter's verdict: the filters of leaves
 * that keep nothing pay nothing (s6's form in `geom` made every call pay
 * and lengthened that chain).
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned tri4_pair_filter_lanes(const struct tri4_ray *r,
                                              const struct tri4_packet *p, unsigned valid,
                                              float t_max, struct tri4_lanes out[2],
                                              int any_hit, int early_out, int depth_out,
                                              int behind_out)
{
    /* depth_out's walks set the scalar form only (tri4_filter_lanes_depth). */
    const int scalar = depth_out;
    const __m256 neg_org_x = TRI4_CONST8(r, neg_org_x, k_neg_org[0], scalar);
    const __m256 neg_org_y = TRI4_CONST8(r, neg_org_y, k_neg_org[1], scalar);
    const __m256 neg_org_z = TRI4_CONST8(r, neg_org_z, k_neg_org[2], scalar);
    const __m256 ax = _mm256_add_ps(neg_org_x, tri4_pair_row(p, 0, r->off_x));
    const __m256 ay = _mm256_add_ps(neg_org_y, tri4_pair_row(p, 0, r->off_y));
    const __m256 az = _mm256_add_ps(neg_org_z, tri4_pair_row(p, 0, r->off_z));
    const __m256 bx = _mm256_add_ps(neg_org_x, tri4_pair_row(p, 1, r->off_x));
    const __m256 by = _mm256_add_ps(neg_org_y, tri4_pair_row(p, 1, r->off_y));
    const __m256 bz = _mm256_add_ps(neg_org_z, tri4_pair_row(p, 1, r->off_z));
    const __m256 cx = _mm256_add_ps(neg_org_x, tri4_pair_row(p, 2, r->off_x));
    const __m256 cy = _mm256_add_ps(neg_org_y, tri4_pair_row(p, 2, r->off_y));
    const __m256 cz = _mm256_add_ps(neg_org_z, tri4_pair_row(p, 2, r->off_z));

    const __m256 sx = TRI4_CONST8(r, sx, k_shear[0], scalar);
    const __m256 sy = TRI4_CONST8(r, sy, k_shear[1], scalar);
    struct tri8_sheared sh;
    tri8_shear(ax, ay, az, bx, by, bz, cx, cy, cz, sx, sy, &sh);

    /* The sign test, early return, edge zeros, depth range, box
     * interval and det exactly as tri4_filter_lanes (its comments say
     * why each is the scalar test's). */
    const __m256 zero = _mm256_setzero_ps();
    __m256 Az, Bz, Cz, z_lo, z_hi, t_lo, t_hi, det;
    unsigned mask, deferred;
#if TRACE_AVX512_TABLE
    if (!any_hit) {
        /* AVX-512, the closest-hit leaves: the same comparisons (the same
         * predicates on the same floats, so the same bits) into mask
         * registers, combined there and moved once for each test the
         * code branches on.  The vector form's VEX compares cannot read
         * xmm16-31, where GCC keeps many of this filter's vectors on
         * AVX-512, and it copied them into xmm0-15 before each compare
         * (about nine vmovaps a call in wide8_leaf8_closest, besides the
         * vandps and vmovmskps the masks' logic replaces). */
        const __mmask8 mixed = _kand_mask8(
            _mm256_cmp_ps_mask(_mm256_min_ps(sh.U, _mm256_min_ps(sh.V, sh.W)), zero, _CMP_LT_OQ),
            _mm256_cmp_ps_mask(_mm256_max_ps(sh.U, _mm256_max_ps(sh.V, sh.W)), zero, _CMP_GT_OQ));
        if (early_out && (_cvtmask8_u32(mixed) & valid) == valid)
            return 0;
        const __m256 tmin = TRI4_CONST8(r, tmin, k_tmin, scalar);
        const __m256 limit = _mm256_set1_ps(t_max);
        tri4_pair_depths(TRI4_CONST8(r, sz, k_inv[2], scalar), az, bz, cz, &Az, &Bz, &Cz, &z_lo,
                         &z_hi);
        tri4_pair_box_interval(r, scalar, ax, bx, cx, ay, by, cy, z_lo, z_hi, &t_lo, &t_hi);
        const __mmask8 geom = _kandn_mask8(
            mixed, _kand_mask8(_kand_mask8(_mm256_cmp_ps_mask(z_hi, tmin, _CMP_GE_OQ),
                                           _mm256_cmp_ps_mask(z_lo, limit, _CMP_LT_OQ)),
                               _mm256_cmp_ps_mask(t_lo, limit, _CMP_LT_OQ)));
        /* The lanes wholly before tmin (behind_out, below), compared only
         * where they are used (off the chain to the verdict, as below). */
#define TRI4_PAIR_BEHIND_K                                                                        \
    _kand_mask8(_mm256_cmp_ps_mask(t_hi, tmin, _CMP_LT_OQ),                                       \
                _mm256_cmp_ps_mask(t_lo, tmin, _CMP_LT_OQ))
        /* TRI4_BEHIND_FIRST's refusal (below): geom & ~behind is its
         * pre & ~mixed & ~behind. */
        if (behind_out == TRI4_BEHIND_FIRST &&
            (_cvtmask8_u32(_kandn_mask8(TRI4_PAIR_BEHIND_K, geom)) & valid) == 0)
            return 0;
        /* depth_out's early return (below) is left out: it refuses only
         * where geom has no valid lane, and then the mask below is empty
         * too (keep and deferred lie within geom), so 0 is returned
         * either way. */
        const __mmask8 edge =
            _kor_mask8(_kor_mask8(_mm256_cmp_ps_mask(sh.U, zero, _CMP_EQ_OQ),
                                  _mm256_cmp_ps_mask(sh.V, zero, _CMP_EQ_OQ)),
                       _mm256_cmp_ps_mask(sh.W, zero, _CMP_EQ_OQ));
        det = _mm256_add_ps(_mm256_add_ps(sh.U, sh.V), sh.W);
        const __m256 abs_det = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), det);
        const __mmask8 finite =
            _kand_mask8(_mm256_cmp_ps_mask(det, zero, _CMP_NEQ_UQ),
                        _mm256_cmp_ps_mask(abs_det, _mm256_set1_ps(INFINITY), _CMP_LT_OQ));
        /* (keep & valid) | deferred, keep = geom & finite and deferred =
         * geom & edge & valid, as one mask: geom & (finite | edge). */
        mask = _cvtmask8_u32(_kand_mask8(geom, _kor_mask8(finite, edge))) & valid;
        deferred = _cvtmask8_u32(_kand_mask8(geom, edge)) & valid;
        if (behind_out && mask)
            mask &= ~_cvtmask8_u32(TRI4_PAIR_BEHIND_K);
#undef TRI4_PAIR_BEHIND_K
    } else
#endif
    {
        const __m256 any_neg =
            _mm256_cmp_ps(_mm256_min_ps(sh.U, _mm256_min_ps(sh.V, sh.W)), zero, _CMP_LT_OQ);
        const __m256 any_pos =
            _mm256_cmp_ps(_mm256_max_ps(sh.U, _mm256_max_ps(sh.V, sh.W)), zero, _CMP_GT_OQ);
        const __m256 mixed = _mm256_and_ps(any_neg, any_pos);
        if (early_out && ((unsigned)_mm256_movemask_ps(mixed) & valid) == valid)
            return 0;

        if (behind_out == TRI4_BEHIND_FIRST) {
            /* The leaf refused here, after the signs and before the edge
             * zeros, det, keep and the deferred lanes, when no valid lane
             * with unmixed signs passes the depth and box tests of `geom`
             * below with a box interval that reaches tmin: with a camera
             * inside a room, the leaf whose box holds the camera is visited
             * by nearly every camera ray, and its lanes are missed by the
             * line (mixed signs) or lie wholly behind the camera.  The
             * depths and the box interval computed here are those the code
             * below uses (it computes them only without this block), the
             * same operations in the same order; `behind` is the refusal's
             * own comparisons below.  Exact: the returned mask is a subset of
             * geom & ~behind & valid (keep and deferred lie within geom; the
             * behind refusal takes `behind` out), and geom is pre & ~mixed;
             * so when pre & ~mixed & ~behind & valid is empty the mask below
             * is 0, nothing is stored and 0 is returned, as here.  rr5's exit
             * (round 42) in every 8-lane call; here only in a ray's first
             * leaf (traverse_wide8_ray.h says why). */
            tri4_pair_depths(TRI4_CONST8(r, sz, k_inv[2], scalar), az, bz, cz, &Az, &Bz, &Cz, &z_lo,
                             &z_hi);
            const __m256 limit = _mm256_set1_ps(t_max);
            tri4_pair_box_interval(r, scalar, ax, bx, cx, ay, by, cy, z_lo, z_hi, &t_lo, &t_hi);
            const __m256 tmin = TRI4_CONST8(r, tmin, k_tmin, scalar);
            const __m256 pre =
                _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(z_hi, tmin, _CMP_GE_OQ),
                                            _mm256_cmp_ps(z_lo, limit, _CMP_LT_OQ)),
                              _mm256_cmp_ps(t_lo, limit, _CMP_LT_OQ));
            const __m256 behind = _mm256_and_ps(_mm256_cmp_ps(t_hi, tmin, _CMP_LT_OQ),
                                                _mm256_cmp_ps(t_lo, tmin, _CMP_LT_OQ));
            if (((unsigned)_mm256_movemask_ps(_mm256_andnot_ps(_mm256_or_ps(behind, mixed), pre)) &
                 valid) == 0)
                return 0;
        }

        const __m256 on_edge = tri8_on_edge(&sh);

        if (behind_out != TRI4_BEHIND_FIRST)
            tri4_pair_depths(TRI4_CONST8(r, sz, k_inv[2], scalar), az, bz, cz, &Az, &Bz, &Cz, &z_lo,
                             &z_hi);
        const __m256 limit = _mm256_set1_ps(t_max);
        /* The any-hit early return on depth, as tri4_filter_lanes_depth. */
        if (depth_out &&
            ((unsigned)_mm256_movemask_ps(_mm256_andnot_ps(
                 mixed,
                 _mm256_and_ps(
                     _mm256_cmp_ps(z_hi, TRI4_CONST8(r, tmin, k_tmin, scalar), _CMP_GE_OQ),
                     _mm256_cmp_ps(z_lo, limit, _CMP_LT_OQ)))) &
             valid) == 0)
            return 0;
        if (behind_out != TRI4_BEHIND_FIRST)
            tri4_pair_box_interval(r, scalar, ax, bx, cx, ay, by, cy, z_lo, z_hi, &t_lo, &t_hi);
        const __m256 geom = _mm256_andnot_ps(
            mixed,
            _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(z_hi, TRI4_CONST8(r, tmin, k_tmin, scalar),
                                                      _CMP_GE_OQ),
                                        _mm256_cmp_ps(z_lo, limit, _CMP_LT_OQ)),
                          _mm256_cmp_ps(t_lo, limit, _CMP_LT_OQ)));
        deferred = (unsigned)_mm256_movemask_ps(_mm256_and_ps(on_edge, geom)) & valid;

        det = _mm256_add_ps(_mm256_add_ps(sh.U, sh.V), sh.W);
        const __m256 abs_det = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), det);
        __m256 keep = _mm256_and_ps(geom, _mm256_cmp_ps(det, zero, _CMP_NEQ_UQ));
        keep = _mm256_and_ps(keep, _mm256_cmp_ps(abs_det, _mm256_set1_ps(INFINITY), _CMP_LT_OQ));
        mask = ((unsigned)_mm256_movemask_ps(keep) & valid) | deferred;
        if (behind_out && mask) {
            /* The same comparisons as the per-lane `t_hi < tmin && t_lo <
             * tmin` they replace (ordered: false for NaN), on the same
             * floats; a deferred lane among them is refused too, as its
             * double edge step returns 0 or leads to the same finish. */
            const __m256 tmin = TRI4_CONST8(r, tmin, k_tmin, scalar);
            mask &= ~(unsigned)_mm256_movemask_ps(_mm256_and_ps(
                _mm256_cmp_ps(t_hi, tmin, _CMP_LT_OQ), _mm256_cmp_ps(t_lo, tmin, _CMP_LT_OQ)));
        }
    }
    if (mask) {
        tri4_pair_store(out[0].U, out[1].U, sh.U);
        tri4_pair_store(out[0].V, out[1].V, sh.V);
        tri4_pair_store(out[0].W, out[1].W, sh.W);
        tri4_pair_store(out[0].det, out[1].det, det);
        tri4_pair_store(out[0].Az, out[1].Az, Az);
        tri4_pair_store(out[0].Bz, out[1].Bz, Bz);
        tri4_pair_store(out[0].Cz, out[1].Cz, Cz);
        tri4_pair_store(out[0].t_lo, out[1].t_lo, t_lo);
        tri4_pair_store(out[0].t_hi, out[1].t_hi, t_hi);
        out[0].deferred = deferred & 15u;
        out[1].deferred = deferred >> 4;
        if (!any_hit) {
            const __m256 sign = _mm256_set1_ps(-0.0f);
            __m256 size = _mm256_max_ps(
                _mm256_max_ps(_mm256_andnot_ps(sign, sh.Ax), _mm256_andnot_ps(sign, sh.Ay)),
                _mm256_max_ps(_mm256_andnot_ps(sign, sh.Bx), _mm256_andnot_ps(sign, sh.By)));
            size = _mm256_max_ps(
                size, _mm256_max_ps(_mm256_andnot_ps(sign, sh.Cx), _mm256_andnot_ps(sign, sh.Cy)));
            tri4_pair_store(out[0].size, out[1].size, size);
            if (deferred) {
                tri4_pair_store(out[0].Ax, out[1].Ax, sh.Ax);
                tri4_pair_store(out[0].Ay, out[1].Ay, sh.Ay);
                tri4_pair_store(out[0].Bx, out[1].Bx, sh.Bx);
                tri4_pair_store(out[0].By, out[1].By, sh.By);
                tri4_pair_store(out[0].Cx, out[1].Cx, sh.Cx);
                tri4_pair_store(out[0].Cy, out[1].Cy, sh.Cy);
            }
        }
    }
    return mask;
}
#endif

/* tri4_filter_lanes with the early return. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned tri4_candidates_lanes_impl(const struct tri4_ray *r,
                                                  const struct tri4_packet *p, unsigned valid,
                                                  float t_max, struct tri4_lanes *out,
                                                  int any_hit)
{
    return tri4_filter_lanes(r, p, valid, t_max, out, any_hit, 1);
}

static inline unsigned tri4_candidates_lanes(const struct tri4_ray *r,
                                             const struct tri4_packet *p, unsigned valid,
                                             float t_max, struct tri4_lanes *out)
{
    return tri4_candidates_lanes_impl(r, p, valid, t_max, out, 0);
}

static inline unsigned tri4_candidates(const struct tri4_ray *r, const struct tri4_packet *p,
                                       unsigned valid, float t_max)
{
    return tri4_candidates_lanes(r, p, valid, t_max, NULL);
}

/*
 * The lanes of p among `lanes` on which isect_triangle_finish (a lane
 * the filter kept, with the finish's own floats: the packet's vertices,
 * ray->org, ray->dir) surely computes a t below ray->tmin before its
 * clamp, so that with t_lo < tmin (the clamp then keeps the result below
 * tmin, NaN included: see isect_clamp_to_box) it surely returns 0; a
 * lane where that is not sure is not in the result.  For any-hit rays
 * that start on a surface (shadow rays, whose tmin steps off it): their
 * own triangle passes the float
 * filter (the ray goes through it at t about 0) and fails only on t, and
 * the finish's double-precision plane distance was most of a shadow
 * ray's leaf work.  Here in float, with error bounds; a proof, not an
 * estimate (u = 2^-24; S the largest |component| of a = v0 - org,
 * e1 = v1 - v0, e2 = v2 - v0 in float, which are within (1 + u) of the
 * exact differences; D the largest |dir| component):
 * - the float cross product n of e1, e2 is within 8.1 u S^2 per
 *   component of the exact one (two products of three roundings each and
 *   a subtraction), which the finish's double n matches to 2^-50 S^2;
 *   so n2 >= 2^-20 S^4 in float makes the double n2 at least 0.99 of it,
 *   far above the finish's sliver threshold r^2 lmax, with
 *   r = ISECT_SLIVER_ROUNDINGS 2^-24 size: r^2 lmax <= 2^-36 (4S)^2 12 S^2
 *   < 2^-28 S^4 (size, the largest sheared |x|, |y|, is at most 4S as
 *   |sx|, |sy| <= 1; every edge component is at most 2S), so the finish
 *   takes the plane distance
 *   num / den (this holds while ISECT_SLIVER_ROUNDINGS is below 2^9);
 * - num = n . a and den = n . dir in float are within 46.3 u S^3 and
 *   40.3 u S^2 D of the finish's doubles (below 2^-18.4 S^3, 2^-18.6 S^2 D);
 *   the bounds used are 2^-16 S^3 and 2^-16 S^2 D, which also cover the
 *   few roundings of the bounds and of the test itself;
 * - so |den| - 2^-16 S^2 D > 0 makes the double den non-zero and of
 *   the float den's sign, and then s num + 2^-16 S^3 <= tmin / 4 (|den| -
 *   2^-16 S^2 D), with s that sign, makes num / den <= tmin / 4 (1 + 4u)
 *   (at most 0 when the left side is): its double and then float
 *   rounding stay below tmin, and it is not NaN.  Signed, not |num / den|:
 *   a triangle the ray's line crosses well behind its origin (a
 *   neighbour of the one a shadow ray starts on, across a convex edge)
 *   is refused here too, not only the one the ray starts on (t about 0);
 *   a t below 0 of any size is below tmin, and |t| stays far below
 *   float's range (|num| <= 24 S^3, |den| > 2^-17 S^2 D).
 * S, D and tmin are held to ranges (2^-20 .. 2^20, 2^-40 .. 2^40 for
 * tmin) where none of these products overflows and an underflow's
 * absolute error (2^-149 per operation) is far below the bounds; NaN
 * fails every test.  conformance/internal/tri4_differential checks each
 * lane this refuses against isect_triangle.  Four lanes at once, in
 * world coordinates (the bounds do not depend on the axes' order).
 */
static inline unsigned tri4_before_tmin(const struct trace_ray *ray, const struct tri4_packet *p,
                                        unsigned lanes)
{
    const float tmin = ray->tmin;
    const float d =
        isect_max(fabsf(ray->dir[0]), isect_max(fabsf(ray->dir[1]), fabsf(ray->dir[2])));
    if (!(d >= 0x1p-20f && d <= 0x1p20f && tmin >= 0x1p-40f && tmin <= 0x1p40f))
        return 0;
    const __m128 x0 = _mm_loadu_ps(p->v[0][0]);
    const __m128 y0 = _mm_loadu_ps(p->v[0][1]);
    const __m128 z0 = _mm_loadu_ps(p->v[0][2]);
    const __m128 ax = _mm_sub_ps(x0, _mm_set1_ps(ray->org[0]));
    const __m128 ay = _mm_sub_ps(y0, _mm_set1_ps(ray->org[1]));
    const __m128 az = _mm_sub_ps(z0, _mm_set1_ps(ray->org[2]));
    const __m128 e1x = _mm_sub_ps(_mm_loadu_ps(p->v[1][0]), x0);
    const __m128 e1y = _mm_sub_ps(_mm_loadu_ps(p->v[1][1]), y0);
    const __m128 e1z = _mm_sub_ps(_mm_loadu_ps(p->v[1][2]), z0);
    const __m128 e2x = _mm_sub_ps(_mm_loadu_ps(p->v[2][0]), x0);
    const __m128 e2y = _mm_sub_ps(_mm_loadu_ps(p->v[2][1]), y0);
    const __m128 e2z = _mm_sub_ps(_mm_loadu_ps(p->v[2][2]), z0);
    const __m128 sign = _mm_set1_ps(-0.0f);
    __m128 sc = _mm_max_ps(_mm_andnot_ps(sign, ax),
                           _mm_max_ps(_mm_andnot_ps(sign, ay), _mm_andnot_ps(sign, az)));
    sc = _mm_max_ps(sc, _mm_max_ps(_mm_andnot_ps(sign, e1x),
                                   _mm_max_ps(_mm_andnot_ps(sign, e1y), _mm_andnot_ps(sign, e1z))));
    sc = _mm_max_ps(sc, _mm_max_ps(_mm_andnot_ps(sign, e2x),
                                   _mm_max_ps(_mm_andnot_ps(sign, e2y), _mm_andnot_ps(sign, e2z))));
    const __m128 nx = _mm_sub_ps(_mm_mul_ps(e1y, e2z), _mm_mul_ps(e1z, e2y));
    const __m128 ny = _mm_sub_ps(_mm_mul_ps(e1z, e2x), _mm_mul_ps(e1x, e2z));
    const __m128 nz = _mm_sub_ps(_mm_mul_ps(e1x, e2y), _mm_mul_ps(e1y, e2x));
    const __m128 n2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, nx), _mm_mul_ps(ny, ny)),
                                 _mm_mul_ps(nz, nz));
    const __m128 num = _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, ax), _mm_mul_ps(ny, ay)),
                                  _mm_mul_ps(nz, az));
    const __m128 den =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, _mm_set1_ps(ray->dir[0])),
                              _mm_mul_ps(ny, _mm_set1_ps(ray->dir[1]))),
                   _mm_mul_ps(nz, _mm_set1_ps(ray->dir[2])));
    const __m128 s2 = _mm_mul_ps(sc, sc);
    const __m128 err2 = _mm_mul_ps(_mm_set1_ps(0x1p-16f), s2); /* 2^-16 S^2, exact */
    __m128 ok = _mm_and_ps(_mm_cmpge_ps(sc, _mm_set1_ps(0x1p-20f)),
                           _mm_cmple_ps(sc, _mm_set1_ps(0x1p20f)));
    ok = _mm_and_ps(ok, _mm_cmpge_ps(n2, _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(0x1p-20f), s2), s2)));
    /* num with den's sign flipped in (exact): num / den = snum / |den|. */
    const __m128 snum = _mm_xor_ps(num, _mm_and_ps(sign, den));
    const __m128 lhs = _mm_add_ps(snum, _mm_mul_ps(err2, sc));
    const __m128 rhs =
        _mm_mul_ps(_mm_set1_ps(0.25f * tmin),
                   _mm_sub_ps(_mm_andnot_ps(sign, den), _mm_mul_ps(err2, _mm_set1_ps(d))));
    ok = _mm_and_ps(ok, _mm_cmple_ps(lhs, rhs));
    ok = _mm_and_ps(ok, _mm_cmpgt_ps(rhs, _mm_setzero_ps()));
    return (unsigned)_mm_movemask_ps(ok) & lanes;
}

/*
 * tri4_before_tmin's refusal from the filter's own floats (those it
 * wrote to `lanes`: U, V, W, det, Az, Bz, Cz) and the vertices minus the
 * origin: for most lanes a ray starts on (a shadow ray's own triangle)
 * this decides in 85 instructions a call where tri4_before_tmin took
 * 122 (gears, AVX2), and tri4_before_tmin stays the fallback for a lane
 * this cannot decide (2.8 % of the calls there).  The lanes of `lanes_mask`
 * (kept or deferred by the filter, with t_lo < tmin) on which
 * isect_triangle_finish surely returns 0, because the t it computes is
 * below tmin; a proof, not an estimate.
 *
 * The identity.  With the exact shear (sx = -d_kx / d_kz, sy likewise,
 * sz = 1 / d_kz) and the exact vertices minus origin a_i, the ray is the
 * sheared z axis, and the paper's T / det of the exact edge functions
 * (Woop, Benthin and Wald 2013, sec. 3) is the distance along the ray
 * to the triangle's plane: t_p = T* / det*, det* = U* + V* + W*,
 * T* = U* Az* + V* Bz* + W* Cz*, for any det* != 0 (the barycentrics of
 * the plane's point on the axis, of any sign).  The finish's
 * proper-triangle t is the same t_p, computed in double as num / den =
 * (n . a_0) / (n . dir); and det* = +-(n . dir) / d_kz, so
 * |den| = |det*| D exactly, D = |d_kz|, the largest |dir| component.
 *
 * The errors (u = 2^-24; S the largest |component| of the a_i as the
 * filter computed them in float, each within u of the exact one):
 * - a sheared x or y float (x + sx z, rounded; sx = fl(-d_kx / d_kz),
 *   |sx| <= 1) is within 6.02 u S of the exact value, and both are below
 *   X = 2 S (1 + 4 u);
 * - so each float edge function is within E1 = 4 X 6.02 u S + 4.01 u X^2
 *   <= 64.2 u S^2 of the exact one (the two products' operands, their
 *   roundings, the subtraction's);
 * - a kept lane's U, V, W have one sign (mixed signs are refused), so
 *   |U| + |V| + |W| <= |det| (1 + 2.01 u) and |det - det*| <= 3 E1 +
 *   2.02 u |det|;
 * - a sheared depth Az = fl(sz a_z), sz = fl(1 / d_kz), is within
 *   3.02 u Z of the exact one, with Z = S |sz| (1 + 7.1 u) above both and
 *   above S / D;
 * - so T, computed here as fl(fl(fl(U Az) + fl(V Bz)) + fl(W Cz)), is
 *   within E_T = Z (192.7 u S^2 + 6.04 u |det|) of T*;
 * - the finish's double num and den are within 240 2^-53 S^3 and
 *   240 2^-53 S^2 D of n . a_0 and n . dir (edge components below
 *   2 S (1 + u), exact or once rounded in double).
 * The checks, whose constants exceed these bounds 2.6 times:
 * 1. |det| >= 2^-13 S^2.  Then |det*| >= 0.905 |det| > 0, of det's sign
 *    s, and |n|^2 >= den^2 / |dir|^2 >= det*^2 / 3 exceeds the finish's
 *    sliver threshold (ISECT_SLIVER_ROUNDINGS 2^-24 size)^2 lmax <=
 *    2^-36 X^2 12 S^2 more than 5 times (while ISECT_SLIVER_ROUNDINGS is
 *    below 140): the finish takes num / den, with den != 0 of the exact
 *    den's sign.
 * 2. s T + fl(S |sz|) (2^-15 S^2 + 2^-20 |det|) < tmin (7/8) |det|, in
 *    float.  The left side, with its roundings, bounds s T* + 240 2^-53
 *    S^3 / D (the bound on T / det's error is built as in PBRT 3rd ed.,
 *    sec. 3.9.6, there for t > 0); the right side, with its roundings, is
 *    below tmin (1 - 2^-20) (|det*| - 240 2^-53 S^2), which check 1 makes
 *    at least 0.905 tmin |det| (1 - 2^-20).  Multiplied by D: s num + its
 *    error <= tmin (1 - 2^-20) (|den| - its error), so num / den <= tmin
 *    (1 - 2^-20) in double, its float t (at most 0 when the quotient is)
 *    is below tmin (the float below a normal tmin is at least tmin
 *    (1 - 2^-23)), and so is the clamp of t into [t_lo, t_hi] with
 *    t_lo < tmin: the finish returns 0.  (With 1.0625 in place of 7/8,
 *    tri4_differential's check 4 finds lanes refused that the finish
 *    accepts.)
 * Ranges: S in [2^-20, 2^20], fl(S |sz|) in [2^-60, 2^40], tmin >=
 * 2^-100 (normal), where nothing overflows and underflow's absolute
 * error (2^-150 an operation) is far below the bounds (the error term is at least 2^-115).  NaN fails the
 * comparisons (a NaN coordinate makes det NaN; maxps may drop it from S,
 * not from det).  A deferred lane is decided the same way: the finish's
 * t does not use the filter's U, V, W, which the deferral recomputes,
 * and a deferred lane with det 0 or NaN fails check 1.
 * conformance/internal/tri4_differential checks each lane refused here
 * against isect_triangle, with tmin near the triangle's own t.
 */
/* tri4_before_tmin_lanes's checks on the filter's vectors (sc: S, the
 * largest |component| of the filter's a_i; U, V, W, det, Az, Bz, Cz as
 * the filter computed them): the lanes the checks refuse, as a 4-bit
 * mask.  Shared by tri4_before_tmin_lanes (the values from a struct
 * tri4_lanes) and the any-hit filter's own refusal
 * (tri4_filter_lanes_depth with depth_out, from its registers). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned tri4_before_tmin_vectors(const struct tri4_ray *r, __m128 sc, __m128 U,
                                                __m128 V, __m128 W, __m128 det, __m128 Az,
                                                __m128 Bz, __m128 Cz, int scalar)
{
    /* The checks' constants as 16-byte rows in memory, read through a
     * pointer GCC cannot see into (the empty asm), so that each becomes
     * the memory operand of its multiply or compare.  As _mm_set1_ps
     * constants GCC loads each with a vbroadcastss of its own before
     * use (AVX2: nine a call, AVX-512: five, the others folded as
     * {1to4} operands), about 12 % of this block's instructions.  The
     * same floats in every lane, the same operations in the same order:
     * the same lanes refused, bit for bit. */
    enum { K_2M15, K_2M20, K_7_8, K_2M13, K_2P20, K_2M60, K_2P40, K_2M100, K_ROWS };
#if defined(__GNUC__)
    __attribute__((aligned(16)))
#endif
    static const float consts[K_ROWS][4] = {
        {0x1p-15f, 0x1p-15f, 0x1p-15f, 0x1p-15f},    {0x1p-20f, 0x1p-20f, 0x1p-20f, 0x1p-20f},
        {0.875f, 0.875f, 0.875f, 0.875f},            {0x1p-13f, 0x1p-13f, 0x1p-13f, 0x1p-13f},
        {0x1p20f, 0x1p20f, 0x1p20f, 0x1p20f},        {0x1p-60f, 0x1p-60f, 0x1p-60f, 0x1p-60f},
        {0x1p40f, 0x1p40f, 0x1p40f, 0x1p40f},        {0x1p-100f, 0x1p-100f, 0x1p-100f, 0x1p-100f}};
    const float(*k)[4] = consts;
#if defined(__GNUC__)
    __asm__("" : "+r"(k));
#endif
#define TRI4_NEAR_K(i) _mm_load_ps(k[i])
    /* x >= row i: with AVX, vcmpps' own GE predicate (ordered,
     * signalling: _mm_cmpge_ps' result, false for NaN), so that the row
     * is its memory operand; SSE's cmpge swaps the operands into a
     * cmple, whose row must then be loaded into a register first. */
#if defined(__AVX__)
#define TRI4_NEAR_GE(x, i) _mm_cmp_ps((x), TRI4_NEAR_K(i), _CMP_GE_OS)
#else
#define TRI4_NEAR_GE(x, i) _mm_cmpge_ps((x), TRI4_NEAR_K(i))
#endif
    const __m128 sign = _mm_set1_ps(-0.0f);
    const __m128 s2 = _mm_mul_ps(sc, sc);
    const __m128 zb = _mm_mul_ps(sc, _mm_andnot_ps(sign, TRI4_CONST(r, sz, k_inv[2], scalar)));
    const __m128 abs_det = _mm_andnot_ps(sign, det);
    const __m128 T =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(U, Az), _mm_mul_ps(V, Bz)), _mm_mul_ps(W, Cz));
    /* Check 2: s T (T with det's sign flipped in, exact) + the error
     * term < tmin (7/8) |det|. */
    const __m128 sT = _mm_xor_ps(T, _mm_and_ps(sign, det));
    const __m128 err = _mm_mul_ps(zb, _mm_add_ps(_mm_mul_ps(TRI4_NEAR_K(K_2M15), s2),
                                                 _mm_mul_ps(TRI4_NEAR_K(K_2M20), abs_det)));
    const __m128 rhs = _mm_mul_ps(TRI4_CONST(r, tmin, k_tmin, scalar),
                                  _mm_mul_ps(TRI4_NEAR_K(K_7_8), abs_det));
    __m128 ok = _mm_cmplt_ps(_mm_add_ps(sT, err), rhs);
    /* Check 1. */
    ok = _mm_and_ps(ok, _mm_cmpge_ps(abs_det, _mm_mul_ps(TRI4_NEAR_K(K_2M13), s2)));
    ok = _mm_and_ps(ok, _mm_and_ps(TRI4_NEAR_GE(sc, K_2M20),
                                   _mm_cmple_ps(sc, TRI4_NEAR_K(K_2P20))));
    ok = _mm_and_ps(ok, _mm_and_ps(TRI4_NEAR_GE(zb, K_2M60),
                                   _mm_cmple_ps(zb, TRI4_NEAR_K(K_2P40))));
    ok = _mm_and_ps(ok,
                    TRI4_NEAR_GE(TRI4_CONST(r, tmin, k_tmin, scalar), K_2M100));
#undef TRI4_NEAR_GE
#undef TRI4_NEAR_K
    return (unsigned)_mm_movemask_ps(ok);
}

static inline unsigned tri4_before_tmin_lanes(const struct tri4_ray *r,
                                              const struct tri4_packet *p,
                                              const struct tri4_lanes *lanes,
                                              unsigned lanes_mask, int scalar)
{
    /* scalar: r's scalar form (TRI4_CONST), as the any-hit walks set it. */
    const __m128 neg_org_x = TRI4_CONST(r, neg_org_x, k_neg_org[0], scalar);
    const __m128 neg_org_y = TRI4_CONST(r, neg_org_y, k_neg_org[1], scalar);
    const __m128 neg_org_z = TRI4_CONST(r, neg_org_z, k_neg_org[2], scalar);
    const __m128 sign = _mm_set1_ps(-0.0f);
    /* S from the a_i as the filter computes them: v_i + (-org). */
    __m128 sc = _mm_andnot_ps(sign, _mm_add_ps(neg_org_x, tri4_row(p, 0, r->off_x)));
    sc = _mm_max_ps(sc, _mm_andnot_ps(sign, _mm_add_ps(neg_org_y, tri4_row(p, 0, r->off_y))));
    sc = _mm_max_ps(sc, _mm_andnot_ps(sign, _mm_add_ps(neg_org_z, tri4_row(p, 0, r->off_z))));
    sc = _mm_max_ps(sc, _mm_andnot_ps(sign, _mm_add_ps(neg_org_x, tri4_row(p, 1, r->off_x))));
    sc = _mm_max_ps(sc, _mm_andnot_ps(sign, _mm_add_ps(neg_org_y, tri4_row(p, 1, r->off_y))));
    sc = _mm_max_ps(sc, _mm_andnot_ps(sign, _mm_add_ps(neg_org_z, tri4_row(p, 1, r->off_z))));
    sc = _mm_max_ps(sc, _mm_andnot_ps(sign, _mm_add_ps(neg_org_x, tri4_row(p, 2, r->off_x))));
    sc = _mm_max_ps(sc, _mm_andnot_ps(sign, _mm_add_ps(neg_org_y, tri4_row(p, 2, r->off_y))));
    sc = _mm_max_ps(sc, _mm_andnot_ps(sign, _mm_add_ps(neg_org_z, tri4_row(p, 2, r->off_z))));
    return tri4_before_tmin_vectors(r, sc, _mm_loadu_ps(lanes->U), _mm_loadu_ps(lanes->V),
                                    _mm_loadu_ps(lanes->W), _mm_loadu_ps(lanes->det),
                                    _mm_loadu_ps(lanes->Az), _mm_loadu_ps(lanes->Bz),
                                    _mm_loadu_ps(lanes->Cz), scalar) &
           lanes_mask;
}

/*
 * The sheared x, y of lane l's vertices (A[0..5] = Ax, Ay, Bx, By, Cx,
 * Cy) and isect_triangle's size of them, for the any-hit lane test, whose
 * filter did not keep them (tri4_candidates_lanes_impl with any_hit).
 * isect_triangle's float operations on the packet's coordinates: v - org,
 * then a + s * a_z, each rounded once (no contraction), so the values
 * the filter had in its lane bit for bit.
 */
static inline float tri4_lane_sheared(const struct trace_ray *ray, const struct tri4_packet *p,
                                      unsigned l, float A[6])
{
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
    for (int i = 0; i < 3; i++) {
        const float x = p->v[i][ray->kx][l] - ray->org[ray->kx];
        const float y = p->v[i][ray->ky][l] - ray->org[ray->ky];
        const float z = p->v[i][ray->kz][l] - ray->org[ray->kz];
        A[2 * i] = x + ray->sx * z;
        A[2 * i + 1] = y + ray->sy * z;
    }
    const float size = isect_max(isect_max(fabsf(A[0]), fabsf(A[1])),
                                 isect_max(fabsf(A[2]), fabsf(A[3])));
    return isect_max(size, isect_max(fabsf(A[4]), fabsf(A[5])));
}

/*
 * isect_triangle on lane l of p, which tri4_candidates_lanes kept (with
 * a limit at least t_max) and whose floats it wrote to `lanes`: a
 * deferred lane first gets isect_triangle's double-precision edge
 * functions on those floats (no second float pass); every lane gets the
 * rejections on t_max again with this t_max (z_lo < t_max, t_lo <
 * t_max: the limit may have shrunk since the filter ran) and then
 * isect_triangle_finish9, or isect_triangle_occludes9 for any_hit.  Each
 * step is isect_triangle's on the same floats, so the answer is its
 * answer bit for bit.  ray_d: NULL, or the ray's origin and direction in
 * double (tri4_ray_init_double) for the finish.
 */
static inline int tri4_lane_test(const struct trace_ray *ray, const double *ray_d,
                                 const struct tri4_packet *p, const struct tri4_lanes *lanes,
                                 unsigned l, int any_hit, float t_max, float *t, float *u,
                                 float *w)
{
    float U = lanes->U[l], V = lanes->V[l], W = lanes->W[l], det = lanes->det[l];
    /* The any-hit filter leaves size and the sheared x, y to this lane
     * (tri4_candidates_lanes_impl); computed when first needed. */
    float sheared[6];
    float size = any_hit ? 0.0f : lanes->size[l];
    int have_size = !any_hit;
    if (lanes->deferred >> l & 1u) {
        /* isect_triangle's sec. 4 step on the filter's sheared floats
         * (the same floats it computes): the edge functions in double,
         * their signs, then its float sign and det tests on the values
         * rounded back.  Its depth-range and box-interval rejections
         * follow below as for any lane. */
        if (any_hit) {
            size = tri4_lane_sheared(ray, p, l, sheared);
            have_size = 1;
        } else {
            sheared[0] = lanes->Ax[l];
            sheared[1] = lanes->Ay[l];
            sheared[2] = lanes->Bx[l];
            sheared[3] = lanes->By[l];
            sheared[4] = lanes->Cx[l];
            sheared[5] = lanes->Cy[l];
        }
        const double Ax = sheared[0], Ay = sheared[1];
        const double Bx = sheared[2], By = sheared[3];
        const double Cx = sheared[4], Cy = sheared[5];
        const double dU = Cx * By - Cy * Bx;
        const double dV = Ax * Cy - Ay * Cx;
        const double dW = Bx * Ay - By * Ax;
        if ((dU < 0.0 || dV < 0.0 || dW < 0.0) && (dU > 0.0 || dV > 0.0 || dW > 0.0))
            return 0;
        U = (float)dU;
        V = (float)dV;
        W = (float)dW;
        if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f))
            return 0;
        det = U + V + W;
        if (det == 0.0f || !isfinite(det))
            return 0;
    }
    const float Az = lanes->Az[l], Bz = lanes->Bz[l], Cz = lanes->Cz[l];
    const float z_lo = isect_min(Az, isect_min(Bz, Cz));
    if (!(z_lo < t_max) || !(lanes->t_lo[l] < t_max))
        return 0;
    /* The lane's coordinates straight from the packet (no copy).  The
     * filter kept the lane, so its coordinates are not NaN: the packet
     * holds a triangle with an area (accel_set_packet_lane), and the
     * finish's zero-area test, which would pass, is left out. */
    if (any_hit) {
        /* isect_triangle_occludes_impl with area_known, its short way
         * first: that needs no size. */
        if (isect_occludes_short(ray, lanes->t_lo[l], lanes->t_hi[l], t_max))
            return 1;
        if (!have_size)
            size = tri4_lane_sheared(ray, p, l, sheared);
        float tt, uu, ww;
        return isect_triangle_finish_impl(
            ray, ray_d, p->v[0][0][l], p->v[0][1][l], p->v[0][2][l], p->v[1][0][l], p->v[1][1][l],
            p->v[1][2][l], p->v[2][0][l], p->v[2][1][l], p->v[2][2][l], U, V, W, det, Az, Bz,
            Cz, size, lanes->t_lo[l], lanes->t_hi[l], t_max, 1, &tt, &uu, &ww);
    }
    return isect_triangle_finish_impl(ray, ray_d, p->v[0][0][l], p->v[0][1][l], p->v[0][2][l],
                                      p->v[1][0][l], p->v[1][1][l], p->v[1][2][l],
                                      p->v[2][0][l], p->v[2][1][l], p->v[2][2][l], U, V, W, det,
                                      Az, Bz, Cz, size, lanes->t_lo[l],
                                      lanes->t_hi[l], t_max, 1, t, u, w);
}

/*
 * The closest-hit finish of four lanes at once (TRI4_FINISH_VEC: the
 * AVX2 and AVX-512 tables' single-ray closest-hit leaves, WIDE8_LEAF_TEST's
 * ray_double; on the AVX-512 table since round 61, where it put a Zen 4
 * core's gears camera rays 0.04 of Embree ahead: performance-log.md, zq2).  isect_triangle_finish_impl computes a kept lane's t in
 * double (the plane distance from the exact edge vectors, our addition
 * to Woop, Benthin and Wald 2013's watertight test) one lane at a time,
 * about 100 instructions a lane with its spills (callgrind, a kitchen
 * random ray: 0.55 finishes, 81 of the leaves' 214 instructions with the
 * lane loop).  Here the same double operations run on the packet's four
 * lanes in one 256-bit vector of doubles each: the rows p->v[i][k] are
 * four floats, each converted exactly (vcvtps2pd), then the edges, the
 * normal, n2, l1, l2, the sliver bound, den, num and num / den in the
 * source's order, every operation an IEEE double one lane by lane and
 * never fused (-ffp-contract=off; separate intrinsics), so each lane's
 * doubles are those the scalar finish computes, and its t the same float
 * (vcvtpd2ps rounds to nearest as the cast does).  The clamp into the
 * box is isect_clamp_to_box's (minps(t, t_hi) is t < t_hi ? t : t_hi,
 * maxps(t, t_lo) is t > t_lo ? t : t_lo), then t >= tmin and isfinite(t)
 * (|t| < inf).  Returns the lanes this decides: not deferred (a deferred
 * lane's signs and U, V, W, det come from the double edge step first),
 * proper by the first bound (n2 >= r2 (l1 + l2) ISECT_LONGEST_EDGE_BOUND;
 * the others need isect_sliver_edges and perhaps the sliver's t) and
 * den != 0 (else the paper's t from U, V, W).  Every other lane keeps
 * tri4_lane_test.  *ok: those of the decided lanes whose t passes tmin and
 * is finite; t_out: their t.  The caller still refuses t >= the limit of
 * the moment: t >= t_lo >= z_lo after the clamp, so that test also makes
 * tri4_lane_test's earlier z_lo < t_max and t_lo < t_max refusals (its
 * way to skip the finish), and the answer is the same.  Lanes outside
 * the caller's mask are computed too (NaN for a zero-area lane; no trap:
 * the exceptions are masked) and never read.
 */
#if defined(__AVX__)
#define TRI4_FINISH_VEC 1
#else
#define TRI4_FINISH_VEC 0
#endif
#if TRI4_FINISH_VEC
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned tri4_finish_lanes(const struct tri4_packet *p,
                                         const struct tri4_lanes *lanes, const double *ray_d,
                                         float tmin, float t_out[4], unsigned *ok)
{
    const __m256d v0x = _mm256_cvtps_pd(_mm_loadu_ps(p->v[0][0]));
    const __m256d v0y = _mm256_cvtps_pd(_mm_loadu_ps(p->v[0][1]));
    const __m256d v0z = _mm256_cvtps_pd(_mm_loadu_ps(p->v[0][2]));
    const __m256d e1x = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(p->v[1][0])), v0x);
    const __m256d e1y = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(p->v[1][1])), v0y);
    const __m256d e1z = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(p->v[1][2])), v0z);
    const __m256d e2x = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(p->v[2][0])), v0x);
    const __m256d e2y = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(p->v[2][1])), v0y);
    const __m256d e2z = _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(p->v[2][2])), v0z);
    const __m256d nx = _mm256_sub_pd(_mm256_mul_pd(e1y, e2z), _mm256_mul_pd(e1z, e2y));
    const __m256d ny = _mm256_sub_pd(_mm256_mul_pd(e1z, e2x), _mm256_mul_pd(e1x, e2z));
    const __m256d nz = _mm256_sub_pd(_mm256_mul_pd(e1x, e2y), _mm256_mul_pd(e1y, e2x));
    const __m256d n2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(nx, nx), _mm256_mul_pd(ny, ny)),
                                     _mm256_mul_pd(nz, nz));
    const __m256d l1 =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(e1x, e1x), _mm256_mul_pd(e1y, e1y)),
                      _mm256_mul_pd(e1z, e1z));
    const __m256d l2 =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(e2x, e2x), _mm256_mul_pd(e2y, e2y)),
                      _mm256_mul_pd(e2z, e2z));
    /* isect_triangle_finish_impl's rounding: ISECT_SLIVER_ROUNDINGS *
     * 0x1p-24 * (double)size, the constant product first as C groups it. */
    const __m256d rounding = _mm256_mul_pd(_mm256_set1_pd(ISECT_SLIVER_ROUNDINGS * 0x1p-24),
                                           _mm256_cvtps_pd(_mm_loadu_ps(lanes->size)));
    const __m256d r2 = _mm256_mul_pd(rounding, rounding);
    const __m256d proper = _mm256_cmp_pd(
        n2,
        _mm256_mul_pd(r2, _mm256_mul_pd(_mm256_add_pd(l1, l2),
                                        _mm256_set1_pd(ISECT_LONGEST_EDGE_BOUND))),
        _CMP_GE_OQ);
    const __m256d den = _mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(nx, _mm256_set1_pd(ray_d[4])),
                      _mm256_mul_pd(ny, _mm256_set1_pd(ray_d[5]))),
        _mm256_mul_pd(nz, _mm256_set1_pd(ray_d[6])));
    const __m256d num = _mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(nx, _mm256_sub_pd(v0x, _mm256_set1_pd(ray_d[0]))),
                      _mm256_mul_pd(ny, _mm256_sub_pd(v0y, _mm256_set1_pd(ray_d[1])))),
        _mm256_mul_pd(nz, _mm256_sub_pd(v0z, _mm256_set1_pd(ray_d[2]))));
    /* den != 0.0 as C's != (true for NaN). */
    const __m256d decided =
        _mm256_and_pd(proper, _mm256_cmp_pd(den, _mm256_setzero_pd(), _CMP_NEQ_UQ));
    __m128 t = _mm256_cvtpd_ps(_mm256_div_pd(num, den));
    t = _mm_max_ps(_mm_min_ps(t, _mm_loadu_ps(lanes->t_hi)), _mm_loadu_ps(lanes->t_lo));
    const __m128 pass =
        _mm_and_ps(_mm_cmpge_ps(t, _mm_set1_ps(tmin)),
                   _mm_cmplt_ps(_mm_andnot_ps(_mm_set1_ps(-0.0f), t), _mm_set1_ps(INFINITY)));
    _mm_storeu_ps(t_out, t);
    const unsigned fast = (unsigned)_mm256_movemask_pd(decided) & ~lanes->deferred;
    *ok = (unsigned)_mm_movemask_ps(pass) & fast;
    return fast;
}

/* Lane l of tri4_finish_lanes' decided lanes (ok, t_l: its *ok and
 * t_out[l]) as tri4_lane_test would answer it: isect_triangle_finish_impl's
 * last test (t < t_max, the limit of the moment) and its u, v (V and W
 * times the float 1 / det).  Returns 0 when the lane is refused. */
static inline int tri4_finish_lane(const struct tri4_lanes *lanes, unsigned l, unsigned ok,
                                   float t_l, float t_max, float *t, float *u, float *w)
{
    if (!(ok >> l & 1u) || !(t_l < t_max))
        return 0;
    const float rcp_det = 1.0f / lanes->det[l];
    *t = t_l;
    *u = lanes->V[l] * rcp_det;
    *w = lanes->W[l] * rcp_det;
    return 1;
}
#endif

#endif
