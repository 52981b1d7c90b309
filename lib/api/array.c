/* SPDX-License-Identifier: Apache-2.0 */
/*
 * array.c - vertex arrays: rt*Pointer, rtEnable/DisableClientState,
 * rtDrawArrays and rtDrawElements.
 *
 * A draw call is exactly the rtBegin/rtVertex/rtEnd sequence it stands
 * for (GL's definition of glDrawArrays), with the data read at the call.
 * The whole batch is validated before the first vertex is stored, so a
 * rejected call records nothing.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "api/context.h"
#include "base/alloc.h"
#include "scene/assembly.h"

static struct client_array *client_array_of(struct rt_context *ctx, RTenum array)
{
    switch (array) {
    case RT_VERTEX_ARRAY:
        return &ctx->vertex_array;
    case RT_NORMAL_ARRAY:
        return &ctx->normal_array;
    case RT_COLOR_ARRAY:
        return &ctx->color_array;
    case RT_TEXTURE_COORD_ARRAY:
        return &ctx->texcoord_array;
    default:
        return NULL;
    }
}

static void client_state(const char *caller, RTenum array, int enabled)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    struct client_array *a = client_array_of(ctx, array);
    if (!a) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(array=0x%x)", caller, array);
        return;
    }
    a->enabled = enabled;
}

void rtEnableClientState(RTenum array)
{
    client_state("rtEnableClientState", array, 1);
}

void rtDisableClientState(RTenum array)
{
    client_state("rtDisableClientState", array, 0);
}

static size_t type_size(RTenum type)
{
    switch (type) {
    case RT_BYTE:
    case RT_UNSIGNED_BYTE:
        return 1;
    case RT_SHORT:
    case RT_UNSIGNED_SHORT:
        return 2;
    case RT_INT:
    case RT_UNSIGNED_INT:
    case RT_FLOAT:
        return 4;
    case RT_DOUBLE:
        return 8;
    default:
        return 0;
    }
}

/* Sets an array pointer after checking type (against the allowed list),
 * size range and stride. */
static void set_pointer(const char *caller, struct client_array *(*which)(struct rt_context *),
                        RTint size, int size_lo, int size_hi, RTenum type, const RTenum *types,
                        int type_count, RTsizei stride, const void *pointer)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    int type_ok = 0;
    for (int i = 0; i < type_count; i++)
        type_ok |= types[i] == type;
    if (!type_ok) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(type=0x%x)", caller, type);
        return;
    }
    if (size < size_lo || size > size_hi || stride < 0) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(size=%d, stride=%d)", caller, size, stride);
        return;
    }
    struct client_array *a = which(ctx);
    a->size = size;
    a->type = type;
    a->stride = stride;
    a->pointer = pointer;
}

static struct client_array *vertex_array(struct rt_context *ctx)
{
    return &ctx->vertex_array;
}

static struct client_array *normal_array(struct rt_context *ctx)
{
    return &ctx->normal_array;
}

static struct client_array *color_array(struct rt_context *ctx)
{
    return &ctx->color_array;
}

static struct client_array *texcoord_array(struct rt_context *ctx)
{
    return &ctx->texcoord_array;
}

void rtVertexPointer(RTint size, RTenum type, RTsizei stride, const void *pointer)
{
    static const RTenum types[] = {RT_SHORT, RT_INT, RT_FLOAT, RT_DOUBLE};
    set_pointer("rtVertexPointer", vertex_array, size, 2, 4, type, types, 4, stride, pointer);
}

void rtNormalPointer(RTenum type, RTsizei stride, const void *pointer)
{
    static const RTenum types[] = {RT_BYTE, RT_SHORT, RT_INT, RT_FLOAT, RT_DOUBLE};
    set_pointer("rtNormalPointer", normal_array, 3, 3, 3, type, types, 5, stride, pointer);
}

void rtColorPointer(RTint size, RTenum type, RTsizei stride, const void *pointer)
{
    static const RTenum types[] = {RT_UNSIGNED_BYTE, RT_FLOAT, RT_DOUBLE};
    set_pointer("rtColorPointer", color_array, size, 3, 4, type, types, 3, stride, pointer);
}

