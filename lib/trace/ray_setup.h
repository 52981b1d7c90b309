/* SPDX-License-Identifier: Apache-2.0 */
/*
 * ray_setup.h - the set-up of a ray traced alone (trace.h's
 * trace_ray_init_single) as an inline function, so that the kernels'
 * single-ray entries that take the ray's origin and direction
 * (kernels.h, closest1/any1) set it up in their own frame, compiled with
 * their instruction set, and the walk reads the values from registers
 * rather than from a struct another function has just written.  ray.c's
 * trace_ray_init_single is this function: one text, the same bits (IEEE
 * divisions, comparisons and sign tests only; no contraction is possible).
 */
#ifndef RT_TRACE_RAY_SETUP_H
#define RT_TRACE_RAY_SETUP_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "trace/trace.h"

#if defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <emmintrin.h>
#endif

/* The ray's inputs into ray, dir into d.  They are read into locals
 * before anything is stored: ray may in principle overlap org or dir, so
 * otherwise the compiler checks for the overlap at run time and reloads
 * dir after every store. */
static inline void ray_store_inputs(struct trace_ray *ray, const float org[3],
                                    const float dir[3], float tmin, float d[3])
{
    const float o0 = org[0], o1 = org[1], o2 = org[2];
    d[0] = dir[0];
    d[1] = dir[1];
    d[2] = dir[2];
    ray->org[0] = o0;
    ray->org[1] = o1;
    ray->org[2] = o2;
    ray->dir[0] = d[0];
    ray->dir[1] = d[1];
    ray->dir[2] = d[2];
    ray->tmin = tmin;
}

#if !defined(__SSE2__) || defined(RT_NO_SIMD)
/* The five divisions one by one (without SSE): 1 / dir and the shear. */
static inline void ray_divisions(struct trace_ray *ray, const float d[3], int kx, int ky, int kz)
{
    const float dz = d[kz];
    float q[3];
    for (int k = 0; k < 3; k++) {
        q[k] = 1.0f / d[k];
        ray->inv_dir[k] = q[k];
    }
    ray->sx = -d[kx] / dz;
    ray->sz = q[kz]; /* 1 / dir[kz], already computed */
    ray->sy = -d[ky] / dz;
}
#endif

/*
 * trace_ray_init for a ray traced alone (trace.h): the same ray, bit for
 * bit, with the choice of kz, kx, ky made without branches.  For random
 * directions each of trace_ray_init's three choices is a coin toss for
 * the branch predictor (about 1.2 mispredictions a random ray, callgrind's
 * branch simulation); without them random rays ran 0.08-0.10 of Embree
 * faster on gears and the kitchen.  Coherent rays predict those branches,
 * and there the 17 instructions more and the longer dependency chain cost:
 * set up eight at a time for the packet kernels, primary rays' packets
 * lost 22 % (gears), so trace_ray_init keeps its branches.
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void trace_ray_setup_single(struct trace_ray *ray, const float org[3],
                                          const float dir[3], float tmin)
{
    float d[3];
    ray_store_inputs(ray, org, dir, tmin, d);

    /* Woop, Benthin and Wald 2013: z is the dimension where the direction
     * is largest in magnitude (first one on ties), x and y follow
     * cyclically and are swapped for a negative z to keep the winding. */
    /* Without branches: for random directions each of the three choices
     * (kz 2 or not, 1 or 0, the sign) is a coin toss for the branch
     * predictor, about 1.2 mispredictions a ray (callgrind's branch
     * simulation on random rays).  The same comparisons in the same order
     * as the loop `if (fabsf(d[k]) > fabsf(d[kz])) kz = k` for k = 1, 2
     * (NaN compares false in both), taken as 0/1 values. */
    const float a[3] = {fabsf(d[0]), fabsf(d[1]), fabsf(d[2])};
    const unsigned c1 = a[1] > a[0];
    const unsigned c2 = a[2] > a[c1];
    const unsigned kz = (c1 & (c2 ^ 1u)) | c2 << 1;
    /* kx, ky: the axes after kz cyclically, swapped when d[kz] < 0; two
     * bits each in a table indexed by 2 kz + sign:
     * (1, 2), (2, 1); (2, 0), (0, 2); (0, 1), (1, 0). */
    const unsigned i = 2u * (2u * kz + (unsigned)(d[kz] < 0.0f));
    const int kx = (int)(0x429u >> i & 3u);
    const int ky = (int)(0x186u >> i & 3u);
    ray->kx = kx;
    ray->ky = ky;
    ray->kz = (int)kz;
    /* The five divisions as trace_ray_init's, in two divps where SSE is
     * there. */
#if defined(__SSE2__) && !defined(RT_NO_SIMD)
    const float dz = d[kz];
    /* 1 / dir apart from the shear's two quotients: the node test's
     * inverse then does not wait for the choice of the axes. */
    float q[4], sh[4];
    _mm_storeu_ps(q, _mm_div_ps(_mm_set1_ps(1.0f), _mm_setr_ps(d[0], d[1], d[2], 1.0f)));
    _mm_storeu_ps(sh, _mm_div_ps(_mm_setr_ps(-d[kx], -d[ky], 0.0f, 0.0f),
                                 _mm_setr_ps(dz, dz, 1.0f, 1.0f)));
    ray->inv_dir[0] = q[0];
    ray->inv_dir[1] = q[1];
    ray->inv_dir[2] = q[2];
    ray->sx = sh[0];
    ray->sy = sh[1];
    ray->sz = q[kz]; /* 1 / dir[kz], already computed */
#else
    ray_divisions(ray, d, kx, ky, kz);
#endif
}

#if defined(__AVX__) && !defined(RT_NO_SIMD)
#include <immintrin.h>

