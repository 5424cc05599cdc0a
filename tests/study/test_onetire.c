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

/* The loads tirenv identify takes for a tire file with FNOMIN (the default tire's 17.9 kN):
 * 0.5 to 1.5 times it. */
enum { N_LOADS = 5 };
static void nominal_loads(const tirenv_tire *t, double loads[N_LOADS])
{
    for (size_t i = 0; i < N_LOADS; i++)
        loads[i] = (0.5 + 0.25 * (double)i) * t->cam.fnomin;
}

static void flat_states(const tirenv_model_type *type, const tirenv_tire *t, size_t n,
                        const double loads[], tirenv_flat f[])
{
    tirenv_model *m = tirenv_model_alloc(type, t);
    assert_non_null(m);
    tirenv_diag d;
    for (size_t i = 0; i < n; i++)
        if (tirenv_model_flat(m, loads[i], &f[i], &d))
            fail_msg("%s at %g N: %s: %s", tirenv_model_type_name(type), loads[i], d.field,
                     d.message);
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
    nominal_loads(&t, loads);
    tirenv_tire id;
    tirenv_flat_target tg[N_LOADS];
    tirenv_diag d;
    assert_int_equal(tirenv_identify_flat(&t, tirenv_model_ring, N_LOADS, loads, &id, tg, &d),
                     TIRENV_OK);
    print_message("identified: c_r %.6g c_b %.6g c_z %.6g Q_FZ2 %.6g Q_RA1 %.6g Q_RA2 %.6g\n",
                  id.springs.c_r, id.springs.c_b, id.cam.c_z, id.cam.q_fz2, id.cam.q_ra1,
                  id.cam.q_ra2);
    assert_near(t.springs.c_r, id.springs.c_r, 0, 5e-3);
    assert_near(t.springs.c_b, id.springs.c_b, 0, 5e-3);
    assert_near(t.cam.c_z, id.cam.c_z, 0, 5e-3);
    assert_near(t.cam.q_fz2, id.cam.q_fz2, 0, 5e-3);
    assert_near(t.cam.q_ra1, id.cam.q_ra1, 0, 5e-3);
    assert_near(t.cam.q_ra2, id.cam.q_ra2, 0, 5e-3);
    /* The targets are the ring's own states at those loads. */
    tirenv_flat r[N_LOADS];
    flat_states(tirenv_model_ring, &t, N_LOADS, loads, r);
    for (size_t i = 0; i < N_LOADS; i++) {
        assert_true(tg[i].load == loads[i]);
        assert_true(tg[i].deflection == r[i].deflection);
        assert_true(tg[i].contact_length == r[i].contact_length);
    }
}

/* Relative difference of a from b. */
static double rel(double a, double b) { return fabs(a - b) / b; }

/* The largest relative differences of a pair over the loads: deflection, contact length. */
typedef struct {
    double defl, l;
} pair_miss;

/* Model pairs at the same loads: springs - ring, cam - ring and springs - cam, deflection and
 * contact length at each load, the largest differences printed and returned (e[0] springs -
 * ring, e[1] cam - ring, e[2] springs - cam). */
static void pairs(const char *what, const tirenv_tire *t, size_t n, const double loads[],
                  pair_miss e[3])
{
    tirenv_flat r[16], s[16], c[16];
    assert_true(n <= 16);
    flat_states(tirenv_model_ring, t, n, loads, r);
    flat_states(tirenv_model_springs, t, n, loads, s);
    flat_states(tirenv_model_cam, t, n, loads, c);
    memset(e, 0, 3 * sizeof e[0]);
    for (size_t i = 0; i < n; i++) {
        print_message("%s %8.0f N: deflection ring %.2f springs %.2f cam %.2f mm; contact "
                      "length ring %.4f springs %.4f cam %.4f m\n", what, loads[i],
                      1e3 * r[i].deflection, 1e3 * s[i].deflection, 1e3 * c[i].deflection,
                      r[i].contact_length, s[i].contact_length, c[i].contact_length);
        const tirenv_flat *a[3] = {&s[i], &c[i], &s[i]}, *b[3] = {&r[i], &r[i], &c[i]};
        for (size_t k = 0; k < 3; k++) {
            e[k].defl = fmax(e[k].defl, rel(a[k]->deflection, b[k]->deflection));
            e[k].l = fmax(e[k].l, rel(a[k]->contact_length, b[k]->contact_length));
        }
    }
    print_message("%s: largest differences, deflection / contact length: springs-ring %.2f / "
                  "%.2f %%, cam-ring %.2f / %.2f %%, springs-cam %.2f / %.2f %%\n", what,
                  100 * e[0].defl, 100 * e[0].l, 100 * e[1].defl, 100 * e[1].l,
                  100 * e[2].defl, 100 * e[2].l);
}

static void pairs_within(const char *what, const tirenv_tire *t, size_t n, const double loads[],
                         double tol_springs, double tol_cam)
{
    pair_miss e[3];
    pairs(what, t, n, loads, e);
    assert_true(e[0].defl <= tol_springs && e[0].l <= tol_springs);
    assert_true(e[1].defl <= tol_cam && e[1].l <= tol_cam);
    assert_true(e[2].defl <= tol_springs && e[2].l <= tol_springs);
}

/* The default tire's models at the same loads: the file's load range (0.5 to 1.5 FNOMIN, on
 * which they are identified), the ring's loads at the data set's contact lengths 0.28 to
 * 0.43 m (17.0 to 38.5 kN with the shear-coupled tread, beyond the identification's
 * 26.85 kN) and the tractor's two tire loads (8.74 kN, below it, and 13.34 kN). Tolerance 5 %
 * (docs/models.md section 14) for every pair with the springs model (measured: deflection 2.5 %, contact
 * length 2.5 % against the ring); the cam, whose MF-Tyre laws are fitted to the ring
 * directly, 1 % on the loads it is identified on (measured 0.2 / 0.6 %) and 2.5 % on the
 * others, where its laws are extrapolated (measured 0.97 / 2.17 %: the contact length at
 * 38.5 kN, 2.2 times FNOMIN, and 1.9 % at 8.74 kN). */
