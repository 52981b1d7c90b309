/* SPDX-License-Identifier: Apache-2.0 */
/*
 * texture_mipmap.c - conformance: mipmapped minification filters and the
 * ray-cone level of detail (docs/textures.md, "Mipmaps" and "Level of
 * detail").
 *
 * Texels are observed through rendered pixels.  Every textured surface
 * here has ambient 1, diffuse 0, emission 0 and global ambient 1, so a
 * pixel is exactly its texel in both shading modes (no light is enabled):
 * global_ambient * ambient * texel.
 *
 * The level of detail is pinned with a 64x64 checkerboard of 1-texel
 * checks (black, white): level 0 is the checkerboard and every level after
 * it is uniform 128/255 (each 2x2 box holds two of each).  Under
 * NEAREST_MIPMAP_LINEAR a pixel is then v0 + f (128/255 - v0), v0 the
 * level-0 texel (0 or 1) and f = frac(lambda) for 0 < lambda < 1, so the
 * pixel shows lambda itself.
 *
 * Reference: docs/textures.md.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define QUAD 600u
#define PLANE 601u
#define SMALL 602u
#define LARGE 603u
#define MIRROR 604u
#define FAR_QUAD 605u
#define TEX_CHECKER 610u
#define TEX_NOISE 611u

#define W 16
#define H 16
static float px[W * H * 4];

#define HW 96
#define HH 64
static float horizon_px[HW * HH * 4];

static const float black[4] = {0, 0, 0, 1};
static const float white[4] = {1, 1, 1, 1};
static const float grey128 = 128.0f / 255.0f;

static const float *pixel(int i, int j)
{
    return px + 4 * (j * W + i);
}

/* Ambient 1, diffuse 0, global ambient 1: a pixel is its texel. */
static void texel_material(void)
{
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, white);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, black);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 0.0f);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, white);
}

/* 64x64, 1-texel checks: texel (i, j) white when i + j is even. */
static void upload_checker(void)
{
    static unsigned char image[64 * 64 * 3];
    for (int j = 0; j < 64; j++)
        for (int i = 0; i < 64; i++)
            memset(&image[3 * (j * 64 + i)], (i + j) % 2 ? 0 : 255, 3);
    rtBindTexture(RT_TEXTURE_2D, TEX_CHECKER);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 64, 64, 0, RT_RGB, RT_UNSIGNED_BYTE, image);
}

/* 128x128 of fixed-seed noise, for comparisons where any detail shows. */
static void upload_noise(void)
{
    static unsigned char image[128 * 128 * 3];
    unsigned s = 2463534242u;
    for (int i = 0; i < 128 * 128 * 3; i++) {
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        image[i] = (unsigned char)(s >> 24);
    }
    rtBindTexture(RT_TEXTURE_2D, TEX_NOISE);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 128, 128, 0, RT_RGB, RT_UNSIGNED_BYTE, image);
}

static void set_filters(RTint min, RTint mag)
{
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, min);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, mag);
}

/* A quad in the plane z, x and y in [-r, r], texture coordinates from 0
 * to s1 along both, with the texture `tex` (recorded under the current
 * modelview matrix). */
static void define_quad(RTuint name, RTuint tex, float r, float z, float s1)
{
    rtBindTexture(RT_TEXTURE_2D, tex);
    rtNewObject(name);
    texel_material();
    rtEnable(RT_TEXTURE_2D);
    rtBegin(RT_QUADS);
    rtTexCoord2f(0, 0);
    rtVertex3f(-r, -r, z);
    rtTexCoord2f(s1, 0);
    rtVertex3f(r, -r, z);
    rtTexCoord2f(s1, s1);
    rtVertex3f(r, r, z);
    rtTexCoord2f(0, s1);
    rtVertex3f(-r, r, z);
    rtEnd();
    rtDisable(RT_TEXTURE_2D);
    rtEndObject();
}

static void render(RTuint name)
{
    CHECK(tu_scene1(name));
    tu_render_float(W, H, px);
    CHECK_NO_ERR();
}

static void frustum_camera(double l, double r, double b, double t, double n, double f)
{
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(l, r, b, t, n, f);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
}

