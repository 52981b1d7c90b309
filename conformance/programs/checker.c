/* SPDX-License-Identifier: Apache-2.0 */
/*
 * checker.c - two procedural textures on quads, one facing the viewer
 * and one turned away at an angle, in the style of the GL 1.x teaching
 * programs on texture objects.
 *
 * A checkerboard (its dark squares half transparent) and a pattern of
 * stripes are made in memory, given texture names with glGenTextures and
 * loaded with glTexImage2D, GL_NEAREST filtering and GL_REPEAT wrapping.
 * The checkerboard is applied with GL_DECAL (the dark squares let the
 * quad's own colour through), the stripes with GL_MODULATE on a lit quad,
 * its texture coordinates running to 2 so the pattern repeats.
 *
 *   e   swap the environments: the checkerboard GL_MODULATE, the stripes
 *       GL_DECAL, and back
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

#define CHECK_SIZE 64
#define STRIPE_SIZE 32

static GLubyte check_image[CHECK_SIZE][CHECK_SIZE][4];
static GLubyte stripe_image[STRIPE_SIZE][STRIPE_SIZE][4];
static GLuint textures[2];
static int swapped, gl_errors;

static void check_errors(const char *where)
{
    GLenum error;
    while ((error = glGetError()) != GL_NO_ERROR) {
        fprintf(stderr, "checker: GL error %s in %s\n", (const char *)gluErrorString(error),
                where);
        gl_errors++;
    }
}

static void make_images(void)
{
    int i, j;
    for (i = 0; i < CHECK_SIZE; i++)
        for (j = 0; j < CHECK_SIZE; j++) {
            int light = ((i & 8) == 0) ^ ((j & 8) == 0);
            check_image[i][j][0] = (GLubyte)(light ? 255 : 30);
            check_image[i][j][1] = (GLubyte)(light ? 255 : 30);
            check_image[i][j][2] = (GLubyte)(light ? 240 : 60);
            check_image[i][j][3] = (GLubyte)(light ? 255 : 128);
        }
    for (i = 0; i < STRIPE_SIZE; i++)
        for (j = 0; j < STRIPE_SIZE; j++) {
            int band = ((i + j) / 4) % 3;
            stripe_image[i][j][0] = (GLubyte)(band == 0 ? 255 : band == 1 ? 60 : 200);
            stripe_image[i][j][1] = (GLubyte)(band == 0 ? 200 : band == 1 ? 160 : 60);
            stripe_image[i][j][2] = (GLubyte)(band == 0 ? 40 : band == 1 ? 255 : 80);
            stripe_image[i][j][3] = (GLubyte)(band == 2 ? 100 : 255);
        }
}

static void init(void)
{
    static const GLfloat position[] = {0.0f, 1.0f, 2.0f, 0.0f};
    glClearColor(0.0f, 0.0f, 0.2f, 0.0f);
    glShadeModel(GL_FLAT);
    glEnable(GL_DEPTH_TEST);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glEnable(GL_LIGHT0);

    make_images();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(2, textures);

    glBindTexture(GL_TEXTURE_2D, textures[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, CHECK_SIZE, CHECK_SIZE, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, check_image);

    glBindTexture(GL_TEXTURE_2D, textures[1]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, STRIPE_SIZE, STRIPE_SIZE, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, stripe_image);
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);

    /* the checkerboard, facing the viewer, unlit */
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, swapped ? GL_MODULATE : GL_DECAL);
    glBindTexture(GL_TEXTURE_2D, textures[0]);
    glColor3f(0.9f, 0.3f, 0.2f);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-2.0f, -1.0f, 0.0f);
    glTexCoord2f(1.0f, 0.0f);
    glVertex3f(0.0f, -1.0f, 0.0f);
    glTexCoord2f(1.0f, 1.0f);
    glVertex3f(0.0f, 1.0f, 0.0f);
    glTexCoord2f(0.0f, 1.0f);
    glVertex3f(-2.0f, 1.0f, 0.0f);
    glEnd();

    /* the stripes, turned away at 45 degrees, lit */
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, swapped ? GL_DECAL : GL_MODULATE);
    glBindTexture(GL_TEXTURE_2D, textures[1]);
    glEnable(GL_LIGHTING);
    glBegin(GL_QUADS);
    glNormal3f(0.7071f, 0.0f, 0.7071f);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(1.0f, -1.0f, 0.0f);
    glTexCoord2f(2.0f, 0.0f);
    glVertex3f(2.41421f, -1.0f, -1.41421f);
    glTexCoord2f(2.0f, 1.0f);
    glVertex3f(2.41421f, 1.0f, -1.41421f);
    glTexCoord2f(0.0f, 1.0f);
    glVertex3f(1.0f, 1.0f, 0.0f);
    glEnd();
    glDisable(GL_LIGHTING);

    glDisable(GL_TEXTURE_2D);
    glFlush();
    glutSwapBuffers();
    check_errors("display");
}

static void reshape(int width, int height)
{
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60.0, (GLfloat)width / (GLfloat)(height ? height : 1), 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.6f);
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 'e':
        swapped = !swapped;
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
    glutInitWindowPosition(100, 100);
    glutCreateWindow("checker");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
