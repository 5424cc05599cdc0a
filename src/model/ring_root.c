/* SPDX-License-Identifier: Apache-2.0 */
/* The ring's own step in z for Newton's equilibrium (docs/models.md section 5.3, What
 * the solve reuses; its counts, docs/performance.md 2.19): the shear-coupled tread's F_z is nearly
 * a parabola in z over the few micrometres Newton's first step crosses, and the linear step lands
 * where the parabola's curvature leaves F_z some 1e-4 N off, outside the test's eps_z, so a third
 * evaluation followed at a third of the positions.
 *
 * Held at the states of an evaluation, the contact's system is linear in z wherever no cut
 * moves (its matrix fixed, the points' penetrations linear along their rays), so F_z is linear
 * there and the bordered solve of z with the window's unknowns is Newton's linear step itself
 * (x + dz dx/dz, F + dz dF_z/dz). What bends F_z is the ground's vertices in contact (their
 * cuts, places and weights move with z) and the states changing on the way; neither is known
 * without sampling the ground again. So the curvature is measured: at each position, from
 * the evaluation Newton stepped from (F_0 and its slope k at z_0) and the next at the same x,
 * c = 2 (F - F_0 - k (z - z_0)) / (z - z_0)^2, and the next positions' steps take the median
 * of the last TIRENV_RING_ROOT_KEEP on the side the step goes (F_z bends differently above
 * and below the root: the states that change differ). The step is then the parabola's root,
 * F_0 + k dz + c dz^2 / 2 = G, by one Newton step from the linear one. Nothing else changes:
 * every evaluation is a full one, and Newton's test (|F_z - G| <= eps_F, the next correction
 * <= eps_z) decides as before, so a poor curvature costs an evaluation, never accuracy. */
#include <math.h>
#include <string.h>
#include "model/ring_impl.h"

/* A measurement over a step shorter than this (m) is F_z's round-off, not its curvature. */
static const double root_min_dz = 1e-6;

/* The parabola's share of the step, |c dz^2 / 2| over |F_0 - G|, above which the step is the
 * linear one (the curvature measured elsewhere is not this position's, or a state changes). */
static const double root_max_share = 0.1;

void tirenv_ring__root_clear(tirenv_ring *r) { memset(&r->root, 0, sizeof r->root); }

void tirenv_ring__root_seen(tirenv_ring *r, double x, double z, double F)
{
    tirenv_ring_root *rt = &r->root;
    if (!(rt->have != 0 && x == rt->x))
        return;
    rt->have = 0; /* one measurement a step */
    const double dz = z - rt->z;
    if (!(fabs(dz) >= root_min_dz))
        return;
    const double c = 2 * (F - rt->F - rt->k * dz) / (dz * dz);
    if (!isfinite(c))
        return;
    double *cs = rt->c[dz < 0];
    memmove(cs + 1, cs, (TIRENV_RING_ROOT_KEEP - 1) * sizeof *cs);
    cs[0] = c;
    double *n = &rt->n[dz < 0];
    if (*n < TIRENV_RING_ROOT_KEEP)
        *n += 1;
}

/* The median of a[0 .. n) (n <= 3). */
static double median(const double a[], size_t n)
{
    if (n < 3)
        return n == 1 ? a[0] : 0.5 * (a[0] + a[1]);
    const double lo = fmin(a[0], a[1]), hi = fmax(a[0], a[1]);
    return a[2] < lo ? lo : a[2] > hi ? hi : a[2];
}

int tirenv_ring__root(tirenv_ring *r, double x, double z, double F, double k, double G,
                      double *z_root)
{
    tirenv_ring_root *rt = &r->root;
    rt->x = x, rt->z = z, rt->F = F, rt->k = k, rt->have = 1;
    const double f = F - G, dz = -f / k;
    if (!(k < 0) || !isfinite(dz))
        return 0;
    const int side = dz < 0;
    const size_t n = (size_t)rt->n[side];
    if (n == 0)
        return 0;
    const double c = median(rt->c[side], n), bend = 0.5 * c * dz * dz;
    if (!(fabs(bend) <= root_max_share * fabs(f)))
        return 0;
    /* f + k dz + c dz^2 / 2 = 0: Newton's step from the linear root, where the parabola is
     * bend; its error is bend's share squared, below 1e-2 of the linear step's. */
    *z_root = z + dz - bend / (k + c * dz);
    return 1;
}
