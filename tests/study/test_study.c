/* SPDX-License-Identifier: Apache-2.0 */
/* The comparison (docs/models.md section 8): curve errors on hand-made curves with known answers,
 * per-case predictions against the curves that generated them, and tirenv_compare end to end
 * on a small synthetic data set, down to the images gnuplot draws. */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "tirenv/rng.h"
#include "testutil.h"
#include "tirenv/tirenv.h"
#include "tirenv/nn.h"
#include "tirenv/study.h"

/* ---- metrics ------------------------------------------------------------------------------ */

enum { N_HAND = 41 };

/* A grid with an awkward spacing, and a smooth bump on it (m). */
static void hand_curve(double x[], double h[])
{
    for (size_t k = 0; k < N_HAND; ++k) {
        x[k] = -0.4137 + 0.01093 * (double)k;
        const double u = (double)k / (N_HAND - 1);
        h[k] = 0.0823 * u * u * (3 - 2 * u);
    }
}

/* A constant offset d: every difference is d, so RMS = max = peak = d (to round-off, 1e-15
 * relative). */
static void test_metrics_constant_offset(void **state)
{
    (void)state;
    double x[N_HAND], h[N_HAND], g[N_HAND];
    hand_curve(x, h);
    const double d = 2.385e-3;
    for (size_t k = 0; k < N_HAND; ++k)
        g[k] = h[k] + d;
    tirenv_curve_errors e;
    assert_int_equal(tirenv_curve_errors_compute(N_HAND, x, h, g, 1e-3, &e), TIRENV_OK);
    assert_near(e.rms, d, 0, 1e-12);
    assert_near(e.max, d, 0, 1e-12);
    assert_near(e.peak, d, 0, 1e-12);
    /* Lower by d: the same magnitudes, peak with the sign of the difference. */
    for (size_t k = 0; k < N_HAND; ++k)
        g[k] = h[k] - d;
    assert_int_equal(tirenv_curve_errors_compute(N_HAND, x, h, g, 1e-3, &e), TIRENV_OK);
    assert_near(e.rms, d, 0, 1e-12);
    assert_near(e.max, d, 0, 1e-12);
    assert_near(e.peak, -d, 0, 1e-12);
}

/* Differences +3 and -4 mm on two points: RMS sqrt(12.5) mm, max 4 mm; a curve scaled by
 * 1.27 has its peak 0.27 times the measured peak higher (1e-12 relative). */
static void test_metrics_known_values(void **state)
{
    (void)state;
    const double x2[2] = {0.1, 0.2}, m2[2] = {0.010, 0.020}, p2[2] = {0.013, 0.016};
    tirenv_curve_errors e;
    assert_int_equal(tirenv_curve_errors_compute(2, x2, m2, p2, 1e-3, &e), TIRENV_OK);
    assert_near(e.rms, sqrt(12.5) * 1e-3, 0, 1e-12);
    assert_near(e.max, 4e-3, 0, 1e-12);
    assert_near(e.peak, -4e-3, 0, 1e-12);

    double x[N_HAND], h[N_HAND], g[N_HAND];
    hand_curve(x, h);
    for (size_t k = 0; k < N_HAND; ++k)
        g[k] = 1.27 * h[k];
    assert_int_equal(tirenv_curve_errors_compute(N_HAND, x, h, g, 1e-3, &e), TIRENV_OK);
    assert_near(e.peak, 0.27 * 0.0823, 0, 1e-12);
    assert_near(e.max, 0.27 * 0.0823, 0, 1e-12);
}

/* A ramp h = s (x - a)+ and the same ramp shifted by a distance that is not a multiple of the
 * grid spacing: the first rise moves by exactly the shift (interpolated crossing; 1e-12 m),
 * later or earlier. The grid point before each crossing lies on the ramp, so the linear
 * interpolation is exact. */
