/* SPDX-License-Identifier: Apache-2.0 */
/*
 * instanced_vs_flat.c - a scene of objects under instance transforms
 * against the same geometry flattened into one object.
 *
 * Four objects (a smooth sphere with specular highlights, a flat-shaded
 * mirror box, a heightfield coloured per vertex through RT_COLOR_MATERIAL,
 * a floor) are placed by eight instances under random affine matrices
 * (rotation, non-uniform scale 1..4 with shear, translation).  The flat
 * version issues the very same calls for every instance into ONE object
 * with the instance's matrix loaded as the modelview, so the library
 * transforms vertices (and normals, by the cofactor matrix) at rtVertex
 * time.  Every object calls rtNormal for every vertex, so both versions
 * shade with the given normals (an object without rtNormal calls would use
 * geometric normals, and the flat object could not mix the two).
 *
 * Checked:
 *   - 100k rays: the same hit or miss, the same triangle (flat primitive =
 *     offset of the instance + primitive), t within the tolerance of
 *     brute_force.h (rel 1e-4 plus the grazing term) and barycentrics that
 *     name the same point.  Where the two differ (a ray passing within the
 *     float error of an edge or silhouette), both answers must be accepted
 *     by the double-precision reference (brute_force.h) for the exact world
 *     geometry, and such rays must be rare (< 0.5%).
 *   - Rendered images, eye light and Whitted (two lights, shadows, the
 *     mirror box), 200x150 RGBA float: on at least 99.9% of the pixels every
 *     channel within 1e-4 of the other image.
 *
 * Why the results are not bit-identical: instanced triangles keep their
 * object-space float vertices and the ray is moved into object space by
 * the inverse matrix and rounded to float there; flattened triangles are
 * the matrix applied in double to the same vertices, rounded once to float
 * in world space.  The two
 * computations round differently, by a few float ulps of the coordinates
 * (~1e-6 relative here), so hit distances, normals and shading differ in
 * the last bits (the largest difference is printed; it was 1.1e-5 when
 * this test was written, hence the tolerance 1e-4), and a primary or
 * shadow ray passing within that distance of an edge, a silhouette or a
 * shadow boundary can land on the other side in one of the two versions,
 * which changes that pixel by a visible amount.  Such pixels are a vanishing fraction; the
 * 0.1% allowance leaves room for them without hiding a systematic error,
 * which would change whole surfaces.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "brute_force.h"
#include "testutil.h"

#define RAY_COUNT 100000
#define WIDTH 200
#define HEIGHT 150
#define PIXEL_TOLERANCE 1e-4f
#define MAX_OUTLIER_FRACTION 0.001
#define MAX_MISMATCH_FRACTION 0.005
#define REL_T 1e-4
/* Position error per unit of coordinate magnitude; query_brute_force.c
 * explains the value (rays here start at distance ~40). */
#define POS_EPS_PER_UNIT 1e-5
#define MAX_PRINTED 10

/* A recorded object: the calls it makes, replayable under any modelview. */
struct vertex_rec {
    float position[3];
    float normal[3];
    float color[3];
};

struct object_rec {
    RTuint name;
    struct vertex_rec *vertices; /* 3 per triangle, RT_TRIANGLES order */
    uint32_t tri_count;
    uint32_t capacity;
    float diffuse[4];
    float specular[4];
    float shininess;
    float reflectivity;
    int flat_shaded;
    int color_material;
};

static void add_triangle(struct object_rec *o, const float p[3][3], const float n[3][3],
                         const float c[3][3])
{
    if (3 * o->tri_count + 3 > o->capacity) {
        o->capacity = o->capacity ? 2 * o->capacity : 96;
        o->vertices = bf_xrealloc(o->vertices, o->capacity * sizeof(*o->vertices));
    }
    for (int k = 0; k < 3; k++) {
        struct vertex_rec *v = &o->vertices[3 * o->tri_count + (uint32_t)k];
        memcpy(v->position, p[k], sizeof(v->position));
        memcpy(v->normal, n[k], sizeof(v->normal));
        memcpy(v->color, c[k], sizeof(v->color));
    }
    o->tri_count++;
}

static const float white[3] = {1.0f, 1.0f, 1.0f};

