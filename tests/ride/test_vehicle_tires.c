/* One tire file, one tire: the ride's tire spring k_t and damper c_t from the axle's tire file
 * (tirenv_tire_vertical_stiffness, tirenv_vehicle_tires; docs/models.md section 9.1) unless
 * the vehicle gives them. SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/cam.h"
#include "tirenv/ride.h"
#include "tirenv/tir.h"
#include "tirenv/vehicle_file.h"

#include <math.h>
#include <string.h>

/* A quadratic law unlike the default's in every key, at INFLPRES = NOMPRES (PFZ1's factor
 * exactly 1 although PFZ1 is not 0). */
static tirenv_tire quadratic_tire(void)
{
    tirenv_tire t = tirenv_tire_default();
    t.springs.R0 = 0.7133;
    t.cam.c_z = 383417.2;
    t.cam.fnomin = 17233.9;
    t.cam.q_fz2 = 23.71;
    t.cam.pfz1 = 0.413;
    t.ring.p = t.ring.p_nom = 1.37e5;
    return t;
}

/* VERTICAL_STIFFNESS is the law's tangent at FNOMIN (MF-Tyre 6.1's Q_FZ1 rule, section 7.3):
 * in closed form F_z = FNOMIN*(Q_FZ1*s + Q_FZ2*s^2) at s with that load has the tangent
 * FNOMIN/R0*sqrt(Q_FZ1^2 + 4*Q_FZ2) = VERTICAL_STIFFNESS. Through the law's deflection and
 * its tangent there, within a few roundings (1e-14). At INFLPRES = 1.3 NOMPRES the law is f
 * times as stiff at f times the load (f = 1 + PFZ1*0.3). */
static void test_stiffness_at_fnomin(void **state)
{
    (void)state;
    tirenv_tire t = quadratic_tire();
    assert_near(tirenv_tire_vertical_stiffness(&t, t.cam.fnomin), t.cam.c_z, 0, 1e-14);
    /* Stiffening: below FNOMIN softer, above it stiffer. */
    assert_true(tirenv_tire_vertical_stiffness(&t, 0.5 * t.cam.fnomin) < t.cam.c_z);
    assert_true(tirenv_tire_vertical_stiffness(&t, 1.5 * t.cam.fnomin) > t.cam.c_z);
    t.ring.p = 1.3 * t.ring.p_nom;
    const double f = 1 + t.cam.pfz1 * 0.3;
    assert_near(tirenv_tire_vertical_stiffness(&t, f * t.cam.fnomin), f * t.cam.c_z, 0, 1e-14);
}

/* The same stiffness as the law's own load: a central difference of tirenv_cam_vertical_load
 * about the deflection the law gives at the load. */
static void test_stiffness_is_the_laws_tangent(void **state)
{
    (void)state;
    const tirenv_tire t = quadratic_tire();
    const tirenv_cam_vertical v = {.R0 = t.springs.R0, .fnomin = t.cam.fnomin,
                                   .c_z = t.cam.c_z, .q_fz1 = 0, .q_fz2 = t.cam.q_fz2,
                                   .factor = 1};
    const double loads[] = {2371.9, 8737.03125, 13335.46875, 26130.7};
    for (size_t i = 0; i < sizeof loads / sizeof *loads; ++i) {
        const double rho = tirenv_cam_vertical_deflection(&v, loads[i]), h = 1e-6;
        assert_near(tirenv_cam_vertical_load(&v, rho), loads[i], 0, 1e-13);
        const double fd = (tirenv_cam_vertical_load(&v, rho + h) -
                           tirenv_cam_vertical_load(&v, rho - h)) / (2 * h);
        assert_near(tirenv_tire_vertical_stiffness(&t, loads[i]), fd, 0, 1e-8);
    }
}

/* Without Q_FZ2 (and FNOMIN) the law is linear: VERTICAL_STIFFNESS at every load, bit for
 * bit. */
static void test_linear_law_everywhere(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    t.cam.c_z = 209651.5;
    t.cam.fnomin = 0;
    t.cam.q_fz2 = 0;
    const double loads[] = {517.3, 4000, 8737.03125, 13335.46875, 61234.5};
    for (size_t i = 0; i < sizeof loads / sizeof *loads; ++i)
        assert_bits_equal(tirenv_tire_vertical_stiffness(&t, loads[i]), 209651.5);
}

/* The default tractor on its default tire: each axle its own k_t, the law's at its own static
 * load (8.74 and 13.34 kN: 311.3 and 342.6 kN/m, tractor.veh's header), not the 296 kN/m
 * both axles had before; c_t the tire's VERTICAL_DAMPING. */
