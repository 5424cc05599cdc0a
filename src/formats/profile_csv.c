/* Measured ground profiles as CSV read whole: header "x_m,z_m", one polyline vertex per line
 * (docs/models.md section 2), the rows of the one CSV parser (profile_stream.c) gathered.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/profile_csv.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "formats/profile_csv_impl.h"
#include "io/io.h"

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

/* The vertices of an open reader (freed here), gathered into *out: the reader has checked
 * every row as tirenv_profile_validate would (finite numbers, x non-decreasing, at most two
 * vertices at one x), so that tirenv_profile_alloc can refuse only for want of memory. */
static int read_csv(tirenv_profile_csv__reader *rd, const char *path, tirenv_profile **out,
                    tirenv_diag *diag)
{
    rows r = {0};
    int status = TIRENV_OK, got = 1;
    for (;;) {
        double x, z;
        if ((status = tirenv_profile_csv__reader_next(rd, &x, &z, &got, diag)) || !got)
            break;
        if (r.n == r.cap && rows_grow(&r) != TIRENV_OK) {
            status = tirenv_error(diag, TIRENV_ENOMEM, path, tirenv_profile_csv__reader_line(rd),
                                  "", "out of memory");
            break;
        }
        r.x[r.n] = x;
        r.z[r.n] = z;
        r.n++;
    }
    if (status == TIRENV_OK && !(*out = tirenv_profile_alloc(r.n, r.x, r.z)))
        status = tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    tirenv_profile_csv__reader_free(rd);
    free(r.x);
    free(r.z);
    return status;
}

int tirenv_profile_read_csv(const char *path, tirenv_profile **out, tirenv_diag *diag)
{
    *out = NULL;
    tirenv_csv__reader rd; /* for its open's checks and messages */
    const int status = tirenv_csv__open(&rd, path, diag);
    if (status)
        return status;
    FILE *fp = rd.fp;
    rd.fp = NULL;
    tirenv_csv__close(&rd);
    return tirenv_profile_csv__read(fp, path, out, diag);
}

int tirenv_profile_csv__read(FILE *fp, const char *name, tirenv_profile **out,
                             tirenv_diag *diag)
{
    *out = NULL;
    tirenv_profile_csv__reader *rd;
    const int status = tirenv_profile_csv__reader_open(fp, name, &rd, diag);
    return status ? status : read_csv(rd, name, out, diag);
}
