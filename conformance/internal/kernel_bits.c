/* SPDX-License-Identifier: Apache-2.0 */
/*
 * kernel_bits.c - answers of the ray/triangle kernel that only a bit-for-bit
 * comparison sees.
 *
 * Hits must be identical whatever the kernel's implementation (inlined
 * min/max, early rejections, ISA): an image or a query answer must not
 * change by one bit.  The sign of a zero hit distance is such a bit.  A
 * ray starting exactly on a vertex, running along an axis with a negative
 * zero direction component, gets t = 0 from the clamp into the
 * triangle's box (intersect.h), whose far end is the largest of the
 * vertices' sheared depths; when those are -0 and +0, which of the two
 * wins was decided by fmaxf's tie rule on x86-64 (maxss: the second
 * argument).  An inlined max with the other tie rule gives t = -0 for
 * the first case below and fails this test.
 *
 * Every ISA table of lib/trace/kernels.h that this CPU runs is then
 * compared with the scalar table, closest and any hit, bit for bit (t, u,
 * v, primitive, and the node and triangle counts), on rays that stress the
 * box and triangle tests' corner cases: aimed exactly at vertices and
 * along edges, axis-parallel with both signs of zero from origins on the
 * boxes' planes, grazing, from far away, with tmin > 0 and finite t_max;
 * over a grid-snapped soup (coincident planes and shared coordinates), a
 * random soup, a cube-sphere at 1e5 and a flat cube.
 *
 * The same rays then go through each table's walk over the 4-wide and the
 * 8-wide layout (bvh4_layout.h, traverse_wide.h; a table without the
 * 8-wide walk takes the binary one) and must give the scalar binary
 * walk's answers bit for bit (found, t, u, v, primitive, closest and any
 * hit); the node and triangle counts differ by design and are printed
 * per layout.  The packet walks of each table then take the same kinds of
 * rays in packets of eight (compare_packets).  With `deform`, the mesh's vertices are moved after the
 * build and both layouts refitted (accel_refit_mesh, accel_refit4) as
 * lib/scene/accel.c does for a refit strategy: a wide layout left with
 * the old boxes misses hits and fails the comparison.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/refit.h"
#include "trace/bvh4_layout.h"
#include "accel/bvh_build.h"
#include "accel_testgeo.h"
#include "base/alloc.h"
#include "trace/kernels.h"
#include "trace/scene_traverse.h"
#include "trace/trace.h"

static int failures;

static uint32_t bits(float f)
{
    uint32_t b;
    memcpy(&b, &f, sizeof(b));
    return b;
}

static void signed_zero_case(const float v0[3], const float v1[3], const float v2[3],
                             uint32_t want_t_bits, const char *name)
{
    const float org[3] = {-0.25f, 0.0f, 0.375f};
    const float dir[3] = {0.0f, 1.0f, -0.0f};
    struct trace_ray ray;
    trace_ray_init(&ray, org, dir, 0.0f);
    float t = NAN, u = NAN, v = NAN;
    int hit = trace_triangle(&ray, v0, v1, v2, INFINITY, &t, &u, &v);
    failures += !CHECKF(hit && t == 0.0f && bits(t) == want_t_bits,
             "%s: hit %d, t %a (bits %08x, want %08x)", name, hit, t, bits(t), want_t_bits);
}

/* A ray of kind 0..5 for mesh m. */
static void make_ray(const struct tg_mesh *m, struct tg_rng *r, int kind, float org[3],
                     float dir[3])
{
    uint32_t t = tg_below(r, m->tri_count);
    const float *a = tg_vertex(m, t, 0);
    const float *b = tg_vertex(m, t, 1 + (int)tg_below(r, 2));
    float s = tg_unit(r);
    for (int k = 0; k < 3; k++) {
        switch (kind) {
        case 0: /* at a vertex */
            org[k] = a[k] + tg_range(r, -3.0f, 3.0f);
            dir[k] = a[k] - org[k];
            break;
        case 1: /* at a point of an edge, from far away */
            org[k] = a[k] + tg_range(r, -50.0f, 50.0f);
            dir[k] = a[k] + (b[k] - a[k]) * s - org[k];
            break;
        case 2: /* grazing: along an edge, slightly turned */
            dir[k] = (b[k] - a[k]) + tg_range(r, -1e-4f, 1e-4f);
            org[k] = a[k] + (b[k] - a[k]) * s - dir[k] * (1.0f + tg_unit(r));
            break;
        case 3: /* axis-parallel from a vertex's coordinates (box planes) */
            org[k] = a[k];
            dir[k] = (tg_below(r, 2) ? 0.0f : -0.0f);
            break;
        default: /* anywhere */
            org[k] = a[k] + tg_range(r, -2.0f, 2.0f);
            dir[k] = tg_range(r, -1.0f, 1.0f);
            break;
        }
    }
    if (kind == 3) {
        int axis = (int)tg_below(r, 3);
        org[axis] -= 2.0f * (float)(tg_below(r, 2) ? 1 : -1);
        dir[axis] = tg_below(r, 2) ? 1.0f : -1.0f;
    }
    if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f)
        dir[0] = 1.0f;
}

