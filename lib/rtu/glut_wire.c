/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_wire.c - rtuWireSphere, rtuWireCone, rtuWireTorus: the round wire
 * shapes of GLUT 3 (Kilgard 1996, sec. 11), drawn as lines through the
 * vertices of their solid namesakes (glut_shapes.c, quadric_*.c).
 *
 * GLUT 3.7 draws the wire sphere and cone as GLU quadrics in the GLU_LINE
 * style: the sphere's inner stack circles and its slice meridians, the
 * cone's stack circles (base to apex) and its slice lines, each a line
 * strip whose points are the filled quadric's vertices (same float
 * rounding), with the filled quadric's smooth normals.  The wire torus is
 * the doughnut in polygon mode GL_LINE: the outlines of its quads, which
 * are its ring circles and its tube circles; we emit each circle once as
 * a line strip through the solid's vertices (the same pixels; GL draws
 * the shared edges twice).  The cube, the regular solids and the teapot share
 * their files with the solid versions.
 */
#include "quadric_internal.h"
#include "report.h"

#include <math.h>
#include <stdlib.h>

void rtuWireSphere(RTdouble radius, RTint slices, RTint stacks)
{
    float sin1a[RTU_QUADRIC_CACHE], cos1a[RTU_QUADRIC_CACHE];
    float sin1b[RTU_QUADRIC_CACHE], cos1b[RTU_QUADRIC_CACHE];
    float sin2b[RTU_QUADRIC_CACHE], cos2b[RTU_QUADRIC_CACHE];
    int i, j;
    if (slices >= RTU_QUADRIC_CACHE)
        slices = RTU_QUADRIC_CACHE - 1;
    if (stacks >= RTU_QUADRIC_CACHE)
        stacks = RTU_QUADRIC_CACHE - 1;
    if (slices < 2 || stacks < 1 || !(radius >= 0.0) || !isfinite(radius)) {
        rtu_record_error(RT_INVALID_VALUE, "rtuWireSphere",
                         "needs slices >= 2, stacks >= 1 and a finite radius >= 0");
        return;
    }
    /* The tables of rtu_sphere_fill (outside, smooth). */
    for (i = 0; i < slices; i++) {
        float angle = (float)(2 * RTU_PI * i / slices);
        sin1a[i] = (float)sin(angle);
        cos1a[i] = (float)cos(angle);
    }
    sin1a[slices] = sin1a[0];
    cos1a[slices] = cos1a[0];
    for (j = 0; j <= stacks; j++) {
        float angle = (float)(RTU_PI * j / stacks);
        sin2b[j] = (float)sin(angle);
        cos2b[j] = (float)cos(angle);
        sin1b[j] = (float)(radius * sin(angle));
        cos1b[j] = (float)(radius * cos(angle));
    }
    sin1b[0] = 0.0f;
    sin1b[stacks] = 0.0f;
    /* Stack circles (the poles are points: none there). */
    for (j = 1; j < stacks; j++) {
        rtBegin(RT_LINE_STRIP);
        for (i = 0; i <= slices; i++) {
            rtNormal3f(sin1a[i] * sin2b[j], cos1a[i] * sin2b[j], cos2b[j]);
            rtVertex3f(sin1b[j] * sin1a[i], sin1b[j] * cos1a[i], cos1b[j]);
        }
        rtEnd();
    }
    /* Slice meridians, pole to pole. */
    for (i = 0; i < slices; i++) {
        rtBegin(RT_LINE_STRIP);
        for (j = 0; j <= stacks; j++) {
            rtNormal3f(sin1a[i] * sin2b[j], cos1a[i] * sin2b[j], cos2b[j]);
            rtVertex3f(sin1b[j] * sin1a[i], sin1b[j] * cos1a[i], cos1b[j]);
        }
        rtEnd();
    }
}

