/* SPDX-License-Identifier: Apache-2.0 */
/* Continuous contact of the springs model (docs/models.md section 4.3): a tread between the
 * elements that meets every ground vertex, the tip problem as a QP whose rows couple
 * neighbouring elements, solved exactly by a primal active-set method. */
#include "model/springs_impl.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "profile/profile_impl.h"

/* t closer than this to 0 or 1 is taken as the element itself, and of two rows of a sector
 * closer than this in tau only the higher is kept: two rows on nearly the same point would
 * make the KKT system nearly singular. The tread there moves by at most this fraction of
 * w_(i+1) - w_i (under 1e-8 m). */
static const double t_snap = 1e-6;

double tirenv_springs__cc_gamma(double k_r, double k_ir)
{
    if (!(k_ir > 0))
        return 0.5 * M_PI;
    const double ch = 1 + k_r / (2 * k_ir);
    return acos(1 / (ch + sqrt((ch - 1) * (ch + 1)))); /* exp(-mu) without cancellation */
}

void tirenv_springs__cc_weights(const tirenv_springs__cc_tire *T, double t, double *a,
                                double *b, double *da_dt, double *db_dt)
{
    /* sin((1 - t) g) = sin(g) cos(t g) - cos(g) sin(t g): one sine and cosine of t g. */
    const double g = T->gamma, inv = 1 / T->sin_gamma, cot = T->cot_gamma;
    const double sn = sin(t * g), cs = cos(t * g);
    *a = cs - cot * sn;
    *b = sn * inv;
    *da_dt = -g * (sn + cot * cs);
    *db_dt = g * cs * inv;
}

void tirenv_springs__cc_tire_shape(tirenv_springs__cc_tire *T)
{
    T->gamma = tirenv_springs__cc_gamma(T->k_r, T->k_ir);
    T->sin_gamma = sin(T->gamma);
    T->cot_gamma = cos(T->gamma) / T->sin_gamma;
    /* The bounds from 4096 samples, with margins far above the sampling's error (both
     * functions are smooth, their variation between samples below 1e-7 of their range):
     * ab_lo 1 % under the smallest (a + b - 1) / (t (1 - t)) seen, tau_dev 1 % over the
     * largest |tau - t| plus 1e-9. */
    double lo = INFINITY, dev = 0;
    for (int k = 1; k < 4096; ++k) {
        const double t = k / 4096.0;
        double a, b, da, db;
        tirenv_springs__cc_weights(T, t, &a, &b, &da, &db);
        lo = fmin(lo, (a + b - 1) / (t * (1 - t)));
        dev = fmax(dev, fabs(b / (a + b) - t));
    }
    T->ab_lo = lo > 0 ? 0.99 * lo : 0;
    T->tau_dev = 1.01 * dev + 1e-9;
}

int tirenv_springs__cc_init(tirenv_springs__cc *c, size_t N)
{
    memset(c, 0, sizeof *c);
    size_t **sz[] = {&c->pin_row, &c->sec_first, &c->sec_count, &c->wpos};
    for (size_t k = 0; k < sizeof sz / sizeof sz[0]; ++k)
        if (!(*sz[k] = calloc(N + 1, sizeof **sz[k])))
            return TIRENV_ENOMEM;
    double **dbl[] = {&c->pin_h, &c->w_try, &c->step, &c->raise, &c->tri_piv, &c->tri_mul,
                      &c->tri_x};
    for (size_t k = 0; k < sizeof dbl / sizeof dbl[0]; ++k)
        if (!(*dbl[k] = calloc(N + 2, sizeof **dbl[k])))
            return TIRENV_ENOMEM;
    if (!(c->warm_pin = calloc(N, 1)))
        return TIRENV_ENOMEM;
    if (!(c->chains = calloc(N + 2, sizeof *c->chains))) /* at most (N + 1) / 2 chains */
        return TIRENV_ENOMEM;
    if (!(c->tri_y = calloc(TIRENV_SPRINGS__SCHUR_MAX * (N + 2), sizeof *c->tri_y)))
        return TIRENV_ENOMEM;
    c->f0 = 1;
    c->f1 = 0;
    return TIRENV_OK;
}

void tirenv_springs__cc_free(tirenv_springs__cc *c)
{
    free(c->rows);
    free(c->in_w);
    free(c->lambda);
    free(c->order);
    free(c->env_first);
    free(c->env_last);
    free(c->pos);
    free(c->band);
    free(c->rhs);
    free(c->pin_row);
    free(c->sec_first);
    free(c->sec_count);
    free(c->wpos);
    free(c->pin_h);
    free(c->w_try);
    free(c->step);
    free(c->raise);
    free(c->tri_piv);
    free(c->tri_mul);
    free(c->tri_x);
    free(c->tri_y);
    free(c->chains);
    free(c->warm_ids);
    free(c->warm_pin);
    memset(c, 0, sizeof *c);
}

void tirenv_springs__cc_forget(tirenv_springs__cc *c)
{
    c->n_warm = 0;
    c->n_rows = 0;
    c->f0 = 1;
    c->f1 = 0;
    c->between = 0;
}

