/* SPDX-License-Identifier: Apache-2.0 */
/*
 * packet_scene.c - two-level packet traversal (packet_scene.h).
 *
 * The top-level walk of scene_traverse.c, with a packet: each node's
 * lanes are tested ray by ray with trace_scene_wide_lanes (the single
 * walk's own test), each lane carries the mask of rays that entered it
 * and the smallest of their entry distances, and a popped lane is left
 * by the rays whose closest hit lies in front of it.  An instance leaf
 * transforms each ray with trace_scene_object_ray, as visit_instance
 * does (or the table's packet_xform, the same rays several at a time),
 * and walks the object with the kernels' packet walk (or ray by
 * ray when one ray is left); each ray's hit is then merged with
 * visit_instance's rule (ties to the lower instance), which does not
 * depend on the order of visits.  An instance the scene's hit filter
 * marks is walked for closest hits (any-hit walks too) and filtered ray
 * by ray with the single walk's rule (filter_lanes).
 *
 * A top level of one leaf is not walked when every ray is plain (walk),
 * as the single walk skips it, and its identity instances then take the
 * caller's arrays straight into the table's walk from the arrays
 * (kernels.h closest_packet_arrays): no world set-up at all.  Otherwise
 * the world rays are set up once a packet (world_setup), and what the
 * top level's walk needs of them per ray (octants, live rays, bests) is
 * taken eight rays at a time from the lanes.
 */
#include "trace/packet_scene.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "trace/flat_walk.h"
#include "trace/intersect.h"
#include "trace/scene_filter.h"

struct packet_top {
    const struct trace_scene *scene;
    const struct trace_kernels *kernels;
    const struct trace_packet *p;
    int any_hit;
    struct trace_scene_hit *hits;
    struct trace_scene_counters *counters;
    struct trace_ray ray[TRACE_PACKET];
    float best[TRACE_PACKET];
    /* The rays whose inv_dir[k] is negative (sign bit set), per axis k:
     * a ray's octant (trace_scene_box_rows) is bit r of each. */
    unsigned neg[3];
    unsigned found;
    unsigned done;  /* any hit: the rays with their hit */
    unsigned live; /* the rays traced (active, tmin < tmax) */
    /* The rays trace_scene_plain_class puts in the class of the identity
     * kind TRACE_IDENTITY_ZEROS (plain[0]) and TRACE_IDENTITY_EXACT
     * (plain[1]), found when the first identity instance is visited
     * (plain_ready): a scene without one does not pay for them. */
    unsigned plain[2];
    int plain_ready;
    /* 1 once the world rays are set up (world_setup): ray, the rows, the
     * octants, top's lanes.  A top level of one leaf visits its
     * instances before that, and an identity instance's object walk then
     * sets the rays up itself from the caller's arrays (visit_instance,
     * direct). */
    int ready;
    /* 1 when every live ray has one octant and a finite origin: the top
     * level's nodes are then tested box by box (lanes_by_box, or the
     * table's top_lanes). */
    int across;
    /* The rays across lanes for that test, and every ray's box limit
     * (the best t so far, widened: as in traverse.c). */
    struct trace_top_rays top;
};

/* struct trace_scene_hit begins with struct trace_hit's four fields, in
 * its order (visit_instance copies a hit's t, u, v, prim as one block). */
typedef char hit_prefix_is_trace_hit[sizeof(struct trace_hit) == 16 &&
                                             offsetof(struct trace_scene_hit, t) == 0 &&
                                             offsetof(struct trace_scene_hit, u) == 4 &&
                                             offsetof(struct trace_scene_hit, v) == 8 &&
                                             offsetof(struct trace_scene_hit, prim) == 12 &&
                                             offsetof(struct trace_hit, u) == 4 &&
                                             offsetof(struct trace_hit, v) == 8 &&
                                             offsetof(struct trace_hit, prim) == 12
                                         ? 1
                                         : -1];

/* The number of rays in a mask of at most TRACE_PACKET bits.  Not
 * __builtin_popcount: without -mpopcnt (this file is built for every
 * CPU) GCC calls libgcc's __popcountdi2 for it, 8.8 M Ir of a 3.3 G Ir
 * Whitted frame under callgrind; the SWAR count (Warren, Hacker's
 * Delight, 2nd ed., sec. 5-1) on one byte is a few inline operations. */
