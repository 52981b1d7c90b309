/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene_traverse.c - two-level traversal (see scene_traverse.h).
 */
#include "trace/scene_traverse.h"

#include "base/atomic.h"
#include "trace/flat_walk.h"
#include "trace/intersect.h"
#include "trace/scene_filter.h"

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

void trace_instance_set_rows(struct trace_instance *inst, const double world_to_object[16])
{
    /* The exact kind bit for bit: a -0.0 in the rows can keep a -0.0
     * that the +0.0 rows turn into +0.0 (trace_scene_plain_class). */
    static const double one = 1.0, zero = 0.0;
    int identity = 1, exact = 1;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 4; c++) {
            const double v = world_to_object[4 * c + r];
            inst->world_to_object[4 * r + c] = v;
            identity &= v == (r == c ? 1.0 : 0.0);
            exact &= memcmp(&v, r == c ? &one : &zero, sizeof(v)) == 0;
        }
    inst->identity = exact ? TRACE_IDENTITY_EXACT : identity ? TRACE_IDENTITY_ZEROS : 0u;
}

int trace_scene_object_ray(const struct trace_instance *inst, const float org[3],
                           const float dir[3], float tmin, const struct trace_ray *world,
                           struct trace_ray *o_ray)
{
    /* The identity's rows give back the origin and direction of the
     * classes trace_scene_plain_class names bit for bit, and such a
     * direction is usable.  So the ray is the world ray, set up, as the
     * comparison below would find it, without the twelve products.  A
     * zero whose sign the sum may change or an infinity (0 * inf is a
     * NaN) takes the general path. */
    if (inst->identity && (inst->identity & trace_scene_plain_class(org, dir))) {
        *o_ray = *world;
        return 1;
    }
    float o_org[3], o_dir[3];
    if (!trace_scene_object_inputs(inst, org, dir, o_org, o_dir))
        return 0;
    /* An instance whose matrix leaves the ray as it is (the identity, as
     * for a scene of one static object) reuses the world ray's set-up:
     * trace_ray_init depends on org, dir and tmin alone, so that is the
     * same ray bit for bit, without its five divisions. */
    if (memcmp(o_org, org, sizeof(o_org)) == 0 && memcmp(o_dir, dir, sizeof(o_dir)) == 0)
        *o_ray = *world;
    else
        trace_ray_init(o_ray, o_org, o_dir, tmin);
    return 1;
}

int trace_scene_object_inputs(const struct trace_instance *inst, const float org[3],
                              const float dir[3], float o_org[3], float o_dir[3])
{
    to_object_space(inst->world_to_object, org, dir, o_org, o_dir);
    return usable_direction(o_dir);
}

void trace_scene_flush_ray_count(struct trace_scene_counters *counters)
{
    if (counters->ray_count && counters->ray_count_pending)
        rt_atomic_add_fetch_relaxed(counters->ray_count, counters->ray_count_pending);
    counters->ray_count_pending = 0;
}

void trace_scene_count_rays(struct trace_scene_counters *counters, uint64_t *target,
                            uint64_t tests_before, uint32_t root_tests, uint32_t rays)
{
    if (counters->object.node_tests - tests_before <= (uint64_t)root_tests * rays)
        return;
    trace_scene_add_ray_count(counters, target, rays);
}

void trace_scene_add_ray_count(struct trace_scene_counters *counters, uint64_t *target,
                               uint32_t rays)
{
    if (counters->ray_count != target) {
        trace_scene_flush_ray_count(counters);
        counters->ray_count = target;
    }
    counters->ray_count_pending += rays;
}

/* The per-ray state both top-level walks share. */
struct top_state {
    const struct trace_scene *scene;
    const struct trace_kernels *kernels;
    const float *org;
    const float *dir;
    float tmin;
    struct trace_ray ray; /* the world ray's set-up, once ray_ready */
    int ray_ready;
    int any_hit;
    struct trace_scene_hit *hit;
    struct trace_scene_counters *counters;
    float best;
    float box_limit; /* as in traverse.c: widened once a hit is found */
    int found;
    unsigned plain; /* trace_scene_plain_class of org and dir */
};

/* The world ray's set-up, made when first needed: a top level of one
 * leaf over identity instances never needs it (walk). */
