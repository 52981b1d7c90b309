/* SPDX-License-Identifier: Apache-2.0 */
/*
 * error_string.c - rtuErrorString, the text of an error code (gluErrorString).
 *
 * The strings are GLU's (Mesa's libGLU, src/libutil/error.c), so that a
 * program ported from OpenGL prints what its users already recognise.
 * Like gluErrorString, an unknown code gives NULL.
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include <stddef.h>

const char *rtuErrorString(RTenum error)
{
    switch (error) {
    case RT_NO_ERROR:
        return "no error";
    case RT_INVALID_ENUM:
        return "invalid enumerant";
    case RT_INVALID_VALUE:
        return "invalid value";
    case RT_INVALID_OPERATION:
        return "invalid operation";
    case RT_STACK_OVERFLOW:
        return "stack overflow";
    case RT_STACK_UNDERFLOW:
        return "stack underflow";
    case RT_OUT_OF_MEMORY:
        return "out of memory";
    default:
        return NULL;
    }
}