#if TRACE_PACKET > 8
#error "popcount below counts masks of at most 8 rays"
#endif
static int popcount(unsigned m)
{
    m = m - (m >> 1 & 0x55u);
    m = (m & 0x33u) + (m >> 2 & 0x33u);
    return (int)((m + (m >> 4)) & 0x0Fu);
}

/* More than one ray in the mask. */
static int several(unsigned m)
{
    return (m & (m - 1u)) != 0;
}

static int first(unsigned m)
{
    return __builtin_ctz(m);
}

/* A flattened hierarchy (flat_walk.h) for the rays of mask `rays`: ray by
 * ray with the single walk's flat walk, so the same answers. */
static void visit_group(struct packet_top *s, const struct trace_instance *group, unsigned rays)
{
    const struct trace_scene *scene = s->scene;
    struct trace_flat flat;
    s->counters->instance_tests += (uint64_t)popcount(rays);
    if (!scene->acquire_flat || !scene->acquire_flat(scene->user, group->object, &flat))
        return;
    for (unsigned m = rays; m; m &= m - 1u) {
        const int r = first(m);
        int found = s->found >> r & 1u;
        struct trace_flat_ray fr = {s->p->org[r], s->p->dir[r], s->p->tmin[r], &s->ray[r],
                                    &s->best[r], &s->top.box_limit[r], &found,
                                    s->any_hit ? NULL : &s->hits[r],
                                    scene->filtered ? scene : NULL};
        if (trace_flat_walk(&flat, scene->instances, group, &fr, s->counters))
            s->done |= 1u << r;
        if (found)
            s->found |= 1u << r;
    }
}

/*
 * The hit filter's part for the rays of mask `got` of an instance it
 * marks, ray by ray as the single walk's filter_hits: each ray's closest
 * hit h[r] below limit[r] (the kernels' packet walk gives every ray the
 * single walk's closest hit, packet.h) is asked about first; a ray whose
 * hit the filter rejects walks the object again alone, triangle by
 * triangle (trace_filter_object), for its closest accepted hit (any-hit
 * rays: the first accepted).  Only the rays whose nearest hit is
 * rejected pay that walk; the others keep the packet's work.  Returns
 * the rays left with an accepted hit in h.
 */
static unsigned filter_lanes(struct packet_top *s, uint32_t index,
                             const struct trace_object_view *view,
                             const struct trace_ray o_ray[TRACE_PACKET],
                             const float limit[TRACE_PACKET], unsigned got,
                             struct trace_hit h[TRACE_PACKET])
{
    const struct trace_scene *scene = s->scene;
    for (unsigned m = got; m; m &= m - 1u) {
        const int r = first(m);
        const struct trace_scene_hit cand = {h[r].t, h[r].u, h[r].v, h[r].prim, index};
        if (scene->accept(scene->accept_user, s->p->org[r], s->p->dir[r], &cand))
            continue;
        const struct trace_filter_ray fr = {scene, s->p->org[r], s->p->dir[r], index,
                                            s->any_hit};
        if (!trace_filter_object(view, &o_ray[r], limit[r], &fr, &h[r], &s->counters->object))
            got &= ~(1u << r);
    }
    return got;
}

/* The rays of s->live an identity instance of kind `identity` hands on
 * without a transform (trace_scene_plain_class). */
static unsigned plain_rays(struct packet_top *s, uint32_t identity)
{
    if (!s->plain_ready) {
        for (unsigned m = s->live; m; m &= m - 1u) {
            const int r = first(m);
            const unsigned c = trace_scene_plain_class(s->p->org[r], s->p->dir[r]);
            s->plain[0] |= (c & TRACE_IDENTITY_ZEROS) << r;
            s->plain[1] |= (c >> 1 & 1u) << r;
        }
        s->plain_ready = 1;
    }
    return s->plain[identity - 1u];
}

static void world_setup(struct packet_top *s);

