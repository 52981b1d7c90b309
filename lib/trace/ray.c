/* SPDX-License-Identifier: Apache-2.0 */
/*
 * ray.c - ray preparation (trace.h): the reciprocal direction for the slab
 * test and the shear constants of the watertight triangle test.
 */
#include "trace/trace.h"

#include <math.h>

#include "trace/ray_setup.h"

#if defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <emmintrin.h>
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

/* The same ray, bit for bit, without branches (ray_setup.h says why). */
void trace_ray_init_single(struct trace_ray *ray, const float org[3], const float dir[3],
                           float tmin)
{
    trace_ray_setup_single(ray, org, dir, tmin);
}
