/* SPDX-License-Identifier: Apache-2.0 */
/*
 * traverse_wide8_ray.h - the single-ray 8-wide walk's body (traverse_wide.h,
 * before WIDE8_LEAF_TEST, says how it is arranged), included twice by
 * traverse_wide.h: as walk_wide8_ray with WIDE8_RAY_LEAF8 0 (a leaf of
 * two packets is two 4-lane calls) and as walk_wide8_ray_leaf8 with
 * WIDE8_RAY_LEAF8 1 (one 8-lane call, wide8_leaf8_*).  Two copies of the
 * text rather than a flag of one inline function: with a flag, the walks
 * without the 8-lane call compiled to different code (register allocation
 * and block order; the soup's primary rays were 0.05 of Embree slower),
 * although the flag was a constant 0 in them.  Define WIDE8_RAY,
 * WIDE8_RAY_LEAF8 and WIDE8_RAY_COMPRESS before including; no include
 * guard.  lanes: the ray's set-up in SSE lanes where the walk's caller
 * made it (WIDE8_WALK1), else NULL (the walk reads the struct).
 * WIDE8_RAY_COMPRESS: 1 for the walks
 * whose front child the AVX-512 table may take by compression (by_off
 * below), 0 for the AVX-512 table's copy that takes it by the trailing-zero
 * count as the AVX2 table does (walk_wide8_ray_leaf8_ctz, traverse_wide.h).
 */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int WIDE8_RAY(const struct bvh4 *wide, struct wide_state *s, int any_hit, int stats,
                            int leave_early, const struct ray_lanes *lanes)
{
    const struct trace_ray *ray = s->ray;
    const struct bvh8_node *nodes = wide->nodes8;
    const struct tri4_packet *packets = wide->packets;
    size_t near_x, near_y, near_z, far_x, far_y, far_z;
    int octant = 0;
    if (lanes) {
        /* The set-up's lanes (WIDE8_WALK1): the octant from the signs of
         * dir, which are those of 1 / dir (-0 gives -inf), so the rows
         * do not wait for the division and the first node's loads can
         * start before it ends; the six row offsets from a table by
         * octant (wide8_rows), six loads instead of about 30
         * instructions of arithmetic and register moves. */
        octant = _mm_movemask_ps(lanes->dir) & 7;
        const uint8_t *r = wide8_rows[octant];
        near_x = r[0];
        near_y = r[1];
        near_z = r[2];
        far_x = r[3];
        far_y = r[4];
        far_z = r[5];
    } else {
        /* Row k is min k, row 3 + k max k; a negative direction (-0
         * too) has its near plane at the max.  By arithmetic on the sign
         * bits: near + far = 2k + 3 rows. */
        const size_t row = sizeof(nodes[0].bounds[0]);
        uint32_t bits[3];
        memcpy(bits, ray->inv_dir, sizeof(bits));
        const size_t nx = bits[0] >> 31, ny = bits[1] >> 31, nz = bits[2] >> 31;
        near_x = nx * 3 * row;
        far_x = 3 * row - near_x;
        near_y = (1 + ny * 3) * row;
        far_y = 5 * row - near_y;
        near_z = (2 + nz * 3) * row;
        far_z = 7 * row - near_z;
        octant = (int)(nx | ny << 1 | nz << 2);
    }
    /* A walk from the set-up's lanes (any-hit and closest-hit alike) addresses a
     * node's six rows from six bases, the nodes' array plus each row's offset,
     * and the node's byte offset: base + offset is one address operand of the
     * bound's load, where nodes + cur * 256 + row needed an addition before the
     * loads, one step more on the chain from a node's child word to its bounds,
     * which every node of a walk waits for.  The same addresses, so the same
     * bounds. */
    const char *const node_base = (const char *)(const void *)nodes;
    const char *row_nx = node_base + near_x, *row_fx = node_base + far_x;
    const char *row_ny = node_base + near_y, *row_fy = node_base + far_y;
    const char *row_nz = node_base + near_z, *row_fz = node_base + far_z;
#if defined(__GNUC__)
    /* Opaque values: without the asm GCC keeps the row offsets in stack
     * slots and adds the array's start to each again after every leaf
     * (six loads and six additions a re-broadcast, where it now reloads
     * three or four of the bases as it reloaded the offsets). */
    if (lanes)
        __asm__("" : "+r"(row_nx), "+r"(row_fx), "+r"(row_ny), "+r"(row_fy), "+r"(row_nz),
                "+r"(row_fz));
#endif
    const __m256i order_shift = _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21);
    uint32_t st_child[WIDE_STACK];
    uint32_t st_count[WIDE_STACK];
    float st_t[WIDE_STACK];
    uint32_t sp = 0;
    uint32_t cur = 0;
    uint32_t cur_count = 0;
    /* AVX-512, from the set-up's lanes, a walk whose front child comes by
     * compression (wide8_front_compress, wide8_push_compress): the child
     * as its byte offset in the nodes' array (cur * 256), which the
     * compression gives directly, so that the next node's bounds wait for
     * no shift after it; the leaf's packet index is cur_off >> 8, and a
     * pop sets both.  The shift is within 32-bit lanes (wide8_child_offsets):
     * WIDE8_WALK1, this walk's only caller with lanes, sends a layout with
     * 2^24 nodes or packets or more to the float walk.  Elsewhere cur alone
     * (cur_off's stores are dead). */
