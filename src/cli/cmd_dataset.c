/* tirenv dataset: build the embedded data set, or list a data set's cases.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv dataset build [-o DIR] [--jobs N] [--tire FILE] [--set KEY=VALUE]...\n"
          "       tirenv dataset list [DIR]\n"
          "\n"
          "build: regenerates the embedded data set bit for bit: 28 cleat runs of the\n"
          "flexible-ring reference tire on the virtual rig (19 train, 5 control, 4\n"
          "validation, the paper's Table 3 cases F, J and R among them), raw logs in\n"
          "DIR/logs, imported approach-half curves in DIR/curves, manifest DIR/cases.csv.\n"
          "The data are SIMULATED. Default DIR: dataset in the data directory ($TIRENV_DATA,\n"
          "else the installed data; in a build tree, the source tree's data/dataset).\n"
          "list: prints a data set's manifest as a table (default DIR as for build).\n"
          "\n"
          "options:\n"
          "  -o DIR               where to build (created if missing)\n",
          fp);
    cli_help_jobs(fp);
    cli_help_tire(fp, 1);
    fputs("  -h, --help           show this help\n", fp);
}

static void progress(void *ctx, size_t done, size_t total)
{
    (void)ctx;
    if (isatty(STDERR_FILENO))
        fprintf(stderr, "\rtirenv: dataset: case %zu of %zu%s", done, total,
                done == total ? "\n" : "");
}

static int list(const char *dir, double R0)
{
    tirenv_dataset ds;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_dataset_read(dir, R0, &ds, &diag);
    if (status)
        return cli_fail(status, &diag);
    printf("%-4s %-10s %9s %9s %9s %9s %7s  (data set %s)\n", "case", "split", "l_c_m", "load_N",
           "L_m", "H_m", "points", dir);
    for (size_t i = 0; i < ds.n; ++i) {
        const tirenv_case *c = &ds.cases[i];
        printf("%-4s %-10s %9.3f %9.1f %9.3f %9.3f %7zu\n", c->name,
               tirenv_split_name(c->split), c->contact_length, c->load, c->L, c->H, c->curve.n);
    }
    tirenv_dataset_free(&ds);
    return CLI_EXIT_OK;
}

int cli_dataset_main(int argc, char *argv[])
{
    static const struct option longopts[] = {
        CLI_TIRE_LONGOPTS,
        CLI_METHOD_LONGOPTS,
        CLI_JOBS_LONGOPT,
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    cli_options o;
    cli_options_init(&o);
    char dir_buf[1024];
    const char *dir = cli_data_path("dataset", dir_buf, sizeof dir_buf);
    tirenv_dataset_build_settings build = tirenv_dataset_build_default();
    build.jobs = cli_jobs_default();
    build.progress = progress;
    /* "tirenv dataset ACTION [options]": the action first, then its options. */
    const char *action = argc > 1 && argv[1][0] != '-' ? argv[1] : NULL;
    if (action) {
        --argc;
        ++argv;
    }
    int c;
    cli_getopt_reset();
    while ((c = getopt_long(argc, argv, "ho:", longopts, NULL)) != -1) {
        switch (c) {
        case 'h':
            usage(stdout);
            return CLI_EXIT_OK;
        case 'o':
            dir = optarg;
            break;
        case CLI_OPT_JOBS:
            if (cli_parse_jobs("dataset", optarg, &build.jobs))
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
    if (action && strcmp(action, "list") == 0 && optind < argc)
        dir = argv[optind++];
    if (!action || (strcmp(action, "build") && strcmp(action, "list")) || optind < argc) {
        cli_error("dataset: expected 'build' or 'list'%s%s", action ? ", got " : "",
                  action ? action : "");
        usage(stderr);
        return CLI_EXIT_USAGE;
    }
    tirenv_tire tire;
    int code = cli_tire(&o, &tire);
    if (code)
        return code;
    if (strcmp(action, "list") == 0)
        return list(dir, tire.springs.R0);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_dataset_build(dir, &tire, &build, &diag);
    if (status)
        return cli_fail(status, &diag);
    fprintf(stderr, "tirenv: dataset: 28 simulated cases written to %s\n", dir);
    return CLI_EXIT_OK;
}
