/* SPDX-License-Identifier: Apache-2.0 */
/*
 * shade.h - surface shading: eye light and Whitted-style ray tracing.
 */
#ifndef RT_RENDER_SHADE_H
#define RT_RENDER_SHADE_H

#include "render/render.h"
#include "trace/packet_scene.h"

/* The tile's surface caches (shade_context.cache): camera rays' hits and
 * the reflection depths 1 to 3 (OpenRT's depth, bart's default) each
 * have their own, deeper hits share the last. */
#define SHADE_CACHES 4

/* The eye light's block paths' cache entries (shade_context.eye), direct-
 * mapped by primitive: a power of two.  Counted over a kitchen frame's
 * blocks (137,412 triangle lookups, 17,006 distinct triangles): 52,569
 * misses with the tile's four entries emptied at every tile, 30,325 with
 * 32 entries kept over a worker's tiles, 25,387 with 64. */
#define SHADE_EYE_CACHES 64

/* The reflection depths shade_prime_shadows traces ahead in packets:
 * shade_prime_shadows' surf then has (1 + SHADE_PRIME_DEPTHS) *
 * TRACE_PACKET entries, its `reflected` SHADE_PRIME_DEPTHS * TRACE_PACKET
 * (depth d + 1 at d * TRACE_PACKET). */
#define SHADE_PRIME_DEPTHS 3

/* Per-thread context for shading one ray tree. */
struct shade_context {
    const struct render_state *state;
    const struct scene_frame *frame;
    const struct trace_scene *scene;
    struct trace_scene_counters *counters;
    const struct scene_textures *textures; /* read only */
    int clipping; /* some instance has clip planes (scene_appearance.clip) */
    /* Some instance was drawn with RT_BLEND or RT_ALPHA_TEST
     * (scene_appearance.raster): only then does a primary hit look its
     * instance's raster state up (blend.c). */
    int see_through;
    /* NULL, or the first hit of the camera ray being shaded, already
     * traced with tmin 0 in a packet by the tile loop (render.c): the
     * first trace of render/gl_shade.c's gl_closest_drawn takes it
     * instead of tracing again.  The same hit bit for bit
     * (trace/packet_scene.h). */
    const struct shade_primed *primed;
    /* NULL, or the tile's SHADE_CACHES caches of what surface.c derives
     * from a hit's triangle alone (surface.h, surface_cache): entry d for
     * Whitted's hits at depth d (the last one for deeper hits), entry 0
     * for the other shadings' hits one by one, and, when `eye` is NULL,
     * the eye light's block paths (surface_fetch_lanes) entry
     * prim % SHADE_CACHES: writable through a const context, as they
     * only remember results. */
    struct surface_cache *cache;
    /* NULL, or the worker's SHADE_EYE_CACHES entries for the eye light's
     * block paths (surface_fetch_lanes), entry prim % SHADE_EYE_CACHES,
     * kept from tile to tile over the pass (render_pass.eye_caches): a
     * tile's edge triangles are its neighbours' too.  Writable as
     * `cache`. */
    struct surface_cache *eye;
    /* What shadow rays and reflected or refracted rays trace: `scene`
     * with the filter of render/secondary.h when the frame has clip
     * planes, alpha test or blending, else `scene` itself. */
    const struct trace_scene *shadows;
    const struct trace_scene *rays;
    /* One past the last enabled light of state->lights: Whitted's loops
     * over the lights stop there (shade_context_lights). */
    int light_end;
};

/* Sets sc->light_end from sc->state's lights. */
void shade_context_lights(struct shade_context *sc);

struct surface;

struct shade_primed {
    int found;
    struct trace_scene_hit hit;
    /* NULL, or Whitted shading's surface of `hit` for this camera ray
     * (surface_fetch with shade_hit's arguments at depth 0), fetched by
     * shade_prime_shadows; shade_hit takes it for the same hit at depth
     * 0 instead of fetching again.  Then bit l of shadow_known says light
     * l's shadow ray from it was traced in a packet, bit l of
     * shadow_occluded its answer. */
    const struct surface *surface;
    unsigned shadow_known;
    unsigned shadow_occluded;
    /* With `surface`: 1 when its reflected ray was traced in a packet
     * (shade_prime_shadows), reflect_found and reflect_hit its answer. */
    int reflect_known;
    int reflect_found;
    struct trace_scene_hit reflect_hit;
    /* With reflect_found: that hit primed for shade_hit one depth
     * further (its surface and shadow rays, and on), or NULL. */
    const struct shade_primed *reflected;
};

