/* SPDX-License-Identifier: Apache-2.0 */
/* The ring's tread coupled in shear along the arc (docs/models.md section 5.3): a Pasternak
 * (Filonenko-Borodich) layer between the belt and the ground. The tread surface's inward
 * displacement u is a field of its own, nodal and interpolated between nodes like the belt's w;
 * per unit of belt length the tread stores
 *     1/2 k_c (u - w)^2 + 1/2 k_s (du/ds)^2,   k_s = G_t t_r b (TREAD_SHEAR, the tread depth,
 *                                              BELT_WIDTH),
 * and the ground presses on u at the continuous contact's quadrature points (ring_ground.c)
 * through a contact layer k_g = TIRENV_RING_GROUND_LAYER k_t (ring_impl.h), with k_c chosen so
 * that k_c in series with k_g is the tread's k_t: where the tread surface touches, the tread
 * carries k_t times its compression as before; where it does not, its neighbours drag it in over
 * the decay length sqrt(k_s / k_c). The belt layer beneath the tread acts on w as in
 * ring_smooth.c, so nothing cuts through. The contact is the minimum over the window's (w, u) of
 * the convex, piecewise quadratic
 *     E = 1/2 x.K x + sum_q omega_q R [1/2 k_g max(0, d_q - u_q)^2
 *                                      + 1/2 k_b max(0, d_q - w_q - t_r)^2],
 * K the belt's and the tread's stiffness condensed onto the window. The unknowns are
 * interleaved (w_0, u_0, w_1, u_1, ...), so K is banded with bandwidth 4; the nodes outside the
 * window (no ground) condense out exactly into a 6 x 6 correction on the window's ends (their
 * belt's two end nodes and tread's one), computed once per window length from six banded solves
 * of the exterior. The solve is Newton's method with a line search, the driver ring_smooth.c
 * shares (ring_newton.c).
 *
 * A ground vertex between two nodes (a cleat's corner) presses on the tread surface at one point,
 * where u has a kink that a field linear between nodes cannot follow (its error is of first
 * order in dtheta). So every vertex cut inside a node interval is a knot of u: u is linear
 * between nodes plus, per interval, the hierarchical hats of its knots, zero at the nodes and
 * a_k at knot k, piecewise linear between the knots (u = (1 - s) u_j + s u_j+1 + sum_k a_k
 * hat_k). The hats' shear energy is orthogonal to that of the linear part (the integral of their
 * slope over the interval is zero), so it is the knots' own tridiagonal 1/2 k_s / (R h) (a_k+1
 * - a_k)^2 over the sub-intervals h (a_0 = a_m+1 = 0 at the nodes); their compression is lumped
 * on them alone, 1/2 k_c R (h_k-1 + h_k) / 2 a_k^2. A knot couples to the rest only through
 * the ground's points at it: unloaded, a = 0 and the solution is the nodal one exactly; as a
 * knot nears a node (or another knot) its sub-interval's shear stiffness grows without bound
 * and a tends to the nodal (merged) value, so everything stays continuous in x. The unknowns
 * are the 2 n interleaved ones and then the m knots; the knots are condensed out of each
 * Newton system (their block is tridiagonal, coupled to u_j, u_j+1 of their interval only), so
 * the banded system keeps its bandwidth.
 *
 * This file holds the equilibrium: the window's assembly, the Newton driver's callbacks, the
 * solve on the window or a sub-window, the forces and dF_z/dz. The tread's storage is
 * ring_tread.c's, the sub-windows' choice ring_subwin.c's, the warm start at a new x
 * ring_warm.c's, the banded factorisation ring_tband.c's, the exterior's
 * condensation ring_exterior.c's, the knots' ring_knots.c's and the tests' hooks
 * ring_shear_probe.c's (ring_shear_impl.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "core/capacity.h"
#include "model/ring_shear_impl.h"
#include "model/ring_tband.h"
#include "model/ring_impl.h"

/* The tread's compression stiffness of every node at the centre's x: lugs turn with the tire
 * (ring.c, tread_kappa); k_c in series with the contact layer k_g is the node's k_t. */
static void set_kappa(tirenv_ring *r, double x)
{
    tirenv_ring_tread *T = r->tread;
    if (!T->lugs)
        return;
    for (size_t j = 0; j < T->M; ++j) {
        const double k = tirenv_ring__tread_kappa(r, r->theta[j], x) / (r->R * r->dth);
        T->kap[j] = k * T->k_g / (T->k_g - k) * r->R * r->dth;
    }
}

/* The window's arc of n nodes from lo as add_arc gives it on a zeroed matrix, the band rows'
 * entries written rather than added (the same values: each is one term), so that only the
 * tail's rows need zeroing first; and the right-hand side's 2 n entries (rhs) zeroed with
 * them, in the pass over the nodes that writes their rows, not in a memset of their own. */
