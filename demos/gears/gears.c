/* SPDX-License-Identifier: Apache-2.0 */
/*
 * gears.c - the classic OpenGL "gears" demo, ray traced with Tracelist.
 *
 * A port of Brian Paul's gears.c (the GLUT demo, public domain; glxgears is
 * its X11 twin), kept as close to the original as the API allows so that
 * it reads as a worked example of porting a display-list program (see
 * docs/porting.md).  gear(), init(), draw() and reshape() have the
 * original's structure line for line; the GL calls map as follows:
 *
 *   glGenLists / glNewList / glEndList   rtGenObjects / rtNewObject / rtEndObject
 *   glCallList                           rtInstantiateObject
 *   glBegin / glEnd / glVertex3f         rtBegin / rtEnd / rtVertex3f
 *   glNormal3f / glShadeModel            rtNormal3f / rtShadeModel
 *   glMaterialfv / glLightfv             rtMaterialfv / rtLightfv
 *   glPushMatrix / glRotatef / ...       rtPushMatrix / rtRotatef / ...
 *   glFrustum / glViewport               rtFrustum / rtViewport
 *   glClear + glutSwapBuffers            rtRenderFrame (+ rtReadPixels to get the image)
 *   glEnable(GL_LIGHTING, GL_NORMALIZE)  rtEnable(RT_LIGHTING, RT_NORMALIZE)
 *   glEnable(GL_CULL_FACE)               rtEnable(RT_CULL_FACE) (--gl only)
 *   glEnable(GL_DEPTH_TEST)              accepted, not needed
 *
 * What the ray tracer adds: with the default Whitted shading the light at
 * (5, 5, 10, 0) casts shadows (the gears shadow each other and their own
 * teeth); --eye-light switches to the headlight shading without shadows,
 * --gl to RT_FIXED_FUNCTION, OpenGL's own look (GL's lighting per vertex,
 * the gears culled as the original culls them).
 *
 * Usage: gears [OPTION]...   (gears --help lists the options and keys)
 *
 * Headless (with --headless, without a display, or when built without
 * GLFW) it renders N frames (default 1), advancing the gear angle by 2
 * degrees a frame as the original's idle() does, and writes them to
 * gears.png (gears_0000.png, gears_0001.png, ... by 0-based frame index
 * when N > 1), or to --out FILE (numbered the same way); an extension the
 * build cannot write is refused, and the default becomes gears.ppm in a
 * build without PNG.  With a display it opens a window and animates at 70
 * degrees a second as glxgears does: arrow keys rotate the view, z/Z
 * rotate about the view axis, q or Esc quits; --frames N quits after N
 * frames and --out FILE saves the last one.
 */
#include <rt/rt.h>
#include <rt/rtu.h>

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo_util.h"

#ifdef RT_HAVE_GLFW
#include "demo_window.h"
#endif

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ------------------------------------------------------------------------ */
/* The original program                                                      */
/* ------------------------------------------------------------------------ */

/*
 * Draw a gear wheel.  You'll probably want to call this function when
 * building a display list since we do a lot of trig here.
 *
 * Input:  inner_radius - radius of hole at center
 *         outer_radius - radius at center of teeth
 *         width - width of gear
 *         teeth - number of teeth
 *         tooth_depth - depth of tooth
 *
 * Tracelist: called between rtNewObject and rtEndObject, exactly as the
 * original calls it between glNewList and glEndList.  Flat shading uses
 * GL's provoking vertex (the last of each quad), which is what makes the
 * normals set in the middle of the outward-face strip land on the right
 * faces.
 */
