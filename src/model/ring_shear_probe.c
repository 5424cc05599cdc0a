/* SPDX-License-Identifier: Apache-2.0 */
/* For tests: the shear-coupled tread's hooks (docs/models.md section 5.3), each checking one of
 * its shortcuts against the path it replaces, bit for bit (the factor's restart, its AVX2
 * build, the fused and the leading-zero solves, the exterior's shared columns, the window's
 * assembly), or giving what only a diagnostic needs (the exterior's (w, u)). They allocate. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "model/ring_impl.h"
#include "model/ring_shear_impl.h"
#include "model/ring_tband.h"
#include "tirenv/rng.h"

/* X := the system P (its N, t and m = N - t band rows), into X's own storage. */
static void copy_system(tband *X, const tband *P)
{
    const size_t m = P->N - P->t;
    X->N = P->N, X->t = P->t;
    memcpy(X->L, P->L, (BAND_P + 1) * m * sizeof *X->L);
    memcpy(X->B, P->B, TAIL * m * sizeof *X->B);
    memcpy(X->T, P->T, sizeof X->T);
}

/* Whether the tread holds a factorised window system to probe (its last one, T->ap, with the
 * tail and at least one band row). */
static int holds_system(const tirenv_ring_tread *T)
{
    return T->ap_ok && T->ap.t == TAIL && T->ap.N > TAIL;
}

/* The belt's w outside the window of the last evaluation: the exterior's unloaded (w, u) that
 * the window's ends hold, -K_EE^-1 K_EW x_B, solved afresh (diagnostics only: it allocates).
 * Writes w_out for every node outside the window; nonzero if out of memory. */
int tirenv_ring__tread_exterior(const tirenv_ring *r, double w_out[], double u_out[])
{
    const tirenv_ring_tread *T0 = r->tread;
    const size_t M = r->M, n = r->n, lo = r->lo, ne = M - n, Ne = 2 * ne;
    if (n == 0) {
        for (size_t j = 0; j < M; ++j) {
            w_out[j] = 0;
            if (u_out)
                u_out[j] = 0;
        }
        return 0;
    }
    /* The constants; its own factor of this exterior alone (the same bits as exterior_factor's
     * leading block, without its unit vectors' substitutions, which only compute_end reads). */
    tirenv_ring_tread T = *T0;
    double *rhs = malloc(Ne * sizeof *rhs);
    if (!rhs || tirenv_ring__tband_alloc(&T.ext, Ne, 0)) {
        free(rhs);
        return 1;
    }
    band_reset(&T.ext, Ne, 0);
    tirenv_ring__add_arc(&T.ext, &T, (lo + n) % M, ne);
    tirenv_ring__tband_factor(&T.ext); /* a principal block of the positive definite whole */
    const double *s = T.s, k_sh = T.k_sh;
    const double *w = r->w, *u = T0->u;
    const size_t j0 = lo, j1 = lo + 1, jm2 = lo + n - 2, jm1 = lo + n - 1;
    memset(rhs, 0, Ne * sizeof *rhs);
    rhs[0] = -(s[2] * w[jm2] + s[1] * w[jm1]);
    rhs[1] = k_sh * u[jm1];
    rhs[2] = -s[2] * w[jm1];
    rhs[Ne - 4] = -s[2] * w[j0];
    rhs[Ne - 2] = -(s[1] * w[j0] + s[2] * w[j1]);
    rhs[Ne - 1] = k_sh * u[j0];
    tirenv_ring__tband_solve(&T.ext, rhs);
    for (size_t e = 0; e < ne; ++e) {
        w_out[(lo + n + e) % M] = rhs[2 * e];
        if (u_out)
            u_out[(lo + n + e) % M] = rhs[2 * e + 1];
    }
    free(T.ext.L);
    free(rhs);
    return 0;
}

/* The window's stiffness of the last evaluation (nodes r->lo .. r->lo + r->n - 1), dense, as
 * assemble starts it (fill_window, by_arc 0) or as add_arc writes it on a zeroed matrix (by_arc
 * 1): the two ways the tread writes an arc, which must agree bit for bit. K[i N + k] = K_ik for
 * k <= i, zero above the diagonal (N = 2 n). For tests (it allocates); nonzero if out of memory,
 * the window is too short for the tail (n < 2) or fill_window left an entry of its right-hand
 * side (NaN before) other than zero. */
