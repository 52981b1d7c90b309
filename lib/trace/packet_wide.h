/* SPDX-License-Identifier: Apache-2.0 */
/*
 * packet_wide.h - the packet walk over the wide layout (packet.h),
 * included by the SIMD translation units (kernels.h) after
 * traverse_wide.h, whose per-ray pieces it reuses: each ray of a packet
 * keeps the single-ray walk's state (struct wide_state), every box test
 * of a ray is walk_wide4's or walk_wide8's float operations on that
 * ray's own near and far planes, every leaf is wide_leaf for that ray,
 * and a subtree left with fewer than `hybrid` rays is walked by
 * walk_wide4/walk_wide8 itself from its root, ray by ray.  So each ray
 * gets the single walk's hit bit for bit (traverse_wide.h gives the
 * argument that neither skipped inner nodes nor the order of visits
 * changes it; a packet only visits, for each ray, nodes whose box that
 * ray's own test accepted, in the order of the packet's first ray).
 * Define TRACE_PACKET_CLOSEST and TRACE_PACKET_ANY.
 *
 * 8-wide layout (AVX): a node's children are tested child by child,
 * the eight rays of the packet in the SIMD lanes (packet_walk8, the
 * argument for bit-identity is there).  4-wide layout: ray by ray (one
 * SIMD test over the four children per ray), the results transposed
 * into a mask of rays per child with one AND and OR per ray; a pushed
 * child keeps the smallest entry distance of its rays, and is skipped on
 * pop for the rays whose closest hit so far lies in front of it.
 */
#include "trace/packet.h"

struct packet_entry {
    uint32_t child;
    uint32_t count; /* 0: wide node, else a leaf lane */
    unsigned rays;  /* the rays that enter it */
    float t_entry;  /* the smallest of their entry distances */
};

/* The rays of a packet: the single walk's state per ray, its near and
 * far bound rows per axis and its octant (traverse_wide.h). */
struct packet_state {
    struct wide_state s[TRACE_PACKET];
    int near_row[TRACE_PACKET][3];
    int far_row[TRACE_PACKET][3];
    int octant[TRACE_PACKET];
};

/* Ray r against the four children of n: walk_wide4's operations.  Adds
 * r's bit to rays[l] for each child l it enters and folds its entry
 * distances into *t_min. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packet_box4(const struct bvh4_node *n, struct packet_state *p, unsigned r,
                               __m128 *rays, __m128 *t_min)
{
    const struct trace_ray *ray = p->s[r].ray;
    __m128 t0 = _mm_set1_ps(ray->tmin);
    __m128 t1 = _mm_set1_ps(INFINITY);
    for (int k = 0; k < 3; k++) {
        const __m128 o = _mm_set1_ps(ray->org[k]);
        const __m128 inv = _mm_set1_ps(ray->inv_dir[k]);
        const __m128 tn = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n->bounds[p->near_row[r][k]]), o), inv);
        const __m128 tf = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n->bounds[p->far_row[r][k]]), o), inv);
        t0 = _mm_max_ps(tn, t0);
        t1 = _mm_min_ps(tf, t1);
    }
    t1 = _mm_mul_ps(t1, _mm_set1_ps(ISECT_BOX_FAR_SCALE));
    t1 = _mm_min_ps(t1, _mm_set1_ps(p->s[r].box_limit));
    const __m128 in = _mm_cmple_ps(t0, t1);
    p->s[r].node_tests += 4;
    *rays = _mm_or_ps(*rays, _mm_and_ps(in, _mm_castsi128_ps(_mm_set1_epi32((int)(1u << r)))));
    *t_min = _mm_min_ps(*t_min, _mm_blendv_ps(_mm_set1_ps(INFINITY), t0, in));
}

#if defined(__AVX__)
/*
 * The 8-wide layout with the rays in the SIMD lanes (Wald, Slusallek,
 * Benthin and Wagner 2001 sec. 4; Benthin, Wald, Woop, Ernst and Mark
 * 2012 for wide BVHs): one child box against the eight rays of the
 * packet per AVX instruction, lane r computing exactly walk_wide8's
 * float operations for ray r on that child, so every lane's answer is
 * the single walk's bit for bit:
 * - tn = (near - org) * inv and tf = (far - org) * inv per axis, with
 *   near/far the bound ray r's own octant picks: when all rays of the
 *   packet share an octant (`uniform`), the rows of the first ray;
 *   otherwise a blend on the sign bit of each lane's inverse direction,
 *   the bit walk_wide8's signbit() reads (a selection, no arithmetic);
 * - t0 = max(tn_z, max(tn_y, max(tn_x, tmin))), t1 = min(tf_z, min(tf_y,
 *   min(tf_x, inf))) in the same operand order (maxps/minps return their
 *   second operand for a NaN, so a NaN slab is skipped in each lane as in
 *   the single walk), then t1 * ISECT_BOX_FAR_SCALE, min with the ray's
 *   box_limit, and t0 <= t1 (ordered).
 * Each pushed child keeps every lane's entry distance, and a popped
 * child is left by exactly the rays whose single walk would skip it on
 * its pop (t_entry <= box_limit fails).  Unused child slots (the empty
 * box, min x = +inf) are not tested: no ray's walk could find a hit in
 * them.  Only the order of a node's children follows one ray (the first
 * of the packet), which no answer depends on (traverse_wide.h).
 */