static void gear(RTfloat inner_radius, RTfloat outer_radius, RTfloat width, RTint teeth,
                 RTfloat tooth_depth)
{
    RTint i;
    RTfloat r0, r1, r2;
    RTfloat angle, da;
    RTfloat u, v, len;

    r0 = inner_radius;
    r1 = outer_radius - tooth_depth / 2.0;
    r2 = outer_radius + tooth_depth / 2.0;

    da = 2.0 * M_PI / teeth / 4.0;

    rtShadeModel(RT_FLAT);

    rtNormal3f(0.0, 0.0, 1.0);

    /* draw front face */
    rtBegin(RT_QUAD_STRIP);
    for (i = 0; i <= teeth; i++) {
        angle = i * 2.0 * M_PI / teeth;
        rtVertex3f(r0 * cos(angle), r0 * sin(angle), width * 0.5);
        rtVertex3f(r1 * cos(angle), r1 * sin(angle), width * 0.5);
        if (i < teeth) {
            rtVertex3f(r0 * cos(angle), r0 * sin(angle), width * 0.5);
            rtVertex3f(r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), width * 0.5);
        }
    }
    rtEnd();

    /* draw front sides of teeth */
    rtBegin(RT_QUADS);
    da = 2.0 * M_PI / teeth / 4.0;
    for (i = 0; i < teeth; i++) {
        angle = i * 2.0 * M_PI / teeth;

        rtVertex3f(r1 * cos(angle), r1 * sin(angle), width * 0.5);
        rtVertex3f(r2 * cos(angle + da), r2 * sin(angle + da), width * 0.5);
        rtVertex3f(r2 * cos(angle + 2 * da), r2 * sin(angle + 2 * da), width * 0.5);
        rtVertex3f(r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), width * 0.5);
    }
    rtEnd();

    rtNormal3f(0.0, 0.0, -1.0);

    /* draw back face */
    rtBegin(RT_QUAD_STRIP);
    for (i = 0; i <= teeth; i++) {
        angle = i * 2.0 * M_PI / teeth;
        rtVertex3f(r1 * cos(angle), r1 * sin(angle), -width * 0.5);
        rtVertex3f(r0 * cos(angle), r0 * sin(angle), -width * 0.5);
        if (i < teeth) {
            rtVertex3f(r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), -width * 0.5);
            rtVertex3f(r0 * cos(angle), r0 * sin(angle), -width * 0.5);
        }
    }
    rtEnd();

    /* draw back sides of teeth */
    rtBegin(RT_QUADS);
    da = 2.0 * M_PI / teeth / 4.0;
    for (i = 0; i < teeth; i++) {
        angle = i * 2.0 * M_PI / teeth;

        rtVertex3f(r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), -width * 0.5);
        rtVertex3f(r2 * cos(angle + 2 * da), r2 * sin(angle + 2 * da), -width * 0.5);
        rtVertex3f(r2 * cos(angle + da), r2 * sin(angle + da), -width * 0.5);
        rtVertex3f(r1 * cos(angle), r1 * sin(angle), -width * 0.5);
    }
    rtEnd();

    /* draw outward faces of teeth */
    rtBegin(RT_QUAD_STRIP);
    for (i = 0; i < teeth; i++) {
        angle = i * 2.0 * M_PI / teeth;

        rtVertex3f(r1 * cos(angle), r1 * sin(angle), width * 0.5);
        rtVertex3f(r1 * cos(angle), r1 * sin(angle), -width * 0.5);
        u = r2 * cos(angle + da) - r1 * cos(angle);
        v = r2 * sin(angle + da) - r1 * sin(angle);
        len = sqrt(u * u + v * v);
        u /= len;
        v /= len;
        rtNormal3f(v, -u, 0.0);
        rtVertex3f(r2 * cos(angle + da), r2 * sin(angle + da), width * 0.5);
        rtVertex3f(r2 * cos(angle + da), r2 * sin(angle + da), -width * 0.5);
        rtNormal3f(cos(angle), sin(angle), 0.0);
        rtVertex3f(r2 * cos(angle + 2 * da), r2 * sin(angle + 2 * da), width * 0.5);
        rtVertex3f(r2 * cos(angle + 2 * da), r2 * sin(angle + 2 * da), -width * 0.5);
        u = r1 * cos(angle + 3 * da) - r2 * cos(angle + 2 * da);
        v = r1 * sin(angle + 3 * da) - r2 * sin(angle + 2 * da);
        rtNormal3f(v, -u, 0.0);
        rtVertex3f(r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), width * 0.5);
        rtVertex3f(r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), -width * 0.5);
        rtNormal3f(cos(angle), sin(angle), 0.0);
    }

    rtVertex3f(r1 * cos(0), r1 * sin(0), width * 0.5);
    rtVertex3f(r1 * cos(0), r1 * sin(0), -width * 0.5);

    rtEnd();

    rtShadeModel(RT_SMOOTH);

    /* draw inside radius cylinder */
    rtBegin(RT_QUAD_STRIP);
    for (i = 0; i <= teeth; i++) {
        angle = i * 2.0 * M_PI / teeth;
        rtNormal3f(-cos(angle), -sin(angle), 0.0);
        rtVertex3f(r0 * cos(angle), r0 * sin(angle), -width * 0.5);
        rtVertex3f(r0 * cos(angle), r0 * sin(angle), width * 0.5);
    }
    rtEnd();
}

