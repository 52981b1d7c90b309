/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_binned_avx2.c - the binned builders' two loops over a node's
 * refs, the histogram (build_internal.h, build_fill_bins) and the
 * partition (build_partition_fn), in AVX2 forms (CMakeLists.txt gives
 * this file -mavx2 and -ffp-contract=off, no FMA) that give the portable
 * forms' bytes.
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

build_partition_fn build_partition_avx2_unit(void)
{
    return NULL;
}
#endif
