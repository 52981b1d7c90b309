/* SPDX-License-Identifier: Apache-2.0 */
/*
 * flat_walk.h - the walk of a flattened nested hierarchy: one BVH over
 * the triangles of several instances (the segments a nested display list
 * placed), built in the space of the list called by the application (its
 * "root"), used as an acceleration structure only.
 *
 * Identical hits.  The flattened BVH's boxes are those of the triangles
 * transformed into the root's space, but no transformed vertex is ever
 * intersected: a leaf slot names (member, primitive), and the triangle is
 * tested with its object-space vertices (the floats the object's own
 * structure gathers) against the world ray transformed by the member's
 * own world-to-object matrix, trace_scene_object_ray, exactly as the
 * instance path transforms it.  isect_triangle's answer depends on the
 * ray and the three vertices alone (its t is clamped into the triangle's
 * own box, intersect.h), so each candidate's t, u and v are bit for bit
 * the instance path's.  The hit rule is the instance path's, order-free:
 * the smallest t, then the lowest instance id, then the lowest primitive
 * (scene_traverse.c's visit_instance and traverse_walk.h's walk_leaf), so
 * the answer is the same whatever the tree visits first.  What remains is
 * that the flattened tree never culls a box holding the winning hit: its
 * boxes are padded (scene/flatten.c says by how much and why) and culled
 * against best * ISECT_BOX_FAR_SCALE as the top level is.
 */
#ifndef RT_TRACE_FLAT_WALK_H
#define RT_TRACE_FLAT_WALK_H

#include <stdint.h>

#include "trace/scene_traverse.h"

/* A flattened hierarchy as the walk reads it. */
struct trace_flat {
    const struct bvh *bvh;  /* in the root's space, over leaf slots */
    const float *tri;       /* per leaf slot: the object-space vertices, 9 floats */
    const uint32_t *member; /* per leaf slot: member (0 .. member_count - 1) */
    const uint32_t *prim;   /* per leaf slot: primitive inside the member's object */
};

/* The state of one ray's top-level walk that the flat walk reads and
 * updates (best, box_limit, found, hit as visit_instance keeps them). */
struct trace_flat_ray {
    const float *org;
    const float *dir;
    float tmin;
    const struct trace_ray *world; /* the world ray's set-up */
    float *best;
    float *box_limit;
    int *found;
    struct trace_scene_hit *hit; /* NULL for any hit */
    /* NULL, or the scene whose hit filter (trace_scene.accept) applies to
     * the members it marks. */
    const struct trace_scene *filter;
};

/* Walks group (a top-level slot with member_count > 0) for one ray;
 * members are instances[group->member_base ..].  Returns 1 when an any-hit
 * walk found its hit. */
int trace_flat_walk(const struct trace_flat *flat, const struct trace_instance *instances,
                    const struct trace_instance *group, struct trace_flat_ray *r,
                    struct trace_scene_counters *counters);

#endif
