/* Merging the shards of a sweep (docs/formats.md section 13) into the data set the whole sweep
 * run as one part writes, byte for byte: the description without its shard line, the same
 * tire, the manifest and sweep.csv rows interleaved back into case order (shard K holds the
 * cases K, K + N, K + 2N, ...), and every case's files linked (or copied) as they are.
 * SPDX-License-Identifier: Apache-2.0 */
#include "sweep/sweep_impl.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "tirenv/outfile.h"
#include "io/io.h"

enum { SPEC_MAX = 1 << 20 };

/* One part: its description and tables, split into lines. */
typedef struct {
    const char *dir;
    char *spec, *tire, *cases, *keys;
    size_t spec_len, tire_len, cases_len, keys_len;
    size_t shard, shards;
    size_t rest_begin, rest_end;     /* the shard line within spec */
    char **case_rows, **key_rows;    /* data rows (NUL-terminated in place) */
    size_t n_case_rows, n_key_rows;
    size_t case_head, key_head;      /* bytes of comment and header lines before the rows */
} part;

static void part_free(part *p)
{
    free(p->spec);
    free(p->tire);
    free(p->cases);
    free(p->keys);
    free(p->case_rows);
    free(p->key_rows);
}

static int read_part(part *p, tirenv_diag *diag)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/sweep.txt", p->dir);
    int status = tirenv_sweep__read_text(path, SPEC_MAX, &p->spec, &p->spec_len, diag);
    if (status)
        return status;
    const int has = tirenv_sweep__spec_shard(p->spec, &p->shard, &p->shards, &p->rest_begin,
                                             &p->rest_end);
    if (has <= 0)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "shard",
                            has < 0 ? "malformed shard line; expected 'shard = K/N'"
                                    : "no shard line: %s is a whole sweep, not a shard of one",
                            p->dir);
    snprintf(path, sizeof path, "%s/cases.csv", p->dir);
    struct stat st;
    if (stat(path, &st) != 0)
        return tirenv_error(diag, TIRENV_EINVAL, p->dir, 0, "",
                            "shard %zu/%zu is not complete (no cases.csv): run it again to "
                            "finish it", p->shard, p->shards);
    if ((status = tirenv_sweep__read_text(path, TIRENV_SWEEP__TABLE_MAX, &p->cases,
                                          &p->cases_len, diag)) ||
        (status = tirenv_sweep__split_table(p->cases, p->cases_len, path, &p->case_head,
                                            &p->case_rows, &p->n_case_rows, diag)))
        return status;
    snprintf(path, sizeof path, "%s/sweep.csv", p->dir);
    if ((status = tirenv_sweep__read_text(path, TIRENV_SWEEP__TABLE_MAX, &p->keys,
                                          &p->keys_len, diag)) ||
        (status = tirenv_sweep__split_table(p->keys, p->keys_len, path, &p->key_head,
                                            &p->key_rows, &p->n_key_rows, diag)))
        return status;
    snprintf(path, sizeof path, "%s/tire.tir", p->dir);
    return tirenv_sweep__read_text(path, SPEC_MAX, &p->tire, &p->tire_len, diag);
}

/* The description without its shard line equals part 0's, and so on: one sweep. */
static int same_sweep(const part *a, const part *b, tirenv_diag *diag)
{
    const size_t la = a->spec_len - (a->rest_end - a->rest_begin);
    const size_t lb = b->spec_len - (b->rest_end - b->rest_begin);
    int same = la == lb && a->rest_begin == b->rest_begin &&
               memcmp(a->spec, b->spec, a->rest_begin) == 0 &&
               memcmp(a->spec + a->rest_end, b->spec + b->rest_end, a->spec_len - a->rest_end) ==
                   0;
    if (!same)
        return tirenv_error(diag, TIRENV_EINVAL, b->dir, 0, "sweep.txt",
                            "a shard of another sweep than %s (their sweep.txt differ beyond "
                            "the shard line)", a->dir);
    if (a->shards != b->shards)
        return tirenv_error(diag, TIRENV_EINVAL, b->dir, 0, "shard",
                            "shard %zu of %zu, but %s is one of %zu", b->shard, b->shards,
                            a->dir, a->shards);
    if (a->tire_len != b->tire_len || memcmp(a->tire, b->tire, a->tire_len) != 0)
        return tirenv_error(diag, TIRENV_EINVAL, b->dir, 0, "tire.tir",
                            "another tire than %s's", a->dir);
    if (a->case_head != b->case_head || memcmp(a->cases, b->cases, a->case_head) != 0 ||
        a->key_head != b->key_head || memcmp(a->keys, b->keys, a->key_head) != 0)
        return tirenv_error(diag, TIRENV_EINVAL, b->dir, 0, "cases.csv",
                            "its header differs from %s's", a->dir);
    return TIRENV_OK;
}

