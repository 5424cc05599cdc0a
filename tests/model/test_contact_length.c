/* SPDX-License-Identifier: Apache-2.0 */
/* The springs model's flat-ground contact length (docs/models.md section 1.3): the length of
 * ground its tread touches, shorter than the chord of its free circle by what the interradial
 * springs lift off; the height of a contact length found by the search every deformable model
 * shares (deformable.c); the rigid disc's and the point's contact length still the chord. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "testutil.h"
#include "tirenv/tirenv.h"

static tirenv_model *springs_of(double c_r, double c_b, tirenv_springs_contact contact)
{
    tirenv_tire t = tirenv_tire_default();
    t.springs.c_r = c_r;
    t.springs.c_b = c_b;
    t.springs.contact = contact;
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
    assert_non_null(m);
    return m;
}

static double chord(double R0, double z) { return 2 * sqrt(R0 * R0 - z * z); }

/* Over loads of 2.385 to 61.3 kN (the default tire's): the contact length grows with the
 * load and is shorter than the chord at its deflection (0.37 of it at 2.4 kN, where the
 * interradial springs lift most of the chord off, 0.6 at 30 kN), and the load
 * found for it again is the load to 1e-9 relative (the search stops within 1e-12 m of the
 * height, 4e-7 N at the stiffness 4e5 N/m: 1e-11 relative at 2.4 kN; 1e-9 leaves margin for
 * the flat solve's own tolerance on the load). */
static void test_touched_length(void **state)
{
    (void)state;
    const tirenv_tire t = tirenv_tire_default();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
    assert_non_null(m);
    tirenv_diag d;
    double last = 0;
    for (double G = 2385.0; G < 62000; G *= 1.31) {
        tirenv_flat f;
        assert_int_equal(tirenv_model_flat(m, G, &f, &d), TIRENV_OK);
        const double c = chord(t.springs.R0, f.z_flat);
        print_message("%8.0f N: deflection %.2f mm, contact length %.4f m, chord %.4f m\n", G,
                      1e3 * f.deflection, f.contact_length, c);
        assert_true(f.contact_length > last);
        assert_true(f.contact_length > 0 && f.contact_length < c);
        last = f.contact_length;
        double G2;
        assert_int_equal(tirenv_model_load_for_contact_length(m, f.contact_length, &G2, &d),
                         TIRENV_OK);
        assert_near(G2, G, 0, 1e-9);
    }
    tirenv_model_free(m);
}

/* Along the centre height, on a grid of 0.1 mm steps from 0.55 to 0.679 m (where elements come
 * into contact one by one), the contact length never grows with the height (to 1e-12 m) and
 * never jumps: between neighbouring heights it changes by less than an element spacing's ray
 * step on the ground (a new element touching moves the edge continuously from its free
 * neighbour's interpolation to its own). */
static void test_continuous_and_monotone(void **state)
{
    (void)state;
    const tirenv_tire t = tirenv_tire_default();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
    assert_non_null(m);
    tirenv_diag d;
    const double spacing = t.springs.R0 * t.springs.dphi;  /* 5.9 mm */
    double last = INFINITY, jump = 0;
    for (double z = 0.55; z < 0.679; z += 1e-4) {
        tirenv_flat f;
        assert_int_equal(tirenv_model_flat_at_height(m, z, &f, &d), TIRENV_OK);
        if (isfinite(last)) {
            assert_true(f.contact_length <= last + 1e-12);
            jump = fmax(jump, last - f.contact_length);
        }
        last = f.contact_length;
    }
    print_message("largest change over 0.1 mm of height: %.3g mm\n", 1e3 * jump);
    assert_true(jump < 0.5 * spacing);
    tirenv_model_free(m);
}

/* Pure radial springs (c_b = 0): every element the ground reaches touches it, and the edges'
 * interpolation of the penetration between the last touching element and the first free one
 * lands on the chord's end to its curvature's error over one ray step, (step)^2/(8 R0) about
 * 6e-6 m at each end; so the contact length is the chord within 2e-5 m. With c_b > 0 it is
 * shorter, the more so the stiffer the interradial springs. */
