/* SPDX-License-Identifier: Apache-2.0 */
/*
 * anim_gen.c - the procedural animations of `rtbench dynamic` (bench.h,
 * bench_dynamic.c).
 *
 *   explode  a torus whose triangles (three vertices of their own each)
 *            fly apart, each along its normal with a random extra
 *            velocity: a refitted tree degrades fast (Wald, Ize and Parker (2008) fig. 3's
 *            exploding dragon);
 *   cloth    a waving grid, neighbours stay neighbours: refitting keeps
 *            the first tree good (Yoon, Curtis and Manocha's (2007) cloth benchmark);
 *   soup     N random triangles morphing from one random configuration to
 *            the next every BENCH_SOUP_KEY_FRAMES frames, each moving a
 *            random step (up to 0.75 per axis in a cube of side 4; the unstructured
 *            motion of BART's museum, Wald, Benthin and Slusallek (2003) sec. 5.3, in the shape of
 *            its worst case: uniformly random, never a surface).
 *
 * Frame f of an animation is a pure function of (kind, size, f): values
 * are computed in double from fixed hashes and rounded to float once, so
 * every strategy, Embree and the reference see bit-identical vertices.
 * All animations sit in front of the camera of bench_dynamic.c (at the
 * origin, looking down -z): no matrix is needed to place them.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define ANIM_PI 3.14159265358979323846

/* Distance of every animation's centre from the eye, along -z. */
#define ANIM_DEPTH 7.0