static void test_metrics_first_rise_shift(void **state)
{
    (void)state;
    enum { N = 80 };
    const double dx = 0.01, s = 0.05, a = -0.3137, threshold = 1e-3;
    const double shifts[] = {0.0137, -0.0261, 0.0};
    double x[N], h[N], g[N];
    for (size_t k = 0; k < N; ++k) {
        x[k] = -0.5 + dx * (double)k;
        h[k] = fmax(0, s * (x[k] - a));
    }
    for (size_t i = 0; i < sizeof shifts / sizeof shifts[0]; ++i) {
        for (size_t k = 0; k < N; ++k)
            g[k] = fmax(0, s * (x[k] - a - shifts[i]));
        tirenv_curve_errors e;
        assert_int_equal(tirenv_curve_errors_compute(N, x, h, g, threshold, &e), TIRENV_OK);
        assert_near(e.first_rise, shifts[i], 1e-12, 0);
    }
}

/* No rise above the threshold on either side gives NaN; a curve already above it at its first
 * point rises there. */
static void test_metrics_first_rise_nan(void **state)
{
    (void)state;
    double x[N_HAND], h[N_HAND], flat[N_HAND], high[N_HAND];
    hand_curve(x, h);
    for (size_t k = 0; k < N_HAND; ++k) {
        flat[k] = 0.4e-3;  /* below the 1 mm threshold everywhere */
        high[k] = 5e-3 + h[k];
    }
    tirenv_curve_errors e;
    assert_int_equal(tirenv_curve_errors_compute(N_HAND, x, h, flat, 1e-3, &e), TIRENV_OK);
    assert_true(isnan(e.first_rise));
    assert_int_equal(tirenv_curve_errors_compute(N_HAND, x, flat, h, 1e-3, &e), TIRENV_OK);
    assert_true(isnan(e.first_rise));
    assert_true(isfinite(e.rms));
    /* h crosses 1 mm between points 2 and 3 (u^2 (3 - 2u) = 1/82.3 at u = 0.0646, k = 40u):
     * the model rises at x[0], that much earlier. */
    assert_int_equal(tirenv_curve_errors_compute(N_HAND, x, h, high, 1e-3, &e), TIRENV_OK);
    const double cross = x[2] + (1e-3 - h[2]) / (h[3] - h[2]) * (x[3] - x[2]);
    assert_true(h[2] <= 1e-3 && h[3] > 1e-3);
    assert_near(e.first_rise, x[0] - cross, 1e-15, 0);
}

static void test_metrics_errors(void **state)
{
    (void)state;
    double x[N_HAND], h[N_HAND], g[N_HAND];
    hand_curve(x, h);
    memcpy(g, h, sizeof g);
    tirenv_curve_errors e;
    assert_int_equal(tirenv_curve_errors_compute(0, x, h, g, 1e-3, &e), TIRENV_EINVAL);
    g[7] = NAN;
    assert_int_equal(tirenv_curve_errors_compute(N_HAND, x, h, g, 1e-3, &e), TIRENV_EINVAL);
    g[7] = h[7];
    assert_int_equal(tirenv_curve_errors_compute(N_HAND, x, h, g, NAN, &e), TIRENV_EINVAL);
}

/* ---- predictions -------------------------------------------------------------------------- */

/* One case over an L x H cleat at contact length l_c: points on x_N from -0.15 to 1 (the
 * convention of docs/models.md section 1, with the tire's R0), h left zero. */
static void case_init(tirenv_case *c, const char *name, tirenv_split split, double l_c,
                      double load, double L, double H, double R0, size_t n)
{
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", name);
    c->split = split;
    c->contact_length = l_c;
    c->load = load;
    c->L = L;
    c->H = H;
    assert_int_equal(tirenv_curve_alloc(&c->curve, n), TIRENV_OK);
    const double x_0 = tirenv_xN_origin(R0, l_c, L, H);
    assert_true(x_0 < 0);
    for (size_t k = 0; k < n; ++k) {
        c->curve.x_N[k] = -0.15 + 1.15 * (double)k / (double)(n - 1);
        c->curve.x[k] = x_0 * (1 - c->curve.x_N[k]);
    }
}

