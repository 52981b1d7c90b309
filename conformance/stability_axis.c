/* SPDX-License-Identifier: Apache-2.0 */
/*
 * stability_axis.c - axis-parallel rays and rays grazing along face planes.
 *
 * Axis-parallel rays have two zero direction components: the slab test's
 * reciprocal direction is +-infinity there, and an origin lying exactly on
 * a box plane gives 0 * inf = NaN (intersect.h treats that slab as
 * containing the ray); the watertight test's shear constants are zero.
 *
 * A 4x4 grid of squares over [0,1]^2 in z = 0 (32 triangles, vertices at
 * multiples of 1/4, exact in float) is seen along each of the six axis
 * directions (+-x, +-y, +-z) by turning it with exact 90-degree rotations
 * (rtRotatef with multiples of 90 gives exact matrices), both as an instance
 * under the rotation and flattened (the rotation as the modelview at
 * rtVertex time).  Rays start 2 units in front of the grid, along the axis,
 * with the two other origin coordinates:
 *   - on every vertex and every grid line (multiples of 1/8 in [0, 1],
 *     edges of the grid's bounding box included): must hit at t = 2;
 *   - just outside the grid (-2^-20 or 1 + 2^-20 on one coordinate): must
 *     miss;
 * with directions +-1 along the axis, also written with -0.0 in the zero
 * components, and with lengths 0.5 and 4 (t scales inversely).
 *
 * Grazing rays: a closed box [0,1]^3 (two triangles per face); rays lying
 * exactly in the plane of a face, along each axis, through the face's
 * interior and along its edges.  The face seen edge-on has zero projected
 * area and cannot be hit; the ray runs into the face it meets head on, on
 * that face's edge, which belongs to the face: the hit must be that face at
 * the exact distance.  Rays in the plane of a face but outside the box miss.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brute_force.h"
#include "testutil.h"

#define GRID 1
#define GRID_FLAT 2
#define BOX 3
#define MAX_PRINTED 10

static void emit_grid(void)
{
    rtBegin(RT_QUADS);
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++) {
            float x0 = 0.25f * (float)i, y0 = 0.25f * (float)j;
            rtVertex3f(x0, y0, 0.0f);
            rtVertex3f(x0 + 0.25f, y0, 0.0f);
            rtVertex3f(x0 + 0.25f, y0 + 0.25f, 0.0f);
            rtVertex3f(x0, y0 + 0.25f, 0.0f);
        }
    rtEnd();
}

/* Box faces: face f = 2 * axis + side, triangles 2f and 2f + 1. */
static void emit_box(void)
{
    rtBegin(RT_QUADS);
    for (int axis = 0; axis < 3; axis++)
        for (int side = 0; side < 2; side++) {
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            static const int su[4] = {0, 1, 1, 0}, sv[4] = {0, 0, 1, 1};
            for (int c = 0; c < 4; c++) {
                float p[3];
                p[axis] = (float)side;
                p[u] = (float)su[c];
                p[v] = (float)sv[c];
                rtVertex3fv(p);
            }
        }
    rtEnd();
}

/* Rotation taking the grid's normal +z to `axis` with sign `sign`, as an
 * exact rotation about a coordinate axis by a multiple of 90 degrees. */
static void orient(int axis, int sign)
{
    if (axis == 2) {
        if (sign < 0)
            rtRotatef(180.0f, 1.0f, 0.0f, 0.0f);
    } else if (axis == 0) {
        rtRotatef(sign > 0 ? 90.0f : -90.0f, 0.0f, 1.0f, 0.0f);
    } else {
        rtRotatef(sign > 0 ? -90.0f : 90.0f, 1.0f, 0.0f, 0.0f);
    }
}

/* Maps a grid point (x, y, 0) by orient(axis, sign), exactly (the matrix
 * entries are 0 and +-1). */
