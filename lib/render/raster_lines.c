/* SPDX-License-Identifier: Apache-2.0 */
/*
 * raster_lines.c - line segments over the ray-traced image (raster.h):
 * projection, clipping, GL's non-antialiased segment rules, depth test.
 */
#include "render/raster.h"

#include <math.h>
#include <string.h>

#include "base/alloc.h"
#include "base/mat4.h"
#include "render/blend.h"

double raster_window_depth(const double projection[16], const float org[3], const float dir[3],
                           float t)
{
    if (!isfinite(t))
        return 1.0;
    double p[3];
    for (int k = 0; k < 3; k++)
        p[k] = (double)org[k] + (double)t * (double)dir[k];
    const double *m = projection;
    double z = m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14];
    double w = m[3] * p[0] + m[7] * p[1] + m[11] * p[2] + m[15];
    if (!(w != 0.0))
        return 1.0;
    double d = 0.5 * (z / w) + 0.5;
    return d < 0.0 ? 0.0 : d > 1.0 ? 1.0 : d;
}

void raster_depth_prepare(double *depth, int width, int height)
{
    size_t n = (size_t)width * (size_t)height;
    for (size_t i = 0; i < n; i++)
        if (depth[i] < 1.0)
            depth[i] += RASTER_DEPTH_EPSILON;
}

/* |d(i) - d(j)| when pixel j shows the same instance's surface as pixel i
 * (same state block) and is covered; -1 when it cannot tell. */
static double step(const double *depth, const struct scene_raster *const *state, size_t i,
                   size_t j)
{
    if (state[j] != state[i] || !(depth[j] < 1.0))
        return -1.0;
    return fabs(depth[j] - depth[i]);
}

/* The slope along one axis: the smaller of the two one-sided differences
 * that exist (at a silhouette, the one on the surface's side). */
static double axis_slope(double a, double b)
{
    if (a < 0.0)
        return b < 0.0 ? 0.0 : b;
    return b < 0.0 ? a : fmin(a, b);
}

void raster_depth_offset(double *depth, const struct scene_raster *const *state, int width,
                         int height)
{
    size_t n = (size_t)width * (size_t)height;
    double *d = rt_malloc((n ? n : 1) * sizeof(*d));
    if (d)
        memcpy(d, depth, n * sizeof(*d));
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            size_t i = (size_t)y * (size_t)width + (size_t)x;
            const struct scene_raster *r = state[i];
            if (!r || !r->offset_fill || !(depth[i] < 1.0))
                continue;
            double m = 0.0;
            if (d) {
                double sx = axis_slope(x > 0 ? step(d, state, i, i - 1) : -1.0,
                                       x + 1 < width ? step(d, state, i, i + 1) : -1.0);
                double sy = axis_slope(y > 0 ? step(d, state, i, i - (size_t)width) : -1.0,
                                       y + 1 < height ? step(d, state, i, i + (size_t)width)
                                                      : -1.0);
                m = fmax(sx, sy);
            }
            /* GL's o = m * factor + r * units (OpenGL 1.5 sec. 3.5.5), r
             * the depth buffer's resolution; clamped to GL's depth range. */
            double o = m * (double)r->offset_factor + RASTER_DEPTH_EPSILON * (double)r->offset_units;
            double z = depth[i] + o;
            depth[i] = z < 0.0 ? 0.0 : z > 1.0 ? 1.0 : z;
        }
    rt_free(d);
}

void raster_fragment(const struct raster_target *target, long x, long y, double z,
                     const float color[4])
{
    if (x < 0 || y < 0 || x >= target->width || y >= target->height)
        return;
    size_t i = (size_t)y * (size_t)target->width + (size_t)x;
    if (target->depth_test && !(z < target->depth[i]))
        return; /* GL's default depth function, RT_LESS */
    float *px = &target->rgba[4 * i];
    const struct render_visibility *vis = target->vis;
    const struct scene_raster *r = target->raster;
    /* GL's alpha test, then blending, with the primitive's state. */
    if (r->alpha_test &&
        !scene_alpha_passes(r->alpha_func, fminf(fmaxf(color[3], 0.0f), 1.0f), r->alpha_ref))
        return;
    if (r->blend)
        blend_combine(r->blend_src, r->blend_dst, color, px, px);
    else
        memcpy(px, color, 4 * sizeof(float));
    if (target->depth_test && vis->depth_mask)
        target->depth[i] = z;
}

