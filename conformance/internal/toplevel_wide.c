/* SPDX-License-Identifier: Apache-2.0 */
/*
 * toplevel_wide.c - the wide top level over instances (issue 11 item 2).
 *
 * A scene prepared with a wide layout (bvh_build_params.wide_layout 4 or
 * 8, what a context whose kernels walk 4 or 8 wide sets) has its top
 * level collapsed to that width with leaves of instance slots, and one
 * with wide_layout 0 (isa=scalar) has none.  The two-level walk over the
 * wide top level gives the binary top level's answers bit for bit (t,
 * u, v, primitive, instance; any hit) on many random rays over a scene
 * of many instances whose boxes coincide and overlap, with equal-t hits
 * between instances (duplicated instances, coplanar overlapping quads),
 * whose winner is the lower instance whatever the order of visits.
 *
 * Some instances have the identity matrix, whose rays the walks take
 * as the world rays without transforming them (trace_instance.identity):
 * the same scene with that flag cleared (every ray transformed) gives
 * the same answers, for rays with zero, negative-zero and tiny
 * components too; and 8-ray packets (trace_scene_closest_packet and
 * trace_scene_any_packet: one octant and finite origins test the top
 * level box by box, mixed octants ray by ray) give each ray the single
 * walk's answer.
 *
 * The tables' transform of a packet's rays into an instance's object
 * space (kernels.h packet_xform) gives trace_scene_object_ray's ray bit
 * for bit, and its refusals, on random matrices (inexact sums, scales
 * that overflow a direction to infinity or underflow it to zero) and
 * random rays (zero, negative-zero and subnormal components); and
 * packets over instances whose scales underflow or overflow some rays'
 * directions (such a ray skips that instance) give the single walk's
 * answers, with each table.
 *
 * And trace_scene_object_ray's shortcut for the identity
 * gives the bytes of its general path (the transform in double) for
 * every origin and direction built from zeros of both signs, tiny,
 * huge, infinite and NaN components: the shortcut takes only origins and
 * directions the transform gives back bit for bit (trace_scene_plain_class:
 * a -0.0 can come back +0.0), and only rows that are the identity's bit
 * for bit (a -0.0 in the rows can keep a -0.0).
 */
#include <rt/rt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scene/scene.h"
#include "scene/update.h"
#include "trace/kernels.h"
#include "trace/packet_scene.h"
#include "trace/scene_traverse.h"

static uint32_t rng_state = 12345u;

static float rnd(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (float)(rng_state >> 8) * 0x1p-24f;
}

/* Records triangles (9 doubles each) into a new object `name`. */
static struct scene_object *define(struct scene *scene, uint32_t name, const double *tris,
                                   int count)
{
    struct scene_recording rec;
    memset(&rec, 0, sizeof(rec));
    rec.material_index = -1;
    double identity[16];
    memset(identity, 0, sizeof(identity));
    identity[0] = identity[5] = identity[10] = identity[15] = 1.0;
    struct scene_block block;
    memset(&block, 0, sizeof(block));
    scene_block_start(&block, &rec, RT_TRIANGLES, identity);
    struct scene_material material;
    scene_material_default(&material);
    struct scene_triangle_state ts = {&material, 0, 0, 0};
    const float n[3] = {0, 0, 1}, c[4] = {1, 1, 1, 1}, st[4] = {0, 0, 0, 1};
    for (int i = 0; i < 3 * count; i++)
        CHECK(scene_record_vertex(&rec, &block, &ts, &tris[3 * i], n, c, st) ==
              SCENE_RECORD_OK);
    scene_mesh_compute_bounds(&rec.mesh);
    struct scene_object *object = scene_objects_get_or_create(&scene->objects, name);
    CHECK(object != NULL);
    if (object)
        scene_define_object(scene, object, &rec.mesh);
    return object;
}

/* The instances: object_to_world = translate(t) * R * scale(s), R a
 * rotation by a multiple of 90 degrees about z, s a power of two, so
 * the inverse is exact. */
struct placement {
    int object;
    double s;
    int quarter;
    double t[3];
    int positive_zeros; /* the inverse's zeros all +0.0 */
};

static void matrices(const struct placement *p, double o2w[16], double w2o[16])
{
    static const double cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    double c = cs[p->quarter][0], sn = cs[p->quarter][1];
    memset(o2w, 0, 16 * sizeof(double));
    memset(w2o, 0, 16 * sizeof(double));
    /* Column-major, as GL. */
    o2w[0] = c * p->s;
    o2w[1] = sn * p->s;
    o2w[4] = -sn * p->s;
    o2w[5] = c * p->s;
    o2w[10] = p->s;
    o2w[12] = p->t[0];
    o2w[13] = p->t[1];
    o2w[14] = p->t[2];
    o2w[15] = 1.0;
    /* Inverse: scale(1/s) * R^T * translate(-t). */
    double is = 1.0 / p->s;
    w2o[0] = c * is;
    w2o[1] = -sn * is;
    w2o[4] = sn * is;
    w2o[5] = c * is;
    w2o[10] = is;
    w2o[12] = -(w2o[0] * p->t[0] + w2o[4] * p->t[1]);
    w2o[13] = -(w2o[1] * p->t[0] + w2o[5] * p->t[1]);
    w2o[14] = -is * p->t[2];
    w2o[15] = 1.0;
    /* The identity's rows bit for bit (TRACE_IDENTITY_EXACT) rather than
     * with the -0.0 of -(0 + 0) (TRACE_IDENTITY_ZEROS). */
    if (p->positive_zeros)
        for (int k = 0; k < 16; k++)
            if (w2o[k] == 0.0)
                w2o[k] = 0.0;
}

