/* SPDX-License-Identifier: Apache-2.0 */
/*
 * brute_force.h - the double-precision reference for the correctness tests
 * (query_brute_force.c, instanced_vs_flat.c, stability_*.c).
 *
 * Header only (static inline, so a test that uses part of it compiles
 * without unused-function warnings).  It provides:
 *   - a fixed-seed generator (splitmix64) so every test is deterministic;
 *   - column-major double 4x4 matrices (p' = M p, element (r, c) at m[4c + r],
 *     as rt.h), built and inverted here so a test knows the exact matrix it
 *     handed to rtLoadMatrixd;
 *   - a scene of world-space triangles in double: the test transforms the
 *     float object-space vertices it gave the library by the instance
 *     matrix itself, so nothing of the library's arithmetic is reused;
 *   - a ray/triangle test in double and bf_check_hit, which judges one
 *     RThit of rtTraceRays against every triangle of that scene.
 *
 * Tolerances (bf_check_hit).  The library works in float: it moves each
 * ray into object space (rounding the result to float) and intersects
 * there, so its ray is off the exact one by a few float ulps of the
 * coordinates involved.  A test states that error as pos_eps,
 * a length in world units.  From it:
 *   - a ray moved by pos_eps meets a plane up to pos_eps / cosine away
 *     (cosine between ray and normal), so a triangle is "solidly hit" when
 *     the exact ray meets it at least pos_eps / cosine inside all three
 *     edges, and "nearly hit" when no more than that outside one;
 *   - the allowed error of a hit distance is rel_t * t + pos_eps / |d.n|
 *     (n the unit normal): a position error of pos_eps along the normal
 *     moves the hit by pos_eps / |d.n| in units of d, which is what
 *     grazing hits need; for a ray meeting the surface head on this is a
 *     relative tolerance of about rel_t.
 * A reported hit must be on a nearly hit triangle, at its distance within
 * that tolerance, inside [tmin, tmax), with barycentrics that name a point
 * on the ray (bf_bary_tolerance), and no solidly hit triangle may lie
 * clearly in front of it; a miss is only allowed when no triangle is
 * solidly hit.  Rays whose answer differs from the exact closest triangle
 * within those rules (an edge or silhouette passing within pos_eps, two
 * triangles at the same distance) are counted as "tolerated" so a test can
 * bound how often that happens.
 */
#ifndef RT_CONFORMANCE_BRUTE_FORCE_H
#define RT_CONFORMANCE_BRUTE_FORCE_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <rt/rt.h>

/* ---- fixed-seed random numbers (splitmix64, Steele, Lea and Flood 2014) ---- */

struct bf_rng {
    uint64_t state;
};

static inline void bf_seed(struct bf_rng *r, uint64_t seed)
{
    r->state = seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull;
}

