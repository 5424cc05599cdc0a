/* tirenv envelope: the enveloping curve of one model over one obstacle, as CSV.
 * SPDX-License-Identifier: GPL-3.0-or-later */
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
          "                       [--x-from X] [--x-to X] [--dx DX] [--stream] [-o FILE]\n"
          "                       [--tire FILE] [--set KEY=VALUE]... [--method M]\n"
          "\n"
          "The enveloping curve h(x) = z(x) - z_flat of the tire over an obstacle at constant\n"
          "vertical load, one CSV row per centre position x:\n"
          "  x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations\n"
          "slope is the effective road slope tan(beta) = -fx/fz, the inclination of the ground\n"
          "force (for the cam exactly (Z_f - Z_r)/l_s, docs/models.md section 7).\n"
          "A one-line summary (peak, first rise, iterations) goes to standard error.\n"
          "\n"
          "options:\n",
          fp);
    cli_help_model(fp, "");
    fputs("  --model nn --nn FILE the trained network (tirenv train), the rows as 'tirenv\n"
          "                       predict' writes them: over --cleat the paper's curve, over\n"
          "                       any other obstacle or --profile an extension beyond the\n"
          "                       paper (equivalent cleats; 'tirenv predict --help'); no\n"
          "                       --stream\n",
          fp);
    cli_help_load(fp);
    fputs("  --x-from X, --x-to X first and last centre position, m; default: from R0 + 0.02 m\n"
          "                       before the obstacle's first vertex to R0 + 0.02 m after its\n"
          "                       last\n"
          "  --dx DX              spacing of the positions, m (default 0.001)\n"
          "  --stream             with --profile: read the file as the tire rolls, in memory\n"
          "                       bounded by the tire's reach whatever the road's length (the\n"
          "                       file is read twice: first to check it and find its ends)\n"
          "  -o, --output FILE    write the CSV to FILE, complete or not at all (default or\n"
          "                       '-': standard output)\n"
          "  --detail             with --model ring: two more columns, tread_max_m (the\n"
          "                       largest tread compression) and belt_contacts (nodes where\n"
          "                       the belt itself touches the ground), from one more ring\n"
          "                       evaluation at each row's (x, z); not with --stream\n",
          fp);
    cli_help_tire(fp, 1);
    fputs("  -h, --help           show this help\n", fp);
    cli_help_obstacle(fp);
}

typedef struct {
    int stream;            /* --stream */
    int detail;            /* --detail */
    int have_from, have_to;
    double x_from, x_to, dx;  /* m */
} sweep;

static const char header[] = "x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations\n";

static void write_row(FILE *fp, const tirenv_point *pt)
{
    fprintf(fp, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%zu,%zu\n", pt->x, pt->z, pt->h, pt->slope,
            pt->fx, pt->fz, pt->contacts, pt->iterations);
}

/* --detail: each row and the ring's own state at its (x, z), from a ring of its own (the
 * model's evaluations are the equilibrium's; this one is at the accepted point). */
static int write_detail(FILE *fp, const tirenv_tire *tire, const tirenv_profile *prof,
                        const tirenv_point pt[], size_t n, tirenv_diag *diag)
{
    tirenv_ring *r = tirenv_ring_alloc(tire->springs.R0, &tire->ring);
    if (!r)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    fputs("x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations,tread_max_m,belt_contacts\n", fp);
    int status = TIRENV_OK;
    for (size_t k = 0; k < n && !status; ++k) {
        double fx, fz;
        status = tirenv_ring_forces(r, prof, pt[k].x, pt[k].z, &fx, &fz, NULL, NULL);
        if (status) {
            status = tirenv_error(diag, status, "", 0, "", "ring at x = %g m, z = %g m: no "
                                  "contact solution", pt[k].x, pt[k].z);
            break;
        }
        fprintf(fp, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%zu,%zu,%.9g,%zu\n", pt[k].x, pt[k].z,
                pt[k].h, pt[k].slope, pt[k].fx, pt[k].fz, pt[k].contacts, pt[k].iterations,
                tirenv_ring_tread_max(r), tirenv_ring_belt_contacts(r));
    }
    tirenv_ring_free(r);
    return status;
}