enum { OBJECTS = 3, INSTANCES = 400 };

static void build_scene(struct scene *scene, const struct bvh_build_params *params, int cellsplit,
                        const struct placement *places, int count)
{
    scene_init(scene, params, 0, 0);
    scene->frame.toplevel_cellsplit = cellsplit;
    /* Object 0: the unit quad in z = 0; object 1: random triangles in the
     * unit cube; object 2: two triangles sharing the quad's plane. */
    static const double quad[18] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    double soup[9 * 24];
    uint32_t keep = rng_state;
    rng_state = 777u;
    for (int i = 0; i < 9 * 24; i++)
        soup[i] = (double)rnd();
    rng_state = keep;
    static const double half[18] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 0, 0, 0.5, 0, 0.5, 0, 0};
    struct scene_object *objects[OBJECTS] = {define(scene, 1, quad, 2), define(scene, 2, soup, 24),
                                             define(scene, 3, half, 2)};
    for (int i = 0; i < count; i++) {
        double o2w[16], w2o[16];
        matrices(&places[i], o2w, w2o);
        CHECK(scene_frame_add_instance(&scene->frame, objects[places[i].object], o2w, w2o, o2w) ==
              0);
    }
    struct scene_changes changes;
    CHECK(scene_prepare_toplevel(scene) == SCENE_OK);
    CHECK(scene_prepare_objects(scene, NULL, 100.0, &changes) == SCENE_OK);
}

/* The same `count` instances as a binary reference scene and a scene
 * with the 8-wide layout, default build parameters otherwise. */
static void build_binary_and_wide(struct scene *binary, struct scene *wide,
                                  const struct placement *places, int count)
{
    struct bvh_build_params params;
    bvh_build_params_default(&params);
    params.wide_layout = 0;
    build_scene(binary, &params, 0, places, count);
    params.wide_layout = 8;
    build_scene(wide, &params, 0, places, count);
}

static int acquire(void *user, void *object, struct trace_object_view *view)
{
    struct scene *scene = user;
    int built = 0;
    const struct scene_accel *accel = scene_object_acquire(object, &scene->update_config, &built);
    if (!accel)
        return 0;
    view->bvh = &accel->bvh;
    view->tri = accel->tri;
    view->wide = &accel->wide;
    return 1;
}

static struct trace_scene view_of(struct scene *scene, const struct trace_kernels *kernels,
                                  int wide)
{
    struct trace_scene ts;
    memset(&ts, 0, sizeof(ts));
    ts.top = &scene->frame.top;
    ts.instances = scene->frame.trace_instances;
    ts.acquire = acquire;
    ts.user = scene;
    ts.kernels = kernels;
    ts.top_wide = wide ? &scene->frame.top_wide : NULL;
    return ts;
}

static int same_hit(int got_a, const struct trace_scene_hit *a, int got_b,
                    const struct trace_scene_hit *b)
{
    if (got_a != got_b)
        return 0;
    if (!got_a)
        return 1;
    return memcmp(&a->t, &b->t, sizeof(float)) == 0 && memcmp(&a->u, &b->u, sizeof(float)) == 0 &&
           memcmp(&a->v, &b->v, sizeof(float)) == 0 && a->prim == b->prim &&
           a->instance == b->instance;
}

/* The packet's answers (got, any: closest and any-hit masks, hs: the
 * closest hits) against rs ray by ray: the mismatches, a lane outside
 * pk->active counting as one when it reports a hit.  Adds the
 * reference's hits to *hits. */
static long packet_mismatches(const struct trace_scene *rs, const struct trace_packet *pk,
                              unsigned got, unsigned any,
                              const struct trace_scene_hit hs[TRACE_PACKET], long *hits,
                              struct trace_scene_counters *c)
{
    long mismatches = 0;
    for (int i = 0; i < TRACE_PACKET; i++) {
        if (!(pk->active >> i & 1u)) {
            mismatches += (got >> i & 1u) || (any >> i & 1u);
            continue;
        }
        struct trace_scene_hit ref1;
        const int g = trace_scene_closest(rs, pk->org[i], pk->dir[i], pk->tmin[i], pk->tmax[i],
                                          &ref1, c);
        const int a = trace_scene_any(rs, pk->org[i], pk->dir[i], pk->tmin[i], pk->tmax[i], c);
        *hits += g;
        if (!same_hit(g, &ref1, (int)(got >> i & 1u), &hs[i]) || a != (int)(any >> i & 1u))
            mismatches++;
    }
    return mismatches;
}

