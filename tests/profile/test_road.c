/* The ISO 8608 random road generator: class values, the PSD of a generated road against the
 * class's, exact scaling between classes, Parseval, reproducibility and refusals.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "core/fft.h"

#include "tirenv/tirenv.h"

static tirenv_road_settings road(char road_class, double length, double dx, unsigned long seed)
{
    tirenv_road_settings s = tirenv_road_default();
    s.road_class = road_class;
    s.length = length;
    s.dx = dx;
    s.seed = seed;
    return s;
}

static tirenv_profile *generate(const tirenv_road_settings *s)
{
    tirenv_profile *p = NULL;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_road_iso8608(s, &p, &diag);
    if (status)
        print_error("%s\n", diag.message);
    assert_int_equal(status, TIRENV_OK);
    assert_non_null(p);
    return p;
}

/* ISO 8608's table: the geometric means of the class bands, in 1e-6 m^3. Exact: each is a
 * power of two times 16e-6 (rounding commutes with scaling by 2). */
static void test_class_values(void **state)
{
    (void)state;
    const double gd0[] = {16e-6, 64e-6, 256e-6, 1024e-6, 4096e-6, 16384e-6, 65536e-6,
                          262144e-6};
    for (int k = 0; k < 8; k++) {
        assert_true(tirenv_iso8608_gd0((char)('A' + k)) == gd0[k]);
        assert_true(tirenv_iso8608_gd0((char)('a' + k)) == gd0[k]);
    }
    assert_true(isnan(tirenv_iso8608_gd0('I')));
    assert_true(isnan(tirenv_iso8608_gd0('@')));
    assert_true(isnan(tirenv_iso8608_gd0('\0')));
    tirenv_road_settings s = tirenv_road_default();
    s.road_class = 'D';
    assert_true(tirenv_road_psd(&s, 0.1) == 1024e-6);
    assert_near(tirenv_road_psd(&s, 1.0), 1024e-6 / 100, 0, 1e-15);
    assert_near(tirenv_road_psd(&s, 0.0213), 1024e-6 * pow(0.1 / 0.0213, 2), 0, 1e-15);
    assert_true(tirenv_road_psd(&s, 0.0109) == 0 && tirenv_road_psd(&s, 2.84) == 0);
    s.road_class = 'Z';
    assert_true(isnan(tirenv_road_psd(&s, 0.1)));
}

/* Welch's PSD estimate at the bins of segments of NS points: Hann window, 50 % overlap,
 * segment mean removed, one-sided, P_k = 2 |Y_k|^2 dx / sum(w^2) (m^3). Returns the number of
 * segments averaged. */
enum { NS = 4096 };
static size_t welch(const double z[], size_t n, double dx, double P[NS / 2])
{
    static double complex seg[NS];
    static double w[NS];
    double w2 = 0;
    for (size_t i = 0; i < NS; i++) {
        w[i] = 0.5 * (1 - cos(2 * M_PI * (double)i / NS));
        w2 += w[i] * w[i];
    }
    memset(P, 0, NS / 2 * sizeof P[0]);
    size_t K = 0;
    for (size_t start = 0; start + NS <= n; start += NS / 2, K++) {
        double mean = 0;
        for (size_t i = 0; i < NS; i++)
            mean += z[start + i] / NS;
        for (size_t i = 0; i < NS; i++)
            seg[i] = w[i] * (z[start + i] - mean);
        tirenv_core__fft(seg, NS, -1);
        for (size_t k = 1; k < NS / 2; k++)
            P[k] += 2 * (creal(seg[k]) * creal(seg[k]) + cimag(seg[k]) * cimag(seg[k])) * dx / w2;
    }
    for (size_t k = 1; k < NS / 2; k++)
        P[k] /= (double)K;
    return K;
}

/* A 20 km class C road at 5 cm (400,001 points): the Welch estimate over the bins within
 * [0.8 n, 1.25 n] of each test frequency n, as the mean ratio to the class's Gd, is 1 within
 * the tolerance below.
 *
 * Tolerance. Averaged over K segments, each bin's estimate has relative variance about
 * 1.056/K (Hann, 50 % overlap: the overlapping segments' correlation is 0.167, adding
 * 2*0.167^2). Over B adjacent bins it falls by B/(1 + 2*0.444 + 2*0.028) = B/1.94 (the Hann
 * periodogram's correlation between bins 1 and 2 apart). So the relative standard deviation
 * is sigma = sqrt(1.056*1.94/(K*B)); the tolerance is 4 sigma (a Gaussian road fails it once
 * in 16,000 seeds) plus 1 % for the window's bias on the convex n^-2 spectrum (about
 * 3*(0.5 bin/n)^2, under 0.8 % at the lowest, 10 bins up). */
