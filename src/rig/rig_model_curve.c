/* SPDX-License-Identifier: Apache-2.0 */
/* A model's own enveloping curve on the import's x_N grid: what the import of a noiseless,
 * densely sampled log of it approaches (docs/models.md section 5.7). tirenv sweep writes it
 * without --rig, and tirenv study compares against it where the data set is such a sweep. */
#include "tirenv/rig.h"

#include <math.h>
#include "tirenv/xn.h"

int tirenv_rig_model_curve(tirenv_model *m, const tirenv_import_settings *s, tirenv_curve *out,
                           tirenv_diag *diag)
{
    const double x_0 = tirenv_xN_origin(s->R0, s->contact_length, s->L, s->H);
    if (!isfinite(x_0))
        return tirenv_error(diag, TIRENV_ERANGE, "", 0, "obstacle",
                            "the cleat's corner is out of the tire's reach at this contact "
                            "length (no x_N origin)");
    const size_t n = tirenv_import_grid_points(s);
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dxN",
                            "the x_N grid from %g to %g every %g holds no point or more than "
                            "a million", s->xN_from, s->xN_to, s->dxN);
    int status = tirenv_curve_alloc(out, n);
    if (status)
        return tirenv_error(diag, status, "", 0, "", "out of memory");
    /* In x order (x_N falls as x rises): each equilibrium starts from the previous one. */
    for (size_t k = 0; k < n && !status; ++k) {
        tirenv_point pt;
        out->x_N[k] = s->xN_from + (double)k * s->dxN;
        out->x[k] = x_0 * (1 - out->x_N[k]) + 0.0; /* + 0.0: the centre is 0, not -0 */
        if (!(status = tirenv_model_eval(m, out->x[k], &pt, diag)))
            out->h[k] = pt.h;
    }
    if (status)
        tirenv_curve_free(out);
    return status;
}
