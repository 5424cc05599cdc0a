/* Writing OpenCRG files: a straight reference line along x, long sections at given v, rows
 * written one after the other in any of the four encodings, through tirenv_outfile (all or
 * nothing). SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/crg.h"
#include "tirenv/numtext.h"
#include "tirenv/outfile.h"
#include "tirenv/tirenv.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/io.h"

enum { RECORD_BYTES = 80, HEADER_RECORD = 72 };

struct tirenv_crg_writer {
    tirenv_outfile *out;
    tirenv_crg_encoding enc;
    double z_start;                     /* m, subtracted from every height */
    size_t rows, nv, written;
    double *v;
    unsigned char record[RECORD_BYTES]; /* binary: the record being filled */
    size_t used;                        /* bytes of it filled */
};


/* v in exactly w characters, fixed-point or scientific, whichever reads back closer (fixed on
 * a tie); a leading blank before a non-negative number keeps columns readable. */
static void format_field(char *buf, size_t w, double v)
{
    if (isnan(v)) {
        memset(buf, '*', w);
        memcpy(buf, " *missing", 9);
        buf[w] = '\0';
        return;
    }
    char fixed[64] = "", sci[64] = "";
    for (int d = (int)w - 2; d >= 0 && !fixed[0]; d--) {
        snprintf(fixed, sizeof fixed, "% *.*f", (int)w, d, v);
        if (strlen(fixed) != w)
            fixed[0] = '\0';
    }
    for (int d = (int)w - 7; d >= 0 && !sci[0]; d--) {
        snprintf(sci, sizeof sci, "% *.*e", (int)w, d, v);
        if (strlen(sci) != w)
            sci[0] = '\0';
    }
    const double ef = fixed[0] ? fabs(strtod(fixed, NULL) - v) : INFINITY;
    const double es = sci[0] ? fabs(strtod(sci, NULL) - v) : INFINITY;
    const char *best = ef <= es ? fixed : sci; /* w characters, or "" */
    const size_t len = strlen(best) < w ? strlen(best) : w;
    memcpy(buf, best, len);
    buf[len] = '\0';
}

static int check_layout(const char *path, const tirenv_crg_layout *l, tirenv_diag *diag)
{
    if (!tirenv_crg_encoding_name(l->encoding))
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "encoding",
                            "unknown encoding %d; expected LRFI, LDFI, KRBI or KDBI",
                            (int)l->encoding);
    if (!(isfinite(l->x_start) && isfinite(l->y_start) && isfinite(l->phi_start) &&
          isfinite(l->z_start)))
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "x_start",
                            "reference line start (%g, %g, %g) m, heading %g rad: expected "
                            "finite", l->x_start, l->y_start, l->z_start, l->phi_start);
    if (!(isfinite(l->u_start) && l->u_increment > 0 && isfinite(l->u_increment)))
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "u_increment",
                            "u_start %g and u_increment %g: expected finite, increment > 0",
                            l->u_start, l->u_increment);
    if (l->rows < 2 || l->rows > (size_t)1 << 40)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "rows",
                            "%zu rows; expected at least 2", l->rows);
    if (!isfinite(l->u_start + (double)(l->rows - 1) * l->u_increment))
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "rows", "the road's end overflows");
    if (l->long_sections < 2 || l->long_sections > 100000 || !l->v)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "long_sections",
                            "%zu long sections; expected 2 to 100000 with their positions",
                            l->long_sections);
    /* Within a road's coordinates, as the reader asks (crg_header.c): convert --half-width
     * 1e300 wrote a road whose width overflows. */
    for (size_t j = 0; j < l->long_sections; j++)
        if (!(fabs(l->v[j]) <= TIRENV_PROFILE_MAX_COORDINATE) ||
            (j > 0 && !(l->v[j] > l->v[j - 1])))
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "v",
                                "long section %zu at v = %g; expected ascending positions "
                                "within +-%g m", j + 1, l->v[j], TIRENV_PROFILE_MAX_COORDINATE);
    for (const char *line = l->comment; line && *line;) {
        const size_t n = strcspn(line, "\n");
        if (n > HEADER_RECORD || line[0] == '$' || line[0] == '*')
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "comment",
                                "comment line '%.40s...' is longer than %d characters or "
                                "starts with '$' or '*'", line, HEADER_RECORD);
        line += n + (line[n] == '\n');
    }
    return TIRENV_OK;
}

