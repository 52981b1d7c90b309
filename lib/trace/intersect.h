/* SPDX-License-Identifier: Apache-2.0 */
/*
 * intersect.h - the ray/triangle and ray/box kernels, static inline so that
 * traversal compiles them into its loops; intersect.c exports them as
 * trace_triangle and trace_box (trace.h has the contracts).
 *
 * Both kernels are robust rather than epsilon-based:
 * - isect_triangle is the watertight test of Woop, Benthin and Wald,
 *   "Watertight ray/triangle intersection", JCGT 2(1), 2013, for the
 *   hit/miss decision; additions of ours, only for candidate hits,
 *   reject zero-area triangles and compute t from the triangle's geometry
 *   rather than from the rounded barycentrics (both in double), and clamp
 *   t into the triangle's box as isect_box computes it, so that
 *   traversal, which culls boxes by entry distance, agrees with the brute
 *   force (isect_clamp_to_box);
 * - isect_box is the slab test with the conservative far distance of Ize,
 *   "Robust BVH ray traversal", JCGT 2(2), 2013 (also PBRT 3rd ed.,
 *   sec. 3.9.2, Bounds3::IntersectP).
 *
 * Floating point: the watertight guarantee needs each edge function
 * a*b - c*d to round exactly like its mirror c*d - a*b in the neighbouring
 * triangle.  A fused multiply-add breaks that symmetry (measured: with
 * fmaf in the edge functions, conformance/internal/triangle_watertight.c
 * sees ~0.5% of rays aimed at shared edges leak), so contraction is
 * switched off for this header's functions: clang honours the pragma;
 * GCC does not contract in ISO C mode (-std=c99, which the build uses).
 */
#ifndef RT_TRACE_INTERSECT_H
#define RT_TRACE_INTERSECT_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "trace/trace.h"

/* isect_box_pair tests two sibling boxes at once with SSE2 (the x86-64
 * baseline); elsewhere traversal calls isect_box twice. */
#if defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <emmintrin.h>
#define ISECT_PAIR_SSE 1
#else
#define ISECT_PAIR_SSE 0
#endif

/*
 * Ize 2013: with the three roundings of a slab distance ((b - o) * inv,
 * inv itself rounded), t_far * (1 + 2 gamma(3)) is never below the exact
 * far distance, gamma(n) = n u / (1 - n u), u = 2^-24.  1 + 2 gamma(3) is
 * 1 + 3.0000002 * 2^-23, which lies between two floats; the constant is
 * the upper one, 1 + 4 * 2^-23, so that rounding cannot make the factor
 * smaller than the bound.
 */
#define ISECT_BOX_FAR_SCALE (1.0f + 4.0f * 0x1p-23f)

/* A triangle thinner than this many roundings of its sheared coordinates
 * is a sliver for isect_triangle's t (see there).  Chosen with margin:
 * the edge test's own error is a few roundings. */
#define ISECT_SLIVER_ROUNDINGS 64.0

/* The next float above a finite f >= 0 (nextafterf without the libm call,
 * which would sit in the triangle loop). */
static inline float isect_next_up(float f)
{
    /* -0 too (a hit at t = -0, the origin on the surface): its bits + 1
     * would be the negative denormal, below it. */
    if (f == 0.0f)
        return 0x1p-149f;
    uint32_t bits;
    memcpy(&bits, &f, sizeof(bits));
    bits++;
    memcpy(&f, &bits, sizeof(f));
    return f;
}

/* fminf and fmaxf as the library computed them before they were inlined
 * (glibc on x86-64: minss/maxss, so the second argument on a tie, which
 * decides the sign of a zero result), without the libm call through the
 * PLT that GCC emits for them in the triangle loop.  Only used where
 * neither argument can be NaN.  These are also exactly one minss/maxss. */
static inline float isect_min(float a, float b)
{
    return a < b ? a : b;
}

static inline float isect_max(float a, float b)
{
    return a > b ? a : b;
}

/* The slab test's per-ray constants, hoisted out of traversal loops.  For
 * each axis, the byte offsets in a box of the bound the ray enters
 * through and the one it leaves through: the max for a negative
 * direction (-0 included: its inverse is -inf), else the min.  Offsets
 * rather than a selection per test, as PBRT's dirIsNeg indexes its
 * bounds; they address a struct bvh_node's aabb_min/aabb_max. */
struct isect_box_ray {
    float org[3];
    float inv_dir[3];
    uint32_t near_offset[3];
    uint32_t far_offset[3];
    float tmin;
#if ISECT_PAIR_SSE
    /* isect_box_pair's copies: xyz and a zero lane for the node's
     * first/count word, and all-ones lanes where the direction is
     * negative (the near bound is then the max). */
    __m128 org4;
    __m128 inv4;
    __m128 neg4;
    __m128 keep4;
    __m128 tmin4;
#endif
};

