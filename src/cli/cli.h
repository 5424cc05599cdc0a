/* Private to the tirenv command-line tool: the command table, exit codes, and the one option
 * parser every subcommand goes through (cli_parse): the options they share (tire, load,
 * obstacle, sweep, output, model, network), -h/--help, misuse, repeated options and leftover
 * arguments, so that each command lists only what is its own. Like every part of the CLI it
 * uses the library's public headers alone. SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CLI_H
#define TIRENV_CLI_H

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
int cli_dataset_main(int argc, char *argv[]);
int cli_compare_main(int argc, char *argv[]);
int cli_fit_main(int argc, char *argv[]);
int cli_identify_main(int argc, char *argv[]);
int cli_study_main(int argc, char *argv[]);
int cli_road_main(int argc, char *argv[]);
int cli_convert_main(int argc, char *argv[]);
int cli_ride_main(int argc, char *argv[]);
int cli_sweep_main(int argc, char *argv[]);

/* ---- the shared parser ------------------------------------------------------------------ */

/* The option groups a command takes from cli_parse, besides its own. */
enum {
    CLI_TIRE = 1u << 0,     /* --tire FILE, --set KEY=VALUE (repeatable) */
    CLI_METHOD = 1u << 1,   /* --method newton|secant|brent */
    CLI_LOAD = 1u << 2,     /* --load N | --contact-length M */
    CLI_OBSTACLE = 1u << 3, /* one of --cleat, --step, --trapezoid, --triangle, --cylinder,
                             * --sine, --profile */
    CLI_SWEEP = 1u << 4,    /* --x-from X, --x-to X, --dx DX (m) */
    CLI_OUTPUT = 1u << 5,   /* -o, --output PATH */
    CLI_MODEL = 1u << 6,    /* --model NAME, looked up in the library's table of types */
    CLI_NETWORK = 1u << 7,  /* --nn FILE, the trained network a model type may need */
    CLI_TRACKS = 1u << 8,   /* --width W, --tracks N: tracks across the tire's width (with
                             * CLI_OBSTACLE, which has --track V and --side S) */
    CLI_JOBS = 1u << 9,     /* --jobs N: work items at once (default: the cores) */
    CLI_EXTRAPOLATE = 1u << 10 /* --extrapolate: the network outside its trained ranges, for
                                * a command that evaluates it on inputs of the user's */
};

/* The obstacle options, for cli_options.obstacle. */
enum {
    CLI_CLEAT = 1,
    CLI_STEP,
    CLI_TRAPEZOID,
    CLI_TRIANGLE,
    CLI_CYLINDER,
    CLI_SINE,
    CLI_PROFILE
};

#define CLI_MAX_SETS 64
#define CLI_MAX_ARGS 4
#define CLI_MAX_RUNS 8

/* What the shared options said: filled by cli_parse, turned into objects by cli_tire,
 * cli_load, cli_profile and cli_network. */
typedef struct {
    const char *tire_path;            /* --tire, or NULL for the default tire file */
    const char *sets[CLI_MAX_SETS];   /* --set KEY=VALUE, in command-line order */
    size_t n_sets;
    int have_method;
    tirenv_eq_method method;          /* --method */
    int have_load, have_contact_length;
    double load;                      /* --load, N */
    double contact_length;            /* --contact-length, m */
    int obstacle;                     /* CLI_CLEAT..CLI_PROFILE, or 0 for none */
    const char *obstacle_arg;         /* its argument as given, for messages */
    int have_track, have_side;
    double track;                     /* --track: lateral position on a .crg road, m */
    tirenv_rdf_side side;             /* --side: which side of a .rdf poly_line road */
    int have_crg_nan;
    tirenv_crg_track_spec crg_nan;    /* --crg-nan-mode: its grid_nan_mode and _offset */
    int have_width;
    double width;                     /* --width: the width tracks spread over, m */
    long tracks;                      /* --tracks: tracks across it; 0 if not given */
    double shape[3];                  /* the generator's numbers, m */
    double x_from, x_to, dx;          /* --x-from, --x-to, --dx, m; NaN if not given */
    const char *output;               /* -o, --output, or NULL */
    const tirenv_model_type *type;    /* --model, or NULL */
    int type_alone;                   /* the command uses that model of the tire and no
                                       * other (cli_tire: tirenv_tir_derive's TIRENV_TIR_ONLY) */
    const tirenv_model_type *runs[CLI_MAX_RUNS]; /* the models the command runs on the
                                       * tire, for --set's warnings (cli_set_warnings); none:
                                       * --model's, else nothing is said */
    size_t n_runs;
    unsigned reads_also;              /* cli_model_reads bits the command reads besides */
    const char *nn_path;              /* --nn, or NULL */
    size_t jobs;                      /* --jobs, else cli_jobs_default() (with CLI_JOBS) */
    int extrapolate;                  /* --extrapolate: the network outside its trained
                                       * ranges (tirenv_model_set_extrapolate) */
    const char *args[CLI_MAX_ARGS];   /* positional arguments, in order */
    size_t n_args;
} cli_options;

