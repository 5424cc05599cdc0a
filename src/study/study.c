/* SPDX-License-Identifier: Apache-2.0 */
/* The paper's study in one call (docs/models.md section 8): identify, train, compare; then the
 * paper's proposed workflow and the obstacles outside the training grid. */
#include "tirenv/study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "study/compare_impl.h"
#include "study/study_impl.h"
#include "tirenv/outfile.h"
#include "tirenv/tir.h"
#include "tirenv/parallel.h"
#include "tirenv/rig.h"
#include "tirenv/nn_file.h"
#include "io/io.h"

tirenv_study_settings tirenv_study_default(void)
{
    return (tirenv_study_settings){.data_dir = NULL, .data_label = NULL, .out_dir = "out/study",
                                   .tire = tirenv_tire_default(), .tire_label = NULL,
                                   .trainer = "lm", .seed = 1, .seeds = 20,
                                   .input = TIRENV_NN_INPUT_EVEN,
                                   .simulated_by = tirenv_model_ring, .simulated_raw = 0,
                                   .images = 1, .jobs = 1, .progress = NULL,
                                   .progress_ctx = NULL};
}

enum { STEPS = 7 };

static void progress(const tirenv_study_settings *s, const char *stage, size_t step)
{
    if (s->progress)
        s->progress(s->progress_ctx, stage, step, STEPS);
}

/* ---- the network ------------------------------------------------------------------------ */

typedef struct {
    tirenv_samples set[3];         /* by tirenv_split */
    double *x[3], *y[3];
} sample_sets;

static void sample_sets_free(sample_sets *ss)
{
    for (int k = 0; k < 3; ++k) {
        free(ss->x[k]);
        free(ss->y[k]);
    }
}

static const char *data_label(const tirenv_study_settings *s)
{
    return s->data_label ? s->data_label : s->data_dir;
}

