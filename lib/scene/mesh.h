/* SPDX-License-Identifier: Apache-2.0 */
/*
 * mesh.h - one object definition: assembled triangles and their attributes.
 *
 * A mesh is written only while its object is being recorded (between
 * rtNewObject and rtEndObject) and is immutable once committed, so any
 * number of render threads may read it.  Vertices are in object space
 * (already transformed by the modelview current at rtVertex time).
 *
 * Triangle j uses vertices indices[3j..3j+2]; its material is
 * materials[tri_material[j]]; with TRI_FLAT set it is shaded with the
 * normal and colour of vertex tri_provoking[j] (GL's provoking vertex).
 * Texture coordinates are always interpolated, flat shading or not (GL).
 */
#ifndef RT_SCENE_MESH_H
#define RT_SCENE_MESH_H

#include <stdint.h>

#include "base/aabb.h"
#include "scene/lines.h"

/* Material as set by rtMaterialfv; colours RGBA. */
struct scene_material {
    float ambient[4];
    float diffuse[4];
    float specular[4];
    float emission[4];
    float shininess;
    float reflectivity;
    float transparency;
    float ior;
    /* Name of the 2D texture bound when RT_TEXTURE_2D was enabled, 0 for
     * none.  Kept by name, as a GL display list keeps it: the image is
     * looked up when a frame is rendered (scene/texture.h). */
    uint32_t texture;
    /* Properties (SCENE_MATERIAL_* bits) recorded in a display list before
     * the list set them: taken from the material current at rtCallList,
     * which the instance keeps (struct scene_appearance, frame.h), as GL's
     * geometry takes the state current at glCallList.  0 elsewhere. */
    uint32_t inherit;
};

#define SCENE_MATERIAL_AMBIENT 1u
#define SCENE_MATERIAL_DIFFUSE 2u
#define SCENE_MATERIAL_SPECULAR 4u
#define SCENE_MATERIAL_EMISSION 8u
#define SCENE_MATERIAL_SHININESS 16u
#define SCENE_MATERIAL_REFLECTIVITY 32u
#define SCENE_MATERIAL_TRANSPARENCY 64u
#define SCENE_MATERIAL_IOR 128u
#define SCENE_MATERIAL_ALL 255u

#define TRI_FLAT 1u           /* rtShadeModel(RT_FLAT) was current */
#define TRI_COLOR_MATERIAL 2u /* RT_COLOR_MATERIAL was enabled */
/* Recorded in a display list before the list set a colour: the triangle
 * takes the colour current at rtCallList, which its instance keeps
 * (struct scene_appearance, frame.h), as GL's geometry takes the state
 * current at glCallList (materials: scene_material.inherit). */
#define TRI_INHERIT_COLOR 0x80u
/* Recorded before the list enabled or disabled RT_COLOR_MATERIAL: the
 * enable current at rtCallList applies (the instance's). */
#define TRI_INHERIT_COLOR_MATERIAL 0x40u

struct scene_mesh {
    uint32_t vertex_count;
    uint32_t vertex_capacity;
    float *positions; /* 3 per vertex */
    float *normals;   /* 3 per vertex, not normalised */
    float *colors;    /* 4 per vertex */
    float *texcoords; /* 2 per vertex */

    uint32_t tri_count;
    uint32_t tri_capacity;
    uint32_t *indices;       /* 3 per triangle */
    uint32_t *tri_provoking; /* provoking vertex per triangle */
    uint16_t *tri_material;  /* index into materials */
    uint8_t *tri_flags;      /* TRI_* */

    uint32_t material_count;
    uint32_t material_capacity;
    struct scene_material *materials;

    int has_normals; /* some vertex was given an explicit normal */
    struct aabb bounds;

    /* Lines and points (RT_LINES ..., rtPolygonMode): rasterised, not
     * traced; in object space like the triangles (lines.h). */
    struct scene_lines lines;
};

/* Defaults of OpenGL's material state. */
void scene_material_default(struct scene_material *m);

/* Frees all arrays and zeroes *mesh; safe on a zeroed mesh. */
void scene_mesh_release(struct scene_mesh *mesh);

/* Ensures room for `extra` more vertices / triangles.  Returns 0, or -1
 * on allocation failure leaving the mesh unchanged. */
int scene_mesh_reserve_vertices(struct scene_mesh *mesh, uint32_t extra);
int scene_mesh_reserve_triangles(struct scene_mesh *mesh, uint32_t extra);

/* Sets bounds to the box of the vertices that triangles use (leftover
 * vertices of incomplete primitives do not count). */
void scene_mesh_compute_bounds(struct scene_mesh *mesh);

/* Returns the index of a material equal to *m, appending it if needed; -1
 * on allocation failure or when 65535 distinct materials exist. */
int scene_mesh_intern_material(struct scene_mesh *mesh, const struct scene_material *m);

#endif
