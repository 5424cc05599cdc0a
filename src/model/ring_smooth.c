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
    const double R = r->R;
    tirenv_ring_band *A = &r->A;
    tirenv_ring__band_belt(A, r->belt, r->n);
    tirenv_ring__band_less_ends(A, q4);
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

/* The nodes that can touch. Of the window (every node whose interval holds ground within
 * R0 + t_r), often half never touches: where the ground lies within reach but the belt, pressed
 * in by the patch beside it, stays clear of it (the ring's patch is shorter than the chord of
 * its free circle). The contact is solved on the sub-window of the nodes in contact, REDUCE_PAD
 * more on each side, its ends moved out to multiples of REDUCE_QUANT node indices (so that it
 * stays the same while the patch moves a little, and few window lengths, whose end
 * corrections ring_belt.c keeps, occur); the free nodes outside condense out exactly. The
 * belt on the window's free ends is then solved given the sub-window's, and if no point there
 * is compressed, that is the minimum of E over the whole window (its gradient vanishes at
 * every node: the free ends' points carry no force). The sub-window is first that of the
 * points the last evaluation's belt (zero outside its window) leaves compressed; when the
 * contact found on it asks for another, it is solved again there (Newton from the answer: one
 * step if the states stay), and if a point of the free ends is compressed, on the whole window
 * first. So the answer is always the sub-window's of its own contact, solved with its final
 * states: the same bits whatever the evaluations before (as the whole window's were). The
 * constants choose only which systems are solved, not the answer: the sub-window's and the
 * whole window's minimum agree to round-off. */
enum { REDUCE_PAD = 2, REDUCE_QUANT = 8, REDUCE_MIN_FREE = 16, REDUCE_TRIES = 3 };

/* The warm start of node j: the last evaluation's belt over its window, zero elsewhere. */
static double warm_w(const tirenv_ring *r, size_t j)
{
    return j >= r->warm_lo && j < r->warm_lo + r->warm_n ? r->w[j] : 0;
}

/* The sub-window a .. b of the window r->lo, r->n for the points pts[kf .. kl] (the first and
 * the last in contact), and the points pts[k0 .. k1) of its intervals; 0 where it would not
 * leave at least two free nodes at each end and REDUCE_MIN_FREE in all. */
static int sub_window(const tirenv_ring *r, size_t kf, size_t kl, size_t *a, size_t *b,
                      size_t *k0, size_t *k1)
{
    const size_t lo = r->lo, hi = r->lo + r->n - 1, Q = REDUCE_QUANT;
    const tirenv_ring_point *const pts = r->pts;
    const size_t j1 = pts[kf].j, j2 = pts[kl].j + 1;
    if (j1 < lo + 2 + REDUCE_PAD || j2 + 2 + REDUCE_PAD > hi)
        return 0;
    size_t first = (j1 - REDUCE_PAD) / Q * Q, last = (j2 + REDUCE_PAD) / Q * Q + Q - 1;
    first = first >= lo + 2 ? first : lo + 2;
    last = last + 2 <= hi ? last : hi - 2;
    if ((first - lo) + (hi - last) < REDUCE_MIN_FREE)
        return 0;
    *a = first;
    *b = last;
    tirenv_ring__points_of(r, kf, kl, first, last, k0, k1);
    return 1;
}

/* The first and the last point of pts[k0 .. k1) in contact, by their states (warm: by the
 * compression the window's w of n entries leaves them); 0 if none. */
static int contact_span(const tirenv_ring *r, size_t k0, size_t k1, const double w[], int warm,
                        size_t *kf, size_t *kl)
{
    const tirenv_ring_point *const pts = r->pts;
    size_t k = k0;
    for (; k < k1; ++k)
        if (warm ? pts[k].d != -INFINITY && compression(r, &pts[k], w) > 0 : pts[k].st != 0)
            break;
    if (k == k1)
        return 0;
    *kf = k;
    for (k = k1; k-- > *kf;)
        if (warm ? pts[k].d != -INFINITY && compression(r, &pts[k], w) > 0 : pts[k].st != 0)
            break;
    *kl = k;
    return 1;
}

