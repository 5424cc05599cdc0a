/* Profile CSV read one vertex at a time, the vertex source of tirenv_model_stream: the format
 * and the checks of profile_csv.c, with the whole-profile check of tirenv_profile_validate (x
 * non-decreasing, at most two vertices at one x) done row by row so that it needs no memory
 * of the past rows.
 * SPDX-License-Identifier: Apache-2.0 */
#include "formats/profile_csv_impl.h"

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

int tirenv_profile_csv__reader_next(tirenv_profile_csv__reader *r, double *x, double *z,
                                    int *got,
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
    if (r->rows > 0 && v[0] < r->x_prev)
        return tirenv_csv__fail(&r->rd, f[0].column, "x_m", "x_m decreases (%.31s after %s); "
                                "expected non-decreasing x", f[0].text, r->prev_x);
    r->same_x = r->rows > 0 && v[0] == r->x_prev ? r->same_x + 1 : 1;
    if (r->same_x > 2)
        return tirenv_csv__fail(&r->rd, f[0].column, "x_m", "a third vertex at x_m = %.31s; "
                                "expected at most two (a wall)", f[0].text);
    r->x_prev = v[0];
    snprintf(r->prev_x, sizeof r->prev_x, "%s", f[0].text);
    r->rows++;
    *x = v[0];
    *z = v[1];
    *got = 1;
    return TIRENV_OK;
}