#if TRACE_AVX512_TABLE
    const int by_off = WIDE8_RAY_COMPRESS && (any_hit == 0 || any_hit == 1) && lanes;
#else
    const int by_off = 0;
#endif
    size_t cur_off = 0;
    /* The AVX-512 table's walks from the set-up's lanes with any_hit 0
     * or 1 test a node by node_fused.h's fused test (one fma a slab, the
     * far distances widened by the fma's own constants), which passes
     * every box isect_box passes (node_fused.h proves it; the answers are
     * then the same, the visits a few more); WIDE8_WALK1 set its
     * constants, or sent the ray to the float walk when they do not
     * cover it.  The other walks, and every walk of the AVX2 table, keep
     * isect_box's slabs bit for bit: on the AVX2 table the fused walk's
     * twelve constant vectors do not fit beside the walk's own in 16
     * registers (five spilled, stored again after every leaf), and on a
     * Zen 3 core the AVX2 walks with isect_box's slabs ran 7.6 % fewer
     * instructions (gears, closest hit) and were ahead on the clock on
     * all four meshes (by 0.05-0.07 of Embree on the kitchen's, gears'
     * and bumpy's camera and random rays), and ahead of the fused test
     * with its addends as memory operands (docs/performance-log.md,
     * round 54, zn1; WIDE8_FUSED). */
    const int fused = WIDE8_FUSED(any_hit) && lanes;
    const struct node_fused *const nf = fused ? wide_ray_fused(s) : NULL;
    /* An any-hit walk's box limit never shrinks (it ends at its first
     * hit): kept here, from s->best = t_max as wide_state_init computes
     * it, and not reloaded after each leaf (wide_state_init1). */
    float box_limit = any_hit ? s->best * ISECT_BOX_FAR_SCALE : s->box_limit;
    /* The limit the node test's entries are compared with, at a node and
     * at a pop: box_limit, or for the fused test box_limit widened
     * (node_fused_limit), set again whenever box_limit is. */
    float node_limit = fused ? node_fused_limit(box_limit) : box_limit;
    uint64_t node_tests = 0;
    uint64_t tri_tests = 0;
    int r4_ready = 0;
    /* Per layout: only a layout beyond the caches pays for the stack
     * top's prefetch (bvh4_layout.h).  A closest-hit walk takes it from
     * its copy: every caller picks the copy with leave_early exactly
     * when the layout has prefetch_top (walk_wide, walk_wide_single,
     * walk_wide_single1, TRACE_WIDE_WALK1, TRACE_WIDE_WALK1_COUNTED), so
     * the small layouts' copy has no test of it at its pushes and pops.
     * The any-hit walks do not prefetch the stack top on any layout: on
     * a Raptor Cove core (2 MB L2) shadow rays were level to faster
     * without it (the kitchen up in pf1's loaded pairs, level to up in
     * the lead's quiet ones; the soup up, bumpy level: performance-log.md,
     * round 45); an any-hit walk ends at its first hit, before most
     * pushed entries are popped, so a prefetch of the top is often a
     * line fetched for nothing. */
    const int prefetch_top = !any_hit && leave_early;
    /* After a closest-hit pop, the entry now on top of the stack is the
     * one that comes after the popped subtree: its lines prefetched here
     * (as a push prefetches its new top), so that an entry pushed below
     * the top, which no push prefetched, is not fetched cold when its
     * turn comes.  A hint only: no value is read from it, so the walk's
     * answers and counts are the same.  Not in the any-hit walks (sr3's
     * measurement: the push's node prefetch cost their shadow rays).
     * Only at the pop after a leaf, not at the node loop's pop after a
     * node none of whose children the ray hits: there it cost the soup's
     * random rays 16 instructions of their 2001 (callgrind, AVX2) and
     * the clock did not miss it (performance-log.md, round 43, rw2). */
