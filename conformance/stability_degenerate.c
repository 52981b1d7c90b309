/* SPDX-License-Identifier: Apache-2.0 */
/*
 * stability_degenerate.c - degenerate triangles are never hit and never
 * produce a NaN; their valid neighbours are still hit.
 *
 * Object 1 holds, in this order:
 *   0  V: (0,0,0) (1,0,0) (0,1,0), a valid triangle in z = 0;
 *   1  collinear along V's edge y = 0: (0,0,0) (0.5,0,0) (1,0,0);
 *   2  a repeated vertex on V's long edge: (1,0,0) (1,0,0) (0,1,0);
 *   3  one point three times: (0,1,0) x 3;
 *   4  collinear in 3D: (2,0,0) (3,1,2) (5,3,6);
 *   5  collinear far out: (1000,2000,3000) (1001,2002,3003) (1010,2020,3030);
 *   6  a sliver one float ulp thick: (0,2,0) (4,2,0) (2, 2 + 2^-22, 0);
 *   7  its valid neighbour across the long edge: (0,2,0) (4,2,0) (2,1,0);
 *   8.. a small random soup issued under rtScalef(1, 0, 0) (a singular
 *       modelview is allowed at rtVertex time): every triangle is collapsed
 *       onto the line y = 5, z = 0, zero area, never hit.
 * Object 2 holds only degenerate triangles (points and collinear triples).
 *
 * Zero-area triangles (exactly collinear float vertices) are never hit.
 * The sliver has a positive area (its apex is one ulp above the edge), so a
 * ray through its one-ulp interior may hit it, with sane values; rays aimed
 * at the neighbour's interior hit the neighbour.  Collinear triples rotated
 * by a modelview stop being exactly collinear in float: such "accidental
 * slivers" may be hit, but only on the segment they approximate.
 *
 * Rays: perpendicular to z = 0 at points of the degenerate triangles and of
 * V's edges and vertices (must hit V: edges belong to the triangle);
 * random directions through points of the degenerate triangles; rays lying
 * along their lines; rays into V's and the neighbour's interiors.  Every
 * reported hit must have finite t, u, v in [0, 1] and a non-degenerate
 * triangle.  Eye-light and Whitted images looking at the lot face on and
 * edge on must contain no NaN or infinity.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brute_force.h"
#include "testutil.h"

#define MAIN 1
#define ALL_DEGENERATE 2
#define ROTATED 3
#define SOUP_COUNT 64
#define MAX_PRINTED 10

static const float tris[8][3][3] = {
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
    {{0, 0, 0}, {0.5f, 0, 0}, {1, 0, 0}},
    {{1, 0, 0}, {1, 0, 0}, {0, 1, 0}},
    {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}},
    {{2, 0, 0}, {3, 1, 2}, {5, 3, 6}},
    {{1000, 2000, 3000}, {1001, 2002, 3003}, {1010, 2020, 3030}},
    {{0, 2, 0}, {4, 2, 0}, {2, 2.0f + 0x1p-22f, 0}},
    {{0, 2, 0}, {4, 2, 0}, {2, 1, 0}},
};
#define PRIM_V 0
#define PRIM_SLIVER 6
#define PRIM_NEIGHBOUR 7
#define FIRST_SOUP 8

static int is_valid_prim(RTuint prim)
{
    return prim == PRIM_V || prim == PRIM_SLIVER || prim == PRIM_NEIGHBOUR;
}

static void define_objects(void)
{
    rtNewObject(MAIN);
    rtBegin(RT_TRIANGLES);
    for (int t = 0; t < 8; t++)
        for (int k = 0; k < 3; k++)
            rtVertex3fv(tris[t][k]);
    rtEnd();
    struct bf_rng r;
    bf_seed(&r, 5u);
    rtPushMatrix();
    rtTranslatef(0.0f, 5.0f, 0.0f);
    rtScalef(1.0f, 0.0f, 0.0f);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < 3 * SOUP_COUNT; i++)
        rtVertex3f((float)bf_range(&r, -3, 3), (float)bf_range(&r, -3, 3),
                   (float)bf_range(&r, -3, 3));
    rtEnd();
    rtPopMatrix();
    rtEndObject();

    rtNewObject(ALL_DEGENERATE);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < 30; i++) {
        float a = (float)i;
        rtVertex3f(a, 1, 2);
        rtVertex3f(a, 1, 2);
        rtVertex3f(a, 1, 2);
        rtVertex3f(a, 0, 0);
        rtVertex3f(a + 1, 2, 3);
        rtVertex3f(a + 3, 6, 9);
    }
    rtEnd();
    rtEndObject();

    /* Collinear triples under an arbitrary rotation: rounded apart. */
    rtNewObject(ROTATED);
    rtPushMatrix();
    rtRotatef(37.0f, 0.3f, 0.5f, 0.8f);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < 16; i++) {
        float a = (float)i * 0.25f;
        rtVertex3f(a, 0, 0);
        rtVertex3f(a + 1, 1, 1);
        rtVertex3f(a + 2, 2, 2);
    }
    rtEnd();
    rtPopMatrix();
    rtEndObject();
}