void rtTexCoordPointer(RTint size, RTenum type, RTsizei stride, const void *pointer)
{
    static const RTenum types[] = {RT_SHORT, RT_INT, RT_FLOAT, RT_DOUBLE};
    set_pointer("rtTexCoordPointer", texcoord_array, size, 1, 4, type, types, 4, stride,
                pointer);
}

/* Reads component c of element i of an array as a double.  Normalised
 * types follow GL's conversions for colours (ubyte / 255) and normals
 * (signed: c / (2^(b-1) - 1)). */
static double fetch(const struct client_array *a, size_t i, int c, int normalized)
{
    size_t stride = a->stride ? (size_t)a->stride : (size_t)a->size * type_size(a->type);
    const unsigned char *p = (const unsigned char *)a->pointer + i * stride;
    size_t off = (size_t)c * type_size(a->type);
    switch (a->type) {
    case RT_BYTE: {
        int8_t v;
        memcpy(&v, p + off, sizeof(v));
        return normalized ? v / 127.0 : v;
    }
    case RT_UNSIGNED_BYTE: {
        uint8_t v;
        memcpy(&v, p + off, sizeof(v));
        return normalized ? v / 255.0 : v;
    }
    case RT_SHORT: {
        int16_t v;
        memcpy(&v, p + off, sizeof(v));
        return normalized ? v / 32767.0 : v;
    }
    case RT_INT: {
        int32_t v;
        memcpy(&v, p + off, sizeof(v));
        return normalized ? v / 2147483647.0 : v;
    }
    case RT_FLOAT: {
        float v;
        memcpy(&v, p + off, sizeof(v));
        return v;
    }
    default: {
        double v;
        memcpy(&v, p + off, sizeof(v));
        return v;
    }
    }
}

/* Object-space position of element i; 0 when not finite (or w == 0). */
static int fetch_position(const struct client_array *a, size_t i, double p[3])
{
    for (int c = 0; c < 3; c++)
        p[c] = c < a->size ? fetch(a, i, c, 0) : 0.0;
    if (a->size == 4) {
        double w = fetch(a, i, 3, 0);
        if (w == 0.0 || !isfinite(w))
            return 0;
        for (int c = 0; c < 3; c++)
            p[c] /= w;
    }
    return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]);
}

/* 1 when the first `components` values of element i of an enabled
 * attribute array are finite (integer types always are).  Attributes are
 * stored as float, so a finite double beyond the float range counts as
 * infinite: the rule of vertices (rt_vertex_is_finite) and of
 * rtUpdateVertices, one rule for every array (docs/arrays.md). */
static int attribute_is_finite(const struct client_array *a, size_t i, int components)
{
    if (!a->enabled || (a->type != RT_FLOAT && a->type != RT_DOUBLE))
        return 1;
    for (int c = 0; c < components; c++)
        if (!isfinite((float)fetch(a, i, c, 0)))
            return 0;
    return 1;
}

/* The texture coordinates checked for finiteness: s, t and, with four
 * components, q (r has no meaning for 2D textures). */
static int texcoord_read(const struct client_array *a)
{
    return a->size == 4 ? 4 : (a->size < 2 ? a->size : 2);
}

/* Reads element i's attributes, falling back to the current attribute for
 * disabled arrays (GL). */
static void fetch_element(struct rt_context *ctx, size_t i, double p[3], float normal[3],
                          float color[4], float texcoord[4])
{
    fetch_position(&ctx->vertex_array, i, p);
    memcpy(normal, ctx->current_normal, 3 * sizeof(float));
    memcpy(color, ctx->current_color, 4 * sizeof(float));
    memcpy(texcoord, ctx->current_texcoord, 4 * sizeof(float));
    if (ctx->normal_array.enabled)
        for (int c = 0; c < 3; c++)
            normal[c] = (float)fetch(&ctx->normal_array, i, c, 1);
    if (ctx->color_array.enabled) {
        color[3] = 1.0f;
        for (int c = 0; c < ctx->color_array.size; c++)
            color[c] = fminf(fmaxf((float)fetch(&ctx->color_array, i, c, 1), 0.0f), 1.0f);
    }
    if (ctx->texcoord_array.enabled) {
        /* GL's missing components: t = r = 0, q = 1. */
        texcoord[1] = texcoord[2] = 0.0f;
        texcoord[3] = 1.0f;
        for (int c = 0; c < ctx->texcoord_array.size; c++)
            texcoord[c] = (float)fetch(&ctx->texcoord_array, i, c, 0);
    }
}

