/* SPDX-License-Identifier: Apache-2.0 */
/* Brent's method (Brent 1973, chapter 4; the Algol procedure zero): keep a bracket [b, c] with
 * b the point of smaller |f|; step by inverse quadratic interpolation through a, b, c (the
 * secant when only two points are distinct) when that step lies well inside the bracket and
 * the steps shrink fast enough, else bisect; never step less than the round-off tolerance
 * 0.5 eps |b|. The arithmetic follows the procedure term by term, the order GSL's
 * gsl_root_fsolver_brent uses too, so the roots the library found through GSL are found again
 * to the bit (tests/core/test_numerics.c holds closed-form roots and the failure cases). */
#include "core/brent.h"

#include <float.h>
#include <math.h>

static int same_sign(const double x, const double y)
{
    return (x < 0 && y < 0) || (x > 0 && y > 0);
}

static void set_bracket(tirenv_core__brent *s, const double c)
{
    s->root = s->b;
    s->lo = s->b < c ? s->b : c;
    s->hi = s->b < c ? c : s->b;
}

int tirenv_core__brent_set(tirenv_core__brent *s, const tirenv_core__brent_fn f, void *params,
                           const double lo, const double hi)
{
    const double f_lo = f(lo, params);
    if (!isfinite(f_lo)) /* f(hi) is not asked for then */
        return tirenv_core__brent_set_values(s, f, params, lo, f_lo, hi, NAN);
    return tirenv_core__brent_set_values(s, f, params, lo, f_lo, hi, f(hi, params));
}

int tirenv_core__brent_set_values(tirenv_core__brent *s, const tirenv_core__brent_fn f,
                                  void *params, const double lo, const double f_lo,
                                  const double hi, const double f_hi)
{
    s->f = f;
    s->params = params;
    s->root = 0.5 * (lo + hi);
    s->lo = lo;
    s->hi = hi;
    if (!isfinite(f_lo) || !isfinite(f_hi))
        return TIRENV_CORE__BRENT_NOT_FINITE;
    s->a = lo;
    s->fa = f_lo;
    s->b = s->c = hi;
    s->fb = s->fc = f_hi;
    s->d = s->e = hi - lo;
    return same_sign(f_lo, f_hi) ? TIRENV_CORE__BRENT_NO_BRACKET : 0;
}

int tirenv_core__brent_iterate(tirenv_core__brent *s)
{
    double a = s->a, b = s->b, c = s->c, fa = s->fa, fb = s->fb, fc = s->fc;
    double d = s->d, e = s->e;
    int ac_equal = 0;  /* a and c are the same point: interpolate linearly */
    if (same_sign(fb, fc)) {  /* the root left [b, c]: the contrapoint is a */
        ac_equal = 1;
        c = a;
        fc = fa;
        d = e = b - a;
    }
    if (fabs(fc) < fabs(fb)) {  /* b the better end */
        ac_equal = 1;
        a = b;
        b = c;
        c = a;
        fa = fb;
        fb = fc;
        fc = fa;
    }
    const double tol = 0.5 * DBL_EPSILON * fabs(b);
    const double m = 0.5 * (c - b);
    if (fb == 0) {
        s->root = s->lo = s->hi = b;
        return 0;
    }
    if (fabs(m) <= tol) {
        set_bracket(s, c);
        s->root = b;
        return 0;
    }
    if (fabs(e) < tol || fabs(fa) <= fabs(fb)) {  /* the steps stalled: bisect */
        d = e = m;
    } else {
        const double r_s = fb / fa;
        double p, q;
        if (ac_equal) {  /* secant */
            p = 2 * m * r_s;
            q = 1 - r_s;
        } else {  /* inverse quadratic interpolation */
            const double q_a = fa / fc, r_b = fb / fc;
            p = r_s * (2 * m * q_a * (q_a - r_b) - (b - a) * (r_b - 1));
            q = (q_a - 1) * (r_b - 1) * (r_s - 1);
        }
        if (p > 0)
            q = -q;
        else
            p = -p;
        /* Accept the step if it stays within three quarters of the bracket and is less than
         * half the step before last; else bisect. */
        if (2 * p < fmin(3 * m * q - fabs(tol * q), fabs(e * q))) {
            e = d;
            d = p / q;
        } else {
            d = e = m;
        }
    }
    a = b;
    fa = fb;
    if (fabs(d) > tol)
        b += d;
    else
        b += m > 0 ? tol : -tol;
    fb = s->f(b, s->params);
    if (!isfinite(fb))
        return TIRENV_CORE__BRENT_NOT_FINITE;
    s->a = a;
    s->b = b;
    s->c = c;
    s->fa = fa;
    s->fb = fb;
    s->fc = fc;
    s->d = d;
    s->e = e;
    set_bracket(s, same_sign(fb, fc) ? a : c);
    return 0;
}

int tirenv_core__brent_converged(const tirenv_core__brent *s, const double eps_abs)
{
    return fabs(s->hi - s->lo) < eps_abs;
}

const char *tirenv_core__brent_strerror(const int status)
{
    switch (status) {
    case 0:
        return "success";
    case TIRENV_CORE__BRENT_NO_BRACKET:
        return "the ends of the interval do not bracket a root";
    case TIRENV_CORE__BRENT_NOT_FINITE:
        return "the function value is not finite";
    default:
        return "unknown status";
    }
}
