/* Rig-log import: a known curve recovered from synthetic logs (noise, offsets, direction,
 * rate, repeated and dropped samples) within a tolerance derived from the noise, the samples
 * behind each point and the smoother's bias; and every malformed log refused with file, line
 * and column, leaving no output file. SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/tirenv.h"
#include "tirenv/curve.h"
#include "tirenv/rig.h"
#include "rig/rig_impl.h"

#include "tirenv/rng.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

/* ---- the known curve ------------------------------------------------------------------- */

/* The paper's case F: default tire, contact length 0.38 m, cleat 0.30 x 0.10 m. */
static const double L_F = 0.30, H_F = 0.10, LC_F = 0.38; /* m */
/* The springs model tabulated every 0.25 mm over +-1.2 m: finer than any rig in the tests. */
static const double DX_TRUTH = 0.25e-3, X_TRUTH = 1.2; /* m */
/* The known curve is the table's linear interpolant: the logs are made from it and the
 * import is compared with it, so the table's own spacing costs nothing. */
typedef struct {
    size_t n;
    double *h;             /* h(x_k), x_k = -X_TRUTH + k*DX_TRUTH, m */
    double *slope;         /* h' between nodes k and k+1 */
    double z_flat;         /* flat-ground centre height, m */
    double R0;             /* m */
} truth_table;

static truth_table truth;

static double truth_at(const double v[], size_t n, double x)
{
    const double f = (x + X_TRUTH) / DX_TRUTH;
    if (f <= 0)
        return v[0];
    if (f >= (double)(n - 1))
        return v[n - 1];
    const size_t i = (size_t)f;
    const double a = f - (double)i;
    return v[i] * (1 - a) + v[i + 1] * a;
}

/* The springs model's curve, symmetrised (the import assumes symmetry; the model's warm start
 * can pick a different one of two equilibria at an isolated position), then averaged over one
 * element pitch R0*dphi. The averaging removes the model's discretisation staircase (0.5 deg
 * elements meet the cleat's corners one by one: steps of 1 to 1.5 mm every 6 mm), which is not
 * part of a tire's response; what is left keeps the springs curve's shape: the kink at first
 * contact and the sharp bends where the tire reaches the cleat's corners. */
static int truth_setup(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &tire);
    tirenv_profile *p = tirenv_profile_cleat(L_F, H_F);
    double load;
    tirenv_flat flat;
    tirenv_diag d;
    /* The load at which the free circle's chord is case F's contact length (the springs
     * model's contact length before it became the length its tread touches): any load makes a
     * truth; this one keeps the logs' geometry the tests were written for. */
    const double R0 = tire.springs.R0;
    if (!m || !p || tirenv_model_flat_at_height(m, sqrt(R0 * R0 - 0.25 * LC_F * LC_F), &flat, &d))
        return -1;
    load = flat.load;
    if (tirenv_model_flat(m, load, &flat, &d) || tirenv_model_set(m, p, load, &d))
        return -1;
    const size_t n = (size_t)lround(2 * X_TRUTH / DX_TRUTH) + 1;
    double *raw = malloc(n * sizeof *raw), *cum = malloc(n * sizeof *cum);
    truth.h = malloc(n * sizeof *truth.h);
    truth.slope = malloc(n * sizeof *truth.slope);
    size_t failed = 0;
    for (size_t k = 0; k < n; k++) {
        tirenv_point pt;
        /* A position where the model does not converge (reported) keeps its neighbour's h:
         * the table is the truth whatever it holds, and the logs are made from it. */
        if (tirenv_model_eval(m, -X_TRUTH + (double)k * DX_TRUTH, &pt, &d) == TIRENV_OK) {
            raw[k] = pt.h;
        } else {
            raw[k] = k ? raw[k - 1] : 0.0;
            failed++;
        }
    }
    const double pitch = tire.springs.R0 * tire.springs.dphi;
    cum[0] = 0;
    for (size_t k = 1; k < n; k++)
        cum[k] = cum[k - 1] + 0.25 * DX_TRUTH * (raw[k] + raw[n - 1 - k] + raw[k - 1]
                                                 + raw[n - k]);
    for (size_t k = 0; k < n; k++) {
        const double x = -X_TRUTH + (double)k * DX_TRUTH;
        truth.h[k] = (truth_at(cum, n, x + pitch / 2) - truth_at(cum, n, x - pitch / 2)) / pitch;
    }
    for (size_t k = 0; k + 1 < n; k++)
        truth.slope[k] = (truth.h[k + 1] - truth.h[k]) / DX_TRUTH;
    truth.slope[n - 1] = 0;
    truth.n = n;
    truth.z_flat = flat.z_flat;
    truth.R0 = tire.springs.R0;
    free(raw);
    free(cum);
    tirenv_profile_free(p);
    tirenv_model_free(m);
    return failed * 100 < n ? 0 : -1; /* more than 1 % unconverged: the model is broken */
}