/* The level-0 texel under pixel (i, j) of a quad covering the view with
 * texture coordinates 0 .. s1 on the checkerboard: 1 or 0. */
static float checker_texel(int i, int j, float s1)
{
    int u = (int)floor((i + 0.5) / W * s1 * 64.0);
    int v = (int)floor((j + 0.5) / H * s1 * 64.0);
    return (u + v) % 2 ? 0.0f : 1.0f;
}

/* ---- parameters ------------------------------------------------------------ */

static void parameters(void)
{
    static const RTint mip[4] = {RT_NEAREST_MIPMAP_NEAREST, RT_LINEAR_MIPMAP_NEAREST,
                                 RT_NEAREST_MIPMAP_LINEAR, RT_LINEAR_MIPMAP_LINEAR};
    tu_section("mipmapped filters: MIN_FILTER only (GL's values)");
    CHECK_INT(RT_NEAREST_MIPMAP_NEAREST, 0x2700);
    CHECK_INT(RT_LINEAR_MIPMAP_NEAREST, 0x2701);
    CHECK_INT(RT_NEAREST_MIPMAP_LINEAR, 0x2702);
    CHECK_INT(RT_LINEAR_MIPMAP_LINEAR, 0x2703);
    tu_ortho_camera();
    upload_checker();
    /* The initial MIN_FILTER is RT_LINEAR, level 0 only: 3.5 texels a
     * pixel (lambda = 1.8) alias into a pattern of greys, where a
     * mipmapped filter would give uniform 128/255. */
    define_quad(QUAD, TEX_CHECKER, 1, -5, 0.875f);
    render(QUAD);
    {
        float lo = 1.0f, hi = 0.0f;
        for (int i = 0; i < W; i++) {
            lo = fminf(lo, pixel(i, 7)[0]);
            hi = fmaxf(hi, pixel(i, 7)[0]);
        }
        CHECK(hi - lo > 0.2f); /* 0.375 and 0.625 alternate */
    }
    set_filters(RT_NEAREST, RT_NEAREST);
    /* 4 texels a pixel (lambda = 2): the filters decide what shows. */
    define_quad(QUAD, TEX_CHECKER, 1, -5, 1);
    for (int k = 0; k < 4; k++) {
        rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, mip[k]);
        CHECK_NO_ERR();
        render(QUAD);
        /* Levels 1 .. are uniform 128: lambda = 2 reads one of them. */
        CHECK_NEAR(pixel(5, 9)[0], grey128, 1e-6);
        /* Not a magnification filter: RT_INVALID_ENUM, nothing changes
         * (a MAG filter is only used at lambda <= 0: the quad would still
         * look the same, so the filter is checked on a close-up below). */
        rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, mip[k]);
        CHECK_ERR(RT_INVALID_ENUM);
        CHECK_MSG("rtTexParameteri");
    }
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, 0x2704);
    CHECK_ERR(RT_INVALID_ENUM);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_CLAMP_TO_EDGE);
    CHECK_ERR(RT_INVALID_ENUM);
    render(QUAD);
    CHECK_NEAR(pixel(5, 9)[0], grey128, 1e-6);
    /* The failed MAG calls left NEAREST: a magnified close-up shows whole
     * texels (s from 0 to 1/8: 8 x 8 texels over 16 x 16 pixels). */
    define_quad(QUAD, TEX_CHECKER, 1, -5, 0.125f);
    render(QUAD);
    CHECK(pixel(0, 0)[0] == 1.0f && pixel(1, 0)[0] == 1.0f && pixel(2, 0)[0] == 0.0f);

    tu_section("rtTexImage2D: a level > 0 of another size than the chain's is refused");
    {
        static const unsigned char red[3] = {255, 0, 0};
        rtTexImage2D(RT_TEXTURE_2D, 1, RT_RGB, 1, 1, 0, RT_RGB, RT_UNSIGNED_BYTE, red);
        CHECK_ERR(RT_INVALID_VALUE);
        CHECK_MSG("rtTexImage2D");
        render(QUAD);
        CHECK(pixel(0, 0)[0] == 1.0f && pixel(2, 0)[0] == 0.0f);
    }
    tu_section("rtTexImage2D: a level k > 0 of the chain's size replaces level k");
    {
        static unsigned char blue[32 * 32 * 3];
        static const unsigned char red[3] = {255, 0, 0};
        for (int i = 0; i < 32 * 32; i++)
            blue[3 * i + 2] = 255;
        rtBindTexture(RT_TEXTURE_2D, TEX_CHECKER);
        rtTexImage2D(RT_TEXTURE_2D, 1, RT_RGB, 32, 32, 0, RT_RGB, RT_UNSIGNED_BYTE, blue);
        CHECK_NO_ERR();
        rtTexImage2D(RT_TEXTURE_2D, 6, RT_RGB, 1, 1, 0, RT_RGB, RT_UNSIGNED_BYTE, red);
        CHECK_NO_ERR();
        set_filters(RT_NEAREST_MIPMAP_NEAREST, RT_NEAREST);
        /* 2 texels a pixel, lambda = 1: level 1, the uploaded one. */
        define_quad(QUAD, TEX_CHECKER, 1, -5, 0.5f);
        render(QUAD);
        CHECK(pixel(5, 9)[0] == 0.0f && pixel(5, 9)[1] == 0.0f && pixel(5, 9)[2] == 1.0f);
        /* 4 texels a pixel, lambda = 2: level 2, still made from level 0. */
        define_quad(QUAD, TEX_CHECKER, 1, -5, 1);
        render(QUAD);
        CHECK_NEAR(pixel(5, 9)[0], grey128, 1e-6);
        CHECK_NEAR(pixel(5, 9)[2], grey128, 1e-6);
        /* 64 texels a pixel, lambda = 6: the last level, uploaded red. */
        define_quad(QUAD, TEX_CHECKER, 1, -5, 16);
        render(QUAD);
        CHECK(pixel(5, 9)[0] == 1.0f && pixel(5, 9)[2] == 0.0f);
        /* Beyond the chain (64x64 has levels 0 .. 6): refused. */
        rtTexImage2D(RT_TEXTURE_2D, 7, RT_RGB, 1, 1, 0, RT_RGB, RT_UNSIGNED_BYTE, red);
        CHECK_ERR(RT_INVALID_VALUE);
        /* Level 0 again makes the whole chain again. */
        upload_checker();
        define_quad(QUAD, TEX_CHECKER, 1, -5, 0.5f);
        render(QUAD);
        CHECK_NEAR(pixel(5, 9)[2], grey128, 1e-6);
        /* A level before level 0: refused (GL would keep it for later). */
        rtBindTexture(RT_TEXTURE_2D, TEX_CHECKER + 100);
        rtTexImage2D(RT_TEXTURE_2D, 1, RT_RGB, 1, 1, 0, RT_RGB, RT_UNSIGNED_BYTE, red);
        CHECK_ERR(RT_INVALID_VALUE);
        rtBindTexture(RT_TEXTURE_2D, TEX_CHECKER);
    }
    tu_section("lambda of a texture stretched one way: the denser direction, as GL's rho");
    {
        static unsigned char blue[32 * 32 * 3], red[16 * 16 * 3];
        for (int i = 0; i < 32 * 32; i++)
            blue[3 * i + 2] = 255;
        for (int i = 0; i < 16 * 16; i++)
            red[3 * i] = 255;
        rtBindTexture(RT_TEXTURE_2D, TEX_CHECKER);
        rtTexImage2D(RT_TEXTURE_2D, 1, RT_RGB, 32, 32, 0, RT_RGB, RT_UNSIGNED_BYTE, blue);
        rtTexImage2D(RT_TEXTURE_2D, 2, RT_RGB, 16, 16, 0, RT_RGB, RT_UNSIGNED_BYTE, red);
        set_filters(RT_NEAREST_MIPMAP_NEAREST, RT_NEAREST);
        /* 1 texel a pixel across (s to 0.25), 4 along (t to 1): GL's rho
         * is 4, lambda 2, level 2 (red); the two directions' geometric
         * mean, 2 texels, would give level 1 (blue). */
        rtNewObject(QUAD);
        texel_material();
        rtEnable(RT_TEXTURE_2D);
        rtBegin(RT_QUADS);
        rtTexCoord2f(0, 0);
        rtVertex3f(-1, -1, -5);
        rtTexCoord2f(0.25f, 0);
        rtVertex3f(1, -1, -5);
        rtTexCoord2f(0.25f, 1);
        rtVertex3f(1, 1, -5);
        rtTexCoord2f(0, 1);
        rtVertex3f(-1, 1, -5);
        rtEnd();
        rtDisable(RT_TEXTURE_2D);
        rtEndObject();
        render(QUAD);
        CHECK(pixel(5, 9)[0] == 1.0f && pixel(5, 9)[2] == 0.0f);
        CHECK(pixel(12, 3)[0] == 1.0f && pixel(12, 3)[2] == 0.0f);
        upload_checker();
    }
    set_filters(RT_LINEAR, RT_LINEAR);
    CHECK_NO_ERR();
}