/* Stores element i as the next vertex of the stream and assembles. */
static int emit_element(struct rt_context *ctx, const char *caller, size_t i)
{
    double p[3];
    float normal[3], color[4], texcoord[4];
    fetch_element(ctx, i, p, normal, color, texcoord);
    return rt_record_vertex(ctx, caller, p, normal, color, texcoord);
}

/* Checks common to both draw calls; returns 1 when the call may proceed. */
static int draw_allowed(struct rt_context *ctx, const char *caller, RTenum mode)
{
    if (ctx->block.active) {
        rt_error(ctx, RT_INVALID_OPERATION, "%s: not allowed between rtBegin and rtEnd", caller);
        return 0;
    }
    if (!scene_mode_is_valid(mode) && !scene_lines_mode_is_valid(mode)) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(mode=0x%x)", caller, mode);
        return 0;
    }
    return 1;
}

static int arrays_ready(struct rt_context *ctx, const char *caller)
{
    const struct client_array *arrays[4] = {&ctx->vertex_array, &ctx->normal_array,
                                            &ctx->color_array, &ctx->texcoord_array};
    if (!ctx->vertex_array.enabled) {
        rt_error(ctx, RT_INVALID_OPERATION, "%s: RT_VERTEX_ARRAY is not enabled", caller);
        return 0;
    }
    for (int i = 0; i < 4; i++)
        if (arrays[i]->enabled && !arrays[i]->pointer) {
            rt_error(ctx, RT_INVALID_OPERATION, "%s: an enabled array has a NULL pointer",
                     caller);
            return 0;
        }
    return 1;
}

/* Index k of the batch: first + k for rtDrawArrays, indices[k] otherwise. */
static size_t element_index(RTenum index_type, const void *indices, size_t first, size_t k)
{
    if (!indices)
        return first + k;
    switch (index_type) {
    case RT_UNSIGNED_BYTE:
        return ((const uint8_t *)indices)[k];
    case RT_UNSIGNED_SHORT:
        return ((const uint16_t *)indices)[k];
    default:
        return ((const uint32_t *)indices)[k];
    }
}

/* rtDrawArrays: the elements in order, exactly as rtBegin/rtVertex/rtEnd. */
static void draw_sequential(struct rt_context *ctx, const char *caller, size_t first,
                            size_t count)
{
    /* Reserve up front so the batch cannot fail half-way. */
    struct scene_mesh *mesh = &ctx->target->mesh;
    if (count > UINT32_MAX / 2 || scene_mesh_reserve_vertices(mesh, (uint32_t)count) ||
        scene_mesh_reserve_triangles(mesh, (uint32_t)(2 * count))) {
        ctx->target->out_of_memory = 1;
        rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory", caller);
        return;
    }
    for (size_t k = 0; k < count; k++)
        if (emit_element(ctx, caller, first + k))
            return; /* only a material allocation can fail here; recorded */
}

/*
 * rtDrawElements: the array elements from the smallest to the largest
 * index used are stored once each, in array order (so an object's vertex
 * k is array element min + k, which rtUpdateVertices relies on), and the
 * triangles index them.  Elements in that range that no index uses are
 * stored as the origin with the current attributes and are referenced by
 * no triangle.  As glDrawRangeElements, a sparse index range costs memory
 * for the whole range.
 */
