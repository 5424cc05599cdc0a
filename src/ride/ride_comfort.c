/* SPDX-License-Identifier: Apache-2.0 */
/* What the driver feels over a ride run (tirenv_ride_comfort_measure, docs/models.md section
 * 10.4): the seat's vertical axis weighted by Wk, the body's pitch by We, their vibration
 * total value, the largest unweighted seat acceleration and the time with a tire off the
 * ground. The CLI's table and the Python module's Ride.comfort are this function's output. */
#include <math.h>
#include <stdlib.h>

#include "tirenv/comfort.h"
#include "tirenv/ride.h"

int tirenv_ride_comfort_measure(const tirenv_ride_sample s[], size_t n, double dt,
                                double seat_awz[], tirenv_ride_comfort *c, tirenv_diag *diag)
{
    if (!(dt > 0 && isfinite(dt)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dt",
                            "expected an output interval > 0 in s, got %g", dt);
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "samples", "a run of no samples");
    const double fs = 1 / dt;
    double *a = malloc(n * sizeof *a);
    double *own = seat_awz ? NULL : malloc(n * sizeof *own);
    if (!a || (!seat_awz && !own)) {
        free(a);
        free(own);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    double *a_w = seat_awz ? seat_awz : own;
    c->peak_az = c->lift_off = 0;
    for (size_t k = 0; k < n; ++k) {
        a[k] = s[k].seat_az;
        c->peak_az = fmax(c->peak_az, fabs(s[k].seat_az));
        c->lift_off += (s[k].F_front == 0 || s[k].F_rear == 0) ? dt : 0;
    }
    int status = tirenv_comfort_evaluate(TIRENV_WK, fs, a, a_w, n, &c->seat, diag);
    for (size_t k = 0; k < n; ++k)
        a[k] = s[k].atheta;
    if (!status)
        status = tirenv_comfort_evaluate(TIRENV_WE, fs, a, a, n, &c->pitch, diag);
    /* ISO 2631-1 6.5: the seat's vertical and pitch axes, pitch with k = 0.4 m/rad. */
    const double k[2] = {TIRENV_COMFORT_K_Z, TIRENV_COMFORT_K_RY};
    const double rms[2] = {c->seat.rms, c->pitch.rms};
    if (!status)
        status = tirenv_comfort_total_value(k, rms, 2, &c->a_v, diag);
    free(a);
    free(own);
    return status;
}