/* Room for n rows (and their KKT unknowns alongside N elements). */
static int reserve_rows(tirenv_springs__cc *c, size_t n, size_t N)
{
    if (n <= c->cap_rows)
        return TIRENV_OK;
    size_t cap = c->cap_rows ? c->cap_rows : 64;
    while (cap < n)
        cap *= 2;
    void *r = realloc(c->rows, cap * sizeof *c->rows);
    if (!r)
        return TIRENV_ENOMEM;
    c->rows = r;
    unsigned char *in_w = realloc(c->in_w, cap);
    if (!in_w)
        return TIRENV_ENOMEM;
    c->in_w = in_w;
    double *lambda = realloc(c->lambda, cap * sizeof *lambda);
    if (!lambda)
        return TIRENV_ENOMEM;
    c->lambda = lambda;
    size_t *pos = realloc(c->pos, cap * sizeof *pos);
    if (!pos)
        return TIRENV_ENOMEM;
    c->pos = pos;
    size_t *order = realloc(c->order, (cap + N) * sizeof *order);
    if (!order)
        return TIRENV_ENOMEM;
    c->order = order;
    size_t *env_first = realloc(c->env_first, (cap + N) * sizeof *env_first);
    if (!env_first)
        return TIRENV_ENOMEM;
    c->env_first = env_first;
    size_t *env_last = realloc(c->env_last, (cap + N) * sizeof *env_last);
    if (!env_last)
        return TIRENV_ENOMEM;
    c->env_last = env_last;
    double *rhs = realloc(c->rhs, (cap + N) * sizeof *rhs);
    if (!rhs)
        return TIRENV_ENOMEM;
    c->rhs = rhs;
    c->cap_rows = cap;
    return TIRENV_OK;
}

/* The vertex rows: every ground vertex below the centre's height, within
 * R0 of the centre and inside the tread segment's angle, as a row on the sector of elements it
 * lies in (or on one element, if it lies on its ray). Appended after the n_rows present. */
static int vertex_rows(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                       const tirenv_profile *p, double x, double z, size_t a, size_t b,
                       const double d[])
{
    const double *X = p->x, *Z = p->z, R0 = T->R0, R0sq = R0 * R0;
    const double *st = T->sin_t, *ct = T->cos_t;
    const size_t n = p->n, N = T->N;
    /* A vertex within R0 of the centre lies within the angles of the elements that can reach
     * the ground, [a, b], and one more either side (section 4.8): X - x = rho sin(psi). */
    const size_t a1 = a > 0 ? a - 1 : 0, b1 = b + 1 < N ? b + 1 : N - 1;
    const double lo = x + fmin(0, R0 * (ct[a1] >= 0 ? st[a1] : -1));
    const double hi = x + fmax(0, R0 * (ct[b1] >= 0 ? st[b1] : 1));
    size_t j = tirenv_profile__segment_at(p, lo);
    while (j < n && X[j] < lo)
        ++j;
    /* The end of the run from a search, not a walk over it: a road at 1 mm has hundreds of
     * vertices under the patch. */
    size_t j_end = j;
    if (j < n && X[j] <= hi) {
        j_end = tirenv_profile__segment_near(p, j, hi);
        j_end = j_end < j ? j : j_end;
        while (j_end < n && X[j_end] <= hi)
            ++j_end;
    }
    if (reserve_rows(c, c->n_rows + (j_end - j), N))
        return TIRENV_ENOMEM;
    const double ab_lo = T->ab_lo, tau_dev = T->tau_dev;
    size_t i = T->i0; /* the sector of the last vertex: a walk from it is O(1) on a road */
    /* the rays' penetrations at the ends of sector ci and the chord's slack there */
    size_t ci = SIZE_MAX;
    double P_l = 0, P_r = 0, slack_tau = 0;
    /* rows is NULL while nothing was reserved (no vertex in reach): no offset on it then */
    tirenv_springs__cc_row *out = c->rows ? c->rows + c->n_rows : NULL;
    for (; j < j_end; ++j) {
        const double dx = X[j] - x, dz = z - Z[j];
        if (!(dz > 0))
            continue; /* at or above the centre's height: outside the lower half */
        const double rr = dx * dx + dz * dz;
        if (!(rr < R0sq))
            continue;
        /* sigma_k = rho sin(psi - theta_k): >= 0 at or ahead of ray k. The walk keeps the
         * sigmas it computes: sigma_(i+1) < 0 ends the forward walk, and s_n = -sigma_(i+1)
         * is the same number as dz sin(theta_(i+1)) - dx cos(theta_(i+1)) (the same two
         * products; rounding to nearest is symmetric), never 0. */
        double s_n = 0; /* 0: not known */
        while (i + 1 < N) {
            const double u = dx * ct[i + 1] - dz * st[i + 1];
            if (!(u >= 0)) {
                s_n = -u;
                break;
            }
            ++i;
        }
        double s_i = dx * ct[i] - dz * st[i];
        while (i > 0 && s_i < 0) {
            --i;
            s_i = dx * ct[i] - dz * st[i];
            s_n = 0;
        }
        if (s_i < 0)
            continue; /* behind the first element */
        const double rho = sqrt(rr), h = R0 - rho;
        if (!(h > 0))
            continue;
        /* A row on the element alone (t snapped, or exactly on its ray) keeps t = 0 while
         * z moves within the snap: dt/dz = 0 is the derivative of the rows as used. The
         * weights of a row between elements come later, for the rows that can bind
         * (build_rows); dga_dz holds dt/dz until then. */
        size_t r_i = i, r_j = i;
        double r_t = 0, r_dt = 0;
        if (s_i > 0) {
            if (i + 1 >= N)
                continue; /* beyond the last element's ray */
            if (s_n == 0)
                s_n = dz * st[i + 1] - dx * ct[i + 1]; /* > 0: before ray i + 1 */
            const double S = s_i + s_n, t = s_i / S;
            if (t >= 1 - t_snap) {
                r_i = r_j = i + 1;
            } else if (t > t_snap) {
                /* Below the hull of the rays' own rows (build_rows' test with the rays'
                 * penetrations, which the elements' rows only raise): never binds. */
                if (ci != i) {
                    ci = i;
                    P_l = i >= a && i <= b && d[i] > 0 ? d[i] : 0;
                    P_r = i + 1 >= a && i + 1 <= b && d[i + 1] > 0 ? d[i + 1] : 0;
                    slack_tau = fabs(P_r - P_l) * tau_dev;
                }
                const double chord = (1 - t) * P_l + t * P_r - slack_tau;
                if (!(h > chord * (1 + ab_lo * t * (1 - t))))
                    continue;
                r_j = i + 1;
                r_t = t;
                /* d(s_i)/dz = -sin(theta_i), d(s_n)/dz = sin(theta_(i+1)) */
                r_dt = (-st[i] * s_n - s_i * st[i + 1]) / (S * S);
            }
        }
        *out++ = (tirenv_springs__cc_row){.i = r_i, .j = r_j, .t = r_t, .tau = 0, .ga = 1,
                                          .gb = 0, .h = h, .dga_dz = r_dt, .dgb_dz = 0,
                                          .dh_dz = -dz / rho, .id = (long)j};
    }
    c->n_rows = (size_t)(out - c->rows);
    return TIRENV_OK;
}