static void test_psd(void **state)
{
    (void)state;
    const double dx = 0.05;
    const tirenv_road_settings s = road('C', 20000, dx, 20250611);
    tirenv_profile *p = generate(&s);
    const size_t n = tirenv_profile_size(p);
    assert_int_equal(n, 400001);
    static double P[NS / 2];
    const size_t K = welch(tirenv_profile_z(p), n, dx, P);
    const double df = 1.0 / (NS * dx);
    const double freqs[] = {0.05, 0.1, 0.5, 1.0, 2.0};
    for (size_t i = 0; i < sizeof freqs / sizeof freqs[0]; i++) {
        const size_t k_lo = (size_t)ceil(0.8 * freqs[i] / df);
        const size_t k_hi = (size_t)floor(1.25 * freqs[i] / df);
        double ratio = 0;
        for (size_t k = k_lo; k <= k_hi; k++)
            ratio += P[k] / tirenv_road_psd(&s, (double)k * df);
        const double B = (double)(k_hi - k_lo + 1);
        ratio /= B;
        const double sigma = sqrt(1.056 * 1.94 / ((double)K * B));
        print_message("n = %.2f cycles/m: %zu segments x %.0f bins, estimate/Gd = %.4f, "
                      "tolerance %.3f\n", freqs[i], K, B, ratio, 4 * sigma + 0.01);
        assert_near(ratio, 1.0, 4 * sigma + 0.01, 0);
    }
    tirenv_profile_free(p);
}

/* Over a whole period (N = M vertices) Parseval holds exactly: the mean square about the mean
 * is the sum of the cosines' variances, sum Gd(n_k) dn (to round-off, 1e-9 relative). That sum
 * is the integral of Gd over the band, Gd(n0) n0^2 (1/n_min - 1/n_max), up to a Riemann sum's
 * error on a decreasing function sampled every dn: at most 2 dn Gd(n_min). */
static void test_parseval(void **state)
{
    (void)state;
    const double dx = 0.05;
    const tirenv_road_settings s = road('B', 65535 * dx, dx, 77);
    tirenv_profile *p = generate(&s);
    const size_t n = tirenv_profile_size(p);
    assert_int_equal(n, 65536);
    const double *z = tirenv_profile_z(p), dn = 1.0 / (65536 * dx);
    double mean = 0, ms = 0, sum = 0;
    for (size_t j = 0; j < n; j++)
        mean += z[j] / (double)n;
    for (size_t j = 0; j < n; j++)
        ms += (z[j] - mean) * (z[j] - mean) / (double)n;
    for (size_t k = 1; k < 32768; k++)
        sum += tirenv_road_psd(&s, (double)k * dn) * dn;
    const double gd0 = tirenv_iso8608_gd0('B'), n0 = TIRENV_ISO8608_N0;
    const double integral = gd0 * n0 * n0 * (1 / s.n_min - 1 / s.n_max);
    print_message("class B: rms %.3f mm, sum %.4g, integral %.4g m^2\n", sqrt(ms) * 1e3, sum,
                  integral);
    assert_near(ms, sum, 0, 1e-9);
    assert_near(sum, integral, 2 * dn * tirenv_road_psd(&s, s.n_min), 0);
    tirenv_profile_free(p);
}

/* Each class has 4 times the PSD of the one before, so with the same seed (same phases) its
 * road is exactly twice as high, bit for bit: every step of the generation scales exactly by
 * a power of two. The classes are ordered by roughness. */
static void test_class_ordering(void **state)
{
    (void)state;
    tirenv_profile *prev = NULL;
    double rms_prev = 0;
    for (char c = 'A'; c <= 'H'; c++) {
        const tirenv_road_settings s = road(c, 317.3, 0.0213, 9);
        tirenv_profile *p = generate(&s);
        const size_t n = tirenv_profile_size(p);
        const double *z = tirenv_profile_z(p);
        double rms = 0;
        for (size_t j = 0; j < n; j++)
            rms += z[j] * z[j] / (double)n;
        rms = sqrt(rms);
        if (prev) {
            const double *z_prev = tirenv_profile_z(prev);
            for (size_t j = 0; j < n; j++)
                assert_true(z[j] == 2 * z_prev[j]);
            assert_true(rms > rms_prev);
        }
        tirenv_profile_free(prev);
        prev = p;
        rms_prev = rms;
    }
    tirenv_profile_free(prev);
}

/* Same settings, same road bit for bit; another seed, another road. Vertices every dx from 0,
 * N = floor(length/dx) + 1, starting at z = 0. */
