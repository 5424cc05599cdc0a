/* The pitch-plane tractor (src/ride/ride.c) against static equilibrium, the analytic frequency
 * response of its quarter models, energy conservation without damping, and its solvers.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>

#include "tirenv/ride.h"

static const double pi = 3.14159265358979323846;

/* A tractor like the default one, written out so these tests do not depend on the file. */
static tirenv_vehicle tractor(int suspended)
{
    tirenv_vehicle v = {.m = 4500, .I_y = 5000, .a = 1.45, .b = 0.95, .seat_x = -0.75,
                        .seat_h = 1.2, .g = 9.81};
    const tirenv_axle ax = {.tires = 2, .k_t = 342000, .c_t = 3000};
    v.front = v.rear = ax;
    if (suspended) {
        v.front.k_s = 200000;
        v.front.c_s = 8000;
        v.front.m_a = 400;
    }
    return v;
}

/* A track of n heights w(x) = f(x) from x0 at spacing dx (heap; free with free(t.w)). */
static tirenv_ride_track track(double x0, double dx, size_t n, double (*f)(double, const void *),
                               const void *arg)
{
    double *w = malloc(n * sizeof *w);
    assert_non_null(w);
    for (size_t k = 0; k < n; ++k)
        w[k] = f(x0 + (double)k * dx, arg);
    return (tirenv_ride_track){.x0 = x0, .dx = dx, .n = n, .w = w};
}

static double constant(double x, const void *arg)
{
    (void)x;
    return *(const double *)arg;
}

/* At rest on a flat road, at any height, nothing moves and the tires carry the weight. */
static void test_static_equilibrium(void **state)
{
    (void)state;
    for (int suspended = 0; suspended < 2; ++suspended) {
        for (int level = 0; level < 2; ++level) {
            const tirenv_vehicle v = tractor(suspended);
            const double h = level ? 0.1 : 0.0;
            tirenv_ride_track t = track(-10, 0.01, 2001, constant, &h);
            tirenv_ride_settings s = tirenv_ride_default();
            s.speed = 3;
            s.duration = 2;
            const size_t n = tirenv_ride_n_samples(&s);
            assert_int_equal(n, 2001);
            tirenv_ride_sample *out = malloc(n * sizeof *out);
            assert_non_null(out);
            tirenv_diag diag;
            assert_int_equal(tirenv_ride_run(&v, &t, &t, &s, out, &diag), 0);
            const double W = (v.m + (suspended ? v.front.m_a : 0)) * v.g;
            for (size_t k = 0; k < n; ++k) {
                /* Preloads and weights cancel to round-off of forces near 4e4 N: 1e-11 N/kg. */
                assert_near(out[k].z, h, 1e-12, 0);
                assert_near(out[k].theta, 0, 1e-12, 0);
                assert_near(out[k].z_a, h, 1e-12, 0);
                assert_near(out[k].az, 0, 1e-10, 0);
                assert_near(out[k].atheta, 0, 1e-10, 0);
                assert_near(out[k].seat_az, 0, 1e-10, 0);
                assert_near(out[k].F_front + out[k].F_rear, W, 1e-8 * W, 0);
            }
            /* The static split: the rear carries a/(a+b) of the body. */
            assert_near(out[n - 1].F_rear, v.m * v.g * v.a / (v.a + v.b), 1e-8 * W, 0);
            free((double *)t.w);
            free(out);
        }
    }
}

typedef struct {
    double A, f, V, x0; /* amplitude m, frequency Hz, speed m/s, where the sine starts */
} sine_road;

static double sine(double x, const void *arg)
{
    const sine_road *r = arg;
    return x <= r->x0 ? 0 : r->A * sin(2 * pi * r->f * (x - r->x0) / r->V);
}

static double flat(double x, const void *arg)
{
    (void)x;
    (void)arg;
    return 0;
}

/* Road-to-body transfer function of the front quarter: the 1-DOF mass m_f on the tire, or
 * the 2-DOF quarter car with a suspended axle. */
