/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: the paper's study (docs/models.md section 8): identify the physical model on the training
 * cases, evaluate every model on a data set's cases, and measure how far each is off. This is
 * the convenience layer on top of the models, the data sets and the network. */
#ifndef TIRENV_STUDY_H
#define TIRENV_STUDY_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/dataset.h"
#include "tirenv/error.h"
#include "tirenv/model.h"
#include "tirenv/train.h"

TIRENV_BEGIN_DECLS

/* How far a model curve is from a measured one on the same points (all in m). */
typedef struct {
    double rms;            /* root mean square of h_model - h_meas */
    double max;            /* largest |h_model - h_meas| */
    double peak;           /* max h_model - max h_meas (signed) */
    double first_rise;     /* x where h_model first exceeds the threshold minus the same for
                            * h_meas (signed; NaN if either never does) */
} tirenv_curve_errors;

/* Errors over n points at positions x[] (ascending, m); rise_threshold (m) defines "first
 * rise". TIRENV_EINVAL if n is 0. */
int tirenv_curve_errors_compute(size_t n, const double x[], const double h_meas[],
                                const double h_model[], double rise_threshold,
                                tirenv_curve_errors *out);

/* A physical model's curve for a case, at the case's points (curve.x, ascending): the model is
 * driven by the case's applied load over the cleat L x H (or the case's own profile), as on
 * the rig. h[] has curve.n entries. The model is left set on a profile freed on return: set it
 * again before using it directly. */
int tirenv_case_predict_model(tirenv_model *m, const tirenv_case *c, double h[],
                              tirenv_diag *diag);

/* The network's curve for a case at the case's points: driven by the measured contact length,
 * as in the paper. */
int tirenv_case_predict_nn(tirenv_nn *nn, double R0, const tirenv_case *c, double h[],
                           tirenv_diag *diag);

/* Identification of a physical model on the training cases by nonlinear least squares on h
 * (Minpack's lmdif: Levenberg-Marquardt with a trust region), in log parameters so
 * they stay in range. The parameters are the type's (tirenv_model_type_params): springs: c_r
 * and c_b (optionally R0); cam: ELLIPS_SHIFT, ELLIPS_LENGTH, ELLIPS_HEIGHT, ELLIPS_ORDER. */
typedef struct {
    const tirenv_model_type *type;  /* a type with TIRENV_MODEL_FITTABLE; NULL: springs */
    int fit_R0;            /* also fit the type's optional parameters (the springs model's
                            * UNLOADED_RADIUS) */
    size_t max_iter;       /* trust-region iterations (default 50) */
    double xtol;           /* relative step tolerance (default 1e-6) */
    size_t jobs;           /* training cases evaluated at once, each worker with its own
                            * model (default 1: no thread; tirenv/parallel.h); the result is
                            * the same, bit for bit, for every value */
    void (*progress)(void *ctx, size_t iter, double rms); /* may be NULL */
    void *progress_ctx;
} tirenv_fit_settings;

tirenv_fit_settings tirenv_fit_default(void);

#define TIRENV_FIT_MAX_PARAMS 4

typedef struct {
    size_t n_params;
    const char *names[TIRENV_FIT_MAX_PARAMS];   /* .tir keys */
    double value[TIRENV_FIT_MAX_PARAMS];        /* fitted, SI */
    double std_error[TIRENV_FIT_MAX_PARAMS];    /* from the covariance, scaled by the residual
                                                 * variance, SI */
    int at_bound[TIRENV_FIT_MAX_PARAMS];        /* -1: the fit drove it to its lower bound
                                                 * (within 1 % of the bound's scale: |bound|,
                                                 * or the start value for a bound of 0), so
                                                 * the data want a value the model cannot
                                                 * take; 0: inside its range */
    double bound[TIRENV_FIT_MAX_PARAMS];        /* that lower bound (ELLIPS_ORDER 1, a
                                                 * stiffness 0), SI */
    size_t iterations;
    size_t n_points;       /* residuals */
    double rms;            /* over all training points, m */
    double seconds;        /* wall time */
    const char *stop;      /* why the solver stopped */
} tirenv_fit_report;

/* Fits on the cases of split `split` of ds (normally TIRENV_SPLIT_TRAIN), starting from and
 * writing the result into *tire. s NULL: the defaults; report may be NULL; TIRENV_EINVAL
 * if ds or tire is NULL. */
int tirenv_fit(const tirenv_dataset *ds, tirenv_split split, const tirenv_fit_settings *s,
               tirenv_tire *tire, tirenv_fit_report *report, tirenv_diag *diag);

/* ---- The network over seeds ------------------------------------------------------------ */