/* Instance slot `index` for the rays of mask `rays`. */
static void visit_instance(struct packet_top *s, uint32_t index, unsigned rays)
{
    const struct trace_scene *scene = s->scene;
    if (scene->instances[index].member_count) {
        world_setup(s);
        visit_group(s, &scene->instances[index], rays);
        return;
    }
    const struct trace_kernels *k = s->kernels;
    struct trace_scene_counters *counters = s->counters;
    const struct trace_instance *inst = &scene->instances[index];
    struct trace_object_view view = {NULL, NULL, NULL, NULL};
    counters->instance_tests += (uint64_t)popcount(rays);
    if (!scene->acquire(scene->user, inst->object, &view))
        return;
    /* An instance the scene's hit filter marks: every ray takes the
     * closest-hit walk, any-hit rays too, and then filter_lanes, as the
     * single walk's visit_instance does. */
    const int filtered =
        scene->filtered && (scene->filtered[inst->instance_id] & scene->filter_mask);
    const int wide = view.wide && view.wide->node_count && k->closest4;
    /* Before the world set-up (a top level of one leaf, walk: every live
     * ray of trace_scene_plain_class's exact class), an identity instance
     * of the exact kind would take each world ray as it is: the table's
     * packet walk from the caller's arrays sets the rays up itself, the
     * same rays bit for bit as packet_init's (packet.h), straight into
     * its lanes (no rays' structs stored and loaded back). */
    const int direct = !s->ready && inst->identity == TRACE_IDENTITY_EXACT && wide &&
                       !filtered && several(rays);
    if (!direct)
        world_setup(s);
    struct trace_ray rays_o[TRACE_PACKET];
    const struct trace_ray *o_ray = rays_o;
    float limit[TRACE_PACKET];
    unsigned live = 0;
    if (direct) {
        o_ray = NULL;
        live = rays;
    } else if (inst->identity && !(rays & ~plain_rays(s, inst->identity))) {
        /* trace_scene_object_ray would copy each world ray as it is. */
        o_ray = s->ray;
        live = rays;
    } else if (k->packet_xform && several(rays)) {
        /* The same rays, transformed several at a time (packet_xform.h). */
        live = k->packet_xform(inst->world_to_object, s->p->org, s->p->dir, s->p->tmin, rays,
                               rays_o);
    } else {
        for (unsigned m = rays; m; m &= m - 1u) {
            const int r = first(m);
            if (trace_scene_object_ray(inst, s->p->org[r], s->p->dir[r], s->p->tmin[r],
                                       &s->ray[r], &rays_o[r]))
                live |= 1u << r;
        }
    }
    if (!live)
        return;
    /* visit_instance's limits: an equal t at a lower instance still comes
     * back, one ulp above the best.  Without a closest hit yet (any-hit
     * walks, an instance visited first) they are the bests themselves. */
    const float *lim = s->best;
    if (!s->any_hit && (s->found & live)) {
        for (unsigned m = live; m; m &= m - 1u) {
            const int r = first(m);
            limit[r] = s->found >> r & 1u ? isect_next_up(s->best[r]) : s->best[r];
        }
        lim = limit;
    }
    /* RT_AUTOMATIC's count of the rays reaching inside the object, as the
     * single walk's visit_instance counts them. */
    const uint64_t tests_before = counters->object.node_tests;
    const uint32_t root_tests = wide ? view.wide->width : 1;
    if (s->any_hit && !filtered) {
        unsigned hit = 0;
        if (direct) {
            hit = k->any_packet_arrays(view.wide, view.bvh, view.tri, s->p->org, s->p->dir,
                                       s->p->tmin, lim, live, TRACE_PACKET_HYBRID,
                                       &counters->object);
        } else if (wide && several(live)) {
            hit = k->any_packet(view.wide, view.bvh, view.tri, o_ray, lim, live,
                                TRACE_PACKET_HYBRID, &counters->object);
        } else {
            for (unsigned m = live; m; m &= m - 1u) {
                const int r = first(m);
                if (wide ? k->any4(view.wide, view.bvh, view.tri, &o_ray[r], lim[r],
                                   &counters->object)
                         : k->any(view.bvh, view.tri, &o_ray[r], lim[r], &counters->object))
                    hit |= 1u << r;
            }
        }
        if (view.ray_count)
            trace_scene_count_rays(counters, view.ray_count, tests_before, root_tests,
                                   (uint32_t)popcount(live));
        s->done |= hit;
        return;
    }
    struct trace_hit h[TRACE_PACKET];
    unsigned got = 0;
    if (direct) {
        got = k->closest_packet_arrays(view.wide, view.bvh, view.tri, s->p->org, s->p->dir,
                                       s->p->tmin, lim, live, TRACE_PACKET_HYBRID, h,
                                       &counters->object);
    } else if (wide && several(live)) {
        got = k->closest_packet(view.wide, view.bvh, view.tri, o_ray, lim, live,
                                TRACE_PACKET_HYBRID, h, &counters->object);
    } else {
        for (unsigned m = live; m; m &= m - 1u) {
            const int r = first(m);
            if (wide ? k->closest4(view.wide, view.bvh, view.tri, &o_ray[r], lim[r], &h[r],
                                   &counters->object)
                     : k->closest(view.bvh, view.tri, &o_ray[r], lim[r], &h[r],
                                  &counters->object))
                got |= 1u << r;
        }
    }
    if (view.ray_count)
        trace_scene_count_rays(counters, view.ray_count, tests_before, root_tests,
                               (uint32_t)popcount(live));
    if (filtered)
        got = filter_lanes(s, index, &view, o_ray, lim, got, h);
    if (s->any_hit) {
        s->done |= got;
        return;
    }
    /* visit_instance's rule: a ray's first hit is taken; a later one when
     * nearer, or as near at a lower instance. */
    unsigned take = got & ~s->found;
    for (unsigned m = got & s->found; m; m &= m - 1u) {
        const int r = first(m);
        if (trace_scene_hit_replaces(scene, inst, h[r].t, s->best[r], &s->hits[r]))
            take |= 1u << r;
    }
    s->found |= take;
    for (unsigned m = take; m; m &= m - 1u) {
        const int r = first(m);
        struct trace_scene_hit *hit = &s->hits[r];
        s->best[r] = h[r].t;
        s->top.box_limit[r] = h[r].t * ISECT_BOX_FAR_SCALE;
        /* t, u, v, prim in one 16-byte copy (hit_prefix_is_trace_hit). */
        memcpy(hit, &h[r], sizeof(h[r]));
        hit->instance = index;
    }
}

