/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: profiles as CSV (docs/formats.md section 4), read whole or a vertex at a time. */
#ifndef TIRENV_PROFILE_CSV_H
#define TIRENV_PROFILE_CSV_H

#include "tirenv/decls.h"
#include "tirenv/error.h"
#include "tirenv/profile.h"

TIRENV_BEGIN_DECLS

/* Reads a profile CSV: header "x_m,z_m", one vertex per line, '#' comment lines and blank
 * lines allowed. Errors name file, line and column. *out is NULL on failure. */
int tirenv_profile_read_csv(const char *path, tirenv_profile **out, tirenv_diag *diag);

/* A profile CSV ("x_m,z_m", as tirenv_profile_read_csv) read one vertex at a time, for
 * tirenv_model_stream (stream.h) over a road longer than memory. */
typedef struct tirenv_profile_reader tirenv_profile_reader;

/* Opens path and checks its header; *out is NULL on failure (diag names file and line). */
int tirenv_profile_reader_open(const char *path, tirenv_profile_reader **out,
                               tirenv_diag *diag);

/* The next vertex (m) in *x, *z with *got = 1, or *got = 0 at the end of the file. Applies
 * the checks of tirenv_profile_read_csv (numbers, x non-decreasing, at most two vertices at
 * one x, at least one row) and names file, line and column on failure. */
int tirenv_profile_reader_next(tirenv_profile_reader *r, double *x, double *z, int *got,
                               tirenv_diag *diag);

/* Closes the file; NULL is a no-op. */
void tirenv_profile_reader_free(tirenv_profile_reader *r);

/* tirenv_profile_reader_next in the form of a tirenv_vertex_source (stream.h): ctx is the
 * reader. */
int tirenv_profile_reader_source(void *reader, double *x, double *z, int *got,
                                 tirenv_diag *diag);

TIRENV_END_DECLS
#endif
