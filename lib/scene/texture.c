/* SPDX-License-Identifier: Apache-2.0 */
/*
 * texture.c - the texture table, mip chain generation and the texture
 * sampler (see texture.h).
 *
 * The table is the name table shared with objects (base/name_table.h).
 */
#include "scene/texture.h"

#include <math.h>
#include <string.h>

#include "base/alloc.h"
#include "base/name_table.h"

/* The bilinear filter converts and blends a texel's four channels in the
 * SSE lanes: IEEE operations lane by lane, the same floats as one channel
 * at a time (a scalar path under RT_NO_SIMD or without SSE2). */
#if defined(__SSE2__) && !defined(RT_NO_SIMD)
#include <emmintrin.h>
#if defined(__SSE4_1__)
#include <smmintrin.h> /* the AVX2 copy (render/shade_eye_avx2.c) */
#endif
#if defined(__AVX2__)
#include <immintrin.h>
#include <stddef.h>
#define TEXTURE_OCTS 1 /* scene_texture_sample_lod8 */
#if defined(__AVX512F__) && defined(__AVX512DQ__) && defined(__AVX512VL__)
/* The AVX-512 copy (render/shade_eye_avx512.c): sample_lod8's double
 * steps in one 512-bit vector of eight lanes instead of two halves. */
#define TEXTURE_OCTS_512 1
#endif
#endif
#define TEXTURE_LANES 1
#else
#define TEXTURE_LANES 0
#endif

/* First table size: a scene has far fewer textures than objects, so
 * smaller than the object table's 64 (object.c). */
#define TEXTURE_TABLE_MIN_CAPACITY 16u

void scene_textures_init(struct scene_textures *table)
{
    name_table_init(&table->table, TEXTURE_TABLE_MIN_CAPACITY);
}

static void texture_free(void *item)
{
    struct scene_texture *tex = item;
    rt_free(tex->texels);
    rt_free(tex);
}

void scene_textures_release(struct scene_textures *table)
{
    for (uint32_t i = 0; i < table->table.capacity; i++)
        if (table->table.slots[i].name)
            texture_free(table->table.slots[i].item);
    name_table_release(&table->table);
}

struct scene_texture *scene_textures_lookup(const struct scene_textures *table, uint32_t name)
{
    return name_table_lookup(&table->table, name);
}

/* A texture without an image and with the default parameters
 * (docs/textures.md: LINEAR for both filters, REPEAT in s and t). */
static void *texture_new(uint32_t name)
{
    struct scene_texture *tex = rt_calloc(1, sizeof(*tex));
    if (!tex)
        return NULL;
    tex->name = name;
    tex->min_filter = SCENE_FILTER_LINEAR;
    tex->mag_filter = SCENE_FILTER_LINEAR;
    tex->wrap_s = SCENE_WRAP_REPEAT;
    tex->wrap_t = SCENE_WRAP_REPEAT;
    return tex;
}

struct scene_texture *scene_textures_get_or_create(struct scene_textures *table, uint32_t name)
{
    return name_table_get_or_create(&table->table, name, texture_new);
}

int scene_textures_generate(struct scene_textures *table, uint32_t n, uint32_t *names)
{
    return name_table_generate(&table->table, n, names, texture_new, texture_free);
}

void scene_textures_remove(struct scene_textures *table, uint32_t name)
{
    struct scene_texture *tex = name_table_remove(&table->table, name);
    if (tex)
        texture_free(tex);
}

/* ---- mip chain ----------------------------------------------------------- */

/* The size of the level after one of n texels: max(1, floor(n / 2)), as
 * OpenGL 2.0 sec. 3.8.8 ("Mipmapping") sizes non-power-of-two levels. */
static int half_size(int n)
{
    return n > 1 ? n / 2 : 1;
}

int scene_texture_level_count(int width, int height)
{
    int count = 1;
    while (width > 1 || height > 1) {
        width = half_size(width);
        height = half_size(height);
        count++;
    }
    return count;
}

size_t scene_texture_chain_texels(int width, int height)
{
    size_t total = 0;
    for (;;) {
        total += (size_t)width * (size_t)height;
        if (width == 1 && height == 1)
            return total;
        width = half_size(width);
        height = half_size(height);
    }
}

/*
 * The mip chain is built by the area-weighted box filter: texel i of a
 * level n' = half_size(n) texels wide is the mean of the previous level
 * over the interval it covers, [i n / n', (i + 1) n / n'), each source
 * texel weighted by its overlap with it.  For even n that is the usual
 * 2-texel box; for odd n the box is 2 + 1/n' texels wide and straddles
 * three texels with weights (n' - i, n', i + 1) / n: the polyphase box of
 * Guthe and Heckbert, "Non-Power-of-Two Mipmap Creation", NVIDIA technical
 * report TR-01838-001, 2005, whose weights for odd sizes are these.  The
 * filter is separable and applied in 2D (up to 3x3 taps).  Each source texel
 * spreads exactly its own weight, so every level keeps the mean of the one
 * before it: the 1x1 level is the mean of the image.
 *
 * Overlaps are integers when lengths are counted in 1/n' source texel:
 * destination texel i covers [i n, (i + 1) n) and source texel j covers
 * [j n', (j + 1) n'), so the weights are exact and sum to n per axis.
 *
 * Levels are built from the previous level's unrounded values, not its
 * 8-bit texels, so rounding does not accumulate down the chain; each
 * texel is rounded once, to the nearest 8-bit value.  To keep that
 * working memory small, rows stream down the chain: a level keeps its
 * last three rows as floats (a destination row needs at most three source
 * rows, ending with the one just made), and a row of level k+1 is made as
 * soon as the last row of level k it needs exists.
 */
#define MIP_MAX_TAPS 3

struct mip_level {
    int width, height;
    uint8_t *texels; /* in the chain */
    float *rows;     /* MIP_MAX_TAPS rows of 4 * width floats, row j in slot j % 3 */
    int next_row;    /* the next row of this level to make (levels > 0) */
};

/* Source texels under destination texel i along an axis of n texels
 * halved to n2: the first index and up to MIP_MAX_TAPS integer weights,
 * summing to n.  Returns the tap count. */
static int box_taps(int n, int n2, int i, int *first, long weight[MIP_MAX_TAPS])
{
    const long lo = (long)i * n, hi = lo + n;
    int count = 0;
    *first = (int)(lo / n2);
    for (long j = *first; j * n2 < hi; j++) {
        long a = j * n2 > lo ? j * n2 : lo;
        long b = (j + 1) * n2 < hi ? (j + 1) * n2 : hi;
        weight[count++] = b - a;
    }
    return count;
}

static void make_row(struct mip_level *lv, int k, int levels);

/* Row j of level k exists (in its float slot): makes every row of level
 * k+1 that waited for it, each of which may in turn complete rows below. */
static void row_ready(struct mip_level *lv, int k, int j, int levels)
{
    if (k + 1 >= levels)
        return;
    struct mip_level *dst = &lv[k + 1];
    const int m = lv[k].height, m2 = dst->height;
    /* Row r of level k+1 needs source rows up to ceil((r + 1) m / m2) - 1. */
    while (dst->next_row < m2 &&
           ((long)(dst->next_row + 1) * m + m2 - 1) / m2 - 1 <= (long)j)
        make_row(lv, k + 1, levels);
}

