/* SPDX-License-Identifier: Apache-2.0 */
/*
 * reference_image.c - a fixed scene rendered with Whitted shading against a
 * checked-in reference image, conformance/data/reference_whitted.ppm.
 *
 * The scene: a checkerboard floor (flat shading, per-vertex colours through
 * RT_COLOR_MATERIAL), a smooth red sphere with a specular highlight, a blue
 * box turned about y, a green pyramid, and a mirror standing behind them
 * (reflectivity 0.8); a directional light and an attenuated point light,
 * both casting shadows; 160x120 pixels through a perspective frustum, the
 * camera raised and tilted down.
 *
 * Pass: on at least 99.9% of the pixels every channel of the 8-bit image
 * (rtReadPixels with RT_UNSIGNED_BYTE) is within 2/255 of the reference.
 * The allowance is for other compilers and platforms: a different libm
 * (sinf/powf), or floating-point contraction, moves smooth shading by an
 * ulp or two and can flip a rare pixel on a silhouette or a shadow
 * boundary; a real change (a shadow, a reflection, a shape, a colour)
 * changes far more pixels than that.
 *
 * On failure the rendered image is written to reference_whitted_actual.ppm
 * in the current directory (ctest runs the test in its build directory)
 * and the path is printed.
 *
 * Regenerating the reference (after a deliberate change to shading; look at
 * the new image before committing it):
 *     RT_UPDATE_REFERENCE=1 ./conf_api_reference_image
 * writes RT_TEST_DATA_DIR/reference_whitted.ppm (the source tree's
 * conformance/data, compiled in by CMake) and exits 0.
 *
 * The PPM reader and writer are local (binary P6, maxval 255, rows top to
 * bottom as the format defines; rtReadPixels gives rows bottom to top) so
 * the test does not depend on the utility library.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "testutil.h"

#define WIDTH 160
#define HEIGHT 120
#define CHANNEL_TOLERANCE 2
#define MAX_OUTLIER_FRACTION 0.001
#define REFERENCE_NAME "reference_whitted.ppm"
#define ACTUAL_NAME "reference_whitted_actual.ppm"

enum { FLOOR = 1, SPHERE, BOX, PYRAMID, MIRROR };

/* ---- PPM (P6) ----------------------------------------------------------- */

/* Writes rgb (3 bytes per pixel, rows top to bottom); returns 1 on success. */
static int write_ppm(const char *path, int w, int h, const unsigned char *rgb)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    int ok = fprintf(f, "P6\n%d %d\n255\n", w, h) > 0 &&
             fwrite(rgb, 3, (size_t)w * h, f) == (size_t)w * h;
    return fclose(f) == 0 && ok;
}

/* Skips whitespace and '#' comments of a PPM header. */
static void skip_space(FILE *f)
{
    int c;
    while ((c = fgetc(f)) != EOF) {
        if (c == '#') {
            while ((c = fgetc(f)) != EOF && c != '\n')
                ;
        } else if (c != ' ' && c != '\t' && c != '\n' && c != '\r') {
            ungetc(c, f);
            return;
        }
    }
}

/* Reads a P6 file with maxval 255; returns malloc'ed rgb or NULL. */
static unsigned char *read_ppm(const char *path, int *w, int *h)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    int maxval = 0;
    unsigned char *rgb = NULL;
    char magic[3] = {0, 0, 0};
    if (fread(magic, 1, 2, f) != 2 || strcmp(magic, "P6") != 0)
        goto done;
    skip_space(f);
    if (fscanf(f, "%d", w) != 1)
        goto done;
    skip_space(f);
    if (fscanf(f, "%d", h) != 1)
        goto done;
    skip_space(f);
    if (fscanf(f, "%d", &maxval) != 1 || maxval != 255 || fgetc(f) == EOF)
        goto done;
    if (*w <= 0 || *h <= 0 || *w > 16384 || *h > 16384)
        goto done;
    rgb = malloc((size_t)*w * *h * 3);
    if (rgb && fread(rgb, 3, (size_t)*w * *h, f) != (size_t)*w * *h) {
        free(rgb);
        rgb = NULL;
    }
done:
    fclose(f);
    return rgb;
}

/* ---- the scene ------------------------------------------------------------ */