/* A random double with 48 random mantissa bits, sign and a binary
 * exponent in [lo, hi]. */
static double rnd_double(int lo, int hi)
{
    const double m = 1.0 + (double)rnd() + (double)rnd() * 0x1p-24;
    const int e = lo + (int)(rnd() * (float)(hi - lo + 1));
    return (rnd() < 0.5f ? -1.0 : 1.0) * ldexp(m, e < hi ? e : hi);
}

/* A random float component: mostly ordinary, sometimes zero, negative
 * zero, subnormal, or of an extreme exponent. */
static float rnd_component(void)
{
    const float pick = rnd();
    if (pick < 0.05f)
        return 0.0f;
    if (pick < 0.10f)
        return -0.0f;
    if (pick < 0.15f)
        return (rnd() - 0.5f) * 0x1p-130f; /* subnormal */
    if (pick < 0.25f)
        return (float)rnd_double(-149, 127);
    return rnd() * 4.0f - 2.0f;
}

/* Each table's packet_xform against trace_scene_object_ray, ray by ray:
 * the same mask of usable rays and, for each, the same struct bit for
 * bit. */
static void check_packet_xform(void)
{
    const enum trace_isa isas[2] = {TRACE_ISA_AVX2, TRACE_ISA_AVX512};
    for (int t = 0; t < 2; t++) {
        const struct trace_kernels *k = trace_kernels_get(isas[t]);
        if (!k || !k->packet_xform)
            continue;
        long mismatches = 0, refused = 0, usable = 0, equal_world = 0;
        for (int it = 0; it < 20000; it++) {
            /* The matrix, column-major as trace_instance_set_rows takes
             * it: random inexact entries, the identity, a rotation and
             * scale by powers of two, or extreme scales. */
            double w2o[16];
            memset(w2o, 0, sizeof(w2o));
            w2o[15] = 1.0;
            const int kind = it % 8;
            for (int r = 0; r < 3; r++)
                for (int c = 0; c < 4; c++) {
                    double v;
                    if (kind == 0)
                        v = r == c ? 1.0 : 0.0;
                    else if (kind == 1)
                        v = r == c ? ldexp(1.0, (int)(rnd() * 5.0f) - 2) : 0.0;
                    else if (kind == 2)
                        v = rnd() < 0.3f ? 0.0 : rnd_double(-150, 150);
                    else if (kind == 3)
                        v = c == 3 ? rnd_double(-4, 4) : (r == c ? rnd_double(-160, -100) : 0.0);
                    else if (kind == 4)
                        v = c == 3 ? rnd_double(-4, 4) : (r == c ? rnd_double(100, 160) : 0.0);
                    else
                        v = rnd_double(-3, 3);
                    w2o[4 * c + r] = v;
                }
            struct trace_instance inst;
            memset(&inst, 0, sizeof(inst));
            trace_instance_set_rows(&inst, w2o);
            float org[TRACE_PACKET][3], dir[TRACE_PACKET][3], tmin[TRACE_PACKET];
            struct trace_ray world[TRACE_PACKET], ref[TRACE_PACKET], got[TRACE_PACKET];
            unsigned want = 0;
            const unsigned rays = it % 3 ? 0xFFu : (unsigned)(rnd() * 256.0f) & 0xFFu;
            for (int i = 0; i < TRACE_PACKET; i++) {
                for (int c = 0; c < 3; c++) {
                    org[i][c] = rnd() < 0.8f ? rnd() * 20.0f - 10.0f : rnd_component();
                    dir[i][c] = rnd_component();
                }
                if (dir[i][0] == 0.0f && dir[i][1] == 0.0f && dir[i][2] == 0.0f)
                    dir[i][2] = 1.0f; /* a traced world ray has a direction */
                tmin[i] = rnd() < 0.5f ? 0.0f : rnd();
                trace_ray_init(&world[i], org[i], dir[i], tmin[i]);
                if (rays >> i & 1u && trace_scene_object_ray(&inst, org[i], dir[i], tmin[i],
                                                             &world[i], &ref[i]))
                    want |= 1u << i;
            }
            memset(got, 0xA5, sizeof(got));
            const unsigned live = k->packet_xform(inst.world_to_object, (const float(*)[3])org,
                                                  (const float(*)[3])dir, tmin, rays, got);
            if (live != want)
                mismatches++;
            for (int i = 0; i < TRACE_PACKET; i++) {
                if (!(rays >> i & 1u))
                    continue;
                if (!(want >> i & 1u)) {
                    refused++;
                    continue;
                }
                usable++;
                equal_world += memcmp(&ref[i], &world[i], sizeof(ref[i])) == 0;
                if (live >> i & 1u && memcmp(&got[i], &ref[i], sizeof(ref[i])) != 0)
                    mismatches++;
            }
        }
        printf("packet_xform %s: %ld usable rays (%ld the world ray), %ld refused, "
               "%ld mismatches\n",
               k->name, usable, equal_world, refused, mismatches);
        CHECK(mismatches == 0);
        CHECK(refused > 1000 && usable > 50000 && equal_world > 1000);
    }
}

