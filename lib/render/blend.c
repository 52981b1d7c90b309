/* SPDX-License-Identifier: Apache-2.0 */
/*
 * blend.c - the primary-ray path with user clip planes and blending
 * (blend.h).
 *
 * Continuing a ray past a hit (clipped, or see-through) restarts the
 * closest-hit search with tmin just above the hit's t (the next float):
 * the same triangle, whose t for this ray is computed by the same
 * operations every time, can never be found again, and the watertight
 * test and its hit rule are untouched.  Behind an opaque first hit, a
 * triangle at exactly the same t is skipped with it; a clipped one is
 * replaced by the first unclipped triangle at its distance, if any
 * (gl_drawn_tie), which stepping past it would lose.  At a see-through
 * hit every triangle at that t is a fragment (trace_scene_ties), composited
 * in GL's draw order, instance then primitive, as GL blends coplanar
 * translucent triangles one over the other; of the neighbours of one
 * instance sharing the edge or vertex the ray passes through only the
 * first counts, as GL's rasterisation gives such a pixel to one of them.
 */
#include "render/blend.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "base/alloc.h"

#include "render/gl_shade.h"
#include "render/surface.h"
#include "render/visibility.h"
#include "trace/scene_ties.h"

static float clamp01(float x)
{
    return fminf(fmaxf(x, 0.0f), 1.0f);
}

/* GL's factor for channel k. */
static float factor(unsigned f, const float s[4], const float d[4], int k)
{
    switch (f) {
    case RT_ZERO:
        return 0.0f;
    case RT_ONE:
        return 1.0f;
    case RT_SRC_COLOR:
        return s[k];
    case RT_ONE_MINUS_SRC_COLOR:
        return 1.0f - s[k];
    case RT_DST_COLOR:
        return d[k];
    case RT_ONE_MINUS_DST_COLOR:
        return 1.0f - d[k];
    case RT_SRC_ALPHA:
        return s[3];
    case RT_ONE_MINUS_SRC_ALPHA:
        return 1.0f - s[3];
    case RT_DST_ALPHA:
        return d[3];
    case RT_ONE_MINUS_DST_ALPHA:
        return 1.0f - d[3];
    case RT_SRC_ALPHA_SATURATE:
        return k == 3 ? 1.0f : fminf(s[3], 1.0f - d[3]);
    default:
        return 0.0f;
    }
}

void blend_combine(unsigned src_factor, unsigned dst_factor, const float src[4],
                   const float dst[4], float out[4])
{
    float s[4], d[4];
    for (int k = 0; k < 4; k++) {
        s[k] = clamp01(src[k]);
        d[k] = clamp01(dst[k]);
    }
    for (int k = 0; k < 4; k++)
        out[k] = clamp01(s[k] * factor(src_factor, s, d, k) + d[k] * factor(dst_factor, s, d, k));
}

static int uses_destination(unsigned f)
{
    return f == RT_DST_COLOR || f == RT_ONE_MINUS_DST_COLOR || f == RT_DST_ALPHA ||
           f == RT_ONE_MINUS_DST_ALPHA || f == RT_SRC_ALPHA_SATURATE;
}

int blend_needs_destination(unsigned src_factor, unsigned dst_factor, const float src[4])
{
    if (uses_destination(src_factor))
        return 1;
    float s[4], zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int k = 0; k < 4; k++)
        s[k] = clamp01(src[k]);
    for (int k = 0; k < 4; k++)
        if (factor(dst_factor, s, zero, k) != 0.0f)
            return 1;
    return 0;
}

/*
 * The source alpha of a surface: the alpha of its diffuse material, which
 * is the vertex colour's alpha when RT_COLOR_MATERIAL took the colour (as
 * GL's lit alpha is the diffuse alpha).  The seam for GL's unlit alpha
 * (the colour's) is here: a shading mode without lighting changes what
 * surface_fetch puts into the diffuse material, or this function.
 */
static float surface_alpha(const struct shade_context *sc, const struct trace_scene_hit *hit,
                           const float dir[3], struct shade_cone cone)
{
    struct surface_colour s;
    const float distance = hit->t * sqrtf(vec3_dot(dir, dir));
    surface_fetch_colour(sc, hit, dir, fabsf(cone.width + cone.spread * distance), &s);
    return s.diffuse[3];
}

