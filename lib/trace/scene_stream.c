/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene_stream.c - the two-level walk for a batch of rays (see
 * scene_stream.h).
 *
 * Why it gives the single-ray walk's answers: for a top level of one
 * leaf and a ray of trace_scene_plain_class's exact class with
 * tmin < tmax, scene_traverse.c's walk visits the leaf's instances in
 * the leaf's order, each with the limit of the hits found so far (tmax,
 * or isect_next_up(best) once a hit is found, and keep_hit's rule: the
 * earlier t, the lower instance id on equal t), an any-hit ray stopping
 * at its first hit.  Here the instances are taken in the same order, one
 * after the other over the whole batch, each ray with the limit the
 * single walk would pass at that instance, and the same rule.  The
 * object walk of a ray is the stream's, which gives walk1's answer and
 * counts for the ray's origin, direction, tmin and limit (kernels.h);
 * those are the world ray's floats where visit_instance hands the world
 * ray on (the instance the identity and the ray plain), else
 * trace_scene_object_ray's transformed floats, and a set-up depends on
 * them alone (trace_ray_init_single and trace_ray_init give the same
 * ray, ray.c).  walk1 from a ray's floats is closest4/any4 on its
 * set-up, the walks visit_instance takes.  No ray reads another's state:
 * only the order in which the rays run changes, which the counters'
 * sums do not see.
 */
#include "trace/scene_stream.h"

#include <string.h>

#include "trace/intersect.h"

/* Rays per stream call: the stream's slots drain at the end of a call
 * (its last rays walk with fewer in flight), so the more rays a call the
 * less that tail weighs; 256 keeps the scratch below (about 23 KB) and
 * the stream's slots (eight, about 6 KB each: traverse_pair8.h) within
 * 72 KB of the caller's stack.  The library's callers are the query
 * workers (render.c): the pool's threads (base/pool.c creates them with
 * the default attributes: under glibc a stack of the process's stack
 * limit, RLIMIT_STACK, usually 8 MB, or 2 MB where it is unlimited;
 * 128 KB under musl, where this and the walk's frames still fit) and
 * the application's calling thread, whose stack the application sizes
 * (a frame's tiles already take the single walks' stacks, 5-6 KB each,
 * and the shading's buffers on the same threads). */
enum { STREAM_BATCH = 256 };
/* The instances of the one leaf taken through the stream; a larger leaf
 * goes ray by ray (the top-level builder's leaves hold a few). */
enum { STREAM_INSTANCES = 8 };

struct stream_object {
    const struct trace_instance *inst;
    uint32_t slot; /* in scene->instances */
    struct trace_object_view view;
    trace_stream1_counted_fn walk;
};

/* The leaf's instances when the scene qualifies (scene_stream.h), with
 * their views and streams; 0 when it does not. */
static uint32_t stream_objects(const struct trace_scene *scene, int any_hit,
                               struct stream_object *obj)
{
    const struct trace_kernels *k = scene->kernels;
    const struct bvh *top = scene->top;
    if (!k || !k->stream_counted || !k->closest4 || !top || !top->node_count)
        return 0;
    const struct bvh_node *root = &top->nodes[0];
    if (!root->count || root->count > STREAM_INSTANCES)
        return 0;
    for (uint32_t i = 0; i < root->count; i++) {
        struct stream_object *o = &obj[i];
        o->slot = top->prim_index[root->first + i];
        o->inst = &scene->instances[o->slot];
        if (o->inst->member_count)
            return 0;
        if (scene->filtered && (scene->filtered[o->inst->instance_id] & scene->filter_mask))
            return 0;
        memset(&o->view, 0, sizeof(o->view));
        /* An object that cannot be had goes ray by ray, where each ray
         * skips it as the single walk does. */
        if (!scene->acquire(scene->user, o->inst->object, &o->view))
            return 0;
        const struct bvh4 *w = o->view.wide;
        if (!w || w->width != 8 || !w->node_count)
            return 0;
        if (!scene->stream_always && !w->stream_pays)
            return 0;
        o->walk = k->stream_counted(w, any_hit);
        if (!o->walk)
            return 0;
    }
    return root->count;
}

/* The per-batch state: the rays taken through the stream (their index
 * in the caller's arrays, plain class, best t and hit so far) and one
 * instance's stream input and output. */
struct stream_scratch {
    uint32_t ray[STREAM_BATCH];
    unsigned plain[STREAM_BATCH];
    float best[STREAM_BATCH];
    unsigned char found[STREAM_BATCH];
    struct trace_scene_hit hit[STREAM_BATCH];
    float in[8 * STREAM_BATCH];
    uint32_t map[STREAM_BATCH];
    struct trace_hit th[STREAM_BATCH];
    unsigned char got[STREAM_BATCH];
    uint32_t nodes[STREAM_BATCH];
};

/* One instance over the batch's rays still walking: each ray's input as
 * visit_instance makes it, the stream, the view's ray count, and
 * keep_hit's rule (closest hit) or the end of the ray (any hit). */
