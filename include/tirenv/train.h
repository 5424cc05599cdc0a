/* tirenv: training the empirical model's network (docs/models.md section 6); its model file
 * (docs/formats.md section 10), a file format, is in nn_file.h.
 * Trainers are chosen by name: "backprop" (the paper's baseline), "rprop", "lm".
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_TRAIN_H
#define TIRENV_TRAIN_H

#include "tirenv/decls.h"
#include <stddef.h>
#include <stdint.h>
#include "tirenv/error.h"
#include "tirenv/nn.h"

TIRENV_BEGIN_DECLS

/* The three sets of samples a network is trained, stopped and judged on. */
typedef enum {
    TIRENV_SPLIT_TRAIN = 0,   /* fits and trains on it */
    TIRENV_SPLIT_CONTROL,     /* early stopping / model selection */
    TIRENV_SPLIT_VALIDATION   /* reported only, never seen in training */
} tirenv_split;

/* n samples of n_in inputs and one output, borrowed from the caller. For the enveloping
 * model the inputs are x_N, l_c (m), H (m), L (m) and the output is h (m). The samples may
 * come in curves (one per obstacle run): curve c is samples curve_start[c] to
 * curve_start[c + 1] - 1, and curve_start[n_curves] = n. */
typedef struct {
    size_t n;              /* samples (0: an empty set) */
    size_t n_in;           /* inputs per sample */
    const double *x;       /* n*n_in inputs, row-major */
    const double *y;       /* n outputs */
    const double *w;       /* n weights (> 0) on each sample's squared error; NULL: all 1 */
    size_t n_curves;       /* 0: not grouped */
    const size_t *curve_start; /* n_curves + 1 offsets, or NULL */
} tirenv_samples;

/* A trainer algorithm (GSL style: tirenv_trainer_lm); the record is private. */
typedef struct tirenv_trainer_type tirenv_trainer_type;
extern const tirenv_trainer_type *tirenv_trainer_backprop;
extern const tirenv_trainer_type *tirenv_trainer_rprop;
extern const tirenv_trainer_type *tirenv_trainer_lm;

/* The type with this name, or NULL; a type's name; the NULL-terminated list of all. */
const tirenv_trainer_type *tirenv_trainer_type_find(const char *name);
const char *tirenv_trainer_type_name(const tirenv_trainer_type *type);
const tirenv_trainer_type *const *tirenv_trainer_types(void);

/* The paper's standard back-propagation: gradient descent with momentum on the squared error
 * of the scaled output, dw <- -eta*dE/dw + alpha*dw. */
typedef struct {
    double learning_rate;  /* eta, on the scaled error */
    double momentum;       /* alpha, in [0, 1) */
    int online;            /* 1: update after each sample, in an order shuffled every epoch
                              with the rng; 0: once per epoch on the summed gradient */
} tirenv_backprop_settings;

/* iRprop- (Igel and Huesken 2000): per-weight steps grown by eta_plus while the gradient
 * keeps its sign, shrunk by eta_minus (and the step skipped) when it flips. */
typedef struct {
    double delta0;         /* first step of every weight */
    double delta_min;      /* smallest step */
    double delta_max;      /* largest step */
    double eta_plus;       /* > 1 */
    double eta_minus;      /* in (0, 1) */
} tirenv_rprop_settings;

/* How the Levenberg-Marquardt step is solved: damping mu I, Nielsen's update of mu (lm.c says
 * why). One solver since GSL's gsl_multifit_nlinear left (version 0.1 offered it as a second). */
typedef enum {
    TIRENV_LM_CHOLESKY = 0  /* (J^T J + mu I) dw = -J^T r by Cholesky on normal equations
                               formed a block of rows at a time */
} tirenv_lm_solver;

/* Levenberg-Marquardt on the full Jacobian of the residuals (one epoch = one accepted step). */
typedef struct {
    tirenv_lm_solver solver;
    double tau;            /* first damping mu = tau * max diag(J^T J) (Nielsen's tau; GSL's
                              fixes it at 1e-3) */
    double mu_max;         /* cholesky: give up (converged) when mu / max diag(J^T J)
                              exceeds it */
} tirenv_lm_settings;