static int trainer_of(const tirenv_study_settings *s, const tirenv_trainer_type **type,
                      tirenv_train_settings *ts, tirenv_diag *diag)
{
    if (!(*type = tirenv_trainer_type_find(s->trainer)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "trainer",
                            "unknown trainer '%s'; expected lm, rprop or backprop", s->trainer);
    *ts = tirenv_train_default(*type);
    ts->seed = s->seed;
    ts->input = s->input;
    ts->jobs = s->jobs;
    return TIRENV_OK;
}

/* The model file: the network and how it was trained on fit's train and control cases (val's
 * validation cases reported). */
static int write_model(const tirenv_study_settings *s, const tirenv_train_settings *ts,
                       const tirenv_train_report *rep, const tirenv_dataset *fit,
                       const tirenv_dataset *val, const char *path, const tirenv_nn *nn,
                       tirenv_diag *diag)
{
    sample_sets ss = {0};
    const tirenv_dataset *from[3] = {fit, fit, val};
    int status = TIRENV_OK;
    for (int k = 0; k < 3 && !status; ++k)
        status = tirenv_samples_from_dataset(from[k], (tirenv_split)k, &ss.set[k], &ss.x[k],
                                             &ss.y[k], diag);
    if (!status) {
        tirenv_train_record rec;
        memset(&rec, 0, sizeof rec);
        snprintf(rec.trainer, sizeof rec.trainer, "%s", s->trainer);
        rec.settings = *ts;
        rec.report = *rep;
        rec.fingerprint = TIRENV_FNV1A64_OFFSET;
        for (int k = 0; k < 3; ++k)
            rec.fingerprint = tirenv_samples_fingerprint(&ss.set[k], rec.fingerprint);
        rec.R0 = s->tire.springs.R0;
        snprintf(rec.data, sizeof rec.data, "%s", data_label(s));
        /* The load-contact-length relation of the tire the data came from, as tirenv train
         * records it, so that the network takes a load (the ride, envelope --load) as that
         * tire would. */
        char law_what[80] = "";
        status = tirenv_contact_law_of_data(fit, s->simulated_by, &s->tire, &rec.law, law_what,
                                            sizeof law_what, diag);
        if (!status) {
            snprintf(rec.law_source, sizeof rec.law_source, "%s", law_what);
            status = tirenv_nn_write_json(path, nn, &rec, diag);
        }
    }
    sample_sets_free(&ss);
    return status;
}

/* Trains the network on `fit` (train and control splits) with one seed and reports
 * validation on `val`, then writes it with its record to path. */
static int train_network(const tirenv_study_settings *s, const tirenv_dataset *fit,
                         const tirenv_dataset *val, const char *path, tirenv_nn **nn,
                         tirenv_train_report *rep, tirenv_diag *diag)
{
    const tirenv_trainer_type *type;
    tirenv_train_settings ts;
    int status = trainer_of(s, &type, &ts, diag);
    sample_sets ss = {0};
    const tirenv_dataset *from[3] = {fit, fit, val};
    for (int k = 0; k < 3 && !status; ++k)
        status = tirenv_samples_from_dataset(from[k], (tirenv_split)k, &ss.set[k], &ss.x[k],
                                             &ss.y[k], diag);
    if (!status)
        status = tirenv_train(type, &ts, &ss.set[0], &ss.set[1], &ss.set[2], nn, rep, diag);
    sample_sets_free(&ss);
    if (!status)
        status = write_model(s, &ts, rep, fit, val, path, *nn, diag);
    return status;
}

/* nn-seeds.csv: per seed its validation error (the mean over the cases) and each case's. */
static int write_seeds_csv(const char *dir, const tirenv_dataset *ds, const tirenv_nn_seeds *r,
                           tirenv_diag *diag)
{
    tirenv_outfile *f;
    int status = tirenv_compare__open(&f, dir, "nn-seeds.csv", diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    fputs("seed,validation_rms_mm", fp);
    for (size_t c = 0; c < r->n_cases; ++c)
        fprintf(fp, ",%s_rms_mm", ds->cases[r->case_index[c]].name);
    fputc('\n', fp);
    for (size_t k = 0; k < r->n_seeds; ++k) {
        fprintf(fp, "%lu,%.4f", r->seed[k], 1e3 * r->mean_rms[k]);
        for (size_t c = 0; c < r->n_cases; ++c)
            fprintf(fp, ",%.4f", 1e3 * r->rms[k * r->n_cases + c]);
        fputc('\n', fp);
    }
    return tirenv_compare__close(f, diag);
}

/* The network on the measured data over s->seeds seeds: nn-seeds.csv, and nn.json the
 * model of the seed nearest the median, so the tables and plots show a typical network
 * rather than a lucky or an unlucky one. */
static int train_seeds(const tirenv_study_settings *s, const tirenv_dataset *ds, tirenv_nn **nn,
                       tirenv_train_report *rep, tirenv_nn_seeds *seeds, tirenv_diag *diag)
{
    const tirenv_trainer_type *type;
    tirenv_train_settings ts;
    char path[1024];
    int status = trainer_of(s, &type, &ts, diag);
    if (!status)
        status = tirenv_nn_train_seeds(type, &ts, ds, ds, s->tire.springs.R0,
                                       s->seeds ? s->seeds : 1, seeds, nn, rep, diag);
    if (!status)
        status = write_seeds_csv(s->out_dir, ds, seeds, diag);
    if (!status) {
        ts.seed = seeds->seed[seeds->median_seed];
        snprintf(path, sizeof path, "%s/nn.json", s->out_dir);
        status = write_model(s, &ts, rep, ds, ds, path, *nn, diag);
    }
    return status;
}

/* ---- the paper's workflow: a network trained on the physical model's curves -------------- */

/* The rig measured load and contact length together; a physical model is driven by load, so
 * the load at a contact length is read off the data set's own cases (linear between them). */
static double load_at(const tirenv_dataset *ds, double l_c)
{
    double lo_l = -INFINITY, lo_G = NAN, hi_l = INFINITY, hi_G = NAN;
    for (size_t i = 0; i < ds->n; ++i) {
        const double l = ds->cases[i].contact_length, G = ds->cases[i].load;
        if (l <= l_c && l > lo_l) {
            lo_l = l;
            lo_G = G;
        }
        if (l >= l_c && l < hi_l) {
            hi_l = l;
            hi_G = G;
        }
    }
    if (isnan(lo_G))
        return hi_G;
    if (isnan(hi_G) || hi_l == lo_l)
        return lo_G;
    return lo_G + (hi_G - lo_G) * (l_c - lo_l) / (hi_l - lo_l);
}

/* A grid of cleats over the data set's ranges, every fifth one for early stopping: the data
 * set's contact lengths (GRID_LC evenly from the shortest to the longest if it has more), and
 * GRID_L lengths and GRID_H heights evenly over its ranges; for the tractor set 4 x 6 x 4 =
 * 96 cleats, 0.28-0.43 m, 0.05-0.30 m, 0.025-0.10 m. Values are rounded to the micrometre, so
 * that 0.15 m is the double that reads as 0.15. */
enum { GRID_LC = 6, GRID_L = 6, GRID_H = 4, GRID_MAX = GRID_LC * GRID_L * GRID_H };

typedef struct {
    double l_c[GRID_LC], L[GRID_L], H[GRID_H];
    size_t n_l_c;
    double L_min, L_max, H_min, H_max;  /* the data set's ranges, m */
} grid_design;

static double micrometres(double v) { return round(v * 1e6) / 1e6; }

static void even(double lo, double hi, size_t n, double out[])
{
    for (size_t k = 0; k < n; ++k)
        out[k] = micrometres(n > 1 ? lo + (hi - lo) * (double)k / (double)(n - 1) : lo);
}

static int by_value(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void grid_of(const tirenv_dataset *ds, grid_design *g)
{
    double l_c[GRID_LC + 1];
    size_t n = 0;
    double lc_min = INFINITY, lc_max = -INFINITY;
    g->L_min = g->H_min = INFINITY;
    g->L_max = g->H_max = -INFINITY;
    for (size_t i = 0; i < ds->n; ++i) {
        const tirenv_case *c = &ds->cases[i];
        lc_min = fmin(lc_min, c->contact_length);
        lc_max = fmax(lc_max, c->contact_length);
        g->L_min = fmin(g->L_min, c->L);
        g->L_max = fmax(g->L_max, c->L);
        g->H_min = fmin(g->H_min, c->H);
        g->H_max = fmax(g->H_max, c->H);
        size_t k = 0;
        while (k < n && l_c[k] != c->contact_length)
            ++k;
        if (k == n && n <= GRID_LC)
            l_c[n++] = c->contact_length;
    }
    if (n > GRID_LC) {
        even(lc_min, lc_max, GRID_LC, g->l_c);
        g->n_l_c = GRID_LC;
    } else {
        qsort(l_c, n, sizeof l_c[0], by_value);
        memcpy(g->l_c, l_c, n * sizeof l_c[0]);
        g->n_l_c = n;
    }
    even(g->L_min, g->L_max, GRID_L, g->L);
    even(g->H_min, g->H_max, GRID_H, g->H);
}

/* Grid case k, with the springs model of the worker running it; k runs over the grid's
 * contact lengths, then lengths, then heights (heights fastest). */
typedef struct {
    const tirenv_dataset *real;
    const tirenv_tire *fitted;
    const grid_design *g;
    tirenv_dataset *out;
    tirenv_model **models;         /* one per worker, built on first use */
} physical_pass;

static int physical_case(void *ctx, size_t k, size_t worker, tirenv_diag *diag)
{
    physical_pass *p = ctx;
    if (!p->models[worker] &&
        !(p->models[worker] = tirenv_model_alloc(tirenv_model_springs, p->fitted)))
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "study", "out of memory");
    tirenv_case *cs = &p->out->cases[k];
    const tirenv_curve *grid = &p->real->cases[0].curve; /* the data set's x_N grid */
    const size_t a = k / (GRID_L * GRID_H), b = k / GRID_H % GRID_L, c = k % GRID_H;
    snprintf(cs->name, sizeof cs->name, "g%zu", k);
    cs->split = k % 5 == 4 ? TIRENV_SPLIT_CONTROL : TIRENV_SPLIT_TRAIN;
    cs->contact_length = p->g->l_c[a];
    cs->L = p->g->L[b];
    cs->H = p->g->H[c];
    cs->load = load_at(p->real, cs->contact_length);
    int status = tirenv_curve_alloc(&cs->curve, grid->n);
    if (status)
        return tirenv_error(diag, status, "", 0, "study", "out of memory");
    const double x_0 = tirenv_xN_origin(p->fitted->springs.R0, cs->contact_length, cs->L,
                                        cs->H);
    for (size_t j = 0; j < grid->n; ++j) {
        cs->curve.x_N[j] = grid->x_N[j];
        cs->curve.x[j] = x_0 * (1 - grid->x_N[j]);
    }
    return tirenv_case_predict_model(p->models[worker], cs, cs->curve.h, diag);
}

/* The grid's curves on `jobs` threads (a model is set afresh on every case, so a curve does
 * not depend on the worker that made it). */
static int physical_dataset(const tirenv_dataset *real, const tirenv_tire *fitted,
                            const grid_design *g, size_t jobs, tirenv_dataset *out,
                            tirenv_diag *diag)
{
    memset(out, 0, sizeof *out);
    const size_t n = g->n_l_c * GRID_L * GRID_H;
    out->cases = calloc(GRID_MAX, sizeof *out->cases);
    physical_pass p = {real, fitted, g, out, calloc(jobs, sizeof *p.models)};
    if (!out->cases || !p.models) {
        free(p.models);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "study", "out of memory");
    }
    snprintf(out->dir, sizeof out->dir, "(springs model curves)");
    out->n = n;  /* every case's curve is freed with the data set, allocated or not */
    const int status = tirenv_parallel_for(n, jobs, physical_case, NULL, &p, diag);
    for (size_t w = 0; w < jobs; ++w)
        tirenv_model_free(p.models[w]);
    free(p.models);
    return status;
}

/* ---- obstacles outside the training grid -------------------------------------------------- */

/* A size from the data set's ranges: f_max times its largest plus f_min times its smallest
 * obstacle length (of 'L') or height (of 'H'). */
typedef struct {
    char of;
    double f_max, f_min;
} size_rule;

typedef struct {
    const char *name;
    size_t l_c;                    /* which of the data set's contact lengths (0-based) */
    size_rule L, H;                /* extent: for x_N and the network */
    tirenv_profile *(*make)(const double arg[3]);
    size_rule arg[3];              /* the generator's arguments */
} outside_design;

static double size_of(const size_rule *r, const grid_design *g)
{
    if (r->of == 'H')
        return micrometres(r->f_max * g->H_max + r->f_min * g->H_min);
    if (r->of == 'L')
        return micrometres(r->f_max * g->L_max + r->f_min * g->L_min);
    return 0;
}

static tirenv_profile *make_cleat(const double a[3]) { return tirenv_profile_cleat(a[0], a[1]); }
static tirenv_profile *make_cylinder(const double a[3])
{
    return tirenv_profile_half_cylinder(a[0], 64);
}
static tirenv_profile *make_trapezoid(const double a[3])
{
    return tirenv_profile_trapezoid(a[0], a[1], a[2]);
}

/* Taller and shorter than any training cleat, and two shapes the network never saw (given to
 * it as their bounding rectangle, as a user would), sized by the data set's ranges: factors of
 * its tallest cleat and of its longest and shortest lengths. For the tractor set (heights up to
 * 0.10 m, lengths 0.05-0.30 m): a 0.15 x 0.15 m cleat, a 0.03 x 0.05 m one, a half-cylinder
 * of radius 0.08 m and a trapezoid 0.10 / 0.25 m by 0.08 m. The contact lengths are the data
 * set's second and third shortest (the longest if it has fewer). */
static const outside_design outside[] = {
    {"tall", 1, {'L', 0.5, 0}, {'H', 1.5, 0}, make_cleat, {{'L', 0.5, 0}, {'H', 1.5, 0}}},
    {"short", 2, {'L', 0, 0.6}, {'H', 0.5, 0}, make_cleat, {{'L', 0, 0.6}, {'H', 0.5, 0}}},
    {"cylinder", 1, {'H', 1.6, 0}, {'H', 0.8, 0}, make_cylinder, {{'H', 0.8, 0}}},
    {"trapezoid", 2, {'L', 5.0 / 6.0, 0}, {'H', 0.8, 0}, make_trapezoid,
     {{'L', 1.0 / 3.0, 0}, {'L', 5.0 / 6.0, 0}, {'H', 0.8, 0}}},
};
enum { N_OUTSIDE = sizeof outside / sizeof outside[0] };

/* The reference curves: the model that simulated the data set (the ring for measured data)
 * on the virtual rig, imported like the data set's; where the data set is that model's own
 * curves (raw: a sweep without --rig), its own curves too; each obstacle with its own
 * instance of it, so that its curve depends on it alone. */
typedef struct {
    const tirenv_tire *tire;
    const tirenv_model_type *reference;
    int raw;               /* the reference's own curves, no rig (a sweep without --rig) */
    const grid_design *g;
    tirenv_dataset *out;
    tirenv_profile **profiles;
} outside_pass;

static int outside_case(void *ctx, size_t i, size_t worker, tirenv_diag *diag)
{
    outside_pass *p = ctx;
    const outside_design *d = &outside[i];
    const grid_design *g = p->g;
    tirenv_case *cs = &p->out->cases[i];
    (void)worker;
    snprintf(cs->name, sizeof cs->name, "%s", d->name);
    cs->split = TIRENV_SPLIT_VALIDATION;
    cs->contact_length = g->l_c[d->l_c < g->n_l_c ? d->l_c : g->n_l_c - 1];
    const double arg[3] = {size_of(&d->arg[0], g), size_of(&d->arg[1], g),
                           size_of(&d->arg[2], g)};
    cs->L = size_of(&d->L, g);
    cs->H = size_of(&d->H, g);
    cs->profile = p->profiles[i] = d->make(arg);
    tirenv_model *ref = tirenv_model_alloc(p->reference, p->tire);
    if (!p->profiles[i] || !ref) {
        tirenv_model_free(ref);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "study", "out of memory");
    }
    int status = tirenv_model_load_for_contact_length(ref, cs->contact_length, &cs->load, diag);
    if (!status)
        status = tirenv_model_set(ref, p->profiles[i], cs->load, diag);
    tirenv_import_settings imp = tirenv_import_default();
    imp.L = cs->L;
    imp.H = cs->H;
    imp.R0 = p->tire->springs.R0;
    imp.contact_length = cs->contact_length;
    if (!status && p->raw) {
        status = tirenv_rig_model_curve(ref, &imp, &cs->curve, diag);
    } else if (!status) {
        tirenv_rig_settings rig = tirenv_rig_default();
        rig.seed = 777 + i;
        tirenv_rig_log log = {0};
        status = tirenv_rig_simulate(ref, p->profiles[i], &rig, &log, diag);
        if (!status)
            status = tirenv_rig_import_samples(log.n, log.t, log.x, log.z, &imp, &cs->curve,
                                               diag);
        tirenv_rig_log_free(&log);
    }
    tirenv_model_free(ref);
    return status;
}

