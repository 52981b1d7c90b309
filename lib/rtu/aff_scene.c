/* SPDX-License-Identifier: Apache-2.0 */
/*
 * aff_scene.c - AFF scenes as Tracelist objects and instances (rtu.h,
 * docs/aff.md).
 *
 * This is what Wald, Benthin and Slusallek (2003) sec. 4.1 asks of a scene-graph application: group
 * the primitives by their dynamic properties, record each group once as an
 * object, and every frame instantiate the objects under the transforms of
 * the moment, redefining only the objects whose triangles move without
 * structure.  The parser (aff_parse.c) has already grouped geometry by the
 * innermost animated transform; here each group becomes
 *   - its frame's object (the root frame's is the one static object),
 *     recorded with rtBegin/rtVertex under the static 'xs' matrices of
 *     its batches, loaded onto the modelview stack like glLoadMatrix;
 *   - for animated triangles, its frame's unstructured object, whose
 *     vertices are replaced every frame with rtUpdateVertices.
 * The flattened reference (rtuBakeAFF) records the same batches through
 * the same function with the frame's world matrix in front, so the two
 * configurations differ only in where the transform is applied.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <rt/rtu.h>

#include "rtu/aff_internal.h"

struct rtu_aff_scene {
    struct aff_data data;
    RTuint *objects;     /* per frame: object of its triangles, 0: none */
    RTuint *tpa_objects; /* per frame: object of its 'tpa' triangles, 0: none */
    RTuint *textures;    /* per aff texture: texture name */
    double (*cache)[16]; /* per frame: world matrix at the time evaluated */
    int *state;
    float *tpa_positions, *tpa_normals; /* scratch, 9 floats per triangle */
    uint32_t tpa_scratch;
    int tpa_time_valid;
    double tpa_time; /* time of the animated vertices stored in the objects */
};

/* __thread is a GNU extension (gcc and clang have it; C11 spells it
 * _Thread_local), as lib/base/atomic.h documents for the core library. */
static __thread char aff_error[AFF_ERROR_SIZE];

static void set_error(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

static void set_error(const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    vsnprintf(aff_error, sizeof aff_error, fmt, args);
    va_end(args);
}

const char *rtuAFFError(void)
{
    return aff_error;
}

static const double identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/* ------------------------------------------------------------ recording */

static float clampf(float v, float lo, float hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/*
 * FORMAT.md sec. 3.2 maps onto the fixed-function material: ambient,
 * diffuse and specular as given; the specular colour also scales mirror
 * reflection (the ray-traced NFF convention), which our scalar
 * RT_REFLECTIVITY takes as the mean of the three; T is the refracted
 * weight and ior <= 0 means 1.  Exponents above GL's 128 are clamped.
 */
static void apply_material(const struct aff_data *d, int index)
{
    static const struct aff_material fallback = {
        {0.2f, 0.2f, 0.2f}, {0.8f, 0.8f, 0.8f}, {0.0f, 0.0f, 0.0f}, 0.0f, 0.0f, 1.0f};
    const struct aff_material *m = index >= 0 ? &d->materials[index] : &fallback;
    float amb[4] = {m->ambient[0], m->ambient[1], m->ambient[2], 1.0f};
    float dif[4] = {m->diffuse[0], m->diffuse[1], m->diffuse[2], 1.0f};
    float spe[4] = {m->specular[0], m->specular[1], m->specular[2], 1.0f};
    float emi[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, amb);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, dif);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, spe);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_EMISSION, emi);
    rtMaterialf(RT_FRONT_AND_BACK, RT_SHININESS, clampf(m->shine, 0.0f, 128.0f));
    float mirror = (m->specular[0] + m->specular[1] + m->specular[2]) / 3.0f;
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, clampf(mirror, 0.0f, 1.0f));
    rtMaterialf(RT_FRONT_AND_BACK, RT_TRANSPARENCY, clampf(m->transmittance, 0.0f, 1.0f));
    rtMaterialf(RT_FRONT_AND_BACK, RT_INDEX_OF_REFRACTION, m->ior > 0.0f ? m->ior : 1.0f);
}

/* What the recorder last set, so runs of equal state cost no calls. */
struct record_state {
    int material; /* -2: unknown */
    int texture;  /* -2: unknown */
};

