/* tirenv: the enveloping curve over a profile read as it goes, in memory bounded by the
 * tire's reach rather than by the road's length. */
#ifndef TIRENV_STREAM_H
#define TIRENV_STREAM_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"
#include "tirenv/model.h"

TIRENV_BEGIN_DECLS

/* A profile CSV ("x_m,z_m", as tirenv_profile_read_csv) read one vertex at a time. */
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

/* Receives each position as it is computed; a nonzero return stops the sweep with that
 * status (use a TIRENV_ code, e.g. TIRENV_EIO). */
typedef int (*tirenv_point_sink)(void *ctx, const tirenv_point *pt);

/* What a streamed sweep did, for callers and tests of its memory bound. */
typedef struct {
    size_t positions;      /* positions passed to the sink */
    size_t vertices_read;  /* vertices read from the file */
    size_t window_max;     /* most vertices held in the window at once */
    size_t rebuilds;       /* windows built */
} tirenv_stream_stats;

/* Number of positions x_k = x_from + k*dx (m, dx > 0, x_to >= x_from) up to x_to plus a
 * billionth of a step, so that 0 .. 1 at 0.1 gives 11 despite rounding: the sweeps of the CLI
 * and of tirenv_model_stream. */
size_t tirenv_positions_count(double x_from, double x_to, double dx);

/* Evaluates the positions x_k = x_from + k*dx (m) up to x_to (m; as the CLI's sweep) at load
 * (N), reading vertices from in only as far as the tire's reach ahead needs, and passing each
 * point to sink. Equals tirenv_model_set + tirenv_model_envelope over the whole file bit for
 * bit, iterations included (the warm start carries over as the window moves), except that
 * the check that the ground stays below the flat-ground centre height covers only the ground
 * read.
 * stats may be NULL. Consumes in from where it stands. */
int tirenv_model_stream(tirenv_model *m, tirenv_profile_reader *in, double x_from,
                        double x_to, double dx, double load, tirenv_point_sink sink, void *ctx,
                        tirenv_stream_stats *stats, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
