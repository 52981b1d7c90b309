/* SPDX-License-Identifier: Apache-2.0 */
/*
 * instance.c - rtBeginFrame.  rtInstantiateObject is rtCallList
 * (list.c).
 *
 * An instance is an object placed under the modelview matrix current at
 * the call, as glCallList (Wald, Benthin and Slusallek (2003) sec. 4.1).  Instances are issued
 * anew each frame; scene/frame.c decides whether the list changed.
 */
#include "api/context.h"

void rtBeginFrame(void)
{
    GET_CURRENT_CONTEXT(ctx);
    if (!ctx || rt_check_outside_object(ctx, "rtBeginFrame"))
        return;
    scene_frame_begin(&ctx->scene.frame);
    render_overlay_clear(&ctx->overlay); /* the frame's bitmaps (raster.c) */
}
