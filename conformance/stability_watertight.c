/* SPDX-License-Identifier: Apache-2.0 */
/*
 * stability_watertight.c - no ray slips through a closed mesh, through the
 * public API.
 *
 * Closed meshes whose neighbouring triangles share bit-identical float
 * vertices (defined through rtDrawElements, so shared vertices are one
 * array element): a subdivided icosahedron (5120 triangles), a cube whose
 * faces are 16x16 grids (3072 triangles; the grid coordinates are exact in
 * float), and a radially perturbed, non-convex icosphere (1280 triangles).
 * Each is placed four times: a pure integer translation (the world geometry
 * stays exact), a random rotation, and two random rotations with
 * non-uniform scale 0.7..1.4.
 *
 * 1M rays (with the binned builder; 200k more with the sweep builder) are
 * aimed exactly at shared edges (a random point of a random edge, or its
 * midpoint) and at vertices: half from inside the mesh (a random point of
 * the ball of radius 0.4 about the centre), half from outside (from 0.5 to
 * 3 units away, within 30 degrees of the outward direction, so no ray
 * grazes the surface).  The target is computed in double in world space; the
 * ray's direction is rounded to float once.  Watertightness means:
 *   - every ray hits (zero misses), and rtOccludedRays agrees;
 *   - on the two convex meshes the hit is the target: t = 1 within 1e-4 and
 *     the reported triangle touches the target's edge or vertex;
 *   - on the non-convex mesh the hit is no farther than the target.
 * A last batch uses the cube in place with rays from the exact centre to
 * exact grid vertices and edge midpoints, where the edge functions of the
 * watertight test are exactly zero and its double-precision fallback runs.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "brute_force.h"
#include "testutil.h"

#define T_TOLERANCE 1e-4
#define RAYS_PER_BATCH 41667 /* x 2 batches x 12 instances = 1M rays */
#define MAX_PRINTED 10

struct mesh {
    const char *label;
    RTuint name;
    int convex;
    float *positions; /* 3 per vertex */
    uint32_t vertex_count;
    uint32_t *indices; /* 3 per triangle */
    uint32_t tri_count;
    uint32_t *edges; /* 2 per unique edge */
    uint32_t edge_count;
    uint32_t *vt_first; /* CSR vertex -> incident triangles */
    uint32_t *vt_list;
};

/* ---- mesh construction ---------------------------------------------------- */

static uint32_t add_vertex(struct mesh *m, uint32_t *cap, const double p[3])
{
    if (m->vertex_count == *cap) {
        *cap = *cap ? 2 * *cap : 64;
        m->positions = bf_xrealloc(m->positions, (size_t)*cap * 3 * sizeof(float));
    }
    for (int k = 0; k < 3; k++)
        m->positions[3 * (size_t)m->vertex_count + k] = (float)p[k];
    return m->vertex_count++;
}

static void add_tri(struct mesh *m, uint32_t *cap, uint32_t a, uint32_t b, uint32_t c)
{
    if (m->tri_count == *cap) {
        *cap = *cap ? 2 * *cap : 64;
        m->indices = bf_xrealloc(m->indices, (size_t)*cap * 3 * sizeof(uint32_t));
    }
    uint32_t *t = &m->indices[3 * (size_t)m->tri_count++];
    t[0] = a;
    t[1] = b;
    t[2] = c;
}

/* Edge-midpoint cache for subdivision: open addressing on (lo, hi). */
struct edge_map {
    uint64_t *keys;
    uint32_t *values;
    size_t capacity;
};

static uint32_t *edge_map_slot(struct edge_map *map, uint32_t a, uint32_t b, int *found)
{
    uint64_t key = a < b ? ((uint64_t)a << 32 | b) : ((uint64_t)b << 32 | a);
    size_t i = (size_t)((key * 0x9E3779B97F4A7C15ull) >> 20) & (map->capacity - 1);
    while (map->keys[i] != UINT64_MAX && map->keys[i] != key)
        i = (i + 1) & (map->capacity - 1);
    *found = map->keys[i] == key;
    map->keys[i] = key;
    return &map->values[i];
}

