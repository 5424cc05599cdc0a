/* tirenv road: a random road of an ISO 8608 class, as a profile CSV.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/csv_row.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv road --class A..H --length M [--dx M] [--seed S] [-o FILE]\n"
          "                   [--band NMIN,NMAX] [--waviness W]\n"
          "\n"
          "A random road profile of an ISO 8608 road class: displacement PSD\n"
          "Gd(n) = Gd(n0)*(n/n0)^-2 with n0 = 0.1 cycles/m and Gd(n0) = 16e-6 m^3 (class A),\n"
          "4 times more per class up to H, as a sum of cosines with seeded random phases.\n"
          "Writes a profile CSV 'x_m,z_m' (vertices every --dx from x = 0, starting at z = 0)\n"
          "that --profile reads; a one-line summary goes to standard error.\n"
          "\n"
          "options:\n"
          "  --class C            road class, A (smoothest) to H\n"
          "  --length M           road length, m\n"
          "  --dx DX              vertex spacing, m (default 0.01; at most 1/(2*NMAX))\n"
          "  --seed S             seed of the random phases (default 1)\n"
          "  --band NMIN,NMAX     spatial frequencies generated, cycles/m (default the\n"
          "                       standard's 0.011,2.83)\n"
          "  --waviness W         exponent of the PSD (default 2, the standard's)\n"
          "  -o, --output FILE    write the CSV to FILE, complete or not at all (default or\n"
          "                       '-': standard output)\n"
          "  -h, --help           show this help\n",
          fp);
}

static int parse_class(void *dst, const char *arg)
{
    tirenv_road_settings *s = dst;
    if (strlen(arg) != 1 || isnan(tirenv_iso8608_gd0(arg[0]))) {
        cli_error("road: --class expects one letter A to H, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    s->road_class = arg[0];
    return CLI_EXIT_OK;
}

static int parse_band(void *dst, const char *arg)
{
    tirenv_road_settings *s = dst;
    double band[2];
    if (cli_parse_doubles(arg, band, 2) || !(band[0] > 0 && band[1] > band[0])) {
        cli_error("road: --band expects NMIN,NMAX in cycles/m with 0 < NMIN < NMAX, got '%s'",
                  arg);
        return CLI_EXIT_USAGE;
    }
    s->n_min = band[0];
    s->n_max = band[1];
    return CLI_EXIT_OK;
}

static int parse_waviness(void *dst, const char *arg)
{
    double *w = dst;
    if (cli_parse_double(arg, w) || !(*w >= 0)) {
        cli_error("road: --waviness expects a number >= 0, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* Parses the options into *s; returns an exit code, or CLI_GO_ON. */
static int parse(int argc, char *argv[], tirenv_road_settings *s, const char **out_path)
{
    const char unset = '\0';
    s->road_class = unset;
    s->length = NAN;
    long seed = (long)s->seed;
    const cli_opt own[] = {
        {.name = "class", .kind = CLI_CUSTOM, .dst = s, .parse = parse_class},
        {.name = "length", .kind = CLI_POSITIVE, .dst = &s->length,
         .what = "a positive length in m"},
        {.name = "dx", .kind = CLI_POSITIVE, .dst = &s->dx, .what = "a positive length in m"},
        {.name = "seed", .kind = CLI_COUNT, .dst = &seed, .min = 0, .max = 2147483647L,
         .what = "a whole number >= 0"},
        {.name = "band", .kind = CLI_CUSTOM, .dst = s, .parse = parse_band},
        {.name = "waviness", .kind = CLI_CUSTOM, .dst = &s->waviness, .parse = parse_waviness},
        {.name = NULL},
    };
    const cli_parser p = {.name = "road", .usage = usage, .opts = own, .groups = CLI_OUTPUT};
    cli_options o;
    const int code = cli_parse(&p, argc, argv, &o);
    if (code != CLI_GO_ON)
        return code;
    s->seed = (unsigned long)seed;
    if (o.output)
        *out_path = o.output;
    if (s->road_class == unset || isnan(s->length)) {
        cli_error("road: expected %s; 'tirenv road --help' shows the options",
                  s->road_class == unset ? "--class A..H" : "--length M");
        return CLI_EXIT_USAGE;
    }
    return CLI_GO_ON;
}

/* The data rows; the header and comment lines are written before. */
static void write_csv(FILE *fp, const tirenv_profile *p)
{
    const size_t n = tirenv_profile_size(p);
    const double *x = tirenv_profile_x(p), *z = tirenv_profile_z(p);
    for (size_t j = 0; j < n; ++j) {  /* as "%.10g,%.9g\n" */
        char row[2 * CLI_ROW_FIELD], *r = row;
        r = cli_row_g(r, x[j], 10, ',');
        r = cli_row_g(r, z[j], 9, '\n');
        fwrite(row, 1, (size_t)(r - row), fp);
    }
}

int cli_road_main(int argc, char *argv[])
{
    tirenv_road_settings s = tirenv_road_default();
    const char *out_path = "-";
    const int code = parse(argc, argv, &s, &out_path);
    if (code != CLI_GO_ON)
        return code;

    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_profile *p = NULL;
    tirenv_outfile *out;
    /* Generated first: a refused setting must not leave an empty file behind. */
    int status = tirenv_road_iso8608(&s, &p, &diag);
    if (!status && !(status = tirenv_outfile_open(&out, out_path, &diag))) {
        char comment[512];
        snprintf(comment, sizeof comment,
                 "ISO 8608 class %c random road (tirenv road): Gd(n0) = %g m^3 at n0 = %g "
                 "cycles/m, waviness %g,\nspatial frequencies %g to %g cycles/m, length %g m, "
                 "dx %g m, seed %lu",
                 s.road_class, tirenv_iso8608_gd0(s.road_class), TIRENV_ISO8608_N0,
                 s.waviness, s.n_min, s.n_max, s.length, s.dx, s.seed);
        fputs("x_m,z_m\n", tirenv_outfile_stream(out));
        tirenv_outfile_comment(out, comment);
        write_csv(tirenv_outfile_stream(out), p);
        status = tirenv_outfile_commit(out, &diag);  /* it checks the writes */
    }
    if (status) {
        tirenv_profile_free(p);
        return cli_fail(status, &diag);
    }
    const size_t n = tirenv_profile_size(p);
    const double *z = tirenv_profile_z(p);
    double sum = 0, sum2 = 0;
    for (size_t j = 0; j < n; ++j) {
        sum += z[j];
        sum2 += z[j] * z[j];
    }
    const double mean = sum / (double)n, rms = sqrt(fmax(0.0, sum2 / (double)n - mean * mean));
    fprintf(stderr, "tirenv road: ISO 8608 class %c, %zu points over %g m every %g m, "
            "rms %.2f mm about the mean, seed %lu\n", s.road_class, n,
            tirenv_profile_x(p)[n - 1], s.dx, rms * 1e3, s.seed);
    tirenv_profile_free(p);
    return CLI_EXIT_OK;
}
