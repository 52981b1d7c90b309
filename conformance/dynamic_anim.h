/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dynamic_anim.h - procedural animations and the reference comparison
 * shared by the dynamic-scene tests (dynamic_strategies.c,
 * dynamic_stiff.c, dynamic_threads.c).
 *
 * Header only (static inline, like brute_force.h).  It provides:
 *   - three deforming objects whose vertices are a pure function of
 *     (vertex, frame), so a test can define, redefine or update them in any
 *     order and always describe the same geometry:
 *       DA_SPHERE  a tessellated sphere exploding: every triangle has its
 *                  own three vertices and flies off along its normal while
 *                  spinning (Wald, Ize and Parker's (2008) "exploding dragon" in small);
 *       DA_CLOTH   a waving grid drawn with rtDrawElements from a vertex
 *                  array whose first DA_CLOTH_OFFSET elements no index
 *                  uses, so object vertex k is array element
 *                  DA_CLOTH_OFFSET + k (docs/arrays.md);
 *       DA_SOUP    random triangles morphing between random key frames
 *                  (the incoherent motion of BART, Wald, Ize and Parker (2008) sec. 7);
 *       DA_BIG     a larger waving grid (DA_BIG_N^2 * 2 triangles), above
 *                  the size from which updates run on the context's worker
 *                  threads (PARALLEL_UPDATE_MIN_TRIANGLES in update.c);
 *       DA_POPPER  a grid whose resolution changes every frame: its
 *                  topology changes, so it can only be redefined and is
 *                  rebuilt lazily, by whichever render thread reaches it;
 *   - definition by rtBegin/rtDrawElements and update by rtUpdateVertices
 *     (the sphere as floats, the soup as doubles with a 32-byte stride,
 *     the cloth as floats from the array);
 *   - the scene (one instance of each, fixed rotated matrices), a frustum
 *     camera and a fixed set of rays;
 *   - da_strategies: every update strategy, each test's outer loop;
 *   - da_compare_hits: closest hits against a reference (same primitive
 *     and t within DA_T_REL relative, or, where two triangles are equally
 *     close, any of them at that distance).
 *
 * Every value is computed in double from a fixed seed and rounded to float
 * once, so the test context and the reference context receive
 * bit-identical vertices.
 */
#ifndef RT_CONFORMANCE_DYNAMIC_ANIM_H
#define RT_CONFORMANCE_DYNAMIC_ANIM_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <rt/rt.h>

/* Object names: each animation kind k is object DA_NAME_BASE + k. */
#define DA_NAME_BASE 700u
enum { DA_SPHERE, DA_CLOTH, DA_SOUP, DA_BIG, DA_POPPER, DA_KINDS };

#define DA_SPHERE_STACKS 12
#define DA_SPHERE_SLICES 24
#define DA_SPHERE_TRIS (2 * DA_SPHERE_STACKS * DA_SPHERE_SLICES)
#define DA_CLOTH_N 40
#define DA_BIG_N 104
/* Array elements in front of the cloth's first used element. */
#define DA_CLOTH_OFFSET 7
#define DA_SOUP_TRIS 800

/* Image size of the rendered comparisons. */
#define DA_WIDTH 64
#define DA_HEIGHT 48
#define DA_PIXELS (4 * DA_WIDTH * DA_HEIGHT)

/* Relative tolerance of t between a tested and a reference hit. */
#define DA_T_REL 1e-5

/* Every update strategy (RT_ASYNC_REBUILD where the header has it). */
static const RTenum da_strategies[] = {RT_REFIT,
                                       RT_REBUILD,
                                       RT_REBUILD_MEDIAN,
                                       RT_REBUILD_HEURISTIC,
                                       RT_RESTRUCTURE,
#ifdef RT_ASYNC_REBUILD
                                       RT_ASYNC_REBUILD,
#endif
                                       RT_AUTOMATIC};
#define DA_STRATEGY_COUNT ((int)(sizeof(da_strategies) / sizeof(da_strategies[0])))

/* ---- fixed-seed numbers (splitmix64) ---------------------------------- */

static inline uint64_t da_mix(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

/* A number in [0, 1) that depends only on (a, b, c). */
static inline double da_hash01(uint64_t a, uint64_t b, uint64_t c)
{
    uint64_t h = da_mix(da_mix(da_mix(a) ^ b) ^ c);
    return (double)(h >> 11) * (1.0 / 9007199254740992.0);
}

/* ---- geometry ------------------------------------------------------------ */

/* Grid resolution of a grid kind at frame f (0 for the other kinds). */
static inline int da_grid_n(int kind, int f)
{
    return kind == DA_CLOTH ? DA_CLOTH_N
           : kind == DA_BIG ? DA_BIG_N
           : kind == DA_POPPER ? 4 + 3 * (f % 3)
                               : 0;
}

static inline int da_is_grid(int kind)
{
    return kind == DA_CLOTH || kind == DA_BIG || kind == DA_POPPER;
}

/* Vertices of kind at frame f, in recording order (the numbering
 * rtUpdateVertices uses). */
static inline int da_vertex_count(int kind, int f)
{
    if (da_is_grid(kind)) {
        int n = da_grid_n(kind, f);
        return (n + 1) * (n + 1);
    }
    return kind == DA_SPHERE ? 3 * DA_SPHERE_TRIS : 3 * DA_SOUP_TRIS;
}

static inline int da_tri_count(int kind, int f)
{
    if (da_is_grid(kind)) {
        int n = da_grid_n(kind, f);
        return 2 * n * n;
    }
    return kind == DA_SPHERE ? DA_SPHERE_TRIS : DA_SOUP_TRIS;
}

static inline void da_sphere_point(int stack, int slice, double p[3])
{
    double theta = 3.141592653589793 * stack / DA_SPHERE_STACKS;
    double phi = 6.283185307179586 * slice / DA_SPHERE_SLICES;
    p[0] = sin(theta) * cos(phi);
    p[1] = cos(theta);
    p[2] = sin(theta) * sin(phi);
}

/* Rotates p about the unit axis a through c by angle (Rodrigues). */
static inline void da_rotate_about(double p[3], const double c[3], const double a[3],
                                   double angle)
{
    double v[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};
    double cs = cos(angle), sn = sin(angle);
    double d = a[0] * v[0] + a[1] * v[1] + a[2] * v[2];
    double x[3] = {a[1] * v[2] - a[2] * v[1], a[2] * v[0] - a[0] * v[2],
                   a[0] * v[1] - a[1] * v[0]};
    for (int k = 0; k < 3; k++)
        p[k] = c[k] + v[k] * cs + x[k] * sn + a[k] * d * (1.0 - cs);
}

/* Sphere vertices (3 per triangle) at frame f.  The triangles at the poles
 * are degenerate (two equal vertices) and stay so: never hit. */
static inline void da_sphere_frame(int f, double *out)
{
    static const int split[2][3] = {{0, 1, 2}, {0, 2, 3}};
    int t = 0;
    for (int j = 0; j < DA_SPHERE_STACKS; j++)
        for (int i = 0; i < DA_SPHERE_SLICES; i++) {
            double q[4][3];
            da_sphere_point(j, i, q[0]);
            da_sphere_point(j, i + 1, q[1]);
            da_sphere_point(j + 1, i + 1, q[2]);
            da_sphere_point(j + 1, i, q[3]);
            for (int h = 0; h < 2; h++, t++) {
                double tri[3][3], c[3] = {0, 0, 0};
                for (int k = 0; k < 3; k++)
                    for (int a = 0; a < 3; a++) {
                        tri[k][a] = q[split[h][k]][a];
                        c[a] += tri[k][a] / 3.0;
                    }
                double len = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
                double speed = 0.08 + 0.12 * da_hash01(1, (uint64_t)t, 0);
                double axis[3];
                for (int a = 0; a < 3; a++)
                    axis[a] = da_hash01(2, (uint64_t)t, (uint64_t)a) - 0.5;
                double al = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
                for (int a = 0; a < 3; a++)
                    axis[a] = al > 0 ? axis[a] / al : (a == 1);
                double spin = 0.35 * f * da_hash01(3, (uint64_t)t, 0);
                double move[3];
                for (int a = 0; a < 3; a++)
                    move[a] = (len > 0 ? c[a] / len : 0) * speed * f;
                move[1] -= 0.01 * f * f; /* a little gravity */
                for (int k = 0; k < 3; k++) {
                    da_rotate_about(tri[k], c, axis, spin);
                    for (int a = 0; a < 3; a++)
                        out[9 * t + 3 * k + a] = tri[k][a] + move[a];
                }
            }
        }
}

/* Grid vertices ((n+1)^2, row by row) of a waving n x n grid at frame f. */
static inline void da_grid_frame(int n, int f, double *out)
{
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double x = -1.0 + 2.0 * i / n, y = -1.0 + 2.0 * j / n;
            double *p = &out[3 * (j * (n + 1) + i)];
            p[0] = x + 0.04 * sin(2.0 * y + 0.5 * f);
            p[1] = y;
            p[2] = 0.25 * sin(3.0 * x + 0.6 * f) * cos(2.0 * y - 0.4 * f) + 0.04 * f * x * y;
        }
}

/* Soup key frame `key` of vertex v. */
static inline void da_soup_key(int v, int key, double p[3])
{
    int t = v / 3;
    for (int a = 0; a < 3; a++) {
        double centre = 2.0 * da_hash01(10 + (uint64_t)key, (uint64_t)t, (uint64_t)a) - 1.0;
        double jitter = 0.5 * da_hash01(20 + (uint64_t)key, (uint64_t)v, (uint64_t)a) - 0.25;
        p[a] = centre + jitter;
    }
}

/* Soup vertices at frame f: key frames 3 frames apart, linear in between. */
static inline void da_soup_frame(int f, double *out)
{
    int key = f / 3;
    double alpha = (f % 3) / 3.0;
    for (int v = 0; v < 3 * DA_SOUP_TRIS; v++) {
        double a[3], b[3];
        da_soup_key(v, key, a);
        da_soup_key(v, key + 1, b);
        for (int k = 0; k < 3; k++)
            out[3 * v + k] = (1.0 - alpha) * a[k] + alpha * b[k];
    }
}

/* Vertices of animation `kind` at frame f (3 doubles per vertex). */
static inline void da_frame(int kind, int f, double *out)
{
    if (kind == DA_SPHERE)
        da_sphere_frame(f, out);
    else if (kind == DA_SOUP)
        da_soup_frame(f, out);
    else
        da_grid_frame(da_grid_n(kind, f), f, out);
}

/* Triangle indices of an n x n grid into a vertex array whose grid
 * vertices start at element `offset`. */
static inline void da_grid_indices(int n, uint32_t offset, uint32_t *idx)
{
    int k = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            uint32_t a = (uint32_t)(j * (n + 1) + i) + offset;
            uint32_t b = a + 1, c = a + (uint32_t)n + 2, d = a + (uint32_t)n + 1;
            uint32_t tri[6] = {a, b, c, a, c, d};
            for (int m = 0; m < 6; m++)
                idx[k++] = tri[m];
        }
}

