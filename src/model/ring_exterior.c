/* SPDX-License-Identifier: Apache-2.0 */
/* The exterior of the shear-coupled tread's window (docs/models.md section 5.3): the unloaded
 * nodes outside it condense out exactly into a 6 x 6 correction on the window's ends, from six
 * columns of the exterior's inverse (one shared factor of the longest exterior, the columns in
 * lanes), and give the free nodes' (w, u) from the ends of a sub-window. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "model/ring_impl.h"
#include "model/ring_shear_impl.h"
#include "model/ring_tband.h"

/* The belt's and the tread's stiffness of the open arc of count nodes from node j0 (mod M),
 * (w, u) interleaved, into A: the belt's stencil, the tread's compression kap between w and u,
 * its shear k_sh between neighbouring u. The window (assemble) and its exterior (compute_end)
 * are such arcs; apply_K is the window's product with it. */
void tirenv_ring__add_arc(tband *A, const tirenv_ring_tread *T, size_t j0, size_t count)
{
    const double *s = T->s, k_sh = T->k_sh;
    for (size_t e = 0; e < count; ++e) {
        const double kap = T->kap[(j0 + e) % T->M];
        band_add(A, 2 * e, 2 * e, s[0] + kap);
        band_add(A, 2 * e, 2 * e + 1, -kap);
        band_add(A, 2 * e + 1, 2 * e + 1, kap + 2 * k_sh);
        if (e + 1 < count) {
            band_add(A, 2 * e, 2 * e + 2, s[1]);
            band_add(A, 2 * e + 1, 2 * e + 3, -k_sh);
        }
        if (e + 2 < count)
            band_add(A, 2 * e, 2 * e + 4, s[2]);
    }
}

/* The exterior of a window of n nodes starting at lo: the open arc of the other M - n nodes,
 * (w, u) interleaved, unloaded. Only its first and last nodes couple to the window: the
 * belt's pentadiagonal stencil reaches two nodes, the shear one. So K_WE K_EE^-1 K_EW needs
 * K_EE^-1 on six exterior unknowns only. Window ends: w_0, u_0, w_1, w_n-2, w_n-1, u_n-1. */
/* X[e][b]: the whole's entry between the exterior's coupled unknown e (its w_0, u_0, w_1,
 * w_ne-2, w_ne-1, u_ne-1) and window end b (end_index). */
static void ext_coupling(const tirenv_ring_tread *T, double X[NB][NB])
{
    const double *s = T->s, k_sh = T->k_sh;
    memset(X, 0, NB * sizeof *X);
    X[0][3] = s[2], X[0][4] = s[1]; /* exterior w_0 - window w_n-2, w_n-1 */
    X[1][5] = -k_sh;                /* exterior u_0 - window u_n-1 */
    X[2][4] = s[2];                 /* exterior w_1 - window w_n-1 */
    X[3][0] = s[2];                 /* exterior w_ne-2 - window w_0 */
    X[4][0] = s[1], X[4][2] = s[2]; /* exterior w_ne-1 - window w_0, w_1 */
    X[5][1] = -k_sh;                /* exterior u_ne-1 - window u_0 */
}

/* The exterior's coupled unknowns (ext_coupling's rows) in its Ne interleaved unknowns. */
void tirenv_ring__ext_index(size_t Ne, size_t e[NB])
{
    e[0] = 0, e[1] = 1, e[2] = 2, e[3] = Ne - 4, e[4] = Ne - 2, e[5] = Ne - 1;
}

/* The factor of the exterior of ne nodes from node j0 into T->ext. Without lugs an open arc's
 * stiffness depends only on its length (kap is the same at every node), and a shorter arc's is
 * the leading block of a longer one's; so is its factor the leading block of the
 * longer one's, bit for bit (each column of band_factor depends only on the columns before it,
 * which get the same operations in the same order whatever the length, and band_solve reads
 * only the rows of the length it is given). One factorisation of the longest exterior, M - 1
 * nodes, then serves every window length, where each length factorised its own; and so do the
 * forward substitutions of the first three unit vectors, which compute_end's columns start
 * from (row i's y depends only on the rows up to i), kept by rows in ey (four a row, the
 * fourth +0: ext_columns' lanes). */