/* What a reader wants at a glance, gathered point by point so that a streamed sweep, which
 * keeps no points, gives the same line: where the curve peaks, where it starts to rise, and
 * what the equilibrium cost. */
typedef struct {
    size_t n;
    tirenv_point peak;
    int have_rise;
    double rise_x;         /* m */
    double it_sum;
    size_t it_max;
} tally;

static void tally_add(tally *t, const tirenv_point *pt)
{
    if (t->n == 0 || pt->h > t->peak.h)
        t->peak = *pt;
    if (!t->have_rise && pt->h > rise_threshold) {
        t->have_rise = 1;
        t->rise_x = pt->x;
    }
    t->it_sum += (double)pt->iterations;
    if (pt->iterations > t->it_max)
        t->it_max = pt->iterations;
    t->n++;
}

/* The rigid disc has no contact length of its own, so it shows the one asked for, if any. */
static void summary(tirenv_model *m, const cli_options *o, double load, const tally *t)
{
    tirenv_flat flat;
    double l_c = 0;
    if (tirenv_model_flat(m, load, &flat, NULL) == TIRENV_OK)
        l_c = flat.contact_length;
    if (!(l_c > 0) && o->have_contact_length)
        l_c = o->contact_length;
    char lc_text[64] = "no contact length";
    if (l_c > 0)
        snprintf(lc_text, sizeof lc_text, "contact length %.4g m", l_c);
    char rise_text[64] = "no rise above 0.1 mm";
    if (t->have_rise)
        snprintf(rise_text, sizeof rise_text, "first rise at x = %.4f m", t->rise_x);
    fprintf(stderr,
            "tirenv envelope: %s model, load %.6g N (%s), %zu positions: peak h %.3f mm at "
            "x = %.4f m, %s, iterations per position mean %.2f max %zu\n",
            tirenv_model_name(m), load, lc_text, t->n, t->peak.h * 1e3, t->peak.x, rise_text,
            t->n ? t->it_sum / (double)t->n : 0.0, t->it_max);
}

/* The streamed sweep's sink: one row out and into the tally per position. */
typedef struct {
    FILE *fp;
    tally t;
} stream_out;

static int stream_row(void *ctx, const tirenv_point *pt)
{
    stream_out *s = ctx;
    write_row(s->fp, pt);
    tally_add(&s->t, pt);
    return ferror(s->fp) ? TIRENV_EIO : TIRENV_OK;
}

