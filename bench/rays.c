/* SPDX-License-Identifier: Apache-2.0 */
/*
 * rays.c - the benchmark's ray sets and the comparison of hit arrays
 * (bench.h).  All ray sets are generated once per mesh and fed unchanged
 * to every path (ours direct, ours through the API, Embree), so the paths
 * do the same work and their answers can be compared ray by ray.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Shadow ray origins sit on the surface; tmin of this fraction of the
 * scene's diagonal (in units of the ray's direction, whose length is the
 * distance to the light) keeps them from hitting their own triangle. */
#define SHADOW_EPSILON 1e-4f

void bench_rng_seed(struct bench_rng *rng, uint64_t seed)
{
    rng->state = seed;
}

uint64_t bench_rng_next(struct bench_rng *rng)
{
    /* splitmix64, constants from Steele, Lea and Flood 2014. */
    uint64_t z = (rng->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

float bench_rng_float(struct bench_rng *rng)
{
    /* The top 24 bits: exactly representable, never 1.0f. */
    return (float)(bench_rng_next(rng) >> 40) * (1.0f / 16777216.0f);
}

static int alloc_set(struct bench_rays *set, const char *name, uint32_t count)
{
    memset(set, 0, sizeof(*set));
    set->rays = malloc((size_t)(count ? count : 1) * sizeof(*set->rays));
    if (!set->rays)
        return -1;
    set->name = name;
    set->count = count;
    return 0;
}

int bench_rays_primary(struct bench_rays *set, const struct bench_mesh *mesh, uint32_t width,
                       uint32_t height)
{
    if (alloc_set(set, "primary", width * height))
        return -1;
    set->width = width;
    set->height = height;
    const struct bench_camera *c = &mesh->camera;
    const float tan_y = c->tan_x * (float)height / (float)width;
    for (uint32_t y = 0; y < height; y++) {
        float sy = (1.0f - 2.0f * ((float)y + 0.5f) / (float)height) * tan_y;
        for (uint32_t x = 0; x < width; x++) {
            float sx = (2.0f * ((float)x + 0.5f) / (float)width - 1.0f) * c->tan_x;
            RTray *r = &set->rays[(size_t)y * width + x];
            for (int k = 0; k < 3; k++) {
                r->org[k] = c->eye[k];
                r->dir[k] = c->forward[k] + sx * c->right[k] + sy * c->up[k];
            }
            r->tmin = 0.0f;
            r->tmax = INFINITY;
        }
    }
    return 0;
}

int bench_rays_random(struct bench_rays *set, const struct bench_mesh *mesh, uint32_t count,
                      uint64_t seed)
{
    if (alloc_set(set, "random", count))
        return -1;
    struct bench_rng rng;
    bench_rng_seed(&rng, seed);
    const struct aabb *b = &mesh->bounds;
    for (uint32_t i = 0; i < count; i++) {
        RTray *r = &set->rays[i];
        for (int k = 0; k < 3; k++)
            r->org[k] = b->min[k] + bench_rng_float(&rng) * (b->max[k] - b->min[k]);
        /* Uniform on the sphere: z uniform in [-1, 1], azimuth uniform. */
        float z = 2.0f * bench_rng_float(&rng) - 1.0f;
        float phi = 2.0f * (float)M_PI * bench_rng_float(&rng);
        float s = sqrtf(fmaxf(0.0f, 1.0f - z * z));
        r->dir[0] = s * cosf(phi);
        r->dir[1] = s * sinf(phi);
        r->dir[2] = z;
        if (r->dir[0] == 0.0f && r->dir[1] == 0.0f && r->dir[2] == 0.0f)
            r->dir[2] = 1.0f;
        r->tmin = 0.0f;
        r->tmax = INFINITY;
    }
    return 0;
}

int bench_rays_shadow(struct bench_rays *set, const struct bench_mesh *mesh,
                      const struct bench_rays *primary, const struct bench_hit *hits)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < primary->count; i++)
        n += hits[i].prim != BENCH_MISS;
    if (alloc_set(set, "shadow", n))
        return -1;
    float diag = 0.0f;
    for (int k = 0; k < 3; k++) {
        float e = mesh->bounds.max[k] - mesh->bounds.min[k];
        diag += e * e;
    }
    diag = sqrtf(diag);
    uint32_t j = 0;
    for (uint32_t i = 0; i < primary->count; i++) {
        if (hits[i].prim == BENCH_MISS)
            continue;
        const RTray *p = &primary->rays[i];
        RTray *r = &set->rays[j++];
        float len2 = 0.0f;
        for (int k = 0; k < 3; k++) {
            r->org[k] = p->org[k] + hits[i].t * p->dir[k];
            r->dir[k] = mesh->light[k] - r->org[k];
            len2 += r->dir[k] * r->dir[k];
        }
        r->tmin = SHADOW_EPSILON * diag / sqrtf(len2);
        r->tmax = 1.0f;
    }
    return 0;
}

int bench_rays_trace_sets(struct bench_rays sets[3], const struct bench_mesh *mesh,
                          const struct bench_accel *acc, int quick)
{
    memset(sets, 0, 3 * sizeof(*sets));
    uint32_t w = quick ? BENCH_PRIMARY_WIDTH_QUICK : BENCH_PRIMARY_WIDTH;
    uint32_t h = quick ? BENCH_PRIMARY_HEIGHT_QUICK : BENCH_PRIMARY_HEIGHT;
    uint32_t n = quick ? BENCH_RANDOM_RAYS_QUICK : BENCH_RANDOM_RAYS;
    struct bench_hit *hits = NULL;
    if (bench_rays_primary(&sets[0], mesh, w, h) ||
        bench_rays_random(&sets[1], mesh, n, BENCH_RANDOM_SEED))
        goto fail;
    hits = malloc((size_t)sets[0].count * sizeof(*hits));
    if (!hits)
        goto fail;
    /* Ours, single-threaded: the hits are a deterministic function of the
     * tree and the rays. */
    bench_kernel_closest((void *)acc, sets[0].rays, 0, sets[0].count, hits);
    if (bench_rays_shadow(&sets[2], mesh, &sets[0], hits))
        goto fail;
    free(hits);
    return 0;
fail:
    free(hits);
    for (int s = 0; s < 3; s++)
        bench_rays_release(&sets[s]);
    return -1;
}

void bench_rays_release(struct bench_rays *set)
{
    free(set->rays);
    memset(set, 0, sizeof(*set));
}

void bench_compare_hits(struct bench_agreement *a, const struct bench_hit *x,
                        const struct bench_hit *y, uint32_t count, uint32_t stride)
{
    if (stride == 0)
        stride = 1;
    for (uint32_t i = 0; i < count; i += stride) {
        int hx = x[i].prim != BENCH_MISS, hy = y[i].prim != BENCH_MISS;
        a->compared++;
        if (hx != hy) {
            a->hit_miss_diff++;
            continue;
        }
        if (!hx) {
            a->agree++;
            a->same_prim++;
            continue;
        }
        float tol = BENCH_T_TOLERANCE * fmaxf(1.0f, fabsf(x[i].t));
        if (fabsf(x[i].t - y[i].t) <= tol) {
            a->agree++;
            a->same_prim += x[i].prim == y[i].prim;
        }
    }
}

double bench_agreement_percent(const struct bench_agreement *a)
{
    return a->compared ? 100.0 * (double)a->agree / (double)a->compared : 100.0;
}