/* The springs model swept cold (tirenv_model_set before every position, so no warm start)
 * against tirenv_case_predict_model's warm-started sweep: both are the equilibrium at the
 * case's load, so they agree to its tolerance. Equilibrium tolerances are eps_z = 1e-10 m and
 * eps_F = 1e-6 N (over ~1e6 N/m: 1e-12 m); 1e-9 m leaves room for a force jump located to
 * eps_z on each side. */
static void test_predict_model_reproduces_springs(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    tire.springs.dphi = M_PI / 180;
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &tire);
    assert_non_null(m);
    tirenv_diag diag;
    double load;
    assert_int_equal(tirenv_model_load_for_contact_length(m, 0.33, &load, &diag), TIRENV_OK);
    tirenv_case c;
    case_init(&c, "J", TIRENV_SPLIT_VALIDATION, 0.33, load, 0.30, 0.05, tire.springs.R0, 47);
    tirenv_profile *cleat = tirenv_profile_cleat(c.L, c.H);
    for (size_t k = 0; k < c.curve.n; ++k) {
        tirenv_point pt;
        assert_int_equal(tirenv_model_set(m, cleat, load, &diag), TIRENV_OK);
        assert_int_equal(tirenv_model_eval(m, c.curve.x[k], &pt, &diag), TIRENV_OK);
        c.curve.h[k] = pt.h;
    }
    tirenv_profile_free(cleat);
    double h[47];
    assert_int_equal(tirenv_case_predict_model(m, &c, h, &diag), TIRENV_OK);
    for (size_t k = 0; k < c.curve.n; ++k)
        assert_near(h[k], c.curve.h[k], 1e-9, 0);
    assert_true(c.curve.h[c.curve.n - 1] > 0.04);  /* it did climb the 50 mm cleat */

    /* Positions out of order are refused, naming the case and the point. */
    const double t = c.curve.x[3];
    c.curve.x[3] = c.curve.x[5];
    c.curve.x[5] = t;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_case_predict_model(m, &c, h, &diag), TIRENV_EINVAL);
    assert_non_null(strstr(diag.message, "case J"));
    assert_int_equal(diag.line, 5);
    tirenv_curve_free(&c.curve);
    tirenv_model_free(m);
}

/* A network with random weights and no input ranges (so no point is zeroed): the prediction
 * at the case's x positions is the network at the case's own x_N (1e-12 m), i.e. predict_nn
 * and the data set use the same x_N convention. */
static void test_predict_nn_uses_case_xN(void **state)
{
    (void)state;
    tirenv_nn_topology t = tirenv_nn_topology_default();
    tirenv_nn *nn = tirenv_nn_alloc(&t);
    assert_non_null(nn);
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 7211);
    tirenv_nn_init_weights(nn, rng);
    tirenv_rng_free(rng);
    const double mean[4] = {0.5, 0.33, 0.07, 0.2}, sd[4] = {0.3, 0.04, 0.03, 0.1};
    assert_int_equal(tirenv_nn_set_scaling(nn, mean, sd, 0.03, 0.02, NULL), TIRENV_OK);
    const double R0 = 0.6913;
    tirenv_case c;
    case_init(&c, "F", TIRENV_SPLIT_VALIDATION, 0.38, 17000, 0.30, 0.10, R0, 33);
    double h[33];
    tirenv_diag diag;
    assert_int_equal(tirenv_case_predict_nn(nn, R0, &c, h, &diag), TIRENV_OK);
    for (size_t k = 0; k < c.curve.n; ++k) {
        const double in[4] = {c.curve.x_N[k], c.contact_length, c.H, c.L};
        assert_near(h[k], tirenv_nn_run(nn, in), 1e-12, 0);
    }
    tirenv_curve_free(&c.curve);
    tirenv_nn_free(nn);
}

/* ---- the comparison end to end ------------------------------------------------------------ */

enum { N_CMP = 3, N_POINTS = 31 };

/* The paper's Table 3 cases, simulated by the ring reference tire at its own contact lengths
 * (as the embedded data set is), without noise: the ring row must then be exact. */
