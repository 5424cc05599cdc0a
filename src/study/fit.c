/* SPDX-License-Identifier: Apache-2.0 */
/* Identification of a physical model on measured curves (docs/models.md section 8): nonlinear least
 * squares on h over the training cases, with standard errors from the covariance.
 *
 * The solver is Minpack's lmdif (More's Levenberg-Marquardt with a forward-difference
 * Jacobian, through cminpack): the same method GSL's gsl_multifit_nlinear trust region ran
 * with trs_lm until version 0.1, with the same difference step. The standard errors come from
 * the Jacobian at the solution, formed afresh there (lmdif's last one belongs to the point its
 * last iteration started from), by Minpack's qrfac and covar as GSL's covariance did. */
#include "tirenv/study.h"
#include "study/clock.h"
#include "tirenv/parallel.h"

#include <math.h>
#include <stdlib.h>
#include <limits.h>
#include <cminpack.h>
#include "io/io.h"

tirenv_fit_settings tirenv_fit_default(void)
{
    return (tirenv_fit_settings){.type = NULL, .fit_R0 = 0, .max_iter = 50, .xtol = 1e-6,
                                 .jobs = 1, .progress = NULL, .progress_ctx = NULL};
}

/* A parameter is fitted as log(value - lower), which keeps it above its bound (positive
 * stiffnesses, ELLIPS_ORDER > 1) and gives a stiffness of 1e6 and a radius of 0.7 steps of the
 * same relative size. Which parameters a model has is a property of its type
 * (tirenv_model_type_params). */
static double *field(tirenv_tire *t, const tirenv_model_param *p)
{
    return (double *)((char *)t + p->offset);
}

typedef struct {
    const tirenv_dataset *ds;
    tirenv_split split;
    const tirenv_model_type *type;
    tirenv_tire tire;             /* the working copy the parameters are written into */
    const tirenv_model_param *params;
    size_t n_params;
    size_t jobs;                  /* cases evaluated at once (tirenv/parallel.h) */
    size_t n_cases;               /* cases of the split */
    size_t *cases;                /* their indices in ds */
    size_t *offset;               /* where each one's residuals start */
    size_t n_max;                 /* the most points of a case */
    double *h;                    /* scratch: one case's model curve per worker */
    tirenv_model **models;        /* one model per worker, for the parameters of a pass */
    double *r;                    /* the pass's residuals */
    size_t jac_evals;             /* passes for Jacobian columns (n_params per iteration) */
    size_t progress_calls;
    const tirenv_fit_settings *s;
    double last_pass;             /* wall time of the previous pass, s (-1: none yet) */
    int status;                   /* first failure inside the residual function */
    tirenv_diag *diag;
} fit_ctx;

static void set_params(fit_ctx *c, const double p[])
{
    for (size_t i = 0; i < c->n_params; ++i)
        *field(&c->tire, &c->params[i]) = c->params[i].lower + exp(p[i]);
}

/* One case's residuals h_model - h_meas, into its own stretch of r: the cases are
 * independent, so they run on c->jobs threads, each worker with a model of its own built for
 * this pass's parameters (a model is set afresh on every case, so its curve does not depend
 * on which worker ran it). */
