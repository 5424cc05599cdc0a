/* tirenv convert: a road from one file format to another (CSV, OpenCRG, TNO/Adams RDF).
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/road_out.h"
#include "tirenv/crg.h"
#include "tirenv/io.h"
#include "tirenv/profile_file.h"
#include "tirenv/rdf.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv convert --profile IN -o OUT [--track V] [--side left|right|mean]\n"
          "                      [--crg-nan-mode M] [--crg-encoding E] [--dx M]\n"
          "                      [--half-width M] [--pad M]\n"
          "\n"
          "Converts a road between profile CSV ('x_m,z_m'), ASAM OpenCRG (.crg) and TNO/Adams\n"
          "2-D road (.rdf) files. IN's format is told by its content, OUT's by its extension\n"
          "(.csv, .crg, .rdf; '-', a device such as /dev/null or a FIFO without one is written\n"
          "through as CSV). From a .crg one track is taken, the long section at --track (a .crg\n"
          "to a .crg without --track copies every long section); a .crg is written with a\n"
          "straight reference line. An option that would change nothing in what is written\n"
          "(below, each says what it applies to) is refused. A one-line summary goes to\n"
          "standard error.\n"
          "\n"
          "options:\n"
          "  --profile IN         road file to read: CSV, .crg or .rdf\n"
          "  -o, --output OUT     file to write, complete or not at all\n"
          "  --track V            .crg input: lateral position of the track, m, positive to\n"
          "                       the left (default 0, the reference line)\n"
          "  --side S             .rdf poly_line input: left, right or mean (default) of\n"
          "                       its z_left and z_right\n"
          "  --crg-nan-mode M     .crg input: a missing grid value a track needs is an\n"
          "                       error (keep), the nearest valid value of its cross section\n"
          "                       (nearest), the height M in m (a number), or as the file's\n"
          "                       GRID_NAN_MODE says (file, the default; nearest without\n"
          "                       $ROAD_CRG_MODS, as OpenCRG)\n"
          "  --crg-encoding E     .crg output: kdbi (default: binary doubles, exact), krbi\n"
          "                       (binary floats), ldfi or lrfi (text)\n"
          "  --dx M               .crg output: resample every M m (default: the input's own\n"
          "                       spacing, which must then be even), the last row at the\n"
          "                       road's end or the first past it; at most 1e8 rows\n"
          "  --half-width M       .crg output of one track: the road reaches M m to either\n"
          "                       side, the same heights across (default 0.5)\n"
          "  --pad M              .crg output of a profile that starts or ends with a wall (a\n"
          "                       bounded obstacle): M m of flat ground at its end heights\n"
          "                       beyond the wall, which a road file has no other way to\n"
          "                       keep (default 1; 0 refuses such a profile)\n"
          "  -h, --help           show this help\n",
          fp);
}

typedef struct {
    const char *in, *out;
    tirenv_road_file *file;    /* --profile, open: read once, its format told once */
    int have_track;
    /* Which of the options that apply to one input or output format were given: one that
     * would change nothing is refused, as --track is for a CSV or RDF input. */
    int have_side, have_nan_mode, have_encoding, have_dx, have_half_width, have_pad;
    double pad;                /* --pad: flat ground before and after a wall at an end, m */
    tirenv_profile_source src;
    tirenv_profile_write_options w;
} convert;

