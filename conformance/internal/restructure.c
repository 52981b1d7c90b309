/* SPDX-License-Identifier: Apache-2.0 */
/*
 * restructure.c - selective restructuring (lib/accel/restructure.h, Yoon, Curtis and Manocha
 * (2007)) on deforming meshes, frame by frame.
 *
 * Scenes (fixed seeds): a tessellated sphere whose triangles fly apart
 * (radial speeds that differ per triangle plus a tangential drift), a
 * triangle soup morphing between two unrelated random configurations, a
 * cloth-like grid with a travelling wave of growing amplitude, and a
 * sphere of which only a cap explodes (Yoon, Curtis and Manocha (2007) fig. 9-10: "only a small
 * subset of the geometric primitives are moving").  After every frame's
 * accel_restructure (with the fixed default constants, so the decisions
 * do not depend on the clock):
 *   - bvh_layout.h's contract, as conformance/internal/builders.c checks it, plus
 *     parent-first numbering (the reverse-sweep refit relies on it);
 *   - closest hits equal to trace_closest_brute_force on random rays and
 *     on rays aimed at vertices (same primitive with bit-identical t, or a
 *     tie within 1e-6 relative), as conformance/internal/traversal.c;
 *   - the reported costs: sah_before equals accel_sah_cost(1, C_leaf) of a
 *     plain refit of the same tree, sah_after that of the result, and with
 *     verify_cost the result never costs more than the plain refit;
 *   - quality against a refit-only tree (built at frame 0, only refitted)
 *     and a fresh binned SAH build per frame, printed per frame.
 *     Documented behaviour: with the default 512^2 rays the whole-object
 *     deformations (sphere, soup, and also the cloth) are restructured at
 *     the root pair, i.e. rebuilt, every frame, and stay within
 *     RESTRUCTURE_EXPLODE_BOUND of a fresh build while the refit-only tree
 *     reaches 3-50 times its cost; with about as many rays as triangles
 *     the local explosion is restructured around the cap only on most
 *     frames.  Restructuring recovers most of the refit's loss
 *     (RESTRUCTURE_RECOVERY_BOUND).
 * Then: the paper's rule without the cost check (verify_cost 0), no rays
 * (pure refit), NULL params and stats, determinism, a BVH numbered
 * children-before-parents, tiny and degenerate inputs, NaN and infinite
 * boxes, a hand-made caterpillar tree at BVH_MAX_DEPTH where deep
 * restructurings must be skipped, every allocation failure (the BVH must
 * be the plain refit and the state usable afterwards), and the machine
 * constants' measurement (finite, positive, fast).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh_build.h"
#include "accel/restructure.h"
#include "accel_testgeo.h"
#include "base/alloc.h"
#include "base/timer.h"
#include "trace/trace.h"

/* The restructured tree's cost over a fresh binned build's, at most, on
 * every frame of the exploding and morphing scenes; the refit-only tree
 * reaches 3-50 there (the table in the output). */
#define RESTRUCTURE_EXPLODE_BOUND 1.5
/* The same for the cloth, which a refit alone keeps within ~1.25. */
#define RESTRUCTURE_CLOTH_BOUND 1.3
/* Final-frame cost of the restructured tree over the refit-only tree's,
 * at most: restructuring must recover most of what the refit lost. */
#define RESTRUCTURE_RECOVERY_BOUND 0.5
/* Rays per frame for the local explosion: about the triangle count. */
#define RESTRUCTURE_LOCAL_RAYS 16384.0
/* Rays checked against the brute-force reference per frame. */
#define RAYS_PER_FRAME 300

static int failures;

#include "bvh_contract.h"

/* ------------------------------------------------------------ contract */

/* bvh_layout.h's contract for n primitives with boxes (bvh_contract.h), leaves
 * of at most BVH_MAX_LEAF_SIZE; finite == 0 (boxes with NaN) skips box
 * containment. */
static void check_tree_boxes(const char *what, const struct bvh *b, const struct aabb *boxes,
                             uint32_t n, int finite)
{
    bvh_check_tree(what, b, boxes, n, BVH_MAX_LEAF_SIZE, finite);
}

static void check_tree(const char *what, const struct bvh *b, const struct aabb *boxes, uint32_t n)
{
    check_tree_boxes(what, b, boxes, n, 1);
}

/* A plain refit, written independently of lib/accel: post-order walk. */
static void refit_box(struct bvh *b, const struct aabb *boxes, uint32_t ni)
{
    struct bvh_node *n = &b->nodes[ni];
    struct aabb box = aabb_empty();
    if (n->count) {
        for (uint32_t s = n->first; s < n->first + n->count; s++)
            aabb_grow(&box, &boxes[b->prim_index[s]]);
    } else {
        refit_box(b, boxes, n->first);
        refit_box(b, boxes, n->first + 1);
        for (uint32_t c = n->first; c <= n->first + 1; c++) {
            struct aabb cb;
            memcpy(cb.min, b->nodes[c].aabb_min, sizeof(cb.min));
            memcpy(cb.max, b->nodes[c].aabb_max, sizeof(cb.max));
            aabb_grow(&box, &cb);
        }
    }
    memcpy(n->aabb_min, box.min, sizeof(box.min));
    memcpy(n->aabb_max, box.max, sizeof(box.max));
}

