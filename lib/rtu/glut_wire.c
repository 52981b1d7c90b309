/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_wire.c - rtuWireSphere, rtuWireCone, rtuWireTorus: the round wire
 * shapes of GLUT 3 (Kilgard 1996, sec. 11), drawn as lines through the
 * vertices of their solid namesakes (glut_shapes.c, quadric_*.c).
 *
 * GLUT 3.7 draws the wire sphere and cone as GLU quadrics in the GLU_LINE
 * style with smooth normals (gluSphere, gluCylinder with top radius 0), so
 * they are rtu's quadrics in RTU_LINE (quadric_wire.c): the sphere's
 * inner stack circles and its slice meridians, the cone's inner stack
 * circles, its base and apex circles and its slice lines, through the
 * filled quadric's vertices; the trace oracle compares them with libGLU's
 * calls.  The wire torus is
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

/* GLUT's quadric for the wire shapes: GLU's defaults in GLU_LINE. */
static void wire_quadric(struct rtu_quadric *q)
{
    rtu_quadric_defaults(q);
    q->draw_style = RTU_LINE;
}

void rtuWireSphere(RTdouble radius, RTint slices, RTint stacks)
{
    struct rtu_quadric q;
    if (slices >= RTU_QUADRIC_CACHE)
        slices = RTU_QUADRIC_CACHE - 1;
    if (stacks >= RTU_QUADRIC_CACHE)
        stacks = RTU_QUADRIC_CACHE - 1;
    if (slices < 2 || stacks < 1 || !(radius >= 0.0) || !isfinite(radius)) {
        rtu_record_error(RT_INVALID_VALUE, "rtuWireSphere",
                         "needs slices >= 2, stacks >= 1 and a finite radius >= 0");
        return;
    }
    wire_quadric(&q);
    rtu_sphere_wire(&q, radius, slices, stacks);
}

void rtuWireCone(RTdouble base, RTdouble height, RTint slices, RTint stacks)
{
    struct rtu_quadric q;
    if (slices >= RTU_QUADRIC_CACHE)
        slices = RTU_QUADRIC_CACHE - 1;
    if (slices < 2 || stacks < 1 || !(base >= 0.0) || !(height >= 0.0) || !isfinite(base) ||
        !isfinite(height) || (base == 0.0 && height == 0.0)) {
        rtu_record_error(RT_INVALID_VALUE, "rtuWireCone",
                         "needs slices >= 2, stacks >= 1, finite base and height >= 0, "
                         "not both 0");
        return;
    }
    wire_quadric(&q);
    rtu_cylinder_wire(&q, base, 0.0, height, slices, stacks);
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