static void apply_state(const RTUaffscene *s, struct record_state *rs, int material,
                        int texture)
{
    if (material != rs->material) {
        apply_material(&s->data, material);
        rs->material = material;
    }
    if (texture != rs->texture) {
        if (texture >= 0) {
            rtBindTexture(RT_TEXTURE_2D, s->textures[texture]);
            rtEnable(RT_TEXTURE_2D);
        } else {
            rtDisable(RT_TEXTURE_2D);
        }
        rs->texture = texture;
    }
}

/*
 * The loader places vertices itself: a display list's vertices are
 * relative to the list's own matrix (docs/lists.md), and an absolute
 * rtLoadMatrixd would make them ignore the instance matrix, a
 * push/multiply/pop pair would cost every rtuDrawAFF a second stack level.
 * These are the recording's own operations in double (mat4.h's point
 * transform and the cofactor matrix for normals, scene/recording.c), so
 * the stored floats, and the images, are those of the loader before lists
 * had matrices of their own.
 */
static void vertex(const double m[16], const float p[3])
{
    double out[3];
    for (int r = 0; r < 3; r++)
        out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
    rtVertex3d(out[0], out[1], out[2]);
}

static void normal(const double m[16], const float n[3])
{
    const double a = m[0], b = m[4], c = m[8];
    const double d = m[1], e = m[5], f = m[9];
    const double g = m[2], h = m[6], i = m[10];
    const double C[3][3] = {{e * i - f * h, -(d * i - f * g), d * h - e * g},
                            {-(b * i - c * h), a * i - c * g, -(a * h - b * g)},
                            {b * f - c * e, -(a * f - c * d), a * e - b * d}};
    float out[3];
    for (int r = 0; r < 3; r++)
        out[r] = (float)(C[r][0] * n[0] + C[r][1] * n[1] + C[r][2] * n[2]);
    rtNormal3fv(out);
}

/* Records a group's static triangles into the object being defined, each
 * batch under base * (its static matrix). */
static void record_triangles(const RTUaffscene *s, const struct aff_group *g,
                             const double base[16], struct record_state *rs)
{
    for (uint32_t b = 0; b < g->batch_count; b++) {
        const struct aff_batch *batch = &g->batches[b];
        double m[16];
        aff_matrix_mul(m, base, s->data.matrices[batch->matrix]);
        apply_state(s, rs, batch->material, batch->texture);
        rtBegin(RT_TRIANGLES);
        for (uint32_t i = 0; i < batch->count; i++) {
            const struct aff_triangle *t = &g->tris[batch->first + i];
            for (int j = 0; j < 3; j++) {
                normal(m, &t->n[3 * j]);
                if (batch->has_uv)
                    rtTexCoord2fv(&t->uv[2 * j]);
                vertex(m, &t->p[3 * j]);
            }
        }
        rtEnd();
    }
}

static void eval_tpas(RTUaffscene *s, const struct aff_group *g, double t)
{
    for (uint32_t i = 0; i < g->tpa_count; i++)
        aff_tpa_eval(g->tpas[i].keys, g->tpas[i].key_count, t, &s->tpa_positions[9 * i],
                     &s->tpa_normals[9 * i]);
}

/* Records a group's animated triangles at time t (vertex 3i+j is vertex j
 * of triangle i, the numbering rtUpdateVertices relies on). */
static void record_tpas(RTUaffscene *s, const struct aff_group *g, const double base[16],
                        double t, struct record_state *rs)
{
    eval_tpas(s, g, t);
    int open = 0;
    for (uint32_t i = 0; i < g->tpa_count; i++) {
        if (g->tpas[i].material != rs->material || rs->texture != -1) {
            if (open)
                rtEnd();
            apply_state(s, rs, g->tpas[i].material, -1);
            open = 0;
        }
        if (!open) {
            rtBegin(RT_TRIANGLES);
            open = 1;
        }
        for (int j = 0; j < 3; j++) {
            normal(base, &s->tpa_normals[9 * i + 3 * j]);
            vertex(base, &s->tpa_positions[9 * i + 3 * j]);
        }
    }
    if (open)
        rtEnd();
}

/* Saves the modelview matrix and texture state the loader changes. */
struct saved_state {
    RTint matrix_mode;
    RTint texture_binding;
    RTboolean texture_enabled;
};

