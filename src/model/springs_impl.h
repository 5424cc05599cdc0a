/* Private: the pieces of the springs model (docs/models.md section 4), one file each. */
#ifndef TIRENV_SPRINGS_IMPL_H
#define TIRENV_SPRINGS_IMPL_H

#include <stddef.h>
#include "tirenv/profile.h"

/* Ray casting: distance rho (m) from the centre (x, z) along u = (sin_t, -cos_t) to the first
 * crossing of the ground boundary, or INFINITY if there is none within rho_max. drho_dz is
 * d(rho)/dz with the hit segment fixed (0 on a vertical wall). A centre on or below the ground
 * gives rho = 0. */
double tirenv_springs__ray(const tirenv_profile *p, double x, double z, double sin_t,
                           double cos_t, double rho_max, double *drho_dz);

/* The same, given k = tirenv_profile__segment_at(p, x) and g = tirenv_profile_height(p, x)
 * (m), which do not depend on the ray: bit for bit the result of tirenv_springs__ray. */
double tirenv_springs__ray_at(const tirenv_profile *p, double x, size_t k, double g, double z,
                              double sin_t, double cos_t, double rho_max, double *drho_dz);

/* A tridiagonal obstacle problem K w = p, w >= d, p >= 0, p.(w - d) = 0 with K given by its
 * diagonal diag[0..n-1] and constant off-diagonal -k_ir, solved by the primal-dual active
 * set method. active[] holds the starting guess (1 = w_i = d_i) and returns the final set.
 * work holds 2*n doubles and keeps the factorisation for tirenv_springs__lcp_tangent. */
int tirenv_springs__lcp(size_t n, const double diag[], double k_ir, const double d[],
                        double w[], double p[], unsigned char active[], double work[],
                        size_t max_passes, size_t *passes);

/* With the active set and factorisation of the last tirenv_springs__lcp call: dw (m/m) for a
 * change dd of the obstacle on the active elements (inactive entries of dd are ignored). */
void tirenv_springs__lcp_tangent(size_t n, double k_ir, const double dd[],
                                 const unsigned char active[], const double work[],
                                 double dw[]);

#endif
