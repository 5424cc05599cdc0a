/* The paper's comparison (docs/models.md section 8; Table 3 and Figure 5): every model on
 * the chosen cases of a data set, how far each is off, how long each takes per position, one plot per
 * case, and the tables. The report built on them is in report.c.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/study.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <time.h>

#include "study/compare_impl.h"
#include "study/plot.h"
#include "tirenv/outfile.h"
#include "tirenv/nn.h"
#include "tirenv/parallel.h"

/* A cap on timing repeats, should the clock not advance. */
enum { MAX_REPEATS = 1000000 };

tirenv_compare_settings tirenv_compare_default(void)
{
    tirenv_compare_settings s = {
        .cases = NULL,
        .n_cases = 0,
        .split = TIRENV_SPLIT_VALIDATION,
        .n_models = 2,
        .with_nn = 1,
        .simulated = 0,
        .simulated_by = NULL,
        .simulated_raw = 0,
        .nn_R0 = 0,
        .rise_threshold = 1e-3,
        .min_time = 0.02,
        .fail_fraction = 0.1,
        .out_dir = "out/compare",
        .title = NULL,
        .data_label = NULL,
        .tire_label = NULL,
        .nn_label = NULL,
        .images = 1,
        .gnuplot = NULL,
        .jobs = 1,
    };
    s.models[0] = tirenv_model_rigid;
    s.models[1] = tirenv_model_springs;
    return s;
}

void tirenv_compare_result_free(tirenv_compare_result *r)
{
    if (!r)
        return;
    if (r->entry)
        for (size_t k = 0; k < r->n_cases * r->n_models; ++k)
            free(r->entry[k].h);
    free(r->entry);
    free(r->case_index);
    r->entry = NULL;
    r->case_index = NULL;
    r->n_cases = 0;
    r->n_models = 0;
}

/* ---- shared with report.c ----------------------------------------------------------------- */

const tirenv_compare_entry *tirenv_compare__entry(const tirenv_compare_result *r, size_t i,
                                                  size_t j)
{
    return &r->entry[i * r->n_models + j];
}

void tirenv_compare__caption(const tirenv_case *c, char *buf, size_t size)
{
    snprintf(buf, size, "contact length %.4g mm, obstacle %.4g x %.4g mm", c->contact_length * 1e3,
             c->L * 1e3, c->H * 1e3);
}

/* The role of each model in the paper's study, for legends and tables. */
const char *tirenv_compare__label(const tirenv_compare_result *r, size_t j)
{
    static const struct {
        const char *name, *role;
    } roles[] = {{"rigid", "geometric limit"}, {"springs", "physical model"},
                 {"cam", "tandem cam"}, {"point", "point contact"}};
    if ((int)j == r->reference_model)
        return "reference";
    if ((int)j == r->nn_model)
        return "empirical model";
    for (size_t k = 0; k < sizeof roles / sizeof roles[0]; ++k)
        if (strcmp(r->model[j], roles[k].name) == 0)
            return roles[k].role;
    return NULL;
}

/* mm with two decimals (a hundredth of a mm is below any rig's noise), "nan" when there is no
 * number, as strtod reads it back. */
void tirenv_compare__mm(char *buf, size_t size, double metres)
{
    if (isfinite(metres))
        snprintf(buf, size, "%.2f", metres * 1e3);
    else
        snprintf(buf, size, "nan");
}

/* The same with its sign, for differences that have a direction. */
void tirenv_compare__signed_mm(char *buf, size_t size, double metres)
{
    if (isfinite(metres))
        snprintf(buf, size, "%+.2f", metres * 1e3);
    else
        snprintf(buf, size, "nan");
}

/* A duration with a unit a reader takes in at once. */
void tirenv_compare__duration(char *buf, size_t size, double seconds)
{
    if (!isfinite(seconds))
        snprintf(buf, size, "n/a");
    else if (seconds < 1e-6)
        snprintf(buf, size, "%.3g ns", seconds * 1e9);
    else if (seconds < 1e-3)
        snprintf(buf, size, "%.3g µs", seconds * 1e6);
    else if (seconds < 1)
        snprintf(buf, size, "%.3g ms", seconds * 1e3);
    else
        snprintf(buf, size, "%.3g s", seconds);
}

