/* SPDX-License-Identifier: Apache-2.0 */
/*
 * immediate.c - an immediate-mode GL 1.x program: every frame it sends
 * all of its geometry again with glBegin/glEnd, outside any display list,
 * as many programs of the 1990s did.
 *
 * A rippling height field (quad strips, smooth shaded, colours through
 * GL_COLOR_MATERIAL), a ring of triangle fans, a polygon and a few
 * triangles; four frames of its animation are drawn and the last one is
 * written.  The ripple moves every frame, the rest is the same every frame.
 *
 * Built twice from this source: against GL (OSMesa) and against Tracelist
 * through rt/glcompat.h; only the #include lines below differ.
 *
 *     immediate [output.ppm]
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
#define HEIGHT 192
#define GRID 24
#define FRAMES 4

static double height_at(double x, double z, double t)
{
    double r = sqrt(x * x + z * z);
    return 0.25 * cos(3.0 * r - t) * exp(-0.3 * r);
}

/* The height field of [-2, 2]^2, one quad strip per row. */
static void terrain(double t)
{
    int i, j, k;
    for (i = 0; i < GRID; i++) {
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= GRID; j++)
            for (k = 1; k >= 0; k--) {
                double x = -2.0 + 4.0 * (i + k) / GRID, z = -2.0 + 4.0 * j / GRID;
                double e = 1e-3, y = height_at(x, z, t);
                double dx = (height_at(x + e, z, t) - height_at(x - e, z, t)) / (2 * e);
                double dz = (height_at(x, z + e, t) - height_at(x, z - e, t)) / (2 * e);
                glColor3f(0.2f + 0.5f * (float)(y + 0.25), 0.55f, 0.8f - (float)(y + 0.25));
                glNormal3d(-dx, 1.0, -dz); /* not unit length: GL_NORMALIZE */
                glVertex3d(x, y, z);
            }
        glEnd();
    }
}

/* Eight small "flowers" round the field: triangle fans. */
static void flowers(void)
{
    int f, k;
    for (f = 0; f < 8; f++) {
        double a = f * 2.0 * M_PI / 8.0, cx = 2.4 * cos(a), cz = 2.4 * sin(a);
        glBegin(GL_TRIANGLE_FAN);
        glColor3ub(250, 210, 40);
        glNormal3f(0.0f, 1.0f, 0.0f);
        glVertex3d(cx, 0.3, cz);
        glColor3ub(220, 60, 120);
        for (k = 0; k <= 10; k++) {
            double b = k * 2.0 * M_PI / 10.0;
            glVertex3d(cx + 0.25 * cos(b), 0.3, cz - 0.25 * sin(b));
        }
        glEnd();
    }
}

static void markers(void)
{
    /* A pentagon and two triangles, flat shaded with GL's provoking
     * vertex: the last vertex's colour for each triangle. */
    int k;
    glShadeModel(GL_FLAT);
    glBegin(GL_POLYGON);
    glColor3f(0.9f, 0.9f, 0.9f);
    glNormal3f(0.0f, 0.0f, 1.0f);
    for (k = 0; k < 5; k++)
        glVertex3d(0.4 * cos(k * 2.0 * M_PI / 5.0 + M_PI / 2), 1.2 + 0.4 * sin(k * 2.0 * M_PI / 5.0 + M_PI / 2), -2.2);
    glEnd();
    glBegin(GL_TRIANGLES);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex3f(-2.0f, 0.6f, -2.2f);
    glVertex3f(-1.2f, 0.6f, -2.2f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex3f(-1.6f, 1.3f, -2.2f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex3f(1.2f, 0.6f, -2.2f);
    glVertex3f(2.0f, 0.6f, -2.2f);
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex3f(1.6f, 1.3f, -2.2f);
    glEnd();
    glShadeModel(GL_SMOOTH);
}

static void display(double t)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 3.2, 5.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    terrain(t);
    flowers();
    markers();
    glFlush();
}

int main(int argc, char **argv)
{
    static const GLfloat light_position[] = {-1.0f, 3.0f, 2.0f, 0.0f};
    int frame;
    if (!offscreen_open(WIDTH, HEIGHT))
        return 1;
    glViewport(0, 0, WIDTH, HEIGHT);
    glClearColor(0.05f, 0.05f, 0.05f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glShadeModel(GL_SMOOTH);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    /* Light in eye space: positioned under the identity. */
    glLoadIdentity();
    glLightfv(GL_LIGHT0, GL_POSITION, light_position);
    for (frame = 0; frame < FRAMES; frame++) {
        display(0.6 * frame);
        offscreen_swap();
    }
    return offscreen_close(argc > 1 ? argv[1] : "immediate.ppm");
}