static RTfloat view_rotx = 20.0, view_roty = 30.0, view_rotz = 0.0;
static RTuint gear1, gear2, gear3;
static RTfloat angle = 0.0;

/*
 * Describes one frame and renders it.  As in OpenGL the application issues
 * its scene every frame (immediate mode): the three rtInstantiateObject
 * calls replace the previous frame's instances.  Only the instance matrices
 * change from frame to frame, so the gears' BVHs are built once and each
 * frame costs a top-level update plus the rendering.
 */
static void draw(void)
{
    /* glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT): rtRenderFrame
     * fills the background with the clear colour itself. */

    rtPushMatrix();
    rtRotatef(view_rotx, 1.0, 0.0, 0.0);
    rtRotatef(view_roty, 0.0, 1.0, 0.0);
    rtRotatef(view_rotz, 0.0, 0.0, 1.0);

    rtPushMatrix();
    rtTranslatef(-3.0, -2.0, 0.0);
    rtRotatef(angle, 0.0, 0.0, 1.0);
    rtInstantiateObject(gear1); /* glCallList(gear1) */
    rtPopMatrix();

    rtPushMatrix();
    rtTranslatef(3.1, -2.0, 0.0);
    rtRotatef(-2.0 * angle - 9.0, 0.0, 0.0, 1.0);
    rtInstantiateObject(gear2);
    rtPopMatrix();

    rtPushMatrix();
    rtTranslatef(-3.1, 4.2, 0.0);
    rtRotatef(-2.0 * angle - 25.0, 0.0, 0.0, 1.0);
    rtInstantiateObject(gear3);
    rtPopMatrix();

    rtPopMatrix();

    rtRenderFrame(); /* glutSwapBuffers(): the frame is done */
}

/* new window size or exposure */
static void reshape(int width, int height)
{
    RTfloat h = (RTfloat)height / (RTfloat)width;

    rtViewport(0, 0, (RTint)width, (RTint)height);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtFrustum(-1.0, 1.0, -h, h, 5.0, 60.0);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtTranslatef(0.0, 0.0, -40.0);
}

static void init(int eye_light, int gl)
{
    static RTfloat pos[4] = {5.0, 5.0, 10.0, 0.0};
    static RTfloat red[4] = {0.8, 0.1, 0.0, 1.0};
    static RTfloat green[4] = {0.0, 0.8, 0.2, 1.0};
    static RTfloat blue[4] = {0.2, 0.2, 1.0, 1.0};

    /* Set while the modelview is the identity, so the light is fixed in eye
     * space (world space is eye space, as in OpenGL). */
    rtLightfv(RT_LIGHT0, RT_POSITION, pos);
    /* As the original: lighting (recorded with the gears, read by every
     * mode: Whitted and the eye light honour it once it is enabled) and
     * culling, which camera rays obey in every mode, so only --gl asks for
     * it and the Whitted images stay as they were.  The depth test is
     * accepted and not needed: rays find the nearest surface. */
    if (gl)
        rtEnable(RT_CULL_FACE);
    rtEnable(RT_LIGHTING);
    rtEnable(RT_LIGHT0);
    rtEnable(RT_DEPTH_TEST);

    /* Tracelist only: how to light.  Whitted shading traces a shadow ray to
     * the light; the eye light is a headlight without shadows; GL's look is
     * RT_FIXED_FUNCTION.  Opaque black background so that saved images are
     * not transparent. */
    rtShadingMode(gl ? RT_FIXED_FUNCTION : eye_light ? RT_EYE_LIGHT : RT_WHITTED);
    rtClearColor(0.0, 0.0, 0.0, 1.0);

    /* make the gears */
    rtGenObjects(1, &gear1);        /* gear1 = glGenLists(1) */
    rtNewObject(gear1);             /* glNewList(gear1, GL_COMPILE) */
    rtMaterialfv(RT_FRONT, RT_AMBIENT_AND_DIFFUSE, red);
    gear(1.0, 4.0, 1.0, 20, 0.7);
    rtEndObject();                  /* glEndList() */

    rtGenObjects(1, &gear2);
    rtNewObject(gear2);
    rtMaterialfv(RT_FRONT, RT_AMBIENT_AND_DIFFUSE, green);
    gear(0.5, 2.0, 2.0, 10, 0.7);
    rtEndObject();

    rtGenObjects(1, &gear3);
    rtNewObject(gear3);
    rtMaterialfv(RT_FRONT, RT_AMBIENT_AND_DIFFUSE, blue);
    gear(1.3, 2.0, 0.5, 10, 0.7);
    rtEndObject();

    /* The original enables GL_NORMALIZE here, after the lists; GL reads it
     * when the lists are called.  Tracelist records it with the triangles,
     * so the gears above were recorded without it: their normals are unit
     * already, and RT_FIXED_FUNCTION lights them as GL does. */
    rtEnable(RT_NORMALIZE);
}

