/* The elliptical cam over a profile, exact on polylines, and the tandem of two cams
 * (MODEL.md section 7). SPDX-License-Identifier: GPL-3.0-or-later */
#include "model/cam_impl.h"

#include <math.h>

#include "profile/profile_impl.h"

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

/* The best touching point found so far: lift Z and where the cam touches the profile. */
typedef struct {
    double Z, p_x, p_z;
} cam_contact;

static inline void consider(cam_contact *best, double Z, double p_x, double p_z)
{
    if (Z > best->Z) {
        best->Z = Z;
        best->p_x = p_x;
        best->p_z = p_z;
    }
}

/* t^n for a small whole n >= 1, by squaring. */
static inline double ipow(double t, unsigned n)
{
    double r = 1.0;
    for (; n; n >>= 1, t *= t)
        if (n & 1)
            r *= t;
    return r;
}

/* The cam's lower edge above its lowest point, as a function of t = |u|/a_e in [0, 1]:
 * b_e*(g(t) - 1) with g(t) = (1 - t^c_e)^(1/c_e), negative. Two pows: accurate to about an
 * ulp of b_e, which is all a comparison of heights needs (expm1/log1p would keep the relative
 * accuracy near t = 0 too, but cost 10 % more over a cleat, measured). */
static inline double edge_drop(const tirenv_cam__geom *g, double t)
{
    if (t <= 0.0)
        return 0.0;
    const double tc = pow(t, g->c_e);
    return g->b_e * (pow(1.0 - tc, g->inv_c) - 1.0);
}

/* The largest lift the straight segment from (x_k, z_k) with slope s != 0 can give, if it is
 * reached inside the segment. Along it the touching height of a point u = xi - x ahead of the
 * cam's bottom is f(u) = q_k + s*(x + u - x_k) - b_e + b_e*g(|u|/a_e), linear plus concave
 * (c_e > 1), so f has one maximum; it is where the cam is tangent to the segment:
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
 * (1 + k^c)^(1 - 1/c) = m*(1 + j)^(1 - 1/c). Returns 0 and leaves *Z untouched if the tangency
 * point lies outside the open segment (then an end vertex, or the cam's reach, bounds f there;
 * the reach never wins, as g' -> -infinity at t = 1 makes f grow inward). */
static int tangency(const tirenv_cam__geom *g, double x, double x_k, double z_k, double x_k1,
                    double s, double *Z, double *p_x)
{
    const double m = fabs(s) * g->a_over_b;
    /* A shallow segment (m < 1) touches at t = k*P <= k = m^(1/(c_e-1)), and k <= m when
     * c_e <= 2: a segment beyond a_e*m from x (the usual case on a road, where m is small)
     * cannot hold the tangency point, which is known before any exp or log. The relative
     * slack 1e-9 covers the rounding of k, P and t, so that the point computed below would
     * fail the test at the end as well: the result is the same bit for bit. */
    if (m < 1.0 && g->c_e <= 2.0) {
        const double u_max = g->a_e * (m * (1.0 + 1e-9));
        if (s > 0 ? !(x + u_max > x_k) : !(x - u_max < x_k1))
            return 0;
    }
    const double lm = log(m);
    double t, rise_m1; /* t at the tangency, and (1 + k^c)^(1 - 1/c) - 1 */
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
    const double xi = s > 0 ? x + g->a_e * t : x - g->a_e * t;
    if (!(xi > x_k && xi < x_k1))
        return 0;
    *Z = z_k + s * (x - x_k) + g->b_e * rise_m1;
    *p_x = xi;
    return 1;
}

/* A vertex within reach, t = its distance from the cam's bottom / a_e, as a candidate,
 * unless a bound without pow rules it out: its touching height is at most
 * z_k - (b_e/c_e)*t^n_c (see tirenv_cam__geom_set). */
static inline void vertex(const tirenv_cam__geom *g, double t, double x_k, double z_k,
                          cam_contact *best)
{
    t = fabs(t);
    if (!(z_k - g->b_over_c * ipow(t, g->n_c) > best->Z))
        return;
    if (t <= 0.0) {
        consider(best, z_k + edge_drop(g, t), x_k, z_k);
        return;
    }
    /* With t^c_e from the first of edge_drop's two pows, the sharper bound the above stands
     * for, z_k - (b_e/c_e)*t^c_e, rules out most of the rest before the second. The drop it
     * bounds exceeds it by at least b_e*(c_e - 1)*t^(2c_e)/(2c_e^2), and the slack (1e-9
     * relative, 1e-14*b_e absolute) covers the rounding of both, where that gap is smaller:
     * a vertex ruled out here would not have beaten the best, bit for bit. Both sides add
     * z_k to the drop last, so its rounding keeps the order. */
    const double tc = pow(t, g->c_e);
    if (!(z_k + (g->b_e * 1e-14 - g->b_over_c * tc * (1.0 - 1e-9)) > best->Z))
        return;
    consider(best, z_k + g->b_e * (pow(1.0 - tc, g->inv_c) - 1.0), x_k, z_k);
}