static int truth_teardown(void **state)
{
    (void)state;
    free(truth.h);
    free(truth.slope);
    return 0;
}

/* ---- the synthetic rig ------------------------------------------------------------------- */

/* A cart run at constant speed over the obstacle, sampled as a rig logger would. */
typedef struct {
    const char *name;
    double rate;           /* samples per second */
    double sigma;          /* Gaussian noise on z, m (the cart's x encoder is exact) */
    int reversed;          /* the cart moves towards -x */
    double repeat;         /* fraction of samples logged twice (same t) */
    double drop;           /* fraction of samples lost */
    int shuffle;           /* samples handed over in random order */
    double smooth;         /* settings.smooth, m (0: automatic) */
} rig_case;

static const double SPEED = 0.05;          /* m/s: a quasi-static rig */
static const double RUN = 1.0;             /* m: the run covers -RUN..RUN around the cleat */
static const double X_OFFSET = 3.217;      /* m: where the cleat sits on the rails */
static const double Z_OFFSET = 0.0123;     /* m: the height sensor's zero */
static const double T_START = 17.25;       /* s: the logger's clock at the start */
/* A burst of lost samples on the departure flank (a logger hiccup), m of travel. */
static const double GAP_FROM = 0.30, GAP_TO = 0.31;

typedef struct {
    size_t n;
    double *t, *x, *z;
    unsigned char *repeat; /* 1 for the second copy of a sample */
    size_t repeated;
} rig_log;

static void log_free(rig_log *g)
{
    free(g->t);
    free(g->x);
    free(g->z);
    free(g->repeat);
}

static void log_push(rig_log *g, double t, double x, double z, int repeat)
{
    g->t[g->n] = t;
    g->x[g->n] = x;
    g->z[g->n] = z;
    g->repeat[g->n] = (unsigned char)repeat;
    g->n++;
}

/* The samples in a random order, as a logger that buffers per channel might hand them over. */
static void log_shuffle(rig_log *g, tirenv_rng *r)
{
    size_t *perm = malloc(g->n * sizeof *perm);
    rig_log copy = {g->n, malloc(g->n * sizeof(double)), malloc(g->n * sizeof(double)),
                    malloc(g->n * sizeof(double)), malloc(g->n), g->repeated};
    for (size_t i = 0; i < g->n; i++)
        perm[i] = i;
    tirenv_rng_shuffle(r, perm, g->n);
    for (size_t i = 0; i < g->n; i++) {
        copy.t[i] = g->t[perm[i]];
        copy.x[i] = g->x[perm[i]];
        copy.z[i] = g->z[perm[i]];
        copy.repeat[i] = g->repeat[perm[i]];
    }
    log_free(g);
    *g = copy;
    free(perm);
}

static rig_log log_make(const rig_case *c, unsigned long seed)
{
    tirenv_rng *r = tirenv_rng_alloc(0);
    tirenv_rng_seed(r, seed);
    const size_t steps = (size_t)(2 * RUN / SPEED * c->rate);
    rig_log g = {0, NULL, NULL, NULL, NULL, 0};
    const size_t cap = 2 * (steps + 1);
    g.t = malloc(cap * sizeof *g.t);
    g.x = malloc(cap * sizeof *g.x);
    g.z = malloc(cap * sizeof *g.z);
    g.repeat = malloc(cap);
    for (size_t i = 0; i <= steps; i++) {
        const double t = T_START + (double)i / c->rate;
        const double s = -RUN + SPEED * (double)i / c->rate; /* travelled, obstacle frame */
        const double x = c->reversed ? X_OFFSET - s : X_OFFSET + s;
        const double z = Z_OFFSET + truth.z_flat + truth_at(truth.h, truth.n, s)
                         + (c->sigma > 0 ? tirenv_rng_gaussian(r, c->sigma) : 0.0);
        const int in_gap = c->drop > 0 && s >= GAP_FROM && s < GAP_TO;
        if (in_gap || tirenv_rng_uniform(r) < c->drop)
            continue;
        log_push(&g, t, x, z, 0);
        if (tirenv_rng_uniform(r) < c->repeat) {
            log_push(&g, t, x, z, 1);
            g.repeated++;
        }
    }
    if (c->shuffle)
        log_shuffle(&g, r);
    tirenv_rng_free(r);
    return g;
}

