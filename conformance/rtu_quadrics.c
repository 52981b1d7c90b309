/* SPDX-License-Identifier: Apache-2.0 */
/*
 * rtu_quadrics.c - conformance: the GLU quadric objects and the GLUT solid
 * shapes of rtu.
 *
 * Pins: the triangle counts of GLU's tessellations (fans at the poles
 * unless texture coordinates are asked for; one quad strip per stack or
 * ring; a fan in the middle of a disk without a hole) and of GLUT's
 * shapes; the documented errors, recorded through the nearest core call
 * (docs/quadrics.md): a NULL quadric or a bad value RT_INVALID_VALUE, a bad
 * enum RT_INVALID_ENUM, each drawing nothing and leaving the quadric as it
 * was; the draw styles RTU_LINE, RTU_POINT and RTU_SILHOUETTE draw (lines
 * and points, no triangles) without error in every recording state.  That the vertices,
 * normals and texture coordinates are GLU's is pinned call for call by
 * conformance/gl_oracle/trace_oracle.c, and the pixels by the oracle.
 *
 * Reference: docs/quadrics.md.
 */
#include "testutil.h"

#include <rt/rtu.h>

#include <math.h>
#include <stddef.h>

#define OBJ 7u

/* Records `draw` into OBJ and returns its triangle count (-1 on error). */
#define TRIANGLES_OF(draw) (rtNewObject(OBJ), (draw), rtEndObject(), tu_object_triangles(OBJ))

static void tessellation(void)
{
    RTUquadric *q = rtuNewQuadric();
    tu_section("GLU tessellation: triangle counts");
    CHECK(q != NULL);
    /* Sphere: two fans of `slices` triangles + (stacks - 2) strips. */
    CHECK_INT(TRIANGLES_OF(rtuSphere(q, 1.0, 8, 4)), 2 * 8 + 2 * 8 * 2);
    CHECK_NO_ERR();
    /* With texture coordinates every stack is a strip (degenerate
     * triangles at the poles included). */
    rtuQuadricTexture(q, RT_TRUE);
    CHECK_INT(TRIANGLES_OF(rtuSphere(q, 1.0, 8, 4)), 4 * 8 * 2);
    rtuQuadricTexture(q, RT_FALSE);
    /* GLU clamps slices to 239. */
    CHECK_INT(TRIANGLES_OF(rtuCylinder(q, 1.0, 0.5, 1.0, 1000, 2)), 239 * 2 * 2);
    CHECK_INT(TRIANGLES_OF(rtuCylinder(q, 1.0, 0.5, 1.0, 5, 3)), 5 * 3 * 2);
    /* Disk with a hole: loops strips; without: a fan and loops - 1 strips. */
    CHECK_INT(TRIANGLES_OF(rtuDisk(q, 0.5, 1.0, 6, 3)), 6 * 3 * 2);
    CHECK_INT(TRIANGLES_OF(rtuDisk(q, 0.0, 1.0, 6, 3)), 6 + 6 * 2 * 2);
    CHECK_INT(TRIANGLES_OF(rtuPartialDisk(q, 0.5, 1.0, 6, 1, 45.0, -90.0)), 6 * 2);
    CHECK_NO_ERR();
    rtuDeleteQuadric(q);
    rtuDeleteQuadric(NULL);
}

