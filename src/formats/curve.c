/* Enveloping curves on an x_N grid (docs/models.md section 1; x_N itself is the core's,
 * src/nn/xn.c): storage, and the CSV format "x_N,x_m,h_m" the import writes and the data
 * sets read.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/curve.h"
#include "tirenv/numtext.h"
#include "tirenv/outfile.h"
#include "tirenv/profile.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io.h"

enum { CURVE_FIELDS = 3 };
static const char *const curve_names[CURVE_FIELDS] = {"x_N", "x_m", "h_m"};
static const char curve_header[] = "x_N,x_m,h_m";

int tirenv_curve_alloc(tirenv_curve *c, size_t n)
{
    c->n = 0;
    c->x_N = c->x = c->h = NULL;
    /* calloc(0) may return NULL; one element keeps "NULL means no memory" unambiguous. */
    const size_t m = n ? n : 1;
    c->x_N = calloc(m, sizeof *c->x_N);
    c->x = calloc(m, sizeof *c->x);
    c->h = calloc(m, sizeof *c->h);
    if (!c->x_N || !c->x || !c->h) {
        tirenv_curve_free(c);
        return TIRENV_ENOMEM;
    }
    c->n = n;
    return TIRENV_OK;
}

void tirenv_curve_free(tirenv_curve *c)
{
    if (!c)
        return;
    free(c->x_N);
    free(c->x);
    free(c->h);
    c->n = 0;
    c->x_N = c->x = c->h = NULL;
}

/* ---- writing ---------------------------------------------------------------------------- */

/* %.17g round-trips every double, so a curve read back is bit-identical. */
int tirenv_curve_write_csv(const char *path, const tirenv_curve *c, const char *comment,
                           tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    for (size_t k = 0; k < c->n; k++)
        if (!isfinite(c->x_N[k]) || !isfinite(c->x[k]) || !isfinite(c->h[k]))
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "",
                                "curve point %zu is not finite; nothing written", k + 1);
    tirenv_outfile *f;
    int status = tirenv_outfile_open(&f, path, diag);
    if (status != TIRENV_OK)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    int bad = fprintf(fp, "%s\n", curve_header) < 0;
    tirenv_outfile_comment(f, comment);
    for (size_t k = 0; k < c->n && !bad; k++) {
        /* As "%.17g,%.17g,%.17g\n", through the faster formatter. */
        char row[3 * TIRENV_FMT_G_SIZE], *p = row;
        p += tirenv_fmt_g(c->x_N[k], 17, p);
        *p++ = ',';
        p += tirenv_fmt_g(c->x[k], 17, p);
        *p++ = ',';
        p += tirenv_fmt_g(c->h[k], 17, p);
        *p++ = '\n';
        bad = fwrite(row, 1, (size_t)(p - row), fp) != (size_t)(p - row);
    }
    if (bad) {
        const int e = errno;
        tirenv_outfile_abort(f);
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot write: %s",
                            strerror(e ? e : EIO));
    }
    return tirenv_outfile_commit(f, diag);
}

/* ---- reading ---------------------------------------------------------------------------- */

/* Doubles the capacity of the three arrays, keeping c consistent if one realloc fails. */
static int curve_grow(tirenv_curve *c, size_t *cap)
{
    const size_t want = *cap ? 2 * *cap : 128;
    if (want > SIZE_MAX / sizeof(double))
        return TIRENV_ENOMEM;
    double **arrays[CURVE_FIELDS] = {&c->x_N, &c->x, &c->h};
    for (size_t k = 0; k < CURVE_FIELDS; k++) {
        double *p = realloc(*arrays[k], want * sizeof *p);
        if (!p)
            return TIRENV_ENOMEM;
        *arrays[k] = p;
    }
    *cap = want;
    return TIRENV_OK;
}

/* A curve lives on a grid: x_N strictly increasing is what every consumer (interpolation,
 * comparison, training) relies on, so it is checked here with the line that breaks it. */
static int curve_parse_row(tirenv_csv__reader *r, tirenv_curve *out, size_t *cap)
{
    tirenv_csv__field f[CURVE_FIELDS + 1];
    int status = tirenv_csv__fields(r, curve_names, CURVE_FIELDS, f);
    double v[CURVE_FIELDS];
    /* Within a road's bound (TIRENV_PROFILE_MAX_COORDINATE): h = 1e308 made a fit write its
     * tire (exit 0) and training fail naming no file. */
    for (size_t k = 0; k < CURVE_FIELDS && status == TIRENV_OK; k++)
        status = tirenv_csv__number_within(r, &f[k], curve_names[k],
                                           TIRENV_PROFILE_MAX_COORDINATE,
                                           k == 0 ? "a normalised position" : "a length in m",
                                           &v[k]);
    if (status != TIRENV_OK)
        return status;
    if (out->n > 0 && !(v[0] > out->x_N[out->n - 1]))
        return tirenv_csv__fail(r, f[0].column, "x_N",
                                "expected x_N to increase from row to row, got %.17g after %.17g",
                                v[0], out->x_N[out->n - 1]);
    if (out->n == *cap && curve_grow(out, cap) != TIRENV_OK)
        return tirenv_error(r->diag, TIRENV_ENOMEM, r->file, r->line, "", "out of memory");
    out->x_N[out->n] = v[0];
    out->x[out->n] = v[1];
    out->h[out->n] = v[2];
    out->n++;
    return TIRENV_OK;
}

static int curve_parse_lines(tirenv_csv__reader *r, tirenv_curve *out)
{
    size_t cap = 0;
    int more = tirenv_csv__next(r);
    if (more == 0) {
        const int status = tirenv_error(r->diag, TIRENV_EPARSE, r->file, 1, "",
                                        "no header: the file is empty or holds only blank and "
                                        "comment lines; expected the header '%s', then rows",
                                        curve_header);
        if (r->diag)
            r->diag->column = 1;
        return status;
    }
    int status = more < 0 ? -more : tirenv_csv__header(r, curve_names, CURVE_FIELDS);
    while (status == TIRENV_OK && (more = tirenv_csv__next(r)) > 0)
        status = curve_parse_row(r, out, &cap);
    if (status == TIRENV_OK && more < 0)
        status = -more;
    if (status == TIRENV_OK && out->n == 0) {
        status = tirenv_error(r->diag, TIRENV_EPARSE, r->file, r->line + 1, "",
                              "no data rows after the header; expected at least one "
                              "'%s' row", curve_header);
        if (r->diag)
            r->diag->column = 1;
    }
    return status;
}

int tirenv_curve_read_csv(const char *path, tirenv_curve *out, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    out->n = 0;
    out->x_N = out->x = out->h = NULL;
    tirenv_csv__reader r;
    int status = tirenv_csv__open(&r, path, diag);
    if (status == TIRENV_OK)
        status = curve_parse_lines(&r, out);
    tirenv_csv__close(&r);
    if (status != TIRENV_OK)
        tirenv_curve_free(out);
    return status;
}
