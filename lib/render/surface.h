/* SPDX-License-Identifier: Apache-2.0 */
/*
 * surface.h - what a ray hit looks like: the surface fetch the
 * integrators (shade.c: eye light, Whitted; later path tracing) start
 * from.  The hit point and its error bound, the geometric and shading
 * normals facing the ray, and the material with vertex colours and the
 * texture applied.
 */
#ifndef RT_RENDER_SURFACE_H
#define RT_RENDER_SURFACE_H

#include "render/shade.h"

/*
 * What surface.c computes from a hit's triangle (its instance and
 * primitive) and not from the ray: the unit geometric normal in world
 * space and the triangle-only part of the texture level of detail.
 * SHADE_CACHES per render thread and tile (render.c,
 * shade_context.cache), one per Whitted depth, for the last triangle
 * shaded at that depth: neighbouring pixels' rays of one depth mostly hit
 * the same one, and a hit of another triangle replaces it.  (One entry
 * for all depths held a pixel's deepest hit when the next pixel's
 * reflection came: on a BART robots Whitted frame three fetches in four
 * missed.)  The eye light's block paths have SHADE_EYE_CACHES entries of
 * their own per render thread, kept over the thread's tiles for the
 * pass (shade_context.eye).  The cached values are the ones the
 * computation gives, bit for bit, so images do not depend on the order
 * pixels are shaded in.
 */
struct scene_texture;

/* The triangle-only part of the texture level of detail (surface.c,
 * texture_lod): the triangle's world edges w1, w2, their cross product nn
 * (|nn|^2 = nn2, |nn| = p_a, nn / p_a = n) and its texel edges a1, a2
 * (texel area t_a). */
struct surface_lod {
    double w1[3], w2[3], nn[3], nn2, p_a, n[3];
    double a1[2], a2[2], t_a;
};

/* The texel map M of a triangle part and the bound of the lanes the
 * levels of detail take from it (surface.c, lod_fast_quad): sin2 the
 * least sin^2 cos^2 of a lane's ray, (kappa / 64)^2 raised by 2^-20 for
 * its own roundings; state 0 not computed for the cache's current
 * triangle part, 1 usable, -1 not. */
struct surface_lod_fast {
    double m[2][3];
    double sin2;
    int state;
};

struct surface_cache {
    const struct scene_instance *inst; /* NULL: empty */
    uint32_t prim;
    int normal;   /* 0 not computed, 1 ng is the unit normal, -1 degenerate */
    float ng[3];  /* unit geometric normal, world space, recorded winding */
    int geometry; /* the level of detail's world edges (lod.w1 ... lod.n) are set */
    /* lod.a1, lod.a2, lod.t_a: the texel edges of texture `tex` at
     * coordinates st. */
    const struct scene_texture *tex;
    float st[3][2];
    struct surface_lod lod;
    struct surface_lod_fast fast; /* of lod, reset whenever lod changes */
    /* The texture table's answer for name `named` (0: none yet; names
     * are never 0), kept whatever triangle is hit: the table does not
     * change while a frame renders. */
    uint32_t named;
    const struct scene_texture *named_tex;
    /* What the eye light's one-triangle block path (surface_fetch_lanes)
     * resolves from the triangle's material, instance and flags, none of
     * which change while a frame renders: set (block 1) when the colours
     * cannot vary by hit, cleared with the triangle. */
    int block;
    int block_lighting;
    const float *block_emission;
    const struct scene_texture *block_tex;
    float block_ambient[3], block_diffuse[3]; /* the lanes' broadcast colours */
};

/* Surface data at a hit, in world space. */
struct surface {
    float p[3];  /* hit point */
    float ng[3]; /* geometric normal, unit, facing the incoming ray */
    float n[3];  /* shading normal, unit, same side as ng */
    float p_error; /* bound on |p - exact point on the surface| */
    int front;   /* the ray hit the front face (counter-clockwise side) */
    /* The ambient and diffuse colours with vertex colours and the texture
     * applied, and of the rest of the material what the eye-light and
     * Whitted shadings read, each property the recorded one or, when it
     * inherits it (scene_material.inherit), the call's: what
     * surface_resolve_material gives for it, without copying and
     * resolving the whole material (some 260 bytes) at every hit. */
    float ambient[4];
    float diffuse[4];
    float emission[4];
    float specular[4];
    float shininess;
    float reflectivity;
    float transparency;
    float ior;
    int lighting; /* RT_LIGHTING as the primitive was drawn */
};

/* Completes a material recorded in a display list with the properties it
 * inherits (scene_material.inherit) from the appearance current at the
 * call; clears the inherit bits. */
struct scene_appearance;
void surface_resolve_material(const struct scene_appearance *call, struct scene_material *m);

/* The surface at a hit of a ray along dir whose cone is `width` wide
 * there (world units), `depth` the ray's Whitted depth (0 for camera
 * rays): it picks the tile's cache entry (shade_context.cache). */
void surface_fetch(const struct shade_context *sc, const struct trace_scene_hit *hit,
                   const float dir[3], float width, int depth, struct surface *s);

