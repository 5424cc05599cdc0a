/* The property-file engine's writing side: a key's value as text (tirenv_propfile__get) and
 * a whole struct written as a file, every key with its comment (tirenv_propfile__write), in
 * the syntax propfile.c reads back. SPDX-License-Identifier: Apache-2.0 */
#include "formats/propfile.h"
#include "formats/propfile_impl.h"

#include "tirenv/outfile.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef tirenv_propfile__key pf_key;
typedef tirenv_propfile__schema pf_schema;

/* The shortest "%.*g" that reads back to the same double. Precision 17 always does, but
 * 0.68 then comes out as 0.68000000000000005, which a reader would take for a bug. */
static void pf_format_real(char *buf, size_t n, double v)
{
    for (int prec = 1; prec < 17; prec++) {
        snprintf(buf, n, "%.*g", prec, v);
        if (strtod(buf, NULL) == v)
            return;
    }
    snprintf(buf, n, "%.17g", v);
}

/* The text of a REAL or COUNT key's value at field (the shortest that reads back the same;
 * the count in decimal); 0 for any other kind, whose text its caller writes. */
static int pf_number_text(const pf_key *e, const unsigned char *field, char *value, size_t n)
{
    if (e->kind == TIRENV_PROPFILE_REAL) {
        double v;
        memcpy(&v, field, sizeof v);
        pf_format_real(value, n, v);
        return 1;
    }
    if (e->kind == TIRENV_PROPFILE_COUNT) {
        size_t v;
        memcpy(&v, field, sizeof v);
        snprintf(value, n, "%zu", v);
        return 1;
    }
    return 0;
}

int tirenv_propfile__get(const pf_schema *s, const void *obj, const char *field, char *buf,
                         size_t n, tirenv_propfile__kind *kind, tirenv_diag *diag)
{
    char name[sizeof ((tirenv_diag *)NULL)->field], list[1024];
    snprintf(name, sizeof name, "%s", field ? field : "");
    char *dot = strchr(name, '.');
    size_t matches = 0, i;
    if (dot) {
        *dot = '\0';
        i = tirenv_propfile__find_key(s, name, dot + 1, 1, &matches);
        *dot = '.';
    } else {
        i = tirenv_propfile__find_key(s, NULL, name, 1, &matches);
    }
    if (i == s->n_keys)
        return tirenv_error(diag, TIRENV_EINVAL, "get", 0, name, "no such key; expected one of "
                            "%s", tirenv_propfile__key_list(s, NULL, list, sizeof list));
    if (matches > 1)
        return tirenv_error(diag, TIRENV_EINVAL, "get", 0, name, "the key is in %zu sections: "
                            "name it as SECTION.KEY", matches);
    const pf_key *e = &s->keys[i];
    const unsigned char *at = (const unsigned char *)obj + e->offset;
    char value[1100];
    if (pf_number_text(e, at, value, sizeof value)) {
    } else if (e->kind == TIRENV_PROPFILE_NAME) {
        int v;
        memcpy(&v, at, sizeof v);
        const int known = v >= 0 && v < (int)(sizeof e->names / sizeof e->names[0]) &&
                          e->names[v];
        snprintf(value, sizeof value, "%s", known ? e->names[v] : "");
    } else { /* PATH (UNIT keys are not found as settable) */
        snprintf(value, sizeof value, "%.*s", (int)(e->size ? e->size - 1 : 0),
                 (const char *)at);
    }
    if (!buf || strlen(value) >= n)
        return tirenv_error(diag, TIRENV_EINVAL, "get", 0, name, "the value takes %zu bytes; "
                            "the buffer holds %zu", strlen(value) + 1, buf ? n : 0);
    memcpy(buf, value, strlen(value) + 1);
    if (kind)
        *kind = e->kind;
    return TIRENV_OK;
}

/* The name a write error gives a key: SECTION.KEY if the key is in several sections. */
static const char *pf_key_name(const pf_schema *s, const pf_key *e, char *buf, size_t n)
{
    size_t matches = 0;
    tirenv_propfile__find_key(s, NULL, e->key, 1, &matches);
    if (matches > 1)
        snprintf(buf, n, "%s.%s", e->section, e->key);
    else
        snprintf(buf, n, "%s", e->key);
    return buf;
}

/* A path cannot hold a quote: the format has no escapes. cwd is the prefix that makes a
 * relative path absolute, "" if it is to stay relative. */
