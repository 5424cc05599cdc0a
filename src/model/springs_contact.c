/* SPDX-License-Identifier: Apache-2.0 */
/* Continuous contact of the springs model (docs/models.md section 4.8): a tread between the
 * elements that meets every ground vertex, the tip problem as a QP whose rows couple
 * neighbouring elements, solved exactly by a primal active-set method. */
#include "model/springs_impl.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "profile/profile_impl.h"

int tirenv_springs__cc_init(tirenv_springs__cc *c, size_t N)
{
    memset(c, 0, sizeof *c);
    size_t **sz[] = {&c->pin_row, &c->sec_first, &c->sec_count, &c->wpos, &c->pin_src,
                     &c->cand_first, &c->cand_count, &c->hull_sec, &c->held};
    for (size_t k = 0; k < sizeof sz / sizeof sz[0]; ++k)
        if (!(*sz[k] = calloc(N + 1, sizeof **sz[k])))
            return TIRENV_ENOMEM;
    double **dbl[] = {&c->pin_h, &c->w_try, &c->step, &c->raise, &c->tri_piv, &c->tri_mul};
    for (size_t k = 0; k < sizeof dbl / sizeof dbl[0]; ++k)
        if (!(*dbl[k] = calloc(N + 2, sizeof **dbl[k])))
            return TIRENV_ENOMEM;
    if (!(c->warm_pin = calloc(N, 1)))
        return TIRENV_ENOMEM;
    if (!(c->chains = calloc(N + 2, sizeof *c->chains))) /* at most (N + 1) / 2 chains */
        return TIRENV_ENOMEM;
    if (!(c->tri_y = calloc(TIRENV_SPRINGS__SCHUR_MAX * (N + 2), sizeof *c->tri_y)))
        return TIRENV_ENOMEM;
    if (!(c->base_w = calloc(N + 2, sizeof *c->base_w)) ||
        !(c->upd_w = calloc(N + 2, sizeof *c->upd_w)) ||
        !(c->upd_pin = calloc(N, sizeof *c->upd_pin)) ||
        !(c->pred_w = calloc(N + 2, sizeof *c->pred_w)) ||
        !(c->root_y = calloc(2 * (N + 2), sizeof *c->root_y)) ||
        !(c->root_du = calloc(N + 2, sizeof *c->root_du)) ||
        !(c->root_v = calloc(N + 2, sizeof *c->root_v)))
        return TIRENV_ENOMEM;
    c->f0 = 1;
    c->f1 = 0;
    c->tri_ok = 0;
    c->root_v_at = (unsigned long long)-1; /* no K_FF^-1 f yet */
    c->mend_at = (unsigned long long)-2;   /* (nor a flip) */
    c->cols.at = (unsigned long long)-1; /* no rows' columns yet */
    return TIRENV_OK;
}

void tirenv_springs__cc_free(tirenv_springs__cc *c)
{
    free(c->rows);
    free(c->vrows);
    free(c->seen);
    free(c->seen_sec);
    free(c->seen_todo);
    free(c->in_w);
    free(c->lambda);
    free(c->order);
    free(c->env_first);
    free(c->env_last);
    free(c->pos);
    free(c->band);
    free(c->rhs);
    free(c->pin_row);
    free(c->sec_first);
    free(c->sec_count);
    free(c->wpos);
    free(c->pin_src);
    free(c->cand_first);
    free(c->cand_count);
    free(c->hull_sec);
    free(c->held);
    free(c->vforce);
    free(c->pin_h);
    free(c->w_try);
    free(c->step);
    free(c->raise);
    free(c->tri_piv);
    free(c->tri_mul);
    free(c->tri_y);
    free(c->chains);
    free(c->warm_ids);
    free(c->warm_pin);
    free(c->keys);
    free(c->last_keys);
    free(c->base_w);
    free(c->upd_w);
    free(c->upd_pin);
    free(c->dlambda);
    free(c->pred_w);
    free(c->root_y);
    free(c->root_du);
    free(c->root_v);
    memset(c, 0, sizeof *c);
}

void tirenv_springs__cc_forget(tirenv_springs__cc *c)
{
    c->n_warm = 0;
    c->n_rows = 0;
    c->f0 = 1;
    c->f1 = 0;
    c->between = 0;
    c->last_ok = 0;
    c->base_ok = 0;
    c->pred_ok = 0;
}

/* ga w_i + gb w_j - h: the slack at w of a row not working, m (its reaction is 0, so its own
 * compliance adds nothing). */
static double slack(const tirenv_springs__cc_row *r, const double w[])
{
    return r->t > 0 ? r->ga * w[r->i] + r->gb * w[r->j] - r->h : w[r->i] - r->h;
}

