/* tirenv envelope: the enveloping curve of one model over one obstacle, as CSV. Every model
 * type of the library's table runs through the same path, the network (--model nn --nn FILE)
 * and the point contact included; tirenv predict is this command with the network.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/csv_row.h"
#include "cli/envelope.h"
#include "cli/envelope_plot.h"
#include "cli/envelope_chunks.h"
#include "cli/envelope_stream.h"
#include "cli/level.h"
#include "cli/road_out.h"

static const double rise_threshold = 1e-4;  /* first rise: h above 0.1 mm, m */

static void usage(FILE *fp)
{
    fputs("usage: tirenv envelope --model NAME OBSTACLE (--load N | --contact-length M)\n"
          "                       [--track V] [--side S] [--crg-nan-mode M] [--tracks N]\n"
          "                       [--width W] [--x-from X] [--x-to X] [--dx DX] [--stream]\n"
          "                       [-o FILE.csv|FILE.crg|FILE.rdf] [--crg-encoding E]\n"
          "                       [--relative-to ground|datum] [--nn FILE [--extrapolate]]\n"
          "                       [--detail] [--tire FILE] [--set KEY=VALUE]...\n"
          "                       [--method M] [--jobs N] [--plot FILE.png]\n"
          "\n"
          "The enveloping curve h(x) = z(x) - z_flat of the tire over an obstacle at constant\n"
          "vertical load, one CSV row per centre position x:\n"
          "  x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations\n"
          "slope is the effective road slope tan(beta) = -fx/fz, the inclination of the ground\n"
          "force (for the cam exactly (Z_f - Z_r)/l_s, docs/models.md section 7; for the point\n"
          "contact the ground's slope; for the network dh/dx of its curve).\n"
          "A one-line summary (peak, first rise, iterations) goes to standard error, after any\n"
          "warning the model has (the network's inputs outside its training range; the cam\n"
          "touching the ground higher above its lowest point than the tire's ELLIPS_MAX_STEP).\n"
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
    cli_help_road(fp, 1);
    fputs("  --stream             with --profile: read the file as the tire rolls, in memory\n"
          "                       bounded by the tire's reach whatever the road's length\n"
          "                       (into a file the road's rows are read once: a CSV's ends\n"
          "                       from its first and last rows, an OpenCRG or RDF road's\n"
          "                       from its check at open; to standard output or a FIFO\n"
          "                       twice, first to check every row; an OpenCRG road a block\n"
          "                       of rows at a time, an RDF road a line at a time; a pipe\n"
          "                       or /dev/stdin is kept in memory, at most 256 MiB); the\n"
          "                       model's warnings come after the rows\n",
          fp);
    cli_help_envelope_output(fp);
    cli_help_relative_to(fp);
    fputs("  --detail             with --model ring: two more columns, tread_max_m (the\n"
          "                       largest tread compression) and belt_contacts (nodes where\n"
          "                       the belt itself touches the ground), from one more ring\n"
          "                       evaluation at each row's (x, z); one track, no --stream\n",
          fp);
    cli_help_tire(fp, 1, "UNLOADED_RADIUS=0.69 (every model's)");
    cli_help_jobs(fp);
    fputs("                       (the positions in chunks of 8192, each solved from a\n"
          "                       cold start at its first position; with --stream the road\n"
          "                       is read once, in order, each chunk computed on the rows\n"
          "                       within the tire's reach of it, two rounds of 4 N chunks'\n"
          "                       rows and points held; --model nn, and a sweep whose\n"
          "                       chunks would span more than 256 m of road (--dx above\n"
          "                       31.25 mm), stream on one thread, in the tire's reach)\n"
          "  -h, --help           show this help\n",
          fp);
    cli_help_obstacle(fp);
}

static const char header[] = "x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations\n";

/* The bytes of fprintf("%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%zu,%zu\n"), several times faster. */
static void write_row(FILE *fp, const tirenv_point *pt)
{
    char row[8 * CLI_ROW_FIELD], *p = row;
    p = cli_row_g(p, pt->x, 9, ',');
    p = cli_row_g(p, pt->z, 9, ',');
    p = cli_row_g(p, pt->h, 9, ',');
    p = cli_row_g(p, pt->slope, 9, ',');
    p = cli_row_g(p, pt->fx, 9, ',');
    p = cli_row_g(p, pt->fz, 9, ',');
    p = cli_row_size(p, pt->contacts, ',');
    p = cli_row_size(p, pt->iterations, '\n');
    fwrite(row, 1, (size_t)(p - row), fp);
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

/* A position as the summary prints it: a sweep's x near 0 is some 1e-17 m off it (x_from +
 * k*dx), which %.4f showed as "-0.0000". */
static double shown_x(double x)
{
    return fabs(x) < 5e-5 ? 0.0 : x;
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
        snprintf(rise_text, sizeof rise_text, "first rise at x = %.4f m", shown_x(t->rise_x));
    const char *note = tirenv_model_note(m);
    fprintf(stderr,
            "tirenv %s: %s model, load %.6g N (%s), %zu positions: peak h %.3f mm at "
            "x = %.4f m, %s, iterations per position mean %.2f max %zu%s%s\n",
            cmd, tirenv_model_name(m), load, lc_text, t->n, t->peak.h * 1e3, shown_x(t->peak.x),
            rise_text, t->n ? t->it_sum / (double)t->n : 0.0, t->it_max, note[0] ? "; " : "",
            note);
}

void cli_help_envelope_output(FILE *fp)
{
    fputs("  -o, --output FILE    write the curve to FILE, complete or not at all (default or\n"
          "                       '-': CSV on standard output). FILE.crg or FILE.rdf writes\n"
          "                       the effective road instead: h along x as an OpenCRG road\n"
          "                       (straight reference line, rows at the positions, the same\n"
          "                       h at -w/2 and +w/2 across the width w) or a TNO/Adams\n"
          "                       poly_line road, for a point-contact tire in another tool\n"
          "  --crg-encoding E     FILE.crg: kdbi (default: binary doubles, exact), krbi,\n"
          "                       ldfi or lrfi\n"
          "  --plot FILE.png      with -o FILE.csv: draw the curve over the road under the\n"
          "                       centre into FILE.png and FILE.svg, with FILE.gp, the\n"
          "                       gnuplot script (rerun it to restyle), and FILE-road.dat;\n"
          "                       one track, no --stream, h relative to the datum\n",
          fp);
}

static cli_envelope_opts envelope_default(void)
{
    return (cli_envelope_opts){.stream = 0, .detail = 0, .encoding = TIRENV_CRG_KDBI,
                               .have_encoding = 0, .relative = CLI_RELATIVE_DATUM};
}

static int parse_encoding(void *dst, const char *arg)
{
    cli_envelope_opts *e = dst;
    e->have_encoding = 1;
    return cli_parse_crg_encoding(&e->encoding, arg);
}

/* What a run needs besides the options: the tracks and how the curve goes out. */
typedef struct {
    const char *cmd;
    const cli_options *o;
    const tirenv_model_type *type;
    const cli_envelope_opts *e;
    cli_road road;
    tirenv_profile_format out_format;  /* CSV: the curve; CRG, RDF: the effective road */
    char label[640];                   /* the road, for the summary and the file's comment */
} run;

/* A file's name without its directories. */
static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* Appends one comment line of at most 72 characters (the OpenCRG header's record). */
static void comment_line(char *buf, size_t n, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static void comment_line(char *buf, size_t n, const char *fmt, ...)
{
    char line[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    const size_t used = strlen(buf);
    snprintf(buf + used, n - used, "%s%.72s", used ? "\n" : "", line);
}

/* The effective road's file says what it is: the model, the tire, the load, the road and the
 * frame of h (the writers add the program and its version). */
static void road_comment(const run *r, const tirenv_model *m, double load, char *buf,
                         size_t n)
{
    char tire[1024], road[700];
    /* --tire's own path, or the default's written into tire (which is unset with --tire). */
    const char *tire_path = cli_tire_path(r->o, tire, sizeof tire);
    cli_road_label(r->o, &r->road, road, sizeof road);
    buf[0] = '\0';
    comment_line(buf, n, "Effective road: h(x) = z - z_flat, the hub's effective height");
    comment_line(buf, n, "of the %s model at load %.6g N, tire %s%s,", tirenv_model_name(m),
                 load, base_name(tire_path), r->o->n_sets ? " with --set" : "");
    comment_line(buf, n, "over %s", r->road.from_file ? base_name(road) : road);
    comment_line(buf, n, "h is relative to %s; %s",
                 r->e->relative == CLI_RELATIVE_GROUND ? "the road's local level (section 2.6)"
                                                       : "the datum (the road's z = 0)",
                 r->out_format == TIRENV_PROFILE_CRG ? "both long sections" : "both sides");
    comment_line(buf, n, "carry it: the same height across the tire's width.");
}

/* The effective road's writer for n positions from x_from every dx, if one is wanted. */
static int road_out_open(const run *r, const tirenv_model *m, double load, double x_from,
                         double dx, size_t n, tirenv_road_writer **w, tirenv_diag *diag)
{
    char comment[1024];
    road_comment(r, m, load, comment, sizeof comment);
    const tirenv_tire *tire = tirenv_model_tire(m);
    const double width = r->road.width > 0 ? r->road.width : tire->width > 0 ? tire->width : 1;
    /* An effective road of an OpenCRG road lies where that road is (its reference line, the
     * track's v); of another road file or a generated obstacle, on the x axis where that road's
     * x is: its line starts at x = x_from, the first row's u (OpenCRG's x/y evaluation put a
     * line from the origin at u - x_from). */
    const int on_crg = r->road.from_file && r->road.format == TIRENV_PROFILE_CRG;
    const tirenv_road_writer_layout l = {
        .x_from = x_from, .dx = dx, .n = n, .half_width = 0.5 * width,
        .x_start = on_crg ? 0 : x_from,
        .v_track = on_crg ? r->road.src.crg.v : 0, .encoding = r->e->encoding,
        .comment = comment, .on_crg = on_crg ? r->road.file : NULL};
    return tirenv_road_writer_open(r->o->output, r->out_format, &l, w, diag);
}

/* The streamed sweep's sink: one row out (or into the effective road) and into the tally
 * per position. */
typedef struct {
    FILE *fp;
    tirenv_road_writer *road;
    tally t;
    size_t n_level;             /* 0: h relative to the datum; else the tracks' count */
    tirenv_level_stream *level[CLI_MAX_TRACKS];  /* each track's level */
    tirenv_diag diag;           /* the road writer's or the level's failure */
} stream_out;

static int stream_row(void *ctx, const tirenv_point *pt)
{
    stream_out *s = ctx;
    tirenv_point row = *pt;
    int status = TIRENV_OK;
    if (s->n_level) {  /* to_ground's mean, in its order: the same bits */
        double level = 0;
        for (size_t i = 0; i < s->n_level; ++i) {
            double level_i;
            if ((status = tirenv_level_stream_at(s->level[i], pt->x, &level_i, &s->diag)))
                return status;
            level += level_i;
        }
        row.h -= level / (double)s->n_level;
    }
    if (s->road) {
        if ((status = tirenv_road_writer_add(s->road, row.x, row.h, &s->diag)))
            return status;
    } else {
        write_row(s->fp, &row);
    }
    tally_add(&s->t, &row);
    return s->fp && ferror(s->fp) ? TIRENV_EIO : TIRENV_OK;
}

/* The ends of the road for --stream's default sweep. Into a file, which reaches its place
 * only whole, the road's rows are read once: its ends without them (tirenv_road_file_extent:
 * a CSV's first and last rows, an OpenCRG road's pass at open or an RDF road's scan, which
 * check its rows and which the sweep's reader then shares),
 * its rows as the tire rolls, and those past the sweep's reach after it (stream_rest), so that
 * a bad row anywhere, or a track that needs a missing OpenCRG value, fails as in whole mode.
 * Written through (standard output, a FIFO), where rows cannot be taken back, every row of
 * every track is checked first (*checked), so that a bad row late in the file fails before
 * any output: the rows are read twice. Memory is constant either way (a pipe's bytes are kept
 * by the road file). */
static int stream_extent(const run *r, const char *path, int *checked, double *first,
                         double *last, tirenv_diag *diag)
{
    *checked = tirenv_outfile_path_is_through(path);
    return tirenv_road_file_extent(r->road.file, &r->road.src, r->road.n, r->road.v, *checked,
                                   first, last, diag);
}

/* The rows of the road the sweep left unread, each checked (stream_extent). */
static int stream_rest(tirenv_profile_file_reader *in, tirenv_diag *diag)
{
    double x, z[CLI_MAX_TRACKS];
    int got = 1, status = TIRENV_OK;
    while (!status && got)
        status = tirenv_profile_file_reader_next(in, &x, z, &got, diag);
    return status;
}

/* The sweep: --x-from, --x-to and --dx as asked, the library's default sweep over the
 * obstacle's first to last vertex for the rest. */
static tirenv_positions sweep(const cli_options *o, const tirenv_model *m, double first,
                              double last)
{
    tirenv_positions s = tirenv_positions_default(first, last, tirenv_model_tire(m)->springs.R0);
    if (!isnan(o->x_from))
        s.x_from = o->x_from;
    if (!isnan(o->x_to))
        s.x_to = o->x_to;
    if (!isnan(o->dx))
        s.dx = o->dx;
    return s;
}

/* --relative-to ground, streamed: the level under the centre, the mean of the tracks' levels
 * as in whole mode (to_ground), each from a reader of its own of the open file at that track
 * (in[] and s->level[] NULL otherwise; the level of --track alone gave other bytes than whole
 * mode's over several tracks). */
static int level_open(const run *r, const tirenv_model *m, tirenv_profile_file_reader *in[],
                      stream_out *s, tirenv_diag *diag)
{
    if (r->e->relative != CLI_RELATIVE_GROUND)
        return TIRENV_OK;
    const double width = tirenv_level_width(tirenv_model_tire(m));
    int status = TIRENV_OK;
    for (size_t i = 0; i < r->road.n && !status; ++i) {
        status = tirenv_road_file_reader(r->road.file, &r->road.src, 1, &r->road.v[i], &in[i],
                                         diag);
        if (!status && !(s->level[i] = tirenv_level_stream_alloc(
                             tirenv_profile_file_reader_source, in[i], width)))
            status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
        s->n_level = i + 1;
    }
    return status;
}

/* --stream: rows go out as they are computed; the output file is still all or nothing. */
static int envelope_stream(const run *r, tirenv_model *m, double load)
{
    const cli_options *o = r->o;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const char *path = o->output ? o->output : "-";
    double first = 0, last = 0;
    int checked;
    int status = stream_extent(r, path, &checked, &first, &last, &diag);
    if (status)
        return cli_fail(status, &diag);
    const tirenv_positions s = sweep(o, m, first, last);
    const double x_from = s.x_from, x_to = s.x_to, dx = s.dx;
    size_t n_positions = 0;
    const int bad = cli_positions_check(x_from, x_to, dx, CLI_MAX_STREAM_POSITIONS,
                                        &n_positions);
    if (bad)
        return bad;
    tirenv_profile_file_reader *in = NULL;
    tirenv_outfile *out = NULL;
    stream_out so = {0};
    tirenv_diag_clear(&so.diag);
    const size_t n = tirenv_positions_count(x_from, x_to, dx);
    int code = cli_road_open(&r->road, &in);
    if (code)
        return code;
    tirenv_profile_file_reader *in_level[CLI_MAX_TRACKS] = {NULL};
    char said[1024] = "";  /* the chunks' models' warnings */
    status = level_open(r, m, in_level, &so, &diag);
    if (!status && r->out_format != TIRENV_PROFILE_CSV) {
        status = road_out_open(r, m, load, x_from, dx, n, &so.road, &diag);
    } else if (!status && !(status = tirenv_outfile_open(&out, path, &diag))) {
        so.fp = tirenv_outfile_stream(out);
        fputs(header, so.fp);
    }
    if (!status) {
        /* A network's windows are told where they sit in the road (tirenv_model_stream):
         * it streams on one thread; so does a sweep whose chunks would each hold more than
         * CLI_STREAM_CHUNK_SPAN_M of road. */
        const int chunked =
            o->jobs > 1 && !(tirenv_model_type_flags(r->type) & TIRENV_MODEL_NEEDS_NETWORK) &&
            CLI_CHUNK * dx <= CLI_STREAM_CHUNK_SPAN_M;
        status = chunked ? cli_stream_chunks(m, r->type, o, r->road.n,
                                             tirenv_profile_file_reader_source, in, x_from,
                                             x_to, dx, load, o->jobs, stream_row, &so,
                                             said, sizeof said, &diag)
                         : tirenv_model_stream_tracks(m, r->road.n, NULL,
                                                      tirenv_profile_file_reader_source, in,
                                                      x_from, x_to, dx, load, stream_row, &so,
                                                      NULL, &diag);
        if (status == TIRENV_EIO && so.fp && ferror(so.fp))
            status = tirenv_error(&diag, TIRENV_EIO, path, 0, "", "write failed");
        else if (status && so.diag.message[0])  /* the road writer's or the level's */
            diag = so.diag;
        if (!status && !checked)
            status = stream_rest(in, &diag);
        if (!status && so.road) {
            tirenv_road_writer *w = so.road;
            so.road = NULL;
            status = tirenv_road_writer_commit(w, &diag);
        } else if (!status) {
            status = tirenv_outfile_commit(out, &diag);
            out = NULL;
        }
    }
    tirenv_outfile_abort(out);
    tirenv_road_writer_abort(so.road);
    tirenv_profile_file_reader_free(in);
    for (size_t i = 0; i < so.n_level; ++i) {
        tirenv_level_stream_free(so.level[i]);
        tirenv_profile_file_reader_free(in_level[i]);
    }
    if (status)
        return cli_fail(status, &diag);
    /* The network's over the windows, the cam's over the positions: after the rows. */
    if (said[0])
        cli_warnings(r->cmd, said);
    else
        cli_model_warnings(r->cmd, m);
    summary(r->cmd, m, o, load, &so.t);
    return CLI_EXIT_OK;
}

/* Where a whole sweep goes: the CSV curve or the effective road, opened before the sweep so
 * that a bad -o fails at once, not after it. Both reach their target only on commit. */
typedef struct {
    tirenv_outfile *out;  /* NULL once committed or aborted */
    tirenv_road_writer *road;
} whole_out;

static int whole_open(const run *r, const tirenv_model *m, double load, double x_from,
                      double dx, size_t n, whole_out *w, tirenv_diag *diag)
{
    memset(w, 0, sizeof *w);
    if (r->out_format != TIRENV_PROFILE_CSV)
        return road_out_open(r, m, load, x_from, dx, n, &w->road, diag);
    return tirenv_outfile_open(&w->out, r->o->output ? r->o->output : "-", diag);
}

/* Points a sweep may write as they come: into a temporary file or road (nothing reaches the
 * target before commit), so that a long road's points never all sit in memory, whose first
 * touch costs as much as formatting them. Written through (stdout, a FIFO) or with --detail,
 * the sweep is computed whole first, so that a failure midway writes nothing. */
static int whole_streams(const run *r, const whole_out *w)
{
    return (w->road || tirenv_outfile_is_atomic(w->out)) && !r->e->detail;
}

/* Writes the points [k0, k0 + n) of the sweep. */
static int whole_write(const run *r, tirenv_model *m, const tirenv_profile *prof,
                       const tirenv_point pt[], size_t k0, size_t n, whole_out *w,
                       tirenv_diag *diag)
{
    int status = TIRENV_OK;
    if (w->road) {
        for (size_t k = 0; k < n && !status; ++k)
            status = tirenv_road_writer_add(w->road, pt[k].x, pt[k].h, diag);
        return status;
    }
    FILE *fp = tirenv_outfile_stream(w->out);
    if (r->e->detail)
        return write_detail(fp, tirenv_model_tire(m), prof, pt, n, diag);
    if (k0 == 0)
        fputs(header, fp);
    for (size_t k = 0; k < n; ++k)
        write_row(fp, &pt[k]);
    return TIRENV_OK;
}

/* Puts the output in place (checking the writes), or on failure leaves nothing. */
static int whole_close(whole_out *w, int status, tirenv_diag *diag)
{
    tirenv_road_writer *road = w->road;
    w->road = NULL;
    if (road)
        return status ? (tirenv_road_writer_abort(road), status)
                      : tirenv_road_writer_commit(road, diag);
    tirenv_outfile *out = w->out;
    w->out = NULL;
    if (!out)
        return status;
    if (status) {
        tirenv_outfile_abort(out);
        return status;
    }
    return tirenv_outfile_commit(out, diag);
}

/* --relative-to ground: h less the road's local level under the centre, the mean of the
 * tracks' levels (each the opening of docs/models.md section 2.6). */
static void to_ground(const run *r, const tirenv_model *m, tirenv_profile *const prof[],
                      tirenv_point pt[], size_t n)
{
    const double width = tirenv_level_width(tirenv_model_tire(m));
    for (size_t k = 0; k < n; ++k) {
        double level = 0;
        for (size_t i = 0; i < r->road.n; ++i)
            level += tirenv_profile_level(prof[i], width, pt[k].x);
        pt[k].h -= level / (double)r->road.n;
    }
}

/* Points computed and not yet written: --relative-to ground applied, written, tallied. */
typedef struct {
    const run *r;
    tirenv_model *m;             /* its tire only: another thread may be computing with it */
    tirenv_profile *const *prof;
    whole_out *w;
    tally *t;
    tirenv_point *pt;
    size_t k0, n;                /* the sweep's points [k0, k0 + n) */
} pending;

static int pending_write(void *ctx, tirenv_diag *diag)
{
    pending *p = ctx;
    if (p->n == 0)
        return TIRENV_OK;
    if (p->r->e->relative == CLI_RELATIVE_GROUND)
        to_ground(p->r, p->m, p->prof, p->pt, p->n);
    const int status = whole_write(p->r, p->m, p->prof[0], p->pt, p->k0, p->n, p->w, diag);
    for (size_t k = 0; k < p->n && !status; ++k)
        tally_add(p->t, &p->pt[k]);
    p->k0 += p->n;
    p->n = 0;
    return status;
}

/* The sweep through tirenv_model_envelope in chunks of CLI_CHUNK positions on --jobs threads
 * (envelope_chunks.h), a round of chunks at a time when the output can take them as they come
 * (whole_streams), else all of them before the first is written. */
static int envelope_whole(const run *r, tirenv_model *m, double load,
                          tirenv_profile *const prof[])
{
    const cli_options *o = r->o;
    double first, last;
    tirenv_profile_extent(prof[0], &first, &last);
    const tirenv_positions s = sweep(o, m, first, last);
    size_t n = 0;
    int code = cli_positions_check(s.x_from, s.x_to, s.dx, CLI_MAX_STREAM_POSITIONS, &n);
    if (code)
        return code;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const tirenv_profile *tracks[CLI_MAX_TRACKS];
    for (size_t k = 0; k < r->road.n; ++k)
        tracks[k] = prof[k];
    whole_out w;
    tirenv_point *pt[2] = {NULL, NULL};
    cli_chunks *c = NULL;
    tally t = {0};
    int status = tirenv_model_set_tracks(m, r->road.n, tracks, NULL, load, &diag);
    if (!status)
        cli_model_warnings(r->cmd, m);
    if (!status)
        status = cli_chunks_open(m, r->type, o, r->road.n, tracks, load, s.x_from, s.dx, n,
                                 o->jobs, &c, &diag);
    if (!status && !(status = whole_open(r, m, load, s.x_from, s.dx, n, &w, &diag))) {
        const size_t n_chunks = n / CLI_CHUNK + (n % CLI_CHUNK != 0);
        const size_t round = whole_streams(r, &w) ? cli_chunks_round(c) : n_chunks;
        if (!whole_streams(r, &w) || w.road ? (double)n > CLI_MAX_POSITIONS : 0)
            status = tirenv_error(&diag, TIRENV_ERANGE, "", 0, "--dx",
                                 "%zu positions is too many to hold in memory (at most %.0f "
                                 "%s); write the CSV curve to a file with -o FILE.csv, whose "
                                 "rows go out as they are computed, or raise --dx",
                                 n, CLI_MAX_POSITIONS,
                                 w.road ? "in an effective road"
                                        : "written to standard output or with --detail");
        const size_t cap = round * CLI_CHUNK < n ? round * CLI_CHUNK : n;
        for (int b = 0; b < 1 + (n_chunks > round) && !status; ++b)
            if (!(pt[b] = malloc((cap ? cap : 1) * sizeof *pt[b])))
                status = tirenv_error(&diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
        /* A round's chunks are computed into one buffer while the previous round's points,
         * in the other, are written beside them. */
        pending pw = {.r = r, .m = m, .prof = prof, .w = &w, .t = &t};
        for (size_t c0 = 0, b = 0; c0 < n_chunks && !status; c0 += round, b ^= 1) {
            size_t n_k = 0;
            status = cli_chunks_run(c, c0, round, pt[b], &n_k, pending_write, &pw, &diag);
            pw.pt = pt[b];
            pw.n = n_k;
        }
        if (!status)
            status = pending_write(&pw, &diag);
        status = whole_close(&w, status, &diag);
    }
    if (status)
        code = cli_fail(status, &diag);
    /* What the evaluations had to say (the cam's; a network's are its set's, said above). */
    else if (!(tirenv_model_type_flags(r->type) & TIRENV_MODEL_NEEDS_NETWORK))
        cli_warnings(r->cmd, cli_chunks_warnings(c));
    if (!status)
        summary(r->cmd, m, o, load, &t);
    if (!status && r->e->plot) {
        char title[1024];
        snprintf(title, sizeof title, "tirenv %s: %s model, load %.6g N, over %s", r->cmd,
                 tirenv_model_type_name(r->type), load, r->label);
        if ((status = cli_envelope_plot(r->e->plot, o->output, tirenv_model_type_name(r->type),
                                        title, prof[0], s.x_from, s.x_to, &diag)))
            code = cli_fail(status, &diag);
    }
    cli_chunks_free(c);
    free(pt[0]);
    free(pt[1]);
    return code;
}

int cli_envelope_run(const char *cmd, const cli_options *o, const tirenv_model_type *type,
                     const cli_envelope_opts *e)
{
    const char *missing = NULL;
    if (!o->obstacle)
        missing = "an obstacle option";
    else if (!o->have_load && !o->have_contact_length)
        missing = "--load N or --contact-length M";
    else if (e->stream && o->obstacle != CLI_PROFILE)
        missing = "--profile FILE with --stream";
    else if (e->detail && (type != tirenv_model_ring || e->stream))
        missing = "--model ring and no --stream with --detail";
    else if (e->plot && (e->stream || !o->output || strcmp(o->output, "-") == 0 ||
                         e->relative != CLI_RELATIVE_DATUM))
        missing = "-o FILE.csv, no --stream and h relative to the datum with --plot (the plot "
                  "reads the curve from the file, over the road held whole)";
    if (missing) {
        cli_error("%s: expected %s; 'tirenv %s --help' shows the options", cmd, missing, cmd);
        return CLI_EXIT_USAGE;
    }
    if (e->stream && !(tirenv_model_type_flags(type) & TIRENV_MODEL_STREAMS)) {
        cli_error("%s: --stream: the %s model reads the whole profile at once; it cannot "
                  "stream", cmd, tirenv_model_type_name(type));
        return CLI_EXIT_USAGE;
    }
    run r = {.cmd = cmd, .o = o, .type = type, .e = e, .out_format = TIRENV_PROFILE_CSV};
    cli_road_out_wanted(o->output, &r.out_format);
    if (e->plot && r.out_format != TIRENV_PROFILE_CSV) {
        cli_error("%s: --plot draws the CSV curve; -o %s writes an effective road", cmd,
                  o->output);
        return CLI_EXIT_USAGE;
    }
    if (e->plot) {
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        const int status = cli_envelope_plot_check(e->plot, &diag);
        if (status)
            return cli_fail(status, &diag);
    }
    if (e->detail && r.out_format != TIRENV_PROFILE_CSV) {
        cli_error("%s: --detail adds columns to the CSV curve; -o %s writes an effective road",
                  cmd, o->output);
        return CLI_EXIT_USAGE;
    }
    if (e->have_encoding && r.out_format != TIRENV_PROFILE_CRG) {
        if (o->output)
            cli_error("%s: --crg-encoding applies to -o FILE.crg; -o %s writes %s", cmd,
                      o->output,
                      r.out_format == TIRENV_PROFILE_RDF ? "an RDF road" : "the CSV curve");
        else
            cli_error("%s: --crg-encoding applies to -o FILE.crg; without -o the CSV curve "
                      "goes to standard output", cmd);
        return CLI_EXIT_USAGE;
    }
    tirenv_tire tire;
    tirenv_model *m = NULL;
    tirenv_profile *prof[CLI_MAX_TRACKS] = {NULL};
    double load = 0;
    int code = cli_tire(o, &tire);
    if (!code)
        code = cli_road_plan(o, &tire, &r.road);
    if (!code && e->detail && r.road.n > 1) {
        cli_error("%s: --detail is one ring's state on one track; not with --tracks", cmd);
        code = CLI_EXIT_USAGE;
    }
    if (!code && e->plot && r.road.n > 1) {
        cli_error("%s: --plot draws the curve over one track's road; not with --tracks", cmd);
        code = CLI_EXIT_USAGE;
    }
    cli_road_label(o, &r.road, r.label, sizeof r.label);
    if (!code && !e->stream)
        code = cli_road_read(o, &r.road, prof);
    if (!code && !(code = cli_model(type, &tire, o, &m)) && !(code = cli_load(o, m, &load)))
        code = e->stream ? envelope_stream(&r, m, load) : envelope_whole(&r, m, load, prof);
    tirenv_model_free(m);
    for (size_t k = 0; k < r.road.n; ++k)
        tirenv_profile_free(prof[k]);
    cli_road_free(&r.road);
    return code;
}

int cli_envelope_parse(const char *cmd, void (*help)(FILE *fp), int argc, char *argv[],
                       cli_options *o, cli_envelope_opts *e)
{
    *e = envelope_default();
    const cli_opt own[] = {
        /* envelope's own first (the ring's --detail): predict's table starts after it */
        {.name = "detail", .kind = CLI_FLAG, .dst = &e->detail},
        {.name = "plot", .kind = CLI_STRING, .dst = &e->plot},
        {.name = "stream", .kind = CLI_FLAG, .dst = &e->stream},
        {.name = "crg-encoding", .kind = CLI_CUSTOM, .dst = e, .parse = parse_encoding},
        {.name = "relative-to", .kind = CLI_CUSTOM, .dst = &e->relative,
         .parse = cli_parse_relative_to},
        {.name = NULL},
    };
    const cli_parser p = {.name = cmd, .usage = help,
                          .opts = own + (strcmp(cmd, "envelope") == 0 ? 0 : 1),
                          .groups = CLI_TIRE | CLI_METHOD | CLI_LOAD | CLI_OBSTACLE |
                                    CLI_TRACKS | CLI_SWEEP | CLI_OUTPUT | CLI_MODEL |
                                    CLI_NETWORK | CLI_EXTRAPOLATE | CLI_JOBS};
    return cli_parse(&p, argc, argv, o);
}

int cli_envelope_main(int argc, char *argv[])
{
    cli_envelope_opts e;
    cli_options o;
    const int code = cli_envelope_parse("envelope", usage, argc, argv, &o, &e);
    if (code != CLI_GO_ON)
        return code;
    if (!o.type) {
        cli_error("envelope: expected --model NAME; 'tirenv envelope --help' shows the options");
        return CLI_EXIT_USAGE;
    }
    o.type_alone = 1;  /* the model named and no other (--detail: the ring's own) */
    return cli_envelope_run("envelope", &o, o.type, &e);
}
