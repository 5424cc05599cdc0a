/* SPDX-License-Identifier: Apache-2.0 */
/* Private to src/nn: the empirical model over a road (nn_road.c builds it, nn_road_eval.c
 * evaluates it): its record, the evaluation's workspace, and what both ask of an obstacle and
 * of the baseline. */
#ifndef TIRENV_NN_ROAD_IMPL_H
#define TIRENV_NN_ROAD_IMPL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "tirenv/nn_road.h"
#include "tirenv/xn.h"

/* A forward pass gives up on the window hint and bisects when it is this many obstacles
 * behind. Positions are evaluated ROAD_CHUNK at a time, their network evaluations queued and
 * run ROAD_PENDING at a time through tirenv_nn_run_batch (bit for bit tirenv_nn_run, at
 * about 2.5 times its rate); the chunk's slopes take two evaluations per position, so
 * ROAD_PENDING >= 2*ROAD_CHUNK. */
enum { HINT_WALK = 16, ROAD_CHUNK = 64, ROAD_PENDING = 256 };
#define ROAD_NONE SIZE_MAX   /* no obstacle: the baseline wins */

/* Step in x_N of the central difference for the network's dy/dx_N: truncation (step^2 times
 * the third derivative, which is of order 1 m) and rounding (an ulp of h over the step) both
 * stay below 1e-9 of the slope. */
static const double slope_step = 1e-5;

/* The window of an obstacle is its exact reach widened by this relative margin, so that
 * rounding in x_N never drops an obstacle the network still sees (x_N >= x_N_min decides). */
static const double reach_margin = 1e-9;

/* An obstacle counts as outside the trained range only beyond this relative margin: a
 * cleat of exactly the longest trained length comes out of the decomposition a few ulp longer
 * (an area over a height), and is not an extrapolation. It is clamped all the same. */
static const double range_tol = 1e-9;

/* Baseline resampling points at most, beyond which --spacing is surely a typo (2^28 points
 * take 8 GB of workspace while building). */
static const double max_samples = 268435456.0;

/* What a position needs of an obstacle. x_0 and reach depend on the contact length: they
 * are computed when the obstacle is first met at the current one (gen), so that a change of
 * contact length costs O(1), not O(obstacles) (tirenv_nn_road_set_contact_length). */
typedef struct {
    double c;              /* centre (centroid of q - b), m */
    double reach;          /* |x - c| beyond which its curve is 0 (with reach_margin), m */
    double x_0;            /* x_N origin of its cleat, obstacle coordinates, m (< 0) */
    double scale;          /* H/H_min for a height below the trained range, else 1 */
    double H;              /* the lift is clipped to [0, H], m */
    double top;            /* the term is capped at the highest ground point, m */
    double H_net, L_net;   /* the network's obstacle inputs, m */
    unsigned long gen;     /* the contact length x_0 and reach are for (tirenv_nn_road.gen) */
} road_obstacle;

/* The workspace of an evaluation, so that it never allocates: per position of the chunk, and
 * the queue of network evaluations. */
typedef struct {
    double b[ROAD_CHUNK], db[ROAD_CHUNK];  /* baseline and its slope, m, 1 */
    double h[ROAD_CHUNK];                  /* maximum so far, m */
    double x_N[ROAD_CHUNK];                /* the winner's x_N */
    size_t best[ROAD_CHUNK];               /* winning obstacle, or ROAD_NONE */
    int flat[ROAD_CHUNK];                  /* winner clipped at H (1) or capped (2) */
    size_t first[ROAD_CHUNK];              /* the first pass's obstacle */
    size_t lo[ROAD_CHUNK], hi[ROAD_CHUNK]; /* window of obstacles */
    size_t n;                              /* queued evaluations */
    double in[ROAD_PENDING * TIRENV_NN_INPUTS], y[ROAD_PENDING];
    size_t pos[ROAD_PENDING], k[ROAD_PENDING];
} road_work;

struct tirenv_nn_road {
    tirenv_nn *nn;         /* own copy: its workspace is written by every evaluation */
    double R0;             /* free radius, m */
    double l_c;            /* contact length, m */
    unsigned long gen;     /* counts the contact lengths set */
    double x_N_min;        /* first x_N the network was trained on */
    int prune;
    /* Baseline: bs[j] at the samples xs[j] (increasing), linear in between (slope ms[j] on
     * [xs[j], xs[j+1]]), flat beyond. The samples are the resampling points g0 + i*ds, the
     * profile's vertices and their anchors (merge_samples); cell[i] is the sample at (or
     * within round-off of) resampling point i, so that a position finds its segment in O(1)
     * plus the few other samples of one spacing. */
    size_t n_s;
    double *xs, *bs, *ms;  /* m, m, 1 */
    size_t n_grid;
    double g0, inv_ds;     /* m, 1/m */
    size_t *cell;
    /* Obstacles, sorted by c. */
    size_t n_ob;
    road_obstacle *ob;
    tirenv_nn_obstacle *pub;
    size_t k_H_max;        /* the obstacle of the highest network height H_net */
    double L_net_max;      /* the longest network length, m */
    double reach_max;      /* a bound on every ob[k].reach at the contact length, m */
    size_t hint;           /* first obstacle of the last window */
    tirenv_nn_road_info info;
    road_work work;
};

/* b(x) and db/dx: linear between samples, the end values beyond them (where the profile is
 * flat at its end heights, and so is its opening). */
static inline double baseline_at(const tirenv_nn_road *r, double x, double *db)
{
    const double *xs = r->xs;
    const size_t last = r->n_s - 1;
    if (!(x > xs[0])) {
        *db = 0;
        return r->bs[0];
    }
    if (!(x < xs[last])) {
        *db = 0;
        return r->bs[last];
    }
    const double u = (x - r->g0) * r->inv_ds;  /* > 0: xs[0] is resampling point 0 */
    size_t j = r->cell[u < (double)(r->n_grid - 1) ? (size_t)u : r->n_grid - 1];
    while (j > 0 && xs[j] > x)
        --j;
    while (xs[j + 1] <= x)  /* stops before last, since x < xs[last] */
        ++j;
    *db = r->ms[j];
    return r->bs[j] + r->ms[j] * (x - xs[j]);
}

/* x_0 and reach of obstacle k at the current contact length (see road_obstacle), with the
 * public record's reach. */
static inline void obstacle_refresh(tirenv_nn_road *r, size_t k)
{
    road_obstacle *o = &r->ob[k];
    tirenv_nn_obstacle *P = &r->pub[k];
    const double x_0 = tirenv_xN_origin(r->R0, r->l_c, o->L_net, o->H_net);
    P->reach = -x_0 * (1 - r->x_N_min);
    o->x_0 = x_0;
    o->reach = P->reach * (1 + reach_margin);
    o->gen = r->gen;
}

static inline const road_obstacle *obstacle_at(tirenv_nn_road *r, size_t k)
{
    if (r->ob[k].gen != r->gen)
        obstacle_refresh(r, k);
    return &r->ob[k];
}

#endif
