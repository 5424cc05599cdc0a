/* tirenv study: the paper's study in one command (identify, train, compare), as make demo
 * runs it on the embedded data set. SPDX-License-Identifier: GPL-3.0-or-later */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "tirenv/study.h"
#include "tirenv/train.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv study [--data DIR] [-o REPORT_DIR] [--trainer lm|rprop|backprop]\n"
          "                    [--seed S] [--measured | --simulated-by ring] [--no-images]\n"
          "                    [--jobs N] [--tire FILE] [--set KEY=VALUE]...\n"
          "\n"
          "The paper's study in one command: identifies the springs model and the tandem cam\n"
          "on the data set's training cases (tirenv fit), trains the 4-8-1 network with\n"
          "early stopping on the control cases (tirenv train), and compares rigid, springs,\n"
          "cam, the network (and the ring reference tire when it simulated the data) on the\n"
          "validation cases, with a plot per case in the manner of the paper's Figure 5,\n"
          "error tables, timings and report.md. Then the paper's proposed workflow (a\n"
          "network trained on the identified physical model's curves) and obstacles outside\n"
          "the training range.\n"
          "\n"
          "options:\n"
          "  --data DIR           data set with cases.csv (default: the embedded, SIMULATED one)\n"
          "  -o DIR               report directory (default out/study)\n"
          "  --trainer NAME       network trainer (default lm)\n"
          "  --seed S             training seed (default 1)\n"
          "  --simulated-by ring  the data were simulated by the ring tire (default for the\n"
          "                       embedded data set; then the ring is compared too)\n"
          "  --measured           the data are real measurements\n"
          "  --no-images          write the gnuplot scripts but do not run gnuplot\n",
          fp);
    cli_help_jobs(fp);
    cli_help_tire(fp, 1);
    fputs("  -h, --help           show this help\n", fp);
}

/* One line per stage on a terminal, redrawn in place; silent otherwise. */
static void progress(void *ctx, const char *stage, size_t step, size_t steps)
{
    const double *t0 = ctx;
    if (!isatty(STDERR_FILENO))
        return;
    fprintf(stderr, "\r\033[Ktirenv: study: [%zu/%zu] %s (%.1f s)%s", step, steps, stage,
            cli_wall_seconds() - *t0, step == steps ? "\n" : "");
}

int cli_study_main(int argc, char *argv[])
{
    enum { OPT_DATA = CLI_OPT_FIRST_OWN, OPT_TRAINER, OPT_SEED, OPT_SIMULATED, OPT_MEASURED,
           OPT_NO_IMAGES };
    static const struct option longopts[] = {
        CLI_TIRE_LONGOPTS,
        CLI_METHOD_LONGOPTS,
        {"data", required_argument, NULL, OPT_DATA},
        {"trainer", required_argument, NULL, OPT_TRAINER},
        {"seed", required_argument, NULL, OPT_SEED},
        {"simulated-by", required_argument, NULL, OPT_SIMULATED},
        {"measured", no_argument, NULL, OPT_MEASURED},
        {"no-images", no_argument, NULL, OPT_NO_IMAGES},
        CLI_JOBS_LONGOPT,
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    cli_options o;
    cli_options_init(&o);
    tirenv_study_settings s = tirenv_study_default();
    s.jobs = cli_jobs_default();
    char data_buf[1024];
    s.data_dir = cli_data_path("dataset", data_buf, sizeof data_buf);
    int data_given = 0, sim_given = 0, c;
    long seed;
    cli_getopt_reset();
    while ((c = getopt_long(argc, argv, "ho:", longopts, NULL)) != -1) {
        switch (c) {
        case 'h':
            usage(stdout);
            return CLI_EXIT_OK;
        case 'o':
            s.out_dir = optarg;
            break;
        case OPT_DATA:
            s.data_dir = optarg;
            data_given = 1;
            break;
        case OPT_TRAINER:
            s.trainer = optarg;
            break;
        case OPT_SEED:
            if (cli_parse_count(optarg, 0, 2147483647L, &seed)) {
                cli_error("study: --seed expects a whole number >= 0, got '%s'", optarg);
                return CLI_EXIT_USAGE;
            }
            s.seed = (unsigned long)seed;
            break;
        case OPT_SIMULATED:
            if (strcmp(optarg, "ring") != 0) {
                cli_error("study: --simulated-by expects 'ring', got '%s'", optarg);
                return CLI_EXIT_USAGE;
            }
            s.simulated_by_ring = sim_given = 1;
            break;
        case OPT_MEASURED:
            s.simulated_by_ring = 0;
            sim_given = 1;
            break;
        case OPT_NO_IMAGES:
            s.images = 0;
            break;
        case CLI_OPT_JOBS:
            if (cli_parse_jobs("study", optarg, &s.jobs))
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
    if (optind < argc) {
        cli_error("study: unexpected argument '%s'", argv[optind]);
        return CLI_EXIT_USAGE;
    }
    if (!tirenv_trainer_type_find(s.trainer)) {
        cli_error("study: unknown trainer '%s'; expected lm, rprop or backprop", s.trainer);
        return CLI_EXIT_USAGE;
    }
    /* A user's own data set is taken as measured unless they say otherwise. */
    if (data_given && !sim_given)
        s.simulated_by_ring = 0;
    int code = cli_tire(&o, &s.tire);
    if (code)
        return code;
    char label[1024];
    s.tire_label = cli_tire_path(&o, label, sizeof label);
    double t0 = cli_wall_seconds();
    s.progress = progress;
    s.progress_ctx = &t0;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_study(&s, &diag);
    if (status)
        return cli_fail(status, &diag);
    printf("tirenv: study: report written to %s/report.md (%.1f s)\n", s.out_dir,
           cli_wall_seconds() - t0);
    return CLI_EXIT_OK;
}