/* The KKT system of the working set on the unknowns left once the held elements are
 * eliminated: w_e of the free elements in [f0, f1], each followed by the rows of sector e - 1
 * in the working set (whose free elements then precede them), in the symmetric form
 * [K G^T; G -C] [w; mu] = [.; .], mu = -lambda, C the rows' own compliances (diagonal,
 * >= 0; 0 on an element's row). Every row follows the unknowns it couples, so
 * with K positive definite and the rows independent every leading block is nonsingular and
 * LDL^T needs no pivoting (w pivots > 0, row pivots < 0). same_layout: the rows and the
 * working set are the last layout's (cc_solve found them so), so that only the values are
 * new where the Schur path's factor is kept. Returns 1 if a pivot shows the rows dependent
 * (a row on held elements only, among others), -1 out of memory. */
static int kkt_factor(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T, int same_layout,
                      double wq[])
{
    const size_t f0 = c->f0, f1 = c->f1, N = T->N;
    size_t n = 0, n_schur = 0;
    /* wpos still marks the held elements of the last layout: the same span and held
     * elements give the same K_FF, whose factor the Schur path then keeps */
    int same = c->tri_ok && c->tri_f0 == f0 && c->tri_f1 == f1;
    if (same_layout && c->use_schur && same) {
        /* wpos, order, schur_pos and the chains stand; only the values are new. */
        const size_t *wpos = c->wpos;
        const double *pin_h = c->pin_h;
        for (size_t e = f0; e <= f1; ++e)
            wq[e] = wpos[e] == SIZE_MAX ? pin_h[e] : 0;
        return tirenv_springs__cc_schur_factor(c, T, 1);
    }
    /* the workspace's arrays in locals (the stores would make them be read again); the
     * sectors with rows are those in hull_sec (ascending), so the others are not looked at */
    size_t *wpos = c->wpos, *order = c->order;
    const size_t *pin_row = c->pin_row, *hull_sec = c->hull_sec, n_hull = c->n_hull_sec;
    const unsigned char *in_w = c->in_w;
    const double *pin_h = c->pin_h;
    size_t *held_e = c->held, n_held = 0;
    size_t hq = 0;
    while (hq < n_hull && hull_sec[hq] < f0)
        ++hq;
    /* the elements up to the next sector with rows (hull_sec[hq] = s: its working rows
     * after element s + 1, the last they couple), then those rows, and on */
    for (size_t e = f0;;) {
        const int sec = hq < n_hull && hull_sec[hq] + 1 <= f1;
        const size_t stop = sec ? hull_sec[hq] + 1 : f1;
        for (; e <= stop; ++e) {
            const size_t pr = pin_row[e]; /* held by its own row in the working set */
            const int held = pr != SIZE_MAX && in_w[pr];
            same &= held == (wpos[e] == SIZE_MAX);
            if (held) {
                wpos[e] = SIZE_MAX;
                wq[e] = pin_h[e];
                held_e[n_held++] = e;
            } else {
                wpos[e] = n;
                order[n++] = e;
                wq[e] = 0;
            }
        }
        if (!sec)
            break;
        const size_t s = hull_sec[hq++];
        for (size_t r = c->sec_first[s], k = 0; k < c->sec_count[s]; ++k, ++r)
            if (in_w[r]) {
                if (n_schur < TIRENV_SPRINGS__SCHUR_MAX)
                    c->schur_pos[n_schur] = n;
                ++n_schur;
                order[n++] = N + r;
            }
    }
    c->n_kkt = n;
    c->n_held = n_held;
    c->n_schur = n_schur;
    c->use_schur = n_schur <= TIRENV_SPRINGS__SCHUR_MAX;
    if (c->use_schur)
        return tirenv_springs__cc_schur_factor(c, T, same);
    c->tri_ok = 0; /* wpos no longer describes the factor kept */
    /* The band's half-width, for the banded path only: how far each unknown's row reaches
     * back, an element to its free left neighbour, a row (of sector i, laid out after
     * element i + 1) to the first free element of the two it couples. */
    size_t bw = 1;
    for (size_t p = 0; p < n; ++p) {
        const size_t u = c->order[p];
        size_t low;
        if (u < N) {
            low = u > f0 ? c->wpos[u - 1] : SIZE_MAX;
        } else {
            const size_t i = c->rows[u - N].i;
            low = c->wpos[i] != SIZE_MAX ? c->wpos[i] : c->wpos[i + 1];
        }
        if (low != SIZE_MAX && p - low > bw)
            bw = p - low;
    }
    const size_t W = bw + 1;
    if (n * W > c->cap_band) {
        double *band = realloc(c->band, n * W * sizeof *band);
        if (!band)
            return -1;
        c->band = band;
        c->cap_band = n * W;
    }
    c->n_kkt = n;
    c->bw = bw;
    double *L = c->band;
    memset(L, 0, n * W * sizeof *L);
#define AT(p, q) L[(p) * W + ((p) - (q))]
    size_t *first = c->env_first, *last = c->env_last;
    for (size_t e = f0; e <= f1; ++e) {
        if (c->wpos[e] == SIZE_MAX)
            continue;
        const double k_ee = tirenv_springs__cc_k_diag(T, f0, f1, e);
        const size_t p = c->wpos[e];
        AT(p, p) = k_ee;
        first[p] = p;
        if (e > f0 && c->wpos[e - 1] != SIZE_MAX) {
            AT(p, c->wpos[e - 1]) = -T->k_ir;
            first[p] = c->wpos[e - 1];
        }
    }
    for (size_t p = 0; p < n; ++p) {
        if (c->order[p] < N)
            continue;
        const tirenv_springs__cc_row *r = &c->rows[c->order[p] - N];
        first[p] = p;
        AT(p, p) = -r->cmp; /* G w - C mu = h, mu = -lambda: the row's own compliance */
        if (c->wpos[r->i] != SIZE_MAX) {
            AT(p, c->wpos[r->i]) = r->ga;
            first[p] = c->wpos[r->i];
        }
        if (r->t > 0 && c->wpos[r->j] != SIZE_MAX) {
            AT(p, c->wpos[r->j]) = r->gb;
            first[p] = c->wpos[r->j] < first[p] ? c->wpos[r->j] : first[p];
        }
    }
    /* The envelope (skyline) of the band: LDL^T fills no entry of a row before its first
     * nonzero, so each row's loops start there; the entries skipped are exact zeros, which
     * leaves every sum as the full band's. last[q]: the last row p with first[p] <= q (the
     * suffix minimum of first is nondecreasing, so one sweep finds it). */
    for (size_t p = n, m = SIZE_MAX, q = n; p-- > 0;) {
        m = first[p] < m ? first[p] : m; /* min of first[p..n-1] */
        while (q > m)
            last[--q] = p;
    }
    const double k_max = T->k_r + 2 * T->k_ir;
    for (size_t p = 0; p < n; ++p) {
        const size_t lo = first[p];
        double *Lp = L + p * W;
        for (size_t q = lo; q <= p; ++q) {
            const double *Lq = L + q * W;
            double s = Lp[p - q];
            const size_t klo = first[q] > lo ? first[q] : lo;
            for (size_t k = klo; k < q; ++k)
                s -= Lp[p - k] * Lq[q - k] * L[k * W];
            if (q < p)
                Lp[p - q] = s / Lq[0];
            else
                Lp[0] = s;
        }
        const double D = Lp[0];
        if (c->order[p] < N ? !(D > 0) : !(D < -1e-14 / k_max))
            return 1;
    }
    return 0;
}

