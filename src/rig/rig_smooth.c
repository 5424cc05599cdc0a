/* Stage 3 of the rig-log import: both halves of the passage folded onto the approach half,
 * filtered without shifting the curve, and evaluated on the x_N grid.
 *
 * Folding: the curve over a symmetric obstacle is symmetric (docs/models.md section 1), so the
 * departure half, mirrored about the centre, samples the same curve as the approach half.
 * Using both halves doubles the samples behind each point and halves the noise variance. It
 * also forgives the centre: an error dc in it shifts the two halves by +dc and -dc along x,
 * and their average errs only by about h'' dc^2 / 2.
 *
 * Filter: local quadratic regression (Savitzky-Golay on uneven x, LOESS of degree 2) with
 * Epanechnikov weights 1 - v^2, v = (x - u)/w, over the window [u - w, u + w]. The window and
 * weights are symmetric about u, so the filter has zero phase: it does not move a rise or a
 * peak along x, whatever the direction of travel (a causal filter would lag by about w).
 * Its bias, for half-width w (the equivalent kernel is K*(v) = 15/32 (3 - 10v^2 + 7v^4)):
 *   - a parabola is fitted exactly, so a peak's curvature h'' costs nothing, where a moving
 *     average of the same weights would lower the peak by h'' w^2 / 10;
 *   - on a smooth curve the first error term is -h'''' w^4 / 504: for the peak of a cleat
 *     curve (h of 0.1 m bending over some 0.1 m, h'''' ~ 1e3 m^-3) at w = 10 mm, 2e-8 m;
 *   - at a kink, where the slope jumps by ds (first contact, a corner of the cleat reached),
 *     0.078 ds w: 0.16 mm for ds = 0.2 at w = 10 mm. In general |bias| <= 0.36 w times the
 *     spread of h' within the window.
 * Its noise: the standard error of h is sigma sqrt(1.25 / (rho w)) for rho samples per metre
 * of the folded data (1.25 = integral of K*^2), so halving it takes four times the width.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdlib.h>

#include "rig/rig_impl.h"

/* The automatic half-width aims at this standard error of h from noise: a twentieth of the
 * 1 mm that the paper's Figure 5 resolves, small against the differences between models. A
 * smaller target widens the window and with it the bias at kinks (see above). */
static const double TARGET_SE = 0.05e-3; /* m */
/* The integral of K*^2 (see above): var(h) = sigma^2 KERNEL_VARIANCE / (rho w). */
static const double KERNEL_VARIANCE = 1.25;
/* The automatic half-width never exceeds this fraction of |x_0| (the distance from first
 * contact to the centre, 0.55 m for case F): 27 mm there, where a kink's bias stays under
 * 0.5 mm even for a slope jump of 0.2. A noisier log is refused rather than blurred. */
static const double MAX_WIDTH_FRACTION = 0.05;
/* A window needs this many samples: a parabola and five degrees of freedom to spare. */
enum { MIN_FIT_SAMPLES = 8 };
/* The fit's weighted normal matrix in window units, divided by its weight sum cubed, must
 * keep this determinant: samples spread evenly over the window give 0.009, samples bunched
 * at one point (a window inside a gap of the log) give 0. */
static const double MIN_DESIGN = 1e-4;
/* Grids longer than this are surely a typo in the step. */
static const double MAX_GRID = 1e6;

/* Weighted moments of one window, in window units v = (x - u)/w. */
typedef struct {
    double S[5];           /* sum of k v^j, j = 0..4 */
    double T[3];           /* sum of k h v^j, j = 0..2 */
    size_t count;
} rig_window;

static void window_add(rig_window *m, double v, double h)
{
    const double k = 1 - v * v;
    if (!(k > 0))
        return; /* on or beyond the window's edge: weight 0 */
    double p = k;
    for (size_t j = 0; j < 5; j++, p *= v) {
        m->S[j] += p;
        if (j < 3)
            m->T[j] += p * h;
    }
    m->count++;
}

/* The intercept of the weighted parabola (Cramer's rule on the 3x3 normal equations, well
 * conditioned in window units). Returns 0 if the window cannot fix a parabola. */
