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

/* The texture coordinates rtTexGen generates: s, t and q (GL's r has no
 * meaning for 2D textures).  GL divides s and t by q per fragment. */
#define SCENE_TEXGEN_S 0
#define SCENE_TEXGEN_T 1
#define SCENE_TEXGEN_Q 2
#define SCENE_TEXGEN_COORDS 3

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

    /* OpenGL fixed-function state current at the vertex, read by the
     * RT_FIXED_FUNCTION shading mode only (lib/render/gl_shade.c); the
     * eye-light and Whitted modes use the front fields above.  Appended,
     * never reordered: the struct is interned by memcmp, so
     * scene_material_default zeroes it whole first. */
    float back_ambient[4];  /* rtMaterial(RT_BACK, ...) */
    float back_diffuse[4];
    float back_specular[4];
    float back_emission[4];
    float back_shininess;
    uint32_t color_material_face; /* rtColorMaterial: RT_FRONT, RT_BACK, RT_FRONT_AND_BACK */
    uint32_t color_material_mode; /* RT_AMBIENT ... RT_AMBIENT_AND_DIFFUSE */
    uint32_t tex_env_mode;        /* RT_MODULATE, RT_REPLACE, RT_DECAL, RT_BLEND */
    float tex_env_color[4];       /* RT_TEXTURE_ENV_COLOR */
    uint8_t lighting;             /* rtEnable(RT_LIGHTING) */
    uint8_t cull_face;            /* SCENE_CULL_* of RT_CULL_FACE and rtCullFace */
    uint8_t front_cw;             /* rtFrontFace(RT_CW) */
    uint8_t normalize;            /* SCENE_NORMALIZE_* */
    /* rtTexGen for s, t and q (SCENE_TEXGEN_S, _T, _Q): the mode while
     * RT_TEXTURE_GEN_S / _T / _Q was enabled (RT_OBJECT_LINEAR,
     * RT_EYE_LINEAR, RT_SPHERE_MAP but not for q), else 0; the planes
     * (the eye planes already in eye space). */
    uint32_t texgen_mode[SCENE_TEXGEN_COORDS];
    float texgen_object_plane[SCENE_TEXGEN_COORDS][4];
    float texgen_eye_plane[SCENE_TEXGEN_COORDS][4];
    /* Properties (SCENE_MATERIAL_* bits) recorded in a display list before
     * the list set them: taken from the material current at rtCallList,
     * which the instance keeps (struct scene_appearance, frame.h), as GL's
     * geometry takes the state current at glCallList.  0 elsewhere. */
    uint32_t inherit;
    /* rtCullFace's mode as SCENE_CULL_FRONT / _BACK / _BOTH whether or not
     * RT_CULL_FACE is enabled (cull_face is the two together), so that a
     * list's geometry can take the enable and the mode from different
     * places (SCENE_MATERIAL_CULL_ENABLE, SCENE_MATERIAL_CULL_MODE). */
    uint32_t cull_mode;
    /* The 2D texture bound and the RT_TEXTURE_2D enable, each whatever the
     * other (texture is the two together), so that a list's geometry can
     * take them from different places (SCENE_MATERIAL_TEXTURE,
     * SCENE_MATERIAL_TEXTURE_ENABLE): a list that binds its texture, called
     * with RT_TEXTURE_2D enabled, as GL. */
    uint32_t texture_bound;
    uint32_t texture_enabled;
    /* rtPolygonMode of front and back faces: 0 for RT_FILL (so that the
     * zeroed default fills), else RT_LINE or RT_POINT.  GL decides the
     * face of each polygon in window space and draws it in that face's
     * mode (OpenGL 2.1 sec. 3.5.4); a triangle whose face is not filled
     * is passed by camera rays (render/gl_shade.c) and drawn as its
     * boundary edges or vertices by render/raster_polygons.c. */
    uint16_t polygon_mode[2];
    /* The line width and point size those edges and vertices take, as a
     * list recorded them (0: the one current at the call, the instance's
     * scene_raster) or as current when drawn outside lists; 0 while both
     * faces are filled. */
    float polygon_line_width, polygon_point_size;
};

