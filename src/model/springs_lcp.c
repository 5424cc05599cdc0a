/* SPDX-License-Identifier: Apache-2.0 */
/* The tip LCP of the springs model (docs/models.md section 4): a tridiagonal obstacle problem. */
#include "model/springs_impl.h"

#include <math.h>
#include <stddef.h>
#include "tirenv/error.h"

/* Thomas algorithm on the active-set system: rows of active elements read w_i = d_i, the others
 * (K w)_i = 0. Both kinds of row are strictly diagonally dominant, so no pivoting is needed.
 * cp and inv keep the factorisation for the tangent solve. */
static void solve_active(size_t n, const double diag[], double k_ir, const double rhs[],
                         const unsigned char active[], double cp[], double inv[], double w[])
{
    double cp_prev = 0, rp_prev = 0;
    for (size_t i = 0; i < n; ++i) {
        const double sub = active[i] || i == 0 ? 0 : -k_ir;
        const double sup = active[i] || i + 1 == n ? 0 : -k_ir;
        const double b = active[i] ? 1 : diag[i];
        inv[i] = 1 / (b - sub * cp_prev);
        cp[i] = sup * inv[i];
        rp_prev = ((active[i] ? rhs[i] : 0) - sub * rp_prev) * inv[i];
        w[i] = rp_prev;
        cp_prev = cp[i];
    }
    for (size_t i = n - 1; i-- > 0;)
        w[i] -= cp[i] * w[i + 1];
}

/* Primal-dual active set (Hintermueller, Ito & Kunisch 2003): A = {i : p_i + c (d_i - w_i) > 0}.
 * K is an M-matrix, for which the iteration converges monotonically from any start in at most n
 * passes; warm-started from the previous position it typically needs one or two. At the fixed
 * point w_i = d_i with p_i > 0 on A and p_i = 0 with w_i >= d_i off A: the LCP holds exactly. */
int tirenv_springs__lcp(size_t n, const double diag[], double k_ir, const double d[],
                        double w[], double p[], unsigned char active[], double work[],
                        size_t max_passes, size_t *passes)
{
    double *cp = work, *inv = work + n;
    for (size_t pass = 1; pass <= max_passes; ++pass) {
        if (passes)
            *passes = pass;
        if (n == 0)
            return TIRENV_OK;
        solve_active(n, diag, k_ir, d, active, cp, inv, w);
        int changed = 0;
        for (size_t i = 0; i < n; ++i) {
            const double w_l = i > 0 ? w[i - 1] : 0, w_r = i + 1 < n ? w[i + 1] : 0;
            p[i] = active[i] ? diag[i] * w[i] - k_ir * (w_l + w_r) : 0;
            const unsigned char now = p[i] + diag[i] * (d[i] - w[i]) > 0;
            changed |= now != active[i];
            active[i] = now;
        }
        if (!changed)
            return TIRENV_OK;
    }
    return TIRENV_ENOCONV;
}

int tirenv_springs_lcp(size_t n, double k_r, double k_ir, const double d[], double w[],
                       double p[], double work[], size_t max_iter, size_t *passes)
{
    /* work: diag (n), factorisation (2n), active flags (n bytes in the last n doubles). */
    double *diag = work;
    unsigned char *active = (unsigned char *)(work + 3 * n);
    for (size_t i = 0; i < n; ++i) {
        const size_t neighbours = (i > 0) + (i + 1 < n);
        diag[i] = k_r + (double)neighbours * k_ir;
        active[i] = 0;
    }
    return tirenv_springs__lcp(n, diag, k_ir, d, w, p, active, work + n, max_iter, passes);
}

/* ---- The pinned-chain solve ---- */

/* Between pinned tips l and r = l + m + 1 the free elements obey the homogeneous recurrence
 * k_ir w_{t-1} - (k_r + 2 k_ir) w_t + k_ir w_{t+1} = 0, whose solutions are combinations of
 * exp(+-t mu) with cosh(mu) = 1 + k_r / (2 k_ir); with w_0 = d_l and w_{m+1} = d_r,
 *   w_t = (d_l sinh((m+1-t) mu) + d_r sinh(t mu)) / sinh((m+1) mu).
 * Written with e^{-k mu} and 1 - e^{-2k mu} (expm1, so no cancellation when mu is small and
 * no overflow when (m+1) mu is large), every factor is a table entry accurate to an ulp or
 * two. mu = acosh(1 + eps) is evaluated as log1p(eps + sqrt(eps (2 + eps))), exact for small
 * eps. k_ir = 0 gives mu = infinity: every free element is at rest (w = 0). */
