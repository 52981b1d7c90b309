/* SPDX-License-Identifier: Apache-2.0 */
/*
 * kernels.h - the traversal kernels per instruction set, chosen once per
 * context.
 *
 * The single-BVH walk (traverse_walk.h) is compiled once per ISA, each
 * translation unit with its own flags: the scalar baseline (traverse.c,
 * no SIMD intrinsics, the reference), SSE4.2, AVX2 + FMA and AVX-512.
 * Every table gives the same answers bit for bit (traverse_walk.h says
 * why; conformance/internal/kernel_bits checks it), so the choice changes
 * speed only.  A context takes the best table the CPU supports (cpuid)
 * unless its configuration names one (isa=, docs/context.md).
 */
#ifndef RT_TRACE_KERNELS_H
#define RT_TRACE_KERNELS_H

#include <stddef.h>

#include "trace/bvh4_layout.h"
#include "trace/packet.h"
#include "trace/trace.h"

enum trace_isa {
    TRACE_ISA_SCALAR,
    TRACE_ISA_SSE4,
    TRACE_ISA_AVX2,
    TRACE_ISA_AVX512,
    TRACE_ISA_COUNT
};

/* A single-ray walk over one wide layout, from the ray's origin,
 * direction and tmin, without counters: closest1's (hit) or any1's
 * answer (hit unused, NULL allowed), as struct trace_kernels' walk1
 * chooses it for the layout. */
typedef int (*trace_walk1_fn)(const struct bvh4 *wide, const float org[3], const float dir[3],
                              float tmin, float t_max, struct trace_hit *hit,
                              struct trace_counters *counters);

/* A stream of single rays over one wide layout without counters (struct
 * trace_kernels' stream_pair): ray i at rays + i * stride floats, in
 * RTray's layout (org[3], tmin, dir[3], tmax); got[i] walk1's answer
 * for the ray (closest hit: found, with hits[i] its hit when found; any
 * hit: occluded, hits unused, NULL allowed), bit for bit. */
typedef void (*trace_stream1_fn)(const struct bvh4 *wide, const float *rays, size_t stride,
                                 uint32_t count, struct trace_hit *hits, unsigned char *got);

/* trace_stream1_fn with counters: the same answers, and each ray counted
 * as walk1_counted counts it (node tests eight a wide node, a leaf's
 * triangles), the sums added to *counters and ray i's node tests stored
 * in ray_nodes[i] (the two-level walk's rule of the rays that reach
 * inside an object, trace_scene_count_rays). */
typedef void (*trace_stream1_counted_fn)(const struct bvh4 *wide, const float *rays,
                                         size_t stride, uint32_t count, struct trace_hit *hits,
                                         unsigned char *got, struct trace_counters *counters,
                                         uint32_t *ray_nodes);

