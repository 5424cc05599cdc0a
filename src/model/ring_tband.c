/* SPDX-License-Identifier: Apache-2.0 */
/* The shear-coupled tread's banded systems (docs/models.md section 5.3): a symmetric positive
 * definite matrix of bandwidth BAND_P with a dense tail (ring_tband.h), factorised A = U D U^T by
 * columns, kept and restarted from checkpoints when a later system changes from some column on,
 * and solved; the baseline (SSE2) and AVX2 builds of the same operations, chosen at run time
 * (docs/performance.md 2.15, 2.27, 2.29). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "core/cholesky.h"
#include "model/ring_tband.h"
#include "model/ring_impl.h"

/* One interior column i of band_factor with the full tail (i + BAND_P < m), in pairs of lanes
 * (the baseline build's, band_factor_base): its band and tail entries scaled by 1 / d into U's
 * column, and its updates of the next BAND_P columns, two SSE2 lanes at a time; the tail
 * block's lower triangle, and the next column's d and a1 (d_a1), in the caller's registers.
 * fresh: column i + BAND_P's tail entries were never written (fill_window leaves them unset,
 * stale from an earlier window, and they are taken as zero), so its update starts from zero
 * rather than from memory (0 - p, the same operation on the same operands). Nonzero if the
 * pivot is not positive. */
static inline __attribute__((always_inline)) int factor_column2(double *L, double *B, size_t i,
                                                                v2d *t10, v2d *t20, v2d *t30,
                                                                v2d *t32, double *t00,
                                                                double *t22, v2d *d_a1,
                                                                const int fresh,
                                                                const double *src)
{
    double *c = L + (BAND_P + 1) * i;
    /* d and a1 (c[0], c[1]) as the column before left them, from registers: read back from
     * memory, its store and their load would lengthen the chain from pivot to pivot. */
    const double d = (*d_a1)[0];
    if (!(d > 0))
        return 1;
    { /* column i + BAND_P's entries, before this column's update of them (src: A's own, or
       * the system band_refactor copies from) */
        const double *s4 = src + (BAND_P + 1) * (i + BAND_P);
        double *d4 = c + BAND_P * (BAND_P + 1);
        v2_store(d4, v2_load(s4));
        v2_store(d4 + 2, v2_load(s4 + 2));
        d4[4] = s4[4];
    }
    const double dinv = 1 / d;
    const double a1 = (*d_a1)[1], a2 = c[2], a3 = c[3], a4 = c[4];
    const double g1 = a1 * dinv, g2 = a2 * dinv, g3 = a3 * dinv, g4 = a4 * dinv;
    c[0] = dinv;
    c[1] = g1, c[2] = g2, c[3] = g3, c[4] = g4;
    double *r1 = c + (BAND_P + 1), *r2 = r1 + (BAND_P + 1), *r3 = r2 + (BAND_P + 1),
           *r4 = r3 + (BAND_P + 1);
    /* r1[0] -= a1 g1, r1[1] -= a2 g1, r1[2] -= a3 g1, r1[3] -= a4 g1; r2[0] -= a2 g2,
     * r2[1] -= a3 g2, r2[2] -= a4 g2; r3[0] -= a3 g3, r3[1] -= a4 g3; r4[0] -= a4 g4. */
    const v2d a12 = {a1, a2}, a23 = {a2, a3}, a34 = {a3, a4};
    const v2d vg1 = {g1, g1}, vg2 = {g2, g2}, vg3 = {g3, g3};
    *d_a1 = v2_load(r1) - a12 * vg1;
    v2_store(r1, *d_a1);
    v2_store(r1 + 2, v2_load(r1 + 2) - a34 * vg1);
    v2_store(r2, v2_load(r2) - a23 * vg2);
    r2[2] -= a4 * g2;
    v2_store(r3, v2_load(r3) - a34 * vg3);
    r4[0] -= a4 * g4;
    /* The tail rows' entries of columns i .. i + 4: h = B[a][i], U[a][i] = h / d into B[a][i],
     * then B[a][i + k] -= U[a][i] a_k, each entry's one operation of this column. */
    double *b = B + TAIL * i;
    const v2d vdinv = {dinv, dinv};
    const v2d h01 = v2_load(b), h23 = v2_load(b + 2);
    const v2d u01 = h01 * vdinv, u23 = h23 * vdinv;
    v2_store(b, u01);
    v2_store(b + 2, u23);
    const double ak[BAND_P] = {a1, a2, a3, a4};
    for (size_t k = 1; k <= BAND_P; ++k) {
        const v2d va = {ak[k - 1], ak[k - 1]};
        double *bk = b + TAIL * k;
        const v2d zero = {0, 0};
        const int from_zero = fresh && k == BAND_P;
        v2_store(bk, (from_zero ? zero : v2_load(bk)) - u01 * va);
        v2_store(bk + 2, (from_zero ? zero : v2_load(bk + 2)) - u23 * va);
    }
    /* T[a][b] -= U[a][i] h_b, b <= a. */
    const v2d v1 = {u01[1], u01[1]}, v2 = {u23[0], u23[0]}, v3 = {u23[1], u23[1]};
    *t00 -= u01[0] * h01[0];
    *t10 -= v1 * h01;
    *t20 -= v2 * h01;
    *t22 -= u23[0] * h23[0];
    *t30 -= v3 * h01;
    *t32 -= v3 * h23;
    return 0;
}


/* The tail block's lower triangle as factor_column4 carries it in registers through the
 * interior columns: T[0][0], then rows 1 to 3 as four lanes each (T[a][0 .. 3]; the lanes
 * past the diagonal are updated too, and never read). */
