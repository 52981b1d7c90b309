/* SPDX-License-Identifier: Apache-2.0 */
/*
 * shim/GL/glut.h - a headless GLUT subset over Mesa's OSMesa, for building
 * the GLUT programs of conformance/programs against real GL without a
 * display (glut_osmesa.c).  It runs a program the way the Tracelist rtu
 * shell runs it headless: the reshape callback at the window size, the
 * events of TRACELIST_EVENTS, TRACELIST_FRAMES display calls (default 1,
 * each after the idle callback),
 * then the last frame written to TRACELIST_OUT (binary PPM) and exit.
 *
 * Names and values are GLUT 3's (its API, not its code).  Only the calls
 * the programs here use are declared.
 */
#ifndef PROGRAMS_SHIM_GLUT_H
#define PROGRAMS_SHIM_GLUT_H

#include <GL/gl.h>
#include <GL/glu.h>

#define GLUT_RGB 0
#define GLUT_RGBA 0
#define GLUT_SINGLE 0
#define GLUT_DOUBLE 2
#define GLUT_DEPTH 16

#define GLUT_LEFT_BUTTON 0
#define GLUT_MIDDLE_BUTTON 1
#define GLUT_RIGHT_BUTTON 2
#define GLUT_DOWN 0
#define GLUT_UP 1

#define GLUT_KEY_F1 1
#define GLUT_KEY_LEFT 100
#define GLUT_KEY_UP 101
#define GLUT_KEY_RIGHT 102
#define GLUT_KEY_DOWN 103
#define GLUT_KEY_PAGE_UP 104
#define GLUT_KEY_PAGE_DOWN 105
#define GLUT_KEY_HOME 106
#define GLUT_KEY_END 107

/* The bitmap fonts: GLUT 3's names; the glyphs are rtu's (glut_osmesa.c). */
#define GLUT_BITMAP_9_BY_15 ((void *)2)
#define GLUT_BITMAP_8_BY_13 ((void *)3)
#define GLUT_BITMAP_TIMES_ROMAN_10 ((void *)4)
#define GLUT_BITMAP_TIMES_ROMAN_24 ((void *)5)
#define GLUT_BITMAP_HELVETICA_10 ((void *)6)
#define GLUT_BITMAP_HELVETICA_12 ((void *)7)
#define GLUT_BITMAP_HELVETICA_18 ((void *)8)

#define GLUT_WINDOW_WIDTH 102
#define GLUT_WINDOW_HEIGHT 103
#define GLUT_ELAPSED_TIME 700

void glutInit(int *argcp, char **argv);
void glutInitDisplayMode(unsigned int mode);
void glutInitWindowSize(int width, int height);
void glutInitWindowPosition(int x, int y);
int glutCreateWindow(const char *title);
void glutDisplayFunc(void (*func)(void));
void glutReshapeFunc(void (*func)(int width, int height));
void glutKeyboardFunc(void (*func)(unsigned char key, int x, int y));
void glutSpecialFunc(void (*func)(int key, int x, int y));
void glutIdleFunc(void (*func)(void));
void glutMainLoop(void);
void glutSwapBuffers(void);
void glutPostRedisplay(void);
int glutCreateMenu(void (*func)(int value));
void glutAddMenuEntry(const char *label, int value);
void glutAttachMenu(int button);
int glutGet(GLenum state);
void glutBitmapCharacter(void *font, int character);

/* GLUT 3's solids as drawn by ../gl_oracle/glut_gl.c, the wire cube and
 * the wire sphere. */
void glutSolidSphere(GLdouble radius, GLint slices, GLint stacks);
void glutSolidCube(GLdouble size);
void glutSolidCone(GLdouble base, GLdouble height, GLint slices, GLint stacks);
void glutSolidTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings);
void glutSolidTeapot(GLdouble size);
void glutWireCube(GLdouble size);
void glutWireSphere(GLdouble radius, GLint slices, GLint stacks);

#endif /* PROGRAMS_SHIM_GLUT_H */