static void test_model_pairs(void **state)
{
    (void)state;
    const tirenv_tire t = tirenv_test_default_tire();
    double loads[N_LOADS + 6];
    nominal_loads(&t, loads);
    tirenv_model *ring = tirenv_model_alloc(tirenv_model_ring, &t);
    assert_non_null(ring);
    tirenv_diag d;
    for (size_t i = 0; i < 4; i++)
        assert_int_equal(tirenv_model_load_for_contact_length(ring, 0.28 + 0.05 * (double)i,
                                                              &loads[N_LOADS + i], &d),
                         TIRENV_OK);
    tirenv_model_free(ring);
    loads[N_LOADS + 4] = 8737.03;
    loads[N_LOADS + 5] = 13335.47;
    pairs_within("default, identified", &t, N_LOADS, loads, 0.05, 0.01);
    pairs_within("default, beyond", &t, 6, loads + N_LOADS, 0.05, 0.025);
}

/* The MF-Tyre files the tests have, none with a tirenv section but 205-60R15-mfswift.tir;
 * the last two have the cam's contact law (Q_RA1, Q_RA2) of their own, and the 430/50R38
 * (N_OWN_LAW) its vertical law (Q_FZ2 = 0). */
static const char *const mf_files[] = {
    TIRENV_TEST_DATA "/samples/tir/335_65R22_5_G275MSA_60psi.tir",
    TIRENV_TEST_DATA "/samples/tir/HMMWV_Pac02Tire.tir",
    TIRENV_TEST_DATA "/samples/tir/mf_185_80R14.tir",
    TIRENV_TEST_DATA "/samples/tir/tractor_430_50R38.tir",
    TIRENV_TEST_DATA "/tir_mftyre.tir",
};
enum { N_MF = sizeof mf_files / sizeof mf_files[0], N_OWN_CAM = 2, N_OWN_LAW = 3 };
/* The sanitizer build derives the 185/80R14 and the 430/50R38 (the 335/65R22.5 and the
 * HMMWV left out, as cli_tir.sh does there, and tir_mftyre.tir: the rings searched on their
 * own laws, 20 tables for it and 10 for the 430, added 33 s to this test's CPU there, the
 * 430's alone about 10 s): the same code over fewer files; the Release build all five. */
#ifdef __SANITIZE_ADDRESS__
enum { MF_FIRST = 2, MF_END = N_MF - 1 };
#else
enum { MF_FIRST = 0, MF_END = N_MF };
#endif

/* File f read and its models derived (TIRENV_TIR_SPRINGS | TIRENV_TIR_RING needed), once for
 * the tests that look at them: a derivation costs up to 2.7 s of CPU (the 335/65R22.5's). */
static void derived(size_t f, tirenv_tire *t, tirenv_tir_origin *o)
{
    static tirenv_tire tires[N_MF];
    static tirenv_tir_origin origins[N_MF];
    static int done[N_MF];
    assert_true(f < N_MF);
    if (!done[f]) {
        tirenv_diag d;
        tires[f] = tirenv_tire_default();
        if (tirenv_tir_read(mf_files[f], &tires[f], &d) ||
            tirenv_tir_derive(mf_files[f], &tires[f], TIRENV_TIR_SPRINGS | TIRENV_TIR_RING,
                              &origins[f], &d))
            fail_msg("%s: %s: %s", mf_files[f], d.field, d.message);
        done[f] = 1;
    }
    *t = tires[f];
    *o = origins[f];
}

/* The models derived from MF-Tyre files (section 14.2) at 0.5 to 1.5 times each file's
 * FNOMIN: each pair's largest relative difference in deflection and in contact length within
 * 5 % (docs/models.md section 14), bounded here per file at half a per cent above what was measured where that
 * is lower (docs/models.md 14.2 has the figures), so that a change that loses what the
 * derivation gained fails. The springs model is identified on the ring and the ring's
 * pretension raised until their contact lengths grow alike; the cam's Q_RA1, Q_RA2 and, for a
 * file whose vertical law is VERTICAL_STIFFNESS alone, its Q_FZ2 are identified on the ring.
 * What a file gives of its own is kept. Where it is its contact law (Q_RA1, Q_RA2: the
 * 430/50R38's round values, tir_mftyre.tir's the 205/60R15's), the ring is searched on that
 * law and the vertical law together (the 430's own Q_FZ2 = 0, linear; tir_mftyre.tir's Q_FZ2
 * identified on the Winkler ring first) with a carcass that softens on the shear-coupled
 * tread: the cam within 5 % of it (measured 1.6 / 2.3 % and 1.4 / 1.7 %; on the Winkler rings
 * they were 5.1 / 46.6 % and 0.3 / 24.1 %: another tire). The springs model identified on
 * those rings has a sidewall in series (section 4.9), as the 205/60R15's: the elements alone
 * stiffen with the load where these rings follow nearly linear laws, and missed them by
 * 11.3 % in deflection on the 430 (its law linear) and 5.4 % on tir_mftyre.tir. */
typedef struct {
    double springs_ring[2], cam_ring[2], springs_cam[2]; /* deflection, contact length */
} pair_bounds;

