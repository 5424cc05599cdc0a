/* SPDX-License-Identifier: Apache-2.0 */
/* The KKT systems of the springs model's continuous contact (docs/models.md section 4.8) when
 * few rows between elements are working: the free elements' stiffness K_FF is tridiagonal
 * (the held elements split it into chains), so it is factorised by the Thomas algorithm and
 * the working rows G between elements enter through their Schur complement S = G K_FF^-1 G^T,
 * a k x k matrix for k rows (k <= TIRENV_SPRINGS__SCHUR_MAX, usually 1). O(n k) for n free
 * elements, against the banded LDL^T's O(n bw^2) with its index work. */
#include "model/springs_impl.h"

#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* x := K_FF^-1 x on one chain [lo, hi] of free elements, x zero on [lo, from): the forward
 * elimination leaves those zeros as they are (x - mul 0 = +0), so it starts at from. */
static void chain_solve_from(const tirenv_springs__cc *c, double x[], size_t lo, size_t from,
                             size_t hi)
{
    const double *piv = c->tri_piv, *mul = c->tri_mul;
    for (size_t e = from + 1; e <= hi; ++e)
        x[e] -= mul[e] * x[e - 1];
    x[hi] = x[hi] / piv[hi];
    for (size_t e = hi; e-- > lo;)
        x[e] = x[e] / piv[e] - mul[e + 1] * x[e + 1];
}

void tirenv_springs__cc_chain_solve(const tirenv_springs__cc *c, double x[], size_t lo,
                                    size_t from, size_t hi)
{
    chain_solve_from(c, x, lo, from, hi);
}

/* x := K_FF^-1 x on one chain [lo, hi] of free elements (held or outside the span at both
 * ends): K_FF does not couple across a held element. */
static void chain_solve(const tirenv_springs__cc *c, double x[], size_t lo, size_t hi)
{
    chain_solve_from(c, x, lo, lo, hi);
}

/* x1 := K_FF^-1 x1 on chain [lo1, hi1] and x2 := K_FF^-1 x2 on chain [lo2, hi2] at once,
 * each x zero on [lo, from): each chain's operations are chain_solve_from's, in its order, so
 * its bits; the two recurrences interleaved, since each is bound by its latency (a
 * multiplication and a subtraction an element, each way), not by the instructions. x1 and x2
 * are one array on two chains apart, or two arrays on any chains (two columns on one). The
 * element just made is carried in a local (the stores to one would otherwise make the other's
 * be read again). */
static void chain_solve_pair(const tirenv_springs__cc *c, double x1[], size_t lo1,
                             size_t from1, size_t hi1, double x2[], size_t lo2, size_t from2,
                             size_t hi2)
{
    const double *mul = c->tri_mul, *piv = c->tri_piv;
    /* forward, from + 1 .. hi */
    {
        double *y1 = x1 + from1, *y2 = x2 + from2;
        const double *m1 = mul + from1, *m2 = mul + from2;
        const size_t n1 = hi1 - from1, n2 = hi2 - from2, n = n1 < n2 ? n1 : n2;
        double a = y1[0], b = y2[0];
        size_t k = 1;
        for (; k <= n; ++k) {
            a = y1[k] - m1[k] * a;
            b = y2[k] - m2[k] * b;
            y1[k] = a;
            y2[k] = b;
        }
        for (size_t j = k; j <= n1; ++j)
            y1[j] = a = y1[j] - m1[j] * a;
        for (size_t j = k; j <= n2; ++j)
            y2[j] = b = y2[j] - m2[j] * b;
    }
    /* backward, hi .. lo */
    double *y1 = x1 + lo1, *y2 = x2 + lo2;
    const double *m1 = mul + lo1, *m2 = mul + lo2, *p1 = piv + lo1, *p2 = piv + lo2;
    const size_t n1 = hi1 - lo1, n2 = hi2 - lo2, n = n1 < n2 ? n1 : n2;
    double a, b;
    y1[n1] = a = y1[n1] / p1[n1];
    y2[n2] = b = y2[n2] / p2[n2];
    size_t k = 1;
    for (; k <= n; ++k) {
        a = y1[n1 - k] / p1[n1 - k] - m1[n1 - k + 1] * a;
        b = y2[n2 - k] / p2[n2 - k] - m2[n2 - k + 1] * b;
        y1[n1 - k] = a;
        y2[n2 - k] = b;
    }
    for (size_t j = k; j <= n1; ++j)
        y1[n1 - j] = a = y1[n1 - j] / p1[n1 - j] - m1[n1 - j + 1] * a;
    for (size_t j = k; j <= n2; ++j)
        y2[n2 - j] = b = y2[n2 - j] / p2[n2 - j] - m2[n2 - j + 1] * b;
}