static inline void isect_box_ray_init(struct isect_box_ray *br, const struct trace_ray *ray)
{
    for (int k = 0; k < 3; k++) {
        uint32_t lo = (uint32_t)(offsetof(struct bvh_node, aabb_min) + sizeof(float) * k);
        uint32_t hi = (uint32_t)(offsetof(struct bvh_node, aabb_max) + sizeof(float) * k);
        int neg = signbit(ray->inv_dir[k]) != 0;
        br->org[k] = ray->org[k];
        br->inv_dir[k] = ray->inv_dir[k];
        br->near_offset[k] = neg ? hi : lo;
        br->far_offset[k] = neg ? lo : hi;
    }
    br->tmin = ray->tmin;
#if ISECT_PAIR_SSE
    br->org4 = _mm_setr_ps(ray->org[0], ray->org[1], ray->org[2], 0.0f);
    br->inv4 = _mm_setr_ps(ray->inv_dir[0], ray->inv_dir[1], ray->inv_dir[2], 0.0f);
    /* The sign bit of each inverse, spread over its lane. */
    br->neg4 = _mm_castsi128_ps(_mm_srai_epi32(_mm_castps_si128(br->inv4), 31));
    br->keep4 = _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0));
    br->tmin4 = _mm_set1_ps(ray->tmin);
#endif
}

static inline float isect_bound(const struct bvh_node *node, uint32_t offset)
{
    /* Byte arithmetic inside the node, landing on one of its floats. */
    return *(const float *)(const void *)((const char *)node + offset);
}

/*
 * Returns 1 and *t_entry = max(entry, tmin) when the ray's interval
 * [tmin, t_max] overlaps the node's box (closed: conservative for
 * [tmin, t_max)).
 *
 * Axis-parallel rays: inv_dir is +-inf, so a slab the origin lies strictly
 * inside gives (-inf, +inf) and one it lies outside gives an empty
 * interval.  When the origin lies exactly on a slab's plane, 0 * inf is
 * NaN; the comparisons below are written so that a NaN never replaces
 * the running bound (an unordered `>` or `<` is false), i.e. that slab is
 * treated as containing the ray, the conservative answer.  No NaN reaches
 * *t_entry.
 */
static inline int isect_box(const struct isect_box_ray *br, const struct bvh_node *node,
                            float t_max, float *t_entry)
{
    float t0 = br->tmin;
    float t_far_min = INFINITY;
    for (int k = 0; k < 3; k++) {
        float t_near = (isect_bound(node, br->near_offset[k]) - br->org[k]) * br->inv_dir[k];
        float t_far = (isect_bound(node, br->far_offset[k]) - br->org[k]) * br->inv_dir[k];
        t0 = t_near > t0 ? t_near : t0;
        t_far_min = t_far < t_far_min ? t_far : t_far_min;
    }
    /* Ize 2013's robust far bound, applied once to the smallest far
     * distance instead of to each of the three: multiplying by a
     * positive constant is monotone under rounding, so
     * min_k(fl(t_k * s)) = fl(min_k(t_k) * s) bit for bit (NaN slabs are
     * skipped either way; +inf stays +inf). */
    float t1 = t_far_min * ISECT_BOX_FAR_SCALE;
    t1 = t1 < t_max ? t1 : t_max;
    *t_entry = t0;
    return t0 <= t1;
}

/*
 * The boxes of two sibling nodes (pair[0], pair[1]) at once: bit 0 of
 * the result is isect_box's answer for pair[0], bit 1 for pair[1], and
 * t_entry[0..1] their entry distances.  The same float operations as
 * isect_box, lane by lane: each slab distance is the same (bound - org)
 * * inv, the near/far choice is the same sign test, and min/max are
 * minps/maxps, which return their second operand when the first is NaN,
 * exactly the `a < b ? a : b` of isect_box, so a NaN slab is skipped as
 * there.  Only the order in which the three slabs are folded differs;
 * max and min do not care, except that an entry distance of zero may
 * come out as -0 where isect_box gives +0 (or the reverse), which only
 * ever meets comparisons (-0 == +0), never an answer.
 */