static inline uint64_t bf_next(struct bf_rng *r)
{
    uint64_t z = (r->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1), 53 bits. */
static inline double bf_uniform(struct bf_rng *r)
{
    return (double)(bf_next(r) >> 11) * (1.0 / 9007199254740992.0);
}

static inline double bf_range(struct bf_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * bf_uniform(r);
}

/* Uniform integer in [0, n). */
static inline uint32_t bf_below(struct bf_rng *r, uint32_t n)
{
    return (uint32_t)(bf_uniform(r) * n);
}

/* A uniformly distributed unit vector. */
static inline void bf_unit_vector(struct bf_rng *r, double v[3])
{
    double z = bf_range(r, -1.0, 1.0);
    double phi = bf_range(r, 0.0, 6.283185307179586);
    double s = sqrt(1.0 - z * z);
    v[0] = s * cos(phi);
    v[1] = s * sin(phi);
    v[2] = z;
}

/* ---- vectors and matrices (double, column-major) ---------------------------- */

static inline double bf_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void bf_cross(double out[3], const double a[3], const double b[3])
{
    double r[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    memcpy(out, r, sizeof(r));
}

static inline void bf_sub(double out[3], const double a[3], const double b[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = a[k] - b[k];
}

static inline double bf_length(const double a[3])
{
    return sqrt(bf_dot(a, a));
}

static inline void bf_identity(double m[16])
{
    memset(m, 0, 16 * sizeof(double));
    m[0] = m[5] = m[10] = m[15] = 1.0;
}

/* out = a * b; out may alias a or b. */
static inline void bf_mul(double out[16], const double a[16], const double b[16])
{
    double r[16];
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++) {
            double s = 0.0;
            for (int k = 0; k < 4; k++)
                s += a[4 * k + row] * b[4 * c + k];
            r[4 * c + row] = s;
        }
    memcpy(out, r, sizeof(r));
}

static inline void bf_translation(double m[16], double x, double y, double z)
{
    bf_identity(m);
    m[12] = x;
    m[13] = y;
    m[14] = z;
}

static inline void bf_scaling(double m[16], double x, double y, double z)
{
    bf_identity(m);
    m[0] = x;
    m[5] = y;
    m[10] = z;
}

/* glFrustum's matrix (OpenGL 1.5 specification, sec. 2.11.2), column-major. */
static inline void bf_frustum(double m[16], double l, double r, double b, double t, double n,
                              double f)
{
    memset(m, 0, 16 * sizeof(double));
    m[0] = 2.0 * n / (r - l);
    m[5] = 2.0 * n / (t - b);
    m[8] = (r + l) / (r - l);
    m[9] = (t + b) / (t - b);
    m[10] = -(f + n) / (f - n);
    m[11] = -1.0;
    m[14] = -2.0 * f * n / (f - n);
}

/* glOrtho's matrix (OpenGL 1.5 specification, sec. 2.11.2), column-major. */
static inline void bf_ortho(double m[16], double l, double r, double b, double t, double n,
                            double f)
{
    memset(m, 0, 16 * sizeof(double));
    m[0] = 2.0 / (r - l);
    m[5] = 2.0 / (t - b);
    m[10] = -2.0 / (f - n);
    m[12] = -(r + l) / (r - l);
    m[13] = -(t + b) / (t - b);
    m[14] = -(f + n) / (f - n);
    m[15] = 1.0;
}

/* Rotation by angle (radians) about the unit axis a (Rodrigues). */
static inline void bf_rotation(double m[16], double angle, const double a[3])
{
    double c = cos(angle), s = sin(angle), t = 1.0 - c;
    bf_identity(m);
    m[0] = t * a[0] * a[0] + c;
    m[1] = t * a[0] * a[1] + s * a[2];
    m[2] = t * a[0] * a[2] - s * a[1];
    m[4] = t * a[0] * a[1] - s * a[2];
    m[5] = t * a[1] * a[1] + c;
    m[6] = t * a[1] * a[2] + s * a[0];
    m[8] = t * a[0] * a[2] + s * a[1];
    m[9] = t * a[1] * a[2] - s * a[0];
    m[10] = t * a[2] * a[2] + c;
}

static inline void bf_random_rotation(struct bf_rng *r, double m[16])
{
    double axis[3];
    bf_unit_vector(r, axis);
    bf_rotation(m, bf_range(r, 0.0, 6.283185307179586), axis);
}

/*
 * A random affine map T * R1 * S * R2: rotations R1, R2 uniformly random,
 * S a non-uniform scale with each factor in [scale_lo, scale_hi] (log
 * uniform) and a random sign on one axis in a quarter of the cases (a
 * mirror), T a translation with components in [-translate, translate].
 * R1 S R2 has shear as well as scale.  Condition number <= scale_hi/scale_lo.
 */
static inline void bf_random_affine(struct bf_rng *r, double m[16], double scale_lo,
                                    double scale_hi, double translate)
{
    double t[16], r1[16], s[16], r2[16];
    bf_translation(t, bf_range(r, -translate, translate), bf_range(r, -translate, translate),
                   bf_range(r, -translate, translate));
    bf_random_rotation(r, r1);
    bf_random_rotation(r, r2);
    double f[3];
    for (int k = 0; k < 3; k++)
        f[k] = exp(bf_range(r, log(scale_lo), log(scale_hi)));
    if (bf_uniform(r) < 0.25)
        f[bf_below(r, 3)] *= -1.0;
    bf_scaling(s, f[0], f[1], f[2]);
    bf_mul(m, t, r1);
    bf_mul(m, m, s);
    bf_mul(m, m, r2);
}

static inline void bf_transform_point(const double m[16], const double p[3], double out[3])
{
    double r[3];
    for (int row = 0; row < 3; row++)
        r[row] = m[row] * p[0] + m[4 + row] * p[1] + m[8 + row] * p[2] + m[12 + row];
    memcpy(out, r, sizeof(r));
}

static inline void bf_transform_vector(const double m[16], const double v[3], double out[3])
{
    double r[3];
    for (int row = 0; row < 3; row++)
        r[row] = m[row] * v[0] + m[4 + row] * v[1] + m[8 + row] * v[2];
    memcpy(out, r, sizeof(r));
}

/* General 4x4 inverse by Gauss-Jordan elimination with partial pivoting.
 * Returns 0 when a pivot is exactly zero. */
static inline int bf_invert(double out[16], const double m[16])
{
    double a[4][8];
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) {
            a[r][c] = m[4 * c + r];
            a[r][4 + c] = r == c ? 1.0 : 0.0;
        }
    for (int col = 0; col < 4; col++) {
        int pivot = col;
        for (int r = col + 1; r < 4; r++)
            if (fabs(a[r][col]) > fabs(a[pivot][col]))
                pivot = r;
        if (a[pivot][col] == 0.0)
            return 0;
        for (int c = 0; c < 8; c++) {
            double tmp = a[col][c];
            a[col][c] = a[pivot][c];
            a[pivot][c] = tmp;
        }
        double inv = 1.0 / a[col][col];
        for (int c = 0; c < 8; c++)
            a[col][c] *= inv;
        for (int r = 0; r < 4; r++) {
            if (r == col)
                continue;
            double f = a[r][col];
            for (int c = 0; c < 8; c++)
                a[r][c] -= f * a[col][c];
        }
    }
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            out[4 * c + r] = a[r][4 + c];
    return 1;
}

/* Maps a point through a full 4x4 matrix with the homogeneous divide. */
static inline void bf_project(const double m[16], const double p[3], double out[3])
{
    double w = m[3] * p[0] + m[7] * p[1] + m[11] * p[2] + m[15];
    for (int r = 0; r < 3; r++)
        out[r] = (m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]) / w;
}

