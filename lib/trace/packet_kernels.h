/* SPDX-License-Identifier: Apache-2.0 */
/*
 * packet_kernels.h - the packet walk's entries per instruction set,
 * defined by the packet walk's own translation units (packet_sse4.c,
 * packet_avx2.c, packet_avx512.c) and named in the kernels tables of
 * traverse_sse4.c, traverse_avx2.c and traverse_avx512.c (kernels.h says
 * what each entry does).
 *
 * Why units apart: with the packet walk in the single walk's unit, a
 * change to the packet walk alone moved the single walk's code (the
 * functions' starts by 32 bytes), and the single walk, its code
 * unchanged, ran up to 13 % slower in that binary on a quiet machine
 * (docs/performance-log.md, pk11).  The packet units are the last of
 * the library's sources (CMakeLists.txt): the shared library, linked in
 * that order, has nothing after them; a static link places the archive's
 * objects in the order the linker pulls them, and there the single walk
 * stays before them while some other objects follow (pk12).
 */
#ifndef RT_TRACE_PACKET_KERNELS_H
#define RT_TRACE_PACKET_KERNELS_H

#include "trace/kernels.h"

/* The packet walks over set-up rays (packet_wide.h). */
#define TRACE_PACKET_KERNELS_WALKS(isa)                                                           \
    unsigned trace_closest_packet_##isa(const struct bvh4 *wide, const struct bvh *bvh,          \
                                        const float *tri, const struct trace_ray *rays,           \
                                        const float *t_max, unsigned active, unsigned hybrid,     \
                                        struct trace_hit *hits, struct trace_counters *counters); \
    unsigned trace_any_packet_##isa(const struct bvh4 *wide, const struct bvh *bvh,              \
                                    const float *tri, const struct trace_ray *rays,               \
                                    const float *t_max, unsigned active, unsigned hybrid,         \
                                    struct trace_counters *counters)

/* The 256-bit tables' entries besides: the set-up (packet_init.h), the
 * instances' transform (packet_xform.h) and the walks from the caller's
 * arrays (packet_wide.h). */
#define TRACE_PACKET_KERNELS_LANES(isa)                                                           \
    void trace_packet_init_##isa(const float (*org)[3], const float (*dir)[3], const float *tmin, \
                                 unsigned live, struct trace_ray rays[TRACE_PACKET],              \
                                 struct trace_top_rays *top, struct trace_packet_plain *plain);  \
    unsigned trace_packet_xform_##isa(const double m[12], const float (*org)[3],                 \
                                      const float (*dir)[3], const float *tmin, unsigned rays,    \
                                      struct trace_ray o_ray[TRACE_PACKET]);                      \
    unsigned trace_closest_packet_arrays_##isa(                                                   \
        const struct bvh4 *wide, const struct bvh *bvh, const float *tri, const float(*org)[3],  \
        const float(*dir)[3], const float *tmin, const float *t_max, unsigned active,             \
        unsigned hybrid, struct trace_hit *hits, struct trace_counters *counters);                \
    unsigned trace_any_packet_arrays_##isa(                                                       \
        const struct bvh4 *wide, const struct bvh *bvh, const float *tri, const float(*org)[3],  \
        const float(*dir)[3], const float *tmin, const float *t_max, unsigned active,             \
        unsigned hybrid, struct trace_counters *counters)

TRACE_PACKET_KERNELS_WALKS(sse4);
TRACE_PACKET_KERNELS_WALKS(avx2);
TRACE_PACKET_KERNELS_LANES(avx2);
TRACE_PACKET_KERNELS_WALKS(avx512);
TRACE_PACKET_KERNELS_LANES(avx512);

#endif
