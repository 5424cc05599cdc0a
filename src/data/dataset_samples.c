/* The enveloping model's training samples from a data set (docs/models.md section 6): the
 * bridge from the data sets of the auxiliary layer to the core's trainers.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "tirenv/dataset.h"

#include <stdlib.h>

#include "tirenv/nn.h"

int tirenv_samples_from_dataset(const tirenv_dataset *ds, tirenv_split split,
                                tirenv_samples *out, double **x, double **y,
                                tirenv_diag *diag)
{
    size_t n = 0;
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
    }
    if (n == 0)
        return TIRENV_OK;
    double *xs = malloc(n * TIRENV_NN_INPUTS * sizeof *xs);
    double *ys = malloc(n * sizeof *ys);
    if (!xs || !ys) {
        free(xs);
        free(ys);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for %zu samples", n);
    }
    size_t k = 0;
    for (size_t c = 0; c < ds->n; ++c) {
        const tirenv_case *cs = &ds->cases[c];
        if (cs->split != split)
            continue;
        for (size_t i = 0; i < cs->curve.n; ++i, ++k) {
            double *u = xs + k * TIRENV_NN_INPUTS;
            u[TIRENV_NN_X_N] = cs->curve.x_N[i];
            u[TIRENV_NN_CONTACT_LENGTH] = cs->contact_length;
            u[TIRENV_NN_HEIGHT] = cs->H;
            u[TIRENV_NN_LENGTH] = cs->L;
            ys[k] = cs->curve.h[i];
        }
    }
    *x = xs;
    *y = ys;
    *out = (tirenv_samples){.n = n, .n_in = TIRENV_NN_INPUTS, .x = xs, .y = ys};
    return TIRENV_OK;
}