struct packet8 {
    __m256 org[3], inv[3]; /* lane r: ray r */
    __m256 tmin;
    union {
        __m256 v;
        float f[TRACE_PACKET];
    } limit;               /* lane r: ray r's box_limit */
    int uniform;           /* all rays share near_row[first ray] */
};

/* Child l of n against the rays of the packet: the lanes whose test
 * passes (as walk_wide8's mask bit l for each ray) in the returned mask,
 * their entry distances in *t_entry. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned packet8_child(const struct bvh8_node *n, const struct packet8 *q,
                                     const int *near_row, const int *far_row, int uniform,
                                     unsigned l, __m256 *t_entry)
{
    __m256 t0 = q->tmin;
    __m256 t1 = _mm256_set1_ps(INFINITY);
    for (int k = 0; k < 3; k++) {
        __m256 lo, hi;
        if (uniform) {
            lo = _mm256_broadcast_ss(&n->bounds[near_row[k]][l]);
            hi = _mm256_broadcast_ss(&n->bounds[far_row[k]][l]);
        } else {
            const __m256 bmin = _mm256_broadcast_ss(&n->bounds[k][l]);
            const __m256 bmax = _mm256_broadcast_ss(&n->bounds[3 + k][l]);
            lo = _mm256_blendv_ps(bmin, bmax, q->inv[k]);
            hi = _mm256_blendv_ps(bmax, bmin, q->inv[k]);
        }
        const __m256 tn = _mm256_mul_ps(_mm256_sub_ps(lo, q->org[k]), q->inv[k]);
        const __m256 tf = _mm256_mul_ps(_mm256_sub_ps(hi, q->org[k]), q->inv[k]);
        t0 = _mm256_max_ps(tn, t0);
        t1 = _mm256_min_ps(tf, t1);
    }
    t1 = _mm256_mul_ps(t1, _mm256_set1_ps(ISECT_BOX_FAR_SCALE));
    t1 = _mm256_min_ps(t1, q->limit.v);
    *t_entry = t0;
    return (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(t0, t1, _CMP_LE_OQ));
}

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned packet_walk8(const struct bvh4 *wide, struct packet_state *p,
                                    struct packet8 *q, unsigned active, unsigned hybrid,
                                    const int uniform, uint64_t *node_tests)
{
    __m256 st_t[WIDE_STACK];
    uint32_t st_child[WIDE_STACK];
    uint32_t st_count[WIDE_STACK];
    unsigned st_rays[WIDE_STACK];
    uint32_t sp = 0;
    uint32_t cur = 0, cur_count = 0;
    unsigned rays = active;
    unsigned done = 0;
    const int r0 = __builtin_ctz(active);
    const int *near_row = p->near_row[r0];
    const int *far_row = p->far_row[r0];
    for (;;) {
        if ((unsigned)__builtin_popcount(rays) < hybrid) {
            for (unsigned m = rays; m; m &= m - 1u) {
                const unsigned r = (unsigned)__builtin_ctz(m);
                if (walk_wide8(wide, &p->s[r], cur, cur_count))
                    done |= 1u << r;
                q->limit.f[r] = p->s[r].box_limit;
            }
        } else if (cur_count) {
            for (unsigned m = rays; m; m &= m - 1u) {
                const unsigned r = (unsigned)__builtin_ctz(m);
                if (wide_leaf(&p->s[r], wide->packets, cur, cur_count))
                    done |= 1u << r;
                q->limit.f[r] = p->s[r].box_limit;
            }
        } else {
            const struct bvh8_node *n = &wide->nodes8[cur];
            *node_tests += 8u * (unsigned)__builtin_popcount(rays);
            const unsigned used = (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(
                _mm256_load_ps(n->bounds[0]), _mm256_set1_ps(INFINITY), _CMP_NEQ_UQ));
            const int octant = p->octant[__builtin_ctz(rays)];
            const uint32_t order = (uint32_t)n->order[octant][0] |
                                   (uint32_t)n->order[octant][1] << 8 |
                                   (uint32_t)n->order[octant][2] << 16;
            const uint32_t sp0 = sp;
            /* Back to front in the first ray's octant order, so that the
             * front child is popped first. */
            for (int i = 7; i >= 0; i--) {
                const unsigned l = order >> (3 * i) & 7u;
                if (!(used >> l & 1u))
                    continue;
                __m256 te;
                const unsigned in =
                    packet8_child(n, q, near_row, far_row, uniform, l, &te) & rays;
                if (!in)
                    continue;
                st_t[sp] = te;
                st_child[sp] = n->child[l];
                st_count[sp] = n->count[l];
                st_rays[sp] = in;
                sp++;
            }
            if (sp != sp0) {
                sp--;
                cur = st_child[sp];
                cur_count = st_count[sp];
                rays = st_rays[sp];
                if (!cur_count)
                    wide_prefetch(&wide->nodes8[cur], sizeof(struct bvh8_node));
                continue;
            }
        }
        for (;;) {
            if (sp == 0)
                return done;
            sp--;
            /* Each ray leaves the child exactly where its single walk's
             * pop would skip it: t_entry <= box_limit fails. */
            rays = st_rays[sp] & ~done &
                   (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(
                       st_t[sp], q->limit.v, _CMP_LE_OQ));
            if (rays)
                break;
        }
        cur = st_child[sp];
        cur_count = st_count[sp];
    }
}

