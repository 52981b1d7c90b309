/* SPDX-License-Identifier: Apache-2.0 */
/*
 * alpha.c - overlapping translucent triangles and quads in front of an
 * opaque lit sphere, in the style of the GL 1.x teaching programs on
 * blending.
 *
 * The opaque sphere is drawn first.  Then blending is switched on and the
 * depth mask off, and the translucent shapes are drawn back to front: a
 * green quad, then two triangles in one plane that overlap in the middle
 * (which of them is drawn first, and so lies under the other, is what the
 * 't' key changes).  Blending is switched off and the depth mask on again
 * for an opaque quad in front, and on once more, with an additive
 * function, for a last triangle.
 *
 *   t   draw the right triangle first / the left triangle first
 *   Esc quit
 *
 * Built twice from this source: against GL (headless with the OSMesa GLUT
 * subset in shim/, or any GLUT) and against Tracelist through
 * rt/glcompat.h; only the #include lines below differ.
 */
#ifdef USE_TRACELIST
#include <rt/glcompat.h>
#else
#include <GL/glut.h>
#endif

#include <stdio.h>
#include <stdlib.h>

static int gl_errors, left_first = 1;

static void check_errors(const char *where)
{
    GLenum error;
    while ((error = glGetError()) != GL_NO_ERROR) {
        fprintf(stderr, "alpha: GL error %s in %s\n", (const char *)gluErrorString(error), where);
        gl_errors++;
    }
}

static void init(void)
{
    static const GLfloat position[] = {2.0f, 3.0f, 4.0f, 0.0f};
    glClearColor(0.1f, 0.1f, 0.1f, 0.0f);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
}

static void left_triangle(void)
{
    glColor4f(1.0f, 0.9f, 0.1f, 0.75f);
    glBegin(GL_TRIANGLES);
    glVertex3f(-1.6f, -0.9f, 0.4f);
    glVertex3f(0.5f, -0.2f, 0.4f);
    glVertex3f(-1.4f, 1.1f, 0.4f);
    glEnd();
}

static void right_triangle(void)
{
    glColor4f(0.1f, 0.8f, 1.0f, 0.75f);
    glBegin(GL_TRIANGLES);
    glVertex3f(1.6f, -0.9f, 0.4f);
    glVertex3f(1.4f, 1.1f, 0.4f);
    glVertex3f(-0.5f, -0.2f, 0.4f);
    glEnd();
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* the opaque sphere, lit */
    glEnable(GL_LIGHTING);
    glColor3f(0.8f, 0.3f, 0.25f);
    glPushMatrix();
    glTranslatef(0.7f, 0.4f, -1.6f);
    glutSolidSphere(1.0, 24, 18);
    glPopMatrix();
    glDisable(GL_LIGHTING);

    /* the translucent shapes, back to front, not writing depth */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glColor4f(0.2f, 0.9f, 0.3f, 0.5f);
    glBegin(GL_QUADS);
    glVertex3f(-2.0f, -1.2f, -0.6f);
    glVertex3f(0.4f, -1.2f, -0.6f);
    glVertex3f(0.4f, 1.3f, -0.6f);
    glVertex3f(-2.0f, 1.3f, -0.6f);
    glEnd();
    if (left_first) {
        left_triangle();
        right_triangle();
    } else {
        right_triangle();
        left_triangle();
    }
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);

    /* an opaque quad in front of them */
    glColor3f(0.85f, 0.2f, 0.6f);
    glBegin(GL_QUADS);
    glVertex3f(-1.9f, -1.5f, 0.8f);
    glVertex3f(-0.9f, -1.5f, 0.8f);
    glVertex3f(-0.9f, -0.6f, 0.8f);
    glVertex3f(-1.9f, -0.6f, 0.8f);
    glEnd();

    /* an additive triangle over everything */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE);
    glDepthMask(GL_FALSE);
    glColor4f(0.3f, 0.3f, 0.9f, 0.6f);
    glBegin(GL_TRIANGLES);
    glVertex3f(0.3f, 0.6f, 1.0f);
    glVertex3f(1.8f, 0.4f, 1.0f);
    glVertex3f(1.2f, 1.6f, 1.0f);
    glEnd();
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);

    glutSwapBuffers();
    check_errors("display");
}

static void reshape(int width, int height)
{
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (GLdouble)width / (height ? height : 1), 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 0.0, 5.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 't':
    case 'T':
        left_first = !left_first;
        glutPostRedisplay();
        break;
    case 27:
        exit(gl_errors != 0);
    }
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutCreateWindow("alpha");
    init();
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
