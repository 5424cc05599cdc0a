/* What the ride refuses (src/ride/ride_checks.c, docs/models.md section 9.6): an RK4 step too
 * long for the vehicle's fastest mode, a vehicle whose static loads drown the dynamic tire
 * forces in rounding, and samples that are not finite.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ride/ride_impl.h"
#include "tirenv/ride.h"

static tirenv_vehicle tractor(double k_t, int suspended)
{
    tirenv_vehicle v = {.m = 4500, .I_y = 5000, .a = 1.45, .b = 0.95, .seat_x = -0.75,
                        .seat_h = 1.2, .g = 9.81};
    const tirenv_axle ax = {.tires = 2, .k_t = k_t, .c_t = 3000};
    v.front = v.rear = ax;
    if (suspended) {
        v.front.k_s = 200000;
        v.front.c_s = 8000;
        v.front.m_a = 400;
    }
    return v;
}

/* Without damping and with the CG midway (a = b), heave and pitch decouple: the modes are
 * +-i*sqrt(2 n k/m) and +-i*sqrt(n k (a^2 + b^2)/I), to round-off of the eigensolver. With
 * a suspended axle on stiff tires the fastest mode is the axle hopping on its tires and
 * suspension, sqrt((n k_t + k_s)/m_a); the body couples in by about k_s/(n k_t) = 1e-3,
 * hence 1 %. */
static void test_fastest_mode(void **state)
{
    (void)state;
    tirenv_vehicle v = tractor(341235.7, 0);
    v.a = v.b = 1.2;
    v.front.c_t = v.rear.c_t = 0;
    v.I_y = 2345.6;
    double lambda = 0;
    tirenv_diag diag;
    assert_int_equal(tirenv_ride__fastest_mode(&v, &lambda, &diag), 0);
    const double heave = sqrt(2 * 2 * v.front.k_t / v.m);
    const double pitch = sqrt(2 * v.front.k_t * (v.a * v.a + v.b * v.b) / v.I_y);
    assert_true(pitch > heave);
    assert_near(lambda, pitch, 0, 1e-10);

    v = tractor(1e8, 1);
    assert_int_equal(tirenv_ride__fastest_mode(&v, &lambda, &diag), 0);
    assert_near(lambda, sqrt((2 * v.front.k_t + v.front.k_s) / v.front.m_a), 0, 0.01);
}

static double step_up(double x, const void *arg)
{
    (void)arg;
    return x > 1.0 ? 0.05 : 0.0;
}

static int ride(const tirenv_vehicle *v, tirenv_ride_method method, double dt,
                tirenv_diag *diag)
{
    const size_t n = 1001;
    double *w = malloc(n * sizeof *w);
    assert_non_null(w);
    for (size_t k = 0; k < n; ++k)
        w[k] = step_up(-2 + 0.005 * (double)k, NULL);
    const tirenv_ride_track t = {.x0 = -2, .dx = 0.005, .n = n, .w = w};
    tirenv_ride_settings s = tirenv_ride_default();
    s.speed = 5.0;
    s.duration = 0.5;
    s.dt = dt;
    s.method = method;
    s.tol = 1e-8;
    tirenv_ride_sample *out = malloc(tirenv_ride_n_samples(&s) * sizeof *out);
    assert_non_null(out);
    tirenv_diag_clear(diag);
    const int status = tirenv_ride_run(v, &t, &t, &s, out, diag);
    free(out);
    free(w);
    return status;
}

/* Tires of 1e9 N/m (the audit's case): RK4 at dt 1 ms (2 substeps at 5 m/s on a 5 mm grid,
 * h*|lambda| = 0.57) is refused naming dt, its step and the limit; RK8PD runs; RK4 runs at
 * the dt the message gives. The default tires pass with a wide margin. */
static void test_rk4_step_refused(void **state)
{
    (void)state;
    tirenv_diag diag;
    const tirenv_vehicle stiff = tractor(1e9, 0);
    assert_int_equal(ride(&stiff, TIRENV_RIDE_RK4, 1e-3, &diag), TIRENV_ERANGE);
    assert_string_equal(diag.field, "dt");
    assert_non_null(strstr(diag.message, "0.0005 s (dt 0.001 s in 2 substeps)"));
    assert_non_null(strstr(diag.message, "rk8pd"));
    const char *at_most = strstr(diag.message, "dt of at most ");
    assert_non_null(at_most);
    const double dt_max = strtod(at_most + strlen("dt of at most "), NULL);
    double lambda = 0;
    assert_int_equal(tirenv_ride__fastest_mode(&stiff, &lambda, &diag), 0);
    assert_near(dt_max, RK4_MAX_H_LAMBDA / lambda, 0, 2e-3);  /* printed to 3 digits */
    assert_int_equal(ride(&stiff, TIRENV_RIDE_RK8PD, 1e-3, &diag), 0);
    assert_int_equal(ride(&stiff, TIRENV_RIDE_RK4, 0.99 * dt_max, &diag), 0);
    for (int suspended = 0; suspended < 2; ++suspended) {
        const tirenv_vehicle v = tractor(296000, suspended);
        assert_int_equal(ride(&v, TIRENV_RIDE_RK4, 1e-3, &diag), 0);
        assert_int_equal(tirenv_ride__fastest_mode(&v, &lambda, &diag), 0);
        assert_true(5e-4 * lambda < 0.1 * RK4_MAX_H_LAMBDA);
    }
}

/* MASS = 1e30 left every seat acceleration exactly 0 and a crest factor of 0/0 with exit 0:
 * the static deflection (6.6e24 m) is refused by the vehicle check, naming the axle. A heavy
 * but resolvable vehicle passes. */
static void test_static_loads(void **state)
{
    (void)state;
    tirenv_diag diag;
    tirenv_vehicle v = tractor(296000, 0);
    v.m = 1e30;
    assert_int_equal(tirenv_vehicle_check(&v, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "FRONT_AXLE.TIRE_STIFFNESS");
    assert_non_null(strstr(diag.message, "unphysical"));
    assert_int_equal(ride(&v, TIRENV_RIDE_RK4, 1e-3, &diag), TIRENV_EINVAL);
    v.m = 4.5e5;
    assert_int_equal(tirenv_vehicle_check(&v, &diag), 0);
}

static void test_finite_sample(void **state)
{
    (void)state;
    tirenv_diag diag;
    tirenv_ride_sample s = {.t = 1.25, .x_front = 3.5};
    assert_int_equal(tirenv_ride__finite_sample(&s, &diag), 0);
    s.seat_az = NAN;
    assert_int_equal(tirenv_ride__finite_sample(&s, &diag), TIRENV_ENOCONV);
    assert_non_null(strstr(diag.message, "t = 1.25 s (x_front = 3.5 m)"));
    s.seat_az = 0;
    s.F_rear = INFINITY;
    assert_int_equal(tirenv_ride__finite_sample(&s, &diag), TIRENV_ENOCONV);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fastest_mode),
        cmocka_unit_test(test_rk4_step_refused),
        cmocka_unit_test(test_static_loads),
        cmocka_unit_test(test_finite_sample),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
