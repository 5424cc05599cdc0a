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
    /* A model already set on this profile only changes its load (a table's next row): the
     * profile's own work (the network's decomposition of a road) is not done again. */
    int status = tirenv_model_profile(m) == p ? tirenv_model_set_load(m, load, diag)
                                              : tirenv_model_set(m, p, load, diag);
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

/* One row per load: the model is set on the profile once, then only its load changes. */
int tirenv_ride_table_fill(tirenv_model *model, const tirenv_profile *p, size_t m,
                           const double load[], double x0, double dx, size_t n, double w[],
                           tirenv_diag *diag)
{
    if (!load || m < 1)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "load", "expected at least one load");
    int status = TIRENV_OK;
    for (size_t j = 0; j < m && !status; ++j)
        status = tirenv_ride_effective(model, p, load[j], x0, dx, n, w + j * n, diag);
    return status;
}