static double complex quarter_response(const tirenv_vehicle *v, double m_f, double f)
{
    const double w = 2 * pi * f;
    const double complex Kt = v->front.tires * (v->front.k_t + I * w * v->front.c_t);
    if (!(v->front.k_s > 0))
        return Kt / (Kt - m_f * w * w);
    const double complex Ks = v->front.k_s + I * w * v->front.c_s;
    const double complex axle = Kt + Ks - v->front.m_a * w * w, body = Ks - m_f * w * w;
    return Kt * Ks / (axle * body - Ks * Ks);
}

/* With I_y = m a b (dynamic index 1) the body's motions above the two axles decouple into
 * two independent quarter models of masses m b/l and m a/l. Driving the front with a sine,
 * the steady body motion above the front axle must follow the quarter model's analytic
 * response. Tolerance: the input is Steffen-interpolated on a 0.5 mm grid, >= 200 points per
 * wavelength here, which flattens the sine near its extrema by at most ~(2 pi/200)^2/8 =
 * 1.2e-4 relative; RK4 at 1 ms adds (omega dt)^4 < 1e-5; the 20 s of run-in leave e^-20 of
 * the start transient. 1e-3 relative (and 1e-3 rad in phase) bounds both with margin, and a
 * wrong mass, stiffness or damping term shows up at several per cent. */
static void test_quarter_response(void **state)
{
    (void)state;
    const double freqs[] = {0.7, 2.0, 3.3, 5.0, 9.0};
    for (int suspended = 0; suspended < 2; ++suspended) {
        tirenv_vehicle v = tractor(suspended);
        v.I_y = v.m * v.a * v.b;
        const double m_f = v.m * v.b / (v.a + v.b);
        for (size_t i = 0; i < sizeof freqs / sizeof freqs[0]; ++i) {
            const sine_road road = {.A = 0.001, .f = freqs[i], .V = 1.0, .x0 = 0.0};
            tirenv_ride_settings s = tirenv_ride_default();
            s.speed = road.V;
            s.duration = 40;
            const double dx = 5e-4;
            const size_t n_road = (size_t)(45.0 / dx);
            tirenv_ride_track front = track(-1, dx, n_road, sine, &road);
            tirenv_ride_track rear = track(-5, dx, n_road, flat, NULL);
            const size_t n = tirenv_ride_n_samples(&s);
            tirenv_ride_sample *out = malloc(n * sizeof *out);
            assert_non_null(out);
            tirenv_diag diag;
            assert_int_equal(tirenv_ride_run(&v, &front, &rear, &s, out, &diag), 0);
            /* Project z + a theta onto sin and cos over whole periods after t = 20 s. */
            const double T = 1 / road.f;
            const size_t k0 = (size_t)(20.0 / s.dt);
            const size_t m = (size_t)(floor((s.duration - 20.0) / T) * T / s.dt);
            double cs = 0, sn = 0;
            for (size_t k = k0; k < k0 + m; ++k) {
                const double t = out[k].t, z_fb = out[k].z + v.a * out[k].theta;
                sn += z_fb * sin(2 * pi * road.f * t);
                cs += z_fb * cos(2 * pi * road.f * t);
            }
            const double complex got = (2.0 / (double)m) * (sn + I * cs) / road.A;
            const double complex want = quarter_response(&v, m_f, road.f);
            assert_near(cabs(got), cabs(want), 0, 1e-3);
            assert_near(carg(got / want), 0, 1e-3, 0);
            /* Decoupled: nothing reaches the body above the rear axle. */
            double rear_max = 0;
            for (size_t k = k0; k < n; ++k)
                rear_max = fmax(rear_max, fabs(out[k].z - v.b * out[k].theta));
            assert_true(rear_max < 1e-9);
            free((double *)front.w);
            free((double *)rear.w);
            free(out);
        }
    }
}

