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
    const cli_parser p = {.name = "dataset", .usage = usage, .max_args = 2,
                          .groups = CLI_TIRE | CLI_METHOD | CLI_OUTPUT | CLI_JOBS};
    cli_options o;
    const int parsed = cli_parse(&p, argc, argv, &o);
    if (parsed != CLI_GO_ON)
        return parsed;
    /* "tirenv dataset build [-o DIR]" or "tirenv dataset list [DIR]". */
    const char *action = o.n_args ? o.args[0] : NULL;
    const int build = action && strcmp(action, "build") == 0;
    const int listing = action && strcmp(action, "list") == 0;
    if (!build && !listing) {
        cli_error("dataset: expected 'build' or 'list'%s%s", action ? ", got " : "",
                  action ? action : "");
        usage(stderr);
        return CLI_EXIT_USAGE;
    }
    if (build && o.n_args > 1) {
        cli_error("dataset: build writes to -o DIR, not to the argument '%s'", o.args[1]);
        return CLI_EXIT_USAGE;
    }
    char dir_buf[1024];
    const char *dir = o.n_args > 1 ? o.args[1]
                      : o.output   ? o.output
                                   : cli_data_path("dataset", dir_buf, sizeof dir_buf);
    tirenv_tire tire;
    int code = cli_tire(&o, &tire);
    if (code)
        return code;
    if (listing)
        return list(dir, tire.springs.R0);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_dataset_build_settings bs = tirenv_dataset_build_default();
    bs.jobs = o.jobs;
    bs.progress = progress;
    const int status = tirenv_dataset_build(dir, &tire, &bs, &diag);
    if (status)
        return cli_fail(status, &diag);
    fprintf(stderr, "tirenv: dataset: 28 simulated cases written to %s\n", dir);
    return CLI_EXIT_OK;
}
