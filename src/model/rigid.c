/* The rigid disc over a profile, the geometric limit of every model (docs/models.md section 3).
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/rigid.h"

#include <math.h>

#include "model/rigid_impl.h"
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

/* The larger of two numbers, neither NaN: fmax without its call (GCC keeps fmax out of line
 * for its NaN rule). */
static inline double max2(double a, double b)
{
    return a > b ? a : b;
}

/* Height over the point (p_x, p_z) of a disc centred at abscissa x that touches it:
 * p_z + sqrt(R0^2 - u^2), u = x - p_x, with the radicand as (R0 - u)(R0 + u), which keeps
 * its accuracy near u = +-R0 where the two squares nearly cancel. */
static double over_point(double R0, double x, double p_x, double p_z)
{
    const double u = x - p_x;
    const double r2 = (R0 - u) * (R0 + u); /* never -0: one factor is then 2 R0 > 0 */
    return p_z + sqrt(r2 > 0.0 ? r2 : 0.0); /* fmax(0, r2), without its call */
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
 * Only segments meeting [x - R0, x + R0] can touch; a binary search finds the first.
 *
 * Pruning, which changes no result. The point of the ground straight below x touches at
 * q_x + R0, so the highest touching point is at least that high, and so at least the bar
 * max(q_x + R0, best so far). A block of the profile's block-maximum index whose highest
 * vertex, z_b, at the block's nearest distance d from x, touches below the bar,
 * z_b + sqrt(R0^2 - d^2) < bar, holds no winner and is skipped whole; within a block, a vertex
 * or a segment whose higher end cannot reach the bar (z + R0 < bar) is skipped before its
 * square root or hypot. Only candidates strictly below the final best are skipped, and the
 * rest are considered in the same order, so the result, ties included, is the plain scan's
 * bit for bit. The comparisons are made against bar - margin, with margin = 2^-40 (|q_x| +
 * R0): far above the few ulps by which a computed touching height (or q_x) can differ from
 * its exact value, far below any difference that matters. On a long road this leaves a few
 * blocks near x to scan, not the 2*R0/dx vertices within reach. */
static void rigid_scan(const struct tirenv_profile *p, double R0, double x, size_t *hint,
                       rigid_contact *best)
{
    const size_t n = p->n, B = TIRENV_PROFILE__BLOCK;
    const double *xs = p->x, *zs = p->z;
    const double x_lo = x - R0, x_hi = x + R0, half_inv_R0 = 0.5 / R0;

    if (x <= xs[0]) /* left flat extension, tangent straight below */
        consider(best, zs[0] + R0, x, zs[0]);
    if (x >= xs[n - 1]) /* right flat extension */
        consider(best, zs[n - 1] + R0, x, zs[n - 1]);

    /* The ground under x, as tirenv_profile_height computes it. */
    /* A sweep's positions are close together: search from the last one's segment. Both
     * searches give the same index, so the result does not depend on the hint. */
    const size_t k_x = hint ? tirenv_profile__segment_near(p, *hint < n ? *hint : n - 1, x)
                            : tirenv_profile__segment_at(p, x);
    if (hint)
        *hint = k_x;
    const double q_x = tirenv_profile__height_in(p, x, k_x);
    const double margin = 0x1p-40 * (fabs(q_x) + R0);
    double bar_0 = q_x + R0 - margin;
    /* A few vertices around x raise the bar close to its final height before the ordered
     * scan: they are touching points, so any of their heights is a lower bound too. */
    for (size_t j = k_x > 4 ? k_x - 4 : 0; j < n && j <= k_x + 5; j++)
        if (xs[j] >= x_lo && xs[j] <= x_hi)
            bar_0 = max2(bar_0, over_point(R0, x, xs[j], zs[j]) - margin);
    double bar = max2(best->z_c - margin, bar_0);

    /* The first segment within reach, the last vertex with x_k <= x_lo, by galloping back
     * from k_x: O(log) of the vertices within reach rather than of the whole profile. */
    size_t k = 0;
    if (!(x_lo < xs[0])) {
        size_t step = 1;
        while (step <= k_x && xs[k_x - step] > x_lo)
            step *= 2;
        size_t lo = step <= k_x ? k_x - step : 0, hi = k_x - step / 2; /* xs[lo] <= x_lo */
        while (lo < hi) { /* the last index in [lo, hi] with xs <= x_lo */
            const size_t mid = hi - (hi - lo) / 2;
            if (xs[mid] <= x_lo)
                lo = mid;
            else
                hi = mid - 1;
        }
        k = lo;
    }
    while (k < n && xs[k] <= x_hi) {
        /* The rest of k's block: vertices k .. k_end - 1 and the segments they start. */
        const size_t b = k / B, k_end = (b + 1) * B < n ? (b + 1) * B : n;
        const double x_a = xs[b * B], x_b = xs[k_end < n ? k_end : n - 1];
        const double d = x < x_a ? x_a - x : x > x_b ? x - x_b : 0.0;
        const double gap = bar - p->z_block[b]; /* the lift the block would need */
        if (gap > 0.0 && (d >= R0 || gap * gap > (R0 - d) * (R0 + d))) {
            k = k_end;
            continue;
        }
        for (; k < k_end; k++) {
            if (xs[k] > x_hi)
                return;
            /* sqrt(R0^2 - u^2) <= R0 - u^2/(2 R0): a bound without the square root, whose
             * rounding the margin absorbs like that of the others. */
            const double u_k = x - xs[k];
            if (xs[k] >= x_lo && zs[k] + R0 - u_k * u_k * half_inv_R0 >= bar) {
                consider(best, over_point(R0, x, xs[k], zs[k]), xs[k], zs[k]);
                bar = max2(best->z_c - margin, bar_0);
            }
            if (k + 1 == n || !(xs[k + 1] > xs[k]) || max2(zs[k], zs[k + 1]) + R0 < bar)
                continue; /* last vertex, a wall (its vertices are the candidates), or low */
            const double dx = xs[k + 1] - xs[k], dz = zs[k + 1] - zs[k];
            /* The tangency point lies R0*|dz|/len < R0*|dz|/dx from x, towards the segment's
             * rising end; a segment beside x that faces away, or lies farther than that, cannot
             * hold it, and is ruled out before the hypot. The relative slack 1e-9 covers the
             * rounding of P_x below (and the floor 1e-250 keeps clear of subnormals), so the
             * test on P_x would fail too: the same candidates, bit for bit. */
            const double gap_x = xs[k] > x ? xs[k] - x : x > xs[k + 1] ? x - xs[k + 1] : 0.0;
            if (gap_x > 0.0) {
                const double rise = xs[k] > x ? dz : -dz; /* towards x's side: rising? */
                const double reach_x = gap_x * dx * (1.0 - 1e-9);
                const int normal = gap_x > 1e-250 && reach_x > 1e-250;
                if (!(rise > 0.0) || (normal && R0 * rise < reach_x))
                    continue;
            }
            const double len = hypot(dx, dz);
            const double P_x = x + R0 * (dz / len);
            if (P_x > xs[k] && P_x < xs[k + 1]) {
                const double P_z = zs[k] + dz * ((P_x - xs[k]) / dx);
                consider(best, P_z + R0 * (dx / len), P_x, P_z);
                bar = max2(best->z_c - margin, bar_0);
            }
        }
    }
}

/* Returns NAN (and a NAN contact) if R0 is not positive and finite or x is not finite. */
double tirenv_rigid__height_hint(const tirenv_profile *p, double R0, double x, size_t *hint,
                                 double *px, double *pz)
{
    rigid_contact best = {-INFINITY, NAN, NAN};
    if (isfinite(R0) && R0 > 0.0 && isfinite(x))
        rigid_scan(p, R0, x, hint, &best);
    else
        best.z_c = NAN;
    if (px)
        *px = best.p_x;
    if (pz)
        *pz = best.p_z;
    return best.z_c;
}

/* Track 0 starts the maxima, so that one track is its own heights bit for bit (a NaN
 * included: a non-finite x). */
void tirenv_rigid__bracket(size_t n, const tirenv_profile *const p[], double R0, double x,
                           size_t hint[], double *z_lo, double *z_hi)
{
    *z_lo = tirenv_profile_height(p[0], x);
    *z_hi = tirenv_rigid__height_hint(p[0], R0, x, &hint[0], NULL, NULL);
    for (size_t k = 1; k < n; ++k) {
        *z_lo = fmax(*z_lo, tirenv_profile_height(p[k], x));
        *z_hi = fmax(*z_hi, tirenv_rigid__height_hint(p[k], R0, x, &hint[k], NULL, NULL));
    }
}

double tirenv_rigid_height(const tirenv_profile *p, double R0, double x, double *px,
                           double *pz)
{
    return tirenv_rigid__height_hint(p, R0, x, NULL, px, pz);
}