static void define_objects(void)
{
    /* Checkerboard floor [-6,6] x [-6,6] at y = 0: flat shading takes each
     * quad's colour from its provoking (last) vertex. */
    rtNewObject(FLOOR);
    rtEnable(RT_COLOR_MATERIAL);
    rtShadeModel(RT_FLAT);
    rtNormal3f(0.0f, 1.0f, 0.0f);
    rtBegin(RT_QUADS);
    for (int j = 0; j < 12; j++)
        for (int i = 0; i < 12; i++) {
            float x0 = -6.0f + (float)i, z0 = -6.0f + (float)j;
            if ((i + j) % 2)
                rtColor3f(0.9f, 0.9f, 0.85f);
            else
                rtColor3f(0.25f, 0.25f, 0.3f);
            rtVertex3f(x0, 0.0f, z0);
            rtVertex3f(x0, 0.0f, z0 + 1.0f);
            rtVertex3f(x0 + 1.0f, 0.0f, z0 + 1.0f);
            rtVertex3f(x0 + 1.0f, 0.0f, z0);
        }
    rtEnd();
    rtShadeModel(RT_SMOOTH);
    rtDisable(RT_COLOR_MATERIAL);
    rtColor3f(1.0f, 1.0f, 1.0f);
    rtEndObject();

    /* Unit sphere, smooth normals, red with a white highlight. */
    const float red[4] = {0.8f, 0.1f, 0.08f, 1.0f};
    const float white[4] = {0.8f, 0.8f, 0.8f, 1.0f};
    rtNewObject(SPHERE);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, red);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, white);
    rtMaterialf(RT_FRONT_AND_BACK, RT_SHININESS, 50.0f);
    const int slices = 32, stacks = 16;
    for (int j = 0; j < stacks; j++) {
        rtBegin(RT_QUAD_STRIP);
        for (int i = 0; i <= slices; i++)
            for (int k = 0; k < 2; k++) {
                double theta = 3.14159265358979 * (j + k) / stacks;
                double phi = 6.28318530717959 * i / slices;
                float p[3] = {(float)(sin(theta) * cos(phi)), (float)cos(theta),
                              (float)(-sin(theta) * sin(phi))};
                rtNormal3fv(p);
                rtVertex3fv(p);
            }
        rtEnd();
    }
    rtEndObject();

    /* Unit cube [0,1]^3 with face normals. */
    const float blue[4] = {0.15f, 0.3f, 0.85f, 1.0f};
    rtNewObject(BOX);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, blue);
    rtBegin(RT_QUADS);
    for (int axis = 0; axis < 3; axis++)
        for (int side = 0; side < 2; side++) {
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            float n[3] = {0, 0, 0};
            n[axis] = side ? 1.0f : -1.0f;
            rtNormal3fv(n);
            static const int su[4] = {0, 1, 1, 0}, sv[4] = {0, 0, 1, 1};
            for (int c = 0; c < 4; c++) {
                float p[3];
                p[axis] = (float)side;
                p[u] = (float)(side ? su[c] : sv[c]);
                p[v] = (float)(side ? sv[c] : su[c]);
                rtVertex3fv(p);
            }
        }
    rtEnd();
    rtEndObject();

    /* Square pyramid, geometric normals (no rtNormal in the definition). */
    const float green[4] = {0.2f, 0.7f, 0.25f, 1.0f};
    rtNewObject(PYRAMID);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, green);
    rtBegin(RT_TRIANGLE_FAN);
    rtVertex3f(0.0f, 1.5f, 0.0f);
    rtVertex3f(-0.7f, 0.0f, 0.7f);
    rtVertex3f(0.7f, 0.0f, 0.7f);
    rtVertex3f(0.7f, 0.0f, -0.7f);
    rtVertex3f(-0.7f, 0.0f, -0.7f);
    rtVertex3f(-0.7f, 0.0f, 0.7f);
    rtEnd();
    rtEndObject();

    /* The mirror: a slightly tinted, highly reflective upright quad. */
    const float tint[4] = {0.1f, 0.1f, 0.12f, 1.0f};
    rtNewObject(MIRROR);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, tint);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 0.8f);
    rtBegin(RT_QUADS);
    rtVertex3f(-4.0f, 0.0f, 0.0f);
    rtVertex3f(4.0f, 0.0f, 0.0f);
    rtVertex3f(4.0f, 3.5f, 0.0f);
    rtVertex3f(-4.0f, 3.5f, 0.0f);
    rtEnd();
    rtEndObject();
}

static void render_scene(unsigned char *rgba)
{
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 60.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    /* The camera: 3.5 up, 10 back, looking 18 degrees down. */
    rtRotatef(18.0f, 1.0f, 0.0f, 0.0f);
    rtTranslatef(0.0f, -3.5f, -10.0f);

    const float sun[4] = {-0.5f, 1.0f, 0.7f, 0.0f};
    const float sun_color[4] = {0.75f, 0.72f, 0.65f, 1.0f};
    const float lamp[4] = {3.5f, 4.0f, 3.0f, 1.0f};
    const float lamp_color[4] = {0.6f, 0.6f, 0.7f, 1.0f};
    rtLightfv(RT_LIGHT0, RT_POSITION, sun);
    rtLightfv(RT_LIGHT0, RT_DIFFUSE, sun_color);
    rtLightfv(RT_LIGHT0, RT_SPECULAR, sun_color);
    rtLightfv(RT_LIGHT0 + 1, RT_POSITION, lamp);
    rtLightfv(RT_LIGHT0 + 1, RT_DIFFUSE, lamp_color);
    rtLightfv(RT_LIGHT0 + 1, RT_SPECULAR, lamp_color);
    rtLightf(RT_LIGHT0 + 1, RT_QUADRATIC_ATTENUATION, 0.01f);
    rtEnable(RT_LIGHT0);
    rtEnable(RT_LIGHT0 + 1);

    rtBeginFrame();
    rtInstantiateObject(FLOOR);
    rtPushMatrix();
    rtTranslatef(-1.2f, 1.0f, 0.5f);
    rtInstantiateObject(SPHERE);
    rtPopMatrix();
    rtPushMatrix();
    rtTranslatef(1.0f, 0.0f, 1.2f);
    rtRotatef(30.0f, 0.0f, 1.0f, 0.0f);
    rtScalef(1.2f, 1.6f, 1.2f);
    rtInstantiateObject(BOX);
    rtPopMatrix();
    rtPushMatrix();
    rtTranslatef(0.6f, 0.0f, 3.2f);
    rtInstantiateObject(PYRAMID);
    rtPopMatrix();
    rtPushMatrix();
    rtTranslatef(0.0f, 0.0f, -2.5f);
    rtRotatef(-10.0f, 0.0f, 1.0f, 0.0f);
    rtInstantiateObject(MIRROR);
    rtPopMatrix();

    rtShadingMode(RT_WHITTED);
    rtClearColor(0.45f, 0.6f, 0.8f, 1.0f);
    rtViewport(0, 0, WIDTH, HEIGHT);
    rtRenderFrame();
    rtReadPixels(0, 0, WIDTH, HEIGHT, RT_RGBA, RT_UNSIGNED_BYTE, rgba);
}

