/* SPDX-License-Identifier: Apache-2.0 */
/*
 * kernels.c - choosing the traversal kernels' ISA table (kernels.h).
 *
 * The CPU is asked through the compiler's cpuid wrapper
 * (__builtin_cpu_supports, which also checks that the operating system
 * saves the AVX registers); nothing is cached, so there is no global
 * state: a context asks once, at creation.
 */
#include "trace/kernels.h"
#include "trace/scene_traverse.h"

#include <string.h>

static const struct trace_kernels scalar_table = {TRACE_ISA_SCALAR, "scalar", trace_closest,
                                                  trace_any, NULL, NULL, NULL, NULL, 0, NULL,
                                                  NULL, NULL, NULL, trace_scene_wide_lanes,
                                                  NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL};

static const char *const isa_names[TRACE_ISA_COUNT] = {"scalar", "sse4", "avx2", "avx512"};

static int cpu_runs(enum trace_isa isa)
{
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
    __builtin_cpu_init();
    switch (isa) {
    case TRACE_ISA_SCALAR:
        return 1;
    case TRACE_ISA_SSE4:
        return __builtin_cpu_supports("sse4.2");
    case TRACE_ISA_AVX2:
        return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
               __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
    case TRACE_ISA_AVX512:
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
               __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
               __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
               __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
    default:
        return 0;
    }
#else
    return isa == TRACE_ISA_SCALAR;
#endif
}

/*
 * 1 when the AVX-512 table's single-ray walks should take their front
 * child by the trailing-zero count (trace_kernels_avx512_ctz) rather than
 * by compression (vpcompressd, trace_kernels_avx512): on AMD CPUs, by the
 * cpuid vendor.  The compression was chosen on an Intel Emerald Rapids
 * core (family 6 model 207), where it put gears' camera rays 0.10 of
 * Embree ahead and random rays 0.01-0.03 (performance-log.md, rounds
 * 46-48).  On an AMD Zen 4 core (family 25 model 17) the same walks
 * with the count were ahead: gears' camera and random rays by about
 * 0.08 of Embree, the soup's by 0.09-0.12, shadow rays level to 0.04
 * ahead (round 61, zq2; why the compression costs there was not
 * measured).  The Zen 4 and Zen 5 cores of rounds 1-44 never ran the
 * compression.  The answers are the same either way; only the speed
 * depends on this.
 */
static int cpu_avx512_front_by_count(void)
{
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
    __builtin_cpu_init();
    return __builtin_cpu_is("amd");
#else
    return 0;
#endif
}

const struct trace_kernels *trace_kernels_get(enum trace_isa isa)
{
    const struct trace_kernels *k = NULL;
    switch (isa) {
    case TRACE_ISA_SCALAR:
        return &scalar_table;
    case TRACE_ISA_SSE4:
        k = trace_kernels_sse4();
        break;
    case TRACE_ISA_AVX2:
        k = trace_kernels_avx2();
        break;
    case TRACE_ISA_AVX512:
        k = cpu_avx512_front_by_count() ? trace_kernels_avx512_ctz() : trace_kernels_avx512();
        break;
    default:
        return NULL;
    }
    return k && cpu_runs(isa) ? k : NULL;
}

const struct trace_kernels *trace_kernels_best(void)
{
    for (int i = TRACE_ISA_COUNT - 1; i > TRACE_ISA_SCALAR; i--) {
        const struct trace_kernels *k = trace_kernels_get((enum trace_isa)i);
        if (k)
            return k;
    }
    return &scalar_table;
}

int trace_isa_parse(const char *name, size_t len, enum trace_isa *isa)
{
    for (int i = 0; i < TRACE_ISA_COUNT; i++) {
        if (strlen(isa_names[i]) == len && memcmp(name, isa_names[i], len) == 0) {
            *isa = (enum trace_isa)i;
            return 0;
        }
    }
    return -1;
}