static void test_derived_pairs(void **state)
{
    (void)state;
    /* Measured (%): 335/65R22.5 2.52/1.32, 0.25/0.61, 2.60/1.51; HMMWV 2.49/1.52, 0.68/0.46,
     * 2.76/1.22; 185/80R14 4.47/3.03, 1.26/0.26, 3.96/2.80; 430/50R38 2.29/3.60, 1.57/2.31,
     * 3.92/1.32; tir_mftyre.tir 1.10/1.91, 1.42/1.73, 2.56/2.26 (the last two on the rings
     * searched on their own laws, the springs model with a sidewall; without it 11.35/4.25,
     * 13.13/2.55 and 5.36/1.88, 6.87/2.22; before, on the Winkler rings, cam - ring
     * 5.08/46.63 and 0.32/24.05). */
    static const pair_bounds bound[N_MF] = {
        {{0.031, 0.019}, {0.008, 0.012}, {0.032, 0.021}},
        {{0.030, 0.021}, {0.012, 0.010}, {0.033, 0.018}},
        {{0.050, 0.036}, {0.018, 0.008}, {0.045, 0.033}},
        {{0.028, 0.041}, {0.021, 0.029}, {0.045, 0.019}},
        {{0.016, 0.024}, {0.020, 0.023}, {0.031, 0.028}},
    };
    for (size_t f = MF_FIRST; f < MF_END; f++) {
        tirenv_tire t;
        tirenv_tir_origin o;
        derived(f, &t, &o);
        print_message("%s: tau %.3f, Q_FZ2 %.4g: %s\n", mf_files[f], o.pretension_ratio,
                      t.cam.q_fz2, o.note);
        double loads[N_LOADS];
        for (size_t i = 0; i < N_LOADS; i++)
            loads[i] = (0.5 + 0.25 * (double)i) * o.fnomin;
        pair_miss e[3];
        pairs(strrchr(mf_files[f], '/') + 1, &t, N_LOADS, loads, e);
        const double *b[3] = {bound[f].springs_ring, bound[f].cam_ring, bound[f].springs_cam};
        for (size_t k = 0; k < 3; k++) {
            assert_true(e[k].defl <= b[k][0]);
            assert_true(e[k].l <= b[k][1]);
        }
        /* What the derivation said is what the models do. The derivation tables every
         * derived ring by Newton on the ring's forces (tir_derive.c ring_flats), which solves
         * the same equilibrium to the same eps_z = 1e-10 m of centre height as the model's
         * tirenv_model_flat from another start, so their deflections agree within 2e-10 m,
         * 1.3e-8 of the smallest compared (15 mm, the 430/50R38's at 0.5 FNOMIN): 2e-8 on
         * the misses (measured 1.3e-10 in deflection on the files with laws of their own,
         * and the same bits on the others, which no argument promises). */
        const double said_tol = 2e-8;
        assert_near(o.cam_ring_deflection, e[1].defl, said_tol, 0);
        assert_near(o.cam_ring_contact_length, e[1].l, said_tol, 0);
        assert_non_null(strstr(o.note, "cam against ring"));
        /* The first three files give no pressure: the derived ring's air is said. */
        assert_true((strstr(o.note, "the file gives no INFLPRES or NOMPRES") == NULL) == (f >= 3));
        if (f < N_MF - N_OWN_CAM) {
            assert_int_equal(o.derived & TIRENV_TIR_CAM, TIRENV_TIR_CAM);
            assert_non_null(strstr(o.note, "derived on the ring Q_RA1"));
        } else {
            assert_int_equal(o.own & TIRENV_TIR_CAM, TIRENV_TIR_CAM);
            assert_int_equal(o.derived & TIRENV_TIR_CAM, 0);
            assert_non_null(strstr(o.note, "the file's own cam contact law kept"));
            /* Its cam is this tire: the ring is searched on its laws (section 14.2), with the
             * softening carcass on the shear-coupled tread, and said. */
            assert_non_null(strstr(o.note, "searched on the file's own vertical and contact laws"));
            assert_true(e[1].defl <= 0.05 && e[1].l <= 0.05);
            assert_true(t.ring.w_cs > 0 && t.ring.w_c0 > 0 && t.ring.G_t > 0);
            assert_true(t.ring.dtheta == M_PI / 720.0);
            /* Its springs model has a sidewall in series, identified on that ring, and said. */
            assert_true(t.springs.k_s > 0 && t.springs.F_s0 >= 0);
            assert_non_null(strstr(o.note, "SIDEWALL_STIFFNESS = "));
            assert_non_null(strstr(o.note, "SIDEWALL_PRELOAD = "));
        }
        if (f < N_MF - N_OWN_CAM) {  /* the paper's springs model, no sidewall */
            assert_true(t.springs.k_s == 0 && t.springs.F_s0 == 0);
            assert_null(strstr(o.note, "SIDEWALL"));
        }
        if (f == N_OWN_LAW) {  /* the 430/50R38's Q_FZ2 = 0: its own law, kept and said */
            assert_int_equal(o.own & TIRENV_TIR_VERTICAL, TIRENV_TIR_VERTICAL);
            assert_int_equal(o.derived & TIRENV_TIR_VERTICAL, 0);
            assert_true(t.cam.q_fz2 == 0);
            assert_non_null(strstr(o.note, "(the file's own vertical law)"));
        } else {
            assert_int_equal(o.derived & TIRENV_TIR_VERTICAL, TIRENV_TIR_VERTICAL);
            assert_true(t.cam.q_fz2 > 0);  /* the ring stiffens with the load */
            assert_non_null(strstr(o.note, "no Q_FZ2 of its own: derived on the ring Q_FZ2 = "));
        }
    }
}

/* The 205/60R15 (data/tires/205-60R15-mfswift.tir) has every model of its own: TNO's cam
 * (its linear law, Q_RA1, Q_RA2), kept, and tirenv's ring and springs model identified on it
 * (docs/models.md 14.2): a ring whose carcass softens as it is pressed in, searched on the
 * cam's laws (scripts/ring-on-laws.py), and the springs model with a sidewall in series
 * (section 4.9) identified on that ring and the cam together, the largest difference from
 * both the least (scripts/springs-softening-study.py); its data set is made by its cam, so
 * nothing is derived. At 0.5 to 1.5 FNOMIN, measured, deflection / contact length: cam -
 * ring 1.02 / 1.68 %, springs - ring 4.68 / 3.91 %, springs - cam 4.80 / 4.81 %. Identified
 * on the ring alone the springs model missed the cam's contact length by 5.48 % at 6 kN (its
 * elements' patch grows as F^0.51, TNO's law as F^0.60); the sidewall took its deflection
 * from 14.72 % (the elements alone stiffen as their patch grows) into the 5 %. Bounded by
 * the 5 % for every pair with the springs model, the cam and the ring at their
 * measured figures plus half a per cent. (With a linear carcass the ring missed TNO's laws
 * by 8.5 % at best, and the file's earlier ring by 42 % in contact length.) */