static int parse_track(void *dst, const char *arg)
{
    convert *cv = dst;
    if (cli_parse_double(arg, &cv->src.crg.v)) {
        cli_error("convert: --track expects a lateral position in m, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    cv->have_track = 1;
    return CLI_EXIT_OK;
}

static int parse_pad(void *dst, const char *arg)
{
    convert *cv = dst;
    if (cli_parse_double(arg, &cv->pad) || !(cv->pad >= 0) || !isfinite(cv->pad)) {
        cli_error("convert: --pad expects a length >= 0 in m, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    cv->have_pad = 1;
    return CLI_EXIT_OK;
}

static int parse_side(void *dst, const char *arg)
{
    convert *cv = dst;
    if (tirenv_rdf_side_find(arg, &cv->src.rdf_side)) {
        cli_error("convert: --side expects left, right or mean, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    cv->have_side = 1;
    return CLI_EXIT_OK;
}

static int parse_nan_mode(void *dst, const char *arg)
{
    convert *cv = dst;
    cv->have_nan_mode = 1;
    return cli_parse_crg_nan_mode(&cv->src.crg, arg);
}

static int parse_encoding(void *dst, const char *arg)
{
    convert *cv = dst;
    cv->have_encoding = 1;
    return cli_parse_crg_encoding(&cv->w.crg_encoding, arg);
}

/* --dx and --half-width: a length > 0, m. */
static int parse_length(const char *name, const char *arg, double *v, int *given)
{
    if (cli_parse_double(arg, v) || !(*v > 0)) {
        cli_error("--%s: expected a positive length in m, got '%s'", name, arg);
        return CLI_EXIT_USAGE;
    }
    *given = 1;
    return CLI_EXIT_OK;
}

static int parse_dx(void *dst, const char *arg)
{
    convert *cv = dst;
    return parse_length("dx", arg, &cv->w.crg_u_increment, &cv->have_dx);
}

/* The long sections at -M and +M must lie within a road's coordinates (the writer and the
 * reader refuse a road beyond them). */
static int parse_half_width(void *dst, const char *arg)
{
    convert *cv = dst;
    const int code = parse_length("half-width", arg, &cv->w.crg_half_width,
                                  &cv->have_half_width);
    if (code || cv->w.crg_half_width <= TIRENV_PROFILE_MAX_COORDINATE)
        return code;
    cli_error("--half-width: expected a positive length in m up to %g, a road's lateral "
              "reach, got '%s'", TIRENV_PROFILE_MAX_COORDINATE, arg);
    return CLI_EXIT_USAGE;
}

/* An option given for a format it does not apply to changes nothing in what is written: the
 * first such one, refused, or NULL. A .crg to a .crg without --track is a copy of every long
 * section as it lies, its rows and lateral positions the input's. */
static const char *unused_option(const convert *cv, tirenv_profile_format from,
                                 tirenv_profile_format to, char *buf, size_t n)
{
    const char *in = from == TIRENV_PROFILE_CRG ? "a .crg" : from == TIRENV_PROFILE_RDF
                                                                ? "an RDF road"
                                                                : "a CSV profile";
    const int copy = from == TIRENV_PROFILE_CRG && to == TIRENV_PROFILE_CRG && !cv->have_track;
    if (cv->have_side && from != TIRENV_PROFILE_RDF)
        snprintf(buf, n, "--side applies to an RDF input; %s is %s", cv->in, in);
    else if (cv->have_nan_mode && from != TIRENV_PROFILE_CRG)
        snprintf(buf, n, "--crg-nan-mode applies to a .crg input; %s is %s", cv->in, in);
    else if ((cv->have_encoding || cv->have_dx || cv->have_half_width || cv->have_pad) &&
             to != TIRENV_PROFILE_CRG)
        snprintf(buf, n, "--%s applies to a .crg output; %s is written as %s",
                 cv->have_encoding ? "crg-encoding" : cv->have_dx ? "dx"
                                                  : cv->have_half_width ? "half-width"
                                                                        : "pad",
                 cv->out, tirenv_profile_format_name(to));
    else if ((cv->have_dx || cv->have_half_width) && copy)
        snprintf(buf, n, "--%s with a .crg copied to a .crg: the copy keeps every long "
                 "section with the input's rows and lateral positions; give --track V to "
                 "write one track, resampled and as wide as asked",
                 cv->have_dx ? "dx" : "half-width");
    else if (cv->have_pad && from == TIRENV_PROFILE_CRG)
        snprintf(buf, n, "--pad applies to a CSV or RDF profile that starts or ends with a "
                 "wall; a .crg road has none");
    else
        return NULL;
    return buf;
}

/* Returns an exit code, or CLI_GO_ON. */
static int parse(int argc, char *argv[], convert *cv)
{
    const cli_opt own[] = {
        {.name = "profile", .kind = CLI_STRING, .dst = &cv->in},
        {.name = "track", .kind = CLI_CUSTOM, .dst = cv, .parse = parse_track},
        {.name = "side", .kind = CLI_CUSTOM, .dst = cv, .parse = parse_side},
        {.name = "crg-nan-mode", .kind = CLI_CUSTOM, .dst = cv, .parse = parse_nan_mode},
        {.name = "crg-encoding", .kind = CLI_CUSTOM, .dst = cv, .parse = parse_encoding},
        {.name = "dx", .kind = CLI_CUSTOM, .dst = cv, .parse = parse_dx},
        {.name = "half-width", .kind = CLI_CUSTOM, .dst = cv, .parse = parse_half_width},
        {.name = "pad", .kind = CLI_CUSTOM, .dst = cv, .parse = parse_pad},
        {.name = NULL},
    };
    const cli_parser p = {.name = "convert", .usage = usage, .opts = own, .groups = CLI_OUTPUT};
    cli_options o;
    const int code = cli_parse(&p, argc, argv, &o);
    if (code != CLI_GO_ON)
        return code;
    cv->out = o.output;
    if (!cv->in || !cv->out) {
        cli_error("convert: expected %s; 'tirenv convert --help' shows the options",
                  !cv->in ? "--profile IN" : "-o OUT");
        return CLI_EXIT_USAGE;
    }
    return CLI_GO_ON;
}

/* A .crg to a .crg without --track: every long section, row by row, where the input lies:
 * its reference line's start and heading in x/y (its offsets and modifiers applied, as
 * tirenv_crg_refline places it) and its first row's height as START_Z, so that OpenCRG
 * evaluates the copy at every (x, y) as the input (tests/formats/crg_opencrg_samples.sh). A
 * curved reference line is refused: the copy's is straight and would lie elsewhere. */
static int crg_copy(const tirenv_crg *crg, const convert *cv, tirenv_diag *diag)
{
    if (tirenv_crg_is_curved(crg))
        return tirenv_error(diag, TIRENV_EINVAL, cv->in, 0, "reference line phi",
                            "a curved reference line: tirenv writes an OpenCRG road on a "
                            "straight one, which would lie elsewhere; convert a track "
                            "(--track V) to .csv, .rdf or .crg instead");
    const size_t nv = tirenv_crg_long_sections(crg), nu = tirenv_crg_rows(crg);
    double *v = malloc(nv * sizeof *v);
    double *x = malloc(nu * sizeof *x), *y = malloc(nu * sizeof *y);
    double *phi = malloc(nu * sizeof *phi), *z0 = malloc(nv * sizeof *z0);
    int status = v && x && y && phi && z0
                     ? tirenv_crg_refline(crg, x, y, phi, diag)
                     : tirenv_error(diag, TIRENV_ENOMEM, cv->out, 0, "", "out of memory");
    if (!status)
        status = tirenv_crg_grid_rows(crg, 0, 1, z0, diag);
    /* START_Z: the first row's first height (the rows then hold the relief less it, which
     * OpenCRG keeps in single precision). */
    double z_start = 0;
    for (size_t j = 0; !status && j < nv; j++) {
        v[j] = tirenv_crg_v(crg, j);
        if (isfinite(z0[j]) && z_start == 0)
            z_start = z0[j];
    }
    const tirenv_crg_layout layout = {
        .encoding = cv->w.crg_encoding, .u_start = tirenv_crg_u_start(crg),
        .x_start = status ? 0 : x[0], .y_start = status ? 0 : y[0],
        .phi_start = status ? 0 : phi[0], .z_start = z_start,
        .u_increment = tirenv_crg_u_increment(crg), .rows = nu, .long_sections = nv, .v = v,
        .comment = "Converted by tirenv convert: every long section, heights with the\n"
                   "reference line's slope and banking, where the input's line lies."};
    free(x);
    free(y);
    free(phi);
    free(z0);
    if (status) {
        free(v);
        return status;
    }
    tirenv_crg_writer *w = NULL;
    enum { BLOCK = 1024 };
    double *z = malloc(BLOCK * nv * sizeof *z);
    status = z ? tirenv_crg_writer_open(cv->out, &layout, &w, diag)
                   : tirenv_error(diag, TIRENV_ENOMEM, cv->out, 0, "", "out of memory");
    for (size_t i0 = 0; !status && i0 < nu; i0 += BLOCK) {
        const size_t n = nu - i0 < BLOCK ? nu - i0 : BLOCK;
        status = tirenv_crg_grid_rows(crg, i0, n, z, diag);
        for (size_t k = 0; !status && k < n; k++)
            status = tirenv_crg_writer_row(w, z + k * nv, diag);
    }
    free(z);
    free(v);
    if (status) {
        tirenv_crg_writer_abort(w);
        return status;
    }
    return tirenv_crg_writer_commit(w, diag);
}

/* A .crg track to CSV, a block of rows at a time, so a long road needs little memory: the
 * open file's row reader (tirenv_road_file_reader), which envelope --stream reads too. */
static int crg_to_csv(const tirenv_crg *crg, const convert *cv, double range[4],
                      tirenv_diag *diag)
{
    tirenv_profile_file_reader *r;
    int status = tirenv_road_file_reader(cv->file, &cv->src, 1, NULL, &r, diag);
    if (status)
        return status;
    tirenv_outfile *f;
    if ((status = tirenv_outfile_open(&f, cv->out, diag))) {
        tirenv_profile_file_reader_free(r);
        return status;
    }
    char comment[160], v[TIRENV_FMT_G_SIZE];
    tirenv_fmt_shortest(cv->src.crg.v, v);
    snprintf(comment, sizeof comment, "track at v = %s m of an OpenCRG road (tirenv convert)", v);
    FILE *fp = tirenv_outfile_stream(f);
    fputs("x_m,z_m\n", fp);
    tirenv_outfile_comment(f, comment);
    double u, z;
    int got;
    char a[TIRENV_FMT_G_SIZE], b[TIRENV_FMT_G_SIZE];
    while (!(status = tirenv_profile_file_reader_next(r, &u, &z, &got, diag)) && got) {
        tirenv_fmt_shortest(u, a);  /* the heights read back exactly, as every writer's */
        tirenv_fmt_shortest(z, b);
        fprintf(fp, "%s,%s\n", a, b);
        range[2] = fmin(range[2], z);
        range[3] = fmax(range[3], z);
    }
    tirenv_profile_file_reader_free(r);
    if (status) {
        tirenv_outfile_abort(f);
        return status;
    }
    range[0] = tirenv_crg_u_start(crg);
    range[1] = tirenv_crg_u_end(crg);
    return tirenv_outfile_commit(f, diag);
}

/* A .crg resampled every --dx holds the profile's length over it in rows: a typo such as
 * 1e-9 for 1e-3 would write 16 bytes a row per long section, 32 GB over 2 m, before it ended.
 * At most as many rows as a streamed sweep's positions (CLI_MAX_STREAM_POSITIONS), the
 * same bound for the same reason. */
static int check_rows(const convert *cv, const tirenv_profile *p, tirenv_diag *diag)
{
    if (!cv->have_dx)
        return TIRENV_OK;
    double x0, x1;
    tirenv_profile_extent(p, &x0, &x1);
    const double rows = ceil((x1 - x0) / cv->w.crg_u_increment) + 1;
    if (!(rows <= CLI_MAX_STREAM_POSITIONS))
        return tirenv_error(diag, TIRENV_EINVAL, cv->out, 0, "dx",
                            "%.3g rows from %g to %g m every %g m is too many (at most %.0f); "
                            "expected a larger --dx", rows, x0, x1, cv->w.crg_u_increment,
                            CLI_MAX_STREAM_POSITIONS);
    return TIRENV_OK;
}

/* Every read of the .crg goes through the open file's one handle (tirenv_road_file_crg): its
 * pass at open made once, for the copy, the row reader or the track read whole. */
static int from_crg(const convert *cv, tirenv_profile_format to, size_t *n, double range[4],
                    tirenv_diag *diag)
{
    const tirenv_crg *crg;
    int status = tirenv_road_file_crg(cv->file, &crg, diag);
    if (status)
        return status;
    *n = tirenv_crg_rows(crg);
    if (to == TIRENV_PROFILE_CSV) {
        status = crg_to_csv(crg, cv, range, diag);
    } else if (to == TIRENV_PROFILE_CRG && !cv->have_track) {
        range[0] = tirenv_crg_u_start(crg);
        range[1] = tirenv_crg_u_end(crg);
        status = crg_copy(crg, cv, diag);
    } else {
        tirenv_profile *p;
        if (!(status = tirenv_road_file_read(cv->file, &cv->src, 1, NULL, &p, diag))) {
            if (!(status = check_rows(cv, p, diag)))
                status = tirenv_profile_write_file(cv->out, p, &cv->w, diag);
            const double *x = tirenv_profile_x(p), *z = tirenv_profile_z(p);
            range[0] = x[0];
            range[1] = x[*n - 1];
            for (size_t k = 0; k < *n; k++) {
                range[2] = fmin(range[2], z[k]);
                range[3] = fmax(range[3], z[k]);
            }
            tirenv_profile_free(p);
        }
    }
    return status;
}

/* A profile that starts or ends with a wall (a bounded obstacle: two vertices at its first or
 * last x) has its ground beyond that wall only by tirenv's rule that a profile goes on level
 * at its end heights; an OpenCRG road has no ground beyond its rows, and its first row at the
 * wall would take the wall's top (the higher side), so the obstacle would become a plateau.
 * Flat ground of --pad m at the end heights is added before it is written (default 1 m), or
 * with --pad 0 the conversion is refused, saying so. Other profiles are written unchanged. */
static int pad_walls(const convert *cv, tirenv_profile **p, tirenv_diag *diag)
{
    const size_t n = tirenv_profile_size(*p);
    const double *x = tirenv_profile_x(*p), *z = tirenv_profile_z(*p);
    const int wall_first = n >= 2 && x[0] == x[1], wall_last = n >= 2 && x[n - 1] == x[n - 2];
    if (!wall_first && !wall_last)
        return TIRENV_OK;
    if (!(cv->pad > 0))
        return tirenv_error(diag, TIRENV_EINVAL, cv->in, 0, "",
                            "the profile %s with a wall at x = %g m: an OpenCRG road has no "
                            "ground beyond its rows, so the wall and the ground %s it would be "
                            "lost; give --pad M for M m of flat ground at each end",
                            wall_first ? "starts" : "ends", wall_first ? x[0] : x[n - 1],
                            wall_first ? "before" : "after");
    /* The pad's vertex must be a profile's (tirenv_profile_validate): one segment, within
     * the coordinates' bound. Checked here, as --pad's: the profile's own check named a
     * vertex of IN that IN does not have ("wall.csv: vertex 4: x = 1e+300 m"). */
    const double end = wall_first ? x[0] : x[n - 1];
    const double most = fmin(TIRENV_PROFILE_MAX_SEGMENT,
                             TIRENV_PROFILE_MAX_COORDINATE - (wall_first ? -end : end));
    if (cv->pad > most)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "--pad",
                            "%g m of flat ground beyond the wall at x = %g m; expected at most "
                            "%g m (a profile's segments reach %g m, its vertices +-%g m)",
                            cv->pad, end, most, TIRENV_PROFILE_MAX_SEGMENT,
                            TIRENV_PROFILE_MAX_COORDINATE);
    double *px = malloc((n + 2) * sizeof *px), *pz = malloc((n + 2) * sizeof *pz);
    if (!px || !pz) {
        free(px);
        free(pz);
        return tirenv_error(diag, TIRENV_ENOMEM, cv->in, 0, "", "out of memory");
    }
    size_t m = 0;
    if (wall_first) {
        px[m] = x[0] - cv->pad;
        pz[m++] = z[0];
    }
    memcpy(px + m, x, n * sizeof *px);
    memcpy(pz + m, z, n * sizeof *pz);
    m += n;
    if (wall_last) {
        px[m] = x[n - 1] + cv->pad;
        pz[m++] = z[n - 1];
    }
    tirenv_profile *padded;
    const int status = tirenv_profile_make(m, px, pz, cv->in, &padded, diag);
    free(px);
    free(pz);
    if (status)
        return status;
    tirenv_profile_free(*p);
    *p = padded;
    return TIRENV_OK;
}

int cli_convert_main(int argc, char *argv[])
{
    convert cv = {.pad = 1, .src = tirenv_profile_source_default(),
                  .w = tirenv_profile_write_default()};
    const int code = parse(argc, argv, &cv);
    if (code != CLI_GO_ON)
        return code;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_profile_format from, to = TIRENV_PROFILE_CSV;
    /* "-", /dev/null, a FIFO: written through, as CSV unless the name says otherwise. */
    if (tirenv_profile_format_of_name(cv.out, &to) && !tirenv_outfile_path_is_through(cv.out)) {
        cli_error("convert: -o %s: unknown extension; expected .csv, .crg or .rdf, or a "
                  "device, a FIFO or '-' (written as CSV)", cv.out);
        return CLI_EXIT_USAGE;
    }
    int status = tirenv_road_file_open(cv.in, &cv.file, &diag);
    if (status)
        return cli_fail(status, &diag);
    from = tirenv_road_file_format(cv.file);
    if (cv.have_track && from != TIRENV_PROFILE_CRG) {
        cli_error("convert: --track applies to a .crg input; %s is %s", cv.in,
                  from == TIRENV_PROFILE_RDF ? "an RDF road (use --side)" : "a CSV profile");
        tirenv_road_file_free(cv.file);
        return CLI_EXIT_USAGE;
    }
    char why[400];
    if (unused_option(&cv, from, to, why, sizeof why)) {
        cli_error("convert: %s", why);
        tirenv_road_file_free(cv.file);
        return CLI_EXIT_USAGE;
    }
    size_t n = 0;
    double range[4] = {0, 0, INFINITY, -INFINITY};
    if (from == TIRENV_PROFILE_CRG) {
        status = from_crg(&cv, to, &n, range, &diag);
    } else {
        tirenv_profile *p;
        if (!(status = tirenv_road_file_read(cv.file, &cv.src, 1, NULL, &p, &diag))) {
            if (to == TIRENV_PROFILE_CSV)
                status = tirenv_profile_write_csv(cv.out, p, cv.w.comment, &diag);
            else if (to != TIRENV_PROFILE_CRG || (!(status = pad_walls(&cv, &p, &diag)) &&
                                                  !(status = check_rows(&cv, p, &diag))))
                status = tirenv_profile_write_file(cv.out, p, &cv.w, &diag);
            n = tirenv_profile_size(p);
            const double *x = tirenv_profile_x(p), *z = tirenv_profile_z(p);
            range[0] = x[0];
            range[1] = x[n - 1];
            for (size_t k = 0; k < n; k++) {
                range[2] = fmin(range[2], z[k]);
                range[3] = fmax(range[3], z[k]);
            }
            tirenv_profile_free(p);
        }
    }
    tirenv_road_file_free(cv.file);
    if (status) {
        const int failed = cli_fail(status, &diag);
        if (strcmp(diag.field, "u_increment") == 0 && !cv.have_dx) /* the library's --dx */
            cli_error("convert: --dx M resamples the road every M metres");
        return failed;
    }
    fprintf(stderr, "tirenv convert: %s (%s) -> %s (%s): %zu %s, x %g to %g m", cv.in,
            tirenv_profile_format_name(from), cv.out, tirenv_profile_format_name(to), n,
            from == TIRENV_PROFILE_CRG ? "rows" : "vertices", range[0], range[1]);
    if (range[2] <= range[3])
        fprintf(stderr, ", z %g to %g m", range[2], range[3]);
    fputc('\n', stderr);
    return CLI_EXIT_OK;
}
