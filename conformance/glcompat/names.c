/* SPDX-License-Identifier: Apache-2.0 */
/*
 * names.c - a translation unit written as a GL 1.x / GLU / GLUT program
 * writes it, with only <rt/glcompat.h> included: it compiles (strict C99,
 * -Werror, and as C++ in names_cxx.cpp) and runs against Tracelist.
 *
 * It uses the names whose targets exist today (mapped, adapted and no-op
 * ones; docs/glcompat.md) and checks at run time that the adapters convert
 * as GL does and that the no-ops record no error.  The names that wait for
 * a feature are used only when glcompat.h finds the feature.
 */
#include <rt/glcompat.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

static int failures;

static void check(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "glcompat/names: FAILED: %s\n", what);
        failures++;
    }
}

static void check_no_error(const char *what)
{
    GLenum error = glGetError();
    if (error != GL_NO_ERROR) {
        fprintf(stderr, "glcompat/names: %s: error 0x%x (%s)\n", what, error,
                (const char *)gluErrorString(error));
        failures++;
    }
}

/* A program's init(): state calls, half of which are no-ops here. */
static void init(void)
{
    static const GLfloat pos[4] = {5.0f, 5.0f, 10.0f, 0.0f};
    static const GLint ambient[4] = {0, 0, 0, 2147483647};
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f); /* misses keep alpha 0 */
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glDepthRange(0.0, 1.0);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glDrawBuffer(GL_BACK);
    glReadBuffer(GL_BACK);
    glClearStencil(0);
    glPolygonOffset(1.0f, 1.0f);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DITHER);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLighti(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1);
    glLightModeliv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT1, GL_POSITION, pos); /* GL_LIGHT1 is RT_LIGHT0 + 1 */
    glEnable(GL_LIGHT1);
    check(glIsEnabled(GL_LIGHT1) == GL_TRUE, "glIsEnabled(GL_LIGHT1)");
    glDisable(GL_LIGHT1);
    glEnable(GL_COLOR_MATERIAL);
    check(glIsEnabled(GL_COLOR_MATERIAL) == GL_TRUE, "glIsEnabled(GL_COLOR_MATERIAL)");
    check_no_error("init");
}

/* A list's worth of geometry in every vertex, normal, colour and texture
 * coordinate form the adapters provide. */
static void shape(GLUquadric *q)
{
    static const GLshort sv[3] = {0, 1, 0};
    static const GLint iv[3] = {1, 1, 0};
    static const GLdouble dv[3] = {0.0, 0.0, 1.0};
    static const GLubyte ubv[4] = {255, 128, 0, 255};
    GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, white);
    glMateriali(GL_FRONT_AND_BACK, GL_SHININESS, 20);
    glBegin(GL_TRIANGLES);
    glColor3ub(255, 0, 0);
    glNormal3d(0.0, 0.0, 1.0);
    glTexCoord2i(0, 0);
    glVertex2i(0, 0);
    glColor4ubv(ubv);
    glNormal3sv(sv);
    glTexCoord1f(1.0f);
    glVertex3s(1, 0, 0);
    glColor3d(0.0, 0.0, 1.0);
    glNormal3dv(dv);
    glTexCoord3f(1.0f, 1.0f, 0.5f);
    glVertex3iv(iv);
    glEnd();
    glBegin(GL_QUADS);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    glVertex3f(-1.0f, -1.0f, -1.0f);
    glVertex3d(-0.5, -1.0, -1.0);
    glVertex2fv(white);
    glVertex3fv(white);
    glEnd();
    glRectf(-2.0f, -2.0f, -1.5f, -1.5f);
    glPushMatrix();
    glTranslated(0.0, 0.0, -2.0);
    glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
    glScalef(0.5f, 0.5f, 0.5f);
    gluQuadricNormals(q, GLU_SMOOTH);
    gluQuadricOrientation(q, GLU_OUTSIDE);
    gluQuadricTexture(q, GL_FALSE);
    gluQuadricDrawStyle(q, GLU_FILL);
    gluSphere(q, 0.5, 12, 8);
    gluCylinder(q, 0.5, 0.25, 1.0, 12, 2);
    gluDisk(q, 0.1, 0.5, 12, 1);
    gluPartialDisk(q, 0.1, 0.5, 12, 1, 0.0, 90.0);
    glutSolidTeapot(0.5);
    glutSolidCube(0.5);
    glutSolidTorus(0.1, 0.4, 8, 12);
    glutSolidCone(0.3, 0.6, 8, 2);
    glutSolidSphere(0.3, 8, 6);
    glutSolidIcosahedron();
    glPopMatrix();
}

