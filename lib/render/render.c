/* SPDX-License-Identifier: Apache-2.0 */
/*
 * render.c - frames (tiles over the worker pool) and ray-query batches.
 */
#include "render/render.h"

#include <math.h>
#include <string.h>

#include "base/alloc.h"
#include "base/atomic.h"
#include "base/mat4.h"
#include "base/timer.h"
#include "render/blend.h"
#include "render/filled.h"
#include "render/gl_shade.h"
#include "render/overlay.h"
#include "render/secondary.h"
#include "render/raster.h"
#include "render/shade.h"
#include "render/surface.h"
#include "trace/kernels.h"
#include "trace/packet_scene.h"
#include "trace/scene_stream.h"

/* Primary rays pair their double arithmetic in SSE2 lanes (near and far
 * point, two neighbours): IEEE operations lane by lane, the same floats as
 * one at a time. */
#if defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <emmintrin.h>
#define RENDER_PAIRS 1
#else
#define RENDER_PAIRS 0
#endif

/* The AVX2 copy of this file (render_avx2.c) unprojects a row and makes
 * a block row's rays four at a time in the 256-bit double lanes: the
 * same IEEE operations lane by lane, half the divider instructions of
 * the pairs.  The divider's throughput bounds this code (llvm-mca of the
 * block: its pipe is the bottleneck), and a 256-bit vsqrtpd or vdivpd
 * occupies it about as long as a 128-bit one on AMD's recent cores (Fog,
 * "Instruction tables": Zen 2 to 4; Zen 5 by the frame's time); where it
 * takes twice as long (older Intel cores) nothing is lost. */
#if RENDER_PAIRS && defined(__AVX2__)
#include <immintrin.h>
#define RENDER_QUADS 1
#else
#define RENDER_QUADS 0
#endif

/* The eye light's block pipeline of the shading copy for this copy's
 * instruction set (shade.h): the AVX-512 one in render_avx512.c, the
 * AVX2 one in render_avx2.c. */
#if defined(RENDER_UNIT_AVX512)
#define RENDER_EYE_BLOCK_BEGIN shade_eye_block_begin_avx512
#define RENDER_EYE_BLOCK_END shade_eye_block_end_avx512
#else
#define RENDER_EYE_BLOCK_BEGIN shade_eye_block_begin_avx2
#define RENDER_EYE_BLOCK_END shade_eye_block_end_avx2
#endif

/* The AVX2 and AVX-512 copies' eye-light tiles traced whole before they
 * are shaded (render_tile_eye_traced_first); the other copies keep the
 * block loop. */
#if defined(RENDER_UNIT_AVX2) && RENDER_QUADS
#define RENDER_TILE_TRACED_FIRST 1
#else
#define RENDER_TILE_TRACED_FIRST 0
#endif

/* Packet blocks of the tile loop: 4 x 2 pixels, one packet of
 * TRACE_PACKET camera rays. */
#define RENDER_BLOCK_W 4
#define RENDER_BLOCK_H 2

/* Rays per work item of a query batch. */
#define RENDER_QUERY_CHUNK 1024

/* A structure a render thread built on first use: counted for the
 * frame's statistics (RT_OBJECTS_BUILT, build time). */
static void count_build(struct render_pass *sh, int built_now, double start)
{
    if (built_now) {
        rt_atomic_add_fetch_relaxed(&sh->builds, 1);
        rt_atomic_add_fetch_relaxed(&sh->build_us,
                                    (uint64_t)((rt_now_ms() - start) * 1000.0));
    }
}

/* The object's leaf-ordered triangles into view->tri: what the structure
 * has, or, when this pass may walk the binary tree (reads_binary) or the
 * structure has no wide layout, the array gathered on first need
 * (scene_object_triangles).  A pass that walks only the wide layout
 * leaves view->tri NULL for a structure made without it: no wide walk
 * reads it (only the binary walks do, trace/scene_traverse.h).  0 when
 * the gather fails. */
static int view_triangles(struct render_pass *sh, struct scene_object *o,
                          const struct scene_accel *accel, struct trace_object_view *view)
{
    view->tri = rt_atomic_load_acquire(&accel->tri);
    if (view->tri || (!sh->reads_binary && accel->wide.node_count))
        return 1;
    view->tri = scene_object_triangles(o, accel);
    if (view->tri)
        return 1;
    rt_atomic_store_relaxed(&sh->failed, 1);
    return 0;
}

static int acquire_object(void *user, void *object, struct trace_object_view *view)
{
    struct render_pass *sh = user;
    /* The common case, an object already built, takes no lock and no
     * clock reading. */
    const struct scene_accel *accel = scene_object_peek(object);
    struct scene_object *o = object;
    /* The rays reaching inside an object the automatic strategy updates:
     * its cost model's expected rays (scene/prepare.c). */
    if (o->count_rays)
        view->ray_count = &o->ray_visits;
    if (accel && accel->serial == o->serial) {
        view->bvh = &accel->bvh;
        view->wide = &accel->wide;
        return view_triangles(sh, o, accel, view);
    }
    int built_now;
    double start = rt_now_ms();
    accel = scene_object_acquire(object, sh->job->update, &built_now);
    if (!accel) {
        rt_atomic_store_relaxed(&sh->failed, 1);
        return 0;
    }
    count_build(sh, built_now, start);
    view->bvh = &accel->bvh;
    view->wide = &accel->wide;
    return view_triangles(sh, o, accel, view);
}

/* A flattened nested hierarchy (scene/flatten.h), built on first use. */
static int acquire_flat(void *user, void *object, struct trace_flat *flat)
{
    struct render_pass *sh = user;
    struct scene_flat *f = object;
    const struct scene_flat_accel *a = rt_atomic_load_acquire(&f->accel);
    if (!a) {
        int built_now;
        double start = rt_now_ms();
        a = scene_flat_acquire(f, &built_now);
        if (!a) {
            rt_atomic_store_relaxed(&sh->failed, 1);
            return 0;
        }
        count_build(sh, built_now, start);
    }
    flat->bvh = &a->bvh;
    flat->tri = a->tri;
    flat->member = a->member;
    flat->prim = a->prim;
    return 1;
}

static int shared_init(struct render_pass *sh, const struct render_job *job)
{
    memset(sh, 0, sizeof(*sh));
    sh->job = job;
    sh->scene.top = &job->frame->top;
    sh->scene.instances = job->frame->trace_instances;
    sh->scene.acquire = acquire_object;
    sh->scene.acquire_flat = acquire_flat;
    sh->scene.kernels = job->kernels;
    sh->scene.top_wide = &job->frame->top_wide;
    sh->scene.stream_always = job->stream_always;
    sh->scene.user = sh;
    /* A table without a wide walk walks every object's binary tree. */
    sh->reads_binary = !job->kernels || !job->kernels->closest4;
    /* The workers' counters, then each worker's SHADE_EYE_CACHES eye-light
     * cache entries (shade_context.eye), all empty (inst NULL), in one
     * allocation that every path frees with the counters. */
    const size_t threads = (size_t)rt_pool_threads(job->pool);
    sh->counters = rt_calloc(1, threads * (sizeof(*sh->counters) +
                                           SHADE_EYE_CACHES * sizeof(struct surface_cache)));
    if (!sh->counters)
        return -1;
    sh->eye_caches = (struct surface_cache *)(void *)(sh->counters + threads);
    return 0;
}

static void shared_finish(struct render_pass *sh, struct render_stats *stats)
{
    int n = rt_pool_threads(sh->job->pool);
    for (int i = 0; i < n; i++) {
        trace_scene_flush_ray_count(&sh->counters[i].c);
        const struct trace_scene_counters *c = &sh->counters[i].c;
        stats->rays += c->rays;
        stats->node_tests += c->top_node_tests + c->object.node_tests;
        stats->triangle_tests += c->object.triangle_tests;
        stats->instance_tests += c->instance_tests;
    }
    stats->object_builds += sh->builds;
    stats->build_ms += (double)sh->build_us / 1000.0;
    rt_free(sh->counters);
    rt_free(sh->secondary);
    sh->secondary = NULL;
}

/* The products of the inverse projection's first sum that depend on one
 * viewport coordinate only: m[r] nx for a column (nx = 2 x / w - 1),
 * m[4 + r] ny for a row, r = 0..3.  A tile computes each column's and
 * each row's once (struct unproject_cache) instead of per point: the
 * same expressions, so the same doubles. */
static void unproject_axis(const struct render_pass *sh, int axis, double c, double out[4])
{
    const int *vp = sh->job->state->viewport;
    const double n = 2.0 * c / vp[2 + axis] - 1.0;
    const double *m = sh->inv_projection;
    for (int r = 0; r < 4; r++)
        out[r] = m[4 * axis + r] * n;
}

/* The largest |2 c / size - 1| (unproject_axis's n) for c in [lo, hi]:
 * at an end, as n is monotone in c (each operation rounds monotonically). */
static double unproject_axis_bound(double lo, double hi, int size)
{
    return fmax(fabs(2.0 * lo / size - 1.0), fabs(2.0 * hi / size - 1.0));
}

/*
 * 1 when the row fill's divisors are frame constants whose quotients
 * base/quotient_known.h gives exactly, for every point at pixel
 * coordinates x in [x_lo, x_hi] and y in [y_lo, y_hi], with the
 * constants in sh->wn and sh->wf.  A point's w is ((m3 nx + m7 ny) + a)
 * + m15 (unproject_row_fill's sums), a = m11 z the same for every point
 * (z = -1 near, 1 far).  Two cases make it one double for the frame:
 * - m3 and m7 zero (glFrustum, glOrtho, gluPerspective: their inverse's
 *   w row has no x or y term): the first sum is a zero of either sign,
 *   and ((+-0 + a) + m15) is tried with both signs;
 * - a projection with the camera multiplied in (BART's scenes), whose
 *   inverse has m3 and m7 of rounding size: a is not zero and the first
 *   sum s is smaller than half the spacing of the doubles around a (a
 *   quarter of its ulp when |a| is a power of two, whose lower neighbour
 *   is nearer), so RN(s + a) = a for every point.  |s| is at most
 *   RN(RN(|m3| NX) + RN(|m7| NY)) for NX, NY bounds on |nx|, |ny|, since
 *   rounding is monotone.
 * The dividends must lie in the helper's range (+-0 or 2^-450 <= |x| <=
 * 2^450): every term of their sums is m nx, m ny, m z or m for an entry
 * m of the inverse, with nx, ny = 2 c / size - 1 zero or of magnitude in
 * [2^-53, 2^33] (Sterbenz's lemma where 2 c / size is in [1/2, 2], at
 * least 1/2 elsewhere; |c| < 2^31).  With each entry zero or 2^-300 <=
 * |m| <= 2^300, every term is zero or a normal double with last bit at
 * least 2^-405 and magnitude at most 2^333, so their sums are zero or at
 * least 2^-405 and below 2^336.
 */