static void glut_shapes(void)
{
    tu_section("GLUT solids: triangle counts");
    CHECK_INT(TRIANGLES_OF(rtuSolidCube(1.0)), 12);
    CHECK_INT(TRIANGLES_OF(rtuSolidTetrahedron()), 4);
    CHECK_INT(TRIANGLES_OF(rtuSolidOctahedron()), 8);
    CHECK_INT(TRIANGLES_OF(rtuSolidIcosahedron()), 20);
    CHECK_INT(TRIANGLES_OF(rtuSolidDodecahedron()), 12 * 3);
    CHECK_INT(TRIANGLES_OF(rtuSolidSphere(1.0, 8, 4)), 2 * 8 + 2 * 8 * 2);
    CHECK_INT(TRIANGLES_OF(rtuSolidCone(1.0, 2.0, 8, 3)), 8 * 3 * 2);
    /* GLUT's doughnut: sides + 1 vertex pairs a ring, sides quads. */
    CHECK_INT(TRIANGLES_OF(rtuSolidTorus(0.25, 1.0, 6, 10)), 10 * 6 * 2);
    /* 6 patches x 4 quadrants + 4 x 2 halves, 7 x 7 grid each. */
    CHECK_INT(TRIANGLES_OF(rtuSolidTeapot(1.0)), 32 * 7 * 7 * 2);
    CHECK_NO_ERR();

    tu_section("GLUT solids: bounds");
    {
        RTfloat b[6];
        rtNewObject(OBJ);
        rtuSolidCube(2.0);
        rtEndObject();
        rtGetObjectfv(OBJ, RT_OBJECT_BOUNDS, b);
        CHECK(b[0] == -1.0f && b[1] == -1.0f && b[2] == -1.0f && b[3] == 1.0f && b[4] == 1.0f &&
              b[5] == 1.0f);
        /* The teapot of size s: body radius s, y up, from y = -0.75 s. */
        rtNewObject(OBJ);
        rtuSolidTeapot(2.0);
        rtEndObject();
        rtGetObjectfv(OBJ, RT_OBJECT_BOUNDS, b);
        CHECK_NEAR(b[1], -1.5, 1e-5);
        CHECK_NEAR(b[4], 1.65, 1e-5);
        CHECK_NEAR(b[2], -2.0, 1e-5);
        CHECK_NEAR(b[5], 2.0, 1e-5);
        CHECK_NEAR(b[0], -3.0, 1e-2);
        CHECK_NEAR(b[3], 3.4338, 1e-3); /* the spout's lip */
        /* Radii: tetrahedron and dodecahedron sqrt(3), the others 1. */
        rtNewObject(OBJ);
        rtuSolidTetrahedron();
        rtEndObject();
        rtGetObjectfv(OBJ, RT_OBJECT_BOUNDS, b);
        CHECK_NEAR(b[3], 1.0, 1e-6);
        rtNewObject(OBJ);
        rtuSolidIcosahedron();
        rtEndObject();
        rtGetObjectfv(OBJ, RT_OBJECT_BOUNDS, b);
        CHECK_NEAR(b[4], 0.850650808, 1e-6);
        rtNewObject(OBJ);
        rtuSolidDodecahedron();
        rtEndObject();
        rtGetObjectfv(OBJ, RT_OBJECT_BOUNDS, b);
        CHECK_NEAR(b[5], 1.618034, 1e-6);
        CHECK_NO_ERR();
    }
}

