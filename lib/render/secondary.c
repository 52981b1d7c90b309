/* SPDX-License-Identifier: Apache-2.0 */
/*
 * secondary.c - the hit filters of secondary rays and queries
 * (secondary.h).
 */
#include "render/secondary.h"

#include <math.h>

#include "base/alloc.h"
#include "render/blend.h"
#include "render/filled.h"
#include "render/raster.h"
#include "render/surface.h"

static float clamp01(float x)
{
    return fminf(fmaxf(x, 0.0f), 1.0f);
}

/* 1 when every enabled plane keeps the whole box (world = eye space),
 * with a margin of 2^-16 of the box's size and of its distance from the
 * origin on every side: a hit point computed from the ray (org + t dir,
 * rounded) lies in the box to far less than that, so no hit of the
 * instance can be clipped and its hits need no test. */
static int keeps_box(const struct scene_clip *c, const struct aabb *b)
{
    double lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
        const double size = (double)b->max[k] - (double)b->min[k];
        const double far = fmax(fabs((double)b->min[k]), fabs((double)b->max[k]));
        const double margin = (size + far) * 0x1p-16;
        lo[k] = (double)b->min[k] - margin;
        hi[k] = (double)b->max[k] + margin;
    }
    for (int i = 0; i < SCENE_MAX_CLIP_PLANES; i++) {
        if (!(c->enabled >> i & 1u))
            continue;
        const double *e = c->plane[i];
        /* The box's corner where the plane's value is least. */
        double v = e[3];
        for (int k = 0; k < 3; k++)
            v += e[k] * (e[k] < 0.0 ? hi[k] : lo[k]);
        if (!(v >= 0.0))
            return 0;
    }
    return 1;
}

/* 1 when the factors can show what lies behind (blend_needs_destination
 * can say yes for some source colour). */
static int may_see_through(unsigned src, unsigned dst)
{
    const int src_reads_dst = src == RT_DST_COLOR || src == RT_ONE_MINUS_DST_COLOR ||
                              src == RT_DST_ALPHA || src == RT_ONE_MINUS_DST_ALPHA ||
                              src == RT_SRC_ALPHA_SATURATE;
    return src_reads_dst || dst != RT_ZERO;
}

/* What the hits of an instance must be checked for: a clip plane that may
 * cut it, an alpha test that may fail (not RT_ALWAYS), a blend that may
 * show what lies behind. */
static unsigned instance_marks(const struct scene_instance *inst, unsigned kinds)
{
    const struct scene_appearance *a = &inst->appearance;
    unsigned m = 0;
    if ((kinds & SECONDARY_CLIP) && a->clip.enabled) {
        const struct aabb box = scene_instance_box(inst);
        if (!keeps_box(&a->clip, &box))
            m |= SECONDARY_CLIP;
    }
    if ((kinds & SECONDARY_ALPHA) && a->raster.alpha_test && a->raster.alpha_func != RT_ALWAYS)
        m |= SECONDARY_ALPHA;
    if ((kinds & SECONDARY_UNFILLED) && raster_polygons_present(inst))
        m |= SECONDARY_UNFILLED;
    if ((kinds & SECONDARY_BLEND) && a->raster.blend &&
        may_see_through(a->raster.blend_src, a->raster.blend_dst))
        m |= SECONDARY_BLEND;
    return m;
}

int secondary_marks(const struct scene_frame *frame, unsigned kinds, uint8_t **out)
{
    const uint32_t n = frame->committed.count;
    uint32_t first = n;
    unsigned m0 = 0;
    *out = NULL;
    for (uint32_t i = 0; i < n; i++) {
        m0 = instance_marks(&frame->committed.items[i], kinds);
        if (m0) {
            first = i;
            break;
        }
    }
    if (first == n)
        return 0;
    uint8_t *marks = rt_calloc(n, 1);
    if (!marks)
        return -1;
    marks[first] = (uint8_t)m0;
    for (uint32_t i = first + 1; i < n; i++)
        marks[i] = (uint8_t)instance_marks(&frame->committed.items[i], kinds);
    *out = marks;
    return 0;
}