static void copy_bvh(struct bvh *dst, const struct bvh *src)
{
    *dst = *src;
    dst->nodes = tg_alloc(sizeof(*dst->nodes) * (src->node_count ? src->node_count : 1));
    dst->prim_index = tg_alloc(sizeof(uint32_t) * (src->prim_count ? src->prim_count : 1));
    if (src->node_count)
        memcpy(dst->nodes, src->nodes, sizeof(*dst->nodes) * src->node_count);
    if (src->prim_count)
        memcpy(dst->prim_index, src->prim_index, sizeof(uint32_t) * src->prim_count);
}

static void free_copy(struct bvh *b)
{
    free(b->nodes);
    free(b->prim_index);
    memset(b, 0, sizeof(*b));
}

static int same_tree(const struct bvh *a, const struct bvh *b)
{
    return a->node_count == b->node_count && a->prim_count == b->prim_count &&
           a->depth == b->depth &&
           memcmp(a->nodes, b->nodes, sizeof(*a->nodes) * a->node_count) == 0 &&
           memcmp(a->prim_index, b->prim_index, sizeof(uint32_t) * a->prim_count) == 0;
}

/* ------------------------------------------------------------ hits */

/* Closest hits against the brute-force reference: random rays through
 * the scene's padded bounds, and rays aimed at vertices. */
static void check_hits(const char *what, const struct tg_mesh *m, const struct bvh *bvh,
                       struct tg_rng *r)
{
    float *tri = accel_gather_triangles(bvh, m->pos, m->idx);
    failures += !CHECKF(tri != NULL, "%s: gather", what);
    if (!tri)
        return;
    struct aabb box = aabb_empty();
    for (uint32_t v = 0; v < m->vertex_count; v++)
        aabb_grow_point(&box, &m->pos[3 * v]);
    int before = failures;
    for (int i = 0; i < RAYS_PER_FRAME && failures - before < 5; i++) {
        float org[3];
        float dir[3];
        for (int k = 0; k < 3; k++) {
            float pad = 0.3f * (box.max[k] - box.min[k]) + 0.01f;
            org[k] = tg_range(r, box.min[k] - pad, box.max[k] + pad);
            dir[k] = tg_range(r, -1.0f, 1.0f);
        }
        if (i % 2) {
            const float *v = &m->pos[3 * tg_below(r, m->vertex_count)];
            for (int k = 0; k < 3; k++)
                dir[k] = v[k] + 0.01f * tg_range(r, -1.0f, 1.0f) - org[k];
        }
        if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f)
            dir[0] = 1.0f;
        struct trace_ray ray;
        trace_ray_init(&ray, org, dir, 0.0f);
        struct trace_hit ref;
        struct trace_hit h;
        int found_ref = trace_closest_brute_force(m->pos, m->idx, m->tri_count, &ray, INFINITY, &ref);
        int found = trace_closest(bvh, tri, &ray, INFINITY, &h, NULL);
        failures += !CHECKF(found == found_ref, "%s ray %d: found %d, reference %d", what, i, found,
                 found_ref);
        if (!found || !found_ref)
            continue;
        if (h.prim == ref.prim)
            failures += !CHECKF(h.t == ref.t && h.u == ref.u && h.v == ref.v,
                     "%s ray %d: prim %u t %.9g vs %.9g", what, i, h.prim, h.t, ref.t);
        else
            failures += !CHECKF(h.t >= ref.t && h.t - ref.t <= 1e-6f * fabsf(ref.t),
                     "%s ray %d: prim %u t=%.9g, reference prim %u t=%.9g", what, i, h.prim, h.t,
                     ref.prim, ref.t);
    }
    rt_free(tri);
}

/* ------------------------------------------------------------ scenes */

struct anim {
    const char *name;
    struct tg_mesh mesh;
    float *base;  /* positions at frame 0 */
    float *extra; /* per-scene motion data */
    uint32_t frames;
    uint32_t partial_frames; /* frames that restructured less than half the primitives */
    void (*pose)(struct anim *a, uint32_t frame);
};

/* The sphere as a soup (three vertices per triangle) so that its
 * triangles can separate. */
static void soup_of(struct tg_mesh *soup, const struct tg_mesh *m)
{
    tg_mesh_alloc(soup, 3 * m->tri_count, m->tri_count);
    for (uint32_t t = 0; t < m->tri_count; t++) {
        for (int c = 0; c < 3; c++) {
            memcpy(&soup->pos[9 * t + 3 * c], tg_vertex(m, t, c), 3 * sizeof(float));
            soup->idx[3 * t + c] = 3 * t + (uint32_t)c;
        }
    }
}

