/* SPDX-License-Identifier: Apache-2.0 */
/*
 * appearance.c - conformance: materials, lights, the light model, shading
 * modes and the ray-depth parameter.  Errors are checked at the call, and
 * their "changed nothing" half is observed in rendered pixels.
 *
 * Scenes are seen through an orthographic camera looking down -z; pixel
 * values are read back as floats.  Formulas (docs/appearance.md):
 *   eye light: emission + global_ambient * ambient + diffuse * |cos|
 *   Whitted:   emission + global_ambient * ambient + sum over enabled lights
 *              of attenuation * (La * ambient + Ld * diffuse * max(N.L, 0)
 *              + Ls * specular * max(N.H, 0)^shininess)   (= local)
 *              colour = (1 - transparency) * local
 *                       + reflectivity * reflected + transparency * refracted.
 *
 * Reference: docs/appearance.md.
 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>

#define OBJ 400u
#define OCC 401u
#define WALL 402u

#define W 16
#define H 16
static float px[W * H * 4];

static const float black[4] = {0, 0, 0, 1};

static RTint geti(RTenum pname)
{
    RTint v = -12345;
    rtGetIntegerv(pname, &v);
    return v;
}

/* GL's default material, set explicitly between tests. */
static void default_material(void)
{
    static const float amb[4] = {0.2f, 0.2f, 0.2f, 1}, dif[4] = {0.8f, 0.8f, 0.8f, 1},
                       spe[4] = {0, 0, 0, 1}, emi[4] = {0, 0, 0, 1};
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, amb);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, dif);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, spe);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, emi);
    rtMaterialf(RT_FRONT_AND_BACK, RT_SHININESS, 0);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 0);
    rtMaterialf(RT_FRONT_AND_BACK, RT_TRANSPARENCY, 0);
    rtMaterialf(RT_FRONT_AND_BACK, RT_INDEX_OF_REFRACTION, 1);
}

/* The Whitted section's materials: black diffuse and ambient, the given
 * emission, reflectivity and transparency.  Its objects set no material
 * of their own, so each takes the one current at rtInstantiateObject
 * (GL's glCallList semantics, docs/lists.md). */
static void whitted_material(const float emission[4], float reflectivity, float transparency)
{
    static const float black4[4] = {0, 0, 0, 1};
    default_material();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, black4);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black4);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, emission);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, reflectivity);
    rtMaterialf(RT_FRONT_AND_BACK, RT_TRANSPARENCY, transparency);
}

/* A camera-facing quad [-0.9, 0.9]^2 at depth z. */
static void define_facing_quad(RTuint name, float z)
{
    rtNewObject(name);
    rtBegin(RT_QUADS);
    rtVertex3f(-0.9f, -0.9f, z);
    rtVertex3f(0.9f, -0.9f, z);
    rtVertex3f(0.9f, 0.9f, z);
    rtVertex3f(-0.9f, 0.9f, z);
    rtEnd();
    rtEndObject();
}

static void render(void)
{
    tu_render_float(W, H, px);
}

static const float *pixel(int i, int j)
{
    return px + 4 * (j * W + i);
}

static int rgb_is(const char *file, int line, const float *p, float r, float g, float b)
{
    int ok = fabsf(p[0] - r) <= 0.01f && fabsf(p[1] - g) <= 0.01f && fabsf(p[2] - b) <= 0.01f;
    if (!tu_check(ok, file, line, "pixel colour"))
        fprintf(stderr, "    pixel (%g, %g, %g), expected (%g, %g, %g)\n", p[0], p[1], p[2], r,
                g, b);
    return ok;
}
#define CHECK_RGB(p, r, g, b) rgb_is(__FILE__, __LINE__, (p), (r), (g), (b))
#define CENTRE pixel(W / 2, H / 2)

static void render_quad(void)
{
    define_facing_quad(OBJ, -5);
    CHECK(tu_scene1(OBJ));
    render();
    CHECK_NO_ERR();
}

