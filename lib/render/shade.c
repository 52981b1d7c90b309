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
#include <stdint.h>
#include <string.h>

#include "base/mat4.h"
#include "render/blend.h"
#include "render/gl_light.h"
#include "render/gl_shade.h"
#include "render/lanes.h"
#include "render/surface.h"
#include "trace/kernels.h"

/* The eye light's colour in the four float lanes, one colour channel a
 * lane: IEEE operations lane by lane, the same floats as one channel at
 * a time (the scalar loop under RT_NO_SIMD or without SSE2). */
#if defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <emmintrin.h>
#define SHADE_LANES 1
#if defined(__AVX__)
#include <immintrin.h> /* the AVX2 copy (render/shade_eye_avx2.c) */
#endif
#else
#define SHADE_LANES 0
#endif

/* Safety factor on the error bound of the hit point (see surface_fetch in surface.c). */
#define OFFSET_ERROR_SCALE 2.0

/* nextafterf(f, INFINITY) when up, else nextafterf(f, -INFINITY), for
 * every f, without the library call through the PLT (GCC does not
 * inline nextafterf; a robots Whitted frame made 228,000 of them): a
 * finite non-zero float's neighbour is one step of its bits away from
 * zero when the direction is its sign's, towards zero otherwise. */
static float next_float(float f, int up)
{
    if (f != f || f == (up ? INFINITY : -INFINITY))
        return f;
    if (f == 0.0f)
        return up ? 0x1p-149f : -0x1p-149f;
    uint32_t bits;
    memcpy(&bits, &f, sizeof(bits));
    bits += (f > 0.0f) == (up != 0) ? 1u : UINT32_MAX;
    memcpy(&f, &bits, sizeof(f));
    return f;
}

/* shade_offset_point, inlined into shade.c's callers: out of line, its
 * call cost more than the steps above saved. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void offset_point(const float p[3], const float n[3], float error, float out[3])
{
    double d = OFFSET_ERROR_SCALE * (double)error;
    for (int k = 0; k < 3; k++) {
        double target = (double)p[k] + d * (double)n[k];
        float f = (float)target;
        /* Round away from the surface, never back towards it, so the
         * point moves at least d along n whatever the rounding. */
        if (n[k] > 0.0f && (double)f < target)
            f = next_float(f, 1);
        else if (n[k] < 0.0f && (double)f > target)
            f = next_float(f, 0);
        out[k] = f;
    }
}

void shade_context_lights(struct shade_context *sc)
{
    sc->light_end = 0;
    for (int i = 0; i < RENDER_MAX_LIGHTS; i++)
        if (sc->state->lights[i].enabled)
            sc->light_end = i + 1;
}