static tirenv_import_settings case_f_settings(double smooth)
{
    tirenv_import_settings s = tirenv_import_default();
    s.L = L_F;
    s.H = H_F;
    s.R0 = truth.R0;
    s.contact_length = LC_F;
    s.smooth = smooth;
    return s;
}

/* ---- the tolerance ---------------------------------------------------------------------- */

/* The smoother (src/rig/rig_smooth.c) is local quadratic regression with Epanechnikov
 * weights; its equivalent kernel is K*(v) = 15/32 (3 - 10v^2 + 7v^4) on [-1, 1]. Noise:
 * var h = sigma^2 * 1.25 / (rho w), 1.25 being the integral of K*^2. Bias: parabolas come
 * out unchanged, so for any parabola q the error is the smoother applied to h - q, plus
 * q - h at the point itself: |bias| <= (1 + integral of |K*|) max |h - q| over the window,
 * and the integral of |K*| is 1.2445. The test takes q as h's least-squares parabola over the
 * window. For a kink of slope jump ds this gives about 0.15 ds w; the true bias there is
 * 0.078 ds w. */
static const double KERNEL_VARIANCE = 1.25, BIAS_PER_MISFIT = 2.2445;
/* Error allowances in standard errors: the largest of ~100 independent normal deviates stays
 * below 4.5 with probability 0.9993; their RMS below 1.3 times the standard error with
 * probability better than 0.9999 (its own standard error is 1/sqrt(200)). */
static const double MAX_K = 4.5, RMS_K = 1.3, CENTRE_K = 4.0, BASE_K = 4.0;

/* How far the truth is from a parabola over [x - w, x + w]: the largest residual of its
 * least-squares parabola through MISFIT_POINTS evenly spread points. */
enum { MISFIT_POINTS = 201 };

static double quadratic_misfit(double x, double w)
{
    double S[5] = {0}, T[3] = {0}, v[MISFIT_POINTS], h[MISFIT_POINTS];
    for (size_t i = 0; i < MISFIT_POINTS; i++) {
        v[i] = -1 + 2.0 * (double)i / (MISFIT_POINTS - 1);
        h[i] = truth_at(truth.h, truth.n, x + w * v[i]);
        for (size_t j = 0; j < 5; j++)
            S[j] += pow(v[i], (double)j);
        for (size_t j = 0; j < 3; j++)
            T[j] += h[i] * pow(v[i], (double)j);
    }
    /* Symmetric points: S1 = S3 = 0, so a1 is T1/S2 and a0, a2 solve a 2x2 system. */
    const double det = S[0] * S[4] - S[2] * S[2];
    const double a0 = (T[0] * S[4] - S[2] * T[2]) / det, a2 = (S[0] * T[2] - S[2] * T[0]) / det;
    const double a1 = T[1] / S[2];
    double misfit = 0;
    for (size_t i = 0; i < MISFIT_POINTS; i++)
        misfit = fmax(misfit, fabs(h[i] - (a0 + a1 * v[i] + a2 * v[i] * v[i])));
    return misfit;
}

/* Spread (max - min) of the truth's slope over [x - w, x + w]. */
static double slope_spread(double x, double w)
{
    const double lo = (x - w + X_TRUTH) / DX_TRUTH, hi = (x + w + X_TRUTH) / DX_TRUTH;
    double smin = INFINITY, smax = -INFINITY;
    for (long k = (long)floor(lo); k <= (long)ceil(hi); k++) {
        if (k < 0 || (size_t)k + 1 >= truth.n)
            continue;
        smin = fmin(smin, truth.slope[k]);
        smax = fmax(smax, truth.slope[k]);
    }
    return smax - smin;
}

/* Samples per metre behind grid position x once both halves are folded onto the approach
 * half (from the log itself, so drops and gaps count), and whether the window reaches the
 * centre, where the mirrored samples enter twice without adding information. */
static double folded_density(const rig_log *g, int reversed, double x, double w)
{
    const double u0 = fabs(x), lo = fmax(0, u0 - w), hi = u0 + w;
    size_t count = 0;
    for (size_t i = 0; i < g->n; i++) {
        if (g->repeat[i])
            continue; /* a repeat brings no new information */
        const double s = reversed ? X_OFFSET - g->x[i] : g->x[i] - X_OFFSET;
        const double u = fabs(s);
        count += u >= lo && u <= hi;
    }
    return (double)count / (hi - lo);
}

/* Standard error of the flat baseline: the median of the flat samples on both sides (those
 * beyond 0.7 m from the centre, past the bump and the importer's margin). */
static double baseline_se(const rig_case *c)
{
    const double n_flat = 2 * (RUN - 0.7) / SPEED * c->rate;
    return 1.2533 * c->sigma / sqrt(n_flat);
}