/* Each triangle moves by frame * (radial direction * speed + drift), its
 * velocity drawn once: speeds 0.5..1.5, drift up to 0.4 per axis.  With
 * cap > -1 only the triangles whose centre lies above z = cap (on the
 * unit sphere) move: a local explosion, the case selective restructuring
 * is made for (Yoon, Curtis and Manocha (2007) fig. 9 and 10: "only a small subset of the
 * geometric primitives are moving"). */
static void explode_pose(struct anim *a, uint32_t frame)
{
    float t = 0.35f * (float)frame;
    for (uint32_t i = 0; i < a->mesh.tri_count; i++) {
        const float *vel = &a->extra[3 * i];
        for (int c = 0; c < 3; c++) {
            for (int k = 0; k < 3; k++) {
                size_t at = 9 * (size_t)i + 3 * (size_t)c + (size_t)k;
                a->mesh.pos[at] = a->base[at] + t * vel[k];
            }
        }
    }
}

static void make_explode(struct anim *a, int g, uint32_t frames, float cap, struct tg_rng *r)
{
    const double origin[3] = {0.0, 0.0, 0.0};
    struct tg_mesh sphere;
    tg_cube_sphere(&sphere, g, 1, 1.0, origin);
    soup_of(&a->mesh, &sphere);
    tg_mesh_free(&sphere);
    uint32_t n = a->mesh.tri_count;
    a->name = cap > -1.0f ? "cap explodes" : "sphere explodes";
    a->frames = frames;
    a->partial_frames = 0;
    a->pose = explode_pose;
    a->base = tg_alloc(sizeof(float) * 9 * (size_t)n);
    memcpy(a->base, a->mesh.pos, sizeof(float) * 9 * (size_t)n);
    a->extra = tg_alloc(sizeof(float) * 3 * (size_t)n);
    for (uint32_t i = 0; i < n; i++) {
        float c[3] = {0.0f, 0.0f, 0.0f};
        for (int v = 0; v < 3; v++)
            for (int k = 0; k < 3; k++)
                c[k] += a->base[9 * i + 3 * v + k] / 3.0f;
        float len = sqrtf(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        float speed = tg_range(r, 0.5f, 1.5f);
        for (int k = 0; k < 3; k++)
            a->extra[3 * i + k] = c[k] / len * speed + tg_range(r, -0.4f, 0.4f);
        if (c[2] / len <= cap)
            memset(&a->extra[3 * i], 0, 3 * sizeof(float));
    }
}

/* A travelling wave whose amplitude grows with the frame. */
static void cloth_pose(struct anim *a, uint32_t frame)
{
    float amp = 0.02f + 0.03f * (float)frame;
    float phase = 0.7f * (float)frame;
    for (uint32_t v = 0; v < a->mesh.vertex_count; v++) {
        const float *p = &a->base[3 * v];
        float *q = &a->mesh.pos[3 * v];
        q[0] = p[0];
        q[2] = p[2] + 0.3f * amp * sinf(9.0f * p[0] + phase);
        q[1] = amp * sinf(6.0f * p[0] + phase) * cosf(5.0f * p[2] - 0.5f * phase);
    }
}

static void make_cloth(struct anim *a, int g, uint32_t frames, struct tg_rng *r)
{
    tg_terrain(&a->mesh, g, r);
    for (uint32_t v = 0; v < a->mesh.vertex_count; v++)
        a->mesh.pos[3 * v + 1] = 0.0f;
    a->name = "cloth waves";
    a->frames = frames;
    a->partial_frames = 0;
    a->pose = cloth_pose;
    a->base = tg_alloc(sizeof(float) * 3 * (size_t)a->mesh.vertex_count);
    memcpy(a->base, a->mesh.pos, sizeof(float) * 3 * (size_t)a->mesh.vertex_count);
    a->extra = NULL;
}

/* Linear morph from the soup's first configuration to a second,
 * unrelated one (every triangle moves to a random place). */
static void morph_pose(struct anim *a, uint32_t frame)
{
    float t = (float)frame / (float)(a->frames - 1);
    size_t n = 9 * (size_t)a->mesh.tri_count;
    for (size_t i = 0; i < n; i++)
        a->mesh.pos[i] = (1.0f - t) * a->base[i] + t * a->extra[i];
}

static void make_morph(struct anim *a, uint32_t n, uint32_t frames, struct tg_rng *r)
{
    tg_soup(&a->mesh, n, 1.0f, 0.03f, r);
    struct tg_mesh other;
    tg_soup(&other, n, 1.0f, 0.03f, r);
    a->name = "soup morphs";
    a->frames = frames;
    a->partial_frames = 0;
    a->pose = morph_pose;
    a->base = tg_alloc(sizeof(float) * 9 * (size_t)n);
    memcpy(a->base, a->mesh.pos, sizeof(float) * 9 * (size_t)n);
    a->extra = tg_alloc(sizeof(float) * 9 * (size_t)n);
    memcpy(a->extra, other.pos, sizeof(float) * 9 * (size_t)n);
    tg_mesh_free(&other);
}

static void free_anim(struct anim *a)
{
    tg_mesh_free(&a->mesh);
    free(a->base);
    free(a->extra);
}

static double tree_cost(const struct bvh *b, float c_leaf)
{
    return accel_sah_cost(b, 1.0f, c_leaf);
}

static int close_to(double a, double b)
{
    return fabs(a - b) <= 1e-5 * fabs(b) + 1e-9;
}

/* Runs an animation; returns the last frame's restructured/refit-only
 * cost ratio. */
static double run_anim(struct anim *a, const struct accel_restructure_params *params,
                       double fresh_bound, struct tg_rng *r)
{
    char what[96];
    struct aabb *boxes = tg_boxes(&a->mesh);
    struct bvh bvh;
    if (accel_build(&bvh, boxes, a->mesh.tri_count, NULL)) {
        failures += !CHECKF(0, "%s: initial build", a->name);
        free(boxes);
        return 1.0;
    }
    struct bvh refit_only;
    copy_bvh(&refit_only, &bvh);
    struct accel_restructure_state state;
    accel_restructure_state_init(&state);
    const float c_leaf = params->c_leaf;
    double last_ratio = 1.0;
    printf("  %s: %u triangles, %.0f rays, verify_cost %d\n"
           "    frame  refit/fresh  restr/fresh  ops  prims  pairs  heap   ms: restr  fresh\n",
           a->name, a->mesh.tri_count, params->rays_per_frame, params->verify_cost);
    for (uint32_t frame = 1; frame < a->frames; frame++) {
        a->pose(a, frame);
        free(boxes);
        boxes = tg_boxes(&a->mesh);
        snprintf(what, sizeof(what), "%s frame %u", a->name, frame);

        /* The same tree refitted only, before this frame's restructuring:
         * sah_before must be its cost. */
        struct bvh pre;
        copy_bvh(&pre, &bvh);
        refit_box(&pre, boxes, 0);
        double pre_cost = tree_cost(&pre, c_leaf);
        free_copy(&pre);

        struct accel_restructure_stats stats;
        int rc = accel_restructure(&bvh, boxes, &state, params, &stats);
        failures += !CHECKF(rc == 0, "%s: accel_restructure returned %d", what, rc);
        check_tree(what, &bvh, boxes, a->mesh.tri_count);
        check_hits(what, &a->mesh, &bvh, r);

        double cost = tree_cost(&bvh, c_leaf);
        failures += !CHECKF(close_to(stats.sah_before, pre_cost), "%s: sah_before %.6f, refit %.6f",
                 what, stats.sah_before, pre_cost);
        failures += !CHECKF(close_to(stats.sah_after, cost), "%s: sah_after %.6f, tree %.6f", what,
                 stats.sah_after, cost);
        if (params->verify_cost)
            failures += !CHECKF(stats.restructures == 0 || cost <= pre_cost * (1.0 + 1e-6),
                     "%s: restructured cost %.6f above the refit's %.6f", what, cost, pre_cost);
        if (stats.restructures == 0)
            failures += !CHECKF(close_to(cost, pre_cost), "%s: nothing restructured but cost moved",
                     what);

        refit_box(&refit_only, boxes, 0);
        double refit_cost = tree_cost(&refit_only, c_leaf);
        struct bvh fresh;
        double t0 = rt_now_ms();
        int fr = accel_build(&fresh, boxes, a->mesh.tri_count, NULL);
        double fresh_ms = rt_now_ms() - t0;
        double fresh_cost = fr ? 1.0 : tree_cost(&fresh, c_leaf);
        if (!fr)
            bvh_release(&fresh);
        printf("    %5u %12.3f %12.3f %4u %6u %6u %5u %10.2f %6.2f\n", frame,
               refit_cost / fresh_cost, cost / fresh_cost, stats.restructures,
               stats.prims_restructured, stats.pairs_examined, stats.pairs_candidates,
               stats.ms_total, fresh_ms);
        if (stats.restructures > 0 && stats.prims_restructured < a->mesh.tri_count / 2)
            a->partial_frames++;
        if (fresh_bound > 0.0)
            failures += !CHECKF(cost <= fresh_bound * fresh_cost,
                     "%s: cost %.3f is %.2f x a fresh build's", what, cost, cost / fresh_cost);
        last_ratio = cost / refit_cost;
    }
    accel_restructure_state_release(&state);
    free_copy(&refit_only);
    bvh_release(&bvh);
    free(boxes);
    return last_ratio;
}

/* ------------------------------------------------------------ special cases */

/* Rays 0: only the refit; the result equals the independent refit. */
static void check_no_rays(struct tg_rng *r)
{
    struct anim a;
    make_morph(&a, 2000, 4, r);
    struct aabb *boxes = tg_boxes(&a.mesh);
    struct bvh bvh;
    if (accel_build(&bvh, boxes, a.mesh.tri_count, NULL) == 0) {
        struct accel_restructure_params p;
        accel_restructure_params_default(&p);
        p.rays_per_frame = 0.0;
        struct accel_restructure_state st;
        accel_restructure_state_init(&st);
        a.pose(&a, 3);
        free(boxes);
        boxes = tg_boxes(&a.mesh);
        struct bvh expect;
        copy_bvh(&expect, &bvh);
        refit_box(&expect, boxes, 0);
        struct accel_restructure_stats s;
        failures += !CHECKF(accel_restructure(&bvh, boxes, &st, &p, &s) == 0, "no rays");
        failures += !CHECKF(s.restructures == 0 && s.pairs_candidates == 0 && same_tree(&bvh, &expect),
                 "no rays: %u restructures, tree differs from the refit", s.restructures);
        /* NULL params and NULL stats are accepted. */
        failures += !CHECKF(accel_restructure(&bvh, boxes, &st, NULL, NULL) == 0, "NULL params");
        check_tree("NULL params", &bvh, boxes, a.mesh.tri_count);
        free_copy(&expect);
        accel_restructure_state_release(&st);
        accel_restructure_state_release(&st); /* safe twice */
        bvh_release(&bvh);
    }
    free(boxes);
    free_anim(&a);
}

/* Determinism: two runs from the same build give the same trees. */
static void check_deterministic(struct tg_rng *r)
{
    struct anim a;
    make_explode(&a, 10, 4, -2.0f, r);
    struct aabb *boxes = tg_boxes(&a.mesh);
    struct bvh t[2];
    struct accel_restructure_state st[2];
    for (int i = 0; i < 2; i++) {
        accel_build(&t[i], boxes, a.mesh.tri_count, NULL);
        accel_restructure_state_init(&st[i]);
    }
    for (uint32_t f = 1; f < a.frames; f++) {
        a.pose(&a, f);
        free(boxes);
        boxes = tg_boxes(&a.mesh);
        for (int i = 0; i < 2; i++)
            failures += !CHECKF(accel_restructure(&t[i], boxes, &st[i], NULL, NULL) == 0,
                     "deterministic run %d", i);
        failures += !CHECKF(same_tree(&t[0], &t[1]), "two runs differ at frame %u", f);
    }
    for (int i = 0; i < 2; i++) {
        accel_restructure_state_release(&st[i]);
        bvh_release(&t[i]);
    }
    free(boxes);
    free_anim(&a);
}

/*
 * A tree numbered children before parents: the sibling pairs (nodes 1-2,
 * 3-4, ...) are renumbered in reverse order, pair p going to pair P-1-p,
 * which keeps siblings adjacent and the root at 0 but puts most children
 * before their parents.  accel_restructure must take it (refit and
 * metrics through a pre-order) and give back a tree numbered
 * parent-first.
 */
static void check_unordered(struct tg_rng *r)
{
    struct anim a;
    make_morph(&a, 3000, 3, r);
    struct aabb *boxes = tg_boxes(&a.mesh);
    struct bvh bvh;
    if (accel_build(&bvh, boxes, a.mesh.tri_count, NULL) == 0 && bvh.node_count >= 3) {
        uint32_t pairs = (bvh.node_count - 1) / 2;
        /* Old node i >= 1 is in pair (i - 1) / 2 at offset (i - 1) % 2. */
        uint32_t *to = tg_alloc(sizeof(uint32_t) * bvh.node_count);
        to[0] = 0;
        for (uint32_t i = 1; i < bvh.node_count; i++)
            to[i] = 1 + 2 * (pairs - 1 - (i - 1) / 2) + (i - 1) % 2;
        struct bvh_node *nodes = rt_malloc(sizeof(*nodes) * bvh.node_count);
        for (uint32_t i = 0; i < bvh.node_count; i++) {
            nodes[to[i]] = bvh.nodes[i];
            if (!bvh.nodes[i].count)
                nodes[to[i]].first = to[bvh.nodes[i].first];
        }
        rt_free(bvh.nodes);
        bvh.nodes = nodes;
        free(to);
        a.pose(&a, 2);
        free(boxes);
        boxes = tg_boxes(&a.mesh);
        struct accel_restructure_state st;
        accel_restructure_state_init(&st);
        struct accel_restructure_stats s;
        failures += !CHECKF(accel_restructure(&bvh, boxes, &st, NULL, &s) == 0, "unordered");
        failures += !CHECKF(s.restructures > 0, "unordered: nothing restructured");
        check_tree("unordered", &bvh, boxes, a.mesh.tri_count);
        check_hits("unordered", &a.mesh, &bvh, r);
        accel_restructure_state_release(&st);
        bvh_release(&bvh);
    }
    free(boxes);
    free_anim(&a);
}

/* Boxes with NaN and infinities break the contract: the tree must stay
 * structurally valid (every primitive once, depth bounded), with the
 * paper's rule and with the cost check. */
static void check_nonfinite(struct tg_rng *r)
{
    const uint32_t n = 2000;
    struct aabb *boxes = tg_alloc(sizeof(*boxes) * n);
    for (uint32_t i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++) {
            boxes[i].min[k] = tg_unit(r);
            boxes[i].max[k] = boxes[i].min[k] + 0.01f;
        }
    }
    for (int verify = 0; verify < 2; verify++) {
        struct bvh b;
        if (accel_build(&b, boxes, n, NULL))
            continue;
        struct accel_restructure_params p;
        accel_restructure_params_default(&p);
        p.verify_cost = verify;
        struct accel_restructure_state st;
        accel_restructure_state_init(&st);
        struct aabb *moved = tg_alloc(sizeof(*boxes) * n);
        for (uint32_t frame = 1; frame < 4; frame++) {
            for (uint32_t i = 0; i < n; i++) {
                moved[i] = boxes[(i * 7 * frame) % n];
                if (i % 7 == 0)
                    moved[i].min[i % 3] = NAN;
                if (i % 11 == 0)
                    moved[i].max[(i + 1) % 3] = INFINITY;
                if (i % 13 == 0)
                    moved[i].min[(i + 2) % 3] = -INFINITY;
            }
            int rc = accel_restructure(&b, moved, &st, &p, NULL);
            failures += !CHECKF(rc == 0, "non-finite boxes: rc %d", rc);
            check_tree_boxes("non-finite boxes", &b, moved, n, 0);
        }
        free(moved);
        accel_restructure_state_release(&st);
        bvh_release(&b);
    }
    free(boxes);
}

