/* SPDX-License-Identifier: Apache-2.0 */
/*
 * offscreen_rt.c - offscreen.h over Tracelist: the build under test.  A
 * frame ends with rtFinish, as it ends with glFinish on the GL side: in a
 * GL-style frame (one begun by glClear / rtClear) the frame described and
 * not rendered yet is rendered then, and an already rendered one (by the
 * program's glFlush) is not rendered again.  Every error is counted and
 * printed through rtErrorCallback, so that a program that renders the
 * right image with errors along the way fails.
 */
#include "offscreen.h"
#include "ppm.h"

#include <rt/rt.h>

#include <stdio.h>
#include <stdlib.h>

struct offscreen {
    RTcontext context;
    int width, height, errors;
};

static struct offscreen state;

static void count_error(RTenum error, const char *message, void *user)
{
    struct offscreen *s = user;
    if (s->errors++ < 20)
        fprintf(stderr, "Tracelist error 0x%x: %s\n", error, message ? message : "");
}

int offscreen_open(int width, int height)
{
    state.context = rtCreateContext(NULL);
    if (!state.context || !rtMakeCurrent(state.context)) {
        fprintf(stderr, "offscreen: cannot create a Tracelist context\n");
        return 0;
    }
    rtErrorCallback(count_error, &state);
    state.width = width;
    state.height = height;
    return 1;
}

void offscreen_swap(void)
{
    rtFinish();
}

int offscreen_close(const char *path)
{
    unsigned char *rgba = malloc((size_t)state.width * state.height * 4);
    int ok = rgba != NULL;
    if (ok) {
        rtReadPixels(0, 0, state.width, state.height, RT_RGBA, RT_UNSIGNED_BYTE, rgba);
        ok = ppm_write(path, state.width, state.height, rgba);
        if (!ok)
            fprintf(stderr, "offscreen: cannot write %s\n", path);
    }
    if (state.errors)
        fprintf(stderr, "offscreen: %d Tracelist error(s) recorded\n", state.errors);
    free(rgba);
    rtMakeCurrent(NULL);
    rtDestroyContext(state.context);
    return !ok || state.errors != 0;
}