/* Candidates, and why they suffice. The lift is the largest touching height over the profile
 * within reach, [x - a_e, x + a_e]. On each straight segment the touching height is concave
 * (see tangency), so its maximum over the part within reach is the tangency point if that lies
 * inside, or else a vertex (the ends of the reach never win). A flat segment's tangency is
 * straight below the bottom (u = 0), which is the ground height under x. A vertical wall's
 * points differ only in height, so only its top vertex can win. Hence: the ground under x,
 * every vertex within reach, and the tangency points of the sloped segments.
 *
 * Pruning, which changes no result: a point at height z and distance t*a_e from the bottom
 * touches at most z - (b_e/c_e)*t^n_c high (tirenv_cam__geom_set), so the ground under x
 * starts the search and most candidates are ruled out by a few multiplications, without a
 * pow. One binary search finds x; the scan walks outward from it, O(vertices within reach),
 * and fewer when z_cap ends a side's walk early. No allocation. */
double tirenv_cam__lift(const tirenv_cam__geom *g, const tirenv_profile *p, double x,
                        double z_cap, double *px, double *pz)
{
    const size_t n = p->n;
    const double *xs = p->x, *zs = p->z;
    /* The ground under x (at a wall the higher vertex; off the ends the flat extensions). */
    const size_t k_x = tirenv_profile__segment_at(p, x);
    double q_x;
    if (x < xs[0])
        q_x = zs[0];
    else if (x == xs[k_x] && k_x >= 1 && xs[k_x - 1] == x)
        q_x = fmax(zs[k_x - 1], zs[k_x]);
    else if (k_x == n - 1)
        q_x = zs[n - 1];
    else
        q_x = zs[k_x] + (zs[k_x + 1] - zs[k_x]) * ((x - xs[k_x]) / (xs[k_x + 1] - xs[k_x]));
    cam_contact best = {q_x, x, q_x};

    /* A tighter z_cap from the profile's block maxima: the highest vertex from the last one
     * at or before the reach's start to the first one beyond its end, which bounds every
     * point within reach. On a long road this is the local relief, not the whole road's. */
    {
        const size_t B = TIRENV_PROFILE__BLOCK;
        /* Searched outward from k_x, near them, rather than over the whole road. */
        const size_t k_l = tirenv_profile__segment_near(p, k_x, x - g->a_e);
        const size_t k_r = tirenv_profile__segment_near(p, k_x, x + g->a_e);
        const size_t b_r = (k_r + 1 < n ? k_r + 1 : n - 1) / B;
        double z_local = p->z_block[k_l / B];
        for (size_t b = k_l / B + 1; b <= b_r; b++)
            z_local = z_local > p->z_block[b] ? z_local : p->z_block[b];
        if (z_local < z_cap)
            z_cap = z_local;
    }

    /* The vertices first, nearest first on each side: they are cheap to rule out and raise
     * the bar for the tangencies. A side's walk stops at the first vertex (out of reach, or)
     * where even the highest ground z_cap could not beat the best lift at its distance: the
     * bound only falls outward and the best only rises. */
    const double b_c = g->b_over_c;
    size_t k_left = 0; /* the walks' ends: segments beyond them cannot win either */
    size_t k_right = n - 1;
    for (size_t k = k_x + 1; k-- > 0;) {
        const double t = (x - xs[k]) * g->inv_a;
        if (t > 1.0 || z_cap - b_c * ipow(fmax(t, 0.0), g->n_c) <= best.Z) {
            k_left = k;
            break;
        }
        vertex(g, t, xs[k], zs[k], &best);
    }
    for (size_t k = k_x + 1; k < n; k++) {
        const double t = (xs[k] - x) * g->inv_a;
        if (t > 1.0 || z_cap - b_c * ipow(t, g->n_c) <= best.Z) {
            k_right = k;
            break;
        }
        vertex(g, t, xs[k], zs[k], &best);
    }

    /* The sloped segments within reach, each bounded by its higher end at its nearest point
     * to x before its tangency is computed. */
    for (size_t k = k_left; k < k_right; k++) {
        const double x_a = xs[k], x_b = xs[k + 1], z_a = zs[k], z_b = zs[k + 1];
        if (!(x_b > x_a) || z_b == z_a)
            continue; /* a wall or a flat segment: its vertices and q_x cover it */
        const double s = (z_b - z_a) / (x_b - x_a);
        /* A rising segment touches ahead of the bottom, a falling one behind it. */
        if (s > 0 ? !(x_b > x) : !(x_a < x))
            continue;
        const double t_near = (x < x_a ? x_a - x : x > x_b ? x - x_b : 0.0) * g->inv_a;
        if (!(fmax(z_a, z_b) - g->b_over_c * ipow(t_near, g->n_c) > best.Z))
            continue;
        double Z, xi;
        if (tangency(g, x, x_a, z_a, x_b, s, &Z, &xi))
            consider(&best, Z, xi, z_a + s * (xi - x_a));
    }
    if (px)
        *px = best.p_x;
    if (pz)
        *pz = best.p_z;
    return best.Z;
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
    return tirenv_cam__lift(&g, p, x, INFINITY, px, pz);
}

int tirenv_cam_tandem(const tirenv_profile *p, const tirenv_cam_shape *cam, double l_s,
                      double x, double *w, double *tan_beta)
{
    tirenv_cam__geom g;
    if (tirenv_cam__geom_set(&g, cam) != TIRENV_OK || !(l_s > 0 && isfinite(l_s)) ||
        !isfinite(x))
        return TIRENV_EINVAL;
    const double Z_f = tirenv_cam__lift(&g, p, x + 0.5 * l_s, INFINITY, NULL, NULL);
    const double Z_r = tirenv_cam__lift(&g, p, x - 0.5 * l_s, INFINITY, NULL, NULL);
    *w = 0.5 * (Z_f + Z_r);
    *tan_beta = (Z_f - Z_r) / l_s;
    return TIRENV_OK;
}
