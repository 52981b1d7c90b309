/* SPDX-License-Identifier: Apache-2.0 */
/*
 * quadric_internal.h - the quadric object shared by the quadric files and
 * the GLUT shapes built on them.
 *
 * Precision.  GLU's quadrics (Mesa's libGLU, from the SGI sample
 * implementation) compute their sine/cosine tables and vertices in single
 * precision from double-precision arguments.  Ours round at the same
 * places, so the vertices we emit are the floats GLU passes to
 * glVertex3f, and the triangles cover the pixels GLU's cover.
 */
#ifndef RTU_QUADRIC_INTERNAL_H
#define RTU_QUADRIC_INTERNAL_H

#include <rt/rt.h>
#include <rt/rtu.h>

/* GLU clamps slices (and a sphere's stacks) to one less than the size of
 * its angle tables, 240 in the SGI implementation (a non-power of two "to
 * avoid cache thrashing"); the clamp changes the tessellation, so we keep
 * it. */
#define RTU_QUADRIC_CACHE 240

/* pi as GLU spells it (a double constant; angles are formed in double and
 * stored as float). */
#define RTU_PI 3.14159265358979323846

struct rtu_quadric {
    RTenum normals;     /* RTU_SMOOTH, RTU_FLAT or RTU_NONE */
    RTenum orientation; /* RTU_OUTSIDE or RTU_INSIDE */
    RTenum draw_style;  /* RTU_FILL, RTU_LINE, RTU_POINT or RTU_SILHOUETTE */
    RTboolean texture;  /* emit texture coordinates */
};

/* The drawing options of a fresh quadric (GLU's defaults). */
void rtu_quadric_defaults(struct rtu_quadric *q);

/*
 * Checks common to every quadric: q non-NULL and the caller's own argument
 * check `values_ok` (else RT_INVALID_VALUE).  Returns 1 when drawing may
 * go on.
 */
int rtu_quadric_drawable(const char *caller, const struct rtu_quadric *q, int values_ok);

/*
 * The angle tables of a sphere, as GLU computes them (quadric_sphere.c).
 * a: around the axis (slices); b: from pole to pole (stacks).  1:
 * positions (1b scaled by the radius), 2: smooth normals (2b carries the
 * orientation's sign; 2a is 1a), 3: flat normals, half a slice / stack
 * back (3b signed).  Entry `slices` of the a tables repeats entry 0.
 */
struct rtu_sphere_tables {
    float sin1a[RTU_QUADRIC_CACHE], cos1a[RTU_QUADRIC_CACHE];
    float sin3a[RTU_QUADRIC_CACHE], cos3a[RTU_QUADRIC_CACHE];
    float sin1b[RTU_QUADRIC_CACHE], cos1b[RTU_QUADRIC_CACHE];
    float sin2b[RTU_QUADRIC_CACHE], cos2b[RTU_QUADRIC_CACHE];
    float sin3b[RTU_QUADRIC_CACHE], cos3b[RTU_QUADRIC_CACHE];
};
void rtu_sphere_tables(struct rtu_sphere_tables *t, const struct rtu_quadric *q, double radius,
                       int slices, int stacks);

/*
 * The angle tables of a cylinder (quadric_cylinder.c): 1 positions, 2
 * smooth normals' x and y (scaled by the side's slope and signed by the
 * orientation), 3 flat ones half a slice back; z_normal is every normal's
 * z.  Entry `slices` repeats entry 0.
 */
struct rtu_cylinder_tables {
    float sin1[RTU_QUADRIC_CACHE], cos1[RTU_QUADRIC_CACHE];
    float sin2[RTU_QUADRIC_CACHE], cos2[RTU_QUADRIC_CACHE];
    float sin3[RTU_QUADRIC_CACHE], cos3[RTU_QUADRIC_CACHE];
    float delta_radius, z_normal;
};
void rtu_cylinder_tables(struct rtu_cylinder_tables *t, const struct rtu_quadric *q,
                         double base_radius, double top_radius, double height, int slices);

/* The angle table of a (partial) disk (quadric_disk.c), slices + 1
 * entries; the last repeats the first for a full turn. */
struct rtu_disk_tables {
    float sin1[RTU_QUADRIC_CACHE], cos1[RTU_QUADRIC_CACHE];
};
void rtu_disk_tables(struct rtu_disk_tables *t, int slices, double start_angle,
                     double sweep_angle);

/* The drawing functions, after the public entry points' checks. */
void rtu_sphere_fill(const struct rtu_quadric *q, double radius, int slices, int stacks);
void rtu_cylinder_fill(const struct rtu_quadric *q, double base_radius, double top_radius,
                       double height, int slices, int stacks);

/* RTU_POINT, RTU_LINE and RTU_SILHOUETTE (quadric_wire.c). */
void rtu_sphere_wire(const struct rtu_quadric *q, double radius, int slices, int stacks);
void rtu_cylinder_wire(const struct rtu_quadric *q, double base_radius, double top_radius,
                       double height, int slices, int stacks);
void rtu_partial_disk_wire(const struct rtu_quadric *q, double inner, double outer, int slices,
                           int loops, double start_angle, double sweep_angle);

#endif /* RTU_QUADRIC_INTERNAL_H */