void raster_to_window(const struct raster_target *target, const double clip[4], double win[3])
{
    const int *vp = target->viewport;
    win[0] = vp[0] + (clip[0] / clip[3] + 1.0) * 0.5 * vp[2];
    win[1] = vp[1] + (clip[1] / clip[3] + 1.0) * 0.5 * vp[3];
    win[2] = (clip[2] / clip[3] + 1.0) * 0.5;
}

void raster_vertex(const struct raster_target *target, const struct scene_lines *lines,
                   uint32_t v, const double object_to_eye[16], double eye[3], double clip[4])
{
    const float *p = &lines->positions[3 * v];
    double po[3] = {p[0], p[1], p[2]};
    mat4_transform_point(object_to_eye, po, eye);
    const double *m = target->projection;
    for (int r = 0; r < 4; r++)
        clip[r] = m[r] * eye[0] + m[4 + r] * eye[1] + m[8 + r] * eye[2] + m[12 + r];
}

long raster_pixels(float value, float current, float max)
{
    float v = value > 0.0f ? value : current;
    v = fminf(v, max);
    long n = (long)floor((double)v + 0.5);
    return n < 1 ? 1 : n;
}

/*
 * Clips the segment (eye ea..eb, clip ca..cb) to the view volume and the
 * user clip planes enabled when it was drawn (Liang-Barsky on the parameter, which is the
 * same in eye and clip space: both are affine images of the object-space
 * segment).  Returns 0 when nothing is left, else [*t0, *t1].
 */
static int clip_segment(const struct scene_clip *clip, const double ea[3],
                        const double eb[3], const double ca[4], const double cb[4], double *t0,
                        double *t1)
{
    double lo = 0.0, hi = 1.0;
    double da[6 + RENDER_MAX_CLIP_PLANES], db[6 + RENDER_MAX_CLIP_PLANES];
    int n = 0;
    for (int axis = 0; axis < 3; axis++) {
        da[n] = ca[3] + ca[axis];
        db[n++] = cb[3] + cb[axis];
        da[n] = ca[3] - ca[axis];
        db[n++] = cb[3] - cb[axis];
    }
    for (int i = 0; i < RENDER_MAX_CLIP_PLANES; i++) {
        if (!(clip->enabled >> i & 1u))
            continue;
        const double *e = clip->plane[i];
        da[n] = e[0] * ea[0] + e[1] * ea[1] + e[2] * ea[2] + e[3];
        db[n++] = e[0] * eb[0] + e[1] * eb[1] + e[2] * eb[2] + e[3];
    }
    for (int i = 0; i < n; i++) {
        if (!isfinite(da[i]) || !isfinite(db[i]))
            return 0;
        if (da[i] < 0.0 && db[i] < 0.0)
            return 0;
        if (da[i] < 0.0)
            lo = fmax(lo, da[i] / (da[i] - db[i]));
        else if (db[i] < 0.0)
            hi = fmin(hi, da[i] / (da[i] - db[i]));
    }
    *t0 = lo;
    *t1 = hi;
    return lo <= hi;
}

/* A clipped segment in window space with what its fragments need. */
struct window_segment {
    double a[3], b[3];      /* window x, y, z of the ends */
    double wa, wb;          /* clip w of the ends, for perspective-correct colour */
    float ca[4], cb[4];     /* colours of the ends */
    int flat;
    long width;             /* whole pixels */
    int x_major;
};

/* Colour at window parameter s: interpolated in clip space (GL's
 * perspective-correct attribute interpolation, sec. 3.4.1 eq. 3.6). */
