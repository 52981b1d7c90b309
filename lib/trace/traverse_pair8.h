/* SPDX-License-Identifier: Apache-2.0 */
/*
 * traverse_pair8.h - a stream of single rays over an 8-wide layout,
 * walked PAIR8_SLOTS at a time: one step of ray A, then one step of ray
 * B, and so on round the slots (a step: one node test with its push or
 * pop and its choice of the next node, or one leaf call), each ray with
 * its own state in a slot of its own (struct pair8_slot); when a ray
 * ends, its slot takes the stream's next ray.  Named for the first form,
 * two slots (the "pair"); eight measured best (below, PAIR8_SLOTS).
 * Included by traverse_wide.h's users after it (the AVX2
 * table, stream_avx2.c), with TRACE_PAIR8_STREAM and
 * TRACE_PAIR8_STREAM_COUNTED defined as the names of kernels.h's
 * stream_pair and stream_counted entries; no include guard.
 *
 * Why: a single ray's walk is a chain of dependent loads (a node's
 * bounds -> its child's bounds -> the leaf's packet), and a random ray
 * of a large mesh waits for about 30 of them from the L3, one after the
 * other (docs/performance-log.md, rounds 54-59); the out-of-order core
 * overlaps the next ray's work only as far as its reorder buffer
 * reaches (256 entries on Zen 3, about an eighth of a soup ray).  Rays
 * stepped in turn give the core the other rays' chains to run while one
 * waits on a miss: asynchronous memory access chaining (Kocberber,
 * Falsafi and Grot 2015, VLDB 9(4)); for hash joins, group and
 * software-pipelined prefetching (Chen, Ailamaki, Gibbons and Mowry
 * 2004).
 *
 * Each ray's walk is walk_wide8_ray_leaf8's from the set-up's lanes
 * (WIDE8_WALK1, traverse_wide8_ray.h) on the AVX2 table: the same node
 * test (isect_box's slabs bit for bit, the entry as a signed integer
 * maximum), the same pushes (wide8_push in the octant's order for
 * closest hit, wide8_push_stored / wide8_push_any for any hit), the same
 * pops against the same limits, the same leaf calls (the 8-lane call for
 * 5-8 triangles, the first-leaf copy at a closest-hit ray's first leaf,
 * the 4-lane call for 1-4) on a state set up as WIDE8_WALK1 sets it, and
 * the same prefetches, with one more (a closest-hit leaf's packet when a
 * node test chooses it, pair8_step), a hint only.  So every ray's node
 * tests, leaf calls and answer are walk1's, by construction; conformance/internal/pair8_stream checks
 * it hit by hit.  Only the order in which the rays' steps run differs,
 * and no step reads another ray's state.
 *
 * The AVX2 table only: the AVX-512 table's walks from the set-up's lanes
 * take the fused node test and the front child by compression, which
 * this file does not copy.
 */

/* One ray's walk between two steps: walk_wide8_ray's locals, kept in
 * memory (the other rays' steps run between two of this one's, and the
 * leaf calls clobber every vector register anyway). */
struct pair8_slot {
    /* The node test's vectors, broadcast once at the ray's start (the
     * same floats walk_wide8_ray broadcasts after each leaf): -org, the
     * inverse direction (memory operands of the multiplications) and
     * tmin's bits for the entry's integer maximum. */
    __m256 neg_org_x, neg_org_y, neg_org_z;
    __m256 inv_x, inv_y, inv_z;
    __m256i tmin8;
    struct wide_ray_state rs; /* the leaves' state; rs.s.ray is &ray */
    struct trace_ray ray;
    /* The six rows' bases, the nodes' array plus the octant's row
     * offsets (walk_wide8_ray's row_nx .. row_fz). */
    const char *row_nx, *row_fx, *row_ny, *row_fy, *row_nz, *row_fz;
    int octant;
    uint32_t index; /* the ray's place in the stream */
    /* An any-hit walk's box limit (it never shrinks: walk_wide8_ray
     * keeps it from s->best); a closest-hit walk reads rs.s.box_limit,
     * which only its leaves change, as walk_wide8_ray reloads it after
     * each leaf. */
    float any_limit;
    int r4_ready;
    uint32_t st_child[WIDE_STACK];
    uint32_t st_count[WIDE_STACK];
    float st_t[WIDE_STACK];
};

