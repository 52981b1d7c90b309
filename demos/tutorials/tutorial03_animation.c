/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Tutorial 3: an animated object (docs/tutorials/03-animation.md).
 *
 * A waving flag: a grid of triangles whose vertices move every frame.  The
 * object is recorded once; each frame rtUpdateVertices replaces its
 * positions in place (the triangles stay the same), and the runtime brings
 * its BVH up to date with the update strategy chosen for it (here refit:
 * keep the tree, recompute its boxes).  A second object, the pole, moves
 * rigidly: it is only re-instantiated under a new matrix, which costs a
 * top-level update and nothing for the object itself.
 */
#include <rt/rt.h>

#include <math.h>
#include <stdio.h>

#define NX 32
#define NY 16
#define FRAMES 8

static float positions[(NX + 1) * (NY + 1)][3];

/* The flag at time t: z = a travelling wave along x. */
static void wave(float t)
{
    for (int y = 0; y <= NY; y++)
        for (int x = 0; x <= NX; x++) {
            float *p = positions[y * (NX + 1) + x];
            p[0] = (float)x / NX * 4.0f;
            p[1] = (float)y / NY * 2.0f;
            p[2] = 0.3f * sinf(3.0f * p[0] - 4.0f * t) * p[0] / 4.0f;
        }
}

int main(void)
{
    RTcontext context = rtCreateContext("threads=2");
    if (context == NULL || !rtMakeCurrent(context)) {
        fprintf(stderr, "tutorial03: cannot create a context\n");
        return 1;
    }
    const RTuint flag = 1, pole = 2;
    static unsigned int indices[NX * NY * 6];
    int n = 0;
    for (int y = 0; y < NY; y++)
        for (int x = 0; x < NX; x++) {
            unsigned int a = (unsigned)(y * (NX + 1) + x), b = a + 1, c = a + NX + 1,
                         d = c + 1;
            unsigned int quad[6] = {a, b, d, a, d, c};
            for (int k = 0; k < 6; k++)
                indices[n++] = quad[k];
        }
    wave(0.0f);
    rtNewObject(flag);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, positions);
    rtDrawElements(RT_TRIANGLES, n, RT_UNSIGNED_INT, indices);
    rtDisableClientState(RT_VERTEX_ARRAY);
    rtEndObject();
    /* Hints: the flag deforms every frame; refit its tree in place. */
    rtObjectParameteri(flag, RT_OBJECT_CLASS, RT_UNSTRUCTURED);
    rtObjectParameteri(flag, RT_UPDATE_STRATEGY, RT_REFIT);

    rtNewObject(pole); /* a thin quad standing at x = 0 */
    rtBegin(RT_QUADS);
    rtVertex3f(-0.05f, -3.0f, 0.0f);
    rtVertex3f(0.05f, -3.0f, 0.0f);
    rtVertex3f(0.05f, 2.0f, 0.0f);
    rtVertex3f(-0.05f, 2.0f, 0.0f);
    rtEnd();
    rtEndObject();

    int ok = 1;
    float previous = NAN;
    for (int frame = 0; frame < FRAMES; frame++) {
        float t = (float)frame / 10.0f;
        /* Deform: new positions for the same triangles. */
        wave(t);
        rtUpdateVertices(flag, RT_VERTEX_ARRAY, 0, (NX + 1) * (NY + 1), RT_FLOAT, 0, positions);

        /* Describe the frame: both objects, the whole scene swaying in x. */
        rtBeginFrame();
        rtLoadIdentity();
        rtTranslatef(0.2f * sinf(t), 0.0f, -6.0f);
        rtInstantiateObject(pole);
        rtInstantiateObject(flag);

        /* A ray at the flag's free end, where the wave is largest. */
        RTray ray = {{3.9f + 0.2f * sinf(t), 1.0f, 0.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, INFINITY};
        RThit hit;
        rtTraceRays(1, &ray, &hit);
        RTint updates = 0;
        rtGetIntegerv(RT_STAT_OBJECT_UPDATES, &updates);
        RTint klass = 0;
        rtGetObjectiv(flag, RT_OBJECT_CLASS, &klass);
        printf("frame %d: hit object %u at t = %.4f, objects updated %d, flag class %s\n", frame,
               hit.object, (double)hit.t, updates,
               klass == RT_UNSTRUCTURED ? "unstructured" : "other");
        /* The flag is hit every frame, at a depth that follows the wave. */
        float expected = 6.0f - 0.3f * sinf(3.0f * 3.9f - 4.0f * t) * 3.9f / 4.0f;
        ok = ok && hit.object == flag && fabsf(hit.t - expected) < 0.02f;
        ok = ok && !(hit.t == previous);
        previous = hit.t;
    }
    ok = ok && rtGetError() == RT_NO_ERROR;
    rtDestroyContext(context);
    printf("tutorial03: %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