static void errors(void)
{
    RTUquadric *q = rtuNewQuadric();
    const float dummy[3] = {0, 0, 0};
    tu_section("quadric errors");
    tu_capture_errors();

    /* NULL quadric. */
    rtuQuadricNormals(NULL, RTU_FLAT);
    CHECK_ERR(RT_INVALID_VALUE);
    rtuQuadricOrientation(NULL, RTU_INSIDE);
    CHECK_ERR(RT_INVALID_VALUE);
    rtuQuadricTexture(NULL, RT_TRUE);
    CHECK_ERR(RT_INVALID_VALUE);
    rtuQuadricDrawStyle(NULL, RTU_FILL);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuSphere(NULL, 1.0, 8, 4)), 0);
    CHECK_ERR(RT_INVALID_VALUE);

    /* Bad enums: recorded against the rtu function; the option is unchanged
     * (the draw style stays RTU_FILL, so drawing works). */
    tu_reset_captured();
    rtuQuadricNormals(q, RTU_FILL);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtuQuadricNormals");
    rtuQuadricOrientation(q, RTU_SMOOTH);
    CHECK_ERR(RT_INVALID_ENUM);
    rtuQuadricDrawStyle(q, RTU_OUTSIDE);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_INT(TRIANGLES_OF(rtuDisk(q, 0.5, 1.0, 4, 1)), 8);
    CHECK_NO_ERR();

    /* Bad values: recorded against the rtu function; nothing drawn. */
    tu_reset_captured();
    CHECK_INT(TRIANGLES_OF(rtuSphere(q, -1.0, 8, 4)), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtuSphere");
    CHECK_INT(TRIANGLES_OF(rtuSphere(q, 1.0, 1, 4)), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuSphere(q, 1.0, 8, 0)), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuSphere(q, NAN, 8, 4)), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuCylinder(q, 1.0, 1.0, 0.0, 8, 1)), 0); /* no side */
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuCylinder(q, -1.0, 1.0, 1.0, 8, 1)), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuCylinder(q, 1.0, 1.0, INFINITY, 8, 1)), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuDisk(q, 2.0, 1.0, 8, 1)), 0); /* inner > outer */
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuDisk(q, 0.0, 0.0, 8, 1)), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuPartialDisk(q, 0.0, 1.0, 8, 0, 0.0, 90.0)), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuPartialDisk(q, 0.0, 1.0, 8, 1, NAN, 90.0)), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuSolidCube(-1.0)), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuSolidTorus(0.5, 1.0, 0, 8)), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtuSolidTorus");
    CHECK_INT(TRIANGLES_OF(rtuSolidTeapot(NAN)), 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_INT(TRIANGLES_OF(rtuSolidSphere(1.0, 1, 1)), 0);
    CHECK_ERR(RT_INVALID_VALUE);

    tu_section("draw styles drawn as lines and points");
    {
        /* RTU_LINE, RTU_POINT and RTU_SILHOUETTE draw lines and points
         * (their calls are pinned against libGLU by the trace oracle):
         * no error in any recording state and no triangles. */
        const RTenum styles[3] = {RTU_LINE, RTU_POINT, RTU_SILHOUETTE};
        int s;
        for (s = 0; s < 3; s++) {
            rtuQuadricDrawStyle(q, styles[s]);
            CHECK_NO_ERR();
            /* In an object. */
            CHECK_INT(TRIANGLES_OF(rtuSphere(q, 1.0, 8, 4)), 0);
            CHECK_NO_ERR();
            CHECK_INT(TRIANGLES_OF(rtuPartialDisk(q, 0.5, 1.0, 8, 2, 10.0, 90.0)), 0);
            CHECK_NO_ERR();
            /* In an object with an enabled vertex array. */
            rtEnableClientState(RT_VERTEX_ARRAY);
            rtVertexPointer(3, RT_FLOAT, 0, dummy);
            CHECK_INT(TRIANGLES_OF(rtuCylinder(q, 1.0, 1.0, 1.0, 8, 1)), 0);
            CHECK_NO_ERR();
            rtDisableClientState(RT_VERTEX_ARRAY);
            /* Outside objects (immediate mode). */
            rtBeginFrame();
            rtuDisk(q, 0.0, 1.0, 8, 1);
            CHECK_NO_ERR();
            rtBeginFrame();
            /* Bad values are still refused first. */
            rtuSphere(q, -1.0, 8, 4);
            CHECK_ERR(RT_INVALID_VALUE);
        }
        rtuQuadricDrawStyle(q, RTU_FILL);
        CHECK_INT(TRIANGLES_OF(rtuSphere(q, 1.0, 8, 4)), 48);
        CHECK_NO_ERR();
    }

    tu_section("quadrics outside objects and inside rtBegin");
    rtBeginFrame();
    rtuSphere(q, 1.0, 8, 4);
    CHECK_NO_ERR(); /* immediate mode outside objects (docs/lists.md) */
    rtBeginFrame();
    /* As GLU's and GLUT's calls in GL: the shape's own rtBegin fails, its
     * vertices join the open primitive and its rtEnd closes it. */
    {
        RTuint scratch = TU_SCRATCH_OBJECT;
        tu_begin_scratch(RT_TRIANGLES);
        rtuSolidCube(1.0);
        CHECK_ERR(RT_INVALID_OPERATION);
        rtEnd();
        CHECK_ERR(RT_INVALID_OPERATION); /* already closed */
        rtEndObject();
        CHECK_NO_ERR();
        /* The first face's 4 vertices made one triangle of the open
         * RT_TRIANGLES block; the other 5 faces were drawn as quads. */
        CHECK_INT(tu_object_triangles(scratch), 1 + 5 * 2);
        rtDeleteObjects(1, &scratch);
    }
    rtuDeleteQuadric(q);
}

static void no_context(void)
{
    RTUquadric *q = rtuNewQuadric();
    tu_section("no current context");
    /* Options are client state: set without a context, errors dropped. */
    rtuQuadricNormals(q, RTU_FLAT);
    rtuQuadricNormals(q, 0);
    rtuSphere(q, 1.0, 8, 4);
    rtuSphere(q, -1.0, 8, 4);
    rtuSolidTeapot(1.0);
    CHECK(rtGetCurrentContext() == NULL);
    rtuDeleteQuadric(q);
}

int main(void)
{
    RTcontext ctx = tu_make_context(NULL);
    tessellation();
    glut_shapes();
    errors();
    rtMakeCurrent(NULL);
    no_context();
    rtMakeCurrent(ctx);
    tu_destroy_context(ctx);
    return test_summary("rtu_quadrics");
}
