/* Private to src/train: what a trainer provides to the driver in train.c, and the helpers
 * they share. SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_TRAIN_IMPL_H
#define TIRENV_TRAIN_IMPL_H

#include <math.h>
#include "tirenv/rng.h"
#include "tirenv/train.h"

/* Every trainer minimises E = 1/2 sum_s r_s^2 over the training samples, with the residual
 * of the scaled output r_s = sqrt(w_s) (y_s - t_s)/out_std (w_s the sample's weight, 1
 * without): the scaling makes one learning rate or one damping fit every data set. */
struct tirenv_trainer_type {
    const char *name;
    /* State for training nets shaped like nn on sets of train's size, into *state. Fails
     * with TIRENV_ENOMEM, or TIRENV_EINVAL if the sizes do not suit the trainer. */
    int (*alloc)(void **state, const tirenv_nn *nn, const tirenv_samples *train,
                 const tirenv_train_settings *s, tirenv_diag *diag);
    /* Starts a restart from nn's (new) weights: clears momenta, steps, damping. */
    int (*set)(void *state, tirenv_nn *nn, const tirenv_samples *train, tirenv_diag *diag);
    /* One epoch (a pass over the samples, or one accepted LM step). Sets *train_sse to the
     * error E*2 seen during the epoch. Returns TIRENV_ECONTINUE to go on, TIRENV_OK when
     * converged (no step lowers the error), or a failure. */
    int (*epoch)(void *state, tirenv_nn *nn, const tirenv_samples *train, tirenv_rng *rng,
                 double *train_sse, tirenv_diag *diag);
    void (*free)(void *state);  /* NULL is a no-op */
};

/* What turns sample k's error y - t into its residual r: 1/out_std (inv_std), times the
 * square root of its weight if the set has weights. Without weights exactly inv_std, so
 * unweighted sums are the same bits as ever. */
static inline double tirenv_train__residual_scale(const tirenv_samples *s, size_t k,
                                                  double inv_std)
{
    return s->w ? inv_std * sqrt(s->w[k]) : inv_std;
}

/* sum_s r_s^2 over s and g = dE/dw (n_weights); grad is workspace of n_weights. */
double tirenv_train__gradient(tirenv_nn *nn, const tirenv_samples *s, double g[],
                              double grad[]);

/* sum_s r_s^2 over s by the batch path; y is workspace of s->n. */
double tirenv_train__sse(tirenv_nn *nn, const tirenv_samples *s, double y[]);

#endif
