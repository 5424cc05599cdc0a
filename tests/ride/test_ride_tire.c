/* The ride's tire force is its tire file's vertical law (src/ride/ride_tire.c, docs/models.md
 * section 9.3), not the law's tangent at the static load; a vehicle's TIRE_STIFFNESS keeps the
 * linear spring. SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "ride/ride_impl.h"
#include "tirenv/cam.h"
#include "tirenv/ride.h"

/* The default tractor on a tire, its springs and dampers the tire's (tirenv_vehicle_tires). */
static tirenv_vehicle tractor_on(const tirenv_tire *t)
{
    tirenv_vehicle v = tirenv_vehicle_default();
    tirenv_diag d;
    assert_int_equal(tirenv_vehicle_tires(&v, t, t, &d), TIRENV_OK);
    return v;
}

/* The front axle's tire of the default tractor on the default tire (Q_FZ2 28.7). */
static tirenv_ride__tire default_front(tirenv_vehicle *v)
{
    const tirenv_tire t = tirenv_tire_default();
    *v = tractor_on(&t);
    assert_true(v->front.law.factor > 0);
    tirenv_ride__tire tire;
    tirenv_diag d;
    assert_int_equal(tirenv_ride__tire_set(&tire, &v->front, tirenv_vehicle_tire_load(v, 0),
                                           "front", &d),
                     TIRENV_OK);
    return tire;
}

/* At rest the law carries the static load: exactly in the force (its F_z(rho0) is taken out),
 * and to 1e-9 in the law itself at its deflection rho0. Either side by 20 mm the force is the
 * law's, not the tangent's: the law is progressive, and there the two differ by 444 N per tire
 * (f*FNOMIN*Q_FZ2*(0.02/R0)^2 = 17900*28.7*(0.02/0.68)^2), 4e7 times the tolerance. The force
 * goes through tirenv_ride__axle on a flat track, as the ride computes it. */
static void test_force_is_the_law(void **state)
{
    (void)state;
    tirenv_vehicle v;
    const tirenv_ride__tire t = default_front(&v);
    const double G0 = t.G0, k_t = v.front.k_t;
    assert_near(tirenv_cam_vertical_load(&v.front.law, t.rho0), G0, 0, 1e-9);
    assert_bits_equal(tirenv_ride__tire_load(&t, 0, 0), G0);

    const double w_flat[2] = {0, 0};
    const tirenv_ride_track flat = {.x0 = -1, .dx = 2, .n = 2, .w = w_flat};
    tirenv_ride__input in;
    assert_int_equal(tirenv_ride__input_init(&in, "front", &flat, NULL, NULL), TIRENV_OK);
    const double dz[] = {-0.02, 0.02};  /* the axle 20 mm lower: the tire 20 mm deeper */
    for (size_t i = 0; i < 2; ++i) {
        double w, w_dot, F;
        tirenv_diag d;
        assert_int_equal(tirenv_ride__axle(&in, &t, 2.7, 0.3, dz[i], 0, &w, &w_dot, &F, &d),
                         TIRENV_OK);
        const double rho = t.rho0 - dz[i];
        const double law = t.n * tirenv_cam_vertical_load(&v.front.law, rho);
        const double tangent = t.n * (G0 + k_t * -dz[i]);
        assert_near(F, law, 0, 1e-9);
        assert_true(law - tangent > 2 * 400); /* stiffer than the tangent either way */
    }
    tirenv_ride__input_free(&in);
}

/* The tire lifts off where its deflection ends, rho = 0, not where the tangent's line would
 * cross zero (G0/k_t below the static deflection: 28.1 mm, against the law's rho0 of 31.6 mm,
 * the law being softer than its tangent towards lift-off): nothing at rho = 0, a little just
 * above, and nothing just below even while the axle falls towards the ground (the damper of a
 * tire in the air does not push); where the tangent's tire has lifted off, the law's still
 * carries 3.6 mm of deflection. */
