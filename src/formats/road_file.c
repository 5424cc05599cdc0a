/* SPDX-License-Identifier: Apache-2.0 */
/* The one road reader's open file (tirenv_road_file, profile_file.h): a road file opened once
 * and its format told once from its first bytes, by the rules of tirenv_profile_detect_memory;
 * the readers of the formats then take their bytes from it (road_file_impl.h), never the path.
 * A regular file is read where asked (pread), so every reader has a position of its own; a
 * pipe or a device can be read only once, so what is read of it is kept, and every reader
 * reads that copy, the pipe read further only as far as the furthest reader asks. What a
 * format reads before its first row (an OpenCRG road's pass at open, an RDF road's scan, which
 * checks its rows and keeps none) is read once and shared by every reader of the file
 * (tirenv_road_file__crg, tirenv_road_file__rdf), so that a road's ends come from one
 * reading and its rows from one more, in bounded memory. */
#define _GNU_SOURCE /* fopencookie */
#include "formats/road_file_impl.h"

#include "formats/crg_impl.h"
#include "formats/rdf_impl.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>
#include "io/io.h"

struct tirenv_road_file {
    char *name;                   /* the path, for messages */
    tirenv_profile_format format; /* told by the first bytes */
    int fd;
    int regular;                  /* a regular file: read where asked */
    tirenv_source src;            /* its bytes at any position; a pipe's once read whole
                                   * (src.name set: opened) */
    unsigned char *buf;           /* a pipe or device: what has been read of it */
    size_t len, cap;
    int eof;                      /* ... and whether that is all of it */
    tirenv_crg *crg;              /* an OpenCRG road, opened once for every reader, or NULL */
    tirenv_rdf__road *rdf;        /* an RDF road, scanned once for every reader, or NULL */
};

/* Reads the pipe on until it holds want bytes or ends: 0, or an errno value (EFBIG beyond
 * TIRENV_ROAD_FILE_PIPE_MAX bytes). */
static int fill(tirenv_road_file *f, size_t want)
{
    while (!f->eof && f->len < want) {
        if (f->len == f->cap) {
            if (f->cap >= TIRENV_ROAD_FILE_PIPE_MAX)
                return EFBIG;
            const size_t cap = f->cap ? 2 * f->cap : 65536;
            unsigned char *b = realloc(f->buf, cap);
            if (!b)
                return ENOMEM;
            f->buf = b;
            f->cap = cap;
        }
        const ssize_t got = read(f->fd, f->buf + f->len, f->cap - f->len);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            return errno;
        if (got == 0)
            f->eof = 1;
        f->len += (size_t)got;
    }
    return 0;
}

/* Up to n bytes at offset into buf: how many (0 at the end), or -1 with errno set. */
static ssize_t read_at(tirenv_road_file *f, size_t offset, void *buf, size_t n)
{
    if (f->regular) {
        for (;;) {
            const ssize_t got = pread(f->fd, buf, n, (off_t)offset);
            if (!(got < 0 && errno == EINTR))
                return got;
        }
    }
    /* At least one byte past offset (as read(2) returns what has come), or the end. */
    const int e = n ? fill(f, offset == SIZE_MAX ? SIZE_MAX : offset + 1) : 0;
    if (e) {
        errno = e;
        return -1;
    }
    const size_t m = offset >= f->len ? 0 : f->len - offset < n ? f->len - offset : n;
    memcpy(buf, f->buf + offset, m);
    return (ssize_t)m;
}

/* ---- streams with a position of their own ------------------------------------------------ */

typedef struct {
    tirenv_road_file *f;
    size_t offset;
} cookie;

static ssize_t cookie_read(void *c, char *buf, size_t n)
{
    cookie *k = c;
    const ssize_t got = read_at(k->f, k->offset, buf, n);
    if (got > 0)
        k->offset += (size_t)got;
    return got;
}

static int cookie_close(void *c)
{
    free(c);
    return 0;
}

FILE *tirenv_road_file__stream(tirenv_road_file *f, tirenv_diag *diag)
{
    cookie *k = malloc(sizeof *k);
    FILE *fp = NULL;
    if (k) {
        *k = (cookie){.f = f, .offset = 0};
        fp = fopencookie(k, "r", (cookie_io_functions_t){.read = cookie_read,
                                                         .close = cookie_close});
    }
    if (!fp) {
        free(k);
        tirenv_error(diag, TIRENV_ENOMEM, f->name, 0, "", "out of memory");
    }
    return fp;
}

int tirenv_road_file__source(tirenv_road_file *f, const tirenv_source **out, tirenv_diag *diag)
{
    *out = NULL;
    if (!f->src.name) {
        const int e = fill(f, SIZE_MAX);
        if (e == EFBIG)
            return tirenv_error(diag, TIRENV_EIO, f->name, 0, "",
                                "a pipe or device of more than %d bytes, which is kept in "
                                "memory; expected a regular file", TIRENV_ROAD_FILE_PIPE_MAX);
        if (e)
            return tirenv_error(diag, e == ENOMEM ? TIRENV_ENOMEM : TIRENV_EIO, f->name, 0, "",
                                "cannot read: %s", strerror(e));
        const int status = tirenv_source__open_memory(&f->src, f->buf, f->len, f->name, diag);
        if (status)
            return status;
    }
    *out = &f->src;
    return TIRENV_OK;
}

