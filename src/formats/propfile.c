/* The property-file engine: the .tir syntax ([SECTION]s of KEY = value, '$' and '!'
 * comments) read and overridden for any struct described by a key table; propfile_write.c
 * writes it.
 * SPDX-License-Identifier: Apache-2.0 */
#include "formats/propfile.h"
#include "formats/propfile_impl.h"
#include "io/io.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

typedef tirenv_propfile__key pf_key;
typedef tirenv_propfile__section pf_section;
typedef tirenv_propfile__schema pf_schema;

/* Where the text being parsed came from (file is the path, or "--set" with line 0), the
 * file's directory for relative paths, and its [UNITS]. */
typedef struct {
    tirenv_propfile__where at;
    size_t dir_len;   /* length of file's directory part with its '/', 0 if none or --set */
    double *factor;   /* the file's [UNITS]: factor to SI per quantity; NULL for --set */
} pf_ctx;

/* Records a parse error; 'at' points into the line at the offending character. */
#define pf_fail(c, ...) tirenv_propfile__fail(&(c)->at, __VA_ARGS__)

int tirenv_propfile__fail(const tirenv_propfile__where *w, const char *at, const char *field,
                          const char *fmt, ...)
{
    char msg[sizeof ((tirenv_diag *)NULL)->message];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    const int status = tirenv_error(w->diag, TIRENV_EPARSE, w->file, w->line, field, "%s", msg);
    if (w->diag && w->base && at)
        w->diag->column = (size_t)(at - w->base) + 1;
    return status;
}

char *tirenv_propfile__trim(char *s)
{
    while (isspace((unsigned char)*s))
        s++;
    size_t n = strlen(s);
    while (n > 0 && isspace((unsigned char)s[n - 1]))
        s[--n] = '\0';
    return s;
}

/* '$' starts a comment anywhere, except inside a quoted string. */
static void pf_strip_comment(char *s)
{
    int quoted = 0;
    for (; *s; s++) {
        if (*s == '\'')
            quoted = !quoted;
        else if (*s == '$' && !quoted) {
            *s = '\0';
            return;
        }
    }
}

/* Appends one item of a list to buf, so that the list reads "A", "A or B", "A, B or C". */
static void pf_list_item(char *buf, size_t n, size_t *k, size_t index, int last,
                         const char *item, const char *quote_open, const char *quote_close)
{
    if (*k >= n)
        return;
    const char *sep = index == 0 ? "" : last ? " or " : ", ";
    const int r = snprintf(buf + *k, n - *k, "%s%s%s%s", sep, quote_open, item, quote_close);
    *k += r > 0 ? (size_t)r : 0;
}

/* "'a', 'b' or 'c'": the names a NAME or UNIT key accepts. */
static const char *pf_name_list(const pf_key *e, char *buf, size_t n)
{
    const size_t max = sizeof e->names / sizeof e->names[0];
    size_t count = 0, k = 0;
    while (count < max && e->names[count])
        count++;
    buf[0] = '\0';
    for (size_t i = 0; i < count; i++)
        pf_list_item(buf, n, &k, i, i + 1 == count, e->names[i], "'", "'");
    return buf;
}

static int pf_is_own_section(const pf_schema *s, const char *name)
{
    return strncasecmp(name, s->own_prefix, strlen(s->own_prefix)) == 0;
}

/* "[A], [B] or [C]": the sections of this format that an unknown own section may mean. */
static const char *pf_section_list(const pf_schema *s, char *buf, size_t n)
{
    size_t count = 0, k = 0, index = 0;
    for (size_t i = 0; i < s->n_sections; i++)
        count += (size_t)pf_is_own_section(s, s->sections[i].name);
    buf[0] = '\0';
    for (size_t i = 0; i < s->n_sections; i++)
        if (pf_is_own_section(s, s->sections[i].name)) {
            pf_list_item(buf, n, &k, index, index + 1 == count, s->sections[i].name, "[", "]");
            index++;
        }
    return buf;
}

