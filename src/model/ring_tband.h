/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the ring: the banded U D U^T factorisation and its solves (ring_tband.c) on which
 * the shear-coupled tread solves its window's and its exterior's systems (ring_shear.c,
 * ring_exterior.c; docs/models.md section 5.3, docs/performance.md 2.15, 2.27, 2.29). */
#ifndef TIRENV_RING_TBAND_H
#define TIRENV_RING_TBAND_H

#include <stddef.h>
#include <string.h>

enum { BAND_P = 4, TAIL = 4 };

/* A symmetric positive definite N x N matrix of bandwidth BAND_P whose last t <= TAIL rows are
 * dense (the window's ends coupled through the exterior): L[5 i + k] = A[i + k][i] for the band
 * rows i, k <= BAND_P (i + k < N - t); B[TAIL i + a] = A[N - t + a][i] for i < N - t (the tail
 * rows interleaved, so that a column's four are adjacent: two pairs of SSE2 lanes); T the dense
 * t x t tail (lower triangle). Factorised in place, A = U D U^T with U unit lower triangular
 * and D diagonal on the band's rows: L[5 i] = 1 / D[i], L[5 i + k] = U[i + k][i], B[TAIL i +
 * a] = U[N - t + a][i]; T then the Cholesky factor of the tail's Schur complement. Without
 * square roots, the chain from one pivot to the next is a division, two products and a
 * difference, and a solve's from one row to the next a product and a difference
 * (docs/performance.md 2.15). */
typedef struct {
    size_t N, t;
    double *L;
    double *B;
    double T[TAIL][TAIL];
} tband;

/* Two doubles in SSE2 lanes: each lane's product and difference are the scalar ones, bit for
 * bit (no fused multiply-add in the baseline x86-64 the library is built for, nor elsewhere
 * without -ffp-contract). */
typedef double v2d __attribute__((vector_size(2 * sizeof(double))));

static inline v2d v2_load(const double *p)
{
    v2d v;
    memcpy(&v, p, sizeof v);
    return v;
}

static inline void v2_store(double *p, v2d v) { memcpy(p, &v, sizeof v); }

/* Four doubles: in one AVX2 register in band_factor_avx2 (else two SSE2 pairs); either way
 * each lane's product and difference are the scalar ones, bit for bit. */
typedef double v4d __attribute__((vector_size(4 * sizeof(double))));

/* By pointer, not by value: a function passing a v4d would have an ABI that depends on
 * whether AVX is enabled (GCC's -Wpsabi). */
static inline void v4_load(v4d *v, const double *p) { memcpy(v, p, sizeof *v); }

static inline void v4_store(double *p, const v4d *v) { memcpy(p, v, sizeof *v); }

static inline void band_reset(tband *A, size_t N, size_t t)
{
    A->N = N;
    A->t = t;
    memset(A->L, 0, (BAND_P + 1) * N * sizeof *A->L);
    if (t > 0)
        memset(A->B, 0, TAIL * N * sizeof *A->B);
    memset(A->T, 0, sizeof A->T);
}

/* A[k][i] += v, i <= k, k - i <= BAND_P unless row k is a tail row. */
static inline void band_add(tband *A, size_t i, size_t k, double v)
{
    const size_t m = A->N - A->t;
    if (k < m)
        A->L[(BAND_P + 1) * i + (k - i)] += v;
    else if (i < m)
        A->B[TAIL * i + (k - m)] += v;
    else
        A->T[k - m][i - m] += v;
}


/* The tail columns of the window's band that assemble may write before the factorisation
 * (fill_window zeroes these, and only these): the end correction's coupling of the first
 * unknowns (columns below FRESH_FROM) and the band's entries in the tail rows (the last
 * BAND_P columns). The others' tail entries are zero until band_factor's first update of
 * them (factor_column's fresh). */
enum { FRESH_FROM = BAND_P + 1 };

