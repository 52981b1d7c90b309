/* SPDX-License-Identifier: Apache-2.0 */
/*
 * stability_scale.c - far from the origin and at extreme scales, scenes
 * render without shadow acne, holes or misplaced shadows.
 *
 * The scene: a floor (an 8x8 grid over [-10,10]^2 at y = 0) and a box
 * ([-2,2] x [0,4] x [-2,2], each face a 4x4 grid) lit by one directional
 * light, Whitted shading with shadows, seen by a tilted orthographic camera
 * at 160x120.  It is rendered at the origin at unit scale and then moved by
 * a world placement W: translated by (1e5, 1e5, 1e5), scaled by 1e-4,
 * scaled by 1e4, turned about an oblique axis, and turned and translated,
 * each both as instances under W and flattened (W as the modelview at
 * rtVertex time).  The projection is Ortho * View * W^-1 and the light is
 * given under W, so every variant shows the same picture.
 *
 * The test classifies every pixel itself, in double, from the unit scene:
 * background, floor lit or in the box's shadow, or one of the box's faces
 * (lit, or turned away from the light).  A pixel whose class is the same at
 * its centre and at eight points one pixel away is "interior"; its colour is
 * known exactly (ambient + diffuse * N.L when lit, ambient alone
 * otherwise; the material and light have no specular part).  Checked per
 * variant:
 *   - no acne: no interior lit pixel shows its shadow colour;
 *   - no holes: no interior surface pixel shows the background, and no
 *     background pixel a surface;
 *   - shadows where they belong: no interior shadow pixel shows the lit
 *     colour;
 *   - every interior pixel has its exact colour within 1e-4 (1e-2 for the
 *     flattened, turned scene 1e5 from the origin, whose float vertices
 *     are themselves off the faces' planes: QUANTIZED_VALUE_TOLERANCE);
 *   - against the unit scene: pixels differing by more than that are all
 *     non-interior (boundary) pixels, at most 3% of the image.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brute_force.h"
#include "testutil.h"

#define WIDTH 160
#define HEIGHT 120
#define VALUE_TOLERANCE 1e-4
/* Flattened, turned and 1e5 from the origin, the world vertices are
 * rounded to float on a grid of 2^-7 (half an ulp of 1e5 off), so faces
 * 1 to 2.5 units wide are no longer plane: their normals tilt by up to
 * ~8e-3 and N.L moves by that much.  Acne or a hole changes a pixel by
 * 0.15 or more. */
#define QUANTIZED_VALUE_TOLERANCE 1e-2
#define MARGIN_PIXELS 1.0
#define MAX_BOUNDARY_FRACTION 0.03
#define MAX_PRINTED 8

enum { FLOOR = 1, BOX = 2, FLAT_SCENE = 3 };

/* Classes of a pixel. */
enum { BACKGROUND, FLOOR_LIT, FLOOR_SHADOW, BOX_FACE0 };

static const float floor_ambient[4] = {0.3f, 0.3f, 0.3f, 1.0f};
static const float floor_diffuse[4] = {0.6f, 0.6f, 0.55f, 1.0f};
static const float box_ambient[4] = {0.3f, 0.1f, 0.1f, 1.0f};
static const float box_diffuse[4] = {0.8f, 0.3f, 0.2f, 1.0f};
static const float clear_color[4] = {0.1f, 0.2f, 0.9f, 0.0f};
static const double light_dir[3] = {-1.5, 1.5, 1.0};
static const double global_ambient = 0.2;

/* The unit-scene camera: eye space = View * world. */
static void view_matrix(double v[16])
{
    double t[16], rx[16], ry[16];
    const double ax[3] = {1, 0, 0}, ay[3] = {0, 1, 0};
    bf_translation(t, 0.0, 0.0, -40.0);
    bf_rotation(rx, 35.0 * 3.14159265358979323846 / 180.0, ax);
    bf_rotation(ry, -30.0 * 3.14159265358979323846 / 180.0, ay);
    bf_mul(v, t, rx);
    bf_mul(v, v, ry);
}

static void ortho_matrix(double m[16])
{
    bf_ortho(m, -11.0, 11.0, -8.25, 8.25, 1.0, 100.0);
}

/* ---- the reference classification (unit scene, double) ---------------------- */

