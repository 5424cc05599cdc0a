/* SPDX-License-Identifier: Apache-2.0 */
/* TAP output for the test programs that are not cmocka suites (those that link a third-party
 * oracle or load an FMU): tap_check prints "ok N - ..." or "not ok N - ...", tap_done the plan
 * and a summary, and returns the exit status. One program, one translation unit. */
#ifndef TIRENV_TEST_TAP_H
#define TIRENV_TEST_TAP_H

#include <stdarg.h>
#include <stdio.h>

static int tap_n_checks, tap_n_failed;

static void check(int ok, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    printf("%s %d - ", ok ? "ok" : "not ok", ++tap_n_checks);
    vprintf(fmt, ap);
    putchar('\n');
    va_end(ap);
    tap_n_failed += !ok;
}

static int tap_done(void)
{
    printf("1..%d\n%d passed, %d failed\n", tap_n_checks, tap_n_checks - tap_n_failed,
           tap_n_failed);
    return tap_n_failed ? 1 : 0;
}

#endif
