/* SPDX-License-Identifier: Apache-2.0 */
/* The ring's contact (docs/models.md section 5) on the window of nodes that can touch: with
 * each node free, in tread contact or held by the belt, the belt displacements solve one banded
 * system; the states come from block principal pivoting, with projected Newton on the contact
 * energy where pivoting stalls. */
#include <math.h>
#include <string.h>
#include "model/ring_impl.h"

/* Block pivoting passes before projected Newton takes over; from the last position's states
 * they typically need 1 to 3. */
enum { RING_MAX_PASSES = 30 };

enum {
    FREE = TIRENV_RING_FREE,
    T_BASIC = TIRENV_RING_T_BASIC,
    B_BASIC = TIRENV_RING_B_BASIC,
    TREAD = TIRENV_RING_T_BASIC,
};

/* The condensed belt stiffness S between window nodes i and k (local indices, i != k). */
static double belt_S(const tirenv_ring *r, const double (*q)[4], size_t i, size_t k)
{
    const size_t n = r->n, dist = i > k ? i - k : k - i;
    double s = dist <= 2 ? tirenv_ring__belt_stencil(r->belt)[dist] : 0;
    const int ei = i < 2 ? (int)i : i + 2 >= n ? (int)(i + 4 - n) : -1;
    const int ek = k < 2 ? (int)k : k + 2 >= n ? (int)(k + 4 - n) : -1;
    if (ei >= 0 && ek >= 0)
        s -= q[ei][ek];
    return s;
}

/* The window nodes coupled to node i in S: the band and, for the two nodes at either end,
 * the two at the other end. */
static size_t couplings(size_t n, size_t i, size_t k[6])
{
    size_t c = 0;
    for (size_t j = i >= 2 ? i - 2 : 0; j <= i + 2 && j < n; ++j)
        if (j != i)
            k[c++] = j;
    if (i < 2) {
        k[c++] = n - 2;
        k[c++] = n - 1;
    } else if (i + 2 >= n) {
        k[c++] = 0;
        k[c++] = 1;
    }
    return c;
}

/* (S w)_i: the ground force that holds window node i where it is. */
double tirenv_ring__belt_force(const tirenv_ring *r, const double (*q)[4], const double w[],
                               size_t i)
{
    const size_t n = r->n;
    const int ei = i < 2 ? (int)i : i + 2 >= n ? (int)(i + 4 - n) : -1;
    double sum = (tirenv_ring__belt_stencil(r->belt)[0] - (ei >= 0 ? q[ei][ei] : 0)) * w[i];
    size_t k[6];
    const size_t nk = couplings(n, i, k);
    for (size_t c = 0; c < nk; ++c)
        sum += belt_S(r, q, i, k[c]) * w[k[c]];
    return sum;
}

/* Holding the belt nodes: their values move to the right-hand side of the other rows. */
static void eliminate_belt(const tirenv_ring *r, const double (*q)[4], double rhs[])
{
    for (size_t i = 0; i < r->n; ++i) {
        if (!(r->state[r->lo + i] & B_BASIC))
            continue;
        size_t k[6];
        const size_t nk = couplings(r->n, i, k);
        for (size_t c = 0; c < nk; ++c)
            if (!(r->state[r->lo + k[c]] & B_BASIC))
                rhs[k[c]] -= belt_S(r, q, k[c], i) * rhs[i];
    }
}

/* The window system's matrix for the row kinds in r->state: S, plus kappa on the TREAD rows,
 * and identity rows (their couplings removed) on the B_BASIC rows, which hold the belt. */
static void assemble_matrix(tirenv_ring *r, const double (*q)[4])
{
    const size_t n = r->n, lo = r->lo;
    tirenv_ring_band *A = &r->A;
    tirenv_ring__band_belt(A, r->belt, n);
    for (size_t i = 0; i < n; ++i)
        if (r->state[lo + i] == TREAD)
            A->a0[i] += r->kappa[lo + i];
    tirenv_ring__band_less_ends(A, q);
    for (size_t i = 0; i < n; ++i) {
        if (!(r->state[lo + i] & B_BASIC))
            continue;
        A->a0[i] = 1;
        A->a1[i] = 0;
        A->a2[i] = 0;
        if (i >= 1)
            A->a1[i - 1] = 0;
        if (i >= 2)
            A->a2[i - 2] = 0;
        if (i < 2)
            A->c[i][0] = A->c[i][1] = 0;
        else if (i + 2 >= n)
            A->c[0][i + 2 - n] = A->c[1][i + 2 - n] = 0;
    }
}