/* "cases = M" of a description. */
static int spec_cases(const part *p, size_t *m, tirenv_diag *diag)
{
    const char *line = strstr(p->spec, "\ncases = ");
    char *end;
    if (line) {
        errno = 0;
        const unsigned long long v = strtoull(line + 9, &end, 10);
        if (!errno && *end == '\n' && v <= TIRENV_SWEEP__MAX_CASES) {
            *m = (size_t)v;
            return TIRENV_OK;
        }
    }
    return tirenv_error(diag, TIRENV_EPARSE, p->dir, 0, "sweep.txt",
                        "no valid 'cases = M' line");
}

static int copy_file(const char *from, const char *to, tirenv_diag *diag)
{
    FILE *in = fopen(from, "rb");
    if (!in)
        return tirenv_error(diag, TIRENV_EIO, from, 0, "", "cannot open: %s", strerror(errno));
    tirenv_outfile *out;
    int status = tirenv_outfile_open(&out, to, diag);
    if (status) {
        fclose(in);
        return status;
    }
    char buf[65536];
    size_t got;
    while ((got = fread(buf, 1, sizeof buf, in)) > 0)
        fwrite(buf, 1, got, tirenv_outfile_stream(out));
    const int failed = ferror(in);
    fclose(in);
    if (failed) {
        tirenv_outfile_abort(out);
        return tirenv_error(diag, TIRENV_EIO, from, 0, "", "cannot read");
    }
    return tirenv_outfile_commit(out, diag);
}

/* A case file (a manifest path relative to the part) into the merged directory. */
static int bring(const char *part_dir, const char *rel, size_t rel_len, const char *stage,
                 tirenv_diag *diag)
{
    if (rel_len == 0)
        return TIRENV_OK;
    char from[1200], to[1200];
    snprintf(from, sizeof from, "%s/%.*s", part_dir, (int)rel_len, rel);
    snprintf(to, sizeof to, "%s/%.*s", stage, (int)rel_len, rel);
    if (link(from, to) == 0)
        return TIRENV_OK;
    if (errno == EEXIST)
        return tirenv_error(diag, TIRENV_EINVAL, from, 0, "",
                            "a second file for %s: two shards name the same case", to);
    return copy_file(from, to, diag);
}

