/* SPDX-License-Identifier: Apache-2.0 */
/* Where the springs model's hub force meets the load on the working set of the last QP solve
 * (docs/models.md section 4.8, Newton's step on the working set): Newton's step solved
 * together with the QP's equalities,
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
#include <string.h>
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
    double w_T[S_MAX], dw[S_MAX];      /* the base's w and dw/dz at the slots */
    int no_l;                          /* l0 = dl = 0 (root_at's): no base reactions */
    const tirenv_springs__cc_cols *col; /* K_FF^-1 e_s at the slots (the workspace's) */
    size_t todo[S_MAX], n_todo;        /* the slots whose columns base_rows left to solve */
} root_rows;

/* A vertex row of sector (i, i + 1) at dx = V_x - x, dzv = z - V_z: its t into *t, and
 * whether it lies inside the sector (springs_rows.c's snap apart), where its row keeps its
 * kind. */
static inline int row_inside(const tirenv_springs__cc_tire *T, size_t i, double dx, double dzv,
                             double *t)
{
    const double *st = T->sin_t, *ct = T->cos_t;
    const double s_i = dx * ct[i] - dzv * st[i], s_n = dzv * st[i + 1] - dx * ct[i + 1];
    *t = s_i / (s_i + s_n);
    return s_i > 0 && s_n > 0 && *t > t_snap && *t < 1 - t_snap;
}

/* at_height with W->k = k rows, inlined where k is a constant, and where no_l (root_at's
 * l0 = dl = 0) without the base reactions' kap. There each kap is +0: g0 > 0 (a row inside
 * its sector has both weights > 0), so 0 g0 is +0 and dz (0 g0 + 0 g1) is +0 or -0, which
 * summed to +0 give +0. Then lam g - (+0) is lam g to the bit, and so is v - (+0) Y (a +0 or
 * a -0) since v is never -0: a slot's w_T + dz dw starts from a sum begun at +0 (ua) or from
 * h = R0 - rho, neither -0. */
static inline __attribute__((always_inline)) int
rows_at(const tirenv_springs__cc_tire *T, const root_rows *W, double x, double z, double dz,
        double lam[], double B[], double g_out[], double *dF, const size_t k, const int no_l)
{
    const size_t ns = 2 * k;
    double g[S_MAX], cmp[K_MAX], h[K_MAX], kap[S_MAX], u[S_MAX];
    for (size_t q = 0; q < k; ++q) {
        const size_t i = W->el[2 * q];
        const double dx = W->X[q] - x, dzv = z - W->Z[q];
        double t;
        if (!row_inside(T, i, dx, dzv, &t))
            return 0;
        double da, db;
        tirenv_springs__cc_weights(T, t, &g[2 * q], &g[2 * q + 1], &da, &db);
        cmp[q] = tirenv_springs__cc_compliance(T, g[2 * q], g[2 * q + 1]);
        h[q] = T->R0 - sqrt(dx * dx + dzv * dzv);
    }
    for (size_t s = 0; s < ns; ++s) {
        const size_t q = s / 2;
        kap[s] = W->fr[s] && !no_l ? W->l0[q] * W->g0[s] +
                                         dz * (W->dl[q] * W->g0[s] + W->l0[q] * W->g1[s])
                                   : 0;
    }
    for (size_t r = 0; r < ns; ++r) {
        double v = W->w_T[r] + dz * W->dw[r];
        for (size_t s = 0; s < ns && !no_l; ++s)
            v -= kap[s] * W->col->Y[s][r];
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
                    m += g[a] * g[b] * W->col->Y[b][a];
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
        g_out[s] = g[s];
        B[s] = W->fr[s] ? (no_l ? lam[s / 2] * g[s] : lam[s / 2] * g[s] - kap[s]) : 0;
        f += B[s] * W->col->phi[s];
    }
    *dF = f;
    return 1;
}

/* At centre height z (dz from the base): the reactions lam, the slots' B and F - F_0 - dz
 * dF_0 (N) into *dF; 0 if a row leaves its sector's inside. One row is the commonest case
 * (over the bench cleat 1,276 roots of 1,404, some 4 calls a root): its loops compiled
 * unrolled, the same operations in the same order, so the same bits. */
static int at_height(const tirenv_springs__cc_tire *T, const root_rows *W, double x, double z,
                     double dz, double lam[], double B[], double g_out[], double *dF)
{
    if (W->k == 1)
        return W->no_l ? rows_at(T, W, x, z, dz, lam, B, g_out, dF, 1, 1)
                       : rows_at(T, W, x, z, dz, lam, B, g_out, dF, 1, 0);
    if (W->k == 0) { /* no row: the loops' share is the sum's start, +0 (the roads' commonest) */
        *dF = 0;
        return 1;
    }
    return W->no_l ? rows_at(T, W, x, z, dz, lam, B, g_out, dF, W->k, 1)
                   : rows_at(T, W, x, z, dz, lam, B, g_out, dF, W->k, 0);
}

/* Slot s's column y = K_FF^-1 e_s on its row's chain [lo, hi] into W's cols: phi_s = f . y
 * (the hub's weights, the free chains' beyond the span at its ends), y at the chain's ends
 * and at the slots on it. */
