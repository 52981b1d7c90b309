/* SPDX-License-Identifier: Apache-2.0 */
/*
 * bart - plays the BART benchmark scenes (kitchen, robots, museum) through
 * Tracelist, the way Wald, Benthin and Slusallek (2003, sec. 5)
 * played them through OpenRT: the scene is recorded once as objects by
 * rtuLoadAFF, and every frame the application only sets the camera and
 * re-issues its instances (rtuDrawAFF), with the animated triangles of the
 * museum redefined in place.
 *
 * With a display it opens a GLFW window and plays in real time at the
 * scene's frame rate, skipping frames when rendering falls behind; without
 * one (or with --headless) it renders a frame range to numbered images.
 * Run `bart --help` for the options and keys; docs/bart.md has more.
 * Frames are numbered by their 0-based index in the scene in every output
 * (kitchen_0000.png is frame 0), as in gears.
 */
#include <rt/rt.h>
#include <rt/rtu.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo_util.h"

#ifdef RT_HAVE_GLFW
#include "demo_window.h"
#endif

#ifndef RT_BART_DIR
#define RT_BART_DIR "../shared/bart"
#endif

#define PROGRAM "bart"

struct scene_file {
    const char *name, *folder, *top;
};

static const struct scene_file known_scenes[] = {
    {"kitchen", "kitchen", "kitchen.aff"},
    {"robots", "robots", "Robot.aff"},
    {"museum", "museum", "museum5.aff"},
};

static const struct {
    const char *name;
    RTenum value;
} strategies[] = {
    {"automatic", RT_AUTOMATIC},       {"refit", RT_REFIT},
    {"rebuild", RT_REBUILD},           {"median", RT_REBUILD_MEDIAN},
    {"heuristic", RT_REBUILD_HEURISTIC}, {"restructure", RT_RESTRUCTURE},
    {"async", RT_ASYNC_REBUILD},
};
#define STRATEGY_COUNT ((int)(sizeof strategies / sizeof strategies[0]))

struct options {
    const char *scene;    /* kitchen | robots | museum | path to an .aff */
    const char *bart_dir; /* --bart-dir; NULL: TRACELIST_BART_DIR or the default */
    int headless;
    int first, last, step; /* frame range (0-based, inclusive), last < 0: to the end */
    int width, height;
    int threads, build_threads;
    int strategy;  /* index into strategies */
    int eye_light; /* --shading eye */
    int depth;     /* Whitted recursion depth */
    int flat;      /* --flat: bake every frame into one static object */
    int stats;     /* --stats: one line of statistics per frame */
    int window_frames; /* --window-frames N: quit the window after N frames */
    int sheet_cols, sheet_rows; /* --contact-sheet CxR: one image of C x R frames */
    const char *out;
};

static void usage(FILE *f)
{
    fprintf(f,
            "Usage: bart [OPTION]... [kitchen|robots|museum|FILE.aff]\n"
            "Play a BART benchmark scene (default kitchen) with Tracelist: in a window when\n"
            "there is a display, else (or with --headless) to numbered image files.\n\n"
            "  -H, --headless            render frames to images instead of a window\n"
            "  -n, --frames=A-B          frame range, 0-based and inclusive (default: all;\n"
            "                            A alone is one frame)\n"
            "      --step=K              render every K-th frame of the range (headless)\n"
            "  -s, --size=WxH            image or window size (default 640x480)\n"
            "  -t, --threads=N           render threads (default: all processors)\n"
            "      --build-threads=K     asynchronous rebuild threads (default 1)\n"
            "      --strategy=S          update strategy of moving objects: automatic\n"
            "                            (default), refit, rebuild, median, heuristic,\n"
            "                            restructure, async\n"
            "      --shading=M           whitted (default: shadows and reflections) or eye\n"
            "      --depth=N             Whitted reflection depth (default 3, as in OpenRT)\n"
            "      --flat                bake each frame into one static object (the\n"
            "                            reference of the two-level configuration)\n"
            "      --stats               print update/render times and ray counts per frame\n"
            "  -o, --out=FILE            output name, FILE_0000.ext ... by frame index\n"
            "                            (default <scene>.png); an unknown extension is refused\n"
            "      --bart-dir=DIR        the BART folder (default: $TRACELIST_BART_DIR, else\n"
            "                            " RT_BART_DIR ")\n"
            "      --window-frames=N     close the window after N frames (for tests)\n"
            "      --contact-sheet=CxR   one image of C x R frames spread evenly over the\n"
            "                            range, each --size large, first frame top left\n"
            "      --info                print the library version, renderer and configuration\n"
            "  -h, --help                display this help and exit\n"
            "  -V, --version             output version information and exit\n\n"
            "Keys in the window:\n" DEMO_COMMON_KEYS
            "  space          pause / resume\n"
            "  right, left    step one frame forward / back (pauses)\n"
            "  s              eye-light / Whitted shading\n"
            "  t              next update strategy\n"
            "  r              restart from frame 0\n\n"
            "The BART scenes (Lext, Assarsson, Moller 2000) are public; see docs/bart.md.\n");
}