static int unproject_w_known(struct render_pass *sh, double x_lo, double x_hi, double y_lo,
                             double y_hi)
{
    const double *m = sh->inv_projection;
    const int *vp = sh->job->state->viewport;
    for (int i = 0; i < 16; i++) {
        const double a = fabs(m[i]);
        if (a != 0.0 && !(a >= 0x1p-300 && a <= 0x1p300))
            return 0;
    }
    if (!(fabs(x_lo) < 0x1p31 && fabs(x_hi) < 0x1p31 && fabs(y_lo) < 0x1p31 &&
          fabs(y_hi) < 0x1p31))
        return 0;
    double w[2];
    for (int k = 0; k < 2; k++) {
        const double a = m[11] * (k == 0 ? -1.0 : 1.0);
        if (m[3] == 0.0 && m[7] == 0.0) {
            w[k] = (0.0 + a) + m[15];
            if (quotient_known_bits(w[k]) != quotient_known_bits((-0.0 + a) + m[15]))
                return 0;
        } else {
            if (a == 0.0)
                return 0;
            const double s = fabs(m[3]) * unproject_axis_bound(x_lo, x_hi, vp[2]) +
                             fabs(m[7]) * unproject_axis_bound(y_lo, y_hi, vp[3]);
            int e;
            const double f = frexp(fabs(a), &e); /* |a| = f 2^e, ulp 2^(e - 53) */
            const double half_gap = ldexp(1.0, e - 53 - (f == 0.5 ? 2 : 1));
            if (!(s < half_gap))
                return 0;
            w[k] = a + m[15];
        }
    }
    return quotient_known_prepare(&sh->wn, w[0]) && quotient_known_prepare(&sh->wf, w[1]);
}

#if !RENDER_PAIRS
/* The near- and far-plane points under viewport position (x, y), in
 * pixels from the viewport's corner, through the inverse projection. */
static int unproject(const struct render_pass *sh, double x, double y, double near_pt[3],
                     double far_pt[3])
{
    const int *vp = sh->job->state->viewport;
    double ndc_near[3] = {2.0 * x / vp[2] - 1.0, 2.0 * y / vp[3] - 1.0, -1.0};
    double ndc_far[3] = {ndc_near[0], ndc_near[1], 1.0};
    return mat4_project(sh->inv_projection, ndc_near, near_pt) &&
           mat4_project(sh->inv_projection, ndc_far, far_pt);
}
#endif

#if RENDER_PAIRS
/* Two lanes' distances to a line along the unit vector d, a[k] being each
 * point less a point of the line: the component along d removed, then the
 * length of the rest (distances_to_line's operations in its order, so the
 * same bits). */
static inline __m128d pair_distance_to_line(const __m128d a[3], const __m128d d[3])
{
    const __m128d along = _mm_add_pd(_mm_add_pd(_mm_mul_pd(a[0], d[0]), _mm_mul_pd(a[1], d[1])),
                                     _mm_mul_pd(a[2], d[2]));
    /* The sum from 0 as distances_to_line's: 0 + perp0 perp0 is perp0
     * perp0 itself (a square is +0, positive or NaN, and +0 + +0 is +0),
     * so the first term needs no addition. */
    const __m128d perp0 = _mm_sub_pd(a[0], _mm_mul_pd(along, d[0]));
    __m128d r2 = _mm_mul_pd(perp0, perp0);
    for (int k = 1; k < 3; k++) {
        const __m128d perp = _mm_sub_pd(a[k], _mm_mul_pd(along, d[k]));
        r2 = _mm_add_pd(r2, _mm_mul_pd(perp, perp));
    }
    return _mm_sqrt_pd(r2);
}
#endif

#if RENDER_QUADS
/* pair_distance_to_line in four lanes. */
static inline __m256d quad_distance_to_line(const __m256d a[3], const __m256d d[3])
{
    const __m256d along = _mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(a[0], d[0]), _mm256_mul_pd(a[1], d[1])),
        _mm256_mul_pd(a[2], d[2]));
    const __m256d perp0 = _mm256_sub_pd(a[0], _mm256_mul_pd(along, d[0]));
    __m256d r2 = _mm256_mul_pd(perp0, perp0);
    for (int k = 1; k < 3; k++) {
        const __m256d perp = _mm256_sub_pd(a[k], _mm256_mul_pd(along, d[k]));
        r2 = _mm256_add_pd(r2, _mm256_mul_pd(perp, perp));
    }
    return _mm256_sqrt_pd(r2);
}
#endif

/* Distances from q[0..3] to the line through p along the unit vector
 * d: the same operations for each, in this order. */
static void distances_to_line(const double *const q[4], const double p[3], const double d[3],
                              double out[4])
{
#if RENDER_PAIRS
    __m128d pv[3], dv[3];
    for (int k = 0; k < 3; k++) {
        pv[k] = _mm_set1_pd(p[k]);
        dv[k] = _mm_set1_pd(d[k]);
    }
    for (int h = 0; h < 4; h += 2) {
        __m128d a[3];
        for (int k = 0; k < 3; k++)
            a[k] = _mm_sub_pd(_mm_set_pd(q[h + 1][k], q[h][k]), pv[k]);
        _mm_storeu_pd(out + h, pair_distance_to_line(a, dv));
    }
#else
    for (int i = 0; i < 4; i++) {
        double a[3] = {q[i][0] - p[0], q[i][1] - p[1], q[i][2] - p[2]};
        double along = a[0] * d[0] + a[1] * d[1] + a[2] * d[2];
        double r2 = 0.0;
        for (int k = 0; k < 3; k++) {
            double perp = a[k] - along * d[k];
            r2 += perp * perp;
        }
        out[i] = sqrt(r2);
    }
#endif
}

/*
 * Primary ray through the centre of viewport pixel (px, py): from the near
 * to the far plane through the inverse projection, as OpenGL clips.
 *
 * Its cone (shade.h) is the pixel's footprint, measured from the
 * projection itself so that any rtFrustum, rtOrtho or rtLoadMatrixd works:
 * the rays through the centres of the next pixel in x and in y pass the
 * ray's near and far points at some distances; the cone's width at the
 * near plane is the near distance, its spread the growth from near to far
 * per unit length (the angle between neighbouring rays, Akenine-Möller et
 * al. 2019 sec. 20.3.4, without assuming a symmetric perspective), 0 for
 * an orthographic projection, where the width stays one pixel.  The
 * larger of the x and y footprints is taken, as GL's rho is the larger of
 * its x and y scale factors.  When a neighbour cannot be unprojected the
 * cone is {0, 0}: unfiltered textures, as before there were cones.
 */
/*
 * Every pixel's ray needs the unprojection of its own centre and of its
 * right and lower neighbours' (the cone), which are other pixels' centres:
 * a tile keeps the unprojected centres of the row it is on and the next
 * one, so that each is computed once instead of three times, the whole
 * row as it enters the cache (a tile reads every point of its rows: its
 * pixels' and their right neighbours' column), the column's and row's
 * products once (unproject_axis).  A row is kept coordinate by
 * coordinate (struct unproject_row), so that two neighbouring points'
 * coordinate is one SSE2 pair: the row is unprojected two points at a
 * time and the rays of a 4 x 2 block are made two at a time from pairs
 * loaded whole (block_rays).  The cached point is the one a direct
 * mat4_project gives, bit for bit: unprojected at (X + 0.5, Y + 0.5) for
 * whole X, Y, and px + 0.5 + 1 is exactly (px + 1) + 0.5 in double.
 */
struct unproject_point {
    double near_pt[3], far_pt[3];
};

/* Rows y, y + 1 and y + 2 across a tile and the next column: the packet
 * loop's 4 x 2 blocks step two rows at a time and share the row between
 * two steps, the scalar loop steps one. */
#define UNPROJECT_ROWS RENDER_UNPROJECT_ROWS
/* Points of a row: the tile's columns, the next one (the last column's
 * right neighbours) and one more to make whole pairs. */
#define UNPROJECT_COLS RENDER_UNPROJECT_COLS

struct unproject_row {
    double near_pt[3][UNPROJECT_COLS], far_pt[3][UNPROJECT_COLS];
    double axis[4];                    /* unproject_axis of the row */
    signed char state[UNPROJECT_COLS]; /* 1 unprojected, -1 cannot be */
    int whole; /* 1 when all of the first RENDER_TILE_SIZE + 1 are unprojected */
};

struct unproject_cache {
    int x0, y;                                  /* viewport pixel of rows[0]'s first point */
    struct unproject_row *rows[UNPROJECT_ROWS]; /* row y + r: a ring over store */
    struct unproject_row store[UNPROJECT_ROWS];
    double col[4][UNPROJECT_COLS]; /* unproject_axis of each column, by product */
};

