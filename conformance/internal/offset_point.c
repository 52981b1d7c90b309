/* SPDX-License-Identifier: Apache-2.0 */
/*
 * offset_point.c - shade_offset_point (lib/render/shade.c), whose steps
 * to the next float away from the surface are made on the bits, against
 * the same computation with libm's nextafterf, bit for bit: special
 * points (signed zeros, subnormals, the largest floats, infinities, NaN),
 * normals of every sign with zeros, error bounds from 0 to infinity, and
 * pseudo-random bit patterns; a mutation (a zero stepped to the
 * smallest normal instead of the smallest subnormal) fails it.
 *
 * Internal test (links the static library).  Non-zero exit on failure.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "render/shade.h"

/* shade_offset_point as written with nextafterf (its scale factor 2). */
static void reference(const float p[3], const float n[3], float error, float out[3])
{
    double d = 2.0 * (double)error;
    for (int k = 0; k < 3; k++) {
        double target = (double)p[k] + d * (double)n[k];
        float f = (float)target;
        if (n[k] > 0.0f && (double)f < target)
            f = nextafterf(f, INFINITY);
        else if (n[k] < 0.0f && (double)f > target)
            f = nextafterf(f, -INFINITY);
        out[k] = f;
    }
}

/* The same floats bit for bit; a NaN (a NaN point, normal or bound) as
 * any NaN: which operand's NaN a sum passes on is the compiler's choice
 * of operand order, not the step this test is about. */
static int same(const float p[3], const float n[3], float error)
{
    float a[3], b[3];
    shade_offset_point(p, n, error, a);
    reference(p, n, error, b);
    for (int k = 0; k < 3; k++)
        if (memcmp(&a[k], &b[k], sizeof(float)) != 0 && !(isnan(a[k]) && isnan(b[k])))
            return 0;
    return 1;
}

static float from_bits(uint32_t b)
{
    float f;
    memcpy(&f, &b, sizeof(f));
    return f;
}

int main(void)
{
    const float points[] = {0.0f,     -0.0f,      0x1p-149f,  -0x1p-149f, FLT_MIN,  -FLT_MIN,
                            1.0f,     -1.0f,      0.1f,       -12345.678f, 1e30f,   FLT_MAX,
                            -FLT_MAX, INFINITY,   -INFINITY,  NAN,        0x1p-140f, 3.0e-39f};
    const float normals[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.57735f, -0.57735f, 1e-30f, -1e-30f};
    const float errors[] = {0.0f, 0x1p-149f, 1e-7f, 1e-3f, 1.0f, 1e38f, FLT_MAX, INFINITY};
    const int np = (int)(sizeof(points) / sizeof(points[0]));
    const int nn = (int)(sizeof(normals) / sizeof(normals[0]));
    const int ne = (int)(sizeof(errors) / sizeof(errors[0]));

    tu_section("special points, normals and bounds");
    int bad = 0;
    for (int i = 0; i < np; i++)
        for (int j = 0; j < nn; j++)
            for (int e = 0; e < ne; e++) {
                const float p[3] = {points[i], points[(i + 5) % np], points[(i + 11) % np]};
                const float n[3] = {normals[j], normals[(j + 3) % nn], normals[(j + 6) % nn]};
                bad += !same(p, n, errors[e]);
            }
    CHECK_INT(bad, 0);

    tu_section("pseudo-random bits");
    uint32_t x = 0x9e3779b9u;
    bad = 0;
    for (int i = 0; i < 200000; i++) {
        float v[7];
        for (int k = 0; k < 7; k++) {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            v[k] = from_bits(x);
        }
        /* Bounds near the points' ulps, so that the rounding steps run. */
        const float error = fabsf(v[0]) * 0x1p-20f;
        const float p[3] = {v[1], v[2], v[3]};
        const float n[3] = {v[4], v[5], v[6]};
        bad += !same(p, n, error);
        bad += !same(p, n, fabsf(v[6]));
    }
    CHECK_INT(bad, 0);

    return test_summary("internal/offset_point");
}