/* With 19 training curves a network's validation error depends on its seed about as much as
 * on anything else, so one seed's figure says little: this trains one configuration with n
 * seeds and reports the distribution. The measure is the study's: per seed the mean over
 * the validation cases of each case's RMS error (the network's curve as tirenv_compare
 * draws it, tirenv_case_predict_nn). */
typedef struct {
    size_t n_seeds, n_cases;
    unsigned long *seed;           /* n_seeds: settings->seed, settings->seed + 1, ... */
    size_t *case_index;            /* n_cases: the validation cases, indices into val */
    double *rms;                   /* n_seeds x n_cases: seed s on case c, rms[s*n_cases + c], m */
    double *mean_rms;              /* n_seeds: the mean over the cases, m */
    double median, q1, q3, min, max;  /* of mean_rms, m; quartiles interpolated linearly
                                      * between order statistics (R's type 7) */
    double *control_rms;           /* n_seeds: the same measure on fit's control cases, m
                                    * (what a choice of settings may be tuned on; NaN if
                                    * there are none) */
    double control_median, control_q1, control_q3;  /* of control_rms, m */
    size_t median_seed;            /* the seed (index) whose mean_rms is nearest the median,
                                    * the lower one of two */
    double seconds;                /* the trainings' wall time, summed over the seeds */
} tirenv_nn_seeds;

/* Trains with the trainer and settings on the train and control cases of fit and measures on
 * the validation cases of val, for seeds settings->seed to settings->seed + n_seeds - 1, R0
 * the radius x_N refers to. Each seed is a function of its arguments alone. median_net (may
 * be NULL) receives the model of the median seed and median_report its training report
 * (may be NULL). Free out with tirenv_nn_seeds_free, also after a failure. */
int tirenv_nn_train_seeds(const tirenv_trainer_type *type, const tirenv_train_settings *settings,
                          const tirenv_dataset *fit, const tirenv_dataset *val, double R0,
                          size_t n_seeds, tirenv_nn_seeds *out, tirenv_nn **median_net,
                          tirenv_train_report *median_report, tirenv_diag *diag);
void tirenv_nn_seeds_free(tirenv_nn_seeds *r);  /* NULL is a no-op */

/* ---- Comparison (docs/models.md section 8; the paper's Table 3 and Figure 5) ------------ */

#define TIRENV_COMPARE_MAX_MODELS 8   /* physical models plus the network */

/* What to compare and where to write it. */
typedef struct {
    const char *const *cases;   /* names of the cases to compare, in this order; NULL or
                                 * n_cases 0: every case of `split` in data-set order */
    size_t n_cases;
    tirenv_split split;         /* used when no names are given (default validation) */
    const tirenv_model_type *models[TIRENV_COMPARE_MAX_MODELS - 1];
    size_t n_models;            /* models evaluated (default rigid, springs); the network's
                                 * type (TIRENV_MODEL_NEEDS_NETWORK) among them needs nn and
                                 * comes last, run at the cases' contact lengths */
    int with_nn;                /* also the network when one is given and it is not listed
                                 * (default 1) */
    int simulated;              /* 1: the "measured" curves are simulated (default 0) */
    const tirenv_model_type *simulated_by; /* the reference model that simulated them, or
                                 * NULL; it is evaluated too (with the tire's parameters)
                                 * and implies simulated */
    int simulated_raw;          /* 1: they are simulated_by's own curves, not through the
                                 * virtual rig (a tirenv sweep without --rig): no noise, no
                                 * import (default 0) */
    double nn_R0;               /* free radius the network's x_N refers to (the model file's
                                 * record), m; 0: the tire's R0 (default 0) */
    double rise_threshold;      /* h defining the first rise, m (default 1e-3) */
    double min_time;            /* timing: at least this long per model, s (default 0.02) */
    double fail_fraction;       /* the report calls a model off on a case when its RMS error
                                 * exceeds this share of the measured peak (default 0.1) */
    const char *out_dir;        /* created if missing (default "out/compare") */
    const char *title;          /* headline of the report, or NULL for a generic one */
    const char *data_label;     /* how the report names the data set (e.g. its directory),
                                 * or NULL for ds->dir */
    const char *tire_label;     /* where the physical models' parameters came from, or NULL */
    const char *nn_label;       /* where the network came from, or NULL */
    int images;                 /* 1: run gnuplot to draw PNG and SVG (default 1) */
    const char *gnuplot;        /* the gnuplot program (default "gnuplot", found on PATH) */
    size_t jobs;                /* (model, case) evaluations run at once, each worker with
                                 * its own instance of every model (default 1: no thread;
                                 * tirenv/parallel.h); the curves and errors are the same, bit
                                 * for bit, for every value, the timings are each thread's
                                 * own CPU time */
} tirenv_compare_settings;