void shade_offset_point(const float p[3], const float n[3], float error, float out[3])
{
    offset_point(p, n, error, out);
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
        c[k] = s->emission[k] + global_ambient[k] * s->ambient[k];
    float view[3] = {-dir[0], -dir[1], -dir[2]};
    vec3_normalize(view);
    float origin[3];
    offset_point(s->p, s->ng, s->p_error, origin);
    for (int i = 0; i < sc->light_end; i++) {
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
                float spec = s->shininess > 0.0f ? powf(n_dot_h, s->shininess) : 1.0f;
                add_scaled(c, light->specular, s->specular, attenuation * spec);
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

/* The eye light's colour of a hit whose surface colours are e, seen
 * along the unit vector u: `cosine` is |e->n . u| (vec3_dot). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void eye_light(const struct render_state *st, const struct surface_colour *e,
                             const float global_ambient[4], float cosine, float rgba[4])
{
#if SHADE_LANES
    /* Channel k in lane k: (emission + ambient_g ambient) + diffuse cosine
     * as the scalar loop evaluates it; lane 3 (whatever the alphas give)
     * is replaced by the opaque 1. */
    __m128 c = _mm_loadu_ps(e->diffuse);
    if (e->lighting || !st->lighting_used)
        c = _mm_add_ps(_mm_add_ps(_mm_loadu_ps(e->emission),
                                  _mm_mul_ps(_mm_loadu_ps(global_ambient),
                                             _mm_loadu_ps(e->ambient))),
                       _mm_mul_ps(c, _mm_set1_ps(cosine)));
    /* (c2, 1, c3, 1), then (c0, c1, c2, 1). */
    const __m128 high = _mm_unpackhi_ps(c, _mm_set1_ps(1.0f));
    _mm_storeu_ps(rgba, _mm_shuffle_ps(c, high, _MM_SHUFFLE(1, 0, 1, 0)));
#else
    float c[3];
    for (int k = 0; k < 3; k++)
        c[k] = !e->lighting && st->lighting_used
                   ? e->diffuse[k]
                   : e->emission[k] + global_ambient[k] * e->ambient[k] + e->diffuse[k] * cosine;
    memcpy(rgba, c, sizeof(c));
    rgba[3] = 1.0f;
#endif
}

void shade_ray(const struct shade_context *sc, const float org[3], const float dir[3],
               float tmax, struct shade_cone cone, int depth, float rgba[4])
{
    struct trace_scene_hit hit;
    /* Reflected and refracted rays see every face; camera rays, which
     * skip the faces RT_CULL_FACE removes, go through render/blend.c.
     * Surfaces clipped away or failing their alpha test are not there
     * (sc->rays, render/secondary.h). */
    if (!trace_scene_closest(sc->rays, org, dir, 0.0f, tmax, &hit, sc->counters)) {
        memcpy(rgba, sc->state->clear_color, 4 * sizeof(float));
        return;
    }
    shade_hit(sc, org, dir, &hit, cone, depth, rgba);
}

/* shade_hit with the primed hit `primed` (NULL: none): the camera ray's
 * (shade_context.primed) at depth 0, its reflected ray's at depth 1. */
static void shade_hit_primed(const struct shade_context *sc, const struct shade_primed *primed,
                             const float org[3], const float dir[3],
                             const struct trace_scene_hit *found, struct shade_cone cone,
                             int depth, float rgba[4])
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
        eye_light(st, &e, global_ambient, fabsf(vec3_dot(e.n, unit_dir)), rgba);
        return;
    }
    /* The camera ray's first hit: shade_prime_shadows may have fetched
     * its surface and traced its shadow rays already. */
    const struct shade_primed *pr = primed;
    if (pr && !(pr->surface && same_hit(&pr->hit, &hit)))
        pr = NULL;
    struct surface fetched;
    if (!pr)
        surface_fetch(sc, &hit, dir, at_hit.width, depth, &fetched);
    const struct surface *sp = pr ? pr->surface : &fetched;

    const int unlit = st->lighting_used && !sp->lighting;
    if (unlit)
        memcpy(c, sp->diffuse, sizeof(c));
    else
        local_whitted(sc, sp, global_ambient, unit_dir, pr ? pr->shadow_known : 0u,
                      pr ? pr->shadow_occluded : 0u, c);
    float kr = sp->reflectivity, kt = sp->transparency;
    if (depth < st->max_depth && (kr > 0.0f || kt > 0.0f)) {
        float out[4], next_org[3], next_dir[3];
        float local_weight = 1.0f - kt;
        for (int k = 0; k < 3; k++)
            c[k] *= local_weight;
        if (kr > 0.0f) {
            reflect_dir(unit_dir, sp->n, next_dir);
            if (vec3_dot(next_dir, sp->ng) <= 0.0f)
                reflect_dir(unit_dir, sp->ng, next_dir);
            offset_point(sp->p, sp->ng, sp->p_error, next_org);
            if (pr && pr->reflect_known) {
                /* Traced ahead in the block's packet (shade_prime_shadows):
                 * the same ray, so the same hit. */
                if (pr->reflect_found)
                    shade_hit_primed(sc, pr->reflected, next_org, next_dir, &pr->reflect_hit,
                                     at_hit, depth + 1, out);
                else
                    memcpy(out, st->clear_color, 4 * sizeof(float));
            } else
                shade_ray(sc, next_org, next_dir, INFINITY, at_hit, depth + 1, out);
            for (int k = 0; k < 3; k++)
                c[k] += kr * out[k];
        }
        if (kt > 0.0f) {
            float eta = sp->front ? 1.0f / sp->ior : sp->ior;
            float below[3] = {-sp->ng[0], -sp->ng[1], -sp->ng[2]};
            if (refract_dir(unit_dir, sp->n, eta, next_dir) && vec3_dot(next_dir, sp->ng) < 0.0f) {
                offset_point(sp->p, below, sp->p_error, next_org);
            } else {
                /* Total internal reflection. */
                reflect_dir(unit_dir, sp->ng, next_dir);
                offset_point(sp->p, sp->ng, sp->p_error, next_org);
            }
            shade_ray(sc, next_org, next_dir, INFINITY, at_hit, depth + 1, out);
            for (int k = 0; k < 3; k++)
                c[k] += kt * out[k];
        }
    }
    memcpy(rgba, c, sizeof(c));
    rgba[3] = 1.0f;
}