void tirenv_springs__cc_chain_solve_pair(const tirenv_springs__cc *c, double x1[], size_t lo1,
                                         size_t from1, size_t hi1, double x2[], size_t lo2,
                                         size_t from2, size_t hi2)
{
    chain_solve_pair(c, x1, lo1, from1, hi1, x2, lo2, from2, hi2);
}

/* x, y and z := K_FF^-1 of each on one chain [lo, hi], x whole, y zero on [lo, from_y) and z
 * on [lo, from_z), from_y <= from_z: a vector and two columns on their chain. Each the bits of
 * chain_solve_from on its own, the three recurrences in one loop where they overlap. */
void tirenv_springs__cc_chain_solve_three(const tirenv_springs__cc *c, double x[], double y[],
                                          size_t from_y, double z[], size_t from_z, size_t lo,
                                          size_t hi)
{
    const double *mul = c->tri_mul, *piv = c->tri_piv;
    double a = x[lo];
    size_t e = lo + 1;
    for (; e <= from_y; ++e)
        x[e] = a = x[e] - mul[e] * a;
    double b = y[from_y];
    for (; e <= from_z; ++e) {
        a = x[e] - mul[e] * a;
        b = y[e] - mul[e] * b;
        x[e] = a;
        y[e] = b;
    }
    double d = z[from_z];
    for (; e <= hi; ++e) {
        a = x[e] - mul[e] * a;
        b = y[e] - mul[e] * b;
        d = z[e] - mul[e] * d;
        x[e] = a;
        y[e] = b;
        z[e] = d;
    }
    x[hi] = a = x[hi] / piv[hi];
    y[hi] = b = y[hi] / piv[hi];
    z[hi] = d = z[hi] / piv[hi];
    for (e = hi; e-- > lo;) {
        a = x[e] / piv[e] - mul[e + 1] * a;
        b = y[e] / piv[e] - mul[e + 1] * b;
        d = z[e] / piv[e] - mul[e + 1] * d;
        x[e] = a;
        y[e] = b;
        z[e] = d;
    }
}

/* x := K_FF^-1 x on every free element of [f0, f1] (the chains the factor found), two chains
 * at a time. */
static void tri_solve(const tirenv_springs__cc *c, double x[])
{
    const size_t *ch = c->chains, n_ch = c->n_chains;
    size_t q = 0;
    for (; q + 2 <= n_ch; q += 2)
        chain_solve_pair(c, x, ch[2 * q], ch[2 * q], ch[2 * q + 1], x, ch[2 * q + 2],
                         ch[2 * q + 2], ch[2 * q + 3]);
    if (q < n_ch)
        chain_solve(c, x, ch[2 * q], ch[2 * q + 1]);
}

void tirenv_springs__cc_chains_solve(const tirenv_springs__cc *c, double x[])
{
    tri_solve(c, x);
}

/* g_r . x over the row's free elements within [lo, hi] (x is zero outside). */
static double row_dot(const tirenv_springs__cc *c, const tirenv_springs__cc_row *r,
                      const double x[], size_t lo, size_t hi)
{
    double s = 0;
    if (c->wpos[r->i] != SIZE_MAX && lo <= r->i && r->i <= hi)
        s += r->ga * x[r->i];
    if (r->t > 0 && c->wpos[r->j] != SIZE_MAX && lo <= r->j && r->j <= hi)
        s += r->gb * x[r->j];
    return s;
}

/* The working rows' columns of K_FF^-1 G^T on the factor kept, then S = G K_FF^-1 G^T and its
 * LDL^T; 1 if the rows are dependent. */
