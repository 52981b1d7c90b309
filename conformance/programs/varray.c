/* SPDX-License-Identifier: Apache-2.0 */
/*
 * varray.c - a GL 1.x vertex-array program: a torus knot-like tube and a
 * floor in vertex arrays, lit by two lights, in linear fog, cut by a user
 * clip plane; the whole scene is compiled into one display list while the
 * viewing matrix is current, as programs often do in their init().
 *
 * GL dereferences the arrays when glDrawElements / glDrawArrays is
 * compiled, records glClipPlane and applies it, like the geometry, under
 * the modelview current when the list is called.  The view current at
 * compile time therefore does not matter: the list is called under the
 * view each frame.
 *
 * Built twice from this source: against GL (OSMesa) and against Tracelist
 * through rt/glcompat.h; only the #include lines below differ.
 *
 *     varray [output.ppm]
 */
#ifdef USE_TRACELIST
#include <rt/glcompat.h>
#else
#include <GL/gl.h>
#include <GL/glu.h>
#endif
#include "offscreen.h"

#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define WIDTH 256
#define HEIGHT 256
#define RINGS 48
#define SIDES 12

static GLfloat tube_vertices[RINGS * SIDES * 3];
static GLfloat tube_normals[RINGS * SIDES * 3];
static GLushort tube_indices[RINGS * SIDES * 6];
static GLuint scene_list;

/* A tube of radius 0.35 around a (2, 3) torus knot-like closed curve, in
 * vertex and normal arrays indexed as triangles. */
static void make_tube(void)
{
    int i, j, n = 0;
    for (i = 0; i < RINGS; i++) {
        double a = 2.0 * M_PI * i / RINGS;
        double c[3], d[3], u[3], w[3], len;
        c[0] = (1.6 + 0.5 * cos(3.0 * a)) * cos(2.0 * a);
        c[1] = 0.5 * sin(3.0 * a);
        c[2] = (1.6 + 0.5 * cos(3.0 * a)) * sin(2.0 * a);
        /* tangent by differences, then a frame around it */
        d[0] = (1.6 + 0.5 * cos(3.0 * (a + 1e-4))) * cos(2.0 * (a + 1e-4)) - c[0];
        d[1] = 0.5 * sin(3.0 * (a + 1e-4)) - c[1];
        d[2] = (1.6 + 0.5 * cos(3.0 * (a + 1e-4))) * sin(2.0 * (a + 1e-4)) - c[2];
        len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        d[0] /= len, d[1] /= len, d[2] /= len;
        u[0] = d[1] * 0.0 - d[2] * 1.0; /* d x y */
        u[1] = d[2] * 0.0 - d[0] * 0.0;
        u[2] = d[0] * 1.0 - d[1] * 0.0;
        len = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        u[0] /= len, u[1] /= len, u[2] /= len;
        w[0] = d[1] * u[2] - d[2] * u[1];
        w[1] = d[2] * u[0] - d[0] * u[2];
        w[2] = d[0] * u[1] - d[1] * u[0];
        for (j = 0; j < SIDES; j++) {
            double b = 2.0 * M_PI * j / SIDES;
            int k;
            for (k = 0; k < 3; k++) {
                double nk = cos(b) * u[k] + sin(b) * w[k];
                tube_normals[3 * (i * SIDES + j) + k] = (GLfloat)nk;
                tube_vertices[3 * (i * SIDES + j) + k] = (GLfloat)(c[k] + 0.35 * nk);
            }
        }
    }
    for (i = 0; i < RINGS; i++)
        for (j = 0; j < SIDES; j++) {
            GLushort a = (GLushort)(i * SIDES + j);
            GLushort b = (GLushort)(((i + 1) % RINGS) * SIDES + j);
            GLushort c = (GLushort)(((i + 1) % RINGS) * SIDES + (j + 1) % SIDES);
            GLushort d = (GLushort)(i * SIDES + (j + 1) % SIDES);
            tube_indices[n++] = a, tube_indices[n++] = b, tube_indices[n++] = c;
            tube_indices[n++] = a, tube_indices[n++] = c, tube_indices[n++] = d;
        }
}

static void compile_scene(void)
{
    static const GLfloat floor_vertices[] = {-4, -1, -4, -4, -1, 4, 4, -1, -4, 4, -1, 4};
    static const GLfloat floor_normals[] = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
    static const GLfloat floor_colour[] = {0.5f, 0.5f, 0.45f, 1.0f};
    static const GLfloat tube_colour[] = {0.8f, 0.3f, 0.25f, 1.0f};
    static const GLfloat white[] = {1.0f, 1.0f, 1.0f, 1.0f};
    /* Keep y <= 0.3: the plane 0x - 1y + 0z + 0.3 >= 0. */
    static const GLdouble cut[] = {0.0, -1.0, 0.0, 0.3};

    scene_list = glGenLists(1);
    glNewList(scene_list, GL_COMPILE);

    glClipPlane(GL_CLIP_PLANE0, cut);
    glEnable(GL_CLIP_PLANE0);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, tube_colour);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 60.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, tube_vertices);
    glNormalPointer(GL_FLOAT, 0, tube_normals);
    glDrawElements(GL_TRIANGLES, RINGS * SIDES * 6, GL_UNSIGNED_SHORT, tube_indices);
    glDisable(GL_CLIP_PLANE0);

    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, floor_colour);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 5.0f);
    glVertexPointer(3, GL_FLOAT, 0, floor_vertices);
    glNormalPointer(GL_FLOAT, 0, floor_normals);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);

    glEndList();
}

static void view(void)
{
    glLoadIdentity();
    gluLookAt(0.0, 3.0, 7.0, 0.0, -0.2, 0.0, 0.0, 1.0, 0.0);
}

static void init(void)
{
    static const GLfloat fog_colour[] = {0.35f, 0.4f, 0.45f, 1.0f};
    static const GLfloat light1_diffuse[] = {0.4f, 0.5f, 0.9f, 1.0f};

    glClearColor(fog_colour[0], fog_colour[1], fog_colour[2], 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, light1_diffuse);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.1f);

    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogfv(GL_FOG_COLOR, fog_colour);
    glFogf(GL_FOG_START, 5.0f);
    glFogf(GL_FOG_END, 12.0f);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (GLdouble)WIDTH / HEIGHT, 1.0, 40.0);
    glMatrixMode(GL_MODELVIEW);

    make_tube();
    view(); /* the list is compiled under the view matrix */
    compile_scene();
}

static void display(void)
{
    static const GLfloat light0_position[] = {1.0f, 2.0f, 1.5f, 0.0f};
    static const GLfloat light1_position[] = {-3.0f, 1.0f, 2.0f, 1.0f};
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    view();
    glLightfv(GL_LIGHT0, GL_POSITION, light0_position);
    glLightfv(GL_LIGHT1, GL_POSITION, light1_position);
    glPushMatrix();
    glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
    glCallList(scene_list);
    glPopMatrix();
    glFlush();
}

int main(int argc, char **argv)
{
    if (!offscreen_open(WIDTH, HEIGHT))
        return 1;
    glViewport(0, 0, WIDTH, HEIGHT);
    init();
    display();
    offscreen_swap();
    return offscreen_close(argc > 1 ? argv[1] : "varray.ppm");
}