/*
 * Defines (or redefines) object `name` as animation `kind` at frame f with
 * the same calls every time, so a redefinition has the same topology
 * (except DA_POPPER, whose resolution changes).  Grids are drawn with
 * rtDrawElements from an array whose first DA_CLOTH_OFFSET elements no
 * index uses (and hold values that would be rejected if read); the others
 * with rtBegin(RT_TRIANGLES), the sphere with rtVertex3f, the soup with
 * rtVertex3d.  The modelview must be the identity.
 */
static inline void da_define(RTuint name, int kind, int f)
{
    int nv = da_vertex_count(kind, f);
    double *p = (double *)malloc(3 * sizeof(double) * (size_t)nv);
    da_frame(kind, f, p);
    rtNewObject(name);
    if (da_is_grid(kind)) {
        int n = da_grid_n(kind, f);
        uint32_t *idx = (uint32_t *)malloc(6 * sizeof(uint32_t) * (size_t)n * (size_t)n);
        float *arr = (float *)malloc(3 * sizeof(float) * (size_t)(nv + DA_CLOTH_OFFSET));
        for (int k = 0; k < 3 * DA_CLOTH_OFFSET; k++)
            arr[k] = nanf("");
        for (int k = 0; k < 3 * nv; k++)
            arr[3 * DA_CLOTH_OFFSET + k] = (float)p[k];
        da_grid_indices(n, DA_CLOTH_OFFSET, idx);
        rtVertexPointer(3, RT_FLOAT, 0, arr);
        rtEnableClientState(RT_VERTEX_ARRAY);
        rtDrawElements(RT_TRIANGLES, 6 * n * n, RT_UNSIGNED_INT, idx);
        rtDisableClientState(RT_VERTEX_ARRAY);
        rtVertexPointer(3, RT_FLOAT, 0, NULL);
        free(arr);
        free(idx);
    } else {
        rtBegin(RT_TRIANGLES);
        for (int v = 0; v < nv; v++) {
            if (kind == DA_SPHERE)
                rtVertex3f((float)p[3 * v], (float)p[3 * v + 1], (float)p[3 * v + 2]);
            else
                rtVertex3d(p[3 * v], p[3 * v + 1], p[3 * v + 2]);
        }
        rtEnd();
    }
    rtEndObject();
    free(p);
}

