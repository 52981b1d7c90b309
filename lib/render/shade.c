/*
 * shade.c - eye-light and Whitted shading (see shade.h).
 *
 * Lighting follows OpenGL's fixed-function model (OpenGL 2.1 spec sec.
 * 2.14.1: emission + global ambient + per light attenuated ambient,
 * diffuse and Blinn-Phong specular) so a ported GL program looks as it
 * did, with hard shadows, mirror reflection and refraction added in the
 * manner of Whitted (1980).  Surfaces are two-sided: normals are turned
 * towards the incoming ray.  Textures modulate the ambient and diffuse
 * material (GL's MODULATE texture environment, applied to the material
 * rather than to the lit colour; see apply_texture), filtered by a level
 * of detail from the ray cone each camera, reflected and refracted ray
 * carries (shade.h, texture_lod).
 */
#include "render/shade.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "base/mat4.h"

/* Surface data at a hit, in world space. */
struct surface {
    float p[3];  /* hit point */
    float ng[3]; /* geometric normal, unit, facing the incoming ray */
    float n[3];  /* shading normal, unit, same side as ng */
    float p_error; /* bound on |p - exact point on the surface| */
    int front;   /* the ray hit the front face (counter-clockwise side) */
    struct scene_material mat;
};

/* Safety factor on the error bound of the hit point (see fetch_surface). */
#define OFFSET_ERROR_SCALE 2.0

void shade_offset_point(const float p[3], const float n[3], float error, float out[3])
{
    double d = OFFSET_ERROR_SCALE * (double)error;
    for (int k = 0; k < 3; k++) {
        double target = (double)p[k] + d * (double)n[k];
        float f = (float)target;
        /* Round away from the surface, never back towards it, so the
         * point moves at least d along n whatever the rounding. */
        if (n[k] > 0.0f && (double)f < target)
            f = nextafterf(f, INFINITY);
        else if (n[k] < 0.0f && (double)f > target)
            f = nextafterf(f, -INFINITY);
        out[k] = f;
    }
}

static void transform_normal(const double m[16], const float in[3], float out[3])
{
    for (int r = 0; r < 3; r++)
        out[r] = (float)(m[r] * in[0] + m[4 + r] * in[1] + m[8 + r] * in[2]);
}

static void interpolate(const float *attr, int stride, const uint32_t v[3], float b0, float b1,
                        float b2, int n, float *out)
{
    for (int k = 0; k < n; k++)
        out[k] = b0 * attr[stride * v[0] + k] + b1 * attr[stride * v[1] + k] +
                 b2 * attr[stride * v[2] + k];
}

/* Smallest |cos| between ray and surface in the level of detail.  It only
 * keeps lambda finite for a ray nearly parallel to the surface (which hits
 * it only by rounding): there the footprint is already 2^16.6 times wider
 * than head-on, more than the 14 halvings of the largest mip chain. */
#define LOD_MIN_COSINE 1e-5

/*
 * The texture level of detail at a hit by ray cones (Akenine-Möller et
 * al. 2019, "Texture Level of Detail Strategies for Real-Time Ray
 * Tracing", Ray Tracing Gems ch. 20, sec. 20.3.4):
 *
 *     lambda = Delta + log2(width / |n . d|),  Delta = 0.5 log2(t_a / p_a)
 *
 * `width` is the cone's width at the hit (world units), n the unit
 * geometric normal and d the unit ray direction, so width / |n . d| is the
 * footprint stretched across the triangle's plane; t_a is the triangle's
 * area in level-0 texels (w h |(st1 - st0) x (st2 - st0)|) and p_a its
 * area in world space, so sqrt(t_a / p_a) converts world length to texels
 * and lambda is log2 of the texels a pixel spans, GL's log2(rho).  The
 * triangle's edges go through the instance matrix before p_a is taken,
 * so an instance scaled 4x gets the level of detail of the same triangles
 * recorded 4x larger.  All in double; the same operations for every pixel,
 * so the result does not depend on threads.  A triangle without texture
 * area (constant coordinates) gives -inf, a magnification; one without
 * world area +inf, the last level; 0 / 0 a NaN, which the sampler takes as
 * a magnification.
 */