static void make_sphere(struct object_rec *o, int slices, int stacks)
{
    for (int j = 0; j < stacks; j++)
        for (int i = 0; i < slices; i++) {
            float p[4][3];
            for (int c = 0; c < 4; c++) {
                double theta = 3.141592653589793 * (j + (c >> 1)) / stacks;
                double phi = 6.283185307179586 * (i + (c & 1)) / slices;
                p[c][0] = (float)(sin(theta) * cos(phi));
                p[c][1] = (float)cos(theta);
                p[c][2] = (float)(sin(theta) * sin(phi));
            }
            /* On a unit sphere the normal is the position.  Triangles at
             * the poles would be degenerate: leave them out. */
            const float c3[3][3] = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
            if (j != 0) {
                const float t[3][3] = {{p[0][0], p[0][1], p[0][2]},
                                       {p[1][0], p[1][1], p[1][2]},
                                       {p[3][0], p[3][1], p[3][2]}};
                add_triangle(o, t, t, c3);
            }
            if (j != stacks - 1) {
                const float t[3][3] = {{p[0][0], p[0][1], p[0][2]},
                                       {p[3][0], p[3][1], p[3][2]},
                                       {p[2][0], p[2][1], p[2][2]}};
                add_triangle(o, t, t, c3);
            }
        }
}

static void make_box(struct object_rec *o)
{
    /* Six faces of [-1,1]^3, counter-clockwise seen from outside. */
    for (int axis = 0; axis < 3; axis++)
        for (int side = -1; side <= 1; side += 2) {
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            float q[4][3], n[3] = {0, 0, 0};
            n[axis] = (float)side;
            static const int su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
            for (int c = 0; c < 4; c++) {
                q[c][axis] = (float)side;
                q[c][u] = (float)(su[c] * side);
                q[c][v] = (float)sv[c];
            }
            const float nn[3][3] = {{n[0], n[1], n[2]}, {n[0], n[1], n[2]}, {n[0], n[1], n[2]}};
            const float c3[3][3] = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
            const float t1[3][3] = {{q[0][0], q[0][1], q[0][2]},
                                    {q[1][0], q[1][1], q[1][2]},
                                    {q[2][0], q[2][1], q[2][2]}};
            const float t2[3][3] = {{q[0][0], q[0][1], q[0][2]},
                                    {q[2][0], q[2][1], q[2][2]},
                                    {q[3][0], q[3][1], q[3][2]}};
            add_triangle(o, t1, nn, c3);
            add_triangle(o, t2, nn, c3);
        }
}

/* Heightfield over [-1,1]^2 (y up) with per-vertex normals and colours. */
static void make_heightfield(struct object_rec *o, struct bf_rng *r, int n)
{
    float h[17][17];
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++)
            h[j][i] = (float)bf_range(r, 0.0, 0.25);
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            float p[4][3], nrm[4][3], col[4][3];
            for (int c = 0; c < 4; c++) {
                int x = i + (c & 1), z = j + (c >> 1);
                p[c][0] = -1.0f + 2.0f * (float)x / (float)n;
                p[c][1] = h[z][x];
                p[c][2] = -1.0f + 2.0f * (float)z / (float)n;
                int xl = x > 0 ? x - 1 : x, xr = x < n ? x + 1 : x;
                int zl = z > 0 ? z - 1 : z, zr = z < n ? z + 1 : z;
                double dx = (h[z][xr] - h[z][xl]) / (2.0 / n * (xr - xl));
                double dz = (h[zr][x] - h[zl][x]) / (2.0 / n * (zr - zl));
                double len = sqrt(dx * dx + 1.0 + dz * dz);
                nrm[c][0] = (float)(-dx / len);
                nrm[c][1] = (float)(1.0 / len);
                nrm[c][2] = (float)(-dz / len);
                col[c][0] = (float)x / (float)n;
                col[c][1] = 0.5f;
                col[c][2] = (float)z / (float)n;
            }
            static const int a[2][3] = {{0, 2, 3}, {0, 3, 1}};
            for (int t = 0; t < 2; t++) {
                float tp[3][3], tn[3][3], tc[3][3];
                for (int k = 0; k < 3; k++) {
                    memcpy(tp[k], p[a[t][k]], sizeof(tp[k]));
                    memcpy(tn[k], nrm[a[t][k]], sizeof(tn[k]));
                    memcpy(tc[k], col[a[t][k]], sizeof(tc[k]));
                }
                add_triangle(o, tp, tn, tc);
            }
        }
}