static void material_errors_and_defaults(void)
{
    static const float red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1};
    float bad[4] = {0, 0, 0, 1};
    tu_section("material defaults (eye light)");
    tu_ortho_camera();
    rtShadingMode(RT_EYE_LIGHT);
    /* Default material and light model: 0.2 * 0.2 + 0.8 * 1. */
    render_quad();
    CHECK_RGB(CENTRE, 0.84f, 0.84f, 0.84f);
    /* Pixels that miss show the clear colour. */
    CHECK_RGB(pixel(0, 0), 0, 0, 0);

    tu_section("material errors change nothing");
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, red);
    bad[1] = tu_nan();
    rtMaterialfv(RT_FRONT, RT_DIFFUSE, bad);
    CHECK_ERR(RT_INVALID_VALUE);
    rtMaterialfv(RT_FRONT, RT_DIFFUSE, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    rtMaterialfv(0x1234, RT_DIFFUSE, green);
    CHECK_ERR(RT_INVALID_ENUM);
    rtMaterialfv(RT_FRONT, 0x1234, green);
    CHECK_ERR(RT_INVALID_ENUM);
    rtMaterialfv(RT_FRONT, RT_POSITION, green); /* a light parameter */
    CHECK_ERR(RT_INVALID_ENUM);
    rtMaterialf(RT_FRONT, RT_DIFFUSE, 0.5f); /* vector parameter via the scalar call */
    CHECK_ERR(RT_INVALID_ENUM);
    rtMaterialf(RT_FRONT, RT_AMBIENT_AND_DIFFUSE, 0.5f);
    CHECK_ERR(RT_INVALID_ENUM);
    render_quad();
    CHECK_RGB(CENTRE, 1, 0, 0);

    tu_section("scalar material ranges");
    rtMaterialf(RT_FRONT, RT_SHININESS, 0);
    rtMaterialf(RT_FRONT, RT_SHININESS, 128);
    rtMaterialf(RT_FRONT, RT_REFLECTIVITY, 0);
    rtMaterialf(RT_FRONT, RT_REFLECTIVITY, 1);
    rtMaterialf(RT_FRONT, RT_TRANSPARENCY, 1);
    rtMaterialf(RT_FRONT, RT_TRANSPARENCY, 0);
    rtMaterialf(RT_FRONT, RT_INDEX_OF_REFRACTION, 0.5f);
    rtMaterialf(RT_FRONT, RT_INDEX_OF_REFRACTION, 2.4f);
    {
        const float one = 1.0f;
        rtMaterialfv(RT_BACK, RT_INDEX_OF_REFRACTION, &one);
        rtMaterialfv(RT_BACK, RT_SHININESS, &one);
    }
    CHECK_NO_ERR();
    rtMaterialf(RT_FRONT, RT_SHININESS, -1);
    CHECK_ERR(RT_INVALID_VALUE);
    rtMaterialf(RT_FRONT, RT_SHININESS, 128.5f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtMaterialf(RT_FRONT, RT_REFLECTIVITY, -0.01f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtMaterialf(RT_FRONT, RT_REFLECTIVITY, 1.01f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtMaterialf(RT_FRONT, RT_TRANSPARENCY, 2);
    CHECK_ERR(RT_INVALID_VALUE);
    rtMaterialf(RT_FRONT, RT_TRANSPARENCY, -1);
    CHECK_ERR(RT_INVALID_VALUE);
    rtMaterialf(RT_FRONT, RT_INDEX_OF_REFRACTION, 0);
    CHECK_ERR(RT_INVALID_VALUE);
    rtMaterialf(RT_FRONT, RT_INDEX_OF_REFRACTION, -1.5f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtMaterialf(RT_FRONT, RT_INDEX_OF_REFRACTION, tu_inf());
    CHECK_ERR(RT_INVALID_VALUE);

    tu_section("faces, emission, ambient-and-diffuse");
    /* RT_BACK sets the back material only (GL; issue 10: it used to set
     * the one two-sided material); the eye light shows the front. */
    rtMaterialfv(RT_BACK, RT_DIFFUSE, green);
    render_quad();
    CHECK_RGB(CENTRE, 1, 0, 0);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, green);
    render_quad();
    CHECK_RGB(CENTRE, 0, 1, 0);
    /* Emission adds; RT_AMBIENT_AND_DIFFUSE sets both. */
    {
        static const float emi[4] = {0.25f, 0, 0, 1}, ad[4] = {0, 0, 0.5f, 1},
                           amb_model[4] = {0.5f, 0.5f, 0.5f, 1};
        rtMaterialfv(RT_FRONT, RT_EMISSION, emi);
        rtMaterialfv(RT_FRONT, RT_AMBIENT_AND_DIFFUSE, ad);
        rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, amb_model);
        render_quad();
        /* 0.25 red + 0.5 * 0.5 blue ambient + 0.5 blue diffuse. */
        CHECK_RGB(CENTRE, 0.25f, 0, 0.75f);
    }
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
    default_material();

    tu_section("a triangle takes the material current at its last vertex");
    rtNewObject(OBJ);
    rtBegin(RT_TRIANGLES);
    rtMaterialfv(RT_FRONT, RT_DIFFUSE, red);
    rtVertex3f(-0.9f, -0.9f, -5);
    rtVertex3f(0.9f, -0.9f, -5);
    rtVertex3f(0.9f, 0.9f, -5); /* triangle 0: red */
    rtVertex3f(-0.9f, -0.9f, -5);
    rtVertex3f(0.9f, 0.9f, -5);
    rtMaterialfv(RT_FRONT, RT_DIFFUSE, green); /* allowed inside rtBegin */
    rtVertex3f(-0.9f, 0.9f, -5);               /* triangle 1: green */
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
    /* The material is recorded: changing it now does not change the object. */
    rtMaterialfv(RT_FRONT, RT_DIFFUSE, black);
    CHECK(tu_scene1(OBJ));
    render();
    CHECK_RGB(pixel(12, 3), 1, 0, 0);
    CHECK_RGB(pixel(3, 12), 0, 1, 0);
    default_material();
    CHECK_NO_ERR();
}

static void color_material(void)
{
    tu_section("RT_COLOR_MATERIAL");
    tu_ortho_camera();
    rtShadingMode(RT_EYE_LIGHT);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
    default_material();
    rtColor3f(1, 0, 0);
    /* Disabled: the vertex colour is ignored, diffuse 0.8 shows. */
    rtDisable(RT_COLOR_MATERIAL);
    render_quad();
    CHECK_RGB(CENTRE, 0.8f, 0.8f, 0.8f);
    /* Enabled: the vertex colour replaces ambient and diffuse. */
    rtEnable(RT_COLOR_MATERIAL);
    render_quad();
    CHECK_RGB(CENTRE, 1, 0, 0);
    /* It is recorded with the triangles: disabling it now changes nothing
     * until the object is redefined. */
    rtDisable(RT_COLOR_MATERIAL);
    render();
    CHECK_RGB(CENTRE, 1, 0, 0);
    /* A new quad: GL wrote the colour into the tracked ambient and diffuse
     * while RT_COLOR_MATERIAL was on, and they keep it after the disable
     * (OpenGL 2.1 sec. 2.14.3; gl_oracle/material checks it against Mesa). */
    render_quad();
    CHECK_RGB(CENTRE, 1, 0, 0);
    rtColor3f(1, 1, 1);
    default_material();
}

static void light_errors(void)
{
    static const float white[4] = {1, 1, 1, 1};
    float v[4] = {0, 0, 1, 0};
    tu_section("light errors");
    rtLightfv(RT_LIGHT0 + 8, RT_DIFFUSE, white);
    CHECK_ERR(RT_INVALID_ENUM);
    rtLightfv(RT_LIGHT0 - 1, RT_DIFFUSE, white);
    CHECK_ERR(RT_INVALID_ENUM);
    rtLightfv(RT_LIGHT0, RT_SHININESS, white);
    CHECK_ERR(RT_INVALID_ENUM);
    rtLightfv(RT_LIGHT0, RT_EMISSION, white);
    CHECK_ERR(RT_INVALID_ENUM);
    rtLightfv(RT_LIGHT0, RT_DIFFUSE, NULL);
    CHECK_ERR(RT_INVALID_VALUE);
    v[3] = tu_nan();
    rtLightfv(RT_LIGHT0, RT_POSITION, v);
    CHECK_ERR(RT_INVALID_VALUE);
    rtLightf(RT_LIGHT0, RT_CONSTANT_ATTENUATION, -1);
    CHECK_ERR(RT_INVALID_VALUE);
    rtLightf(RT_LIGHT0, RT_LINEAR_ATTENUATION, -0.5f);
    CHECK_ERR(RT_INVALID_VALUE);
    rtLightf(RT_LIGHT0, RT_QUADRATIC_ATTENUATION, tu_inf());
    CHECK_ERR(RT_INVALID_VALUE);
    rtLightf(RT_LIGHT0, RT_DIFFUSE, 1); /* vector parameter via the scalar call */
    CHECK_ERR(RT_INVALID_ENUM);
    rtLightf(RT_LIGHT0 + 9, RT_CONSTANT_ATTENUATION, 1);
    CHECK_ERR(RT_INVALID_ENUM);
    rtLightf(RT_LIGHT0 + 7, RT_QUADRATIC_ATTENUATION, 0);
    rtLightfv(RT_LIGHT0 + 7, RT_LINEAR_ATTENUATION, white);
    CHECK_NO_ERR();
    tu_begin_scratch(RT_TRIANGLES);
    rtLightfv(RT_LIGHT0, RT_DIFFUSE, white);
    CHECK_ERR(RT_INVALID_OPERATION);
    rtLightf(RT_LIGHT0, RT_CONSTANT_ATTENUATION, 1);
    CHECK_ERR(RT_INVALID_OPERATION);
    tu_end_scratch();

    tu_section("light model");
    {
        float f[4] = {-1, -1, -1, -1};
        static const float amb[4] = {0.1f, 0.2f, 0.3f, 0.4f};
        rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, amb);
        rtGetFloatv(RT_LIGHT_MODEL_AMBIENT, f);
        CHECK(f[0] == amb[0] && f[1] == amb[1] && f[2] == amb[2] && f[3] == amb[3]);
        v[0] = v[1] = v[2] = 0.5f;
        v[3] = tu_inf();
        rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, v);
        CHECK_ERR(RT_INVALID_VALUE);
        rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, NULL);
        CHECK_ERR(RT_INVALID_VALUE);
        rtLightModelfv(RT_AMBIENT, amb);
        CHECK_ERR(RT_INVALID_ENUM);
        rtGetFloatv(RT_LIGHT_MODEL_AMBIENT, f);
        CHECK(f[0] == amb[0] && f[1] == amb[1] && f[2] == amb[2] && f[3] == amb[3]);
        rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
    }
}

