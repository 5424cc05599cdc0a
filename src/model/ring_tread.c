/* SPDX-License-Identifier: Apache-2.0 */
/* The shear-coupled tread's storage (docs/models.md section 5.3): its allocation, the room its
 * knots take as a solve finds them, the tests' NaN in what no solve wrote, its small accessors;
 * and the softening carcass's law (section 5.1), which the tread's energy and Newton system
 * add per node. The equilibrium that uses them is ring_shear.c's. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "core/capacity.h"
#include "model/ring_shear_impl.h"
#include "model/ring_tband.h"
#include "model/ring_impl.h"

/* The driver's vectors (2 M + cap_k each) and the knots' arrays (cap_k each) from the N + m
 * unknowns and m knots of the solve about to start on: NaN (T->poison). */
void tirenv_ring__poison_past(tirenv_ring_tread *T, size_t N, size_t m)
{
    const size_t V = 2 * T->M + T->cap_k, cap = T->cap_k;
    double *const vec[] = {T->x, T->xn, T->xt, T->g, T->kp};
    double *const knot[] = {T->kd, T->ko, T->dd, T->doff, T->c0,
                            T->c1, T->z0, T->z1, T->kphi, T->kdphi};
    for (size_t v = 0; v < sizeof vec / sizeof *vec; ++v)
        for (size_t i = N + m; i < V; ++i)
            vec[v][i] = NAN;
    for (size_t v = 0; v < sizeof knot / sizeof *knot; ++v)
        for (size_t k = m; k < cap; ++k)
            knot[v][k] = NAN;
}

/* Room for m knots: the driver's vectors (2 M + m each) and the knots' arrays. Nonzero if
 * out of memory (T keeps what it had). Not zeroed: a solve reads only what it wrote (its N + m
 * unknowns, its m knots), and zeros hid from valgrind's memcheck (tests/model/memcheck.sh)
 * the read that find_knots' knots outside the window made; the tests put NaN there
 * (tirenv_ring__tread_poison). */
int tirenv_ring__reserve_knots(tirenv_ring_tread *T, size_t m)
{
    if (T->col && m <= T->cap_k)
        return 0;
    const size_t cap = tirenv_core__capacity(T->cap_k, 16, m);
    const size_t V = 2 * T->M + cap;
    double *col = malloc((2 * T->M + 5 * V) * sizeof *col);
    size_t *kj = malloc(cap * sizeof *kj);
    double *kd = malloc(10 * cap * sizeof *kd);
    if (!col || !kj || !kd) {
        free(col);
        free(kj);
        free(kd);
        return 1;
    }
    free(T->col);
    free(T->kj);
    free(T->kd);
    T->col = col;
    T->x = col + 2 * T->M;
    T->xn = T->x + V;
    T->xt = T->xn + V;
    T->g = T->xt + V;
    T->kp = T->g + V;
    T->kj = kj;
    T->kd = kd;
    T->ko = kd + cap;
    T->dd = kd + 2 * cap;
    T->doff = kd + 3 * cap;
    T->c0 = kd + 4 * cap;
    T->c1 = kd + 5 * cap;
    T->z0 = kd + 6 * cap;
    T->z1 = kd + 7 * cap;
    T->kphi = kd + 8 * cap;
    T->kdphi = kd + 9 * cap;
    T->cap_k = cap;
    if (T->poison) {
        for (size_t i = 0; i < 2 * T->M; ++i)
            col[i] = NAN;
        tirenv_ring__poison_past(T, 0, 0);
    }
    return 0;
}

void tirenv_ring__tread_poison(tirenv_ring_tread *T)
{
    T->poison = 1;
    for (size_t i = 0; i < 2 * T->M; ++i)
        T->col[i] = NAN;
    tirenv_ring__poison_past(T, 0, 0);
}

double tirenv_ring__tread_shear(const tirenv_ring_params *par)
{
    return par->G_t * par->t_r * par->b_p;
}

