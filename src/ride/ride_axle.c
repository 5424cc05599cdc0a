/* What an axle's tires follow and the force they make (docs/models.md sections 9.2, 9.3 and
 * 9.5): a track at the static load, or an input that depends on the load, taken at the load
 * the tires then carry. SPDX-License-Identifier: Apache-2.0
 *
 * The load a tire carries depends on the input, and the input on the load: per tire
 *     G = max(0, g(G)),   g(G) = the tire's load (ride_tire.c) at the deflection
 *     w(x, G) - z_a from the static one and its rate V*dw/dx(x, G) - dz_a/dt.
 * On a table, w is linear in G between two rows. With the vehicle's linear spring k_t,
 * g(G) = G0 + k_t*(w - z_a) + c_t*(...) is then linear too, and the balancing load on a
 * segment of rows is where the line g(G) - G crosses zero: exact, two rows per segment. With
 * the tire file's vertical law g curves on the segment (convex for Q_FZ2 > 0, so one zero
 * between a positive and a negative end), and regula falsi, whose first estimate is that
 * line's zero, finds it to 1e-9 of G0. The search starts from the segment of the last
 * evaluation and walks towards the sign change, so it usually reads two rows. With
 * phi(G) = g(G) - G decreasing (the tire's effective height changing with its load by less
 * than 1/k per N, k the spring's stiffness there: on the default tractor it is about 0.1 of
 * that at the static load) the balance is unique and the start changes no result; otherwise
 * the walk ends at the balance nearest its start. Below the lightest row the input is the
 * lightest row's; a tire whose g there is not positive has lifted off (G = 0) and touches
 * down where that row lets it. Above the heaviest row the heaviest row's. The damper acts on
 * the rolling rate V*dw/dx at the load found; the rate at which the load itself moves the
 * effective road is left out (it would make the tire force depend on its own rate of
 * change). */
#include "ride/ride_impl.h"

#include <math.h>
#include <stdlib.h>

/* Steffen's monotone slopes (M. Steffen, A simple method for monotonic interpolation in one
 * dimension, Astron. Astrophys. 239, 1990, his eq. 11 with the one-sided slopes at the ends, the
 * "simplest possibility" of his section 2.2), on a uniform grid of spacing h: at an inner point
 * the smallest of the two secants and half their mean, signed alike, 0 at an extremum. Tracks
 * and tables both use it (a track is a table of one row), so that a table's rows share one
 * index per position and give value and slope together. Until version 0.1 a track went
 * through GSL's gsl_interp_steffen, the same interpolant; its grid spacing x_(k+1) - x_k and
 * slope mean differ from these by round-off, and so did the rides on tracks. */
static void steffen_slopes(size_t n, double h, const double w[], double yp[])
{
    yp[0] = (w[1] - w[0]) / h;
    yp[n - 1] = (w[n - 1] - w[n - 2]) / h;
    for (size_t k = 1; k + 1 < n; ++k) {
        const double s_l = (w[k] - w[k - 1]) / h, s_r = (w[k + 1] - w[k]) / h;
        const double mean = 0.5 * (s_l + s_r);
        const double mag = fmin(fmin(fabs(s_l), fabs(s_r)), 0.5 * fabs(mean));
        yp[k] = (s_l > 0) == (s_r > 0) && s_l != 0 && s_r != 0 ? copysign(2 * mag, s_l) : 0;
    }
}

int tirenv_ride__input_init(tirenv_ride__input *in, const char *name,
                            const tirenv_ride_track *track, const tirenv_ride_table *table,
                            const tirenv_ride_input *fn)
{
    *in = (tirenv_ride__input){.name = name, .track = track, .table = table, .fn = fn};
    if (fn) {
        in->kind = TIRENV_RIDE__FUNCTION;
        in->dx = fn->dx;
        return TIRENV_OK;
    }
    in->x0 = track ? track->x0 : table->x0;
    in->dx = track ? track->dx : table->dx;
    in->n = track ? track->n : table->n;
    in->m = track ? 1 : table->m;
    in->w = track ? track->w : table->w;
    in->kind = table ? TIRENV_RIDE__TABLE : TIRENV_RIDE__TRACK;
    if (in->n < 2)
        return TIRENV_EINVAL;
    if (!(in->slope = malloc(in->m * in->n * sizeof *in->slope)))
        return TIRENV_ENOMEM;
    for (size_t j = 0; j < in->m; ++j)
        steffen_slopes(in->n, in->dx, in->w + j * in->n, in->slope + j * in->n);
    return TIRENV_OK;
}

