/* SPDX-License-Identifier: Apache-2.0 */
/*
 * surface.h - what a ray hit looks like: the surface fetch the
 * integrators (shade.c: eye light, Whitted; later path tracing) start
 * from.  The hit point and its error bound, the geometric and shading
 * normals facing the ray, and the material with vertex colours and the
 * texture applied.
 */
#ifndef RT_RENDER_SURFACE_H
#define RT_RENDER_SURFACE_H

#include "render/shade.h"

/* Surface data at a hit, in world space. */
struct surface {
    float p[3];  /* hit point */
    float ng[3]; /* geometric normal, unit, facing the incoming ray */
    float n[3];  /* shading normal, unit, same side as ng */
    float p_error; /* bound on |p - exact point on the surface| */
    int front;   /* the ray hit the front face (counter-clockwise side) */
    struct scene_material mat;
};

/* The surface at a hit of a ray along dir whose cone is `width` wide
 * there (world units). */
void surface_fetch(const struct shade_context *sc, const struct trace_scene_hit *hit,
                   const float dir[3], float width, struct surface *s);

/* The texel of texture `name` at a hit, for the RT_FIXED_FUNCTION mode,
 * which applies it after lighting through the texture environment
 * (gl_shade.c): the interpolated coordinates, filtered for the cone's
 * `width` as apply_texture does; ng is the unit geometric normal in world
 * space.  Returns 0 (texel untouched) when the name has no image. */
int surface_texel(const struct shade_context *sc, const struct trace_scene_hit *hit,
                  uint32_t name, const float ng[3], const float dir[3], float width,
                  float texel[4]);

#endif