/* Ray/box slab test; returns the entry distance and face (0..5: -x,+x,-y,
 * +y,-z,+z) or INFINITY. */
static double hit_box(const double o[3], const double d[3], int *face)
{
    const double lo[3] = {-2, 0, -2}, hi[3] = {2, 4, 2};
    double t0 = -INFINITY, t1 = INFINITY;
    int entry_face = -1;
    for (int k = 0; k < 3; k++) {
        if (d[k] == 0.0) {
            if (o[k] < lo[k] || o[k] > hi[k])
                return INFINITY;
            continue;
        }
        double a = (lo[k] - o[k]) / d[k], b = (hi[k] - o[k]) / d[k];
        int fa = 2 * k, fb = 2 * k + 1;
        if (a > b) {
            double tmp = a;
            a = b;
            b = tmp;
            fa = 2 * k + 1;
        }
        (void)fb;
        if (a > t0) {
            t0 = a;
            entry_face = fa;
        }
        if (b < t1)
            t1 = b;
    }
    if (t0 > t1 || t0 <= 1e-9)
        return INFINITY;
    *face = entry_face;
    return t0;
}

static int classify_ray(const double o[3], const double d[3])
{
    int face = -1;
    double tb = hit_box(o, d, &face);
    double tf = d[1] != 0.0 ? -o[1] / d[1] : INFINITY;
    if (tf > 0.0) {
        double x = o[0] + tf * d[0], z = o[2] + tf * d[2];
        if (fabs(x) > 10.0 || fabs(z) > 10.0)
            tf = INFINITY;
    } else {
        tf = INFINITY;
    }
    if (tb < tf)
        return BOX_FACE0 + face;
    if (tf == INFINITY)
        return BACKGROUND;
    double p[3] = {o[0] + tf * d[0], 0.0, o[2] + tf * d[2]};
    int dummy;
    return hit_box(p, light_dir, &dummy) < INFINITY ? FLOOR_SHADOW : FLOOR_LIT;
}

/* The unit-scene ray through window point (x, y) (pixel units). */
static void pixel_ray(const double inv[16], double x, double y, double o[3], double d[3])
{
    double ndc_near[3] = {2.0 * x / WIDTH - 1.0, 2.0 * y / HEIGHT - 1.0, -1.0};
    double ndc_far[3] = {ndc_near[0], ndc_near[1], 1.0};
    double f[3];
    bf_project(inv, ndc_near, o);
    bf_project(inv, ndc_far, f);
    bf_sub(d, f, o);
}

/* Class of each pixel, or -1 for a boundary pixel. */
static void classify(int *classes)
{
    double v[16], p[16], pv[16], inv[16];
    view_matrix(v);
    ortho_matrix(p);
    bf_mul(pv, p, v);
    bf_invert(inv, pv);
    for (int y = 0; y < HEIGHT; y++)
        for (int x = 0; x < WIDTH; x++) {
            double o[3], d[3];
            pixel_ray(inv, x + 0.5, y + 0.5, o, d);
            int c = classify_ray(o, d);
            for (int dy = -1; dy <= 1 && c >= 0; dy++)
                for (int dx = -1; dx <= 1 && c >= 0; dx++) {
                    pixel_ray(inv, x + 0.5 + MARGIN_PIXELS * dx, y + 0.5 + MARGIN_PIXELS * dy, o,
                              d);
                    if (classify_ray(o, d) != c)
                        c = -1;
                }
            classes[y * WIDTH + x] = c;
        }
}

/* Expected RGB of a class. */
static void expected_color(int c, double rgb[3])
{
    double l[3];
    double len = bf_length(light_dir);
    for (int k = 0; k < 3; k++)
        l[k] = light_dir[k] / len;
    if (c == BACKGROUND) {
        for (int k = 0; k < 3; k++)
            rgb[k] = clear_color[k];
        return;
    }
    const float *amb = c >= BOX_FACE0 ? box_ambient : floor_ambient;
    const float *dif = c >= BOX_FACE0 ? box_diffuse : floor_diffuse;
    double n_dot_l = 0.0;
    if (c == FLOOR_LIT) {
        n_dot_l = l[1];
    } else if (c >= BOX_FACE0) {
        int face = c - BOX_FACE0;
        double n = (face & 1) ? 1.0 : -1.0;
        n_dot_l = n * l[face / 2];
        if (n_dot_l < 0.0)
            n_dot_l = 0.0;
    }
    for (int k = 0; k < 3; k++)
        rgb[k] = global_ambient * amb[k] + dif[k] * n_dot_l;
}