static void segment_color(const struct window_segment *seg, double s, float out[4])
{
    if (seg->flat) {
        memcpy(out, seg->ca, 4 * sizeof(float));
        return;
    }
    double u = (s / seg->wb) / ((1.0 - s) / seg->wa + s / seg->wb);
    if (!isfinite(u))
        u = s;
    for (int k = 0; k < 4; k++)
        out[k] = (float)((1.0 - u) * seg->ca[k] + u * seg->cb[k]);
}

/* The fragment whose diamond test passed: with its column (x-major) or
 * row (y-major) of `width` fragments. */
static void emit(const struct raster_target *target, const struct window_segment *seg, long xf,
                 long yf)
{
    /* Depth and colour at the pixel centre's projection onto the segment
     * (GL's t of sec. 3.4.1 eq. 3.5, on the unshifted segment). */
    double dx = seg->b[0] - seg->a[0], dy = seg->b[1] - seg->a[1];
    double len2 = dx * dx + dy * dy;
    double off = seg->x_major ? 0.0 : (double)(seg->width - 1) / 2.0;
    double offy = seg->x_major ? (double)(seg->width - 1) / 2.0 : 0.0;
    double cx = xf + 0.5 + off, cy = yf + 0.5 + offy;
    double s = len2 > 0.0 ? ((cx - seg->a[0]) * dx + (cy - seg->a[1]) * dy) / len2 : 0.0;
    s = s < 0.0 ? 0.0 : s > 1.0 ? 1.0 : s;
    double z = seg->a[2] + s * (seg->b[2] - seg->a[2]);
    float color[4];
    segment_color(seg, s, color);
    for (long i = 0; i < seg->width; i++) {
        if (seg->x_major)
            raster_fragment(target, xf, yf + i, z, color);
        else
            raster_fragment(target, xf + i, yf, z, color);
    }
}

/* L1 distance from (cx, cy) to the segment p + t d, t in [0, 1]: convex
 * and piecewise linear in t, so its minimum is at an end or a kink. */
static double l1_distance(const double p[2], const double d[2], double cx, double cy)
{
    double ts[4] = {0.0, 1.0, d[0] != 0.0 ? (cx - p[0]) / d[0] : 0.0,
                    d[1] != 0.0 ? (cy - p[1]) / d[1] : 0.0};
    double best = INFINITY;
    for (int i = 0; i < 4; i++) {
        double t = ts[i] < 0.0 ? 0.0 : ts[i] > 1.0 ? 1.0 : ts[i];
        best = fmin(best, fabs(p[0] + t * d[0] - cx) + fabs(p[1] + t * d[1] - cy));
    }
    return best;
}

/*
 * GL's diamond-exit rule (sec. 3.4.1): fragment f is produced when the
 * segment meets the open diamond |x - xf - 1/2| + |y - yf - 1/2| < 1/2
 * and its end point is not inside it.  The ends are perturbed by
 * -(eps, eps^2), as the spec perturbs them, so a segment along a
 * diamond's edge decides as the spec's perturbed one: a horizontal line
 * at y = 80 exactly lights row 79, as Mesa's does (the overlay oracle's
 * crosshair).  Wide segments are shifted by (width - 1) / 2 across
 * their major axis first, and each fragment then starts a column or row.
 */