void tirenv_springs__chain_tables(size_t N, double k_r, double k_ir, double ce[], double cm[],
                                  double cmi[])
{
    const double eps = k_ir > 0 ? k_r / (2 * k_ir) : INFINITY;
    const double mu = isinf(eps) ? INFINITY : log1p(eps + sqrt(eps * (2 + eps)));
    ce[0] = 1;
    cm[0] = 0;
    cmi[0] = 0; /* never used: a chain of m elements uses cmi[m + 1] */
    for (size_t k = 1; k < N + 2; ++k) {
        ce[k] = isinf(mu) ? 0 : exp(-(double)k * mu);
        cm[k] = isinf(mu) ? 1 : -expm1(-2 * (double)k * mu);
        cmi[k] = 1 / cm[k];
    }
}

/* The pinned elements of active[f0..f1] as first, last and the gaps between them that hold
 * free elements. */
static void gather(const unsigned char active[], size_t f0, size_t f1,
                   tirenv_springs__pins *P)
{
    size_t count = 0, prev = 0, n_gaps = 0;
    for (size_t i = f0; i <= f1; ++i) {
        if (!active[i])
            continue;
        if (count == 0)
            P->first = i;
        else if (i - prev > 1) {
            P->gap[2 * n_gaps] = prev;
            P->gap[2 * n_gaps + 1] = i;
            ++n_gaps;
        }
        prev = i;
        ++count;
    }
    P->last = prev;
    P->count = count;
    P->n_gaps = n_gaps;
}

void tirenv_springs__pinned_solve(const tirenv_springs__chains *c, size_t f0, size_t f1,
                                  const tirenv_springs__pins *P, const double v[], double w[])
{
    if (P->count == 0) { /* nothing holds the tread: at rest */
        for (size_t i = f0; i <= f1; ++i)
            w[i] = 0;
        return;
    }
    const double *ce = c->ce, *cm = c->cm, *cmi = c->cmi;
    const size_t first = P->first, last = P->last;
    for (size_t i = first; i <= last; ++i) /* the pins; the gaps' entries are overwritten */
        w[i] = v[i];
    for (size_t k = 0; k < P->n_gaps; ++k) {
        const size_t l = P->gap[2 * k], r = P->gap[2 * k + 1], m = r - l - 1;
        const double d_l = v[l], d_r = v[r], inv = cmi[m + 1];
        const double *cm_l = cm + m + 1, *ce_r = ce + m + 1;
        double *wl = w + l;
        for (size_t t = 1; t <= m; ++t)
            wl[t] = (d_l * ce[t] * cm_l[-(long)t] + d_r * ce_r[-(long)t] * cm[t]) * inv;
    }
    /* The free ends: Gaussian elimination from element 0 (lq) and from N - 1 (rq). */
    for (size_t j = first; j-- > f0;)
        w[j] = c->lq[j] * w[j + 1];
    for (size_t j = last + 1; j <= f1; ++j)
        w[j] = c->rq[j] * w[j - 1];
}

int tirenv_springs__lcp_pinned(const tirenv_springs__chains *c, size_t f0, size_t f1,
                               const double d[], double w[], double p[],
                               unsigned char active[], tirenv_springs__pins *P,
                               size_t max_passes, size_t *passes)
{
    const double k_ir = c->k_ir, *diag = c->diag;
    /* The neighbours' deflections just outside [f0, f1]: free chains to the tire's ends. */
    const double lq_out = f0 > 0 ? c->lq[f0 - 1] : 0;
    const double rq_out = f1 + 1 < c->N ? c->rq[f1 + 1] : 0;
    for (size_t i = f0; i <= f1; ++i) /* no warm start where there is nothing to touch */
        active[i] = active[i] && d[i] > 0;
    gather(active, f0, f1, P);
    for (size_t pass = 1; pass <= max_passes; ++pass) {
        if (passes)
            *passes = pass;
        tirenv_springs__pinned_solve(c, f0, f1, P, d, w);
        double *w0 = w + f0, *w1 = w + f1;
        w0[-1] = lq_out * w0[0];
        w1[1] = rq_out * w1[0];
        /* The same test as tirenv_springs__lcp: A = {i : p_i + diag_i (d_i - w_i) > 0}, with
         * w_i = d_i on A and p_i = 0 off it. */
        unsigned char changed = 0;
        for (size_t i = f0; i <= f1; ++i) {
            const double *wi = w + i;
            const double p_i = diag[i] * wi[0] - k_ir * (wi[-1] + wi[1]);
            const unsigned char was = active[i];
            const unsigned char now = was ? p_i > 0 : diag[i] * (d[i] - w[i]) > 0;
            p[i] = was ? p_i : 0;
            changed |= now ^ was;
            active[i] = now;
        }
        if (!changed)
            return TIRENV_OK;
        gather(active, f0, f1, P);
    }
    return TIRENV_ENOCONV;
}