void tirenv_ring__fill_window(tband *A, const tirenv_ring_tread *T, size_t lo, size_t n,
                              double rhs[])
{
    const size_t N = 2 * n, m = N - TAIL;
    const double *s = T->s, k_sh = T->k_sh;
    A->N = N;
    A->t = TAIL;
    /* The tail's columns that assemble writes to (FRESH_FROM); band_factor_from takes the
     * others as zero. */
    if (m < FRESH_FROM + BAND_P) {
        memset(A->B, 0, TAIL * m * sizeof *A->B);
    } else {
        memset(A->B, 0, TAIL * FRESH_FROM * sizeof *A->B);
        memset(A->B + TAIL * (m - BAND_P), 0, TAIL * BAND_P * sizeof *A->B);
    }
    memset(A->T, 0, sizeof A->T);
    double *L = A->L;
    size_t e = 0;
    /* The nodes whose two rows lie in the band with all their entries (then e + 2 < n): the
     * rows below, written straight. */
    {
        /* The two rows' ten entries as five pairs, three of them the same at every node, in
         * locals: a store would otherwise make the compiler load s and k_sh again. Without
         * lugs kap is every node's (set_kappa), and so are all five. */
        const double s0 = s[0], k2 = 2 * k_sh, s2 = s[2];
        const v2d s1_0 = {s[1], 0}, z_mk = {0, -k_sh}, zero = {0, 0};
        const double *kap = T->kap + lo;
        if (!T->lugs) {
            const double k = kap[0];
            const v2d w01 = {s0 + k, -k}, w4u0 = {s2, k + k2};
            for (; 2 * e + 1 + BAND_P < m; ++e) {
                double *lw = L + (BAND_P + 1) * 2 * e;
                v2_store(lw, w01);
                v2_store(lw + 2, s1_0);
                v2_store(lw + 4, w4u0);
                v2_store(lw + 6, z_mk);
                v2_store(lw + 8, zero);
                v2_store(rhs + 2 * e, zero);
            }
        }
        for (; 2 * e + 1 + BAND_P < m; ++e) {
            const double k = kap[e];
            double *lw = L + (BAND_P + 1) * 2 * e;
            v2_store(lw, (v2d){s0 + k, -k});      /* lw[0], lw[1] */
            v2_store(lw + 2, s1_0);               /* lw[2], lw[3] */
            v2_store(lw + 4, (v2d){s2, k + k2});  /* lw[4], lu[0] */
            v2_store(lw + 6, z_mk);               /* lu[1], lu[2] */
            v2_store(lw + 8, zero);               /* lu[3], lu[4] */
            v2_store(rhs + 2 * e, zero);
        }
    }
    for (; e < n; ++e) {
        const double kap = T->kap[lo + e];
        rhs[2 * e] = 0, rhs[2 * e + 1] = 0;
        const size_t iw = 2 * e, iu = iw + 1;
        /* Rows w_e, u_e: A[i + k][i] for k = 0 .. BAND_P, those of a tail row in B. */
        const double cw[BAND_P + 1] = {s[0] + kap, -kap, e + 1 < n ? s[1] : 0, 0,
                                       e + 2 < n ? s[2] : 0};
        const double cu[BAND_P + 1] = {kap + 2 * k_sh, 0, e + 1 < n ? -k_sh : 0, 0, 0};
        for (int h = 0; h < 2; ++h) {
            const size_t i = h ? iu : iw;
            const double *c = h ? cu : cw;
            if (i >= m) {
                for (size_t k = 0; i + k < N && k <= BAND_P; ++k)
                    if (c[k] != 0)
                        band_add(A, i, i + k, c[k]);
                continue;
            }
            double *l = L + (BAND_P + 1) * i;
            for (size_t k = 0; k <= BAND_P; ++k) {
                if (i + k < m)
                    l[k] = c[k];
                else {
                    l[k] = 0;
                    if (i + k < N && c[k] != 0)
                        band_add(A, i, i + k, c[k]);
                }
            }
        }
    }
}

/* y = K x: the window's belt and tread stiffness, condensed (x, y interleaved, 2 n entries). */
static void apply_K(const tirenv_ring *r, const double (*Q)[NB], const double x[], double y[])
{
    const tirenv_ring_tread *T = r->tread;
    const size_t n = r->n, lo = r->lo;
    const double *s = T->s, k_sh = T->k_sh;
    for (size_t i = 0; i < n; ++i) {
        const double w = x[2 * i], u = x[2 * i + 1], kap = T->kap[lo + i];
        double yw = s[0] * w + kap * (w - u), yu = kap * (u - w) + 2 * k_sh * u;
        if (i >= 1)
            yw += s[1] * x[2 * i - 2], yu -= k_sh * x[2 * i - 1];
        if (i + 1 < n)
            yw += s[1] * x[2 * i + 2], yu -= k_sh * x[2 * i + 3];
        if (i >= 2)
            yw += s[2] * x[2 * i - 4];
        if (i + 2 < n)
            yw += s[2] * x[2 * i + 4];
        y[2 * i] = yw;
        y[2 * i + 1] = yu;
    }
    size_t b[NB];
    end_index(n, b);
    for (size_t v = 0; v < NB; ++v)
        for (size_t u = 0; u < NB; ++u)
            y[b[v]] -= Q[v][u] * x[b[u]];
    /* The knots' own tridiagonal stiffness. */
    const double *a = x + 2 * n;
    double *ya = y + 2 * n;
    for (size_t k = 0; k < T->m; ++k) {
        double v = T->kd[k] * a[k];
        if (k + 1 < T->m)
            v += T->ko[k] * a[k + 1];
        if (k > 0)
            v += T->ko[k - 1] * a[k - 1];
        ya[k] = v;
    }
}

/* A point's knot (-1: none, a point at a node). */
static long knot_of(const tirenv_ring *r, const tirenv_ring_point *q)
{
    (void)r;
    return q->knot;
}

/* A point's tread surface and belt, interpolated (the surface with its knot's hat). */
static double at_u(const tirenv_ring *r, const tirenv_ring_point *q, const double x[])
{
    const size_t i = q->j - r->lo;
    const long k = knot_of(r, q);
    const double u = (1 - q->s) * x[2 * i + 1] + q->s * x[2 * i + 3];
    return k < 0 ? u : u + x[2 * r->n + (size_t)k];
}

static double at_w(const tirenv_ring *r, const tirenv_ring_point *q, const double x[])
{
    const size_t i = q->j - r->lo;
    return (1 - q->s) * x[2 * i] + q->s * x[2 * i + 2];
}

/* Every point's state at x, from its tread surface and belt there (at_u, at_w): bit 1 the
 * ground on the tread surface, bit 2 the belt layer; returns how many changed. */
static size_t set_states(tirenv_ring *r, const double x[])
{
    tirenv_ring_tread *T = r->tread;
    if (T->soft)
        for (size_t i = 0; i < r->n; ++i)
            T->wc[i] = x[2 * i];
    /* r's fields in locals: a state's store (a char) may alias them. */
    tirenv_ring_point *const pts = r->pts;
    const size_t n_pts = r->n_pts, lo = r->lo;
    const double *const xa = x + 2 * r->n, t_r = r->par.t_r;
    size_t changed = 0;
    for (size_t k = 0; k < n_pts; ++k) {
        tirenv_ring_point *q = &pts[k];
        unsigned char st = 0;
        if (q->d != -INFINITY) {
            const size_t i = q->j - lo;
            const double s = q->s;
            double u = (1 - s) * x[2 * i + 1] + s * x[2 * i + 3];
            if (q->knot >= 0)
                u = u + xa[q->knot];
            const double w = (1 - s) * x[2 * i] + s * x[2 * i + 2];
            st = (unsigned char)((q->d > u ? 1 : 0) | (q->d - w > t_r ? 2 : 0));
        }
        changed += st != q->st;
        q->st = st;
    }
    return changed;
}

/* The points' share of E at x (the layers' energy), their forces taken from grad if it is
 * not NULL (grad holding K x: the gradient of E). */