static void oriented_point(int axis, int sign, double x, double y, double out[3])
{
    double m[16], p[3] = {x, y, 0.0};
    bf_identity(m);
    if (axis == 2 && sign < 0) {
        m[5] = -1.0;
        m[10] = -1.0;
    } else if (axis == 0) {
        /* Rotation about y by +-90: x -> -+z, z -> +-x. */
        m[0] = 0.0;
        m[10] = 0.0;
        m[8] = sign > 0 ? 1.0 : -1.0;
        m[2] = sign > 0 ? -1.0 : 1.0;
    } else if (axis == 1) {
        /* Rotation about x by -+90: y -> -+z, z -> +-y. */
        m[5] = 0.0;
        m[10] = 0.0;
        m[6] = sign > 0 ? -1.0 : 1.0;
        m[9] = sign > 0 ? 1.0 : -1.0;
    }
    bf_transform_point(m, p, out);
}

struct ray_case {
    RTray ray;
    int expect_hit;
    float expect_t;
};

static long run_cases(const struct ray_case *cases, int count, RTuint object, const char *what)
{
    RTray *rays = calloc((size_t)count, sizeof(*rays));
    RThit *hits = calloc((size_t)count, sizeof(*hits));
    RTboolean *occ = calloc((size_t)count, 1);
    if (!rays || !hits || !occ) {
        fprintf(stderr, "%s: out of memory\n", what);
        exit(1);
    }
    for (int i = 0; i < count; i++)
        rays[i] = cases[i].ray;
    rtTraceRays(count, rays, hits);
    CHECK_NO_ERR();
    rtOccludedRays(count, rays, occ);
    CHECK_NO_ERR();
    long bad = 0;
    for (int i = 0; i < count; i++) {
        const RThit *h = &hits[i];
        int hit = h->t < INFINITY;
        int ok = hit == cases[i].expect_hit && occ[i] == (RTboolean)hit && !isnan(h->u) &&
                 !isnan(h->v) && (!hit || (h->t == cases[i].expect_t && h->object == object));
        if (!ok && bad++ < MAX_PRINTED)
            fprintf(stderr,
                    "  %s: org (%.9g, %.9g, %.9g) dir (%g, %g, %g): expected %s t %.9g, got t "
                    "%.9g (occluded %d) primitive %u\n",
                    what, rays[i].org[0], rays[i].org[1], rays[i].org[2], rays[i].dir[0],
                    rays[i].dir[1], rays[i].dir[2], cases[i].expect_hit ? "hit" : "miss",
                    cases[i].expect_t, h->t, occ[i], h->primitive);
    }
    free(rays);
    free(hits);
    free(occ);
    return bad;
}

static void grid_rays(int flat)
{
    static struct ray_case cases[6 * 2 * 3 * 400];
    int count = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int sign = -1; sign <= 1; sign += 2) {
            rtBeginFrame();
            if (flat) {
                rtInstantiateObject(GRID_FLAT + 10 * (axis * 2 + (sign > 0)));
            } else {
                rtPushMatrix();
                orient(axis, sign);
                rtInstantiateObject(GRID);
                rtPopMatrix();
            }
            count = 0;
            for (int j = -1; j <= 9; j++)
                for (int i = -1; i <= 9; i++) {
                    double x = i / 8.0, y = j / 8.0;
                    int inside = i >= 0 && i <= 8 && j >= 0 && j <= 8;
                    if (!inside) {
                        /* Just outside: nudge the out-of-range coordinate
                         * to 2^-20 beyond the grid's edge. */
                        x = i < 0 ? -0x1p-20 : i > 8 ? 1.0 + 0x1p-20 : x;
                        y = j < 0 ? -0x1p-20 : j > 8 ? 1.0 + 0x1p-20 : y;
                    }
                    double p[3];
                    oriented_point(axis, sign, x, y, p);
                    /* The ray comes from the side the normal points to and
                     * travels against it; three lengths, and -0.0 zeros. */
                    for (int variant = 0; variant < 3; variant++) {
                        static const float lengths[3] = {1.0f, 0.5f, 4.0f};
                        struct ray_case *c = &cases[count++];
                        for (int k = 0; k < 3; k++) {
                            c->ray.org[k] = (float)p[k];
                            c->ray.dir[k] = variant == 1 ? -0.0f : 0.0f;
                        }
                        c->ray.org[axis] += 2.0f * (float)sign;
                        c->ray.dir[axis] = -(float)sign * lengths[variant];
                        c->ray.tmin = 0.0f;
                        c->ray.tmax = INFINITY;
                        c->expect_hit = inside;
                        c->expect_t = 2.0f / lengths[variant];
                    }
                    /* The reverse direction from behind: also a hit. */
                    struct ray_case *c = &cases[count++];
                    for (int k = 0; k < 3; k++) {
                        c->ray.org[k] = (float)p[k];
                        c->ray.dir[k] = 0.0f;
                    }
                    c->ray.org[axis] -= 2.0f * (float)sign;
                    c->ray.dir[axis] = (float)sign;
                    c->ray.tmin = 0.0f;
                    c->ray.tmax = INFINITY;
                    c->expect_hit = inside;
                    c->expect_t = 2.0f;
                }
            char what[64];
            snprintf(what, sizeof(what), "%s grid facing %c%c", flat ? "flattened" : "instanced",
                     sign > 0 ? '+' : '-', "xyz"[axis]);
            CHECK_INT(run_cases(cases, count,
                                flat ? GRID_FLAT + 10 * (axis * 2 + (sign > 0)) : GRID, what),
                      0);
        }
}