/* Moves object `name` (defined by da_define at an earlier frame) to frame f
 * with rtUpdateVertices: floats for the sphere, doubles with a 32-byte
 * stride for the soup, floats in two overlapping batches for the grids.
 * DA_POPPER cannot be updated (its vertex count changes): redefined. */
static inline void da_update(RTuint name, int kind, int f)
{
    if (kind == DA_POPPER) {
        da_define(name, kind, f);
        return;
    }
    int nv = da_vertex_count(kind, f);
    double *p = (double *)malloc(4 * sizeof(double) * (size_t)nv);
    da_frame(kind, f, p);
    if (kind == DA_SOUP) {
        /* Spread to 4 doubles per element; the fourth is a NaN that a
         * reader honouring the stride never sees. */
        for (int v = nv - 1; v >= 0; v--) {
            double x = p[3 * v], y = p[3 * v + 1], z = p[3 * v + 2];
            p[4 * v] = x;
            p[4 * v + 1] = y;
            p[4 * v + 2] = z;
            p[4 * v + 3] = nan("");
        }
        rtUpdateVertices(name, RT_VERTEX_ARRAY, 0, nv, RT_DOUBLE, 4 * sizeof(double), p);
    } else {
        float *q = (float *)malloc(3 * sizeof(float) * (size_t)nv);
        for (int k = 0; k < 3 * nv; k++)
            q[k] = (float)p[k];
        if (kind == DA_SPHERE) {
            rtUpdateVertices(name, RT_VERTEX_ARRAY, 0, nv, RT_FLOAT, 0, q);
        } else {
            int half = nv / 2;
            rtUpdateVertices(name, RT_VERTEX_ARRAY, 0, half + 10, RT_FLOAT, 0, q);
            rtUpdateVertices(name, RT_VERTEX_ARRAY, half, nv - half, RT_FLOAT, 0, q + 3 * half);
        }
        free(q);
    }
    free(p);
}

