/* tirenv compare: every model against a data set's curves, as the paper's Table 3 and
 * Figure 5 do (docs/models.md section 8): plots, error tables, timing and a report.
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "tirenv/nn.h"
#include "tirenv/study.h"
#include "tirenv/nn_file.h"

enum { MAX_CASES = 256 };

static void usage(FILE *fp)
{
    fputs("usage: tirenv compare [--data DIR] [--tire FITTED.tir] [--nn MODEL.json]\n"
          "                      [--cases F,J,R | --split NAME] [--simulated-by MODEL]\n"
          "                      [--simulated] [-o REPORT_DIR] [--models LIST]\n"
          "                      [--title TEXT] [--no-images] [--jobs N] [--set KEY=VALUE]...\n"
          "                      [--method M]\n"
          "\n"
          "Evaluates every model on the chosen cases of a data set and writes to\nREPORT_DIR:\n"
          "  <case>.png, <case>.svg  h (mm) over x_N: measured points, one line per model\n"
          "                          (drawn by gnuplot from <case>.dat and <case>.gp)\n"
          "  errors.csv, errors.md   per case and model: RMS, max, peak-height and\n"
          "                          first-rise errors in mm; mean RMS per model\n"
          "  timing.csv              per model the evaluation time per position, and its\n"
          "                          ratio to the network's\n"
          "  report.md               all of it, with what the numbers say\n"
          "The physical models are driven by each case's load, the network by its contact\n"
          "length, as in the paper.\n"
          "\n"
          "options:\n"
          "  --data DIR           data set (a directory with cases.csv); default: the\n"
          "                       embedded one, dataset in the data directory ($TIRENV_DATA,\n"
          "                       else the installed data; 'tirenv --help'). When its\n"
          "                       source.txt names the model that simulated it (tirenv\n"
          "                       dataset build), or its sweep.txt does (tirenv sweep, no\n"
          "                       tire key set), that model is compared as the reference\n"
          "                       and its tire is the default --tire; a sweep over tire\n"
          "                       keys needs --simulated-by or --simulated\n"
          "  --nn MODEL.json      the trained network (tirenv train); without it the\n"
          "                       network is left out\n"
          "  --cases LIST         comma-separated case names, e.g. F,J,R\n"
          "  --split NAME         all cases of a split: train, control or validation\n"
          "                       (default: validation)\n"
          "  --simulated-by MODEL the data were simulated by this model (e.g. ring): say so\n"
          "                       in every output and compare that model too\n"
          "  --simulated          the data are simulated, by a model tirenv does not have\n"
          "  --models LIST        models to compare, comma-separated, from:\n"
          "                      ",
          fp);
    for (const tirenv_model_type *const *t = tirenv_model_types(); *t; ++t)
        fprintf(fp, " %s", tirenv_model_type_name(*t));
    fputs("\n"
          "                       (default: rigid,springs,nn; nn needs --nn)\n"
          "  --title TEXT         headline of the report\n"
          "  --no-images          write the gnuplot scripts but do not run gnuplot\n"
          "  -o, --output DIR     report directory, created if missing\n"
          "                       (default out/compare)\n",
          fp);
    cli_help_jobs(fp);
    cli_help_tire_as(fp, 1, "RADIAL_STIFFNESS=4.5e5 (the springs model's)",
                     cli_help_data_tire);
    fputs("  -h, --help           show this help\n", fp);
}

typedef struct {
    const char *data;
    int have_cases, have_split;
    char *case_list;                  /* a copy of --cases, cut at the commas */
    const char *case_names[MAX_CASES];
    tirenv_compare_settings s;
} compare_options;

/* "F,J,R" into names, in place; empty names are refused. */
static int parse_cases(void *dst, const char *arg)
{
    compare_options *co = dst;
    co->have_cases = 1;
    co->case_list = malloc(strlen(arg) + 1);
    if (!co->case_list) {
        cli_error("out of memory");
        return CLI_EXIT_DATA;
    }
    strcpy(co->case_list, arg);
    size_t n = 0;
    for (char *p = co->case_list;;) {
        char *comma = strchr(p, ',');
        if (comma)
            *comma = '\0';
        if (!*p || n == MAX_CASES) {
            cli_error("--cases: expected up to %d comma-separated case names, got '%s'",
                      MAX_CASES, arg);
            return CLI_EXIT_USAGE;
        }
        co->case_names[n++] = p;
        if (!comma)
            break;
        p = comma + 1;
    }
    co->s.cases = co->case_names;
    co->s.n_cases = n;
    return CLI_EXIT_OK;
}

static int parse_split(void *dst, const char *arg)
{
    compare_options *co = dst;
    const tirenv_split splits[] = {TIRENV_SPLIT_TRAIN, TIRENV_SPLIT_CONTROL,
                                   TIRENV_SPLIT_VALIDATION};
    co->have_split = 1;
    for (size_t k = 0; k < sizeof splits / sizeof splits[0]; ++k)
        if (strcmp(arg, tirenv_split_name(splits[k])) == 0) {
            co->s.split = splits[k];
            return CLI_EXIT_OK;
        }
    cli_error("--split: expected train, control or validation, got '%s'", arg);
    return CLI_EXIT_USAGE;
}

