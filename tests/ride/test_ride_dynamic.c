/* The ride with inputs that follow the tire load (docs/models.md section 9.5,
 * tirenv_ride_run_dynamic and tirenv_ride_run_input): with inputs that do not depend on the
 * load it is the static ride to round-off; with a model evaluated at each load it reports at
 * every sample the model's effective height at the load the tires then carry, exactly, and a
 * lifted tire's input is the lightest load's; tables over loads give the same within their
 * interpolation error, and the same comfort figures within a few tenths of a per cent.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/tirenv.h"

/* A tractor like the default one, written out so these tests do not depend on the file. */
static tirenv_vehicle tractor(void)
{
    tirenv_vehicle v = {.m = 4500, .I_y = 5000, .a = 1.45, .b = 0.95, .seat_x = -0.75,
                        .seat_h = 1.2, .g = 9.81};
    const tirenv_axle ax = {.tires = 2, .k_t = 342000, .c_t = 3000};
    v.front = v.rear = ax;
    return v;
}

/* The grid of the inputs: from 4 m before the cleat to 6 m after it at 5 mm. */
static const double grid_x0 = -4.0, grid_dx = 0.005;
enum { GRID_N = 2001 };

static tirenv_ride_settings cleat_run(double speed)
{
    tirenv_ride_settings s = tirenv_ride_default();
    s.speed = speed;
    s.x_front0 = -1.0;
    s.duration = 4.0 / speed;
    return s;
}

enum { N_FACTORS = TIRENV_RIDE_TABLE_LOADS };

static int samples_close(const tirenv_ride_sample *a, const tirenv_ride_sample *b, double rel)
{
    const double pa[] = {a->z, a->theta, a->w_front, a->w_rear, a->seat_az, a->F_front,
                         a->F_rear};
    const double pb[] = {b->z, b->theta, b->w_front, b->w_rear, b->seat_az, b->F_front,
                         b->F_rear};
    const double scale[] = {0.05, 0.05, 0.05, 0.05, 10, 5e4, 5e4};
    for (size_t i = 0; i < sizeof pa / sizeof pa[0]; ++i)
        if (!(fabs(pa[i] - pb[i]) <= rel * scale[i])) {
            print_message("field %zu: %.17g against %.17g\n", i, pa[i], pb[i]);
            return 0;
        }
    return 1;
}

/* A table of one row, or of rows all alike, is the static track: the same ride to round-off
 * (the tire force is summed in another order, n*(G0 + ...) against n*G0 + n*(...)), over a
 * cleat with lift-off, RK4 and RK8PD: every quantity within 1e-8 of its scale (the round-off
 * grows by some 1e6 through the kinks of lift-off and touch-down). */