/* ---- scene, camera and rays ------------------------------------------------ */

/* The instance matrix of animation kind (applied to the modelview). */
static inline void da_place(int kind)
{
    if (kind == DA_SPHERE) {
        rtTranslatef(-1.3f, 0.35f, -6.5f);
        rtRotatef(20.0f, 1.0f, 1.0f, 0.0f);
    } else if (kind == DA_CLOTH) {
        rtTranslatef(1.4f, -0.2f, -7.0f);
        rtRotatef(-55.0f, 1.0f, 0.2f, 0.0f);
        rtScalef(1.2f, 1.0f, 1.0f);
    } else if (kind == DA_BIG) {
        rtTranslatef(0.0f, 0.0f, -11.0f);
        rtRotatef(-10.0f, 1.0f, 0.3f, 0.0f);
        rtScalef(5.0f, 4.0f, 2.0f);
    } else if (kind == DA_POPPER) {
        rtTranslatef(-1.6f, -1.3f, -5.0f);
        rtRotatef(40.0f, 0.2f, 1.0f, 0.3f);
        rtScalef(0.5f, 0.5f, 0.5f);
    } else {
        rtTranslatef(0.1f, -0.5f, -5.5f);
        rtRotatef(33.0f, 0.3f, 1.0f, 0.1f);
        rtScalef(0.8f, 0.8f, 0.8f);
    }
}

/* Issues the frame's instances: one of each kind listed in kinds[0..n). */
static inline void da_instantiate(const int *kinds, int n)
{
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtBeginFrame();
    for (int i = 0; i < n; i++) {
        rtPushMatrix();
        da_place(kinds[i]);
        rtInstantiateObject(DA_NAME_BASE + (RTuint)kinds[i]);
        rtPopMatrix();
    }
}