/* True when the modelview stack has a free level.  The loader's push must
 * not fail: a failed rtPushMatrix changes nothing, and the matching
 * rtPopMatrix would then remove the application's own top matrix (found by
 * conformance/aff_loader.c with a full stack). */
static int modelview_level_free(void)
{
    RTint depth = 0, max_depth = 0;
    rtGetIntegerv(RT_MODELVIEW_STACK_DEPTH, &depth);
    rtGetIntegerv(RT_MAX_MODELVIEW_STACK_DEPTH, &max_depth);
    return depth < max_depth;
}

/* Records RT_STACK_OVERFLOW for a full modelview stack, as a GL utility's
 * failing glPushMatrix would, whatever the matrix mode; changes nothing. */
static void record_modelview_overflow(void)
{
    RTint mode = RT_MODELVIEW;
    rtGetIntegerv(RT_MATRIX_MODE, &mode);
    rtMatrixMode(RT_MODELVIEW);
    rtPushMatrix();
    rtMatrixMode((RTenum)mode);
}

/* Returns 0, changing nothing, when the modelview stack is full. */
static int save_state(struct saved_state *sv)
{
    if (!modelview_level_free())
        return 0;
    rtGetIntegerv(RT_MATRIX_MODE, &sv->matrix_mode);
    rtGetIntegerv(RT_TEXTURE_BINDING_2D, &sv->texture_binding);
    sv->texture_enabled = rtIsEnabled(RT_TEXTURE_2D);
    rtMatrixMode(RT_MODELVIEW);
    rtPushMatrix();
    return 1;
}

static void restore_state(const struct saved_state *sv)
{
    rtPopMatrix();
    rtMatrixMode((RTenum)sv->matrix_mode);
    rtBindTexture(RT_TEXTURE_2D, (RTuint)sv->texture_binding);
    if (sv->texture_enabled)
        rtEnable(RT_TEXTURE_2D);
    else
        rtDisable(RT_TEXTURE_2D);
}

/* ------------------------------------------------------------ loading */

static void scene_free(RTUaffscene *s)
{
    int frames = s->data.frame_count_nodes;
    for (int f = 0; f < frames; f++) {
        if (s->objects && s->objects[f])
            rtDeleteObjects(1, &s->objects[f]);
        if (s->tpa_objects && s->tpa_objects[f])
            rtDeleteObjects(1, &s->tpa_objects[f]);
    }
    if (s->textures) {
        for (int i = 0; i < s->data.texture_count; i++)
            if (s->textures[i])
                rtDeleteTextures(1, &s->textures[i]);
    }
    free(s->objects);
    free(s->tpa_objects);
    free(s->textures);
    free(s->cache);
    free(s->state);
    free(s->tpa_positions);
    free(s->tpa_normals);
    aff_data_release(&s->data);
    free(s);
}

/* FORMAT.md sec. 6: v = 0 is the first row stored in the file.  rtuLoadImage
 * returns rows bottom to top and rtTexImage2D takes row 0 as t = 0, so the
 * rows are flipped once more on the way in. */
static int load_texture(RTUaffscene *s, int i)
{
    const struct aff_texture *tex = &s->data.textures[i];
    RTsizei w, h;
    /* The file policy of includes holds for textures too (aff_file.c):
     * rtuLoadImage would block on a FIFO and read any file it is given. */
    char why[AFF_ERROR_SIZE];
    if (aff_file_check(tex->path, s->data.root, s->data.max_file_bytes, why, sizeof why)) {
        set_error("%s: texture '%s': %s", tex->where, tex->name, why);
        return -1;
    }
    unsigned char *pixels = rtuLoadImage(tex->path, &w, &h, RT_UNSIGNED_BYTE);
    if (!pixels) {
        set_error("%s: texture '%s': %s", tex->where, tex->name, rtuImageError());
        return -1;
    }
    size_t row = (size_t)w * 4;
    unsigned char *tmp = malloc(row);
    if (!tmp) {
        rtuFreeImage(pixels);
        set_error("%s: texture '%s': out of memory", tex->where, tex->name);
        return -1;
    }
    for (RTsizei y = 0; y < h / 2; y++) {
        unsigned char *a = pixels + (size_t)y * row, *b = pixels + (size_t)(h - 1 - y) * row;
        memcpy(tmp, a, row);
        memcpy(a, b, row);
        memcpy(b, tmp, row);
    }
    free(tmp);
    rtGenTextures(1, &s->textures[i]);
    rtBindTexture(RT_TEXTURE_2D, s->textures[i]);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_WRAP_S, RT_REPEAT);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_WRAP_T, RT_REPEAT);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_LINEAR_MIPMAP_LINEAR);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_LINEAR);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGBA, w, h, 0, RT_RGBA, RT_UNSIGNED_BYTE, pixels);
    rtuFreeImage(pixels);
    return 0;
}

