/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: .tir tire property files (MF-Tyre's layout; docs/formats.md section 2). */
#ifndef TIRENV_TIR_H
#define TIRENV_TIR_H

#include "tirenv/decls.h"
#include "tirenv/error.h"
#include "tirenv/tire.h"

TIRENV_BEGIN_DECLS

/* Reads a .tir file (sections in brackets, KEY = value, '$' comments, [UNITS] in SI) into
 * *tire, overriding only the keys present. Keys this library knows (see data/tires/default.tir)
 * are checked; sections it does not know are skipped so that MF-Tyre files load unchanged.
 * Errors name file, line and key. On failure *tire is unchanged. */
int tirenv_tir_read(const char *path, tirenv_tire *tire, tirenv_diag *diag);

/* Applies one "KEY=VALUE" override (KEY as in the .tir file, e.g. RADIAL_STIFFNESS=1.6e6),
 * as the --set option does. On failure *tire is unchanged. */
int tirenv_tir_set(tirenv_tire *tire, const char *assignment, tirenv_diag *diag);

/* Writes *tire as a .tir file (atomically: all or nothing). */
int tirenv_tir_write(const char *path, const tirenv_tire *tire, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
