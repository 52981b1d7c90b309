/* SPDX-License-Identifier: Apache-2.0 */
/*
 * torus.c - a torus compiled once into a display list and called every
 * frame, beside the teapot and an open tube, with back faces culled, in
 * the style of the GL 1.x teaching programs on display lists.
 *
 * The torus is made of quad strips computed with sin and cos inside
 * glNewList / glEndList and drawn with glCallList, flat shaded (one
 * colour per quad, GL's provoking vertex).  Back faces are culled for the
 * whole frame.  The teapot's front faces wind clockwise, so it is drawn
 * between glFrontFace(GL_CW) and glFrontFace(GL_CCW), and smooth shaded.
 * The tube, a gluCylinder without caps, shows the culling: its inner far
 * wall faces away from the viewer and is not drawn.
 *
 *   x / y   turn the torus about x / y     i   reset
 *   Esc     quit
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

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PI_ 3.14159265358979323846

static GLuint torus_list;
static GLUquadricObj *tube;
static GLfloat turn_x = 30.0f, turn_y = 0.0f;
static int gl_errors;

static void check_errors(const char *where)
{
    GLenum error;
    while ((error = glGetError()) != GL_NO_ERROR) {
        fprintf(stderr, "torus: GL error %s in %s\n", (const char *)gluErrorString(error),
                where);
        gl_errors++;
    }
}

/* A torus round the z axis: numc segments round the tube, numt round
 * the ring, each ring segment one quad strip. */
static void torus(int numc, int numt, double tube_radius, double ring_radius)
{
    int i, j, k;
    for (i = 0; i < numt; i++) {
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= numc; j++) {
            for (k = 1; k >= 0; k--) {
                double s = (i + k) % numt + 0.5;
                double t = j % numc;
                double a = t * 2.0 * PI_ / numc, b = s * 2.0 * PI_ / numt;
                double x = (ring_radius + tube_radius * cos(a)) * cos(b);
                double y = (ring_radius + tube_radius * cos(a)) * sin(b);
                double z = tube_radius * sin(a);
                glNormal3d(cos(a) * cos(b), cos(a) * sin(b), sin(a));
                glVertex3d(x, y, z);
            }
        }
        glEnd();
    }
}

static void init(void)
{
    static const GLfloat position[] = {1.0f, 1.5f, 2.0f, 0.0f};
    glClearColor(0.2f, 0.2f, 0.25f, 0.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glShadeModel(GL_FLAT);

    torus_list = glGenLists(1);
    glNewList(torus_list, GL_COMPILE);
    torus(10, 24, 0.28, 0.9);
    glEndList();

    tube = gluNewQuadric();
    gluQuadricNormals(tube, GLU_SMOOTH);
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* the torus list, flat shaded */
    glColor3f(0.3f, 0.75f, 0.4f);
    glPushMatrix();
    glTranslatef(-1.5f, 0.3f, 0.0f);
    glRotatef(turn_x, 1.0f, 0.0f, 0.0f);
    glRotatef(turn_y, 0.0f, 1.0f, 0.0f);
    glCallList(torus_list);
    glPopMatrix();

    /* the teapot, clockwise front faces, smooth shaded */
    glShadeModel(GL_SMOOTH);
    glColor3f(0.85f, 0.55f, 0.25f);
    glPushMatrix();
    glTranslatef(1.3f, 0.6f, 0.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    glFrontFace(GL_CW);
    glutSolidTeapot(0.7);
    glFrontFace(GL_CCW);
    glPopMatrix();

    /* the open tube, its far inner wall culled */
    glColor3f(0.4f, 0.5f, 0.9f);
    glPushMatrix();
    glTranslatef(0.3f, -1.2f, 0.5f);
    glRotatef(-25.0f, 1.0f, 0.0f, 0.0f);
    gluCylinder(tube, 0.55, 0.55, 0.8, 24, 1);
    glPopMatrix();
    glShadeModel(GL_FLAT);

    glutSwapBuffers();
    check_errors("display");
}

static void reshape(int width, int height)
{
    glViewport(0, 0, (GLsizei)width, (GLsizei)height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(35.0, (GLfloat)width / (GLfloat)(height ? height : 1), 1.0, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 0.0, 8.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 'x':
    case 'X':
        turn_x += 10.0f;
        break;
    case 'y':
    case 'Y':
        turn_y += 10.0f;
        break;
    case 'i':
    case 'I':
        turn_x = 30.0f;
        turn_y = 0.0f;
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
    glutCreateWindow("torus");
    init();
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