#define SCENE_MATERIAL_AMBIENT 1u
#define SCENE_MATERIAL_DIFFUSE 2u
#define SCENE_MATERIAL_SPECULAR 4u
#define SCENE_MATERIAL_EMISSION 8u
#define SCENE_MATERIAL_SHININESS 16u
#define SCENE_MATERIAL_REFLECTIVITY 32u
#define SCENE_MATERIAL_TRANSPARENCY 64u
#define SCENE_MATERIAL_IOR 128u
/* The back material's properties (rtMaterial(RT_BACK, ...)): the front
 * bit shifted by SCENE_MATERIAL_BACK_SHIFT. */
#define SCENE_MATERIAL_BACK_SHIFT 8
#define SCENE_MATERIAL_LIGHTING (1u << 13) /* rtEnable(RT_LIGHTING) */
#define SCENE_MATERIAL_ALL ((1u << 14) - 1u)
/* The rest of the per-primitive state a triangle records in its material,
 * inherited the same way (surface_resolve_material): the RT_CULL_FACE
 * enable, rtCullFace, rtFrontFace, rtTexEnv, rtTexGen and its enables,
 * rtColorMaterial's face and mode, the texture bound (rtBindTexture), the
 * RT_TEXTURE_2D enable and RT_NORMALIZE / RT_RESCALE_NORMAL. */
#define SCENE_MATERIAL_CULL_ENABLE (1u << 14)
#define SCENE_MATERIAL_CULL_MODE (1u << 15)
#define SCENE_MATERIAL_FRONT_FACE (1u << 16)
#define SCENE_MATERIAL_TEX_ENV (1u << 17)
#define SCENE_MATERIAL_TEXGEN (1u << 18)
#define SCENE_MATERIAL_COLOR_MATERIAL_MODE (1u << 19)
#define SCENE_MATERIAL_TEXTURE (1u << 20)
#define SCENE_MATERIAL_NORMALIZE (1u << 21)
#define SCENE_MATERIAL_TEXTURE_ENABLE (1u << 22)
/* rtPolygonMode of the front and of the back face (polygon_mode[0], [1]). */
#define SCENE_MATERIAL_POLYGON_MODE_FRONT (1u << 23)
#define SCENE_MATERIAL_POLYGON_MODE_BACK (1u << 24)
#define SCENE_MATERIAL_ALL_STATE ((1u << 25) - 1u)

/* Which faces RT_CULL_FACE removes (scene_material.cull_face). */
#define SCENE_CULL_NONE 0u
#define SCENE_CULL_FRONT 1u
#define SCENE_CULL_BACK 2u
#define SCENE_CULL_BOTH 3u
/* RT_NORMALIZE / RT_RESCALE_NORMAL (scene_material.normalize). */
#define SCENE_NORMALIZE_OFF 0u
#define SCENE_NORMALIZE_RESCALE 1u
#define SCENE_NORMALIZE_ON 2u

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
/* Recorded in a display list before the list called rtShadeModel: the
 * shade model current at rtCallList applies (scene_appearance.flat). */
#define TRI_INHERIT_SHADE 0x20u

struct scene_mesh {
    uint32_t vertex_count;
    uint32_t vertex_capacity;
    float *positions; /* 3 per vertex */
    float *normals;   /* 3 per vertex, not normalised */
    float *colors;    /* 4 per vertex */
    float *texcoords; /* 2 per vertex */
    /* NULL, or 1 per vertex (vertex_capacity of them): q of GL's
     * (s, t, r, q) from rtTexCoord4, allocated when the first vertex with
     * q != 1 is stored; GL divides s and t by the interpolated q per
     * fragment.  r has no meaning for 2D textures and is not kept. */
    float *texcoord_q;

    uint32_t tri_count;
    uint32_t tri_capacity;
    uint32_t *indices;       /* 3 per triangle */
    uint32_t *tri_provoking; /* provoking vertex per triangle */
    uint16_t *tri_material;  /* index into materials */
    uint8_t *tri_flags;      /* TRI_* */
    /* GL's edge flags (OpenGL 2.1 sec. 2.6.2): bit i set when edge
     * v[i] -> v[(i + 1) % 3] is a boundary edge of the polygon the
     * triangle came from (not a diagonal of a quad or polygon), what
     * rtPolygonMode RT_LINE draws; RT_POINT draws v[i] for each set bit. */
    uint8_t *tri_edges;

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
