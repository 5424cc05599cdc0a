/* SPDX-License-Identifier: Apache-2.0 */
/* The state of the springs model's continuous contact at a new centre height from the last
 * QP solve at the same x, by the tangent of its working set, accepted only where the QP's
 * KKT conditions hold there (docs/models.md section 4.8, The confirming evaluation):
 * Newton's confirming evaluation, a hair from the one before, without building the rows or solving
 * again. */
#include "model/springs_impl.h"

#include <math.h>
#include <stdint.h>
#include <stddef.h>
#include <string.h>
#include "profile/profile_impl.h"

/* The farthest (m) from the base's height an update is tried from the tangent. The tangent
 * errs by the rows' curvature in z times dz^2 / 2 (a vertex row's h = R0 - |V - C| and its
 * weights; a ray's row on a fixed face is linear), about dz^2 / |V - C|: below the equality
 * tolerance (eq_tol) only for dz under about 1e-7 m, and within 1e-6 m after a correction
 * or two (below). Newton's second evaluation, 1e-5 to 1e-4 m from the first, starts instead
 * from the state tirenv_springs__cc_root solved for at that height (springs_root.c), exact
 * but for round-off where the working set holds; from the tangent it would need more
 * corrections (tried: it cost more than it spared, docs/performance.md 1.4). */
static const double upd_dz_max = 1e-6;

/* Corrections of the tangent's residual before the update is given up: each divides it by
 * some 50 or more within upd_dz_max, so two take 1e-6 m's residual to round-off. */
enum { max_corrections = 2 };

/* The working rows must hold as equalities, and K w = G^T lambda, within these (relative to
 * R0, and to k_max R0 in N): a few hundred units of round-off of h and w (R0 about 0.7 m, an
 * ulp of it 1.1e-16 m), against the 1e-12 R0 to which the solve's rows hold. A state within
 * them is the QP's solution to within about 1e-14 R0 in w (K is positive definite and its
 * working rows independent), so F_z within about the hub's stiffness times 1e-14 R0, some
 * 1e-8 N at the bench's load, far below the equilibrium's force tolerance (1e-4 N). */
static const double eq_tol = 1e-14;

/* The vertex row of vertex id among V[0..n) (ascending by id), or SIZE_MAX. */
static size_t find_vrow(const tirenv_springs__cc_row V[], size_t n, long id)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (V[mid].id < id)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < n && V[lo].id == id ? lo : SIZE_MAX;
}

typedef double v2d __attribute__((vector_size(2 * sizeof(double))));
typedef long long v2l __attribute__((vector_size(2 * sizeof(long long))));

/* Whether one of d[0..len) is > 0, two a step without a branch (the rays beyond the span). */
static inline __attribute__((always_inline)) int any_positive(const double *d, size_t len)
{
    const v2d zero = {0, 0};
    v2l o = {0, 0};
    size_t k = 0;
    for (; k + 2 <= len; k += 2) {
        v2d v;
        memcpy(&v, d + k, sizeof v);
        o |= v > zero;
    }
    int any = (o[0] | o[1]) != 0;
    for (; k < len; ++k)
        any |= d[k] > 0;
    return any;
}

/* The free elements of one chain, len of them from res, ph and w: *off set where one's
 * residual exceeds tol_k in size (or, given w for res, where one's |w| exceeds it), *below
 * where one stands below its own row (ph > 0) by more than tol; their reactions pq set to 0.
 * Two elements a step in GCC's vector extension: GCC 12 does not vectorise a comparison of
 * doubles counted into an integer, and the pass was a quarter of the update's instructions. */