/* Frustum camera looking down -z, eye-light shading, 64x48 viewport. */
static inline void da_camera(void)
{
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-0.5, 0.5, -0.375, 0.375, 1.0, 100.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtShadingMode(RT_EYE_LIGHT);
    rtClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    rtViewport(0, 0, DA_WIDTH, DA_HEIGHT);
}

/* n fixed rays: half from the eye into the view, half between random
 * points around the scene, all world space. */
static inline void da_rays(RTray *rays, int n, uint64_t seed)
{
    for (int i = 0; i < n; i++) {
        RTray *r = &rays[i];
        double h[6];
        for (int k = 0; k < 6; k++)
            h[k] = da_hash01(seed, (uint64_t)i, (uint64_t)k);
        double org[3], target[3];
        if (i % 2 == 0) {
            org[0] = org[1] = org[2] = 0.0;
            target[0] = (h[0] - 0.5) * 1.0;
            target[1] = (h[1] - 0.5) * 0.75;
            target[2] = -1.0;
        } else {
            double z = 2.0 * h[0] - 1.0, phi = 6.283185307179586 * h[1];
            double s = sqrt(1.0 - z * z);
            org[0] = 7.0 * s * cos(phi);
            org[1] = 7.0 * s * sin(phi);
            org[2] = -6.0 + 7.0 * z;
            target[0] = -2.8 + 5.6 * h[2];
            target[1] = -2.0 + 4.0 * h[3];
            target[2] = -8.5 + 4.0 * h[4];
        }
        for (int k = 0; k < 3; k++) {
            r->org[k] = (float)org[k];
            r->dir[k] = (float)(target[k] - org[k]);
        }
        r->tmin = 0.0f;
        r->tmax = INFINITY;
    }
}

/* ---- comparison -------------------------------------------------------------- */

struct da_compare_stats {
    long rays;
    long hits;
    long same_prim_t_not_bitwise; /* same primitive, t equal within tolerance only */
    long ties;                    /* another primitive at the same distance */
    long mismatches;
};

static inline int da_t_close(float t, float ref)
{
    double tol = DA_T_REL * fmax(1.0, fabs((double)ref));
    return fabs((double)t - (double)ref) <= tol;
}

/*
 * Compares hits[0..n) with ref[0..n).  A hit agrees when both miss, or
 * both name the same instance, object and primitive with t within
 * DA_T_REL (relative) and u, v within 1e-4, or when a different primitive
 * is hit at the reference distance (two triangles equally close: an edge
 * shared by both, or coincident faces).  Prints the first few
 * disagreements with `label` and returns their count.
 */
static inline long da_compare_hits(const RThit *hits, const RThit *ref, int n,
                                   const char *label, struct da_compare_stats *st)
{
    long bad = 0;
    for (int i = 0; i < n; i++) {
        const RThit *a = &hits[i], *b = &ref[i];
        int ok;
        st->rays++;
        if (b->t == INFINITY || a->t == INFINITY) {
            ok = a->t == b->t && a->primitive == b->primitive && a->object == b->object;
        } else {
            st->hits++;
            if (a->instance == b->instance && a->object == b->object &&
                a->primitive == b->primitive) {
                ok = da_t_close(a->t, b->t) && fabsf(a->u - b->u) <= 1e-4f &&
                     fabsf(a->v - b->v) <= 1e-4f;
                if (ok && a->t != b->t)
                    st->same_prim_t_not_bitwise++;
            } else {
                ok = da_t_close(a->t, b->t);
                if (ok)
                    st->ties++;
            }
        }
        if (!ok) {
            if (bad < 5)
                fprintf(stderr,
                        "%s: ray %d: hit t %.9g inst %u obj %u prim %u (u %g v %g); reference t "
                        "%.9g inst %u obj %u prim %u (u %g v %g)\n",
                        label, i, a->t, a->instance, a->object, a->primitive, a->u, a->v, b->t,
                        b->instance, b->object, b->primitive, b->u, b->v);
            bad++;
        }
    }
    st->mismatches += bad;
    return bad;
}