static int pf_check_paths(const pf_schema *s, const void *obj, const char *path, char *cwd,
                          size_t n, tirenv_diag *diag)
{
    cwd[0] = '\0';
    for (size_t i = 0; i < s->n_keys; i++) {
        const pf_key *e = &s->keys[i];
        if (e->kind != TIRENV_PROPFILE_PATH)
            continue;
        const char *value = (const char *)obj + e->offset;
        char name[128];
        if (!memchr(value, '\0', e->size))
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, pf_key_name(s, e, name, sizeof name),
                                "path is not terminated within its %zu bytes", e->size);
        if (strpbrk(value, "'\n\r"))
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, pf_key_name(s, e, name, sizeof name),
                                "path '%.60s' holds a quote or a line break, which the file "
                                "format cannot hold", value);
        if (value[0] && value[0] != '/' && strchr(path, '/') && !cwd[0]) {
            if (!getcwd(cwd, n - 1))
                return tirenv_error(diag, TIRENV_EIO, path, 0,
                                    pf_key_name(s, e, name, sizeof name),
                                    "cannot find the working directory to write the relative "
                                    "path '%.60s' as an absolute one: %s", value,
                                    strerror(errno));
            strcat(cwd, "/");
        }
    }
    return TIRENV_OK;
}

static void pf_print(const pf_schema *s, FILE *fp, const void *obj, const char *cwd,
                     const char *header)
{
    if (header)
        fputs(header, fp);
    else if (s->preamble)
        s->preamble(fp);
    for (size_t k = 0; k < s->n_sections; k++) {
        const char *name = s->sections[k].name;
        fprintf(fp, "$----------------------------------------------------------------%s\n"
                    "[%s]\n", name, name);
        for (size_t i = 0; i < s->n_keys; i++) {
            const pf_key *e = &s->keys[i];
            if (strcmp(e->section, name) != 0)
                continue;
            const unsigned char *field = (const unsigned char *)obj + e->offset;
            if ((e->omit_zero || e->omit_nan) && e->kind == TIRENV_PROPFILE_REAL) {
                double v;
                memcpy(&v, field, sizeof v);
                if ((e->omit_zero && v == 0) || (e->omit_nan && isnan(v)))
                    continue;
            }
            char value[40];
            if (!pf_number_text(e, field, value, sizeof value)) {
                switch ((int)e->kind) {
                case TIRENV_PROPFILE_NAME: {
                    int v;
                    memcpy(&v, field, sizeof v);
                    if (v >= 0 && v < (int)(sizeof e->names / sizeof e->names[0]) && e->names[v])
                        snprintf(value, sizeof value, "'%s'", e->names[v]);
                    else
                        snprintf(value, sizeof value, "%d", v); /* unreadable, as it should be */
                    break;
                }
                case TIRENV_PROPFILE_UNIT:
                    snprintf(value, sizeof value, "'%s'", e->names[0]);
                    break;
                case TIRENV_PROPFILE_PATH: {
                    /* Too long for value[]: printed here, padded as %-22s would. */
                    const char *p = (const char *)field;
                    const char *prefix = p[0] && p[0] != '/' ? cwd : "";
                    fprintf(fp, "%-24s = ", e->key);
                    const int w = fprintf(fp, "'%s%s'", prefix, p);
                    fprintf(fp, "%*s $ %s\n", w < 22 ? 22 - w : 0, "", e->comment);
                    continue;
                }
                }
            }
            fprintf(fp, "%-24s = %-22s $ %s\n", e->key, value, e->comment);
        }
    }
}

/* A struct that fails the check is refused: its file could not be read back. */
int tirenv_propfile__write(const pf_schema *s, const char *path, const void *obj,
                           tirenv_diag *diag)
{
    return tirenv_propfile__write_headed(s, path, obj, NULL, diag);
}

int tirenv_propfile__write_headed(const pf_schema *s, const char *path, const void *obj,
                                  const char *header, tirenv_diag *diag)
{
    int status = s->check ? s->check(obj, diag) : TIRENV_OK;
    if (status != TIRENV_OK)
        return status;
    char cwd[4096];
    status = pf_check_paths(s, obj, path, cwd, sizeof cwd, diag);
    if (status != TIRENV_OK)
        return status;
    tirenv_outfile *f;
    status = tirenv_outfile_open(&f, path, diag);
    if (status != TIRENV_OK)
        return status;
    pf_print(s, tirenv_outfile_stream(f), obj, cwd, header);
    return tirenv_outfile_commit(f, diag);
}
