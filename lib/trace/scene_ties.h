/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene_ties.h - the hits that share one distance along a ray.
 *
 * trace_scene_closest returns, of the hits at exactly the same t, the one
 * of the lowest instance and then the lowest primitive (scene_traverse.c).
 * A caller that must see every surface at that distance (coplanar
 * translucent triangles, which GL blends one after the other in the
 * order they were drawn) asks here for the next ones in that same order.
 */
#ifndef RT_TRACE_SCENE_TIES_H
#define RT_TRACE_SCENE_TIES_H

#include "trace/scene_traverse.h"

/*
 * The hits at exactly `after->t` whose (instance, prim) comes after
 * after's, in increasing (instance, prim) order: the `max` first of them
 * go to out[], and the number stored is returned (0 to max); *total (when
 * not NULL) receives how many there are, so that a caller that wants
 * them all can make room and ask once more.  Each t is
 * the one trace_scene_closest computes for that triangle, bit for bit
 * (the same object ray, box and triangle tests), so a triangle is either
 * one of these ties or lies at another distance, never both.  One walk of
 * both levels restricted to the point at t, whatever max is: the cost is
 * bounded by the triangles whose boxes hold that point.
 */
int trace_scene_ties(const struct trace_scene *scene, const float org[3], const float dir[3],
                     const struct trace_scene_hit *after, struct trace_scene_hit *out, int max,
                     int *total, struct trace_scene_counters *counters);

#endif