/* What the progress callback sees after every epoch: the loss as an RMS error, in m for the
 * target h, as a fraction of H for h/H (for the curves loss the mean of the curves' RMS). */
typedef struct {
    size_t restart;        /* 0-based */
    size_t restarts;       /* how many */
    size_t epoch;          /* epochs done in this restart */
    size_t max_epochs;
    double train_rms;      /* during the epoch (online backprop) or before its step */
    double control_rms;    /* after the epoch */
    double best_rms;       /* best control error of this restart so far */
    size_t best_epoch;
} tirenv_train_progress;

/* Returns 0 to go on, nonzero to stop training (the best weights so far are kept). */
typedef int (*tirenv_train_progress_fn)(const tirenv_train_progress *p, void *data);

/* What the trainers minimise over the training samples (and early stopping over control). */
typedef enum {
    TIRENV_TRAIN_LOSS_POINTS = 0, /* the sum of squared errors over all points (the paper's) */
    TIRENV_TRAIN_LOSS_CURVES      /* the mean over curves of each curve's RMS error: every
                                     curve counts once, however many points it has and
                                     however well it is fitted (the study's own measure);
                                     minimised by reweighting each curve by 1/its RMS error
                                     at the start of every epoch */
} tirenv_train_loss;

/* "points", "curves"; NULL for an unknown value. */
const char *tirenv_train_loss_name(tirenv_train_loss loss);
/* The loss of that name; -1 if none. */
int tirenv_train_loss_find(const char *name);

typedef struct {
    tirenv_nn_topology topology;  /* size[0] must equal the samples' n_in */
    unsigned long seed;           /* fixes initial weights and online order, bit for bit */
    size_t restarts;              /* independent starts (M), each from its own seed */
    size_t ensemble;              /* K: the model is the mean of the K restarts best on the
                                     control set (min(K, M); 1: the best one alone) */
    tirenv_nn_input_form input;   /* how x_N reaches the network (nn.h) */
    double even_width;            /* a of the even form, in x_N (TIRENV_NN_EVEN_WIDTH) */
    tirenv_nn_target_form target; /* h or h/H; h/H also makes the loss one on h/H (each
                                     point's squared error weighted by 1/H^2) */
    tirenv_train_loss loss;
    size_t max_epochs;            /* per restart */
    size_t patience;              /* stop after this many epochs without a better control
                                     error; 0: never stop early (still keep the best) */
    tirenv_backprop_settings backprop;
    tirenv_rprop_settings rprop;
    tirenv_lm_settings lm;
    size_t jobs;                  /* restarts run at once, one thread each (default 1: no
                                     thread; tirenv/parallel.h); the network is the same, bit
                                     for bit, for every value. With more than one, progress
                                     calls come from several threads (never at once), and a
                                     cancel stops every restart running */
    tirenv_train_progress_fn progress;  /* NULL: none */
    void *progress_data;
} tirenv_train_settings;

/* Defaults for a trainer (NULL: lm): 4-8-1, seed 1, the even input, the h/H target, the
 * curves loss, an ensemble of 4 (each chosen on the control error's median over 20 seeds of
 * the embedded data set: train.c says by how much), and by trainer
 *   backprop  2e5 epochs (the paper's cycles), no early stop, 1 restart, online,
 *             learning rate 0.01, momentum 0.9;
 *   rprop     5000 epochs, patience 500, 4 restarts, delta0 0.1, [1e-6, 50], 1.2 / 0.5;
 *   lm        1000 epochs, patience 60, 8 restarts, tau 1e-3, mu_max 1e10.
 * The paper's own setup is tirenv_train_paper. */
tirenv_train_settings tirenv_train_default(const tirenv_trainer_type *type);
/* The same with the paper's network: x_N as input, h as target, the loss over points, the
 * best restart alone. */
tirenv_train_settings tirenv_train_paper(const tirenv_trainer_type *type);