static inline __attribute__((always_inline)) void
chain_check(const double *res, const double *ph, const double *w, double *pq, size_t len,
            double tol_k, double tol, int *off, int *below)
{
    const v2d tk = {tol_k, tol_k}, nt = {-tol, -tol}, zero = {0, 0};
    const v2l no_sign = {0x7fffffffffffffffLL, 0x7fffffffffffffffLL};
    v2l o = {0, 0}, b = {0, 0};
    size_t k = 0;
    for (; k + 2 <= len; k += 2) {
        v2d r, h, x;
        memcpy(&r, res + k, sizeof r);
        memcpy(&h, ph + k, sizeof h);
        memcpy(&x, w + k, sizeof x);
        memcpy(pq + k, &zero, sizeof zero);
        o |= (v2d)((v2l)r & no_sign) > tk; /* |r|: the sign bit cleared, as fabs */
        /* x - h where h > 0, else +0 (not below -tol): one comparison to OR in, since GCC 12
         * turns an OR of two masks ANDed into a select a lane at a time */
        b |= (v2d)((v2l)(x - h) & (h > zero)) < nt;
    }
    int of = (o[0] | o[1]) != 0, be = (b[0] | b[1]) != 0;
    for (; k < len; ++k) {
        of |= fabs(res[k]) > tol_k;
        be |= (ph[k] > 0) & (w[k] - ph[k] < -tol);
        pq[k] = 0;
    }
    *off |= of;
    *below |= be;
}

/* K w on [lo, hi] within [f0, f1], the free chains beyond the span left for the caller to
 * fold in: its ends apart (a 0 for the neighbour beyond, as written), the middle a loop the
 * compiler vectorises. The same expression at every element whatever range it is asked for. */
static inline __attribute__((always_inline)) void
k_times_w(double res[], const double w[], const double diag[], double k_ir, size_t f0, size_t f1,
          size_t lo, size_t hi)
{
    if (f0 == f1) {
        res[f0] = diag[f0] * w[f0] - k_ir * (0.0 + 0.0);
        return;
    }
    size_t e = lo;
    if (e == f0) {
        res[f0] = diag[f0] * w[f0] - k_ir * (0.0 + w[f0 + 1]);
        ++e;
    }
    const size_t m = hi < f1 ? hi : f1 - 1;
    const v2d kk = {k_ir, k_ir};
    for (; e + 1 <= m; e += 2) { /* two a step: GCC 12 left the short runs' loop scalar */
        v2d dg, wc, wl, wr;
        memcpy(&dg, diag + e, sizeof dg);
        memcpy(&wc, w + e, sizeof wc);
        memcpy(&wl, w + e - 1, sizeof wl);
        memcpy(&wr, w + e + 1, sizeof wr);
        const v2d r = dg * wc - kk * (wl + wr);
        memcpy(res + e, &r, sizeof r);
    }
    for (; e <= m; ++e)
        res[e] = diag[e] * w[e] - k_ir * (w[e - 1] + w[e + 1]);
    if (hi == f1)
        res[f1] = diag[f1] * w[f1] - k_ir * (w[f1 - 1] + 0.0);
}

/* One run of held elements, len of them from ph: w set to ph, 1 if one is not above 0 (or is
 * NaN). Two elements a step, as chain_check. */
static inline __attribute__((always_inline)) int run_on_rows(const double *ph, double *w,
                                                            size_t len)
{
    const v2d zero = {0, 0};
    v2l not_on = {0, 0};
    size_t k = 0;
    for (; k + 2 <= len; k += 2) {
        v2d h;
        memcpy(&h, ph + k, sizeof h);
        memcpy(w + k, &h, sizeof h);
        not_on |= (v2d)((v2l)h & (h > zero)) <= zero; /* h where h > 0, else +0 */
    }
    int no = (not_on[0] | not_on[1]) != 0;
    for (; k < len; ++k) {
        no |= !(ph[k] > 0);
        w[k] = ph[k];
    }
    return no;
}

/* One run of held elements' reactions, len of them from res, into pq: *l_min lowered to the
 * least r by the comparison the scalar pass made (NaN passes it not), *n_pos counting those > 0
 * (as a double: exact, and GCC 12 counts a mask into an integer a lane at a time). The largest
 * |r| is wanted only where some reaction is below 0 (the caller takes it then). */
static inline __attribute__((always_inline)) void
run_reactions(const double *res, double *pq, size_t len, double *l_min, double *n_pos)
{
    const v2d zero = {0, 0}, one = {1, 1};
    v2d mn = {*l_min, *l_min}, np = {0, 0};
    size_t k = 0;
    for (; k + 2 <= len; k += 2) {
        v2d r;
        memcpy(&r, res + k, sizeof r);
        memcpy(pq + k, &r, sizeof r);
        const v2l down = r < mn;
        mn = (v2d)((down & (v2l)r) | (~down & (v2l)mn));
        np += (v2d)((v2l)one & (r > zero));
    }
    double lo = mn[1] < mn[0] ? mn[1] : mn[0], n = np[0] + np[1];
    for (; k < len; ++k) {
        const double r = res[k];
        lo = r < lo ? r : lo;
        n += r > 0;
        pq[k] = r;
    }
    *l_min = lo;
    *n_pos += n;
}

