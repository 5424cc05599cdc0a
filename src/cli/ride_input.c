/* What one axle's tires follow, for any model type: shared by tirenv ride and tirenv bench.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/ride_cli.h"

int ride_cli_axle_input(const tirenv_model_type *type, const tirenv_tire *tire, double load,
                        const tirenv_profile *p, const tirenv_nn *nn, double R0_nn, double x0,
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

const char *ride_enveloping_name(ride_enveloping e)
{
    static const char *const names[RIDE_N_ENVELOPING] = {"static", "dynamic", "direct"};
    return (size_t)e < RIDE_N_ENVELOPING ? names[e] : "unknown";
}

/* The loads of a table, as factors of the static load (docs/models.md section 9.5): from a
 * tenth, below which a tire is nearly off the ground, to three times, beyond which the loads
 * over the demo's cleats do not go; closer at light loads, where the patch and with it the
 * enveloping change fastest (like the square root of the deflection). 1 is a row, so that a
 * tire at its static load follows the static input (exactly, but for the springs and the
 * ring, whose rows after the first come from tirenv_model_set_load: within the equilibrium's
 * tolerance). */
static const double table_factors[] = {0.1, 0.2,  0.3, 0.4,  0.55, 0.7, 0.85,
                                       1.0, 1.2, 1.45, 1.75, 2.1, 2.5, 3.0};

size_t ride_cli_table_loads(double G0, double load[])
{
    const size_t m = sizeof table_factors / sizeof table_factors[0];
    for (size_t j = 0; j < m; ++j)
        load[j] = table_factors[j] * G0;
    return m;
}

int ride_cli_axle_table(const tirenv_model_type *type, const tirenv_tire *tire, double G0,
                        const tirenv_profile *p, const tirenv_nn *nn, double R0_nn, double x0,
                        double dx, size_t n, tirenv_ride_table *table, char *warnings,
                        size_t warnings_size, tirenv_diag *diag)
{
    double want[RIDE_TABLE_LOADS];
    const size_t m_want = ride_cli_table_loads(G0, want);
    *table = (tirenv_ride_table){.x0 = x0, .dx = dx, .n = n, .m = 0};
    double *load = malloc(m_want * sizeof *load), *w = malloc(m_want * n * sizeof *w);
    tirenv_model *m = tirenv_model_alloc(type, tire);
    int status = load && w && m ? TIRENV_OK
                                : tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    if (!status && (tirenv_model_type_flags(type) & TIRENV_MODEL_NEEDS_NETWORK))
        status = nn ? tirenv_model_set_network(m, nn, R0_nn, diag)
                    : tirenv_error(diag, TIRENV_EINVAL, "", 0, "network",
                                   "the %s model needs a trained network",
                                   tirenv_model_type_name(type));
    size_t rows = 0;
    /* The warnings of the static load's row, then of the lightest and the heaviest rows if
     * they have their own (the network's contact length leaving its trained range). */
    char ends[2][512] = {"", ""};
    if (warnings && warnings_size)
        warnings[0] = '\0';
    for (size_t j = 0; j < m_want && !status; ++j) {
        tirenv_diag d;
        const int s = tirenv_ride_effective(m, p, want[j], x0, dx, n, w + rows * n, &d);
        if (s && want[j] == G0) {
            *diag = d;  /* the static load must work: the static input is that row */
            status = s;
        } else if (s && want[j] > G0) {
            break;      /* heavier than the model takes: the last row holds beyond */
        } else if (!s) {
            const char *said = tirenv_model_warnings(m);
            if (want[j] == G0 && warnings && warnings_size)
                snprintf(warnings, warnings_size, "%s", said);
            else if (said[0] && (rows == 0 || want[j] > G0))
                snprintf(ends[rows == 0 ? 0 : 1], sizeof ends[0], "table row at %.6g N: %.400s",
                         want[j], said);
            load[rows++] = want[j];
        }
    }
    for (int e = 0; e < 2 && warnings && warnings_size; ++e)
        if (ends[e][0]) {
            const size_t used = strlen(warnings);
            snprintf(warnings + used, warnings_size - used, "%s%s", used ? "\n" : "", ends[e]);
        }
    /* Rows all alike: the model's road does not depend on the load (rigid, point). */
    int alike = rows > 1;
    for (size_t k = n; alike && k < rows * n; ++k)
        alike = memcmp(&w[k], &w[k % n], sizeof *w) == 0;
    if (alike) {
        for (size_t j = 0; j < rows; ++j)
            if (load[j] == G0)
                memmove(w, w + j * n, n * sizeof *w);
        load[0] = G0;
        rows = 1;
    }
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

int ride_cli_direct_input(void *ctx, double x, double load, double *w, double *dw_dx,
                          tirenv_diag *diag)
{
    ride_direct *d = ctx;
    tirenv_point lo, mid, hi;
    const double h = 0.5 * d->dx;
    int status = tirenv_model_set_load(d->m, load, diag);
    if (!status)
        status = tirenv_model_eval(d->m, x - h, &lo, diag);
    if (!status)
        status = tirenv_model_eval(d->m, x, &mid, diag);
    if (!status)
        status = tirenv_model_eval(d->m, x + h, &hi, diag);
    if (status)
        return status;
    *w = mid.h;
    *dw_dx = (hi.h - lo.h) / (2 * h);
    return TIRENV_OK;
}
