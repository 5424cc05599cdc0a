/* Private to the tirenv command-line tool: the command table, exit codes, and the options
 * every subcommand shares (tire, load, obstacle). SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TIRENV_CLI_H
#define TIRENV_CLI_H

#include <getopt.h>
#include <stddef.h>
#include <stdio.h>

#include "tirenv/tirenv.h"

/* Exit codes, documented in "tirenv help". */
enum {
    CLI_EXIT_OK = 0,      /* success */
    CLI_EXIT_USAGE = 1,   /* misuse: unknown command or option, malformed option value */
    CLI_EXIT_DATA = 2,    /* bad data: unreadable or malformed file, unphysical parameter */
    CLI_EXIT_NUMERIC = 3  /* numerical failure: no equilibrium, no convergence */
};

/* One subcommand: kmod's {name, cmd, help} record. main gets argv[0] = the command name. */
typedef struct {
    const char *name;
    int (*main)(int argc, char *argv[]);
    const char *summary;
} cli_command;

int cli_flat_main(int argc, char *argv[]);
int cli_envelope_main(int argc, char *argv[]);
int cli_bench_main(int argc, char *argv[]);
int cli_rig_main(int argc, char *argv[]);
int cli_import_main(int argc, char *argv[]);
int cli_train_main(int argc, char *argv[]);
int cli_predict_main(int argc, char *argv[]);
int cli_predict_is_nn(int argc, char *argv[]);  /* envelope --model nn: run predict */
int cli_dataset_main(int argc, char *argv[]);
int cli_compare_main(int argc, char *argv[]);
int cli_fit_main(int argc, char *argv[]);
int cli_study_main(int argc, char *argv[]);
int cli_road_main(int argc, char *argv[]);
int cli_ride_main(int argc, char *argv[]);
int cli_sweep_main(int argc, char *argv[]);

/* getopt_long codes of the shared long options; above 255 so they never clash with a short
 * option character. */
enum {
    CLI_OPT_TIRE = 256,
    CLI_OPT_SET,
    CLI_OPT_METHOD,
    CLI_OPT_LOAD,
    CLI_OPT_CONTACT_LENGTH,
    CLI_OPT_CLEAT,
    CLI_OPT_STEP,
    CLI_OPT_TRAPEZOID,
    CLI_OPT_TRIANGLE,
    CLI_OPT_CYLINDER,
    CLI_OPT_SINE,
    CLI_OPT_PROFILE,
    CLI_OPT_JOBS,
    CLI_OPT_FIRST_OWN  /* first code free for a subcommand's own long-only options */
};

/* struct option entries to paste into a subcommand's table, by group. */
#define CLI_TIRE_LONGOPTS                                                                    \
    {"tire", required_argument, NULL, CLI_OPT_TIRE},                                         \
    {"set", required_argument, NULL, CLI_OPT_SET}
#define CLI_METHOD_LONGOPTS {"method", required_argument, NULL, CLI_OPT_METHOD}
#define CLI_LOAD_LONGOPTS                                                                    \
    {"load", required_argument, NULL, CLI_OPT_LOAD},                                         \
    {"contact-length", required_argument, NULL, CLI_OPT_CONTACT_LENGTH}
#define CLI_OBSTACLE_LONGOPTS                                                                \
    {"cleat", required_argument, NULL, CLI_OPT_CLEAT},                                       \
    {"step", required_argument, NULL, CLI_OPT_STEP},                                         \
    {"trapezoid", required_argument, NULL, CLI_OPT_TRAPEZOID},                               \
    {"triangle", required_argument, NULL, CLI_OPT_TRIANGLE},                                 \
    {"cylinder", required_argument, NULL, CLI_OPT_CYLINDER},                                 \
    {"sine", required_argument, NULL, CLI_OPT_SINE},                                         \
    {"profile", required_argument, NULL, CLI_OPT_PROFILE}

#define CLI_MAX_SETS 64

/* What the shared options said: filled by cli_option, turned into objects by cli_tire,
 * cli_load and cli_profile. */
