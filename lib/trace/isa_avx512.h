/* SPDX-License-Identifier: Apache-2.0 */
/*
 * isa_avx512.h - TRACE_AVX512_TABLE: 1 in the translation units compiled
 * for the AVX-512 table (traverse_avx512.c, packet_avx512.c: -mavx512vl
 * and -mavx512dq among their flags), 0 in every other.  The walks and
 * leaves shared by the tables (intersect_tri4.h, traverse_wide.h,
 * traverse_wide8_ray.h, packet_wide.h) choose their AVX-512 forms
 * (compares into mask registers, compress, the fused node test) by this
 * one name, so the condition is written once.  A macro whose expansion
 * holds `defined` is undefined behaviour in #if (C99 6.10.1), hence the
 * 0 or 1 value.
 */
#ifndef RT_TRACE_ISA_AVX512_H
#define RT_TRACE_ISA_AVX512_H

#if defined(__AVX512VL__) && defined(__AVX512DQ__)
#define TRACE_AVX512_TABLE 1
#else
#define TRACE_AVX512_TABLE 0
#endif

#endif /* RT_TRACE_ISA_AVX512_H */
