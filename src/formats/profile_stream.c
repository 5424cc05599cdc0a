/* The one parser of profile CSV ("x_m,z_m", docs/formats.md section 4): a vertex at a time,
 * the vertex source of tirenv_model_stream and what tirenv_profile_read_csv (profile_csv.c)
 * gathers into a whole profile. The whole-profile check of tirenv_profile_validate (x
 * non-decreasing, at most two vertices at one x) is done row by row, so that it needs no
 * memory of the past rows.
 * SPDX-License-Identifier: Apache-2.0 */
#include "formats/profile_csv_impl.h"

#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io.h"

enum { FIELDS = 2 };
static const char *const names[FIELDS] = {"x_m", "z_m"};

struct tirenv_profile_csv__reader {
    tirenv_csv__reader rd;
    char *path;            /* copy: the diag of later calls names it */
    size_t rows;           /* vertices returned so far */
    double x_prev;         /* previous vertex x, m */
    size_t same_x;         /* vertices so far at x_prev */
    char prev_x[32];       /* previous x as written, for messages */
    int done;
};

void tirenv_profile_csv__reader_free(tirenv_profile_csv__reader *r)
{
    if (!r)
        return;
    tirenv_csv__close(&r->rd);
    free(r->path);
    free(r);
}

int tirenv_profile_csv__reader_open(FILE *fp, const char *name,
                                    tirenv_profile_csv__reader **out, tirenv_diag *diag)
{
    *out = NULL;
    tirenv_profile_csv__reader *r = calloc(1, sizeof *r);
    const size_t len = strlen(name) + 1;
    if (!r || !(r->path = malloc(len))) {
        free(r);
        fclose(fp);
        return tirenv_error(diag, TIRENV_ENOMEM, name, 0, "", "out of memory");
    }
    memcpy(r->path, name, len);
    tirenv_csv__open_stream(&r->rd, fp, r->path, diag);
    int status;
    const int got = tirenv_csv__next(&r->rd);
    if (got == 0)
        status = tirenv_error(diag, TIRENV_EPARSE, name, 0, "",
                              "no header line (only blank or comment lines); expected the "
                              "header 'x_m,z_m', then data rows");
    else if (got < 0)
        status = -got;
    else
        status = tirenv_csv__header(&r->rd, names, FIELDS);
    if (status) {
        tirenv_profile_csv__reader_free(r);
        return status;
    }
    *out = r;
    return TIRENV_OK;
}

/* The next row (tirenv_profile_csv__reader_next), inlined into the loop of
 * tirenv_profile_csv__reader_rest. */
static inline int next_row(tirenv_profile_csv__reader *r, double *x, double *z, int *got,
                           tirenv_diag *diag)
{
    *got = 0;
    if (r->done)
        return TIRENV_OK;
    r->rd.diag = diag;
    const int line = tirenv_csv__next(&r->rd);
    if (line < 0)
        return -line;
    if (line == 0) {
        r->done = 1;
        if (r->rows == 0)
            return tirenv_error(diag, TIRENV_EPARSE, r->path, 0, "",
                                "no data rows after the header; expected at least one 'x,z' "
                                "row");
        return TIRENV_OK;
    }
    tirenv_csv__field f[FIELDS + 1];
    int status = tirenv_csv__fields(&r->rd, names, FIELDS, f);
    double v[FIELDS];
    for (size_t k = 0; k < FIELDS && status == TIRENV_OK; k++)
        status = tirenv_csv__number(&r->rd, &f[k], names[k], &v[k]);
    if (status)
        return status;
    for (size_t k = 0; k < FIELDS; k++)
        if (!(fabs(v[k]) <= TIRENV_PROFILE_MAX_COORDINATE))
            return tirenv_csv__fail(&r->rd, f[k].column, names[k], "%s = %.31s is beyond "
                                    "+-%g m; expected a road's coordinates (in m?)", names[k],
                                    f[k].text, TIRENV_PROFILE_MAX_COORDINATE);
    if (r->rows > 0 && v[0] - r->x_prev > TIRENV_PROFILE_MAX_SEGMENT)
        return tirenv_csv__fail(&r->rd, f[0].column, "x_m", "x_m = %.31s is %g m after the "
                                "previous vertex (%s); expected at most %g m (flat ground "
                                "continues by itself before the first vertex and after the "
                                "last)", f[0].text, v[0] - r->x_prev, r->prev_x,
                                TIRENV_PROFILE_MAX_SEGMENT);
    if (r->rows > 0 && v[0] < r->x_prev)
        return tirenv_csv__fail(&r->rd, f[0].column, "x_m", "x_m decreases (%.31s after %s); "
                                "expected non-decreasing x", f[0].text, r->prev_x);
    r->same_x = r->rows > 0 && v[0] == r->x_prev ? r->same_x + 1 : 1;
    if (r->same_x > 2)
        return tirenv_csv__fail(&r->rd, f[0].column, "x_m", "a third vertex at x_m = %.31s; "
                                "expected at most two (a wall)", f[0].text);
    r->x_prev = v[0];
    const size_t len = strnlen(f[0].text, sizeof r->prev_x - 1);  /* snprintf's bytes, faster */
    memcpy(r->prev_x, f[0].text, len);
    r->prev_x[len] = '\0';
    r->rows++;
    *x = v[0];
    *z = v[1];
    *got = 1;
    return TIRENV_OK;
}

