/* SPDX-License-Identifier: Apache-2.0 */
/*
 * gl_shade.c - the RT_FIXED_FUNCTION shading mode (see gl_shade.h): the
 * colour OpenGL 1.x's fixed-function pipeline gives a fragment, at the
 * hit of a camera ray.
 *
 * GL lights per vertex and interpolates the lit colours across the
 * triangle (Gouraud shading, OpenGL 2.1 spec sec. 2.14 and 3.5.1); under
 * RT_FLAT the provoking vertex's lit colour covers the triangle (sec.
 * 2.14.7).  This mode does the same: GL's lighting equation (gl_light.c)
 * at the triangle's three vertices in eye space, the colours blended with
 * the hit's barycentrics.  The barycentrics of a ray hit are the
 * perspective-correct ones, which is how Mesa interpolates colours; the
 * alternative, evaluating the equation at the hit with the interpolated
 * normal (Phong shading), gives smoother highlights but differs from GL
 * wherever a highlight falls inside a triangle, and matched OSMesa's images
 * less well (docs/gl_oracle.md has the figures).  GL_SHADE_PER_PIXEL
 * switches to it for that comparison.
 *
 * After lighting (or the vertex colour, RT_LIGHTING disabled) comes the
 * texture, its coordinates recorded or generated per vertex (rtTexGen),
 * through the texture environment (sec. 3.8.13) and then fog (sec. 3.10), whose
 * coordinate is the hit's |z| in eye space, as Mesa's default
 * (GL_EYE_PLANE_ABSOLUTE_NV) takes it.
 */
#include "render/gl_shade.h"

#include <math.h>
#include <string.h>

#include "base/mat4.h"
#include "render/gl_light.h"
#include "render/surface.h"
#include "trace/scene_ties.h"

#ifndef GL_SHADE_PER_PIXEL
#define GL_SHADE_PER_PIXEL 0
#endif

/* Culled triangles a camera ray passes before it gives up (a miss): far
 * more layers of culled surfaces than a GL scene stacks in one pixel. */
#define GL_SHADE_MAX_CULLED 256

/* A hit triangle with what every step here needs. */
struct gl_triangle {
    const struct scene_instance *inst;
    const struct scene_mesh *mesh;
    const uint32_t *v;
    const struct scene_material *mat; /* the recorded one, or &resolved */
    struct scene_material resolved;   /* the recorded one with what it inherits */
    uint8_t flags;         /* with TRI_COLOR_MATERIAL as inherited from the call */
    const float *call_color; /* TRI_INHERIT_COLOR: the colour at the call, else NULL */
    uint32_t provoking;
    /* The lights the primitive was drawn under (scene/gl_state.h):
     * looked up only when it is lit (gl_shade_hit). */
    const struct scene_light *lights;
    float ng[3]; /* eye-space geometric normal of the counter-clockwise side */
};

static void eye_position(const struct scene_instance *inst, const struct scene_mesh *mesh,
                         uint32_t vertex, float out[3])
{
    const float *p = &mesh->positions[3 * vertex];
    double po[3] = {p[0], p[1], p[2]}, pw[3];
    mat4_transform_point(inst->object_to_world, po, pw);
    for (int k = 0; k < 3; k++)
        out[k] = (float)pw[k];
}

static void fetch_triangle_of(const struct scene_instance *inst, uint32_t prim,
                              struct gl_triangle *t)
{
    t->inst = inst;
    t->mesh = &t->inst->object->mesh;
    t->v = &t->mesh->indices[3 * prim];
    /* A material that inherits nothing is used where it is recorded: the
     * copy (some 260 bytes a hit) only for one completed from the call. */
    const struct scene_material *recorded = &t->mesh->materials[t->mesh->tri_material[prim]];
    if (recorded->inherit) {
        t->resolved = *recorded;
        surface_resolve_material(&t->inst->appearance, &t->resolved);
        t->mat = &t->resolved;
    } else {
        t->mat = recorded;
    }
    t->flags = t->mesh->tri_flags[prim];
    /* Recorded in a list before it set a colour or the RT_COLOR_MATERIAL
     * enable: the caller's (the instance keeps them), as GL. */
    if (t->flags & TRI_INHERIT_COLOR_MATERIAL)
        t->flags = (uint8_t)((t->flags & ~TRI_COLOR_MATERIAL) |
                             (t->inst->appearance.color_material ? TRI_COLOR_MATERIAL : 0u));
    if (t->flags & TRI_INHERIT_SHADE) /* rtShadeModel at the call */
        t->flags = (uint8_t)((t->flags & ~TRI_FLAT) | (t->inst->appearance.flat ? TRI_FLAT : 0u));
    t->call_color = (t->flags & TRI_INHERIT_COLOR) ? t->inst->appearance.color : NULL;
    t->provoking = t->mesh->tri_provoking[prim];
    float p[3][3], e1[3], e2[3];
    for (int i = 0; i < 3; i++)
        eye_position(t->inst, t->mesh, t->v[i], p[i]);
    vec3_sub(e1, p[1], p[0]);
    vec3_sub(e2, p[2], p[0]);
    vec3_cross(t->ng, e1, e2);
}