static void test_default_tractor(void **state)
{
    (void)state;
    tirenv_vehicle v = tirenv_vehicle_default();
    assert_true(isnan(v.front.k_t) && isnan(v.front.c_t) && isnan(v.rear.k_t) &&
                isnan(v.rear.c_t));
    const tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    assert_int_equal(tirenv_vehicle_tires(&v, &t, &t, &d), TIRENV_OK);
    assert_bits_equal(v.front.k_t, tirenv_tire_vertical_stiffness(&t, 8737.03125));
    assert_bits_equal(v.rear.k_t, tirenv_tire_vertical_stiffness(&t, 13335.46875));
    assert_near(v.front.k_t, 311320.5, 0.1, 0);
    assert_near(v.rear.k_t, 342572.7, 0.1, 0);
    assert_bits_equal(v.front.c_t, 3000);
    assert_bits_equal(v.rear.c_t, 3000);
    assert_int_equal(tirenv_vehicle_check(&v, &d), TIRENV_OK);
}

/* What the vehicle gives wins over the tire file, key by key and axle by axle. */
static void test_vehicle_overrides(void **state)
{
    (void)state;
    tirenv_vehicle v = tirenv_vehicle_default();
    tirenv_diag d;
    assert_int_equal(tirenv_vehicle_set(&v, "FRONT_AXLE.TIRE_STIFFNESS=283117.3", &d), 0);
    assert_int_equal(tirenv_vehicle_set(&v, "REAR_AXLE.TIRE_DAMPING=2371.9", &d), 0);
    const tirenv_tire t = tirenv_tire_default();
    assert_int_equal(tirenv_vehicle_tires(&v, &t, &t, &d), TIRENV_OK);
    assert_bits_equal(v.front.k_t, 283117.3);
    assert_bits_equal(v.front.c_t, 3000);
    assert_bits_equal(v.rear.k_t, tirenv_tire_vertical_stiffness(&t, 13335.46875));
    assert_bits_equal(v.rear.c_t, 2371.9);
    /* Set once, kept: a second call changes nothing. */
    const tirenv_vehicle once = v;
    assert_int_equal(tirenv_vehicle_tires(&v, &t, &t, &d), TIRENV_OK);
    assert_memory_equal(&once, &v, sizeof v);
}

/* The published 205/60R15 file (data/tires/205-60R15-mfswift.tir) has a linear law of its own
 * VERTICAL_STIFFNESS 209651.5 N/m and no VERTICAL_DAMPING: a vehicle on it gets that
 * stiffness, and without the vehicle's TIRE_DAMPING is refused, naming the axle and both
 * keys, that axle unchanged. */
