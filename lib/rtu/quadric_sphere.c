/* SPDX-License-Identifier: Apache-2.0 */
/*
 * quadric_sphere.c - rtuSphere (gluSphere): its angle tables and the
 * filled sphere (the other draw styles are in quadric_wire.c).
 *
 * Tessellation of GLU 1.3 as Mesa's libGLU draws it: the sphere is centred
 * at the origin with its axis on z; slice i lies at angle 2 pi i / slices
 * measured from +y towards +x (x = r sin, y = r cos), stack j at polar
 * angle pi j / stacks from +z.  Without texture coordinates the two polar
 * stacks are triangle fans around (0, 0, +-radius) and the others quad
 * strips; with them every stack is a quad strip (a pole vertex needs a
 * different s for every triangle).  Texture coordinates: s = 1 - i/slices,
 * t = 1 - j/stacks (so t is 0 at z = -radius and 1 at +radius as GLU
 * specifies; s runs the other way round from GLU's prose, as in every SGI
 * derived GLU, and we follow the implementation programs were tuned on).
 * Smooth normals are the unit radial vectors, flat ones those of the
 * facet centres (half a slice and half a stack back), negated inside.
 * Normals are given in GLU's order of calls, so the current normal when a
 * vertex is emitted is the one GLU's vertex gets.
 */
#include "quadric_internal.h"

#include <math.h>

void rtu_sphere_tables(struct rtu_sphere_tables *t, const struct rtu_quadric *q, double radius,
                       int slices, int stacks)
{
    const float sign = q->orientation == RTU_OUTSIDE ? 1.0f : -1.0f;
    int i, j;

    for (i = 0; i < slices; i++) {
        float angle = (float)(2 * RTU_PI * i / slices);
        t->sin1a[i] = (float)sin(angle);
        t->cos1a[i] = (float)cos(angle);
        angle = (float)(2 * RTU_PI * (i - 0.5) / slices);
        t->sin3a[i] = (float)sin(angle);
        t->cos3a[i] = (float)cos(angle);
    }
    t->sin1a[slices] = t->sin1a[0];
    t->cos1a[slices] = t->cos1a[0];
    t->sin3a[slices] = t->sin3a[0];
    t->cos3a[slices] = t->cos3a[0];
    for (j = 0; j <= stacks; j++) {
        float angle = (float)(RTU_PI * j / stacks);
        t->sin2b[j] = sign * (float)sin(angle);
        t->cos2b[j] = sign * (float)cos(angle);
        t->sin1b[j] = (float)(radius * sin(angle));
        t->cos1b[j] = (float)(radius * cos(angle));
        angle = (float)(RTU_PI * (j - 0.5) / stacks);
        t->sin3b[j] = sign * (float)sin(angle);
        t->cos3b[j] = sign * (float)cos(angle);
    }
    /* The poles are exactly on the axis. */
    t->sin1b[0] = 0.0f;
    t->sin1b[stacks] = 0.0f;
}

