/* The enveloping model's training samples from a data set (docs/models.md section 6): the
 * bridge from the data sets of the auxiliary layer to the core's trainers.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/dataset.h"

#include <stdlib.h>

#include "tirenv/nn.h"

int tirenv_samples_from_dataset(const tirenv_dataset *ds, tirenv_split split,
                                tirenv_samples *out, double **x, double **y,
                                tirenv_diag *diag)
{
    size_t n = 0, n_curves = 0;
    *x = *y = NULL;
    *out = (tirenv_samples){.n = 0, .n_in = TIRENV_NN_INPUTS, .x = NULL, .y = NULL};
    for (size_t c = 0; c < ds->n; ++c) {
        const tirenv_case *cs = &ds->cases[c];
        if (cs->split != split)
            continue;
        if (cs->curve.n == 0 || !cs->curve.x_N || !cs->curve.h)
            return tirenv_error(diag, TIRENV_EINVAL, ds->dir, 0, "curve",
                                "case '%s' has no curve points", cs->name);
        n += cs->curve.n;
        ++n_curves;
    }
    if (n == 0)
        return TIRENV_OK;
    /* The curve offsets after the inputs, in the same block (size_t is no more strictly
     * aligned than double on any platform tirenv builds on; checked below). */
    _Static_assert(_Alignof(size_t) <= _Alignof(double), "size_t after doubles");
    double *xs = malloc(n * TIRENV_NN_INPUTS * sizeof *xs + (n_curves + 1) * sizeof(size_t));
    double *ys = malloc(n * sizeof *ys);
    if (!xs || !ys) {
        free(xs);
        free(ys);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for %zu samples", n);
    }
    size_t *start = (size_t *)(xs + n * TIRENV_NN_INPUTS);
    size_t k = 0, curve = 0;
    for (size_t c = 0; c < ds->n; ++c) {
        const tirenv_case *cs = &ds->cases[c];
        if (cs->split != split)
            continue;
        start[curve++] = k;
        for (size_t i = 0; i < cs->curve.n; ++i, ++k) {
            double *u = xs + k * TIRENV_NN_INPUTS;
            u[TIRENV_NN_X_N] = cs->curve.x_N[i];
            u[TIRENV_NN_CONTACT_LENGTH] = cs->contact_length;
            u[TIRENV_NN_HEIGHT] = cs->H;
            u[TIRENV_NN_LENGTH] = cs->L;
            ys[k] = cs->curve.h[i];
        }
    }
    start[n_curves] = n;
    *x = xs;
    *y = ys;
    *out = (tirenv_samples){.n = n, .n_in = TIRENV_NN_INPUTS, .x = xs, .y = ys, .w = NULL,
                            .n_curves = n_curves, .curve_start = start};
    return TIRENV_OK;
}
