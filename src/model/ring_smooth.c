/* SPDX-License-Identifier: Apache-2.0 */
/* The ring's continuous contact (docs/models.md section 5.3): the belt's displacement w(phi)
 * between nodes is the linear interpolation (1 - s) w_j + s w_j+1, the tread between belt and
 * ground is compressed by e(phi) = d(phi) - w(phi), and the contact is the minimum over the
 * window's w of
 *     E(w) = 1/2 w.S w + sum_q omega_q R psi(e_q),
 *     psi(e) = 1/2 k_t max(0, e)^2 + 1/2 k_b max(0, e - t_r)^2,
 * the trapezoid rule of the tread's energy over the pieces of ring_ground.c. The second term of
 * psi is the belt and carcass beneath the tread: where the ground has compressed the tread
 * through its thickness t_r it meets them, k_b = TIRENV_RING_BELT_LAYER times stiffer than the
 * tread, so nothing cuts through the belt (a compression beyond t_r costs a thousand times
 * more). E is convex and piecewise quadratic, so Newton's method on it, with the pieces (the
 * points' states: free, tread, tread and belt) taken from the current w, ends exactly, when a
 * step does not change them; a backtracking line search on E makes it converge from anywhere
 * (ring_newton.c, the driver both treads share). The hub force is the sum of the points'
 * radial forces f_q = omega_q R psi'(e_q). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "model/ring_impl.h"

static double compression(const tirenv_ring *r, const tirenv_ring_point *q, const double w[])
{
    const size_t i = q->j - r->lo;
    return q->d - ((1 - q->s) * w[i] + q->s * w[i + 1]);
}

static unsigned char state_of(double e, double t_r) { return e > t_r ? 2 : e > 0 ? 1 : 0; }

/* psi(e) and psi'(e) of a point, per unit of arc. */
static double psi(const tirenv_ring_point *q, double k_b, double t_r, double e, double *dpsi)
{
    double f = 0, df = 0;
    if (e > 0) {
        f = 0.5 * q->k_t * e * e;
        df = q->k_t * e;
    }
    if (e > t_r) {
        f += 0.5 * k_b * (e - t_r) * (e - t_r);
        df += k_b * (e - t_r);
    }
    *dpsi = df;
    return f;
}

/* y = S w, the window's condensed belt stiffness. Away from the window's ends S is the
 * stencil: tirenv_ring__belt_force's sum, in its order, without its look-ups. */
static void apply_S(const tirenv_ring *r, const double (*q4)[4], const double w[], double y[])
{
    const size_t n = r->n;
    const double *s = tirenv_ring__belt_stencil(r->belt);
    for (size_t i = 0; i < n; ++i)
        y[i] = i >= 2 && i + 2 < n ? s[0] * w[i] + s[2] * w[i - 2] + s[1] * w[i - 1] +
                                         s[1] * w[i + 1] + s[2] * w[i + 2]
                                   : tirenv_ring__belt_force(r, q4, w, i);
}

/* The points' share of E at w, sum_q omega_q R psi(e_q), their forces taken from grad if it
 * is not NULL (grad holding S w: the gradient of E). */
static double points_energy(tirenv_ring *r, const double w[], double grad[])
{
    const double t_r = r->par.t_r, R = r->R;
    double E = 0;
    for (size_t k = 0; k < r->n_pts; ++k) {
        const tirenv_ring_point *q = &r->pts[k];
        if (q->d == -INFINITY)
            continue;
        const double k_b = TIRENV_RING_BELT_LAYER * q->k_t, e = compression(r, q, w);
        double dpsi;
        E += q->omega * R * psi(q, k_b, t_r, e, &dpsi);
        if (grad && dpsi != 0) {
            const size_t i = q->j - r->lo;
            grad[i] -= q->omega * R * dpsi * (1 - q->s);
            grad[i + 1] -= q->omega * R * dpsi * q->s;
        }
    }
    return E;
}

/* The right-hand side of the window's system: the points' omega R (k_t d + k_b (d - t_r)) N
 * (assemble's; alone where the matrix is kept). */
static void assemble_rhs(const tirenv_ring *r, double rhs[])
{
    const double t_r = r->par.t_r, R = r->R;
    for (size_t i = 0; i < r->n; ++i)
        rhs[i] = 0;
    for (size_t k = 0; k < r->n_pts; ++k) {
        const tirenv_ring_point *q = &r->pts[k];
        if (q->st == 0)
            continue;
        const double k_b = TIRENV_RING_BELT_LAYER * q->k_t;
        const double b = q->omega * R * (q->k_t * q->d + (q->st == 2 ? k_b * (q->d - t_r) : 0));
        const size_t i = q->j - r->lo;
        rhs[i] += b * (1 - q->s);
        rhs[i + 1] += b * q->s;
    }
}

