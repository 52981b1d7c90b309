/* SPDX-License-Identifier: Apache-2.0 */
/*
 * isa_images.c - images and ray answers bit for bit across the traversal
 * ISA tables, hence across layouts (scalar: the binary walk; sse4: the
 * 4-wide walk; avx2, avx512: the 8-wide walk; lib/trace/kernels.h), and
 * across thread counts.
 *
 * One scene (a sphere with smooth normals, a grid-snapped triangle soup
 * with shared planes and slivers, a floor with a mipmapped texture, a
 * wall of small and larger cells on three materials, and patches with
 * colours by vertex and flat quads, under seven instance matrices)
 * is rendered with eye light and Whitted shading (RGBA float) and
 * queried with 20,000 rays (rtTraceRays and rtOccludedRays) in a context
 * per configuration: "threads=1 isa=scalar" is the reference, every other
 * ISA this machine runs is tried with threads=1 and threads=3.  Every
 * float of every image and every hit record must equal the reference's
 * (memcmp); an ISA the CPU cannot run is skipped (rtCreateContext gives
 * NULL), so on an AVX2 machine the 4- and 8-wide layouts are both
 * compared with the binary one.
 *
 * Packets (lib/trace/packet_scene.h): every SIMD configuration runs with
 * packets=on (the default: camera rays in 4 x 2 blocks, coherent query
 * groups of eight) and packets=off, both against the same reference.
 * COHERENT more query rays follow the random ones, in groups of eight
 * that rtTraceRays takes as packets: camera rays from the eye, shadow
 * rays from the floor to a point light, rays aimed exactly at the
 * vertices and edge midpoints of an instanced sphere, rays grazing the
 * floor, and rays from 1e4 away; packets=on must do different node work
 * than packets=off on them (the packet path ran) with the same answers.
 * A third image, Whitted with a point light besides the sun (shadow rays
 * converging on a point as well as parallel ones), and a fourth with four
 * lights, two behind surfaces, are compared the same way, with their
 * RT_STAT_RAYS: with packets on, Whitted's shadow rays of each block go
 * as a packet per light (render/shade.h, shade_prime_shadows).  Two
 * eye-light images under projections loaded with rtLoadMatrixd (one whose
 * w varies by pixel, one with a camera multiplied in) check the camera
 * rays' row fill off rtFrustum's path (loaded_projections).
 */
#include <rt/rt.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brute_force.h"
#include "check.h"
#include "testutil.h"

#define WIDTH 96
#define HEIGHT 72
#define RANDOM_RAYS 20000
#define COHERENT 12000
#define RAYS (RANDOM_RAYS + COHERENT)

static uint64_t rng_state = 12345;

static float unit(void)
{
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return (float)(rng_state >> 40) * (1.0f / 16777216.0f);
}

/* Two triangles of the wall (object 4) on the quad of 0.5 x 0.45 at
 * (x0, y0): a gently curved surface with smooth normals, and texture
 * coordinates minified (several texels a pixel) and bent by vertex, so
 * that each triangle has its own level-of-detail part and the levels
 * matter in every lane.  With flat_st the second triangle's three
 * vertices take the coordinates of the quad's first corner: a triangle
 * without texture area, off lod_ray's common path (its lambda -inf, a
 * magnification), beside the first triangle's minification. */
static void wall_quad(float x0, float y0, int flat_st)
{
    static const int corner[6] = {0, 1, 3, 0, 3, 2};
    for (int k = 0; k < 6; k++) {
        const float x = x0 + 0.5f * (float)(corner[k] & 1);
        const float y = y0 + 0.45f * (float)(corner[k] >> 1);
        const float n[3] = {0.2f * sinf(x), 0.1f * cosf(y), 1.0f};
        const float sx = flat_st && k >= 3 ? x0 : x, sy = flat_st && k >= 3 ? y0 : y;
        rtNormal3fv(n);
        rtTexCoord2f(2.9f * sx + 0.6f * sinf(3.1f * sx + 1.7f * sy),
                     2.3f * sy + 0.4f * sx + 0.5f * cosf(2.3f * sx * sy));
        rtVertex3f(x, y, -4.0f + 0.3f * sinf(0.7f * x + y));
    }
}