static void arrays(void)
{
    static const GLfloat v[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    static const GLfloat n[] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    static const GLubyte c[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255};
    static const GLushort e[] = {0, 1, 2};
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glNormalPointer(GL_FLOAT, 0, n);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDrawElements(GL_TRIANGLE_FAN, 3, GL_UNSIGNED_SHORT, e);
    glDrawRangeElements(GL_TRIANGLES, 0, 2, 3, GL_UNSIGNED_SHORT, e);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
}

static void texture(void)
{
    static const GLubyte texels[2 * 2 * 3] = {255, 255, 255, 0, 0, 0, 0, 0, 0, 255, 255, 255};
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, texels);
    check(glIsTexture(name) == GL_TRUE, "glIsTexture after gluBuild2DMipmaps");
    glBindTexture(GL_TEXTURE_2D, 0);
    glDeleteTextures(1, &name);
    check_no_error("textures");
}

static void queries(void)
{
    GLdouble model[16], proj[16], wx, wy, wz;
    GLint viewport[4] = {0, 0, 0, 0};
    GLboolean lit[4] = {9, 9, 9, 9};
    GLfloat clear[4];
    const GLubyte *version = glGetString(GL_VERSION);
    check(version != NULL && strlen((const char *)version) > 0, "glGetString(GL_VERSION)");
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, 1.0, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 0.0, 5.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glGetDoublev(GL_MODELVIEW_MATRIX, model);
    glGetDoublev(GL_PROJECTION_MATRIX, proj);
    glGetIntegerv(GL_VIEWPORT, viewport);
    check(model[14] == -5.0, "glGetDoublev(GL_MODELVIEW_MATRIX)");
    check(gluProject(0.0, 0.0, 0.0, model, proj, viewport, &wx, &wy, &wz) == GL_TRUE,
          "gluProject");
    check(fabs(wx - viewport[2] / 2.0) < 1e-6 && fabs(wy - viewport[3] / 2.0) < 1e-6,
          "gluProject of the origin is the viewport's centre");
    /* glGetBooleanv writes exactly GL's count: one value here. */
    glGetBooleanv(GL_MATRIX_MODE, lit);
    check(lit[0] == GL_TRUE && lit[1] == 9, "glGetBooleanv writes one value");
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    check(clear[3] == 0.0f, "glGetFloatv(GL_COLOR_CLEAR_VALUE)");
    check_no_error("queries");
}

int main(void)
{
    static GLubyte pixels[64 * 64 * 4];
    GLUquadric *q;
    GLuint object = 1;
    GLsizei i, lit = 0;
    rtMakeCurrent(rtCreateContext(NULL));
    glViewport(0, 0, 64, 64);
    init();
    texture();
    queries();
    q = gluNewQuadric();
    check(q != NULL, "gluNewQuadric");
    /* Recorded under the identity: the same with GL's and with the object
     * semantics of today's rtNewObject (vertices through the modelview). */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    /* The GL-named list calls are a feature of their own (glcompat.h maps
     * glNewList once rt.h has it); the object calls are the same thing. */
#ifdef RT_GLCOMPAT_HAVE_LISTS
    object = glGenLists(1);
    glNewList(object, GL_COMPILE);
#else
    rtNewObject(object);
#endif
    shape(q);
    arrays();
#ifdef RT_GLCOMPAT_HAVE_LISTS
    glEndList();
#else
    rtEndObject();
#endif
    gluDeleteQuadric(q);
    check_no_error("recording");
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -6.0f);
#ifdef RT_GLCOMPAT_HAVE_LISTS
    glCallList(object);
#else
    rtInstantiateObject(object);
#endif
    rtRenderFrame();
    glFinish();
    glReadPixels(0, 0, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    check_no_error("rendering");
    for (i = 0; i < 64 * 64; i++)
        lit += pixels[4 * i + 3] == 255;
    check(lit > 100, "the frame shows the geometry");
    rtDestroyContext(rtGetCurrentContext());
    printf("glcompat/names: %d failure(s), %d lit pixels\n", failures, (int)lit);
    return failures != 0;
}