static double cos_bump(double x, const void *arg)
{
    (void)arg;
    return x > 1 && x < 1.5 ? 0.005 * (1 - cos(2 * pi * (x - 1) / 0.5)) : 0;
}

/* Undamped, after both axles have left a bump the vertical energy stays constant: RK4's
 * energy error for these frequencies (omega dt <= 0.05) is ~(omega dt)^6/144 per step, < 1e-6
 * of E over the 5000 steps; 1e-5 bounds it, while the bump itself changes E by O(1). With the
 * tire file's progressive law (the default tire's) as with a linear spring: the energy adds up
 * the law's own work. */
static void test_energy(void **state)
{
    (void)state;
    for (int c = 0; c < 4; ++c) {
        const int suspended = c & 1, law = c >> 1;
        tirenv_vehicle v = tractor(suspended);
        if (law) {
            const tirenv_tire tire = tirenv_tire_default();
            v.front.k_t = v.rear.k_t = NAN;
            assert_int_equal(tirenv_vehicle_tires(&v, &tire, &tire, NULL), 0);
            assert_true(v.front.law.factor > 0 && v.front.law.q_fz2 > 0);
        }
        v.front.c_t = v.rear.c_t = v.front.c_s = 0;
        tirenv_ride_track t = track(-5, 0.001, 20001, cos_bump, NULL);
        tirenv_ride_settings s = tirenv_ride_default();
        s.speed = 2;
        s.duration = 8;
        const size_t n = tirenv_ride_n_samples(&s);
        tirenv_ride_sample *out = malloc(n * sizeof *out);
        assert_non_null(out);
        tirenv_diag diag;
        assert_int_equal(tirenv_ride_run(&v, &t, &t, &s, out, &diag), 0);
        assert_true(tirenv_ride_energy(&v, &out[0]) == 0);
        /* The rear axle leaves the bump at x_front = 1.5 + 2.4 m, t = 1.95 s. */
        const size_t k0 = (size_t)(2.0 / s.dt);
        const double E0 = tirenv_ride_energy(&v, &out[k0]);
        assert_true(E0 > 1.0);
        for (size_t k = k0; k < n; ++k) {
            assert_true(out[k].F_front > 0 && out[k].F_rear > 0); /* never lifted off */
            assert_near(tirenv_ride_energy(&v, &out[k]), E0, 0, 1e-5);
        }
        free((double *)t.w);
        free(out);
    }
}

static double cleat(double x, const void *arg)
{
    (void)arg;
    return x >= 0 && x <= 0.3 ? 0.1 : 0;
}

/* Over a sharp cleat at speed the tires lift off; forces stay >= 0 and finite; RK4 at 1 ms
 * (substepped to half the 2 mm grid) agrees with adaptive RK8PD at 1e-10 within 0.5 % of the
 * peak seat acceleration (measured 0.09 %; without the substeps it was 8 %: the input's
 * kinks at grid points and lift-off make the right-hand side non-smooth). */
static void test_cleat_liftoff_and_solvers(void **state)
{
    (void)state;
    const tirenv_vehicle v = tractor(1);
    tirenv_ride_track t = track(-5, 0.002, 7501, cleat, NULL);
    tirenv_ride_settings s = tirenv_ride_default();
    s.speed = 5;
    s.x_front0 = -1;
    s.duration = 1.5;
    const size_t n = tirenv_ride_n_samples(&s);
    tirenv_ride_sample *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    assert_non_null(a);
    assert_non_null(b);
    tirenv_diag diag;
    assert_int_equal(tirenv_ride_run(&v, &t, &t, &s, a, &diag), 0);
    s.method = TIRENV_RIDE_RK8PD;
    assert_int_equal(tirenv_ride_run(&v, &t, &t, &s, b, &diag), 0);
    double peak = 0, dmax = 0;
    size_t lifted = 0;
    for (size_t k = 0; k < n; ++k) {
        assert_true(isfinite(a[k].seat_az) && a[k].F_front >= 0 && a[k].F_rear >= 0);
        lifted += a[k].F_front == 0 || a[k].F_rear == 0;
        peak = fmax(peak, fabs(b[k].seat_az));
        dmax = fmax(dmax, fabs(a[k].seat_az - b[k].seat_az));
    }
    assert_true(lifted > 0);
    assert_true(peak > 5);
    assert_true(dmax < 0.005 * peak);
    free((double *)t.w);
    free(a);
    free(b);
}