/* The run of held elements [*h0, *h1) before chain q of ch[0..2 n_ch) (q = n_ch: after the
 * last) within [f0, f1]. The chains are the factor's, the free elements' maximal runs in
 * ascending order (tirenv_springs__cc_schur_factor and its flips), so h0 <= h1: the first
 * and the last run may be empty, the others hold at least one element. */
static inline void held_run(const size_t ch[], size_t n_ch, size_t f0, size_t f1, size_t q,
                            size_t *h0, size_t *h1)
{
    *h0 = q == 0 ? f0 : ch[2 * q - 1] + 1;
    *h1 = q == n_ch ? f1 + 1 : ch[2 * q];
}

/* Where the state is tirenv_springs__cc_root_at's, each free element inside a chain (not its
 * ends, not a working row's) holds w as that solve left it, and its equation's right-hand
 * side is 0 in both systems: its residual is the Thomas solve's own. For K_FF, a symmetric
 * diagonally dominant M-matrix, the computed LDL^T solve satisfies (K + dK) w = b with
 * |dK| <= 8 u |K| element by element (u = 2^-53: the factor's rounding and the two sweeps',
 * |L| |D| |L^T| being |K| to O(u) since mul < 0 < piv), and the update's three operations
 * add 3 u |K| |w|: |K w|_e <= 11 u (k_r + 4 k_ir) max |w|, which is below a quarter of
 * eq_tol R0 (k_r + 2 k_ir) while every |w| <= R0 (tol_w = R0 below). The update checks that
 * premise on those elements instead of their residual (docs/models.md section 4.8, A start at
 * a new x; test_inner_residual_bound). (The helpers above are forced inline: called apart,
 * they cost more in calls than the residuals they spare.) */

/* The working rows between elements at z, as the update carries them. */
typedef struct {
    size_t n;                                       /* rows */
    size_t i[TIRENV_SPRINGS__SCHUR_MAX];            /* each row's elements i and i + 1 */
    double ga[TIRENV_SPRINGS__SCHUR_MAX], gb[TIRENV_SPRINGS__SCHUR_MAX]; /* weights a(t), b(t) */
    double cmp[TIRENV_SPRINGS__SCHUR_MAX];          /* the tread's compliance c(t), m/N */
    double h[TIRENV_SPRINGS__SCHUR_MAX];            /* R0 - |V - C|, m */
    double lam[TIRENV_SPRINGS__SCHUR_MAX];          /* the reaction, N */
    double res[TIRENV_SPRINGS__SCHUR_MAX];          /* the row's equation's residual, m */
} upd_rows;

/* Each element's own row at z over [f0, f1]: 0 outside the rays [ra, rb], d inside (>= 0 as
 * the caller gives it), raised where a vertex on an element stands higher; and which row
 * (c->upd_pin: the vertex, or -1 - e for the ray), pin written only on the elements a vertex
 * row sits on (a pass over the span cost some 400 instructions an update; the others are
 * their rays'). Where the rays cover the span and no vertex stands higher, d itself (a copy
 * of it cost some 450 instructions an update); else in three pieces (zeros, a copy of d,
 * zeros) in c->upd_w. */
static const double *own_rows(tirenv_springs__cc *c, const double d[], size_t ra, size_t rb)
{
    const size_t f0 = c->f0, f1 = c->f1, nv = c->n_vrows;
    const tirenv_springs__cc_row *V = c->vrows;
    long *pin = c->upd_pin;
    for (size_t k = 0; k < nv; ++k)
        if (V[k].t == 0)
            pin[V[k].i] = -1 - (long)V[k].i;
    const size_t r0 = ra <= rb ? ra : f1 + 1, r1 = ra <= rb ? rb : f1;
    int raised = r0 != f0 || r1 != f1;
    for (size_t k = 0; k < nv && !raised; ++k)
        raised = V[k].t == 0 && V[k].h > d[V[k].i];
    if (!raised)
        return d;
    double *ph_w = c->upd_w + 1;
    for (size_t e = f0; e < r0; ++e)
        ph_w[e] = 0;
    if (r0 <= r1) /* d >= 0, never -0 or NaN: what max(d, 0) gives */
        memcpy(ph_w + r0, d + r0, (r1 - r0 + 1) * sizeof *ph_w);
    for (size_t e = r1 + 1; e <= f1; ++e)
        ph_w[e] = 0;
    for (size_t k = 0; k < nv; ++k)
        if (V[k].t == 0 && V[k].h > ph_w[V[k].i]) {
            ph_w[V[k].i] = V[k].h;
            pin[V[k].i] = V[k].id;
        }
    return ph_w;
}

