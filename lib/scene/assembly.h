/* SPDX-License-Identifier: Apache-2.0 */
/*
 * assembly.h - OpenGL primitive assembly: vertex stream -> triangles.
 *
 * Incremental: after vertex k (0-based within one rtBegin/rtEnd block or
 * one draw call) has been stored at mesh index base + k, scene_assemble
 * returns the triangles that vertex completes, with GL's vertex order
 * (which fixes winding and barycentrics) and GL's provoking vertex (which
 * flat shading uses).  Leftover vertices of an incomplete primitive simply
 * never complete a triangle, which is GL's "dropped silently".
 */
#ifndef RT_SCENE_ASSEMBLY_H
#define RT_SCENE_ASSEMBLY_H

#include <stdint.h>

struct scene_tri {
    uint32_t v[3];
    uint32_t provoking;
    /* GL's edge flags: bit i when edge v[i] -> v[(i + 1) % 3] lies on the
     * boundary of the polygon (SCENE_TRI_EDGE_*).  A polygon's closing
     * edge is known only at its end (scene_block_close_polygon). */
    uint8_t edges;
};

#define SCENE_TRI_EDGE_0 1u
#define SCENE_TRI_EDGE_1 2u
#define SCENE_TRI_EDGE_2 4u
#define SCENE_TRI_EDGES_ALL 7u

/* mode is one of RT_TRIANGLES ... RT_POLYGON (already validated).
 * Writes 0, 1 or 2 triangles into out and returns how many. */
int scene_assemble(unsigned mode, uint32_t base, uint32_t k, struct scene_tri out[2]);

/* Returns 1 when mode is one of the six primitive modes. */
int scene_mode_is_valid(unsigned mode);

#endif