void tirenv_ride__input_free(tirenv_ride__input *in)
{
    free(in->slope);
    in->slope = NULL;
}

double tirenv_ride__input_dx(const tirenv_ride__input *in)
{
    return in->dx;
}

/* Where position x falls on a table's grid: its cell k and the offset t (m) into it; the
 * rows all read there. Beyond the grid (out = 1) the end values continue, flat. */
typedef struct {
    size_t k;
    double t;
    int out;
} grid_spot;

static grid_spot spot_of(const tirenv_ride__input *in, double x)
{
    const double x_end = in->x0 + (double)(in->n - 1) * in->dx;
    if (x <= in->x0)
        return (grid_spot){0, 0, 1};
    if (x >= x_end)
        return (grid_spot){in->n - 1, 0, 1};
    const double u = (x - in->x0) / in->dx;
    size_t k = (size_t)u;
    if (k > in->n - 2)
        k = in->n - 2;
    return (grid_spot){k, x - (in->x0 + (double)k * in->dx), 0};
}

/* Row j's height and dw/dx at a spot: the cubic of Steffen's eqs. 2 to 5 on the cell, from its
 * ends' heights and slopes. */
static void row_at(const tirenv_ride__input *in, size_t j, const grid_spot *p, double *w,
                   double *w_x)
{
    const double *row = in->w + j * in->n, *yp = in->slope + j * in->n;
    if (p->out) {
        *w = row[p->k];
        *w_x = 0;
        return;
    }
    const double h = in->dx, y0 = row[p->k], y1 = row[p->k + 1];
    const double d0 = yp[p->k], d1 = yp[p->k + 1], s = (y1 - y0) / h, t = p->t;
    const double a = (d0 + d1 - 2 * s) / (h * h), b = (3 * s - 2 * d0 - d1) / h;
    *w = y0 + t * (d0 + t * (b + t * a));
    *w_x = d0 + t * (2 * b + 3 * a * t);
}

/* A track's height and dw/dx at position x; beyond the grid the end values, flat. */
static void track_at(const tirenv_ride__input *in, double x, double *w, double *w_x)
{
    const grid_spot p = spot_of(in, x);
    row_at(in, 0, &p, w, w_x);
}

/* What a tire's load would be with the input w, w_x: g of the file's comment. */
typedef struct {
    const tirenv_ride__tire *t;
    double V, z, zd;
} balance;

static double g_of(const balance *b, double w, double w_x)
{
    return tirenv_ride__tire_load(b->t, w - b->z, b->V * w_x - b->zd);
}

/* The input at a load G (N) of one tire: a function's, or a table's on one segment of rows. */
typedef int (*input_at)(const void *ctx, double x, double G, double *w, double *w_x,
                        tirenv_diag *diag);

/* The balance phi(G) = g(G) - G = 0 bracketed by phi(lo) = f_lo > 0 > phi(hi) = f_hi, by the
 * Illinois variant of regula falsi, to 1e-9 of the static load: far below anything a load
 * changes in a ride; or until the bracket is 1e-12 of top (the heaviest load) wide (a balance
 * on a jump of phi, which the bracket closes in on). The models take at most 13 iterations
 * over the demo's cleat on a function (the cam and the springs under the default tire's law,
 * 434 of 1.1 million over 8), 4 on a table's segment. On a jump whose two sides differ by
 * orders of magnitude the Illinois steps can crawl: the springs model over an ISO 8608 class
 * H road left a bracket 9e-6 N wide after the budget, 350 times the width that ends the
 * search, and the ride stopped there. Past the budget the search bisects, which halves the
 * bracket each step, so that the width is reached within BISECT_MAX_ITER (2^-64 of any
 * bracket in [0, top] is below it); a search that converged within the budget is unchanged.
 * [bottom, top] is the input's range of loads, for the message. */
enum { FN_MAX_ITER = 100, BISECT_MAX_ITER = 64 };

