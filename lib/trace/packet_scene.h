/* SPDX-License-Identifier: Apache-2.0 */
/*
 * packet_scene.h - two-level traversal of a packet of up to TRACE_PACKET
 * rays (packet.h): the wide top level over instances walked by the
 * packet, each instance's object walked by the kernels' packet walk with
 * the rays transformed ray by ray into its space.
 *
 * Every ray gets exactly trace_scene_closest's (trace_scene_any's)
 * answer for it alone, bit for bit, and the `rays` counter counts it
 * once; the node and triangle counts differ.  After an instance's
 * transform the rays of a packet need not share the octant of their
 * directions (Wald, Benthin and Slusallek 2003 sec. 4.4): every box test
 * is a ray's own, with its own near and far planes, and only the order
 * in which a node's children are visited follows the packet's first ray,
 * which no answer depends on.  A scene with a hit filter
 * (trace_scene.filtered) is filtered as the single walk filters it: the
 * instances the filter marks are walked for every ray's closest hit,
 * which the filter is asked about ray by ray, and a ray whose hit it
 * rejects finishes that instance alone (scene_filter.h); the filter sees
 * the single walk's candidates, in another order between rays (an
 * accept function must not depend on the order of its calls).  When
 * the scene's kernels have no packet walk (isa=scalar, packets=off) or
 * no wide top level, each ray is traced alone.
 */
#ifndef RT_TRACE_PACKET_SCENE_H
#define RT_TRACE_PACKET_SCENE_H

#include "trace/packet.h"
#include "trace/scene_traverse.h"

/* The rays of a packet, world space: ray i (bit i of active) is org[i],
 * dir[i] with tmin[i] <= t < tmax[i], as trace_scene_closest takes them. */
struct trace_packet {
    float org[TRACE_PACKET][3];
    float dir[TRACE_PACKET][3];
    float tmin[TRACE_PACKET];
    float tmax[TRACE_PACKET];
    unsigned active;
};

/* Closest hits: returns the mask of rays with a hit and fills hits[i]
 * for them; hits[i] of the others is left alone. */
unsigned trace_scene_closest_packet(const struct trace_scene *scene, const struct trace_packet *p,
                                    struct trace_scene_hit hits[TRACE_PACKET],
                                    struct trace_scene_counters *counters);

/* Any hits: returns the mask of occluded rays. */
unsigned trace_scene_any_packet(const struct trace_scene *scene, const struct trace_packet *p,
                                struct trace_scene_counters *counters);

/*
 * Whether the directions dir[0..n) (n <= TRACE_PACKET) look coherent
 * enough for a packet: they share an octant and lie within about 25
 * degrees of the first one.  A cheap guess for callers with rays from
 * anywhere (rtTraceRays); a wrong guess costs time, never an answer.
 */
int trace_packet_coherent(const float *const dir[], int n);

#endif