/* Packets over instances whose scales underflow or overflow some rays'
 * transformed directions: a floor scaled by 2^60 (world-to-object 2^-60:
 * a direction of magnitude 2^-100 becomes zero) among instances scaled
 * by 1/2 (world-to-object 2: a direction of 2^127 overflows to
 * infinity).  Such a ray skips that instance (trace_scene_object_ray
 * refuses it) and each packet's rays, through every table with a packet
 * walk, get the scalar single walk's answers. */
static void check_extreme_packets(void)
{
    enum { EXTREME = 48 };
    struct placement places[EXTREME];
    for (int i = 0; i < EXTREME; i++) {
        struct placement *p = &places[i];
        p->object = i % 6 == 0 ? 0 : (int)(rnd() * OBJECTS) % OBJECTS;
        p->s = i % 6 == 0 ? 0x1p60 : ldexp(1.0, (int)(rnd() * 3.0f) - 1);
        p->quarter = (int)(rnd() * 4.0f) % 4;
        for (int k = 0; k < 3; k++)
            p->t[k] = floor((double)rnd() * 16.0) * 0.5;
        if (i % 6 == 0) {
            /* The floor's corner far off, so that it lies under every
             * packet whatever its quarter turn. */
            p->t[0] = p->quarter == 1 || p->quarter == 2 ? 0x1p59 : -0x1p59;
            p->t[1] = p->quarter >= 2 ? 0x1p59 : -0x1p59;
            p->t[2] = -(double)i;
        }
    }
    struct scene ref_scene, wide_scene;
    build_binary_and_wide(&ref_scene, &wide_scene, places, EXTREME);
    const struct trace_kernels *tables[2] = {trace_kernels_best(),
                                             trace_kernels_get(TRACE_ISA_AVX2)};
    long mismatches = 0, hits = 0, underflow = 0, overflow = 0, packets = 0;
    for (int q = 0; q < 600; q++) {
        struct trace_packet pk;
        memset(&pk, 0, sizeof(pk));
        const int scale = q % 3 == 0 ? -100 : (q % 3 == 1 ? 127 : 0);
        const float o[3] = {rnd() * 14.0f - 2.0f, rnd() * 14.0f - 2.0f, 12.0f + rnd() * 4.0f};
        const float d[3] = {rnd() - 0.5f, rnd() - 0.5f, -1.0f};
        for (int i = 0; i < TRACE_PACKET; i++) {
            for (int k = 0; k < 3; k++) {
                pk.org[i][k] = o[k];
                pk.dir[i][k] = ldexpf(d[k] + (rnd() - 0.5f) * 0.05f, scale);
            }
            pk.tmin[i] = 0.0f;
            pk.tmax[i] = INFINITY;
            /* The (ray, instance) pairs whose direction cannot be traced. */
            struct trace_ray world, o_ray;
            trace_ray_init(&world, pk.org[i], pk.dir[i], 0.0f);
            for (uint32_t j = 0; j < wide_scene.frame.trace_instance_count; j++)
                if (!trace_scene_object_ray(&wide_scene.frame.trace_instances[j], pk.org[i],
                                            pk.dir[i], 0.0f, &world, &o_ray)) {
                    underflow += scale < 0;
                    overflow += scale > 0;
                }
        }
        pk.active = q % 5 == 4 ? 0x6Du : 0xFFu;
        for (int t = 0; t < 2; t++) {
            const struct trace_kernels *k = tables[t];
            if (!k || !k->closest_packet || (t == 1 && k == tables[0]))
                continue;
            packets++;
            struct trace_scene_counters c;
            memset(&c, 0, sizeof(c));
            struct trace_scene ts = view_of(&wide_scene, k, 1);
            struct trace_scene rs = view_of(&ref_scene, trace_kernels_get(TRACE_ISA_SCALAR), 0);
            struct trace_scene_hit hs[TRACE_PACKET];
            const unsigned got = trace_scene_closest_packet(&ts, &pk, hs, &c);
            const unsigned any = trace_scene_any_packet(&ts, &pk, &c);
            /* pk.tmin 0, pk.tmax infinite on every ray here. */
            mismatches += packet_mismatches(&rs, &pk, got, any, hs, &hits, &c);
        }
    }
    printf("extreme scales: %ld packets, %ld hits, %ld mismatches; (ray, instance) pairs "
           "refused: %ld underflowing, %ld overflowing\n",
           packets, hits, mismatches, underflow, overflow);
    CHECK(mismatches == 0);
    CHECK(underflow > 0 && overflow > 0);
    CHECK(packets == 0 || hits > 1000);
    scene_release(&ref_scene);
    scene_release(&wide_scene);
}

