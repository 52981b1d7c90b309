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

/* 1 when the ray at r (RTray's layout) is one the batch walk may take
 * through the stream: tmin < tmax and trace_scene_plain_class's exact
 * class, the rays that the single-ray walk hands to a one-leaf top
 * level's instances at once, acquiring each (scene_traverse.c, walk). */
static inline int trace_scene_stream_ray(const float *r)
{
    return r[3] < r[7] && (trace_scene_plain_class(r, r + 4) & TRACE_IDENTITY_EXACT) != 0;
}

/* 1 when the scene qualifies (above) for closest-hit (any_hit 0) or
 * any-hit rays, so that the batch functions would take the stream; 0
 * when they would go ray by ray, which a caller may then do itself.
 * Acquires the leaf's objects (scene->acquire), which may build them:
 * call it once a trace_scene_stream_ray ray has come, which acquires
 * them too in the single-ray walk (an any-hit ray there stops at its
 * first hit, before the leaf's later instances: those are built here
 * where that walk might not have built them yet; the batch functions
 * do the same). */
int trace_scene_stream_ready(const struct trace_scene *scene, int any_hit);

#endif