/* The window's belt stiffness S (band, corner) plus, on every point in tread (or belt)
 * contact, omega R psi'' N N^T; the right-hand side the points' omega R (k_t d + k_b (d -
 * t_r)) N, so that the solution is the minimum of E with the points' states fixed. */
static void assemble(tirenv_ring *r, const double (*q4)[4], double rhs[])
{
    const size_t n = r->n;
    const double *s = tirenv_ring__belt_stencil(r->belt), R = r->R;
    tirenv_ring_band *A = &r->A;
    A->n = n;
    for (size_t i = 0; i < n; ++i) {
        A->a0[i] = s[0];
        A->a1[i] = i + 1 < n ? s[1] : 0;
        A->a2[i] = i + 2 < n ? s[2] : 0;
    }
    A->a0[0] -= q4[0][0];
    A->a1[0] -= q4[0][1];
    A->a0[1] -= q4[1][1];
    A->a0[n - 2] -= q4[2][2];
    A->a1[n - 2] -= q4[2][3];
    A->a0[n - 1] -= q4[3][3];
    for (size_t i = 0; i < 2; ++i)
        for (size_t k = 0; k < 2; ++k)
            A->c[i][k] = -q4[i][2 + k];
    for (size_t k = 0; k < r->n_pts; ++k) {
        const tirenv_ring_point *q = &r->pts[k];
        if (q->st == 0)
            continue;
        const double k_b = TIRENV_RING_BELT_LAYER * q->k_t;
        const double c = q->omega * R * (q->k_t + (q->st == 2 ? k_b : 0));
        const size_t i = q->j - r->lo;
        const double n0 = 1 - q->s, n1 = q->s;
        A->a0[i] += c * n0 * n0;
        A->a0[i + 1] += c * n1 * n1;
        A->a1[i] += c * n0 * n1;
    }
    assemble_rhs(r, rhs);
}

/* What makes the matrix of a point in contact (assemble). */
typedef struct {
    size_t j;
    double s, omega, k_t;
    unsigned char st;
} matrix_key;

/* Whether the matrix of the points' current states is the one last factorised. */
static int matrix_is_factored(const tirenv_ring *r)
{
    if (!(r->key_valid && r->key_lo == r->lo && r->key_n == r->n))
        return 0;
    const matrix_key *e = r->key, *const end = e + r->n_key;
    for (size_t k = 0; k < r->n_pts; ++k) {
        const tirenv_ring_point *q = &r->pts[k];
        if (q->st == 0)
            continue;
        if (e == end || !(e->j == q->j && e->s == q->s && e->omega == q->omega &&
                          e->k_t == q->k_t && e->st == q->st))
            return 0;
        ++e;
    }
    return e == end;
}

/* Keeps what makes the matrix of the points' current states; 0 if the key cannot grow. */
static int remember_matrix(tirenv_ring *r)
{
    size_t n_on = 0;
    for (size_t k = 0; k < r->n_pts; ++k)
        n_on += r->pts[k].st != 0;
    if (n_on > r->cap_key) {
        void *nk = realloc(r->key, 2 * n_on * sizeof(matrix_key));
        if (!nk)
            return 0;
        r->key = nk;
        r->cap_key = 2 * n_on;
    }
    matrix_key *e = r->key;
    for (size_t k = 0; k < r->n_pts; ++k) {
        const tirenv_ring_point *q = &r->pts[k];
        if (q->st != 0)
            *e++ = (matrix_key){q->j, q->s, q->omega, q->k_t, q->st};
    }
    r->n_key = n_on;
    r->key_lo = r->lo;
    r->key_n = r->n;
    return 1;
}

/* The driver's callbacks (ring_newton.c). The factor is kept when the matrix is the last
 * one's: between the evaluations of a position over level ground (no ground vertex between
 * nodes) the points' weights stay, and the states mostly. */
static int factor_cb(tirenv_ring *r, const void *K, double rhs[])
{
    if (matrix_is_factored(r)) {
        assemble_rhs(r, rhs);
        return 0;
    }
    r->key_valid = 0;
    const int keyed = remember_matrix(r);
    assemble(r, (const double(*)[4])K, rhs);
    const int bad = tirenv_ring__band_factor(&r->A);
    ++r->n_factor;
    r->key_valid = keyed && !bad;
    return bad;
}

static void solve_cb(tirenv_ring *r, double x[]) { tirenv_ring__band_solve(&r->A, x); }

