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

/* The start at a new x. The line through the last two equilibria (deformable.c's start) is
 * some 1e-5 m off over a cleat at 1 mm steps, where h ripples with the node spacing
 * (docs/models.md 5.3), and the parabola's step from there misses the root by the error of its
 * curvature times the square of that distance. Continued by the mean slope over the last
 * three steps, z_1 + (z_1 - z_4) / 3, the start averages the ripple out: 7.0e-6 m off (median
 * over the bench cleat's positions with two evaluations or more; 1.27e-5 m by the line), so
 * the parabola's step lands closer and fewer positions need a third. But its error from h's
 * own curvature is twice the line's (2 h'' dx^2 against h'' dx^2), which rules at coarser
 * steps (over a 0.10 x 0.05 m cleat at 4 mm it took 4 % more evaluations). So the ring scores
 * both on the equilibria as they come (each predictor's squared miss, the older ones decayed
 * by START_DECAY a position) and proposes the mean slope's only where it scores better. */
static const double START_DECAY = 0.75;

/* Equal steps: a sweep's, to 1e-9 of the step (x = x_from + i dx rounds). */
static int step_apart(double a, double b, double h)
{
    return fabs((a - b) - h) <= 1e-9 * fabs(h);
}

/* Whether the equilibria eq[0 .. K-1] (newest first) lie a step h apart up to x, h = x -
 * eq_x[0] (nonzero). */
static int in_steps(const tirenv_ring_root *rt, double x)
{
    enum { K = TIRENV_RING_START_KEEP };
    const double h = x - rt->eq_x[0];
    if (!(rt->eq_n >= K && h != 0))
        return 0;
    for (size_t i = 0; i + 1 < K; ++i)
        if (!step_apart(rt->eq_x[i], rt->eq_x[i + 1], h))
            return 0;
    return 1;
}

/* The mean slope's start and the line's at x from the equilibria held. */
static double by_mean(const tirenv_ring_root *rt)
{
    enum { K = TIRENV_RING_START_KEEP };
    return rt->eq_z[0] + (rt->eq_z[0] - rt->eq_z[K - 1]) / (K - 1);
}

static double by_line(const tirenv_ring_root *rt) { return 2 * rt->eq_z[0] - rt->eq_z[1]; }

/* The last evaluation taken as its x's equilibrium, once x has moved on: the two starts
 * scored on it, where they had the steps for it, and it joins the equilibria held. */
static void push_last(tirenv_ring_root *rt, double x)
{
    if (!(rt->e_have != 0 && !tirenv_ring__same_bits(&x, &rt->ex, 1)))
        return;
    if (in_steps(rt, rt->ex)) {
        const double em = rt->ez - by_mean(rt), el = rt->ez - by_line(rt);
        rt->s_mean = START_DECAY * rt->s_mean + em * em;
        rt->s_line = START_DECAY * rt->s_line + el * el;
    } else {
        rt->s_mean = rt->s_line = 0; /* unscored: equal, so the line's start stands */
    }
    memmove(rt->eq_x + 1, rt->eq_x, (TIRENV_RING_START_KEEP - 1) * sizeof *rt->eq_x);
    memmove(rt->eq_z + 1, rt->eq_z, (TIRENV_RING_START_KEEP - 1) * sizeof *rt->eq_z);
    rt->eq_x[0] = rt->ex, rt->eq_z[0] = rt->ez;
    if (rt->eq_n < TIRENV_RING_START_KEEP)
        rt->eq_n += 1;
    rt->e_have = 0;
}

void tirenv_ring__root_eval(tirenv_ring *r, double x, double z)
{
    tirenv_ring_root *rt = &r->root;
    push_last(rt, x); /* Newton's last iterate at the x before was its equilibrium */
    rt->ex = x, rt->ez = z, rt->e_have = 1;
}

int tirenv_ring__root_start(tirenv_ring *r, double x, double *z)
{
    tirenv_ring_root *rt = &r->root;
    push_last(rt, x);
    if (!(in_steps(rt, x) && rt->s_mean < rt->s_line))
        return 0;
    *z = by_mean(rt);
    return isfinite(*z);
}
