/* SPDX-License-Identifier: Apache-2.0 */
/* Identification: the fitter recovers the parameters that generated the curves. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "tirenv/rng.h"
#include "testutil.h"
#include "tirenv/tirenv.h"
#include "tirenv/study.h"

enum { N_CASES = 6, N_POINTS = 61 };

/* Curves of the springs model at known c_r, c_b over cleats, on an x_N grid like the data
 * set's, with Gaussian noise sigma on h: what a rig would have measured of that tire. */
static void make_dataset_of(const tirenv_model_type *type, tirenv_dataset *ds,
                            tirenv_case cases[], const tirenv_tire *truth, double sigma,
                            unsigned long seed)
{
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, seed);
    tirenv_model *m = tirenv_model_alloc(type, truth);
    memset(ds, 0, sizeof *ds);
    ds->n = N_CASES;
    ds->cases = cases;
    for (size_t i = 0; i < N_CASES; ++i) {
        tirenv_case *c = &cases[i];
        char name[16];
        snprintf(name, sizeof name, "T%zu", i);
        tirenv_test_model_case(m, truth->springs.R0, tirenv_test_fit_design[i], name, N_POINTS,
                               c);
        for (size_t j = 0; j < N_POINTS; ++j)
            c->curve.h[j] += tirenv_rng_gaussian(rng, sigma);
    }
    tirenv_model_free(m);
    tirenv_rng_free(rng);
}

static void make_dataset(tirenv_dataset *ds, tirenv_case cases[], const tirenv_tire *truth,
                         double sigma, unsigned long seed)
{
    make_dataset_of(tirenv_model_springs, ds, cases, truth, sigma, seed);
}

static void free_dataset(tirenv_case cases[])
{
    for (size_t i = 0; i < N_CASES; ++i)
        tirenv_curve_free(&cases[i].curve);
}

/* From a start 40 % off, the fit lands within 3 reported standard errors of the truth (a
 * 99.7 % interval if the errors are right), the errors are not absurdly wide (under 5 % of the
 * value), and the residual RMS is the noise's sigma within 15 % (366 points). */
static void test_recovers_known_parameters(void **state)
{
    (void)state;
    tirenv_tire truth = tirenv_tire_default();
    truth.springs.c_r = 1.537e6;
    truth.springs.c_b = 1.371e4;
    truth.springs.dphi = M_PI / 180; /* 1 deg keeps the test quick; the fit does not care */
    static tirenv_case cases[N_CASES];
    tirenv_dataset ds;
    const double sigma = 2e-4;
    make_dataset(&ds, cases, &truth, sigma, 4242);

    tirenv_tire tire = truth;
    tire.springs.c_r = 0.6 * truth.springs.c_r;
    tire.springs.c_b = 1.4 * truth.springs.c_b;
    tirenv_fit_settings s = tirenv_fit_default();
    tirenv_fit_report rep;
    tirenv_diag diag;
    assert_int_equal(tirenv_fit(&ds, TIRENV_SPLIT_TRAIN, &s, &tire, &rep, &diag), TIRENV_OK);
    print_message("c_r %.6g +- %.2g (true %.6g), c_b %.6g +- %.2g (true %.6g), rms %.3g mm, "
                  "%zu iterations\n", rep.value[0], rep.std_error[0], truth.springs.c_r,
                  rep.value[1], rep.std_error[1], truth.springs.c_b, 1e3 * rep.rms,
                  rep.iterations);
    const double true_values[2] = {truth.springs.c_r, truth.springs.c_b};
    assert_int_equal(rep.n_params, 2);
    for (size_t i = 0; i < 2; ++i) {
        assert_true(rep.std_error[i] > 0);
        assert_true(rep.std_error[i] < 0.05 * true_values[i]);
        assert_near(rep.value[i], true_values[i], 3 * rep.std_error[i], 0);
    }
    assert_near(tire.springs.c_r, rep.value[0], 0, 0);
    assert_near(rep.rms, sigma, 0.15 * sigma, 0);
    assert_int_equal(rep.n_points, N_CASES * N_POINTS);
    free_dataset(cases);
}