typedef struct {
    double t00;
    v4d t1, t2, t3;
} tail_acc;

/* The forward substitution that band_factor_fwd_avx2 runs with the factorisation: the last
 * four rows' z (z1 the nearest) and the tail's right-hand side y. */
typedef struct {
    double z1, z2, z3, z4;
    v4d y;
} fwd_state;

/* factor_column2 in fours of lanes (the AVX2 build's, band_factor_avx2: split into pairs, as
 * the baseline would have them, it costs more than factor_column2): its band and tail entries
 * scaled by 1 / d into U's column, and its updates of the next BAND_P columns; the tail
 * block's lower triangle (acc), the next column's d (*dp) and d, a1, a2, a3 (nx), and the
 * column after it's entries 0 .. 3 (p1), in the caller's registers. fresh: column i + BAND_P's
 * tail entries were never written (fill_window leaves them unset, stale from an earlier
 * window, and they are taken as zero), so its update starts from zero rather than from memory
 * (0 - p, the same operation on the same operands). fx (not NULL): row i of fx's forward
 * substitution as well (fs its state; band_factor_fwd_avx2). Nonzero if the pivot is not
 * positive.
 *
 * Its time is the chain from pivot to pivot, d -> 1 / d -> g1 = a1 / d -> d' = r1[0] - a1 g1
 * (docs/performance.md 2.29): the pivot is carried as a scalar, so that no broadcast into
 * four lanes lies on that chain (the four lanes of r1's update give the same d' in lane 0,
 * stored with them); r1, the next column's entries, comes from a register and not from
 * memory, where the last column's updates of it were stores of one, two and three lanes that
 * a load of four cannot take forwarded, and so waits until they reach the cache; and each
 * column's updates of r2, r3 and r4 are stores of four lanes, the lanes it must not change
 * taken back from the load (x - 0 g is not x for x = -0), so that the next column's loads
 * of them are forwarded. */
static inline __attribute__((always_inline)) int factor_column4(double *L, double *B, size_t i,
                                                               tail_acc *acc, double *dp,
                                                               v4d *nx, v4d *p1,
                                                               const int fresh,
                                                               const double *src, double *fx,
                                                               fwd_state *fs)
{
    double *c = L + (BAND_P + 1) * i;
    /* d, a1, a2 and a3 (c[0 .. 3]) as the column before left them, from registers: read
     * back from memory, its stores and their loads would lengthen the chain from pivot to
     * pivot. */
    const double d = *dp;
    if (!(d > 0))
        return 1;
    /* column i + BAND_P's entries, before this column's update of them (src: A's own, or the
     * system band_refactor copies from); stored with r4's update below */
    const double *s4 = src + (BAND_P + 1) * (i + BAND_P);
    double *d4 = c + BAND_P * (BAND_P + 1);
    v4d s;
    v4_load(&s, s4);
    d4[4] = s4[4];
    const double dinv = 1 / d;
    const double a1 = (*nx)[1], a4 = c[4];
    const v4d a14 = {a1, (*nx)[2], (*nx)[3], a4}, g = a14 * (v4d){dinv, dinv, dinv, dinv};
    const double g1 = a1 * dinv; /* g[0]'s operation, in a scalar register */
    c[0] = dinv;
    v4_store(c + 1, &g);
    double *r1 = c + (BAND_P + 1), *r2 = r1 + (BAND_P + 1), *r3 = r2 + (BAND_P + 1);
    /* r1[0] -= a1 g1, r1[1] -= a2 g1, r1[2] -= a3 g1, r1[3] -= a4 g1; r2[0] -= a2 g2,
     * r2[1] -= a3 g2, r2[2] -= a4 g2; r3[0] -= a3 g3, r3[1] -= a4 g3; r4[0] -= a4 g4. */
    *dp = (*p1)[0] - a1 * g1;
    *nx = *p1 - a14 * (v4d){g1, g1, g1, g1};
    v4_store(r1, nx);
    v4d r2v, r3v;
    v4_load(&r2v, r2);
    const v4d a24 = __builtin_shufflevector(a14, a14, 1, 2, 3, 3);
    const v4d t2 = r2v - a24 * __builtin_shufflevector(g, g, 1, 1, 1, 1);
    *p1 = __builtin_shufflevector(t2, r2v, 0, 1, 2, 7);
    v4_store(r2, p1);
    v4_load(&r3v, r3);
    const v4d a34 = __builtin_shufflevector(a14, a14, 2, 3, 3, 3);
    const v4d t3 = r3v - a34 * __builtin_shufflevector(g, g, 2, 2, 2, 2);
    const v4d r3n = __builtin_shufflevector(t3, r3v, 0, 1, 6, 7);
    v4_store(r3, &r3n);
    const v4d t4 = s - __builtin_shufflevector(a14, a14, 3, 3, 3, 3) *
                           __builtin_shufflevector(g, g, 3, 3, 3, 3);
    const v4d r4n = __builtin_shufflevector(t4, s, 0, 5, 6, 7);
    v4_store(d4, &r4n);
    /* The tail rows' entries of columns i .. i + 4: h = B[a][i], U[a][i] = h / d into B[a][i],
     * then B[a][i + k] -= U[a][i] a_k, each entry's one operation of this column. */
    double *b = B + TAIL * i;
    v4d h;
    v4_load(&h, b);
    const v4d u = h * (v4d){dinv, dinv, dinv, dinv};
    v4_store(b, &u);
    const double ak[BAND_P] = {a1, a14[1], a14[2], a4};
    for (size_t k = 1; k <= BAND_P; ++k) {
        const v4d va = {ak[k - 1], ak[k - 1], ak[k - 1], ak[k - 1]};
        double *bk = b + TAIL * k;
        const v4d zero = {0, 0, 0, 0};
        const int from_zero = fresh && k == BAND_P;
        v4d x = zero;
        if (!from_zero)
            v4_load(&x, bk);
        x -= u * va;
        v4_store(bk, &x);
    }
    /* T[a][b] -= U[a][i] h_b, b <= a. */
    acc->t00 -= u[0] * h[0];
    acc->t1 -= (v4d){u[1], u[1], u[1], u[1]} * h;
    acc->t2 -= (v4d){u[2], u[2], u[2], u[2]} * h;
    acc->t3 -= (v4d){u[3], u[3], u[3], u[3]} * h;
    if (fx) { /* row i of the forward substitution, as band_solve_t's (fwd_row, tail_fwd) */
        double v = fx[i];
        if (i >= BAND_P) {
            v -= L[(BAND_P + 1) * (i - 4) + 4] * fs->z4;
            v -= L[(BAND_P + 1) * (i - 3) + 3] * fs->z3;
            v -= L[(BAND_P + 1) * (i - 2) + 2] * fs->z2;
            v -= L[(BAND_P + 1) * (i - 1) + 1] * fs->z1;
        } else {
            for (size_t k = i; k >= 1; --k)
                v -= L[(BAND_P + 1) * (i - k) + k] * fx[i - k];
        }
        fx[i] = v;
        fs->y -= u * (v4d){v, v, v, v};
        fs->z4 = fs->z3, fs->z3 = fs->z2, fs->z2 = fs->z1, fs->z1 = v;
    }
    return 0;
}