/* packet_walk8 for the rays of `active`, whose lanes p describes. */
static unsigned packet_run8(const struct bvh4 *wide, struct packet_state *p, unsigned active,
                            unsigned hybrid, uint64_t *node_tests)
{
    struct packet8 q;
    float org[3][TRACE_PACKET], inv[3][TRACE_PACKET], tmin[TRACE_PACKET];
    const int r0 = __builtin_ctz(active);
    int uniform = 1;
    for (unsigned r = 0; r < TRACE_PACKET; r++) {
        /* Lanes outside `active` copy the first ray: never read, but
         * finite. */
        const unsigned from = active >> r & 1u ? r : (unsigned)r0;
        const struct trace_ray *ray = p->s[from].ray;
        for (int k = 0; k < 3; k++) {
            org[k][r] = ray->org[k];
            inv[k][r] = ray->inv_dir[k];
        }
        tmin[r] = ray->tmin;
        q.limit.f[r] = p->s[from].box_limit;
        uniform &= p->octant[from] == p->octant[r0];
    }
    for (int k = 0; k < 3; k++) {
        q.org[k] = _mm256_loadu_ps(org[k]);
        q.inv[k] = _mm256_loadu_ps(inv[k]);
    }
    q.tmin = _mm256_loadu_ps(tmin);
    if (uniform)
        return packet_walk8(wide, p, &q, active, hybrid, 1, node_tests);
    return packet_walk8(wide, p, &q, active, hybrid, 0, node_tests);
}
#endif