int tirenv_ring__tread_window(const tirenv_ring *r, int by_arc, double K[])
{
    const tirenv_ring_tread *T = r->tread;
    const size_t n = r->n, N = 2 * n, m = N - TAIL;
    tband A;
    if (n < 2 || tirenv_ring__tband_alloc(&A, N, TAIL))
        return 1;
    if (by_arc) {
        band_reset(&A, N, TAIL);
        tirenv_ring__add_arc(&A, T, r->lo, n);
    } else {
        /* NaN wherever fill_window should write, so that an entry it leaves unset shows; then
         * the fresh columns, which it leaves unset on purpose, as band_factor_from takes them
         * (zero). */
        for (size_t i = 0; i < (BAND_P + 1 + TAIL) * N; ++i)
            A.L[i] = NAN;
        for (size_t a = 0; a < TAIL; ++a)
            for (size_t b = 0; b < TAIL; ++b)
                A.T[a][b] = NAN;
        double *rhs = malloc(N * sizeof *rhs); /* NaN, which fill_window must zero */
        if (!rhs) {
            free(A.L);
            return 1;
        }
        for (size_t i = 0; i < N; ++i)
            rhs[i] = NAN;
        tirenv_ring__fill_window(&A, T, r->lo, n, rhs);
        const size_t fresh = m >= FRESH_FROM + BAND_P ? m - BAND_P - FRESH_FROM : 0;
        if (fresh > 0)
            memset(A.B + TAIL * FRESH_FROM, 0, TAIL * fresh * sizeof *A.B);
        int zeroed = 1;
        for (size_t i = 0; i < N; ++i)
            zeroed &= rhs[i] == 0;
        free(rhs);
        if (!zeroed) {
            free(A.L);
            return 1;
        }
    }
    for (size_t i = 0; i < N; ++i)
        for (size_t k = 0; k < N; ++k)
            K[i * N + k] = k > i ? 0
                           : i < m ? (i - k <= BAND_P ? A.L[(BAND_P + 1) * k + (i - k)] : 0)
                           : k < m ? A.B[TAIL * k + (i - m)]
                                   : A.T[i - m][k - m];
    free(A.L);
    return 0;
}

/* For tests: band_refactor's restart from a checkpoint against a full factorisation. The
 * window's system of the last factorisation (T->ap, whose factor T->win holds), its diagonal
 * scaled by 1 + 2^-10 from column c on (still positive definite), is factorised by
 * band_refactor (which keeps the columns before the checkpoint at or before c) and, on a copy,
 * by band_factor_from from column 0. *q: the column band_refactor restarted at (0: from the
 * start); *moved: 1 if the new factor's column c differs from the old one's (the comparison
 * sees changed columns). Returns 0 if the two factors are the same bits, 1 if they differ, -1
 * if it cannot (no factor held, c beyond the band, out of memory). Leaves the window's factor
 * marked stale, so that the next Newton step factorises afresh. *m: the band's rows, N - t. */
int tirenv_ring__tread_refactor(tirenv_ring *r, size_t c, size_t *m_out, size_t *q, int *moved)
{
    tirenv_ring_tread *T = r->tread;
    tband *S = &T->as, *P = &T->ap, *F = &T->win;
    const size_t N = P->N, t = P->t, W = BAND_P + 1;
    *m_out = N > t ? N - t : 0;
    if (!holds_system(T) || c >= N - t)
        return -1;
    const size_t m = N - t;
    tband X;
    if (tirenv_ring__tband_alloc(&X, N, TAIL))
        return -1;
    const double old_c = F->L[W * c];
    copy_system(S, P);
    for (size_t i = c; i < m; ++i)
        S->L[W * i] *= 1 + 0x1p-10;
    copy_system(&X, S);
    *q = 0;
    if (m > 2 * CKS + BAND_P) {
        const size_t p = tirenv_ring__tband_first_change(S, P, m);
        *q = tirenv_ring__tband_restart_column(p, m);
    }
    int fused;
    int st = tirenv_ring__tband_refactor(S, P, F, T->ck, &T->ap_ok, NULL, &fused) != 0 ||
                     tirenv_ring__tband_factor_from(&X, 1, 0, NULL, NULL, NULL) != 0
                 ? -1
                 : 0;
    if (st == 0) {
        *moved = !tirenv_ring__same_bits(&F->L[W * c], &old_c, 1);
        st = !tirenv_ring__same_bits(F->L, X.L, W * m) ||
             !tirenv_ring__same_bits(F->B, X.B, TAIL * m) ||
             !tirenv_ring__same_bits(&F->T[0][0], &X.T[0][0], TAIL * TAIL);
    }
    T->ap_ok = 0;
    free(X.L);
    return st;
}

