/* SPDX-License-Identifier: Apache-2.0 */
/*
 * pixel_store.c - rtPixelStorei and rtPixelStoref: how images are laid
 * out in client memory, GL's pixel storage modes (GL 1.5 sec. 3.6.1 and
 * table 3.1 for unpacking, sec. 4.3.2 for packing).
 *
 * The unpack state is read by rtTexImage2D, rtTexSubImage2D and rtBitmap,
 * the pack state by rtReadPixels.  Defaults as GL: alignment 4, row
 * length and skips 0, no byte swapping, most significant bit first.  The
 * state is client state: it is not recorded in display lists (GL executes
 * glPixelStore at once, also while compiling), and rtPushClientAttrib
 * saves it (attrib.c).  Errors as Mesa's pixelstore.c: an unknown pname
 * is RT_INVALID_ENUM, a negative length or skip and an alignment other
 * than 1, 2, 4 or 8 are RT_INVALID_VALUE.
 */
#include <math.h>

#include "api/context.h"
#include "api/enum_names.h"

void rt_pixel_layout(const struct pixel_store *ps, int width, int components, int size,
                     size_t *first, size_t *row_stride)
{
    const size_t l = ps->row_length > 0 ? (size_t)ps->row_length : (size_t)(width > 0 ? width : 0);
    const size_t a = (size_t)ps->alignment;
    size_t stride;
    if (size == 0) {
        /* Bitmaps: a * ceil(l / 8a) bytes a row (GL 1.5 eq. 3.14). */
        stride = a * ((l + 8 * a - 1) / (8 * a));
        *first = (size_t)ps->skip_rows * stride;
    } else {
        /* k = a/s * ceil(s n l / a) elements when s < a, else n l (eq. 3.13). */
        const size_t s = (size_t)size, n = (size_t)components;
        stride = s >= a ? s * n * l : a * ((s * n * l + a - 1) / a);
        *first = (size_t)ps->skip_rows * stride + (size_t)ps->skip_pixels * n * s;
    }
    *row_stride = stride;
}

static void pixel_store(const char *caller, RTenum pname, RTint param)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_begin(ctx, caller))
        return;
    const int unpack = pname >= RT_UNPACK_SWAP_BYTES && pname <= RT_UNPACK_ALIGNMENT;
    const int pack = pname >= RT_PACK_SWAP_BYTES && pname <= RT_PACK_ALIGNMENT;
    char b1[RT_ENUM_STRING_SIZE];
    if (!unpack && !pack) {
        rt_error(ctx, RT_INVALID_ENUM, "%s(pname=%s): not a pixel storage parameter", caller,
                 rt_enum_string(pname, b1));
        return;
    }
    struct pixel_store *ps = unpack ? &ctx->unpack : &ctx->pack;
    const RTenum which = unpack ? pname - RT_UNPACK_SWAP_BYTES + RT_PACK_SWAP_BYTES : pname;
    switch (which) {
    case RT_PACK_SWAP_BYTES:
        ps->swap_bytes = param != 0;
        return;
    case RT_PACK_LSB_FIRST:
        ps->lsb_first = param != 0;
        return;
    case RT_PACK_ALIGNMENT:
        if (param != 1 && param != 2 && param != 4 && param != 8) {
            rt_error(ctx, RT_INVALID_VALUE, "%s(%s, %d): the alignment is 1, 2, 4 or 8", caller,
                     rt_enum_string(pname, b1), param);
            return;
        }
        ps->alignment = param;
        return;
    default:
        break;
    }
    if (param < 0) {
        rt_error(ctx, RT_INVALID_VALUE, "%s(%s, %d): negative", caller,
                 rt_enum_string(pname, b1), param);
        return;
    }
    if (which == RT_PACK_ROW_LENGTH)
        ps->row_length = param;
    else if (which == RT_PACK_SKIP_ROWS)
        ps->skip_rows = param;
    else
        ps->skip_pixels = param;
}

void rtPixelStorei(RTenum pname, RTint param)
{
    pixel_store("rtPixelStorei", pname, param);
}

void rtPixelStoref(RTenum pname, RTfloat param)
{
    /* GL: booleans are param != 0, the rest rounded to the nearest
     * integer; a value no integer holds (or NaN) is out of range. */
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx)
        return;
    RTint i;
    if (pname == RT_UNPACK_SWAP_BYTES || pname == RT_UNPACK_LSB_FIRST ||
        pname == RT_PACK_SWAP_BYTES || pname == RT_PACK_LSB_FIRST)
        i = param != 0.0f;
    else if (!(param > -2147483648.0f && param < 2147483647.0f))
        i = -1; /* INVALID_VALUE for a length, skip or alignment */
    else
        i = (RTint)lrintf(param);
    pixel_store("rtPixelStoref", pname, i);
}
