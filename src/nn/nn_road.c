/* The empirical model over any profile: equivalent-cleat decomposition with max-plus
 * superposition (docs/models.md section 12; nn_road.h states the model, this file says how
 * and why, and builds it; nn_road_eval.c evaluates it).
 * SPDX-License-Identifier: Apache-2.0
 *
 * Why this shape. The network knows one thing: the curve of a rectangular cleat (L, H) on flat
 * ground at contact length l_c. A road is not a cleat, so it is split into what the network
 * can be asked about. The opening b of the profile with a flat element wider than every
 * trained cleat is the largest "smooth from below" ground under q: it removes exactly the
 * features narrower than W (morphology's granulometry), which are the cleat-like ones, and
 * keeps longer undulations, which the tire follows. What sticks out above b comes in runs;
 * each is replaced by the rectangle of equal height and area, so a true rectangular cleat is
 * reproduced exactly, and a bump of another shape by the cleat that stores the same volume of
 * ground under the tire. Contributions are combined by their maximum (max-plus), as the cam
 * model of docs/models.md section 7 combines ground points: the tire is carried by whatever
 * holds it highest, and a maximum is exactly the single-cleat curve wherever one obstacle dominates.
 *
 * Two departures from "b_k + g_k", with reasons:
 * - The lift g_k is added to the baseline under the tire, b(x), rather than to the obstacle's
 *   own base level b_k. With b_k, every obstacle on sloping ground switches on with a step of
 *   b_k - b(x) at the edge of its reach: on the 1 km class C road of tirenv bench, b_k (the
 *   mean baseline under the run) is above b(x) at 1769 of the 3198 reach edges, by 2.9 mm on
 *   average and up to 14 mm, kicks a ride simulation would feel. With b(x) each term is
 *   continuous, and on level ground (where the network was trained) both are the same.
 * - The term is capped at the obstacle's highest ground point: a lift relative to b(x) on a
 *   slope could otherwise exceed it, and a tire cannot be carried above the ground.
 * The baseline term itself is b(x), not a rigid-disc envelope of b: b is long-wavelength by
 * construction (no feature narrower than W survives above it), the disc would cost a search
 * per position, and the network carries the tire's geometry in g_k already.
 *
 * The baseline is the opening of samples of q: a uniform resampling, the vertices, and the
 * centres of elements ending on a vertex (merge_samples says why), interpolated linearly. So
 * it is continuous wherever q is, exact on plateaus and monotone stretches, and otherwise
 * within about a spacing's rise of the opening of the polyline itself.
 *
 * Speed. Obstacles are sorted by centre and each has a reach (where its curve is non-zero);
 * a position looks only at the window of centres within the largest reach. Positions go in
 * chunks; for each, the obstacle of highest bound min(top_k, b(x) + H_k) is evaluated first,
 * then only the others whose bound can still beat the maximum. The bound is exact (a term
 * never exceeds it) and ties go to the lowest obstacle index whatever the order, so pruning
 * changes no bit of h or of the slope. Network evaluations are queued and run in batches. */
#include "tirenv/nn_road.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "nn/nn_road_impl.h"
#include "nn/opening.h"
#include "tirenv/xn.h"

tirenv_nn_road_settings tirenv_nn_road_default(void)
{
    return (tirenv_nn_road_settings){
        .width_factor = 1.5, .width = 0, .spacing = 0.005, .eps = 1e-6, .prune = 1};
}

void tirenv_nn_road_free(tirenv_nn_road *r)
{
    if (!r)
        return;
    tirenv_nn_free(r->nn);
    free(r->xs);
    free(r->bs);
    free(r->ms);
    free(r->cell);
    free(r->ob);
    free(r->pub);
    free(r);
}

double tirenv_nn_road_baseline(const tirenv_nn_road *r, double x)
{
    double db;
    return baseline_at(r, x, &db);
}

