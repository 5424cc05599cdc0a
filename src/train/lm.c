/* Levenberg-Marquardt on the full Jacobian of the residuals (Hagan and Menhaj, "Training
 * feedforward networks with the Marquardt algorithm", 1994): the network is small (49
 * weights), so the p x p normal equations cost little next to the Jacobian itself.
 *
 * Levenberg damping (J^T J + mu I) dw = -J^T r and Nielsen's update of mu (1999). J^T J and
 * J^T r are formed a block of rows at a time (J is never stored whole), solved by Cholesky
 * (core/cholesky.c), and J is kept through rejected steps. Until version 0.1 a second solver handed
 * the same residuals to GSL's gsl_multifit_nlinear trust region; it took the same 77 epochs
 * to the same errors on the embedded data set in 0.226 s against this one's 0.022 s (it
 * stored the n x p Jacobian and formed J^T J with gslcblas's reference dsyrk), so when GSL
 * left this one stayed, alone, rather than moving to Minpack's lmder, which also
 * stores the whole Jacobian and factors it by QR (n p^2 flops against J^T J's n p^2/2).
 * - Choices that lost: MATLAB trainlm's update (mu x10 / x0.1) stalled where Nielsen's went
 *   on (tests' function, 100 epochs: training RMS 0.104 against 0.024 mm); GSL's default
 *   More scaling stalled at 2.5 mm on the same function (Levenberg: 0.024 mm); weight decay
 *   (adding 0.01 to 10 times |w|^2 to the error) lowered the embedded data set's control
 *   error by 6 % at most (at 0.01) and raised it from 0.1 up, so it is not offered.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/cholesky.h"
#include "train/train_impl.h"

/* Rows of J formed at a time: 256 x 56 doubles (112 KiB) stay in L2. A multiple of
 * LM_BLOCK, the rows lm_accumulate takes together. */
enum { LM_ROWS = 256 };

/* Columns of J^T J summed together: one AVX-512 register of doubles. Rows of J and of J^T J
 * are padded to a multiple of it. */
enum { LM_LANES = 8 };

/* Rows of J added to J^T J together, so that each row of it is loaded and stored once per
 * LM_BLOCK rows. LM_ROWS is a multiple of it. */
enum { LM_BLOCK = 8 };

/* As in nn/network.c: the kernel below is compiled per instruction set and picked at load
 * time; ISO C mode keeps FMA contraction off, so every clone sums the same way. Not under
 * ThreadSanitizer, whose runtime is not up when the ifunc resolver runs. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__) &&     \
    !defined(TIRENV_NN_NO_CLONES) && !defined(__SANITIZE_THREAD__)
#define LM_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define LM_CLONES
#endif

typedef struct {
    tirenv_lm_settings set;
    size_t n, p;
    size_t P;              /* p rounded up to LM_LANES: the row stride of Jc and A */
    double mu, nu;         /* damping and its growth factor (Nielsen); mu = 0: not started */
    double *A;             /* p x P: J^T J, lower triangle */
    double *b;             /* P: J^T r */
    double *M;             /* p x p: A + mu I, then its Cholesky factor */
    double *dw;            /* p: the step */
    double *w_old;         /* p */
    double *Jc;            /* LM_ROWS x P: a block of rows of J, zero-padded */
    double *yc;            /* LM_ROWS: outputs, then residuals, of the block */
    double *y;             /* n: outputs of a trial step */
} lm_state;

static void lm_free(void *state)
{
    lm_state *st = state;
    if (!st)
        return;
    free(st->A);
    free(st->b);
    free(st->M);
    free(st->dw);
    free(st->w_old);
    free(st->Jc);
    free(st->yc);
    free(st->y);
    free(st);
}

static double lm_inv_std(const tirenv_nn *nn)
{
    double out_std;
    tirenv_nn_scaling(nn, NULL, NULL, NULL, &out_std);
    return 1.0 / out_std;
}

/* The weights LM takes at most: its normal equations keep two p x p matrices (A and M), 16 p^2
 * bytes, 400 MB at 5000 (the paper's 4-8-1 has 49). Four hidden layers of 64 (12,865 weights)
 * need 2.65 GB a restart by that count; run, one held 1.3 GB and had not finished an epoch
 * after 20 s. rprop's memory is linear in p. */
enum { LM_MAX_WEIGHTS = 5000 };

