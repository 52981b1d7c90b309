/* SPDX-License-Identifier: Apache-2.0 */
/*
 * surface.c - the surface at a hit (see surface.h): hit point in double,
 * normals, vertex colours, and textures filtered by the ray cone's level
 * of detail (shade.h, texture_lod).
 */
#include "render/surface.h"

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "base/mat4.h"
#include "render/lanes.h"

/* The level of detail maps its footprint's two axes to texels in the two
 * SSE2 lanes: IEEE operations lane by lane, the same doubles as one axis
 * at a time (a scalar path under RT_NO_SIMD or without SSE2). */
#if defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <emmintrin.h>
#define SURFACE_PAIRS 1
#if defined(__AVX2__)
#include <immintrin.h>
#define SURFACE_QUADS 1 /* the AVX2 copy (render/shade_eye_avx2.c) */
#endif
#if defined(__AVX2__) && defined(__AVX512F__) && defined(__AVX512DQ__) && defined(__AVX512VL__)
#define SURFACE_OCTS 1 /* the AVX-512 copy (render/shade_eye_avx512.c) */
#endif
#else
#define SURFACE_PAIRS 0
#endif

/* Small steps of the per-hit path inlined into their callers: their
 * calls' spills and argument set-up cost a tenth or more of their work. */
#if defined(__GNUC__)
#define SURFACE_INLINE static inline __attribute__((always_inline))
#else
#define SURFACE_INLINE static inline
#endif

/* What a hit's texture lookup needs (surface_fetch_colours): the
 * colours come first, then the level of detail from the rest, then the
 * lookup. */
struct surface_texture {
    const struct scene_texture *tex; /* NULL: nothing to apply */
    float st[2];                     /* the interpolated coordinates */
    float lambda;                    /* the level of detail, once known */
    int lod;                         /* 1: lambda still to compute from the rest */
    float ng[3], dir[3], width;
    /* The triangle part the level of detail reads: &tri, a copy (the
     * tile's cache entry may be taken by a later hit of the batch), or
     * the cache entry itself when the whole batch is on one triangle
     * (fetch_colours_one_triangle), which nothing changes before the
     * levels of detail are computed. */
    const struct surface_lod *lodp;
    struct surface_lod tri;
};

static void transform_normal(const double m[16], const float in[3], float out[3])
{
    for (int r = 0; r < 3; r++)
        out[r] = (float)(m[r] * in[0] + m[4 + r] * in[1] + m[8 + r] * in[2]);
}

static void interpolate(const float *attr, int stride, const uint32_t v[3], float b0, float b1,
                        float b2, int n, float *out)
{
    for (int k = 0; k < n; k++)
        out[k] = b0 * attr[stride * v[0] + k] + b1 * attr[stride * v[1] + k] +
                 b2 * attr[stride * v[2] + k];
}

/* Smallest |cos| between ray and surface in the level of detail.  It only
 * keeps lambda finite for a ray nearly parallel to the surface (which hits
 * it only by rounding): there the footprint is already 2^16.6 times wider
 * than head-on, more than the 14 halvings of the largest mip chain. */
#define LOD_MIN_COSINE 1e-5

static double dot3d(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3d(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

#if !SURFACE_PAIRS
/* The level-0 texel vector of the in-plane vector e of the triangle
 * with world edges w1, w2 (normal nn = w1 x w2, |nn|^2 = nn2) and texel
 * edges a1, a2: e = alpha w1 + beta w2 maps to alpha a1 + beta a2. */
static void texel_vector(const double e[3], const double w1[3], const double w2[3],
                         const double nn[3], double nn2, const double a1[2], const double a2[2],
                         double out[2])
{
    double ew2[3], w1e[3];
    cross3d(e, w2, ew2);
    cross3d(w1, e, w1e);
    const double alpha = dot3d(ew2, nn) / nn2, beta = dot3d(w1e, nn) / nn2;
    out[0] = alpha * a1[0] + beta * a2[0];
    out[1] = alpha * a1[1] + beta * a2[1];
}
#endif

/* texel_vector of e (out[0]) and of f (out[1]) together: lane 0 e,
 * lane 1 f, each lane texel_vector's operations in its order. */
static void texel_vectors(const double e[3], const double f[3], const double w1[3],
                          const double w2[3], const double nn[3], double nn2, const double a1[2],
                          const double a2[2], double out[2][2])
{
#if SURFACE_PAIRS
    __m128d x[3], w1v[3], w2v[3];
    for (int k = 0; k < 3; k++) {
        x[k] = _mm_set_pd(f[k], e[k]);
        w1v[k] = _mm_set1_pd(w1[k]);
        w2v[k] = _mm_set1_pd(w2[k]);
    }
    /* ew2 = x cross w2, w1e = w1 cross x (cross3d's order). */
    const __m128d ew2[3] = {
        _mm_sub_pd(_mm_mul_pd(x[1], w2v[2]), _mm_mul_pd(x[2], w2v[1])),
        _mm_sub_pd(_mm_mul_pd(x[2], w2v[0]), _mm_mul_pd(x[0], w2v[2])),
        _mm_sub_pd(_mm_mul_pd(x[0], w2v[1]), _mm_mul_pd(x[1], w2v[0]))};
    const __m128d w1e[3] = {
        _mm_sub_pd(_mm_mul_pd(w1v[1], x[2]), _mm_mul_pd(w1v[2], x[1])),
        _mm_sub_pd(_mm_mul_pd(w1v[2], x[0]), _mm_mul_pd(w1v[0], x[2])),
        _mm_sub_pd(_mm_mul_pd(w1v[0], x[1]), _mm_mul_pd(w1v[1], x[0]))};
    const __m128d n0 = _mm_set1_pd(nn[0]), n1 = _mm_set1_pd(nn[1]), n2 = _mm_set1_pd(nn[2]);
    const __m128d q = _mm_set1_pd(nn2);
    const __m128d alpha = _mm_div_pd(
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(ew2[0], n0), _mm_mul_pd(ew2[1], n1)),
                   _mm_mul_pd(ew2[2], n2)),
        q);
    const __m128d beta = _mm_div_pd(
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(w1e[0], n0), _mm_mul_pd(w1e[1], n1)),
                   _mm_mul_pd(w1e[2], n2)),
        q);
    const __m128d o0 = _mm_add_pd(_mm_mul_pd(alpha, _mm_set1_pd(a1[0])),
                                  _mm_mul_pd(beta, _mm_set1_pd(a2[0])));
    const __m128d o1 = _mm_add_pd(_mm_mul_pd(alpha, _mm_set1_pd(a1[1])),
                                  _mm_mul_pd(beta, _mm_set1_pd(a2[1])));
    double l0[2], l1[2];
    _mm_storeu_pd(l0, o0);
    _mm_storeu_pd(l1, o1);
    out[0][0] = l0[0];
    out[0][1] = l1[0];
    out[1][0] = l0[1];
    out[1][1] = l1[1];
#else
    texel_vector(e, w1, w2, nn, nn2, a1, a2, out[0]);
    texel_vector(f, w1, w2, nn, nn2, a1, a2, out[1]);
#endif
}

/* The cache entry of the hit's triangle (surface_cache), emptied when it
 * held another one; NULL without a cache. */
static struct surface_cache *triangle_cache(struct surface_cache *c,
                                            const struct scene_instance *inst, uint32_t prim)
{
    if (c && (c->inst != inst || c->prim != prim)) {
        c->inst = inst;
        c->prim = prim;
        c->normal = 0;
        c->geometry = 0;
        c->tex = NULL;
        c->block = 0;
    }
    return c;
}

/* Relative margin by which one footprint axis must win on squared
 * lengths before the other's hypot is left out: far above the few
 * roundings (some 1e-16 each) between the squares and the hypots. */
#define LOD_AXIS_MARGIN 1e-6

/* Bounds of lod_near (see there): the relative distance between its
 * footprint and texture_lod's, at most 2^-49, and between their log2s,
 * at most 2^-45, taken 16 and 8 times larger. */
#define LOD_NEAR_RELATIVE 0x1p-45
#define LOD_NEAR_ABSOLUTE 0x1p-42

/*
 * texture_lod's result from the footprint xs = sqrt(s2) width [/ cosine]
 * instead of x = hypot(a, b) width [/ cosine] (s2 = a a + b b), when that
 * provably gives the same float: returns 1 with it in *lambda, or 0 when
 * the caller must take the hypot.  A sqrt for the hypot, the library's
 * slowest step here.  Why it is the same: with s2 a normal number far
 * from overflow, sqrt(s2) is within 2^-52 (relative) of a b's exact
 * length, hypot within 1 ulp (glibc's documented bound), so with the same
 * two roundings after them xs is within 2^-49 of x.  Then xs beyond 1 or
 * `top` by more than that puts x on the same side (-inf, +inf, as
 * texture_lod); between them, log2 (within 2 ulps of the exact value,
 * again the library's bound; lambda < 32, so 2^-47) gives log2(xs) and
 * log2(x) within 2^-45 of each other, and when every value within
 * LOD_NEAR_ABSOLUTE of log2(xs) rounds to the same float, float(log2(x))
 * is that float (rounding is monotonic).  Otherwise (close to a rounding
 * boundary: about one call in 2^15 for lambda near 1, every one for
 * lambda near 0) the caller computes x exactly as before.
 */
static int lod_near(double s2, double xs, double top, float *lambda)
{
    if (!(s2 >= 0x1p-960 && s2 <= 0x1p960))
        return 0;
    if (xs < 1.0 - LOD_NEAR_RELATIVE) {
        *lambda = -INFINITY; /* x < 1: a magnification */
        return 1;
    }
    if (xs > top * (1.0 + LOD_NEAR_RELATIVE)) {
        *lambda = INFINITY; /* x > top: the last level */
        return 1;
    }
    if (!(xs > 1.0 + LOD_NEAR_RELATIVE && xs < top * (1.0 - LOD_NEAR_RELATIVE)))
        return 0;
    const double l = log2(xs);
    const float f = (float)l;
    if ((float)(l - LOD_NEAR_ABSOLUTE) != f || (float)(l + LOD_NEAR_ABSOLUTE) != f)
        return 0;
    *lambda = f;
    return 1;
}

/*
 * The texture level of detail at a hit by ray cones (Akenine-Möller et
 * al. 2019, "Texture Level of Detail Strategies for Real-Time Ray
 * Tracing", Ray Tracing Gems ch. 20, sec. 20.3.4), with the footprint's
 * two axes mapped to texels separately, as GL's rho takes the longer of
 * the texel derivatives along the two screen axes (OpenGL 1.1, texture
 * minification):
 *
 *     lambda = log2(max(|J e1| width / |n . d|, |J e2| width))
 *
 * `width` is the cone's width at the hit (world units), n the unit normal
 * of the triangle's plane and d the unit ray direction; the cone's
 * footprint on the plane is an ellipse, width / |n . d| long along e1 (the
 * ray's direction projected into the plane) and width wide along e2 = n x
 * e1; J maps in-plane world vectors to level-0 texels (the triangle's
 * edges to its texture-coordinate edges times w and h).  A texture laid
 * on with the same density in every direction has |J e| the same for all
 * e, sqrt(t_a / p_a) (t_a the triangle's area in texels, p_a in world
 * units), and this is the chapter's Delta + log2(width / |n . d|).  One
 * stretched more one way (a long floor with its coordinates running to
 * 2000 along and 8 across) takes its level from the denser direction, as
 * GL does, where the chapter's isotropic Delta would average the two.
 * The triangle's edges go through the instance matrix first, so an
 * instance scaled 4x gets the level of detail of the same triangles
 * recorded 4x larger.  All in double; the same operations for every
 * pixel, so the result does not depend on threads.  A triangle without
 * texture area (constant coordinates) gives -inf, a magnification; one
 * without world area +inf, the last level; 0 / 0 a NaN, which the
 * sampler takes as a magnification.
 *
 * What the sampler does with lambda is all that counts
 * (scene_texture_sample_lod), so where it cannot matter the work is left
 * out, each step giving the lookup the full computation gives: the
 * triangle's edges, normal and texel edges come from the tile's cache
 * (surface_cache) when the last hit was on the same triangle; the hypot
 * of an axis that loses the max by far is not taken (squared lengths
 * decide); and a footprint of at most one texel (log2 <= 0, a
 * magnification whatever the filters) or of at least 2^(q + 2) texels
 * (beyond the last level q) returns -inf or +inf without the log2.
 *
 * texture_lod (below) is lod_triangle, the part of the triangle, then
 * lod_ray, the part of the ray; lod_ray_pair computes the latter for two
 * hits at once (texture_lods).
 */

/* The triangle-only part of texture_lod: from the tile's cache when the
 * last hit was on the same triangle (and, for the texel edges, the same
 * texture and coordinates), else computed into it (or into `scratch`
 * without a cache). */
SURFACE_INLINE const struct surface_lod *lod_triangle(struct surface_cache *cache,
                                                      const struct scene_texture *tex,
                                                      const struct scene_instance *inst,
                                                      const struct scene_mesh *mesh,
                                                      uint32_t prim, const uint32_t v[3],
                                                      const float *const st[3],
                                                      struct surface_cache *scratch)
{
    struct surface_cache *c = triangle_cache(cache, inst, prim);
    if (!c) {
        c = scratch;
        c->geometry = 0;
        c->tex = NULL;
    }
    struct surface_lod *l = &c->lod;
    if (!c->geometry) {
        const float *p0 = &mesh->positions[3 * v[0]];
        const float *p1 = &mesh->positions[3 * v[1]];
        const float *p2 = &mesh->positions[3 * v[2]];
        double e1[3], e2[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = (double)p1[k] - (double)p0[k];
            e2[k] = (double)p2[k] - (double)p0[k];
        }
        mat4_transform_vector(inst->object_to_world, e1, l->w1);
        mat4_transform_vector(inst->object_to_world, e2, l->w2);
        cross3d(l->w1, l->w2, l->nn);
        l->nn2 = dot3d(l->nn, l->nn);
        l->p_a = sqrt(l->nn2);
        for (int k = 0; k < 3; k++)
            l->n[k] = l->nn[k] / l->p_a;
        c->geometry = 1;
        c->fast.state = 0;
    }
    if (c->tex != tex || memcmp(c->st[0], st[0], sizeof(c->st[0])) ||
        memcmp(c->st[1], st[1], sizeof(c->st[1])) || memcmp(c->st[2], st[2], sizeof(c->st[2]))) {
        const float *t0 = st[0], *t1 = st[1], *t2 = st[2];
        l->a1[0] = ((double)t1[0] - (double)t0[0]) * tex->width;
        l->a1[1] = ((double)t1[1] - (double)t0[1]) * tex->height;
        l->a2[0] = ((double)t2[0] - (double)t0[0]) * tex->width;
        l->a2[1] = ((double)t2[1] - (double)t0[1]) * tex->height;
        l->t_a = fabs(l->a1[0] * l->a2[1] - l->a2[0] * l->a1[1]);
        for (int i = 0; i < 3; i++)
            memcpy(c->st[i], st[i], sizeof(c->st[i]));
        c->tex = tex;
        c->fast.state = 0;
    }
    return l;
}

/* The last level's threshold of texture_lod: a footprint of 2^(q + 2)
 * texels or more is beyond the last level q. */
static double lod_top(int level_count)
{
    return (double)(1u << (level_count + 1));
}

/* The end of texture_lod, from the footprint's two texel vectors ja
 * (the long axis, along) and jb (across), their squared lengths sa, sb
 * and sbc = sb cosine^2. */
SURFACE_INLINE float lod_axes(const double ja[2], const double jb[2], double sa, double sb,
                              double sbc, double cosine, float width, double top)
{
    /* major = hypot(ja) width / cosine, minor = hypot(jb) width: major
     * wins when |ja|^2 > |jb|^2 cosine^2 by the margin, minor when the
     * reverse holds; NaNs fail both tests and take the full max. */
    double x;
    float near_lambda;
    if (sa > sbc * (1.0 + LOD_AXIS_MARGIN)) {
        if (lod_near(sa, sqrt(sa) * (double)width / cosine, top, &near_lambda))
            return near_lambda;
        x = hypot(ja[0], ja[1]) * (double)width / cosine;
    } else if (sbc > sa * (1.0 + LOD_AXIS_MARGIN)) {
        if (lod_near(sb, sqrt(sb) * (double)width, top, &near_lambda))
            return near_lambda;
        x = hypot(jb[0], jb[1]) * (double)width;
    } else
        x = fmax(hypot(ja[0], ja[1]) * (double)width / cosine, hypot(jb[0], jb[1]) * (double)width);
    if (!(x > 1.0))
        return -INFINITY; /* log2(x) <= 0 or NaN: a magnification */
    if (x >= top)
        return INFINITY; /* log2(x) >= q + 2: level q (or a non-mipmapped minification) */
    return (float)log2(x);
}

/* texture_lod's part that depends on the ray, for the triangle part l
 * (lod_triangle) of a texture with level_count levels. */
