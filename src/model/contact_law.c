/* SPDX-License-Identifier: Apache-2.0 */
/* A tire's flat-ground relation between load and contact length (docs/models.md section
 * 14.3): the table's checks, its monotone cubic interpolation and the inverse of that same
 * curve.
 *
 * Between its knots the law is the piecewise cubic Hermite interpolant whose slopes at the
 * knots are Fritsch and Carlson's weighted harmonic means of the neighbouring secants (the
 * PCHIP form; one-sided secants at the ends): monotone wherever the knots are, continuous with
 * its first derivative, and exact at the knots bit for bit (a knot returns its own value, so a
 * data set's case load gives back its case's contact length). Each segment's value is clamped
 * to its two knots' values, so round-off can never take it out of them. The inverse solves the
 * same cubic by bisection to adjacent doubles, so that law(inverse(l_c)) = l_c to round-off. */
#include <math.h>

#include "model/model_impl.h"

int tirenv_contact_law_check(const tirenv_contact_law *law, tirenv_diag *diag)
{
    if (!(law->n >= 2 && law->n <= TIRENV_CONTACT_LAW_MAX))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact law",
                            "%zu points; expected 2 to %d", law->n, TIRENV_CONTACT_LAW_MAX);
    for (size_t i = 0; i < law->n; i++) {
        const int bad = !(law->load[i] > 0 && isfinite(law->load[i]) && law->l_c[i] > 0 &&
                          isfinite(law->l_c[i])) ||
                        (i > 0 && !(law->load[i] > law->load[i - 1] &&
                                    law->l_c[i] > law->l_c[i - 1]));
        if (bad)
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact law",
                                "point %zu (%g N, %g m): loads and contact lengths must be "
                                "positive and strictly ascending", i + 1, law->load[i],
                                law->l_c[i]);
    }
    return TIRENV_OK;
}

/* The secant of segment i (load[i] to load[i + 1]), m/N. */
static double secant(const tirenv_contact_law *law, size_t i)
{
    return (law->l_c[i + 1] - law->l_c[i]) / (law->load[i + 1] - law->load[i]);
}

/* The slope at knot k: Fritsch-Carlson's weighted harmonic mean of the secants on either side
 * (both positive, as the law is strictly ascending), the one secant at an end. */
static double knot_slope(const tirenv_contact_law *law, size_t k)
{
    if (k == 0)
        return secant(law, 0);
    if (k == law->n - 1)
        return secant(law, law->n - 2);
    const double h0 = law->load[k] - law->load[k - 1], h1 = law->load[k + 1] - law->load[k];
    const double d0 = secant(law, k - 1), d1 = secant(law, k);
    const double w0 = 2 * h1 + h0, w1 = h1 + 2 * h0;
    return (w0 + w1) / (w0 / d0 + w1 / d1);
}

/* The cubic of segment i at load G in [load[i], load[i + 1]], clamped to its knots. */
static double segment_at(const tirenv_contact_law *law, size_t i, double G)
{
    const double G0 = law->load[i], G1 = law->load[i + 1];
    const double y0 = law->l_c[i], y1 = law->l_c[i + 1];
    if (G == G0)
        return y0;
    if (G == G1)
        return y1;
    const double h = G1 - G0, t = (G - G0) / h, s = 1 - t;
    const double m0 = knot_slope(law, i), m1 = knot_slope(law, i + 1);
    const double y = s * s * (1 + 2 * t) * y0 + t * t * (3 - 2 * t) * y1 + s * s * t * h * m0 -
                     t * t * s * h * m1;
    return fmin(fmax(y, y0), y1);
}

/* The segment i whose knots xs[i] <= x <= xs[i + 1] (x within the table). */
static size_t segment_of(const double xs[], size_t n, double x)
{
    size_t i = 0;
    while (i + 2 < n && x > xs[i + 1])
        i++;
    return i;
}

static int out_of_law(const double xs[], size_t n, double x, const char *what,
                      const char *unit, tirenv_diag *diag)
{
    return tirenv_error(diag, TIRENV_ERANGE, "", 0, what,
                        "%g %s is outside %g to %g %s, the range of the relation between load "
                        "and contact length that the network file records for its tire "
                        "(docs/models.md section 14.3)", x, unit, xs[0], xs[n - 1], unit);
}

int tirenv_contact_law_eval(const tirenv_contact_law *law, double load, double *l_c,
                            tirenv_diag *diag)
{
    if (!(load >= law->load[0] && load <= law->load[law->n - 1]))
        return out_of_law(law->load, law->n, load, "load", "N", diag);
    *l_c = segment_at(law, segment_of(law->load, law->n, load), load);
    return TIRENV_OK;
}

int tirenv_contact_law_inverse(const tirenv_contact_law *law, double l_c, double *load,
                               tirenv_diag *diag)
{
    if (!(l_c >= law->l_c[0] && l_c <= law->l_c[law->n - 1]))
        return out_of_law(law->l_c, law->n, l_c, "contact length", "m", diag);
    const size_t i = segment_of(law->l_c, law->n, l_c);
    if (l_c == law->l_c[i] || l_c == law->l_c[i + 1]) {
        *load = l_c == law->l_c[i] ? law->load[i] : law->load[i + 1];
        return TIRENV_OK;
    }
    /* Bisection on the segment's monotone cubic until its bracket is two adjacent doubles:
     * at most about 64 halvings. */
    double lo = law->load[i], hi = law->load[i + 1];
    for (;;) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi))
            break;
        if (segment_at(law, i, mid) < l_c)
            lo = mid;
        else
            hi = mid;
    }
    *load = l_c - segment_at(law, i, lo) <= segment_at(law, i, hi) - l_c ? lo : hi;
    return TIRENV_OK;
}