static int illinois(const char *name, const balance *b, input_at at, const void *ctx, double x,
                    double lo, double hi, double f_lo, double f_hi, double bottom, double top,
                    double *w, double *w_x, double *G, tirenv_diag *diag)
{
    const double tol = 1e-9 * b->t->G0, width = 1e-12 * top;
    int side = 0, status;
    double c = lo, fc = f_lo, wc, wxc;
    for (int it = 0; it < FN_MAX_ITER + BISECT_MAX_ITER; ++it) {
        c = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        if (!(c > lo && c < hi) || it >= FN_MAX_ITER)
            c = 0.5 * (lo + hi);
        if ((status = at(ctx, x, c, &wc, &wxc, diag)))
            return status;
        fc = g_of(b, wc, wxc) - c;
        if (fabs(fc) <= tol || hi - lo <= width) {
            *w = wc;
            *w_x = wxc;
            *G = c;
            return TIRENV_OK;
        }
        if (fc > 0) {
            lo = c;
            f_lo = fc;
            if (side == 1)
                f_hi *= 0.5;
            side = 1;
        } else {
            hi = c;
            f_hi = fc;
            if (side == -1)
                f_lo *= 0.5;
            side = -1;
        }
    }
    tirenv_error(diag, TIRENV_ENOCONV, "", 0, name,
                 "the load G of one tire that balances its input at x = %.6g m, "
                 "G = max(0, g(G)), not found in %d iterations of regula falsi and %d of "
                 "bisection: G in "
                 "[%.10g, %.10g] N (%.3g N wide; load range [%g, %g] N), g(G) - G = %.3g N at "
                 "G = %.10g N; expected |g(G) - G| <= %.3g N or a bracket <= %.3g N (does "
                 "the input jump with the load?)",
                 x, FN_MAX_ITER, BISECT_MAX_ITER, lo, hi, hi - lo, bottom, top, fc, c, tol,
                 width);
    /* The code itself, not tirenv_error's value: GCC cannot see that one is non-zero, and
     * would take the caller's unset w_x and G as maybe used. */
    return TIRENV_ENOCONV;
}

/* A table's segment of rows j, j + 1 at one spot: w linear in the load between them. */
typedef struct {
    double G_j, G_k, w_j, wx_j, w_k, wx_k;
} segment;

static int segment_at(const void *ctx, double x, double G, double *w, double *w_x,
                      tirenv_diag *diag)
{
    (void)x;
    (void)diag;
    const segment *sg = ctx;
    const double s = (G - sg->G_j) / (sg->G_k - sg->G_j);
    *w = sg->w_j + s * (sg->w_k - sg->w_j);
    *w_x = sg->wx_j + s * (sg->wx_k - sg->wx_j);
    return TIRENV_OK;
}

/* The balance on a table: see the file's comment. */
static int table_axle(tirenv_ride__input *in, const balance *b, double x, double *w,
                      double *w_x, double *G, tirenv_diag *diag)
{
    const tirenv_ride_table *t = in->table;
    const size_t m = t->m;
    const grid_spot p = spot_of(in, x);
    if (m == 1) {
        row_at(in, 0, &p, w, w_x);
        const double g = g_of(b, *w, *w_x);
        *G = g > 0 ? g : 0;
        return TIRENV_OK;
    }
    size_t j = in->hint < m - 1 ? in->hint : m - 2;
    double wj, wxj, wk, wxk;  /* rows j and k = j + 1 */
    row_at(in, j, &p, &wj, &wxj);
    row_at(in, j + 1, &p, &wk, &wxk);
    for (;;) {
        const double phi_j = g_of(b, wj, wxj) - t->load[j];
        const double phi_k = g_of(b, wk, wxk) - t->load[j + 1];
        if (phi_j <= 0 && j == 0) {  /* lighter than the lightest row, or lifted off */
            const double g = phi_j + t->load[0];
            *w = wj;
            *w_x = wxj;
            *G = g > 0 ? g : 0;
            break;
        }
        if (phi_j < 0) {  /* the balance is lighter */
            --j;
            wk = wj;
            wxk = wxj;
            row_at(in, j, &p, &wj, &wxj);
            continue;
        }
        if (phi_k >= 0 && j + 2 == m) {  /* heavier than the heaviest row */
            *w = wk;
            *w_x = wxk;
            *G = phi_k + t->load[j + 1];
            break;
        }
        if (phi_k > 0) {  /* the balance is heavier */
            ++j;
            wj = wk;
            wxj = wxk;
            row_at(in, j + 1, &p, &wk, &wxk);
            continue;
        }
        /* phi_j >= 0 >= phi_k: with the linear spring g - G is a line on the segment, its
         * zero the balance; the law's g curves, and regula falsi follows it from there. */
        in->hint = j;
        if (b->t->has_law && phi_j > 0 && phi_k < 0) {
            const segment sg = {t->load[j], t->load[j + 1], wj, wxj, wk, wxk};
            return illinois(in->name, b, segment_at, &sg, x, t->load[j], t->load[j + 1],
                            phi_j, phi_k, t->load[0], t->load[m - 1], w, w_x, G, diag);
        }
        const double s = phi_j > phi_k ? phi_j / (phi_j - phi_k) : 0;
        *G = t->load[j] + s * (t->load[j + 1] - t->load[j]);
        *w = wj + s * (wk - wj);
        *w_x = wxj + s * (wxk - wxj);
        return TIRENV_OK;
    }
    in->hint = j;
    return TIRENV_OK;
}

