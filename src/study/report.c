/* report.md: the comparison told in one page (docs/models.md section 8): what was compared, whether
 * the data are simulated, the tables, the plots, the speed, and what the numbers say. The
 * text is generated from the numbers only; it states them and does not interpret beyond
 * "closest" and "off by". SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/study.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "study/compare_impl.h"
#include "study/plot.h"
#include "io/io.h"

static const tirenv_case *case_of(const tirenv_dataset *ds, const tirenv_compare_result *r,
                                  size_t i)
{
    return &ds->cases[r->case_index[i]];
}

/* What each model is, with the parameters that make it this tire's. */
static void describe_models(FILE *fp, const tirenv_compare_settings *s,
                            const tirenv_compare_result *r)
{
    const tirenv_springs_params *sp = &r->tire.springs;
    for (size_t j = 0; j < r->n_models; ++j) {
        const char *name = r->model[j];
        fprintf(fp, "- **%s**: ", name);
        if ((int)j == r->nn_model) {
            fprintf(fp, "the paper's empirical model, a feed-forward network %s driven by the "
                        "measured contact length", r->nn_layers);
            if (s->nn_label)
                fprintf(fp, " (`%s`)", s->nn_label);
        } else if (strcmp(name, "rigid") == 0) {
            fprintf(fp, "the rigid disc of radius R0 = %.4g mm, the geometric limit", sp->R0 * 1e3);
        } else if (strcmp(name, "springs") == 0) {
            fprintf(fp,
                    "the paper's physical model, radial + interradial springs: c_r = %.4g "
                    "N/m/rad, c_b = %.4g N rad/m, elements %.3g deg apart, R0 = %.4g mm",
                    sp->c_r, sp->c_b, sp->dphi * 180 / M_PI, sp->R0 * 1e3);
            if (s->tire_label)
                fprintf(fp, " (`%s`)", s->tire_label);
        } else if (strcmp(name, "cam") == 0) {
            const tirenv_cam_params *cp = &r->tire.cam;
            fprintf(fp,
                    "MF-Swift's tandem elliptical cam (docs/models.md section 7): ELLIPS_SHIFT %.4g, "
                    "ELLIPS_LENGTH %.4g, ELLIPS_HEIGHT %.4g, ELLIPS_ORDER %.4g, "
                    "VERTICAL_STIFFNESS %.4g N/m",
                    cp->shift, cp->length, cp->height, cp->order, cp->c_z);
            /* As the reference it keeps the tire that simulated the data. */
            if (s->tire_label && (int)j != r->reference_model)
                fprintf(fp, " (`%s`)", s->tire_label);
        } else if (strcmp(name, "ring") == 0) {
            fputs("the flexible-ring reference tire (docs/models.md section 5) with the tire file's "
                  "[ENVELOPING_RING] parameters", fp);
        } else {
            fputs("a physical model with the tire file's parameters", fp);
        }
        if ((int)j == r->reference_model)
            fputs(s->simulated_raw ? "; it simulated the data, its own curves, so it meets "
                                     "them to round-off"
                                   : "; it simulated the data, so its errors show the rig's "
                                     "noise and the import rather than a model error",
                  fp);
        fputs(".\n", fp);
    }
}

static void list_cases(FILE *fp, const tirenv_dataset *ds, const tirenv_compare_result *r)
{
    for (size_t i = 0; i < r->n_cases; ++i)
        fprintf(fp, "%s%s", i == 0 ? "" : i + 1 == r->n_cases ? " and " : ", ",
                case_of(ds, r, i)->name);
}