/* The set-up's results in SSE lanes (trace_ray_setup_lanes) that the
 * walk reads from registers: lanes 0-2 the axes 0-2 (dir) or kx, ky, kz
 * (org_k, inv_k, the watertight test's order). */
struct ray_lanes {
    __m128 dir;   /* dir[0], dir[1], dir[2], 1: the octant's signs */
    __m128 org;   /* org[0], org[1], org[2], 0 */
    __m128 org_k; /* org[kx], org[ky], org[kz], 0 */
    __m128 inv_k; /* inv_dir[kx], inv_dir[ky], inv_dir[kz] (= sz), 1 */
    __m128 inv;   /* inv_dir[0], inv_dir[1], inv_dir[2], 1 (node_fused_init:
                   * the AVX-512 table only; unread, so dropped, elsewhere) */
    __m128 shear; /* sx, sy, -1, - */
    __m128i order; /* kx, ky, kz, 3: the permutation's indices (the any-hit
                    * leaves' row offsets, tri4_ray_init_scalar_lanes) */
    int kx, ky, kz;
};

/* trace_ray_setup_lanes stores org, dir and inv_dir 16 bytes at a time,
 * each store's lane 3 overwritten by the next field: they must be
 * consecutive, as must sx and sy. */
typedef char ray_setup_lanes_layout
    [offsetof(struct trace_ray, dir) == offsetof(struct trace_ray, org) + 3 * sizeof(float) &&
             offsetof(struct trace_ray, inv_dir) ==
                 offsetof(struct trace_ray, dir) + 3 * sizeof(float) &&
             offsetof(struct trace_ray, tmin) ==
                 offsetof(struct trace_ray, inv_dir) + 3 * sizeof(float) &&
             offsetof(struct trace_ray, sy) == offsetof(struct trace_ray, sx) + sizeof(float)
         ? 1
         : -1];

/* The lane order kx, ky, kz (and lane 3) per 2 kz + (d[kz] < 0):
 * trace_ray_setup_single's table of (kx, ky) with kz, as _mm_permutevar_ps
 * indices. */
static const int32_t ray_lane_order[6][4] = {{1, 2, 0, 3}, {2, 1, 0, 3}, {2, 0, 1, 3},
                                             {0, 2, 1, 3}, {0, 1, 2, 3}, {1, 0, 2, 3}};

/*
 * trace_ray_setup_single's ray, bit for bit, computed in SSE lanes and
 * stored into *ray (which the leaves' rarer paths read), with the lanes
 * left in *l for the caller to broadcast: the choice of kz by the same
 * comparisons in the same order (c1 = |d1| > |d0|, then |d2| against the
 * larger of the two as `a1 > a0 ? a1 : a0` picks it, NaN comparing false
 * in both), the sign d[kz] < 0 by the same comparison, the same
 * quotients 1 / d[k] and -d[kx] / d[kz], -d[ky] / d[kz] (IEEE division
 * lane by lane, negation by the sign bit, as C's unary minus), and no
 * array indexed by kx, ky, kz, which GCC keeps on the stack (a lane
 * permutation instead).  Lane 3 of a store is overwritten by the next
 * store (the fields are consecutive floats, trace.h).
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void trace_ray_setup_lanes(struct trace_ray *ray, struct ray_lanes *l,
                                         const float org[3], const float dir[3], float tmin)
{
    const float d0 = dir[0], d1 = dir[1], d2 = dir[2];
    const __m128 o = _mm_setr_ps(org[0], org[1], org[2], 0.0f);
    const __m128 d = _mm_setr_ps(d0, d1, d2, 1.0f);
    const float a0 = fabsf(d0), a1 = fabsf(d1), a2 = fabsf(d2);
    const unsigned c1 = a1 > a0;
    const unsigned c2 = a2 > (a1 > a0 ? a1 : a0);
    const unsigned kz = (c1 & (c2 ^ 1u)) | c2 << 1;
    const unsigned neg =
        (unsigned)_mm_movemask_ps(_mm_cmplt_ps(d, _mm_setzero_ps())) >> kz & 1u;
    const int32_t *order = ray_lane_order[2u * kz + neg];
    const __m128i idx = _mm_loadu_si128((const __m128i *)(const void *)order);
    const __m128 sign = _mm_set1_ps(-0.0f);
    const __m128 inv = _mm_div_ps(_mm_set1_ps(1.0f), d);
    const __m128 d_k = _mm_permutevar_ps(d, idx);
    const __m128 shear = _mm_div_ps(_mm_xor_ps(d_k, sign), _mm_permute_ps(d_k, 0xAA));
    l->dir = d;
    l->org = o;
    l->org_k = _mm_permutevar_ps(o, idx);
    l->inv_k = _mm_permutevar_ps(inv, idx);
    l->inv = inv;
    l->shear = shear;
    l->order = idx;
    l->kx = order[0];
    l->ky = order[1];
    l->kz = (int)kz;
    char *b = (char *)(void *)ray;
    _mm_storeu_ps((float *)(void *)(b + offsetof(struct trace_ray, org)), o);
    _mm_storeu_ps((float *)(void *)(b + offsetof(struct trace_ray, dir)), d);
    _mm_storeu_ps((float *)(void *)(b + offsetof(struct trace_ray, inv_dir)), inv);
    ray->tmin = tmin;
    ray->kx = order[0];
    ray->ky = order[1];
    ray->kz = (int)kz;
    _mm_storel_pi((__m64 *)(void *)(b + offsetof(struct trace_ray, sx)), shear);
    _mm_store_ss(&ray->sz, _mm_permute_ps(l->inv_k, 0xAA));
}
#endif

#endif
