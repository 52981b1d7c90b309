/* SPDX-License-Identifier: Apache-2.0 */
/*
 * quadric_cylinder.c - rtuCylinder (gluCylinder): its angle tables and the
 * filled side (the other draw styles are in quadric_wire.c).
 *
 * GLU 1.3: a (truncated) cone along +z from z = 0 (radius baseRadius) to
 * z = height (radius topRadius), without end caps; slice i at angle
 * 2 pi i / slices from +y towards +x (x = r sin, y = r cos), stacks
 * equally spaced in z, one quad strip per stack.  Texture coordinates
 * s = 1 - i/slices, t = j/stacks (t = 0 at z = 0).  Normals point away
 * from the axis (towards it inside) tilted by the cone's slope: (h sin,
 * h cos, baseRadius - topRadius) / length; flat ones at the facet centres.
 * Computed in single precision at the places Mesa's libGLU rounds
 * (quadric_internal.h).
 */
#include "quadric_internal.h"

#include <math.h>

void rtu_cylinder_tables(struct rtu_cylinder_tables *t, const struct rtu_quadric *q,
                         double base_radius, double top_radius, double height, int slices)
{
    const float delta_radius = (float)(base_radius - top_radius);
    const float length =
        (float)sqrt(delta_radius * delta_radius + height * height);
    const float xy_ratio = (float)(height / length);
    const double signed_ratio = q->orientation == RTU_OUTSIDE ? xy_ratio : -xy_ratio;
    int i;

    t->delta_radius = delta_radius;
    t->z_normal = delta_radius / length;
    for (i = 0; i < slices; i++) {
        float angle = (float)(2 * RTU_PI * i / slices);
        t->sin2[i] = (float)(signed_ratio * sin(angle));
        t->cos2[i] = (float)(signed_ratio * cos(angle));
        t->sin1[i] = (float)sin(angle);
        t->cos1[i] = (float)cos(angle);
        angle = (float)(2 * RTU_PI * (i - 0.5) / slices);
        t->sin3[i] = (float)(signed_ratio * sin(angle));
        t->cos3[i] = (float)(signed_ratio * cos(angle));
    }
    t->sin1[slices] = t->sin1[0];
    t->cos1[slices] = t->cos1[0];
    t->sin2[slices] = t->sin2[0];
    t->cos2[slices] = t->cos2[0];
    t->sin3[slices] = t->sin3[0];
    t->cos3[slices] = t->cos3[0];
}

void rtu_cylinder_fill(const struct rtu_quadric *q, double base_radius, double top_radius,
                       double height, int slices, int stacks)
{
    struct rtu_cylinder_tables t;
    const float *sin1 = t.sin1, *cos1 = t.cos1, *sin2 = t.sin2, *cos2 = t.cos2;
    const float *sin3 = t.sin3, *cos3 = t.cos3;
    const int outside = q->orientation == RTU_OUTSIDE;
    float delta_radius, z_normal;
    int i, j;

    rtu_cylinder_tables(&t, q, base_radius, top_radius, height, slices);
    delta_radius = t.delta_radius;
    z_normal = t.z_normal;

    for (j = 0; j < stacks; j++) {
        const float z_low = (float)(j * height / stacks);
        const float z_high = (float)((j + 1) * height / stacks);
        const float r_low = (float)(base_radius - delta_radius * ((float)j / stacks));
        const float r_high = (float)(base_radius - delta_radius * ((float)(j + 1) / stacks));
        const float t_low = (float)j / stacks;
        const float t_high = (float)(j + 1) / stacks;
        rtBegin(RT_QUAD_STRIP);
        for (i = 0; i <= slices; i++) {
            const float s = 1 - (float)i / slices;
            if (q->normals == RTU_FLAT)
                rtNormal3f(sin3[i], cos3[i], z_normal);
            else if (q->normals == RTU_SMOOTH)
                rtNormal3f(sin2[i], cos2[i], z_normal);
            /* Outside: low then high, so the strip's quads face out. */
            if (outside) {
                if (q->texture)
                    rtTexCoord2f(s, t_low);
                rtVertex3f(r_low * sin1[i], r_low * cos1[i], z_low);
                if (q->texture)
                    rtTexCoord2f(s, t_high);
                rtVertex3f(r_high * sin1[i], r_high * cos1[i], z_high);
            } else {
                if (q->texture)
                    rtTexCoord2f(s, t_high);
                rtVertex3f(r_high * sin1[i], r_high * cos1[i], z_high);
                if (q->texture)
                    rtTexCoord2f(s, t_low);
                rtVertex3f(r_low * sin1[i], r_low * cos1[i], z_low);
            }
        }
        rtEnd();
    }
}

void rtuCylinder(RTUquadric *quadric, RTdouble baseRadius, RTdouble topRadius, RTdouble height,
                 RTint slices, RTint stacks)
{
    int ok;
    if (slices >= RTU_QUADRIC_CACHE)
        slices = RTU_QUADRIC_CACHE - 1;
    ok = slices >= 2 && stacks >= 1 && baseRadius >= 0.0 && topRadius >= 0.0 && height >= 0.0 &&
         isfinite(baseRadius) && isfinite(topRadius) && isfinite(height);
    /* GLU also refuses a cylinder whose side has no length (both radii
     * equal and no height): its normal is undefined. */
    if (ok) {
        float delta = (float)(baseRadius - topRadius);
        ok = (float)sqrt(delta * delta + height * height) != 0.0f;
    }
    if (!rtu_quadric_drawable("rtuCylinder", quadric, ok))
        return;
    if (quadric->draw_style == RTU_FILL)
        rtu_cylinder_fill(quadric, baseRadius, topRadius, height, slices, stacks);
    else
        rtu_cylinder_wire(quadric, baseRadius, topRadius, height, slices, stacks);
}
