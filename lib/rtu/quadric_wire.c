/* SPDX-License-Identifier: Apache-2.0 */
/*
 * quadric_wire.c - the quadrics in the draw styles RTU_POINT, RTU_LINE and
 * RTU_SILHOUETTE (gluQuadricDrawStyle's GLU_POINT, GLU_LINE,
 * GLU_SILHOUETTE).
 *
 * GLU 1.3 draws these styles from the vertices of the filled tessellation
 * (the same angle tables, rounded at the same places: quadric_internal.h),
 * as Mesa's libGLU emits them:
 *
 *  - RTU_POINT: one RT_POINTS block with every vertex of the mesh, slice
 *    by slice (a sphere: stack by stack), poles and centres repeated once
 *    per slice.
 *  - RTU_LINE: the mesh's edges as RT_LINE_STRIPs, no triangulation
 *    diagonals and no pole fans: a sphere's parallels (stacks 1 ...
 *    stacks - 1) then its meridians from +z to -z; a cylinder's inner
 *    rings, its two end rings, then its lines along the side; a disk's
 *    rings from the outside in, then its spokes.
 *  - RTU_SILHOUETTE: the outline only.  A sphere has no edge that is not
 *    shared, so it draws as RTU_LINE; a cylinder draws its end rings and
 *    its side lines (without the inner rings); a disk its outer and inner
 *    rings and, for a sweep below 360 degrees, the two straight edges.
 *
 * Orientation changes only the normals' sign here (no winding to keep).
 * The normals are the fill's: smooth ones at the vertex, flat ones mixing
 * the facet-centre table with the smooth one as GLU does (a line has no
 * facet), texture coordinates as in the fill.  Like the fill, every
 * normal is given where GLU gives it, so the current normal at each
 * vertex is GLU's.
 *
 * Two cases GLU leaves undefined: with RTU_FLAT normals, libGLU draws
 * points and a sphere's or cylinder's silhouette from angle tables it
 * fills only for other styles (it reads uninitialised memory; the trace
 * oracle sees NaNs).  We give points the smooth normals (the flat ones
 * of a point's facets would be four different ones) and a silhouette the
 * normals RTU_LINE gives the same edges, which is what GLU's code reads
 * the tables for.
 */
#include "quadric_internal.h"

#include <math.h>

void rtu_sphere_wire(const struct rtu_quadric *q, double radius, int slices, int stacks)
{
    struct rtu_sphere_tables t;
    const int normals = q->normals != RTU_NONE;
    const int flat = q->normals == RTU_FLAT;
    int i, j;

    rtu_sphere_tables(&t, q, radius, slices, stacks);

    if (q->draw_style == RTU_POINT) {
        rtBegin(RT_POINTS);
        for (j = 0; j <= stacks; j++) {
            for (i = 0; i < slices; i++) {
                /* A point has no facet: flat normals are the smooth ones. */
                if (normals)
                    rtNormal3f(t.sin1a[i] * t.sin2b[j], t.cos1a[i] * t.sin2b[j], t.cos2b[j]);
                if (q->texture)
                    rtTexCoord2f(1 - (float)i / slices, 1 - (float)j / stacks);
                rtVertex3f(t.sin1b[j] * t.sin1a[i], t.sin1b[j] * t.cos1a[i], t.cos1b[j]);
            }
        }
        rtEnd();
        return;
    }

    /* RTU_LINE and RTU_SILHOUETTE: the parallels, without the poles. */
    for (j = 1; j < stacks; j++) {
        rtBegin(RT_LINE_STRIP);
        for (i = 0; i <= slices; i++) {
            if (flat)
                rtNormal3f(t.sin3a[i] * t.sin2b[j], t.cos3a[i] * t.sin2b[j], t.cos2b[j]);
            else if (normals)
                rtNormal3f(t.sin1a[i] * t.sin2b[j], t.cos1a[i] * t.sin2b[j], t.cos2b[j]);
            if (q->texture)
                rtTexCoord2f(1 - (float)i / slices, 1 - (float)j / stacks);
            rtVertex3f(t.sin1b[j] * t.sin1a[i], t.sin1b[j] * t.cos1a[i], t.cos1b[j]);
        }
        rtEnd();
    }
    /* The meridians, pole to pole. */
    for (i = 0; i < slices; i++) {
        rtBegin(RT_LINE_STRIP);
        for (j = 0; j <= stacks; j++) {
            if (flat)
                rtNormal3f(t.sin1a[i] * t.sin3b[j], t.cos1a[i] * t.sin3b[j], t.cos3b[j]);
            else if (normals)
                rtNormal3f(t.sin1a[i] * t.sin2b[j], t.cos1a[i] * t.sin2b[j], t.cos2b[j]);
            if (q->texture)
                rtTexCoord2f(1 - (float)i / slices, 1 - (float)j / stacks);
            rtVertex3f(t.sin1a[i] * t.sin1b[j], t.cos1a[i] * t.sin1b[j], t.cos1b[j]);
        }
        rtEnd();
    }
}

