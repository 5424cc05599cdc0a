/* tirenv: the paper's study (MODEL.md section 8): identify the physical model on the training
 * cases, evaluate every model on a data set's cases, and measure how far each is off. This is
 * the convenience layer on top of the models, the data sets and the network. */
#ifndef TIRENV_STUDY_H
#define TIRENV_STUDY_H

#include <stddef.h>
#include "tirenv/dataset.h"
#include "tirenv/error.h"
#include "tirenv/model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct tirenv_nn tirenv_nn;  /* the network, tirenv/nn.h */

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
 * driven by the case's applied load over the cleat L x H, as on the rig. h[] has curve.n
 * entries. */
int tirenv_case_predict_model(tirenv_model *m, const tirenv_case *c, double h[],
                              tirenv_diag *diag);

/* The network's curve for a case at the case's points: driven by the measured contact length,
 * as in the paper. */
int tirenv_case_predict_nn(tirenv_nn *nn, double R0, const tirenv_case *c, double h[],
                           tirenv_diag *diag);

/* Identification of a physical model (c_r and c_b, optionally R0) on the training cases by
 * nonlinear least squares on h (GSL multifit_nlinear, trust region with Levenberg-Marquardt
 * steps), in log parameters so they stay positive. */
typedef struct {
    const tirenv_model_type *type;  /* springs (default) */
    int fit_R0;            /* also fit UNLOADED_RADIUS */
    size_t max_iter;       /* trust-region iterations (default 50) */
    double xtol;           /* relative step tolerance (default 1e-6) */
    void (*progress)(void *ctx, size_t iter, double rms); /* may be NULL */
    void *progress_ctx;
} tirenv_fit_settings;

tirenv_fit_settings tirenv_fit_default(void);

#define TIRENV_FIT_MAX_PARAMS 3

typedef struct {
    size_t n_params;
    const char *names[TIRENV_FIT_MAX_PARAMS];   /* .tir keys */
    double value[TIRENV_FIT_MAX_PARAMS];        /* fitted, SI */
    double std_error[TIRENV_FIT_MAX_PARAMS];    /* from the covariance, scaled by the residual
                                                 * variance, SI */
    size_t iterations;
    size_t n_points;       /* residuals */
    double rms;            /* over all training points, m */
    double seconds;        /* wall time */
    const char *stop;      /* why the solver stopped */
} tirenv_fit_report;

/* Fits on the cases of split `split` of ds (normally TIRENV_SPLIT_TRAIN), starting from and
 * writing the result into *tire. */
int tirenv_fit(const tirenv_dataset *ds, tirenv_split split, const tirenv_fit_settings *s,
               tirenv_tire *tire, tirenv_fit_report *report, tirenv_diag *diag);

#ifdef __cplusplus
}
#endif
#endif