static int write_table(const char *path, const part *parts, size_t n, int keys, size_t m,
                       tirenv_diag *diag)
{
    tirenv_outfile *f;
    int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    const part **by_shard = malloc(n * sizeof *by_shard);
    if (!by_shard) {
        tirenv_outfile_abort(f);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    for (size_t k = 0; k < n; ++k)
        by_shard[parts[k].shard] = &parts[k];
    const part *p0 = &parts[0];
    FILE *fp = tirenv_outfile_stream(f);
    fwrite(keys ? p0->keys : p0->cases, 1, keys ? p0->key_head : p0->case_head, fp);
    for (size_t i = 0; i < m; ++i) {
        const part *p = by_shard[i % n];
        fputs((keys ? p->key_rows : p->case_rows)[i / n], fp);
        fputc('\n', fp);
    }
    free(by_shard);
    return tirenv_outfile_commit(f, diag);
}

static int merge_into(const char *stage, const part *parts, size_t n, size_t m,
                      tirenv_diag *diag)
{
    const part *p0 = &parts[0];
    char path[1200];
    snprintf(path, sizeof path, "%s/sweep.txt", stage);
    /* The description as one part writes it: without the shard line. */
    char *rest = malloc(p0->spec_len + 1);
    if (!rest)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    memcpy(rest, p0->spec, p0->rest_begin);
    memcpy(rest + p0->rest_begin, p0->spec + p0->rest_end, p0->spec_len - p0->rest_end);
    const size_t rest_len = p0->spec_len - (p0->rest_end - p0->rest_begin);
    int status = tirenv_sweep__write_text(path, rest, rest_len, diag);
    free(rest);
    snprintf(path, sizeof path, "%s/tire.tir", stage);
    if (!status)
        status = tirenv_sweep__write_text(path, p0->tire, p0->tire_len, diag);
    const char *subs[] = {"curves", "logs"};
    for (size_t k = 0; k < 2 && !status; ++k) {
        snprintf(path, sizeof path, "%s/%s", stage, subs[k]);
        status = tirenv_mkdir_p(path, diag);
    }
    int any_log = 0;
    for (size_t k = 0; k < n && !status; ++k)
        for (size_t j = 0; j < parts[k].n_case_rows && !status; ++j) {
            const char *log = NULL, *curve = NULL;
            size_t log_len = 0, curve_len = 0;
            if (tirenv_sweep__row_files(parts[k].case_rows[j], &log, &log_len, &curve,
                                        &curve_len) != 0)
                status = tirenv_error(diag, TIRENV_EPARSE, parts[k].dir, j + 1, "cases.csv",
                                      "row %zu does not name its files as a sweep does", j + 1);
            char c_path[1200], l_path[1200];
            snprintf(c_path, sizeof c_path, "%s/%.*s", parts[k].dir, (int)curve_len, curve);
            snprintf(l_path, sizeof l_path, "%s/%.*s", parts[k].dir, (int)log_len, log);
            if (!status)
                status = tirenv_sweep__check_case(
                    c_path, log_len ? l_path : NULL, "in a part to merge",
                    "run that part again (the same command with its --shard), or copy it "
                    "whole", diag);
            if (!status)
                status = bring(parts[k].dir, log, log_len, stage, diag);
            if (!status)
                status = bring(parts[k].dir, curve, curve_len, stage, diag);
            any_log |= log_len > 0;
        }
    if (!status && !any_log) {  /* curves from the model: no logs/, as one part writes */
        snprintf(path, sizeof path, "%s/logs", stage);
        (void)rmdir(path);
    }
    snprintf(path, sizeof path, "%s/sweep.csv", stage);
    if (!status)
        status = write_table(path, parts, n, 1, m, diag);
    snprintf(path, sizeof path, "%s/cases.csv", stage);
    if (!status)
        status = write_table(path, parts, n, 0, m, diag);  /* last, as a run writes it */
    return status;
}

int tirenv_sweep_merge(const char *dir, size_t n, const char *const parts_dir[],
                       tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    if (n == 0 || !parts_dir)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "parts", "no shard to merge");
    if (!dir || !dir[0] || strlen(dir) > 900)
        return tirenv_error(diag, TIRENV_EINVAL, dir ? dir : "", 0, "dir",
                            "expected an output directory name of 1 to 900 characters");
    part *parts = calloc(n, sizeof *parts);
    if (!parts)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    int status = TIRENV_OK;
    for (size_t k = 0; k < n && !status; ++k) {
        parts[k].dir = parts_dir[k];
        status = read_part(&parts[k], diag);
        if (!status && k > 0)
            status = same_sweep(&parts[0], &parts[k], diag);
        for (size_t j = 0; j < k && !status; ++j)
            if (parts[j].shard == parts[k].shard)
                status = tirenv_error(diag, TIRENV_EINVAL, parts[k].dir, 0, "shard",
                                      "shard %zu/%zu again (also %s)", parts[k].shard,
                                      parts[k].shards, parts[j].dir);
    }
    if (!status && parts[0].shards != n) {
        char missing[256] = "";
        for (size_t s = 0; s < parts[0].shards && strlen(missing) < 200; ++s) {
            size_t k = 0;
            while (k < n && parts[k].shard != s)
                ++k;
            if (k == n)
                snprintf(missing + strlen(missing), sizeof missing - strlen(missing), "%s%zu",
                         missing[0] ? ", " : "", s);
        }
        status = tirenv_error(diag, TIRENV_EINVAL, "", 0, "parts",
                              "the sweep has %zu shards, %zu given; missing: %s",
                              parts[0].shards, n, missing);
    }
    size_t m = 0;
    if (!status)
        status = spec_cases(&parts[0], &m, diag);
    for (size_t k = 0; k < n && !status; ++k)
        if (!(status = tirenv_sweep__check_rows(
                  parts[k].dir, "cases.csv",
                  tirenv_sweep__lines(parts[k].cases, parts[k].case_head), parts[k].case_rows,
                  parts[k].n_case_rows, m, parts[k].shard, parts[k].shards, diag)))
            status = tirenv_sweep__check_rows(
                parts[k].dir, "sweep.csv", tirenv_sweep__lines(parts[k].keys, parts[k].key_head),
                parts[k].key_rows, parts[k].n_key_rows, m, parts[k].shard, parts[k].shards,
                diag);
    /* The target: absent or empty, or this very sweep already merged. */
    char *rest = NULL;
    int state = 0;
    if (!status) {
        const part *p0 = &parts[0];
        rest = malloc(p0->spec_len + 1);
        if (!rest) {
            status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
        } else {
            memcpy(rest, p0->spec, p0->rest_begin);
            memcpy(rest + p0->rest_begin, p0->spec + p0->rest_end,
                   p0->spec_len - p0->rest_end + 1);
            state = tirenv_sweep__target_state(dir, rest, p0->tire, p0->tire_len, m, 0, 1,
                                               diag);
            if (state < 0)
                status = -state;
        }
    }
    /* Written as a whole (tirenv_outdir): a staging directory beside dir, swapped into place
     * once every file is there. A merge is not resumable (it only links or copies), so a
     * killed one leaves nothing that the next run in that directory does not sweep away. */
    if (!status && state == 0) {
        tirenv_outdir *out = NULL;
        status = tirenv_outdir_begin(dir, &out, diag);
        if (!status)
            status = merge_into(tirenv_outdir_path(out), parts, n, m, diag);
        if (!status)
            status = tirenv_outdir_commit(out, diag);
        else
            tirenv_outdir_abort(out);
    }
    free(rest);
    for (size_t k = 0; k < n; ++k)
        part_free(&parts[k]);
    free(parts);
    return status;
}