/* ---- world-space triangles ---------------------------------------------------- */

/* A world-space triangle with the per-triangle constants of bf_intersect;
 * fill v and call bf_tri_prepare. */
struct bf_tri {
    double v[3][3];
    double n[3];    /* (v1 - v0) x (v2 - v0) */
    double nlen;    /* |n| = twice the area */
    double g1[3];   /* (p - v0).g1 = b1 for p in the plane: (e2 x n) / |n|^2 */
    double g2[3];   /* (p - v0).g2 = b2: (n x e1) / |n|^2 */
    double edge[3]; /* length of the edge opposite vertex k */
    double max_edge;
};

static inline void bf_tri_prepare(struct bf_tri *t)
{
    double e1[3], e2[3];
    bf_sub(e1, t->v[1], t->v[0]);
    bf_sub(e2, t->v[2], t->v[0]);
    bf_cross(t->n, e1, e2);
    double n2 = bf_dot(t->n, t->n);
    t->nlen = sqrt(n2);
    bf_cross(t->g1, e2, t->n);
    bf_cross(t->g2, t->n, e1);
    for (int k = 0; k < 3; k++) {
        t->g1[k] = n2 > 0.0 ? t->g1[k] / n2 : 0.0;
        t->g2[k] = n2 > 0.0 ? t->g2[k] / n2 : 0.0;
    }
    t->max_edge = 0.0;
    for (int k = 0; k < 3; k++) {
        double e[3];
        bf_sub(e, t->v[(k + 2) % 3], t->v[(k + 1) % 3]);
        t->edge[k] = bf_length(e);
        if (t->edge[k] > t->max_edge)
            t->max_edge = t->edge[k];
    }
}

struct bf_scene {
    struct bf_tri *tris;
    size_t count, capacity;
    /* Instance i owns tris[base[i] .. base[i] + tri_count[i]). */
    size_t *base;
    uint32_t *tri_count;
    uint32_t *object;
    uint32_t instances, instance_capacity;
};