/* w at z: the held elements on their row (the same row as the base's), the free ones along
 * the tangent (or as root_at's state has them, pred), each above its own row; 0 if one is
 * not. c->wpos marks the held elements of the base's last KKT system, its final working
 * set. A held element on its ray's row must have no vertex standing higher on it now; one on
 * a vertex's (held_vertex of them, counted by the solve), that vertex, which the pass over
 * the vertex rows after this one counts (n_same): so this pass reads no row. */
static int held_at(const tirenv_springs__cc *c, const double ph[], double wn[], int pred,
                   double dz, const double dw[])
{
    const size_t f0 = c->f0, f1 = c->f1, nv = c->n_vrows;
    const tirenv_springs__cc_row *V = c->vrows;
    const long *pin = c->upd_pin;
    const size_t *wpos = c->wpos, *pin_row = c->pin_row;
    const tirenv_springs__cc_row *rows = c->rows;
    const double *base_w = c->base_w + 1;
    size_t n_same = 0;
    /* The held elements are the chains' complement in [f0, f1] (the base's factor's chains
     * and its layout's held list describe the same wpos; the count checks it): the free ones
     * as the state has them (a copy a chain, or a loop the compiler vectorises), then the held
     * runs between the chains, each on its row. */
    const size_t *ch = c->chains, n_ch = c->n_chains;
    if (pred) {
        for (size_t q = 0; q < n_ch; ++q)
            memcpy(wn + ch[2 * q], c->pred_w + ch[2 * q],
                   (ch[2 * q + 1] - ch[2 * q] + 1) * sizeof *wn);
    } else {
        for (size_t e = f0; e <= f1; ++e)
            wn[e] = base_w[e] + dz * dw[e];
    }
    size_t n_free = 0;
    int not_on = 0;
    for (size_t q = 0; q <= n_ch; ++q) {
        size_t h0, h1;
        held_run(ch, n_ch, f0, f1, q, &h0, &h1);
        n_free += q < n_ch ? ch[2 * q + 1] - ch[2 * q] + 1 : 0;
        not_on |= run_on_rows(ph + h0, wn + h0, h1 - h0);
    }
    if (not_on || n_free + c->n_held != f1 - f0 + 1)
        return 0;
    for (size_t k = 0; k < nv; ++k) {
        const size_t e = V[k].i;
        if (V[k].t != 0 || pin[e] != V[k].id || wpos[e] != SIZE_MAX)
            continue; /* not the row e stands on now, or e free */
        if (pin_row[e] == SIZE_MAX || rows[pin_row[e]].id != V[k].id)
            return 0; /* e held on its ray's row, or another vertex's, at the base (or held
                       * by the start at a new x, with no row at the base) */
        ++n_same;
    }
    return n_same == c->held_vertex; /* else an element held on a vertex at the base stands
                                      * on its ray now */
}

/* The working rows between elements at z: the same vertex in the same sector, its weights at
 * its new t, its reaction along the tangent (or root_at's, pred); 0 if a row is not. */
static int rows_at(const tirenv_springs__cc *c, const tirenv_springs__cc_tire *T, int pred,
                   double dz, upd_rows *R)
{
    const tirenv_springs__cc_row *V = c->vrows;
    const size_t nv = c->n_vrows;
    R->n = c->n_schur;
    for (size_t q = 0; q < R->n; ++q) {
        const size_t r = c->order[c->schur_pos[q]] - T->N;
        const tirenv_springs__cc_row *W = &c->rows[r];
        const size_t k = W->t > 0 ? find_vrow(V, nv, W->id) : SIZE_MAX;
        if (k == SIZE_MAX || V[k].t == 0 || V[k].i != W->i)
            return 0;
        double da, db;
        tirenv_springs__cc_weights(T, V[k].t, &R->ga[q], &R->gb[q], &da, &db);
        R->cmp[q] = tirenv_springs__cc_compliance(T, R->ga[q], R->gb[q]);
        R->h[q] = V[k].h;
        R->i[q] = W->i;
        R->lam[q] = pred ? c->pred_lam[q] : c->lambda[r] + dz * c->dlambda[r];
    }
    return 1;
}

