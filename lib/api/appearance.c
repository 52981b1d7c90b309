/* SPDX-License-Identifier: Apache-2.0 */
/*
 * appearance.c - materials, lights, the light model, shading modes and
 * render parameters.
 *
 * Materials are two-sided: RT_FRONT, RT_BACK and RT_FRONT_AND_BACK all set
 * the one material (a ray tracer sees both sides of every triangle).
 * Light positions are transformed by the modelview at the call, as GL.
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "base/mat4.h"

/* Number of values a material pname takes; 0 for an unknown pname. */
static int material_size(RTenum pname)
{
    switch (pname) {
    case RT_AMBIENT:
    case RT_DIFFUSE:
    case RT_SPECULAR:
    case RT_EMISSION:
    case RT_AMBIENT_AND_DIFFUSE:
        return 4;
    case RT_SHININESS:
    case RT_REFLECTIVITY:
    case RT_TRANSPARENCY:
    case RT_INDEX_OF_REFRACTION:
        return 1;
    default:
        return 0;
    }
}

static void material(const char *caller, RTenum face, RTenum pname, const RTfloat *params,
                     int scalar_only)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    if (face != RT_FRONT && face != RT_BACK && face != RT_FRONT_AND_BACK) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(face=0x%x)", caller, face);
        return;
    }
    int n = material_size(pname);
    if (n == 0 || (scalar_only && n != 1)) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(pname=0x%x)", caller, pname);
        return;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(params=NULL)", caller);
        return;
    }
    if (!rt_check_finite(ctx, caller, params, n))
        return;
    float v = params[0];
    int bad = (pname == RT_SHININESS && (v < 0.0f || v > 128.0f)) ||
              ((pname == RT_REFLECTIVITY || pname == RT_TRANSPARENCY) && (v < 0.0f || v > 1.0f)) ||
              (pname == RT_INDEX_OF_REFRACTION && !(v > 0.0f));
    if (bad) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(pname=0x%x, value=%g): out of range", caller, pname,
                 (double)v);
        return;
    }
    rt_list_state(ctx, LIST_MATERIAL, face, pname, params, n);
    struct scene_material m = ctx->material;
    switch (pname) {
    case RT_AMBIENT:
        memcpy(m.ambient, params, sizeof(m.ambient));
        break;
    case RT_DIFFUSE:
        memcpy(m.diffuse, params, sizeof(m.diffuse));
        break;
    case RT_AMBIENT_AND_DIFFUSE:
        memcpy(m.ambient, params, sizeof(m.ambient));
        memcpy(m.diffuse, params, sizeof(m.diffuse));
        break;
    case RT_SPECULAR:
        memcpy(m.specular, params, sizeof(m.specular));
        break;
    case RT_EMISSION:
        memcpy(m.emission, params, sizeof(m.emission));
        break;
    case RT_SHININESS:
        m.shininess = v;
        break;
    case RT_REFLECTIVITY:
        m.reflectivity = v;
        break;
    case RT_TRANSPARENCY:
        m.transparency = v;
        break;
    default:
        m.ior = v;
        break;
    }
    if (memcmp(&m, &ctx->material, sizeof(m)) == 0)
        return; /* unchanged: keep the interned index (Mesa compares first) */
    ctx->material = m;
    ctx->recording.material_index = -1;
}

void rtMaterialf(RTenum face, RTenum pname, RTfloat param)
{
    /* Padded to the size of a vector pname: the compiler cannot see that
     * scalar_only keeps the 4-float paths from reading it. */
    const RTfloat params[4] = {param, 0.0f, 0.0f, 0.0f};
    material("rtMaterialf", face, pname, params, 1);
}

void rtMaterialfv(RTenum face, RTenum pname, const RTfloat *params)
{
    material("rtMaterialfv", face, pname, params, 0);
}

static int light_size(RTenum pname)
{
    switch (pname) {
    case RT_AMBIENT:
    case RT_DIFFUSE:
    case RT_SPECULAR:
    case RT_POSITION:
        return 4;
    case RT_CONSTANT_ATTENUATION:
    case RT_LINEAR_ATTENUATION:
    case RT_QUADRATIC_ATTENUATION:
        return 1;
    default:
        return 0;
    }
}

