/* SPDX-License-Identifier: Apache-2.0 */
/*
 * build_binned_sah_avx2.c - the binned SAH builder (build_binned_sah.c)
 * compiled again with AVX2 enabled (CMakeLists.txt gives this file -mavx2
 * and -ffp-contract=off, no FMA), as render_avx2.c does for the frame's
 * packet loop.  The source is the same, included with its external
 * function renamed (build_binned_sah_source_avx2), so every float
 * operation is the same IEEE operation in the same order, only
 * VEX-encoded: three operands, so the register copies before most SSE
 * operations go (find_best_split's sweep: 67 instructions a bin in the
 * SSE2 encoding), and the same trees bit for bit.  build_binned_sah_source
 * calls this copy when the CPU runs AVX2 (build_cpu_runs_avx2).  Under
 * RT_NO_SIMD, or where the compiler does not target AVX2, the unit is
 * absent (accel_build_binned_sah_avx2_unit returns NULL).
 */
#include "accel/build_internal.h"

#if defined(__AVX2__) && !defined(RT_NO_SIMD)
#define BUILD_BINNED_UNIT_AVX2 1
#define accel_build_binned_sah accel_build_binned_sah_avx2
#define build_binned_sah_forms build_binned_sah_forms_avx2
#define build_binned_sah_source build_binned_sah_source_avx2
#define build_binned_sah_refs build_binned_sah_refs_avx2

#include "accel/build_binned_sah.c"

build_binned_fn accel_build_binned_sah_avx2_unit(void)
{
    return build_cpu_runs_avx2() ? build_binned_sah_source_avx2 : NULL;
}

build_binned_refs_fn build_binned_sah_refs_avx2_unit(void)
{
    return build_cpu_runs_avx2() ? build_binned_sah_refs_avx2 : NULL;
}
#else
build_binned_fn accel_build_binned_sah_avx2_unit(void)
{
    return NULL;
}

build_binned_refs_fn build_binned_sah_refs_avx2_unit(void)
{
    return NULL;
}
#endif
