/* tirenv fit: identify the physical model's stiffnesses on a data set's training cases.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "cli/cli.h"
#include "tirenv/study.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv fit --data DIR [--model springs|cam] [--fit-radius]\n"
          "                  [--check-refinement] [-o FITTED.tir] [--jobs N] [--tire FILE]\n"
          "                  [--set K=V]...\n"
          "\n"
          "Identifies RADIAL_STIFFNESS and INTERRADIAL_STIFFNESS (and UNLOADED_RADIUS with\n"
          "--fit-radius) of the springs model, or ELLIPS_SHIFT, ELLIPS_LENGTH, ELLIPS_HEIGHT\n"
          "and ELLIPS_ORDER of the cam model, on the data set's training cases by nonlinear\n"
          "least squares on h (GSL multifit_nlinear), starting from the tire file, and\n"
          "reports standard errors and the fit per case. The discretisation (ELEMENT_ANGLE) is a setting, not a\n"
          "fitted parameter: --check-refinement refits with it halved and reports how much\n"
          "the parameters and the fitted curves change.\n"
          "\n"
          "options:\n"
          "  --data DIR           data set directory with cases.csv\n"
          "  --model NAME         model to identify: springs (default) or cam\n"
          "  --fit-radius         also fit UNLOADED_RADIUS\n"
          "  --check-refinement   refit with ELEMENT_ANGLE / 2 and compare\n"
          "  -o FILE              write the fitted tire (.tir); default: print only\n",
          fp);
    cli_help_jobs(fp);
    cli_help_tire(fp, 1);
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
    for (size_t i = 0; i < r->n_params; ++i)
        printf("  %-22s = %.6g +- %.2g (1 sigma)\n", r->names[i], r->value[i], r->std_error[i]);
}

int cli_fit_main(int argc, char *argv[])
{
    enum { OPT_DATA = CLI_OPT_FIRST_OWN, OPT_MODEL, OPT_RADIUS, OPT_REFINE };
    static const struct option longopts[] = {
        CLI_TIRE_LONGOPTS,
        CLI_METHOD_LONGOPTS,
        {"data", required_argument, NULL, OPT_DATA},
        {"model", required_argument, NULL, OPT_MODEL},
        {"fit-radius", no_argument, NULL, OPT_RADIUS},
        {"check-refinement", no_argument, NULL, OPT_REFINE},
        CLI_JOBS_LONGOPT,
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    cli_options o;
    cli_options_init(&o);
    tirenv_fit_settings fs = tirenv_fit_default();
    fs.type = tirenv_model_springs;
    fs.progress = progress;
    fs.jobs = cli_jobs_default();
    const char *data = NULL, *out = NULL;
    int refine = 0, c;
    cli_getopt_reset();
    while ((c = getopt_long(argc, argv, "ho:", longopts, NULL)) != -1) {
        switch (c) {
        case 'h':
            usage(stdout);
            return CLI_EXIT_OK;
        case 'o':
            out = optarg;
            break;
        case OPT_DATA:
            data = optarg;
            break;
        case OPT_MODEL:
            if (cli_model_type(optarg, &fs.type))
                return CLI_EXIT_USAGE;
            if (fs.type != tirenv_model_springs && fs.type != tirenv_model_cam) {
                cli_error("fit: --model %s has no parameters tirenv fits; expected springs or "
                          "cam (the ring is the reference tire)", optarg);
                return CLI_EXIT_USAGE;
            }
            break;
        case OPT_RADIUS:
            fs.fit_R0 = 1;
            break;
        case OPT_REFINE:
            refine = 1;
            break;
        case CLI_OPT_JOBS:
            if (cli_parse_jobs("fit", optarg, &fs.jobs))
                return CLI_EXIT_USAGE;
            break;
        case '?':
            usage(stderr);
            return CLI_EXIT_USAGE;
        default:
            if (cli_option(&o, c, optarg))
                return CLI_EXIT_USAGE;
        }
    }
    if (refine && fs.type != tirenv_model_springs) {
        cli_error("fit: --check-refinement halves ELEMENT_ANGLE, a springs-model setting; the "
                  "cam has no discretisation");
        return CLI_EXIT_USAGE;
    }
    if (optind < argc || !data) {
        cli_error(data ? "fit: unexpected argument '%s'" : "fit: --data DIR is required%s",
                  data ? argv[optind] : "");
        return CLI_EXIT_USAGE;
    }
    tirenv_tire tire;
    int code = cli_tire(&o, &tire);
    if (code)
        return code;
    tirenv_dataset ds;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    int status = tirenv_dataset_read(data, tire.springs.R0, &ds, &diag);
    if (status)
        return cli_fail(status, &diag);
    tirenv_fit_report rep;
    status = tirenv_fit(&ds, TIRENV_SPLIT_TRAIN, &fs, &tire, &rep, &diag);
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
