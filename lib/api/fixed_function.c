/* SPDX-License-Identifier: Apache-2.0 */
/*
 * fixed_function.c - the rest of GL 1.x's fixed-function state that ported
 * programs set: rtFog (frame state, docs/fog.md), rtTexEnv (recorded with
 * the triangles, as GL applies it per primitive; docs/textures.md), and
 * the names with no ray tracing meaning, accepted with no effect after
 * GL's own validation (docs/appearance.md, "Accepted no-ops").
 */
#include <math.h>
#include <string.h>

#include "api/context.h"
#include "api/enum_names.h"

static void fog(const char *caller, RTenum pname, const RTfloat *params, int vector)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    char b1[RT_ENUM_STRING_SIZE];
    if (pname != RT_FOG_MODE && pname != RT_FOG_DENSITY && pname != RT_FOG_START &&
        pname != RT_FOG_END && (pname != RT_FOG_COLOR || !vector)) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(pname=%s): not a fog parameter%s", caller,
                 rt_enum_string(pname, b1),
                 pname == RT_FOG_COLOR ? " for a scalar call" : "");
        return;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(params=NULL)", caller);
        return;
    }
    if (!rt_check_finite(ctx, caller, params, pname == RT_FOG_COLOR ? 4 : 1))
        return;
    struct render_fog *f = &ctx->render.fog;
    switch (pname) {
    case RT_FOG_MODE: {
        RTenum mode = (RTenum)params[0];
        if ((float)mode != params[0] ||
            (mode != RT_LINEAR && mode != RT_EXP && mode != RT_EXP2)) {
            rt_error(ctx, RT_INVALID_ENUM, "%s(RT_FOG_MODE, %s): not RT_LINEAR, RT_EXP or RT_EXP2",
                     caller, rt_enum_string(mode, b1));
            return;
        }
        f->mode = mode;
        break;
    }
    case RT_FOG_DENSITY:
        if (params[0] < 0.0f) {
            rt_error(ctx, RT_INVALID_VALUE, "%s(RT_FOG_DENSITY, %g): negative", caller,
                     (double)params[0]);
            return;
        }
        f->density = params[0];
        break;
    case RT_FOG_START:
        f->start = params[0];
        break;
    case RT_FOG_END:
        f->end = params[0];
        break;
    default:
        /* GL clamps the fog colour to [0, 1]. */
        for (int k = 0; k < 4; k++)
            f->color[k] = params[k] < 0.0f ? 0.0f : (params[k] > 1.0f ? 1.0f : params[k]);
        break;
    }
}

void rtFogf(RTenum pname, RTfloat param)
{
    fog("rtFogf", pname, &param, 0);
}

void rtFogi(RTenum pname, RTint param)
{
    RTfloat f = (RTfloat)param;
    fog("rtFogi", pname, &f, 0);
}

void rtFogfv(RTenum pname, const RTfloat *params)
{
    fog("rtFogfv", pname, params, 1);
}

static void tex_env(const char *caller, RTenum target, RTenum pname, const RTfloat *params,
                    int vector)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    char b1[RT_ENUM_STRING_SIZE];
    if (target != RT_TEXTURE_ENV) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(target=%s): not RT_TEXTURE_ENV", caller,
                 rt_enum_string(target, b1));
        return;
    }
    if (pname != RT_TEXTURE_ENV_MODE && (pname != RT_TEXTURE_ENV_COLOR || !vector)) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(pname=%s): not a texture environment parameter%s",
                 caller, rt_enum_string(pname, b1),
                 pname == RT_TEXTURE_ENV_COLOR ? " for a scalar call" : "");
        return;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(params=NULL)", caller);
        return;
    }
    struct scene_material m = ctx->material;
    if (pname == RT_TEXTURE_ENV_MODE) {
        RTenum mode = (RTenum)params[0];
        if ((float)mode != params[0] || (mode != RT_MODULATE && mode != RT_REPLACE &&
                                         mode != RT_DECAL && mode != RT_BLEND)) {
            rt_error(ctx, RT_INVALID_ENUM,
                     "%s(RT_TEXTURE_ENV_MODE, %s): not RT_MODULATE, RT_REPLACE, RT_DECAL or "
                     "RT_BLEND",
                     caller, rt_enum_string(mode, b1));
            return;
        }
        m.tex_env_mode = mode;
    } else {
        if (!rt_check_finite(ctx, caller, params, 4))
            return;
        for (int k = 0; k < 4; k++)
            m.tex_env_color[k] = params[k] < 0.0f ? 0.0f : (params[k] > 1.0f ? 1.0f : params[k]);
    }
    if (memcmp(&m, &ctx->material, sizeof(m)) == 0)
        return;
    ctx->material = m;
    ctx->recording.material_index = -1;
}

