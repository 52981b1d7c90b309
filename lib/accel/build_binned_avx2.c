/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_binned_avx2.c - the binned builders' two loops over a node's
 * refs, the histogram (build_internal.h, build_fill_bins) and the
 * partition (build_partition_fn), in AVX2 forms (CMakeLists.txt gives
 * this file -mavx2 and -ffp-contract=off, no FMA) that give the portable
 * forms' bytes; and the histogram form the binned builders take, which
 * fills a large node's refs in four streams (fill_four_streams says why and why the
 * bytes are the same).
 *
 * The histogram.  A bin's 32-byte record is its box, min xyz - then max xyz -.  While
 * the loop runs, the max half is kept negated, so that a ref grows the
 * whole record with one 256-bit min against (lo, -hi) instead of a
 * 128-bit min and a 128-bit max with their loads and stores: the loop
 * is 32 instructions a ref against the portable form's 43 (GCC 12),
 * and a one-thread binned build of a million triangles (rtbench's bumpy)
 * 2,472 M -> 2,271 M instructions.  max(a, b) = -min(-a, -b) bit for bit in the SSE
 * semantics both forms use: maxps(a, b) is a > b ? a : b and
 * minps(-a, -b) is -a < -b ? -a : -b, the same comparison, so the same
 * operand is chosen, also on equal zeros and when either is NaN (the
 * comparison is false and b is taken); negation is exact.  The operands
 * stay in the portable form's order (the bin first, the ref second).
 * The bins start at +inf in all eight lanes (-inf negated), and their max
 * halves are negated back at the end.  The bin of a ref is
 * build_bin_offsets, the very computation of the portable form (the same
 * IEEE operations, VEX-encoded), so every bin gets the same refs and the
 * histogram the same bytes.  Under RT_NO_SIMD, or where the compiler
 * does not target AVX2, the unit is absent.
 */
#include "accel/build_internal.h"

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
#include <immintrin.h>

static void fill_bins_avx2(char *box_base, char *count_base, const uint32_t axis_base[4],
                           int bin_count, const struct build_bin_map *map,
                           const struct build_ref *refs, uint32_t begin, uint32_t end)
{
    /* The axes' first records, read once: the stores through char
     * pointers below could alias axis_base. */
    const size_t first[3] = {axis_base[0], axis_base[1], axis_base[2]};
    const size_t bytes = 32u * (size_t)bin_count;
    const __m256 empty = _mm256_set1_ps(INFINITY);
    for (int k = 0; k < 3; k++) {
        for (size_t off = first[k]; off < first[k] + bytes; off += 32) {
            _mm256_storeu_ps((float *)(void *)(box_base + off), empty);
            *(uint32_t *)(void *)(count_base + off) = 0;
        }
    }
    /* Lane 3 (the ref's index, whose bits would be denormal floats) to
     * 0, as vec4_xyz0 in the portable form; lanes 4-7 (the max) negated. */
    const __m256 keep = _mm256_castsi256_ps(_mm256_setr_epi32(-1, -1, -1, 0, -1, -1, -1, -1));
    const __m256 negate_hi =
        _mm256_setr_ps(0.0f, 0.0f, 0.0f, 0.0f, -0.0f, -0.0f, -0.0f, -0.0f);
    for (uint32_t i = begin; i < end; i++) {
        const __m256 r = _mm256_and_ps(_mm256_loadu_ps(refs[i].lo), keep);
        uint32_t off[4];
        build_bin_offsets(map, vec4_add(_mm256_castps256_ps128(r), _mm256_extractf128_ps(r, 1)),
                          axis_base, off);
        const __m256 key = _mm256_xor_ps(r, negate_hi);
        for (int k = 0; k < 3; k++) {
            float *box = (float *)(void *)(box_base + off[k]);
            _mm256_storeu_ps(box, _mm256_min_ps(_mm256_loadu_ps(box), key));
            (*(uint32_t *)(void *)(count_base + off[k]))++;
        }
    }
    for (int k = 0; k < 3; k++) {
        for (size_t off = first[k]; off < first[k] + bytes; off += 32) {
            float *box = (float *)(void *)(box_base + off);
            _mm256_storeu_ps(box, _mm256_xor_ps(_mm256_loadu_ps(box), negate_hi));
        }
    }
}

/* One ref into a histogram whose axis k starts at box[k] (boxes, max
 * half negated) and count[k] (counts, 32-byte stride): the bins of the
 * ref's doubled centroid (build_bin_offsets, from zero), each grown by
 * one 256-bit min and counted.  Returns the ref's key (lo, -hi). */
static inline __m256 fill_one(char *const box[3], char *const count[3],
                              const struct build_bin_map *map, const float *ref, __m256 keep,
                              __m256 negate_hi)
{
    static const uint32_t zero[4] = {0, 0, 0, 0};
    const __m256 r = _mm256_and_ps(_mm256_loadu_ps(ref), keep);
    uint32_t off[4];
    build_bin_offsets(map, vec4_add(_mm256_castps256_ps128(r), _mm256_extractf128_ps(r, 1)), zero,
                      off);
    const __m256 key = _mm256_xor_ps(r, negate_hi);
    for (int k = 0; k < 3; k++) {
        float *b = (float *)(void *)(box[k] + off[k]);
        _mm256_storeu_ps(b, _mm256_min_ps(_mm256_loadu_ps(b), key));
        (*(uint32_t *)(void *)(count[k] + off[k]))++;
    }
    return key;
}

/* Four streams from this many refs on, for at most FILL_STREAM_BINS
 * bins an axis (the three extra histograms are on the stack, 9 KB; the
 * builders' default is 16 bins).  The four-stream loop costs about 7 %
 * more instructions a ref than the one-stream loop (the NaN checks, the
 * extra histograms' pointers), which pays where the chains were long:
 * bumpy's stage-1 chunks and large deferred nodes (a regular grid, whose
 * neighbouring triangles share bins).  From 1,024 refs on, the kitchen's
 * parallel build did 3 % more instructions and its two-thread CPU time
 * went both ways (6 of 8 alternated pairs lower, 2 higher); from 16,384
 * its two-thread chunks (n / 8 refs, 13,820) and deferred nodes keep the
 * one-stream loop and bumpy keeps the gain.  With this threshold the
 * serial builder's top nodes take it too (its in-place partition keeps
 * the left sides in the input's order): its binary build's CPU time
 * bumpy -7 to -10 %, the kitchen -4 %, the soup lower (two rounds of
 * old new new old). */
#define FILL_STREAM_MIN_REFS 16384
#define FILL_STREAM_BINS 16

/*
 * Why four streams.  A ref's three bins are read, min'ed and stored, and
 * the next ref's read of the same bin waits for that store: neighbouring
 * refs of a mesh fall in the same bins, and the parallel builder's
 * stable partitions keep them neighbours, so the loop is one long chain
 * of store-to-load forwards.  The node's refs are cut into four runs s0,
 * s1, s2, s3 (quarters, the last one taking the remainder), s0 filled
 * into the caller's bins and s1-s3 each into a histogram of its own on
 * the stack, one ref of each run a step: the runs are far apart in the
 * mesh and mostly hit other bins, so four chains run side by side.
 * Then s1's, s2's and s3's histograms are merged into the caller's, in
 * that order, bin by bin.
 *
 * Why the merge gives the one-stream loop's bits.  Per lane the loop is
 * the fold v <- (v < x ? v : x) (minps, the bin first) over the refs in
 * order from +inf.  Without NaN among the x, a fold from any non-NaN v
 * over a non-empty run s ends at v when v < m, m the numerical minimum
 * of s, and otherwise at the LAST element of s equal to m (each x == m
 * replaces v, since v < x is false on equal values, -0 and +0 included,
 * and nothing below m comes).  So a run's own histogram, B = fold(+inf,
 * s), holds that last element, and fold(A, s) = (A < B ? A : B) =
 * minps(A, B): the same operand picked, sign of a zero included.  From a
 * NaN v the first x replaces it, so fold(NaN, s) = fold(+inf, s) = B =
 * minps(NaN, B) too.  A bin that the run never reached keeps A, as the
 * one-stream loop does: the merge skips bins whose count in B is 0
 * (minps(NaN, +inf) would not keep a NaN A).  Applied run after run,
 * fold(+inf, s0 s1 s2 s3) = fold(fold(fold(fold(+inf, s0), s1), s2), s3)
 * is the caller's bins merged with s1's, then s2's, then s3's.  The max
 * halves are negated minima, the same argument.  A NaN inside s1-s3 (a
 * caller's non-finite box; triangle boxes never hold one, build.c)
 * would break it, so those runs OR an unordered self-comparison of their
 * keys, and if any lane was NaN the caller's histogram is filled again
 * by the one-stream loop; with check_nan 0 the caller has seen every
 * ref's box free of NaN (build_fill_bins_ordered_finite_avx2_unit), and
 * the checks, 1.5 instructions a ref, are left out.  Counts are sums.  The trees are the same
 * bytes (rtbench build, the builders' and invariance tests).
 */
__attribute__((always_inline)) static inline int
fill_four_streams(char *const box_a[3], char *const count_a[3], int bin_count,
                  const struct build_bin_map *map, const struct build_ref *refs, uint32_t begin,
                  uint32_t end, __m256 keep, __m256 negate_hi, int check_nan)
{
    __m256 box_rec[3][3 * FILL_STREAM_BINS];         /* 32-byte aligned records */
    uint32_t count_rec[3][3 * FILL_STREAM_BINS * 8]; /* a count every 32 bytes */
    const size_t bytes = 32u * (size_t)bin_count;
    char *box_s[3][3];
    char *count_s[3][3];
    const __m256 empty = _mm256_set1_ps(INFINITY);
    for (int s = 0; s < 3; s++) {
        char *bb = (char *)box_rec[s];
        char *cb = (char *)count_rec[s];
        for (int k = 0; k < 3; k++) {
            box_s[s][k] = bb + k * bytes;
            count_s[s][k] = cb + k * bytes;
        }
        for (size_t off = 0; off < 3 * bytes; off += 32) {
            _mm256_store_ps((float *)(void *)(bb + off), empty);
            *(uint32_t *)(void *)(cb + off) = 0;
        }
    }
    const uint32_t q = (end - begin) / 4;
    const uint32_t b1 = begin + q;
    const uint32_t b2 = begin + 2 * q;
    const uint32_t b3 = begin + 3 * q;
    __m256 nan = _mm256_setzero_ps();
    for (uint32_t i = 0; i < q; i++) {
        fill_one(box_a, count_a, map, refs[begin + i].lo, keep, negate_hi);
        const __m256 k1 = fill_one(box_s[0], count_s[0], map, refs[b1 + i].lo, keep, negate_hi);
        const __m256 k2 = fill_one(box_s[1], count_s[1], map, refs[b2 + i].lo, keep, negate_hi);
        const __m256 k3 = fill_one(box_s[2], count_s[2], map, refs[b3 + i].lo, keep, negate_hi);
        if (check_nan) {
            nan = _mm256_or_ps(nan, _mm256_cmp_ps(k1, k1, _CMP_UNORD_Q));
            nan = _mm256_or_ps(nan, _mm256_cmp_ps(k2, k2, _CMP_UNORD_Q));
            nan = _mm256_or_ps(nan, _mm256_cmp_ps(k3, k3, _CMP_UNORD_Q));
        }
    }
    /* s3's remainder, after its first q refs, in order. */
    for (uint32_t i = b3 + q; i < end; i++) {
        const __m256 k3 = fill_one(box_s[2], count_s[2], map, refs[i].lo, keep, negate_hi);
        if (check_nan)
            nan = _mm256_or_ps(nan, _mm256_cmp_ps(k3, k3, _CMP_UNORD_Q));
    }
    if (check_nan && _mm256_movemask_ps(nan))
        return 0;
    for (int s = 0; s < 3; s++) {
        for (int k = 0; k < 3; k++) {
            for (size_t off = 0; off < bytes; off += 32) {
                const uint32_t nb = *(const uint32_t *)(const void *)(count_s[s][k] + off);
                if (!nb)
                    continue;
                float *a = (float *)(void *)(box_a[k] + off);
                const __m256 b = _mm256_load_ps((const float *)(const void *)(box_s[s][k] + off));
                _mm256_storeu_ps(a, _mm256_min_ps(_mm256_loadu_ps(a), b));
                *(uint32_t *)(void *)(count_a[k] + off) += nb;
            }
        }
    }
    return 1;
}

/* The binned builders' form (build_fill_bins_ordered_best): a node of
 * FILL_STREAM_MIN_REFS refs or more in four streams, else and after a NaN
 * the one-stream loop of fill_bins_avx2 (the same steps, fill_one).
 * check_nan 0: the caller promises refs without NaN (fill_four_streams). */
__attribute__((always_inline)) static inline void
fill_bins_streams(char *box_base, char *count_base, const uint32_t axis_base[4], int bin_count,
                  const struct build_bin_map *map, const struct build_ref *refs, uint32_t begin,
                  uint32_t end, int check_nan)
{
    /* The axes' first records, read once: the stores through char
     * pointers below could alias axis_base. */
    const size_t first[3] = {axis_base[0], axis_base[1], axis_base[2]};
    const size_t bytes = 32u * (size_t)bin_count;
    char *const box[3] = {box_base + first[0], box_base + first[1], box_base + first[2]};
    char *const count[3] = {count_base + first[0], count_base + first[1], count_base + first[2]};
    const __m256 empty = _mm256_set1_ps(INFINITY);
    /* Lane 3 (the ref's index, whose bits would be denormal floats) to
     * 0, as vec4_xyz0 in the portable form; lanes 4-7 (the max) negated. */
    const __m256 keep = _mm256_castsi256_ps(_mm256_setr_epi32(-1, -1, -1, 0, -1, -1, -1, -1));
    const __m256 negate_hi =
        _mm256_setr_ps(0.0f, 0.0f, 0.0f, 0.0f, -0.0f, -0.0f, -0.0f, -0.0f);
    int done = 0;
    for (int pass = 0; !done; pass++) {
        for (int k = 0; k < 3; k++) {
            for (size_t off = 0; off < bytes; off += 32) {
                _mm256_storeu_ps((float *)(void *)(box[k] + off), empty);
                *(uint32_t *)(void *)(count[k] + off) = 0;
            }
        }
        /* Four streams for a large node; a second pass (after a NaN in
         * s1-s3) and small nodes take the one-stream loop. */
        if (pass == 0 && end - begin >= FILL_STREAM_MIN_REFS && bin_count <= FILL_STREAM_BINS) {
            done = fill_four_streams(box, count, bin_count, map, refs, begin, end, keep, negate_hi,
                                     check_nan);
        } else {
            for (uint32_t i = begin; i < end; i++)
                fill_one(box, count, map, refs[i].lo, keep, negate_hi);
            done = 1;
        }
    }
    for (int k = 0; k < 3; k++) {
        for (size_t off = 0; off < bytes; off += 32) {
            float *b = (float *)(void *)(box[k] + off);
            _mm256_storeu_ps(b, _mm256_xor_ps(_mm256_loadu_ps(b), negate_hi));
        }
    }
}

static void fill_bins_streams_avx2(char *box_base, char *count_base, const uint32_t axis_base[4],
                                   int bin_count, const struct build_bin_map *map,
                                   const struct build_ref *refs, uint32_t begin, uint32_t end)
{
    fill_bins_streams(box_base, count_base, axis_base, bin_count, map, refs, begin, end, 1);
}

static void fill_bins_streams_finite_avx2(char *box_base, char *count_base,
                                          const uint32_t axis_base[4], int bin_count,
                                          const struct build_bin_map *map,
                                          const struct build_ref *refs, uint32_t begin,
                                          uint32_t end)
{
    fill_bins_streams(box_base, count_base, axis_base, bin_count, map, refs, begin, end, 0);
}

/*
 * The partition (build_partition_fn).  Per ref the same steps as the
 * portable loops: the doubled centroid lo + hi (lane 3 of lo masked),
 * the side from one comparison with the threshold, the side bounds grown
 * by build_side_offset's additions, and the 32-byte move(s).  The moves
 * are one 256-bit load and store each instead of two 128-bit ones, and a
 * side's bounds (lo, hi) are one 256-bit record with hi negated, grown by
 * one min: (c + offset_lo, -(c + offset_hi)), the sum computed as in the
 * portable form and then negated, so the max is again -min(-a, -b) on
 * the very values the portable form takes the max of.
 */
static inline __m256 side_value(__m256 c2, const float *offset, __m256 negate_hi)
{
    return _mm256_xor_ps(_mm256_add_ps(c2, _mm256_loadu_ps(offset)), negate_hi);
}

static void store_bounds(float bounds[4][4], __m256 left, __m256 right, __m256 negate_hi)
{
    left = _mm256_xor_ps(left, negate_hi);
    right = _mm256_xor_ps(right, negate_hi);
    _mm_storeu_ps(bounds[0], _mm256_castps256_ps128(left));
    _mm_storeu_ps(bounds[1], _mm256_extractf128_ps(left, 1));
    _mm_storeu_ps(bounds[2], _mm256_castps256_ps128(right));
    _mm_storeu_ps(bounds[3], _mm256_extractf128_ps(right, 1));
}

static uint32_t partition_avx2(const struct build_ref *src, struct build_ref *dst,
                               uint32_t begin, uint32_t end, uint32_t left_dst,
                               uint32_t right_dst, int axis, float threshold,
                               float bounds[4][4])
{
    const __m256 keep = _mm256_castsi256_ps(_mm256_setr_epi32(-1, -1, -1, 0, -1, -1, -1, -1));
    const __m256 negate_hi =
        _mm256_setr_ps(0.0f, 0.0f, 0.0f, 0.0f, -0.0f, -0.0f, -0.0f, -0.0f);
    const __m128 t = _mm_set1_ps(threshold);
    __m256 left_bounds = _mm256_set1_ps(INFINITY);
    __m256 right_bounds = left_bounds;
    if (!dst) {
        /* In place: build_binned_sah.c's Lomuto loop, every ref swapped
         * with the first right slot, which advances past left ones. */
        struct build_ref *refs = (struct build_ref *)src;
        uint32_t first_right = begin;
        for (uint32_t i = begin; i < end; i++) {
            const __m256 x = _mm256_loadu_ps(refs[i].lo);
            const __m256 xm = _mm256_and_ps(x, keep);
            const __m128 c = _mm_add_ps(_mm256_castps256_ps128(xm), _mm256_extractf128_ps(x, 1));
            const uint32_t left =
                (((uint32_t)_mm_movemask_ps(_mm_cmpge_ps(c, t)) >> axis) & 1u) ^ 1u;
            const __m256 c2 = _mm256_set_m128(c, c);
            const float *off = &build_side_offset[left][0][0];
            left_bounds = _mm256_min_ps(left_bounds, side_value(c2, off, negate_hi));
            right_bounds = _mm256_min_ps(right_bounds, side_value(c2, off + 8, negate_hi));
            _mm256_storeu_ps(refs[i].lo, _mm256_loadu_ps(refs[first_right].lo));
            _mm256_storeu_ps(refs[first_right].lo, x);
            first_right += left;
        }
        store_bounds(bounds, left_bounds, right_bounds, negate_hi);
        return first_right;
    }
    /* Stable, into dst: build_parallel.c's partition_task. */
    uint32_t li = left_dst;
    uint32_t ri = right_dst;
    for (uint32_t i = begin; i < end; i++) {
        const __m256 x = _mm256_loadu_ps(src[i].lo);
        const __m256 xm = _mm256_and_ps(x, keep);
        const __m128 c = _mm_add_ps(_mm256_castps256_ps128(xm), _mm256_extractf128_ps(x, 1));
        const uint32_t left = (((uint32_t)_mm_movemask_ps(_mm_cmpge_ps(c, t)) >> axis) & 1u) ^ 1u;
        const __m256 c2 = _mm256_set_m128(c, c);
        const float *off = &build_side_offset[left][0][0];
        left_bounds = _mm256_min_ps(left_bounds, side_value(c2, off, negate_hi));
        right_bounds = _mm256_min_ps(right_bounds, side_value(c2, off + 8, negate_hi));
        /* The slot without a branch (the sides are effectively random,
         * build_binned_sah.c's partition note): li when left, else ri. */
        const uint32_t slot = ri ^ ((li ^ ri) & (0u - left));
        _mm256_storeu_ps(dst[slot].lo, x);
        li += left;
        ri += 1 - left;
    }
    store_bounds(bounds, left_bounds, right_bounds, negate_hi);
    return li;
}

/* The compiler's cpuid wrapper, as trace/kernels.c: it also checks that
 * the operating system saves the AVX registers. */
int build_cpu_runs_avx2(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") ? 1 : 0;
}

build_fill_bins_fn build_fill_bins_avx2_unit(void)
{
    return build_cpu_runs_avx2() ? fill_bins_avx2 : NULL;
}

build_fill_bins_fn build_fill_bins_ordered_avx2_unit(void)
{
    return build_cpu_runs_avx2() ? fill_bins_streams_avx2 : NULL;
}

build_fill_bins_fn build_fill_bins_ordered_finite_avx2_unit(void)
{
    return build_cpu_runs_avx2() ? fill_bins_streams_finite_avx2 : NULL;
}

build_partition_fn build_partition_avx2_unit(void)
{
    return build_cpu_runs_avx2() ? partition_avx2 : NULL;
}
#else
int build_cpu_runs_avx2(void)
{
    return 0;
}

build_fill_bins_fn build_fill_bins_avx2_unit(void)
{
    return NULL;
}

build_fill_bins_fn build_fill_bins_ordered_avx2_unit(void)
{
    return NULL;
}

build_fill_bins_fn build_fill_bins_ordered_finite_avx2_unit(void)
{
    return NULL;
}

build_partition_fn build_partition_avx2_unit(void)
{
    return NULL;
}
#endif