/* Every obstacle brought to the current contact length, and the reach of the info. The
 * getters call it: they report, and need not be fast. */
static void refresh_all(tirenv_nn_road *r)
{
    r->info.reach = 0;
    for (size_t k = 0; k < r->n_ob; ++k) {
        const tirenv_nn_obstacle *P = &r->pub[k];
        obstacle_at(r, k);
        r->info.reach = fmax(r->info.reach, P->reach + fmax(P->c - P->x_lo, P->x_hi - P->c));
    }
}

/* The getters are const to their callers; the obstacles' values at the contact length are a
 * cache of the object's, which lives in writable memory (tirenv_nn_road_alloc's). */
const tirenv_nn_obstacle *tirenv_nn_road_obstacles(const tirenv_nn_road *r)
{
    refresh_all((tirenv_nn_road *)r);
    return r->pub;
}

tirenv_nn_road_info tirenv_nn_road_info_of(const tirenv_nn_road *r)
{
    refresh_all((tirenv_nn_road *)r);
    return r->info;
}

/* Whether obstacle P lies outside the trained range by more than range_tol, each way (the
 * counts of tirenv_nn_road_info). */
static void count_outside(tirenv_nn_road_info *in, const tirenv_nn_obstacle *P)
{
    in->height_below += P->H < in->H_min * (1 - range_tol);
    in->height_above += P->H > in->H_max * (1 + range_tol);
    in->length_below += P->L < in->L_min * (1 - range_tol);
    in->length_above += P->L > in->L_max * (1 + range_tol);
}

tirenv_nn_road_info tirenv_nn_road_info_after(const tirenv_nn_road *r, double x)
{
    tirenv_nn_road_info in = tirenv_nn_road_info_of(r);
    in.obstacles = in.height_below = in.height_above = in.length_below = in.length_above = 0;
    for (size_t k = 0; k < r->n_ob; ++k)
        if (r->pub[k].c > x) {
            in.obstacles++;
            count_outside(&in, &r->pub[k]);
        }
    return in;
}

/* ---- building --------------------------------------------------------------------------- */

/* A point of the merged polyline (profile vertices and resampling points): ground q,
 * baseline b, residual r = q - b, all m. */
typedef struct {
    double x, q, b, r;
} road_point;

/* The run being integrated: moments of r about its start x_s, so that the centroid of a run
 * 900 m down the road keeps the digits of a run at 0. */
typedef struct {
    int open;
    double x_s;            /* start, m */
    double area;           /* integral of r dx, m^2 */
    double moment;         /* integral of (x - x_s) r dx, m^3 */
    double base;           /* integral of b dx, m^2 */
    double H, top;         /* largest r and q, m */
} road_run;

/* Growing arrays of obstacles while the profile is swept. */
typedef struct {
    size_t n, cap;
    tirenv_nn_obstacle *pub;
} road_found;

static double max3(double a, double b, double c)
{
    const double m = a > b ? a : b;
    return m > c ? m : c;
}

/* Exact integrals of the linear pieces of r and b between A and B (A.x <= B.x). */
static void run_add(road_run *run, const road_point *A, const road_point *B)
{
    const double dx = B->x - A->x, u = A->x - run->x_s, v = B->x - run->x_s;
    run->area += 0.5 * dx * (A->r + B->r);
    run->moment += dx / 6.0 * (u * (2 * A->r + B->r) + v * (A->r + 2 * B->r));
    run->base += 0.5 * dx * (A->b + B->b);
    run->H = max3(run->H, A->r, B->r);
    run->top = max3(run->top, A->q, B->q);
}

/* Where r crosses eps between P and Q (P.r and Q.r on either side of it). At a wall
 * (P.x == Q.x) the crossing is the wall itself. */
static road_point crossing(const road_point *P, const road_point *Q, double eps)
{
    const double t = (eps - P->r) / (Q->r - P->r);
    return (road_point){.x = P->x + t * (Q->x - P->x), .q = P->q + t * (Q->q - P->q),
                        .b = P->b + t * (Q->b - P->b), .r = eps};
}

