/* SPDX-License-Identifier: Apache-2.0 */
/* The ring's belt (docs/models.md section 5): its banded stiffness, condensed onto a window of
 * nodes, and the O(n) Cholesky factorisation of the window's contact system. */
#include "model/ring_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct tirenv_ring_belt {
    size_t M;               /* nodes around the circle */
    double s[3];            /* stencil of K, N/m */
    double (*end)[4][4];    /* per window length n: the end correction, N/m */
    unsigned char *have;    /* per window length: end[n] filled */
    tirenv_ring_band ext;   /* the exterior's band system, for filling end[] */
    double *col;            /* a right-hand side of the exterior, M entries */
};

/* The sidewalls' radial stiffness per unit of pressure (docs/models.md section 5.1): each
 * sidewall a membrane arc of half angle alpha under the meridional tension N = p r (r its
 * radius) of the air; its length fixed, the pull N cos(alpha) it exerts on the crown edge falls
 * as the crown comes in by dc, at the rate p (alpha sin(alpha) + cos(alpha)) /
 * (2 (sin(alpha) - alpha cos(alpha))) per unit circumference; the two sidewalls give twice
 * that. */
double tirenv_ring__sidewall_gamma(double alpha)
{
    return (alpha * sin(alpha) + cos(alpha)) / (sin(alpha) - alpha * cos(alpha));
}

double tirenv_ring__foundation(const tirenv_ring_params *par)
{
    return par->k_c + tirenv_ring__sidewall_gamma(par->alpha_s) * par->p;
}

/* The belt's tension energy c1 sum (w[j+1] - w[j])^2 + c0 sum w[j]^2. The carcass's own
 * pretension T in the finite-difference form of 1/2 (T/R^2)(w'^2 - w^2) (section 5.1). The
 * air's part is the second variation of its follower load on the deformed belt: with the belt
 * the polygon of nodes at radius R - w[j], the air does the work p b A (A: the polygon's area)
 * and the belt, inextensible, holds it with the tension T_p = p b R cos(h) (h = dtheta/2) that
 * balances it at w = 0, at the cost T_p L (L: its perimeter). The quadratic part of
 * -p b A + T_p L is exactly c1 = T_p (1 + sin(h)^2) / (4 R sin(h)), c0 = -T_p sin(h) / R
 * (tests/model/test_ring.c checks it against finite differences of A and L); both tend to the
 * continuous form as dtheta -> 0. */
void tirenv_ring__tension(size_t M, double R, const tirenv_ring_params *par, double *c1,
                          double *c0)
{
    const double dth = 2 * M_PI / (double)M, h = 0.5 * dth, sh = sin(h);
    const double T_p = par->p * par->b_p * R * cos(h);
    *c1 = par->T / (2 * R * dth) + T_p * (1 + sh * sh) / (4 * R * sh);
    *c0 = -par->T * dth / (2 * R) - T_p * sh / R;
}

/* K = R dtheta [EI/R^4 L^2 + k_f I] + the tension's, with L = -D2 - I and D2 the second
 * difference (w[j-1] - 2 w[j] + w[j+1]) / dtheta^2: the symbol of -D2 is sigma =
 * (2 sin(n dtheta/2) / dtheta)^2, so this is the mode stiffness of section 5 node by node. L
 * has the stencil (l1, l0, l1) and L^2 the stencil (l1^2, 2 l0 l1, l0^2 + 2 l1^2, ...); the
 * tension c1 sum (dw)^2 + c0 sum w^2 adds (-2 c1, 4 c1 + 2 c0, -2 c1). */
static void stencil(size_t M, double R, const tirenv_ring_params *par, double s[3])
{
    const double dth = 2 * M_PI / (double)M, e = 1 / (dth * dth);
    const double l0 = 2 * e - 1, l1 = -e;
    const double bend = par->EI / (R * R * R * R), arc = R * dth;
    double c1, c0;
    tirenv_ring__tension(M, R, par, &c1, &c0);
    s[0] = arc * (bend * (l0 * l0 + 2 * l1 * l1) + tirenv_ring__foundation(par)) + 4 * c1 +
           2 * c0;
    s[1] = arc * bend * 2 * l0 * l1 - 2 * c1;
    s[2] = arc * bend * l1 * l1;
}