/* Icosahedron subdivided `levels` times, vertices on the unit sphere times
 * 1 + noise * uniform[0,1) (noise 0: convex). */
static void make_icosphere(struct mesh *m, int levels, double noise, uint64_t seed)
{
    const double g = (1.0 + sqrt(5.0)) / 2.0;
    const double base[12][3] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    static const uint32_t faces[20][3] = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    /* Work in double and round once at the end. */
    size_t vcap = 12 + 30 * ((size_t)1 << (2 * levels));
    double *v = bf_xrealloc(NULL, vcap * 3 * sizeof(double));
    size_t nv = 12;
    for (int i = 0; i < 12; i++) {
        double len = bf_length(base[i]);
        for (int k = 0; k < 3; k++)
            v[3 * i + k] = base[i][k] / len;
    }
    uint32_t *tris = bf_xrealloc(NULL, 20 * 3 * sizeof(uint32_t));
    memcpy(tris, faces, sizeof(faces));
    size_t nt = 20;
    for (int level = 0; level < levels; level++) {
        struct edge_map map;
        map.capacity = 1;
        while (map.capacity < 4 * nt)
            map.capacity *= 2;
        map.keys = bf_xrealloc(NULL, map.capacity * sizeof(uint64_t));
        map.values = bf_xrealloc(NULL, map.capacity * sizeof(uint32_t));
        memset(map.keys, 0xFF, map.capacity * sizeof(uint64_t));
        uint32_t *next = bf_xrealloc(NULL, nt * 4 * 3 * sizeof(uint32_t));
        for (size_t t = 0; t < nt; t++) {
            uint32_t mid[3];
            for (int e = 0; e < 3; e++) {
                uint32_t a = tris[3 * t + e], b = tris[3 * t + (e + 1) % 3];
                int found;
                uint32_t *slot = edge_map_slot(&map, a, b, &found);
                if (!found) {
                    double p[3];
                    for (int k = 0; k < 3; k++)
                        p[k] = v[3 * a + k] + v[3 * b + k];
                    double len = bf_length(p);
                    for (int k = 0; k < 3; k++)
                        v[3 * nv + k] = p[k] / len;
                    *slot = (uint32_t)nv++;
                }
                mid[e] = *slot;
            }
            const uint32_t *c = &tris[3 * t];
            uint32_t *o = &next[12 * t];
            const uint32_t quad[12] = {c[0],   mid[0], mid[2], mid[0], c[1],   mid[1],
                                       mid[2], mid[1], c[2],   mid[0], mid[1], mid[2]};
            memcpy(o, quad, sizeof(quad));
        }
        free(tris);
        free(map.keys);
        free(map.values);
        tris = next;
        nt *= 4;
    }
    struct bf_rng r;
    bf_seed(&r, seed);
    uint32_t vc = 0, tc = 0;
    for (size_t i = 0; i < nv; i++) {
        double s = 1.0 + noise * bf_uniform(&r), p[3];
        for (int k = 0; k < 3; k++)
            p[k] = v[3 * i + k] * s;
        add_vertex(m, &vc, p);
    }
    for (size_t t = 0; t < nt; t++)
        add_tri(m, &tc, tris[3 * t], tris[3 * t + 1], tris[3 * t + 2]);
    free(v);
    free(tris);
}

/* Cube [-1,1]^3, each face an n x n grid; vertices on shared cube edges are
 * created once (indexed by their integer lattice point). */
