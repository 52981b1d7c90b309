/* SPDX-License-Identifier: Apache-2.0 */
/*
 * tri4_differential.c - the packet triangle test (trace/intersect_tri4.h)
 * against the scalar watertight test (trace/intersect.h's isect_triangle),
 * randomized, lane by lane.
 *
 * Two checks per packet of four triangles and ray:
 * 1. the filter keeps every lane isect_triangle accepts at the packet's
 *    limit (a lane it drops must be one the scalar test rejects);
 * 2. the leaf as the wide walk tests it (filter once, then tri4_lane_test:
 *    the rest of isect_triangle on the filter's own floats, or for any
 *    hit isect_triangle_occludes, on the kept lanes in order with
 *    walk_leaf's shrinking limit and tie rule) gives bit for bit the
 *    answer of walk_leaf's plain loop over the four triangles: found, t,
 *    u, v and primitive, closest and any.
 * 3. a leaf of 5-8 triangles in two packets as walk_wide8_ray_leaf8 of the AVX2
 *    and AVX-512 tables tests it, one 8-lane call (tri4_pair_filter_lanes;
 *    also the closest-hit walk's copy for a ray's first leaf, which may
 *    refuse the whole leaf right after the signs), against the same leaf
 *    as two 4-lane calls and against walk_leaf's
 *    loop over its triangles: found, t, u, v and primitive bit for bit,
 *    closest (with and without the filter's early return, with and
 *    without an earlier leaf's hit to beat) and any; duplicates across
 *    the two packets make ties between them, and shared edges and the
 *    aims below on-edge hits.
 * The rays are aimed at the triangles' vertices and edge points (where
 * the edge functions are 0 and the double-precision fallback decides),
 * at their insides, and past them; the triangles are random, grid
 * snapped (shared planes, exact zeros), collinear or with repeated
 * vertices, slivers, far from the origin (1e5), and the rays have zero
 * direction components, tmin > 0 and finite limits.  The packets are
 * filled as the collapse fills them (accel_set_packet_lane: a zero-area
 * lane holds NaN, and the packet finish leaves out its zero-area test):
 * a zero-area lane left unmarked is accepted by the packet finish and
 * fails check 2, a proper lane marked fails check 1.  It also counts the
 * lanes the filter kept that the scalar test then rejected: those are
 * the candidate hits the scalar test needs its double precision for
 * (edge-function zeros included), and must be a small share.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "accel_testgeo.h"

#if defined(__SSE2__)
#include "trace/intersect_tri4.h"
#include "trace/kernels.h"

static int failures;

struct leaf_answer {
    int found;
    struct trace_hit hit;
};

/* walk_leaf's loop (traverse_walk.h) over n triangles, after an
 * earlier leaf's answer *before (found or not; its t the limit). */
static struct leaf_answer scalar_leaf_n(const struct trace_ray *ray, const float (*tri)[9],
                                        const uint32_t *prim, int n, float t_max, int any_hit,
                                        const struct leaf_answer *before)
{
    struct leaf_answer a = *before;
    float best = a.found ? a.hit.t : t_max;
    for (int l = 0; l < n; l++) {
        float t, u, w;
        float limit = a.found ? isect_next_up(best) : best;
        if (!isect_triangle(ray, tri[l], tri[l] + 3, tri[l] + 6, limit, &t, &u, &w))
            continue;
        if (any_hit) {
            a.found = 1;
            return a;
        }
        if (a.found && !(t < best || prim[l] < a.hit.prim))
            continue;
        a.found = 1;
        best = t;
        a.hit.t = t;
        a.hit.u = u;
        a.hit.v = w;
        a.hit.prim = prim[l];
    }
    return a;
}

/* walk_leaf's loop over four triangles. */
static struct leaf_answer scalar_leaf(const struct trace_ray *ray, const float tri[4][9],
                                      const uint32_t prim[4], float t_max, int any_hit)
{
    struct leaf_answer none;
    memset(&none, 0, sizeof(none));
    return scalar_leaf_n(ray, tri, prim, 4, t_max, any_hit, &none);
}