/* A ratio to two or three significant digits, without exponents in a sentence. */
void tirenv_compare__ratio(char *buf, size_t size, double ratio)
{
    if (!isfinite(ratio))
        snprintf(buf, size, "n/a");
    else if (ratio >= 100)
        snprintf(buf, size, "%.0f", ratio);
    else if (ratio >= 10)
        snprintf(buf, size, "%.1f", ratio);
    else
        snprintf(buf, size, "%.2f", ratio);
}

/* RMS/H as a percentage with one decimal, "nan" without a number. */
void tirenv_compare__percent(char *buf, size_t size, double fraction)
{
    if (isfinite(fraction))
        snprintf(buf, size, "%.1f", fraction * 1e2);
    else
        snprintf(buf, size, "nan");
}

double tirenv_compare__mean_rms_over_H(const tirenv_dataset *ds, const tirenv_compare_result *r,
                                       size_t j)
{
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < r->n_cases; ++i) {
        const tirenv_compare_entry *e = tirenv_compare__entry(r, i, j);
        if (e->status == TIRENV_OK) {
            sum += e->errors.rms / ds->cases[r->case_index[i]].H;
            ++n;
        }
    }
    return n ? sum / (double)n : NAN;
}

double tirenv_compare__mean_rms(const tirenv_compare_result *r, size_t j, size_t *n_ok)
{
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < r->n_cases; ++i) {
        const tirenv_compare_entry *e = tirenv_compare__entry(r, i, j);
        if (e->status == TIRENV_OK) {
            sum += e->errors.rms;
            ++n;
        }
    }
    if (n_ok)
        *n_ok = n;
    return n ? sum / (double)n : NAN;
}

/* The tables of errors.md, also the body of report.md: per case and model the four errors in
 * mm, then per model its mean RMS error and its time per position. hashes is the Markdown
 * heading level of the section titles ("##"). */
void tirenv_compare__tables(FILE *fp, const char *hashes, const tirenv_dataset *ds,
                            const tirenv_compare_settings *s, const tirenv_compare_result *r)
{
    char a[32], b[32], c[32], d[32];
    fprintf(fp, "%s Errors per case and model\n\n", hashes);
    fprintf(fp,
            "Model minus measurement, in mm. RMS and Max: root mean square and largest "
            "absolute difference of h over the case's points; RMS/H: the RMS as a share of "
            "the obstacle height, which compares obstacles (and tires) of any size. Peak: the "
            "model's highest h minus the measured one. First rise: where the model's h first "
            "exceeds %.3g mm minus where the measured h does (negative: the model rises "
            "earlier), along x.\n\n",
            s->rise_threshold * 1e3);
    fputs("| Case | Contact length (mm) | Obstacle L x H (mm) | Model | RMS (mm) | RMS/H (%) "
          "| Max (mm) | Peak (mm) | First rise (mm) |\n"
          "|---|---:|---:|---|---:|---:|---:|---:|---:|\n",
          fp);
    for (size_t i = 0; i < r->n_cases; ++i) {
        const tirenv_case *cs = &ds->cases[r->case_index[i]];
        for (size_t j = 0; j < r->n_models; ++j) {
            const tirenv_compare_entry *e = tirenv_compare__entry(r, i, j);
            if (j == 0)
                fprintf(fp, "| %s | %.4g | %.4g x %.4g ", cs->name, cs->contact_length * 1e3,
                        cs->L * 1e3, cs->H * 1e3);
            else
                fputs("| | | ", fp);
            if (e->status) {
                fprintf(fp, "| %s | failed: %s | | | | |\n", r->model[j],
                        tirenv_strerror(e->status));
                continue;
            }
            char q[32];
            tirenv_compare__mm(a, sizeof a, e->errors.rms);
            tirenv_compare__percent(q, sizeof q, e->errors.rms / cs->H);
            tirenv_compare__mm(b, sizeof b, e->errors.max);
            tirenv_compare__signed_mm(c, sizeof c, e->errors.peak);
            tirenv_compare__signed_mm(d, sizeof d, e->errors.first_rise);
            fprintf(fp, "| %s | %s | %s | %s | %s | %s |\n", r->model[j], a, q, b, c,
                    isfinite(e->errors.first_rise) ? d : "n/a");
        }
    }

    fprintf(fp, "\n%s Mean RMS error per model\n\n", hashes);
    fputs("| Model | Mean RMS (mm) | Mean RMS/H (%) | Cases |\n|---|---:|---:|---:|\n", fp);
    for (size_t j = 0; j < r->n_models; ++j) {
        size_t n_ok;
        const double mean = tirenv_compare__mean_rms(r, j, &n_ok);
        tirenv_compare__mm(a, sizeof a, mean);
        tirenv_compare__percent(b, sizeof b, tirenv_compare__mean_rms_over_H(ds, r, j));
        fprintf(fp, "| %s | %s | %s | %zu of %zu |\n", r->model[j], a, b, n_ok, r->n_cases);
    }

    fprintf(fp, "\n%s Evaluation time per position\n\n", hashes);
    fprintf(fp,
            "Measured in this run: each model's pass over all the cases above (for a physical "
            "model: set the load and the cleat, then the equilibrium at every point) repeated "
            "for at least %.3g ms; the fastest pass, divided by its positions.\n\n",
            s->min_time * 1e3);
    const double t_nn = r->nn_model >= 0 ? r->time_per_position[r->nn_model] : NAN;
    fprintf(fp, "| Model | Time per position | %s | Positions per pass | Passes |\n"
                "|---|---:|---:|---:|---:|\n",
            r->nn_model >= 0 ? "Time / network's" : "(no network)");
    for (size_t j = 0; j < r->n_models; ++j) {
        tirenv_compare__duration(a, sizeof a, r->time_per_position[j]);
        tirenv_compare__ratio(b, sizeof b, r->time_per_position[j] / t_nn);
        fprintf(fp, "| %s | %s | %s | %zu | %zu |\n", r->model[j], a,
                r->nn_model >= 0 ? b : "", r->timed_positions[j], r->timed_repeats[j]);
    }
}