/* No training case, no fit: an error, not a garbage tire. */
static void test_refuses_empty_split(void **state)
{
    (void)state;
    tirenv_tire truth = tirenv_tire_default();
    truth.springs.dphi = M_PI / 90;
    static tirenv_case cases[N_CASES];
    tirenv_dataset ds;
    make_dataset(&ds, cases, &truth, 0, 1);
    tirenv_tire tire = truth;
    tirenv_fit_settings s = tirenv_fit_default();
    tirenv_fit_report rep;
    tirenv_diag diag;
    assert_int_equal(tirenv_fit(&ds, TIRENV_SPLIT_VALIDATION, &s, &tire, &rep, &diag),
                     TIRENV_EINVAL);
    assert_true(strstr(diag.message, "too few") != NULL);
    /* No data set or tire: refused (they were dereferenced); no settings: the defaults, and
     * no report wanted: none written (both crashed). */
    assert_int_equal(tirenv_fit(NULL, TIRENV_SPLIT_TRAIN, &s, &tire, &rep, &diag), TIRENV_EINVAL);
    assert_int_equal(tirenv_fit(&ds, TIRENV_SPLIT_TRAIN, &s, NULL, &rep, &diag), TIRENV_EINVAL);
    assert_int_equal(tirenv_fit(&ds, TIRENV_SPLIT_VALIDATION, NULL, &tire, NULL, &diag),
                     TIRENV_EINVAL);
    assert_true(strstr(diag.message, "too few") != NULL);
    free_dataset(cases);
}

/* A fit the data drive to a bound says so: curves of a cam of ELLIPS_ORDER 1.002, just above
 * the bound 1 of a convex cam, pull the fitted order from 1.5 down to within 1 % of 1, and
 * the report flags it (and only it); curves of a cam of order 1.6 leave every parameter
 * inside. The fitted order is also checked against the truth, so the flag is not a fit
 * that merely wandered. */
static void test_reports_bound(void **state)
{
    (void)state;
    static const double order[2] = {1.002, 1.6};
    for (int k = 0; k < 2; ++k) {
        tirenv_tire truth = tirenv_tire_default();
        truth.cam.order = order[k];
        static tirenv_case cases[N_CASES];
        tirenv_dataset ds;
        make_dataset_of(tirenv_model_cam, &ds, cases, &truth, 0, 7);
        tirenv_tire tire = truth;
        tire.cam.order = 1.5;
        tire.cam.height *= 1.2;
        tirenv_fit_settings s = tirenv_fit_default();
        s.type = tirenv_model_cam;
        tirenv_fit_report rep;
        tirenv_diag diag;
        assert_int_equal(tirenv_fit(&ds, TIRENV_SPLIT_TRAIN, &s, &tire, &rep, &diag),
                         TIRENV_OK);
        print_message("truth ELLIPS_ORDER %.4g: fitted %.6g (flag %d), rms %.3g mm\n",
                      order[k], rep.value[3], rep.at_bound[3], 1e3 * rep.rms);
        assert_int_equal(rep.n_params, 4);
        assert_string_equal(rep.names[3], "ELLIPS_ORDER");
        assert_near(rep.value[3], order[k], 1e-3, 0);
        assert_int_equal(rep.at_bound[3], k == 0 ? -1 : 0);
        assert_true(rep.bound[3] == 1.0);
        for (size_t i = 0; i < 3; ++i)
            assert_int_equal(rep.at_bound[i], 0);
        /* the tallest training cleat: the range the shape was identified on */
        double H_max = 0;
        for (size_t i = 0; i < ds.n; ++i)
            if (ds.cases[i].split == TIRENV_SPLIT_TRAIN && ds.cases[i].H > H_max)
                H_max = ds.cases[i].H;
        assert_true(H_max > 0 && tire.cam.max_step == H_max);
        free_dataset(cases);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reports_bound),
        cmocka_unit_test(test_recovers_known_parameters),
        cmocka_unit_test(test_refuses_empty_split),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