/* Solves the banded factored system for b (length n_kkt) in place (the Schur path solves
 * by element, tirenv_springs__cc_schur_solve_at). */
static void kkt_solve(const tirenv_springs__cc *c, double b[])
{
    const size_t n = c->n_kkt, bw = c->bw, W = bw + 1;
    const double *L = c->band;
    const size_t *first = c->env_first, *last = c->env_last;
    for (size_t p = 0; p < n; ++p) {
        const size_t lo = first[p];
        const double *Lp = L + p * W;
        double s = b[p];
        for (size_t k = lo; k < p; ++k)
            s -= Lp[p - k] * b[k];
        b[p] = s;
    }
    for (size_t p = 0; p < n; ++p)
        b[p] /= L[p * W];
    for (size_t p = n; p-- > 0;) {
        const size_t hi = last[p]; /* rows past it have a zero in column p */
        double s = b[p];
        for (size_t k = p + 1; k <= hi; ++k)
            s -= AT(k, p) * b[k];
        b[p] = s;
    }
#undef AT
}

/* The right-hand side of the reduced banded system for held values v (v[e] on held
 * elements) and w-part and row-part sources: w-part k_ir v of held neighbours, row-part
 * less the held elements' share (schur_rhs on the Schur path). */
static void reduced_rhs(const tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                        const double v[], double b[])
{
    const size_t N = T->N, f0 = c->f0, f1 = c->f1;
    for (size_t p = 0; p < c->n_kkt; ++p) {
        const size_t u = c->order[p];
        if (u < N) {
            if (u > f0 && c->wpos[u - 1] == SIZE_MAX)
                b[p] += T->k_ir * v[u - 1];
            if (u < f1 && c->wpos[u + 1] == SIZE_MAX)
                b[p] += T->k_ir * v[u + 1];
        } else {
            const tirenv_springs__cc_row *r = &c->rows[u - N];
            if (c->wpos[r->i] == SIZE_MAX)
                b[p] -= r->ga * v[r->i];
            if (r->t > 0 && c->wpos[r->j] == SIZE_MAX)
                b[p] -= r->gb * v[r->j];
        }
    }
}

/* The right-hand side on the Schur path, by element: x[e] (free elements) plus k_ir v of
 * held neighbours (a free element next to a held one ends a chain), lam[q] (the q-th
 * working row between elements) less the held elements' share. */
