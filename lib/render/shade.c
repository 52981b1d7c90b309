/* SPDX-License-Identifier: Apache-2.0 */
/*
 * shade.c - the integrators: eye light and Whitted (see shade.h); what a
 * hit looks like (material, texture, normals) is surface.c's.  The
 * RT_FIXED_FUNCTION mode, GL's own pipeline, is gl_shade.c's.
 *
 * Lighting follows OpenGL's fixed-function model (OpenGL 2.1 spec sec.
 * 2.14.1: emission + global ambient + per light attenuated ambient,
 * diffuse and Blinn-Phong specular) so a ported GL program looks as it
 * did, with hard shadows, mirror reflection and refraction added in the
 * manner of Whitted (1980).  Surfaces are two-sided: normals are turned
 * towards the incoming ray.  Textures modulate the ambient and diffuse
 * material (GL's MODULATE texture environment, applied to the material
 * rather than to the lit colour; see apply_texture), filtered by a level
 * of detail from the ray cone each camera, reflected and refracted ray
 * carries (shade.h, texture_lod).
 */
#include "render/shade.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "base/mat4.h"
#include "render/blend.h"
#include "render/gl_light.h"
#include "render/gl_shade.h"
#include "render/surface.h"

/* Safety factor on the error bound of the hit point (see surface_fetch in surface.c). */
#define OFFSET_ERROR_SCALE 2.0

void shade_offset_point(const float p[3], const float n[3], float error, float out[3])
{
    double d = OFFSET_ERROR_SCALE * (double)error;
    for (int k = 0; k < 3; k++) {
        double target = (double)p[k] + d * (double)n[k];
        float f = (float)target;
        /* Round away from the surface, never back towards it, so the
         * point moves at least d along n whatever the rounding. */
        if (n[k] > 0.0f && (double)f < target)
            f = nextafterf(f, INFINITY);
        else if (n[k] < 0.0f && (double)f > target)
            f = nextafterf(f, -INFINITY);
        out[k] = f;
    }
}

static void add_scaled(float acc[3], const float a[4], const float b[4], float scale)
{
    for (int k = 0; k < 3; k++)
        acc[k] += a[k] * b[k] * scale;
}

/* The shadow ray from `origin` to a light (tmin 0), and the direction
 * to it, not yet normalised: local_whitted's and shade_prime_shadows'
 * one computation, so both trace the same ray bit for bit. */
static void light_ray(const struct scene_light *light, const float origin[3], float to_light[3],
                      float shadow_dir[3], float *shadow_tmax)
{
    if (light->position[3] != 0.0f) {
        float lp[3];
        for (int k = 0; k < 3; k++)
            lp[k] = light->position[k] / light->position[3];
        vec3_sub(shadow_dir, lp, origin);
        *shadow_tmax = 1.0f;
    } else {
        memcpy(shadow_dir, light->position, 3 * sizeof(float));
        *shadow_tmax = INFINITY;
    }
    memcpy(to_light, shadow_dir, 3 * sizeof(float));
}

/* Whether a surface faces the light along the normalised to_light: only
 * then is a shadow ray traced (local_whitted). */
static int faces_light(const struct surface *s, const float to_light[3], float *n_dot_l)
{
    *n_dot_l = vec3_dot(s->n, to_light);
    return !(*n_dot_l <= 0.0f || vec3_dot(s->ng, to_light) <= 0.0f);
}

/* known / occluded: the answers shade_prime_shadows traced ahead, bit l
 * for light l (0, 0 when none). */