/* 0, 1, 2 and identical primitives, and a zero-area root. */
static void check_tiny(void)
{
    struct accel_restructure_state st;
    accel_restructure_state_init(&st);
    struct bvh empty;
    memset(&empty, 0, sizeof(empty));
    struct aabb one = {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}};
    failures += !CHECKF(accel_restructure(&empty, &one, &st, NULL, NULL) == 0 &&
                           empty.node_count == 0,
             "empty BVH");
    struct aabb boxes[64];
    for (uint32_t n = 1; n <= 64; n *= 2) {
        for (int kind = 0; kind < 3; kind++) {
            for (uint32_t i = 0; i < n; i++) {
                float x = (float)i / (float)n;
                if (kind == 0) { /* identical boxes */
                    boxes[i] = one;
                } else if (kind == 1) { /* points on a line: zero area */
                    struct aabb b = {{x, 0.0f, 0.0f}, {x, 0.0f, 0.0f}};
                    boxes[i] = b;
                } else { /* unit boxes sliding past each other */
                    struct aabb b = {{x, 0.0f, 0.0f}, {x + 0.1f, 0.1f, 0.1f}};
                    boxes[i] = b;
                }
            }
            struct bvh b;
            if (accel_build(&b, boxes, n, NULL))
                continue;
            accel_restructure_state_release(&st);
            accel_restructure_state_init(&st);
            for (uint32_t frame = 0; frame < 3; frame++) {
                for (uint32_t i = 0; i < n && kind == 2; i++) {
                    float x = (i % 2 ? 1.0f - (float)i / (float)n : (float)i / (float)n);
                    x = (1.0f - 0.5f * (float)frame) * (float)i / (float)n + 0.5f * (float)frame * x;
                    struct aabb nb = {{x, 0.0f, 0.0f}, {x + 0.1f, 0.1f, 0.1f}};
                    boxes[i] = nb;
                }
                char what[64];
                snprintf(what, sizeof(what), "tiny n=%u kind=%d frame %u", n, kind, frame);
                failures += !CHECKF(accel_restructure(&b, boxes, &st, NULL, NULL) == 0, "%s", what);
                check_tree(what, &b, boxes, n);
            }
            bvh_release(&b);
        }
    }
    accel_restructure_state_release(&st);
}