/* Makes row lv[k].next_row of level k (k > 0) from level k - 1. */
static void make_row(struct mip_level *lv, int k, int levels)
{
    const struct mip_level *src = &lv[k - 1];
    struct mip_level *dst = &lv[k];
    const int n = src->width, m = src->height, n2 = dst->width, m2 = dst->height;
    const int r = dst->next_row;
    int y0, x0;
    long wy[MIP_MAX_TAPS], wx[MIP_MAX_TAPS];
    const int ny = box_taps(m, m2, r, &y0, wy);
    /* The last level keeps no float rows: nothing is made from it. */
    float *out = dst->rows ? &dst->rows[(size_t)(r % MIP_MAX_TAPS) * 4 * (size_t)n2] : NULL;
    uint8_t *texels = &dst->texels[(size_t)r * 4 * (size_t)n2];
    const double total = (double)n * (double)m;
    for (int i = 0; i < n2; i++) {
        const int nx = box_taps(n, n2, i, &x0, wx);
        double sum[4] = {0, 0, 0, 0};
        for (int b = 0; b < ny; b++) {
            const float *row = &src->rows[(size_t)((y0 + b) % MIP_MAX_TAPS) * 4 * (size_t)n];
            for (int a = 0; a < nx; a++) {
                const double w = (double)(wy[b] * wx[a]);
                for (int c = 0; c < 4; c++)
                    sum[c] += w * (double)row[4 * (x0 + a) + c];
            }
        }
        for (int c = 0; c < 4; c++) {
            const double v = sum[c] / total; /* in [0, 255]: a weighted mean */
            if (out)
                out[4 * i + c] = (float)v;
            texels[4 * i + c] = (uint8_t)lrint(v);
        }
    }
    dst->next_row++;
    row_ready(lv, k, r, levels);
}

int scene_texture_build_mipmaps(uint8_t *chain, int width, int height)
{
    struct mip_level lv[SCENE_TEXTURE_MAX_LEVELS];
    const int levels = scene_texture_level_count(width, height);
    if (levels < 2)
        return 0;
    /* Float rows for every level that has a level after it. */
    size_t row_floats = 0, offset = 0;
    for (int k = 0, w = width, h = height; k < levels; k++) {
        lv[k].width = w;
        lv[k].height = h;
        lv[k].texels = chain + 4 * offset;
        lv[k].next_row = 0;
        offset += (size_t)w * (size_t)h;
        if (k + 1 < levels)
            row_floats += MIP_MAX_TAPS * 4 * (size_t)w;
        w = half_size(w);
        h = half_size(h);
    }
    float *rows = rt_malloc(row_floats * sizeof(float));
    if (!rows)
        return -1;
    for (int k = 0; k + 1 < levels; k++) {
        lv[k].rows = rows;
        rows += MIP_MAX_TAPS * 4 * (size_t)lv[k].width;
    }
    lv[levels - 1].rows = NULL;
    /* Level 0 streams in row by row; the rows below follow. */
    for (int j = 0; j < height; j++) {
        const uint8_t *in = &chain[(size_t)j * 4 * (size_t)width];
        float *slot = &lv[0].rows[(size_t)(j % MIP_MAX_TAPS) * 4 * (size_t)width];
        for (size_t c = 0; c < 4 * (size_t)width; c++)
            slot[c] = (float)in[c];
        row_ready(lv, 0, j, levels);
    }
    rt_free(lv[0].rows);
    return 0;
}

void scene_texture_set_image(struct scene_texture *tex, int width, int height, uint8_t *chain)
{
    rt_free(tex->texels);
    tex->width = width;
    tex->height = height;
    tex->texels = chain;
    tex->level_count = scene_texture_level_count(width, height);
    const uint8_t *p = chain;
    for (int k = 0; k < tex->level_count; k++) {
        tex->levels[k].width = width;
        tex->levels[k].height = height;
        tex->levels[k].texels = p;
        p += 4 * (size_t)width * (size_t)height;
        width = half_size(width);
        height = half_size(height);
    }
}

/* ---- sampling ------------------------------------------------------------ */

/*
 * The coordinate reduced to a range where scaling by the size cannot
 * overflow: REPEAT keeps the fractional part, s - floor(s), in [0, 1);
 * CLAMP_TO_EDGE bounds it to [-1, 2], which changes no lookup.  Computed
 * in double, where s - floor(s) is exact for every float s but a tiny
 * negative one.  NaN and infinities become 0.
 */
/* floor(x) for |x| < 2^52 without the library call: the truncation,
 * one lower for a negative x with a fraction.  Exact, as floor is; only
 * the sign of a zero result may differ (-0 for floor(-0)), which no use
 * here can see: it is subtracted from or converted to an integer. */
static double floor_small(double x)
{
    const double t = (double)(long long)x;
    return t > x ? t - 1.0 : t;
}

static double reduce_coord(float s, enum scene_texture_wrap wrap)
{
    double d = isfinite(s) ? (double)s : 0.0;
    if (wrap == SCENE_WRAP_REPEAT) {
        double f = d - (fabs(d) < 0x1p52 ? floor_small(d) : floor(d));
        /* A tiny negative s has its fractional part just below 1, which
         * can round to 1: keep it in the last texel, where it belongs. */
        return f < 1.0 ? f : 0x1.fffffffffffffp-1;
    }
    return fmin(fmax(d, -1.0), 2.0);
}

/* Texel index i (any value in [-n - 1, 2n + 1]) mapped into [0, n). */
static int wrap_index(long i, int n, enum scene_texture_wrap wrap)
{
    if (wrap == SCENE_WRAP_REPEAT) {
        /* The filters' indices lie within one period of [0, n): no
         * division (a 64-bit one per index cost more than the filter). */
        if (i >= 0 && i < n)
            return (int)i;
        if (i < 0 && i >= -(long)n)
            return (int)(i + n);
        if (i >= n && i < 2 * (long)n)
            return (int)(i - n);
        i %= n;
        return (int)(i < 0 ? i + n : i);
    }
    return i < 0 ? 0 : i >= n ? n - 1 : (int)i;
}

/* b / 255 for every 8-bit b, each the float division itself (folded by
 * the compiler, correctly rounded as at run time): a division, not a
 * multiplication by 1/255, so that it is the correctly rounded value of
 * the 8-bit colour, exactly what an application computes for it; looked
 * up, because 16 divisions per bilinear lookup were most of its cost. */
#define UNIT8_1(b) ((float)(b) / 255.0f)
#define UNIT8_4(b) UNIT8_1(b), UNIT8_1((b) + 1), UNIT8_1((b) + 2), UNIT8_1((b) + 3)
#define UNIT8_16(b) UNIT8_4(b), UNIT8_4((b) + 4), UNIT8_4((b) + 8), UNIT8_4((b) + 12)
#define UNIT8_64(b) UNIT8_16(b), UNIT8_16((b) + 16), UNIT8_16((b) + 32), UNIT8_16((b) + 48)
static const float unit8[256] = {UNIT8_64(0), UNIT8_64(64), UNIT8_64(128), UNIT8_64(192)};

