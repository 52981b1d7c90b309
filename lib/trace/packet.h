/* SPDX-License-Identifier: Apache-2.0 */
/*
 * packet.h - ray packets: up to TRACE_PACKET coherent rays walked through
 * one BVH together (Wald, Slusallek, Benthin and Wagner 2001; Wald,
 * Benthin and Boulos 2008 for wide BVHs), with the same answers as the
 * single-ray walk bit for bit.
 *
 * A packet visits a node once for all its active rays: the node is
 * fetched once, the stack is pushed and popped once, and each child
 * carries the mask of the rays whose box test it passed.  A box test is
 * the single-ray walk's own, ray by ray (each ray with its own near/far
 * planes, so rays of one packet need not share the octant of their
 * directions: after an instance transform they may not, Wald, Benthin
 * and Slusallek 2003 sec. 4.4), or, for a packet in one octant over the
 * 8-wide layout, an interval test for the whole packet that passes every
 * child one of its rays' own tests passes (packet_wide.h,
 * packet_walk8_ia; leaf boxes per ray where the beam is wide against
 * them); a triangle test is isect_triangle's answer for each ray, eight
 * rays at a time
 * (packet_tri8.h) or ray by ray; and the closest-hit rule (smallest t,
 * ties to the lower primitive, traverse_walk.h) does not depend on the
 * order of visits; so a ray of a packet gets exactly the hit it gets
 * alone, only the node and triangle counts differ.
 *
 * Hybrid fallback (Benthin, Wald, Woop, Ernst and Mark 2012, Embree's
 * hybrid traversal): when fewer than TRACE_PACKET_HYBRID rays of a
 * packet are left in a subtree, each continues alone through the
 * single-ray walk from that subtree's root (docs/performance-log.md has the
 * measurement behind the threshold).
 */
#ifndef RT_TRACE_PACKET_H
#define RT_TRACE_PACKET_H

#include <stdint.h>

#include "trace/bvh4_layout.h"
#include "trace/trace.h"

/* Rays per packet: 8, one ray per bit of an active mask. */
#define TRACE_PACKET 8
/* Below this many active rays a subtree is walked ray by ray.  0: never.
 * Measured (rtbench packets, docs/performance-log.md): with every box test
 * a ray's own, a packet of few rays wastes no SIMD lanes, only its
 * bookkeeping, and falling back at 2, 3, 4 or 6 rays was up to 10%
 * slower than never on the coherent sets (within noise on two of six). */
#define TRACE_PACKET_HYBRID 0

/*
 * A packet's rays as a wide top-level node test wants them (packet_scene.c,
 * kernels.h top_lanes): ray r in lane r of each array, the live rays
 * sharing one octant, whose rows near_row/far_row name (bounds rows per
 * axis, as trace_scene_box_rows gives them), and having finite origins;
 * box_limit is each ray's current t_max for boxes.  The lanes of rays not
 * in the walk hold zeros.
 */
struct trace_top_rays {
    float tmin[TRACE_PACKET] __attribute__((aligned(32)));
    float box_limit[TRACE_PACKET] __attribute__((aligned(32)));
    float org[3][TRACE_PACKET] __attribute__((aligned(32)));
    float inv_dir[3][TRACE_PACKET] __attribute__((aligned(32)));
    int near_row[3];
    int far_row[3];
};

#if defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <xmmintrin.h>

/* The lanes of a wide node (bounds[row * width + lane], width 4 or 8,
 * 16-byte aligned rows) whose box is not the empty box of an unused lane
 * (min x <= max x; bvh4_layout.h). */
static inline unsigned trace_top_used_lanes(const float *bounds, uint32_t width)
{
    unsigned used = 0;
    for (uint32_t h = 0; h < width; h += 4)
        used |= (unsigned)_mm_movemask_ps(_mm_cmple_ps(_mm_load_ps(bounds + h),
                                                       _mm_load_ps(bounds + 3 * width + h)))
                << h;
    return used;
}
#endif

