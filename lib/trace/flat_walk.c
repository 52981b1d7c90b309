/* SPDX-License-Identifier: Apache-2.0 */
/*
 * flat_walk.c - the walk of a flattened nested hierarchy (flat_walk.h).
 */
#include "trace/flat_walk.h"

#include <math.h>
#include <stddef.h>

#include "trace/intersect.h"

/* One leaf slot; returns 1 when an any-hit walk has its hit.  *cached is
 * the member whose object-space ray o_ray holds (UINT32_MAX: none yet);
 * *usable whether that ray can be traced. */
static int test_slot(const struct trace_flat *flat, const struct trace_instance *instances,
                     const struct trace_instance *group, struct trace_flat_ray *r,
                     uint32_t slot, uint32_t *cached, int *usable, struct trace_ray *o_ray,
                     struct trace_scene_counters *counters)
{
    const uint32_t member = flat->member[slot];
    const struct trace_instance *mi = &instances[group->member_base + member];
    if (member != *cached) {
        /* The instance path's transformation of the world ray, bit for
         * bit (trace_scene_object_ray): its t, u, v follow. */
        *cached = member;
        counters->instance_tests++;
        *usable = trace_scene_object_ray(mi, r->org, r->dir, r->tmin, r->world, o_ray);
    }
    if (!*usable)
        return 0;
    const float *v = &flat->tri[9 * (size_t)slot];
    float t, u, w;
    counters->object.triangle_tests++;
    const float limit = *r->found ? isect_next_up(*r->best) : *r->best;
    if (!isect_triangle(o_ray, v, v + 3, v + 6, limit, &t, &u, &w))
        return 0;
    const uint32_t prim = flat->prim[slot];
    struct trace_scene_hit *hit = r->hit;
    if (hit && *r->found && !(t < *r->best)) {
        /* t equals the best (limit is one ulp above it): the lower
         * instance id, then the lower primitive wins, as in the instance
         * path (lexicographic (t, instance, primitive)). */
        const uint32_t best_id = instances[hit->instance].instance_id;
        if (!(mi->instance_id < best_id || (mi->instance_id == best_id && prim < hit->prim)))
            return 0;
    }
    /* The scene's hit filter, for the members it marks (scene_traverse.h). */
    const struct trace_scene *f = r->filter;
    if (f && (f->filtered[mi->instance_id] & f->filter_mask)) {
        const struct trace_scene_hit cand = {t, u, w, prim, group->member_base + member};
        if (!f->accept(f->accept_user, r->org, r->dir, &cand))
            return 0;
    }
    if (!hit) {
        *r->found = 1;
        return 1;
    }
    *r->found = 1;
    *r->best = t;
    *r->box_limit = t * ISECT_BOX_FAR_SCALE;
    hit->t = t;
    hit->u = u;
    hit->v = w;
    hit->prim = prim;
    hit->instance = group->member_base + member;
    return 0;
}

int trace_flat_walk(const struct trace_flat *flat, const struct trace_instance *instances,
                    const struct trace_instance *group, struct trace_flat_ray *r,
                    struct trace_scene_counters *counters)
{
    const struct bvh *bvh = flat->bvh;
    if (!bvh || bvh->node_count == 0)
        return 0;
    /* The ray in the root's space, for the boxes only. */
    struct trace_ray g_ray;
    if (!trace_scene_object_ray(group, r->org, r->dir, r->tmin, r->world, &g_ray))
        return 0;
    struct isect_box_ray br;
    isect_box_ray_init(&br, &g_ray);
    struct {
        uint32_t node;
        float t_entry;
    } stack[BVH_MAX_DEPTH + 1];
    uint32_t sp = 0, current = 0, cached = UINT32_MAX;
    int usable = 0;
    struct trace_ray o_ray;
    float t_entry;
    counters->object.node_tests++;
    if (!isect_box(&br, &bvh->nodes[0], *r->box_limit, &t_entry))
        return 0;
    for (;;) {
        const struct bvh_node *node = &bvh->nodes[current];
        if (node->count) {
            for (uint32_t s = node->first; s < node->first + node->count; s++)
                if (test_slot(flat, instances, group, r, s, &cached, &usable, &o_ray,
                              counters))
                    return 1;
        } else {
            const uint32_t left = node->first, right = left + 1;
            float t_left, t_right;
            counters->object.node_tests += 2;
#if ISECT_PAIR_SSE
            /* Both siblings in one SSE test, as the object walk does
             * (traverse_walk.h); the same entries as isect_box. */
            float t_pair[2];
            const unsigned mask = isect_box_pair(&br, &bvh->nodes[left], *r->box_limit, t_pair);
            const int hit_left = mask & 1u, hit_right = mask >> 1;
            t_left = t_pair[0];
            t_right = t_pair[1];
#else
            const int hit_left = isect_box(&br, &bvh->nodes[left], *r->box_limit, &t_left);
            const int hit_right = isect_box(&br, &bvh->nodes[right], *r->box_limit, &t_right);
#endif
            if (hit_left && hit_right) {
                const int right_first = t_right < t_left;
                stack[sp].node = right_first ? left : right;
                stack[sp].t_entry = right_first ? t_left : t_right;
                sp++;
                current = right_first ? right : left;
                continue;
            }
            if (hit_left || hit_right) {
                current = hit_left ? left : right;
                continue;
            }
        }
        for (;;) {
            if (sp == 0)
                return 0;
            sp--;
            if (stack[sp].t_entry <= *r->box_limit)
                break;
        }
        current = stack[sp].node;
    }
}
