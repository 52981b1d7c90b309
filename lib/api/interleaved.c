/* SPDX-License-Identifier: Apache-2.0 */
/*
 * interleaved.c - rtInterleavedArrays: GL 1.1's interleaved vertex array
 * formats (OpenGL 1.1 spec sec. 2.8, table 2.5), set through the ordinary
 * array pointers (array.c) after GL's checks.  The two formats with four
 * texture coordinates (RT_T4F_V4F, RT_T4F_C4F_N3F_V4F) give projective
 * coordinates (s, t, r, q) and homogeneous vertices (x, y, z, w).
 */
#include "api/context.h"
#include "api/enum_names.h"

/* One row of table 2.5: which arrays, their sizes and offsets (bytes),
 * and the default stride. */
struct interleaved_format {
    RTenum format;
    int texcoords; /* texture coordinate components, 0 for none */
    int color_size, normals, vertex_size;
    RTenum color_type;
    int color_offset, normal_offset, vertex_offset, stride;
};

#define F ((int)sizeof(float))
/* c: four unsigned bytes padded to a float multiple. */
#define C4UB 4

static const struct interleaved_format formats[] = {
    {RT_V2F, 0, 0, 0, 2, 0, 0, 0, 0, 2 * F},
    {RT_V3F, 0, 0, 0, 3, 0, 0, 0, 0, 3 * F},
    {RT_C4UB_V2F, 0, 4, 0, 2, RT_UNSIGNED_BYTE, 0, 0, C4UB, C4UB + 2 * F},
    {RT_C4UB_V3F, 0, 4, 0, 3, RT_UNSIGNED_BYTE, 0, 0, C4UB, C4UB + 3 * F},
    {RT_C3F_V3F, 0, 3, 0, 3, RT_FLOAT, 0, 0, 3 * F, 6 * F},
    {RT_N3F_V3F, 0, 0, 1, 3, 0, 0, 0, 3 * F, 6 * F},
    {RT_C4F_N3F_V3F, 0, 4, 1, 3, RT_FLOAT, 0, 4 * F, 7 * F, 10 * F},
    {RT_T2F_V3F, 2, 0, 0, 3, 0, 0, 0, 2 * F, 5 * F},
    {RT_T2F_C4UB_V3F, 2, 4, 0, 3, RT_UNSIGNED_BYTE, 2 * F, 0, 2 * F + C4UB, 5 * F + C4UB},
    {RT_T2F_C3F_V3F, 2, 3, 0, 3, RT_FLOAT, 2 * F, 0, 5 * F, 8 * F},
    {RT_T2F_N3F_V3F, 2, 0, 1, 3, 0, 0, 2 * F, 5 * F, 8 * F},
    {RT_T2F_C4F_N3F_V3F, 2, 4, 1, 3, RT_FLOAT, 2 * F, 6 * F, 9 * F, 12 * F},
    {RT_T4F_V4F, 4, 0, 0, 4, 0, 0, 0, 4 * F, 8 * F},
    {RT_T4F_C4F_N3F_V4F, 4, 4, 1, 4, RT_FLOAT, 4 * F, 8 * F, 11 * F, 15 * F},
};

void rtInterleavedArrays(RTenum format, RTsizei stride, const void *pointer)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, "rtInterleavedArrays"))
        return;
    const struct interleaved_format *f = NULL;
    for (size_t i = 0; i < sizeof formats / sizeof formats[0]; i++)
        if (formats[i].format == format)
            f = &formats[i];
    if (!f) {
        char b1[RT_ENUM_STRING_SIZE];
        rt_error(ctx, RT_INVALID_ENUM, "rtInterleavedArrays(format=%s)",
                 rt_enum_string(format, b1));
        return;
    }
    if (stride < 0) {
        rt_error(ctx, RT_INVALID_VALUE, "rtInterleavedArrays(stride=%d): negative", stride);
        return;
    }
    const RTsizei s = stride ? stride : f->stride;
    const char *base = pointer;
    /* GL: the texture coordinate, colour and normal arrays the format
     * lacks are disabled; the vertex array is enabled. */
    if (f->texcoords) {
        rtTexCoordPointer(f->texcoords, RT_FLOAT, s, base);
        rtEnableClientState(RT_TEXTURE_COORD_ARRAY);
    } else {
        rtDisableClientState(RT_TEXTURE_COORD_ARRAY);
    }
    if (f->color_size) {
        rtColorPointer(f->color_size, f->color_type, s, base + f->color_offset);
        rtEnableClientState(RT_COLOR_ARRAY);
    } else {
        rtDisableClientState(RT_COLOR_ARRAY);
    }
    if (f->normals) {
        rtNormalPointer(RT_FLOAT, s, base + f->normal_offset);
        rtEnableClientState(RT_NORMAL_ARRAY);
    } else {
        rtDisableClientState(RT_NORMAL_ARRAY);
    }
    rtVertexPointer(f->vertex_size, RT_FLOAT, s, base + f->vertex_offset);
    rtEnableClientState(RT_VERTEX_ARRAY);
}
