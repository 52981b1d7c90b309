/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Tutorial 1: minimal ray queries (docs/tutorials/01-minimal.md).
 *
 * The smallest complete Tracelist program: create a context, record one
 * triangle as an object (like an OpenGL display list), place it in the
 * scene once, and ask rtTraceRays and rtOccludedRays about a few rays.
 * No camera, no rendering, no utility library: rt.h only.
 */
#include <rt/rt.h>

#include <math.h>
#include <stdio.h>

int main(void)
{
    /* 1. A context, made current on this thread (like glXMakeCurrent). */
    RTcontext context = rtCreateContext("threads=1");
    if (context == NULL || !rtMakeCurrent(context)) {
        fprintf(stderr, "tutorial01: cannot create a context\n");
        return 1;
    }

    /* 2. Geometry is recorded into a named object, in immediate mode. */
    rtNewObject(1);
    rtBegin(RT_TRIANGLES);
    rtVertex3f(-1.0f, -1.0f, -5.0f);
    rtVertex3f(1.0f, -1.0f, -5.0f);
    rtVertex3f(0.0f, 1.0f, -5.0f);
    rtEnd();
    rtEndObject();

    /* 3. The scene: one instance under the current (identity) modelview. */
    rtInstantiateObject(1);

    /* 4. Rays: origin, tmin, direction, tmax.  The first hits the
     * triangle's middle, the second passes beside it. */
    RTray rays[2] = {
        {{0.0f, 0.0f, 0.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, INFINITY},
        {{3.0f, 0.0f, 0.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, INFINITY},
    };
    RThit hits[2];
    rtTraceRays(2, rays, hits);
    for (int i = 0; i < 2; i++) {
        if (hits[i].object == RT_INVALID_ID)
            printf("ray %d: miss\n", i);
        else
            printf("ray %d: hit object %u, triangle %u at t = %g (u = %.3f, v = %.3f)\n", i,
                   hits[i].object, hits[i].primitive, (double)hits[i].t, (double)hits[i].u,
                   (double)hits[i].v);
    }

    /* 5. Shadow-ray style queries only answer "is anything in the way". */
    RTboolean occluded[2];
    rtOccludedRays(2, rays, occluded);
    printf("occluded: %d %d\n", occluded[0], occluded[1]);

    /* 6. Errors are recorded, never returned: check once at the end. */
    RTenum error = rtGetError();
    rtDestroyContext(context);

    int ok = error == RT_NO_ERROR && hits[0].object == 1 && fabsf(hits[0].t - 5.0f) < 1e-4f &&
             hits[1].object == RT_INVALID_ID && occluded[0] && !occluded[1];
    printf("tutorial01: %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
