/* SPDX-License-Identifier: Apache-2.0 */
/*
 * stability_matrices.c - near-singular, singular and extreme instance
 * matrices.
 *
 * An object (a closed box [-1,1]^3 of 12 triangles plus 200 random small
 * triangles inside [-1,1]^3) is placed under:
 *   - near-singular matrices: scale 1e-7 along one of the object's axes,
 *     then a random rotation or none, then a translation.
 *     rtInstantiateObject accepts them (no error, the instance is counted),
 *     and rays hit what the double-precision reference (brute_force.h) hits.
 *     (Not tested: a rotation applied BEFORE the near-singular scale, T R1 S
 *     R2.  Its inverse maps a ray origin 10 units from the object to about
 *     1e8 units from it along an oblique object-space direction, so every
 *     object-space coordinate of the origin carries a float rounding error
 *     of several units against an object 2 units wide: no float
 *     object-space traversal can answer that, only flattening the object
 *     into world space can.);
 *   - exactly singular matrices (singular as stored, in double: a zero
 *     scale alone or under an exact 90-degree rotation, a zero upper 3x3,
 *     a third row that is the sum of the first two, a rank-one matrix).  rtInstantiateObject
 * records RT_INVALID_VALUE, and the instance list and the hits are unchanged;
 *   - huge and tiny uniform scales (1e-30, 1e-15, 1e15, 1e30), rotated, and
 *     a long thin beam (scales 1e-3, 1, 1e3 along the object's axes, then
 *     rotated): hits match the reference, with rays whose origins,
 *     directions and distances scale with the scene.
 * Each placement is checked with 20k rays aimed at random points of random
 * world triangles (a tenth on edges) plus random rays, judged by
 * bf_check_hit with rel_t = 1e-4 and pos_eps = 1e-5 times the largest
 * coordinate magnitude (query_brute_force.c explains the value), and
 * rtOccludedRays must agree with rtTraceRays.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brute_force.h"
#include "testutil.h"

#define OBJECT 1
#define RAYS 20000
#define REL_T 1e-4
#define POS_EPS_PER_UNIT 1e-5
#define MAX_PRINTED 8

static float *positions;
static uint32_t tri_count;

static void make_object(void)
{
    struct bf_rng r;
    bf_seed(&r, 9u);
    tri_count = 12 + 200;
    positions = malloc((size_t)tri_count * 9 * sizeof(float));
    /* The box: two triangles per face. */
    uint32_t t = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int side = -1; side <= 1; side += 2) {
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            float q[4][3];
            static const int su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
            for (int c = 0; c < 4; c++) {
                q[c][axis] = (float)side;
                q[c][u] = (float)su[c];
                q[c][v] = (float)sv[c];
            }
            memcpy(&positions[9 * t + 0], q[0], 3 * sizeof(float));
            memcpy(&positions[9 * t + 3], q[1], 3 * sizeof(float));
            memcpy(&positions[9 * t + 6], q[2], 3 * sizeof(float));
            t++;
            memcpy(&positions[9 * t + 0], q[0], 3 * sizeof(float));
            memcpy(&positions[9 * t + 3], q[2], 3 * sizeof(float));
            memcpy(&positions[9 * t + 6], q[3], 3 * sizeof(float));
            t++;
        }
    for (; t < tri_count; t++) {
        double c[3] = {bf_range(&r, -0.8, 0.8), bf_range(&r, -0.8, 0.8), bf_range(&r, -0.8, 0.8)};
        for (int k = 0; k < 9; k++)
            positions[9 * t + k] = (float)(c[k % 3] + bf_range(&r, -0.2, 0.2));
    }
    rtNewObject(OBJECT);
    rtBegin(RT_TRIANGLES);
    for (uint32_t i = 0; i < 3 * tri_count; i++)
        rtVertex3fv(&positions[3 * i]);
    rtEnd();
    rtEndObject();
}

static RTint instance_count(void)
{
    RTint n = -1;
    rtGetIntegerv(RT_INSTANCE_COUNT, &n);
    return n;
}