/* Whether the outside cases' reference curves are the model's own (outside_pass's raw): a
 * data set of a model's own curves says so by simulated_raw. */
static int outside_raw(const tirenv_study_settings *s)
{
    return s->simulated_by && s->simulated_raw;
}

static int outside_dataset(const tirenv_tire *tire, const tirenv_model_type *reference, int raw,
                           const grid_design *g, size_t jobs, tirenv_dataset *out,
                           tirenv_profile *profiles[N_OUTSIDE], tirenv_diag *diag)
{
    memset(out, 0, sizeof *out);
    snprintf(out->dir, sizeof out->dir, raw ? "(the %s model's own curves)"
                                            : "(virtual rig, %s model)",
             tirenv_model_type_name(reference));
    out->cases = calloc(N_OUTSIDE, sizeof *out->cases);
    if (!out->cases)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "study", "out of memory");
    out->n = N_OUTSIDE;
    outside_pass p = {tire, reference, raw, g, out, profiles};
    return tirenv_parallel_for(N_OUTSIDE, jobs, outside_case, NULL, &p, diag);
}

/* ---- the report's own account ------------------------------------------------------------- */

static void append_model_means(FILE *fp, const tirenv_compare_result *r)
{
    for (size_t m = 0; m < r->n_models; ++m)
        fprintf(fp, "%s%s %.2f mm", m ? ", " : "", r->model[m],
                1e3 * tirenv_compare__mean_rms(r, m, NULL));
}

