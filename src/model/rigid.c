/* The rigid disc over a profile, the geometric limit of every model (MODEL.md section 3).
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "tirenv/rigid.h"

#include <math.h>

#include "profile/profile_impl.h"

/* The best touching point found so far: centre height z_c and where the disc touches. */
typedef struct {
    double z_c, p_x, p_z;
} rigid_contact;

static void consider(rigid_contact *best, double z_c, double p_x, double p_z)
{
    if (z_c > best->z_c) {
        best->z_c = z_c;
        best->p_x = p_x;
        best->p_z = p_z;
    }
}

/* Height over the point (p_x, p_z) of a disc centred at abscissa x that touches it:
 * p_z + sqrt(R0^2 - u^2), u = x - p_x, with the radicand as (R0 - u)(R0 + u), which keeps
 * its accuracy near u = +-R0 where the two squares nearly cancel. */
static double over_point(double R0, double x, double p_x, double p_z)
{
    const double u = x - p_x;
    return p_z + sqrt(fmax(0.0, (R0 - u) * (R0 + u)));
}

/* Why these candidates suffice. Along one segment the touching height
 * f(p_x) = p_z(p_x) + sqrt(R0^2 - (x - p_x)^2) is a linear function plus a concave one, so
 * it is concave: its maximum over the part of the segment within reach is the stationary
 * point (where the disc is tangent to the segment) if that lies inside, or else one end of
 * that part. The ends at p_x = x +- R0 never win, because the square root's slope is
 * infinite there and f grows inward; so the remaining ends are the segment's vertices.
 * A vertical wall has no interior point with a different abscissa from its vertices and
 * only the higher of them can touch, so walls need their vertices only. The flat
 * extensions are segments too: their tangency point is straight below the centre.
 *
 * Tangency: with d = (dx, dz) the segment direction (dx > 0) and n = (-dz, dx) / |d| its
 * upward unit normal, the centre is C = P + R0 n for the touching point P on the segment.
 * C_x = x fixes P_x = x + R0 dz / |d|, and then z_c = P_z + R0 dx / |d|. The quotients are
 * formed first so that a flat segment (|d| = dx exactly) gives z_c = P_z + R0 exactly.
 *
 * Only segments meeting [x - R0, x + R0] can touch; a binary search finds the first. */
static void rigid_scan(const struct tirenv_profile *p, double R0, double x, rigid_contact *best)
{
    const size_t n = p->n;
    const double *xs = p->x, *zs = p->z;
    const double x_lo = x - R0, x_hi = x + R0;

    if (x <= xs[0]) /* left flat extension, tangent straight below */
        consider(best, zs[0] + R0, x, zs[0]);
    if (x >= xs[n - 1]) /* right flat extension */
        consider(best, zs[n - 1] + R0, x, zs[n - 1]);

    for (size_t k = x_lo < xs[0] ? 0 : tirenv_profile__segment_at(p, x_lo); k < n; k++) {
        if (xs[k] > x_hi)
            break;
        if (xs[k] >= x_lo)
            consider(best, over_point(R0, x, xs[k], zs[k]), xs[k], zs[k]);
        if (k + 1 == n || !(xs[k + 1] > xs[k]))
            continue; /* last vertex, or a wall: its vertices are the candidates */
        const double dx = xs[k + 1] - xs[k], dz = zs[k + 1] - zs[k];
        const double len = hypot(dx, dz);
        const double P_x = x + R0 * (dz / len);
        if (P_x > xs[k] && P_x < xs[k + 1]) {
            const double P_z = zs[k] + dz * ((P_x - xs[k]) / dx);
            consider(best, P_z + R0 * (dx / len), P_x, P_z);
        }
    }
}

/* Returns NAN (and a NAN contact) if R0 is not positive and finite or x is not finite. */
double tirenv_rigid_height(const tirenv_profile *p, double R0, double x, double *px,
                           double *pz)
{
    rigid_contact best = {-INFINITY, NAN, NAN};
    if (isfinite(R0) && R0 > 0.0 && isfinite(x))
        rigid_scan(p, R0, x, &best);
    else
        best.z_c = NAN;
    if (px)
        *px = best.p_x;
    if (pz)
        *pz = best.p_z;
    return best.z_c;
}
