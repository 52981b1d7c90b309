/* SPDX-License-Identifier: Apache-2.0 */
/*
 * aabb.h - axis-aligned boxes and small float vector helpers.
 *
 * Convention: a box is empty when min > max on any axis; aabb_empty()
 * returns the canonical empty box (+inf, -inf) which is the identity of
 * aabb_grow.  All functions are pure and inline.
 */
#ifndef RT_BASE_AABB_H
#define RT_BASE_AABB_H

#include <math.h>

struct aabb {
    float min[3];
    float max[3];
};

static inline struct aabb aabb_empty(void)
{
    struct aabb b = {{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    return b;
}

/* fminf and fmaxf written out, with the same result bit for bit as the
 * x86-64 C library's (y NaN: x; otherwise x < y ? x : y, so x NaN gives y
 * and equal zeros give y): without -ffast-math a compiler keeps them as
 * library calls, which made the triangle boxes of a build cost about
 * 200 instructions each; these compile to a compare and a blend. */
static inline float aabb_fminf(float x, float y)
{
    return y != y ? x : (x < y ? x : y);
}

static inline float aabb_fmaxf(float x, float y)
{
    return y != y ? x : (x > y ? x : y);
}

static inline void aabb_grow_point(struct aabb *b, const float p[3])
{
    for (int k = 0; k < 3; k++) {
        b->min[k] = aabb_fminf(b->min[k], p[k]);
        b->max[k] = aabb_fmaxf(b->max[k], p[k]);
    }
}

static inline void aabb_grow(struct aabb *b, const struct aabb *o)
{
    for (int k = 0; k < 3; k++) {
        b->min[k] = aabb_fminf(b->min[k], o->min[k]);
        b->max[k] = aabb_fmaxf(b->max[k], o->max[k]);
    }
}

static inline int aabb_is_empty(const struct aabb *b)
{
    return !(b->min[0] <= b->max[0] && b->min[1] <= b->max[1] && b->min[2] <= b->max[2]);
}

/* Half the surface area (the SAH only needs ratios); 0 for empty boxes. */
static inline float aabb_half_area(const struct aabb *b)
{
    if (aabb_is_empty(b))
        return 0.0f;
    float dx = b->max[0] - b->min[0];
    float dy = b->max[1] - b->min[1];
    float dz = b->max[2] - b->min[2];
    return dx * dy + dy * dz + dz * dx;
}

static inline float aabb_centroid(const struct aabb *b, int axis)
{
    return 0.5f * (b->min[axis] + b->max[axis]);
}

static inline void vec3_sub(float out[3], const float a[3], const float b[3])
{
    out[0] = a[0] - b[0];
    out[1] = a[1] - b[1];
    out[2] = a[2] - b[2];
}

static inline void vec3_cross(float out[3], const float a[3], const float b[3])
{
    float x = a[1] * b[2] - a[2] * b[1];
    float y = a[2] * b[0] - a[0] * b[2];
    float z = a[0] * b[1] - a[1] * b[0];
    out[0] = x;
    out[1] = y;
    out[2] = z;
}

static inline float vec3_dot(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Normalises in place; a zero or non-finite vector is left unchanged and
 * 0 is returned, otherwise 1. */
static inline int vec3_normalize(float v[3])
{
    float len = sqrtf(vec3_dot(v, v));
    if (!(len > 0.0f) || !isfinite(len))
        return 0;
    float inv = 1.0f / len;
    v[0] *= inv;
    v[1] *= inv;
    v[2] *= inv;
    return 1;
}

#endif
