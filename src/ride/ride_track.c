/* What each axle's tires follow: a model's effective profile at the axle's static tire load,
 * the point contact's being the raw profile (docs/models.md section 9.2).
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/ride.h"

#include <stdio.h>
#include <string.h>

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

/* Factors of the static load (docs/models.md section 9.5): from a tenth, below which a tire is
 * nearly off the ground, to three times, beyond which the loads over the demo's cleats do not
 * go; closer at light loads, where the patch and with it the enveloping change fastest (like
 * the square root of the deflection). 1 is a row, so that a tire at its static load follows
 * the static input (exactly, but for the springs and the ring, whose rows after the first come
 * from tirenv_model_set_load: within the equilibrium's tolerance). */
static const double table_factors[TIRENV_RIDE_TABLE_LOADS] = {
    0.1, 0.2, 0.3, 0.4, 0.55, 0.7, 0.85, 1.0, 1.2, 1.45, 1.75, 2.1, 2.5, 3.0};

void tirenv_ride_table_loads(double G0, double load[])
{
    for (size_t j = 0; j < TIRENV_RIDE_TABLE_LOADS; ++j)
        load[j] = table_factors[j] * G0;
}

int tirenv_ride_table_build(tirenv_model *model, const tirenv_profile *p, double G0, double x0,
                            double dx, size_t n, double load[], double w[], size_t *rows,
                            char *warnings, size_t warnings_size, tirenv_diag *diag)
{
    double want[TIRENV_RIDE_TABLE_LOADS];
    tirenv_ride_table_loads(G0, want);
    /* The warnings of G0's row, then of the lightest and the heaviest rows if they have their
     * own (the network's contact length leaving its trained range). */
    char end_said[2][512] = {"", ""};
    double end_load[2] = {0, 0};
    if (warnings && warnings_size)
        warnings[0] = '\0';
    size_t m = 0;
    int status = TIRENV_OK;
    for (size_t j = 0; j < TIRENV_RIDE_TABLE_LOADS && !status; ++j) {
        tirenv_diag d;
        const int s = tirenv_ride_effective(model, p, want[j], x0, dx, n, w + m * n, &d);
        if (s && want[j] == G0) {
            if (diag)
                *diag = d;  /* the static load must work: the static input is that row */
            status = s;
        } else if (s && want[j] > G0) {
            break;      /* heavier than the model takes: the last row holds beyond */
        } else if (!s) {
            const char *said = tirenv_model_warnings(model);
            if (want[j] == G0 && warnings && warnings_size)
                snprintf(warnings, warnings_size, "%s", said);
            else if (said[0] && (m == 0 || want[j] > G0)) {
                end_load[m == 0 ? 0 : 1] = want[j];
                snprintf(end_said[m == 0 ? 0 : 1], sizeof end_said[0], "%s", said);
            }
            load[m++] = want[j];
        }
    }
    if (status)
        return status;
    /* An end row's own warnings only: the cam's, of the ground, are G0's too. */
    for (int e = 0; e < 2 && warnings && warnings_size; ++e)
        if (end_said[e][0] && strncmp(end_said[e], warnings, sizeof end_said[e] - 1)) {
            const size_t used = strlen(warnings);
            snprintf(warnings + used, warnings_size - used, "%stable row at %.6g N: %.400s",
                     used ? "\n" : "", end_load[e], end_said[e]);
        }
    int alike = m > 1;
    for (size_t k = n; alike && k < m * n; ++k)
        alike = memcmp(&w[k], &w[k % n], sizeof *w) == 0;
    if (alike) {
        load[0] = G0;
        m = 1;
    }
    *rows = m;
    return TIRENV_OK;
}