static void introduction(FILE *fp, const tirenv_dataset *ds, const tirenv_compare_settings *s,
                         const tirenv_compare_result *r)
{
    fprintf(fp, "# %s\n\n",
            s->title ? s->title : "Enveloping models compared with the measured curves");
    fprintf(fp, "This report compares %zu model%s of the quasi-static enveloping curve with the "
                "measured curves of %zu case%s (",
            r->n_models, r->n_models == 1 ? "" : "s", r->n_cases, r->n_cases == 1 ? "" : "s");
    list_cases(fp, ds, r);
    if (!(s->cases && s->n_cases))
        fprintf(fp, ": the %s cases", tirenv_split_name(s->split));
    fputs(") in the manner of the paper's Table 3 and Figure 5 (docs/models.md section 8). The "
          "physical models are driven by each case's applied load and the network by its "
          "measured contact length, as in the paper; every curve is compared at the measured "
          "points of the approach half, from first contact (x_N = 0) to the tire axis over "
          "the obstacle centre (x_N = 1).\n\n",
          fp);
    tirenv_compare__data_note(fp, ds, s);
    if (s->simulated_by && s->simulated_raw)
        fprintf(fp, "\n> **SIMULATED DATA.** The \"measured\" curves in this report are the %s "
                "model's own curves (a tirenv sweep without --rig: no sensor noise, no import), "
                "not a tire on a real rig. The errors below say how well each model reproduces "
                "that model, not a real tire.\n",
                tirenv_model_type_name(s->simulated_by));
    else if (s->simulated_by)
        fputs("\n> **SIMULATED DATA.** The \"measured\" curves in this report were produced by "
              "tirenv's virtual rig (docs/models.md section 5), a model with sensor noise added, not "
              "by a tire on a real rig. The errors below say how well each model reproduces "
              "that reference, not a real tire.\n",
              fp);
    else if (s->simulated)
        fputs("\n> **SIMULATED DATA.** The \"measured\" curves in this report were simulated, "
              "by a model the comparison does not name, not measured on a real tire. The errors "
              "below say how well each model reproduces that model, not a real tire.\n",
              fp);
    fputs("\nModels:\n\n", fp);
    describe_models(fp, s, r);
}

/* Per model its time per position and how many times the network's that is; then whether
 * the paper's claim (fast network, slow physical model) holds here, with springs as the
 * physical model when it was compared. */
static void speed(FILE *fp, const tirenv_compare_result *r)
{
    char t[32], q[32];
    const int nn = r->nn_model;
    const double t_nn = nn >= 0 ? r->time_per_position[nn] : NAN;
    fputs("Per position, measured in this run: ", fp);
    int first = 1;
    if (nn >= 0) {
        tirenv_compare__duration(t, sizeof t, t_nn);
        fprintf(fp, "the network took %s", t);
        first = 0;
    }
    for (size_t j = 0; j < r->n_models; ++j) {
        if ((int)j == nn)
            continue;
        tirenv_compare__duration(t, sizeof t, r->time_per_position[j]);
        fprintf(fp, "%s%s %s", first ? "" : ", ", r->model[j], t);
        if (nn >= 0 && isfinite(r->time_per_position[j] / t_nn)) {
            tirenv_compare__ratio(q, sizeof q, r->time_per_position[j] / t_nn);
            fprintf(fp, " (%s times the network's)", q);
        }
        first = 0;
    }
    fputs(".", fp);
    size_t phys = r->n_models;
    for (size_t j = 0; j < r->n_models; ++j)
        if (strcmp(r->model[j], "springs") == 0)
            phys = j;
    if (nn < 0 || phys == r->n_models || !isfinite(r->time_per_position[phys] / t_nn)) {
        fputs(" No network and springs model timed together, so the paper's speed claim is "
              "not tested here.\n",
              fp);
        return;
    }
    const double ratio = r->time_per_position[phys] / t_nn;
    tirenv_compare__ratio(q, sizeof q, ratio > 1 ? ratio : 1 / ratio);
    if (ratio > 1)
        fprintf(fp, " The paper's claim that the network is fast and the physical model slow "
                    "holds here: springs takes %s times as long per position as the network.\n",
                q);
    else
        fprintf(fp, " The paper's claim that the network is faster than the physical model "
                    "does not hold here: the network takes %s times as long per position as "
                    "springs.\n",
                q);
}

