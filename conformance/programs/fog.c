/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fog.c - a row of lit teapots and spheres going away from the viewer in
 * grey fog, in the style of the GL 1.x teaching programs on fog.
 *
 *   f   next fog mode: GL_EXP (first), GL_EXP2, GL_LINEAR, GL_EXP again
 *   d   denser fog (the exponential modes)
 *   Esc quit
 *
 * The fog colour is the clear colour, so the far objects fade into the
 * background.  The mode is written in the corner with glRasterPos under a
 * pushed window projection and glutBitmapCharacter.  Built twice from this source: against GL (headless with
 * the OSMesa GLUT subset in shim/, or any GLUT) and against Tracelist
 * through rt/glcompat.h; only the #include lines below differ.
 */
#ifdef USE_TRACELIST
#include <rt/glcompat.h>
#else
#include <GL/glut.h>
#endif

#include <stdio.h>
#include <stdlib.h>

static int gl_errors;
static GLint fog_mode = GL_EXP;
static GLfloat density = 0.25f;

static void check_errors(const char *where)
{
    GLenum error;
    while ((error = glGetError()) != GL_NO_ERROR) {
        fprintf(stderr, "fog: GL error %s in %s\n", (const char *)gluErrorString(error), where);
        gl_errors++;
    }
}

static void init(void)
{
    static const GLfloat position[] = {0.5f, 0.8f, 1.0f, 0.0f};
    static const GLfloat fog_colour[] = {0.5f, 0.5f, 0.55f, 1.0f};
    static const GLfloat specular[] = {0.6f, 0.6f, 0.6f, 1.0f};
    glEnable(GL_DEPTH_TEST);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);

    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, fog_mode);
    glFogfv(GL_FOG_COLOR, fog_colour);
    glFogf(GL_FOG_DENSITY, density);
    glHint(GL_FOG_HINT, GL_DONT_CARE);
    glFogf(GL_FOG_START, 3.0f);
    glFogf(GL_FOG_END, 14.0f);
    glClearColor(0.5f, 0.5f, 0.55f, 1.0f);
}

static void object(int i, GLfloat x, GLfloat z)
{
    GLfloat colour[4];
    colour[0] = 0.9f - 0.12f * i;
    colour[1] = 0.2f + 0.1f * i;
    colour[2] = 0.15f + 0.05f * i;
    colour[3] = 1.0f;
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colour);
    glPushMatrix();
    glTranslatef(x, 0.0f, z);
    if (i % 2 == 0) {
        glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
        glutSolidTeapot(0.8);
    } else {
        glutSolidSphere(0.7, 24, 16);
    }
    glPopMatrix();
}

/* The fog mode in the top left corner, as text on a panel over the scene,
 * and a crosshair: a window projection pushed, popped again. */
static void show_mode(void)
{
    const char *text = fog_mode == GL_EXP ? "GL_EXP" : fog_mode == GL_EXP2 ? "GL_EXP2" : "GL_LINEAR";
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    glDisable(GL_LIGHTING);
    glDisable(GL_FOG);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    gluOrtho2D(0.0, (GLdouble)viewport[2], 0.0, (GLdouble)viewport[3]);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    /* A heads-up display drawn as geometry: a translucent panel under the
     * text, a crosshair in the middle. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.0f, 0.0f, 0.0f, 0.6f);
    glBegin(GL_QUADS);
    glVertex2i(4, viewport[3] - 26);
    glVertex2i(112, viewport[3] - 26);
    glVertex2i(112, viewport[3] - 2);
    glVertex2i(4, viewport[3] - 2);
    glEnd();
    glDisable(GL_BLEND);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_LINES);
    glVertex2i(viewport[2] / 2 - 8, viewport[3] / 2);
    glVertex2i(viewport[2] / 2 + 8, viewport[3] / 2);
    glVertex2i(viewport[2] / 2, viewport[3] / 2 - 8);
    glVertex2i(viewport[2] / 2, viewport[3] / 2 + 8);
    glEnd();
    glColor3f(1.0f, 1.0f, 0.3f);
    glRasterPos2i(8, viewport[3] - 20);
    while (*text)
        glutBitmapCharacter(GLUT_BITMAP_HELVETICA_18, *text++);
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_FOG);
    glEnable(GL_LIGHTING);
}

static void display(void)
{
    int i;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (i = 0; i < 5; i++)
        object(i, -1.8f + 1.4f * i, -6.0f - 2.0f * i);
    show_mode();
    glFlush();
    glutSwapBuffers();
    check_errors("display");
}

static void reshape(int width, int height)
{
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (GLdouble)width / (height ? height : 1), 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, -0.3f, 0.0f);
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 'f':
    case 'F':
        fog_mode = fog_mode == GL_EXP ? GL_EXP2 : fog_mode == GL_EXP2 ? GL_LINEAR : GL_EXP;
        glFogi(GL_FOG_MODE, fog_mode);
        printf("fog mode %s\n", fog_mode == GL_EXP ? "GL_EXP"
                                : fog_mode == GL_EXP2 ? "GL_EXP2" : "GL_LINEAR");
        glutPostRedisplay();
        break;
    case 'd':
        density *= 1.5f;
        glFogf(GL_FOG_DENSITY, density);
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
    glutInitWindowSize(320, 240);
    glutCreateWindow("fog");
    init();
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