static void column_done(tirenv_springs__cc *c, const root_rows *W,
                        const tirenv_springs__cc_tire *T, double S_l, double S_r, size_t s,
                        const double y[])
{
    const size_t f0 = c->f0, f1 = c->f1, ns = 2 * W->k;
    const size_t lo = c->chain_lo[s / 2], hi = c->chain_hi[s / 2];
    const double k_r = T->k_r, *ct = T->cos_t;
    tirenv_springs__cc_cols *C = &c->cols;
    double f = 0;
    for (size_t e = lo; e <= hi; ++e)
        f += k_r * ct[e] * y[e];
    f += (lo == f0 ? S_l * y[f0] : 0) + (hi == f1 ? S_r * y[f1] : 0);
    C->phi[s] = f;
    C->ylo[s] = y[lo];
    C->yhi[s] = y[hi];
    for (size_t r = 0; r < ns; ++r)
        if (W->fr[r] && lo <= W->el[r] && W->el[r] <= hi)
            C->Y[s][r] = y[W->el[r]];
}

/* column_done for slots s1 and s2 on one chain: the two sums interleaved, each in its order. */
static void columns_done(tirenv_springs__cc *c, const root_rows *W,
                         const tirenv_springs__cc_tire *T, double S_l, double S_r, size_t s1,
                         const double y1[], size_t s2, const double y2[])
{
    const size_t f0 = c->f0, f1 = c->f1, ns = 2 * W->k;
    const size_t lo = c->chain_lo[s1 / 2], hi = c->chain_hi[s1 / 2];
    const double k_r = T->k_r, *ct = T->cos_t;
    tirenv_springs__cc_cols *C = &c->cols;
    double f = 0, g = 0;
    for (size_t e = lo; e <= hi; ++e) {
        const double w_e = k_r * ct[e];
        f += w_e * y1[e];
        g += w_e * y2[e];
    }
    f += (lo == f0 ? S_l * y1[f0] : 0) + (hi == f1 ? S_r * y1[f1] : 0);
    g += (lo == f0 ? S_l * y2[f0] : 0) + (hi == f1 ? S_r * y2[f1] : 0);
    C->phi[s1] = f;
    C->phi[s2] = g;
    C->ylo[s1] = y1[lo];
    C->yhi[s1] = y1[hi];
    C->ylo[s2] = y2[lo];
    C->yhi[s2] = y2[hi];
    for (size_t r = 0; r < ns; ++r)
        if (W->fr[r] && lo <= W->el[r] && W->el[r] <= hi) {
            C->Y[s1][r] = y1[W->el[r]];
            C->Y[s2][r] = y2[W->el[r]];
        }
}

/* The working rows of the base's final set (c->rows at c->schur_pos) into W's slots, with
 * each free slot's column of K_FF^-1 on its row's chain (K_FF couples no other) and f . that
 * column (S_l, S_r: the free chains' beyond the span) in c->cols, W->col pointing at them
 * (solved only where the factor or the rows changed since: W->todo names the slots whose
 * columns columns_solve is then to solve); w_T and dw at the slots, l0 and dl the base's
 * (with_lambda 0: 0). 0 where a row is not a ground vertex's between elements. */
static int base_rows(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                     const tirenv_profile *p, double S_l, double S_r, const double w_T[],
                     const double dw[], int with_lambda, root_rows *W)
{
    const size_t N = T->N, k = c->n_schur;
    const size_t *wpos = c->wpos;
    W->k = k;
    W->no_l = !with_lambda;
    W->n_todo = 0;
    const size_t ns = 2 * k;
    for (size_t q = 0; q < k; ++q) {
        const size_t r = c->order[c->schur_pos[q]] - N;
        const tirenv_springs__cc_row *R = &c->rows[r];
        if (R->id < 0 || !(R->t > 0) || c->chain_lo[q] > c->chain_hi[q])
            return 0;
        W->el[2 * q] = R->i;
        W->el[2 * q + 1] = R->j;
        W->g0[2 * q] = R->ga;
        W->g0[2 * q + 1] = R->gb;
        W->g1[2 * q] = R->dga_dz;
        W->g1[2 * q + 1] = R->dgb_dz;
        W->l0[q] = with_lambda ? c->lambda[r] : 0;
        W->dl[q] = with_lambda ? c->dlambda[r] : 0;
        W->X[q] = p->x[R->id];
        W->Z[q] = p->z[R->id];
    }
    tirenv_springs__cc_cols *C = &c->cols;
    W->col = C;
    int same_el = C->k == k && C->S[0] == S_l && C->S[1] == S_r;
    for (size_t s = 0; s < ns; ++s) {
        const size_t e_s = W->el[s];
        W->fr[s] = wpos[e_s] != SIZE_MAX;
        W->w_T[s] = w_T[e_s];
        W->dw[s] = dw[e_s];
        same_el = same_el && C->el[s] == e_s;
    }
    if (same_el && C->at == c->n_factors) /* the last root's on this factor, bit for bit */
        return 1;
    /* after a flip of the factor they were solved on, a slot whose element and chain the flip
     * left as they were keeps its column */
    const int mended = same_el && C->at == c->mend_at && c->n_factors == c->mend_at + 1;
    for (size_t s = 0; s < ns; ++s) {
        const size_t lo = c->chain_lo[s / 2], hi = c->chain_hi[s / 2];
        if (mended && (W->fr[s] ? hi < c->mend_lo || lo > c->mend_hi
                                : W->el[s] < c->mend_lo || W->el[s] > c->mend_hi))
            continue;
        for (size_t r = 0; r < ns; ++r)
            C->Y[s][r] = 0;
        C->phi[s] = 0;
        C->el[s] = W->el[s];
        if (W->fr[s])
            W->todo[W->n_todo++] = s;
    }
    C->at = c->n_factors;
    C->k = k;
    C->S[0] = S_l;
    C->S[1] = S_r;
    return 1;
}