static double points_energy(tirenv_ring *r, const double x[], double grad[])
{
    const tirenv_ring_tread *T = r->tread;
    const double t_r = r->par.t_r, R = r->R;
    double E = 0;
    for (size_t k = 0; k < r->n_pts; ++k) {
        const tirenv_ring_point *q = &r->pts[k];
        if (q->d == -INFINITY)
            continue;
        const size_t i = q->j - r->lo;
        const double eg = q->d - at_u(r, q, x), eb = q->d - at_w(r, q, x) - t_r;
        const double k_b = TIRENV_RING_BELT_LAYER * q->k_t;
        if (eg > 0) {
            E += q->omega * R * 0.5 * T->k_g * eg * eg;
            if (grad) {
                const double f = q->omega * R * T->k_g * eg;
                const long kn = knot_of(r, q);
                grad[2 * i + 1] -= f * (1 - q->s);
                grad[2 * i + 3] -= f * q->s;
                if (kn >= 0)
                    grad[2 * r->n + (size_t)kn] -= f;
            }
        }
        if (eb > 0) {
            E += q->omega * R * 0.5 * k_b * eb * eb;
            if (grad) {
                const double f = q->omega * R * k_b * eb;
                grad[2 * i] -= f * (1 - q->s);
                grad[2 * i + 2] -= f * q->s;
            }
        }
    }
    if (T->soft) /* the carcass beyond its linear range: its energy and force less k w */
        for (size_t i = 0; i < r->n; ++i) {
            double g1, g2;
            E += tirenv_ring__carcass(&T->law, x[2 * i], &g1, &g2);
            if (grad)
                grad[2 * i] += g1;
        }
    return E;
}

/* The window's system with the points' states fixed: K plus the active layers, and their
 * right-hand side, so that its solution is the minimum of E with those states. */
static void assemble(tirenv_ring *r, const double (*Q)[NB], double rhs[])
{
    tirenv_ring_tread *T = r->tread;
    const size_t n = r->n, lo = r->lo, N = 2 * n;
    const double t_r = r->par.t_r, R = r->R;
    tband *A = &T->as;
    tirenv_ring__fill_window(A, T, lo, n, rhs);
    const size_t m = A->N - A->t; /* the band's rows */
    size_t b[NB];
    end_index(n, b);
    for (size_t v = 0; v < NB; ++v)
        for (size_t u = v; u < NB; ++u)
            band_add(A, b[v], b[u], -Q[v][u]);
    for (size_t k = 0; k < T->m; ++k) {
        rhs[N + k] = 0;
        T->dd[k] = T->kd[k];
        T->c0[k] = T->c1[k] = 0;
    }
    for (size_t k = 0; k < r->n_pts; ++k) {
        const tirenv_ring_point *q = &r->pts[k];
        if (q->st == 0)
            continue;
        const size_t i = q->j - r->lo;
        const double n0 = 1 - q->s, n1 = q->s;
        /* Rows 2 i .. 2 i + 3 in the band (band_add's first case): written there. */
        const int in_band = 2 * i + 3 < m;
        double *const L = A->L + (BAND_P + 1) * 2 * i;
        if (q->st & 1) {
            const double c = q->omega * R * T->k_g;
            if (in_band) {
                L[BAND_P + 1] += c * n0 * n0;
                L[BAND_P + 3] += c * n0 * n1;
                L[3 * (BAND_P + 1)] += c * n1 * n1;
            } else {
                band_add(A, 2 * i + 1, 2 * i + 1, c * n0 * n0);
                band_add(A, 2 * i + 1, 2 * i + 3, c * n0 * n1);
                band_add(A, 2 * i + 3, 2 * i + 3, c * n1 * n1);
            }
            rhs[2 * i + 1] += c * q->d * n0;
            rhs[2 * i + 3] += c * q->d * n1;
            const long kn = knot_of(r, q);
            if (kn >= 0) { /* the knot's hat is 1 there */
                T->dd[kn] += c;
                T->c0[kn] += c * n0;
                T->c1[kn] += c * n1;
                rhs[N + (size_t)kn] += c * q->d;
            }
        }
        if (q->st & 2) {
            const double c = q->omega * R * TIRENV_RING_BELT_LAYER * q->k_t;
            if (in_band) {
                L[0] += c * n0 * n0;
                L[2] += c * n0 * n1;
                L[2 * (BAND_P + 1)] += c * n1 * n1;
            } else {
                band_add(A, 2 * i, 2 * i, c * n0 * n0);
                band_add(A, 2 * i, 2 * i + 2, c * n0 * n1);
                band_add(A, 2 * i + 2, 2 * i + 2, c * n1 * n1);
            }
            rhs[2 * i] += c * (q->d - t_r) * n0;
            rhs[2 * i + 2] += c * (q->d - t_r) * n1;
        }
    }
    /* The carcass linearised at the iterate: its tangent less k on the diagonal, and on the
     * right-hand side what makes the system's residual the gradient's there (Newton's step on
     * the nonlinear system; zero in the linear range). */
    if (T->soft)
        for (size_t i = 0; i < n; ++i) {
            double g1, g2;
            tirenv_ring__carcass(&T->law, T->wc[i], &g1, &g2);
            if (g2 != 0 || g1 != 0) {
                band_add(A, 2 * i, 2 * i, g2);
                rhs[2 * i] += g2 * T->wc[i] - g1;
            }
        }
}

/* d(omega)/dz of point q: half the motion of the angles between its pieces' ends, its
 * neighbours in pts as q->ends says (one piece, or two joined at q: tirenv_ring__sample). */
static double piece_dom(const tirenv_ring_point *q)
{
    if (q->ends == 1)
        return 0.5 * (q[1].dphi - q->dphi);
    const double before = 0.5 * (q->dphi - q[-1].dphi);
    return q->ends == 2 ? before : before + 0.5 * (q[1].dphi - q->dphi);
}

/* Whether point q's cut, or the other cut of a piece it ends, moves with z. */
static int cut_moves(const tirenv_ring_point *q)
{
    return q->dphi != 0 || ((q->ends & 1) && q[1].dphi != 0) ||
           ((q->ends & 2) && q[-1].dphi != 0);
}

/* dF_z/dz follows the cuts at ground vertices (docs/models.md section 5.3): as the centre
 * moves, a vertex's angle phi moves (q->dphi), so its points' place s in their interval, their
 * pieces' weight omega (half the angle between the pieces' ends: piece_dom) and the knot at
 * the vertex do. Point k's share: ds = ds/dz, dom = d(omega)/dz, and the parts of
 * d(f_ground)/dz, d(f_belt)/dz at fixed x that these add to the ground's own motion along the
 * cut (omega R k q->ddt): R k (dom e - omega ds (v_j+1 - v_j)), v the field the layer presses
 * on (u, or w for the belt). Zero for a node's points between nodes' cuts. */
static void moving_cut(const tirenv_ring *r, size_t k, const double x[], double *ds, double *dom,
                       double *dfg, double *dfb)
{
    const tirenv_ring_point *q = &r->pts[k];
    *ds = q->dphi / r->dth;
    *dom = piece_dom(q);
    *dfg = *dfb = 0;
    if (*ds == 0 && *dom == 0)
        return;
    const size_t i = q->j - r->lo;
    const double R = r->R;
    if (q->st & 1)
        *dfg = R * r->tread->k_g *
               (*dom * (q->d - at_u(r, q, x)) - q->omega * *ds * (x[2 * i + 3] - x[2 * i + 1]));
    if (q->st & 2)
        *dfb = R * TIRENV_RING_BELT_LAYER * q->k_t *
               (*dom * (q->d - at_w(r, q, x) - r->par.t_r) -
                q->omega * *ds * (x[2 * i + 2] - x[2 * i]));
}

