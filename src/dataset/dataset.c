/* Data sets of enveloping curves: a directory with a manifest cases.csv, one case per line,
 * pointing at each case's raw rig log and/or its imported approach-half curve (paths relative
 * to the directory). The split follows the paper's Table 2: train, control, validation.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/dataset.h"
#include "tirenv/rig.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "dataset/dataset_impl.h"
#include "io/io.h"

enum {
    COL_CASE,
    COL_SPLIT,
    COL_CONTACT_LENGTH,
    COL_LOAD,
    COL_L,
    COL_H,
    COL_LOG,
    COL_CURVE,
    MANIFEST_FIELDS
};
static const char *const manifest_names[MANIFEST_FIELDS] = {
    "case", "split", "contact_length_m", "load_N", "obstacle_length_m", "obstacle_height_m",
    "log", "curve"};
static const char *const split_names[] = {"train", "control", "validation"};
enum { N_SPLITS = sizeof split_names / sizeof split_names[0] };

const char *tirenv_split_name(tirenv_split split)
{
    return (size_t)split < N_SPLITS ? split_names[split] : "unknown";
}

void tirenv_dataset_free(tirenv_dataset *ds)
{
    if (!ds)
        return;
    for (size_t i = 0; i < ds->n; i++)
        tirenv_curve_free(&ds->cases[i].curve);
    free(ds->cases);
    ds->cases = NULL;
    ds->n = 0;
    ds->dir[0] = '\0';
}

static int parse_split(const tirenv_csv__reader *r, const tirenv_csv__field *f,
                       tirenv_split *out)
{
    for (size_t k = 0; k < N_SPLITS; k++)
        if (strcmp(f->text, split_names[k]) == 0) {
            *out = (tirenv_split)k;
            return TIRENV_OK;
        }
    return tirenv_csv__fail(r, f->column, "split",
                            "expected train, control or validation, got '%.60s'", f->text);
}

/* A positive length or force: what every number of the manifest is; at most a road's
 * bound, TIRENV_PROFILE_MAX_COORDINATE (m or N): a load of 1e308 was listed as 309 digits
 * and trained into a network's contact law with exit 0. */
static int parse_positive(const tirenv_csv__reader *r, const tirenv_csv__field *f, size_t col,
                          double *out)
{
    const int status = tirenv_csv__number_within(r, f, manifest_names[col],
                                                 TIRENV_PROFILE_MAX_COORDINATE,
                                                 col == COL_LOAD ? "a force in N"
                                                                 : "a length in m",
                                                 out);
    if (status == TIRENV_OK && !(*out > 0))
        return tirenv_csv__fail(r, f->column, manifest_names[col],
                                "expected a positive number, got '%.60s'", f->text);
    return status;
}

/* A file of the case: relative to the data-set directory unless absolute; "" stays "". */
static int parse_path(const tirenv_csv__reader *r, const tirenv_csv__field *f, size_t col,
                      const char *dir, char out[512])
{
    out[0] = '\0';
    if (f->text[0] == '\0')
        return TIRENV_OK;
    const int w = f->text[0] == '/' ? snprintf(out, 512, "%s", f->text)
                                    : snprintf(out, 512, "%s/%s", dir, f->text);
    if (w < 0 || w >= 512)
        return tirenv_csv__fail(r, f->column, manifest_names[col],
                                "the path is longer than 511 characters with the directory");
    return TIRENV_OK;
}

/* The case names seen so far, for the duplicate check: open addressing on FNV-1a, indices
 * into ds->cases plus one (0 = empty), at most half full. A scan of every earlier name made
 * 100,000 cases take 66 s. */
typedef struct {
    size_t *slot;
    size_t cap;   /* a power of two, or 0 */
} name_set;

static size_t name_hash(const char *s)
{
    uint64_t h = 14695981039346656037u;
    for (; *s; ++s)
        h = (h ^ (unsigned char)*s) * 1099511628211u;
    return (size_t)h;
}