static int fn_at(const void *ctx, double x, double G, double *w, double *w_x, tirenv_diag *diag)
{
    const tirenv_ride_input *f = ctx;
    return f->fn(f->ctx, x, G, w, w_x, diag);
}

/* The balance on a function over [load_min, load_max], by illinois. */
static int fn_axle(tirenv_ride__input *in, const balance *b, double x, double *w, double *w_x,
                   double *G, tirenv_diag *diag)
{
    const tirenv_ride_input *f = in->fn;
    double lo = f->load_min, hi = f->load_max, w_lo, wx_lo, w_hi, wx_hi;
    int status = f->fn(f->ctx, x, lo, &w_lo, &wx_lo, diag);
    if (status)
        return status;
    double f_lo = g_of(b, w_lo, wx_lo) - lo;
    if (f_lo <= 0) {
        *w = w_lo;
        *w_x = wx_lo;
        *G = f_lo + lo > 0 ? f_lo + lo : 0;
        return TIRENV_OK;
    }
    if ((status = f->fn(f->ctx, x, hi, &w_hi, &wx_hi, diag)))
        return status;
    double f_hi = g_of(b, w_hi, wx_hi) - hi;
    if (f_hi >= 0) {
        *w = w_hi;
        *w_x = wx_hi;
        *G = f_hi + hi;
        return TIRENV_OK;
    }
    return illinois(in->name, b, fn_at, f, x, lo, hi, f_lo, f_hi, f->load_min,
                    f->load_max, w, w_x, G, diag);
}

int tirenv_ride__axle(tirenv_ride__input *in, const tirenv_ride__tire *t, double V, double x,
                      double z_a, double zd_a, double *w, double *w_dot, double *F,
                      tirenv_diag *diag)
{
    double w_x, G;
    if (in->kind == TIRENV_RIDE__TRACK) {
        track_at(in, x, w, &w_x);
        *w_dot = V * w_x;
        *F = tirenv_ride__tire_force(t, *w - z_a, *w_dot - zd_a);
        return TIRENV_OK;
    }
    const balance b = {.t = t, .V = V, .z = z_a, .zd = zd_a};
    const int status = in->kind == TIRENV_RIDE__TABLE ? table_axle(in, &b, x, w, &w_x, &G, diag)
                                                      : fn_axle(in, &b, x, w, &w_x, &G, diag);
    if (status)
        return status;
    *w_dot = V * w_x;
    *F = t->n * G;
    return TIRENV_OK;
}

/* The table's rows around G0, interpolated as table_axle does. */
int tirenv_ride__input_static(tirenv_ride__input *in, double G0, double x, double *w,
                              tirenv_diag *diag)
{
    double w_x;
    if (in->kind == TIRENV_RIDE__FUNCTION) {
        const double G = fmin(fmax(G0, in->fn->load_min), in->fn->load_max);
        return in->fn->fn(in->fn->ctx, x, G, w, &w_x, diag);
    }
    if (in->kind == TIRENV_RIDE__TRACK) {
        track_at(in, x, w, &w_x);
        return TIRENV_OK;
    }
    const grid_spot p = spot_of(in, x);
    if (in->m == 1) {
        row_at(in, 0, &p, w, &w_x);
        return TIRENV_OK;
    }
    const double *load = in->table->load;
    size_t j = 0;
    while (j + 2 < in->m && load[j + 1] <= G0)
        ++j;
    in->hint = j;
    double wj, wk;
    row_at(in, j, &p, &wj, &w_x);
    row_at(in, j + 1, &p, &wk, &w_x);
    const double s = fmin(fmax((G0 - load[j]) / (load[j + 1] - load[j]), 0.0), 1.0);
    *w = wj + s * (wk - wj);
    return TIRENV_OK;
}