/* ---- the level of detail ----------------------------------------------------- */

/* Checks pixels (i0 .. i1 - 1, j0 .. j1 - 1) of the checkerboard quad (s
 * from 0 to s1) against v0 + f (128/255 - v0); tol absorbs the lambda of
 * off-axis pixels. */
static void check_fraction(float s1, float f, float tol, int i0, int i1, int j0, int j1)
{
    int bad = 0;
    for (int j = j0; j < j1; j++)
        for (int i = i0; i < i1; i++) {
            float v0 = checker_texel(i, j, s1);
            float e = v0 + f * (grey128 - v0);
            if (!(fabsf(pixel(i, j)[0] - e) <= tol)) {
                if (!bad)
                    fprintf(stderr, "    pixel (%d, %d) is %.6f, expected %.6f\n", i, j,
                            pixel(i, j)[0], e);
                bad++;
            }
        }
    CHECK(bad == 0);
}

/* frac(lambda) at pixel (i, j) under NEAREST_MIPMAP_LINEAR on the
 * checkerboard, for 0 < lambda < 1, whatever the level-0 texel. */
static float fraction_at(int i, int j)
{
    float p = pixel(i, j)[0];
    float v0 = p > grey128 ? 1.0f : 0.0f;
    return (p - v0) / (grey128 - v0);
}