/* The rays in flight.  Random rays on a Zen 3 core (rtbench embree,
 * ours/Embree, quads under load; docs/performance-log.md, round 60,
 * zn17): bumpy 1.05 with 2 slots, 1.27 with 4, 1.52 with 8 (walk1:
 * 0.88-0.91); the soup 0.88, 0.92-1.06, 0.87-1.00 (walk1: 0.80-0.82). */
#ifndef PAIR8_SLOTS
#define PAIR8_SLOTS 8
#endif

/* The slot's current entry and stack pointer, apart from the slot: the
 * stream's locals (pair8_stream): with two slots, each stepped by its
 * own inlined copy, the compiler kept them in registers (the slot's address
 * escapes to the leaf calls, these do not); with more slots and one
 * copy of the step they live in memory, as the slot does. */
struct pair8_walk {
    uint32_t cur;
    uint32_t cur_count;
    uint32_t sp;
};

/* The counted streams' (stats 1) node and triangle tests of a slot's ray
 * so far, as walk1_counted counts them (traverse_wide8_ray.h: eight a
 * node test, a leaf's triangles at its call).  Apart from struct
 * pair8_walk, in an array of their own that the streams without
 * counters never touch: with the counts inside it those streams' code
 * changed (GCC allocated the closest-hit copies' registers otherwise). */
struct pair8_counts {
    uint32_t node_tests;
    uint32_t tri_tests;
};

