/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: profiles as CSV (docs/formats.md section 4), read whole; a vertex at a time through
 * the one streaming reader of every road format, tirenv_profile_file_reader (profile_file.h). */
#ifndef TIRENV_PROFILE_CSV_H
#define TIRENV_PROFILE_CSV_H

#include "tirenv/decls.h"
#include "tirenv/error.h"
#include "tirenv/profile.h"

TIRENV_BEGIN_DECLS

/* Reads a profile CSV: header "x_m,z_m", one vertex per line, '#' comment lines and blank
 * lines allowed. Errors name file, line and column. *out is NULL on failure. */
int tirenv_profile_read_csv(const char *path, tirenv_profile **out, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