/* The same leaf as traverse_wide.h's wide_leaf tests it. */
static struct leaf_answer packet_leaf(const struct trace_ray *ray, const struct tri4_packet *p,
                                      float t_max, int any_hit, unsigned *kept)
{
    struct leaf_answer a;
    memset(&a, 0, sizeof(a));
    struct tri4_ray r4;
    tri4_ray_init(&r4, ray);
    /* The closest-hit finish with the ray's doubles set once, as the
     * single-ray closest-hit leaves take them; the any-hit finish
     * converts them itself. */
    double ray_d[8];
    tri4_ray_init_double(ray_d, ray);
    float best = t_max;
    struct tri4_lanes lanes;
    memset(&lanes, 0, sizeof(lanes)); /* written only for kept lanes */
    /* Any hit: the filter with its early returns, as wide_packet_body
     * calls it. */
    unsigned mask = tri4_candidates_lanes_impl(&r4, p, 15u, t_max, &lanes, any_hit);
    *kept = mask;
    if (any_hit && mask) {
        /* As wide_packet_body: the lanes the ray starts on, refused in
         * float when that is sure. */
        unsigned near = 0;
        for (unsigned l = 0; l < 4; l++)
            near |= (unsigned)(lanes.t_lo[l] < ray->tmin) << l;
        /* The single-ray walks' order (traverse_wide.h,
         * wide_near_refused): the filter's floats first, then the
         * world-space test. */
        near &= mask;
        const unsigned sure = tri4_before_tmin_lanes(&r4, p, &lanes, near, 0);
        mask &= ~sure;
        mask &= ~tri4_before_tmin(ray, p, near & ~sure);
    }
    while (mask) {
        unsigned l = (unsigned)__builtin_ctz(mask);
        mask &= mask - 1u;
        float t, u, w;
        float limit = a.found ? isect_next_up(best) : best;
        /* The filter's floats, the rest of isect_triangle on them (or,
         * any hit, its answer without t). */
        if (!tri4_lane_test(ray, any_hit ? NULL : ray_d, p, &lanes, l, any_hit, limit, &t,
                            &u, &w))
            continue;
        if (any_hit) {
            a.found = 1;
            return a;
        }
        if (a.found && !(t < best || p->prim[l] < a.hit.prim))
            continue;
        a.found = 1;
        best = t;
        a.hit.t = t;
        a.hit.u = u;
        a.hit.v = w;
        a.hit.prim = p->prim[l];
    }
    return a;
}

static void random_triangle(struct tg_rng *r, int kind, const float centre[3], float tri[9])
{
    for (int i = 0; i < 9; i++) {
        float x = centre[i % 3] + tg_range(r, -1.0f, 1.0f);
        if (kind == 1)
            x = roundf(x * 4.0f) / 4.0f; /* grid: shared planes, exact zeros */
        tri[i] = x;
    }
    if (kind == 2) {
        /* Collinear: v2 on the line through v0 and v1, or v2 = v1. */
        float s = tg_below(r, 2) ? 0.5f : 1.0f;
        for (int k = 0; k < 3; k++)
            tri[6 + k] = tri[k] + s * (tri[3 + k] - tri[k]);
    } else if (kind == 3) {
        /* Sliver: v2 a hair beside the midpoint of v0 v1. */
        for (int k = 0; k < 3; k++)
            tri[6 + k] = 0.5f * (tri[k] + tri[3 + k]) + tg_range(r, -1e-6f, 1e-6f);
    }
}

/* A random power of ten in [10^lo, 10^hi]. */
static float pow10_range(struct tg_rng *r, float lo, float hi)
{
    return powf(10.0f, tg_range(r, lo, hi));
}

/*
 * shadow: the ray starts on (or, by a random distance, beside) a point
 * of one of the triangles, towards a random light, with a small tmin, as
 * a shadow ray does: the lane it starts on is kept by the filter and
 * refused on t (tri4_before_tmin).  Each lane that test refuses
 * must be one isect_triangle refuses (*refused counts them).
 */
/* A leaf packet of the four triangles, as the collapse fills packets (a
 * zero-area lane is marked). */
static void fill_packet(struct tri4_packet *p, const float tri[4][9], const uint32_t prim[4])
{
    for (int l = 0; l < 4; l++) {
        accel_set_packet_lane(p, (uint32_t)l, tri[l]);
        p->prim[l] = prim[l];
    }
}