/* How the physical models were identified: the springs model, and the cam where it did not
 * simulate the data (facts->cam_fit NULL: it is then the reference, not fitted). */
static void notes_fits(FILE *fp, const tirenv_study__facts *facts)
{
    const tirenv_fit_report *fit = facts->springs_fit, *cam_fit = facts->cam_fit;
    fprintf(fp, "## How the models were obtained\n\n"
                "**Physical model (springs)**, identified on the training cases by nonlinear "
                "least squares on h (%zu points, %zu iterations, stopped by %s, %.1f s, RMS "
                "%.2f mm); standard errors from the covariance, scaled by the residual "
                "variance:\n\n",
            fit->n_points, fit->iterations, fit->stop, fit->seconds, 1e3 * fit->rms);
    tirenv_study__fit_table(fp, fit);
    if (!cam_fit) {
        fprintf(fp, "\n**Tandem elliptical cam (cam)**: it simulated the data, so it is the "
                    "reference, run with the data set's tire as it is, not fitted. The fitted "
                    "tire is in `fitted.tir`.\n\n");
        return;
    }
    fprintf(fp, "\n**Tandem elliptical cam (cam)**, MF-Swift's effective road model "
                "(docs/models.md section 7), identified the same way (%zu iterations, "
                "stopped by %s, %.2f s, RMS %.2f mm); its contact-length keys (Q_RA1, "
                "Q_RA2, VERTICAL_STIFFNESS) stay as in the tire file:\n\n",
            cam_fit->iterations, cam_fit->stop, cam_fit->seconds, 1e3 * cam_fit->rms);
    tirenv_study__fit_table(fp, cam_fit);
    tirenv_study__cam_limits(fp, facts);
    fprintf(fp, "\nThe fitted tire (both models) is in `fitted.tir`.\n\n");
}