struct batch {
    RTray rays[4096];
    int count;
    /* Expectation per ray. */
    signed char expect[4096];
};

enum { ANY, MUST_HIT_V, MUST_HIT_NEIGHBOUR, MUST_MISS, V_OR_MISS };

static void add_ray(struct batch *b, const double org[3], const double dir[3], int expect)
{
    RTray *r = &b->rays[b->count];
    for (int k = 0; k < 3; k++) {
        r->org[k] = (float)org[k];
        r->dir[k] = (float)dir[k];
    }
    r->tmin = 0.0f;
    r->tmax = INFINITY;
    b->expect[b->count] = (signed char)expect;
    b->count++;
}

/* Perpendicular ray down onto point p of the z = 0 plane. */
static void add_down(struct batch *b, double x, double y, int expect)
{
    const double org[3] = {x, y, 5.0}, dir[3] = {0.0, 0.0, -1.0};
    add_ray(b, org, dir, expect);
}

/* A ray through p from a random direction, starting 3 units away. */
static void add_through(struct batch *b, struct bf_rng *r, const double p[3], int expect,
                        int avoid_grazing)
{
    double u[3];
    do
        bf_unit_vector(r, u);
    while (avoid_grazing && fabs(u[2]) < 0.3);
    double org[3], dir[3];
    for (int k = 0; k < 3; k++) {
        org[k] = p[k] + 3.0 * u[k];
        dir[k] = -u[k];
    }
    add_ray(b, org, dir, expect);
}

static void lerp3(const float a[3], const float c[3], double s, double out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = a[k] + s * (c[k] - a[k]);
}

static long check_batch(const struct batch *b, RTuint object, const char *what)
{
    RThit hits[4096];
    RTboolean occluded[4096];
    rtTraceRays(b->count, b->rays, hits);
    CHECK_NO_ERR();
    rtOccludedRays(b->count, b->rays, occluded);
    CHECK_NO_ERR();
    long bad = 0;
    for (int i = 0; i < b->count; i++) {
        const RThit *h = &hits[i];
        const char *problem = NULL;
        int hit = h->t < INFINITY;
        if (isnan(h->t) || isnan(h->u) || isnan(h->v) || h->t < 0.0f)
            problem = "NaN or negative value";
        else if (hit && !(h->u >= 0.0f && h->v >= 0.0f && h->u + h->v <= 1.0f + 1e-6f))
            problem = "barycentrics outside [0, 1]";
        else if (hit && object == MAIN && !is_valid_prim(h->primitive))
            problem = "a zero-area triangle was hit";
        else if (hit && object == ALL_DEGENERATE)
            problem = "a zero-area triangle was hit";
        else if (occluded[i] != (RTboolean)hit)
            problem = "rtOccludedRays disagrees";
        else if (b->expect[i] == MUST_HIT_V && !(hit && h->primitive == PRIM_V))
            problem = "V was not hit";
        else if (b->expect[i] == V_OR_MISS && hit && h->primitive != PRIM_V)
            problem = "hit something other than V";
        else if (b->expect[i] == MUST_HIT_NEIGHBOUR && !(hit && h->primitive == PRIM_NEIGHBOUR))
            problem = "the sliver's neighbour was not hit";
        else if (b->expect[i] == MUST_MISS && hit)
            problem = "hit where only degenerate triangles are";
        if (problem && bad++ < MAX_PRINTED) {
            const RTray *r = &b->rays[i];
            fprintf(stderr,
                    "  %s ray %d: %s: org (%.9g, %.9g, %.9g) dir (%.9g, %.9g, %.9g) -> t %.9g u "
                    "%.9g v %.9g primitive %u\n",
                    what, i, problem, r->org[0], r->org[1], r->org[2], r->dir[0], r->dir[1],
                    r->dir[2], h->t, h->u, h->v, h->primitive);
        }
    }
    return bad;
}

