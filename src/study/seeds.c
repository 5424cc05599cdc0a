/* The network trained with many seeds, and the spread of its validation error
 * (docs/models.md section 6): with 19 training curves one seed's figure is an anecdote.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/study.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tirenv/parallel.h"

void tirenv_nn_seeds_free(tirenv_nn_seeds *r)
{
    if (!r)
        return;
    free(r->seed);
    free(r->case_index);
    free(r->rms);
    free(r->mean_rms);
    free(r->control_rms);
    memset(r, 0, sizeof *r);
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The p-quantile of n sorted values, linear between order statistics (type 7). */
static double quantile(const double v[], size_t n, double p)
{
    const double h = (double)(n - 1) * p;
    const size_t lo = (size_t)floor(h);
    return lo + 1 < n ? v[lo] + (h - (double)lo) * (v[lo + 1] - v[lo]) : v[n - 1];
}

/* The RMS error of the network's curve on one case; h is scratch of cs->curve.n. */
static int case_rms(tirenv_nn *nn, double R0, const tirenv_case *cs, double h[], double *rms,
                    tirenv_diag *diag)
{
    tirenv_curve_errors e;
    int status = tirenv_case_predict_nn(nn, R0, cs, h, diag);
    if (!status)
        status = tirenv_curve_errors_compute(cs->curve.n, cs->curve.x, cs->curve.h, h, 1e-3,
                                             &e);
    if (!status)
        *rms = e.rms;
    return status;
}

/* The mean over the cases of `split` in ds of each one's RMS error (the network's curve);
 * NaN if there are none. */
static int mean_case_rms(tirenv_nn *nn, double R0, const tirenv_dataset *ds, tirenv_split split,
                         double h[], double *mean, tirenv_diag *diag)
{
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < ds->n; ++i) {
        if (ds->cases[i].split != split)
            continue;
        double rms;
        const int status = case_rms(nn, R0, &ds->cases[i], h, &rms, diag);
        if (status)
            return status;
        sum += rms;
        ++n;
    }
    *mean = n ? sum / (double)n : NAN;
    return TIRENV_OK;
}

/* One seed: train, then the network's curve on every validation case and its RMS error. A
 * function of its arguments alone, with its own scratch: it writes only seed k's entries of
 * out, *nn and *rep, so seeds may run in any order, or at once. */
static int one_seed(const tirenv_trainer_type *type, const tirenv_train_settings *s,
                    const tirenv_samples set[3], const tirenv_dataset *fit,
                    const tirenv_dataset *val, double R0, size_t n_max,
                    const tirenv_nn_seeds *out, size_t k, tirenv_nn **nn,
                    tirenv_train_report *rep, tirenv_diag *diag)
{
    double *h = malloc((n_max ? n_max : 1) * sizeof *h);
    if (!h)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    int status = tirenv_train(type, s, &set[0], &set[1], &set[2], nn, rep, diag);
    if (!status)
        status = mean_case_rms(*nn, R0, fit, TIRENV_SPLIT_CONTROL, h, &out->control_rms[k],
                               diag);
    double sum = 0;
    for (size_t c = 0; c < out->n_cases && !status; ++c) {
        double *rms = &out->rms[k * out->n_cases + c];
        status = case_rms(*nn, R0, &val->cases[out->case_index[c]], h, rms, diag);
        if (!status)
            sum += *rms;
    }
    out->mean_rms[k] = sum / (double)out->n_cases;
    free(h);
    return status;
}

/* The seeds as work items (tirenv/parallel.h); a progress callback is called by one training
 * at a time, and once it asks to stop, every training running stops at its next call
 * (tirenv_train_progress_gate). */
typedef struct {
    const tirenv_trainer_type *type;
    const tirenv_train_settings *settings;
    const tirenv_samples *set;
    const tirenv_dataset *fit, *val;
    double R0;
    size_t n_max;
    tirenv_nn_seeds *out;
    tirenv_nn **nets;
    tirenv_train_report *reps;
    tirenv_train_settings inner;   /* each seed's training, its progress through the gate
                                    * when the seeds run at once */
} seeds_pass;

static int seed_item(void *ctx, size_t k, size_t worker, tirenv_diag *diag)
{
    seeds_pass *p = ctx;
    (void)worker;
    tirenv_train_settings s = p->inner;
    s.seed = p->settings->seed + k;
    p->out->seed[k] = s.seed;
    return one_seed(p->type, &s, p->set, p->fit, p->val, p->R0, p->n_max, p->out, k,
                    &p->nets[k], &p->reps[k], diag);
}