static void test_205_pairs(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    tirenv_tir_origin o;
    const char *path = TIRENV_DATA_DIR "/tires/205-60R15-mfswift.tir";
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
    assert_int_equal(tirenv_tir_derive(path, &t, 0, &o, &d), TIRENV_OK);
    assert_int_equal(o.derived, 0);
    double loads[N_LOADS];
    for (size_t i = 0; i < N_LOADS; i++)
        loads[i] = (0.5 + 0.25 * (double)i) * o.fnomin;
    pair_miss e[3];
    pairs("205/60R15", &t, N_LOADS, loads, e);
    static const double bound[3][2] = {{0.05, 0.05}, {0.0152, 0.0218}, {0.05, 0.05}};
    for (size_t k = 0; k < 3; k++) {
        assert_true(e[k].defl <= bound[k][0]);
        assert_true(e[k].l <= bound[k][1]);
    }
}

/* tirenv_identify_flat_on on the 205/60R15's ring and cam together (tirenv identify
 * --reference ring,cam, docs/models.md 14.1) at the five loads 0.5 to 1.5 FNOMIN: the cam,
 * a reference, comes back as read, bit for bit, and so does every key but the springs
 * model's four; the springs model is within 5 % of both (measured springs - ring 4.60 /
 * 3.83 %, springs - cam 4.72 / 4.74 %; at the 41 loads of the shipped values 4.81 % at
 * most), and c_r, c_b within 1 % of those shipped, which the same search wrote at those 41
 * loads (measured +0.07 and +0.26 %). The springs
 * model as a reference, or none, is refused. */
static void test_205_identified_on_both(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    tirenv_tir_origin o;
    const char *path = TIRENV_DATA_DIR "/tires/205-60R15-mfswift.tir";
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
    assert_int_equal(tirenv_tir_derive(path, &t, 0, &o, &d), TIRENV_OK);
    double loads[N_LOADS];
    for (size_t i = 0; i < N_LOADS; i++)
        loads[i] = (0.5 + 0.25 * (double)i) * o.fnomin;
    const tirenv_model_type *const refs[] = {tirenv_model_ring, tirenv_model_cam};
    tirenv_tire id;
    tirenv_flat_target tg[2 * N_LOADS];
    assert_int_equal(tirenv_identify_flat_on(&t, 2, refs, N_LOADS, loads, &id, tg, &d),
                     TIRENV_OK);
    print_message("205/60R15 on ring and cam: c_r %.6g, c_b %.6g, k_s %.6g, F_s0 %.6g\n",
                  id.springs.c_r, id.springs.c_b, id.springs.k_s, id.springs.F_s0);
    assert_memory_equal(&id.cam, &t.cam, offsetof(tirenv_cam_params, given) + sizeof t.cam.given);
    assert_true(id.cam.max_step == t.cam.max_step);
    assert_memory_equal(&id.ring, &t.ring, sizeof t.ring);
    tirenv_flat c[N_LOADS];
    flat_states(tirenv_model_cam, &t, N_LOADS, loads, c);
    for (size_t i = 0; i < N_LOADS; i++) /* the cam's own states, after the ring's */
        assert_true(tg[N_LOADS + i].deflection == c[i].deflection &&
                    tg[N_LOADS + i].contact_length == c[i].contact_length);
    tirenv_tire rest = id;
    rest.springs.c_r = t.springs.c_r;
    rest.springs.c_b = t.springs.c_b;
    rest.springs.k_s = t.springs.k_s;
    rest.springs.F_s0 = t.springs.F_s0;
    assert_memory_equal(&rest, &t, sizeof t);
    pair_miss e[3];
    pairs("205/60R15 identified on ring and cam", &id, N_LOADS, loads, e);
    for (size_t k = 0; k < 3; k += 2)
        assert_true(e[k].defl <= 0.05 && e[k].l <= 0.05);
    assert_near(id.springs.c_r, t.springs.c_r, 0, 0.01);
    assert_near(id.springs.c_b, t.springs.c_b, 0, 0.01);
    const tirenv_model_type *const bad[] = {tirenv_model_ring, tirenv_model_springs};
    assert_int_equal(tirenv_identify_flat_on(&t, 2, bad, N_LOADS, loads, &id, NULL, &d),
                     TIRENV_EINVAL);
    assert_string_equal(d.field, "references");
    assert_int_equal(tirenv_identify_flat_on(&t, 0, refs, N_LOADS, loads, &id, NULL, &d),
                     TIRENV_EINVAL);
    assert_string_equal(d.field, "references");
}

/* Derived springs and ring: each carries FNOMIN at the file's deflection (to the 1e-9 m of
 * the inversion), and the cam's law deflects there too (within the derivation's 1e-6); none
 * keeps the tractor's values. What that deflection is follows MF-Tyre's meaning of
 * VERTICAL_STIFFNESS (docs/models.md 7.3, 14.2): with a Q_FZ2 it is the law's tangent at
 * FNOMIN, so where Q_FZ2 was identified on the ring the cam's tangent there is the file's
 * VERTICAL_STIFFNESS (to round-off) and the ring's and the springs model's tangents are near
 * it (measured: ring -2.9 to +1.3 %, springs +3.7 to +5.7 %; bounded at 3.5 and 6.5 %, the
 * issue's bound is 10 %; before Q_FZ2 was derived they were 10 to 25 % above); their secant
 * is the law's, below it. On tir_mftyre.tir, whose ring is searched on its own contact law
 * (section 14.2), the springs model identified on that ring with a sidewall in series is
 * -1.3 % at FNOMIN (ring -1.5 %), bounded at half a per cent above (without the sidewall,
 * +11.1 %: the elements stiffen with the load). A file's own linear law (the 430/50R38's
 * Q_FZ2 = 0) is its secant: FNOMIN over the deflection is VERTICAL_STIFFNESS there. */