/* 1 when a clip plane the hit's primitive was drawn under removes the
 * hit point (the ray is in eye space, where the planes are kept; the
 * point computed as the primary path computes it, blend.c). */
static int clipped(const struct scene_instance *inst, const float org[3], const float dir[3],
                   const struct trace_scene_hit *hit)
{
    if (!inst->appearance.clip.enabled)
        return 0;
    double p[3];
    for (int k = 0; k < 3; k++)
        p[k] = (double)org[k] + (double)hit->t * (double)dir[k];
    return scene_clip_removes(&inst->appearance.clip, p);
}

/*
 * Whether a secondary ray stops at a hit: not when clipped away, not when
 * its alpha fails the alpha test, and (shadow rays) not at a blended
 * surface that shows what lies behind it.  The alpha is the primary
 * path's (blend.c): the diffuse material's, textured, here at the
 * texture's finest level (a secondary ray carries no footprint to the
 * filter).  The blend rule is the primary path's too: the surface is
 * see-through when blend_needs_destination says the colour behind it
 * counts, asked with the diffuse colour.
 */
static int accept_secondary(const struct shade_context *sc, const float org[3],
                            const float dir[3], const struct trace_scene_hit *hit, int shadow)
{
    const struct scene_instance *inst = shade_hit_instance(sc, hit);
    if (clipped(inst, org, dir, hit))
        return 0;
    /* A face drawn as lines or points (filled_face returns at once for a
     * triangle whose two faces are filled). */
    if (!filled_face(sc->frame, sc->scene, dir, hit))
        return 0;
    const struct scene_raster *r = &inst->appearance.raster;
    const int blend = shadow && r->blend;
    if (!r->alpha_test && !blend)
        return 1;
    struct surface_colour s;
    surface_fetch_colour(sc, hit, dir, 0.0f, &s);
    if (r->alpha_test && !scene_alpha_passes(r->alpha_func, clamp01(s.diffuse[3]), r->alpha_ref))
        return 0;
    if (blend && blend_needs_destination(r->blend_src, r->blend_dst, s.diffuse))
        return 0;
    return 1;
}

static int accept_shadow(void *user, const float org[3], const float dir[3],
                         const struct trace_scene_hit *hit)
{
    return accept_secondary(user, org, dir, hit, 1);
}

static int accept_ray(void *user, const float org[3], const float dir[3],
                      const struct trace_scene_hit *hit)
{
    return accept_secondary(user, org, dir, hit, 0);
}

int secondary_accept_query(void *user, const float org[3], const float dir[3],
                           const struct trace_scene_hit *hit)
{
    const struct render_pass *pass = user;
    const struct trace_instance *ti = &pass->scene.instances[hit->instance];
    const struct scene_instance *inst = &pass->job->frame->committed.items[ti->instance_id];
    if (clipped(inst, org, dir, hit))
        return 0;
    return filled_face(pass->job->frame, &pass->scene, dir, hit);
}

void secondary_scenes_init(struct secondary_scenes *s, struct shade_context *sc,
                           const struct trace_scene *base, const uint8_t *marks)
{
    sc->shadows = base;
    sc->rays = base;
    if (!marks)
        return;
    s->shadow = *base;
    s->shadow.filtered = marks;
    s->shadow.filter_mask = SECONDARY_CLIP | SECONDARY_ALPHA | SECONDARY_BLEND | SECONDARY_UNFILLED;
    s->shadow.accept = accept_shadow;
    s->shadow.accept_user = sc;
    s->ray = s->shadow;
    s->ray.filter_mask = SECONDARY_CLIP | SECONDARY_ALPHA | SECONDARY_UNFILLED;
    s->ray.accept = accept_ray;
    sc->shadows = &s->shadow;
    sc->rays = &s->ray;
}