static void one_case(struct tg_rng *r, uint64_t *cases, uint64_t *kept_rejected, uint64_t *hits,
                     int shadow, uint64_t *refused)
{
    float centre[3] = {0.0f, 0.0f, 0.0f};
    if (tg_below(r, 4) == 0) {
        centre[0] = 1e5f;
        centre[1] = -1e5f;
        centre[2] = 3e4f;
    }
    float tri[4][9];
    uint32_t prim[4];
    const int kind = (int)tg_below(r, 4);
    for (int l = 0; l < 4; l++) {
        random_triangle(r, kind, centre, tri[l]);
        prim[l] = (uint32_t)tg_below(r, 1000);
    }
    /* Neighbours share an edge (watertightness) now and then. */
    if (tg_below(r, 2)) {
        memcpy(tri[1], tri[0] + 3, 6 * sizeof(float));
        memcpy(tri[2], tri[0], 3 * sizeof(float));
        memcpy(tri[2] + 3, tri[0] + 6, 3 * sizeof(float));
    }
    if (tg_below(r, 8) == 0)
        memcpy(tri[3], tri[2], sizeof(tri[2])); /* a duplicate: a tie */
    /* The aim: a vertex, an edge point, an inside point or anywhere. */
    const float *t0 = tri[tg_below(r, 4)];
    float target[3];
    const int aim = (int)tg_below(r, 4);
    const float a = tg_unit(r), b = tg_unit(r);
    for (int k = 0; k < 3; k++) {
        if (aim == 0)
            target[k] = t0[3 * (int)(a * 3.0f) + k];
        else if (aim == 1)
            target[k] = t0[k] + a * (t0[3 + k] - t0[k]);
        else if (aim == 2)
            target[k] = t0[k] + a * (t0[3 + k] - t0[k]) * (1.0f - b) + b * (t0[6 + k] - t0[k]) * (1.0f - a);
        else
            target[k] = centre[k] + tg_range(r, -1.5f, 1.5f);
    }
    float org[3], dir[3];
    for (int k = 0; k < 3; k++)
        org[k] = centre[k] + tg_range(r, -4.0f, 4.0f);
    if (tg_below(r, 8) == 0) {
        /* Axis-parallel from a grid point: zero direction components. */
        int axis = (int)tg_below(r, 3);
        for (int k = 0; k < 3; k++)
            org[k] = k == axis ? target[k] - 3.0f : target[k];
    }
    for (int k = 0; k < 3; k++)
        dir[k] = target[k] - org[k];
    if (tg_below(r, 8) == 0)
        dir[tg_below(r, 3)] = tg_below(r, 2) ? 0.0f : -0.0f;
    if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f)
        dir[2] = 1.0f;
    float tmin = tg_below(r, 6) == 0 ? tg_range(r, 0.0f, 1.0f) : 0.0f;
    const int limit_kind = (int)tg_below(r, 4);
    float t_max = limit_kind == 0 ? tg_range(r, 0.5f, 1.5f) : INFINITY;
    if (shadow) {
        /* From a point of t0 (an inside point, on an edge or at a vertex
         * as aimed above, or inside), moved off it now and then, to a
         * light; tmin a random small step, t_max 1 (at the light) or
         * unbounded. */
        const float *s0 = t0;
        const float sa = tg_unit(r), sb = tg_unit(r);
        const float off = tg_below(r, 2) ? pow10_range(r, -9.0f, -1.0f) : 0.0f;
        float len2 = 0.0f;
        for (int k = 0; k < 3; k++) {
            org[k] = aim == 3 ? s0[k] + sa * (s0[3 + k] - s0[k]) * (1.0f - sb) +
                                    sb * (s0[6 + k] - s0[k]) * (1.0f - sa)
                              : target[k];
            org[k] += off * tg_range(r, -1.0f, 1.0f);
            const float light = centre[k] + tg_range(r, -4.0f, 4.0f) * pow10_range(r, 0.0f, 1.0f);
            dir[k] = light - org[k];
            len2 += dir[k] * dir[k];
        }
        if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f)
            dir[2] = 1.0f;
        if (len2 == 0.0f)
            len2 = 1.0f;
        tmin = pow10_range(r, -9.0f, -1.0f) / sqrtf(len2);
        t_max = tg_below(r, 2) ? 1.0f : INFINITY;
    }

    struct trace_ray ray;
    trace_ray_init(&ray, org, dir, tmin);
    struct tri4_packet p;
    fill_packet(&p, (const float(*)[9])tri, prim);
    /* Check 1: no lane the scalar test accepts is dropped. */
    struct tri4_ray r4;
    tri4_ray_init(&r4, &ray);
    /* The branch-free filter (no early return), as the 8-wide
     * closest-hit walk runs it on a small layout. */
    const unsigned mask = tri4_filter_lanes(&r4, &p, 15u, t_max, NULL, 0, 0);
    for (int any = 0; any < 2; any++) {
        /* The filter's early returns (any hit and closest hit) refuse
         * only what the branch-free filter refuses: the same mask. */
        struct tri4_lanes early;
        const unsigned mask_early = tri4_candidates_lanes_impl(&r4, &p, 15u, t_max, &early, any);
        if (mask_early != mask) {
            if (failures < 10)
                printf("  FAIL: early-out filter (any %d) mask %x, filter %x\n", any,
                       mask_early, mask);
            failures++;
        }
    }
    for (int l = 0; l < 4; l++) {
        float t, u, w;
        int accepted = isect_triangle(&ray, tri[l], tri[l] + 3, tri[l] + 6, t_max, &t, &u, &w);
        *hits += (uint64_t)accepted;
        if (accepted && !(mask >> l & 1u)) {
            if (failures < 10)
                printf("  FAIL: lane %d accepted (t %a) but dropped; org %a %a %a dir %a %a %a\n",
                       l, t, org[0], org[1], org[2], dir[0], dir[1], dir[2]);
            failures++;
        }
        if (!accepted && (mask >> l & 1u))
            (*kept_rejected)++;
    }
    /* Check 3: every kept lane tri4_before_tmin refuses (with
     * t_lo < tmin, as tri4_lane_test asks it) the scalar test refuses,
     * whatever the limit. */
    {
        struct tri4_lanes lanes;
        memset(&lanes, 0, sizeof(lanes)); /* written only for kept lanes */
        const unsigned kept = tri4_candidates_lanes(&r4, &p, 15u, INFINITY, &lanes);
        unsigned near = 0;
        for (unsigned l = 0; l < 4; l++)
            near |= (unsigned)(lanes.t_lo[l] < ray.tmin) << l;
        const unsigned before = tri4_before_tmin(&ray, &p, kept & near);
        const unsigned before_lanes = tri4_before_tmin_lanes(&r4, &p, &lanes, kept & near, 0);
        for (unsigned l = 0; l < 4; l++) {
            if (!((before | before_lanes) >> l & 1u))
                continue;
            (*refused)++;
            float t, u, w;
            if (isect_triangle(&ray, tri[l], tri[l] + 3, tri[l] + 6, INFINITY, &t, &u, &w)) {
                if (failures < 10)
                    printf("  FAIL: lane %u refused before tmin %a (%s) but hit at t %a\n", l,
                           ray.tmin, before_lanes >> l & 1u ? "filter's floats" : "world",
                           t);
                failures++;
            }
        }
    }
    /* Check 2: the leaf's answer, closest and any. */
    for (int any = 0; any < 2; any++) {
        unsigned kept;
        struct leaf_answer s = scalar_leaf(&ray, tri, prim, t_max, any);
        struct leaf_answer q = packet_leaf(&ray, &p, t_max, any, &kept);
        if (s.found != q.found ||
            (!any && s.found && memcmp(&s.hit, &q.hit, sizeof(s.hit)) != 0)) {
            if (failures < 10)
                printf("  FAIL: leaf %s: found %d/%d t %a/%a prim %u/%u\n",
                       any ? "any" : "closest", s.found, q.found, s.hit.t, q.hit.t, s.hit.prim,
                       q.hit.prim);
            failures++;
        }
    }
    (*cases)++;
}