static int parse_range(const char *text, int *first, int *last)
{
    char buf[64];
    if (text == NULL || strlen(text) >= sizeof buf)
        return 0;
    strcpy(buf, text);
    char *dash = strchr(buf, '-');
    if (dash == NULL) {
        if (!demo_parse_int(buf, 0, 100000000, first))
            return 0;
        *last = *first;
        return 1;
    }
    *dash = '\0';
    return demo_parse_int(buf, 0, 100000000, first) &&
           demo_parse_int(dash + 1, 0, 100000000, last) && *last >= *first;
}

enum {
    OPT_STEP = 256,
    OPT_BUILD_THREADS,
    OPT_STRATEGY,
    OPT_SHADING,
    OPT_DEPTH,
    OPT_FLAT,
    OPT_STATS,
    OPT_BART_DIR,
    OPT_WINDOW_FRAMES,
    OPT_CONTACT_SHEET,
    OPT_INFO
};

/* Returns 1 to run, 0 to exit with *status (help, version, a bad option). */
static int parse_options(int argc, char **argv, struct options *o, int *info, int *status)
{
    static const struct option long_options[] = {
        {"headless", no_argument, NULL, 'H'},
        {"frames", required_argument, NULL, 'n'},
        {"step", required_argument, NULL, OPT_STEP},
        {"size", required_argument, NULL, 's'},
        {"threads", required_argument, NULL, 't'},
        {"build-threads", required_argument, NULL, OPT_BUILD_THREADS},
        {"strategy", required_argument, NULL, OPT_STRATEGY},
        {"shading", required_argument, NULL, OPT_SHADING},
        {"depth", required_argument, NULL, OPT_DEPTH},
        {"flat", no_argument, NULL, OPT_FLAT},
        {"stats", no_argument, NULL, OPT_STATS},
        {"out", required_argument, NULL, 'o'},
        {"bart-dir", required_argument, NULL, OPT_BART_DIR},
        {"window-frames", required_argument, NULL, OPT_WINDOW_FRAMES},
        {"contact-sheet", required_argument, NULL, OPT_CONTACT_SHEET},
        {"info", no_argument, NULL, OPT_INFO},
        {"help", no_argument, NULL, 'h'},
        {"version", no_argument, NULL, 'V'},
        {NULL, 0, NULL, 0}};
    memset(o, 0, sizeof *o);
    o->scene = "kitchen";
    o->last = -1;
    o->step = 1;
    o->width = 640;
    o->height = 480;
    o->build_threads = 1;
    o->depth = 3;
    *info = 0;
    *status = 2;
    opterr = 0;
    int c;
    while ((c = getopt_long(argc, argv, ":Hn:s:t:o:hV", long_options, NULL)) != -1) {
        const char *bad = NULL; /* what the argument should have been */
        switch (c) {
        case 'H':
            o->headless = 1;
            break;
        case OPT_FLAT:
            o->flat = 1;
            break;
        case OPT_STATS:
            o->stats = 1;
            break;
        case 'n':
            if (!parse_range(optarg, &o->first, &o->last))
                bad = "a frame A or a range A-B with A <= B";
            break;
        case OPT_STEP:
            if (!demo_parse_int(optarg, 1, 1000000, &o->step))
                bad = "a whole number, 1 or more";
            break;
        case OPT_CONTACT_SHEET:
            if (!demo_parse_size(optarg, &o->sheet_cols, &o->sheet_rows))
                bad = "CxR, e.g. 3x2";
            o->headless = 1;
            break;
        case 's':
            if (!demo_parse_size(optarg, &o->width, &o->height))
                bad = "WxH, e.g. 640x480, at most 16384";
            break;
        case 't':
            if (!demo_parse_int(optarg, 1, 256, &o->threads))
                bad = "1 to 256";
            break;
        case OPT_BUILD_THREADS:
            if (!demo_parse_int(optarg, 1, 64, &o->build_threads))
                bad = "1 to 64";
            break;
        case OPT_DEPTH:
            if (!demo_parse_int(optarg, 0, 16, &o->depth))
                bad = "0 to 16";
            break;
        case OPT_WINDOW_FRAMES:
            if (!demo_parse_int(optarg, 1, 100000000, &o->window_frames))
                bad = "a whole number, 1 or more";
            break;
        case OPT_STRATEGY: {
            int found = 0;
            for (int k = 0; k < STRATEGY_COUNT; k++)
                if (strcmp(optarg, strategies[k].name) == 0)
                    o->strategy = k, found = 1;
            if (!found)
                bad = "automatic, refit, rebuild, median, heuristic, restructure or async";
            break;
        }
        case OPT_SHADING:
            if (strcmp(optarg, "eye") == 0 || strcmp(optarg, "whitted") == 0)
                o->eye_light = strcmp(optarg, "eye") == 0;
            else
                bad = "whitted or eye";
            break;
        case 'o':
            if (optarg[0] == '\0')
                bad = "a file name";
            o->out = optarg;
            break;
        case OPT_BART_DIR:
            if (optarg[0] == '\0')
                bad = "a folder";
            o->bart_dir = optarg;
            break;
        case OPT_INFO:
            *info = 1;
            break;
        case 'h':
            usage(stdout);
            *status = 0;
            return 0;
        case 'V':
            *status = demo_print_version(PROGRAM);
            return 0;
        case ':':
            demo_usage_error(PROGRAM, "option '%s' requires an argument", argv[optind - 1]);
            return 0;
        default:
            demo_usage_error(PROGRAM, "unrecognized option '%s'", argv[optind - 1]);
            return 0;
        }
        if (bad != NULL) {
            const char *option = "";
            for (int k = 0; long_options[k].name != NULL; k++)
                if (long_options[k].val == c)
                    option = long_options[k].name;
            demo_usage_error(PROGRAM, "invalid argument '%s' for '--%s' (%s)", optarg, option,
                             bad);
            return 0;
        }
    }
    if (optind < argc)
        o->scene = argv[optind++];
    if (optind < argc) {
        demo_usage_error(PROGRAM, "unexpected argument '%s' (one scene only)", argv[optind]);
        return 0;
    }
    return 1;
}