/* How a command's own option takes its argument. */
typedef enum {
    CLI_FLAG,      /* no argument: *(int *)dst = 1 */
    CLI_STRING,    /* *(const char **)dst = the argument */
    CLI_NUMBER,    /* *(double *)dst, any finite number */
    CLI_POSITIVE,  /* *(double *)dst, a number > 0 */
    CLI_COUNT,     /* *(long *)dst, a whole number in [min, max] */
    CLI_CUSTOM     /* parse(dst, arg) decides, and says why it refuses */
} cli_kind;

/* One option of a command's own, in a table ended by {NULL}. A malformed value is refused
 * with "--NAME: expected WHAT, got 'ARG'" and exit status 1. */
typedef struct cli_opt {
    const char *name;      /* long name, without "--" */
    cli_kind kind;
    void *dst;
    const char *what;      /* what a number must be, for the message ("a length in m") */
    long min, max;         /* CLI_COUNT's range */
    int (*parse)(void *dst, const char *arg);  /* CLI_CUSTOM: an exit code, after printing */
    int repeatable;        /* may be given more than once (else that is misuse) */
    int input;             /* CLI_STRING: CLI_INPUT_FILE, a file the command reads, which -o
                            * may not name (cli_refuse_clobber); CLI_INPUT_DIR, a directory
                            * whose files it reads, none of which -o may name */
} cli_opt;

enum { CLI_INPUT_FILE = 1, CLI_INPUT_DIR = 2 }; /* cli_opt's input */

/* A command's parser. */
typedef struct {
    const char *name;           /* the command, for messages ("envelope") */
    void (*usage)(FILE *fp);    /* its usage text */
    unsigned groups;            /* CLI_TIRE | CLI_LOAD | ... */
    const cli_opt *opts;        /* its own options, or NULL */
    size_t max_args;            /* positional arguments it takes (into o->args) */
} cli_parser;

/* Parses argv (argv[0] is the command) into o (initialised here) and the own options' dst:
 * -h/--help prints the usage on stdout and returns CLI_EXIT_OK (CLI_EXIT_USAGE, naming them,
 * if the usage's option entries miss a long option the command takes); an unknown option or a
 * missing argument prints the usage on stderr, a malformed value or a single-valued option given twice
 * names the option, more positional arguments than p->max_args name the first extra one: each
 * returns CLI_EXIT_USAGE. A model type that needs a network without --nn (or in a command that
 * takes none) is misuse too. Returns CLI_GO_ON when the command has work to do. */
#define CLI_GO_ON (-1)
int cli_parse(const cli_parser *p, int argc, char *argv[], cli_options *o);

/* Option help text for the groups above, indented for a usage message. */
void cli_help_tire(FILE *fp, int with_method, const char *example);
/* The same for a command whose tire defaults to another than tires/default.tir: tire_help is
 * its whole --tire entry, as it prints. */
void cli_help_tire_as(FILE *fp, int with_method, const char *example,
                      const char *tire_help);
/* The --tire entry of the commands that read a data set: the tire its source.txt names. */
extern const char cli_help_data_tire[];
void cli_help_load(FILE *fp);
void cli_help_obstacle(FILE *fp);
void cli_help_sweep(FILE *fp);
void cli_help_jobs(FILE *fp);
/* "--model NAME", listing the models the library has (those whose flags include all of
 * `with` and none of `without`), then fallback (e.g. " (default x)"). */