/* Standard error of the centre from matching the bump with its mirror image: the noise over
 * the sum of the squared slopes at the samples, var dc = sigma^2 / (2 sum h'^2). */
static double centre_se(const rig_case *c)
{
    double int_slope2 = 0;
    for (size_t k = 0; k + 1 < truth.n; k++)
        int_slope2 += truth.slope[k] * truth.slope[k] * DX_TRUTH;
    return c->sigma / sqrt(2 * c->rate / SPEED * int_slope2);
}

typedef struct {
    double max, rms;       /* allowed error over the grid, m */
} tolerance;

/* Per grid point: the noise (MAX_K or RMS_K standard errors; near the centre the mirrored
 * samples enter twice, which doubles the variance), the bias bound, the baseline's error
 * (BASE_K standard errors) and the centre's error dc to second order: folding cancels the
 * first, as the two halves shift h by +h'dc and -h'dc, leaving at most dc/2 times the spread
 * of h' over [x - dc, x + dc]. */
static tolerance tolerance_for(const rig_log *g, const rig_case *c, const tirenv_curve *out,
                               double w)
{
    const double dc = CENTRE_K * centre_se(c), base = BASE_K * baseline_se(c);
    double max = 0, sum_b2 = 0, sum_se2 = 0;
    for (size_t k = 0; k < out->n; k++) {
        const double x = out->x[k];
        const double rho = folded_density(g, c->reversed, x, w);
        const double twice = fabs(x) < w ? M_SQRT2 : 1;
        const double se = c->sigma * sqrt(KERNEL_VARIANCE / (rho * w)) * twice;
        const double bias = BIAS_PER_MISFIT * quadratic_misfit(x, w)
                            + 0.5 * dc * slope_spread(x, dc) + base;
        max = fmax(max, bias + MAX_K * se);
        sum_b2 += bias * bias;
        sum_se2 += se * se;
    }
    const tolerance tol = {max, sqrt(sum_b2 / (double)out->n)
                                    + RMS_K * sqrt(sum_se2 / (double)out->n)};
    return tol;
}

/* ---- recovering the known curve --------------------------------------------------------- */

static const rig_case cases[] = {
    /* name               rate  sigma   rev rep   drop  shuf smooth */
    {"noise and offsets", 250, 0.2e-3, 0, 0, 0, 0, 0},
    {"reversed", 250, 0.2e-3, 1, 0, 0, 0, 0},
    {"slower rate", 100, 0.2e-3, 0, 0, 0, 0, 0},
    {"faster rate", 1000, 0.2e-3, 0, 0, 0, 0, 0},
    {"repeated and dropped", 250, 0.2e-3, 0, 0.05, 0.05, 0, 0},
    {"shuffled", 250, 0.2e-3, 0, 0, 0, 1, 0},
    {"all at once", 100, 0.2e-3, 1, 0.03, 0.08, 1, 0},
    {"set half-width", 250, 0.2e-3, 0, 0, 0, 0, 6e-3},
    {"noise-free", 250, 0, 0, 0, 0, 0, 0},
    {"noise-free, wide window", 250, 0, 1, 0, 0, 0, 10e-3},
};

static void check_recovers(const rig_case *c, unsigned long seed)
{
    rig_log g = log_make(c, seed);
    const tirenv_import_settings s = case_f_settings(c->smooth);
    tirenv_curve out;
    tirenv_import_info info;
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const int status = tirenv_rig__import(g.n, g.t, g.x, g.z, &s, &out, &info, &d);
    if (status != TIRENV_OK)
        print_error("%s: %s\n", c->name, d.message);
    assert_int_equal(status, TIRENV_OK);

    /* What it found. */
    assert_int_equal(info.reversed, c->reversed);
    assert_int_equal(info.n_repeated, g.repeated);
    assert_int_equal(info.n_samples, g.n - g.repeated);
    if (c->sigma > 0)
        assert_near(info.sigma, c->sigma, 0, 0.05); /* thousands of pseudo-residuals */
    assert_near(info.centre, X_OFFSET, CENTRE_K * centre_se(c) + 1e-6, 0);
    assert_near(info.baseline, Z_OFFSET + truth.z_flat, BASE_K * baseline_se(c) + 1e-9, 0);
    if (c->smooth > 0)
        assert_true(info.half_width == c->smooth);

    /* The grid: x_N from -0.25 to 1 in steps of 0.0125, x = x_0 (1 - x_N). */
    const double x_0 = tirenv_xN_origin(s.R0, s.contact_length, s.L, s.H);
    assert_int_equal(out.n, 101);
    for (size_t k = 0; k < out.n; k++) {
        assert_true(out.x_N[k] == s.xN_from + (double)k * s.dxN);
        assert_near(out.x[k], x_0 * (1 - out.x_N[k]), 1e-15, 0);
    }

    /* The curve. */
    const tolerance tol = tolerance_for(&g, c, &out, info.half_width);
    double max = 0, sum2 = 0;
    for (size_t k = 0; k < out.n; k++) {
        const double e = out.h[k] - truth_at(truth.h, truth.n, out.x[k]);
        max = fmax(max, fabs(e));
        sum2 += e * e;
    }
    const double rms = sqrt(sum2 / (double)out.n);
    print_message("%-24s n %5zu  w %5.2f mm  error rms %.4f (allowed %.4f) max %.4f (allowed "
                  "%.4f) mm\n", c->name, g.n, info.half_width * 1e3, rms * 1e3, tol.rms * 1e3,
                  max * 1e3, tol.max * 1e3);
    assert_true(rms <= tol.rms);
    assert_true(max <= tol.max);
    /* And the tolerance is tight enough to mean something: under the 1 mm resolution of the
     * paper's Figure 5 (1 % of the peak). */
    assert_true(tol.max < 1e-3);
    tirenv_curve_free(&out);
    log_free(&g);
}

