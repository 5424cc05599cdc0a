/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: numbers as text, the bytes printf writes, faster (docs/formats.md section 1). */
#ifndef TIRENV_NUMTEXT_H
#define TIRENV_NUMTEXT_H

#include "tirenv/decls.h"
#include <stddef.h>

TIRENV_BEGIN_DECLS

/* Room for any number tirenv_fmt_g writes, with its NUL ("-1.2345678901234567e-308"). */
#define TIRENV_FMT_G_SIZE 32

/* Writes x into buf exactly as snprintf(buf, TIRENV_FMT_G_SIZE, "%.*g", precision, x) does
 * (the same bytes, ties rounded as glibc rounds them, "-0", "inf", "-nan") and returns the
 * length; precision 1 to 17 (otherwise writes "" and returns 0). buf must have
 * TIRENV_FMT_G_SIZE bytes, all of which may be written (what follows the NUL is scratch).
 * Several times faster than printf: exact integer arithmetic with a proven error bound, and
 * snprintf only in the rare cases the bound cannot decide. For CSV rows in a buffer with
 * that much room left before each number: p += tirenv_fmt_g(v, 9, p). */
size_t tirenv_fmt_g(double x, int precision, char *buf);

/* Writes into buf (TIRENV_FMT_G_SIZE bytes, all of which may be written) the shortest text
 * that strtod reads back to exactly x, and returns its length: the shortest "%.*g", or plain
 * decimals where they are at most 4 characters longer (0.1, -10000, 250.2 rather than
 * -1e+04; 1e-07, 6.02e+23 stay). Never longer than "%.17g"; -0 keeps its sign; inf and nan
 * are written as "%g" writes them (a nan reads back as a nan, not its bits). */
size_t tirenv_fmt_shortest(double x, char *buf);

TIRENV_END_DECLS
#endif
