/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Tutorial 2: objects and instances (docs/tutorials/02-instances.md).
 *
 * One object (a unit cube from a vertex array and rtDrawElements), placed
 * many times under different modelview matrices, like calling one display
 * list under glTranslate/glRotate.  Each instance shares the object's
 * geometry and acceleration structure; a hit says which instance (position
 * in the frame's list), which object and which triangle was hit.
 */
#include <rt/rt.h>

#include <math.h>
#include <stdio.h>

#define GRID 5 /* GRID x GRID cubes */

static void define_cube(RTuint name)
{
    static const float corners[8][3] = {{-0.5f, -0.5f, -0.5f}, {0.5f, -0.5f, -0.5f},
                                        {0.5f, 0.5f, -0.5f},   {-0.5f, 0.5f, -0.5f},
                                        {-0.5f, -0.5f, 0.5f},  {0.5f, -0.5f, 0.5f},
                                        {0.5f, 0.5f, 0.5f},    {-0.5f, 0.5f, 0.5f}};
    static const unsigned short quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                               {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    rtNewObject(name);
    rtEnableClientState(RT_VERTEX_ARRAY);
    rtVertexPointer(3, RT_FLOAT, 0, corners);
    rtDrawElements(RT_QUADS, 24, RT_UNSIGNED_SHORT, quads);
    rtDisableClientState(RT_VERTEX_ARRAY);
    rtEndObject();
}

int main(void)
{
    RTcontext context = rtCreateContext("threads=2");
    if (context == NULL || !rtMakeCurrent(context)) {
        fprintf(stderr, "tutorial02: cannot create a context\n");
        return 1;
    }
    RTuint cube;
    rtGenObjects(1, &cube); /* like glGenLists */
    define_cube(cube);

    /* A GRID x GRID field of cubes at z = -10, each turned a little more. */
    rtMatrixMode(RT_MODELVIEW);
    for (int i = 0; i < GRID * GRID; i++) {
        rtPushMatrix();
        rtTranslatef((float)(i % GRID) * 2.0f - (GRID - 1), (float)(i / GRID) * 2.0f - (GRID - 1),
                     -10.0f);
        rtRotatef(9.0f * (float)i, 0.0f, 1.0f, 0.0f);
        rtInstantiateObject(cube);
        rtPopMatrix();
    }

    /* One ray down the middle of every cube: each hits its own instance at
     * the cube's front face (the rotation about y keeps the centre line
     * inside the cube). */
    RTray rays[GRID * GRID];
    RThit hits[GRID * GRID];
    for (int i = 0; i < GRID * GRID; i++) {
        RTray r = {{(float)(i % GRID) * 2.0f - (GRID - 1), (float)(i / GRID) * 2.0f - (GRID - 1),
                    0.0f},
                   0.0f,
                   {0.0f, 0.0f, -1.0f},
                   INFINITY};
        rays[i] = r;
    }
    rtTraceRays(GRID * GRID, rays, hits);

    int ok = rtGetError() == RT_NO_ERROR;
    for (int i = 0; i < GRID * GRID; i++) {
        printf("ray %2d: instance %2u object %u triangle %2u t = %.3f\n", i, hits[i].instance,
               hits[i].object, hits[i].primitive, (double)hits[i].t);
        ok = ok && hits[i].instance == (RTuint)i && hits[i].object == cube &&
             hits[i].t > 9.2f && hits[i].t < 9.51f;
    }
    RTint instances = 0, triangles = 0;
    rtGetIntegerv(RT_INSTANCE_COUNT, &instances);
    rtGetObjectiv(cube, RT_OBJECT_TRIANGLES, &triangles);
    printf("%d instances of one object of %d triangles\n", instances, triangles);
    ok = ok && instances == GRID * GRID && triangles == 12;

    rtDestroyContext(context);
    printf("tutorial02: %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