/* The frame's instance a hit belongs to: its appearance, clip planes and
 * raster state, and its object's mesh. */
static inline const struct scene_instance *shade_hit_instance(const struct shade_context *sc,
                                                              const struct trace_scene_hit *hit)
{
    const struct trace_instance *ti = &sc->scene->instances[hit->instance];
    return &sc->frame->committed.items[ti->instance_id];
}

/*
 * A ray cone, the pixel footprint a ray carries for texture level of
 * detail (Akenine-Möller, Nilsson, Andersson, Barré-Brisebois, Toth and
 * Karras, "Texture Level of Detail Strategies for Real-Time Ray Tracing",
 * Ray Tracing Gems, 2019, ch. 20, sec. 20.3.4): the cone's width at the
 * ray's origin (world units, across the ray) and its spread, the width it
 * gains per unit of distance along the ray (the cone's full angle, in the
 * small-angle sense).  A perspective primary ray starts on the near plane
 * with the width of a pixel there; an orthographic one has spread 0.
 * {0, 0} asks for no filtering: every texture lookup is a magnification.
 */
struct shade_cone {
    float width;
    float spread;
};

/*
 * Colour seen along a world-space secondary ray (reflected or refracted;
 * camera rays take render/blend.c's path) (dir need not be normalised)
 * with 0 <= t < tmax; depth counts the recursion of Whitted shading.  `cone` is
 * the ray's footprint for textures; reflected and refracted rays continue
 * it.  Writes RGBA to rgba; alpha is 1 on a hit and the clear alpha on a
 * miss.
 */
void shade_ray(const struct shade_context *sc, const float org[3], const float dir[3],
               float tmax, struct shade_cone cone, int depth, float rgba[4]);

/* The colour of a hit `found` of a ray along dir (what shade_ray does
 * after tracing): the primary path of render/blend.c, which continues
 * rays past clipped and blended surfaces, shades the hits it keeps. */
void shade_hit(const struct shade_context *sc, const float org[3], const float dir[3],
               const struct trace_scene_hit *found, struct shade_cone cone, int depth,
               float rgba[4]);

/*
 * shade_hit at depth 0 in the eye-light mode for n <= TRACE_PACKET hits
 * at once (hits[i] of the ray along dir[i] with cone[i],
 * colour into rgba[i]): the texture level of detail of two hits is
 * computed together in SSE2 lanes (surface.h, surface_fetch_colours).
 * The same operations on the same values as shade_hit, so the same
 * colours bit for bit.
 */
void shade_eye_hits(const struct shade_context *sc, int n, const float *const dir[],
                    const struct trace_scene_hit *const hits[],
                    const struct shade_cone cone[], float *const rgba[]);

/* shade_eye_hits compiled for AVX2 (shade_eye_avx2.c: the same source,
 * so the same colours bit for bit), which shade_eye_hits calls when the
 * context's traversal table is AVX2 or AVX-512; NULL where that unit is
 * absent (no AVX2 compiler target, RT_NO_SIMD). */
typedef void (*shade_eye_hits_fn)(const struct shade_context *sc, int n, const float *const dir[],
                                  const struct trace_scene_hit *const hits[],
                                  const struct shade_cone cone[], float *const rgba[]);
shade_eye_hits_fn shade_eye_hits_avx2_unit(void);
/* The same compiled for AVX-512 (shade_eye_avx512.c: the same source,
 * the levels of detail of a block's two quads in one eight-lane vector),
 * which shade_eye_hits calls when the table is AVX-512; NULL where that
 * unit is absent. */