/* The driver's callbacks (ring_newton.c). */
/* The system at K and the points' states factorised; its right-hand side rhs, eliminated of the
 * knots' and forward-substituted with the factorisation where it can, waits for solve_cb
 * (T->fwd, T->fwd_fused): the driver solves it next. */
static int factor_cb(tirenv_ring *r, const void *K, double rhs[])
{
    tirenv_ring_tread *T = r->tread;
    T->fwd = NULL;
    assemble(r, (const double(*)[NB])K, rhs);
    if (tirenv_ring__condense_knots(T))
        return 1;
    tirenv_ring__knots_eliminate(r, rhs);
    if (tirenv_ring__tband_refactor(&T->as, &T->ap, &T->win, T->ck, &T->ap_ok, rhs,
                                   &T->fwd_fused))
        return 1;
    T->fwd = rhs;
    return 0;
}

static void solve_cb(tirenv_ring *r, double x[])
{
    tirenv_ring_tread *T = r->tread;
    if (x == T->fwd)
        tirenv_ring__solve_after(r, x, T->fwd_fused);
    else
        tirenv_ring__solve_full(r, x);
    T->fwd = NULL;
}

/* The points' terms of E along x + alpha p: per point in reach, the contact layer on the
 * tread surface (c = omega R k_g, a = d - u_q(x), b = u_q(p)) and the belt layer beneath
 * (c = omega R k_b, a = d - w_q(x) - t_r, b = w_q(p)). */
static size_t line_cb(tirenv_ring *r, const double x[], const double p[], const double **c,
                      const double **a, const double **b)
{
    tirenv_ring_tread *T = r->tread;
    if (2 * r->n_pts > T->cap_l) { /* geometric: settles at the largest window's */
        const size_t cap = tirenv_core__capacity(T->cap_l, 512, 2 * r->n_pts);
        double *buf = malloc(3 * cap * sizeof *buf);
        if (!buf)
            return (size_t)-1;
        free(T->lc);
        T->lc = buf;
        T->la = buf + cap;
        T->lb = buf + 2 * cap;
        T->cap_l = cap;
    }
    const double R = r->R, t_r = r->par.t_r;
    size_t n = 0;
    /* A term with a <= 0 and a - b <= 0 is zero all along 0 <= alpha <= 1: left out. */
    for (size_t k = 0; k < r->n_pts; ++k) {
        const tirenv_ring_point *q = &r->pts[k];
        if (q->d == -INFINITY)
            continue;
        const double ag = q->d - at_u(r, q, x), bg = at_u(r, q, p);
        if (ag > 0 || ag - bg > 0) {
            T->lc[n] = q->omega * R * T->k_g;
            T->la[n] = ag;
            T->lb[n] = bg;
            ++n;
        }
        const double ab = q->d - at_w(r, q, x) - t_r, bb = at_w(r, q, p);
        if (ab > 0 || ab - bb > 0) {
            T->lc[n] = q->omega * R * TIRENV_RING_BELT_LAYER * q->k_t;
            T->la[n] = ab;
            T->lb[n] = bb;
            ++n;
        }
    }
    *c = T->lc, *a = T->la, *b = T->lb;
    return n;
}

/* The softening carcass along x + alpha p: its energy's slope and curvature at alpha = 0. */
static void carcass_line(tirenv_ring *r, const double x[], const double p[], double *d1,
                         double *d2)
{
    const tirenv_ring_tread *T = r->tread;
    double s1 = 0, s2 = 0;
    for (size_t i = 0; i < r->n; ++i) {
        double g1, g2;
        tirenv_ring__carcass(&T->law, x[2 * i], &g1, &g2);
        s1 += g1 * p[2 * i];
        s2 += g2 * p[2 * i] * p[2 * i];
    }
    *d1 = s1;
    *d2 = s2;
}

static void apply_cb(tirenv_ring *r, const void *K, const double x[], double y[])
{
    apply_K(r, (const double(*)[NB])K, x, y);
}


/* With the softening carcass the Newton system is the energy's linearisation: settled when
 * the states stay and a step moves no unknown by more than this (m; the equilibrium's own
 * STEP_TOLERANCE default, and Newton's quadratic convergence leaves an error of about
 * step^2/w_s beyond it). A smaller one met the round-off of the stiff contact layer (the
 * sub-window and the whole window agree to 4e-12 m). */
static const double carcass_newton_tol = 1e-10;

typedef struct {
    tirenv_ring_point *pts;
    size_t n_pts, lo, n;
} window_save;

/* r's window and points become the nodes a .. b and the points pts[k0 .. k1); leave restores
 * them. */
static void enter(tirenv_ring *r, window_save *sv, size_t a, size_t b, size_t k0, size_t k1)
{
    *sv = (window_save){r->pts, r->n_pts, r->lo, r->n};
    r->pts += k0;
    r->n_pts = k1 - k0;
    r->lo = a;
    r->n = b - a + 1;
}

static void leave(tirenv_ring *r, const window_save *sv)
{
    r->pts = sv->pts;
    r->n_pts = sv->n_pts;
    r->lo = sv->lo;
    r->n = sv->n;
}

/* The contact Newton's peel (ring_newton.c). PEEL_GRAZE (m): a point pressed in by no more
 * than this at the Newton point is grazing, the tread draped over a corner; the points freed
 * one a step lay 1e-8 to 2e-6 m clear at the step that freed them in the solves looked at, and
 * 3e-7 m and 1e-5 m cost more instructions over the cleats (docs/performance.md 2.24). */
static const double PEEL_GRAZE = 1e-6;

/* A point in contact (its tread surface) at the Newton point xn, free at the start x0, pressed
 * in at xn by at most PEEL_GRAZE. */
static int grazes(const tirenv_ring *r, const tirenv_ring_point *q, const double x0[],
                  const double xn[])
{
    return (q->st & 1) && !(q->d > at_u(r, q, x0)) && q->d - at_u(r, q, xn) <= PEEL_GRAZE;
}

/* The driver's peel callback: the points that the step from x to xn freed (in contact at x, free
 * now) and that were free at the start x0; each frees with it the grazing points beside it, on
 * either side, that came into contact since x0 (a run entered with it). Freed is st 0, both
 * bits: a guess, which the next step's set_states overrules where wrong. Returns how many it
 * freed, and counts them in T->n_peel. */
