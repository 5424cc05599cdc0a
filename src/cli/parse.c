/* The one option parser of the subcommands (cli_parse): the groups of options they share, a
 * command's own options from a table, -h/--help, misuse, repeated options and leftover
 * arguments, and the help text of the shared groups. SPDX-License-Identifier:
 * Apache-2.0 */
#include "cli/cli.h"

#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* getopt_long codes of the shared options; above 255 so they never clash with a short option
 * character, and below the codes cli_parse gives a command's own options. */
enum {
    OPT_TIRE = 256,
    OPT_SET,
    OPT_METHOD,
    OPT_LOAD,
    OPT_CONTACT_LENGTH,
    OPT_OBSTACLE,          /* OPT_OBSTACLE + CLI_CLEAT .. CLI_PROFILE */
    OPT_X_FROM = OPT_OBSTACLE + CLI_PROFILE + 1,
    OPT_X_TO,
    OPT_DX,
    OPT_MODEL,
    OPT_NN,
    OPT_TRACK,
    OPT_SIDE,
    OPT_CRG_NAN_MODE,
    OPT_WIDTH,
    OPT_TRACKS,
    OPT_JOBS,
    OPT_EXTRAPOLATE,
    OPT_OWN                /* OPT_OWN + i: the command's own option i */
};

/* The numbers each obstacle option takes, and how to say so when they are malformed. */
static const struct {
    int code;
    const char *name;
    size_t n;
    const char *expected;
} obstacles[] = {
    {CLI_CLEAT, "cleat", 2, "L,H: length and height in m"},
    {CLI_STEP, "step", 2, "X0,H: position and height in m (H < 0 steps down)"},
    {CLI_TRAPEZOID, "trapezoid", 3, "LTOP,LBASE,H: top and base lengths and height in m"},
    {CLI_TRIANGLE, "triangle", 2, "L,H: base length and height in m"},
    {CLI_CYLINDER, "cylinder", 1, "R: radius in m"},
    {CLI_SINE, "sine", 3, "A,WAVELENGTH,PERIODS: amplitude and wavelength in m, periods"},
    {CLI_PROFILE, "profile", 0, "a road file: CSV x_m,z_m, OpenCRG .crg or TNO/Adams .rdf"},
};
enum { N_OBSTACLES = sizeof obstacles / sizeof obstacles[0] };

/* The shared options, each with its group; --set is the one a user repeats. */
static const struct {
    unsigned group;
    struct option opt;
    int repeatable;
} shared[] = {
    {CLI_TIRE, {"tire", required_argument, NULL, OPT_TIRE}, 0},
    {CLI_TIRE, {"set", required_argument, NULL, OPT_SET}, 1},
    {CLI_METHOD, {"method", required_argument, NULL, OPT_METHOD}, 0},
    {CLI_LOAD, {"load", required_argument, NULL, OPT_LOAD}, 0},
    {CLI_LOAD, {"contact-length", required_argument, NULL, OPT_CONTACT_LENGTH}, 0},
    {CLI_OBSTACLE, {"cleat", required_argument, NULL, OPT_OBSTACLE + CLI_CLEAT}, 0},
    {CLI_OBSTACLE, {"step", required_argument, NULL, OPT_OBSTACLE + CLI_STEP}, 0},
    {CLI_OBSTACLE, {"trapezoid", required_argument, NULL, OPT_OBSTACLE + CLI_TRAPEZOID}, 0},
    {CLI_OBSTACLE, {"triangle", required_argument, NULL, OPT_OBSTACLE + CLI_TRIANGLE}, 0},
    {CLI_OBSTACLE, {"cylinder", required_argument, NULL, OPT_OBSTACLE + CLI_CYLINDER}, 0},
    {CLI_OBSTACLE, {"sine", required_argument, NULL, OPT_OBSTACLE + CLI_SINE}, 0},
    {CLI_OBSTACLE, {"profile", required_argument, NULL, OPT_OBSTACLE + CLI_PROFILE}, 0},
    {CLI_OBSTACLE, {"track", required_argument, NULL, OPT_TRACK}, 0},
    {CLI_OBSTACLE, {"side", required_argument, NULL, OPT_SIDE}, 0},
    {CLI_OBSTACLE, {"crg-nan-mode", required_argument, NULL, OPT_CRG_NAN_MODE}, 0},
    {CLI_TRACKS, {"width", required_argument, NULL, OPT_WIDTH}, 0},
    {CLI_TRACKS, {"tracks", required_argument, NULL, OPT_TRACKS}, 0},
    {CLI_SWEEP, {"x-from", required_argument, NULL, OPT_X_FROM}, 0},
    {CLI_SWEEP, {"x-to", required_argument, NULL, OPT_X_TO}, 0},
    {CLI_SWEEP, {"dx", required_argument, NULL, OPT_DX}, 0},
    {CLI_OUTPUT, {"output", required_argument, NULL, 'o'}, 0},
    {CLI_MODEL, {"model", required_argument, NULL, OPT_MODEL}, 0},
    {CLI_NETWORK, {"nn", required_argument, NULL, OPT_NN}, 0},
    {CLI_JOBS, {"jobs", required_argument, NULL, OPT_JOBS}, 0},
    {CLI_EXTRAPOLATE, {"extrapolate", no_argument, NULL, OPT_EXTRAPOLATE}, 0},
};
enum { N_SHARED = sizeof shared / sizeof shared[0], MAX_OWN = 32 };