shade_eye_hits_fn shade_eye_hits_avx512_unit(void);

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
/*
 * shade_eye_hits of a whole block (TRACE_PACKET hits, every ray a hit)
 * in two steps, in the AVX2 copy only (shade_eye_avx2.c; the frame's
 * AVX2 packet loop, render_avx2.c, calls them, and runs only where that
 * copy is chosen).  shade_eye_block_begin does everything up to the
 * eight-lane texture lookups, their texels' addresses computed and their
 * cache lines asked for, keeping the block in *pending and returning 1;
 * or it shades the block completely and returns 0 (no texture, or a
 * block the lanes or the sampler do not take).  shade_eye_block_end then
 * loads and blends the texels and writes the pixels.  Between the two
 * the caller does other work (the next block's rays), which the core
 * runs while the texels come into the cache.  The rays come by
 * component (rays), and as dir[i] for a block the lanes do not take.
 * The same operations on the same values as shade_eye_hits, so the same
 * colours bit for bit; pixels do not depend on the order they are
 * written in.
 */
struct shade_eye_pending;
/* The block's rays as the lanes read them, written by the ray maker
 * beside its packet (render.c, ray_quad): dir[k][i] component k of ray
 * i's direction, width[i] and spread[i] its cone's; the same floats as
 * the packet's dir[i] and cone[i]. */
struct shade_eye_rays {
    float dir[3][TRACE_PACKET];
    float width[TRACE_PACKET];
    float spread[TRACE_PACKET];
};
int shade_eye_block_begin_avx2(const struct shade_context *sc, const float *const dir[],
                               const struct shade_eye_rays *rays,
                               const struct trace_scene_hit *const hits[], float *const rgba[],
                               struct shade_eye_pending *pending);
void shade_eye_block_end_avx2(const struct shade_context *sc, struct shade_eye_pending *pending);
/* The same two steps in the AVX-512 copy (shade_eye_avx512.c), for the
 * frame's AVX-512 packet loop (render_avx512.c); absent, and not called,
 * where the compiler does not target AVX-512. */
int shade_eye_block_begin_avx512(const struct shade_context *sc, const float *const dir[],
                                 const struct shade_eye_rays *rays,
                                 const struct trace_scene_hit *const hits[], float *const rgba[],
                                 struct shade_eye_pending *pending);
void shade_eye_block_end_avx512(const struct shade_context *sc,
                                struct shade_eye_pending *pending);
#endif

/* That unit's eight-lane texture lookup (scene_texture_sample_lod8,
 * scene/texture.h), for the tests that compare it with
 * scene_texture_sample_lod bit for bit; NULL where the unit is absent. */
struct scene_texture;
typedef int (*shade_texture_lod8_fn)(const struct scene_texture *tex, const float lambda[8],
                                     const float s[8], const float t[8], float rgb[3][8]);
shade_texture_lod8_fn shade_texture_lod8_avx2_unit(void);
/* The same lookup in the two steps the frame's pipeline takes
 * (scene_texture_prefetch_lod8, then scene_texture_finish_lod8), for the
 * test that they give sample_lod8's floats; NULL where the unit is
 * absent. */
shade_texture_lod8_fn shade_texture_lod8_steps_avx2_unit(void);
/* The AVX-512 unit's copies of the two above (its 512-bit set-up,
 * TEXTURE_OCTS_512 in scene/texture.c); NULL where that unit is absent
 * (a caller also checks that the CPU runs AVX-512). */
shade_texture_lod8_fn shade_texture_lod8_avx512_unit(void);
shade_texture_lod8_fn shade_texture_lod8_steps_avx512_unit(void);
/* That unit's four-lane log2 of the levels of detail (render/lanes.h,
 * lanes_log2_4 into out, lanes_log2_4_half into half), for the test of
 * its bound; NULL where it is absent. */
typedef void (*shade_log2_quad_fn)(const double x[4], double out[4], double half[4]);
shade_log2_quad_fn shade_log2_quad_avx2_unit(void);
/* The AVX-512 unit's eight-lane halved log2 (lanes_log2_8_half into half),
 * for the test of its own bound; NULL where that unit is absent. */