/* How the network was trained (nn: the one kept, nearest the median seed). */
static void notes_network(FILE *fp, const tirenv_study_settings *s,
                          const tirenv_study__facts *facts, const tirenv_train_report *nn)
{
    const tirenv_nn_seeds *seeds = facts->seeds;
    tirenv_train_settings ts = tirenv_train_default(tirenv_trainer_type_find(s->trainer));
    ts.input = s->input;
    size_t n_train = 0;
    for (size_t i = 0; i < facts->ds->n; ++i)
        n_train += facts->ds->cases[i].split == TIRENV_SPLIT_TRAIN;
    /* Without control cases tirenv_train selects and stops on the training error, and an
     * error over the control split's no points is no number: the text says so. */
    const int held = nn->error[TIRENV_SPLIT_CONTROL].n > 0;
    char errors[160];
    if (held)
        snprintf(errors, sizeof errors, "train, control and validation cases %.2f, %.2f and "
                 "%.2f mm", 1e3 * nn->error[0].rms, 1e3 * nn->error[1].rms,
                 1e3 * nn->error[2].rms);
    else
        snprintf(errors, sizeof errors, "train and validation cases %.2f and %.2f mm",
                 1e3 * nn->error[0].rms, 1e3 * nn->error[2].rms);
    fprintf(fp, "**Empirical model (nn)**, 4-8-1 (input %s, target %s, loss over %s), trained "
                "on the training cases with %s; each model is "
                "the mean of the %zu of %zu restarts best on %s. With %zu training curves "
                "the result depends on the seed, so it was trained with %zu seeds (%lu to "
                "%lu, %.1f s in all; each seed's errors in `nn-seeds.csv`): validation error "
                "(the mean over the validation cases of each case's RMS) median %.2f mm, "
                "quartiles %.2f to %.2f mm, range %.2f to %.2f mm. The network in the tables "
                "and plots, `nn.json`, is seed %lu, the one nearest the median: %zu epochs "
                "in %.2f s; RMS error over the points of the %s.\n\n",
            tirenv_nn_input_form_name(ts.input), tirenv_nn_target_form_name(ts.target),
            tirenv_train_loss_name(ts.loss),
            held ? "early stopping on the control cases"
                 : "the training error choosing the weights and stopping the training (the "
                   "data set has no control cases)",
            nn->members, ts.restarts, held ? "control" : "the training error",
            n_train, seeds->n_seeds, seeds->seed[0],
            seeds->seed[seeds->n_seeds - 1], seeds->seconds, 1e3 * seeds->median,
            1e3 * seeds->q1, 1e3 * seeds->q3, 1e3 * seeds->min, 1e3 * seeds->max,
            seeds->seed[seeds->median_seed], nn->total_epochs, nn->wall_time, errors);
}

/* The paper's proposed workflow: the network trained on the physical model's curves over the
 * grid g (nn_phys), against the one trained on the measurements. */