static void test_derived_from_mftyre(void **state)
{
    (void)state;
    static const double TANGENT_TOL_RING = 0.035, TANGENT_TOL_SPRINGS = 0.065,
                        TANGENT_TOL_SPRINGS_ON_LAWS = 0.018;
    const tirenv_tire def = tirenv_tire_default();
    for (size_t f = MF_FIRST; f < MF_END; f++) {
        tirenv_tire t;
        tirenv_tir_origin o;
        derived(f, &t, &o);
        assert_int_equal(o.own & (TIRENV_TIR_SPRINGS | TIRENV_TIR_RING), 0);
        assert_int_equal(o.derived & (TIRENV_TIR_SPRINGS | TIRENV_TIR_RING),
                         TIRENV_TIR_SPRINGS | TIRENV_TIR_RING);
        assert_true(o.fnomin > 0);
        assert_non_null(strstr(o.note, "derived RADIAL_STIFFNESS"));
        assert_true(t.springs.c_r != def.springs.c_r && t.ring.k_c != def.ring.k_c);
        const double k_file = t.cam.c_z;  /* VERTICAL_STIFFNESS as read */
        const int law_derived = (o.derived & TIRENV_TIR_VERTICAL) != 0;
        const int own_cam = (o.own & TIRENV_TIR_CAM) != 0;
        const tirenv_model_type *types[] = {tirenv_model_springs, tirenv_model_ring,
                                            tirenv_model_cam};
        for (size_t k = 0; k < 3; k++) {
            tirenv_flat fl;
            flat_states(types[k], &t, 1, &o.fnomin, &fl);
            print_message("%s %s: FNOMIN %.0f N, deflection %.3f mm (file %.3f), secant "
                          "%.1f kN/m, tangent %.1f kN/m (%+.1f %%), file %.1f kN/m%s\n",
                          mf_files[f], tirenv_model_type_name(types[k]), o.fnomin,
                          1e3 * fl.deflection, 1e3 * o.rho_nominal,
                          o.fnomin / fl.deflection / 1e3, fl.stiffness / 1e3,
                          100 * (fl.stiffness / k_file - 1), k_file / 1e3,
                          law_derived ? " (Q_FZ2 derived)" : "");
            assert_near(fl.deflection, o.rho_nominal, 0, types[k] == tirenv_model_cam ? 2e-6
                                                                                       : 1e-7);
            if (!law_derived)
                assert_near(o.fnomin / fl.deflection, k_file, 0, 1e-6);
            else if (types[k] == tirenv_model_cam)
                assert_near(fl.stiffness, k_file, 0, 1e-12);
            else
                assert_near(fl.stiffness, k_file, 0,
                            types[k] == tirenv_model_ring ? TANGENT_TOL_RING
                            : own_cam                     ? TANGENT_TOL_SPRINGS_ON_LAWS
                                                          : TANGENT_TOL_SPRINGS);
        }
        if (law_derived)  /* the ring stiffens with the load: the secant is below */
            assert_true(o.fnomin / o.rho_nominal < 0.95 * k_file);
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
    assert_int_equal(o.own, TIRENV_TIR_SPRINGS | TIRENV_TIR_RING | TIRENV_TIR_CAM);
    assert_int_equal(o.derived, 0);
    assert_string_equal(o.note, "");
    assert_memory_equal(&t, &before, sizeof t);
}

/* The derived keys of two tires bit for bit (whole structs would compare their padding too):
 * springs (what), ring, cam. */
static void same_keys(const tirenv_tire *a, const tirenv_tire *b, int what)
{
    const double sa[] = {a->springs.c_r, a->springs.c_b, a->springs.phi, a->springs.dphi,
                         a->springs.k_s, a->springs.F_s0};
    const double sb[] = {b->springs.c_r, b->springs.c_b, b->springs.phi, b->springs.dphi,
                         b->springs.k_s, b->springs.F_s0};
    const double ra[] = {a->ring.t_r, a->ring.EI, a->ring.T, a->ring.k_c, a->ring.k_t,
                         a->ring.G_t, a->ring.dtheta, a->ring.b_p, a->ring.w_cs, a->ring.w_c0,
                         a->ring.p, a->ring.p_nom};
    const double rb[] = {b->ring.t_r, b->ring.EI, b->ring.T, b->ring.k_c, b->ring.k_t,
                         b->ring.G_t, b->ring.dtheta, b->ring.b_p, b->ring.w_cs, b->ring.w_c0,
                         b->ring.p, b->ring.p_nom};
    const double ca[] = {a->cam.c_z, a->cam.fnomin, a->cam.q_fz1, a->cam.q_fz2, a->cam.q_ra1,
                         a->cam.q_ra2, a->cam.pfz1};
    const double cb[] = {b->cam.c_z, b->cam.fnomin, b->cam.q_fz1, b->cam.q_fz2, b->cam.q_ra1,
                         b->cam.q_ra2, b->cam.pfz1};
    if (what & TIRENV_TIR_SPRINGS)
        assert_memory_equal(sa, sb, sizeof sa);
    if (what & TIRENV_TIR_RING)
        assert_memory_equal(ra, rb, sizeof ra);
    if (what & TIRENV_TIR_CAM) {
        assert_memory_equal(ca, cb, sizeof ca);
        assert_int_equal(a->cam.given, b->cam.given);
    }
}

/* A derivation for the ring or the cam alone (t, o) against the whole one (full, o_full):
 * the same ring and cam; on tir_mftyre.tir (a contact law of its own) the springs model as
 * read, not derived, and said; on the others everything the same. */
static void alone_keys(size_t f, const tirenv_tire *t, const tirenv_tir_origin *o,
                       const tirenv_tire *read, const tirenv_tire *full,
                       const tirenv_tir_origin *o_full)
{
    same_keys(t, full, TIRENV_TIR_RING | TIRENV_TIR_CAM);
    if (f == N_MF - 1) {
        assert_int_equal(o->own & TIRENV_TIR_CAM, TIRENV_TIR_CAM);
        assert_int_equal(o->derived, o_full->derived & ~TIRENV_TIR_SPRINGS);
        assert_int_equal(o_full->derived & TIRENV_TIR_SPRINGS, TIRENV_TIR_SPRINGS);
        same_keys(t, read, TIRENV_TIR_SPRINGS);
        assert_non_null(strstr(o->note, "no [ENVELOPING_SPRINGS]: the springs model not "
                                        "derived (not used here)"));
    } else {
        same_keys(t, full, TIRENV_TIR_SPRINGS);
        assert_int_equal(o->derived, o_full->derived);
        assert_string_equal(o->note, o_full->note);
    }
}

/* File f derived whole (into full, o_full) and for one model alone, need TIRENV_TIR_ONLY |
 * model (into t, o; read: the tire as read, before either). */
static void derive_alone(size_t f, unsigned model, tirenv_tire *t, tirenv_tir_origin *o,
                         tirenv_tire *read, tirenv_tire *full, tirenv_tir_origin *o_full)
{
    derived(f, full, o_full);
    tirenv_diag d;
    *t = tirenv_tire_default();
    assert_int_equal(tirenv_tir_read(mf_files[f], t, &d), TIRENV_OK);
    *read = *t;
    assert_int_equal(tirenv_tir_derive(mf_files[f], t, TIRENV_TIR_ONLY | model, o, &d),
                     TIRENV_OK);
    print_message("%s, the %s alone: %s\n", mf_files[f],
                  model == TIRENV_TIR_CAM ? "cam" : "ring", o->note);
}

/* need TIRENV_TIR_ONLY | TIRENV_TIR_CAM (the caller uses the cam alone, as tirenv flat and
 * envelope --model cam do): a file whose cam laws are all its own (the 430/50R38: Q_RA1,
 * Q_RA2, Q_FZ2 = 0) gets the same cam, bit for bit, with no ring or springs model derived
 * (they keep the values passed in, said in the note); a file whose Q_FZ2 is derived on the
 * ring (tir_mftyre.tir) gets the same ring and cam as without the flag, its ring searched on
 * its own contact law, and no springs model identified on that ring (alone_keys). The files
 * without a contact law of their own derive theirs on the ring, so the flag changes nothing
 * there either (the 185/80R14, the cheapest). */
static void test_cam_alone(void **state)
{
    (void)state;
    const size_t files[] = {2, N_OWN_LAW, N_MF - 1};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        const size_t f = files[i];
        if ((int)f < (int)MF_FIRST || f >= MF_END)
            continue;  /* the sanitizer build: as test_derived_pairs */
        tirenv_tire full, t, read;
        tirenv_tir_origin o_full, o;
        derive_alone(f, TIRENV_TIR_CAM, &t, &o, &read, &full, &o_full);
        same_keys(&t, &full, TIRENV_TIR_CAM);
        if (f == N_OWN_LAW) {
            assert_int_equal(o.derived, 0);
            assert_int_equal(o.own & TIRENV_TIR_CAM, TIRENV_TIR_CAM);
            same_keys(&t, &read, TIRENV_TIR_SPRINGS | TIRENV_TIR_RING);
            assert_non_null(strstr(o.note, "no [ENVELOPING_RING]: the ring model not derived"));
            assert_non_null(strstr(o.note, "no [ENVELOPING_SPRINGS]: the springs model not "
                                           "derived"));
            assert_true(isnan(o.cam_ring_deflection));
        } else {
            alone_keys(f, &t, &o, &read, &full, &o_full);
        }
    }
}

