/* Stage 2 of the rig-log import: where the passage is in the log. The noise, the flat
 * baseline, the bump, and the obstacle's centre as the bump's axis of symmetry; a log that
 * does not hold a whole passage (flat ground, bump, flat ground) is refused with the reason.
 * The obstacle is a cleat on flat ground, so the bump rises above the flat level.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdlib.h>
#include <string.h>


#include "rig/rig_impl.h"

/* The noise estimate never goes below 1 um, far below any rig sensor's resolution, so that
 * the noise-relative thresholds below keep a meaning on noise-free (simulated) logs. */
static const double SIGMA_FLOOR = 1e-6; /* m */
/* Median absolute deviation to standard deviation for Gaussian noise: 1/Phi^-1(3/4). */
static const double MAD_TO_SIGMA = 1.482602218505602;
/* Standard error of a median over that of a mean, Gaussian noise: sqrt(pi/2). */
static const double MEDIAN_SE_FACTOR = 1.2533141373155003;
/* The first guess at the flat level looks at this fraction of the run at each end. */
static const double END_FRACTION = 0.1;
/* Detection bins: about this many over the distance from first contact to the centre
 * (|x_0|), so that the centre is found to a small fraction of a millimetre... */
static const double BINS_PER_HALF = 400.0;
/* ...but with at least this many samples per bin on average, so a bin mean is a mean. */
static const double MIN_BIN_SAMPLES = 4.0;
/* A bump is real if its highest bin mean stands this many standard errors above the flat
 * level: the highest of a few thousand bins of pure Gaussian noise is about 3.5. */
static const double BUMP_K = 8.0;
/* The bump ends where bin means fall below the larger of SUPPORT_K standard deviations of a
 * bin mean and SUPPORT_FRACTION of the peak... */
static const double SUPPORT_K = 5.0;
static const double SUPPORT_FRACTION = 0.01;
/* ...and flat ground starts a further FLAT_MARGIN of the bump's width out: room for the low
 * tail of the first rise, which those thresholds do not see. */
static const double FLAT_MARGIN = 0.1;
/* Flat ground needs this many samples on each side to give a level and a noise figure. */
enum { MIN_FLAT_SAMPLES = 10 };
/* The flat ground before and after must be level to LEVEL_K standard errors of the two
 * medians, plus RAIL_LEVEL for rails that are straight but not perfectly so. */
static const double LEVEL_K = 5.0;
static const double RAIL_LEVEL = 0.2e-3; /* m */
/* A hump of the passage is a run of bins at or above half the peak at least this many bins
 * long and a quarter as long as the peak's own run: shorter runs are noise on a flank. */
enum { MIN_HUMP_BINS = 3 };
/* Centre refinement: within +-CENTRE_SEARCH bins of the half-peak midpoint, in steps of a
 * CENTRE_STEPS-th of a bin, then a parabola through the best step and its neighbours. */
enum { CENTRE_SEARCH = 4, CENTRE_STEPS = 8 };

/* A bin of the detection grid: samples with x in [x_lo + k*delta, x_lo + (k+1)*delta). */
typedef struct {
    double x;              /* mean x of its samples, m: unbiased where h is sloped */
    double g;              /* mean h of its samples, m */
    size_t count;
    size_t first;          /* first sample of the bin (index into tirenv_rig__samples) */
} rig_bin;

/* The median of v[0..n-1], n >= 1, reordering v: Hoare's selection (Find, CACM 4(7), 1961)
 * places the element of rank n/2 with everything before it no larger, in O(n) expected; for
 * even n the other middle one is the largest of that lower part. The mean of the two middle
 * values for even n, the value itself for odd n: the same as sorting and reading the middle. */
static double median_in_place(double v[], const size_t n)
{
    const size_t k = n / 2;
    size_t lo = 0, hi = n - 1;
    while (lo < hi) {
        const double pivot = v[lo + (hi - lo) / 2];
        size_t i = lo, j = hi;
        while (i <= j) {
            while (v[i] < pivot)
                ++i;
            while (v[j] > pivot)
                --j;
            if (i <= j) {
                const double t = v[i];
                v[i] = v[j];
                v[j] = t;
                ++i;
                if (j == 0)
                    break;
                --j;
            }
        }
        if (k <= j)
            hi = j;
        else if (k >= i)
            lo = i;
        else
            break;  /* v[k] lies between the parts, equal to the pivot */
    }
    if (n % 2)
        return v[k];
    double below = v[0];
    for (size_t i = 1; i < k; ++i)
        below = fmax(below, v[i]);
    return 0.5 * (below + v[k]);
}

