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
};

/* mode is one of RT_TRIANGLES ... RT_POLYGON (already validated).
 * Writes 0, 1 or 2 triangles into out and returns how many. */
int scene_assemble(unsigned mode, uint32_t base, uint32_t k, struct scene_tri out[2]);

/* Returns 1 when mode is one of the six primitive modes. */
int scene_mode_is_valid(unsigned mode);

#endif