static void make_dataset(tirenv_dataset *ds, tirenv_case cases[], const tirenv_tire *tire)
{
    static const struct {
        const char *name;
        double l_c, L, H;
    } design[N_CMP] = {{"F", 0.38, 0.30, 0.10}, {"J", 0.33, 0.30, 0.05}, {"R", 0.28, 0.10, 0.10}};
    tirenv_model *ring = tirenv_model_alloc(tirenv_model_ring, tire);
    assert_non_null(ring);
    memset(ds, 0, sizeof *ds);
    snprintf(ds->dir, sizeof ds->dir, "synthetic");
    ds->n = N_CMP;
    ds->cases = cases;
    for (size_t i = 0; i < N_CMP; ++i) {
        tirenv_diag diag;
        double load;
        assert_int_equal(tirenv_model_load_for_contact_length(ring, design[i].l_c, &load, &diag),
                         TIRENV_OK);
        case_init(&cases[i], design[i].name, TIRENV_SPLIT_VALIDATION, design[i].l_c, load,
                  design[i].L, design[i].H, tire->springs.R0, N_POINTS);
        assert_int_equal(tirenv_case_predict_model(ring, &cases[i], cases[i].curve.h, &diag),
                         TIRENV_OK);
    }
    tirenv_model_free(ring);
}

static void free_dataset(tirenv_dataset *ds)
{
    for (size_t i = 0; i < ds->n; ++i)
        tirenv_curve_free(&ds->cases[i].curve);
}

/* A small trained-looking network: random weights scaled to the data's h. */
static tirenv_nn *small_nn(void)
{
    tirenv_nn_topology t = tirenv_nn_topology_default();
    tirenv_nn *nn = tirenv_nn_alloc(&t);
    assert_non_null(nn);
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 99);
    tirenv_nn_init_weights(nn, rng);
    tirenv_rng_free(rng);
    const double mean[4] = {0.5, 0.33, 0.07, 0.2}, sd[4] = {0.3, 0.04, 0.03, 0.1};
    assert_int_equal(tirenv_nn_set_scaling(nn, mean, sd, 0.04, 0.02, NULL), TIRENV_OK);
    return nn;
}

static char *read_text(const char *dir, const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *fp = fopen(path, "r");
    if (!fp)
        return NULL;
    static char buf[1 << 17];
    const size_t n = fread(buf, 1, sizeof buf - 1, fp);
    buf[n] = '\0';
    fclose(fp);
    return buf;
}

static long file_size(const char *dir, const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

static size_t count_lines(const char *text)
{
    size_t n = 0;
    for (; *text; ++text)
        n += *text == '\n';
    return n;
}

/* Removes the files of a flat scratch directory, then the directory; fails the test if any
 * temporary file was left behind. */
static void remove_dir(const char *dir)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    struct dirent *e;
    while ((e = readdir(d))) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        if (strstr(e->d_name, "tmp."))
            fail_msg("temporary file left behind: %s/%s", dir, e->d_name);
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        assert_int_equal(remove(path), 0);
    }
    closedir(d);
    assert_int_equal(rmdir(dir), 0);
}

/* Every file the comparison promises, with one CSV row per case and model; the images are
 * drawn (gnuplot is a build dependency: scripts/deps.sh), so their absence fails. The ring,
 * which made the data, reproduces them to the equilibrium tolerance (1e-9 m); the springs
 * model with the default tire does not (it is another model), and every time is positive. */