static const pf_section *pf_find_section(const pf_schema *s, const char *name)
{
    for (size_t i = 0; i < s->n_sections; i++)
        if (strcasecmp(s->sections[i].name, name) == 0)
            return &s->sections[i];
    return NULL;
}

/* The index of the first matching key in s->keys, or s->n_keys. section NULL matches any
 * section; settable leaves out the [UNITS] keys (MASS is both a unit and a vehicle key).
 * *matches, if not NULL, counts the keys that match. */
size_t tirenv_propfile__find_key(const pf_schema *s, const char *section, const char *key,
                                 int settable, size_t *matches)
{
    size_t first = s->n_keys, count = 0;
    for (size_t i = 0; i < s->n_keys; i++) {
        const pf_key *e = &s->keys[i];
        if ((!section || strcasecmp(e->section, section) == 0) &&
            strcasecmp(e->key, key) == 0 && !(settable && e->kind == TIRENV_PROPFILE_UNIT)) {
            if (count++ == 0)
                first = i;
        }
    }
    if (matches)
        *matches = count;
    return first;
}

/* The key a check names: "KEY" or "SECTION.KEY"; s->n_keys if none. */
static size_t pf_find_field(const pf_schema *s, const char *field)
{
    char buf[sizeof ((tirenv_diag *)NULL)->field];
    snprintf(buf, sizeof buf, "%s", field);
    char *dot = strchr(buf, '.');
    if (!dot)
        return tirenv_propfile__find_key(s, NULL, buf, 1, NULL);
    *dot = '\0';
    return tirenv_propfile__find_key(s, buf, dot + 1, 1, NULL);
}

/* "A, B, C": the keys of one section, or every settable key (each name once) if section is
 * NULL. */
const char *tirenv_propfile__key_list(const pf_schema *s, const char *section, char *buf,
                                      size_t n)
{
    size_t k = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < s->n_keys && k < n; i++) {
        const pf_key *e = &s->keys[i];
        if (section ? strcmp(e->section, section) != 0 : e->kind == TIRENV_PROPFILE_UNIT)
            continue;
        if (!section && tirenv_propfile__find_key(s, NULL, e->key, 1, NULL) != i)
            continue; /* listed already, from an earlier section */
        const int r = snprintf(buf + k, n - k, "%s%s", k ? ", " : "", e->key);
        k += r > 0 ? (size_t)r : 0;
    }
    return buf;
}

int tirenv_propfile__real(const tirenv_propfile__where *w, const char *key, const char *text,
                          double *out)
{
    char *end;
    const double v = strtod(text, &end);
    if (end == text)
        return tirenv_propfile__fail(w, text, key, "expected a number, got '%.60s'", text);
    if (*end) {
        const char *junk = end + strspn(end, " \t");
        return tirenv_propfile__fail(w, junk, key, "unexpected '%.60s' after the number %.*s; "
                                     "expected only a number", junk, (int)(end - text), text);
    }
    if (!isfinite(v))
        return tirenv_propfile__fail(w, text, key, "expected a finite number, got '%.60s'",
                                     text);
    *out = v;
    return TIRENV_OK;
}

static int pf_parse_count(const pf_ctx *c, const pf_key *e, const char *text, size_t *out)
{
    /* strtoull would accept "-3" as a huge count; insist on digits first. */
    if (!isdigit((unsigned char)text[0]))
        return pf_fail(c, text, e->key, "expected a positive integer, got '%.60s'", text);
    char *end;
    errno = 0;
    const unsigned long long v = strtoull(text, &end, 10);
    if (*end) {
        const char *junk = end + strspn(end, " \t");
        return pf_fail(c, junk, e->key, "unexpected '%.60s' after %.*s; expected a positive "
                       "integer", junk, (int)(end - text), text);
    }
    if (errno == ERANGE || v > SIZE_MAX || v == 0)
        return pf_fail(c, text, e->key, "expected a positive integer, got '%.60s'", text);
    *out = (size_t)v;
    return TIRENV_OK;
}

