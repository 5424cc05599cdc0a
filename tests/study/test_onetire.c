/* SPDX-License-Identifier: Apache-2.0 */
/* One tire, every model (docs/models.md section 14): the default tire's springs and cam
 * identified on its ring agree with it over the load range, model pair by model pair; the
 * models of MF-Tyre files without tirenv sections derived from their keys; the in-place
 * update of a tire file. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "testutil.h"
#include "tirenv/tirenv.h"

/* The ring's loads at contact lengths spanning the paper's regimes, 0.28 to 0.38 m: the
 * range the default tire is identified on (tirenv identify). */
enum { N_LOADS = 5 };
static void ring_loads(const tirenv_tire *t, double loads[N_LOADS])
{
    tirenv_model *ring = tirenv_model_alloc(tirenv_model_ring, t);
    assert_non_null(ring);
    tirenv_diag d;
    for (size_t i = 0; i < N_LOADS; i++)
        assert_int_equal(tirenv_model_load_for_contact_length(ring, 0.28 + 0.025 * (double)i,
                                                              &loads[i], &d), TIRENV_OK);
    tirenv_model_free(ring);
}

static void flat_states(const tirenv_model_type *type, const tirenv_tire *t, size_t n,
                        const double loads[], tirenv_flat f[])
{
    tirenv_model *m = tirenv_model_alloc(type, t);
    assert_non_null(m);
    tirenv_diag d;
    for (size_t i = 0; i < n; i++)
        assert_int_equal(tirenv_model_flat(m, loads[i], &f[i], &d), TIRENV_OK);
    tirenv_model_free(m);
}

/* The shipped default tire is what tirenv identify makes of its ring, to the three digits it
 * writes (half a unit in the third digit: 0.5 % relative at worst); a ring that changes
 * without scripts/identify-default-tire.sh being run fails here. */
static void test_default_is_identified(void **state)
{
    (void)state;
    const tirenv_tire t = tirenv_test_default_tire();
    double loads[N_LOADS];
    ring_loads(&t, loads);
    tirenv_tire id;
    tirenv_flat_target tg[N_LOADS];
    tirenv_diag d;
    assert_int_equal(tirenv_identify_flat(&t, tirenv_model_ring, N_LOADS, loads, &id, tg, &d),
                     TIRENV_OK);
    print_message("identified: c_r %.6g c_b %.6g c_z %.6g Q_RA1 %.6g Q_RA2 %.6g\n",
                  id.springs.c_r, id.springs.c_b, id.cam.c_z, id.cam.q_ra1, id.cam.q_ra2);
    assert_near(t.springs.c_r, id.springs.c_r, 0, 5e-3);
    assert_near(t.springs.c_b, id.springs.c_b, 0, 5e-3);
    assert_near(t.cam.c_z, id.cam.c_z, 0, 5e-3);
    assert_near(t.cam.q_ra1, id.cam.q_ra1, 0, 5e-3);
    assert_near(t.cam.q_ra2, id.cam.q_ra2, 2e-4, 0);  /* small: its third digit is 1e-4 */
    /* The targets are the ring's own states at those loads. */
    for (size_t i = 0; i < N_LOADS; i++)
        assert_near(tg[i].contact_length, 0.28 + 0.025 * (double)i, 1e-6, 0);
}

/* Model pairs at the same loads over the range the default tire is identified on and the
 * tractor's two tire loads (8.74 and 13.34 kN). Tolerances: springs against ring, deflection
 * 1 % (identified to 0.1 %); cam against ring, contact length 1 % (0.1 %); cam against ring
 * and springs, deflection 1 % within the range (MF-Tyre's quadratic vertical law with Q_FZ2
 * stiffens with load as the ring does: 0.2 % at most; the linear law it replaced missed by
 * 5.8 % at the range's ends) and 2 % at the front tire's 8.74 kN below it, outside the loads
 * it is identified on (0.8 %; the linear law: 10.9 %). The springs model's contact length, the chord of its
 * free circle, is 1.7 to 1.8 times the ring's patch: asserted as such, so that a change of that
 * convention is seen here: by construction it cannot be the ring's (docs/models.md 14.1). */