double tirenv_rig__median(const double v[], size_t n, double scratch[])
{
    memcpy(scratch, v, n * sizeof *v);
    return median_in_place(scratch, n);
}

/* Gasser, Sroka and Jennen-Steinmetz (1986) pseudo-residuals: each z against the straight
 * line through its two neighbours, scaled to the noise's variance. Unlike first differences
 * they cancel the bump's slope (which would count as noise), and they allow uneven spacing;
 * the median of their absolute values ignores the few that straddle a kink of the curve. */
static double noise_sigma(const tirenv_rig__samples *s, double scratch[])
{
    size_t m = 0;
    for (size_t i = 1; i + 1 < s->n; i++) {
        const double span = s->x[i + 1] - s->x[i - 1];
        const double a = span > 0 ? (s->x[i + 1] - s->x[i]) / span : 0.5;
        const double b = 1.0 - a;
        const double e = (a * s->z[i - 1] + b * s->z[i + 1] - s->z[i]) / sqrt(1 + a * a + b * b);
        scratch[m++] = fabs(e);
    }
    const double sigma = MAD_TO_SIGMA * median_in_place(scratch, m);
    return sigma > SIGMA_FLOOR ? sigma : SIGMA_FLOOR;
}

/* A first guess at the flat level from the ends of the run. The bump only ever raises z, so
 * the lower end is the better guess when a log ends (or starts) on the bump; that case is
 * refused later, with its reason, once the bump has been found. */
static double first_level(const tirenv_rig__samples *s, double scratch[])
{
    const size_t n = s->n;
    const double reach = END_FRACTION * (s->x[n - 1] - s->x[0]);
    size_t a = 0, b = 0;
    while (a < n && s->x[a] <= s->x[0] + reach)
        a++;
    while (b < n && s->x[n - 1 - b] >= s->x[n - 1] - reach)
        b++;
    a = a > MIN_FLAT_SAMPLES ? a : MIN_FLAT_SAMPLES;
    b = b > MIN_FLAT_SAMPLES ? b : MIN_FLAT_SAMPLES;
    const double z_start = tirenv_rig__median(s->z, a, scratch);
    const double z_end = tirenv_rig__median(s->z + n - b, b, scratch);
    return z_start < z_end ? z_start : z_end;
}

/* How many bins there can be: delta >= MIN_BIN_SAMPLES * span / (n - 1) leaves at most
 * (n - 1) / MIN_BIN_SAMPLES + 1 of them, and one more for round-off. */
static size_t bins_capacity(size_t n)
{
    return (size_t)((double)(n - 1) / MIN_BIN_SAMPLES) + 2;
}

/* Bin means of h = z - level; empty bins are left out. Returns the number of bins. */
static size_t bins_build(const tirenv_rig__samples *s, double level, double delta,
                         rig_bin b[])
{
    const size_t cap = bins_capacity(s->n);
    size_t m = 0;
    long current = -1;
    for (size_t i = 0; i < s->n; i++) {
        const long k = (long)floor((s->x[i] - s->x[0]) / delta);
        if (k != current && m < cap) {
            b[m++] = (rig_bin){0, 0, 0, i};
            current = k;
        }
        rig_bin *bin = &b[m - 1];
        bin->x += s->x[i];
        bin->g += s->z[i] - level;
        bin->count++;
    }
    for (size_t k = 0; k < m; k++) {
        b[k].x /= (double)b[k].count;
        b[k].g /= (double)b[k].count;
    }
    return m;
}

static size_t bins_peak(const rig_bin b[], size_t m)
{
    size_t peak = 0;
    for (size_t k = 1; k < m; k++)
        if (b[k].g > b[peak].g)
            peak = k;
    return peak;
}

/* Scanning from bin peak (at or above level) in direction dir (-1 or +1), where the bin
 * means first fall below level: the position interpolated between the last bin above and the first below, and that
 * first bin in *stop. NaN if the run ends first. */
