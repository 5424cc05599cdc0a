/* SPDX-License-Identifier: Apache-2.0 */
/* A .tir file's values set in place, comments and layout kept (tirenv_tir_update): how
 * `tirenv identify --write` records identified parameters in a hand-written tire file. */
#include "tirenv/outfile.h"
#include "tirenv/tir.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include "io/io.h"

static const char begin_mark[] = "! tirenv identify: begin";
static const char end_mark[] = "! tirenv identify: end";

/* The whole file, NUL-terminated, or NULL. */
static char *slurp(const char *path, int *status, tirenv_diag *diag)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) {
        *status = tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot open the tire file");
        return NULL;
    }
    size_t cap = 1 << 14, len = 0;
    char *buf = malloc(cap);
    for (size_t got; buf && (got = fread(buf + len, 1, cap - len - 1, fp)) > 0;) {
        len += got;
        if (len + 1 == cap) {
            char *more = realloc(buf, cap *= 2);
            if (!more) {
                free(buf);
                buf = NULL;
            }
            buf = more;
        }
    }
    const int bad = ferror(fp);
    fclose(fp);
    if (!buf || bad || memchr(buf, '\0', len)) {
        free(buf);
        *status = tirenv_error(diag, bad ? TIRENV_EIO : buf ? TIRENV_EPARSE : TIRENV_ENOMEM, path, 0, "",
                     "cannot read the tire file as text");
        return NULL;
    }
    buf[len] = '\0';
    return buf;
}

/* The section a line opens ("[NAME]", name copied upper-case into sec), or 0. */
static int section_of(const char *line, size_t len, char sec[64])
{
    size_t i = 0;
    while (i < len && (line[i] == ' ' || line[i] == '\t'))
        i++;
    if (i >= len || line[i] != '[')
        return 0;
    size_t k = 0;
    for (i++; i < len && line[i] != ']' && k < 63; i++)
        sec[k++] = (char)toupper((unsigned char)line[i]);
    sec[k] = '\0';
    return 1;
}

/* The index of the value this line sets in section sec, or n. */
static size_t value_of(const char *line, size_t len, const char *sec, size_t n,
                       const tirenv_tir_value v[], size_t *eq)
{
    size_t i = 0;
    while (i < len && (line[i] == ' ' || line[i] == '\t'))
        i++;
    const size_t k0 = i;
    while (i < len && (isalnum((unsigned char)line[i]) || line[i] == '_'))
        i++;
    const size_t k1 = i;
    while (i < len && (line[i] == ' ' || line[i] == '\t'))
        i++;
    if (k1 == k0 || i >= len || line[i] != '=')
        return n;
    *eq = i;
    for (size_t j = 0; j < n; j++)
        if (!strcasecmp(v[j].section, sec) && strlen(v[j].key) == k1 - k0 &&
            !strncasecmp(v[j].key, line + k0, k1 - k0))
            return j;
    return n;
}

/* eol: the line end the file's lines have ("\r\n" or "\n"), for the lines written anew. */
static void put_key(FILE *fp, const tirenv_tir_value *v, const char *eol)
{
    fprintf(fp, "%-24s = %.6g%s", v->key, v->value, eol);
}

/* The line with its value replaced: the comment ('$' on) stays at its column when the new
 * value fits before it. */
static void put_replaced(FILE *fp, const char *line, size_t len, size_t eq, double value,
                         const char *eol)
{
    size_t i = eq + 1;
    while (i < len && (line[i] == ' ' || line[i] == '\t'))
        i++;
    const char *dollar = memchr(line + i, '$', len - i);
    char text[64];
    const int w = snprintf(text, sizeof text, "%.6g", value);
    fprintf(fp, "%.*s%s", (int)i, line, text);
    if (dollar) {
        const size_t col = (size_t)(dollar - line);
        size_t at = i + (size_t)w;
        fputc(' ', fp);
        for (at++; at < col; at++)
            fputc(' ', fp);
        fprintf(fp, "%.*s", (int)(len - col), dollar);
    }
    fputs(eol, fp);
}

static void put_note(FILE *fp, const char *note, const char *eol)
{
    fprintf(fp, "%s%s", begin_mark, eol);
    for (const char *p = note; p && *p;) {
        const size_t l = strcspn(p, "\n");
        fprintf(fp, "! %.*s%s", (int)l, p, eol);
        p += l + (p[l] == '\n');
    }
    fprintf(fp, "%s%s", end_mark, eol);
}

enum { MAX_VALUES = 64 }; /* the values one update sets */

/* One rewrite of a file: the values to set and which are written (done), the note and whether
 * it is, and the line end of the lines written anew (eol: the file's first line's, "\r\n" or
 * "\n"). */
typedef struct {
    FILE *fp;
    size_t n;
    const tirenv_tir_value *values;
    int done[MAX_VALUES];
    const char *note, *eol;
    int noted;
} rewrite;

static void write_note(rewrite *w)
{
    put_note(w->fp, w->note, w->eol);
    w->noted = 1;
}