static float lod_ray(const struct surface_lod *l, int level_count, const float ng[3],
                     const float dir[3], float width)
{
    const double *w1 = l->w1, *w2 = l->w2, *nn = l->nn, *n = l->n, *a1 = l->a1, *a2 = l->a2;
    const double nn2 = l->nn2, p_a = l->p_a, t_a = l->t_a;
    const double d[3] = {dir[0], dir[1], dir[2]};
    const double dir_len = sqrt(dot3d(d, d));
    double cosine = fabs((double)ng[0] * d[0] + (double)ng[1] * d[1] + (double)ng[2] * d[2]) /
                    dir_len;
    if (!(cosine >= LOD_MIN_COSINE))
        cosine = LOD_MIN_COSINE;
    if (!(p_a > 0.0) || !(t_a > 0.0) || !(dir_len > 0.0) || !isfinite(nn2))
        return (float)(0.5 * log2(t_a / p_a) + log2((double)width / cosine));
    /* The footprint's axes: e1 along the ray's projection into the plane
     * (any in-plane direction when the ray meets the plane head-on). */
    double along[3], across[3];
#if SURFACE_PAIRS
    /* The four quotients by dir_len in two pairs, the three by along_len
     * in a pair and one: the same quotients. */
    double q[4];
    const __m128d len_v = _mm_set1_pd(dir_len);
    _mm_storeu_pd(q, _mm_div_pd(_mm_set_pd(d[0], dot3d(d, n)), len_v));
    _mm_storeu_pd(q + 2, _mm_div_pd(_mm_set_pd(d[2], d[1]), len_v));
    const double dn = q[0];
    for (int k = 0; k < 3; k++)
        along[k] = q[1 + k] - dn * n[k];
#else
    const double dn = dot3d(d, n) / dir_len;
    for (int k = 0; k < 3; k++)
        along[k] = d[k] / dir_len - dn * n[k];
#endif
    double along_len = sqrt(dot3d(along, along));
    if (!(along_len > 1e-9)) {
        for (int k = 0; k < 3; k++)
            along[k] = w1[k];
        along_len = sqrt(dot3d(along, along));
    }
#if SURFACE_PAIRS
    _mm_storeu_pd(along, _mm_div_pd(_mm_loadu_pd(along), _mm_set1_pd(along_len)));
    along[2] /= along_len;
#else
    for (int k = 0; k < 3; k++)
        along[k] /= along_len;
#endif
    cross3d(n, along, across);
    double j[2][2];
    texel_vectors(along, across, w1, w2, nn, nn2, a1, a2, j);
    const double *ja = j[0], *jb = j[1];
    const double sa = ja[0] * ja[0] + ja[1] * ja[1], sb = jb[0] * jb[0] + jb[1] * jb[1];
    const double sbc = sb * (cosine * cosine);
    return lod_axes(ja, jb, sa, sb, sbc, cosine, width, lod_top(level_count));
}

static float texture_lod(const struct shade_context *sc, const struct scene_texture *tex,
                         const struct scene_instance *inst, const struct scene_mesh *mesh,
                         uint32_t prim, const uint32_t v[3], const float *const st[3],
                         const float ng[3], const float dir[3], float width)
{
    struct surface_cache scratch;
    return lod_ray(lod_triangle(sc->cache, tex, inst, mesh, prim, v, st, &scratch),
                   tex->level_count, ng, dir, width);
}

/* t's level of detail from its triangle part alone (lod_ray). */
static void texture_lambda(struct surface_texture *t)
{
    t->lambda = lod_ray(t->lodp, t->tex->level_count, t->ng, t->dir, t->width);
}

#if SURFACE_PAIRS
static __m128d pair_dot(const __m128d a[3], const __m128d b[3])
{
    return _mm_add_pd(_mm_add_pd(_mm_mul_pd(a[0], b[0]), _mm_mul_pd(a[1], b[1])),
                      _mm_mul_pd(a[2], b[2]));
}

/* cross3d in lanes. */
static void pair_cross(const __m128d a[3], const __m128d b[3], __m128d out[3])
{
    out[0] = _mm_sub_pd(_mm_mul_pd(a[1], b[2]), _mm_mul_pd(a[2], b[1]));
    out[1] = _mm_sub_pd(_mm_mul_pd(a[2], b[0]), _mm_mul_pd(a[0], b[2]));
    out[2] = _mm_sub_pd(_mm_mul_pd(a[0], b[1]), _mm_mul_pd(a[1], b[0]));
}

/* texel_vector of the in-plane vectors e in lanes (lane i: triangle
 * lane i's w1, w2, nn, nn2, a1, a2), each lane texel_vector's operations
 * in its order. */
SURFACE_INLINE void pair_texel_vector(const __m128d e[3], const __m128d w1[3],
                                      const __m128d w2[3], const __m128d nn[3], __m128d nn2,
                                      const __m128d a1[2], const __m128d a2[2], __m128d out[2])
{
    __m128d ew2[3], w1e[3];
    pair_cross(e, w2, ew2);
    pair_cross(w1, e, w1e);
    const __m128d alpha = _mm_div_pd(pair_dot(ew2, nn), nn2);
    const __m128d beta = _mm_div_pd(pair_dot(w1e, nn), nn2);
    out[0] = _mm_add_pd(_mm_mul_pd(alpha, a1[0]), _mm_mul_pd(beta, a2[0]));
    out[1] = _mm_add_pd(_mm_mul_pd(alpha, a1[1]), _mm_mul_pd(beta, a2[1]));
}

/* lod_ray of two textures' hits in the two lanes (lane 0 a, lane 1 b):
 * each lane lod_ray's operations on its values in its order, so the same
 * doubles; a lane that leaves lod_ray's common path (a degenerate
 * triangle or direction, a ray meeting the plane head-on) is computed
 * again by lod_ray itself. */
SURFACE_INLINE void lod_ray_pair(struct surface_texture *a, struct surface_texture *b)
{
    const struct surface_lod *la = a->lodp, *lb = b->lodp;
    __m128d d[3], g[3], n[3];
    for (int k = 0; k < 3; k++) {
        d[k] = _mm_set_pd((double)b->dir[k], (double)a->dir[k]);
        g[k] = _mm_set_pd((double)b->ng[k], (double)a->ng[k]);
        n[k] = _mm_set_pd(lb->n[k], la->n[k]);
    }
    const __m128d dir_len = _mm_sqrt_pd(pair_dot(d, d));
    const __m128d sign = _mm_set1_pd(-0.0);
    __m128d cosine = _mm_div_pd(_mm_andnot_pd(sign, pair_dot(g, d)), dir_len);
    const __m128d min_cos = _mm_set1_pd(LOD_MIN_COSINE);
    const __m128d keep = _mm_cmpge_pd(cosine, min_cos);
    cosine = _mm_or_pd(_mm_and_pd(keep, cosine), _mm_andnot_pd(keep, min_cos));
    const __m128d dn = _mm_div_pd(pair_dot(d, n), dir_len);
    __m128d along[3];
    for (int k = 0; k < 3; k++)
        along[k] = _mm_sub_pd(_mm_div_pd(d[k], dir_len), _mm_mul_pd(dn, n[k]));
    const __m128d along_len = _mm_sqrt_pd(pair_dot(along, along));
    for (int k = 0; k < 3; k++)
        along[k] = _mm_div_pd(along[k], along_len);
    __m128d across[3];
    pair_cross(n, along, across);
    __m128d w1[3], w2[3], nn[3], a1[2], a2[2];
    for (int k = 0; k < 3; k++) {
        w1[k] = _mm_set_pd(lb->w1[k], la->w1[k]);
        w2[k] = _mm_set_pd(lb->w2[k], la->w2[k]);
        nn[k] = _mm_set_pd(lb->nn[k], la->nn[k]);
    }
    for (int k = 0; k < 2; k++) {
        a1[k] = _mm_set_pd(lb->a1[k], la->a1[k]);
        a2[k] = _mm_set_pd(lb->a2[k], la->a2[k]);
    }
    const __m128d nn2 = _mm_set_pd(lb->nn2, la->nn2);
    __m128d ja[2], jb[2];
    pair_texel_vector(along, w1, w2, nn, nn2, a1, a2, ja);
    pair_texel_vector(across, w1, w2, nn, nn2, a1, a2, jb);
    const __m128d sa = _mm_add_pd(_mm_mul_pd(ja[0], ja[0]), _mm_mul_pd(ja[1], ja[1]));
    const __m128d sb = _mm_add_pd(_mm_mul_pd(jb[0], jb[0]), _mm_mul_pd(jb[1], jb[1]));
    const __m128d sbc = _mm_mul_pd(sb, _mm_mul_pd(cosine, cosine));
    double v_len[2], v_cos[2], v_along[2], v_ja[2][2], v_jb[2][2], v_sa[2], v_sb[2], v_sbc[2];
    _mm_storeu_pd(v_len, dir_len);
    _mm_storeu_pd(v_cos, cosine);
    _mm_storeu_pd(v_along, along_len);
    _mm_storeu_pd(v_ja[0], ja[0]);
    _mm_storeu_pd(v_ja[1], ja[1]);
    _mm_storeu_pd(v_jb[0], jb[0]);
    _mm_storeu_pd(v_jb[1], jb[1]);
    _mm_storeu_pd(v_sa, sa);
    _mm_storeu_pd(v_sb, sb);
    _mm_storeu_pd(v_sbc, sbc);
    struct surface_texture *t[2] = {a, b};
    for (int i = 0; i < 2; i++) {
        const struct surface_lod *l = t[i]->lodp;
        if (!(l->p_a > 0.0) || !(l->t_a > 0.0) || !(v_len[i] > 0.0) || !isfinite(l->nn2) ||
            !(v_along[i] > 1e-9)) {
            texture_lambda(t[i]);
            continue;
        }
        const double ja_i[2] = {v_ja[0][i], v_ja[1][i]}, jb_i[2] = {v_jb[0][i], v_jb[1][i]};
        t[i]->lambda = lod_axes(ja_i, jb_i, v_sa[i], v_sb[i], v_sbc[i], v_cos[i], t[i]->width,
                                lod_top(t[i]->tex->level_count));
    }
}
#endif

#if defined(SURFACE_QUADS)
static __m256d quad_dot(const __m256d a[3], const __m256d b[3])
{
    return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a[0], b[0]), _mm256_mul_pd(a[1], b[1])),
                         _mm256_mul_pd(a[2], b[2]));
}

static void quad_cross(const __m256d a[3], const __m256d b[3], __m256d out[3])
{
    out[0] = _mm256_sub_pd(_mm256_mul_pd(a[1], b[2]), _mm256_mul_pd(a[2], b[1]));
    out[1] = _mm256_sub_pd(_mm256_mul_pd(a[2], b[0]), _mm256_mul_pd(a[0], b[2]));
    out[2] = _mm256_sub_pd(_mm256_mul_pd(a[0], b[1]), _mm256_mul_pd(a[1], b[0]));
}

/* pair_texel_vector in four double lanes. */
SURFACE_INLINE void quad_texel_vector(const __m256d e[3], const __m256d w1[3],
                                      const __m256d w2[3], const __m256d nn[3], __m256d nn2,
                                      const __m256d a1[2], const __m256d a2[2], __m256d out[2])
{
    __m256d ew2[3], w1e[3];
    quad_cross(e, w2, ew2);
    quad_cross(w1, e, w1e);
    const __m256d alpha = _mm256_div_pd(quad_dot(ew2, nn), nn2);
    const __m256d beta = _mm256_div_pd(quad_dot(w1e, nn), nn2);
    out[0] = _mm256_add_pd(_mm256_mul_pd(alpha, a1[0]), _mm256_mul_pd(beta, a2[0]));
    out[1] = _mm256_add_pd(_mm256_mul_pd(alpha, a1[1]), _mm256_mul_pd(beta, a2[1]));
}

/* What lod_quad leaves to a lane it does not decide: lod_axes's
 * arguments, and whether the lane is on lod_ray's common path. */
struct lod_quad_rest {
    double cos[4], ja[2][4], jb[2][4], sa[4], sb[4], sbc[4];
    int common; /* mask of the lanes on the common path */
};

/* The low 32 bits of each double lane of a mask: the mask in four float
 * lanes. */
static inline __m128 quad_mask_ps(__m256d m)
{
    return _mm256_castps256_ps128(_mm256_castsi256_ps(_mm256_permutevar8x32_epi32(
        _mm256_castpd_si256(m), _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6))));
}

/* lod_decide_quad's thresholds: 1 (1 -+ relative) and top (1 -+
 * relative), made once where top is known (lod_bounds). */
struct lod_bounds {
    __m256d one_lo, one_hi, top_lo, top_hi;
};

/* The thresholds for footprints (squared: for their squares, top the
 * square of lod_top and relative doubled; see lod_decide_quad). */
static inline struct lod_bounds lod_bounds(__m256d top, double relative, int squared)
{
    if (squared)
        relative *= 2.0;
    struct lod_bounds b;
    b.one_lo = _mm256_set1_pd(1.0 - relative);
    b.one_hi = _mm256_set1_pd(1.0 + relative);
    b.top_lo = _mm256_mul_pd(top, _mm256_set1_pd(1.0 - relative));
    b.top_hi = _mm256_mul_pd(top, _mm256_set1_pd(1.0 + relative));
    return b;
}

/* The levels of detail of four footprints x where they are decided
 * (lod_quad, lod_fast_quad): -inf below 1 - relative, +inf beyond top (1
 * + relative), and between 1 + relative and top (1 - relative) the float
 * of lanes_log2_4(x) when every value within `absolute` of it rounds to
 * that float.  Writes lambda[i] of every lane and returns the mask of the
 * lanes so decided; the caller ANDs the lanes its bound covers.  The
 * thresholds come from lod_bounds (once a block where the caller can),
 * made with the same `squared`.
 *
 * With `squared` (a constant at each call), x holds the footprint's
 * square y, the bounds are those of the square of lod_top, and no square
 * root is taken: the tests are against 1 -+ 2 relative and top^2 (1 -+ 2
 * relative), and the log2 is lanes_log2_4(y) / 2 (lanes_log2_4_half).
 * lod_top is a power of two, so every threshold is exact; sqrt(y) <
 * sqrt(1 - 2 relative) < 1 - relative, and sqrt(y) > sqrt(1 + 2
 * relative) > 1 + relative - relative^2 / 2, likewise for top: the exact
 * sqrt(y) meets the unsquared tests but for relative^2 / 2 of 1 or top,
 * 2^-33 of relative for the caller's relative of 2^-32, which its margin
 * covers (lod_fast's, below).  The log2 is within
 * 2^-48 of log2(y) for y in [1, 2^32] (lanes_log2_4), so its half within
 * 2^-49 of log2(sqrt(y)). */
SURFACE_INLINE int lod_decide_quad(__m256d x, const struct lod_bounds *b, double absolute,
                                   int squared, float lambda[4])
{
    const __m256d below = _mm256_cmp_pd(x, b->one_lo, _CMP_LT_OQ);
    const __m256d beyond = _mm256_cmp_pd(x, b->top_hi, _CMP_GT_OQ);
    const __m256d inside = _mm256_and_pd(_mm256_cmp_pd(x, b->one_hi, _CMP_GT_OQ),
                                         _mm256_cmp_pd(x, b->top_lo, _CMP_LT_OQ));
    const __m256d lg = squared ? lanes_log2_4_half(x) : lanes_log2_4(x);
    const __m128 lg_f = _mm256_cvtpd_ps(lg);
    const __m256d margin = _mm256_set1_pd(absolute);
    const __m128 exact =
        _mm_and_ps(_mm_cmpeq_ps(_mm256_cvtpd_ps(_mm256_sub_pd(lg, margin)), lg_f),
                   _mm_cmpeq_ps(_mm256_cvtpd_ps(_mm256_add_pd(lg, margin)), lg_f));
    /* Below 1: a magnification; beyond the last level; between: the
     * log2's float where it is decided. */
    const __m128 below_ps = quad_mask_ps(below), beyond_ps = quad_mask_ps(beyond);
    _mm_storeu_ps(lambda,
                  _mm_blendv_ps(_mm_blendv_ps(lg_f, _mm_set1_ps(INFINITY), beyond_ps),
                                _mm_set1_ps(-INFINITY), below_ps));
    return _mm256_movemask_pd(_mm256_or_pd(below, beyond)) |
           (_mm256_movemask_pd(inside) & _mm_movemask_ps(exact));
}

/*
 * lod_ray_pair in the four double lanes of the AVX2 copy: lane i a hit
 * along d (its direction) on a surface with the facing normal g, its
 * cone's width at the hit, the triangle part l[i] (one for all when
 * `shared`: its values broadcast) and top its texture's lod_top, each
 * lane lod_ray's operations in its order (the comparisons ordered, as
 * cmpge and cmpgt in the pair), so the same doubles.  Writes lambda[i]
 * of every lane and returns the mask of the lanes whose lambda is
 * texture_lod's; a lane not in it takes lod_axes with rest's values when
 * it is in rest->common, else lod_ray (lod_quad_finish).
 */
