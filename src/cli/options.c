/* What the subcommands share: number parsing, the tire / load / obstacle options, and the
 * mapping from library status to exit code. SPDX-License-Identifier: GPL-3.0-or-later */
#include "cli/cli.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Resolution of the generated curved obstacles: a 1 degree polygon for the cylinder and 64
 * vertices per sine period keep the polyline within 0.02 % of the curve's height. */
enum { CYLINDER_SEGMENTS = 180, SINE_POINTS_PER_PERIOD = 64 };

void cli_error(const char *fmt, ...)
{
    va_list ap;
    fputs("tirenv: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

int cli_exit_code(int status)
{
    switch (status) {
    case TIRENV_OK:
        return CLI_EXIT_OK;
    case TIRENV_ENOBRACKET:
    case TIRENV_ENOCONV:
    case TIRENV_ECONTINUE:
        return CLI_EXIT_NUMERIC;
    default:  /* EINVAL, EIO, EPARSE, ERANGE, ENOMEM: the input (or the machine) is at fault */
        return CLI_EXIT_DATA;
    }
}

int cli_fail(int status, const tirenv_diag *diag)
{
    char buf[1200];
    if (diag && (diag->message[0] || diag->file[0] || diag->field[0]))
        cli_error("%s", tirenv_diag_format(diag, buf, sizeof buf));
    else
        cli_error("%s", tirenv_strerror(status));
    return cli_exit_code(status);
}

double cli_cpu_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double cli_wall_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int cli_mkdir(const char *dir)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_mkdir_p(dir, &diag);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

int cli_parse_double(const char *s, double *v)
{
    char *end;
    errno = 0;
    const double d = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE || !isfinite(d))
        return -1;
    *v = d;
    return 0;
}

/* Splits on commas without copying: strtod stops at the comma, which is then required. */
int cli_parse_doubles(const char *s, double v[], size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        char *end;
        errno = 0;
        v[i] = strtod(s, &end);
        if (end == s || errno == ERANGE || !isfinite(v[i]))
            return -1;
        if (i + 1 < n ? *end != ',' : *end != '\0')
            return -1;
        s = end + 1;
    }
    return 0;
}

int cli_parse_count(const char *s, long min, long max, long *v)
{
    char *end;
    errno = 0;
    const long l = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE || l < min || l > max)
        return -1;
    *v = l;
    return 0;
}

void cli_options_init(cli_options *o)
{
    memset(o, 0, sizeof *o);
}

void cli_getopt_reset(void)
{
    optind = 0;
}

/* The numbers each obstacle option takes, and how to say so when they are malformed. */
static const struct {
    int code;
    const char *name;
    size_t n;
    const char *expected;
} obstacles[] = {
    {CLI_OPT_CLEAT, "cleat", 2, "L,H: length and height in m"},
    {CLI_OPT_STEP, "step", 2, "X0,H: position and height in m (H < 0 steps down)"},
    {CLI_OPT_TRAPEZOID, "trapezoid", 3, "LTOP,LBASE,H: top and base lengths and height in m"},
    {CLI_OPT_TRIANGLE, "triangle", 2, "L,H: base length and height in m"},
    {CLI_OPT_CYLINDER, "cylinder", 1, "R: radius in m"},
    {CLI_OPT_SINE, "sine", 3, "A,WAVELENGTH,PERIODS: amplitude and wavelength in m, periods"},
    {CLI_OPT_PROFILE, "profile", 0, "FILE.csv with header x_m,z_m"},
};

enum { N_OBSTACLES = sizeof obstacles / sizeof obstacles[0] };

/* Index of an obstacle option in the table, or N_OBSTACLES if code is none of them. */
static size_t obstacle_index(int code)
{
    size_t i = 0;
    while (i < N_OBSTACLES && obstacles[i].code != code)
        ++i;
    return i;
}

