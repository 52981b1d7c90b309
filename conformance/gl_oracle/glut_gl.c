/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_gl.c - the GL side of the oracle's GLUT shapes: GLUT 3.7's solids
 * as GLUT draws them, with OpenGL 1.x and Mesa's libGLU.
 *
 * Why not freeglut itself: the installed freeglut (3.x) draws its shapes
 * through the current GLUT window, which needs glutInit, an X display and
 * a window; the oracle renders off-screen with OSMesa.  So the shapes are
 * drawn here the way GLUT 3.7 draws them (Kilgard 1996, sec. 11), through
 * independent paths from rtu's:
 *   - sphere and cone: Mesa's gluSphere / gluCylinder (smooth, filled);
 *   - teapot: Mesa's evaluators (glMap2f, glMapGrid2f, glEvalMesh2 with
 *     GL_AUTO_NORMAL) on the same Newell patches, placed with glRotatef,
 *     glScalef and glTranslatef inside the list;
 *   - cube and torus: GLUT's loops in GL calls;
 *   - the regular solids: every triangle of vertices whose plane has all
 *     other vertices on one side (a brute-force convex hull), so no face
 *     table is shared with rtu's dual-direction construction.
 */
#include "glut_gl.h"

#include <GL/gl.h>
#include <GL/glu.h>

#include <math.h>

#include "rtu/teapot_data.h"

#define ORACLE_PI 3.14159265358979323846

void oracle_glutSolidSphere(double radius, int slices, int stacks)
{
    GLUquadric *q = gluNewQuadric();
    gluQuadricDrawStyle(q, GLU_FILL);
    gluQuadricNormals(q, GLU_SMOOTH);
    gluSphere(q, radius, slices, stacks);
    gluDeleteQuadric(q);
}

void oracle_glutSolidCone(double base, double height, int slices, int stacks)
{
    GLUquadric *q = gluNewQuadric();
    gluQuadricDrawStyle(q, GLU_FILL);
    gluQuadricNormals(q, GLU_SMOOTH);
    gluCylinder(q, base, 0.0, height, slices, stacks);
    gluDeleteQuadric(q);
}

void oracle_glutSolidCube(double size)
{
    const GLfloat h = (GLfloat)(size / 2);
    static const GLfloat n[6][3] = {{-1, 0, 0}, {0, 1, 0}, {1, 0, 0},
                                    {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    /* Corners as (x, y, z) sign triples, each face outward. */
    static const int f[6][4][3] = {
        {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}},
        {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}},
        {{1, 1, -1}, {1, 1, 1}, {1, -1, 1}, {1, -1, -1}},
        {{1, -1, -1}, {1, -1, 1}, {-1, -1, 1}, {-1, -1, -1}},
        {{1, -1, 1}, {1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}},
        {{1, 1, -1}, {1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}}};
    int i, k;
    for (i = 5; i >= 0; i--) {
        glBegin(GL_QUADS);
        glNormal3fv(n[i]);
        for (k = 0; k < 4; k++)
            glVertex3f(f[i][k][0] * h, f[i][k][1] * h, f[i][k][2] * h);
        glEnd();
    }
}

void oracle_glutSolidTorus(double inner_radius, double outer_radius, int sides, int rings)
{
    const double ring_step = 2.0 * ORACLE_PI / rings;
    const double side_step = 2.0 * ORACLE_PI / sides;
    int i, j;
    for (i = 0; i < rings; i++) {
        /* GLUT's rings run from theta = 0 in steps of -ring_step about z
         * (y = -sin); i counts them the other way round here. */
        const double t0 = i * ring_step;
        const double t1 = (i + 1) * ring_step;
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= sides; j++) {
            const double phi = (j + 1) * side_step;
            const double d = outer_radius + inner_radius * cos(phi);
            glNormal3d(cos(t1) * cos(phi), -sin(t1) * cos(phi), sin(phi));
            glVertex3d(cos(t1) * d, -sin(t1) * d, inner_radius * sin(phi));
            glNormal3d(cos(t0) * cos(phi), -sin(t0) * cos(phi), sin(phi));
            glVertex3d(cos(t0) * d, -sin(t0) * d, inner_radius * sin(phi));
        }
        glEnd();
    }
}