/* The contact with the states fixed: right-hand side kappa d (tread), 0 (free), b - t_r
 * (belt, eliminated from the other rows); the belt displacements w and the ground forces F,
 * kappa (d - w) on a tread node and the belt's (S w) on a held one. */
static int solve_states(tirenv_ring *r, const double (*q)[4])
{
    const size_t n = r->n, lo = r->lo;
    assemble_matrix(r, q);
    if (tirenv_ring__band_factor(&r->A))
        return TIRENV_ENOCONV;
    for (size_t i = 0; i < n; ++i) {
        const size_t j = lo + i;
        r->rhs[i] = r->state[j] & B_BASIC  ? r->b[j] - r->par.t_r
                    : r->state[j] == TREAD ? r->kappa[j] * r->d[j]
                                           : 0;
    }
    eliminate_belt(r, q, r->rhs);
    tirenv_ring__band_solve(&r->A, r->rhs);
    for (size_t i = 0; i < n; ++i) {
        const size_t j = lo + i;
        r->w[j] = r->rhs[i];
        r->F[j] = r->state[j] & B_BASIC  ? tirenv_ring__belt_force(r, q, r->rhs, i)
                  : r->state[j] == TREAD ? r->kappa[j] * (r->d[j] - r->w[j])
                                         : 0;
    }
    return 0;
}

/* The pairs of the node whose complementarity the solution of the current states violates
 * (bits T_BASIC, B_BASIC): a tread force below zero, or a compressed tread without one; a belt
 * reaction below zero, or a belt in the ground. */
static unsigned char violated(const tirenv_ring *r, size_t j)
{
    const unsigned char s = r->state[j];
    unsigned char bad = 0;
    const double l = r->b[j] - r->par.t_r; /* the belt's lowest allowed displacement */
    double F_t = 0;                         /* tread force */
    if (s & T_BASIC)
        F_t = s & B_BASIC ? r->kappa[j] * (r->d[j] - l) : r->F[j];
    if (s & B_BASIC) {
        if (r->F[j] - F_t < 0)
            bad |= B_BASIC;
    } else if (r->w[j] < l) {
        bad |= B_BASIC;
    }
    if (r->d[j] > -INFINITY) {
        if (s & T_BASIC) {
            if (F_t < 0)
                bad |= T_BASIC;
        } else if (r->d[j] - r->w[j] > 0) {
            bad |= T_BASIC;
        }
    }
    return bad;
}

/* The violated pairs of every node into r->flip; their number. */
static size_t count_violated(tirenv_ring *r)
{
    size_t count = 0;
    for (size_t j = r->lo; j < r->lo + r->n; ++j) {
        r->flip[j] = r->b[j] == -INFINITY ? 0 : violated(r, j);
        count += (r->flip[j] & T_BASIC) + (r->flip[j] >> 1);
    }
    return count;
}

/* The energy whose minimum over w >= b - t_r the contact is (section 5): the belt's
 * 1/2 w.S w plus the tread's sum 1/2 kappa max(0, d - w)^2 (J), and its gradient
 * S w - kappa max(0, d - w) (N), window-local. */
static double energy(const tirenv_ring *r, const double (*q)[4], const double w[],
                     double grad[])
{
    double f = 0;
    for (size_t i = 0; i < r->n; ++i) {
        const size_t j = r->lo + i;
        const double Sw = tirenv_ring__belt_force(r, q, w, i), e = r->d[j] - w[i];
        const double F_t = e > 0 ? r->kappa[j] * e : 0;
        f += 0.5 * (w[i] * Sw + F_t * fmax(e, 0));
        if (grad)
            grad[i] = Sw - F_t;
    }
    return f;
}

/* Of each run of neighbouring nodes whose belt the solution puts into the ground, only the
 * deepest is held in the next pass: holding a whole run at once overshoots (the belt bends, a
 * held stretch lifts its middle off and the reactions there come out negative), and flipping
 * such runs back and forth is what makes block pivoting cycle. Splitting runs at their deepest
 * node reaches a wide held stretch in a few halvings. */