static float texture_lod(const struct scene_texture *tex, const struct scene_instance *inst,
                         const struct scene_mesh *mesh, const uint32_t v[3], const float ng[3],
                         const float dir[3], float width)
{
    const float *p0 = &mesh->positions[3 * v[0]];
    const float *p1 = &mesh->positions[3 * v[1]];
    const float *p2 = &mesh->positions[3 * v[2]];
    const float *t0 = &mesh->texcoords[2 * v[0]];
    const float *t1 = &mesh->texcoords[2 * v[1]];
    const float *t2 = &mesh->texcoords[2 * v[2]];
    double e1[3], e2[3], w1[3], w2[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = (double)p1[k] - (double)p0[k];
        e2[k] = (double)p2[k] - (double)p0[k];
    }
    mat4_transform_vector(inst->object_to_world, e1, w1);
    mat4_transform_vector(inst->object_to_world, e2, w2);
    const double cx = w1[1] * w2[2] - w1[2] * w2[1];
    const double cy = w1[2] * w2[0] - w1[0] * w2[2];
    const double cz = w1[0] * w2[1] - w1[1] * w2[0];
    const double p_a = sqrt(cx * cx + cy * cy + cz * cz);
    const double uv_cross = ((double)t1[0] - (double)t0[0]) * ((double)t2[1] - (double)t0[1]) -
                            ((double)t2[0] - (double)t0[0]) * ((double)t1[1] - (double)t0[1]);
    const double t_a = (double)tex->width * (double)tex->height * fabs(uv_cross);
    const double dir_len = sqrt((double)dir[0] * dir[0] + (double)dir[1] * dir[1] +
                                (double)dir[2] * dir[2]);
    double cosine = fabs((double)ng[0] * dir[0] + (double)ng[1] * dir[1] +
                         (double)ng[2] * dir[2]) /
                    dir_len;
    if (!(cosine >= LOD_MIN_COSINE))
        cosine = LOD_MIN_COSINE;
    return (float)(0.5 * log2(t_a / p_a) + log2((double)width / cosine));
}

/*
 * GL's MODULATE environment (OpenGL 1.1 sec. 3.8.6, table 3.19: C = Cf Ct)
 * applied before lighting to the colours that carry the surface's own
 * colour: ambient and diffuse (which RT_COLOR_MATERIAL may have replaced).
 * Emission and specular are left alone, as with GL 1.2's separate
 * specular colour.  Lighting is linear in both, so for them this equals
 * modulating the lit colour.  The triangle keeps the texture's name; a
 * name without an image (deleted, or never given one) leaves the surface
 * untextured.  Texture coordinates are interpolated, never flat.  The
 * texel is filtered for the ray cone's `width` at the hit (texture_lod);
 * when both filters are the same non-mipmapped one every level of detail
 * gives the same lookup, and none is computed.
 */
static void apply_texture(const struct shade_context *sc, const struct scene_instance *inst,
                          const struct scene_mesh *mesh, const uint32_t v[3], float b0,
                          float b1, float b2, const float ng[3], const float dir[3],
                          float width, struct scene_material *mat)
{
    const struct scene_texture *tex = scene_textures_lookup(sc->textures, mat->texture);
    if (!tex || !tex->texels)
        return;
    float st[2], texel[4];
    interpolate(mesh->texcoords, 2, v, b0, b1, b2, 2, st);
    float lambda = -INFINITY; /* a magnification */
    if (tex->min_filter != tex->mag_filter)
        lambda = texture_lod(tex, inst, mesh, v, ng, dir, width);
    scene_texture_sample_lod(tex, lambda, st[0], st[1], texel);
    for (int k = 0; k < 3; k++) {
        mat->ambient[k] *= texel[k];
        mat->diffuse[k] *= texel[k];
    }
}

/* The surface at a hit of a ray along dir whose cone is `width` wide
 * there (world units). */