static void exterior_factor(tirenv_ring_tread *T, size_t j0, size_t ne)
{
    tband *E = &T->ext;
    if (!T->lugs && T->ext_all) {
        E->N = 2 * ne;
        return;
    }
    const size_t nf = T->lugs ? ne : T->M - 1, Nf = 2 * nf;
    band_reset(E, Nf, 0);
    tirenv_ring__add_arc(E, T, j0, nf);
    tirenv_ring__tband_factor(E); /* a principal block of the positive definite whole */
    T->ext_all = !T->lugs;
    for (size_t a = 0; a < 3 && T->ext_all; ++a) {
        double *y = T->col;
        memset(y, 0, Nf * sizeof *y);
        y[a] = 1;
        tirenv_ring__tband_forward(E, y, a);
        for (size_t i = 0; i < Nf; ++i)
            T->ey[4 * i + a] = y[i];
    }
    for (size_t i = 0; i < Nf && T->ext_all; ++i)
        T->ey[4 * i + 3] = 0;
    E->N = 2 * ne;
}

/* Rows the ext_columns' last unit vectors' forward substitutions reach back to: the first of
 * them, Ne - 4, and the BAND_P rows before it that its row reads. */
enum { EXT_LAST = 8 };

/* One row i < Ne - EXT_LAST of ext_columns' back substitution, the six columns in three pairs
 * of lanes (p1 .. p4: each pair's x at rows i + 1 .. i + 4, moved on by one); z from ey's row
 * (columns 0 .. 3, the fourth +0) and +0 (4, 5). */
static inline __attribute__((always_inline)) void
ext_row(const double *L, const double *ey, size_t Ne, size_t i, v2d p4[3], v2d p3[3], v2d p2[3],
        v2d p1[3], double *cols, const int store)
{
    const double *l = L + (BAND_P + 1) * i;
    const v2d l0 = {l[0], l[0]}, l1 = {l[1], l[1]}, l2 = {l[2], l[2]}, l3 = {l[3], l[3]},
              l4 = {l[4], l[4]};
    const v2d z[3] = {v2_load(ey + 4 * i), v2_load(ey + 4 * i + 2), {0, 0}};
    for (size_t g = 0; g < 3; ++g) {
        v2d v = z[g] * l0;
        v -= l4 * p4[g];
        v -= l3 * p3[g];
        v -= l2 * p2[g];
        v -= l1 * p1[g];
        p4[g] = p3[g], p3[g] = p2[g], p2[g] = p1[g], p1[g] = v;
        if (store) {
            cols[2 * g * Ne + i] = v[0];
            cols[(2 * g + 1) * Ne + i] = v[1];
        }
    }
}

/* The six columns of K_EE^-1 at the coupled unknowns as ext_solve gives them one by one
 * (compute_end's reference, ext_columns_each), in lanes (ext_columns_base, ext_columns_avx2):
 * each lane gets a column's operations in its order, so the same bits. Row i of the back
 * substitution (t = 0) is
 *     x_i = z_i / D_i - U_i+4,i x_i+4 - ... - U_i+1,i x_i+1   (the farthest product first),
 * fewer products in the last BAND_P rows; z the forward substitution: the first three columns'
 * from ey (exterior_factor), the last three's zero up to their unit row, solved from there
 * (rows Ne - EXT_LAST on), so that below row Ne - EXT_LAST the lanes' z are ey's row, its +0
 * fourth, and +0. The factor's row is loaded once for the six columns, where each column's
 * solve loaded it again, and no column is copied in or zeroed first. cols (NULL: only G
 * wanted): the columns, Ne each; G[c][a]: column a at coupled unknown c. Ne >= 2 EXT_LAST.
 * Here the rows from Ne - EXT_LAST on, column by column, into xl (and cols), and G's rows at
 * the last three coupled unknowns. */
static inline __attribute__((always_inline)) void
ext_last_rows(tirenv_ring_tread *T, size_t Ne, const size_t eidx[NB], double *cols,
              double G[NB][NB], double xl[NB][EXT_LAST])
{
    const tband *E = &T->ext;
    const double *const L = E->L, *const ey = T->ey;
    const size_t i1 = Ne - EXT_LAST;
    /* The last rows of all six: z, then x, by column (the general rows of band_solve_t). */
    for (size_t a = 0; a < NB; ++a) {
        double z[EXT_LAST];
        if (a < 3) {
            for (size_t k = 0; k < EXT_LAST; ++k)
                z[k] = ey[4 * (i1 + k) + a];
        } else {
            double *y = T->col;
            memset(y + i1, 0, EXT_LAST * sizeof *y);
            y[eidx[a]] = 1;
            tirenv_ring__tband_forward(E, y, eidx[a]);
            memcpy(z, y + i1, sizeof z);
        }
        for (size_t k = EXT_LAST; k-- > 0;) {
            const size_t i = i1 + k, nk = Ne - 1 - i < BAND_P ? Ne - 1 - i : BAND_P;
            double v = z[k] * L[(BAND_P + 1) * i];
            for (size_t h = nk; h >= 1; --h)
                v -= L[(BAND_P + 1) * i + h] * xl[a][k + h];
            xl[a][k] = v;
        }
        if (cols)
            memcpy(cols + a * Ne + i1, xl[a], sizeof xl[a]);
        for (size_t c = 3; c < NB; ++c)
            G[c][a] = xl[a][eidx[c] - i1];
    }
}