static double crossing(const rig_bin b[], size_t m, size_t peak, int dir, double level,
                       size_t *stop)
{
    size_t k = peak;
    while (b[k].g >= level) {
        if ((dir < 0 && k == 0) || (dir > 0 && k + 1 == m))
            return NAN;
        k = dir < 0 ? k - 1 : k + 1;
    }
    *stop = k;
    const rig_bin *below = &b[k], *above = dir < 0 ? &b[k + 1] : &b[k - 1];
    return below->x + (level - below->g) * (above->x - below->x) / (above->g - below->g);
}

/* The refusals when the run ends (dir > 0) or starts (dir < 0) on the bump. */
static int cut_off(const tirenv_rig__samples *s, const rig_bin b[], size_t m, int dir,
                   tirenv_diag *diag)
{
    const size_t i = dir > 0 ? s->n - 1 : 0;
    const double h = (dir > 0 ? b[m - 1].g : b[0].g) * 1e3;
    if (dir > 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", s->index[i] + 1, "z",
                            "log ends before the tire leaves the obstacle: h is still %.3g mm "
                            "above the flat ground at the end; a passage needs flat ground "
                            "after the bump", h);
    return tirenv_error(diag, TIRENV_EINVAL, "", s->index[i] + 1, "z",
                        "log starts after the tire has reached the obstacle: h is already "
                        "%.3g mm above the flat ground at the start; a passage needs flat "
                        "ground before the bump", h);
}

/* The bump: its highest bin, checked against the noise. */
static int bump_find(const tirenv_rig__samples *s, const rig_bin b[], size_t m, double sigma,
                     size_t *peak, tirenv_diag *diag)
{
    *peak = bins_peak(b, m);
    const double se = sigma / sqrt((double)b[*peak].count);
    if (b[*peak].g > BUMP_K * se)
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_EINVAL, "", s->index[b[*peak].first] + 1, "z",
                        "no bump above the noise: the highest stretch is %.3g mm above the "
                        "flat level, %.1f times the %.3g mm noise of its mean (%g needed); "
                        "is this a log over flat ground?",
                        b[*peak].g * 1e3, b[*peak].g / se, se * 1e3, BUMP_K);
}

/* Counts the flat samples before x_lo and after x_hi; refuses if either side is short. */
static int flat_sides(const tirenv_rig__samples *s, double x_lo, double x_hi, size_t *n_left,
                      size_t *right, tirenv_diag *diag)
{
    size_t a = 0, c = s->n;
    while (a < s->n && s->x[a] < x_lo)
        a++;
    while (c > 0 && s->x[c - 1] > x_hi)
        c--;
    if (a < MIN_FLAT_SAMPLES)
        return tirenv_error(diag, TIRENV_EINVAL, "", s->index[0] + 1, "x",
                            "log starts too close to the obstacle: %zu samples of flat ground "
                            "before x = %.4g m, where the bump's approach begins; at least %d "
                            "needed", a, x_lo, MIN_FLAT_SAMPLES);
    if (s->n - c < MIN_FLAT_SAMPLES)
        return tirenv_error(diag, TIRENV_EINVAL, "", s->index[s->n - 1] + 1, "x",
                            "log ends too soon after the obstacle: %zu samples of flat ground "
                            "after x = %.4g m, where the bump's departure ends; at least %d "
                            "needed", s->n - c, x_hi, MIN_FLAT_SAMPLES);
    *n_left = a;
    *right = c;
    return TIRENV_OK;
}

/* The flat baseline: the median z of the flat ground on both sides of the bump, which must
 * be level. */
static int flat_baseline(const tirenv_rig__samples *s, double x_lo, double x_hi, double sigma,
                         double scratch[], double *baseline, tirenv_diag *diag)
{
    size_t a = 0, c = s->n;
    const int status = flat_sides(s, x_lo, x_hi, &a, &c, diag);
    if (status != TIRENV_OK)
        return status;
    const size_t nr = s->n - c;
    const double z_left = tirenv_rig__median(s->z, a, scratch);
    const double z_right = tirenv_rig__median(s->z + c, nr, scratch);
    const double allowed = LEVEL_K * MEDIAN_SE_FACTOR * sigma
                               * sqrt(1.0 / (double)a + 1.0 / (double)nr) + RAIL_LEVEL;
    if (fabs(z_right - z_left) > allowed)
        return tirenv_error(diag, TIRENV_EINVAL, "", s->index[s->n - 1] + 1, "z",
                            "the flat ground after the obstacle is %.3g mm %s than before it "
                            "(noise and rails allow %.3g mm): the log does not hold one "
                            "passage over level ground", fabs(z_right - z_left) * 1e3,
                            z_right > z_left ? "higher" : "lower", allowed * 1e3);
    memcpy(scratch, s->z, a * sizeof *scratch);
    memcpy(scratch + a, s->z + c, nr * sizeof *scratch);
    *baseline = median_in_place(scratch, a + nr);
    return TIRENV_OK;
}