tirenv_ring_belt *tirenv_ring__belt_alloc(size_t M, double R, const tirenv_ring_params *par)
{
    tirenv_ring_belt *b = calloc(1, sizeof *b);
    if (!b)
        return NULL;
    b->M = M;
    stencil(M, R, par, b->s);
    b->end = malloc(M * sizeof *b->end);
    b->have = calloc(M, 1);
    b->ext.a0 = malloc(6 * M * sizeof(double));
    b->col = malloc(M * sizeof(double));
    if (!b->end || !b->have || !b->ext.a0 || !b->col) {
        tirenv_ring__belt_free(b);
        return NULL;
    }
    b->ext.a1 = b->ext.a0 + M;
    b->ext.a2 = b->ext.a0 + 2 * M;
    b->ext.bm[0] = b->ext.a0 + 3 * M;
    b->ext.bm[1] = b->ext.a0 + 4 * M;
    return b;
}

void tirenv_ring__belt_free(tirenv_ring_belt *b)
{
    if (!b)
        return;
    free(b->end);
    free(b->have);
    free(b->ext.a0);
    free(b->col);
    free(b);
}

const double *tirenv_ring__belt_stencil(const tirenv_ring_belt *b) { return b->s; }

/* The exterior E of a window of n nodes is the open arc of the other M - n nodes, an unloaded
 * pentadiagonal Toeplitz block K_EE. Only E's two nodes at each end touch the window:
 * E's node 0 (the one after the window's last) couples to the window's last two nodes, E's
 * last node to the window's first two. So K_WE K_EE^-1 K_EW needs G = K_EE^-1 on those four
 * nodes only: four O(M) solves, once per window length. */
const double (*tirenv_ring__belt_end(tirenv_ring_belt *b, size_t n))[4]
{
    if (b->have[n])
        return (const double(*)[4])b->end[n];
    const size_t ne = b->M - n;
    const double *s = b->s;
    tirenv_ring_band *E = &b->ext;
    tirenv_ring__band_belt(E, b, ne);
    memset(E->c, 0, sizeof E->c);
    tirenv_ring__band_factor(E); /* a principal block of the positive definite K */
    const size_t e_idx[4] = {0, 1, ne - 2, ne - 1};
    double G[4][4];
    for (size_t a = 0; a < 4; ++a) {
        memset(b->col, 0, ne * sizeof *b->col);
        b->col[e_idx[a]] = 1;
        tirenv_ring__band_solve(E, b->col);
        for (size_t c = 0; c < 4; ++c)
            G[c][a] = b->col[e_idx[c]];
    }
    /* X[e][w] = K between E's end node e and the window's end node w (0, 1, n-2, n-1). */
    const double X[4][4] = {
        {0, 0, s[2], s[1]},
        {0, 0, 0, s[2]},
        {s[2], 0, 0, 0},
        {s[1], s[2], 0, 0},
    };
    double (*q)[4] = b->end[n];
    for (size_t v = 0; v < 4; ++v)
        for (size_t u = 0; u < 4; ++u) {
            double sum = 0;
            for (size_t e = 0; e < 4; ++e)
                for (size_t f = 0; f < 4; ++f)
                    sum += X[e][v] * G[e][f] * X[f][u];
            q[v][u] = sum;
        }
    /* Symmetric by construction up to round-off; make it exactly so. */
    for (size_t v = 0; v < 4; ++v)
        for (size_t u = 0; u < v; ++u)
            q[v][u] = q[u][v] = 0.5 * (q[v][u] + q[u][v]);
    b->have[n] = 1;
    return (const double(*)[4])q;
}

void tirenv_ring__band_belt(tirenv_ring_band *A, const tirenv_ring_belt *b, const size_t n)
{
    const double *s = b->s;
    A->n = n;
    for (size_t i = 0; i < n; ++i) {
        A->a0[i] = s[0];
        A->a1[i] = i + 1 < n ? s[1] : 0;
        A->a2[i] = i + 2 < n ? s[2] : 0;
    }
}

