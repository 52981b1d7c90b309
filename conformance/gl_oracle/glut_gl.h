/* SPDX-License-Identifier: Apache-2.0 */
/* glut_gl.h - GLUT 3's solid shapes drawn with OpenGL 1.x and GLU (glut_gl.c). */
#ifndef ORACLE_GLUT_GL_H
#define ORACLE_GLUT_GL_H

void oracle_glutSolidSphere(double radius, int slices, int stacks);
void oracle_glutSolidCone(double base, double height, int slices, int stacks);
void oracle_glutSolidCube(double size);
void oracle_glutSolidTorus(double inner_radius, double outer_radius, int sides, int rings);
void oracle_glutSolidTeapot(double size);
void oracle_glutSolidDodecahedron(void);
void oracle_glutSolidOctahedron(void);
void oracle_glutSolidTetrahedron(void);
void oracle_glutSolidIcosahedron(void);

#endif /* ORACLE_GLUT_GL_H */
