/* SPDX-License-Identifier: Apache-2.0 */
/*
 * mesh_gen.c - the benchmark's procedural workloads (bench.h):
 *
 *   bumpy  a torus displaced along its tube normal by a sum of sines, as a
 *          regular grid of quads split into two triangles each: smooth,
 *          coherent, 1M triangles (50k with --quick).  Stands in for a
 *          scanned model without shipping one.
 *   gears  the three gears of the classic gears.c, triangulated exactly as
 *          Tracelist assembles gear()'s quad strips and quads (OpenGL 2.1
 *          sec. 2.6.1, lib/scene/assembly.c), placed as draw() places them
 *          at angle 0 and seen through its view rotation: 880 triangles,
 *          including the zero-area ones gear() produces where a strip
 *          repeats a vertex (GL rasterises nothing there, and a ray tracer
 *          must cope with them).
 *   soup   100k (10k with --quick) small triangles with random positions
 *          and orientations in a cube: no coherence for traversal to use.
 *
 * Each mesh carries the camera for its primary rays and a point light for
 * shadow rays.  Everything is deterministic (fixed seeds, bench_rng).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Grid of the bumpy torus: 2 * U * V triangles. */
#define BUMPY_U 1000
#define BUMPY_V 500
#define BUMPY_U_QUICK 200
#define BUMPY_V_QUICK 125
#define SOUP_TRIS 100000
#define SOUP_TRIS_QUICK 10000
/* Soup triangle size: vertices within +-SOUP_SIZE of the centre in a cube
 * of side 2, so a ray crossing the cube meets on the order of 20
 * triangles at full size. */
#define SOUP_SIZE 0.04f
/* Primary image aspect (bench_rays_primary's w/h is set by the caller;
 * the camera's vertical extent follows from it). */
#define CAMERA_TAN_X 0.57735027f /* 60 degrees horizontal field of view */

/* ------------------------------------------------------------ building */

struct builder {
    struct bench_mesh *mesh;
    uint32_t vertex_capacity;
    uint32_t tri_capacity;
    int failed;
};

static uint32_t add_vertex(struct builder *b, float x, float y, float z)
{
    struct bench_mesh *m = b->mesh;
    if (m->vertex_count == b->vertex_capacity) {
        uint32_t cap = b->vertex_capacity ? 2 * b->vertex_capacity : 1024;
        float *p = realloc(m->positions, (size_t)cap * 3 * sizeof(*p));
        if (!p) {
            b->failed = 1;
            return 0;
        }
        m->positions = p;
        b->vertex_capacity = cap;
    }
    float *p = &m->positions[3 * (size_t)m->vertex_count];
    p[0] = x;
    p[1] = y;
    p[2] = z;
    return m->vertex_count++;
}

static void add_triangle(struct builder *b, uint32_t i0, uint32_t i1, uint32_t i2)
{
    struct bench_mesh *m = b->mesh;
    if (b->failed)
        return;
    if (m->tri_count == b->tri_capacity) {
        uint32_t cap = b->tri_capacity ? 2 * b->tri_capacity : 1024;
        uint32_t *p = realloc(m->indices, (size_t)cap * 3 * sizeof(*p));
        if (!p) {
            b->failed = 1;
            return;
        }
        m->indices = p;
        b->tri_capacity = cap;
    }
    uint32_t *t = &m->indices[3 * (size_t)m->tri_count++];
    t[0] = i0;
    t[1] = i1;
    t[2] = i2;
}

static void normalize3(float v[3])
{
    float len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= len;
    v[1] /= len;
    v[2] /= len;
}