static void test_constant_load_is_static(void **state)
{
    (void)state;
    const tirenv_vehicle v = tractor();
    const tirenv_tire tire = tirenv_test_tire_before_identify();
    tirenv_profile *cleat = tirenv_profile_cleat(0.30, 0.05);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &tire);
    tirenv_diag d;
    double *w[2], *rows[2];
    double G0[2], load3[2][3];
    for (int axle = 0; axle < 2; ++axle) {
        G0[axle] = tirenv_vehicle_tire_load(&v, axle);
        w[axle] = malloc(GRID_N * sizeof(double));
        rows[axle] = malloc(3 * GRID_N * sizeof(double));
        assert_true(w[axle] && rows[axle]);
        assert_int_equal(tirenv_ride_effective(m, cleat, G0[axle], grid_x0, grid_dx, GRID_N,
                                               w[axle], &d), TIRENV_OK);
        for (int j = 0; j < 3; ++j) {
            memcpy(rows[axle] + j * GRID_N, w[axle], GRID_N * sizeof(double));
            load3[axle][j] = G0[axle] * (0.5 + 0.5 * j);
        }
    }
    for (int method = 0; method < 2; ++method) {
        tirenv_ride_settings s = cleat_run(10 / 3.6);
        s.method = method ? TIRENV_RIDE_RK8PD : TIRENV_RIDE_RK4;
        const size_t n = tirenv_ride_n_samples(&s);
        tirenv_ride_sample *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b),
                           *c = malloc(n * sizeof *c);
        assert_true(a && b && c);
        const tirenv_ride_track tf = {grid_x0, grid_dx, GRID_N, w[0]};
        const tirenv_ride_track tr = {grid_x0, grid_dx, GRID_N, w[1]};
        const tirenv_ride_table one_f = {grid_x0, grid_dx, GRID_N, 1, &G0[0], w[0]};
        const tirenv_ride_table one_r = {grid_x0, grid_dx, GRID_N, 1, &G0[1], w[1]};
        const tirenv_ride_table three_f = {grid_x0, grid_dx, GRID_N, 3, load3[0], rows[0]};
        const tirenv_ride_table three_r = {grid_x0, grid_dx, GRID_N, 3, load3[1], rows[1]};
        assert_int_equal(tirenv_ride_run(&v, &tf, &tr, &s, a, &d), TIRENV_OK);
        assert_int_equal(tirenv_ride_run_dynamic(&v, &one_f, &one_r, &s, b, &d), TIRENV_OK);
        assert_int_equal(tirenv_ride_run_dynamic(&v, &three_f, &three_r, &s, c, &d), TIRENV_OK);
        size_t lifted = 0;
        for (size_t k = 0; k < n; ++k) {
            if (!samples_close(&a[k], &b[k], 1e-8) || !samples_close(&a[k], &c[k], 1e-8))
                fail_msg("sample %zu (t %g s): static F_front %.12g N, dynamic %.12g and "
                         "%.12g N", k, a[k].t, a[k].F_front, b[k].F_front, c[k].F_front);
            lifted += a[k].F_front == 0 || a[k].F_rear == 0;
        }
        assert_true(lifted > 10);  /* the cleat at 10 km/h lifts the tires off */
        free(a);
        free(b);
        free(c);
    }
    for (int axle = 0; axle < 2; ++axle) {
        free(w[axle]);
        free(rows[axle]);
    }
    tirenv_model_free(m);
    /* The rigid disc's road does not depend on the load: its table is one row, at G0. */
    tirenv_model *rigid = tirenv_model_alloc(tirenv_model_rigid, &tire);
    double rl[TIRENV_RIDE_TABLE_LOADS], *rw = malloc(TIRENV_RIDE_TABLE_LOADS * GRID_N *
                                                     sizeof *rw);
    size_t rows_rigid = 0;
    assert_non_null(rw);
    assert_int_equal(tirenv_ride_table_build(rigid, cleat, G0[0], grid_x0, grid_dx, GRID_N, rl,
                                             rw, &rows_rigid, NULL, 0, &d), TIRENV_OK);
    assert_int_equal(rows_rigid, 1);
    assert_true(rl[0] == G0[0]);
    free(rw);
    tirenv_model_free(rigid);
    tirenv_profile_free(cleat);
}

/* The direct input: a model evaluated at the position and the load (set_load, then three
 * evaluations for the height and its slope), for the test and as the reference. */
typedef struct {
    tirenv_model *m;
    double dx;
    size_t calls;
} direct;

static int direct_input(void *ctx, double x, double load, double *w, double *dw_dx,
                        tirenv_diag *diag)
{
    direct *d = ctx;
    tirenv_point lo, mid, hi;
    d->calls++;
    int status = tirenv_model_set_load(d->m, load, diag);
    if (!status)
        status = tirenv_model_eval(d->m, x - 0.5 * d->dx, &lo, diag);
    if (!status)
        status = tirenv_model_eval(d->m, x, &mid, diag);
    if (!status)
        status = tirenv_model_eval(d->m, x + 0.5 * d->dx, &hi, diag);
    *w = mid.h;
    *dw_dx = (hi.h - lo.h) / d->dx;
    return status;
}