static void fetch_texel(const struct scene_texture_level *lv, int i, int j, float rgba[4])
{
    const uint8_t *p = &lv->texels[4 * ((size_t)j * (size_t)lv->width + (size_t)i)];
    for (int k = 0; k < 4; k++)
        rgba[k] = unit8[p[k]];
}

#if TEXTURE_LANES
/* The texel's channels b / 255 in four lanes: each the correctly rounded
 * quotient of the byte (exact in float) by 255, the value unit8 holds. */
static __m128 texel_lanes(const struct scene_texture_level *lv, int i, int j)
{
    const uint8_t *p = &lv->texels[4 * ((size_t)j * (size_t)lv->width + (size_t)i)];
    int32_t bits;
    memcpy(&bits, p, sizeof(bits));
    const __m128i zero = _mm_setzero_si128();
    const __m128i b = _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(bits), zero), zero);
    return _mm_div_ps(_mm_cvtepi32_ps(b), _mm_set1_ps(255.0f));
}

/* GL 1.1 eq. 3.17's four texels from (i, j) (before wrapping) weighted
 * by a and b as nested interpolations, in four lanes: where the four
 * texels agree the result is exactly their value (an opaque alpha stays
 * 1). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline __m128 bilinear_lanes(const struct scene_texture *tex,
                                    const struct scene_texture_level *lv, long i, long j,
                                    float a, float b)
{
    const int i0 = wrap_index(i, lv->width, tex->wrap_s);
    const int i1 = wrap_index(i + 1, lv->width, tex->wrap_s);
    const int j0 = wrap_index(j, lv->height, tex->wrap_t);
    const int j1 = wrap_index(j + 1, lv->height, tex->wrap_t);
    const __m128 c00 = texel_lanes(lv, i0, j0), c10 = texel_lanes(lv, i1, j0);
    const __m128 c01 = texel_lanes(lv, i0, j1), c11 = texel_lanes(lv, i1, j1);
    const __m128 va = _mm_set1_ps(a);
    const __m128 bottom = _mm_add_ps(c00, _mm_mul_ps(va, _mm_sub_ps(c10, c00)));
    const __m128 top = _mm_add_ps(c01, _mm_mul_ps(va, _mm_sub_ps(c11, c01)));
    return _mm_add_ps(bottom, _mm_mul_ps(_mm_set1_ps(b), _mm_sub_ps(top, bottom)));
}
#endif

/* scene_texture_sample_level with the coordinates already reduced
 * (reduce_coord), which do not depend on the level. */
static void sample_level_reduced(const struct scene_texture *tex, int level,
                                 enum scene_texture_filter filter, double rs, double rt,
                                 float rgba[4])
{
    const struct scene_texture_level *lv = &tex->levels[level];
    const int w = lv->width, h = lv->height;
    const double u = rs * w;
    const double v = rt * h;
    if (filter == SCENE_FILTER_NEAREST || filter == SCENE_FILTER_NEAREST_MIPMAP_NEAREST ||
        filter == SCENE_FILTER_NEAREST_MIPMAP_LINEAR) {
        /* GL 1.1 eq. 3.16: the texel whose square contains (u, v). */
        int i = wrap_index((long)floor_small(u), w, tex->wrap_s);
        int j = wrap_index((long)floor_small(v), h, tex->wrap_t);
        fetch_texel(lv, i, j, rgba);
        return;
    }
    /* GL 1.1 eq. 3.17: i0 = floor(u - 1/2), alpha = frac(u - 1/2); the
     * four texels around the sample point, weighted bilinearly. */
    const double uc = u - 0.5, vc = v - 0.5;
    const double fi = floor_small(uc), fj = floor_small(vc);
    const float a = (float)(uc - fi), b = (float)(vc - fj);
#if TEXTURE_LANES
    _mm_storeu_ps(rgba, bilinear_lanes(tex, lv, (long)fi, (long)fj, a, b));
#else
    /* The same weights as nested interpolations: where the four texels
     * agree the result is exactly their value (an opaque alpha stays 1). */
    const int i0 = wrap_index((long)fi, w, tex->wrap_s);
    const int i1 = wrap_index((long)fi + 1, w, tex->wrap_s);
    const int j0 = wrap_index((long)fj, h, tex->wrap_t);
    const int j1 = wrap_index((long)fj + 1, h, tex->wrap_t);
    float c00[4], c10[4], c01[4], c11[4];
    fetch_texel(lv, i0, j0, c00);
    fetch_texel(lv, i1, j0, c10);
    fetch_texel(lv, i0, j1, c01);
    fetch_texel(lv, i1, j1, c11);
    for (int k = 0; k < 4; k++) {
        float bottom = c00[k] + a * (c10[k] - c00[k]);
        float top = c01[k] + a * (c11[k] - c01[k]);
        rgba[k] = bottom + b * (top - bottom);
    }
#endif
}

#if TEXTURE_LANES
/* floor_small of both lanes, for |x| < 2^31: the truncation (cvttpd2dq
 * truncates as the conversion to long long does there), one lower where
 * it is above x.  The integers in the low two int32 lanes of *index. */
static __m128d pair_floor(__m128d x, __m128i *index)
{
    const __m128i i = _mm_cvttpd_epi32(x);
    const __m128d t = _mm_cvtepi32_pd(i);
    const __m128d above = _mm_cmpgt_pd(t, x);
    /* above is all ones (-1 as int64) in the lanes to lower: as int32
     * pairs, lane k's low word is -1 too after the shuffle. */
    *index = _mm_add_epi32(i, _mm_shuffle_epi32(_mm_castpd_si128(above), _MM_SHUFFLE(3, 3, 2, 0)));
    return _mm_sub_pd(t, _mm_and_pd(above, _mm_set1_pd(1.0)));
}

/* wrap_index of the four int32 lanes of i, lane k wrapped into [0, n_k)
 * by REPEAT where `repeat` is all ones, else by CLAMP_TO_EDGE.  For
 * REPEAT, wrap_index's first three cases (i in [-n, 2n)): the lookups'
 * indices are there, since a reduced coordinate lies in [0, 1) and its
 * index i in [-1, n - 1] (i + 1 in [0, n]). */
static __m128i wrap_lanes(__m128i i, __m128i n, __m128i repeat)
{
    const __m128i last = _mm_sub_epi32(n, _mm_set1_epi32(1));
    const __m128i below = _mm_cmplt_epi32(i, _mm_setzero_si128());
    const __m128i above = _mm_cmpgt_epi32(i, last);
    const __m128i wrapped =
        _mm_sub_epi32(_mm_add_epi32(i, _mm_and_si128(below, n)), _mm_and_si128(above, n));
    const __m128i clamped = _mm_or_si128(_mm_andnot_si128(_mm_or_si128(below, above), i),
                                         _mm_and_si128(above, last));
    return _mm_or_si128(_mm_and_si128(repeat, wrapped), _mm_andnot_si128(repeat, clamped));
}

/* The channels of the texel at byte offset `off` of `texels`, as
 * texel_lanes. */