static void test_model_pairs(void **state)
{
    (void)state;
    const tirenv_tire t = tirenv_test_default_tire();
    double loads[N_LOADS + 2];
    ring_loads(&t, loads);
    loads[N_LOADS] = 8737.03;
    loads[N_LOADS + 1] = 13335.47;
    const size_t n = N_LOADS + 2;
    tirenv_flat r[N_LOADS + 2], s[N_LOADS + 2], c[N_LOADS + 2];
    flat_states(tirenv_model_ring, &t, n, loads, r);
    flat_states(tirenv_model_springs, &t, n, loads, s);
    flat_states(tirenv_model_cam, &t, n, loads, c);
    for (size_t i = 0; i < n; i++) {
        const double cam_tol = loads[i] < 0.99 * loads[0] ? 0.02 : 0.01;
        print_message("%8.0f N: deflection ring %.2f springs %.2f cam %.2f mm; contact length "
                      "ring %.4f springs %.4f cam %.4f m\n", loads[i], 1e3 * r[i].deflection,
                      1e3 * s[i].deflection, 1e3 * c[i].deflection, r[i].contact_length,
                      s[i].contact_length, c[i].contact_length);
        assert_near(s[i].deflection, r[i].deflection, 0, 0.01);
        assert_near(c[i].deflection, r[i].deflection, 0, cam_tol);
        assert_near(c[i].deflection, s[i].deflection, 0, cam_tol);
        assert_near(c[i].contact_length, r[i].contact_length, 0, 0.01);
        const double chord_ratio = s[i].contact_length / r[i].contact_length;
        assert_true(chord_ratio > 1.6 && chord_ratio < 1.9);
    }
}

/* The MF-Tyre files the tests have, none with a tirenv section but 205-60R15-mfswift.tir. */
static const char *const mf_files[] = {
    TIRENV_TEST_DATA "/samples/tir/335_65R22_5_G275MSA_60psi.tir",
    TIRENV_TEST_DATA "/samples/tir/HMMWV_Pac02Tire.tir",
    TIRENV_TEST_DATA "/samples/tir/tractor_430_50R38.tir",
    TIRENV_TEST_DATA "/samples/tir/mf_185_80R14.tir",
    TIRENV_TEST_DATA "/tir_mftyre.tir",
};

/* Derived springs and ring: each carries FNOMIN at the file's deflection (to the 1e-9 of the
 * inversion), so its secant stiffness there is the file's VERTICAL_STIFFNESS within 10 %
 * (exact for a linear law); none
 * keeps the tractor's values. */
