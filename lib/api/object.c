/* SPDX-License-Identifier: Apache-2.0 */
/*
 * object.c - objects, the display lists of Tracelist: rtGenObjects,
 * rtDeleteObjects, rtIsObject, rtGetObject*, rtObjectParameteri,
 * rtUpdateVertices.  rtNewObject and rtEndObject are rtNewList(RT_COMPILE)
 * and rtEndList (list.c).
 *
 * A definition is recorded into a private mesh and swapped in whole at
 * rtEndObject, so instances keep showing the previous definition until
 * the new one is complete (and keep it if recording ran out of memory).
 */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "api/context.h"

void rtGenObjects(RTsizei n, RTuint *names)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtGenObjects"))
        return;
    if (n < 0 || (n > 0 && !names)) {
        rt_error(ctx, RT_INVALID_VALUE, "rtGenObjects(n=%d, objects=%p)", n, (void *)names);
        return;
    }
    if (scene_objects_generate(&ctx->scene.objects, (uint32_t)n, names))
        rt_error(ctx, RT_OUT_OF_MEMORY, "rtGenObjects(n=%d): out of memory", n);
}

void rtDeleteObjects(RTsizei n, const RTuint *names)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_object(ctx, "rtDeleteObjects"))
        return;
    if (n < 0 || (n > 0 && !names)) {
        rt_error(ctx, RT_INVALID_VALUE, "rtDeleteObjects(n=%d, objects=%p)", n,
                 (const void *)names);
        return;
    }
    /* 0 and unknown names are ignored, as glDeleteLists. */
    for (RTsizei i = 0; i < n; i++)
        scene_delete_object(&ctx->scene, names[i]);
}

RTboolean rtIsObject(RTuint name)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtIsObject"))
        return RT_FALSE;
    const struct scene_object *object = scene_objects_lookup(&ctx->scene.objects, name);
    return object && object->defined ? RT_TRUE : RT_FALSE;
}

/* Looks up a defined object for a query; records RT_INVALID_VALUE if none. */
static const struct scene_object *query_object(struct rt_context *ctx, const char *caller,
                                               RTuint name, const void *params)
{
    const struct scene_object *object = scene_objects_lookup(&ctx->scene.objects, name);
    if (!object || !object->defined) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(object=%u): not an object", caller, name);
        return NULL;
    }
    if (!params) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(params=NULL)", caller);
        return NULL;
    }
    return object;
}

static int pname_is_valid(RTenum pname, int as_float)
{
    switch (pname) {
    case RT_OBJECT_TRIANGLES:
    case RT_OBJECT_BUILT:
    case RT_OBJECT_BVH_NODES:
    case RT_OBJECT_BOUNDS:
    case RT_OBJECT_CLASS:
    case RT_UPDATE_STRATEGY:
    case RT_OBJECT_REBUILDS:
    case RT_OBJECT_REFITS:
    case RT_OBJECT_VERTICES:
    case RT_ACCELERATION_HINT:
        return 1;
    case RT_OBJECT_SAH_COST:
    case RT_OBJECT_BUILD_TIME:
    case RT_OBJECT_UPDATE_TIME:
        return as_float;
    default:
        return 0;
    }
}

void rtGetObjectiv(RTuint name, RTenum pname, RTint *params)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtGetObjectiv"))
        return;
    if (!pname_is_valid(pname, 0)) {
        rt_error(ctx, RT_INVALID_ENUM, "rtGetObjectiv(pname=0x%x)", pname);
        return;
    }
    const struct scene_object *object = query_object(ctx, "rtGetObjectiv", name, params);
    if (!object)
        return;
    double v[6];
    int n = scene_object_values(object, pname, v);
    for (int i = 0; i < n; i++)
        params[i] = v[i] >= INT_MAX ? INT_MAX : v[i] <= INT_MIN ? INT_MIN : (RTint)v[i];
}