static void fetch_triangle(const struct shade_context *sc, const struct trace_scene_hit *hit,
                           struct gl_triangle *t)
{
    fetch_triangle_of(shade_hit_instance(sc, hit), hit->prim, t);
}

/* The colour of a vertex of the triangle: recorded, or the call's. */
static const float *vertex_color(const struct gl_triangle *t, uint32_t vertex)
{
    return t->call_color ? t->call_color : &t->mesh->colors[4 * vertex];
}

/* GL decides the face by the winding in window coordinates; for a camera
 * ray that is the side of the triangle's plane the ray comes from. */
static int is_front(const struct gl_triangle *t, const float dir[3])
{
    int counter_clockwise = vec3_dot(t->ng, dir) < 0.0f;
    return t->mat->front_cw ? !counter_clockwise : counter_clockwise;
}

/* Culled (RT_CULL_FACE), or drawn as lines or points by the polygon mode
 * of the face the ray sees (render/raster_polygons.c draws those): either
 * way GL rasterises no fragment of the triangle's interior. */
static int culled(const struct gl_triangle *t, const float dir[3])
{
    const int front = is_front(t, dir);
    unsigned face = front ? SCENE_CULL_FRONT : SCENE_CULL_BACK;
    return (t->mat->cull_face & face) != 0 || t->mat->polygon_mode[front ? 0 : 1] != 0;
}

/* Coincident hits fetched per walk of trace_scene_ties: GL scenes stack
 * few surfaces in one plane; more take another walk. */
#define GL_SHADE_TIES 8

int gl_drawn_tie(const struct shade_context *sc, const float org[3], const float dir[3],
                 int max_walks,
                 int (*reject)(const struct shade_context *sc, const float org[3],
                               const float dir[3], const struct trace_scene_hit *tie),
                 struct trace_scene_hit *hit)
{
    struct trace_scene_hit ties[GL_SHADE_TIES], after = *hit;
    for (int walk = 0; max_walks < 0 || walk < max_walks; walk++) {
        const int n =
            trace_scene_ties(sc->scene, org, dir, &after, ties, GL_SHADE_TIES, NULL, sc->counters);
        for (int i = 0; i < n; i++)
            if (gl_hit_drawn(sc, dir, &ties[i]) && !(reject && reject(sc, org, dir, &ties[i]))) {
                *hit = ties[i];
                return 1;
            }
        if (n < GL_SHADE_TIES)
            break;
        after = ties[n - 1];
    }
    return 0;
}

int gl_closest_drawn(const struct shade_context *sc, const float org[3], const float dir[3],
                     float tmin, float tmax, struct trace_scene_hit *hit)
{
    for (int i = 0; i <= GL_SHADE_MAX_CULLED; i++) {
        /* A camera ray the tile loop traced in a packet: its first hit. */
        if (i == 0 && sc->primed && tmin == 0.0f) {
            if (!sc->primed->found)
                return 0;
            *hit = sc->primed->hit;
        } else if (!trace_scene_closest(sc->scene, org, dir, tmin, tmax, hit, sc->counters))
            return 0;
        if (gl_hit_drawn(sc, dir, hit))
            return 1;
        /* The hit is not drawn: another triangle at exactly its distance
         * (a filled surface coplanar with a culled or outlined one, the
         * same quad drawn twice) is GL's fragment there, so the triangles
         * at that t are tried by identity, in draw order, before the ray
         * moves past it (scene_ties.h gives exactly the t the closest-hit
         * walk computes, so none is skipped or found twice). */
        if (gl_drawn_tie(sc, org, dir, GL_SHADE_MAX_CULLED / GL_SHADE_TIES, NULL, hit))
            return 1;
        tmin = nextafterf(hit->t, INFINITY);
    }
    return 0;
}