static void schur_rhs(const tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                      const double v[], double x[], double lam[])
{
    const size_t N = T->N, f0 = c->f0, f1 = c->f1;
    for (size_t q = 0; q < c->n_chains; ++q) {
        const size_t lo = c->chains[2 * q], hi = c->chains[2 * q + 1];
        if (lo > f0)
            x[lo] += T->k_ir * v[lo - 1];
        if (hi < f1)
            x[hi] += T->k_ir * v[hi + 1];
    }
    for (size_t q = 0; q < c->n_schur; ++q) {
        const tirenv_springs__cc_row *r = &c->rows[c->order[c->schur_pos[q]] - N];
        if (c->wpos[r->i] == SIZE_MAX)
            lam[q] -= r->ga * v[r->i];
        if (r->t > 0 && c->wpos[r->j] == SIZE_MAX)
            lam[q] -= r->gb * v[r->j];
    }
}

/* The minimiser of 1/2 w^T K w on the working set's rows as equalities: w into wq[f0..f1],
 * the rows' reactions into lambda (a held element's own row's from its equation of K w =
 * G^T lambda); same_layout as for kkt_factor. 1 if the rows are dependent, -1 out of
 * memory. */
static int eqp(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T, double wq[],
               int same_layout)
{
    /* kkt_factor writes wq: the held elements' w, their own row's h (which the layout made
     * pin_h: a ray's row takes it, a vertex's gave it), 0 on the free ones (the Schur path's
     * right-hand side there; the banded path reads wq on the held elements alone, and writes
     * the free ones), in its pass deciding which are held where it makes one (a pass of its
     * own cost some 650 instructions an equality problem) */
    const int st = kkt_factor(c, T, same_layout, wq);
    if (st)
        return st;
    const size_t N = T->N, f0 = c->f0, f1 = c->f1;
    double *b = c->rhs;
    if (c->use_schur) {
        /* By element, not in the KKT order (the free elements' entries of wq, the rows'
         * in lam). */
        double lam[TIRENV_SPRINGS__SCHUR_MAX];
        for (size_t q = 0; q < c->n_schur; ++q)
            lam[q] = c->rows[c->order[c->schur_pos[q]] - N].h;
        schur_rhs(c, T, wq, wq, lam);
        tirenv_springs__cc_schur_solve_at(c, T, wq, lam);
        for (size_t q = 0; q < c->n_schur; ++q)
            c->lambda[c->order[c->schur_pos[q]] - N] = lam[q];
    } else {
        for (size_t p = 0; p < c->n_kkt; ++p)
            b[p] = c->order[p] < N ? 0 : c->rows[c->order[p] - N].h;
        reduced_rhs(c, T, wq, b);
        kkt_solve(c, b);
        for (size_t p = 0; p < c->n_kkt; ++p) {
            if (c->order[p] < N)
                wq[c->order[p]] = b[p];
            else
                c->lambda[c->order[p] - N] = -b[p];
        }
    }
    /* The held elements' reactions: (K w)_e less what the working rows between elements
     * put on e (sectors e - 1 and e, in that order). The workspace's arrays in locals: the
     * stores to lambda would make them be read again at every element. K w first, the ends
     * of the span apart (the free chains beyond folded into their diagonal), so that the
     * loop over the others tests nothing but whether e is held; then the rows, sector by
     * sector (only those in hull_sec have any), each subtracted from what the first pass
     * stored: the operations, and their order for each element, are the ones a single pass
     * makes, so the same bits. */
    const size_t *wpos = c->wpos, *pin_row = c->pin_row;
    const unsigned char *in_w = c->in_w;
    const tirenv_springs__cc_row *rows = c->rows;
    const double *diag = T->diag, k_ir = T->k_ir;
    double *lambda = c->lambda;
    if (wpos[f0] == SIZE_MAX) {
        double k_ee = diag[f0];
        if (f0 > 0)
            k_ee -= k_ir * T->lq[f0 - 1];
        if (f0 == f1 && f1 + 1 < N)
            k_ee -= k_ir * T->rq[f1 + 1];
        double Kw = k_ee * wq[f0];
        if (f0 < f1)
            Kw -= k_ir * wq[f0 + 1];
        lambda[pin_row[f0]] = Kw;
    }
    /* the held elements inside the span, from kkt_factor's list (no look at the free ones) */
    const size_t *held_e = c->held;
    size_t h0 = 0, h1 = c->n_held;
    if (h0 < h1 && held_e[h0] == f0)
        ++h0;
    if (h1 > h0 && held_e[h1 - 1] == f1)
        --h1;
    for (size_t k = h0; k < h1; ++k) {
        const size_t e = held_e[k];
        double Kw = diag[e] * wq[e];
        Kw -= k_ir * wq[e - 1];
        Kw -= k_ir * wq[e + 1];
        lambda[pin_row[e]] = Kw;
    }
    if (f1 > f0 && wpos[f1] == SIZE_MAX) {
        double k_ee = diag[f1];
        if (f1 + 1 < N)
            k_ee -= k_ir * T->rq[f1 + 1];
        double Kw = k_ee * wq[f1];
        Kw -= k_ir * wq[f1 - 1];
        lambda[pin_row[f1]] = Kw;
    }
    const size_t *sec_first = c->sec_first, *sec_count = c->sec_count;
    for (size_t q = 0; q < c->n_hull_sec; ++q) {
        const size_t e = c->hull_sec[q]; /* sector e: element e's sector e, e + 1's e - 1 */
        const size_t r0 = sec_first[e], r1 = r0 + sec_count[e];
        if (e + 1 > f0 && e + 1 <= f1 && wpos[e + 1] == SIZE_MAX) {
            double *l = &lambda[pin_row[e + 1]];
            for (size_t r = r0; r < r1; ++r)
                if (in_w[r])
                    *l -= rows[r].gb * lambda[r];
        }
        if (e >= f0 && e < f1 && wpos[e] == SIZE_MAX) {
            double *l = &lambda[pin_row[e]];
            for (size_t r = r0; r < r1; ++r)
                if (in_w[r])
                    *l -= rows[r].ga * lambda[r];
        }
    }
    return 0;
}

