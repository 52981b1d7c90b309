/* SPDX-License-Identifier: Apache-2.0 */
/*
 * ray.c - ray preparation (trace.h): the reciprocal direction for the slab
 * test and the shear constants of the watertight triangle test.
 */
#include "trace/trace.h"

#include <math.h>

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

void trace_ray_init(struct trace_ray *ray, const float org[3], const float dir[3], float tmin)
{
    float d[3];
    ray_store_inputs(ray, org, dir, tmin, d);

    /* Woop, Benthin and Wald 2013: z is the dimension where the direction
     * is largest in magnitude (first one on ties), x and y follow
     * cyclically and are swapped for a negative z to keep the winding. */
    int kz = 0;
    for (int k = 1; k < 3; k++) {
        if (fabsf(d[k]) > fabsf(d[kz]))
            kz = k;
    }
    int kx = kz == 2 ? 0 : kz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0.0f) {
        int tmp = kx;
        kx = ky;
        ky = tmp;
    }
    ray->kx = kx;
    ray->ky = ky;
    ray->kz = kz;
    /* The five divisions: 1 / dir (IEEE division: a zero component gives
     * an infinity of the zero's sign, which the slab test handles,
     * intersect.h) and the shear, stored negated (trace.h).  Four of them
     * in one divps where SSE is there: the same correctly rounded
     * quotients, without waiting for five scalar divisions in turn. */
#if defined(__SSE2__) && !defined(RT_NO_SIMD)
    const float dz = d[kz];
    float q[4];
    _mm_storeu_ps(q, _mm_div_ps(_mm_setr_ps(1.0f, 1.0f, 1.0f, -d[kx]),
                                _mm_setr_ps(d[0], d[1], d[2], dz)));
    ray->inv_dir[0] = q[0];
    ray->inv_dir[1] = q[1];
    ray->inv_dir[2] = q[2];
    ray->sx = q[3];
    ray->sz = q[kz]; /* 1 / dir[kz], already computed */
    ray->sy = -d[ky] / dz;
#else
    ray_divisions(ray, d, kx, ky, kz);
#endif
}

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
void trace_ray_init_single(struct trace_ray *ray, const float org[3], const float dir[3],
                           float tmin)
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
