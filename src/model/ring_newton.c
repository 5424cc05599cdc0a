/* SPDX-License-Identifier: Apache-2.0 */
/* The continuous contact's Newton driver (docs/models.md section 5.3), one for both treads:
 * the Winkler tread (ring_smooth.c, unknowns w) and the shear-coupled one (ring_shear.c, w and u
 * interleaved). Each minimises a convex, piecewise quadratic energy whose pieces are the
 * quadrature points' states, so Newton's method with the states taken from the current iterate
 * ends exactly, when a step does not change them; the first steps are full, then a line
 * search on the energy makes it converge from anywhere. Where no step lowers the energy beyond
 * its round-off (the states of a few points at zero compression flip back and forth), full
 * Newton steps follow, a few at most: a consistent set of states is the unique minimiser
 * whatever the start, and if a point keeps flipping the Newton point, closer to the minimum
 * than the stall tolerance, is the answer. */
#include <math.h>
#include <string.h>
#include "model/ring_impl.h"

enum { NEWTON_BACKTRACK = 20, NEWTON_POLISH = 8 };
/* A step that changed the states of at most NEWTON_FULL_CHANGES points, among the first
 * NEWTON_FULL steps of a piecewise quadratic E, is followed by a full Newton step, without the
 * line search (a semismooth Newton step): from the warm start a step mostly moves the contact's
 * edges by a piece or two, and there the line search's two products with K, its passes for the
 * energy and its terms and the states' pass again cost more than the few steps it saves. Where
 * many states changed (a start far from the answer, a rough road's many vertices) full steps
 * overshoot and take more steps than the line search does; and they can cycle between two sets
 * of states, which the line search after NEWTON_FULL steps breaks. Measured with callgrind
 * (docs/performance.md 2.12): over the bench cleat's sweep 7.2 % fewer
 * instructions, over 3 m of a class C road 19 % (vertices 10 mm apart) and 23 % (1 mm) fewer;
 * full steps whatever the changes took 6 % and 20 % more there. The answer is the system of its
 * final states solved, as before: the same bits. Not with a smooth part (the softening
 * carcass), whose answer is where Newton stops within nl_tol, so depends on the path: there
 * the line search as before. */
enum { NEWTON_FULL = 10, NEWTON_FULL_CHANGES = 32 };
/* The peel (nw->peel; docs/performance.md 2.24). Where the first step moves a contact's edge
 * onto ground the tread only grazes (beside a cleat's corner, where the tread drapes over it),
 * a run of points enters at once, and the full steps after free them one a step from the run's
 * end, each some 1e-7 m clear of the ground at the step that frees it (over the bench cleat 27
 * contact solves of 4 to 15 steps, 253 steps in all). So where the second full step frees a
 * point that the first one brought into contact, the points beside it that came in with it and
 * are pressed in by no more than a graze are freed too. Once a solve, at the second step only:
 * the start is kept in g until then (the line search's vector, unused while the steps are
 * full). A wrong guess costs a step; the answer is the system of its final states solved,
 * which no guess changes (the same bits). */
static const double newton_sigma = 1e-4; /* Armijo's sufficient decrease */
/* A Newton step this short (m) ends the iteration even if a point's state flips with it: a
 * point whose compression is zero to round-off carries no force either way. */
static const double newton_step_tol = 1e-12;
/* Where no step lowers E beyond round-off, a Newton step up to this long (m) is taken as
 * settled, then polished by full steps. Seen at NODE_ANGLE 1/16 degree, 5.7e-7 m. */
static const double newton_stall_tol = 1e-6;

/* The minimiser over 0 < alpha <= 1 of the convex piecewise quadratic
 *     phi(alpha) = alpha Kxp + 1/2 alpha^2 pKp + sum_i 1/2 c_i max(0, a_i - alpha b_i)^2
 * (E along x + alpha p up to a constant; phi'(0) < 0 along a descent direction): 1 if phi'(1)
 * <= 0, else Newton's method on phi', piecewise linear and increasing, each step exact on its
 * piece, kept inside the bracket of its sign change (bisection otherwise), to a relative
 * 1e-6 of alpha: the next Newton step corrects what is left. */
static double exact_alpha(double Kxp, double pKp, size_t n, const double c[], const double a[],
                          const double b[])
{
    double lo = 0, hi = 1, alpha = 1;
    for (int it = 0; it < 60; ++it) {
        double d1 = Kxp + alpha * pKp, d2 = pKp;
        for (size_t i = 0; i < n; ++i) {
            const double e = a[i] - alpha * b[i];
            if (e > 0) {
                d1 -= c[i] * b[i] * e;
                d2 += c[i] * b[i] * b[i];
            }
        }
        if (it == 0 && d1 <= 0)
            return 1;
        if (d1 == 0)
            return alpha;
        if (d1 < 0)
            lo = alpha;
        else
            hi = alpha;
        double next = d2 > 0 ? alpha - d1 / d2 : NAN;
        if (!(next > lo && next < hi))
            next = 0.5 * (lo + hi);
        if (fabs(next - alpha) <= 1e-6 * next)
            return next;
        alpha = next;
    }
    return alpha;
}