#if ISECT_PAIR_SSE
/*
 * A wide top-level node's test for the rays of mask `rays`, box by box
 * with four rays a register, when they share one octant (so one pair of
 * rows per axis) and have finite origins: for each ray and lane the same
 * operations in the same order as trace_scene_wide_lanes, so the same
 * bits, but the work of a lane no child uses is left out.  An unused
 * lane holds the empty box (bvh4_layout.h), which a finite origin always
 * misses: its near distance is +inf (or its far one -inf) on every axis
 * whatever the direction, so the lane's test fails for every such ray.
 * Ray by ray, a node whose instance boxes are one or two of its eight
 * lanes (a scene of one object) paid the test of all eight, and a call
 * per ray: about 150 instructions a ray against under 10.
 */
static void lanes_by_box(const struct trace_top_rays *q, const float *bounds, uint32_t width,
                         unsigned rays, unsigned lane_rays[8], float t_min[8])
{
    unsigned used = trace_top_used_lanes(bounds, width);
    const __m128 scale4 = _mm_set1_ps(ISECT_BOX_FAR_SCALE);
    for (; used; used &= used - 1u) {
        const int l = first(used);
        const float bn[3] = {bounds[q->near_row[0] * width + l], bounds[q->near_row[1] * width + l],
                             bounds[q->near_row[2] * width + l]};
        const float bf[3] = {bounds[q->far_row[0] * width + l], bounds[q->far_row[1] * width + l],
                             bounds[q->far_row[2] * width + l]};
        for (int g = 0; g < TRACE_PACKET; g += 4) {
            const unsigned group = rays >> g & 15u;
            if (!group)
                continue;
            __m128 t0 = _mm_load_ps(q->tmin + g);
            __m128 t1 = _mm_set1_ps(INFINITY);
            for (int k = 0; k < 3; k++) {
                const __m128 o = _mm_load_ps(q->org[k] + g);
                const __m128 inv = _mm_load_ps(q->inv_dir[k] + g);
                const __m128 tn = _mm_mul_ps(_mm_sub_ps(_mm_set1_ps(bn[k]), o), inv);
                const __m128 tf = _mm_mul_ps(_mm_sub_ps(_mm_set1_ps(bf[k]), o), inv);
                t0 = _mm_max_ps(tn, t0);
                t1 = _mm_min_ps(tf, t1);
            }
            t1 = _mm_min_ps(_mm_mul_ps(t1, scale4), _mm_load_ps(q->box_limit + g));
            unsigned in = (unsigned)_mm_movemask_ps(_mm_cmple_ps(t0, t1)) & group;
            if (!in)
                continue;
            float te[4];
            _mm_storeu_ps(te, t0);
            lane_rays[l] |= in << g;
            for (; in; in &= in - 1u) {
                const float t = te[first(in)];
                t_min[l] = t < t_min[l] ? t : t_min[l];
            }
        }
    }
}
#endif

/* Ray r's octant, as trace_scene_box_rows gives it (bit k: inv_dir[k]
 * negative). */
static int octant_of(const struct packet_top *s, int r)
{
    return (int)((s->neg[0] >> r & 1u) | (s->neg[1] >> r & 1u) << 1 | (s->neg[2] >> r & 1u) << 2);
}

