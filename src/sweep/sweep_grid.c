/* The sweep's grid (docs/formats.md section 13): which case is where, its name, its tire,
 * its split, and the description (sweep.txt) that a resumed run and a merge compare. Every
 * answer here is a function of the settings alone, so every shard of a sweep, on any node,
 * agrees on it. SPDX-License-Identifier: Apache-2.0 */
#include "sweep/sweep_impl.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "tirenv/outfile.h"
#include "tirenv/tir.h"
#include "io/io.h"

tirenv_sweep_settings tirenv_sweep_default(void)
{
    tirenv_sweep_settings s;
    memset(&s, 0, sizeof s);
    s.type = tirenv_model_ring;
    s.rig = 0;
    s.split = TIRENV_SPLIT_TRAIN;
    s.split_seed = 1;
    s.seed = 1;
    s.shard = 0;
    s.shards = 1;
    s.jobs = 1;
    return s;
}

size_t tirenv_sweep__variants(const tirenv_sweep_settings *s)
{
    size_t n = 1;
    for (size_t k = 0; k < s->n_keys; ++k) {
        if (s->keys[k].n == 0 || n > TIRENV_SWEEP__MAX_CASES / s->keys[k].n)
            return 0;
        n *= s->keys[k].n;
    }
    return n;
}

size_t tirenv_sweep__regimes(const tirenv_sweep_settings *s)
{
    return s->n_contact_lengths ? s->n_contact_lengths : s->n_loads;
}

size_t tirenv_sweep_count(const tirenv_sweep_settings *s)
{
    const size_t f[] = {tirenv_sweep__variants(s), tirenv_sweep__regimes(s), s->n_lengths,
                        s->n_heights};
    size_t n = 1;
    for (size_t k = 0; k < sizeof f / sizeof f[0]; ++k) {
        if (f[k] == 0 || n > TIRENV_SWEEP__MAX_CASES / f[k])
            return 0;
        n *= f[k];
    }
    return n;
}

/* Heights fastest, then lengths, regimes, and the tire keys (the last key fastest): a shard
 * taking every N-th case then gets a fair share of every kind. */
void tirenv_sweep__coords_of(const tirenv_sweep_settings *s, size_t i, tirenv_sweep__coords *c)
{
    c->height = i % s->n_heights;
    i /= s->n_heights;
    c->length = i % s->n_lengths;
    i /= s->n_lengths;
    c->regime = i % tirenv_sweep__regimes(s);
    i /= tirenv_sweep__regimes(s);
    c->variant = i;
    for (size_t k = s->n_keys; k-- > 0;) {
        c->key_index[k] = i % s->keys[k].n;
        i /= s->keys[k].n;
    }
}

void tirenv_sweep__case_name(const tirenv_sweep_settings *s, size_t i, char buf[32])
{
    tirenv_sweep__name_of(tirenv_sweep_count(s), i, buf);
}

void tirenv_sweep__name_of(size_t n, size_t i, char buf[32])
{
    int width = 1;
    for (size_t last = n > 0 ? n - 1 : 0; last >= 10; last /= 10)
        ++width;
    snprintf(buf, 32, "c%0*zu", width < 4 ? 4 : width, i);
}

void tirenv_sweep__number(double x, char buf[32])
{
    for (int digits = 15; digits <= 17; ++digits) {
        snprintf(buf, 32, "%.*g", digits, x);
        if (strtod(buf, NULL) == x)
            return;
    }
}