static int run_close(road_run *run, double x_e, road_found *f)
{
    run->open = 0;
    if (!(run->area > 0) || !(run->H > 0) || !isfinite(run->area))
        return TIRENV_OK;  /* a run of no width (cannot happen on a valid profile) */
    if (f->n == f->cap) {
        const size_t cap = f->cap ? 2 * f->cap : 256;
        tirenv_nn_obstacle *p = realloc(f->pub, cap * sizeof *p);
        if (!p)
            return TIRENV_ENOMEM;
        f->pub = p;
        f->cap = cap;
    }
    const double width = x_e - run->x_s;
    f->pub[f->n++] = (tirenv_nn_obstacle){
        .x_lo = run->x_s, .x_hi = x_e, .c = run->x_s + run->moment / run->area,
        .H = run->H, .L = run->area / run->H,
        .base = width > 0 ? run->base / width : 0, .top = run->top};
    return TIRENV_OK;
}

/* One segment P -> Q of the merged polyline: the part with r > eps belongs to a run. */
static int sweep_segment(road_run *run, const road_point *P, const road_point *Q, double eps,
                         road_found *f)
{
    const int in_p = P->r > eps, in_q = Q->r > eps;
    if (in_p && in_q) {
        run_add(run, P, Q);
    } else if (in_p) {
        const road_point X = crossing(P, Q, eps);
        run_add(run, P, &X);
        return run_close(run, X.x, f);
    } else if (in_q) {
        const road_point X = crossing(P, Q, eps);
        *run = (road_run){.open = 1, .x_s = X.x, .H = X.r, .top = X.q};
        run_add(run, &X, Q);
    }
    return TIRENV_OK;
}

/* What the build needs besides what it keeps (the erosion goes where the segment slopes will
 * be): the ground at the samples, the higher vertex at a wall, m; the opening's deque. */
typedef struct {
    double *q;
    size_t *deque;
} road_build;

/* The samples of the baseline, in increasing order: the resampling points
 * x_first + (i - m)*ds, i = 0..n_grid-1 (from the first vertex, so that a road sampled at a
 * multiple of ds has its vertices on them), the profile's vertices, and the anchors x_v - a
 * and x_v + a of every vertex: where an element of the opening that ends on the vertex is
 * centred. Without the anchors a plateau whose wall falls between resampling points would
 * lose the last spacing before the wall to the baseline, and leave a sliver obstacle as high
 * as the plateau. A wall's two vertices are one sample with the higher height (the opening
 * of the ground's upper envelope: the wall's top belongs to the ground). Points within tol
 * of a vertex give way to it, and of each other to the first. Between vertices the ground is
 * tirenv_profile_height's interpolation, found by walking rather than bisecting. */
static void merge_samples(tirenv_nn_road *r, const tirenv_profile *p, double x_first, double m,
                          double i_lo, double ds, double a, double tol, road_build *w)
{
    const size_t n_v = tirenv_profile_size(p), n_g = r->n_grid;
    const double *xv = tirenv_profile_x(p), *zv = tirenv_profile_z(p);
    size_t i = 0, j = 0, left = 0, right = 0, n = 0;  /* next grid point, vertex, anchors */
    for (;;) {
        const double x_g = i < n_g ? x_first + ((double)i + i_lo - m) * ds : INFINITY;
        const double x_v = j < n_v ? xv[j] : INFINITY;
        const double x_l = left < n_v ? xv[left] - a : INFINITY;
        const double x_r = right < n_v ? xv[right] + a : INFINITY;
        const double x_other = fmin(x_g, fmin(x_l, x_r));
        if (x_v == INFINITY && x_other == INFINITY)
            break;
        double x;
        if (x_v <= x_other + tol) {
            const int wall = j + 1 < n_v && xv[j + 1] == xv[j];
            x = x_v;
            w->q[n] = wall && zv[j + 1] > zv[j] ? zv[j + 1] : zv[j];
            j += wall ? 2 : 1;
        } else {
            x = x_other;
            w->q[n] = j == 0     ? zv[0]
                      : j == n_v ? zv[n_v - 1]
                                 : zv[j - 1] + (zv[j] - zv[j - 1]) *
                                                   ((x - xv[j - 1]) / (xv[j] - xv[j - 1]));
        }
        r->xs[n] = x;
        for (; i < n_g && x_first + ((double)i + i_lo - m) * ds <= x + tol; ++i)
            r->cell[i] = n;
        while (left < n_v && xv[left] - a <= x + tol)
            ++left;
        while (right < n_v && xv[right] + a <= x + tol)
            ++right;
        ++n;
    }
    r->n_s = n;
}