static void test_recovers_known_curve(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        check_recovers(&cases[i], 20240611 + i);
}

/* The automatic half-width brings the noise down to its 0.05 mm target (or stays at its
 * bounds) and grows as the log thins out: four times fewer samples, four times the width. */
static void test_automatic_half_width(void **state)
{
    (void)state;
    const rig_case fast = {"", 400, 0.2e-3, 0, 0, 0, 0, 0};
    const rig_case slow = {"", 100, 0.2e-3, 0, 0, 0, 0, 0};
    const tirenv_import_settings s = case_f_settings(0);
    double w[2];
    for (int i = 0; i < 2; i++) {
        rig_log g = log_make(i ? &slow : &fast, 7);
        tirenv_curve out;
        tirenv_import_info info;
        assert_int_equal(tirenv_rig__import(g.n, g.t, g.x, g.z, &s, &out, &info, NULL),
                         TIRENV_OK);
        assert_near(info.noise_se, 0.05e-3, 0, 1e-9);
        w[i] = info.half_width;
        tirenv_curve_free(&out);
        log_free(&g);
    }
    assert_near(w[1] / w[0], 4.0, 0, 0.1); /* sigma estimates differ by a few % */
}

/* A symmetric bump far from the default grid's needs: x_N from 0 to 2 covers both halves,
 * and the curve comes out symmetric about x_N = 1. */
static void test_grid_past_centre(void **state)
{
    (void)state;
    const rig_case c = {"", 250, 0.2e-3, 0, 0, 0, 0, 0};
    rig_log g = log_make(&c, 11);
    tirenv_import_settings s = case_f_settings(0);
    s.xN_from = 0;
    s.xN_to = 2;
    s.dxN = 0.05;
    tirenv_curve out;
    assert_int_equal(tirenv_rig_import_samples(g.n, g.t, g.x, g.z, &s, &out, NULL), TIRENV_OK);
    assert_int_equal(out.n, 41);
    for (size_t k = 0; k < out.n; k++) /* x_N and 2 - x_N differ by round-off only */
        assert_near(out.h[k], out.h[out.n - 1 - k], 1e-9, 0);
    tirenv_curve_free(&out);
    log_free(&g);
}

/* ---- the same through a CSV file --------------------------------------------------------- */

static void temp_path(char path[64], const char *tag)
{
    snprintf(path, 64, "/tmp/tirenv_test_rig_%s_XXXXXX", tag);
    const int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
}

/* Sample i as a line of the log file. */
static void log_line(const rig_log *g, size_t i, char line[128])
{
    const int len = snprintf(line, 128, "%.6f,%.9f,%.9f", g->t[i], g->x[i], g->z[i]);
    assert_true(len > 0 && len < 128);
}

/* The 1-based column where sample i's z starts on its line. */
static size_t z_column(const rig_log *g, size_t i)
{
    char line[128];
    log_line(g, i, line);
    return (size_t)(strrchr(line, ',') - line) + 2;
}

/* Writes the header and the first n samples. */
static void write_log(const char *path, const rig_log *g, size_t n)
{
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    fputs("t_s,x_m,z_m\n", fp);
    for (size_t i = 0; i < n; i++) {
        char line[128];
        log_line(g, i, line);
        fprintf(fp, "%s\n", line);
    }
    assert_int_equal(fclose(fp), 0);
}