/* ------------------------------------------------------------------------ */
/* The program around it: options, headless frames, a GLFW window            */
/* ------------------------------------------------------------------------ */

struct options {
    int headless;      /* --headless */
    int frames;        /* --frames N; 0 = not given */
    int width, height; /* --size WxH */
    int threads;       /* --threads N; 0 = the library's default */
    const char *out;   /* --out FILE; NULL = default name */
    int eye_light;     /* --eye-light */
    int gl;            /* --gl */
};

static void usage(FILE *f)
{
    fprintf(f, "Usage: gears [OPTION]...\n"
               "Ray trace the classic OpenGL gears with Tracelist: in a window when there is a\n"
               "display, else (or with --headless) to image files.\n\n"
               "  -H, --headless       render without a window and write image files\n"
               "  -n, --frames=N       frames to render (headless default 1; window: until quit)\n"
               "  -s, --size=WxH       image or window size (default 640x480)\n"
               "  -t, --threads=N      render threads (default: all processors)\n"
               "  -o, --out=FILE       output image; FILE_0000.ext, FILE_0001.ext, ... by\n"
               "                       frame index when N > 1 (default gears.png, gears.ppm\n"
               "                       in a build without PNG); an unknown extension is refused\n"
               "  -e, --eye-light      OpenGL-like headlight shading instead of Whitted\n"
               "  -g, --gl             OpenGL's fixed-function look (RT_FIXED_FUNCTION)\n"
               "      --info           print the library version, renderer and configuration\n"
               "  -h, --help           display this help and exit\n"
               "  -V, --version        output version information and exit\n\n"
               "Keys in the window:\n" DEMO_COMMON_KEYS
               "  arrows         rotate the view\n"
               "  z, Z           rotate about the view axis\n");
}

enum { OPT_INFO = 256 };

