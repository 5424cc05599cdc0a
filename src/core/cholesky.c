/* SPDX-License-Identifier: Apache-2.0 */
/* Cholesky-Banachiewicz, row by row (Golub and Van Loan, Matrix Computations, 4th ed.,
 * algorithm 4.2.1 in its row-oriented form): for the p x p systems tirenv solves (p <= a few
 * hundred) the unblocked loop is as fast as a library's and needs no BLAS. */
#include "core/cholesky.h"

#include <math.h>

int tirenv_core__cholesky(double *M, const size_t n, const size_t ld)
{
    for (size_t i = 0; i < n; ++i) {
        double *Li = M + i * ld;
        for (size_t j = 0; j < i; ++j) {
            const double *Lj = M + j * ld;
            double s = Li[j];
            for (size_t k = 0; k < j; ++k)
                s -= Li[k] * Lj[k];
            Li[j] = s / Lj[j];
        }
        double d = Li[i];
        for (size_t k = 0; k < i; ++k)
            d -= Li[k] * Li[k];
        if (!(d > 0) || !isfinite(d))
            return (int)i + 1;
        Li[i] = sqrt(d);
    }
    return 0;
}

void tirenv_core__cholesky_solve(const double *L, const size_t n, const size_t ld,
                                 const double b[], double x[])
{
    for (size_t i = 0; i < n; ++i) {  /* L z = b */
        double s = b[i];
        for (size_t k = 0; k < i; ++k)
            s -= L[i * ld + k] * x[k];
        x[i] = s / L[i * ld + i];
    }
    for (size_t i = n; i-- > 0;) {  /* L^T x = z */
        double s = x[i];
        for (size_t k = i + 1; k < n; ++k)
            s -= L[k * ld + i] * x[k];
        x[i] = s / L[i * ld + i];
    }
}
