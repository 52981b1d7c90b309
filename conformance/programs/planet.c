/* SPDX-License-Identifier: Apache-2.0 */
/*
 * planet.c - a light that moves with the modelview and a little solar
 * system of nested transformations, in the style of the GL 1.x teaching
 * programs on viewing and modelling.
 *
 * A lit solid torus sits at the centre.  The light is placed by
 * glLightfv(GL_POSITION) under a rotation (so it circles the torus as
 * the 'l' key turns it) and marked by a small unlit wire sphere drawn
 * under the same matrix.  Round the torus a wire planet circles on its
 * year, turns on its day, and carries a small lit solid moon: each body
 * between glPushMatrix and glPopMatrix.  The idle callback moves the
 * planet on between frames.
 *
 *   l   move the light 30 degrees     y / Y   planet's year forward / back
 *   d   planet's day forward          space   animation (the idle callback) on/off
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

static int spin = 300, year = 120, day = 0, animate = 1, gl_errors;

static void check_errors(const char *where)
{
    GLenum error;
    while ((error = glGetError()) != GL_NO_ERROR) {
        fprintf(stderr, "planet: GL error %s in %s\n", (const char *)gluErrorString(error),
                where);
        gl_errors++;
    }
}

static void init(void)
{
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
}

static void display(void)
{
    static const GLfloat position[] = {0.0f, 0.0f, 1.8f, 1.0f};
    static const GLfloat torus_colour[] = {0.7f, 0.6f, 0.3f, 1.0f};
    static const GLfloat moon_colour[] = {0.8f, 0.8f, 0.85f, 1.0f};
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    gluLookAt(0.0, 2.5, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

    /* the light, turned by spin about the x axis, and its marker */
    glPushMatrix();
    glRotated((GLdouble)spin, 1.0, 0.0, 0.0);
    glRotated(25.0, 0.0, 1.0, 0.0);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glTranslated(0.0, 0.0, 1.8);
    glDisable(GL_LIGHTING);
    glColor3f(1.0f, 1.0f, 0.3f);
    glutWireSphere(0.12, 8, 6);
    glEnable(GL_LIGHTING);
    glPopMatrix();

    /* the torus at the centre */
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, torus_colour);
    glPushMatrix();
    glRotatef(-50.0f, 1.0f, 0.0f, 0.0f);
    glutSolidTorus(0.25, 0.8, 16, 32);
    glPopMatrix();

    /* the planet: its year, its day, and its moon */
    glPushMatrix();
    glRotatef((GLfloat)year, 0.0f, 1.0f, 0.0f);
    glTranslatef(2.4f, 0.0f, 0.0f);
    glRotatef((GLfloat)day, 0.0f, 1.0f, 0.0f);
    glDisable(GL_LIGHTING);
    glColor3f(0.3f, 0.6f, 1.0f);
    glutWireSphere(0.45, 12, 8);
    glEnable(GL_LIGHTING);
    glPushMatrix();
    glRotatef(60.0f, 0.0f, 0.0f, 1.0f);
    glTranslatef(0.8f, 0.0f, 0.0f);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, moon_colour);
    glutSolidSphere(0.15, 12, 10);
    glPopMatrix();
    glPopMatrix();

    glPopMatrix();
    glutSwapBuffers();
    check_errors("display");
}

static void reshape(int width, int height)
{
    glViewport(0, 0, (GLsizei)width, (GLsizei)height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (GLfloat)width / (GLfloat)(height ? height : 1), 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* The animation: a step of the planet's day and year per idle call. */
static void step(void)
{
    day = (day + 10) % 360;
    year = (year + 3) % 360;
    glutPostRedisplay();
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 'l':
        spin = (spin + 30) % 360;
        break;
    case 'y':
        year = (year + 10) % 360;
        break;
    case 'Y':
        year = (year + 350) % 360;
        break;
    case 'd':
        day = (day + 15) % 360;
        break;
    case ' ':
        animate = !animate;
        glutIdleFunc(animate ? step : NULL);
        break;
    case 27:
        exit(gl_errors != 0);
    default:
        return;
    }
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutInitWindowPosition(100, 100);
    glutCreateWindow("planet");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutIdleFunc(step);
    glutMainLoop();
    return 0;
}
