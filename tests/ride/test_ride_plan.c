/* SPDX-License-Identifier: Apache-2.0 */
/* The run plan tirenv ride and the Python module share (src/ride/ride_plan.c,
 * docs/models.md section 9.4): each speed's start, duration and settings, and the grid, from
 * the span's functions bit for bit; the names of the integrators and ways of enveloping; and
 * the requests it refuses, each naming its field. */
#include "testutil.h"

#include <math.h>
#include <string.h>

#include "tirenv/ride.h"

/* A two-vertex step from -0.1466 m to 0.2391 m: the span's start and end depend on these. */
static tirenv_profile *ground(void)
{
    const double x[] = {-0.1466, 0.2391}, z[] = {0.0, 0.0};
    tirenv_profile *p = tirenv_profile_alloc(2, x, z);
    assert_non_null(p);
    return p;
}

static tirenv_vehicle vehicle(void)
{
    tirenv_vehicle v = tirenv_vehicle_default();
    v.a = 1.4537;
    v.b = 0.9461;
    return v;
}

static void test_plan_is_the_spans(void **state)
{
    (void)state;
    tirenv_profile *p = ground();
    const tirenv_vehicle v = vehicle();
    const tirenv_ride_plan_params pp = tirenv_ride_plan_params_default();
    const tirenv_ride_settings d = tirenv_ride_default();
    assert_bits_equal(pp.dt, d.dt);
    assert_bits_equal(pp.tol, d.tol);
    assert_int_equal(pp.method, d.method);
    assert_true(isnan(pp.x_from) && isnan(pp.x_to));
    assert_bits_equal(pp.span.dx, tirenv_ride_span_default().dx);
    const double speeds[] = {1.1, 2.3};  /* slow: settles 3 m past; fast: 2 s of travel */
    tirenv_ride_plan plan;
    tirenv_diag diag;
    assert_int_equal(tirenv_ride_plan_make(&pp, &v, p, speeds, 2, &plan, &diag), TIRENV_OK);
    const double x_from = tirenv_ride_span_start(&pp.span, -0.1466);
    double x_to_max = x_from;
    for (size_t j = 0; j < 2; ++j) {
        const double x_to = tirenv_ride_span_end(&pp.span, &v, 0.2391, speeds[j]);
        const tirenv_ride_settings *s = &plan.run[j];
        assert_bits_equal(s->speed, speeds[j]);
        assert_bits_equal(s->x_front0, x_from);
        assert_bits_equal(s->duration, (x_to - x_from) / speeds[j]);
        assert_bits_equal(s->dt, pp.dt);
        assert_bits_equal(s->tol, pp.tol);
        assert_int_equal(s->method, pp.method);
        x_to_max = fmax(x_to_max, x_to);
    }
    double x0;
    const double n = tirenv_ride_span_grid(&pp.span, &v, x_from, x_to_max, &x0);
    assert_bits_equal(plan.x0, x0);
    assert_bits_equal(plan.dx, pp.span.dx);
    assert_true((double)plan.n == n);
    tirenv_profile_free(p);
}

/* Given ends are the runs' ends at every speed; the integrator and tolerance pass through. */
static void test_plan_takes_the_given_ends(void **state)
{
    (void)state;
    tirenv_profile *p = ground();
    const tirenv_vehicle v = vehicle();
    tirenv_ride_plan_params pp = tirenv_ride_plan_params_default();
    pp.x_from = -2.3817;
    pp.x_to = 4.1923;
    pp.span.dx = 0.0117;
    pp.dt = 0.00213;
    pp.method = TIRENV_RIDE_RK8PD;
    pp.tol = 1e-8;
    const double speeds[] = {2.3, 0.7};
    tirenv_ride_plan plan;
    tirenv_diag diag;
    assert_int_equal(tirenv_ride_plan_make(&pp, &v, p, speeds, 2, &plan, &diag), TIRENV_OK);
    for (size_t j = 0; j < 2; ++j) {
        assert_bits_equal(plan.run[j].x_front0, -2.3817);
        assert_bits_equal(plan.run[j].duration, (4.1923 - -2.3817) / speeds[j]);
        assert_int_equal(plan.run[j].method, TIRENV_RIDE_RK8PD);
        assert_bits_equal(plan.run[j].tol, 1e-8);
        assert_bits_equal(plan.run[j].dt, 0.00213);
    }
    double x0;
    const double n = tirenv_ride_span_grid(&pp.span, &v, -2.3817, 4.1923, &x0);
    assert_bits_equal(plan.x0, x0);
    assert_true((double)plan.n == n);
    tirenv_profile_free(p);
}

