/* SPDX-License-Identifier: Apache-2.0 */
/* The shear-coupled tread's knots (docs/models.md section 5.3; ring_shear.c's header): every
 * ground vertex cut inside a node interval is a knot of the tread surface u, an unknown of its
 * own with a tridiagonal stiffness, condensed out of each Newton system so that the banded
 * system keeps its bandwidth, and solved back after it; and how their stiffness moves with z. */
#include <math.h>
#include "model/ring_impl.h"
#include "model/ring_shear_impl.h"
#include "model/ring_tband.h"

/* The knots of the window's points (ring_shear.c's header): T->m, each point's knot, T->kj and the
 * knots' own stiffness T->kd, T->ko. Nonzero if out of memory. */
int tirenv_ring__find_knots(tirenv_ring *r)
{
    tirenv_ring_tread *T = r->tread;
    /* Each knot's interval and angle (the last of its points', as they are met), while they
     * fit in the arrays; then the sub-intervals and the stiffness. */
    tirenv_ring_point *const pts = r->pts;
    const size_t n_pts = r->n_pts, cap = T->cap_k, lo = r->lo, n = r->n;
    double *phi = T->kphi;
    size_t m = 0;
    for (size_t k = 0; k < n_pts; ++k) {
        tirenv_ring_point *q = &pts[k];
        /* Only in the window's own intervals. The whole window's points are all that
         * tirenv_ring__sample cast, up to two nodes past the ground within reach; those
         * outside the window are out of reach (it holds the intervals of every point within
         * reach). A knot there is an unknown coupled to nothing whose interval index q->j - lo
         * lies outside the window: solve_full's x[2 i + 1], x[2 i + 3] (weighted by c0 = c1
         * = 0) read and wrote outside the window's unknowns, before them (i = (size_t)-1:
         * x[-1], the last entry of the vector before, never written) or past them (another
         * knot's entry, or one past the N + m); NaN there made the knot NaN, and Newton did
         * not settle. */
        const int inner = q->s > 0 && q->s < 1 && q->j >= lo && q->j + 1 < lo + n;
        const int same = inner && k > 0 && pts[k - 1].knot >= 0 && pts[k - 1].j == q->j &&
                         pts[k - 1].phi == q->phi;
        if (inner && !same)
            ++m;
        q->knot = inner ? (long)m - 1 : -1;
        if (inner && m <= cap) {
            T->kj[m - 1] = q->j - r->lo;
            phi[m - 1] = q->phi;
            T->kdphi[m - 1] = q->dphi;
        }
    }
    if (m > cap) {
        if (tirenv_ring__reserve_knots(T, m))
            return 1;
        phi = T->kphi;
        for (size_t k = 0; k < n_pts; ++k)
            if (pts[k].knot >= 0) {
                T->kj[pts[k].knot] = pts[k].j - r->lo;
                phi[pts[k].knot] = pts[k].phi;
                T->kdphi[pts[k].knot] = pts[k].dphi;
            }
    }
    T->m = m;
    const double R = r->R, k_s = tirenv_ring__tread_shear(&r->par);
    for (size_t k = 0; k < m; ++k) {
        const size_t i = T->kj[k], j = r->lo + i;
        const int first = k == 0 || T->kj[k - 1] != i, last = k + 1 == m || T->kj[k + 1] != i;
        const double hl = phi[k] - (first ? r->theta[j] : phi[k - 1]);
        const double hr = (last ? r->theta[j + 1] : phi[k + 1]) - phi[k];
        const double s = (phi[k] - r->theta[j]) / r->dth;
        const double k_c = ((1 - s) * T->kap[j] + s * T->kap[j + 1]) / (R * r->dth);
        T->kd[k] = k_s / (R * hl) + k_s / (R * hr) + k_c * R * 0.5 * (hl + hr);
        T->ko[k] = last ? 0 : -k_s / (R * hr);
    }
    return 0;
}

/* The knots' block D (tridiagonal, T->dd and T->ko) factorised in place, D = L L^T: T->dd its
 * diagonal, T->doff its subdiagonal. Nonzero if not positive definite. */
static int knots_factor(tirenv_ring_tread *T)
{
    for (size_t k = 0; k < T->m; ++k) {
        double d = T->dd[k];
        if (k > 0)
            d -= T->doff[k - 1] * T->doff[k - 1];
        if (!(d > 0))
            return 1;
        T->dd[k] = sqrt(d);
        T->doff[k] = k + 1 < T->m ? T->ko[k] / T->dd[k] : 0;
    }
    return 0;
}

/* y = D^-1 y with the knots' factor. */
static void knots_solve(const tirenv_ring_tread *T, double y[])
{
    const size_t m = T->m;
    for (size_t k = 0; k < m; ++k)
        y[k] = (y[k] - (k > 0 ? T->doff[k - 1] * y[k - 1] : 0)) / T->dd[k];
    for (size_t k = m; k-- > 0;)
        y[k] = (y[k] - (k + 1 < m ? T->doff[k] * y[k + 1] : 0)) / T->dd[k];
}