/* Every CKS-th column i, band_factor_from keeps the factorisation's state as it stands before
 * it (CK_LEN doubles), from which band_refactor starts again: the tail block's accumulators
 * (CK_ACC, the lower triangle by rows), then the band's and the tail rows' entries of columns
 * i .. i + BAND_P - 1, the only ones that the columns before i have updated and i has not
 * factorised. */
enum {
    CKS = 16,
    CK_ACC = TAIL * (TAIL + 1) / 2,
    CK_LEN = CK_ACC + (BAND_P + 1 + TAIL) * BAND_P
};

/* The AVX2 builds of the factorisation and of the exterior's columns, where the compiler can
 * (ring_tband.c's band_factor_avx2, ring_exterior.c's ext_columns_avx2), taken where the
 * processor has it. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(TIRENV_RING_NO_AVX2)
#define TIRENV_RING_AVX2 1
#else
#define TIRENV_RING_AVX2 0
#endif

/* Room for A's N x N with a tail of t rows (L, and B if t > 0; one allocation, A->L to free).
 * Nonzero if out of memory. */
int tirenv_ring__tband_alloc(tband *A, size_t N, size_t t);
/* A = U D U^T in place, from column 0: nonzero if not positive definite. */
int tirenv_ring__tband_factor(tband *A);
/* The same from column q0 (acc0 its tail accumulators), fresh tail columns taken as zero,
 * checkpoints into ck (may be NULL), the band's entries copied from src as reached (NULL: A's
 * own): the AVX2 build where the processor has it, else the baseline's. */
int tirenv_ring__tband_factor_from(tband *A, int fresh, size_t q0, const double acc0[CK_ACC],
                                   double *ck, const double *src);
/* The baseline build's and (TIRENV_RING_AVX2) the AVX2 build's, whatever the processor (the
 * tests compare them). */
int tirenv_ring__tband_factor_base(tband *A, int fresh, size_t q0, const double acc0[CK_ACC],
                                   double *ck, const double *src);
#if TIRENV_RING_AVX2
int tirenv_ring__tband_factor_avx2(tband *A, int fresh, size_t q0, const double acc0[CK_ACC],
                                   double *ck, const double *src);
#endif
/* tirenv_ring__tband_factor_from, and x's forward substitution in the same pass where it can
 * (*fused 1: x then waits for tirenv_ring__tband_solve_rest). */
int tirenv_ring__tband_factor_x(tband *A, int fresh, size_t q0, const double acc0[CK_ACC],
                                double *ck, const double *src, double x[], int *fused);
/* Checkpoint q (a multiple of CKS) of ck back into A; returns its tail accumulators. */
const double *tirenv_ring__tband_ck_restore(const double *ck, tband *A, size_t q);
/* The window's factor F of its system S, P the system before it (F its factor if *ok), kept
 * up to the first column that changed; S and P swap. x (may be NULL): its forward
 * substitution too where it can (*fused). Nonzero if not positive definite. */
int tirenv_ring__tband_refactor(tband *S, tband *P, tband *F, double *ck, int *ok, double x[],
                                int *fused);
/* The first column of S (m band rows) whose entries differ from P's; the checkpoint column a
 * restart at first change p takes (0: from the start). */
size_t tirenv_ring__tband_first_change(const tband *S, const tband *P, size_t m);
size_t tirenv_ring__tband_restart_column(size_t p, size_t m);
/* Solves A x = b with the factor, x overwriting b: from the first row of b that is not +0. */
void tirenv_ring__tband_solve(const tband *A, double x[]);
/* The same from row i0, x's rows before it holding their z (U^-1 b) already. */
void tirenv_ring__tband_solve_from(const tband *A, double x[], size_t i0);
/* Without a tail (t = 0): the forward substitution alone, from row i0, x then U^-1 b. */
void tirenv_ring__tband_forward(const tband *A, double x[], size_t i0);
/* The solve after tirenv_ring__tband_factor_x's fused forward substitution. */
void tirenv_ring__tband_solve_rest(const tband *A, double x[]);

#endif