/* The model's effective height at (x, load), from a model of its own set afresh. */
static double h_at(const tirenv_model_type *type, const tirenv_profile *p, double x,
                   double load)
{
    const tirenv_tire tire = tirenv_test_tire_before_identify();
    tirenv_model *m = tirenv_model_alloc(type, &tire);
    tirenv_diag d;
    tirenv_point pt;
    assert_int_equal(tirenv_model_set(m, p, load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_eval(m, x, &pt, &d), TIRENV_OK);
    tirenv_model_free(m);
    return pt.h;
}

/* Over a cleat at 10 km/h with the cam and the springs model evaluated during the run: at
 * samples where a tire carries a load within the range, the front input is the model's
 * effective height at that load (F_front / tires), as a model set at that load gives it (the
 * cam bit for bit; the springs within its equilibrium's tolerance); where the tire is off the
 * ground, the lightest load's. The load does swing (between under half and over 1.5 times
 * the static load), so the test is not vacuous. Then the tables: their run's samples against
 * the model at their own load within the tables' interpolation error (measured over this
 * cleat at random positions and loads: at most 1.1 mm for the springs, 0.55 mm for the cam;
 * as much comes from the 5 mm grid in x as from the load), and the r.m.s. seat acceleration of
 * the two runs within 1 %.
 * The sanitizer build (GCC's __SANITIZE_ADDRESS__) runs the springs model's rides over the
 * front axle's half of the cleat run only, x_front from -1 to 1 m (its crossing, lift-offs and
 * the largest load swing: measured 1.1 to 24.4 kN, 7 samples lifted off), and checks every
 * 17th sample instead of every 37th (32 checked): the same code, the springs model's direct
 * rides 40 % of the Release run's CPU (3.1 of 7.6 s; they were most of this test's time
 * under the sanitizers). The Release build runs the whole run, x_front -1 to 3 m. */
static void follows_the_load(size_t i)
{
    const tirenv_vehicle v = tractor();
    const tirenv_tire tire = tirenv_test_tire_before_identify();
    tirenv_profile *cleat = tirenv_profile_cleat(0.30, 0.05);
    const char *names[] = {"cam", "springs"};
    const tirenv_model_type *type = tirenv_model_type_find(names[i]);
    tirenv_ride_settings s = cleat_run(10 / 3.6);
    size_t every = 37;  /* the samples checked against the model at their load */
#ifdef __SANITIZE_ADDRESS__
    if (i == 1) {
        s.duration = 2.0 / s.speed;
        every = 17;
        print_message("sanitizer build: springs over x_front -1 to 1 m, every 17th sample "
                      "checked (the Release build: the whole run, every 37th)\n");
    }
#endif
    const size_t n = tirenv_ride_n_samples(&s);
    tirenv_ride_sample *dir = malloc(n * sizeof *dir), *tab = malloc(n * sizeof *tab);
    assert_true(dir && tab);
    direct dd[2];
    tirenv_ride_input fn[2];
    tirenv_ride_table table[2];
    double loads[2][N_FACTORS], *rows[2];
    tirenv_diag d;
    for (int axle = 0; axle < 2; ++axle) {
        const double G0 = tirenv_vehicle_tire_load(&v, axle);
        size_t m = 0;
        rows[axle] = malloc(N_FACTORS * GRID_N * sizeof(double));
        assert_non_null(rows[axle]);
        tirenv_model *tm = tirenv_model_alloc(type, &tire);
        assert_int_equal(tirenv_ride_table_build(tm, cleat, G0, grid_x0, grid_dx, GRID_N,
                                                 loads[axle], rows[axle], &m, NULL, 0, &d),
                         TIRENV_OK);
        assert_true(m >= 8);  /* the cam's contact law ends below 3 times the load */
        tirenv_model_free(tm);
        table[axle] = (tirenv_ride_table){grid_x0, grid_dx, GRID_N, m, loads[axle],
                                          rows[axle]};
        dd[axle] = (direct){tirenv_model_alloc(type, &tire), grid_dx, 0};
        assert_int_equal(tirenv_model_set(dd[axle].m, cleat, G0, &d), TIRENV_OK);
        fn[axle] = (tirenv_ride_input){direct_input, &dd[axle], loads[axle][0],
                                       loads[axle][m - 1], grid_dx};
    }
    if (tirenv_ride_run_input(&v, &fn[0], &fn[1], &s, dir, &d))
        fail_msg("%s direct: %s", names[i], d.message);
    assert_true(dd[0].calls > n);
    /* The library's direct input (tirenv_ride_direct_input, what tirenv ride --enveloping
     * direct runs): the tables' load range, and this test's run to the solver's tolerance
     * (its models start each solve from where the load probe left them, not from G0's). */
    tirenv_ride_sample *lib = malloc(n * sizeof *lib);
    assert_non_null(lib);
    tirenv_model *lm[2];
    tirenv_ride_direct ld[2];
    tirenv_ride_input lf[2];
    for (int axle = 0; axle < 2; ++axle) {
        const double G0 = tirenv_vehicle_tire_load(&v, axle);
        lm[axle] = tirenv_model_alloc(type, &tire);
        assert_int_equal(tirenv_model_set(lm[axle], cleat, G0, &d), TIRENV_OK);
        assert_int_equal(tirenv_ride_direct_input(lm[axle], G0, grid_dx, &ld[axle],
                                                  &lf[axle], &d), TIRENV_OK);
        assert_true(lf[axle].load_min == loads[axle][0]);
        assert_true(lf[axle].load_max == loads[axle][table[axle].m - 1]);
        assert_true(lf[axle].dx == grid_dx && lf[axle].ctx == &ld[axle]);
    }
    assert_int_equal(tirenv_ride_run_input(&v, &lf[0], &lf[1], &s, lib, &d), TIRENV_OK);
    for (size_t k = 0; k < n; ++k)
        assert_true(samples_close(&lib[k], &dir[k], 1e-9));
    tirenv_model_free(lm[0]);
    tirenv_model_free(lm[1]);
    free(lib);
    assert_int_equal(tirenv_ride_run_dynamic(&v, &table[0], &table[1], &s, tab, &d), 0);
    const double n_f = v.front.tires, G0_f = tirenv_vehicle_tire_load(&v, 0);
    double G_min = INFINITY, G_max = 0, worst = 0;
    size_t checked = 0, lifted = 0;
    for (size_t k = 50; k < n; k += every) {
        const double G = dir[k].F_front / n_f, x = dir[k].x_front;
        if (G == 0) { /* lifted off: the lightest load's input */
            const double want = h_at(type, cleat, x, loads[0][0]);
            assert_near(dir[k].w_front, want, i ? 1e-9 : 0, 0);
            ++lifted;
            continue;
        }
        if (!(G > loads[0][0] && G < loads[0][table[0].m - 1]))
            continue;
        const double want = h_at(type, cleat, x, G);
        assert_near(dir[k].w_front, want, i ? 1e-9 : 0, 0);
        G_min = fmin(G_min, G);
        G_max = fmax(G_max, G);
        ++checked;
        /* The table at the table run's own load and position. */
        const double G_t = tab[k].F_front / n_f;
        if (G_t > loads[0][0] && G_t < loads[0][table[0].m - 1]) {
            const double e = fabs(tab[k].w_front - h_at(type, cleat, tab[k].x_front, G_t));
            worst = fmax(worst, e);
        }
    }
    print_message("%s: %zu samples checked, tire load %.0f to %.0f N (static %.0f N), %zu "
                  "lifted off; tables within %.3g mm\n", names[i], checked, G_min, G_max,
                  G0_f, lifted, 1e3 * worst);
    assert_true(checked >= 20 && lifted >= 1);
    assert_true(G_min < 0.6 * G0_f && G_max > 1.5 * G0_f);
    assert_true(worst < (i ? 1.6e-3 : 0.7e-3));
    /* What the driver feels, over the same samples. */
    double s_dir = 0, s_tab = 0;
    for (size_t k = 0; k < n; ++k) {
        s_dir += dir[k].seat_az * dir[k].seat_az;
        s_tab += tab[k].seat_az * tab[k].seat_az;
    }
    assert_near(sqrt(s_tab / (double)n), sqrt(s_dir / (double)n), 0, 0.01);
    for (int axle = 0; axle < 2; ++axle) {
        free(rows[axle]);
        tirenv_model_free(dd[axle].m);
    }
    free(dir);
    free(tab);
    tirenv_profile_free(cleat);
}

/* The cam and the springs model apart, so that CTest can run them side by side. */
static void test_follows_the_load_cam(void **state)
{
    (void)state;
    follows_the_load(0);
}

static void test_follows_the_load_springs(void **state)
{
    (void)state;
    follows_the_load(1);
}

/* Refusals: a table whose loads do not increase, a function without a load range; an input
 * function's failure stops the run, naming the time and its own reason. */
typedef struct {
    double fail_after;  /* m */
} failing;

static int failing_input(void *ctx, double x, double load, double *w, double *dw_dx,
                         tirenv_diag *diag)
{
    (void)load;
    *w = 0;
    *dw_dx = 0;
    if (x > ((const failing *)ctx)->fail_after)
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "test", "made to fail at %g m", x);
    return TIRENV_OK;
}