/* The columns base_rows left (W->todo) solved and done, two at a time (a row's two on its
 * chain), each its own solve's bits: the Thomas recurrences and f's sum are latency chains.
 * With v (not NULL), v := K_FF^-1 v on chain [v_lo, v_hi] too: in the same loop as the first
 * two columns where they are on that chain, else first on its own. */
static void columns_solve(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T, root_rows *W,
                          double S_l, double S_r, double v[], size_t v_lo, size_t v_hi)
{
    const size_t N = T->N;
    double *y1 = c->root_y, *y2 = c->root_y + (N + 2);
    for (size_t m = 0; m < W->n_todo; m += 2) {
        const size_t s1 = W->todo[m], s2 = m + 1 < W->n_todo ? W->todo[m + 1] : SIZE_MAX;
        const size_t lo1 = c->chain_lo[s1 / 2], hi1 = c->chain_hi[s1 / 2], e1 = W->el[s1];
        for (size_t e = lo1; e <= hi1; ++e)
            y1[e] = 0;
        y1[e1] = 1;
        const int v_here = v && lo1 == v_lo && hi1 == v_hi;
        if (s2 == SIZE_MAX) {
            if (v_here)
                tirenv_springs__cc_chain_solve_pair(c, v, v_lo, v_lo, v_hi, y1, lo1, e1, hi1);
            else if (v)
                tirenv_springs__cc_chain_solve(c, v, v_lo, v_lo, v_hi);
            if (!v_here)
                tirenv_springs__cc_chain_solve(c, y1, lo1, e1, hi1);
            column_done(c, W, T, S_l, S_r, s1, y1);
            v = NULL;
            continue;
        }
        const size_t lo2 = c->chain_lo[s2 / 2], hi2 = c->chain_hi[s2 / 2], e2 = W->el[s2];
        for (size_t e = lo2; e <= hi2; ++e)
            y2[e] = 0;
        y2[e2] = 1;
        const int one = lo1 == lo2 && hi1 == hi2;
        if (v_here && one) {
            if (e1 <= e2)
                tirenv_springs__cc_chain_solve_three(c, v, y1, e1, y2, e2, lo1, hi1);
            else
                tirenv_springs__cc_chain_solve_three(c, v, y2, e2, y1, e1, lo1, hi1);
        } else {
            if (v)
                tirenv_springs__cc_chain_solve(c, v, v_lo, v_lo, v_hi);
            tirenv_springs__cc_chain_solve_pair(c, y1, lo1, e1, hi1, y2, lo2, e2, hi2);
        }
        v = NULL;
        if (one) {
            columns_done(c, W, T, S_l, S_r, s1, y1, s2, y2);
        } else {
            column_done(c, W, T, S_l, S_r, s1, y1);
            column_done(c, W, T, S_l, S_r, s2, y2);
        }
    }
    if (v)
        tirenv_springs__cc_chain_solve(c, v, v_lo, v_lo, v_hi);
    W->n_todo = 0;
}

/* The secant on R(z) = F0 + (z - z0) dF0 + (the rows' share at z) - G from (za, Ra), its
 * first step by slope (N/m, < 0), to 1e-15 R0 in z: *zb with the reactions lam and the
 * slots' B there; 0 if it does not settle or a row leaves its sector. */
static int secant(const tirenv_springs__cc_tire *T, const root_rows *W, double x, double z0,
                  double F0, double dF0, double G, double za, double Ra, double slope0,
                  double lam[], double B[], double g[], double *z_out, size_t *q_neg)
{
    *q_neg = SIZE_MAX;
    double zb = za - Ra / slope0;
    for (size_t it = 0; it < max_steps; ++it) {
        double dF;
        if (!at_height(T, W, x, zb, zb - z0, lam, B, g, &dF))
            return 0;
        const double Rb = F0 + (zb - z0) * dF0 + dF - G;
        double slope = (Rb - Ra) / (zb - za);
        if (!(slope < 0))
            slope = slope0;
        const double step = -Rb / slope;
        if (fabs(step) <= 1e-15 * T->R0) {
            /* a reaction below 0 at the root: the least one's row leaves the set */
            for (size_t q = 0; q < W->k; ++q)
                if (!(lam[q] >= 0) && (*q_neg == SIZE_MAX || lam[q] < lam[*q_neg]))
                    *q_neg = q;
            if (*q_neg != SIZE_MAX)
                return 0;
            *z_out = zb;
            return 1;
        }
        za = zb;
        Ra = Rb;
        zb += step;
    }
    return 0;
}

/* The state at zb (dz from the height of wa) kept as the update's start: wa + dz dwa over the
 * span, then each row's B by one solve on its chain; c->pred_*. wa may be c->pred_w. */
