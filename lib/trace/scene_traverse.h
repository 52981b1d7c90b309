/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene_traverse.h - two-level traversal: a top-level BVH over instances,
 * object BVHs below (Wald, Benthin and Slusallek (2003) sec. 4.4).
 *
 * A ray reaching an instance leaf is transformed into the object's space
 * by the instance's world-to-object matrix, without renormalising the
 * direction, so hit distances compare directly across instances.  The
 * object's own root box then clips it exactly in object space.  Each
 * instance sits in exactly one top-level leaf (the BVH partitions
 * instances, not space), so no ray visits an instance twice: that is the
 * equivalent of the mailboxing Wald, Benthin and Slusallek (2003) needs for its top-level BSP.
 *
 * Object structures are obtained through a callback the first time a ray
 * reaches the instance, which lets the scene build them on demand.
 */
#ifndef RT_TRACE_SCENE_TRAVERSE_H
#define RT_TRACE_SCENE_TRAVERSE_H

#include <stdint.h>
#include <string.h>

#if defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <emmintrin.h>
#endif

#include "trace/kernels.h"
#include "trace/trace.h"

struct trace_instance {
    /* Row-major 3x4: rows 0..2 of the inverse instance matrix.  Double,
     * because a float translation of 1e5 alone would move the object by
     * up to 4e-3 and the ray origin rounding would put secondary rays'
     * origins on the wrong side of their surface. */
    double world_to_object[12];
    uint32_t instance_id;      /* reported in hits */
    void *object;              /* opaque, handed to the acquire callback */
    /* A flattened nested hierarchy (trace/flat_walk.h) when member_count
     * is not 0: world_to_object is then the inverse of its root's matrix,
     * object is handed to acquire_flat, and its members are the slots
     * member_base .. member_base + member_count - 1 of the instances
     * array, which no top-level leaf names (hits report them). */
    uint32_t member_base;
    uint32_t member_count;
    /* Whether world_to_object's rows are the identity's (set by
     * trace_instance_set_rows): TRACE_IDENTITY_EXACT when they are bit
     * for bit (ones on the diagonal, +0.0 elsewhere), TRACE_IDENTITY_ZEROS
     * when some zeros are -0.0, else 0.  trace_scene_object_ray then
     * hands a ray that trace_scene_plain_class accepts for that kind on
     * without transforming it.  0 is always safe. */
    uint32_t identity;
};

enum { TRACE_IDENTITY_ZEROS = 1, TRACE_IDENTITY_EXACT = 2 };

/* world_to_object's rows from a column-major 4x4 inverse instance matrix
 * (OpenGL's order), and the identity flag. */
void trace_instance_set_rows(struct trace_instance *inst, const double world_to_object[16]);

struct trace_flat;
struct trace_scene_hit;

/*
 * An optional filter of hits: called, with the world ray, for each hit
 * of a filtered instance (trace_scene.filtered) that the walk would keep
 * (the closest so far, or an any-hit walk's hit); 0 rejects it and the
 * walk goes on as if that triangle were not there.  The renderer removes
 * so what GL's per-primitive state removed from the picture (clip planes,
 * alpha test) from secondary rays and queries (render/secondary.h).
 */
typedef int (*trace_accept_fn)(void *user, const float org[3], const float dir[3],
                               const struct trace_scene_hit *hit);

struct trace_object_view {
    const struct bvh *bvh;
    const float *tri;
    const struct bvh4 *wide; /* NULL or empty: the binary walk only */
    /* NULL, or where the rays that reach inside the object are counted
     * (the automatic update strategy's measured rays, scene/update.c):
     * visit_instance counts them per thread in trace_scene_counters and
     * the caller adds them here with flush_ray_count. */
    uint64_t *ray_count;
};

/* Fills *view for the object; returns 0 when it cannot be had (allocation
 * failure), in which case the instance is skipped. */
typedef int (*trace_acquire_fn)(void *user, void *object, struct trace_object_view *view);

