/* The network as a model outside its trained ranges (docs/models.md sections 6.3 and 12):
 * refused by tirenv_model_set naming the input, its value and the range, unless allowed by
 * tirenv_model_set_extrapolate, which evaluates it with a warning.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include "tirenv/rng.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/tirenv.h"

/* A 4-8-1 network with random weights, trained (as far as its ranges say) on l_c 0.28 to
 * 0.43 m, heights 0.025 to 0.1 m and lengths 0.05 to 0.3 m, as the embedded data set. */
static tirenv_nn *net(void)
{
    const tirenv_nn_topology t = tirenv_nn_topology_default();
    tirenv_nn *nn = tirenv_nn_alloc(&t);
    assert_non_null(nn);
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 2385);
    tirenv_nn_init_weights(nn, rng);
    tirenv_rng_free(rng);
    const double mean[4] = {0.5, 0.35, 0.06, 0.17}, std[4] = {0.36, 0.05, 0.027, 0.08};
    const double lo[4] = {-0.25, 0.28, 0.025, 0.05}, hi[4] = {1, 0.43, 0.1, 0.3};
    tirenv_diag diag;
    assert_int_equal(tirenv_nn_set_scaling(nn, mean, std, 0.02, 0.02, &diag), 0);
    assert_int_equal(tirenv_nn_set_input_range(nn, lo, hi, &diag), 0);
    return nn;
}

/* Sets the model on p at contact length l_c; returns the status. */
static int set_at(tirenv_model *m, const tirenv_profile *p, double l_c, tirenv_diag *diag)
{
    double load;
    assert_int_equal(tirenv_model_load_for_contact_length(m, l_c, &load, diag), 0);
    tirenv_diag_clear(diag);
    return tirenv_model_set(m, p, load, diag);
}

/* Over a cleat: inside the ranges no warning; a cleat 0.2 m high, or a contact length of
 * 0.25 m, refused by default naming the input, the value and the range; allowed, evaluated
 * with one warning naming it. */
static void test_cleat(void **state)
{
    (void)state;
    tirenv_nn *nn = net();
    tirenv_diag diag;
    tirenv_profile *ok = tirenv_profile_cleat(0.2, 0.05), *tall = tirenv_profile_cleat(0.2, 0.2);
    for (int allow = -1; allow <= 1; ++allow) {  /* -1: the default, never set */
        tirenv_model *m = tirenv_test_nn_model(nn, allow);
        assert_int_equal(set_at(m, ok, 0.33, &diag), 0);
        assert_string_equal(tirenv_model_warnings(m), "");
        const int status = set_at(m, tall, 0.33, &diag);
        if (allow == 1) {
            assert_int_equal(status, 0);
            assert_non_null(strstr(tirenv_model_warnings(m), "obstacle height 0.2 m"));
            tirenv_point p;
            assert_int_equal(tirenv_model_eval(m, -0.1, &p, &diag), 0);
            assert_true(isfinite(p.h));
        } else {
            assert_int_equal(status, TIRENV_ERANGE);
            assert_string_equal(diag.field, "obstacle height");
            assert_non_null(strstr(diag.message, "0.2 m is outside"));
            assert_non_null(strstr(diag.message, "0.025 to 0.1 m"));
            tirenv_point p;  /* the model is unset */
            assert_int_equal(tirenv_model_eval(m, -0.1, &p, &diag), TIRENV_EINVAL);
        }
        assert_int_equal(set_at(m, ok, 0.25, &diag), allow == 1 ? 0 : TIRENV_ERANGE);
        if (allow != 1) {
            assert_string_equal(diag.field, "contact length");
            assert_non_null(strstr(diag.message, "0.28 to 0.43 m"));
        }
        tirenv_model_free(m);
    }
    tirenv_profile_free(ok);
    tirenv_profile_free(tall);
    tirenv_nn_free(nn);
}

/* Over a profile: two bumps within the ranges pass; one 1 cm bump (below the trained
 * heights: its curve would be the 2.5 cm cleat's scaled) is refused naming its position and
 * height; allowed, it draws the warning that counts the scaled bumps. A wall 0.3 m high is
 * clamped when allowed, refused otherwise. */
static void test_profile(void **state)
{
    (void)state;
    tirenv_nn *nn = net();
    tirenv_diag diag;
    const double x[] = {-3, -1.05, -1.05, -0.95, -0.95, 0.95, 0.95, 1.05, 1.05, 3};
    double z[] = {0, 0, 0.05, 0.05, 0, 0, 0.04, 0.04, 0, 0};
    tirenv_profile *two = tirenv_profile_alloc(10, x, z);
    z[6] = z[7] = 0.01;
    tirenv_profile *low = tirenv_profile_alloc(10, x, z);
    z[6] = z[7] = 0.3;
    tirenv_profile *wall = tirenv_profile_alloc(10, x, z);
    assert_true(two && low && wall);
    tirenv_model *m = tirenv_test_nn_model(nn, 0);
    assert_int_equal(set_at(m, two, 0.33, &diag), 0);
    assert_string_equal(tirenv_model_warnings(m), "");
    assert_int_equal(set_at(m, low, 0.33, &diag), TIRENV_ERANGE);
    assert_string_equal(diag.field, "obstacle height");
    assert_non_null(strstr(diag.message, "the obstacle at x = 1 m (0.95 to 1.05 m, 0.01 m high"));
    assert_non_null(strstr(diag.message, "(1 of 2 obstacles are)"));
    assert_int_equal(set_at(m, wall, 0.33, &diag), TIRENV_ERANGE);
    assert_non_null(strstr(diag.message, "0.3 m high"));
    tirenv_model_set_extrapolate(m, 1);
    assert_int_equal(set_at(m, low, 0.33, &diag), 0);
    assert_non_null(strstr(tirenv_model_warnings(m), "1 of 2 obstacles lower than the lowest"));
    assert_int_equal(set_at(m, wall, 0.33, &diag), 0);
    assert_non_null(strstr(tirenv_model_warnings(m), "1 heights above 0.1 m"));
    /* Allowed again off: refused again (the setting is kept across sets, not latched). */
    tirenv_model_set_extrapolate(m, 0);
    assert_int_equal(set_at(m, low, 0.33, &diag), TIRENV_ERANGE);
    tirenv_model_free(m);
    tirenv_profile_free(two);
    tirenv_profile_free(low);
    tirenv_profile_free(wall);
    tirenv_nn_free(nn);
}

/* The physical models have no trained range: the setting changes nothing. */
static void test_other_models(void **state)
{
    (void)state;
    const tirenv_tire t = tirenv_tire_default();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &t);
    tirenv_model_set_extrapolate(m, 1);
    tirenv_profile *tall = tirenv_profile_cleat(0.2, 0.2);
    tirenv_diag diag;
    assert_int_equal(tirenv_model_set(m, tall, 1e4, &diag), 0);
    tirenv_profile_free(tall);
    tirenv_model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cleat),
        cmocka_unit_test(test_profile),
        cmocka_unit_test(test_other_models),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
