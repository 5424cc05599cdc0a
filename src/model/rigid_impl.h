/* Private: the rigid disc with a search hint, for sweeps that call it position after position. */
#ifndef TIRENV_RIGID_IMPL_H
#define TIRENV_RIGID_IMPL_H

#include <stddef.h>
#include "tirenv/profile.h"

/* tirenv_rigid_height, starting its search for x's segment from *hint (any index; updated to
 * x's segment). The result is the same as without the hint. */
double tirenv_rigid__height_hint(const tirenv_profile *p, double R0, double x, size_t *hint,
                                 double *px, double *pz);

#endif