/* The runs of r > eps on the polyline through the samples, walls drawn with both their
 * vertices: r is linear between consecutive points, so the integrals are exact. The first
 * sample is far enough before the profile to lie on the baseline. A sample is vertex v's if
 * it has its abscissa (a resampling point there gave way to it). */
static int sweep(const tirenv_nn_road *r, const tirenv_profile *p, const road_build *w,
                 double eps, road_found *f)
{
    const size_t n_v = tirenv_profile_size(p);
    const double *xv = tirenv_profile_x(p), *zv = tirenv_profile_z(p);
    road_run run = {0};
    road_point prev = {0};
    int status = TIRENV_OK;
    size_t v = 0;
    for (size_t j = 0; j < r->n_s && !status; ++j) {
        road_point P[2];
        size_t n_p = 1;
        if (v < n_v && r->xs[j] == xv[v]) {
            P[0] = (road_point){.x = xv[v], .q = zv[v], .b = r->bs[j]};
            if (v + 1 < n_v && xv[v + 1] == xv[v]) {
                ++v;
                P[n_p++] = (road_point){.x = xv[v], .q = zv[v], .b = r->bs[j]};
            }
            ++v;
        } else {
            P[0] = (road_point){.x = r->xs[j], .q = w->q[j], .b = r->bs[j]};
        }
        for (size_t k = 0; k < n_p && !status; ++k) {
            P[k].r = P[k].q - P[k].b;
            if (j > 0 || k > 0)
                status = sweep_segment(&run, &prev, &P[k], eps, f);
            else if (P[k].r > eps)  /* a window cut inside a run (never the whole road's) */
                run = (road_run){.open = 1, .x_s = P[k].x, .H = P[k].r, .top = P[k].q};
            prev = P[k];
        }
    }
    if (!status && run.open)
        status = run_close(&run, prev.x, f);
    return status;
}

/* The baseline: samples from before the profile's first vertex to after its last, by a
 * margin of m >= 2a/ds + 1 spacings on each side, where the profile is flat: there the
 * truncated windows of the opening see only the end height, as the infinite flat extension
 * would. Then the opening, the segment slopes, and the obstacles. A window of a longer road
 * (win not NULL) takes the road's resampling points over its own extent: their index counts
 * from the road's first vertex, so that each has the abscissa it has over the whole road. */