static void test_csv_log(void **state)
{
    (void)state;
    const rig_case c = {"", 100, 0.2e-3, 1, 0.03, 0.05, 1, 0};
    rig_log g = log_make(&c, 5);
    char path[64];
    temp_path(path, "log");
    write_log(path, &g, g.n);
    const tirenv_import_settings s = case_f_settings(0);
    tirenv_curve from_file, from_samples;
    tirenv_diag d;
    tirenv_diag_clear(&d);
    assert_int_equal(tirenv_rig_import(path, &s, &from_file, &d), TIRENV_OK);
    /* The same numbers as the text holds (%.6f, %.9f): re-read them to compare exactly. */
    tirenv_rig__log_file log;
    assert_int_equal(tirenv_rig__log_read(path, &log, &d), TIRENV_OK);
    assert_int_equal(log.n, g.n);
    assert_int_equal(log.line[0], 2);
    assert_int_equal(
        tirenv_rig_import_samples(log.n, log.t, log.x, log.z, &s, &from_samples, &d),
        TIRENV_OK);
    assert_int_equal(from_file.n, from_samples.n);
    for (size_t k = 0; k < from_file.n; k++)
        assert_true(from_file.h[k] == from_samples.h[k]);
    tirenv_rig__log_file_free(&log);
    tirenv_curve_free(&from_file);
    tirenv_curve_free(&from_samples);
    log_free(&g);
    remove(path);
}

/* ---- refusals ---------------------------------------------------------------------------- */

typedef struct {
    const char *name;
    const char *text;      /* the file, or NULL for a generated log */
    int status;
    size_t line, column;
    const char *field;
    const char *message;   /* a part of the message */
} bad_log;

static const bad_log bad_logs[] = {
    {"empty file", "", TIRENV_EPARSE, 1, 1, "", "no header"},
    {"only comments", "# rig 3, run 12\n\n", TIRENV_EPARSE, 1, 1, "", "no header"},
    {"missing header", "0.0,1.5,0.70\n0.1,1.6,0.70\n", TIRENV_EPARSE, 1, 1, "t_s",
     "expected the header 't_s,x_m,z_m'"},
    {"wrong header name", "t_s,x_m,h_m\n", TIRENV_EPARSE, 1, 9, "z_m", "got 'h_m'"},
    {"header only", "t_s,x_m,z_m\n", TIRENV_EPARSE, 2, 1, "", "no samples"},
    {"non-numeric", "t_s,x_m,z_m\n0.0,1.5,0.70\n0.1,1.6x,0.70\n", TIRENV_EPARSE, 3, 5, "x_m",
     "expected a number, got '1.6x'"},
    {"empty field", "t_s,x_m,z_m\n0.0,,0.70\n", TIRENV_EPARSE, 2, 5, "x_m", "empty field"},
    {"too few fields", "t_s,x_m,z_m\n0.0,1.5,0.70\n0.1,1.6\n", TIRENV_EPARSE, 3, 8, "z_m",
     "expected 3 fields, got 2"},
    {"too many fields", "t_s,x_m,z_m\n0.0,1.5,0.70,9\n", TIRENV_EPARSE, 2, 14, "",
     "expected 3 fields, got 4"},
    {"NaN", "t_s,x_m,z_m\n0.0,1.5,0.70\n0.1,1.6, nan\n", TIRENV_EPARSE, 3, 10, "z_m",
     "finite"},
    {"infinite", "t_s,x_m,z_m\n1e999,1.5,0.70\n", TIRENV_EPARSE, 2, 1, "t_s", "finite"},
    {"too few samples", "t_s,x_m,z_m\n0.0,1.5,0.70\n0.1,1.6,0.70\n", TIRENV_EINVAL, 0, 0, "t_s",
     "fewer than 50 samples"},
};

static void expect_diag(const tirenv_diag *d, const char *path, size_t line, size_t column,
                        const char *field, const char *message)
{
    char buf[1200];
    print_message("    %s\n", tirenv_diag_format(d, buf, sizeof buf));
    assert_string_equal(d->file, path);
    assert_int_equal(d->line, line);
    assert_int_equal(d->column, column);
    assert_string_equal(d->field, field);
    assert_non_null(strstr(d->message, message));
}