int tirenv_springs__long_in(const long *v, size_t n, long key)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (v[mid] < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < n && v[lo] == key;
}

/* The warm start's working set: the last solution's, where it still names rows here. */
static void warm_set(tirenv_springs__cc *c)
{
    /* in locals: the byte stores to in_w would make c's fields be read again at every row */
    const tirenv_springs__cc_row *rows = c->rows;
    unsigned char *in_w = c->in_w;
    const unsigned char *warm_pin = c->warm_pin;
    const long *warm_ids = c->warm_ids;
    const size_t n_rows = c->n_rows, n_warm = c->n_warm;
    for (size_t r = 0; r < n_rows; ++r) {
        const tirenv_springs__cc_row *R = &rows[r];
        in_w[r] = R->t == 0 ? warm_pin[R->i] : tirenv_springs__long_in(warm_ids, n_warm, R->id);
    }
}

/* Room in warm_ids for every row (the solve's last pass over the rows fills it,
 * with no count before). */
static int reserve_warm(tirenv_springs__cc *c)
{
    if (c->n_rows <= c->cap_warm)
        return TIRENV_OK;
    long *ids = realloc(c->warm_ids, c->n_rows * sizeof *ids);
    if (!ids)
        return TIRENV_ENOMEM;
    c->warm_ids = ids;
    c->cap_warm = c->n_rows;
    return TIRENV_OK;
}

/* Whether the rows are the last solve's, laid out the same (and over the same span). */
static int same_as_last(const tirenv_springs__cc *c)
{
    return c->n_rows == c->n_last && c->f0 == c->last_f0 && c->f1 == c->last_f1 &&
           !memcmp(c->keys, c->last_keys, c->n_rows * sizeof *c->keys);
}

/* Records the rows and span of the solve just finished: its keys become the last (the
 * buffers swap; the next layout writes the other). */
static void keep_last(tirenv_springs__cc *c)
{
    tirenv_springs__cc_key *k = c->last_keys;
    c->last_keys = c->keys;
    c->keys = k;
    c->n_last = c->n_rows;
    c->last_f0 = c->f0;
    c->last_f1 = c->f1;
    c->last_ok = 1;
}

int tirenv_springs__cc_pins_hold(const tirenv_springs__cc *c, const double w[], double tol)
{
    for (size_t r = 0; r < c->n_rows; ++r)
        if (c->rows[r].t > 0 && slack(&c->rows[r], w) < -tol)
            return 0;
    return 1;
}

/* The active-set method's feasible start, into c->w_try: the last working set's minimiser, if
 * the rows are independent; raised where rows are violated (rows have weights >= 0, so
 * raising w satisfies them), which keeps the working set's rows that are still tight. Else a
 * cold start from w_e = the largest h of a row on e, which satisfies every row, with no row
 * working. *at_min where the start is its working set's minimiser; -1 out of memory. */