/* Row y of the cache's columns into u. */
static void unproject_row_fill(const struct render_pass *sh, const struct unproject_cache *c,
                               struct unproject_row *u, int y)
{
    unproject_axis(sh, 1, y + 0.5, u->axis);
#if RENDER_PAIRS
    /* mat4_project of two neighbours' near (z = -1) and far (z = 1)
     * points, a lane each: each sum in mat4_project's order, ((m0 x + m1
     * y) + m2 z) + m3, the shared first sum once; m2 z is the same
     * product for every point (multiplying by -1 or 1 is exact).  w = 0
     * needs no test of its own: a division by zero gives an infinity or a
     * NaN, which the finiteness test refuses as mat4_project's w test
     * does. */
    const double *m = sh->inv_projection;
    __m128d axis[4], zn[4], zf[4], last[4];
    for (int r = 0; r < 4; r++) {
        axis[r] = _mm_set1_pd(u->axis[r]);
        zn[r] = _mm_set1_pd(m[8 + r] * -1.0);
        zf[r] = _mm_set1_pd(m[8 + r] * 1.0);
        last[r] = _mm_set1_pd(m[12 + r]);
    }
    /* The sum of every coordinate: an infinity or a NaN makes it an
     * infinity or a NaN for good, so a finite sum means every coordinate
     * is finite (a sum that overflows only sends the row to the test
     * point by point below). */
    __m128d sum = _mm_setzero_pd();
    int first_pair = 0;
#if RENDER_QUADS
    /* Four points a lane each, the same sums in the same order; the
     * row's last pair below. */
    __m256d axis4[4], zn4[4], zf4[4], last4[4];
    for (int r = 0; r < 4; r++) {
        axis4[r] = _mm256_set1_pd(u->axis[r]);
        zn4[r] = _mm256_set1_pd(m[8 + r] * -1.0);
        zf4[r] = _mm256_set1_pd(m[8 + r] * 1.0);
        last4[r] = _mm256_set1_pd(m[12 + r]);
    }
    __m256d sum4 = _mm256_setzero_pd();
#if QUOTIENT_KNOWN_FMA
    /* w the frame's two constants (sh->w_known): each quotient by one
     * product and one FMA (base/quotient_known.h), the same doubles as
     * the division's, and no w to sum.  Every point is then finite
     * (unproject_w_known bounds the dividends below 2^336 and |w| is at
     * least 2^-300), so the finiteness sum, a chain of dependent
     * additions longer than the rest of the row's work, is not made. */
    if (sh->w_known) {
        const __m256d nh = _mm256_set1_pd(sh->wn.zh), nl = _mm256_set1_pd(sh->wn.zl);
        const __m256d fh = _mm256_set1_pd(sh->wf.zh), fl = _mm256_set1_pd(sh->wf.zl);
        for (; first_pair + 3 < UNPROJECT_COLS; first_pair += 4) {
            const int i = first_pair;
            for (int r = 0; r < 3; r++) {
                const __m256d s = _mm256_add_pd(_mm256_loadu_pd(&c->col[r][i]), axis4[r]);
                _mm256_storeu_pd(&u->near_pt[r][i],
                                 quotient_known4(_mm256_add_pd(_mm256_add_pd(s, zn4[r]), last4[r]),
                                                 nh, nl));
                _mm256_storeu_pd(&u->far_pt[r][i],
                                 quotient_known4(_mm256_add_pd(_mm256_add_pd(s, zf4[r]), last4[r]),
                                                 fh, fl));
            }
        }
        for (; first_pair < UNPROJECT_COLS; first_pair += 2) {
            const int i = first_pair;
            for (int r = 0; r < 3; r++) {
                const __m128d s = _mm_add_pd(_mm_loadu_pd(&c->col[r][i]), axis[r]);
                _mm_storeu_pd(&u->near_pt[r][i],
                              quotient_known2(_mm_add_pd(_mm_add_pd(s, zn[r]), last[r]),
                                              _mm256_castpd256_pd128(nh),
                                              _mm256_castpd256_pd128(nl)));
                _mm_storeu_pd(&u->far_pt[r][i],
                              quotient_known2(_mm_add_pd(_mm_add_pd(s, zf[r]), last[r]),
                                              _mm256_castpd256_pd128(fh),
                                              _mm256_castpd256_pd128(fl)));
            }
        }
        memset(u->state, 1, sizeof(u->state));
        u->whole = 1;
        return;
    }
#endif
    for (; first_pair + 3 < UNPROJECT_COLS; first_pair += 4) {
        const int i = first_pair;
        const __m256d s3 = _mm256_add_pd(_mm256_loadu_pd(&c->col[3][i]), axis4[3]);
        const __m256d wn = _mm256_add_pd(_mm256_add_pd(s3, zn4[3]), last4[3]);
        const __m256d wf = _mm256_add_pd(_mm256_add_pd(s3, zf4[3]), last4[3]);
        for (int r = 0; r < 3; r++) {
            const __m256d s = _mm256_add_pd(_mm256_loadu_pd(&c->col[r][i]), axis4[r]);
            const __m256d n = _mm256_div_pd(_mm256_add_pd(_mm256_add_pd(s, zn4[r]), last4[r]), wn);
            const __m256d f = _mm256_div_pd(_mm256_add_pd(_mm256_add_pd(s, zf4[r]), last4[r]), wf);
            _mm256_storeu_pd(&u->near_pt[r][i], n);
            _mm256_storeu_pd(&u->far_pt[r][i], f);
            sum4 = _mm256_add_pd(_mm256_add_pd(sum4, n), f);
        }
    }
    /* The four lanes' sums into the pair's (any order: only whether the
     * sum is finite counts). */
    sum = _mm_add_pd(_mm256_castpd256_pd128(sum4), _mm256_extractf128_pd(sum4, 1));
#endif
    for (int i = first_pair; i < UNPROJECT_COLS; i += 2) {
        const __m128d s3 = _mm_add_pd(_mm_loadu_pd(&c->col[3][i]), axis[3]);
        const __m128d wn = _mm_add_pd(_mm_add_pd(s3, zn[3]), last[3]);
        const __m128d wf = _mm_add_pd(_mm_add_pd(s3, zf[3]), last[3]);
        for (int r = 0; r < 3; r++) {
            const __m128d s = _mm_add_pd(_mm_loadu_pd(&c->col[r][i]), axis[r]);
            const __m128d n = _mm_div_pd(_mm_add_pd(_mm_add_pd(s, zn[r]), last[r]), wn);
            const __m128d f = _mm_div_pd(_mm_add_pd(_mm_add_pd(s, zf[r]), last[r]), wf);
            _mm_storeu_pd(&u->near_pt[r][i], n);
            _mm_storeu_pd(&u->far_pt[r][i], f);
            sum = _mm_add_pd(_mm_add_pd(sum, n), f);
        }
    }
    /* x - x is 0 for a finite x, NaN for an infinity or a NaN. */
    if (_mm_movemask_pd(_mm_cmpeq_pd(_mm_sub_pd(sum, sum), _mm_setzero_pd())) == 3) {
        memset(u->state, 1, sizeof(u->state));
        u->whole = 1;
        return;
    }
    for (int i = 0; i < UNPROJECT_COLS; i++) {
        int ok = 1;
        for (int r = 0; r < 3; r++)
            ok &= isfinite(u->near_pt[r][i]) && isfinite(u->far_pt[r][i]);
        u->state[i] = ok ? 1 : -1;
    }
#else
    for (int i = 0; i < UNPROJECT_COLS; i++) {
        /* Zero where mat4_project writes nothing (w = 0): never read. */
        double near_pt[3] = {0.0, 0.0, 0.0}, far_pt[3] = {0.0, 0.0, 0.0};
        const int ok = unproject(sh, c->x0 + i + 0.5, y + 0.5, near_pt, far_pt);
        for (int r = 0; r < 3; r++) {
            u->near_pt[r][i] = near_pt[r];
            u->far_pt[r][i] = far_pt[r];
        }
        u->state[i] = ok ? 1 : -1;
    }
#endif
    u->whole = 1;
    for (int i = 0; i <= RENDER_TILE_SIZE; i++)
        u->whole &= u->state[i] > 0;
}

static void unproject_cache_init(const struct render_pass *sh, struct unproject_cache *c,
                                 int x0, int y)
{
    c->x0 = x0;
    c->y = y;
    double col[4];
    for (int i = 0; i < UNPROJECT_COLS; i++) {
        unproject_axis(sh, 0, x0 + i + 0.5, col);
        for (int r = 0; r < 4; r++)
            c->col[r][i] = col[r];
    }
    for (int r = 0; r < UNPROJECT_ROWS; r++) {
        c->rows[r] = &c->store[r];
        unproject_row_fill(sh, c, c->rows[r], y + r);
    }
}

/* Moves the cache's first row to y, keeping the rows it already has from
 * y on (the ring turns; the rows it frees take the new ones). */
static void unproject_cache_row(const struct render_pass *sh, struct unproject_cache *c, int y)
{
    const int shift = y - c->y;
    if (shift == 0)
        return;
    int keep = 0;
    if (shift > 0 && shift < UNPROJECT_ROWS) {
        struct unproject_row *old[UNPROJECT_ROWS];
        memcpy(old, c->rows, sizeof(old));
        for (int r = 0; r < UNPROJECT_ROWS; r++)
            c->rows[r] = old[(r + shift) % UNPROJECT_ROWS];
        keep = UNPROJECT_ROWS - shift;
    }
    c->y = y;
    for (int r = keep; r < UNPROJECT_ROWS; r++)
        unproject_row_fill(sh, c, c->rows[r], y + r);
}

/* The unprojected centre of pixel (x, y) into p, with x - x0 in
 * [0, RENDER_TILE_SIZE] and y - (the cache's row) in [0, UNPROJECT_ROWS);
 * 0 when it cannot be unprojected. */
static int unproject_cached(const struct unproject_cache *c, int x, int y,
                            struct unproject_point *p)
{
    const struct unproject_row *u = c->rows[y - c->y];
    const int i = x - c->x0;
    if (u->state[i] < 0)
        return 0;
    for (int r = 0; r < 3; r++) {
        p->near_pt[r] = u->near_pt[r][i];
        p->far_pt[r] = u->far_pt[r][i];
    }
    return 1;
}

static int primary_ray(const struct unproject_cache *cache, int px, int py, float org[3],
                       float dir[3], float *tmax, struct shade_cone *cone)
{
    struct unproject_point centre, right, below;
    if (!unproject_cached(cache, px, py, &centre))
        return 0;
    const double *near_pt = centre.near_pt, *far_pt = centre.far_pt;
    double d[3] = {far_pt[0] - near_pt[0], far_pt[1] - near_pt[1], far_pt[2] - near_pt[2]};
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(len > 0.0) || !isfinite(len))
        return 0;
#if RENDER_PAIRS
    /* x and y divided in one pair: the same quotients. */
    _mm_storeu_pd(d, _mm_div_pd(_mm_loadu_pd(d), _mm_set1_pd(len)));
    d[2] /= len;
#else
    for (int k = 0; k < 3; k++)
        d[k] /= len;
#endif
    for (int k = 0; k < 3; k++) {
        org[k] = (float)near_pt[k];
        dir[k] = (float)d[k];
    }
    *tmax = (float)len;
    /* The spread is the larger growth over len: one division, as the
     * larger of the two quotients is the quotient of the larger (a
     * correctly rounded division by len > 0 keeps the order). */
    double width = 0.0, growth = 0.0, spread = 0.0;
    if (unproject_cached(cache, px + 1, py, &right) &&
        unproject_cached(cache, px, py + 1, &below)) {
        /* The neighbours' near distances, then their far ones, x first. */
        const double *const q[4] = {right.near_pt, below.near_pt, right.far_pt, below.far_pt};
        double dist[4]; /* near x, near y, far x, far y */
        distances_to_line(q, near_pt, d, dist);
        for (int axis = 0; axis < 2; axis++) {
            width = mat4_fmax_left(width, dist[axis]);
            growth = mat4_fmax_left(growth, dist[2 + axis] - dist[axis]);
        }
        spread = growth / len;
    }
    cone->width = (float)width;
    cone->spread = (float)spread;
    return 1;
}

#if RENDER_PAIRS
/* Two doubles as two floats (the low half), each rounded as a cast
 * does. */
static inline __m128 floats2(__m128d v)
{
    return _mm_cvtpd_ps(v);
}

/* Two points given coordinate by coordinate (the low halves of x, y, z)
 * into out[2][3]. */
static inline void store_points2(float *out, __m128 x, __m128 y, __m128 z)
{
    const __m128 yz = _mm_unpacklo_ps(y, z);                          /* y0 z0 y1 z1 */
    const __m128 xxyz = _mm_shuffle_ps(x, yz, _MM_SHUFFLE(1, 0, 1, 0)); /* x0 x1 y0 z0 */
    _mm_storeu_ps(out, _mm_shuffle_ps(xxyz, xxyz, _MM_SHUFFLE(1, 3, 2, 0))); /* x0 y0 z0 x1 */
    _mm_storeh_pi((__m64 *)(out + 4), yz);                                /* y1 z1 */
}

/* The cone's two floats are stored as a pair of lanes (ray_pair). */
typedef char render_cone_is_two_floats[sizeof(struct shade_cone) == 2 * sizeof(float) ? 1 : -1];

/* primary_ray of the pixels at points i and i + 1 of cache row a (b the
 * row below) in the two lanes, lane 0 the left one, written straight
 * into the packet's rays first and first + 1 and their cones: each lane
 * primary_ray's operations on its points in its order, so the same
 * floats.  Every point it reads must be unprojected.  Returns the mask of
 * the lanes whose length is positive and finite; the others leave
 * primary_ray's common path, and what was written for them is to be
 * made again by primary_ray. */
static inline int ray_pair(const struct unproject_row *a, const struct unproject_row *b, int i,
                           struct trace_packet *pk, int first, struct shade_cone cone[])
{
    __m128d p[3], d[3];
    for (int k = 0; k < 3; k++) {
        p[k] = _mm_loadu_pd(&a->near_pt[k][i]);
        d[k] = _mm_sub_pd(_mm_loadu_pd(&a->far_pt[k][i]), p[k]);
    }
    store_points2(&pk->org[first][0], floats2(p[0]), floats2(p[1]), floats2(p[2]));
    const __m128d len = _mm_sqrt_pd(_mm_add_pd(
        _mm_add_pd(_mm_mul_pd(d[0], d[0]), _mm_mul_pd(d[1], d[1])), _mm_mul_pd(d[2], d[2])));
    /* len > 0 and finite: 0 < len < infinity, false for a NaN. */
    const int ok = _mm_movemask_pd(_mm_and_pd(_mm_cmpgt_pd(len, _mm_setzero_pd()),
                                              _mm_cmplt_pd(len, _mm_set1_pd(INFINITY))));
    _mm_storel_pi((__m64 *)&pk->tmax[first], floats2(len));
    for (int k = 0; k < 3; k++)
        d[k] = _mm_div_pd(d[k], len);
    store_points2(&pk->dir[first][0], floats2(d[0]), floats2(d[1]), floats2(d[2]));
    /* distances_to_line of the neighbours' near points (h = 0: right, 1:
     * below), then of their far points (h = 2, 3). */
    __m128d dist[4];
    for (int h = 0; h < 4; h++) {
        const struct unproject_row *q = h % 2 ? b : a;
        const int at = h % 2 ? i : i + 1;
        __m128d v[3];
        for (int k = 0; k < 3; k++)
            v[k] = _mm_sub_pd(_mm_loadu_pd(h < 2 ? &q->near_pt[k][at] : &q->far_pt[k][at]),
                              p[k]);
        dist[h] = pair_distance_to_line(v, d);
    }
    /* mat4_fmax_left(x, y) = y > x ? y : x is maxpd with y first (it gives its
     * first operand when greater, else its second, also for NaNs and
     * zeros: Intel SDM, MAXPD), from 0, x before y. */
    const __m128d zero = _mm_setzero_pd();
    const __m128d width = _mm_max_pd(dist[1], _mm_max_pd(dist[0], zero));
    const __m128d growth = _mm_max_pd(_mm_sub_pd(dist[3], dist[1]),
                                      _mm_max_pd(_mm_sub_pd(dist[2], dist[0]), zero));
    const __m128d spread = _mm_div_pd(growth, len);
    _mm_storeu_ps((float *)&cone[first], _mm_unpacklo_ps(floats2(width), floats2(spread)));
    return ok;
}