int tirenv_sweep__variant_tire(const tirenv_sweep_settings *s, const tirenv_tire *tire,
                               size_t v, tirenv_tire *out, tirenv_diag *diag)
{
    size_t index[TIRENV_SWEEP_MAX_KEYS];
    for (size_t k = s->n_keys; k-- > 0;) {
        index[k] = v % s->keys[k].n;
        v /= s->keys[k].n;
    }
    tirenv_tire t = *tire;
    for (size_t k = 0; k < s->n_keys; ++k) {
        const tirenv_sweep_axis *a = &s->keys[k];
        char assignment[160], value[32];
        tirenv_sweep__number(a->values[index[k]], value);
        snprintf(assignment, sizeof assignment, "%.120s=%s", a->key, value);
        const int status = tirenv_tir_set(&t, assignment, diag);
        if (status)
            return status;
    }
    const int status = tirenv_tire_check(&t, diag);
    if (status == TIRENV_OK)
        *out = t;
    return status;
}

/* splitmix64 (Steele, Lea and Flood 2014): a seeded stream whose every value is a function
 * of (seed, step) alone. */
static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += UINT64_C(0x9e3779b97f4a7c15));
    z = (z ^ (z >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94d049bb133111eb);
    return z ^ (z >> 31);
}

/* The split by exact counts: a seeded Fisher-Yates permutation of the whole grid, whose first
 * round(f_v n) cases are validation and next round(f_c n) control. Every shard computes the
 * same permutation, so a case's split does not depend on which part runs it. */
int tirenv_sweep__splits(const tirenv_sweep_settings *s, unsigned char **out,
                         tirenv_diag *diag)
{
    const size_t n = tirenv_sweep_count(s);
    unsigned char *split = malloc(n ? n : 1);
    if (!split)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for %zu cases", n);
    if (!(s->control_fraction > 0) && !(s->validation_fraction > 0)) {
        memset(split, (int)s->split, n);
        *out = split;
        return TIRENV_OK;
    }
    uint32_t *perm = malloc((n ? n : 1) * sizeof *perm);
    if (!perm) {
        free(split);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for %zu cases", n);
    }
    for (size_t i = 0; i < n; ++i)
        perm[i] = (uint32_t)i;
    uint64_t state = s->split_seed;
    for (size_t i = n; i > 1; --i) {
        const size_t j = (size_t)(splitmix64(&state) % i);
        const uint32_t t = perm[i - 1];
        perm[i - 1] = perm[j];
        perm[j] = t;
    }
    const size_t n_val = (size_t)floor(s->validation_fraction * (double)n + 0.5);
    size_t n_ctl = (size_t)floor(s->control_fraction * (double)n + 0.5);
    if (n_ctl > n - n_val)
        n_ctl = n - n_val;
    memset(split, TIRENV_SPLIT_TRAIN, n);
    for (size_t k = 0; k < n_val + n_ctl; ++k)
        split[perm[k]] = k < n_val ? TIRENV_SPLIT_VALIDATION : TIRENV_SPLIT_CONTROL;
    free(perm);
    *out = split;
    return TIRENV_OK;
}

/* ---- the checks ---------------------------------------------------------------------- */

/* Each value positive and below hi (up to hi, if up_to), said as hi_what, each once. */
static int check_list(const char *name, const double v[], size_t n, double hi, int up_to,
                      const char *hi_what, tirenv_diag *diag)
{
    if (n == 0 || !v)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, name, "expected at least one value");
    for (size_t k = 0; k < n; ++k) {
        if (!isfinite(v[k]) || !(v[k] > 0) || !(up_to ? v[k] <= hi : v[k] < hi))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, name,
                                "value %zu is %g; expected a positive number%s%s", k + 1,
                                v[k], hi_what ? (up_to ? " up to " : " below ") : "",
                                hi_what ? hi_what : "");
        for (size_t j = 0; j < k; ++j)
            if (v[j] == v[k])
                return tirenv_error(diag, TIRENV_EINVAL, "", 0, name,
                                    "%g is listed twice (values %zu and %zu)", v[k], j + 1,
                                    k + 1);
    }
    return TIRENV_OK;
}