/* The packet walk of the 4-wide layout, ray by ray inside a node; returns
 * the rays an any-hit walk found a hit for (0 for closest hit, whose
 * hits are in the states). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned packet_walk4(const struct bvh4 *wide, struct packet_state *p,
                                    unsigned active, unsigned hybrid)
{
    struct packet_entry stack[WIDE_STACK];
    uint32_t sp = 0;
    uint32_t cur = 0, cur_count = 0;
    unsigned rays = active;
    unsigned done = 0;
    for (;;) {
        if ((unsigned)__builtin_popcount(rays) < hybrid) {
            /* Hybrid: the few rays left take the single walk from here. */
            for (unsigned m = rays; m; m &= m - 1u) {
                const unsigned r = (unsigned)__builtin_ctz(m);
                if (walk_wide4(wide, &p->s[r], cur, cur_count))
                    done |= 1u << r;
            }
        } else if (cur_count) {
            for (unsigned m = rays; m; m &= m - 1u) {
                const unsigned r = (unsigned)__builtin_ctz(m);
                if (wide_leaf(&p->s[r], wide->packets, cur, cur_count))
                    done |= 1u << r;
            }
        } else {
            uint32_t lane_rays[4];
            float t_min[4];
            const uint32_t *child;
            const uint8_t *count;
            uint32_t order; /* 3 bits per position */
            const int octant = p->octant[__builtin_ctz(rays)];
            {
                const struct bvh4_node *n = &wide->nodes[cur];
                __m128 in = _mm_setzero_ps();
                __m128 tm = _mm_set1_ps(INFINITY);
                for (unsigned m = rays; m; m &= m - 1u)
                    packet_box4(n, p, (unsigned)__builtin_ctz(m), &in, &tm);
                _mm_storeu_ps((float *)lane_rays, in);
                _mm_storeu_ps(t_min, tm);
                child = n->child;
                count = n->count;
                order = 0;
                for (int q = 0; q < 4; q++)
                    order |= (uint32_t)(n->order[octant] >> (2 * q) & 3u) << (3 * q);
            }
            const uint32_t sp0 = sp;
            for (int q = 3; q >= 0; q--) {
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
                return done;
            sp--;
            rays = stack[sp].rays & ~done;
            /* The rays whose closest hit lies in front of the subtree
             * leave it, as the single walk's pop skips it. */
            const float t_entry = stack[sp].t_entry;
            for (unsigned m = rays; m; m &= m - 1u) {
                const unsigned r = (unsigned)__builtin_ctz(m);
                if (!(t_entry <= p->s[r].box_limit))
                    rays &= ~(1u << r);
            }
            if (rays)
                break;
        }
        cur = stack[sp].child;
        cur_count = stack[sp].count;
    }
}

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline unsigned packet_run(const struct bvh4 *wide, const struct bvh *bvh,
                                  const float *tri, const struct trace_ray *rays,
                                  const float *t_max, unsigned active, unsigned hybrid,
                                  int any_hit, struct trace_hit *hits,
                                  struct trace_counters *counters)
{
    active &= (1u << TRACE_PACKET) - 1u;
    unsigned result = 0;
    int packet = active && wide->node_count && wide->width == 4;
#if defined(__AVX__)
    packet |= active && wide->node_count && wide->width == 8;
#endif
    if (!packet) {
        /* A layout this table does not walk: ray by ray (walk_wide
         * takes the binary walk). */
        for (unsigned m = active; m; m &= m - 1u) {
            const unsigned r = (unsigned)__builtin_ctz(m);
            if (walk_wide(wide, bvh, tri, &rays[r], t_max[r], any_hit, any_hit ? NULL : &hits[r],
                          counters))
                result |= 1u << r;
        }
        return result;
    }
    struct packet_state p;
    for (unsigned m = active; m; m &= m - 1u) {
        const unsigned r = (unsigned)__builtin_ctz(m);
        struct wide_state *s = &p.s[r];
        const struct trace_ray *ray = &rays[r];
        s->ray = ray;
        tri4_ray_init(&s->r4, ray);
        s->any_hit = any_hit;
        s->hit = any_hit ? NULL : &hits[r];
        s->found = 0;
        s->best = t_max[r];
        s->box_limit = t_max[r] * ISECT_BOX_FAR_SCALE; /* as walk_wide */
        s->node_tests = 0;
        s->triangle_tests = 0;
        int octant = 0;
        for (int k = 0; k < 3; k++) {
            const int neg = signbit(ray->inv_dir[k]) != 0;
            p.near_row[r][k] = neg ? 3 + k : k;
            p.far_row[r][k] = neg ? k : 3 + k;
            octant |= neg << k;
        }
        p.octant[r] = octant;
    }
    unsigned done;
    uint64_t node_tests = 0;
#if defined(__AVX__)
    if (wide->width == 8)
        done = packet_run8(wide, &p, active, hybrid, &node_tests);
    else
#endif
        done = packet_walk4(wide, &p, active, hybrid);
    if (counters)
        counters->node_tests += node_tests;
    for (unsigned m = active; m; m &= m - 1u) {
        const unsigned r = (unsigned)__builtin_ctz(m);
        if (counters) {
            counters->node_tests += p.s[r].node_tests;
            counters->triangle_tests += p.s[r].triangle_tests;
        }
        if (!any_hit && p.s[r].found)
            result |= 1u << r;
    }
    return any_hit ? done : result;
}

unsigned TRACE_PACKET_CLOSEST(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                              const struct trace_ray *rays, const float *t_max, unsigned active,
                              unsigned hybrid, struct trace_hit *hits,
                              struct trace_counters *counters);
unsigned TRACE_PACKET_CLOSEST(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                              const struct trace_ray *rays, const float *t_max, unsigned active,
                              unsigned hybrid, struct trace_hit *hits,
                              struct trace_counters *counters)
{
    return packet_run(wide, bvh, tri, rays, t_max, active, hybrid, 0, hits, counters);
}

unsigned TRACE_PACKET_ANY(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                          const struct trace_ray *rays, const float *t_max, unsigned active,
                          unsigned hybrid, struct trace_counters *counters);
unsigned TRACE_PACKET_ANY(const struct bvh4 *wide, const struct bvh *bvh, const float *tri,
                          const struct trace_ray *rays, const float *t_max, unsigned active,
                          unsigned hybrid, struct trace_counters *counters)
{
    return packet_run(wide, bvh, tri, rays, t_max, active, hybrid, 1, NULL, counters);
}