void rtGetObjectfv(RTuint name, RTenum pname, RTfloat *params)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtGetObjectfv"))
        return;
    if (!pname_is_valid(pname, 1)) {
        rt_error(ctx, RT_INVALID_ENUM, "rtGetObjectfv(pname=0x%x)", pname);
        return;
    }
    const struct scene_object *object = query_object(ctx, "rtGetObjectfv", name, params);
    if (!object)
        return;
    double v[6];
    int n = scene_object_values(object, pname, v);
    for (int i = 0; i < n; i++)
        params[i] = (RTfloat)v[i];
}

/* 1 when s names an update strategy usable as a hint (RT_AUTOMATIC
 * included). */
int rt_strategy_is_valid(RTenum s)
{
    switch (s) {
    case RT_AUTOMATIC:
    case RT_REFIT:
    case RT_REBUILD:
    case RT_REBUILD_MEDIAN:
    case RT_REBUILD_HEURISTIC:
    case RT_RESTRUCTURE:
    case RT_ASYNC_REBUILD:
        return 1;
    default:
        return 0;
    }
}

void rtObjectParameteri(RTuint name, RTenum pname, RTint param)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtObjectParameteri"))
        return;
    RTenum value = (RTenum)param;
    int valid_value;
    if (pname == RT_OBJECT_CLASS)
        valid_value = value == RT_AUTOMATIC || value == RT_STATIC || value == RT_AFFINE ||
                      value == RT_UNSTRUCTURED;
    else if (pname == RT_UPDATE_STRATEGY)
        valid_value = rt_strategy_is_valid(value);
    else {
        rt_error(ctx, RT_INVALID_ENUM, "rtObjectParameteri(pname=0x%x)", pname);
        return;
    }
    if (!valid_value) {
        rt_error(ctx, RT_INVALID_ENUM, "rtObjectParameteri(pname=0x%x, param=0x%x)", pname,
                 value);
        return;
    }
    struct scene_object *object = scene_objects_lookup(&ctx->scene.objects, name);
    if (!object || !object->defined) {
        rt_error(ctx, RT_INVALID_VALUE, "rtObjectParameteri(object=%u): not an object", name);
        return;
    }
    if (pname == RT_OBJECT_CLASS)
        object->class_hint = value;
    else
        object->strategy_hint = value;
}

void rtUpdateVertices(RTuint name, RTenum array, RTint first, RTsizei count, RTenum type,
                      RTsizei stride, const void *data)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_object(ctx, "rtUpdateVertices"))
        return;
    if (array != RT_VERTEX_ARRAY && array != RT_NORMAL_ARRAY) {
        rt_error(ctx, RT_INVALID_ENUM, "rtUpdateVertices(array=0x%x)", array);
        return;
    }
    if (type != RT_FLOAT && type != RT_DOUBLE) {
        rt_error(ctx, RT_INVALID_ENUM, "rtUpdateVertices(type=0x%x)", type);
        return;
    }
    struct scene_object *object = scene_objects_lookup(&ctx->scene.objects, name);
    if (!object || !object->defined) {
        rt_error(ctx, RT_INVALID_VALUE, "rtUpdateVertices(object=%u): not an object", name);
        return;
    }
    struct scene_mesh *mesh = &object->mesh;
    if (first < 0 || count < 0 || stride < 0 || (count > 0 && !data) ||
        (uint64_t)first + (uint64_t)count > mesh->vertex_count) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "rtUpdateVertices(first=%d, count=%d, stride=%d, data=%p): object %u has %u "
                 "vertices",
                 first, count, stride, data, name, mesh->vertex_count);
        return;
    }
    size_t element = 3 * (type == RT_FLOAT ? sizeof(float) : sizeof(double));
    size_t step = stride ? (size_t)stride : element;
    /* Validate the whole batch first: a rejected call changes nothing. */
    for (RTsizei i = 0; i < count; i++)
        for (int c = 0; c < 3; c++) {
            double v = scene_array_component(data, type == RT_DOUBLE, step, (size_t)i, c);
            if (!isfinite((float)v)) {
                rt_error(ctx, RT_INVALID_VALUE,
                         "rtUpdateVertices: element %d is not finite as a float", i);
                return;
            }
        }
    scene_update_vertices(&ctx->scene, object, array == RT_NORMAL_ARRAY, (uint32_t)first,
                          (uint32_t)count, data, type == RT_DOUBLE, step);
}