static void ray_checks(void)
{
    struct bf_rng r;
    bf_seed(&r, 17u);
    static struct batch b;

    tu_section("rays onto V's edges, vertices and the degenerate triangles on them");
    b.count = 0;
    for (int i = 0; i <= 64; i++) {
        double s = i / 64.0;
        add_down(&b, s, 0.0, MUST_HIT_V);     /* edge y = 0, triangle 1 */
        add_down(&b, 0.0, s, MUST_HIT_V);     /* edge x = 0 */
        add_down(&b, s, 1.0 - s, MUST_HIT_V); /* long edge, triangle 2 */
        add_down(&b, s * 0.5, s * 0.25, MUST_HIT_V);
    }
    add_down(&b, 0.0, 1.0, MUST_HIT_V); /* triangle 3's point */
    /* Just outside V along its edges: nothing but degenerate triangles. */
    add_down(&b, 0.5, -1e-6, MUST_MISS);
    add_down(&b, -1e-6, 0.5, MUST_MISS);
    add_down(&b, 1.0 + 1e-6, 0.0, MUST_MISS);
    CHECK_INT(check_batch(&b, MAIN, "onto V"), 0);

    tu_section("random directions through the degenerate triangles");
    b.count = 0;
    for (int i = 0; i < 500; i++) {
        double p[3];
        int t = 1 + (int)bf_below(&r, 5);
        double s = bf_uniform(&r);
        lerp3(tris[t][0], tris[t][2], s, p);
        /* Triangles 1..3 lie on V's boundary: V (edge inclusive) or a miss
         * for grazing rays; 4 and 5 have nothing around them. */
        add_through(&b, &r, p, t <= 3 ? V_OR_MISS : MUST_MISS, 0);
    }
    /* The collapsed soup: points of the line y = 5, z = 0. */
    for (int i = 0; i < 500; i++) {
        double p[3] = {bf_range(&r, -3, 3), 5.0, 0.0};
        add_through(&b, &r, p, MUST_MISS, 0);
    }
    CHECK_INT(check_batch(&b, MAIN, "through degenerate"), 0);

    tu_section("rays along the degenerate triangles' lines");
    b.count = 0;
    for (int t = 1; t <= 5; t++) {
        if (t == 3)
            continue; /* a single point has no line */
        double a[3], c[3], d[3], o[3];
        lerp3(tris[t][0], tris[t][2], 0.0, a);
        lerp3(tris[t][0], tris[t][2], 1.0, c);
        bf_sub(d, c, a);
        for (int k = 0; k < 3; k++)
            o[k] = a[k] - d[k];
        add_ray(&b, o, d, ANY);
        double back[3] = {-d[0], -d[1], -d[2]};
        for (int k = 0; k < 3; k++)
            o[k] = c[k] + d[k];
        add_ray(&b, o, back, ANY);
    }
    {
        const double o[3] = {-5.0, 5.0, 0.0}, d[3] = {1.0, 0.0, 0.0};
        add_ray(&b, o, d, MUST_MISS); /* along the collapsed soup's line */
    }
    CHECK_INT(check_batch(&b, MAIN, "along"), 0);

    tu_section("the sliver and its neighbour");
    b.count = 0;
    for (int i = 0; i < 200; i++) {
        double x = bf_range(&r, 0.05, 3.95);
        double below = 2.0 - bf_range(&r, 1e-3, 0.9) * (1.0 - fabs(x - 2.0) / 2.0);
        double p[3] = {x, below, 0.0};
        add_through(&b, &r, p, MUST_HIT_NEIGHBOUR, 1);
        add_down(&b, x, 2.0, ANY);                                         /* the shared edge */
        add_down(&b, x, 2.0 + 0x1p-24 * (1.0 - fabs(x - 2.0) / 2.0), ANY); /* inside the sliver */
        add_down(&b, x, 2.0 + 1e-5, MUST_MISS);                            /* above both */
    }
    CHECK_INT(check_batch(&b, MAIN, "sliver"), 0);

    /* Random directions through the sliver's long edge: a hit on the
     * sliver or its neighbour must be where the ray meets the plane z = 0
     * (both lie in it), i.e. at the aim point. */
    b.count = 0;
    for (int i = 0; i < 1000; i++) {
        double p[3] = {bf_range(&r, 0.05, 3.95), 2.0, 0.0};
        add_through(&b, &r, p, ANY, 0);
    }
    {
        RThit hits[4096];
        rtTraceRays(b.count, b.rays, hits);
        CHECK_NO_ERR();
        long off = 0, sliver_hits = 0;
        for (int i = 0; i < b.count; i++) {
            if (!(hits[i].t < INFINITY))
                continue;
            sliver_hits += hits[i].primitive == PRIM_SLIVER;
            double z = b.rays[i].org[2] + (double)hits[i].t * b.rays[i].dir[2];
            double x = b.rays[i].org[0] + (double)hits[i].t * b.rays[i].dir[0];
            double y = b.rays[i].org[1] + (double)hits[i].t * b.rays[i].dir[1];
            if (!is_valid_prim(hits[i].primitive) || fabs(z) > 1e-5 || fabs(y - 2.0) > 1e-5 ||
                !(fabs(hits[i].t - 3.0) < 1e-5)) {
                if (off++ < MAX_PRINTED)
                    fprintf(stderr,
                            "  through the sliver's edge: primitive %u hit at (%.9g, %.9g, "
                            "%.9g), t %.9g, expected t 3 at the edge\n",
                            hits[i].primitive, x, y, z, hits[i].t);
            }
        }
        printf("   %d rays through the sliver's edge: %ld hit the sliver, %ld elsewhere than "
               "the edge\n",
               b.count, sliver_hits, off);
        CHECK_INT(off, 0);
    }

    tu_section("an object of degenerate triangles only");
    rtBeginFrame();
    rtInstantiateObject(ALL_DEGENERATE);
    RTint n = -1;
    rtGetObjectiv(ALL_DEGENERATE, RT_OBJECT_TRIANGLES, &n);
    CHECK_INT(n, 60);
    b.count = 0;
    for (int i = 0; i < 30; i++) {
        const double p[3] = {i + 1.0, 2.0, 3.0}, q[3] = {(double)i, 1.0, 2.0};
        add_through(&b, &r, p, MUST_MISS, 0);
        add_through(&b, &r, q, MUST_MISS, 0);
    }
    CHECK_INT(check_batch(&b, ALL_DEGENERATE, "all degenerate"), 0);

    tu_section("collinear triples rounded apart by a rotation");
    rtBeginFrame();
    rtInstantiateObject(ROTATED);
    b.count = 0;
    double m[16], axis[3] = {0.3, 0.5, 0.8};
    double len = bf_length(axis);
    for (int k = 0; k < 3; k++)
        axis[k] /= len;
    bf_rotation(m, 37.0 * 3.14159265358979323846 / 180.0, axis);
    for (int i = 0; i < 1000; i++) {
        /* Segment j runs from (j/4, 0, 0) to (j/4 + 2, 2, 2). */
        double a = bf_below(&r, 16) * 0.25, t = bf_range(&r, 0.0, 2.0);
        double p[3] = {a + t, t, t}, w[3];
        bf_transform_point(m, p, w);
        add_through(&b, &r, w, ANY, 0);
    }
    RThit hits[4096];
    rtTraceRays(b.count, b.rays, hits);
    CHECK_NO_ERR();
    double inverse[16];
    bf_invert(inverse, m);
    long bad = 0, hit_count = 0;
    for (int i = 0; i < b.count; i++) {
        const RThit *h = &hits[i];
        if (!(h->t < INFINITY)) {
            bad += !(h->t == INFINITY);
            continue;
        }
        hit_count++;
        /* The hit point, in object space, must be on one of the segments:
         * y = z in [0, 2] and x - y a multiple of 1/4 in [0, 3.75]. */
        double w[3], q[3];
        for (int k = 0; k < 3; k++)
            w[k] = b.rays[i].org[k] + (double)h->t * b.rays[i].dir[k];
        bf_transform_point(inverse, w, q);
        double c = 4.0 * (q[0] - q[1]);
        double off = fabs(q[1] - q[2]) + fabs(c - floor(c + 0.5)) / 4.0;
        if (!isfinite(h->u) || !isfinite(h->v) || off > 1e-4 || q[1] < -1e-4 || q[1] > 2.0 + 1e-4 ||
            c < -1e-3 || c > 15.0 + 1e-3) {
            if (bad++ < MAX_PRINTED)
                fprintf(stderr,
                        "  rotated collinear: hit t %.9g at object point (%.9g, %.9g, %.9g), "
                        "not on a segment\n",
                        h->t, q[0], q[1], q[2]);
        }
    }
    printf("   %ld of %d rays hit an accidental sliver\n", hit_count, b.count);
    CHECK_INT(bad, 0);
    CHECK_NO_ERR();
}