/* Before interior column i of A: its checkpoint's state into ck's slot for it, where i is the
 * next multiple of CKS to keep (*next, moved on to the one after; SIZE_MAX: none kept). One
 * comparison a column. */
static inline void ck_save(double *ck, const double *L, const double *B, size_t i,
                           const tail_acc *acc, size_t *next)
{
    if (i != *next)
        return;
    *next += CKS;
    ck += CK_LEN * (i / CKS);
    ck[0] = acc->t00, ck[1] = acc->t1[0], ck[2] = acc->t1[1];
    ck[3] = acc->t2[0], ck[4] = acc->t2[1], ck[5] = acc->t2[2];
    v4_store(ck + 6, &acc->t3);
    memcpy(ck + CK_ACC, L + (BAND_P + 1) * i, (BAND_P + 1) * BAND_P * sizeof *ck);
    memcpy(ck + CK_ACC + (BAND_P + 1) * BAND_P, B + TAIL * i, TAIL * BAND_P * sizeof *ck);
}

/* ck_save with the tail block's accumulators in pairs (factor_column2's). */
static inline void ck_save2(double *ck, const double *L, const double *B, size_t i, double t00,
                            v2d t10, v2d t20, double t22, v2d t30, v2d t32, size_t *next)
{
    if (i != *next)
        return;
    *next += CKS;
    ck += CK_LEN * (i / CKS);
    ck[0] = t00, ck[1] = t10[0], ck[2] = t10[1], ck[3] = t20[0], ck[4] = t20[1];
    ck[5] = t22, ck[6] = t30[0], ck[7] = t30[1], ck[8] = t32[0], ck[9] = t32[1];
    memcpy(ck + CK_ACC, L + (BAND_P + 1) * i, (BAND_P + 1) * BAND_P * sizeof *ck);
    memcpy(ck + CK_ACC + (BAND_P + 1) * BAND_P, B + TAIL * i, TAIL * BAND_P * sizeof *ck);
}

/* The checkpoint of column q (a multiple of CKS) back into A's columns q .. q + BAND_P - 1;
 * returns its tail block's accumulators (band_factor_from's acc0). */
const double *tirenv_ring__tband_ck_restore(const double *ck, tband *A, size_t q)
{
    ck += CK_LEN * (q / CKS);
    memcpy(A->L + (BAND_P + 1) * q, ck + CK_ACC, (BAND_P + 1) * BAND_P * sizeof *ck);
    memcpy(A->B + TAIL * q, ck + CK_ACC + (BAND_P + 1) * BAND_P, TAIL * BAND_P * sizeof *ck);
    return ck;
}

/* U D U^T by columns, right-looking: O(N (BAND_P + t)^2). Nonzero if not positive definite.
 * With the full tail, the interior columns (all but the last BAND_P of the band) come first,
 * unrolled (factor_column), the tail block's lower triangle held in registers until they end:
 * each entry gets the same operations in the same order as in the general loop below, so the
 * same bits. fresh: the tail's entries of the columns from FRESH_FROM to m - BAND_P - 1 are
 * unset (fill_window), zero until their first update. From column q0 (0: all; else an
 * interior column, the columns before it factorised and their updates of the later ones
 * applied, acc0 the tail block's accumulators then: band_refactor); ck (may be NULL): the
 * state before every CKS-th interior column from q0 on, into ck[CK_LEN (i / CKS)]. wide: the
 * AVX2 kernel (factor_column4), with fx (not NULL) fx's forward substitution of the interior
 * columns' rows (from q0, the rows before it done, the tail's right-hand side in fx's tail
 * rows before and after); *i_end the first column not interior. */