static void modes_and_parameters(void)
{
    tu_section("rtShadingMode / rtRenderParameteri");
    CHECK_INT(geti(RT_SHADING_MODE), RT_EYE_LIGHT);
    rtShadingMode(RT_WHITTED);
    CHECK_INT(geti(RT_SHADING_MODE), RT_WHITTED);
    rtShadingMode(0x1234);
    CHECK_ERR(RT_INVALID_ENUM);
    rtShadingMode(RT_FLAT);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_INT(geti(RT_SHADING_MODE), RT_WHITTED);
    rtShadingMode(RT_EYE_LIGHT);
    CHECK_INT(geti(RT_SHADING_MODE), RT_EYE_LIGHT);

    CHECK_INT(geti(RT_MAX_RAY_DEPTH), 3);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 0);
    CHECK_INT(geti(RT_MAX_RAY_DEPTH), 0);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 16);
    CHECK_INT(geti(RT_MAX_RAY_DEPTH), 16);
    CHECK_NO_ERR();
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 17);
    CHECK_ERR(RT_INVALID_VALUE);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, -1);
    CHECK_ERR(RT_INVALID_VALUE);
    rtRenderParameteri(0x1234, 2);
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_INT(geti(RT_MAX_RAY_DEPTH), 16);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 3);
}

