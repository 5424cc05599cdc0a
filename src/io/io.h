/* SPDX-License-Identifier: Apache-2.0 */
/* The io module's interface to the auxiliary modules after it (formats, rig, dataset): the
 * byte-level readers their file readers are written with. As SQLite's btree.h beside
 * btreeInt.h, this header, named after its module, is what other modules may include; io's
 * other headers (fmt.h, tmpfiles.h, umask.h, ...) are its own. Not the user's: the names are
 * tirenv_<object>__ (internal, not exported by libtirenv.so), the user's are in
 * include/tirenv/. The layer check (cmake/CheckLayers.cmake) holds every auxiliary module to
 * this: its own headers, the public ones, and the interface header <module>/<module>.h of a
 * module before it.
 *
 *   - the "C" locale for the public entries that read or write numbers as text, whatever
 *     the host's LC_NUMERIC (TIRENV_NUMERIC_C);
 *   - a bounded text line of a FILE (tirenv_text__getline), for the readers that took
 *     getline's unbounded lines (csv_line.c, formats' propfile.c);
 *   - the bytes a road-file reader parses, from a file read where asked or a caller's buffer
 *     (tirenv_source__*), and the lines of its text parts (tirenv_lines__*): formats' RDF and
 *     OpenCRG readers;
 *   - small comma-separated files line by line (tirenv_csv__*), with the splitting, number
 *     parsing and file:line:column errors that the curve, rig-log, data-set and profile
 *     readers share;
 *   - the target of a temporary file's name (tirenv_tmp__target_of), for sweep's resume. */
#ifndef TIRENV_IO_IO_H
#define TIRENV_IO_IO_H

#include <locale.h>
#include <stddef.h>
#include <stdio.h>

#include "tirenv/error.h"

/* ---- numbers with '.' whatever the host's locale (c_numeric.c) ------------------------- */
/* The "C" locale on this thread from here to the end of the enclosing block (the end of a
 * public entry that reads or writes numbers as text), the host's restored then, on every
 * return path; blocks nest. */
#define TIRENV_NUMERIC_C()                                                                     \
    locale_t tirenv_numeric__before                                                            \
        __attribute__((cleanup(tirenv_numeric__leave), unused)) = tirenv_numeric__enter()
/* Its two halves: the thread's locale before (to restore), and the restore. */
locale_t tirenv_numeric__enter(void);
void tirenv_numeric__leave(locale_t *before);

/* ---- one line of a text file, with a length cap (text_line.c) -------------------------- */
/* getline grows its buffer without limit (/dev/zero as a file is one endless line) and
 * reports running out of memory as the end of the file; this reader stops at the cap and
 * says why it stopped. */

/* Longest line accepted (characters, end of line excluded): the cap the RDF and CRG readers
 * have (TIRENV_SOURCE__MAX_LINE). A profile row of a thousand tracks fits 25 times over. */
#define TIRENV_TEXT__MAX_LINE 65536

/* What tirenv_text__getline found. */
enum {
    TIRENV_TEXT__LINE = 1,   /* a line, in *buf */
    TIRENV_TEXT__EOF = 0,    /* the end of the file, no character read */
    TIRENV_TEXT__ERROR = -1, /* a read failed or memory ran out: errno says which */
    TIRENV_TEXT__LONG = -2   /* the line is longer than TIRENV_TEXT__MAX_LINE */
};

/* Reads the next line of fp into *buf (grown as needed; *cap its size), '\n' kept when there
 * is one, NUL-terminated, its length (NUL bytes within counted) in *len. Returns one of the
 * codes above; after TIRENV_TEXT__LONG the rest of the line is unread. */
int tirenv_text__getline(char **buf, size_t *cap, FILE *fp, size_t *len);

/* The error for a last line that holds data (not blank, not a comment) and has no line end:
 * the file ends inside the line, and a file cut there (a copy that stopped, a full disk)
 * reads as a shorter number or word ("0.12" of "0.125") that no check can tell from a whole
 * one. Every file tirenv writes ends its lines. TIRENV_EPARSE at line and column (the column
 * after the line's last character), field "". */
int tirenv_text__unterminated(tirenv_diag *diag, const char *file, size_t line, size_t column);

/* For a last line text that has no line end: TIRENV_OK where it holds only blanks (spaces,
 * tabs, CR) or a comment (its first other character one of comments), else
 * tirenv_text__unterminated's error, its column after the last character but CRs. */