/* A path read from a file is relative to that file, as an #include is: a vehicle file and
 * the tire files it names then move together. It is stored relative to the working
 * directory, which is what fopen wants. */
static int pf_parse_path(const pf_ctx *c, const pf_key *e, const char *text, char *out)
{
    const size_t dir = text[0] && text[0] != '/' ? c->dir_len : 0;
    const size_t n = dir + strlen(text);
    if (n >= e->size)
        return pf_fail(c, text, e->key, "path of %zu characters%s is too long; expected at "
                       "most %zu", n, dir ? " (with the file's directory before it)" : "",
                       e->size - 1);
    memcpy(out, c->at.file, dir);
    memcpy(out + dir, text, n - dir + 1);
    return TIRENV_OK;
}

static int pf_is_number(tirenv_propfile__kind kind)
{
    return kind == TIRENV_PROPFILE_REAL || kind == TIRENV_PROPFILE_COUNT;
}

/* Parses value (trimmed, comment removed, in place) for key e and stores it in obj. */
static int pf_apply(const pf_ctx *c, const pf_key *e, char *value, void *obj)
{
    if (!*value)
        return pf_fail(c, value, e->key, "missing value after '='; expected %s",
                       pf_is_number(e->kind) ? "a number"
                       : e->kind == TIRENV_PROPFILE_PATH ? "a path in quotes" : "a name");
    int quoted = 0;
    if (value[0] == '\'') {
        char *close = strchr(value + 1, '\'');
        if (!close)
            return pf_fail(c, value, e->key, "unterminated string; expected a closing '");
        if (close[1])
            return pf_fail(c, close + 1, e->key, "unexpected '%.60s' after the string",
                           close + 1);
        *close = '\0';
        value++;
        quoted = 1;
    }
    if (quoted && pf_is_number(e->kind))
        return pf_fail(c, value - 1, e->key, "expected a number, got the string '%.60s'",
                       value);
    unsigned char *field = (unsigned char *)obj + e->offset;
    char names[128];
    switch (e->kind) {
    case TIRENV_PROPFILE_REAL: {
        double v = 0;
        const int status = tirenv_propfile__real(&c->at, e->key, value, &v);
        if (status == TIRENV_OK)
            memcpy(field, &v, sizeof v);
        return status;
    }
    case TIRENV_PROPFILE_COUNT: {
        size_t v = 0;
        const int status = pf_parse_count(c, e, value, &v);
        if (status == TIRENV_OK)
            memcpy(field, &v, sizeof v);
        return status;
    }
    case TIRENV_PROPFILE_NAME:
        for (int m = 0; m < (int)(sizeof e->names / sizeof e->names[0]) && e->names[m]; m++)
            if (strcasecmp(value, e->names[m]) == 0) {
                memcpy(field, &m, sizeof m);
                return TIRENV_OK;
            }
        return pf_fail(c, value, e->key, "unknown %s '%.60s'; expected %s", e->noun, value,
                       pf_name_list(e, names, sizeof names));
    case TIRENV_PROPFILE_UNIT:
        if (e->converts) {
            double f;
            char list[512];
            if (tirenv_units__factor(e->unit, value, &f) != TIRENV_OK)
                return pf_fail(c, value, e->key, "unknown unit '%.60s'; expected one of %s",
                               value, tirenv_units__list(e->unit, list, sizeof list));
            if (c->factor)
                c->factor[e->unit] = f;
            return TIRENV_OK;
        }
        for (size_t a = 0; a < sizeof e->names / sizeof e->names[0] && e->names[a]; a++)
            if (strcasecmp(value, e->names[a]) == 0)
                return TIRENV_OK;
        return pf_fail(c, value, e->key, "unit '%.60s' is not supported (tirenv reads SI "
                       "only); expected %s", value, pf_name_list(e, names, sizeof names));
    case TIRENV_PROPFILE_PATH:
        return pf_parse_path(c, e, value, (char *)field);
    }
    return pf_fail(c, value, e->key, "internal error: unknown key kind");
}

