/* SPDX-License-Identifier: Apache-2.0 */
/*
 * report.h - how rtu records an error in the current context.
 *
 * rtu sees rt.h only; it records its errors through rtRecordError, the
 * core's entry point for layered libraries (docs/errors.md), so that the
 * message names the rtu function, as GLU's errors live in GL's error state.
 */
#ifndef RTU_REPORT_H
#define RTU_REPORT_H

#include <rt/rt.h>

/*
 * Records `code` against the rtu entry point `function` in the current
 * context (nothing without one).  Between rtBegin and rtEnd the core
 * records RT_INVALID_OPERATION instead, as for any core call there.
 */
void rtu_record_error(RTenum code, const char *function, const char *message);

#endif /* RTU_REPORT_H */