/* The ray at r (RTray's layout: org[3], tmin, dir[3], tmax) into slot q,
 * as WIDE8_WALK1 starts its walk: the set-up in the slot's frame, the
 * state as wide_state_init1 leaves it, the node test's -org (closest
 * hit) or the leaves' scalar constants (any hit), the octant's rows.
 * hit: where a closest-hit walk's leaves write its hit.  The caller has
 * sent a ray with tmin not >= 0 to walk1 instead (its float walk). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void pair8_start(const struct bvh4 *wide, struct pair8_slot *q,
                               struct pair8_walk *w, const float *r, uint32_t index,
                               struct trace_hit *hit, int any_hit)
{
    struct ray_lanes lanes;
    trace_ray_setup_lanes(&q->ray, &lanes, r, r + 4, r[3]);
    struct wide_state *const s = &q->rs.s;
    wide_state_init1(s, &q->ray, r[7], any_hit != 0, 0, hit);
    if (any_hit)
        tri4_ray_init_scalar_lanes(&s->r4, &lanes, r[3]);
    else
        tri4_ray_init_node_org(&s->r4, &lanes, r[3]);
    const int octant = _mm_movemask_ps(lanes.dir) & 7;
    const uint8_t *rows = wide8_rows[octant];
    const char *const node_base = (const char *)(const void *)wide->nodes8;
    q->row_nx = node_base + rows[0];
    q->row_ny = node_base + rows[1];
    q->row_nz = node_base + rows[2];
    q->row_fx = node_base + rows[3];
    q->row_fy = node_base + rows[4];
    q->row_fz = node_base + rows[5];
    q->octant = octant;
    q->index = index;
    w->sp = 0;
    w->cur = 0;
    w->cur_count = 0;
    q->neg_org_x = _mm256_broadcast_ss(&s->r4.node_neg_org[0]);
    q->neg_org_y = _mm256_broadcast_ss(&s->r4.node_neg_org[1]);
    q->neg_org_z = _mm256_broadcast_ss(&s->r4.node_neg_org[2]);
    q->inv_x = _mm256_broadcast_ss(&q->ray.inv_dir[0]);
    q->inv_y = _mm256_broadcast_ss(&q->ray.inv_dir[1]);
    q->inv_z = _mm256_broadcast_ss(&q->ray.inv_dir[2]);
    q->tmin8 = _mm256_max_epi32(_mm256_castps_si256(_mm256_broadcast_ss(&q->ray.tmin)),
                                _mm256_setzero_si256());
    q->any_limit = s->best * ISECT_BOX_FAR_SCALE;
    q->r4_ready = 0;
}

/* walk_wide8_ray's prefetch of the stack's top entry (its lines, a
 * packet's or a node's), for a walk with prefetch_top: sp entries on
 * slot q's stack, at least one. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void pair8_prefetch_top(const struct pair8_slot *q, uint32_t sp,
                                      const struct bvh8_node *nodes,
                                      const struct tri4_packet *packets)
{
    const uint32_t top = q->st_child[sp - 1];
    const char *a = q->st_count[sp - 1] ? (const char *)&packets[top] : (const char *)&nodes[top];
    WIDE_PREFETCH_LINES(a, 3);
}

/* walk_wide8_ray's pop: the stack's entries from sp down, those a
 * closest-hit walk's limit has passed skipped, the first one left made
 * slot q's current entry (returns 1); or, with the stack empty, the walk
 * ended with *answer walk1's (returns 0). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int pair8_pop(struct pair8_slot *q, struct pair8_walk *w, uint32_t sp,
                            float node_limit, int any_hit, int *answer)
{
    for (;;) {
        if (sp == 0) {
            *answer = any_hit ? 0 : q->rs.s.found;
            return 0;
        }
        sp--;
        if (any_hit || q->st_t[sp] <= node_limit)
            break;
    }
    w->sp = sp;
    w->cur = q->st_child[sp];
    w->cur_count = q->st_count[sp];
    return 1;
}

/* wide8_push (the closest-hit push in the octant's order, through
 * wide8_push_order) with the stack's new top entry also returned, in *top and *top_count, from the
 * node: the child second in the order among the hit ones, which the push
 * stores last.  The prefetch of the top (pair8_prefetch_top) read it back
 * from the stack, a 4-byte load from the 32-byte store just made; from
 * the node it is the same entry, so the same lines, without waiting on
 * the store. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void pair8_push(const struct bvh8_node *n, int octant, __m256 hit, __m256 t0,
                              uint32_t *st_child, uint32_t *st_count, float *st_t,
                              uint32_t *sp, uint32_t *cur, uint32_t *cur_count, uint32_t *top,
                              uint32_t *top_count)
{
    const __m256i order_shift = _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21);
    uint32_t order;
    const unsigned pm = wide8_push_order(n, octant, hit, t0, order_shift, st_child, st_count,
                                         st_t, sp, cur, cur_count, &order);
    /* pm has two bits at least (the caller's mask did). */
    const unsigned l2 = order >> (3 * (unsigned)__builtin_ctz(pm & (pm - 1u))) & 7u;
    *top = n->child[l2];
    *top_count = n->count[l2];
}