int tirenv_ring__newton(tirenv_ring *r, const tirenv_ring_newton *nw, double x[], double xn[],
                        double xt[], double g[], int *factored)
{
    const size_t N = nw->N;
    nw->set_states(r, x); /* every point's (its count of changes not needed) */
    *factored = 0;
    size_t polish = 0; /* full Newton steps taken after the line search stalled */
    int full = 1;      /* every step so far a full one */
    const int peel = nw->peel != NULL && nw->nl_tol == 0; /* see the peel above */
    for (size_t it = 0; it < TIRENV_RING_NEWTON_MAX_ITER; ++it) {
        if (nw->steps)
            ++*nw->steps;
        if (nw->factor(r, nw->K, xn))
            return TIRENV_RING_NEWTON_BREAKDOWN;
        nw->solve(r, xn);
        /* The states at the Newton point: unchanged, it is the minimum (of a piecewise
         * quadratic E, whatever the step's length: not measured then). */
        const size_t changed = nw->set_states(r, xn);
        if (changed == 0 && nw->nl_tol == 0) {
            memcpy(x, xn, N * sizeof *x);
            *factored = 1;
            return TIRENV_RING_NEWTON_OK;
        }
        double step = 0; /* "v > step": fmax(step, v) without its call, the same bits (step
                          * is never NaN and v = |...| never -0; a NaN v is passed over) */
        for (size_t i = 0; i < N; ++i) {
            const double v = fabs(xn[i] - x[i]);
            if (v > step)
                step = v;
        }
        if ((changed == 0 && step <= nw->nl_tol) ||  /* nl_tol 0 returned above */
            step <= newton_step_tol) {
            memcpy(x, xn, N * sizeof *x);
            *factored = changed == 0;
            return TIRENV_RING_NEWTON_OK;
        }
        if (polish > 0) {
            memcpy(x, xn, N * sizeof *x);
            if (++polish > NEWTON_POLISH)
                return TIRENV_RING_NEWTON_OK;
            continue;
        }
        if (it < NEWTON_FULL && changed <= NEWTON_FULL_CHANGES && nw->nl_tol == 0) {
            /* The full step, its states already set: see NEWTON_FULL, and the peel. */
            if (peel && it == 0)
                memcpy(g, x, N * sizeof *x);
            else if (peel && it == 1 && full)
                nw->peel(r, g, x, xn);
            memcpy(x, xn, N * sizeof *x);
            continue;
        }
        full = 0; /* g is the line search's from here */
        /* Else a step towards it that lowers E enough. Along x + alpha p (p = xn - x) the
         * quadratic 1/2 x.K x is E_K + alpha Kx.p + 1/2 alpha^2 p.K p: one product with K
         * for the whole line search, the points' share at each trial. */
        nw->apply(r, nw->K, x, g);
        for (size_t i = 0; i < N; ++i)
            xt[i] = xn[i] - x[i];
        nw->apply(r, nw->K, xt, nw->kp);
        double E_K = 0, Kxp = 0, pKp = 0;
        for (size_t i = 0; i < N; ++i) {
            E_K += 0.5 * x[i] * g[i];
            Kxp += g[i] * xt[i];
            pKp += xt[i] * nw->kp[i];
        }
        const double E0 = E_K + nw->points(r, x, g);
        double slope = 0;
        for (size_t i = 0; i < N; ++i)
            slope += g[i] * (xn[i] - x[i]);
        double alpha = 1;
        size_t b = 0;
        if (nw->line) {
            /* The exact minimiser along the step, checked as a trial of its own: one pass
             * over the points for the line's terms, then arithmetic on them alone, where
             * halving tried about six steps, each a pass over the points. */
            const double *lc, *la, *lb;
            const size_t nt = nw->line(r, x, xt, &lc, &la, &lb);
            if (nt != (size_t)-1) {
                /* A smooth part of E (the softening carcass) enters the line's model by its
                 * slope and curvature at x; the check below takes E itself. */
                double d1 = 0, d2 = 0;
                if (nw->smooth)
                    nw->smooth(r, x, xt, &d1, &d2);
                const double a_ex = exact_alpha(Kxp + d1, pKp + d2, nt, lc, la, lb);
                if (a_ex > 0 && isfinite(a_ex)) {
                    double *xs = nw->kp; /* K p is no longer needed */
                    for (size_t i = 0; i < N; ++i)
                        xs[i] = x[i] + a_ex * xt[i];
                    const double E = E_K + a_ex * Kxp + 0.5 * a_ex * a_ex * pKp +
                                     nw->points(r, xs, NULL);
                    if (E <= E0 + newton_sigma * a_ex * slope) {
                        memcpy(x, xs, N * sizeof *x);
                        nw->set_states(r, x);
                        continue;
                    }
                }
            }
        }
        for (; b < NEWTON_BACKTRACK; ++b, alpha *= 0.5) {
            for (size_t i = 0; i < N; ++i)
                xt[i] = x[i] + alpha * (xn[i] - x[i]);
            const double E = E_K + alpha * Kxp + 0.5 * alpha * alpha * pKp +
                             nw->points(r, xt, NULL);
            if (E <= E0 + newton_sigma * alpha * slope)
                break;
        }
        if (b == NEWTON_BACKTRACK && step <= newton_stall_tol) {
            /* No step of at least 2^-20 of the way lowers E: x is the minimum to E's
             * round-off, the Newton point differs from it by a few points at zero compression
             * flipping. Take it, with its states, and polish. (Shorter steps would "lower" E
             * by its round-off alone.) */
            memcpy(x, xn, N * sizeof *x);
            polish = 1;
            continue;
        }
        memcpy(x, xt, N * sizeof *x);
        nw->set_states(r, x);
    }
    return TIRENV_RING_NEWTON_NOCONV;
}

int tirenv_ring__newton_error(const tirenv_ring *r, int st, size_t n, const char *system,
                              const char *contact, tirenv_diag *diag)
{
    if (st == TIRENV_RING_NEWTON_BREAKDOWN)
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "ring",
                            "the factorisation of the %zu-node banded %s system broke "
                            "down (not numerically positive definite)", n, system);
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "ring",
                        "the %s contact of %zu points on %zu nodes did not settle in %d Newton "
                        "steps", contact, r->n_pts, n, TIRENV_RING_NEWTON_MAX_ITER);
}