/* The .aff file for the scene argument. */
static const char *scene_path(const struct options *o, char *out, size_t size,
                              const char **short_name)
{
    const char *dir = o->bart_dir ? o->bart_dir : getenv("TRACELIST_BART_DIR");
    if (dir == NULL || dir[0] == '\0')
        dir = RT_BART_DIR;
    for (size_t i = 0; i < sizeof known_scenes / sizeof known_scenes[0]; i++)
        if (strcmp(o->scene, known_scenes[i].name) == 0) {
            snprintf(out, size, "%s/%s/%s", dir, known_scenes[i].folder, known_scenes[i].top);
            *short_name = known_scenes[i].name;
            return out;
        }
    snprintf(out, size, "%s", o->scene);
    const char *slash = strrchr(o->scene, '/');
    *short_name = slash ? slash + 1 : o->scene;
    return out;
}

/* ------------------------------------------------------------ one frame */

struct player {
    const struct options *o;
    RTUaffscene *scene;
    int frames;
    int eye_light;
    int strategy;
    RTuint flat_object;
    double update_ms, render_ms; /* of the last frame */
};

static void apply_settings(struct player *p)
{
    rtShadingMode(p->eye_light ? RT_EYE_LIGHT : RT_WHITTED);
    rtRenderParameteri(RT_MAX_RAY_DEPTH, p->o->depth);
    rtRenderParameteri(RT_UPDATE_STRATEGY, (RTint)strategies[p->strategy].value);
}