/* Runs the format's physical check and points its error at the line where the offending key
 * was set (line 0 if the value did not come from this file, or seen is NULL). */
static int pf_check(const pf_schema *s, const void *obj, const char *file, const size_t seen[],
                    tirenv_diag *diag)
{
    if (!s->check)
        return TIRENV_OK;
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const int status = s->check(obj, &d);
    if (status == TIRENV_OK)
        return TIRENV_OK;
    const size_t i = pf_find_field(s, d.field);
    return tirenv_error(diag, status, file, seen && i < s->n_keys ? seen[i] : 0, d.field, "%s",
                        d.message);
}

/* Handles a "[SECTION]" line; *sec becomes the section, or NULL if it is to be skipped. */
static int pf_section_line(const pf_schema *s, const pf_ctx *c, char *open,
                           const pf_section **sec)
{
    pf_strip_comment(open);
    char *close = strchr(open, ']');
    if (!close)
        return pf_fail(c, open, "", "unterminated section header; expected ']'");
    char *rest = tirenv_propfile__trim(close + 1);
    if (*rest)
        return pf_fail(c, rest, "", "unexpected '%.60s' after the section header", rest);
    *close = '\0';
    const char *name = tirenv_propfile__trim(open + 1);
    if (!*name)
        return pf_fail(c, open, "", "empty section name; expected [NAME]");
    *sec = pf_find_section(s, name);
    if (!*sec && pf_is_own_section(s, name)) {
        char list[256];
        return pf_fail(c, open + 1, name, "unknown section [%.60s]; expected %s", name,
                       pf_section_list(s, list, sizeof list));
    }
    return TIRENV_OK;
}

/* Handles a "KEY = value" line inside section sec. */
static int pf_key_line(const pf_schema *s, const pf_ctx *c, char *text, const pf_section *sec,
                       void *obj, size_t seen[])
{
    pf_strip_comment(text);
    char *eq = strchr(text, '=');
    if (!eq) {
        char *gap = text + strcspn(text, " \t");
        const char saved = *gap;
        *gap = '\0';
        const int status = pf_fail(c, gap, text, "missing '='; expected KEY = value");
        *gap = saved;
        return status;
    }
    *eq = '\0';
    const char *key = tirenv_propfile__trim(text);
    char *value = tirenv_propfile__trim(eq + 1);
    if (!*key)
        return pf_fail(c, eq, "", "missing key before '='; expected KEY = value");
    const size_t i = tirenv_propfile__find_key(s, sec->name, key, 0, NULL);
    if (i == s->n_keys) {
        /* A key this format reads elsewhere would be skipped here without a word. */
        const size_t other = tirenv_propfile__find_key(s, NULL, key, 1, NULL);
        if (other < s->n_keys)
            return pf_fail(c, key, s->keys[other].key, "key of [%s] in [%s]; expected it in "
                           "[%s], where it is read", s->keys[other].section, sec->name,
                           s->keys[other].section);
        if (!sec->strict)
            return TIRENV_OK;
        char keys[256];
        return pf_fail(c, key, key, "unknown key in [%s]; expected one of %s", sec->name,
                       tirenv_propfile__key_list(s, sec->name, keys, sizeof keys));
    }
    if (seen[i])
        return pf_fail(c, key, s->keys[i].key, "duplicate key (first set on line %zu); "
                       "expected each key once", seen[i]);
    seen[i] = c->at.line;
    return pf_apply(c, &s->keys[i], value, obj);
}