static int qp_start(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T, int same_rows,
                    int *at_min)
{
    const size_t f0 = c->f0, f1 = c->f1, n_rows = c->n_rows;
    const double tol = 1e-12 * T->R0;
    double *wc = c->w_try, *wq = c->step, *raise = c->raise;
    if (!same_rows) /* else in_w holds the last final set, which warm_set would give */
        warm_set(c);
    *at_min = 0;
    const int st = eqp(c, T, wq, same_rows);
    if (st < 0)
        return -1;
    if (st == 0) {
        /* Usually no row is violated (the same working set as the last evaluation's, a step
         * away): then wc = wq, and raise is not needed. */
        int violated = 0;
        {
            const unsigned char *in_w = c->in_w;
            const tirenv_springs__cc_row *rows = c->rows;
            for (size_t r = 0; r < n_rows; ++r)
                if (!in_w[r] && slack(&rows[r], wq) < -tol) {
                    violated = 1;
                    break;
                }
        }
        if (violated) {
            for (size_t e = f0; e <= f1; ++e)
                raise[e] = 0;
            for (size_t r = 0; r < n_rows; ++r) {
                const double s = slack(&c->rows[r], wq);
                if (!c->in_w[r] && s < -tol) {
                    const tirenv_springs__cc_row *R = &c->rows[r];
                    raise[R->i] = fmax(raise[R->i], -s);
                    if (R->t > 0)
                        raise[R->j] = fmax(raise[R->j], -s);
                }
            }
        }
        /* A working row whose tip is raised leaves the set. With its own compliance it
         * stood below its h (G w = h - c*lambda), so it is raised onto its row as well, which
         * may release further rows: until every released row holds (raising only lifts the
         * tread, so no row that holds stops holding; each pass releases a row or ends). */
        for (int more = violated; more;) {
            more = 0;
            for (size_t r = 0; r < n_rows; ++r) {
                const tirenv_springs__cc_row *R = &c->rows[r];
                if (!c->in_w[r] || !(raise[R->i] > 0 || (R->t > 0 && raise[R->j] > 0)))
                    continue;
                c->in_w[r] = 0;
                const double s = R->t > 0 ? R->ga * (wq[R->i] + raise[R->i]) +
                                                R->gb * (wq[R->j] + raise[R->j]) - R->h
                                          : wq[R->i] + raise[R->i] - R->h;
                if (s < -tol) { /* the weights sum to >= 1: -s on both tips lifts it by >= -s */
                    raise[R->i] -= s;
                    if (R->t > 0)
                        raise[R->j] -= s;
                    more = 1;
                }
            }
        }
        for (size_t e = f0; e <= f1; ++e) /* + 0 when nothing is raised: as wq + raise */
            wc[e] = violated ? wq[e] + raise[e] : wq[e] + 0.0;
        if (!violated)
            *at_min = 1;
    } else {
        for (size_t e = f0; e <= f1; ++e)
            wc[e] = 0;
        for (size_t r = 0; r < n_rows; ++r) {
            const tirenv_springs__cc_row *R = &c->rows[r];
            c->in_w[r] = 0;
            wc[R->i] = fmax(wc[R->i], R->h);
            if (R->t > 0)
                wc[R->j] = fmax(wc[R->j], R->h);
        }
    }
    return 0;
}

/* The primal active-set method (Nocedal and Wright, Algorithm 16.3) from the feasible start
 * in c->w_try (at_min: its working set's minimiser): step to the working set's minimiser or
 * to the first row in the way (which joins the set: independent of it, since the step keeps
 * its rows); at the minimiser, release the row with the most negative reaction, or stop:
 * every reaction >= 0. Finite without cycling for a strictly convex QP whose steps are not
 * degenerate. The steps into c->iterations. */
static int qp_iterate(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T, double x,
                      double z, int at_min, tirenv_diag *diag)
{
    const size_t f0 = c->f0, f1 = c->f1, n_rows = c->n_rows;
    double *wc = c->w_try, *wq = c->step, *raise = c->raise;
    const size_t max_iter = 3 * n_rows + 10;
    size_t it = 0;
    for (;; ++it) {
        if (it >= max_iter)
            return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "ELEMENT_ANGLE",
                                "the continuous tip contact (%zu rows on elements %zu to "
                                "%zu) did not settle in %zu active-set steps at x = %.9g m, "
                                "z = %.9g m", n_rows, f0, f1, max_iter, x, z);
        if (!at_min) {
            const int st = eqp(c, T, wq, 0);
            if (st)
                return tirenv_error(diag, st < 0 ? TIRENV_ENOMEM : TIRENV_ENOCONV, "", 0,
                                    "ELEMENT_ANGLE",
                                    "the continuous tip contact at x = %.9g m, z = %.9g m met "
                                    "dependent rows (%zu rows on elements %zu to %zu)", x, z,
                                    n_rows, f0, f1);
            double alpha = 1;
            size_t block = SIZE_MAX;
            for (size_t e = f0; e <= f1; ++e)
                raise[e] = wq[e] - wc[e]; /* the step */
            for (size_t r = 0; r < n_rows; ++r) {
                if (c->in_w[r])
                    continue;
                const tirenv_springs__cc_row *R = &c->rows[r];
                const double gp = R->t > 0 ? R->ga * raise[R->i] + R->gb * raise[R->j]
                                           : raise[R->i];
                if (!(gp < 0))
                    continue;
                const double s = fmax(slack(R, wc), 0), ar = s / -gp;
                if (ar < alpha) {
                    alpha = ar;
                    block = r;
                }
            }
            if (block == SIZE_MAX) {
                for (size_t e = f0; e <= f1; ++e)
                    wc[e] = wq[e];
                at_min = 1;
            } else {
                for (size_t e = f0; e <= f1; ++e)
                    wc[e] += alpha * raise[e];
                c->in_w[block] = 1;
                continue;
            }
        }
        /* At the working set's minimiser: the reactions decide. */
        double l_min = 0, l_max = 0;
        size_t drop = SIZE_MAX;
        const unsigned char *in_w = c->in_w;
        const double *lambda = c->lambda;
        for (size_t r = 0; r < n_rows; ++r) {
            if (!in_w[r])
                continue;
            const double l = lambda[r], m = fabs(l);
            if (m > l_max) /* fmax(l_max, |l|) but for a NaN, which fmax skips too */
                l_max = m;
            if (l < l_min) {
                l_min = l;
                drop = r;
            }
        }
        if (drop == SIZE_MAX || l_min >= -1e-12 * l_max)
            break;
        c->in_w[drop] = 0;
        at_min = 0;
    }
    c->iterations = it + 1;
    return TIRENV_OK;
}

