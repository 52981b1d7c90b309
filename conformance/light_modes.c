/* SPDX-License-Identifier: Apache-2.0 */
/*
 * light_modes.c - GL's lighting switches in the eye-light and Whitted
 * modes (docs/appearance.md, "GL switches in the eye-light and Whitted
 * modes"): the global ambient is the one each primitive was drawn under,
 * as in RT_FIXED_FUNCTION; RT_LIGHTING is honoured per primitive once the
 * program has enabled it (an unlit primitive shows its colour), and a
 * program that never enabled it is lit as before; the lights themselves
 * are the ones current at rtRenderFrame in these modes (they cast
 * shadows across the whole scene), while RT_FIXED_FUNCTION lights each
 * primitive with the lights current at its draw.  The first three
 * sections fail against main before n-light, which took the global
 * ambient at rtRenderFrame and lit every surface in these modes.
 */
#include <math.h>

#include "testutil.h"

#define W 4
#define H 4

static float px[4 * W * H];

static const float *pixel(int x, int y)
{
    return &px[4 * (y * W + x)];
}

#define CHECK_RGB(p, r, g, b)                                                                 \
    CHECKF(fabsf((p)[0] - (r)) < 2e-3f && fabsf((p)[1] - (g)) < 2e-3f &&                      \
               fabsf((p)[2] - (b)) < 2e-3f,                                                   \
           "pixel (%g, %g, %g), expected (%g, %g, %g)", (double)(p)[0], (double)(p)[1],      \
           (double)(p)[2], (double)(r), (double)(g), (double)(b))

/* A square at z = -5 facing the camera over x in [x0, x0 + 1]. */
static void square(float x0)
{
    rtBegin(RT_QUADS);
    rtNormal3f(0, 0, 1);
    rtVertex3f(x0, -1, -5);
    rtVertex3f(x0 + 1, -1, -5);
    rtVertex3f(x0 + 1, 1, -5);
    rtVertex3f(x0, 1, -5);
    rtEnd();
}

/* A material that only the global ambient lights: ambient white, no
 * diffuse, specular or emission. */
static void ambient_only_material(void)
{
    static const float white[4] = {1, 1, 1, 1}, black[4] = {0, 0, 0, 1};
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, white);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
}

/* Immediate mode: the left square under one global ambient, the right
 * under another; both rendered in `mode` with no light enabled. */
static void ambient_between(RTenum mode)
{
    static const float dark[4] = {0.1f, 0.2f, 0.3f, 1}, bright[4] = {0.6f, 0.5f, 0.4f, 1};
    tu_section(mode == RT_WHITTED ? "Whitted: the global ambient per primitive"
                                  : "eye light: the global ambient per primitive");
    tu_ortho_camera();
    rtShadingMode(mode);
    rtDisable(RT_LIGHT0);
    ambient_only_material();
    rtClear(RT_COLOR_BUFFER_BIT);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, dark);
    square(-1);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, bright);
    square(0);
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 0.1f, 0.2f, 0.3f);
    CHECK_RGB(pixel(3, 1), 0.6f, 0.5f, 0.4f);
    /* In a list: the ambient at the call, for each call. */
    rtNewList(1, RT_COMPILE);
    square(-1);
    rtEndList();
    rtNewList(2, RT_COMPILE);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, dark);
    rtTranslatef(1, 0, 0);
    rtCallList(1);
    rtEndList();
    rtClear(RT_COLOR_BUFFER_BIT);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, bright);
    rtCallList(1); /* left, bright */
    rtCallList(2); /* right, dark (the list sets it) */
    tu_render_float(W, H, px);
    CHECK_RGB(pixel(0, 1), 0.6f, 0.5f, 0.4f);
    CHECK_RGB(pixel(3, 1), 0.1f, 0.2f, 0.3f);
    rtDeleteLists(1, 2);
    static const float initial[4] = {0.2f, 0.2f, 0.2f, 1};
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, initial);
    CHECK_NO_ERR();
}