/* A cell of the wall of 2 x 1.8 on one material with texture `texture`:
 * 4 x 4 of wall_quad's quads from (x0, y0). */
static void wall_cell(unsigned texture, float x0, float y0, int flat_st)
{
    rtBindTexture(RT_TEXTURE_2D, texture);
    rtEnable(RT_TEXTURE_2D);
    rtBegin(RT_TRIANGLES);
    for (int a = 0; a < 4; a++)
        for (int b = 0; b < 4; b++)
            wall_quad(x0 + 0.5f * (float)b, y0 + 0.45f * (float)a, flat_st);
    rtEnd();
    rtDisable(RT_TEXTURE_2D);
}

static void define_scene(void)
{
    rng_state = 777; /* the same soup in every context */
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    /* 1: a sphere, smooth normals. */
    rtNewObject(1);
    rtBegin(RT_TRIANGLES);
    const int slices = 24, stacks = 12;
    for (int i = 0; i < stacks; i++) {
        for (int j = 0; j < slices; j++) {
            float p[4][3];
            for (int c = 0; c < 4; c++) {
                int a = i + (c >> 1), b = j + (c & 1);
                float th = 3.14159265f * (float)a / (float)stacks;
                float ph = 6.2831853f * (float)b / (float)slices;
                p[c][0] = sinf(th) * cosf(ph);
                p[c][1] = cosf(th);
                p[c][2] = sinf(th) * sinf(ph);
            }
            static const int tri[6] = {0, 1, 2, 1, 3, 2};
            for (int k = 0; k < 6; k++) {
                rtNormal3fv(p[tri[k]]);
                rtVertex3fv(p[tri[k]]);
            }
        }
    }
    rtEnd();
    rtEndObject();
    /* 2: a grid-snapped soup: shared planes, coincident edges, slivers. */
    rtNewObject(2);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 0.5f);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < 3 * 600; i++) {
        float v[3];
        for (int k = 0; k < 3; k++)
            v[k] = roundf((unit() * 4.0f - 2.0f) * 4.0f) / 4.0f;
        rtVertex3fv(v);
    }
    rtEnd();
    rtEndObject();
    /* 3: a floor with a mipmapped noise texture, trilinear, repeated
     * along s and clamped to its edges along t: the eye light's levels of
     * detail and lookups, which the AVX2 shading copy computes in other
     * lanes (render/shade_eye_avx2.c), over the floor's whole range of
     * angles and distances. */
    static unsigned char noise[64 * 64 * 3];
    uint32_t bits = 2463534242u;
    for (int i = 0; i < 64 * 64 * 3; i++) {
        bits ^= bits << 13;
        bits ^= bits >> 17;
        bits ^= bits << 5;
        noise[i] = (unsigned char)(bits >> 24);
    }
    rtBindTexture(RT_TEXTURE_2D, 1);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 64, 64, 0, RT_RGB, RT_UNSIGNED_BYTE, noise);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_LINEAR_MIPMAP_LINEAR);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_LINEAR);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_WRAP_T, RT_CLAMP_TO_EDGE);
    rtNewObject(3);
    rtEnable(RT_TEXTURE_2D);
    rtBegin(RT_TRIANGLES);
    rtTexCoord2f(0, -2);
    rtVertex3f(-20, -2, -20);
    rtTexCoord2f(40, 6);
    rtVertex3f(20, -2, 20);
    rtTexCoord2f(40, -2);
    rtVertex3f(20, -2, -20);
    rtTexCoord2f(0, -2);
    rtVertex3f(-20, -2, -20);
    rtTexCoord2f(0, 6);
    rtVertex3f(-20, -2, 20);
    rtTexCoord2f(40, 6);
    rtVertex3f(20, -2, 20);
    rtEnd();
    rtDisable(RT_TEXTURE_2D);
    rtEndObject();
    /* 4: a wall of small cells (about three pixels), each of one of
     * three materials of the same emission: texture 1, no texture with
     * another diffuse colour, texture 2 (another size; smooth normals
     * across the wall); every eleventh cell with an emission of its own.
     * A 4 x 2 block of the eye light on it lies on several triangles of
     * two or three materials, which the AVX2 shading copy takes in lanes
     * where the emission and lighting agree (surface.c, fetch_lanes_mixed
     * and fetch_lanes_two) and hit by hit otherwise. */
    static unsigned char stripes[16 * 8 * 3];
    for (int i = 0; i < 16 * 8 * 3; i++)
        stripes[i] = (unsigned char)(i * 37 + (i / 48) * 101);
    rtBindTexture(RT_TEXTURE_2D, 2);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 16, 8, 0, RT_RGB, RT_UNSIGNED_BYTE, stripes);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_LINEAR_MIPMAP_LINEAR);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_LINEAR);
    rtNewObject(4);
    const float plain[4] = {0.3f, 0.6f, 0.2f, 1.0f}, grey[4] = {0.8f, 0.8f, 0.8f, 1.0f};
    const float dark[4] = {0.0f, 0.0f, 0.0f, 1.0f}, glow[4] = {0.2f, 0.1f, 0.0f, 1.0f};
    for (int i = 0; i < 14; i++) {
        for (int j = 0; j < 30; j++) {
            const int kind = (i + j) % 3;
            rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, kind == 1 ? plain : grey);
            rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, (i * 30 + j) % 11 ? dark : glow);
            if (kind != 1) {
                rtBindTexture(RT_TEXTURE_2D, kind == 0 ? 1u : 2u);
                rtEnable(RT_TEXTURE_2D);
            }
            rtBegin(RT_TRIANGLES);
            wall_quad(-7.5f + 0.5f * (float)j, -1.5f + 0.45f * (float)i, 0);
            rtEnd();
            rtDisable(RT_TEXTURE_2D);
        }
    }
    /* Above the wall, seven cells of 2 x 1.8 (some ten pixels), each of
     * one material (texture 1 and texture 2 in turn) and 4 x 4 quads: a
     * block there lies on several triangles of one material, which
     * fetch_lanes_mixed takes with each lane's level of detail from its
     * own triangle's part (the coordinates bent by vertex, so that the
     * parts differ).  Without them a fault in that choice passed this
     * test (round 58). */
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, dark);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, grey);
    for (int j = 0; j < 7; j++)
        wall_cell(j % 2 ? 2u : 1u, -7.5f + 2.0f * (float)j, 4.8f, 0);
    /* Left and right of the wall, two columns of four such cells whose
     * quads' second triangles have no texture area (wall_quad's
     * flat_st): a block there mixes lanes on lod_ray's common path with
     * lanes off it, which lod_quad_lanes gives lod_ray on their own
     * triangle's part.  A fault that took the quad's first lane's part
     * there changed the kitchen frame and passed this test (round 58). */
    for (int j = 0; j < 8; j++)
        wall_cell(j % 2 ? 2u : 1u, j < 4 ? -9.5f : 7.0f, -1.5f + 1.8f * (float)(j % 4), 1);
    rtEndObject();
    /* 5: two patches of 0.8 x 0.5, instanced twice in front of the
     * floor's lower edge (some 160 pixels each).  On the left a quad of
     * two triangles with a colour at each vertex and RT_COLOR_MATERIAL:
     * its ambient and diffuse colours vary by hit, so surface_fetch_lanes
     * takes its blocks hit by hit and keeps no colour in the triangle's
     * cache entry.  On the right 4 x 3 quads under RT_FLAT with a normal
     * of its own at each vertex: a block there lies on several
     * triangles, each lane with its own triangle's provoking normal
     * (fetch_lanes_mixed).  The second instance is turned about the x
     * axis only (its matrix's first column that of the identity): the
     * normals go through its matrix (lanes_shading_normal).  Faults in
     * each of these three passed this test (round 58). */
    rtNewObject(5);
    rtEnable(RT_COLOR_MATERIAL);
    rtBegin(RT_TRIANGLES);
    static const float quad5[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 6; k++) {
        const float a = quad5[k][0], b = quad5[k][1];
        rtColor3f(0.9f - 0.6f * a, 0.2f + 0.7f * b, 0.3f + 0.4f * a * b);
        rtNormal3f(0.1f * a, 0.2f, 1.0f);
        rtVertex3f(-0.8f + 0.8f * a, -0.25f + 0.5f * b, 0.0f);
    }
    rtEnd();
    rtDisable(RT_COLOR_MATERIAL);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, plain);
    rtShadeModel(RT_FLAT);
    rtBegin(RT_TRIANGLES);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            for (int k = 0; k < 6; k++) {
                const float x = 0.2f * ((float)j + quad5[k][0]);
                const float y = -0.25f + (0.5f / 3.0f) * ((float)i + quad5[k][1]);
                rtNormal3f(0.6f * sinf(9.0f * x + 5.0f * y), 0.5f * cosf(7.0f * y - 4.0f * x),
                           1.0f);
                rtVertex3f(x, y, 0.0f);
            }
    rtEnd();
    rtShadeModel(RT_SMOOTH);
    rtEndObject();

    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 100.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    const float sun[4] = {0.4f, 1.0f, 0.6f, 0.0f};
    rtLightfv(RT_LIGHT0, RT_POSITION, sun);
    rtEnable(RT_LIGHT0);
    rtViewport(0, 0, WIDTH, HEIGHT);
    rtBeginFrame();
    rtTranslatef(0.0f, 0.0f, -8.0f);
    rtPushMatrix();
    rtTranslatef(-2.0f, 0.0f, 0.0f);
    rtInstantiateObject(1);
    rtPopMatrix();
    rtPushMatrix();
    rtTranslatef(2.0f, 0.5f, -1.0f);
    rtRotatef(30.0f, 0.3f, 1.0f, 0.2f);
    rtScalef(1.0f, 2.0f, 0.5f);
    rtInstantiateObject(1);
    rtPopMatrix();
    rtPushMatrix();
    rtRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    rtInstantiateObject(2);
    rtPopMatrix();
    rtInstantiateObject(3);
    rtInstantiateObject(4);
    rtPushMatrix();
    rtTranslatef(-1.2f, -1.6f, 5.0f);
    rtInstantiateObject(5);
    rtTranslatef(2.4f, 0.0f, 0.0f);
    rtRotatef(35.0f, 1.0f, 0.0f, 0.0f);
    rtInstantiateObject(5);
    rtPopMatrix();
    rtLoadIdentity();
}

