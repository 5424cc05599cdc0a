/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the core: Cholesky factorisation and solve of a small dense symmetric positive
 * definite matrix (the LM trainer's normal equations, ring_tband.c's dense tail). */
#ifndef TIRENV_CORE_CHOLESKY_H
#define TIRENV_CORE_CHOLESKY_H

#include <stddef.h>

/* M (n x n, row stride ld) = L L^T in place: reads the lower triangle, writes L there (the
 * upper triangle untouched). Returns 0, or 1 + the column where a pivot was not positive
 * and finite (M not positive definite to round-off). */
int tirenv_core__cholesky(double *M, size_t n, size_t ld);
/* Solves L L^T x = b with the factor from tirenv_core__cholesky; x may be b. */
void tirenv_core__cholesky_solve(const double *L, size_t n, size_t ld, const double b[],
                                 double x[]);

#endif
