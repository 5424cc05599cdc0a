/* Private to the tirenv command-line tool: CSV rows of the big writers (envelope, predict,
 * road, ride series) built in a buffer, numbers as printf("%.9g") writes them but through
 * tirenv_fmt_g (several times faster, the same bytes), counts as "%zu" does.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CLI_CSV_ROW_H
#define TIRENV_CLI_CSV_ROW_H

#include <stddef.h>

#include "tirenv/numtext.h"

/* Room a row buffer needs per field: each append writes up to this many bytes. */
#define CLI_ROW_FIELD TIRENV_FMT_G_SIZE

/* Appends v with `precision` significant digits (as "%.*g") and the separator sep; returns
 * the end. */
static inline char *cli_row_g(char *p, double v, int precision, char sep)
{
    p += tirenv_fmt_g(v, precision, p);
    *p++ = sep;
    return p;
}

/* Appends n as "%zu" does, and sep. */
static inline char *cli_row_size(char *p, size_t n, char sep)
{
    char d[24];
    size_t k = 0;
    do {
        d[k++] = (char)('0' + n % 10);
        n /= 10;
    } while (n);
    while (k)
        *p++ = d[--k];
    *p++ = sep;
    return p;
}

#endif