SURFACE_INLINE int lod_quad(const struct surface_lod *const l[4], int shared, const __m256d d[3],
                            const __m256d g[3], __m256d width, __m256d top, float lambda[4],
                            struct lod_quad_rest *rest)
{
#define QUAD(f) _mm256_set_pd(f(3), f(2), f(1), f(0))
    __m256d n[3], w1[3], w2[3], nn[3], a1[2], a2[2], nn2, p_a, t_a;
    if (shared) {
        /* One triangle part for the four (fetch_colours_one_triangle):
         * its values broadcast, the same doubles in every lane. */
        const struct surface_lod *o = l[0];
        for (int k = 0; k < 3; k++) {
            n[k] = _mm256_set1_pd(o->n[k]);
            w1[k] = _mm256_set1_pd(o->w1[k]);
            w2[k] = _mm256_set1_pd(o->w2[k]);
            nn[k] = _mm256_set1_pd(o->nn[k]);
        }
        for (int k = 0; k < 2; k++) {
            a1[k] = _mm256_set1_pd(o->a1[k]);
            a2[k] = _mm256_set1_pd(o->a2[k]);
        }
        nn2 = _mm256_set1_pd(o->nn2);
        p_a = _mm256_set1_pd(o->p_a);
        t_a = _mm256_set1_pd(o->t_a);
    } else {
        for (int k = 0; k < 3; k++) {
#define N(i) l[i]->n[k]
#define W1(i) l[i]->w1[k]
#define W2(i) l[i]->w2[k]
#define NN(i) l[i]->nn[k]
            n[k] = QUAD(N);
            w1[k] = QUAD(W1);
            w2[k] = QUAD(W2);
            nn[k] = QUAD(NN);
        }
        for (int k = 0; k < 2; k++) {
#define A1(i) l[i]->a1[k]
#define A2(i) l[i]->a2[k]
            a1[k] = QUAD(A1);
            a2[k] = QUAD(A2);
        }
#define NN2(i) l[i]->nn2
#define P_A(i) l[i]->p_a
#define T_A(i) l[i]->t_a
        nn2 = QUAD(NN2);
        p_a = QUAD(P_A);
        t_a = QUAD(T_A);
    }
#undef QUAD
#undef N
#undef W1
#undef W2
#undef NN
#undef A1
#undef A2
#undef NN2
#undef P_A
#undef T_A
    const __m256d dir_len = _mm256_sqrt_pd(quad_dot(d, d));
    const __m256d sign = _mm256_set1_pd(-0.0);
    __m256d cosine = _mm256_div_pd(_mm256_andnot_pd(sign, quad_dot(g, d)), dir_len);
    const __m256d min_cos = _mm256_set1_pd(LOD_MIN_COSINE);
    const __m256d keep = _mm256_cmp_pd(cosine, min_cos, _CMP_GE_OQ);
    cosine = _mm256_blendv_pd(min_cos, cosine, keep);
    const __m256d dn = _mm256_div_pd(quad_dot(d, n), dir_len);
    __m256d along[3];
    for (int k = 0; k < 3; k++)
        along[k] = _mm256_sub_pd(_mm256_div_pd(d[k], dir_len), _mm256_mul_pd(dn, n[k]));
    const __m256d along_len = _mm256_sqrt_pd(quad_dot(along, along));
    for (int k = 0; k < 3; k++)
        along[k] = _mm256_div_pd(along[k], along_len);
    __m256d across[3];
    quad_cross(n, along, across);
    __m256d ja[2], jb[2];
    quad_texel_vector(along, w1, w2, nn, nn2, a1, a2, ja);
    quad_texel_vector(across, w1, w2, nn, nn2, a1, a2, jb);
    const __m256d sa = _mm256_add_pd(_mm256_mul_pd(ja[0], ja[0]), _mm256_mul_pd(ja[1], ja[1]));
    const __m256d sb = _mm256_add_pd(_mm256_mul_pd(jb[0], jb[0]), _mm256_mul_pd(jb[1], jb[1]));
    const __m256d sbc = _mm256_mul_pd(sb, _mm256_mul_pd(cosine, cosine));
    /* lod_ray's common path (the triangle and direction not degenerate,
     * the ray not meeting the plane head-on) and, there, lod_axes's first
     * steps in the lanes: which axis wins by the margin, and lod_near's
     * footprint xs and its tests against 1 and the last level (`top`), each
     * lane the scalar operations in their order, and lod_near's log2 and
     * its rounding test.  That log2 is lanes_log2_4, not glibc's: lod_near
     * needs log2(xs) within 2^-45 of log2(x) (x = hypot width [/ cosine],
     * what lod_axes takes glibc's log2 of), and lanes_log2_4 is within
     * 2^-47 of the exact log2(xs) (xs < top <= 2^16, in its domain), the
     * exact log2(xs) within 2^-48.4 of the exact log2(x) (xs within 2^-49
     * of x, relative), and glibc's log2(x) within 2 ulps, 2^-47, of that:
     * 2^-45.4 in all, so every value within LOD_NEAR_ABSOLUTE (2^-42) of
     * lanes_log2_4(xs) rounding to one float f still makes f = float(glibc's
     * log2(x)).  A lane whose answer is not decided so (no axis wins, a
     * footprint close to a bound or the log2 close to a float's rounding
     * boundary) takes lod_axes whole, as before, and a lane off the common
     * path lod_ray. */
    const __m256d zero = _mm256_setzero_pd();
    /* isfinite(nn2): |nn2| <= DBL_MAX, which a NaN fails. */
    const __m256d finite = _mm256_cmp_pd(_mm256_andnot_pd(sign, nn2), _mm256_set1_pd(DBL_MAX),
                                         _CMP_LE_OQ);
    const __m256d common = _mm256_and_pd(
        _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(p_a, zero, _CMP_GT_OQ),
                                    _mm256_cmp_pd(t_a, zero, _CMP_GT_OQ)),
                      _mm256_and_pd(_mm256_cmp_pd(dir_len, zero, _CMP_GT_OQ), finite)),
        _mm256_cmp_pd(along_len, _mm256_set1_pd(1e-9), _CMP_GT_OQ));
    const __m256d margin = _mm256_set1_pd(1.0 + LOD_AXIS_MARGIN);
    const __m256d major = _mm256_cmp_pd(sa, _mm256_mul_pd(sbc, margin), _CMP_GT_OQ);
    const __m256d minor =
        _mm256_andnot_pd(major, _mm256_cmp_pd(sbc, _mm256_mul_pd(sa, margin), _CMP_GT_OQ));
    /* lod_near(sa, sqrt(sa) width / cosine, ...) or lod_near(sb,
     * sqrt(sb) width, ...). */
    const __m256d s2 = _mm256_blendv_pd(sb, sa, major);
    const __m256d root = _mm256_mul_pd(_mm256_sqrt_pd(s2), width);
    const __m256d xs = _mm256_blendv_pd(root, _mm256_div_pd(root, cosine), major);
    const __m256d usable = _mm256_and_pd(
        _mm256_and_pd(common, _mm256_or_pd(major, minor)),
        _mm256_and_pd(_mm256_cmp_pd(s2, _mm256_set1_pd(0x1p-960), _CMP_GE_OQ),
                      _mm256_cmp_pd(s2, _mm256_set1_pd(0x1p960), _CMP_LE_OQ)));
    const struct lod_bounds bounds = lod_bounds(top, LOD_NEAR_RELATIVE, 0);
    const int decided = _mm256_movemask_pd(usable) &
                        lod_decide_quad(xs, &bounds, LOD_NEAR_ABSOLUTE, 0, lambda);
    rest->common = _mm256_movemask_pd(common);
    if (decided != 15) {
        _mm256_storeu_pd(rest->cos, cosine);
        _mm256_storeu_pd(rest->ja[0], ja[0]);
        _mm256_storeu_pd(rest->ja[1], ja[1]);
        _mm256_storeu_pd(rest->jb[0], jb[0]);
        _mm256_storeu_pd(rest->jb[1], jb[1]);
        _mm256_storeu_pd(rest->sa, sa);
        _mm256_storeu_pd(rest->sb, sb);
        _mm256_storeu_pd(rest->sbc, sbc);
    }
    return decided;
}

/* Lane i's lambda that lod_quad did not decide, from rest (lod_axes) on
 * the common path, else NaN: the caller takes lod_ray. */
SURFACE_INLINE int lod_quad_axes(const struct lod_quad_rest *rest, int i, float width,
                                 double top, float *lambda)
{
    if (!(rest->common >> i & 1))
        return 0;
    const double ja[2] = {rest->ja[0][i], rest->ja[1][i]}, jb[2] = {rest->jb[0][i], rest->jb[1][i]};
    *lambda = lod_axes(ja, jb, rest->sa[i], rest->sb[i], rest->sbc[i], rest->cos[i], width, top);
    return 1;
}

/* The levels of detail of half h (lanes 4h..4h+3) of a block: lod_quad's
 * chain on the quad, then lane by lane what it left, from its common
 * rest (lod_quad_axes) or else lod_ray with the lane's own triangle part
 * l[i], facing normal and direction: the per-hit path's lambdas.  For
 * surface_fetch_lanes (one part, shared) and fetch_lanes_mixed. */
SURFACE_INLINE void lod_quad_lanes(const struct surface_lod *const l[4], int shared,
                                   const __m256d d[3], const __m256d g[3], __m256d width4,
                                   double top, int level_count, int h, const float width[],
                                   const float lane_g[3][TRACE_PACKET],
                                   const float dir[3][TRACE_PACKET], float lambda[])
{
    struct lod_quad_rest rest;
    const int decided =
        lod_quad(l, shared, d, g, width4, _mm256_set1_pd(top), &lambda[4 * h], &rest);
    for (int i = 0; i < 4; i++) {
        const int j = 4 * h + i;
        if (decided >> i & 1 || lod_quad_axes(&rest, i, width[j], top, &lambda[j]))
            continue;
        const float ngj[3] = {lane_g[0][j], lane_g[1][j], lane_g[2][j]};
        const float dj[3] = {dir[0][j], dir[1][j], dir[2][j]};
        lambda[j] = lod_ray(l[i], level_count, ngj, dj, width[j]);
    }
}

/*
 * The level of detail of a block of hits on one triangle
 * (surface_fetch_lanes) from the triangle's texel map, with a proven
 * margin instead of lod_quad's chain of thirteen divisions and three
 * square roots a lane.
 *
 * lod_ray's texel vectors are linear in the in-plane vector e: alpha =
 * (e x w2) . nn / nn2 = e . (w2 x nn) / nn2 and beta = (w1 x e) . nn /
 * nn2 = e . (nn x w1) / nn2 (the scalar triple product's cyclic
 * symmetry), so J e = M e with the 2 x 3 matrix M = (a1 (w2 x nn)^T + a2
 * (nn x w1)^T) / nn2, and M nn = 0.  With along = P d / |P d| (P the
 * projection off the unit normal, |P d| = |n x d|) and across = n x
 * along, M along = M d / |n x d| and M across = M (n x d) / |n x d|; the
 * cosine is |g . d| / |d|.  So lod_axes's two footprints, A = |J along|
 * width / cosine and B = |J across| width, are
 *
 *     A^2 = |M d|^2 |d|^2 width^2 / (|n x d|^2 (g . d)^2),
 *     B^2 = |M (n x d)|^2 width^2 / |n x d|^2,
 *
 * and texture_lod's lambda is float(log2(x)) for x its computed max(A,
 * B) (lod_axes takes A or B alone only when it wins by LOD_AXIS_MARGIN,
 * far above the roundings between the squares and the hypots), -inf for
 * x <= 1 and +inf from x >= top on.  Here x' = sqrt(y), y = w^2 max(|M
 * d|^2 |d|^2, |M (n x d)|^2 (g . d)^2) / (|n x d|^2 (g . d)^2): one
 * division a lane, M once a triangle part (lod_fast_init, kept in the
 * tile's cache beside the triangle part), and the square root not taken
 * (lod_decide_quad's `squared`: y's tests against the squared bounds and
 * log2(y) / 2; x' below is the exact sqrt(y)).
 *
 * The margin.  Both x' and lod_ray's x are within delta x of the exact
 * value of these expressions (the same inputs: d, g, width and the
 * triangle part's doubles), delta = C eps (kappa / (sin cos) + 1 / cos +
 * 1), eps = 2^-53, sin = |n x d| / |d|, cos = |g . d| / |d|, kappa = 2 K
 * / |M| (|M| Frobenius') with K = (|w2| |a1| + |w1| |a2|) / |nn|: K
 * bounds M's norm and the absolute error of a texel vector's
 * computation, and since along and across are an orthonormal basis of
 * the plane, |J along|^2 + |J across|^2 = |M|^2, so x >= width |M| / 2
 * and an absolute error eps K |d| in M d, M (n x d), M along or M across
 * is at most eps kappa / (sin cos) of x after the division by |n x d|
 * and the cosine.  lod_ray's along carries absolute errors of some 35 eps
 * before its normalisation (d / |d|, its dot with n, n's own from nn /
 * p_a, the subtraction), so about 75 eps / sin after it, 160 eps / sin in
 * across, and its texel vectors some 14 eps K of their own: about 175
 * eps kappa / (sin cos) in all; the cosine's dot loses 5 eps / cos of
 * x.  x' takes some 50 eps kappa / (sin cos) (M's entries, its two
 * products, the cross product, the squares and the quotient; the exact
 * square root halves the quotient's relative error).  C = 2^12
 * covers these sums 18 times.  A lane is taken only with kappa / (sin
 * cos) <= 64 and 1 / cos <= 64 (so lod_ray is on its common path:
 * along_len > 1e-9, the cosine above LOD_MIN_COSINE), |d|^2 in [1/4, 4]
 * and its squares in the normal range (an underflow's absolute error is
 * then negligible): delta < 2^-41 129 < 2^-33.98, x' within 2^-32.97 of
 * x, and log2(x') within 1.443 2^-32.97 + lanes_log2_4(y) / 2's 2^-49 +
 * glibc's 2 ulps (2^-47) < 2^-32.4 of glibc's log2(x).  So x' beyond 1 or
 * top by LOD_FAST_RELATIVE (less 2^-65, lod_decide_quad's squared tests)
 * decides the side, and a log2 whose LOD_FAST_ABSOLUTE
 * neighbourhood rounds to one float gives lod_ray's float (rounding is
 * monotonic).  Undecided lanes (a footprint near 1 or the last level, a
 * log2 within 2^-32 of a float's rounding boundary, a ray within a few
 * degrees of the normal) take lod_quad, as before.
 */
#define LOD_FAST_RELATIVE 0x1p-32
#define LOD_FAST_ABSOLUTE 0x1p-32
/* (kappa / (sin cos))^2 <= 64^2. */
#define LOD_FAST_RATIO2 4096.0

/* l's texel map and bound into f (surface_lod_fast; state 1), or state
 * -1 when the triangle part leaves lod_ray's common path or its values
 * are too large or small for the bound's ranges.  M's entries need not
 * be any particular rounding, only within a few eps K of the exact ones
 * (the product by 1 / nn2 adds one); kappa^2 = 4 K^2 / |M|^2 needs no
 * square root of its own. */
static void lod_fast_init(const struct surface_lod *l, struct surface_lod_fast *f)
{
    f->state = -1;
    const double lo = 0x1p-100, hi = 0x1p100;
    const double w1s = dot3d(l->w1, l->w1), w2s = dot3d(l->w2, l->w2);
    const double a1s = l->a1[0] * l->a1[0] + l->a1[1] * l->a1[1];
    const double a2s = l->a2[0] * l->a2[0] + l->a2[1] * l->a2[1];
    if (!(l->p_a >= lo && l->p_a <= hi && l->t_a >= lo && l->t_a <= hi && w1s >= lo &&
          w1s <= hi && w2s >= lo && w2s <= hi && a1s >= lo && a1s <= hi && a2s >= lo &&
          a2s <= hi && isfinite(l->nn2)))
        return;
    const double inv = 1.0 / l->nn2;
    double c2[3], c1[3];
    cross3d(l->w2, l->nn, c2);
    cross3d(l->nn, l->w1, c1);
    for (int k = 0; k < 3; k++) {
        c2[k] *= inv;
        c1[k] *= inv;
    }
    double m2 = 0.0;
    for (int r = 0; r < 2; r++) {
        for (int k = 0; k < 3; k++)
            f->m[r][k] = l->a1[r] * c2[k] + l->a2[r] * c1[k];
        m2 += dot3d(f->m[r], f->m[r]);
    }
    if (!(m2 >= 0x1p-200 && m2 <= 0x1p200))
        return;
    /* K^2 = (|w2| |a1| + |w1| |a2|)^2 / nn2. */
    const double k_sum = sqrt(w2s * a1s) + sqrt(w1s * a2s);
    const double kappa2 = fmax(4.0 * (k_sum * k_sum * inv) / m2, 1.0);
    f->sin2 = kappa2 / LOD_FAST_RATIO2 * (1.0 + 0x1p-20);
    if (f->sin2 < 1.0)
        f->state = 1;
}

/* A triangle part's values that lod_fast_quad reads in every lane (its
 * unit normal, f's texel map and bound), broadcast once for a block's
 * two quads: the same doubles in every lane as broadcast per quad. */
struct lod_fast_broadcast {
    __m256d n[3], m0[3], m1[3];
    __m256d sin2;
    struct lod_bounds bounds; /* squared, of the texture's lod_top */
};

SURFACE_INLINE void lod_fast_quad_lanes(const struct surface_lod_fast *f, const double unit[3],
                                        double top, struct lod_fast_broadcast *b)
{
    b->bounds = lod_bounds(_mm256_set1_pd(top * top), LOD_FAST_RELATIVE, 1);
    for (int k = 0; k < 3; k++) {
        b->n[k] = _mm256_set1_pd(unit[k]);
        b->m0[k] = _mm256_set1_pd(f->m[0][k]);
        b->m1[k] = _mm256_set1_pd(f->m[1][k]);
    }
    b->sin2 = _mm256_set1_pd(f->sin2);
}

/* lod_quad's lambdas of four hits on b's triangle (d their directions,
 * g their facing normals, width their cones' widths at the hits; b's
 * bounds from the texture's lod_top) where lod_fast's margin decides
 * them: writes those into lambda and returns their mask. */