/* Returns 1 to run, 0 to exit with *status (help, version, a bad option). */
static int parse_options(int argc, char **argv, struct options *o, int *info, int *status)
{
    static const struct option long_options[] = {
        {"headless", no_argument, NULL, 'H'},   {"frames", required_argument, NULL, 'n'},
        {"size", required_argument, NULL, 's'}, {"threads", required_argument, NULL, 't'},
        {"out", required_argument, NULL, 'o'},  {"eye-light", no_argument, NULL, 'e'},
        {"gl", no_argument, NULL, 'g'},
        {"info", no_argument, NULL, OPT_INFO},  {"help", no_argument, NULL, 'h'},
        {"version", no_argument, NULL, 'V'},    {NULL, 0, NULL, 0}};
    int c;
    memset(o, 0, sizeof *o);
    o->width = 640;
    o->height = 480;
    *info = 0;
    *status = 2;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":Hn:s:t:o:eghV", long_options, NULL)) != -1) {
        switch (c) {
        case 'H':
            o->headless = 1;
            break;
        case 'e':
            o->eye_light = 1;
            break;
        case 'g':
            o->gl = 1;
            break;
        case 'n':
            if (!demo_parse_int(optarg, 1, 1000000, &o->frames)) {
                demo_usage_error("gears", "invalid frame count '%s' (a whole number, 1 or more)",
                                 optarg);
                return 0;
            }
            break;
        case 's':
            if (!demo_parse_size(optarg, &o->width, &o->height)) {
                demo_usage_error("gears", "invalid size '%s' (WxH, e.g. 640x480, at most 16384)",
                                 optarg);
                return 0;
            }
            break;
        case 't':
            if (!demo_parse_int(optarg, 1, 256, &o->threads)) {
                demo_usage_error("gears", "invalid thread count '%s' (1 to 256)", optarg);
                return 0;
            }
            break;
        case 'o':
            if (optarg[0] == '\0') {
                demo_usage_error("gears", "--out needs a file name");
                return 0;
            }
            o->out = optarg;
            break;
        case OPT_INFO:
            *info = 1;
            break;
        case 'h':
            usage(stdout);
            *status = 0;
            return 0;
        case 'V':
            *status = demo_print_version("gears");
            return 0;
        case ':':
            demo_usage_error("gears", "option '%s' requires an argument", argv[optind - 1]);
            return 0;
        default:
            demo_usage_error("gears", "unrecognized option '%s'", argv[optind - 1]);
            return 0;
        }
    }
    if (optind < argc) {
        demo_usage_error("gears", "unexpected argument '%s'", argv[optind]);
        return 0;
    }
    return 1;
}

static int run_headless(const struct options *o)
{
    const int frames = o->frames > 0 ? o->frames : 1;
    char base_buffer[4096];
    const char *base =
        demo_output_name(base_buffer, sizeof base_buffer, o->out, "gears.png", "gears");
    unsigned char *pixels;
    double render_seconds = 0.0;
    double start = demo_now();
    char path[4096], first[4096];
    int k;
    if (base == NULL)
        return 2;
    pixels = malloc((size_t)o->width * (size_t)o->height * 4);
    if (pixels == NULL) {
        fprintf(stderr, "gears: out of memory\n");
        return 1;
    }
    path[0] = '\0';
    for (k = 1; k <= frames; k++) {
        double t0 = demo_now();
        double elapsed;
        draw();
        render_seconds += demo_now() - t0;
        if (demo_report_error("gears", "rendering"))
            break;
        demo_frame_name(path, sizeof path, base, k - 1, frames > 1);
        if (k == 1)
            snprintf(first, sizeof first, "%s", path);
        if (!demo_save_frame("gears", path, o->width, o->height, pixels))
            break;
        angle += 2.0; /* idle() of the original: one step per frame */

        elapsed = demo_now() - start;
        demo_progress("gears", k, frames, elapsed, 1e3 * render_seconds / k, NULL);
    }
    free(pixels);
    if (k <= frames)
        return 1;
    printf("gears: %d frame%s of %dx%d in %.3f s = %.2f fps (rendering only)\n", frames,
           frames == 1 ? "" : "s", o->width, o->height, render_seconds,
           frames / render_seconds);
    demo_report_written("gears", first, path);
    return 0;
}

#ifdef RT_HAVE_GLFW

/* special() and key() of the original, on GLFW's callbacks. */
static void key(GLFWwindow *window, int k, int scancode, int action, int mods)
{
    (void)scancode;
    (void)mods;
    if (action != GLFW_PRESS && action != GLFW_REPEAT)
        return;
    switch (k) {
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q:
        glfwSetWindowShouldClose(window, GLFW_TRUE);
        break;
    case GLFW_KEY_UP:
        view_rotx += 5.0;
        break;
    case GLFW_KEY_DOWN:
        view_rotx -= 5.0;
        break;
    case GLFW_KEY_LEFT:
        view_roty += 5.0;
        break;
    case GLFW_KEY_RIGHT:
        view_roty -= 5.0;
        break;
    default:
        break;
    }
}

static void character(GLFWwindow *window, unsigned int codepoint)
{
    (void)window;
    if (codepoint == 'z')
        view_rotz += 5.0;
    else if (codepoint == 'Z')
        view_rotz -= 5.0;
}

/*
 * Opens a window and animates until Esc (or o->frames frames).  Each frame
 * is ray traced by Tracelist and shown with glDrawPixels: rtReadPixels
 * returns rows bottom to top, which is the order glDrawPixels wants.
 * Returns -1 when no window could be opened (the caller goes headless),
 * else the exit status.
 */
