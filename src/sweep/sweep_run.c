/* Running a sweep (docs/formats.md section 13): the cases of one shard into "<dir>.partial",
 * each case's files atomically, so that a killed run leaves only whole cases, which the next
 * run keeps; the manifest last, from the grid; then the directory renamed into place.
 * SPDX-License-Identifier: Apache-2.0 */
#include "dataset/dataset.h"
#include "sweep/sweep_impl.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#include "tirenv/curve.h"
#include "tirenv/outfile.h"
#include "tirenv/tir.h"
#include "tirenv/parallel.h"
#include "tirenv/rig.h"
#include "io/io.h"

enum { SPEC_MAX = 1 << 20, TIRE_MAX = 1 << 20 };

typedef struct {
    const tirenv_sweep_settings *s;
    const tirenv_tire *tire;
    char dir[1024];              /* the partial directory */
    size_t n;                    /* cases of the grid */
    unsigned char *split;        /* by case */
    size_t *pairs;               /* the (variant, regime) pairs this shard needs, as
                                  * variant * regimes + regime */
    size_t n_pairs;
    double *load, *l_c;          /* N, m, by pair (NaN where not needed) */
    size_t *todo;                /* cases to run */
    size_t n_todo;
    size_t resumed;
} sweep_run;

static int exists_regular(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* "case cNNNN (cleat L x H m, contact length l m | load G N, KEY = v, ...)" for messages and
 * file comments. */
static void describe_case(const sweep_run *r, size_t i, char *buf, size_t size)
{
    const tirenv_sweep_settings *s = r->s;
    tirenv_sweep__coords c;
    tirenv_sweep__coords_of(s, i, &c);
    char name[32], L[32], H[32], g[32];
    tirenv_sweep__case_name(s, i, name);
    tirenv_sweep__number(s->lengths[c.length], L);
    tirenv_sweep__number(s->heights[c.height], H);
    tirenv_sweep__number(s->n_contact_lengths ? s->contact_lengths[c.regime]
                                              : s->loads[c.regime], g);
    int w = snprintf(buf, size, "case %s (cleat %s x %s m, %s %s %s", name, L, H,
                     s->n_contact_lengths ? "contact length" : "load", g,
                     s->n_contact_lengths ? "m" : "N");
    for (size_t k = 0; k < s->n_keys && w > 0 && (size_t)w < size; ++k) {
        char v[32];
        tirenv_sweep__number(s->keys[k].values[c.key_index[k]], v);
        w += snprintf(buf + w, size - (size_t)w, ", %s = %s", s->keys[k].key, v);
    }
    if (w > 0 && (size_t)w < size)
        snprintf(buf + w, size - (size_t)w, ")");
}

/* Prefixes a failure's message with the case it happened in. */
static int case_failed(const sweep_run *r, size_t i, int status, tirenv_diag *diag)
{
    if (!diag)
        return status;
    char what[400], msg[sizeof diag->message];
    describe_case(r, i, what, sizeof what);
    snprintf(msg, sizeof msg, "%.200s: %.300s", what, diag->message);
    memcpy(diag->message, msg, sizeof msg);
    return status;
}

/* A model of the sweep's type for a tire variant, with the sweep's network if it needs one. */
static int sweep_model(const tirenv_sweep_settings *s, const tirenv_tire *t, tirenv_model **m,
                       tirenv_diag *diag)
{
    *m = tirenv_model_alloc(s->type, t);
    if (!*m)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "tire",
                            "the %s model cannot be built from this tire (or memory ran out)",
                            tirenv_model_type_name(s->type));
    if (!(tirenv_model_type_flags(s->type) & TIRENV_MODEL_NEEDS_NETWORK))
        return TIRENV_OK;
    int status = tirenv_model_set_network(*m, s->network, s->network_R0, diag);
    /* The network's own tire relates the regime's load and contact length, as envelope's
     * network does: the springs model stood in for it, and a sweep at 0.3 m wrote the springs
     * model's 18803 N where the network's tire carries 19276 N. */
    if (!status && s->network_law)
        status = tirenv_model_set_contact_law(*m, s->network_law, diag);
    if (!status)
        tirenv_model_set_extrapolate(*m, s->extrapolate);
    if (status) {
        tirenv_model_free(*m);
        *m = NULL;
    }
    return status;
}

/* ---- loads and contact lengths, once per (tire variant, regime) ------------------------- */