/* The solution as the model takes it: w, pe = +0 and obstacle = pin_h, which is >= 0 and
 * never -0 or NaN (the rays' d > 0, else +0, or a higher vertex's h): what max(pin_h, 0)
 * gives, copied. Then one pass: the rows out of the set get no reaction, the others load
 * their tips (a row with no reaction would add 0, which leaves pe as it is: pe starts at +0
 * and no sum of nonzero terms gives -0), and the final set is kept for the next solve's warm
 * start. */
static void qp_keep(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T, double w[],
                    double pe[], double obstacle[])
{
    const size_t N = T->N, f0 = c->f0, f1 = c->f1, n_rows = c->n_rows;
    const size_t n_span = f1 - f0 + 1;
    memcpy(w + f0, c->w_try + f0, n_span * sizeof *w);
    memset(pe + f0, 0, n_span * sizeof *pe);
    memcpy(obstacle + f0, c->pin_h + f0, n_span * sizeof *obstacle);
    memset(c->warm_pin, 0, N);
    size_t n_warm = 0;
    /* The workspace's arrays in locals: the stores to pe and lambda would make them be
     * read again at every row. */
    const tirenv_springs__cc_row *rows = c->rows;
    const unsigned char *in_w = c->in_w;
    double *lambda = c->lambda;
    /* the final set kept for the warm start here, not in a function reading c (the byte
     * stores to warm_pin would make c's fields be read again at every row) */
    unsigned char *warm_pin = c->warm_pin;
    long *warm_ids = c->warm_ids;
    size_t held_vertex = 0;
    for (size_t r = 0; r < n_rows; ++r) {
        const tirenv_springs__cc_row *R = &rows[r];
        if (!in_w[r]) {
            lambda[r] = 0;
            continue;
        }
        if (R->t > 0) {
            const long id = R->id; /* into warm_ids, kept ascending */
            size_t m = n_warm++;
            while (m > 0 && warm_ids[m - 1] > id) {
                warm_ids[m] = warm_ids[m - 1];
                --m;
            }
            warm_ids[m] = id;
            pe[R->i] += R->ga * lambda[r];
            pe[R->j] += R->gb * lambda[r];
        } else {
            warm_pin[R->i] = 1;
            held_vertex += R->id >= 0;
            pe[R->i] += lambda[r];
        }
    }
    c->n_warm = n_warm;
    c->held_vertex = held_vertex;
    keep_last(c);
    w[(long)f0 - 1] = f0 > 0 ? T->lq[f0 - 1] * w[f0] : 0;
    w[f1 + 1] = f1 + 1 < N ? T->rq[f1 + 1] * w[f1] : 0;
}

/* The QP on the rows laid out (tirenv_springs__cc_solve without the check of the rows the
 * hulls dropped). */
static int qp_solve(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T, double x,
                    double z, double w[], double pe[], double obstacle[], tirenv_diag *diag)
{
    c->iterations = 0;
    const int same_rows = c->last_ok && same_as_last(c);
    c->last_ok = 0;
    if (c->f0 > c->f1) {
        c->n_warm = 0;
        memset(c->warm_pin, 0, T->N);
        return TIRENV_OK;
    }
    int at_min;
    if (qp_start(c, T, same_rows, &at_min) < 0)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for the contact "
                            "of the springs model");
    const int st = qp_iterate(c, T, x, z, at_min, diag);
    if (st)
        return st;
    if (reserve_warm(c))
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for the contact "
                            "of the springs model");
    qp_keep(c, T, w, pe, obstacle);
    return TIRENV_OK;
}

/* The QP on the rows laid out, then on those and every row the hulls dropped that its
 * solution violates, until none does (an outer active-set pass: each round adds a row, so
 * it ends; nearly always none is violated and one solve does). The rows dropped and never
 * added hold at the final w with reaction 0, so it solves the QP of every row. */
