/* Identification of a physical model on measured curves (docs/models.md section 8): nonlinear least
 * squares on h over the training cases, with standard errors from the covariance. */
#include "tirenv/study.h"
#include "study/clock.h"
#include "tirenv/parallel.h"

#include <math.h>
#include <stdlib.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

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
    gsl_vector *r;                /* the pass's residuals */
    double last_pass;             /* wall time of the previous pass, s (-1: none yet) */
    int status;                   /* first failure inside the residual function */
    tirenv_diag *diag;
} fit_ctx;

static void set_params(fit_ctx *c, const gsl_vector *p)
{
    for (size_t i = 0; i < c->n_params; ++i)
        *field(&c->tire, &c->params[i]) = c->params[i].lower + exp(gsl_vector_get(p, i));
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
        gsl_vector_set(c->r, c->offset[k] + j, h[j] - cs->curve.h[j]);
    return TIRENV_OK;
}

/* Threads pay only for passes that take a while: starting them and handing out the cases
 * costs tens of microseconds, and on a loaded machine a new thread may wait milliseconds for
 * its first turn, against a pass of the cam (19 cases x 101 points at 0.1 us) that takes a
 * fraction of one. So the first pass runs on this thread, and the others run on c->jobs only
 * when the one before took PARALLEL_PASS or longer. The residuals are the same either way. */
enum { PARALLEL_PASS_US = 5000 };

/* Residuals h_model - h_meas over every point of every case of the split. */
static int residuals(const gsl_vector *p, void *data, gsl_vector *r)
{
    fit_ctx *c = data;
    set_params(c, p);
    c->r = r;
    for (size_t w = 0; w < c->jobs; ++w)
        c->models[w] = NULL;
    if (!(c->models[0] = tirenv_model_alloc(c->type, &c->tire))) {
        /* A trial step out of the physical range (the ring's belt buckling on its
         * foundation, say) is a step the trust region must refuse, not the end of the fit:
         * a residual of 1 m at every point is worse than any curve of the model. */
        gsl_vector_set_all(r, 1.0);
        return GSL_SUCCESS;
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
        return GSL_EDOM;
    }
    return GSL_SUCCESS;
}

static void fit_callback(const size_t iter, void *params_, const gsl_multifit_nlinear_workspace *w)
{
    const tirenv_fit_settings *s = params_;
    if (!s->progress)
        return;
    const gsl_vector *f = gsl_multifit_nlinear_residual(w);
    double norm;
    norm = gsl_blas_dnrm2(f);
    s->progress(s->progress_ctx, iter, norm / sqrt((double)f->size));
}