/* How far the bins k_lo..k_hi are from their mirror image about c: the sum of squared
 * differences to the mirror image, read off by linear interpolation between bin means (held
 * at the end values beyond the run), less what the noise alone is expected to add. That
 * expectation, var g_k + (1-a)^2 var g_j + a^2 var g_j+1 for the mirror point a of the way
 * from bin j to j+1, dips wherever the mirror falls midway between bins and would otherwise
 * pull c there. (Maximising the correlation of h(x) with h(2c - x) is the same away from
 * noise, but over interpolated bins it is piecewise linear in c, its maximum stuck at a
 * half-bin step.) The range reaches into the flat ground on both sides, so its ends favour no
 * c. The mirror positions 2c - x fall as x rises, so one pointer walks down. */
static double asymmetry(const rig_bin b[], size_t m, size_t k_lo, size_t k_hi, double c,
                        double sigma)
{
    const double var = sigma * sigma;
    double sum = 0;
    size_t j = m - 1;
    for (size_t k = k_lo; k <= k_hi; k++) {
        const double y = 2 * c - b[k].x;
        while (j > 0 && b[j].x > y)
            j--;
        double g, noise;
        if (y <= b[0].x || j + 1 >= m) {
            const rig_bin *end = y <= b[0].x ? &b[0] : &b[m - 1];
            g = end->g;
            noise = var / (double)end->count;
        } else {
            const double a = (y - b[j].x) / (b[j + 1].x - b[j].x);
            g = (1 - a) * b[j].g + a * b[j + 1].g;
            noise = var * ((1 - a) * (1 - a) / (double)b[j].count
                           + a * a / (double)b[j + 1].count);
        }
        const double d = b[k].g - g;
        sum += d * d - noise - var / (double)b[k].count;
    }
    return sum;
}

/* The axis of symmetry near c0: a scan of the asymmetry, then the vertex of the parabola
 * through the best step and its neighbours (the asymmetry is smooth in c near its minimum). */
static double centre_refine(const rig_bin b[], size_t m, size_t k_lo, size_t k_hi, double c0,
                            double delta, double sigma)
{
    enum { STEPS = 2 * CENTRE_SEARCH * CENTRE_STEPS + 1 };
    const double step = delta / CENTRE_STEPS;
    double f[STEPS];
    size_t best = 0;
    for (size_t j = 0; j < STEPS; j++) {
        f[j] = asymmetry(b, m, k_lo, k_hi,
                         c0 + ((double)j - CENTRE_SEARCH * CENTRE_STEPS) * step, sigma);
        if (f[j] < f[best])
            best = j;
    }
    double c = c0 + ((double)best - CENTRE_SEARCH * CENTRE_STEPS) * step;
    if (best > 0 && best + 1 < STEPS) {
        const double curv = f[best - 1] - 2 * f[best] + f[best + 1];
        if (curv > 0)
            c += 0.5 * step * (f[best - 1] - f[best + 1]) / curv;
    }
    return c;
}

/* The bins with mean x in [x_lo, x_hi]: *k_lo..*k_hi. */
static void bins_between(const rig_bin b[], size_t m, double x_lo, double x_hi, size_t *k_lo,
                         size_t *k_hi)
{
    size_t lo = 0, hi = m - 1;
    while (lo + 1 < m && b[lo].x < x_lo)
        lo++;
    while (hi > lo && b[hi].x > x_hi)
        hi--;
    *k_lo = lo;
    *k_hi = hi;
}

/* Where the bump is: from its outermost humps outwards. */
typedef struct {
    double c0;             /* midpoint of the outermost half-peak crossings, m: a first
                              centre */
    double x_a, x_b;       /* where it rises from and falls back to the flat level, m */
} rig_bump;

/* The whole passage's humps: the first and last bin of the outermost runs of bins at or
 * above half (runs of MIN_HUMP_BINS bins and a quarter of the peak's run at least). A cleat
 * shorter than the contact patch makes two humps, one as the patch's front reaches it and one
 * as its rear leaves it, and the highest point is on either; a flat top is one run. */