/* The packet walk of the wide top level (scene_traverse.c's walk_wide,
 * ray by ray inside each node, or box by box: lanes_by_box). */
static void walk_top(struct packet_top *s, const struct bvh4 *wide, unsigned active)
{
    const struct bvh *top = s->scene->top;
    struct trace_scene_counters *counters = s->counters;
    const uint32_t width = wide->width;
    struct {
        uint32_t child;
        uint32_t count;
        unsigned rays;
        float t_entry;
    } stack[7 * BVH_MAX_DEPTH + 8];
    uint32_t sp = 0;
    uint32_t cur = 0, cur_count = 0;
    unsigned rays = active;
    for (;;) {
        if (cur_count) {
            for (uint32_t i = 0; i < cur_count && rays; i++) {
                visit_instance(s, top->prim_index[cur + i], rays);
                rays &= ~s->done;
            }
        } else {
            const float *bounds;
            const uint32_t *child;
            const uint8_t *count;
            uint32_t order;
            const int octant = octant_of(s, first(rays));
            order = trace_scene_wide_node(wide, width, cur, octant, &bounds, &child, &count);
            unsigned lane_rays[8] = {0, 0, 0, 0, 0, 0, 0, 0};
            float t_min[8];
            for (uint32_t l = 0; l < width; l++)
                t_min[l] = INFINITY;
#if ISECT_PAIR_SSE
            if (s->across) {
                counters->top_node_tests += width * (uint64_t)popcount(rays);
                if (s->kernels->top_lanes)
                    s->kernels->top_lanes(&s->top, bounds, width, rays, lane_rays, t_min);
                else
                    lanes_by_box(&s->top, bounds, width, rays, lane_rays, t_min);
            } else
#endif
            for (unsigned m = rays; m; m &= m - 1u) {
                const int r = first(m);
                float te[8];
                int near_row[3], far_row[3];
                trace_scene_box_rows(&s->ray[r], near_row, far_row);
                counters->top_node_tests += width;
                unsigned in = s->kernels->top_lanes1(bounds, width, near_row, far_row, &s->ray[r],
                                                     s->top.box_limit[r], te);
                for (; in; in &= in - 1u) {
                    const int l = first(in);
                    lane_rays[l] |= 1u << r;
                    t_min[l] = te[l] < t_min[l] ? te[l] : t_min[l];
                }
            }
            const uint32_t sp0 = sp;
            for (int q = (int)width - 1; q >= 0; q--) {
                const unsigned l = order >> (3 * q) & 7u;
                if (!lane_rays[l])
                    continue;
                stack[sp].child = child[l];
                stack[sp].count = count[l];
                stack[sp].rays = lane_rays[l];
                stack[sp].t_entry = t_min[l];
                sp++;
            }
            if (sp != sp0) {
                sp--;
                cur = stack[sp].child;
                cur_count = stack[sp].count;
                rays = stack[sp].rays;
                continue;
            }
        }
        for (;;) {
            if (sp == 0)
                return;
            sp--;
            rays = stack[sp].rays & ~s->done;
            for (unsigned m = rays; m; m &= m - 1u) {
                const int r = first(m);
                if (!(stack[sp].t_entry <= s->top.box_limit[r]))
                    rays &= ~(1u << r);
            }
            if (rays)
                break;
        }
        cur = stack[sp].child;
        cur_count = stack[sp].count;
    }
}

/* The world rays' set-up, once a packet and only when something needs it
 * (the top level's walk, a transformed instance, a flattened group, a hit
 * filter): rays[r] as trace_ray_init sets them up (the table's
 * packet_init, eight at a time), the rows and octant of each ray, and
 * the top level's lanes.  best and box_limit are not touched: a top level
 * of one leaf may have merged hits into them before. */
