/* The tip LCP of the springs model (docs/models.md section 4): a tridiagonal obstacle problem. */
#include "model/springs_impl.h"

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

void tirenv_springs__lcp_tangent(size_t n, double k_ir, const double dd[],
                                 const unsigned char active[], const double work[],
                                 double dw[])
{
    const double *cp = work, *inv = work + n;
    double rp_prev = 0;
    for (size_t i = 0; i < n; ++i) {
        const double sub = active[i] || i == 0 ? 0 : -k_ir;
        rp_prev = ((active[i] ? dd[i] : 0) - sub * rp_prev) * inv[i];
        dw[i] = rp_prev;
    }
    for (size_t i = n - 1; n > 0 && i-- > 0;)
        dw[i] -= cp[i] * dw[i + 1];
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
