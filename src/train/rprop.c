/* iRprop- (Igel and Huesken, "Improving the Rprop learning algorithm", 2000), the variant
 * FANN's FANN_TRAIN_RPROP implements: batch gradient, one step size per weight, only the
 * sign of the gradient used. SPDX-License-Identifier: Apache-2.0 */
#include <stdlib.h>
#include <string.h>

#include "train/train_impl.h"

typedef struct {
    tirenv_rprop_settings set;
    size_t p;
    double *delta;         /* p: step of each weight */
    double *g_prev;        /* p: last epoch's gradient (0 after a sign change) */
    double *g;             /* p: this epoch's gradient */
    double *grad;          /* p: workspace of tirenv_train__gradient */
} rprop_state;

static void rprop_free(void *state)
{
    rprop_state *st = state;
    if (!st)
        return;
    free(st->delta);
    free(st->g_prev);
    free(st->g);
    free(st->grad);
    free(st);
}

static int rprop_alloc(void **state, const tirenv_nn *nn, const tirenv_samples *train,
                       const tirenv_train_settings *s, tirenv_diag *diag)
{
    rprop_state *st = calloc(1, sizeof *st);
    (void)train;
    *state = st;
    if (!st)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    st->set = s->rprop;
    st->p = tirenv_nn_n_weights(nn);
    st->delta = malloc(st->p * sizeof(double));
    st->g_prev = malloc(st->p * sizeof(double));
    st->g = malloc(st->p * sizeof(double));
    st->grad = malloc(st->p * sizeof(double));
    if (!st->delta || !st->g_prev || !st->g || !st->grad) {
        rprop_free(st);
        *state = NULL;
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    return TIRENV_OK;
}

static int rprop_set(void *state, tirenv_nn *nn, const tirenv_samples *train,
                     tirenv_diag *diag)
{
    rprop_state *st = state;
    (void)nn;
    (void)train;
    (void)diag;
    for (size_t j = 0; j < st->p; ++j) {
        st->delta[j] = st->set.delta0;
        st->g_prev[j] = 0;
    }
    return TIRENV_OK;
}

static int rprop_epoch(void *state, tirenv_nn *nn, const tirenv_samples *train,
                       tirenv_rng *rng, double *train_sse, tirenv_diag *diag)
{
    rprop_state *st = state;
    const tirenv_rprop_settings *c = &st->set;
    double *w = tirenv_nn_weights(nn);
    (void)rng;
    (void)diag;
    *train_sse = tirenv_train__gradient(nn, train, st->g, st->grad);
    for (size_t j = 0; j < st->p; ++j) {
        const double g = st->g[j], turn = g * st->g_prev[j];
        if (turn > 0) {
            const double d = st->delta[j] * c->eta_plus;
            st->delta[j] = d < c->delta_max ? d : c->delta_max;
        } else if (turn < 0) {
            const double d = st->delta[j] * c->eta_minus;
            st->delta[j] = d > c->delta_min ? d : c->delta_min;
            st->g_prev[j] = 0;  /* the "-": no step, and no growth next epoch */
            continue;
        }
        w[j] -= g > 0 ? st->delta[j] : g < 0 ? -st->delta[j] : 0;
        st->g_prev[j] = g;
    }
    return TIRENV_ECONTINUE;
}

const struct tirenv_trainer_type tirenv_train__rprop_type = {
    .name = "rprop",
    .alloc = rprop_alloc,
    .set = rprop_set,
    .epoch = rprop_epoch,
    .free = rprop_free,
};