static void stream_instance(const struct trace_scene *scene, const struct stream_object *o,
                            const float *rays, size_t stride, uint32_t m, int any_hit,
                            struct stream_scratch *sc, struct trace_scene_counters *counters)
{
    const struct trace_instance *inst = o->inst;
    uint32_t live = 0;
    for (uint32_t e = 0; e < m; e++) {
        if (any_hit && sc->found[e])
            continue;
        const float *r = rays + (size_t)sc->ray[e] * stride;
        counters->instance_tests++;
        float *in = &sc->in[8 * (size_t)live];
        if (inst->identity & sc->plain[e]) {
            /* visit_instance's handed_on: the world ray. */
            memcpy(in, r, 3 * sizeof(float));
            memcpy(in + 4, r + 4, 3 * sizeof(float));
        } else if (!trace_scene_object_inputs(inst, r, r + 4, in, in + 4)) {
            continue; /* the instance is skipped for this ray */
        }
        in[3] = r[3];
        /* The tie rule is keep_hit's (visit_instance's limit); an
         * any-hit ray's limit stays tmax. */
        in[7] = !any_hit && sc->found[e] ? isect_next_up(sc->best[e]) : sc->best[e];
        sc->map[live++] = e;
    }
    if (!live)
        return;
    o->walk(o->view.wide, sc->in, 8, live, any_hit ? NULL : sc->th, sc->got, &counters->object,
            sc->nodes);
    if (o->view.ray_count) {
        /* trace_scene_count_rays' rule ray by ray: a ray reaches inside
         * when it tests more boxes than the root's eight. */
        uint32_t reached = 0;
        for (uint32_t l = 0; l < live; l++)
            reached += sc->nodes[l] > o->view.wide->width;
        if (reached)
            trace_scene_add_ray_count(counters, o->view.ray_count, reached);
    }
    for (uint32_t l = 0; l < live; l++) {
        if (!sc->got[l])
            continue;
        const uint32_t e = sc->map[l];
        if (any_hit) {
            sc->found[e] = 1;
            continue;
        }
        const struct trace_hit *h = &sc->th[l];
        struct trace_scene_hit *hit = &sc->hit[e];
        if (!sc->found[e] || trace_scene_hit_replaces(scene, inst, h->t, sc->best[e], hit)) {
            sc->best[e] = h->t;
            sc->found[e] = 1;
            hit->t = h->t;
            hit->u = h->u;
            hit->v = h->v;
            hit->prim = h->prim;
            hit->instance = o->slot;
        }
    }
}

static void batch(const struct trace_scene *scene, const float *rays, size_t stride,
                  uint32_t count, int any_hit, struct trace_scene_hit *hits, unsigned char *got,
                  struct trace_scene_counters *counters)
{
    struct stream_object obj[STREAM_INSTANCES];
    /* The scene's qualification, made when the first ray that reaches
     * the leaf at once comes (trace_scene_stream_ready says why). */
    int known = 0;
    uint32_t objects = 0;
    struct stream_scratch sc;
    for (uint32_t base = 0; base < count; base += STREAM_BATCH) {
        const uint32_t n = count - base < STREAM_BATCH ? count - base : STREAM_BATCH;
        uint32_t m = 0;
        for (uint32_t j = 0; j < n; j++) {
            const uint32_t i = base + j;
            const float *r = rays + (size_t)i * stride;
            const unsigned plain = trace_scene_plain_class(r, r + 4);
            if (r[3] < r[7] && (plain & TRACE_IDENTITY_EXACT)) {
                if (!known) {
                    objects = stream_objects(scene, any_hit, obj);
                    known = 1;
                }
                if (objects) {
                    counters->rays++;
                    sc.ray[m] = i;
                    sc.plain[m] = plain;
                    sc.best[m] = r[7];
                    sc.found[m] = 0;
                    m++;
                    continue;
                }
            }
            /* The single walk: the scene does not qualify, or the ray
             * takes its other paths (scene_stream.h). */
            got[i] = (unsigned char)(any_hit ? trace_scene_any(scene, r, r + 4, r[3], r[7],
                                                               counters)
                                             : trace_scene_closest(scene, r, r + 4, r[3], r[7],
                                                                   &hits[i], counters));
        }
        for (uint32_t k = 0; k < objects && m; k++)
            stream_instance(scene, &obj[k], rays, stride, m, any_hit, &sc, counters);
        for (uint32_t e = 0; e < m; e++) {
            got[sc.ray[e]] = sc.found[e];
            if (!any_hit && sc.found[e])
                hits[sc.ray[e]] = sc.hit[e];
        }
    }
}

int trace_scene_stream_ready(const struct trace_scene *scene, int any_hit)
{
    struct stream_object obj[STREAM_INSTANCES];
    return stream_objects(scene, any_hit, obj) != 0;
}

void trace_scene_closest_batch(const struct trace_scene *scene, const float *rays, size_t stride,
                               uint32_t count, struct trace_scene_hit *hits, unsigned char *found,
                               struct trace_scene_counters *counters)
{
    batch(scene, rays, stride, count, 0, hits, found, counters);
}

void trace_scene_any_batch(const struct trace_scene *scene, const float *rays, size_t stride,
                           uint32_t count, unsigned char *occluded,
                           struct trace_scene_counters *counters)
{
    batch(scene, rays, stride, count, 1, NULL, occluded, counters);
}
