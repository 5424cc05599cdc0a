/* SPDX-License-Identifier: Apache-2.0 */
/* The empirical model over a road, evaluated (tirenv_nn_road_eval; the model and why it is
 * built so: nn_road.c and docs/models.md section 12). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "nn/nn_road_impl.h"
#include "tirenv/nn_road.h"

/* Where a term's network input x_N comes from: tirenv_xN(-|d|, x_0) for the obstacle's cleat,
 * d = x - c, exactly as tirenv_nn_envelope forms it for a cleat centred at 0. */
static double obstacle_xN(const road_obstacle *o, double d)
{
    return (-fabs(d) - o->x_0) / (-o->x_0);
}

/* Queues one network evaluation: obstacle k at position p of the chunk. */
static void push(tirenv_nn_road *r, size_t p, size_t k, double x_N);

/* Runs the queued evaluations in one batch and folds each term into its position's maximum.
 * A term is tirenv_nn_envelope's value (0 for a negative output), scaled, clipped to [0, H],
 * added to b(x) and capped at the top. The winner of equal terms is the lowest obstacle
 * index (a term equal to the baseline does not win): a rule that does not depend on the
 * order terms arrive in, so pruned and exhaustive evaluation pick the same winner. */
static void flush(tirenv_nn_road *r)
{
    road_work *w = &r->work;
    if (w->n == 0)
        return;
    tirenv_nn_run_batch(r->nn, w->n, w->in, w->y);
    for (size_t j = 0; j < w->n; ++j) {
        const size_t p = w->pos[j], k = w->k[j];
        const road_obstacle *o = &r->ob[k];  /* met at this contact length when pushed */
        const double y = w->y[j] >= 0 ? w->y[j] : 0;  /* NaN cannot come, but maps to 0 */
        double g = o->scale * y;
        int flat = 0;
        if (g > o->H) {
            g = o->H;
            flat = 1;
        }
        double t = w->b[p] + g;
        if (t > o->top) {
            t = o->top;
            flat = 2;
        }
        if (t > w->h[p] || (t == w->h[p] && w->best[p] != ROAD_NONE && k < w->best[p])) {
            w->h[p] = t;
            w->best[p] = k;
            w->flat[p] = flat;
            w->x_N[p] = w->in[j * TIRENV_NN_INPUTS + TIRENV_NN_X_N];
        }
    }
    w->n = 0;
}

static void push(tirenv_nn_road *r, size_t p, size_t k, double x_N)
{
    road_work *w = &r->work;
    if (w->n == ROAD_PENDING)
        flush(r);
    double *u = w->in + w->n * TIRENV_NN_INPUTS;
    u[TIRENV_NN_X_N] = x_N;
    u[TIRENV_NN_CONTACT_LENGTH] = r->l_c;
    u[TIRENV_NN_HEIGHT] = r->ob[k].H_net;
    u[TIRENV_NN_LENGTH] = r->ob[k].L_net;
    w->pos[w->n] = p;
    w->k[w->n] = k;
    w->n++;
}

/* The first obstacle whose centre is at or after x_lo, from the last window's. */
static size_t window_start(tirenv_nn_road *r, double x_lo)
{
    const road_obstacle *ob = r->ob;
    size_t lo = 0, hi = r->n_ob, k = r->hint;
    if (k > 0 && ob[k - 1].c >= x_lo) {
        hi = k - 1;  /* went backwards: bisect before the hint */
    } else {
        for (size_t walk = 0; walk < HINT_WALK && k < r->n_ob && ob[k].c < x_lo; ++walk)
            ++k;
        if (k == r->n_ob || ob[k].c >= x_lo)
            return r->hint = k;
        lo = k;
    }
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (ob[mid].c < x_lo)
            lo = mid + 1;
        else
            hi = mid;
    }
    return r->hint = lo;
}

/* Pruned: each position looks only at obstacles whose centre is within the largest reach,
 * and at those only within their own reach. First pass: the one with the highest bound
 * min(top, b + H), which is usually the winner. Second pass: the others whose bound can
 * still beat the maximum so far (a term never exceeds its bound: g <= H and rounding is
 * monotone), under the winner rule of flush. */