static void make_cube(struct mesh *m, int n)
{
    size_t side = (size_t)n + 1;
    uint32_t *id = bf_xrealloc(NULL, side * side * side * sizeof(uint32_t));
    memset(id, 0xFF, side * side * side * sizeof(uint32_t));
    uint32_t vc = 0, tc = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int s = 0; s <= n; s += n) {
            int u = (axis + 1) % 3, w = (axis + 2) % 3;
            uint32_t grid[17][17];
            for (int j = 0; j <= n; j++)
                for (int i = 0; i <= n; i++) {
                    int l[3];
                    l[axis] = s;
                    l[u] = i;
                    l[w] = j;
                    size_t key = ((size_t)l[0] * side + (size_t)l[1]) * side + (size_t)l[2];
                    if (id[key] == UINT32_MAX) {
                        double p[3];
                        for (int k = 0; k < 3; k++)
                            p[k] = -1.0 + 2.0 * l[k] / n;
                        id[key] = add_vertex(m, &vc, p);
                    }
                    grid[j][i] = id[key];
                }
            for (int j = 0; j < n; j++)
                for (int i = 0; i < n; i++) {
                    uint32_t a = grid[j][i], b = grid[j][i + 1], c = grid[j + 1][i + 1],
                             d = grid[j + 1][i];
                    if (s) {
                        add_tri(m, &tc, a, b, c);
                        add_tri(m, &tc, a, c, d);
                    } else {
                        add_tri(m, &tc, a, c, b);
                        add_tri(m, &tc, a, d, c);
                    }
                }
        }
    free(id);
}

/* Unique edges and vertex -> triangle adjacency; checks that the mesh is
 * closed (every edge in exactly two triangles). */
static int finish_mesh(struct mesh *m)
{
    struct edge_map map;
    map.capacity = 1;
    while (map.capacity < 4 * (size_t)m->tri_count)
        map.capacity *= 2;
    map.keys = bf_xrealloc(NULL, map.capacity * sizeof(uint64_t));
    map.values = bf_xrealloc(NULL, map.capacity * sizeof(uint32_t));
    memset(map.keys, 0xFF, map.capacity * sizeof(uint64_t));
    m->edges = bf_xrealloc(NULL, 3 * (size_t)m->tri_count * 2 * sizeof(uint32_t));
    uint32_t *uses = bf_xrealloc(NULL, 3 * (size_t)m->tri_count * sizeof(uint32_t));
    m->edge_count = 0;
    for (uint32_t t = 0; t < m->tri_count; t++)
        for (int e = 0; e < 3; e++) {
            uint32_t a = m->indices[3 * t + e], b = m->indices[3 * t + (e + 1) % 3];
            int found;
            uint32_t *slot = edge_map_slot(&map, a, b, &found);
            if (!found) {
                *slot = m->edge_count;
                uses[m->edge_count] = 0;
                m->edges[2 * m->edge_count] = a;
                m->edges[2 * m->edge_count + 1] = b;
                m->edge_count++;
            }
            uses[*slot]++;
        }
    int closed = 1;
    for (uint32_t e = 0; e < m->edge_count; e++)
        closed &= uses[e] == 2;
    free(uses);
    free(map.keys);
    free(map.values);
    m->vt_first = bf_xrealloc(NULL, ((size_t)m->vertex_count + 1) * sizeof(uint32_t));
    memset(m->vt_first, 0, ((size_t)m->vertex_count + 1) * sizeof(uint32_t));
    for (uint32_t i = 0; i < 3 * m->tri_count; i++)
        m->vt_first[m->indices[i] + 1]++;
    for (uint32_t v = 0; v < m->vertex_count; v++)
        m->vt_first[v + 1] += m->vt_first[v];
    m->vt_list = bf_xrealloc(NULL, 3 * (size_t)m->tri_count * sizeof(uint32_t));
    uint32_t *fill = bf_xrealloc(NULL, (size_t)m->vertex_count * sizeof(uint32_t));
    memcpy(fill, m->vt_first, (size_t)m->vertex_count * sizeof(uint32_t));
    for (uint32_t i = 0; i < 3 * m->tri_count; i++)
        m->vt_list[fill[m->indices[i]]++] = i / 3;
    free(fill);
    return closed;
}

static void free_mesh(struct mesh *m)
{
    free(m->positions);
    free(m->indices);
    free(m->edges);
    free(m->vt_first);
    free(m->vt_list);
}