static void whitted_lights(void)
{
    static const float dir_x[4] = {1, 0, 0, 0}, origin[4] = {0, 0, 0, 1};
    tu_section("Whitted: light 0 defaults, position under the modelview");
    tu_ortho_camera();
    default_material();
    rtShadingMode(RT_WHITTED);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
    /* No light enabled: nothing but ambient (here 0). */
    render_quad();
    CHECK_RGB(CENTRE, 0, 0, 0);
    /* Light 0: white, directional from +z by default: 0.8 * N.L = 0.8. */
    rtEnable(RT_LIGHT0);
    render_quad();
    CHECK_RGB(CENTRE, 0.8f, 0.8f, 0.8f);
    /* Lights 1..7 are black by default. */
    rtDisable(RT_LIGHT0);
    rtEnable(RT_LIGHT0 + 1);
    render_quad();
    CHECK_RGB(CENTRE, 0, 0, 0);
    rtDisable(RT_LIGHT0 + 1);
    rtEnable(RT_LIGHT0);
    /* The position is transformed by the modelview at the call: (0,0,1,0)
     * under a 90 degree turn about y becomes (1,0,0,0): N.L = 0. */
    rtPushMatrix();
    rtRotatef(90, 0, 1, 0);
    {
        static const float z[4] = {0, 0, 1, 0};
        rtLightfv(RT_LIGHT0, RT_POSITION, z);
    }
    rtPopMatrix();
    render_quad();
    CHECK_RGB(CENTRE, 0, 0, 0);
    /* Set directly along +x: the same. */
    rtLightfv(RT_LIGHT0, RT_POSITION, dir_x);
    render_quad();
    CHECK_RGB(CENTRE, 0, 0, 0);
    /* A failing call leaves the position. */
    {
        float bad[4] = {0, 0, 1, 0};
        bad[2] = tu_nan();
        rtLightfv(RT_LIGHT0, RT_POSITION, bad);
        CHECK_ERR(RT_INVALID_VALUE);
        render_quad();
        CHECK_RGB(CENTRE, 0, 0, 0);
    }
    /* A point light at the eye with constant 1, linear 0.2 at distance 5:
     * attenuation 1/2. */
    rtLightfv(RT_LIGHT0, RT_POSITION, origin);
    rtLightf(RT_LIGHT0, RT_CONSTANT_ATTENUATION, 1);
    rtLightf(RT_LIGHT0, RT_LINEAR_ATTENUATION, 0.2f);
    render_quad();
    CHECK_RGB(CENTRE, 0.4f, 0.4f, 0.4f);
    /* Failing attenuation calls leave it. */
    rtLightf(RT_LIGHT0, RT_LINEAR_ATTENUATION, -1);
    CHECK_ERR(RT_INVALID_VALUE);
    render_quad();
    CHECK_RGB(CENTRE, 0.4f, 0.4f, 0.4f);
    rtLightf(RT_LIGHT0, RT_LINEAR_ATTENUATION, 0);
    {
        static const float z[4] = {0, 0, 1, 0};
        rtLightfv(RT_LIGHT0, RT_POSITION, z);
    }
    /* Light ambient adds La * ambient. */
    {
        static const float la[4] = {0.5f, 0.5f, 0.5f, 1};
        rtLightfv(RT_LIGHT0, RT_AMBIENT, la);
        render_quad();
        CHECK_RGB(CENTRE, 0.9f, 0.9f, 0.9f); /* 0.5 * 0.2 + 0.8 */
        rtLightfv(RT_LIGHT0, RT_AMBIENT, black);
    }
    CHECK_NO_ERR();
}