static void local_whitted(const struct shade_context *sc, const struct surface *s,
                          const float global_ambient[4], const float dir[3], unsigned known,
                          unsigned occluded, float c[3])
{
    const struct render_state *st = sc->state;
    for (int k = 0; k < 3; k++)
        c[k] = s->mat->emission[k] + global_ambient[k] * s->ambient[k];
    float view[3] = {-dir[0], -dir[1], -dir[2]};
    vec3_normalize(view);
    float origin[3];
    shade_offset_point(s->p, s->ng, s->p_error, origin);
    for (int i = 0; i < RENDER_MAX_LIGHTS; i++) {
        const struct scene_light *light = &st->lights[i];
        if (!light->enabled)
            continue;
        float to_light[3], shadow_dir[3], shadow_tmax, attenuation = 1.0f;
        light_ray(light, origin, to_light, shadow_dir, &shadow_tmax);
        if (light->position[3] != 0.0f) {
            float d = sqrtf(vec3_dot(to_light, to_light));
            float att = light->attenuation[0] + light->attenuation[1] * d +
                        light->attenuation[2] * d * d;
            attenuation = att > 0.0f ? 1.0f / att : 1.0f;
            if (light->spot_cutoff != 180.0f && d > 0.0f) {
                /* GL's spot cone (gl_light.c) scales every term of the
                 * light, its ambient one too; 180 (the default) leaves the
                 * Whitted images as they were. */
                float u[3] = {to_light[0] / d, to_light[1] / d, to_light[2] / d};
                attenuation *= gl_spot_factor(light, u);
            }
        }
        add_scaled(c, light->ambient, s->ambient, attenuation);
        if (!vec3_normalize(to_light))
            continue;
        float n_dot_l;
        if (!faces_light(s, to_light, &n_dot_l))
            continue;
        if (known >> i & 1u ? (int)(occluded >> i & 1u)
                            : trace_scene_any(sc->shadows, origin, shadow_dir, 0.0f, shadow_tmax,
                                              sc->counters))
            continue;
        add_scaled(c, light->diffuse, s->diffuse, attenuation * n_dot_l);
        float h[3] = {to_light[0] + view[0], to_light[1] + view[1], to_light[2] + view[2]};
        if (vec3_normalize(h)) {
            float n_dot_h = vec3_dot(s->n, h);
            if (n_dot_h > 0.0f) {
                float spec = s->mat->shininess > 0.0f ? powf(n_dot_h, s->mat->shininess) : 1.0f;
                add_scaled(c, light->specular, s->mat->specular, attenuation * spec);
            }
        }
    }
}

static void reflect_dir(const float d[3], const float n[3], float r[3])
{
    float k = 2.0f * vec3_dot(d, n);
    for (int i = 0; i < 3; i++)
        r[i] = d[i] - k * n[i];
}

/* Refraction by Snell's law; returns 0 on total internal reflection.
 * d is unit, n unit facing against d, eta = n_incident / n_transmitted. */
static int refract_dir(const float d[3], const float n[3], float eta, float t[3])
{
    float cos_i = -vec3_dot(d, n);
    float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);
    if (k < 0.0f)
        return 0;
    float a = eta * cos_i - sqrtf(k);
    for (int i = 0; i < 3; i++)
        t[i] = eta * d[i] + a * n[i];
    return 1;
}

/* The reflected (kind 0) or refracted (kind 1) ray of surface sp hit
 * along unit_dir: shade_hit's and shade_prime_shadows' one computation,
 * so both trace the same ray bit for bit.  A refraction that Snell's law
 * refuses, or that would not leave below the surface, reflects (total
 * internal reflection). */
static void next_ray(const struct surface *sp, const float unit_dir[3], int kind, float org[3],
                     float dir[3])
{
    if (kind == 0) {
        reflect_dir(unit_dir, sp->n, dir);
        if (vec3_dot(dir, sp->ng) <= 0.0f)
            reflect_dir(unit_dir, sp->ng, dir);
        shade_offset_point(sp->p, sp->ng, sp->p_error, org);
        return;
    }
    const float eta = sp->front ? 1.0f / sp->mat->ior : sp->mat->ior;
    const float below[3] = {-sp->ng[0], -sp->ng[1], -sp->ng[2]};
    if (refract_dir(unit_dir, sp->n, eta, dir) && vec3_dot(dir, sp->ng) < 0.0f) {
        shade_offset_point(sp->p, below, sp->p_error, org);
    } else {
        reflect_dir(unit_dir, sp->ng, dir);
        shade_offset_point(sp->p, sp->ng, sp->p_error, org);
    }
}

/* A cone after distance t along dir (shade_hit). */
static struct shade_cone cone_at(struct shade_cone cone, const float dir[3], float t)
{
    const float distance = t * sqrtf(vec3_dot(dir, dir));
    const struct shade_cone at = {fabsf(cone.width + cone.spread * distance), cone.spread};
    return at;
}

/* The same hit bit for bit (t by its bits: -0 and NaN are no hits). */
static int same_hit(const struct trace_scene_hit *a, const struct trace_scene_hit *b)
{
    return memcmp(&a->t, &b->t, sizeof(float)) == 0 && memcmp(&a->u, &b->u, sizeof(float)) == 0 &&
           memcmp(&a->v, &b->v, sizeof(float)) == 0 && a->prim == b->prim &&
           a->instance == b->instance;
}

static void hit_colour(const struct shade_context *sc, const float org[3], const float dir[3],
                       const struct trace_scene_hit *found, struct shade_cone cone, int depth,
                       const struct shade_primed *given, float rgba[4]);

/* shade_ray, with `given` NULL or the ray traced ahead
 * (shade_primed.next): the same ray, so its answer is taken. */