#if RENDER_QUADS
/*
 * Eight points given coordinate by coordinate (x, y, z; lane r point r)
 * into out[8][3] as three 32-byte stores, the three rows the walk's
 * set-up loads (trace/packet_init.h, packet_init_soa3, whose transpose
 * this inverts: x of point r at float 3 r, so at position 3 r mod 8 of
 * its row, which a permutation by 3 p mod 8 (3 is its own inverse mod 8)
 * and two blends a row put there, y and z likewise one and two floats
 * on).  A load that spans two smaller stores still in the store buffer is
 * not forwarded from them and waits until both have reached the cache
 * (Intel's optimization manual, store forwarding), so with 16-byte
 * stores of four points each the walk's first loads waited for the
 * block's whole ray generation, its cones included, to retire.  The
 * packet holds eight rays (a block), stored as 24 floats a field.
 */
typedef char render_packet_is_eight[TRACE_PACKET == 8 ? 1 : -1];

static inline void store_points8(float *out, __m256 x, __m256 y, __m256 z)
{
    const __m256 xp = _mm256_permutevar8x32_ps(x, _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5));
    const __m256 yp = _mm256_permutevar8x32_ps(y, _mm256_setr_epi32(5, 0, 3, 6, 1, 4, 7, 2));
    const __m256 zp = _mm256_permutevar8x32_ps(z, _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7));
    /* Row 0: x y z x y z x y; row 1: z x y z x y z x; row 2: y z x y z x
     * y z. */
    _mm256_storeu_ps(out, _mm256_blend_ps(_mm256_blend_ps(xp, yp, 0x92), zp, 0x24));
    _mm256_storeu_ps(out + 8, _mm256_blend_ps(_mm256_blend_ps(zp, xp, 0x92), yp, 0x24));
    _mm256_storeu_ps(out + 16, _mm256_blend_ps(_mm256_blend_ps(yp, zp, 0x92), xp, 0x24));
}

/* Two quads' lanes (lo for points 0 to 3) as eight. */
static inline __m256 floats8(__m128 lo, __m128 hi)
{
    return _mm256_insertf128_ps(_mm256_castps128_ps256(lo), hi, 1);
}

/* ray_pair of the four pixels at points i to i + 3 of row a in the four
 * lanes, lane 0 the leftmost: each lane primary_ray's operations in its
 * order.  The origins and directions as floats by component into org_f
 * and dir_f (the caller stores a block's eight, store_points8), the
 * directions and cones also by component into rays (the eye light's
 * lanes read them so; the same floats).  Returns the mask of the lanes
 * whose length is positive and finite. */
static inline int ray_quad(const struct unproject_row *a, const struct unproject_row *b, int i,
                           struct trace_packet *pk, int first, struct shade_cone cone[],
                           struct shade_eye_rays *rays, __m128 org_f[3], __m128 dir_f[3])
{
    __m256d p[3], d[3];
    for (int k = 0; k < 3; k++) {
        p[k] = _mm256_loadu_pd(&a->near_pt[k][i]);
        d[k] = _mm256_sub_pd(_mm256_loadu_pd(&a->far_pt[k][i]), p[k]);
        org_f[k] = _mm256_cvtpd_ps(p[k]);
    }
    const __m256d len = _mm256_sqrt_pd(
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(d[0], d[0]), _mm256_mul_pd(d[1], d[1])),
                      _mm256_mul_pd(d[2], d[2])));
    const int ok = _mm256_movemask_pd(
        _mm256_and_pd(_mm256_cmp_pd(len, _mm256_setzero_pd(), _CMP_GT_OQ),
                      _mm256_cmp_pd(len, _mm256_set1_pd(INFINITY), _CMP_LT_OQ)));
    _mm_storeu_ps(&pk->tmax[first], _mm256_cvtpd_ps(len));
    for (int k = 0; k < 3; k++) {
        d[k] = _mm256_div_pd(d[k], len);
        dir_f[k] = _mm256_cvtpd_ps(d[k]);
        _mm_storeu_ps(&rays->dir[k][first], dir_f[k]);
    }
    __m256d dist[4];
    for (int h = 0; h < 4; h++) {
        const struct unproject_row *q = h % 2 ? b : a;
        const int at = h % 2 ? i : i + 1;
        __m256d v[3];
        for (int k = 0; k < 3; k++)
            v[k] = _mm256_sub_pd(
                _mm256_loadu_pd(h < 2 ? &q->near_pt[k][at] : &q->far_pt[k][at]), p[k]);
        dist[h] = quad_distance_to_line(v, d);
    }
    /* max_left as vmaxpd with y first, as maxpd in ray_pair. */
    const __m256d zero = _mm256_setzero_pd();
    const __m256d width = _mm256_max_pd(dist[1], _mm256_max_pd(dist[0], zero));
    const __m256d growth = _mm256_max_pd(_mm256_sub_pd(dist[3], dist[1]),
                                         _mm256_max_pd(_mm256_sub_pd(dist[2], dist[0]), zero));
    const __m256d spread = _mm256_div_pd(growth, len);
    const __m128 w = _mm256_cvtpd_ps(width), sp = _mm256_cvtpd_ps(spread);
    _mm_storeu_ps(&rays->width[first], w);
    _mm_storeu_ps(&rays->spread[first], sp);
    _mm_storeu_ps((float *)&cone[first], _mm_unpacklo_ps(w, sp));
    _mm_storeu_ps((float *)&cone[first + 2], _mm_unpackhi_ps(w, sp));
    return ok;
}
#endif

/* What block_rays writes beside the packet: the rays by component
 * where the AVX2 copy's eye light reads them (shade.h), else nothing. */
#if RENDER_QUADS
struct block_lanes {
    struct shade_eye_rays rays;
};
#else
struct block_lanes {
    char unused;
};
#endif

/* The rays of the 4 x 2 block whose first pixel is point i of the
 * cache's first row (rows 0 to 2 whole) straight into the packet and the
 * cones: primary_ray's rays and cones.  Returns 0 when one would leave
 * primary_ray's common path (the packet then holds some rays of this
 * block, some not, and its mask is not set). */
static inline int block_rays(const struct unproject_cache *c, int i, struct trace_packet *pk,
                             struct shade_cone cone[], struct block_lanes *lanes)
{
#if RENDER_QUADS
    /* A block row a quad; the packet's points and tmins in the walk's
     * loads' widths (store_points8). */
    __m128 org0[3], dir0[3], org1[3], dir1[3];
    const int ok = ray_quad(c->rows[0], c->rows[1], i, pk, 0, cone, &lanes->rays, org0, dir0) &
                   ray_quad(c->rows[1], c->rows[2], i, pk, 4, cone, &lanes->rays, org1, dir1);
    store_points8(&pk->org[0][0], floats8(org0[0], org1[0]), floats8(org0[1], org1[1]),
                  floats8(org0[2], org1[2]));
    store_points8(&pk->dir[0][0], floats8(dir0[0], dir1[0]), floats8(dir0[1], dir1[1]),
                  floats8(dir0[2], dir1[2]));
    _mm256_storeu_ps(pk->tmin, _mm256_setzero_ps());
    return ok == 15;
#else
    (void)lanes;
    /* Written out pair by pair: constant offsets into the packet. */
    const int ok = ray_pair(c->rows[0], c->rows[1], i, pk, 0, cone) &
                   ray_pair(c->rows[0], c->rows[1], i + 2, pk, 2, cone) &
                   ray_pair(c->rows[1], c->rows[2], i, pk, 4, cone) &
                   ray_pair(c->rows[1], c->rows[2], i + 2, pk, 6, cone);
    for (int k = 0; k < TRACE_PACKET; k += 4)
        _mm_storeu_ps(&pk->tmin[k], _mm_setzero_ps());
    return ok == 3;
#endif
}
#endif

void render_framebuffer_release(struct render_framebuffer *fb)
{
    rt_free(fb->rgba);
    rt_free(fb->spare);
    memset(fb, 0, sizeof(*fb));
}

/* 1 when an instance of the committed frame has lines or points, or
 * triangles that may be drawn as either (rtPolygonMode), or is
 * rasterised (scene_instance.overlay): the depth buffer is needed. */
static int frame_has_lines(const struct scene_frame *frame)
{
    for (uint32_t i = 0; i < frame->committed.count; i++)
        if (scene_lines_nonempty(&frame->committed.items[i].object->mesh.lines) ||
            raster_polygons_present(&frame->committed.items[i]) ||
            frame->committed.items[i].overlay)
            return 1;
    return 0;
}

/* 1 when some instance was drawn under a clip plane: only then does a
 * primary hit look its instance's planes up (blend.c). */
static int frame_has_clip(const struct scene_frame *frame)
{
    for (uint32_t i = 0; i < frame->committed.count; i++)
        if (frame->committed.items[i].appearance.clip.enabled)
            return 1;
    return 0;
}

/* 1 when some instance was drawn with RT_BLEND or RT_ALPHA_TEST: only
 * then does a primary hit look its instance's raster state up (blend.c),
 * so a frame without them costs nothing per ray. */
static int frame_has_see_through(const struct scene_frame *frame)
{
    for (uint32_t i = 0; i < frame->committed.count; i++)
        if (scene_raster_see_through(&frame->committed.items[i].appearance.raster))
            return 1;
    return 0;
}

/* 1 when some instance was drawn with RT_POLYGON_OFFSET_FILL. */
static int frame_has_offset(const struct scene_frame *frame)
{
    for (uint32_t i = 0; i < frame->committed.count; i++)
        if (frame->committed.items[i].appearance.raster.offset_fill)
            return 1;
    return 0;
}

/* The clear colour into every pixel of fb, or with `all_tiles` (every
 * tile will be rendered, as render_frame does) into those the tiles do
 * not write: all of them when there are no tiles, else those left of and
 * below the viewport (its origin is never negative, api/frame.c), since
 * a tile writes each of its pixels, the clear colour where no ray is
 * made. */