static void test_compare_writes_everything(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    tire.springs.dphi = M_PI / 180;   /* 1 deg keeps the test quick */
    tire.ring.dtheta = M_PI / 180;
    static tirenv_case cases[N_CMP];
    tirenv_dataset ds;
    make_dataset(&ds, cases, &tire);
    tirenv_nn *nn = small_nn();

    char dir[] = "/tmp/tirenv-test-study-XXXXXX";
    assert_non_null(mkdtemp(dir));
    char out_dir[sizeof dir + 16];
    snprintf(out_dir, sizeof out_dir, "%s/report", dir);  /* created by compare */
    tirenv_compare_settings s = tirenv_compare_default();
    s.out_dir = out_dir;
    s.simulated_by = tirenv_model_ring;
    s.min_time = 0.005;
    s.title = "Test comparison";
    tirenv_compare_result r;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_compare(&ds, &tire, nn, &s, &r, &diag);
    if (status)
        print_error("%s\n", diag.message);
    assert_int_equal(status, TIRENV_OK);
    assert_int_equal(r.n_cases, N_CMP);
    assert_int_equal(r.n_models, 4);  /* rigid, springs, ring (the reference), nn */
    assert_string_equal(r.model[0], "rigid");
    assert_string_equal(r.model[1], "springs");
    assert_string_equal(r.model[2], "ring");
    assert_string_equal(r.model[3], "nn");
    assert_int_equal(r.reference_model, 2);
    assert_int_equal(r.nn_model, 3);
    assert_true(r.images);
    for (size_t i = 0; i < N_CMP; ++i) {
        const tirenv_compare_entry *ring = &r.entry[i * r.n_models + 2];
        assert_int_equal(ring->status, TIRENV_OK);
        assert_near(ring->errors.rms, 0, 1e-9, 0);
        assert_near(ring->errors.peak, 0, 1e-9, 0);
        for (size_t j = 0; j < r.n_models; ++j)
            assert_int_equal(r.entry[i * r.n_models + j].status, TIRENV_OK);
        assert_true(r.entry[i * r.n_models + 1].errors.rms > 1e-4);
    }
    for (size_t j = 0; j < r.n_models; ++j) {
        assert_true(r.time_per_position[j] > 0 && isfinite(r.time_per_position[j]));
        assert_int_equal(r.timed_positions[j], N_CMP * N_POINTS);
        assert_true(r.timed_repeats[j] >= 1);
    }
    assert_int_equal(tirenv_compare_report(&ds, &s, &r, "Notes from the test.\n", &diag),
                     TIRENV_OK);

    char *text = read_text(out_dir, "errors.csv");
    assert_non_null(text);
    assert_non_null(strstr(text, "case,model,rms_mm,max_mm,peak_mm,first_rise_mm,rms_over_H\n"));
    assert_int_equal(count_lines(text), 1 + N_CMP * 4);
    assert_non_null(strstr(text, "\nR,springs,"));
    /* rms_over_H is the RMS over the case's obstacle height: the row's rms_mm (4 decimals)
     * over H in mm, to the rounding of either column. */
    for (size_t i = 0; i < N_CMP; ++i) {
        char key[48];
        snprintf(key, sizeof key, "\n%.31s,springs,", cases[i].name);
        const char *row = strstr(text, key);
        assert_non_null(row);
        double rms_mm, max_mm, peak_mm, rise_mm, over_H;
        assert_int_equal(sscanf(row + strlen(key), "%lf,%lf,%lf,%lf,%lf", &rms_mm, &max_mm,
                                &peak_mm, &rise_mm, &over_H), 5);
        assert_near(over_H, rms_mm / (1e3 * cases[i].H), 1e-6 + 5e-5 / (1e3 * cases[i].H), 0);
        assert_near(over_H, r.entry[i * r.n_models + 1].errors.rms / cases[i].H, 1e-6, 0);
    }
    assert_non_null(strstr(text, "\nF,nn,"));
    assert_int_equal(count_lines(read_text(out_dir, "timing.csv")), 1 + 4);
    text = read_text(out_dir, "errors.md");
    assert_non_null(text);
    assert_non_null(strstr(text, "| Case |"));
    assert_non_null(strstr(text, "| RMS/H (%) |"));
    assert_non_null(strstr(text, "SIMULATED"));
    text = read_text(out_dir, "report.md");
    assert_non_null(text);
    assert_non_null(strstr(text, "SIMULATED"));
    assert_non_null(strstr(text, "![Case R"));
    assert_non_null(strstr(text, "(R.png)"));
    assert_non_null(strstr(text, "Notes from the test."));
    assert_non_null(strstr(text, "times the network's"));
    for (size_t i = 0; i < N_CMP; ++i) {
        char name[64];
        snprintf(name, sizeof name, "%.31s.gp", cases[i].name);
        text = read_text(out_dir, name);
        assert_non_null(text);
        assert_non_null(strstr(text, "pngcairo"));
        assert_non_null(strstr(text, "set terminal svg"));
        assert_non_null(strstr(text, "SIMULATED"));
        snprintf(name, sizeof name, "%.31s.dat", cases[i].name);
        text = read_text(out_dir, name);
        assert_non_null(text);
        assert_non_null(strstr(text, "SIMULATED"));
        assert_int_equal(count_lines(text) - 4, N_POINTS);  /* four comment lines */
        snprintf(name, sizeof name, "%.31s.png", cases[i].name);
        if (file_size(out_dir, name) <= 0)
            fail_msg("%s/%s was not drawn: is gnuplot installed (scripts/deps.sh)?", out_dir,
                     name);
        snprintf(name, sizeof name, "%.31s.svg", cases[i].name);
        if (file_size(out_dir, name) <= 0)
            fail_msg("%s/%s was not drawn: is gnuplot installed (scripts/deps.sh)?", out_dir,
                     name);
    }
    tirenv_compare_result_free(&r);
    tirenv_compare_result_free(&r);  /* twice is harmless */
    if (!getenv("TIRENV_KEEP_TEST_OUTPUT")) {
        remove_dir(out_dir);
        assert_int_equal(rmdir(dir), 0);
    } else {
        print_message("output kept in %s\n", out_dir);
    }
    tirenv_nn_free(nn);
    free_dataset(&ds);
}