/*
 * A caterpillar at the depth limit: inner node d has a leaf of 8 boxes
 * on its left and inner node d + 1 on its right, down to depth
 * BVH_MAX_DEPTH.  The boxes of the deepest leaves are then shuffled among
 * themselves, so the overlapping pairs lie deep down where a restructured
 * sub-BVH would need more levels than remain: those restructurings must
 * be skipped (rejected_depth), shallower ones may go ahead, and the
 * depth bound must hold.
 */
#define CATERPILLAR_SHUFFLED_LEAVES 3

static void check_depth_limit(struct tg_rng *r)
{
    const uint32_t inner = BVH_MAX_DEPTH;
    const uint32_t leaves = inner + 1;
    const uint32_t per_leaf = BVH_MAX_LEAF_SIZE;
    const uint32_t n = leaves * per_leaf;
    struct bvh b;
    b.node_count = 2 * inner + 1;
    b.prim_count = n;
    b.depth = inner;
    b.nodes = rt_malloc(sizeof(*b.nodes) * b.node_count);
    b.prim_index = rt_malloc(sizeof(uint32_t) * n);
    struct aabb *boxes = tg_alloc(sizeof(*boxes) * n);
    /* Leaf j (j = 0..leaves-1) holds slots [8j, 8j + 8), boxes at x = j. */
    for (uint32_t i = 0; i < n; i++) {
        b.prim_index[i] = i;
        float x = (float)(i / per_leaf);
        struct aabb bx = {{x, 0.0f, 0.0f}, {x + 0.5f, 1.0f, 1.0f}};
        boxes[i] = bx;
    }
    /* Node 0 is inner 0; inner d's children are 2d + 1 (leaf d) and
     * 2d + 2 (inner d + 1, or the last leaf). */
    for (uint32_t d = 0; d < inner; d++) {
        uint32_t node = d == 0 ? 0 : 2 * d;
        b.nodes[node].first = 2 * d + 1;
        b.nodes[node].count = 0;
        b.nodes[2 * d + 1].first = d * per_leaf;
        b.nodes[2 * d + 1].count = per_leaf;
    }
    b.nodes[2 * inner].first = inner * per_leaf;
    b.nodes[2 * inner].count = per_leaf;
    struct aabb *start = tg_alloc(sizeof(*boxes) * n);
    memcpy(start, boxes, sizeof(*boxes) * n);
    /* Shuffle: the boxes of the last leaves go to random places among
     * those leaves. */
    const uint32_t first_moved = (leaves - CATERPILLAR_SHUFFLED_LEAVES) * per_leaf;
    for (uint32_t i = first_moved; i < n; i++) {
        float x = tg_range(r, (float)(leaves - CATERPILLAR_SHUFFLED_LEAVES), (float)leaves);
        struct aabb bx = {{x, 0.0f, 0.0f}, {x + 0.5f, 1.0f, 1.0f}};
        boxes[i] = bx;
    }
    /* The refit tree is valid: refit the start boxes first, so that the
     * tree handed in satisfies the contract. */
    refit_box(&b, start, 0);
    check_tree("caterpillar before", &b, start, n);
    struct accel_restructure_state st;
    accel_restructure_state_init(&st);
    struct accel_restructure_stats s;
    failures += !CHECKF(accel_restructure(&b, boxes, &st, NULL, &s) == 0, "caterpillar");
    check_tree("caterpillar", &b, boxes, n);
    printf("  caterpillar: %u restructures, %u skipped for depth, depth now %u\n",
           s.restructures, s.rejected_depth, b.depth);
    failures += !CHECKF(s.rejected_depth > 0, "caterpillar: no restructuring hit the depth limit");
    failures += !CHECKF(s.restructures > 0, "caterpillar: nothing restructured");
    failures += !CHECKF(s.sah_after < s.sah_before, "caterpillar: cost %.3f -> %.3f", s.sah_before,
             s.sah_after);
    accel_restructure_state_release(&st);
    bvh_release(&b);
    free(boxes);
    free(start);
}