static int pair_item(void *ctx, size_t k, size_t worker, tirenv_diag *diag)
{
    sweep_run *r = ctx;
    const tirenv_sweep_settings *s = r->s;
    const size_t regimes = tirenv_sweep__regimes(s);
    const size_t p = r->pairs[k], v = p / regimes, a = p % regimes;
    (void)worker;
    tirenv_tire t;
    tirenv_model *m = NULL;
    int status = tirenv_sweep__variant_tire(s, r->tire, v, &t, diag);
    if (!status)
        status = sweep_model(s, &t, &m, diag);
    if (!status && s->n_contact_lengths) {
        r->l_c[p] = s->contact_lengths[a];
        status = tirenv_model_load_for_contact_length(m, r->l_c[p], &r->load[p], diag);
    } else if (!status) {
        tirenv_flat flat;
        r->load[p] = s->loads[a];
        status = tirenv_model_flat(m, r->load[p], &flat, diag);
        if (!status)
            r->l_c[p] = flat.contact_length;
        if (!status && !(flat.contact_length > 0 && flat.contact_length < 2 * t.springs.R0))
            status = tirenv_error(diag, TIRENV_ERANGE, "", 0, "load",
                                  "the %s model's contact length at %g N is %g m; a case "
                                  "needs one in (0, 2 R0)", tirenv_model_type_name(s->type),
                                  r->load[p], flat.contact_length);
    }
    tirenv_model_free(m);
    if (status) {
        /* Name the first case of the shard that needs this pair. */
        for (size_t i = s->shard; i < r->n; i += s->shards) {
            tirenv_sweep__coords c;
            tirenv_sweep__coords_of(s, i, &c);
            if (c.variant == v && c.regime == a)
                return case_failed(r, i, status, diag);
        }
    }
    return status;
}