int tirenv_springs__cc_solve(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                             double x, double z, double w[], double pe[], double obstacle[],
                             tirenv_diag *diag)
{
    for (;;) {
        const int st = qp_solve(c, T, x, z, w, pe, obstacle, diag);
        if (st || c->f0 > c->f1 || !tirenv_springs__cc_add_dropped(c, w, 1e-12 * T->R0))
            return st;
    }
}

/* Room for a d(lambda)/dz per row. */
static int reserve_dl(tirenv_springs__cc *c)
{
    if (c->n_rows <= c->cap_dl)
        return TIRENV_OK;
    double **arr[] = {&c->dlambda};
    for (size_t k = 0; k < sizeof arr / sizeof arr[0]; ++k) {
        double *v = realloc(*arr[k], c->n_rows * sizeof *v);
        if (!v)
            return TIRENV_ENOMEM;
        *arr[k] = v;
    }
    c->cap_dl = c->n_rows;
    return TIRENV_OK;
}

int tirenv_springs__cc_slope(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                             const double w[], const double dd[], double dw[])
{
    const size_t N = T->N, f0 = c->f0, f1 = c->f1;
    if (f0 > f1)
        return TIRENV_OK;
    const int room = reserve_dl(c) == TIRENV_OK;
    /* The factors are the working set's from the last eqp (the final set: the last solve
     * was at its minimiser). d/dz of K w = G^T lambda and of G w = h with the set fixed:
     * K dw - G^T dlambda = dG^T lambda, G dw = dh - dG w; a held element's dw is its row's
     * dh. */
    if (dd) { /* 0 on the free elements (as for eqp's wq); else the caller's */
        const size_t *wpos = c->wpos, *pin_row = c->pin_row;
        const tirenv_springs__cc_row *rows = c->rows;
        for (size_t e = f0; e <= f1; ++e) {
            if (wpos[e] == SIZE_MAX) {
                const tirenv_springs__cc_row *R = &rows[pin_row[e]];
                dw[e] = R->id < 0 ? dd[e] : R->dh_dz;
            } else {
                dw[e] = 0;
            }
        }
    }
    if (c->use_schur) { /* by element: the same sums as the banded path's below */
        double lam[TIRENV_SPRINGS__SCHUR_MAX];
        for (size_t q = 0; q < c->n_schur; ++q) {
            const size_t r = c->order[c->schur_pos[q]] - N;
            const tirenv_springs__cc_row *R = &c->rows[r];
            double rhs = R->id < 0 ? (dd ? dd[R->i] : dw[R->i]) : R->dh_dz;
            if (R->t > 0) {
                rhs -= R->dga_dz * w[R->i] + R->dgb_dz * w[R->j] + R->dcmp_dz * c->lambda[r];
                if (c->wpos[R->i] != SIZE_MAX)
                    dw[R->i] += R->dga_dz * c->lambda[r];
                if (c->wpos[R->j] != SIZE_MAX)
                    dw[R->j] += R->dgb_dz * c->lambda[r];
            }
            lam[q] = rhs;
        }
        schur_rhs(c, T, dw, dw, lam);
        tirenv_springs__cc_schur_solve_at(c, T, dw, lam);
        if (room)
            for (size_t q = 0; q < c->n_schur; ++q)
                c->dlambda[c->order[c->schur_pos[q]] - N] = lam[q];
        return room ? TIRENV_OK : TIRENV_ENOMEM;
    }
    double *b = c->rhs;
    for (size_t p = 0; p < c->n_kkt; ++p)
        b[p] = 0;
    for (size_t p = 0; p < c->n_kkt; ++p) {
        if (c->order[p] < N)
            continue;
        const size_t r = c->order[p] - N;
        const tirenv_springs__cc_row *R = &c->rows[r];
        double rhs = R->id < 0 ? (dd ? dd[R->i] : dw[R->i]) : R->dh_dz;
        if (R->t > 0) {
            rhs -= R->dga_dz * w[R->i] + R->dgb_dz * w[R->j] + R->dcmp_dz * c->lambda[r];
            if (c->wpos[R->i] != SIZE_MAX)
                b[c->wpos[R->i]] += R->dga_dz * c->lambda[r];
            if (c->wpos[R->j] != SIZE_MAX)
                b[c->wpos[R->j]] += R->dgb_dz * c->lambda[r];
        }
        b[p] = rhs;
    }
    reduced_rhs(c, T, dw, b);
    kkt_solve(c, b);
    for (size_t e = f0; e <= f1; ++e)
        if (c->wpos[e] != SIZE_MAX)
            dw[e] = b[c->wpos[e]];
    if (room) /* mu = -lambda */
        for (size_t p = 0; p < c->n_kkt; ++p)
            if (c->order[p] >= N)
                c->dlambda[c->order[p] - N] = -b[p];
    return room ? TIRENV_OK : TIRENV_ENOMEM;
}