void shade_hit(const struct shade_context *sc, const float org[3], const float dir[3],
               const struct trace_scene_hit *found, struct shade_cone cone, int depth,
               float rgba[4])
{
    shade_hit_primed(sc, depth == 0 ? sc->primed : NULL, org, dir, found, cone, depth, rgba);
}

/* The surfaces a block fetches together (surface_fetches): packet lane
 * index[f] is the f-th of n. */
struct fetch_list {
    const struct trace_scene_hit *hit[TRACE_PACKET];
    const float *dir[TRACE_PACKET];
    float width[TRACE_PACKET];
    struct surface *surf[TRACE_PACKET];
    int index[TRACE_PACKET];
    int n;
};

static inline void fetch_list_add(struct fetch_list *fl, int lane,
                                  const struct trace_scene_hit *hit, const float *dir,
                                  float width, struct surface *surf)
{
    fl->hit[fl->n] = hit;
    fl->dir[fl->n] = dir;
    fl->width[fl->n] = width;
    fl->surf[fl->n] = surf;
    fl->index[fl->n++] = lane;
}

/* The shadow rays of the surfaces surf[i] (bit i of lit) from origin[i],
 * one packet per light when at least two are coherent, their answers in
 * primed[i] (shade_prime_shadows). */
static void prime_light_packets(const struct shade_context *sc, const struct surface *surf,
                                const float origin[TRACE_PACKET][3], unsigned lit,
                                struct shade_primed primed[TRACE_PACKET])
{
    const struct render_state *st = sc->state;
    if (!lit)
        return;
    for (int l = 0; l < sc->light_end; l++) {
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

/* The fewest reflected rays prime_reflections traces as a packet: with
 * two or three (or an octant's two or three of an incoherent block) the
 * packet cost the BART robots and kitchen more than the single rays. */
#define PRIME_MIN_RAYS 4

/* The octant of a direction, one bit a sign. */
static int dir_octant(const float d[3])
{
    return (d[0] < 0.0f) | (d[1] < 0.0f) << 1 | (d[2] < 0.0f) << 2;
}

/*
 * The reflected rays of a block's primed hits at `depth` (hits[i] of the
 * ray along dir[i] with cone[i], its surface surf[i], primed[i]; camera
 * rays at depth 0) with a reflective surface, traced together when they
 * are at least PRIME_MIN_RAYS and coherent (trace_packet_coherent), else
 * each octant's rays together when they are: on a BART robots Whitted
 * frame every camera ray's hit reflects and 82 % of the blocks'
 * reflected rays pass the test.  Each ray is shade_hit's own (the same
 * unit direction, reflection and offset operations), and a packet's hits
 * are the single rays' (trace/packet_scene.h): shade_hit takes
 * primed[i]'s answer instead of tracing it alone.  A reflected hit's
 * surface is fetched as shade_hit fetches it at depth + 1 (its cone: the
 * ray's at its hit, then along the reflected ray) into next_surf[i] and
 * primed in next[i] (its direction and cone in next_dir[i] and
 * next_cone[i]), its shadow rays traced in packets too.  Returns the
 * mask of the rays primed in next.
 */
static unsigned prime_reflections(const struct shade_context *sc, int depth,
                                  const struct trace_scene_hit hits[TRACE_PACKET],
                                  const float dir[TRACE_PACKET][3],
                                  const struct shade_cone cone[TRACE_PACKET],
                                  const struct surface *surf,
                                  struct shade_primed primed[TRACE_PACKET],
                                  struct surface *next_surf, struct shade_primed next[TRACE_PACKET],
                                  float next_dir[TRACE_PACKET][3],
                                  struct shade_cone next_cone[TRACE_PACKET])
{
    if (depth >= sc->state->max_depth)
        return 0;
    struct trace_packet pk;
    const float *dirs[TRACE_PACKET];
    int n = 0;
    pk.active = 0;
    for (int i = 0; i < TRACE_PACKET; i++) {
        next[i].surface = NULL;
        if (primed[i].surface != &surf[i] || !(surf[i].reflectivity > 0.0f))
            continue;
        const struct surface *sp = &surf[i];
        float unit_dir[3] = {dir[i][0], dir[i][1], dir[i][2]};
        vec3_normalize(unit_dir);
        reflect_dir(unit_dir, sp->n, pk.dir[i]);
        if (vec3_dot(pk.dir[i], sp->ng) <= 0.0f)
            reflect_dir(unit_dir, sp->ng, pk.dir[i]);
        offset_point(sp->p, sp->ng, sp->p_error, pk.org[i]);
        pk.tmin[i] = 0.0f;
        pk.tmax[i] = INFINITY;
        pk.active |= 1u << i;
        dirs[n++] = pk.dir[i];
    }
    if (n < PRIME_MIN_RAYS)
        return 0;
    struct trace_scene_hit rhits[TRACE_PACKET];
    unsigned found = 0;
    if (trace_packet_coherent(dirs, n)) {
        found = trace_scene_closest_packet(sc->rays, &pk, rhits, sc->counters);
    } else {
        /* The rays of each octant alone, when PRIME_MIN_RAYS or more of
         * them are coherent; the others are left to shade_hit. */
        unsigned rest = pk.active, traced = 0;
        while (rest) {
            int first = 0;
            while (!(rest >> first & 1u))
                first++;
            const int octant = dir_octant(pk.dir[first]);
            unsigned group = 0;
            int m = 0;
            for (int i = first; i < TRACE_PACKET; i++) {
                if (!(rest >> i & 1u) || dir_octant(pk.dir[i]) != octant)
                    continue;
                group |= 1u << i;
                dirs[m++] = pk.dir[i];
            }
            rest &= ~group;
            if (m < PRIME_MIN_RAYS || !trace_packet_coherent(dirs, m))
                continue;
            pk.active = group;
            found |= trace_scene_closest_packet(sc->rays, &pk, rhits, sc->counters);
            traced |= group;
        }
        pk.active = traced;
        if (!traced)
            return 0;
    }
    float origin[TRACE_PACKET][3];
    unsigned lit = 0;
    struct fetch_list fl;
    fl.n = 0;
    for (int i = 0; i < TRACE_PACKET; i++) {
        if (!(pk.active >> i & 1u))
            continue;
        primed[i].reflect_known = 1;
        primed[i].reflect_found = (int)(found >> i & 1u);
        primed[i].reflected = NULL;
        if (!primed[i].reflect_found)
            continue;
        primed[i].reflect_hit = rhits[i];
        next_cone[i] = cone_at(cone[i], dir[i], hits[i].t);
        memcpy(next_dir[i], pk.dir[i], sizeof(next_dir[i]));
        fetch_list_add(&fl, i, &rhits[i], next_dir[i],
                       cone_at(next_cone[i], pk.dir[i], rhits[i].t).width, &next_surf[i]);
    }
    surface_fetches(sc, fl.n, fl.hit, fl.dir, fl.width, depth + 1, fl.surf);
    for (int f = 0; f < fl.n; f++) {
        const int i = fl.index[f];
        const struct surface *rs = &next_surf[i];
        next[i].found = 1;
        next[i].hit = rhits[i];
        next[i].surface = rs;
        next[i].shadow_known = 0;
        next[i].shadow_occluded = 0;
        next[i].reflect_known = 0;
        next[i].reflected = NULL;
        primed[i].reflected = &next[i];
        if (sc->state->lighting_used && !rs->lighting)
            continue; /* unlit: no shadow rays */
        offset_point(rs->p, rs->ng, rs->p_error, origin[i]);
        lit |= 1u << i;
    }
    prime_light_packets(sc, next_surf, (const float(*)[3])origin, lit, next);
    return found & pk.active;
}

void shade_prime_shadows(const struct shade_context *sc, unsigned found,
                         const struct trace_scene_hit hits[TRACE_PACKET],
                         const float org[TRACE_PACKET][3], const float dir[TRACE_PACKET][3],
                         const struct shade_cone cone[TRACE_PACKET],
                         struct surface *surf,
                         struct shade_primed primed[TRACE_PACKET],
                         struct shade_primed *reflected)
{
    const struct render_state *st = sc->state;
    /* A frame with a hit filter (sc->shadows, render/secondary.h) traces
     * its packets with the filter, which packet_scene.c applies ray by
     * ray as the single walk does. */
    if (st->shading != RENDER_WHITTED)
        return;
    float origin[TRACE_PACKET][3];
    unsigned lit = 0;
    struct fetch_list fl;
    fl.n = 0;
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
        fetch_list_add(&fl, i, &hits[i], dir[i], cone_at(cone[i], dir[i], hits[i].t).width,
                       &surf[i]);
    }
    /* The surfaces together: their levels of detail two at a time. */
    surface_fetches(sc, fl.n, fl.hit, fl.dir, fl.width, 0, fl.surf);
    for (int f = 0; f < fl.n; f++) {
        const int i = fl.index[f];
        primed[i].surface = &surf[i];
        primed[i].shadow_known = 0;
        primed[i].shadow_occluded = 0;
        primed[i].reflect_known = 0;
        if (st->lighting_used && !surf[i].lighting)
            continue; /* unlit: no shadow rays */
        offset_point(surf[i].p, surf[i].ng, surf[i].p_error, origin[i]);
        lit |= 1u << i;
    }
    /* The reflected rays depth by depth, while some are primed. */
    struct trace_scene_hit level_hits[SHADE_PRIME_DEPTHS][TRACE_PACKET];
    float level_dir[SHADE_PRIME_DEPTHS][TRACE_PACKET][3];
    struct shade_cone level_cone[SHADE_PRIME_DEPTHS][TRACE_PACKET];
    const struct trace_scene_hit *at_hits = hits;
    const float(*at_dir)[3] = dir;
    const struct shade_cone *at_cone = cone;
    struct shade_primed *at_primed = primed;
    for (int d = 0; d < SHADE_PRIME_DEPTHS; d++) {
        struct shade_primed *next = reflected + d * TRACE_PACKET;
        const unsigned got = prime_reflections(
            sc, d, at_hits, at_dir, at_cone, surf + d * TRACE_PACKET, at_primed,
            surf + (d + 1) * TRACE_PACKET, next, level_dir[d], level_cone[d]);
        if (!got)
            break;
        for (int i = 0; i < TRACE_PACKET; i++)
            if (got >> i & 1u)
                level_hits[d][i] = next[i].hit;
        at_hits = level_hits[d];
        at_dir = (const float(*)[3])level_dir[d];
        at_cone = level_cone[d];
        at_primed = next;
    }
    prime_light_packets(sc, surf, (const float(*)[3])origin, lit, primed);
}

#if SHADE_LANES && defined(__AVX__)
/* eye_widths8 (below) from the directions and cones by component
 * (lane_d[k][i], lane_w[i], lane_s[i]), as shade_eye_block_begin has
 * them from the ray maker. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void eye_widths8_lanes(const float lane_d[3][TRACE_PACKET], const float lane_w[],
                                     const float lane_s[],
                                     const struct trace_scene_hit *const hits[], float width[],
                                     float unit[3][TRACE_PACKET])
{
    float lane_t[TRACE_PACKET];
    for (int i = 0; i < TRACE_PACKET; i++)
        lane_t[i] = hits[i]->t;
    __m256 d[3];
    for (int k = 0; k < 3; k++)
        d[k] = _mm256_loadu_ps(lane_d[k]);
    const __m256 len = _mm256_sqrt_ps(lanes_dot8(d, d));
    const __m256 w = _mm256_add_ps(
        _mm256_loadu_ps(lane_w),
        _mm256_mul_ps(_mm256_loadu_ps(lane_s), _mm256_mul_ps(_mm256_loadu_ps(lane_t), len)));
    _mm256_storeu_ps(width, _mm256_andnot_ps(_mm256_set1_ps(-0.0f), w));
    /* len > 0 and finite (not above FLT_MAX; a NaN fails both): the
     * direction times 1 / len, else the direction itself. */
    const __m256 ok = _mm256_and_ps(_mm256_cmp_ps(len, _mm256_setzero_ps(), _CMP_GT_OQ),
                                    _mm256_cmp_ps(len, _mm256_set1_ps(FLT_MAX), _CMP_LE_OQ));
    const __m256 inv = _mm256_div_ps(_mm256_set1_ps(1.0f), len);
    for (int k = 0; k < 3; k++)
        _mm256_storeu_ps(unit[k], _mm256_blendv_ps(d[k], _mm256_mul_ps(d[k], inv), ok));
}