/* Starts an object; rs is reset because a display list's state calls
 * apply inside it only (GL_COMPILE): each object sets its own material
 * and texture, or its triangles would take the caller's at
 * rtInstantiateObject (docs/lists.md). */
static RTuint new_object(struct record_state *rs)
{
    rs->material = -2;
    rs->texture = -2;
    RTuint name = 0;
    rtGenObjects(1, &name);
    if (name)
        rtNewObject(name);
    return name;
}

RTUaffscene *rtuLoadAFF(const char *path)
{
    return rtuLoadAFFv(path, NULL);
}

/* The attribute list of rtuLoadAFFv into limits; 0, or -1 with the
 * reason set. */
static int read_attributes(const RTint *attribs, struct aff_limits *limits)
{
    aff_limits_default(limits);
    for (int i = 0; attribs && attribs[i] != 0; i += 2) {
        RTint v = attribs[i + 1];
        switch (attribs[i]) {
        case RTU_AFF_MAX_TRIANGLES:
            if (v < 1)
                break;
            limits->max_triangles = (uint64_t)v;
            continue;
        case RTU_AFF_MAX_READ_MIB:
            if (v < 1)
                break;
            limits->max_read_bytes = (uint64_t)v << 20;
            continue;
        case RTU_AFF_MAX_FILE_MIB:
            if (v < 1)
                break;
            limits->max_file_bytes = (uint64_t)v << 20;
            continue;
        case RTU_AFF_ANY_DIRECTORY:
            if (v != RT_TRUE && v != RT_FALSE)
                break;
            limits->any_directory = v == RT_TRUE;
            continue;
        default:
            set_error("rtuLoadAFFv: unknown attribute 0x%x", (unsigned)attribs[i]);
            return -1;
        }
        set_error("rtuLoadAFFv: attribute 0x%x: value %d is out of range", (unsigned)attribs[i],
                  v);
        return -1;
    }
    return 0;
}

RTUaffscene *rtuLoadAFFv(const char *path, const RTint *attribs)
{
    aff_error[0] = '\0';
    if (!path) {
        set_error("rtuLoadAFF: path is NULL");
        return NULL;
    }
    if (!rtGetCurrentContext()) {
        set_error("rtuLoadAFF(%s): no current context", path);
        return NULL;
    }
    struct aff_limits limits;
    if (read_attributes(attribs, &limits))
        return NULL;
    struct aff_data data;
    if (aff_parse_file(path, &limits, &data, aff_error, sizeof aff_error))
        return NULL;
    return aff_scene_create(&data, path);
}