void tirenv_ring__band_less_ends(tirenv_ring_band *A, const double (*q)[4])
{
    const size_t n = A->n;
    A->a0[0] -= q[0][0];
    A->a1[0] -= q[0][1];
    A->a0[1] -= q[1][1];
    A->a0[n - 2] -= q[2][2];
    A->a1[n - 2] -= q[2][3];
    A->a0[n - 1] -= q[3][3];
    for (size_t i = 0; i < 2; ++i)
        for (size_t k = 0; k < 2; ++k)
            A->c[i][k] = -q[i][2 + k];
}

/* Cholesky by columns. A band row i < m = n-2 has L entries only at i-1 and i-2; the last two
 * rows fill in along their whole length (the corner couples them to rows 0 and 1). The band
 * entries of A are read before they are overwritten: A[i+1][i] when column i is done, and the
 * last rows' band entries A[m][m-2], A[m][m-1], A[m+1][m-1] are never overwritten. */
int tirenv_ring__band_factor(tirenv_ring_band *A)
{
    const size_t n = A->n, m = n - 2;
    double *a0 = A->a0, *a1 = A->a1, *a2 = A->a2, *b0 = A->bm[0], *b1 = A->bm[1];
    double s00 = 0, s10 = 0, s11 = 0; /* sums over i < m of the last rows' products */
    for (size_t i = 0; i < m; ++i) {
        const double l1 = i >= 1 ? a1[i - 1] : 0, l2 = i >= 2 ? a2[i - 2] : 0;
        const double d = a0[i] - l1 * l1 - l2 * l2;
        if (!(d > 0))
            return 1;
        const double lii = sqrt(d), inv = 1 / lii;
        a0[i] = lii;
        /* The last rows: their entry of A in column i (band or corner), minus the fill. */
        double r0 = i + 2 == m ? a2[i] : i + 1 == m ? a1[i] : 0;
        double r1 = i + 1 == m ? a2[i] : 0;
        if (i < 2) {
            r0 += A->c[i][0];
            r1 += A->c[i][1];
        }
        const double p0 = i >= 1 ? b0[i - 1] : 0, p1 = i >= 1 ? b1[i - 1] : 0;
        const double q0 = i >= 2 ? b0[i - 2] : 0, q1 = i >= 2 ? b1[i - 2] : 0;
        b0[i] = (r0 - p0 * l1 - q0 * l2) * inv;
        b1[i] = (r1 - p1 * l1 - q1 * l2) * inv;
        s00 += b0[i] * b0[i];
        s10 += b1[i] * b0[i];
        s11 += b1[i] * b1[i];
        if (i + 1 < m)
            a1[i] = (a1[i] - (i >= 1 ? a2[i - 1] * l1 : 0)) * inv;
        if (i + 2 < m)
            a2[i] *= inv;
    }
    const double d0 = a0[m] - s00;
    if (!(d0 > 0))
        return 1;
    A->t[0] = sqrt(d0);
    A->t[1] = (a1[m] - s10) / A->t[0];
    const double d1 = a0[m + 1] - s11 - A->t[1] * A->t[1];
    if (!(d1 > 0))
        return 1;
    A->t[2] = sqrt(d1);
    return 0;
}

void tirenv_ring__band_solve(const tirenv_ring_band *A, double x[])
{
    const size_t n = A->n, m = n - 2;
    const double *a0 = A->a0, *a1 = A->a1, *a2 = A->a2, *b0 = A->bm[0], *b1 = A->bm[1];
    double y0 = x[m], y1 = x[m + 1];
    for (size_t i = 0; i < m; ++i) {
        double v = x[i];
        if (i >= 1)
            v -= a1[i - 1] * x[i - 1];
        if (i >= 2)
            v -= a2[i - 2] * x[i - 2];
        x[i] = v / a0[i];
        y0 -= b0[i] * x[i];
        y1 -= b1[i] * x[i];
    }
    y0 /= A->t[0];
    y1 = (y1 - A->t[1] * y0) / A->t[2];
    x[m + 1] = y1 / A->t[2];
    x[m] = (y0 - A->t[1] * x[m + 1]) / A->t[0];
    for (size_t i = m; i-- > 0;) {
        double v = x[i] - b0[i] * x[m] - b1[i] * x[m + 1];
        if (i + 1 < m)
            v -= a1[i] * x[i + 1];
        if (i + 2 < m)
            v -= a2[i] * x[i + 2];
        x[i] = v / a0[i];
    }
}