static void test_users_mf_tyre_file(void **state)
{
    (void)state;
    tirenv_tire car = tirenv_tire_default();
    tirenv_diag d;
    assert_int_equal(tirenv_tir_read(TIRENV_DATA_DIR "/tires/205-60R15-mfswift.tir", &car, &d),
                     TIRENV_OK);
    assert_true(isnan(car.k_z));
    const tirenv_tire tractor = tirenv_tire_default();
    tirenv_vehicle v = tirenv_vehicle_default();
    assert_int_equal(tirenv_vehicle_tires(&v, &tractor, &car, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "REAR_AXLE.TIRE_DAMPING");
    assert_non_null(strstr(d.message, "VERTICAL_DAMPING"));
    assert_non_null(strstr(d.message, "TIRE_DAMPING in [REAR_AXLE]"));
    assert_true(isnan(v.rear.k_t) && isnan(v.rear.c_t));

    v = tirenv_vehicle_default();
    assert_int_equal(tirenv_vehicle_set(&v, "REAR_AXLE.TIRE_DAMPING=500", &d), 0);
    assert_int_equal(tirenv_vehicle_tires(&v, &tractor, &car, &d), TIRENV_OK);
    assert_bits_equal(v.rear.k_t, 209651.5);
    assert_true(fabs(v.rear.k_t - v.front.k_t) > 1e5);  /* not the tractor tire's */
    assert_bits_equal(v.rear.c_t, 500);
}

/* A law that carries no such load is refused naming the axle's stiffness key and its load;
 * the vehicle's own TIRE_STIFFNESS is then the way out. Q_FZ2 = -300 peaks at FNOMIN*(1 +
 * k^2/1200), k = VERTICAL_STIFFNESS*R0/FNOMIN: 20.9 kN, below the rear tires' 22.2 kN of a
 * 7.5 t tractor (the front's 14.6 kN it carries). */
static void test_law_without_the_load(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    t.cam.q_fz2 = -300;
    tirenv_vehicle v = tirenv_vehicle_default();
    v.m = 7500;
    tirenv_diag d;
    assert_int_equal(tirenv_vehicle_tires(&v, &t, &t, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "REAR_AXLE.TIRE_STIFFNESS");
    assert_non_null(strstr(d.message, "at the static tire load 22225.8 N"));
    assert_true(v.front.k_t > 0 && isnan(v.rear.k_t));
    v.rear.k_t = 3e5;
    assert_int_equal(tirenv_vehicle_tires(&v, &t, &t, &d), TIRENV_OK);
}

/* A load that the law would carry only with the tire crushed by its whole free radius or more
 * (the centre at or below the ground, which the cam refuses: cam_patch) gives no stiffness:
 * the ride of a 300 t tractor took its rear tires' k_t from the default law at 889 kN, a
 * deflection of 1.17 R0, and ran (exit 0). The default law reaches R0 at 677.6 kN; the front
 * tires' 582.5 kN it carries. The linear law of 209651.5 N/m reaches R0 = 0.68 m at
 * 142563 N. */
static void test_load_past_the_free_radius(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    tirenv_vehicle v = tirenv_vehicle_default();
    v.m = 3e5;
    tirenv_diag d;
    assert_int_equal(tirenv_vehicle_tires(&v, &t, &t, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "REAR_AXLE.TIRE_STIFFNESS");
    assert_non_null(strstr(d.message, "at the static tire load 889031 N"));
    assert_non_null(strstr(d.message, "free radius"));
    assert_true(v.front.k_t > 0 && isnan(v.rear.k_t));
    assert_true(isnan(tirenv_tire_vertical_stiffness(&t, 677.7e3)));
    assert_true(tirenv_tire_vertical_stiffness(&t, 677.5e3) > 0);
    t.cam.c_z = 209651.5;
    t.cam.fnomin = 0;
    t.cam.q_fz2 = 0;
    assert_true(isnan(tirenv_tire_vertical_stiffness(&t, 0.6801 * 209651.5)));
    assert_bits_equal(tirenv_tire_vertical_stiffness(&t, 0.6799 * 209651.5), 209651.5);
}

/* The ride refuses a vehicle whose tires were never set, naming the key. */
static void test_ride_needs_the_tires(void **state)
{
    (void)state;
    const tirenv_vehicle v = tirenv_vehicle_default();
    tirenv_ride_settings s = tirenv_ride_default();
    s.duration = 0.1;
    tirenv_ride_sample out[128];
    const double w[2] = {0, 0};
    const tirenv_ride_track track = {.x0 = -100, .dx = 200, .n = 2, .w = w};
    tirenv_diag d;
    assert_int_equal(tirenv_ride_run(&v, &track, &track, &s, out, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "FRONT_AXLE.TIRE_STIFFNESS");
    assert_non_null(strstr(d.message, "tirenv_vehicle_tires"));
    tirenv_vehicle w_only_rear_damping = v;  /* the rest given: the one left NAN is named */
    w_only_rear_damping.front.k_t = w_only_rear_damping.rear.k_t = 3e5;
    w_only_rear_damping.front.c_t = 3000;
    assert_int_equal(tirenv_ride_run(&w_only_rear_damping, &track, &track, &s, out, &d),
                     TIRENV_EINVAL);
    assert_string_equal(d.field, "REAR_AXLE.TIRE_DAMPING");
    const tirenv_tire t = tirenv_tire_default();
    tirenv_vehicle u = v;
    assert_int_equal(tirenv_vehicle_tires(NULL, &t, &t, NULL), TIRENV_EINVAL);
    assert_int_equal(tirenv_vehicle_tires(&u, NULL, &t, NULL), TIRENV_EINVAL);
    assert_true(isnan(u.front.k_t));
}

/* The vehicle file: without TIRE_STIFFNESS and TIRE_DAMPING (tractor.veh) both are NAN, even
 * read over a vehicle that had values; an old file with them still reads them. */
static void test_vehicle_file_keys(void **state)
{
    (void)state;
    tirenv_vehicle v = tirenv_vehicle_default();
    v.front.k_t = v.rear.k_t = 296000;
    v.front.c_t = v.rear.c_t = 3000;
    tirenv_diag d;
    assert_int_equal(tirenv_vehicle_read(TIRENV_DATA_DIR "/vehicles/tractor.veh", &v, &d), 0);
    assert_true(isnan(v.front.k_t) && isnan(v.front.c_t) && isnan(v.rear.k_t) &&
                isnan(v.rear.c_t));
    assert_int_equal(tirenv_vehicle_read(TIRENV_DATA_DIR "/../tests/fuzz/corpus/veh/tractor.veh",
                                         &v, &d), 0);
    assert_bits_equal(v.front.k_t, 342000);
    assert_bits_equal(v.rear.c_t, 3000);
    /* A read that fails leaves them as they were. */
    assert_int_equal(tirenv_vehicle_read(TIRENV_DATA_DIR "/vehicles/no-such.veh", &v, &d),
                     TIRENV_EIO);
    assert_bits_equal(v.front.k_t, 342000);
    assert_bits_equal(v.rear.c_t, 3000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stiffness_at_fnomin),
        cmocka_unit_test(test_stiffness_is_the_laws_tangent),
        cmocka_unit_test(test_linear_law_everywhere),
        cmocka_unit_test(test_default_tractor),
        cmocka_unit_test(test_vehicle_overrides),
        cmocka_unit_test(test_users_mf_tyre_file),
        cmocka_unit_test(test_law_without_the_load),
        cmocka_unit_test(test_load_past_the_free_radius),
        cmocka_unit_test(test_ride_needs_the_tires),
        cmocka_unit_test(test_vehicle_file_keys),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