/* need TIRENV_TIR_ONLY | TIRENV_TIR_RING (the ring alone, as tirenv flat and envelope
 * --model ring and the FMU use it): the same ring and cam as the whole derivation, bit for
 * bit; on a file with a contact law of its own (tir_mftyre.tir), whose ring is searched on its
 * laws alone, no springs model derived on it (kept as passed in, said in the note), elsewhere
 * (the 185/80R14, whose ring's pretension is chosen with its springs model) the whole
 * derivation. */
static void test_ring_alone(void **state)
{
    (void)state;
    const size_t files[] = {2, N_MF - 1};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        const size_t f = files[i];
        if ((int)f < (int)MF_FIRST || f >= MF_END)
            continue;  /* the sanitizer build: as test_derived_pairs */
        tirenv_tire full, t, read;
        tirenv_tir_origin o_full, o;
        derive_alone(f, TIRENV_TIR_RING, &t, &o, &read, &full, &o_full);
        alone_keys(f, &t, &o, &read, &full, &o_full);
        tirenv_tire t_null = read; /* origin and diag may be NULL: the same tire */
        assert_int_equal(tirenv_tir_derive(mf_files[f], &t_null,
                                           TIRENV_TIR_ONLY | TIRENV_TIR_RING, NULL, NULL),
                         TIRENV_OK);
        same_keys(&t_null, &t, TIRENV_TIR_SPRINGS | TIRENV_TIR_RING | TIRENV_TIR_CAM);
    }
}

