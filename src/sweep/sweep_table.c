/* A sweep's tables (cases.csv, sweep.csv) as a merge and a finished run check them: split into
 * the lines that open them and their rows, and each row the case it must be, so that a table
 * cut at a line end, whole rows short, is not taken for a smaller sweep (docs/formats.md
 * section 13).
 * SPDX-License-Identifier: Apache-2.0 */
#include "dataset/dataset.h"
#include "sweep/sweep_impl.h"

#include <stdlib.h>
#include <string.h>

int tirenv_sweep__split_table(char *text, size_t len, const char *path, size_t *head,
                              char ***rows, size_t *n_rows, tirenv_diag *diag)
{
    const size_t lines = tirenv_sweep__lines(text, len);
    *rows = malloc((lines + 1) * sizeof **rows);
    if (!*rows)
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    *n_rows = 0;
    *head = 0;
    int have_header = 0;
    for (char *p = text; p < text + len;) {
        char *eol = memchr(p, '\n', (size_t)(text + len - p));
        if (!eol)
            return tirenv_error(diag, TIRENV_EPARSE, path, lines + 1, "",
                                "the last line has no newline: not a file a sweep wrote");
        if (!have_header || (*n_rows == 0 && p[0] == '#')) {
            have_header = have_header || p[0] != '#';
            *head = (size_t)(eol + 1 - text);
        } else {
            *eol = '\0';
            (*rows)[(*n_rows)++] = p;
        }
        p = eol + 1;
    }
    if (!have_header)
        return tirenv_error(diag, TIRENV_EPARSE, path, 0, "", "no header line");
    return TIRENV_OK;
}

int tirenv_sweep__check_rows(const char *dir, const char *table, size_t head_lines,
                             char **rows, size_t n_rows, size_t m, size_t shard, size_t shards,
                             tirenv_diag *diag)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", dir, table);
    const size_t want = tirenv_dataset__shard_rows(m, shard, shards);
    char part[96];
    if (shards > 1)
        snprintf(part, sizeof part, "shard %zu/%zu of the sweep's %zu cases has %zu", shard,
                 shards, m, want);
    else
        snprintf(part, sizeof part, "the sweep has %zu cases", m);
    if (n_rows != want) {
        /* After the last row when rows are missing, else at the first row too many. */
        const size_t line = head_lines + (n_rows < want ? n_rows : want) + 1;
        return tirenv_error(diag, TIRENV_EPARSE, path, line, "",
                            "%zu rows, but %s; expected one row each (%s)", n_rows, part,
                            n_rows < want ? "a table cut short" : "rows added");
    }
    for (size_t j = 0; j < n_rows; ++j) {
        char name[32];
        tirenv_sweep__name_of(m, shard + j * shards, name);
        const size_t len = strlen(name);
        if (strncmp(rows[j], name, len) != 0 || rows[j][len] != ',')
            return tirenv_error(diag, TIRENV_EPARSE, path, head_lines + j + 1, "case",
                                "row %zu should be case %s", j + 1, name);
    }
    return TIRENV_OK;
}

int tirenv_sweep__row_files(const char *row, const char **log, size_t *log_len,
                            const char **curve, size_t *curve_len)
{
    const char *f = row;
    for (int k = 0; k < 6; ++k) {
        f = strchr(f, ',');
        if (!f)
            return -1;
        ++f;
    }
    const char *comma = strchr(f, ',');
    if (!comma || strchr(comma + 1, ','))
        return -1;
    *log = f;
    *log_len = (size_t)(comma - f);
    *curve = comma + 1;
    *curve_len = strlen(comma + 1);
    /* Only files inside the part: a sweep writes logs/<case>.csv and curves/<case>.csv. */
    if (*log_len && (*log_len <= 5 || strncmp(*log, "logs/", 5) != 0 ||
                     memchr(*log + 5, '/', *log_len - 5)))
        return -1;
    if (*curve_len <= 7 || strncmp(*curve, "curves/", 7) != 0 || strchr(*curve + 7, '/') ||
        strstr(row, ".."))
        return -1;
    return 0;
}

size_t tirenv_sweep__lines(const char *text, size_t len)
{
    size_t n = 0;
    for (size_t k = 0; k < len; ++k)
        n += text[k] == '\n';
    return n;
}