static void hold_deepest(tirenv_ring *r)
{
    const double t_r = r->par.t_r;
    size_t deepest = 0;
    double depth = 0;
    int in_run = 0;
    for (size_t j = r->lo; j <= r->lo + r->n; ++j) {
        const int adds = j < r->lo + r->n && (r->flip[j] & B_BASIC) && !(r->state[j] & B_BASIC);
        if (adds) {
            const double dj = r->b[j] - t_r - r->w[j];
            if (!in_run || dj > depth) {
                depth = dj;
                deepest = j;
            }
            in_run = 1;
            r->flip[j] &= (unsigned char)~B_BASIC;
        } else if (in_run) {
            r->flip[deepest] |= B_BASIC;
            in_run = 0;
        }
    }
}

/* The contact is a linear complementarity problem in the tread forces and belt reactions,
 * two pairs per node, whose matrix [[C + diag(1/kappa), C], [C, C]] (C: the window's
 * compliance) is symmetric positive definite: one solution. Block principal pivoting (the
 * primal-dual active set, a semi-smooth Newton method) finds it from the last position's
 * states in one to three solves: solve with the current states, flip every violated pair.
 * Flipping all can cycle (the ring's compliance is not an M-matrix: a belt node held down
 * lifts its neighbours), so, as Judice and Pires do, block flips go on while the number of
 * violated pairs keeps falling, with a few chances. 0: solved; 1: stalled. */
enum { RING_BLOCK_CHANCES = 8 };
static int pivot(tirenv_ring *r, const double (*q)[4], size_t max_passes)
{
    size_t best = (size_t)-1;
    int chances = RING_BLOCK_CHANCES;
    for (size_t pass = 0; pass < max_passes; ++pass) {
        if (solve_states(r, q))
            return -1;
        const size_t count = count_violated(r);
        if (count == 0)
            return 0;
        if (count < best) {
            best = count;
            chances = RING_BLOCK_CHANCES;
        } else if (chances-- == 0) {
            return 1;
        }
        hold_deepest(r);
        for (size_t j = r->lo; j < r->lo + r->n; ++j)
            r->state[j] ^= r->flip[j];
    }
    return 1;
}

/* Where the pivoting stalls, Bertsekas' projected Newton method on that energy, which
 * converges from anywhere: Newton on the nodes off their bound (S plus kappa where the tread
 * is compressed), a scaled gradient step on those within eps of it that the gradient pushes
 * in, projection onto the bounds, Armijo backtracking. After each step the states its iterate
 * shows are solved exactly and checked; the first that satisfy every pair are the solution. */
enum { RING_PN_ITER = 200, RING_PN_BACKTRACK = 60, RING_PN_PIVOTS = 5 };
static const double ring_pn_eps = 1e-4;      /* largest eps of the active set, m */
static const double ring_pn_sigma = 1e-4;    /* Armijo's sufficient decrease */
static int projected_newton(tirenv_ring *r, const double (*q)[4])
{
    const size_t n = r->n, lo = r->lo;
    const double t_r = r->par.t_r;
    double *w = r->pn_w, *p = r->pn_p, *wt = r->pn_t, *g = r->pn_g;
    for (size_t i = 0; i < n; ++i)
        w[i] = fmax(r->w[lo + i], r->b[lo + i] - t_r);
    for (size_t it = 0; it < RING_PN_ITER; ++it) {
        const double f = energy(r, q, w, g), s0 = tirenv_ring__belt_stencil(r->belt)[0];
        double delta = 0; /* distance to the projected gradient step: 0 at the minimum */
        for (size_t i = 0; i < n; ++i)
            delta = fmax(delta, fabs(w[i] - fmax(r->b[lo + i] - t_r, w[i] - g[i] / s0)));
        const double eps = fmin(ring_pn_eps, delta);
        for (size_t i = 0; i < n; ++i) {
            const size_t j = lo + i;
            const int held = w[i] - (r->b[j] - t_r) <= eps && g[i] > 0;
            r->state[j] = held ? B_BASIC : r->d[j] - w[i] > 0 ? TREAD : FREE;
            p[i] = held ? 0 : -g[i];
        }
        assemble_matrix(r, q);
        if (tirenv_ring__band_factor(&r->A))
            return -1;
        tirenv_ring__band_solve(&r->A, p);
        for (size_t i = 0; i < n; ++i)
            if (r->state[lo + i] & B_BASIC)
                p[i] = -g[i] / s0;
        double alpha = 1;
        for (size_t k = 0; k < RING_PN_BACKTRACK; ++k, alpha *= 0.5) {
            double slope = 0;
            for (size_t i = 0; i < n; ++i) {
                wt[i] = fmax(r->b[lo + i] - t_r, w[i] + alpha * p[i]);
                slope += g[i] * (wt[i] - w[i]);
            }
            if (energy(r, q, wt, NULL) <= f + ring_pn_sigma * slope)
                break;
        }
        memcpy(w, wt, n * sizeof *w);
        for (size_t i = 0; i < n; ++i) {
            const size_t j = lo + i;
            const double l = r->b[j] - t_r;
            r->state[j] = r->b[j] == -INFINITY ? FREE
                          : w[i] <= l          ? (r->d[j] - l > 0 ? B_BASIC | T_BASIC : B_BASIC)
                          : r->d[j] - w[i] > 0 ? TREAD
                                               : FREE;
        }
        const int st = pivot(r, q, RING_PN_PIVOTS);
        if (st < 0)
            return -1;
        if (st == 0)
            return 0;
    }
    return TIRENV_ENOCONV;
}