/* One line: blank, comment ('!' or '$'), [SECTION] header, or KEY = value. */
static int pf_line(const pf_schema *s, const pf_ctx *c, char *line, const pf_section **sec,
                   int *in_section, void *obj, size_t seen[])
{
    char *p = line;
    while (isspace((unsigned char)*p))
        p++;
    if (*p == '\0' || *p == '!' || *p == '$')
        return TIRENV_OK;
    if (*p == '[') {
        *in_section = 1;
        return pf_section_line(s, c, p, sec);
    }
    if (!*in_section)
        return pf_fail(c, p, "", "text before the first section; expected a [SECTION] "
                       "header such as [%s]", s->first_section);
    if (!*sec)
        return TIRENV_OK; /* a section of another program (MF-Tyre's [VERTICAL], [SHAPE]...) */
    return pf_key_line(s, c, p, *sec, obj, seen);
}

/* The file's REAL values from its [UNITS] to SI: times each quantity's factor to the power
 * of the key's dimension. */
static void pf_convert(const pf_schema *s, void *obj, const size_t seen[], const double f[])
{
    for (size_t i = 0; i < s->n_keys; i++) {
        const pf_key *e = &s->keys[i];
        if (e->kind != TIRENV_PROPFILE_REAL || !seen[i])
            continue;
        double factor = 1;
        for (int k = 0; k < TIRENV_UNIT_KINDS; k++)
            for (int p = 0; p < abs(e->dim[k]); p++)
                factor = e->dim[k] > 0 ? factor * f[k] : factor / f[k];
        double v;
        memcpy(&v, (unsigned char *)obj + e->offset, sizeof v);
        v *= factor;
        memcpy((unsigned char *)obj + e->offset, &v, sizeof v);
    }
}

/* Which tracked keys have a value of the file's own: the others' bits are cleared. */
static void pf_mark_given(const pf_schema *s, void *obj, const size_t seen[])
{
    if (!s->given_mask)
        return;
    unsigned given;
    memcpy(&given, (unsigned char *)obj + s->given_offset, sizeof given);
    given &= ~s->given_mask;
    for (size_t i = 0; i < s->n_keys; i++)
        if (seen[i])
            given |= s->keys[i].given;
    memcpy((unsigned char *)obj + s->given_offset, &given, sizeof given);
}

/* A file that sets no value (empty, comments only, or only another program's sections) is
 * not a tire or vehicle: refused rather than read as the defaults. */
static int pf_check_any(const pf_schema *s, const char *path, size_t lines, const size_t seen[],
                        tirenv_diag *diag)
{
    const pf_key *first = NULL;
    for (size_t i = 0; i < s->n_keys; i++) {
        if (s->keys[i].kind == TIRENV_PROPFILE_UNIT)
            continue;
        if (seen[i])
            return TIRENV_OK;
        if (!first)
            first = &s->keys[i];
    }
    return tirenv_error(diag, TIRENV_EPARSE, path, lines, "", "%s sets none of the keys tirenv "
                        "reads; expected at least one, such as [%s] %s", lines ? "the file" :
                        "the empty file", first ? first->section : "", first ? first->key : "");
}

/* The lines of fp (named path) over *obj; each line read is written to kept too, if not NULL,
 * so that a second pass needs no second read of a file that may be a pipe. */