static void world_setup(struct packet_top *s)
{
    if (s->ready)
        return;
    s->ready = 1;
    const struct trace_kernels *k = s->kernels;
    const struct trace_packet *p = s->p;
    const unsigned live = s->live;
#if ISECT_PAIR_SSE
    float origin_probe = 0.0f; /* lanes_by_box's condition without packet_init */
#endif
    /* The table's set-up of all the rays at once, where it has one. */
    const int at_once = k->packet_init != NULL;
#if ISECT_PAIR_SSE
    unsigned finite_org = 0;
#endif
    s->neg[0] = s->neg[1] = s->neg[2] = 0;
    if (at_once) {
        struct trace_packet_plain plain;
        k->packet_init(p->org, p->dir, p->tmin, live, s->ray, &s->top, &plain);
        s->plain[0] = plain.zeros;
        s->plain[1] = plain.exact;
        s->plain_ready = 1;
#if ISECT_PAIR_SSE
        finite_org = plain.finite_org;
        /* The octants from top's inv_dir lanes, which hold each live
         * ray's inv_dir bit for bit (packet.h): their sign bits, eight
         * rays in two movemasks an axis, where trace_scene_box_rows ray
         * by ray cost about 36 instructions a ray. */
        for (int a = 0; a < 3; a++)
            s->neg[a] = ((unsigned)_mm_movemask_ps(_mm_load_ps(s->top.inv_dir[a])) |
                         (unsigned)_mm_movemask_ps(_mm_load_ps(s->top.inv_dir[a] + 4)) << 4) &
                        live;
#endif
    }
    for (unsigned m = at_once && ISECT_PAIR_SSE ? 0u : live; m; m &= m - 1u) {
        const int r = first(m);
        if (!at_once)
            trace_ray_init(&s->ray[r], p->org[r], p->dir[r], p->tmin[r]);
        int near_row[3], far_row[3];
        const int octant = trace_scene_box_rows(&s->ray[r], near_row, far_row);
        for (int a = 0; a < 3; a++)
            s->neg[a] |= (unsigned)(octant >> a & 1) << r;
#if ISECT_PAIR_SSE
        /* Without packet_init's masks: x - x is +0.0 for a finite x and a
         * NaN for an infinity or a NaN, so the sum over the origins'
         * components stays 0 when all are finite. */
        origin_probe += (p->org[r][0] - p->org[r][0]) + (p->org[r][1] - p->org[r][1]) +
                        (p->org[r][2] - p->org[r][2]);
        /* lanes_by_box's rays across lanes (packet_init's already). */
        s->top.tmin[r] = s->ray[r].tmin;
        for (int a = 0; a < 3; a++) {
            s->top.org[a][r] = s->ray[r].org[a];
            s->top.inv_dir[a][r] = s->ray[r].inv_dir[a];
        }
#endif
    }
#if ISECT_PAIR_SSE
    /* The lanes of the rays left out hold zeros, which it masks out. */
    for (unsigned m = ~live & ((1u << TRACE_PACKET) - 1u); m; m &= m - 1u) {
        const int r = first(m);
        s->top.tmin[r] = s->top.box_limit[r] = 0.0f;
        for (int a = 0; a < 3; a++)
            s->top.org[a][r] = s->top.inv_dir[a][r] = 0.0f;
    }
    const int finite_origins = at_once ? finite_org == live : origin_probe == 0.0f;
    /* One octant: on each axis all the live rays negative or none. */
    int one_octant = 1;
    for (int a = 0; a < 3; a++)
        one_octant &= s->neg[a] == 0 || s->neg[a] == live;
    s->across = finite_origins && one_octant;
    if (s->across && live)
        trace_scene_box_rows(&s->ray[first(live)], s->top.near_row, s->top.far_row);
#else
    s->across = 0;
#endif
}

/*
 * The rays of `live` that trace_scene_plain_class puts in the class
 * TRACE_IDENTITY_EXACT (every component finite, none -0.0, the direction
 * not zero), from all eight rays' arrays at once: each float's bits
 * tested as trace_scene_plain_class tests them (a magnitude below the
 * infinity's bits is finite; -0.0 is the bits 0x80000000), the 24
 * components of each array in six registers, float 3r + k in bit 3r + k
 * of a mask; a ray is out when one of its three bits is set in the
 * origins' or the directions' mask of bad components, or all three in
 * the mask of the directions' zeros.  The lanes of rays not in `live`
 * are read too (any bits) and masked out.  Ray by ray the class cost
 * about 20 instructions a ray.
 */
