/* SPDX-License-Identifier: Apache-2.0 */
/* Compiled with -std=c99 -pedantic-errors: the public headers are C99. */
#include <rt/rt.h>
#include <rt/rtu.h>

int header_c99_probe(void);
int header_c99_probe(void)
{
    RTray ray = {{0, 0, 0}, 0, {0, 0, 1}, 1};
    return (int)ray.tmax + RT_NO_ERROR;
}