/* One ring of a cylinder at stack j, as a line strip. */
static void cylinder_ring(const struct rtu_quadric *q, const struct rtu_cylinder_tables *t,
                          double base_radius, double height, int slices, int stacks, int j)
{
    const float z = (float)(j * height / stacks);
    const float r = (float)(base_radius - t->delta_radius * ((float)j / stacks));
    int i;
    rtBegin(RT_LINE_STRIP);
    for (i = 0; i <= slices; i++) {
        if (q->normals == RTU_FLAT)
            rtNormal3f(t->sin3[i], t->cos3[i], t->z_normal);
        else if (q->normals == RTU_SMOOTH)
            rtNormal3f(t->sin2[i], t->cos2[i], t->z_normal);
        if (q->texture)
            rtTexCoord2f(1 - (float)i / slices, (float)j / stacks);
        rtVertex3f(r * t->sin1[i], r * t->cos1[i], z);
    }
    rtEnd();
}

/* The vertices of slice i of a cylinder from z = 0 to z = height. */
static void cylinder_slice(const struct rtu_quadric *q, const struct rtu_cylinder_tables *t,
                           double base_radius, double height, int slices, int stacks, int i)
{
    int j;
    for (j = 0; j <= stacks; j++) {
        const float z = (float)(j * height / stacks);
        const float r = (float)(base_radius - t->delta_radius * ((float)j / stacks));
        if (q->texture)
            rtTexCoord2f(1 - (float)i / slices, (float)j / stacks);
        rtVertex3f(r * t->sin1[i], r * t->cos1[i], z);
    }
}

void rtu_cylinder_wire(const struct rtu_quadric *q, double base_radius, double top_radius,
                       double height, int slices, int stacks)
{
    struct rtu_cylinder_tables t;
    const int normals = q->normals != RTU_NONE;
    int i, j;

    rtu_cylinder_tables(&t, q, base_radius, top_radius, height, slices);

    if (q->draw_style == RTU_POINT) {
        rtBegin(RT_POINTS);
        for (i = 0; i < slices; i++) {
            if (normals)
                rtNormal3f(t.sin2[i], t.cos2[i], t.z_normal);
            cylinder_slice(q, &t, base_radius, height, slices, stacks, i);
        }
        rtEnd();
        return;
    }

    if (q->draw_style == RTU_LINE)
        for (j = 1; j < stacks; j++)
            cylinder_ring(q, &t, base_radius, height, slices, stacks, j);
    /* Both: the two end rings, then the lines along the side, each with
     * one normal given before the strip.  libGLU gives these lines the
     * smooth normal's x and y with z = 0 (the cone's slope left out); we
     * keep that, so that a lit wireframe shades as GLU's does. */
    cylinder_ring(q, &t, base_radius, height, slices, stacks, 0);
    cylinder_ring(q, &t, base_radius, height, slices, stacks, stacks);
    for (i = 0; i < slices; i++) {
        if (normals)
            rtNormal3f(t.sin2[i], t.cos2[i], 0.0f);
        rtBegin(RT_LINE_STRIP);
        cylinder_slice(q, &t, base_radius, height, slices, stacks, i);
        rtEnd();
    }
}

