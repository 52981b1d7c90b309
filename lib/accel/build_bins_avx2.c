/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_bins_avx2.c - the binned builders' histogram loop
 * (build_internal.h, build_fill_bins) compiled for AVX2 (CMakeLists.txt
 * gives this file -mavx2 and -ffp-contract=off, no FMA).
 *
 * A bin's 32-byte record is its box, min xyz - then max xyz -.  While
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

build_fill_bins_fn build_fill_bins_avx2_unit(void)
{
    /* The compiler's cpuid wrapper, as trace/kernels.c: it also checks
     * that the operating system saves the AVX registers. */
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") ? fill_bins_avx2 : NULL;
}
#else
build_fill_bins_fn build_fill_bins_avx2_unit(void)
{
    return NULL;
}
#endif