static void cross3(float out[3], const float a[3], const float b[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Bounds, then a camera that looks at the centre from direction `from`
 * (towards the eye) at `zoom` times the distance where the bounding sphere
 * fills the image's height (below 1 when the mesh's silhouette is much
 * smaller than its bounding sphere), and a light in direction `light_dir`
 * three radii out. */
static void finish_mesh(struct bench_mesh *m, const float from[3], const float light_dir[3],
                        float zoom)
{
    m->bounds = aabb_empty();
    for (uint32_t i = 0; i < m->vertex_count; i++)
        aabb_grow_point(&m->bounds, &m->positions[3 * (size_t)i]);
    float center[3], radius = 0.0f;
    for (int k = 0; k < 3; k++) {
        center[k] = 0.5f * (m->bounds.min[k] + m->bounds.max[k]);
        float h = 0.5f * (m->bounds.max[k] - m->bounds.min[k]);
        radius += h * h;
    }
    radius = sqrtf(radius);
    float dir[3] = {from[0], from[1], from[2]};
    normalize3(dir);
    struct bench_camera *c = &m->camera;
    /* 4:3 images: the vertical half-angle's tangent is 0.75 tan_x. */
    float dist = radius / (0.75f * CAMERA_TAN_X) * zoom;
    float world_up[3] = {0.0f, 0.0f, 1.0f};
    if (fabsf(dir[2]) > 0.99f) {
        world_up[1] = 1.0f;
        world_up[2] = 0.0f;
    }
    for (int k = 0; k < 3; k++) {
        c->eye[k] = center[k] + dist * dir[k];
        c->forward[k] = -dir[k];
    }
    cross3(c->right, c->forward, world_up);
    normalize3(c->right);
    cross3(c->up, c->right, c->forward);
    c->tan_x = CAMERA_TAN_X;
    float l[3] = {light_dir[0], light_dir[1], light_dir[2]};
    normalize3(l);
    for (int k = 0; k < 3; k++)
        m->light[k] = center[k] + 3.0f * radius * l[k];
}

/* ------------------------------------------------------------ bumpy */

static int gen_bumpy(struct bench_mesh *m, int quick)
{
    const uint32_t nu = quick ? BUMPY_U_QUICK : BUMPY_U;
    const uint32_t nv = quick ? BUMPY_V_QUICK : BUMPY_V;
    const double big_r = 1.0, small_r = 0.35;
    m->name = "bumpy";
    m->description =
        quick ? "displaced torus, 200 x 125 quads" : "displaced torus, 1000 x 500 quads";
    m->vertex_count = nu * nv;
    m->tri_count = 2 * nu * nv;
    m->positions = malloc((size_t)m->vertex_count * 3 * sizeof(float));
    m->indices = malloc((size_t)m->tri_count * 3 * sizeof(uint32_t));
    if (!m->positions || !m->indices)
        return -1;
    for (uint32_t i = 0; i < nu; i++) {
        double u = 2.0 * M_PI * i / nu;
        for (uint32_t j = 0; j < nv; j++) {
            double v = 2.0 * M_PI * j / nv;
            /* Three octaves of bumps; the integer frequencies keep the
             * surface periodic, so the grid closes without a seam. */
            double d = 0.040 * sin(7.0 * u) * sin(5.0 * v) + 0.015 * sin(23.0 * u + 11.0 * v) +
                       0.006 * sin(61.0 * u) * cos(43.0 * v);
            double rr = big_r + (small_r + d) * cos(v);
            float *p = &m->positions[3 * ((size_t)i * nv + j)];
            p[0] = (float)(rr * cos(u));
            p[1] = (float)(rr * sin(u));
            p[2] = (float)((small_r + d) * sin(v));
        }
    }
    uint32_t *t = m->indices;
    for (uint32_t i = 0; i < nu; i++) {
        uint32_t i1 = (i + 1) % nu;
        for (uint32_t j = 0; j < nv; j++) {
            uint32_t j1 = (j + 1) % nv;
            uint32_t a = i * nv + j, b = i1 * nv + j, c = i1 * nv + j1, d = i * nv + j1;
            t[0] = a;
            t[1] = b;
            t[2] = c;
            t[3] = a;
            t[4] = c;
            t[5] = d;
            t += 6;
        }
    }
    const float from[3] = {0.35f, -1.0f, 0.9f};
    const float light[3] = {-0.4f, -0.3f, 1.0f};
    /* The flat torus seen at 45 degrees covers about half its bounding
     * sphere's height. */
    finish_mesh(m, from, light, 0.7f);
    return 0;
}

/* ------------------------------------------------------------ gears */

/* Primitive assembly for gear(): vertices of the current rtBegin/rtEnd
 * pair go through a 4x3 placement matrix and are split into triangles by
 * the rules of lib/scene/assembly.c (quad i of a strip is 2i, 2i+1, 2i+3,
 * 2i+2; a quad a, b, c, d becomes a, b, c and a, c, d). */
enum gear_mode { GEAR_QUADS, GEAR_QUAD_STRIP };

struct gear_ctx {
    struct builder *b;
    double m[12]; /* row-major 3x4 object-to-eye placement */
    enum gear_mode mode;
    uint32_t first; /* first vertex of the current primitive */
    uint32_t emitted;
};

static void gear_begin(struct gear_ctx *g, enum gear_mode mode)
{
    g->mode = mode;
    g->first = g->b->mesh->vertex_count;
    g->emitted = 0;
}

/* Takes the float coordinates gear() computes (its locals are RTfloat and
 * rtVertex3f takes floats) and places them in double, as the library's
 * double modelview does. */
static void gear_vertex(struct gear_ctx *g, float x, float y, float z)
{
    double p[3];
    for (int r = 0; r < 3; r++)
        p[r] = g->m[4 * r] * x + g->m[4 * r + 1] * y + g->m[4 * r + 2] * z + g->m[4 * r + 3];
    add_vertex(g->b, (float)p[0], (float)p[1], (float)p[2]);
    uint32_t k = g->emitted++;
    uint32_t base = g->first;
    if (g->mode == GEAR_QUADS && k % 4 == 3) {
        add_triangle(g->b, base + k - 3, base + k - 2, base + k - 1);
        add_triangle(g->b, base + k - 3, base + k - 1, base + k);
    } else if (g->mode == GEAR_QUAD_STRIP && k >= 3 && k % 2 == 1) {
        uint32_t i = (k - 3) / 2;
        uint32_t v0 = base + 2 * i, v1 = v0 + 1, v2 = v0 + 3, v3 = v0 + 2;
        add_triangle(g->b, v0, v1, v2);
        add_triangle(g->b, v0, v2, v3);
    }
}

/* gear() of gears.c (Brian Paul, public domain), geometry only: the same
 * loops and the same float arithmetic; normals and shade model dropped. */
static void gear(struct gear_ctx *g, float inner_radius, float outer_radius, float width, int teeth,
                 float tooth_depth)
{
    int i;
    float r0, r1, r2;
    float angle, da;

    r0 = inner_radius;
    r1 = outer_radius - tooth_depth / 2.0;
    r2 = outer_radius + tooth_depth / 2.0;
    da = 2.0 * M_PI / teeth / 4.0;

    /* front face */
    gear_begin(g, GEAR_QUAD_STRIP);
    for (i = 0; i <= teeth; i++) {
        angle = i * 2.0 * M_PI / teeth;
        gear_vertex(g, r0 * cos(angle), r0 * sin(angle), width * 0.5);
        gear_vertex(g, r1 * cos(angle), r1 * sin(angle), width * 0.5);
        if (i < teeth) {
            gear_vertex(g, r0 * cos(angle), r0 * sin(angle), width * 0.5);
            gear_vertex(g, r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), width * 0.5);
        }
    }
    /* front sides of teeth */
    gear_begin(g, GEAR_QUADS);
    for (i = 0; i < teeth; i++) {
        angle = i * 2.0 * M_PI / teeth;
        gear_vertex(g, r1 * cos(angle), r1 * sin(angle), width * 0.5);
        gear_vertex(g, r2 * cos(angle + da), r2 * sin(angle + da), width * 0.5);
        gear_vertex(g, r2 * cos(angle + 2 * da), r2 * sin(angle + 2 * da), width * 0.5);
        gear_vertex(g, r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), width * 0.5);
    }
    /* back face */
    gear_begin(g, GEAR_QUAD_STRIP);
    for (i = 0; i <= teeth; i++) {
        angle = i * 2.0 * M_PI / teeth;
        gear_vertex(g, r1 * cos(angle), r1 * sin(angle), -width * 0.5);
        gear_vertex(g, r0 * cos(angle), r0 * sin(angle), -width * 0.5);
        if (i < teeth) {
            gear_vertex(g, r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), -width * 0.5);
            gear_vertex(g, r0 * cos(angle), r0 * sin(angle), -width * 0.5);
        }
    }
    /* back sides of teeth */
    gear_begin(g, GEAR_QUADS);
    for (i = 0; i < teeth; i++) {
        angle = i * 2.0 * M_PI / teeth;
        gear_vertex(g, r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), -width * 0.5);
        gear_vertex(g, r2 * cos(angle + 2 * da), r2 * sin(angle + 2 * da), -width * 0.5);
        gear_vertex(g, r2 * cos(angle + da), r2 * sin(angle + da), -width * 0.5);
        gear_vertex(g, r1 * cos(angle), r1 * sin(angle), -width * 0.5);
    }
    /* outward faces of teeth */
    gear_begin(g, GEAR_QUAD_STRIP);
    for (i = 0; i < teeth; i++) {
        angle = i * 2.0 * M_PI / teeth;
        gear_vertex(g, r1 * cos(angle), r1 * sin(angle), width * 0.5);
        gear_vertex(g, r1 * cos(angle), r1 * sin(angle), -width * 0.5);
        gear_vertex(g, r2 * cos(angle + da), r2 * sin(angle + da), width * 0.5);
        gear_vertex(g, r2 * cos(angle + da), r2 * sin(angle + da), -width * 0.5);
        gear_vertex(g, r2 * cos(angle + 2 * da), r2 * sin(angle + 2 * da), width * 0.5);
        gear_vertex(g, r2 * cos(angle + 2 * da), r2 * sin(angle + 2 * da), -width * 0.5);
        gear_vertex(g, r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), width * 0.5);
        gear_vertex(g, r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), -width * 0.5);
    }
    gear_vertex(g, r1 * cos(0), r1 * sin(0), width * 0.5);
    gear_vertex(g, r1 * cos(0), r1 * sin(0), -width * 0.5);
    /* inside radius cylinder */
    gear_begin(g, GEAR_QUAD_STRIP);
    for (i = 0; i <= teeth; i++) {
        angle = i * 2.0 * M_PI / teeth;
        gear_vertex(g, r0 * cos(angle), r0 * sin(angle), -width * 0.5);
        gear_vertex(g, r0 * cos(angle), r0 * sin(angle), width * 0.5);
    }
}

