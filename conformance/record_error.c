/* SPDX-License-Identifier: Apache-2.0 */
/*
 * record_error.c - conformance: rtRecordError (errors of layered libraries)
 * and rtuErrorString (the text of a code).
 *
 * Pins (docs/errors.md, docs/rtu.md): rtRecordError records its code as if
 * `function` had failed (the callback's message starts with that name and
 * carries the reason); the first error sticks; a code that is not an error
 * is RT_INVALID_ENUM and an empty function name RT_INVALID_VALUE, both
 * against rtRecordError; between rtBegin and rtEnd RT_INVALID_OPERATION is
 * recorded instead (the core's order of checks); no current context is a
 * no-op.  rtuErrorString gives GLU's strings and NULL for a non-error, with
 * or without a context; rtuPerspective(0, ...) names rtuPerspective.
 */
#include "testutil.h"

#include <rt/rtu.h>

#include <string.h>

static void record(void)
{
    tu_section("rtRecordError");
    tu_capture_errors();
    tu_reset_captured();
    rtRecordError(RT_INVALID_VALUE, "myLibFunction", "radius -1 is negative");
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("myLibFunction");
    CHECK(strstr(tu_captured_message(), "radius -1 is negative") != NULL);

    /* NULL message: the code's name stands in. */
    rtRecordError(RT_OUT_OF_MEMORY, "myLibFunction", NULL);
    CHECK_ERR(RT_OUT_OF_MEMORY);
    CHECK_MSG("myLibFunction");

    /* The first error sticks. */
    rtRecordError(RT_STACK_OVERFLOW, "first", "one");
    rtRecordError(RT_INVALID_ENUM, "second", "two");
    CHECK_ERR(RT_STACK_OVERFLOW);
    CHECK_NO_ERR();

    /* Bad arguments are errors of rtRecordError itself. */
    rtRecordError(RT_NO_ERROR, "myLibFunction", "x");
    CHECK_ERR(RT_INVALID_ENUM);
    CHECK_MSG("rtRecordError");
    rtRecordError(0x1234, "myLibFunction", "x");
    CHECK_ERR(RT_INVALID_ENUM);
    rtRecordError(RT_INVALID_VALUE, NULL, "x");
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtRecordError");
    rtRecordError(RT_INVALID_VALUE, "", "x");
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtRecordError");

    /* Inside rtBegin the mode check comes first, named after the caller. */
    tu_begin_scratch(RT_TRIANGLES);
    rtRecordError(RT_INVALID_VALUE, "myLibFunction", "x");
    CHECK_ERR(RT_INVALID_OPERATION);
    CHECK_MSG("myLibFunction");
    tu_end_scratch();
    CHECK_NO_ERR();
    rtErrorCallback(NULL, NULL);
}

static void rtu_reports_itself(void)
{
    tu_section("rtu helpers name themselves");
    tu_capture_errors();
    rtMatrixMode(RT_PROJECTION);
    rtuPerspective(0.0, 1.0, 0.1, 100.0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtuPerspective");
    rtuLookAt(0, 0, 0, 0, 0, 0, 0, 1, 0);
    CHECK_ERR(RT_INVALID_VALUE);
    CHECK_MSG("rtuLookAt");
    rtErrorCallback(NULL, NULL);
}

static void error_strings(void)
{
    tu_section("rtuErrorString");
    CHECK(strcmp(rtuErrorString(RT_NO_ERROR), "no error") == 0);
    CHECK(strcmp(rtuErrorString(RT_INVALID_ENUM), "invalid enumerant") == 0);
    CHECK(strcmp(rtuErrorString(RT_INVALID_VALUE), "invalid value") == 0);
    CHECK(strcmp(rtuErrorString(RT_INVALID_OPERATION), "invalid operation") == 0);
    CHECK(strcmp(rtuErrorString(RT_STACK_OVERFLOW), "stack overflow") == 0);
    CHECK(strcmp(rtuErrorString(RT_STACK_UNDERFLOW), "stack underflow") == 0);
    CHECK(strcmp(rtuErrorString(RT_OUT_OF_MEMORY), "out of memory") == 0);
    CHECK(rtuErrorString(RT_TRIANGLES) == NULL);
    CHECK(rtuErrorString(0x0506) == NULL);
}

int main(void)
{
    /* No context: rtRecordError does nothing, rtuErrorString still works. */
    rtRecordError(RT_INVALID_VALUE, "myLibFunction", "x");
    CHECK(rtGetError() == RT_NO_ERROR);
    error_strings();

    RTcontext ctx = tu_make_context("threads=1");
    record();
    rtu_reports_itself();
    error_strings();
    tu_destroy_context(ctx);
    return test_summary("record_error");
}