RTUaffscene *aff_scene_create(struct aff_data *data, const char *name)
{
    aff_error[0] = '\0';
    if (!rtGetCurrentContext()) {
        set_error("rtuLoadAFF(%s): no current context", name);
        aff_data_release(data);
        return NULL;
    }
    RTUaffscene *s = calloc(1, sizeof *s);
    if (!s) {
        /* Line 0: the file as a whole (docs/aff.md). */
        set_error("%s:0: out of memory while recording the scene", name);
        aff_data_release(data);
        return NULL;
    }
    /* The scene owns the data from here on; scene_free releases it. */
    s->data = *data;
    memset(data, 0, sizeof *data);
    const struct aff_data *d = &s->data;
    int frames = d->frame_count_nodes;
    uint32_t max_tpa = 0;
    for (int f = 0; f < frames; f++)
        if (d->frames[f].group.tpa_count > max_tpa)
            max_tpa = d->frames[f].group.tpa_count;
    s->objects = calloc((size_t)frames, sizeof *s->objects);
    s->tpa_objects = calloc((size_t)frames, sizeof *s->tpa_objects);
    s->textures = calloc((size_t)d->texture_count + 1, sizeof *s->textures);
    s->cache = malloc((size_t)frames * sizeof *s->cache);
    s->state = calloc((size_t)frames, sizeof *s->state);
    s->tpa_scratch = max_tpa;
    s->tpa_positions = malloc(((size_t)max_tpa * 9 + 1) * sizeof(float));
    s->tpa_normals = malloc(((size_t)max_tpa * 9 + 1) * sizeof(float));
    if (!s->objects || !s->tpa_objects || !s->textures || !s->cache || !s->state ||
        !s->tpa_positions || !s->tpa_normals) {
        scene_free(s);
        set_error("%s:0: out of memory while recording the scene", name);
        return NULL;
    }

    /* The loader reports the API's errors as its own failure; an error the
     * application left pending is read (and cleared) first. */
    (void)rtGetError();
    struct saved_state sv;
    if (!save_state(&sv)) {
        scene_free(s);
        set_error("%s:0: the modelview stack is full; the loader needs one level", name);
        return NULL;
    }
    int ok = 1;
    for (int i = 0; i < d->texture_count && ok; i++)
        ok = load_texture(s, i) == 0;
    struct record_state rs = {-2, -2};
    double t0 = d->t0;
    for (int f = 0; f < frames && ok; f++) {
        const struct aff_group *g = &d->frames[f].group;
        if (g->tri_count) {
            s->objects[f] = new_object(&rs);
            record_triangles(s, g, identity, &rs);
            rtEndObject();
        }
        if (g->tpa_count) {
            s->tpa_objects[f] = new_object(&rs);
            record_tpas(s, g, identity, t0, &rs);
            rtEndObject();
        }
    }
    restore_state(&sv);
    if (ok) {
        RTenum e = rtGetError();
        if (e != RT_NO_ERROR) {
            set_error("%s:0: the Tracelist API recorded error 0x%04x%s while the scene was "
                      "recorded",
                      name, e, e == RT_OUT_OF_MEMORY ? " (out of memory)" : "");
            ok = 0;
        }
    }
    if (!ok) {
        scene_free(s);
        return NULL;
    }
    s->tpa_time_valid = 1;
    s->tpa_time = t0;
    return s;
}

void rtuDeleteAFF(RTUaffscene *scene)
{
    if (scene)
        scene_free(scene);
}

/* ------------------------------------------------------------ queries */

const struct aff_data *aff_scene_data(const RTUaffscene *s)
{
    return s ? &s->data : NULL;
}

void rtuGetAFFiv(const RTUaffscene *s, RTenum pname, RTint *params)
{
    if (!s || !params)
        return;
    const struct aff_data *d = &s->data;
    int statics = 0, animated = 0, unstructured = 0;
    for (int f = 0; f < d->frame_count_nodes; f++) {
        if (s->objects[f])
            *(f == 0 ? &statics : &animated) += 1;
        if (s->tpa_objects[f])
            unstructured++;
    }
    switch (pname) {
    case RTU_AFF_FRAMES:
        params[0] = d->frame_count;
        break;
    case RTU_AFF_RESOLUTION:
        params[0] = d->resolution[0];
        params[1] = d->resolution[1];
        break;
    case RTU_AFF_OBJECTS:
    case RTU_AFF_INSTANCES:
        params[0] = statics + animated + unstructured;
        break;
    case RTU_AFF_STATIC_OBJECTS:
        params[0] = statics;
        break;
    case RTU_AFF_ANIMATED_OBJECTS:
        params[0] = animated;
        break;
    case RTU_AFF_UNSTRUCTURED_OBJECTS:
        params[0] = unstructured;
        break;
    case RTU_AFF_TRIANGLES:
        params[0] = (RTint)(d->static_triangles + d->animated_triangles + d->tpa_triangles);
        break;
    case RTU_AFF_ANIMATED_TRIANGLES:
        params[0] = (RTint)d->tpa_triangles;
        break;
    case RTU_AFF_LIGHTS:
        params[0] = d->light_count;
        break;
    case RTU_AFF_TEXTURES:
        params[0] = d->texture_count;
        break;
    case RTU_AFF_MATERIALS:
        params[0] = d->material_count;
        break;
    case RTU_AFF_TRANSFORM_NODES:
        params[0] = d->frame_count_nodes - 1;
        break;
    default:
        break;
    }
}