static inline __attribute__((always_inline)) int
band_factor_body(tband *A, const int fresh, size_t q0, const double acc0[CK_ACC], double *ck,
                 const double *src, const int wide, double *fx, size_t *i_end)
{
    if (!src)
        src = A->L;
    const size_t N = A->N, t = A->t, m = N - t;
    /* L and B in locals: the columns' stores (memcpy's, which may alias anything) would
     * otherwise make the compiler load them again from A at every column. */
    double *const L = A->L, *const B = A->B;
    size_t i = q0;
    if (t == TAIL && m > BAND_P && !wide) {
        double(*T)[TAIL] = A->T;
        v2d t10 = {T[1][0], T[1][1]}, t20 = {T[2][0], T[2][1]}, t30 = {T[3][0], T[3][1]},
            t32 = {T[3][2], T[3][3]};
        double t00 = T[0][0], t22 = T[2][2];
        if (acc0) {
            t00 = acc0[0], t10 = (v2d){acc0[1], acc0[2]}, t20 = (v2d){acc0[3], acc0[4]};
            t22 = acc0[5], t30 = (v2d){acc0[6], acc0[7]}, t32 = (v2d){acc0[8], acc0[9]};
        }
        size_t ck_next = ck ? (i + CKS - 1) / CKS * CKS : SIZE_MAX;
        int broke = 0;
        v2d d_a1 = v2_load(L + (BAND_P + 1) * i); /* column i's d and a1 */
        /* Column i's update reaches column i + BAND_P: unset from i = FRESH_FROM - BAND_P
         * while i + BAND_P < m - BAND_P. */
        const size_t f0 = fresh ? FRESH_FROM - BAND_P : m,
                     f1 = fresh && m > 2 * BAND_P ? m - 2 * BAND_P : 0;
        for (; i + BAND_P < m && i < f0 && !broke; ++i) {
            ck_save2(ck, L, B, i, t00, t10, t20, t22, t30, t32, &ck_next);
            broke = factor_column2(L, B, i, &t10, &t20, &t30, &t32, &t00, &t22, &d_a1, 0, src);
        }
        for (; i < f1 && !broke; ++i) {
            ck_save2(ck, L, B, i, t00, t10, t20, t22, t30, t32, &ck_next);
            broke = factor_column2(L, B, i, &t10, &t20, &t30, &t32, &t00, &t22, &d_a1, 1, src);
        }
        for (; i + BAND_P < m && !broke; ++i) {
            ck_save2(ck, L, B, i, t00, t10, t20, t22, t30, t32, &ck_next);
            broke = factor_column2(L, B, i, &t10, &t20, &t30, &t32, &t00, &t22, &d_a1, 0, src);
        }
        T[0][0] = t00, T[1][0] = t10[0], T[1][1] = t10[1], T[2][0] = t20[0], T[2][1] = t20[1];
        T[2][2] = t22, T[3][0] = t30[0], T[3][1] = t30[1], T[3][2] = t32[0], T[3][3] = t32[1];
        if (broke)
            return 1;
    } else if (t == TAIL && m > BAND_P) {
        double(*T)[TAIL] = A->T;
        tail_acc acc = {T[0][0], {T[1][0], T[1][1], 0, 0}, {T[2][0], T[2][1], T[2][2], 0},
                        {T[3][0], T[3][1], T[3][2], T[3][3]}};
        if (acc0)
            acc = (tail_acc){acc0[0], {acc0[1], acc0[2], 0, 0}, {acc0[3], acc0[4], acc0[5], 0},
                             {acc0[6], acc0[7], acc0[8], acc0[9]}};
        size_t ck_next = ck ? (i + CKS - 1) / CKS * CKS : SIZE_MAX;
        int broke = 0;
        v4d nx, p1; /* column i's d, a1, a2 and a3; column i + 1's entries 0 .. 3 */
        v4_load(&nx, L + (BAND_P + 1) * i);
        v4_load(&p1, L + (BAND_P + 1) * (i + 1));
        double d = nx[0];
        fwd_state fs = {0, 0, 0, 0, {0, 0, 0, 0}};
        if (fx) {
            v4_load(&fs.y, fx + m);
            if (i >= BAND_P)
                fs.z1 = fx[i - 1], fs.z2 = fx[i - 2], fs.z3 = fx[i - 3], fs.z4 = fx[i - 4];
        }
        /* Column i's update reaches column i + BAND_P: unset from i = FRESH_FROM - BAND_P
         * while i + BAND_P < m - BAND_P. */
        const size_t f0 = fresh ? FRESH_FROM - BAND_P : m,
                     f1 = fresh && m > 2 * BAND_P ? m - 2 * BAND_P : 0;
        for (; i + BAND_P < m && i < f0 && !broke; ++i) {
            ck_save(ck, L, B, i, &acc, &ck_next);
            broke = factor_column4(L, B, i, &acc, &d, &nx, &p1, 0, src, fx, &fs);
        }
        for (; i < f1 && !broke; ++i) {
            ck_save(ck, L, B, i, &acc, &ck_next);
            broke = factor_column4(L, B, i, &acc, &d, &nx, &p1, 1, src, fx, &fs);
        }
        for (; i + BAND_P < m && !broke; ++i) {
            ck_save(ck, L, B, i, &acc, &ck_next);
            broke = factor_column4(L, B, i, &acc, &d, &nx, &p1, 0, src, fx, &fs);
        }
        if (fx)
            v4_store(fx + m, &fs.y);
        T[0][0] = acc.t00, T[1][0] = acc.t1[0], T[1][1] = acc.t1[1];
        T[2][0] = acc.t2[0], T[2][1] = acc.t2[1], T[2][2] = acc.t2[2];
        T[3][0] = acc.t3[0], T[3][1] = acc.t3[1], T[3][2] = acc.t3[2], T[3][3] = acc.t3[3];
        if (broke)
            return 1;
    }
    *i_end = i;
    for (; i < m; ++i) {
        double *c = L + (BAND_P + 1) * i;
        if (!(c[0] > 0))
            return 1;
        /* As factor_column: a_k (the column's entries) and h_a (its tail rows') before
         * they are scaled by 1 / d. */
        const double dinv = 1 / c[0];
        c[0] = dinv;
        const size_t kmax = m - 1 - i < BAND_P ? m - 1 - i : BAND_P;
        double u[TAIL];
        for (size_t a = 0; a < t; ++a)
            u[a] = B[TAIL * i + a] * dinv;
        for (size_t k1 = 1; k1 <= kmax; ++k1) {
            double *c1 = L + (BAND_P + 1) * (i + k1);
            const double g = c[k1] * dinv;
            for (size_t k2 = k1; k2 <= kmax; ++k2)
                c1[k2 - k1] -= c[k2] * g;
            for (size_t a = 0; a < t; ++a)
                B[TAIL * (i + k1) + a] -= u[a] * c[k1];
        }
        for (size_t a = 0; a < t; ++a)
            for (size_t b = 0; b <= a; ++b)
                A->T[a][b] -= u[a] * B[TAIL * i + b];
        for (size_t k = 1; k <= kmax; ++k)
            c[k] *= dinv;
        for (size_t a = 0; a < t; ++a)
            B[TAIL * i + a] = u[a];
    }
    /* The dense tail, Schur complement of the band: src/core's Cholesky. */
    return t > 0 && tirenv_core__cholesky(&A->T[0][0], t, TAIL) != 0;
}