int tirenv_profile_csv__reader_next(tirenv_profile_csv__reader *r, double *x, double *z,
                                    int *got, tirenv_diag *diag)
{
    return next_row(r, x, z, got, diag);
}

/* Doubles the room of x[] and z[]; each keeps its old block if a later realloc fails. */
static int rows_grow(double **x, double **z, size_t *cap)
{
    const size_t c = *cap ? 2 * *cap : 64;
    if (c > SIZE_MAX / sizeof(double))
        return TIRENV_ENOMEM;
    double *a = realloc(*x, c * sizeof *a);
    if (!a)
        return TIRENV_ENOMEM;
    *x = a;
    double *b = realloc(*z, c * sizeof *b);
    if (!b)
        return TIRENV_ENOMEM;
    *z = b;
    *cap = c;
    return TIRENV_OK;
}

int tirenv_profile_csv__reader_rest(tirenv_profile_csv__reader *r, double **x, double **z,
                                    size_t *n, size_t *cap, tirenv_diag *diag)
{
    for (;;) {
        double xk, zk;
        int got;
        const int status = next_row(r, &xk, &zk, &got, diag);
        if (status || !got)
            return status;
        if (*n == *cap && rows_grow(x, z, cap) != TIRENV_OK)
            return tirenv_error(diag, TIRENV_ENOMEM, r->path, r->rd.line, "", "out of memory");
        (*x)[*n] = xk;
        (*z)[*n] = zk;
        ++*n;
    }
}

/* The x of the row in line[0, n) (its end-of-line characters included), if it is a whole
 * data row by the reader's rules: 1 with *x set, else 0. */
static int row_x(const char *line, size_t n, double *x)
{
    char *text = malloc(n + 1);
    if (!text)
        return 0;
    memcpy(text, line, n);
    while (n > 0 && (text[n - 1] == '\n' || text[n - 1] == '\r'))
        n--;
    text[n] = '\0';
    tirenv_csv__reader rd = {.file = "", .line = 0, .text = text, .length = n, .diag = NULL};
    tirenv_csv__field f[FIELDS + 1];
    double v[FIELDS];
    const int ok = tirenv_csv__fields(&rd, names, FIELDS, f) == TIRENV_OK &&
                   tirenv_csv__number(&rd, &f[0], names[0], &v[0]) == TIRENV_OK &&
                   tirenv_csv__number(&rd, &f[1], names[1], &v[1]) == TIRENV_OK;
    free(text);
    if (ok)
        *x = v[0];
    return ok;
}

/* The reader's lines, taken from the end: the last line with content (not blank, not a '#'
 * comment: tirenv_csv__next's rule) within the last TAIL bytes, which hold at least two
 * lines of the longest length the reader takes, and ended by a line end (one without is an
 * error tirenv_csv__next reports at its line). */
int tirenv_profile_csv__last_x(const tirenv_source *s, double *x)
{
    enum { TAIL = 2 * (TIRENV_TEXT__MAX_LINE + 2) };
    const size_t n = s->size < TAIL ? s->size : TAIL, offset = s->size - n;
    char *buf = malloc(n ? n : 1);
    if (!buf || tirenv_source__read(s, offset, buf, n, NULL) != TIRENV_OK) {
        free(buf);
        return 0;
    }
    int found = 0;
    size_t end = n;  /* the end of the line looked at, its '\n' excluded */
    if (end > 0 && buf[end - 1] == '\n')
        end--;
    for (;;) {
        size_t begin = end;
        while (begin > 0 && buf[begin - 1] != '\n')
            begin--;
        /* A line that may start before the window, or the file's first (the header, its
         * byte-order mark): not told from here. So is a NUL byte, an error at its line. */
        if (begin == 0 || memchr(buf + begin, '\0', end - begin))
            break;
        const char *p = buf + begin;
        while (p < buf + end && isspace((unsigned char)*p))
            p++;
        if (p < buf + end && *p != '#') {
            /* Not a last line without a line end (end == n): an error from the start. */
            found = end < n && row_x(buf + begin, end - begin, x);
            break;
        }
        end = begin - 1;
    }
    free(buf);
    return found;
}