/* Describes and renders frame f; returns 0 on a Tracelist error. */
static int render_frame(struct player *p, int f, int width, int height)
{
    double t = rtuAFFFrameTime(p->scene, f);
    rtViewport(0, 0, width, height);
    rtMatrixMode(RT_PROJECTION);
    rtLoadIdentity();
    rtuAFFView(p->scene, t, (double)width / (double)height);
    rtMatrixMode(RT_MODELVIEW);
    rtLoadIdentity();
    rtuAFFLights(p->scene, t);
    if (p->o->flat) {
        if (p->flat_object)
            rtDeleteObjects(1, &p->flat_object);
        p->flat_object = rtuBakeAFF(p->scene, t);
        rtInstantiateObject(p->flat_object);
    } else {
        rtuDrawAFF(p->scene, t);
    }
    rtRenderFrame();
    float update = 0.0f, render = 0.0f;
    rtGetFloatv(RT_STAT_UPDATE_TIME, &update);
    rtGetFloatv(RT_STAT_RENDER_TIME, &render);
    p->update_ms = update;
    p->render_ms = render;
    if (p->o->stats) {
        RTint rays = 0, builds = 0, updates = 0;
        float top = 0.0f, build = 0.0f;
        rtGetIntegerv(RT_STAT_RAYS, &rays);
        rtGetIntegerv(RT_STAT_OBJECT_BUILDS, &builds);
        rtGetIntegerv(RT_STAT_OBJECT_UPDATES, &updates);
        rtGetFloatv(RT_STAT_TOPLEVEL_TIME, &top);
        rtGetFloatv(RT_STAT_BUILD_TIME, &build);
        printf("frame %d t=%.4f render %.2f ms update %.3f ms toplevel %.3f ms build %.2f ms "
               "rays %d builds %d updates %d\n",
               f, t, render, update, top, build, rays, builds, updates);
    }
    return !demo_report_error(PROGRAM, "rendering");
}

/*
 * --contact-sheet CxR: C x R frames spread evenly over the range, tiled
 * left to right and top to bottom into one image (rtReadPixels rows run
 * bottom to top, so sheet rows are filled from the top of the buffer's
 * end).
 */
static int run_contact_sheet(struct player *p, const char *name, int first, int last)
{
    const struct options *o = p->o;
    int cols = o->sheet_cols, rows = o->sheet_rows, n = cols * rows;
    size_t sheet_w = (size_t)cols * (size_t)o->width, sheet_h = (size_t)rows * (size_t)o->height;
    unsigned char *tile = malloc((size_t)o->width * (size_t)o->height * 4);
    unsigned char *sheet = calloc(sheet_w * sheet_h, 4);
    char fallback[256], path[4096];
    int status = 0;
    if (!tile || !sheet || sheet_w > 16384 || sheet_h > 16384) {
        fprintf(stderr, PROGRAM ": contact sheet too large\n");
        free(tile);
        free(sheet);
        return 1;
    }
    double start = demo_now();
    for (int i = 0; i < n; i++) {
        int f = n > 1 ? first + (int)((long)(last - first) * i / (n - 1)) : first;
        if (!render_frame(p, f, o->width, o->height)) {
            status = 1;
            break;
        }
        rtReadPixels(0, 0, o->width, o->height, RT_RGBA, RT_UNSIGNED_BYTE, tile);
        int col = i % cols, row = rows - 1 - i / cols; /* row 0 at the bottom */
        for (int y = 0; y < o->height; y++)
            memcpy(sheet + (((size_t)row * o->height + y) * sheet_w + (size_t)col * o->width) * 4,
                   tile + (size_t)y * o->width * 4, (size_t)o->width * 4);
        demo_progress(PROGRAM, i + 1, n, demo_now() - start, 1e3 * (demo_now() - start) / (i + 1),
                      NULL);
    }
    snprintf(fallback, sizeof fallback, "%s_sheet.png", name);
    if (demo_output_name(path, sizeof path, o->out, fallback, PROGRAM) == NULL)
        status = 2;
    if (status == 0 && !rtuSaveImage(path, (RTsizei)sheet_w, (RTsizei)sheet_h, RT_UNSIGNED_BYTE,
                                     sheet)) {
        fprintf(stderr, PROGRAM ": %s\n", rtuImageError());
        status = 1;
    }
    if (status == 0) {
        printf(PROGRAM ": %s: contact sheet of %d frames (%d..%d)\n", name, n, first, last);
        demo_report_written(PROGRAM, path, path);
    }
    free(tile);
    free(sheet);
    return status;
}