#if ISECT_PAIR_SSE
static inline unsigned isect_box_pair(const struct isect_box_ray *br,
                                      const struct bvh_node *pair, float t_max,
                                      float t_entry[2])
{
    const __m128 keep = br->keep4;
    const __m128 lmin = _mm_and_ps(_mm_loadu_ps(pair[0].aabb_min), keep);
    const __m128 lmax = _mm_and_ps(_mm_loadu_ps(pair[0].aabb_max), keep);
    const __m128 rmin = _mm_and_ps(_mm_loadu_ps(pair[1].aabb_min), keep);
    const __m128 rmax = _mm_and_ps(_mm_loadu_ps(pair[1].aabb_max), keep);
    const __m128 la = _mm_mul_ps(_mm_sub_ps(lmin, br->org4), br->inv4);
    const __m128 lb = _mm_mul_ps(_mm_sub_ps(lmax, br->org4), br->inv4);
    const __m128 ra = _mm_mul_ps(_mm_sub_ps(rmin, br->org4), br->inv4);
    const __m128 rb = _mm_mul_ps(_mm_sub_ps(rmax, br->org4), br->inv4);
    /* Swap min and max distances where the direction is negative. */
    const __m128 ld = _mm_and_ps(_mm_xor_ps(la, lb), br->neg4);
    const __m128 rd = _mm_and_ps(_mm_xor_ps(ra, rb), br->neg4);
    const __m128 lnear = _mm_xor_ps(la, ld);
    const __m128 lfar = _mm_xor_ps(lb, ld);
    const __m128 rnear = _mm_xor_ps(ra, rd);
    const __m128 rfar = _mm_xor_ps(rb, rd);
    /* [Lx Rx Ly Ry] and [Lz Rz - -]. */
    const __m128 near_xy = _mm_unpacklo_ps(lnear, rnear);
    const __m128 near_z = _mm_unpackhi_ps(lnear, rnear);
    const __m128 far_xy = _mm_unpacklo_ps(lfar, rfar);
    const __m128 far_z = _mm_unpackhi_ps(lfar, rfar);
    __m128 t0 = _mm_max_ps(near_xy, br->tmin4);
    t0 = _mm_max_ps(_mm_movehl_ps(t0, t0), t0);
    t0 = _mm_max_ps(near_z, t0);
    __m128 t1 = _mm_min_ps(far_xy, _mm_set1_ps(INFINITY));
    t1 = _mm_min_ps(_mm_movehl_ps(t1, t1), t1);
    t1 = _mm_min_ps(far_z, t1);
    t1 = _mm_mul_ps(t1, _mm_set1_ps(ISECT_BOX_FAR_SCALE));
    t1 = _mm_min_ps(t1, _mm_set1_ps(t_max));
    t_entry[0] = _mm_cvtss_f32(t0);
    t_entry[1] = _mm_cvtss_f32(_mm_shuffle_ps(t0, t0, 1));
    return (unsigned)_mm_movemask_ps(_mm_cmple_ps(t0, t1)) & 3u;
}
#endif

/*
 * The ray's parameter interval through one slab of a triangle's box, as
 * isect_box computes it: d0, d1, d2 are the vertices' coordinates minus
 * the origin on that axis, rounded (the float differences isect_triangle
 * has at hand), inv is ray->inv_dir on that axis.  Rounding is monotone,
 * so min(d) * inv is bit for bit isect_box's (min(v) - org) * inv for the
 * triangle's own box, and no larger than its value for any box holding
 * the triangle (whose bound is at most min(v)); likewise for the far end.
 * A NaN end (0 * inf: the origin on the slab's plane, zero direction)
 * leaves the interval alone, as isect_box ignores it.
 */
static inline void isect_slab(float d0, float d1, float d2, float inv, float *t_lo, float *t_hi)
{
    /* Plain comparisons rather than fminf, which is a libm call here. */
    float lo = d0 < d1 ? d0 : d1;
    float hi = d0 < d1 ? d1 : d0;
    lo = lo < d2 ? lo : d2;
    hi = hi > d2 ? hi : d2;
    const float t_near = (inv < 0.0f ? hi : lo) * inv;
    const float t_far = (inv < 0.0f ? lo : hi) * inv;
    *t_lo = t_near > *t_lo ? t_near : *t_lo;
    *t_hi = t_far < *t_hi ? t_far : *t_hi;
}

/*
 * isect_clamp_interval computes [t_lo, t_hi], the ray's interval through
 * the triangle's box as isect_box computes it, and isect_clamp_to_box
 * clamps a hit distance t into it (isect_slab;
 * tag-graze-t-in-box).  When the interval is empty (the rounded edge
 * test accepted a ray that passes a rounding error beside the box) the
 * result is t_lo.  A NaN t gives t_hi or t_lo.
 *
 * Why.  Traversal culls a box whose entry distance lies beyond the
 * closest hit so far; that is only sound if the point org + t dir of
 * every hit lies in its triangle's box, hence in every ancestor's box.
 * The hit/miss decision of Woop, Benthin and Wald 2013 is made on
 * sheared, rounded coordinates, so it accepts rays that pass within a
 * few ulps of the triangle (as it must, for watertightness), while t is
 * computed separately: the paper's T / det, or here the plane distance.
 * For a ray through (or an ulp beside) a vertex or an edge at a grazing
 * angle theta to the plane, that sideways error of the decision becomes
 * an error along the ray of about ulps / sin(theta).  Measured on a unit
 * sphere (conformance/internal/traversal_grazing.c): a ray aimed at a
 * vertex passes it by ~1e-8 and meets the plane of one of its triangles
 * at 0.1 degrees, at t = 0.999995 where the vertex is at t = 1; that
 * point is 2.5e-6 outside the triangle's box, whose entry distance is 1,
 * 80 ulps beyond t.  PBRT 3rd ed. sec. 3.9.6 bounds the error of T / det
 * (to reject hits behind the origin): the bound grows as 1 / |det|, i.e.
 * without limit as the ray turns into the plane, so no constant relative
 * widening of the box test (ISECT_BOX_FAR_SCALE, Ize 2013) or of the
 * boxes at build time can cover it.  Clamping makes the reported point
 * consistent with the box by construction and changes nothing for a ray
 * that really crosses the triangle away from the box's faces.
 *
 * The guarantee is exact, not an error bound, because the clamp uses
 * the box test's own roundings: for any box holding the triangle and any
 * t_max >= t, isect_box returns 1 with an entry distance <= t (each
 * slab's computed near end is <= t_lo <= t and far end >= t_hi >= t, by
 * monotone rounding; Ize's scaling of the far end only widens), so
 * traverse.c's culling against best * ISECT_BOX_FAR_SCALE
 * (tag-graze-box-limit) never skips the box of a hit at or below best.
 * The kz slab is [z_lo, z_hi] bit for bit (ray->sz is ray->inv_dir[kz]):
 * the vertices' depth range, to which t was clamped before, so t only
 * changes where it lay outside the box on the kx or ky axis.  In an
 * empty interval t_lo keeps the entry <= t; whether the box is accepted
 * then depends on Ize's far scaling, as for any box the exact ray
 * misses by a rounding error.
 */