/* What the KKT equations' last pass found. */
typedef struct {
    double l_max, l_min;  /* the rows' largest |reaction| and every reaction's least, N */
    size_t n_c;           /* the held elements with a reaction > 0 */
} upd_check;

/* The KKT equations of the working set at z, K w = G^T lambda on the free elements and
 * G w + C lambda = h on the rows between elements, hold along the tangent but for the rows'
 * curvature in z; their residual is corrected with the base's factors (the system at z
 * differs from the base's only by the rows' weights, t moving some 200 times dz/m: a few per
 * cent of S at 1e-4 m, 2e-4 at 1e-6 m), until it is at round-off, or the update is given up
 * (0; 0 too where a free element is below its own row). With the equations: the reactions'
 * least (the held elements' are their residuals of K w = G^T lambda; the largest, the rows'
 * here and the held ones' in reactions_hold, only where the least is below 0), and whether
 * each free element is above its own row (its ray's, or a vertex's on it); each element's
 * own reaction into pq (0 on the free ones; a pass of its own cost some 700 instructions). */
static int settle(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T, const double ph[],
                  double wn[], double pq[], upd_rows *R, int pred, upd_check *out)
{
    const size_t f0 = c->f0, f1 = c->f1, N = T->N, n_s = R->n;
    const double R0 = T->R0, tol = 1e-12 * R0, tol_eq = eq_tol * R0;
    const double k_ir = T->k_ir, tol_k = eq_tol * R0 * (T->k_r + 2 * k_ir);
    const size_t *ch = c->chains, n_ch = c->n_chains, *wpos = c->wpos;
    double *res = c->raise, *x_c = c->w_try;
    double l_max = 0, l_min = 0;
    int above = 1;
    size_t n_c = 0;
    /* part: the first pass from root_at's state takes K w only where the right-hand side or
     * w differs from that solve's (the held elements, the chains' ends, the working rows'
     * elements) and checks |w| <= tol_w on the chains instead (above); if anything is off,
     * the pass is made again over every element, as the corrections need */
    const double tol_w = R0;
    int part = pred && c->pred_held;
    for (size_t it = 0;;) {
        /* K w, the free chains beyond the span folded into its ends' diagonal as in the
         * KKT system, less G^T lambda */
        const double *diag = T->diag;
        if (part) { /* between the chains' insides, ends included, then the rows' elements */
            size_t lo = f0;
            for (size_t q = 0; q < n_ch; ++q) {
                k_times_w(res, wn, diag, k_ir, f0, f1, lo, ch[2 * q]);
                lo = ch[2 * q + 1];
            }
            k_times_w(res, wn, diag, k_ir, f0, f1, lo, f1);
            for (size_t q = 0; q < n_s; ++q)
                k_times_w(res, wn, diag, k_ir, f0, f1, R->i[q], R->i[q] + 1);
        } else {
            k_times_w(res, wn, diag, k_ir, f0, f1, f0, f1);
        }
        if (f0 > 0)
            res[f0] -= k_ir * T->lq[f0 - 1] * wn[f0];
        if (f1 + 1 < N)
            res[f1] -= k_ir * T->rq[f1 + 1] * wn[f1];
        int ok = 1;
        l_max = l_min = 0;
        for (size_t q = 0; q < n_s; ++q) {
            const size_t i = R->i[q];
            res[i] -= R->ga[q] * R->lam[q];
            res[i + 1] -= R->gb[q] * R->lam[q];
            R->res[q] = R->ga[q] * wn[i] + R->gb[q] * wn[i + 1] + R->cmp[q] * R->lam[q] -
                        R->h[q];
            ok = ok && fabs(R->res[q]) <= tol_eq;
            l_max = fabs(R->lam[q]) > l_max ? fabs(R->lam[q]) : l_max;
            l_min = R->lam[q] < l_min ? R->lam[q] : l_min;
        }
        /* the free elements chain by chain (the base's factor's chains: wpos' free ones),
         * each a loop without a branch; then the held runs between them */
        int off = 0, below = 0;
        for (size_t q = 0; q < n_ch; ++q) {
            const size_t e0 = ch[2 * q], e1 = ch[2 * q + 1], len = e1 - e0 + 1;
            if (part) {
                chain_check(wn + e0, ph + e0, wn + e0, pq + e0, len, tol_w, tol, &off, &below);
                off |= (fabs(res[e0]) > tol_k) | (fabs(res[e1]) > tol_k);
            } else {
                chain_check(res + e0, ph + e0, wn + e0, pq + e0, len, tol_k, tol, &off, &below);
            }
        }
        for (size_t q = 0; part && q < n_s; ++q)
            for (size_t e = R->i[q]; e <= R->i[q] + 1; ++e)
                off |= wpos[e] != SIZE_MAX && fabs(res[e]) > tol_k;
        ok &= !off;
        above = !below;
        double n_pos = 0;
        for (size_t q = 0; q <= n_ch; ++q) {
            size_t h0, h1;
            held_run(ch, n_ch, f0, f1, q, &h0, &h1);
            run_reactions(res + h0, pq + h0, h1 - h0, &l_min, &n_pos);
        }
        n_c = (size_t)n_pos;
        if (ok)
            break;
        if (part) { /* every element's residual, as the corrections take it */
            part = 0;
            continue;
        }
        if (it++ == max_corrections)
            return 0;
        for (size_t e = f0; e <= f1; ++e)
            x_c[e] = wpos[e] == SIZE_MAX ? 0 : -res[e];
        for (size_t q = 0; q < n_s; ++q)
            R->res[q] = -R->res[q];
        tirenv_springs__cc_schur_solve_at(c, T, x_c, R->res);
        for (size_t e = f0; e <= f1; ++e)
            if (wpos[e] != SIZE_MAX)
                wn[e] += x_c[e];
        for (size_t q = 0; q < n_s; ++q)
            R->lam[q] += R->res[q];
    }
    *out = (upd_check){l_max, l_min, n_c};
    return above;
}