static void test_derived_from_mftyre(void **state)
{
    (void)state;
    const tirenv_tire def = tirenv_tire_default();
    for (size_t f = 0; f < sizeof mf_files / sizeof mf_files[0]; f++) {
        tirenv_tire t = tirenv_tire_default();
        tirenv_diag d;
        assert_int_equal(tirenv_tir_read(mf_files[f], &t, &d), TIRENV_OK);
        tirenv_tir_origin o;
        if (tirenv_tir_derive(mf_files[f], &t, TIRENV_TIR_SPRINGS | TIRENV_TIR_RING, &o, &d))
            fail_msg("%s: %s: %s", mf_files[f], d.field, d.message);
        assert_int_equal(o.own, 0);
        assert_int_equal(o.derived, TIRENV_TIR_SPRINGS | TIRENV_TIR_RING);
        assert_true(o.fnomin > 0);
        assert_non_null(strstr(o.note, "derived RADIAL_STIFFNESS"));
        assert_true(t.springs.c_r != def.springs.c_r && t.ring.k_f != def.ring.k_f);
        const double k_file = t.cam.c_z;  /* VERTICAL_STIFFNESS as read */
        const tirenv_model_type *types[] = {tirenv_model_springs, tirenv_model_ring};
        for (size_t k = 0; k < 2; k++) {
            tirenv_flat fl;
            flat_states(types[k], &t, 1, &o.fnomin, &fl);
            print_message("%s %s: FNOMIN %.0f N, deflection %.2f mm (file %.2f), secant "
                          "%.0f kN/m, tangent %.0f kN/m, file %.0f kN/m\n", mf_files[f],
                          tirenv_model_type_name(types[k]), o.fnomin, 1e3 * fl.deflection,
                          1e3 * o.rho_nominal, o.fnomin / fl.deflection / 1e3,
                          fl.stiffness / 1e3, k_file / 1e3);
            assert_near(fl.deflection, o.rho_nominal, 0, 1e-7);
            assert_near(o.fnomin / fl.deflection, k_file, 0, 0.10);
        }
    }
    /* A file with every section: nothing derived, nothing changed. */
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    const char *own = TIRENV_DATA_DIR "/tires/205-60R15-mfswift.tir";
    assert_int_equal(tirenv_tir_read(own, &t, &d), TIRENV_OK);
    const tirenv_tire before = t;
    tirenv_tir_origin o;
    assert_int_equal(tirenv_tir_derive(own, &t, TIRENV_TIR_SPRINGS | TIRENV_TIR_RING, &o, &d),
                     TIRENV_OK);
    assert_int_equal(o.own, TIRENV_TIR_SPRINGS | TIRENV_TIR_RING);
    assert_int_equal(o.derived, 0);
    assert_string_equal(o.note, "");
    assert_memory_equal(&t, &before, sizeof t);
}

static void write_file(const char *path, const char *text)
{
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    fputs(text, fp);
    assert_int_equal(fclose(fp), 0);
}

/* The derived models follow the file's pressure dependence: with PFZ1 the stiffness at FNOMIN
 * is VERTICAL_STIFFNESS*(1 + PFZ1*(INFLPRES - NOMPRES)/NOMPRES) (MF-Tyre 6.1), so two
 * pressures give the ratio of those factors (here 1.2625/0.895) to the inversion's 1e-7. */
static void test_pressure_dependence(void **state)
{
    (void)state;
    char dir[] = "/tmp/tirenv_onetire_XXXXXX";
    assert_non_null(mkdtemp(dir));
    const double p[2] = {1.6e5, 2.9e5}, pfz1 = 0.7, p0 = 2.0e5;
    double k[2][2];
    for (int i = 0; i < 2; i++) {
        char path[128], text[1024];
        snprintf(path, sizeof path, "%s/p%d.tir", dir, i);
        snprintf(text, sizeof text,
                 "[UNITS]\nLENGTH = 'meter'\nFORCE = 'newton'\nPRESSURE = 'pascal'\n"
                 "[DIMENSION]\nUNLOADED_RADIUS = 0.3135\nWIDTH = 0.205\nASPECT_RATIO = 0.6\n"
                 "[OPERATING_CONDITIONS]\nINFLPRES = %g\nNOMPRES = %g\n"
                 "[VERTICAL]\nFNOMIN = 4000\nVERTICAL_STIFFNESS = 209651.5\nPFZ1 = %g\n",
                 p[i], p0, pfz1);
        write_file(path, text);
        tirenv_tire t = tirenv_tire_default();
        tirenv_diag d;
        tirenv_tir_origin o;
        assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
        assert_int_equal(tirenv_tir_derive(path, &t, TIRENV_TIR_SPRINGS | TIRENV_TIR_RING, &o,
                                           &d), TIRENV_OK);
        const tirenv_model_type *types[] = {tirenv_model_springs, tirenv_model_ring};
        for (int m = 0; m < 2; m++) {
            tirenv_flat fl;
            flat_states(types[m], &t, 1, &o.fnomin, &fl);
            k[m][i] = o.fnomin / fl.deflection;
        }
        assert_near(k[0][i], 209651.5 * (1 + pfz1 * (p[i] - p0) / p0), 0, 1e-6);
        unlink(path);
    }
    const double want = (1 + pfz1 * (p[1] - p0) / p0) / (1 + pfz1 * (p[0] - p0) / p0);
    assert_near(k[0][1] / k[0][0], want, 0, 1e-6);
    assert_near(k[1][1] / k[1][0], want, 0, 1e-6);
    rmdir(dir);
}