static int touches(const struct mesh *m, uint32_t vertex, uint32_t tri)
{
    for (uint32_t i = m->vt_first[vertex]; i < m->vt_first[vertex + 1]; i++)
        if (m->vt_list[i] == tri)
            return 1;
    return 0;
}

static void define_mesh(const struct mesh *m)
{
    rtNewObject(m->name);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, m->positions);
    rtDrawElements(RT_TRIANGLES, (RTsizei)(3 * m->tri_count), RT_UNSIGNED_INT, m->indices);
    rtDisableClientState(RT_VERTEX_ARRAY);
    rtEndObject();
}

/* ---- rays ------------------------------------------------------------------ */

struct target {
    uint32_t a, b; /* the edge's endpoints (a == b for a vertex) */
};

struct batch {
    RTray *rays;
    struct target *targets;
    RThit *hits;
    RTboolean *occluded;
    int count;
};

static void object_point(const struct mesh *m, uint32_t v, double p[3])
{
    for (int k = 0; k < 3; k++)
        p[k] = m->positions[3 * (size_t)v + k];
}

/* Fills a batch for one instance (matrix mm) from inside or outside. */
static void make_batch(struct bf_rng *r, const struct mesh *m, const double mm[16], int inside,
                       struct batch *b)
{
    for (int i = 0; i < b->count; i++) {
        struct target *tg = &b->targets[i];
        double kind = bf_uniform(r);
        double target[3], pa[3], pb[3];
        if (kind < 0.25) {
            tg->a = tg->b = bf_below(r, m->vertex_count);
            object_point(m, tg->a, target);
        } else {
            uint32_t e = bf_below(r, m->edge_count);
            tg->a = m->edges[2 * e];
            tg->b = m->edges[2 * e + 1];
            object_point(m, tg->a, pa);
            object_point(m, tg->b, pb);
            double s = kind < 0.5 ? 0.5 : bf_uniform(r);
            for (int k = 0; k < 3; k++)
                target[k] = pa[k] + s * (pb[k] - pa[k]);
        }
        double org[3], u[3];
        bf_unit_vector(r, u);
        if (inside) {
            double radius = 0.4 * cbrt(bf_uniform(r));
            for (int k = 0; k < 3; k++)
                org[k] = radius * u[k];
        } else {
            /* Outward: the sum of the normals of the cube faces the target
             * lies on, or the radial direction for the spheres. */
            double out[3] = {0, 0, 0};
            if (m->convex == 2) {
                for (int k = 0; k < 3; k++)
                    if (fabs(target[k]) == 1.0)
                        out[k] = target[k];
            } else {
                memcpy(out, target, sizeof(out));
            }
            double len = bf_length(out);
            for (int k = 0; k < 3; k++)
                out[k] = out[k] / len + 0.5 * u[k]; /* within 30 degrees */
            len = bf_length(out);
            double dist = bf_range(r, 0.5, 3.0);
            for (int k = 0; k < 3; k++)
                org[k] = target[k] + dist * out[k] / len;
        }
        double wt[3], wo[3];
        bf_transform_point(mm, target, wt);
        bf_transform_point(mm, org, wo);
        RTray *ray = &b->rays[i];
        for (int k = 0; k < 3; k++) {
            ray->org[k] = (float)wo[k];
            ray->dir[k] = (float)(wt[k] - (double)ray->org[k]);
        }
        ray->tmin = 0.0f;
        ray->tmax = INFINITY;
    }
}

struct tally {
    long rays, misses, not_occluded, wrong_t, wrong_tri;
};