/* The case with this name, or NULL. */
static const tirenv_case *name_find(const name_set *set, const tirenv_dataset *ds,
                                    const char *name)
{
    if (!set->cap)
        return NULL;
    for (size_t i = name_hash(name) & (set->cap - 1);; i = (i + 1) & (set->cap - 1)) {
        if (!set->slot[i])
            return NULL;
        if (strcmp(ds->cases[set->slot[i] - 1].name, name) == 0)
            return &ds->cases[set->slot[i] - 1];
    }
}

/* Records case k of ds (its name not yet in the set). */
static int name_add(name_set *set, const tirenv_dataset *ds, size_t k)
{
    if (2 * (k + 1) > set->cap) {
        const size_t cap = set->cap ? 2 * set->cap : 64;
        size_t *slot = calloc(cap, sizeof *slot);
        if (!slot)
            return TIRENV_ENOMEM;
        for (size_t j = 0; j < k; ++j) {
            size_t i = name_hash(ds->cases[j].name) & (cap - 1);
            while (slot[i])
                i = (i + 1) & (cap - 1);
            slot[i] = j + 1;
        }
        free(set->slot);
        set->slot = slot;
        set->cap = cap;
    }
    size_t i = name_hash(ds->cases[k].name) & (set->cap - 1);
    while (set->slot[i])
        i = (i + 1) & (set->cap - 1);
    set->slot[i] = k + 1;
    return TIRENV_OK;
}

static int parse_name(const tirenv_csv__reader *r, const tirenv_csv__field *f,
                      const tirenv_dataset *ds, const name_set *names, char out[32])
{
    const size_t n = strlen(f->text);
    if (n == 0)
        return tirenv_csv__fail(r, f->column, "case", "expected a case name, got nothing");
    if (n >= 32)
        return tirenv_csv__fail(r, f->column, "case",
                                "case names have at most 31 characters, got %zu", n);
    if (name_find(names, ds, f->text))
        return tirenv_csv__fail(r, f->column, "case",
                                "case '%s' appears twice; names must be unique", f->text);
    memcpy(out, f->text, n + 1);
    return TIRENV_OK;
}

static int parse_case(tirenv_csv__reader *r, const tirenv_dataset *ds, const name_set *names,
                      tirenv_case *c)
{
    tirenv_csv__field f[MANIFEST_FIELDS + 1];
    int status = tirenv_csv__fields(r, manifest_names, MANIFEST_FIELDS, f);
    if (status == TIRENV_OK)
        status = parse_name(r, &f[COL_CASE], ds, names, c->name);
    if (status == TIRENV_OK)
        status = parse_split(r, &f[COL_SPLIT], &c->split);
    if (status == TIRENV_OK)
        status = parse_positive(r, &f[COL_CONTACT_LENGTH], COL_CONTACT_LENGTH,
                                &c->contact_length);
    if (status == TIRENV_OK)
        status = parse_positive(r, &f[COL_LOAD], COL_LOAD, &c->load);
    if (status == TIRENV_OK)
        status = parse_positive(r, &f[COL_L], COL_L, &c->L);
    if (status == TIRENV_OK)
        status = parse_positive(r, &f[COL_H], COL_H, &c->H);
    if (status == TIRENV_OK)
        status = parse_path(r, &f[COL_LOG], COL_LOG, ds->dir, c->log);
    if (status == TIRENV_OK)
        status = parse_path(r, &f[COL_CURVE], COL_CURVE, ds->dir, c->curve_path);
    if (status == TIRENV_OK && !c->log[0] && !c->curve_path[0])
        status = tirenv_csv__fail(r, f[COL_LOG].column, "log",
                                  "case '%s' has neither a log nor a curve file; expected at "
                                  "least one", c->name);
    return status;
}