/*
 * The packet walks (packet.h, packet_wide.h) against the scalar binary
 * walk, ray by ray and bit for bit (found, t, u, v, primitive; closest
 * and any hit), on packets of TRACE_PACKET rays: incoherent ones (eight
 * consecutive rays of make_ray, any mix of octants, tmin and t_max),
 * coherent ones (one origin, directions turned by up to 1e-3 around one
 * aimed at a vertex or an edge, the first exactly at it), divergent ones
 * (one origin, one octant, directions up to 60% apart per component:
 * the interval-arithmetic node test), one-origin ones with degenerate
 * lanes (a direction component 0, -0, denormal, NaN, infinite or huge),
 * the last two with t ranges that differ per lane, with random
 * inactive lanes, and with the hybrid fallback off (0: the packet walk
 * to the leaves, TRACE_PACKET_HYBRID's value), at 3 and always (9: every
 * ray alone).
 * Returns the number of failed checks.
 */
static int compare_packets(const char *name, const struct trace_kernels *k, const char *layout,
                           const struct tg_mesh *m, const struct bvh4 *wide,
                           const struct bvh *bvh, const float *tri, int rays, uint64_t seed)
{
    const struct trace_kernels *ref = trace_kernels_get(TRACE_ISA_SCALAR);
    static const unsigned hybrids[3] = {0, 3, TRACE_PACKET + 1};
    struct tg_rng r;
    tg_seed(&r, seed ^ 0x9e3779b97f4a7c15ull);
    int differ = 0, compared = 0;
    struct trace_counters cp = {0, 0}, cs = {0, 0};
    for (int g = 0; g + TRACE_PACKET <= rays; g += TRACE_PACKET) {
        struct trace_ray ray[TRACE_PACKET];
        float t_max[TRACE_PACKET];
        /* The same rays as arrays, for the entries that take them. */
        float orgs[TRACE_PACKET][3], dirs[TRACE_PACKET][3], tmins[TRACE_PACKET];
        /* Packet kinds by group: 0 incoherent, 1 coherent, 2 divergent
         * from one origin in one octant (the interval node test's case,
         * packet_box8_ia), 3 one origin with degenerate lanes. */
        const int kind = (g / TRACE_PACKET) % 6 < 4 ? (g / TRACE_PACKET) % 2
                                                     : 2 + (g / TRACE_PACKET) % 2;
        const int coherent = kind == 1;
        float org0[3], dir0[3];
        make_ray(m, &r, (g / TRACE_PACKET / 2) % 3 == 0 ? 1 : 0, org0, dir0);
        for (int i = 0; i < TRACE_PACKET; i++) {
            float org[3], dir[3];
            if (kind >= 2) {
                for (int a = 0; a < 3; a++) {
                    org[a] = org0[a];
                    /* Up to +-60% per component, keeping its sign. */
                    dir[a] = dir0[a] * (1.0f + (i ? tg_range(&r, -0.6f, 0.6f) : 0.0f));
                }
                if (kind == 3) {
                    const int a = (int)tg_below(&r, 3);
                    static const float odd[8] = {0.0f, -0.0f, 1e-40f, -1e-42f, NAN,
                                                 INFINITY, -INFINITY, 1e30f};
                    if (i % 2)
                        dir[a] = odd[tg_below(&r, 8)];
                }
            } else if (coherent) {
                for (int a = 0; a < 3; a++) {
                    org[a] = org0[a];
                    dir[a] = dir0[a] * (1.0f + (i ? tg_range(&r, -1e-3f, 1e-3f) : 0.0f));
                }
            } else {
                make_ray(m, &r, (g + i) % 6, org, dir);
            }
            float tmin = (g + i) % 7 == 0 ? 0.5f : 0.0f;
            t_max[i] = (g + i) % 11 == 0 ? 1.0f : INFINITY;
            if (kind >= 2) {
                /* t ranges that differ per lane. */
                tmin = tg_below(&r, 2) ? tg_range(&r, 0.0f, 0.8f) : 0.0f;
                t_max[i] = tg_below(&r, 2) ? tmin + tg_range(&r, 0.0f, 1.5f) : INFINITY;
            }
            trace_ray_init(&ray[i], org, dir, tmin);
            memcpy(orgs[i], org, sizeof(orgs[i]));
            memcpy(dirs[i], dir, sizeof(dirs[i]));
            tmins[i] = tmin;
        }
        const unsigned active = (g / TRACE_PACKET) % 5 == 0
                                    ? (unsigned)tg_below(&r, 1u << TRACE_PACKET)
                                    : (1u << TRACE_PACKET) - 1u;
        const unsigned hybrid = hybrids[(g / TRACE_PACKET) % 3];
        struct trace_hit hp[TRACE_PACKET];
        memset(hp, 0, sizeof(hp));
        const unsigned fp = k->closest_packet(wide, bvh, tri, ray, t_max, active, hybrid, hp, &cp);
        const unsigned ap = k->any_packet(wide, bvh, tri, ray, t_max, active, hybrid, NULL);
        if (k->closest_packet_arrays && k->packet_init) {
            /* The entries from the arrays: the packet walks' answers for
             * the rays packet_init sets up from them, bit for bit. */
            struct trace_ray set[TRACE_PACKET];
            struct trace_top_rays top;
            struct trace_hit hq[TRACE_PACKET], hr[TRACE_PACKET];
            memset(hq, 0, sizeof(hq));
            memset(hr, 0, sizeof(hr));
            k->packet_init((const float(*)[3])orgs, (const float(*)[3])dirs, tmins, active, set,
                           &top, NULL);
            const unsigned fq = k->closest_packet(wide, bvh, tri, set, t_max, active, hybrid, hq,
                                                  NULL);
            const unsigned aq = k->any_packet(wide, bvh, tri, set, t_max, active, hybrid, NULL);
            const unsigned fr = k->closest_packet_arrays(
                wide, bvh, tri, (const float(*)[3])orgs, (const float(*)[3])dirs, tmins, t_max,
                active, hybrid, hr, NULL);
            const unsigned ar = k->any_packet_arrays(wide, bvh, tri, (const float(*)[3])orgs,
                                                     (const float(*)[3])dirs, tmins, t_max,
                                                     active, hybrid, NULL);
            int bad = fq != fr || aq != ar;
            for (int i = 0; i < TRACE_PACKET; i++)
                bad |= (fq >> i & 1u) && memcmp(&hq[i], &hr[i], sizeof(hq[i])) != 0;
            if (bad) {
                if (differ < 5)
                    printf("    packet %s group %d (hybrid %u): the arrays entries differ "
                           "(closest %02x/%02x any %02x/%02x)\n",
                           layout, g / TRACE_PACKET, hybrid, fq, fr, aq, ar);
                differ++;
            }
        }
        for (int i = 0; i < TRACE_PACKET; i++) {
            struct trace_hit h0;
            memset(&h0, 0, sizeof(h0));
            const int in = active >> i & 1u;
            const int f0 = in && ref->closest(bvh, tri, &ray[i], t_max[i], &h0, &cs);
            const int a0 = in && ref->any(bvh, tri, &ray[i], t_max[i], NULL);
            const int f1 = (int)(fp >> i & 1u), a1 = (int)(ap >> i & 1u);
            compared += in;
            if (f0 != f1 || a0 != a1 || (f0 && memcmp(&h0, &hp[i], sizeof(h0)) != 0)) {
                if (differ < 5)
                    printf("    packet %s group %d ray %d (hybrid %u): found %d/%d any %d/%d "
                           "t %a/%a prim %u/%u\n",
                           layout, g / TRACE_PACKET, i, hybrid, f0, f1, a0, a1, h0.t, hp[i].t,
                           h0.prim, hp[i].prim);
                differ++;
            }
        }
    }
    printf("  %s: %s %s packets = scalar binary on %d rays; per closest ray: nodes %.1f, "
           "triangles %.1f (binary %.1f, %.1f)\n",
           name, k->name, layout, compared - differ, (double)cp.node_tests / compared,
           (double)cp.triangle_tests / compared, (double)cs.node_tests / compared,
           (double)cs.triangle_tests / compared);
    return !CHECKF(differ == 0, "%s: %s %s packets differ from scalar binary on %d of %d rays",
                   name, k->name, layout, differ, compared);
}