static __m128 texel_at(const uint8_t *texels, int32_t off)
{
    int32_t bits;
    memcpy(&bits, texels + off, sizeof(bits));
#if defined(__SSE4_1__)
    /* The four bytes zero-extended in one instruction (pmovzxbd, folded
     * with the load): the same integers. */
    const __m128i b = _mm_cvtepu8_epi32(_mm_cvtsi32_si128(bits));
#else
    const __m128i zero = _mm_setzero_si128();
    const __m128i b = _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(bits), zero), zero);
#endif
    return _mm_div_ps(_mm_cvtepi32_ps(b), _mm_set1_ps(255.0f));
}

/* bilinear_lanes from the four texels' byte offsets (c00, c10, c01,
 * c11), already wrapped: the same blend. */
static inline __m128 bilinear_at(const uint8_t *texels, const int32_t off[4], float a, float b)
{
    const __m128 c00 = texel_at(texels, off[0]), c10 = texel_at(texels, off[1]);
    const __m128 c01 = texel_at(texels, off[2]), c11 = texel_at(texels, off[3]);
    const __m128 va = _mm_set1_ps(a);
    const __m128 bottom = _mm_add_ps(c00, _mm_mul_ps(va, _mm_sub_ps(c10, c00)));
    const __m128 top = _mm_add_ps(c01, _mm_mul_ps(va, _mm_sub_ps(c11, c01)));
    return _mm_add_ps(bottom, _mm_mul_ps(_mm_set1_ps(b), _mm_sub_ps(top, bottom)));
}

/* reduce_coord of s (lane 0) and t (lane 1) in the double lanes, each
 * lane its operations in their order (pair_floor for floor_small: the
 * same value, the same zero); 0 when a finite coordinate is 2^31 or more
 * in magnitude, left to reduce_coord. */
static int pair_reduce(float s, float t, enum scene_texture_wrap wrap_s,
                       enum scene_texture_wrap wrap_t, __m128d *out)
{
    __m128d d = _mm_cvtps_pd(_mm_unpacklo_ps(_mm_set_ss(s), _mm_set_ss(t)));
    /* isfinite(s) ? s : 0: d - d is 0 only for a finite d. */
    d = _mm_and_pd(_mm_cmpeq_pd(_mm_sub_pd(d, d), _mm_setzero_pd()), d);
    const __m128d magnitude = _mm_andnot_pd(_mm_set1_pd(-0.0), d);
    if (_mm_movemask_pd(_mm_cmplt_pd(magnitude, _mm_set1_pd(0x1p31))) != 3)
        return 0;
    __m128i index;
    const __m128d f = _mm_sub_pd(d, pair_floor(d, &index));
    const __m128d below_one = _mm_cmplt_pd(f, _mm_set1_pd(1.0));
    const __m128d repeat = _mm_or_pd(_mm_andnot_pd(below_one, _mm_set1_pd(0x1.fffffffffffffp-1)),
                                     _mm_and_pd(below_one, f));
    /* fmin(fmax(d, -1), 2): d is finite here, where maxpd and minpd are
     * fmax and fmin. */
    const __m128d clamp = _mm_min_pd(_mm_max_pd(d, _mm_set1_pd(-1.0)), _mm_set1_pd(2.0));
    const __m128d is_repeat = _mm_castsi128_pd(
        _mm_set_epi32(-(wrap_t == SCENE_WRAP_REPEAT), -(wrap_t == SCENE_WRAP_REPEAT),
                      -(wrap_s == SCENE_WRAP_REPEAT), -(wrap_s == SCENE_WRAP_REPEAT)));
    *out = _mm_or_pd(_mm_and_pd(is_repeat, repeat), _mm_andnot_pd(is_repeat, clamp));
    return 1;
}

/* The bilinear filter of sample_level_reduced (LINEAR) of levels `level`
 * and level + 1 blended by f, scene_texture_sample_lod's *_MIPMAP_LINEAR
 * step: the two levels' u, v, their floors and weights in the two
 * double lanes (lane 0 the finer level), each lane sample_level_reduced's
 * operations in its order, and the blend fine + f (coarse - fine) in the
 * four float lanes as the scalar loop does per channel: the same floats.
 * rs and rt are reduced (reduce_coord: within [-1, 2]), so with at most
 * SCENE_TEXTURE_MAX_SIZE texels a side u and v are far inside int32. */
static void sample_trilinear(const struct scene_texture *tex, int level, __m128d rst, float f,
                             float rgba[4])
{
    const struct scene_texture_level *lv[2] = {&tex->levels[level], &tex->levels[level + 1]};
    const __m128d half = _mm_set1_pd(0.5);
    const __m128d uc = _mm_sub_pd(_mm_mul_pd(_mm_unpacklo_pd(rst, rst),
                                             _mm_set_pd((double)lv[1]->width, (double)lv[0]->width)),
                                  half);
    const __m128d vc = _mm_sub_pd(
        _mm_mul_pd(_mm_unpackhi_pd(rst, rst),
                   _mm_set_pd((double)lv[1]->height, (double)lv[0]->height)),
        half);
    __m128i ii, ji;
    const __m128d fi = pair_floor(uc, &ii), fj = pair_floor(vc, &ji);
    float a[4], b[4];
    _mm_storeu_ps(a, _mm_cvtpd_ps(_mm_sub_pd(uc, fi)));
    _mm_storeu_ps(b, _mm_cvtpd_ps(_mm_sub_pd(vc, fj)));
    /* The eight texels' byte offsets in int32 lanes: lanes (i fine,
     * i coarse, j fine, j coarse) and the sizes (w, w', h, h'). */
    const __m128i n = _mm_set_epi32(lv[1]->height, lv[0]->height, lv[1]->width, lv[0]->width);
    const __m128i repeat =
        _mm_set_epi32(-(tex->wrap_t == SCENE_WRAP_REPEAT), -(tex->wrap_t == SCENE_WRAP_REPEAT),
                      -(tex->wrap_s == SCENE_WRAP_REPEAT), -(tex->wrap_s == SCENE_WRAP_REPEAT));
    const __m128i lo = _mm_unpacklo_epi64(ii, ji);
    const __m128i w0 = wrap_lanes(lo, n, repeat);
    const __m128i w1 = wrap_lanes(_mm_add_epi32(lo, _mm_set1_epi32(1)), n, repeat);
    /* The rows j0 w, j1 w of both levels, (fine j0, coarse j0, fine j1,
     * coarse j1): every factor is in [0, 2^14], so the 16-bit products
     * madd forms are the exact 32-bit ones (the high halves are 0). */
    const __m128i rows = _mm_madd_epi16(_mm_unpackhi_epi64(w0, w1),
                                        _mm_shuffle_epi32(n, _MM_SHUFFLE(1, 0, 1, 0)));
    /* (i0, i1) of the fine level twice plus (row j0, row j0, row j1, row
     * j1) of it; the same for the coarse level: c00, c10, c01, c11. */
    const __m128i cols = _mm_unpacklo_epi32(w0, w1); /* i0 f, i1 f, i0 c, i1 c */
    int32_t off[2][4];
    _mm_storeu_si128((__m128i *)off[0],
                     _mm_slli_epi32(_mm_add_epi32(_mm_shuffle_epi32(cols, _MM_SHUFFLE(1, 0, 1, 0)),
                                                  _mm_shuffle_epi32(rows, _MM_SHUFFLE(2, 2, 0, 0))),
                                    2));
    _mm_storeu_si128((__m128i *)off[1],
                     _mm_slli_epi32(_mm_add_epi32(_mm_shuffle_epi32(cols, _MM_SHUFFLE(3, 2, 3, 2)),
                                                  _mm_shuffle_epi32(rows, _MM_SHUFFLE(3, 3, 1, 1))),
                                    2));
    __m128 c[2];
    for (int l = 0; l < 2; l++)
        c[l] = bilinear_at(lv[l]->texels, off[l], a[l], b[l]);
    _mm_storeu_ps(rgba, _mm_add_ps(c[0], _mm_mul_ps(_mm_set1_ps(f), _mm_sub_ps(c[1], c[0]))));
}
#endif