struct trace_kernels {
    enum trace_isa isa;
    const char *name; /* "scalar", "sse4", "avx2", "avx512": the isa= value */
    int (*closest)(const struct bvh *bvh, const float *tri, const struct trace_ray *ray,
                   float t_max, struct trace_hit *hit, struct trace_counters *counters);
    int (*any)(const struct bvh *bvh, const float *tri, const struct trace_ray *ray,
               float t_max, struct trace_counters *counters);
    /* The walk over the wide layout (traverse_wide.h), 4- or 8-wide as
     * wide->width says, same answers as closest/any (not the same node
     * and triangle counts); NULL in the scalar table, which keeps the
     * binary walk as the reference.  bvh and tri are the binary tree
     * wide was collapsed from and its triangles: a width the table does
     * not walk takes the binary walk over them. */
    int (*closest4)(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                    const struct trace_ray *ray, float t_max, struct trace_hit *hit,
                    struct trace_counters *counters);
    int (*any4)(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                const struct trace_ray *ray, float t_max, struct trace_counters *counters);
    /* closest4/any4 from the ray's origin, direction and tmin, for a
     * ray traced alone: trace_ray_init_single's ray, set up inside the
     * walk (ray_setup.h), so the walk starts from the set-up's registers
     * instead of a struct stored by another function and read back; the
     * same answers as trace_ray_init_single followed by closest4/any4.
     * org and dir as trace_ray_init's (finite, dir non-zero).  NULL in
     * the scalar table, as closest4/any4. */
    int (*closest1)(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                    const float org[3], const float dir[3], float tmin, float t_max,
                    struct trace_hit *hit, struct trace_counters *counters);
    int (*any1)(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                const float org[3], const float dir[3], float tmin, float t_max,
                struct trace_counters *counters);
    /* The widest layout closest4/any4 walk: 0 (scalar), 4 (SSE4.2) or 8
     * (AVX2, AVX-512); the width a context's objects are collapsed to
     * (bvh_build_params.wide_layout). */
    uint32_t wide_width;
    /* Packet walks over the wide layout (packet.h, packet_wide.h): up to
     * TRACE_PACKET rays at once, each with closest4's (any4's) answer bit
     * for bit.  NULL in the scalar table, and in a context's copy of a
     * table when its configuration says packets=off: every caller then
     * traces ray by ray, which is how packets on and off are compared. */
    trace_packet_closest_fn closest_packet;
    trace_packet_any_fn any_packet;
    /* The 8-wide walks' leaf test on its own (traverse_wide.h,
     * TRACE_WIDE_LEAF8), for conformance/internal/tri4_differential:
     * the n triangles of p[0], p[1] with the 8-lane call (eight 1; 2:
     * the closest-hit walk's first-leaf copy) or the 4-lane calls
     * (eight 0).  NULL in the tables without the
     * 8-wide walk (scalar, SSE4.2). */
    int (*leaf8)(const struct trace_ray *ray, const struct tri4_packet *p, uint32_t n,
                 float t_max, int any_hit, int early_out, int eight, int found,
                 struct trace_hit *hit);
    /* The top level's node tests (top_lanes.h): a packet's, eight rays a
     * register, NULL in the tables without 256-bit lanes (packet_scene.c
     * then tests four rays a register itself); and a single ray's, eight
     * lanes a register, in the tables without 256-bit lanes
     * trace_scene_wide_lanes itself (four lanes a register). */
    trace_top_lanes_fn top_lanes;
    unsigned (*top_lanes1)(const float *bounds, uint32_t width, const int near_row[3],
                           const int far_row[3], const struct trace_ray *ray, float t_max,
                           float t_entry[8]);
    /* A packet's rays set up eight at a time for the two-level packet walk
     * (packet_init.h); NULL in the tables without 256-bit lanes, where
     * packet_scene.c calls trace_ray_init ray by ray. */
    trace_packet_init_fn packet_init;
    /* trace_scene_object_ray (scene_traverse.h) for the rays of mask
     * `rays` of a packet at once (packet_xform.h): o_ray[r] for each ray
     * whose transformed direction can be traced, bit for bit that
     * function's ray, and the mask of those rays returned.  org, dir and
     * tmin are a packet's arrays, all TRACE_PACKET entries read; m is
     * trace_instance.world_to_object.  NULL in the tables without 256-bit
     * lanes, where packet_scene.c transforms ray by ray. */
    unsigned (*packet_xform)(const double m[12], const float (*org)[3], const float (*dir)[3],
                             const float *tmin, unsigned rays,
                             struct trace_ray o_ray[TRACE_PACKET]);
    /* The walk closest1 (any_hit 0) or any1 (any_hit 1) takes on this
     * layout without counters, chosen once for the layout instead of
     * once a ray (the entries test width, node count, prefetch_top and,
     * any hit, any_longest every ray): called with counters NULL it gives
     * closest1's / any1's answer bit for bit.  NULL where those entries
     * take no walk of their own (a layout without an 8-wide walk in this
     * table: call closest1 / any1), and in the tables without the 8-wide
     * walk. */
    trace_walk1_fn (*walk1)(const struct bvh4 *wide, int any_hit);
    /* The walks closest1 / any1 take with counters on an 8-wide layout
     * with nodes (width 8, node_count > 0), by index 2 any_hit +
     * ((any_hit ? any_longest : prefetch_top) != 0), for a caller that
     * has tested the layout
     * already: the two-level walk's rays that reach an identity
     * instance's object without a world set-up (scene_traverse.c), which
     * then call the walk without the entries' per-ray tests of counters,
     * width, node count and prefetch_top.  Called with counters (not
     * NULL), the answers and counts of closest1 / any1 with counters, bit
     * for bit.  NULL in the tables without the 8-wide walk. */
    const trace_walk1_fn *walk1_counted;
    /* closest_packet / any_packet from the caller's arrays instead of
     * set-up rays (packet.h): the set-up and the walk in one call, the
     * rays kept in the lanes between them.  NULL where closest_packet is
     * (and in the tables without AVX2). */
    trace_packet_closest_arrays_fn closest_packet_arrays;
    trace_packet_any_arrays_fn any_packet_arrays;
    /* walk1's rays as a stream (trace_stream1_fn), several rays walked
     * at once, one step of each in turn (traverse_pair8.h), for the layout
     * walk1 chooses its walk for (any_hit 0 or 1); the same answers as
     * walk1 ray by ray.  NULL where walk1 is, and in the tables without
     * the pair walk (scalar, SSE4.2).  The AVX-512 table takes the AVX2
     * table's (trace_stream_pair_avx2: every AVX-512 CPU runs AVX2, and
     * every table's answers are the same), so its rays walk with
     * isect_box's node test, not the AVX-512 walk1's fused one: the same
     * answers, and the counts of the AVX2 table (stream_counted). */
    trace_stream1_fn (*stream_pair)(const struct bvh4 *wide, int any_hit);
    /* stream_pair's walks with counters (trace_stream1_counted_fn), for
     * the two-level batch walk (scene_stream.h), which counts every ray
     * as the single-ray walk does; NULL where stream_pair is, and in a
     * context's copy of a table whose configuration says stream=off. */
    trace_stream1_counted_fn (*stream_counted)(const struct bvh4 *wide, int any_hit);
};