/* The weights of a row between elements at its t (dga_dz holding dt/dz). */
static void row_weights(const tirenv_springs__cc_tire *T, tirenv_springs__cc_row *r)
{
    const double dt_dz = r->dga_dz;
    double da, db;
    tirenv_springs__cc_weights(T, r->t, &r->ga, &r->gb, &da, &db);
    r->tau = r->gb / (r->ga + r->gb);
    r->dga_dz = da * dt_dz;
    r->dgb_dz = db * dt_dz;
}

/* Rows ordered by sector, then t, then h: insertion sort (the walk gives nearly that order). */
static void sort_rows(tirenv_springs__cc_row *r, size_t n)
{
    for (size_t k = 1; k < n; ++k) {
        const tirenv_springs__cc_row v = r[k];
        size_t m = k;
        while (m > 0 && (r[m - 1].i > v.i ||
                         (r[m - 1].i == v.i && (r[m - 1].t > v.t ||
                                                (r[m - 1].t == v.t && r[m - 1].h > v.h))))) {
            r[m] = r[m - 1];
            --m;
        }
        r[m] = v;
    }
}

/* (1 - t) w_i + t w_j - h: the row's slack at w, m. */
static double slack(const tirenv_springs__cc_row *r, const double w[])
{
    return r->t > 0 ? r->ga * w[r->i] + r->gb * w[r->j] - r->h : w[r->i] - r->h;
}

/* Upper hull of the sector's points (0, P_l), the rows' (tau, h / (ga + gb)) for rows
 * [first, first + m) and (1, P_r): a row reads (1 - tau) w_i + tau w_j >= h / (ga + gb), so
 * only rows on the hull can bind (a line over [0, 1] above the hull's vertices is above every
 * point), and keeping only them keeps the KKT systems nonsingular. The kept rows
 * are appended at c->rows[*out]; stack has room for m + 2. */
static void hull_rows(tirenv_springs__cc *c, size_t first, size_t m, double P_l, double P_r,
                      size_t *stack, size_t *out)
{
    const tirenv_springs__cc_row *r = c->rows + first;
    size_t top = 0;
    /* point k: 0 the left end, 1..m the rows, m + 1 the right end */
#define PT_T(k) ((k) == 0 ? 0.0 : (k) == m + 1 ? 1.0 : r[(k) - 1].tau)
#define PT_H(k) ((k) == 0 ? P_l : (k) == m + 1 ? P_r : r[(k) - 1].h / (r[(k) - 1].ga + r[(k) - 1].gb))
    for (size_t k = 0; k <= m + 1; ++k) {
        while (top >= 2) {
            const size_t o = stack[top - 2], a = stack[top - 1];
            const double cross = (PT_T(a) - PT_T(o)) * (PT_H(k) - PT_H(o)) -
                                 (PT_H(a) - PT_H(o)) * (PT_T(k) - PT_T(o));
            if (cross < 0)
                break; /* a strictly above the line o-k: a right turn */
            --top;
        }
        stack[top++] = k;
    }
    /* Of two hull vertices within t_snap of each other in tau only the higher is kept (a
     * vertex that near an end was made the element's own row: tau < t_snap needs t < tau). */
    size_t kept = 0;
    double tau_prev = 0, y_prev = 0;
    for (size_t q = 1; q + 1 < top; ++q) {
        const size_t k = stack[q];
        const double y = PT_H(k);
        if (kept > 0 && PT_T(k) - tau_prev < t_snap) {
            if (y > y_prev) {
                c->rows[*out - 1] = r[k - 1];
                tau_prev = PT_T(k);
                y_prev = y;
            }
            continue;
        }
        c->rows[(*out)++] = r[k - 1];
        ++kept;
        tau_prev = PT_T(k);
        y_prev = y;
    }
#undef PT_T
#undef PT_H
}