static inline void *bf_xrealloc(void *p, size_t n)
{
    void *q = realloc(p, n ? n : 1);
    if (!q) {
        fprintf(stderr, "fatal: out of memory in the test's reference scene\n");
        exit(1);
    }
    return q;
}

static inline void bf_scene_free(struct bf_scene *s)
{
    free(s->tris);
    free(s->base);
    free(s->tri_count);
    free(s->object);
    memset(s, 0, sizeof(*s));
}

/*
 * Appends instance number s->instances of object `object`: the tri_count
 * triangles of `positions` (9 floats each: v0, v1, v2, the values handed to
 * rtVertex3f under an identity modelview) mapped by m in double.
 */
static inline void bf_scene_add_instance(struct bf_scene *s, const float *positions,
                                         uint32_t tri_count, const double m[16], uint32_t object)
{
    if (s->instances == s->instance_capacity) {
        s->instance_capacity = s->instance_capacity ? 2 * s->instance_capacity : 8;
        s->base = bf_xrealloc(s->base, s->instance_capacity * sizeof(*s->base));
        s->tri_count = bf_xrealloc(s->tri_count, s->instance_capacity * sizeof(*s->tri_count));
        s->object = bf_xrealloc(s->object, s->instance_capacity * sizeof(*s->object));
    }
    if (s->count + tri_count > s->capacity) {
        while (s->count + tri_count > s->capacity)
            s->capacity = s->capacity ? 2 * s->capacity : 64;
        s->tris = bf_xrealloc(s->tris, s->capacity * sizeof(*s->tris));
    }
    s->base[s->instances] = s->count;
    s->tri_count[s->instances] = tri_count;
    s->object[s->instances] = object;
    s->instances++;
    for (uint32_t i = 0; i < tri_count; i++) {
        struct bf_tri *t = &s->tris[s->count++];
        for (int c = 0; c < 3; c++) {
            const float *p = &positions[9 * (size_t)i + 3 * c];
            double pd[3] = {p[0], p[1], p[2]};
            bf_transform_point(m, pd, t->v[c]);
        }
        bf_tri_prepare(t);
    }
}

/* ---- ray/triangle in double ------------------------------------------------ */

struct bf_isect {
    int valid;     /* 0: degenerate triangle or ray parallel to its plane */
    double t;      /* where the ray meets the plane, units of dir */
    double b[3];   /* barycentrics of that point (b[1] = u, b[2] = v) */
    double margin; /* signed distance inside the nearest edge line (< 0 outside) */
    double cosine; /* |d.n| / |d|, n the unit normal */
    double max_edge;
};

/* Intersects the ray org + t dir with the plane of a prepared triangle;
 * dir_len = |dir|. */
static inline struct bf_isect bf_intersect_len(const struct bf_tri *tri, const double org[3],
                                               const double dir[3], double dir_len)
{
    struct bf_isect x;
    double denom = bf_dot(dir, tri->n);
    if (tri->nlen == 0.0 || denom == 0.0) {
        memset(&x, 0, sizeof(x));
        return x;
    }
    double w[3];
    bf_sub(w, tri->v[0], org);
    x.t = bf_dot(w, tri->n) / denom;
    double p[3];
    for (int k = 0; k < 3; k++)
        p[k] = org[k] + x.t * dir[k] - tri->v[0][k];
    x.b[1] = bf_dot(p, tri->g1);
    x.b[2] = bf_dot(p, tri->g2);
    x.b[0] = 1.0 - x.b[1] - x.b[2];
    /* The height over edge k is |n| / |edge k|, so b[k] times it is the
     * signed distance of the point from that edge's line. */
    x.margin = INFINITY;
    for (int k = 0; k < 3; k++) {
        double d = x.b[k] * tri->nlen / tri->edge[k];
        if (d < x.margin)
            x.margin = d;
    }
    x.cosine = fabs(denom) / (tri->nlen * dir_len);
    x.max_edge = tri->max_edge;
    x.valid = 1;
    return x;
}

