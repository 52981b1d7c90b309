/* SPDX-License-Identifier: Apache-2.0 */
/*
 * instance.c - rtInstantiateObject and rtBeginFrame.
 *
 * An instance is an object placed under the modelview matrix current at
 * the call, as glCallList (Wald, Benthin and Slusallek (2003) sec. 4.1).  Instances are issued
 * anew each frame; scene/frame.c decides whether the list changed.
 */
#include <string.h>

#include "api/context.h"
#include "base/mat4.h"

void rtInstantiateObject(RTuint name)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_object(ctx, "rtInstantiateObject"))
        return;
    struct scene_object *object = scene_objects_lookup(&ctx->scene.objects, name);
    if (!object || !object->defined) {
        rt_error(ctx, RT_INVALID_VALUE, "rtInstantiateObject(object=%u): not an object", name);
        return;
    }
    const double *m = ctx->modelview.m[ctx->modelview.depth - 1];
    double inverse[16], normal[16];
    /* Rays are transformed into object space by the inverse (Wald, Benthin and Slusallek (2003)
     * sec. 4.4); an instance whose matrix cannot be inverted in double
     * precision, or is not affine, cannot be traced. */
    if (m[3] != 0.0 || m[7] != 0.0 || m[11] != 0.0 || m[15] != 1.0) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "rtInstantiateObject(object=%u): the modelview matrix is projective", name);
        return;
    }
    if (!mat4_invert(inverse, m) || !mat4_normal_matrix(normal, m)) {
        rt_error(ctx, RT_INVALID_VALUE,
                 "rtInstantiateObject(object=%u): the modelview matrix is singular", name);
        return;
    }
    if (scene_frame_add_instance(&ctx->scene.frame, object, m, inverse, normal))
        rt_error(ctx, RT_OUT_OF_MEMORY, "rtInstantiateObject(object=%u): out of memory", name);
}

void rtBeginFrame(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_object(ctx, "rtBeginFrame"))
        return;
    scene_frame_begin(&ctx->scene.frame);
    render_overlay_clear(&ctx->overlay); /* the frame's bitmaps (raster.c) */
}
