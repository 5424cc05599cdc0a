/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the auxiliary layer (src/io): one line of a text file with a length cap, for the readers that took
 * getline's unbounded lines (csv_line.c, propfile.c). getline grows its buffer without limit
 * (/dev/zero as a file is one endless line) and reports running out of memory as the end of
 * the file; this reader stops at the cap and says why it stopped. */
#ifndef TIRENV_TEXT_LINE_H
#define TIRENV_TEXT_LINE_H

#include <stddef.h>
#include <stdio.h>

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

#endif