static void clear_outside_tiles(const struct render_pass *pass, float *fb, size_t pixels,
                                int all_tiles)
{
    const struct render_state *st = pass->job->state;
    const int *vp = st->viewport;
    if (!all_tiles || render_pass_tiles(pass) == 0) {
        for (size_t i = 0; i < pixels; i++)
            memcpy(&fb[4 * i], st->clear_color, 4 * sizeof(float));
        return;
    }
    const size_t w = (size_t)pass->fb_width;
    for (size_t i = 0; i < (size_t)vp[1] * w; i++)
        memcpy(&fb[4 * i], st->clear_color, 4 * sizeof(float));
    for (size_t y = (size_t)vp[1]; y < (size_t)pass->fb_height; y++)
        for (size_t x = 0; x < (size_t)vp[0]; x++)
            memcpy(&fb[4 * (y * w + x)], st->clear_color, 4 * sizeof(float));
}

/* render_pass_begin into `storage` (fb_width x fb_height pixels, owned
 * by the pass from here on) when not NULL: a spare image, whose pixels
 * are all overwritten, so it needs no zeroing; all_tiles as
 * clear_outside_tiles. */
static int pass_begin(struct render_pass *pass, const struct render_job *job, int fb_width,
                      int fb_height, float *storage, int all_tiles)
{
    const struct render_state *st = job->state;
    size_t pixels = (size_t)fb_width * (size_t)fb_height;
    float *fb = storage ? storage : rt_malloc((pixels ? pixels : 1) * 4 * sizeof(float));
    if (!fb)
        return -1;
    if (shared_init(pass, job)) {
        rt_free(fb);
        return -1;
    }
    pass->clipping = frame_has_clip(job->frame);
    pass->see_through = frame_has_see_through(job->frame);
    pass->all_drawn = gl_frame_all_drawn(job->frame);
    /* Only Whitted shading traces shadow, reflected and refracted rays;
     * they pass what clip planes, the alpha test, see-through blending and
     * faces drawn as lines or points take out of the picture. */
    if (st->shading == RENDER_WHITTED &&
        (pass->clipping || pass->see_through || filled_frame_has_unfilled(job->frame)) &&
        secondary_marks(job->frame,
                        SECONDARY_CLIP | SECONDARY_ALPHA | SECONDARY_BLEND | SECONDARY_UNFILLED,
                        &pass->secondary)) {
        rt_free(fb);
        rt_free(pass->counters);
        return -1;
    }
    if (frame_has_lines(job->frame)) {
        pass->depth = rt_malloc((pixels ? pixels : 1) * sizeof(*pass->depth));
        if (!pass->depth) {
            rt_free(fb);
            rt_free(pass->counters);
            return -1;
        }
        for (size_t i = 0; i < pixels; i++)
            pass->depth[i] = 1.0;
        if (frame_has_offset(job->frame)) {
            pass->depth_state = rt_calloc(pixels ? pixels : 1, sizeof(*pass->depth_state));
            if (!pass->depth_state) {
                rt_free(pass->depth);
                pass->depth = NULL;
                rt_free(fb);
                rt_free(pass->counters);
                return -1;
            }
        }
    }
    pass->fb = fb;
    pass->fb_width = fb_width;
    pass->fb_height = fb_height;
    /* The ties walk (trace_scene_ties: blend.c's layers and clipped
     * hits, gl_shade.c's undrawn faces) and the hit filter's walk
     * (secondary rays past what GL removed) read the binary tree. */
    pass->reads_binary |= pass->clipping || pass->see_through || !pass->all_drawn ||
                          pass->secondary != NULL;
    pass->tiles_x = (st->viewport[2] + RENDER_TILE_SIZE - 1) / RENDER_TILE_SIZE;
    pass->tiles_y = (st->viewport[3] + RENDER_TILE_SIZE - 1) / RENDER_TILE_SIZE;
    /* A singular projection leaves every pixel at the clear colour. */
    pass->projectable = mat4_invert(pass->inv_projection, st->projection);
    /* Every pixel centre a tile's cache unprojects (its columns and the
     * next two, its rows and the next two), with a tile's margin. */
    pass->w_known =
        pass->projectable &&
        unproject_w_known(pass, 0.5 - RENDER_TILE_SIZE,
                          (double)(pass->tiles_x + 1) * RENDER_TILE_SIZE + 0.5,
                          0.5 - RENDER_TILE_SIZE, (double)(pass->tiles_y + 1) * RENDER_TILE_SIZE + 0.5);
    clear_outside_tiles(pass, fb, pixels, all_tiles);
    return 0;
}

int render_pass_begin(struct render_pass *pass, const struct render_job *job, int fb_width,
                      int fb_height)
{
    return pass_begin(pass, job, fb_width, fb_height, NULL, 0);
}

uint32_t render_pass_tiles(const struct render_pass *pass)
{
    if (!pass->projectable || pass->tiles_x <= 0 || pass->tiles_y <= 0)
        return 0;
    return (uint32_t)pass->tiles_x * (uint32_t)pass->tiles_y;
}


/* Pixel i of the 4 x 2 block at (bx, by) of the tile at (x0, y0): 1 when
 * it is inside the tile and the viewport. */
static int block_pixel_inside(const int *vp, int x0, int y0, int bx, int by, int i)
{
    const int x = bx + i % RENDER_BLOCK_W, y = by + i / RENDER_BLOCK_W;
    return x < x0 + RENDER_TILE_SIZE && x < vp[2] && y < y0 + RENDER_TILE_SIZE && y < vp[3];
}

/* The eye light's direct hits of a block, shaded together
 * (shade_eye_hits: their texture levels of detail two at a time). */
struct eye_batch {
    const float *dir[TRACE_PACKET];
    const struct trace_scene_hit *hit[TRACE_PACKET];
    struct shade_cone cone[TRACE_PACKET];
    float *px[TRACE_PACKET];
    int n;
};

static void eye_batch_add(struct eye_batch *b, const float *dir,
                          const struct trace_scene_hit *hit, struct shade_cone cone, float *px)
{
    b->dir[b->n] = dir;
    b->hit[b->n] = hit;
    b->cone[b->n] = cone;
    b->px[b->n++] = px;
}

static void eye_batch_shade(const struct shade_context *sc, const struct eye_batch *b)
{
    if (b->n)
        shade_eye_hits(sc, b->n, b->dir, b->hit, b->cone, b->px);
}

/* The pixels of a traced block (render_tile_packets) in the eye light's
 * direct case with every hit drawn: the block's hits shaded together
 * (shade_eye_hits), the clear colour where a ray hit nothing or none was
 * made, and the window depth where the frame keeps one, as the general
 * loop writes them. */
static void eye_block(struct render_pass *pass, struct shade_context *sc, int x0, int y0,
                      int bx, int by, const struct trace_packet *pk, unsigned found,
                      const struct trace_scene_hit hits[TRACE_PACKET],
                      const struct shade_cone cone[TRACE_PACKET])
{
    const struct render_state *st = pass->job->state;
    const int *vp = st->viewport;
    struct eye_batch eyes = {.n = 0};
    for (int i = 0; i < TRACE_PACKET; i++) {
        if (!block_pixel_inside(vp, x0, y0, bx, by, i))
            continue;
        const int x = bx + i % RENDER_BLOCK_W, y = by + i / RENDER_BLOCK_W;
        const size_t at = (size_t)(vp[1] + y) * pass->fb_width + vp[0] + x;
        float *px = &pass->fb[4 * at];
        if (!(pk->active >> i & 1u)) {
            memcpy(px, st->clear_color, 4 * sizeof(float));
            continue;
        }
        float t_first;
        if (!(found >> i & 1u)) {
            memcpy(px, st->clear_color, 4 * sizeof(float));
            t_first = INFINITY;
        } else {
            eye_batch_add(&eyes, pk->dir[i], &hits[i], cone[i], px);
            t_first = hits[i].t;
        }
        if (pass->depth)
            pass->depth[at] = raster_window_depth(st->projection, pk->org[i], pk->dir[i], t_first);
    }
    eye_batch_shade(sc, &eyes);
}

/* The camera rays of the 4 x 2 block at (bx, by) of the tile at (x0, y0)
 * into the packet and the cones, its active mask set: the whole block in
 * lanes (block_rays; beside the packet in by_lane) when its block row can
 * (lanes: block_row_lanes) and the block lies inside the tile and the
 * viewport, else pixel by pixel (primary_ray) for the pixels inside.
 * Returns 1 in the first case: every pixel's ray made, the block whole. */
struct block_lanes;
static int block_camera_rays(const struct unproject_cache *cache, const int *vp, int x0, int y0,
                             int bx, int by, int lanes, struct trace_packet *pk,
                             struct shade_cone cone[TRACE_PACKET], struct block_lanes *by_lane)
{
#if RENDER_PAIRS
    if (lanes && bx + RENDER_BLOCK_W <= x0 + RENDER_TILE_SIZE && bx + RENDER_BLOCK_W <= vp[2] &&
        block_rays(cache, bx - x0, pk, cone, by_lane)) {
        pk->active = (1u << TRACE_PACKET) - 1u;
        return 1;
    }
#else
    (void)lanes;
    (void)by_lane;
#endif
    pk->active = 0;
    for (int i = 0; i < TRACE_PACKET; i++) {
        const int x = bx + i % RENDER_BLOCK_W, y = by + i / RENDER_BLOCK_W;
        if (block_pixel_inside(vp, x0, y0, bx, by, i) &&
            primary_ray(cache, x, y, pk->org[i], pk->dir[i], &pk->tmax[i], &cone[i])) {
            pk->tmin[i] = 0.0f;
            pk->active |= 1u << i;
        }
    }
    return 0;
}

#if RENDER_PAIRS
/* Whether the blocks of the block row at by of the tile at (x0, y0) can
 * take their rays in lanes (block_camera_rays): both rows inside and
 * every point of the rows and the next one unprojected. */
static int block_row_lanes(const struct unproject_cache *cache, const int *vp, int y0, int by)
{
    return by + RENDER_BLOCK_H <= y0 + RENDER_TILE_SIZE && by + RENDER_BLOCK_H <= vp[3] &&
           cache->rows[0]->whole && cache->rows[1]->whole && cache->rows[2]->whole;
}
#endif

/* The framebuffer pixels of the whole 4 x 2 block at (bx, by), in the
 * packet's ray order. */
static void block_pixels(const struct render_pass *pass, int bx, int by,
                         float *px[TRACE_PACKET])
{
    const int *vp = pass->job->state->viewport;
    float *row = &pass->fb[4 * ((size_t)(vp[1] + by) * pass->fb_width + (size_t)(vp[0] + bx))];
    for (int i = 0; i < RENDER_BLOCK_W; i++) {
        px[i] = row + 4 * i;
        px[RENDER_BLOCK_W + i] = row + 4 * ((size_t)pass->fb_width + (size_t)i);
    }
}

#if defined(RENDER_UNIT_AVX2)
/* A software pipeline of one block (Lam 1988, software pipelining; here
 * across a tile's blocks): a whole block's texel lines are asked for when
 * its hits are known (shade_eye_block_begin: their addresses, a
 * prefetch) and its texels loaded and blended into its pixels after the
 * next block's (shade_eye_block_end), so that the core works on the next
 * block while the texels come into the cache, instead of waiting for
 * them in the block's shading.  Two slots: the block begun and the one
 * before it.  Only the order in which pixels are written changes; each
 * pixel's operations are the same. */
struct eye_pipeline {
    struct shade_eye_pending pending[2];
    int slot; /* the slot the next block begins in */
    int full; /* the other slot holds a block to end */
};

/* A whole block of hits into the pipeline: its prefetches, then the last
 * block's texels. */
static void eye_pipeline_block(const struct shade_context *sc, struct eye_pipeline *p,
                               const float *const dirs[], const struct shade_eye_rays *rays,
                               const struct trace_scene_hit *const hits[], float *const px[])
{
    const int begun = RENDER_EYE_BLOCK_BEGIN(sc, dirs, rays, hits, px, &p->pending[p->slot]);
    if (p->full)
        RENDER_EYE_BLOCK_END(sc, &p->pending[p->slot ^ 1]);
    p->full = begun;
    p->slot ^= begun;
}

