/* Line-by-line reading of the small CSV files of src/data (curves, rig logs, manifests).
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "data/csv_line.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

int tirenv_csv__open(tirenv_csv__reader *r, const char *path, tirenv_diag *diag)
{
    memset(r, 0, sizeof *r);
    r->file = path;
    r->diag = diag;
    r->fp = fopen(path, "r");
    if (!r->fp)
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot open: %s", strerror(errno));
    /* fopen takes a directory; only the first read fails, with a bare "Is a directory". */
    struct stat st;
    if (fstat(fileno(r->fp), &st) == 0 && S_ISDIR(st.st_mode)) {
        fclose(r->fp);
        r->fp = NULL;
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "is a directory; expected a CSV "
                            "file");
    }
    return TIRENV_OK;
}

void tirenv_csv__close(tirenv_csv__reader *r)
{
    if (r->fp)
        fclose(r->fp);
    free(r->buf);
    r->fp = NULL;
    r->buf = NULL;
    r->cap = 0;
}

int tirenv_csv__next(tirenv_csv__reader *r)
{
    for (;;) {
        errno = 0;
        const ssize_t len = getline(&r->buf, &r->cap, r->fp);
        if (len == -1) {
            if (ferror(r->fp))
                return -tirenv_error(r->diag, TIRENV_EIO, r->file, r->line + 1, "",
                                     "cannot read: %s", strerror(errno ? errno : EIO));
            return 0;
        }
        r->line++;
        /* A NUL ends the C string: the rest of the line would be dropped without a word. */
        const char *nul = memchr(r->buf, '\0', (size_t)len);
        if (nul) {
            const int status = tirenv_error(r->diag, TIRENV_EPARSE, r->file, r->line, "",
                                            "a NUL byte in the line; expected text (is this "
                                            "a binary file?)");
            if (r->diag)
                r->diag->column = (size_t)(nul - r->buf) + 1;
            return -status;
        }
        char *text = r->buf;
        if (r->line == 1 && strncmp(text, "\xEF\xBB\xBF", 3) == 0)
            text += 3; /* the UTF-8 byte-order mark spreadsheet programs write */
        size_t n = strlen(text);
        while (n > 0 && (text[n - 1] == '\n' || text[n - 1] == '\r'))
            text[--n] = '\0';
        r->text = text;
        r->length = n;
        const char *p = text;
        while (isspace((unsigned char)*p))
            p++;
        if (*p != '\0' && *p != '#')
            return 1;
    }
}

size_t tirenv_csv__split(tirenv_csv__reader *r, tirenv_csv__field f[], size_t max)
{
    size_t count = 0;
    char *p = r->text;
    for (;;) {
        char *comma = strchr(p, ',');
        if (comma)
            *comma = '\0';
        if (count <= max) {
            while (isspace((unsigned char)*p))
                p++;
            size_t n = strlen(p);
            while (n > 0 && isspace((unsigned char)p[n - 1]))
                p[--n] = '\0';
            f[count].text = p;
            f[count].column = (size_t)(p - r->text) + 1;
        }
        count++;
        if (!comma)
            return count;
        p = comma + 1;
    }
}

int tirenv_csv__fail(const tirenv_csv__reader *r, size_t column, const char *field,
                     const char *fmt, ...)
{
    char msg[sizeof ((tirenv_diag *)NULL)->message];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    const int status = tirenv_error(r->diag, TIRENV_EPARSE, r->file, r->line, field, "%s", msg);
    if (r->diag)
        r->diag->column = column;
    return status;
}

void tirenv_csv__join(const char *const names[], size_t n, char *buf, size_t size)
{
    size_t k = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < n && k < size; i++) {
        const int w = snprintf(buf + k, size - k, "%s%s", i ? "," : "", names[i]);
        k += w > 0 ? (size_t)w : 0;
    }
}

/* The header is compared column by column so the message points at the first wrong name. */
int tirenv_csv__header(tirenv_csv__reader *r, const char *const names[], size_t n)
{
    char want[256];
    tirenv_csv__join(names, n, want, sizeof want);
    tirenv_csv__field f[16];
    const size_t max = n < 15 ? n : 15;
    const size_t count = tirenv_csv__split(r, f, max);
    for (size_t k = 0; k < n && k < count && k <= max; k++)
        if (strcmp(f[k].text, names[k]) != 0)
            return tirenv_csv__fail(r, f[k].column, names[k],
                                    "expected the header '%s', got '%.60s' for column %zu",
                                    want, f[k].text, k + 1);
    if (count != n)
        return tirenv_csv__fail(r, count > n ? f[max].column : r->length + 1, "",
                                "expected the header '%s' (%zu columns), got %zu column%s",
                                want, n, count, count == 1 ? "" : "s");
    return TIRENV_OK;
}

int tirenv_csv__fields(tirenv_csv__reader *r, const char *const names[], size_t n,
                       tirenv_csv__field f[])
{
    const size_t count = tirenv_csv__split(r, f, n);
    if (count > n)
        return tirenv_csv__fail(r, f[n].column, "", "expected %zu fields, got %zu", n, count);
    if (count < n)
        return tirenv_csv__fail(r, r->length + 1, names[count],
                                "expected %zu fields, got %zu (missing %s)", n, count,
                                names[count]);
    return TIRENV_OK;
}

int tirenv_csv__number(const tirenv_csv__reader *r, const tirenv_csv__field *f,
                       const char *name, double *out)
{
    if (f->text[0] == '\0')
        return tirenv_csv__fail(r, f->column, name, "expected a number, got an empty field");
    char *end;
    const double v = strtod(f->text, &end);
    if (end == f->text || *end)
        return tirenv_csv__fail(r, f->column, name, "expected a number, got '%.60s'", f->text);
    /* Overflow gives infinity; underflow to a denormal or 0 is a fine small number. */
    if (!isfinite(v))
        return tirenv_csv__fail(r, f->column, name, "expected a finite number, got '%.60s'",
                                f->text);
    *out = v;
    return TIRENV_OK;
}