/* The columns in the baseline build: the last rows (ext_last_rows), then the others in pairs
 * of lanes (ext_row). */
static inline __attribute__((always_inline)) void
ext_columns_body(tirenv_ring_tread *T, size_t Ne, const size_t eidx[NB], double *cols,
                 double G[NB][NB], const int store)
{
    const double *const L = T->ext.L, *const ey = T->ey;
    const size_t i1 = Ne - EXT_LAST;
    double xl[NB][EXT_LAST];
    ext_last_rows(T, Ne, eidx, cols, G, xl);
    /* The other rows, all four products each: columns 0, 1 | 2, 3 | 4, 5 in pairs of lanes,
     * the last four rows' x of each pair carried in registers; rows 0 .. 2 also into G. */
    v2d p4[3], p3[3], p2[3], p1[3];
    for (size_t g = 0; g < 3; ++g) {
        p4[g] = (v2d){xl[2 * g][3], xl[2 * g + 1][3]};
        p3[g] = (v2d){xl[2 * g][2], xl[2 * g + 1][2]};
        p2[g] = (v2d){xl[2 * g][1], xl[2 * g + 1][1]};
        p1[g] = (v2d){xl[2 * g][0], xl[2 * g + 1][0]};
    }
    size_t i = i1;
    for (; i > 3; --i)
        ext_row(L, ey, Ne, i - 1, p4, p3, p2, p1, cols, store);
    for (; i > 0; --i) {
        ext_row(L, ey, Ne, i - 1, p4, p3, p2, p1, cols, store);
        for (size_t g = 0; g < 3; ++g)
            G[i - 1][2 * g] = p1[g][0], G[i - 1][2 * g + 1] = p1[g][1];
    }
}

static void ext_columns_base(tirenv_ring_tread *T, size_t Ne, const size_t eidx[NB],
                             double *cols, double G[NB][NB])
{
    if (cols)
        ext_columns_body(T, Ne, eidx, cols, G, 1);
    else
        ext_columns_body(T, Ne, eidx, NULL, G, 0);
}

#if TIRENV_RING_AVX2
/* ext_row in the AVX2 build: columns 0 .. 3 in four lanes (a1 .. a4: their x at rows i + 1 ..
 * i + 4), 4 and 5 in two (b1 .. b4), the same operations in each lane; x_i into *va, *vb. */
__attribute__((target("avx2"))) static inline __attribute__((always_inline)) void
ext_row4(const double *L, const double *ey, size_t Ne, size_t i, const v4d *a4, const v4d *a3,
         const v4d *a2, const v4d *a1, const v2d *b4, const v2d *b3, const v2d *b2,
         const v2d *b1, v4d *va, v2d *vb, double *cols, const int store)
{
    const double *l = L + (BAND_P + 1) * i;
    v4d z;
    v4_load(&z, ey + 4 * i);
    v4d v = z * (v4d){l[0], l[0], l[0], l[0]};
    v -= (v4d){l[4], l[4], l[4], l[4]} * *a4;
    v -= (v4d){l[3], l[3], l[3], l[3]} * *a3;
    v -= (v4d){l[2], l[2], l[2], l[2]} * *a2;
    v -= (v4d){l[1], l[1], l[1], l[1]} * *a1;
    v2d w = (v2d){0, 0} * (v2d){l[0], l[0]};
    w -= (v2d){l[4], l[4]} * *b4;
    w -= (v2d){l[3], l[3]} * *b3;
    w -= (v2d){l[2], l[2]} * *b2;
    w -= (v2d){l[1], l[1]} * *b1;
    if (store) {
        cols[i] = v[0], cols[Ne + i] = v[1], cols[2 * Ne + i] = v[2];
        cols[3 * Ne + i] = v[3], cols[4 * Ne + i] = w[0], cols[5 * Ne + i] = w[1];
    }
    *va = v, *vb = w;
}