/* For tests: the window's last factorised system (T->ap, its fresh tail entries taken as zero)
 * factorised from column 0 by band_factor_body's baseline build and by its AVX2 one, with
 * checkpoints; 0 if the two factors and their checkpoints are the same bits, 1 if not, -1 if it
 * cannot (no factor held, out of memory). *avx2: 1 if the AVX2 build ran (compiled in and the
 * processor has it), else 0 and only the baseline ran (returns 0). */
int tirenv_ring__tread_factor_isa(const tirenv_ring *r, int *avx2)
{
    const tirenv_ring_tread *T = r->tread;
    const tband *P = &T->ap;
    const size_t N = P->N, t = P->t;
    *avx2 = 0;
    if (!holds_system(T))
        return -1;
    const size_t m = N - t, n_ck = CK_LEN * (m / CKS + 1);
    tband X[2] = {{0}};
    double *ck = calloc(2 * n_ck, sizeof *ck);
    int st = !ck || tirenv_ring__tband_alloc(&X[0], N, TAIL) ||
                     tirenv_ring__tband_alloc(&X[1], N, TAIL)
                 ? -1
                 : 0;
    for (int k = 0; k < 2 && st == 0; ++k)
        copy_system(&X[k], P);
    if (st == 0) {
        st = tirenv_ring__tband_factor_base(&X[0], 1, 0, NULL, ck, NULL) != 0 ? -1 : 0;
#if TIRENV_RING_AVX2
        if (st == 0 && __builtin_cpu_supports("avx2")) {
            const size_t n_kept = m > BAND_P ? CK_LEN * ((m - BAND_P - 1) / CKS + 1) : 0;
            *avx2 = 1;
            st = tirenv_ring__tband_factor_avx2(&X[1], 1, 0, NULL, ck + n_ck, NULL) != 0 ? -1 : 0;
            if (st == 0)
                st = !tirenv_ring__same_bits(X[0].L, X[1].L, (BAND_P + 1) * m) ||
                     !tirenv_ring__same_bits(X[0].B, X[1].B, TAIL * m) ||
                     !tirenv_ring__same_bits(&X[0].T[0][0], &X[1].T[0][0], TAIL * TAIL) ||
                     !tirenv_ring__same_bits(ck, ck + n_ck, n_kept);
        }
#endif
    }
    free(X[0].L);
    free(X[1].L);
    free(ck);
    return st;
}

/* For tests: the window's last factorised system (T->ap, its fresh tail entries taken as zero)
 * factorised from column 0 with checkpoints and then solved (band_factor_from, band_solve), and
 * factorised again with the solve's forward substitution in the same pass (band_factor_x):
 * from column 0, and restarted at each checkpoint from the first factor's state there (as
 * band_refactor does). A right-hand side of pseudo-random entries in [-1, 1) from seed with
 * lead leading +0 rows, its tail entry neg0 (< 4; else none) -0. 0 if every fused solve and
 * factor is the same bits as the first, 1 if not, -1 if it cannot; *fused 1 if the fused pass
 * ran (the AVX2 build), *n_restarts the restarts compared. */