static int lm_alloc(void **state, const tirenv_nn *nn, const tirenv_samples *train,
                    const tirenv_train_settings *s, tirenv_diag *diag)
{
    const size_t n_w = tirenv_nn_n_weights(nn);
    *state = NULL;
    if (n_w > LM_MAX_WEIGHTS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "topology",
                            "%zu weights; Levenberg-Marquardt keeps two matrices of their "
                            "square (%.3g GB), so it takes at most %d: a smaller network, or "
                            "the rprop trainer", n_w, 16.0 * (double)n_w * (double)n_w / 1e9,
                            LM_MAX_WEIGHTS);
    lm_state *st = calloc(1, sizeof *st);
    *state = st;
    if (!st)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    st->set = s->lm;
    st->n = train->n;
    st->p = tirenv_nn_n_weights(nn);
    const size_t n = st->n, p = st->p;
    st->P = (p + LM_LANES - 1) / LM_LANES * LM_LANES;
    st->A = calloc(p * st->P, sizeof(double));
    st->b = calloc(st->P, sizeof(double));
    st->M = malloc(p * p * sizeof(double));
    st->dw = malloc(p * sizeof(double));
    st->w_old = malloc(p * sizeof(double));
    st->Jc = calloc(LM_ROWS * st->P, sizeof(double));  /* the padding stays 0 */
    st->yc = calloc(LM_ROWS, sizeof(double));
    st->y = malloc(n * sizeof(double));
    if (!st->A || !st->b || !st->M || !st->dw || !st->w_old || !st->Jc || !st->yc ||
        !st->y) {
        lm_free(st);
        *state = NULL;
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    return TIRENV_OK;
}

static int lm_set(void *state, tirenv_nn *nn, const tirenv_samples *train, tirenv_diag *diag)
{
    lm_state *st = state;
    (void)nn;
    (void)train;
    (void)diag;
    st->mu = 0;
    st->nu = 2;
    return TIRENV_OK;
}

/* LM_LANES doubles as one GCC generic vector (the compiler splits it into what the target
 * has), so the kernel below is vectorised the same at -O2 and -O3. */
typedef double lm_vec __attribute__((vector_size(LM_LANES * sizeof(double))));

/* a[0..LM_LANES) += sum over LM_BLOCK rows k of c[k] * g_k[j0..], g_k = g + k*P + j0, through
 * memcpy (no alignment assumed). */
#if defined(__GNUC__)
__attribute__((always_inline))  /* compiled for the caller's clone's instruction set */
#endif
static inline void lm_axpy(double *a, const double *c, size_t c_stride, const double *g,
                           size_t P)
{
    lm_vec av, sum, v;
    memcpy(&v, g, sizeof v);
    sum = c[0] * v;
    for (size_t k = 1; k < LM_BLOCK; ++k) {
        memcpy(&v, g + k * P, sizeof v);
        sum += c[k * c_stride] * v;
    }
    memcpy(&av, a, sizeof av);
    av += sum;
    memcpy(a, &av, sizeof av);
}

/* A += sum_k g_k g_k^T and b += sum_k r_k g_k over m rows g_k of J (stride P, zero columns
 * past p, and zero rows up to a multiple of LM_BLOCK). LM_BLOCK rows at a time, so each row
 * of A is loaded and stored once per block; LM_LANES columns at a time, so the lower triangle is
 * rounded up to whole groups and a few entries above the diagonal are summed too (never
 * read). This replaced gslcblas's reference dsyrk, which took 70 % of an LM run. */
LM_CLONES static void lm_accumulate(size_t m, size_t p, size_t P, const double *restrict J,
                                    const double *restrict r, double *restrict A,
                                    double *restrict b)
{
    for (size_t k = 0; k < m; k += LM_BLOCK) {
        const double *g = J + k * P;
        for (size_t i = 0; i < p; ++i)
            for (size_t j0 = 0; j0 <= i; j0 += LM_LANES)
                lm_axpy(A + i * P + j0, g + i, P, g + j0, P);
        for (size_t j0 = 0; j0 < P; j0 += LM_LANES)
            lm_axpy(b + j0, r + k, 1, g + j0, P);
    }
}

/* A = J^T J (lower triangle), b = J^T r, returns r.r, forming LM_ROWS rows of J at a time. */
static double lm_normal_equations(lm_state *st, tirenv_nn *nn, const tirenv_samples *train)
{
    const size_t p = st->p, P = st->P, n_in = train->n_in;
    const double inv_std = lm_inv_std(nn);
    double sse = 0;
    memset(st->A, 0, p * P * sizeof(double));
    memset(st->b, 0, P * sizeof(double));
    for (size_t k0 = 0; k0 < train->n; k0 += LM_ROWS) {
        const size_t m = train->n - k0 < LM_ROWS ? train->n - k0 : LM_ROWS;
        const size_t m_blk = (m + LM_BLOCK - 1) / LM_BLOCK * LM_BLOCK;
        for (size_t k = 0; k < m; ++k) {
            double *g = st->Jc + k * P;
            const double y = tirenv_nn_gradient(nn, train->x + (k0 + k) * n_in, g);
            const double scale = tirenv_train__residual_scale(train, k0 + k, inv_std);
            const double r = (y - train->y[k0 + k]) * scale;
            st->yc[k] = r;
            sse += r * r;
            for (size_t j = 0; j < p; ++j)
                g[j] *= scale;
        }
        for (size_t k = m; k < m_blk; ++k) {  /* the zero rows of a short last block */
            memset(st->Jc + k * P, 0, P * sizeof(double));
            st->yc[k] = 0;
        }
        lm_accumulate(m_blk, p, P, st->Jc, st->yc, st->A, st->b);
    }
    return sse;
}

/* Nielsen's damping update (H. B. Nielsen, "Damping parameter in Marquardt's method", 1999;
 * GSL's trs_lm uses the same): after a step that lowers the error, by a gain ratio rho of
 * actual to predicted reduction, mu *= max(1/3, 1 - (2 rho - 1)^3); after one that does not,
 * mu *= nu, nu *= 2. With the Jacobian kept, a rejected step costs one Cholesky (p^3/3 = 4e4
 * flops) and one forward pass. */
static int lm_epoch_cholesky(lm_state *st, tirenv_nn *nn, const tirenv_samples *train,
                             double *train_sse)
{
    double *w = tirenv_nn_weights(nn);
    const size_t p = st->p;
    const double sse = lm_normal_equations(st, nn, train);
    double diag_max = 0;
    for (size_t j = 0; j < p; ++j)
        diag_max = fmax(diag_max, st->A[j * st->P + j]);
    if (!(diag_max > 0))
        diag_max = 1;  /* J = 0: every neuron saturated; any positive scale will do */
    if (st->mu == 0)  /* a new restart: Nielsen's start */
        st->mu = st->set.tau * diag_max;
    *train_sse = sse;
    memcpy(st->w_old, w, p * sizeof(double));
    for (;;) {
        for (size_t i = 0; i < p; ++i) {  /* the factorisation reads the lower triangle only */
            double *row = st->M + i * p;
            memcpy(row, st->A + i * st->P, (i + 1) * sizeof(double));
            row[i] += st->mu;
        }
        /* Not positive definite (J^T J singular to round-off and mu tiny): damp more. */
        if (tirenv_core__cholesky(st->M, p, p) == 0) {
            tirenv_core__cholesky_solve(st->M, p, p, st->b, st->dw);
            /* dw solves (A + mu I) dw = g; the step is -dw. Predicted reduction of sse:
             * dw.(mu dw + g) (twice that of E = sse/2). */
            double predicted = 0;
            for (size_t j = 0; j < p; ++j) {
                const double d = st->dw[j];
                w[j] = st->w_old[j] - d;
                predicted += d * (st->mu * d + st->b[j]);
            }
            const double sse_new = tirenv_train__sse(nn, train, st->y);
            if (sse_new < sse) {
                const double rho = predicted > 0 ? (sse - sse_new) / predicted : 1;
                const double c = 2 * rho - 1;
                st->mu *= fmax(1.0 / 3.0, 1 - c * c * c);
                st->nu = 2;
                return TIRENV_ECONTINUE;
            }
            memcpy(w, st->w_old, p * sizeof(double));
        }
        st->mu *= st->nu;
        st->nu *= 2;
        if (st->mu > st->set.mu_max * diag_max)
            return TIRENV_OK;  /* no step lowers the error: a minimum, to round-off */
    }
}

static int lm_epoch(void *state, tirenv_nn *nn, const tirenv_samples *train, tirenv_rng *rng,
                    double *train_sse, tirenv_diag *diag)
{
    (void)rng;
    (void)diag;
    return lm_epoch_cholesky(state, nn, train, train_sse);
}

const struct tirenv_trainer_type tirenv_train__lm_type = {
    .name = "lm",
    .alloc = lm_alloc,
    .set = lm_set,
    .epoch = lm_epoch,
    .free = lm_free,
};