static int schur_rows(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T)
{
    const size_t f0 = c->f0, f1 = c->f1, N = T->N, k = c->n_schur;
    const double k_max = T->k_r + 2 * T->k_ir;
    for (size_t q = 0; q < k; ++q) {
        const tirenv_springs__cc_row *r = &c->rows[c->order[c->schur_pos[q]] - N];
        double *y = c->tri_y + q * (N + 2);
        /* K_FF^-1 g_r is nonzero on the chain of free elements holding the row's only */
        size_t lo = c->wpos[r->i] != SIZE_MAX ? r->i : r->j, hi = lo;
        if (c->wpos[lo] == SIZE_MAX) { /* on held elements only: dependent on their rows */
            c->chain_lo[q] = 1;
            c->chain_hi[q] = 0;
            continue;
        }
        while (lo > f0 && c->wpos[lo - 1] != SIZE_MAX)
            --lo;
        while (hi < f1 && c->wpos[hi + 1] != SIZE_MAX)
            ++hi;
        c->chain_lo[q] = lo;
        c->chain_hi[q] = hi;
        for (size_t e = lo; e <= hi; ++e)
            y[e] = 0;
        size_t from = hi;
        if (c->wpos[r->i] != SIZE_MAX) {
            y[r->i] = r->ga;
            from = r->i;
        }
        if (r->t > 0 && c->wpos[r->j] != SIZE_MAX) {
            y[r->j] = r->gb;
            from = r->j < from ? r->j : from;
        }
        chain_solve_from(c, y, lo, from, hi);
    }
    double *S = c->schur;
    for (size_t p = 0; p < k; ++p) {
        const tirenv_springs__cc_row *r = &c->rows[c->order[c->schur_pos[p]] - N];
        for (size_t q = 0; q <= p; ++q)
            S[p * TIRENV_SPRINGS__SCHUR_MAX + q] =
                row_dot(c, r, c->tri_y + q * (N + 2), c->chain_lo[q], c->chain_hi[q]);
    }
    for (size_t p = 0; p < k; ++p) /* G w + C lambda = h: S + C, C the rows' compliances */
        S[p * TIRENV_SPRINGS__SCHUR_MAX + p] += c->rows[c->order[c->schur_pos[p]] - N].cmp;
    /* S = L D L^T in place (unit L below the diagonal, D on it); S is positive definite when
     * the rows are independent: a pivot at round-off level shows them dependent, as the
     * banded factorisation's row pivot does. */
#define S_AT(p, q) S[(p) * TIRENV_SPRINGS__SCHUR_MAX + (q)]
    for (size_t p = 0; p < k; ++p) {
        for (size_t q = 0; q <= p; ++q) {
            double s = S_AT(p, q);
            for (size_t m = 0; m < q; ++m)
                s -= S_AT(p, m) * S_AT(q, m) * S_AT(m, m);
            if (q < p)
                S_AT(p, q) = s / S_AT(q, q);
            else
                S_AT(p, p) = s;
        }
        if (!(S_AT(p, p) > 1e-14 / k_max))
            return 1;
    }
    return 0;
}

int tirenv_springs__cc_schur_factor(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                   int same)
{
    const size_t f0 = c->f0, f1 = c->f1;
    const double k_ir = T->k_ir;
    double *piv = c->tri_piv, *mul = c->tri_mul;
    size_t n_chains = 0;
    /* K_FF depends on the span and the held elements only: its factor is kept while they
     * stay (kkt_factor compares them), bit for bit what factorising again gives. */
    c->tri_ok = 0;
    c->factor_kept = same;
    c->n_factors += !same; /* what a K_FF^-1 f kept was solved with (springs_root.c) */
    /* Free element e's stiffness (tirenv_springs__cc_k_diag); coupled to e - 1 if that is
     * free and in the span. On locals: the stores to chains (size_t) would make c's fields be read
     * again at every element. */
    const size_t *wpos = c->wpos;
    size_t *chains = c->chains;
    for (size_t e = f0; !same && e <= f1; ++e) {
        if (wpos[e] == SIZE_MAX)
            continue;
        double d = tirenv_springs__cc_k_diag(T, f0, f1, e);
        if (e > f0 && wpos[e - 1] != SIZE_MAX) {
            mul[e] = -k_ir / piv[e - 1];
            d += k_ir * mul[e]; /* d - k_ir^2 / piv[e - 1] */
            chains[2 * n_chains - 1] = e;
        } else {
            chains[2 * n_chains] = chains[2 * n_chains + 1] = e;
            ++n_chains;
        }
        if (!(d > 0))
            return 1;
        piv[e] = d;
    }
    if (!same)
        c->n_chains = n_chains;
    c->tri_ok = 1;
    c->tri_f0 = f0;
    c->tri_f1 = f1;
    return schur_rows(c, T);
}

/* The Thomas factor of chain elements [from, hi] (from the chain's first, or after a factor
 * kept for [lo, from)): each element's pivot depends on those before it in its chain alone,
 * so these are the bits a factor of the whole span gives. 1 at a pivot <= 0. */
static int chain_factor(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T, size_t lo,
                        size_t from, size_t hi)
{
    const size_t f0 = c->f0, f1 = c->f1;
    const double k_ir = T->k_ir;
    double *piv = c->tri_piv, *mul = c->tri_mul;
    for (size_t e = from; e <= hi; ++e) {
        double d = tirenv_springs__cc_k_diag(T, f0, f1, e);
        if (e > lo) {
            mul[e] = -k_ir / piv[e - 1];
            d += k_ir * mul[e]; /* d - k_ir^2 / piv[e - 1] */
        }
        if (!(d > 0))
            return 1;
        piv[e] = d;
    }
    return 0;
}