static int build(tirenv_nn_road *r, const tirenv_profile *p, const tirenv_nn_road_window *win,
                 double a, double ds, double eps, road_found *f, tirenv_diag *diag)
{
    double x_first, x_last;
    tirenv_profile_extent(p, &x_first, &x_last);
    const double x_anchor = win ? win->x_first : x_first;  /* the grid's anchor */
    const double m = ceil(2 * a / ds) + 2;
    const double i_lo = win ? floor((x_first - x_anchor) / ds) : 0;
    const double steps = ceil((x_last - x_anchor) / ds) - i_lo;
    if (!(x_first >= x_anchor))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "window",
                            "a window starting at x = %g m, before the road's first vertex at "
                            "%g m", x_first, x_anchor);
    if (!(steps + 2 * m + 1 <= max_samples))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "spacing",
                            "a profile %g m long at a spacing of %g m needs %.15g baseline "
                            "points; expected at most %.0f (raise the spacing)",
                            x_last - x_first, ds, steps + 2 * m + 1, max_samples);
    const size_t n_g = (size_t)(steps + 2 * m) + 1, n_max = n_g + 3 * tirenv_profile_size(p);
    const double tol = 1e-9 * ds;  /* round-off in the resampling points' abscissae */
    r->n_grid = n_g;
    r->g0 = win ? x_anchor + (i_lo - m) * ds : x_first - m * ds;
    r->inv_ds = 1 / ds;
    road_build w = {.q = malloc(n_max * sizeof(double)),
                    .deque = malloc(n_max * sizeof(size_t))};
    r->xs = malloc(n_max * sizeof *r->xs);
    r->bs = malloc(n_max * sizeof *r->bs);
    r->ms = malloc(n_max * sizeof *r->ms);
    r->cell = malloc(n_g * sizeof *r->cell);
    int status = TIRENV_OK;
    if (!w.q || !w.deque || !r->xs || !r->bs || !r->ms || !r->cell) {
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "",
                              "out of memory for %zu baseline points", n_max);
    } else {
        merge_samples(r, p, x_anchor, m, i_lo, ds, a, tol, &w);
        tirenv_nn__opening(r->n_s, r->xs, w.q, a + tol, r->bs, r->ms, w.deque);
        for (size_t j = 0; j + 1 < r->n_s; ++j)
            r->ms[j] = (r->bs[j + 1] - r->bs[j]) / (r->xs[j + 1] - r->xs[j]);
        r->ms[r->n_s - 1] = 0;
        if ((status = sweep(r, p, &w, eps, f)))
            tirenv_error(diag, status, "", 0, "", "out of memory for %zu obstacles", f->n);
    }
    free(w.q);
    free(w.deque);
    return status;
}

/* A window's exact part: what lies within these of a cut end (one that is not the road's)
 * may differ from the whole road's (the proof is at tirenv_nn_road_window_margin). */
static double exact_margin(double a, double ds)
{
    return 3 * (a + ds);  /* a sample's anchors (a), then the erosion and the dilation (2a) */
}
static double run_bound(double a, double ds)
{
    return 2 * (a + ds);  /* every window of the opening holds a sample on the baseline */
}

/* Keeps the obstacles of a window whose whole run, and the sample before and after it, lie
 * in its exact part: those are the whole road's, bit for bit (a run's integrals start at its
 * first crossing); the others are cut by the window's end, and a neighbouring window has
 * them whole. A run longer than run_bound cannot be (tirenv_nn_road_window_margin); it is
 * refused rather than trusted. */
static int window_keep(const tirenv_profile *p, const tirenv_nn_road_window *win, double a,
                       double ds, road_found *f, tirenv_diag *diag)
{
    double x_first, x_last;
    tirenv_profile_extent(p, &x_first, &x_last);
    const double lo = win->bof ? -INFINITY : x_first + exact_margin(a, ds);
    const double hi = win->eof ? INFINITY : x_last - exact_margin(a, ds);
    size_t n = 0;
    for (size_t k = 0; k < f->n; ++k) {
        const tirenv_nn_obstacle *P = &f->pub[k];
        if (!(P->x_lo - ds >= lo && P->x_hi + ds <= hi))
            continue;
        if (!(P->x_hi - P->x_lo <= run_bound(a, ds)))
            return tirenv_error(diag, TIRENV_ERANGE, "", 0, "obstacle",
                                "the obstacle from x = %.9g to %.9g m is %g m long; a window "
                                "of the road holds runs of at most %g m (the opening's width "
                                "plus two spacings), which no decomposition should exceed",
                                P->x_lo, P->x_hi, P->x_hi - P->x_lo, run_bound(a, ds));
        f->pub[n++] = *P;
    }
    f->n = n;
    return TIRENV_OK;
}