static size_t peel_cb(tirenv_ring *r, const double x0[], const double x[], const double xn[])
{
    tirenv_ring_point *const pts = r->pts;
    const size_t n_pts = r->n_pts;
    size_t freed = 0;
    for (size_t k = 0; k < n_pts; ++k) {
        const tirenv_ring_point *q = &pts[k];
        /* Freed beside a point in contact (else there is no run to free), entered since x0. */
        if (q->st != 0 ||
            !((k > 0 && (pts[k - 1].st & 1)) || (k + 1 < n_pts && (pts[k + 1].st & 1))) ||
            q->d == -INFINITY || !(q->d > at_u(r, q, x)) || q->d > at_u(r, q, x0))
            continue;
        for (size_t i = k; i-- > 0 && grazes(r, &pts[i], x0, xn);)
            pts[i].st = 0, ++freed;
        for (size_t i = k + 1; i < n_pts && grazes(r, &pts[i], x0, xn); ++i)
            pts[i].st = 0, ++freed;
    }
    r->tread->n_peel += freed;
    return freed;
}

/* Whether solve_on's Newton peels, with m knots on n nodes: not with the softening carcass
 * (whose Newton has no full steps to peel), nor where the tests ask so (no_peel), nor with more
 * than a knot per 8 nodes. */
static int peels(const tirenv_ring_tread *T, size_t m, size_t n)
{
    return !T->soft && !T->no_peel && 8 * m <= n;
}

/* Newton on the nodes a .. b with the points pts[k0 .. k1) (a .. b the whole window: every
 * point), from the window's xw there and the knots at zero: its answer, knots included, in
 * T->x, and copied into xw; with want, the factor of its final states in T->win. -1 if out of
 * memory for the knots, else the driver's status. */
static int solve_on(tirenv_ring *r, double x_c, size_t a, size_t b, size_t k0, size_t k1,
                    int want)
{
    tirenv_ring_tread *T = r->tread;
    double *xw = T->xw + 2 * (a - r->lo);
    window_save sv;
    enter(r, &sv, a, b, k0, k1);
    const size_t N = 2 * r->n;
    int st = -1;
    if (!tirenv_ring__find_knots(r)) {
        const size_t m = T->m;
        if (T->poison)
            tirenv_ring__poison_past(T, N, m);
        const double(*Q)[NB] = tirenv_ring__window_end(r, x_c);
        double *x = T->x;
        memcpy(x, xw, N * sizeof *x);
        for (size_t k = 0; k < m; ++k)
            x[N + k] = 0;
        /* The peel (ring_newton.c) where the vertex cuts are few, as over obstacles: over a
         * road, a cut in every node interval or more, its pass over the many points and its
         * wrong guesses cost more than it saved (the 1 mm road's instructions +0.5 %,
         * docs/performance.md 2.24). */
        const tirenv_ring_newton nw = {N + m, Q, factor_cb, solve_cb, set_states, apply_cb,
                                       points_energy, T->kp, line_cb,
                                       T->soft ? carcass_newton_tol : 0, &T->n_newton,
                                       T->soft ? carcass_line : NULL,
                                       peels(T, m, r->n) ? peel_cb : NULL};
        int factored;
        st = tirenv_ring__newton(r, &nw, x, T->xn, T->xt, T->g, &factored);
        /* The factor of the final states, for dF_z/dz (the last Newton step's, if they did
         * not change with it: the same matrix). */
        if (st == TIRENV_RING_NEWTON_OK && want && !factored && factor_cb(r, Q, T->xt))
            st = TIRENV_RING_NEWTON_BREAKDOWN;
        T->fin_factored = want || factored, T->fin_Q = Q;
        memcpy(xw, x, N * sizeof *x);
    }
    leave(r, &sv);
    return st;
}

/* solve_on over the whole window, and if its Newton does not settle, once more from rest (w
 * and u zero, a first evaluation's start). The warm start is the last equilibrium's belt and
 * tread moved along their slope in z; where z jumps by centimetres (Brent's bisection after a
 * root: 0.148 m over Horstwalde.crg) that extrapolation can leave Newton more than its 200
 * steps from the minimum, which does not depend on the start. Only a solve that failed is
 * repeated: every answer that settled is as it was. */
static int solve_whole(tirenv_ring *r, double x_c, int want)
{
    int st = solve_on(r, x_c, r->lo, r->lo + r->n - 1, 0, r->n_pts, want);
    if (st == TIRENV_RING_NEWTON_NOCONV) {
        memset(r->tread->xw, 0, 2 * r->n * sizeof *r->tread->xw);
        st = solve_on(r, x_c, r->lo, r->lo + r->n - 1, 0, r->n_pts, want);
    }
    return st;
}

/* The error of solve_on's status st on n nodes. */
static int solve_error(const tirenv_ring *r, int st, size_t n, tirenv_diag *diag)
{
    if (st < 0)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "ring",
                            "out of memory for the tread surface's knots");
    return tirenv_ring__newton_error(r, st, n, "belt-and-tread", "shear-coupled tread", diag);
}

/* dF_z/dz of the equilibrium just solved on the window entered (its nodes and points): dx/dz
 * from xt, the force pass's part of its right-hand side, then the sum over the points in
 * contact. */
static double slope_in(tirenv_ring *r, const double x[], double xt[])
{
    tirenv_ring_tread *T = r->tread;
    const double R = r->R;
    tirenv_ring__knots_moving(r, x, xt);
    tirenv_ring__solve_full(r, xt); /* dx/dz */
    double dF = 0;
    for (size_t k = 0; k < r->n_pts; ++k) {
        const tirenv_ring_point *q = &r->pts[k];
        if (q->st == 0)
            continue;
        double df = 0;
        if (q->st & 1)
            df += q->omega * R * T->k_g * (q->ddt - at_u(r, q, xt));
        if (q->st & 2)
            df += q->omega * R * TIRENV_RING_BELT_LAYER * q->k_t * (q->ddt - at_w(r, q, xt));
        if (cut_moves(q)) {
            double ds, dom, dfg, dfb;
            moving_cut(r, k, x, &ds, &dom, &dfg, &dfb);
            df += ((q->st & 1) ? dfg : 0) + ((q->st & 2) ? dfb : 0);
            dF -= q->f * q->sn * q->dphi; /* the force's direction turns with the cut */
        }
        dF += df * q->cs;
    }
    return dF;
}

/* dx/dz of that equilibrium (xt, on the nodes a .. b solved) kept over the window as the
 * next evaluation's warm start: its slope in z from z. */
static void slope_out(tirenv_ring *r, size_t a, size_t b, int sub, double z, double x_c)
{
    tirenv_ring_tread *T = r->tread;
    const size_t lo = r->lo, n = r->n, N = 2 * (b - a + 1);
    double *dxw = T->dxw;
    const double *xt = T->xt;
    memcpy(dxw + 2 * (a - lo), xt, N * sizeof *xt);
    if (sub)
        tirenv_ring__fill_free(r, a, b, dxw);
    for (size_t i = 0; i < n; ++i) {
        T->dw[lo + i] = dxw[2 * i];
        T->du[lo + i] = dxw[2 * i + 1];
    }
    T->pred[0] = z, T->pred[1] = x_c, T->pred[2] = 1;
}