static void notes_physical_network(FILE *fp, const tirenv_study_settings *s,
                                   const grid_design *g, const tirenv_nn_seeds *seeds,
                                   const tirenv_train_report *nn_phys,
                                   const tirenv_compare_result *phys)
{
    fprintf(fp, "## The paper's proposed workflow: a network trained on the physical model\n\n"
                "The paper proposes to train the network on curves of the physical model "
                "instead of rig runs. Here: %zu curves of the identified springs model over a "
                "grid of cleats (lengths %.3g to %.3g m, heights %.3g to %.3g m, contact "
                "lengths %.3g to %.3g m, loads read off the data set), no rig time, one seed "
                "(%lu). Trained in %.2f s; its validation error (the mean over the measured "
                "validation cases of each case's RMS) is %.2f mm, against a median of %.2f mm "
                "over the seeds of the network trained on the measurements. Mean RMS over the "
                "validation cases: ",
            g->n_l_c * GRID_L * GRID_H, g->L_min, g->L_max, g->H_min, g->H_max, g->l_c[0],
            g->l_c[g->n_l_c - 1], s->seed, nn_phys->wall_time,
            phys->nn_model >= 0 ? 1e3 * tirenv_compare__mean_rms(phys, (size_t)phys->nn_model,
                                                                 NULL)
                                : NAN,
            1e3 * seeds->median);
    append_model_means(fp, phys);
    fprintf(fp, ". Plots: [physical-network/](physical-network/report.md).\n\n");
}

/* The outside cases' RMS errors, a row per case and a column per model (mm). */
static void outside_table(FILE *fp, const tirenv_compare_result *out_r,
                          const tirenv_dataset *outside_ds)
{
    fprintf(fp, ". The network sees the half-cylinder and the trapezoid as their bounding "
                "rectangles. RMS error per case (mm):\n\n| case |");
    for (size_t m = 0; m < out_r->n_models; ++m)
        fprintf(fp, " %s |", out_r->model[m]);
    fprintf(fp, "\n|---|");
    for (size_t m = 0; m < out_r->n_models; ++m)
        fprintf(fp, "---|");
    fprintf(fp, "\n");
    for (size_t c = 0; c < out_r->n_cases; ++c) {
        fprintf(fp, "| %s |", outside_ds->cases[out_r->case_index[c]].name);
        for (size_t m = 0; m < out_r->n_models; ++m)
            fprintf(fp, " %.2f |", 1e3 * out_r->entry[c * out_r->n_models + m].errors.rms);
        fprintf(fp, "\n");
    }
}

/* What the outside cases say of generalising: the network's mean error against the physical
 * model's, unless the physical model simulated them. */
static void outside_verdict(FILE *fp, const tirenv_study_settings *s,
                            const tirenv_compare_result *out_r)
{
    const int nn_m = out_r->nn_model;
    size_t springs_m = 0;
    for (size_t m = 0; m < out_r->n_models; ++m)
        if (strcmp(out_r->model[m], "springs") == 0)
            springs_m = m;
    if (s->simulated_by == tirenv_model_springs) {
        /* The physical model is the reference here: a ratio to its error says nothing. */
        fprintf(fp, ". The springs model simulated these curves%s, so its error is %s, not how "
                    "it generalises. Plots: [outside/](outside/report.md).\n\n",
                s->simulated_raw ? "" : " on the virtual rig",
                s->simulated_raw ? "zero by construction" : "the rig's noise and the import");
    } else if (nn_m >= 0) {
        const double ratio = tirenv_compare__mean_rms(out_r, (size_t)nn_m, NULL) /
                             tirenv_compare__mean_rms(out_r, springs_m, NULL);
        fprintf(fp, ". Outside its training range the network's mean error is %.1f times the "
                    "physical model's%s. Plots: [outside/](outside/report.md).\n\n",
                ratio, ratio >= 2   ? ": the physical model generalises, the network does not"
                       : ratio > 1 ? ": both degrade, the network more"
                                   : ": here the network held up as well as the physical "
                                     "model");
    } else {
        fprintf(fp, ". Plots: [outside/](outside/report.md).\n\n");
    }
}

/* Obstacles no training case resembles (outside_ds, compared in out_r). */
static void notes_outside(FILE *fp, const tirenv_study_settings *s,
                          const tirenv_compare_result *out_r, const tirenv_dataset *outside_ds)
{
    const char *ref_name =
        tirenv_model_type_name(s->simulated_by ? s->simulated_by : tirenv_model_ring);
    fprintf(fp, "## Outside the training range\n\n"
                "Obstacles no training case resembles, with reference curves ");
    fprintf(fp, outside_raw(s) ? "that are the %s model's own, as the data set's (no rig, "
                                 "SIMULATED): "
                               : "from the same virtual rig (%s model, SIMULATED): ",
            ref_name);
    for (size_t i = 0; i < outside_ds->n; ++i) {
        const tirenv_case *c = &outside_ds->cases[i];
        fprintf(fp, "%s%s (%.0f x %.0f mm, contact length %.0f mm)", i ? ", " : "", c->name,
                1e3 * c->L, 1e3 * c->H, 1e3 * c->contact_length);
    }
    outside_table(fp, out_r, outside_ds);
    fprintf(fp, "\nMean: ");
    append_model_means(fp, out_r);
    outside_verdict(fp, s, out_r);
}