SURFACE_INLINE int lod_fast_quad(const struct lod_fast_broadcast *b, const __m256d d[3],
                                 const __m256d g[3], __m256d width, float lambda[4])
{
    const __m256d *n = b->n, *m0 = b->m0, *m1 = b->m1;
    __m256d c[3];
    quad_cross(n, d, c);
    const __m256d dd = quad_dot(d, d), s = quad_dot(c, c);
    const __m256d gd = quad_dot(g, d), gg = _mm256_mul_pd(gd, gd);
    const __m256d u0 = quad_dot(m0, d), u1 = quad_dot(m1, d);
    const __m256d v0 = quad_dot(m0, c), v1 = quad_dot(m1, c);
    const __m256d p = _mm256_add_pd(_mm256_mul_pd(u0, u0), _mm256_mul_pd(u1, u1));
    const __m256d q = _mm256_add_pd(_mm256_mul_pd(v0, v0), _mm256_mul_pd(v1, v1));
    const __m256d ww = _mm256_mul_pd(width, width);
    const __m256d num = _mm256_max_pd(_mm256_mul_pd(p, dd), _mm256_mul_pd(q, gg));
    /* x'^2: lod_decide_quad takes the square (no square root). */
    const __m256d x2 = _mm256_div_pd(_mm256_mul_pd(ww, num), _mm256_mul_pd(s, gg));
    /* The bound's conditions (NaNs fail every one); 1 / cos <= 64 follows
     * from kappa / (sin cos) <= 64 with kappa >= 1 and sin <= 1. */
    const __m256d tiny = _mm256_set1_pd(0x1p-500), huge = _mm256_set1_pd(0x1p500);
    __m256d ok = _mm256_and_pd(_mm256_cmp_pd(dd, _mm256_set1_pd(0.25), _CMP_GE_OQ),
                               _mm256_cmp_pd(dd, _mm256_set1_pd(4.0), _CMP_LE_OQ));
    ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_mul_pd(s, gg),
                                         _mm256_mul_pd(b->sin2, _mm256_mul_pd(dd, dd)),
                                         _CMP_GE_OQ));
    ok = _mm256_and_pd(ok, _mm256_and_pd(_mm256_cmp_pd(ww, _mm256_set1_pd(0x1p-200), _CMP_GE_OQ),
                                         _mm256_cmp_pd(ww, _mm256_set1_pd(0x1p200), _CMP_LE_OQ)));
    ok = _mm256_and_pd(ok, _mm256_and_pd(_mm256_cmp_pd(p, tiny, _CMP_GE_OQ),
                                         _mm256_cmp_pd(p, huge, _CMP_LE_OQ)));
    ok = _mm256_and_pd(ok, _mm256_and_pd(_mm256_cmp_pd(q, tiny, _CMP_GE_OQ),
                                         _mm256_cmp_pd(q, huge, _CMP_LE_OQ)));
    return _mm256_movemask_pd(ok) &
           lod_decide_quad(x2, &b->bounds, LOD_FAST_ABSOLUTE, 1, lambda);
}

#if defined(SURFACE_OCTS)
/* quad_dot and quad_cross in eight lanes. */
static inline __m512d oct_dot(const __m512d a[3], const __m512d b[3])
{
    return _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(a[0], b[0]), _mm512_mul_pd(a[1], b[1])),
                         _mm512_mul_pd(a[2], b[2]));
}

static inline void oct_cross(const __m512d a[3], const __m512d b[3], __m512d out[3])
{
    out[0] = _mm512_sub_pd(_mm512_mul_pd(a[1], b[2]), _mm512_mul_pd(a[2], b[1]));
    out[1] = _mm512_sub_pd(_mm512_mul_pd(a[2], b[0]), _mm512_mul_pd(a[0], b[2]));
    out[2] = _mm512_sub_pd(_mm512_mul_pd(a[0], b[1]), _mm512_mul_pd(a[1], b[0]));
}

/* lod_decide_quad of eight footprints, squared (its `squared` form
 * only: top the square of lod_top), lanes_log2_8_half for
 * lanes_log2_4_half: the same comparisons, conversions and choices lane
 * by lane. */
SURFACE_INLINE int lod_decide_oct(__m512d x, __m512d top, double relative, double absolute,
                                  float lambda[8])
{
    relative *= 2.0;
    const __mmask8 below = _mm512_cmp_pd_mask(x, _mm512_set1_pd(1.0 - relative), _CMP_LT_OQ);
    const __mmask8 beyond =
        _mm512_cmp_pd_mask(x, _mm512_mul_pd(top, _mm512_set1_pd(1.0 + relative)), _CMP_GT_OQ);
    const __mmask8 inside =
        _mm512_cmp_pd_mask(x, _mm512_set1_pd(1.0 + relative), _CMP_GT_OQ) &
        _mm512_cmp_pd_mask(x, _mm512_mul_pd(top, _mm512_set1_pd(1.0 - relative)), _CMP_LT_OQ);
    const __m512d lg = lanes_log2_8_half(x);
    const __m256 lg_f = _mm512_cvtpd_ps(lg);
    const __m512d margin = _mm512_set1_pd(absolute);
    const __mmask8 exact =
        _mm256_cmp_ps_mask(_mm512_cvtpd_ps(_mm512_sub_pd(lg, margin)), lg_f, _CMP_EQ_OQ) &
        _mm256_cmp_ps_mask(_mm512_cvtpd_ps(_mm512_add_pd(lg, margin)), lg_f, _CMP_EQ_OQ);
    _mm256_storeu_ps(lambda,
                     _mm256_mask_blend_ps(below,
                                          _mm256_mask_blend_ps(beyond, lg_f,
                                                               _mm256_set1_ps(INFINITY)),
                                          _mm256_set1_ps(-INFINITY)));
    return (below | beyond) | (inside & exact);
}

/* lod_fast_quad of eight hits, each lane on its own triangle part: n,
 * m0, m1 and sin2 lane i's part's unit normal, texel map rows and bound
 * (lod_fast_init), d, g and width its hit's as in lod_fast_quad, top2
 * the texture's lod_top squared.  Each lane its operations in their
 * order, so the same y, conditions and lambdas as lod_fast_quad gives a
 * hit on that part; writes all eight lambdas (a lane not decided gets a
 * value the caller must not use) and returns the mask of the decided. */
SURFACE_INLINE int lod_fast_oct_lanes(const __m512d n[3], const __m512d m0[3],
                                      const __m512d m1[3], __m512d sin2, const __m512d d[3],
                                      const __m512d g[3], __m512d width, __m512d top2,
                                      float lambda[8])
{
    __m512d c[3];
    oct_cross(n, d, c);
    const __m512d dd = oct_dot(d, d), s = oct_dot(c, c);
    const __m512d gd = oct_dot(g, d), gg = _mm512_mul_pd(gd, gd);
    const __m512d u0 = oct_dot(m0, d), u1 = oct_dot(m1, d);
    const __m512d v0 = oct_dot(m0, c), v1 = oct_dot(m1, c);
    const __m512d p = _mm512_add_pd(_mm512_mul_pd(u0, u0), _mm512_mul_pd(u1, u1));
    const __m512d q = _mm512_add_pd(_mm512_mul_pd(v0, v0), _mm512_mul_pd(v1, v1));
    const __m512d ww = _mm512_mul_pd(width, width);
    /* vmaxpd's rule (the second operand unless the first is greater) in
     * every encoding without {sae}: Intel SDM, VMAXPD. */
    const __m512d num = _mm512_max_pd(_mm512_mul_pd(p, dd), _mm512_mul_pd(q, gg));
    const __m512d x2 = _mm512_div_pd(_mm512_mul_pd(ww, num), _mm512_mul_pd(s, gg));
    const __m512d tiny = _mm512_set1_pd(0x1p-500), huge = _mm512_set1_pd(0x1p500);
    __mmask8 ok = _mm512_cmp_pd_mask(dd, _mm512_set1_pd(0.25), _CMP_GE_OQ) &
                  _mm512_cmp_pd_mask(dd, _mm512_set1_pd(4.0), _CMP_LE_OQ);
    ok &= _mm512_cmp_pd_mask(_mm512_mul_pd(s, gg), _mm512_mul_pd(sin2, _mm512_mul_pd(dd, dd)),
                             _CMP_GE_OQ);
    ok &= _mm512_cmp_pd_mask(ww, _mm512_set1_pd(0x1p-200), _CMP_GE_OQ) &
          _mm512_cmp_pd_mask(ww, _mm512_set1_pd(0x1p200), _CMP_LE_OQ);
    ok &= _mm512_cmp_pd_mask(p, tiny, _CMP_GE_OQ) & _mm512_cmp_pd_mask(p, huge, _CMP_LE_OQ);
    ok &= _mm512_cmp_pd_mask(q, tiny, _CMP_GE_OQ) & _mm512_cmp_pd_mask(q, huge, _CMP_LE_OQ);
    return ok & lod_decide_oct(x2, top2, LOD_FAST_RELATIVE, LOD_FAST_ABSOLUTE, lambda);
}

/* lod_fast_quad of eight hits on one triangle part (a block's two quads
 * in one vector, lane i hit i): lod_fast_oct_lanes with f's values and
 * the part's unit normal broadcast, the same doubles in every lane. */
SURFACE_INLINE int lod_fast_oct(const struct surface_lod_fast *f, const double unit[3],
                                const __m512d d[3], const __m512d g[3], __m512d width,
                                __m512d top2, float lambda[8])
{
    __m512d n[3], m0[3], m1[3];
    for (int k = 0; k < 3; k++) {
        n[k] = _mm512_set1_pd(unit[k]);
        m0[k] = _mm512_set1_pd(f->m[0][k]);
        m1[k] = _mm512_set1_pd(f->m[1][k]);
    }
    return lod_fast_oct_lanes(n, m0, m1, _mm512_set1_pd(f->sin2), d, g, width, top2, lambda);
}
#endif

/* lod_quad of four textures' hits t[i] (their lodp, dir, ng, width and
 * texture), each lambda into t[i]. */
SURFACE_INLINE void lod_ray_quad(struct surface_texture *const t[4])
{
    const struct surface_lod *l[4] = {t[0]->lodp, t[1]->lodp, t[2]->lodp, t[3]->lodp};
    const int shared = l[0] == l[1] && l[0] == l[2] && l[0] == l[3];
#define QUAD(f) _mm256_set_pd(f(3), f(2), f(1), f(0))
#define DIR(i) (double)t[i]->dir[k]
#define NG(i) (double)t[i]->ng[k]
#define WIDTH(i) (double)t[i]->width
#define TOP(i) lod_top(t[i]->tex->level_count)
    __m256d d[3], g[3];
    for (int k = 0; k < 3; k++) {
        d[k] = QUAD(DIR);
        g[k] = QUAD(NG);
    }
    /* One triangle part, so one block on one triangle and texture
     * (fetch_colours_one_triangle): one top. */
    const __m256d top = shared ? _mm256_set1_pd(TOP(0)) : QUAD(TOP);
    float lambda[4];
    struct lod_quad_rest rest;
    const int decided = lod_quad(l, shared, d, g, QUAD(WIDTH), top, lambda, &rest);
#undef QUAD
#undef DIR
#undef NG
#undef WIDTH
#undef TOP
    for (int i = 0; i < 4; i++) {
        if (decided >> i & 1)
            t[i]->lambda = lambda[i];
        else if (!lod_quad_axes(&rest, i, t[i]->width, lod_top(t[i]->tex->level_count),
                                &t[i]->lambda))
            texture_lambda(t[i]);
    }
}
#endif

/* The level of detail of the n textures t[i] with lod set, four (in the
 * AVX copy) or two at a time. */
static void texture_lods(struct surface_texture *const *t, int n)
{
    int i = 0;
#if defined(SURFACE_QUADS)
    for (; i + 3 < n; i += 4)
        lod_ray_quad(&t[i]);
#endif
#if SURFACE_PAIRS
    for (; i + 1 < n; i += 2)
        lod_ray_pair(t[i], t[i + 1]);
#endif
    for (; i < n; i++)
        texture_lambda(t[i]);
}

/*
 * GL's projective texture coordinates (OpenGL 1.1 sec. 3.8: s / q and
 * t / q): s, t and q interpolated across the triangle and divided at the
 * fragment.  The hit's barycentric weights are those of the triangle in
 * space, so this is the perspective-correct interpolation GL's
 * rasteriser makes (Heckbert and Moreton 1991, interpolation of
 * homogeneous attributes), the projective texture mapping of Segal,
 * Korobkin, van Widenfelt, Foran and Haeberli (1992).  The level of
 * detail takes the map's tangent at the hit: vertex coordinates
 * u + (s_i - u q_i) / q, whose linear interpolation has the value u and
 * the derivatives of s / q there.  A fragment with q = 0 (s / q
 * undefined) samples (0, 0).
 */
static void projective_st(const float *const vst[3], const float q[3], float b0, float b1,
                          float b2, float st[2], float lod_st[3][2])
{
    const float qb = b0 * q[0] + b1 * q[1] + b2 * q[2];
    for (int k = 0; k < 2; k++) {
        float u = (b0 * vst[0][k] + b1 * vst[1][k] + b2 * vst[2][k]) / qb;
        int finite = isfinite(u);
        st[k] = finite ? u : 0.0f;
        for (int i = 0; i < 3; i++) {
            float l = st[k] + (vst[i][k] - st[k] * q[i]) / qb;
            lod_st[i][k] = finite && isfinite(l) ? l : st[k];
        }
    }
}

/*
 * GL's MODULATE environment (OpenGL 1.1 sec. 3.8.6, table 3.19: C = Cf Ct)
 * applied before lighting to the colours that carry the surface's own
 * colour: ambient and diffuse (which RT_COLOR_MATERIAL may have replaced).
 * Emission and specular are left alone, as with GL 1.2's separate
 * specular colour.  Lighting is linear in both, so for them this equals
 * modulating the lit colour.  The triangle keeps the texture's name; a
 * name without an image (deleted, or never given one) leaves the surface
 * untextured.  Texture coordinates are interpolated, never flat.  The
 * texel is filtered for the ray cone's `width` at the hit (texture_lod);
 * when both filters are the same non-mipmapped one every level of detail
 * gives the same lookup, and none is computed.
 */
/* The texture named `name` (not 0), through the tile's cache when the
 * last textured hit had the same name. */
static const struct scene_texture *texture_named(const struct shade_context *sc,
                                                 struct surface_cache *c, uint32_t name)
{
    if (c && c->named == name)
        return c->named_tex;
    const struct scene_texture *tex = scene_textures_lookup(sc->textures, name);
    if (c) {
        c->named = name;
        c->named_tex = tex;
    }
    return tex;
}

/* What the lookup of texture `name` at a hit needs, into t; with `now`
 * the level of detail too (t->lod stays 0), else t->lod says it is still
 * to compute from t's copy of the triangle part (texture_lods). */
SURFACE_INLINE void texture_begin(const struct shade_context *sc, struct surface_cache *cache,
                                  const struct scene_instance *inst, const struct scene_mesh *mesh,
                                  uint32_t prim, const uint32_t v[3], float b0, float b1, float b2,
                                  const float ng[3], const float dir[3], float width,
                                  uint32_t name, int now, struct surface_texture *t)
{
    const struct scene_texture *tex = texture_named(sc, cache, name);
    t->tex = NULL;
    t->lod = 0;
    if (!tex || !tex->texels)
        return;
    t->tex = tex;
    t->lambda = -INFINITY; /* a magnification */
    const float *const vst[3] = {&mesh->texcoords[2 * v[0]], &mesh->texcoords[2 * v[1]],
                                 &mesh->texcoords[2 * v[2]]};
    float lod_st[3][2];
    const float *lst[3] = {vst[0], vst[1], vst[2]};
    if (mesh->texcoord_q) {
        /* rtTexCoord4: s / q, t / q (q = 1 everywhere else, unchanged). */
        const float q[3] = {mesh->texcoord_q[v[0]], mesh->texcoord_q[v[1]],
                            mesh->texcoord_q[v[2]]};
        projective_st(vst, q, b0, b1, b2, t->st, lod_st);
        for (int i = 0; i < 3; i++)
            lst[i] = lod_st[i];
    } else {
        interpolate(mesh->texcoords, 2, v, b0, b1, b2, 2, t->st);
    }
    if (tex->min_filter != tex->mag_filter) {
        struct surface_cache scratch;
        const struct surface_lod *tri =
            lod_triangle(cache, tex, inst, mesh, prim, v, lst, &scratch);
        if (now) {
            /* texture_lambda's operations on the same values, without
             * the copy of the triangle part into t. */
            t->lambda = lod_ray(tri, tex->level_count, ng, dir, width);
            return;
        }
        t->tri = *tri;
        t->lodp = &t->tri;
        memcpy(t->ng, ng, sizeof(t->ng));
        memcpy(t->dir, dir, sizeof(t->dir));
        t->width = width;
        t->lod = 1;
    }
}

static void texture_end(const struct surface_texture *t, float ambient[4], float diffuse[4])
{
    if (!t->tex)
        return;
    float texel[4];
    scene_texture_sample_lod(t->tex, t->lambda, t->st[0], t->st[1], texel);
    for (int k = 0; k < 3; k++) {
        ambient[k] *= texel[k];
        diffuse[k] *= texel[k];
    }
}

#if defined(SURFACE_QUADS)
/* texture_end of TRACE_PACKET hits on one texture, their lookups in the
 * eight lanes (scene_texture_sample_lod8: the same texels) and the
 * products as texture_end's; 0, having changed nothing, when the hits
 * are not all on one texture or the sampler leaves the block to
 * texture_end. */
static int texture_end8(const struct surface_texture t[], float *const ambient[],
                        float *const diffuse[])
{
    const struct scene_texture *tex = t[0].tex;
    if (!tex)
        return 0;
    float lambda[TRACE_PACKET], s[TRACE_PACKET], tc[TRACE_PACKET];
    for (int i = 0; i < TRACE_PACKET; i++) {
        if (t[i].tex != tex)
            return 0;
        lambda[i] = t[i].lambda;
        s[i] = t[i].st[0];
        tc[i] = t[i].st[1];
    }
    float rgb[3][TRACE_PACKET];
    if (!scene_texture_sample_lod8(tex, lambda, s, tc, rgb))
        return 0;
    for (int i = 0; i < TRACE_PACKET; i++)
        for (int k = 0; k < 3; k++) {
            ambient[i][k] *= rgb[k][i];
            diffuse[i][k] *= rgb[k][i];
        }
    return 1;
}
#endif

