/* tirenv compare: every model against a data set's curves, as the paper's Table 3 and
 * Figure 5 do (docs/models.md section 8): plots, error tables, timing and a report.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "tirenv/nn.h"
#include "tirenv/study.h"
#include "tirenv/train.h"

enum { MAX_CASES = 256 };

static void usage(FILE *fp)
{
    fputs("usage: tirenv compare [--data DIR] [--tire FITTED.tir] [--nn MODEL.json]\n"
          "                      [--cases F,J,R | --split NAME] [--simulated-by MODEL]\n"
          "                      [-o REPORT_DIR] [--models LIST] [--no-images] [--jobs N]\n"
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
          "                       else the installed data; 'tirenv --help'),\n"
          "                       whose data are simulated by the ring reference tire\n"
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
    fputs(" nn\n"
          "                       (default: rigid,springs,nn)\n"
          "  --title TEXT         headline of the report\n"
          "  --no-images          write the gnuplot scripts but do not run gnuplot\n"
          "  -o, --output DIR     report directory, created if missing\n"
          "                       (default out/compare)\n",
          fp);
    cli_help_jobs(fp);
    cli_help_tire(fp, 1);
    fputs("  -h, --help           show this help\n", fp);
}

typedef struct {
    const char *data;
    const char *nn_path;
    int nn_listed;                    /* --models names nn */
    char *case_list;                  /* a copy of --cases, cut at the commas */
    const char *case_names[MAX_CASES];
    tirenv_compare_settings s;
} compare_options;