typedef void (*shade_log2_oct_half_fn)(const double x[8], double half[8]);
shade_log2_oct_half_fn shade_log2_oct_half_avx512_unit(void);
/* That unit's levels of detail of four hits on one triangle by the
 * triangle's texel map (surface.c, lod_fast_quad) beside lod_ray's, for
 * the test that the lanes it decides are lod_ray's bit for bit: l the
 * triangle part, lane i a hit along dir[i] with the facing normal ng[i]
 * and the cone's width[i]; fast[i] and ref[i] get the two lambdas; returns
 * the mask of the lanes lod_fast_quad decided.  NULL where it is absent. */
struct surface_lod;
typedef int (*shade_lod_fast_fn)(const struct surface_lod *l, int level_count,
                                 const float dir[4][3], const float ng[4][3],
                                 const float width[4], float fast[4], float ref[4]);
shade_lod_fast_fn shade_lod_fast_avx2_unit(void);
/* That unit's levels of detail of four hits by the blocks' chain
 * (surface.c, lod_quad_lanes: lod_quad, then lod_quad_axes or lod_ray for
 * the lanes it leaves), every lane on triangle part l with `shared` as
 * given, into quad[i]: for the test that every lane is lod_ray's bit for
 * bit, the lanes lod_quad leaves near its boundaries included.  NULL
 * where it is absent. */
typedef void (*shade_lod_quad_fn)(const struct surface_lod *l, int shared, int level_count,
                                  const float dir[4][3], const float ng[4][3],
                                  const float width[4], float quad[4]);
shade_lod_quad_fn shade_lod_quad_avx2_unit(void);
/* The AVX-512 copy's eight-lane form of it (lod_fast_oct, the four hits
 * twice), for the same test; NULL where that unit is absent. */
shade_lod_fast_fn shade_lod_fast_avx512_unit(void);

/*
 * Whitted shading's shadow rays of a 4 x 2 block's camera rays, one
 * packet per light (Wald, Slusallek, Benthin and Wagner 2001 sec. 4:
 * shadow rays of neighbouring pixels to one light share their end point,
 * so they are as coherent as the camera rays).  For each ray i with a
 * first hit (bit i of found, hits[i], ray from org[i] along dir[i] with
 * cone[i]) that the shading certainly shades as it is (drawn, not
 * clipped, lit), surf[i] gets its surface and primed[i] points at it
 * with the answers of the shadow rays traced in a packet, through the
 * frame's shadow filter (sc->shadows, render/secondary.h) when it has
 * one (surf has (1 + SHADE_PRIME_DEPTHS) * TRACE_PACKET entries); primed[i]'s other fields are left
 * alone.  A light whose rays are fewer than two or not coherent
 * (trace_packet_coherent) leaves them to the shading, ray by ray.  The
 * rays are computed by local_whitted's own operations and a packet's
 * answers are the single rays' (trace/packet_scene.h), so the image and
 * the ray count are those of single rays.  The reflected rays of the
 * primed surfaces are traced ahead too, depth by depth up to
 * SHADE_PRIME_DEPTHS, in a packet where at least two are coherent: their
 * hits' surfaces go to surf[TRACE_PACKET...], primed in `reflected`
 * (primed[i].reflected and on), with their shadow rays as above.
 */
void shade_prime_shadows(const struct shade_context *sc, unsigned found,
                         const struct trace_scene_hit hits[TRACE_PACKET],
                         const float org[TRACE_PACKET][3], const float dir[TRACE_PACKET][3],
                         const struct shade_cone cone[TRACE_PACKET],
                         struct surface *surf,
                         struct shade_primed primed[TRACE_PACKET],
                         struct shade_primed *reflected);

/*
 * Moves a point off a surface along the unit normal n by
 * OFFSET_ERROR_SCALE times `error`, the bound on the point's distance from
 * the exact surface, rounding each coordinate away from the surface so a
 * ray leaving it cannot hit the surface it starts on (the bound-based
 * offset of PBRT 3rd ed. sec. 3.9.5).  Scale-invariant: the bound is
 * relative to the coordinates' magnitude, so it works 1e5 from the origin
 * and for scenes 1e-4 across alike.
 */
void shade_offset_point(const float p[3], const float n[3], float error, float out[3]);

#endif