static int pf_read_stream(const pf_schema *s, const char *path, FILE *fp, void *obj,
                          FILE *kept, tirenv_diag *diag)
{
    void *copy = malloc(s->size);            /* *obj changes only once everything has passed */
    size_t *seen = calloc(s->n_keys, sizeof *seen); /* line where each key was set */
    if (!copy || !seen) {
        free(copy);
        free(seen);
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    }
    memcpy(copy, obj, s->size);
    const char *slash = strrchr(path, '/');
    const pf_section *sec = NULL;
    int in_section = 0;
    char *buf = NULL;
    size_t cap = 0;
    size_t len = 0;
    double factor[TIRENV_UNIT_KINDS];
    for (int k = 0; k < TIRENV_UNIT_KINDS; k++)
        factor[k] = 1;
    pf_ctx c = {{path, 0, NULL, diag}, slash ? (size_t)(slash - path) + 1 : 0, factor};
    int status = TIRENV_OK;
    int got;
    while (status == TIRENV_OK &&
           (got = tirenv_text__getline(&buf, &cap, fp, &len)) != TIRENV_TEXT__EOF) {
        if (got == TIRENV_TEXT__LONG) {
            status = tirenv_error(diag, TIRENV_EPARSE, path, c.at.line + 1, "",
                                  "line longer than %d characters; expected a text line (is "
                                  "this a text file?)", TIRENV_TEXT__MAX_LINE);
            break;
        }
        if (got == TIRENV_TEXT__ERROR) {  /* a read error, or no memory: never the end */
            status = tirenv_error(diag, errno == ENOMEM ? TIRENV_ENOMEM : TIRENV_EIO, path,
                                  c.at.line + 1, "", "cannot read: %s", strerror(errno));
            break;
        }
        c.at.line++;
        if (kept && fwrite(buf, 1, len, kept) != len) {
            status = tirenv_error(diag, TIRENV_ENOMEM, path, c.at.line, "", "out of memory");
            break;
        }
        char *line = buf;
        /* A NUL ends the C string: the rest of the line would be dropped without a word. */
        const char *nul = memchr(buf, '\0', len);
        if (nul) {
            c.at.base = buf;
            status = pf_fail(&c, nul, "", "a NUL byte in the line; expected text (is this a "
                             "binary file?)");
            break;
        }
        if (c.at.line == 1 && strncmp(line, "\xEF\xBB\xBF", 3) == 0)
            line += 3; /* a UTF-8 byte-order mark some Windows editors add */
        c.at.base = line;
        /* The last line, cut maybe: refused when it holds more than blanks or a comment. */
        if (buf[len - 1] != '\n' &&
            (status = tirenv_text__check_unterminated(diag, path, c.at.line, line, "$!")))
            break;
        status = pf_line(s, &c, line, &sec, &in_section, copy, seen);
    }
    if (status == TIRENV_OK && ferror(fp))
        status = tirenv_error(diag, TIRENV_EIO, path, c.at.line + 1, "", "cannot read: %s",
                              strerror(errno));
    free(buf);
    if (status == TIRENV_OK)
        status = pf_check_any(s, path, c.at.line, seen, diag);
    if (status == TIRENV_OK) {
        pf_convert(s, copy, seen, factor);
        pf_mark_given(s, copy, seen);
        status = pf_check(s, copy, path, seen, diag);
    }
    if (status == TIRENV_OK)
        memcpy(obj, copy, s->size);
    free(copy);
    free(seen);
    return status;
}

int tirenv_propfile__read(const pf_schema *s, const char *path, void *obj, tirenv_diag *diag)
{
    return tirenv_propfile__read_kept(s, path, obj, NULL, NULL, diag);
}

int tirenv_propfile__read_kept(const pf_schema *s, const char *path, void *obj, char **text,
                               size_t *len, tirenv_diag *diag)
{
    FILE *fp = fopen(path, "r");
    if (!fp)
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot open: %s", strerror(errno));
    FILE *kept = NULL;
    if (text) {
        *text = NULL;
        *len = 0;
        if (!(kept = open_memstream(text, len))) {
            fclose(fp);
            return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
        }
    }
    int status = pf_read_stream(s, path, fp, obj, kept, diag);
    fclose(fp);
    if (kept && fclose(kept) != 0 && status == TIRENV_OK)
        status = tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    if (status && text) {
        free(*text);
        *text = NULL;
        *len = 0;
    }
    return status;
}

