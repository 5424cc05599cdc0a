/* tirenv: the command-line tool. A table of subcommands drives dispatch and "tirenv help",
 * as in kmod's tools/kmod.c; each subcommand lives in its own cmd_<name>.c.
 * SPDX-License-Identifier: Apache-2.0 */
#include <getopt.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "tirenv/version.h"
#include "cli/signals.h"

static int help_main(int argc, char *argv[]);

static const cli_command commands[] = {
    {"help", help_main, "show this help, or a command's: tirenv help COMMAND"},
    {"flat", cli_flat_main, "flat-ground state: load, deflection, contact length, stiffness"},
    {"envelope", cli_envelope_main, "enveloping curve over an obstacle, as CSV"},
    {"road", cli_road_main, "random road profile of an ISO 8608 class, as CSV"},
    {"convert", cli_convert_main, "a road from one file format to another: CSV, OpenCRG, RDF"},
    {"rig", cli_rig_main, "virtual test rig: a simulated cart run written as a raw log"},
    {"import", cli_import_main, "rig log to an approach-half enveloping curve, as CSV"},
    {"dataset", cli_dataset_main, "build or list the embedded (simulated) data set"},
    {"study", cli_study_main, "the paper's study in one command: fit, train, compare"},
    {"sweep", cli_sweep_main, "a data set over a grid of cleats, regimes and tire keys"},
    {"identify", cli_identify_main, "one tire, every model: springs and cam identified on the ring's flat ground"},
    {"fit", cli_fit_main, "identify the springs model's stiffnesses (or the cam's shape) on a data set"},
    {"train", cli_train_main, "train the empirical model's network on a data set"},
    {"predict", cli_predict_main, "the trained network's enveloping curve over a cleat, as CSV"},
    {"compare", cli_compare_main, "every model against a data set: plots, error tables, report"},
    {"ride", cli_ride_main, "tractor ride over a profile: point contact vs enveloping, ISO 2631"},
    {"bench", cli_bench_main, "time the models and equilibrium solvers on a fixed sweep"},
};
enum { N_COMMANDS = sizeof commands / sizeof commands[0] };

static void usage(FILE *fp)
{
    fputs("usage: tirenv [--help] [--version] COMMAND [OPTIONS]\n"
          "\n"
          "How a tractor tire envelopes obstacles: the quasi-static enveloping curve at\n"
          "constant vertical load.\n"
          "\n"
          "commands:\n",
          fp);
    for (size_t i = 0; i < N_COMMANDS; ++i)
        fprintf(fp, "  %-10s %s\n", commands[i].name, commands[i].summary);
    fputs("\n"
          "Run 'tirenv COMMAND --help' for a command's options.\n"
          "\n"
          "exit status:\n"
          "  0  success\n"
          "  1  misuse: unknown command or option, malformed option value\n"
          "  2  bad data: unreadable or malformed file, unphysical parameter, obstacle\n"
          "     outside the model's domain (or out of memory)\n"
          "  3  numerical failure: no equilibrium (load beyond what the tire carries) or\n"
          "     no convergence; the message names the position x\n"
          "\n"
          "environment:\n"
          "  TIRENV_DATA  the data directory: default tire tires/default.tir, tractor\n"
          "               vehicles/tractor.veh, embedded data set dataset/. Unset: the\n"
          "               installed data, share/tirenv under the prefix tirenv is\n"
          "               installed in, found from the program's own location (the\n"
          "               installed tree may be moved); for a program in its build\n"
          "               tree, the source tree's data/\n"
          "\n"
          "Units are SI (m, N) in options and CSV files; summaries show mm and kN.\n",
          fp);
}

static const cli_command *find_command(const char *name)
{
    for (size_t i = 0; i < N_COMMANDS; ++i)
        if (strcmp(commands[i].name, name) == 0)
            return &commands[i];
    return NULL;
}

/* "tirenv help" lists everything; "tirenv help CMD" is "tirenv CMD --help". */
static int help_main(int argc, char *argv[])
{
    if (argc < 2 || strcmp(argv[1], "help") == 0 || strcmp(argv[1], "--help") == 0 ||
        strcmp(argv[1], "-h") == 0) {
        usage(stdout);
        return CLI_EXIT_OK;
    }
    const cli_command *cmd = find_command(argv[1]);
    if (argc > 2) {
        cli_error("help: expected at most one command name");
        return CLI_EXIT_USAGE;
    }
    if (!cmd) {
        cli_error("help: unknown command '%s'; 'tirenv help' lists them", argv[1]);
        return CLI_EXIT_USAGE;
    }
    char help_opt[] = "--help";
    char *sub_argv[] = {argv[1], help_opt, NULL};
    return cmd->main(2, sub_argv);
}

/* A full disk or a closed pipe on stdout must not pass for success, whatever printed there:
 * a command, or the usage and version that main prints itself. */
static int finish(int code)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        cli_error("error writing to standard output");
        if (code == CLI_EXIT_OK)
            code = CLI_EXIT_DATA;
    }
    return code;
}

int main(int argc, char *argv[])
{
    static const struct option longopts[] = {
        {"help", no_argument, NULL, 'h'},
        {"version", no_argument, NULL, 'V'},
        {NULL, 0, NULL, 0},
    };
    cli_signals_install();
    int c;
    /* '+' stops at the command name, so its options are left for it to parse. */
    while ((c = getopt_long(argc, argv, "+hV", longopts, NULL)) != -1) {
        switch (c) {
        case 'h': /* "tirenv --help CMD" is "tirenv help CMD" */
            return finish(help_main(argc - optind + 1, argv + optind - 1));
        case 'V':
            if (optind < argc) { /* "tirenv --version envelope" asked for something else */
                cli_error("--version takes no operand, got '%s'", argv[optind]);
                return CLI_EXIT_USAGE;
            }
            printf("tirenv %s\n", TIRENV_VERSION);  /* tirenv/version.h */
            return finish(CLI_EXIT_OK);
        default:
            usage(stderr);
            return CLI_EXIT_USAGE;
        }
    }
    if (optind >= argc) {
        cli_error("missing command");
        usage(stderr);
        return CLI_EXIT_USAGE;
    }
    const cli_command *cmd = find_command(argv[optind]);
    if (!cmd) {
        cli_error("unknown command '%s'; 'tirenv help' lists them", argv[optind]);
        return CLI_EXIT_USAGE;
    }
    return finish(cmd->main(argc - optind, argv + optind));
}