typedef struct {
    const char *tire_path;            /* --tire, or NULL for the default tire file */
    const char *sets[CLI_MAX_SETS];   /* --set KEY=VALUE, in command-line order */
    size_t n_sets;
    int have_method;
    tirenv_eq_method method;          /* --method */
    int have_load, have_contact_length;
    double load;                      /* --load, N */
    double contact_length;            /* --contact-length, m */
    int obstacle;                     /* CLI_OPT_CLEAT..CLI_OPT_PROFILE, or 0 for none */
    const char *obstacle_arg;         /* its argument as given, for messages */
    double shape[3];                  /* the generator's numbers, m */
} cli_options;

void cli_options_init(cli_options *o);

/* Handles one shared option (code from the tables above). Returns CLI_EXIT_OK, or
 * CLI_EXIT_USAGE after printing why the value is malformed. */
int cli_option(cli_options *o, int code, const char *arg);

/* Restarts getopt scanning for a subcommand's own argv (optind = 0 resets glibc and musl). */
void cli_getopt_reset(void);

/* Option help text for the groups above, indented for a usage message. */
void cli_help_tire(FILE *fp, int with_method);
void cli_help_load(FILE *fp);
void cli_help_obstacle(FILE *fp);
/* "--model NAME", listing the models the library has, then fallback (e.g. " (default x)"). */
void cli_help_model(FILE *fp, const char *fallback);

/* The data directory (datadir.c): $TIRENV_DATA if set, else the installed data found from the
 * program's own location (or, in the build tree, the source tree's data/). */
const char *cli_data_dir(void);
/* rel (e.g. "dataset") under the data directory, in buf. */
const char *cli_data_path(const char *rel, char *buf, size_t n);

/* The tire file in use: --tire, else tires/default.tir in the data directory. */
const char *cli_tire_path(const cli_options *o, char *buf, size_t n);

/* Reads the tire file, applies --set in order and --method, and checks the result.
 * Returns an exit code after printing any error. */
int cli_tire(const cli_options *o, tirenv_tire *tire);

/* The model type named by --model; prints the valid names and returns CLI_EXIT_USAGE if
 * there is none. */
int cli_model_type(const char *name, const tirenv_model_type **type);

/* Allocates a model for a checked tire; prints and returns an exit code on failure. */
int cli_model(const tirenv_model_type *type, const tirenv_tire *tire, tirenv_model **out);

/* The load (N) the options ask for: --load as given, or --contact-length through the model's
 * own flat-ground contact length. Needs one of them; returns an exit code. */
int cli_load(const cli_options *o, tirenv_model *m, double *load);

/* Positions from x_from to x_to (m) every dx (m), allocated (free it); at most
 * CLI_MAX_POSITIONS, beyond which a sweep is surely a typo in --dx. Prints why and returns an
 * exit code on bad input. */
#define CLI_MAX_POSITIONS 10000000.0
int cli_positions(double x_from, double x_to, double dx, double **x_out, size_t *n_out);

/* The obstacle the options ask for (one required); returns an exit code. */
int cli_profile(const cli_options *o, tirenv_profile **out);

/* Parsers with full checks (whole string consumed, finite, in range); 0 on success. */
int cli_parse_double(const char *s, double *v);
int cli_parse_doubles(const char *s, double v[], size_t n);  /* exactly n, comma-separated */
int cli_parse_count(const char *s, long min, long max, long *v);

/* Prints "tirenv: <fmt...>" on stderr. */
void cli_error(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* Prints "tirenv: <diag>" (or the status text if diag is empty) and returns the exit code
 * for status. */
int cli_fail(int status, const tirenv_diag *diag);

/* The exit code for a library status. */
int cli_exit_code(int status);

/* CPU time of this process, s (what "on one core" means for a single-threaded run). */
double cli_cpu_seconds(void);
/* Wall time since an arbitrary start (CLOCK_MONOTONIC), s. */
double cli_wall_seconds(void);

/* mkdir -p; prints and returns an exit code on failure. */
int cli_mkdir(const char *dir);

/* --jobs (jobs.c): the default, every core this process may run on; parses N in [1,
 * CLI_MAX_JOBS] (prints "CMD: --jobs ..." and returns CLI_EXIT_USAGE if malformed); help. */
#define CLI_MAX_JOBS 1024
#define CLI_JOBS_LONGOPT {"jobs", required_argument, NULL, CLI_OPT_JOBS}
size_t cli_jobs_default(void);
int cli_parse_jobs(const char *cmd, const char *arg, size_t *jobs);
void cli_help_jobs(FILE *fp);

#endif