/* trace_packet_coherent's reference: its loop ray by ray. */
static int coherent_ref(const float *const dir[], int n)
{
    if (n < 2)
        return 0;
    const float *d0 = dir[0];
    const float l0 = d0[0] * d0[0] + d0[1] * d0[1] + d0[2] * d0[2];
    for (int i = 1; i < n; i++) {
        const float *d = dir[i];
        for (int k = 0; k < 3; k++)
            if (signbit(d[k]) != signbit(d0[k]))
                return 0;
        const float dot = d[0] * d0[0] + d[1] * d0[1] + d[2] * d0[2];
        const float l = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (!(dot > 0.0f) || !(dot * dot > 0.81f * l * l0))
            return 0;
    }
    return 1;
}

/* trace_packet_coherent (four rays a register) decides as its loop ray by
 * ray does, on directions near the 25-degree bound, with zeros of both
 * signs, tiny and huge components, for 1 to 8 rays. */
static void check_coherent(void)
{
    static const float odd[] = {0.0f, -0.0f, 1e-30f, -1e-40f, 3.0e38f, 1e20f, NAN, INFINITY};
    long differ = 0, yes = 0, total = 0;
    for (int q = 0; q < 200000; q++) {
        float d[TRACE_PACKET][3];
        const float *dirs[TRACE_PACKET];
        const float base[3] = {rnd() - 0.5f, rnd() - 0.5f, rnd() - 0.5f};
        const float spread = q % 4 == 0 ? 0.9f : (q % 4 == 1 ? 0.5f : 0.35f);
        for (int i = 0; i < TRACE_PACKET; i++) {
            for (int k = 0; k < 3; k++)
                d[i][k] = base[k] + (rnd() - 0.5f) * spread;
            dirs[i] = d[i];
        }
        if (q % 5 == 0)
            d[(int)(rnd() * TRACE_PACKET) % TRACE_PACKET][(int)(rnd() * 3.0f) % 3] =
                odd[(int)(rnd() * 8.0f) % 8];
        const int n = 1 + q % TRACE_PACKET;
        const int want = coherent_ref(dirs, n), got = trace_packet_coherent(dirs, n);
        differ += want != got;
        yes += want;
        total++;
    }
    printf("trace_packet_coherent: %ld sets, %ld coherent, %ld differ\n", total, yes, differ);
    CHECK(differ == 0);
    CHECK(yes > total / 20);
}

/* A top level of one leaf (a scene of one, two or three instances): the
 * packet walk visits the leaf's instances without the top level's box
 * test when every ray is of trace_scene_plain_class's exact class, and an
 * identity instance of the exact kind then walks its object from the
 * packet's arrays (packet_scene.c); every ray must still get the single
 * walk's answer, also in packets with a ray of zero, -0.0, tiny,
 * subnormal or huge components (rtTraceRays lets every finite component
 * through; a ray with a -0.0 takes the top level's walk), over
 * identity instances of both kinds and a transformed one. */
static void check_one_leaf_packets(void)
{
    static const float odd[] = {0.0f, -0.0f, 1e-30f, -1e-40f, 3.0e38f, -2.5e38f};
    enum { NODD = sizeof(odd) / sizeof(odd[0]) };
    struct placement places[3];
    memset(places, 0, sizeof(places));
    for (int i = 0; i < 3; i++) {
        places[i].object = i == 1 ? 1 : 0;
        places[i].s = 1.0;
    }
    places[0].positive_zeros = 1; /* TRACE_IDENTITY_EXACT */
    places[2].t[2] = -0.5;        /* transformed */
    /* Instance 1 keeps the -0.0 of -(0 + 0): TRACE_IDENTITY_ZEROS. */
    const struct trace_kernels *k = trace_kernels_best();
    const struct trace_kernels *scalar = trace_kernels_get(TRACE_ISA_SCALAR);
    long mismatches = 0, hits = 0, skipped = 0, packets = 0, leaves = 0;
    for (int count = 1; count <= 3; count++) {
        struct scene ref_scene, wide_scene;
        build_binary_and_wide(&ref_scene, &wide_scene, places, count);
        leaves += wide_scene.frame.top.nodes[0].count > 0;
        for (int q = 0; q < 2000; q++) {
            struct trace_packet pk;
            memset(&pk, 0, sizeof(pk));
            const float o[3] = {rnd() * 1.4f - 0.2f, rnd() * 1.4f - 0.2f, 3.0f + rnd()};
            for (int i = 0; i < TRACE_PACKET; i++) {
                for (int c = 0; c < 3; c++) {
                    pk.org[i][c] = o[c] + (rnd() - 0.5f) * 0.1f;
                    pk.dir[i][c] = c == 2 ? -1.0f : (rnd() - 0.5f) * 0.4f;
                }
                pk.tmin[i] = 0.0f;
                pk.tmax[i] = q % 7 == 6 && i % 2 ? 3.2f : INFINITY;
            }
            /* One component of one ray of every third packet odd. */
            if (q % 3 == 1) {
                const int i = (int)(rnd() * TRACE_PACKET) % TRACE_PACKET;
                const int c = (int)(rnd() * 6.0f) % 6;
                const float v = odd[(int)(rnd() * NODD) % NODD];
                if (c < 3)
                    pk.org[i][c] = v;
                else
                    pk.dir[i][c - 3] = v;
            }
            pk.active = q % 11 == 10 ? 0xB5u : 0xFFu;
            struct trace_scene_counters c;
            memset(&c, 0, sizeof(c));
            struct trace_scene ts = view_of(&wide_scene, k, 1);
            struct trace_scene_hit hs[TRACE_PACKET];
            const unsigned got = trace_scene_closest_packet(&ts, &pk, hs, &c);
            const unsigned any = trace_scene_any_packet(&ts, &pk, &c);
            packets++;
            skipped += c.top_node_tests == 0;
            struct trace_scene rs = view_of(&ref_scene, scalar, 0);
            mismatches += packet_mismatches(&rs, &pk, got, any, hs, &hits, &c);
        }
        scene_release(&ref_scene);
        scene_release(&wide_scene);
    }
    printf("one-leaf top level: %ld packets (%ld without a top-level test), %ld hits, %ld "
           "mismatches\n",
           packets, skipped, hits, mismatches);
    CHECK(mismatches == 0);
    CHECK(hits > 10000);
    CHECK(leaves == 2); /* one instance and two: a leaf; three: a node */
    /* The tables with the arrays entries skip the leaf's test for the
     * packets of plain rays (about two thirds). */
    if (k && k->closest_packet_arrays)
        CHECK(skipped > packets / 2);
}

