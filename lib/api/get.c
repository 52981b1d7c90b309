/* SPDX-License-Identifier: Apache-2.0 */
/*
 * get.c - state queries (rtGetString, rtGetIntegerv, rtGetFloatv) and
 * capabilities (rtEnable, rtDisable, rtIsEnabled).
 *
 * One table-like function, state_values, produces every queryable value
 * as doubles; the typed entry points convert, so the integer and float
 * queries can never disagree.
 */
#include <limits.h>
#include <string.h>

#include "api/context.h"
#include "api/enum_names.h"

/* GL form: "<version> <vendor-specific>"; the numbers come from the
 * generated rt_version.h, so the string cannot drift from the package. */
#define RT_VERSION_STRING_FULL RT_VERSION_STRING " Tracelist"

const char *rtGetString(RTenum name)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtGetString"))
        return NULL;
    switch (name) {
    case RT_VENDOR:
        return "Tracelist";
    case RT_RENDERER:
        return "Tracelist CPU ray tracer (binned SAH BVH, two-level, pthreads)";
    case RT_VERSION:
        return RT_VERSION_STRING_FULL;
    case RT_EXTENSIONS:
        return "";
    case RT_CONFIGURATION:
        return ctx->configuration;
    default:
        rt_error(ctx, RT_INVALID_ENUM, "rtGetString(name=0x%x)", name);
        return NULL;
    }
}

enum value_kind { VALUE_NONE, VALUE_INT, VALUE_FLOAT, VALUE_MATRIX };

/* Writes the values of pname into v (at most 16) and returns their count
 * and kind; VALUE_NONE for an unknown pname. */
