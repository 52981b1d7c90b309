/* SPDX-License-Identifier: Apache-2.0 */
/*
 * node_fused.c - the 8-wide walks' fused node test (trace/node_fused.h)
 * passes every box the reference slab test passes (trace_box, which is
 * isect_box), on adversarial ray/box pairs: rays aimed at box corners,
 * edges and faces and a few ulps beside them, boxes touching tmin or the
 * limit (tmin and the limit set to the reference's own entry or exit
 * distance and their neighbours), boxes far from the origin (1e5-1e7),
 * tiny (1e-6) and huge (1e6) boxes, near-axis directions, rays starting
 * inside boxes, random pairs.  A pair the fused constants do not cover
 * (node_fused_init refuses the ray: a direction component below 2^-60
 * or above 2^60, an origin beyond 2^60) takes the reference test in the
 * walks, so it is only counted.
 *
 * The same pairs with the widening taken out (S = 1, D = 0: both
 * distances fma(b, i, fl(-o i)), the limit unscaled) must lose boxes:
 * the test reports how many, and fails if none, so that the pairs are
 * known to reach the cases the widening is for.  Likewise with S alone
 * and with D alone (reported only).
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#if defined(__SSE2__)
#include "trace/intersect.h"
#include "trace/node_fused.h"
#include "trace/trace.h"

static int failures;

/* node_fused_init from the ray's floats in SSE lanes, as the walks'
 * set-up has them (lane 3: 0 and 1). */
static int fused_init(struct node_fused *f, const struct trace_ray *ray)
{
    return node_fused_init(f, _mm_setr_ps(ray->org[0], ray->org[1], ray->org[2], 0.0f),
                           _mm_setr_ps(ray->dir[0], ray->dir[1], ray->dir[2], 1.0f),
                           _mm_setr_ps(ray->inv_dir[0], ray->inv_dir[1], ray->inv_dir[2], 1.0f));
}

static uint64_t rng_state = 0x9e3779b97f4a7c15ull;

static uint64_t rng_next(void)
{
    uint64_t x = rng_state;
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    rng_state = x;
    return x * 0x2545f4914f6cdd1dull;
}

/* Uniform in [0, 1). */
static double rng_unit(void)
{
    return (double)(rng_next() >> 11) * 0x1p-53;
}

static uint32_t rng_below(uint32_t n)
{
    return (uint32_t)(rng_next() % n);
}

/* f moved by k ulps (k may be negative), through the float's bits as an
 * ordered integer. */
static float ulps(float f, int k)
{
    int32_t b;
    memcpy(&b, &f, sizeof(b));
    int64_t ord = b < 0 ? -(int64_t)(b & 0x7fffffff) : (int64_t)b;
    ord += k;
    int32_t nb = ord < 0 ? (int32_t)((uint32_t)(-ord) | 0x80000000u) : (int32_t)ord;
    float r;
    memcpy(&r, &nb, sizeof(r));
    return isfinite(r) ? r : f;
}

static const double scales[] = {1e-6, 1e-3, 1.0, 1e3, 1e6};
static const double offsets[] = {0.0, 1.0, 1e5, 1e6, 1e7};

/* The reference's exit distance, as isect_box computes it (before the
 * limit): min_k fl(fl(far_k - o_k) * i_k) * ISECT_BOX_FAR_SCALE. */
static float ref_exit(const struct trace_ray *ray, const float lo[3], const float hi[3])
{
    float t = INFINITY;
    for (int k = 0; k < 3; k++) {
        const float b = signbit(ray->inv_dir[k]) ? lo[k] : hi[k];
        const float f = (b - ray->org[k]) * ray->inv_dir[k];
        t = f < t ? f : t;
    }
    return t * ISECT_BOX_FAR_SCALE;
}

/* Variants: 0 the walks' constants, 1 no widening (S = 1, D = 0),
 * 2 S only (D = 0), 3 D only (S = 1); the limit likewise. */
static void fused_variant(struct node_fused *f, const struct trace_ray *ray, int variant)
{
    if (variant == 0)
        return;
    for (int k = 0; k < 3; k++) {
        const float o = ray->org[k], i = ray->inv_dir[k];
        const float slack = variant == 3 ? fabsf(i) * ((fabsf(o) + 0x1p-20f) * 0x1p-20f) : 0.0f;
        f->inv_s[k] = variant == 2 ? i * NODE_FUSED_SCALE : i;
        f->near_c[k] = fmaf(-o, i, -slack);
        f->far_c[k] = fmaf(-o, f->inv_s[k], slack);
    }
}

