/* SPDX-License-Identifier: Apache-2.0 */
/*
 * layer_gl.h - the oracle's macro layer bound to OpenGL: Mesa's OSMesa,
 * Mesa's libGLU, and GLUT 3's solids drawn with GL 1.x (glut_gl.c; the
 * installed freeglut needs a window to draw its shapes).
 *
 *   O_GL(Name)    glName       O_GLC(NAME)   GL_NAME
 *   O_GLU(Name)   gluName      O_GLUC(NAME)  GLU_NAME
 *   O_GLUT(Name)  glutName, as GLUT 3.7 draws it
 */
#ifndef ORACLE_LAYER_H
#define ORACLE_LAYER_H

#include <GL/gl.h>
#include <GL/glu.h>

#include "glut_gl.h"

#define O_GL(name) gl##name
#define O_GLC(name) GL_##name
#define O_GLU(name) glu##name
#define O_GLUC(name) GLU_##name
#define O_GLUT(name) oracle_glut##name
#define O_QUADRIC GLUquadric
#define O_INT GLint
#define O_UNLIT_COLOR(r, g, b, a) glColor4f(r, g, b, a)
#define ORACLE_SCENES oracle_scenes_gl
#define ORACLE_SCENE_COUNT oracle_scene_count_gl

#endif /* ORACLE_LAYER_H */