/* TIRENV_OK, or TIRENV_EINVAL naming the first bad setting (topology, counts, forms,
 * each trainer's constants) in diag. */
int tirenv_train_settings_check(const tirenv_train_settings *s, tirenv_diag *diag);

/* Why a restart stopped. */
typedef enum {
    TIRENV_TRAIN_MAX_EPOCHS = 0, /* ran max_epochs */
    TIRENV_TRAIN_PATIENCE,       /* patience epochs without a better control error */
    TIRENV_TRAIN_CONVERGED,      /* the trainer could not lower the error further */
    TIRENV_TRAIN_DIVERGED,       /* the error became infinite or NaN */
    TIRENV_TRAIN_CANCELLED       /* the progress callback asked to stop */
} tirenv_train_stop;

/* "max-epochs", "patience", "converged", "diverged", "cancelled". */
const char *tirenv_train_stop_name(tirenv_train_stop stop);

/* Error of a network on one sample set, m. */
typedef struct {
    size_t n;              /* samples (0: no such set) */
    double rms;            /* root mean square error, m */
    double max;            /* largest absolute error, m */
} tirenv_train_error;

typedef struct {
    size_t restart;        /* the restart best on control, 0-based */
    size_t epochs;         /* epochs it ran */
    size_t best_epoch;     /* its epoch of least control error (0: the initial weights) */
    double best_time;      /* s from its start to that epoch */
    size_t total_epochs;   /* over all restarts */
    double wall_time;      /* s, all restarts */
    tirenv_train_stop stop;/* why the kept restart stopped */
    size_t members;        /* networks in the model (the ensemble's K) */
    size_t member_restart[TIRENV_NN_MAX_MEMBERS]; /* the restart of each, best first */
    tirenv_train_error error[3];  /* of the model, indexed by tirenv_split: train, control,
                                     validation */
} tirenv_train_report;

/* Errors of nn on a sample set; uses the batch path. */
tirenv_train_error tirenv_train_evaluate(tirenv_nn *nn, const tirenv_samples *s);

/* Trains a network of settings->topology on train, early-stopping on control (if it is empty,
 * on train), and reports errors on all three (validation may be NULL or empty). Scaling and
 * input ranges come from train only. Each restart r is a function of the samples, the
 * settings and r alone (its seed is derived from settings->seed and r), so restarts can run
 * in any order. *out is the model, the kept network or the ensemble of the kept ones (free
 * it with tirenv_nn_free); report may be NULL. TIRENV_ENOCONV (and *out NULL) if a kept
 * restart diverged, its error no longer finite (docs/models.md section 6.4).
 * Deterministic: the same arguments give the same weights bit for bit. */
int tirenv_train(const tirenv_trainer_type *type, const tirenv_train_settings *settings,
                 const tirenv_samples *train, const tirenv_samples *control,
                 const tirenv_samples *validation, tirenv_nn **out,
                 tirenv_train_report *report, tirenv_diag *diag);

/* One progress callback shared by trainings that run at once (tirenv_train calls as work
 * items of tirenv_parallel_for, or the restarts of one on settings.jobs threads): its calls
 * never overlap, and once it asks to stop, every training stops at its next call. */
typedef struct tirenv_train_progress_gate tirenv_train_progress_gate;

/* A gate for s's progress callback, and s's progress and progress_data pointed through it
 * (s without a callback is left as it is); give s, or copies of it, to the trainings. NULL if
 * out of memory. */
tirenv_train_progress_gate *tirenv_train_progress_gate_alloc(tirenv_train_settings *s);
/* Frees g after the trainings that use it have returned; NULL is a no-op. */
void tirenv_train_progress_gate_free(tirenv_train_progress_gate *g);

/* FNV-1a (64 bit) over the IEEE bits of every input and output in order, little-endian,
 * continuing from h (start with TIRENV_FNV1A64_OFFSET): the data-set fingerprint. */
#define TIRENV_FNV1A64_OFFSET UINT64_C(0xcbf29ce484222325)
uint64_t tirenv_samples_fingerprint(const tirenv_samples *s, uint64_t h);

TIRENV_END_DECLS
#endif