static void make_floor(struct object_rec *o, int n)
{
    const float up[3][3] = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    const float c3[3][3] = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            float x0 = -1.0f + 2.0f * (float)i / (float)n,
                  x1 = -1.0f + 2.0f * (float)(i + 1) / (float)n;
            float z0 = -1.0f + 2.0f * (float)j / (float)n,
                  z1 = -1.0f + 2.0f * (float)(j + 1) / (float)n;
            const float t1[3][3] = {{x0, 0, z0}, {x0, 0, z1}, {x1, 0, z1}};
            const float t2[3][3] = {{x0, 0, z0}, {x1, 0, z1}, {x1, 0, z0}};
            add_triangle(o, t1, up, c3);
            add_triangle(o, t2, up, c3);
        }
}

/* Issues the object's calls under the current modelview (inside an object). */
static void emit(const struct object_rec *o)
{
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, o->diffuse);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, o->specular);
    rtMaterialf(RT_FRONT_AND_BACK, RT_SHININESS, o->shininess);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, o->reflectivity);
    rtShadeModel(o->flat_shaded ? RT_FLAT : RT_SMOOTH);
    /* Named here, so that the rtDisable below writes the colour into
     * properties known while recording: a list naming no mode writes
     * those the call names (GL), which cuts the flat list into a segment
     * per object (docs/lists.md). */
    rtColorMaterial(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE);
    if (o->color_material)
        rtEnable(RT_COLOR_MATERIAL);
    rtBegin(RT_TRIANGLES);
    for (uint32_t i = 0; i < 3 * o->tri_count; i++) {
        const struct vertex_rec *v = &o->vertices[i];
        rtNormal3fv(v->normal);
        rtColor3fv(v->color);
        rtVertex3fv(v->position);
    }
    rtEnd();
    rtDisable(RT_COLOR_MATERIAL);
    rtShadeModel(RT_SMOOTH);
    rtColor3fv(white);
}

#define OBJECTS 4
#define INSTANCES 8
#define FLAT_OBJECT 100

struct world {
    struct object_rec objects[OBJECTS];
    double matrices[INSTANCES][16];
    int instance_object[INSTANCES];
    uint32_t flat_offset[INSTANCES]; /* first flat primitive of each instance */
    struct bf_scene ref;
    double extent;
};

static void make_world(struct world *w)
{
    memset(w, 0, sizeof(*w));
    struct bf_rng r;
    bf_seed(&r, 20240611u);
    static const float materials[OBJECTS][4] = {{0.8f, 0.2f, 0.2f, 1.0f},
                                                {0.3f, 0.3f, 0.35f, 1.0f},
                                                {1, 1, 1, 1},
                                                {0.6f, 0.6f, 0.5f, 1.0f}};
    for (int k = 0; k < OBJECTS; k++) {
        struct object_rec *o = &w->objects[k];
        o->name = (RTuint)(k + 1);
        memcpy(o->diffuse, materials[k], sizeof(o->diffuse));
        const float black[4] = {0, 0, 0, 1}, spec[4] = {0.6f, 0.6f, 0.6f, 1};
        memcpy(o->specular, k == 0 ? spec : black, sizeof(o->specular));
        o->shininess = k == 0 ? 32.0f : 0.0f;
        o->reflectivity = k == 1 ? 0.6f : 0.0f;
        o->flat_shaded = k == 1;
        o->color_material = k == 2;
    }
    make_sphere(&w->objects[0], 32, 16);
    make_box(&w->objects[1]);
    make_heightfield(&w->objects[2], &r, 16);
    make_floor(&w->objects[3], 8);

    /* Instances: three spheres, two boxes, two heightfields, one floor. */
    static const int which[INSTANCES] = {0, 0, 0, 1, 1, 2, 2, 3};
    uint32_t offset = 0;
    for (int i = 0; i < INSTANCES; i++) {
        w->instance_object[i] = which[i];
        double *m = w->matrices[i];
        if (which[i] == 3) {
            double t[16], s[16];
            bf_translation(t, 0.0, -3.0, -22.0);
            bf_scaling(s, 14.0, 1.0, 14.0);
            bf_mul(m, t, s);
        } else {
            bf_random_affine(&r, m, 1.0, 4.0, 0.0);
            double t[16];
            bf_translation(t, bf_range(&r, -8.0, 8.0), bf_range(&r, -0.5, 3.0),
                           bf_range(&r, -28.0, -16.0));
            bf_mul(m, t, m);
        }
        const struct object_rec *o = &w->objects[which[i]];
        float *positions = bf_xrealloc(NULL, (size_t)o->tri_count * 9 * sizeof(float));
        for (uint32_t v = 0; v < 3 * o->tri_count; v++)
            memcpy(&positions[3 * v], o->vertices[v].position, 3 * sizeof(float));
        bf_scene_add_instance(&w->ref, positions, o->tri_count, m, o->name);
        free(positions);
        w->flat_offset[i] = offset;
        offset += o->tri_count;
    }
    for (size_t i = 0; i < w->ref.count; i++)
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < 3; k++)
                if (fabs(w->ref.tris[i].v[c][k]) > w->extent)
                    w->extent = fabs(w->ref.tris[i].v[c][k]);
}

