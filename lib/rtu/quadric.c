/* SPDX-License-Identifier: Apache-2.0 */
/*
 * quadric.c - the quadric object: rtuNewQuadric, rtuDeleteQuadric and the
 * four option setters (gluNewQuadric ... gluQuadricDrawStyle).
 *
 * A quadric holds drawing options only, no context state, exactly as in
 * GLU.  GLU reports a bad enum through the quadric's error callback and
 * changes nothing; rtu records RT_INVALID_ENUM in the current context
 * (report.h) and changes nothing.  Setting options needs no context.
 */
#include "quadric_internal.h"
#include "report.h"

#include <stdlib.h>

void rtu_quadric_defaults(struct rtu_quadric *q)
{
    q->normals = RTU_SMOOTH;
    q->orientation = RTU_OUTSIDE;
    q->draw_style = RTU_FILL;
    q->texture = RT_FALSE;
}

int rtu_quadric_drawable(const char *caller, const struct rtu_quadric *q, int values_ok)
{
    if (!q || !values_ok) {
        rtu_record_error(RT_INVALID_VALUE, caller,
                         q ? "a size, count or radius is out of range" : "quadric is NULL");
        return 0;
    }
    return 1;
}

RTUquadric *rtuNewQuadric(void)
{
    struct rtu_quadric *q = malloc(sizeof *q);
    if (q)
        rtu_quadric_defaults(q);
    return q;
}

void rtuDeleteQuadric(RTUquadric *quadric)
{
    free(quadric);
}

void rtuQuadricNormals(RTUquadric *quadric, RTenum normals)
{
    if (!quadric) {
        rtu_record_error(RT_INVALID_VALUE, "rtuQuadricNormals", "quadric is NULL");
        return;
    }
    if (normals != RTU_SMOOTH && normals != RTU_FLAT && normals != RTU_NONE) {
        rtu_record_error(RT_INVALID_ENUM, "rtuQuadricNormals", NULL);
        return;
    }
    quadric->normals = normals;
}

void rtuQuadricOrientation(RTUquadric *quadric, RTenum orientation)
{
    if (!quadric) {
        rtu_record_error(RT_INVALID_VALUE, "rtuQuadricOrientation", "quadric is NULL");
        return;
    }
    if (orientation != RTU_OUTSIDE && orientation != RTU_INSIDE) {
        rtu_record_error(RT_INVALID_ENUM, "rtuQuadricOrientation", NULL);
        return;
    }
    quadric->orientation = orientation;
}

void rtuQuadricTexture(RTUquadric *quadric, RTboolean textureCoords)
{
    if (!quadric) {
        rtu_record_error(RT_INVALID_VALUE, "rtuQuadricTexture", "quadric is NULL");
        return;
    }
    /* GLU stores the GLboolean as given; any non-zero value means yes. */
    quadric->texture = textureCoords ? RT_TRUE : RT_FALSE;
}

void rtuQuadricDrawStyle(RTUquadric *quadric, RTenum drawStyle)
{
    if (!quadric) {
        rtu_record_error(RT_INVALID_VALUE, "rtuQuadricDrawStyle", "quadric is NULL");
        return;
    }
    if (drawStyle != RTU_FILL && drawStyle != RTU_LINE && drawStyle != RTU_POINT &&
        drawStyle != RTU_SILHOUETTE) {
        rtu_record_error(RT_INVALID_ENUM, "rtuQuadricDrawStyle", NULL);
        return;
    }
    quadric->draw_style = drawStyle;
}