tirenv_compare_settings tirenv_compare_default(void);

/* One model on one case. */
typedef struct {
    int status;                 /* TIRENV_OK, or why the model failed on the case */
    char message[512];          /* the failure, or "" */
    tirenv_curve_errors errors; /* m; all NaN if the model failed */
    double *h;                  /* the model's curve at the case's points, m (curve.n
                                 * values; NaN if it failed); owned by the result */
} tirenv_compare_entry;

typedef struct {
    size_t n_cases;
    size_t *case_index;         /* the compared cases, as indices into ds->cases */
    size_t n_models;            /* physical models first, the network last if any */
    char model[TIRENV_COMPARE_MAX_MODELS][32];   /* model names ("springs", "nn") */
    int nn_model;               /* index of the network in model[], or -1 */
    int reference_model;        /* index of the model that simulated the data, or -1 */
    tirenv_compare_entry *entry;/* n_cases x n_models, entry[case * n_models + model] */
    double time_per_position[TIRENV_COMPARE_MAX_MODELS]; /* best repeat, s; NaN if the
                                 * model failed on every case */
    size_t timed_positions[TIRENV_COMPARE_MAX_MODELS];   /* positions in one repeat */
    size_t timed_repeats[TIRENV_COMPARE_MAX_MODELS];     /* repeats measured */
    int images;                 /* 1 if the PNG and SVG plots were drawn */
    tirenv_tire tire;           /* the physical models' parameters */
    char nn_layers[64];         /* the network's layer sizes ("4-8-1"), or "" */
} tirenv_compare_result;

/* Evaluates the chosen models on the chosen cases of ds and writes into s->out_dir: per case
 * <case>.dat and <case>.gp (and, with s->images, <case>.png and <case>.svg drawn by gnuplot),
 * errors.csv, errors.md and timing.csv. Physical models are built from tire (checked), the
 * network (NULL: none) is run at the cases' contact lengths with s->nn_R0 when it is above 0
 * (the radius the network's data referred to), else the tire's R0. A model that
 * fails on a case does not stop the comparison: its entry records why. Timing (CPU time of
 * the evaluating thread) repeats each model's pass over all cases until s->min_time has
 * passed and keeps the fastest pass.
 * *out must be freed with tirenv_compare_result_free, also after a failure. TIRENV_EINVAL
 * for an unknown case name or no case, or ds, tire, s or out NULL; TIRENV_EIO when a file
 * cannot be written or gnuplot fails (diag names it). */
int tirenv_compare(const tirenv_dataset *ds, const tirenv_tire *tire, tirenv_nn *nn,
                   const tirenv_compare_settings *s, tirenv_compare_result *out,
                   tirenv_diag *diag);
void tirenv_compare_result_free(tirenv_compare_result *r);  /* NULL is a no-op */

/* Writes s->out_dir/report.md: what was compared, whether the data are simulated, the error
 * table, the plots, the speed ratios and a paragraph on the numbers. notes (Markdown, or
 * NULL) is inserted after the introduction, for a pipeline's own account (fit, training). */
int tirenv_compare_report(const tirenv_dataset *ds, const tirenv_compare_settings *s,
                          const tirenv_compare_result *r, const char *notes,
                          tirenv_diag *diag);

/* The whole study in one call (tirenv study, make demo): identify the springs model (and the
 * cam, unless it simulated the data) on the training cases, train the network on the
 * training cases (early stopping on control), compare every model on the validation cases;
 * then the paper's proposed workflow (a network trained on curves of the identified physical
 * model over a dense grid of obstacles spanning the data set's, no rig time) and the models
 * on obstacles outside the training grid (taller, shorter, other shapes, scaled to the data
 * set's), whose reference curves the virtual rig simulates with the model that simulated the
 * data (the ring for measured data). Writes into out_dir:
 * fitted.tir, nn.json, nn-physical.json, nn-seeds.csv (seed,validation_rms_mm and one
 * <case>_rms_mm column per validation case, mm), report.md with plots and tables, and the
 * subdirectories physical-network/ and outside/ with theirs. */
