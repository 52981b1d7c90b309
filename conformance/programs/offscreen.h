/* SPDX-License-Identifier: Apache-2.0 */
/*
 * offscreen.h - the window system of the programs that do not use GLUT,
 * as an OSMesa program has one: make a context of a size, mark the end of
 * each frame, write the last frame to a file.  Implemented twice, with the
 * same behaviour: offscreen_gl.c over Mesa's OSMesa and offscreen_rt.c over
 * Tracelist.  The programs include it in both builds.
 */
#ifndef PROGRAMS_OFFSCREEN_H
#define PROGRAMS_OFFSCREEN_H

/* Creates the context (RGBA, a depth buffer) and makes it current.
 * Returns 0 and says why on failure. */
int offscreen_open(int width, int height);

/* Ends a frame, as a buffer swap does: the frame is complete after it. */
void offscreen_swap(void);

/* Reads the last frame back, writes it to path (binary PPM) and releases
 * the context.  Returns the program's exit status: 0, or 1 when an error
 * was recorded at any time (GL: glGetError; Tracelist: the error
 * callback, every error counted and printed) or the file was not written. */
int offscreen_close(const char *path);

#endif /* PROGRAMS_OFFSCREEN_H */
