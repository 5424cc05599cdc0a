/* SPDX-License-Identifier: Apache-2.0 */
/* Where the springs model's hub force meets the load on the working set of the last QP solve
 * (docs/models.md section 4.8, Cost): Newton's step solved together with the QP's equalities,
 * so that the next evaluation, at that height, is the update's check of the working set there
 * (springs_update.c) instead of a full evaluation and a third one to confirm it.
 *
 * With the working set fixed, the held elements sit on their rays' rows, linear in z on the
 * faces the rays end on (a held element on a ground vertex is not taken), and the free ones
 * solve K_FF w_F = b_F(z) + G_W(z)^T lambda. The tangent w_T = w_0 + dz dw (the base's slope)
 * already moves b_F and the rows' weights to first order, so the state at z is
 *
 *     w = w_T + sum_s B_s K_FF^-1 e_s,   B_s = lambda_q g_s(z) - lambda_0q g_s0
 *                                              - dz (dlambda_q g_s0 + lambda_0q dg_s/dz),
 *
 * s over the working rows' two elements each (their weights g_s: a and b), and the rows'
 * equalities g(z) . w + c(z) lambda = h(z) are k equations in the k reactions, linear once z
 * is fixed: a k x k system from the columns of K_FF^-1 at the rows' elements. F_z is linear
 * in w, F = F_0 + dz dF_0 + sum_s B_s phi_s with phi_s = f . K_FF^-1 e_s (f the hub's
 * weights), so F(z) = G is a scalar root, found by the secant from the base and Newton's
 * step. O(k) a step after 2 k solves on the rows' chains. */
#include "model/springs_impl.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include "profile/profile_impl.h"

enum { K_MAX = TIRENV_SPRINGS__SCHUR_MAX, S_MAX = 2 * TIRENV_SPRINGS__SCHUR_MAX };

/* Secant steps before giving up: from Newton's step (1e-5 to 1e-4 m from the base) the
 * root is at round-off in three or four. */
enum { max_steps = 12 };

/* A vertex row inside its sector: its t more than this from either element (springs_rows.c's
 * snap), else its row would change kind on the way. */
static const double t_snap = TIRENV_SPRINGS__T_SNAP;

/* The working rows as the base left them, and what the root needs of K_FF^-1. */
typedef struct {
    size_t k;                          /* rows between elements */
    size_t el[S_MAX];                  /* each row's two elements: slots 2 q, 2 q + 1 */
    int fr[S_MAX];                     /* the slot's element is free */
    double g0[S_MAX], g1[S_MAX];       /* the weights at the base and their d/dz, 1/m */
    double l0[K_MAX], dl[K_MAX];       /* reactions at the base (N) and d/dz (N/m) */
    double X[K_MAX], Z[K_MAX];         /* the rows' ground vertices, m */
    double phi[S_MAX];                 /* f . K_FF^-1 e_s, N/N */
    double Y[S_MAX][S_MAX];            /* Y[s][r]: (K_FF^-1 e_s) at slot r's element, m/N */
    double w_T[S_MAX], dw[S_MAX];      /* the base's w and dw/dz at the slots */
} root_rows;

/* At centre height z (dz from the base): the reactions lam, the slots' B and F - F_0 - dz
 * dF_0 (N) into *dF; 0 if a row leaves its sector's inside. */