/* band_factor_body compiled for the baseline (SSE2 on x86-64), its interior columns in pairs
 * (factor_column2), and, where the compiler can, for AVX2 in fours (factor_column4: 256-bit
 * registers hold a column's four tail entries and a tail block's row in one, and the
 * three-operand instructions save the copies); band_factor_from takes the AVX2 one where the
 * processor has it (docs/performance.md 2.27). The same IEEE operations on the same
 * operands in both, no FMA (AVX2 alone does not enable it, and ISO C mode does not contract),
 * so the same bits (tirenv_ring__tread_factor_isa). */
int tirenv_ring__tband_factor_base(tband *A, const int fresh, size_t q0,
                                   const double acc0[CK_ACC], double *ck, const double *src)
{
    size_t i_end;
    return band_factor_body(A, fresh, q0, acc0, ck, src, 0, NULL, &i_end);
}

#if TIRENV_RING_AVX2
__attribute__((target("avx2"))) int tirenv_ring__tband_factor_avx2(tband *A, const int fresh,
                                                                   size_t q0,
                                                                   const double acc0[CK_ACC],
                                                                   double *ck, const double *src)
{
    size_t i_end;
    return band_factor_body(A, fresh, q0, acc0, ck, src, 1, NULL, &i_end);
}
#endif

int tirenv_ring__tband_factor_from(tband *A, const int fresh, size_t q0,
                                   const double acc0[CK_ACC], double *ck, const double *src)
{
#if TIRENV_RING_AVX2
    if (__builtin_cpu_supports("avx2"))
        return tirenv_ring__tband_factor_avx2(A, fresh, q0, acc0, ck, src);
#endif
    return tirenv_ring__tband_factor_base(A, fresh, q0, acc0, ck, src);
}

int tirenv_ring__tband_factor(tband *A)
{
    return tirenv_ring__tband_factor_from(A, 0, 0, NULL, NULL, NULL);
}

/* Row i's z_i = v taken off the tail's right-hand side: y01, y23 with the full tail, else y. */
static inline __attribute__((always_inline)) void tail_fwd(const double *B, const size_t t,
                                                           size_t i, double v, v2d *y01,
                                                           v2d *y23, double y[])
{
    if (t == TAIL) {
        const v2d vx = {v, v};
        *y01 -= v2_load(B + TAIL * i) * vx;
        *y23 -= v2_load(B + TAIL * i + 2) * vx;
    } else {
        for (size_t k = 0; k < t; ++k)
            y[k] -= B[TAIL * i + k] * v;
    }
}

/* v less row i's products with the tail's solution (y01, y23 with the full tail, else y), in
 * order. */
static inline __attribute__((always_inline)) double tail_bwd(const double *B, const size_t t,
                                                             size_t i, double v, v2d y01,
                                                             v2d y23, const double y[])
{
    if (t == TAIL) { /* the products two at a time, subtracted in order */
        const v2d p01 = v2_load(B + TAIL * i) * y01, p23 = v2_load(B + TAIL * i + 2) * y23;
        v -= p01[0];
        v -= p01[1];
        v -= p23[0];
        v -= p23[1];
    } else {
        for (size_t k = 0; k < t; ++k)
            v -= B[TAIL * i + k] * y[k];
    }
    return v;
}

/* One interior row i of the forward substitution (i >= BAND_P), the rows before it a .. d
 * (d the nearest) from registers: z_i into x[i], its tail products taken off y. */
static inline __attribute__((always_inline)) double fwd_row(const tband *A, double x[],
                                                            const size_t t, size_t i, double a,
                                                            double b, double c, double d,
                                                            v2d *y01, v2d *y23, double y[])
{
    const double *l = A->L + (BAND_P + 1) * (i - 1);
    double v = x[i];
    v -= l[-3 * (BAND_P + 1) + 4] * a;
    v -= l[-2 * (BAND_P + 1) + 3] * b;
    v -= l[-(BAND_P + 1) + 2] * c;
    v -= l[1] * d;
    x[i] = v;
    tail_fwd(A->B, t, i, v, y01, y23, y);
    return v;
}

/* One interior row i of the back substitution (i + BAND_P < m), the rows after it a .. d (a
 * the nearest) from registers: the tail's products first (they wait on no row), then the
 * band's, the nearest row's last. */
