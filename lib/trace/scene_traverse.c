/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene_traverse.c - two-level traversal (see scene_traverse.h).
 */
#include "trace/scene_traverse.h"

#include "trace/intersect.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* The ray in object space, computed in double and rounded once. */
static void to_object_space(const double m[12], const float org[3], const float dir[3],
                            float o_org[3], float o_dir[3])
{
    for (int r = 0; r < 3; r++) {
        const double *row = &m[4 * r];
        o_org[r] = (float)(row[0] * org[0] + row[1] * org[1] + row[2] * org[2] + row[3]);
        o_dir[r] = (float)(row[0] * dir[0] + row[1] * dir[1] + row[2] * dir[2]);
    }
}

/* A transformed direction can underflow to zero or overflow for extreme
 * (but accepted) matrices; such a ray cannot be traced in object space. */
static int usable_direction(const float d[3])
{
    return isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2]) &&
           (d[0] != 0.0f || d[1] != 0.0f || d[2] != 0.0f);
}

/* Shared top-level walk.  With any_hit the first hit ends the walk. */
static int walk(const struct trace_scene *scene, const float org[3], const float dir[3],
                float tmin, float tmax, int any_hit, struct trace_scene_hit *hit,
                struct trace_scene_counters *counters)
{
    const struct bvh *top = scene->top;
    if (!top || top->node_count == 0 || !(tmin < tmax))
        return 0;
    const struct trace_kernels *kernels =
        scene->kernels ? scene->kernels : trace_kernels_get(TRACE_ISA_SCALAR);
    /* One set-up per ray: the ray constants, and the box test's, which
     * every top-level box test below shares. */
    struct trace_ray ray;
    trace_ray_init(&ray, org, dir, tmin);
    struct isect_box_ray br;
    isect_box_ray_init(&br, &ray);

    float best = tmax;
    float box_limit = tmax; /* as in traverse.c: widened once a hit is found */
    int found = 0;
    /* Deferred far children with their entry distances: a popped subtree
     * that starts beyond the closest hit so far is skipped. */
    uint32_t stack[BVH_MAX_DEPTH + 1];
    float stack_t[BVH_MAX_DEPTH + 1];
    int sp = 0;
    uint32_t node_index = 0;
    float t_entry;
    counters->top_node_tests++;
    if (!isect_box(&br, &top->nodes[0], best, &t_entry))
        return 0;
    for (;;) {
        const struct bvh_node *node = &top->nodes[node_index];
        if (node->count) {
            for (uint32_t i = 0; i < node->count; i++) {
                const struct trace_instance *inst =
                    &scene->instances[top->prim_index[node->first + i]];
                struct trace_object_view view = {NULL, NULL, NULL};
                counters->instance_tests++;
                if (!scene->acquire(scene->user, inst->object, &view))
                    continue;
                float o_org[3], o_dir[3];
                to_object_space(inst->world_to_object, org, dir, o_org, o_dir);
                if (!usable_direction(o_dir))
                    continue;
                /* An instance whose matrix leaves the ray as it is (the
                 * identity, as for a scene of one static object) reuses
                 * the world ray's set-up: trace_ray_init depends on org,
                 * dir and tmin alone, so that is the same ray bit for
                 * bit, without its five divisions. */
                struct trace_ray o_ray;
                if (memcmp(o_org, org, sizeof(o_org)) == 0 &&
                    memcmp(o_dir, dir, sizeof(o_dir)) == 0)
                    o_ray = ray;
                else
                    trace_ray_init(&o_ray, o_org, o_dir, tmin);
                /* The wide walk where the table has one and the object a
                 * wide layout: the same answers (kernels.h). */
                const int wide = view.wide && view.wide->node_count && kernels->closest4;
                if (any_hit) {
                    if (wide ? kernels->any4(view.wide, view.bvh, view.tri, &o_ray, best,
                                             &counters->object)
                             : kernels->any(view.bvh, view.tri, &o_ray, best,
                                            &counters->object))
                        return 1;
                    continue;
                }
                /* Ties between instances go to the lower instance, as ties
                 * inside an object go to the lower primitive: hits do not
                 * depend on the top-level tree. */
                uint32_t index = top->prim_index[node->first + i];
                float limit = found ? isect_next_up(best) : best;
                struct trace_hit h;
                int got = wide ? kernels->closest4(view.wide, view.bvh, view.tri, &o_ray, limit,
                                                   &h, &counters->object)
                               : kernels->closest(view.bvh, view.tri, &o_ray, limit, &h,
                                                  &counters->object);
                if (got &&
                    (!found || h.t < best || index < hit->instance)) {
                    best = h.t;
                    box_limit = best * ISECT_BOX_FAR_SCALE;
                    found = 1;
                    hit->t = h.t;
                    hit->u = h.u;
                    hit->v = h.v;
                    hit->prim = h.prim;
                    hit->instance = index;
                }
            }
        } else {
            /* Visit the nearer child first; push the farther one. */
            uint32_t left = node->first, right = node->first + 1;
            float t_left, t_right;
            counters->top_node_tests += 2;
            int hit_left = isect_box(&br, &top->nodes[left], box_limit, &t_left);
            int hit_right = isect_box(&br, &top->nodes[right], box_limit, &t_right);
            if (hit_left && hit_right) {
                if (t_right < t_left) {
                    uint32_t tmp = left;
                    left = right;
                    right = tmp;
                    float tmp_t = t_left;
                    t_left = t_right;
                    t_right = tmp_t;
                }
                stack_t[sp] = t_right;
                stack[sp++] = right;
                node_index = left;
                continue;
            }
            if (hit_left) {
                node_index = left;
                continue;
            }
            if (hit_right) {
                node_index = right;
                continue;
            }
        }
        do {
            if (sp == 0)
                return found;
            --sp;
        } while (stack_t[sp] > box_limit);
        node_index = stack[sp];
    }
}

int trace_scene_closest(const struct trace_scene *scene, const float org[3], const float dir[3],
                        float tmin, float tmax, struct trace_scene_hit *hit,
                        struct trace_scene_counters *counters)
{
    counters->rays++;
    return walk(scene, org, dir, tmin, tmax, 0, hit, counters);
}

int trace_scene_any(const struct trace_scene *scene, const float org[3], const float dir[3],
                    float tmin, float tmax, struct trace_scene_counters *counters)
{
    counters->rays++;
    return walk(scene, org, dir, tmin, tmax, 1, NULL, counters);
}