/* RGBA rows bottom to top -> RGB rows top to bottom. */
static void to_rgb(const unsigned char *rgba, unsigned char *rgb)
{
    for (int y = 0; y < HEIGHT; y++)
        for (int x = 0; x < WIDTH; x++)
            memcpy(&rgb[3 * ((size_t)(HEIGHT - 1 - y) * WIDTH + x)],
                   &rgba[4 * ((size_t)y * WIDTH + x)], 3);
}

static void save_actual(const unsigned char *rgb)
{
    char cwd[PATH_MAX];
    if (write_ppm(ACTUAL_NAME, WIDTH, HEIGHT, rgb))
        fprintf(stderr, "  rendered image written to %s/%s\n", getcwd(cwd, sizeof(cwd)) ? cwd : ".",
                ACTUAL_NAME);
    else
        fprintf(stderr, "  could not write %s in the current directory\n", ACTUAL_NAME);
}

int main(void)
{
    RTcontext ctx = tu_make_context(NULL);
    define_objects();
    CHECK_NO_ERR();
    unsigned char *rgba = malloc((size_t)WIDTH * HEIGHT * 4);
    unsigned char *rgb = malloc((size_t)WIDTH * HEIGHT * 3);
    render_scene(rgba);
    CHECK_NO_ERR();
    to_rgb(rgba, rgb);

    const char *reference_path = RT_TEST_DATA_DIR "/" REFERENCE_NAME;
    const char *update = getenv("RT_UPDATE_REFERENCE");
    if (update && strcmp(update, "1") == 0) {
        tu_section("updating the reference");
        if (CHECK(write_ppm(reference_path, WIDTH, HEIGHT, rgb)))
            printf("   wrote %s: look at it before committing\n", reference_path);
    } else {
        tu_section("comparing with the reference");
        int w = 0, h = 0;
        unsigned char *ref = read_ppm(reference_path, &w, &h);
        if (!CHECK(ref != NULL)) {
            fprintf(stderr, "  cannot read %s (RT_UPDATE_REFERENCE=1 regenerates it)\n",
                    reference_path);
            save_actual(rgb);
        } else if (!CHECK(w == WIDTH && h == HEIGHT)) {
            fprintf(stderr, "  %s is %dx%d, expected %dx%d\n", reference_path, w, h, WIDTH, HEIGHT);
            save_actual(rgb);
        } else {
            int outliers = 0, worst = 0;
            for (int p = 0; p < WIDTH * HEIGHT; p++) {
                int diff = 0;
                for (int c = 0; c < 3; c++) {
                    int d = abs((int)rgb[3 * p + c] - (int)ref[3 * p + c]);
                    if (d > diff)
                        diff = d;
                }
                if (diff > worst)
                    worst = diff;
                if (diff > CHANNEL_TOLERANCE) {
                    if (outliers < 10)
                        fprintf(stderr, "  pixel (%d, %d) from the top left differs by %d/255\n",
                                p % WIDTH, p / WIDTH, diff);
                    outliers++;
                }
            }
            printf("   %d of %d pixels differ by more than %d/255 (largest difference %d)\n",
                   outliers, WIDTH * HEIGHT, CHANNEL_TOLERANCE, worst);
            if (!CHECK(outliers <= MAX_OUTLIER_FRACTION * WIDTH * HEIGHT))
                save_actual(rgb);
        }
        free(ref);
    }
    /* Alpha: the clear alpha is 1 here, and every pixel hit something or
     * shows the clear colour, so alpha is 255 everywhere. */
    int alpha_ok = 1;
    for (int p = 0; p < WIDTH * HEIGHT; p++)
        alpha_ok &= rgba[4 * p + 3] == 255;
    CHECK(alpha_ok);
    free(rgba);
    free(rgb);
    tu_destroy_context(ctx);
    return test_summary("reference_image");
}