static void rasterise_segment(const struct raster_target *target, struct window_segment *seg)
{
    const double eps = 1.0 / 4096.0;
    double dx = seg->b[0] - seg->a[0], dy = seg->b[1] - seg->a[1];
    seg->x_major = fabs(dx) >= fabs(dy);
    double shift = (double)(seg->width - 1) / 2.0;
    double p[2] = {seg->a[0] - eps, seg->a[1] - eps * eps};
    double e[2] = {seg->b[0] - eps, seg->b[1] - eps * eps};
    if (seg->x_major) {
        p[1] -= shift;
        e[1] -= shift;
    } else {
        p[0] -= shift;
        e[0] -= shift;
    }
    double d[2] = {e[0] - p[0], e[1] - p[1]};
    int major = seg->x_major ? 0 : 1, minor = 1 - major;
    long limit_major = major == 0 ? target->width : target->height;
    long limit_minor = major == 0 ? target->height : target->width;
    double lo = fmin(p[major], e[major]), hi = fmax(p[major], e[major]);
    long first = (long)fmax(floor(lo) - 1.0, -1.0);
    long last = (long)fmin(floor(hi) + 1.0, (double)limit_major);
    for (long m = first; m <= last; m++) {
        double c_major = m + 0.5;
        double along = d[major] != 0.0 ? (c_major - p[major]) / d[major] : 0.0;
        along = along < 0.0 ? 0.0 : along > 1.0 ? 1.0 : along;
        double at = p[minor] + along * d[minor];
        long base = (long)floor(at);
        for (long n = base - 1; n <= base + 1; n++) {
            if (n < -seg->width || n > limit_minor)
                continue;
            double cx = major == 0 ? c_major : n + 0.5;
            double cy = major == 0 ? n + 0.5 : c_major;
            if (l1_distance(p, d, cx, cy) >= 0.5)
                continue;
            if (fabs(e[0] - cx) + fabs(e[1] - cy) < 0.5)
                continue; /* the segment ends inside: it does not exit */
            if (major == 0)
                emit(target, seg, m, n);
            else
                emit(target, seg, n, m);
        }
    }
}

static void lerp4(const float *a, const float *b, double t, float out[4])
{
    for (int k = 0; k < 4; k++)
        out[k] = (float)((1.0 - t) * a[k] + t * b[k]);
}

static void draw_segment(const struct raster_target *target, const struct scene_lines *lines,
                         const struct scene_line_segment *sg, const double object_to_eye[16])
{
    double ea[3], eb[3], ca[4], cb[4];
    raster_vertex(target, lines, sg->v[0], object_to_eye, ea, ca);
    raster_vertex(target, lines, sg->v[1], object_to_eye, eb, cb);
    /* The vertices' colours: GL's lines with lighting disabled.  Lit lines
     * (GL lights a line's vertices like any vertex) would compute the
     * vertex colours here, from a normal and material stored with them. */
    const int flat = (sg->flags & SCENE_LINE_FLAT) != 0;
    const float *col_a = &lines->colors[4 * (flat ? sg->provoking : sg->v[0])];
    const float *col_b = &lines->colors[4 * (flat ? sg->provoking : sg->v[1])];
    raster_segment(target, ea, eb, ca, cb, col_a, col_b, flat,
                   raster_pixels(sg->width, target->raster->line_width, RENDER_MAX_LINE_WIDTH));
}

void raster_segment(const struct raster_target *target, const double ea[3], const double eb[3],
                    const double ca[4], const double cb[4], const float col_a[4],
                    const float col_b[4], int flat, long width)
{
    double t0, t1;
    if (!clip_segment(target->clip, ea, eb, ca, cb, &t0, &t1))
        return;
    double c0[4], c1[4];
    for (int k = 0; k < 4; k++) {
        c0[k] = ca[k] + t0 * (cb[k] - ca[k]);
        c1[k] = ca[k] + t1 * (cb[k] - ca[k]);
    }
    if (!(c0[3] > 0.0) || !(c1[3] > 0.0))
        return;
    struct window_segment seg;
    raster_to_window(target, c0, seg.a);
    raster_to_window(target, c1, seg.b);
    seg.wa = c0[3];
    seg.wb = c1[3];
    seg.flat = flat;
    if (seg.flat) {
        memcpy(seg.ca, col_a, sizeof(seg.ca));
        memcpy(seg.cb, seg.ca, sizeof(seg.cb));
    } else {
        lerp4(col_a, col_b, t0, seg.ca);
        lerp4(col_a, col_b, t1, seg.cb);
    }
    seg.width = width;
    seg.x_major = 1;
    rasterise_segment(target, &seg);
}

void raster_lines(const struct raster_target *target, const struct scene_lines *lines,
                  const double object_to_eye[16])
{
    for (uint32_t i = 0; i < lines->segment_count; i++)
        draw_segment(target, lines, &lines->segments[i], object_to_eye);
    raster_points(target, lines, object_to_eye);
}
