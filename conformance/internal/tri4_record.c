/* SPDX-License-Identifier: Apache-2.0 */
/*
 * tri4_record.c - the packets' records for the closest-hit finish
 * (struct tri4_record, bvh4_layout.h; read by tri4_finish_lanes,
 * intersect_tri4.h).
 *
 * - The threshold: for triangles of every shape (proper, slivers of
 *   heights 2^-10 to 2^-40 of their length, tiny and huge, collinear,
 *   NaN lanes), size_max must be the largest float size for which the
 *   finish's first sliver test holds, written out here as
 *   isect_triangle_finish_impl writes it: the test holds at size_max and
 *   fails one float above (or size_max is FLT_MAX, or -inf where it
 *   never holds), and size <= size_max answers as the test for sizes
 *   around it.  A threshold one float off fails this.
 * - The normal: the record's doubles are the finish's cross product bit
 *   for bit.
 * - The layout: every packet's record of an 8-wide layout equals one
 *   filled from the packet now, after the collapse and after a refit of
 *   a deformed mesh (a stale record fails), and the closest hits of the
 *   8-wide single-ray walks of every table (the AVX2 table's finish reads
 *   the records) equal the scalar table's on the deformed mesh.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;

#include "accel/bvh_build.h"
#include "accel/refit.h"
#include "accel_testgeo.h"
#include "base/alloc.h"
#include "check.h"
#include "trace/bvh4_layout.h"
#include "trace/intersect.h"
#include "trace/kernels.h"
#include "trace/trace.h"

/* isect_triangle_finish_impl's first sliver test, as written there. */
static int finish_proper(const float v[9], float size, double n_out[3])
{
    const double e1x = (double)v[3] - v[0];
    const double e1y = (double)v[4] - v[1];
    const double e1z = (double)v[5] - v[2];
    const double e2x = (double)v[6] - v[0];
    const double e2y = (double)v[7] - v[1];
    const double e2z = (double)v[8] - v[2];
    const double nx = e1y * e2z - e1z * e2y;
    const double ny = e1z * e2x - e1x * e2z;
    const double nz = e1x * e2y - e1y * e2x;
    const double n2 = nx * nx + ny * ny + nz * nz;
    const double l1 = e1x * e1x + e1y * e1y + e1z * e1z;
    const double l2 = e2x * e2x + e2y * e2y + e2z * e2z;
    const double rounding = ISECT_SLIVER_ROUNDINGS * 0x1p-24 * (double)size;
    const double r2 = rounding * rounding;
    if (n_out) {
        n_out[0] = nx;
        n_out[1] = ny;
        n_out[2] = nz;
    }
    return n2 >= r2 * ((l1 + l2) * ISECT_LONGEST_EDGE_BOUND);
}

static int same_double(double a, double b)
{
    return memcmp(&a, &b, sizeof(a)) == 0;
}

static int checked;

/* Lane l of r (filled from p) against the test above. */
static void check_lane(const struct tri4_packet *p, const struct tri4_record *r, uint32_t l,
                       const char *what)
{
    float v[9];
    for (int j = 0; j < 9; j++)
        v[j] = p->v[j / 3][j % 3][l];
    double n[3];
    finish_proper(v, 0.0f, n);
    const float s = r->size_max[l];
    int ok = 1;
    if (!isnan(v[0])) {
        for (int k = 0; k < 3; k++)
            ok &= same_double(r->n[k][l], n[k]);
    }
    if (s == -INFINITY) {
        /* Never proper: not even at 0 (a NaN lane). */
        ok &= !finish_proper(v, 0.0f, NULL) && !finish_proper(v, FLT_MIN, NULL);
    } else {
        /* Proper at s, and not one float above (FLT_MAX: never above). */
        ok &= finish_proper(v, s, NULL) && !finish_proper(v, nextafterf(s, INFINITY), NULL);
        /* size <= s answers as the test around s and at a few others. */
        float lo = s, hi = s;
        for (int k = 0; k < 8; k++) {
            lo = nextafterf(lo, 0.0f);
            hi = nextafterf(hi, INFINITY);
            ok &= (lo <= s) == finish_proper(v, lo, NULL);
            ok &= (hi <= s) == finish_proper(v, hi, NULL);
        }
        const float others[5] = {0.0f, 1e-30f, 0.5f, 1e30f, INFINITY};
        for (int k = 0; k < 5; k++)
            ok &= (others[k] <= s) == finish_proper(v, others[k], NULL);
    }
    ok &= !(NAN <= s) && !finish_proper(v, NAN, NULL);
    checked++;
    failures += !CHECKF(ok,
                        "%s lane %u: size_max %a (test there %d, one float above %d) or its "
                        "normal is not the finish's",
                        what, l, (double)s, finish_proper(v, s, NULL),
                        finish_proper(v, nextafterf(s, INFINITY), NULL));
}

