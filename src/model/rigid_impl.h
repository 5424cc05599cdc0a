/* SPDX-License-Identifier: Apache-2.0 */
/* Private: the rigid disc with a search hint, for sweeps that call it position after position. */
#ifndef TIRENV_RIGID_IMPL_H
#define TIRENV_RIGID_IMPL_H

#include <stddef.h>
#include "tirenv/profile.h"

/* tirenv_rigid_height, starting its search for x's segment from *hint (any index; updated to
 * x's segment). The result is the same as without the hint. */
double tirenv_rigid__height_hint(const tirenv_profile *p, double R0, double x, size_t *hint,
                                 double *px, double *pz);

/* The bracket of the equilibrium at x (docs/models.md sections 11.1 and 13.2) for n >= 1
 * tracks under one rim of free radius R0 (m): *z_lo the highest ground under the centre (m;
 * lower, the rim would be in the ground), *z_hi the highest rigid-disc height (m; above it no
 * track touches). hint[k] is track k's segment hint, as tirenv_rigid__height_hint's. */
void tirenv_rigid__bracket(size_t n, const tirenv_profile *const p[], double R0, double x,
                           size_t hint[], double *z_lo, double *z_hi);

#endif