static void plots(FILE *fp, const tirenv_dataset *ds, const tirenv_compare_result *r)
{
    fputs("\n## Plots\n\n", fp);
    fputs("h in mm over x_N, measured points as markers and one line per model, as in the "
          "paper's Figure 5. Each plot's numbers are in `<case>.dat` and its gnuplot script in "
          "`<case>.gp` (run `gnuplot <case>.gp` in this directory to redraw it).\n\n",
          fp);
    for (size_t i = 0; i < r->n_cases; ++i) {
        const tirenv_case *c = case_of(ds, r, i);
        char base[64], caption[160];
        tirenv_plot__base(c->name, base, sizeof base);
        tirenv_compare__caption(c, caption, sizeof caption);
        if (r->images)
            fprintf(fp, "![Case %s: %s](%s.png)\n\nCase %s: %s ([SVG](%s.svg)).\n\n", c->name,
                    caption, base, c->name, caption, base);
        else
            fprintf(fp, "Case %s: %s. Not drawn in this run; `gnuplot %s.gp` draws it.\n\n",
                    c->name, caption, base);
    }
}

/* H/L of a case, and whether it is the largest among the compared ones (the paper's point:
 * both models struggle above some height-to-length ratio). */
static int tallest(const tirenv_dataset *ds, const tirenv_compare_result *r, size_t i)
{
    if (r->n_cases < 2)
        return 0;
    const tirenv_case *c = case_of(ds, r, i);
    for (size_t k = 0; k < r->n_cases; ++k) {
        const tirenv_case *o = case_of(ds, r, k);
        if (k != i && o->H / o->L >= c->H / c->L)
            return 0;
    }
    return 1;
}

static double measured_peak(const tirenv_case *c)
{
    double peak = c->curve.h[0];
    for (size_t k = 1; k < c->curve.n; ++k)
        peak = fmax(peak, c->curve.h[k]);
    return peak;
}

/* "springs is off by 12.3 mm RMS, 14 % of the 88.5 mm measured peak (peak 8.1 mm too high,
 * first rise 25.0 mm early, largest error 20.0 mm)". */
static void off_by(FILE *fp, const char *model, const tirenv_curve_errors *e, double peak)
{
    fprintf(fp, " %s is off by %.1f mm RMS, %.0f %% of the %.1f mm measured peak (peak %.1f mm "
                "too %s",
            model, e->rms * 1e3, 100 * e->rms / peak, peak * 1e3, fabs(e->peak) * 1e3,
            e->peak >= 0 ? "high" : "low");
    if (isfinite(e->first_rise))
        fprintf(fp, ", first rise %.1f mm %s", fabs(e->first_rise) * 1e3,
                e->first_rise >= 0 ? "late" : "early");
    fprintf(fp, ", largest error %.1f mm).", e->max * 1e3);
}

/* Per case: the models ranked by RMS error (the reference that simulated the data apart),
 * and every model off by more than fail_fraction of the measured peak or failed outright. */