static int case_residuals(void *ctx, size_t k, size_t worker, tirenv_diag *diag)
{
    fit_ctx *c = ctx;
    if (!c->models[worker] && !(c->models[worker] = tirenv_model_alloc(c->type, &c->tire)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "fit",
                            "parameters left the physical range");
    const tirenv_case *cs = &c->ds->cases[c->cases[k]];
    double *h = c->h + worker * c->n_max;
    const int status = tirenv_case_predict_model(c->models[worker], cs, h, diag);
    if (status)
        return status;
    for (size_t j = 0; j < cs->curve.n; ++j)
        c->r[c->offset[k] + j] = h[j] - cs->curve.h[j];
    return TIRENV_OK;
}

/* Threads pay only for passes that take a while: starting them and handing out the cases
 * costs tens of microseconds, and on a loaded machine a new thread may wait milliseconds for
 * its first turn, against a pass of the cam (19 cases x 101 points at 0.1 us) that takes a
 * fraction of one. So the first pass runs on this thread, and the others run on c->jobs only
 * when the one before took PARALLEL_PASS or longer. The residuals are the same either way. */
enum { PARALLEL_PASS_US = 5000 };

/* Residuals h_model - h_meas over every point of every case of the split. */
static int residuals(const double p[], fit_ctx *c, double r[], size_t n)
{
    set_params(c, p);
    c->r = r;
    for (size_t w = 0; w < c->jobs; ++w)
        c->models[w] = NULL;
    if (!(c->models[0] = tirenv_model_alloc(c->type, &c->tire))) {
        /* A trial step out of the physical range (the ring's belt buckling on its
         * foundation, say) is a step the trust region must refuse, not the end of the fit:
         * a residual of 1 m at every point is worse than any curve of the model. */
        for (size_t i = 0; i < n; ++i)
            r[i] = 1.0;
        return TIRENV_OK;
    }
    const size_t jobs = c->last_pass >= 1e-6 * PARALLEL_PASS_US ? c->jobs : 1;
    const double t0 = tirenv_study__wall_seconds();
    const int status = tirenv_parallel_for(c->n_cases, jobs, case_residuals, NULL, c,
                                           c->diag);
    c->last_pass = tirenv_study__wall_seconds() - t0;
    for (size_t w = 0; w < c->jobs; ++w)
        tirenv_model_free(c->models[w]);
    if (status) {
        c->status = status;
        return status;
    }
    return TIRENV_OK;
}

/* lmdif's callback: iflag 1 residuals, 2 residuals for a Jacobian column, 0 progress (at the
 * start of every iteration and before returning, with fvec the current residuals). A
 * negative return stops lmdif: a failure of the model, kept in c->status. */
static int lmdif_fcn(void *p, int m, int n, const double *x, double *fvec, int iflag)
{
    fit_ctx *c = p;
    (void)n;
    if (iflag == 0) {
        if (c->s->progress) {
            double sum = 0;
            for (int i = 0; i < m; ++i)
                sum += fvec[i] * fvec[i];
            c->s->progress(c->s->progress_ctx, c->progress_calls, sqrt(sum / (double)m));
        }
        ++c->progress_calls;
        return 0;
    }
    if (iflag == 2)
        ++c->jac_evals;
    return residuals(x, c, fvec, (size_t)m) ? -1 : 0;
}

/* The forward-difference Jacobian at x (column-major, n x p), step 1e-4 |x_j| (1e-4 at 0) as
 * lmdif's with epsfcn 1e-8; f the residuals at x, x restored. */
static int jacobian_at(fit_ctx *c, double x[], const double f[], size_t n, double J[],
                       double f_step[])
{
    for (size_t j = 0; j < c->n_params; ++j) {
        const double x_j = x[j], h = x_j != 0 ? 1e-4 * fabs(x_j) : 1e-4;
        x[j] = x_j + h;
        const int status = residuals(x, c, f_step, n);
        x[j] = x_j;
        if (status)
            return status;
        for (size_t i = 0; i < n; ++i)
            J[j * n + i] = (f_step[i] - f[i]) / h;
    }
    return residuals(x, c, f_step, n);  /* leave the working tire at x */
}

/* lmdif's arrays: the log parameters x, the residuals f, the Jacobian J (lmdif's fjac, then
 * the one at the solution), ipvt, and its work vectors carved out of work. */
typedef struct {
    double *x, *f, *J, *work;
    int *ipvt;
    double *diag_scale, *qtf, *wa1, *wa2, *wa3, *wa4, *f_step;
} fit_arrays;

/* The arrays of tirenv_fit, freed on both of its ways out once they are allocated (any of
 * them may be NULL: a failed allocation). */
static void fit_free(fit_ctx *c, fit_arrays *a)
{
    free(c->h);
    free(c->cases);
    free(c->offset);
    free(c->models);
    free(a->x);
    free(a->f);
    free(a->J);
    free(a->work);
    free(a->ipvt);
}

/* The points of the split's cases; c's count of them and their longest curve. */
static size_t count_points(const tirenv_dataset *ds, tirenv_split split, fit_ctx *c)
{
    size_t n = 0;
    for (size_t i = 0; i < ds->n; ++i)
        if (ds->cases[i].split == split) {
            n += ds->cases[i].curve.n;
            c->n_max = ds->cases[i].curve.n > c->n_max ? ds->cases[i].curve.n : c->n_max;
            ++c->n_cases;
        }
    return n;
}

/* c's cases and workers' arrays and lmdif's for n points, the split's cases indexed with
 * where each one's residuals start; nonzero if any could not be had (fit_free frees what
 * was). */
static int fit_alloc(fit_ctx *c, size_t n, fit_arrays *a)
{
    const tirenv_dataset *ds = c->ds;
    c->cases = malloc(c->n_cases * sizeof *c->cases);
    c->offset = malloc(c->n_cases * sizeof *c->offset);
    c->models = calloc(c->jobs, sizeof *c->models);
    c->h = malloc(c->jobs * c->n_max * sizeof *c->h);
    if (c->cases && c->offset) {
        size_t k = 0, at = 0;
        for (size_t i = 0; i < ds->n; ++i)
            if (ds->cases[i].split == c->split) {
                c->cases[k] = i;
                c->offset[k++] = at;
                at += ds->cases[i].curve.n;
            }
    }
    const size_t p = c->n_params;
    a->x = malloc(p * sizeof *a->x);
    a->f = malloc(n * sizeof *a->f);
    a->J = malloc(n * p * sizeof *a->J);
    a->work = malloc((5 * p + 2 * n) * sizeof *a->work);
    a->ipvt = malloc(p * sizeof *a->ipvt);
    if (!c->h || !c->cases || !c->offset || !c->models || !a->x || !a->f || !a->J ||
        !a->work || !a->ipvt || n > (size_t)INT_MAX / (p + 1))
        return -1;
    a->diag_scale = a->work;
    a->qtf = a->work + p;
    a->wa1 = a->work + 2 * p;
    a->wa2 = a->work + 3 * p;
    a->wa3 = a->work + 4 * p;
    a->wa4 = a->work + 5 * p;
    a->f_step = a->work + 5 * p + n;
    return 0;
}

/* The report at the solution a->x (the Jacobian there in a->J, lmdif's info): the fitted
 * values with their standard errors, and which sit at their bounds (start: the values the fit
 * started from). c's tire is left at the solution. */
static void report_fit(fit_ctx *c, fit_arrays *a, size_t n, int info, const double start[],
                       tirenv_fit_report *report)
{
    const size_t p = c->n_params;
    double *J = a->J;
    /* Covariance of the log parameters, scaled by the residual variance; for c = lower + e^p
     * the standard error is (c - lower) * sigma_p to first order. */
    double chisq = 0;
    for (size_t i = 0; i < n; ++i)
        chisq += a->f[i] * a->f[i];
    qrfac((int)n, (int)p, J, (int)n, 1, a->ipvt, (int)p, a->wa1, a->wa2, a->wa3);
    for (size_t j = 0; j < p; ++j)
        J[j * n + j] = a->wa1[j];  /* qrfac keeps R's diagonal apart */
    covar((int)p, J, (int)n, a->ipvt, 0.0, a->wa1);
    const double sigma2 = chisq / (double)(n - p);
    set_params(c, a->x);
    *report = (tirenv_fit_report){
        .n_params = p,
        .iterations = c->jac_evals / p,
        .n_points = n,
        .rms = sqrt(chisq / (double)n),
        .stop = info == 5                           ? "iteration limit"
                : info == 2 || info == 3 || info == 7 ? "small step"
                : info == 4 || info == 8            ? "small gradient"
                                                    : "small reduction",
    };
    for (size_t i = 0; i < p; ++i) {
        report->names[i] = c->params[i].key;
        report->value[i] = *field(&c->tire, &c->params[i]);
        report->std_error[i] = (report->value[i] - c->params[i].lower) *
                               sqrt(sigma2 * J[i * n + i]);
        /* In log(value - lower) the bound is at minus infinity: the solver only gets near
         * it, so "at the bound" is within 1 % of the bound's own scale (|lower|, or the start
         * for a bound of 0, as a stiffness has). */
        const double lo = c->params[i].lower;
        const double scale = lo != 0 ? fabs(lo) : fabs(start[i] - lo);
        report->bound[i] = lo;
        report->at_bound[i] = report->value[i] - lo <= 0.01 * scale ? -1 : 0;
    }
}

/* A cam's shape holds up to the tallest obstacle it was identified on, which is what
 * MF-Swift's ELLIPS_MAX_STEP says (docs/models.md section 7.5), within its range (R0). */
static double tallest_step(const fit_ctx *c, double R0)
{
    double max_step = 0;
    for (size_t k = 0; k < c->n_cases; ++k)
        max_step = fmax(max_step, c->ds->cases[c->cases[k]].H);
    return fmin(max_step, R0);
}

int tirenv_fit(const tirenv_dataset *ds, tirenv_split split, const tirenv_fit_settings *s,
               tirenv_tire *tire, tirenv_fit_report *report, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    const double t0 = tirenv_study__wall_seconds();
    if (!ds || !tire)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "no data set or no tire to fit");
    const tirenv_fit_settings defaults = tirenv_fit_default();
    tirenv_fit_report unreported;
    s = s ? s : &defaults;
    report = report ? report : &unreported;
    const tirenv_model_type *type = s->type ? s->type : tirenv_model_springs;
    size_t n_params, n_params_max;
    const tirenv_model_param *params = tirenv_model_type_params(type, &n_params, &n_params_max);
    if (!(tirenv_model_type_flags(type) & TIRENV_MODEL_FITTABLE) || !params)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "model",
                            "the %s model has no parameters to fit", tirenv_model_type_name(type));
    fit_ctx c = {.ds = ds, .split = split, .type = type, .tire = *tire, .params = params,
                 .n_params = s->fit_R0 ? n_params_max : n_params,
                 .jobs = s->jobs ? s->jobs : 1, .last_pass = -1, .diag = diag};
    if (c.n_params > TIRENV_FIT_MAX_PARAMS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "model",
                            "the %s model has %zu parameters; a fit takes at most %d",
                            tirenv_model_type_name(type), c.n_params, TIRENV_FIT_MAX_PARAMS);
    /* The start must be a tire the model takes: out of range, every residual would read as
     * a refused step (residuals()) and the fit would report 1 m as its result. */
    const int start_ok = tirenv_tire_check(tire, diag);
    if (start_ok)
        return start_ok;
    const size_t n = count_points(ds, split, &c);
    if (n <= c.n_params)
        return tirenv_error(diag, TIRENV_EINVAL, ds->dir, 0, "split",
                            "%zu points in the %s cases: too few to fit %zu parameters", n,
                            tirenv_split_name(split), c.n_params);
    if (c.jobs > c.n_cases)
        c.jobs = c.n_cases;
    fit_arrays a = {.x = NULL};
    if (fit_alloc(&c, n, &a)) {
        fit_free(&c, &a);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "fit", "out of memory");
    }
    const size_t p = c.n_params;
    for (size_t i = 0; i < p; ++i)
        a.x[i] = log(fmax(*field(&c.tire, &c.params[i]) - c.params[i].lower, 1e-12));
    double start[TIRENV_FIT_MAX_PARAMS];
    for (size_t i = 0; i < p; ++i)
        start[i] = *field(&c.tire, &c.params[i]);
    c.s = s;
    /* Finite-difference Jacobian: the step must dwarf the equilibrium tolerance (1e-10 m)
     * relative to h (1e-2 m); sqrt(epsfcn) = 1e-4 in log parameters moves h by about 1e-6 m.
     * An iteration costs one pass per parameter for the Jacobian and one or more trial steps:
     * max_iter iterations are about max_iter (p + 1) passes. */
    /* factor: the first step's bound, times the scaled norm of the start. Minpack's usual 100
     * let the first trial of a cam fit (test_fit's bound case) jump to where its curves no
     * longer depend on the parameters, and it stopped there on a zero gradient at 12.6 mm
     * RMS; 0.3 and 1 both found the truth (measured), 0.3 with fewer iterations. */
    int nfev = 0;
    const int maxfev = (int)(s->max_iter * (p + 1) + 1);
    const int info = lmdif(lmdif_fcn, &c, (int)n, (int)p, a.x, a.f, 1e-10, s->xtol, 1e-10,
                           maxfev, 1e-8, a.diag_scale, 1, 0.3, 1, &nfev, a.J, (int)n, a.ipvt,
                           a.qtf, a.wa1, a.wa2, a.wa3, a.wa4);
    int result = TIRENV_OK;
    if (c.status) {
        result = c.status;
    } else if (info < 1 || info > 8) {
        result = tirenv_error(diag, TIRENV_ENOCONV, "", 0, "fit",
                              "Minpack's lmdif stopped with info %d", info);
    } else if (!(result = jacobian_at(&c, a.x, a.f, n, a.J, a.f_step))) {
        report_fit(&c, &a, n, info, start, report);
        *tire = c.tire;
        if (type == tirenv_model_cam)
            tire->cam.max_step = tallest_step(&c, tire->springs.R0);
    }
    report->seconds = tirenv_study__wall_seconds() - t0;
    fit_free(&c, &a);
    return result;
}