static void keep_state(tirenv_springs__cc *c, const root_rows *W, const double wa[],
                       const double dwa[], double x, double zb, double dz, const double lam[],
                       const double B[])
{
    const size_t f0 = c->f0, f1 = c->f1, k = W->k;
    double *pw = c->pred_w, *y = c->root_y;
    for (size_t e = f0; e <= f1; ++e)
        pw[e] = wa[e] + dz * dwa[e];
    for (size_t q = 0; q < k; ++q) {
        const size_t lo = c->chain_lo[q], hi = c->chain_hi[q];
        size_t from = hi + 1;
        for (size_t e = lo; e <= hi; ++e)
            y[e] = 0;
        for (size_t s = 2 * q; s < 2 * q + 2; ++s)
            if (W->fr[s]) {
                y[W->el[s]] += B[s];
                from = W->el[s] < from ? W->el[s] : from;
            }
        tirenv_springs__cc_chain_solve(c, y, lo, from, hi);
        for (size_t e = lo; e <= hi; ++e)
            pw[e] += y[e];
        c->pred_lam[q] = lam[q];
    }
    c->pred_x = x;
    c->pred_z = zb;
    c->pred_held = 0;
    c->pred_ok = 1;
}

int tirenv_springs__cc_root(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                            const tirenv_profile *p, double x, double G, double F0, double dF0,
                            double S_l, double S_r, const double dw[], double *z_root)
{
    c->pred_ok = 0;
    const size_t f0 = c->f0, f1 = c->f1, k = c->n_schur;
    if (!c->base_ok || c->base_pins || !c->use_schur || f0 > f1 || k > K_MAX || !(dF0 < 0))
        return 0;
    const double z0 = c->base_z, *base_w = c->base_w + 1;
    /* The held elements on their rays' rows (linear in z), not on ground vertices: the
     * solve's last pass over the rows counted them (a pass over the span here cost some
     * 500 instructions a root). */
    if (c->held_vertex > 0)
        return 0;
    root_rows W;
    if (!base_rows(c, T, p, S_l, S_r, base_w, dw, 1, &W))
        return 0;
    columns_solve(c, T, &W, S_l, S_r, NULL, 0, 0);
    /* The secant on F(z) - G from the base and Newton's step. */
    double lam[K_MAX], B[S_MAX], g[S_MAX], zb;
    size_t q_neg;
    if (!secant(T, &W, x, z0, F0, dF0, G, z0, F0 - G, dF0, lam, B, g, &zb, &q_neg))
        return 0;
    keep_state(c, &W, base_w, dw, x, zb, zb - z0, lam, B);
    *z_root = zb;
    return 1;
}

int tirenv_springs__cc_rows_inside(const tirenv_springs__cc *c,
                                   const tirenv_springs__cc_tire *T, const tirenv_profile *p,
                                   double x, double z)
{
    for (size_t q = 0, k = c->n_schur; q < k; ++q) {
        const tirenv_springs__cc_row *R = &c->rows[c->order[c->schur_pos[q]] - T->N];
        double t;
        if (R->id >= 0 && R->t > 0 &&
            !row_inside(T, R->i, p->x[R->id] - x, z - p->z[R->id], &t))
            return 0;
    }
    return 1;
}

/* Row R between elements i and i + 1 at t for its vertex at dx = V_x - x, dzv = z - V_z: its
 * weights, compliance and h and their derivatives in z, as springs_rows.c puts them. */
static void put_row(const tirenv_springs__cc_tire *T, size_t i, double t, double dx, double dzv,
                    tirenv_springs__cc_row *R)
{
    const double *st = T->sin_t, *ct = T->cos_t;
    const double s_a = dx * ct[i] - dzv * st[i], s_b = dzv * st[i + 1] - dx * ct[i + 1];
    const double S = s_a + s_b, rho = sqrt(dx * dx + dzv * dzv);
    const double dt_dz = (-st[i] * s_b - s_a * st[i + 1]) / (S * S);
    double da, db;
    R->i = i;
    R->j = i + 1;
    R->t = t;
    tirenv_springs__cc_weights(T, t, &R->ga, &R->gb, &da, &db);
    R->tau = R->gb / (R->ga + R->gb);
    R->dga_dz = da * dt_dz;
    R->dgb_dz = db * dt_dz;
    R->cmp = tirenv_springs__cc_compliance(T, R->ga, R->gb);
    R->dcmp_dz = R->cmp > 0 ? T->c0 * (da + db) * dt_dz : 0;
    R->h = T->R0 - rho;
    R->dh_dz = -dzv / rho;
}

/* The element beyond the span's end beside sector i (between elements i and i + 1), or
 * SIZE_MAX where sector i is not at an end: a row in that sector takes the element into the
 * span (span_take), as the QP's span ends where no row reaches. */
static size_t span_beyond(const tirenv_springs__cc *c, size_t i)
{
    return i + 1 == c->f0 ? i : i == c->f1 ? i + 1 : SIZE_MAX;
}

/* Element b, just beyond the span's end, into the span, free. */
static void span_take(tirenv_springs__cc *c, size_t b)
{
    c->f0 = b < c->f0 ? b : c->f0;
    c->f1 = b > c->f1 ? b : c->f1;
    c->wpos[b] = 0; /* free: any position but SIZE_MAX (the layout makes them anew) */
}

