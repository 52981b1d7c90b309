/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene_stream.h - the two-level walk for a batch of single rays: the
 * answers of trace_scene_closest / trace_scene_any ray by ray, bit for
 * bit, and the same counters, with the rays of a qualifying scene sent
 * through the table's stream walk (kernels.h, stream_counted;
 * traverse_pair8.h), which steps several rays in turn so that one ray's
 * cache misses overlap the others' work (Kocberber, Falsafi and Grot
 * 2015, asynchronous memory access chaining).
 *
 * A scene qualifies when its top level is one leaf (a scene of one
 * instance, or a few in one leaf: the common flattened static scene)
 * whose instances are plain (not a flattened group, not marked for the
 * scene's hit filter) with an 8-wide layout the table has a stream for,
 * and, unless scene->stream_always, every one of them flagged as a
 * layout where the stream pays (bvh4.stream_pays).  Other scenes, and
 * the rays that the single-ray walk would not hand to the leaf at once
 * (not tmin < tmax, or an origin or direction outside
 * trace_scene_plain_class's exact class, which take the world set-up
 * and the top-level box test), go ray by ray through
 * trace_scene_closest / trace_scene_any.  A top level of several leaves
 * goes ray by ray too (the top-level walk is not repeated here).
 */
#ifndef RT_TRACE_SCENE_STREAM_H
#define RT_TRACE_SCENE_STREAM_H

#include <stddef.h>
#include <stdint.h>

#include "trace/scene_traverse.h"

/* Ray i at rays + i * stride floats in RTray's layout (org[3], tmin,
 * dir[3], tmax).  Closest hit: found[i] as trace_scene_closest returns
 * it, hits[i] its hit when found.  Any hit: occluded[i] as
 * trace_scene_any returns it.  Every ray counted in *counters as those
 * functions count it (rays, instance tests, node and triangle tests,
 * the view's ray_count).  Uses about 70 KB of the caller's stack
 * (scene_stream.c says why). */
void trace_scene_closest_batch(const struct trace_scene *scene, const float *rays, size_t stride,
                               uint32_t count, struct trace_scene_hit *hits, unsigned char *found,
                               struct trace_scene_counters *counters);
void trace_scene_any_batch(const struct trace_scene *scene, const float *rays, size_t stride,
                           uint32_t count, unsigned char *occluded,
                           struct trace_scene_counters *counters);

#endif