void cli_help_model(FILE *fp, unsigned with, unsigned without, const char *fallback);

/* ---- turning options into objects ----------------------------------------------------- */

/* The data directory (datadir.c): $TIRENV_DATA if set, else the installed data found from the
 * program's own location (or, in the build tree, the source tree's data/). */
const char *cli_data_dir(void);
/* rel (e.g. "dataset") under the data directory, in buf. */
const char *cli_data_path(const char *rel, char *buf, size_t n);

/* The tire file in use, returned: --tire's own string, else tires/default.tir in the data
 * directory written into buf (buf is left unset with --tire: read the return). */
const char *cli_tire_path(const cli_options *o, char *buf, size_t n);

/* What the data set in dir says about its source (its source.txt, tirenv_dataset_source):
 * into *src, and when --tire is not given and it names the tire that simulated the data,
 * that tire becomes the tire file (o->tire_path, kept in buf). Prints and returns an exit code
 * for a malformed source.txt. */
int cli_data_source(const char *dir, cli_options *o, tirenv_dataset_source *src, char *buf,
                    size_t n);

/* A sweep's data set (src from cli_data_source of dir) whose source is not one physical model
 * of one tire file (it set tire keys, or its model needs a network) has no reference to
 * compare against: prints why, naming sweep.txt's line, and the options that say what to do
 * (`instead`), and returns CLI_EXIT_DATA; else CLI_EXIT_OK. `cmd` names the command. */
int cli_sweep_reference(const char *cmd, const char *dir, const tirenv_dataset_source *src,
                        const char *instead);

/* The data set in dir and its tire: cli_data_source (src, buf, n as there), then the tire as
 * cli_tire reads it into *tire, then the data set read with that tire's R0 into *ds (free it
 * with tirenv_dataset_free). Prints and returns an exit code on failure, with nothing to free. */
int cli_data_and_tire(const char *dir, cli_options *o, tirenv_dataset_source *src, char *buf,
                      size_t n, tirenv_tire *tire, tirenv_dataset *ds);

/* The origin of the tire the last cli_tire read (what was derived, its FNOMIN). */
extern tirenv_tir_origin cli_tire_origin;

/* The nominal load (N) that flat tabulates around (0.5 to 1.5 times it) when given no loads
 * (identify takes the file's FNOMIN itself): the tire file's FNOMIN, or 0 for the paper's
 * working regimes (contact lengths 0.28 to 0.38 m) where the file has none or its FNOMIN lies within the ring's loads at those
 * regimes (a tire of the paper's class, whose nominal load is one of its regimes: the default
 * tractor tire, whose FNOMIN is its 0.33 m load for the cam's vertical law). */
double cli_nominal_load(const tirenv_tire *tire);

/* CLI_EXIT_DATA, printing that path is a pipe (a FIFO, /dev/stdin from a pipe, a socket)
 * and why a regular file is needed (why: "bench runs itself in child processes that read it
 * again"); else CLI_EXIT_OK. A command that reads a file twice refuses a pipe before it
 * opens it, where the second open would wait for a writer that has gone. */
int cli_refuse_pipe(const char *path, const char *why);

/* tirenv_tir_read_derive(path, tire, need) (need: tirenv_tir_need's bits; one read of the
 * file), printing what was derived on standard error. */
int cli_tire_read_derive(const char *path, unsigned need, tirenv_tire *tire,
                         tirenv_tir_origin *origin);

/* TIRENV_EINVAL naming nn_path and training.data.contact_law when a network file without a
 * contact law would take the springs model of the tire at tire_path, whose file neither has
 * nor derived one (origin: cli_tire_origin, or a ride axle's); TIRENV_OK otherwise. */
int cli_nn_springs_stand_in(const char *nn_path, const char *tire_path,
                            const tirenv_tir_origin *origin, tirenv_diag *diag);

/* Reads the tire file, applies --set in order and --method, and checks the result; says on
 * standard error which --set keys no model of o->runs (else --model) reads.
 * Returns an exit code after printing any error. */
int cli_tire(const cli_options *o, tirenv_tire *tire);

/* The sections of a tire file a model of type reads (bits private to set_keys.c), with the
 * springs model's for the rigid disc and the point when a contact length is their load. */