/* Row-major 3x4 product out = a * b. */
static void mul34(double out[12], const double a[12], const double b[12])
{
    double r[12];
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 4; j++) {
            double s = a[4 * i] * b[j] + a[4 * i + 1] * b[4 + j] + a[4 * i + 2] * b[8 + j];
            if (j == 3)
                s += a[4 * i + 3];
            r[4 * i + j] = s;
        }
    }
    memcpy(out, r, sizeof(r));
}

/* glRotatef(angle_deg, axis) as a 3x4 matrix, axis x, y or z. */
static void rotation(double m[12], double angle_deg, int axis)
{
    double a = angle_deg * M_PI / 180.0, c = cos(a), s = sin(a);
    memset(m, 0, 12 * sizeof(double));
    int i = (axis + 1) % 3, j = (axis + 2) % 3;
    m[4 * axis + axis] = 1.0;
    m[4 * i + i] = c;
    m[4 * i + j] = -s;
    m[4 * j + i] = s;
    m[4 * j + j] = c;
}

static void translation(double m[12], double x, double y, double z)
{
    memset(m, 0, 12 * sizeof(double));
    m[0] = m[5] = m[10] = 1.0;
    m[3] = x;
    m[7] = y;
    m[11] = z;
}

static int gen_gears(struct bench_mesh *m)
{
    struct builder b = {m, 0, 0, 0};
    m->name = "gears";
    m->description = "the three gears of gears.c at angle 0, seen as draw() sees them";
    /* draw(): the view rotation (view_rotx = 20, view_roty = 30), then
     * each gear's translation and rotation at angle 0.  reshape()'s
     * translation by -40 is the camera's distance below. */
    double view[12], rx[12], ry[12];
    rotation(rx, 20.0, 0);
    rotation(ry, 30.0, 1);
    mul34(view, rx, ry);
    static const struct {
        double x, y, rot;
        float inner, outer, width;
        int teeth;
    } gears[3] = {
        {-3.0, -2.0, 0.0, 1.0f, 4.0f, 1.0f, 20},
        {3.1, -2.0, -9.0, 0.5f, 2.0f, 2.0f, 10},
        {-3.1, 4.2, -25.0, 1.3f, 2.0f, 0.5f, 10},
    };
    for (int i = 0; i < 3; i++) {
        struct gear_ctx g;
        double t[12], r[12];
        memset(&g, 0, sizeof(g));
        g.b = &b;
        translation(t, gears[i].x, gears[i].y, 0.0);
        rotation(r, gears[i].rot, 2);
        mul34(g.m, view, t);
        mul34(g.m, g.m, r);
        gear(&g, gears[i].inner, gears[i].outer, gears[i].width, gears[i].teeth, 0.7f);
    }
    if (b.failed)
        return -1;
    /* The camera of reshape(): eye at the origin of eye space, 40 units
     * in front of the scene, glFrustum(-1, 1, -h, h, 5, 60) gives a
     * horizontal half-angle tangent of 1/5.  Light: draw()'s (5, 5, 10)
     * direction. */
    m->bounds = aabb_empty();
    for (uint32_t i = 0; i < m->vertex_count; i++)
        aabb_grow_point(&m->bounds, &m->positions[3 * (size_t)i]);
    struct bench_camera *c = &m->camera;
    const float eye[3] = {0.0f, 0.0f, 40.0f}, fwd[3] = {0.0f, 0.0f, -1.0f};
    const float right[3] = {1.0f, 0.0f, 0.0f}, up[3] = {0.0f, 1.0f, 0.0f};
    memcpy(c->eye, eye, sizeof(eye));
    memcpy(c->forward, fwd, sizeof(fwd));
    memcpy(c->right, right, sizeof(right));
    memcpy(c->up, up, sizeof(up));
    c->tan_x = 0.2f;
    float l[3] = {5.0f, 5.0f, 10.0f};
    normalize3(l);
    for (int k = 0; k < 3; k++)
        m->light[k] = 30.0f * l[k];
    return 0;
}