static void whitted_shadows(void)
{
    /* Camera ortho [-4,4]^2, 16x16 pixels of 0.5; floor z = -5; a strip
     * occluder x in [-0.5, 0.5] at z = -3; light direction (1, 0, 1): the
     * shadow falls on x in [-2.5, -1.5]. */
    static const float light_dir[4] = {1, 0, 1, 0};
    const float lit = 0.8f * 0.70710678f;
    tu_section("Whitted: hard shadows");
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtOrtho(-4, 4, -4, 4, 1, 100);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    default_material();
    rtShadingMode(RT_WHITTED);
    rtEnable(RT_LIGHT0);
    rtLightfv(RT_LIGHT0, RT_POSITION, light_dir);
    CHECK(tu_define_quad(OBJ, -4, -4, 4, 4, -5));
    CHECK(tu_define_quad(OCC, -0.5f, -4, 0.5f, 4, -3));
    rtBeginFrame();
    rtInstantiateObject(OBJ);
    rtInstantiateObject(OCC);
    render();
    CHECK_NO_ERR();
    /* Column i has its centre at x = -4 + 0.5 (i + 0.5). */
    CHECK_RGB(pixel(3, 8), 0, 0, 0);       /* x = -2.25: in shadow */
    CHECK_RGB(pixel(4, 8), 0, 0, 0);       /* x = -1.75: in shadow */
    CHECK_RGB(pixel(12, 8), lit, lit, lit); /* x = +2.25: lit */
    CHECK_RGB(pixel(8, 8), lit, lit, lit);  /* the occluder itself, lit */
    CHECK_RGB(pixel(1, 8), lit, lit, lit);  /* x = -3.25: past the shadow */
    /* Eye-light mode has no shadows. */
    rtShadingMode(RT_EYE_LIGHT);
    render();
    CHECK_RGB(pixel(3, 8), 0.8f, 0.8f, 0.8f);
    rtDisable(RT_LIGHT0);
    {
        static const float z[4] = {0, 0, 1, 0};
        rtLightfv(RT_LIGHT0, RT_POSITION, z);
    }
}