static void level_of_detail(void)
{
    tu_section("lambda = log2(texels a pixel spans), orthographic");
    /* tu_ortho_camera: 2 x 2 world units over 16 x 16 pixels.  s from 0
     * to s1 puts 64 s1 texels over 16 pixels: 4 s1 texels a pixel. */
    tu_ortho_camera();
    upload_checker();
    set_filters(RT_NEAREST_MIPMAP_LINEAR, RT_NEAREST);
    define_quad(QUAD, TEX_CHECKER, 1, -5, 0.375f); /* 1.5 texels a pixel */
    render(QUAD);
    check_fraction(0.375f, (float)log2(1.5), 2e-4f, 0, W, 0, H);
    define_quad(QUAD, TEX_CHECKER, 1, -5, 0.3125f); /* 1.25 */
    render(QUAD);
    check_fraction(0.3125f, (float)log2(1.25), 2e-4f, 0, W, 0, H);
    /* Under a pixel a texel: a magnification, level 0 with NEAREST. */
    define_quad(QUAD, TEX_CHECKER, 1, -5, 0.125f);
    render(QUAD);
    check_fraction(0.125f, 0.0f, 0.0f, 0, W, 0, H);

    tu_section("lambda, perspective (rtFrustum)");
    /* Near plane 1, view [-1, 1]^2 there: at z = -2 the view is 4 x 4
     * world units, a pixel 1/4; a quad of half-size 2 at z = -2 with s to
     * s1 has 16 s1 texels a world unit, 4 s1 a pixel, as above.  The four
     * pixels around the axis look at it nearly head-on; further out the
     * isotropic cone overestimates the footprint across the tilt of the
     * ray by 1/cos (docs/textures.md). */
    frustum_camera(-1, 1, -1, 1, 1, 10);
    define_quad(QUAD, TEX_CHECKER, 2, -2, 0.375f);
    render(QUAD);
    check_fraction(0.375f, (float)log2(1.5), 3e-3f, 7, 9, 7, 9);
    /* An off-centre frustum with the far plane 1e4 away: the cone is
     * measured from the projection, not assumed symmetric.  The view at
     * z = -2 is x in [-1, 3]; the axis passes between columns 3 and 4. */
    frustum_camera(-0.5, 1.5, -1, 1, 1, 1e4);
    rtTranslatef(1, 0, 0);
    define_quad(QUAD, TEX_CHECKER, 2, -2, 0.375f);
    render(QUAD); /* instanced under the translation (a list's own matrix starts at identity) */
    rtLoadIdentity();
    check_fraction(0.375f, (float)log2(1.5), 3e-3f, 3, 5, 7, 9);
    /* 0.75 texels a pixel head-on: a magnification, level 0 exactly. */
    frustum_camera(-1, 1, -1, 1, 1, 10);
    define_quad(QUAD, TEX_CHECKER, 2, -2, 0.1875f);
    render(QUAD);
    check_fraction(0.1875f, 0.0f, 0.0f, 7, 9, 7, 9);
    /* Tilted 60 degrees about x: the footprint stretches by 1/|cos| = 2,
     * one level more: lambda = log2(0.75) + 1 = 0.58 at the centre, a
     * little more or less at the pixels around it (the plane's distance
     * changes across them). */
    rtTranslatef(0, 0, -2);
    rtRotatef(60, 1, 0, 0);
    rtTranslatef(0, 0, 2);
    define_quad(QUAD, TEX_CHECKER, 2, -2, 0.1875f);
    render(QUAD);
    rtLoadIdentity();
    for (int j = 7; j < 9; j++)
        for (int i = 7; i < 9; i++) {
            float f = fraction_at(i, j);
            if (!CHECK(f > 0.25f && f < 0.95f))
                fprintf(stderr, "    pixel (%d, %d): frac(lambda) %g\n", i, j, (double)f);
        }
    set_filters(RT_LINEAR, RT_LINEAR);
    CHECK_NO_ERR();
}