/* ext_columns_body's rows below Ne - EXT_LAST in the AVX2 build (ext_row4), four rows an
 * iteration so that the carried x need no moves; xl: the last EXT_LAST rows' x by column. */
__attribute__((target("avx2"))) static inline __attribute__((always_inline)) void
ext_rows4(const double *L, const double *ey, size_t Ne, double xl[NB][EXT_LAST], double *cols,
          double G[NB][NB], const int store)
{
    v4d a4 = {xl[0][3], xl[1][3], xl[2][3], xl[3][3]},
        a3 = {xl[0][2], xl[1][2], xl[2][2], xl[3][2]},
        a2 = {xl[0][1], xl[1][1], xl[2][1], xl[3][1]},
        a1 = {xl[0][0], xl[1][0], xl[2][0], xl[3][0]};
    v2d b4 = {xl[4][3], xl[5][3]}, b3 = {xl[4][2], xl[5][2]}, b2 = {xl[4][1], xl[5][1]},
        b1 = {xl[4][0], xl[5][0]};
    size_t i = Ne - EXT_LAST;
    for (; i >= 3 + 4; i -= 4) {
        v4d v0, v1, v2, v3;
        v2d w0, w1, w2, w3;
        ext_row4(L, ey, Ne, i - 1, &a4, &a3, &a2, &a1, &b4, &b3, &b2, &b1, &v0, &w0, cols, store);
        ext_row4(L, ey, Ne, i - 2, &a3, &a2, &a1, &v0, &b3, &b2, &b1, &w0, &v1, &w1, cols, store);
        ext_row4(L, ey, Ne, i - 3, &a2, &a1, &v0, &v1, &b2, &b1, &w0, &w1, &v2, &w2, cols, store);
        ext_row4(L, ey, Ne, i - 4, &a1, &v0, &v1, &v2, &b1, &w0, &w1, &w2, &v3, &w3, cols, store);
        a4 = v0, a3 = v1, a2 = v2, a1 = v3;
        b4 = w0, b3 = w1, b2 = w2, b1 = w3;
    }
    for (; i > 0; --i) {
        v4d v;
        v2d w;
        ext_row4(L, ey, Ne, i - 1, &a4, &a3, &a2, &a1, &b4, &b3, &b2, &b1, &v, &w, cols, store);
        a4 = a3, a3 = a2, a2 = a1, a1 = v;
        b4 = b3, b3 = b2, b2 = b1, b1 = w;
        if (i - 1 < 3) {
            double *g = G[i - 1];
            g[0] = v[0], g[1] = v[1], g[2] = v[2], g[3] = v[3], g[4] = w[0], g[5] = w[1];
        }
    }
}

/* The same in the AVX2 build: columns 0 .. 3 in four lanes, 4 and 5 in two, and the
 * three-operand instructions save the copies (as band_factor's, docs/performance.md 2.27);
 * the same operations in each lane. */
__attribute__((target("avx2"))) static void ext_columns_avx2(tirenv_ring_tread *T, size_t Ne,
                                                             const size_t eidx[NB],
                                                             double *cols, double G[NB][NB])
{
    double xl[NB][EXT_LAST];
    ext_last_rows(T, Ne, eidx, cols, G, xl);
    if (cols)
        ext_rows4(T->ext.L, T->ey, Ne, xl, cols, G, 1);
    else
        ext_rows4(T->ext.L, T->ey, Ne, xl, NULL, G, 0);
}
#endif

/* The same one column at a time (ext_solve), each copied in (a kept forward substitution) or
 * a unit vector: with lugs (no kept ones) or short exteriors, and the tests' reference. */
static void ext_columns_each(tirenv_ring_tread *T, size_t Ne, const size_t eidx[NB],
                             double *cols, double G[NB][NB])
{
    const tband *E = &T->ext;
    for (size_t a = 0; a < NB; ++a) {
        /* Unit vectors: their leading zeros are their own y (ext_solve), and the first
         * three's whole y the longest exterior's (exterior_factor). */
        const int kept = T->ext_all && eidx[a] < 3;
        double *const col = cols ? cols + a * Ne : T->col; /* solved where it is kept */
        if (kept) {
            for (size_t i = 0; i < Ne; ++i)
                col[i] = T->ey[4 * i + eidx[a]];
        } else {
            memset(col, 0, Ne * sizeof *col);
            col[eidx[a]] = 1;
        }
        tirenv_ring__tband_solve_from(E, col, kept ? Ne : eidx[a]);
        for (size_t c = 0; c < NB; ++c)
            G[c][a] = col[eidx[c]];
    }
}