static void compare_tables(const char *name, struct tg_mesh *m, int rays, uint64_t seed,
                           int deform)
{
    struct aabb *boxes = tg_boxes(m);
    struct bvh bvh;
    if (accel_build(&bvh, boxes, m->tri_count, NULL)) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    float *tri = accel_gather_triangles(&bvh, m->pos, m->idx);
    struct bvh4 wides[2];
    if (accel_collapse_wide(&wides[0], &bvh, tri, 4) ||
        accel_collapse_wide(&wides[1], &bvh, tri, 8)) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    printf("  %s: node bytes per triangle: binary %.1f, bvh4 %.1f, bvh8 %.1f\n", name,
           32.0 * bvh.node_count / m->tri_count,
           (double)bvh4_node_bytes(&wides[0]) / m->tri_count,
           (double)bvh4_node_bytes(&wides[1]) / m->tri_count);
    /* Which copy of the 8-wide any-hit walk this layout takes (the
     * random soup's: the longest segment's, bvh4_layout.h any_longest);
     * both are compared with the scalar table below. */
    printf("  %s: bvh8 child crossings %.2f, any-hit order %s\n", name,
           accel_wide_child_crossings(&wides[1]),
           wides[1].any_longest ? "longest segment" : "stored");
    if (deform) {
        /* A twist about z growing with height, and a shift: every box
         * moves. */
        for (uint32_t i = 0; i < m->vertex_count; i++) {
            float *p = &m->pos[3 * i];
            float a = 0.3f * p[2];
            float x = p[0] * cosf(a) - p[1] * sinf(a);
            float y = p[0] * sinf(a) + p[1] * cosf(a);
            p[0] = x + 0.25f;
            p[1] = y;
        }
        accel_refit_mesh(&bvh, tri, m->pos, m->idx, NULL);
        /* A layout that left zero-area triangles out is collapsed
         * again (accel_refit4's contract). */
        for (int w = 0; w < 2; w++) {
            if (accel_refit4(&wides[w], &bvh, tri) == 0)
                continue;
            bvh4_release(&wides[w]);
            if (accel_collapse_wide(&wides[w], &bvh, tri, w ? 8u : 4u)) {
                fprintf(stderr, "out of memory\n");
                exit(1);
            }
        }
    }
    const struct trace_kernels *ref = trace_kernels_get(TRACE_ISA_SCALAR);
    /* Every table this CPU runs, on each layout, then (the last two
     * rounds) the AVX-512 table's other single-ray walk form, the one
     * trace_kernels_get does not give on this CPU (kernels.h,
     * trace_kernels_avx512_ctz): both forms are checked on every CPU
     * with AVX-512. */
    const struct trace_kernels *avx512 = trace_kernels_get(TRACE_ISA_AVX512);
    const struct trace_kernels *avx512_other = NULL;
    if (avx512)
        avx512_other = avx512 == trace_kernels_avx512() ? trace_kernels_avx512_ctz()
                                                        : trace_kernels_avx512();
    for (int isa = TRACE_ISA_SCALAR + 1; isa < 2 * TRACE_ISA_COUNT + 2; isa++) {
        const int other = isa >= 2 * TRACE_ISA_COUNT;
        const struct trace_kernels *k =
            other ? avx512_other : trace_kernels_get((enum trace_isa)(isa / 2));
        if (!k || isa / 2 == TRACE_ISA_SCALAR)
            continue;
        char kname[64];
        snprintf(kname, sizeof(kname), "%s%s", k->name, other ? " (other walk form)" : "");
        const struct bvh4 *wide = &wides[isa % 2];
        const char *layout = isa % 2 ? "bvh8" : "bvh4";
        struct tg_rng r;
        tg_seed(&r, seed);
        int differ = 0;
        int differ4 = 0;
        int walk1_rays = 0;
        struct trace_counters n2 = {0, 0}, n4 = {0, 0};
        for (int i = 0; i < rays; i++) {
            float org[3], dir[3];
            make_ray(m, &r, i % 6, org, dir);
            /* Now and then tmin -0, which the 8-wide single-ray walks'
             * integer maximum of a box's entry takes as +0
             * (traverse_wide8_ray.h).  Not a negative tmin: the API
             * refuses it, and the wide walks' leaves already answer it
             * otherwise than the binary walk (hits at t < 0). */
            const float tmin = i % 7 == 0 ? 0.5f : i % 13 == 0 ? -0.0f : 0.0f;
            const float t_max = i % 11 == 0 ? 1.0f : INFINITY;
            struct trace_ray ray;
            trace_ray_init(&ray, org, dir, tmin);
            struct trace_hit h0, h1;
            memset(&h0, 0, sizeof(h0));
            memset(&h1, 0, sizeof(h1));
            struct trace_counters c0 = {0, 0}, c1 = {0, 0};
            int f0 = ref->closest(&bvh, tri, &ray, t_max, &h0, &c0);
            int f1 = k->closest(&bvh, tri, &ray, t_max, &h1, &c1);
            int a0 = ref->any(&bvh, tri, &ray, t_max, &c0);
            int a1 = k->any(&bvh, tri, &ray, t_max, &c1);
            if (f0 != f1 || a0 != a1 || memcmp(&h0, &h1, sizeof(h0)) != 0 ||
                c0.node_tests != c1.node_tests || c0.triangle_tests != c1.triangle_tests)
                differ++;
            if (k->closest4) {
                struct trace_hit h4;
                memset(&h4, 0, sizeof(h4));
                struct trace_counters c4 = {0, 0};
                int f4 = k->closest4(wide, &bvh, tri, &ray, t_max, &h4, &c4);
                n4.node_tests += c4.node_tests;
                n4.triangle_tests += c4.triangle_tests;
                int a4 = k->any4(wide, &bvh, tri, &ray, t_max, NULL);
                struct trace_counters c2 = {0, 0};
                struct trace_hit h2;
                ref->closest(&bvh, tri, &ray, t_max, &h2, &c2);
                n2.node_tests += c2.node_tests;
                n2.triangle_tests += c2.triangle_tests;
                /* The entries from org and dir (the ray set up inside
                 * the walk, ray_setup.h), without counters: the walks
                 * rtbench and a ray traced alone take. */
                struct trace_hit h5;
                memset(&h5, 0, sizeof(h5));
                int f5 = k->closest1(wide, &bvh, tri, org, dir, tmin, t_max, &h5, NULL);
                int a5 = k->any1(wide, &bvh, tri, org, dir, tmin, t_max, NULL);
                /* The walks walk1 chooses for the layout, called
                 * directly (rtbench's loops). */
                if (k->walk1 && k->walk1(wide, 0)) {
                    struct trace_hit h6;
                    memset(&h6, 0, sizeof(h6));
                    const int f6 = k->walk1(wide, 0)(wide, org, dir, tmin, t_max, &h6, NULL);
                    const int a6 = k->walk1(wide, 1)(wide, org, dir, tmin, t_max, NULL, NULL);
                    if (f0 != f6 || a0 != a6 || memcmp(&h0, &h6, sizeof(h0)) != 0) {
                        if (differ4 < 5)
                            printf("    %s ray %d (walk1): found %d/%d any %d/%d t %a/%a "
                                   "prim %u/%u\n",
                                   layout, i, f0, f6, a0, a6, h0.t, h6.t, h0.prim, h6.prim);
                        differ4++;
                    }
                    walk1_rays++;
                }
                /* The any-hit walks walk1 and any1 choose by prefetch_top
                 * and any_longest (a copy per flag pair): any's answer on
                 * the layout with each of the four pairs (a shallow copy:
                 * the walks read the flags only). */
                for (int flags = 0; flags < 4 && k->walk1 && wide->width == 8 &&
                                    wide->node_count;
                     flags++) {
                    struct bvh4 wp = *wide;
                    wp.prefetch_top = (uint32_t)(flags & 1);
                    wp.any_longest = (uint32_t)(flags >> 1);
                    const trace_walk1_fn w = k->walk1(&wp, 1);
                    const int a9 = w ? w(&wp, org, dir, tmin, t_max, NULL, NULL) : a0;
                    const int a10 = k->any1(&wp, &bvh, tri, org, dir, tmin, t_max, NULL);
                    if (a0 != a9 || a0 != a10) {
                        if (differ4 < 5)
                            printf("    %s ray %d (any-hit walk, flags %d): any %d/%d/%d\n",
                                   layout, i, flags, a0, a9, a10);
                        differ4++;
                    }
                }
                /* The counting walks the two-level walk takes from
                 * walk1_counted: closest1's / any1's answers and counts
                 * with counters, on the layout with prefetch_top and
                 * any_longest both 0 and both 1 (a shallow copy: the walks
                 * read the flags only; both any-hit orders on every
                 * layout). */
                for (int pre = 0; pre < 2 && k->walk1_counted && wide->width == 8 &&
                                  wide->node_count;
                     pre++) {
                    struct bvh4 wp = *wide;
                    wp.prefetch_top = (uint32_t)pre;
                    wp.any_longest = (uint32_t)pre;
                    struct trace_hit h7, h8;
                    memset(&h7, 0, sizeof(h7));
                    memset(&h8, 0, sizeof(h8));
                    struct trace_counters c7 = {0, 0}, c8 = {0, 0};
                    const int f7 = k->walk1_counted[pre](&wp, org, dir, tmin, t_max, &h7, &c7);
                    const int a7 =
                        k->walk1_counted[2 + pre](&wp, org, dir, tmin, t_max, NULL, &c7);
                    const int f8 = k->closest1(&wp, &bvh, tri, org, dir, tmin, t_max, &h8, &c8);
                    const int a8 = k->any1(&wp, &bvh, tri, org, dir, tmin, t_max, &c8);
                    if (f0 != f7 || a0 != a7 || f8 != f7 || a8 != a7 ||
                        memcmp(&h0, &h7, sizeof(h0)) != 0 || memcmp(&h8, &h7, sizeof(h0)) != 0 ||
                        c7.node_tests != c8.node_tests || c7.triangle_tests != c8.triangle_tests) {
                        if (differ4 < 5)
                            printf("    %s ray %d (walk1_counted): found %d/%d any %d/%d "
                                   "nodes %llu/%llu\n",
                                   layout, i, f0, f7, a0, a7,
                                   (unsigned long long)c8.node_tests,
                                   (unsigned long long)c7.node_tests);
                        differ4++;
                    }
                }
                if (f0 != f5 || a0 != a5 || memcmp(&h0, &h5, sizeof(h0)) != 0) {
                    if (differ4 < 5)
                        printf("    %s ray %d (closest1/any1): found %d/%d any %d/%d t %a/%a "
                               "prim %u/%u\n",
                               layout, i, f0, f5, a0, a5, h0.t, h5.t, h0.prim, h5.prim);
                    differ4++;
                }
                if (f0 != f4 || a0 != a4 || memcmp(&h0, &h4, sizeof(h0)) != 0) {
                    if (differ4 < 5)
                        printf("    %s ray %d: found %d/%d any %d/%d t %a/%a prim %u/%u\n",
                               layout, i, f0, f4, a0, a4, h0.t, h4.t, h0.prim, h4.prim);
                    differ4++;
                }
            }
        }
        if (k->closest_packet && !other) /* the other form's packets are the table's */
            failures += compare_packets(name, k, layout, m, wide, &bvh, tri, rays, seed);
        failures += !CHECKF(differ == 0, "%s: %s differs from scalar on %d of %d rays", name,
                 kname, differ, rays);
        printf("  %s: %s = scalar on %d rays\n", name, kname, rays - differ);
        if (k->closest4) {
            failures += !CHECKF(differ4 == 0, "%s: %s %s differs from scalar binary on %d of %d rays",
                     name, kname, layout, differ4, rays);
            printf("  %s: %s %s = scalar binary on %d rays (%d of them also through walk1); "
                   "per closest ray: nodes %.1f -> %.1f, triangles %.1f -> %.1f\n",
                   name, kname, layout, rays - differ4, walk1_rays,
                   (double)n2.node_tests / rays, (double)n4.node_tests / rays,
                   (double)n2.triangle_tests / rays, (double)n4.triangle_tests / rays);
        }
    }
    rt_free(tri);
    bvh4_release(&wides[0]);
    bvh4_release(&wides[1]);
    bvh_release(&bvh);
    free(boxes);
}