/* One step of slot q's walk: a node test (with its push or pop) when its
 * current entry is a node, else the leaf's call and the pop after it.
 * Returns 1 while the walk goes on; 0 when it has ended, with *answer
 * walk1's (any hit: occluded; closest hit: found, the hit in *rs.s.hit). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int pair8_step(const struct bvh8_node *nodes, const struct tri4_packet *packets,
                             struct pair8_slot *q, struct pair8_walk *w, int any_hit,
                             int leave_early, int stats, struct pair8_counts *c, int *answer)
{
    struct wide_state *const s = &q->rs.s;
    /* As walk_wide8_ray: the stack top's prefetch only in closest-hit
     * walks over a layout with prefetch_top (leave_early). */
    const int prefetch_top = !any_hit && leave_early;
    uint32_t sp = w->sp;
    if (!w->cur_count) {
        const float node_limit = any_hit ? q->any_limit : s->box_limit;
        const uint32_t cur = w->cur;
        const size_t node_off = (size_t)cur * sizeof(nodes[0]);
        const struct bvh8_node *const n = &nodes[cur];
        const __m256 neg_org_x = q->neg_org_x, neg_org_y = q->neg_org_y,
                     neg_org_z = q->neg_org_z;
        const __m256 inv_x = q->inv_x, inv_y = q->inv_y, inv_z = q->inv_z;
        const __m256i tmin8 = q->tmin8;
        if (stats)
            c->node_tests += 8;
        /* walk_wide8_ray's node test, operation for operation. */
        const __m256 tnx =
            _mm256_mul_ps(_mm256_add_ps(neg_org_x, wide8_bound(q->row_nx, node_off)), inv_x);
        const __m256 tfx =
            _mm256_mul_ps(_mm256_add_ps(neg_org_x, wide8_bound(q->row_fx, node_off)), inv_x);
        const __m256 tny =
            _mm256_mul_ps(_mm256_add_ps(neg_org_y, wide8_bound(q->row_ny, node_off)), inv_y);
        const __m256 tfy =
            _mm256_mul_ps(_mm256_add_ps(neg_org_y, wide8_bound(q->row_fy, node_off)), inv_y);
        const __m256 tnz =
            _mm256_mul_ps(_mm256_add_ps(neg_org_z, wide8_bound(q->row_nz, node_off)), inv_z);
        const __m256 tfz =
            _mm256_mul_ps(_mm256_add_ps(neg_org_z, wide8_bound(q->row_fz, node_off)), inv_z);
        const __m256 t0 = _mm256_castsi256_ps(_mm256_max_epi32(
            _mm256_max_epi32(_mm256_castps_si256(tnx), _mm256_castps_si256(tny)),
            _mm256_max_epi32(_mm256_castps_si256(tnz), tmin8)));
        const __m256 scale = _mm256_set1_ps(ISECT_BOX_FAR_SCALE);
        const __m256 exit_x = _mm256_mul_ps(tfx, scale);
        const __m256 exit_y = _mm256_mul_ps(tfy, scale);
        const __m256 exit_z = _mm256_mul_ps(tfz, scale);
        const __m256 hit = _mm256_and_ps(
            _mm256_and_ps(_mm256_cmp_ps(t0, _mm256_set1_ps(node_limit), _CMP_LE_OQ),
                          _mm256_cmp_ps(t0, exit_x, _CMP_NGT_UQ)),
            _mm256_and_ps(_mm256_cmp_ps(t0, exit_y, _CMP_NGT_UQ),
                          _mm256_cmp_ps(t0, exit_z, _CMP_NGT_UQ)));
        const unsigned mask = (unsigned)_mm256_movemask_ps(hit);
        if (mask) {
            uint32_t next, next_count;
            if (!(mask & (mask - 1u))) {
                const unsigned l = (unsigned)__builtin_ctz(mask);
                next = n->child[l];
                next_count = n->count[l];
            } else {
                if (any_hit == WIDE_ANY_LONGEST) {
                    const __m256 t1 = _mm256_min_ps(
                        _mm256_mul_ps(tfz, scale),
                        _mm256_min_ps(_mm256_mul_ps(tfy, scale),
                                      _mm256_min_ps(_mm256_mul_ps(tfx, scale),
                                                    _mm256_set1_ps(node_limit))));
                    wide8_push_any(n, mask, hit, t0, t1, q->st_child, q->st_count, &sp, &next,
                                   &next_count);
                } else if (any_hit) {
                    wide8_push_stored(n, mask, t0, q->st_child, q->st_count, &sp, &next,
                                      &next_count);
                } else {
                    uint32_t top, top_count;
                    pair8_push(n, q->octant, hit, t0, q->st_child, q->st_count, q->st_t, &sp,
                               &next, &next_count, &top, &top_count);
                    if (prefetch_top) {
                        const char *a = top_count ? (const char *)&packets[top]
                                                  : (const char *)&nodes[top];
                        WIDE_PREFETCH_LINES(a, 3);
                    }
                }
                w->sp = sp;
                /* The any-hit walks do not prefetch the top (prefetch_top
                 * is 0 for them). */
            }
            w->cur = next;
            w->cur_count = next_count;
            if (!any_hit && !next_count)
                WIDE_PREFETCH_LINES((const char *)&nodes[next], 4);
            /* A leaf chosen here is tested at the slot's next turn, after
             * the other slots' steps: its packet's lines requested now
             * (walk_wide8_ray, which tests it at once, does not), so that
             * their load overlaps those steps.  A hint only. */
            if (!any_hit && next_count) {
                const char *a = (const char *)&packets[next];
                WIDE_PREFETCH_LINES(a, 3);
                if (next_count > 4)
                    WIDE_PREFETCH_LINES(a + 192, 3);
            }
            return 1;
        }
        /* Pop (walk_wide8_ray's pop after a node: no prefetch). */
        return pair8_pop(q, w, sp, node_limit, any_hit, answer);
    }
    /* The leaf (walk_wide8_ray's, WIDE8_RAY_LEAF8 1). */
    {
        int stop;
        const uint32_t cur_count = w->cur_count;
        const struct tri4_packet *p = &packets[w->cur];
        const int first_leaf = !any_hit && !q->r4_ready;
        if (stats)
            c->tri_tests += cur_count;
        if (first_leaf) {
            tri4_ray_init_vec(&s->r4, &q->ray);
            tri4_ray_init_double(wide_ray_doubles(s), &q->ray);
            q->r4_ready = 1;
        }
        if (cur_count > 4) {
            if (any_hit)
                stop = wide8_leaf8_any(s, p, cur_count);
            else if (leave_early)
                stop = first_leaf ? wide8_leaf8_closest_first(s, p, cur_count)
                                  : wide8_leaf8_closest(s, p, cur_count);
            else
                stop = first_leaf ? wide8_leaf8_full_first(s, p, cur_count)
                                  : wide8_leaf8_full(s, p, cur_count);
        } else {
            if (any_hit)
                stop = wide8_packet_any(s, p, cur_count);
            else if (leave_early)
                stop = wide8_packet_closest(s, p, cur_count);
            else
                stop = wide8_packet_full(s, p, cur_count);
        }
        if (stop) {
            *answer = any_hit ? 1 : s->found;
            return 0;
        }
    }
    if (!pair8_pop(q, w, sp, any_hit ? q->any_limit : s->box_limit, any_hit, answer))
        return 0;
    /* walk_wide8_ray's WIDE8_PREFETCH_NEXT_TOP. */
    if (prefetch_top && w->sp)
        pair8_prefetch_top(q, w->sp, nodes, packets);
    return 1;
}

