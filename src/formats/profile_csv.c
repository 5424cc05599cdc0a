/* Measured ground profiles as CSV: header "x_m,z_m", one polyline vertex per line (docs/models.md
 * section 2). Reading, splitting and number checks are the shared ones of csv_line.c.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/profile_csv.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/profile_csv_impl.h"
#include "io/io.h"

enum { FIELDS = 2 };
static const char *const names[FIELDS] = {"x_m", "z_m"};

typedef struct {
    double *x, *z;         /* vertices, m */
    size_t n, cap;
} rows;

static int rows_grow(rows *r)
{
    const size_t cap = r->cap ? 2 * r->cap : 64;
    if (cap > SIZE_MAX / sizeof(double))
        return TIRENV_ENOMEM;
    /* Each array keeps its old block if a later realloc fails, so r stays consistent. */
    double *x = realloc(r->x, cap * sizeof *x);
    if (!x)
        return TIRENV_ENOMEM;
    r->x = x;
    double *z = realloc(r->z, cap * sizeof *z);
    if (!z)
        return TIRENV_ENOMEM;
    r->z = z;
    r->cap = cap;
    return TIRENV_OK;
}

/* One vertex; prev_x is the previous row's x as written, so "decreases" quotes the user. */
static int read_row(tirenv_csv__reader *rd, rows *r, char prev_x[32])
{
    tirenv_csv__field f[FIELDS + 1];
    int status = tirenv_csv__fields(rd, names, FIELDS, f);
    double v[FIELDS];
    for (size_t k = 0; k < FIELDS && status == TIRENV_OK; k++)
        status = tirenv_csv__number(rd, &f[k], names[k], &v[k]);
    if (status != TIRENV_OK)
        return status;
    if (r->n > 0 && v[0] < r->x[r->n - 1])
        return tirenv_csv__fail(rd, f[0].column, "x_m", "x_m decreases (%.31s after %s); "
                                "expected non-decreasing x", f[0].text, prev_x);
    if (r->n == r->cap && rows_grow(r) != TIRENV_OK)
        return tirenv_error(rd->diag, TIRENV_ENOMEM, rd->file, rd->line, "", "out of memory");
    r->x[r->n] = v[0];
    r->z[r->n] = v[1];
    r->n++;
    const size_t len = strnlen(f[0].text, 31);  /* snprintf(prev_x, 32, "%s"), faster */
    memcpy(prev_x, f[0].text, len);
    prev_x[len] = '\0';
    return TIRENV_OK;
}

/* The rows of an open reader (closed here), named rd->file in messages. */
static int read_rows(tirenv_csv__reader *rd, rows *r, tirenv_diag *diag)
{
    const char *path = rd->file;
    int status = TIRENV_OK;
    int got = tirenv_csv__next(rd);
    if (got == 0)
        status = tirenv_error(diag, TIRENV_EPARSE, path, 0, "",
                              "no header line (only blank or comment lines); expected the "
                              "header 'x_m,z_m', then data rows");
    else if (got < 0)
        status = -got;  /* a line that cannot be read (a NUL byte): never skipped */
    else
        status = tirenv_csv__header(rd, names, FIELDS);
    char prev_x[32] = "";
    while (status == TIRENV_OK && (got = tirenv_csv__next(rd)) > 0)
        status = read_row(rd, r, prev_x);
    if (status == TIRENV_OK && got < 0)
        status = -got;
    if (status == TIRENV_OK && r->n == 0)
        status = tirenv_error(diag, TIRENV_EPARSE, path, 0, "",
                              "no data rows after the header; expected at least one 'x,z' "
                              "row");
    tirenv_csv__close(rd);
    return status;
}

/* The file line of data row k (1-based), read again from the stream again() opens (NULL:
 * no line): only an error needs it, and a table of every row's line would cost more memory
 * than the vertices (8 MB a million rows). */
static size_t line_of_row(FILE *fp, size_t k)
{
    if (!fp)
        return 0;
    tirenv_csv__reader rd;
    tirenv_csv__open_stream(&rd, fp, "", NULL);
    size_t line = 0;
    for (size_t row = 0; row <= k && tirenv_csv__next(&rd) > 0; ++row)  /* row 0: header */
        line = rd.line;
    tirenv_csv__close(&rd);
    return line;
}

/* After the rows parse, tirenv_profile_validate has the last word (e.g. three vertices at
 * one x); its vertex index is turned back into the file line. tirenv_profile_alloc
 * validates too: it is asked first, and only a refusal runs the check that says why. */
static int read_csv(tirenv_csv__reader *rd, FILE *(*again)(void *ctx), void *ctx,
                    tirenv_profile **out, tirenv_diag *diag)
{
    const char *path = rd->file;
    rows r = {0};
    int status = read_rows(rd, &r, diag);
    if (status == TIRENV_OK && !(*out = tirenv_profile_alloc(r.n, r.x, r.z))) {
        tirenv_diag d;
        tirenv_diag_clear(&d);
        if (tirenv_profile_validate(r.n, r.x, r.z, &d) != TIRENV_OK) {
            const size_t line = d.line >= 1 && d.line <= r.n ? line_of_row(again(ctx), d.line)
                                                             : 0;
            const char *field = strcmp(d.field, "x") == 0   ? "x_m"
                                : strcmp(d.field, "z") == 0 ? "z_m"
                                                            : d.field;
            status = tirenv_error(diag, TIRENV_EPARSE, path, line, field, "%s", d.message);
        } else {
            status = tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
        }
    }
    free(r.x);
    free(r.z);
    return status;
}

static FILE *open_path(void *path) { return fopen(path, "r"); }

int tirenv_profile_read_csv(const char *path, tirenv_profile **out, tirenv_diag *diag)
{
    *out = NULL;
    tirenv_csv__reader rd;
    const int status = tirenv_csv__open(&rd, path, diag);
    return status ? status : read_csv(&rd, open_path, (void *)path, out, diag);
}

int tirenv_profile_csv__read(FILE *fp, const char *name, FILE *(*again)(void *ctx), void *ctx,
                             tirenv_profile **out, tirenv_diag *diag)
{
    *out = NULL;
    tirenv_csv__reader rd;
    tirenv_csv__open_stream(&rd, fp, name, diag);
    return read_csv(&rd, again, ctx, out, diag);
}