static void free_world(struct world *w)
{
    for (int k = 0; k < OBJECTS; k++)
        free(w->objects[k].vertices);
    bf_scene_free(&w->ref);
}

static void camera_and_lights(void)
{
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 200.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    const float sun[4] = {0.4f, 1.0f, 0.6f, 0.0f};
    const float lamp[4] = {-6.0f, 8.0f, -10.0f, 1.0f};
    const float lamp_color[4] = {0.5f, 0.45f, 0.4f, 1.0f};
    rtLightfv(RT_LIGHT0, RT_POSITION, sun);
    rtLightfv(RT_LIGHT0 + 1, RT_POSITION, lamp);
    rtLightfv(RT_LIGHT0 + 1, RT_DIFFUSE, lamp_color);
    rtLightfv(RT_LIGHT0 + 1, RT_SPECULAR, lamp_color);
    rtEnable(RT_LIGHT0);
    rtEnable(RT_LIGHT0 + 1);
    rtClearColor(0.1f, 0.2f, 0.3f, 0.0f);
    rtViewport(0, 0, WIDTH, HEIGHT);
}

static void define_instanced(const struct world *w)
{
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    for (int k = 0; k < OBJECTS; k++) {
        rtNewObject(w->objects[k].name);
        emit(&w->objects[k]);
        rtEndObject();
    }
    rtBeginFrame();
    for (int i = 0; i < INSTANCES; i++) {
        rtLoadMatrixd(w->matrices[i]);
        rtInstantiateObject(w->objects[w->instance_object[i]].name);
    }
    rtLoadIdentity();
}

static void define_flat(const struct world *w)
{
    rtMatrixMode(RT_MODELVIEW);
    rtNewObject(FLAT_OBJECT);
    for (int i = 0; i < INSTANCES; i++) {
        /* Relative to the list's own identity: one mesh whose vertices
         * are transformed by exactly this matrix (an absolute
         * rtLoadMatrixd would make each a segment of its own). */
        rtPushMatrix();
        rtMultMatrixd(w->matrices[i]);
        emit(&w->objects[w->instance_object[i]]);
        rtPopMatrix();
    }
    rtEndObject();
    rtLoadIdentity();
    rtBeginFrame();
    rtInstantiateObject(FLAT_OBJECT);
}

/* Instance and primitive of a flat primitive id. */
static void unflatten(const struct world *w, RTuint prim, RTuint *instance, RTuint *primitive)
{
    int i = INSTANCES - 1;
    while (i > 0 && w->flat_offset[i] > prim)
        i--;
    *instance = (RTuint)i;
    *primitive = prim - w->flat_offset[i];
}