static int at_height(const tirenv_springs__cc_tire *T, const root_rows *W, double x, double z,
                     double dz, double lam[], double B[], double *dF)
{
    const size_t k = W->k, ns = 2 * k;
    const double *st = T->sin_t, *ct = T->cos_t;
    double g[S_MAX], cmp[K_MAX], h[K_MAX], kap[S_MAX], u[S_MAX];
    for (size_t q = 0; q < k; ++q) {
        const size_t i = W->el[2 * q];
        const double dx = W->X[q] - x, dzv = z - W->Z[q];
        const double s_i = dx * ct[i] - dzv * st[i], s_n = dzv * st[i + 1] - dx * ct[i + 1];
        const double t = s_i / (s_i + s_n);
        if (!(s_i > 0 && s_n > 0 && t > t_snap && t < 1 - t_snap))
            return 0;
        double da, db;
        tirenv_springs__cc_weights(T, t, &g[2 * q], &g[2 * q + 1], &da, &db);
        cmp[q] = tirenv_springs__cc_compliance(T, g[2 * q], g[2 * q + 1]);
        h[q] = T->R0 - sqrt(dx * dx + dzv * dzv);
    }
    for (size_t s = 0; s < ns; ++s) {
        const size_t q = s / 2;
        kap[s] = W->fr[s] ? W->l0[q] * W->g0[s] +
                                dz * (W->dl[q] * W->g0[s] + W->l0[q] * W->g1[s])
                          : 0;
    }
    for (size_t r = 0; r < ns; ++r) {
        double v = W->w_T[r] + dz * W->dw[r];
        for (size_t s = 0; s < ns; ++s)
            v -= kap[s] * W->Y[s][r];
        u[r] = v;
    }
    /* M lambda = rhs: M = G K_FF^-1 G^T + C at z, symmetric positive definite (the rows
     * independent), by Cholesky without pivoting. */
    double M[K_MAX][K_MAX], rhs[K_MAX];
    for (size_t q = 0; q < k; ++q) {
        rhs[q] = h[q] - g[2 * q] * u[2 * q] - g[2 * q + 1] * u[2 * q + 1];
        for (size_t p = 0; p < k; ++p) {
            double m = 0;
            for (size_t a = 2 * q; a < 2 * q + 2; ++a)
                for (size_t b = 2 * p; b < 2 * p + 2; ++b)
                    m += g[a] * g[b] * W->Y[b][a];
            M[q][p] = m + (p == q ? cmp[q] : 0);
        }
    }
    for (size_t q = 0; q < k; ++q) {
        for (size_t p = 0; p < q; ++p) {
            double v = M[q][p];
            for (size_t m = 0; m < p; ++m)
                v -= M[q][m] * M[p][m];
            M[q][p] = v / M[p][p];
        }
        double d = M[q][q];
        for (size_t m = 0; m < q; ++m)
            d -= M[q][m] * M[q][m];
        if (!(d > 0))
            return 0;
        M[q][q] = sqrt(d);
    }
    for (size_t q = 0; q < k; ++q) {
        double v = rhs[q];
        for (size_t m = 0; m < q; ++m)
            v -= M[q][m] * lam[m];
        lam[q] = v / M[q][q];
    }
    for (size_t q = k; q-- > 0;) {
        double v = lam[q];
        for (size_t m = q + 1; m < k; ++m)
            v -= M[m][q] * lam[m];
        lam[q] = v / M[q][q];
    }
    double f = 0;
    for (size_t s = 0; s < ns; ++s) {
        B[s] = W->fr[s] ? lam[s / 2] * g[s] - kap[s] : 0;
        f += B[s] * W->phi[s];
    }
    *dF = f;
    return 1;
}