static void outer_humps(const rig_bin b[], size_t m, size_t peak, double half, size_t *first,
                        size_t *last)
{
    size_t a = peak, z = peak;
    while (a > 0 && b[a - 1].g >= half)
        a--;
    while (z + 1 < m && b[z + 1].g >= half)
        z++;
    const size_t quarter = (z - a + 1) / 4;
    const size_t need = quarter > MIN_HUMP_BINS ? quarter : MIN_HUMP_BINS;
    *first = a;
    *last = z;
    for (size_t k = 0; k < m;) {
        if (b[k].g < half) {
            k++;
            continue;
        }
        size_t e = k;
        while (e + 1 < m && b[e + 1].g >= half)
            e++;
        if (e - k + 1 >= need) {
            *first = k < *first ? k : *first;
            *last = e > *last ? e : *last;
        }
        k = e + 1;
    }
}

/* The bump's half-peak crossings and its extent, over the whole passage; refuses a run that
 * starts or ends on it. */
static int bump_extent(const tirenv_rig__samples *s, const rig_bin b[], size_t m, double sigma,
                       rig_bump *bump, tirenv_diag *diag)
{
    size_t peak, stop, first, last;
    const int status = bump_find(s, b, m, sigma, &peak, diag);
    if (status != TIRENV_OK)
        return status;
    const double half = 0.5 * b[peak].g;
    outer_humps(b, m, peak, half, &first, &last);
    const double x_L = crossing(b, m, first, -1, half, &stop);
    const double x_R = crossing(b, m, last, +1, half, &stop);
    if (isnan(x_L) || isnan(x_R))
        return cut_off(s, b, m, isnan(x_R) ? +1 : -1, diag);
    /* Never above the half-peak level, which the scans have just found on both sides. */
    const double se_bin = sigma / sqrt(MIN_BIN_SAMPLES);
    const double thr = fmin(half, fmax(SUPPORT_K * se_bin, SUPPORT_FRACTION * b[peak].g));
    bump->x_a = crossing(b, m, first, -1, thr, &stop);
    bump->x_b = crossing(b, m, last, +1, thr, &stop);
    if (isnan(bump->x_a) || isnan(bump->x_b))
        return cut_off(s, b, m, isnan(bump->x_b) ? +1 : -1, diag);
    bump->c0 = 0.5 * (x_L + x_R);
    return TIRENV_OK;
}

/* The stages of finding the passage, on bins of a width set by the obstacle's scale and the
 * sampling. */
static int passage_on_bins(const tirenv_rig__samples *s, double x_0, rig_bin b[],
                           double scratch[], tirenv_rig__passage *p, tirenv_diag *diag)
{
    const double span = s->x[s->n - 1] - s->x[0];
    const double delta = fmax(-x_0 / BINS_PER_HALF, MIN_BIN_SAMPLES * span / (double)(s->n - 1));
    const double level = first_level(s, scratch);
    const size_t m = bins_build(s, level, delta, b);
    rig_bump bump = {NAN, NAN, NAN};
    int status = bump_extent(s, b, m, p->sigma, &bump, diag);
    const double margin = FLAT_MARGIN * (bump.x_b - bump.x_a);
    if (status == TIRENV_OK)
        status = flat_baseline(s, bump.x_a - margin, bump.x_b + margin, p->sigma, scratch,
                               &p->baseline, diag);
    if (status != TIRENV_OK)
        return status;
    for (size_t k = 0; k < m; k++)
        b[k].g += level - p->baseline;
    size_t k_lo, k_hi;
    bins_between(b, m, bump.x_a - margin, bump.x_b + margin, &k_lo, &k_hi);
    p->centre = centre_refine(b, m, k_lo, k_hi, bump.c0, delta, p->sigma);
    p->x_a = bump.x_a;
    p->x_b = bump.x_b;
    p->delta = delta;
    return TIRENV_OK;
}

int tirenv_rig__find_passage(const tirenv_rig__samples *s, double x_0,
                             tirenv_rig__passage *p, tirenv_diag *diag)
{
    double *scratch = malloc(s->n * sizeof *scratch);
    rig_bin *b = malloc(bins_capacity(s->n) * sizeof *b);
    int status;
    if (!scratch || !b) {
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    } else {
        p->sigma = noise_sigma(s, scratch);
        status = passage_on_bins(s, x_0, b, scratch, p, diag);
    }
    free(scratch);
    free(b);
    return status;
}