/* cols (NULL: not wanted): the six columns of K_EE^-1 at the coupled unknowns, Ne each; how:
 * EXT_AUTO, or one of the tests' references. */
void tirenv_ring__compute_end_by(tirenv_ring_tread *T, size_t lo, size_t n, double Q[NB][NB],
                                 double *cols, int how)
{
    const size_t M = T->M, ne = M - n, Ne = 2 * ne;
    exterior_factor(T, (lo + n) % M, ne);
    size_t eidx[NB];
    tirenv_ring__ext_index(Ne, eidx);
    double X[NB][NB];
    ext_coupling(T, X);
    double G[NB][NB];
    if (!T->ext_all || Ne < 2 * EXT_LAST || how == EXT_EACH)
        ext_columns_each(T, Ne, eidx, cols, G);
#if TIRENV_RING_AVX2
    else if (how == EXT_AUTO && __builtin_cpu_supports("avx2"))
        ext_columns_avx2(T, Ne, eidx, cols, G);
#endif
    else
        ext_columns_base(T, Ne, eidx, cols, G);
    for (size_t v = 0; v < NB; ++v)
        for (size_t u = 0; u < NB; ++u) {
            double sum = 0;
            for (size_t e = 0; e < NB; ++e)
                for (size_t f = 0; f < NB; ++f)
                    sum += X[e][v] * G[e][f] * X[f][u];
            Q[v][u] = sum;
        }
    for (size_t v = 0; v < NB; ++v)
        for (size_t u = 0; u < v; ++u)
            Q[v][u] = Q[u][v] = 0.5 * (Q[v][u] + Q[u][v]);
}

static void compute_end(tirenv_ring_tread *T, size_t lo, size_t n, double Q[NB][NB],
                        double *cols)
{
    tirenv_ring__compute_end_by(T, lo, n, Q, cols, EXT_AUTO);
}

const double (*tirenv_ring__window_end(tirenv_ring *r, double x_c))[NB]
{
    tirenv_ring_tread *T = r->tread;
    const size_t n = r->n;
    if (T->lugs) {
        /* The lugs' stiffness turns with x: the exterior's, so its ends, depend on x, lo
         * and n, which stay the same over a position's evaluations. */
        if (!(T->lug_n == n && T->lug_lo == r->lo && T->lug_x == x_c)) {
            compute_end(T, r->lo, n, T->end[0], NULL);
            T->lug_x = x_c;
            T->lug_lo = r->lo;
            T->lug_n = n;
        }
        return (const double(*)[NB])T->end[0];
    }
    if (!T->have[n]) {
        compute_end(T, r->lo, n, T->end[n], NULL);
        T->have[n] = 1;
    }
    return (const double(*)[NB])T->end[n];
}

/* The exterior's columns for a sub-window of n nodes from lo (computing them, and its end
 * correction, the first time); NULL if out of memory. */
const double *tirenv_ring__sub_cols(tirenv_ring_tread *T, size_t lo, size_t n)
{
    if (!T->cols[n]) {
        double *c = malloc(NB * 2 * (T->M - n) * sizeof *c);
        if (!c)
            return NULL;
        double Q[NB][NB];
        compute_end(T, lo, n, Q, c);
        if (!T->have[n]) {
            memcpy(T->end[n], Q, sizeof Q);
            T->have[n] = 1;
        }
        T->cols[n] = c;
    }
    return T->cols[n];
}

/* What a sub-window of ns nodes, its (w, u) vs (interleaved), puts on its exterior's end
 * unknowns: f = X v_B, which the columns of K_EE^-1 (sub_cols) turn into the exterior's
 * unloaded response. */
static void exterior_load(const tirenv_ring_tread *T, size_t ns, const double vs[],
                          double f[NB])
{
    size_t bi[NB];
    end_index(ns, bi);
    double X[NB][NB];
    ext_coupling(T, X);
    for (size_t e = 0; e < NB; ++e) {
        f[e] = 0;
        for (size_t c = 0; c < NB; ++c)
            f[e] += X[e][c] * vs[bi[c]];
    }
}

/* The free nodes of the window r->lo, r->n outside the sub-window a .. b (their columns
 * computed: sub_cols): their (w, u) in v (the window's, interleaved), from the sub-window's
 * there, as the unloaded exterior's -K_EE^-1 K_EB v_B. */
