/* tirenv envelope: the enveloping curve of one model over one obstacle, as CSV.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"

/* The default sweep starts and ends this far beyond the tire's first and last reach, m. */
static const double margin = 0.02;
static const double default_dx = 0.001;  /* m */
static const double rise_threshold = 1e-4;  /* first rise: h above 0.1 mm, m */

static void usage(FILE *fp)
{
    fputs("usage: tirenv envelope --model NAME OBSTACLE (--load N | --contact-length M)\n"
          "                       [--x-from X] [--x-to X] [--dx DX] [-o FILE]\n"
          "                       [--tire FILE] [--set KEY=VALUE]... [--method M]\n"
          "\n"
          "The enveloping curve h(x) = z(x) - z_flat of the tire over an obstacle at constant\n"
          "vertical load, one CSV row per centre position x:\n"
          "  x_m,z_m,h_m,fx_N,fz_N,contacts,iterations\n"
          "A one-line summary (peak, first rise, iterations) goes to standard error.\n"
          "\n"
          "options:\n",
          fp);
    cli_help_model(fp, "");
    fputs("  --model nn --nn FILE the trained network (tirenv train); cleats only, the rows\n"
          "                       as 'tirenv predict' writes them\n",
          fp);
    cli_help_load(fp);
    fputs("  --x-from X, --x-to X first and last centre position, m; default: from R0 + 0.02 m\n"
          "                       before the obstacle's first vertex to R0 + 0.02 m after its\n"
          "                       last\n"
          "  --dx DX              spacing of the positions, m (default 0.001)\n"
          "  -o, --output FILE    write the CSV to FILE, complete or not at all (default or\n"
          "                       '-': standard output)\n",
          fp);
    cli_help_tire(fp, 1);
    fputs("  -h, --help           show this help\n", fp);
    cli_help_obstacle(fp);
}

typedef struct {
    int have_from, have_to;
    double x_from, x_to, dx;  /* m */
} sweep;

static int write_csv(FILE *fp, size_t n, const tirenv_point pt[])
{
    fputs("x_m,z_m,h_m,fx_N,fz_N,contacts,iterations\n", fp);
    for (size_t k = 0; k < n; ++k)
        fprintf(fp, "%.9g,%.9g,%.9g,%.9g,%.9g,%zu,%zu\n", pt[k].x, pt[k].z, pt[k].h, pt[k].fx,
                pt[k].fz, pt[k].contacts, pt[k].iterations);
    return ferror(fp) ? -1 : 0;
}

/* What a reader wants at a glance: where the curve peaks, where it starts to rise, and what
 * the equilibrium cost. The rigid disc has no contact length of its own, so it shows the one
 * asked for, if any. */
static void summary(tirenv_model *m, const cli_options *o, double load, size_t n,
                    const tirenv_point pt[])
{
    tirenv_flat flat;
    double l_c = 0;
    if (tirenv_model_flat(m, load, &flat, NULL) == TIRENV_OK)
        l_c = flat.contact_length;
    if (!(l_c > 0) && o->have_contact_length)
        l_c = o->contact_length;
    size_t peak = 0, rise = n, it_max = 0;
    double it_sum = 0;
    for (size_t k = 0; k < n; ++k) {
        if (pt[k].h > pt[peak].h)
            peak = k;
        if (rise == n && pt[k].h > rise_threshold)
            rise = k;
        it_sum += (double)pt[k].iterations;
        if (pt[k].iterations > it_max)
            it_max = pt[k].iterations;
    }
    char lc_text[64] = "no contact length";
    if (l_c > 0)
        snprintf(lc_text, sizeof lc_text, "contact length %.4g m", l_c);
    char rise_text[64] = "no rise above 0.1 mm";
    if (rise < n)
        snprintf(rise_text, sizeof rise_text, "first rise at x = %.4f m", pt[rise].x);
    fprintf(stderr,
            "tirenv envelope: %s model, load %.6g N (%s), %zu positions: peak h %.3f mm at "
            "x = %.4f m, %s, iterations per position mean %.2f max %zu\n",
            tirenv_model_name(m), load, lc_text, n, pt[peak].h * 1e3, pt[peak].x, rise_text,
            it_sum / (double)n, it_max);
}

