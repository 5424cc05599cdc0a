/* Raw rig logs: CSV "t_s,x_m,z_m", one sample of the tire centre per line (docs/formats.md
 * section 7; docs/models.md section 5.7; the paper's Figure 2). Order, rate and repeats are
 * the importer's business; this file only reads, and remembers each sample's line for
 * messages.
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdint.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "io/io.h"
#include "rig/rig_impl.h"

enum { LOG_FIELDS = 3 };
static const char *const log_names[LOG_FIELDS] = {"t_s", "x_m", "z_m"};

void tirenv_rig__log_file_free(tirenv_rig__log_file *log)
{
    if (!log)
        return;
    free(log->t);
    free(log->x);
    free(log->z);
    free(log->line);
    *log = (tirenv_rig__log_file){0};
}

/* Each array keeps its old block if a later realloc fails, so the log stays consistent. */
static int log_grow(tirenv_rig__log_file *log, size_t *cap, size_t want)
{
    if (want > SIZE_MAX / sizeof(double))
        return TIRENV_ENOMEM;
    double **arrays[LOG_FIELDS] = {&log->t, &log->x, &log->z};
    for (size_t k = 0; k < LOG_FIELDS; k++) {
        double *p = realloc(*arrays[k], want * sizeof *p);
        if (!p)
            return TIRENV_ENOMEM;
        *arrays[k] = p;
    }
    size_t *line = realloc(log->line, want * sizeof *line);
    if (!line)
        return TIRENV_ENOMEM;
    log->line = line;
    *cap = want;
    return TIRENV_OK;
}

/* The largest reading taken, in s or m, is a road's coordinates' bound: a reading beyond it is
 * a typo or a unit slip, and one sample of it (1e308) passed as a time far after the others,
 * or overflowed the importer's filter into a curve point refused naming the output file, or
 * made a passage error at another line and field. */
static const double reading_max = TIRENV_PROFILE_MAX_COORDINATE;

static int log_parse_row(tirenv_csv__reader *r, tirenv_rig__log_file *log, size_t *cap)
{
    tirenv_csv__field f[LOG_FIELDS + 1];
    int status = tirenv_csv__fields(r, log_names, LOG_FIELDS, f);
    double v[LOG_FIELDS];
    for (size_t k = 0; k < LOG_FIELDS && status == TIRENV_OK; k++)
        status = tirenv_csv__number_within(r, &f[k], log_names[k], reading_max,
                                           "a rig's reading (t in s, x and z in m)", &v[k]);
    if (status != TIRENV_OK)
        return status;
    if (log->n == *cap && log_grow(log, cap, 2 * *cap) != TIRENV_OK)
        return tirenv_error(r->diag, TIRENV_ENOMEM, r->file, r->line, "", "out of memory");
    const size_t i = log->n++;
    log->t[i] = v[0];
    log->x[i] = v[1];
    log->z[i] = v[2];
    log->line[i] = r->line;
    return TIRENV_OK;
}

/* Room for the samples a file of this size probably holds, so that a long log is not copied
 * from block to block as it grows: a row like "12.345,1.234567,0.654321" has 25 bytes. */
enum { TYPICAL_ROW_BYTES = 24, MIN_ROWS = 256 };

static size_t log_expected_rows(FILE *fp)
{
    struct stat st;
    if (fstat(fileno(fp), &st) != 0 || st.st_size <= 0)
        return MIN_ROWS;
    return (size_t)st.st_size / TYPICAL_ROW_BYTES + MIN_ROWS;
}

static int log_parse_lines(tirenv_csv__reader *r, tirenv_rig__log_file *log)
{
    size_t cap = 0;
    if (log_grow(log, &cap, log_expected_rows(r->fp)) != TIRENV_OK)
        return tirenv_error(r->diag, TIRENV_ENOMEM, r->file, 0, "", "out of memory");
    int more = tirenv_csv__next(r);
    if (more == 0) {
        const int status = tirenv_error(r->diag, TIRENV_EPARSE, r->file, 1, "",
                                        "no header: the file is empty or holds only blank and "
                                        "comment lines; expected the header 't_s,x_m,z_m', "
                                        "then one sample per line");
        if (r->diag)
            r->diag->column = 1;
        return status;
    }
    int status = more < 0 ? -more : tirenv_csv__header(r, log_names, LOG_FIELDS);
    while (status == TIRENV_OK && (more = tirenv_csv__next(r)) > 0)
        status = log_parse_row(r, log, &cap);
    if (status == TIRENV_OK && more < 0)
        status = -more;
    if (status == TIRENV_OK && log->n == 0) {
        status = tirenv_error(r->diag, TIRENV_EPARSE, r->file, r->line + 1, "",
                              "no samples after the header; expected 't,x,z' rows");
        if (r->diag)
            r->diag->column = 1;
    }
    return status;
}

int tirenv_rig__log_read(const char *path, tirenv_rig__log_file *log, tirenv_diag *diag)
{
    *log = (tirenv_rig__log_file){0};
    tirenv_csv__reader r;
    int status = tirenv_csv__open(&r, path, diag);
    if (status == TIRENV_OK)
        status = log_parse_lines(&r, log);
    tirenv_csv__close(&r);
    if (status != TIRENV_OK)
        tirenv_rig__log_file_free(log);
    return status;
}

/* Columns are not stored for every sample (three numbers per sample, needed only when one is
 * at fault): the line is read again and split. 0 if it cannot be. */
size_t tirenv_rig__log_column(const char *path, size_t line, size_t field)
{
    if (field >= LOG_FIELDS)
        return 0;
    tirenv_csv__reader r;
    size_t column = 0;
    if (tirenv_csv__open(&r, path, NULL) == TIRENV_OK) {
        while (tirenv_csv__next(&r) > 0 && r.line < line)
            ;
        tirenv_csv__field f[LOG_FIELDS + 1];
        if (r.line == line && tirenv_csv__split(&r, f, LOG_FIELDS) > field)
            column = f[field].column;
    }
    tirenv_csv__close(&r);
    return column;
}