/* A block's TRACE_PACKET hits' cone widths and unit directions (eye_hits'
 * first loop) in eight float lanes, lane i hit i, each lane the scalar
 * operations in their order: the same floats.  unit[k][i] is component k
 * of hit i's, lane_d[k][i] that of its direction as given (for
 * surface_fetch_lanes).  Inlined (with eye_widths8_lanes): GCC kept
 * it out of line when it had two callers, its arrays then passed
 * through memory (16 M instructions a kitchen frame). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void eye_widths8(const float *const dir[], const struct trace_scene_hit *const hits[],
                        const struct shade_cone cone[], float width[],
                        float unit[3][TRACE_PACKET], float lane_d[3][TRACE_PACKET])
{
    float lane_w[TRACE_PACKET], lane_s[TRACE_PACKET];
    for (int i = 0; i < TRACE_PACKET; i++) {
        for (int k = 0; k < 3; k++)
            lane_d[k][i] = dir[i][k];
        lane_w[i] = cone[i].width;
        lane_s[i] = cone[i].spread;
    }
    eye_widths8_lanes(lane_d, lane_w, lane_s, hits, width, unit);
}

/* |e[i].n . unit_i| of the TRACE_PACKET hits in eight float lanes. */
static void eye_cosines8(const struct surface_colour e[], float unit[3][TRACE_PACKET],
                         float cosine[])
{
    float lane_n[3][TRACE_PACKET];
    for (int i = 0; i < TRACE_PACKET; i++)
        for (int k = 0; k < 3; k++)
            lane_n[k][i] = e[i].n[k];
    __m256 nv[3], u[3];
    for (int k = 0; k < 3; k++) {
        nv[k] = _mm256_loadu_ps(lane_n[k]);
        u[k] = _mm256_loadu_ps(unit[k]);
    }
    _mm256_storeu_ps(cosine, _mm256_andnot_ps(_mm256_set1_ps(-0.0f), lanes_dot8(nv, u)));
}
#endif