static void write_header(FILE *fp, const tirenv_crg_layout *l)
{
    char a[40], b[40], c[40];
    fputs("$CT\n", fp);
    fprintf(fp, "Road surface written by tirenv %s\n", TIRENV_VERSION);
    if (l->comment && *l->comment) {
        fputs(l->comment, fp);
        if (l->comment[strlen(l->comment) - 1] != '\n')
            fputc('\n', fp);
    }
    fputs("$\n$ROAD_CRG\n", fp);
    tirenv_fmt_shortest(l->u_start, a);
    tirenv_fmt_shortest(l->u_start + (double)(l->rows - 1) * l->u_increment, b);
    tirenv_fmt_shortest(l->u_increment, c);
    fprintf(fp, "REFERENCE_LINE_START_U   = %s\nREFERENCE_LINE_END_U     = %s\n"
                "REFERENCE_LINE_INCREMENT = %s\n", a, b, c);
    tirenv_fmt_shortest(l->x_start, a);
    tirenv_fmt_shortest(l->y_start, b);
    tirenv_fmt_shortest(l->phi_start, c);
    fprintf(fp, "REFERENCE_LINE_START_X   = %s\nREFERENCE_LINE_START_Y   = %s\n"
                "REFERENCE_LINE_START_PHI = %s\n", a, b, c);
    /* OpenCRG takes a straight line's heading beyond its start (its xy2uv past the last row,
     * its heading along the line) from END_PHI, 0 when not given: a turned line states it. */
    if (l->phi_start != 0)
        fprintf(fp, "REFERENCE_LINE_END_PHI   = %s\n", c);
    if (l->z_start != 0) {
        tirenv_fmt_shortest(l->z_start, a);
        fprintf(fp, "REFERENCE_LINE_START_Z   = %s\n", a);
    }
    tirenv_fmt_shortest(l->v[0], a);
    tirenv_fmt_shortest(l->v[l->long_sections - 1], b);
    fprintf(fp, "LONG_SECTION_V_RIGHT     = %s\nLONG_SECTION_V_LEFT      = %s\n", a, b);
    /* A modifier section, even one that sets nothing, replaces OpenCRG's default modifiers
     * (which move the reference point to x = y = z = 0, heading 0): the road stays where
     * the reference line above puts it, at the heights below. */
    fputs("$\n$ROAD_CRG_MODS\n"
          "* no modifiers: evaluate the road where its reference line puts it\n", fp);
    fputs("$\n$KD_DEFINITION\n", fp);
    fprintf(fp, "#:%s\n", tirenv_crg_encoding_name(l->encoding));
    for (size_t j = 0; j < l->long_sections; j++) {
        tirenv_fmt_shortest(l->v[j], a);
        fprintf(fp, "D:long section at v = %s,m\n", a);
    }
    fputs("$\n", fp);
    for (int k = 0; k < HEADER_RECORD; k++)
        fputc('$', fp);
    fputc('\n', fp);
}

void tirenv_crg_writer_abort(tirenv_crg_writer *w)
{
    if (!w)
        return;
    tirenv_outfile_abort(w->out);
    free(w->v);
    free(w);
}

int tirenv_crg_writer_open(const char *path, const tirenv_crg_layout *layout,
                           tirenv_crg_writer **out, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *out = NULL;
    int status = check_layout(path, layout, diag);
    if (status)
        return status;
    tirenv_crg_writer *w = calloc(1, sizeof *w);
    if (w)
        w->v = malloc(layout->long_sections * sizeof *w->v);
    if (!w || !w->v) {
        free(w);
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    }
    memcpy(w->v, layout->v, layout->long_sections * sizeof *w->v);
    w->enc = layout->encoding;
    w->z_start = layout->z_start;
    w->rows = layout->rows;
    w->nv = layout->long_sections;
    if ((status = tirenv_outfile_open(&w->out, path, diag))) {
        free(w->v);
        free(w);
        return status;
    }
    write_header(tirenv_outfile_stream(w->out), layout);
    *out = w;
    return TIRENV_OK;
}