/*
 * Every allocation failure: -1 and the plain refit (the tree equals an
 * independent refit of the input tree), or 0 and a valid tree; the state
 * stays usable (the next frame succeeds).  The state is fresh for each N,
 * so the failures also hit the scratch arrays' first growth.  Run on a
 * frame with one restructuring of the root pair and on one with several
 * (min_ops), where a failure can come after restructurings were accepted.
 */
static void check_alloc_failures(struct tg_rng *r, int g, float cap, uint32_t frame, double rays,
                                 uint32_t min_ops)
{
    struct anim a;
    make_explode(&a, g, frame + 1, cap, r);
    struct aabb *boxes0 = tg_boxes(&a.mesh);
    a.pose(&a, frame);
    struct aabb *boxes = tg_boxes(&a.mesh);
    struct accel_restructure_params p;
    accel_restructure_params_default(&p);
    p.rays_per_frame = rays;
    struct bvh start;
    if (accel_build(&start, boxes0, a.mesh.tri_count, NULL)) {
        free(boxes0);
        free(boxes);
        free_anim(&a);
        return;
    }
    struct bvh expect;
    copy_bvh(&expect, &start);
    refit_box(&expect, boxes, 0);
    int succeeded = 0;
    uint32_t ops = 0;
    long k;
    for (k = 0; k < 400 && !succeeded; k++) {
        /* The library frees and replaces the arrays: hand it its own. */
        struct bvh owned = start;
        owned.nodes = rt_malloc(sizeof(*start.nodes) * start.node_count);
        owned.prim_index = rt_malloc(sizeof(uint32_t) * start.prim_count);
        if (!owned.nodes || !owned.prim_index) {
            fprintf(stderr, "out of memory\n");
            exit(2);
        }
        memcpy(owned.nodes, start.nodes, sizeof(*start.nodes) * start.node_count);
        memcpy(owned.prim_index, start.prim_index, sizeof(uint32_t) * start.prim_count);
        struct accel_restructure_state st;
        accel_restructure_state_init(&st);
        struct accel_restructure_stats s;
        rt_alloc_fail_after(k);
        int rc = accel_restructure(&owned, boxes, &st, &p, &s);
        long injected = rt_alloc_failures();
        rt_alloc_fail_reset();
        if (rc == 0) {
            succeeded = injected == 0;
            ops = s.restructures;
            check_tree("after injected failures", &owned, boxes, a.mesh.tri_count);
        } else {
            failures += !CHECKF(rc == -1 && injected > 0, "failure %ld: rc %d", k, rc);
            failures += !CHECKF(same_tree(&owned, &expect), "failure %ld: not the plain refit", k);
        }
        failures += !CHECKF(accel_restructure(&owned, boxes, &st, &p, NULL) == 0,
                 "failure %ld: the next frame failed", k);
        check_tree("frame after a failure", &owned, boxes, a.mesh.tri_count);
        accel_restructure_state_release(&st);
        bvh_release(&owned);
    }
    printf("  allocation failures: %ld injection points, %u restructurings\n", k - 1, ops);
    failures += !CHECKF(succeeded, "never succeeded without an injected failure");
    failures += !CHECKF(ops >= min_ops, "%u restructurings, the sweep wants %u", ops, min_ops);
    free_copy(&expect);
    bvh_release(&start);
    free(boxes0);
    free(boxes);
    free_anim(&a);
}