/* "rigid,springs,nn": model types by their names; the list replaces the default, network
 * included. */
static int parse_models(void *dst, const char *arg)
{
    compare_options *co = dst;
    co->s.with_nn = 0;
    return cli_model_list("--models", arg, co->s.models,
                          sizeof co->s.models / sizeof co->s.models[0], &co->s.n_models);
}

static int parse_simulated_by(void *dst, const char *arg)
{
    compare_options *co = dst;
    co->s.simulated = 1;
    return cli_model_type("--simulated-by", arg, &co->s.simulated_by);
}

/* Parses the options; returns an exit code, or CLI_GO_ON. */
static int parse(int argc, char *argv[], cli_options *o, compare_options *co)
{
    int simulated = 0, no_images = 0;
    const cli_opt own[] = {
        {.name = "data", .kind = CLI_STRING, .dst = &co->data, .input = CLI_INPUT_DIR},
        {.name = "cases", .kind = CLI_CUSTOM, .dst = co, .parse = parse_cases},
        {.name = "split", .kind = CLI_CUSTOM, .dst = co, .parse = parse_split},
        {.name = "simulated-by", .kind = CLI_CUSTOM, .dst = co, .parse = parse_simulated_by},
        {.name = "simulated", .kind = CLI_FLAG, .dst = &simulated},
        {.name = "models", .kind = CLI_CUSTOM, .dst = co, .parse = parse_models},
        {.name = "title", .kind = CLI_STRING, .dst = &co->s.title},
        {.name = "no-images", .kind = CLI_FLAG, .dst = &no_images},
        {.name = NULL},
    };
    const cli_parser p = {.name = "compare", .usage = usage, .opts = own,
                          .groups = CLI_TIRE | CLI_METHOD | CLI_OUTPUT | CLI_NETWORK |
                                    CLI_JOBS};
    const int code = cli_parse(&p, argc, argv, o);
    if (code != CLI_GO_ON)
        return code;
    co->s.jobs = o->jobs;
    co->s.simulated |= simulated;
    if (no_images)
        co->s.images = 0;
    if (o->output)
        co->s.out_dir = o->output;
    for (size_t k = 0; k < co->s.n_models; ++k)
        if ((tirenv_model_type_flags(co->s.models[k]) & TIRENV_MODEL_NEEDS_NETWORK) &&
            !o->nn_path) {
            cli_error("compare: --models lists %s; expected --nn MODEL.json",
                      tirenv_model_type_name(co->s.models[k]));
            return CLI_EXIT_USAGE;
        }
    if (co->have_cases && co->have_split) {
        cli_error("compare: expected --cases or --split, not both");
        return CLI_EXIT_USAGE;
    }
    return CLI_GO_ON;
}

/* One line per model a reader can act on: the mean RMS error and the speed. */
static void summary(const compare_options *co, const tirenv_compare_result *r)
{
    printf("tirenv compare: %zu case%s x %zu model%s%s; mean RMS error:", r->n_cases,
           r->n_cases == 1 ? "" : "s", r->n_models, r->n_models == 1 ? "" : "s",
           co->s.simulated ? " (SIMULATED data)" : "");
    for (size_t j = 0; j < r->n_models; ++j) {
        double sum = 0;
        size_t n = 0;
        for (size_t i = 0; i < r->n_cases; ++i) {
            const tirenv_compare_entry *e = &r->entry[i * r->n_models + j];
            if (!e->status) {
                sum += e->errors.rms;
                ++n;
            }
        }
        if (n == r->n_cases)
            printf(" %s %.2f mm%s", r->model[j], 1e3 * sum / (double)n,
                   j + 1 < r->n_models ? "," : "");
        else if (n)
            printf(" %s %.2f mm (%zu of %zu cases)%s", r->model[j], 1e3 * sum / (double)n, n,
                   r->n_cases, j + 1 < r->n_models ? "," : "");
        else
            printf(" %s failed%s", r->model[j], j + 1 < r->n_models ? "," : "");
    }
    printf("\nreport: %s/report.md\n", co->s.out_dir);
}

/* The data set (--data, else the embedded one) and what simulated it, with which tire, if it
 * says (its source.txt, as tirenv dataset build writes it for the embedded sets): the
 * reference, unless the command line names one. */
static int data_and_source(compare_options *co, cli_options *o, char data_buf[1024],
                           char src_tire[1024])
{
    if (!co->data)
        co->data = cli_data_path("dataset", data_buf, 1024);
    tirenv_dataset_source src;
    int code;
    if ((code = cli_data_source(co->data, o, &src, src_tire, 1024)) ||
        (!co->s.simulated &&
         (code = cli_sweep_reference("compare", co->data, &src,
                                     "--simulated-by MODEL with --tire FILE, or --simulated"))))
        return code;
    if (src.model[0] && !co->s.simulated_by && !co->s.simulated) {
        co->s.simulated_by = tirenv_model_type_find(src.model);
        co->s.simulated = 1;
        co->s.simulated_raw = src.sweep_raw;
    }
    return CLI_EXIT_OK;
}