static inline void isect_clamp_interval(const struct trace_ray *ray, float ax, float bx,
                                        float cx, float ay, float by, float cy, float z_lo,
                                        float z_hi, float *t_lo, float *t_hi)
{
    *t_lo = z_lo;
    *t_hi = z_hi;
    isect_slab(ax, bx, cx, ray->inv_dir[ray->kx], t_lo, t_hi);
    isect_slab(ay, by, cy, ray->inv_dir[ray->ky], t_lo, t_hi);
}

static inline float isect_clamp_to_box(float t_lo, float t_hi, float t)
{
    t = t < t_hi ? t : t_hi;
    return t > t_lo ? t : t_lo;
}

/*
 * isect_triangle_zero_area: 1 when the cross product of the triangle's
 * edge vectors, computed in double as isect_triangle_finish computes it
 * (the same expressions in the same order, so the same doubles), is
 * exactly zero: the triangles isect_triangle never hits, whatever the
 * ray.  The wide layout's packets (bvh4_layout.h) mark such a lane when
 * they are filled, so that the packet test never keeps it and its finish
 * (area_known below) skips this test.
 */
static inline int isect_triangle_zero_area(float x0, float y0, float z0, float x1, float y1,
                                           float z1, float x2, float y2, float z2)
{
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
    const double e1x = (double)x1 - x0;
    const double e1y = (double)y1 - y0;
    const double e1z = (double)z1 - z0;
    const double e2x = (double)x2 - x0;
    const double e2y = (double)y2 - y0;
    const double e2z = (double)z2 - z0;
    const double nx = e1y * e2z - e1z * e2y;
    const double ny = e1z * e2x - e1x * e2z;
    const double nz = e1x * e2y - e1y * e2x;
    return nx == 0.0 && ny == 0.0 && nz == 0.0;
}

/*
 * The bound 2 (l1 + l2) on the longest edge's squared length, with a
 * margin for the roundings: the finish compares n2 against r2 times
 * fl(fl(l1 + l2) * ISECT_LONGEST_EDGE_BOUND), which must be at least
 * each of the computed l1, l2, l3 (isect_sliver_edges).  Let a = e1, b =
 * e2 be the edge vectors as doubles and u = 2^-53.  Every value here is
 * a sum of non-negative terms, without underflow (a non-zero difference
 * of floats is at least 2^-149, its square 2^-298, a normal double) or
 * overflow (the squares stay below 2^258), so each operation's relative
 * error is at most u:
 * - l1 >= |a|^2 (1 - u)^3 and l2 >= |b|^2 (1 - u)^3 (three roundings:
 *   the squares, two additions);
 * - e3_k = fl(b_k - a_k) has |e3_k| <= (|a_k| + |b_k|) (1 + u), so
 *   fl(e3_k^2) <= (|a_k| + |b_k|)^2 (1 + u)^3 <= 2 (a_k^2 + b_k^2)
 *   (1 + u)^3 ((x + y)^2 <= 2 x^2 + 2 y^2), and l3 <= 2 (|a|^2 + |b|^2)
 *   (1 + u)^5;
 * - the bound is >= (l1 + l2) K (1 - u)^2 >= (|a|^2 + |b|^2) K (1 - u)^5
 *   for K = ISECT_LONGEST_EDGE_BOUND.
 * K = 2 + 2^-40 > 2 (1 + u)^5 / (1 - u)^5 (about 2 + 2^-49), so the
 * bound is >= l3; and >= 2 (l1 + l2) (1 - u)^2 >= l1, l2.  K is exact in
 * double.
 */
#define ISECT_LONGEST_EDGE_BOUND (2.0 + 0x1p-40)

/*
 * The finish's test for a proper triangle on the longest edge itself,
 * when the bound above did not decide: the third edge e3 = e2 - e1 and
 * its squared length *l3 (for isect_sliver_t), lmax the largest of l1,
 * l2, l3, and 1 when n2 >= fl(r2 * lmax), the test the finish made on
 * every candidate before the bound.  Apart because nearly every
 * candidate is decided by the bound.
 */