/* "F,J,R" into names, in place; empty names are refused. */
static int parse_cases(compare_options *co, const char *arg)
{
    free(co->case_list);
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

static int parse_split(compare_options *co, const char *arg)
{
    const tirenv_split splits[] = {TIRENV_SPLIT_TRAIN, TIRENV_SPLIT_CONTROL,
                                   TIRENV_SPLIT_VALIDATION};
    for (size_t k = 0; k < sizeof splits / sizeof splits[0]; ++k)
        if (strcmp(arg, tirenv_split_name(splits[k])) == 0) {
            co->s.split = splits[k];
            return CLI_EXIT_OK;
        }
    cli_error("--split: expected train, control or validation, got '%s'", arg);
    return CLI_EXIT_USAGE;
}

/* "rigid,springs,nn": physical models by their names, and "nn" for the network. */
static int parse_models(compare_options *co, const char *arg)
{
    co->s.n_models = 0;
    co->s.with_nn = 0;
    const char *p = arg;
    for (;;) {
        const size_t len = strcspn(p, ",");
        char name[32];
        if (len == 0 || len >= sizeof name) {
            cli_error("--models: expected comma-separated model names, got '%s'", arg);
            return CLI_EXIT_USAGE;
        }
        memcpy(name, p, len);
        name[len] = '\0';
        if (strcmp(name, "nn") == 0) {
            co->s.with_nn = co->nn_listed = 1;
        } else {
            const tirenv_model_type *type;
            if (cli_model_type(name, &type))
                return CLI_EXIT_USAGE;
            if (co->s.n_models == sizeof co->s.models / sizeof co->s.models[0]) {
                cli_error("--models: too many models in '%s'", arg);
                return CLI_EXIT_USAGE;
            }
            co->s.models[co->s.n_models++] = type;
        }
        if (!p[len])
            break;
        p += len + 1;
    }
    return CLI_EXIT_OK;
}

/* Parses the options; returns an exit code, or -1 to go on. */
static int parse(int argc, char *argv[], cli_options *o, compare_options *co)
{
    enum {
        OPT_DATA = CLI_OPT_FIRST_OWN,
        OPT_NN,
        OPT_CASES,
        OPT_SPLIT,
        OPT_SIMULATED_BY,
        OPT_SIMULATED,
        OPT_MODELS,
        OPT_TITLE,
        OPT_NO_IMAGES
    };
    static const struct option longopts[] = {
        CLI_TIRE_LONGOPTS,
        CLI_METHOD_LONGOPTS,
        {"data", required_argument, NULL, OPT_DATA},
        {"nn", required_argument, NULL, OPT_NN},
        {"cases", required_argument, NULL, OPT_CASES},
        {"split", required_argument, NULL, OPT_SPLIT},
        {"simulated-by", required_argument, NULL, OPT_SIMULATED_BY},
        {"simulated", no_argument, NULL, OPT_SIMULATED},
        {"models", required_argument, NULL, OPT_MODELS},
        {"title", required_argument, NULL, OPT_TITLE},
        {"no-images", no_argument, NULL, OPT_NO_IMAGES},
        {"output", required_argument, NULL, 'o'},
        CLI_JOBS_LONGOPT,
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    int c, have_cases = 0, have_split = 0, code;
    cli_getopt_reset();
    while ((c = getopt_long(argc, argv, "ho:", longopts, NULL)) != -1) {
        switch (c) {
        case 'h':
            usage(stdout);
            return CLI_EXIT_OK;
        case 'o':
            co->s.out_dir = optarg;
            break;
        case OPT_DATA:
            co->data = optarg;
            break;
        case OPT_NN:
            co->nn_path = optarg;
            break;
        case OPT_CASES:
            have_cases = 1;
            if ((code = parse_cases(co, optarg)))
                return code;
            break;
        case OPT_SPLIT:
            have_split = 1;
            if ((code = parse_split(co, optarg)))
                return code;
            break;
        case OPT_SIMULATED_BY:
            if (cli_model_type(optarg, &co->s.simulated_by))
                return CLI_EXIT_USAGE;
            co->s.simulated = 1;
            break;
        case OPT_SIMULATED:
            co->s.simulated = 1;
            break;
        case OPT_MODELS:
            if ((code = parse_models(co, optarg)))
                return code;
            break;
        case OPT_TITLE:
            co->s.title = optarg;
            break;
        case OPT_NO_IMAGES:
            co->s.images = 0;
            break;
        case CLI_OPT_JOBS:
            if (cli_parse_jobs("compare", optarg, &co->s.jobs))
                return CLI_EXIT_USAGE;
            break;
        case '?':
            usage(stderr);
            return CLI_EXIT_USAGE;
        default:
            if (cli_option(o, c, optarg))
                return CLI_EXIT_USAGE;
        }
    }
    if (optind < argc) {
        cli_error("compare: unexpected argument '%s'", argv[optind]);
        return CLI_EXIT_USAGE;
    }
    if (co->nn_listed && !co->nn_path) {
        cli_error("compare: --models lists nn; expected --nn MODEL.json");
        return CLI_EXIT_USAGE;
    }
    if (have_cases && have_split) {
        cli_error("compare: expected --cases or --split, not both");
        return CLI_EXIT_USAGE;
    }
    return -1;
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

int cli_compare_main(int argc, char *argv[])
{
    cli_options o;
    cli_options_init(&o);
    compare_options co = {.s = tirenv_compare_default()};
    co.s.jobs = cli_jobs_default();
    int code = parse(argc, argv, &o, &co);
    if (code >= 0) {
        free(co.case_list);
        return code;
    }
    char data_buf[1024], tire_buf[1024];
    if (!co.data) {
        /* The embedded data set, simulated on the ring reference tire
         * (docs/models.md section 5). */
        co.data = cli_data_path("dataset", data_buf, sizeof data_buf);
        if (!co.s.simulated_by)
            co.s.simulated_by = tirenv_model_ring;
        co.s.simulated = 1;
    }
    co.s.data_label = co.data;
    co.s.tire_label = cli_tire_path(&o, tire_buf, sizeof tire_buf);
    co.s.nn_label = co.nn_path;

    tirenv_tire tire;
    tirenv_dataset ds = {0};
    int have_ds = 0;
    tirenv_nn *nn = NULL;
    tirenv_compare_result r = {0};
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if ((code = cli_tire(&o, &tire)))
        goto done;
    int status = tirenv_dataset_read(co.data, tire.springs.R0, &ds, &diag);
    have_ds = status == TIRENV_OK;
    if (!status && co.nn_path) {
        tirenv_train_record rec;
        status = tirenv_nn_read_json(co.nn_path, &nn, &rec, &diag);
        if (!status)
            co.s.nn_R0 = rec.R0;
    }
    if (!status)
        status = tirenv_compare(&ds, &tire, nn, &co.s, &r, &diag);
    if (!status)
        status = tirenv_compare_report(&ds, &co.s, &r, NULL, &diag);
    if (status == TIRENV_EIO && strcmp(diag.field, "gnuplot") == 0 && r.entry) {
        /* Everything but the images is written: finish the report, then say what failed. */
        tirenv_diag report_diag;
        tirenv_diag_clear(&report_diag);
        code = cli_fail(status, &diag);
        if (tirenv_compare_report(&ds, &co.s, &r, NULL, &report_diag) == TIRENV_OK)
            cli_error("compare: tables and report written to %s without images "
                      "(--no-images skips gnuplot)", co.s.out_dir);
        goto done;
    }
    if (status) {
        code = cli_fail(status, &diag);
        goto done;
    }
    summary(&co, &r);
    code = CLI_EXIT_OK;
done:
    tirenv_compare_result_free(&r);
    tirenv_nn_free(nn);
    if (have_ds)
        tirenv_dataset_free(&ds);
    free(co.case_list);
    return code;
}