/* Network inputs of each obstacle, clamped to the trained range (and counted): what does not
 * depend on the contact length. */
static void prepare_obstacles(tirenv_nn_road *r, const double lo[], const double hi[])
{
    const double H_min = lo[TIRENV_NN_HEIGHT], H_max = hi[TIRENV_NN_HEIGHT];
    const double L_min = lo[TIRENV_NN_LENGTH], L_max = hi[TIRENV_NN_LENGTH];
    r->k_H_max = 0;
    r->L_net_max = 0;
    for (size_t k = 0; k < r->n_ob; ++k) {
        tirenv_nn_obstacle *P = &r->pub[k];
        const double scale = P->H < H_min ? P->H / H_min : 1;
        const double H_net = P->H < H_min ? H_min : P->H > H_max ? H_max : P->H;
        const double L_net = P->L < L_min ? L_min : P->L > L_max ? L_max : P->L;
        count_outside(&r->info, P);
        P->H_net = H_net;
        P->L_net = L_net;
        r->ob[k] = (road_obstacle){.c = P->c, .scale = scale, .H = P->H, .top = P->top,
                                   .H_net = H_net, .L_net = L_net, .gen = 0};
        if (H_net > r->ob[r->k_H_max].H_net)
            r->k_H_max = k;
        r->L_net_max = fmax(r->L_net_max, L_net);
    }
}

/* The contact length's part, O(1): the check that no obstacle's cleat reaches the chord height
 * (the highest is enough), and the window of obstacles a position looks at. Each obstacle's
 * reach is -x_0*(1 - x_N_min) with -x_0 = L/2 + sqrt(R0^2 - (z_c - H)^2) (tirenv_xN_origin),
 * which grows with L and with H below z_c, so the longest and the highest bound them all; the
 * window is only where obstacles are looked for, each is then held to its own reach, so that
 * the bound changes no result. */
int tirenv_nn_road_set_contact_length(tirenv_nn_road *r, double l_c, tirenv_diag *diag)
{
    const double R0 = r->R0;
    if (!(l_c > 0) || !(l_c < 2 * R0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact length",
                            "expected 0 < l_c < 2*R0 = %g m, got %g", 2 * R0, l_c);
    const double z_c = sqrt(R0 * R0 - 0.25 * l_c * l_c);  /* chord height */
    if (r->n_ob > 0) {
        const tirenv_nn_obstacle *P = &r->pub[r->k_H_max];
        if (!(P->H_net < z_c))
            return tirenv_error(diag, TIRENV_ERANGE, "", 0, "obstacle_height_m",
                                "the obstacle at x = %g m is %g m high (network input %g m): "
                                "it reaches the centre height %g m of a tire of radius %g m at "
                                "contact length %g m", P->c, P->H, P->H_net, z_c, R0, l_c);
        const double H = P->H_net;
        r->reach_max = (0.5 * r->L_net_max + sqrt(R0 * R0 - (z_c - H) * (z_c - H))) *
                       (1 - r->x_N_min) * (1 + 2 * reach_margin);
    } else {
        r->reach_max = 0;
    }
    r->l_c = l_c;
    r->gen++;
    return TIRENV_OK;
}

static int check_settings(const tirenv_nn_road_settings *s, tirenv_diag *diag)
{
    if (!(s->spacing > 0) || !isfinite(s->spacing))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "spacing",
                            "spacing %g m; expected a positive number", s->spacing);
    if (!(s->eps >= 0) || !isfinite(s->eps))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "eps",
                            "eps %g m; expected a number >= 0", s->eps);
    if (!(s->width >= 0) || !isfinite(s->width))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "width",
                            "width %g m; expected 0 (from width_factor) or a positive number",
                            s->width);
    if (s->width == 0 && (!(s->width_factor > 1) || !isfinite(s->width_factor)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "width_factor",
                            "width_factor %g; expected a number above 1 (the opening must be "
                            "wider than every trained cleat)", s->width_factor);
    if (s->prune != 0 && s->prune != 1)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "prune", "prune %d; expected 0 or 1",
                            s->prune);
    return TIRENV_OK;
}

