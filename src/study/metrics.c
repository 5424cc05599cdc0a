/* How far a model's enveloping curve is from a measured one (docs/models.md section 8): the four
 * figures of the comparison table. SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/study.h"

#include <math.h>

/* Where h first exceeds the threshold, linearly interpolated between the last point at or
 * below it and the first above, so that a curve shifted by less than the grid spacing moves
 * its first rise by exactly that shift (a grid-point answer would move in whole steps). A
 * curve already above the threshold at its first point rises there. NaN if it never does. */
static double first_rise(size_t n, const double x[], const double h[], double threshold)
{
    for (size_t k = 0; k < n; ++k) {
        if (!(h[k] > threshold))
            continue;
        if (k == 0)
            return x[0];
        const double t = (threshold - h[k - 1]) / (h[k] - h[k - 1]);
        return x[k - 1] + t * (x[k] - x[k - 1]);
    }
    return NAN;
}

int tirenv_curve_errors_compute(size_t n, const double x[], const double h_meas[],
                                const double h_model[], double rise_threshold,
                                tirenv_curve_errors *out)
{
    if (n == 0)
        return tirenv_error(NULL, TIRENV_EINVAL, "", 0, "", "no points to compare");
    if (!isfinite(rise_threshold))
        return tirenv_error(NULL, TIRENV_EINVAL, "", 0, "rise_threshold",
                            "expected a finite threshold, got %g m", rise_threshold);
    for (size_t k = 0; k < n; ++k)
        if (!isfinite(x[k]) || !isfinite(h_meas[k]) || !isfinite(h_model[k]))
            return tirenv_error(NULL, TIRENV_EINVAL, "", k + 1, "",
                                "point %zu is not finite (x %g m, measured %g m, model %g m)",
                                k + 1, x[k], h_meas[k], h_model[k]);
    double sum2 = 0, max = 0, peak_meas = h_meas[0], peak_model = h_model[0];
    for (size_t k = 0; k < n; ++k) {
        const double e = h_model[k] - h_meas[k];
        sum2 += e * e;
        max = fmax(max, fabs(e));
        peak_meas = fmax(peak_meas, h_meas[k]);
        peak_model = fmax(peak_model, h_model[k]);
    }
    out->rms = sqrt(sum2 / (double)n);
    out->max = max;
    out->peak = peak_model - peak_meas;
    /* NaN - anything is NaN: the contract's "NaN if either never rises". */
    out->first_rise = first_rise(n, x, h_model, rise_threshold) -
                      first_rise(n, x, h_meas, rise_threshold);
    return TIRENV_OK;
}
