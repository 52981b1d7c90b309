/* SPDX-License-Identifier: Apache-2.0 */
/*
 * secondary.c - the hit filters of secondary rays and queries
 * (secondary.h).
 */
#include "render/secondary.h"

#include <math.h>

#include "base/alloc.h"
#include "render/blend.h"
#include "render/surface.h"

static float clamp01(float x)
{
    return fminf(fmaxf(x, 0.0f), 1.0f);
}

int secondary_marks(const struct scene_frame *frame, unsigned kinds, uint8_t **out)
{
    const uint32_t n = frame->committed.count;
    int any = 0;
    *out = NULL;
    for (uint32_t i = 0; i < n && !any; i++) {
        const struct scene_appearance *a = &frame->committed.items[i].appearance;
        any = ((kinds & SECONDARY_CLIP) && a->clip.enabled) ||
              ((kinds & SECONDARY_ALPHA) && a->raster.alpha_test) ||
              ((kinds & SECONDARY_BLEND) && a->raster.blend);
    }
    if (!any)
        return 0;
    uint8_t *marks = rt_malloc(n);
    if (!marks)
        return -1;
    for (uint32_t i = 0; i < n; i++) {
        const struct scene_appearance *a = &frame->committed.items[i].appearance;
        marks[i] = (uint8_t)(((kinds & SECONDARY_CLIP) && a->clip.enabled ? SECONDARY_CLIP : 0u) |
                             ((kinds & SECONDARY_ALPHA) && a->raster.alpha_test ? SECONDARY_ALPHA
                                                                                : 0u) |
                             ((kinds & SECONDARY_BLEND) && a->raster.blend ? SECONDARY_BLEND : 0u));
    }
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
    return !clipped(&pass->job->frame->committed.items[ti->instance_id], org, dir, hit);
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
    s->shadow.filter_mask = SECONDARY_CLIP | SECONDARY_ALPHA | SECONDARY_BLEND;
    s->shadow.accept = accept_shadow;
    s->shadow.accept_user = sc;
    s->ray = s->shadow;
    s->ray.filter_mask = SECONDARY_CLIP | SECONDARY_ALPHA;
    s->ray.accept = accept_ray;
    sc->shadows = &s->shadow;
    sc->rays = &s->ray;
}
