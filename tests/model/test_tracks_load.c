/* Several tracks with a load that changes and a ground that reaches the hub (tracks.h,
 * docs/models.md sections 13.4, 2.5 and 1.7): tirenv_model_set_load on a model set with two
 * tracks gives the curve of tracks set afresh at the new load; the hub's clearance is checked
 * against every track, not only the first; a model set with several tracks refuses to save or
 * restore a state (a state is one track's).
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/tirenv.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double load_1 = 11903.6, load_2 = 15500.0;  /* N */

enum { N_POS = 121 };

/* set_load(load_2) after set_tracks(load_1) and a sweep, against set_tracks(load_2) on a fresh
 * instance: the same curve bit for bit for every type (the equilibrium over the tracks starts
 * afresh after a load change, and each track's state keeps nothing a load changes but what its
 * set_load recomputes). */
static void test_set_load_every_track(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_test_default_tire();
    tirenv_profile *cleat = tirenv_profile_cleat(0.3, 0.06);
    tirenv_profile *step = tirenv_profile_step(0.1, 0.03);
    const tirenv_profile *two[2] = {cleat, step};
    const tirenv_model_type *types[] = {tirenv_model_rigid, tirenv_model_springs,
                                        tirenv_model_ring, tirenv_model_cam, tirenv_model_point};
    double x[N_POS];
    for (size_t k = 0; k < N_POS; ++k)
        x[k] = -0.6 + 0.01 * (double)k;
    static tirenv_point moved[N_POS], fresh[N_POS];
    for (size_t t = 0; t < sizeof types / sizeof types[0]; ++t) {
        tirenv_diag d;
        tirenv_model *a = tirenv_model_alloc(types[t], &tire);
        tirenv_model *b = tirenv_model_alloc(types[t], &tire);
        assert_int_equal(tirenv_model_set_tracks(a, 2, two, NULL, load_1, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_envelope(a, N_POS, x, moved, NULL, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_set_load(a, load_2, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_tracks(a), 2);
        assert_int_equal(tirenv_model_envelope(a, N_POS, x, moved, NULL, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_set_tracks(b, 2, two, NULL, load_2, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_envelope(b, N_POS, x, fresh, NULL, &d), TIRENV_OK);
        for (size_t k = 0; k < N_POS; ++k) {
            assert_bits_equal(moved[k].h, fresh[k].h);
            assert_bits_equal(moved[k].fz, fresh[k].fz);
            assert_bits_equal(moved[k].slope, fresh[k].slope);
        }
        tirenv_model_free(a);
        tirenv_model_free(b);
    }
    tirenv_profile_free(cleat);
    tirenv_profile_free(step);
}

/* A wall 2 m tall under the second track only: refused where it stands within R0 of the hub,
 * whichever track it is on; far from it the model runs. */
static void test_clearance_every_track(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_test_default_tire();
    const double xf[2] = {-5, 5}, zf[2] = {0, 0};
    const double xw[4] = {-5, 0.0, 0.0, 5}, zw[4] = {0, 0, 2.0, 2.0};
    tirenv_profile *flat = tirenv_profile_alloc(2, xf, zf);
    tirenv_profile *wall = tirenv_profile_alloc(4, xw, zw);
    const tirenv_profile *orders[2][2] = {{flat, wall}, {wall, flat}};
    for (int o = 0; o < 2; ++o) {
        tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &tire);
        tirenv_diag d;
        assert_int_equal(tirenv_model_set_tracks(m, 2, orders[o], NULL, load_1, &d), TIRENV_OK);
        tirenv_point pt;
        assert_int_equal(tirenv_model_eval(m, -2.0, &pt, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_eval(m, -0.2, &pt, &d), TIRENV_ERANGE);
        assert_non_null(strstr(d.message, "clears the ground"));
        tirenv_model_free(m);
    }
    tirenv_profile_free(flat);
    tirenv_profile_free(wall);
}

static void test_state_one_track(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_test_default_tire();
    tirenv_profile *cleat = tirenv_profile_cleat(0.3, 0.06);
    tirenv_profile *step = tirenv_profile_step(0.1, 0.03);
    const tirenv_profile *two[2] = {cleat, step};
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &tire);
    tirenv_diag d;
    const size_t size = tirenv_model_state_size(m);
    unsigned char *buf = malloc(size);
    assert_non_null(buf);
    assert_int_equal(tirenv_model_set(m, cleat, load_1, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_state_save(m, buf, size, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set_tracks(m, 2, two, NULL, load_1, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_state_save(m, buf, size, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "2 tracks"));
    assert_int_equal(tirenv_model_state_restore(m, buf, size, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_tracks(m), 2);  /* left as it was */
    free(buf);
    tirenv_model_free(m);
    tirenv_profile_free(cleat);
    tirenv_profile_free(step);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_set_load_every_track),
        cmocka_unit_test(test_clearance_every_track),
        cmocka_unit_test(test_state_one_track),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