#if defined(TEXTURE_OCTS)
/* wrap_index of a bilinear lookup's two indices i and i + 1 along one
 * axis of n texels (wrap that axis' mode) in eight int32 lanes, into *lo
 * and *hi: the same integers.  With REPEAT, quad_reduce leaves the
 * coordinate in [0, 1 - 2^-53], its product by n (an integer from 1 to
 * 2^14) in [0, n] (rounding may reach n), less 1/2 in [-1/2, n - 1/2],
 * so i, its floor, is in [-1, n - 1] and i + 1 in [0, n]: wrap_index
 * adds n to an i of -1 and takes n from an i + 1 of n, and no other
 * case of it arises (one comparison an index where the general wrap
 * took both sides and a blend of the two modes).  Otherwise (clamped)
 * it gives i itself in [0, n - 1], 0 below and n - 1 above: min then
 * max, for any i. */
static inline void wrap_pair8(__m256i i, __m256i n, enum scene_texture_wrap wrap, __m256i *lo,
                              __m256i *hi)
{
    const __m256i last = _mm256_sub_epi32(n, _mm256_set1_epi32(1));
    const __m256i next = _mm256_add_epi32(i, _mm256_set1_epi32(1));
    if (wrap == SCENE_WRAP_REPEAT) {
        const __m256i below = _mm256_cmpgt_epi32(_mm256_setzero_si256(), i);
        *lo = _mm256_add_epi32(i, _mm256_and_si256(below, n));
        *hi = _mm256_sub_epi32(next, _mm256_and_si256(_mm256_cmpgt_epi32(next, last), n));
    } else {
        *lo = _mm256_max_epi32(_mm256_min_epi32(i, last), _mm256_setzero_si256());
        *hi = _mm256_max_epi32(_mm256_min_epi32(next, last), _mm256_setzero_si256());
    }
}

/* pair_reduce of four coordinates x along one axis (wrap) in the double
 * lanes: reduce_coord's value in each, the floor taken by roundpd (exact,
 * as floor_small; only the sign of a zero may differ, which the product
 * by the level's size and the subtraction of 1/2 after it cannot show).
 * 0 when a finite one is 2^31 or more in magnitude. */
static inline int quad_reduce(__m128 x, enum scene_texture_wrap wrap, __m256d *out)
{
    __m256d d = _mm256_cvtps_pd(x);
    d = _mm256_and_pd(_mm256_cmp_pd(_mm256_sub_pd(d, d), _mm256_setzero_pd(), _CMP_EQ_OQ), d);
    const __m256d magnitude = _mm256_andnot_pd(_mm256_set1_pd(-0.0), d);
    if (_mm256_movemask_pd(_mm256_cmp_pd(magnitude, _mm256_set1_pd(0x1p31), _CMP_LT_OQ)) != 15)
        return 0;
    if (wrap == SCENE_WRAP_REPEAT) {
        const __m256d f = _mm256_sub_pd(d, _mm256_floor_pd(d));
        *out = _mm256_blendv_pd(_mm256_set1_pd(0x1.fffffffffffffp-1), f,
                                _mm256_cmp_pd(f, _mm256_set1_pd(1.0), _CMP_LT_OQ));
    } else {
        *out = _mm256_min_pd(_mm256_max_pd(d, _mm256_set1_pd(-1.0)), _mm256_set1_pd(2.0));
    }
    return 1;
}

#if defined(TEXTURE_OCTS_512)
/* quad_reduce of eight coordinates in one vector: each lane the same
 * operations (a non-finite coordinate zeroed by the mask where
 * quad_reduce ands it with an all-zero compare, +0 either way; the
 * magnitude's sign cleared; the blend by a mask register). */
static inline int oct_reduce(__m256 x, enum scene_texture_wrap wrap, __m512d *out)
{
    __m512d d = _mm512_cvtps_pd(x);
    d = _mm512_maskz_mov_pd(_mm512_cmp_pd_mask(_mm512_sub_pd(d, d), _mm512_setzero_pd(),
                                               _CMP_EQ_OQ),
                            d);
    const __m512d magnitude = _mm512_andnot_pd(_mm512_set1_pd(-0.0), d);
    if (_mm512_cmp_pd_mask(magnitude, _mm512_set1_pd(0x1p31), _CMP_LT_OQ) != 0xff)
        return 0;
    if (wrap == SCENE_WRAP_REPEAT) {
        const __m512d f = _mm512_sub_pd(d, _mm512_floor_pd(d));
        *out = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(f, _mm512_set1_pd(1.0), _CMP_LT_OQ),
                                    _mm512_set1_pd(0x1.fffffffffffffp-1), f);
    } else {
        *out = _mm512_min_pd(_mm512_max_pd(d, _mm512_set1_pd(-1.0)), _mm512_set1_pd(2.0));
    }
    return 1;
}

/* A block's eight reduced coordinates along one axis, lane i point i. */
typedef __m512d texture_reduced8;
#else
typedef struct {
    __m256d half[2]; /* points 0-3 and 4-7 */
} texture_reduced8;
#endif

/* The level entry's int32 fields as gather indices: the width, the
 * height and the low half of the texel pointer (x86 is little-endian). */
typedef char texture_level_ints[sizeof(struct scene_texture_level) % sizeof(int) == 0 &&
                                        offsetof(struct scene_texture_level, texels) %
                                                sizeof(int) ==
                                            0
                                    ? 1
                                    : -1];
#define LEVEL_INTS ((int)(sizeof(struct scene_texture_level) / sizeof(int)))

/* The bilinear lookups (sample_level_reduced, LINEAR) of eight points
 * (rs, rt reduced, four a register) on the levels `level` (one a lane),
 * each lane sample_level_reduced's operations in their order: u = rs w,
 * uc = u - 1/2, its floor, the weight (float)(uc - floor), the four
 * texels wrapped as wrap_index (bilinear8_offsets: their byte offsets
 * and the weights va, vb; bilinear8_gather loads them), each channel b / 255, and
 * the nested blends of bilinear_at (bilinear8_blend).  The texels' byte
 * offsets from level 0's first texel fit int32: a chain is at most 4/3
 * of 16384^2 texels of 4 bytes, below 2^31 bytes, so one gather fetches
 * a texel of each lane. */