static void put_binary(tirenv_crg_writer *w, double v)
{
    unsigned char b[8];
    size_t n;
    if (w->enc == TIRENV_CRG_KRBI) {
        const float f = (float)v;
        uint32_t u;
        memcpy(&u, &f, sizeof u);
        for (n = 0; n < 4; n++)
            b[n] = (unsigned char)(u >> (24 - 8 * n));
    } else {
        uint64_t u;
        memcpy(&u, &v, sizeof u);
        for (n = 0; n < 8; n++)
            b[n] = (unsigned char)(u >> (56 - 8 * n));
    }
    memcpy(w->record + w->used, b, n);
    w->used += n;
    if (w->used == RECORD_BYTES) {
        fwrite(w->record, 1, RECORD_BYTES, tirenv_outfile_stream(w->out));
        w->used = 0;
    }
}

int tirenv_crg_writer_row(tirenv_crg_writer *w, const double z[], tirenv_diag *diag)
{
    const char *path = tirenv_outfile_path(w->out);
    if (w->written == w->rows)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "rows",
                            "row %zu beyond the %zu rows of the layout", w->written + 1,
                            w->rows);
    size_t lo = w->nv, hi = 0;
    for (size_t j = 0; j < w->nv; j++) {
        const double zw = z[j] - w->z_start;  /* what the file holds */
        if (isinf(z[j]) || isinf(zw) || (w->enc == TIRENV_CRG_KRBI && !isnan(zw) &&
                                         isinf((float)zw)))
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "z",
                                "row %zu, long section %zu: height %g is not finite%s",
                                w->written + 1, j + 1, z[j],
                                w->enc == TIRENV_CRG_KRBI ? " as a float32" : "");
        if (!isnan(z[j])) {
            lo = lo < j ? lo : j;
            hi = j;
        }
    }
    if (lo == w->nv)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "z",
                            "row %zu has no height; expected at least one number",
                            w->written + 1);
    for (size_t j = lo; j <= hi; j++)
        if (isnan(z[j]))
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "z",
                                "row %zu, long section %zu: missing value between numbers; "
                                "OpenCRG allows them only at a row's ends", w->written + 1,
                                j + 1);
    if (w->enc == TIRENV_CRG_KRBI || w->enc == TIRENV_CRG_KDBI) {
        for (size_t j = 0; j < w->nv; j++)
            put_binary(w, z[j] - w->z_start);
    } else {
        const size_t width = w->enc == TIRENV_CRG_LRFI ? 10 : 20;
        const size_t per = RECORD_BYTES / width;
        FILE *const fp = tirenv_outfile_stream(w->out);
        char field[32];
        for (size_t j = 0; j < w->nv; j++) {
            format_field(field, width, z[j] - w->z_start);
            fputs(field, fp);
            if ((j + 1) % per == 0 || j + 1 == w->nv)
                fputc('\n', fp);
        }
    }
    w->written++;
    return TIRENV_OK;
}

int tirenv_crg_writer_commit(tirenv_crg_writer *w, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    if (w->written != w->rows) {
        const int status = tirenv_error(diag, TIRENV_EINVAL, tirenv_outfile_path(w->out), 0, "rows",
                                        "%zu rows written of the %zu the layout announced",
                                        w->written, w->rows);
        tirenv_crg_writer_abort(w);
        return status;
    }
    while (w->used > 0) /* the last record is padded with NaN */
        put_binary(w, NAN);
    const int status = tirenv_outfile_commit(w->out, diag);
    free(w->v);
    free(w);
    return status;
}