/* Four triangles in a packet, their record filled and checked. */
static void check_packet(const float tri[4][9], const char *what)
{
    struct tri4_packet p;
    memset(&p, 0, sizeof(p));
    for (uint32_t l = 0; l < 4; l++)
        accel_set_packet_lane(&p, l, tri[l]);
    struct tri4_record r;
    accel_fill_packet_record(&r, &p);
    for (uint32_t l = 0; l < 4; l++)
        check_lane(&p, &r, l, what);
}

static void check_shapes(void)
{
    tu_section("thresholds");
    struct tg_rng rng;
    tg_seed(&rng, 5);
    float tri[4][9];
    /* Slivers: v2 at height h over the middle of the edge v0 v1, turned
     * and scaled at random; h from 2^-10 to 2^-40 of the length. */
    for (int i = 0; i < 4000; i++) {
        const float scale = ldexpf(1.0f, (int)tg_below(&rng, 60) - 30);
        for (int l = 0; l < 4; l++) {
            const float h = ldexpf(tg_unit(&rng) + 0.5f, -10 - (int)tg_below(&rng, 31));
            float base[9] = {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, tg_unit(&rng), h, 0.0f};
            const float a = tg_range(&rng, 0.0f, 6.2831853f);
            const float c[3] = {tg_range(&rng, -4.0f, 4.0f), tg_range(&rng, -4.0f, 4.0f),
                                tg_range(&rng, -4.0f, 4.0f)};
            for (int j = 0; j < 3; j++) {
                const float x = base[3 * j], y = base[3 * j + 1], z = base[3 * j + 2];
                tri[l][3 * j + 0] = (x * cosf(a) - y * sinf(a)) * scale + c[0];
                tri[l][3 * j + 1] = (x * sinf(a) + y * cosf(a)) * scale + c[1];
                tri[l][3 * j + 2] = (z + 0.25f * x) * scale + c[2];
            }
        }
        check_packet((const float(*)[9])tri, "sliver");
    }
    /* Proper triangles at every scale, and with coordinates up to
     * FLT_MAX / 4. */
    for (int i = 0; i < 4000; i++) {
        const float scale = ldexpf(1.0f, (int)tg_below(&rng, 250) - 125);
        for (int l = 0; l < 4; l++) {
            for (int j = 0; j < 9; j++)
                tri[l][j] = tg_range(&rng, -1.0f, 1.0f) * scale;
        }
        check_packet((const float(*)[9])tri, "proper");
    }
    /* Collinear (zero area: NaN lanes), a point, and denormal edges. */
    const float special[4][9] = {
        {0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 2.0f, 2.0f, 2.0f},
        {1.0f, 2.0f, 3.0f, 1.0f, 2.0f, 3.0f, 1.0f, 2.0f, 3.0f},
        {0.0f, 0.0f, 0.0f, 0x1p-149f, 0.0f, 0.0f, 0.0f, 0x1p-149f, 0.0f},
        {0.0f, 0.0f, 0.0f, 0x1p-140f, 0x1p-149f, 0.0f, 0.0f, 0x1p-130f, 0x1p-149f},
    };
    check_packet(special, "special");
    printf("  thresholds: %d lanes checked\n", checked);
}

/* Every packet's record of wide equals one filled from the packet now. */
static void check_layout_records(const struct bvh4 *wide, const char *what)
{
    int bad = 0;
    for (uint32_t i = 0; i < wide->packet_count; i++) {
        const struct tri4_packet *p = &wide->packets[i];
        struct tri4_record want;
        accel_fill_packet_record(&want, p);
        const struct tri4_record *have = tri4_packet_record(p, wide->record_offset);
        if (memcmp(have, &want, sizeof(want)) != 0)
            bad++;
    }
    failures += !CHECKF(wide->record_raw.base != NULL && bad == 0,
                        "%s: %d of %u packets' records differ from their packets'", what, bad,
                        wide->packet_count);
}

