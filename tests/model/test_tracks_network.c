/* The network over several tracks (tracks.h, docs/models.md section 13) after a contact
 * length was made into a load (tirenv_model_load_for_contact_length): every track's state
 * gets the contact length, those made before it as well as after, so each track reaches the
 * network at exactly that l_c; the set in place stays in place, as with one track. And the
 * permission to extrapolate (tirenv_model_set_extrapolate) reaches every track's state too.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/tirenv.h"
#include "tirenv/nn.h"

#include <math.h>
#include <stdlib.h>

static void test_contact_length_reaches_every_track(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_test_tire_before_identify();
    const double R0 = tire.springs.R0, l_c = 0.3313, L = 0.1873, H = 0.0617;
    enum { N = 301 };
    static double x[N], h[N];
    static tirenv_point before[N], pt[N];
    for (size_t k = 0; k < N; ++k)
        x[k] = -0.6 + 0.004 * (double)k;
    tirenv_nn *nn = tirenv_test_made_up_network(977, 61);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_nn, &tire);
    assert_non_null(m);
    tirenv_diag d;
    assert_int_equal(tirenv_model_set_network(m, nn, 0, &d), TIRENV_OK);
    /* Two tracks of the same cleat in separate objects: two states, the mean of equal
     * points (weights 1/2, exact). */
    tirenv_profile *a = tirenv_profile_cleat(L, H), *b = tirenv_profile_cleat(L, H);
    const tirenv_profile *two[2] = {a, b};
    /* N: a trained regime before the contact length is given (the springs model's contact
     * length, which a network without a recorded law takes: 0.3 m at 15.1 kN) */
    const double load_0 = 15000;
    assert_int_equal(tirenv_model_set_tracks(m, 2, two, NULL, load_0, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_tracks(m), 2);
    assert_int_equal(tirenv_model_envelope(m, N, x, before, NULL, &d), TIRENV_OK);

    double load;
    assert_int_equal(tirenv_model_load_for_contact_length(m, l_c, &load, &d), TIRENV_OK);
    /* The set in place is untouched. */
    assert_int_equal(tirenv_model_tracks(m), 2);
    assert_int_equal(tirenv_model_envelope(m, N, x, pt, NULL, &d), TIRENV_OK);
    for (size_t k = 0; k < N; ++k)
        assert_bits_equal(pt[k].h, before[k].h);

    /* Set again at that load: both tracks see l_c exactly, so the mean is the paper's curve
     * at l_c bit for bit (a load turned back into l_c by the springs would differ in the
     * last bits, and the network's output with it). */
    assert_int_equal(tirenv_model_set_tracks(m, 2, two, NULL, load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_tracks(m), 2);
    assert_int_equal(tirenv_model_envelope(m, N, x, pt, NULL, &d), TIRENV_OK);
    assert_int_equal(tirenv_nn_envelope(nn, R0, l_c, L, H, N, x, h, &d), TIRENV_OK);
    size_t raised = 0;
    for (size_t k = 0; k < N; ++k) {
        assert_bits_equal(pt[k].h, h[k]);
        raised += h[k] > 1e-4;
    }
    assert_true(raised > N / 10);

    /* A third track made after the contact length was given gets it too. */
    tirenv_profile *c = tirenv_profile_cleat(L, H);
    const tirenv_profile *three[3] = {a, b, c};
    const double w[3] = {0.25, 0.5, 0.25};
    assert_int_equal(tirenv_model_set_tracks(m, 3, three, w, load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_tracks(m), 3);
    assert_int_equal(tirenv_model_envelope(m, N, x, pt, NULL, &d), TIRENV_OK);
    for (size_t k = 0; k < N; ++k)
        assert_bits_equal(pt[k].h, h[k]);

    tirenv_model_free(m);
    tirenv_nn_free(nn);
    tirenv_profile_free(a);
    tirenv_profile_free(b);
    tirenv_profile_free(c);
}

/* A cleat far higher than the network saw (0.2 m against at most 0.1 m) on two tracks: refused
 * by default; allowed, whether given before the tracks' states exist or after; refused again
 * when withdrawn; the allowed mean equals one track's curve. */
static void test_extrapolate_reaches_every_track(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_test_tire_before_identify();
    const double l_c = 0.3313, L = 0.1873, H = 0.2;
    enum { N = 201 };
    static double x[N];
    static tirenv_point one[N], pt[N];
    for (size_t k = 0; k < N; ++k)
        x[k] = -0.6 + 0.006 * (double)k;
    tirenv_nn *nn = tirenv_test_made_up_network(977, 61);
    tirenv_profile *a = tirenv_profile_cleat(L, H), *b = tirenv_profile_cleat(L, H);
    const tirenv_profile *two[2] = {a, b};
    tirenv_diag d;
    double load;
    for (int before = 0; before < 2; ++before) {
        tirenv_model *m = tirenv_model_alloc(tirenv_model_nn, &tire);
        assert_non_null(m);
        assert_int_equal(tirenv_model_set_network(m, nn, 0, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_load_for_contact_length(m, l_c, &load, &d), TIRENV_OK);
        if (before) {
            tirenv_model_set_extrapolate(m, 1);  /* no further state exists yet */
        } else {
            assert_int_equal(tirenv_model_set_tracks(m, 2, two, NULL, load, &d), TIRENV_ERANGE);
            tirenv_model_set_extrapolate(m, 1);  /* the further state exists */
        }
        assert_int_equal(tirenv_model_set(m, a, load, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_envelope(m, N, x, one, NULL, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_set_tracks(m, 2, two, NULL, load, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_tracks(m), 2);
        assert_int_equal(tirenv_model_envelope(m, N, x, pt, NULL, &d), TIRENV_OK);
        for (size_t k = 0; k < N; ++k)
            assert_bits_equal(pt[k].h, one[k].h);
        tirenv_model_set_extrapolate(m, 0);
        assert_int_equal(tirenv_model_set_tracks(m, 2, two, NULL, load, &d), TIRENV_ERANGE);
        tirenv_model_free(m);
    }
    tirenv_nn_free(nn);
    tirenv_profile_free(a);
    tirenv_profile_free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_contact_length_reaches_every_track),
        cmocka_unit_test(test_extrapolate_reaches_every_track),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