struct trace_scene {
    const struct bvh *top;                 /* over instances[] */
    const struct trace_instance *instances; /* indexed by top->prim_index */
    trace_acquire_fn acquire;
    void *user;
    /* The object walk's ISA table (kernels.h); NULL means the scalar one.
     * Every table gives the same answers. */
    const struct trace_kernels *kernels;
    /* NULL or empty: the binary walk over `top`.  Else `top` collapsed to
     * the wide layout with range leaves (accel_collapse_wide with no
     * triangles), walked when kernels has a wide walk (wide_width != 0):
     * the same answers as the binary walk. */
    const struct bvh4 *top_wide;
    /* Fills *flat for a flattened hierarchy's object (trace_instance);
     * 0 when it cannot be had (the group is skipped). */
    int (*acquire_flat)(void *user, void *object, struct trace_flat *flat);
    /* NULL: every hit counts (no cost).  Else an instance whose
     * filtered[instance_id] & filter_mask is not 0 has its triangles
     * tested one by one against accept (trace/scene_filter.h), giving
     * the closest accepted hit with the walk's tie rule; the others are
     * walked as without a filter. */
    const uint8_t *filtered;
    uint8_t filter_mask;
    trace_accept_fn accept;
    void *accept_user;
    /* The batch walk (scene_stream.h): 1 to send a qualifying scene's
     * rays through the stream walk whatever its objects' size (the
     * configuration's stream=on), 0 only where the layouts say it pays
     * (stream=auto, bvh4.stream_pays).  stream=off is the table's
     * stream_counted NULL. */
    int stream_always;
};

struct trace_scene_hit {
    float t;
    float u;
    float v;
    uint32_t prim;     /* primitive index inside the object */
    uint32_t instance; /* index into trace_scene.instances (a member slot for a
                        * flattened hierarchy's hit) */
};

struct trace_scene_counters {
    struct trace_counters object; /* node and triangle tests below instances */
    uint64_t top_node_tests;
    uint64_t instance_tests;
    uint64_t rays;
    /* Rays counted for view.ray_count and not yet added to it: one
     * counter at a time per thread, added (one atomic add) when another
     * counted object comes, and by trace_scene_flush_ray_count. */
    uint64_t *ray_count;
    uint64_t ray_count_pending;
};

/* Adds the rays counted for a view's ray_count (see above) to it;
 * call when the thread's tracing is over. */
void trace_scene_flush_ray_count(struct trace_scene_counters *counters);
/* Counts `rays` rays for `target` when their object walk went past the
 * root's `root_tests` box tests a ray (tests_before: the node tests before
 * the walk).  A packet's rays are counted together, all of them when the
 * packet went past the root (some of its rays may have stopped there). */
void trace_scene_count_rays(struct trace_scene_counters *counters, uint64_t *target,
                            uint64_t tests_before, uint32_t root_tests, uint32_t rays);
/* Counts `rays` rays for `target` that reached inside its object (the
 * caller applied trace_scene_count_rays' rule ray by ray). */
void trace_scene_add_ray_count(struct trace_scene_counters *counters, uint64_t *target,
                               uint32_t rays);

/* Closest hit with tmin <= t < tmax in world space.  Returns 1 on a hit. */
int trace_scene_closest(const struct trace_scene *scene, const float org[3], const float dir[3],
                        float tmin, float tmax, struct trace_scene_hit *hit,
                        struct trace_scene_counters *counters);

/* Any hit with tmin <= t < tmax; returns 1 on the first found. */
int trace_scene_any(const struct trace_scene *scene, const float org[3], const float dir[3],
                    float tmin, float tmax, struct trace_scene_counters *counters);

/* The instance id the tie rule compares for the hit's slot. */
static inline uint32_t trace_scene_hit_id(const struct trace_scene *scene,
                                          const struct trace_scene_hit *hit)
{
    return scene->instances[hit->instance].instance_id;
}

/* The tie rule between instances, for a ray that has a hit already:
 * whether instance inst's hit at t replaces the kept hit (at best): when
 * nearer, or as near at a lower instance id.  The single-ray walk
 * (scene_traverse.c), the packet walk (packet_scene.c) and the batch walk
 * (scene_stream.c) all keep hits by it. */
