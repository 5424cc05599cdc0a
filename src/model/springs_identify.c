/* SPDX-License-Identifier: Apache-2.0 */
/* The springs model's stiffnesses identified on a reference's flat ground (docs/models.md
 * section 14.1): at each of the reference's loads the springs model deflects as the reference
 * does and touches as much ground. Used by tirenv identify (src/study/identify.c) and by the
 * models derived from an MF-Tyre file (src/formats/tir_derive.c). */
#include "tirenv/springs.h"

#include <math.h>
#include "tirenv/model.h"

enum { MAX_LOADS = 64 };

/* The springs model's load at deflection d (m) per unit c_r and its contact length, with
 * c_b = beta*c_r: both from one force evaluation at the centre height R0 - d
 * (tirenv_model_flat_at_height). The load is proportional to (c_r, c_b) together and the
 * contact length, the length of ground the tread touches (section 1.3), depends on their
 * ratio alone; the solve runs at c_r = 1e6 N/m per rad, inside the plausible range
 * (docs/formats.md section 2), and divides the load by it. */
static int unit_load(const tirenv_springs_params *par, double beta, size_t n, const double d[],
                     double f[], double l[], tirenv_diag *diag)
{
    tirenv_tire t = tirenv_tire_default();
    const double c_unit = 1e6;
    t.springs = *par;
    t.springs.c_r = c_unit;
    t.springs.c_b = beta * c_unit;
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
    if (!m)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "INTERRADIAL_STIFFNESS",
                            "no springs model with c_r %g N/m per rad and c_b %g N*rad/m",
                            c_unit, beta * c_unit);
    const double R0 = t.springs.R0;
    int status = TIRENV_OK;
    for (size_t i = 0; i < n && !status; i++) {
        tirenv_flat fl;
        if (!(status = tirenv_model_flat_at_height(m, R0 - d[i], &fl, diag))) {
            f[i] = fl.load / c_unit;
            l[i] = fl.contact_length;
        }
    }
    tirenv_model_free(m);
    return status;
}

/* For a ratio beta, the least-squares c_r of log(load) at the reference's deflections (into *c_r
 * unless NULL) and the
 * sum of squared residuals: those of log(load), and those of log(contact length) at the same
 * deflections, which c_r does not change. Both relative, so a per cent of either weighs the
 * same. */
static int residual(const tirenv_springs_params *par, double log_beta, size_t n,
                    const double load[], const double d[], const double l_ref[], double *c_r,
                    double *ss, tirenv_diag *diag)
{
    double f[MAX_LOADS], l[MAX_LOADS], r[MAX_LOADS];
    const int status = unit_load(par, exp(log_beta), n, d, f, l, diag);
    if (status)
        return status;
    double mean = 0;
    for (size_t i = 0; i < n; i++)
        mean += (r[i] = log(load[i] / f[i])) / (double)n;
    *ss = 0;
    for (size_t i = 0; i < n; i++) {
        const double r_l = l[i] > 0 ? log(l[i] / l_ref[i]) : INFINITY;
        *ss += (r[i] - mean) * (r[i] - mean) + r_l * r_l;
    }
    if (c_r)
        *c_r = exp(mean);
    return TIRENV_OK;
}

/* Golden section on log(c_b/c_r) over [1e-6, 10] rad^2: the fit is smooth and one-dimensional
 * once c_r is eliminated; 60 steps narrow the bracket to 1e-12 of its width. c_b/c_r sets how
 * far the interradial springs lift the tread off the ground towards the chord's ends, so the
 * contact length, and with c_r the stiffness. */
int tirenv_springs_identify(tirenv_springs_params *par, size_t n, const double load[],
                            const double deflection[], const double contact_length[],
                            tirenv_diag *diag)
{
    if (n < 2 || n > MAX_LOADS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "loads",
                            "identification needs 2 to %d loads, got %zu", MAX_LOADS, n);
    for (size_t i = 0; i < n; i++)
        if (!(load[i] > 0 && deflection[i] > 0 && deflection[i] < par->R0 &&
              contact_length[i] > 0 && isfinite(load[i]) && isfinite(contact_length[i])))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "loads",
                                "target %zu: load %g N, deflection %g m, contact length %g m "
                                "is no flat-ground state of a tire of radius %g m", i + 1,
                                load[i], deflection[i], contact_length[i], par->R0);
    const double g = 0.5 * (sqrt(5.0) - 1);
    double a = log(1e-6), b = log(10.0);
    double x1 = b - g * (b - a), x2 = a + g * (b - a), s1, s2;
    int status = residual(par, x1, n, load, deflection, contact_length, NULL, &s1, diag);
    if (!status)
        status = residual(par, x2, n, load, deflection, contact_length, NULL, &s2, diag);
    for (int k = 0; k < 60 && !status; k++) {
        if (s1 <= s2) {
            b = x2;
            x2 = x1;
            s2 = s1;
            x1 = b - g * (b - a);
            status = residual(par, x1, n, load, deflection, contact_length, NULL, &s1, diag);
        } else {
            a = x1;
            x1 = x2;
            s1 = s2;
            x2 = a + g * (b - a);
            status = residual(par, x2, n, load, deflection, contact_length, NULL, &s2, diag);
        }
    }
    double c_r, ss;
    if (!status)
        status = residual(par, 0.5 * (a + b), n, load, deflection, contact_length, &c_r, &ss,
                          diag);
    if (status)
        return status;
    par->c_b = c_r * exp(0.5 * (a + b));
    par->c_r = c_r;
    return TIRENV_OK;
}