/* ---- profiles ---------------------------------------------------------------------------- */

/* The profiles' common x, if they share one evenly spaced x: its start and step. */
static int shared_grid(size_t n, const tirenv_profile *const tracks[], double *x0, double *dx,
                       size_t *rows)
{
    const size_t m = tirenv_profile_size(tracks[0]);
    const double *x = tirenv_profile_x(tracks[0]);
    if (m < 2)
        return 0;
    for (size_t k = 1; k < n; k++)
        if (tirenv_profile_size(tracks[k]) != m ||
            memcmp(tirenv_profile_x(tracks[k]), x, m * sizeof *x) != 0)
            return 0;
    const double step = (x[m - 1] - x[0]) / (double)(m - 1);
    if (!(step > 0))
        return 0;
    for (size_t i = 0; i < m; i++)
        if (fabs(x[i] - (x[0] + (double)i * step)) > 1e-6 * step)
            return 0;
    *x0 = x[0];
    *dx = step;
    *rows = m;
    return 1;
}

int tirenv_crg_write_profiles(const char *path, tirenv_crg_encoding encoding, size_t n,
                              const double v[], const tirenv_profile *const tracks[],
                              double u_increment, const char *comment, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    if (n < 2 || !tracks || !v)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "tracks",
                            "%zu tracks; an OpenCRG road needs at least two long sections", n);
    for (size_t k = 0; k < n; k++)
        if (!tracks[k])
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "tracks", "track %zu is NULL",
                                k + 1);
    double x0, dx;
    size_t rows;
    const int on_grid = u_increment == 0 && shared_grid(n, tracks, &x0, &dx, &rows);
    if (u_increment == 0 && !on_grid)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "u_increment",
                            "the profiles do not share one evenly spaced x (an OpenCRG road is "
                            "a regular grid); give an increment to resample them");
    if (!on_grid) {
        if (!(u_increment > 0 && isfinite(u_increment)))
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "u_increment",
                                "increment %g; expected a positive length, m", u_increment);
        double lo = -INFINITY, hi = INFINITY;
        for (size_t k = 0; k < n; k++) {
            double a, b;
            tirenv_profile_extent(tracks[k], &a, &b);
            lo = fmax(lo, a);
            hi = fmin(hi, b);
        }
        /* Rows up to the extent's end or the first one past it (where the profiles go on
         * level at their end heights): a last row short of the end dropped the road's last
         * part, 0.1 m and its height of a 1 m road every 0.3 m. An extent within 1e-9 of
         * whole increments ends on a row. */
        const double span = ceil((hi - lo) / u_increment - 1e-9);
        if (!(span >= 1) || span > 1e12)
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "u_increment",
                                "the profiles' common extent %g to %g m holds %g increments of "
                                "%g m; expected at least one", lo, hi, span + 0.0 /* not -0 */,
                                u_increment);
        x0 = lo;
        dx = u_increment;
        rows = (size_t)span + 1;
    }
    /* The line on the x axis where the profiles' x is (x = u): from the origin, OpenCRG's x/y
     * evaluation put every height x0 before its x. */
    const tirenv_crg_layout layout = {.encoding = encoding, .x_start = x0, .u_start = x0,
                                      .u_increment = dx, .rows = rows, .long_sections = n,
                                      .v = v, .comment = comment};
    tirenv_crg_writer *w;
    int status = tirenv_crg_writer_open(path, &layout, &w, diag);
    if (status)
        return status;
    double *z = malloc(n * sizeof *z);
    if (!z)
        status = tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    for (size_t i = 0; !status && i < rows; i++) {
        for (size_t k = 0; k < n; k++)
            z[k] = on_grid ? tirenv_profile_z(tracks[k])[i]
                           : tirenv_profile_height(tracks[k], x0 + (double)i * dx);
        status = tirenv_crg_writer_row(w, z, diag);
    }
    free(z);
    if (status) {
        tirenv_crg_writer_abort(w);
        return status;
    }
    return tirenv_crg_writer_commit(w, diag);
}