static int regime_table(sweep_run *r, tirenv_diag *diag)
{
    const tirenv_sweep_settings *s = r->s;
    const size_t n_pairs_all = tirenv_sweep__variants(s) * tirenv_sweep__regimes(s);
    unsigned char *need = calloc(n_pairs_all, 1);
    r->load = malloc(n_pairs_all * sizeof *r->load);
    r->l_c = malloc(n_pairs_all * sizeof *r->l_c);
    r->pairs = malloc(n_pairs_all * sizeof *r->pairs);
    if (!need || !r->load || !r->l_c || !r->pairs) {
        free(need);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    for (size_t i = s->shard; i < r->n; i += s->shards) {
        tirenv_sweep__coords c;
        tirenv_sweep__coords_of(s, i, &c);
        need[c.variant * tirenv_sweep__regimes(s) + c.regime] = 1;
    }
    for (size_t p = 0; p < n_pairs_all; ++p) {
        r->load[p] = r->l_c[p] = NAN;
        if (need[p])
            r->pairs[r->n_pairs++] = p;
    }
    free(need);
    return tirenv_parallel_for(r->n_pairs, s->jobs, pair_item, NULL, r, diag);
}

/* ---- one case ---------------------------------------------------------------------------- */

static void case_path(const sweep_run *r, const char *sub, size_t i, char *buf, size_t size)
{
    char name[32];
    tirenv_sweep__case_name(r->s, i, name);
    snprintf(buf, size, "%s/%s/%s.csv", r->dir, sub, name);
}

/* Case files are written whole or not at all (tirenv_outfile, fsync before rename), so one
 * that is not came from elsewhere: a part copied from a node in part, a file edited or
 * damaged. A resume or a merge that took it would call complete a data set holding it. */
int tirenv_sweep__check_case(const char *curve, const char *log, const char *what,
                             const char *remedy, tirenv_diag *diag)
{
    tirenv_curve c = {0};
    int status = tirenv_curve_read_csv(curve, &c, diag);
    const tirenv_import_settings g = tirenv_import_default();
    const size_t n = tirenv_import_grid_points(&g);
    if (!status && c.n != n)
        status = tirenv_error(diag, TIRENV_EPARSE, curve, 0, "x_N",
                              "%zu points, where a sweep's curve has the %zu of the x_N grid "
                              "%g to %g every %g", c.n, n, g.xN_from, g.xN_to, g.dxN);
    tirenv_curve_free(&c);
    if (!status && log) {
        FILE *fp = fopen(log, "rb");
        int last = EOF;
        if (fp && fseek(fp, -1, SEEK_END) == 0)
            last = fgetc(fp);
        if (fp)
            fclose(fp);
        if (last != '\n')
            status = tirenv_error(diag, TIRENV_EPARSE, log, 0, "",
                                  fp ? "empty, or its last line ends without a newline (cut "
                                       "short)"
                                     : "cannot open: %s", strerror(errno));
    }
    if (!status)
        return TIRENV_OK;
    if (diag) {
        char why[sizeof diag->message];
        memcpy(why, diag->message, sizeof why);
        /* Each part bounded to fit the message; the file is named apart, in diag->file. */
        snprintf(diag->message, sizeof diag->message,
                 "%s, %.40s, is not a whole case file: %.250s; %.150s",
                 diag->file[0] ? "this file" : "a case file", what, why, remedy);
    }
    return TIRENV_EPARSE;
}

/* The model's own curve on the import's x_N grid (tirenv_rig_model_curve). */
static int model_curve(tirenv_model *m, const tirenv_profile *cleat, double load, double R0,
                       double l_c, double L, double H, tirenv_curve *out, tirenv_diag *diag)
{
    tirenv_import_settings g = tirenv_import_default();
    g.L = L;
    g.H = H;
    g.R0 = R0;
    g.contact_length = l_c;
    int status = tirenv_model_set(m, cleat, load, diag);
    return status ? status : tirenv_rig_model_curve(m, &g, out, diag);
}

/* The rig as tirenv_dataset_build runs it: each run its own noise and its own rig zero. */
static int rig_curve(const sweep_run *r, size_t i, tirenv_model *m,
                     const tirenv_profile *cleat, double load, double R0, double l_c, double L,
                     double H, const char *what, tirenv_curve *out, tirenv_diag *diag)
{
    tirenv_rig_settings rig = tirenv_rig_default();
    rig.seed = r->s->seed + i;
    rig.x_offset = 1.5 + 0.1 * (double)(i % 10);
    rig.z_offset = 0.35 + 0.01 * (double)(i % 10);
    tirenv_rig_log log = {0};
    int status = tirenv_model_set(m, cleat, load, diag);
    if (!status)
        status = tirenv_rig_simulate(m, cleat, &rig, &log, diag);
    char path[1200], comment[1200];
    case_path(r, "logs", i, path, sizeof path);
    snprintf(comment, sizeof comment,
             "SIMULATED rig data (tirenv sweep: the %s model on the virtual rig), not a "
             "measurement.\n%s; speed %g m/s, %g Hz, noise sigma x %g m, z %g m, seed %lu",
             tirenv_model_name(m), what, rig.speed, rig.rate, rig.noise_x, rig.noise_z,
             rig.seed);
    if (!status)
        status = tirenv_rig_write_log(path, &log, comment, diag);
    tirenv_import_settings imp = tirenv_import_default();
    imp.L = L;
    imp.H = H;
    imp.R0 = R0;
    imp.contact_length = l_c;
    if (!status)
        status = tirenv_rig_import_samples(log.n, log.t, log.x, log.z, &imp, out, diag);
    tirenv_rig_log_free(&log);
    return status;
}

static int case_item(void *ctx, size_t k, size_t worker, tirenv_diag *diag)
{
    const sweep_run *r = ctx;
    const tirenv_sweep_settings *s = r->s;
    const size_t i = r->todo[k];
    (void)worker;
    tirenv_sweep__coords c;
    tirenv_sweep__coords_of(s, i, &c);
    const size_t p = c.variant * tirenv_sweep__regimes(s) + c.regime;
    const double L = s->lengths[c.length], H = s->heights[c.height];
    tirenv_tire t;
    tirenv_model *m = NULL;
    int status = tirenv_sweep__variant_tire(s, r->tire, c.variant, &t, diag);
    /* The case's own model instance: its curve depends on the case alone. */
    if (!status)
        status = sweep_model(s, &t, &m, diag);
    tirenv_profile *cleat = tirenv_profile_cleat(L, H);
    if (!status && !cleat)
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    /* At a contact length, the case's model finds its load itself (a model whose input is the
     * contact length, the network, remembers it); the same number as the table's, which the
     * manifest writes. */
    if (!status && s->n_contact_lengths) {
        double load;
        status = tirenv_model_load_for_contact_length(m, r->l_c[p], &load, diag);
        if (!status && load != r->load[p])
            status = tirenv_error(diag, TIRENV_ENOCONV, "", 0, "load",
                                  "the load at contact length %.17g m came out %.17g N here "
                                  "and %.17g N before: the model is not deterministic",
                                  r->l_c[p], load, r->load[p]);
    }
    char name[32], L_s[32], H_s[32], load_s[32], l_c_s[32], path[1200], comment[1200];
    tirenv_sweep__case_name(s, i, name);
    tirenv_sweep__number(L, L_s);
    tirenv_sweep__number(H, H_s);
    tirenv_sweep__number(r->load[p], load_s);
    tirenv_sweep__number(r->l_c[p], l_c_s);
    /* The case line of its files: the regime both ways, whichever was swept. */
    char line[600];
    int w = snprintf(line, sizeof line, "case %s: cleat %s x %s m, contact length %s m, load "
                     "%s N", name, L_s, H_s, l_c_s, load_s);
    for (size_t j = 0; j < s->n_keys && w > 0 && (size_t)w < sizeof line; ++j) {
        char v[32];
        tirenv_sweep__number(s->keys[j].values[c.key_index[j]], v);
        w += snprintf(line + w, sizeof line - (size_t)w, ", %s = %s", s->keys[j].key, v);
    }
    tirenv_curve curve = {0};
    if (!status && s->rig)
        status = rig_curve(r, i, m, cleat, r->load[p], t.springs.R0, r->l_c[p], L, H, line,
                           &curve, diag);
    else if (!status)
        status = model_curve(m, cleat, r->load[p], t.springs.R0, r->l_c[p], L, H, &curve,
                             diag);
    if (s->rig)
        snprintf(comment, sizeof comment,
                 "SIMULATED curve (tirenv sweep: the %s model on the virtual rig, its log "
                 "imported), not a measurement.\n%s", tirenv_model_type_name(s->type), line);
    else
        snprintf(comment, sizeof comment,
                 "SIMULATED curve (tirenv sweep: the %s model's enveloping curve on the x_N "
                 "grid), not a measurement.\n%s", tirenv_model_type_name(s->type), line);
    case_path(r, "curves", i, path, sizeof path);
    if (!status)
        status = tirenv_curve_write_csv(path, &curve, comment, diag);
    tirenv_curve_free(&curve);
    tirenv_profile_free(cleat);
    tirenv_model_free(m);
    return status ? case_failed(r, i, status, diag) : TIRENV_OK;
}

static void case_done(void *ctx, size_t item, size_t n_done)
{
    const sweep_run *r = ctx;
    (void)item;
    if (r->s->progress)
        r->s->progress(r->s->progress_ctx, r->resumed + n_done, r->resumed + r->n_todo);
}

/* ---- the directory ----------------------------------------------------------------------- */

/* Case i's index from a file name "<case>.csv" of this shard, or SIZE_MAX. */
static size_t case_of_file(const sweep_run *r, const char *file)
{
    char name[32];
    const size_t len = strlen(file);
    if (len < 6 || len > 36 || strcmp(file + len - 4, ".csv") != 0 || file[0] != 'c')
        return SIZE_MAX;
    char *end;
    errno = 0;
    const unsigned long long i = strtoull(file + 1, &end, 10);
    if (errno || end != file + len - 4 || i >= r->n || i % r->s->shards != r->s->shard)
        return SIZE_MAX;
    tirenv_sweep__case_name(r->s, (size_t)i, name);
    return strncmp(file, name, len - 4) == 0 && name[len - 4] == '\0' ? (size_t)i : SIZE_MAX;
}

/* 1 if a run writes a file of this name into the partial directory (sub NULL) or into its
 * sub directory sub. */
static int run_writes(const sweep_run *r, const char *sub, const char *name)
{
    if (sub)
        return case_of_file(r, name) != SIZE_MAX;
    static const char *const top[] = {"sweep.txt", "tire.tir", "sweep.csv", "cases.csv"};
    for (size_t k = 0; k < sizeof top / sizeof top[0]; ++k)
        if (strcmp(name, top[k]) == 0)
            return 1;
    return 0;
}

/* 1 if f is a temporary file of a write a run makes there: ".<name>.tirenv-tmp.*"
 * (tirenv_outfile), or "<name>.tmp.*" as tirenv wrote them before. */
static int run_temporary(const sweep_run *r, const char *sub, const char *f)
{
    char name[64];
    if (tirenv_tmp__target_of(f, name, sizeof name))
        return run_writes(r, sub, name);
    const char *mark = strstr(f, ".tmp.");
    const size_t n = mark ? (size_t)(mark - f) : 0;
    if (n == 0 || n >= sizeof name)
        return 0;
    memcpy(name, f, n);
    name[n] = '\0';
    return run_writes(r, sub, name);
}

/* What an interrupted run may have left besides whole cases: temporary files of writes it
 * did not finish, a manifest written just before the kill. Removed, so that what the
 * directory holds at the end is what a run without interruption writes. An entry that no run
 * writes is refused: the directory is not only ours (a file of one's own in DIR.partial was
 * removed without a word). */
static int tidy(const sweep_run *r, const char *sub, tirenv_diag *diag)
{
    char path[1200];
    if (sub)
        snprintf(path, sizeof path, "%s/%s", r->dir, sub);
    else
        snprintf(path, sizeof path, "%s", r->dir);
    DIR *d = opendir(path);
    if (!d)
        return errno == ENOENT ? TIRENV_OK
                               : tirenv_error(diag, TIRENV_EIO, path, 0, "",
                                              "cannot read the directory: %s", strerror(errno));
    int status = TIRENV_OK;
    struct dirent *e;
    while (!status && (e = readdir(d))) {
        const char *f = e->d_name;
        if (strcmp(f, ".") == 0 || strcmp(f, "..") == 0)
            continue;
        char full[1500];
        snprintf(full, sizeof full, "%s/%s", path, f);
        if (sub ? case_of_file(r, f) != SIZE_MAX
                : (strcmp(f, "sweep.txt") == 0 || strcmp(f, "tire.tir") == 0 ||
                   strcmp(f, "curves") == 0 || (r->s->rig && strcmp(f, "logs") == 0)))
            continue;
        struct stat st;
        const int leftover = (!sub && (strcmp(f, "sweep.csv") == 0 ||
                                       strcmp(f, "cases.csv") == 0)) ||
                             run_temporary(r, sub, f);
        if (!leftover || lstat(full, &st) != 0 || !S_ISREG(st.st_mode))
            status = tirenv_error(diag, TIRENV_EIO, full, 0, "",
                                  "an entry no sweep writes; is this directory the sweep's?");
        else if (unlink(full) != 0)
            status = tirenv_error(diag, TIRENV_EIO, full, 0, "", "cannot remove: %s",
                                  strerror(errno));
    }
    closedir(d);
    return status;
}

/* The first line where two descriptions differ, for the message. */
static void first_difference(const char *a, const char *b, char *buf, size_t size)
{
    size_t line = 1;
    while (*a && *a == *b) {
        line += *a == '\n';
        ++a;
        ++b;
    }
    while (line > 1 && a[-1] != '\n') {
        --a;
        --b;
    }
    const int la = (int)strcspn(a, "\n"), lb = (int)strcspn(b, "\n");
    snprintf(buf, size, "line %zu: '%.*s' there, '%.*s' here", line, la > 100 ? 100 : la, a,
             lb > 100 ? 100 : lb, b);
}

/* Compares a file with the text this sweep writes there; 1 equal, 0 absent, else an error. */
static int same_text(const char *path, const char *text, size_t len, const char *what,
                     tirenv_diag *diag)
{
    if (!exists_regular(path))
        return 0;
    char *have;
    size_t n;
    int status = tirenv_sweep__read_text(path, 4 * (size_t)SPEC_MAX, &have, &n, diag);
    if (status)
        return -status;
    if (n == len && memcmp(have, text, len) == 0) {
        free(have);
        return 1;
    }
    char where[300];
    first_difference(have, text, where, sizeof where);
    free(have);
    return -tirenv_error(diag, TIRENV_EINVAL, path, 0, "",
                         "holds %s of another sweep (%s); continue that sweep with its own "
                         "options, or remove the directory", what, where);
}

/* The tire file's text, written by tirenv_tir_write to a scratch file and read back. The
 * file's name is the process's and this call's own: named by the process alone, two sweeps of
 * one process into one parent at once (two threads) wrote one file, and one read the other's
 * tire (its sweep then wrote the wrong tire.tir, status OK) while the other found it gone. */
static int tire_text(const char *dir, const tirenv_tire *tire, char **text, size_t *len,
                     tirenv_diag *diag)
{
    static atomic_uint serial;
    char path[1200];
    snprintf(path, sizeof path, "%s/.tire.tir.%ld.%u", dir, (long)getpid(),
             atomic_fetch_add(&serial, 1u));
    int status = tirenv_tir_write(path, tire, diag);
    if (!status)
        status = tirenv_sweep__read_text(path, TIRE_MAX, text, len, diag);
    unlink(path);
    return status;
}

/* Each case file a manifest's rows name, whole (tirenv_sweep__check_case). */
static int whole_cases(const char *dir, char **rows, size_t n_rows, tirenv_diag *diag)
{
    int status = TIRENV_OK;
    for (size_t j = 0; j < n_rows && !status; ++j) {
        const char *log = NULL, *curve = NULL;
        size_t log_len = 0, curve_len = 0;
        if (tirenv_sweep__row_files(rows[j], &log, &log_len, &curve, &curve_len) != 0)
            return tirenv_error(diag, TIRENV_EPARSE, dir, 0, "cases.csv",
                                "row %zu does not name its files as a sweep does", j + 1);
        char c_path[1200], l_path[1200];
        snprintf(c_path, sizeof c_path, "%s/%.*s", dir, (int)curve_len, curve);
        snprintf(l_path, sizeof l_path, "%s/%.*s", dir, (int)log_len, log);
        status = tirenv_sweep__check_case(c_path, log_len ? l_path : NULL,
                                          "in a sweep taken for complete",
                                          "remove the directory and run the sweep again, or "
                                          "copy it whole", diag);
    }
    return status;
}

/* A complete directory's tables hold every row of the sweep (shard), and its case files are
 * whole: a copy cut at a line end holds whole rows only, and would pass for this sweep,
 * complete, with cases missing or a curve short of its points. */
static int whole_tables(const char *dir, size_t m, size_t shard, size_t shards,
                        tirenv_diag *diag)
{
    static const char *const tables[] = {"cases.csv", "sweep.csv"};
    int status = TIRENV_OK;
    for (size_t t = 0; t < 2 && !status; ++t) {
        char path[1200];
        snprintf(path, sizeof path, "%s/%s", dir, tables[t]);
        char *text = NULL, **rows = NULL;
        size_t len = 0, head = 0, n_rows = 0;
        status = tirenv_sweep__read_text(path, TIRENV_SWEEP__TABLE_MAX, &text, &len, diag);
        if (!status)
            status = tirenv_sweep__split_table(text, len, path, &head, &rows, &n_rows, diag);
        if (!status)
            status = tirenv_sweep__check_rows(dir, tables[t], tirenv_sweep__lines(text, head),
                                              rows, n_rows, m, shard, shards, diag);
        if (!status && t == 0)
            status = whole_cases(dir, rows, n_rows, diag);
        free(rows);
        free(text);
    }
    return status;
}

int tirenv_sweep__target_state(const char *dir, const char *spec, const char *tire,
                               size_t tire_len, size_t m, size_t shard, size_t shards,
                               tirenv_diag *diag)
{
    struct stat st;
    if (stat(dir, &st) != 0)
        return errno == ENOENT ? 0
                               : -tirenv_error(diag, TIRENV_EIO, dir, 0, "", "cannot stat: %s",
                                               strerror(errno));
    if (!S_ISDIR(st.st_mode))
        return -tirenv_error(diag, TIRENV_EIO, dir, 0, "", "exists and is not a directory");
    char path[1200];
    snprintf(path, sizeof path, "%s/cases.csv", dir);
    const int complete = exists_regular(path);
    snprintf(path, sizeof path, "%s/sweep.txt", dir);
    int same = complete ? same_text(path, spec, strlen(spec), "the description", diag) : 0;
    if (same < 0)
        return same;
    snprintf(path, sizeof path, "%s/tire.tir", dir);
    if (same == 1 && (same = same_text(path, tire, tire_len, "the tire", diag)) < 0)
        return same;
    if (same == 1) {
        const int status = whole_tables(dir, m, shard, shards, diag);
        return status ? -status : 1;
    }
    DIR *d = opendir(dir);
    if (!d)
        return -tirenv_error(diag, TIRENV_EIO, dir, 0, "", "cannot read: %s", strerror(errno));
    struct dirent *e;
    int empty = 1;
    while (empty && (e = readdir(d)))
        empty = strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0;
    closedir(d);
    if (!empty)
        return -tirenv_error(diag, TIRENV_EIO, dir, 0, "",
                             "exists and is not this sweep, complete; remove it or choose "
                             "another output directory");
    return 0;
}

/* The partial directory, locked against a second run, checked to be this sweep's. */
static int open_partial(sweep_run *r, const char *spec, const char *tire, size_t tire_len,
                        int *lock_fd, tirenv_diag *diag)
{
    int status = tirenv_mkdir_p(r->dir, diag);
    if (status)
        return status;
    *lock_fd = open(r->dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (*lock_fd < 0)
        return tirenv_error(diag, TIRENV_EIO, r->dir, 0, "", "cannot open: %s",
                            strerror(errno));
    if (flock(*lock_fd, LOCK_EX | LOCK_NB) != 0)
        return tirenv_error(diag, TIRENV_EIO, r->dir, 0, "",
                            errno == EWOULDBLOCK ? "another tirenv sweep is writing it"
                                                 : "cannot lock: %s", strerror(errno));
    char path[1200];
    snprintf(path, sizeof path, "%s/sweep.txt", r->dir);
    int same = same_text(path, spec, strlen(spec), "the description", diag);
    if (same < 0)
        return -same;
    if (same == 0) {
        /* New (or killed before its description): nothing else may be in it yet but what a
         * run writes before the description. */
        if ((status = tidy(r, NULL, diag)))
            return status;
        if ((status = tirenv_sweep__write_text(path, spec, strlen(spec), diag)))
            return status;
    }
    snprintf(path, sizeof path, "%s/tire.tir", r->dir);
    if ((same = same_text(path, tire, tire_len, "the tire", diag)) < 0)
        return -same;
    if (same == 0 && (status = tirenv_sweep__write_text(path, tire, tire_len, diag)))
        return status;
    const char *subs[] = {"curves", "logs"};
    for (size_t k = 0; k < (r->s->rig ? 2u : 1u) && !status; ++k) {
        snprintf(path, sizeof path, "%s/%s", r->dir, subs[k]);
        status = tirenv_mkdir_p(path, diag);
    }
    for (size_t k = 0; k < 2 && !status; ++k)
        status = tidy(r, subs[k], diag);
    return status ? status : tidy(r, NULL, diag);
}

/* The cases of this shard not yet written. */
static int find_todo(sweep_run *r, tirenv_diag *diag)
{
    const size_t part = tirenv_dataset__shard_rows(r->n, r->s->shard, r->s->shards);
    r->todo = malloc((part ? part : 1) * sizeof *r->todo);
    if (!r->todo)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    char path[1200], log[1200];
    for (size_t i = r->s->shard; i < r->n; i += r->s->shards) {
        case_path(r, "curves", i, path, sizeof path);
        case_path(r, "logs", i, log, sizeof log);
        const int done = exists_regular(path) && (!r->s->rig || exists_regular(log));
        if (done) {
            const int status = tirenv_sweep__check_case(
                path, r->s->rig ? log : NULL, "kept from an interrupted run",
                "remove it and run the same command again to run that case", diag);
            if (status)
                return status;
            ++r->resumed;
        } else {
            r->todo[r->n_todo++] = i;
        }
    }
    return TIRENV_OK;
}

static int write_manifest(const sweep_run *r, tirenv_diag *diag)
{
    const tirenv_sweep_settings *s = r->s;
    char path[1200];
    snprintf(path, sizeof path, "%s/cases.csv", r->dir);
    char *comment = tirenv_sweep__manifest_comment(s, r->n);
    if (!comment)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    tirenv_outfile *f;
    int status = tirenv_outfile_open(&f, path, diag);
    if (status) {
        free(comment);
        return status;
    }
    FILE *fp = tirenv_outfile_stream(f);
    fputs("case,split,contact_length_m,load_N,obstacle_length_m,obstacle_height_m,log,curve\n",
          fp);
    tirenv_outfile_comment(f, comment);
    free(comment);
    for (size_t i = s->shard; i < r->n; i += s->shards) {
        tirenv_sweep__coords c;
        tirenv_sweep__coords_of(s, i, &c);
        const size_t p = c.variant * tirenv_sweep__regimes(s) + c.regime;
        char name[32], l_c[32], load[32], L[32], H[32];
        tirenv_sweep__case_name(s, i, name);
        tirenv_sweep__number(r->l_c[p], l_c);
        tirenv_sweep__number(r->load[p], load);
        tirenv_sweep__number(s->lengths[c.length], L);
        tirenv_sweep__number(s->heights[c.height], H);
        fprintf(fp, "%s,%s,%s,%s,%s,%s,", name,
                tirenv_split_name((tirenv_split)r->split[i]), l_c, load, L, H);
        if (s->rig)
            fprintf(fp, "logs/%s.csv", name);
        fprintf(fp, ",curves/%s.csv\n", name);
    }
    return tirenv_outfile_commit(f, diag);
}

/* sweep.csv: each case's tire variant and the values of the swept keys. */
static int write_keys(const sweep_run *r, tirenv_diag *diag)
{
    const tirenv_sweep_settings *s = r->s;
    char path[1200];
    snprintf(path, sizeof path, "%s/sweep.csv", r->dir);
    tirenv_outfile *f;
    int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    fputs("case,variant", fp);
    for (size_t k = 0; k < s->n_keys; ++k)
        fprintf(fp, ",%s", s->keys[k].key);
    fputc('\n', fp);
    tirenv_outfile_comment(f, "tirenv sweep: the tire-key values of each case (the tire: "
                               "tire.tir with these keys set)");
    for (size_t i = s->shard; i < r->n; i += s->shards) {
        tirenv_sweep__coords c;
        tirenv_sweep__coords_of(s, i, &c);
        char name[32], v[32];
        tirenv_sweep__case_name(s, i, name);
        fprintf(fp, "%s,%zu", name, c.variant);
        for (size_t k = 0; k < s->n_keys; ++k) {
            tirenv_sweep__number(s->keys[k].values[c.key_index[k]], v);
            fprintf(fp, ",%s", v);
        }
        fputc('\n', fp);
    }
    return tirenv_outfile_commit(f, diag);
}

static void run_free(sweep_run *r)
{
    free(r->split);
    free(r->pairs);
    free(r->load);
    free(r->l_c);
    free(r->todo);
}

int tirenv_sweep_run(const char *dir, const tirenv_tire *tire, const tirenv_sweep_settings *s,
                     tirenv_sweep_report *report, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    tirenv_sweep_report rep = {0};
    if (report)
        *report = rep;
    int status = tirenv_sweep_check(s, tire, diag);
    if (status)
        return status;
    if (!dir || !dir[0] || strlen(dir) > 900)
        return tirenv_error(diag, TIRENV_EINVAL, dir ? dir : "", 0, "dir",
                            "expected an output directory name of 1 to 900 characters");
    sweep_run r = {.s = s, .tire = tire, .n = tirenv_sweep_count(s)};
    snprintf(r.dir, sizeof r.dir, "%s.partial", dir);
    rep.cases = r.n;
    char *spec = tirenv_sweep__spec(s), *tire_s = NULL;
    size_t tire_len = 0;
    int lock_fd = -1;
    if (!spec)
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    /* The tire's text is written in the partial directory's parent, which must exist. */
    char parent[1024];
    snprintf(parent, sizeof parent, "%s", dir);
    char *slash = strrchr(parent, '/');
    if (slash == parent)
        parent[1] = '\0';
    else if (slash)
        *slash = '\0';
    else
        snprintf(parent, sizeof parent, ".");
    if (!status)
        status = tirenv_mkdir_p(parent, diag);
    if (!status)
        status = tire_text(parent, tire, &tire_s, &tire_len, diag);
    int state = status ? 0 : tirenv_sweep__target_state(dir, spec, tire_s, tire_len, r.n,
                                                                s->shard, s->shards, diag);
    if (state < 0)
        status = -state;
    if (!status && state == 1) {
        rep.already_complete = 1;
        rep.part_cases = tirenv_dataset__shard_rows(r.n, s->shard, s->shards);
        rep.resumed = rep.part_cases;
    } else if (!status) {
        status = open_partial(&r, spec, tire_s, tire_len, &lock_fd, diag);
        if (!status)
            status = tirenv_sweep__splits(s, &r.split, diag);
        if (!status)
            status = find_todo(&r, diag);
        rep.part_cases = r.resumed + r.n_todo;
        rep.resumed = r.resumed;
        if (!status && s->progress)
            s->progress(s->progress_ctx, r.resumed, rep.part_cases);
        if (!status)
            status = regime_table(&r, diag);
        if (!status)
            status = tirenv_parallel_for(r.n_todo, s->jobs, case_item, case_done, &r, diag);
        if (!status)
            rep.run = r.n_todo;
        if (!status)
            status = write_keys(&r, diag);
        if (!status)
            status = write_manifest(&r, diag);  /* last: with it, the part is whole */
        if (!status && rename(r.dir, dir) != 0)
            status = tirenv_error(diag, TIRENV_EIO, dir, 0, "",
                                  "cannot move the finished sweep %s into place: %s", r.dir,
                                  strerror(errno));
    }
    if (lock_fd >= 0)
        close(lock_fd);
    free(spec);
    free(tire_s);
    run_free(&r);
    if (report)
        *report = rep;
    return status;
}