/* Mean |difference| of horizontal neighbours over rows j0 .. j1 - 1 of the
 * horizon image, and the mean value there. */
static void row_stats(int j0, int j1, double *mean_diff, double *mean)
{
    double d = 0.0, m = 0.0;
    int nd = 0, nm = 0;
    for (int j = j0; j < j1; j++)
        for (int i = 0; i < HW; i++) {
            const float *p = horizon_px + 4 * (j * HW + i);
            m += p[0];
            nm++;
            if (i + 1 < HW) {
                d += fabs((double)p[4] - p[0]);
                nd++;
            }
        }
    *mean_diff = d / nd;
    *mean = m / nm;
}

static void horizon(void)
{
    tu_section("a checkerboard plane to the horizon: mipmapping removes the aliasing");
    /* Eye 1 above the plane y = -1, looking along -z; the horizon is the
     * middle row.  20 texels a world unit (a check is 0.05 wide): beyond a
     * few units a pixel spans many checks. */
    frustum_camera(-0.15, 0.15, -0.1, 0.1, 0.1, 5000);
    upload_checker();
    rtBindTexture(RT_TEXTURE_2D, TEX_CHECKER);
    rtNewObject(PLANE);
    texel_material();
    rtEnable(RT_TEXTURE_2D);
    rtBegin(RT_QUADS);
    rtTexCoord2f(-312.5f, 0);
    rtVertex3f(-1000, -1, 0);
    rtTexCoord2f(312.5f, 0);
    rtVertex3f(1000, -1, 0);
    rtTexCoord2f(312.5f, 312.5f);
    rtVertex3f(1000, -1, -1000);
    rtTexCoord2f(-312.5f, 312.5f);
    rtVertex3f(-1000, -1, -1000);
    rtEnd();
    rtDisable(RT_TEXTURE_2D);
    rtEndObject();
    CHECK(tu_scene1(PLANE));
    rtShadingMode(RT_EYE_LIGHT);
    double diff_mip, mean_mip, diff_lin, mean_lin, diff_near_mip, mean_near_mip;
    set_filters(RT_LINEAR_MIPMAP_LINEAR, RT_LINEAR);
    tu_render_float(HW, HH, horizon_px);
    /* Rows 20 .. 31: the plane from 3 to 64 units away. */
    row_stats(20, 32, &diff_mip, &mean_mip);
    row_stats(0, 4, &diff_near_mip, &mean_near_mip);
    set_filters(RT_LINEAR, RT_LINEAR);
    tu_render_float(HW, HH, horizon_px);
    row_stats(20, 32, &diff_lin, &mean_lin);
    CHECK_NO_ERR();
    printf("far rows: mean |neighbour difference| %.4f mipmapped, %.4f LINEAR; mean %.4f, "
           "%.4f\n",
           diff_mip, diff_lin, mean_mip, mean_lin);
    /* Mipmapped: a smooth mid-grey. */
    CHECK(diff_mip < 0.02);
    CHECK_NEAR(mean_mip, 0.5, 0.02);
    /* LINEAR on level 0: the checks alias into noise and moire. */
    CHECK(diff_lin > 0.1);
    /* Near rows are magnified or barely minified: detail remains. */
    CHECK(diff_near_mip > 0.05);
}

