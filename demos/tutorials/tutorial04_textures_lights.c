/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Tutorial 4: textures and lights (docs/tutorials/04-textures-lights.md).
 *
 * A textured floor, a partly reflective box and two lights, rendered
 * with Whitted shading (shadows, reflections) to an image.  Everything a
 * fixed-function OpenGL program would set is set the same way: materials
 * with rtMaterialfv, lights with rtLightfv under the modelview matrix,
 * textures with rtGenTextures / rtTexImage2D / rtTexParameteri, the camera
 * with rtuPerspective and rtuLookAt from the utility library, which also
 * writes the image.
 *
 * Usage: tutorial04_textures_lights [OUT.ppm]   (default tutorial04.ppm)
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include <stdio.h>
#include <stdlib.h>

#define W 320
#define H 240

static void checker_texture(RTuint texture)
{
    static unsigned char texels[8 * 8 * 3];
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            unsigned char v = ((x + y) & 1) ? 230 : 40;
            unsigned char *t = texels + (y * 8 + x) * 3;
            t[0] = v;
            t[1] = v;
            t[2] = (unsigned char)(v / 2 + 60);
        }
    rtBindTexture(RT_TEXTURE_2D, texture);
    rtTexImage2D(RT_TEXTURE_2D, 0, RT_RGB, 8, 8, 0, RT_RGB, RT_UNSIGNED_BYTE, texels);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MAG_FILTER, RT_NEAREST);
    rtTexParameteri(RT_TEXTURE_2D, RT_TEXTURE_MIN_FILTER, RT_LINEAR_MIPMAP_LINEAR);
}

static void floor_object(RTuint name, RTuint texture)
{
    static const float white[4] = {1, 1, 1, 1};
    rtNewObject(name);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, white);
    rtBindTexture(RT_TEXTURE_2D, texture); /* recorded with the triangles, as in a display list */
    rtEnable(RT_TEXTURE_2D);
    rtNormal3f(0, 1, 0);
    rtBegin(RT_QUADS);
    rtTexCoord2f(0, 0);
    rtVertex3f(-6, 0, -6);
    rtTexCoord2f(0, 3);
    rtVertex3f(-6, 0, 6);
    rtTexCoord2f(3, 3);
    rtVertex3f(6, 0, 6);
    rtTexCoord2f(3, 0);
    rtVertex3f(6, 0, -6);
    rtEnd();
    rtDisable(RT_TEXTURE_2D);
    rtEndObject();
}

/* A unit box with per-face normals, red and partly reflective. */
static void box_object(RTuint name)
{
    static const float red[4] = {0.8f, 0.15f, 0.1f, 1};
    static const float white[4] = {1, 1, 1, 1};
    static const float n[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    rtNewObject(name);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_AMBIENT_AND_DIFFUSE, red);
    rtMaterialfv(RT_FRONT_AND_BACK, RT_SPECULAR, white);
    rtMaterialf(RT_FRONT_AND_BACK, RT_SHININESS, 40.0f);
    rtMaterialf(RT_FRONT_AND_BACK, RT_REFLECTIVITY, 0.3f);
    rtBegin(RT_QUADS);
    for (int f = 0; f < 6; f++) {
        /* Two axes spanning the face. */
        float u[3] = {n[f][1] != 0 ? 1.0f : 0.0f, n[f][1] != 0 ? 0.0f : 1.0f, 0.0f};
        float v[3] = {n[f][1] * u[2] - n[f][2] * u[1], n[f][2] * u[0] - n[f][0] * u[2],
                      n[f][0] * u[1] - n[f][1] * u[0]};
        static const float su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
        rtNormal3fv(n[f]);
        for (int k = 0; k < 4; k++)
            rtVertex3f(0.5f * (n[f][0] + su[k] * u[0] + sv[k] * v[0]),
                       0.5f * (n[f][1] + su[k] * u[1] + sv[k] * v[1]),
                       0.5f * (n[f][2] + su[k] * u[2] + sv[k] * v[2]));
    }
    rtEnd();
    rtEndObject();
}

int main(int argc, char **argv)
{
    const char *out = argc > 1 ? argv[1] : "tutorial04.ppm";
    RTcontext context = rtCreateContext("threads=2");
    if (context == NULL || !rtMakeCurrent(context)) {
        fprintf(stderr, "tutorial04: cannot create a context\n");
        return 1;
    }
    RTuint texture;
    rtGenTextures(1, &texture);
    checker_texture(texture);
    floor_object(1, texture);
    box_object(2);

    /* Camera: projection and viewing transform, as with GLU. */
    rtViewport(0, 0, W, H);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtuPerspective(50.0, (double)W / H, 0.1, 100.0);
    rtuLookAt(0, 3, 7, 0, 0.5, 0, 0, 1, 0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();

    /* Lights: a warm directional key light (w = 0) and a cool point light. */
    static const float key_position[4] = {-3, 5, 4, 0};
    static const float key_colour[4] = {1.0f, 0.9f, 0.8f, 1};
    static const float fill_position[4] = {3, 2, 2, 1};
    static const float fill_colour[4] = {0.2f, 0.3f, 0.5f, 1};
    rtLightfv(RT_LIGHT0, RT_POSITION, key_position);
    rtLightfv(RT_LIGHT0, RT_DIFFUSE, key_colour);
    rtLightfv(RT_LIGHT0 + 1, RT_POSITION, fill_position);
    rtLightfv(RT_LIGHT0 + 1, RT_DIFFUSE, fill_colour);
    rtEnable(RT_LIGHT0);
    rtEnable(RT_LIGHT0 + 1);
    rtShadingMode(RT_WHITTED); /* shadows and reflections */
    rtClearColor(0.05f, 0.05f, 0.1f, 1.0f);

    /* The scene: the floor, and the box standing on it, turned 30 degrees. */
    rtInstantiateObject(1);
    rtPushMatrix();
    rtTranslatef(0, 0.5f, 0);
    rtRotatef(30, 0, 1, 0);
    rtInstantiateObject(2);
    rtPopMatrix();
    rtRenderFrame();

    unsigned char *pixels = malloc((size_t)W * H * 4);
    if (pixels == NULL)
        return 1;
    rtReadPixels(0, 0, W, H, RT_RGBA, RT_UNSIGNED_BYTE, pixels);
    RTenum error = rtGetError();
    if (error != RT_NO_ERROR)
        fprintf(stderr, "tutorial04: Tracelist error: %s\n", rtuErrorString(error));
    int saved = rtuSaveImage(out, W, H, RT_UNSIGNED_BYTE, pixels);
    if (!saved)
        fprintf(stderr, "tutorial04: %s\n", rtuImageError());

    /* Checks: the box is red at the image centre; the floor shows both
     * checker colours (bright and dark) in the bottom rows. */
    const unsigned char *centre = pixels + ((H / 2) * W + W / 2) * 4;
    int bright = 0, dark = 0;
    for (int x = 0; x < W; x++) {
        const unsigned char *p = pixels + (10 * W + x) * 4;
        bright += p[0] > 120;
        dark += p[0] < 60;
    }
    int ok = error == RT_NO_ERROR && saved && centre[0] > centre[1] + 40 && bright > 10 &&
             dark > 10;
    printf("centre pixel %d %d %d; bottom row %d bright, %d dark; wrote %s\n", centre[0],
           centre[1], centre[2], bright, dark, out);
    free(pixels);
    rtDeleteTextures(1, &texture);
    rtDestroyContext(context);
    printf("tutorial04: %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