/* solve_shear's statuses where the window's ground has gaps (ring_ground.c) that it needs
 * sampled: NEED_GROUND, a sub-window reaching a gap or a gap its bound does not certify clear
 * of the answer (then solved again from where it had come); NEED_WHOLE, the whole window to
 * solve (then solved so at once, as it would have been). And the starts: predicted along the
 * slope, where the last solve had come (T->xw), and that on the whole window. */
enum { NEED_GROUND = -2, NEED_WHOLE = -3 };
enum { START_PREDICTED, START_KEPT, START_WHOLE };

/* The start of a new evaluation: the last evaluation's belt and tread where this window
 * overlaps its window, moved along their slope in z to this z (dx/dz of that equilibrium,
 * found with its dF_z/dz), zero elsewhere; the states of the first Newton step are then
 * nearly this equilibrium's. The minimum does not depend on the start (its states' system is
 * solved last). */
static void warm_predict(tirenv_ring *r, double x_c, double z, double xw[])
{
    const tirenv_ring_tread *T = r->tread;
    const size_t n = r->n, lo = r->lo;
    const double dz = T->pred[2] != 0 ? z - T->pred[0] : 0;
    /* The last window's nodes in this one, lo + ia .. lo + ib - 1; zero elsewhere. */
    const size_t wa = r->warm_lo > lo ? r->warm_lo : lo, w1 = r->warm_lo + r->warm_n,
                 wb = w1 < lo + n ? w1 : lo + n;
    const size_t ia = wa < wb ? wa - lo : 0, ib = wa < wb ? wb - lo : 0;
    for (size_t i = 0; i < ia; ++i)
        xw[2 * i] = xw[2 * i + 1] = 0;
    for (size_t i = ia; i < ib; ++i) {
        const size_t j = lo + i;
        xw[2 * i] = r->w[j] + dz * T->dw[j];
        xw[2 * i + 1] = T->u[j] + dz * T->du[j];
    }
    for (size_t i = ib; i < n; ++i)
        xw[2 * i] = xw[2 * i + 1] = 0;
    tirenv_ring__warm_shift(r, x_c, z, xw);
}

/* The nodes solved, a .. b (the whole window or a sub-window), and their points k0 .. k1. */
typedef struct {
    size_t a, b, k0, k1;
    int sub;  /* a sub-window */
} solved_span;

/* The equilibrium on the sub-window of the contact (see sub_window; not with lugs, whose
 * exterior turns with the tire) where there is one; else, or where a free point would touch,
 * on the whole window, and then on the sub-window of its contact. Into T->xw, with where it
 * was solved in *s and, with the carcass's law, the node outside the nodes solved pressed in
 * furthest in *j_out. 0, NEED_GROUND or NEED_WHOLE, or an error. */
static int solve_span(tirenv_ring *r, double x_c, int start, int want, solved_span *s,
                      size_t *j_out, tirenv_diag *diag)
{
    tirenv_ring_tread *T = r->tread;
    const size_t n = r->n, lo = r->lo, hi = lo + n - 1, n_pts = r->n_pts;
    double *xw = T->xw;
    size_t a = lo, b = hi, k0 = 0, k1 = n_pts, kf, kl, a2, b2, k02, k12;
    size_t beyond[2];
    int sub = start != START_WHOLE && !T->lugs && !T->whole &&
              tirenv_ring__contact_span(r, 0, n_pts, xw, 1, &kf, &kl) &&
              tirenv_ring__sub_window(r, kf, kl, tirenv_ring__warm_span(r, x_c, xw, beyond), &a,
                                      &b, &k0, &k1);
    if (r->n_gaps && !sub)
        return NEED_WHOLE;
    if (r->n_gaps && !tirenv_ring__sampled_over(r, a, b))
        return NEED_GROUND;
    for (size_t t = 0; sub; ++t) {
        sub = t < SUB_TRIES && tirenv_ring__sub_cols(T, a, b - a + 1) &&
              solve_on(r, x_c, a, b, k0, k1, want) == TIRENV_RING_NEWTON_OK &&
              tirenv_ring__contact_span(r, k0, k1, xw, 0, &kf, &kl);
        if (sub && T->soft) /* the free nodes' w, for those pressed beyond w_0 */
            tirenv_ring__fill_free(r, a, b, xw);
        sub = sub && tirenv_ring__sub_window(r, kf, kl, tirenv_ring__beyond_span(r, xw, beyond),
                                             &a2, &b2, &k02, &k12);
        if (!sub)
            break;
        if (r->n_gaps && !tirenv_ring__sampled_over(r, a2, b2))
            return NEED_GROUND;
        if (a2 == a && b2 == b) {
            if (!T->soft) /* with the law, filled above */
                tirenv_ring__fill_free(r, a, b, xw);
            sub = tirenv_ring__free_clear(r, k0, k1, xw);
            if (sub && !tirenv_ring__gaps_clear(r, xw))
                return NEED_GROUND; /* the free points sampled may be clear after all */
            sub = sub && (!T->soft || tirenv_ring__outside_sub(r, a, b, xw, j_out) <= T->law.w_0);
            break;
        }
        a = a2, b = b2, k0 = k02, k1 = k12;
    }
    if (!sub && r->n_gaps)
        return NEED_WHOLE;
    if (!sub) {
        int st = solve_whole(r, x_c, want);
        if (st != TIRENV_RING_NEWTON_OK)
            return solve_error(r, st, n, diag);
        /* The same answer as the sub-window's of this contact, if it has one: solved there
         * (one Newton step, the states kept), else the whole window's. */
        sub = !T->lugs && !T->whole && tirenv_ring__contact_span(r, 0, n_pts, xw, 0, &kf, &kl) &&
              tirenv_ring__sub_window(r, kf, kl, tirenv_ring__beyond_span(r, xw, beyond), &a,
                                      &b, &k0, &k1) &&
              tirenv_ring__sub_cols(T, a, b - a + 1);
        if (sub) {
            st = solve_on(r, x_c, a, b, k0, k1, want);
            if (st != TIRENV_RING_NEWTON_OK)
                return solve_error(r, st, b - a + 1, diag);
            tirenv_ring__fill_free(r, a, b, xw);
            sub = tirenv_ring__free_clear(r, k0, k1, xw) &&
                  (!T->soft || tirenv_ring__outside_sub(r, a, b, xw, j_out) <= T->law.w_0);
            if (!sub) { /* round-off at the sub-window's ends, or the carcass beyond its
                         * linear range there: the whole window's, again */
                st = solve_whole(r, x_c, want);
                if (st != TIRENV_RING_NEWTON_OK)
                    return solve_error(r, st, n, diag);
            }
        }
    }
    if (!sub)
        a = lo, b = hi, k0 = 0, k1 = n_pts;
    *s = (solved_span){a, b, k0, k1, sub};
    return 0;
}

