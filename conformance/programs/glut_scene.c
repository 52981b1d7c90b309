/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_scene.c - a GLUT program in the classic style: GLU quadrics (a
 * sphere, a capped cylinder, a disk for the ground), the teapot, lines
 * (coordinate axes, a line loop round the ground, an optional wire cube),
 * a pop-up menu and keys.
 *
 *   arrow keys   turn the view          a   axes on/off
 *   w            wire cube on/off       Esc quit
 *   menu         "Toggle teapot", "Flat shading", "Smooth shading"
 *
 * Built twice from this source: against GL (headless with the OSMesa GLUT
 * subset in shim/, or any GLUT) and against Tracelist through
 * rt/glcompat.h with the rtu GLUT shell; only the #include lines below
 * differ.  Errors are checked after every frame, as careful GL programs do.
 */
#ifdef USE_TRACELIST
#include <rt/glcompat.h>
#else
#include <GL/glut.h>
#endif

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static GLUquadricObj *quadric;
static GLfloat view_x = 20.0f, view_y = -30.0f;
static int show_axes = 1, show_wire_cube = 0, show_teapot = 1, gl_errors;

static void check_errors(const char *where)
{
    GLenum error;
    while ((error = glGetError()) != GL_NO_ERROR) {
        fprintf(stderr, "glut_scene: GL error %s in %s\n", (const char *)gluErrorString(error),
                where);
        gl_errors++;
    }
}

static void init(void)
{
    static const GLfloat light_position[] = {3.0f, 5.0f, 4.0f, 0.0f};
    static const GLfloat specular[] = {0.8f, 0.8f, 0.8f, 1.0f};
    glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light_position);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
    quadric = gluNewQuadric();
    gluQuadricNormals(quadric, GLU_SMOOTH);
}

static void reshape(int width, int height)
{
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (GLdouble)width / (height ? height : 1), 1.0, 50.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void axes(void)
{
    glDisable(GL_LIGHTING);
    glLineWidth(2.0f);
    glBegin(GL_LINES);
    glColor3f(1.0f, 0.2f, 0.2f);
    glVertex3f(0.0f, 0.0f, 0.0f);
    glVertex3f(2.5f, 0.0f, 0.0f);
    glColor3f(0.2f, 1.0f, 0.2f);
    glVertex3f(0.0f, 0.0f, 0.0f);
    glVertex3f(0.0f, 2.5f, 0.0f);
    glColor3f(0.3f, 0.3f, 1.0f);
    glVertex3f(0.0f, 0.0f, 0.0f);
    glVertex3f(0.0f, 0.0f, 2.5f);
    glEnd();
    glLineWidth(1.0f);
    glEnable(GL_LIGHTING);
}

static void display(void)
{
    int i;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glTranslatef(0.0f, -0.5f, -9.0f);
    glRotatef(view_x, 1.0f, 0.0f, 0.0f);
    glRotatef(view_y, 0.0f, 1.0f, 0.0f);

    /* the ground: a disk in y = 0 and a line loop round it */
    glColor3f(0.35f, 0.5f, 0.3f);
    glPushMatrix();
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    gluDisk(quadric, 0.0, 3.0, 32, 2);
    glPopMatrix();
    glDisable(GL_LIGHTING);
    glColor3f(1.0f, 1.0f, 0.6f);
    glBegin(GL_LINE_LOOP);
    for (i = 0; i < 32; i++) {
        double a = i * 6.283185307179586 / 32.0;
        glVertex3d(3.2 * cos(a), 0.01, 3.2 * sin(a));
    }
    glEnd();
    glEnable(GL_LIGHTING);

    /* a sphere, a cylinder with its caps, the teapot */
    glColor3f(0.85f, 0.25f, 0.2f);
    glPushMatrix();
    glTranslatef(-1.5f, 0.7f, 0.5f);
    gluSphere(quadric, 0.7, 24, 16);
    glPopMatrix();

    glColor3f(0.25f, 0.45f, 0.9f);
    glPushMatrix();
    glTranslatef(1.4f, 0.0f, 0.8f);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    gluCylinder(quadric, 0.45, 0.45, 1.4, 24, 1);
    glTranslatef(0.0f, 0.0f, 1.4f);
    gluDisk(quadric, 0.0, 0.45, 24, 1);
    glPopMatrix();

    if (show_teapot) {
        glColor3f(0.9f, 0.75f, 0.3f);
        glPushMatrix();
        glTranslatef(0.0f, 0.55f, -1.2f);
        glutSolidTeapot(0.8);
        glPopMatrix();
    }

    if (show_wire_cube) {
        glDisable(GL_LIGHTING);
        glColor3f(1.0f, 1.0f, 1.0f);
        glPushMatrix();
        glTranslatef(0.0f, 1.0f, 0.0f);
        glutWireCube(3.0);
        glPopMatrix();
        glEnable(GL_LIGHTING);
    }

    if (show_axes)
        axes();

    glPopMatrix();
    glutSwapBuffers();
    check_errors("display");
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 'a':
        show_axes = !show_axes;
        break;
    case 'w':
        show_wire_cube = !show_wire_cube;
        break;
    case 27:
        exit(gl_errors != 0);
    default:
        return;
    }
    glutPostRedisplay();
}

static void special(int key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case GLUT_KEY_LEFT:
        view_y -= 10.0f;
        break;
    case GLUT_KEY_RIGHT:
        view_y += 10.0f;
        break;
    case GLUT_KEY_UP:
        view_x += 5.0f;
        break;
    case GLUT_KEY_DOWN:
        view_x -= 5.0f;
        break;
    default:
        return;
    }
    glutPostRedisplay();
}

static void menu(int value)
{
    switch (value) {
    case 1:
        show_teapot = !show_teapot;
        break;
    case 2:
        glShadeModel(GL_FLAT);
        break;
    case 3:
        glShadeModel(GL_SMOOTH);
        break;
    }
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutCreateWindow("glut_scene");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutSpecialFunc(special);
    glutCreateMenu(menu);
    glutAddMenuEntry("Toggle teapot", 1);
    glutAddMenuEntry("Flat shading", 2);
    glutAddMenuEntry("Smooth shading", 3);
    glutAttachMenu(GLUT_RIGHT_BUTTON);
    glutMainLoop();
    return 0;
}