static uint64_t anim_mix(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

/* A number in [0, 1) that depends only on (a, b, c). */
static double anim_hash01(uint64_t a, uint64_t b, uint64_t c)
{
    uint64_t h = anim_mix(anim_mix(anim_mix(a) ^ b) ^ c);
    return (double)(h >> 11) * (1.0 / 9007199254740992.0);
}

/* Rotation about x by angle a, then the shift to the animation's depth. */
static void anim_place(double p[3], double a, float out[3])
{
    double c = cos(a), s = sin(a);
    double y = c * p[1] - s * p[2], z = s * p[1] + c * p[2];
    out[0] = (float)p[0];
    out[1] = (float)y;
    out[2] = (float)(z - ANIM_DEPTH);
}

static void torus_point(double u, double v, double p[3], double n[3])
{
    const double big = 1.3, small = 0.45;
    double cu = cos(u), su = sin(u), cv = cos(v), sv = sin(v);
    n[0] = cv * cu;
    n[1] = cv * su;
    n[2] = sv;
    p[0] = (big + small * cv) * cu;
    p[1] = (big + small * cv) * su;
    p[2] = small * sv;
}

int bench_anim_create(struct bench_anim *a, enum bench_anim_kind kind, uint32_t size, int frames)
{
    memset(a, 0, sizeof(*a));
    a->kind = kind;
    a->size = size;
    a->frames = frames;
    switch (kind) {
    case BENCH_ANIM_EXPLODE:
        /* size = quads around the torus; the tube has size / 2. */
        a->name = "explode";
        a->tri_count = 2 * size * (size / 2);
        a->vertex_count = 3 * a->tri_count;
        break;
    case BENCH_ANIM_CLOTH:
        a->name = "cloth";
        a->tri_count = 2 * size * size;
        a->vertex_count = (size + 1) * (size + 1);
        break;
    case BENCH_ANIM_SOUP:
        a->name = "soup";
        a->tri_count = size;
        a->vertex_count = 3 * size;
        break;
    default:
        return -1;
    }
    a->positions = malloc((size_t)a->vertex_count * 3 * sizeof(float));
    a->indices = malloc((size_t)a->tri_count * 3 * sizeof(uint32_t));
    if (!a->positions || !a->indices) {
        bench_anim_release(a);
        return -1;
    }
    if (kind == BENCH_ANIM_CLOTH) {
        uint32_t t = 0;
        for (uint32_t j = 0; j < size; j++)
            for (uint32_t i = 0; i < size; i++) {
                uint32_t v0 = j * (size + 1) + i, v1 = v0 + 1, v2 = v0 + size + 2,
                         v3 = v0 + size + 1;
                uint32_t *q = &a->indices[6 * t++];
                q[0] = v0, q[1] = v1, q[2] = v2;
                q[3] = v0, q[4] = v2, q[5] = v3;
            }
    } else {
        for (uint32_t k = 0; k < 3 * a->tri_count; k++)
            a->indices[k] = k;
    }
    bench_anim_frame(a, 0);
    return 0;
}

void bench_anim_release(struct bench_anim *a)
{
    free(a->positions);
    free(a->indices);
    memset(a, 0, sizeof(*a));
}

static void frame_explode(struct bench_anim *a, int f)
{
    const uint32_t nu = a->size, nv = a->size / 2;
    static const int corner[2][3][2] = {{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {1, 1}, {0, 1}}};
    uint32_t t = 0;
    for (uint32_t j = 0; j < nv; j++)
        for (uint32_t i = 0; i < nu; i++)
            for (int h = 0; h < 2; h++, t++) {
                double p[3][3], n[3][3], nc[3] = {0, 0, 0};
                for (int k = 0; k < 3; k++) {
                    double u = 2.0 * ANIM_PI * (i + corner[h][k][0]) / nu;
                    double v = 2.0 * ANIM_PI * (j + corner[h][k][1]) / nv;
                    torus_point(u, v, p[k], n[k]);
                    for (int c = 0; c < 3; c++)
                        nc[c] += n[k][c] / 3.0;
                }
                /* Along the normal at 0.01..0.04 per frame, plus up to
                 * 0.01 per frame in a random direction. */
                double speed = 0.01 + 0.03 * anim_hash01(1, t, 0);
                double vel[3];
                for (int c = 0; c < 3; c++)
                    vel[c] = nc[c] * speed + 0.02 * (anim_hash01(2, t, (uint64_t)c) - 0.5);
                for (int k = 0; k < 3; k++) {
                    double q[3];
                    for (int c = 0; c < 3; c++)
                        q[c] = p[k][c] + vel[c] * f;
                    anim_place(q, -1.0, &a->positions[9 * t + 3 * k]);
                }
            }
}

static void frame_cloth(struct bench_anim *a, int f)
{
    const uint32_t n = a->size;
    for (uint32_t j = 0; j <= n; j++)
        for (uint32_t i = 0; i <= n; i++) {
            double x = -2.2 + 4.4 * i / n, y = -2.2 + 4.4 * j / n;
            double q[3];
            q[0] = x + 0.08 * sin(1.5 * y + 0.25 * f);
            q[1] = y;
            q[2] = 0.35 * sin(2.0 * x + 0.3 * f) * cos(1.5 * y - 0.2 * f);
            anim_place(q, -0.9, &a->positions[3 * (j * (n + 1) + i)]);
        }
}

/* Coordinate c of vertex k of triangle t in soup key configuration key:
 * centres start uniform in a cube of side 4 and take a random step of up
 * to 0.75 per axis from one key to the next (reflected at the cube's
 * faces), so the soup is uniformly random at every key but a triangle
 * does not cross the whole cube in one morph (that would make a refitted
 * tree useless within one morph and a refit frame last seconds);
 * triangles of size about 2 / cbrt(N), so the density does not depend
 * on N. */
static double soup_key(uint32_t n, uint32_t t, int k, int c, int key)
{
    double s = 2.0 / cbrt((double)n);
    double x = 4.0 * anim_hash01(10, t, (uint64_t)c) - 2.0;
    for (int i = 1; i <= key; i++) {
        x += 1.5 * (anim_hash01(20 + (uint64_t)i, t, (uint64_t)c) - 0.5);
        x = x > 2.0 ? 4.0 - x : x < -2.0 ? -4.0 - x : x;
    }
    return x + s * (anim_hash01(1000 + (uint64_t)key, 3ull * t + (uint64_t)k, (uint64_t)c) - 0.5);
}

static void frame_soup(struct bench_anim *a, int f)
{
    int key = f / BENCH_SOUP_KEY_FRAMES;
    double w = (double)(f % BENCH_SOUP_KEY_FRAMES) / BENCH_SOUP_KEY_FRAMES;
    w = w * w * (3.0 - 2.0 * w); /* smoothstep: rest at every key */
    for (uint32_t t = 0; t < a->tri_count; t++)
        for (int k = 0; k < 3; k++) {
            double q[3];
            for (int c = 0; c < 3; c++) {
                double x0 = soup_key(a->tri_count, t, k, c, key);
                double x1 = w > 0.0 ? soup_key(a->tri_count, t, k, c, key + 1) : x0;
                q[c] = (1.0 - w) * x0 + w * x1;
            }
            anim_place(q, 0.0, &a->positions[9 * t + 3 * k]);
        }
}

void bench_anim_frame(struct bench_anim *a, int frame)
{
    switch (a->kind) {
    case BENCH_ANIM_EXPLODE:
        frame_explode(a, frame);
        break;
    case BENCH_ANIM_CLOTH:
        frame_cloth(a, frame);
        break;
    case BENCH_ANIM_SOUP:
        frame_soup(a, frame);
        break;
    }
}

struct bench_mesh bench_anim_mesh(const struct bench_anim *a)
{
    struct bench_mesh m;
    memset(&m, 0, sizeof(m));
    m.name = a->name;
    m.positions = a->positions;
    m.indices = a->indices;
    m.vertex_count = a->vertex_count;
    m.tri_count = a->tri_count;
    return m;
}