int tirenv_sweep_check(const tirenv_sweep_settings *s, const tirenv_tire *tire,
                       tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    if (!s->type)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "model", "no model type");
    if ((tirenv_model_type_flags(s->type) & TIRENV_MODEL_NEEDS_NETWORK) && !s->network)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "network",
                            "the %s model needs a trained network", tirenv_model_type_name(s->type));
    const double R0 = tire->springs.R0;
    /* A cleat no longer than a road's segment (as envelope --cleat's): 1e308 became a profile
     * refused as "out of memory". */
    int status = check_list("lengths", s->lengths, s->n_lengths, TIRENV_PROFILE_MAX_SEGMENT, 1,
                            "1e7 m, a road's longest segment", diag);
    if (!status)
        status = check_list("heights", s->heights, s->n_heights, R0, 0, "the tire's radius",
                            diag);
    if (!status && (s->n_contact_lengths > 0) == (s->n_loads > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "regimes",
                            "expected either contact lengths or loads (one list), got %s",
                            s->n_loads ? "both" : "neither");
    if (!status && s->n_contact_lengths)
        status = check_list("contact_lengths", s->contact_lengths, s->n_contact_lengths,
                            2 * R0, 0, "twice the tire's radius", diag);
    if (!status && s->n_loads)
        status = check_list("loads", s->loads, s->n_loads, INFINITY, 0, NULL, diag);
    if (status)
        return status;
    /* A case's contact length is the model's at its load; the rigid disc and the point have
     * none (the network's is its file's law): refused before anything is written, where each
     * case failed after DIR.partial was made. */
    const unsigned flags = tirenv_model_type_flags(s->type);
    if (s->n_loads &&
        !(flags & (TIRENV_MODEL_CONTACT_LENGTH | TIRENV_MODEL_NEEDS_NETWORK)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "loads",
                            "the %s model has no contact length of its own at a load; expected "
                            "the regimes as contact lengths (--contact-lengths)",
                            tirenv_model_type_name(s->type));
    if (s->n_keys > TIRENV_SWEEP_MAX_KEYS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "keys", "%zu tire keys; at most %d",
                            s->n_keys, TIRENV_SWEEP_MAX_KEYS);
    for (size_t k = 0; k < s->n_keys; ++k) {
        const tirenv_sweep_axis *a = &s->keys[k];
        if (!a->key || !a->key[0] || strlen(a->key) > 120 || strpbrk(a->key, "=,\n"))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "keys",
                                "tire key %zu is not a key name", k + 1);
        for (size_t j = 0; j < k; ++j)
            if (strcasecmp(s->keys[j].key, a->key) == 0)
                return tirenv_error(diag, TIRENV_EINVAL, "", 0, a->key,
                                    "the key is swept twice; give its values in one list");
        if (a->n == 0 || !a->values)
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, a->key, "expected at least one "
                                "value");
        for (size_t m = 0; m < a->n; ++m) {
            for (size_t j = 0; j < m; ++j)
                if (a->values[j] == a->values[m])
                    return tirenv_error(diag, TIRENV_EINVAL, "", 0, a->key,
                                        "%g is listed twice (values %zu and %zu)",
                                        a->values[m], j + 1, m + 1);
            /* Each value on the tire as given: the key exists, takes a number, and the tire
             * it makes holds together. A refusal is the settings' (EINVAL, naming the key and
             * the value), not the --set parser's "malformed file" it is found by. */
            tirenv_tire t = *tire;
            char assignment[160], value[32];
            tirenv_sweep__number(a->values[m], value);
            snprintf(assignment, sizeof assignment, "%s=%s", a->key, value);
            if (!isfinite(a->values[m]))
                return tirenv_error(diag, TIRENV_EINVAL, "", 0, a->key,
                                    "value %zu is not finite", m + 1);
            tirenv_diag why;
            tirenv_diag_clear(&why);
            if (tirenv_tir_set(&t, assignment, &why) || tirenv_tire_check(&t, &why))
                return tirenv_error(diag, TIRENV_EINVAL, "", 0, a->key,
                                    "swept tire key %zu, value %zu (%s): %s%s%s", k + 1, m + 1,
                                    value, strcmp(why.field, a->key) ? why.field : "",
                                    strcmp(why.field, a->key) ? ": " : "", why.message);
        }
    }
    /* The cam's shape is never derived: a tire without its own would give every case another
     * tire's cam, as tirenv_dataset_build_design refuses it. A swept key counts as given,
     * since every case sets it: the first case's tire is checked. */
    if (s->type == tirenv_model_cam) {
        tirenv_tire first;
        if ((status = tirenv_sweep__variant_tire(s, tire, 0, &first, diag)) ||
            (status = tirenv_tire_check_cam_keys(&first, diag)))
            return status;
    }
    if (tirenv_sweep_count(s) == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "grid",
                            "the grid has more than %u cases", TIRENV_SWEEP__MAX_CASES);
    const double fc = s->control_fraction, fv = s->validation_fraction;
    if (!(fc >= 0 && fc <= 1) || !(fv >= 0 && fv <= 1) || !(fc + fv <= 1))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "fractions",
                            "control %g, validation %g; expected each in [0, 1], together "
                            "at most 1", fc, fv);
    if ((unsigned)s->split > TIRENV_SPLIT_VALIDATION)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "split", "unknown split %d",
                            (int)s->split);
    if (s->shards < 1 || s->shard >= s->shards)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "shard",
                            "shard %zu of %zu; expected 0 <= K < N", s->shard, s->shards);
    return TIRENV_OK;
}