/* 1 when a triangle of material m, in an instance called with material
 * c, has both faces drawn filled: no culling recorded, and none taken
 * from the call (a list's triangles that did not set the enable inherit
 * it, mesh.h), and no face drawn as lines or points.  0 says nothing:
 * the face the ray sees decides (culled). */
static int material_always_drawn(const struct scene_material *m, const struct scene_material *c)
{
    const uint32_t poly = SCENE_MATERIAL_POLYGON_MODE_FRONT | SCENE_MATERIAL_POLYGON_MODE_BACK;
    return m->cull_face == SCENE_CULL_NONE &&
           (!(m->inherit & SCENE_MATERIAL_CULL_ENABLE) || c->cull_face == SCENE_CULL_NONE) &&
           (m->polygon_mode[0] | m->polygon_mode[1]) == 0 &&
           (!(m->inherit & poly) || (c->polygon_mode[0] | c->polygon_mode[1]) == 0);
}

int gl_frame_all_drawn(const struct scene_frame *frame)
{
    for (uint32_t i = 0; i < frame->committed.count; i++) {
        const struct scene_instance *inst = &frame->committed.items[i];
        const struct scene_mesh *mesh = &inst->object->mesh;
        for (uint32_t k = 0; k < mesh->material_count; k++)
            if (!material_always_drawn(&mesh->materials[k], &inst->appearance.material))
                return 0;
    }
    return 1;
}

int gl_hit_drawn(const struct shade_context *sc, const float dir[3],
                 const struct trace_scene_hit *hit)
{
    const struct scene_instance *inst = shade_hit_instance(sc, hit);
    const struct scene_mesh *mesh = &inst->object->mesh;
    const struct scene_material *m = &mesh->materials[mesh->tri_material[hit->prim]];
    /* Both faces filled: drawn, with no more work than before. */
    if (material_always_drawn(m, &inst->appearance.material))
        return 1;
    struct gl_triangle t;
    fetch_triangle(sc, hit, &t);
    return !culled(&t, dir);
}

/* The eye-space normal GL lights with: the recorded normal through the
 * instance's inverse transpose, normalised under RT_NORMALIZE and
 * RT_RESCALE_NORMAL (see docs/appearance.md), else as it comes. */
static void eye_normal(const struct gl_triangle *t, const float n[3], float out[3])
{
    const double *m = t->inst->normal_to_world;
    for (int r = 0; r < 3; r++)
        out[r] = (float)(m[r] * n[0] + m[4 + r] * n[1] + m[8 + r] * n[2]);
    if (t->mat->normalize != SCENE_NORMALIZE_OFF)
        vec3_normalize(out);
}

static void lit_colour(const struct gl_triangle *t,
                       const float p[3], const float n_in[3], const float color[4], int back,
                       float out[4])
{
    float n[3];
    eye_normal(t, n_in, n);
    if (back)
        for (int k = 0; k < 3; k++)
            n[k] = -n[k];
    struct gl_face_material fm;
    gl_face_material(t->mat, back, (t->flags & TRI_COLOR_MATERIAL) != 0, color, &fm);
    gl_light_point_model(t->lights, &t->inst->appearance.gl.light_model, &fm, p, n, out);
}

/*
 * The texture coordinates of a vertex: recorded, or generated as GL 1.1
 * sec. 2.10.4 does per vertex (the rasteriser then interpolates them):
 * RT_OBJECT_LINEAR dots the vertex as recorded with the object plane,
 * RT_EYE_LINEAR its eye position with the eye plane (transformed at the
 * rtTexGen call), RT_SPHERE_MAP reflects the unit vector from the eye
 * about the eye normal, r = u - 2 n (n . u), and maps it with
 * m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2) to (rx / m + 1/2, ry / m + 1/2).
 * q (*q) is generated the same way by the two linear modes (eye-linear
 * s, t and q from a projector's matrix project a texture onto the scene),
 * else it is rtTexCoord4's, else 1; s and t are divided by its
 * interpolated value per fragment (surface_texel).
 */