static void apply_texture(const struct shade_context *sc, struct surface_cache *cache,
                          const struct scene_instance *inst,
                          const struct scene_mesh *mesh, uint32_t prim, const uint32_t v[3],
                          float b0, float b1, float b2, const float ng[3], const float dir[3],
                          float width, uint32_t name, float ambient[4], float diffuse[4])
{
    struct surface_texture t;
    texture_begin(sc, cache, inst, mesh, prim, v, b0, b1, b2, ng, dir, width, name, 1, &t);
    if (t.lod)
        texture_lambda(&t);
    texture_end(&t, ambient, diffuse);
}

void surface_resolve_material(const struct scene_appearance *call, struct scene_material *m)
{
    uint32_t k = m->inherit;
    if (!k)
        return;
    /* Recorded in a list before it set these properties: the material
     * current at the call (its instance's), as GL. */
    const struct scene_material *c = &call->material;
    if (k & SCENE_MATERIAL_AMBIENT)
        memcpy(m->ambient, c->ambient, sizeof(m->ambient));
    if (k & SCENE_MATERIAL_DIFFUSE)
        memcpy(m->diffuse, c->diffuse, sizeof(m->diffuse));
    if (k & SCENE_MATERIAL_SPECULAR)
        memcpy(m->specular, c->specular, sizeof(m->specular));
    if (k & SCENE_MATERIAL_EMISSION)
        memcpy(m->emission, c->emission, sizeof(m->emission));
    if (k & SCENE_MATERIAL_SHININESS)
        m->shininess = c->shininess;
    if (k & SCENE_MATERIAL_REFLECTIVITY)
        m->reflectivity = c->reflectivity;
    if (k & SCENE_MATERIAL_TRANSPARENCY)
        m->transparency = c->transparency;
    if (k & SCENE_MATERIAL_IOR)
        m->ior = c->ior;
    const uint32_t back = k >> SCENE_MATERIAL_BACK_SHIFT;
    if (back & SCENE_MATERIAL_AMBIENT)
        memcpy(m->back_ambient, c->back_ambient, sizeof(m->back_ambient));
    if (back & SCENE_MATERIAL_DIFFUSE)
        memcpy(m->back_diffuse, c->back_diffuse, sizeof(m->back_diffuse));
    if (back & SCENE_MATERIAL_SPECULAR)
        memcpy(m->back_specular, c->back_specular, sizeof(m->back_specular));
    if (back & SCENE_MATERIAL_EMISSION)
        memcpy(m->back_emission, c->back_emission, sizeof(m->back_emission));
    if (back & SCENE_MATERIAL_SHININESS)
        m->back_shininess = c->back_shininess;
    if (k & SCENE_MATERIAL_LIGHTING)
        m->lighting = c->lighting;
    /* The rest of GL's per-primitive state (mesh.h).  The cull enable and
     * rtCullFace's mode may come from different places. */
    if (k & (SCENE_MATERIAL_CULL_ENABLE | SCENE_MATERIAL_CULL_MODE)) {
        int on = (k & SCENE_MATERIAL_CULL_ENABLE) ? c->cull_face != SCENE_CULL_NONE
                                                  : m->cull_face != SCENE_CULL_NONE;
        if (k & SCENE_MATERIAL_CULL_MODE)
            m->cull_mode = c->cull_mode;
        m->cull_face = on ? (uint8_t)m->cull_mode : (uint8_t)SCENE_CULL_NONE;
    }
    if (k & SCENE_MATERIAL_FRONT_FACE)
        m->front_cw = c->front_cw;
    if (k & SCENE_MATERIAL_COLOR_MATERIAL_MODE) {
        m->color_material_face = c->color_material_face;
        m->color_material_mode = c->color_material_mode;
    }
    if (k & (SCENE_MATERIAL_TEXTURE | SCENE_MATERIAL_TEXTURE_ENABLE)) {
        uint32_t bound = (k & SCENE_MATERIAL_TEXTURE) ? c->texture_bound : m->texture_bound;
        uint32_t on = (k & SCENE_MATERIAL_TEXTURE_ENABLE) ? c->texture_enabled : m->texture_enabled;
        m->texture = on ? bound : 0;
    }
    /* The environment and generation matter to textured triangles only:
     * an untextured hit copies nothing more. */
    if (m->texture) {
        if (k & SCENE_MATERIAL_TEX_ENV) {
            m->tex_env_mode = c->tex_env_mode;
            memcpy(m->tex_env_color, c->tex_env_color, sizeof(m->tex_env_color));
        }
        /* Planes are zero while generation is off (rt_sync_fixed_function):
         * nothing to copy when neither side generates, the common case. */
        if ((k & SCENE_MATERIAL_TEXGEN) &&
            (c->texgen_mode[0] | c->texgen_mode[1] | c->texgen_mode[2] | m->texgen_mode[0] |
             m->texgen_mode[1] | m->texgen_mode[2])) {
            memcpy(m->texgen_mode, c->texgen_mode, sizeof(m->texgen_mode));
            memcpy(m->texgen_object_plane, c->texgen_object_plane, sizeof(m->texgen_object_plane));
            memcpy(m->texgen_eye_plane, c->texgen_eye_plane, sizeof(m->texgen_eye_plane));
        }
    }
    if (k & SCENE_MATERIAL_NORMALIZE)
        m->normalize = c->normalize;
    if (k & SCENE_MATERIAL_POLYGON_MODE_FRONT)
        m->polygon_mode[0] = c->polygon_mode[0];
    if (k & SCENE_MATERIAL_POLYGON_MODE_BACK)
        m->polygon_mode[1] = c->polygon_mode[1];
    m->inherit = 0;
}

/* The texture name of material m as resolved under the call's material
 * (surface_resolve_material's rule: the bound name and the enable each
 * from where the list takes it). */
SURFACE_INLINE uint32_t material_texture(const struct scene_material *m,
                                         const struct scene_material *call)
{
    const uint32_t k = m->inherit;
    if (!(k & (SCENE_MATERIAL_TEXTURE | SCENE_MATERIAL_TEXTURE_ENABLE)))
        return m->texture;
    const uint32_t bound = (k & SCENE_MATERIAL_TEXTURE) ? call->texture_bound : m->texture_bound;
    const uint32_t on =
        (k & SCENE_MATERIAL_TEXTURE_ENABLE) ? call->texture_enabled : m->texture_enabled;
    return on ? bound : 0;
}

/* The triangle of a hit and what its barycentrics and flags say. */
struct hit_triangle {
    const struct scene_instance *inst;
    const struct scene_mesh *mesh;
    const uint32_t *v;
    float b0, b1, b2;
    uint8_t flags; /* TRI_FLAT as inherited from the call */
    uint32_t provoking;
};

SURFACE_INLINE void hit_triangle(const struct shade_context *sc,
                                 const struct trace_scene_hit *hit, struct hit_triangle *t)
{
    t->inst = shade_hit_instance(sc, hit);
    t->mesh = &t->inst->object->mesh;
    t->v = &t->mesh->indices[3 * hit->prim];
    t->b1 = hit->u;
    t->b2 = hit->v;
    t->b0 = 1.0f - hit->u - hit->v;
    uint8_t flags = t->mesh->tri_flags[hit->prim];
    if (flags & TRI_INHERIT_SHADE) /* the shade model at the call (frame.h) */
        flags = (uint8_t)((flags & ~TRI_FLAT) | (t->inst->appearance.flat ? TRI_FLAT : 0u));
    t->flags = flags;
    t->provoking = t->mesh->tri_provoking[hit->prim];
}

/* The triangle's unit geometric normal in world space (recorded
 * winding) into ng, from the tile's cache when the last hit was on the
 * same triangle (surface_cache; `c` is triangle_cache's entry or NULL);
 * 0 when it is degenerate (a sliver too thin for float). */
SURFACE_INLINE int triangle_normal(struct surface_cache *c, const struct hit_triangle *t,
                                   float ng[3])
{
    if (c && c->normal) {
        memcpy(ng, c->ng, sizeof(c->ng));
        return c->normal > 0;
    }
    const struct scene_mesh *mesh = t->mesh;
    const uint32_t *v = t->v;
    const float *p0 = &mesh->positions[3 * v[0]];
    const float *p1 = &mesh->positions[3 * v[1]];
    const float *p2 = &mesh->positions[3 * v[2]];
    float e1[3], e2[3], ngo[3];
    vec3_sub(e1, p1, p0);
    vec3_sub(e2, p2, p0);
    vec3_cross(ngo, e1, e2);
    transform_normal(t->inst->normal_to_world, ngo, ng);
    const int unit = vec3_normalize(ng) != 0;
    if (c) {
        memcpy(c->ng, ng, sizeof(c->ng));
        c->normal = unit ? 1 : -1;
    }
    return unit;
}

/* The shading normal n at the hit (t's barycentrics) on the side of the
 * unit geometric normal ng (already facing the ray); ng itself without
 * vertex normals or where the interpolated one does not normalise. */
SURFACE_INLINE void shading_normal(const struct hit_triangle *t, const float ng[3], float n[3])
{
    const struct scene_mesh *mesh = t->mesh;
    memcpy(n, ng, 3 * sizeof(float));
    if (mesh->has_normals) {
        float no[3];
        if (t->flags & TRI_FLAT)
            memcpy(no, &mesh->normals[3 * t->provoking], sizeof(no));
        else
            interpolate(mesh->normals, 3, t->v, t->b0, t->b1, t->b2, 3, no);
        float nw[3];
        transform_normal(t->inst->normal_to_world, no, nw);
        if (vec3_normalize(nw)) {
            if (vec3_dot(nw, ng) < 0.0f)
                for (int k = 0; k < 3; k++)
                    nw[k] = -nw[k];
            memcpy(n, nw, 3 * sizeof(float));
        }
    }
}

/* The unit geometric normal ng (unit: whether triangle_normal gave one)
 * turned to face the ray along dir, and whether the ray hit the front
 * face. */
SURFACE_INLINE void facing_normal(int unit, const float dir[3], float ng[3], int *front)
{
    if (!unit) {
        /* Sliver too thin for float: any unit vector facing the ray. */
        ng[0] = -dir[0];
        ng[1] = -dir[1];
        ng[2] = -dir[2];
        vec3_normalize(ng);
    }
    *front = vec3_dot(ng, dir) < 0.0f;
    if (!*front)
        for (int k = 0; k < 3; k++)
            ng[k] = -ng[k];
}

/* The unit geometric normal facing the ray along dir, whether the ray
 * hit the front face, and the shading normal on the same side.  Inlined:
 * the call's spills and argument set-up were a tenth of its cost. */
SURFACE_INLINE void hit_normals(struct surface_cache *cache, const struct hit_triangle *t,
                                uint32_t prim, const float dir[3], float ng[3], float n[3],
                                int *front)
{
    const int unit = triangle_normal(triangle_cache(cache, t->inst, prim), t, ng);
    facing_normal(unit, dir, ng, front);
    shading_normal(t, ng, n);
}

/* The vertex colour RT_COLOR_MATERIAL puts into the ambient and diffuse
 * material, when it is on for the triangle (as recorded or as at the
 * call) or the primitive is unlit (`unlit`, see surface_fetch); 0 when
 * neither. */
SURFACE_INLINE int color_material_on(const struct hit_triangle *t, int unlit)
{
    const uint8_t flags = t->flags;
    int color_material = (flags & TRI_INHERIT_COLOR_MATERIAL)
                             ? t->inst->appearance.color_material
                             : (flags & TRI_COLOR_MATERIAL) != 0;
    return color_material || unlit;
}

SURFACE_INLINE int hit_color_material(const struct hit_triangle *t, int unlit, float c[4])
{
    const uint8_t flags = t->flags;
    if (!color_material_on(t, unlit))
        return 0;
    if (flags & TRI_INHERIT_COLOR)
        memcpy(c, t->inst->appearance.color, 4 * sizeof(float)); /* the colour at the call */
    else if (flags & TRI_FLAT)
        memcpy(c, &t->mesh->colors[4 * t->provoking], 4 * sizeof(float));
    else
        interpolate(t->mesh->colors, 4, t->v, t->b0, t->b1, t->b2, 4, c);
    return 1;
}

/* Whether a primitive drawn with RT_LIGHTING `lighting` shows its own
 * colour unlit (see hit_colours). */
SURFACE_INLINE int hit_unlit(const struct shade_context *sc, int lighting)
{
    return sc->state->lighting_used && !lighting && sc->state->shading != RENDER_FIXED_FUNCTION;
}

/* A hit's ambient and diffuse colours: the vertex colour where
 * hit_color_material gives it (the primitive unlit in the eye-light and
 * Whitted modes, render_state.lighting_used, shade.c: it shows its
 * colour, which the ambient and diffuse material carry from here on, as
 * under RT_COLOR_MATERIAL, so that the texture modulates it and blending
 * takes its alpha), else the material's, the call's where the list
 * inherits them (as surface_resolve_material). */
SURFACE_INLINE void hit_colours(const struct shade_context *sc, const struct hit_triangle *t,
                                const struct scene_material *m,
                                const struct scene_material *call, int lighting,
                                float ambient[4], float diffuse[4])
{
    const uint32_t k = m->inherit;
    if (hit_color_material(t, hit_unlit(sc, lighting), ambient)) {
        memcpy(diffuse, ambient, 4 * sizeof(float));
    } else {
        memcpy(ambient, (k & SCENE_MATERIAL_AMBIENT) ? call->ambient : m->ambient,
               4 * sizeof(float));
        memcpy(diffuse, (k & SCENE_MATERIAL_DIFFUSE) ? call->diffuse : m->diffuse,
               4 * sizeof(float));
    }
}

/* surface_fetch up to the texture: with `now` the texture applied, else
 * what its lookup needs in tx (its level of detail still to compute when
 * tx->lod) for texture_end. */
SURFACE_INLINE void fetch_begin(const struct shade_context *sc, const struct trace_scene_hit *hit,
                                const float dir[3], float width, int depth, struct surface *s,
                                int now, struct surface_texture *tx)
{
    /* The cache of the hit's depth: a tile's pixels take turns at every
     * depth, so one cache for all held the last pixel's deepest hit. */
    struct surface_cache *cache =
        sc->cache ? &sc->cache[depth < SHADE_CACHES ? depth : SHADE_CACHES - 1] : NULL;
    struct hit_triangle t;
    hit_triangle(sc, hit, &t);
    const struct scene_instance *inst = t.inst;
    const struct scene_mesh *mesh = t.mesh;
    const uint32_t *v = t.v;

    const float *p0 = &mesh->positions[3 * v[0]];
    const float *p1 = &mesh->positions[3 * v[1]];
    const float *p2 = &mesh->positions[3 * v[2]];

    /* The hit point is p0 + u (p1 - p0) + v (p2 - p0) evaluated in double
     * (the float differences are exact there), so it lies on the plane of
     * the float triangle to double precision wherever the barycentrics
     * land, and is then mapped to world space in double.  Its only
     * significant error is the final rounding to float, plus the rounding
     * of the next ray's origin into object space: together at most half an
     * ulp of each (PBRT 3rd ed. sec. 3.9 bounds the hit point the same way
     * and offsets secondary rays by that bound along the normal). */
    double po[3], pw[3];
    double max_object = 0.0, max_world = 0.0, norm = 0.0;
    for (int k = 0; k < 3; k++) {
        po[k] = (double)p0[k] + (double)hit->u * ((double)p1[k] - (double)p0[k]) +
                (double)hit->v * ((double)p2[k] - (double)p0[k]);
        max_object = mat4_fmax_left(max_object, fabs(po[k]));
    }
    mat4_transform_point(inst->object_to_world, po, pw);
    for (int k = 0; k < 3; k++) {
        s->p[k] = (float)pw[k];
        max_world = mat4_fmax_left(max_world, fabs(pw[k]));
        const double *m = inst->object_to_world;
        norm = mat4_fmax_left(norm, fabs(m[k]) + fabs(m[4 + k]) + fabs(m[8 + k]));
    }
    s->p_error = (float)(0.5 * FLT_EPSILON * (max_world + norm * max_object) + FLT_MIN);
    hit_normals(cache, &t, hit->prim, dir, s->ng, s->n, &s->front);

    /* The material's properties one by one, as surface_resolve_material
     * resolves them: the call's (the instance's) where the list inherits
     * them, else the recorded ones. */
    const struct scene_material *m = &mesh->materials[mesh->tri_material[hit->prim]];
    const struct scene_material *call = &inst->appearance.material;
    const uint32_t k = m->inherit;
    memcpy(s->emission, (k & SCENE_MATERIAL_EMISSION) ? call->emission : m->emission,
           sizeof(s->emission));
    memcpy(s->specular, (k & SCENE_MATERIAL_SPECULAR) ? call->specular : m->specular,
           sizeof(s->specular));
    s->shininess = (k & SCENE_MATERIAL_SHININESS) ? call->shininess : m->shininess;
    s->reflectivity = (k & SCENE_MATERIAL_REFLECTIVITY) ? call->reflectivity : m->reflectivity;
    s->transparency = (k & SCENE_MATERIAL_TRANSPARENCY) ? call->transparency : m->transparency;
    s->ior = (k & SCENE_MATERIAL_IOR) ? call->ior : m->ior;
    s->lighting = (k & SCENE_MATERIAL_LIGHTING) ? call->lighting : m->lighting;
    const uint32_t texture = material_texture(m, call);
    hit_colours(sc, &t, m, call, s->lighting, s->ambient, s->diffuse);
    tx->tex = NULL;
    tx->lod = 0;
    if (!texture)
        return;
    if (now)
        apply_texture(sc, cache, inst, mesh, hit->prim, v, t.b0, t.b1, t.b2, s->ng, dir, width,
                      texture, s->ambient, s->diffuse);
    else
        texture_begin(sc, cache, inst, mesh, hit->prim, v, t.b0, t.b1, t.b2, s->ng, dir, width,
                      texture, 0, tx);
}