int tirenv_nn_train_seeds(const tirenv_trainer_type *type, const tirenv_train_settings *settings,
                          const tirenv_dataset *fit, const tirenv_dataset *val, double R0,
                          size_t n_seeds, tirenv_nn_seeds *out, tirenv_nn **median_net,
                          tirenv_train_report *median_report, tirenv_diag *diag)
{
    memset(out, 0, sizeof *out);
    if (median_net)
        *median_net = NULL;
    if (n_seeds < 1)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "seeds", "no seeds to train");
    size_t n_cases = 0, n_max = 0;
    for (size_t i = 0; i < val->n; ++i)
        if (val->cases[i].split == TIRENV_SPLIT_VALIDATION) {
            ++n_cases;
            n_max = val->cases[i].curve.n > n_max ? val->cases[i].curve.n : n_max;
        }
    for (size_t i = 0; i < fit->n; ++i)
        if (fit->cases[i].split == TIRENV_SPLIT_CONTROL)
            n_max = fit->cases[i].curve.n > n_max ? fit->cases[i].curve.n : n_max;
    if (n_cases == 0)
        return tirenv_error(diag, TIRENV_EINVAL, val->dir, 0, "split",
                            "no validation cases to measure the network on");
    out->n_seeds = n_seeds;
    out->n_cases = n_cases;
    out->seed = malloc(n_seeds * sizeof *out->seed);
    out->case_index = malloc(n_cases * sizeof *out->case_index);
    out->rms = malloc(n_seeds * n_cases * sizeof *out->rms);
    out->mean_rms = malloc(n_seeds * sizeof *out->mean_rms);
    out->control_rms = malloc(n_seeds * sizeof *out->control_rms);
    tirenv_nn **nets = calloc(n_seeds, sizeof *nets);
    tirenv_train_report *reps = malloc(n_seeds * sizeof *reps);
    double *sorted = malloc(n_seeds * sizeof *sorted);
    tirenv_samples set[3];
    double *x[3] = {NULL, NULL, NULL}, *y[3] = {NULL, NULL, NULL};
    int status = TIRENV_OK;
    if (!out->seed || !out->case_index || !out->rms || !out->mean_rms || !out->control_rms ||
        !nets || !reps || !sorted)
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    for (size_t i = 0, c = 0; i < val->n && !status; ++i)
        if (val->cases[i].split == TIRENV_SPLIT_VALIDATION)
            out->case_index[c++] = i;
    const tirenv_dataset *from[3] = {fit, fit, val};
    for (int sp = 0; sp < 3 && !status; ++sp)
        status = tirenv_samples_from_dataset(from[sp], (tirenv_split)sp, &set[sp], &x[sp],
                                             &y[sp], diag);
    /* Independent seeds: no state is shared from one to the next, so they run on
     * settings->jobs threads, each training's restarts sharing the same threads
     * (tirenv/parallel.h: nested calls share the budget). */
    seeds_pass sp_ = {type, settings, set, fit, val, R0, n_max, out, nets, reps, *settings};
    const size_t jobs = settings->jobs < 1 ? 1 : settings->jobs;
    tirenv_train_progress_gate *gate = NULL;
    if (!status && jobs > 1 && n_seeds > 1 && settings->progress &&
        !(gate = tirenv_train_progress_gate_alloc(&sp_.inner)))
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    if (!status)
        status = tirenv_parallel_for(n_seeds, jobs, seed_item, NULL, &sp_, diag);
    tirenv_train_progress_gate_free(gate);
    for (size_t k = 0; k < n_seeds && !status; ++k)
        out->seconds += reps[k].wall_time;
    if (!status) {
        memcpy(sorted, out->mean_rms, n_seeds * sizeof *sorted);
        qsort(sorted, n_seeds, sizeof *sorted, cmp_double);
        out->min = sorted[0];
        out->max = sorted[n_seeds - 1];
        out->q1 = quantile(sorted, n_seeds, 0.25);
        out->median = quantile(sorted, n_seeds, 0.5);
        out->q3 = quantile(sorted, n_seeds, 0.75);
        memcpy(sorted, out->control_rms, n_seeds * sizeof *sorted);
        qsort(sorted, n_seeds, sizeof *sorted, cmp_double);
        out->control_q1 = quantile(sorted, n_seeds, 0.25);
        out->control_median = quantile(sorted, n_seeds, 0.5);
        out->control_q3 = quantile(sorted, n_seeds, 0.75);
        for (size_t k = 1; k < n_seeds; ++k) {
            const double d = fabs(out->mean_rms[k] - out->median),
                         best = fabs(out->mean_rms[out->median_seed] - out->median);
            if (d < best || (d == best && out->mean_rms[k] < out->mean_rms[out->median_seed]))
                out->median_seed = k;
        }
        if (median_net) {
            *median_net = nets[out->median_seed];
            nets[out->median_seed] = NULL;
        }
        if (median_report)
            *median_report = reps[out->median_seed];
    }
    for (size_t k = 0; nets && k < n_seeds; ++k)
        tirenv_nn_free(nets[k]);
    for (int sp = 0; sp < 3; ++sp) {
        free(x[sp]);
        free(y[sp]);
    }
    free(nets);
    free(reps);
    free(sorted);
    return status;
}
