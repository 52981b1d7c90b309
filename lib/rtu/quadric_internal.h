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
    RTenum draw_style;  /* RTU_FILL (others recorded, not drawable yet) */
    RTboolean texture;  /* emit texture coordinates */
};

/* The drawing options of a fresh quadric (GLU's defaults). */
void rtu_quadric_defaults(struct rtu_quadric *q);

/*
 * Checks common to every quadric: q non-NULL (else RT_INVALID_VALUE) and a
 * draw style that can be drawn (RTU_FILL; else RT_INVALID_OPERATION: lines
 * and points are not in the core yet).  `values_ok` is the caller's own
 * argument check, reported as RT_INVALID_VALUE before the draw style, in
 * GLU's order.  Returns 1 when drawing may go on.
 */
int rtu_quadric_drawable(const char *caller, const struct rtu_quadric *q, int values_ok);

/* The drawing functions, after the public entry points' checks. */
void rtu_sphere_fill(const struct rtu_quadric *q, double radius, int slices, int stacks);
void rtu_cylinder_fill(const struct rtu_quadric *q, double base_radius, double top_radius,
                       double height, int slices, int stacks);

#endif /* RTU_QUADRIC_INTERNAL_H */