static enum value_kind state_values(const struct rt_context *ctx, RTenum pname, double v[16],
                                    int *count)
{
    const struct render_stats *st = &ctx->stats;
    *count = 1;
    switch (pname) {
    case RT_MATRIX_MODE:
        v[0] = ctx->matrix_mode;
        return VALUE_INT;
    case RT_LIST_BASE:
        v[0] = ctx->list_base;
        return VALUE_INT;
    case RT_LIST_INDEX:
        v[0] = ctx->recording.active ? ctx->recording.name : 0;
        return VALUE_INT;
    case RT_LIST_MODE:
        v[0] = ctx->recording.active ? ctx->list_mode : 0;
        return VALUE_INT;
    case RT_MAX_LIST_NESTING:
        v[0] = 64;
        return VALUE_INT;
    case RT_MODELVIEW_STACK_DEPTH:
        v[0] = ctx->modelview.depth;
        return VALUE_INT;
    case RT_PROJECTION_STACK_DEPTH:
        v[0] = ctx->projection.depth;
        return VALUE_INT;
    case RT_MAX_MODELVIEW_STACK_DEPTH:
        v[0] = ctx->modelview.max_depth;
        return VALUE_INT;
    case RT_MAX_PROJECTION_STACK_DEPTH:
        v[0] = ctx->projection.max_depth;
        return VALUE_INT;
    case RT_VIEWPORT:
        for (int i = 0; i < 4; i++)
            v[i] = ctx->render.viewport[i];
        *count = 4;
        return VALUE_INT;
    case RT_MAX_LIGHTS:
        v[0] = RENDER_MAX_LIGHTS;
        return VALUE_INT;
    case RT_THREADS:
        v[0] = ctx->threads;
        return VALUE_INT;
    case RT_BVH_BINS:
        v[0] = ctx->build_params.bins;
        return VALUE_INT;
    case RT_ACCELERATION_HINT:
        v[0] = ctx->acceleration_hint;
        return VALUE_INT;
    case RT_OBJECT_COUNT:
        v[0] = ctx->scene.objects.defined;
        return VALUE_INT;
    case RT_INSTANCE_COUNT:
        v[0] = ctx->scene.frame.open ? ctx->scene.frame.pending.count : ctx->scene.frame.committed.count;
        return VALUE_INT;
    case RT_NESTED_GROUPS:
        v[0] = ctx->scene.frame.flats.groups;
        return VALUE_INT;
    case RT_FLATTENED_GROUPS:
        v[0] = ctx->scene.frame.flats.flattened;
        return VALUE_INT;
    case RT_WORKER_THREADS_RUNNING:
        v[0] = ctx->pool ? rt_pool_threads(ctx->pool) - 1 : 0;
        return VALUE_INT;
    case RT_UPDATE_STRATEGY:
        v[0] = ctx->scene.default_strategy;
        return VALUE_INT;
    case RT_BUILD_THREADS:
        v[0] = ctx->build_threads;
        return VALUE_INT;
    case RT_BUILD_THREADS_RUNNING:
        v[0] = scene_async_threads_running(&ctx->scene.async);
        return VALUE_INT;
    case RT_SHADING_MODE:
        v[0] = ctx->render.shading == RENDER_WHITTED     ? RT_WHITTED
               : ctx->render.shading == RENDER_EYE_LIGHT ? RT_EYE_LIGHT
                                                         : RT_FIXED_FUNCTION;
        return VALUE_INT;
    case RT_COLOR_MATERIAL_FACE:
        v[0] = ctx->material.color_material_face;
        return VALUE_INT;
    case RT_COLOR_MATERIAL_PARAMETER:
        v[0] = ctx->material.color_material_mode;
        return VALUE_INT;
    case RT_CULL_FACE_MODE:
        v[0] = ctx->cull_face_mode;
        return VALUE_INT;
    case RT_FRONT_FACE:
        v[0] = ctx->material.front_cw ? RT_CW : RT_CCW;
        return VALUE_INT;
    case RT_LIGHT_MODEL_TWO_SIDE:
        v[0] = ctx->render.light_model_two_side;
        return VALUE_INT;
    case RT_LIGHT_MODEL_LOCAL_VIEWER:
        v[0] = ctx->render.light_model_local_viewer;
        return VALUE_INT;
    case RT_FOG_MODE:
        v[0] = ctx->render.fog.mode;
        return VALUE_INT;
    case RT_FOG_DENSITY:
        v[0] = ctx->render.fog.density;
        return VALUE_FLOAT;
    case RT_FOG_START:
        v[0] = ctx->render.fog.start;
        return VALUE_FLOAT;
    case RT_FOG_END:
        v[0] = ctx->render.fog.end;
        return VALUE_FLOAT;
    case RT_FOG_COLOR:
        for (int i = 0; i < 4; i++)
            v[i] = ctx->render.fog.color[i];
        *count = 4;
        return VALUE_FLOAT;
    case RT_MAX_RAY_DEPTH:
        v[0] = ctx->render.max_depth;
        return VALUE_INT;
    case RT_SHADE_MODEL:
        v[0] = ctx->shade_model;
        return VALUE_INT;
    case RT_TEXTURE_BINDING_2D:
        v[0] = ctx->texture_binding;
        return VALUE_INT;
    case RT_MAX_TEXTURE_SIZE:
        v[0] = SCENE_TEXTURE_MAX_SIZE;
        return VALUE_INT;
    case RT_STAT_RAYS:
        v[0] = (double)st->rays;
        return VALUE_INT;
    case RT_STAT_NODE_TESTS:
        v[0] = (double)st->node_tests;
        return VALUE_INT;
    case RT_STAT_TRIANGLE_TESTS:
        v[0] = (double)st->triangle_tests;
        return VALUE_INT;
    case RT_STAT_INSTANCE_TESTS:
        v[0] = (double)st->instance_tests;
        return VALUE_INT;
    case RT_STAT_OBJECT_BUILDS:
        v[0] = (double)st->object_builds;
        return VALUE_INT;
    case RT_STAT_TOPLEVEL_BUILDS:
        v[0] = (double)st->toplevel_builds;
        return VALUE_INT;
    case RT_STAT_OBJECT_UPDATES:
        v[0] = (double)st->object_updates;
        return VALUE_INT;
    case RT_STAT_UPDATE_TIME:
        v[0] = st->update_ms;
        return VALUE_FLOAT;
    case RT_STAT_BUILD_TIME:
        v[0] = st->build_ms;
        return VALUE_FLOAT;
    case RT_STAT_TOPLEVEL_TIME:
        v[0] = st->toplevel_ms;
        return VALUE_FLOAT;
    case RT_STAT_RENDER_TIME:
        v[0] = st->render_ms;
        return VALUE_FLOAT;
    case RT_COLOR_CLEAR_VALUE:
        for (int i = 0; i < 4; i++)
            v[i] = ctx->render.clear_color[i];
        *count = 4;
        return VALUE_FLOAT;
    case RT_LIGHT_MODEL_AMBIENT:
        for (int i = 0; i < 4; i++)
            v[i] = ctx->render.global_ambient[i];
        *count = 4;
        return VALUE_FLOAT;
    case RT_LINE_WIDTH:
        v[0] = ctx->render.vis.line_width;
        return VALUE_FLOAT;
    case RT_POINT_SIZE:
        v[0] = ctx->render.vis.point_size;
        return VALUE_FLOAT;
    case RT_ALIASED_LINE_WIDTH_RANGE:
        v[0] = 1.0;
        v[1] = RENDER_MAX_LINE_WIDTH;
        *count = 2;
        return VALUE_FLOAT;
    case RT_ALIASED_POINT_SIZE_RANGE:
        v[0] = 1.0;
        v[1] = RENDER_MAX_POINT_SIZE;
        *count = 2;
        return VALUE_FLOAT;
    case RT_FRAMES_TRACED:
        v[0] = (double)ctx->frames_traced;
        return VALUE_INT;
    case RT_FRAME_CURRENT:
        v[0] = ctx->gl_frames && !ctx->frame_unrendered && ctx->frames_traced > 0;
        return VALUE_INT;
    case RT_POLYGON_MODE:
        v[0] = ctx->polygon_mode[0];
        v[1] = ctx->polygon_mode[1];
        *count = 2;
        return VALUE_INT;
    case RT_BLEND_SRC:
        v[0] = ctx->render.vis.blend_src;
        return VALUE_INT;
    case RT_BLEND_DST:
        v[0] = ctx->render.vis.blend_dst;
        return VALUE_INT;
    case RT_DEPTH_WRITEMASK:
        v[0] = ctx->render.vis.depth_mask;
        return VALUE_INT;
    case RT_ALPHA_TEST_FUNC:
        v[0] = ctx->render.vis.alpha_func;
        return VALUE_INT;
    case RT_ALPHA_TEST_REF:
        v[0] = ctx->render.vis.alpha_ref;
        return VALUE_FLOAT;
    case RT_POLYGON_OFFSET_FACTOR:
        v[0] = ctx->render.vis.offset_factor;
        return VALUE_FLOAT;
    case RT_POLYGON_OFFSET_UNITS:
        v[0] = ctx->render.vis.offset_units;
        return VALUE_FLOAT;
    case RT_MAX_CLIP_PLANES:
        v[0] = RENDER_MAX_CLIP_PLANES;
        return VALUE_INT;
    case RT_MODELVIEW_MATRIX:
        memcpy(v, ctx->modelview.m[ctx->modelview.depth - 1], 16 * sizeof(double));
        *count = 16;
        return VALUE_MATRIX;
    case RT_PROJECTION_MATRIX:
        memcpy(v, ctx->projection.m[ctx->projection.depth - 1], 16 * sizeof(double));
        *count = 16;
        return VALUE_MATRIX;
    case RT_CURRENT_RASTER_POSITION: /* raster.c */
        for (int i = 0; i < 4; i++)
            v[i] = ctx->raster_pos[i];
        *count = 4;
        return VALUE_FLOAT;
    case RT_CURRENT_RASTER_COLOR:
        for (int i = 0; i < 4; i++)
            v[i] = ctx->raster_color[i];
        *count = 4;
        return VALUE_FLOAT;
    case RT_CURRENT_RASTER_POSITION_VALID:
        v[0] = ctx->raster_valid;
        return VALUE_INT;
    case RT_CURRENT_COLOR:
        for (int i = 0; i < 4; i++)
            v[i] = ctx->current_color[i];
        *count = 4;
        return VALUE_FLOAT;
    case RT_CURRENT_NORMAL:
        for (int i = 0; i < 3; i++)
            v[i] = ctx->current_normal[i];
        *count = 3;
        return VALUE_FLOAT;
    case RT_CURRENT_TEXTURE_COORDS: /* s, t, r, q (GL) */
        for (int i = 0; i < 4; i++)
            v[i] = ctx->current_texcoord[i];
        *count = 4;
        return VALUE_FLOAT;
    case RT_ATTRIB_STACK_DEPTH: /* attrib.c */
        v[0] = ctx->attrib_depth;
        return VALUE_INT;
    case RT_MAX_ATTRIB_STACK_DEPTH:
        v[0] = API_MAX_ATTRIB_STACK_DEPTH;
        return VALUE_INT;
    case RT_CLIENT_ATTRIB_STACK_DEPTH:
        v[0] = ctx->client_attrib_depth;
        return VALUE_INT;
    case RT_MAX_CLIENT_ATTRIB_STACK_DEPTH:
        v[0] = API_MAX_CLIENT_ATTRIB_STACK_DEPTH;
        return VALUE_INT;
    case RT_UNPACK_SWAP_BYTES: /* pixel_store.c */
    case RT_PACK_SWAP_BYTES:
        v[0] = (pname == RT_PACK_SWAP_BYTES ? &ctx->pack : &ctx->unpack)->swap_bytes;
        return VALUE_INT;
    case RT_UNPACK_LSB_FIRST:
    case RT_PACK_LSB_FIRST:
        v[0] = (pname == RT_PACK_LSB_FIRST ? &ctx->pack : &ctx->unpack)->lsb_first;
        return VALUE_INT;
    case RT_UNPACK_ROW_LENGTH:
    case RT_PACK_ROW_LENGTH:
        v[0] = (pname == RT_PACK_ROW_LENGTH ? &ctx->pack : &ctx->unpack)->row_length;
        return VALUE_INT;
    case RT_UNPACK_SKIP_ROWS:
    case RT_PACK_SKIP_ROWS:
        v[0] = (pname == RT_PACK_SKIP_ROWS ? &ctx->pack : &ctx->unpack)->skip_rows;
        return VALUE_INT;
    case RT_UNPACK_SKIP_PIXELS:
    case RT_PACK_SKIP_PIXELS:
        v[0] = (pname == RT_PACK_SKIP_PIXELS ? &ctx->pack : &ctx->unpack)->skip_pixels;
        return VALUE_INT;
    case RT_UNPACK_ALIGNMENT:
    case RT_PACK_ALIGNMENT:
        v[0] = (pname == RT_PACK_ALIGNMENT ? &ctx->pack : &ctx->unpack)->alignment;
        return VALUE_INT;
    default:
        *count = 0;
        return VALUE_NONE;
    }
}

