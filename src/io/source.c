/* Bytes and lines of a road file, from a file read where asked (pread) or from memory.
 * SPDX-License-Identifier: Apache-2.0 */
#include "io/io.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char *dup_name(const char *name)
{
    const size_t n = strlen(name) + 1;
    char *copy = malloc(n);
    if (copy)
        memcpy(copy, name, n);
    return copy;
}

/* pread needs a file with a size and random access: a pipe or a terminal has neither, so it
 * is refused up front rather than failing half way through a road. */
int tirenv_source__open_file(tirenv_source *s, const char *path, tirenv_diag *diag)
{
    memset(s, 0, sizeof *s);
    s->fd = open(path, O_RDONLY);
    if (s->fd < 0)
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot open: %s", strerror(errno));
    struct stat st;
    if (fstat(s->fd, &st) != 0) {
        const int e = errno;
        tirenv_source__close(s);
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot read: %s", strerror(e));
    }
    if (S_ISDIR(st.st_mode)) {
        tirenv_source__close(s);
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "is a directory; expected a file");
    }
    if (!S_ISREG(st.st_mode)) {
        tirenv_source__close(s);
        return tirenv_error(diag, TIRENV_EIO, path, 0, "",
                            "not a regular file (a pipe or device); expected a file that can "
                            "be read at any position");
    }
    if (!(s->name = dup_name(path))) {
        tirenv_source__close(s);
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    }
    s->size = (size_t)st.st_size;
    return TIRENV_OK;
}

int tirenv_source__share(tirenv_source *s, const tirenv_source *from, tirenv_diag *diag)
{
    memset(s, 0, sizeof *s);
    s->fd = -1;
    if (!(s->name = dup_name(from->name)))
        return tirenv_error(diag, TIRENV_ENOMEM, from->name, 0, "", "out of memory");
    s->mem = from->mem;
    s->fd = from->fd;
    s->size = from->size;
    s->shared = 1;
    return TIRENV_OK;
}

int tirenv_source__open_memory(tirenv_source *s, const void *data, size_t size,
                               const char *name, tirenv_diag *diag)
{
    memset(s, 0, sizeof *s);
    s->fd = -1;
    if (!name)
        name = "(memory)";
    if (!data && size > 0)
        return tirenv_error(diag, TIRENV_EINVAL, name, 0, "", "NULL buffer of %zu bytes", size);
    if (!(s->name = dup_name(name)))
        return tirenv_error(diag, TIRENV_ENOMEM, name, 0, "", "out of memory");
    s->mem = data ? data : (const unsigned char *)"";
    s->size = size;
    return TIRENV_OK;
}

int tirenv_source__read(const tirenv_source *s, size_t offset, void *buf, size_t n,
                        tirenv_diag *diag)
{
    if (offset > s->size || n > s->size - offset)
        return tirenv_error(diag, TIRENV_EIO, s->name, 0, "",
                            "cannot read %zu bytes at byte offset %zu: the file has %zu bytes "
                            "(did it change while being read?)", n, offset, s->size);
    if (s->mem) {
        memcpy(buf, s->mem + offset, n);
        return TIRENV_OK;
    }
    unsigned char *p = buf;
    while (n > 0) {
        const ssize_t got = pread(s->fd, p, n, (off_t)offset);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            return tirenv_error(diag, TIRENV_EIO, s->name, 0, "",
                                "cannot read at byte offset %zu: %s", offset,
                                got < 0 ? strerror(errno) : "unexpected end of file");
        p += got;
        offset += (size_t)got;
        n -= (size_t)got;
    }
    return TIRENV_OK;
}

void tirenv_source__close(tirenv_source *s)
{
    if (s->fd >= 0 && !s->shared)
        close(s->fd);
    s->fd = -1;
    free(s->name);
    s->name = NULL;
    s->mem = NULL;
}

/* ---- lines ----------------------------------------------------------------------------- */

enum { READ_AHEAD = 65536 };

int tirenv_lines__init(tirenv_lines *r, const tirenv_source *s, size_t offset, size_t line,
                       tirenv_diag *diag)
{
    memset(r, 0, sizeof *r);
    r->src = s;
    r->pos = offset;
    r->line = line > 0 ? line - 1 : 0;
    r->cap = 256;
    r->text = malloc(r->cap);
    if (!s->mem) {
        r->buf_cap = READ_AHEAD;
        r->buf = malloc(r->buf_cap);
    }
    if (!r->text || (!s->mem && !r->buf)) {
        tirenv_lines__free(r);
        return tirenv_error(diag, TIRENV_ENOMEM, s->name, 0, "", "out of memory");
    }
    r->text[0] = '\0';
    return TIRENV_OK;
}

/* The byte at offset pos (< size), through the read-ahead window for a file. */
static int byte_at(tirenv_lines *r, size_t pos, unsigned char *c, tirenv_diag *diag)
{
    const tirenv_source *s = r->src;
    if (s->mem) {
        *c = s->mem[pos];
        return TIRENV_OK;
    }
    if (pos < r->buf_off || pos >= r->buf_off + r->buf_len) {
        const size_t n = s->size - pos < r->buf_cap ? s->size - pos : r->buf_cap;
        const int status = tirenv_source__read(s, pos, r->buf, n, diag);
        if (status)
            return status;
        r->buf_off = pos;
        r->buf_len = n;
    }
    *c = r->buf[pos - r->buf_off];
    return TIRENV_OK;
}

int tirenv_lines__next(tirenv_lines *r, tirenv_diag *diag)
{
    const tirenv_source *s = r->src;
    if (r->pos >= s->size)
        return 0;
    r->line++;
    r->start = r->pos;
    r->len = 0;
    r->eol = 0;
    while (r->pos < s->size) {
        unsigned char c;
        const int status = byte_at(r, r->pos, &c, diag);
        if (status)
            return -status;
        r->pos++;
        if (c == '\n') {
            r->eol = 1;
            break;
        }
        if (c == '\0')
            return -tirenv_error(diag, TIRENV_EPARSE, s->name, r->line, "",
                                 "NUL byte at column %zu (byte offset %zu); expected text",
                                 r->len + 1, r->pos - 1);
        if (r->len >= TIRENV_SOURCE__MAX_LINE)
            return -tirenv_error(diag, TIRENV_EPARSE, s->name, r->line, "",
                                 "line longer than %d characters; expected a text line",
                                 TIRENV_SOURCE__MAX_LINE);
        if (r->len + 1 >= r->cap) {
            char *t = realloc(r->text, 2 * r->cap);
            if (!t)
                return -tirenv_error(diag, TIRENV_ENOMEM, s->name, r->line, "",
                                     "out of memory");
            r->text = t;
            r->cap *= 2;
        }
        r->text[r->len++] = (char)c;
    }
    if (r->len > 0 && r->text[r->len - 1] == '\r')
        r->len--;
    r->text[r->len] = '\0';
    return 1;
}

void tirenv_lines__free(tirenv_lines *r)
{
    free(r->text);
    free(r->buf);
    r->text = NULL;
    r->buf = NULL;
}
