/* SPDX-License-Identifier: Apache-2.0 */
/* Private to src/formats: a profile CSV ("x_m,z_m", as tirenv_profile_read_csv) read from a
 * stream the open road file gives (tirenv_road_file, road_file.c), whole or one vertex at a
 * time, the CSV case of the one public streaming reader, tirenv_profile_file_reader
 * (profile_reader.c). */
#ifndef TIRENV_FORMATS_PROFILE_CSV_IMPL_H
#define TIRENV_FORMATS_PROFILE_CSV_IMPL_H

#include <stdio.h>

#include "io/io.h"
#include "tirenv/error.h"
#include "tirenv/profile.h"

/* Reads fp (closed here) whole, named name in messages, as tirenv_profile_read_csv: the rows
 * of the reader below, gathered. *out is NULL on failure. */
int tirenv_profile_csv__read(FILE *fp, const char *name, tirenv_profile **out,
                             tirenv_diag *diag);

typedef struct tirenv_profile_csv__reader tirenv_profile_csv__reader;

/* Reads fp (closed by the reader, or here on failure), named name in messages, and checks
 * its header; *out is NULL on failure (diag names file and line). */
int tirenv_profile_csv__reader_open(FILE *fp, const char *name,
                                    tirenv_profile_csv__reader **out, tirenv_diag *diag);

/* The next vertex (m) in *x, *z with *got = 1, or *got = 0 at the end of the file. Applies
 * the checks of tirenv_profile_read_csv (numbers, x non-decreasing, at most two vertices at
 * one x, at least one row) and names file, line and column on failure. */
int tirenv_profile_csv__reader_next(tirenv_profile_csv__reader *r, double *x, double *z,
                                    int *got, tirenv_diag *diag);

/* Every row after the last one read, as tirenv_profile_csv__reader_next reads them, appended
 * to x[*n..] and z[*n..] (m), which are grown with realloc (*cap: their room); on failure they
 * hold the rows before the bad one, the caller's to free either way. */
int tirenv_profile_csv__reader_rest(tirenv_profile_csv__reader *r, double **x, double **z,
                                    size_t *n, size_t *cap, tirenv_diag *diag);

/* Closes the file; NULL is a no-op. */
void tirenv_profile_csv__reader_free(tirenv_profile_csv__reader *r);

/* The x (m) of the last data row of the CSV text in s, found from its end without reading
 * the rows before it: 1 with *x set, or 0 where it cannot be told so (that row does not
 * parse, a NUL byte, more than two of the longest lines of comments after it, a read error),
 * and a reader from the start must find it, or the first bad row. */
int tirenv_profile_csv__last_x(const tirenv_source *s, double *x);

#endif