void surface_fetch(const struct shade_context *sc, const struct trace_scene_hit *hit,
                   const float dir[3], float width, int depth, struct surface *s)
{
    struct surface_texture tx;
    fetch_begin(sc, hit, dir, width, depth, s, 1, &tx);
}

void surface_fetches(const struct shade_context *sc, int n,
                     const struct trace_scene_hit *const hits[], const float *const dir[],
                     const float width[], int depth, struct surface *const s[])
{
    struct surface_texture tex[TRACE_PACKET];
    struct surface_texture *lod[TRACE_PACKET] = {NULL}; /* lods of them set */
    int lods = 0;
    for (int i = 0; i < n; i++) {
        fetch_begin(sc, hits[i], dir[i], width[i], depth, s[i], 0, &tex[i]);
        if (tex[i].lod)
            lod[lods++] = &tex[i];
    }
    texture_lods(lod, lods);
#if defined(SURFACE_QUADS)
    if (n == TRACE_PACKET) {
        float *ambient[TRACE_PACKET], *diffuse[TRACE_PACKET];
        for (int i = 0; i < TRACE_PACKET; i++) {
            ambient[i] = s[i]->ambient;
            diffuse[i] = s[i]->diffuse;
        }
        if (texture_end8(tex, ambient, diffuse))
            return;
    }
#endif
    for (int i = 0; i < n; i++)
        texture_end(&tex[i], s[i]->ambient, s[i]->diffuse);
}

/*
 * surface_fetch's normals and colours without the hit point, and of the
 * material only what the eye light reads: a hit there used to copy the
 * whole recorded material (some 260 bytes) and resolve every inherited
 * property of it, the largest part of the frame's cost besides tracing.
 * The same operations on the same values as surface_fetch and
 * surface_resolve_material, so the same colours bit for bit.
 */
SURFACE_INLINE void fetch_colour_begin(const struct shade_context *sc,
                                       const struct trace_scene_hit *hit, const float dir[3],
                                       float width, struct surface_colour *s,
                                       struct surface_texture *tx)
{
    struct hit_triangle t;
    hit_triangle(sc, hit, &t);
    hit_normals(sc->cache, &t, hit->prim, dir, s->ng, s->n, &s->front);
    const struct scene_material *m = &t.mesh->materials[t.mesh->tri_material[hit->prim]];
    const struct scene_material *call = &t.inst->appearance.material;
    const uint32_t k = m->inherit;
    memcpy(s->emission, (k & SCENE_MATERIAL_EMISSION) ? call->emission : m->emission,
           sizeof(s->emission));
    const uint32_t texture = material_texture(m, call);
    s->lighting = (k & SCENE_MATERIAL_LIGHTING) ? call->lighting : m->lighting;
    hit_colours(sc, &t, m, call, s->lighting, s->ambient, s->diffuse);
    tx->tex = NULL;
    tx->lod = 0;
    if (texture)
        texture_begin(sc, sc->cache, t.inst, t.mesh, hit->prim, t.v, t.b0, t.b1, t.b2, s->ng,
                      dir, width, texture, 0, tx);
}

void surface_fetch_colour(const struct shade_context *sc, const struct trace_scene_hit *hit,
                          const float dir[3], float width, struct surface_colour *s)
{
    struct surface_texture t;
    fetch_colour_begin(sc, hit, dir, width, s, &t);
    if (t.lod)
        texture_lambda(&t);
    texture_end(&t, s->ambient, s->diffuse);
}

#if defined(SURFACE_QUADS)
/* interpolate's (b0 x0 + b1 x1) + b2 x2 of one component, x broadcast. */
#define LANES_INTERPOLATE(x0, x1, x2)                                                             \
    _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(b0, _mm256_set1_ps(x0)),                            \
                                _mm256_mul_ps(b1, _mm256_set1_ps(x1))),                           \
                  _mm256_mul_ps(b2, _mm256_set1_ps(x2)))

/* transform_normal in double, four lanes at a time: the object-space
 * normals no through the matrix mt into nw. */
SURFACE_INLINE void lanes_transform_normal(const double *mt, const __m256 no[3], __m256 nw[3])
{
    for (int r = 0; r < 3; r++) {
        __m128 half[2];
        for (int h = 0; h < 2; h++) {
            __m256d x[3];
            for (int k = 0; k < 3; k++)
                x[k] = _mm256_cvtps_pd(h ? _mm256_extractf128_ps(no[k], 1)
                                         : _mm256_castps256_ps128(no[k]));
            half[h] = _mm256_cvtpd_ps(_mm256_add_pd(
                _mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(mt[r]), x[0]),
                              _mm256_mul_pd(_mm256_set1_pd(mt[4 + r]), x[1])),
                _mm256_mul_pd(_mm256_set1_pd(mt[8 + r]), x[2])));
        }
        nw[r] = _mm256_insertf128_ps(_mm256_castps128_ps256(half[0]), half[1], 1);
    }
}

/* Whether the upper-left 3 x 3 of the column-major matrix m is the
 * identity bit for bit (a -0.0 is not 0.0 here: its products differ in
 * the sign of zero). */
SURFACE_INLINE int lanes_identity3(const double *m)
{
    int same = 7;
    for (int c = 0; c < 3; c++) {
        const __m256i col = _mm256_loadu_si256((const __m256i *)(const void *)(m + 4 * c));
        const __m256i unit = _mm256_castpd_si256(
            _mm256_set_pd(0.0, c == 2 ? 1.0 : 0.0, c == 1 ? 1.0 : 0.0, c == 0 ? 1.0 : 0.0));
        same &= _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpeq_epi64(col, unit)));
    }
    return same == 7;
}

/* shading_normal's end in the lanes: the object-space normals no
 * through the matrix mt, normalised, turned to the side of the facing
 * geometric normals g, into nv where they normalise (nv keeps g
 * elsewhere), each lane the scalar operations in their order. */
SURFACE_INLINE void lanes_shading_normal(const double *mt, const __m256 no[3], const __m256 g[3],
                                         __m256 nv[3])
{
    const __m256 sign = _mm256_set1_ps(-0.0f);
    __m256 nw[3];
    if (lanes_identity3(mt)) {
        /* transform_normal by the identity (the instance not turned or
         * scaled: every BART kitchen instance) in float: each product is
         * a component times 1 or 0, exact in float as in double, and each
         * sum adds a signed zero (or, where a component is infinite or
         * NaN, gives NaN), exact too with the same sign rules, so the
         * double sum is a float and its conversion changes nothing: the
         * same floats in the same order, or a non-finite value in the
         * same component (the normal then fails the length test below
         * either way, which all that follows reads). */
        const __m256 one = _mm256_set1_ps(1.0f), zero = _mm256_setzero_ps();
        for (int r = 0; r < 3; r++)
            nw[r] = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(no[0], r == 0 ? one : zero),
                                                _mm256_mul_ps(no[1], r == 1 ? one : zero)),
                                  _mm256_mul_ps(no[2], r == 2 ? one : zero));
    } else
        lanes_transform_normal(mt, no, nw);
    /* vec3_normalize: a length that is positive and finite (not
     * above FLT_MAX; NaN fails both) scales by 1 / len, else the
     * geometric normal stays. */
    const __m256 len = _mm256_sqrt_ps(lanes_dot8(nw, nw));
    const __m256 unit =
        _mm256_and_ps(_mm256_cmp_ps(len, _mm256_setzero_ps(), _CMP_GT_OQ),
                      _mm256_cmp_ps(len, _mm256_set1_ps(FLT_MAX), _CMP_LE_OQ));
    const __m256 inv = _mm256_div_ps(_mm256_set1_ps(1.0f), len);
    for (int k = 0; k < 3; k++)
        nw[k] = _mm256_mul_ps(nw[k], inv);
    const __m256 away = _mm256_and_ps(
        _mm256_cmp_ps(lanes_dot8(nw, g), _mm256_setzero_ps(), _CMP_LT_OQ), sign);
    for (int k = 0; k < 3; k++)
        nv[k] = _mm256_blendv_ps(g[k], _mm256_xor_ps(nw[k], away), unit);
}

/* n vectors of TRACE_PACKET floats from x on set to zero. */
SURFACE_INLINE void lanes_zero(float *x, int n)
{
    for (int i = 0; i < n; i++)
        _mm256_storeu_ps(x + TRACE_PACKET * i, _mm256_setzero_ps());
}

#if defined(SURFACE_OCTS)
/* n vectors of TRACE_PACKET doubles from x on set to zero. */
SURFACE_INLINE void lanes_zero_pd(double *x, int n)
{
    for (int i = 0; i < n; i++)
        _mm512_storeu_pd(x + TRACE_PACKET * i, _mm512_setzero_pd());
}
#endif

/* Lane i of the result is the first lane j <= i with p[j] == p[i]: the
 * lanes j = i - 1 down to 0 compared with lane i, each in one permute and
 * compare of all lanes (the lanes i < k masked off in step k), the last
 * equal one kept.  No branch, whatever the values. */
SURFACE_INLINE __m256i lanes_first_equal(__m256i p)
{
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    __m256i first = lane;
    for (int k = 1; k < TRACE_PACKET; k++) {
        const __m256i back = _mm256_sub_epi32(lane, _mm256_set1_epi32(k)); /* i - k */
        const __m256i eq = _mm256_andnot_si256(_mm256_srai_epi32(back, 31),
                                               _mm256_cmpeq_epi32(p, _mm256_permutevar8x32_epi32(
                                                                         p, back)));
        first = _mm256_blendv_epi8(first, back, eq);
    }
    return first;
}

/* Lane i of the result is per_slot[slots[i]] (slots in 0..7): a float
 * moved, not computed. */
SURFACE_INLINE __m256 lanes_by_slot(const float per_slot[TRACE_PACKET], __m256i slots)
{
    return _mm256_permutevar8x32_ps(_mm256_loadu_ps(per_slot), slots);
}

/* interpolate's (b0 x0 + b1 x1) + b2 x2 of one component, x[j] taken
 * lane by lane from the lane's triangle slot (x[j][s]: vertex j of the
 * triangle in slot s; lanes_by_slot). */
SURFACE_INLINE __m256 lanes_interpolate_slots(__m256 b0, __m256 b1, __m256 b2,
                                              const float x[3][TRACE_PACKET], __m256i slots)
{
    return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(b0, lanes_by_slot(x[0], slots)),
                                       _mm256_mul_ps(b1, lanes_by_slot(x[1], slots))),
                         _mm256_mul_ps(b2, lanes_by_slot(x[2], slots)));
}

/* facing_normal in the lanes: front = ng . dir < 0, the back face's ng
 * negated (a sign flip, the same floats). */
static inline void lanes_facing(__m256 g[3], const __m256 dv[3])
{
    const __m256 front = _mm256_cmp_ps(lanes_dot8(g, dv), _mm256_setzero_ps(), _CMP_LT_OQ);
    const __m256 flip = _mm256_andnot_ps(front, _mm256_set1_ps(-0.0f));
    for (int k = 0; k < 3; k++)
        g[k] = _mm256_xor_ps(g[k], flip);
}

/* The material properties a lane pass needs, as fetch_colour_begin
 * resolves them (the call's where the list inherits them, else the
 * recorded ones): the emission and lighting in *emission and *lighting;
 * returns the texture with texels, or NULL for none. */
static inline const struct scene_texture *lanes_material(const struct shade_context *sc,
                                                         const struct scene_material *m,
                                                         const struct scene_material *call,
                                                         const float **emission, int *lighting)
{
    const uint32_t inherit = m->inherit;
    *emission = (inherit & SCENE_MATERIAL_EMISSION) ? call->emission : m->emission;
    *lighting = (inherit & SCENE_MATERIAL_LIGHTING) ? call->lighting : m->lighting;
    const uint32_t texture = material_texture(m, call);
    if (!texture)
        return NULL;
    const struct scene_texture *tx = texture_named(sc, sc->cache, texture);
    return tx && tx->texels ? tx : NULL;
}

/* A block's ambient and diffuse colours in amb and dif: t's (the
 * material's, hit_colours) broadcast when they cannot vary by hit, else
 * hit by hit into out's arrays and loaded from there.  Hit i's triangle
 * is t with hit i's barycentrics (hit_triangle's 1 - u - v), or with
 * each_triangle hit_triangle of hit i itself (its own triangle). */
static inline void lanes_colours(const struct shade_context *sc, const struct hit_triangle *t,
                                 const struct trace_scene_hit *const hits[], int vary,
                                 int each_triangle, const struct scene_material *m,
                                 const struct scene_material *call, int lighting,
                                 struct surface_lanes *out, __m256 amb[3], __m256 dif[3])
{
    if (!vary) {
        float ambient[4], diffuse[4];
        hit_colours(sc, t, m, call, lighting, ambient, diffuse);
        for (int k = 0; k < 3; k++) {
            amb[k] = _mm256_set1_ps(ambient[k]);
            dif[k] = _mm256_set1_ps(diffuse[k]);
        }
        return;
    }
    for (int i = 0; i < TRACE_PACKET; i++) {
        float ambient[4], diffuse[4];
        struct hit_triangle ti = *t;
        if (each_triangle) {
            hit_triangle(sc, hits[i], &ti);
        } else {
            ti.b1 = hits[i]->u;
            ti.b2 = hits[i]->v;
            ti.b0 = 1.0f - hits[i]->u - hits[i]->v;
        }
        hit_colours(sc, &ti, m, call, lighting, ambient, diffuse);
        for (int k = 0; k < 3; k++) {
            out->ambient[k][i] = ambient[k];
            out->diffuse[k][i] = diffuse[k];
        }
    }
    for (int k = 0; k < 3; k++) {
        amb[k] = _mm256_loadu_ps(out->ambient[k]);
        dif[k] = _mm256_loadu_ps(out->diffuse[k]);
    }
}

/* texture_end of a block's lanes: the texels at the lanes' levels of
 * detail (the 8-lane sampler when it takes the block, else lane by lane)
 * times the ambient and diffuse colours; a product is the same in either
 * order.  Shared by surface_fetch_lanes and fetch_lanes_mixed.  With
 * `defer` the 8-lane sampler's lookups are only prepared in *defer
 * (scene_texture_prefetch_lod8) and 1 returned, amb and dif left as
 * they are: the caller multiplies them by scene_texture_finish_lod8's
 * colours later (the same products on the same floats); 0 when the
 * colours are done. */
static inline int lanes_texture_end(const struct scene_texture *tx,
                                    const float lambda[TRACE_PACKET],
                                    const float lane_st[2][TRACE_PACKET], __m256 amb[3],
                                    __m256 dif[3], struct scene_texture_lookup8 *defer)
{
    if (defer && scene_texture_prefetch_lod8(tx, lambda, lane_st[0], lane_st[1], defer))
        return 1;
    float rgb[3][TRACE_PACKET];
    if (!scene_texture_sample_lod8(tx, lambda, lane_st[0], lane_st[1], rgb)) {
        for (int i = 0; i < TRACE_PACKET; i++) {
            float texel[4];
            scene_texture_sample_lod(tx, lambda[i], lane_st[0][i], lane_st[1][i], texel);
            for (int k = 0; k < 3; k++)
                rgb[k][i] = texel[k];
        }
    }
    for (int k = 0; k < 3; k++) {
        const __m256 texel = _mm256_loadu_ps(rgb[k]);
        amb[k] = _mm256_mul_ps(amb[k], texel);
        dif[k] = _mm256_mul_ps(dif[k], texel);
    }
    return 0;
}

/* The eye light's block paths' cache entry for primitive prim: the
 * worker's SHADE_EYE_CACHES entries (shade_context.eye), or without them
 * the tile's SHADE_CACHES entries (one per Whitted depth, which an
 * eye-light frame does not have), direct-mapped by the primitive's low
 * bits, so that the two or three triangles of a block on an edge, the
 * neighbouring blocks' triangles and the neighbouring tiles' stay in the
 * cache together instead of taking one entry in turns.  An entry holds
 * the values the computation gives (surface_cache), whichever entry, tile
 * or worker computed them, so this changes no value, only what is
 * computed again. */
static inline struct surface_cache *eye_cache(const struct shade_context *sc, uint32_t prim)
{
    if (sc->eye)
        return &sc->eye[prim % SHADE_EYE_CACHES];
    return &sc->cache[prim % SHADE_CACHES];
}

/* The level-of-detail parts of a block on several triangles in slot
 * order (fetch_lanes_mixed; slot j's in [j]): each distinct triangle's
 * part of its own material's texture, and in the AVX-512 copy its
 * lod_fast values: the part's unit normal, its texel map's rows and bound
 * (lod_fast_init, kept in the triangle's cache entry) and the slots whose
 * map is usable (bit j). */
struct slots_lod {
    struct surface_lod part[TRACE_PACKET];
#if defined(SURFACE_OCTS)
    double n[3][TRACE_PACKET], m[2][3][TRACE_PACKET], sin2[TRACE_PACKET];
    int usable;
#endif
};

/*
 * The levels of detail of texture tx in the lanes of `mine` (a bit a
 * lane) of a block on several triangles (fetch_lanes_mixed): lod_quad_lanes
 * on each quad holding a lane of `mine`, each lane on its own triangle's
 * part (tri->part[slot[lane]]).  A lane outside `mine` takes lane `first`'s
 * part (one of `mine`) in its place, and its lambda is the caller's to
 * drop.  With every lane in `mine` (a constant, folded when inlined) this
 * is the one-material block's loop.  The AVX-512 copy first takes
 * lod_fast_oct_lanes in the lanes of `mine` whose triangle's map is usable
 * (tri->usable), each lane on its own triangle's map, as a one-triangle
 * block of that triangle would (surface_fetch_lanes; a lane off those
 * computes on its slot's values, zeros where the slot has none, and is
 * masked off: no value of it is used), and skips a quad whose lanes of
 * `mine` it all decided; lod_quad_lanes writes a quad's four lambdas again
 * otherwise (the same floats where lod_fast decided: lod_fast's margin
 * proves its lambda lod_ray's, which lod_quad gives).
 */