/* The system with the knots condensed out: the band gets - C^T D^-1 C, C the knots' coupling
 * to u_j, u_j+1 of their intervals (D is block diagonal by interval, so each interval's knots
 * add to its own 2 x 2 block of u). */
int tirenv_ring__condense_knots(tirenv_ring_tread *T)
{
    const size_t m = T->m;
    if (m == 0)
        return 0;
    if (knots_factor(T))
        return 1;
    for (size_t k = 0; k < m; ++k)
        T->z0[k] = T->c0[k], T->z1[k] = T->c1[k];
    knots_solve(T, T->z0);
    knots_solve(T, T->z1);
    for (size_t k = 0; k < m;) {
        const size_t i = T->kj[k];
        double s00 = 0, s01 = 0, s11 = 0;
        for (; k < m && T->kj[k] == i; ++k) {
            s00 += T->c0[k] * T->z0[k];
            s01 += T->c0[k] * T->z1[k];
            s11 += T->c1[k] * T->z1[k];
        }
        if (s00 != 0 || s01 != 0 || s11 != 0) {
            band_add(&T->as, 2 * i + 1, 2 * i + 1, -s00);
            band_add(&T->as, 2 * i + 1, 2 * i + 3, -s01);
            band_add(&T->as, 2 * i + 3, 2 * i + 3, -s11);
        }
    }
    return 0;
}

/* The knots' right-hand side eliminated from the band's rows of x (2 n + m entries), the
 * first part of the full system's solve (solve_full). */
void tirenv_ring__knots_eliminate(tirenv_ring *r, double x[])
{
    tirenv_ring_tread *T = r->tread;
    const size_t m = T->m, N = 2 * r->n;
    double *xa = x + N, *y = T->z0; /* free after condense_knots */
    for (size_t k = 0; k < m; ++k)
        y[k] = xa[k];
    knots_solve(T, y);
    for (size_t k = 0; k < m; ++k) {
        const size_t i = T->kj[k];
        x[2 * i + 1] -= T->c0[k] * y[k];
        x[2 * i + 3] -= T->c1[k] * y[k];
    }
}

/* solve_full's part after the band's forward substitution (fused: done with the
 * factorisation, band_factor_x; else the band's whole solve here), the knots' right-hand
 * side eliminated before it (knots_eliminate). */
void tirenv_ring__solve_after(tirenv_ring *r, double x[], int fused)
{
    tirenv_ring_tread *T = r->tread;
    const size_t m = T->m, N = 2 * r->n;
    double *xa = x + N;
    if (fused)
        tirenv_ring__tband_solve_rest(&T->win, x);
    else
        tirenv_ring__tband_solve(&T->win, x);
    for (size_t k = 0; k < m; ++k) {
        const size_t i = T->kj[k];
        xa[k] -= T->c0[k] * x[2 * i + 1] + T->c1[k] * x[2 * i + 3];
    }
    knots_solve(T, xa);
}

/* The full system's solve (x: 2 n + m entries) with the band's factor and the knots': the
 * knots' right-hand side eliminated, the band solved, the knots back-substituted. */
void tirenv_ring__solve_full(tirenv_ring *r, double x[])
{
    tirenv_ring__knots_eliminate(r, x);
    tirenv_ring__solve_after(r, x, 0);
}

/* The knots' own stiffness moves with them (find_knots: their sub-intervals h and, with lugs,
 * their compression k_c): rhs -= (dK_knots/dz) a at the solution x. */
void tirenv_ring__knots_moving(const tirenv_ring *r, const double x[], double rhs[])
{
    const tirenv_ring_tread *T = r->tread;
    const size_t m = T->m, N = 2 * r->n;
    const double *phi = T->kphi, *dp = T->kdphi, *a = x + N;
    const double R = r->R, k_s = tirenv_ring__tread_shear(&r->par);
    double dko_prev = 0;
    for (size_t k = 0; k < m; ++k) {
        const size_t i = T->kj[k], j = r->lo + i;
        const int first = k == 0 || T->kj[k - 1] != i, last = k + 1 == m || T->kj[k + 1] != i;
        const double hl = phi[k] - (first ? r->theta[j] : phi[k - 1]);
        const double hr = (last ? r->theta[j + 1] : phi[k + 1]) - phi[k];
        const double dhl = dp[k] - (first ? 0 : dp[k - 1]);
        const double dhr = (last ? 0 : dp[k + 1]) - dp[k];
        const double s = (phi[k] - r->theta[j]) / r->dth;
        const double k_c = ((1 - s) * T->kap[j] + s * T->kap[j + 1]) / (R * r->dth);
        const double dk_c = (T->kap[j + 1] - T->kap[j]) * dp[k] / (r->dth * R * r->dth);
        const double dkd = -k_s * dhl / (R * hl * hl) - k_s * dhr / (R * hr * hr) +
                           k_c * R * 0.5 * (dhl + dhr) + dk_c * R * 0.5 * (hl + hr);
        const double dko = last ? 0 : k_s * dhr / (R * hr * hr);
        double v = dkd * a[k];
        if (k + 1 < m)
            v += dko * a[k + 1];
        if (k > 0)
            v += dko_prev * a[k - 1];
        rhs[N + k] -= v;
        dko_prev = dko;
    }
}