static void world_ray(struct top_state *s)
{
    if (!s->ray_ready) {
        /* A single ray: the set-up without branches (ray.c). */
        trace_ray_init_single(&s->ray, s->org, s->dir, s->tmin);
        s->ray_ready = 1;
    }
}

/* A flattened hierarchy in slot `index` (flat_walk.h): the same answers
 * as its members visited as instances. */
static int visit_group(struct top_state *s, const struct trace_instance *group)
{
    const struct trace_scene *scene = s->scene;
    world_ray(s);
    struct trace_flat flat;
    s->counters->instance_tests++;
    if (!scene->acquire_flat || !scene->acquire_flat(scene->user, group->object, &flat))
        return 0;
    struct trace_flat_ray r = {s->org, s->dir, s->tmin, &s->ray, &s->best, &s->box_limit,
                               &s->found, s->any_hit ? NULL : s->hit,
                               scene->filtered ? scene : NULL};
    return trace_flat_walk(&flat, scene->instances, group, &r, s->counters);
}

/* Keeps an instance's closest hit h (slot `index`) when it comes before
 * the best so far.  Ties between instances go to the lower instance, as
 * ties inside an object go to the lower primitive: hits do not depend on
 * the top-level tree nor on the order of visits (an instance's hit at the
 * current best still comes back, with the limit one ulp above it, and
 * then the lower index wins).  The index compared is the instance id (the
 * order of the committed list), which slots follow except for a
 * flattened hierarchy's members (flat_walk.h). */
static void keep_hit(struct top_state *s, uint32_t index, const struct trace_hit *h)
{
    const struct trace_instance *inst = &s->scene->instances[index];
    struct trace_scene_hit *hit = s->hit;
    if (!s->found || trace_scene_hit_replaces(s->scene, inst, h->t, s->best, hit)) {
        s->best = h->t;
        s->box_limit = s->best * ISECT_BOX_FAR_SCALE;
        s->found = 1;
        hit->t = h->t;
        hit->u = h->u;
        hit->v = h->v;
        hit->prim = h->prim;
        hit->instance = index;
    }
}

/*
 * The hit filter's part of an instance it marks (trace_scene.filtered),
 * after the kernel's closest-hit walk found h (for an any-hit walk too):
 * the kernel's closest hit, when accepted, is the closest accepted (the
 * same triangle test, the same tie rule, scene_filter.h), and an
 * accepted hit ends an any-hit walk; else the triangles one by one.  So a
 * marked instance costs the kernel's walk alone for the rays that miss it
 * or whose nearest hit stays.
 */
static int filter_hits(struct top_state *s, uint32_t index, const struct trace_object_view *view,
                       const struct trace_ray *o_ray, float limit, struct trace_hit *h)
{
    const struct trace_scene *scene = s->scene;
    const struct trace_scene_hit cand = {h->t, h->u, h->v, h->prim, index};
    if (scene->accept(scene->accept_user, s->org, s->dir, &cand))
        return 1;
    const struct trace_filter_ray fr = {scene, s->org, s->dir, index, s->any_hit};
    return trace_filter_object(view, o_ray, limit, &fr, h, &s->counters->object);
}

/* The instance in slot `index` of scene->instances.  Returns 1 when an
 * any-hit walk has its hit. */