int cli_option(cli_options *o, int code, const char *arg)
{
    switch (code) {
    case CLI_OPT_TIRE:
        o->tire_path = arg;
        return CLI_EXIT_OK;
    case CLI_OPT_SET:
        if (o->n_sets == CLI_MAX_SETS) {
            cli_error("--set: at most %d assignments", CLI_MAX_SETS);
            return CLI_EXIT_USAGE;
        }
        o->sets[o->n_sets++] = arg;
        return CLI_EXIT_OK;
    case CLI_OPT_METHOD:
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
    case CLI_OPT_LOAD:
    case CLI_OPT_CONTACT_LENGTH: {
        const int is_load = code == CLI_OPT_LOAD;
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
    default:
        break;
    }
    /* An obstacle option; anything else is a subcommand's code it forgot to handle. */
    const size_t i = obstacle_index(code);
    if (i == N_OBSTACLES) {
        cli_error("internal error: unhandled option code %d", code);
        return CLI_EXIT_USAGE;
    }
    if (o->obstacle && o->obstacle != code) {
        cli_error("--%s: only one obstacle option may be given (already --%s)",
                  obstacles[i].name, obstacles[obstacle_index(o->obstacle)].name);
        return CLI_EXIT_USAGE;
    }
    if (obstacles[i].n && cli_parse_doubles(arg, o->shape, obstacles[i].n)) {
        cli_error("--%s: expected %s, got '%s'", obstacles[i].name, obstacles[i].expected, arg);
        return CLI_EXIT_USAGE;
    }
    o->obstacle = code;
    o->obstacle_arg = arg;
    return CLI_EXIT_OK;
}

void cli_help_tire(FILE *fp, int with_method)
{
    fputs("  --tire FILE          tire property file (.tir); default: tires/default.tir in\n"
          "                       the data directory ($TIRENV_DATA, else the installed data)\n"
          "  --set KEY=VALUE      override one .tir key after reading the file (repeatable,\n"
          "                       applied in order), e.g. --set RADIAL_STIFFNESS=1.8e6\n",
          fp);
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

void cli_help_model(FILE *fp, const char *fallback)
{
    fputs("  --model NAME         one of", fp);
    for (const tirenv_model_type *const *t = tirenv_model_types(); *t; ++t)
        fprintf(fp, " %s", tirenv_model_type_name(*t));
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
          "  --profile FILE.csv   measured profile: header x_m,z_m, one vertex per line\n",
          fp);
}

const char *cli_tire_path(const cli_options *o, char *buf, size_t n)
{
    return o->tire_path ? o->tire_path : cli_data_path("tires/default.tir", buf, n);
}

int cli_tire(const cli_options *o, tirenv_tire *tire)
{
    char buf[1024];
    const char *path = cli_tire_path(o, buf, sizeof buf);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    *tire = tirenv_tire_default();
    int status = tirenv_tir_read(path, tire, &diag);
    if (status)
        return cli_fail(status, &diag);
    for (size_t i = 0; i < o->n_sets; ++i) {
        status = tirenv_tir_set(tire, o->sets[i], &diag);
        if (status && diag.file[0])  /* already says "--set: KEY: ..." */
            return cli_fail(status, &diag);
        if (status) {
            char msg[1200];
            cli_error("--set %s: %s", o->sets[i], tirenv_diag_format(&diag, msg, sizeof msg));
            return cli_exit_code(status);
        }
    }
    if (o->have_method)
        tire->eq.method = o->method;
    /* Checked here, not left to tirenv_model_alloc, which can only say NULL. */
    status = tirenv_tire_check(tire, &diag);
    if (status) {
        char msg[1200];
        cli_error("tire from %s%s: %s", path, o->n_sets ? " and --set" : "",
                  tirenv_diag_format(&diag, msg, sizeof msg));
        return cli_exit_code(status);
    }
    return CLI_EXIT_OK;
}

int cli_model_type(const char *name, const tirenv_model_type **type)
{
    *type = tirenv_model_type_find(name);
    if (*type)
        return CLI_EXIT_OK;
    fputs("tirenv: --model: expected one of", stderr);
    for (const tirenv_model_type *const *t = tirenv_model_types(); *t; ++t)
        fprintf(stderr, " %s", tirenv_model_type_name(*t));
    fprintf(stderr, ", got '%s'\n", name);
    return CLI_EXIT_USAGE;
}

int cli_model(const tirenv_model_type *type, const tirenv_tire *tire, tirenv_model **out)
{
    *out = tirenv_model_alloc(type, tire);
    if (!*out)  /* the tire was checked: only memory is left */
        return cli_fail(TIRENV_ENOMEM, NULL);
    return CLI_EXIT_OK;
}

int cli_load(const cli_options *o, tirenv_model *m, double *load)
{
    if (o->have_load) {
        *load = o->load;
        return CLI_EXIT_OK;
    }
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status =
        tirenv_model_load_for_contact_length(m, o->contact_length, load, &diag);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

int cli_profile(const cli_options *o, tirenv_profile **out)
{
    const double *s = o->shape;
    *out = NULL;
    switch (o->obstacle) {
    case CLI_OPT_PROFILE: {
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        const int status = tirenv_profile_read_csv(o->obstacle_arg, out, &diag);
        return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
    }
    case CLI_OPT_CLEAT: *out = tirenv_profile_cleat(s[0], s[1]); break;
    case CLI_OPT_STEP: *out = tirenv_profile_step(s[0], s[1]); break;
    case CLI_OPT_TRAPEZOID: *out = tirenv_profile_trapezoid(s[0], s[1], s[2]); break;
    case CLI_OPT_TRIANGLE: *out = tirenv_profile_triangle(s[0], s[1]); break;
    case CLI_OPT_CYLINDER: *out = tirenv_profile_half_cylinder(s[0], CYLINDER_SEGMENTS); break;
    case CLI_OPT_SINE:
        *out = tirenv_profile_sine(s[0], s[1], s[2], SINE_POINTS_PER_PERIOD);
        break;
    default:
        cli_error("an obstacle option is required (--cleat, --step, --trapezoid, --triangle, "
                  "--cylinder, --sine or --profile)");
        return CLI_EXIT_USAGE;
    }
    if (*out)
        return CLI_EXIT_OK;
    /* The generators refuse non-positive sizes (and a zero step) with NULL. */
    const size_t i = obstacle_index(o->obstacle);
    const char *why = o->obstacle == CLI_OPT_STEP        ? "H nonzero"
                      : o->obstacle == CLI_OPT_TRAPEZOID ? "all positive, LBASE >= LTOP"
                                                         : "all positive";
    cli_error("--%s %s: not a valid obstacle; expected %s, %s", obstacles[i].name,
              o->obstacle_arg, obstacles[i].expected, why);
    return CLI_EXIT_DATA;
}

/* Positions x_k = x_from + k*dx up to x_to (with a 1e-9 dx allowance for round-off), by
 * multiplication so that no error accumulates over thousands of steps. */
int cli_positions(double x_from, double x_to, double dx, double **x_out, size_t *n_out)
{
    if (!(dx > 0) || !(x_to >= x_from)) {
        cli_error("expected --dx > 0 and --x-to >= --x-from, got dx %g m from %g to %g m", dx,
                  x_from, x_to);
        return CLI_EXIT_USAGE;
    }
    const double steps = floor((x_to + dx * 1e-9 - x_from) / dx);
    if (!(steps < CLI_MAX_POSITIONS)) {
        cli_error("%.0f positions is too many (at most %.0f); raise --dx", steps + 1,
                  CLI_MAX_POSITIONS);
        return CLI_EXIT_USAGE;
    }
    const size_t n = tirenv_positions_count(x_from, x_to, dx);
    double *x = malloc(n * sizeof *x);
    if (!x)
        return cli_fail(TIRENV_ENOMEM, NULL);
    for (size_t k = 0; k < n; ++k)
        x[k] = x_from + (double)k * dx;
    *x_out = x;
    *n_out = n;
    return CLI_EXIT_OK;
}
