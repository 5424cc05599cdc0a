/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: measured or simulated enveloping curves, approach half, on an x_N grid
 * (docs/models.md section 1; x_N itself is in xn.h), and their CSV format. */
#ifndef TIRENV_CURVE_H
#define TIRENV_CURVE_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"
#include "tirenv/xn.h"  /* x_N itself, an equation of the core */

TIRENV_BEGIN_DECLS

/* The approach half of an enveloping curve over a symmetric obstacle centred at x = 0. */
typedef struct {
    size_t n;              /* number of points */
    double *x_N;           /* normalised position (0 first contact, 1 over the centre) */
    double *x;             /* position in obstacle coordinates, m */
    double *h;             /* effective profile height, m */
} tirenv_curve;

/* Allocates the three arrays of n points (zeroed); TIRENV_ENOMEM on failure. */
int tirenv_curve_alloc(tirenv_curve *c, size_t n);
/* Frees the arrays and zeroes c; NULL or an empty curve is a no-op. */
void tirenv_curve_free(tirenv_curve *c);

/* CSV "x_N,x_m,h_m" (the import's output, the data set's curve files); '#' lines are
 * comments. The write is atomic: the header line, then comment (may be NULL) as '#' lines,
 * then the rows (docs/formats.md section 1). */
int tirenv_curve_read_csv(const char *path, tirenv_curve *out, tirenv_diag *diag);
int tirenv_curve_write_csv(const char *path, const tirenv_curve *c, const char *comment,
                           tirenv_diag *diag);

TIRENV_END_DECLS
#endif
