/* SPDX-License-Identifier: Apache-2.0 */
/*
 * absent.c - must NOT compile: a name Tracelist does not have stops the
 * compilation with glcompat.h's message (the ctest matches the message).
 */
#include <rt/glcompat.h>

void absent_accumulation(void)
{
    glAccum(GL_RETURN, 1.0f);
}