struct answers {
    float image[6][WIDTH * HEIGHT * 4];
    RThit hits[RAYS];
    RTboolean occluded[RAYS];
    /* RT_STAT_RAYS and RT_STAT_NODE_TESTS of the two frames, the trace
     * and the occlusion query, and of the Whitted frame with a point
     * light besides the sun, and with four lights. */
    RTint rays[6];
    RTint nodes[6];
};

static void stats(struct answers *out, int i)
{
    rtGetIntegerv(RT_STAT_RAYS, &out->rays[i]);
    rtGetIntegerv(RT_STAT_NODE_TESTS, &out->nodes[i]);
}

/* The coherent query rays, in groups of eight (a multiple of 8 per
 * kind, so that groups never straddle two kinds). */
static void coherent_rays(RTray *rays, int count)
{
    int n = 0;
    /* Camera rays from the eye, rows of a 100 x 30 grid. */
    for (int y = 0; y < 30 && n + 100 <= count; y++)
        for (int x = 0; x < 100; x++, n++) {
            RTray *r = &rays[n];
            r->org[0] = r->org[1] = r->org[2] = 0.0f;
            r->dir[0] = 0.8f * (2.0f * ((float)x + 0.5f) / 100.0f - 1.0f);
            r->dir[1] = 0.6f * (2.0f * ((float)y + 0.5f) / 30.0f - 1.0f);
            r->dir[2] = -1.0f;
            r->tmin = 0.0f;
            r->tmax = INFINITY;
        }
    /* Shadow rays from points of the floor to a point light. */
    const float light[3] = {3.0f, 6.0f, -4.0f};
    for (int z = 0; z < 40 && n + 80 <= count; z++)
        for (int x = 0; x < 80; x++, n++) {
            RTray *r = &rays[n];
            r->org[0] = -6.0f + 12.0f * (float)x / 80.0f;
            r->org[1] = -2.0f;
            r->org[2] = -14.0f + 12.0f * (float)z / 40.0f;
            for (int k = 0; k < 3; k++)
                r->dir[k] = light[k] - r->org[k];
            r->tmin = 1e-4f;
            r->tmax = 1.0f;
        }
    /* At the vertices and edge midpoints of the sphere instanced at
     * (-2, 0, -8), from the eye, neighbours in one group. */
    for (int i = 0; i <= 12; i++)
        for (int j = 0; j < 24; j++)
            for (int mid = 0; mid < 2 && n < count; mid++, n++) {
                const float b = (float)j + 0.5f * (float)mid;
                const float th = 3.14159265f * (float)i / 12.0f;
                const float ph = 6.2831853f * b / 24.0f;
                RTray *r = &rays[n];
                r->org[0] = r->org[1] = r->org[2] = 0.0f;
                r->dir[0] = sinf(th) * cosf(ph) - 2.0f;
                r->dir[1] = cosf(th);
                r->dir[2] = sinf(th) * sinf(ph) - 8.0f;
                r->tmin = 0.0f;
                r->tmax = INFINITY;
            }
    n = (n + 7) / 8 * 8;
    for (int i = 1; i < 8 && n - i >= 0 && n <= count; i++)
        if (rays[n - i].dir[2] == 0.0f && rays[n - i].dir[0] == 0.0f)
            rays[n - i] = rays[0];
    /* Grazing the floor: in its plane, or a hair above it. */
    for (int i = 0; i < 1000 && n < count; i++, n++) {
        RTray *r = &rays[n];
        r->org[0] = -5.0f + 10.0f * (float)(i % 200) / 200.0f;
        r->org[1] = -2.0f + (i / 200 == 1 ? 1e-6f : 0.0f);
        r->org[2] = 0.0f;
        r->dir[0] = 0.01f * (float)(i / 200);
        r->dir[1] = i / 200 == 2 ? -1e-7f : 0.0f;
        r->dir[2] = -1.0f;
        r->tmin = 0.0f;
        r->tmax = INFINITY;
    }
    /* From far away, towards the middle of the scene. */
    for (int i = 0; n < count; i++, n++) {
        RTray *r = &rays[n];
        r->org[0] = 1e4f + 0.5f * (float)(i % 8);
        r->org[1] = 5e3f;
        r->org[2] = 1e4f + 0.5f * (float)((i / 8) % 8);
        const float target[3] = {-3.0f + 6.0f * unit(), -2.0f + 4.0f * unit(), -8.0f};
        for (int k = 0; k < 3; k++)
            r->dir[k] = target[k] - r->org[k];
        if (i % 8)
            for (int k = 0; k < 3; k++)
                r->dir[k] = rays[n - 1].dir[k] * (1.0f + 1e-3f * (unit() - 0.5f));
        r->tmin = 0.0f;
        r->tmax = INFINITY;
    }
}