/* ---- magnification is unchanged ------------------------------------------------- */

static void magnification(void)
{
    static float reference[W * H * 4];
    tu_section("magnification: the pixels of LINEAR, bit for bit");
    static const RTint mins[4] = {RT_NEAREST_MIPMAP_NEAREST, RT_LINEAR_MIPMAP_NEAREST,
                                  RT_NEAREST_MIPMAP_LINEAR, RT_LINEAR_MIPMAP_LINEAR};
    for (int persp = 0; persp < 2; persp++) {
        if (persp)
            frustum_camera(-1, 1, -1, 1, 1, 10);
        else
            tu_ortho_camera();
        /* 8 x 8 texels over the 16 x 16 view: lambda = -1; at most 1/4
         * texel a pixel in the perspective close-up too. */
        upload_noise();
        define_quad(QUAD, TEX_NOISE, persp ? 1.9f : 1.0f, persp ? -1.9f : -5.0f, 0.0625f);
        for (int mag = 0; mag < 2; mag++) {
            RTint m = mag ? RT_LINEAR : RT_NEAREST;
            set_filters(m, m);
            render(QUAD);
            memcpy(reference, px, sizeof(px));
            for (int k = 0; k < 4; k++) {
                rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, mins[k]);
                render(QUAD);
                CHECK(memcmp(reference, px, sizeof(px)) == 0);
            }
        }
    }
    set_filters(RT_LINEAR, RT_LINEAR);
    CHECK_NO_ERR();
}

/* ---- instances ------------------------------------------------------------------- */

static void instance_scale(void)
{
    static float large[W * H * 4], level0[W * H * 4];
    tu_section("an instance scaled 4x has the level of detail of the quad recorded 4x larger");
    frustum_camera(-0.25, 0.25, -0.25, 0.25, 1, 100);
    upload_noise();
    set_filters(RT_LINEAR_MIPMAP_LINEAR, RT_LINEAR);
    /* Half-size 1 and 4, texture coordinates 0 .. 1/4: 32 texels across
     * 2 or 8 world units, seen 20 units away (10 world units across the
     * view) and tilted: lambda from about 1 to 2, where the noise keeps
     * contrast and a level more or less would show. */
    define_quad(SMALL, TEX_NOISE, 1.0f, 0, 0.25f);
    define_quad(LARGE, TEX_NOISE, 4.0f, 0, 0.25f);
    rtBeginFrame();
    rtTranslatef(0, 0, -20);
    rtRotatef(50, 1, 0.3f, 0);
    rtScalef(4, 4, 4);
    rtInstantiateObject(SMALL);
    rtLoadIdentity();
    rtFinish();
    tu_render_float(W, H, px);
    rtBeginFrame();
    rtTranslatef(0, 0, -20);
    rtRotatef(50, 1, 0.3f, 0);
    rtInstantiateObject(LARGE);
    rtLoadIdentity();
    rtFinish();
    tu_render_float(W, H, large);
    CHECK_NO_ERR();
    int covered = 0, far_off = 0;
    float max_diff = 0.0f;
    for (int i = 0; i < W * H * 4; i += 4) {
        if (large[i + 3] == 0.0f)
            continue; /* the clear colour: a miss in both */
        covered++;
        for (int k = 0; k < 3; k++)
            max_diff = fmaxf(max_diff, fabsf(px[i + k] - large[i + k]));
    }
    printf("instance scaled 4x vs recorded 4x larger: max difference %.3g (%d covered pixels)\n",
           (double)max_diff, covered);
    CHECK(covered > W * H / 4);
    CHECK(max_diff <= 1.0f / 255.0f);
    /* And it is minified: level 0 alone looks different. */
    rtBindTexture(RT_TEXTURE_2D, TEX_NOISE);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_LINEAR);
    tu_render_float(W, H, level0);
    for (int i = 0; i < W * H * 4; i += 4)
        far_off += large[i + 3] != 0.0f && fabsf(level0[i] - large[i]) > 0.05f;
    CHECK(far_off > covered / 4);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_LINEAR_MIPMAP_LINEAR);
    CHECK_NO_ERR();
}