/* A model that fails on one case is recorded, not fatal: a load no springs tire carries gives
 * no equilibrium; its row is nan, the others are numbers; unknown case names and a missing
 * gnuplot are errors that say so, the latter after the data files are written and without
 * leaving temporary images. */
static void test_compare_failures(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    tire.springs.dphi = M_PI / 180;
    tire.ring.dtheta = M_PI / 180;
    static tirenv_case cases[N_CMP];
    tirenv_dataset ds;
    make_dataset(&ds, cases, &tire);
    cases[1].load = 5e8;  /* J: far beyond what the tire carries */

    char dir[] = "/tmp/tirenv-test-study-XXXXXX";
    assert_non_null(mkdtemp(dir));
    tirenv_compare_settings s = tirenv_compare_default();
    s.out_dir = dir;
    s.simulated = 1;
    s.min_time = 0;
    s.gnuplot = "/nonexistent/tirenv-test/gnuplot";
    const char *names[] = {"R", "J"};
    s.cases = names;
    s.n_cases = 2;
    tirenv_compare_result r;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_compare(&ds, &tire, NULL, &s, &r, &diag), TIRENV_EIO);
    assert_non_null(strstr(diag.message, "gnuplot"));
    assert_non_null(strstr(diag.message, "not found"));
    assert_false(r.images);
    assert_int_equal(r.n_cases, 2);
    assert_int_equal(r.n_models, 2);  /* rigid, springs: no network, no reference */
    assert_int_equal(r.case_index[0], 2);
    const tirenv_compare_entry *bad = &r.entry[1 * r.n_models + 1];
    assert_int_equal(bad->status, TIRENV_ENOBRACKET);
    assert_non_null(strstr(bad->message, "case J"));
    assert_true(isnan(bad->errors.rms));
    assert_int_equal(r.entry[0 * r.n_models + 1].status, TIRENV_OK);
    char *text = read_text(dir, "errors.csv");
    assert_non_null(text);
    assert_non_null(strstr(text, "\nJ,springs,nan,nan,nan,nan,nan\n"));
    assert_non_null(strstr(text, "\nR,springs,"));
    assert_non_null(read_text(dir, "R.gp"));
    text = read_text(dir, "J.gp");
    assert_non_null(text);
    assert_non_null(strstr(text, "springs is not drawn"));
    assert_true(file_size(dir, "R.png") < 0);
    /* The report still says what happened. */
    s.images = 0;
    assert_int_equal(tirenv_compare_report(&ds, &s, &r, NULL, &diag), TIRENV_OK);
    text = read_text(dir, "report.md");
    assert_non_null(strstr(text, "springs failed"));
    assert_non_null(strstr(text, "gnuplot R.gp"));
    tirenv_compare_result_free(&r);

    /* A gnuplot that fails: its exit status is reported, no image is left behind. */
    s.images = 1;
    s.gnuplot = "false";
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_compare(&ds, &tire, NULL, &s, &r, &diag), TIRENV_EIO);
    assert_non_null(strstr(diag.message, "exited with status 1"));
    assert_true(file_size(dir, "R.png") < 0);
    tirenv_compare_result_free(&r);

    const char *unknown[] = {"F", "Q"};
    s.cases = unknown;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_compare(&ds, &tire, NULL, &s, &r, &diag), TIRENV_EINVAL);
    assert_non_null(strstr(diag.message, "'Q'"));
    assert_non_null(strstr(diag.message, "F, J, R"));
    tirenv_compare_result_free(&r);

    /* No case of the split asked for. */
    s.cases = NULL;
    s.n_cases = 0;
    s.split = TIRENV_SPLIT_TRAIN;
    assert_int_equal(tirenv_compare(&ds, &tire, NULL, &s, &r, &diag), TIRENV_EINVAL);
    assert_non_null(strstr(diag.message, "train"));
    tirenv_compare_result_free(&r);

    remove_dir(dir);
    free_dataset(&ds);
}