static unsigned exact_rays(const struct trace_packet *p, unsigned live)
{
#if ISECT_PAIR_SSE
    const __m128i magnitude = _mm_set1_epi32(0x7fffffff);
    const __m128i inf = _mm_set1_epi32(0x7f800000);
    const __m128i sign = _mm_set1_epi32((int)0x80000000u);
    const __m128i zero = _mm_setzero_si128();
    uint32_t bad = 0, dir_zero = 0;
    const float *o = &p->org[0][0], *d = &p->dir[0][0];
    for (int q = 0; q < 6; q++) {
        const __m128i vo = _mm_castps_si128(_mm_loadu_ps(o + 4 * q));
        const __m128i vd = _mm_castps_si128(_mm_loadu_ps(d + 4 * q));
        const __m128i md = _mm_and_si128(vd, magnitude);
        /* Not finite (the magnitude at or above the infinity's bits, as
         * signed integers: the magnitude's sign bit is clear) or -0.0. */
        const __m128i bo = _mm_or_si128(
            _mm_cmpeq_epi32(_mm_cmplt_epi32(_mm_and_si128(vo, magnitude), inf), zero),
            _mm_cmpeq_epi32(vo, sign));
        const __m128i bd = _mm_or_si128(_mm_cmpeq_epi32(_mm_cmplt_epi32(md, inf), zero),
                                        _mm_cmpeq_epi32(vd, sign));
        bad |= (uint32_t)_mm_movemask_ps(_mm_castsi128_ps(_mm_or_si128(bo, bd))) << (4 * q);
        dir_zero |= (uint32_t)_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(md, zero)))
                    << (4 * q);
    }
    /* Bit 3r: ray r has a bad component, or a zero direction. */
    const uint32_t out = ((bad | bad >> 1 | bad >> 2) | (dir_zero & dir_zero >> 1 & dir_zero >> 2));
    unsigned exact = 0;
    for (int r = 0; r < TRACE_PACKET; r++)
        exact |= (~out >> (3 * r) & 1u) << r;
    return exact & live;
#else
    unsigned exact = 0;
    for (unsigned m = live; m; m &= m - 1u) {
        const int r = first(m);
        if (trace_scene_plain_class(p->org[r], p->dir[r]) & TRACE_IDENTITY_EXACT)
            exact |= 1u << r;
    }
    return exact;
#endif
}

static unsigned walk(const struct trace_scene *scene, const struct trace_packet *p, int any_hit,
                     struct trace_scene_hit *hits, struct trace_scene_counters *counters)
{
    const struct trace_kernels *k = scene->kernels;
    const struct bvh4 *wide = scene->top_wide;
    const struct bvh *top = scene->top;
    const unsigned active = p->active & ((1u << TRACE_PACKET) - 1u);
    unsigned result = 0;
    if (!k || !k->closest_packet || !k->wide_width || !wide || !wide->node_count ||
        !(wide->width == 4 || wide->width == 8) || !top || top->node_count == 0 ||
        !several(active)) {
        for (unsigned m = active; m; m &= m - 1u) {
            const int r = first(m);
            if (any_hit ? trace_scene_any(scene, p->org[r], p->dir[r], p->tmin[r], p->tmax[r],
                                          counters)
                        : trace_scene_closest(scene, p->org[r], p->dir[r], p->tmin[r],
                                              p->tmax[r], &hits[r], counters))
                result |= 1u << r;
        }
        return result;
    }
    struct packet_top s;
    s.scene = scene;
    s.kernels = k;
    s.p = p;
    s.any_hit = any_hit;
    s.hits = hits;
    s.counters = counters;
    s.found = 0;
    s.done = 0;
    s.plain[0] = s.plain[1] = 0;
    s.plain_ready = 0;
    s.ready = 0;
    counters->rays += (uint64_t)popcount(active);
    /* The rays with tmin < tmax (else trace_scene_closest's early miss),
     * and every ray's best and box limit its tmax. */
    unsigned live = 0;
#if ISECT_PAIR_SSE
    for (int g = 0; g < TRACE_PACKET; g += 4) {
        const __m128 tmax = _mm_loadu_ps(p->tmax + g);
        live |= (unsigned)_mm_movemask_ps(_mm_cmplt_ps(_mm_loadu_ps(p->tmin + g), tmax)) << g;
        _mm_storeu_ps(s.best + g, tmax);
        _mm_store_ps(s.top.box_limit + g, tmax);
    }
    live &= active;
#else
    for (unsigned m = active; m; m &= m - 1u) {
        const int r = first(m);
        if (p->tmin[r] < p->tmax[r])
            live |= 1u << r;
        s.best[r] = p->tmax[r];
        s.top.box_limit[r] = p->tmax[r];
    }
#endif
    s.live = live;
    if (!live)
        return 0;
    /* A top level of one leaf (a scene of one instance), as the single
     * walk takes it (scene_traverse.c, walk): its box test would only
     * repeat what each instance's walk tests (it culls, it never decides
     * a hit), so when every ray is of the class the single walk asks for
     * there, the leaf's instances are visited at once, and an identity
     * instance's object walk sets the rays up itself from the caller's
     * arrays (visit_instance); the world set-up is made only when
     * something needs it.  RT_STAT_NODE_TESTS counts the tests made. */
    const struct bvh_node *root = &top->nodes[0];
    if (root->count && k->closest_packet_arrays && k->any_packet_arrays &&
        exact_rays(p, live) == live) {
        unsigned rays = live;
        for (uint32_t i = 0; i < root->count && rays; i++) {
            visit_instance(&s, top->prim_index[root->first + i], rays);
            rays &= ~s.done;
        }
        return any_hit ? s.done : s.found;
    }
    world_setup(&s);
    walk_top(&s, wide, live);
    return any_hit ? s.done : s.found;
}