RTsizei rtuAFFObjects(const RTUaffscene *s, RTenum kind, RTsizei max, RTuint *names)
{
    if (!s)
        return 0;
    RTsizei n = 0;
    for (int f = 0; f < s->data.frame_count_nodes; f++) {
        RTuint name = 0;
        if (kind == RT_STATIC && f == 0)
            name = s->objects[f];
        else if (kind == RT_AFFINE && f > 0)
            name = s->objects[f];
        else if (kind == RT_UNSTRUCTURED)
            name = s->tpa_objects[f];
        if (name) {
            if (names && n < max)
                names[n] = name;
            n++;
        }
    }
    return n;
}

RTdouble rtuAFFFrameTime(const RTUaffscene *s, RTint frame)
{
    if (!s)
        return 0.0;
    return aff_frame_time(s->data.t0, s->data.t1, s->data.frame_count, frame);
}

static void normalize3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0.0)
        for (int k = 0; k < 3; k++)
            v[k] /= l;
}

/* FORMAT.md sec. 8: 'k camera' overrides from/at/up; with a translation
 * track only, the camera keeps aiming at the static 'at' point. */
void rtuAFFCamera(const RTUaffscene *s, RTdouble t, RTdouble eye[3], RTdouble dir[3],
                  RTdouble up[3])
{
    if (!s || !eye || !dir || !up)
        return;
    const struct aff_data *d = &s->data;
    const struct aff_animation *cam = d->camera >= 0 ? &d->animations[d->camera] : NULL;
    for (int k = 0; k < 3; k++) {
        eye[k] = d->from[k];
        dir[k] = (double)d->at[k] - (double)d->from[k];
        up[k] = d->up[k];
    }
    if (cam && cam->has_transl && cam->has_rot) {
        aff_camera_eval(&cam->transl, &cam->rot, t, eye, dir, up);
    } else if (cam && cam->has_transl) {
        aff_track_eval(&cam->transl, t, eye);
        for (int k = 0; k < 3; k++)
            dir[k] = (double)d->at[k] - eye[k];
    }
    normalize3(dir);
    normalize3(up);
}

void rtuAFFView(const RTUaffscene *s, RTdouble t, RTdouble aspect)
{
    if (!s)
        return;
    const struct aff_data *d = &s->data;
    double eye[3], dir[3], up[3];
    rtuAFFCamera(s, t, eye, dir, up);
    if (!(aspect > 0.0))
        aspect = (double)d->resolution[0] / (double)d->resolution[1];
    /* No yon in AFF (sec. 3.1): a far plane 1e7 near distances away keeps
     * the projection well conditioned in double and never clips the
     * scenes (the robot city spans 700 units at hither 1). */
    rtuPerspective(d->fov_degrees, aspect, d->hither, (double)d->hither * 1e7);
    rtuLookAt(eye[0], eye[1], eye[2], eye[0] + dir[0], eye[1] + dir[1], eye[2] + dir[2], up[0],
              up[1], up[2]);
}

void rtuAFFLights(const RTUaffscene *s, RTdouble t)
{
    if (!s)
        return;
    const struct aff_data *d = &s->data;
    RTint max_lights = 0;
    rtGetIntegerv(RT_MAX_LIGHTS, &max_lights);
    float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    for (int i = 0; i < max_lights; i++) {
        RTenum light = RT_LIGHT0 + (RTenum)i;
        if (i >= d->light_count) {
            rtDisable(light);
            continue;
        }
        const struct aff_light *l = &d->lights[i];
        float pos[4] = {l->position[0], l->position[1], l->position[2], 1.0f};
        if (l->animation >= 0) {
            double p[3];
            aff_track_eval(&d->animations[l->animation].transl, t, p);
            for (int k = 0; k < 3; k++)
                pos[k] = (float)p[k];
        }
        float col[4] = {l->color[0], l->color[1], l->color[2], 1.0f};
        rtLightfv(light, RT_POSITION, pos);
        rtLightfv(light, RT_AMBIENT, black);
        rtLightfv(light, RT_DIFFUSE, col);
        rtLightfv(light, RT_SPECULAR, col);
        rtLightf(light, RT_CONSTANT_ATTENUATION, 1.0f);
        rtLightf(light, RT_LINEAR_ATTENUATION, 0.0f);
        rtLightf(light, RT_QUADRATIC_ATTENUATION, 0.0f);
        rtEnable(light);
    }
    float am[4] = {d->ambient[0], d->ambient[1], d->ambient[2], 1.0f};
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, am);
    if (d->has_background)
        rtClearColor(d->background[0], d->background[1], d->background[2], 1.0f);
    else
        rtClearColor(0.0f, 0.0f, 0.0f, 1.0f);
}