static void fetch_surface(const struct shade_context *sc, const struct trace_scene_hit *hit,
                          const float dir[3], float width, struct surface *s)
{
    const struct trace_instance *ti = &sc->scene->instances[hit->instance];
    const struct scene_instance *inst = &sc->frame->committed.items[ti->instance_id];
    const struct scene_mesh *mesh = &inst->object->mesh;
    const uint32_t *v = &mesh->indices[3 * hit->prim];
    const float b1 = hit->u, b2 = hit->v, b0 = 1.0f - hit->u - hit->v;

    const float *p0 = &mesh->positions[3 * v[0]];
    const float *p1 = &mesh->positions[3 * v[1]];
    const float *p2 = &mesh->positions[3 * v[2]];

    /* The hit point is p0 + u (p1 - p0) + v (p2 - p0) evaluated in double
     * (the float differences are exact there), so it lies on the plane of
     * the float triangle to double precision wherever the barycentrics
     * land, and is then mapped to world space in double.  Its only
     * significant error is the final rounding to float, plus the rounding
     * of the next ray's origin into object space: together at most half an
     * ulp of each (PBRT 3rd ed. sec. 3.9 bounds the hit point the same way
     * and offsets secondary rays by that bound along the normal). */
    double po[3], pw[3];
    double max_object = 0.0, max_world = 0.0, norm = 0.0;
    for (int k = 0; k < 3; k++) {
        po[k] = (double)p0[k] + (double)hit->u * ((double)p1[k] - (double)p0[k]) +
                (double)hit->v * ((double)p2[k] - (double)p0[k]);
        max_object = fmax(max_object, fabs(po[k]));
    }
    mat4_transform_point(inst->object_to_world, po, pw);
    for (int k = 0; k < 3; k++) {
        s->p[k] = (float)pw[k];
        max_world = fmax(max_world, fabs(pw[k]));
        const double *m = inst->object_to_world;
        norm = fmax(norm, fabs(m[k]) + fabs(m[4 + k]) + fabs(m[8 + k]));
    }
    s->p_error = (float)(0.5 * FLT_EPSILON * (max_world + norm * max_object) + FLT_MIN);
    float e1[3], e2[3], ngo[3];
    vec3_sub(e1, p1, p0);
    vec3_sub(e2, p2, p0);
    vec3_cross(ngo, e1, e2);
    transform_normal(inst->normal_to_world, ngo, s->ng);
    if (!vec3_normalize(s->ng)) {
        /* Sliver too thin for float: any unit vector facing the ray. */
        s->ng[0] = -dir[0];
        s->ng[1] = -dir[1];
        s->ng[2] = -dir[2];
        vec3_normalize(s->ng);
    }
    s->front = vec3_dot(s->ng, dir) < 0.0f;
    if (!s->front)
        for (int k = 0; k < 3; k++)
            s->ng[k] = -s->ng[k];

    uint8_t flags = mesh->tri_flags[hit->prim];
    uint32_t provoking = mesh->tri_provoking[hit->prim];
    memcpy(s->n, s->ng, sizeof(s->n));
    if (mesh->has_normals) {
        float no[3];
        if (flags & TRI_FLAT)
            memcpy(no, &mesh->normals[3 * provoking], sizeof(no));
        else
            interpolate(mesh->normals, 3, v, b0, b1, b2, 3, no);
        float nw[3];
        transform_normal(inst->normal_to_world, no, nw);
        if (vec3_normalize(nw)) {
            if (vec3_dot(nw, s->ng) < 0.0f)
                for (int k = 0; k < 3; k++)
                    nw[k] = -nw[k];
            memcpy(s->n, nw, sizeof(s->n));
        }
    }

    s->mat = mesh->materials[mesh->tri_material[hit->prim]];
    if (flags & TRI_COLOR_MATERIAL) {
        float c[4];
        if (flags & TRI_FLAT)
            memcpy(c, &mesh->colors[4 * provoking], sizeof(c));
        else
            interpolate(mesh->colors, 4, v, b0, b1, b2, 4, c);
        memcpy(s->mat.ambient, c, sizeof(c));
        memcpy(s->mat.diffuse, c, sizeof(c));
    }
    if (s->mat.texture)
        apply_texture(sc, inst, mesh, v, b0, b1, b2, s->ng, dir, width, &s->mat);
}

static void add_scaled(float acc[3], const float a[4], const float b[4], float scale)
{
    for (int k = 0; k < 3; k++)
        acc[k] += a[k] * b[k] * scale;
}

static void local_whitted(const struct shade_context *sc, const struct surface *s,
                          const float dir[3], float c[3])
{
    const struct render_state *st = sc->state;
    for (int k = 0; k < 3; k++)
        c[k] = s->mat.emission[k] + st->global_ambient[k] * s->mat.ambient[k];
    float view[3] = {-dir[0], -dir[1], -dir[2]};
    vec3_normalize(view);
    float origin[3];
    shade_offset_point(s->p, s->ng, s->p_error, origin);
    for (int i = 0; i < RENDER_MAX_LIGHTS; i++) {
        const struct render_light *light = &st->lights[i];
        if (!light->enabled)
            continue;
        float to_light[3], shadow_dir[3], shadow_tmax, attenuation = 1.0f;
        if (light->position[3] != 0.0f) {
            float lp[3];
            for (int k = 0; k < 3; k++)
                lp[k] = light->position[k] / light->position[3];
            vec3_sub(shadow_dir, lp, origin);
            shadow_tmax = 1.0f;
            memcpy(to_light, shadow_dir, sizeof(to_light));
            float d = sqrtf(vec3_dot(to_light, to_light));
            float att = light->attenuation[0] + light->attenuation[1] * d +
                        light->attenuation[2] * d * d;
            attenuation = att > 0.0f ? 1.0f / att : 1.0f;
        } else {
            memcpy(to_light, light->position, sizeof(to_light));
            memcpy(shadow_dir, to_light, sizeof(shadow_dir));
            shadow_tmax = INFINITY;
        }
        add_scaled(c, light->ambient, s->mat.ambient, attenuation);
        if (!vec3_normalize(to_light))
            continue;
        float n_dot_l = vec3_dot(s->n, to_light);
        if (n_dot_l <= 0.0f || vec3_dot(s->ng, to_light) <= 0.0f)
            continue;
        if (trace_scene_any(sc->scene, origin, shadow_dir, 0.0f, shadow_tmax, sc->counters))
            continue;
        add_scaled(c, light->diffuse, s->mat.diffuse, attenuation * n_dot_l);
        float h[3] = {to_light[0] + view[0], to_light[1] + view[1], to_light[2] + view[2]};
        if (vec3_normalize(h)) {
            float n_dot_h = vec3_dot(s->n, h);
            if (n_dot_h > 0.0f) {
                float spec = s->mat.shininess > 0.0f ? powf(n_dot_h, s->mat.shininess) : 1.0f;
                add_scaled(c, light->specular, s->mat.specular, attenuation * spec);
            }
        }
    }
}