/* Number of pixels whose RGBA floats differ in any bit (first one printed). */
static inline long da_compare_images(const float *a, const float *b, const char *label)
{
    long bad = 0;
    for (int i = 0; i < DA_PIXELS; i += 4) {
        if (memcmp(&a[i], &b[i], 4 * sizeof(float)) != 0) {
            if (bad == 0)
                fprintf(stderr, "%s: pixel (%d, %d) is (%.9g %.9g %.9g %.9g), expected (%.9g %.9g "
                        "%.9g %.9g)\n",
                        label, (i / 4) % DA_WIDTH, (i / 4) / DA_WIDTH, a[i], a[i + 1], a[i + 2],
                        a[i + 3], b[i], b[i + 1], b[i + 2], b[i + 3]);
            bad++;
        }
    }
    return bad;
}

/* rtRenderFrame and read the RGBA floats of the 64x48 viewport. */
static inline void da_render(float *rgba)
{
    rtRenderFrame();
    rtReadPixels(0, 0, DA_WIDTH, DA_HEIGHT, RT_RGBA, RT_FLOAT, rgba);
}

/* ---- the reference ----------------------------------------------------------- */

/* Reference answers for an animation: per frame, the hits of the fixed
 * rays and the image. */
struct da_reference {
    int frames;
    int ray_count;
    RThit *hits;   /* frames * ray_count */
    float *images; /* frames * DA_PIXELS */
};

/*
 * Computes the reference in a context of its own ("builder=sweep
 * threads=1": the quality builder, one thread) in which every object is
 * deleted and defined afresh each frame, so nothing is ever updated:
 * kinds[0..n) are instantiated with da_instantiate.  The calling thread's
 * current context is restored.  Returns the first error the reference
 * context recorded (RT_NO_ERROR when all went well).
 */
static inline RTenum da_reference_compute(struct da_reference *ref, const int *kinds, int n,
                                          int frames, const RTray *rays, int ray_count)
{
    RTcontext saved = rtGetCurrentContext();
    RTcontext c = rtCreateContext("builder=sweep threads=1");
    RTenum err = RT_INVALID_OPERATION;
    ref->frames = frames;
    ref->ray_count = ray_count;
    ref->hits = (RThit *)calloc((size_t)frames * (size_t)ray_count, sizeof(RThit));
    ref->images = (float *)calloc((size_t)frames * DA_PIXELS, sizeof(float));
    if (!c || !rtMakeCurrent(c))
        goto done;
    da_camera();
    err = RT_NO_ERROR;
    for (int f = 0; f < frames && err == RT_NO_ERROR; f++) {
        for (int i = 0; i < n; i++) {
            RTuint name = DA_NAME_BASE + (RTuint)kinds[i];
            rtDeleteObjects(1, &name);
            da_define(name, kinds[i], f);
        }
        da_instantiate(kinds, n);
        rtTraceRays(ray_count, rays, &ref->hits[(size_t)f * (size_t)ray_count]);
        da_render(&ref->images[(size_t)f * DA_PIXELS]);
        err = rtGetError();
    }
done:
    rtMakeCurrent(saved);
    if (c)
        rtDestroyContext(c);
    return err;
}

static inline void da_reference_free(struct da_reference *ref)
{
    free(ref->hits);
    free(ref->images);
    memset(ref, 0, sizeof(*ref));
}

static inline const char *da_strategy_name(RTenum s)
{
    switch (s) {
    case RT_AUTOMATIC:
        return "RT_AUTOMATIC";
    case RT_REFIT:
        return "RT_REFIT";
    case RT_REBUILD:
        return "RT_REBUILD";
    case RT_REBUILD_MEDIAN:
        return "RT_REBUILD_MEDIAN";
    case RT_REBUILD_HEURISTIC:
        return "RT_REBUILD_HEURISTIC";
    case RT_RESTRUCTURE:
        return "RT_RESTRUCTURE";
#ifdef RT_ASYNC_REBUILD
    case RT_ASYNC_REBUILD:
        return "RT_ASYNC_REBUILD";
#endif
    default:
        return "?";
    }
}

static inline const char *da_kind_name(int kind)
{
    static const char *names[DA_KINDS] = {"sphere", "cloth", "soup", "big cloth", "popper"};
    return kind >= 0 && kind < DA_KINDS ? names[kind] : "?";
}

#endif