static void test_malformed_logs(void **state)
{
    (void)state;
    const tirenv_import_settings s = case_f_settings(0);
    for (size_t i = 0; i < sizeof bad_logs / sizeof bad_logs[0]; i++) {
        const bad_log *b = &bad_logs[i];
        print_message("%s\n", b->name);
        char path[64];
        temp_path(path, "bad");
        FILE *fp = fopen(path, "w");
        assert_non_null(fp);
        fputs(b->text, fp);
        assert_int_equal(fclose(fp), 0);
        tirenv_curve out = {7, NULL, NULL, NULL};
        tirenv_diag d;
        tirenv_diag_clear(&d);
        assert_int_equal(tirenv_rig_import(path, &s, &out, &d), b->status);
        assert_int_equal(out.n, 0);
        assert_null(out.h);
        expect_diag(&d, path, b->line, b->column, b->field, b->message);
        remove(path);
    }
}

/* Logs that parse but do not hold a whole passage. */
static void test_incomplete_passages(void **state)
{
    (void)state;
    const tirenv_import_settings s = case_f_settings(0);
    const rig_case c = {"", 100, 0.2e-3, 0, 0, 0, 0, 0};
    rig_log g = log_make(&c, 3);
    char path[64];
    temp_path(path, "cut");
    tirenv_curve out;
    tirenv_diag d;

    /* Cut off 0.2 m past the centre, on the bump's departure flank (h near 80 mm): the error
     * points at the last sample's z. */
    size_t n = 0;
    while (n < g.n && g.x[n] < X_OFFSET + 0.2)
        n++;
    write_log(path, &g, n);
    assert_int_equal(tirenv_rig_import(path, &s, &out, &d), TIRENV_EINVAL);
    expect_diag(&d, path, n + 1, z_column(&g, n - 1), "z_m",
                "log ends before the tire leaves the obstacle");

    /* Started 0.2 m before the centre, on the approach flank. */
    size_t start = 0;
    while (start < g.n && g.x[start] < X_OFFSET - 0.2)
        start++;
    rig_log tail = {g.n - start, g.t + start, g.x + start, g.z + start, NULL, 0};
    write_log(path, &tail, tail.n);
    assert_int_equal(tirenv_rig_import(path, &s, &out, &d), TIRENV_EINVAL);
    expect_diag(&d, path, 2, z_column(&tail, 0), "z_m",
                "log starts after the tire has reached the obstacle");

    /* Only flat ground: the noise, no bump. */
    for (size_t i = 0; i < g.n; i++)
        g.z[i] = Z_OFFSET + truth.z_flat + (g.z[i] - Z_OFFSET - truth.z_flat
                                            - truth_at(truth.h, truth.n, g.x[i] - X_OFFSET));
    write_log(path, &g, g.n);
    assert_int_equal(tirenv_rig_import(path, &s, &out, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "no bump above the noise"));
    assert_string_equal(d.field, "z_m");
    assert_true(d.line >= 2 && d.line <= g.n + 1);
    assert_true(d.column >= 6);

    /* A cart that never moved. */
    for (size_t i = 0; i < g.n; i++)
        g.x[i] = X_OFFSET;
    write_log(path, &g, g.n);
    assert_int_equal(tirenv_rig_import(path, &s, &out, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "the cart did not move"));
    assert_int_equal(out.n, 0);
    log_free(&g);
    remove(path);
}

/* A run that starts too close to the obstacle for the default grid (from x_N = -0.25, 0.68 m
 * before the centre): refused with the distances, and accepted once the grid starts later. */
static void test_short_run(void **state)
{
    (void)state;
    const rig_case c = {"", 250, 0.2e-3, 0, 0, 0, 0, 0};
    rig_log g = log_make(&c, 9);
    size_t a = 0, b = g.n;
    while (g.x[a] < X_OFFSET - 0.66)
        a++;
    while (g.x[b - 1] > X_OFFSET + 0.66)
        b--;
    tirenv_import_settings s = case_f_settings(0);
    tirenv_curve out;
    tirenv_diag d;
    assert_int_equal(tirenv_rig_import_samples(b - a, g.t + a, g.x + a, g.z + a, &s, &out, &d),
                     TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "does not reach far enough"));
    s.xN_from = 0;
    assert_int_equal(tirenv_rig_import_samples(b - a, g.t + a, g.x + a, g.z + a, &s, &out, &d),
                     TIRENV_OK);
    tirenv_curve_free(&out);
    log_free(&g);
}

/* Two samples a second (5 cm apart) cannot show a curve with 1 cm features: refused, and a
 * window as small as a few samples is refused point by point. */
static void test_sparse_log(void **state)
{
    (void)state;
    const rig_case c = {"", 2, 0.2e-3, 0, 0, 0, 0, 0};
    rig_log g = log_make(&c, 13);
    tirenv_import_settings s = case_f_settings(0);
    tirenv_curve out;
    tirenv_diag d;
    assert_int_equal(tirenv_rig_import_samples(g.n, g.t, g.x, g.z, &s, &out, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "log too sparse"));
    s.smooth = 0.03;
    assert_int_equal(tirenv_rig_import_samples(g.n, g.t, g.x, g.z, &s, &out, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "too few samples near x_N"));
    assert_int_equal(out.n, 0);
    log_free(&g);
}