static inline void bilinear8_offsets(const struct scene_texture *tex, __m256i level,
                                     const texture_reduced8 *rs, const texture_reduced8 *rt,
                                     __m256i off[4], __m256 *va, __m256 *vb)
{
    const int base = (int)(uint32_t)(uintptr_t)tex->levels[0].texels;
    const int l0 = _mm256_cvtsi256_si32(level);
    __m256i w, h, first;
    if (_mm256_movemask_epi8(_mm256_cmpeq_epi32(level, _mm256_set1_epi32(l0))) == -1) {
        /* Every lane on one level (all but a few per cent of a frame's
         * lookups): its entry's fields broadcast, the integers the
         * gathers below would give every lane, without their loads on
         * the chain from the lambdas to the texel offsets. */
        const struct scene_texture_level *lv = &tex->levels[l0];
        w = _mm256_set1_epi32(lv->width);
        h = _mm256_set1_epi32(lv->height);
        first = _mm256_sub_epi32(_mm256_set1_epi32((int)(uint32_t)(uintptr_t)lv->texels),
                                 _mm256_set1_epi32(base));
    } else {
        const int *entries = (const int *)tex->levels;
        const __m256i at = _mm256_mullo_epi32(level, _mm256_set1_epi32(LEVEL_INTS));
        w = _mm256_i32gather_epi32(entries, at, 4);
        h = _mm256_i32gather_epi32(entries, _mm256_add_epi32(at, _mm256_set1_epi32(1)), 4);
        first = _mm256_sub_epi32(
            _mm256_i32gather_epi32(
                entries,
                _mm256_add_epi32(at, _mm256_set1_epi32((int)(offsetof(struct scene_texture_level,
                                                                       texels) /
                                                              sizeof(int)))),
                4),
            _mm256_set1_epi32(base));
    }
#if defined(TEXTURE_OCTS_512)
    /* The halves' steps below in one vector, each lane's the same. */
    const __m512d half = _mm512_set1_pd(0.5);
    const __m512d uc = _mm512_sub_pd(_mm512_mul_pd(*rs, _mm512_cvtepi32_pd(w)), half);
    const __m512d vc = _mm512_sub_pd(_mm512_mul_pd(*rt, _mm512_cvtepi32_pd(h)), half);
    const __m512d fi = _mm512_floor_pd(uc), fj = _mm512_floor_pd(vc);
    *va = _mm512_cvtpd_ps(_mm512_sub_pd(uc, fi));
    *vb = _mm512_cvtpd_ps(_mm512_sub_pd(vc, fj));
    const __m256i vi = _mm512_cvttpd_epi32(fi), vj = _mm512_cvttpd_epi32(fj);
#else
    const __m256d half = _mm256_set1_pd(0.5);
    __m128 a[2], b[2];
    __m128i i[2], j[2];
    for (int k = 0; k < 2; k++) {
        const __m256d wd = _mm256_cvtepi32_pd(k ? _mm256_extracti128_si256(w, 1)
                                                : _mm256_castsi256_si128(w));
        const __m256d hd = _mm256_cvtepi32_pd(k ? _mm256_extracti128_si256(h, 1)
                                                : _mm256_castsi256_si128(h));
        const __m256d uc = _mm256_sub_pd(_mm256_mul_pd(rs->half[k], wd), half);
        const __m256d vc = _mm256_sub_pd(_mm256_mul_pd(rt->half[k], hd), half);
        const __m256d fi = _mm256_floor_pd(uc), fj = _mm256_floor_pd(vc);
        a[k] = _mm256_cvtpd_ps(_mm256_sub_pd(uc, fi));
        b[k] = _mm256_cvtpd_ps(_mm256_sub_pd(vc, fj));
        i[k] = _mm256_cvttpd_epi32(fi);
        j[k] = _mm256_cvttpd_epi32(fj);
    }
    *va = _mm256_set_m128(a[1], a[0]);
    *vb = _mm256_set_m128(b[1], b[0]);
    const __m256i vi = _mm256_set_m128i(i[1], i[0]), vj = _mm256_set_m128i(j[1], j[0]);
#endif
    __m256i i0, i1, j0, j1;
    wrap_pair8(vi, w, tex->wrap_s, &i0, &i1);
    wrap_pair8(vj, h, tex->wrap_t, &j0, &j1);
    /* Rows j w: at most 2^14 by 2^14, exact in int32. */
    const __m256i r0 = _mm256_mullo_epi32(j0, w);
    const __m256i r1 = _mm256_mullo_epi32(j1, w);
    /* first + 4 (r + i) as (first + 4 r) + 4 i: each row's start and
     * each column's bytes once for the four corners (lane arithmetic is
     * modulo 2^32, so the two forms are the same integer; both are the
     * byte offset, below 2^31). */
    const __m256i row0 = _mm256_add_epi32(first, _mm256_slli_epi32(r0, 2));
    const __m256i row1 = _mm256_add_epi32(first, _mm256_slli_epi32(r1, 2));
    const __m256i col0 = _mm256_slli_epi32(i0, 2), col1 = _mm256_slli_epi32(i1, 2);
    off[0] = _mm256_add_epi32(row0, col0);
    off[1] = _mm256_add_epi32(row0, col1);
    off[2] = _mm256_add_epi32(row1, col0);
    off[3] = _mm256_add_epi32(row1, col1);
}

#if !defined(TEXTURE_OCTS_512)
/* A row's two texels (columns i0 and i0 + 1, adjacent bytes) of the
 * eight lanes from one 8-byte load a lane: two 4-lane qword gathers over
 * the lanes in the order 0, 1, 4, 5 and 2, 3, 6, 7, whose low and high
 * dwords vshufps puts back in lane order. */
static inline void bilinear8_row_pair(const int *texels, __m256i off, __m256i *left,
                                      __m256i *right)
{
    const __m256i order = _mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7);
    const __m256i o = _mm256_permutevar8x32_epi32(off, order);
    const long long *base = (const long long *)(const void *)texels;
    const __m256 a = _mm256_castsi256_ps(_mm256_i32gather_epi64(base, _mm256_castsi256_si128(o), 1));
    const __m256 b =
        _mm256_castsi256_ps(_mm256_i32gather_epi64(base, _mm256_extracti128_si256(o, 1), 1));
    *left = _mm256_castps_si256(_mm256_shuffle_ps(a, b, 0x88));
    *right = _mm256_castps_si256(_mm256_shuffle_ps(a, b, 0xdd));
}
#endif

/* The four texels at bilinear8_offsets' byte offsets off. */
static inline void bilinear8_gather(const struct scene_texture *tex, const __m256i off[4],
                                    __m256i x[4])
{
    const int *texels = (const int *)(const void *)tex->levels[0].texels;
#if !defined(TEXTURE_OCTS_512)
    /* Where every lane's second column is the next texel of its row
     * (off[1] = off[0] + 4, and then off[3] = off[2] + 4: the rows share
     * the columns), both texels of a row come from one 8-byte load, 16
     * elements in four gathers instead of 32 in four: a gather's cost
     * grows with its elements, and on AMD's Zen 3 a dword gather of
     * eight takes about 1.6 times as long as two qword gathers of four
     * with their shuffles (measured in a loop on cached texels: 13.0
     * against 8.3 ns for a block's four corners).  A lane at the last
     * column of a repeating texture (its right texel the row's first) or
     * clamped at an edge takes the dword gathers. */
    if (_mm256_movemask_epi8(_mm256_cmpeq_epi32(_mm256_sub_epi32(off[1], off[0]),
                                                _mm256_set1_epi32(4))) == -1) {
        bilinear8_row_pair(texels, off[0], &x[0], &x[1]);
        bilinear8_row_pair(texels, off[2], &x[2], &x[3]);
        return;
    }
#endif
    for (int c = 0; c < 4; c++)
        x[c] = _mm256_i32gather_epi32(texels, off[c], 1);
}

