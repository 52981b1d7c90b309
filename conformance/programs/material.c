/* SPDX-License-Identifier: Apache-2.0 */
/*
 * material.c - twelve lit spheres in a 4 x 3 grid, each with its own
 * material, in the style of the GL 1.x teaching programs that show what
 * the terms of the lighting equation do.
 *
 *   rows (top to bottom)   no ambient reflection, grey ambient, yellow ambient
 *   columns (left to right) diffuse only; diffuse and a broad specular
 *                          highlight (shininess 6); diffuse and a tight one
 *                          (shininess 90); diffuse and an emission
 *
 *   l   local viewer on/off (GL_LIGHT_MODEL_LOCAL_VIEWER)
 *   Esc quit
 *
 * One directional light, a global ambient light, an orthographic view and
 * glutSolidSphere placed with glPushMatrix / glTranslatef per sphere.
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

static int gl_errors, local_viewer;

static void check_errors(const char *where)
{
    GLenum error;
    while ((error = glGetError()) != GL_NO_ERROR) {
        fprintf(stderr, "material: GL error %s in %s\n", (const char *)gluErrorString(error),
                where);
        gl_errors++;
    }
}

static void init(void)
{
    static const GLfloat black[] = {0.0f, 0.0f, 0.0f, 1.0f};
    static const GLfloat white[] = {1.0f, 1.0f, 1.0f, 1.0f};
    static const GLfloat direction[] = {-1.0f, 2.5f, 2.0f, 0.0f};
    static const GLfloat scene_ambient[] = {0.35f, 0.35f, 0.35f, 1.0f};
    glClearColor(0.0f, 0.1f, 0.12f, 0.0f);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glLightfv(GL_LIGHT0, GL_AMBIENT, black);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightfv(GL_LIGHT0, GL_POSITION, direction);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, scene_ambient);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, local_viewer);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
}

static void sphere(GLfloat x, GLfloat y, const GLfloat *ambient, int column)
{
    static const GLfloat none[] = {0.0f, 0.0f, 0.0f, 1.0f};
    static const GLfloat diffuse[] = {0.15f, 0.45f, 0.85f, 1.0f};
    static const GLfloat specular[] = {1.0f, 1.0f, 1.0f, 1.0f};
    static const GLfloat emission[] = {0.35f, 0.15f, 0.1f, 0.0f};
    glPushMatrix();
    glTranslatef(x, y, 0.0f);
    glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, column == 1 || column == 2 ? specular : none);
    glMaterialf(GL_FRONT, GL_SHININESS, column == 1 ? 6.0f : column == 2 ? 90.0f : 0.0f);
    glMaterialfv(GL_FRONT, GL_EMISSION, column == 3 ? emission : none);
    glutSolidSphere(1.0, 20, 16);
    glPopMatrix();
}

static void display(void)
{
    static const GLfloat no_ambient[] = {0.0f, 0.0f, 0.0f, 1.0f};
    static const GLfloat grey_ambient[] = {0.7f, 0.7f, 0.7f, 1.0f};
    static const GLfloat yellow_ambient[] = {0.8f, 0.75f, 0.2f, 1.0f};
    const GLfloat *ambient[3];
    int row, column;
    ambient[0] = no_ambient;
    ambient[1] = grey_ambient;
    ambient[2] = yellow_ambient;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (row = 0; row < 3; row++)
        for (column = 0; column < 4; column++)
            sphere(-3.75f + 2.5f * column, 2.6f - 2.6f * row, ambient[row], column);
    glFlush();
    glutSwapBuffers();
    check_errors("display");
}

static void reshape(int width, int height)
{
    GLdouble aspect = (GLdouble)width / (height ? height : 1);
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (width <= height)
        glOrtho(-5.5, 5.5, -5.5 / aspect, 5.5 / aspect, -10.0, 10.0);
    else
        glOrtho(-4.2 * aspect, 4.2 * aspect, -4.2, 4.2, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 'l':
        local_viewer = !local_viewer;
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, local_viewer);
        glutPostRedisplay();
        break;
    case 27:
        exit(gl_errors != 0);
    }
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(400, 300);
    glutInitWindowPosition(100, 100);
    glutCreateWindow("material");
    init();
    glutReshapeFunc(reshape);
    glutDisplayFunc(display);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