static void test_bad_settings(void **state)
{
    (void)state;
    const rig_case c = {"", 100, 0.2e-3, 0, 0, 0, 0, 0};
    rig_log g = log_make(&c, 1);
    static const struct {
        const char *field;
        double value;
    } bad[] = {{"L", NAN}, {"H", 0}, {"R0", -0.68}, {"contact_length", 1.4},
               {"dxN", 0}, {"xN_to", -1}, {"smooth", -1e-3}, {"H", 2.5}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        tirenv_import_settings s = case_f_settings(0);
        double *v = strcmp(bad[i].field, "L") == 0                ? &s.L
                    : strcmp(bad[i].field, "H") == 0              ? &s.H
                    : strcmp(bad[i].field, "R0") == 0             ? &s.R0
                    : strcmp(bad[i].field, "contact_length") == 0 ? &s.contact_length
                    : strcmp(bad[i].field, "dxN") == 0            ? &s.dxN
                    : strcmp(bad[i].field, "xN_to") == 0          ? &s.xN_to
                                                                  : &s.smooth;
        *v = bad[i].value;
        tirenv_curve out;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        assert_int_equal(tirenv_rig_import_samples(g.n, g.t, g.x, g.z, &s, &out, &d),
                         TIRENV_EINVAL);
        assert_string_equal(d.field, bad[i].field);
        assert_int_equal(out.n, 0);
    }
    /* A NaN sample is named by its index. */
    g.z[123] = NAN;
    tirenv_import_settings s = case_f_settings(0);
    tirenv_curve out;
    tirenv_diag d;
    assert_int_equal(tirenv_rig_import_samples(g.n, g.t, g.x, g.z, &s, &out, &d), TIRENV_EINVAL);
    assert_int_equal(d.line, 124);
    assert_string_equal(d.field, "z");
    log_free(&g);
}

/* ---- the command: all or nothing ------------------------------------------------------------ */

static int run(const char *cmd)
{
    const int status = system(cmd);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static void test_command_writes_all_or_nothing(void **state)
{
    (void)state;
    const rig_case c = {"", 100, 0.2e-3, 1, 0, 0, 0, 0};
    rig_log g = log_make(&c, 21);
    char log_path[64], out_path[80], cli[1024], cmd[1536];
    temp_path(log_path, "cli");
    snprintf(out_path, sizeof out_path, "%s.curve.csv", log_path);
    const char *const fmt = "%s import --log %s --cleat 0.30,0.10 --contact-length 0.38 "
                            "-o %s 2>/dev/null";

    write_log(log_path, &g, g.n);
    snprintf(cmd, sizeof cmd, fmt, tirenv_test_shell_quote(TIRENV_CLI, cli, sizeof cli),
             log_path, out_path);
    assert_int_equal(run(cmd), 0);
    tirenv_curve out;
    tirenv_diag d;
    assert_int_equal(tirenv_curve_read_csv(out_path, &out, &d), TIRENV_OK);
    assert_int_equal(out.n, 101);
    tirenv_curve_free(&out);
    remove(out_path);

    /* Every refusal: exit status 2 (bad data) and no output file, not even a partial one. */
    for (size_t i = 0; i < sizeof bad_logs / sizeof bad_logs[0]; i++) {
        FILE *fp = fopen(log_path, "w");
        assert_non_null(fp);
        fputs(bad_logs[i].text, fp);
        assert_int_equal(fclose(fp), 0);
        assert_int_equal(run(cmd), 2);
        struct stat st;
        assert_int_equal(stat(out_path, &st), -1);
    }
    write_log(log_path, &g, g.n / 2); /* cut off at the centre */
    assert_int_equal(run(cmd), 2);
    struct stat st;
    assert_int_equal(stat(out_path, &st), -1);
    remove(log_path);
    log_free(&g);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_recovers_known_curve),
        cmocka_unit_test(test_automatic_half_width),
        cmocka_unit_test(test_grid_past_centre),
        cmocka_unit_test(test_csv_log),
        cmocka_unit_test(test_malformed_logs),
        cmocka_unit_test(test_incomplete_passages),
        cmocka_unit_test(test_short_run),
        cmocka_unit_test(test_sparse_log),
        cmocka_unit_test(test_bad_settings),
        cmocka_unit_test(test_command_writes_all_or_nothing),
    };
    return cmocka_run_group_tests(tests, truth_setup, truth_teardown);
}
