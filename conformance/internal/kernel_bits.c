/* SPDX-License-Identifier: Apache-2.0 */
/*
 * kernel_bits.c - answers of the ray/triangle kernel that only a bit-for-bit
 * comparison sees.
 *
 * Hits must be identical whatever the kernel's implementation (inlined
 * min/max, early rejections, ISA): an image or a query answer must not
 * change by one bit.  The sign of a zero hit distance is such a bit.  A
 * ray starting exactly on a vertex, running along an axis with a negative
 * zero direction component, gets t = 0 from the clamp into the
 * triangle's box (intersect.h), whose far end is the largest of the
 * vertices' sheared depths; when those are -0 and +0, which of the two
 * wins was decided by fmaxf's tie rule on x86-64 (maxss: the second
 * argument).  An inlined max with the other tie rule gives t = -0 for
 * the first case below and fails this test.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "accel_testgeo.h"
#include "trace/trace.h"

static int failures;

static uint32_t bits(float f)
{
    uint32_t b;
    memcpy(&b, &f, sizeof(b));
    return b;
}

static void signed_zero_case(const float v0[3], const float v1[3], const float v2[3],
                             uint32_t want_t_bits, const char *name)
{
    const float org[3] = {-0.25f, 0.0f, 0.375f};
    const float dir[3] = {0.0f, 1.0f, -0.0f};
    struct trace_ray ray;
    trace_ray_init(&ray, org, dir, 0.0f);
    float t = NAN, u = NAN, v = NAN;
    int hit = trace_triangle(&ray, v0, v1, v2, INFINITY, &t, &u, &v);
    TG_CHECK(failures, hit && t == 0.0f && bits(t) == want_t_bits,
             "%s: hit %d, t %a (bits %08x, want %08x)", name, hit, t, bits(t), want_t_bits);
}

int main(void)
{
    printf("kernel_bits:\n");
    /* The origin is v2 of the first triangle and of the second. */
    const float a0[3] = {-0.375f, -0.125f, 0.5f};
    const float a1[3] = {-0.25f, -0.0f, 0.5f};
    const float a2[3] = {-0.25f, 0.0f, 0.375f};
    signed_zero_case(a0, a1, a2, 0x00000000u, "vertex hit, depths -0 and +0");
    const float b0[3] = {-0.25f, 0.125f, 0.25f};
    const float b1[3] = {-0.125f, 0.125f, 0.25f};
    const float b2[3] = {-0.25f, -0.0f, 0.375f};
    signed_zero_case(b0, b1, b2, 0x80000000u, "vertex hit, depth -0 only");
    printf("  %s (%d failures)\n", failures ? "FAIL" : "ok", failures);
    return failures ? 1 : 0;
}
