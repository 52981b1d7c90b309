/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_bins.c - the binned builders' histogram loop (build_internal.h,
 * build_fill_bins), portable form, and the choice of form.
 *
 * The loop is the largest part of a binned build (a third of the
 * instructions of a one-thread build of a million triangles): per ref
 * and axis one box grown by a min and a max, and a count.
 * build_binned_avx2.c does the same with one 256-bit min per bin.
 */
#include "accel/build_internal.h"

void build_fill_bins(char *box_base, char *count_base, const uint32_t axis_base[4],
                     int bin_count, const struct build_bin_map *map,
                     const struct build_ref *refs, uint32_t begin, uint32_t end)
{
    /* The axes' first records, read once: the stores through char
     * pointers below could alias axis_base. */
    const size_t first[3] = {axis_base[0], axis_base[1], axis_base[2]};
    const size_t bytes = 32u * (size_t)bin_count;
    const vec4 empty_lo = vec4_splat(INFINITY);
    const vec4 empty_hi = vec4_splat(-INFINITY);
    for (int k = 0; k < 3; k++) {
        for (size_t off = first[k]; off < first[k] + bytes; off += 32) {
            float *box = (float *)(void *)(box_base + off);
            vec4_store(&box[0], empty_lo);
            vec4_store(&box[4], empty_hi);
            *(uint32_t *)(void *)(count_base + off) = 0;
        }
    }
    for (uint32_t i = begin; i < end; i++) {
        const struct build_ref *r = &refs[i];
        /* Lane 3 masked: the index's bits would be denormal floats, and
         * arithmetic on denormals can cost a microcode assist each. */
        vec4 lo = vec4_xyz0(vec4_load(r->lo));
        vec4 hi = vec4_load(r->hi);
        uint32_t off[4];
        build_bin_offsets(map, vec4_add(lo, hi), axis_base, off);
        for (int k = 0; k < 3; k++) {
            float *box = (float *)(void *)(box_base + off[k]);
            vec4_store(&box[0], vec4_min(vec4_load(&box[0]), lo));
            vec4_store(&box[4], vec4_max(vec4_load(&box[4]), hi));
            (*(uint32_t *)(void *)(count_base + off[k]))++;
        }
    }
}

build_fill_bins_fn build_fill_bins_best(void)
{
    build_fill_bins_fn avx2 = build_fill_bins_avx2_unit();
    return avx2 ? avx2 : build_fill_bins;
}

build_fill_bins_fn build_fill_bins_ordered_best(void)
{
    build_fill_bins_fn avx2 = build_fill_bins_ordered_avx2_unit();
    return avx2 ? avx2 : build_fill_bins;
}

build_fill_bins_fn build_fill_bins_ordered_finite_best(int finite)
{
    build_fill_bins_fn avx2 = finite ? build_fill_bins_ordered_finite_avx2_unit() : NULL;
    return avx2 ? avx2 : build_fill_bins_ordered_best();
}