static int image_is_finite(const float *rgba, int w, int h)
{
    for (int i = 0; i < 4 * w * h; i++)
        if (!isfinite(rgba[i]))
            return 0;
    for (int i = 0; i < w * h; i++)
        if (rgba[4 * i + 3] != 0.0f && rgba[4 * i + 3] != 1.0f)
            return 0;
    return 1;
}

static void image_checks(void)
{
    tu_section("images");
    static float rgba[4 * 96 * 96];
    const float spec[4] = {1, 1, 1, 1};
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, spec);
    rtEnable(RT_LIGHT0);
    const float lamp[4] = {1.0f, 1.0f, 3.0f, 1.0f};
    rtLightfv(RT_LIGHT0 + 1, RT_POSITION, lamp);
    rtLightfv(RT_LIGHT0 + 1, RT_DIFFUSE, spec);
    rtEnable(RT_LIGHT0 + 1);
    /* Face on (looking down -z at z = 0), edge on (looking along +x at the
     * plane z = 0 and the degenerate lines), and at the flattened soup. */
    static const double views[3][4] = {
        {0.0, 0.0, 0.0, 0.0}, {90.0, 0.0, 1.0, 0.0}, {90.0, 1.0, 0.0, 0.0}};
    for (int v = 0; v < 3; v++)
        for (int mode = 0; mode < 2; mode++) {
            rtMatrixMode(RT_PROJECTION);
            rtLoadIdentity();
            rtOrtho(-6.0, 6.0, -6.0, 6.0, 1.0, 100.0);
            if (views[v][0] != 0.0)
                rtRotated(views[v][0], views[v][1], views[v][2], views[v][3]);
            rtTranslated(0.0, 0.0, -20.0);
            rtMatrixMode(RT_MODELVIEW);
            rtBeginFrame();
            rtInstantiateObject(MAIN);
            rtInstantiateObject(ALL_DEGENERATE);
            rtInstantiateObject(ROTATED);
            rtShadingMode(mode ? RT_WHITTED : RT_EYE_LIGHT);
            tu_render_float(96, 96, rgba);
            CHECK_NO_ERR();
            if (!CHECK(image_is_finite(rgba, 96, 96)))
                fprintf(stderr, "  view %d, %s: a pixel is not finite\n", v,
                        mode ? "Whitted" : "eye light");
        }
}

int main(void)
{
    RTcontext ctx = tu_make_context(NULL);
    define_objects();
    CHECK_NO_ERR();
    RTint n = -1;
    rtGetObjectiv(MAIN, RT_OBJECT_TRIANGLES, &n);
    CHECK_INT(n, FIRST_SOUP + SOUP_COUNT); /* degenerate triangles count */
    rtBeginFrame();
    rtInstantiateObject(MAIN);
    ray_checks();
    image_checks();
    tu_destroy_context(ctx);
    return test_summary("stability_degenerate");
}