static int window_solve(const rig_window *m, double *h)
{
    const double *S = m->S, *T = m->T;
    const double c0 = S[2] * S[4] - S[3] * S[3];
    const double c1 = S[1] * S[4] - S[2] * S[3];
    const double c2 = S[1] * S[3] - S[2] * S[2];
    const double det = S[0] * c0 - S[1] * c1 + S[2] * c2;
    if (m->count < MIN_FIT_SAMPLES || !(det > MIN_DESIGN * S[0] * S[0] * S[0]))
        return 0;
    const double num = T[0] * c0 - S[1] * (T[1] * S[4] - S[3] * T[2])
                       + S[2] * (T[1] * S[3] - S[2] * T[2]);
    *h = num / det;
    return 1;
}

/* First index with u[i] >= key (u ascending). */
static size_t lower_bound(const double u[], size_t n, double key)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (u[mid] < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* The filter at u0 <= 0. Near the centre the window reaches past u = 0, where the curve
 * continues as its own mirror image: the folded samples enter a second time, reflected, so
 * the window stays symmetric up to the centre itself. */
static int smooth_at(const double u[], const double h[], size_t n, double u0, double w,
                     double *value, size_t *count)
{
    rig_window m = {{0}, {0}, 0};
    for (size_t i = lower_bound(u, n, u0 - w); i < n && u[i] <= u0 + w; i++)
        window_add(&m, (u[i] - u0) / w, h[i]);
    if (u0 + w > 0)
        for (size_t i = lower_bound(u, n, -(u0 + w)); i < n && u[i] < 0; i++)
            window_add(&m, (-u[i] - u0) / w, h[i]);
    *count = m.count;
    return window_solve(&m, value);
}

/* u = -|x - centre| in ascending order, h = z - baseline. Samples before the centre come in
 * with u ascending, those after it with u descending: one merge of the two runs. */
static void fold(const tirenv_rig__samples *s, const tirenv_rig__passage *p, double u[],
                 double h[])
{
    const double c = p->centre;
    size_t a = lower_bound(s->x, s->n, c); /* first sample at or after the centre */
    size_t i = 0, j = s->n, k = 0;
    while (i < a || j > a) {
        const int left = j == a || (i < a && s->x[i] - c <= c - s->x[j - 1]);
        const size_t from = left ? i++ : --j;
        u[k] = -fabs(s->x[from] - c);
        h[k++] = s->z[from] - p->baseline;
    }
}

/* By multiplication, so that no error accumulates. */
size_t tirenv_import_grid_points(const tirenv_import_settings *set)
{
    const double limit = set->xN_to + set->dxN * 1e-9;
    const double steps = floor((limit - set->xN_from) / set->dxN);
    /* A step of 0 or less, or an end before the start, is no grid: counted as one, the
     * loops below never ended (a negative step) or started from (size_t) of a negative. */
    if (!(set->dxN > 0) || !(steps >= 0 && steps < MAX_GRID))
        return 0;
    size_t n = (size_t)steps + 1;
    while (n > 1 && set->xN_from + (double)(n - 1) * set->dxN > limit)
        n--;
    while (set->xN_from + (double)n * set->dxN <= limit)
        n++;
    return n;
}

/* The half-width: the user's, or the narrowest that brings the noise down to TARGET_SE,
 * within [MIN_FIT_SAMPLES samples a half-width, MAX_WIDTH_FRACTION * |x_0|]. A log too noisy
 * or too sparse for that is smoothed at the cap, which keeps the shape, and says so (*capped):
 * a 6 mm-sampled log of case R, refused before, is imported at the cap within 0.36 mm of the
 * same run sampled every mm. Only where even the cap's window holds fewer than
 * MIN_FIT_SAMPLES samples on average (a parabola with five degrees of freedom to spare, as
 * smooth_at needs) can the shape not be kept: refused. */
static int half_width(double sigma, double rho, double x_0, double smooth, double *w,
                      int *capped, tirenv_diag *diag)
{
    *capped = 0;
    if (smooth > 0) {
        *w = smooth;
        return TIRENV_OK;
    }
    const double w_noise = KERNEL_VARIANCE * sigma * sigma / (rho * TARGET_SE * TARGET_SE);
    const double w_fit = MIN_FIT_SAMPLES / rho;
    const double w_max = MAX_WIDTH_FRACTION * -x_0;
    if (2 * w_max * rho < MIN_FIT_SAMPLES)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x",
                            "log too sparse: %.0f samples per metre (both halves together) put "
                            "%.1f samples on average in the widest smoothing window that keeps "
                            "the curve's shape (half-width %.3g m, %.0f %% of |x_0|); fitting a "
                            "parabola needs %d; sample faster, or set the half-width "
                            "(--smooth)", rho, 2 * w_max * rho, w_max,
                            100 * MAX_WIDTH_FRACTION, MIN_FIT_SAMPLES);
    *capped = fmax(w_noise, w_fit) > w_max;
    *w = fmin(fmax(w_noise, w_fit), w_max);
    return TIRENV_OK;
}

