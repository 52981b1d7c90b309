/* SPDX-License-Identifier: Apache-2.0 */
/*
 * backend_gl.c - renders an oracle scene with Mesa's OSMesa (software
 * OpenGL 1.x) and Mesa's libGLU: the reference side of the oracle.
 *
 * Fixed-function state for coverage: depth test on, lighting off, colour
 * white, so every covered pixel is white and every other one the clear
 * colour.  The geometry is compiled into display list 1 under the identity
 * modelview and called under the scene's view (oracle.h).
 */
#include "oracle.h"

#include <GL/osmesa.h>
#include <GL/gl.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static OSMesaContext context;
static unsigned char *buffer;

int oracle_gl_init(void)
{
    context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    buffer = malloc((size_t)ORACLE_W * ORACLE_H * 4);
    if (!context || !buffer ||
        !OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, ORACLE_W, ORACLE_H)) {
        fprintf(stderr, "gl_oracle: cannot create an OSMesa context\n");
        return 0;
    }
    return 1;
}

int oracle_gl_render(const struct oracle_scene *scene, unsigned char *rgba)
{
    GLenum error;
    glViewport(0, 0, ORACLE_W, ORACLE_H);
    glClearColor(ORACLE_BG_R, ORACLE_BG_G, ORACLE_BG_B, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);
    glDisable(GL_CULL_FACE);
    glColor3f(1.0f, 1.0f, 1.0f);
    /* What a scene may have changed (scenes_vis.inc), back to GL's initial state. */
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glLineWidth(1.0f);
    glPointSize(1.0f);
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    glDepthMask(GL_TRUE);
    for (int i = 0; i < 6; i++)
        glDisable(GL_CLIP_PLANE0 + i);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    scene->projection();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glNewList(1, GL_COMPILE);
    scene->shape();
    glEndList();
    glLoadIdentity();
    scene->view();
    glCallList(1);
    glDeleteLists(1, 1);
    glFinish();
    error = glGetError();
    if (error != GL_NO_ERROR) {
        fprintf(stderr, "gl_oracle: %s/%s: GL error 0x%x\n", scene->family, scene->name, error);
        return 0;
    }
    /* OSMesa's buffer has its rows bottom to top, as glReadPixels. */
    memcpy(rgba, buffer, (size_t)ORACLE_W * ORACLE_H * 4);
    return 1;
}

void oracle_gl_finish(void)
{
    if (context)
        OSMesaDestroyContext(context);
    free(buffer);
    context = NULL;
    buffer = NULL;
}
