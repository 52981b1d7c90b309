/* SPDX-License-Identifier: Apache-2.0 */
/*
 * raster_triangles.c - instances drawn under a projection or viewport
 * other than the frame's (a heads-up display under a pushed rtuOrtho2D, a
 * minimap in an inset viewport), drawn as GL draws them (raster.h).
 *
 * A ray traced frame has one camera: the projection current when it is
 * rendered.  GL has none; every primitive is projected by the matrix
 * current when it is drawn.  Geometry drawn under another projection
 * cannot be traced through the frame's camera, so it is rasterised here
 * with GL's rules for polygons (OpenGL 1.5 sec. 3.5.1, 2.1 sec. 3.6.1):
 *
 *  - vertices to eye space by the modelview at the call, lit there per
 *    vertex when lighting is on (render/gl_light.c, which is exactly what
 *    GL does: Gouraud shading), to clip space by the instance's
 *    projection, clipped against the view volume and the user clip
 *    planes (Sutherland and Hodgman 1974), to window space by its
 *    viewport;
 *  - facing from the sign of the window-space area and rtFrontFace, then
 *    RT_CULL_FACE and rtPolygonMode (faces in RT_LINE / RT_POINT go to
 *    raster_polygons);
 *  - a fragment at every pixel whose centre is inside the triangle; a
 *    centre exactly on an edge belongs to the triangle only on its left
 *    or bottom edges, so that two triangles sharing an edge never both
 *    draw a pixel (GL asks for that, sec. 3.5.1; the rule is the one
 *    Mesa's rasterisers apply with GL's lower-left origin); vertex
 *    positions snapped to the same 1/256 pixel grid as points
 *    (RASTER_SUBPIXEL_STEPS), so the edge functions are exact in double;
 *  - colours (and the fog coordinate) interpolated perspective-correctly
 *    from the barycentric coordinates divided by w (Heckbert and Moreton
 *    1991), window z linearly in window space as GL specifies (eq. 3.7);
 *    under RT_FLAT the provoking vertex's colour throughout;
 *  - fog with the fog state at the call (eye |z|, as gl_shade.c), then the
 *    depth test (when RT_DEPTH_TEST was enabled at the call: RT_LESS,
 *    written under rtDepthMask; disabled: neither), alpha test and
 *    blending by raster_fragment.
 *
 *  - the bound texture (when enabled at the call): s, t and q, recorded or
 *    generated per vertex (gl_shade.c), interpolated perspective-correctly
 *    as the colours and divided per fragment (s / q, t / q), sampled with
 *    the texture's filters at GL's level of detail lambda (fragment_texel:
 *    the derivatives per 2 x 2 pixel quad, as GPUs take them); then the
 *    texture environment, before fog (sec. 3.8.13).
 */
#include "render/raster.h"

#include <math.h>
#include <string.h>

#include "base/mat4.h"
#include "render/gl_light.h"
#include "render/gl_shade.h"
#include "render/surface.h"
#include "scene/frame.h"
#include "scene/texture.h"

/* Vertices a triangle can have after clipping by the six planes of the
 * view volume and the user clip planes: one more per plane. */
#define CLIP_MAX_VERTICES (3 + 6 + SCENE_MAX_CLIP_PLANES + 2)

struct clip_vertex {
    double clip[4];
    double eye[3];
    float color[4];
    double tex[3]; /* s, t, q */
};

/* Signed distance of v from clipping plane k: 0..5 the view volume's
 * (w + x, w - x, w + y, w - y, w + z, w - z >= 0), then the user planes. */
static double plane_distance(const struct scene_clip *clip, int k, const struct clip_vertex *v)
{
    if (k < 6) {
        const double c = v->clip[k / 2];
        return k % 2 ? v->clip[3] - c : v->clip[3] + c;
    }
    const double *p = clip->plane[k - 6];
    return p[0] * v->eye[0] + p[1] * v->eye[1] + p[2] * v->eye[2] + p[3];
}

static void lerp_vertex(const struct clip_vertex *a, const struct clip_vertex *b, double t,
                        struct clip_vertex *out)
{
    for (int k = 0; k < 4; k++)
        out->clip[k] = a->clip[k] + t * (b->clip[k] - a->clip[k]);
    for (int k = 0; k < 3; k++)
        out->eye[k] = a->eye[k] + t * (b->eye[k] - a->eye[k]);
    for (int k = 0; k < 4; k++)
        out->color[k] = (float)(a->color[k] + t * (b->color[k] - a->color[k]));
    for (int k = 0; k < 3; k++)
        out->tex[k] = a->tex[k] + t * (b->tex[k] - a->tex[k]);
}

