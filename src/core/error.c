/* SPDX-License-Identifier: Apache-2.0 */
/* One place where every error is recorded, and the table of their descriptions. */
#include "tirenv/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

const char *tirenv_strerror(int status)
{
    switch (status) {
    case TIRENV_OK: return "success";
    case TIRENV_EINVAL: return "invalid argument or unphysical parameter";
    case TIRENV_ENOMEM: return "out of memory";
    case TIRENV_EIO: return "input/output error";
    case TIRENV_EPARSE: return "malformed file";
    case TIRENV_ENOBRACKET: return "no equilibrium: load beyond what the tire can carry";
    case TIRENV_ENOCONV: return "iteration did not converge";
    case TIRENV_ECONTINUE: return "not converged yet";
    case TIRENV_ERANGE: return "value outside the model's domain";
    default: return "unknown status";
    }
}

void tirenv_diag_clear(tirenv_diag *diag)
{
    if (diag)
        memset(diag, 0, sizeof *diag);
}

static void copy_string(char *dst, size_t n, const char *src)
{
    snprintf(dst, n, "%s", src ? src : "");
}

int tirenv_error(tirenv_diag *diag, int status, const char *file, size_t line,
                 const char *field, const char *fmt, ...)
{
    if (!diag)
        return status;
    copy_string(diag->file, sizeof diag->file, file);
    diag->line = line;
    diag->column = 0;
    copy_string(diag->field, sizeof diag->field, field);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(diag->message, sizeof diag->message, fmt, ap);
    va_end(ap);
    return status;
}

char *tirenv_diag_format(const tirenv_diag *diag, char *buf, size_t n)
{
    size_t k = 0;
#define APPEND(...)                                                                          \
    do {                                                                                     \
        if (k < n) {                                                                         \
            const int r = snprintf(buf + k, n - k, __VA_ARGS__);                             \
            k += r > 0 ? (size_t)r : 0;                                                      \
        }                                                                                    \
    } while (0)
    if (n == 0)
        return buf;
    buf[0] = '\0';
    if (diag->file[0]) {
        APPEND("%s", diag->file);
        if (diag->line)
            APPEND(":%zu", diag->line);
        if (diag->line && diag->column)
            APPEND(":%zu", diag->column);
        APPEND(": ");
    }
    if (diag->field[0])
        APPEND("%s: ", diag->field);
    APPEND("%s", diag->message);
#undef APPEND
    return buf;
}