/* The raster state of the instance a hit belongs to (raster_state.h). */
static const struct scene_raster *hit_raster(const struct shade_context *sc,
                                             const struct trace_scene_hit *hit)
{
    return &shade_hit_instance(sc, hit)->appearance.raster;
}

void blend_trace_primary(const struct shade_context *sc, const float org[3], const float dir[3],
                         float tmax, struct shade_cone cone, float rgba[4], float *t_first)
{
    blend_trace_primary_state(sc, org, dir, tmax, cone, rgba, t_first, NULL);
}

/* A hit on an edge or a vertex of its triangle, to rounding: where the
 * neighbours sharing that edge or vertex are hit at the same t too.  The
 * tolerance covers the rounding of u, v and u + v (a few ulps of 1) and
 * the double-precision fallback's tiny non-zero edge values. */
static int on_boundary(const struct trace_scene_hit *h)
{
    const float eps = 0x1p-20f;
    return h->u <= eps || h->v <= eps || h->u + h->v >= 1.0f - eps;
}

/* Neighbours in two instances: the shared vertices compared in eye space.
 * GL's rasterisation gives a pixel on an edge to one of the triangles
 * sharing it whatever draw call each came from, so two instances that
 * meet along an edge (a model issued in two segments, two tiles of a
 * floor) count once there too. */
static int neighbours_across(const struct shade_context *sc, const struct trace_scene_hit *a,
                             const struct trace_scene_hit *b)
{
    double pa[3][3], pb[3][3];
    scene_instance_world_triangle(shade_hit_instance(sc, a), a->prim, pa);
    scene_instance_world_triangle(shade_hit_instance(sc, b), b->prim, pb);
    int shared = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (pa[i][0] == pb[j][0] && pa[i][1] == pb[j][1] && pa[i][2] == pb[j][2]) {
                shared++;
                break;
            }
    return shared >= 1 && shared <= 2;
}

/* 1 when the triangles of two hits are neighbours: they share one or two
 * vertex positions (an edge or a vertex of a mesh, drawn with shared or
 * with repeated vertices, or of two instances that meet there), and are
 * not the same triangle drawn twice (a coincident copy, which GL draws
 * again). */
static int neighbours(const struct shade_context *sc, const struct trace_scene_hit *a,
                      const struct trace_scene_hit *b)
{
    if (a->instance != b->instance)
        return neighbours_across(sc, a, b);
    const struct scene_mesh *mesh = &shade_hit_instance(sc, a)->object->mesh;
    const uint32_t *va = &mesh->indices[3 * a->prim], *vb = &mesh->indices[3 * b->prim];
    int shared = 0;
    for (int i = 0; i < 3; i++) {
        const float *p = &mesh->positions[3 * va[i]];
        for (int j = 0; j < 3; j++)
            if (memcmp(p, &mesh->positions[3 * vb[j]], 3 * sizeof(float)) == 0) {
                shared++;
                break;
            }
    }
    return shared >= 1 && shared <= 2;
}

/* 1 when a clip plane the hit's triangle was drawn under removes it. */
static int clipped(const struct shade_context *sc, const float org[3], const float dir[3],
                   const struct trace_scene_hit *hit)
{
    double p[3];
    for (int k = 0; k < 3; k++)
        p[k] = (double)org[k] + (double)hit->t * (double)dir[k];
    /* The planes the hit triangle was drawn under: GL clips each
     * primitive by its own (scene/clip.h). */
    return scene_clip_removes(&shade_hit_instance(sc, hit)->appearance.clip, p);
}

int blend_hit_clipped(const struct shade_context *sc, const float org[3], const float dir[3],
                      const struct trace_scene_hit *hit)
{
    return clipped(sc, org, dir, hit);
}

/* One fragment of a group: its colour and what GL does with it. */
struct fragment {
    float rgba[4];
    const struct scene_raster *raster; /* the instance's */
    const struct scene_raster *state;  /* blends by; NULL: copied */
    unsigned char kept, stops;
    unsigned char boundary; /* an edge or vertex hit that counts */
};

/*
 * The fragments of one distance, in GL's draw order: BLEND_MAX_LAYERS in
 * arrays of the caller's (no allocation for the pixels of real scenes),
 * more on the heap when a pixel has more coincident surfaces; a failed
 * allocation keeps the first drawn, as many as there is room for.
 */
struct fragment_group {
    struct trace_scene_hit *hit;
    struct fragment *f;
    int count, cap;
    int heap; /* hit and f were allocated here */
};

