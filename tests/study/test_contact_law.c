/* SPDX-License-Identifier: Apache-2.0 */
/* The network's tire (docs/models.md section 14.3): the contact law's monotone cubic is exact
 * at its knots, monotone between them and its inverse is the same curve's; the law a network
 * records of the embedded data set gives back every case's contact length at its load. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "testutil.h"
#include "tirenv/tirenv.h"

/* Knots of uneven spacing and uneven slopes (a fast rise, then nearly flat): where a cubic
 * without Fritsch and Carlson's limits overshoots. */
static tirenv_contact_law uneven_law(void)
{
    static const double G[] = {1234.5, 2871.3, 3017.9, 7452.2, 7460.1, 15893.7, 31002.4};
    static const double l[] = {0.1131, 0.2187, 0.2611, 0.2639, 0.3302, 0.33021, 0.4913};
    tirenv_contact_law law = {.n = sizeof G / sizeof G[0]};
    memcpy(law.load, G, sizeof G);
    memcpy(law.l_c, l, sizeof l);
    return law;
}

/* Knots exact both ways (bit for bit); 20001 loads across: ascending, each within its
 * segment's knots, and the inverse of each gives a load whose contact length is the same
 * to 1e-12 m (adjacent doubles of load: the curve's slope times a few ulps of 3e4 N). */
static void test_monotone_exact_inverse(void **state)
{
    (void)state;
    const tirenv_contact_law law = uneven_law();
    tirenv_diag d;
    assert_int_equal(tirenv_contact_law_check(&law, &d), TIRENV_OK);
    for (size_t k = 0; k < law.n; k++) {
        double l_c = 0, G = 0;
        assert_int_equal(tirenv_contact_law_eval(&law, law.load[k], &l_c, &d), TIRENV_OK);
        assert_true(l_c == law.l_c[k]);
        assert_int_equal(tirenv_contact_law_inverse(&law, law.l_c[k], &G, &d), TIRENV_OK);
        assert_true(G == law.load[k]);
    }
    const size_t n = 20001;
    double prev = 0;
    size_t seg = 0;
    for (size_t i = 0; i < n; i++) {
        const double G = law.load[0] + (law.load[law.n - 1] - law.load[0]) * (double)i /
                                               (double)(n - 1);
        double l_c = 0, G_back = 0, l_back = 0;
        assert_int_equal(tirenv_contact_law_eval(&law, G, &l_c, &d), TIRENV_OK);
        assert_true(l_c >= prev);
        while (seg + 2 < law.n && G > law.load[seg + 1])
            seg++;
        assert_true(l_c >= law.l_c[seg] && l_c <= law.l_c[seg + 1]);
        assert_int_equal(tirenv_contact_law_inverse(&law, l_c, &G_back, &d), TIRENV_OK);
        assert_int_equal(tirenv_contact_law_eval(&law, G_back, &l_back, &d), TIRENV_OK);
        assert_near(l_back, l_c, 1e-12, 0);
        prev = l_c;
    }
    /* Smooth: a load just inside a knot is just beside its value (continuity), not a step. */
    double a = 0, b = 0;
    assert_int_equal(tirenv_contact_law_eval(&law, nextafter(law.load[3], 0), &a, &d), 0);
    assert_int_equal(tirenv_contact_law_eval(&law, nextafter(law.load[3], 1e9), &b, &d), 0);
    assert_near(a, law.l_c[3], 1e-12, 0);
    assert_near(b, law.l_c[3], 1e-12, 0);
}

/* Outside the knots: TIRENV_ERANGE naming the quantity; a descending law is refused. */
static void test_refused(void **state)
{
    (void)state;
    tirenv_contact_law law = uneven_law();
    tirenv_diag d;
    double y = -1;
    assert_int_equal(tirenv_contact_law_eval(&law, nextafter(law.load[0], 0), &y, &d),
                     TIRENV_ERANGE);
    assert_string_equal(d.field, "load");
    assert_true(y == -1);
    assert_int_equal(tirenv_contact_law_inverse(&law, 0.5, &y, &d), TIRENV_ERANGE);
    assert_string_equal(d.field, "contact length");
    law.l_c[4] = law.l_c[3];
    assert_int_equal(tirenv_contact_law_check(&law, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "point 5"));
}

/* The law of the embedded data set by its source model (the ring of tire.tir): every case's
 * own load gives back its contact length bit for bit (the cases are knots, and the cubic
 * takes a knot's value there), and the law ascends. */
static void test_law_of_embedded_data(void **state)
{
    (void)state;
    const char *dir = TIRENV_DATA_DIR "/dataset";
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    assert_int_equal(tirenv_tir_read(TIRENV_DATA_DIR "/dataset/tire.tir", &t, &d), TIRENV_OK);
    tirenv_dataset ds;
    if (tirenv_dataset_read(dir, t.springs.R0, &ds, &d))
        fail_msg("%s:%zu: %s: %s", d.file, d.line, d.field, d.message);
    tirenv_dataset_source src;
    assert_int_equal(tirenv_dataset_source_read(dir, &src, &d), TIRENV_OK);
    const tirenv_model_type *source = tirenv_model_type_find(src.model);
    assert_non_null(source);
    tirenv_contact_law law;
    char what[128];
    assert_int_equal(tirenv_contact_law_of_data(&ds, source, &t, &law, what, sizeof what, &d),
                     TIRENV_OK);
    assert_non_null(strstr(what, "through the cases"));
    assert_int_equal(tirenv_contact_law_check(&law, &d), TIRENV_OK);
    for (size_t i = 0; i < ds.n; i++) {
        double l_c = 0;
        assert_int_equal(tirenv_contact_law_eval(&law, ds.cases[i].load, &l_c, &d), TIRENV_OK);
        assert_true(l_c == ds.cases[i].contact_length);
    }
    /* Another tire's ring (the 185/80R14 car tire's, derived from its MF-Tyre keys) with the
     * same cases: no ascending law, and the message says the tire is not the data's. */
    tirenv_tire car = tirenv_tire_default();
    tirenv_tir_origin origin;
    const char *car_path = TIRENV_SAMPLES "/tir/mf_185_80R14.tir";
    assert_int_equal(tirenv_tir_read(car_path, &car, &d), TIRENV_OK);
    assert_int_equal(tirenv_tir_derive(car_path, &car, TIRENV_TIR_RING, &origin, &d), TIRENV_OK);
    assert_int_equal(tirenv_contact_law_of_data(&ds, source, &car, &law, what, sizeof what, &d),
                     TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "the ring model of this tire and the data set's cases"));
    assert_non_null(strstr(d.message, "expected the tire that simulated the data"));
    tirenv_dataset_free(&ds);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_monotone_exact_inverse),
        cmocka_unit_test(test_refused),
        cmocka_unit_test(test_law_of_embedded_data),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