/* The opening's width W of the settings for network nn (NaN if it has none). */
static double opening_width(const tirenv_nn *nn, const tirenv_nn_road_settings *s)
{
    double lo[TIRENV_NN_INPUTS], hi[TIRENV_NN_INPUTS];
    tirenv_nn_input_range(nn, lo, hi);
    const double W = s->width > 0 ? s->width : s->width_factor * hi[TIRENV_NN_LENGTH];
    return isfinite(W) && W > 0 ? W : NAN;
}

static int alloc_road(const tirenv_nn *nn, double R0, double l_c, const tirenv_profile *p,
                      const tirenv_nn_road_settings *settings,
                      const tirenv_nn_road_window *win, tirenv_nn_road **out,
                      tirenv_diag *diag)
{
    if (!out)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "no place for the result (NULL)");
    *out = NULL;
    if (!nn || !p)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, nn ? "profile" : "network",
                            "the %s is NULL", nn ? "profile" : "network");
    const tirenv_nn_road_settings s = settings ? *settings : tirenv_nn_road_default();
    int status = check_settings(&s, diag);
    if (status)
        return status;
    if (tirenv_nn_n_inputs(nn) != TIRENV_NN_INPUTS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "topology",
                            "the enveloping model needs %d inputs (x_N, l_c, H, L); this "
                            "network has %zu", TIRENV_NN_INPUTS, tirenv_nn_n_inputs(nn));
    if (!(R0 > 0) || !isfinite(R0) || !(l_c > 0) || !(l_c < 2 * R0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "",
                            "expected R0 > 0 and 0 < l_c < 2*R0 (m); got R0 %g, l_c %g", R0,
                            l_c);
    double lo[TIRENV_NN_INPUTS], hi[TIRENV_NN_INPUTS];
    tirenv_nn_input_range(nn, lo, hi);
    const double x_N_min = lo[TIRENV_NN_X_N];
    if (!isfinite(x_N_min) || !(x_N_min < 1))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x_N",
                            "the network's trained range of x_N starts at %g; expected a "
                            "finite value below 1 (where its curve begins)", x_N_min);
    const double W = opening_width(nn, &s);
    if (!(W > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "width",
                            "the network records no trained range of obstacle length (its "
                            "longest is %g m); set the opening width", hi[TIRENV_NN_LENGTH]);

    tirenv_nn_road *r = calloc(1, sizeof *r);
    if (!r || !(r->nn = tirenv_nn_clone(nn))) {
        free(r);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    r->R0 = R0;
    r->x_N_min = x_N_min;
    r->prune = s.prune;
    r->info = (tirenv_nn_road_info){
        .H_min = lo[TIRENV_NN_HEIGHT], .H_max = hi[TIRENV_NN_HEIGHT],
        .L_min = lo[TIRENV_NN_LENGTH], .L_max = hi[TIRENV_NN_LENGTH],
        .width = W, .spacing = s.spacing};
    road_found f = {0};
    status = build(r, p, win, 0.5 * W, s.spacing, s.eps, &f, diag);
    if (!status && win)
        status = window_keep(p, win, 0.5 * W, s.spacing, &f, diag);
    r->pub = f.pub;
    r->n_ob = f.n;
    r->info.obstacles = f.n;
    if (!status && !(r->ob = malloc((f.n ? f.n : 1) * sizeof *r->ob)))
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for %zu "
                              "obstacles", f.n);
    if (!status) {
        prepare_obstacles(r, lo, hi);
        status = tirenv_nn_road_set_contact_length(r, l_c, diag);
    }
    if (status) {
        tirenv_nn_road_free(r);
        return status;
    }
    *out = r;
    return TIRENV_OK;
}