static int run_headless(struct player *p, const char *name)
{
    const struct options *o = p->o;
    int last = o->last < 0 || o->last >= p->frames ? p->frames - 1 : o->last;
    if (o->first > last) {
        fprintf(stderr, PROGRAM ": frame %d is past the scene's last frame %d\n", o->first,
                p->frames - 1);
        return 1;
    }
    if (o->sheet_cols > 0)
        return run_contact_sheet(p, name, o->first, last);
    int total = (last - o->first) / o->step + 1;
    char fallback[256], base[4096];
    snprintf(fallback, sizeof fallback, "%s.png", name);
    if (demo_output_name(base, sizeof base, o->out, fallback, PROGRAM) == NULL)
        return 2;
    unsigned char *pixels = malloc((size_t)o->width * (size_t)o->height * 4);
    if (!pixels) {
        fprintf(stderr, PROGRAM ": out of memory\n");
        return 1;
    }
    double start = demo_now(), frame_seconds = 0.0, update_ms = 0.0;
    int done = 0, status = 0;
    char path[4200], first_path[4200];
    for (int f = o->first; f <= last; f += o->step) {
        double t0 = demo_now();
        if (!render_frame(p, f, o->width, o->height)) {
            status = 1;
            break;
        }
        frame_seconds += demo_now() - t0;
        update_ms += p->update_ms;
        demo_frame_name(path, sizeof path, base, f, total > 1);
        if (!demo_save_frame(PROGRAM, path, o->width, o->height, pixels)) {
            status = 1;
            break;
        }
        if (done == 0)
            snprintf(first_path, sizeof first_path, "%s", path);
        done++;
        char detail[64];
        snprintf(detail, sizeof detail, "update %.2f ms", update_ms / done);
        demo_progress(PROGRAM, done, total, demo_now() - start, 1e3 * frame_seconds / done,
                      detail);
    }
    free(pixels);
    if (status == 0)
        printf(PROGRAM ": %s, %d frame%s of %dx%d, %.1f ms/frame = %.2f fps (describe + "
               "update + render), update %.3f ms/frame\n",
               name, done, done == 1 ? "" : "s", o->width, o->height,
               1e3 * frame_seconds / done, done / frame_seconds, update_ms / done);
    if (status == 0)
        demo_report_written(PROGRAM, first_path, path);
    return status;
}

#ifdef RT_HAVE_GLFW

struct window_state {
    struct player *p;
    int paused;
    int step;       /* frames to step while paused (+1 / -1) */
    int restart;
    int settings_changed;
};