/* Grazing rays in the planes of the box's faces. */
static void grazing_rays(void)
{
    static struct ray_case cases[4096];
    int count = 0;
    rtBeginFrame();
    rtInstantiateObject(BOX);
    for (int plane_axis = 0; plane_axis < 3; plane_axis++)
        for (int plane_side = 0; plane_side < 2; plane_side++)
            for (int along = 0; along < 3; along++) {
                if (along == plane_axis)
                    continue;
                int other = 3 - plane_axis - along;
                for (int dir_sign = -1; dir_sign <= 1; dir_sign += 2)
                    for (int s = -2; s <= 10; s++) {
                        /* The ray lies in the plane coordinate[plane_axis]
                         * = plane_side and runs along `along`; its third
                         * coordinate sweeps across the face, edges
                         * included, and beyond. */
                        double w = s / 8.0;
                        struct ray_case *c = &cases[count++];
                        float o[3];
                        o[plane_axis] = (float)plane_side;
                        o[other] = (float)w;
                        o[along] = dir_sign > 0 ? -1.0f : 2.0f;
                        for (int k = 0; k < 3; k++) {
                            c->ray.org[k] = o[k];
                            c->ray.dir[k] = 0.0f;
                        }
                        c->ray.dir[along] = (float)dir_sign;
                        c->ray.tmin = 0.0f;
                        c->ray.tmax = INFINITY;
                        /* It meets the face perpendicular to `along` on
                         * that face's edge (or on a box edge) at t = 1. */
                        c->expect_hit = s >= 0 && s <= 8;
                        c->expect_t = 1.0f;
                    }
            }
    CHECK_INT(run_cases(cases, count, BOX, "grazing"), 0);
}

int main(void)
{
    RTcontext ctx = tu_make_context(NULL);
    rtNewObject(GRID);
    emit_grid();
    rtEndObject();
    for (int axis = 0; axis < 3; axis++)
        for (int sign = -1; sign <= 1; sign += 2) {
            rtNewObject(GRID_FLAT + 10 * (axis * 2 + (sign > 0)));
            rtPushMatrix();
            orient(axis, sign);
            emit_grid();
            rtPopMatrix();
            rtEndObject();
        }
    rtNewObject(BOX);
    emit_box();
    rtEndObject();
    CHECK_NO_ERR();

    tu_section("axis-parallel rays onto instanced grids");
    grid_rays(0);
    tu_section("axis-parallel rays onto flattened grids");
    grid_rays(1);
    tu_section("rays grazing along the faces of a box");
    grazing_rays();
    tu_destroy_context(ctx);
    return test_summary("stability_axis");
}
