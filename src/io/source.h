/* Private to src/io, for the road-file readers of src/formats: the bytes a road-file reader parses, from a file (read where asked,
 * so that a long road need not be in memory) or from a caller's buffer (the fuzz harnesses,
 * embedded data), and the lines of its text parts, with line numbers for messages.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_IO_SOURCE_H
#define TIRENV_IO_SOURCE_H

#include <stddef.h>

#include "tirenv/error.h"

/* A readable span of bytes. */
typedef struct {
    const unsigned char *mem; /* the caller's buffer, or NULL for a file */
    int fd;                   /* the open file when mem is NULL, else -1 */
    size_t size;              /* bytes in the file or buffer */
    char *name;               /* file name (or the caller's label) for messages; owned */
    int shared;               /* fd (or mem) belongs to another source or to an open road
                               * file (tirenv_road_file): close leaves it open */
} tirenv_source;

/* Opens path for reading; TIRENV_EIO naming the reason (a directory included). */
int tirenv_source__open_file(tirenv_source *s, const char *path, tirenv_diag *diag);

/* Wraps a buffer that must outlive the source; name labels messages. */
int tirenv_source__open_memory(tirenv_source *s, const void *data, size_t size,
                               const char *name, tirenv_diag *diag);

/* A source over an open regular file of size bytes that the caller keeps open (fd) and
 * closes after the source; name labels messages (copied). */
int tirenv_source__open_fd(tirenv_source *s, int fd, size_t size, const char *name,
                           tirenv_diag *diag);

/* s reads what from reads (the same file or buffer, which must outlive s), with its own
 * copy of the name. */
int tirenv_source__share(tirenv_source *s, const tirenv_source *from, tirenv_diag *diag);

/* Copies exactly n bytes from offset into buf; TIRENV_EIO if the file cannot be read or is
 * shorter (it changed under us). */
int tirenv_source__read(const tirenv_source *s, size_t offset, void *buf, size_t n,
                        tirenv_diag *diag);

/* Closes the file and frees the name; safe on a zeroed or failed source. */
void tirenv_source__close(tirenv_source *s);

/* Longest line the line reader accepts (characters, end of line excluded). */
#define TIRENV_SOURCE__MAX_LINE 65536

/* Reads lines one after the other from a byte offset. */
typedef struct {
    const tirenv_source *src;
    size_t pos;            /* offset of the next unread byte */
    size_t line;           /* 1-based number of the line last returned */
    size_t start;          /* offset of the line last returned */
    unsigned char *buf;    /* read-ahead window of the file */
    size_t buf_off, buf_len, buf_cap;
    char *text;            /* the line, without LF or CRLF, NUL-terminated */
    size_t len;            /* its length */
    size_t cap;
} tirenv_lines;

/* Starts reading at offset; line is the number the next line gets. */
int tirenv_lines__init(tirenv_lines *r, const tirenv_source *s, size_t offset, size_t line,
                       tirenv_diag *diag);

/* The next line in r->text: 1, or 0 at the end of the source, or a negated status (a NUL
 * byte, a line longer than TIRENV_SOURCE__MAX_LINE, a read error) with diag set. A last line
 * without an end-of-line character counts as a line. */
int tirenv_lines__next(tirenv_lines *r, tirenv_diag *diag);

/* Frees the buffers; safe twice. */
void tirenv_lines__free(tirenv_lines *r);

#endif