SURFACE_INLINE void lod_slots_lanes(const struct scene_texture *tx,
                                    const struct slots_lod *tri, const int slot[TRACE_PACKET],
                                    int mine, int first, const __m256 dv[3], const __m256 g[3],
                                    const float width[], const float lane_g[3][TRACE_PACKET],
                                    const float dir[3][TRACE_PACKET], float lambda[TRACE_PACKET])
{
    const double top = lod_top(tx->level_count);
    const __m256 wv = _mm256_loadu_ps(width);
    int fast8 = 0;
#if defined(SURFACE_OCTS)
    int usable = 0;
    for (int i = 0; i < TRACE_PACKET; i++)
        usable |= (tri->usable >> slot[i] & 1) << i;
    usable &= mine;
    if (usable) {
        const __m512i s =
            _mm512_cvtepi32_epi64(_mm256_loadu_si256((const __m256i *)(const void *)slot));
        __m512d n[3], m0[3], m1[3], d8[3], g8[3];
        for (int k = 0; k < 3; k++) {
            n[k] = _mm512_permutexvar_pd(s, _mm512_loadu_pd(tri->n[k]));
            m0[k] = _mm512_permutexvar_pd(s, _mm512_loadu_pd(tri->m[0][k]));
            m1[k] = _mm512_permutexvar_pd(s, _mm512_loadu_pd(tri->m[1][k]));
            d8[k] = _mm512_cvtps_pd(dv[k]);
            g8[k] = _mm512_cvtps_pd(g[k]);
        }
        fast8 = usable & lod_fast_oct_lanes(n, m0, m1,
                                            _mm512_permutexvar_pd(s, _mm512_loadu_pd(tri->sin2)),
                                            d8, g8, _mm512_cvtps_pd(wv),
                                            _mm512_set1_pd(top * top), lambda);
    }
#endif
    for (int h = 0; h < TRACE_PACKET / 4; h++) {
        const int want = mine >> 4 * h & 15;
        if (!want || (fast8 >> 4 * h & 15) == want)
            continue;
        const struct surface_lod *l4[4];
        for (int i = 0; i < 4; i++) {
            const int j = 4 * h + i;
            l4[i] = &tri->part[slot[mine >> j & 1 ? j : first]];
        }
        const int shared = l4[0] == l4[1] && l4[0] == l4[2] && l4[0] == l4[3];
#define HALF(v) _mm256_cvtps_pd(h ? _mm256_extractf128_ps(v, 1) : _mm256_castps256_ps128(v))
        __m256d d[3], gd[3];
        for (int k = 0; k < 3; k++) {
            d[k] = HALF(dv[k]);
            gd[k] = HALF(g[k]);
        }
        lod_quad_lanes(l4, shared, d, gd, HALF(wv), top, tx->level_count, h, width, lane_g, dir,
                       lambda);
#undef HALF
    }
}

/*
 * fetch_lanes_mixed's colours for a block on two materials: lanes in
 * group 1 (other_lane[i] all ones) are on m2's triangles, the rest on
 * the first material's, whose colours amb and dif hold on entry (the
 * material's, lanes_colours without vertex colours).  Group 1's colours
 * (hit_colours of m2, the same for every hit without vertex colours)
 * are blended into its lanes; then each group's texture, where it has
 * one, on that group's lanes: the lanes' texture coordinates, their
 * levels of detail from their own triangle parts (lod_quad_lanes on the
 * quads holding a lane of the group; a lane of the other group takes a
 * triangle part of this group's in its place, and its lambda is
 * dropped), the eight lookups with the other group's lanes given the
 * coordinates and lambda of one of this group's lanes (so that they
 * read lines this group reads; their texels are dropped), and
 * texture_end's products in the group's lanes only.  Each lane of the
 * group gets the operations the per-hit path (fetch_colour_begin,
 * texture_lods, texture_end8 or texture_end) gives its hit, on the same
 * values: the same colours bit for bit.  The lookups are made at once
 * (not deferred in the block pipeline).
 */
static void fetch_lanes_two(const struct shade_context *sc, const struct hit_triangle *t,
                            const float dir[3][TRACE_PACKET], const float width[],
                            const struct scene_material *m2, const struct scene_material *call,
                            int lighting, const struct scene_texture *tx, int lod,
                            const struct scene_texture *tx2, int lod2,
                            const int slot[TRACE_PACKET], const int32_t other_lane[TRACE_PACKET],
                            const float tri_st[2][3][TRACE_PACKET],
                            const struct slots_lod *tri_lod, __m256 b0, __m256 b1,
                            __m256 b2, const __m256 g[3], const __m256 dv[3],
                            const float lane_g[3][TRACE_PACKET], __m256 amb[3], __m256 dif[3])
{
    const __m256 in_other =
        _mm256_castsi256_ps(_mm256_loadu_si256((const __m256i *)(const void *)other_lane));
    {
        float ambient[4], diffuse[4];
        hit_colours(sc, t, m2, call, lighting, ambient, diffuse);
        for (int k = 0; k < 3; k++) {
            amb[k] = _mm256_blendv_ps(amb[k], _mm256_set1_ps(ambient[k]), in_other);
            dif[k] = _mm256_blendv_ps(dif[k], _mm256_set1_ps(diffuse[k]), in_other);
        }
    }
    if (!tx && !tx2)
        return;
    const __m256i slots = _mm256_loadu_si256((const __m256i *)(const void *)slot);
    float lane_st[2][TRACE_PACKET];
    for (int k = 0; k < 2; k++)
        _mm256_storeu_ps(lane_st[k], lanes_interpolate_slots(b0, b1, b2, tri_st[k], slots));
    const int other_mask = _mm256_movemask_ps(in_other);
    for (int group = 0; group < 2; group++) {
        const struct scene_texture *gt = group ? tx2 : tx;
        if (!gt)
            continue;
        const int mine = group ? other_mask : ~other_mask & ((1 << TRACE_PACKET) - 1);
        const int first = __builtin_ctz((unsigned)mine); /* one lane of the group */
        float lambda[TRACE_PACKET];
        for (int i = 0; i < TRACE_PACKET; i++)
            lambda[i] = -INFINITY;
        if (group ? lod2 : lod)
            lod_slots_lanes(gt, tri_lod, slot, mine, first, dv, g, width, lane_g, dir, lambda);
        float gl[TRACE_PACKET], gs[2][TRACE_PACKET];
        for (int i = 0; i < TRACE_PACKET; i++) {
            const int j = mine >> i & 1 ? i : first;
            gl[i] = lambda[j];
            gs[0][i] = lane_st[0][j];
            gs[1][i] = lane_st[1][j];
        }
        /* lanes_texture_end's lookups and products in every lane, kept
         * in the group's. */
        __m256 amb_g[3], dif_g[3];
        for (int k = 0; k < 3; k++) {
            amb_g[k] = amb[k];
            dif_g[k] = dif[k];
        }
        lanes_texture_end(gt, gl, gs, amb_g, dif_g, NULL);
        const __m256 here = group ? in_other : _mm256_xor_ps(in_other, _mm256_castsi256_ps(
                                                                           _mm256_set1_epi32(-1)));
        for (int k = 0; k < 3; k++) {
            amb[k] = _mm256_blendv_ps(amb[k], amb_g[k], here);
            dif[k] = _mm256_blendv_ps(dif[k], dif_g[k], here);
        }
    }
}

/*
 * surface_fetch_lanes of a whole block whose hits are on two to eight
 * triangles of one instance and mesh that share one material and one
 * set of recorded flags (a quarter of a BART kitchen frame's blocks,
 * most of them on the kitchen's small triangles), or two materials of
 * one emission and lighting (fetch_lanes_two, below).  What the per-hit
 * path takes from the instance and the material (the emission, the
 * lighting, the texture and its filters, the material's colours, the
 * flags and what they select) is then the same for every hit, once;
 * what it takes from the triangle (the cached unit normal, the vertex
 * or flat normals, texture coordinates and vertex colours, the triangle
 * part of the level of detail) once per distinct triangle, gathered
 * into each lane from its own triangle.  Each lane then runs
 * fetch_colour_begin's operations in their order on the same values
 * (the cache only saves recomputing a triangle's values, which are the
 * same whenever computed), and the levels of detail are lod_quad on the
 * four lanes' own triangle parts, lod_quad_axes, then lod_ray: the same
 * steps as texture_lods' lod_ray_quad on the per-hit path's copies (in
 * the AVX-512 copy lod_fast first, each lane on its own triangle's texel
 * map, where its margin decides: lod_slots_lanes).  So the same colours
 * bit for bit.  Returns 0 as surface_fetch_lanes.  Measured (zt2, round
 * 64, this Zen 4): lod_fast by lane, the distinct triangles without
 * branches and their vertex lines asked for together took the kitchen
 * eye-light frame from about 70.3 to 68.5 ms (avx512; avx2 75.3 to 73.6).
 */
static int fetch_lanes_mixed(const struct shade_context *sc,
                             const struct trace_scene_hit *const hits[],
                             const float dir[3][TRACE_PACKET], const float width[],
                             struct surface_lanes *out, struct scene_texture_lookup8 *defer)
{
    const struct trace_scene_hit *h0 = hits[0];
    for (int i = 1; i < TRACE_PACKET; i++)
        if (hits[i]->instance != h0->instance)
            return 0;
    struct hit_triangle t;
    hit_triangle(sc, h0, &t);
    const struct scene_mesh *mesh = t.mesh;
    if (mesh->texcoord_q)
        return 0;
    const uint32_t material = mesh->tri_material[h0->prim];
    const uint8_t recorded = mesh->tri_flags[h0->prim];
    /* The distinct triangles: lane i is on the triangle of slot[i], the
     * first lane hitting it (lanes_first_equal), and the slots taken are
     * the lanes `leaders`, in the order of their first hit.  Every lane's
     * recorded flags must be the first's (the same flags after
     * hit_triangle's inheritance: one instance).  The triangles may be of
     * two materials: `material`, that of the first hit, and `other`
     * (group 1: other_lane[i] all ones for lane i), see the second
     * material below.  Tests without branches on the hits, which decide
     * no value: a block is taken or refused as a search of the distinct
     * triangles would. */
    uint32_t prim[TRACE_PACKET], mat[TRACE_PACKET], other = material;
    int slot[TRACE_PACKET], two = 0;
    int32_t other_lane[TRACE_PACKET];
    unsigned flags_differ = 0;
    for (int i = 0; i < TRACE_PACKET; i++) {
        const uint32_t p = hits[i]->prim;
        prim[i] = p;
        mat[i] = mesh->tri_material[p];
        flags_differ |= mesh->tri_flags[p] ^ recorded;
    }
    if (flags_differ)
        return 0;
    const __m256i prims = _mm256_loadu_si256((const __m256i *)(const void *)prim);
    const __m256i first_lane = lanes_first_equal(prims);
    _mm256_storeu_si256((__m256i *)(void *)slot, first_lane);
    const int leaders = _mm256_movemask_ps(_mm256_castsi256_ps(
        _mm256_cmpeq_epi32(first_lane, _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7))));
    const __m256i mats = _mm256_loadu_si256((const __m256i *)(const void *)mat);
    const __m256i in_other = _mm256_xor_si256(
        _mm256_cmpeq_epi32(mats, _mm256_set1_epi32((int32_t)material)), _mm256_set1_epi32(-1));
    const int other_mask = _mm256_movemask_ps(_mm256_castsi256_ps(in_other));
    if (other_mask) {
        other = mat[__builtin_ctz((unsigned)other_mask)];
        two = 1;
        const int of_other = _mm256_movemask_ps(
            _mm256_castsi256_ps(_mm256_cmpeq_epi32(mats, _mm256_set1_epi32((int32_t)other))));
        if ((of_other & other_mask) != other_mask)
            return 0; /* a third material */
    }
    _mm256_storeu_si256((__m256i *)(void *)other_lane, in_other);
    /* The distinct triangles' vertex lines asked for together (hints, no
     * value read): the loop over the triangles below reads each
     * triangle's positions, normals and texture coordinates only after
     * the last triangle's work, which fills the reorder buffer, so their
     * misses would otherwise come one triangle after the other. */
    for (unsigned left = (unsigned)leaders; left; left &= left - 1) {
        const uint32_t *v = &mesh->indices[3 * prim[__builtin_ctz(left)]];
        for (int k = 0; k < 3; k++) {
            __builtin_prefetch(&mesh->positions[3 * v[k]]);
            if (mesh->normals)
                __builtin_prefetch(&mesh->normals[3 * v[k]]);
            if (mesh->texcoords)
                __builtin_prefetch(&mesh->texcoords[2 * v[k]]);
        }
    }
    const struct scene_material *m = &mesh->materials[material];
    const struct scene_material *call = &t.inst->appearance.material;
    const float *emission;
    int lighting;
    const struct scene_texture *tx = lanes_material(sc, m, call, &emission, &lighting);
    const int lod = tx && tx->min_filter != tx->mag_filter;
    /*
     * A second material (some 4,600 blocks of a BART kitchen frame at
     * 1024x768, 98 % of the blocks this path refused when it took one
     * material only: a counting build, zn12, round 58; all of them on
     * one instance, with one set of flags, the emission and lighting of
     * both the same, no vertex colours, and in two thirds of them one
     * material textured and the other not).  The eye light's lanes
     * (eye_light8) read one emission and one lighting: the block is
     * taken when the second material's are the same floats bit for bit
     * (memcmp) and the same switch; its colours then differ from the
     * first's only by the material's ambient and diffuse colours and
     * its texture, which are taken per lane by the lane's group (the
     * colours blended, each texture's levels of detail and lookups on
     * its own lanes).  With vertex colours (color_material_on: the
     * flags, the instance and the lighting, the same for both) the
     * per-hit path keeps the block.  Measured (zn12): six kitchen frames
     * (callgrind, this core's caches) 4,497.8 -> 4,448.4 M instructions
     * (-1.1 %; surface_fetch_colours, texture_lods and the per-hit
     * lookups some 142 M fewer, fetch_lanes_mixed and the 8-lane lookups
     * some 90 M more) and L1i misses 11.16 -> 10.30 M; the fastest frame
     * (frame-overhead, five sets of quads against the per-hit path) 0.1
     * to 0.7 ms faster in each set, the fastest-run ratio level: those
     * blocks cost some 4.8 ms on the per-hit path (a knock-out), and the
     * lanes' work on their many triangles is slow per instruction.
     */
    const struct scene_material *m2 = m;
    const struct scene_texture *tx2 = NULL;
    int lod2 = 0;
    if (two) {
        m2 = &mesh->materials[other];
        const float *emission2;
        int lighting2;
        tx2 = lanes_material(sc, m2, call, &emission2, &lighting2);
        if (lighting2 != lighting || memcmp(emission2, emission, sizeof(out->emission)) ||
            color_material_on(&t, hit_unlit(sc, lighting)))
            return 0;
        lod2 = tx2 && tx2->min_filter != tx2->mag_filter;
    }
    /* Per triangle: its unit normal (triangle_normal; a degenerate one
     * leaves the block to the per-hit path) and its level-of-detail
     * part, copied out of the tile's one cache entry, which the next
     * triangle takes. */
    /* Each distinct triangle's values in slot order, a vector of up to
     * eight slots per component (tri_x[...][j]: slot j's): each lane then
     * takes its slot's value with one vpermps by the lanes' slot indices
     * (lanes_by_slot), the same floats as loading them lane by lane from
     * the lane's own triangle, moved, not computed.  The slots of no
     * leader are zeros that no index selects. */
    float tri_ng[3][TRACE_PACKET], tri_n[3][3][TRACE_PACKET], tri_st[2][3][TRACE_PACKET];
    lanes_zero(tri_ng[0], 3);
    const int smooth = mesh->has_normals && !(t.flags & TRI_FLAT);
    if (smooth)
        lanes_zero(tri_n[0][0], 9);
    const int textured = tx || tx2;
    if (textured)
        lanes_zero(tri_st[0][0], 6);
    struct slots_lod tri_lod;
#if defined(SURFACE_OCTS)
    /* The slots of no leader are zeros that no index selects. */
    tri_lod.usable = 0;
    if (lod || lod2) {
        lanes_zero_pd(tri_lod.n[0], 3);
        lanes_zero_pd(tri_lod.m[0][0], 6);
        lanes_zero_pd(tri_lod.sin2, 1);
    }