/* b / 255 of eight bytes b (int32 lanes, 0 to 255) without the divider:
 * 1/255 = 1/256 + 1/65280, so b / 255 = b 2^-8 + b / 65280, taken as
 * RN(b 2^-8 + RN(b c)) with c = RN(1/65280) = 0x1.010102p-16.  b 2^-8 is
 * exact, and this sum is the correctly rounded quotient RN(b / 255) for
 * every one of the 256 bytes (checked exhaustively, and by
 * internal/unit8_split through both units' lookups; the single product
 * RN(b RN(1/255)) misses it for 126 bytes): the same float as vdivps,
 * unit8 and the scalar path.  Two products and a sum go to the
 * pipelined multipliers and adders where twelve divisions a level
 * queued on the divider (one a channel and corner).  On round 65's Zen 4
 * it took about 7 % of finish_lod8's samples, some 0.3 ms of the frame,
 * within the clock's spread (performance-log.md, round 65, zu2). */
static inline __m256 unit8_lanes(__m256i b)
{
    const __m256 f = _mm256_cvtepi32_ps(b);
    return _mm256_add_ps(_mm256_mul_ps(f, _mm256_set1_ps(0x1p-8f)),
                         _mm256_mul_ps(f, _mm256_set1_ps(0x1.010102p-16f)));
}

/* The blends of bilinear8_gather's texels x (corners 00, 10, 01, 11)
 * with bilinear8_offsets' weights va, vb: each channel b / 255
 * (unit8_lanes), then bilinear_at's nested blends. */
static inline void bilinear8_blend(const __m256i x[4], __m256 va, __m256 vb, __m256 out[3])
{
    const __m256i byte = _mm256_set1_epi32(0xff);
#define CHANNEL(x, k) unit8_lanes(_mm256_and_si256(_mm256_srli_epi32(x, 8 * (k)), byte))
    for (int k = 0; k < 3; k++) {
        const __m256 c00 = CHANNEL(x[0], k), c10 = CHANNEL(x[1], k);
        const __m256 c01 = CHANNEL(x[2], k), c11 = CHANNEL(x[3], k);
        const __m256 bottom = _mm256_add_ps(c00, _mm256_mul_ps(va, _mm256_sub_ps(c10, c00)));
        const __m256 top = _mm256_add_ps(c01, _mm256_mul_ps(va, _mm256_sub_ps(c11, c01)));
        out[k] = _mm256_add_ps(bottom, _mm256_mul_ps(vb, _mm256_sub_ps(top, bottom)));
    }
#undef CHANNEL
}

/* bilinear8_offsets, bilinear8_gather, then bilinear8_blend. */
static inline void bilinear8(const struct scene_texture *tex, __m256i level,
                             const texture_reduced8 *rs, const texture_reduced8 *rt, __m256 out[3])
{
    __m256i off[4], x[4];
    __m256 va, vb;
    bilinear8_offsets(tex, level, rs, rt, off, &va, &vb);
    bilinear8_gather(tex, off, x);
    bilinear8_blend(x, va, vb, out);
}
#undef LEVEL_INTS

/* What scene_texture_sample_lod8 decides before its loads: the reduced
 * coordinates (rs, rt), each lane's fine and coarse level, the blend
 * weight f and the mask `two` of the lanes that blend two levels.
 * Returns 0 where sample_lod8 does not take the block. */
struct lod8_plan {
    texture_reduced8 rs, rt;
    __m256i fine, coarse;
    __m256 f, two;
};

static inline int lod8_plan(const struct scene_texture *tex, const float lambda[8],
                            const float s[8], const float t[8], struct lod8_plan *p)
{
    if (tex->min_filter != SCENE_FILTER_LINEAR_MIPMAP_LINEAR ||
        tex->mag_filter != SCENE_FILTER_LINEAR)
        return 0;
#if defined(TEXTURE_OCTS_512)
    if (!oct_reduce(_mm256_loadu_ps(s), tex->wrap_s, &p->rs) ||
        !oct_reduce(_mm256_loadu_ps(t), tex->wrap_t, &p->rt))
        return 0;
#else
    for (int k = 0; k < 2; k++)
        if (!quad_reduce(_mm_loadu_ps(s + 4 * k), tex->wrap_s, &p->rs.half[k]) ||
            !quad_reduce(_mm_loadu_ps(t + 4 * k), tex->wrap_t, &p->rt.half[k]))
            return 0;
#endif
    const __m256 lam = _mm256_loadu_ps(lambda);
    const int q = tex->level_count - 1;
    /* c = 0 for these filters: lambda > 0 minifies (a NaN does not). */
    const __m256 minified = _mm256_cmp_ps(lam, _mm256_setzero_ps(), _CMP_GT_OQ);
    const __m256 last =
        _mm256_and_ps(minified, _mm256_cmp_ps(lam, _mm256_set1_ps((float)q), _CMP_GE_OQ));
    p->two = _mm256_andnot_ps(last, minified);
    /* floorf(lambda) for 0 < lambda < q by the truncation, as the
     * scalar path; the other lanes' values are not used. */
    const __m256i d1 = _mm256_cvttps_epi32(lam);
    p->f = _mm256_sub_ps(lam, _mm256_cvtepi32_ps(d1));
    const __m256i two_i = _mm256_castps_si256(p->two);
    p->fine = _mm256_blendv_epi8(
        _mm256_and_si256(_mm256_castps_si256(last), _mm256_set1_epi32(q)), d1, two_i);
    p->coarse = _mm256_sub_epi32(p->fine, two_i); /* + 1 where two levels */
    return 1;
}

/* sample_lod8's last step: a lane's fine colour c0, or where it blends
 * two levels fine + f (coarse - fine), as the scalar loop. */
static inline void lod8_store(const __m256 c0[3], const __m256 c1[3], __m256 f, __m256 two,
                              float rgb[3][8])
{
    for (int k = 0; k < 3; k++)
        _mm256_storeu_ps(
            rgb[k], _mm256_blendv_ps(c0[k],
                                     _mm256_add_ps(c0[k], _mm256_mul_ps(f, _mm256_sub_ps(c1[k], c0[k]))),
                                     two));
}

/*
 * scene_texture_sample_lod of eight lookups, LINEAR_MIPMAP_LINEAR and
 * LINEAR only: each lane takes scene_texture_sample_lod's branch by its
 * own lambda (a magnification: level 0; from the last level q on: level
 * q; between: levels floor(lambda) and the next, blended by the
 * fraction), all lanes through two bilinear lookups (bilinear8), a lane
 * with one level looking it up twice and keeping the first; the blend
 * fine + f (coarse - fine) as the scalar loop's.
 */
