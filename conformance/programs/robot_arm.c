/* SPDX-License-Identifier: Apache-2.0 */
/*
 * robot_arm.c - a hierarchical robot arm drawn from nested display lists,
 * written in the style of a GL 1.x program of the 1990s.
 *
 * The parts are display lists that call other lists: a unit cube, a
 * finger made of two cube segments, a hand that calls the finger list
 * three times, an upper arm and a forearm that call the cube.  None of
 * the geometry lists sets a material: the caller sets one with
 * glMaterialfv before glCallList, so one list is drawn in several
 * materials.  The hand list sets a material of its own after its palm, so
 * the fingers it draws, and whatever the caller draws after it, are gold.
 * The lists are compiled with a viewing matrix current, which must not
 * matter (GL applies the modelview when a list is called, not compiled).
 *
 * Built twice from this source: against GL (OSMesa) and against Tracelist
 * through rt/glcompat.h; only the #include lines below differ.
 *
 *     robot_arm [output.ppm]
 */
#ifdef USE_TRACELIST
#include <rt/glcompat.h>
#else
#include <GL/gl.h>
#include <GL/glu.h>
#endif
#include "offscreen.h"

#define WIDTH 256
#define HEIGHT 256

static GLuint base_list;
#define CUBE (base_list + 0)
#define FINGER (base_list + 1)
#define HAND (base_list + 2)
#define UPPER_ARM (base_list + 3)
#define FOREARM (base_list + 4)
#define PEDESTAL (base_list + 5)

static GLfloat shoulder = 30.0f, elbow = -50.0f, wrist = 20.0f, grip = 15.0f;

static const GLfloat grey[] = {0.45f, 0.45f, 0.5f, 1.0f};
static const GLfloat orange[] = {0.9f, 0.45f, 0.1f, 1.0f};
static const GLfloat blue[] = {0.2f, 0.35f, 0.85f, 1.0f};
static const GLfloat gold[] = {0.85f, 0.7f, 0.2f, 1.0f};
static const GLfloat green[] = {0.2f, 0.7f, 0.3f, 1.0f};
static const GLfloat white[] = {1.0f, 1.0f, 1.0f, 1.0f};