static void draw_indexed(struct rt_context *ctx, const char *caller, size_t count,
                         RTenum index_type, const void *indices)
{
    if (count == 0)
        return;
    size_t lo = SIZE_MAX, hi = 0;
    for (size_t k = 0; k < count; k++) {
        size_t i = element_index(index_type, indices, 0, k);
        lo = i < lo ? i : lo;
        hi = i > hi ? i : hi;
    }
    size_t range = hi - lo + 1;
    struct scene_mesh *mesh = &ctx->target->mesh;
    uint32_t *map = NULL;
    unsigned char *used = NULL;
    if (range > UINT32_MAX / 2 || count > UINT32_MAX / 2 ||
        !(map = rt_malloc(count * sizeof(*map))) || !(used = rt_calloc(range, 1)) ||
        scene_mesh_reserve_vertices(mesh, (uint32_t)range) ||
        scene_mesh_reserve_triangles(mesh, (uint32_t)(2 * count))) {
        rt_free(map);
        rt_free(used);
        ctx->target->out_of_memory = 1;
        rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory", caller);
        return;
    }
    uint32_t base = mesh->vertex_count;
    for (size_t k = 0; k < count; k++) {
        size_t i = element_index(index_type, indices, 0, k);
        used[i - lo] = 1;
        map[k] = base + (uint32_t)(i - lo);
    }
    for (size_t e = 0; e < range; e++) {
        double p[3] = {0.0, 0.0, 0.0};
        float normal[3], color[4], texcoord[4];
        if (used[e]) {
            fetch_element(ctx, lo + e, p, normal, color, texcoord);
        } else {
            /* Not validated, so not read: the application may keep
             * anything in elements no index uses. */
            memcpy(normal, ctx->current_normal, sizeof(normal));
            memcpy(color, ctx->current_color, sizeof(color));
            memcpy(texcoord, ctx->current_texcoord, sizeof(texcoord));
        }
        /* Cannot fail: room reserved and every used element validated. */
        rt_store_vertex(ctx, caller, p, normal, color, texcoord);
    }
    for (size_t k = 0; k < count; k++)
        if (rt_assemble_indexed(ctx, caller, (uint32_t)k, map))
            break; /* only a material allocation can fail here; recorded */
    rt_free(map);
    rt_free(used);
}

/* A batch that gives lines or points (lines.c): every index in order, as
 * the rtBegin/rtArrayElement/rtEnd sequence it stands for (vertices are
 * not shared: lines are not traced). */
static void draw_lines(struct rt_context *ctx, const char *caller, RTenum index_type,
                       const void *indices, size_t first, size_t count)
{
    for (size_t k = 0; k < count; k++) {
        double p[3];
        float normal[3], color[4], texcoord[4];
        fetch_element(ctx, element_index(index_type, indices, first, k), p, normal, color,
                      texcoord);
        if (rt_lines_vertex(ctx, caller, p, color)) {
            ctx->lines_block = 0;
            return;
        }
    }
    rt_lines_block_end(ctx, caller);
}

static void draw(struct rt_context *ctx, const char *caller, RTenum mode, size_t first,
                 size_t count, RTenum index_type, const void *indices)
{
    /* Validate every vertex first: a rejected batch stores nothing.  A
     * non-finite normal, colour or texture coordinate is rejected as
     * rtNormal, rtColor and rtTexCoord reject it (only the components
     * emit_element reads are checked). */
    if (rt_block_start(ctx, mode)) {
        rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory", caller);
        return;
    }
    int texcoord_components = texcoord_read(&ctx->texcoord_array);
    for (size_t k = 0; k < count; k++) {
        double p[3];
        size_t i = element_index(index_type, indices, first, k);
        if (!fetch_position(&ctx->vertex_array, i, p) || !rt_vertex_is_finite(ctx, p)) {
            rt_error(ctx, RT_INVALID_VALUE, "%s: vertex %zu is not finite", caller, i);
            return;
        }
        if (!attribute_is_finite(&ctx->normal_array, i, 3) ||
            !attribute_is_finite(&ctx->color_array, i, ctx->color_array.size) ||
            !attribute_is_finite(&ctx->texcoord_array, i, texcoord_components)) {
            rt_error(ctx, RT_INVALID_VALUE, "%s: an attribute of vertex %zu is not finite",
                     caller, i);
            return;
        }
    }
    int lines = rt_lines_block_start(ctx, mode);
    if (lines < 0) {
        rt_error(ctx, RT_OUT_OF_MEMORY, "%s: out of memory", caller);
        return;
    }
    if (lines) {
        draw_lines(ctx, caller, index_type, indices, first, count);
        return;
    }
    /* Colours from an array are the list's own (not the caller's). */
    if (ctx->color_array.enabled && count > 0 && ctx->target == &ctx->recording)
        ctx->recording.color_set = 1;
    /* Normals from an array count as set normals (see rtNormal3f). */
    if (ctx->normal_array.enabled && count > 0) {
        ctx->target->mesh.has_normals = 1;
        if (ctx->target != &ctx->recording)
            ctx->normal_given = 1;
    }
    if (indices)
        draw_indexed(ctx, caller, count, index_type, indices);
    else
        draw_sequential(ctx, caller, first, count);
    scene_block_close_polygon(ctx->target, &ctx->block, (uint32_t)count);
}