void oracle_glutSolidTeapot(double size)
{
    static const GLfloat tex[2][2][2] = {{{0, 0}, {1, 0}}, {{0, 1}, {1, 1}}};
    GLfloat p[4][4][3], q[4][4][3], r[4][4][3], s[4][4][3];
    int i, j, k, l;
    glPushAttrib(GL_ENABLE_BIT | GL_EVAL_BIT);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_NORMALIZE);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_MAP2_TEXTURE_COORD_2);
    glPushMatrix();
    glRotatef(270.0f, 1.0f, 0.0f, 0.0f);
    glScalef((GLfloat)(0.5 * size), (GLfloat)(0.5 * size), (GLfloat)(0.5 * size));
    glTranslatef(0.0f, 0.0f, -1.5f);
    for (i = 0; i < RTU_TEAPOT_PATCHES; i++) {
        for (j = 0; j < 4; j++)
            for (k = 0; k < 4; k++)
                for (l = 0; l < 3; l++) {
                    const float *a = rtu_teapot_points[rtu_teapot_patches[i][j * 4 + k]];
                    const float *b = rtu_teapot_points[rtu_teapot_patches[i][j * 4 + 3 - k]];
                    p[j][k][l] = a[l];
                    q[j][k][l] = l == 1 ? -b[l] : b[l];
                    r[j][k][l] = l == 0 ? -b[l] : b[l];
                    s[j][k][l] = l < 2 ? -a[l] : a[l];
                }
        glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 2, 2, 0, 1, 4, 2, &tex[0][0][0]);
        glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &p[0][0][0]);
        glMapGrid2f(7, 0.0f, 1.0f, 7, 0.0f, 1.0f);
        glEvalMesh2(GL_FILL, 0, 7, 0, 7);
        glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &q[0][0][0]);
        glEvalMesh2(GL_FILL, 0, 7, 0, 7);
        if (i < RTU_TEAPOT_FOUR_FOLD) {
            glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &r[0][0][0]);
            glEvalMesh2(GL_FILL, 0, 7, 0, 7);
            glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &s[0][0][0]);
            glEvalMesh2(GL_FILL, 0, 7, 0, 7);
        }
    }
    glPopMatrix();
    glPopAttrib();
}

/* Draws every hull triangle of the n points: triangles whose plane has no
 * point strictly outside.  Faces with more than three vertices are drawn
 * as all their overlapping triangles: the same pixels. */
static void draw_hull(const double (*v)[3], int n)
{
    int a, b, c, m;
    glBegin(GL_TRIANGLES);
    for (a = 0; a < n; a++)
        for (b = a + 1; b < n; b++)
            for (c = b + 1; c < n; c++) {
                double e1[3], e2[3], nn[3];
                int above = 0, below = 0;
                for (m = 0; m < 3; m++) {
                    e1[m] = v[b][m] - v[a][m];
                    e2[m] = v[c][m] - v[a][m];
                }
                nn[0] = e1[1] * e2[2] - e1[2] * e2[1];
                nn[1] = e1[2] * e2[0] - e1[0] * e2[2];
                nn[2] = e1[0] * e2[1] - e1[1] * e2[0];
                for (m = 0; m < n; m++) {
                    double d = nn[0] * (v[m][0] - v[a][0]) + nn[1] * (v[m][1] - v[a][1]) +
                               nn[2] * (v[m][2] - v[a][2]);
                    above += d > 1e-9;
                    below += d < -1e-9;
                }
                if (above && below)
                    continue;
                glNormal3d(nn[0], nn[1], nn[2]);
                glVertex3dv(v[a]);
                glVertex3dv(v[b]);
                glVertex3dv(v[c]);
            }
    glEnd();
}

void oracle_glutSolidTetrahedron(void)
{
    static const double v[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    draw_hull(v, 4);
}

void oracle_glutSolidOctahedron(void)
{
    static const double v[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    draw_hull(v, 6);
}

void oracle_glutSolidIcosahedron(void)
{
    /* GLUT 3.7's table: X = .525731112119133606, Z = .850650808352039932. */
    const double X = .525731112119133606, Z = .850650808352039932;
    const double v[12][3] = {{-X, 0, Z}, {X, 0, Z},  {-X, 0, -Z}, {X, 0, -Z},
                             {0, Z, X},  {0, Z, -X}, {0, -Z, X},  {0, -Z, -X},
                             {Z, X, 0},  {-Z, X, 0}, {Z, -X, 0},  {-Z, -X, 0}};
    draw_hull(v, 12);
}

void oracle_glutSolidDodecahedron(void)
{
    /* GLUT 3.7's initDodecahedron: alpha = sqrt(2 / (3 + sqrt(5))),
     * beta = 1 + sqrt(6 / (3 + sqrt(5)) - 2 + 2 sqrt(2 / (3 + sqrt(5)))). */
    const double al = sqrt(2.0 / (3.0 + sqrt(5.0)));
    const double be = 1.0 + sqrt(6.0 / (3.0 + sqrt(5.0)) - 2.0 + 2.0 * sqrt(2.0 / (3.0 + sqrt(5.0))));
    const double v[20][3] = {{-al, 0, be}, {al, 0, be},  {-1, -1, -1}, {-1, -1, 1}, {-1, 1, -1},
                             {-1, 1, 1},   {1, -1, -1},  {1, -1, 1},   {1, 1, -1},  {1, 1, 1},
                             {be, al, 0},  {be, -al, 0}, {-be, al, 0}, {-be, -al, 0},
                             {-al, 0, -be}, {al, 0, -be}, {0, be, al}, {0, be, -al},
                             {0, -be, al}, {0, -be, -al}};
    draw_hull(v, 20);
}