/* The models run on the tire, for --set's warnings: each model compared and the one that
 * simulated the data (the reference, evaluated beside them), each at the case's load (the
 * network at its contact length: the springs model is counted for it all the same), which is
 * what cli_tire counts for each of o->runs, compare having no --contact-length. */
static void models_run(const compare_options *co, cli_options *o)
{
    for (size_t k = 0; k <= co->s.n_models && o->n_runs < CLI_MAX_RUNS; ++k) {
        const tirenv_model_type *t = k < co->s.n_models ? co->s.models[k] : co->s.simulated_by;
        size_t j = 0;
        while (j < o->n_runs && o->runs[j] != t)
            ++j;
        if (t && j == o->n_runs)
            o->runs[o->n_runs++] = t;
    }
}

/* The tire; the cam of a tire file without MF-Swift's shape keys would be the default
 * tire's. */
static int read_tire(const compare_options *co, cli_options *o, tirenv_tire *tire)
{
    int code = cli_tire(o, tire);
    for (size_t k = 0; k <= co->s.n_models && !code; ++k)
        code = cli_cam_keys(k < co->s.n_models ? co->s.models[k] : co->s.simulated_by, tire,
                            co->s.tire_label);
    return code;
}

/* The data set with the tire's radius, and --nn's network with the radius it was trained at
 * (into co's settings). */
static int read_data(compare_options *co, const cli_options *o, double R0, tirenv_dataset *ds,
                     int *have_ds, tirenv_nn **nn, tirenv_diag *diag)
{
    int status = tirenv_dataset_read(co->data, R0, ds, diag);
    *have_ds = status == TIRENV_OK;
    if (!status && o->nn_path) {
        tirenv_train_record rec;
        status = tirenv_nn_read_json(o->nn_path, nn, &rec, diag);
        if (!status)
            co->s.nn_R0 = rec.R0;
    }
    return status;
}

/* The comparison and its report into the output directory, written as a whole
 * (tirenv_outdir): a failed or killed comparison leaves the previous one as it was. Where
 * only gnuplot failed, everything but the images is written, and then what failed is said.
 * An exit code. */
static int write_comparison(compare_options *co, const tirenv_dataset *ds,
                            const tirenv_tire *tire, tirenv_nn *nn, tirenv_compare_result *r,
                            tirenv_diag *diag)
{
    const char *out_dir = co->s.out_dir;
    tirenv_outdir *staged = NULL;
    int status = tirenv_outdir_begin(out_dir, &staged, diag);
    if (!status)
        co->s.out_dir = tirenv_outdir_path(staged);
    if (!status)
        status = tirenv_compare(ds, tire, nn, &co->s, r, diag);
    if (!status)
        status = tirenv_compare_report(ds, &co->s, r, NULL, diag);
    if (status == TIRENV_EIO && strcmp(diag->field, "gnuplot") == 0 && r->entry) {
        tirenv_diag report_diag;
        tirenv_diag_clear(&report_diag);
        const int code = cli_fail(status, diag);
        if (tirenv_compare_report(ds, &co->s, r, NULL, &report_diag) == TIRENV_OK &&
            tirenv_outdir_commit(staged, &report_diag) == TIRENV_OK)
            cli_error("compare: tables and report written to %s without images "
                      "(--no-images skips gnuplot)", out_dir);
        else
            tirenv_outdir_abort(staged);
        return code;
    }
    co->s.out_dir = out_dir;
    if (!status && staged) {
        status = tirenv_outdir_commit(staged, diag);
        staged = NULL;
    }
    tirenv_outdir_abort(staged);
    return status ? cli_fail(status, diag) : CLI_EXIT_OK;
}

int cli_compare_main(int argc, char *argv[])
{
    cli_options o;
    compare_options co = {.s = tirenv_compare_default()};
    int code = parse(argc, argv, &o, &co);
    if (code != CLI_GO_ON) {
        free(co.case_list);
        return code;
    }
    char data_buf[1024], tire_buf[1024], src_tire[1024];
    if ((code = data_and_source(&co, &o, data_buf, src_tire))) {
        free(co.case_list);
        return code;
    }
    co.s.data_label = co.data;
    co.s.tire_label = cli_tire_path(&o, tire_buf, sizeof tire_buf);
    co.s.nn_label = o.nn_path;
    models_run(&co, &o);

    tirenv_tire tire;
    tirenv_dataset ds = {0};
    int have_ds = 0;
    tirenv_nn *nn = NULL;
    tirenv_compare_result r = {0};
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (!(code = read_tire(&co, &o, &tire))) {
        const int status = read_data(&co, &o, tire.springs.R0, &ds, &have_ds, &nn, &diag);
        code = status ? cli_fail(status, &diag)
                      : write_comparison(&co, &ds, &tire, nn, &r, &diag);
        if (!code)
            summary(&co, &r);
    }
    tirenv_compare_result_free(&r);
    tirenv_nn_free(nn);
    if (have_ds)
        tirenv_dataset_free(&ds);
    free(co.case_list);
    return code;
}