/* Closest hits of the 8-wide single-ray walks against the scalar table. */
static void check_rays(const struct tg_mesh *m, const struct bvh *bvh, const float *tri,
                       const struct bvh4 *wide, const char *what)
{
    const struct trace_kernels *ref = trace_kernels_get(TRACE_ISA_SCALAR);
    for (int isa = TRACE_ISA_SCALAR + 1; isa < TRACE_ISA_COUNT; isa++) {
        const struct trace_kernels *k = trace_kernels_get((enum trace_isa)isa);
        if (!k || !k->walk1 || !k->walk1(wide, 0))
            continue;
        struct tg_rng rng;
        tg_seed(&rng, 77);
        int differ = 0, hits = 0;
        for (int i = 0; i < 20000; i++) {
            /* Rays from outside the mesh's box towards a random triangle. */
            const uint32_t t = tg_below(&rng, m->tri_count);
            float target[3], org[3], dir[3];
            const float a = tg_unit(&rng), b = tg_unit(&rng) * (1.0f - a);
            for (int c = 0; c < 3; c++) {
                target[c] = tg_vertex(m, t, 0)[c] * (1.0f - a - b) + tg_vertex(m, t, 1)[c] * a +
                            tg_vertex(m, t, 2)[c] * b;
                org[c] = tg_range(&rng, -3.0f, 5.0f);
                dir[c] = target[c] - org[c];
            }
            struct trace_ray ray;
            trace_ray_init(&ray, org, dir, 0.0f);
            struct trace_hit h0, h1;
            memset(&h0, 0, sizeof(h0));
            memset(&h1, 0, sizeof(h1));
            const int f0 = ref->closest(bvh, tri, &ray, INFINITY, &h0, NULL);
            const int f1 = k->walk1(wide, 0)(wide, org, dir, 0.0f, INFINITY, &h1, NULL);
            hits += f0;
            if (f0 != f1 || (f0 && memcmp(&h0, &h1, sizeof(h0)) != 0))
                differ++;
        }
        printf("  %s: %s closest walk1 = scalar on %d of 20000 rays (%d hits)\n", what, k->name,
               20000 - differ, hits);
        failures += !CHECKF(differ == 0, "%s: %s: %d rays differ from the scalar table", what,
                            k->name, differ);
    }
}

static void check_layouts(void)
{
    tu_section("layouts");
    struct tg_rng rng;
    struct tg_mesh m;
    tg_seed(&rng, 9);
    tg_soup(&m, 6000, 2.0f, 0.2f, &rng);
    struct aabb *boxes = tg_boxes(&m);
    struct bvh bvh;
    if (accel_build(&bvh, boxes, m.tri_count, NULL)) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    float *tri = accel_gather_triangles(&bvh, m.pos, m.idx);
    struct bvh4 wide, wide4;
    if (!tri || accel_collapse_wide(&wide, &bvh, tri, 8) ||
        accel_collapse_wide(&wide4, &bvh, tri, 4)) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    /* The 4-wide layout has none (its walks do not read them). */
    failures += !CHECKF(wide4.record_raw.base == NULL && bvh4_record_bytes(&wide4) == 0,
                        "a 4-wide layout has records");
    check_layout_records(&wide, "soup, collapsed");
    check_rays(&m, &bvh, tri, &wide, "soup, collapsed");
    /* Every vertex moved (a twist and a stretch: every normal changes),
     * then both refits, as lib/scene/accel.c does. */
    for (uint32_t i = 0; i < m.vertex_count; i++) {
        float *p = &m.pos[3 * i];
        const float a = 0.7f * p[2];
        const float x = p[0] * cosf(a) - p[1] * sinf(a);
        const float y = p[0] * sinf(a) + p[1] * cosf(a);
        p[0] = x * 1.5f + 0.125f;
        p[1] = y;
        p[2] = p[2] * 0.75f + 0.25f * x;
    }
    accel_refit_mesh(&bvh, tri, m.pos, m.idx, NULL);
    failures += !CHECKF(accel_refit4(&wide, &bvh, tri) == 0, "the wide refit refused");
    check_layout_records(&wide, "soup, deformed and refitted");
    check_rays(&m, &bvh, tri, &wide, "soup, deformed and refitted");
    bvh4_release(&wide);
    bvh4_release(&wide4);
    rt_free(tri);
    free(boxes);
    bvh_release(&bvh);
    tg_mesh_free(&m);
}

int main(void)
{
    check_shapes();
    check_layouts();
    printf("  %s (%d failures)\n", failures ? "FAIL" : "ok", failures);
    return test_summary("tri4_record") | (failures ? 1 : 0);
}
