/* Private to src/io and the modules after it: reading small comma-separated files line by line, with the splitting,
 * number parsing and file:line:column errors that the curve, rig-log, manifest and profile
 * readers share. SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CSV_LINE_H
#define TIRENV_CSV_LINE_H

#include <stddef.h>
#include <stdio.h>

#include "tirenv/error.h"

/* A file being read, and its current line. */
typedef struct {
    FILE *fp;
    const char *file;      /* name for messages */
    char *buf;             /* line buffer (text_line.h) */
    size_t cap;
    size_t line;           /* 1-based number of the current line */
    char *text;            /* current line without BOM and end-of-line characters */
    size_t length;         /* strlen(text) before splitting: the column after the last field */
    tirenv_diag *diag;
} tirenv_csv__reader;

/* One field of the current line, blanks around it removed in place. */
typedef struct {
    char *text;
    size_t column;         /* 1-based position in the line */
} tirenv_csv__field;

/* Opens path; TIRENV_EIO with the reason if it cannot. */
int tirenv_csv__open(tirenv_csv__reader *r, const char *path, tirenv_diag *diag);

/* Reads fp (an open stream, closed by tirenv_csv__close) as the file name; never fails. */
void tirenv_csv__open_stream(tirenv_csv__reader *r, FILE *fp, const char *name,
                             tirenv_diag *diag);

/* Advances to the next line with content, skipping blank lines and '#' comment lines;
 * accepts a UTF-8 byte-order mark and CRLF ends. Returns 1 for a line, 0 at the end of the
 * file, or a status negated (so < 0) with diag set: TIRENV_EIO on a read error, TIRENV_ENOMEM
 * when memory runs out, TIRENV_EPARSE for a NUL byte in a line (its column in diag) or a line
 * longer than TIRENV_TEXT__MAX_LINE characters (text_line.h). */
int tirenv_csv__next(tirenv_csv__reader *r);

/* Frees the buffer and closes the file; safe after a failed open. */
void tirenv_csv__close(tirenv_csv__reader *r);

/* Splits the current line at commas; stores at most max + 1 fields (so an extra one can be
 * pointed at) and returns how many there are. */
size_t tirenv_csv__split(tirenv_csv__reader *r, tirenv_csv__field f[], size_t max);

/* Records TIRENV_EPARSE at the current line and the given column, for the named field. */
int tirenv_csv__fail(const tirenv_csv__reader *r, size_t column, const char *field,
                     const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* Splits the current line and checks it is exactly the header names[0..n-1]. */
int tirenv_csv__header(tirenv_csv__reader *r, const char *const names[], size_t n);

/* Splits the current line into exactly n fields (f must hold n + 1); error otherwise, naming
 * the first missing column or pointing at the first extra one. */
int tirenv_csv__fields(tirenv_csv__reader *r, const char *const names[], size_t n,
                       tirenv_csv__field f[]);

/* strtod(s) that must take the whole of s: 0 with *out set, or -1 (empty, trailing text).
 * Plain decimals of at most 19 digits with powers of ten up to 22 (what CSV files hold) take
 * an exact fast path, several times faster than strtod and bit for bit the same value. */
int tirenv_csv__parse_double(const char *s, double *out);

/* strtod with an end-pointer check; refuses empty text, trailing characters, NaN, infinity
 * and overflow. */
int tirenv_csv__number(const tirenv_csv__reader *r, const tirenv_csv__field *f,
                       const char *name, double *out);

/* The header names joined with commas, for messages. */
void tirenv_csv__join(const char *const names[], size_t n, char *buf, size_t size);

#endif