/* Whether element e is held by its own row in the working set: then w_e = h is known and
 * neither w_e nor that row's reaction is an unknown of the KKT system. */
static int fixed(const tirenv_springs__cc *c, size_t e)
{
    const size_t pr = c->pin_row[e];
    return pr != SIZE_MAX && c->in_w[pr];
}

/* The KKT system of the working set on the unknowns left once the held elements are
 * eliminated: w_e of the free elements in [f0, f1], each followed by the rows of sector e - 1
 * in the working set (whose free elements then precede them), in the symmetric form
 * [K G^T; G 0] [w; mu] = [.; .], mu = -lambda. Every row follows the unknowns it couples, so
 * with K positive definite and the rows independent every leading block is nonsingular and
 * LDL^T needs no pivoting (w pivots > 0, row pivots < 0). Returns 1 if a pivot shows the rows
 * dependent (a row on held elements only, among others), -1 out of memory. */
static int kkt_factor(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T)
{
    const size_t f0 = c->f0, f1 = c->f1, N = T->N;
    size_t n = 0, n_schur = 0;
    for (size_t e = f0; e <= f1; ++e) {
        if (fixed(c, e)) {
            c->wpos[e] = SIZE_MAX;
        } else {
            c->wpos[e] = n;
            c->order[n++] = e;
        }
        if (e > f0)
            for (size_t r = c->sec_first[e - 1], k = 0; k < c->sec_count[e - 1]; ++k, ++r)
                if (c->in_w[r]) {
                    c->pos[r] = n;
                    if (n_schur < TIRENV_SPRINGS__SCHUR_MAX)
                        c->schur_pos[n_schur] = n;
                    ++n_schur;
                    c->order[n++] = N + r;
                }
    }
    c->n_kkt = n;
    c->n_schur = n_schur;
    c->use_schur = n_schur <= TIRENV_SPRINGS__SCHUR_MAX;
    if (c->use_schur)
        return tirenv_springs__cc_schur_factor(c, T);
    /* The band's half-width, for the banded path only: how far each unknown's row reaches
     * back, an element to its free left neighbour, a row (of sector i, laid out after
     * element i + 1) to the first free element of the two it couples. */
    size_t bw = 1;
    for (size_t p = 0; p < n; ++p) {
        const size_t u = c->order[p];
        size_t low;
        if (u < N) {
            low = u > f0 ? c->wpos[u - 1] : SIZE_MAX;
        } else {
            const size_t i = c->rows[u - N].i;
            low = c->wpos[i] != SIZE_MAX ? c->wpos[i] : c->wpos[i + 1];
        }
        if (low != SIZE_MAX && p - low > bw)
            bw = p - low;
    }
    const size_t W = bw + 1;
    if (n * W > c->cap_band) {
        double *band = realloc(c->band, n * W * sizeof *band);
        if (!band)
            return -1;
        c->band = band;
        c->cap_band = n * W;
    }
    c->n_kkt = n;
    c->bw = bw;
    double *L = c->band;
    memset(L, 0, n * W * sizeof *L);
#define AT(p, q) L[(p) * W + ((p) - (q))]
    size_t *first = c->env_first, *last = c->env_last;
    for (size_t e = f0; e <= f1; ++e) {
        if (c->wpos[e] == SIZE_MAX)
            continue;
        double k_ee = T->diag[e];
        if (e == f0 && f0 > 0)
            k_ee -= T->k_ir * T->lq[f0 - 1];
        if (e == f1 && f1 + 1 < N)
            k_ee -= T->k_ir * T->rq[f1 + 1];
        const size_t p = c->wpos[e];
        AT(p, p) = k_ee;
        first[p] = p;
        if (e > f0 && c->wpos[e - 1] != SIZE_MAX) {
            AT(p, c->wpos[e - 1]) = -T->k_ir;
            first[p] = c->wpos[e - 1];
        }
    }
    for (size_t p = 0; p < n; ++p) {
        if (c->order[p] < N)
            continue;
        const tirenv_springs__cc_row *r = &c->rows[c->order[p] - N];
        first[p] = p;
        if (c->wpos[r->i] != SIZE_MAX) {
            AT(p, c->wpos[r->i]) = r->ga;
            first[p] = c->wpos[r->i];
        }
        if (r->t > 0 && c->wpos[r->j] != SIZE_MAX) {
            AT(p, c->wpos[r->j]) = r->gb;
            first[p] = c->wpos[r->j] < first[p] ? c->wpos[r->j] : first[p];
        }
    }
    /* The envelope (skyline) of the band: LDL^T fills no entry of a row before its first
     * nonzero, so each row's loops start there; the entries skipped are exact zeros, which
     * leaves every sum as the full band's. last[q]: the last row p with first[p] <= q (the
     * suffix minimum of first is nondecreasing, so one sweep finds it). */
    for (size_t p = n, m = SIZE_MAX, q = n; p-- > 0;) {
        m = first[p] < m ? first[p] : m; /* min of first[p..n-1] */
        while (q > m)
            last[--q] = p;
    }
    const double k_max = T->k_r + 2 * T->k_ir;
    for (size_t p = 0; p < n; ++p) {
        const size_t lo = first[p];
        double *Lp = L + p * W;
        for (size_t q = lo; q <= p; ++q) {
            const double *Lq = L + q * W;
            double s = Lp[p - q];
            const size_t klo = first[q] > lo ? first[q] : lo;
            for (size_t k = klo; k < q; ++k)
                s -= Lp[p - k] * Lq[q - k] * L[k * W];
            if (q < p)
                Lp[p - q] = s / Lq[0];
            else
                Lp[0] = s;
        }
        const double D = Lp[0];
        if (c->order[p] < N ? !(D > 0) : !(D < -1e-14 / k_max))
            return 1;
    }
    return 0;
}

