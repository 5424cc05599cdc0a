/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the .tir reader (tir.c) and the derivation (tir_derive.c): the read that keeps
 * the file's bytes, so that the derivation reads them and not the file a second time. */
#ifndef TIRENV_FORMATS_TIR_IMPL_H
#define TIRENV_FORMATS_TIR_IMPL_H

#include <stddef.h>

#include "tirenv/error.h"
#include "tirenv/tire.h"

/* tirenv_tir_read, with the bytes read in *text (*len bytes, malloc'd, the caller frees)
 * when text is not NULL (tirenv_propfile__read_kept). */
int tirenv_tir__read_kept(const char *path, tirenv_tire *tire, char **text, size_t *len,
                          tirenv_diag *diag);

#endif