/* The last block's texels, at the tile's end. */
static void eye_pipeline_finish(const struct shade_context *sc, struct eye_pipeline *p)
{
    if (p->full)
        RENDER_EYE_BLOCK_END(sc, &p->pending[p->slot ^ 1]);
    p->full = 0;
}
#endif

#if RENDER_TILE_TRACED_FIRST
/* A block of render_tile_eye_traced_first's tile: its rays (packet,
 * cones, the lanes' copy), its hits and where it lies. */
struct traced_block {
    struct trace_packet pk;
    struct shade_cone cone[TRACE_PACKET];
    struct trace_scene_hit hits[TRACE_PACKET];
    struct block_lanes lanes;
    unsigned found;
    int whole, bx, by;
};

/*
 * render_tile_packets' eye-light tile when every hit is drawn and the
 * frame keeps no depth (its common case, the loop below it otherwise):
 * first every block's rays and walk, then every block's shading, in the
 * same block order, each block through the same steps (block_rays or
 * primary_ray, trace_scene_closest_packet, then the one-block pipeline
 * of shade_eye_block_begin / end or eye_block), so every pixel is the
 * same; only the order in which the blocks' steps run changes.
 *
 * Why: the frame's loop ran a block's ray generation, walk and shading
 * one after the other, some 55 KB of code hot in each block's pass (the
 * walk's hot lines 15 KB, the shading's surface_fetch_lanes 5 KB,
 * fetch_lanes_mixed 8 KB, the ray generation, the texture set-up), where
 * the bare rays' loop runs 27 KB: the 32 KB L1i of Zen 3 (as of Zen 2,
 * Zen 4 and Intel's recent cores) held neither half across the other.
 * Callgrind, this core's caches (`--D1=32768,8,64 --LL=524288,8,64`),
 * six kitchen eye-light frames: L1i misses 57.1 M with a block at a
 * time against 1.7 M for five bare passes; tracing the tile's 32 blocks
 * first, 11.0 M, and the L1d read misses 19.9 M -> 10.6 M (the walk's
 * nodes and the shading's triangles stay in the cache from one block to
 * the next), for 0.35 % more instructions.  Fastest-run ratio of
 * `rtbench frame-overhead --runs 15 --thread-clock --threads 1`, six
 * quads at load 1-2: lower in four, by 0.034 on average (about 3 % of
 * the frame; the clock's spread is as wide).  The AVX-512 copy on a Zen 4
 * core (32 KB L1i as well), the same command, four quads at load 5:
 * lower in all four, 1.494 -> 1.461 on average (the median-run ratio
 * 1.495 -> 1.44).  The tile's blocks take some 21 KB of stack a 16x16
 * tile, 85 KB a 32x32 one (RENDER_TILE_SIZE), written by the walks and
 * read by the shading.  The camera rays of all the
 * tile's blocks are made before the first walk (see below; about 1.7-2 ms of
 * the 71 ms kitchen frame on a Zen 4, performance-log.md, round 63, zs2).
 */
static void render_tile_eye_traced_first(struct render_pass *pass, struct shade_context *sc,
                                         int x0, int y0)
{
    const struct render_state *st = pass->job->state;
    const int *vp = st->viewport;
    struct unproject_cache cache;
    unproject_cache_init(pass, &cache, x0, y0);
    struct traced_block blocks[(RENDER_TILE_SIZE / RENDER_BLOCK_H) *
                               (RENDER_TILE_SIZE / RENDER_BLOCK_W)];
    int n = 0;
    for (int by = y0; by < y0 + RENDER_TILE_SIZE && by < vp[3]; by += RENDER_BLOCK_H) {
        unproject_cache_row(pass, &cache, by);
        const int lanes = block_row_lanes(&cache, vp, y0, by);
        for (int bx = x0; bx < x0 + RENDER_TILE_SIZE && bx < vp[2]; bx += RENDER_BLOCK_W) {
            struct traced_block *b = &blocks[n++];
            b->bx = bx;
            b->by = by;
            b->whole =
                block_camera_rays(&cache, vp, x0, y0, bx, by, lanes, &b->pk, b->cone, &b->lanes);
        }
    }
    /* The tile's camera rays all made before the first is traced: a
     * block's rays are one chain of long latencies (the length's square
     * root, the divisions by it, the cone's square roots, the spread's
     * division; perf puts the samples after them), exposed between two
     * walks; made in a row, the blocks' chains are independent and
     * overlap, bound then by the divider's throughput, and the
     * generation's code runs once a tile instead of alternating with the
     * walk's (the L1i misses above).  Making them only one to four
     * blocks ahead of the walk bought nothing (performance-log.md, round
     * 63, zs2).  The same rays, traced in the same order. */
    for (int j = 0; j < n; j++) {
        struct traced_block *b = &blocks[j];
        b->found = trace_scene_closest_packet(sc->scene, &b->pk, b->hits, sc->counters);
    }
    struct eye_pipeline pipe = {.slot = 0, .full = 0};
    for (int j = 0; j < n; j++) {
        const struct traced_block *b = &blocks[j];
        if (!b->whole || b->found != b->pk.active) {
            eye_block(pass, sc, x0, y0, b->bx, b->by, &b->pk, b->found, b->hits, b->cone);
            continue;
        }
        const float *dirs[TRACE_PACKET];
        const struct trace_scene_hit *hits[TRACE_PACKET];
        float *px[TRACE_PACKET];
        for (int i = 0; i < TRACE_PACKET; i++) {
            dirs[i] = b->pk.dir[i];
            hits[i] = &b->hits[i];
        }
        block_pixels(pass, b->bx, b->by, px);
        eye_pipeline_block(sc, &pipe, dirs, &b->lanes.rays, hits, px);
    }
    eye_pipeline_finish(sc, &pipe);
}
#endif

/*
 * The tile with packets (packets=on, trace/packet_scene.h): the camera
 * rays of each 4 x 2 block of pixels are traced together to their first
 * hit, then each pixel is shaded as render_tile does, its first trace
 * taken from the packet (shade_context.primed).  The same image bit for
 * bit: a packet's hits are the single rays' hits, and pixels do not
 * depend on the order they are shaded in.
 */
static void render_tile_packets(struct render_pass *pass, struct shade_context *sc, int x0,
                                int y0)
{
    const struct render_state *st = pass->job->state;
    const int *vp = st->viewport;
#if RENDER_TILE_TRACED_FIRST
    /* The loop's eye-light case below (eye, direct, all drawn) without a
     * depth buffer: the whole tile traced first. */
    if (st->shading == RENDER_EYE_LIGHT && !pass->depth_state && !sc->clipping &&
        !sc->see_through && pass->all_drawn && !pass->depth) {
        render_tile_eye_traced_first(pass, sc, x0, y0);
        return;
    }
#endif
    /* The tile's blocks share their unprojected pixel centres: each one
     * once, where a cache per block made the blocks' right and lower
     * neighbours a second time. */
    struct unproject_cache cache;
    unproject_cache_init(pass, &cache, x0, y0);
    /* Without clip planes, blending, the alpha test and polygon offset a
     * pixel is its camera ray's first hit, shaded, when GL draws that
     * hit (not culled, not outlined), or the clear colour when there is
     * none: what blend_trace_primary gives then, without its layer stack,
     * the second look at the primed hit and the next distance it steps
     * to (some 130 instructions a pixel). */
    const int direct = !pass->depth_state && !sc->clipping && !sc->see_through;
    /* The eye light's direct hits of a block are shaded together, their
     * texture levels of detail two at a time (shade_eye_hits). */
    const int eye = st->shading == RENDER_EYE_LIGHT;
    struct trace_packet pk;
    struct shade_cone cone[TRACE_PACKET];
    struct trace_scene_hit hits[TRACE_PACKET];
#if RENDER_PAIRS
    struct block_lanes by_lane;
#endif
    /* A whole block's eye-light hits, every ray made and every one a hit
     * (eye_block's common case): its rays' directions and hits are the
     * same arrays for every block of the tile. */
    const float *block_dirs[TRACE_PACKET];
    const struct trace_scene_hit *block_hits[TRACE_PACKET];
    for (int i = 0; i < TRACE_PACKET; i++) {
        block_dirs[i] = pk.dir[i];
        block_hits[i] = &hits[i];
    }
#if defined(RENDER_UNIT_AVX2)
    /* The texels of a block are loaded after the next block's trace
     * (eye_pipeline). */
    struct eye_pipeline pipe = {.slot = 0, .full = 0};
#endif
    for (int by = y0; by < y0 + RENDER_TILE_SIZE && by < vp[3]; by += RENDER_BLOCK_H) {
        unproject_cache_row(pass, &cache, by);
#if RENDER_PAIRS
        const int lanes = block_row_lanes(&cache, vp, y0, by);
        struct block_lanes *lanes_out = &by_lane;
#else
        const int lanes = 0;
        struct block_lanes *lanes_out = NULL;
#endif
        for (int bx = x0; bx < x0 + RENDER_TILE_SIZE && bx < vp[2]; bx += RENDER_BLOCK_W) {
            /* every pixel of the block inside and its ray made */
            const int whole =
                block_camera_rays(&cache, vp, x0, y0, bx, by, lanes, &pk, cone, lanes_out);
            const unsigned found = trace_scene_closest_packet(sc->scene, &pk, hits, sc->counters);
            if (eye && direct && pass->all_drawn) {
                /* The loop below when every hit is drawn and shaded by the
                 * eye light: a pixel is its ray's hit, shaded with the
                 * block's others, or the clear colour, without the primed
                 * hits (only Whitted's shading reads them) or the other
                 * branches' tests. */
                if (whole && found == pk.active && !pass->depth) {
                    /* eye_block's batch when all eight are hits. */
                    float *px[TRACE_PACKET];
                    block_pixels(pass, bx, by, px);
#if defined(RENDER_UNIT_AVX2)
                    eye_pipeline_block(sc, &pipe, block_dirs, &by_lane.rays, block_hits, px);
#else
                    shade_eye_hits(sc, TRACE_PACKET, block_dirs, block_hits, cone, px);
#endif
                } else
                    eye_block(pass, sc, x0, y0, bx, by, &pk, found, hits, cone);
                continue;
            }
            /* Whitted shading's shadow rays of the block's first hits,
             * one packet per light, and the surfaces they start on. */
            struct shade_primed primed[TRACE_PACKET];
            struct shade_primed reflected[SHADE_PRIME_DEPTHS * TRACE_PACKET];
            struct surface surf[(1 + SHADE_PRIME_DEPTHS) * TRACE_PACKET];
            for (int i = 0; i < TRACE_PACKET; i++) {
                primed[i].found = (int)(found >> i & 1u);
                if (primed[i].found)
                    primed[i].hit = hits[i];
                primed[i].surface = NULL;
                primed[i].shadow_known = 0;
                primed[i].shadow_occluded = 0;
                primed[i].reflect_known = 0;
            }
            shade_prime_shadows(sc, found, hits, (const float(*)[3])pk.org,
                                (const float(*)[3])pk.dir, cone, surf, primed, reflected);
            struct eye_batch eyes = {.n = 0};
            for (int i = 0; i < TRACE_PACKET; i++) {
                if (!block_pixel_inside(vp, x0, y0, bx, by, i))
                    continue;
                const int x = bx + i % RENDER_BLOCK_W, y = by + i / RENDER_BLOCK_W;
                float *px = &pass->fb[4 * ((size_t)(vp[1] + y) * pass->fb_width + vp[0] + x)];
                if (!(pk.active >> i & 1u)) {
                    memcpy(px, st->clear_color, 4 * sizeof(float));
                    continue;
                }
                sc->primed = &primed[i];
                float t_first;
                const size_t at = (size_t)(vp[1] + y) * pass->fb_width + vp[0] + x;
                if (direct && !primed[i].found) {
                    /* blend_trace_primary without a hit: the clear colour. */
                    memcpy(px, st->clear_color, 4 * sizeof(float));
                    t_first = INFINITY;
                } else if (direct &&
                           (pass->all_drawn || gl_hit_drawn(sc, pk.dir[i], &primed[i].hit))) {
                    /* blend_trace_primary's first, opaque, drawn hit. */
                    if (eye) {
                        /* Shaded with the block's others below. */
                        eye_batch_add(&eyes, pk.dir[i], &primed[i].hit, cone[i], px);
                    } else
                        shade_hit(sc, pk.org[i], pk.dir[i], &primed[i].hit, cone[i], 0, px);
                    t_first = primed[i].hit.t;
                } else if (pass->depth_state) /* polygon offset in the frame (lines.c) */
                    blend_trace_primary_state(sc, pk.org[i], pk.dir[i], pk.tmax[i], cone[i], px,
                                              &t_first, &pass->depth_state[at]);
                else
                    blend_trace_primary(sc, pk.org[i], pk.dir[i], pk.tmax[i], cone[i], px,
                                        &t_first);
                sc->primed = NULL;
                if (pass->depth)
                    pass->depth[at] =
                        raster_window_depth(st->projection, pk.org[i], pk.dir[i], t_first);
            }
            eye_batch_shade(sc, &eyes);
        }
    }
#if defined(RENDER_UNIT_AVX2)
    eye_pipeline_finish(sc, &pipe);
#endif
}