/* Every reaction >= 0, by the solve's own rule: where the least is below 0, within 1e-12 of
 * the largest |reaction|, the held ones' from pq (l_min >= 0 passes). */
static int reactions_hold(const tirenv_springs__cc *c, const double pq[], const upd_check *k)
{
    if (!(k->l_min < 0))
        return 1;
    const size_t *ch = c->chains, n_ch = c->n_chains;
    double l_max = k->l_max;
    for (size_t q = 0; q <= n_ch; ++q) {
        size_t h0, h1;
        held_run(ch, n_ch, c->f0, c->f1, q, &h0, &h1);
        for (size_t e = h0; e < h1; ++e)
            l_max = fabs(pq[e]) > l_max ? fabs(pq[e]) : l_max;
    }
    return !(k->l_min < -1e-12 * l_max);
}

/* Every other vertex row between elements holds: below the chord of its tips less the bounds
 * of the weights (as the scan drops vertices, with w for the rays' penetrations), else by its
 * weights. (Those on an element were checked with the pins; the working rows are equalities,
 * checked in settle.) */
static int others_hold(const tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                       const double wn[], size_t n_s)
{
    const tirenv_springs__cc_row *V = c->vrows;
    const double tol = 1e-12 * T->R0;
    for (size_t k = 0; k < c->n_vrows; ++k) {
        const tirenv_springs__cc_row *Q = &V[k];
        if (Q->t == 0 || (n_s > 0 && tirenv_springs__long_in(c->warm_ids, c->n_warm, Q->id)))
            continue;
        const double t = Q->t, wi = wn[Q->i], wj = wn[Q->j];
        const double chord = (1 - t) * wi + t * wj - fabs(wj - wi) * T->tau_dev;
        if (chord > 0 && Q->h <= chord * (1 + T->ab_lo * t * (1 - t)))
            continue;
        double a_t, b_t, da, db;
        tirenv_springs__cc_weights(T, t, &a_t, &b_t, &da, &db);
        if (a_t * wi + b_t * wj - Q->h < -tol)
            return 0;
    }
    return 1;
}