int tirenv_springs__cc_schur_flip(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                  size_t e)
{
    const size_t f0 = c->f0, f1 = c->f1;
    if (!c->tri_ok || c->tri_f0 != f0 || c->tri_f1 != f1 || e < f0 || e > f1)
        return tirenv_springs__cc_schur_factor(c, T, 0);
    size_t *ch = c->chains, n = c->n_chains, q = 0;
    while (q < n && ch[2 * q + 1] < e) /* the first chain ending at or after e */
        ++q;
    const int inside = q < n && ch[2 * q] <= e;
    if ((c->wpos[e] == SIZE_MAX) != inside) /* (e did not flip: no chain to mend) */
        return tirenv_springs__cc_schur_factor(c, T, 0);
    c->tri_ok = 0;
    c->factor_kept = 0;
    c->mend_at = c->n_factors++;
    if (inside) { /* e held: its chain [lo, hi] splits into [lo, e - 1] and [e + 1, hi], the
                   * latter factorised anew */
        const size_t lo = ch[2 * q], hi = ch[2 * q + 1];
        const int left = lo < e, right = e < hi;
        const size_t keep = (size_t)left + (size_t)right; /* chains in its place */
        memmove(ch + 2 * (q + keep), ch + 2 * (q + 1), 2 * (n - q - 1) * sizeof *ch);
        size_t at = q;
        if (left) {
            ch[2 * at] = lo;
            ch[2 * at++ + 1] = e - 1;
        }
        if (right) {
            ch[2 * at] = e + 1;
            ch[2 * at + 1] = hi;
        }
        c->n_chains = n - 1 + keep;
        c->mend_lo = lo;
        c->mend_hi = hi;
        if (right && chain_factor(c, T, e + 1, e + 1, hi))
            return 1;
    } else { /* e let go: the chains either side (ending at e - 1, starting at e + 1) join
              * it, the factor kept up to e - 1 */
        const int left = q > 0 && ch[2 * q - 1] + 1 == e;
        const int right = q < n && ch[2 * q] == e + 1;
        const size_t lo = left ? ch[2 * (q - 1)] : e, hi = right ? ch[2 * q + 1] : e;
        const size_t first = left ? q - 1 : q, gone = (size_t)left + (size_t)right;
        /* chains [first, first + gone) become one (or one is put in at q) */
        if (gone == 0)
            memmove(ch + 2 * (q + 1), ch + 2 * q, 2 * (n - q) * sizeof *ch);
        else
            memmove(ch + 2 * (first + 1), ch + 2 * (first + gone),
                    2 * (n - first - gone) * sizeof *ch);
        ch[2 * first] = lo;
        ch[2 * first + 1] = hi;
        c->n_chains = n + 1 - gone;
        c->mend_lo = lo;
        c->mend_hi = hi;
        if (chain_factor(c, T, lo, e, hi))
            return 1;
    }
    c->tri_ok = 1;
    return schur_rows(c, T);
}

void tirenv_springs__cc_schur_solve_at(const tirenv_springs__cc *c,
                                       const tirenv_springs__cc_tire *T, double x[],
                                       double lam[])
{
    const size_t f0 = c->f0, f1 = c->f1, N = T->N, k = c->n_schur;
    const double *S = c->schur;
    /* K w = b_w + G^T lambda, G w = b_r: w = w0 + K^-1 G^T lambda with w0 = K^-1 b_w, and
     * S lambda = b_r - G w0. */
    tri_solve(c, x);
    for (size_t p = 0; p < k; ++p)
        lam[p] -= row_dot(c, &c->rows[c->order[c->schur_pos[p]] - N], x, f0, f1);
    for (size_t p = 0; p < k; ++p)
        for (size_t m = 0; m < p; ++m)
            lam[p] -= S_AT(p, m) * lam[m];
    for (size_t p = 0; p < k; ++p)
        lam[p] /= S_AT(p, p);
    for (size_t p = k; p-- > 0;)
        for (size_t m = p + 1; m < k; ++m)
            lam[p] -= S_AT(m, p) * lam[m];
#undef S_AT
    for (size_t q = 0; q < k; ++q) {
        const double *y = c->tri_y + q * (N + 2);
        for (size_t e = c->chain_lo[q]; e <= c->chain_hi[q]; ++e)
            x[e] += lam[q] * y[e];
    }
}