static int visit_instance(struct top_state *s, uint32_t index)
{
    const struct trace_scene *scene = s->scene;
    if (scene->instances[index].member_count)
        return visit_group(s, &scene->instances[index]);
    const struct trace_kernels *kernels = s->kernels;
    struct trace_scene_counters *counters = s->counters;
    const struct trace_instance *inst = &scene->instances[index];
    struct trace_object_view view = {NULL, NULL, NULL, NULL};
    counters->instance_tests++;
    if (!scene->acquire(scene->user, inst->object, &view))
        return 0;
    /* The object's ray: the world ray itself where the instance is the
     * identity and the ray is plain (what trace_scene_object_ray would
     * copy), without the copy. */
    struct trace_ray o_copy;
    const struct trace_ray *o_ray = &s->ray;
    const int handed_on = (inst->identity & s->plain) != 0;
    if (!handed_on) {
        world_ray(s);
        if (!trace_scene_object_ray(inst, s->org, s->dir, s->tmin, &s->ray, &o_copy))
            return 0;
        o_ray = &o_copy;
    }
    /* An instance the scene's hit filter applies to (filter_hits); a
     * frame without one pays this test only. */
    const int filtered =
        scene->filtered && (scene->filtered[inst->instance_id] & scene->filter_mask);
    /* The wide walk where the table has one and the object a wide
     * layout: the same answers (kernels.h). */
    const int wide = view.wide && view.wide->node_count && kernels->closest4;
    /* The world ray handed on before anything set it up (a top level of
     * one leaf, walk): the table's single-ray entries set it up inside
     * the object's walk, the same ray bit for bit (kernels.h). */
    const int direct = handed_on && !s->ray_ready && wide && kernels->closest1 && !filtered;
    if (!direct)
        world_ray(s);
    /* On an 8-wide layout the walk those entries would choose, taken
     * from the table by the layout's fields (kernels.h, walk1_counted):
     * the same walk without the entry's tests of what is known here. */
    const trace_walk1_fn walk1 =
        direct && kernels->walk1_counted && view.wide->width == 8
            ? kernels->walk1_counted[2 * (s->any_hit != 0) +
                                     ((s->any_hit ? view.wide->any_longest
                                                  : view.wide->prefetch_top) != 0)]
            : NULL;
    /* A ray reaches inside the object when its walk tests more boxes than
     * the root's (the root box for the binary walk, the root's children
     * for a wide one). */
    const uint64_t tests_before = counters->object.node_tests;
    if (s->any_hit && !filtered) {
        int got = walk1 ? walk1(view.wide, s->org, s->dir, s->tmin, s->best, NULL,
                                &counters->object)
                  : direct ? kernels->any1(view.wide, view.bvh, view.tri, s->org, s->dir, s->tmin,
                                           s->best, &counters->object)
                  : wide ? kernels->any4(view.wide, view.bvh, view.tri, o_ray, s->best,
                                         &counters->object)
                         : kernels->any(view.bvh, view.tri, o_ray, s->best, &counters->object);
        if (view.ray_count)
            trace_scene_count_rays(counters, view.ray_count, tests_before,
                                   wide ? view.wide->width : 1, 1);
        return got;
    }
    /* The tie rule is keep_hit's. */
    float limit = s->found ? isect_next_up(s->best) : s->best;
    struct trace_hit h;
    int got = walk1 ? walk1(view.wide, s->org, s->dir, s->tmin, limit, &h, &counters->object)
              : direct ? kernels->closest1(view.wide, view.bvh, view.tri, s->org, s->dir, s->tmin,
                                           limit, &h, &counters->object)
              : wide ? kernels->closest4(view.wide, view.bvh, view.tri, o_ray, limit, &h,
                                         &counters->object)
                     : kernels->closest(view.bvh, view.tri, o_ray, limit, &h, &counters->object);
    if (view.ray_count)
        trace_scene_count_rays(counters, view.ray_count, tests_before,
                                   wide ? view.wide->width : 1, 1);
    if (got && filtered)
        got = filter_hits(s, index, &view, o_ray, limit, &h);
    if (s->any_hit)
        return got;
    if (got)
        keep_hit(s, index, &h);
    return 0;
}

/* The binary top-level walk.  With any_hit the first hit ends it. */
static int walk_binary(struct top_state *s)
{
    const struct bvh *top = s->scene->top;
    struct trace_scene_counters *counters = s->counters;
    /* One set-up per ray: the box test's, which every top-level box test
     * below shares. */
    struct isect_box_ray br;
    isect_box_ray_init(&br, &s->ray);
    /* Deferred far children with their entry distances: a popped subtree
     * that starts beyond the closest hit so far is skipped. */
    uint32_t stack[BVH_MAX_DEPTH + 1];
    float stack_t[BVH_MAX_DEPTH + 1];
    int sp = 0;
    uint32_t node_index = 0;
    float t_entry;
    counters->top_node_tests++;
    if (!isect_box(&br, &top->nodes[0], s->best, &t_entry))
        return 0;
    for (;;) {
        const struct bvh_node *node = &top->nodes[node_index];
        if (node->count) {
            for (uint32_t i = 0; i < node->count; i++)
                if (visit_instance(s, top->prim_index[node->first + i]))
                    return 1;
        } else {
            /* Visit the nearer child first; push the farther one. */
            uint32_t left = node->first, right = node->first + 1;
            float t_left, t_right;
            counters->top_node_tests += 2;
            int hit_left = isect_box(&br, &top->nodes[left], s->box_limit, &t_left);
            int hit_right = isect_box(&br, &top->nodes[right], s->box_limit, &t_right);
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
                return s->found;
            --sp;
        } while (stack_t[sp] > s->box_limit);
        node_index = stack[sp];
    }
}