static void findings_case(FILE *fp, const tirenv_dataset *ds, const tirenv_compare_settings *s,
                          const tirenv_compare_result *r, size_t i)
{
    const tirenv_case *c = case_of(ds, r, i);
    char caption[160];
    tirenv_compare__caption(c, caption, sizeof caption);
    fprintf(fp, "- On **%s** (%s, H/L = %.2f%s):", c->name, caption, c->H / c->L,
            tallest(ds, r, i) ? ", the tallest relative to its length of these cases" : "");
    size_t order[TIRENV_COMPARE_MAX_MODELS], n = 0;
    for (size_t j = 0; j < r->n_models; ++j) {
        const tirenv_compare_entry *e = tirenv_compare__entry(r, i, j);
        if ((int)j == r->reference_model || e->status)
            continue;
        size_t k = n++;
        for (; k > 0 && tirenv_compare__entry(r, i, order[k - 1])->errors.rms > e->errors.rms;
             --k)
            order[k] = order[k - 1];
        order[k] = j;
    }
    if (n > 0) {
        const tirenv_curve_errors *best = &tirenv_compare__entry(r, i, order[0])->errors;
        fprintf(fp, " %s is closest to the measurement, %.2f mm RMS (largest error %.2f mm)",
                r->model[order[0]], best->rms * 1e3, best->max * 1e3);
        for (size_t k = 1; k < n; ++k)
            fprintf(fp, "%s%s %.2f mm", k == 1 ? "; then " : ", ", r->model[order[k]],
                    tirenv_compare__entry(r, i, order[k])->errors.rms * 1e3);
        fputs(".", fp);
    }
    if (r->reference_model >= 0) {
        const tirenv_compare_entry *e = tirenv_compare__entry(r, i, (size_t)r->reference_model);
        if (!e->status)
            fprintf(fp, " The reference %s, which simulated the data, is at %.2f mm RMS.",
                    r->model[r->reference_model], e->errors.rms * 1e3);
    }
    const double peak = measured_peak(c);
    for (size_t j = 0; j < r->n_models; ++j) {
        const tirenv_compare_entry *e = tirenv_compare__entry(r, i, j);
        if (e->status)
            fprintf(fp, " %s failed: %s.", r->model[j], e->message);
        else if (peak > 0 && e->errors.rms > s->fail_fraction * peak)
            off_by(fp, r->model[j], &e->errors, peak);
    }
    fputc('\n', fp);
}

/* Over all cases: mean RMS per model, lowest first, and which cases had a model off. */
static void findings(FILE *fp, const tirenv_dataset *ds, const tirenv_compare_settings *s,
                     const tirenv_compare_result *r)
{
    fputs("\n## Findings\n\n", fp);
    fprintf(fp, "A model is called off on a case when its RMS error exceeds %.0f %% of the "
                "measured peak height.\n\n",
            100 * s->fail_fraction);
    for (size_t i = 0; i < r->n_cases; ++i)
        findings_case(fp, ds, s, r, i);
    size_t order[TIRENV_COMPARE_MAX_MODELS], n = 0;
    for (size_t j = 0; j < r->n_models; ++j) {
        const double m = tirenv_compare__mean_rms(r, j, NULL);
        if (!isfinite(m))
            continue;
        size_t k = n++;
        for (; k > 0 && tirenv_compare__mean_rms(r, order[k - 1], NULL) > m; --k)
            order[k] = order[k - 1];
        order[k] = j;
    }
    if (n == 0)
        return;
    fprintf(fp, "\nMean RMS error over the cases each model completed, lowest first: ");
    for (size_t k = 0; k < n; ++k) {
        size_t n_ok;
        const double m = tirenv_compare__mean_rms(r, order[k], &n_ok);
        fprintf(fp, "%s%s %.2f mm", k ? ", " : "", r->model[order[k]], m * 1e3);
        if (n_ok < r->n_cases)
            fprintf(fp, " (%zu of %zu cases)", n_ok, r->n_cases);
    }
    fputs(".\n", fp);
}

int tirenv_compare_report(const tirenv_dataset *ds, const tirenv_compare_settings *s,
                          const tirenv_compare_result *r, const char *notes, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    if (!r->entry || r->n_cases == 0 || r->n_models == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "",
                            "no comparison to report (tirenv_compare did not complete)");
    tirenv_outfile *f;
    int status = tirenv_compare__open(&f, s->out_dir, "report.md", diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    introduction(fp, ds, s, r);
    if (notes && *notes)
        fprintf(fp, "\n%s%s", notes, notes[strlen(notes) - 1] == '\n' ? "" : "\n");
    fputc('\n', fp);
    tirenv_compare__tables(fp, "##", ds, s, r);
    fputc('\n', fp);
    speed(fp, r);
    plots(fp, ds, r);
    findings(fp, ds, s, r);
    fputs("\nThe same numbers are in `errors.csv` and `timing.csv`; `errors.md` holds the "
          "tables alone.\n",
          fp);
    return tirenv_compare__close(f, diag);
}