/* The derived models follow the file's pressure dependence: MF-Tyre 6.1's vertical law at
 * INFLPRES is the one at NOMPRES times 1 + PFZ1*(INFLPRES - NOMPRES)/NOMPRES. With a linear law
 * of the file's own (Q_FZ2 = 0 given) the stiffness at FNOMIN is VERTICAL_STIFFNESS times that
 * factor, so two pressures give the ratio of the factors (here 1.2625/0.895) to the
 * inversion's 1e-7. Without Q_FZ2 (identified on the pressure's ring) the deflection at
 * FNOMIN is that of the law with the factor and the identified Q_FZ2 (to the derivation's
 * 1e-6), and the models carry FNOMIN there; where none can be identified, the linear law. */
static void test_pressure_dependence(void **state)
{
    (void)state;
    char dir[] = "/tmp/tirenv_onetire_XXXXXX";
    assert_non_null(mkdtemp(dir));
    const double p[2] = {1.6e5, 2.9e5}, pfz1 = 0.7, p0 = 2.0e5, R0 = 0.3135, c_z = 209651.5;
    for (int own = 1; own >= 0; own--) {
        double k[2][2];
        for (int i = 0; i < 2; i++) {
            char path[128], text[1024];
            const double factor = 1 + pfz1 * (p[i] - p0) / p0;
            snprintf(path, sizeof path, "%s/p%d.tir", dir, i);
            snprintf(text, sizeof text,
                     "[UNITS]\nLENGTH = 'meter'\nFORCE = 'newton'\nPRESSURE = 'pascal'\n"
                     "[DIMENSION]\nUNLOADED_RADIUS = %g\nWIDTH = 0.205\nASPECT_RATIO = 0.6\n"
                     "[OPERATING_CONDITIONS]\nINFLPRES = %g\nNOMPRES = %g\n"
                     "[VERTICAL]\nFNOMIN = 4000\nVERTICAL_STIFFNESS = %.17g\nPFZ1 = %g\n%s",
                     R0, p[i], p0, c_z, pfz1, own ? "Q_FZ2 = 0\n" : "");
            tirenv_test_write_text(path, text);
            tirenv_tire t = tirenv_tire_default();
            tirenv_diag d;
            tirenv_tir_origin o;
            assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
            assert_int_equal(tirenv_tir_derive(path, &t, TIRENV_TIR_SPRINGS | TIRENV_TIR_RING,
                                               &o, &d), TIRENV_OK);
            /* Without Q_FZ2 at 2.9 bar (factor 1.315) the car-sized ring's air alone is
             * stiffer at FNOMIN than any law with VERTICAL_STIFFNESS its tangent: no Q_FZ2
             * deflects with it, the linear law is kept and said. */
            const int linear = own || i == 1;
            assert_int_equal(o.derived & TIRENV_TIR_VERTICAL, linear ? 0 : TIRENV_TIR_VERTICAL);
            if (!own && linear)
                assert_non_null(strstr(o.note, "no Q_FZ2 of its own and none derived, the "
                                                "file's linear law kept (the derived ring and "
                                                "the Q_FZ2 identified on it found no common "
                                                "deflection at FNOMIN"));
            const tirenv_model_type *types[] = {tirenv_model_springs, tirenv_model_ring};
            for (int m = 0; m < 2; m++) {
                tirenv_flat fl;
                flat_states(types[m], &t, 1, &o.fnomin, &fl);
                k[m][i] = o.fnomin / fl.deflection;
                assert_near(fl.deflection, o.rho_nominal, 0, 1e-7);
            }
            /* The cam takes the same law (section 7.3), PFZ1's factor included: its deflection
             * at FNOMIN is the closed form's to round-off (1e-12) and, where the law is the
             * file's own, the derivation's; where Q_FZ2 was identified on the ring, that law
             * deflects with the ring to the derivation's 1e-6. */
            tirenv_flat cam;
            flat_states(tirenv_model_cam, &t, 1, &o.fnomin, &cam);
            const double q2c = t.cam.q_fz2, q1c = tirenv_cam_q_fz1(c_z, R0, 4000, q2c);
            const double closed = q2c == 0 ? 4000 / (factor * c_z)
                                : R0 * (-q1c + sqrt(q1c * q1c + 4 * q2c / factor)) / (2 * q2c);
            print_message("p %g Pa: cam %.4f mm at FNOMIN, closed form %.4f mm, derived "
                          "models %.4f mm\n", p[i], 1e3 * cam.deflection, 1e3 * closed,
                          1e3 * o.rho_nominal);
            assert_near(cam.deflection, closed, 0, 1e-12);
            assert_near(cam.deflection, o.rho_nominal, 0, linear ? 1e-12 : 2e-6);
            assert_non_null(strstr(o.note, "the vertical law times PFZ1's pressure factor"));
            if (linear) {
                assert_near(k[0][i], c_z * factor, 0, 1e-6);
                assert_true(t.cam.q_fz2 == 0);
            } else {
                const double q2 = t.cam.q_fz2, q1 = tirenv_cam_q_fz1(c_z, R0, 4000, q2);
                print_message("p %g Pa: Q_FZ2 %.6g, secant %.1f kN/m\n", p[i], q2,
                              k[1][i] / 1e3);
                assert_true(q2 > 0);
                assert_near(o.rho_nominal, tirenv_cam_vertical_root(R0, q1, q2, 1 / factor), 0,
                            2e-6);
            }
            unlink(path);
        }
        if (own) {
            const double want = (1 + pfz1 * (p[1] - p0) / p0) / (1 + pfz1 * (p[0] - p0) / p0);
            assert_near(k[0][1] / k[0][0], want, 0, 1e-6);
            assert_near(k[1][1] / k[1][0], want, 0, 1e-6);
        }
    }
    rmdir(dir);
}

/* MF-Tyre's rule: a file without INFLPRES is at its NOMPRES (PFZ1's factor 1), said, not at the
 * pressure of the tire it was read over (the default's 120 kPa); with INFLPRES, its own. A file
 * with every model's section, so nothing is derived. */