/*
 * Check 4: tri4_before_tmin_lanes (the near lanes' refusal from the
 * filter's floats) where it is tightest.  A ray starts on a triangle or
 * beside it (along its normal, 10^-9 .. 1 of its size), towards a light
 * at a random distance or at a grazing angle; the triangle's size is
 * 2^-18 .. 2^18 and now and then it lies far from the origin (2^17 of
 * its size away); tmin is set around the triangle's own t: just above or
 * below the double-precision plane distance, at the float t the scalar
 * test computes (where it accepts, t >= tmin) or the next float above
 * it, far above, or a shadow ray's small step.  Every lane refused must
 * be one isect_triangle refuses; a bound too tight by a factor of a few
 * refuses lanes the scalar test accepts at tmin just below their t.
 * *accepted counts the near lanes the scalar test accepts (those a too
 * tight bound would refuse), *refused the lanes refused, *close those
 * refused with tmin within 2^-10 of the triangle's t.
 */
static void tmin_case(struct tg_rng *r, uint64_t *cases, uint64_t *accepted, uint64_t *refused,
                      uint64_t *close)
{
    const float scale = ldexpf(1.0f, (int)tg_below(r, 37) - 18);
    float centre[3] = {0.0f, 0.0f, 0.0f};
    if (tg_below(r, 3) == 0)
        for (int k = 0; k < 3; k++)
            centre[k] = scale * 0x1p17f * tg_range(r, -1.0f, 1.0f);
    float tri[4][9];
    uint32_t prim[4];
    for (int l = 0; l < 4; l++) {
        for (int i = 0; i < 9; i++)
            tri[l][i] = centre[i % 3] + scale * tg_range(r, -1.0f, 1.0f);
        prim[l] = (uint32_t)l;
    }
    /* The ray's triangle is lane 0; a neighbour sharing its edge now and
     * then. */
    if (tg_below(r, 2))
        memcpy(tri[1], tri[0] + 3, 6 * sizeof(float));
    const float *t0 = tri[0];
    double e1[3], e2[3], n[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = (double)t0[3 + k] - t0[k];
        e2[k] = (double)t0[6 + k] - t0[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(nn > 0.0))
        return;
    /* The origin: a point inside the triangle, moved along the normal
     * now and then. */
    float a = tg_unit(r), b = tg_unit(r);
    if (a + b > 1.0f) {
        a = 1.0f - a;
        b = 1.0f - b;
    }
    const double off = tg_below(r, 2) ? 0.0
                                      : (tg_below(r, 2) ? 1.0 : -1.0) * scale *
                                            pow(10.0, -9.0 * tg_unit(r));
    float org[3], dir[3];
    for (int k = 0; k < 3; k++)
        org[k] = (float)(t0[k] + a * e1[k] + b * e2[k] + off * n[k] / nn);
    /* The direction: to a light 1 .. 100 sizes away, or nearly in the
     * plane (grazing, 10^-6 .. 1 of the normal in it). */
    if (tg_below(r, 4) == 0) {
        const double g = pow(10.0, -6.0 * tg_unit(r)) * (tg_below(r, 2) ? 1.0 : -1.0);
        const double s = tg_range(r, -1.0f, 1.0f);
        for (int k = 0; k < 3; k++)
            dir[k] = (float)(scale * (e1[k] + s * e2[k]) / nn * scale + g * scale * n[k] / nn);
    } else {
        const float dist = scale * powf(10.0f, 2.0f * tg_unit(r));
        for (int k = 0; k < 3; k++)
            dir[k] = dist * tg_range(r, -1.0f, 1.0f);
    }
    if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f)
        return;
    /* The triangle's t: the plane distance in double, and the float t
     * of the scalar test where it hits with a tmin far below. */
    double num = 0.0, den = 0.0;
    for (int k = 0; k < 3; k++) {
        num += n[k] * ((double)t0[k] - org[k]);
        den += n[k] * dir[k];
    }
    if (den == 0.0)
        return;
    const double t_plane = num / den;
    struct trace_ray ray;
    trace_ray_init(&ray, org, dir, 0x1p-126f);
    float t_hit, uu, ww;
    const int hit = isect_triangle(&ray, t0, t0 + 3, t0 + 6, INFINITY, &t_hit, &uu, &ww);
    const double ta = fabs(t_plane);
    double tmin;
    const int kind = (int)tg_below(r, 6);
    if (kind == 0)
        tmin = ta * (1.0 + ldexp(1.0, -2 - (int)tg_below(r, 21)));
    else if (kind == 1)
        tmin = ta * (1.0 - ldexp(1.0, -2 - (int)tg_below(r, 21)));
    else if (kind == 2)
        tmin = ta * ldexp(1.0, 1 + (int)tg_below(r, 20));
    else if (kind == 3 && hit)
        tmin = tg_below(r, 2) ? t_hit : isect_next_up(t_hit);
    else
        tmin = pow(10.0, -9.0 * tg_unit(r)) * scale /
               sqrt((double)dir[0] * dir[0] + (double)dir[1] * dir[1] + (double)dir[2] * dir[2]);
    const float tmin_f = (float)tmin;
    if (!(tmin_f >= 0x1p-126f) || !isfinite(tmin_f))
        return;
    trace_ray_init(&ray, org, dir, tmin_f);
    struct tri4_packet p;
    fill_packet(&p, (const float(*)[9])tri, prim);
    struct tri4_ray r4;
    tri4_ray_init(&r4, &ray);
    struct tri4_lanes lanes;
    memset(&lanes, 0, sizeof(lanes)); /* written only for kept lanes */
    const unsigned kept = tri4_candidates_lanes(&r4, &p, 15u, INFINITY, &lanes);
    unsigned near = 0;
    for (unsigned l = 0; l < 4; l++)
        near |= (unsigned)(lanes.t_lo[l] < tmin_f) << l;
    near &= kept;
    const unsigned sure = tri4_before_tmin_lanes(&r4, &p, &lanes, near, 0);
    for (unsigned l = 0; l < 4; l++) {
        if (!(near >> l & 1u))
            continue;
        float t, u, w;
        const int acc = isect_triangle(&ray, tri[l], tri[l] + 3, tri[l] + 6, INFINITY, &t, &u, &w);
        *accepted += (uint64_t)acc;
        if (!(sure >> l & 1u))
            continue;
        (*refused)++;
        *close += (uint64_t)(l == 0 && fabs(tmin - ta) <= ldexp(ta, -10));
        if (acc) {
            if (failures < 10)
                printf("  FAIL: lane %u refused from the filter's floats, tmin %a, but hit at "
                       "t %a (scale %a)\n",
                       l, tmin_f, t, scale);
            failures++;
        }
    }
    (*cases)++;
}