int scene_texture_sample_lod8(const struct scene_texture *tex, const float lambda[8],
                              const float s[8], const float t[8], float rgb[3][8])
{
    struct lod8_plan p;
    if (!lod8_plan(tex, lambda, s, t, &p))
        return 0;
    __m256 c0[3], c1[3];
    bilinear8(tex, p.fine, &p.rs, &p.rt, c0);
    if (!_mm256_movemask_ps(p.two)) {
        /* One level in every lane (magnified, or at the last level). */
        for (int k = 0; k < 3; k++)
            _mm256_storeu_ps(rgb[k], c0[k]);
        return 1;
    }
    bilinear8(tex, p.coarse, &p.rs, &p.rt, c1);
    lod8_store(c0, c1, p.f, p.two, rgb);
    return 1;
}

int scene_texture_prefetch_lod8(const struct scene_texture *tex, const float lambda[8],
                             const float s[8], const float t[8],
                             struct scene_texture_lookup8 *out)
{
    struct lod8_plan p;
    if (!lod8_plan(tex, lambda, s, t, &p))
        return 0;
    /* The same levels and texels as sample_lod8: their byte offsets
     * (int32) and the weights (float) stored as computed, exact; the
     * loads and blends left to scene_texture_finish_lod8.  The lines of
     * the block's corner lanes (0 and 7: a 4 x 2 block's texels lie
     * between them) on both rows asked for now, a hint that reads no
     * value, so that they are in the cache by then. */
    const char *texels = (const char *)tex->levels[0].texels;
    out->tex = tex;
    out->levels = _mm256_movemask_ps(p.two) ? 2 : 1;
    for (int l = 0; l < out->levels; l++) {
        __m256i off[4];
        __m256 va, vb;
        bilinear8_offsets(tex, l ? p.coarse : p.fine, &p.rs, &p.rt, off, &va, &vb);
        for (int c = 0; c < 4; c++)
            _mm256_storeu_si256((__m256i *)(void *)out->offset[l][c], off[c]);
        _mm256_storeu_ps(out->a[l], va);
        _mm256_storeu_ps(out->b[l], vb);
        _mm_prefetch(texels + out->offset[l][0][0], _MM_HINT_T0);
        _mm_prefetch(texels + out->offset[l][2][0], _MM_HINT_T0);
        _mm_prefetch(texels + out->offset[l][0][7], _MM_HINT_T0);
        _mm_prefetch(texels + out->offset[l][2][7], _MM_HINT_T0);
    }
    _mm256_storeu_ps(out->f, p.f);
    _mm256_storeu_ps(out->two, p.two);
    return 1;
}

void scene_texture_finish_lod8(const struct scene_texture_lookup8 *in, float rgb[3][8])
{
    __m256 c[2][3];
    for (int l = 0; l < in->levels; l++) {
        __m256i off[4], x[4];
        for (int k = 0; k < 4; k++)
            off[k] = _mm256_loadu_si256((const __m256i *)(const void *)in->offset[l][k]);
        bilinear8_gather(in->tex, off, x);
        bilinear8_blend(x, _mm256_loadu_ps(in->a[l]), _mm256_loadu_ps(in->b[l]), c[l]);
    }
    if (in->levels == 1) {
        for (int k = 0; k < 3; k++)
            _mm256_storeu_ps(rgb[k], c[0][k]);
        return;
    }
    lod8_store(c[0], c[1], _mm256_loadu_ps(in->f), _mm256_loadu_ps(in->two), rgb);
}
#endif

void scene_texture_sample_level(const struct scene_texture *tex, int level,
                                enum scene_texture_filter filter, float s, float t,
                                float rgba[4])
{
    sample_level_reduced(tex, level, filter, reduce_coord(s, tex->wrap_s),
                         reduce_coord(t, tex->wrap_t), rgba);
}

void scene_texture_sample(const struct scene_texture *tex, enum scene_texture_filter filter,
                          float s, float t, float rgba[4])
{
    scene_texture_sample_level(tex, 0, filter, s, t, rgba);
}

void scene_texture_sample_lod(const struct scene_texture *tex, float lambda, float s, float t,
                              float rgba[4])
{
    const enum scene_texture_filter min = tex->min_filter;
    /* GL 1.1 sec. 3.8.2: the switch-over point c is 0.5 for a LINEAR
     * magnification with a NEAREST_MIPMAP_* minification, "to ensure that
     * a minified texture does not appear sharper than a magnified
     * texture"; otherwise 0. */
    const float c = tex->mag_filter == SCENE_FILTER_LINEAR &&
                            (min == SCENE_FILTER_NEAREST_MIPMAP_NEAREST ||
                             min == SCENE_FILTER_NEAREST_MIPMAP_LINEAR)
                        ? 0.5f
                        : 0.0f;
    if (!(lambda > c)) { /* magnification; also a NaN lambda */
        scene_texture_sample_level(tex, 0, tex->mag_filter, s, t, rgba);
        return;
    }
    if (min == SCENE_FILTER_NEAREST || min == SCENE_FILTER_LINEAR) {
        scene_texture_sample_level(tex, 0, min, s, t, rgba);
        return;
    }
    /* GL 1.1 sec. 3.8.1, "Mipmapping"; q is the last level. */
    const int q = tex->level_count - 1;
    if (min == SCENE_FILTER_NEAREST_MIPMAP_NEAREST || min == SCENE_FILTER_LINEAR_MIPMAP_NEAREST) {
        /* d = 0 for lambda <= 1/2, ceil(lambda + 1/2) - 1 up to q + 1/2,
         * then q: the level nearest to lambda, ties to the finer one. */
        int d = 0;
        if (lambda > (float)q + 0.5f)
            d = q;
        else if (lambda > 0.5f)
            d = (int)ceilf(lambda + 0.5f) - 1;
        scene_texture_sample_level(tex, d, min, s, t, rgba);
        return;
    }
    /* *_MIPMAP_LINEAR: levels d1 = floor(lambda) and d1 + 1 blended by
     * frac(lambda); from lambda >= q on, level q alone. */
    if (lambda >= (float)q) {
        scene_texture_sample_level(tex, q, min, s, t, rgba);
        return;
    }
    /* floorf(lambda) for c < lambda < q: the truncation of a positive
     * float below 2^31 is its floor, without the library call. */
    const float d1 = (float)(int)lambda, f = lambda - d1;
    float fine[4], coarse[4];
#if TEXTURE_LANES
    if (min == SCENE_FILTER_LINEAR_MIPMAP_LINEAR) {
        __m128d rst;
        if (!pair_reduce(s, t, tex->wrap_s, tex->wrap_t, &rst))
            rst = _mm_set_pd(reduce_coord(t, tex->wrap_t), reduce_coord(s, tex->wrap_s));
        sample_trilinear(tex, (int)d1, rst, f, rgba);
        return;
    }
#endif
    const double rs = reduce_coord(s, tex->wrap_s), rt = reduce_coord(t, tex->wrap_t);
    sample_level_reduced(tex, (int)d1, min, rs, rt, fine);
    sample_level_reduced(tex, (int)d1 + 1, min, rs, rt, coarse);
    /* As the bilinear weights: equal levels give exactly their value. */
    for (int k = 0; k < 4; k++)
        rgba[k] = fine[k] + f * (coarse[k] - fine[k]);
}
