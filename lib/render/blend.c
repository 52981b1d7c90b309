/* SPDX-License-Identifier: Apache-2.0 */
/*
 * blend.c - the primary-ray path with user clip planes and blending
 * (blend.h).
 *
 * Continuing a ray past a hit (clipped, or see-through) restarts the
 * closest-hit search with tmin just above the hit's t (the next float):
 * the same triangle, whose t for this ray is computed by the same
 * operations every time, can never be found again, and the watertight
 * test and its hit rule are untouched.  A triangle at exactly the same t
 * (a neighbour sharing the edge the ray passes through, a coincident
 * copy) is skipped with it: it is the same point, so it is clipped or
 * covered alike.
 */
#include "render/blend.h"

#include <math.h>
#include <string.h>

#include "render/gl_shade.h"
#include "render/surface.h"
#include "render/visibility.h"

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

void blend_trace_primary_state(const struct shade_context *sc, const float org[3],
                               const float dir[3], float tmax, struct shade_cone cone,
                               float rgba[4], float *t_first,
                               const struct scene_raster **first_state)
{
    float layers[BLEND_MAX_LAYERS][4];
    /* Each layer's blend state: GL blends a fragment by the state current
     * when its primitive was drawn; NULL or blend off: opaque. */
    const struct scene_raster *layer_state[BLEND_MAX_LAYERS];
    int n = 0;
    float tmin = 0.0f;
    const int clipping = sc->clipping;
    const int see_through = sc->see_through;
    *t_first = INFINITY;
    if (first_state)
        *first_state = NULL;
    for (;;) {
        struct trace_scene_hit hit;
        /* Faces RT_CULL_FACE removes are passed as GL does not draw them. */
        if (!gl_closest_drawn(sc, org, dir, tmin, tmax, &hit))
            break;
        tmin = nextafterf(hit.t, INFINITY);
        if (clipping) {
            double p[3];
            for (int k = 0; k < 3; k++)
                p[k] = (double)org[k] + (double)hit.t * (double)dir[k];
            /* The planes the hit triangle was drawn under: GL clips each
             * primitive by its own (scene/clip.h). */
            if (scene_clip_removes(&shade_hit_instance(sc, &hit)->appearance.clip, p))
                continue;
        }
        shade_hit(sc, org, dir, &hit, cone, 0, layers[n]);
        /* A frame with neither blending nor the alpha test anywhere: the
         * nearest kept hit, with no look-up per hit. */
        const struct scene_raster *r = see_through ? hit_raster(sc, &hit) : NULL;
        if (!r || !scene_raster_see_through(r)) {
            if (n == 0) {
                *t_first = hit.t;
                if (first_state)
                    *first_state = hit_raster(sc, &hit);
                memcpy(rgba, layers[0], 4 * sizeof(float));
                return;
            }
            layer_state[n++] = NULL; /* opaque: what lies behind is hidden */
            break;
        }
        /* The fixed-function mode's colour carries GL's alpha (the
         * colour's unlit, the diffuse material's lit, times the texture's
         * under RT_MODULATE); the other modes take the diffuse material's. */
        if (sc->state->shading != RENDER_FIXED_FUNCTION)
            layers[n][3] = surface_alpha(sc, &hit, dir, cone);
        /* GL's alpha test (OpenGL 1.5 sec. 4.1.4) on the fragment's
         * clamped alpha: a failing surface is not drawn, so the ray goes
         * on behind it, a cutout. */
        if (r->alpha_test && !scene_alpha_passes(r->alpha_func, clamp01(layers[n][3]), r->alpha_ref))
            continue;
        if (n == 0) {
            *t_first = hit.t;
            if (first_state)
                *first_state = r;
        }
        layer_state[n] = r->blend ? r : NULL;
        n++;
        if (!r->blend || n == BLEND_MAX_LAYERS ||
            !blend_needs_destination(r->blend_src, r->blend_dst, layers[n - 1]))
            break;
    }
    /* Back to front: the clear colour, then every layer over it, as GL
     * blends surfaces drawn from the back to the front. */
    float c[4];
    memcpy(c, sc->state->clear_color, sizeof(c));
    for (int i = n - 1; i >= 0; i--) {
        const struct scene_raster *r = layer_state[i];
        if (!r) {
            memcpy(c, layers[i], sizeof(c));
            continue;
        }
        blend_combine(r->blend_src, r->blend_dst, layers[i], c, c);
    }
    memcpy(rgba, c, sizeof(c));
}