static inline __attribute__((always_inline)) double bwd_row(const tband *A, double x[],
                                                            const size_t t, size_t i, double a,
                                                            double b, double c, double d,
                                                            v2d y01, v2d y23, const double y[])
{
    const double *l = A->L + (BAND_P + 1) * i;
    double v = tail_bwd(A->B, t, i, x[i] * l[0], y01, y23, y);
    v -= l[4] * d;
    v -= l[3] * c;
    v -= l[2] * b;
    v -= l[1] * a;
    x[i] = v;
    return v;
}

/* band_solve_t's forward substitution, rows i .. i1 - 1 (x's rows before i holding their z),
 * the tail's right-hand side in y01, y23 (the full tail) or y. */
static inline __attribute__((always_inline)) void band_fwd_t(const tband *A, double x[],
                                                             const size_t t, size_t i,
                                                             const size_t i1, v2d *y01,
                                                             v2d *y23, double y[])
{
    const double *L = A->L;
    const double *B = A->B;
    for (; i < i1 && i < BAND_P; ++i) {
        double v = x[i];
        for (size_t k = i; k >= 1; --k)
            v -= L[(BAND_P + 1) * (i - k) + k] * x[i - k];
        x[i] = v;
        tail_fwd(B, t, i, v, y01, y23, y);
    }
    if (i < i1) {
        /* The last BAND_P rows' unknowns in registers, not read back from x: a store and its
         * load would lengthen the chain. Four rows an iteration, so that they need no
         * moves. */
        double x4 = x[i - 4], x3 = x[i - 3], x2 = x[i - 2], x1 = x[i - 1];
        for (; i + 4 <= i1; i += 4) {
            const double v0 = fwd_row(A, x, t, i, x4, x3, x2, x1, y01, y23, y);
            const double v1 = fwd_row(A, x, t, i + 1, x3, x2, x1, v0, y01, y23, y);
            const double v2 = fwd_row(A, x, t, i + 2, x2, x1, v0, v1, y01, y23, y);
            const double v3 = fwd_row(A, x, t, i + 3, x1, v0, v1, v2, y01, y23, y);
            x4 = v0, x3 = v1, x2 = v2, x1 = v3;
        }
        for (; i < i1; ++i) {
            const double v = fwd_row(A, x, t, i, x4, x3, x2, x1, y01, y23, y);
            x4 = x3, x3 = x2, x2 = x1, x1 = v;
        }
    }
}

/* band_solve_t after its forward substitution: the tail's Schur complement solved for y (its
 * right-hand side), then the back substitution. */
static inline __attribute__((always_inline)) void band_bwd_t(const tband *A, double x[],
                                                             const size_t t, double y[])
{
    const size_t N = A->N, m = N - t;
    const double *L = A->L;
    const double *B = A->B;
    if (t > 0)
        tirenv_core__cholesky_solve(&A->T[0][0], t, TAIL, y, y);
    for (size_t a = 0; a < t; ++a)
        x[m + a] = y[a];
    v2d y01 = {0, 0}, y23 = {0, 0};
    if (t == TAIL) /* now the tail's solution */
        y01 = (v2d){y[0], y[1]}, y23 = (v2d){y[2], y[3]};
    size_t i = m;
    for (; i > 0 && i - 1 + BAND_P >= m; --i) { /* the last BAND_P rows */
        const size_t r = i - 1;
        double v = tail_bwd(B, t, r, x[r] * L[(BAND_P + 1) * r], y01, y23, y);
        for (size_t k = m - 1 - r; k >= 1; --k)
            v -= L[(BAND_P + 1) * r + k] * x[r + k];
        x[r] = v;
    }
    if (i > 0) {
        double x1 = x[i], x2 = x[i + 1], x3 = x[i + 2], x4 = x[i + 3];
        for (; i >= 4; i -= 4) {
            const double v0 = bwd_row(A, x, t, i - 1, x1, x2, x3, x4, y01, y23, y);
            const double v1 = bwd_row(A, x, t, i - 2, v0, x1, x2, x3, y01, y23, y);
            const double v2 = bwd_row(A, x, t, i - 3, v1, v0, x1, x2, y01, y23, y);
            const double v3 = bwd_row(A, x, t, i - 4, v2, v1, v0, x1, y01, y23, y);
            x1 = v3, x2 = v2, x3 = v1, x4 = v0;
        }
        for (; i > 0; --i) {
            const double v = bwd_row(A, x, t, i - 1, x1, x2, x3, x4, y01, y23, y);
            x4 = x3, x3 = x2, x2 = x1, x1 = v;
        }
    }
}

/* Solves A x = b with the factor, x overwriting b: z = U^-1 b, the tail's Schur complement
 * solved, x = U^-T (D^-1 z - the tail's share). O(N (BAND_P + t)). Each row's unknown waits on
 * the one before it (after it, going back), so a solve's time is that chain's: a row takes
 * the farther rows' products first, and U's unit diagonal leaves a product and a difference
 * from row to row, where a chain of four differences and a division was (docs/performance.md
 * 2.15). Inlined with t a
 * constant (band_solve): the tail's loops unrolled, its right-hand side y in registers, with the
 * full tail two lanes at a time; the same operations in the same order for every t. The
 * forward substitution may start at row i0, x's rows before it holding their z already (the
 * window's, band_solve: its leading +0 rows; the exterior's, ext_solve: a unit vector's
 * zeros or a kept y), and, without a tail, stop there (forward_only: x then holds U^-1 b). */