/* Each table's packet set-up (kernels.h packet_init) against
 * trace_ray_init byte for byte, and its lanes, on directions
 * with ties between |components| (the axis choice), zeros of both signs
 * and values of every magnitude; some rays left out; and its masks
 * against trace_scene_plain_class, with origins of every kind (zeros of
 * both signs, infinities, NaN) too. */
static void compare_packet_init(void)
{
    static const float pick[] = {1.0f,   -1.0f, 0.0f,  -0.0f, 0.5f,   -0.5f,
                                 3e-30f, 7e29f, 2.0f, -2.0f,  1e-40f, -0.75f};
    /* Origins of every kind for the masks (a set-up copies the origin). */
    static const float pick_org[] = {0.0f, -0.0f, 1e-40f, -3.4e38f, INFINITY, -INFINITY, NAN, 5.0f};
    const int npick_org = (int)(sizeof(pick_org) / sizeof(pick_org[0]));
    const int npick = (int)(sizeof(pick) / sizeof(pick[0]));
    uint32_t state = 99u;
    for (int isa = 0; isa < TRACE_ISA_COUNT; isa++) {
        const struct trace_kernels *k = trace_kernels_get((enum trace_isa)isa);
        if (!k || !k->packet_init)
            continue;
        long bad = 0, rays = 0;
        for (int q = 0; q < 20000; q++) {
            float org[TRACE_PACKET][3], dir[TRACE_PACKET][3], tmin[TRACE_PACKET];
            for (int i = 0; i < TRACE_PACKET; i++) {
                for (int c = 0; c < 3; c++) {
                    state = state * 1664525u + 1013904223u;
                    org[i][c] = q % 5 == 3 ? pick_org[(state >> 12) % (uint32_t)npick_org]
                                           : (float)(int)(state >> 12) * 0x1p-10f - 512.0f;
                    state = state * 1664525u + 1013904223u;
                    dir[i][c] = q % 2 ? pick[(state >> 8) % (uint32_t)npick]
                                      : (float)(int)(state >> 8) * 0x1p-23f - 1.0f;
                }
                if (dir[i][0] == 0.0f && dir[i][1] == 0.0f && dir[i][2] == 0.0f)
                    dir[i][q % 3] = -3.0f; /* trace_ray_init needs a direction */
                tmin[i] = (float)(q % 3) * 0.25f;
            }
            state = state * 1664525u + 1013904223u;
            const unsigned live = q % 4 ? 0xFFu : (state >> 16) & 0xFFu;
            struct trace_ray got[TRACE_PACKET];
            struct trace_top_rays top;
            struct trace_packet_plain plain;
            k->packet_init((const float(*)[3])org, (const float(*)[3])dir, tmin, live, got, &top,
                           &plain);
            /* Without the masks (plain NULL): the same rays. */
            struct trace_ray again[TRACE_PACKET];
            struct trace_top_rays top_again;
            memcpy(again, got, sizeof(again));
            k->packet_init((const float(*)[3])org, (const float(*)[3])dir, tmin, live, again,
                           &top_again, NULL);
            bad += memcmp(again, got, sizeof(again)) != 0;
            for (int i = 0; i < TRACE_PACKET; i++) {
                /* The masks: trace_scene_plain_class's classes, finite
                 * origins, nothing for the rays left out. */
                const unsigned cls = trace_scene_plain_class(org[i], dir[i]);
                const unsigned in = live >> i & 1u;
                const int finite_org = isfinite(org[i][0]) && isfinite(org[i][1]) &&
                                       isfinite(org[i][2]);
                bad += (plain.zeros >> i & 1u) != (in & (cls & TRACE_IDENTITY_ZEROS ? 1u : 0u)) ||
                       (plain.exact >> i & 1u) != (in & (cls & TRACE_IDENTITY_EXACT ? 1u : 0u)) ||
                       (plain.finite_org >> i & 1u) != (in & (unsigned)finite_org);
                if (!(live >> i & 1u)) {
                    bad += bits(top.tmin[i]) != 0 || bits(top.inv_dir[0][i]) != 0;
                    continue;
                }
                struct trace_ray want;
                memset(&want, 0, sizeof(want));
                trace_ray_init(&want, org[i], dir[i], tmin[i]);
                rays++;
                for (int c = 0; c < 3; c++)
                    bad += bits(top.org[c][i]) != bits(org[i][c]) ||
                           bits(top.inv_dir[c][i]) != bits(want.inv_dir[c]);
                bad += memcmp(&got[i], &want, sizeof(want)) != 0 ||
                       bits(top.tmin[i]) != bits(tmin[i]);
            }
        }
        printf("  packet_init %s: %ld rays, %ld differences\n", k->name, rays, bad);
        if (bad || rays == 0)
            failures++;
    }
}