static void reflect_dir(const float d[3], const float n[3], float r[3])
{
    float k = 2.0f * vec3_dot(d, n);
    for (int i = 0; i < 3; i++)
        r[i] = d[i] - k * n[i];
}

/* Refraction by Snell's law; returns 0 on total internal reflection.
 * d is unit, n unit facing against d, eta = n_incident / n_transmitted. */
static int refract_dir(const float d[3], const float n[3], float eta, float t[3])
{
    float cos_i = -vec3_dot(d, n);
    float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);
    if (k < 0.0f)
        return 0;
    float a = eta * cos_i - sqrtf(k);
    for (int i = 0; i < 3; i++)
        t[i] = eta * d[i] + a * n[i];
    return 1;
}

void shade_ray(const struct shade_context *sc, const float org[3], const float dir[3],
               float tmax, struct shade_cone cone, int depth, float rgba[4])
{
    const struct render_state *st = sc->state;
    struct trace_scene_hit hit;
    if (!trace_scene_closest(sc->scene, org, dir, 0.0f, tmax, &hit, sc->counters)) {
        memcpy(rgba, st->clear_color, 4 * sizeof(float));
        return;
    }
    /* The cone at the hit: t counts in units of dir, which need not be
     * unit length.  Reflected and refracted rays start with this width and
     * the same spread: the paper's curvature term (sec. 20.3.4), which
     * widens cones off convex surfaces and narrows them off concave ones,
     * is left out, so secondary rays filter as if every mirror were flat. */
    const float distance = hit.t * sqrtf(vec3_dot(dir, dir));
    const struct shade_cone at_hit = {fabsf(cone.width + cone.spread * distance), cone.spread};
    struct surface s;
    fetch_surface(sc, &hit, dir, at_hit.width, &s);
    float c[3];
    float unit_dir[3] = {dir[0], dir[1], dir[2]};
    vec3_normalize(unit_dir);

    if (st->shading == RENDER_EYE_LIGHT) {
        /* A headlight at the eye, no shadows: paper 004's "OpenGL-like
         * ray casting". */
        float cosine = fabsf(vec3_dot(s.n, unit_dir));
        for (int k = 0; k < 3; k++)
            c[k] = s.mat.emission[k] + st->global_ambient[k] * s.mat.ambient[k] +
                   s.mat.diffuse[k] * cosine;
        memcpy(rgba, c, sizeof(c));
        rgba[3] = 1.0f;
        return;
    }

    local_whitted(sc, &s, unit_dir, c);
    float kr = s.mat.reflectivity, kt = s.mat.transparency;
    if (depth < st->max_depth && (kr > 0.0f || kt > 0.0f)) {
        float out[4], next_org[3], next_dir[3];
        float local_weight = 1.0f - kt;
        for (int k = 0; k < 3; k++)
            c[k] *= local_weight;
        if (kr > 0.0f) {
            reflect_dir(unit_dir, s.n, next_dir);
            if (vec3_dot(next_dir, s.ng) <= 0.0f)
                reflect_dir(unit_dir, s.ng, next_dir);
            shade_offset_point(s.p, s.ng, s.p_error, next_org);
            shade_ray(sc, next_org, next_dir, INFINITY, at_hit, depth + 1, out);
            for (int k = 0; k < 3; k++)
                c[k] += kr * out[k];
        }
        if (kt > 0.0f) {
            float eta = s.front ? 1.0f / s.mat.ior : s.mat.ior;
            float below[3] = {-s.ng[0], -s.ng[1], -s.ng[2]};
            if (refract_dir(unit_dir, s.n, eta, next_dir) && vec3_dot(next_dir, s.ng) < 0.0f) {
                shade_offset_point(s.p, below, s.p_error, next_org);
            } else {
                /* Total internal reflection. */
                reflect_dir(unit_dir, s.ng, next_dir);
                shade_offset_point(s.p, s.ng, s.p_error, next_org);
            }
            shade_ray(sc, next_org, next_dir, INFINITY, at_hit, depth + 1, out);
            for (int k = 0; k < 3; k++)
                c[k] += kt * out[k];
        }
    }
    memcpy(rgba, c, sizeof(c));
    rgba[3] = 1.0f;
}