/* ---- choosing ----------------------------------------------------------------------------- */

typedef struct {
    char base[32];  /* the plot files' name: a case name has at most 31 characters */
    size_t case_k;  /* its place among the compared cases */
} plot_name;

static int plot_name_cmp(const void *a, const void *b)
{
    const plot_name *p = a, *q = b;
    const int c = strcmp(p->base, q->base);
    return c ? c : (p->case_k > q->case_k) - (p->case_k < q->case_k);
}

/* Two compared cases whose names give the same plot files (tirenv_plot__base: "x y" and "x_y"
 * are both x_y.*) would write them over each other, and the report would show one case's
 * figure under the other's name; so they are refused, naming both. Sorted, not compared
 * pairwise: a sweep may have a million cases. */
static int distinct_plot_names(const tirenv_dataset *ds, const tirenv_compare_result *r,
                               tirenv_diag *diag)
{
    plot_name *names = malloc((r->n_cases ? r->n_cases : 1) * sizeof *names);
    if (!names)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    for (size_t k = 0; k < r->n_cases; ++k) {
        tirenv_plot__base(ds->cases[r->case_index[k]].name, names[k].base,
                          sizeof names[k].base);
        names[k].case_k = k;
    }
    qsort(names, r->n_cases, sizeof *names, plot_name_cmp);
    int status = TIRENV_OK;
    for (size_t k = 1; k < r->n_cases && !status; ++k)
        if (strcmp(names[k - 1].base, names[k].base) == 0)
            status = tirenv_error(diag, TIRENV_EINVAL, ds->dir, 0, "cases",
                                  "cases '%s' and '%s' would share the plot files %s.*; "
                                  "expected names that differ in letters, digits, '.', '_' "
                                  "or '-' (other characters become '_')",
                                  ds->cases[r->case_index[names[k - 1].case_k]].name,
                                  ds->cases[r->case_index[names[k].case_k]].name,
                                  names[k].base);
    free(names);
    return status;
}