/*
 * The lanes of a wide node (bounds[row * width + lane], bvh4_layout.h)
 * whose boxes the ray's [tmin, t_max] meets, as a bit mask, with their
 * entry distances.  isect_box's float operations lane by lane (the
 * argument of traverse_wide.h): the same (bound - org) * inv per slab
 * and near/far choice, the entry folded with `>` and the exit with `<`
 * so that a NaN slab is skipped (maxps/minps return their second operand
 * for a NaN first one, which is the same rule), the far scale, the clamp
 * to t_max.  The lanes are binary nodes' boxes bit for bit.
 */
unsigned trace_scene_wide_lanes(const float *bounds, uint32_t width, const int near_row[3],
                                const int far_row[3], const struct trace_ray *ray, float t_max,
                                float t_entry[8])
{
    unsigned mask = 0;
#if ISECT_PAIR_SSE
    const __m128 scale4 = _mm_set1_ps(ISECT_BOX_FAR_SCALE);
    const __m128 limit4 = _mm_set1_ps(t_max);
    for (uint32_t h = 0; h < width; h += 4) {
        __m128 t0 = _mm_set1_ps(ray->tmin);
        __m128 t1 = _mm_set1_ps(INFINITY);
        for (int k = 0; k < 3; k++) {
            const __m128 o = _mm_set1_ps(ray->org[k]);
            const __m128 inv = _mm_set1_ps(ray->inv_dir[k]);
            const __m128 tn =
                _mm_mul_ps(_mm_sub_ps(_mm_load_ps(bounds + near_row[k] * width + h), o), inv);
            const __m128 tf =
                _mm_mul_ps(_mm_sub_ps(_mm_load_ps(bounds + far_row[k] * width + h), o), inv);
            t0 = _mm_max_ps(tn, t0);
            t1 = _mm_min_ps(tf, t1);
        }
        t1 = _mm_min_ps(_mm_mul_ps(t1, scale4), limit4);
        mask |= (unsigned)_mm_movemask_ps(_mm_cmple_ps(t0, t1)) << h;
        _mm_storeu_ps(t_entry + h, t0);
    }
#else
    for (uint32_t l = 0; l < width; l++) {
        float t0 = ray->tmin;
        float t_far_min = INFINITY;
        for (int k = 0; k < 3; k++) {
            float t_near = (bounds[near_row[k] * width + l] - ray->org[k]) * ray->inv_dir[k];
            float t_far = (bounds[far_row[k] * width + l] - ray->org[k]) * ray->inv_dir[k];
            t0 = t_near > t0 ? t_near : t0;
            t_far_min = t_far < t_far_min ? t_far : t_far_min;
        }
        float t1 = t_far_min * ISECT_BOX_FAR_SCALE;
        t1 = t1 < t_max ? t1 : t_max;
        t_entry[l] = t0;
        mask |= (unsigned)(t0 <= t1) << l;
    }
#endif
    return mask;
}

/*
 * The wide top-level walk over scene->top_wide (4 or 8 wide, range
 * leaves of instance slots): the object walk's child order (the node's
 * precomputed order for the ray's octant, Fuetterling, Lojewski,
 * Pfreundt and Ebert 2017) and entry-distance culling on pop.  The same
 * answers as walk_binary: every box holding a hit at or below the best
 * so far passes (the lanes are boxes of the binary tree, tested as
 * isect_box tests them), and visit_instance's rule does not depend on
 * the order of visits.
 */