static inline int isect_sliver_edges(double e1x, double e1y, double e1z, double e2x,
                                     double e2y, double e2z, double l1, double l2, double r2,
                                     double n2, double e3[3], double *l3)
{
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
    e3[0] = e2x - e1x;
    e3[1] = e2y - e1y;
    e3[2] = e2z - e1z;
    *l3 = e3[0] * e3[0] + e3[1] * e3[1] + e3[2] * e3[2];
    /* The longest edge's squared length as a maximum (maxsd: `a > b ?
     * a : b`), without a branch: which edge is longest is a coin toss
     * for the branch predictor (callgrind, gears' camera rays: the first
     * comparison went each way 60/40).  The same value as choosing the
     * first of l1, l2, l3 that is >= the others: the squares and sums of
     * differences of finite floats are finite, so no NaN, and equal
     * maxima are the same double (all >= +0). */
    const double l12 = l1 > l2 ? l1 : l2;
    const double lmax = l12 > *l3 ? l12 : *l3;
    return n2 >= r2 * lmax;
}

/* isect_triangle_finish_impl's t for a sliver (see there): the ray's
 * closest approach to the longest edge (p, p + e), e1 = v1 - v0, e2 =
 * v2 - v0 (starting at v0) or e3 = e2 - e1 (starting at v1), with their
 * squared lengths l1, l2, l3; the first of them that is >= the others.
 * NaN when the ray is parallel to that edge.  Apart from the finish
 * because only slivers reach it.  ray_d as for
 * isect_triangle_finish_impl. */
static inline double isect_sliver_t(const struct trace_ray *ray, const double *ray_d,
                                    const float v0[3], const float v1[3], const double e1[3],
                                    const double e2[3], const double e3[3], double l1, double l2,
                                    double l3)
{
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
    const int longest = l1 >= l2 && l1 >= l3 ? 1 : (l2 >= l3 ? 2 : 3);
    const double *e = longest == 1 ? e1 : (longest == 2 ? e2 : e3);
    const double ex = e[0], ey = e[1], ez = e[2];
    const double dx = ray_d ? ray_d[4] : (double)ray->dir[0];
    const double dy = ray_d ? ray_d[5] : (double)ray->dir[1];
    const double dz = ray_d ? ray_d[6] : (double)ray->dir[2];
    const double wx =
        (double)(longest == 3 ? v1[0] : v0[0]) - (ray_d ? ray_d[0] : (double)ray->org[0]);
    const double wy =
        (double)(longest == 3 ? v1[1] : v0[1]) - (ray_d ? ray_d[1] : (double)ray->org[1]);
    const double wz =
        (double)(longest == 3 ? v1[2] : v0[2]) - (ray_d ? ray_d[2] : (double)ray->org[2]);
    const double dd = dx * dx + dy * dy + dz * dz;
    const double de = dx * ex + dy * ey + dz * ez;
    const double ee = ex * ex + ey * ey + ez * ez;
    const double dw = dx * wx + dy * wy + dz * wz;
    const double ew = ex * wx + ey * wy + ez * wz;
    const double den = dd * ee - de * de;
    return den > 0.0 ? (ee * dw - de * ew) / den : NAN;
}