static void ray_colour(const struct shade_context *sc, const float org[3], const float dir[3],
                       float tmax, struct shade_cone cone, int depth,
                       const struct shade_primed *given, float rgba[4])
{
    struct trace_scene_hit hit;
    if (given && !(tmax == INFINITY && memcmp(given->org, org, sizeof(given->org)) == 0 &&
                   memcmp(given->dir, dir, sizeof(given->dir)) == 0))
        given = NULL;
    /* Reflected and refracted rays see every face; camera rays, which
     * skip the faces RT_CULL_FACE removes, go through render/blend.c.
     * Surfaces clipped away or failing their alpha test are not there
     * (sc->rays, render/secondary.h). */
    if (given ? !given->found
              : !trace_scene_closest(sc->rays, org, dir, 0.0f, tmax, &hit, sc->counters)) {
        memcpy(rgba, sc->state->clear_color, 4 * sizeof(float));
        return;
    }
    hit_colour(sc, org, dir, given ? &given->hit : &hit, cone, depth, given, rgba);
}

void shade_ray(const struct shade_context *sc, const float org[3], const float dir[3],
               float tmax, struct shade_cone cone, int depth, float rgba[4])
{
    ray_colour(sc, org, dir, tmax, cone, depth, NULL, rgba);
}

void shade_hit(const struct shade_context *sc, const float org[3], const float dir[3],
               const struct trace_scene_hit *found, struct shade_cone cone, int depth,
               float rgba[4])
{
    hit_colour(sc, org, dir, found, cone, depth, NULL, rgba);
}

/* shade_hit, with `given` NULL or what shade_prime_shadows traced ahead
 * for this hit at depth > 0 (at depth 0, sc->primed). */
static void hit_colour(const struct shade_context *sc, const float org[3], const float dir[3],
                       const struct trace_scene_hit *found, struct shade_cone cone, int depth,
                       const struct shade_primed *given, float rgba[4])
{
    const struct render_state *st = sc->state;
    const struct trace_scene_hit hit = *found;
    /* The cone at the hit: t counts in units of dir, which need not be
     * unit length.  Reflected and refracted rays start with this width and
     * the same spread: the paper's curvature term (sec. 20.3.4), which
     * widens cones off convex surfaces and narrows them off concave ones,
     * is left out, so secondary rays filter as if every mirror were flat. */
    const struct shade_cone at_hit = cone_at(cone, dir, hit.t);
    if (st->shading == RENDER_FIXED_FUNCTION) {
        gl_shade_hit(sc, &hit, org, dir, at_hit.width, rgba);
        return;
    }
    float c[3];
    float unit_dir[3] = {dir[0], dir[1], dir[2]};
    vec3_normalize(unit_dir);

    /* GL's switches that mean something here (docs/appearance.md): the
     * global ambient the primitive was drawn under (scene/gl_state.h), and
     * RT_LIGHTING once the program has used it (surface.c put the colour
     * of an unlit primitive into its diffuse material). */
    const float *global_ambient = shade_hit_instance(sc, &hit)->appearance.gl.light_model.ambient;
    if (st->shading == RENDER_EYE_LIGHT) {
        /* A headlight at the eye, no shadows: Wald, Benthin and Slusallek's (2003) "OpenGL-like
         * ray casting".  Only the colours it reads are fetched. */
        struct surface_colour e;
        surface_fetch_colour(sc, &hit, dir, at_hit.width, &e);
        float cosine = fabsf(vec3_dot(e.n, unit_dir));
        for (int k = 0; k < 3; k++)
            c[k] = !e.lighting && st->lighting_used
                       ? e.diffuse[k]
                       : e.emission[k] + global_ambient[k] * e.ambient[k] + e.diffuse[k] * cosine;
        memcpy(rgba, c, sizeof(c));
        rgba[3] = 1.0f;
        return;
    }
    /* The camera ray's first hit, or its reflected or refracted ray's:
     * shade_prime_shadows may have fetched its surface and traced its
     * shadow rays already. */
    const struct shade_primed *pr = depth == 0 ? sc->primed : given;
    if (pr && !(pr->surface && same_hit(&pr->hit, &hit)))
        pr = NULL;
    struct surface fetched;
    if (!pr)
        surface_fetch(sc, &hit, dir, at_hit.width, &fetched);
    const struct surface *sp = pr ? pr->surface : &fetched;

    const int unlit = st->lighting_used && !sp->mat->lighting;
    if (unlit)
        memcpy(c, sp->diffuse, sizeof(c));
    else
        local_whitted(sc, sp, global_ambient, unit_dir, pr ? pr->shadow_known : 0u,
                      pr ? pr->shadow_occluded : 0u, c);
    float kr = sp->mat->reflectivity, kt = sp->mat->transparency;
    if (depth < st->max_depth && (kr > 0.0f || kt > 0.0f)) {
        float out[4], next_org[3], next_dir[3];
        float local_weight = 1.0f - kt;
        for (int k = 0; k < 3; k++)
            c[k] *= local_weight;
        if (kr > 0.0f) {
            next_ray(sp, unit_dir, 0, next_org, next_dir);
            ray_colour(sc, next_org, next_dir, INFINITY, at_hit, depth + 1,
                       pr ? pr->next[0] : NULL, out);
            for (int k = 0; k < 3; k++)
                c[k] += kr * out[k];
        }
        if (kt > 0.0f) {
            next_ray(sp, unit_dir, 1, next_org, next_dir);
            ray_colour(sc, next_org, next_dir, INFINITY, at_hit, depth + 1,
                       pr ? pr->next[1] : NULL, out);
            for (int k = 0; k < 3; k++)
                c[k] += kt * out[k];
        }
    }
    memcpy(rgba, c, sizeof(c));
    rgba[3] = 1.0f;
}