static void apply_cb(tirenv_ring *r, const void *K, const double x[], double y[])
{
    apply_S(r, (const double(*)[4])K, x, y);
}

/* Sets every point's state from w; the number that changed. */
static size_t set_states(tirenv_ring *r, const double w[])
{
    size_t changed = 0;
    for (size_t k = 0; k < r->n_pts; ++k) {
        tirenv_ring_point *q = &r->pts[k];
        const unsigned char st = q->d == -INFINITY ? 0 : state_of(compression(r, q, w), r->par.t_r);
        changed += st != q->st;
        q->st = st;
    }
    return changed;
}

int tirenv_ring__solve_smooth(tirenv_ring *r, double *fx, double *fz, double *dfz_dz,
                              tirenv_diag *diag)
{
    const size_t n = r->n, lo = r->lo;
    const double(*q4)[4] = tirenv_ring__belt_end(r->belt, n);
    const double t_r = r->par.t_r, R = r->R;
    double *w = r->pn_w, *wn = r->pn_p, *wt = r->pn_t, *g = r->pn_g;
    /* From the last evaluation's belt where this window overlaps its window (zero
     * elsewhere): the states there are usually this one's, and the solution does not depend
     * on the start (the minimum of a strictly convex E). */
    for (size_t i = 0; i < n; ++i) {
        const size_t j = lo + i;
        w[i] = j >= r->warm_lo && j < r->warm_lo + r->warm_n ? r->w[j] : 0;
    }
    const tirenv_ring_newton nw = {n, q4, factor_cb, solve_cb, set_states, apply_cb,
                                   points_energy, r->rhs};
    int factored;
    const int st = tirenv_ring__newton(r, &nw, w, wn, wt, g, &factored);
    if (st != TIRENV_RING_NEWTON_OK)
        return tirenv_ring__newton_error(r, st, n, "contact", "continuous tread", diag);
    /* The factor of the final states, for dF_z/dz (the last Newton step's if they did not
     * change with it: the same matrix). */
    if (dfz_dz && !factored) {
        if (factor_cb(r, q4, wt))
            return tirenv_ring__newton_error(r, TIRENV_RING_NEWTON_BREAKDOWN, n, "contact",
                                             "continuous tread", diag);
    }
    double sum_c = 0, sum_s = 0;
    for (size_t j = r->warm_lo; j < r->warm_lo + r->warm_n; ++j)
        r->w[j] = 0;
    r->warm_lo = lo;
    r->warm_n = n;
    for (size_t i = 0; i < n; ++i) {
        r->w[lo + i] = w[i];
        r->F[lo + i] = 0;
        r->g[lo + i] = 0;
        wt[i] = 0;
    }
    for (size_t k = 0; k < r->n_pts; ++k) {
        tirenv_ring_point *q = &r->pts[k];
        q->e = q->d == -INFINITY ? -INFINITY : compression(r, q, w);
        q->f = 0;
        if (q->st == 0)
            continue;
        const double k_b = TIRENV_RING_BELT_LAYER * q->k_t;
        double dpsi;
        psi(q, k_b, t_r, q->e, &dpsi);
        q->f = q->omega * R * dpsi;
        r->F[q->j] += (1 - q->s) * q->f;
        r->F[q->j + 1] += q->s * q->f;
        if (q->st == 2) {
            const double gb = q->omega * R * k_b * (q->e - t_r);
            r->g[q->j] += (1 - q->s) * gb;
            r->g[q->j + 1] += q->s * gb;
        }
        sum_c += q->f * q->cs;
        sum_s += q->f * q->sn;
        /* dF_z/dz: the right-hand side omega R psi'' d' N. */
        const double c = q->omega * R * (q->k_t + (q->st == 2 ? k_b : 0)) * q->dd;
        wt[q->j - lo] += c * (1 - q->s);
        wt[q->j - lo + 1] += c * q->s;
    }
    *fz = sum_c;
    *fx = -sum_s;
    if (dfz_dz) {
        tirenv_ring__band_solve(&r->A, wt);
        double dF = 0;
        for (size_t k = 0; k < r->n_pts; ++k) {
            const tirenv_ring_point *q = &r->pts[k];
            if (q->st == 0)
                continue;
            const double k_b = TIRENV_RING_BELT_LAYER * q->k_t;
            const double de = q->dd - ((1 - q->s) * wt[q->j - lo] + q->s * wt[q->j - lo + 1]);
            dF += q->omega * R * (q->k_t + (q->st == 2 ? k_b : 0)) * de * q->cs;
        }
        *dfz_dz = dF;
    }
    return 0;
}
