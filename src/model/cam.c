/* The elliptical cam (docs/models.md section 7): its shape, its tangency with a straight segment,
 * and the public lift and tandem of two cams (the exact lift itself is cam_lift.c's).
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>

#include "model/cam_impl.h"

int tirenv_cam__geom_set(tirenv_cam__geom *g, const tirenv_cam_shape *shape)
{
    const double a_e = shape->a_e, b_e = shape->b_e, c_e = shape->c_e;
    if (!(a_e > 0 && isfinite(a_e) && b_e > 0 && isfinite(b_e) && c_e > 1 && isfinite(c_e)))
        return TIRENV_EINVAL;
    *g = (tirenv_cam__geom){
        .a_e = a_e,
        .b_e = b_e,
        .c_e = c_e,
        .inv_a = 1.0 / a_e,
        .a_over_b = a_e / b_e,
        .inv_c = 1.0 / c_e,
        .inv_c1 = 1.0 / (c_e - 1.0),
        .p = c_e / (c_e - 1.0),
        /* For pruning: g(t) = (1 - t^c)^(1/c) <= 1 - t^c/c (y^(1/c) lies below its tangent
         * at y = 1), so the edge drop is at least (b_e/c_e)*t^c >= (b_e/c_e)*t^n for any whole
         * n >= c_e, on t in [0, 1]: a bound without pow. Beyond c_e = 64, no bound. */
        .b_over_c = c_e <= 64 ? b_e / c_e : 0.0,
        .n_c = c_e <= 64 ? (unsigned)ceil(c_e) : 1u,
    };
    return TIRENV_OK;
}

/* The largest lift a straight segment of slope s != 0 can give, if it is reached inside the
 * segment. Along it the touching height of a point u = xi - x ahead of the cam's bottom is
 * f(u) = q_k + s*(x + u - x_k) - b_e + b_e*g(|u|/a_e), linear plus concave (c_e > 1), so f has
 * one maximum; it is where the cam is tangent to the segment:
 *   s = -b_e*d g(|u|/a_e)/du.
 * With t = |u|/a_e and the cam's slope scale m = |s|*a_e/b_e this reads
 *   t^(c-1) * (1 - t^c)^((1-c)/c) = m,  i.e.  t/(1 - t^c)^(1/c) = k := m^(1/(c-1)),
 * so t^c = k^c/(1 + k^c), t = k*(1 + k^c)^(-1/c), g = (1 + k^c)^(-1/c), with u of the sign of s
 * (a rising segment touches ahead of the bottom). At the tangency
 *   s*u + b_e*g = b_e*(m*t + g) = b_e*(1 + k^c)^(1 - 1/c)
 * (as k^(c-1) = m: the support function of the super-ellipse, the c/(c-1)-norm of (m, 1)), so
 *   Z = q_k + s*(x - x_k) + b_e*((1 + k^c)^(1 - 1/c) - 1).
 * Evaluated with j = k^c = m^(c/(c-1)) = k*m for m < 1, and for m >= 1 (where k^c can overflow
 * as c -> 1) with j = k^-c = m^(-c/(c-1)): then t = (1 + j)^(-1/c) and
 * (1 + k^c)^(1 - 1/c) = m*(1 + j)^(1 - 1/c). Both u = a_e*t and the rise
 * b_e*((1 + k^c)^(1 - 1/c) - 1) depend on m alone, not on where the cam is. */
void tirenv_cam__tangent(const tirenv_cam__geom *g, double m, double *u, double *rise)
{
    const double lm = log(m);
    double t, rise_m1;
    if (m < 1.0) {
        const double k = exp(lm * g->inv_c1), j = k * m;
        const double L = log1p(j), P = exp(-g->inv_c * L);   /* P = (1 + j)^(-1/c) */
        t = k * P;
        rise_m1 = j * P + expm1(-g->inv_c * L);               /* (1 + j) P - 1 */
    } else {
        const double j = exp(-lm * g->p), L = log1p(j), P = exp(-g->inv_c * L);
        t = P;
        rise_m1 = m * (1.0 + j) * P - 1.0;
    }
    *u = g->a_e * t;
    *rise = g->b_e * rise_m1;
}

double tirenv_cam_lift(const tirenv_profile *p, const tirenv_cam_shape *cam, double x,
                       double *px, double *pz)
{
    tirenv_cam__geom g;
    if (tirenv_cam__geom_set(&g, cam) != TIRENV_OK || !isfinite(x)) {
        if (px)
            *px = NAN;
        if (pz)
            *pz = NAN;
        return NAN;
    }
    return tirenv_cam__lift(&g, p, x, INFINITY, NULL, NULL, px, pz);
}

int tirenv_cam_tandem(const tirenv_profile *p, const tirenv_cam_shape *cam, double l_s,
                      double x, double *w, double *tan_beta)
{
    tirenv_cam__geom g;
    if (tirenv_cam__geom_set(&g, cam) != TIRENV_OK || !(l_s > 0 && isfinite(l_s)) ||
        !isfinite(x))
        return TIRENV_EINVAL;
    const double Z_f = tirenv_cam__lift(&g, p, x + 0.5 * l_s, INFINITY, NULL, NULL, NULL, NULL);
    const double Z_r = tirenv_cam__lift(&g, p, x - 0.5 * l_s, INFINITY, NULL, NULL, NULL, NULL);
    *w = 0.5 * (Z_f + Z_r);
    *tan_beta = (Z_f - Z_r) / l_s;
    return TIRENV_OK;
}