static void texture_coordinates(const struct gl_triangle *t, uint32_t vertex, float st[2],
                                float *q)
{
    const struct scene_material *m = t->mat;
    const float *tc = &t->mesh->texcoords[2 * vertex];
    st[0] = tc[0];
    st[1] = tc[1];
    *q = t->mesh->texcoord_q ? t->mesh->texcoord_q[vertex] : 1.0f;
    if (!m->texgen_mode[SCENE_TEXGEN_S] && !m->texgen_mode[SCENE_TEXGEN_T] &&
        !m->texgen_mode[SCENE_TEXGEN_Q])
        return;
    const float *po = &t->mesh->positions[3 * vertex];
    float pe[3], sphere[SCENE_TEXGEN_COORDS] = {0.0f, 0.0f, 1.0f};
    eye_position(t->inst, t->mesh, vertex, pe);
    if (m->texgen_mode[0] == RT_SPHERE_MAP || m->texgen_mode[1] == RT_SPHERE_MAP) {
        float u[3] = {pe[0], pe[1], pe[2]}, n[3], r[3];
        vec3_normalize(u);
        eye_normal(t, &t->mesh->normals[3 * vertex], n);
        float nu = vec3_dot(n, u);
        for (int k = 0; k < 3; k++)
            r[k] = u[k] - 2.0f * n[k] * nu;
        float mm = 2.0f * sqrtf(r[0] * r[0] + r[1] * r[1] + (r[2] + 1.0f) * (r[2] + 1.0f));
        if (mm > 0.0f) {
            sphere[0] = r[0] / mm + 0.5f;
            sphere[1] = r[1] / mm + 0.5f;
        }
    }
    float *const out[SCENE_TEXGEN_COORDS] = {&st[0], &st[1], q};
    for (int i = 0; i < SCENE_TEXGEN_COORDS; i++) {
        const float *p;
        switch (m->texgen_mode[i]) {
        case RT_OBJECT_LINEAR:
            p = m->texgen_object_plane[i];
            *out[i] = p[0] * po[0] + p[1] * po[1] + p[2] * po[2] + p[3];
            break;
        case RT_EYE_LINEAR:
            p = m->texgen_eye_plane[i];
            *out[i] = p[0] * pe[0] + p[1] * pe[1] + p[2] * pe[2] + p[3];
            break;
        case RT_SPHERE_MAP: /* s and t only (rtTexGen refuses it for q) */
            *out[i] = sphere[i];
            break;
        default:
            break;
        }
    }
}

static void texture_environment(const struct scene_material *mat, const float tex[4],
                                float c[4])
{
    gl_texture_env_apply(mat->tex_env_mode, mat->tex_env_color, tex, c);
}

void gl_texture_env_apply(uint32_t mode, const float env_color[4], const float tex[4], float c[4])
{
    switch (mode) {
    case RT_REPLACE:
        memcpy(c, tex, 4 * sizeof(float));
        break;
    case RT_DECAL:
        for (int k = 0; k < 3; k++)
            c[k] = c[k] * (1.0f - tex[3]) + tex[k] * tex[3];
        break;
    case RT_BLEND:
        for (int k = 0; k < 3; k++)
            c[k] = c[k] * (1.0f - tex[k]) + env_color[k] * tex[k];
        c[3] *= tex[3];
        break;
    default: /* RT_MODULATE */
        for (int k = 0; k < 4; k++)
            c[k] *= tex[k];
        break;
    }
}