/*
 * The rest of isect_triangle once its float part has accepted the
 * triangle as a candidate below t_max: the zero-area test, t and its
 * clamp, the barycentrics.  U, V, W, det, Az, Bz, Cz, t_lo, t_hi and
 * size (the largest |sheared x, y| of the three vertices) are the float
 * values isect_triangle computed; the SIMD leaf test (intersect_tri4.h)
 * computes the same floats four lanes at a time and calls this for the
 * lanes it keeps, so that a candidate costs no second float pass.
 * isect_triangle_finish9 is this with area_known 0.  area_known 1 (a
 * constant where it is inlined): the caller knows the triangle is not
 * isect_triangle_zero_area (a packet lane the filter kept: such a lane
 * is marked NaN when the packet is filled), so the zero-area test, which
 * would pass, is left out; every other step is the same.  ray_d: NULL,
 * or the ray's origin and direction already in double (org[0..2] at
 * 0..2, dir[0..2] at 4..6: tri4_ray_init_double), so that a ray finishing
 * several candidates converts them once.
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int isect_triangle_finish_impl(const struct trace_ray *ray,
                                             const double *ray_d, float x0, float y0,
                                             float z0, float x1, float y1, float z1, float x2,
                                             float y2, float z2, float U, float V, float W,
                                             float det, float Az, float Bz, float Cz,
                                             float size, float t_lo, float t_hi, float t_max,
                                             int area_known, float *t_out, float *u_out,
                                             float *v_out)
{
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
    /* The vertices by value (isect_triangle_finish below takes them by
     * pointer): the packet leaf (intersect_tri4.h) passes a lane's
     * coordinates straight from the packet, without copying them to
     * three arrays first. */
    const float v0[3] = {x0, y0, z0};
    const float v1[3] = {x1, y1, z1};
    const float v2[3] = {x2, y2, z2};
    const float rcp_det = 1.0f / det;

    /* A triangle whose vertices are collinear can still project to a tiny
     * non-zero area once the sheared coordinates are rounded (measured:
     * about one ray in ten aimed at such a triangle hit it).  It has no
     * area, so it is never hit: the edge vectors' cross product in double
     * is exactly zero for collinear float vertices (the differences are
     * exact when the coordinates are within 2^29 of each other, and equal
     * products round equally).  Our addition to the paper; it runs only
     * for candidate hits.  A closed mesh that contains such a triangle
     * can leak through the sliver its rounded projection covers; meshes
     * without zero-area triangles keep the paper's guarantee. */
    const double e1x = (double)v1[0] - v0[0];
    const double e1y = (double)v1[1] - v0[1];
    const double e1z = (double)v1[2] - v0[2];
    const double e2x = (double)v2[0] - v0[0];
    const double e2y = (double)v2[1] - v0[1];
    const double e2z = (double)v2[2] - v0[2];
    const double nx = e1y * e2z - e1z * e2y;
    const double ny = e1z * e2x - e1x * e2z;
    const double nz = e1x * e2y - e1y * e2x;
    if (!area_known && nx == 0.0 && ny == 0.0 && nz == 0.0)
        return 0;

    /* t.  The paper's T / det is only as good as U, V, W: fine for a
     * proper triangle, but for a sliver thinner than the rounding of the
     * sheared coordinates the weights are noise and T / det lands anywhere
     * between the vertices' depths.  So (our addition too) t comes from
     * geometry computed in double from the exact edge vectors above:
     * - a proper triangle: the distance to its plane;
     * - a sliver, whose height is below ISECT_SLIVER_ROUNDINGS roundings
     *   of the sheared coordinates: there the edge test itself cannot
     *   tell whether the ray passes through the sliver or beside it, and
     *   the plane is no better than that, so t is the ray's closest
     *   approach to the sliver's longest edge.
     * The paper's t remains when the double computation is degenerate (a
     * ray parallel to the plane, or to the edge).  Whichever it is, t is
     * then clamped into the triangle's box (isect_clamp_to_box). */
    float t;
    {
        /* The ray's origin and direction in double: ray_d's when the
         * caller has them (the single-ray closest-hit leaves convert them
         * once a ray, tri4_ray_init_double), else converted here.  A float
         * converts to double exactly, so either way they are the same
         * doubles; only where the conversions happen differs.  With ray_d
         * NULL (a constant where this is inlined) the code is as before. */
        const double dx = ray->dir[0];
        const double dy = ray->dir[1];
        const double dz = ray->dir[2];
        const double n2 = nx * nx + ny * ny + nz * nz;
        const double l1 = e1x * e1x + e1y * e1y + e1z * e1z;
        const double l2 = e2x * e2x + e2y * e2y + e2z * e2z;
        /* One rounding of the sheared coordinates: 2^-24 of their size. */
        const double rounding = ISECT_SLIVER_ROUNDINGS * 0x1p-24 * (double)size;
        const double r2 = rounding * rounding;
        /* A proper triangle when height^2 = n2 / lmax >= r2, lmax the
         * longest edge's squared length (isect_sliver_edges).  Decided
         * first on the bound lmax <= 2 (l1 + l2) (isect_sliver_edges
         * proves it for the computed values with the margin of
         * ISECT_LONGEST_EDGE_BOUND), which needs neither the third edge
         * nor the maxima: when n2 >= fl(r2 * bound), then n2 >= fl(r2 *
         * lmax) too (bound >= lmax, r2 >= 0, and rounding is monotone),
         * the test below would say the same.  Otherwise the test on lmax
         * itself decides, as before: the same answer either way. */
        int proper = n2 >= r2 * ((l1 + l2) * ISECT_LONGEST_EDGE_BOUND);
        double e3[3], l3 = 0.0;
        if (!proper)
            proper = isect_sliver_edges(e1x, e1y, e1z, e2x, e2y, e2z, l1, l2, r2, n2, e3, &l3);
        if (proper) {
            /* height^2 = n2 / lmax: a proper triangle, t the distance to
             * its plane.  num is finite (finite factors, far below the
             * double range) and den finite, so num / den is never NaN
             * when den != 0: the paper's t is needed only when den == 0. */
            /* ray_d's direction read here, at its use, not above with
             * dx, dy, dz (unused then, and dropped): read above, GCC
             * loaded the three doubles early and kept them on the stack
             * through the sliver test. */
            const double den = ray_d ? nx * ray_d[4] + ny * ray_d[5] + nz * ray_d[6]
                                     : nx * dx + ny * dy + nz * dz;
            const double ox = ray_d ? ray_d[0] : (double)ray->org[0];
            const double oy = ray_d ? ray_d[1] : (double)ray->org[1];
            const double oz = ray_d ? ray_d[2] : (double)ray->org[2];
            const double num = nx * ((double)v0[0] - ox) + ny * ((double)v0[1] - oy) +
                               nz * ((double)v0[2] - oz);
            if (den != 0.0)
                t = (float)(num / den);
            else
                t = (U * Az + V * Bz + W * Cz) * rcp_det;
        } else {
            const double e1[3] = {e1x, e1y, e1z};
            const double e2[3] = {e2x, e2y, e2z};
            const double tp = isect_sliver_t(ray, ray_d, v0, v1, e1, e2, e3, l1, l2, l3);
            t = !isnan(tp) ? (float)tp : (U * Az + V * Bz + W * Cz) * rcp_det;
        }
    }
    t = isect_clamp_to_box(t_lo, t_hi, t);
    if (!(t >= ray->tmin && t < t_max) || !isfinite(t))
        return 0;

    *t_out = t;
    *u_out = V * rcp_det;
    *v_out = W * rcp_det;
    return 1;
}