static inline __attribute__((always_inline)) void band_solve_t(const tband *A, double x[],
                                                               const size_t t, const size_t i0,
                                                               const int forward_only)
{
    const size_t m = A->N - t;
    double y[TAIL];
    for (size_t a = 0; a < t; ++a)
        y[a] = x[m + a];
    v2d y01 = {0, 0}, y23 = {0, 0};
    if (t == TAIL)
        y01 = (v2d){y[0], y[1]}, y23 = (v2d){y[2], y[3]};
    band_fwd_t(A, x, t, i0, m, &y01, &y23, y);
    if (forward_only)
        return;
    if (t == TAIL)
        y[0] = y01[0], y[1] = y01[1], y[2] = y23[0], y[3] = y23[1];
    band_bwd_t(A, x, t, y);
}

/* The first of b's rows 0 .. m whose bits are not +0 (m if none). */
static size_t leading_zeros(const double b[], size_t m)
{
    size_t i = 0;
    for (; i < m; ++i) {
        uint64_t u;
        memcpy(&u, &b[i], sizeof u);
        if (u != 0)
            break;
    }
    return i;
}

/* The window's systems have the tail, the exterior's none. A Newton step's right-hand side
 * (assemble) is zero up to the first node a point in contact loads: rows of +0 before it are
 * their own z (+0 less products with +0, each +0 or -0, stays +0; the factor's entries are
 * finite), and take nothing off the tail's right-hand side unless one of its entries is -0
 * (-0 - -0 is +0), so the forward substitution starts at the first row that is not +0, as
 * ext_solve's does at its unit vector's one. */
void tirenv_ring__tband_solve(const tband *A, double x[])
{
    if (A->t == TAIL) {
        const size_t m = A->N - TAIL;
        int neg0 = 0;
        for (size_t a = 0; a < TAIL; ++a)
            neg0 |= x[m + a] == 0 && signbit(x[m + a]);
        band_solve_t(A, x, TAIL, neg0 ? 0 : leading_zeros(x, m), 0);
    } else if (A->t == 0) {
        band_solve_t(A, x, 0, 0, 0);
    } else {
        band_solve_t(A, x, A->t, 0, 0);
    }
}

/* band_solve's solve from row i0 as given: the exterior's (no tail), its forward substitution
 * from row i0 (x's rows before it hold their z: a right-hand side's leading zeros are their own
 * z, +0 - u (+0) staying +0), and the tests' reference for the window's (from row 0). */
void tirenv_ring__tband_solve_from(const tband *A, double x[], size_t i0)
{
    if (A->t == TAIL)
        band_solve_t(A, x, TAIL, i0, 0);
    else if (A->t == 0)
        band_solve_t(A, x, 0, i0, 0);
    else
        band_solve_t(A, x, A->t, i0, 0);
}

/* The exterior's forward substitution alone (no tail), from row i0 (exterior_factor's unit
 * vectors' kept y, ext_columns' last rows). */
void tirenv_ring__tband_forward(const tband *A, double x[], size_t i0)
{
    band_solve_t(A, x, 0, i0, 1);
}

/* band_solve after band_factor_x's forward substitution (*fused): x holds z in its band rows
 * and the tail's right-hand side in its tail rows. */
void tirenv_ring__tband_solve_rest(const tband *A, double x[])
{
    const size_t m = A->N - TAIL;
    double y[TAIL];
    for (size_t a = 0; a < TAIL; ++a)
        y[a] = x[m + a];
    band_bwd_t(A, x, TAIL, y);
}

#if TIRENV_RING_AVX2
/* band_factor_avx2 with band_solve's forward substitution of x in the same pass: the rows
 * before q0 first (the factor's columns there are kept), each later row with its column
 * (factor_column4), the last BAND_P rows after the factorisation; the tail's right-hand side
 * left in x's tail rows. The factorisation's time is its chain from pivot to pivot, and the
 * substitution's its chain from row to row: side by side, the second costs little more than
 * its instructions (docs/performance.md 2.29). Rows from the first row that is not +0 as in
 * band_solve; the rows of +0 before it that the fused pass takes as well are their own z and
 * leave y alone, as there, so the same bits. */
__attribute__((target("avx2"))) static int band_factor_fwd_avx2(tband *A, const int fresh,
                                                                size_t q0,
                                                                const double acc0[CK_ACC],
                                                                double *ck, const double *src,
                                                                double x[])
{
    const size_t m = A->N - TAIL;
    int neg0 = 0;
    for (size_t a = 0; a < TAIL; ++a)
        neg0 |= x[m + a] == 0 && signbit(x[m + a]);
    double y[TAIL]; /* unused with the full tail */
    v2d y01 = v2_load(x + m), y23 = v2_load(x + m + 2);
    band_fwd_t(A, x, TAIL, neg0 ? 0 : leading_zeros(x, q0), q0, &y01, &y23, y);
    v2_store(x + m, y01);
    v2_store(x + m + 2, y23);
    size_t i_end = q0;
    if (band_factor_body(A, fresh, q0, acc0, ck, src, 1, x, &i_end))
        return 1;
    y01 = v2_load(x + m), y23 = v2_load(x + m + 2);
    band_fwd_t(A, x, TAIL, i_end, m, &y01, &y23, y);
    v2_store(x + m, y01);
    v2_store(x + m + 2, y23);
    return 0;
}
#endif

/* band_factor_from, and with x (not NULL) and the full tail, where the AVX2 build runs, x's
 * forward substitution in the same pass (band_factor_fwd_avx2): *fused 1, and x then waits for
 * band_solve_rest; else *fused 0. */
