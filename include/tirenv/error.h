/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: status codes and error details shared by every module. The library holds no
 * process-wide error state and installs no handler: every failure, its own or a numerical
 * one (a root not bracketed, an integrator that cannot keep its tolerance), comes back as a
 * status and a tirenv_diag.
 *
 * Pointer arguments: a diag may always be NULL, a _free function takes NULL as a no-op, and
 * any other pointer may be NULL only where its function's comment says so (many refuse it
 * with TIRENV_EINVAL as well, but that is a courtesy, not a promise): as in the C library, a
 * NULL the comment does not allow is the caller's error. */
#ifndef TIRENV_ERROR_H
#define TIRENV_ERROR_H

#include "tirenv/decls.h"
#include <stddef.h>

TIRENV_BEGIN_DECLS

/* Every function that can fail returns one of these; 0 is success. */
typedef enum {
    TIRENV_OK = 0,       /* success */
    TIRENV_EINVAL,       /* an argument or parameter is invalid or unphysical */
    TIRENV_ENOMEM,       /* an allocation failed */
    TIRENV_EIO,          /* a file could not be opened, read or written */
    TIRENV_EPARSE,       /* a file is malformed (see tirenv_diag for file, line, field) */
    TIRENV_ENOBRACKET,   /* no equilibrium exists: the load exceeds what the tire can carry */
    TIRENV_ENOCONV,      /* an iteration stopped before meeting its tolerances */
    TIRENV_ECONTINUE,    /* not converged yet: iterate again (not a failure) */
    TIRENV_ERANGE        /* a value lies outside the model's domain (e.g. obstacle too tall) */
} tirenv_status;

/* A static, human-readable description of a status code; never NULL. */
const char *tirenv_strerror(int status);

/* Where and why a parser or solver failed, for the caller to print (the library never prints).
 * line and column are 1-based; 0 means "not applicable". Every function's tirenv_diag *diag
 * may be NULL: the status alone then says what failed. */
typedef struct {
    char file[512];      /* file name, or "" */
    size_t line;         /* 1-based line, or 0 */
    size_t column;       /* 1-based column, or 0 */
    char field[64];      /* key or column name, or "" */
    char message[512];   /* what is wrong and what was expected */
} tirenv_diag;

/* Clears a diagnostic (all fields empty / zero); NULL is a no-op. */
void tirenv_diag_clear(tirenv_diag *diag);

/* Records a failure in diag (if not NULL) with a printf-style message and returns status.
 * Every error in the library flows through here, so one breakpoint catches all. */
int tirenv_error(tirenv_diag *diag, int status, const char *file, size_t line,
                 const char *field, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 7)))
#endif
    ;

/* Formats diag as one line "file:line:column: field: message" (omitting empty parts) into
 * buf of size n; returns buf. */
char *tirenv_diag_format(const tirenv_diag *diag, char *buf, size_t n);

TIRENV_END_DECLS
#endif