static void make_rays(const struct world *w, RTray *rays, int count)
{
    struct bf_rng r;
    bf_seed(&r, 777u);
    for (int i = 0; i < count; i++) {
        double org[3], dir[3], u[3];
        bf_unit_vector(&r, u);
        double centre[3] = {0.0, 0.0, -22.0};
        for (int k = 0; k < 3; k++)
            org[k] = centre[k] + 40.0 * u[k];
        if (bf_uniform(&r) < 0.7) {
            const struct bf_tri *t = &w->ref.tris[bf_below(&r, (uint32_t)w->ref.count)];
            double a = bf_uniform(&r), b = bf_uniform(&r);
            if (a + b > 1.0) {
                a = 1.0 - a;
                b = 1.0 - b;
            }
            for (int k = 0; k < 3; k++)
                dir[k] = t->v[0][k] + a * (t->v[1][k] - t->v[0][k]) +
                         b * (t->v[2][k] - t->v[0][k]) - org[k];
        } else {
            bf_unit_vector(&r, dir);
            for (int k = 0; k < 3; k++)
                dir[k] = centre[k] + 15.0 * dir[k] - org[k];
        }
        for (int k = 0; k < 3; k++) {
            rays[i].org[k] = (float)org[k];
            rays[i].dir[k] = (float)dir[k];
        }
        rays[i].tmin = 0.0f;
        rays[i].tmax = INFINITY;
    }
}

static void compare_hits(const struct world *w, const RTray *rays, const RThit *inst,
                         const RThit *flat, int count)
{
    struct bf_tolerance tol = {REL_T, POS_EPS_PER_UNIT * 62.0};
    long mismatches = 0, failures = 0, hits = 0;
    struct bf_stats stats;
    memset(&stats, 0, sizeof(stats));
    char why[256];
    for (int i = 0; i < count; i++) {
        const RThit *a = &inst[i], *b = &flat[i];
        int a_hit = a->t < INFINITY, b_hit = b->t < INFINITY;
        int same = a_hit == b_hit;
        RTuint b_instance = RT_INVALID_ID, b_primitive = RT_INVALID_ID;
        if (b_hit) {
            if (b->object != FLAT_OBJECT || b->instance != 0) {
                if (failures++ < MAX_PRINTED)
                    fprintf(stderr, "  ray %d: flat hit names object %u instance %u\n", i,
                            b->object, b->instance);
                continue;
            }
            unflatten(w, b->primitive, &b_instance, &b_primitive);
        }
        if (a_hit && b_hit)
            same = a->instance == b_instance && a->primitive == b_primitive;
        if (!same) {
            /* Both answers must be right for the exact geometry. */
            mismatches++;
            RThit mapped = *b;
            if (b_hit) {
                mapped.instance = b_instance;
                mapped.primitive = b_primitive;
                mapped.object = w->objects[w->instance_object[b_instance]].name;
            }
            for (int version = 0; version < 2; version++) {
                const RThit *h = version == 0 ? a : &mapped;
                if (!bf_check_hit(&w->ref, &rays[i], h, &tol, &stats, why, sizeof(why)) &&
                    failures++ < MAX_PRINTED)
                    fprintf(stderr, "  ray %d (%s): %s\n", i, version ? "flat" : "instanced", why);
            }
            continue;
        }
        if (!a_hit)
            continue;
        hits++;
        const struct bf_tri *t = &w->ref.tris[w->ref.base[a->instance] + a->primitive];
        double org[3] = {rays[i].org[0], rays[i].org[1], rays[i].org[2]};
        double dir[3] = {rays[i].dir[0], rays[i].dir[1], rays[i].dir[2]};
        struct bf_isect x = bf_intersect(t, org, dir);
        double tt = 2.0 * bf_t_tolerance(&tol, x.t, x.cosine, bf_length(dir));
        /* The two barycentric pairs must name nearby points. */
        double du = (double)a->u - b->u, dv = (double)a->v - b->v, d[3];
        for (int k = 0; k < 3; k++)
            d[k] = du * (t->v[1][k] - t->v[0][k]) + dv * (t->v[2][k] - t->v[0][k]);
        double allowed = 2.0 * bf_bary_tolerance(&tol, t, org, x.cosine, x.max_edge);
        if (a->object != w->objects[w->instance_object[a->instance]].name ||
            !(fabs((double)a->t - b->t) <= tt) || bf_length(d) > allowed) {
            if (failures++ < MAX_PRINTED)
                fprintf(stderr,
                        "  ray %d: instanced t=%.9g u=%.9g v=%.9g, flat t=%.9g u=%.9g v=%.9g "
                        "(t tolerance %.3g, point distance %.3g allowed %.3g)\n",
                        i, a->t, a->u, a->v, b->t, b->u, b->v, tt, bf_length(d), allowed);
        }
    }
    printf("   %d rays: %ld hits on the same triangle, %ld answered differently (both "
           "checked against the reference), %ld failures\n",
           count, hits, mismatches, failures);
    CHECK_INT(failures, 0);
    CHECK(mismatches <= MAX_MISMATCH_FRACTION * count);
}

