/* The paper's trainer (Table 1: "standard backpropagation algorithm"): gradient descent with
 * momentum, dw <- -eta*dE/dw + alpha*dw (Rumelhart, Hinton and Williams 1986), online or
 * batch. The baseline the modern trainers are measured against.
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdlib.h>
#include <string.h>

#include "train/train_impl.h"

typedef struct {
    tirenv_backprop_settings set;
    size_t p;              /* weights */
    double *dw;            /* p: last change of each weight (the momentum term) */
    double *grad;          /* p: dy/dw of one sample */
    double *g;             /* p: dE/dw summed over the epoch (batch mode) */
    size_t *order;         /* n: sample order of an online epoch */
} backprop_state;

static void backprop_free(void *state)
{
    backprop_state *st = state;
    if (!st)
        return;
    free(st->dw);
    free(st->grad);
    free(st->g);
    free(st->order);
    free(st);
}

static int backprop_alloc(void **state, const tirenv_nn *nn, const tirenv_samples *train,
                          const tirenv_train_settings *s, tirenv_diag *diag)
{
    backprop_state *st = calloc(1, sizeof *st);
    *state = st;
    if (!st)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    st->set = s->backprop;
    st->p = tirenv_nn_n_weights(nn);
    st->dw = malloc(st->p * sizeof *st->dw);
    st->grad = malloc(st->p * sizeof *st->grad);
    st->g = malloc(st->p * sizeof *st->g);
    st->order = malloc(train->n * sizeof *st->order);
    if (!st->dw || !st->grad || !st->g || !st->order) {
        backprop_free(st);
        *state = NULL;
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    return TIRENV_OK;
}

static int backprop_set(void *state, tirenv_nn *nn, const tirenv_samples *train,
                        tirenv_diag *diag)
{
    backprop_state *st = state;
    (void)nn;
    (void)diag;
    memset(st->dw, 0, st->p * sizeof *st->dw);
    for (size_t k = 0; k < train->n; ++k)
        st->order[k] = k;
    return TIRENV_OK;
}

/* Online: one update per sample, in an order reshuffled every epoch (otherwise the curves'
 * points, which come sorted by x_N, pull the weights back and forth in a fixed cycle).
 * Batch: one update per epoch on the summed gradient, which is what the online updates of an
 * epoch would add up to at fixed weights, so one learning rate means about the same in
 * both modes. */
static int backprop_epoch(void *state, tirenv_nn *nn, const tirenv_samples *train,
                          tirenv_rng *rng, double *train_sse, tirenv_diag *diag)
{
    backprop_state *st = state;
    const double eta = st->set.learning_rate, alpha = st->set.momentum;
    double *w = tirenv_nn_weights(nn), *dw = st->dw;
    const size_t p = st->p;
    (void)diag;
    if (!st->set.online) {
        *train_sse = tirenv_train__gradient(nn, train, st->g, st->grad);
        for (size_t j = 0; j < p; ++j) {
            dw[j] = -eta * st->g[j] + alpha * dw[j];
            w[j] += dw[j];
        }
        return TIRENV_ECONTINUE;
    }
    double out_std;
    tirenv_nn_scaling(nn, NULL, NULL, NULL, &out_std);
    const double inv_std = 1.0 / out_std;
    tirenv_rng_shuffle(rng, st->order, train->n);
    double sse = 0;
    for (size_t k = 0; k < train->n; ++k) {
        const size_t s = st->order[k];
        const double y = tirenv_nn_gradient(nn, train->x + s * train->n_in, st->grad);
        const double scale = tirenv_train__residual_scale(train, s, inv_std);
        const double r = (y - train->y[s]) * scale;
        sse += r * r;
        const double c = -eta * r * scale;  /* dE_s/dw = r * grad * scale */
        for (size_t j = 0; j < p; ++j) {
            dw[j] = c * st->grad[j] + alpha * dw[j];
            w[j] += dw[j];
        }
    }
    *train_sse = sse;
    return TIRENV_ECONTINUE;
}

const struct tirenv_trainer_type tirenv_train__backprop_type = {
    .name = "backprop",
    .alloc = backprop_alloc,
    .set = backprop_set,
    .epoch = backprop_epoch,
    .free = backprop_free,
};