void rtuWireCone(RTdouble base, RTdouble height, RTint slices, RTint stacks)
{
    float sin1[RTU_QUADRIC_CACHE], cos1[RTU_QUADRIC_CACHE];
    float sin2[RTU_QUADRIC_CACHE], cos2[RTU_QUADRIC_CACHE];
    float length, z_normal, xy_ratio, delta_radius;
    int i, j;
    if (slices >= RTU_QUADRIC_CACHE)
        slices = RTU_QUADRIC_CACHE - 1;
    if (slices < 2 || stacks < 1 || !(base >= 0.0) || !(height >= 0.0) || !isfinite(base) ||
        !isfinite(height) || (base == 0.0 && height == 0.0)) {
        rtu_record_error(RT_INVALID_VALUE, "rtuWireCone",
                         "needs slices >= 2, stacks >= 1, finite base and height >= 0, "
                         "not both 0");
        return;
    }
    /* The tables of rtu_cylinder_fill with top radius 0 (outside). */
    delta_radius = (float)base;
    length = (float)sqrt(delta_radius * delta_radius + height * height);
    z_normal = delta_radius / length;
    xy_ratio = (float)(height / length);
    for (i = 0; i < slices; i++) {
        float angle = (float)(2 * RTU_PI * i / slices);
        sin2[i] = (float)(xy_ratio * sin(angle));
        cos2[i] = (float)(xy_ratio * cos(angle));
        sin1[i] = (float)sin(angle);
        cos1[i] = (float)cos(angle);
    }
    sin1[slices] = sin1[0];
    cos1[slices] = cos1[0];
    sin2[slices] = sin2[0];
    cos2[slices] = cos2[0];
    /* Stack circles, base to apex (the apex circle has radius 0). */
    for (j = 0; j <= stacks; j++) {
        const float z = (float)(j * height / stacks);
        const float r = (float)(base - delta_radius * ((float)j / stacks));
        rtBegin(RT_LINE_STRIP);
        for (i = 0; i <= slices; i++) {
            rtNormal3f(sin2[i], cos2[i], z_normal);
            rtVertex3f(r * sin1[i], r * cos1[i], z);
        }
        rtEnd();
    }
    /* Slice lines, base to apex. */
    for (i = 0; i < slices; i++) {
        rtBegin(RT_LINE_STRIP);
        rtNormal3f(sin2[i], cos2[i], z_normal);
        for (j = 0; j <= stacks; j++) {
            const float z = (float)(j * height / stacks);
            const float r = (float)(base - delta_radius * ((float)j / stacks));
            rtVertex3f(r * sin1[i], r * cos1[i], z);
        }
        rtEnd();
    }
}

void rtuWireTorus(RTdouble innerRadius, RTdouble outerRadius, RTint sides, RTint rings)
{
    /* The angles of rtuSolidTorus, accumulated in float as it does:
     * ring k at theta_k (k = 0 .. rings), tube point m at phi_m
     * (m = 1 .. sides + 1; phi_(sides+1) closes the tube). */
    const float r = (float)innerRadius;
    const float big_r = (float)outerRadius;
    float *cos_theta, *sin_theta, *cos_phi, *sin_phi;
    float theta = 0.0f, phi = 0.0f, ring_delta, side_delta;
    int k, m;
    if (sides < 1 || rings < 1 || !(innerRadius >= 0.0) || !(outerRadius >= 0.0) ||
        !isfinite(innerRadius) || !isfinite(outerRadius) || sides > (1 << 20) ||
        rings > (1 << 20)) {
        rtu_record_error(RT_INVALID_VALUE, "rtuWireTorus",
                         "sides and rings must be in 1 .. 2^20, the radii finite and >= 0");
        return;
    }
    ring_delta = (float)(2.0 * RTU_PI / rings);
    side_delta = (float)(2.0 * RTU_PI / sides);
    cos_theta = malloc(sizeof(float) * (size_t)(2 * (rings + 1) + 2 * (sides + 2)));
    if (!cos_theta) {
        rtu_record_error(RT_OUT_OF_MEMORY, "rtuWireTorus", "out of memory");
        return;
    }
    sin_theta = cos_theta + rings + 1;
    cos_phi = sin_theta + rings + 1;
    sin_phi = cos_phi + sides + 2;
    cos_theta[0] = 1.0f;
    sin_theta[0] = 0.0f;
    for (k = 1; k <= rings; k++) {
        theta = theta + ring_delta;
        cos_theta[k] = (float)cos(theta);
        sin_theta[k] = (float)sin(theta);
    }
    for (m = 1; m <= sides + 1; m++) {
        phi += side_delta;
        cos_phi[m] = (float)cos(phi);
        sin_phi[m] = (float)sin(phi);
    }
    /* The outlines of the solid's quads without repeats: the tube lines at
     * every ring boundary k = 0 .. rings, then the ring lines at every
     * tube point m = 1 .. sides + 1, each a strip through the solid's
     * vertices (its last ring and tube point close the circles with the
     * solid's own floats). */
    for (k = 0; k <= rings; k++) {
        rtBegin(RT_LINE_STRIP);
        for (m = 1; m <= sides + 1; m++) {
            const float dist = big_r + r * cos_phi[m];
            rtNormal3f(cos_theta[k] * cos_phi[m], -sin_theta[k] * cos_phi[m], sin_phi[m]);
            rtVertex3f(cos_theta[k] * dist, -sin_theta[k] * dist, r * sin_phi[m]);
        }
        rtEnd();
    }
    for (m = 1; m <= sides + 1; m++) {
        const float dist = big_r + r * cos_phi[m];
        rtBegin(RT_LINE_STRIP);
        for (k = 0; k <= rings; k++) {
            rtNormal3f(cos_theta[k] * cos_phi[m], -sin_theta[k] * cos_phi[m], sin_phi[m]);
            rtVertex3f(cos_theta[k] * dist, -sin_theta[k] * dist, r * sin_phi[m]);
        }
        rtEnd();
    }
    free(cos_theta);
}