/* ---- reflections continue the cone ----------------------------------------------- */

static void reflection(void)
{
    static float direct[W * H * 4], level0[W * H * 4];
    tu_section("a mirror continues the cone: as far as the unfolded path");
    /* Eye at 0 looking along -z; a black mirror (reflectivity 1) at z = -5
     * and a textured quad behind the eye at z = +5: the mirror shows it as
     * the quad at z = -15 would look, 15 units along the path. */
    frustum_camera(-1, 1, -1, 1, 1, 100);
    upload_noise();
    set_filters(RT_LINEAR_MIPMAP_LINEAR, RT_LINEAR);
    /* 1 texel a world unit: at 15 units 1.9 texels a pixel. */
    define_quad(QUAD, TEX_NOISE, 16, 5, 0.25f);
    rtNewObject(MIRROR);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, black);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 1.0f);
    rtBegin(RT_QUADS);
    rtVertex3f(-20, -20, -5);
    rtVertex3f(20, -20, -5);
    rtVertex3f(20, 20, -5);
    rtVertex3f(-20, 20, -5);
    rtEnd();
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 0.0f);
    rtEndObject();
    rtShadingMode(RT_WHITTED);
    rtBeginFrame();
    rtInstantiateObject(MIRROR);
    rtInstantiateObject(QUAD);
    rtFinish();
    tu_render_float(W, H, px);
    define_quad(FAR_QUAD, TEX_NOISE, 16, -15, 0.25f);
    CHECK(tu_scene1(FAR_QUAD));
    tu_render_float(W, H, direct);
    rtBindTexture(RT_TEXTURE_2D, TEX_NOISE);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_LINEAR);
    tu_render_float(W, H, level0);
    rtShadingMode(RT_EYE_LIGHT);
    CHECK_NO_ERR();
    float max_diff = 0.0f;
    int far_off = 0;
    for (int i = 0; i < W * H * 4; i += 4) {
        for (int k = 0; k < 3; k++)
            max_diff = fmaxf(max_diff, fabsf(px[i + k] - direct[i + k]));
        far_off += fabsf(level0[i] - direct[i]) > 0.05f;
    }
    printf("mirror vs direct view: max difference %.3g\n", (double)max_diff);
    CHECK(max_diff <= 2.0f / 255.0f);
    CHECK(far_off > W * H / 4); /* and the quad is minified there */
    set_filters(RT_LINEAR, RT_LINEAR);
    CHECK_NO_ERR();
}

/* ---- the renderer's per-tile triangle cache ---------------------------------------- */

#define CW 64
#define CH 32

/* Instances A and B of one quad, side by side, rendered into `out`
 * (which: 1 A alone, 2 B alone, 3 both). */