int tirenv_road_file__crg(tirenv_road_file *f, const tirenv_crg **out, tirenv_diag *diag)
{
    *out = NULL;
    if (!f->crg) {
        const tirenv_source *s;
        int status = tirenv_road_file__source(f, &s, diag);
        if (!status)
            status = tirenv_crg__open_source(s, &f->crg, diag);
        if (status)
            return status;
    }
    *out = f->crg;
    return TIRENV_OK;
}

int tirenv_road_file__rdf(tirenv_road_file *f, tirenv_rdf_side side,
                          const tirenv_rdf__road **out, tirenv_diag *diag)
{
    *out = NULL;
    if (!tirenv_rdf_side_name(side))  /* tirenv_rdf__side's words, before the scan */
        return tirenv_error(diag, TIRENV_EINVAL, f->name, 0, "side", "unknown side %d",
                            (int)side);
    if (!f->rdf) {
        const tirenv_source *s;
        int status = tirenv_road_file__source(f, &s, diag);
        if (!status)
            status = tirenv_rdf__open(s, &f->rdf, diag);
        if (status)
            return status;
    }
    const int status = tirenv_rdf__side(f->rdf, side, diag);
    if (!status)
        *out = f->rdf;
    return status;
}

int tirenv_road_file__rdf_whole(tirenv_road_file *f, tirenv_rdf_side side,
                                tirenv_profile **out, tirenv_diag *diag)
{
    *out = NULL;
    const tirenv_rdf__road *road;
    if (f->rdf) {  /* scanned already: the rows read once more */
        const int status = tirenv_road_file__rdf(f, side, &road, diag);
        return status ? status : tirenv_rdf__profile(road, side, out, diag);
    }
    const tirenv_source *s;
    const int status = tirenv_road_file__source(f, &s, diag);
    return status ? status : tirenv_rdf__open_whole(s, side, &f->rdf, out, diag);
}

/* ---- opening ------------------------------------------------------------------------------ */

void tirenv_road_file_free(tirenv_road_file *f)
{
    if (!f)
        return;
    tirenv_crg_free(f->crg);  /* before the source it shares */
    tirenv_rdf__free(f->rdf);  /* before the source it reads */
    tirenv_source__close(&f->src);
    if (f->fd >= 0)
        close(f->fd);
    free(f->buf);
    free(f->name);
    free(f);
}

/* The format by the first 64 KB, as tirenv_profile_detect_memory tells it. */
static int detect(tirenv_road_file *f, tirenv_diag *diag)
{
    enum { HEAD = 65536 };
    char *buf = malloc(HEAD);
    if (!buf)
        return tirenv_error(diag, TIRENV_ENOMEM, f->name, 0, "", "out of memory");
    size_t n = 0;
    while (n < HEAD) {
        const ssize_t got = read_at(f, n, buf + n, HEAD - n);
        if (got < 0) {
            const int e = errno;
            free(buf);
            return tirenv_error(diag, e == ENOMEM ? TIRENV_ENOMEM : TIRENV_EIO, f->name, 0, "",
                                "cannot read: %s", strerror(e));
        }
        if (got == 0)
            break;
        n += (size_t)got;
    }
    /* A line cut at the end of the window may look like CSV; trim to the last whole line. */
    size_t m = n;
    if (n == HEAD)
        while (m > 0 && buf[m - 1] != '\n')
            m--;
    f->format = tirenv_profile_detect_memory(buf, m ? m : n);
    free(buf);
    return TIRENV_OK;
}

int tirenv_road_file_open(const char *path, tirenv_road_file **out, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *out = NULL;
    tirenv_road_file *f = calloc(1, sizeof *f);
    const size_t len = strlen(path) + 1;
    if (!f || !(f->name = malloc(len))) {
        free(f);
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    }
    memcpy(f->name, path, len);
    f->src.fd = -1;
    int status = TIRENV_OK;
    struct stat st;
    if ((f->fd = open(path, O_RDONLY)) < 0)
        status = tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot open: %s",
                              strerror(errno));
    else if (fstat(f->fd, &st) != 0)
        status = tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot read: %s",
                              strerror(errno));
    else if (S_ISDIR(st.st_mode))
        status = tirenv_error(diag, TIRENV_EIO, path, 0, "", "is a directory; expected a CSV, "
                              "OpenCRG or RDF road file");
    else if ((f->regular = S_ISREG(st.st_mode)))
        status = tirenv_source__share(
            &f->src, &(tirenv_source){.fd = f->fd, .size = (size_t)st.st_size, .name = f->name},
            diag);
    if (!status)
        status = detect(f, diag);
    if (status) {
        tirenv_road_file_free(f);
        return status;
    }
    *out = f;
    return TIRENV_OK;
}

tirenv_profile_format tirenv_road_file_format(const tirenv_road_file *f) { return f->format; }

const char *tirenv_road_file_name(const tirenv_road_file *f) { return f->name; }

int tirenv_profile_detect(const char *path, tirenv_profile_format *format, tirenv_diag *diag)
{
    tirenv_road_file *f;
    const int status = tirenv_road_file_open(path, &f, diag);
    if (!status)
        *format = f->format;
    tirenv_road_file_free(f);
    return status;
}