#endif
    for (unsigned left = (unsigned)leaders; left; left &= left - 1) {
        const int j = __builtin_ctz(left);
        const int in_two = mat[j] != material;
        struct hit_triangle tj = t;
        tj.v = &mesh->indices[3 * prim[j]];
        struct surface_cache *c = triangle_cache(eye_cache(sc, prim[j]), t.inst, prim[j]);
        float ng[3];
        if (!triangle_normal(c, &tj, ng))
            return 0;
        for (int k = 0; k < 3; k++)
            tri_ng[k][j] = ng[k];
        for (int v = 0; v < 3; v++) {
            if (smooth)
                for (int k = 0; k < 3; k++)
                    tri_n[k][v][j] = mesh->normals[3 * tj.v[v] + k];
            if (textured)
                for (int k = 0; k < 2; k++)
                    tri_st[k][v][j] = mesh->texcoords[2 * tj.v[v] + k];
        }
        /* The triangle part of its own material's texture. */
        if (in_two ? lod2 : lod) {
            const float *const vst[3] = {&mesh->texcoords[2 * tj.v[0]],
                                         &mesh->texcoords[2 * tj.v[1]],
                                         &mesh->texcoords[2 * tj.v[2]]};
            const struct surface_lod *l =
                lod_triangle(c, in_two ? tx2 : tx, t.inst, mesh, prim[j], tj.v, vst, NULL);
            tri_lod.part[j] = *l;
#if defined(SURFACE_OCTS)
            /* Its texel map once per triangle part, as surface_fetch_lanes. */
            if (!c->fast.state)
                lod_fast_init(l, &c->fast);
            if (c->fast.state > 0) {
                for (int k = 0; k < 3; k++) {
                    tri_lod.n[k][j] = l->n[k];
                    tri_lod.m[0][k][j] = c->fast.m[0][k];
                    tri_lod.m[1][k][j] = c->fast.m[1][k];
                }
                tri_lod.sin2[j] = c->fast.sin2;
                tri_lod.usable |= 1 << j;
            }
#endif
        }
    }
    const __m256i slots = _mm256_loadu_si256((const __m256i *)(const void *)slot);
    float lane_b[3][TRACE_PACKET];
    for (int i = 0; i < TRACE_PACKET; i++) {
        lane_b[1][i] = hits[i]->u;
        lane_b[2][i] = hits[i]->v;
    }
    const __m256 b1 = _mm256_loadu_ps(lane_b[1]), b2 = _mm256_loadu_ps(lane_b[2]);
    const __m256 b0 = _mm256_sub_ps(_mm256_sub_ps(_mm256_set1_ps(1.0f), b1), b2);
    __m256 g[3], dv[3];
    for (int k = 0; k < 3; k++) {
        g[k] = lanes_by_slot(tri_ng[k], slots);
        dv[k] = _mm256_loadu_ps(dir[k]);
    }
    lanes_facing(g, dv);
    __m256 nv[3] = {g[0], g[1], g[2]};
    if (mesh->has_normals) {
        __m256 no[3];
        if (t.flags & TRI_FLAT) {
            float lane_n[3][TRACE_PACKET];
            for (int i = 0; i < TRACE_PACKET; i++) {
                const float *nf = &mesh->normals[3 * mesh->tri_provoking[hits[i]->prim]];
                for (int k = 0; k < 3; k++)
                    lane_n[k][i] = nf[k];
            }
            for (int k = 0; k < 3; k++)
                no[k] = _mm256_loadu_ps(lane_n[k]);
        } else {
            for (int k = 0; k < 3; k++)
                no[k] = lanes_interpolate_slots(b0, b1, b2, tri_n[k], slots);
        }
        lanes_shading_normal(t.inst->normal_to_world, no, g, nv);
    }
    float lane_g[3][TRACE_PACKET];
    for (int k = 0; k < 3; k++) {
        _mm256_storeu_ps(lane_g[k], g[k]);
        _mm256_storeu_ps(out->n[k], nv[k]);
    }
    memcpy(out->emission, emission, sizeof(out->emission));
    out->lighting = lighting;
    /* The colours: the material's once, or hit by hit whenever a vertex
     * colour may stand in for them (it may differ by triangle). */
    __m256 amb[3], dif[3];
    int deferred = 0;
    lanes_colours(sc, &t, hits, color_material_on(&t, hit_unlit(sc, lighting)), 1, m, call,
                  lighting, out, amb, dif);
    if (two) {
        fetch_lanes_two(sc, &t, dir, width, m2, call, lighting, tx, lod, tx2, lod2, slot,
                        other_lane, tri_st, &tri_lod, b0, b1, b2, g, dv, lane_g, amb, dif);
        tx = NULL; /* done */
    }
    if (tx) {
        float lane_st[2][TRACE_PACKET];
        for (int k = 0; k < 2; k++)
            _mm256_storeu_ps(lane_st[k], lanes_interpolate_slots(b0, b1, b2, tri_st[k], slots));
        float lambda[TRACE_PACKET];
        for (int i = 0; i < TRACE_PACKET; i++)
            lambda[i] = -INFINITY;
        if (lod)
            lod_slots_lanes(tx, &tri_lod, slot, (1 << TRACE_PACKET) - 1, 0, dv, g, width, lane_g,
                            dir, lambda);
        deferred = lanes_texture_end(tx, lambda, lane_st, amb, dif, defer);
    }
    for (int k = 0; k < 3; k++) {
        _mm256_storeu_ps(out->ambient[k], amb[k]);
        _mm256_storeu_ps(out->diffuse[k], dif[k]);
    }
    return 1 + deferred;
}

/* A hit's instance follows its primitive with no gap between them (read
 * as one 64-bit word in surface_fetch_lanes). */
typedef char hit_prim_instance[offsetof(struct trace_scene_hit, instance) ==
                                       offsetof(struct trace_scene_hit, prim) + sizeof(uint32_t)
                                   ? 1
                                   : -1];

/*
 * surface_fetch_lanes (surface.h): fetch_colour_begin of a whole block's
 * TRACE_PACKET hits on one triangle of one instance (three blocks in
 * four of a BART kitchen frame at 1024x768).  What depends on the
 * triangle alone (its instance, vertices and flags, the cached unit
 * normal, the material's emission, lighting and texture name, the
 * texture, the triangle part of the level of detail) once, the rest in
 * eight lanes with fetch_colour_begin's operations; the levels of detail
 * from the lanes and the one cached triangle part (lod_quad), the
 * lookups in the lanes when the sampler takes the block (else hit by
 * hit), and texture_end's products in the lanes (a product is the same
 * in either order).  The same values, so the same colours bit for bit.
 * A block on several triangles goes to fetch_lanes_mixed.
 */
int surface_fetch_lanes(const struct shade_context *sc, const struct trace_scene_hit *const hits[],
                        const float dir[3][TRACE_PACKET], const float width[],
                        struct surface_lanes *out, struct scene_texture_lookup8 *defer)
{
    const struct trace_scene_hit *h0 = hits[0];
    if (!sc->cache)
        return 0;
    /* The primitive and instance of each hit as one 64-bit word (two
     * adjacent uint32 fields, hit_prim_instance): the same test as
     * comparing both, one compare a hit. */
    uint64_t key0;
    memcpy(&key0, &h0->prim, sizeof(key0));
    for (int i = 1; i < TRACE_PACKET; i++) {
        uint64_t key;
        memcpy(&key, &hits[i]->prim, sizeof(key));
        if (key != key0)
            return fetch_lanes_mixed(sc, hits, dir, width, out, defer);
    }
    struct hit_triangle t;
    hit_triangle(sc, h0, &t);
    const struct scene_mesh *mesh = t.mesh;
    if (mesh->texcoord_q)
        return 0;
    struct surface_cache *c = triangle_cache(eye_cache(sc, h0->prim), t.inst, h0->prim);
    float ng[3];
    if (!triangle_normal(c, &t, ng))
        return 0;
    /* The material's resolution (lanes_material, the colours when they
     * cannot vary by hit) once per triangle, kept in its cache entry:
     * the same pointers and floats as resolving them again. */
    const struct scene_material *m = NULL, *call = NULL;
    const float *emission;
    int lighting;
    const struct scene_texture *tx;
    if (c->block) {
        emission = c->block_emission;
        lighting = c->block_lighting;
        tx = c->block_tex;
    } else {
        m = &mesh->materials[mesh->tri_material[h0->prim]];
        call = &t.inst->appearance.material;
        tx = lanes_material(sc, m, call, &emission, &lighting);
    }
    const float *const vst[3] = {
        tx ? &mesh->texcoords[2 * t.v[0]] : NULL, tx ? &mesh->texcoords[2 * t.v[1]] : NULL,
        tx ? &mesh->texcoords[2 * t.v[2]] : NULL};
    const struct surface_lod *tri = NULL;
    if (tx && tx->min_filter != tx->mag_filter)
        tri = lod_triangle(c, tx, t.inst, mesh, h0->prim, t.v, vst, NULL);
    /* Hit by hit, lane i hit i: the barycentrics, the geometric normal
     * facing the ray, the shading normal and the texture coordinates,
     * each lane the scalar operations in their order (hit_triangle,
     * facing_normal, shading_normal, interpolate; no FMA in this copy),
     * so the same floats and doubles. */
    float lane_b[3][TRACE_PACKET];
    for (int i = 0; i < TRACE_PACKET; i++) {
        lane_b[1][i] = hits[i]->u;
        lane_b[2][i] = hits[i]->v;
    }
    const __m256 b1 = _mm256_loadu_ps(lane_b[1]), b2 = _mm256_loadu_ps(lane_b[2]);
    const __m256 b0 = _mm256_sub_ps(_mm256_sub_ps(_mm256_set1_ps(1.0f), b1), b2);
    __m256 g[3], dv[3];
    for (int k = 0; k < 3; k++) {
        g[k] = _mm256_set1_ps(ng[k]);
        dv[k] = _mm256_loadu_ps(dir[k]);
    }
    lanes_facing(g, dv);
    __m256 nv[3] = {g[0], g[1], g[2]};
    if (mesh->has_normals) {
        __m256 no[3];
        if (t.flags & TRI_FLAT) {
            for (int k = 0; k < 3; k++)
                no[k] = _mm256_set1_ps(mesh->normals[3 * t.provoking + k]);
        } else {
            const float *n0 = &mesh->normals[3 * t.v[0]], *n1 = &mesh->normals[3 * t.v[1]],
                        *n2 = &mesh->normals[3 * t.v[2]];
            for (int k = 0; k < 3; k++)
                no[k] = LANES_INTERPOLATE(n0[k], n1[k], n2[k]);
        }
        lanes_shading_normal(t.inst->normal_to_world, no, g, nv);
    }
    float lane_g[3][TRACE_PACKET];
    for (int k = 0; k < 3; k++) {
        _mm256_storeu_ps(lane_g[k], g[k]);
        _mm256_storeu_ps(out->n[k], nv[k]);
    }
    memcpy(out->emission, emission, sizeof(out->emission));
    out->lighting = lighting;
    /* The colours: the material's or a vertex colour that is the same
     * for the whole triangle once (kept in the cache entry with the
     * material's resolution), interpolated vertex colours hit by hit. */
    __m256 amb[3], dif[3];
    int deferred = 0;
    if (c->block) {
        for (int k = 0; k < 3; k++) {
            amb[k] = _mm256_set1_ps(c->block_ambient[k]);
            dif[k] = _mm256_set1_ps(c->block_diffuse[k]);
        }
    } else {
        const int vary = color_material_on(&t, hit_unlit(sc, lighting)) &&
                         !(t.flags & (TRI_INHERIT_COLOR | TRI_FLAT));
        lanes_colours(sc, &t, hits, vary, 0, m, call, lighting, out, amb, dif);
        if (!vary) {
            for (int k = 0; k < 3; k++) {
                c->block_ambient[k] = _mm256_cvtss_f32(amb[k]);
                c->block_diffuse[k] = _mm256_cvtss_f32(dif[k]);
            }
            c->block_emission = emission;
            c->block_lighting = lighting;
            c->block_tex = tx;
            c->block = 1;
        }
    }
    if (tx) {
        float lane_st[2][TRACE_PACKET];
        for (int k = 0; k < 2; k++)
            _mm256_storeu_ps(lane_st[k], LANES_INTERPOLATE(vst[0][k], vst[1][k], vst[2][k]));
        /* The levels of detail straight from the lanes (lod_quad, four
         * hits a quad: the directions, facing normals and widths that
         * texture_lods reads from a surface_texture), a magnification
         * without them (texture_begin), then the eight lookups in the
         * lanes (scene_texture_sample_lod8) or, where the sampler does not
         * take the block, hit by hit as texture_end. */
        float lambda[TRACE_PACKET];
        for (int i = 0; i < TRACE_PACKET; i++)
            lambda[i] = -INFINITY;
        if (tri) {
            const struct surface_lod *const l4[4] = {tri, tri, tri, tri};
            const double top = lod_top(tx->level_count);
            const __m256 wv = _mm256_loadu_ps(width);
            /* The texel map once per triangle part (the tile's cache). */
            if (!c->fast.state)
                lod_fast_init(tri, &c->fast);
            const int use_fast = c->fast.state > 0;
#if defined(SURFACE_OCTS)
            /* Both quads' lod_fast_quad in one vector (lod_fast_oct),
             * then lod_quad's chain for a quad it did not decide whole,
             * as below (lod_fast_quad wrote that quad's four lambdas
             * before its chain there too; lod_quad_lanes writes them all
             * again). */
            int fast8 = 0;
            if (use_fast) {
                __m512d d8[3], g8[3];
                for (int k = 0; k < 3; k++) {
                    d8[k] = _mm512_cvtps_pd(dv[k]);
                    g8[k] = _mm512_cvtps_pd(g[k]);
                }
                fast8 = lod_fast_oct(&c->fast, tri->n, d8, g8, _mm512_cvtps_pd(wv),
                                     _mm512_set1_pd(top * top), lambda);
            }
            for (int h = 0; h < TRACE_PACKET / 4; h++) {
                if ((fast8 >> 4 * h & 15) == 15)
                    continue;
#define HALF(v) _mm256_cvtps_pd(h ? _mm256_extractf128_ps(v, 1) : _mm256_castps256_ps128(v))
                __m256d d[3], gd[3];
                for (int k = 0; k < 3; k++) {
                    d[k] = HALF(dv[k]);
                    gd[k] = HALF(g[k]);
                }
                lod_quad_lanes(l4, 1, d, gd, HALF(wv), top, tx->level_count, h, width, lane_g,
                               dir, lambda);
#undef HALF
            }
#else
            /* The triangle part's lanes once for both quads, and top's.
             * Every read of fast_lanes is behind use_fast, as its
             * writes; GCC's -Wmaybe-uninitialized does not see it at -O2
             * with ThreadSanitizer's instrumentation (RelWithDebInfo),
             * so it is silenced here, for this block only:
             * an initialiser would change the Release build's register
             * allocation of this loop. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
            struct lod_fast_broadcast fast_lanes;
            if (use_fast)
                lod_fast_quad_lanes(&c->fast, tri->n, top, &fast_lanes);
            for (int h = 0; h < TRACE_PACKET / 4; h++) {
#define HALF(v) _mm256_cvtps_pd(h ? _mm256_extractf128_ps(v, 1) : _mm256_castps256_ps128(v))
                __m256d d[3], gd[3];
                for (int k = 0; k < 3; k++) {
                    d[k] = HALF(dv[k]);
                    gd[k] = HALF(g[k]);
                }
                /* lod_fast_quad where its margin decides all four, else
                 * lod_quad's chain for the quad (the same lambdas). */
                if (use_fast &&
                    lod_fast_quad(&fast_lanes, d, gd, HALF(wv), &lambda[4 * h]) == 15)
                    continue;
                lod_quad_lanes(l4, 1, d, gd, HALF(wv), top, tx->level_count, h, width, lane_g,
                               dir, lambda);
#undef HALF
            }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#endif
        }
        deferred = lanes_texture_end(tx, lambda, lane_st, amb, dif, defer);
    }
    for (int k = 0; k < 3; k++) {
        _mm256_storeu_ps(out->ambient[k], amb[k]);
        _mm256_storeu_ps(out->diffuse[k], dif[k]);
    }
    return 1 + deferred;
}
#endif

void surface_fetch_colours(const struct shade_context *sc, int n,
                           const struct trace_scene_hit *const hits[], const float *const dir[],
                           const float width[], struct surface_colour s[])
{
    struct surface_texture tex[TRACE_PACKET];
    struct surface_texture *lod[TRACE_PACKET] = {NULL}; /* lods of them set */
    int lods = 0;
    for (int i = 0; i < n; i++) {
        fetch_colour_begin(sc, hits[i], dir[i], width[i], &s[i], &tex[i]);
        if (tex[i].lod)
            lod[lods++] = &tex[i];
    }
    texture_lods(lod, lods);
#if defined(SURFACE_QUADS)
    if (n == TRACE_PACKET) {
        float *ambient[TRACE_PACKET], *diffuse[TRACE_PACKET];
        for (int i = 0; i < TRACE_PACKET; i++) {
            ambient[i] = s[i].ambient;
            diffuse[i] = s[i].diffuse;
        }
        if (texture_end8(tex, ambient, diffuse))
            return;
    }
#endif
    for (int i = 0; i < n; i++)
        texture_end(&tex[i], s[i].ambient, s[i].diffuse);
}

int surface_texel(const struct shade_context *sc, const struct trace_scene_hit *hit,
                  uint32_t name, const float vertex_st[3][2], const float vertex_q[3],
                  const float ng[3], const float dir[3], float width, float texel[4])
{
    const struct scene_texture *tex = scene_textures_lookup(sc->textures, name);
    if (!tex || !tex->texels)
        return 0;
    const struct scene_instance *inst = shade_hit_instance(sc, hit);
    const struct scene_mesh *mesh = &inst->object->mesh;
    const uint32_t *v = &mesh->indices[3 * hit->prim];
    const float b1 = hit->u, b2 = hit->v, b0 = 1.0f - hit->u - hit->v;
    const float *const vst[3] = {vertex_st[0], vertex_st[1], vertex_st[2]};
    float st[2], lod_st[3][2];
    const float *lst[3] = {vst[0], vst[1], vst[2]};
    if (vertex_q) {
        projective_st(vst, vertex_q, b0, b1, b2, st, lod_st);
        for (int k = 0; k < 3; k++)
            lst[k] = lod_st[k];
    } else {
        for (int k = 0; k < 2; k++)
            st[k] = b0 * vst[0][k] + b1 * vst[1][k] + b2 * vst[2][k];
    }
    float lambda = -INFINITY;
    if (tex->min_filter != tex->mag_filter)
        lambda = texture_lod(sc, tex, inst, mesh, hit->prim, v, lst, ng, dir, width);
    scene_texture_sample_lod(tex, lambda, st[0], st[1], texel);
    return 1;
}
