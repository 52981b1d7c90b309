/* SPDX-License-Identifier: Apache-2.0 */
/*
 * assembly.c - OpenGL primitive assembly rules (OpenGL 2.1 spec sec. 2.6.1;
 * provoking vertices from table 2.12).
 */
#include "scene/assembly.h"

#include <rt/rt.h>

static void tri(struct scene_tri *t, uint32_t a, uint32_t b, uint32_t c, uint32_t provoking)
{
    t->v[0] = a;
    t->v[1] = b;
    t->v[2] = c;
    t->provoking = provoking;
    t->edges = SCENE_TRI_EDGES_ALL;
}

int scene_mode_is_valid(unsigned mode)
{
    switch (mode) {
    case RT_TRIANGLES:
    case RT_TRIANGLE_STRIP:
    case RT_TRIANGLE_FAN:
    case RT_QUADS:
    case RT_QUAD_STRIP:
    case RT_POLYGON:
        return 1;
    default:
        return 0;
    }
}

int scene_assemble(unsigned mode, uint32_t base, uint32_t k, struct scene_tri out[2])
{
    const uint32_t b = base;
    switch (mode) {
    case RT_TRIANGLES:
        if (k % 3 != 2)
            return 0;
        tri(&out[0], b + k - 2, b + k - 1, b + k, b + k);
        return 1;
    case RT_TRIANGLE_STRIP: {
        if (k < 2)
            return 0;
        uint32_t i = k - 2; /* triangle index in the strip */
        /* Odd triangles swap their first two vertices to keep winding. */
        if (i % 2 == 0)
            tri(&out[0], b + i, b + i + 1, b + i + 2, b + k);
        else
            tri(&out[0], b + i + 1, b + i, b + i + 2, b + k);
        return 1;
    }
    case RT_TRIANGLE_FAN:
        if (k < 2)
            return 0;
        tri(&out[0], b, b + k - 1, b + k, b + k);
        return 1;
    case RT_POLYGON:
        /* A convex polygon is a fan; its provoking vertex is the first. */
        if (k < 2)
            return 0;
        tri(&out[0], b, b + k - 1, b + k, b);
        /* A fan: the edge from the centre is the boundary only for the
         * first triangle, the closing edge only for the last. */
        out[0].edges = (uint8_t)(SCENE_TRI_EDGE_1 | (k == 2 ? SCENE_TRI_EDGE_0 : 0u));
        return 1;
    case RT_QUADS:
        if (k % 4 != 3)
            return 0;
        tri(&out[0], b + k - 3, b + k - 2, b + k - 1, b + k);
        tri(&out[1], b + k - 3, b + k - 1, b + k, b + k);
        out[0].edges = SCENE_TRI_EDGE_0 | SCENE_TRI_EDGE_1; /* not the diagonal */
        out[1].edges = SCENE_TRI_EDGE_1 | SCENE_TRI_EDGE_2;
        return 2;
    case RT_QUAD_STRIP: {
        if (k < 3 || k % 2 == 0)
            return 0;
        /* Quad i has vertices 2i, 2i+1, 2i+3, 2i+2 in boundary order. */
        uint32_t i = (k - 3) / 2;
        uint32_t v0 = b + 2 * i, v1 = v0 + 1, v2 = v0 + 3, v3 = v0 + 2;
        tri(&out[0], v0, v1, v2, b + k);
        tri(&out[1], v0, v2, v3, b + k);
        out[0].edges = SCENE_TRI_EDGE_0 | SCENE_TRI_EDGE_1;
        out[1].edges = SCENE_TRI_EDGE_1 | SCENE_TRI_EDGE_2;
        return 2;
    }
    default:
        return 0;
    }
}