static void chunk_pruned(tirenv_nn_road *r, size_t m, const double x[])
{
    road_work *w = &r->work;
    for (size_t p = 0; p < m; ++p) {
        const size_t lo = window_start(r, x[p] - r->reach_max);
        size_t hi = lo, k_best = ROAD_NONE;
        double bound_best = w->b[p], x_N_best = 0;
        for (; hi < r->n_ob && r->ob[hi].c <= x[p] + r->reach_max; ++hi) {
            const road_obstacle *o = obstacle_at(r, hi);
            const double d = x[p] - o->c;
            const double lift = w->b[p] + o->H, bound = o->top < lift ? o->top : lift;
            if (fabs(d) > o->reach || !(bound > bound_best))
                continue;
            const double x_N = obstacle_xN(o, d);
            if (!(x_N >= r->x_N_min))
                continue;
            k_best = hi;
            bound_best = bound;
            x_N_best = x_N;
        }
        w->lo[p] = lo;
        w->hi[p] = hi;
        w->first[p] = k_best;
        if (k_best != ROAD_NONE)
            push(r, p, k_best, x_N_best);
    }
    flush(r);
    for (size_t p = 0; p < m; ++p) {
        for (size_t k = w->lo[p]; k < w->hi[p]; ++k) {
            const road_obstacle *o = obstacle_at(r, k);
            const double d = x[p] - o->c;
            const double lift = w->b[p] + o->H, bound = o->top < lift ? o->top : lift;
            if (k == w->first[p] || fabs(d) > o->reach || bound < w->h[p] ||
                (bound == w->h[p] && (w->best[p] == ROAD_NONE || k > w->best[p])))
                continue;
            const double x_N = obstacle_xN(o, d);
            if (x_N >= r->x_N_min)
                push(r, p, k, x_N);
        }
    }
    flush(r);
}

/* Exhaustive (prune 0): every obstacle at every position, the definition of h. */
static void chunk_all(tirenv_nn_road *r, size_t m, const double x[])
{
    for (size_t p = 0; p < m; ++p)
        for (size_t k = 0; k < r->n_ob; ++k) {
            const double x_N = obstacle_xN(obstacle_at(r, k), x[p] - r->ob[k].c);
            if (x_N >= r->x_N_min)
                push(r, p, k, x_N);
        }
    flush(r);
}

/* dh/dx of the winning term: b'(x) for the baseline or a lift clipped at H, 0 for a term
 * capped at the top, else b'(x) + scale * dy/dx_N * dx_N/dx with dx_N/dx = sign(d)/x_0
 * (x_N = 1 + |d|/x_0; 0 on the axis of symmetry, where the curve has its corner). dy/dx_N by
 * central differences of the network, step slope_step in x_N, in one batch. */
static void chunk_slope(tirenv_nn_road *r, size_t m, const double x[], double slope[])
{
    road_work *w = &r->work;
    size_t n = 0;
    for (size_t p = 0; p < m; ++p) {
        const size_t k = w->best[p];
        slope[p] = k == ROAD_NONE || w->flat[p] == 1 ? w->db[p] : 0;
        if (k == ROAD_NONE || w->flat[p])
            continue;
        for (int side = -1; side <= 1; side += 2) {
            double *u = w->in + n++ * TIRENV_NN_INPUTS;
            u[TIRENV_NN_X_N] = w->x_N[p] + side * slope_step;
            u[TIRENV_NN_CONTACT_LENGTH] = r->l_c;
            u[TIRENV_NN_HEIGHT] = r->ob[k].H_net;
            u[TIRENV_NN_LENGTH] = r->ob[k].L_net;
        }
    }
    tirenv_nn_run_batch(r->nn, n, w->in, w->y);
    n = 0;
    for (size_t p = 0; p < m; ++p) {
        const size_t k = w->best[p];
        if (k == ROAD_NONE || w->flat[p])
            continue;
        const road_obstacle *o = &r->ob[k];
        const double dy = (w->y[n + 1] - w->y[n]) / (2 * slope_step);
        n += 2;
        const double d = x[p] - o->c, sign = d > 0 ? 1.0 : d < 0 ? -1.0 : 0.0;
        slope[p] = w->db[p] + o->scale * dy * sign / o->x_0;
    }
}

int tirenv_nn_road_eval(tirenv_nn_road *r, size_t n, const double x[], double h[],
                        double slope[], tirenv_diag *diag)
{
    if (!r || (n > 0 && (!x || !h)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "",
                            "expected a decomposition and arrays x and h of %zu positions",
                            n);
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(x[i]))
            return tirenv_error(diag, TIRENV_EINVAL, "", i + 1, "x",
                                "position %zu: x = %g; expected a finite number (m)", i,
                                x[i]);
    road_work *w = &r->work;
    for (size_t i0 = 0; i0 < n; i0 += ROAD_CHUNK) {
        const size_t m = n - i0 < ROAD_CHUNK ? n - i0 : ROAD_CHUNK;
        for (size_t p = 0; p < m; ++p) {
            w->b[p] = w->h[p] = baseline_at(r, x[i0 + p], &w->db[p]);
            w->best[p] = ROAD_NONE;
        }
        if (r->prune)
            chunk_pruned(r, m, x + i0);
        else
            chunk_all(r, m, x + i0);
        memcpy(h + i0, w->h, m * sizeof *h);
        if (slope)
            chunk_slope(r, m, x + i0, slope + i0);
    }
    return TIRENV_OK;
}