#if SHADE_LANES && defined(__AVX2__)
/* eye_light of a block on one triangle (surface_fetch_lanes) in eight
 * float lanes, lane i hit i: the cosine |n . unit| as eye_cosines8, then
 * each channel (emission + ambient_g ambient) + diffuse cosine, or the
 * diffuse colour where the primitive is unlit in a lit frame, as
 * eye_light evaluates it, and alpha 1 (the pixels transposed out of the
 * lanes).  Inlined into its callers (eye_hits, shade_eye_block_begin,
 * shade_eye_block_end) as eye_widths8. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void eye_light8(const struct render_state *st, const struct surface_lanes *e,
                       const float global_ambient[4], float unit[3][TRACE_PACKET],
                       float *const rgba[])
{
    __m256 nv[3], u[3], c[3];
    for (int k = 0; k < 3; k++) {
        nv[k] = _mm256_loadu_ps(e->n[k]);
        u[k] = _mm256_loadu_ps(unit[k]);
    }
    const __m256 cosine = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), lanes_dot8(nv, u));
    const int lit = e->lighting || !st->lighting_used;
    for (int k = 0; k < 3; k++) {
        c[k] = _mm256_loadu_ps(e->diffuse[k]);
        if (lit)
            c[k] = _mm256_add_ps(_mm256_add_ps(_mm256_set1_ps(e->emission[k]),
                                               _mm256_mul_ps(_mm256_set1_ps(global_ambient[k]),
                                                             _mm256_loadu_ps(e->ambient[k]))),
                                 _mm256_mul_ps(c[k], cosine));
    }
    /* (r, g, b, 1) of each lane: lanes i and i + 4 share a 128-bit half. */
    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256 rg_lo = _mm256_unpacklo_ps(c[0], c[1]), rg_hi = _mm256_unpackhi_ps(c[0], c[1]);
    const __m256 b1_lo = _mm256_unpacklo_ps(c[2], one), b1_hi = _mm256_unpackhi_ps(c[2], one);
    const __m256 p[4] = {_mm256_shuffle_ps(rg_lo, b1_lo, _MM_SHUFFLE(1, 0, 1, 0)),
                         _mm256_shuffle_ps(rg_lo, b1_lo, _MM_SHUFFLE(3, 2, 3, 2)),
                         _mm256_shuffle_ps(rg_hi, b1_hi, _MM_SHUFFLE(1, 0, 1, 0)),
                         _mm256_shuffle_ps(rg_hi, b1_hi, _MM_SHUFFLE(3, 2, 3, 2))};
    for (int i = 0; i < 4; i++) {
        _mm_storeu_ps(rgba[i], _mm256_castps256_ps128(p[i]));
        _mm_storeu_ps(rgba[i + 4], _mm256_extractf128_ps(p[i], 1));
    }
}
#endif