static void test_inflpres_is_nompres(void **state)
{
    (void)state;
    for (int given = 0; given < 2; given++) {
        char path[64], text[512];
        snprintf(text, sizeof text,
                 "[OPERATING_CONDITIONS]\n%sNOMPRES = 250000\n[VERTICAL]\nPFZ1 = 0.7\n"
                 "[ENVELOPING_SPRINGS]\nRADIAL_STIFFNESS = 407000\n[ENVELOPING_RING]\n"
                 "FOUNDATION_STIFFNESS = 1.1e5\n[CONTACT_PATCH]\nQ_RA1 = 0.6\nQ_RA2 = 0.7\n",
                 given ? "INFLPRES = 90000\n" : "");
        tirenv_test_write_temp(path, "onetire_p", text);
        tirenv_tire t = tirenv_tire_default();
        tirenv_diag d;
        tirenv_tir_origin o;
        assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
        assert_int_equal(tirenv_tir_derive(path, &t, 0, &o, &d), TIRENV_OK);
        print_message("INFLPRES %s: %g Pa, note '%s'\n", given ? "given" : "not given", t.ring.p,
                      o.note);
        assert_true(t.ring.p == (given ? 90000 : 250000));
        assert_true((strstr(o.note, "no INFLPRES: NOMPRES's 250 kPa") == NULL) == given);
        unlink(path);
    }
}

/* A file's own Q_FZ1 (MF-Tyre 6.1 takes it where not 0, docs/models.md 7.3): with its Q_FZ2
 * 21.7 the car tire's VERTICAL_STIFFNESS would give Q_FZ1 = 12.6; the file says 19.3. The
 * derived springs and ring models carry FNOMIN at the deflection of the file's law (to the
 * derivation's 1e-7), and the cam deflects there too: the closed form's root of
 * Q_FZ1*s + Q_FZ2*s^2 = 1, to round-off (1e-12). The note says the file's Q_FZ1 is taken. */
static void test_own_q_fz1(void **state)
{
    (void)state;
    char path[64];
    const double R0 = 0.3135, F0 = 4000, q1 = 19.3, q2 = 21.7;
    tirenv_test_write_temp(path, "onetire_q",
                           "[DIMENSION]\nUNLOADED_RADIUS = 0.3135\nWIDTH = 0.205\n"
                           "ASPECT_RATIO = 0.6\n[VERTICAL]\nFNOMIN = 4000\n"
                           "VERTICAL_STIFFNESS = 200000\nQ_FZ1 = 19.3\nQ_FZ2 = 21.7\n");
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    tirenv_tir_origin o;
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
    assert_int_equal(tirenv_tir_derive(path, &t, TIRENV_TIR_SPRINGS | TIRENV_TIR_RING, &o, &d),
                     TIRENV_OK);
    print_message("note: %s\n", o.note);
    assert_non_null(strstr(o.note, "the vertical law takes the file's Q_FZ1 = 19.3, not one "
                                   "from VERTICAL_STIFFNESS 200 kN/m"));
    assert_int_equal(o.own & TIRENV_TIR_VERTICAL, TIRENV_TIR_VERTICAL);
    const double closed = R0 * (-q1 + sqrt(q1 * q1 + 4 * q2)) / (2 * q2);
    const tirenv_model_type *types[] = {tirenv_model_springs, tirenv_model_ring,
                                        tirenv_model_cam};
    for (int m = 0; m < 3; m++) {
        tirenv_flat fl;
        flat_states(types[m], &t, 1, &F0, &fl);
        print_message("%s: %.4f mm at FNOMIN (closed form %.4f mm)\n",
                      tirenv_model_type_name(types[m]), 1e3 * fl.deflection, 1e3 * closed);
        assert_near(fl.deflection, closed, 0, types[m] == tirenv_model_cam ? 1e-12 : 1e-7);
    }
    assert_near(o.rho_nominal, closed, 0, 1e-12);
    unlink(path);
}

/* A file that lacks what a model needs: refused naming the file and key when the model is needed,
 * said in the note (and the tire left as it was) when it is not. */
static void test_refuses_naming_the_key(void **state)
{
    (void)state;
    char path[64];
    tirenv_test_write_temp(path, "onetire_nofnomin", "[DIMENSION]\nUNLOADED_RADIUS = 0.376\n"
                                                     "[VERTICAL]\nVERTICAL_STIFFNESS = 1.75e5\n");
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    tirenv_tir_origin o;
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
    const tirenv_tire before = t;
    assert_int_equal(tirenv_tir_derive(path, &t, TIRENV_TIR_SPRINGS, &o, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "FNOMIN");
    assert_string_equal(d.file, path);
    assert_non_null(strstr(d.message, "ENVELOPING_SPRINGS"));
    assert_memory_equal(&t, &before, sizeof t);
    assert_int_equal(tirenv_tir_derive(path, &t, TIRENV_TIR_RING, &o, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "FNOMIN");
    assert_int_equal(tirenv_tir_derive(path, &t, 0, &o, &d), TIRENV_OK);
    assert_int_equal(o.derived, 0);
    assert_non_null(strstr(o.note, "no FNOMIN"));
    assert_memory_equal(&t, &before, sizeof t);
    unlink(path);
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
    tirenv_test_write_text(path,
                           "[MDI_HEADER]\nFILE_TYPE = 'tir'\n! a header comment\n$---rule\n"
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
    tirenv_test_read_text(path, text, sizeof text);
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
        cmocka_unit_test(test_derived_pairs),
        cmocka_unit_test(test_205_pairs),
        cmocka_unit_test(test_205_identified_on_both),
        cmocka_unit_test(test_derived_from_mftyre),
        cmocka_unit_test(test_cam_alone),
        cmocka_unit_test(test_ring_alone),
        cmocka_unit_test(test_pressure_dependence),
        cmocka_unit_test(test_own_q_fz1),
        cmocka_unit_test(test_inflpres_is_nompres),
        cmocka_unit_test(test_refuses_naming_the_key),
        cmocka_unit_test(test_update_in_place),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