int tirenv_text__check_unterminated(tirenv_diag *diag, const char *file, size_t line,
                                    const char *text, const char *comments);

/* ---- bytes of a file or buffer, and their lines (source.c) ------------------------------ */

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
    int eol;               /* 1: the line ended with LF; 0: the source ended first */
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

/* ---- comma-separated files line by line (csv_line.c) ------------------------------------ */

/* A file being read, and its current line. */
typedef struct {
    FILE *fp;
    const char *file;      /* name for messages */
    char *buf;             /* line buffer (tirenv_text__getline) */
    size_t cap;
    size_t line;           /* 1-based number of the current line */
    char *text;            /* current line without BOM and end-of-line characters */
    size_t length;         /* strlen(text) before splitting: the column after the last field */
    tirenv_diag *diag;
} tirenv_csv__reader;

/* One field of the current line, blanks around it removed in place. */
typedef struct {
    char *text;
    size_t column;         /* 1-based position in the line */
} tirenv_csv__field;

/* Opens path; TIRENV_EIO with the reason if it cannot. */
int tirenv_csv__open(tirenv_csv__reader *r, const char *path, tirenv_diag *diag);

/* Reads fp (an open stream, closed by tirenv_csv__close) as the file name; never fails. */
void tirenv_csv__open_stream(tirenv_csv__reader *r, FILE *fp, const char *name,
                             tirenv_diag *diag);

/* Advances to the next line with content, skipping blank lines and '#' comment lines;
 * accepts a UTF-8 byte-order mark and CRLF ends. Returns 1 for a line, 0 at the end of the
 * file, or a status negated (so < 0) with diag set: TIRENV_EIO on a read error, TIRENV_ENOMEM
 * when memory runs out, TIRENV_EPARSE for a NUL byte in a line (its column in diag) or a line
 * longer than TIRENV_TEXT__MAX_LINE characters (above). */
int tirenv_csv__next(tirenv_csv__reader *r);

/* Frees the buffer and closes the file; safe after a failed open. */
void tirenv_csv__close(tirenv_csv__reader *r);

/* Splits the current line at commas; stores at most max + 1 fields (so an extra one can be
 * pointed at) and returns how many there are. */
size_t tirenv_csv__split(tirenv_csv__reader *r, tirenv_csv__field f[], size_t max);

/* Records TIRENV_EPARSE at the current line and the given column, for the named field. */
int tirenv_csv__fail(const tirenv_csv__reader *r, size_t column, const char *field,
                     const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* Splits the current line and checks it is exactly the header names[0..n-1]. */
int tirenv_csv__header(tirenv_csv__reader *r, const char *const names[], size_t n);

/* Splits the current line into exactly n fields (f must hold n + 1); error otherwise, naming
 * the first missing column or pointing at the first extra one. */
int tirenv_csv__fields(tirenv_csv__reader *r, const char *const names[], size_t n,
                       tirenv_csv__field f[]);

/* strtod(s) that must take the whole of s: 0 with *out set, or -1 (empty, trailing text).
 * Plain decimals of at most 19 digits with powers of ten up to 22 (what CSV files hold) take
 * an exact fast path, several times faster than strtod and bit for bit the same value. */
int tirenv_csv__parse_double(const char *s, double *out);

/* strtod with an end-pointer check; refuses empty text, trailing characters, NaN, infinity
 * and overflow. */
int tirenv_csv__number(const tirenv_csv__reader *r, const tirenv_csv__field *f,
                       const char *name, double *out);

/* tirenv_csv__number within +-max: a value beyond is refused at its field, "NAME = TEXT is
 * beyond +-MAX; expected EXPECTED" (a reading, a length, a force: its unit). */
int tirenv_csv__number_within(const tirenv_csv__reader *r, const tirenv_csv__field *f,
                              const char *name, double max, const char *expected, double *out);

/* The header names joined with commas, for messages. */
void tirenv_csv__join(const char *const names[], size_t n, char *buf, size_t size);

/* ---- temporary files of the writes (tmpfiles.c) ---------------------------------------- */

/* 1 with the target's name in name (n bytes) if entry, a directory entry's name, is the
 * temporary file of a write in progress or cut short (".<name>.tirenv-tmp.<host>.<pid>.
 * <random>", include/tirenv/outfile.h); else 0. */
int tirenv_tmp__target_of(const char *entry, char *name, size_t n);

#endif