static int walk_wide(struct top_state *s, const struct bvh4 *wide)
{
    const struct bvh *top = s->scene->top;
    struct trace_scene_counters *counters = s->counters;
    const struct trace_ray *ray = &s->ray;
    const uint32_t width = wide->width;
    int near_row[3], far_row[3];
    const int octant = trace_scene_box_rows(ray, near_row, far_row);
    struct {
        uint32_t child;
        uint32_t count; /* 0: wide node, else a leaf of `count` slots */
        float t_entry;
    } stack[7 * BVH_MAX_DEPTH + 8];
    uint32_t sp = 0;
    uint32_t cur = 0, cur_count = 0;
    for (;;) {
        if (cur_count) {
            for (uint32_t i = 0; i < cur_count; i++)
                if (visit_instance(s, top->prim_index[cur + i]))
                    return 1;
        } else {
            const float *bounds;
            const uint32_t *child;
            const uint8_t *count;
            uint32_t order;
            order = trace_scene_wide_node(wide, width, cur, octant, &bounds, &child, &count);
            counters->top_node_tests += width;
            float te[8];
            const unsigned mask =
                s->kernels->top_lanes1(bounds, width, near_row, far_row, ray, s->box_limit, te);
            if (mask && !(mask & (mask - 1u))) {
                /* One lane entered (most nodes of a top level over a few
                 * instances): it is the front one, which the push and pop
                 * below would take at once, so it is taken without them
                 * (the octant's order over eight positions was about 70
                 * instructions a ray). */
                const unsigned l = (unsigned)__builtin_ctz(mask);
                cur = child[l];
                cur_count = count[l];
                continue;
            }
            if (mask) {
                /* Push the hit lanes back to front in the octant's order
                 * (3 bits per position here), then take the front one. */
                for (int p = (int)width - 1; p >= 0; p--) {
                    const unsigned l = order >> (3 * p) & 7u;
                    if (!(mask >> l & 1u))
                        continue;
                    stack[sp].child = child[l];
                    stack[sp].count = count[l];
                    stack[sp].t_entry = te[l];
                    sp++;
                }
                sp--;
                cur = stack[sp].child;
                cur_count = stack[sp].count;
                continue;
            }
        }
        for (;;) {
            if (sp == 0)
                return s->found;
            sp--;
            if (stack[sp].t_entry <= s->box_limit)
                break;
        }
        cur = stack[sp].child;
        cur_count = stack[sp].count;
    }
}

/* Shared by closest and any hit: the wide walk where the table walks a
 * wide layout and the scene has one, else the binary walk. */
static int walk(const struct trace_scene *scene, const float org[3], const float dir[3],
                float tmin, float tmax, int any_hit, struct trace_scene_hit *hit,
                struct trace_scene_counters *counters)
{
    const struct bvh *top = scene->top;
    if (!top || top->node_count == 0 || !(tmin < tmax))
        return 0;
    struct top_state s;
    s.scene = scene;
    s.kernels = scene->kernels ? scene->kernels : trace_kernels_get(TRACE_ISA_SCALAR);
    s.org = org;
    s.dir = dir;
    s.tmin = tmin;
    s.plain = trace_scene_plain_class(org, dir);
    s.any_hit = any_hit;
    s.hit = hit;
    s.counters = counters;
    s.best = tmax;
    s.box_limit = tmax;
    s.found = 0;
    s.ray_ready = 0;
    /* A top level of one leaf (a scene of one instance): its box test
     * would only repeat what each instance's walk tests, so a finite ray
     * visits the leaf's instances at once, and an identity instance's
     * object walk sets the ray up itself (visit_instance).  The box test
     * culls, it never decides a hit: the same answers, without the world
     * set-up, the top-level walk and its box test (RT_STAT_NODE_TESTS
     * counts the tests made). */
    const struct bvh_node *root = &top->nodes[0];
    if (root->count && (s.plain & TRACE_IDENTITY_EXACT)) {
        for (uint32_t i = 0; i < root->count; i++)
            if (visit_instance(&s, top->prim_index[root->first + i]))
                return 1;
        return s.found;
    }
    /* One set-up per ray; instances with the identity matrix reuse it. */
    world_ray(&s);
    const struct bvh4 *wide = scene->top_wide;
    if (wide && wide->node_count && s.kernels->wide_width &&
        (wide->width == 4 || wide->width == 8))
        return walk_wide(&s, wide);
    return walk_binary(&s);
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
