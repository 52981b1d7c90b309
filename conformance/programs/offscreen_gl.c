/* SPDX-License-Identifier: Apache-2.0 */
/*
 * offscreen_gl.c - offscreen.h over Mesa's OSMesa: the reference build of
 * the programs.  GL errors are collected with glGetError at every frame's
 * end and at the close.
 */
#include "offscreen.h"
#include "ppm.h"

#include <GL/osmesa.h>
#include <GL/gl.h>

#include <stdio.h>
#include <stdlib.h>

static OSMesaContext context;
static unsigned char *buffer;
static int frame_width, frame_height, errors;

static void collect_errors(const char *where)
{
    GLenum error;
    while ((error = glGetError()) != GL_NO_ERROR) {
        fprintf(stderr, "GL error 0x%x %s\n", error, where);
        errors++;
    }
}

int offscreen_open(int width, int height)
{
    context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    buffer = malloc((size_t)width * height * 4);
    if (!context || !buffer || !OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, width, height)) {
        fprintf(stderr, "offscreen: cannot create an OSMesa context\n");
        return 0;
    }
    frame_width = width;
    frame_height = height;
    return 1;
}

void offscreen_swap(void)
{
    glFinish();
    collect_errors("in a frame");
}

int offscreen_close(const char *path)
{
    int ok;
    glFinish();
    collect_errors("at the end");
    /* OSMesa's buffer has its rows bottom to top, as glReadPixels. */
    ok = ppm_write(path, frame_width, frame_height, buffer);
    if (!ok)
        fprintf(stderr, "offscreen: cannot write %s\n", path);
    OSMesaDestroyContext(context);
    free(buffer);
    return !ok || errors != 0;
}