void render_tile(struct render_pass *pass, uint32_t tile, int worker)
{
    const struct render_state *st = pass->job->state;
    struct surface_cache cache_entry[SHADE_CACHES];
    memset(cache_entry, 0, sizeof(cache_entry));
    struct shade_context sc = {st,
                               pass->job->frame,
                               &pass->scene,
                               &pass->counters[worker].c,
                               pass->job->textures,
                               pass->clipping,
                               pass->see_through,
                               NULL,
                               cache_entry,
                               pass->eye_caches
                                   ? &pass->eye_caches[(size_t)worker * SHADE_EYE_CACHES]
                                   : NULL,
                               NULL,
                               NULL,
                               0};
    shade_context_lights(&sc);
    struct secondary_scenes secondary;
    secondary_scenes_init(&secondary, &sc, &pass->scene, pass->secondary);
    const int *vp = st->viewport;
    int x0 = (int)(tile % (uint32_t)pass->tiles_x) * RENDER_TILE_SIZE;
    int y0 = (int)(tile / (uint32_t)pass->tiles_x) * RENDER_TILE_SIZE;
    if (pass->scene.kernels && pass->scene.kernels->closest_packet) {
#if !defined(RENDER_UNIT_AVX2)
        /* The AVX-512 copy of the packet loop (render_avx512.c, the
         * eye light's AVX-512 shading) when the context traces with
         * AVX-512, else the AVX2 copy (render_avx2.c) when it traces
         * with AVX2 (trace/kernels.c has then checked that the CPU and
         * the OS run that instruction set). */
        if (pass->scene.kernels->isa >= TRACE_ISA_AVX512) {
            const render_tile_packets_fn avx512 = render_tile_packets_avx512_unit();
            if (avx512) {
                avx512(pass, &sc, x0, y0);
                return;
            }
        }
        if (pass->scene.kernels->isa >= TRACE_ISA_AVX2) {
            const render_tile_packets_fn avx2 = render_tile_packets_avx2_unit();
            if (avx2) {
                avx2(pass, &sc, x0, y0);
                return;
            }
        }
#endif
        render_tile_packets(pass, &sc, x0, y0);
        return;
    }
    struct unproject_cache cache;
    unproject_cache_init(pass, &cache, x0, y0);
    for (int y = y0; y < y0 + RENDER_TILE_SIZE && y < vp[3]; y++) {
        unproject_cache_row(pass, &cache, y);
        for (int x = x0; x < x0 + RENDER_TILE_SIZE && x < vp[2]; x++) {
            float *px = &pass->fb[4 * ((size_t)(vp[1] + y) * pass->fb_width + vp[0] + x)];
            float org[3], dir[3], tmax;
            struct shade_cone cone;
            if (!primary_ray(&cache, x, y, org, dir, &tmax, &cone)) {
                memcpy(px, st->clear_color, 4 * sizeof(float));
                continue;
            }
            float t_first;
            const size_t i = (size_t)(vp[1] + y) * pass->fb_width + vp[0] + x;
            if (pass->depth_state)
                blend_trace_primary_state(&sc, org, dir, tmax, cone, px, &t_first,
                                          &pass->depth_state[i]);
            else
                blend_trace_primary(&sc, org, dir, tmax, cone, px, &t_first);
            if (pass->depth)
                pass->depth[i] = raster_window_depth(st->projection, org, dir, t_first);
        }
    }
}

/* The light set an instance was drawn under (the frame's when it has
 * none, as gl_shade_hit). */
static const struct scene_light *instance_lights(const struct render_pass *pass,
                                                 const struct scene_instance *inst)
{
    const struct scene_frame *frame = pass->job->frame;
    const uint32_t set = inst->appearance.gl.light_set;
    return set < frame->committed_lights.count ? frame->committed_lights.items[set].light
                                               : pass->job->state->lights;
}

/* A target for the rasterised instance inst: its projection, viewport,
 * clip planes, raster state and depth test. */
static void overlay_target(struct raster_target *target, const struct scene_instance *inst)
{
    const struct scene_raster *r = &inst->appearance.raster;
    target->projection = r->projection;
    target->viewport = r->viewport;
    target->clip = &inst->appearance.clip;
    target->raster = r;
    target->depth_test = r->depth_test;
}

/*
 * GL's draw order for what was drawn under another projection before the
 * first traced instance (a background quad drawn first): drawn into a
 * layer of its own, on the clear colour and a cleared depth buffer, and
 * the traced image goes over it where GL's depth test would have let the
 * scene's fragments through, its window depth less than the layer's (a
 * layer drawn with RT_DEPTH_TEST disabled writes no depth, so the scene
 * covers it wherever the scene is).  Elsewhere the layer shows, its depth
 * what the later primitives are tested against.  Returns -1 when out of
 * memory (the layer is then drawn after the scene).
 */
static int raster_under(struct render_pass *pass, uint32_t first_traced)
{
    const size_t pixels = (size_t)pass->fb_width * (size_t)pass->fb_height;
    const struct render_state *st = pass->job->state;
    float *rgba = rt_malloc((pixels ? pixels : 1) * 4 * sizeof(float));
    double *depth = rt_malloc((pixels ? pixels : 1) * sizeof(double));
    if (!rgba || !depth) {
        rt_free(rgba);
        rt_free(depth);
        return -1;
    }
    for (size_t i = 0; i < pixels; i++) {
        memcpy(&rgba[4 * i], st->clear_color, 4 * sizeof(float));
        depth[i] = 1.0;
    }
    struct raster_target target = {rgba, depth, pass->fb_width, pass->fb_height, NULL, NULL,
                                   &st->vis, NULL, NULL, 1, pass->job->textures};
    const struct scene_instance_list *list = &pass->job->frame->committed;
    for (uint32_t i = 0; i < first_traced; i++) {
        const struct scene_instance *inst = &list->items[i];
        if (!inst->overlay)
            continue;
        overlay_target(&target, inst);
        raster_instance(&target, inst, instance_lights(pass, inst));
    }
    for (size_t i = 0; i < pixels; i++)
        if (!(pass->depth[i] < depth[i])) {
            memcpy(&pass->fb[4 * i], &rgba[4 * i], 4 * sizeof(float));
            pass->depth[i] = depth[i];
            if (pass->depth_state)
                pass->depth_state[i] = NULL;
        }
    rt_free(rgba);
    rt_free(depth);
    return 0;
}

void render_pass_raster(struct render_pass *pass)
{
    const struct render_overlay *bitmaps = pass->job->overlay;
    if (!pass->depth) {
        if (bitmaps)
            render_overlay_draw(bitmaps, 0, UINT32_MAX, pass->fb, pass->fb_width,
                                pass->fb_height);
        return;
    }
    size_t next_bitmap = 0;
    const struct scene_instance_list *list = &pass->job->frame->committed;
    /* The first instance the frame traces: rasterised ones before it are
     * under the scene (raster_under). */
    uint32_t first_traced = 0;
    while (first_traced < list->count && (list->items[first_traced].overlay ||
                                          list->items[first_traced].object->mesh.tri_count == 0))
        first_traced++;
    if (first_traced == list->count)
        first_traced = 0; /* nothing traced: all in order over the clear colour */
    if (first_traced && raster_under(pass, first_traced))
        first_traced = 0;
    if (pass->depth_state)
        raster_depth_offset(pass->depth, pass->depth_state, pass->fb_width, pass->fb_height);
    raster_depth_prepare(pass->depth, pass->fb_width, pass->fb_height);
    const struct render_state *st = pass->job->state;
    struct raster_target target = {pass->fb, pass->depth, pass->fb_width, pass->fb_height,
                                   st->viewport, st->projection, &st->vis, NULL, NULL, 1,
                                   pass->job->textures};
    for (uint32_t i = 0; i < list->count; i++) {
        const struct scene_instance *inst = &list->items[i];
        if (inst->overlay) {
            if (i < first_traced)
                continue; /* drawn under the scene */
            /* The bitmaps drawn before it go under it, as in GL. */
            if (bitmaps)
                next_bitmap = render_overlay_draw(bitmaps, next_bitmap, i, pass->fb,
                                                  pass->fb_width, pass->fb_height);
            struct raster_target own = target;
            overlay_target(&own, inst);
            raster_instance(&own, inst, instance_lights(pass, inst));
            continue;
        }
        if (!pass->projectable)
            continue; /* a singular projection: nothing of the frame's is drawn */
        target.clip = &inst->appearance.clip; /* GL clips per primitive */
        target.raster = &inst->appearance.raster; /* and blends, sizes */
        raster_polygons(&target, inst);
        raster_lines(&target, &inst->object->mesh.lines, inst->object_to_world);
    }
    if (bitmaps)
        render_overlay_draw(bitmaps, next_bitmap, UINT32_MAX, pass->fb, pass->fb_width,
                            pass->fb_height);
}

int render_pass_end(struct render_pass *pass, struct render_framebuffer *fb,
                    struct render_stats *stats)
{
    int failed = pass->failed;
    shared_finish(pass, stats);
    rt_free(pass->depth);
    pass->depth = NULL;
    rt_free(pass->depth_state);
    pass->depth_state = NULL;
    if (failed) {
        rt_free(pass->fb);
        return -1;
    }
    if (fb->width != pass->fb_width || fb->height != pass->fb_height)
        fb->frames = 0;
    /* The image shown until now is the next frame's to render into when
     * it has the same size (render_framebuffer.spare). */
    const size_t old_pixels = (size_t)fb->width * (size_t)fb->height;
    if (fb->rgba && old_pixels > 0 &&
        old_pixels == (size_t)pass->fb_width * (size_t)pass->fb_height) {
        rt_free(fb->spare);
        fb->spare = fb->rgba;
        fb->spare_pixels = old_pixels;
    } else {
        rt_free(fb->rgba);
    }
    fb->rgba = pass->fb;
    fb->width = pass->fb_width;
    fb->height = pass->fb_height;
    fb->frames++;
    return 0;
}