static void test_lift_off_at_zero_deflection(void **state)
{
    (void)state;
    tirenv_vehicle v;
    const tirenv_ride__tire t = default_front(&v);
    const double d_off = -t.rho0;
    assert_true(tirenv_ride__tire_force(&t, d_off, 0) == 0);
    assert_true(tirenv_ride__tire_force(&t, d_off + 1e-9, 0) > 0);
    assert_true(tirenv_ride__tire_force(&t, d_off - 1e-9, 0.5) == 0);
    const double d_tangent = -t.G0 / v.front.k_t;
    assert_near(d_tangent, -0.0281, 1e-4, 0);
    assert_near(t.rho0, 0.0316, 1e-4, 0);
    assert_true(tirenv_ride__tire_force(&t, d_tangent, 0) > 1000);
}

/* A linear law (Q_FZ2 0) is today's spring of its VERTICAL_STIFFNESS: the law's force equals
 * G0 + k_t*d + c_t*d_dot to a few roundings of its largest term (the law forms
 * f*c_z*(rho0 + d) - f*c_z*rho0 where the spring forms k_t*d, each term within half an ulp,
 * so 4*DBL_EPSILON of the largest term bounds the difference) wherever the tire touches the
 * ground; with FNOMIN given, Q_FZ1 = sqrt((c_z*R0/FNOMIN)^2) is c_z*R0/FNOMIN to an ulp or two
 * more, 16*DBL_EPSILON. */
static void test_linear_law_is_the_spring(void **state)
{
    (void)state;
    for (int with_fnomin = 0; with_fnomin < 2; ++with_fnomin) {
        tirenv_tire tire = tirenv_tire_default();
        tire.cam.q_fz2 = 0;
        tire.cam.c_z = 283117.3;
        tire.cam.fnomin = with_fnomin ? 17233.9 : 0;
        tirenv_vehicle v = tractor_on(&tire);
        tirenv_vehicle given = v;
        given.front.law = given.rear.law = (tirenv_cam_vertical){0};
        assert_near(v.front.k_t, 283117.3, 0, 1e-14);
        for (int axle = 0; axle < 2; ++axle) {
            tirenv_ride__tire law, spring;
            const double G0 = tirenv_vehicle_tire_load(&v, axle);
            assert_int_equal(tirenv_ride__tire_set(&law, axle ? &v.rear : &v.front, G0, "", NULL),
                             0);
            assert_int_equal(tirenv_ride__tire_set(&spring, axle ? &given.rear : &given.front,
                                                   G0, "", NULL),
                             0);
            assert_true(law.has_law && !spring.has_law);
            const double eps = (with_fnomin ? 16 : 4) * DBL_EPSILON;
            for (double d = -0.9 * law.rho0; d < 0.06; d += 0.00731)
                for (double d_dot = -0.4; d_dot < 0.5; d_dot += 0.2371) {
                    const double big = law.G0 + fabs(law.k_t * d) + fabs(law.c_t * d_dot) +
                                       law.k_t * law.rho0;
                    assert_near(tirenv_ride__tire_force(&law, d, d_dot),
                                tirenv_ride__tire_force(&spring, d, d_dot), eps * 2 * big, 0);
                }
        }
    }
}

/* The derivatives the ride relies on, by central differences with h = 1 um: the spring's
 * energy grows by its force less G0 (what tirenv_ride_energy adds up), and the law's tangent
 * at the static load is the k_t the linear checks use. The balance itself uses no derivative
 * (regula falsi). Tolerances: the energy W is cubic in d, so its difference carries
 * h^2/6*F'' = h^2/6 * n*2*FNOMIN*Q_FZ2/R0^2 = 7.4e-7 N of truncation and some eps*1e3 J/h =
 * 2e-7 N of rounding: 1e-5 N holds them ten times over. The load is quadratic: its central
 * difference is exact but for rounding, eps*G0/h = 2e-6 N/m, 1e-11 of k_t: 1e-9 relative. */
static void test_derivatives(void **state)
{
    (void)state;
    tirenv_vehicle v;
    const tirenv_ride__tire t = default_front(&v);
    const double h = 1e-6;
    for (double d = -0.021; d < 0.05; d += 0.00917) {
        const double fd = (tirenv_ride__tire_energy(&t, d + h) -
                           tirenv_ride__tire_energy(&t, d - h)) / (2 * h);
        const double F = t.n * (tirenv_ride__tire_load(&t, d, 0) - t.G0);
        assert_true(fabs(F) > 100); /* not a zero gradient */
        assert_near(fd, F, 1e-5, 0);
    }
    const double k_fd = (tirenv_ride__tire_load(&t, h, 0) - tirenv_ride__tire_load(&t, -h, 0)) /
                        (2 * h);
    assert_near(k_fd, v.front.k_t, 0, 1e-9);
}