/* Solves the factored system for b (length n_kkt) in place. */
static void kkt_solve(const tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                      double b[])
{
    if (c->use_schur) {
        tirenv_springs__cc_schur_solve(c, T, b);
        return;
    }
    const size_t n = c->n_kkt, bw = c->bw, W = bw + 1;
    const double *L = c->band;
    const size_t *first = c->env_first, *last = c->env_last;
    for (size_t p = 0; p < n; ++p) {
        const size_t lo = first[p];
        const double *Lp = L + p * W;
        double s = b[p];
        for (size_t k = lo; k < p; ++k)
            s -= Lp[p - k] * b[k];
        b[p] = s;
    }
    for (size_t p = 0; p < n; ++p)
        b[p] /= L[p * W];
    for (size_t p = n; p-- > 0;) {
        const size_t hi = last[p]; /* rows past it have a zero in column p */
        double s = b[p];
        for (size_t k = p + 1; k <= hi; ++k)
            s -= AT(k, p) * b[k];
        b[p] = s;
    }
#undef AT
}

/* The right-hand side of the reduced system for held values v (v[e] on held elements) and
 * w-part and row-part sources: w-part k_ir v of held neighbours, row-part less the held
 * elements' share. */
static void reduced_rhs(const tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                        const double v[], double b[])
{
    const size_t N = T->N, f0 = c->f0, f1 = c->f1;
    if (c->use_schur) { /* a free element next to a held one ends a chain */
        for (size_t q = 0; q < c->n_chains; ++q) {
            const size_t lo = c->chains[2 * q], hi = c->chains[2 * q + 1];
            if (lo > f0)
                b[c->wpos[lo]] += T->k_ir * v[lo - 1];
            if (hi < f1)
                b[c->wpos[hi]] += T->k_ir * v[hi + 1];
        }
        for (size_t q = 0; q < c->n_schur; ++q) {
            const size_t p = c->schur_pos[q];
            const tirenv_springs__cc_row *r = &c->rows[c->order[p] - N];
            if (c->wpos[r->i] == SIZE_MAX)
                b[p] -= r->ga * v[r->i];
            if (r->t > 0 && c->wpos[r->j] == SIZE_MAX)
                b[p] -= r->gb * v[r->j];
        }
        return;
    }
    for (size_t p = 0; p < c->n_kkt; ++p) {
        const size_t u = c->order[p];
        if (u < N) {
            if (u > f0 && c->wpos[u - 1] == SIZE_MAX)
                b[p] += T->k_ir * v[u - 1];
            if (u < f1 && c->wpos[u + 1] == SIZE_MAX)
                b[p] += T->k_ir * v[u + 1];
        } else {
            const tirenv_springs__cc_row *r = &c->rows[u - N];
            if (c->wpos[r->i] == SIZE_MAX)
                b[p] -= r->ga * v[r->i];
            if (r->t > 0 && c->wpos[r->j] == SIZE_MAX)
                b[p] -= r->gb * v[r->j];
        }
    }
}

/* The minimiser of 1/2 w^T K w on the working set's rows as equalities: w into wq[f0..f1],
 * the rows' reactions into lambda (a held element's own row's from its equation of K w =
 * G^T lambda). 1 if the rows are dependent, -1 out of memory. */
static int eqp(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T, double wq[])
{
    const int st = kkt_factor(c, T);
    if (st)
        return st;
    const size_t N = T->N, f0 = c->f0, f1 = c->f1;
    double *b = c->rhs;
    for (size_t e = f0; e <= f1; ++e)
        if (c->wpos[e] == SIZE_MAX)
            wq[e] = c->rows[c->pin_row[e]].h;
    for (size_t p = 0; p < c->n_kkt; ++p)
        b[p] = c->order[p] < N ? 0 : c->rows[c->order[p] - N].h;
    reduced_rhs(c, T, wq, b);
    kkt_solve(c, T, b);
    for (size_t p = 0; p < c->n_kkt; ++p) {
        if (c->order[p] < N)
            wq[c->order[p]] = b[p];
        else
            c->lambda[c->order[p] - N] = -b[p];
    }
    /* The held elements' reactions: (K w)_e less what the working rows between elements
     * put on e. */
    for (size_t e = f0; e <= f1; ++e) {
        if (c->wpos[e] != SIZE_MAX)
            continue;
        double k_ee = T->diag[e];
        if (e == f0 && f0 > 0)
            k_ee -= T->k_ir * T->lq[f0 - 1];
        if (e == f1 && f1 + 1 < N)
            k_ee -= T->k_ir * T->rq[f1 + 1];
        double Kw = k_ee * wq[e];
        if (e > f0)
            Kw -= T->k_ir * wq[e - 1];
        if (e < f1)
            Kw -= T->k_ir * wq[e + 1];
        for (int side = 0; side < 2; ++side) { /* sectors e - 1 and e */
            if ((side == 0 && e == f0) || (side == 1 && e == f1))
                continue;
            const size_t sec = side == 0 ? e - 1 : e;
            for (size_t r = c->sec_first[sec], k = 0; k < c->sec_count[sec]; ++k, ++r)
                if (c->in_w[r])
                    Kw -= (side == 0 ? c->rows[r].gb : c->rows[r].ga) * c->lambda[r];
        }
        c->lambda[c->pin_row[e]] = Kw;
    }
    return 0;
}