/* The report's own account, section by section; NULL without memory. */
static char *study_notes(const tirenv_study_settings *s, const grid_design *g,
                         const tirenv_study__facts *facts,
                         const tirenv_train_report *nn, const tirenv_train_report *nn_phys,
                         const tirenv_compare_result *phys, const tirenv_compare_result *out_r,
                         const tirenv_dataset *outside_ds)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *fp = open_memstream(&buf, &len);
    if (!fp)
        return NULL;
    tirenv_study__findings(fp, facts);
    notes_fits(fp, facts);
    notes_network(fp, s, facts, nn);
    notes_physical_network(fp, s, g, facts->seeds, nn_phys, phys);
    notes_outside(fp, s, out_r, outside_ds);
    fclose(fp);
    return buf;
}

/* ---- the pipeline -------------------------------------------------------------------------- */


static tirenv_compare_settings compare_settings(const tirenv_study_settings *s, const char *dir,
                                                const char *title)
{
    tirenv_compare_settings cs = tirenv_compare_default();
    cs.split = TIRENV_SPLIT_VALIDATION;
    cs.models[cs.n_models++] = tirenv_model_cam;
    cs.out_dir = dir;
    cs.title = title;
    cs.images = s->images;
    cs.jobs = s->jobs;
    cs.tire_label = "fitted.tir (identified on the training cases)";
    cs.data_label = data_label(s);
    if (s->simulated_by) {
        cs.simulated = 1;
        cs.simulated_by = s->simulated_by;
        cs.simulated_raw = s->simulated_raw;
    }
    return cs;
}

/* ---- the three comparisons ----------------------------------------------------------------- */

typedef struct {
    const tirenv_study_settings *s;
    const tirenv_dataset *ds;
    const tirenv_tire *tire;
    const grid_design *grid;
    const tirenv_model_type *reference;  /* what simulates the obstacles outside */
    tirenv_nn *nn;
    tirenv_compare_settings cs;
    tirenv_compare_result *main_r;
    tirenv_dataset *phys_ds;
    tirenv_nn **nn_phys;
    tirenv_train_report *phys_rep;
    tirenv_compare_result *phys_r;
    tirenv_dataset *out_ds;
    tirenv_profile **profiles;
    tirenv_compare_result *out_r;
} study_parts;

/* The paper's comparison on the validation cases. */
static int part_main(study_parts *p, tirenv_diag *diag)
{
    return tirenv_compare(p->ds, p->tire, p->nn, &p->cs, p->main_r, diag);
}

/* The paper's workflow: a network trained on the identified physical model's curves. */
static int part_physical(study_parts *p, tirenv_diag *diag)
{
    const tirenv_study_settings *s = p->s;
    char path[1024], sub[1024];
    int status = physical_dataset(p->ds, p->tire, p->grid, s->jobs ? s->jobs : 1, p->phys_ds,
                                  diag);
    snprintf(path, sizeof path, "%s/nn-physical.json", s->out_dir);
    if (!status)
        status = train_network(s, p->phys_ds, p->ds, path, p->nn_phys, p->phys_rep, diag);
    snprintf(sub, sizeof sub, "%s/physical-network", s->out_dir);
    tirenv_compare_settings ps = compare_settings(s, sub, "A network trained on the identified "
                                                  "physical model's curves (no rig time)");
    ps.nn_label = "nn-physical.json (trained on springs-model curves)";
    if (!status)
        status = tirenv_compare(p->ds, p->tire, *p->nn_phys, &ps, p->phys_r, diag);
    if (!status)
        status = tirenv_compare_report(p->ds, &ps, p->phys_r, NULL, diag);
    return status;
}

/* The obstacles outside the training grid. */
static int part_outside(study_parts *p, tirenv_diag *diag)
{
    const tirenv_study_settings *s = p->s;
    char sub[1024];
    const int raw = outside_raw(s);
    int status = outside_dataset(&s->tire, p->reference, raw, p->grid, s->jobs ? s->jobs : 1,
                                 p->out_ds, p->profiles, diag);
    snprintf(sub, sizeof sub, "%s/outside", s->out_dir);
    tirenv_compare_settings os = compare_settings(s, sub, "Obstacles outside the training "
                                                  "range");
    os.simulated = 1;
    os.simulated_by = p->reference;
    os.simulated_raw = raw;
    os.data_label = raw ? "taller, shorter and other shapes, the reference model's own curves"
                        : "taller, shorter and other shapes on the virtual rig";
    if (!status)
        status = tirenv_compare(p->out_ds, p->tire, p->nn, &os, p->out_r, diag);
    if (!status)
        status = tirenv_compare_report(p->out_ds, &os, p->out_r, NULL, diag);
    return status;
}