/* A table whose rows move the road down as the load grows (3 rows, 6 mm over 1.5*G0): on a
 * segment the law's g(G) curves, and the balance regula falsi finds satisfies G = g(G) to
 * 1e-9 of G0, with the road interpolated at G as the ride does; the linear spring's line
 * meets it elsewhere. */
static void test_table_balance_under_the_law(void **state)
{
    (void)state;
    tirenv_vehicle v;
    const tirenv_ride__tire t = default_front(&v);
    const double G0 = t.G0, load[3] = {0.5 * G0, G0, 2 * G0};
    const double h[3] = {0.004, 0.0, -0.002};
    double rows[3 * 2];
    for (size_t j = 0; j < 3; ++j)
        rows[2 * j] = rows[2 * j + 1] = h[j];
    const tirenv_ride_table table = {.x0 = -1, .dx = 2, .n = 2, .m = 3, .w = rows, .load = load};
    tirenv_ride__input in;
    assert_int_equal(tirenv_ride__input_init(&in, "front", NULL, &table, NULL), TIRENV_OK);
    const double z_a[] = {-0.0237, -0.0081, 0.0043, 0.0119};
    for (size_t i = 0; i < sizeof z_a / sizeof *z_a; ++i) {
        double w, w_dot, F;
        tirenv_diag d;
        assert_int_equal(tirenv_ride__axle(&in, &t, 2.7, 0.1, z_a[i], 0, &w, &w_dot, &F, &d),
                         TIRENV_OK);
        const double G = F / t.n;
        assert_true(G > load[0] && G < load[2]);
        const size_t j = G < load[1] ? 0 : 1;
        const double s = (G - load[j]) / (load[j + 1] - load[j]);
        const double w_G = h[j] + s * (h[j + 1] - h[j]);
        assert_near(w, w_G, 1e-15, 0);
        assert_near(tirenv_ride__tire_load(&t, w_G - z_a[i], 0), G, 1e-9 * G0, 0);
    }
    tirenv_ride__input_free(&in);
}

/* A law whose deflection under the static load is not found (a Q_FZ2 < 0 law peaks below the
 * load) stops the ride before it starts, naming the axle's tire file. */
static void test_law_without_the_load(void **state)
{
    (void)state;
    tirenv_vehicle v = tirenv_vehicle_default();
    const tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    assert_int_equal(tirenv_vehicle_tires(&v, &t, &t, &d), TIRENV_OK);
    v.m = 4500 * 40;  /* after the tires: a load far beyond the peak of the law below */
    v.rear.law.q_fz2 = -40;
    tirenv_ride__tire tire;
    assert_int_equal(tirenv_ride__tire_set(&tire, &v.rear, tirenv_vehicle_tire_load(&v, 1),
                                           "REAR_AXLE.TIRE_FILE", &d),
                     TIRENV_EINVAL);
    assert_string_equal(d.field, "REAR_AXLE.TIRE_FILE");
    /* Past the peak the law holds it, never falling. */
    const tirenv_cam_vertical *law = &v.rear.law;
    const double rho_p = -law->R0 * tirenv_cam_vertical_q1(law) / (2 * law->q_fz2);
    const double F_p = tirenv_cam_vertical_contact(law, rho_p);
    assert_true(F_p > tirenv_cam_vertical_contact(law, 0.9 * rho_p));
    assert_bits_equal(tirenv_cam_vertical_contact(law, 1.5 * rho_p), F_p);
    assert_near(tirenv_cam_vertical_work(law, 1.5 * rho_p) - tirenv_cam_vertical_work(law, rho_p),
                0.5 * rho_p * F_p, 0, 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_force_is_the_law),
        cmocka_unit_test(test_lift_off_at_zero_deflection),
        cmocka_unit_test(test_linear_law_is_the_spring),
        cmocka_unit_test(test_derivatives),
        cmocka_unit_test(test_table_balance_under_the_law),
        cmocka_unit_test(test_law_without_the_load),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
