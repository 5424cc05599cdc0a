/* A data set's source.txt: what simulated its curves and with which tire (docs/formats.md
 * section 9), so that a study compares the right reference model with the right tire.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/dataset.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dataset/dataset_impl.h"
#include "io/io.h"
#include "tirenv/model.h"

#define FORMAT "tirenv-dataset 1"

/* Blanks off both ends, in place. */
static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t')
        ++s;
    size_t n = strlen(s);
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t'))
        s[--n] = '\0';
    return s;
}

/* A text value into a field of its size; "" is refused (a key given must say something). */
static int store(const tirenv_csv__reader *r, size_t column, const char *key, const char *value,
                 char *out, size_t size)
{
    if (!value[0])
        return tirenv_csv__fail(r, column, key, "expected a value after '='");
    if (strlen(value) >= size)
        return tirenv_csv__fail(r, column, key, "at most %zu characters, got %zu", size - 1,
                                strlen(value));
    memcpy(out, value, strlen(value) + 1);
    return TIRENV_OK;
}

/* The manifest's number of cases: digits alone (no sign, no exponent), 1 to the most a
 * manifest holds, so that a typo cannot declare a count no manifest could meet. */
static int parse_cases(const tirenv_csv__reader *r, size_t column, const char *value,
                       size_t *out)
{
    const size_t digits = strspn(value, "0123456789");
    const unsigned long cases = digits && digits <= 7 && !value[digits]
                                    ? strtoul(value, NULL, 10) : 0;
    if (cases < 1 || cases > TIRENV_DATASET__MAX_CASES)
        return tirenv_csv__fail(r, column, "cases", "expected the number of cases of the "
                                                    "manifest, a whole number from 1 to %u, "
                                                    "got '%.60s'", TIRENV_DATASET__MAX_CASES,
                                value);
    *out = cases;
    return TIRENV_OK;
}

static int parse_line(tirenv_csv__reader *r, const char *dir, tirenv_dataset_source *out,
                      unsigned *seen)
{
    static const char *const keys[] = {"format", "design", "model", "tire", "cases"};
    char *eq = strchr(r->text, '=');
    if (!eq)
        return tirenv_csv__fail(r, 1, "", "expected 'key = value' (keys format, design, model, "
                                          "tire, cases)");
    *eq = '\0';
    const char *key = trim(r->text);
    char *value = trim(eq + 1);
    const size_t column = (size_t)(value - r->text) + 1;
    size_t k = 0;
    while (k < sizeof keys / sizeof keys[0] && strcmp(key, keys[k]) != 0)
        ++k;
    if (k == sizeof keys / sizeof keys[0])
        return tirenv_csv__fail(r, 1, key, "unknown key; expected format, design, model, "
                                           "tire or cases");
    if (*seen & (1u << k))
        return tirenv_csv__fail(r, 1, key, "given twice");
    *seen |= 1u << k;
    switch (k) {
    case 0:
        if (strcmp(value, FORMAT) != 0)
            return tirenv_csv__fail(r, column, key, "expected '" FORMAT "', got '%.60s'",
                                    value);
        return TIRENV_OK;
    case 1:
        return store(r, column, key, value, out->design, sizeof out->design);
    case 2: {
        const tirenv_model_type *type = tirenv_model_type_find(value);
        if (!type || (tirenv_model_type_flags(type) & TIRENV_MODEL_NEEDS_NETWORK))
            return tirenv_csv__fail(r, column, key, "expected the physical model that "
                                                    "simulated the data (ring, cam, springs, "
                                                    "rigid), got '%.60s'", value);
        return store(r, column, key, value, out->model, sizeof out->model);
    }
    case 4:
        out->cases_line = r->line;
        return parse_cases(r, column, value, &out->cases);
    default: {
        char path[sizeof out->tire + 1];
        const int w = value[0] == '/' ? snprintf(path, sizeof path, "%s", value)
                                      : snprintf(path, sizeof path, "%s/%s", dir, value);
        if (w < 0 || (size_t)w >= sizeof out->tire)
            return tirenv_csv__fail(r, column, key, "the path is longer than %zu characters "
                                                    "with the directory", sizeof out->tire - 1);
        return store(r, column, key, path, out->tire, sizeof out->tire);
    }
    }
}

/* A sweep's directory has no source.txt: its sweep.txt says what simulated every case, and
 * with no tire key set, with the tire it wrote beside it. */
static int sweep_source(const char *dir, tirenv_dataset_source *out, tirenv_diag *diag)
{
    tirenv_dataset__declared d;
    const int status = tirenv_dataset__sweep_declared(dir, &d, diag);
    if (status || !d.model[0])
        return status;
    snprintf(out->sweep_model, sizeof out->sweep_model, "%s", d.model);
    snprintf(out->sweep_key, sizeof out->sweep_key, "%s", d.key);
    out->sweep_key_line = d.key_line;
    out->sweep_raw = d.raw;
    const tirenv_model_type *type = tirenv_model_type_find(d.model);
    if (d.key[0] || !type || (tirenv_model_type_flags(type) & TIRENV_MODEL_NEEDS_NETWORK))
        return TIRENV_OK;  /* simulated, but not by one physical model of one tire */
    snprintf(out->model, sizeof out->model, "%s", d.model);
    char tire[sizeof out->tire + 1];
    const int w = snprintf(tire, sizeof tire, "%s/tire.tir", dir);
    if (w > 0 && (size_t)w < sizeof out->tire && access(tire, F_OK) == 0)
        memcpy(out->tire, tire, (size_t)w + 1);
    return TIRENV_OK;
}

int tirenv_dataset_source_read(const char *dir, tirenv_dataset_source *out, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    memset(out, 0, sizeof *out);
    char path[1024];
    const int w = snprintf(path, sizeof path, "%s/source.txt", dir ? dir : "");
    if (!dir || !dir[0] || w < 0 || (size_t)w >= sizeof path)
        return tirenv_error(diag, TIRENV_EINVAL, dir ? dir : "", 0, "",
                            "expected a data-set directory name of 1 to %zu characters",
                            sizeof path - 12);
    if (access(path, F_OK) != 0 && errno == ENOENT)
        return sweep_source(dir, out, diag);  /* a sweep's, or nothing: measured, or unknown */
    int status = tirenv_dataset__refuse_pipe(path, diag);
    if (status)
        return status;
    tirenv_csv__reader r;
    status = tirenv_csv__open(&r, path, diag);
    unsigned seen = 0;
    int more = 0;
    while (!status && (more = tirenv_csv__next(&r)) > 0)
        status = parse_line(&r, dir, out, &seen);
    if (!status && more < 0)
        status = -more;
    if (!status && !(seen & 1u))
        status = tirenv_error(diag, TIRENV_EPARSE, path, r.line, "format",
                              "missing; expected 'format = " FORMAT "'");
    tirenv_csv__close(&r);
    if (status)
        memset(out, 0, sizeof *out);
    else
        out->present = 1;
    return status;
}