unsigned cli_model_reads(const tirenv_model_type *type, int at_contact_length);
/* One line on standard error for each of the n_sets KEY=VALUE whose key's section is not in
 * reads (cli_model_reads bits), naming the key, its section and the n_runs models; nothing if
 * n_runs is 0. */
void cli_set_warnings(const char *const sets[], size_t n_sets,
                      const tirenv_model_type *const runs[], size_t n_runs, unsigned reads);
/* The same for --method, the solver's METHOD: a line when no model of runs reads it. */
void cli_method_warning(const tirenv_model_type *const runs[], size_t n_runs, unsigned reads);

/* The model type named name; prints the valid names after option (the option as the user
 * gave it, e.g. "--simulated-by") and returns CLI_EXIT_USAGE if there is none. */
int cli_model_type(const char *option, const char *name, const tirenv_model_type **type);

/* "rigid,springs,nn": 1 to max model types by their names into types[], their number into
 * *n; prints an error naming option and returns CLI_EXIT_USAGE for an empty or unknown name
 * or more than max. */
int cli_model_list(const char *option, const char *arg, const tirenv_model_type *types[],
                   size_t max, size_t *n);

/* For the cam (type): whether the tire from path has MF-Swift's cam keys of its own
 * (tirenv_tire_check_cam_keys); prints the refusal naming them and path and returns an exit
 * code if not. CLI_EXIT_OK for the other models. */
int cli_cam_keys(const tirenv_model_type *type, const tirenv_tire *tire, const char *path);

/* Allocates a model for a checked tire and, if its type needs one, gives it the network of
 * --nn (read from the model file, with the R0 its x_N refers to); prints and returns an exit
 * code on failure. */
int cli_model(const tirenv_model_type *type, const tirenv_tire *tire, const cli_options *o,
              tirenv_model **out);

/* The load (N) the options ask for: --load as given, or --contact-length through the model's
 * own flat-ground contact length. Needs one of them; returns an exit code. */
int cli_load(const cli_options *o, tirenv_model *m, double *load);

/* Prints the model's warnings (tirenv_model_warnings), one "tirenv: CMD: warning: ..." line
 * each. */
void cli_model_warnings(const char *cmd, const tirenv_model *m);
/* Lines of warnings ("" or one a line), each as "tirenv: CMD: warning: ..." on stderr. */
void cli_warnings(const char *cmd, const char *warnings);

/* Positions from x_from to x_to (m) every dx (m), allocated (free it); at most
 * CLI_MAX_POSITIONS, beyond which a sweep is surely a typo in --dx. Prints why and returns an
 * exit code on bad input. */
#define CLI_MAX_POSITIONS 10000000.0

/* Most positions of a sweep whose rows go out as they are computed (envelope --stream, and
 * -o FILE.csv in whole mode), which holds none of them: 100 km every 1 mm, about 6 GB of CSV.
 * Beyond it a sweep is a typo in --x-to or --dx, and would fill the disk before it ends. */
#define CLI_MAX_STREAM_POSITIONS 100000000.0

/* Checks a sweep from x_from to x_to (m) every dx (m) has at most max positions (what
 * tirenv_positions_count allows, too) and sets *n_out to their count; prints why not, naming
 * the options, and returns an exit code. */
int cli_positions_check(double x_from, double x_to, double dx, double max, size_t *n_out);
int cli_positions(double x_from, double x_to, double dx, double **x_out, size_t *n_out);

/* The generated obstacle the options ask for (parse.c; one required, not --profile); returns
 * an exit code. */
int cli_obstacle(const cli_options *o, tirenv_profile **out);

/* ---- roads from files, and tracks across the width (road.c) --------------------------- */

#define CLI_MAX_TRACKS 64

/* The tracks the obstacle options ask for. */
typedef struct {
    int from_file;                 /* --profile */
    tirenv_road_file *file;        /* it, open (cli_road_free closes it); NULL if not a file */
    tirenv_profile_format format;  /* its format (by content); CSV for a generated obstacle */
    tirenv_profile_source src;     /* --track, --side */
    size_t n;                      /* tracks evaluated: --tracks over a road that varies across
                                    * (a .crg), else 1 */
    double width;                  /* m: the width they spread over; 0 with one track */
    double v[CLI_MAX_TRACKS];      /* their lateral positions, m */
} cli_road;

