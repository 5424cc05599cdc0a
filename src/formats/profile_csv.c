/* Measured ground profiles as CSV read whole: header "x_m,z_m", one polyline vertex per line
 * (docs/models.md section 2), the rows of the one CSV parser (profile_stream.c) gathered.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/profile_csv.h"

#include <stdio.h>
#include <stdlib.h>

#include "formats/profile_csv_impl.h"
#include "io/io.h"

/* The rows of an open reader (freed here) gathered into *out: the reader has checked every row
 * as tirenv_profile_validate would (finite numbers, x non-decreasing, at most two vertices at
 * one x), so that tirenv_profile_alloc can refuse only for want of memory. */
static int read_csv(tirenv_profile_csv__reader *rd, const char *path, tirenv_profile **out,
                    tirenv_diag *diag)
{
    double *x = NULL, *z = NULL;  /* the vertices, m */
    size_t n = 0, cap = 0;
    int status = tirenv_profile_csv__reader_rest(rd, &x, &z, &n, &cap, diag);
    if (status == TIRENV_OK)
        status = tirenv_profile_make(n, x, z, path, out, diag);
    tirenv_profile_csv__reader_free(rd);
    free(x);
    free(z);
    return status;
}

int tirenv_profile_read_csv(const char *path, tirenv_profile **out, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
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