static inline int trace_scene_hit_replaces(const struct trace_scene *scene,
                                           const struct trace_instance *inst, float t, float best,
                                           const struct trace_scene_hit *kept)
{
    return t < best || inst->instance_id < trace_scene_hit_id(scene, kept);
}

/*
 * Pieces of the single-ray walk that the packet walk (packet_scene.c)
 * repeats ray by ray, so that its answers are the same bit for bit.
 * trace_scene_object_ray: the world ray (org, dir, tmin; `world` its
 * set-up) in the instance's object space, set up; 0 when the transformed
 * direction cannot be traced (the instance is skipped).
 * trace_scene_box_rows: the rows of a wide node's bounds that hold the
 * ray's near and far planes per axis (by the signs of inv_dir), and its
 * octant (bit k set for a negative axis k).
 * trace_scene_wide_lanes: the lanes of a wide top-level node
 * (bounds[row * width + lane]) whose boxes the ray's [tmin, t_max]
 * meets, with their entry distances.
 */
static inline int trace_scene_box_rows(const struct trace_ray *ray, int near_row[3],
                                       int far_row[3])
{
    /* The sign bits, read as bits: the compilers turned signbit() and the
     * selects into branches and flag moves, about fifty instructions a
     * ray for what is three shifts. */
    uint32_t bits[3];
    memcpy(bits, ray->inv_dir, sizeof(bits));
    int octant = 0;
    for (int k = 0; k < 3; k++) {
        const int neg = (int)(bits[k] >> 31);
        near_row[k] = k + 3 * neg;
        far_row[k] = k + 3 - 3 * neg;
        octant |= neg << k;
    }
    return octant;
}

/*
 * The kinds of identity instance (TRACE_IDENTITY_*, a mask) whose
 * transform gives the origin and direction back bit for bit, so that
 * trace_scene_object_ray hands the world ray on.  The transform
 * (to_object_space) sums ((r0 x + r1 y) + r2 z) + r3 per row in double
 * and rounds to float.  A finite non-zero component is the exact product
 * 1 x, and adding zeros keeps it: both kinds.  A zero is a sum of zeros,
 * -0.0 only when every term is: with the exact rows a +0.0 stays +0.0
 * (the +0.0 of 1 x is among the terms), but a -0.0 may come back +0.0
 * (the origin's last term, r3, is +0.0); with -0.0 in the rows a zero of
 * either sign may change.  An infinity gives 0 inf, a NaN.  So: every
 * component finite and not zero, both kinds; finite and none -0.0 (the
 * direction not all zero, which is not usable and makes the instance
 * skipped), the exact kind; else neither.  Camera rays from an eye on an
 * axis (gluLookAt from (0, 0, 40)) are of the second class.  Read as
 * bits: a magnitude below the infinity's bits is finite.
 */