/* The test's frustum (define_scene's rtFrustum), column-major. */
static void test_frustum(double m[16])
{
    bf_frustum(m, -0.8, 0.8, -0.6, 0.6, 1.0, 100.0);
}

/* Two more eye-light frames under projections given by rtLoadMatrixd:
 * the frustum after a clip-space map that adds 0.06 x - 0.04 y to w, so
 * that each pixel's w differs (the SIMD copies' row fill divides by each
 * point's w, render.c), and the frustum with a camera multiplied in (a
 * turn of 7 degrees about a tilted axis and a shift, as BART's scenes
 * load the view), whose inverse's w row has x and y terms of rounding
 * size (w the same double for every pixel when they are small enough:
 * render.c's unproject_w_known, the quotients then without the
 * divider). */
static void loaded_projections(struct answers *out)
{
    double p[16], m[16];
    test_frustum(p);
    const double skew[16] = {1, 0, 0, 0.06, 0, 1, 0, -0.04, 0, 0, 1, 0, 0, 0, 0, 1};
    bf_mul(m, skew, p);
    rtShadingMode(RT_EYE_LIGHT);
    rtMatrixMode(RT_PROJECTION);
    rtLoadMatrixd(m);
    rtRenderFrame();
    rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, out->image[4]);
    double ax[3] = {0.3, 1.0, 0.2};
    const double len = sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
    for (int k = 0; k < 3; k++)
        ax[k] /= len;
    double view[16];
    bf_rotation(view, 7.0 * 3.14159265358979323846 / 180.0, ax);
    view[12] = 0.3;
    view[13] = -0.2;
    view[14] = 0.5;
    bf_mul(m, p, view);
    rtLoadMatrixd(m);
    rtRenderFrame();
    rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, out->image[5]);
    rtLoadIdentity();
    rtFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 100.0);
    rtMatrixMode(RT_MODELVIEW);
}

