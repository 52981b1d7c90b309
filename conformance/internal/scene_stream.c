/* SPDX-License-Identifier: Apache-2.0 */
/*
 * scene_stream.c - the two-level batch walk (lib/trace/scene_stream.h)
 * against the single-ray walk (trace_scene_closest / trace_scene_any),
 * ray by ray, bit for bit, with every counter of struct
 * trace_scene_counters, the views' ray counts (the automatic update
 * strategy's measured rays, which the public statistics do not show)
 * among them.
 *
 * Scene: a random soup (many leaves, 8-wide layout) as two objects with
 * their own ray-count targets, instanced four times in one top-level
 * leaf: object A as the identity (instance 0), object B rotated about z
 * (1), A again (2: coincident with 0, ties at equal t) and B rotated
 * again (3).  Rays: random, some with tmin > 0, a short tmax, tmin >=
 * tmax, -0.0 and 0.0 components (the single walk's other paths), in
 * batches of 1, 7, 255, 256, 257 and 1000 rays.  The AVX2 table, then
 * (stream_always) the AVX-512 table's two forms where the CPU runs
 * them.  The batch walk must take the stream here
 * (trace_scene_stream_ready) and must not where
 * the scene does not qualify: a layout without stream_pays under
 * stream=auto (stream_always 0), an instance under the hit filter, a
 * table without a stream.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh_build.h"
#include "accel_testgeo.h"
#include "base/alloc.h"
#include "check.h"
#include "trace/bvh4_layout.h"
#include "trace/kernels.h"
#include "trace/scene_stream.h"
#include "trace/scene_traverse.h"

struct object {
    struct bvh bvh;
    float *tri;
    struct bvh4 wide;
    uint64_t ray_count;
};

static int acquire(void *user, void *object, struct trace_object_view *view)
{
    (void)user;
    struct object *o = object;
    view->bvh = &o->bvh;
    view->tri = o->tri;
    view->wide = &o->wide;
    view->ray_count = &o->ray_count;
    return 1;
}

static int accept_none(void *user, const float org[3], const float dir[3],
                       const struct trace_scene_hit *hit)
{
    (void)user, (void)org, (void)dir, (void)hit;
    return 1;
}

/* Column-major 4x4 world-to-object matrix of a rotation by -a about z
 * (the inverse of the instance's rotation by a). */
static void rotation_inverse(double a, double m[16])
{
    memset(m, 0, 16 * sizeof(double));
    m[0] = cos(a);
    m[1] = -sin(a);
    m[4] = sin(a);
    m[5] = cos(a);
    m[10] = 1.0;
    m[15] = 1.0;
}

#define RAYS 6000

static void make_rays(float *rays, struct tg_rng *r)
{
    for (int i = 0; i < RAYS; i++) {
        float *v = rays + 8 * i;
        for (int k = 0; k < 3; k++) {
            v[k] = tg_range(r, -1.5f, 1.5f);
            v[4 + k] = tg_range(r, -1.0f, 1.0f);
        }
        v[3] = 0.0f;
        v[7] = INFINITY;
        switch (i % 9) {
        case 1:
            v[3] = tg_range(r, 0.0f, 0.5f);
            break;
        case 2:
            v[7] = tg_range(r, 0.05f, 0.6f);
            break;
        case 3:
            v[1] = -0.0f;
            break;
        case 4:
            v[6] = 0.0f;
            break;
        case 5:
            v[3] = 1.0f;
            v[7] = 1.0f; /* empty interval */
            break;
        default:
            break;
        }
    }
}

static const uint32_t batch_sizes[] = {1, 7, 255, 256, 257, 1000};

static int same_counters(const struct trace_scene_counters *a,
                         const struct trace_scene_counters *b)
{
    return a->rays == b->rays && a->instance_tests == b->instance_tests &&
           a->top_node_tests == b->top_node_tests &&
           a->object.node_tests == b->object.node_tests &&
           a->object.triangle_tests == b->object.triangle_tests;
}

/* The batch walk against the single walk over all rays, closest and any
 * hit; returns the failures. */