/* A worker's share of a frame: tiles from the atomic counter. */
static void frame_task(void *arg, int worker)
{
    struct render_pass *pass = arg;
    uint32_t tiles = render_pass_tiles(pass);
    for (;;) {
        uint32_t tile = rt_atomic_fetch_add_relaxed(&pass->next_item, 1);
        if (tile >= tiles)
            break;
        render_tile(pass, tile, worker);
    }
}

int render_frame(const struct render_job *job, int fb_width, int fb_height,
                 struct render_framebuffer *fb, struct render_stats *stats)
{
    struct render_pass pass;
    const size_t pixels = (size_t)fb_width * (size_t)fb_height;
    float *storage = NULL;
    if (fb->spare && pixels > 0 && fb->spare_pixels == pixels) {
        storage = fb->spare;
        fb->spare = NULL;
        fb->spare_pixels = 0;
    }
    if (pass_begin(&pass, job, fb_width, fb_height, storage, 1))
        return -1;
    if (render_pass_tiles(&pass) > 0)
        rt_pool_run(job->pool, frame_task, &pass);
    render_pass_raster(&pass);
    return render_pass_end(&pass, fb, stats);
}

static void miss(RThit *h)
{
    h->t = INFINITY;
    h->u = 0.0f;
    h->v = 0.0f;
    h->instance = RT_INVALID_ID;
    h->object = RT_INVALID_ID;
    h->primitive = RT_INVALID_ID;
}

static void store_hit(const struct render_pass *sh, const struct trace_scene_hit *h, RThit *out)
{
    const struct trace_instance *ti = &sh->scene.instances[h->instance];
    const struct scene_object *object = ti->object;
    out->t = h->t;
    out->u = h->u;
    out->v = h->v;
    out->instance = ti->instance_id;
    out->object = object->name;
    out->primitive = h->prim;
}

/* Rays i .. i + TRACE_PACKET - 1 of a query as one packet, when their
 * directions look coherent (trace_packet_coherent); returns 0, having
 * traced nothing, when they do not.  The answers are the single rays'. */
static int query_packet(struct render_pass *sh, size_t i, struct trace_scene_counters *counters)
{
    const float *dirs[TRACE_PACKET];
    for (int j = 0; j < TRACE_PACKET; j++)
        dirs[j] = sh->rays[i + (size_t)j].dir;
    if (!trace_packet_coherent(dirs, TRACE_PACKET))
        return 0;
    struct trace_packet pk;
    for (int j = 0; j < TRACE_PACKET; j++) {
        const RTray *r = &sh->rays[i + (size_t)j];
        memcpy(pk.org[j], r->org, sizeof(pk.org[j]));
        memcpy(pk.dir[j], r->dir, sizeof(pk.dir[j]));
        pk.tmin[j] = r->tmin;
        pk.tmax[j] = r->tmax;
    }
    pk.active = (1u << TRACE_PACKET) - 1u;
    if (sh->occluded) {
        const unsigned occ = trace_scene_any_packet(&sh->scene, &pk, counters);
        for (int j = 0; j < TRACE_PACKET; j++)
            sh->occluded[i + (size_t)j] = (RTboolean)(occ >> j & 1u);
        return 1;
    }
    struct trace_scene_hit h[TRACE_PACKET];
    const unsigned found = trace_scene_closest_packet(&sh->scene, &pk, h, counters);
    for (int j = 0; j < TRACE_PACKET; j++) {
        if (found >> j & 1u)
            store_hit(sh, &h[j], &sh->hits[i + (size_t)j]);
        else
            miss(&sh->hits[i + (size_t)j]);
    }
    return 1;
}

/* The rays first .. last - 1 of a query that do not go as packets,
 * through the batch walk (trace/scene_stream.h: the single rays'
 * answers and counts, through the stream walk where the scene
 * qualifies), in pieces of QUERY_STREAM_RUN rays: the answers' scratch
 * here, about 5 KB, beside the batch walk's 72 KB, on a pool thread's
 * stack or the caller's (scene_stream.c says why that is enough). */
enum { QUERY_STREAM_RUN = 256 };
typedef char rtray_is_eight_floats[sizeof(RTray) == 8 * sizeof(float) ? 1 : -1];

static void query_stream(struct render_pass *sh, size_t first, size_t last,
                         struct trace_scene_counters *counters)
{
    struct trace_scene_hit h[QUERY_STREAM_RUN];
    unsigned char got[QUERY_STREAM_RUN];
    const size_t stride = sizeof(RTray) / sizeof(float);
    while (first < last) {
        const uint32_t n =
            (uint32_t)(last - first < QUERY_STREAM_RUN ? last - first : QUERY_STREAM_RUN);
        /* RTray is eight floats (org, tmin, dir, tmax): the batch walk's
         * layout, read through the struct's address. */
        const float *rays = (const float *)(const void *)&sh->rays[first];
        if (sh->occluded) {
            trace_scene_any_batch(&sh->scene, rays, stride, n, got, counters);
            for (uint32_t j = 0; j < n; j++)
                sh->occluded[first + j] = (RTboolean)got[j];
        } else {
            trace_scene_closest_batch(&sh->scene, rays, stride, n, h, got, counters);
            for (uint32_t j = 0; j < n; j++) {
                if (got[j])
                    store_hit(sh, &h[j], &sh->hits[first + j]);
                else
                    miss(&sh->hits[first + j]);
            }
        }
        first += n;
    }
}

/* A chunk's rays with the stream walk on (query_stream): coherent groups
 * as packets, as query_task's loop sends them, the runs of rays between
 * them through the batch walk. */
static void query_chunk_stream(struct render_pass *sh, size_t first, size_t last, int packets,
                               struct trace_scene_counters *counters)
{
    size_t run = first;
    for (size_t i = first; i + TRACE_PACKET <= last; i += TRACE_PACKET) {
        if (packets && query_packet(sh, i, counters)) {
            query_stream(sh, run, i, counters);
            run = i + TRACE_PACKET;
        }
    }
    query_stream(sh, run, last, counters);
}

static void query_task(void *arg, int worker)
{
    struct render_pass *sh = arg;
    struct trace_scene_counters *counters = &sh->counters[worker].c;
    /* Packets walk with the hit filter of a frame with clip planes, ray
     * by ray as single rays (trace/packet_scene.h). */
    const int packets = sh->scene.kernels && sh->scene.kernels->closest_packet;
    /* stream=off (or a table without the stream), and a scene where the
     * batch walk would go ray by ray anyway (stream=auto on small
     * objects, a top level of several leaves), keep the loop below.
     * Whether the scene qualifies is asked once a ray comes that reaches
     * its leaf at once (trace_scene_stream_ready): -1 until then. */
    int stream = sh->scene.kernels && sh->scene.kernels->stream_counted ? -1 : 0;
    for (;;) {
        uint32_t item = rt_atomic_fetch_add_relaxed(&sh->next_item, 1);
        size_t first = (size_t)item * RENDER_QUERY_CHUNK;
        if (first >= (size_t)sh->count)
            break;
        size_t last = first + RENDER_QUERY_CHUNK;
        if (last > (size_t)sh->count)
            last = (size_t)sh->count;
        for (size_t i = first; stream < 0 && i < last; i++)
            if (trace_scene_stream_ray((const float *)(const void *)&sh->rays[i]))
                stream = trace_scene_stream_ready(&sh->scene, sh->occluded != NULL);
        if (stream > 0) {
            query_chunk_stream(sh, first, last, packets, counters);
            continue;
        }
        for (size_t i = first; i < last; i++) {
            const RTray *r = &sh->rays[i];
            /* Coherent groups of TRACE_PACKET rays go as a packet. */
            if (packets && (i - first) % TRACE_PACKET == 0 && last - i >= TRACE_PACKET &&
                query_packet(sh, i, counters)) {
                i += TRACE_PACKET - 1;
                continue;
            }
            if (sh->occluded) {
                sh->occluded[i] =
                    (RTboolean)trace_scene_any(&sh->scene, r->org, r->dir, r->tmin, r->tmax,
                                               counters);
                continue;
            }
            struct trace_scene_hit h;
            RThit *out = &sh->hits[i];
            if (!trace_scene_closest(&sh->scene, r->org, r->dir, r->tmin, r->tmax, &h,
                                     counters)) {
                miss(out);
                continue;
            }
            store_hit(sh, &h, out);
        }
    }
}

static int run_queries(const struct render_job *job, int count, const RTray *rays, RThit *hits,
                       RTboolean *occluded, struct render_stats *stats)
{
    struct render_pass sh;
    if (shared_init(&sh, job))
        return -1;
    sh.count = count;
    sh.rays = rays;
    sh.hits = hits;
    sh.occluded = occluded;
    /* What the user clip planes remove is not there for a query either,
     * nor the inside of a face drawn as lines or points
     * (render/secondary.h). */
    if (frame_has_clip(job->frame) || filled_frame_has_unfilled(job->frame)) {
        if (secondary_marks(job->frame, SECONDARY_CLIP | SECONDARY_UNFILLED, &sh.secondary)) {
            rt_free(sh.counters);
            return -1;
        }
        sh.scene.filtered = sh.secondary;
        sh.scene.filter_mask = SECONDARY_CLIP | SECONDARY_UNFILLED;
        sh.scene.accept = secondary_accept_query;
        sh.scene.accept_user = &sh;
        sh.reads_binary = 1; /* the hit filter's walk */
    }
    /* One chunk needs no helpers: avoid waking the pool for tiny batches. */
    rt_pool_run(count > RENDER_QUERY_CHUNK ? job->pool : NULL, query_task, &sh);
    int failed = sh.failed;
    shared_finish(&sh, stats);
    return failed ? -1 : 0;
}

int render_trace_rays(const struct render_job *job, int count, const RTray *rays, RThit *hits,
                      struct render_stats *stats)
{
    return run_queries(job, count, rays, hits, NULL, stats);
}

int render_occluded_rays(const struct render_job *job, int count, const RTray *rays,
                         RTboolean *occluded, struct render_stats *stats)
{
    return run_queries(job, count, rays, NULL, occluded, stats);
}

int render_unproject_rows(const double projection[16], const int viewport[4], int x0, int y,
                          double near_pt[][3], double far_pt[][3], signed char *state)
{
    struct render_state st;
    memset(&st, 0, sizeof(st));
    memcpy(st.viewport, viewport, sizeof(st.viewport));
    memcpy(st.projection, projection, sizeof(st.projection));
    struct render_job job;
    memset(&job, 0, sizeof(job));
    job.state = &st;
    struct render_pass pass;
    memset(&pass, 0, sizeof(pass));
    pass.job = &job;
    if (!mat4_invert(pass.inv_projection, projection))
        return -1;
    pass.w_known = unproject_w_known(&pass, x0 + 0.5, x0 + UNPROJECT_COLS - 0.5, y + 0.5,
                                     y + UNPROJECT_ROWS - 0.5);
    struct unproject_cache c;
    unproject_cache_init(&pass, &c, x0, y);
    for (int r = 0; r < UNPROJECT_ROWS; r++) {
        for (int i = 0; i < UNPROJECT_COLS; i++) {
            const int p = r * UNPROJECT_COLS + i;
            for (int k = 0; k < 3; k++) {
                near_pt[p][k] = c.rows[r]->near_pt[k][i];
                far_pt[p][k] = c.rows[r]->far_pt[k][i];
            }
            state[p] = c.rows[r]->state[i];
        }
    }
    return pass.w_known;
}