void rtGetIntegerv(RTenum pname, RTint *params)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    double v[16];
    int n;
    enum value_kind kind = state_values(ctx, pname, v, &n);
    if (kind != VALUE_INT) {
        char b1[RT_ENUM_STRING_SIZE];
        rt_error(ctx, RT_INVALID_ENUM, "rtGetIntegerv(pname=%s)", rt_enum_string(pname, b1));
        return;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "rtGetIntegerv(params=NULL)");
        return;
    }
    for (int i = 0; i < n; i++)
        params[i] = v[i] >= (double)INT_MAX ? INT_MAX : (RTint)v[i];
}

void rtGetFloatv(RTenum pname, RTfloat *params)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    double v[16];
    int n;
    if (state_values(ctx, pname, v, &n) == VALUE_NONE) {
        char b1[RT_ENUM_STRING_SIZE];
        rt_error(ctx, RT_INVALID_ENUM, "rtGetFloatv(pname=%s)", rt_enum_string(pname, b1));
        return;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "rtGetFloatv(params=NULL)");
        return;
    }
    for (int i = 0; i < n; i++)
        params[i] = (RTfloat)v[i];
}

/* The flag behind a capability, or NULL when cap is not one.  RT_LIGHTING
 * is the material's byte (per primitive, as GL) and handled by the
 * callers. */