static void check_measure(void)
{
    struct accel_restructure_params p;
    double t0 = rt_now_ms();
    accel_restructure_measure_constants(&p);
    double ms = rt_now_ms() - t0;
    struct accel_restructure_params d;
    accel_restructure_params_default(&d);
    printf("  measured constants (%.1f ms): C_leaf %.3f  C_rebuild %.3f  C_refine %.3f"
           "  (defaults %.3f %.3f %.3f)\n",
           ms, p.c_leaf, p.c_rebuild, p.c_refine, d.c_leaf, d.c_rebuild, d.c_refine);
    failures += !CHECKF(isfinite(p.c_leaf) && p.c_leaf > 0.0f && isfinite(p.c_rebuild) &&
                           p.c_rebuild > 0.0f && isfinite(p.c_refine) && p.c_refine > 0.0f,
             "measured constants");
    /* < 50 ms in a Release build; sanitizer builds run several times
     * slower, hence the margin. */
    failures += !CHECKF(ms < 1000.0, "measurement took %.0f ms", ms);
    failures += !CHECKF(p.rays_per_frame == d.rays_per_frame && p.verify_cost == d.verify_cost,
             "measure_constants fills the other fields with the defaults");
}

int main(void)
{
    double t0 = rt_now_ms();
    struct tg_rng r;
    tg_seed(&r, 2007);
    printf("restructure:\n");
    struct accel_restructure_params p;
    accel_restructure_params_default(&p);
    struct anim a;

    /* Whole-object deformation with the default 512^2 rays: restructuring
     * must recover most of what the refit loses. */
    make_explode(&a, 28, 8, -2.0f, &r);
    double recovery = run_anim(&a, &p, RESTRUCTURE_EXPLODE_BOUND, &r);
    failures += !CHECKF(recovery <= RESTRUCTURE_RECOVERY_BOUND,
             "%s: final cost %.3f of the refit-only tree's", a.name, recovery);
    free_anim(&a);

    make_morph(&a, 8000, 6, &r);
    recovery = run_anim(&a, &p, RESTRUCTURE_EXPLODE_BOUND, &r);
    failures += !CHECKF(recovery <= RESTRUCTURE_RECOVERY_BOUND,
             "%s: final cost %.3f of the refit-only tree's", a.name, recovery);
    free_anim(&a);

    make_cloth(&a, 80, 6, &r);
    run_anim(&a, &p, RESTRUCTURE_CLOTH_BOUND, &r);
    free_anim(&a);

    /* A local explosion with about as many rays as triangles (the paper's
     * ratio: 512^2 rays on 92k-252k triangles, table 1 and 2): only the
     * exploding region should be restructured on most frames. */
    struct accel_restructure_params local = p;
    local.rays_per_frame = RESTRUCTURE_LOCAL_RAYS;
    make_explode(&a, 28, 8, 0.8f, &r);
    recovery = run_anim(&a, &local, RESTRUCTURE_EXPLODE_BOUND, &r);
    failures += !CHECKF(recovery <= RESTRUCTURE_RECOVERY_BOUND,
             "%s: final cost %.3f of the refit-only tree's", a.name, recovery);
    failures += !CHECKF(2 * a.partial_frames >= a.frames - 1,
             "%s: only %u of %u frames restructured selectively", a.name, a.partial_frames,
             a.frames - 1);
    free_anim(&a);

    /* The paper's rule alone: every restructuring whose estimated benefit
     * exceeds its cost is applied. */
    struct accel_restructure_params paper = local;
    paper.verify_cost = 0;
    make_explode(&a, 16, 6, 0.5f, &r);
    run_anim(&a, &paper, 0.0, &r);
    free_anim(&a);

    check_no_rays(&r);
    check_deterministic(&r);
    check_unordered(&r);
    check_tiny();
    check_nonfinite(&r);
    check_depth_limit(&r);
    check_alloc_failures(&r, 6, -2.0f, 2, ACCEL_RESTRUCTURE_DEFAULT_RAYS, 1);
    check_alloc_failures(&r, 16, 0.5f, 1, 2048.0, 3);
    check_measure();

    printf("restructure: %s (%d failures, %.0f ms)\n", failures ? "FAIL" : "ok", failures,
           rt_now_ms() - t0);
    return failures ? 1 : 0;
}
