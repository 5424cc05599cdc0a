/* What each axle's tires follow: a model's effective profile at the axle's static tire load,
 * the point contact's being the raw profile (docs/models.md section 9.2).
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "tirenv/ride.h"

/* Positions per call of tirenv_model_envelope: the network evaluates them as one batch. */
enum { RIDE_BLOCK = 256 };

int tirenv_ride_effective(tirenv_model *m, const tirenv_profile *p, double load, double x0,
                          double dx, size_t n, double w[], tirenv_diag *diag)
{
    if (!p || !w || !(dx > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "expected a profile, an output "
                            "array and dx > 0 m");
    if (!m) {
        for (size_t k = 0; k < n; ++k)
            w[k] = tirenv_profile_height(p, x0 + (double)k * dx);
        return TIRENV_OK;
    }
    int status = tirenv_model_set(m, p, load, diag);
    double x[RIDE_BLOCK];
    tirenv_point pt[RIDE_BLOCK];
    for (size_t k0 = 0; k0 < n && !status; k0 += RIDE_BLOCK) {
        const size_t b = n - k0 < RIDE_BLOCK ? n - k0 : RIDE_BLOCK;
        for (size_t k = 0; k < b; ++k)
            x[k] = x0 + (double)(k0 + k) * dx;
        status = tirenv_model_envelope(m, b, x, pt, NULL, diag);
        for (size_t k = 0; k < b && !status; ++k)
            w[k0 + k] = pt[k].h;
    }
    return status;
}