int tirenv_ring__tread_fused_solve(const tirenv_ring *r, unsigned long seed, size_t lead,
                                   size_t neg0, int *fused, size_t *n_restarts)
{
    const tirenv_ring_tread *T = r->tread;
    const tband *P = &T->ap;
    const size_t N = P->N, t = P->t, W = BAND_P + 1;
    *fused = 0, *n_restarts = 0;
    if (!holds_system(T))
        return -1;
    const size_t m = N - t, n_ck = CK_LEN * (m / CKS + 1);
    lead = lead < m ? lead : m;
    tband X = {0}, Y = {0};
    double *ck = calloc(n_ck, sizeof *ck), *x = malloc(3 * N * sizeof *x);
    tirenv_rng *rng = tirenv_rng_alloc(seed);
    int st = !ck || !x || !rng || tirenv_ring__tband_alloc(&X, N, TAIL) ||
                     tirenv_ring__tband_alloc(&Y, N, TAIL)
                 ? -1
                 : 0;
    double *b = x + N, *y = x + 2 * N;
    if (st == 0) {
        for (size_t i = 0; i < N; ++i)
            b[i] = i < lead ? 0 : 2 * tirenv_rng_uniform(rng) - 1;
        if (neg0 < TAIL)
            b[m + neg0] = -0.0;
        copy_system(&X, P);
        st = tirenv_ring__tband_factor_from(&X, 1, 0, NULL, ck, NULL) != 0 ? -1 : 0;
    }
    if (st == 0) {
        memcpy(x, b, N * sizeof *x);
        tirenv_ring__tband_solve(&X, x);
    }
    /* q = 0: the whole factorisation; then each checkpoint's restart */
    for (size_t q = 0; st == 0 && q + BAND_P < m; q += CKS) {
        Y.N = N, Y.t = t;
        const double *acc = NULL;
        if (q == 0) {
            copy_system(&Y, P);
        } else {
            if (q + BAND_P >= m - BAND_P)
                break;
            memcpy(Y.L, X.L, W * m * sizeof *Y.L);
            memcpy(Y.B, X.B, TAIL * m * sizeof *Y.B);
            acc = tirenv_ring__tband_ck_restore(ck, &Y, q);
            memcpy(Y.B + TAIL * (m - BAND_P), P->B + TAIL * (m - BAND_P),
                   TAIL * BAND_P * sizeof *Y.B);
            memcpy(Y.T, P->T, sizeof Y.T);
            ++*n_restarts;
        }
        memcpy(y, b, N * sizeof *y);
        int f = 0;
        if (tirenv_ring__tband_factor_x(&Y, 1, q, acc, NULL, P->L, y, &f) != 0) {
            st = -1;
            break;
        }
        *fused |= f;
        if (f)
            tirenv_ring__tband_solve_rest(&Y, y);
        else
            tirenv_ring__tband_solve(&Y, y);
        if (!tirenv_ring__same_bits(x, y, N) || !tirenv_ring__same_bits(X.L, Y.L, W * m) ||
            !tirenv_ring__same_bits(X.B, Y.B, TAIL * m) ||
            !tirenv_ring__same_bits(&X.T[0][0], &Y.T[0][0], TAIL * TAIL))
            st = 1;
    }
    tirenv_rng_free(rng);
    free(X.L);
    free(Y.L);
    free(ck);
    free(x);
    return st;
}

/* For tests: the window's last factorised system (T->ap, its fresh tail entries taken as zero)
 * solved with its factor (T->win) for a right-hand side of pseudo-random entries in [-1, 1)
 * drawn from seed (tirenv_rng): max |b - A x| / (max row sum of |A| * max |x|), a few machine
 * epsilons for a backward-stable solve. -1 if no factor is held or out of memory. */
double tirenv_ring__tread_solve_residual(const tirenv_ring *r, unsigned long seed)
{
    const tirenv_ring_tread *T = r->tread;
    const tband *P = &T->ap;
    const size_t N = P->N, t = P->t, W = BAND_P + 1;
    if (!holds_system(T))
        return -1;
    const size_t m = N - t;
    double *b = malloc(4 * N * sizeof *b);
    tirenv_rng *rng = tirenv_rng_alloc(seed);
    if (!b || !rng) {
        free(b);
        tirenv_rng_free(rng);
        return -1;
    }
    double *x = b + N, *y = x + N, *rs = y + N;
    for (size_t i = 0; i < N; ++i)
        b[i] = x[i] = 2 * tirenv_rng_uniform(rng) - 1;
    tirenv_rng_free(rng);
    tirenv_ring__tband_solve(&T->win, x);
    for (size_t i = 0; i < N; ++i)
        y[i] = rs[i] = 0;
    /* A x and the row sums of |A|, from the lower triangle: the band, the tail rows, T. */
    for (size_t i = 0; i < m; ++i) {
        for (size_t k = 0; k <= BAND_P && i + k < m; ++k) {
            const double a = P->L[W * i + k];
            y[i + k] += a * x[i];
            rs[i + k] += fabs(a);
            if (k > 0) {
                y[i] += a * x[i + k];
                rs[i] += fabs(a);
            }
        }
        const int fresh = i >= FRESH_FROM && i + BAND_P < m;
        for (size_t a = 0; a < t && !fresh; ++a) {
            const double e = P->B[TAIL * i + a];
            y[m + a] += e * x[i];
            y[i] += e * x[m + a];
            rs[m + a] += fabs(e);
            rs[i] += fabs(e);
        }
    }
    for (size_t a = 0; a < t; ++a)
        for (size_t c = 0; c <= a; ++c) {
            const double e = P->T[a][c];
            y[m + a] += e * x[m + c];
            rs[m + a] += fabs(e);
            if (c < a) {
                y[m + c] += e * x[m + a];
                rs[m + c] += fabs(e);
            }
        }
    double res = 0, na = 0, nx = 0;
    for (size_t i = 0; i < N; ++i) {
        res = fmax(res, fabs(b[i] - y[i]));
        na = fmax(na, rs[i]);
        nx = fmax(nx, fabs(x[i]));
    }
    free(b);
    return res / (na * nx);
}