/* ---- the library's rendering -------------------------------------------------- */

static void grid_quad(int axis, double level, double u0, double u1, double v0, double v1, int n,
                      int flip)
{
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double corner[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
            for (int c = 0; c < 4; c++) {
                int cc = flip ? 3 - c : c;
                double p[3];
                p[axis] = level;
                p[u] = u0 + (u1 - u0) * corner[cc][0] / n;
                p[v] = v0 + (v1 - v0) * corner[cc][1] / n;
                rtVertex3d(p[0], p[1], p[2]);
            }
        }
}

/* Issues the floor and the box (inside an object definition). */
static void emit_floor(void)
{
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, floor_ambient);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, floor_diffuse);
    rtBegin(RT_QUADS);
    grid_quad(1, 0.0, -10.0, 10.0, -10.0, 10.0, 8, 0);
    rtEnd();
}

static void emit_box(void)
{
    static const double lo[3] = {-2, 0, -2}, hi[3] = {2, 4, 2};
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT, box_ambient);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_DIFFUSE, box_diffuse);
    rtBegin(RT_QUADS);
    for (int axis = 0; axis < 3; axis++) {
        int u = (axis + 1) % 3, v = (axis + 2) % 3;
        grid_quad(axis, lo[axis], lo[u], hi[u], lo[v], hi[v], 4, 1);
        grid_quad(axis, hi[axis], lo[u], hi[u], lo[v], hi[v], 4, 0);
    }
    rtEnd();
}

struct variant {
    const char *label;
    double offset;
    double scale;
    int flat;
    int rotated;      /* W also turns the scene about an oblique axis */
    double tolerance; /* of a pixel's value */
};

/* W = T(offset) R S(scale), R a fixed oblique rotation or the identity. */
static void placement(const struct variant *vr, double w[16])
{
    double t[16], r[16], s[16];
    bf_translation(t, vr->offset, vr->offset, vr->offset);
    bf_scaling(s, vr->scale, vr->scale, vr->scale);
    bf_identity(r);
    if (vr->rotated) {
        double axis[3] = {0.3, -0.8, 0.52};
        double len = bf_length(axis);
        for (int k = 0; k < 3; k++)
            axis[k] /= len;
        bf_rotation(r, 0.7, axis);
    }
    bf_mul(w, t, r);
    bf_mul(w, w, s);
}

/* Renders the scene placed by W (placement()); RGBA floats. */
static void render_variant(const struct variant *vr, float *rgba)
{
    RTcontext ctx = tu_make_context(NULL);
    double w[16], w_inverse[16];
    placement(vr, w);
    bf_invert(w_inverse, w);

    rtMatrixMode(RT_MODELVIEW);
    if (vr->flat) {
        rtNewObject(FLAT_SCENE);
        rtLoadMatrixd(w);
        emit_floor();
        emit_box();
        rtEndObject();
        rtLoadIdentity();
        rtBeginFrame();
        rtInstantiateObject(FLAT_SCENE);
    } else {
        rtNewObject(FLOOR);
        emit_floor();
        rtEndObject();
        rtNewObject(BOX);
        emit_box();
        rtEndObject();
        rtLoadMatrixd(w);
        rtBeginFrame();
        rtInstantiateObject(FLOOR);
        rtInstantiateObject(BOX);
        rtLoadIdentity();
    }

    /* Projection = Ortho * View * W^-1. */
    double v[16];
    view_matrix(v);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtOrtho(-11.0, 11.0, -8.25, 8.25, 1.0, 100.0);
    rtMultMatrixd(v);
    rtMultMatrixd(w_inverse);
    rtMatrixMode(RT_MODELVIEW);

    /* The light's direction turns with the scene (a position is
     * transformed by the modelview at the call). */
    const float l[4] = {(float)light_dir[0], (float)light_dir[1], (float)light_dir[2], 0.0f};
    rtLoadMatrixd(w);
    const float black[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1};
    const float ambient[4] = {(float)global_ambient, (float)global_ambient, (float)global_ambient,
                              1.0f};
    rtLightfv(RT_LIGHT0, RT_POSITION, l);
    rtLoadIdentity();
    rtLightfv(RT_LIGHT0, RT_AMBIENT, black);
    rtLightfv(RT_LIGHT0, RT_DIFFUSE, white);
    rtLightfv(RT_LIGHT0, RT_SPECULAR, black);
    rtEnable(RT_LIGHT0);
    rtLightModelfv(RT_LIGHT_MODEL_AMBIENT, ambient);
    rtClearColor(clear_color[0], clear_color[1], clear_color[2], clear_color[3]);
    rtShadingMode(RT_WHITTED);
    tu_render_float(WIDTH, HEIGHT, rgba);
    CHECK_NO_ERR();
    tu_destroy_context(ctx);
}

