/* What each axle's tires follow: the raw profile (point contact) or a model's effective
 * profile at the axle's static tire load (docs/models.md section 9.2).
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "tirenv/ride.h"

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
    for (size_t k = 0; k < n && !status; ++k) {
        tirenv_point pt;
        if (!(status = tirenv_model_eval(m, x0 + (double)k * dx, &pt, diag)))
            w[k] = pt.h;
    }
    return status;
}
