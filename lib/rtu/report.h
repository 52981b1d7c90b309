/* SPDX-License-Identifier: Apache-2.0 */
/*
 * report.h - how rtu records an error in the current context.
 *
 * rt.h has no entry point through which a layered library records an
 * arbitrary error under its own name, and rtu may use nothing else.  So
 * rtu makes the core record the code through the nearest public call that
 * fails with it and has no other effect (docs/quadrics.md, "How rtu
 * records errors"): the code and the first-error-sticks rule are the
 * core's, the message names that core call.  When the core grows an entry
 * point for layered libraries, this one function is what changes.
 */
#ifndef RTU_REPORT_H
#define RTU_REPORT_H

#include <rt/rt.h>

/*
 * Records `code` (RT_INVALID_ENUM, RT_INVALID_VALUE or RT_INVALID_OPERATION)
 * in the current context; nothing without one.  Between rtBegin and rtEnd
 * every code becomes RT_INVALID_OPERATION, as for any core call there.
 */
void rtu_record_error(RTenum code);

#endif /* RTU_REPORT_H */