/* The leaf tests of the 8-wide single-ray walk in the tables this CPU
 * runs (the tables' leaf8). */
typedef int (*leaf8_fn)(const struct trace_ray *ray, const struct tri4_packet *p, uint32_t n,
                        float t_max, int any_hit, int early_out, int eight, int found,
                        struct trace_hit *hit);

/*
 * Check 3: a leaf of n = 5..8 triangles in two packets.  The triangles
 * are drawn as one_case draws a packet's (the same kinds, a shared
 * centre), with edges shared across the two packets, duplicates of a
 * first-packet triangle in the second packet under a lower or higher
 * primitive (ties the 8-lane test must break as the two calls do), and
 * now and then an earlier leaf's hit to beat, at a triangle's own t
 * (another tie) or elsewhere.
 */
static void pair_case(struct tg_rng *r, const leaf8_fn *fns, int fn_count, uint64_t *cases,
                      uint64_t *hits, uint64_t *second, uint64_t *ties, uint64_t *edges)
{
    float centre[3] = {0.0f, 0.0f, 0.0f};
    if (tg_below(r, 4) == 0) {
        centre[0] = -3e4f;
        centre[1] = 1e5f;
        centre[2] = 2e3f;
    }
    const int n = 5 + (int)tg_below(r, 4);
    float tri[8][9];
    uint32_t prim[8];
    for (int l = 0; l < 8; l++) {
        random_triangle(r, (int)tg_below(r, 4), centre, tri[l]);
        prim[l] = (uint32_t)tg_below(r, 1000);
    }
    if (tg_below(r, 2)) {
        /* Neighbours across the packets share an edge. */
        const int a = (int)tg_below(r, 4), b = 4 + (int)tg_below(r, (uint32_t)n - 4);
        memcpy(tri[b], tri[a] + 3, 6 * sizeof(float));
    }
    if (tg_below(r, 3) == 0) {
        /* A duplicate of a first-packet triangle in the second packet. */
        const int a = (int)tg_below(r, 4), b = 4 + (int)tg_below(r, (uint32_t)n - 4);
        memcpy(tri[b], tri[a], sizeof(tri[a]));
        prim[b] = tg_below(r, 2) ? prim[a] + 1u + tg_below(r, 5)
                                 : (prim[a] > 0 ? prim[a] - 1u - tg_below(r, prim[a]) : 1000u);
    }
    const float *t0 = tri[tg_below(r, (uint32_t)n)];
    const int aim = (int)tg_below(r, 4);
    const float a = tg_unit(r), b = tg_unit(r);
    float target[3], org[3], dir[3];
    for (int k = 0; k < 3; k++) {
        if (aim == 0)
            target[k] = t0[3 * (int)(a * 3.0f) + k];
        else if (aim == 1)
            target[k] = t0[k] + a * (t0[3 + k] - t0[k]);
        else if (aim == 2)
            target[k] = t0[k] + a * (t0[3 + k] - t0[k]) * (1.0f - b) +
                        b * (t0[6 + k] - t0[k]) * (1.0f - a);
        else
            target[k] = centre[k] + tg_range(r, -1.5f, 1.5f);
        org[k] = centre[k] + tg_range(r, -4.0f, 4.0f);
    }
    if (tg_below(r, 8) == 0) {
        const int axis = (int)tg_below(r, 3);
        for (int k = 0; k < 3; k++)
            org[k] = k == axis ? target[k] - 3.0f : target[k];
    }
    for (int k = 0; k < 3; k++)
        dir[k] = target[k] - org[k];
    if (tg_below(r, 8) == 0)
        dir[tg_below(r, 3)] = tg_below(r, 2) ? 0.0f : -0.0f;
    if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f)
        dir[2] = 1.0f;
    const float tmin = tg_below(r, 6) == 0 ? tg_range(r, 0.0f, 1.0f) : 0.0f;
    const float t_max = tg_below(r, 4) == 0 ? tg_range(r, 0.5f, 1.5f) : INFINITY;
    struct trace_ray ray;
    trace_ray_init(&ray, org, dir, tmin);

    struct tri4_packet p[2];
    for (int l = 0; l < 8; l++) {
        /* The lanes beyond n repeat the last triangle, as the collapse
         * fills them; they are never tested. */
        const int src = l < n ? l : n - 1;
        accel_set_packet_lane(&p[l / 4], (uint32_t)(l % 4), tri[src]);
        p[l / 4].prim[l % 4] = prim[src];
    }

    /* An earlier leaf's hit now and then: at a triangle's own t (a tie
     * the primitive index breaks) or at a random distance. */
    struct leaf_answer before;
    memset(&before, 0, sizeof(before));
    if (tg_below(r, 4) == 0) {
        float t, u, w;
        const float *q = tri[tg_below(r, (uint32_t)n)];
        before.found = 1;
        before.hit.t = isect_triangle(&ray, q, q + 3, q + 6, t_max, &t, &u, &w)
                           ? t
                           : tg_range(r, 0.5f, 3.0f);
        before.hit.u = 0.25f;
        before.hit.v = 0.5f;
        before.hit.prim = (uint32_t)tg_below(r, 1000);
    }

    for (int any = 0; any < 2; any++) {
        struct leaf_answer none;
        memset(&none, 0, sizeof(none));
        const struct leaf_answer *start = any ? &none : &before;
        const struct leaf_answer s0 = scalar_leaf_n(&ray, tri, prim, n, t_max, any, start);
        *hits += (uint64_t)s0.found;
        if (!any && s0.found) {
            /* The winner's packet, and a hit at the same t in the other
             * packet (a tie across the two). */
            int winner = -1;
            for (int l = 0; l < n && winner < 0; l++) {
                float t, u, w;
                if (prim[l] == s0.hit.prim &&
                    isect_triangle(&ray, tri[l], tri[l] + 3, tri[l] + 6, t_max, &t, &u, &w) &&
                    t == s0.hit.t)
                    winner = l;
            }
            *second += (uint64_t)(winner >= 4);
            for (int l = 0; l < n && winner >= 0; l++) {
                float t, u, w;
                if ((l < 4) != (winner < 4) &&
                    isect_triangle(&ray, tri[l], tri[l] + 3, tri[l] + 6, t_max, &t, &u, &w) &&
                    t == s0.hit.t) {
                    (*ties)++;
                    break;
                }
            }
            /* An edge function exactly 0 at the hit: u or v is 0, or
             * their sum 1. */
            *edges += (uint64_t)(s0.hit.u == 0.0f || s0.hit.v == 0.0f ||
                                 s0.hit.u + s0.hit.v == 1.0f);
        }
        for (int f = 0; f < fn_count; f++) {
            for (int early = 0; early < 2; early++) {
                /* eight 2: the closest-hit walk's copy for a ray's
                 * first leaf, which may refuse the whole leaf right
                 * after the signs (TRI4_BEHIND_FIRST). */
                for (int eight = 0; eight < 3; eight++) {
                    struct trace_hit h = start->hit;
                    const int found = fns[f](&ray, p, (uint32_t)n, t_max, any, early, eight,
                                             start->found, &h);
                    if (found != s0.found ||
                        (!any && found && memcmp(&h, &s0.hit, sizeof(h)) != 0)) {
                        if (failures < 10)
                            printf("  FAIL: two-packet leaf (table %d, %s, early %d, eight %d, "
                                   "n %d): found %d/%d t %a/%a prim %u/%u\n",
                                   f, any ? "any" : "closest", early, eight, n, s0.found, found,
                                   s0.hit.t, h.t, s0.hit.prim, h.prim);
                        failures++;
                    }
                }
            }
        }
    }
    (*cases)++;
}

