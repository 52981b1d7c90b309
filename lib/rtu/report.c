/* SPDX-License-Identifier: Apache-2.0 */
/*
 * report.c - rtu_record_error: each code through a public call that fails
 * with exactly that code and changes nothing (report.h says why).
 *
 *   RT_INVALID_VALUE      rtMultMatrixd with an all-NaN matrix (refused as
 *                         non-finite, the matrix is unchanged; the same call
 *                         camera.c has always used).
 *   RT_INVALID_ENUM       rtGetString(0): 0 names no string.
 *   RT_INVALID_OPERATION  rtDrawArrays(RT_TRIANGLES, 0, 0), which records it
 *                         inside rtBegin/rtEnd, outside rtNewObject, or with
 *                         no vertex array enabled; and then rtNewObject(0),
 *                         which records it inside an object (objects do not
 *                         nest) in the one remaining case, an object with an
 *                         enabled vertex array, where the empty draw drew
 *                         nothing.  The first error sticks, so the code is
 *                         RT_INVALID_OPERATION in every state; an error
 *                         callback may be told twice.
 */
#include "report.h"

#include <math.h>

void rtu_record_error(RTenum code)
{
    if (!rtGetCurrentContext())
        return;
    if (code == RT_INVALID_ENUM) {
        (void)rtGetString(0);
    } else if (code == RT_INVALID_OPERATION) {
        rtDrawArrays(RT_TRIANGLES, 0, 0);
        rtNewObject(0);
    } else {
        RTdouble m[16];
        int i;
        for (i = 0; i < 16; i++)
            m[i] = NAN;
        rtMultMatrixd(m);
    }
}
