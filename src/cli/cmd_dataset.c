/* tirenv dataset: build the embedded data set, or list a data set's cases.
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv dataset build [--design NAME] [-o DIR] [--jobs N] [--tire FILE]\n"
          "                           [--set KEY=VALUE]... [--method M]\n"
          "       tirenv dataset list [DIR]\n"
          "\n"
          "build: regenerates an embedded data set bit for bit: 28 cleat runs on the virtual\n"
          "rig (19 train, 5 control, 4 validation, the paper's Table 3 cases F, J and R\n"
          "among them), raw logs in DIR/logs, imported approach-half curves in DIR/curves,\n"
          "the tire as simulated in DIR/tire.tir, what simulated the data in DIR/source.txt,\n"
          "manifest DIR/cases.csv. The data are SIMULATED. Designs:\n",
          fp);
    for (const tirenv_design *const *d = tirenv_designs(); *d; ++d)
        fprintf(fp, "  %-19s %s; model %s, tire %s, DIR %s%s\n", (*d)->name, (*d)->summary,
                (*d)->model, (*d)->tire_file, (*d)->dir,
                d == tirenv_designs() ? " (the default)" : "");
    fputs("DIR, the tire file and the data set to list default to the design's in the data\n"
          "directory ($TIRENV_DATA, else the installed data; in a build tree, the source\n"
          "tree's data/).\n"
          "list: prints a data set's manifest as a table, what simulated it and how many\n"
          "cases its source.txt declares (a manifest with another count is refused).\n"
          "\n"
          "options:\n"
          "  --design NAME        the data set to build (default 14.9R28)\n"
          "  -o, --output DIR     where to build (created if missing)\n",
          fp);
    cli_help_jobs(fp);
    cli_help_tire_as(fp, 1, "FOUNDATION_STIFFNESS=1.2e5 (the ring's)",
                     "  --tire FILE          tire property file (.tir); default: the design's, in\n"
                     "                       the data directory ($TIRENV_DATA, else the installed\n"
                     "                       data); for list, the data set's own\n");
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
    tirenv_dataset_source src;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    int status = tirenv_dataset_source_read(dir, &src, &diag);
    if (!status)
        status = tirenv_dataset_read(dir, R0, &ds, &diag);
    if (status)
        return cli_fail(status, &diag);
    if (src.sweep_model[0])
        printf("SIMULATED by the %s model (tirenv sweep: %s/sweep.txt); tire %s/tire.tir%s\n",
               src.sweep_model, dir, dir,
               src.sweep_key[0] ? " with each case's keys of sweep.csv" : "");
    else if (src.model[0])
        printf("SIMULATED by the %s model on the virtual rig%s%s%s; tire %s\n", src.model,
               src.design[0] ? " (design " : "", src.design, src.design[0] ? ")" : "",
               src.tire[0] ? src.tire : "not recorded");
    if (src.cases)  /* the read checked the manifest against it */
        printf("%zu cases, as source.txt declares\n", src.cases);
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

static int parse_design(void *dst, const char *arg)
{
    const tirenv_design *d = tirenv_design_find(arg);
    if (!d) {
        cli_error("dataset: --design: unknown design '%s'; expected one of:", arg);
        for (const tirenv_design *const *k = tirenv_designs(); *k; ++k)
            fprintf(stderr, "  %s\n", (*k)->name);
        return CLI_EXIT_USAGE;
    }
    *(const tirenv_design **)dst = d;
    return CLI_EXIT_OK;
}

int cli_dataset_main(int argc, char *argv[])
{
    const tirenv_design *design = NULL;
    const cli_opt own[] = {
        {.name = "design", .kind = CLI_CUSTOM, .dst = &design, .parse = parse_design},
        {.name = NULL},
    };
    const cli_parser p = {.name = "dataset", .usage = usage, .max_args = 2, .opts = own,
                          .groups = CLI_TIRE | CLI_METHOD | CLI_OUTPUT | CLI_JOBS};
    cli_options o;
    const int parsed = cli_parse(&p, argc, argv, &o);
    if (parsed != CLI_GO_ON)
        return parsed;
    /* "tirenv dataset build [--design NAME] [-o DIR]" or "tirenv dataset list [DIR]". */
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
    if (listing && design) {
        cli_error("dataset: list reads a data set's own source.txt; --design is for build");
        return CLI_EXIT_USAGE;
    }
    if (!design)
        design = tirenv_designs()[0];
    tirenv_dataset_source src;
    char src_tire[1024];
    char dir_buf[1024], tire_buf[1024];
    const char *dir = o.n_args > 1 ? o.args[1]
                      : o.output   ? o.output
                                   : cli_data_path(design->dir, dir_buf, sizeof dir_buf);
    /* To list: the data set's own tire (it may import logs with its R0). To build: the
     * design's own tire. --tire names another. */
    int code;
    if (listing && (code = cli_data_source(dir, &o, &src, src_tire, sizeof src_tire)))
        return code;
    if (!o.tire_path)
        o.tire_path = cli_data_path(design->tire_file, tire_buf, sizeof tire_buf);
    tirenv_tire tire;
    if ((code = cli_tire(&o, &tire)))
        return code;
    if (listing)
        return list(dir, tire.springs.R0);
    if ((code = cli_cam_keys(tirenv_model_type_find(design->model), &tire, o.tire_path)))
        return code;
    /* The files a build writes into dir besides its cases' CSV logs and curves
     * (src/dataset/dataset_build.c), of which --tire may be one: `--tire DIR/tire.tir -o
     * DIR` replaced the user's tire file by the data set's. */
    static const char *const writes[] = {"tire.tir", "cases.csv", "source.txt", NULL};
    if ((code = cli_refuse_clobber_into("dataset", dir, writes, "--tire", o.tire_path)))
        return code;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_dataset_build_settings bs = tirenv_dataset_build_default();
    bs.jobs = o.jobs;
    bs.progress = progress;
    const int status = tirenv_dataset_build_design(dir, design, &tire, &bs, &diag);
    if (status)
        return cli_fail(status, &diag);
    fprintf(stderr, "tirenv: dataset: %zu simulated cases (%s) written to %s\n",
            design->n_cases, design->name, dir);
    return CLI_EXIT_OK;
}