/* The layers a ray composites, likewise growable. */
struct layer {
    float rgba[4];
    const struct scene_raster *state; /* NULL or blend off: opaque */
};

struct layer_stack {
    struct layer *l;
    int n, cap;
    int heap;
};

/* Room for at least `want` fragments (hit[0] kept); 0 when there is none
 * and the group stays as it was. */
static int group_grow(struct fragment_group *g, int want)
{
    int cap = g->cap;
    while (cap < want) {
        if (cap > INT32_MAX / 2)
            return 0;
        cap *= 2;
    }
    struct trace_scene_hit *hit = rt_realloc_array(NULL, (size_t)cap, sizeof(*hit));
    struct fragment *f = rt_realloc_array(NULL, (size_t)cap, sizeof(*f));
    if (!hit || !f) {
        rt_free(hit);
        rt_free(f);
        return 0;
    }
    hit[0] = g->hit[0];
    if (g->heap) {
        rt_free(g->hit);
        rt_free(g->f);
    }
    g->hit = hit;
    g->f = f;
    g->cap = cap;
    g->heap = 1;
    return 1;
}

static int layers_grow(struct layer_stack *s)
{
    if (s->cap > INT32_MAX / 2)
        return 0;
    struct layer *l = rt_realloc_array(NULL, (size_t)s->cap * 2, sizeof(*l));
    if (!l)
        return 0;
    memcpy(l, s->l, (size_t)s->n * sizeof(*l));
    if (s->heap)
        rt_free(s->l);
    s->l = l;
    s->cap *= 2;
    s->heap = 1;
    return 1;
}

/*
 * Shades fragment i of the group: whether GL draws it (its face, its
 * clip planes, the alpha test; of the neighbours hit on the edge or
 * vertex they share only the first, as GL's rasterisation gives such a
 * pixel to one of the triangles that share it), its colour, and whether
 * what lies behind it still shows through (not `stops`).
 */
static void shade_fragment(const struct shade_context *sc, const float org[3],
                           const float dir[3], struct shade_cone cone,
                           struct fragment_group *g, int i)
{
    const struct trace_scene_hit *hit = &g->hit[i];
    struct fragment *f = &g->f[i];
    f->kept = 0;
    f->boundary = 0;
    if (i > 0 && !gl_hit_drawn(sc, dir, hit))
        return;
    /* A clipped fragment does not take the pixel of an edge it shares
     * with a neighbour of another instance drawn without the plane. */
    if (sc->clipping && clipped(sc, org, dir, hit))
        return;
    if (on_boundary(hit)) {
        for (int j = 0; j < i; j++)
            if (g->f[j].boundary && neighbours(sc, &g->hit[j], hit))
                return;
        f->boundary = 1;
    }
    shade_hit(sc, org, dir, hit, cone, 0, f->rgba);
    const struct scene_raster *r = hit_raster(sc, hit);
    f->raster = r;
    if (!sc->see_through || !scene_raster_see_through(r)) {
        f->state = NULL;
        f->stops = 1;
        f->kept = 1;
        return;
    }
    if (sc->state->shading != RENDER_FIXED_FUNCTION)
        f->rgba[3] = surface_alpha(sc, hit, dir, cone);
    if (r->alpha_test && !scene_alpha_passes(r->alpha_func, clamp01(f->rgba[3]), r->alpha_ref))
        return;
    f->state = r->blend ? r : NULL;
    f->stops = !r->blend || !blend_needs_destination(r->blend_src, r->blend_dst, f->rgba);
    f->kept = 1;
}

/* Every hit at the group's distance after hit[0], in draw order: as many
 * as memory allows (trace_scene_ties gives the first `room` and says how
 * many there are; with more, asked once again with room for all). */
static void group_ties(const struct shade_context *sc, const float org[3], const float dir[3],
                       struct fragment_group *g)
{
    int total;
    int n = trace_scene_ties(sc->scene, org, dir, &g->hit[0], &g->hit[1], g->cap - 1, &total,
                             sc->counters);
    if (total > n && total < INT32_MAX && group_grow(g, total + 1))
        n = trace_scene_ties(sc->scene, org, dir, &g->hit[0], &g->hit[1], g->cap - 1, NULL,
                             sc->counters);
    g->count = 1 + n;
}

