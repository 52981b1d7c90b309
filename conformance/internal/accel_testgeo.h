/* SPDX-License-Identifier: Apache-2.0 */
/*
 * accel_testgeo.h - deterministic test geometry for the accel/trace module
 * tests (builders.c, traversal.c, triangle_watertight.c): a seeded random
 * generator, triangle soups, a closed cube-sphere, a height field, and the
 * per-triangle boxes the builders take.  Header-only: every test is one
 * program.
 *
 * Meshes are indexed triangle lists (positions xyz per vertex, indices
 * 3 per triangle), wound counter-clockwise seen from outside for the
 * closed ones, the layout accel_gather_triangles expects.
 */
#ifndef RT_CONFORMANCE_ACCEL_TESTGEO_H
#define RT_CONFORMANCE_ACCEL_TESTGEO_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/aabb.h"
#include "check.h"

/* xorshift64* (Vigna 2016): tiny, and the same sequence everywhere. */
struct tg_rng {
    uint64_t s;
};

static inline void tg_seed(struct tg_rng *r, uint64_t seed)
{
    r->s = seed * 0x9e3779b97f4a7c15ull + 0x1234567ull;
    if (!r->s)
        r->s = 1;
}

static inline uint64_t tg_next(struct tg_rng *r)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return r->s * 0x2545f4914f6cdd1dull;
}

/* Uniform in [0, 1), 24 random bits. */
static inline float tg_unit(struct tg_rng *r)
{
    return (float)(tg_next(r) >> 40) * (1.0f / 16777216.0f);
}

/* Uniform in [lo, hi). */
static inline float tg_range(struct tg_rng *r, float lo, float hi)
{
    return lo + (hi - lo) * tg_unit(r);
}

static inline uint32_t tg_below(struct tg_rng *r, uint32_t n)
{
    return (uint32_t)(tg_next(r) % n);
}

struct tg_mesh {
    float *pos;
    uint32_t *idx;
    uint32_t vertex_count;
    uint32_t tri_count;
};

static inline void *tg_alloc(size_t bytes)
{
    void *p = malloc(bytes ? bytes : 1);
    if (!p) {
        fprintf(stderr, "test: out of memory\n");
        exit(2);
    }
    return p;
}

static inline void tg_mesh_free(struct tg_mesh *m)
{
    free(m->pos);
    free(m->idx);
    memset(m, 0, sizeof(*m));
}

static inline void tg_mesh_alloc(struct tg_mesh *m, uint32_t vertices, uint32_t tris)
{
    m->pos = tg_alloc(sizeof(float) * 3 * (size_t)vertices);
    m->idx = tg_alloc(sizeof(uint32_t) * 3 * (size_t)tris);
    m->vertex_count = vertices;
    m->tri_count = tris;
}

static inline void tg_set_tri(struct tg_mesh *m, uint32_t t, uint32_t a, uint32_t b, uint32_t c)
{
    m->idx[3 * (size_t)t + 0] = a;
    m->idx[3 * (size_t)t + 1] = b;
    m->idx[3 * (size_t)t + 2] = c;
}

/* n independent triangles: centres uniform in [0, extent)^3, vertices
 * within +-size/2 of the centre. */
static inline void tg_soup(struct tg_mesh *m, uint32_t n, float extent, float size,
                           struct tg_rng *r)
{
    tg_mesh_alloc(m, 3 * n, n);
    for (uint32_t t = 0; t < n; t++) {
        float c[3];
        for (int k = 0; k < 3; k++)
            c[k] = tg_range(r, 0.0f, extent);
        for (int v = 0; v < 3; v++) {
            for (int k = 0; k < 3; k++)
                m->pos[9 * t + 3 * v + k] = c[k] + size * (tg_unit(r) - 0.5f);
            m->idx[3 * t + v] = 3 * t + v;
        }
    }
}

/*
 * A closed surface: the cube [-1, 1]^3 with each face split into g x g
 * quads (two triangles each), vertices shared along the cube's edges, and
 * with sphere != 0 every vertex pushed onto the unit sphere (so no face
 * is flat or axis-aligned).  Then p -> p * scale + offset (computed in
 * double, rounded once).  Outward counter-clockwise winding.
 */