void rtu_sphere_fill(const struct rtu_quadric *q, double radius, int slices, int stacks)
{
    struct rtu_sphere_tables t;
    const float *sin1a = t.sin1a, *cos1a = t.cos1a, *sin3a = t.sin3a, *cos3a = t.cos3a;
    const float *sin1b = t.sin1b, *cos1b = t.cos1b, *sin2b = t.sin2b, *cos2b = t.cos2b;
    const float *sin3b = t.sin3b, *cos3b = t.cos3b;
    const int outside = q->orientation == RTU_OUTSIDE;
    const int smooth = q->normals == RTU_SMOOTH;
    const int flat = q->normals == RTU_FLAT;
    int i, j, start, finish;

    rtu_sphere_tables(&t, q, radius, slices, stacks);

    if (!q->texture) {
        float s2, z, s3 = 0.0f, c3 = 0.0f;
        start = 1;
        finish = stacks - 1;

        /* The fan around +z (stack 0). */
        s2 = sin1b[1];
        z = cos1b[1];
        if (flat) {
            s3 = sin3b[1];
            c3 = cos3b[1];
        } else if (smooth) {
            s3 = sin2b[1];
            c3 = cos2b[1];
            rtNormal3f(sin1a[0] * sin2b[0], cos1a[0] * sin2b[0], cos2b[0]);
        }
        rtBegin(RT_TRIANGLE_FAN);
        rtVertex3f(0.0f, 0.0f, (float)radius);
        for (int k = 0; k <= slices; k++) {
            /* Outside the fan turns clockwise seen from +z (i falling),
             * so that its triangles face out. */
            i = outside ? slices - k : k;
            if (smooth)
                rtNormal3f(sin1a[i] * s3, cos1a[i] * s3, c3);
            else if (flat && outside && i != slices)
                rtNormal3f(sin3a[i + 1] * s3, cos3a[i + 1] * s3, c3);
            else if (flat && !outside)
                rtNormal3f(sin3a[i] * s3, cos3a[i] * s3, c3);
            rtVertex3f(s2 * sin1a[i], s2 * cos1a[i], z);
        }
        rtEnd();

        /* The fan around -z (stack stacks - 1). */
        s2 = sin1b[stacks - 1];
        z = cos1b[stacks - 1];
        if (flat) {
            s3 = sin3b[stacks];
            c3 = cos3b[stacks];
        } else if (smooth) {
            /* GLU reads its slice table at index `stacks` here; the sine
             * factor is sin(pi), so x and y are below 1e-7 whatever it
             * holds.  We read a defined entry. */
            int k = stacks <= slices ? stacks : 0;
            s3 = sin2b[stacks - 1];
            c3 = cos2b[stacks - 1];
            rtNormal3f(sin1a[k] * sin2b[stacks], cos1a[k] * sin2b[stacks], cos2b[stacks]);
        }
        rtBegin(RT_TRIANGLE_FAN);
        rtVertex3f(0.0f, 0.0f, (float)-radius);
        for (int k = 0; k <= slices; k++) {
            i = outside ? k : slices - k;
            if (smooth)
                rtNormal3f(sin1a[i] * s3, cos1a[i] * s3, c3);
            else if (flat && outside)
                rtNormal3f(sin3a[i] * s3, cos3a[i] * s3, c3);
            else if (flat && !outside && i != slices)
                rtNormal3f(sin3a[i + 1] * s3, cos3a[i + 1] * s3, c3);
            rtVertex3f(s2 * sin1a[i], s2 * cos1a[i], z);
        }
        rtEnd();
    } else {
        start = 0;
        finish = stacks;
    }

    for (j = start; j < finish; j++) {
        const float z_low = cos1b[j];
        const float z_high = cos1b[j + 1];
        const float s_low = sin1b[j];
        const float s_high = sin1b[j + 1];
        /* First vertex of each pair: the high stack outside, the low one
         * inside; 3 is the first vertex's normal, 4 the second's. */
        const float t_first = 1 - (float)(outside ? j + 1 : j) / stacks;
        const float t_second = 1 - (float)(outside ? j : j + 1) / stacks;
        const float s_first = outside ? s_high : s_low;
        const float z_first = outside ? z_high : z_low;
        const float s_second = outside ? s_low : s_high;
        const float z_second = outside ? z_low : z_high;
        float s3 = 0.0f, c3 = 0.0f, s4 = 0.0f, c4 = 0.0f;
        if (flat) {
            s4 = sin3b[j + 1];
            c4 = cos3b[j + 1];
        } else if (smooth) {
            int first = outside ? j + 1 : j;
            int second = outside ? j : j + 1;
            s3 = sin2b[first];
            c3 = cos2b[first];
            s4 = sin2b[second];
            c4 = cos2b[second];
        }
        rtBegin(RT_QUAD_STRIP);
        for (i = 0; i <= slices; i++) {
            const float s = 1 - (float)i / slices;
            if (smooth)
                rtNormal3f(sin1a[i] * s3, cos1a[i] * s3, c3);
            if (q->texture)
                rtTexCoord2f(s, t_first);
            rtVertex3f(s_first * sin1a[i], s_first * cos1a[i], z_first);
            if (smooth)
                rtNormal3f(sin1a[i] * s4, cos1a[i] * s4, c4);
            else if (flat)
                rtNormal3f(sin3a[i] * s4, cos3a[i] * s4, c4);
            if (q->texture)
                rtTexCoord2f(s, t_second);
            rtVertex3f(s_second * sin1a[i], s_second * cos1a[i], z_second);
        }
        rtEnd();
    }
}

void rtuSphere(RTUquadric *quadric, RTdouble radius, RTint slices, RTint stacks)
{
    if (slices >= RTU_QUADRIC_CACHE)
        slices = RTU_QUADRIC_CACHE - 1;
    if (stacks >= RTU_QUADRIC_CACHE)
        stacks = RTU_QUADRIC_CACHE - 1;
    if (!rtu_quadric_drawable("rtuSphere", quadric, slices >= 2 && stacks >= 1 && radius >= 0.0 &&
                                           isfinite(radius)))
        return;
    if (quadric->draw_style == RTU_FILL)
        rtu_sphere_fill(quadric, radius, slices, stacks);
    else
        rtu_sphere_wire(quadric, radius, slices, stacks);
}