#if SHADE_LANES && defined(__AVX__)
/* eye_hits of a whole block that surface_fetch_lanes does not take: the
 * colours hit by hit (surface_fetch_colours), the cosines in the lanes,
 * then the eye light hit by hit. */
static void eye_block_hits(const struct shade_context *sc, const float *const dir[],
                           const struct trace_scene_hit *const hits[], const float width[],
                           float unit[3][TRACE_PACKET], float *const rgba[])
{
    struct surface_colour e[TRACE_PACKET];
    float cosine[TRACE_PACKET];
    surface_fetch_colours(sc, TRACE_PACKET, hits, dir, width, e);
    eye_cosines8(e, unit, cosine);
    const struct scene_instance *inst = NULL;
    uint32_t instance = 0;
    for (int i = 0; i < TRACE_PACKET; i++) {
        if (!inst || hits[i]->instance != instance) {
            inst = shade_hit_instance(sc, hits[i]);
            instance = hits[i]->instance;
        }
        eye_light(sc->state, &e[i], inst->appearance.gl.light_model.ambient, cosine[i], rgba[i]);
    }
}
#endif

#if defined(SHADE_UNIT_AVX2)
int shade_eye_block_begin(const struct shade_context *sc, const float *const dir[],
                          const struct shade_eye_rays *rays,
                          const struct trace_scene_hit *const hits[], float *const rgba[],
                          struct shade_eye_pending *pending)
{
    float width[TRACE_PACKET];
    eye_widths8_lanes(rays->dir, rays->width, rays->spread, hits, width, pending->unit);
    const int got = surface_fetch_lanes(sc, hits, rays->dir, width, &pending->lanes,
                                        &pending->lookup);
    if (!got) {
        eye_block_hits(sc, dir, hits, width, pending->unit, rgba);
        return 0;
    }
    const float *global_ambient =
        shade_hit_instance(sc, hits[0])->appearance.gl.light_model.ambient;
    if (got == 1) {
        eye_light8(sc->state, &pending->lanes, global_ambient, pending->unit, rgba);
        return 0;
    }
    pending->global_ambient = global_ambient;
    for (int i = 0; i < TRACE_PACKET; i++)
        pending->rgba[i] = rgba[i];
    return 1;
}