/* For tests: the window's factor (T->win) applied by band_solve to a right-hand side whose
 * first lead rows are +0 and the others pseudo-random in [-1, 1) from seed (tirenv_rng), with
 * tail entry neg0 (0 .. TAIL - 1; TAIL: none) -0 and with lead_neg0 a -0 at row lead (lead
 * at most the band's rows m, larger taken as m: then the whole band +0), against the forward
 * substitution from row 0: 0 if the same bits, 1 if not, -1 if it cannot (no factor held, out
 * of memory). */
int tirenv_ring__tread_solve_zeros(const tirenv_ring *r, unsigned long seed, size_t lead,
                                   size_t neg0, int lead_neg0)
{
    const tirenv_ring_tread *T = r->tread;
    const tband *F = &T->win;
    const size_t N = F->N;
    if (!T->ap_ok || F->t != TAIL || N <= TAIL)
        return -1;
    lead = lead < N - TAIL ? lead : N - TAIL;
    double *x = malloc(2 * N * sizeof *x);
    tirenv_rng *rng = tirenv_rng_alloc(seed);
    if (!x || !rng) {
        free(x);
        tirenv_rng_free(rng);
        return -1;
    }
    double *y = x + N;
    for (size_t i = 0; i < N; ++i)
        x[i] = y[i] = i < lead ? 0 : 2 * tirenv_rng_uniform(rng) - 1;
    tirenv_rng_free(rng);
    if (lead_neg0)
        x[lead] = y[lead] = -0.0;
    if (neg0 < TAIL)
        x[N - TAIL + neg0] = y[N - TAIL + neg0] = -0.0;
    tirenv_ring__tband_solve(F, x);
    tirenv_ring__tband_solve_from(F, y, 0);
    const int same = tirenv_ring__same_bits(x, y, N);
    free(x);
    return same ? 0 : 1;
}

/* For tests: the six columns of the exterior's inverse for a window of n nodes as compute_end
 * gives them (the longest exterior's shared factor, the forward substitutions it keeps and a
 * unit vector's leading zeros skipped: exterior_factor, ext_columns in lanes, the AVX2 build's
 * where the processor has it) against a factorisation of that exterior alone and full solves,
 * and its columns and end correction against the baseline build's lanes (ext_columns_base)
 * and the columns one at a time (ext_columns_each), and the end correction without the columns
 * (window_end's); 0 if the same bits, 1 if not, -1 if it cannot (lugs, n + 4 > M or
 * n < 2, out of memory). */
int tirenv_ring__tread_end_check(tirenv_ring *r, size_t n)
{
    tirenv_ring_tread *T = r->tread;
    const size_t M = T->M, ne = M - n, Ne = 2 * ne;
    if (T->lugs || n < 2 || n + 4 > M)
        return -1;
    double *c1 = malloc(4 * NB * Ne * sizeof *c1);
    tband E;
    if (!c1 || tirenv_ring__tband_alloc(&E, Ne, 0)) {
        free(c1);
        return -1;
    }
    double *c2 = c1 + NB * Ne, *c3 = c2 + NB * Ne, *c4 = c3 + NB * Ne, Q[4][NB][NB];
    tirenv_ring__compute_end_by(T, 0, n, Q[0], c1, EXT_AUTO);
    tirenv_ring__compute_end_by(T, 0, n, Q[1], NULL, EXT_AUTO);
    tirenv_ring__compute_end_by(T, 0, n, Q[2], c3, EXT_EACH);
    tirenv_ring__compute_end_by(T, 0, n, Q[3], c4, EXT_BASE);
    band_reset(&E, Ne, 0);
    tirenv_ring__add_arc(&E, T, n, ne);
    int st = tirenv_ring__tband_factor(&E) ? -1 : 0;
    size_t eidx[NB];
    tirenv_ring__ext_index(Ne, eidx);
    for (size_t a = 0; a < NB && st == 0; ++a) {
        double *c = c2 + a * Ne;
        memset(c, 0, Ne * sizeof *c);
        c[eidx[a]] = 1;
        tirenv_ring__tband_solve(&E, c);
    }
    if (st == 0)
        st = !(tirenv_ring__same_bits(c1, c2, NB * Ne) &&
               tirenv_ring__same_bits(c1, c3, NB * Ne) &&
               tirenv_ring__same_bits(c1, c4, NB * Ne) &&
               tirenv_ring__same_bits(&Q[0][0][0], &Q[1][0][0], NB * NB) &&
               tirenv_ring__same_bits(&Q[0][0][0], &Q[2][0][0], NB * NB) &&
               tirenv_ring__same_bits(&Q[0][0][0], &Q[3][0][0], NB * NB));
    free(E.L);
    free(c1);
    return st;
}
