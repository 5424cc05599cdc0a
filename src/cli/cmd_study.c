/* tirenv study: the paper's study in one command (identify, train, compare), as make demo
 * runs it on the embedded data set. SPDX-License-Identifier: Apache-2.0 */
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
          "                    [--measured | --simulated-by MODEL] [--no-images] [--jobs N]\n"
          "                    [--tire FILE] [--set KEY=VALUE]... [--method M]\n"
          "\n"
          "The paper's study in one command: identifies the springs model and the tandem cam\n"
          "on the data set's training cases (tirenv fit), trains the 4-8-1 network with\n"
          "early stopping on the control cases (tirenv train), and compares rigid, springs,\n"
          "cam, the network (and the model that simulated the data, as the reference) on the\n"
          "validation cases, with a plot per case in the manner of the paper's Figure 5,\n"
          "error tables, timings and report.md. Then the paper's proposed workflow (a\n"
          "network trained on the identified physical model's curves) and obstacles outside\n"
          "the training range. A data set's source.txt (as tirenv dataset build writes it)\n"
          "says which model simulated it and with which tire: that model is the reference,\n"
          "not fitted, and that tire is the tire unless --tire is given; so does a tirenv\n"
          "sweep's sweep.txt (its model, and its tire.tir when it set no tire key; one\n"
          "that did, or whose model is the network, is refused unless --simulated-by or\n"
          "--measured says what to compare against). A data set with neither is taken as\n"
          "measured.\n"
          "\n"
          "options:\n"
          "  --data DIR           data set with cases.csv (default: the embedded, SIMULATED\n"
          "                       tractor set; data/dataset-205-60R15 is the car tire's)\n"
          "  -o, --output DIR     report directory (default out/study)\n"
          "  --trainer NAME       network trainer (default lm)\n"
          "  --seed S             first training seed (default 1)\n"
          "  --seeds N            train the network with seeds S to S+N-1 (default 20) and\n"
          "                       report the median and quartiles of its validation error;\n"
          "                       nn.json, the tables and plots are the seed nearest the\n"
          "                       median, nn-seeds.csv has every seed\n"
          "  --input FORM         the network's input: even (default, the rounded distance\n"
          "                       from the obstacle centre: smooth over the centre) or\n"
          "                       paper (x_N, as in the paper)\n"
          "  --simulated-by MODEL the data were simulated by this model (ring, cam, ...),\n"
          "                       whatever the data set's source.txt says\n"
          "  --measured           the data are real measurements\n"
          "  --no-images          write the gnuplot scripts but do not run gnuplot\n",
          fp);
    cli_help_jobs(fp);
    cli_help_tire_as(fp, 1, "UNLOADED_RADIUS=0.69 (every model's)", cli_help_data_tire);
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

/* --simulated-by: any physical model the virtual rig can run. */
static int parse_simulated_by(void *dst, const char *arg)
{
    const tirenv_model_type *type;
    if (cli_model_type("study: --simulated-by", arg, &type))
        return CLI_EXIT_USAGE;
    if (tirenv_model_type_flags(type) & TIRENV_MODEL_NEEDS_NETWORK) {
        cli_error("study: --simulated-by expects a physical model (e.g. ring, cam), got '%s'",
                  arg);
        return CLI_EXIT_USAGE;
    }
    *(const tirenv_model_type **)dst = type;
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
    const tirenv_model_type *simulated_by = NULL;
    int measured = 0, no_images = 0;
    const cli_opt own[] = {
        {.name = "data", .kind = CLI_STRING, .dst = &data, .input = CLI_INPUT_DIR},
        {.name = "trainer", .kind = CLI_STRING, .dst = &s.trainer},
        {.name = "seed", .kind = CLI_COUNT, .dst = &seed, .min = 0, .max = 2147483647L,
         .what = "a whole number >= 0"},
        {.name = "simulated-by", .kind = CLI_CUSTOM, .dst = &simulated_by,
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
    if (simulated_by && measured) {
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
    /* The data set says what simulated it and with which tire (source.txt, as tirenv dataset
     * build writes it); a data set that says nothing is taken as measured. */
    tirenv_dataset_source src;
    char tire_buf[1024];
    int code = cli_data_source(s.data_dir, &o, &src, tire_buf, sizeof tire_buf);
    if (!code && !simulated_by && !measured)
        code = cli_sweep_reference("study", s.data_dir, &src,
                                   "--simulated-by MODEL with --tire FILE, or --measured");
    if (code)
        return code;
    s.simulated_by = simulated_by                ? simulated_by
                     : measured || !src.model[0] ? NULL
                                                 : tirenv_model_type_find(src.model);
    s.simulated_raw = !simulated_by && !measured && src.sweep_raw;
    if (!tirenv_trainer_type_find(s.trainer)) {
        cli_error("study: unknown trainer '%s'; expected lm, rprop or backprop", s.trainer);
        return CLI_EXIT_USAGE;
    }
    if ((code = cli_tire(&o, &s.tire)))
        return code;
    char label[1024];
    s.tire_label = cli_tire_path(&o, label, sizeof label);
    /* The data set's own tire is named as the data set is (data/dataset/tire.tir). */
    const size_t n_dir = strlen(s.data_dir);
    if (o.tire_path == tire_buf && strncmp(tire_buf, s.data_dir, n_dir) == 0) {
        snprintf(label, sizeof label, "%s%s", s.data_label, tire_buf + n_dir);
        s.tire_label = label;
    }
    double t0 = cli_wall_seconds();
    s.progress = progress;
    s.progress_ctx = &t0;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_study(&s, &diag);
    if (status) {
        code = cli_fail(status, &diag);
        if (status == TIRENV_EIO && strcmp(diag.field, "gnuplot") == 0)
            cli_error("study: nothing written to %s; --no-images writes the report with the "
                      "gnuplot scripts, to draw later", s.out_dir);
        return code;
    }
    printf("tirenv: study: report written to %s/report.md (%.1f s)\n", s.out_dir,
           cli_wall_seconds() - t0);
    return CLI_EXIT_OK;
}