static int run_window(const struct options *o)
{
    GLFWwindow *window;
    unsigned char *pixels = NULL;
    int width = 0, height = 0;
    int frames = 0, title_frames = 0;
    int status = 0;
    double last = demo_now();
    double title_time = last;
    if (!glfwInit())
        return -1;
    window = glfwCreateWindow(o->width, o->height, "Tracelist gears", NULL, NULL);
    if (window == NULL) {
        glfwTerminate();
        return -1;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(0);
    glfwSetKeyCallback(window, key);
    glfwSetCharCallback(window, character);

    while (!glfwWindowShouldClose(window) && (o->frames == 0 || frames < o->frames)) {
        int fb_width, fb_height;
        double t;
        glfwGetFramebufferSize(window, &fb_width, &fb_height);
        if (fb_width <= 0 || fb_height <= 0) { /* minimised */
            glfwWaitEvents();
            continue;
        }
        if (fb_width != width || fb_height != height) {
            unsigned char *grown = realloc(pixels, (size_t)fb_width * (size_t)fb_height * 4);
            if (grown == NULL) {
                fprintf(stderr, "gears: out of memory\n");
                status = 1;
                break;
            }
            pixels = grown;
            width = fb_width;
            height = fb_height;
            reshape(width, height);
        }

        draw();
        if (demo_report_error("gears", "rendering")) {
            status = 1;
            break;
        }
        demo_present(window, width, height, pixels);
        frames++;
        title_frames++;

        /* glxgears: advance rotation for next frame, 70 degrees per second */
        t = demo_now();
        angle += 70.0 * (t - last);
        if (angle > 3600.0)
            angle -= 3600.0;
        last = t;
        if (t - title_time >= 1.0) {
            char title[96];
            snprintf(title, sizeof title, "Tracelist gears - %.1f fps (%dx%d)",
                     title_frames / (t - title_time), width, height);
            glfwSetWindowTitle(window, title);
            printf("gears: %d frames in %.1f seconds = %.3f FPS\n", title_frames,
                   t - title_time, title_frames / (t - title_time));
            fflush(stdout);
            title_frames = 0;
            title_time = t;
        }
    }
    /* --out in a window: keep the last frame shown (the name was checked
     * before the window opened). */
    char name[4096];
    if (status == 0 && o->out != NULL && pixels != NULL &&
        demo_output_name(name, sizeof name, o->out, "gears.png", "gears") != NULL) {
        if (!rtuSaveImage(name, width, height, RT_UNSIGNED_BYTE, pixels)) {
            fprintf(stderr, "gears: %s\n", rtuImageError());
            status = 1;
        } else {
            demo_report_written("gears", name, name);
        }
    }
    free(pixels);
    glfwDestroyWindow(window);
    glfwTerminate();
    return status;
}

#endif /* RT_HAVE_GLFW */

int main(int argc, char **argv)
{
    struct options o;
    char config[32];
    char checked[4096];
    RTcontext context;
    int status = -1, info = 0;

    if (!parse_options(argc, argv, &o, &info, &status))
        return status;
    status = -1; /* not run yet */
    if (o.threads > 0)
        snprintf(config, sizeof config, "threads=%d", o.threads);
    else
        config[0] = '\0';
    if (info)
        return demo_print_info("gears", config);
    /* Refuse an unwritable --out before any work. */
    if (o.out != NULL && demo_output_name(checked, sizeof checked, o.out, NULL, "gears") == NULL)
        return 2;
    context = demo_create_context("gears", config);
    if (context == NULL)
        return 1;

    init(o.eye_light, o.gl);
    reshape(o.width, o.height);
    if (demo_report_error("gears", "setting up the scene")) {
        rtDestroyContext(context);
        return 1;
    }

#ifdef RT_HAVE_GLFW
    if (!o.headless && (getenv("DISPLAY") != NULL || getenv("WAYLAND_DISPLAY") != NULL)) {
        status = run_window(&o);
        if (status < 0)
            fprintf(stderr, "gears: cannot open a window; rendering headless\n");
    }
#endif
    if (status < 0)
        status = run_headless(&o);

    rtDestroyContext(context);
    return status;
}