static int select_cases(const tirenv_dataset *ds, const tirenv_compare_settings *s,
                        tirenv_compare_result *r, tirenv_diag *diag)
{
    const size_t want = s->cases && s->n_cases ? s->n_cases : ds->n;
    r->case_index = malloc((want ? want : 1) * sizeof *r->case_index);
    if (!r->case_index)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    if (s->cases && s->n_cases) {
        for (size_t k = 0; k < s->n_cases; ++k) {
            size_t i = 0;
            while (i < ds->n && strcmp(ds->cases[i].name, s->cases[k]) != 0)
                ++i;
            if (i == ds->n) {
                char list[256] = "";
                for (size_t m = 0; m < ds->n && strlen(list) + 40 < sizeof list; ++m)
                    snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s",
                             m ? ", " : "", ds->cases[m].name);
                return tirenv_error(diag, TIRENV_EINVAL, ds->dir, 0, "cases",
                                    "no case '%s' in the data set; its cases are %s%s",
                                    s->cases[k], list, ds->n > 0 ? "" : "(none)");
            }
            /* Twice in the list, a case would count twice in the means (section 8.3). */
            for (size_t m = 0; m < r->n_cases; ++m)
                if (r->case_index[m] == i)
                    return tirenv_error(diag, TIRENV_EINVAL, ds->dir, 0, "cases",
                                        "case '%s' is listed twice (cases %zu and %zu of the "
                                        "list); expected each case once, as each counts once "
                                        "in the means", s->cases[k], m + 1, k + 1);
            r->case_index[r->n_cases++] = i;
        }
    } else {
        for (size_t i = 0; i < ds->n; ++i)
            if (ds->cases[i].split == s->split)
                r->case_index[r->n_cases++] = i;
        if (r->n_cases == 0)
            return tirenv_error(diag, TIRENV_EINVAL, ds->dir, 0, "split",
                                "the data set has no %s cases to compare",
                                tirenv_split_name(s->split));
    }
    for (size_t k = 0; k < r->n_cases; ++k) {
        const tirenv_case *c = &ds->cases[r->case_index[k]];
        if (c->curve.n == 0 || !c->curve.x || !c->curve.h || !c->curve.x_N)
            return tirenv_error(diag, TIRENV_EINVAL, ds->dir, 0, "curve",
                                "case %s has no curve to compare with", c->name);
    }
    return distinct_plot_names(ds, r, diag);
}

/* The physical models asked for, then the one that simulated the data if it is not among
 * them, then the network: a type that evaluates a network (TIRENV_MODEL_NEEDS_NETWORK) is the
 * last column, whether listed or added by with_nn. */
static int select_models(const tirenv_compare_settings *s, const tirenv_nn *nn,
                         const tirenv_model_type *types[], tirenv_compare_result *r,
                         tirenv_diag *diag)
{
    const size_t max = TIRENV_COMPARE_MAX_MODELS - 1;
    if (s->n_models > max)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "models",
                            "%zu physical models asked for; at most %zu", s->n_models, max);
    size_t n = 0;
    const tirenv_model_type *network = NULL;
    r->reference_model = -1;
    r->nn_model = -1;
    for (size_t k = 0; k < s->n_models; ++k) {
        if (!s->models[k])
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "models",
                                "model %zu of the list is NULL", k + 1);
        if (tirenv_model_type_flags(s->models[k]) & TIRENV_MODEL_NEEDS_NETWORK) {
            if (!nn)
                return tirenv_error(diag, TIRENV_EINVAL, "", 0, "models",
                                    "the %s model needs a trained network, and none is given",
                                    tirenv_model_type_name(s->models[k]));
            network = s->models[k];
            continue;
        }
        size_t dup = 0;
        while (dup < n && types[dup] != s->models[k])
            ++dup;
        if (dup == n)
            types[n++] = s->models[k];
    }
    if (!network && s->with_nn)
        network = tirenv_model_nn;
    if (s->simulated_by &&
        (tirenv_model_type_flags(s->simulated_by) & TIRENV_MODEL_NEEDS_NETWORK))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "simulated_by",
                            "the data cannot have been simulated by the %s model: the virtual "
                            "rig runs a physical model", tirenv_model_type_name(s->simulated_by));
    if (s->simulated_by) {
        size_t k = 0;
        while (k < n && types[k] != s->simulated_by)
            ++k;
        if (k == n) {
            if (n == max)
                return tirenv_error(diag, TIRENV_EINVAL, "", 0, "models",
                                    "no room for the reference model %s: at most %zu "
                                    "physical models", tirenv_model_type_name(s->simulated_by),
                                    max);
            types[n++] = s->simulated_by;
        }
        r->reference_model = (int)k;
    }
    for (size_t k = 0; k < n; ++k)
        snprintf(r->model[k], sizeof r->model[k], "%s", tirenv_model_type_name(types[k]));
    if (nn && network) {
        r->nn_model = (int)n;
        types[n] = network;
        snprintf(r->model[n], sizeof r->model[n], "%s", tirenv_model_type_name(network));
        ++n;
    }
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "models", "no model to compare");
    r->n_models = n;
    return TIRENV_OK;
}

