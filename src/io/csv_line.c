/* Line-by-line reading of the small CSV files of the auxiliary layer (curves, rig logs, manifests).
 * SPDX-License-Identifier: Apache-2.0 */
#include "io/io.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
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

void tirenv_csv__open_stream(tirenv_csv__reader *r, FILE *fp, const char *name,
                             tirenv_diag *diag)
{
    memset(r, 0, sizeof *r);
    r->file = name;
    r->diag = diag;
    r->fp = fp;
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
        size_t len = 0;
        const int got = tirenv_text__getline(&r->buf, &r->cap, r->fp, &len);
        if (got == TIRENV_TEXT__EOF)
            return 0;
        if (got == TIRENV_TEXT__LONG)
            return -tirenv_error(r->diag, TIRENV_EPARSE, r->file, r->line + 1, "",
                                 "line longer than %d characters; expected a text line (is "
                                 "this a text file?)", TIRENV_TEXT__MAX_LINE);
        if (got == TIRENV_TEXT__ERROR)  /* a read error, or no memory: never the end */
            /* EFBIG: a pipe read whole into memory (road_file.c) passed its limit */
            return -tirenv_error(r->diag, errno == ENOMEM ? TIRENV_ENOMEM : TIRENV_EIO,
                                 r->file, r->line + 1, "", "cannot read: %s%s",
                                 strerror(errno), errno == EFBIG ? " (a pipe or device is kept "
                                 "in memory, up to a limit; expected a regular file)" : "");
        r->line++;
        /* A NUL ends the C string: the rest of the line would be dropped without a word. */
        const char *nul = memchr(r->buf, '\0', len);
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
        const int eol = r->buf[len - 1] == '\n';
        size_t n = strlen(text);
        while (n > 0 && (text[n - 1] == '\n' || text[n - 1] == '\r'))
            text[--n] = '\0';
        r->text = text;
        r->length = n;
        const char *p = text;
        while (isspace((unsigned char)*p))
            p++;
        if (*p != '\0' && *p != '#') {
            if (!eol)
                return -tirenv_text__unterminated(r->diag, r->file, r->line, n + 1);
            return 1;
        }
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

/* Exact powers of ten: every one up to 1e22 is a double (5^22 < 2^53). */
static const double exact_pow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                     1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                     1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

/* Clinger's fast path: a plain decimal [+-]digits[.digits][e[+-]digits] whose digits make an
 * integer w <= 2^53 with a power of ten 10^k, |k| <= 22, is w * 10^k or w / 10^-k: one
 * correctly rounded operation on two exact doubles, so exactly strtod's value. Returns 0
 * for anything else (more digits, larger powers, hexadecimal, inf, nan, malformed text),
 * which strtod then parses or refuses as before. */
static int decimal_fast(const char *s, double *out)
{
    const char *p = s;
    const int neg = *p == '-';
    if (*p == '-' || *p == '+')
        ++p;
    uint64_t w = 0;
    int digits = 0, frac = 0, any = 0;
    for (; *p >= '0' && *p <= '9'; ++p, any = 1)
        if (w || *p != '0') {
            if (++digits > 19)
                return 0;
            w = 10 * w + (uint64_t)(*p - '0');
        }
    if (*p == '.')
        for (++p; *p >= '0' && *p <= '9'; ++p, any = 1) {
            ++frac;
            if (w || *p != '0') {
                if (++digits > 19)
                    return 0;
                w = 10 * w + (uint64_t)(*p - '0');
            }
        }
    if (!any)
        return 0;
    int k = 0;
    if (*p == 'e' || *p == 'E') {
        ++p;
        const int eneg = *p == '-';
        if (*p == '-' || *p == '+')
            ++p;
        if (!(*p >= '0' && *p <= '9'))
            return 0;
        for (; *p >= '0' && *p <= '9'; ++p) {
            if (k > 10000)
                return 0;
            k = 10 * k + (*p - '0');
        }
        k = eneg ? -k : k;
    }
    if (*p != '\0' || w > ((uint64_t)1 << 53))
        return 0;
    k -= frac;
    double v;
    if (w == 0)
        v = 0;
    else if (k >= 0 && k <= 22)
        v = (double)w * exact_pow10[k];
    else if (k < 0 && k >= -22)
        v = (double)w / exact_pow10[-k];
    else
        return 0;
    *out = neg ? -v : v;
    return 1;
}

int tirenv_csv__parse_double(const char *s, double *out)
{
    if (decimal_fast(s, out))
        return 0;
    char *end;
    const double v = strtod(s, &end);
    if (end == s || *end)
        return -1;
    *out = v;
    return 0;
}

int tirenv_csv__number(const tirenv_csv__reader *r, const tirenv_csv__field *f,
                       const char *name, double *out)
{
    if (f->text[0] == '\0')
        return tirenv_csv__fail(r, f->column, name, "expected a number, got an empty field");
    double v;
    if (tirenv_csv__parse_double(f->text, &v))
        return tirenv_csv__fail(r, f->column, name, "expected a number, got '%.60s'", f->text);
    /* Overflow gives infinity; underflow to a denormal or 0 is a fine small number. */
    if (!isfinite(v))
        return tirenv_csv__fail(r, f->column, name, "expected a finite number, got '%.60s'",
                                f->text);
    *out = v;
    return TIRENV_OK;
}

int tirenv_csv__number_within(const tirenv_csv__reader *r, const tirenv_csv__field *f,
                              const char *name, double max, const char *expected, double *out)
{
    const int status = tirenv_csv__number(r, f, name, out);
    if (status == TIRENV_OK && !(fabs(*out) <= max))
        return tirenv_csv__fail(r, f->column, name, "%s = %.40s is beyond +-%g; expected %s",
                                name, f->text, max, expected);
    return status;
}
