/* SPDX-License-Identifier: Apache-2.0 */
/*
 * pending.c - must NOT compile while the GL-named list calls are missing
 * from rt.h: glNewList then stops the compilation with glcompat.h's
 * "needs ..." message (the ctest matches it).  Once rt.h has them, the test
 * reports itself skipped.
 */
#include <rt/glcompat.h>

#ifdef RT_GLCOMPAT_HAVE_LISTS
#error "glcompat-skip: the list calls are present"
#else
void pending_list(void)
{
    glNewList(1, 0x1300);
}
#endif
