/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: the rigid disc over a profile, the geometric limit (docs/models.md section 3). */
#ifndef TIRENV_RIGID_H
#define TIRENV_RIGID_H

#include "tirenv/decls.h"
#include "tirenv/profile.h"

TIRENV_BEGIN_DECLS

/* Exact centre height (m) of a rigid disc of radius R0 (m) resting on the profile at x (m):
 * max over boundary points p of p_z + sqrt(R0^2 - (x - p_x)^2). The touching point is stored
 * in *px, *pz (m) if not NULL. */
double tirenv_rigid_height(const tirenv_profile *p, double R0, double x, double *px,
                           double *pz);

TIRENV_END_DECLS
#endif