/* ------------------------------------------------------------ frames */

static void update_tpas(RTUaffscene *s, double t)
{
    if (s->tpa_time_valid && s->tpa_time == t)
        return;
    const struct aff_data *d = &s->data;
    for (int f = 0; f < d->frame_count_nodes; f++) {
        const struct aff_group *g = &d->frames[f].group;
        if (!s->tpa_objects[f])
            continue;
        eval_tpas(s, g, t);
        RTsizei n = (RTsizei)(3 * g->tpa_count);
        rtUpdateVertices(s->tpa_objects[f], RT_VERTEX_ARRAY, 0, n, RT_FLOAT, 0, s->tpa_positions);
        rtUpdateVertices(s->tpa_objects[f], RT_NORMAL_ARRAY, 0, n, RT_FLOAT, 0, s->tpa_normals);
    }
    s->tpa_time = t;
    s->tpa_time_valid = 1;
}

void rtuDrawAFF(RTUaffscene *s, RTdouble t)
{
    if (!s)
        return;
    const struct aff_data *d = &s->data;
    if (!modelview_level_free()) {
        /* Draw nothing rather than pop the application's matrix (see
         * save_state). */
        record_modelview_overflow();
        return;
    }
    update_tpas(s, t);
    RTint mode, texture_binding;
    rtGetIntegerv(RT_MATRIX_MODE, &mode);
    /* Calling the objects replays their texture calls (GL's glCallList
     * semantics, docs/lists.md): the application's texture state is put
     * back below. */
    rtGetIntegerv(RT_TEXTURE_BINDING_2D, &texture_binding);
    RTboolean texture_enabled = rtIsEnabled(RT_TEXTURE_2D);
    rtMatrixMode(RT_MODELVIEW);
    memset(s->state, 0, (size_t)d->frame_count_nodes * sizeof *s->state);
    for (int f = 0; f < d->frame_count_nodes; f++) {
        if (!s->objects[f] && !s->tpa_objects[f])
            continue;
        double m[16];
        if (!aff_frame_matrix(d, f, t, s->cache, s->state, m))
            continue; /* hidden, or a matrix that is not finite */
        rtPushMatrix();
        rtMultMatrixd(m);
        if (s->objects[f])
            rtInstantiateObject(s->objects[f]);
        if (s->tpa_objects[f])
            rtInstantiateObject(s->tpa_objects[f]);
        rtPopMatrix();
    }
    rtBindTexture(RT_TEXTURE_2D, (RTuint)texture_binding);
    if (texture_enabled)
        rtEnable(RT_TEXTURE_2D);
    else
        rtDisable(RT_TEXTURE_2D);
    rtMatrixMode((RTenum)mode);
}

RTuint rtuBakeAFF(RTUaffscene *s, RTdouble t)
{
    if (!s)
        return 0;
    const struct aff_data *d = &s->data;
    struct saved_state sv;
    if (!save_state(&sv)) {
        record_modelview_overflow(); /* see rtuDrawAFF */
        return 0;
    }
    struct record_state rs = {-2, -2};
    RTuint name = new_object(&rs);
    if (name) {
        memset(s->state, 0, (size_t)d->frame_count_nodes * sizeof *s->state);
        for (int f = 0; f < d->frame_count_nodes; f++) {
            const struct aff_group *g = &d->frames[f].group;
            double m[16];
            if ((!g->tri_count && !g->tpa_count) ||
                !aff_frame_matrix(d, f, t, s->cache, s->state, m))
                continue;
            if (g->tri_count)
                record_triangles(s, g, m, &rs);
            if (g->tpa_count)
                record_tpas(s, g, m, t, &rs);
        }
        rtEndObject();
    }
    restore_state(&sv);
    return name;
}
