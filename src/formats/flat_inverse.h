/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the auxiliary layer: a model's flat-ground load at a given deflection, the
 * inverse of tirenv_model_flat that the derivation of a tire's models from MF-Tyre data
 * (src/formats/tir_derive.c) and their identification on a reference (src/study/identify.c)
 * share. */
#ifndef TIRENV_FLAT_INVERSE_H
#define TIRENV_FLAT_INVERSE_H

#include "tirenv/model.h"

/* The load G (N) at which the model's flat-ground deflection R0 - z_flat is d (m), 0 < d <
 * R0. The deflection grows with the load in every model, so the root is bracketed by
 * doubling a trial load from guess (N, > 0) and narrowed by the Illinois method until the
 * deflection is within 1e-9 relative of d. TIRENV_ENOBRACKET or TIRENV_ERANGE (from
 * tirenv_model_flat) when the model cannot reach d within its valid range; TIRENV_ENOCONV
 * with the last bracket in diag if 200 evaluations do not converge. */
int tirenv_flat__load_at_deflection(tirenv_model *m, double d, double guess, double *G,
                                    tirenv_diag *diag);

#endif
