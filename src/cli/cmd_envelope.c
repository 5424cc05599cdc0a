/* tirenv envelope: the enveloping curve of one model over one obstacle, as CSV. Every model
 * type of the library's table runs through the same path, the network (--model nn --nn FILE)
 * and the point contact included; tirenv predict is this command with the network.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli/envelope.h"

/* The default sweep starts and ends this far beyond the tire's first and last reach, m. */
static const double margin = 0.02;
static const double default_dx = 0.001;  /* m */
static const double rise_threshold = 1e-4;  /* first rise: h above 0.1 mm, m */

static void usage(FILE *fp)
{
    fputs("usage: tirenv envelope --model NAME OBSTACLE (--load N | --contact-length M)\n"
          "                       [--x-from X] [--x-to X] [--dx DX] [--stream] [-o FILE]\n"
          "                       [--nn FILE [--extrapolate]] [--tire FILE] [--set KEY=VALUE]...\n"
          "                       [--method M]\n"
          "\n"
          "The enveloping curve h(x) = z(x) - z_flat of the tire over an obstacle at constant\n"
          "vertical load, one CSV row per centre position x:\n"
          "  x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations\n"
          "slope is the effective road slope tan(beta) = -fx/fz, the inclination of the ground\n"
          "force (for the cam exactly (Z_f - Z_r)/l_s, docs/models.md section 7; for the point\n"
          "contact the ground's slope; for the network dh/dx of its curve).\n"
          "A one-line summary (peak, first rise, iterations) goes to standard error, after any\n"
          "warning the model has (the network's inputs outside its training range).\n"
          "\n"
          "options:\n",
          fp);
    cli_help_model(fp, 0, 0, "");
    for (const tirenv_model_type *const *t = tirenv_model_types(); *t; ++t)
        fprintf(fp, "%22s %s: %s\n", "", tirenv_model_type_name(*t),
                tirenv_model_type_summary(*t));
    fputs("  --nn FILE            the trained network (tirenv train -o) for --model nn: over\n"
          "                       --cleat the paper's curve, over any other obstacle or\n"
          "                       --profile an extension beyond the paper (equivalent cleats;\n"
          "                       'tirenv predict --help')\n"
          "  --extrapolate        with --nn: evaluate the network outside the ranges it was\n"
          "                       trained on (with a warning) instead of refusing the input\n",
          fp);
    cli_help_load(fp);
    cli_help_sweep(fp);
    fputs("  --stream             with --profile: read the file as the tire rolls, in memory\n"
          "                       bounded by the tire's reach whatever the road's length (the\n"
          "                       file is read twice: first to check it and find its ends);\n"
          "                       not for the network, which reads the whole profile\n"
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
        status = tirenv_ring_forces(r, prof, pt[k].x, pt[k].z, &fx, &fz, NULL, NULL, diag);
        if (status)
            break;
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

/* The rigid disc has no contact length of its own, so it shows the one asked for, if any;
 * the model's note (the network's view of the ground) ends the line. */
static void summary(const char *cmd, tirenv_model *m, const cli_options *o, double load,
                    const tally *t)
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
    const char *note = tirenv_model_note(m);
    fprintf(stderr,
            "tirenv %s: %s model, load %.6g N (%s), %zu positions: peak h %.3f mm at "
            "x = %.4f m, %s, iterations per position mean %.2f max %zu%s%s\n",
            cmd, tirenv_model_name(m), load, lc_text, t->n, t->peak.h * 1e3, t->peak.x,
            rise_text, t->n ? t->it_sum / (double)t->n : 0.0, t->it_max, note[0] ? "; " : "",
            note);
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

/* The sweep's ends: as asked, or R0 + margin beyond the obstacle's first and last vertex. */
static void sweep_ends(const cli_options *o, const tirenv_model *m, double first, double last,
                       double *x_from, double *x_to)
{
    const double R0 = tirenv_model_tire(m)->springs.R0;
    *x_from = isnan(o->x_from) ? first - R0 - margin : o->x_from;
    *x_to = isnan(o->x_to) ? last + R0 + margin : o->x_to;
}

/* --stream: rows go out as they are computed; the output file is still all or nothing. */
static int envelope_stream(const char *cmd, const cli_options *o, tirenv_model *m,
                           double load)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    double first = 0, last = 0, x_from, x_to;
    int status = stream_extent(o->obstacle_arg, &first, &last, &diag);
    if (status)
        return cli_fail(status, &diag);
    sweep_ends(o, m, first, last, &x_from, &x_to);
    const double dx = isnan(o->dx) ? default_dx : o->dx;
    if (!(x_to >= x_from)) {
        cli_error("expected --dx > 0 and --x-to >= --x-from, got dx %g m from %g to %g m", dx,
                  x_from, x_to);
        return CLI_EXIT_USAGE;
    }
    tirenv_profile_reader *in = NULL;
    tirenv_outfile out;
    stream_out so = {0};
    const char *path = o->output ? o->output : "-";
    if (!(status = tirenv_profile_reader_open(o->obstacle_arg, &in, &diag)) &&
        !(status = tirenv_outfile_open(&out, path, &diag))) {
        so.fp = out.fp;
        fputs(header, out.fp);
        status = tirenv_model_stream(m, tirenv_profile_reader_source, in, x_from, x_to, dx,
                                     load, stream_row, &so, NULL, &diag);
        if (status == TIRENV_EIO && ferror(out.fp))
            status = tirenv_error(&diag, TIRENV_EIO, path, 0, "", "write failed");
        if (!status)
            status = tirenv_outfile_commit(&out, &diag);
        else
            tirenv_outfile_abort(&out);
    }
    tirenv_profile_reader_free(in);
    if (status)
        return cli_fail(status, &diag);
    summary(cmd, m, o, load, &so.t);
    return CLI_EXIT_OK;
}

/* The whole sweep in memory, through tirenv_model_envelope, the rows written after it. */
static int envelope_whole(const char *cmd, const cli_options *o, tirenv_model *m, double load,
                          const tirenv_profile *prof, int detail)
{
    double first, last, x_from, x_to, *x = NULL;
    tirenv_profile_extent(prof, &first, &last);
    sweep_ends(o, m, first, last, &x_from, &x_to);
    size_t n = 0;
    int code = cli_positions(x_from, x_to, isnan(o->dx) ? default_dx : o->dx, &x, &n);
    if (code)
        return code;
    tirenv_point *pt = malloc(n * sizeof *pt);
    if (!pt) {
        free(x);
        return cli_fail(TIRENV_ENOMEM, NULL);
    }
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_outfile out;
    int status = tirenv_model_set(m, prof, load, &diag);
    if (!status)
        cli_model_warnings(cmd, m);
    /* Opened before the sweep so that a bad -o path fails at once, not after it. */
    if (!status && !(status = tirenv_outfile_open(&out, o->output ? o->output : "-", &diag))) {
        status = tirenv_model_envelope(m, n, x, pt, NULL, &diag);
        if (!status && detail) {
            status = write_detail(out.fp, tirenv_model_tire(m), prof, pt, n, &diag);
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
    } else {
        tally t = {0};
        for (size_t k = 0; k < n; ++k)
            tally_add(&t, &pt[k]);
        summary(cmd, m, o, load, &t);
    }
    free(pt);
    free(x);
    return code;
}

int cli_envelope_run(const char *cmd, const cli_options *o, const tirenv_model_type *type,
                     int stream, int detail)
{
    const char *missing = NULL;
    if (!o->obstacle)
        missing = "an obstacle option";
    else if (!o->have_load && !o->have_contact_length)
        missing = "--load N or --contact-length M";
    else if (stream && o->obstacle != CLI_PROFILE)
        missing = "--profile FILE with --stream";
    else if (detail && (type != tirenv_model_ring || stream))
        missing = "--model ring and no --stream with --detail";
    if (missing) {
        cli_error("%s: expected %s; 'tirenv %s --help' shows the options", cmd, missing, cmd);
        return CLI_EXIT_USAGE;
    }
    if (stream && !(tirenv_model_type_flags(type) & TIRENV_MODEL_STREAMS)) {
        cli_error("%s: --stream: the %s model reads the whole profile at once; it cannot "
                  "stream", cmd, tirenv_model_type_name(type));
        return CLI_EXIT_USAGE;
    }
    tirenv_tire tire;
    tirenv_model *m = NULL;
    tirenv_profile *prof = NULL;
    double load = 0;
    int code;
    if (!(code = cli_tire(o, &tire)) && (stream || !(code = cli_profile(o, &prof))) &&
        !(code = cli_model(type, &tire, o, &m)) && !(code = cli_load(o, m, &load)))
        code = stream ? envelope_stream(cmd, o, m, load)
                      : envelope_whole(cmd, o, m, load, prof, detail);
    tirenv_model_free(m);
    tirenv_profile_free(prof);
    return code;
}

int cli_envelope_main(int argc, char *argv[])
{
    int stream = 0, detail = 0;
    const cli_opt own[] = {
        {.name = "stream", .kind = CLI_FLAG, .dst = &stream},
        {.name = "detail", .kind = CLI_FLAG, .dst = &detail},
        {.name = NULL},
    };
    const cli_parser p = {.name = "envelope", .usage = usage, .opts = own,
                          .groups = CLI_TIRE | CLI_METHOD | CLI_LOAD | CLI_OBSTACLE |
                                    CLI_SWEEP | CLI_OUTPUT | CLI_MODEL | CLI_NETWORK};
    cli_options o;
    const int code = cli_parse(&p, argc, argv, &o);
    if (code != CLI_GO_ON)
        return code;
    if (!o.type) {
        cli_error("envelope: expected --model NAME; 'tirenv envelope --help' shows the options");
        return CLI_EXIT_USAGE;
    }
    return cli_envelope_run("envelope", &o, o.type, stream, detail);
}