/* Element e (held) out of the ascending list of held elements, free. */
static void held_remove(tirenv_springs__cc *c, size_t e)
{
    size_t *held = c->held, n = c->n_held, m = 0;
    while (m < n && held[m] < e)
        ++m;
    memmove(held + m, held + m + 1, (n - m - 1) * sizeof *held);
    c->wpos[e] = 0; /* free: any position but SIZE_MAX (the layout makes them anew) */
    c->warm_pin[e] = 0;
    --c->n_held;
}

/* A working row whose vertex crossed one of its elements' rays since the base: at the
 * crossing both sectors' rows read w_e >= h on that element e alone (the weights are (1, 0)
 * at t = 0 and (0, 1) at t = 1), so the working set changes by the row's other element and
 * by e's own row: the row moves into the sector beyond e, and e, where it was held on its
 * ray's row, is let go (its ray now passes onto the vertex's other face, below the row
 * bearing on e). A row at the span's end takes the element beyond into the span, free.
 * K_FF is factorised again where the span or the held elements changed, else kept; the rows'
 * Schur complement is formed again. The row's t, weights, compliance and h at (x, z) as
 * springs_rows.c puts a row between elements. Whatever the start then finds (an element
 * held or let go at the runs' ends, a row's reaction below 0) it finds by its rounds. */
int tirenv_springs__cc_rows_across(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                   const tirenv_profile *p, double x, double z,
                                   size_t crossed[], long vertex[], size_t *n_crossed)
{
    *n_crossed = 0;
    const size_t N = T->N, *wpos = c->wpos;
    const double *st = T->sin_t, *ct = T->cos_t;
    int moved = 0, grew = 0; /* (grew: K_FF changed, a longer span or an element let go) */
    int longer = 0;           /* a longer span */
    size_t n_let = 0, let = SIZE_MAX; /* the elements let go, the last of them */
    for (size_t q = 0, k = c->n_schur; q < k; ++q) {
        tirenv_springs__cc_row *R = &c->rows[c->order[c->schur_pos[q]] - N];
        if (R->id < 0 || !(R->t > 0))
            continue;
        const double dx = p->x[R->id] - x, dzv = z - p->z[R->id];
        double t;
        if (row_inside(T, R->i, dx, dzv, &t))
            continue;
        /* past ray i (its sigma on it no longer > 0): the sector before; past ray i + 1,
         * the one after */
        const double s_i = dx * ct[R->i] - dzv * st[R->i];
        if (!(s_i > 0) && R->i == 0)
            return 0;
        const size_t i = s_i > 0 ? R->i + 1 : R->i - 1;
        /* K_FF factorised again on a longer span */
        const size_t b = span_beyond(c, i);
        if (b != SIZE_MAX) {
            if (b >= N)
                return 0;
            span_take(c, b);
            grew = longer = 1;
        }
        /* the element whose ray the vertex crossed: held on its ray's row, it is let go
         * (its ray passed onto the vertex's other face, below the row now bearing on it) */
        const size_t e_c = s_i > 0 ? R->i + 1 : R->i;
        if (wpos[e_c] == SIZE_MAX) {
            held_remove(c, e_c);
            grew = 1;
            ++n_let;
            let = e_c;
        }
        if (i < c->f0 || i + 1 > c->f1 || !row_inside(T, i, dx, dzv, &t))
            return 0;
        crossed[*n_crossed] = e_c;
        vertex[(*n_crossed)++] = R->id;
        put_row(T, i, t, dx, dzv, R);
        moved = 1;
    }
    /* the layout's keys name the rows by their sector: the next layout makes its own */
    c->last_ok = 0;
    if (!moved)
        return 0;
    /* one element let go on the same span: K_FF's factor mended on its chain alone */
    return !(grew && !longer && n_let == 1 ? tirenv_springs__cc_schur_flip(c, T, let)
                                           : tirenv_springs__cc_schur_factor(c, T, !grew));
}

int tirenv_springs__cc_row_enter(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                 const tirenv_profile *p, double x, double z, size_t e, long v)
{
    const size_t N = T->N, k = c->n_schur;
    if (k >= K_MAX || c->wpos[e] != SIZE_MAX || v < 0 || (size_t)v >= p->n ||
        c->n_kkt + 1 >= c->cap_rows + N)
        return 0;
    /* the sector beside e that holds v, within the span or one beyond its end */
    const double dx = p->x[v] - x, dzv = z - p->z[v];
    double t;
    size_t i = SIZE_MAX;
    if (e > 0 && row_inside(T, e - 1, dx, dzv, &t))
        i = e - 1;
    else if (e + 1 < N && row_inside(T, e, dx, dzv, &t))
        i = e;
    if (i == SIZE_MAX || i + 1 < c->f0 || i > c->f1)
        return 0;
    /* v's row in the base's layout, not working (the layout keeps a vertex's rows on the
     * hulls and those a solve found violated): no row is added to the layout's tables */
    size_t r = SIZE_MAX;
    for (size_t q = 0; q < c->n_rows && r == SIZE_MAX; ++q)
        if (c->rows[q].id == v && c->rows[q].t > 0)
            r = q;
    if (r == SIZE_MAX || tirenv_springs__long_in(c->warm_ids, c->n_warm, v) ||
        c->n_warm >= c->cap_warm)
        return 0;
    for (size_t q = 0; q < k; ++q)
        if (c->order[c->schur_pos[q]] - N == r)
            return 0;
    const size_t b = span_beyond(c, i);
    if (b != SIZE_MAX) {
        span_take(c, b);
        c->warm_pin[b] = 0;
    }
    held_remove(c, e);
    put_row(T, i, t, dx, dzv, &c->rows[r]);
    c->order[c->n_kkt] = N + r;
    c->schur_pos[k] = c->n_kkt++;
    c->n_schur = k + 1;
    size_t m = c->n_warm++; /* warm_ids ascending */
    while (m > 0 && c->warm_ids[m - 1] > v) {
        c->warm_ids[m] = c->warm_ids[m - 1];
        --m;
    }
    c->warm_ids[m] = v;
    c->last_ok = 0;
    /* (on the same span only e changed: its chain's factor mended; else factorised anew) */
    if (tirenv_springs__cc_schur_flip(c, T, e)) {
        c->base_ok = 0;
        c->pred_ok = 0;
        return 0;
    }
    return 1;
}