static float fused_limit(float limit, int variant)
{
    if (variant == 1 || variant == 3) /* S = 1 */
        return limit;
    if (variant == 2)
        return fmaf(limit, NODE_FUSED_SCALE, 0.0f);
    return node_fused_limit(limit);
}

struct counts {
    uint64_t pairs, refused, ref_pass, lost[4], extra;
};

static void one_pair(struct counts *c, const float org[3], const float dir[3], float tmin,
                     float limit, const float lo[3], const float hi[3])
{
    struct trace_ray ray;
    trace_ray_init(&ray, org, dir, tmin);
    c->pairs++;
    float t_ref;
    const int ref = trace_box(&ray, lo, hi, limit, &t_ref);
    struct node_fused f0;
    if (!fused_init(&f0, &ray)) {
        c->refused++;
        return;
    }
    c->ref_pass += (uint64_t)ref;
    for (int v = 0; v < 4; v++) {
        struct node_fused f = f0;
        fused_variant(&f, &ray, v);
        float t_fused;
        const int fused = node_fused_box(&f, ray.inv_dir, ray.tmin, fused_limit(limit, v),
                                         lo, hi, &t_fused);
        if (ref && !fused) {
            if (v == 0 && c->lost[0] < 10)
                printf("  LOST org (%a %a %a) dir (%a %a %a) tmin %a limit %a box (%a %a %a)-(%a "
                       "%a %a)\n",
                       org[0], org[1], org[2], dir[0], dir[1], dir[2], tmin, limit, lo[0], lo[1],
                       lo[2], hi[0], hi[1], hi[2]);
            c->lost[v]++;
        }
        if (v == 0 && fused && !ref)
            c->extra++;
    }
}

/* A box of the given size class at the given offset class. */
static void random_box(float lo[3], float hi[3])
{
    const double size = scales[rng_below(5)];
    const double off = offsets[rng_below(5)];
    for (int k = 0; k < 3; k++) {
        const double centre = off * (2.0 * rng_unit() - 1.0);
        const double half = size * (0.05 + rng_unit());
        lo[k] = (float)(centre - half);
        hi[k] = (float)(centre + half);
        if (!(lo[k] < hi[k]))
            hi[k] = ulps(lo[k], 1 + (int)rng_below(3));
    }
    /* Flat boxes (a triangle in a coordinate plane). */
    if (rng_below(8) == 0) {
        const int k = (int)rng_below(3);
        hi[k] = lo[k];
    }
}

/* A target point on the box: a corner, an edge, a face, inside, then a
 * few ulps off in each coordinate. */
static void target_point(const float lo[3], const float hi[3], float p[3])
{
    const uint32_t kind = rng_below(4); /* coordinates on the boundary: 3, 2, 1, 0 */
    const int free_axis = (int)rng_below(3);
    for (int k = 0; k < 3; k++) {
        int on = kind == 0 || (kind == 1 && k != free_axis) || (kind == 2 && k == free_axis);
        if (on)
            p[k] = rng_below(2) ? hi[k] : lo[k];
        else
            p[k] = (float)(lo[k] + (hi[k] - (double)lo[k]) * rng_unit());
        if (rng_below(2))
            p[k] = ulps(p[k], (int)rng_below(7) - 3);
    }
}

static void aimed_pairs(struct counts *c, uint32_t n)
{
    for (uint32_t r = 0; r < n; r++) {
        float lo[3], hi[3], p[3], org[3], dir[3];
        random_box(lo, hi);
        target_point(lo, hi, p);
        /* A direction: random, near an axis, or exactly along one with
         * the others tiny. */
        double d[3];
        double len = 0.0;
        do {
            len = 0.0;
            for (int k = 0; k < 3; k++) {
                d[k] = 2.0 * rng_unit() - 1.0;
                len += d[k] * d[k];
            }
        } while (len < 1e-6 || len > 1.0);
        const uint32_t axis_kind = rng_below(4);
        if (axis_kind >= 2) {
            const int a = (int)rng_below(3);
            const double tiny = axis_kind == 2 ? 1e-4 : 1e-9;
            for (int k = 0; k < 3; k++)
                if (k != a)
                    d[k] *= tiny;
        }
        const double scale = rng_below(4) == 0 ? pow(10.0, 6.0 * rng_unit() - 3.0) : 1.0;
        /* The origin: inside the box (distance 0), or 1e-6 to 1e7 back
         * from the target along the direction. */
        const double dist = rng_below(8) == 0 ? 0.0 : pow(10.0, 13.0 * rng_unit() - 6.0);
        for (int k = 0; k < 3; k++) {
            dir[k] = (float)(d[k] * scale);
            org[k] = (float)(p[k] - dist * d[k] / sqrt(len));
        }
        if (dist == 0.0)
            for (int k = 0; k < 3; k++)
                org[k] = (float)(lo[k] + (hi[k] - (double)lo[k]) * rng_unit());
        /* tmin and the limit: free, or at the reference's own entry and
         * exit distances and their neighbours (touching boxes). */
        struct trace_ray ray;
        trace_ray_init(&ray, org, dir, 0.0f);
        float t_entry;
        (void)trace_box(&ray, lo, hi, INFINITY, &t_entry);
        const float t_exit = ref_exit(&ray, lo, hi);
        float tmin = 0.0f, limit = INFINITY;
        switch (rng_below(6)) {
        case 0:
            break;
        case 1:
            limit = t_entry;
            break;
        case 2:
            limit = ulps(t_entry, (int)rng_below(5) - 2);
            break;
        case 3:
            tmin = t_exit;
            break;
        case 4:
            tmin = ulps(t_exit, (int)rng_below(5) - 2);
            limit = ulps(t_exit, (int)rng_below(5) - 2);
            break;
        default:
            tmin = (float)(t_entry * rng_unit());
            limit = ulps(t_entry, (int)rng_below(9) - 4) * ISECT_BOX_FAR_SCALE;
            break;
        }
        if (!(tmin >= 0.0f) || !isfinite(tmin))
            tmin = 0.0f;
        if (!(limit >= 0.0f))
            limit = 0.0f;
        one_pair(c, org, dir, tmin, limit, lo, hi);
    }
}

