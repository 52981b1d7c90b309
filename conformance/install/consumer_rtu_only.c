/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Calls only rtu (its image writer's format check and the error string of
 * a code), so the application itself has no reference to the core: it
 * runs only if libtracelist_rtu finds libtracelist by its own runpath.
 */
#include <rt/rt.h>
#include <rt/rtu.h>
#include <stdio.h>
#include <string.h>

int main(void)
{
    int ok = rtuImageFormatSupported("ppm") == RT_TRUE &&
             strcmp((const char *)rtuErrorString(RT_INVALID_VALUE), "invalid value") == 0;
    printf("consumer_rtu_only: %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