/* The stream's rays: ray i at rays + i * stride floats, in RTray's
 * layout (org[3], tmin, dir[3], tmax). */
#define PAIR8_RAY(rays, stride, i) ((rays) + (size_t)(i) * (stride))

/* The stream's next ray into slot q (a ray with tmin not >= 0 taken by
 * walk1 right away, as WIDE8_WALK1 sends it to its float walk).
 * Returns 0 when the stream has no ray left. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int pair8_refill(const struct bvh4 *wide, struct pair8_slot *q,
                               struct pair8_walk *w, uint32_t *next, const float *rays,
                               size_t stride, uint32_t count, struct trace_hit *hits,
                               unsigned char *got, trace_walk1_fn walk1, int any_hit, int stats,
                               struct pair8_counts *pc, struct trace_counters *counters,
                               uint32_t *ray_nodes)
{
    while (*next < count) {
        const uint32_t i = (*next)++;
        const float *r = PAIR8_RAY(rays, stride, i);
        if (r[3] >= 0.0f) {
            pair8_start(wide, q, w, r, i, any_hit ? NULL : &hits[i], any_hit);
            if (stats) {
                pc->node_tests = 0;
                pc->tri_tests = 0;
            }
            return 1;
        }
        if (stats) {
            /* walk1 is then the counting walk (walk1_counted's), which
             * adds to the counters it is given. */
            struct trace_counters c = {0, 0};
            got[i] = (unsigned char)walk1(wide, r, r + 4, r[3], r[7], any_hit ? NULL : &hits[i],
                                          &c);
            counters->node_tests += c.node_tests;
            counters->triangle_tests += c.triangle_tests;
            ray_nodes[i] = (uint32_t)c.node_tests;
            continue;
        }
        got[i] = (unsigned char)walk1(wide, r, r + 4, r[3], r[7], any_hit ? NULL : &hits[i],
                                      NULL);
    }
    return 0;
}

