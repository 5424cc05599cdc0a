/* tirenv fit: identify the physical model's stiffnesses on a data set's training cases.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "cli/cli.h"
#include "tirenv/study.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv fit --data DIR [--model springs|cam|ring] [--fit-radius | --all]\n"
          "                  [--check-refinement] [-o FITTED.tir] [--jobs N] [--tire FILE]\n"
          "                  [--set K=V]... [--method M]\n"
          "\n"
          "Identifies RADIAL_STIFFNESS and INTERRADIAL_STIFFNESS (and UNLOADED_RADIUS with\n"
          "--fit-radius) of the springs model, ELLIPS_SHIFT, ELLIPS_LENGTH, ELLIPS_HEIGHT\n"
          "and ELLIPS_ORDER of the cam model, or FOUNDATION_STIFFNESS and TREAD_STIFFNESS\n"
          "(and BELT_BENDING_STIFFNESS and INFLPRES with --all) of the ring, on the\n"
          "data set's training cases by nonlinear least squares on h (Minpack's lmdif),\n"
          "starting from the tire file (the data set's own when its source.txt names one and\n"
          "--tire is not given), and reports standard errors and the fit per case; a\n"
          "parameter the data drive to its bound (ELLIPS_ORDER to 1, a stiffness towards 0)\n"
          "is reported AT ITS LOWER BOUND. The discretisation (ELEMENT_ANGLE) is a setting,\n"
          "not a fitted parameter: --check-refinement refits the springs model with it\n"
          "halved and reports how much the parameters and the fitted curves change.\n"
          "\n"
          "options:\n"
          "  --data DIR           data set directory with cases.csv\n"
          "  --fit-radius         also fit UNLOADED_RADIUS (springs)\n"
          "  --all                also fit the model's optional parameters (springs: the\n"
          "                       radius; ring: the belt's bending stiffness and tension)\n"
          "  --check-refinement   refit with ELEMENT_ANGLE / 2 and compare\n"
          "  -o, --output FILE    write the fitted tire (.tir); default: print only\n",
          fp);
    cli_help_model(fp, TIRENV_MODEL_FITTABLE, 0, " (default springs)");
    cli_help_jobs(fp);
    cli_help_tire_as(fp, 1, "RADIAL_STIFFNESS=4.5e5 (the springs model's)",
                     cli_help_data_tire);
    fputs("  -h, --help           show this help\n", fp);
}

static void progress(void *ctx, size_t iter, double rms)
{
    (void)ctx;
    if (isatty(STDERR_FILENO))
        fprintf(stderr, "\rtirenv: fit: iteration %zu, rms %.3f mm   ", iter, 1e3 * rms);
}

/* Per-case RMS (mm) of a fitted model on the chosen split, one line per case. */
static int print_cases(const tirenv_dataset *ds, const tirenv_model_type *type,
                       const tirenv_tire *tire, tirenv_split split, const tirenv_tire *other,
                       double *max_change, double *sq_change, size_t *n_change)
{
    size_t n_max = 0;
    for (size_t i = 0; i < ds->n; ++i)
        n_max = ds->cases[i].curve.n > n_max ? ds->cases[i].curve.n : n_max;
    tirenv_model *m = tirenv_model_alloc(type, tire);
    tirenv_model *m2 = other ? tirenv_model_alloc(type, other) : NULL;
    double *h = malloc(2 * n_max * sizeof *h), *h_other = h + n_max;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    int status = m && (!other || m2) && h ? TIRENV_OK : TIRENV_ENOMEM;
    for (size_t i = 0; i < ds->n && !status; ++i) {
        const tirenv_case *c = &ds->cases[i];
        if (c->split != split)
            continue;
        if ((status = tirenv_case_predict_model(m, c, h, &diag)))
            break;
        double sq = 0, mx = 0;
        for (size_t j = 0; j < c->curve.n; ++j) {
            const double e = h[j] - c->curve.h[j];
            sq += e * e;
            mx = fmax(mx, fabs(e));
        }
        printf("  %-4s %-10s l_c %.2f m  %.3f x %.3f m   rms %6.2f mm  max %6.2f mm\n", c->name,
               tirenv_split_name(c->split), c->contact_length, c->L, c->H,
               1e3 * sqrt(sq / (double)c->curve.n), 1e3 * mx);
        if (m2 && !(status = tirenv_case_predict_model(m2, c, h_other, &diag)))
            for (size_t j = 0; j < c->curve.n; ++j) {
                const double d = h_other[j] - h[j];
                *max_change = fmax(*max_change, fabs(d));
                *sq_change += d * d;
                ++*n_change;
            }
    }
    free(h);
    tirenv_model_free(m);
    tirenv_model_free(m2);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

static void print_report(const char *what, const tirenv_fit_report *r)
{
    printf("%s: %zu points, %zu iterations (%s), %.2f s, rms %.3f mm\n", what, r->n_points,
           r->iterations, r->stop, r->seconds, 1e3 * r->rms);
    size_t at_bound = 0;
    for (size_t i = 0; i < r->n_params; ++i) {
        printf("  %-22s = %.6g +- %.2g (1 sigma)", r->names[i], r->value[i], r->std_error[i]);
        if (r->at_bound[i]) {
            printf("  AT ITS LOWER BOUND %g", r->bound[i]);
            ++at_bound;
        }
        putchar('\n');
    }
    if (at_bound)
        printf("  %zu parameter%s at a bound: the data push the model to the edge of what it "
               "can express; the fit is the best the model can do, not an identification\n",
               at_bound, at_bound == 1 ? "" : "s");
}

int cli_fit_main(int argc, char *argv[])
{
    const char *data = NULL;
    int fit_radius = 0, fit_all = 0, refine = 0;
    const cli_opt own[] = {
        {.name = "data", .kind = CLI_STRING, .dst = &data, .input = CLI_INPUT_DIR},
        {.name = "fit-radius", .kind = CLI_FLAG, .dst = &fit_radius},
        {.name = "all", .kind = CLI_FLAG, .dst = &fit_all},
        {.name = "check-refinement", .kind = CLI_FLAG, .dst = &refine},
        {.name = NULL},
    };
    const cli_parser p = {.name = "fit", .usage = usage, .opts = own,
                          .groups = CLI_TIRE | CLI_METHOD | CLI_MODEL | CLI_OUTPUT |
                                    CLI_JOBS};
    cli_options o;
    const int parsed = cli_parse(&p, argc, argv, &o);
    if (parsed != CLI_GO_ON)
        return parsed;
    tirenv_fit_settings fs = tirenv_fit_default();
    fs.type = o.type ? o.type : tirenv_model_springs;
    fs.fit_R0 = fit_radius || fit_all;
    fs.progress = progress;
    fs.jobs = o.jobs;
    const char *out = o.output;
    const unsigned flags = tirenv_model_type_flags(fs.type);
    if (!(flags & TIRENV_MODEL_FITTABLE)) {
        fprintf(stderr, "tirenv: fit: --model %s has no parameters tirenv fits; expected one of",
                tirenv_model_type_name(fs.type));
        for (const tirenv_model_type *const *t = tirenv_model_types(); *t; ++t)
            if (tirenv_model_type_flags(*t) & TIRENV_MODEL_FITTABLE)
                fprintf(stderr, " %s", tirenv_model_type_name(*t));
        fputc('\n', stderr);
        return CLI_EXIT_USAGE;
    }
    if (refine && fs.type != tirenv_model_springs) {
        cli_error("fit: --check-refinement halves ELEMENT_ANGLE, the discretisation of the "
                  "springs model; the %s model has none", tirenv_model_type_name(fs.type));
        return CLI_EXIT_USAGE;
    }
    if (fit_radius && fs.type != tirenv_model_springs) {
        cli_error("fit: --fit-radius fits the springs model's UNLOADED_RADIUS; for the %s "
                  "model --all fits its optional parameters", tirenv_model_type_name(fs.type));
        return CLI_EXIT_USAGE;
    }
    if (!data) {
        cli_error("fit: --data DIR is required");
        return CLI_EXIT_USAGE;
    }
    /* The tire that simulated the data, if the data set says (its source.txt). */
    tirenv_dataset_source src;
    char tire_buf[1024];
    tirenv_tire tire;
    tirenv_dataset ds;
    o.runs[o.n_runs++] = fs.type;
    int code = cli_data_and_tire(data, &o, &src, tire_buf, sizeof tire_buf, &tire, &ds);
    if (code)
        return code;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_fit_report rep;
    int status = tirenv_fit(&ds, TIRENV_SPLIT_TRAIN, &fs, &tire, &rep, &diag);
    if (isatty(STDERR_FILENO))
        fputc('\n', stderr);
    if (status) {
        tirenv_dataset_free(&ds);
        return cli_fail(status, &diag);
    }
    printf("%s model identified on the training cases of %s\n", tirenv_model_type_name(fs.type),
           data);
    print_report("fit", &rep);
    double change = 0, sq_change = 0;
    size_t n_change = 0;
    tirenv_tire fine = tire;
    if (refine) {
        fine.springs.dphi = 0.5 * tire.springs.dphi;
        tirenv_fit_report rep2;
        status = tirenv_fit(&ds, TIRENV_SPLIT_TRAIN, &fs, &fine, &rep2, &diag);
        if (status) {
            tirenv_dataset_free(&ds);
            return cli_fail(status, &diag);
        }
        print_report("refit with ELEMENT_ANGLE halved", &rep2);
    }
    for (int split = TIRENV_SPLIT_TRAIN; split <= TIRENV_SPLIT_VALIDATION && !code; ++split)
        code = print_cases(&ds, fs.type, &tire, (tirenv_split)split, refine ? &fine : NULL,
                           &change, &sq_change, &n_change);
    if (refine && !code && n_change)
        printf("change of the fitted curves when ELEMENT_ANGLE is halved, over all %zu "
               "points: rms %.3f mm, largest %.3f mm\n", n_change,
               1e3 * sqrt(sq_change / (double)n_change), 1e3 * change);
    if (!code && out) {
        if ((status = tirenv_tir_write(out, &tire, &diag)))
            code = cli_fail(status, &diag);
        else
            fprintf(stderr, "tirenv: fit: fitted tire written to %s\n", out);
    }
    tirenv_dataset_free(&ds);
    return code;
}