void rtDrawArrays(RTenum mode, RTint first, RTsizei count)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || !draw_allowed(ctx, "rtDrawArrays", mode))
        return;
    if (first < 0 || count < 0) {
        rt_error(ctx, RT_INVALID_VALUE, "rtDrawArrays(first=%d, count=%d)", first, count);
        return;
    }
    if (!arrays_ready(ctx, "rtDrawArrays"))
        return;
    draw(ctx, "rtDrawArrays", mode, (size_t)first, (size_t)count, 0, NULL);
}

void rtDrawElements(RTenum mode, RTsizei count, RTenum type, const void *indices)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || !draw_allowed(ctx, "rtDrawElements", mode))
        return;
    if (type != RT_UNSIGNED_BYTE && type != RT_UNSIGNED_SHORT && type != RT_UNSIGNED_INT) {
        rt_error(ctx, RT_INVALID_ENUM, "rtDrawElements(type=0x%x)", type);
        return;
    }
    /* NULL indices are invalid whatever the count (docs/arrays.md): there
     * is no element array buffer an offset could refer to. */
    if (count < 0 || !indices) {
        rt_error(ctx, RT_INVALID_VALUE, "rtDrawElements(count=%d, indices=%p)", count, indices);
        return;
    }
    if (!arrays_ready(ctx, "rtDrawElements"))
        return;
    draw(ctx, "rtDrawElements", mode, 0, (size_t)count, type, indices);
}

/* glArrayElement: element i as the next vertex of the current rtBegin
 * block (in a list or immediate mode), with its attributes, which become
 * the current ones as GL's glArrayElement issues glColor, glNormal and
 * glTexCoord.  Outside rtBegin/rtEnd it is RT_INVALID_OPERATION here: a
 * vertex has no primitive to join. */
void rtArrayElement(RTint i)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    if (!ctx->block.active) {
        rt_error(ctx, RT_INVALID_OPERATION, "rtArrayElement: only allowed between rtBegin and rtEnd");
        return;
    }
    if (i < 0) {
        rt_error(ctx, RT_INVALID_VALUE, "rtArrayElement(i=%d)", i);
        return;
    }
    if (!arrays_ready(ctx, "rtArrayElement"))
        return;
    size_t e = (size_t)i;
    double p[3];
    int texcoord_components = texcoord_read(&ctx->texcoord_array);
    if (!fetch_position(&ctx->vertex_array, e, p) || !rt_vertex_is_finite(ctx, p) ||
        !attribute_is_finite(&ctx->normal_array, e, 3) ||
        !attribute_is_finite(&ctx->color_array, e, ctx->color_array.size) ||
        !attribute_is_finite(&ctx->texcoord_array, e, texcoord_components)) {
        rt_error(ctx, RT_INVALID_VALUE, "rtArrayElement(i=%d): not finite", i);
        return;
    }
    float normal[3], color[4], texcoord[4];
    fetch_element(ctx, e, p, normal, color, texcoord);
    if (ctx->normal_array.enabled)
        rtNormal3fv(normal);
    if (ctx->color_array.enabled)
        rtColor4fv(color);
    if (ctx->texcoord_array.enabled)
        rtTexCoord4fv(texcoord);
    rt_record_vertex(ctx, "rtArrayElement", p, normal, color, texcoord);
}