/* The shadow rays from origin[i] of the lanes of `lit` (surfaces surf[i])
 * to each light, one packet per light when at least two are coherent;
 * their answers go to primed[i]'s shadow bits. */
static void shadow_packets(const struct shade_context *sc, unsigned lit,
                           const float origin[TRACE_PACKET][3], const struct surface *surf,
                           struct shade_primed *primed)
{
    const struct render_state *st = sc->state;
    for (int l = 0; l < RENDER_MAX_LIGHTS; l++) {
        const struct scene_light *light = &st->lights[l];
        if (!light->enabled)
            continue;
        struct trace_packet pk;
        const float *dirs[TRACE_PACKET];
        int n = 0;
        pk.active = 0;
        for (int i = 0; i < TRACE_PACKET; i++) {
            if (!(lit >> i & 1u))
                continue;
            float to_light[3], n_dot_l;
            light_ray(light, origin[i], to_light, pk.dir[i], &pk.tmax[i]);
            if (!vec3_normalize(to_light) || !faces_light(&surf[i], to_light, &n_dot_l))
                continue;
            memcpy(pk.org[i], origin[i], sizeof(origin[i]));
            pk.tmin[i] = 0.0f;
            pk.active |= 1u << i;
            dirs[n++] = pk.dir[i];
        }
        if (n < 2 || !trace_packet_coherent(dirs, n))
            continue;
        const unsigned occluded = trace_scene_any_packet(sc->shadows, &pk, sc->counters);
        for (int i = 0; i < TRACE_PACKET; i++) {
            if (!(pk.active >> i & 1u))
                continue;
            primed[i].shadow_known |= 1u << l;
            primed[i].shadow_occluded |= (occluded >> i & 1u) << l;
        }
    }
}

/*
 * The reflected and refracted rays of the primed first hits (lanes of
 * `drawn`, surfaces surf[i], camera rays along dir[i] with cone[i] to
 * hits[i]), which shade_hit traces at depth 0: traced here, a packet
 * per kind when coherent, and their hits' surfaces and shadow rays
 * primed as the first hits' are (shade.h).  Neighbouring pixels' mirror
 * rays off a flat or gently curved surface stay coherent, and their
 * hits' shadow rays share the light's position as the first hits' do:
 * on BART's kitchen 84 % of the shadow rays of depth-1 hits fall in
 * coherent groups of two or more (98 % for first hits).
 */