/* Whether the section sec, whose lines follow at rest, sets the value v. */
static int section_sets(const char *rest, const char *sec, const tirenv_tir_value *v)
{
    char s2[64];
    for (const char *q = rest; *q;) {
        const size_t ql = strcspn(q, "\n");
        size_t eq;
        if (section_of(q, ql, s2))
            return 0;
        if (value_of(q, ql, sec, 1, v, &eq) == 0)
            return 1;
        q += ql + (q[ql] == '\n');
    }
    return 0;
}

/* The header line of section sec (l bytes, its own line end), then right after it each value
 * of sec the section lacks (rest: the lines after the header). */
static void open_section(rewrite *w, const char *line, size_t l, const char *own,
                         const char *sec, const char *rest)
{
    fprintf(w->fp, "%.*s%s", (int)l, line, own);
    for (size_t j = 0; j < w->n; j++)
        if (!strcasecmp(w->values[j].section, sec) && !section_sets(rest, sec, &w->values[j])) {
            put_key(w->fp, &w->values[j], w->eol);
            w->done[j] = 1;
        }
}

/* The file's lines, each as it was but for the values set and the note: the old note left
 * out, the new one where it was, else after [MDI_HEADER]'s keys and comments, before the first
 * '$-' rule or section that follows them. */
static void rewrite_lines(rewrite *w, const char *text)
{
    char sec[64] = "";
    int in_note = 0;
    for (const char *p = text; *p;) {
        const size_t len = strcspn(p, "\n");
        const char *line = p;
        p += len + (p[len] == '\n');
        size_t l = len;
        if (l && line[l - 1] == '\r')
            l--;
        const char *own = l < len ? "\r\n" : "\n";  /* this line's end, kept */
        if (!strncmp(line, begin_mark, sizeof begin_mark - 1)) {
            in_note = 1;
            continue;
        }
        if (in_note) {
            if (!strncmp(line, end_mark, sizeof end_mark - 1)) {
                in_note = 0;
                write_note(w);
            }
            continue;
        }
        const int in_header = !w->noted && !strcmp(sec, "MDI_HEADER");
        if (in_header && l >= 2 && line[0] == '$' && line[1] == '-')
            write_note(w);
        char next[64];
        if (section_of(line, l, next)) {
            if (!w->noted && !strcmp(sec, "MDI_HEADER"))
                write_note(w);
            memcpy(sec, next, sizeof sec);
            open_section(w, line, l, own, sec, p);
            continue;
        }
        size_t eq;
        const size_t j = value_of(line, l, sec, w->n, w->values, &eq);
        if (j < w->n && !w->done[j]) {
            put_replaced(w->fp, line, l, eq, w->values[j].value, own);
            w->done[j] = 1;
        } else {
            fprintf(w->fp, "%.*s%s", (int)l, line, own);
        }
    }
}

/* Sections absent from the file, each once, with all of its keys not yet written. */
static void add_absent_sections(rewrite *w)
{
    const tirenv_tir_value *v = w->values;
    for (size_t j = 0; j < w->n; j++) {
        if (w->done[j])
            continue;
        int first = 1;
        for (size_t i = 0; i < j; i++)
            first &= !(!w->done[i] && !strcasecmp(v[i].section, v[j].section));
        if (!first)
            continue;
        fprintf(w->fp, "[%s]%s", v[j].section, w->eol);
        for (size_t i = j; i < w->n; i++)
            if (!w->done[i] && !strcasecmp(v[i].section, v[j].section))
                put_key(w->fp, &v[i], w->eol);
    }
}

int tirenv_tir_update(const char *path, size_t n, const tirenv_tir_value values[],
                      const char *note, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    if (n > MAX_VALUES)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "", "more than %d values",
                            MAX_VALUES);
    /* Replaced in place, so a file: a pipe would be read once and not be written back. */
    struct stat st;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode))
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "not a regular file (a pipe or "
                            "device); its values are set in place, expected a regular file");
    int status;
    char *text = slurp(path, &status, diag);
    if (!text)
        return status;
    tirenv_outfile *out;
    status = tirenv_outfile_open(&out, path, diag);
    if (status) {
        free(text);
        return status;
    }
    /* A file of "\r\n" line ends keeps them: its lines each as they were, the new ones as its
     * first (a CRLF file was written back with "\n" ends throughout). */
    const size_t end1 = strcspn(text, "\n");
    rewrite w = {.fp = tirenv_outfile_stream(out), .n = n, .values = values, .done = {0},
                 .note = note,
                 .eol = end1 && text[end1] == '\n' && text[end1 - 1] == '\r' ? "\r\n" : "\n",
                 .noted = 0};
    rewrite_lines(&w, text);
    if (!w.noted)
        write_note(&w);
    add_absent_sections(&w);
    free(text);
    if ((status = tirenv_outfile_commit(out, diag)))
        return status;
    /* The result must be a tire file tirenv reads. */
    tirenv_tire check = tirenv_tire_default();
    return tirenv_tir_read(path, &check, diag);
}