static void key(GLFWwindow *window, int k, int scancode, int action, int mods)
{
    struct window_state *ws = glfwGetWindowUserPointer(window);
    (void)scancode;
    (void)mods;
    if (action != GLFW_PRESS && action != GLFW_REPEAT)
        return;
    switch (k) {
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q:
        glfwSetWindowShouldClose(window, GLFW_TRUE);
        break;
    case GLFW_KEY_SPACE:
        ws->paused = !ws->paused;
        break;
    case GLFW_KEY_RIGHT:
        ws->paused = 1;
        ws->step = 1;
        break;
    case GLFW_KEY_LEFT:
        ws->paused = 1;
        ws->step = -1;
        break;
    case GLFW_KEY_S:
        ws->p->eye_light = !ws->p->eye_light;
        ws->settings_changed = 1;
        break;
    case GLFW_KEY_T:
        ws->p->strategy = (ws->p->strategy + 1) % STRATEGY_COUNT;
        ws->settings_changed = 1;
        break;
    case GLFW_KEY_R:
        ws->restart = 1;
        break;
    default:
        break;
    }
}

/*
 * Real-time playback: the frame shown is the one the scene's clock has
 * reached (frames per second = (N - 1) / (t1 - t0)); frames that go by
 * while one is rendered are skipped, as a video player would.  Returns -1
 * when no window could be opened (the caller goes headless).
 */
static int run_window(struct player *p, const char *name)
{
    const struct options *o = p->o;
    if (!glfwInit())
        return -1;
    GLFWwindow *window = glfwCreateWindow(o->width, o->height, "Tracelist BART", NULL, NULL);
    if (window == NULL) {
        glfwTerminate();
        return -1;
    }
    struct window_state ws = {p, 0, 0, 0, 0};
    glfwSetWindowUserPointer(window, &ws);
    glfwMakeContextCurrent(window);
    glfwSwapInterval(0);
    glfwSetKeyCallback(window, key);

    double t_begin = rtuAFFFrameTime(p->scene, 0);
    double t_end = rtuAFFFrameTime(p->scene, p->frames - 1);
    double fps = p->frames > 1 && t_end > t_begin ? (p->frames - 1) / (t_end - t_begin) : 30.0;
    unsigned char *pixels = NULL;
    int width = 0, height = 0, status = 0, shown = 0, skipped = 0, frame = o->first;
    double clock_start = demo_now() - o->first / fps, title_time = demo_now();
    int title_frames = 0;
    while (!glfwWindowShouldClose(window) && (o->window_frames == 0 || shown < o->window_frames)) {
        int fb_width, fb_height;
        glfwGetFramebufferSize(window, &fb_width, &fb_height);
        if (fb_width <= 0 || fb_height <= 0) {
            glfwWaitEvents();
            continue;
        }
        if (fb_width != width || fb_height != height) {
            unsigned char *grown = realloc(pixels, (size_t)fb_width * (size_t)fb_height * 4);
            if (grown == NULL) {
                fprintf(stderr, PROGRAM ": out of memory\n");
                status = 1;
                break;
            }
            pixels = grown;
            width = fb_width;
            height = fb_height;
        }
        if (ws.settings_changed) {
            apply_settings(p);
            ws.settings_changed = 0;
        }
        if (ws.restart) {
            frame = 0;
            clock_start = demo_now();
            ws.restart = 0;
        } else if (ws.paused) {
            frame += ws.step;
            ws.step = 0;
            frame = frame < 0 ? p->frames - 1 : frame % p->frames;
            clock_start = demo_now() - frame / fps; /* resume from here */
        } else {
            int due = (int)((demo_now() - clock_start) * fps);
            if (due >= p->frames) { /* loop */
                clock_start = demo_now();
                due = 0;
            }
            if (due > frame + 1)
                skipped += due - frame - 1;
            frame = due;
        }
        if (!render_frame(p, frame, width, height)) {
            status = 1;
            break;
        }
        demo_present(window, width, height, pixels);
        shown++;
        title_frames++;
        double now = demo_now();
        if (now - title_time >= 0.5 || ws.paused) {
            char title[256];
            snprintf(title, sizeof title,
                     "Tracelist BART %s - frame %d/%d%s - %.1f fps - update %.1f ms render %.0f "
                     "ms - %s - %s - %d skipped",
                     name, frame, p->frames - 1, ws.paused ? " (paused)" : "",
                     title_frames / (now - title_time > 0 ? now - title_time : 1.0),
                     p->update_ms, p->render_ms, p->eye_light ? "eye light" : "Whitted",
                     strategies[p->strategy].name, skipped);
            glfwSetWindowTitle(window, title);
            title_frames = 0;
            title_time = now;
        }
        if (ws.paused && ws.step == 0 && !ws.settings_changed && !ws.restart)
            glfwWaitEventsTimeout(0.1);
    }
    if (status == 0 && o->out != NULL && pixels != NULL) {
        char path[4096];
        if (demo_output_name(path, sizeof path, o->out, o->out, PROGRAM) == NULL) {
            status = 2;
        } else if (!rtuSaveImage(path, width, height, RT_UNSIGNED_BYTE, pixels)) {
            fprintf(stderr, PROGRAM ": %s\n", rtuImageError());
            status = 1;
        } else {
            demo_report_written(PROGRAM, path, path);
        }
    }
    printf(PROGRAM ": %d frames shown, %d skipped to keep real time\n", shown, skipped);
    free(pixels);
    glfwDestroyWindow(window);
    glfwTerminate();
    return status;
}

