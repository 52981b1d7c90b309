/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_polyhedra.c - rtuSolidTetrahedron, rtuSolidOctahedron,
 * rtuSolidDodecahedron, rtuSolidIcosahedron and their rtuWire variants:
 * the regular solids of GLUT 3
 * (Kilgard 1996, sec. 11), centred at the origin with GLUT's radii
 * (circumradius sqrt(3) for the tetrahedron and the dodecahedron, 1 for the
 * octahedron and the icosahedron) and orientation, one flat normal per
 * face.
 *
 * Rather than face tables, each solid is given by its vertices and the
 * directions of its face normals (the vertices of its dual); a face is the
 * set of vertices farthest along its normal, ordered counter-clockwise
 * about it, so every face faces out and no table can be mistyped.  Faces
 * are emitted as triangles (tetrahedron, octahedron, icosahedron) or
 * triangle fans (the dodecahedron's pentagons, as GLUT draws them), with
 * the unit face normal.
 */
#include "report.h"

#include <rt/rtu.h>

#include <math.h>

/* Largest vertex count of a face (pentagon) and of a solid (dodecahedron). */
#define MAX_FACE 5
#define MAX_VERTICES 20
/* Vertices within this much of the largest dot product lie in the face
 * (coordinates are O(1); distinct planes are O(0.1) apart). */
#define FACE_EPS 1e-6

/* The golden ratio, which places the vertices of the dodecahedron and
 * the icosahedron. */
#define PHI 1.61803398874989484820

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Emits the face of `verts` farthest along `dir`: filled, or (wire) as a
 * line loop through the same vertices, as GLUT's wire solids draw each
 * face with GL_LINE_LOOP. */
static void emit_face(const double (*verts)[3], int n, const double dir[3], int wire)
{
    double best = -INFINITY;
    int face[MAX_FACE];
    double angle[MAX_FACE];
    double u[3], w[3], len, centre[3] = {0.0, 0.0, 0.0};
    int count = 0, i, j;
    for (i = 0; i < n; i++)
        best = fmax(best, dot3(verts[i], dir));
    for (i = 0; i < n && count < MAX_FACE; i++)
        if (dot3(verts[i], dir) > best - FACE_EPS)
            face[count++] = i;
    for (i = 0; i < count; i++)
        for (j = 0; j < 3; j++)
            centre[j] += verts[face[i]][j] / count;
    /* A frame (u, w) in the face plane with u x w along dir. */
    len = sqrt(dot3(dir, dir));
    for (j = 0; j < 3; j++)
        u[j] = verts[face[0]][j] - centre[j];
    w[0] = (dir[1] * u[2] - dir[2] * u[1]) / len;
    w[1] = (dir[2] * u[0] - dir[0] * u[2]) / len;
    w[2] = (dir[0] * u[1] - dir[1] * u[0]) / len;
    for (i = 0; i < count; i++) {
        double d[3];
        for (j = 0; j < 3; j++)
            d[j] = verts[face[i]][j] - centre[j];
        angle[i] = atan2(dot3(d, w), dot3(d, u));
    }
    /* Insertion sort by angle: counter-clockwise seen from outside. */
    for (i = 1; i < count; i++)
        for (j = i; j > 0 && angle[j] < angle[j - 1]; j--) {
            double ta = angle[j];
            int tf = face[j];
            angle[j] = angle[j - 1];
            face[j] = face[j - 1];
            angle[j - 1] = ta;
            face[j - 1] = tf;
        }
    rtBegin(wire ? RT_LINE_LOOP : count == 3 ? RT_TRIANGLES : RT_TRIANGLE_FAN);
    rtNormal3f((float)(dir[0] / len), (float)(dir[1] / len), (float)(dir[2] / len));
    for (i = 0; i < count; i++)
        rtVertex3f((float)verts[face[i]][0], (float)verts[face[i]][1],
                   (float)verts[face[i]][2]);
    rtEnd();
}

static void emit_solid(const double (*verts)[3], int n, const double (*dirs)[3], int faces,
                       int wire)
{
    int f;
    for (f = 0; f < faces; f++)
        emit_face(verts, n, dirs[f], wire);
}

/* The 12 points (0, +-a, +-b), (+-b, 0, +-a), (+-a, +-b, 0), scaled by s. */
static int cyclic_points(double a, double b, double s, double (*out)[3])
{
    int n = 0, c, sa, sb;
    for (c = 0; c < 3; c++)
        for (sa = -1; sa <= 1; sa += 2)
            for (sb = -1; sb <= 1; sb += 2) {
                out[n][c] = 0.0;
                out[n][(c + 1) % 3] = sa * a * s;
                out[n][(c + 2) % 3] = sb * b * s;
                n++;
            }
    return n;
}

/* The 8 points (+-s, +-s, +-s). */
static int cube_corners(double s, double (*out)[3])
{
    int n;
    for (n = 0; n < 8; n++) {
        out[n][0] = (n & 4) ? s : -s;
        out[n][1] = (n & 2) ? s : -s;
        out[n][2] = (n & 1) ? s : -s;
    }
    return 8;
}

static void draw_tetrahedron(int wire)
{
    /* Alternate corners of the cube (+-1)^3: circumradius sqrt(3). */
    static const double verts[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    static const double dirs[4][3] = {{-1, -1, -1}, {-1, 1, 1}, {1, -1, 1}, {1, 1, -1}};
    emit_solid(verts, 4, dirs, 4, wire);
}

static void draw_octahedron(int wire)
{
    static const double verts[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    double dirs[8][3];
    cube_corners(1.0, dirs);
    emit_solid(verts, 6, (const double(*)[3])dirs, 8, wire);
}

static void draw_icosahedron(int wire)
{
    /* GLUT's (0, +-phi, +-1) cyclically, scaled to radius 1; its faces
     * point at the vertices of the dual dodecahedron, (+-1, +-1, +-1) and
     * (0, +-1/phi, +-phi) cyclically. */
    double verts[MAX_VERTICES][3];
    double dirs[20][3];
    int n = cyclic_points(PHI, 1.0, 1.0 / sqrt(1.0 + PHI * PHI), verts);
    int f = cube_corners(1.0, dirs);
    f += cyclic_points(1.0 / PHI, PHI, 1.0, dirs + f);
    emit_solid((const double(*)[3])verts, n, (const double(*)[3])dirs, f, wire);
}

static void draw_dodecahedron(int wire)
{
    /* GLUT's (+-1, +-1, +-1) and (0, +-phi, +-1/phi) cyclically: radius
     * sqrt(3); its faces point at the vertices of the dual icosahedron,
     * (0, +-1, +-phi) cyclically. */
    double verts[MAX_VERTICES][3];
    double dirs[12][3];
    int n = cube_corners(1.0, verts);
    int f;
    n += cyclic_points(PHI, 1.0 / PHI, 1.0, verts + n);
    f = cyclic_points(1.0, PHI, 1.0, dirs);
    emit_solid((const double(*)[3])verts, n, (const double(*)[3])dirs, f, wire);
}

void rtuSolidTetrahedron(void)
{
    draw_tetrahedron(0);
}

void rtuWireTetrahedron(void)
{
    draw_tetrahedron(1);
}

void rtuSolidOctahedron(void)
{
    draw_octahedron(0);
}

void rtuWireOctahedron(void)
{
    draw_octahedron(1);
}

void rtuSolidIcosahedron(void)
{
    draw_icosahedron(0);
}

void rtuWireIcosahedron(void)
{
    draw_icosahedron(1);
}

void rtuSolidDodecahedron(void)
{
    draw_dodecahedron(0);
}

void rtuWireDodecahedron(void)
{
    draw_dodecahedron(1);
}