/* Compares two RGBA float images; returns the number of outlier pixels. */
static void compare_images(const float *a, const float *b, const char *what)
{
    int outliers = 0;
    double worst = 0.0, worst_inlier = 0.0;
    int nan_pixels = 0;
    for (int p = 0; p < WIDTH * HEIGHT; p++) {
        double diff = 0.0;
        for (int c = 0; c < 4; c++) {
            if (!isfinite(a[4 * p + c]) || !isfinite(b[4 * p + c]))
                nan_pixels++;
            double d = fabs((double)a[4 * p + c] - b[4 * p + c]);
            if (d > diff)
                diff = d;
        }
        if (diff > worst)
            worst = diff;
        if (diff > PIXEL_TOLERANCE)
            outliers++;
        else if (diff > worst_inlier)
            worst_inlier = diff;
    }
    printf("   %s: %d of %d pixels differ by more than %g (largest %.3g); largest difference "
           "elsewhere %.3g\n",
           what, outliers, WIDTH * HEIGHT, (double)PIXEL_TOLERANCE, worst, worst_inlier);
    CHECK_INT(nan_pixels, 0);
    CHECK(outliers <= MAX_OUTLIER_FRACTION * WIDTH * HEIGHT);
}

int main(void)
{
    clock_t start = clock();
    struct world w;
    make_world(&w);

    RTcontext instanced = tu_make_context(NULL);
    camera_and_lights();
    define_instanced(&w);
    CHECK_NO_ERR();
    RTcontext flat = tu_make_context(NULL);
    camera_and_lights();
    define_flat(&w);
    CHECK_NO_ERR();

    tu_section("100k rays");
    RTray *rays = bf_xrealloc(NULL, RAY_COUNT * sizeof(*rays));
    RThit *hits_inst = bf_xrealloc(NULL, RAY_COUNT * sizeof(*hits_inst));
    RThit *hits_flat = bf_xrealloc(NULL, RAY_COUNT * sizeof(*hits_flat));
    make_rays(&w, rays, RAY_COUNT);
    rtMakeCurrent(instanced);
    rtTraceRays(RAY_COUNT, rays, hits_inst);
    CHECK_NO_ERR();
    rtMakeCurrent(flat);
    rtTraceRays(RAY_COUNT, rays, hits_flat);
    CHECK_NO_ERR();
    RTint flat_tris = -1;
    rtGetObjectiv(FLAT_OBJECT, RT_OBJECT_TRIANGLES, &flat_tris);
    CHECK_INT(flat_tris, (RTint)w.ref.count);
    compare_hits(&w, rays, hits_inst, hits_flat, RAY_COUNT);

    float *img_inst = bf_xrealloc(NULL, (size_t)WIDTH * HEIGHT * 4 * sizeof(float));
    float *img_flat = bf_xrealloc(NULL, (size_t)WIDTH * HEIGHT * 4 * sizeof(float));
    static const RTenum modes[2] = {RT_EYE_LIGHT, RT_WHITTED};
    static const char *const mode_names[2] = {"eye light", "Whitted"};
    for (int m = 0; m < 2; m++) {
        tu_section(mode_names[m]);
        RTcontext contexts[2] = {instanced, flat};
        float *images[2] = {img_inst, img_flat};
        for (int c = 0; c < 2; c++) {
            rtMakeCurrent(contexts[c]);
            rtShadingMode(modes[m]);
            rtRenderFrame();
            rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, images[c]);
            CHECK_NO_ERR();
        }
        compare_images(img_inst, img_flat, mode_names[m]);
    }

    free(rays);
    free(hits_inst);
    free(hits_flat);
    free(img_inst);
    free(img_flat);
    rtMakeCurrent(instanced);
    tu_destroy_context(instanced);
    rtMakeCurrent(flat);
    tu_destroy_context(flat);
    free_world(&w);
    printf("cpu time %.2f s\n", (double)(clock() - start) / CLOCKS_PER_SEC);
    return test_summary("instanced_vs_flat");
}