/* ---- evaluating --------------------------------------------------------------------------- */

/* One model, physical or the network, behind one call. */
typedef struct {
    tirenv_model *m;       /* a physical model, or NULL for the network */
    tirenv_nn *nn;
    double R0;             /* the radius the network's x_N refers to, m */
} evaluator;

static int evaluate(evaluator *ev, const tirenv_case *c, double h[], tirenv_diag *diag)
{
    return ev->m ? tirenv_case_predict_model(ev->m, c, h, diag)
                 : tirenv_case_predict_nn(ev->nn, ev->R0, c, h, diag);
}

static void entry_failed(tirenv_compare_entry *e, size_t n, int status, const tirenv_diag *d)
{
    e->status = status;
    snprintf(e->message, sizeof e->message, "%s",
             d->message[0] ? d->message : tirenv_strerror(status));
    e->errors = (tirenv_curve_errors){NAN, NAN, NAN, NAN};
    for (size_t k = 0; k < n; ++k)
        e->h[k] = NAN;
}

/* The time a thread has spent running, s: what an evaluation costs on one core, whatever
 * else runs beside it (other workers, other programs). */
static double thread_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Every (model, case) entry is independent: they run on s->jobs threads, each worker with
 * its own instance of every model (the network cloned: an instance is not thread-safe), and
 * each entry's evaluation is timed on its own thread's clock. */
typedef struct {
    const tirenv_dataset *ds;
    const tirenv_compare_settings *s;
    tirenv_compare_result *r;
    const tirenv_model_type *const *types;
    const tirenv_tire *tire;
    tirenv_nn *nn;
    evaluator *ev;         /* jobs x n_models, built when a worker first needs one */
    double *seconds;       /* per entry (model-major), s */
} compare_pass;

static int instance(compare_pass *p, size_t worker, size_t j, evaluator **out,
                    tirenv_diag *diag)
{
    evaluator *ev = &p->ev[worker * p->r->n_models + j];
    *out = ev;
    if (ev->m || ev->nn)
        return TIRENV_OK;
    ev->R0 = p->s->nn_R0 > 0 ? p->s->nn_R0 : p->tire->springs.R0;
    if ((int)j == p->r->nn_model)
        ev->nn = tirenv_nn_clone(p->nn);  /* also on the caller's thread: the caller's network
                                           * may be in use by other threads (a study runs its
                                           * comparisons side by side) */
    else
        ev->m = tirenv_model_alloc(p->types[j], p->tire);
    if (!ev->m && !ev->nn)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, p->r->model[j],
                            "cannot allocate the %s model", p->r->model[j]);
    return TIRENV_OK;
}

/* Entry k: model k / n_cases on case k % n_cases. A model failing on a case does not stop
 * the comparison: the entry records why. */
static int evaluate_entry(void *ctx, size_t k, size_t worker, tirenv_diag *diag)
{
    compare_pass *p = ctx;
    tirenv_compare_result *r = p->r;
    const size_t j = k / r->n_cases, i = k % r->n_cases;
    evaluator *ev;
    const int st = instance(p, worker, j, &ev, diag);
    if (st)
        return st;
    const tirenv_case *c = &p->ds->cases[r->case_index[i]];
    tirenv_compare_entry *e = &r->entry[i * r->n_models + j];
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const double t0 = thread_seconds();
    int status = evaluate(ev, c, e->h, &d);
    p->seconds[k] = thread_seconds() - t0;
    if (!status)
        status = tirenv_curve_errors_compute(c->curve.n, c->curve.x, c->curve.h, e->h,
                                             p->s->rise_threshold, &e->errors);
    if (status)
        entry_failed(e, c->curve.n, status, &d);
    return TIRENV_OK;
}

/* Model j's timing: its first pass is the entries' own times; more passes, one model at a
 * time on this thread, only until min_time has passed, and the fastest counts: the others
 * are the same work slowed by whatever else the machine did. Cases the model failed on are
 * left out. */