/* surface_fetch of n <= TRACE_PACKET hits of one depth (hits[i] along
 * dir[i], the cone width[i] wide there, into *s[i]), the levels of detail
 * of their textures two (or, in the AVX2 copy, four) at a time, as
 * surface_fetch_colours: the same operations on the same values, so the
 * same surfaces bit for bit. */
void surface_fetches(const struct shade_context *sc, int n,
                     const struct trace_scene_hit *const hits[], const float *const dir[],
                     const float width[], int depth, struct surface *const s[]);

/* What the eye light and a see-through surface's alpha read of a hit:
 * surface_fetch's normals and its material's emission, ambient and diffuse
 * colours (vertex colours and texture applied), bit for bit, without the
 * hit point or the rest of the material. */
struct surface_colour {
    float ng[3]; /* geometric normal, unit, facing the incoming ray */
    float n[3];  /* shading normal, unit, same side as ng */
    int front;   /* the ray hit the front face (counter-clockwise side) */
    float emission[4];
    float ambient[4];
    float diffuse[4];
    int lighting; /* RT_LIGHTING as the primitive was drawn (resolved) */
};

void surface_fetch_colour(const struct shade_context *sc, const struct trace_scene_hit *hit,
                          const float dir[3], float width, struct surface_colour *s);

/*
 * surface_fetch_colour of n <= TRACE_PACKET hits (hits[i] along dir[i],
 * the cone `width[i]` wide there, colours into s[i]), so that the level
 * of detail of several hits can be computed together: it is a chain of
 * dependent double divisions and square roots, whose latency two hits
 * in the two SSE2 lanes share.  Every hit's colours without the texture
 * first (and what its lookup needs), then the levels of detail two at a
 * time, then the lookups.  One call for the batch, with the per-hit
 * steps inlined, where three calls a hit across files passed their
 * arguments through memory.  The same operations on the same values as
 * surface_fetch_colour, so the same colours bit for bit.
 */
void surface_fetch_colours(const struct shade_context *sc, int n,
                           const struct trace_scene_hit *const hits[], const float *const dir[],
                           const float width[], struct surface_colour s[]);

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
/* What the eye light reads of a block of TRACE_PACKET hits on one
 * triangle (surface_fetch_lanes), lane i hit i: surface_colour's shading
 * normal and colours (vertex colours and texture applied), the emission
 * and lighting being the triangle's. */
struct surface_lanes {
    float n[3][TRACE_PACKET];
    float ambient[3][TRACE_PACKET];
    float diffuse[3][TRACE_PACKET];
    float emission[4];
    int lighting;
};

/* A block of the eye light whose texels are on their way
 * (shade_eye_block_begin, shade.h): its colours before the texture, its
 * texture lookups up to the loads, and what eye_light8 reads besides (unit directions, the
 * instance's global ambient, the pixels). */
struct shade_eye_pending {
    struct surface_lanes lanes;
    struct scene_texture_lookup8 lookup;
    float unit[3][TRACE_PACKET];
    const float *global_ambient;
    float *rgba[TRACE_PACKET];
};

/*
 * surface_fetch_colours of a block of TRACE_PACKET hits when they are
 * all on one instance, and on one triangle or on triangles of one
 * material and one set of flags, in the lanes of the shading's AVX2
 * copy (render/shade_eye_avx2.c renames it), dir[k][i] component k of
 * hit i's direction, into out: the same values bit for bit.  Returns 0,
 * having written nothing the caller reads, when the hits span instances,
 * materials or flags, or the block needs what this leaves to
 * surface_fetch_colours (no cache, a degenerate triangle, projective
 * texture coordinates).  Returns 1 when out holds the colours; with
 * `defer` (else NULL) 2 when the eight-lane sampler took the block's
 * lookups: they are then prepared in *defer (scene_texture_prefetch_lod8)
 * and out's ambient
 * and diffuse colours are those before the texture, each to be
 * multiplied by its lane's channel of scene_texture_finish_lod8 (the
 * products surface_fetch_lanes takes otherwise, on the same floats).
 */
int surface_fetch_lanes(const struct shade_context *sc, const struct trace_scene_hit *const hits[],
                        const float dir[3][TRACE_PACKET], const float width[],
                        struct surface_lanes *out, struct scene_texture_lookup8 *defer);
#endif

/* The texel of texture `name` at a hit, for the RT_FIXED_FUNCTION mode,
 * which applies it after lighting through the texture environment
 * (gl_shade.c): the triangle's vertex coordinates vertex_st (recorded or
 * generated by rtTexGen) interpolated, filtered for the cone's `width` as
 * apply_texture does; ng is the unit geometric normal in world space.
 * vertex_q: the three vertices' q (rtTexCoord4), when s / q and t / q are
 * sampled (GL's projective coordinates); NULL for q = 1.  Returns 0
 * (texel untouched) when the name has no image. */
int surface_texel(const struct shade_context *sc, const struct trace_scene_hit *hit,
                  uint32_t name, const float vertex_st[3][2], const float vertex_q[3],
                  const float ng[3], const float dir[3], float width, float texel[4]);

#endif