/* The grid's far end must lie a full window inside the folded data. */
static int check_reach(const double u[], double u_far, double w, tirenv_diag *diag)
{
    if (u[0] <= u_far - w)
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x",
                        "the log does not reach far enough from the obstacle for the x_N "
                        "grid: its end at %.4g m from the centre needs samples out to %.4g m "
                        "(with the smoothing window), the log reaches %.4g m; log a longer run "
                        "or start the grid later", -u_far, w - u_far, -u[0]);
}

static int smooth_grid(const double u[], const double h[], size_t n, double w, double x_0,
                       const tirenv_import_settings *set, tirenv_curve *out, tirenv_diag *diag)
{
    const size_t n_grid = tirenv_import_grid_points(set);
    if (n_grid == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dxN",
                            "the x_N grid from %g to %g in steps of %g has more than %.0f "
                            "points", set->xN_from, set->xN_to, set->dxN, MAX_GRID);
    /* x is linear in x_N, so the grid's farthest point from the centre is an end point. */
    const double x_first = x_0 * (1 - set->xN_from);
    const double x_last = x_0 * (1 - (set->xN_from + (double)(n_grid - 1) * set->dxN));
    const double u_far = -fmax(fabs(x_first), fabs(x_last));
    int status = check_reach(u, u_far, w, diag);
    if (status == TIRENV_OK && tirenv_curve_alloc(out, n_grid) != TIRENV_OK)
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    for (size_t k = 0; k < n_grid && status == TIRENV_OK; k++) {
        const double x_N = set->xN_from + (double)k * set->dxN;
        const double x = x_0 * (1 - x_N) + 0.0; /* + 0.0: the centre is 0, not -0 */
        size_t count;
        out->x_N[k] = x_N;
        out->x[k] = x;
        if (!smooth_at(u, h, n, -fabs(x), w, &out->h[k], &count))
            status = tirenv_error(diag, TIRENV_EINVAL, "", 0, "x",
                                  "too few samples near x_N = %.4g (x = %.4g m): %zu within "
                                  "the smoothing half-width %.3g m, at least %d spread over "
                                  "it needed; the log has a gap there or is too sparse (a "
                                  "larger --smooth helps)", x_N, x, count, w, MIN_FIT_SAMPLES);
    }
    if (status != TIRENV_OK)
        tirenv_curve_free(out);
    return status;
}

int tirenv_rig__smooth(const tirenv_rig__samples *s, const tirenv_rig__passage *p,
                       const tirenv_import_settings *set, double x_0, tirenv_curve *out,
                       tirenv_import_info *info, tirenv_diag *diag)
{
    double *w = &info->half_width, *noise_se = &info->noise_se;
    info->target_se = TARGET_SE;
    *out = (tirenv_curve){0};
    double *u = malloc(2 * s->n * sizeof *u);
    if (!u)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    double *h = u + s->n;
    fold(s, p, u, h);
    /* Density over the approach half [x_0, 0], where the curve's shape is. */
    const double rho = (double)(s->n - lower_bound(u, s->n, x_0)) / -x_0;
    int status = half_width(p->sigma, rho, x_0, set->smooth, w, &info->width_capped, diag);
    if (status == TIRENV_OK) {
        *noise_se = p->sigma * sqrt(KERNEL_VARIANCE / (rho * *w));
        status = smooth_grid(u, h, s->n, *w, x_0, set, out, diag);
    }
    free(u);
    return status;
}