static double pixel_difference(const float *px, const double rgb[3])
{
    double worst = 0.0;
    for (int k = 0; k < 3; k++) {
        double d = fabs((double)px[k] - rgb[k]);
        if (!(d <= worst))
            worst = d; /* NaN propagates as a failure */
    }
    return worst;
}

static const char *class_name(int c)
{
    static const char *const names[] = {"background",   "lit floor", "floor in shadow",
                                        "box -x",       "box +x",    "box -y (bottom)",
                                        "box +y (top)", "box -z",    "box +z"};
    return c < 0 ? "boundary" : names[c];
}

/* The colour a surface class shows when lit and when in shadow (ambient
 * only); for classes that are never lit both are the ambient colour. */
static void lit_and_shadow(int c, double lit[3], double shadow[3])
{
    expected_color(c, lit);
    expected_color(c == FLOOR_LIT || c == FLOOR_SHADOW ? FLOOR_SHADOW : c, shadow);
    if (c == FLOOR_LIT || c == FLOOR_SHADOW)
        expected_color(FLOOR_LIT, lit);
    if (c >= BOX_FACE0) {
        /* The ambient part alone. */
        for (int k = 0; k < 3; k++)
            shadow[k] = global_ambient * box_ambient[k];
    }
}

static double distance3(const float *px, const double rgb[3])
{
    double d = 0.0;
    for (int k = 0; k < 3; k++)
        d += ((double)px[k] - rgb[k]) * ((double)px[k] - rgb[k]);
    return sqrt(d);
}

/*
 * Judges one variant.  Each interior pixel falls into one of:
 *   hole: background (alpha 0) where a surface is, or a surface where
 *     the background is;
 *   acne: a surface that should be lit shows (closer to) its shadow colour;
 *   misplaced shadow: floor that should be in shadow shows (closer to) its
 *     lit colour;
 *   shading error: the right one of lit/shadow, but off by more than the
 *     variant's tolerance;
 * and against the unit scene an interior pixel must not differ by more
 * than that tolerance either.
 */
static void check_variant(const struct variant *vr, const int *classes, const float *rgba,
                          const float *unit_rgba)
{
    long acne = 0, holes = 0, wrong_shadow = 0, shading = 0;
    long interior_changed = 0, boundary_changed = 0;
    int printed = 0;
    for (int p = 0; p < WIDTH * HEIGHT; p++) {
        int c = classes[p];
        const float *px = &rgba[4 * p];
        if (unit_rgba) {
            double u[3] = {unit_rgba[4 * p], unit_rgba[4 * p + 1], unit_rgba[4 * p + 2]};
            if (!(pixel_difference(px, u) <= vr->tolerance)) {
                if (c < 0)
                    boundary_changed++;
                else
                    interior_changed++;
            }
        }
        if (c < 0)
            continue;
        double rgb[3], lit[3], shadow[3];
        expected_color(c, rgb);
        double diff = pixel_difference(px, rgb);
        if (diff <= vr->tolerance)
            continue;
        const char *what;
        if ((px[3] == 0.0f) != (c == BACKGROUND) || c == BACKGROUND) {
            holes++;
            what = "hole";
        } else {
            lit_and_shadow(c, lit, shadow);
            int looks_lit = distance3(px, lit) < distance3(px, shadow);
            if (c == FLOOR_SHADOW && looks_lit) {
                wrong_shadow++;
                what = "misplaced shadow";
            } else if (c != FLOOR_SHADOW && !looks_lit && lit[0] != shadow[0]) {
                acne++;
                what = "acne";
            } else {
                shading++;
                what = "shading error";
            }
        }
        if (printed++ < MAX_PRINTED)
            fprintf(stderr,
                    "  %s: %s at pixel (%d, %d): %s expected (%.4f %.4f %.4f), got (%.4f %.4f "
                    "%.4f)\n",
                    vr->label, what, p % WIDTH, p / WIDTH, class_name(c), rgb[0], rgb[1], rgb[2],
                    px[0], px[1], px[2]);
    }
    printf("   %s: %ld acne, %ld holes, %ld misplaced shadow, %ld shading errors (tolerance "
           "%g); against the unit scene %ld interior and %ld boundary pixels differ\n",
           vr->label, acne, holes, wrong_shadow, shading, vr->tolerance, interior_changed,
           boundary_changed);
    CHECK_INT(acne, 0);
    CHECK_INT(holes, 0);
    CHECK_INT(wrong_shadow, 0);
    CHECK_INT(shading, 0);
    CHECK_INT(interior_changed, 0);
    CHECK(boundary_changed <= MAX_BOUNDARY_FRACTION * WIDTH * HEIGHT);
}

