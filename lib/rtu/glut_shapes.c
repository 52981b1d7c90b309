/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_shapes.c - rtuSolidSphere, rtuSolidCone, rtuSolidCube,
 * rtuSolidTorus: the round solids of GLUT 3 (Kilgard, "The OpenGL Utility
 * Toolkit (GLUT) Programming Interface, API Version 3", 1996, sec. 11).
 *
 * As in GLUT 3.7: the sphere and the cone are GLU quadrics with smooth
 * normals, filled, outside, without texture coordinates (the cone is
 * gluCylinder with top radius 0 and no base cap); the cube is six quads
 * with their face normals; the torus is GLUT's "doughnut", rings quad
 * strips of sides + 1 vertex pairs, in single precision.  Each emits
 * rtBegin .. rtEnd blocks, so it is called inside rtNewObject.  Bad
 * arguments record RT_INVALID_VALUE (report.h); GLUT draws nothing or
 * garbage for them.
 */
#include "quadric_internal.h"
#include "report.h"

#include <math.h>

void rtuSolidSphere(RTdouble radius, RTint slices, RTint stacks)
{
    struct rtu_quadric q;
    rtu_quadric_defaults(&q);
    rtuSphere(&q, radius, slices, stacks);
}

void rtuSolidCone(RTdouble base, RTdouble height, RTint slices, RTint stacks)
{
    struct rtu_quadric q;
    rtu_quadric_defaults(&q);
    rtuCylinder(&q, base, 0.0, height, slices, stacks);
}

/* GLUT's drawBox(size, type): six faces of four corners each, as `mode`
 * (RT_QUADS filled, RT_LINE_LOOP wire). */
static void draw_box(RTdouble size, RTenum mode, const char *caller)
{
    /* GLUT's drawBox: corners 0-3 at x = -size/2, 4-7 at +size/2; y and z
     * as set below.  Each face lists its corners counter-clockwise seen
     * from outside; faces are drawn last to first, as GLUT does. */
    static const float normals[6][3] = {{-1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f},
                                        {1.0f, 0.0f, 0.0f},  {0.0f, -1.0f, 0.0f},
                                        {0.0f, 0.0f, 1.0f},  {0.0f, 0.0f, -1.0f}};
    static const int faces[6][4] = {{0, 1, 2, 3}, {3, 2, 6, 7}, {7, 6, 5, 4},
                                    {4, 5, 1, 0}, {5, 6, 2, 1}, {7, 4, 0, 3}};
    float v[8][3];
    float h;
    int i, k;
    if (!(size >= 0.0) || !isfinite(size)) {
        rtu_record_error(RT_INVALID_VALUE, caller, "size must be finite and >= 0");
        return;
    }
    h = (float)(size / 2.0);
    for (k = 0; k < 8; k++) {
        v[k][0] = k < 4 ? -h : h;
        v[k][1] = (k == 0 || k == 1 || k == 4 || k == 5) ? -h : h;
        v[k][2] = (k == 0 || k == 3 || k == 4 || k == 7) ? -h : h;
    }
    for (i = 5; i >= 0; i--) {
        rtBegin(mode);
        rtNormal3fv(normals[i]);
        for (k = 0; k < 4; k++)
            rtVertex3fv(v[faces[i][k]]);
        rtEnd();
    }
}

void rtuSolidCube(RTdouble size)
{
    draw_box(size, RT_QUADS, "rtuSolidCube");
}

void rtuWireCube(RTdouble size)
{
    draw_box(size, RT_LINE_LOOP, "rtuWireCube");
}

void rtuSolidTorus(RTdouble innerRadius, RTdouble outerRadius, RTint sides, RTint rings)
{
    /* GLUT's doughnut: ring i spans angles theta .. theta + 2pi/rings about
     * z (turning clockwise seen from +z: y = -sin), each a quad strip
     * around the tube, whose radius is innerRadius; outerRadius is the
     * distance of the tube's centre from the axis. */
    const float r = (float)innerRadius;
    const float big_r = (float)outerRadius;
    const float ring_delta = (float)(2.0 * RTU_PI / rings);
    const float side_delta = (float)(2.0 * RTU_PI / sides);
    float theta = 0.0f, cos_theta = 1.0f, sin_theta = 0.0f;
    int i, j;
    if (sides < 1 || rings < 1 || !(innerRadius >= 0.0) || !(outerRadius >= 0.0) ||
        !isfinite(innerRadius) || !isfinite(outerRadius)) {
        rtu_record_error(RT_INVALID_VALUE, "rtuSolidTorus",
                         "sides and rings must be >= 1, the radii finite and >= 0");
        return;
    }
    for (i = rings - 1; i >= 0; i--) {
        const float theta1 = theta + ring_delta;
        const float cos_theta1 = (float)cos(theta1);
        const float sin_theta1 = (float)sin(theta1);
        float phi = 0.0f;
        rtBegin(RT_QUAD_STRIP);
        for (j = sides; j >= 0; j--) {
            float cos_phi, sin_phi, dist;
            phi += side_delta;
            cos_phi = (float)cos(phi);
            sin_phi = (float)sin(phi);
            dist = big_r + r * cos_phi;
            rtNormal3f(cos_theta1 * cos_phi, -sin_theta1 * cos_phi, sin_phi);
            rtVertex3f(cos_theta1 * dist, -sin_theta1 * dist, r * sin_phi);
            rtNormal3f(cos_theta * cos_phi, -sin_theta * cos_phi, sin_phi);
            rtVertex3f(cos_theta * dist, -sin_theta * dist, r * sin_phi);
        }
        rtEnd();
        theta = theta1;
        cos_theta = cos_theta1;
        sin_theta = sin_theta1;
    }
}