static void whitted_reflection_refraction(void)
{
    static const float green[4] = {0, 1, 0, 1}, red[4] = {1, 0, 0, 1};
    tu_section("Whitted: reflection, refraction, ray depth");
    tu_ortho_camera();
    rtShadingMode(RT_WHITTED);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
    rtClearColor(0, 0, 0, 0);
    /* An emissive green wall at x = 3 facing -x, out of the camera's view. */
    default_material();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, green);
    rtNewObject(WALL);
    rtBegin(RT_QUADS);
    rtVertex3f(3, -2, -8);
    rtVertex3f(3, -2, -2);
    rtVertex3f(3, 2, -2);
    rtVertex3f(3, 2, -8);
    rtEnd();
    rtEndObject();
    /* A mirror with normal (1, 0, 1)/sqrt 2: camera rays reflect to +x. */
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 1);
    rtNewObject(OBJ);
    rtBegin(RT_QUADS);
    rtVertex3f(-0.5f, -1, -4.5f);
    rtVertex3f(0.5f, -1, -5.5f);
    rtVertex3f(0.5f, 1, -5.5f);
    rtVertex3f(-0.5f, 1, -4.5f);
    rtEnd();
    rtEndObject();
    CHECK_NO_ERR();
    rtBeginFrame();
    whitted_material(green, 0, 0);
    rtInstantiateObject(WALL);
    whitted_material(black, 1, 0);
    rtInstantiateObject(OBJ);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 1);
    render();
    CHECK_RGB(CENTRE, 0, 1, 0);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 0);
    render();
    CHECK_RGB(CENTRE, 0, 0, 0);
    /* Eye light ignores reflectivity. */
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 3);
    rtShadingMode(RT_EYE_LIGHT);
    render();
    CHECK_RGB(CENTRE, 0, 0, 0);
    rtShadingMode(RT_WHITTED);

    /* A fully transparent sheet (index 1) in front of an emissive red quad. */
    default_material();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, red);
    define_facing_quad(WALL, -8);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, black);
    rtMaterialf(RT_FRONT_AND_BACK, RT_TRANSPARENCY, 1);
    define_facing_quad(OBJ, -5);
    rtBeginFrame();
    whitted_material(black, 0, 1);
    rtInstantiateObject(OBJ);
    whitted_material(red, 0, 0);
    rtInstantiateObject(WALL);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 2);
    render();
    CHECK_RGB(CENTRE, 1, 0, 0);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 0);
    render();
    CHECK_RGB(CENTRE, 0, 0, 0);

    /* The local colour is weighted by (1 - transparency): an emissive red
     * sheet with transparency 0.5 in front of an emissive green quad shows
     * 0.5 red + 0.5 green. */
    {
        static const float green4[4] = {0, 1, 0, 1};
        rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, green4);
        rtMaterialf(RT_FRONT_AND_BACK, RT_TRANSPARENCY, 0);
        define_facing_quad(WALL, -8);
        rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, red);
        rtMaterialf(RT_FRONT_AND_BACK, RT_TRANSPARENCY, 0.5f);
        define_facing_quad(OBJ, -5);
        rtBeginFrame();
        whitted_material(red, 0, 0.5f);
        rtInstantiateObject(OBJ);
        whitted_material(green4, 0, 0);
        rtInstantiateObject(WALL);
        rtRenderParameteri(RT_MAX_RAY_DEPTH, 2);
        render();
        CHECK_RGB(CENTRE, 0.5f, 0.5f, 0);
        /* At the depth limit the refracted ray is not traced and the
         * local colour stands alone. */
        rtRenderParameteri(RT_MAX_RAY_DEPTH, 0);
        render();
        CHECK_RGB(CENTRE, 1, 0, 0);
    }
    rtRenderParameteri(RT_MAX_RAY_DEPTH, 3);
    default_material();
    rtShadingMode(RT_EYE_LIGHT);
    CHECK_NO_ERR();
}