int main(void)
{
    struct tg_rng r;
    tg_seed(&r, 2017);
    uint64_t cases = 0, kept_rejected = 0, hits = 0, refused = 0, refused_shadow = 0;
    for (int i = 0; i < 400000; i++)
        one_case(&r, &cases, &kept_rejected, &hits, 0, &refused);
    /* Shadow rays (a separate generator, so the cases above are the
     * same as before). */
    struct tg_rng rs;
    tg_seed(&rs, 2013);
    for (int i = 0; i < 200000; i++)
        one_case(&rs, &cases, &kept_rejected, &hits, 1, &refused_shadow);
    /* Check 4: the near lanes' refusal where it is tightest. */
    uint64_t tmin_cases = 0, tmin_accepted = 0, tmin_refused = 0, tmin_close = 0;
    {
        struct tg_rng rt;
        tg_seed(&rt, 2024);
        for (int i = 0; i < 400000; i++)
            tmin_case(&rt, &tmin_cases, &tmin_accepted, &tmin_refused, &tmin_close);
    }
    printf("tri4_differential: %llu rays from or beside a triangle with tmin about its t: "
           "%llu near lanes the scalar test accepts, %llu refused from the filter's floats "
           "(%llu with tmin within 2^-10 of the triangle's t)\n",
           (unsigned long long)tmin_cases, (unsigned long long)tmin_accepted,
           (unsigned long long)tmin_refused, (unsigned long long)tmin_close);
    failures += !CHECKF(tmin_accepted > 1000 && tmin_close > 1000,
                        "too few near lanes accepted (%llu) or refused close to tmin (%llu)",
                        (unsigned long long)tmin_accepted, (unsigned long long)tmin_close);
    /* Leaves of two packets, in each table with the 8-wide walk this
     * CPU runs (none: nothing to compare). */
    leaf8_fn fns[2];
    int fn_count = 0;
    for (int isa = TRACE_ISA_AVX2; isa <= TRACE_ISA_AVX512; isa++) {
        const struct trace_kernels *k = trace_kernels_get((enum trace_isa)isa);
        if (k && k->leaf8)
            fns[fn_count++] = k->leaf8;
    }
    uint64_t pair_cases = 0, pair_hits = 0, pair_second = 0, pair_ties = 0, pair_edges = 0;
    if (fn_count) {
        struct tg_rng rp;
        tg_seed(&rp, 2008);
        for (int i = 0; i < 200000; i++)
            pair_case(&rp, fns, fn_count, &pair_cases, &pair_hits, &pair_second, &pair_ties,
                      &pair_edges);
    }
    printf("tri4_differential: %llu two-packet leaves in %d table(s), %llu scalar hits (closest "
           "and any); of the closest hits %llu in the second packet, %llu tied with the other "
           "packet, %llu on an edge\n",
           (unsigned long long)pair_cases, fn_count, (unsigned long long)pair_hits,
           (unsigned long long)pair_second, (unsigned long long)pair_ties,
           (unsigned long long)pair_edges);
    failures += !CHECKF(fn_count == 0 || (pair_ties > 100 && pair_edges > 100),
                        "too few ties (%llu) or on-edge hits (%llu) across two-packet leaves",
                        (unsigned long long)pair_ties, (unsigned long long)pair_edges);
    printf("tri4_differential: %llu packets x 4 lanes, %llu scalar hits, %llu lanes kept by the "
           "filter and rejected by the scalar test, %llu + %llu kept lanes refused before tmin "
           "in float (ordinary, shadow rays), %d failures\n",
           (unsigned long long)cases, (unsigned long long)hits,
           (unsigned long long)kept_rejected, (unsigned long long)refused,
           (unsigned long long)refused_shadow, failures);
    CHECKF(failures == 0, "the packet test differs from the scalar test on %d checks", failures);
    return failures ? 1 : 0;
}
#else
int main(void)
{
    printf("tri4_differential: no SSE2 on this target, nothing to compare\n");
    return 0;
}
#endif