/* The window's answer xw kept as the next evaluation's warm start: w and u on this window,
 * dw and du cleared where this one does not overwrite them (with dF_z/dz, or deferred, they
 * are written after); the last evaluation's cleared outside it. F and g zeroed for the force
 * pass. */
static void warm_keep(tirenv_ring *r, double z, const double xw[], int slope)
{
    tirenv_ring_tread *T = r->tread;
    const size_t lo = r->lo, n = r->n;
    const size_t w0 = r->warm_lo, w1 = w0 + r->warm_n, h1 = lo + n;
    for (size_t j = w0; j < w1 && j < lo; ++j)
        r->w[j] = T->u[j] = T->dw[j] = T->du[j] = 0;
    for (size_t j = w0 > lo ? w0 : lo; !slope && !T->defer && j < w1 && j < h1; ++j)
        T->dw[j] = T->du[j] = 0;
    for (size_t j = w0 > h1 ? w0 : h1; j < w1; ++j)
        r->w[j] = T->u[j] = T->dw[j] = T->du[j] = 0;
    /* Deferred, the last slope (of the evaluation before, or none) predicts from here until
     * one is asked for (tirenv_ring__shear_slope writes this one's, as with dfz_dz). */
    if (T->defer)
        T->pred[0] = z;
    else
        T->pred[2] = 0;
    r->warm_lo = lo;
    r->warm_n = n;
    for (size_t i = 0; i < n; ++i) {
        r->w[lo + i] = xw[2 * i];
        T->u[lo + i] = xw[2 * i + 1];
        r->F[lo + i] = 0;
        r->g[lo + i] = 0;
    }
}

/* What the force pass over the points found. */
typedef struct {
    double sum_c, sum_s;      /* sum f cos, sum f sin over the points in contact, N */
    size_t k_first, k_last;   /* the first and the last point in contact (k_first > k_last:
                               * none) */
    double e_pts;             /* their largest tread compression u - w, m */
} point_sums;

/* The forces of the points in contact on the window entered (x its answer): each point's f
 * and overlap e, the nodes' F and g, and with rhs the right-hand side of dx/dz into xt
 * (-d(grad E)/dz at fixed x). */
static void point_forces(tirenv_ring *r, const double x[], double xt[], int rhs, point_sums *p)
{
    const tirenv_ring_tread *T = r->tread;
    const size_t ls = r->lo, N = 2 * r->n;
    const double R = r->R, t_r = r->par.t_r;
    double sum_c = 0, sum_s = 0;
    size_t k_first = 1, k_last = 0;
    double e_pts = 0;
    for (size_t k = 0; k < r->n_pts; ++k) {
        tirenv_ring_point *q = &r->pts[k];
        q->f = 0;
        if (q->st == 0) /* its overlap e below, if it borders the patch */
            continue;
        const double u = at_u(r, q, x);
        q->e = q->d - u; /* the ground's overlap with the tread surface */
        if (k_first > k_last)
            k_first = k;
        k_last = k;
        const double v = u - at_w(r, q, x);
        if (v > e_pts)
            e_pts = v;
        const size_t i = q->j - ls;
        const double k_b = TIRENV_RING_BELT_LAYER * q->k_t;
        double fg = 0, fb = 0, cu = 0, cw = 0;
        if (q->st & 1) {
            fg = q->omega * R * T->k_g * q->e;
            cu = q->omega * R * T->k_g * q->ddt;
        }
        if (q->st & 2) {
            fb = q->omega * R * k_b * (q->d - at_w(r, q, x) - t_r);
            cw = q->omega * R * k_b * q->ddt;
        }
        q->f = fg + fb;
        r->F[q->j] += (1 - q->s) * q->f;
        r->F[q->j + 1] += q->s * q->f;
        if (q->st & 2) { /* else fb = 0, and adding +0 leaves g (never -0: from +0, sums of
                          * terms >= 0) the same bits */
            r->g[q->j] += (1 - q->s) * fb;
            r->g[q->j + 1] += q->s * fb;
        }
        sum_c += q->f * q->cs;
        sum_s += q->f * q->sn;
        if (!rhs) /* deferred: the right-hand side kept for the request */
            continue;
        /* -d(grad E)/dz at fixed x: the ground moving along the point's cut (q->ddt), and, at
         * a vertex's cut, the cut itself moving (its place s and its piece's weight). */
        double ds = 0, dfg = 0, dfb = 0;
        if (cut_moves(q)) {
            double dom;
            moving_cut(r, k, x, &ds, &dom, &dfg, &dfb);
        } /* else the cut and its piece stay: moving_cut's ds = +-0, dfg = dfb = 0 */
        cu += dfg;
        cw += dfb;
        xt[2 * i + 1] += cu * (1 - q->s);
        xt[2 * i + 3] += cu * q->s;
        if (knot_of(r, q) >= 0)
            xt[N + (size_t)knot_of(r, q)] += cu;
        if (cw != 0) { /* else adding +-0 leaves xt (never -0: from +0, a sum is -0 only
                        * of two -0) the same bits */
            xt[2 * i] += cw * (1 - q->s);
            xt[2 * i + 2] += cw * q->s;
        }
        if (ds != 0) {
            xt[2 * i + 1] -= fg * ds, xt[2 * i + 3] += fg * ds;
            xt[2 * i] -= fb * ds, xt[2 * i + 2] += fb * ds;
        }
    }
    /* A free point's overlap is read only beside the patch (ring.c's patch length): there. */
    if (k_first <= k_last) {
        const size_t side[2] = {k_first - 1, k_last + 1}; /* k_first - 1 wraps at 0 */
        for (int e = 0; e < 2; ++e)
            if (side[e] < r->n_pts) {
                tirenv_ring_point *q = &r->pts[side[e]];
                q->e = q->d == -INFINITY ? -INFINITY : q->d - at_u(r, q, x);
            }
    }
    *p = (point_sums){sum_c, sum_s, k_first, k_last, e_pts};
}

/* The diagnostics' largest tread compression u - w: at the window's n nodes (xw, the free
 * ones' too) and at the points in contact (e_pts), at most the tread's thickness t_r. */