/* Places the object under m (alone) and judges RAYS rays. */
static void check_placement(const char *label, const double m[16], struct bf_rng *r)
{
    tu_section(label);
    rtBeginFrame();
    rtLoadMatrixd(m);
    rtInstantiateObject(OBJECT);
    rtLoadIdentity();
    CHECK_NO_ERR();
    rtFinish();
    CHECK_INT(instance_count(), 1);

    struct bf_scene ref;
    memset(&ref, 0, sizeof(ref));
    bf_scene_add_instance(&ref, positions, tri_count, m, OBJECT);
    double centre[3] = {0, 0, 0}, lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (size_t i = 0; i < ref.count; i++)
        for (int c = 0; c < 3; c++)
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], ref.tris[i].v[c][k]);
                hi[k] = fmax(hi[k], ref.tris[i].v[c][k]);
            }
    double size = 0.0, magnitude = 0.0;
    for (int k = 0; k < 3; k++) {
        centre[k] = 0.5 * (lo[k] + hi[k]);
        size = fmax(size, hi[k] - lo[k]);
    }
    double radius = 2.0 * size;
    for (int k = 0; k < 3; k++)
        magnitude = fmax(magnitude, fabs(centre[k]) + radius);

    RTray *rays = malloc(RAYS * sizeof(*rays));
    RThit *hits = malloc(RAYS * sizeof(*hits));
    RTboolean *occ = malloc(RAYS);
    for (int i = 0; i < RAYS; i++) {
        double u[3], org[3], dir[3];
        bf_unit_vector(r, u);
        for (int k = 0; k < 3; k++)
            org[k] = centre[k] + radius * u[k];
        if (bf_uniform(r) < 0.8) {
            const struct bf_tri *t = &ref.tris[bf_below(r, (uint32_t)ref.count)];
            double a = bf_uniform(r), b = bf_uniform(r);
            if (bf_uniform(r) < 0.1)
                b = 1.0 - a; /* on the edge v1 v2 */
            else if (a + b > 1.0) {
                a = 1.0 - a;
                b = 1.0 - b;
            }
            for (int k = 0; k < 3; k++)
                dir[k] = t->v[0][k] + a * (t->v[1][k] - t->v[0][k]) +
                         b * (t->v[2][k] - t->v[0][k]) - org[k];
        } else {
            bf_unit_vector(r, dir);
            for (int k = 0; k < 3; k++)
                dir[k] = centre[k] + 0.5 * size * dir[k] - org[k];
        }
        for (int k = 0; k < 3; k++) {
            rays[i].org[k] = (float)org[k];
            rays[i].dir[k] = (float)dir[k];
        }
        rays[i].tmin = 0.0f;
        rays[i].tmax = INFINITY;
    }
    rtTraceRays(RAYS, rays, hits);
    rtOccludedRays(RAYS, rays, occ);
    CHECK_NO_ERR();
    struct bf_tolerance tol = {REL_T, POS_EPS_PER_UNIT * magnitude};
    struct bf_stats stats;
    memset(&stats, 0, sizeof(stats));
    long failures = 0, disagree = 0;
    char why[256];
    for (int i = 0; i < RAYS; i++) {
        if (occ[i] != (RTboolean)(hits[i].t < INFINITY))
            disagree++;
        if (!bf_check_hit(&ref, &rays[i], &hits[i], &tol, &stats, why, sizeof(why)) &&
            failures++ < MAX_PRINTED)
            fprintf(stderr,
                    "  ray %d: %s\n    org (%.9g, %.9g, %.9g) dir (%.9g, %.9g, %.9g); hit t %.9g "
                    "primitive %u\n",
                    i, why, rays[i].org[0], rays[i].org[1], rays[i].org[2], rays[i].dir[0],
                    rays[i].dir[1], rays[i].dir[2], hits[i].t, hits[i].primitive);
    }
    printf("   %ld hits of %d rays, %ld exact, %ld tolerated, %ld failed (pos_eps %.3g)\n",
           stats.hits, RAYS, stats.exact, stats.tolerated, failures, tol.pos_eps);
    CHECK_INT(failures, 0);
    CHECK_INT(disagree, 0);
    CHECK(stats.hits > RAYS / 2);
    free(rays);
    free(hits);
    free(occ);
    bf_scene_free(&ref);
}

static void compose(double out[16], const double t[3], const double *r1, const double s[3],
                    const double *r2)
{
    double tm[16], sm[16];
    bf_translation(tm, t[0], t[1], t[2]);
    bf_scaling(sm, s[0], s[1], s[2]);
    bf_identity(out);
    bf_mul(out, out, tm);
    if (r1)
        bf_mul(out, out, r1);
    bf_mul(out, out, sm);
    if (r2)
        bf_mul(out, out, r2);
}