static void test_errors(void **state)
{
    (void)state;
    const tirenv_vehicle v = tractor();
    tirenv_ride_settings s = cleat_run(2.0);
    const size_t n = tirenv_ride_n_samples(&s);
    tirenv_ride_sample *out = malloc(n * sizeof *out);
    double w[2 * GRID_N] = {0}, loads[2] = {9000, 8000};
    const tirenv_ride_table bad = {grid_x0, grid_dx, GRID_N, 2, loads, w};
    tirenv_diag d;
    assert_int_equal(tirenv_ride_run_dynamic(&v, &bad, &bad, &s, out, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "front");
    failing f = {0.5};
    tirenv_ride_input in = {failing_input, &f, 0, 20000, 0.005};
    assert_int_equal(tirenv_ride_run_input(&v, &in, &in, &s, out, &d), TIRENV_EINVAL);
    in.load_min = 1000;
    assert_int_equal(tirenv_ride_run_input(&v, &in, &in, &s, out, &d), TIRENV_ENOCONV);
    assert_non_null(strstr(d.message, "made to fail"));
    assert_non_null(strstr(d.message, "t = "));
    free(out);
}

/* The balance on a function input, by itself: at t = 0 the axle stands at rest at the height
 * of its input, so on a ramp through the start, w = s(G)*(x - x_front0), the tire load balances
 * G = G0 + c_t*V*s(G) (the damper alone). With s(G) = sigma*(G_bal/G)^3, sigma = (G_bal -
 * G0)/(c_t*V), that has the one root G_bal (g(G) - G decreases): the run's first sample carries
 * it within the solver's tolerance, found in 12 iterations. With a slope that jumps at G0
 * from 1 to -1e-6 the balance is on the jump, with g(G) - G of 6000 N on one side and 6 mN
 * on the other: regula falsi would need some 180 iterations to close its bracket on it, more
 * than its budget of 100 (the run stopped there with TIRENV_ENOCONV, as the springs model
 * over an ISO 8608 class F or H road did); past the budget the search bisects, and closes the
 * bracket on the jump, G0, to 1e-12 of the heaviest load within its 64 steps more. The rear
 * axle's input is flat. */
typedef struct {
    double x_c;          /* where the ramp passes 0, m */
    double G0, G_bal;    /* N */
    double sigma;        /* the smooth ramp's slope at G_bal (0: flat) */
    int jump;            /* the slope jumps at G0 instead */
    size_t calls;
} ramp;

static int ramp_input(void *ctx, double x, double load, double *w, double *dw_dx,
                      tirenv_diag *diag)
{
    ramp *r = ctx;
    (void)diag;
    r->calls++;
    const double s = r->jump ? (load < r->G0 ? 1 : -1e-6) : r->sigma * pow(r->G_bal / load, 3);
    *w = s * (x - r->x_c);
    *dw_dx = s;
    return TIRENV_OK;
}

static void test_balance_budget(void **state)
{
    (void)state;
    const tirenv_vehicle v = tractor();
    tirenv_ride_settings s = cleat_run(2.0);
    s.duration = 0;  /* the sample at t = 0 alone */
    tirenv_ride_sample out[1];
    const double G0 = tirenv_vehicle_tire_load(&v, 0), cV = v.front.c_t * s.speed;
    ramp front = {.x_c = s.x_front0, .G0 = G0, .G_bal = 1.0734 * G0,
                  .sigma = 0.0734 * G0 / cV};
    ramp rear = {.x_c = s.x_front0, .G0 = G0, .G_bal = G0, .sigma = 0};
    tirenv_ride_input fi = {ramp_input, &front, 1000, 20000, 0.005};
    tirenv_ride_input ri = {ramp_input, &rear, 1000, 20000, 0.005};
    tirenv_diag d;
    if (tirenv_ride_run_input(&v, &fi, &ri, &s, out, &d))
        fail_msg("smooth ramp: %s", d.message);
    assert_near(out[0].F_front / v.front.tires, front.G_bal, 1e-9 * G0, 0);
    assert_near(out[0].w_front, 0, 1e-15, 0);
    print_message("smooth balance: %zu evaluations\n", front.calls);
    assert_true(front.calls <= 1 + 2 + 15);  /* the steady start, the bracket, 12 iterations */
    front.jump = 1;
    front.calls = 0;
    if (tirenv_ride_run_input(&v, &fi, &ri, &s, out, &d))
        fail_msg("jump: %s", d.message);
    print_message("balance on the jump: %zu evaluations\n", front.calls);
    assert_true(front.calls > 1 + 2 + 100);  /* the bisection ran */
    assert_true(front.calls <= 1 + 2 + 100 + 64);
    assert_near(out[0].F_front / v.front.tires, G0, 1e-12 * 20000, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_constant_load_is_static),
        cmocka_unit_test(test_follows_the_load_cam),
        cmocka_unit_test(test_follows_the_load_springs),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_balance_budget),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