/* Opens the --profile file (once: every read below takes r->file), checks --track, --side,
 * --width and --tracks against the obstacle and the file's format and places the tracks
 * (tire: the default width, [DIMENSION] WIDTH; NULL where --tracks is not taken). Prints and
 * returns an exit code; cli_road_free(r) after it, whatever it returned. */
int cli_road_plan(const cli_options *o, const tirenv_tire *tire, cli_road *r);
/* The tracks' profiles, whole: r->n of them into out (each to free), from the open file or
 * the generated obstacle. Returns an exit code. */
int cli_road_read(const cli_options *o, const cli_road *r, tirenv_profile *out[]);
/* The open --profile file read a row of r->n heights at a time, from its start, for
 * --stream; several readers may be open at once. */
int cli_road_open(const cli_road *r, tirenv_profile_file_reader **out);
/* Closes the file; safe after a failed cli_road_plan, and twice. */
void cli_road_free(cli_road *r);
/* The obstacle the options ask for (one required): a generated one, or the --profile file's
 * track (--track, --side), the file opened for this one read; returns an exit code. */
int cli_profile(const cli_options *o, tirenv_profile **out);
/* "FILE", "FILE, track v = 0.9 m", "FILE, 5 tracks over 0.38 m around v = 0.9 m", or the
 * generated obstacle as asked for. */
void cli_road_label(const cli_options *o, const cli_road *r, char *buf, size_t n);
/* The help text of --track, --side, --width, --tracks (with_tracks: the last two too). */
void cli_help_road(FILE *fp, int with_tracks);
/* --crg-nan-mode keep|nearest|file|VALUE into spec's grid_nan_mode and grid_nan_offset (dst: a
 * tirenv_crg_track_spec); prints the error and returns CLI_EXIT_USAGE on a bad argument. */
int cli_parse_crg_nan_mode(void *dst, const char *arg);
/* How a message names the obstacle: the file, or the generator as it was asked for. */
void cli_obstacle_label(const cli_options *o, char *buf, size_t n);

/* ---- small things --------------------------------------------------------------------- */

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
/* CPU time of the calling thread, s: one work item's cost when several run at once. */
double cli_thread_seconds(void);
/* Wall time since an arbitrary start (CLOCK_MONOTONIC), s. */
double cli_wall_seconds(void);

/* CLI_EXIT_USAGE, after saying so, when output (-o) names the regular file input, which
 * option gives and cmd reads: writing the output would replace it. Paths name the same file
 * when they resolve to the same name, symbolic links followed (clobber.c). */
int cli_refuse_clobber(const char *cmd, const char *output, const char *option,
                       const char *input);

/* The same for a directory dir whose files the command reads: -o may not name a regular file
 * inside it (at any depth), since the command may read any of them. */
int cli_refuse_clobber_dir(const char *cmd, const char *output, const char *option,
                           const char *dir);

/* cli_refuse_clobber for an output directory dir into which the command writes the files
 * names[] (NULL-terminated): the input must be none of them. */
int cli_refuse_clobber_into(const char *cmd, const char *dir, const char *const names[],
                            const char *option, const char *input);

/* Whether paths a and b name one existing directory, symbolic links followed (clobber.c). */
int cli_same_dir(const char *a, const char *b);

/* mkdir -p; prints and returns an exit code on failure. */
int cli_mkdir(const char *dir);

/* --jobs (jobs.c): the default, every core this process may run on; N parsed from arg, in
 * [1, CLI_MAX_JOBS] (else prints why and returns CLI_EXIT_USAGE). */
#define CLI_MAX_JOBS 1024
size_t cli_jobs_default(void);
int cli_parse_jobs(const char *arg, size_t *jobs);

/* The CLI's own gnuplot scripts (plot_script.c). s in gnuplot's single quotes, where nothing
 * but ' (written twice) is special. */
void cli_plot_quoted(FILE *fp, const char *s);
/* png_out and svg_out, name.png and name.svg unless tirenv_plot_draw set them. */
void cli_plot_outputs(FILE *fp, const char *name);
/* "do for [pass = 1:2] {", a pass each for the PNG and the SVG of width x height pixels; the
 * caller writes the plot commands and the closing "}". */
void cli_plot_passes(FILE *fp, size_t width, size_t height);

#endif