/* tirenv_plot_draw's temporary names hold a symbolic link already (a file left behind, or
 * one placed there): it is replaced, never written through, and the image is a file of its
 * own. Run first, so that this process's first draw is call 0. */
static void test_plot_draw_stale(void **state)
{
    (void)state;
    char dir[] = "/tmp/tirenv-test-plot-XXXXXX";
    assert_non_null(mkdtemp(dir));
    char path[1024], link[1024];
    snprintf(path, sizeof path, "%s/c.gp", dir);
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    fputs("set terminal pngcairo size 200,100\nset output png_out\nplot x\n"
          "set terminal svg size 200,100\nset output svg_out\nplot x\nunset output\n", fp);
    assert_int_equal(fclose(fp), 0);
    snprintf(path, sizeof path, "%s/keep.txt", dir);
    fp = fopen(path, "w");
    assert_non_null(fp);
    fputs("keep\n", fp);
    assert_int_equal(fclose(fp), 0);
    /* The names of this process's first draw, and of the draws before them (the pid alone). */
    const char *const names[] = {"c.png.tmp.%ld.0", "c.svg.tmp.%ld.0", "c.png.tmp.%ld",
                                 "c.svg.tmp.%ld"};
    for (size_t k = 0; k < 4; ++k) {
        char name[64];
        snprintf(name, sizeof name, names[k], (long)getpid());
        snprintf(link, sizeof link, "%s/%s", dir, name);
        assert_int_equal(symlink("keep.txt", link), 0);
    }
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_plot_draw(dir, "c", NULL, &diag), TIRENV_OK);
    assert_string_equal(read_text(dir, "keep.txt"), "keep\n");
    struct stat st;
    snprintf(path, sizeof path, "%s/c.png", dir);
    assert_int_equal(lstat(path, &st), 0);
    assert_true(S_ISREG(st.st_mode) && st.st_size > 0);
    for (size_t k = 2; k < 4; ++k) {  /* not this version's names: left as they were */
        char name[64];
        snprintf(name, sizeof name, names[k], (long)getpid());
        snprintf(link, sizeof link, "%s/%s", dir, name);
        assert_int_equal(remove(link), 0);
    }
    remove_dir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plot_draw_stale),
        cmocka_unit_test(test_metrics_constant_offset),
        cmocka_unit_test(test_metrics_known_values),
        cmocka_unit_test(test_metrics_first_rise_shift),
        cmocka_unit_test(test_metrics_first_rise_nan),
        cmocka_unit_test(test_metrics_errors),
        cmocka_unit_test(test_predict_model_reproduces_springs),
        cmocka_unit_test(test_predict_nn_uses_case_xN),
        cmocka_unit_test(test_compare_writes_everything),
        cmocka_unit_test(test_compare_failures),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