/* A unit cube centred on the origin, one normal per face. */
static void cube(void)
{
    static const GLfloat n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                    {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const int faces[6][4] = {{1, 2, 6, 5}, {0, 4, 7, 3}, {2, 3, 7, 6},
                                    {0, 1, 5, 4}, {4, 5, 6, 7}, {0, 3, 2, 1}};
    GLfloat v[8][3];
    int i;
    for (i = 0; i < 8; i++) {
        v[i][0] = (i == 1 || i == 2 || i == 5 || i == 6) ? 0.5f : -0.5f;
        v[i][1] = (i == 2 || i == 3 || i == 6 || i == 7) ? 0.5f : -0.5f;
        v[i][2] = (i >= 4) ? 0.5f : -0.5f;
    }
    glBegin(GL_QUADS);
    for (i = 0; i < 6; i++) {
        glNormal3fv(n[i]);
        glVertex3fv(v[faces[i][0]]);
        glVertex3fv(v[faces[i][1]]);
        glVertex3fv(v[faces[i][2]]);
        glVertex3fv(v[faces[i][3]]);
    }
    glEnd();
}

/* A box of the given size whose base is at the origin: the cube list
 * under a translation and a scale, both recorded into the calling list. */
static void box(GLfloat x, GLfloat y, GLfloat z)
{
    glPushMatrix();
    glTranslatef(0.0f, y * 0.5f, 0.0f);
    glScalef(x, y, z);
    glCallList(CUBE);
    glPopMatrix();
}

static void make_lists(void)
{
    GLUquadricObj *q = gluNewQuadric();
    int i;

    base_list = glGenLists(6);

    glNewList(CUBE, GL_COMPILE);
    cube();
    glEndList();

    /* Two segments; the joint angle is fixed at compile time. */
    glNewList(FINGER, GL_COMPILE);
    box(0.12f, 0.35f, 0.12f);
    glTranslatef(0.0f, 0.35f, 0.0f);
    glRotatef(-25.0f, 0.0f, 0.0f, 1.0f);
    box(0.1f, 0.3f, 0.1f);
    glEndList();

    /* The palm in the caller's material, then a material of its own: the
     * fingers are gold, and gold stays current after the call. */
    glNewList(HAND, GL_COMPILE);
    box(0.5f, 0.25f, 0.3f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, gold);
    for (i = 0; i < 3; i++) {
        glPushMatrix();
        glTranslatef(-0.18f + 0.18f * (GLfloat)i, 0.25f, 0.0f);
        glRotatef(i == 1 ? 0.0f : (i == 0 ? 12.0f : -12.0f), 0.0f, 0.0f, 1.0f);
        glCallList(FINGER);
        glPopMatrix();
    }
    glEndList();

    glNewList(UPPER_ARM, GL_COMPILE);
    box(0.35f, 1.6f, 0.35f);
    glEndList();

    glNewList(FOREARM, GL_COMPILE);
    box(0.28f, 1.3f, 0.28f);
    glEndList();

    /* The pedestal: a GLU cylinder with a disk lid, axis along y. */
    glNewList(PEDESTAL, GL_COMPILE);
    glPushMatrix();
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    gluCylinder(q, 0.6, 0.45, 0.4, 24, 1);
    glTranslatef(0.0f, 0.0f, 0.4f);
    gluDisk(q, 0.0, 0.45, 24, 1);
    glPopMatrix();
    glEndList();

    gluDeleteQuadric(q);
}

static void init(void)
{
    static const GLfloat light_position[] = {2.0f, 4.0f, 5.0f, 0.0f};
    static const GLfloat ambient[] = {0.15f, 0.15f, 0.15f, 1.0f};

    glClearColor(0.1f, 0.1f, 0.18f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE); /* the boxes are scaled cubes */
    glShadeModel(GL_FLAT);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(32.0, (GLdouble)WIDTH / HEIGHT, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(3.5, 4.0, 8.5, -0.3, 1.9, 0.0, 0.0, 1.0, 0.0);
    /* The light is fixed in the scene: positioned under the view. */
    glLightfv(GL_LIGHT0, GL_POSITION, light_position);

    /* Compiled with the view current: GL ignores it until the call. */
    make_lists();
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();

    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, grey);
    glCallList(PEDESTAL);
    glTranslatef(0.0f, 0.4f, 0.0f);

    glRotatef(shoulder, 0.0f, 0.0f, 1.0f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, orange);
    glCallList(UPPER_ARM);
    glTranslatef(0.0f, 1.6f, 0.0f);

    glRotatef(elbow, 0.0f, 0.0f, 1.0f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, blue);
    glCallList(FOREARM);
    glTranslatef(0.0f, 1.3f, 0.0f);

    glRotatef(wrist, 0.0f, 0.0f, 1.0f);
    glRotatef(grip, 0.0f, 1.0f, 0.0f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, green);
    glCallList(HAND);

    /* No material set here: the hand list left gold current. */
    glTranslatef(0.0f, 0.9f, 0.0f);
    glScalef(0.25f, 0.25f, 0.25f);
    glCallList(CUBE);

    glPopMatrix();

    /* The same cube list twice more in two materials, on the floor. */
    glPushMatrix();
    glTranslatef(-1.6f, 0.25f, 1.0f);
    glScalef(0.5f, 0.5f, 0.5f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, orange);
    glCallList(CUBE);
    glTranslatef(1.6f, 0.0f, 0.8f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, blue);
    glCallList(CUBE);
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
    glDeleteLists(base_list, 6);
    return offscreen_close(argc > 1 ? argv[1] : "robot_arm.ppm");
}