/* RT_LIGHTING in a program that uses it: the left square lit, the right
 * one unlit, which shows its colour (red) as GL draws it. */
static void lighting_between(RTenum mode)
{
    static const float white[4] = {1, 1, 1, 1}, black[4] = {0, 0, 0, 1};
    tu_section(mode == RT_WHITTED ? "Whitted: RT_LIGHTING per primitive"
                                  : "eye light: RT_LIGHTING per primitive");
    tu_ortho_camera();
    rtShadingMode(mode);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, white);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, black);
    rtEnable(RT_LIGHT0); /* (0, 0, 1, 0): straight at the squares */
    rtClear(RT_COLOR_BUFFER_BIT);
    rtColor3f(1, 0, 0);
    rtEnable(RT_LIGHTING);
    square(-1);
    rtDisable(RT_LIGHTING);
    square(0);
    tu_render_float(W, H, px);
    /* Lit: the white diffuse material under a white light (or the eye
     * light) straight on, no ambient. */
    CHECK_RGB(pixel(0, 1), 1, 1, 1);
    CHECK_RGB(pixel(3, 1), 1, 0, 0);
    rtColor3f(1, 1, 1);
    CHECK_NO_ERR();
}

/* A program that never enabled RT_LIGHTING (a context of its own): the
 * eye-light and Whitted modes light every surface, as they always did. */
static void lighting_never_used(void)
{
    static const float white[4] = {1, 1, 1, 1}, black[4] = {0, 0, 0, 1};
    static const float none[4] = {0, 0, 0, 1};
    tu_section("RT_LIGHTING never enabled: every surface lit");
    RTcontext ctx = tu_make_context("threads=2");
    tu_ortho_camera();
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, none);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, white);
    rtEnable(RT_LIGHT0);
    const RTenum modes[2] = {RT_EYE_LIGHT, RT_WHITTED};
    for (int i = 0; i < 2; i++) {
        rtShadingMode(modes[i]);
        rtClear(RT_COLOR_BUFFER_BIT);
        rtColor3f(1, 0, 0);
        square(-1);
        tu_render_float(W, H, px);
        CHECK_RGB(pixel(0, 1), 1, 1, 1);
    }
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
}

/* Whitted lights with the lights current at rtRenderFrame (scene lights:
 * they cast shadows across the scene); RT_FIXED_FUNCTION with the lights
 * current at each primitive's draw. */
static void lights_at_render_in_whitted(void)
{
    static const float white[4] = {1, 1, 1, 1}, black[4] = {0, 0, 0, 1};
    static const float none[4] = {0, 0, 0, 1};
    tu_section("lights: at rtRenderFrame in Whitted, at the draw in RT_FIXED_FUNCTION");
    RTcontext ctx = tu_make_context("threads=2");
    tu_ortho_camera();
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, none);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, white);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, black);
    rtEnable(RT_LIGHTING);
    const RTenum modes[2] = {RT_WHITTED, RT_FIXED_FUNCTION};
    for (int i = 0; i < 2; i++) {
        rtShadingMode(modes[i]);
        rtClear(RT_COLOR_BUFFER_BIT);
        rtDisable(RT_LIGHT0);
        square(-1);
        rtEnable(RT_LIGHT0); /* after the left square, before the right */
        square(0);
        tu_render_float(W, H, px);
        if (modes[i] == RT_WHITTED)
            CHECK_RGB(pixel(0, 1), 1, 1, 1);
        else
            CHECK_RGB(pixel(0, 1), 0, 0, 0);
        CHECK_RGB(pixel(3, 1), 1, 1, 1);
    }
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    ambient_between(RT_EYE_LIGHT);
    ambient_between(RT_WHITTED);
    lighting_between(RT_EYE_LIGHT);
    lighting_between(RT_WHITTED);
    tu_destroy_context(ctx);
    lighting_never_used();
    lights_at_render_in_whitted();
    return test_summary("light_modes");
}