static void prime_next(const struct shade_context *sc, unsigned drawn,
                       const struct trace_scene_hit hits[TRACE_PACKET],
                       const float dir[TRACE_PACKET][3], const struct shade_cone cone[TRACE_PACKET],
                       struct surface *surf, struct shade_primed primed[TRACE_PACKET],
                       struct shade_primed next[2 * TRACE_PACKET])
{
    const struct render_state *st = sc->state;
    for (int kind = 0; kind < 2; kind++) {
        struct trace_packet pk;
        const float *dirs[TRACE_PACKET];
        int n = 0;
        pk.active = 0;
        for (int i = 0; i < TRACE_PACKET; i++) {
            if (!(drawn >> i & 1u))
                continue;
            const struct scene_material *m = surf[i].mat;
            if (!((kind == 0 ? m->reflectivity : m->transparency) > 0.0f))
                continue;
            float unit_dir[3] = {dir[i][0], dir[i][1], dir[i][2]};
            vec3_normalize(unit_dir);
            next_ray(&surf[i], unit_dir, kind, pk.org[i], pk.dir[i]);
            pk.tmin[i] = 0.0f;
            pk.tmax[i] = INFINITY;
            pk.active |= 1u << i;
            dirs[n++] = pk.dir[i];
        }
        if (!pk.active)
            continue;
        struct trace_scene_hit h[TRACE_PACKET];
        unsigned got = 0;
        if (n >= 2 && trace_packet_coherent(dirs, n)) {
            got = trace_scene_closest_packet(sc->rays, &pk, h, sc->counters);
        } else {
            for (int i = 0; i < TRACE_PACKET; i++)
                if (pk.active >> i & 1u &&
                    trace_scene_closest(sc->rays, pk.org[i], pk.dir[i], 0.0f, INFINITY, &h[i],
                                        sc->counters))
                    got |= 1u << i;
        }
        struct shade_primed *nx = &next[kind * TRACE_PACKET];
        struct surface *ns = &surf[(1 + kind) * TRACE_PACKET];
        float origin[TRACE_PACKET][3];
        unsigned lit = 0;
        for (int i = 0; i < TRACE_PACKET; i++) {
            if (!(pk.active >> i & 1u))
                continue;
            nx[i].found = (int)(got >> i & 1u);
            memcpy(nx[i].org, pk.org[i], sizeof(nx[i].org));
            memcpy(nx[i].dir, pk.dir[i], sizeof(nx[i].dir));
            nx[i].surface = NULL;
            nx[i].shadow_known = 0;
            nx[i].shadow_occluded = 0;
            nx[i].next[0] = NULL;
            nx[i].next[1] = NULL;
            primed[i].next[kind] = &nx[i];
            if (!nx[i].found)
                continue;
            nx[i].hit = h[i];
            /* shade_hit's cones: at the first hit, then along this ray. */
            const struct shade_cone first = cone_at(cone[i], dir[i], hits[i].t);
            surface_fetch(sc, &h[i], pk.dir[i], cone_at(first, pk.dir[i], h[i].t).width, &ns[i]);
            nx[i].surface = &ns[i];
            if (st->lighting_used && !ns[i].mat->lighting)
                continue;
            shade_offset_point(ns[i].p, ns[i].ng, ns[i].p_error, origin[i]);
            lit |= 1u << i;
        }
        if (lit)
            shadow_packets(sc, lit, (const float(*)[3])origin, ns, nx);
    }
}

void shade_prime_shadows(const struct shade_context *sc, unsigned found,
                         const struct trace_scene_hit hits[TRACE_PACKET],
                         const float org[TRACE_PACKET][3], const float dir[TRACE_PACKET][3],
                         const struct shade_cone cone[TRACE_PACKET], struct surface *surf,
                         struct shade_primed primed[TRACE_PACKET],
                         struct shade_primed next[2 * TRACE_PACKET])
{
    const struct render_state *st = sc->state;
    /* A frame with a hit filter (sc->shadows, render/secondary.h) traces
     * its packets with the filter, which packet_scene.c applies ray by
     * ray as the single walk does. */
    if (st->shading != RENDER_WHITTED)
        return;
    float origin[TRACE_PACKET][3];
    unsigned lit = 0, drawn = 0;
    for (int i = 0; i < TRACE_PACKET; i++) {
        if (!(found >> i & 1u))
            continue;
        /* A first hit GL does not draw (culled, outlined) gives the pixel
         * to a hit behind it: not primed, so no ray the shading does not
         * ask for is traced. */
        if (!gl_hit_drawn(sc, dir[i], &hits[i]))
            continue;
        /* Nor does a first hit a clip plane removes: blend.c shades
         * another hit behind it or at its distance. */
        if (sc->clipping && blend_hit_clipped(sc, org[i], dir[i], &hits[i]))
            continue;
        surface_fetch(sc, &hits[i], dir[i], cone_at(cone[i], dir[i], hits[i].t).width, &surf[i]);
        primed[i].surface = &surf[i];
        primed[i].shadow_known = 0;
        primed[i].shadow_occluded = 0;
        drawn |= 1u << i;
        if (st->lighting_used && !surf[i].mat->lighting)
            continue; /* unlit: no shadow rays */
        shade_offset_point(surf[i].p, surf[i].ng, surf[i].p_error, origin[i]);
        lit |= 1u << i;
    }
    if (lit)
        shadow_packets(sc, lit, (const float(*)[3])origin, surf, primed);
    /* shade_hit's reflected and refracted rays at depth 0. */
    if (drawn && st->max_depth > 0)
        prime_next(sc, drawn, hits, dir, cone, surf, primed, next);
}