/* v = K_FF^-1 f on the free elements (f the hub's weights k_r cos(theta_e), the free chains'
 * beyond the span S_l and S_r at its ends) into c->root_v for this factor, a chain at a time
 * (after a flip of the factor it was solved for, only on the chains the flip changed); the
 * rows' columns W left to solve (W not NULL) solved with v's on their chain, else after. */
static void hub_solve(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T, root_rows *W,
                      double S_l, double S_r)
{
    const size_t f0 = c->f0, f1 = c->f1, *ch = c->chains, n_ch = c->n_chains;
    const double k_r = T->k_r, *ct = T->cos_t;
    double *v = c->root_v;
    if (c->root_v_at != c->n_factors) {
        const int mended = c->root_v_at == c->mend_at && c->n_factors == c->mend_at + 1;
        for (size_t q = 0; q < n_ch; ++q) {
            const size_t lo = ch[2 * q], hi = ch[2 * q + 1];
            if (mended && (hi < c->mend_lo || lo > c->mend_hi))
                continue;
            for (size_t e = lo; e <= hi; ++e)
                v[e] = k_r * ct[e];
            v[f0] += lo == f0 ? S_l : 0;
            v[f1] += hi == f1 ? S_r : 0;
            if (W && W->n_todo > 0 && lo == c->chain_lo[W->todo[0] / 2] &&
                hi == c->chain_hi[W->todo[0] / 2])
                columns_solve(c, T, W, S_l, S_r, v, lo, hi);
            else
                tirenv_springs__cc_chain_solve(c, v, lo, lo, hi);
        }
        c->root_v_at = c->n_factors;
    }
    if (W && W->n_todo > 0)
        columns_solve(c, T, W, S_l, S_r, NULL, 0, 0);
}

/* At a new x the held elements' rows are their rays' there, h_e(z) = R0 - rho_e(z), linear in
 * z while each ray ends on the same face (the fan at (x, z_a) gives rho_e and d(rho_e)/dz);
 * the free ones solve K_FF w_F = b_F(z) + G_W(z)^T lambda with the base's K_FF (it depends
 * on the span and the held elements alone, not on x), b_F the held neighbours' k_ir h_e(z) at
 * the ends of each chain of free elements. With no reaction on the rows, w at z is u_a +
 * (z - z_a) u_s; the rows enter as at_height has them with l0 = dl = 0 (B_s = lambda g_s(z)).
 * u_a and u_s are not solved for: the root needs them at the rows' elements only, from the
 * rows' columns of K_FF^-1 at their chain's ends, and F_z of them is v . b_F (v = K_FF^-1 f,
 * f the hub's weights on the free elements, kept while the factor is) plus the held
 * elements' share; the state at the root is then one solve a chain. */