static void time_model(compare_pass *p, size_t j, double scratch[])
{
    tirenv_compare_result *r = p->r;
    double pass = 0;
    size_t positions = 0;
    for (size_t i = 0; i < r->n_cases; ++i)
        if (r->entry[i * r->n_models + j].status == TIRENV_OK) {
            pass += p->seconds[j * r->n_cases + i];
            positions += p->ds->cases[r->case_index[i]].curve.n;
        }
    r->timed_positions[j] = positions;
    r->timed_repeats[j] = 1;
    if (positions == 0) {
        r->time_per_position[j] = NAN;
        return;
    }
    evaluator *ev = NULL;
    double best = pass, total = pass;
    size_t repeats = 1;
    while (total < p->s->min_time && repeats < MAX_REPEATS &&
           instance(p, 0, j, &ev, NULL) == TIRENV_OK) {
        const double t0 = thread_seconds();
        for (size_t i = 0; i < r->n_cases; ++i)
            if (r->entry[i * r->n_models + j].status == TIRENV_OK)
                (void)evaluate(ev, &p->ds->cases[r->case_index[i]], scratch, NULL);
        const double t = thread_seconds() - t0;
        total += t;
        best = fmin(best, t);
        ++repeats;
    }
    r->timed_repeats[j] = repeats;
    r->time_per_position[j] = best / (double)positions;
}

static void pass_free(compare_pass *p, size_t jobs)
{
    for (size_t k = 0; p->ev && k < jobs * p->r->n_models; ++k) {
        tirenv_model_free(p->ev[k].m);
        tirenv_nn_free(p->ev[k].nn);
    }
    free(p->ev);
    free(p->seconds);
}

/* ---- writing ------------------------------------------------------------------------------ */

static int path_in(char *buf, size_t size, const char *dir, const char *name, tirenv_diag *diag)
{
    const int n = snprintf(buf, size, "%s/%s", dir, name);
    if (n < 0 || (size_t)n >= size)
        return tirenv_error(diag, TIRENV_EINVAL, dir, 0, "out_dir",
                            "output path '%s/%s' is too long", dir, name);
    return TIRENV_OK;
}

/* Opens dir/name as an all-or-nothing output file. */
int tirenv_compare__open(tirenv_outfile **f, const char *dir, const char *name,
                         tirenv_diag *diag)
{
    char path[512];
    *f = NULL;
    const int status = path_in(path, sizeof path, dir, name, diag);
    return status ? status : tirenv_outfile_open(f, path, diag);
}

int tirenv_compare__close(tirenv_outfile *f, tirenv_diag *diag)
{
    if (ferror(tirenv_outfile_stream(f))) {
        const int e = errno;
        const int status = tirenv_error(diag, TIRENV_EIO, tirenv_outfile_path(f), 0, "",
                                        "cannot write: %s", strerror(e ? e : EIO));
        tirenv_outfile_abort(f);
        return status;
    }
    return tirenv_outfile_commit(f, diag);
}

static void csv_mm(FILE *fp, double metres)
{
    if (isfinite(metres))
        fprintf(fp, ",%.4f", metres * 1e3);
    else
        fputs(",nan", fp);
}