static int *capability(struct rt_context *ctx, RTenum cap)
{
    if (cap >= RT_LIGHT0 && cap < RT_LIGHT0 + RENDER_MAX_LIGHTS)
        return &ctx->render.lights[cap - RT_LIGHT0].enabled;
    switch (cap) {
    case RT_COLOR_MATERIAL:
        return &ctx->color_material;
    case RT_TEXTURE_2D:
        return &ctx->texture_2d;
    case RT_CULL_FACE:
        return &ctx->cull_face_enabled;
    case RT_NORMALIZE:
        return &ctx->normalize_enabled;
    case RT_RESCALE_NORMAL:
        return &ctx->rescale_normal_enabled;
    case RT_FOG:
        return &ctx->render.fog.enabled;
    case RT_TEXTURE_GEN_S:
        return &ctx->texgen_enabled[0];
    case RT_TEXTURE_GEN_T:
        return &ctx->texgen_enabled[1];
    case RT_TEXTURE_GEN_Q:
        return &ctx->texgen_enabled[SCENE_TEXGEN_Q];
    /* Kept for rtIsEnabled and the attribute stack; a 2D texture does not
     * read r, so it changes no geometry (context.h, RT_TEXGEN_R). */
    case RT_TEXTURE_GEN_R:
        return &ctx->texgen_enabled[RT_TEXGEN_R];
    case RT_BLEND:
        return &ctx->render.vis.blend;
    /* No ray tracing meaning: accepted and remembered (docs/appearance.md). */
    case RT_DEPTH_TEST:
        return &ctx->depth_test;
    case RT_DITHER:
        return &ctx->dither;
    case RT_POLYGON_OFFSET_FILL:
        return &ctx->polygon_offset_fill;
    case RT_ALPHA_TEST:
        return &ctx->render.vis.alpha_test;
    default:
        if (cap >= RT_CLIP_PLANE0 && cap < RT_CLIP_PLANE0 + RENDER_MAX_CLIP_PLANES)
            return &ctx->render.vis.clip_enabled[cap - RT_CLIP_PLANE0];
        return NULL;
    }
}