/* Newton on the nodes lo .. lo + n - 1 with the points pts[k0 .. k1), from w (its n entries,
 * overwritten with the answer); with want_factor, the factor of the final states left in r->A.
 * The ring's window and points are restored after. */
static int newton_window(tirenv_ring *r, size_t lo, size_t n, size_t k0, size_t k1, double w[],
                         int want_factor)
{
    tirenv_ring_point *const pts = r->pts;
    const size_t n_pts = r->n_pts, lo0 = r->lo, n0 = r->n;
    r->lo = lo;
    r->n = n;
    r->pts = pts + k0;
    r->n_pts = k1 - k0;
    const double(*q4)[4] = tirenv_ring__belt_end(r->belt, n);
    const tirenv_ring_newton nw = {n, q4, factor_cb, solve_cb, set_states, apply_cb,
                                   points_energy, r->rhs, NULL, 0, NULL, NULL, NULL};
    int factored;
    int st = tirenv_ring__newton(r, &nw, w, r->pn_p, r->pn_t, r->pn_g, &factored);
    /* The factor of the final states, for dF_z/dz (the last Newton step's if they did not
     * change with it: the same matrix). */
    if (st == TIRENV_RING_NEWTON_OK && want_factor && !factored && factor_cb(r, q4, r->pn_t))
        st = TIRENV_RING_NEWTON_BREAKDOWN;
    r->pts = pts;
    r->n_pts = n_pts;
    r->lo = lo0;
    r->n = n0;
    return st;
}

/* The belt on the window's free ends, w[0 .. a - lo) and w[b - lo + 1 .. n), given it on a ..
 * b: the window's condensed stiffness S on the ends' nodes (two runs, coupled only through S's
 * end correction: the band system's corner) against S's coupling to a .. b. 1 if no point of
 * the ends' intervals (pts[0 .. k0), pts[k1 ..)) is then compressed. */
static int ends_free(tirenv_ring *r, size_t a, size_t b, size_t k0, size_t k1, double w[])
{
    const size_t lo = r->lo, n = r->n, nl = a - lo, nr = lo + n - 1 - b, nf = nl + nr;
    const double *s = tirenv_ring__belt_stencil(r->belt);
    const double(*q4)[4] = tirenv_ring__belt_end(r->belt, n);
    tirenv_ring_band *B = &r->B;
    double *x = r->rhs;
    B->n = nf;
    for (size_t f = 0; f < nf; ++f) {
        B->a0[f] = s[0];
        B->a1[f] = s[1];
        B->a2[f] = s[2];
        x[f] = 0;
    }
    /* No band entry across the two runs or past the end. */
    B->a1[nl - 1] = B->a2[nl - 2] = B->a2[nl - 1] = 0;
    B->a1[nf - 1] = B->a2[nf - 2] = B->a2[nf - 1] = 0;
    /* The coupling to the nodes a .. b, known: the two nodes on each side of them. */
    const size_t ia = a - lo, ib = b - lo;
    x[nl - 2] = -s[2] * w[ia];
    x[nl - 1] = -s[1] * w[ia] - s[2] * w[ia + 1];
    x[nl] = -s[1] * w[ib] - s[2] * w[ib - 1];
    x[nl + 1] = -s[2] * w[ib];
    tirenv_ring__band_less_ends(B, q4);
    if (tirenv_ring__band_factor(B))
        return 0;
    tirenv_ring__band_solve(B, x);
    for (size_t f = 0; f < nf; ++f)
        w[f < nl ? f : f - nl + (b - lo) + 1] = x[f];
    for (size_t k = 0; k < r->n_pts; ++k) {
        if (k == k0)
            k = k1;
        if (k >= r->n_pts)
            break;
        const tirenv_ring_point *q = &r->pts[k];
        if (q->d != -INFINITY && compression(r, q, w) > 0)
            return 0;
    }
    return 1;
}

