/* Profile CSV import: a measured or hand-made ground profile as "x_m,z_m" rows.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "tirenv/io.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>

static const char *const csv_names[2] = {"x_m", "z_m"};

/* The vertices read so far, and the file line of each for errors found after reading. */
typedef struct {
    double *x, *z; /* m */
    size_t *line;
    size_t n, cap;
} csv_rows;

/* One line being parsed. */
typedef struct {
    const char *file;
    size_t line;      /* 1-based */
    const char *base; /* start of the line: columns count from here */
    tirenv_diag *diag;
} csv_ctx;

/* One field of a line, with surrounding blanks removed (in place). */
typedef struct {
    char *text;
    size_t column; /* 1-based position of text in the line */
} csv_field;

#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
static int csv_fail(const csv_ctx *c, size_t column, const char *field, const char *fmt, ...)
{
    char msg[sizeof ((tirenv_diag *)NULL)->message];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    const int status = tirenv_error(c->diag, TIRENV_EPARSE, c->file, c->line, field, "%s", msg);
    if (c->diag)
        c->diag->column = column;
    return status;
}

/* Splits line at commas into at most max fields and returns how many there are (which may be
 * more than max: the extra ones are counted, and the first of them stored in f[max]). */
static size_t csv_split(const csv_ctx *c, char *line, csv_field f[], size_t max)
{
    size_t count = 0;
    char *p = line;
    for (;;) {
        char *comma = strchr(p, ',');
        if (comma)
            *comma = '\0';
        if (count <= max) {
            while (isspace((unsigned char)*p))
                p++;
            size_t n = strlen(p);
            while (n > 0 && isspace((unsigned char)p[n - 1]))
                p[--n] = '\0';
            f[count].text = p;
            f[count].column = (size_t)(p - c->base) + 1;
        }
        count++;
        if (!comma)
            return count;
        p = comma + 1;
    }
}

static int csv_header(const csv_ctx *c, char *line)
{
    csv_field f[3];
    const size_t count = csv_split(c, line, f, 2);
    if (count != 2)
        return csv_fail(c, f[0].column, "", "expected the header 'x_m,z_m', got %zu field%s",
                        count, count == 1 ? "" : "s");
    for (size_t k = 0; k < 2; k++)
        if (strcmp(f[k].text, csv_names[k]) != 0)
            return csv_fail(c, f[k].column, csv_names[k], "expected the header 'x_m,z_m', "
                            "got '%.60s' for column %zu", f[k].text, k + 1);
    return TIRENV_OK;
}

static int csv_number(const csv_ctx *c, const csv_field *f, const char *name, double *out)
{
    char *end;
    const double v = strtod(f->text, &end);
    if (end == f->text || *end)
        return csv_fail(c, f->column, name, "expected a number, got '%.60s'", f->text);
    if (!isfinite(v))
        return csv_fail(c, f->column, name, "expected a finite number, got '%.60s'", f->text);
    *out = v;
    return TIRENV_OK;
}

static int csv_grow(csv_rows *r)
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
    size_t *line = realloc(r->line, cap * sizeof *line);
    if (!line)
        return TIRENV_ENOMEM;
    r->line = line;
    r->cap = cap;
    return TIRENV_OK;
}

/* prev_x is the previous row's x as written, so "decreases" quotes the user's own text. */
static int csv_row(const csv_ctx *c, char *line, csv_rows *r, char prev_x[32])
{
    csv_field f[3];
    const size_t count = csv_split(c, line, f, 2);
    if (count != 2)
        return csv_fail(c, count > 2 ? f[2].column : strlen(c->base) + 1,
                        count > 2 ? "" : "z_m", "expected 2 fields, got %zu", count);
    double v[2];
    for (size_t k = 0; k < 2; k++) {
        const int status = csv_number(c, &f[k], csv_names[k], &v[k]);
        if (status != TIRENV_OK)
            return status;
    }
    if (r->n > 0 && v[0] < r->x[r->n - 1])
        return csv_fail(c, f[0].column, "x_m", "x_m decreases (%.31s after %s); expected "
                        "non-decreasing x", f[0].text, prev_x);
    if (r->n == r->cap && csv_grow(r) != TIRENV_OK)
        return tirenv_error(c->diag, TIRENV_ENOMEM, c->file, c->line, "", "out of memory");
    r->x[r->n] = v[0];
    r->z[r->n] = v[1];
    r->line[r->n] = c->line;
    r->n++;
    snprintf(prev_x, 32, "%s", f[0].text);
    return TIRENV_OK;
}