/* A file that lacks what a model needs: refused naming the key when the model is needed,
 * said in the note (and the tire left as it was) when it is not. */
static void test_refuses_naming_the_key(void **state)
{
    (void)state;
    char dir[] = "/tmp/tirenv_onetire_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char path[128];
    snprintf(path, sizeof path, "%s/nofnomin.tir", dir);
    write_file(path, "[DIMENSION]\nUNLOADED_RADIUS = 0.376\n[VERTICAL]\n"
                     "VERTICAL_STIFFNESS = 1.75e5\n");
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    tirenv_tir_origin o;
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
    const tirenv_tire before = t;
    assert_int_equal(tirenv_tir_derive(path, &t, TIRENV_TIR_SPRINGS, &o, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "FNOMIN");
    assert_non_null(strstr(d.message, "ENVELOPING_SPRINGS"));
    assert_memory_equal(&t, &before, sizeof t);
    assert_int_equal(tirenv_tir_derive(path, &t, TIRENV_TIR_RING, &o, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "FNOMIN");
    assert_int_equal(tirenv_tir_derive(path, &t, 0, &o, &d), TIRENV_OK);
    assert_int_equal(o.derived, 0);
    assert_non_null(strstr(o.note, "no FNOMIN"));
    assert_memory_equal(&t, &before, sizeof t);
    unlink(path);
    rmdir(dir);
}

/* tirenv_tir_update: values replaced in place, comments kept, the note block replaced on a
 * second run (not repeated), a missing key and section added; the file reads back with the
 * new values. */
static void test_update_in_place(void **state)
{
    (void)state;
    char dir[] = "/tmp/tirenv_onetire_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char path[128];
    snprintf(path, sizeof path, "%s/t.tir", dir);
    write_file(path, "[MDI_HEADER]\nFILE_TYPE = 'tir'\n! a header comment\n$---rule\n"
                     "[DIMENSION]\nUNLOADED_RADIUS = 0.68   $ R0, m\n"
                     "[ENVELOPING_SPRINGS]\n$ keep me\nRADIAL_STIFFNESS = 7.83e5   $ c_r\n");
    const tirenv_tir_value v[] = {
        {"ENVELOPING_SPRINGS", "RADIAL_STIFFNESS", 3.6912e5},
        {"ENVELOPING_SPRINGS", "INTERRADIAL_STIFFNESS", 3.9518e4},
        {"CONTACT_PATCH", "Q_RA1", 0.8071},
    };
    tirenv_diag d;
    for (int run = 0; run < 2; run++)
        assert_int_equal(tirenv_tir_update(path, 3, v, run ? "second\nnote" : "first", &d),
                         TIRENV_OK);
    char text[2048];
    FILE *fp = fopen(path, "r");
    assert_non_null(fp);
    const size_t len = fread(text, 1, sizeof text - 1, fp);
    fclose(fp);
    text[len] = '\0';
    print_message("%s", text);
    assert_non_null(strstr(text, "RADIAL_STIFFNESS = 369120   $ c_r\n"));
    assert_non_null(strstr(text, "$ keep me\n"));
    assert_non_null(strstr(text, "! a header comment\n! tirenv identify: begin\n! second\n"
                                 "! note\n! tirenv identify: end\n$---rule\n"));
    assert_null(strstr(text, "! first"));
    assert_null(strstr(strstr(text, "identify: end") + 1, "identify: begin"));
    tirenv_tire t = tirenv_tire_default();
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
    assert_true(t.springs.c_r == 369120 && t.springs.c_b == 39518 && t.cam.q_ra1 == 0.8071);
    unlink(path);
    rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_default_is_identified),
        cmocka_unit_test(test_model_pairs),
        cmocka_unit_test(test_derived_from_mftyre),
        cmocka_unit_test(test_pressure_dependence),
        cmocka_unit_test(test_refuses_naming_the_key),
        cmocka_unit_test(test_update_in_place),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