/* ---- the description ----------------------------------------------------------------- */

static void list_line(FILE *fp, const char *name, const double v[], size_t n)
{
    char buf[32];
    fprintf(fp, "%s = ", name);
    for (size_t k = 0; k < n; ++k) {
        tirenv_sweep__number(v[k], buf);
        fprintf(fp, "%s%s", k ? "," : "", buf);
    }
    fputc('\n', fp);
}

char *tirenv_sweep__spec(const tirenv_sweep_settings *s)
{
    char *text = NULL, buf[32];
    size_t len = 0;
    FILE *fp = open_memstream(&text, &len);
    if (!fp)
        return NULL;
    fprintf(fp, "# tirenv sweep: the grid of this data set and how its cases were made\n"
                "# (docs/formats.md section 13). A resumed run and 'tirenv sweep merge' check\n"
                "# that they continue the same sweep. SIMULATED data, not measurements.\n");
    fprintf(fp, "format = tirenv-sweep 1\n");
    fprintf(fp, "model = %s\n", tirenv_model_type_name(s->type));
    fprintf(fp, "curves = %s\n", s->rig ? "rig" : "model");
    if (tirenv_model_type_flags(s->type) & TIRENV_MODEL_NEEDS_NETWORK)
        fprintf(fp, "network = %s\n", s->network_id && s->network_id[0] ? s->network_id
                                                                       : "(unnamed)");
    list_line(fp, "lengths_m", s->lengths, s->n_lengths);
    list_line(fp, "heights_m", s->heights, s->n_heights);
    if (s->n_contact_lengths)
        list_line(fp, "contact_lengths_m", s->contact_lengths, s->n_contact_lengths);
    else
        list_line(fp, "loads_N", s->loads, s->n_loads);
    for (size_t k = 0; k < s->n_keys; ++k) {
        char name[160];
        snprintf(name, sizeof name, "set %s", s->keys[k].key);
        list_line(fp, name, s->keys[k].values, s->keys[k].n);
    }
    if (s->control_fraction > 0 || s->validation_fraction > 0) {
        fprintf(fp, "split = permutation\n");
        tirenv_sweep__number(s->control_fraction, buf);
        fprintf(fp, "control_fraction = %s\n", buf);
        tirenv_sweep__number(s->validation_fraction, buf);
        fprintf(fp, "validation_fraction = %s\n", buf);
        fprintf(fp, "split_seed = %lu\n", s->split_seed);
    } else {
        fprintf(fp, "split = %s\n", tirenv_split_name(s->split));
    }
    if (s->rig)
        fprintf(fp, "rig_seed = %lu\n", s->seed);
    fprintf(fp, "cases = %zu\n", tirenv_sweep_count(s));
    if (s->shards > 1)
        fprintf(fp, "shard = %zu/%zu\n", s->shard, s->shards);
    if (fclose(fp) != 0) {
        free(text);
        return NULL;
    }
    return text;
}