static void test_reproducible(void **state)
{
    (void)state;
    const tirenv_road_settings s = road('E', 123.4567, 0.0137, 31337);
    tirenv_profile *a = generate(&s), *b = generate(&s);
    const tirenv_road_settings s2 = road('E', 123.4567, 0.0137, 31338);
    tirenv_profile *c = generate(&s2);
    const size_t n = tirenv_profile_size(a);
    assert_int_equal(n, (size_t)floor(123.4567 / 0.0137) + 1);
    assert_int_equal(tirenv_profile_size(b), n);
    assert_memory_equal(tirenv_profile_x(a), tirenv_profile_x(b), n * sizeof(double));
    assert_memory_equal(tirenv_profile_z(a), tirenv_profile_z(b), n * sizeof(double));
    assert_true(memcmp(tirenv_profile_z(a), tirenv_profile_z(c), n * sizeof(double)) != 0);
    assert_true(tirenv_profile_z(a)[0] == 0.0);
    for (size_t j = 0; j < n; j += 997)
        assert_true(tirenv_profile_x(a)[j] == (double)j * 0.0137);
    tirenv_profile_free(a);
    tirenv_profile_free(b);
    tirenv_profile_free(c);
}

/* Refusals name the setting. */
static void test_errors(void **state)
{
    (void)state;
    struct {
        tirenv_road_settings s;
        const char *field;
    } cases[] = {
        {road('I', 100, 0.01, 1), "class"},
        {road('C', 0, 0.01, 1), "length"},
        {road('C', NAN, 0.01, 1), "length"},
        {road('C', 100, -0.01, 1), "dx"},
        {road('C', 100, 0.2, 1), "dx"},          /* above 1/(2*2.83) m: aliasing */
        {road('C', 1e6, 0.01, 1), "dx"},         /* 1e8 points */
        {road('C', 0.05, 0.01, 1), "length"},    /* dn = 12.5 cycles/m: nothing in the band */
        {road('C', 100, 0.01, 1), "band"},
        {road('C', 100, 0.01, 1), "waviness"},
        {road('C', 10, 0.01, 1), "waviness"},    /* the PSD overflows: NaN heights */
    };
    cases[7].s.n_min = 3.0;
    cases[8].s.waviness = -1;
    cases[9].s.waviness = 1e308;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        tirenv_profile *p = (tirenv_profile *)&cases; /* must come back NULL */
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        assert_int_equal(tirenv_road_iso8608(&cases[i].s, &p, &diag), TIRENV_EINVAL);
        print_message("case %zu: %s: %s\n", i, diag.field, diag.message);
        assert_null(p);
        assert_string_equal(diag.field, cases[i].field);
    }
    /* A count of 1e303 points in digits filled the message, its advice cut off. */
    tirenv_road_settings s = road('C', 1e300, 0.001, 1);
    tirenv_profile *p = NULL;
    tirenv_diag diag;
    assert_int_equal(tirenv_road_iso8608(&s, &p, &diag), TIRENV_EINVAL);
    assert_non_null(strstr(diag.message, "makes 1e+303 points, more than"));
    assert_non_null(strstr(diag.message, "raise dx"));
}

/* A generated road is a profile like any other: the cam and rigid models run over it. The
 * cam model, which bounds its scan by the road's highest vertex, agrees with the unbounded
 * tirenv_cam_tandem to round-off (TOL of test_cam.c: a pruned candidate cannot win). */
static void test_models_run(void **state)
{
    (void)state;
    const tirenv_road_settings s = road('D', 30, 0.01, 5);
    tirenv_profile *p = generate(&s);
    tirenv_tire tire = tirenv_tire_default();
    const double R0 = tire.springs.R0, G = 12000;
    const tirenv_cam_shape cam = {tire.cam.length * R0, tire.cam.height * R0, tire.cam.order};
    const tirenv_model_type *types[] = {tirenv_model_cam, tirenv_model_rigid};
    for (size_t i = 0; i < 2; i++) {
        tirenv_model *m = tirenv_model_alloc(types[i], &tire);
        assert_non_null(m);
        tirenv_diag diag;
        tirenv_flat f;
        assert_int_equal(tirenv_model_flat(m, G, &f, &diag), TIRENV_OK);
        assert_int_equal(tirenv_model_set(m, p, G, &diag), TIRENV_OK);
        for (double x = -1; x < 31; x += 0.0173) {
            tirenv_point pt;
            assert_int_equal(tirenv_model_eval(m, x, &pt, &diag), TIRENV_OK);
            assert_true(isfinite(pt.h) && isfinite(pt.fx));
            if (types[i] == tirenv_model_cam) {
                double w, tan_beta;
                assert_int_equal(tirenv_cam_tandem(p, &cam, tire.cam.shift * f.contact_length,
                                                   x, &w, &tan_beta), TIRENV_OK);
                assert_near(pt.h, w, 1e-14, 0);
            }
        }
        tirenv_model_free(m);
    }
    tirenv_profile_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_class_values),
        cmocka_unit_test(test_psd),
        cmocka_unit_test(test_parseval),
        cmocka_unit_test(test_class_ordering),
        cmocka_unit_test(test_reproducible),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_models_run),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
