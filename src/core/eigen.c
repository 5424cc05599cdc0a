/* SPDX-License-Identifier: Apache-2.0 */
/* Eigenvalues of a small real matrix by the textbook route (Golub and Van Loan, Matrix
 * Computations, 4th ed., sections 7.5.7, 7.4 and 7.5): balance by powers of two (Parlett and
 * Reinsch, 1969) so that rows and columns of very different scales (the ride's stiffnesses
 * over masses, 1e6, beside ones) do not lose the small ones to round-off; reduce to upper
 * Hessenberg form by Householder reflections; then the single-shift QR iteration in complex
 * arithmetic with Wilkinson's shift, by Givens rotations, deflating a subdiagonal entry below
 * eps times its neighbours on the diagonal, with an exceptional shift every tenth iteration.
 * Every step is a similarity by a unitary (or, for the balance, an exact diagonal) matrix, so
 * the eigenvalues are those of A to round-off in the norm of the balanced matrix. The sizes
 * here are tiny (n <= 8): clarity before speed. tests/core/test_numerics.c checks oscillators and a
 * companion matrix with known roots. */
#include "core/eigen.h"

#include <float.h>
#include <math.h>

enum { N_MAX = TIRENV_CORE__EIGEN_MAX };

static void balance(const size_t n, double complex H[N_MAX][N_MAX])
{
    for (int done = 0; !done;) {
        done = 1;
        for (size_t i = 0; i < n; ++i) {
            double c = 0, r = 0;
            for (size_t j = 0; j < n; ++j)
                if (j != i) {
                    c += cabs(H[j][i]);
                    r += cabs(H[i][j]);
                }
            if (c == 0 || r == 0)
                continue;
            const double s = c + r;
            double f = 1, g = r / 2;
            while (c < g) {
                f *= 2;
                c *= 4;
            }
            g = r * 2;
            while (c > g) {
                f /= 2;
                c /= 4;
            }
            if ((c + r) / f < 0.95 * s) {
                done = 0;
                for (size_t j = 0; j < n; ++j) {
                    H[i][j] /= f;
                    H[j][i] *= f;
                }
            }
        }
    }
}

static void hessenberg(const size_t n, double complex H[N_MAX][N_MAX])
{
    for (size_t k = 0; k + 2 < n; ++k) {
        double norm = 0;
        for (size_t i = k + 1; i < n; ++i)
            norm = hypot(norm, cabs(H[i][k]));
        if (norm == 0)
            continue;
        const double complex x0 = H[k + 1][k];
        const double complex alpha = -(cabs(x0) > 0 ? x0 / cabs(x0) : 1) * norm;
        double complex v[N_MAX];
        double v_norm = 0;
        for (size_t i = k + 1; i < n; ++i) {
            v[i] = H[i][k] - (i == k + 1 ? alpha : 0);
            v_norm = hypot(v_norm, cabs(v[i]));
        }
        if (v_norm == 0)
            continue;
        for (size_t i = k + 1; i < n; ++i)
            v[i] /= v_norm;
        for (size_t j = k; j < n; ++j) {  /* H = (I - 2 v v^H) H */
            double complex s = 0;
            for (size_t i = k + 1; i < n; ++i)
                s += conj(v[i]) * H[i][j];
            for (size_t i = k + 1; i < n; ++i)
                H[i][j] -= 2 * v[i] * s;
        }
        for (size_t i = 0; i < n; ++i) {  /* H = H (I - 2 v v^H) */
            double complex s = 0;
            for (size_t j = k + 1; j < n; ++j)
                s += H[i][j] * v[j];
            for (size_t j = k + 1; j < n; ++j)
                H[i][j] -= 2 * s * conj(v[j]);
        }
        for (size_t i = k + 2; i < n; ++i)
            H[i][k] = 0;
    }
}

/* Of the eigenvalues of [[a, b], [c, d]], the one nearer d (Wilkinson's shift). */
static double complex wilkinson(double complex a, double complex b, double complex c,
                                double complex d)
{
    const double complex half = 0.5 * (a - d);
    const double complex disc = csqrt(half * half + b * c);
    const double complex m1 = 0.5 * (a + d) + disc, m2 = 0.5 * (a + d) - disc;
    return cabs(m1 - d) < cabs(m2 - d) ? m1 : m2;
}

/* One shifted QR step on the window l..hi of the Hessenberg H: H - mu I = QR, H <- RQ + mu I,
 * with Q the product of Givens rotations. */
static void qr_step(const size_t l, const size_t hi, const double complex mu,
                    double complex H[N_MAX][N_MAX])
{
    double complex cs[N_MAX], sn[N_MAX];
    for (size_t k = l; k <= hi; ++k)
        H[k][k] -= mu;
    for (size_t k = l; k < hi; ++k) {
        const double complex x = H[k][k], y = H[k + 1][k];
        const double r = hypot(cabs(x), cabs(y));
        cs[k] = r > 0 ? x / r : 1;
        sn[k] = r > 0 ? y / r : 0;
        for (size_t j = k; j <= hi; ++j) {  /* rows k, k+1 <- G [row k; row k+1] */
            const double complex p = H[k][j], q = H[k + 1][j];
            H[k][j] = conj(cs[k]) * p + conj(sn[k]) * q;
            H[k + 1][j] = -sn[k] * p + cs[k] * q;
        }
    }
    for (size_t k = l; k < hi; ++k) {  /* columns k, k+1 <- [col k, col k+1] G^H */
        for (size_t i = l; i <= hi && i <= k + 1; ++i) {
            const double complex p = H[i][k], q = H[i][k + 1];
            H[i][k] = p * cs[k] + q * sn[k];
            H[i][k + 1] = -p * conj(sn[k]) + q * conj(cs[k]);
        }
    }
    for (size_t k = l; k <= hi; ++k)
        H[k][k] += mu;
}

int tirenv_core__eigenvalues(const size_t n, const double A[], double complex lambda[])
{
    if (n < 1 || n > N_MAX)
        return 1;
    double complex H[N_MAX][N_MAX];
    double norm = 0;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j) {
            if (!isfinite(A[i * n + j]))
                return 1;
            H[i][j] = A[i * n + j];
        }
    balance(n, H);
    hessenberg(n, H);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j)
            norm = fmax(norm, cabs(H[i][j]));
    size_t hi = n - 1, iter = 0, total = 0;
    while (hi > 0) {
        size_t l = hi;
        for (; l > 0; --l) {  /* the lowest row of the unreduced block ending at hi */
            double s = cabs(H[l - 1][l - 1]) + cabs(H[l][l]);
            if (s == 0)
                s = norm;
            if (cabs(H[l][l - 1]) <= DBL_EPSILON * s) {
                H[l][l - 1] = 0;
                break;
            }
        }
        if (l == hi) {  /* a 1 x 1 block: an eigenvalue */
            lambda[hi] = H[hi][hi];
            --hi;
            iter = 0;
            continue;
        }
        if (++total > 30 * n)
            return 2;
        ++iter;
        double complex mu;
        if (iter % 10 == 0)  /* exceptional shift: breaks a cycle of the Wilkinson shifts */
            mu = H[hi][hi] + cabs(H[hi][hi - 1]) + (hi >= 2 ? cabs(H[hi - 1][hi - 2]) : 0);
        else
            mu = wilkinson(H[hi - 1][hi - 1], H[hi - 1][hi], H[hi][hi - 1], H[hi][hi]);
        qr_step(l, hi, mu, H);
    }
    lambda[0] = H[0][0];
    return 0;
}