static int long_in(const long *v, size_t n, long key)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (v[mid] < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < n && v[lo] == key;
}

/* The rows of the problem at (x, z): vertex rows and the rays' pins, reduced to each sector's
 * upper hull, laid out element by element; sets f0, f1. */
static int build_rows(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                      const tirenv_profile *p, double x, double z, size_t a, size_t b,
                      const double d[])
{
    const size_t N = T->N;
    c->n_rows = 0;
    if (vertex_rows(c, T, p, x, z, a <= b ? a : 0, a <= b ? b : N - 1, d))
        return TIRENV_ENOMEM;
    const size_t nv = c->n_rows;
    if (reserve_rows(c, 2 * nv + N + 2, N))
        return TIRENV_ENOMEM;
    tirenv_springs__cc_row *R = c->rows;
    sort_rows(R, nv);
    /* The elements any row can touch: the rays' that meet the ground, the vertices'. */
    size_t lo = N, hi = 0;
    for (size_t e = a; a <= b && e <= b; ++e)
        if (d[e] > 0) {
            lo = e;
            break;
        }
    for (size_t e = b + 1; a <= b && e-- > lo;)
        if (d[e] > 0) {
            hi = e;
            break;
        }
    if (nv > 0) {
        lo = R[0].i < lo ? R[0].i : lo;
        const size_t top = R[nv - 1].t > 0 ? R[nv - 1].i + 1 : R[nv - 1].i;
        hi = top > hi ? top : hi;
    }
    if (lo > hi) {
        c->f0 = 1;
        c->f1 = 0;
        return TIRENV_OK;
    }
    /* Pins: the ray's penetration, or a vertex on the ray standing higher. pin_row holds
     * the vertex row (SIZE_MAX: the ray) until the rows are laid out. */
    for (size_t e = lo; e <= hi; ++e) {
        c->pin_h[e] = a <= e && e <= b && d[e] > 0 ? d[e] : 0;
        c->pin_row[e] = SIZE_MAX;
        c->sec_count[e] = 0;
    }
    for (size_t k = 0; k < nv; ++k)
        if (R[k].t == 0 && R[k].h > c->pin_h[R[k].i]) {
            c->pin_h[R[k].i] = R[k].h;
            c->pin_row[R[k].i] = k;
        }
    /* Lay out the kept rows after the vertex rows, then move them to the front. */
    size_t out = nv, k = 0;
    size_t *stack = c->pos;
    c->f0 = SIZE_MAX;
    c->f1 = 0;
    for (size_t e = lo; e <= hi; ++e) {
        if (c->pin_h[e] > 0) {
            const size_t src = c->pin_row[e];
            c->pin_row[e] = out - nv;
            if (src != SIZE_MAX)
                R[out] = R[src];
            else
                R[out] = (tirenv_springs__cc_row){.i = e, .j = e, .t = 0, .tau = 0, .ga = 1,
                                                  .gb = 0, .h = c->pin_h[e], .dga_dz = 0,
                                                  .dgb_dz = 0, .dh_dz = NAN,
                                                  .id = -1 - (long)e};
            ++out;
            c->f0 = e < c->f0 ? e : c->f0;
            c->f1 = e;
        } else {
            c->pin_row[e] = SIZE_MAX;
        }
        while (k < nv && R[k].i < e)
            ++k;
        size_t first = k, m = 0;
        while (k < nv && R[k].i == e) {
            if (R[k].t > 0) {
                if (m == 0)
                    first = k;
                ++m;
            }
            ++k;
        }
        c->sec_first[e] = out - nv;
        if (m > 0 && e + 1 <= hi) {
            const double P_r = c->pin_h[e + 1] > 0 ? c->pin_h[e + 1] : 0;
            const double P_l = c->pin_h[e] > 0 ? c->pin_h[e] : 0;
            /* A row lies below the hull if h / (ga + gb) is at most the chord between the
             * ends at its tau: with ga + gb >= 1 + ab_lo t (1 - t) and |tau - t| <=
             * tau_dev, if h / (1 + ab_lo t (1 - t)) <= (1 - t) P_l + t P_r - |P_r - P_l|
             * tau_dev. Such rows (nearly every vertex of a smooth road: the tread bows out
             * between its tips) are dropped before their weights are computed. */
            const double slack_tau = fabs(P_r - P_l) * T->tau_dev;
            size_t kept = 0;
            for (size_t q = first; q < first + m; ++q) {
                const double t = R[q].t;
                const double chord = (1 - t) * P_l + t * P_r - slack_tau;
                if (R[q].h > chord * (1 + T->ab_lo * t * (1 - t))) {
                    R[first + kept] = R[q];
                    row_weights(T, &R[first + kept]);
                    ++kept;
                }
            }
            if (kept > 0)
                hull_rows(c, first, kept, P_l, P_r, stack, &out);
        }
        c->sec_count[e] = out - nv - c->sec_first[e];
        if (c->sec_count[e] > 0) {
            c->f0 = e < c->f0 ? e : c->f0;
            c->f1 = e + 1;
        }
    }
    c->n_rows = out - nv;
    memmove(R, R + nv, c->n_rows * sizeof *R);
    if (c->f0 == SIZE_MAX) {
        c->f0 = 1;
        c->f1 = 0;
    }
    return TIRENV_OK;
}