static int compare(const char *what, const struct trace_scene *scene, const float *rays,
                   struct object *objs)
{
    int failures = 0;
    struct trace_scene_hit *want = calloc(RAYS, sizeof(*want));
    struct trace_scene_hit *got = calloc(RAYS, sizeof(*got));
    unsigned char *want_found = calloc(RAYS, 1), *got_found = calloc(RAYS, 1);
    for (int any_hit = 0; any_hit < 2; any_hit++) {
        struct trace_scene_counters cs, cb;
        memset(&cs, 0, sizeof(cs));
        memset(&cb, 0, sizeof(cb));
        objs[0].ray_count = objs[1].ray_count = 0;
        for (int i = 0; i < RAYS; i++) {
            const float *v = rays + 8 * i;
            want_found[i] = (unsigned char)(any_hit
                                                ? trace_scene_any(scene, v, v + 4, v[3], v[7], &cs)
                                                : trace_scene_closest(scene, v, v + 4, v[3], v[7],
                                                                      &want[i], &cs));
        }
        trace_scene_flush_ray_count(&cs);
        const uint64_t want_rc[2] = {objs[0].ray_count, objs[1].ray_count};
        objs[0].ray_count = objs[1].ray_count = 0;
        memset(got, 0xA5, RAYS * sizeof(*got));
        memset(got_found, 0xA5, RAYS);
        uint32_t s = 0;
        for (uint32_t b = 0; b < RAYS; s++) {
            uint32_t n = batch_sizes[s % (sizeof(batch_sizes) / sizeof(batch_sizes[0]))];
            if (n > RAYS - b)
                n = RAYS - b;
            if (any_hit)
                trace_scene_any_batch(scene, rays + 8 * (size_t)b, 8, n, got_found + b, &cb);
            else
                trace_scene_closest_batch(scene, rays + 8 * (size_t)b, 8, n, got + b,
                                          got_found + b, &cb);
            b += n;
        }
        trace_scene_flush_ray_count(&cb);
        int differ = 0, found = 0;
        for (int i = 0; i < RAYS; i++) {
            found += want_found[i] != 0;
            int bad = got_found[i] != want_found[i];
            if (!bad && want_found[i] && !any_hit)
                bad = memcmp(&got[i], &want[i], sizeof(got[i])) != 0;
            if (bad && differ < 4)
                printf("    %s %s ray %d: found %d/%d t %a/%a instance %u/%u prim %u/%u\n", what,
                       any_hit ? "any" : "closest", i, got_found[i], want_found[i], got[i].t,
                       want[i].t, got[i].instance, want[i].instance, got[i].prim, want[i].prim);
            differ += bad;
        }
        printf("  %s %s: %d rays, %d answered, %d differ; rays %llu/%llu instance tests "
               "%llu/%llu node tests %llu/%llu triangle tests %llu/%llu ray counts %llu %llu / "
               "%llu %llu\n",
               what, any_hit ? "any" : "closest", RAYS, found, differ,
               (unsigned long long)cb.rays, (unsigned long long)cs.rays,
               (unsigned long long)cb.instance_tests, (unsigned long long)cs.instance_tests,
               (unsigned long long)(cb.top_node_tests + cb.object.node_tests),
               (unsigned long long)(cs.top_node_tests + cs.object.node_tests),
               (unsigned long long)cb.object.triangle_tests,
               (unsigned long long)cs.object.triangle_tests,
               (unsigned long long)objs[0].ray_count, (unsigned long long)objs[1].ray_count,
               (unsigned long long)want_rc[0], (unsigned long long)want_rc[1]);
        failures += !CHECKF(differ == 0, "%s: %d answers differ", what, differ);
        failures += !CHECKF(same_counters(&cb, &cs), "%s: the counters differ", what);
        failures += !CHECKF(objs[0].ray_count == want_rc[0] && objs[1].ray_count == want_rc[1],
                            "%s: the views' ray counts differ", what);
        failures += !CHECKF(found > RAYS / 5, "%s: too few rays answered (%d)", what, found);
    }
    free(want);
    free(got);
    free(want_found);
    free(got_found);
    return failures;
}