/* Accepted: the outputs as the solve gives them (pe: each element's net reaction, the
 * rows' shares added; the contacts: n_c counted each element by its own reaction, the rows'
 * elements, at most two a row, some shared, counted again by pe as it ends; w beyond the
 * span's ends from the free chains). obstacle = ph, which is >= 0 and never -0 or NaN (as
 * the layout's pin_h): what max(ph, 0) gives, copied (where ph is d and d is obstacle, as the
 * model passes them, already there). */
static void accept(const tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                   const double ph[], double obstacle[], double w[], double pe[],
                   const upd_rows *R, size_t n_c, size_t *contacts)
{
    const size_t f0 = c->f0, f1 = c->f1, N = T->N, n_s = R->n;
    if (ph != obstacle)
        memcpy(obstacle + f0, ph + f0, (f1 - f0 + 1) * sizeof *obstacle);
    size_t el[2 * TIRENV_SPRINGS__SCHUR_MAX], n_el = 0;
    for (size_t q = 0; q < n_s; ++q)
        for (size_t e = R->i[q]; e <= R->i[q] + 1; ++e) {
            size_t m = 0;
            while (m < n_el && el[m] != e)
                ++m;
            if (m == n_el) {
                el[n_el++] = e;
                n_c -= pe[e] > 0;
            }
        }
    for (size_t q = 0; q < n_s; ++q) {
        pe[R->i[q]] += R->ga[q] * R->lam[q];
        pe[R->i[q] + 1] += R->gb[q] * R->lam[q];
    }
    for (size_t m = 0; m < n_el; ++m)
        n_c += pe[el[m]] > 0;
    *contacts = n_c;
    w[(long)f0 - 1] = f0 > 0 ? T->lq[f0 - 1] * w[f0] : 0;
    w[f1 + 1] = f1 + 1 < N ? T->rq[f1 + 1] * w[f1] : 0;
}

int tirenv_springs__cc_update(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                              const tirenv_profile *p, double x, double z, size_t a, size_t b,
                              const double d[], const double dw[], double w[], double pe[],
                              double obstacle[], size_t *contacts)
{
    const size_t f0 = c->f0, f1 = c->f1;
    const double dz = z - c->base_z;
    /* From the tangent a hair from the base, or from the state tirenv_springs__cc_root
     * solved for at its height (Newton's step, which it chose). The corrections below need
     * the working rows between elements on the Schur path. */
    const int pred = c->pred_ok && z == c->pred_z && x == c->pred_x;
    if (!c->base_ok || !c->use_schur || f0 > f1 || a > b ||
        !(pred || (fabs(dz) <= upd_dz_max && !c->base_pins)))
        return 0;
    /* Every ray that meets the ground, and every vertex row, within the base's span: w
     * beyond it is the free chains', which no row held at the base. */
    const size_t o0 = f0 <= b ? f0 : b + 1, o1 = f1 + 1 > a ? f1 + 1 : a; /* [a, o0), [o1, b] */
    if ((o0 > a && any_positive(d + a, o0 - a)) || (o1 <= b && any_positive(d + o1, b + 1 - o1)))
        return 0;
    if (tirenv_springs__cc_vertex_rows(c, T, p, x, z, a, b, d))
        return 0;
    const tirenv_springs__cc_row *V = c->vrows;
    const size_t nv = c->n_vrows;
    if (nv > 0 && (V[0].i < f0 || V[nv - 1].j > f1)) /* in order of vertex, hence of sector */
        return 0;
    /* w and pe are made in place (copies into them cost some 220 instructions an update): a
     * refused update leaves them to the full evaluation that follows, which writes both over
     * its span before it reads them (the tips are read only over the span of the evaluation
     * that gave them) */
    const double *ph = own_rows(c, d, a > f0 ? a : f0, b < f1 ? b : f1);
    if (!held_at(c, ph, w, pred, dz, dw))
        return 0;
    upd_rows R;
    upd_check k;
    if (!rows_at(c, T, pred, dz, &R) || !settle(c, T, ph, w, pe, &R, pred, &k) ||
        !reactions_hold(c, pe, &k) || !others_hold(c, T, w, R.n))
        return 0;
    accept(c, T, ph, obstacle, w, pe, &R, k.n_c, contacts);
    return 1;
}
