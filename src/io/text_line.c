/* SPDX-License-Identifier: Apache-2.0 */
/* One capped line of a text file (io.h, tirenv_text__getline). */
#include "io/io.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

int tirenv_text__getline(char **buf, size_t *cap, FILE *fp, size_t *len)
{
    size_t n = 0;
    int c = EOF;
    *len = 0;
    flockfile(fp);
    for (;;) {
        /* Room for this character, a possible '\n' and the NUL; the buffer doubles up to the
         * cap, so a long line costs a handful of reallocations, never one per character. */
        if (n + 2 > *cap) {
            const size_t want = *cap < 128 ? 128 : 2 * *cap;
            const size_t limit = TIRENV_TEXT__MAX_LINE + 3;
            const size_t size = want < limit ? want : limit;
            if (size <= *cap) {  /* cannot happen below the cap: the check below stops first */
                funlockfile(fp);
                errno = EOVERFLOW;
                return TIRENV_TEXT__ERROR;
            }
            char *b = realloc(*buf, size);
            if (!b) {
                funlockfile(fp);
                errno = ENOMEM;
                return TIRENV_TEXT__ERROR;
            }
            *buf = b;
            *cap = size;
        }
        c = getc_unlocked(fp);
        if (c == EOF)
            break;
        if (c != '\n' && n >= TIRENV_TEXT__MAX_LINE) {
            /* A '\r' before the '\n' is part of the line end: allowed one past the cap. */
            if (!(c == '\r' && n == TIRENV_TEXT__MAX_LINE)) {
                funlockfile(fp);
                return TIRENV_TEXT__LONG;
            }
        }
        (*buf)[n++] = (char)c;
        if (c == '\n')
            break;
    }
    const int failed = c == EOF && ferror(fp);
    const int saved = errno;
    funlockfile(fp);
    (*buf)[n] = '\0';
    *len = n;
    if (failed) {
        errno = saved ? saved : EIO;
        return TIRENV_TEXT__ERROR;
    }
    return n > 0 ? TIRENV_TEXT__LINE : TIRENV_TEXT__EOF;
}

int tirenv_text__unterminated(tirenv_diag *diag, const char *file, size_t line, size_t column)
{
    const int status = tirenv_error(diag, TIRENV_EPARSE, file, line, "",
                                    "the file ends inside this line, which has no line end "
                                    "(cut short?); expected a line end after its last "
                                    "character (add one if the file is whole)");
    if (diag)
        diag->column = column;
    return status;
}

int tirenv_text__check_unterminated(tirenv_diag *diag, const char *file, size_t line,
                                    const char *text, const char *comments)
{
    const char *p = text + strspn(text, " \t\r");
    if (!*p || strchr(comments, *p))
        return TIRENV_OK;
    size_t n = strlen(text);
    while (n > 0 && text[n - 1] == '\r')
        n--;
    return tirenv_text__unterminated(diag, file, line, n + 1);
}