/* The warm start's working set: the last solution's, where it still names rows here. */
static void warm_set(tirenv_springs__cc *c)
{
    for (size_t r = 0; r < c->n_rows; ++r) {
        const tirenv_springs__cc_row *R = &c->rows[r];
        c->in_w[r] = R->t == 0 ? c->warm_pin[R->i] : long_in(c->warm_ids, c->n_warm, R->id);
    }
}

static int keep_warm(tirenv_springs__cc *c, size_t N)
{
    memset(c->warm_pin, 0, N);
    size_t n = 0;
    for (size_t r = 0; r < c->n_rows; ++r)
        if (c->in_w[r] && c->rows[r].t > 0)
            ++n;
    if (n > c->cap_warm) {
        long *ids = realloc(c->warm_ids, n * sizeof *ids);
        if (!ids)
            return TIRENV_ENOMEM;
        c->warm_ids = ids;
        c->cap_warm = n;
    }
    n = 0;
    for (size_t r = 0; r < c->n_rows; ++r) {
        if (!c->in_w[r])
            continue;
        if (c->rows[r].t > 0) {
            const long id = c->rows[r].id;
            size_t m = n++;
            while (m > 0 && c->warm_ids[m - 1] > id) {
                c->warm_ids[m] = c->warm_ids[m - 1];
                --m;
            }
            c->warm_ids[m] = id;
        } else {
            c->warm_pin[c->rows[r].i] = 1;
        }
    }
    c->n_warm = n;
    return TIRENV_OK;
}

int tirenv_springs__cc_rows(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                            const tirenv_profile *p, double x, double z, size_t a, size_t b,
                            const double d[], tirenv_diag *diag)
{
    if (build_rows(c, T, p, x, z, a, b, d))
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for the contact "
                            "rows of the springs model");
    return TIRENV_OK;
}

int tirenv_springs__cc_pins_hold(const tirenv_springs__cc *c, const double w[], double tol)
{
    for (size_t r = 0; r < c->n_rows; ++r)
        if (c->rows[r].t > 0 && slack(&c->rows[r], w) < -tol)
            return 0;
    return 1;
}