#define WIDE8_PREFETCH_NEXT_TOP()                                                                 \
    do {                                                                                          \
        if (!any_hit && prefetch_top && sp) {                                                     \
            const uint32_t next = st_child[sp - 1];                                               \
            const char *a = st_count[sp - 1] ? (const char *)&packets[next]                       \
                                             : (const char *)&nodes[next];                        \
            WIDE_PREFETCH_LINES(a, 3);                                                            \
        }                                                                                         \
    } while (0)
    for (;;) {
        /* A leaf popped after a leaf goes straight to the leaf test: the
         * node test's vectors are broadcast only when an inner node comes
         * next. */
        if (!cur_count) {
            /* The ray's vectors, broadcast again after each leaf call from
             * the ray (which the call may in principle have changed, so the
             * compiler reloads it anyway) instead of spilled and reloaded
             * around it. */
#if defined(__GNUC__)
            /* GCC sees that the packet call leaves the ray alone and keeps
             * these vectors across it, spilling and reloading eight of them
             * around every leaf; an any-hit walk (about three leaf visits per
             * shadow ray) loads them again instead.  The empty asm hides
             * nothing but the pointer's provenance, on a copy: with the
             * asm on the pointer itself GCC also put a vzeroupper before
             * every 4-lane leaf call (callgrind, AVX2: 3.1 instructions a
             * gears shadow ray more); either way it stores the pointer to
             * its stack slot again at every leaf.  An any-hit walk from
             * the set-up's lanes, whose ray and -org copy are this
             * frame's own (WIDE8_WALK1), has a compiler barrier here
             * instead: the floats are loaded again from their stack
             * slots, without the two pointers the asm made GCC keep in
             * stack slots of their own (callgrind, AVX2: 9 instructions
             * a gears shadow ray fewer).  The same loads of the same
             * floats, so the same vectors. */
            const struct trace_ray *rv = ray;
            if (any_hit && lanes)
                __asm__ volatile("" ::: "memory");
            else if (any_hit)
                __asm__("" : "+r"(rv));
#else
            const struct trace_ray *rv = ray;
#endif
            /* The origin negated: bound + (-org) is bound - org bit for bit
             * (IEEE 754's x - y is x + (-y)), and the addition takes the
             * bound as its memory operand (the subtraction cannot, the bound
             * being its minuend): six loads fewer per node. */
            /* A walk from the set-up's lanes (WIDE8_WALK1, any-hit and
             * closest-hit alike) reads -org as the set-up stored it
             * negated (tri4_ray's node_neg_org: the same floats, -org by
             * the sign bit as C's unary minus): a broadcast from memory
             * each, loaded again after each leaf call (the leaf takes s;
             * the barrier above) instead of kept across it, where the
             * ray's org took a load, a sign flip and a register
             * broadcast each time. */
            const float *no = NULL;
            if (lanes)
                no = s->r4.node_neg_org;
            /* The fused test's near constants in their place
             * (node_fused.h), with its far inverses and constants. */
            if (fused)
                no = nf->near_c;
            const __m256 neg_org_x =
                lanes ? _mm256_broadcast_ss(&no[0]) : _mm256_set1_ps(-rv->org[0]);
            const __m256 neg_org_y =
                lanes ? _mm256_broadcast_ss(&no[1]) : _mm256_set1_ps(-rv->org[1]);
            const __m256 neg_org_z =
                lanes ? _mm256_broadcast_ss(&no[2]) : _mm256_set1_ps(-rv->org[2]);
            const __m256 inv_s_x = fused ? _mm256_broadcast_ss(&nf->inv_s[0]) : neg_org_x;
            const __m256 inv_s_y = fused ? _mm256_broadcast_ss(&nf->inv_s[1]) : neg_org_y;
            const __m256 inv_s_z = fused ? _mm256_broadcast_ss(&nf->inv_s[2]) : neg_org_z;
            const __m256 far_c_x = fused ? _mm256_broadcast_ss(&nf->far_c[0]) : neg_org_x;
            const __m256 far_c_y = fused ? _mm256_broadcast_ss(&nf->far_c[1]) : neg_org_y;
            const __m256 far_c_z = fused ? _mm256_broadcast_ss(&nf->far_c[2]) : neg_org_z;
            const __m256 inv_x = _mm256_set1_ps(rv->inv_dir[0]);
            const __m256 inv_y = _mm256_set1_ps(rv->inv_dir[1]);
            const __m256 inv_z = _mm256_set1_ps(rv->inv_dir[2]);
            /* tmin's bits for the entry's integer maximum (below): only
             * rays with tmin >= 0 come here (the others take
             * wide8_walk_tmin_other), and -0 becomes +0, the same number. */
            const __m256i tmin8 = _mm256_max_epi32(
                _mm256_castps_si256(_mm256_set1_ps(rv->tmin)), _mm256_setzero_si256());
            /* Inner nodes until a leaf lane comes up (or the stack empties). */
            while (!cur_count) {
                const size_t node_off = by_off ? cur_off : (size_t)cur * sizeof(nodes[0]);
                const struct bvh8_node *n =
                    by_off ? (const struct bvh8_node *)(const void *)(node_base + node_off)
                           : &nodes[cur];
                const char *b = (const char *)(const void *)n->bounds;
                if (stats)
                    node_tests += 8;
                /* isect_box's slabs, bit for bit: (bound - org) * inv per
                 * plane.  Its entry max(z, max(y, max(x, tmin))) and exit
                 * min(z, min(y, min(x, inf))) * scale, clamped to
                 * box_limit, are four and five dependent operations of 4
                 * cycles each, which every node's choice of child waits
                 * for (perf, AVX-512: the samples sit on the movemask and
                 * the branch after that chain).  The same decision in
                 * fewer steps:
                 * - the entry as a signed integer maximum (1 cycle):
                 *   with tmin >= +0 the maximum is >= +0, where the
                 *   integer order of the bits is the float order, and
                 *   every negative float, and the NaN of 0 * inf (an
                 *   origin on a plane of a zero direction; x86's default
                 *   NaN has the sign bit set), is a negative integer that
                 *   loses, as isect_box's `a > b ? a : b` skips a NaN.
                 *   Bounds are never NaN (bvh_build.h's contract), so
                 *   no other NaN arises; a -0 entry may come out +0, the
                 *   same number for every comparison made with it;
                 * - entry <= min(s * min(far x, y, z), limit) as four
                 *   comparisons ANDed: rounding s * t is monotonic, so
                 *   s * min(a, b) = min(s * a, s * b), and entry <= min
                 *   holds when it holds against each; a far NaN (skipped
                 *   by the exit's fold, the inf taking its place) passes
                 *   its comparison as unordered (!(entry > far)). */
#define WIDE8_ROW_BOUND(row, off)                                                                 \
    (lanes ? wide8_bound(row, node_off) : wide8_bound(b, off))
                __m256 tnx, tfx, tny, tfy, tnz, tfz;
                if (fused) {
                    /* node_fused.h: near fma(b, i, cn), far fma(b, is, cf),
                     * the far already widened (no scale below). */
                    tnx = _mm256_fmadd_ps(WIDE8_ROW_BOUND(row_nx, near_x), inv_x, neg_org_x);
                    tfx = _mm256_fmadd_ps(WIDE8_ROW_BOUND(row_fx, far_x), inv_s_x, far_c_x);
                    tny = _mm256_fmadd_ps(WIDE8_ROW_BOUND(row_ny, near_y), inv_y, neg_org_y);
                    tfy = _mm256_fmadd_ps(WIDE8_ROW_BOUND(row_fy, far_y), inv_s_y, far_c_y);
                    tnz = _mm256_fmadd_ps(WIDE8_ROW_BOUND(row_nz, near_z), inv_z, neg_org_z);
                    tfz = _mm256_fmadd_ps(WIDE8_ROW_BOUND(row_fz, far_z), inv_s_z, far_c_z);
                } else {
                    tnx = _mm256_mul_ps(_mm256_add_ps(neg_org_x, WIDE8_ROW_BOUND(row_nx, near_x)),
                                        inv_x);
                    tfx = _mm256_mul_ps(_mm256_add_ps(neg_org_x, WIDE8_ROW_BOUND(row_fx, far_x)),
                                        inv_x);
                    tny = _mm256_mul_ps(_mm256_add_ps(neg_org_y, WIDE8_ROW_BOUND(row_ny, near_y)),
                                        inv_y);
                    tfy = _mm256_mul_ps(_mm256_add_ps(neg_org_y, WIDE8_ROW_BOUND(row_fy, far_y)),
                                        inv_y);
                    tnz = _mm256_mul_ps(_mm256_add_ps(neg_org_z, WIDE8_ROW_BOUND(row_nz, near_z)),
                                        inv_z);
                    tfz = _mm256_mul_ps(_mm256_add_ps(neg_org_z, WIDE8_ROW_BOUND(row_fz, far_z)),
                                        inv_z);
                }
#undef WIDE8_ROW_BOUND
                const __m256 t0 = _mm256_castsi256_ps(_mm256_max_epi32(
                    _mm256_max_epi32(_mm256_castps_si256(tnx), _mm256_castps_si256(tny)),
                    _mm256_max_epi32(_mm256_castps_si256(tnz), tmin8)));
                const __m256 scale = _mm256_set1_ps(ISECT_BOX_FAR_SCALE);
                const __m256 exit_x = fused ? tfx : _mm256_mul_ps(tfx, scale);
                const __m256 exit_y = fused ? tfy : _mm256_mul_ps(tfy, scale);
                const __m256 exit_z = fused ? tfz : _mm256_mul_ps(tfz, scale);
#if TRACE_AVX512_TABLE
                /* AVX-512: the four comparisons into mask registers and
                 * ANDed there as a tree (kandb), one kmovb; the lanes as a
                 * vector only where a push needs them.  The empty asm
                 * keeps the four masks apart: without it GCC chains the
                 * compares as masked compares (vcmpps ... %k1{%k1}), four
                 * dependent compares, which was no faster than the
                 * vector form below. */
                __mmask8 k0 = _mm256_cmp_ps_mask(t0, _mm256_set1_ps(node_limit), _CMP_LE_OQ);
                __mmask8 k1 = _mm256_cmp_ps_mask(t0, exit_x, _CMP_NGT_UQ);
                __mmask8 k2 = _mm256_cmp_ps_mask(t0, exit_y, _CMP_NGT_UQ);
                __mmask8 k3 = _mm256_cmp_ps_mask(t0, exit_z, _CMP_NGT_UQ);
#if defined(__GNUC__)
                __asm__("" : "+k"(k0), "+k"(k1), "+k"(k2), "+k"(k3));
#endif
                const unsigned mask =
                    (unsigned)_kand_mask8(_kand_mask8(k0, k1), _kand_mask8(k2, k3));
                const __m256 hit = _mm256_castsi256_ps(_mm256_movm_epi32((__mmask8)mask));
#else
                const __m256 hit = _mm256_and_ps(
                    _mm256_and_ps(_mm256_cmp_ps(t0, _mm256_set1_ps(node_limit), _CMP_LE_OQ),
                                  _mm256_cmp_ps(t0, exit_x, _CMP_NGT_UQ)),
                    _mm256_and_ps(_mm256_cmp_ps(t0, exit_y, _CMP_NGT_UQ),
                                  _mm256_cmp_ps(t0, exit_z, _CMP_NGT_UQ)));
                const unsigned mask = (unsigned)_mm256_movemask_ps(hit);
#endif
                if (mask) {
                    if (!(mask & (mask - 1u))) {
#if TRACE_AVX512_TABLE
                        /* The mask register itself (mask's operation on
                         * the same masks, which GCC computes once):
                         * wide8_front_compress says why.  A node with one
                         * hit child has no order to decide, in an any-hit
                         * walk or a closest-hit one: the only hit lane is
                         * the lowest, so the compression takes the child
                         * the count would.  The walks with any_hit ==
                         * WIDE_ANY_LONGEST keep the count (not measured
                         * with the compression).  Written before the
                         * branch, the dead block changed the other walks'
                         * register allocation (performance-log.md, round
                         * 46). */
                        if (by_off)
                            wide8_front_compress(n, _kand_mask8(_kand_mask8(k0, k1),
                                                                _kand_mask8(k2, k3)),
                                                 &cur_off, &cur_count);
                        else
#endif
                        {
                            const unsigned l = (unsigned)__builtin_ctz(mask);
                            cur = n->child[l];
                            cur_count = n->count[l];
                        }
                    } else {
                        if (any_hit == WIDE_ANY_LONGEST) {
                            /* The exits as the test took them (scaled),
                             * clamped to the limit: min returns its second
                             * operand when either is NaN, so a NaN exit
                             * gives way to the limit and t1 is never NaN
                             * (wide8_any_front's keys need that). */
                            const __m256 t1 = _mm256_min_ps(
                                _mm256_mul_ps(tfz, scale),
                                _mm256_min_ps(_mm256_mul_ps(tfy, scale),
                                              _mm256_min_ps(_mm256_mul_ps(tfx, scale),
                                                            _mm256_set1_ps(box_limit))));
                            wide8_push_any(n, mask, hit, t0, t1, st_child, st_count, &sp, &cur,
                                           &cur_count);
                        } else if (any_hit) {
#if TRACE_AVX512_TABLE
                            if (any_hit == 1 && by_off) {
                                wide8_front_compress(n, _kand_mask8(_kand_mask8(k0, k1),
                                                                    _kand_mask8(k2, k3)),
                                                     &cur_off, &cur_count);
                                wide8_store(n, wide8_gather_stored(mask), t0, mask, st_child,
                                            st_count, NULL, &sp);
                            } else
#endif
                            wide8_push_stored(n, mask, t0, st_child, st_count, &sp, &cur,
                                              &cur_count);
                        }
                        else
#if TRACE_AVX512_TABLE
                            if (by_off)
                                wide8_push_compress(n, octant, hit, t0, order_shift, st_child,
                                                    st_count, st_t, &sp, &cur_off, &cur_count);
                            else
#endif
                            wide8_push(n, octant, hit, t0, order_shift, st_child, st_count, st_t,
                                       &sp, &cur, &cur_count);
                        if (prefetch_top) {
                            /* The new stack top, whose subtree comes after
                             * cur's: prefetched now (its bounds, or the
                             * first three lines of its leaf's packet), so
                             * that its load overlaps cur's subtree instead
                             * of following it. */
                            const uint32_t top = st_child[sp - 1];
                            const char *a = st_count[sp - 1] ? (const char *)&packets[top]
                                                             : (const char *)&nodes[top];
                            WIDE_PREFETCH_LINES(a, 3);
                        }
                    }
                    /* The node the walk goes to next, its four lines
                     * prefetched as soon as it is chosen (the bounds' loads
                     * then start together, and the last line, which the
                     * walk reads at an index the test gives, with them).
                     * Closest hit only: in the any-hit walks it cost the
                     * soup's shadow rays 0.03 of Embree in every round
                     * (the packet walk's, round 38: level). */
                    if (!any_hit && !cur_count)
                        WIDE_PREFETCH_LINES(by_off ? node_base + cur_off
                                                   : (const char *)&nodes[cur],
                                            4);
                    continue;
                }
                /* Pop (as below). */
                for (;;) {
                    if (sp == 0)
                        goto done;
                    sp--;
                    if (any_hit || st_t[sp] <= node_limit)
                        break;
                }
                cur = st_child[sp];
                cur_count = st_count[sp];
                cur_off = (size_t)cur * sizeof(nodes[0]);
                /* No WIDE8_PREFETCH_NEXT_TOP here (above). */
            }
        }
        {
            int stop = 0;
            const struct tri4_packet *p =
                &packets[by_off ? (size_t)(cur_off / sizeof(nodes[0])) : (size_t)cur];
            /* A closest-hit ray sets the packet test's constants at its
             * first leaf, not at its start: a ray that misses every leaf
             * box never pays for them.  An any-hit ray (a shadow ray,
             * which starts on a surface and nearly always reaches a leaf)
             * has them set by WIDE8_WALK: the lazy set-up cost it more
             * instructions than it saved (callgrind, gears). */
            /* A ray's first leaf: with a camera inside a room, the leaf
             * whose box holds the camera is entered by nearly every
             * camera ray, and its lanes are missed by the line or lie
             * wholly behind the camera (the BART kitchen: one leaf, 0.99
             * of its camera rays; the first leaf of 0.65 of them, the
             * octant's child order deciding).  A ray's first leaf (r4
             * not yet set), when it holds 5-8 triangles, is tested by a
             * copy that refuses such a leaf right after the signs
             * (wide8_leaf8_closest_first, TRI4_BEHIND_FIRST); every later
             * leaf, and a first leaf of 1-4 triangles, keeps the filter
             * as it was: rr5's same exit in every call (round 42) was
             * level or slower on the clock, its branch taken on about
             * 0.6 of the calls. */
#if WIDE8_RAY_LEAF8
            const int first_leaf = !any_hit && !r4_ready;
#endif
            if (!any_hit && !r4_ready) {
#if defined(__AVX2__)
                tri4_ray_init_vec(&s->r4, ray);
#else
                tri4_ray_init(&s->r4, ray);
#endif
                /* The finish's doubles (WIDE8_LEAF_TEST's ray_double): s is
                 * a struct wide_ray_state's (WIDE8_WALK, WIDE8_WALK1). */
                tri4_ray_init_double(wide_ray_doubles(s), ray);
                r4_ready = 1;
            }
            if (stats)
                tri_tests += cur_count;
#if WIDE8_RAY_LEAF8
            /* Two packets (5-8 triangles) in one 8-lane call. */
            if (cur_count > 4) {
                if (any_hit)
                    stop = wide8_leaf8_any(s, p, cur_count);
                else if (leave_early)
                    stop = first_leaf ? wide8_leaf8_closest_first(s, p, cur_count)
                                      : wide8_leaf8_closest(s, p, cur_count);
                else
                    stop = first_leaf ? wide8_leaf8_full_first(s, p, cur_count)
                                      : wide8_leaf8_full(s, p, cur_count);
            } else
#endif
            for (;;) {
                const uint32_t n = cur_count < 4 ? cur_count : 4;
                if (any_hit)
                    stop = wide8_packet_any(s, p, n);
                else if (leave_early)
                    stop = wide8_packet_closest(s, p, n);
                else
                    stop = wide8_packet_full(s, p, n);
                if (stop || cur_count <= 4)
                    break;
                cur_count -= 4;
                p++;
            }
            if (stop) {
                if (stats) {
                    s->node_tests += node_tests;
                    s->triangle_tests += tri_tests;
                }
                return 1;
            }
        }
        if (!any_hit) {
            box_limit = s->box_limit;
            node_limit = fused ? node_fused_limit(box_limit) : box_limit;
        }
        /* An any-hit walk ends at its first hit, so its box_limit never
         * shrinks and every pushed child passes: the entry distance is
         * not compared. */
        for (;;) {
            if (sp == 0)
                goto done;
            sp--;
            if (any_hit || st_t[sp] <= node_limit)
                break;
        }
        cur = st_child[sp];
        cur_count = st_count[sp];
        cur_off = (size_t)cur * sizeof(nodes[0]);
        WIDE8_PREFETCH_NEXT_TOP();
    }
done:
#undef WIDE8_PREFETCH_NEXT_TOP
    if (stats) {
        s->node_tests += node_tests;
        s->triangle_tests += tri_tests;
    }
    return 0;
}