/* A singular matrix is rejected and changes nothing. */
static void check_singular(const char *label, const double m[16], const RTray *probe,
                           const RThit *before)
{
    tu_section(label);
    rtLoadMatrixd(m);
    rtInstantiateObject(OBJECT);
    CHECK_ERR(RT_INVALID_VALUE);
    rtLoadIdentity();
    CHECK_INT(instance_count(), 1);
    RThit after[64];
    rtTraceRays(64, probe, after);
    CHECK_NO_ERR();
    CHECK(memcmp(before, after, sizeof(after)) == 0);
}

int main(void)
{
    RTcontext ctx = tu_make_context(NULL);
    make_object();
    CHECK_NO_ERR();
    struct bf_rng r;
    bf_seed(&r, 2025u);
    double r1[16], r2[16], m[16];
    bf_random_rotation(&r, r1);
    bf_random_rotation(&r, r2);

    for (int axis = 0; axis < 3; axis++) {
        double s[3] = {1.5, 1.5, 1.5}, t[3] = {3.0, -2.0, 1.0};
        s[axis] = 1e-7;
        char label[96];
        snprintf(label, sizeof(label), "scale 1e-7 on axis %d, axis-aligned", axis);
        compose(m, t, NULL, s, NULL);
        check_placement(label, m, &r);
        snprintf(label, sizeof(label), "scale 1e-7 on axis %d, then rotated", axis);
        compose(m, t, r1, s, NULL);
        check_placement(label, m, &r);
    }
    static const double scales[4] = {1e-30, 1e-15, 1e15, 1e30};
    for (int i = 0; i < 4; i++) {
        double s[3] = {scales[i], scales[i], scales[i]};
        double t[3] = {0.5 * scales[i], -2.0 * scales[i], 0.25 * scales[i]};
        char label[64];
        snprintf(label, sizeof(label), "uniform scale %g, rotated", scales[i]);
        compose(m, t, r1, s, NULL);
        check_placement(label, m, &r);
    }
    {
        /* A long thin beam: scaled along its own axes, then rotated. */
        double s[3] = {1e-3, 1.0, 1e3}, t[3] = {10.0, 0.0, 0.0};
        compose(m, t, r1, s, NULL);
        check_placement("scales 1e-3, 1, 1e3 along the object's axes, rotated", m, &r);
    }

    /* Singular matrices, tried after a frame with one good instance. */
    double good[16], t0[3] = {0, 0, -5}, s1[3] = {1, 1, 1};
    compose(good, t0, r1, s1, NULL);
    rtBeginFrame();
    rtLoadMatrixd(good);
    rtInstantiateObject(OBJECT);
    RTray probe[64];
    RThit before[64];
    for (int i = 0; i < 64; i++) {
        probe[i] =
            tu_ray((float)bf_range(&r, -1, 1), (float)bf_range(&r, -1, 1), 0.0f, 0.0f, 0.0f, -1.0f);
    }
    rtTraceRays(64, probe, before);
    CHECK_NO_ERR();
    /* Singular in their floating-point representation, not just in exact
     * arithmetic (rounding would make a rotated zero scale invertible):
     * zero scales alone or under an exact 90-degree rotation. */
    for (int axis = 0; axis < 3; axis++) {
        double s[3] = {2.0, 2.0, 2.0}, t[3] = {0, 0, -5};
        s[axis] = 0.0;
        double quarter[16];
        bf_identity(quarter);
        quarter[0] = quarter[5] = 0.0;
        quarter[1] = 1.0;
        quarter[4] = -1.0; /* exact rotation by 90 degrees about z */
        compose(m, t, axis == 1 ? quarter : NULL, s, NULL);
        check_singular("exactly singular: zero scale", m, probe, before);
    }
    double zero[16] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 1};
    check_singular("exactly singular: zero upper 3x3", zero, probe, before);
    /* Rows (1 2 3), (4 5 6), (5 7 9): the third is the sum of the others. */
    double dependent[16] = {1, 4, 5, 0, 2, 5, 7, 0, 3, 6, 9, 0, 0, 0, -5, 1};
    check_singular("exactly singular: dependent rows", dependent, probe, before);
    /* Rank one: the outer product of (1, 2, -1) and (3, 0.5, 2). */
    double rank1[16] = {3, 6, -3, 0, 0.5, 1, -0.5, 0, 2, 4, -2, 0, 1, 1, -5, 1};
    check_singular("exactly singular: rank one", rank1, probe, before);

    free(positions);
    tu_destroy_context(ctx);
    return test_summary("stability_matrices");
}