tirenv_ring_tread *tirenv_ring__tread_alloc(size_t M, double R, const tirenv_ring_params *par,
                                            const double stencil[3])
{
    tirenv_ring_tread *T = calloc(1, sizeof *T);
    if (!T)
        return NULL;
    const double dth = 2 * M_PI / (double)M, k_t = par->k_t;
    T->M = M;
    memcpy(T->s, stencil, sizeof T->s);
    T->k_sh = tirenv_ring__tread_shear(par) / (R * dth);
    T->k_g = TIRENV_RING_GROUND_LAYER * k_t;
    T->kap0 = k_t * T->k_g / (T->k_g - k_t) * R * dth;
    T->lugs = par->lug_count > 0 && par->lug_ratio != 1;
    T->kap = malloc((4 * M + 3 + SPAN) * sizeof *T->kap);
    T->end = malloc(M * sizeof *T->end);
    T->have = calloc(M, 1);
    T->cols = calloc(M, sizeof *T->cols);
    T->xw = malloc(8 * M * sizeof *T->xw);
    T->soft = tirenv_ring__carcass_law(par, R * dth, &T->law);
    if (!T->kap || !T->end || !T->have || !T->cols || !T->xw || tirenv_ring__reserve_knots(T, 16) ||
        tirenv_ring__tband_alloc(&T->ext, 2 * M, 0) ||
        tirenv_ring__tband_alloc(&T->win, 2 * M, TAIL) ||
        tirenv_ring__tband_alloc(&T->as, 2 * M, TAIL) ||
        tirenv_ring__tband_alloc(&T->ap, 2 * M, TAIL) ||
        !(T->ck = malloc(CK_LEN * (2 * M / CKS + 1) * sizeof *T->ck)) ||
        !(T->ey = malloc(4 * 2 * M * sizeof *T->ey))) {
        tirenv_ring__tread_free(T);
        return NULL;
    }
    T->u = T->kap + M;
    T->dw = T->u + M;
    T->du = T->dw + M;
    T->pred = T->du + M;
    T->dxw = T->xw + 2 * M;
    T->wc = T->xw + 4 * M;
    T->dn = T->xw + 5 * M;
    T->dn2 = T->xw + 6 * M;
    T->ddn = T->xw + 7 * M;
    for (size_t j = 0; j < M; ++j)
        T->kap[j] = T->kap0;
    T->span = T->pred + 3;
    memset(T->u, 0, (3 * M + 3 + SPAN) * sizeof *T->u);
    return T;
}

void tirenv_ring__tread_free(tirenv_ring_tread *T)
{
    if (!T)
        return;
    free(T->kap);
    free(T->end);
    free(T->have);
    if (T->cols)
        for (size_t n = 0; n < T->M; ++n)
            free(T->cols[n]);
    free(T->cols);
    free(T->xw);
    free(T->col);
    free(T->kj);
    free(T->kd);
    free(T->lc);
    free(T->ext.L);
    free(T->win.L);
    free(T->as.L);
    free(T->ap.L);
    free(T->ck);
    free(T->ey);
    free(T);
}

double *tirenv_ring__tread_u(tirenv_ring_tread *T) { return T->u; }

size_t tirenv_ring__tread_n_sub(const tirenv_ring_tread *T) { return T->n_sub; }

void tirenv_ring__tread_whole(tirenv_ring_tread *T, int whole) { T->whole = whole; }

void tirenv_ring__tread_no_peel(tirenv_ring_tread *T, int no_peel) { T->no_peel = no_peel; }

size_t tirenv_ring__tread_peeled(const tirenv_ring_tread *T) { return T->n_peel; }

size_t tirenv_ring__tread_warm_size(const tirenv_ring_tread *T) { return 3 * T->M + 3 + SPAN; }

int tirenv_ring__carcass_law(const tirenv_ring_params *par, double arc, tirenv_ring_carcass *law)
{
    law->k = par->k_c * arc;
    law->w_0 = par->w_c0;
    law->w_s = par->w_cs;
    return par->w_cs > 0 && par->k_c > 0;
}

/* The law beyond w_0, with t = (w - w_0)/w_s: the force k (w_0 + w_s (1 - e^-t)) less the
 * linear k w is -k w_s (t + expm1(-t)), its energy -k w_s^2 (t^2/2 - t - expm1(-t)), its
 * tangent k expm1(-t); all three vanish as t -> 0 (the force's tangent continuous at w_0).
 * expm1 keeps the tangent accurate there; the force and the energy, of order t^2/2 and t^3/6,
 * are sums of terms of order t and keep absolute errors of a few ulp of k w_s t and k w_s^2 t
 * (relative ones of eps/t and eps/t^2), far below the linear k w and k w^2/2 they are added
 * to. Below w_0, zero. */
double tirenv_ring__carcass(const tirenv_ring_carcass *law, double w, double *g1, double *g2)
{
    if (!(w > law->w_0)) {
        *g1 = *g2 = 0;
        return 0;
    }
    const double t = (w - law->w_0) / law->w_s, em = expm1(-t);
    *g1 = -law->k * law->w_s * (t + em);
    *g2 = law->k * em;
    return -law->k * law->w_s * law->w_s * (0.5 * t * t - t - em);
}

size_t tirenv_ring__tread_newton_steps(const tirenv_ring_tread *T) { return T->n_newton; }
