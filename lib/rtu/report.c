/* SPDX-License-Identifier: Apache-2.0 */
/*
 * report.c - rtu_record_error (report.h).
 */
#include "report.h"

void rtu_record_error(RTenum code, const char *function, const char *message)
{
    rtRecordError(code, function, message);
}