void tirenv_ring__fill_free(const tirenv_ring *r, size_t a, size_t b, double v[])
{
    const tirenv_ring_tread *T = r->tread;
    const size_t lo = r->lo, hi = r->lo + r->n - 1, ns = b - a + 1, ne = T->M - ns,
                 Ne = 2 * ne;
    const double *cols = T->cols[ns], *vs = v + 2 * (a - lo);
    double f[NB];
    exterior_load(T, ns, vs, f);
    _Static_assert(NB == 6, "the lanes below are written out for NB = 6");
    /* The exterior runs from node b + 1 round to node a - 1: the window's nodes lo .. a - 1
     * are its ne - (a - lo) .. ne - 1, and b + 1 .. hi its 0 .. hi - b - 1. */
    const v2d f0 = {f[0], f[0]}, f1 = {f[1], f[1]}, f2 = {f[2], f[2]}, f3 = {f[3], f[3]},
              f4 = {f[4], f[4]}, f5 = {f[5], f[5]};
    for (int run = 0; run < 2; ++run) {
        const size_t count = run ? hi - b : a - lo, ee0 = run ? 0 : ne - (a - lo);
        const double *c = cols + 2 * ee0;
        double *d = v + (run ? 2 * (b + 1 - lo) : 0);
        /* w and u (h = 0, 1) in two lanes: sum_h = sum_e cols[e Ne + 2 ee + h] f[e], from 0
         * in the order of e, as one lane each would. */
        for (size_t t = 0; t < count; ++t, c += 2, d += 2) {
            v2d sum = {0, 0};
            sum += v2_load(c) * f0;
            sum += v2_load(c + Ne) * f1;
            sum += v2_load(c + 2 * Ne) * f2;
            sum += v2_load(c + 3 * Ne) * f3;
            sum += v2_load(c + 4 * Ne) * f4;
            sum += v2_load(c + 5 * Ne) * f5;
            d[0] = -sum[0];
            d[1] = -sum[1];
        }
    }
}

/* The softening carcass's exterior (docs/models.md 5.1-5.2): the nodes outside the set solved
 * are condensed as a linear carcass, exact while none of them is pressed in beyond w_0. The
 * largest w (m) outside the sub-window a .. b of the window's xw, from its columns (sub_cols)
 * as fill_free takes them, every node round the ring; *j_out its node. */
double tirenv_ring__outside_sub(const tirenv_ring *r, size_t a, size_t b, const double xw[],
                                size_t *j_out)
{
    const tirenv_ring_tread *T = r->tread;
    const size_t ns = b - a + 1, ne = T->M - ns, Ne = 2 * ne;
    const double *cols = T->cols[ns], *vs = xw + 2 * (a - r->lo);
    double f[NB];
    exterior_load(T, ns, vs, f);
    double w_max = -INFINITY;
    for (size_t ee = 0; ee < ne; ++ee) {
        double sum = 0;
        for (size_t e = 0; e < NB; ++e)
            sum += cols[e * Ne + 2 * ee] * f[e];
        if (-sum > w_max) {
            w_max = -sum;
            *j_out = (b + 1 + ee) % T->M;
        }
    }
    return w_max;
}

/* The same outside the whole window r->lo, r->n: the exterior's unloaded response to the
 * window's ends in xw, -K_EE^-1 f (f = X v_B, exterior_load, on its coupled unknowns as
 * compute_end numbers them), solved afresh (its factor, as compute_end leaves it, and one
 * solve: the whole window is the fallback, not the rule). */
double tirenv_ring__outside_whole(tirenv_ring *r, const double xw[], size_t *j_out)
{
    tirenv_ring_tread *T = r->tread;
    const size_t M = T->M, n = r->n, lo = r->lo, ne = M - n, Ne = 2 * ne;
    double Q[NB][NB], f[NB];
    compute_end(T, lo, n, Q, NULL);
    exterior_load(T, n, xw, f);
    size_t eidx[NB];
    tirenv_ring__ext_index(Ne, eidx);
    double *rhs = T->col;
    memset(rhs, 0, Ne * sizeof *rhs);
    for (size_t e = 0; e < NB; ++e)
        rhs[eidx[e]] = -f[e];
    tirenv_ring__tband_solve(&T->ext, rhs);
    double w_max = -INFINITY;
    for (size_t e = 0; e < ne; ++e)
        if (rhs[2 * e] > w_max) {
            w_max = rhs[2 * e];
            *j_out = (lo + n + e) % M;
        }
    return w_max;
}