static inline struct bf_isect bf_intersect(const struct bf_tri *tri, const double org[3],
                                           const double dir[3])
{
    return bf_intersect_len(tri, org, dir, bf_length(dir));
}

/* ---- judging a hit ---------------------------------------------------------- */

struct bf_tolerance {
    double rel_t;   /* relative part of the distance tolerance */
    double pos_eps; /* the library's position error, world units */
};

struct bf_stats {
    long rays, hits, exact, tolerated, failures;
    double worst_bary_ratio; /* largest (barycentric point error / allowed) */
};

/* Smallest cosine used in tolerances: below it a ray is taken as lying in
 * the plane (the library then reports no hit on that triangle or one on
 * its edge, and the reference accepts either). */
#define BF_MIN_COSINE 1e-9

/* Allowed error of a hit distance t on a triangle met at `cosine`. */
static inline double bf_t_tolerance(const struct bf_tolerance *tol, double t, double cosine,
                                    double dir_len)
{
    double c = cosine > BF_MIN_COSINE ? cosine : BF_MIN_COSINE;
    return tol->rel_t * fabs(t) + tol->pos_eps / (c * dir_len);
}

/* Allowed error of the in-plane hit point: a ray moved by pos_eps meets
 * the plane up to pos_eps / cosine away. */
static inline double bf_margin_tolerance(const struct bf_tolerance *tol, double cosine)
{
    double c = cosine > BF_MIN_COSINE ? cosine : BF_MIN_COSINE;
    return tol->pos_eps / c;
}

/*
 * Allowed distance between the ray and the point the library's barycentrics
 * name.  The watertight test computes u, v as ratios of 2D edge functions
 * after shearing the triangle into the ray's frame; each edge function
 * carries an absolute rounding error of a few ulps of D * L (D: distance from
 * the ray origin to the triangle, L: its longest edge), and they are divided
 * by the projected double area 2 A cosine, so thin or grazed triangles get
 * imprecise barycentrics.  A barycentric error e moves the named point by up
 * to e L.  Hence 4 pos_eps (the ray's own error) plus 4 ulps of
 * D L^2 / (2 A cosine).  A vertex permutation moves the point by a fraction
 * of the triangle's size, far more.  bf_stats.worst_bary_ratio reports the
 * largest observed / allowed.
 */
static inline double bf_bary_tolerance(const struct bf_tolerance *tol, const struct bf_tri *tri,
                                       const double org[3], double cosine, double max_edge)
{
    double d = 0.0;
    for (int c = 0; c < 3; c++) {
        double w[3];
        bf_sub(w, tri->v[c], org);
        if (bf_length(w) > d)
            d = bf_length(w);
    }
    double c = cosine > BF_MIN_COSINE ? cosine : BF_MIN_COSINE;
    double projected = tri->nlen * c; /* 2 A cosine */
    double conditioning = 4.0 * 0x1p-24 * d * max_edge * max_edge / projected;
    return 4.0 * tol->pos_eps + conditioning;
}

/*
 * Judges one rtTraceRays result against every triangle of s.  Returns 1
 * when it is acceptable under the rules in the header comment; otherwise 0
 * with the reason in why.  Updates stats.
 */