static int write_errors_csv(const tirenv_dataset *ds, const tirenv_compare_settings *s,
                            const tirenv_compare_result *r, tirenv_diag *diag)
{
    tirenv_outfile *f;
    int status = tirenv_compare__open(&f, s->out_dir, "errors.csv", diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    fputs("case,model,rms_mm,max_mm,peak_mm,first_rise_mm,rms_over_H\n", fp);
    for (size_t i = 0; i < r->n_cases; ++i)
        for (size_t j = 0; j < r->n_models; ++j) {
            const tirenv_compare_entry *e = tirenv_compare__entry(r, i, j);
            const tirenv_case *c = &ds->cases[r->case_index[i]];
            const double over_H = e->errors.rms / c->H;
            fprintf(fp, "%s,%s", c->name, r->model[j]);
            csv_mm(fp, e->errors.rms);
            csv_mm(fp, e->errors.max);
            csv_mm(fp, e->errors.peak);
            csv_mm(fp, e->errors.first_rise);
            fprintf(fp, isfinite(over_H) ? ",%.6f\n" : ",nan\n", over_H);
        }
    return tirenv_compare__close(f, diag);
}

static int write_timing_csv(const tirenv_compare_settings *s, const tirenv_compare_result *r,
                            tirenv_diag *diag)
{
    tirenv_outfile *f;
    int status = tirenv_compare__open(&f, s->out_dir, "timing.csv", diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    fputs("model,seconds_per_position,ratio_to_nn,positions_per_pass,passes\n", fp);
    const double t_nn = r->nn_model >= 0 ? r->time_per_position[r->nn_model] : NAN;
    for (size_t j = 0; j < r->n_models; ++j) {
        const double t = r->time_per_position[j];
        fprintf(fp, "%s,", r->model[j]);
        fprintf(fp, isfinite(t) ? "%.6g," : "nan,", t);
        fprintf(fp, isfinite(t / t_nn) ? "%.6g," : "nan,", t / t_nn);
        fprintf(fp, "%zu,%zu\n", r->timed_positions[j], r->timed_repeats[j]);
    }
    return tirenv_compare__close(f, diag);
}

void tirenv_compare__data_note(FILE *fp, const tirenv_dataset *ds,
                               const tirenv_compare_settings *s)
{
    const char *label = s->data_label ? s->data_label : ds->dir;
    if (!(s->simulated || s->simulated_by)) {
        fprintf(fp, "Data: `%s` (measurements).\n", label);
        return;
    }
    fprintf(fp, "Data: `%s`. **These data are SIMULATED**", label);
    if (s->simulated_by)
        fprintf(fp, s->simulated_raw ? " as the %s reference model's own curves (no rig)"
                                     : " by the virtual rig on the %s reference model",
                tirenv_model_type_name(s->simulated_by));
    fputs(", not measured on a real tire.\n", fp);
}

static int write_errors_md(const tirenv_dataset *ds, const tirenv_compare_settings *s,
                           const tirenv_compare_result *r, tirenv_diag *diag)
{
    tirenv_outfile *f;
    int status = tirenv_compare__open(&f, s->out_dir, "errors.md", diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    fprintf(fp, "# Enveloping-curve errors%s%s\n\n", s->title ? ": " : "",
            s->title ? s->title : "");
    tirenv_compare__data_note(fp, ds, s);
    fputc('\n', fp);
    tirenv_compare__tables(fp, "##", ds, s, r);
    return tirenv_compare__close(f, diag);
}

static void series_label(const tirenv_compare_result *r, size_t j, char *buf, size_t size)
{
    const char *what = tirenv_compare__label(r, j);
    if (what)
        snprintf(buf, size, "%s (%s)", r->model[j], what);
    else
        snprintf(buf, size, "%s", r->model[j]);
}

static int write_plot_files(const tirenv_dataset *ds, const tirenv_compare_result *r,
                            const tirenv_plot__settings *ps, tirenv_diag *diag)
{
    tirenv_plot__series series[TIRENV_COMPARE_MAX_MODELS];
    char labels[TIRENV_COMPARE_MAX_MODELS][96];
    for (size_t j = 0; j < r->n_models; ++j)
        series_label(r, j, labels[j], sizeof labels[j]);
    int status = TIRENV_OK;
    for (size_t i = 0; i < r->n_cases && !status; ++i) {
        for (size_t j = 0; j < r->n_models; ++j) {
            const tirenv_compare_entry *e = tirenv_compare__entry(r, i, j);
            series[j] = (tirenv_plot__series){r->model[j], labels[j], e->h,
                                              e->status ? e->message : NULL};
        }
        status = tirenv_plot__case(ps, &ds->cases[r->case_index[i]], r->n_models, series,
                                   diag);
    }
    return status;
}

typedef struct {
    const tirenv_plot__settings *ps;
    const tirenv_dataset *ds;
    const tirenv_compare_result *r;
} draw_pass;

static int draw_case(void *ctx, size_t i, size_t worker, tirenv_diag *diag)
{
    const draw_pass *p = ctx;
    (void)worker;
    return tirenv_plot__draw(p->ps, p->ds->cases[p->r->case_index[i]].name, diag);
}

int tirenv_compare(const tirenv_dataset *ds, const tirenv_tire *tire, tirenv_nn *nn,
                   const tirenv_compare_settings *s, tirenv_compare_result *out,
                   tirenv_diag *diag)
{
    if (!out)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "no result to fill");
    memset(out, 0, sizeof *out);
    out->nn_model = out->reference_model = -1;
    if (!ds || !tire || !s)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "no data set, tire or settings");
    out->tire = *tire;
    if (!(s->rise_threshold >= 0 && isfinite(s->rise_threshold)) ||
        !(s->min_time >= 0 && s->min_time < 3600) ||
        !(s->fail_fraction > 0 && isfinite(s->fail_fraction)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "settings",
                            "expected rise_threshold >= 0 m, min_time in [0, 3600) s and "
                            "fail_fraction > 0; got %g, %g, %g",
                            s->rise_threshold, s->min_time, s->fail_fraction);
    /* The title heads the Markdown report: a line break or another control character would
     * break it (a heading is one line). */
    for (const char *t = s->title; t && *t; ++t)
        if ((unsigned char)*t < 0x20 || *t == 0x7f)
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "title",
                                "a control character (0x%02x) at position %zu; expected one "
                                "line of text", (unsigned)(unsigned char)*t,
                                (size_t)(t - s->title) + 1);
    const tirenv_model_type *types[TIRENV_COMPARE_MAX_MODELS];
    int status = tirenv_tire_check(tire, diag);
    if (!status)
        status = select_cases(ds, s, out, diag);
    if (!status)
        status = select_models(s, nn, types, out, diag);
    if (!status)
        status = tirenv_mkdir_p(s->out_dir, diag);
    if (status)
        return status;
    if (nn) {
        const tirenv_nn_topology *t = tirenv_nn_topology_of(nn);
        for (size_t l = 0; l < t->n_layers; ++l) {
            const size_t used = strlen(out->nn_layers);
            snprintf(out->nn_layers + used, sizeof out->nn_layers - used, "%s%zu",
                     l ? "-" : "", t->size[l]);
        }
    }

    size_t n_max = 0;
    for (size_t i = 0; i < out->n_cases; ++i) {
        const size_t n = ds->cases[out->case_index[i]].curve.n;
        n_max = n > n_max ? n : n_max;
    }
    out->entry = calloc(out->n_cases * out->n_models, sizeof *out->entry);
    double *scratch = malloc(n_max * sizeof *scratch);
    if (!out->entry || !scratch) {
        free(scratch);
        tirenv_compare_result_free(out);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    for (size_t i = 0; i < out->n_cases && !status; ++i)
        for (size_t j = 0; j < out->n_models && !status; ++j) {
            const size_t n = ds->cases[out->case_index[i]].curve.n;
            tirenv_compare_entry *e = &out->entry[i * out->n_models + j];
            if (!(e->h = malloc(n * sizeof *e->h)))
                status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
        }

    const size_t jobs = s->jobs ? s->jobs : 1;
    compare_pass pass = {ds, s, out, types, tire, nn, NULL, NULL};
    pass.ev = calloc(jobs * out->n_models, sizeof *pass.ev);
    pass.seconds = calloc(out->n_cases * out->n_models, sizeof *pass.seconds);
    if (!status && (!pass.ev || !pass.seconds))
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    if (!status)
        status = tirenv_parallel_for(out->n_cases * out->n_models, jobs, evaluate_entry, NULL,
                                     &pass, diag);
    for (size_t j = 0; j < out->n_models && !status; ++j)
        time_model(&pass, j, scratch);
    pass_free(&pass, jobs);
    free(scratch);

    const tirenv_plot__settings ps = {s->out_dir, s->simulated || s->simulated_by != NULL,
                                      s->simulated_by ? tirenv_model_type_name(s->simulated_by)
                                                      : NULL,
                                      s->gnuplot, s->simulated_raw};
    if (!status)
        status = write_errors_csv(ds, s, out, diag);
    if (!status)
        status = write_timing_csv(s, out, diag);
    if (!status)
        status = write_errors_md(ds, s, out, diag);
    if (!status)
        status = write_plot_files(ds, out, &ps, diag);
    /* Last, so that without gnuplot everything else is already written; one gnuplot per case,
     * s->jobs at once. */
    draw_pass dp = {&ps, ds, out};
    if (!status && s->images)
        status = tirenv_parallel_for(out->n_cases, jobs, draw_case, NULL, &dp, diag);
    out->images = !status && s->images;
    return status;
}
