/* Private to the auxiliary layer: .tir writing beyond tirenv_tir_write (src/formats/tir.c).
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_TIR_IMPL_H
#define TIRENV_TIR_IMPL_H

#include "tirenv/error.h"
#include "tirenv/tire.h"

/* Writes *tire as tirenv_tir_write does, with note (lines separated by '\n') as '!'
 * comment lines after the [MDI_HEADER] keys in place of tirenv's own preamble: no tirenv
 * version, for files that must stay the same bytes across versions (a data set's
 * tire.tir). */
int tirenv_tir__write_noted(const char *path, const tirenv_tire *tire, const char *note,
                            tirenv_diag *diag);

#endif