/* Clips the polygon v[0..n) in place by every plane; returns its new
 * vertex count (0: nothing left). */
static int clip_polygon(const struct scene_clip *clip, struct clip_vertex *v, int n)
{
    struct clip_vertex tmp[CLIP_MAX_VERTICES];
    for (int k = 0; k < 6 + SCENE_MAX_CLIP_PLANES && n > 0; k++) {
        if (k >= 6 && !(clip->enabled >> (k - 6) & 1u))
            continue;
        int m = 0;
        for (int i = 0; i < n; i++) {
            const struct clip_vertex *a = &v[i], *b = &v[(i + 1) % n];
            const double da = plane_distance(clip, k, a), db = plane_distance(clip, k, b);
            if (da >= 0.0)
                tmp[m++] = *a;
            if ((da >= 0.0) != (db >= 0.0) && m < CLIP_MAX_VERTICES)
                lerp_vertex(a, b, da / (da - db), &tmp[m++]);
            if (m >= CLIP_MAX_VERTICES)
                break;
        }
        memcpy(v, tmp, (size_t)m * sizeof(*v));
        n = m;
    }
    return n;
}

/* A vertex in window coordinates, with what is interpolated across. */
struct window_vertex {
    double x, y, z; /* x, y snapped to the sub-pixel grid */
    double inv_w;
    double color[4]; /* pre-divided by w */
    double fog_z;    /* |eye z| / w */
    double tex[3];   /* s, t, q pre-divided by w */
};

/* The triangle's texture, when it has one with an image. */
struct raster_texture {
    const struct scene_texture *tex;
    uint32_t env_mode;
    float env_color[4];
};

/*
 * The texel at fragment (x, y) whose barycentric weights (window space)
 * are l and change by dl_dx, dl_dy per pixel: s / q and t / q from the
 * interpolated s / w, t / w and q / w, which are linear in window space.
 * The level of detail is GL's lambda = log2(rho), rho the larger of the
 * lengths of the texel-space derivatives along x and along y (OpenGL 1.5
 * sec. 3.8.8, eq. 3.18), with the derivatives taken as GPUs and Mesa's
 * llvmpipe (the oracle's OSMesa) take them: differences of s / q and
 * t / q, in texels, between the centres of the 2 x 2 pixel quad the
 * fragment belongs to (horizontal along its upper row, vertical along
 * its left column), the same for the four fragments.
 */
static void fragment_texel(const struct raster_texture *rt, const struct window_vertex *const v[3],
                           const double l[3], const double dl_dx[3], const double dl_dy[3],
                           long x, long y, float texel[4])
{
    double a[3] = {0.0, 0.0, 0.0}, ax[3] = {0.0, 0.0, 0.0}, ay[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < 3; i++) {
            a[k] += l[i] * v[i]->tex[k];
            ax[k] += dl_dx[i] * v[i]->tex[k];
            ay[k] += dl_dy[i] * v[i]->tex[k];
        }
    /* s / q and t / q at the quad's upper-left, upper-right and lower-left
     * centres, offsets from this fragment's. */
    const double ox = (double)(x & ~1L) - (double)x, oy = (double)(y | 1L) - (double)y;
    const double corner[3][2] = {{ox, oy}, {ox + 1.0, oy}, {ox, oy - 1.0}};
    const double size[2] = {rt->tex->width, rt->tex->height};
    double uv[3][2];
    for (int c = 0; c < 3; c++) {
        const double q = a[2] + ax[2] * corner[c][0] + ay[2] * corner[c][1];
        for (int k = 0; k < 2; k++)
            uv[c][k] = (a[k] + ax[k] * corner[c][0] + ay[k] * corner[c][1]) / q * size[k];
    }
    const double rho = sqrt(fmax(pow(uv[1][0] - uv[0][0], 2) + pow(uv[1][1] - uv[0][1], 2),
                                 pow(uv[2][0] - uv[0][0], 2) + pow(uv[2][1] - uv[0][1], 2)));
    /* A fragment with q = 0 (s / q undefined) samples (0, 0), as traced
     * surfaces do (surface.c). */
    const double s = a[0] / a[2], t = a[1] / a[2];
    float lambda = -INFINITY; /* a magnification (rho <= 1 or NaN) */
    if (rho > 1.0)
        lambda = isfinite(rho) ? (float)log2(rho) : INFINITY;
    scene_texture_sample_lod(rt->tex, lambda, isfinite(s) ? (float)s : 0.0f,
                             isfinite(t) ? (float)t : 0.0f, texel);
}

