/* SPDX-License-Identifier: Apache-2.0 */
/*
 * wire_render.c - the GLUT wire shapes rendered: each wire shape recorded
 * into an object draws without error, covers pixels along its edges and
 * leaves its faces' insides empty (unlike its solid).  Needs the core's
 * line primitives (another branch): registered DISABLED until they are
 * merged (conformance/CMakeLists.txt).
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include "testutil.h"

#define W 96
#define H 96

static unsigned char image[W * H * 4];

static int covered(int x, int y)
{
    const unsigned char *p = image + 4 * (y * W + x);
    return p[0] || p[1] || p[2];
}

static int render(void (*shape)(void))
{
    int x, y, n = 0;
    rtNewObject(1);
    shape();
    rtEndObject();
    rtBeginFrame();
    rtInstantiateObject(1);
    rtRenderFrame();
    rtReadPixels(0, 0, W, H, RT_RGBA, RT_UNSIGNED_BYTE, image);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            n += covered(x, y);
    return n;
}

static void wire_cube(void) { rtuWireCube(1.0); }
static void solid_cube(void) { rtuSolidCube(1.0); }
static void wire_sphere(void) { rtuWireSphere(0.8, 10, 6); }
static void wire_torus(void) { rtuWireTorus(0.2, 0.6, 8, 12); }
static void wire_teapot(void) { rtuWireTeapot(0.5); }
static void wire_icosahedron(void) { rtuWireIcosahedron(); }

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    int wire, solid;
    rtViewport(0, 0, W, H);
    rtMatrixMode(RT_PROJECTION);
    rtOrtho(-1.2, 1.2, -1.2, 1.2, -5, 5);
    rtMatrixMode(RT_MODELVIEW);
    /* The cube face on: its outline is the square's border, the inside
     * (the centre pixel) is empty. */
    wire = render(wire_cube);
    CHECK_NO_ERR();
    CHECK(wire > 0 && !covered(W / 2, H / 2));
    solid = render(solid_cube);
    CHECK(covered(W / 2, H / 2) && solid > 2 * wire);
    CHECK(render(wire_sphere) > 0);
    CHECK(render(wire_torus) > 0);
    CHECK(render(wire_teapot) > 0);
    rtScaled(0.8, 0.8, 0.8);
    CHECK(render(wire_icosahedron) > 0);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
    return test_summary("glut/wire_render");
}