static int add_case(tirenv_dataset *ds, size_t *cap, const tirenv_case *c)
{
    if (ds->n == *cap) {
        const size_t want = *cap ? 2 * *cap : 32;
        if (want > SIZE_MAX / sizeof *ds->cases)
            return TIRENV_ENOMEM;
        tirenv_case *p = realloc(ds->cases, want * sizeof *p);
        if (!p)
            return TIRENV_ENOMEM;
        ds->cases = p;
        *cap = want;
    }
    ds->cases[ds->n++] = *c;
    return TIRENV_OK;
}

/* The manifest holds other than the cases source.txt (or a sweep's sweep.txt) declares: one
 * cut at a line end reads as a shorter manifest (every row it keeps is whole), so without the
 * count it would pass for a smaller data set. At the first row beyond the count, or after the
 * last line. */
static int cases_differ(const tirenv_csv__reader *r, const tirenv_dataset *ds,
                        const tirenv_dataset__declared *decl)
{
    const int beyond = ds->n == decl->cases;
    const int status = tirenv_error(r->diag, TIRENV_EPARSE, r->file, r->line + !beyond, "",
                                    "%s%zu cases, but %s:%zu declares %s; expected that many "
                                    "(%s, or another data set's %s)", beyond ? "more than " : "",
                                    ds->n, decl->file, decl->line, decl->what,
                                    beyond ? "rows added" : "a manifest cut short",
                                    strrchr(decl->file, '/') + 1);
    if (r->diag)
        r->diag->column = 1;
    return status;
}

static int parse_manifest(tirenv_csv__reader *r, tirenv_dataset *ds,
                          const tirenv_dataset__declared *decl)
{
    int more = tirenv_csv__next(r);
    if (more == 0) {
        const int status = tirenv_error(r->diag, TIRENV_EPARSE, r->file, 1, "",
                                        "no header: the file is empty or holds only blank and "
                                        "comment lines; expected the manifest header");
        if (r->diag)
            r->diag->column = 1;
        return status;
    }
    int status = more < 0 ? -more : tirenv_csv__header(r, manifest_names, MANIFEST_FIELDS);
    size_t cap = 0;
    name_set names = {NULL, 0};
    while (status == TIRENV_OK && (more = tirenv_csv__next(r)) > 0) {
        if (decl->cases && ds->n == decl->cases) {
            status = cases_differ(r, ds, decl);
            break;
        }
        if (ds->n == TIRENV_DATASET__MAX_CASES) {
            status = tirenv_error(r->diag, TIRENV_EPARSE, r->file, r->line, "case",
                                  "more than %u cases; expected at most that many (the "
                                  "most tirenv sweep makes)", TIRENV_DATASET__MAX_CASES);
            break;
        }
        tirenv_case c = {0};
        status = parse_case(r, ds, &names, &c);
        if (status == TIRENV_OK && (add_case(ds, &cap, &c) != TIRENV_OK ||
                                    name_add(&names, ds, ds->n - 1) != TIRENV_OK))
            status = tirenv_error(r->diag, TIRENV_ENOMEM, r->file, r->line, "",
                                  "out of memory");
    }
    free(names.slot);
    if (status == TIRENV_OK && more < 0)
        status = -more;
    if (status == TIRENV_OK && decl->cases && ds->n != decl->cases)
        status = cases_differ(r, ds, decl);
    if (status == TIRENV_OK && ds->n == 0) {
        status = tirenv_error(r->diag, TIRENV_EPARSE, r->file, r->line + 1, "",
                              "no cases after the header; expected one line per case");
        if (r->diag)
            r->diag->column = 1;
    }
    return status;
}

int tirenv_dataset__refuse_pipe(const char *path, tirenv_diag *diag)
{
    struct stat st;
    if (stat(path, &st) != 0 || !(S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode)))
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_EIO, path, 0, "", "a pipe, which can be read only once; "
                        "a data set's files are read more than once (by the command, the "
                        "data-set reader and each stage of a study), expected a regular file");
}

