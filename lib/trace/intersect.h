/*
 * intersect.h - the ray/triangle and ray/box kernels, static inline so that
 * traversal compiles them into its loops; intersect.c exports them as
 * trace_triangle and trace_box (trace.h has the contracts).
 *
 * Both kernels are robust rather than epsilon-based:
 * - isect_triangle is the watertight test of Woop, Benthin and Wald,
 *   "Watertight ray/triangle intersection", JCGT 2(1), 2013, for the
 *   hit/miss decision; two additions of ours, both computed in double and
 *   only for candidate hits, reject zero-area triangles and compute t from
 *   the triangle's geometry rather than from the rounded barycentrics;
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
    uint32_t bits;
    memcpy(&bits, &f, sizeof(bits));
    bits++;
    memcpy(&f, &bits, sizeof(f));
    return f;
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
    float t1 = t_max;
    for (int k = 0; k < 3; k++) {
        float t_near = (isect_bound(node, br->near_offset[k]) - br->org[k]) * br->inv_dir[k];
        float t_far = (isect_bound(node, br->far_offset[k]) - br->org[k]) * br->inv_dir[k];
        t_far *= ISECT_BOX_FAR_SCALE; /* Ize 2013: the robust far bound */
        t0 = t_near > t0 ? t_near : t0;
        t1 = t_far < t1 ? t_far : t1;
    }
    *t_entry = t0;
    return t0 <= t1;
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
     * are exact and each difference rounds once. */
    if (U == 0.0f || V == 0.0f || W == 0.0f) {
        double CxBy = (double)Cx * (double)By;
        double CyBx = (double)Cy * (double)Bx;
        double AxCy = (double)Ax * (double)Cy;
        double AyCx = (double)Ay * (double)Cx;
        double BxAy = (double)Bx * (double)Ay;
        double ByAx = (double)By * (double)Ax;
        U = (float)(CxBy - CyBx);
        V = (float)(AxCy - AyCx);
        W = (float)(BxAy - ByAx);
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

    /* The sheared depths of the vertices: the hit's t is a convex
     * combination of them, so a hit outside their range is impossible
     * (a cheap early rejection; NaN from overflowing input fails too). */
    const float Az = ray->sz * az;
    const float Bz = ray->sz * bz;
    const float Cz = ray->sz * cz;
    const float z_lo = fminf(Az, fminf(Bz, Cz));
    const float z_hi = fmaxf(Az, fmaxf(Bz, Cz));
    if (!(z_hi >= ray->tmin && z_lo < t_max))
        return 0;
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
    if (nx == 0.0 && ny == 0.0 && nz == 0.0)
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
     * Either is clamped to the vertices' depth range, and the paper's t
     * remains when the double computation is degenerate (a ray parallel
     * to the plane, or to the edge). */
    float t = (U * Az + V * Bz + W * Cz) * rcp_det;
    {
        const double dx = ray->dir[0];
        const double dy = ray->dir[1];
        const double dz = ray->dir[2];
        const double n2 = nx * nx + ny * ny + nz * nz;
        /* The longest edge (p, p + e). */
        const double e3x = e2x - e1x;
        const double e3y = e2y - e1y;
        const double e3z = e2z - e1z;
        const double l1 = e1x * e1x + e1y * e1y + e1z * e1z;
        const double l2 = e2x * e2x + e2y * e2y + e2z * e2z;
        const double l3 = e3x * e3x + e3y * e3y + e3z * e3z;
        const int longest = l1 >= l2 && l1 >= l3 ? 1 : (l2 >= l3 ? 2 : 3);
        const double lmax = longest == 1 ? l1 : (longest == 2 ? l2 : l3);
        /* One rounding of the sheared coordinates: 2^-24 of their size. */
        float size = fmaxf(fmaxf(fabsf(Ax), fabsf(Ay)), fmaxf(fabsf(Bx), fabsf(By)));
        size = fmaxf(size, fmaxf(fabsf(Cx), fabsf(Cy)));
        const double rounding = ISECT_SLIVER_ROUNDINGS * 0x1p-24 * (double)size;
        double tp = NAN;
        if (n2 >= rounding * rounding * lmax) {
            /* height^2 = n2 / lmax: a proper triangle. */
            const double den = nx * dx + ny * dy + nz * dz;
            const double num = nx * ((double)v0[0] - ray->org[0]) +
                               ny * ((double)v0[1] - ray->org[1]) +
                               nz * ((double)v0[2] - ray->org[2]);
            if (den != 0.0)
                tp = num / den;
        } else {
            /* e1 and e2 start at v0, e3 at v1. */
            const float *p = longest == 3 ? v1 : v0;
            const double ex = longest == 1 ? e1x : (longest == 2 ? e2x : e3x);
            const double ey = longest == 1 ? e1y : (longest == 2 ? e2y : e3y);
            const double ez = longest == 1 ? e1z : (longest == 2 ? e2z : e3z);
            const double wx = (double)p[0] - ray->org[0];
            const double wy = (double)p[1] - ray->org[1];
            const double wz = (double)p[2] - ray->org[2];
            const double dd = dx * dx + dy * dy + dz * dz;
            const double de = dx * ex + dy * ey + dz * ez;
            const double ee = ex * ex + ey * ey + ez * ez;
            const double dw = dx * wx + dy * wy + dz * wz;
            const double ew = ex * wx + ey * wy + ez * wz;
            const double den = dd * ee - de * de;
            if (den > 0.0)
                tp = (ee * dw - de * ew) / den;
        }
        if (!isnan(tp)) {
            tp = tp > z_lo ? tp : z_lo;
            tp = tp < z_hi ? tp : z_hi;
            t = (float)tp;
        }
    }
    if (!(t >= ray->tmin && t < t_max) || !isfinite(t))
        return 0;

    *t_out = t;
    *u_out = V * rcp_det;
    *v_out = W * rcp_det;
    return 1;
}

#endif