int tirenv_sweep__spec_shard(const char *spec, size_t *shard, size_t *shards, size_t *begin,
                             size_t *end)
{
    const char *p = spec;
    while (p && *p) {
        const char *eol = strchr(p, '\n');
        const char *next = eol ? eol + 1 : p + strlen(p);
        if (strncmp(p, "shard = ", 8) == 0) {
            char *e1, *e2;
            errno = 0;
            const unsigned long k = strtoul(p + 8, &e1, 10);
            if (*e1 != '/')
                return -1;
            const unsigned long n = strtoul(e1 + 1, &e2, 10);
            if (errno || (e2 != eol && *e2) || n < 2 || k >= n)
                return -1;
            *shard = k;
            *shards = n;
            *begin = (size_t)(p - spec);
            *end = (size_t)(next - spec);
            return 1;
        }
        p = next;
    }
    return 0;
}

char *tirenv_sweep__manifest_comment(const tirenv_sweep_settings *s, size_t cases)
{
    char *text = NULL;
    size_t len = 0;
    FILE *fp = open_memstream(&text, &len);
    if (!fp)
        return NULL;
    fprintf(fp, "SIMULATED data set: %zu cleat cases of tirenv sweep, the %s model's curves ",
            cases, tirenv_model_type_name(s->type));
    if (s->rig)
        fprintf(fp, "from the virtual rig\n(noisy logs in logs/, imported to curves/)");
    else
        fprintf(fp, "on the x_N grid\n(curves/, no rig)");
    fprintf(fp, ", not measurements of a real tire. The grid: sweep.txt; the tire:\ntire.tir; "
                "its swept keys per case: sweep.csv.");
    if (fclose(fp) != 0) {
        free(text);
        return NULL;
    }
    return text;
}

/* ---- whole files ------------------------------------------------------------------------ */

int tirenv_sweep__read_text(const char *path, size_t max, char **out, size_t *n,
                            tirenv_diag *diag)
{
    *out = NULL;
    *n = 0;
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot open: %s", strerror(errno));
    /* The buffer grows with what is read, up to max + 1 bytes: the limit is a refusal, not an
     * allocation (sweep merge's 1 GiB limit per table, allocated whole, cost seconds per part
     * under AddressSanitizer, which poisons the shadow of a large block whole, and reserved
     * that much address space in every build). */
    size_t cap = max + 1 < 65536 ? max + 1 : 65536, got = 0;
    char *buf = malloc(cap);
    int failed = 0;
    while (buf) {
        got += fread(buf + got, 1, cap - got, fp);
        if ((failed = ferror(fp)) || got < cap || cap == max + 1)
            break;
        const size_t grown = cap > (max + 1) / 2 ? max + 1 : 2 * cap;
        char *more = realloc(buf, grown);
        if (!more) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = more;
        cap = grown;
    }
    fclose(fp);
    if (!buf)
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    if (failed || got > max) {
        free(buf);
        return tirenv_error(diag, TIRENV_EIO, path, 0, "",
                            failed ? "cannot read" : "longer than %zu bytes", max);
    }
    buf[got] = '\0';
    *out = buf;
    *n = got;
    return TIRENV_OK;
}

int tirenv_sweep__write_text(const char *path, const char *text, size_t len,
                             tirenv_diag *diag)
{
    tirenv_outfile *f;
    int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    fwrite(text, 1, len, tirenv_outfile_stream(f));
    return tirenv_outfile_commit(f, diag);
}
