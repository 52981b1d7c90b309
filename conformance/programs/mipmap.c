/* SPDX-License-Identifier: Apache-2.0 */
/*
 * mipmap.c - a long textured floor going away from the viewer, its
 * mipmap levels loaded one by one, each of another colour, in the style
 * of the GL 1.x teaching programs on mipmapping: the bands of colour show
 * which level the filter takes at each distance.
 *
 * Levels 0 .. 5 (32 x 32 down to 1 x 1) are loaded with glTexImage2D,
 * level by level, and filtered GL_NEAREST_MIPMAP_NEAREST (the 'f' key
 * switches to GL_LINEAR_MIPMAP_LINEAR, which blends neighbouring levels).
 *
 *   f   GL_NEAREST_MIPMAP_NEAREST / GL_LINEAR_MIPMAP_LINEAR
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

static GLuint texture;
static int trilinear, gl_errors;

static void check_errors(const char *where)
{
    GLenum error;
    while ((error = glGetError()) != GL_NO_ERROR) {
        fprintf(stderr, "mipmap: GL error %s in %s\n", (const char *)gluErrorString(error),
                where);
        gl_errors++;
    }
}

/* Level `level` of side `size`, all one colour. */
static void load_level(int level, int size, GLubyte r, GLubyte g, GLubyte b)
{
    static GLubyte image[32 * 32][4];
    int i;
    for (i = 0; i < size * size; i++) {
        image[i][0] = r;
        image[i][1] = g;
        image[i][2] = b;
        image[i][3] = 255;
    }
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
}

static void init(void)
{
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_FLAT);

    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    load_level(0, 32, 255, 255, 0);
    load_level(1, 16, 255, 0, 255);
    load_level(2, 8, 255, 0, 0);
    load_level(3, 4, 0, 255, 0);
    load_level(4, 2, 0, 0, 255);
    load_level(5, 1, 255, 255, 255);
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    glEnable(GL_TEXTURE_2D);
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBindTexture(GL_TEXTURE_2D, texture);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-2.0f, -1.0f, 0.0f);
    glTexCoord2f(0.0f, 8.0f);
    glVertex3f(-2.0f, 1.0f, 0.0f);
    glTexCoord2f(2000.0f, 8.0f);
    glVertex3f(2000.0f, 1.0f, -6000.0f);
    glTexCoord2f(2000.0f, 0.0f);
    glVertex3f(2000.0f, -1.0f, -6000.0f);
    glEnd();
    glFlush();
    glutSwapBuffers();
    check_errors("display");
}

static void reshape(int width, int height)
{
    glViewport(0, 0, (GLsizei)width, (GLsizei)height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60.0, (GLfloat)width / (GLfloat)(height ? height : 1), 1.0, 30000.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.6f);
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 'f':
        trilinear = !trilinear;
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                        trilinear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST);
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
    glutInitWindowPosition(50, 50);
    glutCreateWindow("mipmap");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
