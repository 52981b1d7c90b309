/* SPDX-License-Identifier: Apache-2.0 */
/*
 * quadric_disk.c - rtuDisk and rtuPartialDisk (gluDisk, gluPartialDisk):
 * the angle table and the filled disk (the other draw styles are in
 * quadric_wire.c).
 *
 * GLU 1.3: a disk (annulus) in the plane z = 0, from innerRadius to
 * outerRadius, in `loops` concentric rings; slice i at angle startAngle +
 * sweepAngle i / slices degrees, measured clockwise from +y (x = r sin,
 * y = r cos).  With innerRadius 0 the innermost ring is a triangle fan
 * around the centre.  The normal is +z (-z inside), given once before the
 * rings.  Texture coordinates map the disk of outerRadius onto the unit
 * square: (0.5 + r sin / (2 outerRadius), 0.5 + r cos / (2 outerRadius)).
 * A sweep beyond +-360 degrees becomes 360 and a negative sweep is turned
 * into a positive one from startAngle + sweepAngle, as Mesa's libGLU does.
 * rtuDisk is rtuPartialDisk(0, 360).  Single precision where libGLU rounds
 * (quadric_internal.h).
 */
#include "quadric_internal.h"

#include <math.h>

void rtu_disk_tables(struct rtu_disk_tables *t, int slices, double start_angle,
                     double sweep_angle)
{
    const float angle_offset = (float)(start_angle / 180.0 * RTU_PI);
    int i;
    for (i = 0; i <= slices; i++) {
        const float angle =
            (float)(angle_offset + ((RTU_PI * sweep_angle) / 180.0) * i / slices);
        t->sin1[i] = (float)sin(angle);
        t->cos1[i] = (float)cos(angle);
    }
    if (sweep_angle == 360.0) {
        t->sin1[slices] = t->sin1[0];
        t->cos1[slices] = t->cos1[0];
    }
}

static void partial_disk_fill(const struct rtu_quadric *q, double inner, double outer, int slices,
                              int loops, double start_angle, double sweep_angle)
{
    struct rtu_disk_tables t;
    const float *sin1 = t.sin1, *cos1 = t.cos1;
    const int outside = q->orientation == RTU_OUTSIDE;
    const float delta_radius = (float)(outer - inner);
    int i, j, finish;

    rtu_disk_tables(&t, slices, start_angle, sweep_angle);
    if (q->normals != RTU_NONE)
        rtNormal3f(0.0f, 0.0f, outside ? 1.0f : -1.0f);

    if (inner == 0.0) {
        const float r = (float)(outer - delta_radius * ((float)(loops - 1) / loops));
        const float tex = (float)(r / outer / 2);
        finish = loops - 1;
        rtBegin(RT_TRIANGLE_FAN);
        if (q->texture)
            rtTexCoord2f(0.5f, 0.5f);
        rtVertex3f(0.0f, 0.0f, 0.0f);
        for (int k = 0; k <= slices; k++) {
            /* Outside the fan runs with falling angle: counter-clockwise
             * seen from +z, as angles grow clockwise. */
            i = outside ? slices - k : k;
            if (q->texture)
                rtTexCoord2f((float)(tex * sin1[i] + 0.5), (float)(tex * cos1[i] + 0.5));
            rtVertex3f(r * sin1[i], r * cos1[i], 0.0f);
        }
        rtEnd();
    } else {
        finish = loops;
    }

    for (j = 0; j < finish; j++) {
        const float r_low = (float)(outer - delta_radius * ((float)j / loops));
        const float r_high = (float)(outer - delta_radius * ((float)(j + 1) / loops));
        const float tex_low = (float)(r_low / outer / 2);
        const float tex_high = (float)(r_high / outer / 2);
        /* Outside: the outer ring (low) first. */
        const float r_first = outside ? r_low : r_high;
        const float r_second = outside ? r_high : r_low;
        const float tex_first = outside ? tex_low : tex_high;
        const float tex_second = outside ? tex_high : tex_low;
        rtBegin(RT_QUAD_STRIP);
        for (i = 0; i <= slices; i++) {
            if (q->texture)
                rtTexCoord2f((float)(tex_first * sin1[i] + 0.5),
                             (float)(tex_first * cos1[i] + 0.5));
            rtVertex3f(r_first * sin1[i], r_first * cos1[i], 0.0f);
            if (q->texture)
                rtTexCoord2f((float)(tex_second * sin1[i] + 0.5),
                             (float)(tex_second * cos1[i] + 0.5));
            rtVertex3f(r_second * sin1[i], r_second * cos1[i], 0.0f);
        }
        rtEnd();
    }
}

void rtuPartialDisk(RTUquadric *quadric, RTdouble innerRadius, RTdouble outerRadius,
                    RTint slices, RTint loops, RTdouble startAngle, RTdouble sweepAngle)
{
    if (slices >= RTU_QUADRIC_CACHE)
        slices = RTU_QUADRIC_CACHE - 1;
    if (!rtu_quadric_drawable("rtuPartialDisk", quadric, slices >= 2 && loops >= 1 && outerRadius > 0.0 &&
                                           innerRadius >= 0.0 && innerRadius <= outerRadius &&
                                           isfinite(outerRadius) && isfinite(startAngle) &&
                                           isfinite(sweepAngle)))
        return;
    if (sweepAngle < -360.0)
        sweepAngle = 360.0;
    if (sweepAngle > 360.0)
        sweepAngle = 360.0;
    if (sweepAngle < 0) {
        startAngle += sweepAngle;
        sweepAngle = -sweepAngle;
    }
    if (quadric->draw_style == RTU_FILL)
        partial_disk_fill(quadric, innerRadius, outerRadius, slices, loops, startAngle,
                          sweepAngle);
    else
        rtu_partial_disk_wire(quadric, innerRadius, outerRadius, slices, loops, startAngle,
                              sweepAngle);
}

void rtuDisk(RTUquadric *quadric, RTdouble innerRadius, RTdouble outerRadius, RTint slices,
             RTint loops)
{
    rtuPartialDisk(quadric, innerRadius, outerRadius, slices, loops, 0.0, 360.0);
}