/* Ring j (0 the outer one, loops the inner one) of a disk. */
static void disk_ring(const struct rtu_quadric *q, const struct rtu_disk_tables *t, double outer,
                      float delta_radius, int slices, int loops, int j)
{
    const float r = (float)(outer - delta_radius * ((float)j / loops));
    const float tex = (float)(r / outer / 2);
    int i;
    rtBegin(RT_LINE_STRIP);
    for (i = 0; i <= slices; i++) {
        if (q->texture)
            rtTexCoord2f((float)(tex * t->sin1[i] + 0.5), (float)(tex * t->cos1[i] + 0.5));
        rtVertex3f(r * t->sin1[i], r * t->cos1[i], 0.0f);
    }
    rtEnd();
}

/* The vertices of spoke i of a disk, from the outer ring inwards. */
static void disk_spoke(const struct rtu_quadric *q, const struct rtu_disk_tables *t, double outer,
                       float delta_radius, int loops, int i)
{
    int j;
    for (j = 0; j <= loops; j++) {
        const float r = (float)(outer - delta_radius * ((float)j / loops));
        if (q->texture) {
            const float tex = (float)(r / outer / 2);
            rtTexCoord2f((float)(tex * t->sin1[i] + 0.5), (float)(tex * t->cos1[i] + 0.5));
        }
        rtVertex3f(r * t->sin1[i], r * t->cos1[i], 0.0f);
    }
}

void rtu_partial_disk_wire(const struct rtu_quadric *q, double inner, double outer, int slices,
                           int loops, double start_angle, double sweep_angle)
{
    struct rtu_disk_tables t;
    const float delta_radius = (float)(outer - inner);
    /* A full turn's last slice is its first: its spoke is not repeated. */
    const int spokes = sweep_angle == 360.0 ? slices : slices + 1;
    int i, j;

    rtu_disk_tables(&t, slices, start_angle, sweep_angle);
    if (q->normals != RTU_NONE)
        rtNormal3f(0.0f, 0.0f, q->orientation == RTU_OUTSIDE ? 1.0f : -1.0f);

    switch (q->draw_style) {
    case RTU_POINT:
        rtBegin(RT_POINTS);
        for (i = 0; i < spokes; i++)
            disk_spoke(q, &t, outer, delta_radius, loops, i);
        rtEnd();
        break;
    case RTU_LINE:
        if (inner == outer) {
            /* No area: the one circle, texture coordinates on the unit
             * circle's disk. */
            rtBegin(RT_LINE_STRIP);
            for (i = 0; i <= slices; i++) {
                if (q->texture)
                    rtTexCoord2f((float)(t.sin1[i] / 2 + 0.5), (float)(t.cos1[i] / 2 + 0.5));
                rtVertex3f((float)(inner * t.sin1[i]), (float)(inner * t.cos1[i]), 0.0f);
            }
            rtEnd();
            break;
        }
        for (j = 0; j <= loops; j++)
            disk_ring(q, &t, outer, delta_radius, slices, loops, j);
        for (i = 0; i < spokes; i++) {
            rtBegin(RT_LINE_STRIP);
            disk_spoke(q, &t, outer, delta_radius, loops, i);
            rtEnd();
        }
        break;
    default: /* RTU_SILHOUETTE */
        if (sweep_angle < 360.0) {
            /* The two straight edges of a partial disk. */
            for (i = 0; i <= slices; i += slices) {
                rtBegin(RT_LINE_STRIP);
                disk_spoke(q, &t, outer, delta_radius, loops, i);
                rtEnd();
            }
        }
        disk_ring(q, &t, outer, delta_radius, slices, loops, 0);
        if (inner != outer)
            disk_ring(q, &t, outer, delta_radius, slices, loops, loops);
        break;
    }
}