static int run(const char *config, const RTray *rays, struct answers *out)
{
    RTcontext ctx = rtCreateContext(config);
    if (!ctx)
        return 0;
    rtMakeCurrent(ctx);
    define_scene();
    static const RTenum modes[2] = {RT_EYE_LIGHT, RT_WHITTED};
    for (int m = 0; m < 2; m++) {
        rtShadingMode(modes[m]);
        rtRenderFrame();
        stats(out, m);
        rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, out->image[m]);
    }
    rtTraceRays(RAYS, rays, out->hits);
    stats(out, 2);
    rtOccludedRays(RAYS, rays, out->occluded);
    stats(out, 3);
    /* Whitted again with a point light above the scene as well: shadow
     * rays converging on a point besides the sun's parallel ones. */
    const float lamp[4] = {1.0f, 6.0f, -5.0f, 1.0f};
    rtLightfv(RT_LIGHT1, RT_POSITION, lamp);
    rtEnable(RT_LIGHT1);
    rtShadingMode(RT_WHITTED);
    rtRenderFrame();
    stats(out, 4);
    rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, out->image[2]);
    /* Four lights, two of them behind surfaces: one under the floor
     * (the floor faces away from it: no shadow ray there) and one inside
     * the left sphere (its outside faces away, everything else is
     * shadowed by it), a third given with w = 2 (a divided position).
     * Whitted's shadow rays of a block go as one packet per light
     * (shade_prime_shadows), with lanes left out where the surface faces
     * away or the hit is unlit. */
    const float under[4] = {0.5f, -6.0f, -8.0f, 1.0f};
    const float inside[4] = {-2.0f, 0.1f, -8.0f, 1.0f};
    const float halved[4] = {-6.0f, 8.0f, -4.0f, 2.0f};
    rtLightfv(RT_LIGHT2, RT_POSITION, under);
    rtEnable(RT_LIGHT2);
    rtLightfv(RT_LIGHT3, RT_POSITION, inside);
    rtEnable(RT_LIGHT3);
    rtLightfv(RT_LIGHT1, RT_POSITION, halved);
    rtRenderFrame();
    stats(out, 5);
    rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_FLOAT, out->image[3]);
    loaded_projections(out);
    CHECK_NO_ERR();
    rtMakeCurrent(NULL);
    rtDestroyContext(ctx);
    return 1;
}