int tirenv_nn_road_alloc(const tirenv_nn *nn, double R0, double l_c, const tirenv_profile *p,
                         const tirenv_nn_road_settings *settings, tirenv_nn_road **out,
                         tirenv_diag *diag)
{
    return alloc_road(nn, R0, l_c, p, settings, NULL, out, diag);
}

int tirenv_nn_road_alloc_window(const tirenv_nn *nn, double R0, double l_c,
                                const tirenv_profile *p, const tirenv_nn_road_settings *s,
                                const tirenv_nn_road_window *win, tirenv_nn_road **out,
                                tirenv_diag *diag)
{
    if (!win || !isfinite(win->x_first)) {
        if (out)
            *out = NULL;
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "window",
                            "expected a window with the road's first vertex (finite)");
    }
    return alloc_road(nn, R0, l_c, p, s, win, out, diag);
}

/* Why a window's results are the whole road's farther than D from a cut end (a = W/2, ds the
 * spacing, samples and obstacles as in build):
 * - A resampling point has the road's abscissa (its index counts from the road's first
 *   vertex). A sample's value depends on the vertices within a of it (its anchors) and the two
 *   around it: exact beyond a + ds of a cut end. The opening at a sample takes the samples
 *   within 2a: exact beyond 3(a + ds) (exact_margin). The opening is a minimum and a maximum,
 *   so exact means the same bits.
 * - A run of q - b > eps is no longer than 2(a + ds) (run_bound): the samples within a of any
 *   sample i hold one with b = q (the lowest of them: the erosion at i is its height, the
 *   dilation there is at least that, and b <= q), and a run wider than 2a + ds would hold such
 *   a window around its middle sample, whereas inside a run q - b > eps >= 0.
 * - An obstacle acts on x only within its own reach, -x_0*(1 - x_N_min) with
 *   -x_0 = L/2 + sqrt(R0^2 - (z_c - H)^2) <= L/2 + R0 (tirenv_xN_origin), and its network
 *   length L is at most run_bound, or the trained range's clamp.
 * So a position farther than exact_margin + run_bound + that reach + ds from a cut end sees
 * the whole road's baseline and every obstacle that acts on it whole (window_keep keeps
 * them), and no other: h and slope are the whole road's, bit for bit. 1 % and 2 ds on top
 * cover rounding in the reach. */
double tirenv_nn_road_window_margin(const tirenv_nn *nn, double R0,
                                    const tirenv_nn_road_settings *settings)
{
    const tirenv_nn_road_settings s = settings ? *settings : tirenv_nn_road_default();
    if (!nn || check_settings(&s, NULL) || tirenv_nn_n_inputs(nn) != TIRENV_NN_INPUTS ||
        !(R0 > 0) || !isfinite(R0))
        return NAN;
    double lo[TIRENV_NN_INPUTS], hi[TIRENV_NN_INPUTS];
    tirenv_nn_input_range(nn, lo, hi);
    const double W = opening_width(nn, &s), a = 0.5 * W, ds = s.spacing;
    const double x_N_min = lo[TIRENV_NN_X_N];
    if (!(W > 0) || !isfinite(x_N_min) || !(x_N_min < 1))
        return NAN;
    const double L_min = isfinite(lo[TIRENV_NN_LENGTH]) ? lo[TIRENV_NN_LENGTH] : 0;
    const double L_net = fmax(L_min, fmin(run_bound(a, ds), hi[TIRENV_NN_LENGTH]));
    const double reach = 1.01 * (0.5 * L_net + R0) * (1 - x_N_min);
    return exact_margin(a, ds) + run_bound(a, ds) + reach + 3 * ds;
}
