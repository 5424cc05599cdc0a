/* tirenv study: the paper's study in one command (identify, train, compare), as make demo
 * runs it on the embedded data set. SPDX-License-Identifier: GPL-3.0-or-later */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "tirenv/study.h"
#include "tirenv/train.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv study [--data DIR] [-o REPORT_DIR] [--trainer lm|rprop|backprop]\n"
          "                    [--seed S] [--seeds N] [--input even|paper]\n"
          "                    [--measured | --simulated-by ring] [--no-images] [--jobs N]\n"
          "                    [--tire FILE] [--set KEY=VALUE]...\n"
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
          "  --seed S             first training seed (default 1)\n"
          "  --seeds N            train the network with seeds S to S+N-1 (default 20) and\n"
          "                       report the median and quartiles of its validation error;\n"
          "                       nn.json, the tables and plots are the seed nearest the\n"
          "                       median, nn-seeds.csv has every seed\n"
          "  --input FORM         the network's input: even (default, the rounded distance\n"
          "                       from the obstacle centre: smooth over the centre) or\n"
          "                       paper (x_N, as in the paper)\n"
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

/* --simulated-by: the embedded data set's reference tire is the only simulator the study
 * knows how to compare (tirenv_study_settings.simulated_by_ring). */
static int parse_simulated_by(void *dst, const char *arg)
{
    const tirenv_model_type *type;
    if (cli_model_type(arg, &type))
        return CLI_EXIT_USAGE;
    if (type != tirenv_model_ring) {
        cli_error("study: --simulated-by expects 'ring', got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    *(int *)dst = 1;
    return CLI_EXIT_OK;
}

/* --input: the network's input form. */
static int parse_input(void *dst, const char *arg)
{
    const int f = tirenv_nn_input_form_find(arg);
    if (f < 0) {
        cli_error("study: --input expects even or paper, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    *(tirenv_nn_input_form *)dst = (tirenv_nn_input_form)f;
    return CLI_EXIT_OK;
}

int cli_study_main(int argc, char *argv[])
{
    tirenv_study_settings s = tirenv_study_default();
    char data_buf[1024];
    const char *data = NULL;
    long seed = (long)s.seed, seeds = (long)s.seeds;
    int by_ring = 0, measured = 0, no_images = 0;
    const cli_opt own[] = {
        {.name = "data", .kind = CLI_STRING, .dst = &data},
        {.name = "trainer", .kind = CLI_STRING, .dst = &s.trainer},
        {.name = "seed", .kind = CLI_COUNT, .dst = &seed, .min = 0, .max = 2147483647L,
         .what = "a whole number >= 0"},
        {.name = "simulated-by", .kind = CLI_CUSTOM, .dst = &by_ring,
         .parse = parse_simulated_by},
        {.name = "seeds", .kind = CLI_COUNT, .dst = &seeds, .min = 1, .max = 100000,
         .what = "a whole number from 1 to 100000"},
        {.name = "input", .kind = CLI_CUSTOM, .dst = &s.input, .parse = parse_input},
        {.name = "measured", .kind = CLI_FLAG, .dst = &measured},
        {.name = "no-images", .kind = CLI_FLAG, .dst = &no_images},
        {.name = NULL},
    };
    const cli_parser p = {.name = "study", .usage = usage, .opts = own,
                          .groups = CLI_TIRE | CLI_METHOD | CLI_OUTPUT | CLI_JOBS};
    cli_options o;
    const int parsed = cli_parse(&p, argc, argv, &o);
    if (parsed != CLI_GO_ON)
        return parsed;
    if (by_ring && measured) {
        cli_error("study: --measured and --simulated-by contradict each other: give one");
        return CLI_EXIT_USAGE;
    }
    s.data_dir = data ? data : cli_data_path("dataset", data_buf, sizeof data_buf);
    /* The embedded one is named as in the repository, not by this build's absolute path;
     * a path the user gave (--data, TIRENV_DATA) is theirs to see. */
    const char *env = getenv("TIRENV_DATA");
    s.data_label = data ? data : env && env[0] ? s.data_dir : "data/dataset";
    s.seed = (unsigned long)seed;
    s.seeds = (size_t)seeds;
    s.images = !no_images;
    s.jobs = o.jobs;
    if (o.output)
        s.out_dir = o.output;
    /* A user's own data set is taken as measured unless they say otherwise. */
    s.simulated_by_ring = by_ring || (!measured && !data);
    if (!tirenv_trainer_type_find(s.trainer)) {
        cli_error("study: unknown trainer '%s'; expected lm, rprop or backprop", s.trainer);
        return CLI_EXIT_USAGE;
    }
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