unsigned trace_scene_closest_packet(const struct trace_scene *scene, const struct trace_packet *p,
                                    struct trace_scene_hit hits[TRACE_PACKET],
                                    struct trace_scene_counters *counters)
{
    return walk(scene, p, 0, hits, counters);
}

unsigned trace_scene_any_packet(const struct trace_scene *scene, const struct trace_packet *p,
                                struct trace_scene_counters *counters)
{
    return walk(scene, p, 1, NULL, counters);
}

int trace_packet_coherent(const float *const dir[], int n)
{
    if (n < 2)
        return 0;
    const float *d0 = dir[0];
    const float l0 = d0[0] * d0[0] + d0[1] * d0[1] + d0[2] * d0[2];
#if ISECT_PAIR_SSE
    if (n <= TRACE_PACKET) {
        /* Rays 1 .. n - 1 four a register (lanes past n - 1 hold ray 0,
         * masked out), each lane the loop's operations below in its order,
         * so the same decision: ray by ray it was about 40 instructions a
         * ray of rtTraceRays' packets (trace_packet_coherent 29.5 M of a
         * 604 M BART kitchen pass of 786,432 rays, callgrind). */
        const __m128i sign = _mm_set1_epi32((int)0x80000000u);
        __m128 e[3], s0[3];
        for (int k = 0; k < 3; k++)
            e[k] = _mm_set1_ps(d0[k]);
        for (int k = 0; k < 3; k++)
            s0[k] = _mm_and_ps(e[k], _mm_castsi128_ps(sign));
        const __m128 bound0 = _mm_set1_ps(l0);
        for (int g = 1; g < n; g += 4) {
            float v[3][4];
            for (int j = 0; j < 4; j++) {
                const float *d = g + j < n ? dir[g + j] : d0;
                v[0][j] = d[0];
                v[1][j] = d[1];
                v[2][j] = d[2];
            }
            const __m128 x = _mm_loadu_ps(v[0]), y = _mm_loadu_ps(v[1]), z = _mm_loadu_ps(v[2]);
            /* A sign bit other than ray 0's on some axis. */
            const __m128 flip =
                _mm_or_ps(_mm_or_ps(_mm_xor_ps(_mm_and_ps(x, _mm_castsi128_ps(sign)), s0[0]),
                                    _mm_xor_ps(_mm_and_ps(y, _mm_castsi128_ps(sign)), s0[1])),
                          _mm_xor_ps(_mm_and_ps(z, _mm_castsi128_ps(sign)), s0[2]));
            const __m128 dot = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, e[0]), _mm_mul_ps(y, e[1])),
                                          _mm_mul_ps(z, e[2]));
            const __m128 l = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)),
                                        _mm_mul_ps(z, z));
            const __m128 ok = _mm_and_ps(
                _mm_cmpgt_ps(dot, _mm_setzero_ps()),
                _mm_cmpgt_ps(_mm_mul_ps(dot, dot),
                             _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(0.81f), l), bound0)));
            const int lanes = n - g < 4 ? (1 << (n - g)) - 1 : 15;
            if ((_mm_movemask_ps(flip) | (~_mm_movemask_ps(ok) & 15)) & lanes)
                return 0;
        }
        return 1;
    }
#endif
    for (int i = 1; i < n; i++) {
        const float *d = dir[i];
        for (int k = 0; k < 3; k++)
            if (signbit(d[k]) != signbit(d0[k]))
                return 0;
        const float dot = d[0] * d0[0] + d[1] * d0[1] + d[2] * d0[2];
        const float l = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        /* cos > 0.9 (about 25 degrees), without a square root. */
        if (!(dot > 0.0f) || !(dot * dot > 0.81f * l * l0))
            return 0;
    }
    return 1;
}