static void cache_pair(int which, float *out)
{
    rtBeginFrame();
    if (which & 1) {
        rtTranslatef(-0.05f, 0, -20);
        rtRotatef(35, 0.3f, 1, 0);
        rtScalef(1.4f, 1.4f, 1.4f);
        rtInstantiateObject(SMALL);
        rtLoadIdentity();
    }
    if (which & 2) {
        rtTranslatef(2.45f, 0, -20);
        rtRotatef(-40, 0.2f, 1, 0);
        rtScalef(1.7f, 1.7f, 1.7f);
        rtInstantiateObject(SMALL);
        rtLoadIdentity();
    }
    rtFinish();
    tu_render_float(CW, CH, out);
    CHECK_NO_ERR();
}

/*
 * The renderer remembers what it derived from the last triangle a tile
 * shaded (its unit normal, the level of detail's edges: render/surface.h,
 * surface_cache).  Two instances of one quad have the same triangle
 * numbers under different matrices, and the pair meets inside a tile
 * (x = 40 of 64 pixels, tiles are 16 wide): every pixel of the pair must
 * be bit for bit the pixel of its instance rendered alone, in the
 * fixed-function mode (level of detail) and under the eye light (normal
 * and level of detail).  A cache keyed by the triangle number alone shades
 * B's first pixels with A's normal and level of detail.
 */
static void triangle_cache(void)
{
    static float a[CW * CH * 4], b[CW * CH * 4], both[CW * CH * 4];
    tu_section("two instances of one quad meeting inside a tile: each pixel as rendered alone");
    frustum_camera(-0.25, 0.25, -0.125, 0.125, 1, 100);
    upload_noise();
    set_filters(RT_LINEAR_MIPMAP_LINEAR, RT_LINEAR);
    define_quad(SMALL, TEX_NOISE, 1.0f, 0, 0.25f);
    const float half[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    for (int mode = 0; mode < 2; mode++) {
        rtShadingMode(mode ? RT_EYE_LIGHT : RT_FIXED_FUNCTION);
        if (mode) { /* the eye light's cosine shows the normal */
            rtNewObject(SMALL);
            rtBindTexture(RT_TEXTURE_2D, TEX_NOISE);
            texel_material();
            rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, half);
            rtEnable(RT_TEXTURE_2D);
            rtBegin(RT_QUADS);
            rtTexCoord2f(0, 0);
            rtVertex3f(-1, -1, 0);
            rtTexCoord2f(0.25f, 0);
            rtVertex3f(1, -1, 0);
            rtTexCoord2f(0.25f, 0.25f);
            rtVertex3f(1, 1, 0);
            rtTexCoord2f(0, 0.25f);
            rtVertex3f(-1, 1, 0);
            rtEnd();
            rtDisable(RT_TEXTURE_2D);
            rtEndObject();
        }
        cache_pair(1, a);
        cache_pair(2, b);
        cache_pair(3, both);
        int from_a = 0, from_b = 0, differ = 0, meet = 0;
        for (int j = 0; j < CH; j++)
            for (int i = 0; i < CW; i++) {
                const float *pa = &a[4 * (j * CW + i)], *pb = &b[4 * (j * CW + i)];
                const float *p = &both[4 * (j * CW + i)];
                const int in_a = pa[3] != 0.0f, in_b = pb[3] != 0.0f;
                if (in_a == in_b)
                    continue; /* neither, or both (not expected here) */
                from_a += in_a;
                from_b += in_b;
                differ += memcmp(p, in_a ? pa : pb, 4 * sizeof(float)) != 0;
                /* B right after A in a row of one tile (16 pixels wide) */
                meet += in_b && i % 16 && a[4 * (j * CW + i - 1) + 3] != 0.0f &&
                        b[4 * (j * CW + i - 1) + 3] == 0.0f;
            }
        printf("%s: %d pixels of A, %d of B, %d rows meeting inside a tile, %d differ\n",
               mode ? "eye light" : "fixed function", from_a, from_b, meet, differ);
        CHECK(from_a > CW * CH / 8 && from_b > CW * CH / 8);
        CHECK(meet >= 8);
        CHECK(differ == 0);
    }
    rtShadingMode(RT_FIXED_FUNCTION);
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    parameters();
    level_of_detail();
    horizon();
    magnification();
    instance_scale();
    reflection();
    triangle_cache();
    tu_destroy_context(ctx);
    return test_summary("texture_mipmap");
}