static inline int isect_triangle_finish9(const struct trace_ray *ray, float x0, float y0,
                                         float z0, float x1, float y1, float z1, float x2,
                                         float y2, float z2, float U, float V, float W,
                                         float det, float Az, float Bz, float Cz, float size,
                                         float t_lo, float t_hi, float t_max, float *t_out,
                                         float *u_out, float *v_out)
{
    return isect_triangle_finish_impl(ray, NULL, x0, y0, z0, x1, y1, z1, x2, y2, z2, U, V, W, det,
                                      Az,
                                      Bz, Cz, size, t_lo, t_hi, t_max, 0, t_out, u_out, v_out);
}

static inline int isect_triangle_finish(const struct trace_ray *ray, const float v0[3],
                                        const float v1[3], const float v2[3], float U, float V,
                                        float W, float det, float Az, float Bz, float Cz,
                                        float size, float t_lo, float t_hi, float t_max,
                                        float *t_out, float *u_out, float *v_out)
{
    return isect_triangle_finish9(ray, v0[0], v0[1], v0[2], v1[0], v1[1], v1[2], v2[0], v2[1],
                                  v2[2], U, V, W, det, Az, Bz, Cz, size, t_lo, t_hi, t_max,
                                  t_out, u_out, v_out);
}

/* isect_triangle_occludes9's short way (see there): every t the finish
 * can compute is clamped into [t_lo, t_hi], which lies inside [tmin,
 * t_max) and is finite. */
static inline int isect_occludes_short(const struct trace_ray *ray, float t_lo, float t_hi,
                                       float t_max)
{
    return t_lo >= ray->tmin && t_lo <= t_hi && t_hi < t_max && isfinite(t_lo) &&
           isfinite(t_hi);
}

/*
 * isect_triangle_finish's answer without t, for any-hit queries.  The
 * final t is clamped into [t_lo, t_hi] (isect_clamp_to_box: a NaN or
 * infinite t comes out as t_hi or t_lo), so when that interval is not
 * empty, finite and lies inside [tmin, t_max), every t is accepted and
 * only the zero-area test can refuse the triangle: the division and the
 * double-precision distance are skipped.  Otherwise
 * isect_triangle_finish decides.  Shadow rays, whose t_max is the light's
 * distance, nearly always take the short way.  area_known (a packet
 * lane, as for isect_triangle_finish_impl): the short way needs no
 * double at all.
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int isect_triangle_occludes_impl(const struct trace_ray *ray, float x0, float y0,
                                               float z0, float x1, float y1, float z1, float x2,
                                               float y2, float z2, float U, float V, float W,
                                               float det, float Az, float Bz, float Cz,
                                               float size, float t_lo, float t_hi, float t_max,
                                               int area_known)
{
    if (isect_occludes_short(ray, t_lo, t_hi, t_max))
        return area_known || !isect_triangle_zero_area(x0, y0, z0, x1, y1, z1, x2, y2, z2);
    float t, u, v;
    return isect_triangle_finish_impl(ray, NULL, x0, y0, z0, x1, y1, z1, x2, y2, z2, U, V, W, det,
                                      Az,
                                      Bz, Cz, size, t_lo, t_hi, t_max, area_known, &t, &u, &v);
}

static inline int isect_triangle_occludes9(const struct trace_ray *ray, float x0, float y0,
                                           float z0, float x1, float y1, float z1, float x2,
                                           float y2, float z2, float U, float V, float W,
                                           float det, float Az, float Bz, float Cz, float size,
                                           float t_lo, float t_hi, float t_max)
{
    return isect_triangle_occludes_impl(ray, x0, y0, z0, x1, y1, z1, x2, y2, z2, U, V, W, det,
                                        Az, Bz, Cz, size, t_lo, t_hi, t_max, 0);
}

/*
 * The watertight test of Woop, Benthin and Wald 2013, without backface
 * culling: returns 1 with the hit when tmin <= t < t_max.
 * u, v are the weights of v1 and v2 (trace.h).
 */
