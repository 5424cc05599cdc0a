/* tirenv: file formats (the convenience layer): .tir tire property files, profile CSV,
 * and all-or-nothing output files. */
#ifndef TIRENV_IO_H
#define TIRENV_IO_H

#include "tirenv/decls.h"
#include <stdio.h>
#include "tirenv/error.h"
#include "tirenv/profile.h"
#include "tirenv/tire.h"

TIRENV_BEGIN_DECLS

/* Reads a .tir file (sections in brackets, KEY = value, '$' comments, [UNITS] in SI) into
 * *tire, overriding only the keys present. Keys this library knows (see data/tires/default.tir)
 * are checked; sections it does not know are skipped so that MF-Tyre files load unchanged.
 * Errors name file, line and key. On failure *tire is unchanged. */
int tirenv_tir_read(const char *path, tirenv_tire *tire, tirenv_diag *diag);

/* Applies one "KEY=VALUE" override (KEY as in the .tir file, e.g. RADIAL_STIFFNESS=1.6e6),
 * as the --set option does. On failure *tire is unchanged. */
int tirenv_tir_set(tirenv_tire *tire, const char *assignment, tirenv_diag *diag);

/* Writes *tire as a .tir file (atomically: all or nothing). */
int tirenv_tir_write(const char *path, const tirenv_tire *tire, tirenv_diag *diag);

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

/* An output file written to "<path>.tmp.XXXXXX" and renamed over path on commit, so readers
 * never see half a file. */
typedef struct {
    FILE *fp;              /* write here between open and commit */
    char path[512];
    char tmp[540];
} tirenv_outfile;

/* Opens the temporary file; path "-" writes straight to stdout. */
int tirenv_outfile_open(tirenv_outfile *f, const char *path, tirenv_diag *diag);
/* Flushes, closes and renames into place; on any error removes the temporary file. */
int tirenv_outfile_commit(tirenv_outfile *f, tirenv_diag *diag);
/* Creates a directory and its missing parents (mkdir -p); an existing one is fine. */
int tirenv_mkdir_p(const char *path, tirenv_diag *diag);

/* Writes text as '#' comment lines ("# " before each line of it); NULL writes nothing. */
void tirenv_outfile_comment(tirenv_outfile *f, const char *text);
/* Closes and removes the temporary file (after a failure); safe to call twice. */
void tirenv_outfile_abort(tirenv_outfile *f);

TIRENV_END_DECLS
#endif