int tirenv_fit(const tirenv_dataset *ds, tirenv_split split, const tirenv_fit_settings *s,
               tirenv_tire *tire, tirenv_fit_report *report, tirenv_diag *diag)
{
    const double t0 = tirenv_study__wall_seconds();
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
    size_t n = 0;
    for (size_t i = 0; i < ds->n; ++i)
        if (ds->cases[i].split == split) {
            n += ds->cases[i].curve.n;
            c.n_max = ds->cases[i].curve.n > c.n_max ? ds->cases[i].curve.n : c.n_max;
            ++c.n_cases;
        }
    if (n <= c.n_params)
        return tirenv_error(diag, TIRENV_EINVAL, ds->dir, 0, "split",
                            "%zu points in the %s cases: too few to fit %zu parameters", n,
                            tirenv_split_name(split), c.n_params);
    if (c.jobs > c.n_cases)
        c.jobs = c.n_cases;
    c.cases = malloc(c.n_cases * sizeof *c.cases);
    c.offset = malloc(c.n_cases * sizeof *c.offset);
    c.models = calloc(c.jobs, sizeof *c.models);
    c.h = malloc(c.jobs * c.n_max * sizeof *c.h);
    if (c.cases && c.offset) {
        size_t k = 0, at = 0;
        for (size_t i = 0; i < ds->n; ++i)
            if (ds->cases[i].split == split) {
                c.cases[k] = i;
                c.offset[k++] = at;
                at += ds->cases[i].curve.n;
            }
    }
    gsl_multifit_nlinear_parameters fp = gsl_multifit_nlinear_default_parameters();
    fp.trs = gsl_multifit_nlinear_trs_lm;
    /* Finite-difference Jacobian: the step must dwarf the equilibrium tolerance (1e-10 m)
     * relative to h (1e-2 m); 1e-4 in log parameters moves h by about 1e-6 m. */
    fp.h_df = 1e-4;
    gsl_multifit_nlinear_workspace *w =
        gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &fp, n, c.n_params);
    gsl_vector *p0 = gsl_vector_alloc(c.n_params);
    gsl_matrix *covar = gsl_matrix_alloc(c.n_params, c.n_params);
    if (!c.h || !c.cases || !c.offset || !c.models || !w || !p0 || !covar) {
        free(c.h);
        free(c.cases);
        free(c.offset);
        free(c.models);
        gsl_multifit_nlinear_free(w);
        gsl_vector_free(p0);
        gsl_matrix_free(covar);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "fit", "out of memory");
    }
    for (size_t i = 0; i < c.n_params; ++i)
        gsl_vector_set(p0, i, log(fmax(*field(&c.tire, &c.params[i]) - c.params[i].lower,
                                       1e-12)));
    gsl_multifit_nlinear_fdf fdf = {.f = residuals, .df = NULL, .fvv = NULL, .n = n,
                                    .p = c.n_params, .params = &c};
    double start[TIRENV_FIT_MAX_PARAMS];
    for (size_t i = 0; i < c.n_params; ++i)
        start[i] = *field(&c.tire, &c.params[i]);
    int info = 0;
    int status = gsl_multifit_nlinear_init(p0, &fdf, w);
    if (!status)
        status = gsl_multifit_nlinear_driver(s->max_iter, s->xtol, 1e-10, 1e-10, fit_callback,
                                             (void *)s, &info, w);
    int result = TIRENV_OK;
    if (c.status) {
        result = c.status;
    } else if (status && status != GSL_EMAXITER) {
        result = tirenv_error(diag, TIRENV_ENOCONV, "", 0, "fit", "%s", gsl_strerror(status));
    } else {
        /* Covariance of the log parameters, scaled by the residual variance; for
         * c = lower + e^p the standard error is (c - lower) * sigma_p to first order. */
        const gsl_vector *f = gsl_multifit_nlinear_residual(w);
        double chisq;
        gsl_blas_ddot(f, f, &chisq);
        gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w), 0.0, covar);
        const double sigma2 = chisq / (double)(n - c.n_params);
        set_params(&c, gsl_multifit_nlinear_position(w));
        *report = (tirenv_fit_report){
            .n_params = c.n_params,
            .iterations = gsl_multifit_nlinear_niter(w),
            .n_points = n,
            .rms = sqrt(chisq / (double)n),
            .stop = status == GSL_EMAXITER ? "iteration limit"
                    : info == 1            ? "small step"
                                           : "small gradient",
        };
        for (size_t i = 0; i < c.n_params; ++i) {
            report->names[i] = c.params[i].key;
            report->value[i] = *field(&c.tire, &c.params[i]);
            report->std_error[i] = (report->value[i] - c.params[i].lower) *
                                   sqrt(sigma2 * gsl_matrix_get(covar, i, i));
            /* In log(value - lower) the bound is at minus infinity: the solver only gets
             * near it, so "at the bound" is within 1 % of the bound's own scale (|lower|, or
             * the start for a bound of 0, as a stiffness has). */
            const double lo = c.params[i].lower;
            const double scale = lo != 0 ? fabs(lo) : fabs(start[i] - lo);
            report->bound[i] = lo;
            report->at_bound[i] = report->value[i] - lo <= 0.01 * scale ? -1 : 0;
        }
        *tire = c.tire;
    }
    report->seconds = tirenv_study__wall_seconds() - t0;
    free(c.h);
    free(c.cases);
    free(c.offset);
    free(c.models);
    gsl_multifit_nlinear_free(w);
    gsl_vector_free(p0);
    gsl_matrix_free(covar);
    return result;
}