static inline int isect_triangle(const struct trace_ray *ray, const float v0[3],
                                 const float v1[3], const float v2[3], float t_max, float *t_out,
                                 float *u_out, float *v_out)
{
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
    const int kx = ray->kx;
    const int ky = ray->ky;
    const int kz = ray->kz;

    /* Vertices relative to the origin. */
    const float ax = v0[kx] - ray->org[kx];
    const float ay = v0[ky] - ray->org[ky];
    const float az = v0[kz] - ray->org[kz];
    const float bx = v1[kx] - ray->org[kx];
    const float by = v1[ky] - ray->org[ky];
    const float bz = v1[kz] - ray->org[kz];
    const float cx = v2[kx] - ray->org[kx];
    const float cy = v2[ky] - ray->org[ky];
    const float cz = v2[kz] - ray->org[kz];

    /* Shear so that the ray runs along +z (sx, sy are stored negated:
     * a + sx * b is the paper's a - Sx * b, bit for bit). */
    const float Ax = ax + ray->sx * az;
    const float Ay = ay + ray->sy * az;
    const float Bx = bx + ray->sx * bz;
    const float By = by + ray->sy * bz;
    const float Cx = cx + ray->sx * cz;
    const float Cy = cy + ray->sy * cz;

    /* Scaled barycentrics: each edge function is computed the same way
     * for both triangles sharing the edge, up to an exact sign flip. */
    float U = Cx * By - Cy * Bx;
    float V = Ax * Cy - Ay * Cx;
    float W = Bx * Ay - By * Ax;

    /* Sec. 4: an edge function that rounds to exactly 0 may have the wrong
     * sign; recompute all three in double, where the products of floats
     * are exact and each difference rounds once.  The signs are decided
     * on the doubles: a tiny non-zero value can underflow to 0 in the
     * cast to float (sheared coordinates of denormal size, e.g. an origin
     * 1e-45 beside the plane of a vertex with a zero direction component
     * along it), which would read as "on the edge" and accept a ray that
     * misses the triangle and its box. */
    if (U == 0.0f || V == 0.0f || W == 0.0f) {
        const double CxBy = (double)Cx * (double)By;
        const double CyBx = (double)Cy * (double)Bx;
        const double AxCy = (double)Ax * (double)Cy;
        const double AyCx = (double)Ay * (double)Cx;
        const double BxAy = (double)Bx * (double)Ay;
        const double ByAx = (double)By * (double)Ax;
        const double dU = CxBy - CyBx;
        const double dV = AxCy - AyCx;
        const double dW = BxAy - ByAx;
        if ((dU < 0.0 || dV < 0.0 || dW < 0.0) && (dU > 0.0 || dV > 0.0 || dW > 0.0))
            return 0;
        U = (float)dU;
        V = (float)dV;
        W = (float)dW;
    }

    /* Outside when the signs differ; a point on an edge (0) is inside. */
    if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f))
        return 0;

    /* Zero projected area: degenerate, or seen exactly edge-on.  A
     * non-finite det (NaN or overflowing input) is refused here, which
     * keeps every later value finite. */
    const float det = U + V + W;
    if (det == 0.0f || !isfinite(det))
        return 0;

    /* The sheared depths of the vertices, whose range [z_lo, z_hi] is
     * the ray's interval through the kz slab of the triangle's box as
     * isect_box computes it (ray->sz is ray->inv_dir[kz]).  The final t
     * is clamped into the box's interval (isect_clamp_to_box), so t >=
     * z_lo always and t <= z_hi when the ray crosses the box: a cheap
     * early rejection that never refuses a triangle the test on t at the
     * end would accept below t_max (NaN from overflowing input fails
     * too).  Whether a triangle is hit below t_max thus depends on its t
     * alone, so the brute force and traversal, which pass different
     * t_max, agree about near-ties (tag-graze-t-in-box). */
    const float Az = ray->sz * az;
    const float Bz = ray->sz * bz;
    const float Cz = ray->sz * cz;
    /* Az..Cz are not NaN here: a NaN depth comes from a NaN vertex
     * coordinate, which made det NaN above. */
    const float z_lo = isect_min(Az, isect_min(Bz, Cz));
    const float z_hi = isect_max(Az, isect_max(Bz, Cz));
    if (!(z_hi >= ray->tmin && z_lo < t_max))
        return 0;

    /* The ray's interval through the triangle's box (isect_clamp_to_box
     * below).  The final t is clamped to at least t_lo, so when t_lo is
     * already at or beyond t_max the triangle cannot be accepted, whatever
     * the double-precision work below would compute: rejecting it here
     * gives the same answer without that work.  This is the common case
     * of a candidate behind the closest hit so far. */
    float t_lo, t_hi;
    isect_clamp_interval(ray, ax, bx, cx, ay, by, cy, z_lo, z_hi, &t_lo, &t_hi);
    if (!(t_lo < t_max))
        return 0;
    /* isect_triangle_finish's size: the largest sheared |x|, |y|. */
    float size = isect_max(isect_max(fabsf(Ax), fabsf(Ay)), isect_max(fabsf(Bx), fabsf(By)));
    size = isect_max(size, isect_max(fabsf(Cx), fabsf(Cy)));
    return isect_triangle_finish(ray, v0, v1, v2, U, V, W, det, Az, Bz, Cz, size, t_lo, t_hi,
                                 t_max, t_out, u_out, v_out);
}

#endif
