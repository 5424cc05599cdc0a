/* SPDX-License-Identifier: Apache-2.0 */
/* A model's flat-ground load at a given deflection (src/formats/flat_inverse.h). */
#include "formats/flat_inverse.h"

#include <math.h>

/* Deflection minus target at load G, or a failure of tirenv_model_flat. */
static int excess(tirenv_model *m, double G, double d, double *e, tirenv_diag *diag)
{
    tirenv_flat f;
    const int status = tirenv_model_flat(m, G, &f, diag);
    if (!status)
        *e = f.deflection - d;
    return status;
}

int tirenv_flat__load_at_deflection(tirenv_model *m, double d, double guess, double *G,
                                    tirenv_diag *diag)
{
    const double R0 = tirenv_model_tire(m)->springs.R0;
    if (!(d > 0 && d < R0) || !(guess > 0 && isfinite(guess)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "deflection",
                            "%g m is no deflection of a tire of radius %g m (trial load %g N)",
                            d, R0, guess);
    /* The bracket [lo, hi] with excess e_lo < 0 <= e_hi; the unloaded tire has e = -d. */
    double lo = 0, e_lo = -d, hi = guess, e_hi;
    int status = excess(m, hi, d, &e_hi, diag);
    for (int k = 0; !status && e_hi < 0 && k < 60; k++) {
        lo = hi;
        e_lo = e_hi;
        hi *= 2;
        status = excess(m, hi, d, &e_hi, diag);
    }
    if (status)
        return status;
    if (e_hi < 0)
        return tirenv_error(diag, TIRENV_ENOBRACKET, "", 0, "deflection",
                            "the model does not deflect %g m under %g N", d, hi);
    /* Illinois: regula falsi that halves the value kept twice in a row. */
    int side = 0;
    for (int k = 0; k < 200; k++) {
        const double g = (lo * e_hi - hi * e_lo) / (e_hi - e_lo);
        double e;
        if ((status = excess(m, g, d, &e, diag)))
            return status;
        if (fabs(e) <= 1e-9 * d || hi - lo <= 1e-12 * hi) {
            *G = g;
            return TIRENV_OK;
        }
        if (e < 0) {
            lo = g;
            e_lo = e;
            if (side == -1)
                e_hi *= 0.5;
            side = -1;
        } else {
            hi = g;
            e_hi = e;
            if (side == 1)
                e_lo *= 0.5;
            side = 1;
        }
    }
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "deflection",
                        "no load found for a deflection of %g m: bracket [%.9g, %.9g] N after "
                        "200 flat-ground solves", d, lo, hi);
}