int main(void)
{
    printf("kernel_bits:\n");
    compare_packet_init();
    /* The origin is v2 of the first triangle and of the second. */
    const float a0[3] = {-0.375f, -0.125f, 0.5f};
    const float a1[3] = {-0.25f, -0.0f, 0.5f};
    const float a2[3] = {-0.25f, 0.0f, 0.375f};
    signed_zero_case(a0, a1, a2, 0x00000000u, "vertex hit, depths -0 and +0");
    const float b0[3] = {-0.25f, 0.125f, 0.25f};
    const float b1[3] = {-0.125f, 0.125f, 0.25f};
    const float b2[3] = {-0.25f, -0.0f, 0.375f};
    signed_zero_case(b0, b1, b2, 0x80000000u, "vertex hit, depth -0 only");

    struct tg_rng r;
    struct tg_mesh m;
    tg_seed(&r, 11);
    tg_soup(&m, 3000, 4.0f, 0.5f, &r);
    for (uint32_t i = 0; i < 9 * m.tri_count; i++)
        m.pos[i] = roundf(m.pos[i] * 8.0f) / 8.0f; /* shared planes, slivers, points */
    compare_tables("grid soup", &m, 60000, 12, 0);
    tg_mesh_free(&m);
    tg_soup(&m, 20000, 2.0f, 0.1f, &r);
    compare_tables("soup", &m, 60000, 13, 0);
    compare_tables("soup, deformed and refitted", &m, 60000, 16, 1);
    tg_mesh_free(&m);
    const double far[3] = {1e5, -1e5, 3e4};
    tg_cube_sphere(&m, 24, 1, 1.0, far);
    compare_tables("sphere at 1e5", &m, 30000, 14, 0);
    tg_mesh_free(&m);
    const double zero[3] = {0.0, 0.0, 0.0};
    tg_cube_sphere(&m, 16, 0, 1.0, zero);
    compare_tables("flat cube", &m, 60000, 15, 0);
    tg_mesh_free(&m);
    printf("  %s (%d failures)\n", failures ? "FAIL" : "ok", failures);
    return failures ? 1 : 0;
}