static void set_capability(const char *caller, RTenum cap, int value)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    if (cap == RT_LIGHTING) {
        rt_list_state(ctx, value ? LIST_ENABLE : LIST_DISABLE, cap, 0, NULL, 0);
        if (value) /* the eye-light and Whitted modes honour it from now on */
            ctx->render.lighting_used = 1;
        if (ctx->material.lighting != (uint8_t)value) {
            ctx->material.lighting = (uint8_t)value;
            ctx->recording.material_index = -1;
        }
        return;
    }
    int *flag = capability(ctx, cap);
    if (!flag) {
        char b1[RT_ENUM_STRING_SIZE];
        rt_error(ctx, RT_INVALID_ENUM, "%s(cap=%s): not a capability", caller,
                 rt_enum_string(cap, b1));
        return;
    }
    rt_list_state(ctx, value ? LIST_ENABLE : LIST_DISABLE, cap, 0, NULL, 0);
    /* Tracking ends: the tracked properties keep the current colour. */
    if (cap == RT_COLOR_MATERIAL && !value && *flag)
        rt_color_material_settle(ctx, caller);
    if (cap == RT_COLOR_MATERIAL && value && !*flag)
        ctx->color_material_current = 1; /* GL writes the colour at the enable */
    *flag = value;
    /* Clip planes are per primitive: a list's later geometry gets a
     * segment of its own (list.c). */
    if (cap >= RT_CLIP_PLANE0 && cap < RT_CLIP_PLANE0 + RENDER_MAX_CLIP_PLANES)
        rt_list_state_changed(ctx, caller);
    /* So is the raster state triangles take (scene/raster_state.h). */
    if (cap == RT_BLEND || cap == RT_ALPHA_TEST || cap == RT_POLYGON_OFFSET_FILL)
        rt_list_state_changed(ctx, caller);
    if (cap == RT_CULL_FACE || cap == RT_NORMALIZE || cap == RT_RESCALE_NORMAL ||
        cap == RT_TEXTURE_GEN_S || cap == RT_TEXTURE_GEN_T || cap == RT_TEXTURE_GEN_Q)
        rt_sync_fixed_function(ctx);
    /* Fog and texture generation reach a list's geometry through its
     * instance (scene/gl_state.h, list.c): a segment of its own. */
    if (cap == RT_FOG || cap == RT_TEXTURE_GEN_S || cap == RT_TEXTURE_GEN_T ||
        cap == RT_TEXTURE_GEN_Q)
        rt_list_state_changed(ctx, caller);
    /* So do the light enables (scene/gl_state.h, light_set). */
    if (cap >= RT_LIGHT0 && cap < RT_LIGHT0 + RENDER_MAX_LIGHTS)
        rt_list_state_changed(ctx, caller);
}