static void judge_batch(const struct mesh *m, const struct batch *b, RTuint instance,
                        struct tally *tl, const char *what)
{
    for (int i = 0; i < b->count; i++) {
        const RThit *h = &b->hits[i];
        const struct target *tg = &b->targets[i];
        tl->rays++;
        const char *problem = NULL;
        if (!(h->t < INFINITY)) {
            tl->misses++;
            problem = "miss";
        } else if (!b->occluded[i]) {
            tl->not_occluded++;
            problem = "hit but not occluded";
        } else if (m->convex ? fabs(h->t - 1.0) > T_TOLERANCE : h->t > 1.0 + T_TOLERANCE) {
            tl->wrong_t++;
            problem = "t is not at the target";
        } else if (m->convex &&
                   (h->instance != instance || h->object != m->name ||
                    !(touches(m, tg->a, h->primitive) || touches(m, tg->b, h->primitive)))) {
            tl->wrong_tri++;
            problem = "the hit triangle does not touch the target";
        }
        if (problem && tl->misses + tl->not_occluded + tl->wrong_t + tl->wrong_tri <= MAX_PRINTED)
            fprintf(stderr,
                    "  %s: %s: ray org (%.9g, %.9g, %.9g) dir (%.9g, %.9g, %.9g), target "
                    "vertices %u %u; hit t %.9g instance %u primitive %u\n",
                    what, problem, b->rays[i].org[0], b->rays[i].org[1], b->rays[i].org[2],
                    b->rays[i].dir[0], b->rays[i].dir[1], b->rays[i].dir[2], tg->a, tg->b, h->t,
                    h->instance, h->primitive);
    }
}

static void trace_batch(struct batch *b)
{
    rtTraceRays(b->count, b->rays, b->hits);
    rtOccludedRays(b->count, b->rays, b->occluded);
}

#define MESHES 3
#define PLACEMENTS 4

static void run(struct mesh *meshes, const char *config, int rays_per_batch, uint64_t seed)
{
    tu_section(config);
    RTcontext ctx = tu_make_context(config);
    for (int k = 0; k < MESHES; k++)
        define_mesh(&meshes[k]);
    CHECK_NO_ERR();
    struct bf_rng r;
    bf_seed(&r, seed);
    double matrices[MESHES][PLACEMENTS][16];
    rtBeginFrame();
    for (int k = 0; k < MESHES; k++)
        for (int p = 0; p < PLACEMENTS; p++) {
            double *mm = matrices[k][p];
            double t[16], a[16];
            bf_translation(t, 15.0 * p, 15.0 * k, -4.0);
            if (p == 0)
                bf_identity(a);
            else if (p == 1)
                bf_random_rotation(&r, a);
            else
                bf_random_affine(&r, a, 0.7, 1.4, 0.0);
            bf_mul(mm, t, a);
            rtLoadMatrixd(mm);
            rtInstantiateObject(meshes[k].name);
        }
    rtLoadIdentity();
    CHECK_NO_ERR();

    struct batch b;
    b.count = rays_per_batch;
    b.rays = bf_xrealloc(NULL, (size_t)b.count * sizeof(*b.rays));
    b.targets = bf_xrealloc(NULL, (size_t)b.count * sizeof(*b.targets));
    b.hits = bf_xrealloc(NULL, (size_t)b.count * sizeof(*b.hits));
    b.occluded = bf_xrealloc(NULL, (size_t)b.count);
    for (int k = 0; k < MESHES; k++) {
        struct tally tl;
        memset(&tl, 0, sizeof(tl));
        for (int p = 0; p < PLACEMENTS; p++)
            for (int inside = 0; inside < 2; inside++) {
                make_batch(&r, &meshes[k], matrices[k][p], inside, &b);
                trace_batch(&b);
                judge_batch(&meshes[k], &b, (RTuint)(k * PLACEMENTS + p), &tl, meshes[k].label);
            }
        printf("   %s: %ld rays, %ld misses, %ld not occluded, %ld off the target, %ld on a "
               "triangle away from the target\n",
               meshes[k].label, tl.rays, tl.misses, tl.not_occluded, tl.wrong_t, tl.wrong_tri);
        CHECK_INT(tl.misses, 0);
        CHECK_INT(tl.not_occluded, 0);
        CHECK_INT(tl.wrong_t, 0);
        CHECK_INT(tl.wrong_tri, 0);
    }
    CHECK_NO_ERR();
    free(b.rays);
    free(b.targets);
    free(b.hits);
    free(b.occluded);
    tu_destroy_context(ctx);
}