/* Slot q's turn: one step, and when its ray ends, the answer written and
 * the stream's next ray started in the slot (pair8_refill).  Returns 0
 * when the slot has no ray left. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int pair8_turn(const struct bvh4 *wide, const struct bvh8_node *nodes,
                             const struct tri4_packet *packets, struct pair8_slot *q,
                             struct pair8_walk *w, uint32_t *next,
                             const float *rays, size_t stride, uint32_t count,
                             struct trace_hit *hits, unsigned char *got, trace_walk1_fn walk1,
                             int any_hit, int leave_early, int stats, struct pair8_counts *pc,
                             struct trace_counters *counters, uint32_t *ray_nodes)
{
    int answer;
    if (pair8_step(nodes, packets, q, w, any_hit, leave_early, stats, pc, &answer))
        return 1;
    got[q->index] = (unsigned char)answer;
    if (stats) {
        counters->node_tests += pc->node_tests;
        counters->triangle_tests += pc->tri_tests;
        ray_nodes[q->index] = pc->node_tests;
    }
    return pair8_refill(wide, q, w, next, rays, stride, count, hits, got, walk1, any_hit, stats,
                        pc, counters, ray_nodes);
}

/* The whole stream, the slots stepped in turn; when the stream runs dry
 * the rays still in flight end one after the other.  One copy of the
 * step for all slots: a copy per slot (four, unrolled) was level on the
 * clock (bumpy random 1.27 both, the soup 0.92 / 1.06, one quad). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void pair8_stream(const struct bvh4 *wide, const float *rays, size_t stride,
                                uint32_t count, struct trace_hit *hits, unsigned char *got,
                                trace_walk1_fn walk1, int any_hit, int leave_early, int stats,
                                struct trace_counters *counters, uint32_t *ray_nodes)
{
    struct pair8_slot slot[PAIR8_SLOTS];
    struct pair8_walk walk[PAIR8_SLOTS];
    /* Only the counted streams use it (stats a constant 1). */
    struct pair8_counts counts[PAIR8_SLOTS];
    /* The arrays' bases read once here: in the step, read through wide,
     * they were reloaded every step (the leaf calls between). */
    const struct bvh8_node *const nodes = wide->nodes8;
    const struct tri4_packet *const packets = wide->packets;
    uint32_t next = 0;
    int live[PAIR8_SLOTS];
    int dry = 0;
    for (int k = 0; k < PAIR8_SLOTS; k++) {
        live[k] = pair8_refill(wide, &slot[k], &walk[k], &next, rays, stride, count, hits, got,
                               walk1, any_hit, stats, &counts[k], counters, ray_nodes);
        dry |= !live[k];
    }
    /* live[k] written only when slot k's turn finds the stream dry: as
     * `live[k] = turn(...)` it was a store every step (GCC kept the array
     * in memory). */
    while (!dry)
        for (int k = 0; k < PAIR8_SLOTS; k++)
            if (!pair8_turn(wide, nodes, packets, &slot[k], &walk[k], &next, rays, stride,
                            count, hits, got, walk1, any_hit, leave_early, stats, &counts[k],
                            counters, ray_nodes)) {
                live[k] = 0;
                dry = 1;
            }
    for (int k = 0; k < PAIR8_SLOTS; k++)
        while (live[k])
            live[k] = pair8_turn(wide, nodes, packets, &slot[k], &walk[k], &next, rays, stride,
                                 count, hits, got, walk1, any_hit, leave_early, stats, &counts[k],
                                 counters, ray_nodes);
}
#undef PAIR8_RAY