static int study_part(void *ctx, size_t k, size_t worker, tirenv_diag *diag)
{
    study_parts *p = ctx;
    (void)worker;
    return k == 0 ? part_main(p, diag) : k == 1 ? part_physical(p, diag)
                                                : part_outside(p, diag);
}

static int study_into(const tirenv_study_settings *s, tirenv_diag *diag)
{
    char path[1024];
    tirenv_dataset ds = {0}, phys_ds = {0}, out_ds = {0};
    tirenv_profile *profiles[N_OUTSIDE] = {0};
    tirenv_nn *nn = NULL, *nn_phys = NULL;
    tirenv_compare_result main_r = {0}, phys_r = {0}, out_r = {0};
    tirenv_fit_report fit;
    tirenv_train_report nn_rep, phys_rep;
    tirenv_nn_seeds seeds = {0};
    tirenv_tire tire = s->tire;
    char *notes = NULL;

    int status = TIRENV_OK;
    progress(s, "reading the data set", 0);
    if (!status)
        status = tirenv_dataset_read(s->data_dir, tire.springs.R0, &ds, diag);
    progress(s, "identifying the springs model", 1);
    tirenv_fit_settings fs = tirenv_fit_default();
    fs.type = tirenv_model_springs;
    fs.jobs = s->jobs;
    if (!status)
        status = tirenv_fit(&ds, TIRENV_SPLIT_TRAIN, &fs, &tire, &fit, diag);
    /* The cam's keys live in their own part of the tire, so both fits share one file. A cam
     * that simulated the data is the reference: it keeps the data set's values. */
    tirenv_fit_report cam_fit;
    const int fit_cam = s->simulated_by != tirenv_model_cam;
    fs.type = tirenv_model_cam;
    if (!status && fit_cam)
        status = tirenv_fit(&ds, TIRENV_SPLIT_TRAIN, &fs, &tire, &cam_fit, diag);
    snprintf(path, sizeof path, "%s/fitted.tir", s->out_dir);
    if (!status)
        status = tirenv_tir_write(path, &tire, diag);
    progress(s, "training the network over seeds", 2);
    if (!status)
        status = train_seeds(s, &ds, &nn, &nn_rep, &seeds, diag);
    /* Three independent parts, side by side on the jobs (each with its own work items, all
     * drawing on the same threads: tirenv/parallel.h), in the order a failure is reported:
     * the comparison on the validation cases, the paper's workflow, the obstacles outside. */
    progress(s, "comparing the models: validation cases, a network on physical-model curves, "
                "obstacles outside the training range", 3);
    grid_design grid = {0};
    if (!status)
        grid_of(&ds, &grid);
    study_parts parts = {.s = s, .ds = &ds, .tire = &tire, .grid = &grid,
                         .reference = s->simulated_by ? s->simulated_by : tirenv_model_ring,
                         .nn = nn, .main_r = &main_r,
                         .phys_ds = &phys_ds, .nn_phys = &nn_phys, .phys_rep = &phys_rep,
                         .phys_r = &phys_r, .out_ds = &out_ds, .profiles = profiles,
                         .out_r = &out_r};
    parts.cs = compare_settings(s, s->out_dir, "tirenv study: the paper's comparison on the "
                                               "validation cases");
    if (!status)
        status = tirenv_parallel_for(3, s->jobs ? s->jobs : 1, study_part, NULL, &parts, diag);
    const tirenv_compare_settings cs = parts.cs;

    progress(s, "writing the report", 6);
    const tirenv_study__facts facts = {.ds = &ds, .main = &main_r, .main_settings = &cs,
                                       .seeds = &seeds, .springs_fit = &fit,
                                       .cam_fit = fit_cam ? &cam_fit : NULL,
                                       .R0 = tire.springs.R0};
    if (!status &&
        !(notes = study_notes(s, &grid, &facts, &nn_rep, &phys_rep, &phys_r, &out_r,
                              &out_ds)))
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "study", "out of memory");
    if (!status)
        status = tirenv_compare_report(&ds, &cs, &main_r, notes, diag);
    progress(s, "done", STEPS);

    free(notes);
    tirenv_nn_seeds_free(&seeds);
    tirenv_compare_result_free(&main_r);
    tirenv_compare_result_free(&phys_r);
    tirenv_compare_result_free(&out_r);
    tirenv_nn_free(nn);
    tirenv_nn_free(nn_phys);
    tirenv_dataset_free(&phys_ds);
    tirenv_dataset_free(&out_ds);
    for (size_t i = 0; i < N_OUTSIDE; ++i)
        tirenv_profile_free(profiles[i]);
    tirenv_dataset_free(&ds);
    return status;
}

/* The report directory is written as a whole (tirenv_outdir): a failed or killed study
 * leaves the previous report as it was, and no empty directory. */
int tirenv_study(const tirenv_study_settings *s, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    tirenv_outdir *out;
    int status = tirenv_outdir_begin(s->out_dir, &out, diag);
    if (status)
        return status;
    tirenv_study_settings staged = *s;
    staged.out_dir = tirenv_outdir_path(out);
    if ((status = study_into(&staged, diag))) {
        tirenv_outdir_abort(out);
        return status;
    }
    return tirenv_outdir_commit(out, diag);
}