typedef struct {
    const char *data_dir;          /* data set with cases.csv */
    const char *data_label;        /* how the report and the model files name it (a path as
                                    * the user gave it, never the build machine's); NULL:
                                    * data_dir */
    const char *out_dir;           /* report directory, created if missing */
    tirenv_tire tire;              /* start of the fit; its ring is the reference tire */
    const char *tire_label;        /* where the tire came from, for the report */
    const char *trainer;           /* "lm" (default), "rprop" or "backprop" */
    unsigned long seed;            /* first training seed (default 1) */
    size_t seeds;                  /* the network is trained with seeds seed .. seed + seeds -
                                    * 1 (default 20); nn-seeds.csv holds each one's
                                    * validation error, the report their median and
                                    * quartiles, and nn.json (with the tables and plots) is
                                    * the seed nearest the median */
    tirenv_nn_input_form input;    /* the network's input form (default even; paper: x_N) */
    const tirenv_model_type *simulated_by; /* the model that simulated the data set on the
                                    * virtual rig, with .tire (its source.txt says which,
                                    * tirenv_dataset_source): the reference of the comparison
                                    * and of the obstacles outside the training range, not
                                    * fitted; NULL: measured data, the outside references
                                    * then from the ring (default: the ring, the embedded
                                    * tractor set) */
    int simulated_raw;             /* 1: the data are simulated_by's own curves, not through
                                    * the virtual rig (a tirenv sweep without --rig) (default
                                    * 0) */
    int images;                    /* draw PNG and SVG with gnuplot (default 1) */
    size_t jobs;                   /* threads running at once (default 1: none started;
                                    * tirenv/parallel.h): the fit's cases, the seeds and the
                                    * trainings' restarts, the grid and outside curves, and the
                                    * three comparisons side by side with their evaluations;
                                    * every result but the timings is the same, bit for bit,
                                    * for every value */
    void (*progress)(void *ctx, const char *stage, size_t step, size_t steps);
    void *progress_ctx;
} tirenv_study_settings;

tirenv_study_settings tirenv_study_default(void);

int tirenv_study(const tirenv_study_settings *s, tirenv_diag *diag);

/* ---- One tire, every model: identification on a reference's flat ground (section 14.1) -- */

/* The reference's flat ground at one load, and what the identified models make of it. */
typedef struct {
    double load;             /* N */
    double deflection;       /* the reference's, m */
    double contact_length;   /* the reference's, m */
} tirenv_flat_target;

/* Identifies, on the flat-ground states of the reference model of *tire (the ring for tirenv's
 * tires) at the n >= 2 loads[] (N), the springs model's RADIAL_STIFFNESS and
 * INTERRADIAL_STIFFNESS (its deflection and contact length at each load: the ratio c_b/c_r by
 * golden section on its logarithm, c_r in closed form for each ratio; tirenv_springs_identify,
 * or with a sidewall in *tire tirenv_springs_identify_sidewall) and the cam's
 * VERTICAL_STIFFNESS (with the tire's FNOMIN also Q_FZ2, MF-Tyre's quadratic vertical law),
 * Q_RA1 and Q_RA2 (its deflection, then its contact length: linear least squares in relative
 * error).
 * *out is *tire with those values replaced; target[] (n entries, may be NULL) receives the
 * reference's states. On failure *out is unchanged. */
int tirenv_identify_flat(const tirenv_tire *tire, const tirenv_model_type *reference, size_t n,
                         const double loads[], tirenv_tire *out, tirenv_flat_target target[],
                         tirenv_diag *diag);

/* The same on m reference models refs[] (1 to 4, none the springs model) together: with one,
 * tirenv_identify_flat; with more, the springs model (and its sidewall where *tire has one)
 * by min-max, the largest relative difference of deflection and contact length from every
 * reference at every load the least (tirenv_springs_identify_minmax). A cam among refs is
 * *tire's as given, not identified; otherwise the cam is identified on refs[0]. target[]
 * (m*n entries, may be NULL) receives reference j's states at [j*n, j*n + n). */
int tirenv_identify_flat_on(const tirenv_tire *tire, size_t m,
                            const tirenv_model_type *const refs[], size_t n,
                            const double loads[], tirenv_tire *out,
                            tirenv_flat_target target[], tirenv_diag *diag);

/* The load-to-contact-length relation of the tire a data set's curves came from, for the
 * network trained on them (docs/models.md section 14.3), as at most TIRENV_CONTACT_LAW_MAX
 * knots: the cases' own (load, contact length) pairs and, around them, loads spaced
 * geometrically from half the smallest to 1.5 times the largest case load, each with the
 * flat-ground contact length of the source model (the one that simulated the data, with its
 * tire); or, with source NULL (measured data), loads so spaced with the power law l_c = a*G^b
 * fitted to the cases' (load, contact length) pairs in log-log least squares. what (n bytes)
 * says which.
 * TIRENV_EINVAL where two cases give one load two contact lengths, where no case has a positive
 * load, or, with source NULL, where the cases have fewer than two different loads or their
 * power law does not grow with the load. */
int tirenv_contact_law_of_data(const tirenv_dataset *ds, const tirenv_model_type *source,
                               const tirenv_tire *tire, tirenv_contact_law *law, char *what,
                               size_t n, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