/* The table of an ISA, or NULL when this build has no such table or this
 * CPU cannot run it.  The scalar table always exists. */
const struct trace_kernels *trace_kernels_get(enum trace_isa isa);

/* The fastest table this CPU runs (never NULL). */
const struct trace_kernels *trace_kernels_best(void);

/* The ISA named name[0..len) ("scalar", "sse4", "avx2", "avx512");
 * returns 0 and sets *isa, or -1 for another name. */
int trace_isa_parse(const char *name, size_t len, enum trace_isa *isa);

/* The per-ISA tables themselves (NULL when the translation unit was
 * compiled without its instruction set); trace_kernels_get adds the CPU
 * check. */
const struct trace_kernels *trace_kernels_sse4(void);
const struct trace_kernels *trace_kernels_avx2(void);
const struct trace_kernels *trace_kernels_avx512(void);
/* The AVX-512 table with the single-ray walks' front child by the
 * trailing-zero count instead of compression (traverse_avx512.c; the
 * same answers and counts): the form trace_kernels_get gives for
 * TRACE_ISA_AVX512 on an AMD CPU (kernels.c says why). */
const struct trace_kernels *trace_kernels_avx512_ctz(void);

/* The AVX2 table's stream_pair (stream_avx2.c), defined only where the
 * table is (traverse_avx2.c refers to it only then). */
trace_stream1_fn trace_stream_pair_avx2(const struct bvh4 *wide, int any_hit);
trace_stream1_counted_fn trace_stream_counted_avx2(const struct bvh4 *wide, int any_hit);

#endif