/* trace_scene_object_ray with the identity flag against the same rows
 * without it, every combination of the components below. */
static long object_ray_mismatches(const double w2o[16], uint32_t *flagged)
{
    static const float z[] = {0.0f, -0.0f, 1.5f, -2.0f, 1e-30f, -1e-38f, 3.0e38f, INFINITY,
                              -INFINITY, NAN};
    enum { NZ = sizeof(z) / sizeof(z[0]) };
    struct trace_instance fast, slow;
    memset(&fast, 0, sizeof(fast));
    trace_instance_set_rows(&fast, w2o);
    slow = fast;
    slow.identity = 0;
    *flagged = fast.identity;
    long bad = 0;
    for (int i = 0; i < NZ * NZ * NZ; i++) {
        const float org[3] = {z[i % NZ], z[i / NZ % NZ], z[i / (NZ * NZ)]};
        for (int j = 0; j < NZ * NZ * NZ; j += 1 + j % 3) {
            const float dir[3] = {z[j / (NZ * NZ)], z[j % NZ], z[j / NZ % NZ]};
            struct trace_ray world, a, b;
            memset(&world, 0, sizeof(world));
            memset(&a, 0, sizeof(a));
            memset(&b, 0, sizeof(b));
            trace_ray_init_single(&world, org, dir, 0.25f);
            const int ga = trace_scene_object_ray(&fast, org, dir, 0.25f, &world, &a);
            const int gb = trace_scene_object_ray(&slow, org, dir, 0.25f, &world, &b);
            bad += ga != gb || (ga && memcmp(&a, &b, sizeof(a)) != 0);
        }
    }
    return bad;
}