/* ------------------------------------------------------------ soup */

static int gen_soup(struct bench_mesh *m, int quick)
{
    const uint32_t n = quick ? SOUP_TRIS_QUICK : SOUP_TRIS;
    m->name = "soup";
    m->description = quick ? "10k random triangles in a cube" : "100k random triangles in a cube";
    m->vertex_count = 3 * n;
    m->tri_count = n;
    m->positions = malloc((size_t)m->vertex_count * 3 * sizeof(float));
    m->indices = malloc((size_t)m->tri_count * 3 * sizeof(uint32_t));
    if (!m->positions || !m->indices)
        return -1;
    struct bench_rng rng;
    bench_rng_seed(&rng, 0x50u);
    for (uint32_t i = 0; i < n; i++) {
        float c[3];
        for (int k = 0; k < 3; k++)
            c[k] = 2.0f * bench_rng_float(&rng) - 1.0f;
        for (int v = 0; v < 3; v++) {
            float *p = &m->positions[3 * (3 * (size_t)i + v)];
            for (int k = 0; k < 3; k++)
                p[k] = c[k] + SOUP_SIZE * (2.0f * bench_rng_float(&rng) - 1.0f);
            m->indices[3 * (size_t)i + v] = 3 * i + v;
        }
    }
    const float from[3] = {0.6f, -1.0f, 0.45f};
    const float light[3] = {0.3f, 0.5f, 1.0f};
    finish_mesh(m, from, light, 0.8f);
    return 0;
}