/* Parses the options; returns an exit code, or -1 to go on. */
static int parse(int argc, char *argv[], cli_options *o, const tirenv_model_type **type,
                 sweep *s, const char **out_path)
{
    enum { OPT_MODEL = CLI_OPT_FIRST_OWN, OPT_X_FROM, OPT_X_TO, OPT_DX };
    static const struct option longopts[] = {
        CLI_TIRE_LONGOPTS,
        CLI_METHOD_LONGOPTS,
        CLI_LOAD_LONGOPTS,
        CLI_OBSTACLE_LONGOPTS,
        {"model", required_argument, NULL, OPT_MODEL},
        {"x-from", required_argument, NULL, OPT_X_FROM},
        {"x-to", required_argument, NULL, OPT_X_TO},
        {"dx", required_argument, NULL, OPT_DX},
        {"output", required_argument, NULL, 'o'},
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    int c, longindex = 0;
    cli_getopt_reset();
    while ((c = getopt_long(argc, argv, "ho:", longopts, &longindex)) != -1) {
        switch (c) {
        case 'h':
            usage(stdout);
            return CLI_EXIT_OK;
        case 'o':
            *out_path = optarg;
            break;
        case OPT_MODEL:
            if (cli_model_type(optarg, type))
                return CLI_EXIT_USAGE;
            break;
        case OPT_X_FROM:
        case OPT_X_TO:
        case OPT_DX: {
            double *v = c == OPT_X_FROM ? &s->x_from : c == OPT_X_TO ? &s->x_to : &s->dx;
            if (cli_parse_double(optarg, v)) {
                cli_error("--%s: expected a number in m, got '%s'", longopts[longindex].name,
                          optarg);
                return CLI_EXIT_USAGE;
            }
            s->have_from |= c == OPT_X_FROM;
            s->have_to |= c == OPT_X_TO;
            break;
        }
        case '?':
            usage(stderr);
            return CLI_EXIT_USAGE;
        default:
            if (cli_option(o, c, optarg))
                return CLI_EXIT_USAGE;
        }
    }
    if (optind < argc) {
        cli_error("envelope: unexpected argument '%s'", argv[optind]);
        return CLI_EXIT_USAGE;
    }
    const char *missing = NULL;
    if (!*type)
        missing = "--model NAME";
    else if (!o->obstacle)
        missing = "an obstacle option";
    else if (!o->have_load && !o->have_contact_length)
        missing = "--load N or --contact-length M";
    if (missing) {
        cli_error("envelope: expected %s; 'tirenv envelope --help' shows the options", missing);
        return CLI_EXIT_USAGE;
    }
    return -1;
}

int cli_envelope_main(int argc, char *argv[])
{
    /* --model nn: the network, which reads --nn FILE (cmd_predict.c). */
    if (cli_predict_is_nn(argc, argv))
        return cli_predict_main(argc, argv);
    cli_options o;
    cli_options_init(&o);
    const tirenv_model_type *type = NULL;
    sweep s = {.dx = default_dx};
    const char *out_path = "-";
    int code = parse(argc, argv, &o, &type, &s, &out_path);
    if (code >= 0)
        return code;

    tirenv_tire tire;
    tirenv_model *m = NULL;
    tirenv_profile *prof = NULL;
    double *x = NULL;
    tirenv_point *pt = NULL;
    size_t n = 0;
    double load = 0;
    if ((code = cli_tire(&o, &tire)) || (code = cli_profile(&o, &prof)) ||
        (code = cli_model(type, &tire, &m)) || (code = cli_load(&o, m, &load)))
        goto done;
    double first, last;
    tirenv_profile_extent(prof, &first, &last);
    if (!s.have_from)
        s.x_from = first - tire.springs.R0 - margin;
    if (!s.have_to)
        s.x_to = last + tire.springs.R0 + margin;
    if ((code = cli_positions(s.x_from, s.x_to, s.dx, &x, &n)))
        goto done;
    if (!(pt = malloc(n * sizeof *pt))) {
        code = cli_fail(TIRENV_ENOMEM, NULL);
        goto done;
    }

    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_outfile out;
    int status = tirenv_model_set(m, prof, load, &diag);
    /* Opened before the sweep so that a bad -o path fails at once, not after it. */
    if (!status && !(status = tirenv_outfile_open(&out, out_path, &diag))) {
        status = tirenv_model_envelope(m, n, x, pt, NULL, &diag);
        if (!status && write_csv(out.fp, n, pt))
            status = tirenv_error(&diag, TIRENV_EIO, out_path, 0, "", "write failed");
        if (!status)
            status = tirenv_outfile_commit(&out, &diag);
        else
            tirenv_outfile_abort(&out);
    }
    if (status) {
        code = cli_fail(status, &diag);
        goto done;
    }
    summary(m, &o, load, n, pt);
    code = CLI_EXIT_OK;
done:
    free(pt);
    free(x);
    tirenv_model_free(m);
    tirenv_profile_free(prof);
    return code;
}