static inline unsigned trace_scene_plain_class(const float org[3], const float dir[3])
{
#if defined(__SSE2__) && !defined(RT_NO_SIMD)
    /* The six components in two registers (a plain 1.0 in lane 3), the
     * magnitudes' bits compared as integers.  First the common case,
     * every component finite and not zero: the magnitude less one below
     * FLT_MAX's bits, unsigned (the sign bit flipped for SSE2's signed
     * compare). */
    const __m128i o = _mm_castps_si128(_mm_setr_ps(org[0], org[1], org[2], 1.0f));
    const __m128i d = _mm_castps_si128(_mm_setr_ps(dir[0], dir[1], dir[2], 1.0f));
    const __m128i magnitude = _mm_set1_epi32(0x7fffffff);
    const __m128i sign = _mm_set1_epi32((int)0x80000000u);
    const __m128i one = _mm_set1_epi32(1);
    const __m128i below = _mm_set1_epi32((int)(0x7f7fffffu ^ 0x80000000u));
    const __m128i mo = _mm_and_si128(o, magnitude), md = _mm_and_si128(d, magnitude);
    const __m128i nz = _mm_and_si128(
        _mm_cmplt_epi32(_mm_xor_si128(_mm_sub_epi32(mo, one), sign), below),
        _mm_cmplt_epi32(_mm_xor_si128(_mm_sub_epi32(md, one), sign), below));
    if (_mm_movemask_ps(_mm_castsi128_ps(nz)) == 15)
        return TRACE_IDENTITY_ZEROS | TRACE_IDENTITY_EXACT;
    /* Else finite (the magnitudes, whose sign bit is clear, below the
     * infinity's as signed integers), none -0.0, the direction not zero. */
    const __m128i inf = _mm_set1_epi32(0x7f800000);
    const __m128i finite = _mm_and_si128(_mm_cmplt_epi32(mo, inf), _mm_cmplt_epi32(md, inf));
    const __m128i neg = _mm_or_si128(_mm_cmpeq_epi32(o, sign), _mm_cmpeq_epi32(d, sign));
    const __m128i zero_d = _mm_cmpeq_epi32(md, _mm_setzero_si128());
    const unsigned no_neg_zero =
        _mm_movemask_ps(_mm_castsi128_ps(_mm_andnot_si128(neg, finite))) == 15;
    const unsigned dir_not_zero = _mm_movemask_ps(_mm_castsi128_ps(zero_d)) != 7;
    return (no_neg_zero & dir_not_zero) * TRACE_IDENTITY_EXACT;
#else
    uint32_t a[6];
    memcpy(a, org, 3 * sizeof(float));
    memcpy(&a[3], dir, 3 * sizeof(float));
    unsigned finite = 1, nonzero = 1, no_neg_zero = 1;
    for (int k = 0; k < 6; k++) {
        const uint32_t m = a[k] & 0x7fffffffu;
        finite &= m < 0x7f800000u;
        nonzero &= m - 1u < 0x7f7fffffu;
        no_neg_zero &= a[k] != 0x80000000u;
    }
    const unsigned dir_not_zero = (a[3] | a[4] | a[5]) != 0u;
    return nonzero * (TRACE_IDENTITY_ZEROS | TRACE_IDENTITY_EXACT) |
           (finite & no_neg_zero & dir_not_zero) * TRACE_IDENTITY_EXACT;
#endif
}

int trace_scene_object_ray(const struct trace_instance *inst, const float org[3],
                           const float dir[3], float tmin, const struct trace_ray *world,
                           struct trace_ray *o_ray);
/* trace_scene_object_ray's origin and direction before the set-up: the
 * world ray transformed by the instance's rows (o_org, o_dir; the same
 * floats whichever way that function sets the ray up, since a set-up
 * depends on org, dir and tmin alone); 0 when the direction cannot be
 * traced (the instance is skipped). */
int trace_scene_object_inputs(const struct trace_instance *inst, const float org[3],
                              const float dir[3], float o_org[3], float o_dir[3]);
unsigned trace_scene_wide_lanes(const float *bounds, uint32_t width, const int near_row[3],
                                const int far_row[3], const struct trace_ray *ray, float t_max,
                                float t_entry[8]);

/* Node `cur` of the wide top level: its lane boxes, children and counts,
 * and its child order for `octant` as 3-bit lane numbers (the first lane
 * to visit in the highest bits), whether the layout is 4 or 8 wide; the
 * single and the packet walks read nodes through it. */
static inline uint32_t trace_scene_wide_node(const struct bvh4 *wide, uint32_t width,
                                             uint32_t cur, int octant, const float **bounds,
                                             const uint32_t **child, const uint8_t **count)
{
    if (width == 4) {
        const struct bvh4_node *n = &wide->nodes[cur];
        uint32_t order = 0;
        *bounds = &n->bounds[0][0];
        *child = n->child;
        *count = n->count;
        for (int q = 0; q < 4; q++)
            order |= (uint32_t)(n->order[octant] >> (2 * q) & 3u) << (3 * q);
        return order;
    }
    const struct bvh8_node *n = &wide->nodes8[cur];
    *bounds = &n->bounds[0][0];
    *child = n->child;
    *count = n->count;
    return (uint32_t)n->order[octant][0] | (uint32_t)n->order[octant][1] << 8 |
           (uint32_t)n->order[octant][2] << 16;
}

#endif