void blend_trace_primary_state(const struct shade_context *sc, const float org[3],
                               const float dir[3], float tmax, struct shade_cone cone,
                               float rgba[4], float *t_first,
                               const struct scene_raster **first_state)
{
    struct layer local_layers[BLEND_MAX_LAYERS];
    struct trace_scene_hit local_hits[BLEND_MAX_LAYERS];
    struct fragment local_fragments[BLEND_MAX_LAYERS];
    /* Each layer's blend state: GL blends a fragment by the state current
     * when its primitive was drawn; NULL or blend off: opaque. */
    struct layer_stack ls = {local_layers, 0, BLEND_MAX_LAYERS, 0};
    struct fragment_group g = {local_hits, local_fragments, 0, BLEND_MAX_LAYERS, 0};
    int done = 0;
    float tmin = 0.0f;
    const int clipping = sc->clipping;
    const int see_through = sc->see_through;
    *t_first = INFINITY;
    if (first_state)
        *first_state = NULL;
    while (!done) {
        struct trace_scene_hit *hit = &g.hit[0];
        /* Faces RT_CULL_FACE removes are passed as GL does not draw them. */
        if (!gl_closest_drawn(sc, org, dir, tmin, tmax, hit))
            break;
        tmin = nextafterf(hit->t, INFINITY);
        /* A clipped hit: the first other triangle at exactly its
         * distance, in draw order, that is drawn (its face) and not
         * clipped replaces it (a coincident copy drawn without the plane,
         * which stepping past the distance would lose).  Clipped layers
         * are passed without limit, and so are their ties. */
        if (clipping && clipped(sc, org, dir, hit) && !gl_drawn_tie(sc, org, dir, -1, clipped, hit))
            continue;
        const struct scene_raster *r = see_through ? hit_raster(sc, hit) : NULL;
        /* A frame with neither blending nor the alpha test anywhere, or a
         * surface that neither blends nor tests alpha in front: the
         * nearest kept hit, with no look-up per hit. */
        if (!r || !scene_raster_see_through(r)) {
            if (ls.n == 0) {
                shade_hit(sc, org, dir, hit, cone, 0, rgba);
                *t_first = hit->t;
                if (first_state)
                    *first_state = hit_raster(sc, hit);
                return;
            }
            if (ls.n == ls.cap && !layers_grow(&ls))
                break;
            shade_hit(sc, org, dir, hit, cone, 0, ls.l[ls.n].rgba);
            ls.l[ls.n++].state = NULL; /* opaque: what lies behind is hidden */
            break;
        }
        /* A see-through surface: every other triangle at exactly its
         * distance (coplanar translucent surfaces) is a fragment of its
         * own, which GL blends in the order the triangles were drawn;
         * trace_scene_closest gave the first of them in that order. */
        group_ties(sc, org, dir, &g);
        for (int i = 0; i < g.count; i++)
            shade_fragment(sc, org, dir, cone, &g, i);
        /* Front to back: the last drawn lies over the others; a fragment
         * that hides what lies behind it ends the ray. */
        for (int i = g.count - 1; i >= 0; i--) {
            const struct fragment *f = &g.f[i];
            if (!f->kept)
                continue;
            if (ls.n == ls.cap && !layers_grow(&ls)) {
                done = 1;
                break;
            }
            if (ls.n == 0) {
                *t_first = g.hit[i].t;
                if (first_state)
                    *first_state = f->raster;
            }
            memcpy(ls.l[ls.n].rgba, f->rgba, sizeof(ls.l[ls.n].rgba));
            ls.l[ls.n++].state = f->state;
            if (f->stops) {
                done = 1;
                break;
            }
        }
    }
    /* Back to front: the clear colour, then every layer over it, as GL
     * blends surfaces drawn from the back to the front. */
    float c[4];
    memcpy(c, sc->state->clear_color, sizeof(c));
    for (int i = ls.n - 1; i >= 0; i--) {
        const struct scene_raster *r = ls.l[i].state;
        if (!r) {
            memcpy(c, ls.l[i].rgba, sizeof(c));
            continue;
        }
        blend_combine(r->blend_src, r->blend_dst, ls.l[i].rgba, c, c);
    }
    memcpy(rgba, c, sizeof(c));
    if (ls.heap)
        rt_free(ls.l);
    if (g.heap) {
        rt_free(g.hit);
        rt_free(g.f);
    }
}
