/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the core: the eigenvalues of a small dense real matrix (the ride's state matrix,
 * 4 x 4 or 6 x 6). */
#ifndef TIRENV_CORE_EIGEN_H
#define TIRENV_CORE_EIGEN_H

#include <complex.h>
#include <stddef.h>

enum { TIRENV_CORE__EIGEN_MAX = 8 };  /* the largest n taken */

/* The n eigenvalues of A (n x n, row-major, 1 <= n <= TIRENV_CORE__EIGEN_MAX) into lambda, in
 * no particular order. Returns 0; 1 if n is out of range or A not finite; 2 if the QR
 * iteration did not converge in 30 n iterations. */
int tirenv_core__eigenvalues(size_t n, const double A[], double complex lambda[]);

#endif
