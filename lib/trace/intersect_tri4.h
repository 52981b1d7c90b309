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
 * isect_triangle returns 0 on those values.  Every other lane goes to
 * isect_triangle itself, which decides it with its own double-precision
 * fallback, t, clamp and tie rule: a lane with an edge function of
 * exactly 0 (the paper's sec. 4 fallback case) always does.  So a lane
 * the filter keeps costs one scalar test more, and one it rejects is one
 * isect_triangle rejects.  Bit for bit because
 * - addition, subtraction and multiplication are IEEE single operations
 *   lane by lane, never fused (-ffp-contract=off, and the intrinsics are
 *   separate multiplies and adds);
 * - isect_min(a, b) = a < b ? a : b is minps(a, b) and
 *   isect_max(a, b) = a > b ? a : b is maxps(a, b), NaN rule included;
 *   isect_slab's `d0 < d1 ? d1 : d0` is maxps(d1, d0);
 * - isfinite(det) is |det| < inf, false for NaN as for the infinities.
 * The rejections on t_max (z_lo < t_max, t_lo < t_max) are monotone in
 * t_max, so a packet filtered once with the limit at its start rejects
 * only lanes that the scalar test, run later with a limit no larger,
 * would reject too.  conformance/internal/tri4_differential checks the
 * filter against isect_triangle lane by lane.
 */
#ifndef RT_TRACE_INTERSECT_TRI4_H
#define RT_TRACE_INTERSECT_TRI4_H

#include <immintrin.h>

#include "trace/bvh4_layout.h"
#include "trace/intersect.h"

/* The per-ray constants of the packet test, set once per ray. */
struct tri4_ray {
    __m128 org_x, org_y, org_z; /* org[kx], org[ky], org[kz] */
    __m128 sx, sy, sz;
    __m128 inv_x, inv_y;        /* inv_dir[kx], inv_dir[ky] */
    __m128 tmin;
    int kx, ky, kz;
    int neg_x, neg_y;           /* inv_dir[kx] < 0, inv_dir[ky] < 0 (isect_slab) */
};

static inline void tri4_ray_init(struct tri4_ray *r, const struct trace_ray *ray)
{
    r->kx = ray->kx;
    r->ky = ray->ky;
    r->kz = ray->kz;
    r->org_x = _mm_set1_ps(ray->org[ray->kx]);
    r->org_y = _mm_set1_ps(ray->org[ray->ky]);
    r->org_z = _mm_set1_ps(ray->org[ray->kz]);
    r->sx = _mm_set1_ps(ray->sx);
    r->sy = _mm_set1_ps(ray->sy);
    r->sz = _mm_set1_ps(ray->sz);
    r->inv_x = _mm_set1_ps(ray->inv_dir[ray->kx]);
    r->inv_y = _mm_set1_ps(ray->inv_dir[ray->ky]);
    r->tmin = _mm_set1_ps(ray->tmin);
    r->neg_x = ray->inv_dir[ray->kx] < 0.0f;
    r->neg_y = ray->inv_dir[ray->ky] < 0.0f;
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

/*
 * The lanes of p (among `valid`, bit l for lane l) that isect_triangle
 * with this t_max might accept; every other lane it rejects.
 */
static inline unsigned tri4_candidates(const struct tri4_ray *r, const struct tri4_packet *p,
                                       unsigned valid, float t_max)
{
    /* Unaligned loads: a layout's packets are 32-byte aligned, but a
     * packet elsewhere (a test's, on the stack) need not be; on aligned
     * data they cost what aligned loads do. */
    const __m128 ax = _mm_sub_ps(_mm_loadu_ps(p->v[0][r->kx]), r->org_x);
    const __m128 ay = _mm_sub_ps(_mm_loadu_ps(p->v[0][r->ky]), r->org_y);
    const __m128 az = _mm_sub_ps(_mm_loadu_ps(p->v[0][r->kz]), r->org_z);
    const __m128 bx = _mm_sub_ps(_mm_loadu_ps(p->v[1][r->kx]), r->org_x);
    const __m128 by = _mm_sub_ps(_mm_loadu_ps(p->v[1][r->ky]), r->org_y);
    const __m128 bz = _mm_sub_ps(_mm_loadu_ps(p->v[1][r->kz]), r->org_z);
    const __m128 cx = _mm_sub_ps(_mm_loadu_ps(p->v[2][r->kx]), r->org_x);
    const __m128 cy = _mm_sub_ps(_mm_loadu_ps(p->v[2][r->ky]), r->org_y);
    const __m128 cz = _mm_sub_ps(_mm_loadu_ps(p->v[2][r->kz]), r->org_z);

    const __m128 Ax = _mm_add_ps(ax, _mm_mul_ps(r->sx, az));
    const __m128 Ay = _mm_add_ps(ay, _mm_mul_ps(r->sy, az));
    const __m128 Bx = _mm_add_ps(bx, _mm_mul_ps(r->sx, bz));
    const __m128 By = _mm_add_ps(by, _mm_mul_ps(r->sy, bz));
    const __m128 Cx = _mm_add_ps(cx, _mm_mul_ps(r->sx, cz));
    const __m128 Cy = _mm_add_ps(cy, _mm_mul_ps(r->sy, cz));

    const __m128 U = _mm_sub_ps(_mm_mul_ps(Cx, By), _mm_mul_ps(Cy, Bx));
    const __m128 V = _mm_sub_ps(_mm_mul_ps(Ax, Cy), _mm_mul_ps(Ay, Cx));
    const __m128 W = _mm_sub_ps(_mm_mul_ps(Bx, Ay), _mm_mul_ps(By, Ax));

    const __m128 zero = _mm_setzero_ps();
    /* Lanes with an edge function of exactly 0: the scalar test's
     * double-precision fallback decides them. */
    const __m128 on_edge =
        _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(U, zero), _mm_cmpeq_ps(V, zero)), _mm_cmpeq_ps(W, zero));
    const unsigned deferred = (unsigned)_mm_movemask_ps(on_edge) & valid;

    const __m128 any_neg =
        _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(U, zero), _mm_cmplt_ps(V, zero)), _mm_cmplt_ps(W, zero));
    const __m128 any_pos =
        _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(U, zero), _mm_cmpgt_ps(V, zero)), _mm_cmpgt_ps(W, zero));
    __m128 keep = _mm_andnot_ps(_mm_and_ps(any_neg, any_pos), _mm_cmpeq_ps(zero, zero));

    const __m128 det = _mm_add_ps(_mm_add_ps(U, V), W);
    const __m128 abs_det = _mm_andnot_ps(_mm_set1_ps(-0.0f), det);
    keep = _mm_and_ps(keep, _mm_cmpneq_ps(det, zero));
    keep = _mm_and_ps(keep, _mm_cmplt_ps(abs_det, _mm_set1_ps(INFINITY)));

    const __m128 Az = _mm_mul_ps(r->sz, az);
    const __m128 Bz = _mm_mul_ps(r->sz, bz);
    const __m128 Cz = _mm_mul_ps(r->sz, cz);
    const __m128 z_lo = _mm_min_ps(Az, _mm_min_ps(Bz, Cz));
    const __m128 z_hi = _mm_max_ps(Az, _mm_max_ps(Bz, Cz));
    const __m128 limit = _mm_set1_ps(t_max);
    keep = _mm_and_ps(keep, _mm_cmpge_ps(z_hi, r->tmin));
    keep = _mm_and_ps(keep, _mm_cmplt_ps(z_lo, limit));

    __m128 t_lo = z_lo;
    __m128 t_hi = z_hi;
    tri4_slab(ax, bx, cx, r->inv_x, r->neg_x, &t_lo, &t_hi);
    tri4_slab(ay, by, cy, r->inv_y, r->neg_y, &t_lo, &t_hi);
    keep = _mm_and_ps(keep, _mm_cmplt_ps(t_lo, limit));
    return ((unsigned)_mm_movemask_ps(keep) & valid) | deferred;
}

/* Lane l of p as the three vertices isect_triangle takes. */
static inline void tri4_lane(const struct tri4_packet *p, unsigned l, float v[9])
{
    for (int j = 0; j < 3; j++) {
        for (int k = 0; k < 3; k++)
            v[3 * j + k] = p->v[j][k][l];
    }
}

#endif