int main(void)
{
    tu_section("isa_images");
    RTray *rays = malloc(RAYS * sizeof(*rays));
    struct answers *ref = malloc(sizeof(*ref));
    struct answers *got = malloc(sizeof(*got));
    if (!rays || !ref || !got)
        return 1;
    for (int i = 0; i < RANDOM_RAYS; i++) {
        for (int k = 0; k < 3; k++) {
            rays[i].org[k] = unit() * 6.0f - 3.0f;
            rays[i].dir[k] = unit() * 2.0f - 1.0f;
        }
        rays[i].org[2] += (i & 1) ? 0.0f : -8.0f;
        if (i % 5 == 0)
            rays[i].dir[i % 3] = 0.0f; /* axis-parallel components */
        if (rays[i].dir[0] == 0.0f && rays[i].dir[1] == 0.0f && rays[i].dir[2] == 0.0f)
            rays[i].dir[2] = -1.0f;
        rays[i].tmin = 0.0f;
        rays[i].tmax = (i % 7 == 0) ? 3.0f : INFINITY;
    }
    coherent_rays(rays + RANDOM_RAYS, COHERENT);
    CHECK(run("threads=1 isa=scalar", rays, ref));
    /* The comparison means something only if the scene is hit. */
    int hit_count = 0, coherent_hits = 0, coherent_occluded = 0;
    for (int i = 0; i < RAYS; i++) {
        hit_count += ref->hits[i].t < INFINITY;
        coherent_hits += i >= RANDOM_RAYS && ref->hits[i].t < INFINITY;
        coherent_occluded += i >= RANDOM_RAYS && ref->occluded[i];
    }
    printf("  reference: %d of %d rays hit (%d of the %d coherent ones; %d occluded)\n",
           hit_count, RAYS, coherent_hits, COHERENT, coherent_occluded);
    CHECK(hit_count > RAYS / 10);
    /* The loaded projections took effect: their frames differ from the
     * rtFrustum frame and from each other. */
    CHECK(memcmp(ref->image[4], ref->image[0], sizeof(ref->image[0])) != 0);
    CHECK(memcmp(ref->image[5], ref->image[0], sizeof(ref->image[0])) != 0);
    CHECK(memcmp(ref->image[5], ref->image[4], sizeof(ref->image[0])) != 0);
    CHECK(coherent_hits > COHERENT / 4 && coherent_occluded > COHERENT / 20);
    static const char *const configs[] = {
        "threads=1 isa=sse4",  "threads=3 isa=sse4",   "threads=1 isa=avx2",
        "threads=3 isa=avx2",  "threads=1 isa=avx512", "threads=3 isa=avx512",
        "threads=3 isa=scalar", "threads=1 isa=sse4 packets=off",
        "threads=2 isa=sse4 packets=off", "threads=1 isa=avx2 packets=off",
        "threads=2 isa=avx2 packets=off", "threads=2 isa=avx2 packets=on",
        "threads=1 isa=avx512 packets=off"};
    /* Node tests of the packets=on run of each ISA, threads=1 (the
     * entry before its packets=off one). */
    RTint packet_nodes[8][6];
    int have_packet_nodes[8] = {0};
    for (size_t c = 0; c < sizeof(configs) / sizeof(configs[0]); c++) {
        if (!run(configs[c], rays, got)) {
            printf("  %s: not runnable here, skipped\n", configs[c]);
            continue;
        }
        CHECKF(memcmp(ref->rays, got->rays, sizeof(ref->rays)) == 0,
               "%s: RT_STAT_RAYS %d %d %d %d %d %d, reference %d %d %d %d %d %d", configs[c],
               got->rays[0], got->rays[1], got->rays[2], got->rays[3], got->rays[4],
               got->rays[5], ref->rays[0], ref->rays[1], ref->rays[2], ref->rays[3],
               ref->rays[4], ref->rays[5]);
        const int isa = strstr(configs[c], "sse4") ? 1 : strstr(configs[c], "avx2") ? 2 : 3;
        if (strstr(configs[c], "threads=1") && !strstr(configs[c], "packets=")) {
            memcpy(packet_nodes[isa], got->nodes, sizeof(got->nodes));
            have_packet_nodes[isa] = 1;
        }
        if (strstr(configs[c], "threads=1") && strstr(configs[c], "packets=off") &&
            have_packet_nodes[isa]) {
            /* Different work, same answers: the packet path ran for the
             * frame and the coherent closest-hit queries.  (Any-hit
             * packets of one octant visit exactly the single rays'
             * nodes: same order, no culling by a closest hit.) */
            CHECKF(packet_nodes[isa][0] != got->nodes[0] &&
                       packet_nodes[isa][2] != got->nodes[2],
                   "%s: node tests %d %d equal packets=on's: no packet ran", configs[c],
                   got->nodes[0], got->nodes[2]);
            printf("  %s: node tests eye light %d, trace %d, occluded %d; packets=on: %d, %d, "
                   "%d\n",
                   configs[c], got->nodes[0], got->nodes[2], got->nodes[3],
                   packet_nodes[isa][0], packet_nodes[isa][2], packet_nodes[isa][3]);
        }
        int same_images = memcmp(ref->image, got->image, sizeof(ref->image)) == 0;
        int same_hits = memcmp(ref->hits, got->hits, sizeof(ref->hits)) == 0;
        int same_occ = memcmp(ref->occluded, got->occluded, sizeof(ref->occluded)) == 0;
        CHECKF(same_images && same_hits && same_occ,
               "%s: images %s, hits %s, occlusion %s (against threads=1 isa=scalar)", configs[c],
               same_images ? "same" : "DIFFER", same_hits ? "same" : "DIFFER",
               same_occ ? "same" : "DIFFER");
        printf("  %s: images, hits and occlusion bit-identical to threads=1 isa=scalar\n",
               configs[c]);
    }
    free(rays);
    free(ref);
    free(got);
    return test_summary("isa_images");
}
