/* What a sweep's sweep.txt declares of the manifest beside it (docs/formats.md section 13):
 * the grid's `cases = M` and, in a shard, `shard = K/N`, so that a data set written by tirenv
 * sweep, whose directory has no source.txt, still refuses a manifest cut at a line end; and
 * what simulated it (its model, and whether it set tire keys), its source.
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dataset/dataset.h"
#include "dataset/dataset_impl.h"
#include "io/io.h"

/* A whole number of digits alone at s, up to max, into *v; the characters read, 0 if none or
 * too large. */
static size_t digits(const char *s, unsigned long max, unsigned long *v)
{
    const size_t n = strspn(s, "0123456789");
    if (n == 0 || n > 7)
        return 0;
    *v = strtoul(s, NULL, 10);
    return *v <= max ? n : 0;
}

/* "key = " at the start of the line: the value after it, else NULL. */
static const char *value_of(const char *line, const char *key)
{
    const size_t n = strlen(key);
    return strncmp(line, key, n) == 0 && strncmp(line + n, " = ", 3) == 0 ? line + n + 3
                                                                           : NULL;
}

/* The keys tirenv sweep writes (docs/formats.md section 13), besides "set KEY" per swept key. */
static const char *const sweep_keys[] = {"format", "model", "curves", "network", "lengths_m",
    "heights_m", "contact_lengths_m", "loads_N", "split", "control_fraction",
    "validation_fraction", "split_seed", "rig_seed", "cases", "shard"};
enum { N_SWEEP_KEYS = sizeof sweep_keys / sizeof sweep_keys[0] };

static int known_key(const char *key, size_t n)
{
    if (n > 4 && strncmp(key, "set ", 4) == 0 && !memchr(key + 4, ' ', n - 4))
        return 1;
    for (size_t k = 0; k < N_SWEEP_KEYS; ++k)
        if (strlen(sweep_keys[k]) == n && strncmp(key, sweep_keys[k], n) == 0)
            return 1;
    return 0;
}

/* A line that is no "key = value" of a known key is refused: read past, a misspelt "model"
 * or "set KEY" would make a sweep's cases measurements, or one tire's, without a word. */
static int check_line(const tirenv_csv__reader *r)
{
    const char *eq = strstr(r->text, " = ");
    if (!eq)
        return tirenv_csv__fail(r, 1, "", "expected 'key = value', got '%.60s'", r->text);
    const size_t n = (size_t)(eq - r->text);
    if (known_key(r->text, n))
        return TIRENV_OK;
    char key[64], expected[300];
    snprintf(key, sizeof key, "%.*s", n < sizeof key ? (int)n : (int)sizeof key - 1, r->text);
    tirenv_csv__join(sweep_keys, N_SWEEP_KEYS, expected, sizeof expected);
    return tirenv_csv__fail(r, 1, key, "unknown key; expected one of %s, or set KEY", expected);
}

int tirenv_dataset__sweep_declared(const char *dir, tirenv_dataset__declared *out,
                                   tirenv_diag *diag)
{
    memset(out, 0, sizeof *out);
    char path[1100];
    const int w = snprintf(path, sizeof path, "%s/sweep.txt", dir);
    if (w < 0 || (size_t)w >= sizeof path)
        return TIRENV_OK;  /* no such file can be there: tirenv_dataset_read names the dir */
    const int piped = tirenv_dataset__refuse_pipe(path, diag);
    if (piped)
        return piped;
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return TIRENV_OK;  /* not a sweep */
    tirenv_csv__reader r;
    tirenv_csv__open_stream(&r, fp, path, diag);
    unsigned long cases = 0, k = 0, n = 1;
    size_t cases_line = 0;
    int status = TIRENV_OK, more;
    while (!status && (more = tirenv_csv__next(&r)) > 0) {
        const char *v;
        if ((status = check_line(&r)))
            break;
        if ((v = value_of(r.text, "cases"))) {
            const size_t used = digits(v, TIRENV_DATASET__MAX_CASES, &cases);
            cases_line = r.line;
            if (!used || v[used] || cases == 0)
                status = tirenv_csv__fail(&r, (size_t)(v - r.text) + 1, "cases",
                                          "expected the sweep's number of cases, a whole "
                                          "number from 1 to %u, got '%.60s'",
                                          TIRENV_DATASET__MAX_CASES, v);
        } else if ((v = value_of(r.text, "curves"))) {
            out->raw = strcmp(v, "model") == 0;
        } else if ((v = value_of(r.text, "model"))) {
            snprintf(out->model, sizeof out->model, "%s", v);
        } else if (strncmp(r.text, "set ", 4) == 0 && !out->key_line &&
                   strcspn(r.text + 4, " =") > 0) {
            const size_t len = strcspn(r.text + 4, " =");
            snprintf(out->key, sizeof out->key, "%.*s", (int)len, r.text + 4);
            out->key_line = r.line;
        } else if ((v = value_of(r.text, "shard"))) {
            const size_t a = digits(v, TIRENV_DATASET__MAX_CASES, &k);
            const size_t b = a && v[a] == '/' ? digits(v + a + 1, TIRENV_DATASET__MAX_CASES, &n)
                                              : 0;
            if (!b || v[a + 1 + b] || k >= n)
                status = tirenv_csv__fail(&r, (size_t)(v - r.text) + 1, "shard",
                                          "expected 'K/N' with 0 <= K < N, got '%.60s'", v);
        }
    }
    if (!status && more < 0)
        status = -more;
    tirenv_csv__close(&r);
    if (status || !cases_line)
        return status;  /* a sweep.txt without the count (none of tirenv's): nothing said */
    out->cases = tirenv_dataset__shard_rows(cases, k, n);
    if (!out->cases)
        return TIRENV_OK;  /* a shard beyond the grid: no rows, which the manifest refuses */
    out->line = cases_line;
    snprintf(out->file, sizeof out->file, "%s", path);
    if (n > 1)
        snprintf(out->what, sizeof out->what, "cases = %lu of shard %lu/%lu (%zu rows)", cases,
                 k, n, out->cases);
    else
        snprintf(out->what, sizeof out->what, "cases = %lu", cases);
    return TIRENV_OK;
}