int main(void)
{
    /* The identity shortcut's object rays, for the identity's rows and for
     * rows with a -0.0 (a translation by -0.0, a -0.0 off the diagonal). */
    double id[16];
    memset(id, 0, sizeof(id));
    id[0] = id[5] = id[10] = id[15] = 1.0;
    uint32_t flagged = 0;
    CHECK(object_ray_mismatches(id, &flagged) == 0);
    CHECK(flagged == TRACE_IDENTITY_EXACT);
    id[12] = -0.0;
    CHECK(object_ray_mismatches(id, &flagged) == 0);
    CHECK(flagged == TRACE_IDENTITY_ZEROS);
    id[12] = 0.0;
    id[1] = -0.0;
    CHECK(object_ray_mismatches(id, &flagged) == 0);
    CHECK(flagged == TRACE_IDENTITY_ZEROS);

    const struct trace_kernels *best = trace_kernels_best();
    const struct trace_kernels *scalar = trace_kernels_get(TRACE_ISA_SCALAR);
    check_packet_xform();
    struct placement places[INSTANCES];
    memset(places, 0, sizeof(places));
    for (int i = 0; i < INSTANCES; i++) {
        struct placement *p = &places[i];
        if (i >= 8 && i % 8 == 0) {
            /* An exact duplicate of an earlier instance: equal-t hits
             * across instances, the later one must lose. */
            *p = places[(int)(rnd() * (float)i)];
            continue;
        }
        p->object = (int)(rnd() * OBJECTS) % OBJECTS;
        p->s = ldexp(1.0, (int)(rnd() * 3.0f) - 1);
        p->quarter = (int)(rnd() * 4.0f) % 4;
        for (int k = 0; k < 3; k++)
            p->t[k] = floor((double)rnd() * 16.0) * 0.5;
        if (i % 5 == 1)
            p->t[2] = 2.0; /* coplanar quads in z = 2, overlapping */
        if (i % 7 == 3) {
            /* The identity: object space is world space. */
            p->s = 1.0;
            p->quarter = 0;
            p->t[0] = p->t[1] = p->t[2] = 0.0;
            p->positive_zeros = i % 14 == 3;
        }
    }

    struct bvh_build_params params;
    bvh_build_params_default(&params);
    int widths[3] = {0, 4, 8};
    for (int cellsplit = 0; cellsplit < 2; cellsplit++) {
        struct scene scenes[3];
        for (int w = 0; w < 3; w++) {
            params.wide_layout = widths[w];
            build_scene(&scenes[w], &params, cellsplit, places, INSTANCES);
        }
        /* Structure: the wide top level exists exactly when asked for, at
         * that width, over the same binary tree, with leaves of instance
         * slots and no packets. */
        CHECK(scenes[0].frame.top_wide.node_count == 0);
        for (int w = 1; w < 3; w++) {
            const struct bvh4 *tw = &scenes[w].frame.top_wide;
            CHECK(tw->width == (uint32_t)widths[w] && tw->node_count > 0);
            CHECK(tw->packet_count == 0);
            CHECK(tw->node_count < scenes[w].frame.top.node_count);
            CHECK(scenes[w].frame.top.node_count == scenes[0].frame.top.node_count &&
                  memcmp(scenes[w].frame.top.nodes, scenes[0].frame.top.nodes,
                         scenes[0].frame.top.node_count * sizeof(struct bvh_node)) == 0);
        }
        CHECK(scenes[0].frame.trace_instance_count == INSTANCES);
        /* The best scene's instances with the identity flag cleared: the
         * reference for the flag's shortcut. */
        uint32_t identities = 0, exact = 0;
        const uint32_t n_inst = scenes[2].frame.trace_instance_count;
        struct trace_instance *plain = malloc(n_inst * sizeof(*plain));
        CHECK(plain != NULL);
        if (!plain)
            return test_summary("toplevel_wide");
        memcpy(plain, scenes[2].frame.trace_instances, n_inst * sizeof(*plain));
        for (uint32_t i = 0; i < n_inst; i++) {
            identities += plain[i].identity != 0;
            exact += plain[i].identity == TRACE_IDENTITY_EXACT;
            plain[i].identity = 0;
        }
        CHECK(identities > exact && exact > 0 && identities < n_inst);
        long flag_mismatches = 0;

        long mismatches = 0, hits = 0, ties = 0;
        uint64_t top_tests[3] = {0, 0, 0};
        for (int r = 0; r < 20000; r++) {
            float org[3], dir[3];
            if (r % 4 == 0) {
                /* Straight down onto the coplanar quads (equal t). */
                org[0] = rnd() * 10.0f;
                org[1] = rnd() * 10.0f;
                org[2] = 20.0f;
                dir[0] = 0.0f;
                dir[1] = 0.0f;
                dir[2] = -1.0f;
            } else {
                for (int k = 0; k < 3; k++) {
                    org[k] = rnd() * 14.0f - 2.0f;
                    dir[k] = rnd() * 2.0f - 1.0f;
                }
                if (r % 4 == 1) {
                    /* Aimed at an instance's translation. */
                    const struct placement *p = &places[(int)(rnd() * INSTANCES) % INSTANCES];
                    for (int k = 0; k < 3; k++)
                        dir[k] = (float)p->t[k] + 0.25f - org[k];
                }
                if (r % 16 == 2) {
                    /* Zero, negative-zero and tiny components, which the
                     * identity's shortcut leaves to the transform. */
                    const int k = (int)(rnd() * 3.0f) % 3;
                    const float z[4] = {0.0f, -0.0f, 1e-30f, -1e-38f};
                    dir[k] = z[(int)(rnd() * 4.0f) % 4];
                    org[(k + 1) % 3] = z[(int)(rnd() * 4.0f) % 4];
                }
            }
            struct trace_scene_hit ref, h;
            struct trace_scene_counters c;
            memset(&c, 0, sizeof(c));
            struct trace_scene ts = view_of(&scenes[0], scalar, 0);
            int got_ref = trace_scene_closest(&ts, org, dir, 0.0f, INFINITY, &ref, &c);
            int any_ref = trace_scene_any(&ts, org, dir, 0.0f, INFINITY, &c);
            top_tests[0] += c.top_node_tests;
            hits += got_ref;
            CHECK(any_ref == got_ref);
            for (int w = 1; w < 3; w++) {
                for (int wide = 0; wide < 2; wide++) {
                    memset(&c, 0, sizeof(c));
                    ts = view_of(&scenes[w], best, wide);
                    int got = trace_scene_closest(&ts, org, dir, 0.0f, INFINITY, &h, &c);
                    int any = trace_scene_any(&ts, org, dir, 0.0f, INFINITY, &c);
                    if (wide)
                        top_tests[w] += c.top_node_tests;
                    if (!same_hit(got_ref, &ref, got, &h) || any != any_ref)
                        mismatches++;
                }
            }
            memset(&c, 0, sizeof(c));
            ts = view_of(&scenes[2], best, 1);
            ts.instances = plain;
            int got = trace_scene_closest(&ts, org, dir, 0.0f, INFINITY, &h, &c);
            int any = trace_scene_any(&ts, org, dir, 0.0f, INFINITY, &c);
            if (!same_hit(got_ref, &ref, got, &h) || any != any_ref)
                flag_mismatches++;
            /* An equal-t hit of a duplicated instance: the lower wins. */
            if (got_ref) {
                const struct placement *p = &places[ref.instance];
                for (uint32_t j = 0; j < ref.instance; j++)
                    ties += memcmp(&places[j], p, sizeof(*p)) == 0;
            }
        }
        printf("cellsplit %d: %ld hits of 20000, %ld mismatches, top node tests per ray "
               "binary %.2f wide4 %.2f wide8 %.2f\n",
               cellsplit, hits, mismatches, (double)top_tests[0] / 20000.0,
               (double)top_tests[1] / 20000.0, (double)top_tests[2] / 20000.0);
        CHECK(hits > 5000);
        CHECK(mismatches == 0);
        CHECK(flag_mismatches == 0);
        /* Packets of 8 rays against the single walk, ray by ray: from one
         * origin in one octant (the top level box by box), or mixed. */
        long wrong_packets = 0, packet_hits = 0;
        for (int q = 0; q < 3000; q++) {
            struct trace_packet pk;
            memset(&pk, 0, sizeof(pk));
            const int coherent = q % 3 != 0;
            const float o[3] = {rnd() * 14.0f - 2.0f, rnd() * 14.0f - 2.0f, 12.0f + rnd() * 4.0f};
            const float d[3] = {rnd() - 0.5f, rnd() - 0.5f, -1.0f};
            for (int i = 0; i < TRACE_PACKET; i++) {
                for (int k = 0; k < 3; k++) {
                    pk.org[i][k] = coherent ? o[k] : rnd() * 14.0f - 2.0f;
                    pk.dir[i][k] = coherent ? d[k] + (rnd() - 0.5f) * 0.05f : rnd() * 2.0f - 1.0f;
                }
                if (q % 5 == 4 && i == 3)
                    pk.dir[i][0] = -0.0f; /* a zero component in one ray */
                pk.tmin[i] = 0.0f;
                pk.tmax[i] = q % 7 == 6 && i % 2 ? 9.0f : INFINITY;
            }
            pk.active = q % 11 == 10 ? 0xB5u : 0xFFu;
            /* The best table over the 8-wide scene (its own top-level
             * tests where it has them), and SSE4.2's over the 4-wide one
             * (packet_scene.c's four rays a register); the first with the
             * identity flag cleared too. */
            const struct trace_instance *sets[3] = {scenes[2].frame.trace_instances, plain,
                                                    scenes[1].frame.trace_instances};
            const struct trace_kernels *sse4 = trace_kernels_get(TRACE_ISA_SSE4);
            for (int f = 0; f < 3; f++) {
                if (f == 2 && !sse4)
                    continue;
                struct trace_scene_counters c;
                memset(&c, 0, sizeof(c));
                struct trace_scene ts =
                    f == 2 ? view_of(&scenes[1], sse4, 1) : view_of(&scenes[2], best, 1);
                ts.instances = sets[f];
                struct trace_scene_hit hs[TRACE_PACKET];
                const unsigned got = trace_scene_closest_packet(&ts, &pk, hs, &c);
                const unsigned any = trace_scene_any_packet(&ts, &pk, &c);
                struct trace_scene rs = view_of(&scenes[0], scalar, 0);
                wrong_packets += packet_mismatches(&rs, &pk, got, any, hs, &packet_hits, &c);
            }
        }
        printf("packets: %ld hits, %ld mismatches; identity instances %u of %u\n", packet_hits,
               wrong_packets, identities, n_inst);
        CHECK(packet_hits > 20000);
        CHECK(wrong_packets == 0);
        free(plain);
        /* A winner never has an identical lower-indexed twin. */
        CHECK(ties == 0);
        /* The wide walk ran (tests counted per lane, a multiple of the
         * width) where the kernels walk a wide layout. */
        if (best->wide_width) {
            CHECK(top_tests[1] > 0 && top_tests[1] % 4 == 0);
            CHECK(top_tests[2] > 0 && top_tests[2] % 8 == 0);
        }
        for (int w = 0; w < 3; w++)
            scene_release(&scenes[w]);
    }
    check_extreme_packets();
    check_one_leaf_packets();
    check_coherent();
    return test_summary("toplevel_wide");
}