static void test_invalid(void **state)
{
    (void)state;
    const tirenv_vehicle v = tractor(0);
    const double zero = 0, w_nan[2] = {0, NAN};
    tirenv_ride_track t = track(0, 0.01, 10, constant, &zero);
    const tirenv_ride_track one = {.x0 = 0, .dx = 0.01, .n = 1, .w = t.w};
    const tirenv_ride_track bad = {.x0 = 0, .dx = 0.01, .n = 2, .w = w_nan};
    tirenv_ride_sample out[20];
    tirenv_diag diag;
    tirenv_ride_settings s = tirenv_ride_default();
    s.duration = 0.01;
    assert_int_equal(tirenv_ride_run(&v, &t, &t, &s, out, &diag), 0);
    assert_int_equal(tirenv_ride_run(&v, &one, &t, &s, out, &diag), TIRENV_EINVAL);
    assert_int_equal(tirenv_ride_run(&v, &t, &bad, &s, out, &diag), TIRENV_EINVAL);
    s.speed = 0;
    assert_int_equal(tirenv_ride_run(&v, &t, &t, &s, out, &diag), TIRENV_EINVAL);
    s = tirenv_ride_default();
    s.duration = 0.01;  /* out[] holds 20 samples, should the check ever let dt through */
    s.dt = -1;
    assert_int_equal(tirenv_ride_run(&v, &t, &t, &s, out, &diag), TIRENV_EINVAL);
    tirenv_vehicle heavy = v;
    heavy.m = -1;
    s = tirenv_ride_default();
    s.duration = 0.01;
    assert_int_equal(tirenv_ride_run(&heavy, &t, &t, &s, out, &diag), TIRENV_EINVAL);
    free((double *)t.w);
}

/* Speeds as tirenv ride --speed and the Python module take them: m/s bare or with "m/s",
 * km/h times 1/3.6 (the CLI's conversion, bit for bit); the rest refused naming the field. */
static void test_speed_parse(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        double v;          /* m/s; 0: refused */
    } cases[] = {
        {"2.5", 2.5},      {"2.5m/s", 2.5},   {"10km/h", 10 * (1 / 3.6)},
        {"7.25km/h", 7.25 * (1 / 3.6)},       {"1e-3", 1e-3},   {"0", 0},
        {"-3", 0},         {"km/h", 0},       {"m/s", 0},       {"", 0},
        {"3 km/h", 0},     {"3kmh", 0},       {"inf", 0},       {"nan", 0},
        {"1e400", 0},      {"3,4", 0},        {"fast", 0},
        {"123456789012345678901234567890123456789012345678901234567890123km/h", 0},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        double v = -1;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        const int status = tirenv_ride_speed_parse(cases[k].text, &v, &d);
        if (cases[k].v > 0) {
            assert_int_equal(status, TIRENV_OK);
            assert_bits_equal(v, cases[k].v);
        } else {
            assert_int_equal(status, TIRENV_EINVAL);
            assert_string_equal(d.field, "speed");
            assert_true(v == -1);  /* untouched */
        }
    }
    assert_int_equal(tirenv_ride_speed_parse(NULL, NULL, NULL), TIRENV_EINVAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_static_equilibrium),
        cmocka_unit_test(test_speed_parse),
        cmocka_unit_test(test_quarter_response),
        cmocka_unit_test(test_energy),
        cmocka_unit_test(test_cleat_liftoff_and_solvers),
        cmocka_unit_test(test_invalid),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