/* fmemopen refuses a buffer of no bytes, and a file read before may have been empty. */
int tirenv_propfile__read_text(const pf_schema *s, const char *path, const char *text,
                               size_t len, void *obj, tirenv_diag *diag)
{
    FILE *fp = len ? fmemopen((void *)text, len, "r") : fopen("/dev/null", "r");
    if (!fp)
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "cannot read the text kept in "
                            "memory: %s", strerror(errno));
    const int status = pf_read_stream(s, path, fp, obj, NULL, diag);
    fclose(fp);
    return status;
}

/* Applies "KEY = VALUE" held in buf (modified in place) to a copy of *obj. */
static int pf_set_buf(const pf_schema *s, void *obj, char *buf, const char *assignment,
                      tirenv_diag *diag)
{
    const pf_ctx c = {{"--set", 0, NULL, diag}, 0, NULL};
    char *eq = strchr(buf, '=');
    if (!eq)
        return pf_fail(&c, NULL, "", "expected KEY=VALUE, got '%.60s'", assignment);
    *eq = '\0';
    char *key = tirenv_propfile__trim(buf);
    const char *section = NULL;
    char *dot = strchr(key, '.');
    if (dot) {
        *dot = '\0';
        section = key;
        key = dot + 1;
    }
    size_t matches = 0;
    const size_t i = tirenv_propfile__find_key(s, section, key, 1, &matches);
    if (i == s->n_keys) {
        char keys[448]; /* every settable key: about 400 characters for the .tir */
        return pf_fail(&c, NULL, key, "unknown key%s%s; expected one of %s",
                       section ? " in section " : "", section ? section : "",
                       tirenv_propfile__key_list(s, NULL, keys, sizeof keys));
    }
    if (matches > 1) {
        char list[256];
        size_t k = 0, index = 0;
        list[0] = '\0';
        for (size_t j = i; j < s->n_keys; j++)
            if (strcasecmp(s->keys[j].key, key) == 0 && s->keys[j].kind != TIRENV_PROPFILE_UNIT) {
                char name[128];
                snprintf(name, sizeof name, "%s.%s", s->keys[j].section, s->keys[j].key);
                pf_list_item(list, sizeof list, &k, index, index + 1 == matches, name, "", "");
                index++;
            }
        return pf_fail(&c, NULL, key, "key in more than one section; expected %s", list);
    }
    void *copy = malloc(s->size);
    if (!copy)
        return tirenv_error(diag, TIRENV_ENOMEM, "--set", 0, "", "out of memory");
    memcpy(copy, obj, s->size);
    int status = pf_apply(&c, &s->keys[i], tirenv_propfile__trim(eq + 1), copy);
    if (status == TIRENV_OK && s->given_mask && s->keys[i].given) {
        unsigned given;
        memcpy(&given, (unsigned char *)copy + s->given_offset, sizeof given);
        given |= s->keys[i].given;
        memcpy((unsigned char *)copy + s->given_offset, &given, sizeof given);
    }
    if (status == TIRENV_OK)
        status = pf_check(s, copy, "--set", NULL, diag);
    if (status == TIRENV_OK)
        memcpy(obj, copy, s->size);
    free(copy);
    return status;
}

/* Columns are not reported: with no line number they would be printed as if they were one. */
int tirenv_propfile__set(const pf_schema *s, void *obj, const char *assignment,
                         tirenv_diag *diag)
{
    const size_t n = strlen(assignment);
    char *buf = malloc(n + 1);
    if (!buf)
        return tirenv_error(diag, TIRENV_ENOMEM, "--set", 0, "", "out of memory");
    memcpy(buf, assignment, n + 1);
    const int status = pf_set_buf(s, obj, buf, assignment, diag);
    free(buf);
    return status;
}

const char *tirenv_propfile__key_at(const pf_schema *s, size_t i, const char **section)
{
    for (size_t k = 0; k < s->n_keys; k++) {
        const pf_key *e = &s->keys[k];
        if (e->kind == TIRENV_PROPFILE_UNIT || i-- > 0)
            continue;
        if (section)
            *section = e->section;
        return e->key;
    }
    return NULL;
}
