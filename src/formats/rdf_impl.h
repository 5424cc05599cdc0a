/* SPDX-License-Identifier: Apache-2.0 */
/* Private to src/formats: an RDF road read in bounded memory (rdf.c). One pass over the file
 * (tirenv_rdf__open) reads its keys and checks a poly_line's rows as they pass, keeping none
 * of them; its rows are then read again one at a time as they are wanted (tirenv_rdf__rows),
 * by the streamed sweep or the level's reader, so that a long road is never in memory whole
 * unless a caller wants it whole (tirenv_rdf__open_whole, which gathers one side's rows in
 * the same pass, or tirenv_rdf__profile after a scan). */
#ifndef TIRENV_FORMATS_RDF_IMPL_H
#define TIRENV_FORMATS_RDF_IMPL_H

#include <stddef.h>

#include "io/io.h"
#include "tirenv/rdf.h"

/* A side's first failing row: its line (0: none) and what tirenv_profile_validate says. */
typedef struct {
    size_t line;
    char message[sizeof ((tirenv_diag){0}).message];
} tirenv_rdf__bad;

/* A poly_line's rows as the scan met them. */
typedef struct {
    size_t n;                 /* rows */
    size_t first_line;        /* the first row's line */
    int deferred;             /* a row came before [UNITS] LENGTH: checked again after */
    double x1, x2;            /* the previous two rows' x, m */
    double x_first, x_last;   /* the first and last row's x, file units */
    tirenv_rdf__bad bad[3];   /* each side's (tirenv_rdf_side) first failure */
} tirenv_rdf__check;

typedef struct tirenv_rdf__road tirenv_rdf__road;
typedef struct tirenv_rdf__rows tirenv_rdf__rows;

/* Reads src once (which must outlive the road): every error of the file but a side's own
 * (a row that fails tirenv_profile_validate on that side, tirenv_rdf__side) is reported
 * here, naming file, line, column and key. */
int tirenv_rdf__open(const tirenv_source *src, tirenv_rdf__road **out, tirenv_diag *diag);

/* tirenv_rdf__open that also gathers the rows of side as they pass, for a road read whole:
 * *out the profile (32 bytes a row at the peak, one reading of the file); on side's own error
 * *road is set and *out NULL. */
int tirenv_rdf__open_whole(const tirenv_source *src, tirenv_rdf_side side,
                           tirenv_rdf__road **road, tirenv_profile **out, tirenv_diag *diag);

/* Frees the road; NULL is a no-op. */
void tirenv_rdf__free(tirenv_rdf__road *road);

/* TIRENV_OK if the road on side is a valid profile, else the error the whole read gives. */
int tirenv_rdf__side(const tirenv_rdf__road *road, tirenv_rdf_side side, tirenv_diag *diag);

/* The first and last vertex's x, m (the same on every side). */
void tirenv_rdf__extent(const tirenv_rdf__road *road, double *first, double *last);

/* The road on side (checked with tirenv_rdf__side first) as a profile, gathered from its rows. */
int tirenv_rdf__profile(const tirenv_rdf__road *road, tirenv_rdf_side side,
                        tirenv_profile **out, tirenv_diag *diag);

/* A reader of the road's vertices on side (valid: tirenv_rdf__side), in m, one at a time,
 * from a window of the file (64 KB); several may be open on one road. */
int tirenv_rdf__rows_open(const tirenv_rdf__road *road, tirenv_rdf_side side,
                          tirenv_rdf__rows **out, tirenv_diag *diag);

/* The next vertex (*got 1), or *got 0 after the last. */
int tirenv_rdf__rows_next(tirenv_rdf__rows *w, double *x, double *z, int *got,
                          tirenv_diag *diag);

/* Frees the reader; NULL is a no-op. */
void tirenv_rdf__rows_free(tirenv_rdf__rows *w);

#endif