int tirenv_springs__cc_root_at(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                               const tirenv_profile *p, double x, double z_a,
                               const double rho[], const double drho[], double G,
                               double slope, double S_l, double S_r, double *z_root,
                               size_t *q_neg)
{
    c->pred_ok = 0;
    *q_neg = SIZE_MAX;
    const size_t f0 = c->f0, f1 = c->f1, k = c->n_schur;
    if (!c->base_ok || !c->use_schur || !c->tri_ok || f0 > f1 || k > K_MAX ||
        c->held_vertex > 0 || !(slope < 0))
        return 0;
    const double R0 = T->R0, k_ir = T->k_ir, k_r = T->k_r, *ct = T->cos_t;
    const size_t *held = c->held, n_held = c->n_held, *ch = c->chains, n_ch = c->n_chains;
    /* the held elements' rows at z_a and their slopes, and their share of F_z (the hub's
     * weight k_r cos(theta_e), and the free chains' beyond the span at its ends: held is
     * ascending, so only its first and last can be f0 and f1; adding the others' zeros
     * changed no bit) */
    double *H = c->pred_w, *dH = c->root_du;
    double Fa = 0, dFa = 0;
    /* the first and the last apart, so that the loop between asks nothing (on locals: H may
     * alias rho, so its stores would make rho be read again) */
    for (size_t m = 0; m < n_held; m = m == 0 && n_held > 2 ? n_held - 1 : m + 1) {
        const size_t e = held[m];
        const double h = R0 - rho[e], dh = -drho[e];
        H[e] = h;
        dH[e] = dh;
        double f = k_r * ct[e];
        if (e == f0 || e == f1)
            f = f + (e == f0 ? S_l : 0) + (e == f1 ? S_r : 0);
        Fa += f * h;
        dFa += f * dh;
        for (size_t q = 1; m == 0 && q + 1 < n_held; ++q) {
            const size_t i = held[q];
            const double h_i = R0 - rho[i], dh_i = -drho[i], f_i = k_r * ct[i];
            H[i] = h_i;
            dH[i] = dh_i;
            Fa += f_i * h_i;
            dFa += f_i * dh_i;
        }
    }
    /* the rows' columns of K_FF^-1 (where they are to be solved, with v's on their chain) */
    root_rows W;
    if (!base_rows(c, T, p, S_l, S_r, H, dH, 0, &W)) {
        hub_solve(c, T, NULL, S_l, S_r);
        return 0;
    }
    hub_solve(c, T, &W, S_l, S_r);
    const double *v = c->root_v;
    /* the free elements' share: v . b_F over the chains' ends */
    for (size_t q = 0; q < n_ch; ++q) {
        const size_t lo = ch[2 * q], hi = ch[2 * q + 1];
        if (lo > f0) {
            Fa += v[lo] * k_ir * H[lo - 1];
            dFa += v[lo] * k_ir * dH[lo - 1];
        }
        if (hi < f1) {
            Fa += v[hi] * k_ir * H[hi + 1];
            dFa += v[hi] * k_ir * dH[hi + 1];
        }
    }
    /* u_a and u_s at the rows' free elements, from their columns at the chain's ends */
    for (size_t s = 0; s < 2 * k; ++s) {
        if (!W.fr[s])
            continue;
        const size_t lo = c->chain_lo[s / 2], hi = c->chain_hi[s / 2];
        double ua = 0, us = 0;
        if (lo > f0) {
            ua += W.col->ylo[s] * k_ir * H[lo - 1];
            us += W.col->ylo[s] * k_ir * dH[lo - 1];
        }
        if (hi < f1) {
            ua += W.col->yhi[s] * k_ir * H[hi + 1];
            us += W.col->yhi[s] * k_ir * dH[hi + 1];
        }
        W.w_T[s] = ua;
        W.dw[s] = us;
    }
    double lam[K_MAX], B[S_MAX], g[S_MAX], zb, dF;
    if (!at_height(T, &W, x, z_a, 0, lam, B, g, &dF))
        return 0;
    if (!secant(T, &W, x, z_a, Fa, dFa, G, z_a, Fa + dF - G, slope, lam, B, g, &zb, q_neg))
        return 0;
    for (size_t s = 0; s < 2 * k; ++s) { /* each row's load on its elements, for the check */
        c->pred_el[s] = W.el[s];
        c->pred_gl[s] = lam[s / 2] * g[s];
    }
    /* The state at zb: the held elements' rows there, then each chain's solve with its
     * ends' coupling and the rows' B. */
    const double dz = zb - z_a;
    double *pw = c->pred_w;
    /* (the held elements' rows stay at z_a in pred_w, H: those the check asks for, and the
     * chains' neighbours here, are taken to zb where read; a pass over all of them cost some
     * 340 instructions a root) */
    for (size_t q = 0; q < n_ch; ++q) {
        const size_t lo = ch[2 * q], hi = ch[2 * q + 1];
        memset(pw + lo, 0, (hi - lo + 1) * sizeof *pw); /* +0.0: all bits zero */
        if (lo > f0)
            pw[lo] = k_ir * (H[lo - 1] + dz * dH[lo - 1]);
        if (hi < f1)
            pw[hi] += k_ir * (H[hi + 1] + dz * dH[hi + 1]);
    }
    for (size_t s = 0; s < 2 * k; ++s)
        if (W.fr[s])
            pw[W.el[s]] += B[s];
    tirenv_springs__cc_chains_solve(c, pw);
    for (size_t q = 0; q < k; ++q)
        c->pred_lam[q] = lam[q];
    c->pred_x = x;
    c->pred_z = zb;
    c->pred_held = 1;
    c->pred_dz = dz;
    c->pred_ok = 1;
    *z_root = zb;
    return 1;
}

/* Element e's w at the kept state (m): a held one's row at the root where root_at left it
 * at its own height (pred_held), as root_at's chains took it. */
static inline double pred_w_at(const tirenv_springs__cc *c, size_t e)
{
    const double *w = c->pred_w;
    return c->pred_held && c->wpos[e] == SIZE_MAX ? w[e] + c->pred_dz * c->root_du[e] : w[e];
}

/* A held element's reaction at the kept state: K w there (w beyond the span folded into K's
 * diagonal at its ends) less the working rows' g lambda on it, N. */
static double held_reaction(const tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                            size_t e)
{
    const size_t f0 = c->f0, f1 = c->f1;
    double r = tirenv_springs__cc_k_diag(T, f0, f1, e) * pred_w_at(c, e) -
               T->k_ir * ((e > f0 ? pred_w_at(c, e - 1) : 0) +
                          (e < f1 ? pred_w_at(c, e + 1) : 0));
    for (size_t s = 0; s < 2 * c->n_schur; ++s)
        r -= c->pred_el[s] == e ? c->pred_gl[s] : 0;
    return r;
}

