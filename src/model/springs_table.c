/* SPDX-License-Identifier: Apache-2.0 */
/* The elements' flat ground tabulated for the identifications with a sidewall
 * (springs_identify.c, springs_minmax.c; docs/models.md section 14.1): one table a ratio
 * c_b/c_r, read at any load and c_r by interpolation. */
#include <math.h>
#include "model/springs_impl.h"

void tirenv_springs__table_init(tirenv_springs__table *tb, double *store, size_t points)
{
    tb->points = points;
    tb->n = 0;
    tb->log_f = store;
    tb->log_d = store + points;
    tb->log_l = store + 2 * points;
    tb->d = store + 3 * points;
    tb->f = store + 4 * points;
    tb->l = store + 5 * points;
}

int tirenv_springs__table_of(const tirenv_springs_params *par, double beta, double d_lo,
                             double d_hi, tirenv_springs__table *tb, tirenv_diag *diag)
{
    const size_t points = tb->points;
    double *const d = tb->d, *const f = tb->f, *const l = tb->l;
    d_hi = fmin(d_hi, 0.9 * par->R0);
    for (size_t k = 0; k < points; k++)
        d[k] = d_lo * pow(d_hi / d_lo, (double)k / (double)(points - 1));
    const int status = tirenv_springs__unit_load(par, beta, points, d, f, l, diag);
    if (status)
        return status;
    tb->n = 0;
    for (size_t k = 0; k < points; k++)
        if (f[k] > 0 && l[k] > 0 && (tb->n == 0 || log(f[k]) > tb->log_f[tb->n - 1])) {
            tb->log_f[tb->n] = log(f[k]);
            tb->log_d[tb->n] = log(d[k]);
            tb->log_l[tb->n] = log(l[k]);
            tb->n++;
        }
    return TIRENV_OK;
}

int tirenv_springs__table_at(const tirenv_springs__table *tb, double f, double *d, double *l)
{
    const double x = log(f);
    if (tb->n < 2 || !(x >= tb->log_f[0] && x <= tb->log_f[tb->n - 1]))
        return 0;
    size_t lo = 0, hi = tb->n - 1; /* log_f[lo] <= x <= log_f[hi], ascending */
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (tb->log_f[mid] < x)
            lo = mid;
        else
            hi = mid;
    }
    const double t = (x - tb->log_f[lo]) / (tb->log_f[hi] - tb->log_f[lo]);
    *d = exp(tb->log_d[lo] + t * (tb->log_d[hi] - tb->log_d[lo]));
    *l = exp(tb->log_l[lo] + t * (tb->log_l[hi] - tb->log_l[lo]));
    return 1;
}