static inline int bf_check_hit(const struct bf_scene *s, const RTray *ray, const RThit *hit,
                               const struct bf_tolerance *tol, struct bf_stats *stats, char *why,
                               size_t why_len)
{
    double org[3] = {ray->org[0], ray->org[1], ray->org[2]};
    double dir[3] = {ray->dir[0], ray->dir[1], ray->dir[2]};
    double dir_len = bf_length(dir);
    double tmin = ray->tmin, tmax = ray->tmax;
    /* The closest solid hit and the closest exact hit over all triangles. */
    double solid_t = INFINITY, solid_tol = 0.0, exact_t = INFINITY;
    size_t solid_index = (size_t)-1, exact_index = (size_t)-1;
    for (size_t i = 0; i < s->count; i++) {
        struct bf_isect x = bf_intersect_len(&s->tris[i], org, dir, dir_len);
        if (!x.valid)
            continue;
        if (x.margin >= 0.0 && x.t >= tmin && x.t < tmax && x.t < exact_t) {
            exact_t = x.t;
            exact_index = i;
        }
        double tt = bf_t_tolerance(tol, x.t, x.cosine, dir_len);
        if (x.margin >= bf_margin_tolerance(tol, x.cosine) && x.t >= tmin + tt && x.t < tmax - tt &&
            x.t + tt < solid_t + solid_tol) {
            solid_t = x.t;
            solid_tol = tt;
            solid_index = i;
        }
    }
    stats->rays++;
    why[0] = '\0';
    if (!(hit->t < INFINITY)) {
        if (hit->t != INFINITY || hit->instance != RT_INVALID_ID || hit->object != RT_INVALID_ID ||
            hit->primitive != RT_INVALID_ID || hit->u != 0.0f || hit->v != 0.0f) {
            snprintf(why, why_len, "miss not reported as t=inf, ids RT_INVALID_ID, u=v=0");
            stats->failures++;
            return 0;
        }
        if (solid_index != (size_t)-1) {
            snprintf(why, why_len, "miss, but triangle %zu is solidly hit at t=%.9g", solid_index,
                     solid_t);
            stats->failures++;
            return 0;
        }
        if (exact_index == (size_t)-1)
            stats->exact++;
        else
            stats->tolerated++;
        return 1;
    }
    stats->hits++;
    if (hit->instance >= s->instances || hit->object != s->object[hit->instance] ||
        hit->primitive >= s->tri_count[hit->instance]) {
        snprintf(why, why_len, "bad ids instance=%u object=%u primitive=%u", hit->instance,
                 hit->object, hit->primitive);
        stats->failures++;
        return 0;
    }
    size_t index = s->base[hit->instance] + hit->primitive;
    const struct bf_tri *tri = &s->tris[index];
    struct bf_isect x = bf_intersect(tri, org, dir);
    double tt = bf_t_tolerance(tol, x.t, x.cosine, dir_len);
    if (!(hit->t >= ray->tmin && hit->t < ray->tmax)) {
        snprintf(why, why_len, "t=%.9g outside [tmin=%.9g, tmax=%.9g)", hit->t, ray->tmin,
                 ray->tmax);
    } else if (!x.valid || x.margin < -bf_margin_tolerance(tol, x.cosine)) {
        snprintf(why, why_len, "reported triangle %zu is not hit (margin %.3g, cosine %.3g)", index,
                 x.valid ? x.margin : -INFINITY, x.cosine);
    } else if (fabs(hit->t - x.t) > tt) {
        snprintf(why, why_len, "t=%.9g but the exact distance is %.9g (tolerance %.3g)", hit->t,
                 x.t, tt);
    } else if (solid_t + solid_tol < hit->t - tt) {
        snprintf(why, why_len, "hit at t=%.9g behind triangle %zu solidly hit at t=%.9g", hit->t,
                 solid_index, solid_t);
    } else if (!(hit->u >= 0.0f && hit->v >= 0.0f && hit->u + hit->v <= 1.0f + 1e-6f)) {
        snprintf(why, why_len, "barycentrics u=%.9g v=%.9g outside the triangle", hit->u, hit->v);
    } else {
        /* The point the library's barycentrics name must lie on the ray. */
        double p[3], op[3], c[3];
        for (int k = 0; k < 3; k++)
            p[k] = tri->v[0][k] + hit->u * (tri->v[1][k] - tri->v[0][k]) +
                   hit->v * (tri->v[2][k] - tri->v[0][k]);
        bf_sub(op, p, org);
        bf_cross(c, op, dir);
        double off_ray = bf_length(c) / dir_len;
        double allowed = bf_bary_tolerance(tol, tri, org, x.cosine, x.max_edge);
        if (off_ray / allowed > stats->worst_bary_ratio)
            stats->worst_bary_ratio = off_ray / allowed;
        if (off_ray > allowed)
            snprintf(why, why_len,
                     "barycentrics u=%.9g v=%.9g name a point %.3g off the ray (allowed %.3g)",
                     hit->u, hit->v, off_ray, allowed);
    }
    if (why[0]) {
        stats->failures++;
        return 0;
    }
    if (index == exact_index)
        stats->exact++;
    else
        stats->tolerated++;
    return 1;
}

#endif