void rtEnable(RTenum cap)
{
    set_capability("rtEnable", cap, 1);
}

void rtDisable(RTenum cap)
{
    set_capability("rtDisable", cap, 0);
}

RTboolean rtIsEnabled(RTenum cap)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtIsEnabled"))
        return RT_FALSE;
    if (cap == RT_LIGHTING)
        return ctx->material.lighting ? RT_TRUE : RT_FALSE;
    /* GL's glIsEnabled also answers for the client arrays (array.c). */
    const struct client_array *array = cap == RT_VERTEX_ARRAY   ? &ctx->vertex_array
                                       : cap == RT_NORMAL_ARRAY ? &ctx->normal_array
                                       : cap == RT_COLOR_ARRAY  ? &ctx->color_array
                                       : cap == RT_TEXTURE_COORD_ARRAY ? &ctx->texcoord_array
                                                                       : NULL;
    if (array)
        return array->enabled ? RT_TRUE : RT_FALSE;
    int *flag = capability(ctx, cap);
    if (!flag) {
        char b1[RT_ENUM_STRING_SIZE];
        rt_error(ctx, RT_INVALID_ENUM, "rtIsEnabled(cap=%s): not a capability",
                 rt_enum_string(cap, b1));
        return RT_FALSE;
    }
    return *flag ? RT_TRUE : RT_FALSE;
}

/* GL: a capability reads as its flag; any other state as "non-zero". */
void rtGetBooleanv(RTenum pname, RTboolean *params)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    double v[16];
    int n;
    char b1[RT_ENUM_STRING_SIZE];
    int *flag = pname == RT_LIGHTING ? NULL : capability(ctx, pname);
    if (pname == RT_LIGHTING || flag) {
        if (!params) {
            rt_error(ctx, RT_INVALID_VALUE, "rtGetBooleanv(params=NULL)");
            return;
        }
        params[0] = (pname == RT_LIGHTING ? ctx->material.lighting : *flag) ? RT_TRUE : RT_FALSE;
        return;
    }
    if (state_values(ctx, pname, v, &n) == VALUE_NONE) {
        rt_error(ctx, RT_INVALID_ENUM, "rtGetBooleanv(pname=%s)", rt_enum_string(pname, b1));
        return;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "rtGetBooleanv(params=NULL)");
        return;
    }
    for (int i = 0; i < n; i++)
        params[i] = v[i] != 0.0 ? RT_TRUE : RT_FALSE;
}
