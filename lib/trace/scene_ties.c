/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene_ties.c - the hits at one distance, in draw order (scene_ties.h).
 *
 * A plain depth-first walk of the binary top level and of each object's
 * binary BVH with the ray's interval shrunk to the single value t: a box
 * is entered when trace_box accepts [t, t], a triangle kept when
 * trace_triangle finds it with t <= t' < next float above t, i.e. at t.
 * These are the tests the closest-hit walk makes (trace.h: every kernel
 * gives trace_triangle's answer), so the set of triangles at t is the
 * same for both.  No order of visits is needed: the hits are appended
 * and sorted by (instance, prim) once at the end (n log n for thousands
 * of coincident triangles); only when more than `max` come are they
 * sorted early and the max smallest kept by insertion.
 */
#include "trace/scene_ties.h"

#include <math.h>
#include <stdlib.h>

#include "trace/binary_walk.h"

/* The hits kept so far: out[0 .. n), sorted when `sorted`; total counts
 * every candidate. */
struct tie_set {
    struct trace_scene_hit *out;
    int n, max, sorted, total;
};

static int compare_hits(const void *pa, const void *pb)
{
    const struct trace_scene_hit *a = pa, *b = pb;
    if (a->instance != b->instance)
        return a->instance < b->instance ? -1 : 1;
    return a->prim < b->prim ? -1 : a->prim > b->prim;
}

static void sort_set(struct tie_set *s)
{
    if (!s->sorted)
        qsort(s->out, (size_t)s->n, sizeof(*s->out), compare_hits);
    s->sorted = 1;
}

/* One candidate: appended while there is room, else (sorted first) the
 * sorted insertion keeping the max smallest keys.  The keys are unique
 * (a triangle is found once), so the result does not depend on the
 * order of arrival. */
static void keep(struct tie_set *s, const struct trace_scene_hit *h)
{
    s->total++;
    if (s->n < s->max && !s->sorted) {
        s->out[s->n++] = *h;
        return;
    }
    sort_set(s);
    struct trace_scene_hit *out = s->out;
    int *n = &s->n;
    const int max = s->max;
    int i = *n;
    if (i == max) {
        const struct trace_scene_hit *last = &out[max - 1];
        if (h->instance > last->instance ||
            (h->instance == last->instance && h->prim >= last->prim))
            return;
        i--;
    } else {
        (*n)++;
    }
    while (i > 0 && (out[i - 1].instance > h->instance ||
                     (out[i - 1].instance == h->instance && out[i - 1].prim > h->prim))) {
        out[i] = out[i - 1];
        i--;
    }
    out[i] = *h;
}

/* Every triangle of one object the ray meets at exactly t. */
static void object_ties(const struct trace_object_view *view, const struct trace_ray *o_ray,
                        float t, uint32_t index, const struct trace_scene_hit *after,
                        struct tie_set *set, struct trace_scene_counters *counters)
{
    const struct bvh *bvh = view->bvh;
    if (!bvh || bvh->node_count == 0)
        return;
    const float limit = nextafterf(t, INFINITY);
    struct trace_binary_walk walk;
    trace_binary_walk_init(&walk, bvh);
    const struct bvh_node *leaf;
    while ((leaf = trace_binary_walk_next(&walk, o_ray, t, &counters->object.node_tests))) {
        for (uint32_t i = 0; i < leaf->count; i++) {
            const uint32_t slot = leaf->first + i;
            const float *v = &view->tri[9 * (size_t)slot];
            struct trace_scene_hit h;
            counters->object.triangle_tests++;
            if (!trace_triangle(o_ray, v, v + 3, v + 6, limit, &h.t, &h.u, &h.v) || h.t != t)
                continue;
            h.prim = bvh->prim_index[slot];
            h.instance = index;
            if (index == after->instance && h.prim <= after->prim)
                continue;
            keep(set, &h);
        }
    }
}

int trace_scene_ties(const struct trace_scene *scene, const float org[3], const float dir[3],
                     const struct trace_scene_hit *after, struct trace_scene_hit *out, int max,
                     int *total, struct trace_scene_counters *counters)
{
    const struct bvh *top = scene->top;
    const float t = after->t;
    if (total)
        *total = 0;
    if (max <= 0 || !top || top->node_count == 0 || !isfinite(t))
        return 0;
    struct trace_ray world;
    trace_ray_init(&world, org, dir, t);
    struct tie_set set = {out, 0, max, 0, 0};
    struct trace_binary_walk walk;
    trace_binary_walk_init(&walk, top);
    const struct bvh_node *leaf;
    while ((leaf = trace_binary_walk_next(&walk, &world, t, &counters->top_node_tests))) {
        for (uint32_t i = 0; i < leaf->count; i++) {
            const uint32_t index = top->prim_index[leaf->first + i];
            /* Instances before the one of `after` hold nothing after it. */
            if (index < after->instance)
                continue;
            const struct trace_instance *inst = &scene->instances[index];
            struct trace_object_view view = {NULL, NULL, NULL, NULL};
            struct trace_ray o_ray;
            counters->instance_tests++;
            if (!scene->acquire(scene->user, inst->object, &view) ||
                !trace_scene_object_ray(inst, org, dir, t, &world, &o_ray))
                continue;
            object_ties(&view, &o_ray, t, index, after, &set, counters);
        }
    }
    sort_set(&set);
    if (total)
        *total = set.total;
    return set.n;
}