void rtTexEnvi(RTenum target, RTenum pname, RTint param)
{
    RTfloat f = (RTfloat)param;
    tex_env("rtTexEnvi", target, pname, &f, 0);
}

void rtTexEnvf(RTenum target, RTenum pname, RTfloat param)
{
    tex_env("rtTexEnvf", target, pname, &param, 0);
}

void rtTexEnvfv(RTenum target, RTenum pname, const RTfloat *params)
{
    tex_env("rtTexEnvfv", target, pname, params, 1);
}

/* ---- Accepted no-ops: GL's checks, then nothing ------------------------- */

static struct rt_context *no_op_context(const char *caller)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return NULL;
    return ctx;
}

static void bad_enum(struct rt_context *ctx, const char *caller, const char *what, RTenum e)
{
    char b1[RT_ENUM_STRING_SIZE];
    rt_error(ctx, RT_INVALID_ENUM, "%s(%s=%s)", caller, what, rt_enum_string(e, b1));
}

void rtHint(RTenum target, RTenum mode)
{
    struct rt_context *ctx = no_op_context("rtHint");
    if (!ctx)
        return;
    if (target < RT_PERSPECTIVE_CORRECTION_HINT || target > RT_FOG_HINT)
        bad_enum(ctx, "rtHint", "target", target);
    else if (mode != RT_DONT_CARE && mode != RT_FASTEST && mode != RT_NICEST)
        bad_enum(ctx, "rtHint", "mode", mode);
}

static int is_buffer(RTenum mode)
{
    return mode == RT_NONE || (mode >= RT_FRONT_LEFT && mode <= RT_FRONT_AND_BACK);
}

void rtDrawBuffer(RTenum mode)
{
    struct rt_context *ctx = no_op_context("rtDrawBuffer");
    if (ctx && !is_buffer(mode))
        bad_enum(ctx, "rtDrawBuffer", "mode", mode);
}

void rtReadBuffer(RTenum mode)
{
    struct rt_context *ctx = no_op_context("rtReadBuffer");
    if (ctx && (mode == RT_NONE || !is_buffer(mode)))
        bad_enum(ctx, "rtReadBuffer", "mode", mode);
}

void rtDepthFunc(RTenum func)
{
    struct rt_context *ctx = no_op_context("rtDepthFunc");
    if (ctx && (func < RT_NEVER || func > RT_ALWAYS))
        bad_enum(ctx, "rtDepthFunc", "func", func);
}

void rtDepthRange(RTdouble zNear, RTdouble zFar)
{
    (void)zNear;
    (void)zFar;
    no_op_context("rtDepthRange"); /* GL clamps; nothing is invalid */
}

void rtClearDepth(RTdouble depth)
{
    (void)depth;
    no_op_context("rtClearDepth");
}

void rtPolygonOffset(RTfloat factor, RTfloat units)
{
    (void)factor;
    (void)units;
    no_op_context("rtPolygonOffset");
}

void rtLockArraysEXT(RTint first, RTsizei count)
{
    struct rt_context *ctx = no_op_context("rtLockArraysEXT");
    if (ctx && (first < 0 || count <= 0))
        rt_error(ctx, RT_INVALID_VALUE, "rtLockArraysEXT(first=%d, count=%d)", first, count);
}

void rtUnlockArraysEXT(void)
{
    no_op_context("rtUnlockArraysEXT");
}