/* Random rays against random boxes (most miss; the hits are ordinary). */
static void random_pairs(struct counts *c, uint32_t n)
{
    for (uint32_t r = 0; r < n; r++) {
        float lo[3], hi[3], org[3], dir[3];
        random_box(lo, hi);
        const double off = offsets[rng_below(5)];
        for (int k = 0; k < 3; k++) {
            org[k] = (float)(off * (2.0 * rng_unit() - 1.0));
            dir[k] = (float)(2.0 * rng_unit() - 1.0);
        }
        const float tmin = rng_below(2) ? 0.0f : (float)(off * rng_unit());
        one_pair(c, org, dir, tmin, INFINITY, lo, hi);
    }
}

/* Rays the constants refuse (zero, tiny and huge direction components,
 * huge origins) must be refused, never mistested. */
static void refused_rays(void)
{
    const float org[3] = {1.0f, 2.0f, 3.0f};
    const float zero[3] = {0.0f, 1.0f, 0.0f};
    const float tiny[3] = {1e-35f, 1.0f, 1.0f};
    const float far_org[3] = {1e19f, 0.0f, 0.0f};
    const float one[3] = {1.0f, 1.0f, 1.0f};
    struct trace_ray ray;
    struct node_fused f;
    trace_ray_init(&ray, org, zero, 0.0f);
    failures += !CHECKF(!fused_init(&f, &ray), "zero direction accepted");
    trace_ray_init(&ray, org, tiny, 0.0f);
    failures += !CHECKF(!fused_init(&f, &ray), "tiny direction accepted");
    trace_ray_init(&ray, far_org, one, 0.0f);
    failures += !CHECKF(!fused_init(&f, &ray), "origin 1e19 accepted");
    trace_ray_init(&ray, org, one, 0.0f);
    failures += !CHECKF(fused_init(&f, &ray), "plain ray refused");
}

int main(void)
{
    printf("node_fused:\n");
    refused_rays();
    struct counts c;
    memset(&c, 0, sizeof(c));
    aimed_pairs(&c, 6000000);
    random_pairs(&c, 2000000);
    printf("  %llu pairs, %llu refused (reference test), %llu passed by the reference, "
           "%llu more by the fused test\n",
           (unsigned long long)c.pairs, (unsigned long long)c.refused,
           (unsigned long long)c.ref_pass, (unsigned long long)c.extra);
    printf("  lost: fused %llu, no widening %llu, S only %llu, D only %llu\n",
           (unsigned long long)c.lost[0], (unsigned long long)c.lost[1],
           (unsigned long long)c.lost[2], (unsigned long long)c.lost[3]);
    failures += !CHECKF(c.lost[0] == 0, "the fused test lost %llu boxes",
                        (unsigned long long)c.lost[0]);
    failures += !CHECKF(c.lost[1] > 0, "without the widening no box was lost: the pairs are weak");
    failures += !CHECKF(c.ref_pass > c.pairs / 4, "too few passing pairs");
    printf("node_fused: %s (%d failures)\n", failures ? "FAIL" : "ok", failures);
    return failures ? 1 : 0;
}
#else
/* node_fused.h is the SIMD tables' (x86-64): nothing to test elsewhere. */
int main(void)
{
    printf("node_fused: skipped (no SSE2)\n");
    return 0;
}
#endif