/* The lanes of a wide top-level node (bounds[row * width + lane], width
 * 4 or 8) that the rays of mask `rays` enter: each such ray's bit is or'ed
 * into lane_rays[lane], and t_min[lane] lowered to its entry distance
 * where smaller, in the order of the rays.  Each ray and lane computes
 * what trace_scene_wide_lanes computes, operation for operation; a lane
 * whose box is empty (an unused lane, bvh4_layout.h), which a finite
 * origin always misses, is left out. */
typedef void (*trace_top_lanes_fn)(const struct trace_top_rays *q, const float *bounds,
                                   uint32_t width, unsigned rays, unsigned lane_rays[8],
                                   float t_min[8]);

/* What the two-level packet walk asks of its rays besides their set-up
 * (packet_scene.c), as masks of the rays: the classes of
 * trace_scene_plain_class (scene_traverse.h), zeros (every component
 * finite and not zero) and exact (finite, none -0.0, the direction not
 * zero), and the rays whose origin is finite. */
struct trace_packet_plain {
    unsigned zeros;
    unsigned exact;
    unsigned finite_org;
};

/* Sets up the rays of mask `live` (org[r], dir[r], tmin[r]) into rays[r]
 * as trace_ray_init does, bit for bit, fills top's tmin, org and inv_dir
 * lanes (zeros for the others; box_limit, the rows and the octant are
 * the caller's, trace_scene_box_rows), and, when plain is not NULL,
 * *plain for the live rays (no bits for the others).  Only the two-level
 * walk asks for *plain (its identity instances); a caller of the object
 * walk alone passes NULL and does not pay for it (about 12 instructions a
 * ray of rtbench's kitchen shadow packets, docs/performance-log.md). */
typedef void (*trace_packet_init_fn)(const float (*org)[3], const float (*dir)[3],
                                     const float *tmin, unsigned live,
                                     struct trace_ray rays[TRACE_PACKET],
                                     struct trace_top_rays *top,
                                     struct trace_packet_plain *plain);

/*
 * The packet walks of a kernels table (kernels.h): rays[i] with
 * t_max[i] for every bit i of `active`.  Closest: returns the mask of
 * rays with a hit and fills hits[i] for them (others left alone), each
 * exactly what the table's closest4 returns for that ray alone.  Any:
 * returns the mask of occluded rays, each what any4 returns.  `hybrid`:
 * the hybrid threshold (TRACE_PACKET_HYBRID; 0 never falls back, 9
 * always does).  counters may be NULL.
 */
typedef unsigned (*trace_packet_closest_fn)(const struct bvh4 *wide, const struct bvh *bvh,
                                            const float *tri, const struct trace_ray *rays,
                                            const float *t_max, unsigned active,
                                            unsigned hybrid, struct trace_hit *hits,
                                            struct trace_counters *counters);
typedef unsigned (*trace_packet_any_fn)(const struct bvh4 *wide, const struct bvh *bvh,
                                        const float *tri, const struct trace_ray *rays,
                                        const float *t_max, unsigned active, unsigned hybrid,
                                        struct trace_counters *counters);

/*
 * The same walks from the caller's arrays of a packet (org[r], dir[r],
 * tmin[r] as trace_packet_init_fn reads them; t_max[r]) instead of set-up
 * rays: each ray's answer is the closest (any) packet walk's for the ray
 * the table's packet_init sets up from them, bit for bit.  The rays stay
 * in the lanes from the arrays to the walk: no rays' structs are stored
 * and loaded back unless a per-ray step of the walk needs them
 * (packet_wide.h, packet_run).  NULL in the tables without AVX2.
 */
typedef unsigned (*trace_packet_closest_arrays_fn)(const struct bvh4 *wide,
                                                   const struct bvh *bvh, const float *tri,
                                                   const float (*org)[3], const float (*dir)[3],
                                                   const float *tmin, const float *t_max,
                                                   unsigned active, unsigned hybrid,
                                                   struct trace_hit *hits,
                                                   struct trace_counters *counters);
typedef unsigned (*trace_packet_any_arrays_fn)(const struct bvh4 *wide, const struct bvh *bvh,
                                               const float *tri, const float (*org)[3],
                                               const float (*dir)[3], const float *tmin,
                                               const float *t_max, unsigned active,
                                               unsigned hybrid, struct trace_counters *counters);

#endif