static double tread_compression(const double xw[], size_t n, double e_pts, double t_r)
{
    double e_max = 0; /* "v > e_max": fmax(e_max, v) without its call, the same bits (e_max
                       * is never NaN; a NaN v is passed over; of two zeros the first kept:
                       * so the largest, in any order, the points' taken in the force pass) */
    for (size_t i = 0; i < n; ++i) {
        const double v = xw[2 * i + 1] - xw[2 * i];
        if (v > e_max)
            e_max = v;
    }
    if (e_pts > e_max)
        e_max = e_pts;
    return fmin(e_max, t_r);
}

static int solve_shear(tirenv_ring *r, double x_c, double z, double *fx, double *fz,
                       double *dfz_dz, int start, tirenv_diag *diag)
{
    tirenv_ring_tread *T = r->tread;
    const size_t n = r->n, lo = r->lo, hi = lo + n - 1;
    if (n + 4 > r->M)
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "ring",
                            "the contact window of %zu nodes leaves too few of the %zu outside "
                            "it", n, r->M);
    set_kappa(r, x_c);
    T->deferred = 0;
    double *xw = T->xw;
    if (start == START_PREDICTED)
        warm_predict(r, x_c, z, xw);
    solved_span s = {0, 0, 0, 0, 0}; /* set by solve_span where it returns 0 */
    size_t j_out = 0;
    const int st = solve_span(r, x_c, start, dfz_dz != NULL, &s, &j_out, diag);
    if (st)
        return st;
    if (!s.sub && T->soft) {
        const double w_out = tirenv_ring__outside_whole(r, xw, &j_out);
        /* Beyond the lower half (ring.c's window with the law): a tall obstacle pressing the
         * belt in far from the patch. Solved again on all of the ring but its top nodes,
         * pulled out (no further: their condensation needs some exterior). */
        const size_t h = r->M / 2 - 4;
        if (!(w_out <= T->law.w_0) && (lo > r->i0 - h || hi < r->i0 + h)) {
            r->lo = r->i0 - h;
            r->n = 2 * h + 1;
            return tirenv_ring__solve_shear(r, x_c, z, fx, fz, dfz_dz, diag);
        }
        if (!(w_out <= T->law.w_0))
            return tirenv_error(diag, TIRENV_ERANGE, "", 0, "CARCASS_LINEAR_DEFLECTION",
                                "the belt outside the %zu-node contact window is pressed in "
                                "%.4g m at node %zu (theta %.4g rad), beyond the carcass's "
                                "linear range %.4g m, which the window's condensation needs",
                                n, w_out, j_out, r->theta[j_out], T->law.w_0);
    }
    T->n_sub += s.sub != 0;
    /* The next sampling's far stretches are those of this sub-window (ring_ground.c). */
    r->near_ok = s.sub && !T->lugs && !T->whole && !T->soft;
    r->near_a = s.a, r->near_b = s.b;
    /* The window's free points, clear of the ground, were written by free_clear. */
    warm_keep(r, z, xw, dfz_dz != NULL);
    /* The forces and dx/dz on the nodes solved (the whole window or a sub-window). */
    window_save sv;
    enter(r, &sv, s.a, s.b, s.k0, s.k1);
    const double *x = T->x;
    double *xt = T->xt;
    for (size_t i = 0; i < 2 * r->n + T->m; ++i)
        xt[i] = 0;
    point_sums p;
    point_forces(r, x, xt, dfz_dz || T->defer, &p);
    *fz = p.sum_c;
    *fx = -p.sum_s;
    if (dfz_dz)
        *dfz_dz = slope_in(r, x, xt);
    r->tread_max = tread_compression(xw, n, p.e_pts, r->par.t_r);
    leave(r, &sv);
    r->k_first = p.k_first + s.k0; /* the window's points outside pts[k0 .. k1) are free */
    r->k_last = p.k_last + s.k0;
    T->last_x = x_c, T->last_z = z, T->last_ok = 1;
    T->span[0] = p.k_first <= p.k_last;
    if (p.k_first <= p.k_last) {
        T->span[1] = (double)r->pts[r->k_first].j;
        T->span[2] = (double)(r->pts[r->k_last].j + 1);
        T->span[3] = x_c;
    }
    if (dfz_dz)
        slope_out(r, s.a, s.b, s.sub, z, x_c);
    T->deferred = !dfz_dz && T->defer;
    if (T->deferred)
        T->dfr = (deferred_window){s.a, s.b, s.k0, s.k1, s.sub, z, x_c};
    return 0;
}

int tirenv_ring__solve_shear(tirenv_ring *r, double x_c, double z, double *fx, double *fz,
                             double *dfz_dz, tirenv_diag *diag)
{
    int st = solve_shear(r, x_c, z, fx, fz, dfz_dz, START_PREDICTED, diag);
    if (st == NEED_GROUND || st == NEED_WHOLE) {
        /* The window's gaps sampled, and solved again from where that solve had come (its
         * window's (w, u) in T->xw: the minimum does not depend on the start). */
        r->near_ok = 0;
        if (tirenv_ring__sample_whole(r))
            return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "ring", "out of memory for the "
                                "contact of %zu ground points", r->n_pts);
        st = solve_shear(r, x_c, z, fx, fz, dfz_dz,
                         st == NEED_WHOLE ? START_WHOLE : START_KEPT, diag);
    }
    return st;
}

int tirenv_ring__defer_slope(tirenv_ring *r, int on)
{
    /* Not with the softening carcass: its minimum, found to the carcass's Newton tolerance,
     * depends on the start, which an unasked slope changes (more evaluations, not fewer). */
    if (!r->tread || r->tread->soft)
        return 0;
    r->tread->defer = on;
    r->tread->deferred = 0;
    return on;
}

int tirenv_ring__deferring(const tirenv_ring *r) { return r->tread && r->tread->defer; }

/* dF_z/dz of the last evaluation, which deferred it (T->defer): as tirenv_ring__solve_shear
 * would have computed it, the same operations on the same state (the window's solve, its
 * points and the force pass's part of dx/dz's right-hand side in T->xt are as the evaluation
 * left them). Nonzero if there is none to give or the final states' factorisation breaks
 * down. */
int tirenv_ring__shear_slope(tirenv_ring *r, double *dfz_dz)
{
    tirenv_ring_tread *T = r->tread;
    if (!T || !T->deferred)
        return -1;
    T->deferred = 0;
    window_save sv;
    const deferred_window *w = &T->dfr;
    enter(r, &sv, w->a, w->b, w->k0, w->k1);
    /* The final states' factor where the last Newton step's was not (its right-hand side,
     * not wanted, into the Newton's spare vector: T->xt holds dx/dz's). */
    int bad = !T->fin_factored && factor_cb(r, T->fin_Q, T->xn);
    if (!bad)
        *dfz_dz = slope_in(r, T->x, T->xt);
    leave(r, &sv);
    if (!bad)
        slope_out(r, w->a, w->b, w->sub, w->z, w->x_c);
    return bad;
}
