/* SPDX-License-Identifier: Apache-2.0 */
/*
 * trace.h - rays, ray/box and ray/triangle tests, single-BVH traversal.
 *
 * Everything here is in one coordinate space (object space for objects,
 * world space for the top level) and knows nothing of instances, the
 * context or RT_ enums.  Directions are never normalised: t is measured
 * in units of dir, so the same t holds in world and object space under an
 * affine map (Wald, Benthin and Slusallek (2003) sec. 4.4).
 */
#ifndef RT_TRACE_TRACE_H
#define RT_TRACE_TRACE_H

#include <stdint.h>

#include "trace/bvh_layout.h"

/* A ray prepared for traversal.  Fill with trace_ray_init. */
struct trace_ray {
    float org[3];
    float dir[3];
    float inv_dir[3]; /* 1/dir; +-inf for zero components (Ize 2013 handles it) */
    float tmin;
    /* Watertight ray/triangle constants (Woop, Benthin and Wald 2013,
     * sec. 3): kz = axis of largest |dir|, kx/ky the others (swapped to
     * keep winding), and the shear s = (-dir[kx]/dir[kz],
     * -dir[ky]/dir[kz], 1/dir[kz]). */
    int kx, ky, kz;
    float sx, sy, sz;
};

/* Closest hit.  u, v: barycentric weights of the triangle's second and
 * third vertex, p = (1-u-v) v0 + u v1 + v v2.  prim: the caller's
 * primitive index (prim_index of the leaf slot). */
struct trace_hit {
    float t;
    float u;
    float v;
    uint32_t prim;
};

/* Work counters, per thread; summed by the caller. */
struct trace_counters {
    uint64_t node_tests;     /* ray/box tests */
    uint64_t triangle_tests; /* ray/triangle tests */
};

/* Prepares a ray.  dir must be finite and non-zero. */
void trace_ray_init(struct trace_ray *ray, const float org[3], const float dir[3], float tmin);
/* The same ray, bit for bit, set up without branches: for a ray traced
 * alone (ray.c says why the packet kernels keep trace_ray_init). */
void trace_ray_init_single(struct trace_ray *ray, const float org[3], const float dir[3],
                           float tmin);

/*
 * Watertight ray/triangle test (Woop, Benthin and Wald, JCGT 2013).
 * Returns 1 and sets *t, *u, *v when the ray hits the triangle with
 * ray->tmin <= t < t_max; returns 0 otherwise (and leaves them alone).
 * Edges shared by two triangles are never missed by both (no cracks), and
 * a ray through an edge or vertex may hit every triangle sharing it.
 * Degenerate triangles are never hit: repeated vertices always,
 * collinear ones whenever their coordinate differences are exact in
 * double (coordinates within a factor 2^29 of each other, i.e. any real
 * mesh).  A hit has finite t and u, v >= 0 with u + v <= 1 (up to
 * rounding); no NaN is produced, for any input.  t is the distance to the
 * triangle's plane computed in double (for a sliver too thin for the
 * float test to resolve, the closest approach to its longest edge), so
 * p = org + t dir lies on the triangle (to rounding) even when u, v are
 * inaccurate, clamped into the ray's interval through the triangle's
 * bounding box as trace_box computes it.  So trace_box gives every box
 * holding the triangle an entry distance of at most t, and accepts it
 * (with t_max >= t) whenever the exact ray crosses the triangle's box:
 * traversal's culling relies on that.  The clamp moves t by more than an
 * ulp or two only for a ray that the float test accepts although it
 * passes a rounding error beside the triangle, at a grazing angle, where
 * the plane point can lie far outside it.  Whether a triangle is hit
 * below t_max depends on its t alone.  Double-precision fallback for the
 * edge functions when one is exactly 0, as the paper's sec. 4 describes,
 * with the signs taken in double (no underflow).  Both faces count (no
 * culling).
 */
int trace_triangle(const struct trace_ray *ray, const float v0[3], const float v1[3],
                   const float v2[3], float t_max, float *t, float *u, float *v);

/*
 * Robust slab test (Ize 2013, "Robust BVH ray traversal"): the far
 * distance is scaled by 1 + 2 gamma(3) so that rounding can never make a
 * ray miss a box it touches, axis-parallel rays included (an origin
 * exactly on a slab's plane counts as inside that slab).  Returns 1 and
 * the entry distance (>= ray->tmin, never NaN) when [tmin, t_max]
 * overlaps the box; conservative, so it may also accept a box the ray
 * misses by a rounding error.  Flat (zero-thickness) boxes are fine.
 */
int trace_box(const struct trace_ray *ray, const float aabb_min[3], const float aabb_max[3],
              float t_max, float *t_entry);

/*
 * Closest hit in one BVH.  tri holds 9 floats per leaf slot as produced by
 * accel_gather_triangles.  Only hits with ray->tmin <= t < t_max count.
 * Returns 1 and fills *hit if there is one (else leaves *hit alone); of
 * hits at exactly the same t the lowest primitive index wins, so the
 * answer is trace_closest_brute_force's for every tree over the same
 * triangles (traverse.c; conformance/internal/traversal_grazing.c checks
 * it bit for bit).  An empty BVH (node_count 0) has no hit.  counters may
 * be NULL; otherwise they are incremented (each node and triangle is
 * tested at most once per call).  Read-only on its inputs: any number of threads
 * may trace the same BVH at once.
 */
int trace_closest(const struct bvh *bvh, const float *tri, const struct trace_ray *ray,
                  float t_max, struct trace_hit *hit, struct trace_counters *counters);

/* Any hit with tmin <= t < t_max (shadow rays); returns 1 on the first. */
int trace_any(const struct bvh *bvh, const float *tri, const struct trace_ray *ray,
              float t_max, struct trace_counters *counters);

/*
 * Reference intersector: tests every triangle (indices into positions as
 * for accel_gather_triangles) with trace_triangle and returns the closest
 * hit, ties resolved to the lowest primitive index.  For tests and the
 * benchmark's error measurements, never for rendering.
 */
int trace_closest_brute_force(const float *positions, const uint32_t *indices,
                              uint32_t tri_count, const struct trace_ray *ray, float t_max,
                              struct trace_hit *hit);

#endif