/* 1 when a pixel centre exactly on the edge a -> b of a counter-clockwise
 * triangle belongs to it: left edges (going down) and bottom edges
 * (horizontal, going right). */
static int owns_tie(const struct window_vertex *a, const struct window_vertex *b)
{
    const double dx = b->x - a->x, dy = b->y - a->y;
    return dy < 0.0 || (dy == 0.0 && dx > 0.0);
}

static double edge(const struct window_vertex *a, const struct window_vertex *b, double px,
                   double py)
{
    return (b->x - a->x) * (py - a->y) - (b->y - a->y) * (px - a->x);
}

static void fill_triangle(const struct raster_target *target, const struct window_vertex *v0,
                          const struct window_vertex *v1, const struct window_vertex *v2,
                          const struct scene_fog *fog, const struct raster_texture *texture)
{
    double area = edge(v0, v1, v2->x, v2->y);
    if (!(area != 0.0))
        return; /* degenerate or not finite: no fragments */
    if (area < 0.0) { /* make it counter-clockwise for the tie rule */
        const struct window_vertex *t = v1;
        v1 = v2;
        v2 = t;
        area = -area;
    }
    const struct window_vertex *v[3] = {v0, v1, v2};
    /* The pixels of the viewport (and framebuffer) under the box. */
    const int *vp = target->viewport;
    double lo_x = fmin(v0->x, fmin(v1->x, v2->x)), hi_x = fmax(v0->x, fmax(v1->x, v2->x));
    double lo_y = fmin(v0->y, fmin(v1->y, v2->y)), hi_y = fmax(v0->y, fmax(v1->y, v2->y));
    long x0 = (long)floor(lo_x - 0.5), x1 = (long)ceil(hi_x - 0.5);
    long y0 = (long)floor(lo_y - 0.5), y1 = (long)ceil(hi_y - 0.5);
    const long vx0 = vp[0] > 0 ? vp[0] : 0, vy0 = vp[1] > 0 ? vp[1] : 0;
    const long vx1 = fmin((double)vp[0] + vp[2], (double)target->width) - 1;
    const long vy1 = fmin((double)vp[1] + vp[3], (double)target->height) - 1;
    x0 = x0 < vx0 ? vx0 : x0;
    y0 = y0 < vy0 ? vy0 : y0;
    x1 = x1 > vx1 ? vx1 : x1;
    y1 = y1 > vy1 ? vy1 : y1;
    int tie[3];
    double dl_dx[3], dl_dy[3]; /* the weights' change per pixel */
    for (int i = 0; i < 3; i++) {
        const struct window_vertex *a = v[(i + 1) % 3], *b = v[(i + 2) % 3];
        tie[i] = owns_tie(a, b);
        dl_dx[i] = -(b->y - a->y) / area;
        dl_dy[i] = (b->x - a->x) / area;
    }
    for (long y = y0; y <= y1; y++) {
        const double py = (double)y + 0.5;
        for (long x = x0; x <= x1; x++) {
            const double px = (double)x + 0.5;
            double b[3];
            int inside = 1;
            for (int i = 0; i < 3 && inside; i++) {
                /* b[i]: the edge opposite vertex i. */
                b[i] = edge(v[(i + 1) % 3], v[(i + 2) % 3], px, py);
                inside = b[i] > 0.0 || (b[i] == 0.0 && tie[i]);
            }
            if (!inside)
                continue;
            double l[3], q = 0.0;
            for (int i = 0; i < 3; i++) {
                l[i] = b[i] / area;
                q += l[i] * v[i]->inv_w;
            }
            const double z = l[0] * v[0]->z + l[1] * v[1]->z + l[2] * v[2]->z;
            float c[4];
            for (int k = 0; k < 4; k++) {
                double a = (l[0] * v[0]->color[k] + l[1] * v[1]->color[k] +
                            l[2] * v[2]->color[k]) / q;
                c[k] = (float)(a < 0.0 ? 0.0 : a > 1.0 ? 1.0 : a);
            }
            if (texture->tex) {
                float texel[4];
                fragment_texel(texture, v, l, dl_dx, dl_dy, x, y, texel);
                gl_texture_env_apply(texture->env_mode, texture->env_color, texel, c);
            }
            if (fog->enabled) {
                const double fz = (l[0] * v[0]->fog_z + l[1] * v[1]->fog_z +
                                   l[2] * v[2]->fog_z) / q;
                const float f = gl_fog_factor(fog, (float)fz);
                for (int k = 0; k < 3; k++)
                    c[k] = f * c[k] + (1.0f - f) * fog->color[k];
            }
            raster_fragment(target, x, y, z < 0.0 ? 0.0 : z > 1.0 ? 1.0 : z, c);
        }
    }
}