int tirenv_ring__solve_smooth(tirenv_ring *r, double *fx, double *fz, double *dfz_dz,
                              tirenv_diag *diag)
{
    const size_t n = r->n, lo = r->lo;
    const double t_r = r->par.t_r, R = r->R;
    double *w = r->pn_w, *wt = r->pn_t;
    /* From the last evaluation's belt where this window overlaps its window (zero
     * elsewhere): the states there are usually this one's, and the solution does not depend
     * on the start (the minimum of a strictly convex E). On the sub-window of the contact
     * (sub_window) where there is one; else, or where the free ends would be compressed, on
     * the whole window, and then on the sub-window of its contact. */
    const int want = dfz_dz != NULL;
    for (size_t i = 0; i < n; ++i)
        w[i] = warm_w(r, lo + i);
    size_t a = 0, b = 0, k0 = 0, k1 = r->n_pts, kf, kl, a2, b2, k02, k12;
    int reduced = contact_span(r, 0, r->n_pts, w, 1, &kf, &kl) &&
                  sub_window(r, kf, kl, &a, &b, &k0, &k1);
    for (size_t t = 0; reduced; ++t) {
        reduced = t < REDUCE_TRIES &&
                  newton_window(r, a, b - a + 1, k0, k1, w + (a - lo), want) ==
                      TIRENV_RING_NEWTON_OK &&
                  contact_span(r, k0, k1, w, 0, &kf, &kl) &&
                  sub_window(r, kf, kl, &a2, &b2, &k02, &k12);
        if (!reduced)
            break;
        if (a2 == a && b2 == b) {
            reduced = ends_free(r, a, b, k0, k1, w);
            break;
        }
        a = a2, b = b2, k0 = k02, k1 = k12;
    }
    if (!reduced) {
        const int st = newton_window(r, lo, n, 0, r->n_pts, w, want);
        if (st != TIRENV_RING_NEWTON_OK)
            return tirenv_ring__newton_error(r, st, n, "contact", "continuous tread", diag);
        /* The same answer as the sub-window's of this contact, if it has one: solved there
         * (one Newton step, the states kept), else the whole window's. */
        k0 = 0;
        k1 = r->n_pts;
        reduced = contact_span(r, 0, r->n_pts, w, 0, &kf, &kl) &&
                  sub_window(r, kf, kl, &a, &b, &k0, &k1);
        if (reduced) {
            /* The points outside pts[k0 .. k1) keep the whole window's states: this Newton
             * reads and sets only its own, ends_free none, and they are set free below where
             * the sub-window's answer stands, else set anew by the whole window's Newton. */
            const int st2 = newton_window(r, a, b - a + 1, k0, k1, w + (a - lo), want);
            if (st2 != TIRENV_RING_NEWTON_OK)
                return tirenv_ring__newton_error(r, st2, b - a + 1, "contact",
                                                 "continuous tread", diag);
            reduced = ends_free(r, a, b, k0, k1, w);
        }
        if (!reduced) { /* round-off at the sub-window's ends: the whole window's, again */
            k0 = 0;
            k1 = r->n_pts;
            const int st3 = newton_window(r, lo, n, 0, r->n_pts, w, want);
            if (st3 != TIRENV_RING_NEWTON_OK)
                return tirenv_ring__newton_error(r, st3, n, "contact", "continuous tread",
                                                 diag);
        }
    }
    const size_t off = reduced ? a - lo : 0;
    r->n_sub += reduced != 0;
    for (size_t k = 0; k < r->n_pts; ++k)
        if (k < k0 || k >= k1)
            r->pts[k].st = 0; /* the free ends' points, not compressed (ends_free) */
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
        tirenv_ring__band_solve(&r->A, wt + off);
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