/* ------------------------------------------------------------ public */

int bench_mesh_generate(struct bench_mesh *mesh, enum bench_mesh_kind kind, int quick)
{
    memset(mesh, 0, sizeof(*mesh));
    int rc = -1;
    switch (kind) {
    case BENCH_MESH_BUMPY:
        rc = gen_bumpy(mesh, quick);
        break;
    case BENCH_MESH_GEARS:
        rc = gen_gears(mesh);
        break;
    case BENCH_MESH_SOUP:
        rc = gen_soup(mesh, quick);
        break;
    case BENCH_MESH_COUNT:
        break;
    }
    if (rc)
        bench_mesh_release(mesh);
    return rc;
}

void bench_mesh_release(struct bench_mesh *mesh)
{
    free(mesh->positions);
    free(mesh->indices);
    memset(mesh, 0, sizeof(*mesh));
}

struct aabb *bench_mesh_boxes(const struct bench_mesh *mesh)
{
    struct aabb *boxes = malloc((size_t)(mesh->tri_count ? mesh->tri_count : 1) * sizeof(*boxes));
    if (!boxes)
        return NULL;
    for (uint32_t j = 0; j < mesh->tri_count; j++) {
        boxes[j] = aabb_empty();
        for (int c = 0; c < 3; c++)
            aabb_grow_point(&boxes[j],
                            &mesh->positions[3 * (size_t)mesh->indices[3 * (size_t)j + c]]);
    }
    return boxes;
}