void gl_shade_hit(const struct shade_context *sc, const struct trace_scene_hit *hit,
                  const float org[3], const float dir[3], float width, float rgba[4])
{
    struct gl_triangle t;
    fetch_triangle(sc, hit, &t);
    const struct scene_mesh *mesh = t.mesh;
    const float b[3] = {1.0f - hit->u - hit->v, hit->u, hit->v};
    const int flat = (t.flags & TRI_FLAT) != 0;
    float c[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    if (!t.mat->lighting) {
        if (flat)
            memcpy(c, vertex_color(&t, t.provoking), sizeof(c));
        else
            for (int i = 0; i < 3; i++)
                for (int k = 0; k < 4; k++)
                    c[k] += b[i] * vertex_color(&t, t.v[i])[k];
    } else {
        /* The frame's lights only for an instance that has no set (none
         * could be allocated). */
        const uint32_t set = t.inst->appearance.gl.light_set;
        t.lights = set < sc->frame->committed_lights.count
                       ? sc->frame->committed_lights.items[set].light
                       : sc->state->lights;
        const int back = !is_front(&t, dir) && t.inst->appearance.gl.light_model.two_side;
        if (flat) {
            float p[3];
            eye_position(t.inst, mesh, t.provoking, p);
            lit_colour(&t, p, &mesh->normals[3 * t.provoking],
                       vertex_color(&t, t.provoking), back, c);
        } else if (GL_SHADE_PER_PIXEL) {
            float p[3], n[3] = {0.0f, 0.0f, 0.0f}, col[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            for (int k = 0; k < 3; k++)
                p[k] = org[k] + hit->t * dir[k];
            for (int i = 0; i < 3; i++) {
                for (int k = 0; k < 3; k++)
                    n[k] += b[i] * mesh->normals[3 * t.v[i] + k];
                for (int k = 0; k < 4; k++)
                    col[k] += b[i] * vertex_color(&t, t.v[i])[k];
            }
            lit_colour(&t, p, n, col, back, c);
        } else {
            for (int i = 0; i < 3; i++) {
                float p[3], lit[4];
                eye_position(t.inst, mesh, t.v[i], p);
                lit_colour(&t, p, &mesh->normals[3 * t.v[i]], vertex_color(&t, t.v[i]),
                           back, lit);
                for (int k = 0; k < 4; k++)
                    c[k] += b[i] * lit[k];
            }
        }
    }
    if (t.mat->texture) {
        float ng[3] = {t.ng[0], t.ng[1], t.ng[2]}, tex[4], coords[3][2];
        vec3_normalize(ng);
        /* q: rtTexCoord4's, which rtTexGen of s and t leaves as it is, or
         * generated; none (1 at every vertex) takes the affine path. */
        float q[3];
        for (int i = 0; i < 3; i++)
            texture_coordinates(&t, t.v[i], coords[i], &q[i]);
        const int projective = mesh->texcoord_q || t.mat->texgen_mode[SCENE_TEXGEN_Q];
        if (surface_texel(sc, hit, t.mat->texture, coords, projective ? q : NULL, ng, dir, width,
                          tex))
            texture_environment(t.mat, tex, c);
    }
    /* Fog as current when the primitive was drawn (scene/gl_state.h). */
    const struct scene_fog *fog = &t.inst->appearance.gl.fog;
    if (fog->enabled) {
        float z = fabsf(org[2] + hit->t * dir[2]);
        float f = gl_fog_factor(fog, z);
        for (int k = 0; k < 3; k++)
            c[k] = f * c[k] + (1.0f - f) * fog->color[k];
    }
    for (int k = 0; k < 4; k++)
        rgba[k] = c[k] < 0.0f ? 0.0f : (c[k] > 1.0f ? 1.0f : c[k]);
}

void gl_triangle_colors(const struct scene_instance *inst, uint32_t prim,
                        const struct scene_light *lights, int front, float rgba[3][4])
{
    struct gl_triangle t;
    fetch_triangle_of(inst, prim, &t);
    t.lights = lights;
    const int flat = (t.flags & TRI_FLAT) != 0;
    const int back = !front && inst->appearance.gl.light_model.two_side;
    for (int i = 0; i < 3; i++) {
        const uint32_t v = flat ? t.provoking : t.v[i];
        float c[4];
        if (!t.mat->lighting) {
            memcpy(c, vertex_color(&t, v), sizeof(c));
        } else {
            float p[3];
            eye_position(inst, t.mesh, v, p);
            lit_colour(&t, p, &t.mesh->normals[3 * v], vertex_color(&t, v), back, c);
        }
        for (int k = 0; k < 4; k++)
            rgba[i][k] = c[k] < 0.0f ? 0.0f : (c[k] > 1.0f ? 1.0f : c[k]);
    }
}

uint32_t gl_triangle_texture(const struct scene_instance *inst, uint32_t prim, float st[3][2],
                             float q[3], uint32_t *env_mode, float env_color[4])
{
    struct gl_triangle t;
    fetch_triangle_of(inst, prim, &t);
    if (!t.mat->texture)
        return 0;
    for (int i = 0; i < 3; i++)
        texture_coordinates(&t, t.v[i], st[i], &q[i]);
    *env_mode = t.mat->tex_env_mode;
    memcpy(env_color, t.mat->tex_env_color, 4 * sizeof(float));
    return t.mat->texture;
}
