/* SPDX-License-Identifier: Apache-2.0 */
/*
 * feature_on.c - must compile: a feature's enum switches its family of
 * names on.  Stands in for the rt.h of a Tracelist that has the GL-named
 * list calls (the declarations below have GL's signatures) and checks
 * that glcompat.h then maps glNewList ... to them instead of stopping the
 * compilation.  Compiled only (-fsyntax-only) by the ctest.
 */
#include <rt/rt.h>

#ifndef RT_COMPILE
#define RT_COMPILE 0x1300
void rtNewList(RTuint list, RTenum mode);
void rtEndList(void);
void rtCallList(RTuint list);
RTuint rtGenLists(RTsizei range);
void rtDeleteLists(RTuint list, RTsizei range);
#endif

#include <rt/glcompat.h>

#ifndef RT_GLCOMPAT_HAVE_LISTS
#error "RT_COMPILE did not switch the list names on"
#endif

void feature_on_lists(void)
{
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glEndList();
    glCallList(list);
    glDeleteLists(list, 1);
}