/* The curve file when there is one (the import is done once, when the data set is built);
 * otherwise the log, imported with the case's own regime and obstacle. */
static int load_curve(tirenv_case *c, double R0, tirenv_diag *diag)
{
    const int status = tirenv_dataset__refuse_pipe(c->curve_path[0] ? c->curve_path : c->log,
                                                   diag);
    if (status)
        return status;
    if (c->curve_path[0])
        return tirenv_curve_read_csv(c->curve_path, &c->curve, diag);
    tirenv_import_settings s = tirenv_import_default();
    s.R0 = R0;
    s.contact_length = c->contact_length;
    s.L = c->L;
    s.H = c->H;
    return tirenv_rig_import(c->log, &s, &c->curve, diag);
}

/* A sweep's curve has the points of the data sets' x_N grid (docs/formats.md section 13):
 * one cut at a line end, points short, is no whole case, where it read as a shorter curve. */
static int sweep_curve(const tirenv_case *c, tirenv_diag *diag)
{
    const tirenv_import_settings g = tirenv_import_default();
    const size_t n = tirenv_import_grid_points(&g);
    if (c->curve.n == n)
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_EPARSE, c->curve_path[0] ? c->curve_path : c->log, 0,
                        "x_N", "%zu points, where a sweep's curve (sweep.txt beside the "
                        "manifest) has the %zu of the x_N grid %g to %g every %g; expected a "
                        "whole case file (cut short?)", c->curve.n, n, g.xN_from, g.xN_to,
                        g.dxN);
}

int tirenv_dataset_read(const char *dir, double R0, tirenv_dataset *out, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *out = (tirenv_dataset){{0}, 0, NULL};
    if (!dir || !dir[0] || strlen(dir) >= sizeof out->dir)
        return tirenv_error(diag, TIRENV_EINVAL, dir ? dir : "", 0, "",
                            "expected a data-set directory name of 1 to %zu characters",
                            sizeof out->dir - 1);
    snprintf(out->dir, sizeof out->dir, "%s", dir);
    char path[sizeof out->dir + 16];
    snprintf(path, sizeof path, "%s/cases.csv", dir);
    /* The count source.txt declares, else a sweep's sweep.txt. */
    tirenv_dataset_source src;
    tirenv_dataset__declared decl = {0};
    int status = tirenv_dataset_source_read(dir, &src, diag);
    if (status == TIRENV_OK && src.cases) {
        decl.cases = src.cases;
        decl.line = src.cases_line;
        snprintf(decl.file, sizeof decl.file, "%s/source.txt", dir);
        snprintf(decl.what, sizeof decl.what, "cases = %zu", src.cases);
    } else if (status == TIRENV_OK) {
        status = tirenv_dataset__sweep_declared(dir, &decl, diag);
    }
    const int from_sweep = decl.cases && strcmp(strrchr(decl.file, '/'), "/sweep.txt") == 0;
    if (status == TIRENV_OK) {
        tirenv_csv__reader r;
        memset(&r, 0, sizeof r);  /* closed whether opened or not */
        status = tirenv_dataset__refuse_pipe(path, diag);
        if (status == TIRENV_OK && (status = tirenv_csv__open(&r, path, diag)) == TIRENV_OK)
            status = parse_manifest(&r, out, &decl);
        tirenv_csv__close(&r);
    }
    for (size_t i = 0; i < out->n && status == TIRENV_OK; i++) {
        if (!out->cases[i].curve_path[0] && !(R0 > 0 && isfinite(R0)))
            status = tirenv_error(diag, TIRENV_EINVAL, path, 0, "R0",
                                  "importing the log of case '%s' needs the tire radius R0 > "
                                  "0, got %g", out->cases[i].name, R0);
        else
            status = load_curve(&out->cases[i], R0, diag);
        if (!status && from_sweep)
            status = sweep_curve(&out->cases[i], diag);
    }
    if (status != TIRENV_OK)
        tirenv_dataset_free(out);
    return status;
}