/* Where the working set changes with x: at the ends of the runs of held elements (a free
 * chain's end element coming down onto its ray's row, or the held one beside it lifting
 * off), and on the working rows' elements. Inside a run on one face the reactions stay
 * positive; elsewhere the update's check at the root still decides. */
int tirenv_springs__cc_pred_worst(const tirenv_springs__cc *c,
                                  const tirenv_springs__cc_tire *T, const double h[],
                                  double tol, double tol_f, size_t *e_out, int *hold)
{
    const size_t f0 = c->f0, f1 = c->f1, *ch = c->chains, n_ch = c->n_chains;
    const size_t *wpos = c->wpos;
    const double *w = c->pred_w;
    double worst = tol;
    size_t e_w = SIZE_MAX;
    for (size_t q = 0; q < n_ch; ++q)
        for (size_t m = 0; m < 2; ++m) {
            const size_t e = ch[2 * q + m];
            if (h[e] - w[e] > worst) {
                worst = h[e] - w[e];
                e_w = e;
            }
        }
    if (e_w != SIZE_MAX) {
        *e_out = e_w;
        *hold = 1;
        return 1;
    }
    double r_w = -tol_f;
    for (size_t q = 0; q <= n_ch; ++q) { /* the held elements beside each chain, the span's */
        const size_t ends[2] = {q < n_ch ? ch[2 * q] - 1 : f0, q < n_ch ? ch[2 * q + 1] + 1 : f1};
        for (size_t m = 0; m < 2; ++m) {
            const size_t e = ends[m];
            if (e < f0 || e > f1 || wpos[e] != SIZE_MAX)
                continue;
            const double r = held_reaction(c, T, e);
            if (r < r_w) {
                r_w = r;
                e_w = e;
            }
        }
    }
    for (size_t s = 0; s < 2 * c->n_schur; ++s) {
        const size_t e = c->pred_el[s];
        if (wpos[e] != SIZE_MAX)
            continue;
        const double r = held_reaction(c, T, e);
        if (r < r_w) {
            r_w = r;
            e_w = e;
        }
    }
    if (e_w == SIZE_MAX)
        return 0;
    *e_out = e_w;
    *hold = 0;
    return 1;
}

int tirenv_springs__cc_pred_flip(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                 size_t e, int hold)
{
    if (hold) { /* into the ascending list */
        size_t *held = c->held, n = c->n_held, m = 0;
        while (m < n && held[m] < e)
            ++m;
        memmove(held + m + 1, held + m, (n - m) * sizeof *held);
        held[m] = e;
        c->wpos[e] = SIZE_MAX;
        ++c->n_held;
    } else {
        held_remove(c, e);
    }
    /* the next QP's warm start: the working set as it now stands (the full evaluations come
     * seldom where the start holds, and a warm start many positions old costs them several
     * equality problems more) */
    c->warm_pin[e] = (unsigned char)hold;
    /* the next layout lays out its own KKT system (wpos no longer the last one's) */
    c->last_ok = 0;
    if (tirenv_springs__cc_schur_flip(c, T, e)) {
        c->base_ok = 0;
        c->pred_ok = 0;
        return 1;
    }
    return 0;
}

int tirenv_springs__cc_pred_release(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                    size_t q)
{
    const long id = c->rows[c->order[c->schur_pos[q]] - T->N].id;
    memmove(c->schur_pos + q, c->schur_pos + q + 1, (c->n_schur - q - 1) * sizeof *c->schur_pos);
    --c->n_schur;
    /* no longer a working row: the update checks it as an inequality (warm_ids names the
     * working rows between elements, ascending) */
    size_t m = 0, n = c->n_warm;
    while (m < n && c->warm_ids[m] != id)
        ++m;
    if (m < n) {
        memmove(c->warm_ids + m, c->warm_ids + m + 1, (n - m - 1) * sizeof *c->warm_ids);
        --c->n_warm;
    }
    c->last_ok = 0;
    if (tirenv_springs__cc_schur_factor(c, T, 1)) {
        c->base_ok = 0;
        c->pred_ok = 0;
        return 1;
    }
    return 0;
}

int tirenv_springs__cc_base_pins(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                 size_t f0, size_t f1, const unsigned char pinned[],
                                 double z)
{
    size_t n_held = 0, on_vertex = 0;
    for (size_t e = f0; e <= f1; ++e) {
        if (pinned[e]) {
            c->wpos[e] = SIZE_MAX;
            c->held[n_held++] = e;
            on_vertex += c->rows[c->pin_row[e]].id >= 0;
        } else {
            c->wpos[e] = 0;
        }
    }
    c->f0 = f0;
    c->f1 = f1;
    c->n_held = n_held;
    c->held_vertex = on_vertex;
    c->n_schur = 0;
    c->use_schur = 1;
    c->last_ok = 0; /* wpos is no longer the last KKT layout's */
    c->base_ok = 0;
    c->pred_ok = 0;
    if (on_vertex > 0 || tirenv_springs__cc_schur_factor(c, T, 0))
        return 0;
    c->base_pins = 1;
    c->base_z = z;
    c->base_ok = 1;
    return 1;
}
