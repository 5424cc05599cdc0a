/* What one axle's tires follow, by model name: shared by tirenv ride and tirenv bench.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <stdlib.h>
#include <string.h>

#include "cli/ride_cli.h"

/* The network over the profile at the springs model's contact length for this tire and load
 * (as 'tirenv predict --load' turns a load into the network's regime). */
static int nn_input(const tirenv_tire *tire, double load, const tirenv_profile *p,
                    const tirenv_nn *nn, double R0_nn, double x0, double dx, size_t n,
                    double w[], tirenv_nn_road_info *info, tirenv_diag *diag)
{
    tirenv_model *springs = tirenv_model_alloc(tirenv_model_springs, tire);
    double *x = malloc(n * sizeof *x);
    tirenv_flat flat;
    tirenv_nn_road *road = NULL;
    int status = springs && x ? tirenv_model_flat(springs, load, &flat, diag)
                              : tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    for (size_t k = 0; !status && k < n; ++k)
        x[k] = x0 + (double)k * dx;
    if (!status)
        status = tirenv_nn_road_alloc(nn, R0_nn, flat.contact_length, p, NULL, &road, diag);
    if (!status)
        status = tirenv_nn_road_eval(road, n, x, w, NULL, diag);
    if (!status && info)
        *info = tirenv_nn_road_get_info(road);
    tirenv_nn_road_free(road);
    tirenv_model_free(springs);
    free(x);
    return status;
}

int ride_cli_axle_input(const char *model, const tirenv_tire *tire, double load,
                        const tirenv_profile *p, const tirenv_nn *nn, double R0_nn, double x0,
                        double dx, size_t n, double w[], tirenv_nn_road_info *info,
                        tirenv_diag *diag)
{
    if (strcmp(model, "nn") == 0)
        return nn_input(tire, load, p, nn, R0_nn, x0, dx, n, w, info, diag);
    const tirenv_model_type *type = strcmp(model, "point") == 0 ? NULL
                                                                : tirenv_model_type_find(model);
    int status = type == tirenv_model_cam ? tirenv_tire_check_cam_keys(tire, diag) : TIRENV_OK;
    if (status)
        return status;
    tirenv_model *m = type ? tirenv_model_alloc(type, tire) : NULL;
    if (type && !m)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    status = tirenv_ride_effective(m, p, load, x0, dx, n, w, diag);
    tirenv_model_free(m);
    return status;
}