/* A breakdown of the banded Cholesky is its own failure, not a slow convergence: the contact
 * system is symmetric positive definite in exact arithmetic, so a breakdown means the belt's
 * stiffness is numerically singular (far too stiff or too soft a tire). */
static int contact_failed(const tirenv_ring *r, int breakdown, tirenv_diag *diag)
{
    if (breakdown)
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "ring",
                            "the Cholesky factorisation of the %zu-node banded contact system "
                            "broke down (not numerically positive definite)", r->n);
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "ring",
                        "the tread and belt contact states of %zu nodes did not settle "
                        "(block pivoting stalled and projected Newton ran out of %d iterations)",
                        r->n, RING_PN_ITER);
}

/* From the last evaluation's states (or tread contact wherever a ray penetrates, if there was
 * none), pivoting; where it stalls, projected Newton. */
int tirenv_ring__solve_contact(tirenv_ring *r, tirenv_diag *diag)
{
    const size_t n = r->n, lo = r->lo;
    const int warm = r->warm_n > 0;
    for (size_t j = lo; j < lo + n; ++j) {
        unsigned char s = r->warm[j];
        if (!warm && r->d[j] > 0)
            s = TREAD;
        if (r->d[j] == -INFINITY)
            s &= (unsigned char)~T_BASIC;
        if (r->b[j] == -INFINITY)
            s = FREE;
        r->state[j] = s;
    }
    const double(*q)[4] = tirenv_ring__belt_end(r->belt, n);
    int status = pivot(r, q, RING_MAX_PASSES);
    if (status > 0)
        status = projected_newton(r, q);
    return status ? contact_failed(r, status < 0, diag) : 0;
}

/* dF_z/dz with the states fixed: d and b move with z (d' = -d(rho)/dz), the tread rows carry
 * kappa d', the belt rows hold w' = b'; through the same factor. */
double tirenv_ring__dfz_dz(tirenv_ring *r)
{
    const size_t n = r->n, lo = r->lo;
    const double(*q)[4] = tirenv_ring__belt_end(r->belt, n);
    double *v = r->rhs;
    for (size_t i = 0; i < n; ++i) {
        const size_t j = lo + i;
        v[i] = r->state[j] & B_BASIC ? r->db[j]
               : r->state[j] == TREAD ? r->kappa[j] * r->dd[j]
                                      : 0;
    }
    eliminate_belt(r, q, v);
    tirenv_ring__band_solve(&r->A, v);
    double dF = 0;
    for (size_t i = 0; i < n; ++i) {
        const size_t j = lo + i;
        if (r->state[j] & B_BASIC)
            dF += tirenv_ring__belt_force(r, q, v, i) * r->cos_t[j];
        else if (r->state[j] == TREAD)
            dF += r->kappa[j] * (r->dd[j] - v[i]) * r->cos_t[j];
    }
    return dF;
}