/* Reads every line; *has_header tells an empty file apart from one with no data rows. */
static int csv_read_rows(FILE *fp, const char *path, csv_rows *r, int *has_header,
                         tirenv_diag *diag)
{
    csv_ctx c = {path, 0, NULL, diag};
    char prev_x[32] = "";
    char *buf = NULL;
    size_t cap = 0;
    ssize_t len;
    int status = TIRENV_OK;
    while (status == TIRENV_OK && (len = getline(&buf, &cap, fp)) != -1) {
        c.line++;
        char *line = buf;
        if (c.line == 1 && strncmp(line, "\xEF\xBB\xBF", 3) == 0)
            line += 3; /* the UTF-8 byte-order mark spreadsheet programs write */
        size_t n = strlen(line);
        while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == '\r'))
            line[--n] = '\0';
        c.base = line;
        const char *p = line;
        while (isspace((unsigned char)*p))
            p++;
        if (*p == '\0' || *p == '#')
            continue;
        if (*has_header) {
            status = csv_row(&c, line, r, prev_x);
        } else {
            status = csv_header(&c, line);
            *has_header = 1;
        }
    }
    if (status == TIRENV_OK && ferror(fp))
        status = tirenv_error(diag, TIRENV_EIO, path, c.line + 1, "", "cannot read: %s",
                              strerror(errno));
    free(buf);
    return status;
}

/* After the rows parse, tirenv_profile_validate has the last word (e.g. three vertices at
 * one x); its vertex index is turned back into the file line. */
int tirenv_profile_read_csv(const char *path, tirenv_profile **out, tirenv_diag *diag)
{
    *out = NULL;
    FILE *fp = fopen(path, "r");
    if (!fp)
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot open: %s", strerror(errno));
    csv_rows r = {NULL, NULL, NULL, 0, 0};
    int has_header = 0;
    int status = csv_read_rows(fp, path, &r, &has_header, diag);
    fclose(fp);
    if (status == TIRENV_OK && !has_header)
        status = tirenv_error(diag, TIRENV_EPARSE, path, 0, "",
                              "no header line (only blank or comment lines); expected "
                              "the header 'x_m,z_m', then data rows");
    else if (status == TIRENV_OK && r.n == 0)
        status = tirenv_error(diag, TIRENV_EPARSE, path, 0, "",
                              "no data rows after the header; expected at least one 'x,z' "
                              "row");
    if (status == TIRENV_OK) {
        tirenv_diag d;
        tirenv_diag_clear(&d);
        if (tirenv_profile_validate(r.n, r.x, r.z, &d) != TIRENV_OK) {
            const size_t line = d.line >= 1 && d.line <= r.n ? r.line[d.line - 1] : 0;
            const char *field = strcmp(d.field, "x") == 0   ? "x_m"
                                : strcmp(d.field, "z") == 0 ? "z_m"
                                                            : d.field;
            status = tirenv_error(diag, TIRENV_EPARSE, path, line, field, "%s", d.message);
        }
    }
    if (status == TIRENV_OK) {
        *out = tirenv_profile_alloc(r.n, r.x, r.z);
        if (!*out)
            status = tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    }
    free(r.x);
    free(r.z);
    free(r.line);
    return status;
}