static void whitted_specular(void)
{
    /* Light from 30 degrees off the normal, viewer along the normal: the
     * half vector is 15 degrees off the normal, so Ls * specular * (N.H)^10
     * = 0.5 * cos(15)^10 = 0.5 * 0.7069.  (Phong's reflected-vector form
     * (R.V)^10 = cos(30)^10 would give 0.5 * 0.2370.) */
    static const float spec[4] = {0.5f, 0.5f, 0.5f, 1},
                       light_dir[4] = {0.5f, 0, 0.8660254f, 0};
    const float expected = 0.5f * powf(0.96592583f, 10.0f);
    tu_section("Whitted: specular term (N.H)^shininess");
    tu_ortho_camera();
    rtShadingMode(RT_WHITTED);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, black);
    default_material();
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, black);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, spec);
    rtMaterialf(RT_FRONT_AND_BACK, RT_SHININESS, 10);
    rtLightfv(RT_LIGHT0, RT_POSITION, light_dir);
    rtEnable(RT_LIGHT0);
    render_quad();
    CHECK_RGB(CENTRE, expected, expected, expected);
    /* Diffuse alone: 0.8 * N.L = 0.8 * cos 30. */
    default_material();
    render_quad();
    CHECK_RGB(CENTRE, 0.8f * 0.8660254f, 0.8f * 0.8660254f, 0.8f * 0.8660254f);
    /* A directional light is not attenuated. */
    rtLightf(RT_LIGHT0, RT_CONSTANT_ATTENUATION, 4);
    render_quad();
    CHECK_RGB(CENTRE, 0.8f * 0.8660254f, 0.8f * 0.8660254f, 0.8f * 0.8660254f);
    rtLightf(RT_LIGHT0, RT_CONSTANT_ATTENUATION, 1);
    {
        static const float z[4] = {0, 0, 1, 0};
        rtLightfv(RT_LIGHT0, RT_POSITION, z);
    }
    rtDisable(RT_LIGHT0);
    rtShadingMode(RT_EYE_LIGHT);
    CHECK_NO_ERR();
}

int main(void)
{
    RTcontext ctx = tu_make_context("threads=2");
    tu_capture_errors();
    material_errors_and_defaults();
    color_material();
    light_errors();
    modes_and_parameters();
    whitted_lights();
    whitted_shadows();
    whitted_reflection_refraction();
    whitted_specular();
    tu_destroy_context(ctx);
    return test_summary("appearance");
}