static void light(const char *caller, RTenum which, RTenum pname, const RTfloat *params,
                  int scalar_only)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    if (which < RT_LIGHT0 || which >= RT_LIGHT0 + RENDER_MAX_LIGHTS) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(light=0x%x)", caller, which);
        return;
    }
    int n = light_size(pname);
    if (n == 0 || (scalar_only && n != 1)) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(pname=0x%x)", caller, pname);
        return;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(params=NULL)", caller);
        return;
    }
    if (!rt_check_finite(ctx, caller, params, n))
        return;
    if (n == 1 && params[0] < 0.0f) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(attenuation=%g): negative", caller,
                 (double)params[0]);
        return;
    }
    rt_list_state(ctx, LIST_LIGHT, which, pname, params, n);
    struct render_light *l = &ctx->render.lights[which - RT_LIGHT0];
    switch (pname) {
    case RT_AMBIENT:
        memcpy(l->ambient, params, sizeof(l->ambient));
        break;
    case RT_DIFFUSE:
        memcpy(l->diffuse, params, sizeof(l->diffuse));
        break;
    case RT_SPECULAR:
        memcpy(l->specular, params, sizeof(l->specular));
        break;
    case RT_POSITION: {
        /* Transformed by the modelview at the call (GL), in double. */
        const double *m = ctx->modelview.m[ctx->modelview.depth - 1];
        double p[4] = {params[0], params[1], params[2], params[3]}, out[4];
        for (int r = 0; r < 4; r++)
            out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r] * p[3];
        float f[4];
        for (int r = 0; r < 4; r++)
            f[r] = (float)out[r];
        if (!rt_check_finite(ctx, caller, f, 4))
            return;
        memcpy(l->position, f, sizeof(f));
        break;
    }
    case RT_CONSTANT_ATTENUATION:
        l->attenuation[0] = params[0];
        break;
    case RT_LINEAR_ATTENUATION:
        l->attenuation[1] = params[0];
        break;
    default:
        l->attenuation[2] = params[0];
        break;
    }
}

void rtLightf(RTenum which, RTenum pname, RTfloat param)
{
    const RTfloat params[4] = {param, 0.0f, 0.0f, 0.0f};
    light("rtLightf", which, pname, params, 1);
}

void rtLightfv(RTenum which, RTenum pname, const RTfloat *params)
{
    light("rtLightfv", which, pname, params, 0);
}

void rtLightModelfv(RTenum pname, const RTfloat *params)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtLightModelfv"))
        return;
    if (pname != RT_LIGHT_MODEL_AMBIENT) {
        rt_error(ctx, RT_INVALID_ENUM, "rtLightModelfv(pname=0x%x)", pname);
        return;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "rtLightModelfv(params=NULL)");
        return;
    }
    if (!rt_check_finite(ctx, "rtLightModelfv", params, 4))
        return;
    rt_list_state(ctx, LIST_LIGHT_MODEL, pname, 0, params, 4);
    memcpy(ctx->render.global_ambient, params, 4 * sizeof(float));
}

void rtShadingMode(RTenum mode)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtShadingMode"))
        return;
    if (mode != RT_EYE_LIGHT && mode != RT_WHITTED) {
        rt_error(ctx, RT_INVALID_ENUM, "rtShadingMode(mode=0x%x)", mode);
        return;
    }
    ctx->render.shading = mode == RT_WHITTED ? RENDER_WHITTED : RENDER_EYE_LIGHT;
}

void rtRenderParameteri(RTenum pname, RTint param)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtRenderParameteri"))
        return;
    if (pname == RT_UPDATE_STRATEGY) {
        if (!rt_strategy_is_valid((RTenum)param)) {
            rt_error(ctx, RT_INVALID_ENUM, "rtRenderParameteri(RT_UPDATE_STRATEGY, 0x%x)",
                     (RTenum)param);
            return;
        }
        ctx->scene.default_strategy = (RTenum)param;
        return;
    }
    if (pname != RT_MAX_RAY_DEPTH) {
        rt_error(ctx, RT_INVALID_ENUM, "rtRenderParameteri(pname=0x%x)", pname);
        return;
    }
    if (param < 0 || param > API_MAX_RAY_DEPTH_LIMIT) {
        rt_error(ctx, RT_INVALID_VALUE, "rtRenderParameteri(RT_MAX_RAY_DEPTH, %d): not in 0..%d",
                 param, API_MAX_RAY_DEPTH_LIMIT);
        return;
    }
    ctx->render.max_depth = param;
}