int tirenv_ring__tband_factor_x(tband *A, const int fresh, size_t q0, const double acc0[CK_ACC],
                                double *ck, const double *src, double x[], int *fused)
{
#if TIRENV_RING_AVX2
    if (x && A->t == TAIL && __builtin_cpu_supports("avx2")) {
        *fused = 1;
        return band_factor_fwd_avx2(A, fresh, q0, acc0, ck, src, x);
    }
#endif
    (void)x;
    *fused = 0;
    return tirenv_ring__tband_factor_from(A, fresh, q0, acc0, ck, src);
}

int tirenv_ring__tband_alloc(tband *A, size_t N, size_t t)
{
    A->L = malloc((BAND_P + 1 + (t > 0 ? TAIL : 0)) * N * sizeof *A->L);
    if (!A->L)
        return 1;
    A->B = A->L + (BAND_P + 1) * N;
    return 0;
}

/* The first column of the window's system S whose entries differ from P's, both as
 * fill_window and assemble write them (m band rows, the tail's columns that fill_window
 * zeroes, the tail block): 0 if the tail block or the first tail columns do. */
size_t tirenv_ring__tband_first_change(const tband *S, const tband *P, size_t m)
{
    if (!tirenv_ring__same_bits(&S->T[0][0], &P->T[0][0], TAIL * TAIL) ||
        !tirenv_ring__same_bits(S->B, P->B, TAIL * FRESH_FROM))
        return 0;
    size_t p = m;
    const size_t end = TAIL * (m - BAND_P);
    if (!tirenv_ring__same_bits(S->B + end, P->B + end, TAIL * BAND_P))
        p = m - BAND_P;
    /* Blocks of rows by memcmp (equal bytes are equal bits), then the rows of the first
     * block that differs. */
    enum { ROWS = 8 };
    const size_t W = BAND_P + 1;
    size_t i = 0;
    while (i + ROWS <= p && memcmp(S->L + W * i, P->L + W * i, W * ROWS * sizeof *S->L) == 0)
        i += ROWS;
    for (; i < p; ++i)
        if (!tirenv_ring__same_bits(S->L + W * i, P->L + W * i, W))
            return i;
    return p;
}

/* The column band_refactor restarts at for a system whose first change is at column p (of m
 * band rows, p < m): the last checkpoint whose pending columns all lie before p, 0 if none. */
size_t tirenv_ring__tband_restart_column(size_t p, size_t m)
{
    if (p > m - BAND_P)
        p = m - BAND_P;
    return p < BAND_P ? 0 : (p - BAND_P) / CKS * CKS;
}

/* The window's factor F (ring_shear.c's T->win) of the system S that assemble and
 * condense_knots wrote (T->as), P the system before it (T->ap), whose factor F holds if *ok
 * (T->ap_ok); S and P then swap, P the system F factorises, S free for the next. Between
 * Newton steps and evaluations that system mostly changes from some column on: the points
 * whose states changed, a ground vertex's points in contact (their place and weight move with
 * z). The factor's columns before the first changed one are those of the last factorisation
 * (each column of a right-looking factorisation depends only on the columns before it and its
 * own entries), so they are kept: the factorisation goes on from the last checkpoint (every
 * CKS-th column, in ck) whose BAND_P pending columns lie before the first change, its state
 * (the pending columns' entries as the columns before left them, the tail block's
 * accumulators) taken from the checkpoint. The same bits as factorising the whole. With x
 * (not NULL), x's forward substitution too where band_factor_x can (*fused 1). Nonzero if
 * not positive definite. */
int tirenv_ring__tband_refactor(tband *S, tband *P, tband *F, double *ck, int *ok, double x[],
                                int *fused)
{
    *fused = 0;
    const size_t N = S->N, t = S->t, m = N - t, W = BAND_P + 1;
    size_t q = 0;
    if (*ok && P->N == N && t == TAIL && m > 2 * CKS + BAND_P) {
        const size_t p = tirenv_ring__tband_first_change(S, P, m);
        if (p == m) { /* the same system: win holds its factor */
            const tband sw = *S;
            *S = *P, *P = sw;
            return 0;
        }
        q = tirenv_ring__tband_restart_column(p, m);
    }
    *ok = 0;
    F->N = N, F->t = t;
    int bad;
    if (q == 0) {
        /* The band's first BAND_P columns; the later ones band_factor_from copies as it
         * reaches them (src), or all here where it has no interior columns. */
        const int whole = !(t == TAIL && m > BAND_P);
        memcpy(F->L, S->L, W * (whole ? m : BAND_P) * sizeof *F->L);
        if (m < FRESH_FROM + BAND_P) {
            memcpy(F->B, S->B, TAIL * m * sizeof *F->B);
        } else {
            memcpy(F->B, S->B, TAIL * FRESH_FROM * sizeof *F->B);
            memcpy(F->B + TAIL * (m - BAND_P), S->B + TAIL * (m - BAND_P),
                   TAIL * BAND_P * sizeof *F->B);
        }
        memcpy(F->T, S->T, sizeof F->T);
        bad = tirenv_ring__tband_factor_x(F, 1, 0, NULL, ck, S->L, x, fused);
    } else {
        /* Columns q .. q + BAND_P - 1 as they stood before column q was factorised (their
         * entries the same: the first change is past them), the tail's last BAND_P columns
         * from the system. */
        const double *acc = tirenv_ring__tband_ck_restore(ck, F, q);
        memcpy(F->B + TAIL * (m - BAND_P), S->B + TAIL * (m - BAND_P),
               TAIL * BAND_P * sizeof *F->B);
        bad = tirenv_ring__tband_factor_x(F, 1, q, acc, ck, S->L, x, fused);
    }
    const tband sw = *S;
    *S = *P, *P = sw;
    *ok = !bad;
    return bad;
}