/* Rays from the exact centre of the cube (in place) to exact grid vertices
 * and exact edge midpoints: every coordinate is a small dyadic number. */
static void exact_cube(const struct mesh *cube)
{
    tu_section("exact rays from the centre of the cube");
    RTcontext ctx = tu_make_context(NULL);
    define_mesh(cube);
    rtBeginFrame();
    rtInstantiateObject(cube->name);
    struct batch b;
    b.count = (int)(cube->vertex_count + cube->edge_count);
    b.rays = bf_xrealloc(NULL, (size_t)b.count * sizeof(*b.rays));
    b.targets = bf_xrealloc(NULL, (size_t)b.count * sizeof(*b.targets));
    b.hits = bf_xrealloc(NULL, (size_t)b.count * sizeof(*b.hits));
    b.occluded = bf_xrealloc(NULL, (size_t)b.count);
    for (int i = 0; i < b.count; i++) {
        struct target *tg = &b.targets[i];
        if ((uint32_t)i < cube->vertex_count) {
            tg->a = tg->b = (uint32_t)i;
        } else {
            tg->a = cube->edges[2 * (i - cube->vertex_count)];
            tg->b = cube->edges[2 * (i - cube->vertex_count) + 1];
        }
        for (int k = 0; k < 3; k++) {
            b.rays[i].org[k] = 0.0f;
            b.rays[i].dir[k] =
                0.5f * (cube->positions[3 * tg->a + k] + cube->positions[3 * tg->b + k]);
        }
        b.rays[i].tmin = 0.0f;
        b.rays[i].tmax = INFINITY;
    }
    trace_batch(&b);
    struct tally tl;
    memset(&tl, 0, sizeof(tl));
    judge_batch(cube, &b, 0, &tl, "exact cube");
    printf("   %ld rays, %ld misses, %ld off the target, %ld on a triangle away from it\n", tl.rays,
           tl.misses, tl.wrong_t, tl.wrong_tri);
    CHECK_INT(tl.misses + tl.not_occluded + tl.wrong_t + tl.wrong_tri, 0);
    CHECK_NO_ERR();
    free(b.rays);
    free(b.targets);
    free(b.hits);
    free(b.occluded);
    tu_destroy_context(ctx);
}

int main(void)
{
    clock_t start = clock();
    struct mesh meshes[MESHES];
    memset(meshes, 0, sizeof(meshes));
    meshes[0].label = "icosphere";
    meshes[0].name = 1;
    meshes[0].convex = 1;
    make_icosphere(&meshes[0], 4, 0.0, 1);
    meshes[1].label = "cube";
    meshes[1].name = 2;
    meshes[1].convex = 2; /* convex, and its outward direction comes from its faces */
    make_cube(&meshes[1], 16);
    meshes[2].label = "bumpy icosphere";
    meshes[2].name = 3;
    meshes[2].convex = 0;
    make_icosphere(&meshes[2], 3, 0.2, 2);
    tu_section("meshes");
    for (int k = 0; k < MESHES; k++) {
        CHECK(finish_mesh(&meshes[k]));
        printf("   %s: %u vertices, %u edges, %u triangles\n", meshes[k].label,
               meshes[k].vertex_count, meshes[k].edge_count, meshes[k].tri_count);
    }
    CHECK_INT(meshes[0].tri_count, 5120);
    CHECK_INT(meshes[1].tri_count, 3072);

    run(meshes, "builder=binned", RAYS_PER_BATCH, 11);
    run(meshes, "builder=sweep", RAYS_PER_BATCH / 5, 12);
    exact_cube(&meshes[1]);
    for (int k = 0; k < MESHES; k++)
        free_mesh(&meshes[k]);
    printf("cpu time %.2f s\n", (double)(clock() - start) / CLOCKS_PER_SEC);
    return test_summary("stability_watertight");
}