#define PAIR8_STREAM(name, walk1, any_hit, leave_early)                                         \
    static void name(const struct bvh4 *wide, const float *rays, size_t stride, uint32_t count,  \
                     struct trace_hit *hits, unsigned char *got) WIDE_NOINLINE;                 \
    static void name(const struct bvh4 *wide, const float *rays, size_t stride, uint32_t count,  \
                     struct trace_hit *hits, unsigned char *got)                                \
    {                                                                                           \
        pair8_stream(wide, rays, stride, count, hits, got, walk1, any_hit, leave_early, 0, NULL, \
                     NULL);                                                                     \
    }

PAIR8_STREAM(pair8_stream_closest, wide8_walk1_closest_leaf8, 0, 0)
PAIR8_STREAM(pair8_stream_closest_early, wide8_walk1_closest_early_leaf8, 0, 1)
PAIR8_STREAM(pair8_stream_any, wide8_walk1_any_leaf8, 1, 1)
PAIR8_STREAM(pair8_stream_any_longest, wide8_walk1_any_longest_leaf8, WIDE_ANY_LONGEST, 1)
#undef PAIR8_STREAM

/* The counted streams (kernels.h's stream_counted): the same walks with
 * walk1_counted's counts, per ray and in total; a ray the stream sends
 * to walk1 goes to the counting walk1 (the _stats copy). */
#define PAIR8_STREAM_COUNTED(name, walk1, any_hit, leave_early)                                 \
    static void name(const struct bvh4 *wide, const float *rays, size_t stride, uint32_t count,  \
                     struct trace_hit *hits, unsigned char *got,                                \
                     struct trace_counters *counters, uint32_t *ray_nodes) WIDE_NOINLINE;       \
    static void name(const struct bvh4 *wide, const float *rays, size_t stride, uint32_t count,  \
                     struct trace_hit *hits, unsigned char *got,                                \
                     struct trace_counters *counters, uint32_t *ray_nodes)                      \
    {                                                                                           \
        pair8_stream(wide, rays, stride, count, hits, got, walk1, any_hit, leave_early, 1,      \
                     counters, ray_nodes);                                                      \
    }

PAIR8_STREAM_COUNTED(pair8_counted_closest, wide8_walk1_closest_leaf8_stats, 0, 0)
PAIR8_STREAM_COUNTED(pair8_counted_closest_early, wide8_walk1_closest_early_leaf8_stats, 0, 1)
PAIR8_STREAM_COUNTED(pair8_counted_any, wide8_walk1_any_leaf8_stats, 1, 1)
PAIR8_STREAM_COUNTED(pair8_counted_any_longest, wide8_walk1_any_longest_leaf8_stats,
                     WIDE_ANY_LONGEST, 1)
#undef PAIR8_STREAM_COUNTED

/* kernels.h's stream_pair: the stream walk for the layout walk1 walks
 * (TRACE_WIDE_WALK1's choice), NULL where walk1 is. */
static trace_stream1_fn TRACE_PAIR8_STREAM(const struct bvh4 *wide, int any_hit)
{
    if (wide->width != 8 || !wide->node_count)
        return NULL;
    if (any_hit)
        return wide->any_longest ? pair8_stream_any_longest : pair8_stream_any;
    return wide->prefetch_top ? pair8_stream_closest_early : pair8_stream_closest;
}

/* kernels.h's stream_counted: the counted stream for the same layouts. */
static trace_stream1_counted_fn TRACE_PAIR8_STREAM_COUNTED(const struct bvh4 *wide, int any_hit)
{
    if (wide->width != 8 || !wide->node_count)
        return NULL;
    if (any_hit)
        return wide->any_longest ? pair8_counted_any_longest : pair8_counted_any;
    return wide->prefetch_top ? pair8_counted_closest_early : pair8_counted_closest;
}