int main(void)
{
    printf("scene_stream:\n");
    const struct trace_kernels *k = trace_kernels_get(TRACE_ISA_AVX2);
    if (!k || !k->stream_counted) {
        printf("  no AVX2 table with the stream on this build or CPU: nothing to compare\n");
        return test_summary("scene_stream");
    }
    struct tg_rng r;
    tg_seed(&r, 61);
    struct tg_mesh m;
    tg_soup(&m, 20000, 2.0f, 0.2f, &r);
    /* Centred on the origin, so that the rotation keeps the instances
     * overlapping. */
    for (uint32_t i = 0; i < 3 * m.tri_count; i++)
        for (int c = 0; c < 3; c++)
            m.pos[3 * i + (uint32_t)c] -= 1.0f;
    struct object objs[2];
    for (int o = 0; o < 2; o++) {
        struct aabb *boxes = tg_boxes(&m);
        objs[o].ray_count = 0;
        if (accel_build(&objs[o].bvh, boxes, m.tri_count, NULL) ||
            !(objs[o].tri = accel_gather_triangles(&objs[o].bvh, m.pos, m.idx)) ||
            accel_collapse_wide(&objs[o].wide, &objs[o].bvh, objs[o].tri, 8)) {
            fprintf(stderr, "out of memory\n");
            return 1;
        }
        free(boxes);
    }
    struct trace_instance inst[4];
    memset(inst, 0, sizeof(inst));
    double id[16], rot[16];
    memset(id, 0, sizeof(id));
    id[0] = id[5] = id[10] = id[15] = 1.0;
    rotation_inverse(0.5235987755982988, rot);
    for (uint32_t i = 0; i < 4; i++) {
        trace_instance_set_rows(&inst[i], i % 2 ? rot : id);
        inst[i].instance_id = i;
        inst[i].object = &objs[i % 2];
    }
    CHECK(inst[0].identity == TRACE_IDENTITY_EXACT && inst[1].identity == 0);
    struct bvh_node node;
    memset(&node, 0, sizeof(node));
    for (int c = 0; c < 3; c++) {
        node.aabb_min[c] = -4.0f;
        node.aabb_max[c] = 4.0f;
    }
    node.first = 0;
    node.count = 4;
    uint32_t prim_index[4] = {0, 1, 2, 3};
    struct bvh top = {&node, 1, prim_index, 4, 0};
    struct trace_scene scene;
    memset(&scene, 0, sizeof(scene));
    scene.top = &top;
    scene.instances = inst;
    scene.acquire = acquire;
    scene.kernels = k;
    scene.stream_always = 1;
    float *rays = malloc(8 * sizeof(float) * RAYS);
    make_rays(rays, &r);
    int failures = 0;

    CHECK(trace_scene_stream_ready(&scene, 0) && trace_scene_stream_ready(&scene, 1));
    failures += compare("stream_always", &scene, rays, objs);

    /* The AVX-512 table's two forms (kernels.h, trace_kernels_avx512_ctz),
     * which take the AVX2 stream under their own single-ray walks: the
     * same comparison, each against its own walk and counters, where
     * this CPU runs the table.  Both forms, as internal/kernel_bits does:
     * round 61's merge left one form without the stream and no test saw
     * it (docs/performance-log.md, "round 61's merge"). */
    const struct trace_kernels *avx512 = trace_kernels_get(TRACE_ISA_AVX512);
    if (avx512) {
        const struct trace_kernels *forms[2] = {trace_kernels_avx512(),
                                                trace_kernels_avx512_ctz()};
        for (int f = 0; f < 2; f++) {
            CHECKF(forms[f] && forms[f]->stream_counted, "avx512 form %d without the stream",
                   f);
            if (!forms[f] || !forms[f]->stream_counted)
                continue;
            scene.kernels = forms[f];
            CHECK(trace_scene_stream_ready(&scene, 0) && trace_scene_stream_ready(&scene, 1));
            failures += compare(f ? "stream_always, avx512 ctz" : "stream_always, avx512",
                                &scene, rays, objs);
        }
        scene.kernels = k;
    } else {
        printf("  no AVX-512 table on this build or CPU: its stream not compared\n");
    }

    /* stream=auto on layouts below BVH_WIDE_STREAM_BYTES: ray by ray. */
    CHECK(!objs[0].wide.stream_pays && !objs[1].wide.stream_pays);
    scene.stream_always = 0;
    CHECK(!trace_scene_stream_ready(&scene, 0));
    failures += compare("auto, small layouts", &scene, rays, objs);
    objs[0].wide.stream_pays = objs[1].wide.stream_pays = 1;
    CHECK(trace_scene_stream_ready(&scene, 0));
    failures += compare("auto, flagged layouts", &scene, rays, objs);

    /* An instance under the hit filter: ray by ray. */
    uint8_t filtered[4] = {0, 0, 1, 0};
    scene.filtered = filtered;
    scene.filter_mask = 1;
    scene.accept = accept_none;
    CHECK(!trace_scene_stream_ready(&scene, 0));
    failures += compare("filtered", &scene, rays, objs);
    scene.filtered = NULL;

    /* A table without the stream: ray by ray. */
    struct trace_kernels no_stream = *k;
    no_stream.stream_pair = NULL;
    no_stream.stream_counted = NULL;
    scene.kernels = &no_stream;
    CHECK(!trace_scene_stream_ready(&scene, 0));
    failures += compare("no stream", &scene, rays, objs);

    printf("  %d comparisons failed\n", failures);
    free(rays);
    for (int o = 0; o < 2; o++) {
        bvh4_release(&objs[o].wide);
        rt_free(objs[o].tri);
        bvh_release(&objs[o].bvh);
    }
    tg_mesh_free(&m);
    return test_summary("scene_stream");
}