static size_t obstacle_index(int code)
{
    size_t i = 0;
    while (i < N_OBSTACLES && obstacles[i].code != code)
        ++i;
    return i;
}

/* --method NAME. */
static int method_option(cli_options *o, const char *arg)
{
    if (strcmp(arg, "newton") == 0)
        o->method = TIRENV_EQ_NEWTON;
    else if (strcmp(arg, "secant") == 0)
        o->method = TIRENV_EQ_SECANT;
    else if (strcmp(arg, "brent") == 0)
        o->method = TIRENV_EQ_BRENT;
    else {
        cli_error("--method: expected newton, secant or brent, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    o->have_method = 1;
    return CLI_EXIT_OK;
}

/* --load N or --contact-length M (is_load: which), the one excluding the other. */
static int regime_option(cli_options *o, int is_load, const char *arg)
{
    double v;
    if (cli_parse_double(arg, &v)) {
        cli_error("--%s: expected a number in %s, got '%s'",
                  is_load ? "load" : "contact-length", is_load ? "N" : "m", arg);
        return CLI_EXIT_USAGE;
    }
    if (is_load ? o->have_contact_length : o->have_load) {
        cli_error("--load and --contact-length exclude each other: give one");
        return CLI_EXIT_USAGE;
    }
    *(is_load ? &o->load : &o->contact_length) = v;
    *(is_load ? &o->have_load : &o->have_contact_length) = 1;
    return CLI_EXIT_OK;
}

/* --x-from, --x-to or --dx (code), m. */
static int span_option(cli_options *o, int code, const char *arg)
{
    static const char *const names[] = {"x-from", "x-to", "dx"};
    double *v = code == OPT_X_FROM ? &o->x_from : code == OPT_X_TO ? &o->x_to : &o->dx;
    if (cli_parse_double(arg, v) || (code == OPT_DX && !(*v > 0))) {
        cli_error("--%s: expected %s in m, got '%s'", names[code - OPT_X_FROM],
                  code == OPT_DX ? "a positive number" : "a number", arg);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* One of the obstacle options (code), with its numbers; only one may be given. */
static int obstacle_option(cli_options *o, int code, const char *arg)
{
    const size_t i = obstacle_index(code - OPT_OBSTACLE);
    if (o->obstacle) {
        cli_error("--%s: only one obstacle option may be given (already --%s)",
                  obstacles[i].name, obstacles[obstacle_index(o->obstacle)].name);
        return CLI_EXIT_USAGE;
    }
    if (obstacles[i].n && cli_parse_doubles(arg, o->shape, obstacles[i].n)) {
        cli_error("--%s: expected %s, got '%s'", obstacles[i].name, obstacles[i].expected, arg);
        return CLI_EXIT_USAGE;
    }
    o->obstacle = obstacles[i].code;
    o->obstacle_arg = arg;
    return CLI_EXIT_OK;
}

/* One shared option into o; an exit code. */
static int shared_option(cli_options *o, int code, const char *arg)
{
    switch (code) {
    case OPT_TIRE:
        o->tire_path = arg;
        return CLI_EXIT_OK;
    case OPT_SET:
        if (o->n_sets == CLI_MAX_SETS) {
            cli_error("--set: at most %d assignments", CLI_MAX_SETS);
            return CLI_EXIT_USAGE;
        }
        o->sets[o->n_sets++] = arg;
        return CLI_EXIT_OK;
    case OPT_METHOD:
        return method_option(o, arg);
    case OPT_LOAD:
    case OPT_CONTACT_LENGTH:
        return regime_option(o, code == OPT_LOAD, arg);
    case OPT_X_FROM:
    case OPT_X_TO:
    case OPT_DX:
        return span_option(o, code, arg);
    case 'o':
        if (!*arg) { /* a misuse, caught before any work (the writer would refuse it last) */
            cli_error("-o: empty path; expected a file name or '-'");
            return CLI_EXIT_USAGE;
        }
        o->output = arg;
        return CLI_EXIT_OK;
    case OPT_MODEL:
        return cli_model_type("--model", arg, &o->type);
    case OPT_NN:
        o->nn_path = arg;
        return CLI_EXIT_OK;
    case OPT_JOBS:
        return cli_parse_jobs(arg, &o->jobs);
    case OPT_TRACK:
        if (cli_parse_double(arg, &o->track)) {
            cli_error("--track: expected a lateral position in m, got '%s'", arg);
            return CLI_EXIT_USAGE;
        }
        o->have_track = 1;
        return CLI_EXIT_OK;
    case OPT_CRG_NAN_MODE:
        if (cli_parse_crg_nan_mode(&o->crg_nan, arg))
            return CLI_EXIT_USAGE;
        o->have_crg_nan = 1;
        return CLI_EXIT_OK;
    case OPT_SIDE:
        if (tirenv_rdf_side_find(arg, &o->side)) {
            cli_error("--side: expected left, right or mean, got '%s'", arg);
            return CLI_EXIT_USAGE;
        }
        o->have_side = 1;
        return CLI_EXIT_OK;
    case OPT_WIDTH:
        if (cli_parse_double(arg, &o->width) || !(o->width > 0)) {
            cli_error("--width: expected a positive width in m, got '%s'", arg);
            return CLI_EXIT_USAGE;
        }
        o->have_width = 1;
        return CLI_EXIT_OK;
    case OPT_TRACKS:
        if (cli_parse_count(arg, 1, CLI_MAX_TRACKS, &o->tracks)) {
            cli_error("--tracks: expected a whole number of tracks from 1 to %d, got '%s'",
                      CLI_MAX_TRACKS, arg);
            return CLI_EXIT_USAGE;
        }
        return CLI_EXIT_OK;
    case OPT_EXTRAPOLATE:
        o->extrapolate = 1;
        return CLI_EXIT_OK;
    default:
        return obstacle_option(o, code, arg);
    }
}

/* One own option into its destination; an exit code. */
static int own_option(const cli_opt *opt, const char *arg)
{
    double v;
    switch (opt->kind) {
    case CLI_FLAG:
        *(int *)opt->dst = 1;
        return CLI_EXIT_OK;
    case CLI_STRING:
        *(const char **)opt->dst = arg;
        return CLI_EXIT_OK;
    case CLI_NUMBER:
    case CLI_POSITIVE:
        if (cli_parse_double(arg, &v) || (opt->kind == CLI_POSITIVE && !(v > 0)))
            break;
        *(double *)opt->dst = v;
        return CLI_EXIT_OK;
    case CLI_COUNT:
        if (cli_parse_count(arg, opt->min, opt->max, (long *)opt->dst))
            break;
        return CLI_EXIT_OK;
    case CLI_CUSTOM:
        return opt->parse(opt->dst, arg);
    }
    cli_error("--%s: expected %s, got '%s'", opt->name,
              opt->what ? opt->what
                        : opt->kind == CLI_POSITIVE ? "a positive number"
                          : opt->kind == CLI_COUNT  ? "a whole number"
                                                    : "a number",
              arg);
    return CLI_EXIT_USAGE;
}

/* The checks of the model and the network that every command needs alike. */
static int check_network(const cli_parser *p, const cli_options *o)
{
    const int needs = o->type && (tirenv_model_type_flags(o->type) & TIRENV_MODEL_NEEDS_NETWORK);
    if (needs && !(p->groups & CLI_NETWORK)) {
        cli_error("%s: the %s model needs a trained network, which 'tirenv %s' does not take",
                  p->name, tirenv_model_type_name(o->type), p->name);
        return CLI_EXIT_USAGE;
    }
    if (needs && !o->nn_path) {
        cli_error("%s: --model %s needs the trained network: --nn FILE (from 'tirenv train')",
                  p->name, tirenv_model_type_name(o->type));
        return CLI_EXIT_USAGE;
    }
    if (o->extrapolate && !o->nn_path) {
        cli_error("%s: --extrapolate is for a trained network (--nn FILE), which alone has a "
                  "trained range", p->name);
        return CLI_EXIT_USAGE;
    }
    if (o->nn_path && (p->groups & CLI_MODEL) && o->type && !needs) {
        cli_error("%s: --nn is for a model that evaluates a network; the %s model does not",
                  p->name, tirenv_model_type_name(o->type));
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* -o may name none of the files the command reads: --tire (or the default tire file),
 * --profile, --nn and its own options marked input (a file, or a directory such as --data
 * whose files it reads). */
static int check_clobber(const cli_parser *p, const cli_options *o)
{
    char buf[PATH_MAX];
    const char *tire = p->groups & CLI_TIRE ? cli_tire_path(o, buf, sizeof buf) : NULL;
    int code = cli_refuse_clobber(p->name, o->output, "--tire", tire);
    if (!code && o->obstacle == CLI_PROFILE)
        code = cli_refuse_clobber(p->name, o->output, "--profile", o->obstacle_arg);
    if (!code)
        code = cli_refuse_clobber(p->name, o->output, "--nn", o->nn_path);
    for (const cli_opt *opt = p->opts; !code && opt && opt->name; ++opt)
        if (opt->input) {
            char name[64];
            snprintf(name, sizeof name, "--%s", opt->name);
            const char *in = *(const char **)opt->dst;
            code = opt->input == CLI_INPUT_DIR
                       ? cli_refuse_clobber_dir(p->name, o->output, name, in)
                       : cli_refuse_clobber(p->name, o->output, name, in);
        }
    return code;
}

/* The column where a help text's option descriptions start. */
enum { HELP_TEXT_COLUMN = 23 };

/* Whether help lists --name in an option entry, a line "  -..." up to its description
 * ("  --x-from X, --x-to X first ..."), or all of it when the entry runs past the column
 * ("  --control-fraction F, --validation-fraction F"); prose that mentions an option does not
 * list it. */
static int help_lists(const char *help, const char *name)
{
    const size_t len = strlen(name);
    for (const char *line = help; *line;) {
        const char *end = strchr(line, '\n');
        if (!end)
            end = line + strlen(line);
        const char *entry_end = end;
        if (end - line > HELP_TEXT_COLUMN && line[HELP_TEXT_COLUMN - 1] == ' ' &&
            line[HELP_TEXT_COLUMN] != ' ')
            entry_end = line + HELP_TEXT_COLUMN - 1;
        if (strncmp(line, "  -", 3) == 0)
            for (const char *s = line + 2; s + 2 + len <= entry_end; ++s) {
                const char after = s[2 + len];
                if (s[-1] == ' ' && strncmp(s, "--", 2) == 0 &&
                    strncmp(s + 2, name, len) == 0 &&
                    !(after == '-' || (after >= 'a' && after <= 'z') ||
                      (after >= '0' && after <= '9')))
                    return 1;
            }
        line = *end ? end + 1 : end;
    }
    return 0;
}

/* The help a command prints must list every long option it accepts: a missing one is the
 * program's error, named (tests/cli/cli_docs.sh runs every command's --help, the build's man
 * pages come from them). */
static int help_complete(const cli_parser *p, const struct option longopts[], size_t n)
{
    char *help = NULL;
    size_t size = 0;
    FILE *fp = open_memstream(&help, &size);
    if (!fp) {
        cli_error("%s: out of memory", p->name);
        return CLI_EXIT_DATA;
    }
    p->usage(fp);
    if (fclose(fp)) {
        free(help);
        cli_error("%s: out of memory", p->name);
        return CLI_EXIT_DATA;
    }
    int code = CLI_EXIT_OK;
    for (size_t k = 0; k < n; ++k)
        if (!help_lists(help, longopts[k].name)) {
            cli_error("%s: internal error: --help does not list --%s, which the command "
                      "accepts", p->name, longopts[k].name);
            code = CLI_EXIT_USAGE;
        }
    free(help);
    return code;
}

static int parse_argv(const cli_parser *p, int argc, char *argv[], cli_options *o)
{
    memset(o, 0, sizeof *o);
    o->x_from = o->x_to = o->dx = NAN;
    o->jobs = p->groups & CLI_JOBS ? cli_jobs_default() : 1;
    struct option longopts[N_SHARED + MAX_OWN + 2];
    int repeatable[N_SHARED + MAX_OWN + 2];
    size_t seen[N_SHARED + MAX_OWN + 2] = {0};
    size_t n = 0, n_own = 0;
    for (size_t i = 0; i < N_SHARED; ++i)
        if (p->groups & shared[i].group) {
            repeatable[n] = shared[i].repeatable;
            longopts[n++] = shared[i].opt;
        }
    for (const cli_opt *opt = p->opts; opt && opt->name; ++opt, ++n_own) {
        if (n_own == MAX_OWN) {
            cli_error("%s: internal error: more than %d options", p->name, MAX_OWN);
            return CLI_EXIT_USAGE;
        }
        repeatable[n] = opt->repeatable;
        longopts[n++] = (struct option){opt->name,
                                        opt->kind == CLI_FLAG ? no_argument : required_argument,
                                        NULL, OPT_OWN + (int)n_own};
    }
    repeatable[n] = 0;
    longopts[n++] = (struct option){"help", no_argument, NULL, 'h'};
    longopts[n] = (struct option){NULL, 0, NULL, 0};
    const char *shortopts = p->groups & CLI_OUTPUT ? "ho:" : "h";

    optind = 0;  /* restarts getopt for this argv (glibc and musl) */
    int c, index = 0;
    while ((c = getopt_long(argc, argv, shortopts, longopts, &index)) != -1) {
        if (c == 'h') {
            p->usage(stdout);
            return help_complete(p, longopts, n);
        }
        if (c == '?' || c == ':') {  /* getopt has said what it did not understand */
            p->usage(stderr);
            return CLI_EXIT_USAGE;
        }
        size_t k = 0;  /* the option's entry: a short one is found by its code */
        while (k < n && longopts[k].val != c)
            ++k;
        if (++seen[k] > 1 && !repeatable[k]) {
            cli_error("%s: --%s given twice; give it once", p->name, longopts[k].name);
            return CLI_EXIT_USAGE;
        }
        const int code = c >= OPT_OWN ? own_option(&p->opts[c - OPT_OWN], optarg)
                                      : shared_option(o, c, optarg);
        if (code)
            return code;
    }
    for (; optind < argc; ++optind) {
        if (o->n_args == p->max_args || o->n_args == CLI_MAX_ARGS) {
            cli_error("%s: unexpected argument '%s'", p->name, argv[optind]);
            return CLI_EXIT_USAGE;
        }
        o->args[o->n_args++] = argv[optind];
    }
    int code = check_network(p, o);
    if (!code)
        code = check_clobber(p, o);
    return code ? code : CLI_GO_ON;
}

/* getopt names the program in what it says of an unknown option or a missing value by
 * argv[0], which for a command is its bare name ("envelope: unrecognized option"): the whole
 * name instead, as the command's other messages have it. */
int cli_parse(const cli_parser *p, int argc, char *argv[], cli_options *o)
{
    char prog[80];
    snprintf(prog, sizeof prog, "tirenv %s", p->name);
    char *const argv0 = argv[0];
    argv[0] = prog;
    const int code = parse_argv(p, argc, argv, o);
    argv[0] = argv0;
    return code;
}

int cli_parse_crg_nan_mode(void *dst, const char *arg)
{
    tirenv_crg_track_spec *spec = dst;
    double value;
    if (strcmp(arg, "keep") == 0) {
        spec->grid_nan_mode = 0;
    } else if (strcmp(arg, "nearest") == 0) {
        spec->grid_nan_mode = 2;
        spec->grid_nan_offset = 0;
    } else if (strcmp(arg, "file") == 0) {
        spec->grid_nan_mode = -1;
        spec->grid_nan_offset = NAN;
    } else if (cli_parse_double(arg, &value) == 0) {
        spec->grid_nan_mode = 1;  /* zero, plus the offset: the value */
        spec->grid_nan_offset = value;
    } else {
        cli_error("--crg-nan-mode: expected keep, nearest, file or a height in m, got '%s'",
                  arg);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* ---- help ------------------------------------------------------------------------------- */

const char cli_help_data_tire[] =
    "  --tire FILE          tire property file (.tir); default: the tire the data set's\n"
    "                       source.txt names (a sweep's tire.tir when it set no tire\n"
    "                       key), else tires/default.tir in the data directory\n"
    "                       ($TIRENV_DATA, else the installed data)\n";

void cli_help_tire(FILE *fp, int with_method, const char *example)
{
    cli_help_tire_as(fp, with_method, example,
                     "  --tire FILE          tire property file (.tir); default: tires/default.tir "
                     "in\n"
                     "                       the data directory ($TIRENV_DATA, else the installed "
                     "data)\n");
}

void cli_help_tire_as(FILE *fp, int with_method, const char *example, const char *tire_help)
{
    fputs(tire_help, fp);
    fputs("  --set KEY=VALUE      override one .tir key after reading the file (repeatable,\n"
          "                       applied in order; a key no model of the command reads is\n"
          "                       said on standard error)", fp);
    if (example)
        fprintf(fp, ", e.g.\n                       --set %s", example);
    fputs("\n", fp);
    if (with_method)
        fputs("  --method M           equilibrium solver: newton (default), secant (the\n"
              "                       paper's eq. 2) or brent\n",
              fp);
}

void cli_help_load(FILE *fp)
{
    fputs("  --load N             vertical load, N\n"
          "  --contact-length M   the load at which the model's flat-ground contact length\n"
          "                       is M, in m (excludes --load)\n",
          fp);
}

void cli_help_sweep(FILE *fp)
{
    fputs("  --x-from X, --x-to X first and last centre position, m; default: from R0 + 0.02 m\n"
          "                       before the obstacle's first vertex to R0 + 0.02 m after its\n"
          "                       last\n"
          "  --dx DX              spacing of the positions, m (default 0.001)\n",
          fp);
}

void cli_help_model(FILE *fp, unsigned with, unsigned without, const char *fallback)
{
    fputs("  --model NAME         one of", fp);
    for (const tirenv_model_type *const *t = tirenv_model_types(); *t; ++t) {
        const unsigned f = tirenv_model_type_flags(*t);
        if ((f & with) == with && !(f & without))
            fprintf(fp, " %s", tirenv_model_type_name(*t));
    }
    fprintf(fp, "%s\n", fallback);
}

void cli_help_obstacle(FILE *fp)
{
    fputs("obstacle (exactly one; lengths in m, centred at x = 0):\n"
          "  --cleat L,H          rectangular cleat\n"
          "  --step X0,H          step of height H at X0 (H < 0 steps down)\n"
          "  --trapezoid LTOP,LBASE,H\n"
          "  --triangle L,H       triangle of base L\n"
          "  --cylinder R         half-cylinder of radius R\n"
          "  --sine A,WAVELENGTH,PERIODS\n"
          "                       z = A*(1 - cos(2*pi*x/WAVELENGTH)) from x = 0\n"
          "  --profile FILE       a road file, its format told by its content: a profile CSV\n"
          "                       (header x_m,z_m, one vertex per line), an OpenCRG road\n"
          "                       (.crg) or a TNO/Adams 2-D road (.rdf); docs/formats.md\n"
          "                       sections 4 and 5\n",
          fp);
}

/* ---- the obstacle ----------------------------------------------------------------------- */

int cli_obstacle(const cli_options *o, tirenv_profile **out)
{
    const double *s = o->shape;
    const tirenv_profile_resolution res = tirenv_profile_resolution_default();
    *out = NULL;
    switch (o->obstacle) {
    case CLI_CLEAT: *out = tirenv_profile_cleat(s[0], s[1]); break;
    case CLI_STEP: *out = tirenv_profile_step(s[0], s[1]); break;
    case CLI_TRAPEZOID: *out = tirenv_profile_trapezoid(s[0], s[1], s[2]); break;
    case CLI_TRIANGLE: *out = tirenv_profile_triangle(s[0], s[1]); break;
    case CLI_CYLINDER: *out = tirenv_profile_half_cylinder(s[0], res.cylinder_segments); break;
    case CLI_SINE:
        *out = tirenv_profile_sine(s[0], s[1], s[2], res.sine_points_per_period);
        break;
    case CLI_PROFILE:  /* a file: cli_road_read's (road.c) */
    default:
        cli_error("an obstacle option is required (--cleat, --step, --trapezoid, --triangle, "
                  "--cylinder, --sine or --profile)");
        return CLI_EXIT_USAGE;
    }
    if (*out)
        return CLI_EXIT_OK;
    /* The generators refuse non-positive sizes (and a zero step) with NULL, and so does the
     * profile check sizes beyond its limits (tirenv/profile.h). */
    const size_t i = obstacle_index(o->obstacle);
    const char *why = o->obstacle == CLI_STEP        ? "H nonzero"
                      : o->obstacle == CLI_TRAPEZOID ? "all positive, LBASE >= LTOP"
                                                     : "all positive";
    cli_error("--%s %s: not a valid obstacle; expected %s, %s, sizes up to %g m",
              obstacles[i].name, o->obstacle_arg, obstacles[i].expected, why,
              TIRENV_PROFILE_MAX_SEGMENT);
    return CLI_EXIT_DATA;
}

void cli_obstacle_label(const cli_options *o, char *buf, size_t n)
{
    if (o->obstacle == CLI_PROFILE || !o->obstacle)
        snprintf(buf, n, "%s", o->obstacle_arg ? o->obstacle_arg : "");
    else
        snprintf(buf, n, "--%s %s", obstacles[obstacle_index(o->obstacle)].name,
                 o->obstacle_arg);
}