/* What the plan refuses, and the field it names. */
static void test_plan_e(void **state)
{
    (void)state;
    static const struct {
        const char *what;
        double dt, dx, x_from, x_to, speed;
        size_t n_speeds;
        const char *field, *says;
    } cases[] = {
        {"dt too coarse (100 Hz < 320 Hz)", 0.01, 0.005, NAN, NAN, 3, 1, "dt", "80 Hz"},
        {"dt zero", 0, 0.005, NAN, NAN, 3, 1, "dt", "> 0"},
        {"dt NaN", NAN, 0.005, NAN, NAN, 3, 1, "dt", "> 0"},
        {"dx zero", 0.001, 0, NAN, NAN, 3, 1, "dx", "> 0"},
        {"dx infinite", 0.001, INFINITY, NAN, NAN, 3, 1, "dx", "> 0"},
        {"speed zero", 0.001, 0.005, NAN, NAN, 0, 1, "speed", "> 0"},
        {"speed NaN", 0.001, 0.005, NAN, NAN, NAN, 1, "speed", "> 0"},
        {"no speed", 0.001, 0.005, NAN, NAN, 3, 0, "speed", "1 to 16"},
        {"17 speeds", 0.001, 0.005, NAN, NAN, 3, 17, "speed", "1 to 16"},
        {"end before start", 0.001, 0.005, 3, 1, 3, 1, "x_to", "end after it starts"},
        {"end at start", 0.001, 0.005, 1, 1, 3, 1, "x_to", "end after it starts"},
        /* 1e-6 m at 3 m/s: one sample at rest, every comfort figure 0 before */
        {"a run shorter than dt", 0.001, 0.005, 0.2391, 0.2391 + 1e-6, 3, 1, "x_to",
         "less than one output interval"},
        {"dt too fine (1e9 Hz > 1e5 Hz)", 1e-9, 0.005, NAN, NAN, 3, 1, "dt", "finer"},
        {"too many samples at the finest dt", 1e-5, 0.005, NAN, NAN, 0.01, 1, "speed",
         "samples"},
        {"a crawl of 1e7 s", 0.001, 0.005, NAN, NAN, 1e-6, 1, "speed", "samples"},
        {"a grid of 1.4e10 points", 0.001, 1e-9, NAN, NAN, 3, 1, "dx", "input positions"},
    };
    tirenv_profile *p = ground();
    const tirenv_vehicle v = vehicle();
    for (size_t i = 0; i < sizeof cases / sizeof *cases; ++i) {
        tirenv_ride_plan_params pp = tirenv_ride_plan_params_default();
        pp.dt = cases[i].dt;
        pp.span.dx = cases[i].dx;
        pp.x_from = cases[i].x_from;
        pp.x_to = cases[i].x_to;
        double speeds[TIRENV_RIDE_PLAN_RUNS + 1];
        for (size_t j = 0; j < TIRENV_RIDE_PLAN_RUNS + 1; ++j)
            speeds[j] = cases[i].speed;
        tirenv_ride_plan plan;
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        const int status = tirenv_ride_plan_make(&pp, &v, p, speeds, cases[i].n_speeds, &plan,
                                                 &diag);
        if (status != TIRENV_EINVAL || strcmp(diag.field, cases[i].field) != 0 ||
            !strstr(diag.message, cases[i].says))
            fail_msg("%s: status %d, field '%s', message '%s'", cases[i].what, status,
                     diag.field, diag.message);
    }
    tirenv_profile_free(p);
}

static void test_names(void **state)
{
    (void)state;
    static const char *const ways[] = {"static", "dynamic", "direct"};
    for (int e = 0; e < TIRENV_RIDE_N_ENVELOPING; ++e) {
        tirenv_ride_enveloping got = TIRENV_RIDE_N_ENVELOPING;
        assert_string_equal(tirenv_ride_enveloping_name((tirenv_ride_enveloping)e), ways[e]);
        assert_int_equal(tirenv_ride_enveloping_parse(ways[e], &got, NULL), TIRENV_OK);
        assert_int_equal(got, e);
    }
    assert_string_equal(tirenv_ride_enveloping_name(TIRENV_RIDE_N_ENVELOPING), "unknown");
    static const char *const methods[] = {"rk4", "rk8pd"};
    for (int m = 0; m < 2; ++m) {
        tirenv_ride_method got = (tirenv_ride_method)-1;
        assert_string_equal(tirenv_ride_method_name((tirenv_ride_method)m), methods[m]);
        assert_int_equal(tirenv_ride_method_parse(methods[m], &got, NULL), TIRENV_OK);
        assert_int_equal(got, m);
    }
    tirenv_diag diag;
    tirenv_ride_enveloping e;
    tirenv_ride_method m;
    assert_int_equal(tirenv_ride_enveloping_parse("Dynamic", &e, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "enveloping");
    assert_int_equal(tirenv_ride_method_parse("rk45", &m, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "method");
    assert_int_equal(tirenv_ride_method_parse(NULL, &m, &diag), TIRENV_EINVAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plan_is_the_spans),
        cmocka_unit_test(test_plan_takes_the_given_ends),
        cmocka_unit_test(test_plan_e),
        cmocka_unit_test(test_names),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
