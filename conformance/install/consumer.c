/* SPDX-License-Identifier: Apache-2.0 */
/* Renders one triangle through an installed Tracelist and checks a hit. */
#include <rt/rt.h>
#include <rt/rtu.h>
#include <stdio.h>

int main(void)
{
    RTcontext ctx = rtCreateContext("threads=1");
    if (!ctx || !rtMakeCurrent(ctx))
        return 1;
    rtNewObject(1);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(-1, -1, 0);
    rtVertex3f(1, -1, 0);
    rtVertex3f(0, 1, 0);
    rtEnd();
    rtEndObject();
    rtMatrixMode(RT_PROJECTION);
    rtuPerspective(45.0, 1.0, 0.1, 100.0);
    rtMatrixMode(RT_MODELVIEW);
    rtTranslatef(0, 0, -4);
    rtInstantiateObject(1);
    RTray ray = {{0, 0, 0}, 0.0f, {0, 0, -1}, 100.0f};
    RThit hit;
    rtTraceRays(1, &ray, &hit);
    int ok = rtGetError() == RT_NO_ERROR && hit.object == 1 && hit.t > 3.99f && hit.t < 4.01f;
    printf("consumer: %s (t=%g)\n", ok ? "ok" : "FAILED", (double)hit.t);
    rtDestroyContext(ctx);
    return ok ? 0 : 1;
}
