/* What one axle's tires follow, for any model type: shared by tirenv ride and tirenv bench.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <stdio.h>

#include "cli/ride_cli.h"

int ride_cli_axle_input(const tirenv_model_type *type, const tirenv_tire *tire, double load,
                        const tirenv_profile *p, const tirenv_nn *nn, double R0_nn,
                        int extrapolate, double x0,
                        double dx, size_t n, double w[], char *warnings, size_t warnings_size,
                        tirenv_diag *diag)
{
    /* A tire file without MF-Swift's cam data would give the cam another tire's shape. */
    if (type == tirenv_model_cam) {
        const int status = tirenv_tire_check_cam_keys(tire, diag);
        if (status)
            return status;
    }
    tirenv_model *m = tirenv_model_alloc(type, tire);
    int status = m ? TIRENV_OK : tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    if (m)
        tirenv_model_set_extrapolate(m, extrapolate);
    if (!status && (tirenv_model_type_flags(type) & TIRENV_MODEL_NEEDS_NETWORK))
        status = nn ? tirenv_model_set_network(m, nn, R0_nn, diag)
                    : tirenv_error(diag, TIRENV_EINVAL, "", 0, "network",
                                   "the %s model needs a trained network",
                                   tirenv_model_type_name(type));
    if (!status)
        status = tirenv_ride_effective(m, p, load, x0, dx, n, w, diag);
    if (warnings && warnings_size)
        snprintf(warnings, warnings_size, "%s", !status ? tirenv_model_warnings(m) : "");
    tirenv_model_free(m);
    return status;
}