#endif /* RT_HAVE_GLFW */

int main(int argc, char **argv)
{
    struct options o;
    int info = 0, status = 2;
    if (!parse_options(argc, argv, &o, &info, &status))
        return status;
    char path[4096], config[64], checked[4096];
    const char *name;
    scene_path(&o, path, sizeof path, &name);
    if (o.threads > 0)
        snprintf(config, sizeof config, "threads=%d build_threads=%d", o.threads,
                 o.build_threads);
    else
        snprintf(config, sizeof config, "build_threads=%d", o.build_threads);
    if (info)
        return demo_print_info(PROGRAM, config);
    /* Refuse an unwritable --out before loading anything. */
    if (o.out != NULL && demo_output_name(checked, sizeof checked, o.out, NULL, PROGRAM) == NULL)
        return 2;
    RTcontext context = demo_create_context(PROGRAM, config);
    if (context == NULL)
        return 1;
    double t0 = demo_now();
    RTUaffscene *scene = rtuLoadAFF(path);
    if (scene == NULL) {
        fprintf(stderr, PROGRAM ": %s\n", rtuAFFError());
        if (strcmp(name, o.scene) == 0 || strchr(o.scene, '/') == NULL)
            fprintf(stderr, PROGRAM ": the BART scenes are looked for in --bart-dir, "
                            "$TRACELIST_BART_DIR or " RT_BART_DIR "; they are public "
                            "(Lext, Assarsson, Moller 2000): see docs/bart.md\n");
        rtDestroyContext(context);
        return 1;
    }
    struct player p;
    memset(&p, 0, sizeof p);
    p.o = &o;
    p.scene = scene;
    rtuGetAFFiv(scene, RTU_AFF_FRAMES, &p.frames);
    p.eye_light = o.eye_light;
    p.strategy = o.strategy;
    RTint objects, tris, animated;
    rtuGetAFFiv(scene, RTU_AFF_OBJECTS, &objects);
    rtuGetAFFiv(scene, RTU_AFF_TRIANGLES, &tris);
    rtuGetAFFiv(scene, RTU_AFF_ANIMATED_TRIANGLES, &animated);
    printf(PROGRAM ": %s: %d triangles (%d animated) in %d objects, %d frames, loaded in "
                   "%.2f s\n",
           name, tris, animated, objects, p.frames, demo_now() - t0);
    apply_settings(&p);

    status = -1;
#ifdef RT_HAVE_GLFW
    if (!o.headless && (getenv("DISPLAY") != NULL || getenv("WAYLAND_DISPLAY") != NULL)) {
        status = run_window(&p, name);
        if (status < 0)
            fprintf(stderr, PROGRAM ": cannot open a window; rendering headless\n");
    }
#endif
    if (status < 0)
        status = run_headless(&p, name);
    if (p.flat_object)
        rtDeleteObjects(1, &p.flat_object);
    rtuDeleteAFF(scene);
    rtDestroyContext(context);
    return status;
}