int tirenv_springs__cc_root(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                            const tirenv_profile *p, double x, double G, double F0, double dF0,
                            double S_l, double S_r, const double dw[], double *z_root)
{
    c->pred_ok = 0;
    const size_t f0 = c->f0, f1 = c->f1, N = T->N, k = c->n_schur;
    if (!c->base_ok || !c->use_schur || f0 > f1 || k > K_MAX || !(dF0 < 0))
        return 0;
    const size_t *wpos = c->wpos;
    const double z0 = c->base_z, *base_w = c->base_w + 1;
    /* The held elements on their rays' rows (linear in z), not on ground vertices: the
     * solve's last pass over the rows counted them (a pass over the span here cost some
     * 500 instructions a root). */
    if (c->held_vertex > 0)
        return 0;
    root_rows W;
    W.k = k;
    const size_t ns = 2 * k;
    for (size_t q = 0; q < k; ++q) {
        const size_t r = c->order[c->schur_pos[q]] - N;
        const tirenv_springs__cc_row *R = &c->rows[r];
        if (R->id < 0 || !(R->t > 0) || c->chain_lo[q] > c->chain_hi[q])
            return 0;
        W.el[2 * q] = R->i;
        W.el[2 * q + 1] = R->j;
        W.g0[2 * q] = R->ga;
        W.g0[2 * q + 1] = R->gb;
        W.g1[2 * q] = R->dga_dz;
        W.g1[2 * q + 1] = R->dgb_dz;
        W.l0[q] = c->lambda[r];
        W.dl[q] = c->dlambda[r];
        W.X[q] = p->x[R->id];
        W.Z[q] = p->z[R->id];
    }
    /* Each free slot's column of K_FF^-1, on its row's chain (K_FF couples no other). */
    double *y = c->root_y;
    const double k_r = T->k_r, *ct = T->cos_t;
    for (size_t s = 0; s < ns; ++s) {
        const size_t e_s = W.el[s];
        W.fr[s] = wpos[e_s] != SIZE_MAX;
        W.w_T[s] = base_w[e_s];
        W.dw[s] = dw[e_s];
    }
    for (size_t s = 0; s < ns; ++s) {
        for (size_t r = 0; r < ns; ++r)
            W.Y[s][r] = 0;
        W.phi[s] = 0;
        if (!W.fr[s])
            continue;
        const size_t lo = c->chain_lo[s / 2], hi = c->chain_hi[s / 2];
        for (size_t e = lo; e <= hi; ++e)
            y[e] = 0;
        y[W.el[s]] = 1;
        tirenv_springs__cc_chain_solve(c, y, lo, W.el[s], hi);
        double f = 0;
        for (size_t e = lo; e <= hi; ++e)
            f += k_r * ct[e] * y[e];
        f += (lo == f0 ? S_l * y[f0] : 0) + (hi == f1 ? S_r * y[f1] : 0);
        W.phi[s] = f;
        for (size_t r = 0; r < ns; ++r)
            if (W.fr[r] && lo <= W.el[r] && W.el[r] <= hi)
                W.Y[s][r] = y[W.el[r]];
    }
    /* The secant on F(z) - G from the base and Newton's step. */
    double lam[K_MAX], B[S_MAX];
    double za = z0, Ra = F0 - G, zb = z0 - Ra / dF0;
    int done = 0;
    for (size_t it = 0; it < max_steps && !done; ++it) {
        double dF;
        if (!at_height(T, &W, x, zb, zb - z0, lam, B, &dF))
            return 0;
        const double Rb = F0 + (zb - z0) * dF0 + dF - G;
        double slope = (Rb - Ra) / (zb - za);
        if (!(slope < 0))
            slope = dF0;
        const double step = -Rb / slope;
        if (fabs(step) <= 1e-15 * T->R0) {
            done = 1;
        } else {
            za = zb;
            Ra = Rb;
            zb += step;
        }
    }
    if (!done)
        return 0;
    for (size_t q = 0; q < k; ++q)
        if (!(lam[q] >= 0))
            return 0;
    /* The state at zb: the tangent, then each row's columns by one solve on its chain. */
    const double dz = zb - z0;
    double *pw = c->pred_w;
    for (size_t e = f0; e <= f1; ++e)
        pw[e] = base_w[e] + dz * dw[e];
    for (size_t q = 0; q < k; ++q) {
        const size_t lo = c->chain_lo[q], hi = c->chain_hi[q];
        size_t from = hi + 1;
        for (size_t e = lo; e <= hi; ++e)
            y[e] = 0;
        for (size_t s = 2 * q; s < 2 * q + 2; ++s)
            if (W.fr[s]) {
                y[W.el[s]] += B[s];
                from = W.el[s] < from ? W.el[s] : from;
            }
        tirenv_springs__cc_chain_solve(c, y, lo, from, hi);
        for (size_t e = lo; e <= hi; ++e)
            pw[e] += y[e];
        c->pred_lam[q] = lam[q];
    }
    c->pred_z = zb;
    c->pred_ok = 1;
    *z_root = zb;
    return 1;
}
