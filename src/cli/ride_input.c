/* What one axle's tires follow, for any model type: shared by tirenv ride and tirenv bench.
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/ride_cli.h"

static tirenv_contact_law nn_law;

void ride_cli_set_nn_law(const char *nn_path, const tirenv_contact_law *law)
{
    if (!law->n && !nn_law.n)
        fprintf(stderr, "tirenv: ride: warning: %s records no relation between load and "
                "contact length of its tire (training.data.contact_law; a file written before "
                "tirenv recorded it): loads become contact lengths by the springs model of "
                "the tire file; train it again to record it\n", nn_path);
    nn_law = *law;
}

int ride_cli_axle_model(const tirenv_model_type *type, const tirenv_tire *tire,
                        const tirenv_nn *nn, double R0_nn, int extrapolate, tirenv_model **m,
                        tirenv_diag *diag)
{
    *m = NULL;
    /* A tire file without MF-Swift's cam data would give the cam another tire's shape. */
    if (type == tirenv_model_cam) {
        const int status = tirenv_tire_check_cam_keys(tire, diag);
        if (status)
            return status;
    }
    if (!(*m = tirenv_model_alloc(type, tire)))
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    tirenv_model_set_extrapolate(*m, extrapolate);
    if (!(tirenv_model_type_flags(type) & TIRENV_MODEL_NEEDS_NETWORK))
        return TIRENV_OK;
    int status = nn ? tirenv_model_set_network(*m, nn, R0_nn, diag)
                    : tirenv_error(diag, TIRENV_EINVAL, "", 0, "network",
                                   "the %s model needs a trained network",
                                   tirenv_model_type_name(type));
    if (!status && nn_law.n)
        status = tirenv_model_set_contact_law(*m, &nn_law, diag);
    return status;
}

int ride_cli_axle_input(const tirenv_model_type *type, const tirenv_tire *tire, double load,
                        const tirenv_profile *p, const tirenv_nn *nn, double R0_nn,
                        int extrapolate, double x0,
                        double dx, size_t n, double w[], char *warnings, size_t warnings_size,
                        tirenv_diag *diag)
{
    tirenv_model *m;
    int status = ride_cli_axle_model(type, tire, nn, R0_nn, extrapolate, &m, diag);
    if (!status)
        status = tirenv_ride_effective(m, p, load, x0, dx, n, w, diag);
    if (warnings && warnings_size)
        snprintf(warnings, warnings_size, "%s", !status ? tirenv_model_warnings(m) : "");
    tirenv_model_free(m);
    return status;
}

int ride_cli_axle_table(const tirenv_model_type *type, const tirenv_tire *tire, double G0,
                        const tirenv_profile *p, const tirenv_nn *nn, double R0_nn,
                        int extrapolate, double x0, double dx, size_t n,
                        tirenv_ride_table *table, char *warnings, size_t warnings_size,
                        tirenv_diag *diag)
{
    *table = (tirenv_ride_table){.x0 = x0, .dx = dx, .n = n, .m = 0};
    double *load = malloc(TIRENV_RIDE_TABLE_LOADS * sizeof *load);
    double *w = malloc(TIRENV_RIDE_TABLE_LOADS * n * sizeof *w);
    tirenv_model *m = NULL;
    int status = load && w ? ride_cli_axle_model(type, tire, nn, R0_nn, extrapolate, &m, diag)
                           : tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    size_t rows = 0;
    if (!status)
        status = tirenv_ride_table_build(m, p, G0, x0, dx, n, load, w, &rows, warnings,
                                         warnings_size, diag);
    tirenv_model_free(m);
    if (status) {
        free(load);
        free(w);
        return status;
    }
    table->m = rows;
    table->load = load;
    table->w = w;
    return TIRENV_OK;
}