static inline void tg_cube_sphere(struct tg_mesh *m, int g, int sphere, double scale,
                                  const double offset[3])
{
    int side = g + 1;
    size_t lattice = (size_t)side * side * side;
    uint32_t *map = tg_alloc(sizeof(uint32_t) * lattice);
    for (size_t i = 0; i < lattice; i++)
        map[i] = UINT32_MAX;
    uint32_t vertices = (uint32_t)(6 * g * g + 2);
    uint32_t tris = (uint32_t)(12 * g * g);
    tg_mesh_alloc(m, vertices, tris);
    uint32_t vn = 0;
    uint32_t tn = 0;
    /* Face f: axis a = f / 2 fixed at 0 (side -1) or g (side +1); (u, v)
     * run over the other two axes, ordered so that u x v points outward. */
    for (int f = 0; f < 6; f++) {
        int a = f / 2;
        int plus = f % 2;
        int ua = (a + 1) % 3;
        int va = (a + 2) % 3;
        if (!plus) {
            int t = ua;
            ua = va;
            va = t;
        }
        uint32_t corner[2][2];
        for (int j = 0; j < g; j++) {
            for (int i = 0; i < g; i++) {
                for (int dj = 0; dj < 2; dj++) {
                    for (int di = 0; di < 2; di++) {
                        int c[3];
                        c[a] = plus ? g : 0;
                        c[ua] = i + di;
                        c[va] = j + dj;
                        size_t key = ((size_t)c[0] * side + c[1]) * side + c[2];
                        if (map[key] == UINT32_MAX) {
                            double p[3];
                            for (int k = 0; k < 3; k++)
                                p[k] = 2.0 * c[k] / g - 1.0;
                            if (sphere) {
                                double len = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                                for (int k = 0; k < 3; k++)
                                    p[k] /= len;
                            }
                            for (int k = 0; k < 3; k++)
                                m->pos[3 * vn + k] = (float)(p[k] * scale + offset[k]);
                            map[key] = vn++;
                        }
                        corner[dj][di] = map[key];
                    }
                }
                uint32_t q[4] = {corner[0][0], corner[0][1], corner[1][1], corner[1][0]};
                /* Alternate the diagonal so edges run both ways. */
                int flip = (i + j) & 1;
                if (!flip) {
                    tg_set_tri(m, tn, q[0], q[1], q[2]);
                    tg_set_tri(m, tn + 1, q[0], q[2], q[3]);
                } else {
                    tg_set_tri(m, tn, q[0], q[1], q[3]);
                    tg_set_tri(m, tn + 1, q[1], q[2], q[3]);
                }
                tn += 2;
            }
        }
    }
    free(map);
    m->vertex_count = vn;
    m->tri_count = tn;
}

/* A g x g height field over [0, 1]^2 in x, z with a wavy y. */
static inline void tg_terrain(struct tg_mesh *m, int g, struct tg_rng *r)
{
    int side = g + 1;
    tg_mesh_alloc(m, (uint32_t)(side * side), (uint32_t)(2 * g * g));
    for (int y = 0; y < side; y++) {
        for (int x = 0; x < side; x++) {
            float fx = (float)x / (float)g;
            float fy = (float)y / (float)g;
            float *p = &m->pos[3 * (y * side + x)];
            p[0] = fx;
            p[2] = fy;
            p[1] = 0.1f * sinf(fx * 20.0f) * cosf(fy * 17.0f) + 0.01f * tg_unit(r);
        }
    }
    uint32_t t = 0;
    for (int y = 0; y < g; y++) {
        for (int x = 0; x < g; x++) {
            uint32_t a = (uint32_t)(y * side + x);
            uint32_t b = a + 1;
            uint32_t c = a + (uint32_t)side;
            uint32_t d = c + 1;
            tg_set_tri(m, t, a, b, d);
            tg_set_tri(m, t + 1, a, d, c);
            t += 2;
        }
    }
}

static inline const float *tg_vertex(const struct tg_mesh *m, uint32_t tri, int corner)
{
    return &m->pos[3 * (size_t)m->idx[3 * (size_t)tri + corner]];
}

/* Per-triangle boxes; caller frees. */
static inline struct aabb *tg_boxes(const struct tg_mesh *m)
{
    struct aabb *b = tg_alloc(sizeof(*b) * (size_t)m->tri_count);
    for (uint32_t t = 0; t < m->tri_count; t++) {
        b[t] = aabb_empty();
        for (int v = 0; v < 3; v++)
            aabb_grow_point(&b[t], tg_vertex(m, t, v));
    }
    return b;
}

/* Exact zero-area test in double (differences of floats and their
 * products are exact for the magnitudes the tests use). */
static inline int tg_zero_area(const float *a, const float *b, const float *c)
{
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = (double)b[k] - a[k];
        e2[k] = (double)c[k] - a[k];
    }
    return e1[1] * e2[2] == e1[2] * e2[1] && e1[2] * e2[0] == e1[0] * e2[2] &&
           e1[0] * e2[1] == e1[1] * e2[0];
}

#endif