static void test_radial_limit_and_c_b(void **state)
{
    (void)state;
    const tirenv_tire t = tirenv_tire_default();
    const double z = 0.6213, R0 = t.springs.R0;
    tirenv_diag d;
    double last = INFINITY;
    const double c_b[] = {0, 2385, 22000, 39700, 1.3e5};
    for (size_t k = 0; k < sizeof c_b / sizeof c_b[0]; k++) {
        tirenv_model *m = springs_of(4.21e5, c_b[k], TIRENV_SPRINGS_CONTINUOUS);
        tirenv_flat f;
        assert_int_equal(tirenv_model_flat_at_height(m, z, &f, &d), TIRENV_OK);
        print_message("c_b %8.0f: contact length %.5f m (chord %.5f m)\n", c_b[k],
                      f.contact_length, chord(R0, z));
        if (c_b[k] == 0)
            assert_near(f.contact_length, chord(R0, z), 2e-5, 0);
        assert_true(f.contact_length < last);
        last = f.contact_length;
        tirenv_model_free(m);
    }
}

/* On flat ground the paper's contact along the rays and the continuous tread solve the same
 * problem: the same contact length (to 1e-12 relative: the QP and the closed form may differ
 * in the last bits) and load. */
static void test_rays_as_continuous(void **state)
{
    (void)state;
    tirenv_model *a = springs_of(4.21e5, 22000, TIRENV_SPRINGS_CONTINUOUS);
    tirenv_model *b = springs_of(4.21e5, 22000, TIRENV_SPRINGS_RAYS);
    tirenv_diag d;
    for (double G = 5931.7; G < 40000; G *= 1.7) {
        tirenv_flat fa, fb;
        assert_int_equal(tirenv_model_flat(a, G, &fa, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_flat(b, G, &fb, &d), TIRENV_OK);
        assert_near(fb.contact_length, fa.contact_length, 0, 1e-12);
        assert_near(fb.deflection, fa.deflection, 0, 1e-9);
    }
    tirenv_model_free(a);
    tirenv_model_free(b);
}

/* The rigid disc and the point keep the chord: the load of a contact length is the springs
 * model's at the height where the free circle's chord is that long, bit for bit; the springs
 * model's own load for the same length is larger (its touched length is shorter than the
 * chord, so it sinks further). tirenv_model_flat_at_height refuses models that do not deflect
 * and heights outside (0, R0). */
static void test_rigid_keeps_the_chord(void **state)
{
    (void)state;
    const tirenv_tire t = tirenv_tire_default();
    const double R0 = t.springs.R0;
    tirenv_model *springs = tirenv_model_alloc(tirenv_model_springs, &t);
    tirenv_model *rigid = tirenv_model_alloc(tirenv_model_rigid, &t);
    tirenv_model *point = tirenv_model_alloc(tirenv_model_point, &t);
    assert_non_null(springs);
    assert_non_null(rigid);
    assert_non_null(point);
    tirenv_diag d;
    const double l_c = 0.3385;
    tirenv_flat f;
    assert_int_equal(tirenv_model_flat_at_height(springs, sqrt(R0 * R0 - 0.25 * l_c * l_c), &f,
                                                 &d), TIRENV_OK);
    double G_rigid, G_point, G_springs;
    assert_int_equal(tirenv_model_load_for_contact_length(rigid, l_c, &G_rigid, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_load_for_contact_length(point, l_c, &G_point, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_load_for_contact_length(springs, l_c, &G_springs, &d),
                     TIRENV_OK);
    assert_true(G_rigid == f.load && G_point == f.load);
    assert_true(G_springs > 1.5 * G_rigid);
    assert_int_equal(tirenv_model_flat_at_height(rigid, 0.6, &f, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_flat_at_height(springs, R0, &f, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_flat_at_height(springs, -0.1, &f, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "centre height");
    tirenv_model_free(springs);
    tirenv_model_free(rigid);
    tirenv_model_free(point);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_touched_length),
        cmocka_unit_test(test_continuous_and_monotone),
        cmocka_unit_test(test_radial_limit_and_c_b),
        cmocka_unit_test(test_rays_as_continuous),
        cmocka_unit_test(test_rigid_keeps_the_chord),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