int tirenv_springs__cc_solve(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                             double x, double z, double w[], double pe[], double obstacle[],
                             tirenv_diag *diag)
{
    const size_t N = T->N;
    c->iterations = 0;
    const size_t f0 = c->f0, f1 = c->f1, n_rows = c->n_rows;
    if (f0 > f1) {
        c->n_warm = 0;
        memset(c->warm_pin, 0, N);
        return TIRENV_OK;
    }
    const double tol = 1e-12 * T->R0;
    double *wc = c->w_try, *wq = c->step, *raise = c->raise;
    /* Warm start: the last working set's minimiser, if the rows are independent; raised
     * where rows are violated (rows have weights >= 0, so raising w satisfies them), which
     * keeps the working set's rows that are still tight. Else a cold start from w_e = the
     * largest h of a row on e, which satisfies every row, with no row working. */
    warm_set(c);
    int at_min = 0, st = eqp(c, T, wq);
    if (st < 0)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for the contact "
                            "of the springs model");
    if (st == 0) {
        for (size_t e = f0; e <= f1; ++e)
            raise[e] = 0;
        int violated = 0;
        for (size_t r = 0; r < n_rows; ++r) {
            const double s = slack(&c->rows[r], wq);
            if (!c->in_w[r] && s < -tol) {
                violated = 1;
                const tirenv_springs__cc_row *R = &c->rows[r];
                raise[R->i] = fmax(raise[R->i], -s);
                if (R->t > 0)
                    raise[R->j] = fmax(raise[R->j], -s);
            }
        }
        for (size_t e = f0; e <= f1; ++e)
            wc[e] = wq[e] + raise[e];
        if (violated) {
            for (size_t r = 0; r < n_rows; ++r) {
                const tirenv_springs__cc_row *R = &c->rows[r];
                if (c->in_w[r] && (raise[R->i] > 0 || (R->t > 0 && raise[R->j] > 0)))
                    c->in_w[r] = 0;
            }
        } else {
            at_min = 1;
        }
    } else {
        for (size_t e = f0; e <= f1; ++e)
            wc[e] = 0;
        for (size_t r = 0; r < n_rows; ++r) {
            const tirenv_springs__cc_row *R = &c->rows[r];
            c->in_w[r] = 0;
            wc[R->i] = fmax(wc[R->i], R->h);
            if (R->t > 0)
                wc[R->j] = fmax(wc[R->j], R->h);
        }
    }
    /* The primal active-set method (Nocedal and Wright, Algorithm 16.3): from a feasible
     * point, step to the working set's minimiser or to the first row in the way (which joins
     * the set: independent of it, since the step keeps its rows); at the minimiser, release
     * the row with the most negative reaction, or stop: every reaction >= 0. Finite without
     * cycling for a strictly convex QP whose steps are not degenerate. */
    const size_t max_iter = 3 * n_rows + 10;
    size_t it = 0;
    for (;; ++it) {
        if (it >= max_iter)
            return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "ELEMENT_ANGLE",
                                "the continuous tip contact (%zu rows on elements %zu to "
                                "%zu) did not settle in %zu active-set steps at x = %.9g m, "
                                "z = %.9g m", n_rows, f0, f1, max_iter, x, z);
        if (!at_min) {
            st = eqp(c, T, wq);
            if (st)
                return tirenv_error(diag, st < 0 ? TIRENV_ENOMEM : TIRENV_ENOCONV, "", 0,
                                    "ELEMENT_ANGLE",
                                    "the continuous tip contact at x = %.9g m, z = %.9g m met "
                                    "dependent rows (%zu rows on elements %zu to %zu)", x, z,
                                    n_rows, f0, f1);
            double alpha = 1;
            size_t block = SIZE_MAX;
            for (size_t e = f0; e <= f1; ++e)
                raise[e] = wq[e] - wc[e]; /* the step */
            for (size_t r = 0; r < n_rows; ++r) {
                if (c->in_w[r])
                    continue;
                const tirenv_springs__cc_row *R = &c->rows[r];
                const double gp = R->t > 0 ? R->ga * raise[R->i] + R->gb * raise[R->j]
                                           : raise[R->i];
                if (!(gp < 0))
                    continue;
                const double s = fmax(slack(R, wc), 0), ar = s / -gp;
                if (ar < alpha) {
                    alpha = ar;
                    block = r;
                }
            }
            if (block == SIZE_MAX) {
                for (size_t e = f0; e <= f1; ++e)
                    wc[e] = wq[e];
                at_min = 1;
            } else {
                for (size_t e = f0; e <= f1; ++e)
                    wc[e] += alpha * raise[e];
                c->in_w[block] = 1;
                continue;
            }
        }
        /* At the working set's minimiser: the reactions decide. */
        double l_min = 0, l_max = 0;
        size_t drop = SIZE_MAX;
        for (size_t r = 0; r < n_rows; ++r)
            if (c->in_w[r])
                l_max = fmax(l_max, fabs(c->lambda[r]));
        for (size_t r = 0; r < n_rows; ++r)
            if (c->in_w[r] && c->lambda[r] < l_min) {
                l_min = c->lambda[r];
                drop = r;
            }
        if (drop == SIZE_MAX || l_min >= -1e-12 * l_max)
            break;
        c->in_w[drop] = 0;
        at_min = 0;
    }
    c->iterations = it + 1;
    for (size_t r = 0; r < n_rows; ++r)
        if (!c->in_w[r])
            c->lambda[r] = 0;
    for (size_t e = f0; e <= f1; ++e) {
        w[e] = wc[e];
        pe[e] = 0;
        obstacle[e] = c->pin_h[e] > 0 ? c->pin_h[e] : 0;
    }
    for (size_t r = 0; r < n_rows; ++r) {
        const tirenv_springs__cc_row *R = &c->rows[r];
        if (R->t > 0) {
            pe[R->i] += R->ga * c->lambda[r];
            pe[R->j] += R->gb * c->lambda[r];
        } else {
            pe[R->i] += c->lambda[r];
        }
    }
    w[(long)f0 - 1] = f0 > 0 ? T->lq[f0 - 1] * w[f0] : 0;
    w[f1 + 1] = f1 + 1 < N ? T->rq[f1 + 1] * w[f1] : 0;
    if (keep_warm(c, N))
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for the contact "
                            "of the springs model");
    return TIRENV_OK;
}

void tirenv_springs__cc_slope(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                              const double w[], const double dd[], double dw[])
{
    const size_t N = T->N, f0 = c->f0, f1 = c->f1;
    if (f0 > f1)
        return;
    /* The factors are the working set's from the last eqp (the final set: the last solve
     * was at its minimiser). d/dz of K w = G^T lambda and of G w = h with the set fixed:
     * K dw - G^T dlambda = dG^T lambda, G dw = dh - dG w; a held element's dw is its row's
     * dh. */
    for (size_t e = f0; e <= f1; ++e)
        if (c->wpos[e] == SIZE_MAX) {
            const tirenv_springs__cc_row *R = &c->rows[c->pin_row[e]];
            dw[e] = R->id < 0 ? dd[e] : R->dh_dz;
        }
    double *b = c->rhs;
    for (size_t p = 0; p < c->n_kkt; ++p)
        b[p] = 0;
    for (size_t p = 0; p < c->n_kkt; ++p) {
        if (c->order[p] < N)
            continue;
        const size_t r = c->order[p] - N;
        const tirenv_springs__cc_row *R = &c->rows[r];
        double rhs = R->id < 0 ? dd[R->i] : R->dh_dz;
        if (R->t > 0) {
            rhs -= R->dga_dz * w[R->i] + R->dgb_dz * w[R->j];
            if (c->wpos[R->i] != SIZE_MAX)
                b[c->wpos[R->i]] += R->dga_dz * c->lambda[r];
            if (c->wpos[R->j] != SIZE_MAX)
                b[c->wpos[R->j]] += R->dgb_dz * c->lambda[r];
        }
        b[p] = rhs;
    }
    reduced_rhs(c, T, dw, b);
    kkt_solve(c, T, b);
    for (size_t e = f0; e <= f1; ++e)
        if (c->wpos[e] != SIZE_MAX)
            dw[e] = b[c->wpos[e]];
}