static void to_window(const struct raster_target *target, const struct clip_vertex *c,
                      struct window_vertex *w)
{
    double win[3];
    raster_to_window(target, c->clip, win);
    w->x = raster_snap(win[0]);
    w->y = raster_snap(win[1]);
    w->z = win[2];
    w->inv_w = 1.0 / c->clip[3];
    for (int k = 0; k < 4; k++)
        w->color[k] = (double)c->color[k] * w->inv_w;
    w->fog_z = fabs(c->eye[2]) * w->inv_w;
    for (int k = 0; k < 3; k++)
        w->tex[k] = c->tex[k] * w->inv_w;
}

/* 1 when the triangle is counter-clockwise in window coordinates, from
 * its clip coordinates (raster_polygons.c explains the determinant). */
static int counter_clockwise(const struct clip_vertex v[3])
{
    const double *a = v[0].clip, *b = v[1].clip, *c = v[2].clip;
    const double det = a[0] * (b[1] * c[3] - b[3] * c[1]) - a[1] * (b[0] * c[3] - b[3] * c[0]) +
                       a[3] * (b[0] * c[1] - b[1] * c[0]);
    return !(det < 0.0);
}

void raster_instance(const struct raster_target *target, const struct scene_instance *inst,
                     const struct scene_light *lights)
{
    const struct scene_mesh *mesh = &inst->object->mesh;
    const struct scene_appearance *call = &inst->appearance;
    const double *m = target->projection;
    uint32_t resolved_index = UINT32_MAX;
    struct scene_material mat;
    for (uint32_t t = 0; t < mesh->tri_count; t++) {
        const uint32_t mi = mesh->tri_material[t];
        if (mi != resolved_index) {
            mat = mesh->materials[mi];
            surface_resolve_material(call, &mat);
            resolved_index = mi;
        }
        struct clip_vertex v[CLIP_MAX_VERTICES];
        const uint32_t *idx = &mesh->indices[3 * t];
        for (int i = 0; i < 3; i++) {
            const float *p = &mesh->positions[3 * idx[i]];
            const double po[3] = {p[0], p[1], p[2]};
            mat4_transform_point(inst->object_to_world, po, v[i].eye);
            const double *e = v[i].eye;
            for (int r = 0; r < 4; r++)
                v[i].clip[r] = m[r] * e[0] + m[4 + r] * e[1] + m[8 + r] * e[2] + m[12 + r];
        }
        const int front = counter_clockwise(v) != (mat.front_cw != 0);
        if (mat.cull_face & (front ? SCENE_CULL_FRONT : SCENE_CULL_BACK))
            continue;
        if (mat.polygon_mode[front ? 0 : 1] != 0)
            continue; /* drawn as lines or points by raster_polygons */
        float colors[3][4];
        gl_triangle_colors(inst, t, lights, front, colors);
        for (int i = 0; i < 3; i++)
            memcpy(v[i].color, colors[i], sizeof(colors[i]));
        struct raster_texture texture = {NULL, 0, {0.0f, 0.0f, 0.0f, 0.0f}};
        float st[3][2], q[3];
        const uint32_t name = target->textures ? gl_triangle_texture(inst, t, st, q,
                                                                     &texture.env_mode,
                                                                     texture.env_color)
                                               : 0;
        if (name) {
            texture.tex = scene_textures_lookup(target->textures, name);
            if (texture.tex && !texture.tex->texels)
                texture.tex = NULL; /* no image: untextured, as traced */
        }
        for (int i = 0; i < 3; i++) {
            v[i].tex[0] = texture.tex ? st[i][0] : 0.0;
            v[i].tex[1] = texture.tex ? st[i][1] : 0.0;
            v[i].tex[2] = texture.tex ? q[i] : 1.0;
        }
        int n = clip_polygon(target->clip, v, 3);
        for (int i = 0; i < n; i++)
            if (!(v[i].clip[3] > 0.0))
                n = 0; /* only a degenerate polygon reaches w = 0 inside the volume */
        if (n < 3)
            continue;
        struct window_vertex w[CLIP_MAX_VERTICES];
        for (int i = 0; i < n; i++)
            to_window(target, &v[i], &w[i]);
        for (int i = 1; i + 1 < n; i++)
            fill_triangle(target, &w[0], &w[i], &w[i + 1], &call->gl.fog, &texture);
    }
    raster_polygons(target, inst);
    raster_lines(target, &mesh->lines, inst->object_to_world);
}