void shade_eye_block_end(const struct shade_context *sc, struct shade_eye_pending *pending)
{
    /* surface_fetch_lanes' last step (lanes_texture_end's products, the
     * colour times the texel as there), then eye_light8 as eye_hits. */
    float rgb[3][TRACE_PACKET];
    scene_texture_finish_lod8(&pending->lookup, rgb);
    struct surface_lanes *lanes = &pending->lanes;
    for (int k = 0; k < 3; k++) {
        const __m256 texel = _mm256_loadu_ps(rgb[k]);
        _mm256_storeu_ps(lanes->ambient[k],
                         _mm256_mul_ps(_mm256_loadu_ps(lanes->ambient[k]), texel));
        _mm256_storeu_ps(lanes->diffuse[k],
                         _mm256_mul_ps(_mm256_loadu_ps(lanes->diffuse[k]), texel));
    }
    eye_light8(sc->state, lanes, pending->global_ambient, pending->unit, pending->rgba);
}
#endif

static void eye_hits(const struct shade_context *sc, int n, const float *const dir[],
                     const struct trace_scene_hit *const hits[], const struct shade_cone cone[],
                     float *const rgba[])
{
    float width[TRACE_PACKET] = {0}; /* n of them set (zeros for the compiler's warning) */
#if SHADE_LANES && defined(__AVX__)
    if (n == TRACE_PACKET) {
        /* A whole block: the per-hit steps below in eight lanes. */
        float unit[3][TRACE_PACKET], lane_d[3][TRACE_PACKET];
        eye_widths8(dir, hits, cone, width, unit, lane_d);
#if defined(__AVX2__)
        struct surface_lanes lanes;
        if (surface_fetch_lanes(sc, hits, lane_d, width, &lanes, NULL)) {
            /* One instance (surface_fetch_lanes refuses more). */
            eye_light8(sc->state, &lanes,
                       shade_hit_instance(sc, hits[0])->appearance.gl.light_model.ambient, unit,
                       rgba);
            return;
        }
#endif
        eye_block_hits(sc, dir, hits, width, unit, rgba);
        return;
    }
#endif
    struct surface_colour e[TRACE_PACKET];
    float unit_dir[TRACE_PACKET][3];
    /* shade_hit's steps up to the surface's colours for every hit, ... */
    for (int i = 0; i < n; i++) {
        /* cone_at's |dir| and vec3_normalize's are the same sqrtf of the
         * same dot product: taken once, then each one's operations. */
        const float len = sqrtf(vec3_dot(dir[i], dir[i]));
        width[i] = fabsf(cone[i].width + cone[i].spread * (hits[i]->t * len));
        memcpy(unit_dir[i], dir[i], sizeof(unit_dir[i]));
        if (len > 0.0f && isfinite(len)) {
            const float inv = 1.0f / len;
            for (int k = 0; k < 3; k++)
                unit_dir[i][k] *= inv;
        }
    }
    /* ... the colours, their levels of detail two at a time, ... */
    surface_fetch_colours(sc, n, hits, dir, width, e);
    /* ... and the eye light. */
    for (int i = 0; i < n; i++) {
        const float *global_ambient =
            shade_hit_instance(sc, hits[i])->appearance.gl.light_model.ambient;
        eye_light(sc->state, &e[i], global_ambient, fabsf(vec3_dot(e[i].n, unit_dir[i])),
                  rgba[i]);
    }
}

void shade_eye_hits(const struct shade_context *sc, int n, const float *const dir[],
                    const struct trace_scene_hit *const hits[],
                    const struct shade_cone cone[], float *const rgba[])
{
#if !defined(SHADE_UNIT_AVX2)
    /* The AVX-512 copy of this function (shade_eye_avx512.c) when the
     * context traces with AVX-512, the AVX2 copy (shade_eye_avx2.c) when
     * it traces with AVX2 (or with AVX-512 where that unit is absent);
     * the test before the batch's frame is set up. */
    const struct trace_kernels *table = sc->scene->kernels;
    if (table && table->isa >= TRACE_ISA_AVX512) {
        const shade_eye_hits_fn avx512 = shade_eye_hits_avx512_unit();
        if (avx512) {
            avx512(sc, n, dir, hits, cone, rgba);
            return;
        }
    }
    if (table && table->isa >= TRACE_ISA_AVX2) {
        const shade_eye_hits_fn avx2 = shade_eye_hits_avx2_unit();
        if (avx2) {
            avx2(sc, n, dir, hits, cone, rgba);
            return;
        }
    }
#endif
    eye_hits(sc, n, dir, hits, cone, rgba);
}