int main(void)
{
    static const struct variant variants[] = {
        {"unit scene, instanced", 0.0, 1.0, 0, 0, VALUE_TOLERANCE},
        {"unit scene, flattened", 0.0, 1.0, 1, 0, VALUE_TOLERANCE},
        {"translated by 1e5, instanced", 1e5, 1.0, 0, 0, VALUE_TOLERANCE},
        {"translated by 1e5, flattened", 1e5, 1.0, 1, 0, VALUE_TOLERANCE},
        {"scaled by 1e-4, instanced", 0.0, 1e-4, 0, 0, VALUE_TOLERANCE},
        {"scaled by 1e-4, flattened", 0.0, 1e-4, 1, 0, VALUE_TOLERANCE},
        {"scaled by 1e4, instanced", 0.0, 1e4, 0, 0, VALUE_TOLERANCE},
        {"scaled by 1e4, flattened", 0.0, 1e4, 1, 0, VALUE_TOLERANCE},
        {"rotated, instanced", 0.0, 1.0, 0, 1, VALUE_TOLERANCE},
        {"rotated, flattened", 0.0, 1.0, 1, 1, VALUE_TOLERANCE},
        {"rotated and translated by 1e5, instanced", 1e5, 1.0, 0, 1, VALUE_TOLERANCE},
        {"rotated and translated by 1e5, flattened", 1e5, 1.0, 1, 1, QUANTIZED_VALUE_TOLERANCE},
    };
    int *classes = malloc(sizeof(int) * WIDTH * HEIGHT);
    classify(classes);
    int counts[BOX_FACE0 + 6 + 1];
    memset(counts, 0, sizeof(counts));
    for (int p = 0; p < WIDTH * HEIGHT; p++)
        counts[classes[p] + 1]++;
    tu_section("classification");
    printf("   boundary %d, background %d, lit floor %d, shadow %d, box faces %d %d %d %d %d %d\n",
           counts[0], counts[1], counts[2], counts[3], counts[4], counts[5], counts[6], counts[7],
           counts[8], counts[9]);
    /* The picture must contain every class the checks rely on. */
    CHECK(counts[1 + BACKGROUND] > 100 && counts[1 + FLOOR_LIT] > 1000 &&
          counts[1 + FLOOR_SHADOW] > 200);
    CHECK(counts[1 + BOX_FACE0 + 3] > 100); /* top, lit */

    float *unit = malloc(sizeof(float) * 4 * WIDTH * HEIGHT);
    float *rgba = malloc(sizeof(float) * 4 * WIDTH * HEIGHT);
    for (size_t i = 0; i < sizeof(variants) / sizeof(variants[0]); i++) {
        tu_section(variants[i].label);
        render_variant(&variants[i], i == 0 ? unit : rgba);
        check_variant(&variants[i], classes, i == 0 ? unit : rgba, i == 0 ? NULL : unit);
    }
    free(unit);
    free(rgba);
    free(classes);
    return test_summary("stability_scale");
}