/* Parses the options; returns an exit code, or -1 to go on. */
static int parse(int argc, char *argv[], cli_options *o, const tirenv_model_type **type,
                 sweep *s, const char **out_path)
{
    enum { OPT_MODEL = CLI_OPT_FIRST_OWN, OPT_X_FROM, OPT_X_TO, OPT_DX, OPT_STREAM, OPT_DETAIL };
    static const struct option longopts[] = {
        CLI_TIRE_LONGOPTS,
        CLI_METHOD_LONGOPTS,
        CLI_LOAD_LONGOPTS,
        CLI_OBSTACLE_LONGOPTS,
        {"model", required_argument, NULL, OPT_MODEL},
        {"x-from", required_argument, NULL, OPT_X_FROM},
        {"x-to", required_argument, NULL, OPT_X_TO},
        {"dx", required_argument, NULL, OPT_DX},
        {"stream", no_argument, NULL, OPT_STREAM},
        {"detail", no_argument, NULL, OPT_DETAIL},
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
        case OPT_STREAM:
            s->stream = 1;
            break;
        case OPT_DETAIL:
            s->detail = 1;
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
    else if (s->stream && o->obstacle != CLI_OPT_PROFILE)
        missing = "--profile FILE with --stream";
    else if (s->detail && (*type != tirenv_model_ring || s->stream))
        missing = "--model ring and no --stream with --detail";
    if (missing) {
        cli_error("envelope: expected %s; 'tirenv envelope --help' shows the options", missing);
        return CLI_EXIT_USAGE;
    }
    return -1;
}

/* The first pass of --stream: checks the whole file (so that a bad row late in it fails
 * before any output) and finds its first and last x, in constant memory. */
static int stream_extent(const char *path, double *first, double *last, tirenv_diag *diag)
{
    tirenv_profile_reader *r;
    int status = tirenv_profile_reader_open(path, &r, diag);
    int got = 1;
    for (size_t k = 0; !status && got; ++k) {
        double x, z;
        status = tirenv_profile_reader_next(r, &x, &z, &got, diag);
        if (!status && got) {
            if (k == 0)
                *first = x;
            *last = x;
        }
    }
    tirenv_profile_reader_free(r);
    return status;
}

/* --stream: rows go out as they are computed; the output file is still all or nothing. */
static int envelope_stream(const cli_options *o, const tirenv_tire *tire, tirenv_model *m,
                           double load, sweep *s, const char *out_path)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    double first = 0, last = 0;
    int status = stream_extent(o->obstacle_arg, &first, &last, &diag);
    if (status)
        return cli_fail(status, &diag);
    if (!s->have_from)
        s->x_from = first - tire->springs.R0 - margin;
    if (!s->have_to)
        s->x_to = last + tire->springs.R0 + margin;
    if (!(s->dx > 0) || !(s->x_to >= s->x_from)) {
        cli_error("expected --dx > 0 and --x-to >= --x-from, got dx %g m from %g to %g m",
                  s->dx, s->x_from, s->x_to);
        return CLI_EXIT_USAGE;
    }
    tirenv_profile_reader *in = NULL;
    tirenv_outfile out;
    stream_out so = {0};
    if (!(status = tirenv_profile_reader_open(o->obstacle_arg, &in, &diag)) &&
        !(status = tirenv_outfile_open(&out, out_path, &diag))) {
        so.fp = out.fp;
        fputs(header, out.fp);
        status = tirenv_model_stream(m, in, s->x_from, s->x_to, s->dx, load, stream_row, &so,
                                     NULL, &diag);
        if (status == TIRENV_EIO && ferror(out.fp))
            status = tirenv_error(&diag, TIRENV_EIO, out_path, 0, "", "write failed");
        if (!status)
            status = tirenv_outfile_commit(&out, &diag);
        else
            tirenv_outfile_abort(&out);
    }
    tirenv_profile_reader_free(in);
    if (status)
        return cli_fail(status, &diag);
    summary(m, o, load, &so.t);
    return CLI_EXIT_OK;
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
    if ((code = cli_tire(&o, &tire)) || (!s.stream && (code = cli_profile(&o, &prof))) ||
        (code = cli_model(type, &tire, &m)) || (code = cli_load(&o, m, &load)))
        goto done;
    if (s.stream) {
        code = envelope_stream(&o, &tire, m, load, &s, out_path);
        goto done;
    }
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
        if (!status && s.detail) {
            status = write_detail(out.fp, &tire, prof, pt, n, &diag);
        } else if (!status) {
            fputs(header, out.fp);
            for (size_t k = 0; k < n; ++k)
                write_row(out.fp, &pt[k]);
        }
        if (!status)  /* commit checks the writes and removes the file if one failed */
            status = tirenv_outfile_commit(&out, &diag);
        else
            tirenv_outfile_abort(&out);
    }
    if (status) {
        code = cli_fail(status, &diag);
        goto done;
    }
    tally t = {0};
    for (size_t k = 0; k < n; ++k)
        tally_add(&t, &pt[k]);
    summary(m, &o, load, &t);
    code = CLI_EXIT_OK;
done:
    free(pt);
    free(x);
    tirenv_model_free(m);
    tirenv_profile_free(prof);
    return code;
}
