/* SPDX-License-Identifier: Apache-2.0 */
/*
 * clip.h - the user clip planes a primitive was drawn under: the planes
 * enabled at the draw (or, for a display list's geometry, at the point of
 * the replay of rtCallList where its segment was instanced) with their
 * eye-space equations at that moment.  GL clips each primitive by the
 * planes current when it is drawn (OpenGL 2.1 sec. 2.12), so the state
 * travels with the instance of the geometry (scene_appearance, frame.h),
 * not with the frame.
 */
#ifndef RT_SCENE_CLIP_H
#define RT_SCENE_CLIP_H

#include <stdint.h>

#define SCENE_MAX_CLIP_PLANES 6

struct scene_clip {
    uint32_t enabled; /* bit i: RT_CLIP_PLANE0 + i enabled */
    /* Plane i in eye space: p is kept where plane . (x, y, z, 1) >= 0.
     * Zero for the planes not enabled, so equal states compare equal. */
    double plane[SCENE_MAX_CLIP_PLANES][4];
};

/* 1 when the eye-space point p is removed by an enabled plane of *c. */
static inline int scene_clip_removes(const struct scene_clip *c, const double p[3])
{
    for (int i = 0; i < SCENE_MAX_CLIP_PLANES; i++) {
        const double *e = c->plane[i];
        if ((c->enabled >> i & 1u) && e[0] * p[0] + e[1] * p[1] + e[2] * p[2] + e[3] < 0.0)
            return 1;
    }
    return 0;
}

#endif
