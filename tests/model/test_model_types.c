/* The table of model types: every model, the network and the point contact included, is a
 * type record whose properties (flags, fitted parameters, summary, plot style) say what it
 * can do, and those properties hold when the models run. SPDX-License-Identifier:
 * Apache-2.0 */
#include "testutil.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/tirenv.h"
#include "tirenv/nn.h"
#include "tirenv/nn_road.h"
#include "tirenv/plot.h"
#include "tirenv/study.h"

static size_t n_types(void)
{
    size_t n = 0;
    while (tirenv_model_types()[n])
        ++n;
    return n;
}

/* Names unique and found by name; summaries short; the flags and the fitted parameters agree;
 * every parameter is a .tir key of a double in the tire. */
static void test_records(void **state)
{
    (void)state;
    const size_t n = n_types();
    assert_true(n >= 6);
    const tirenv_tire tire = tirenv_tire_default();
    for (size_t i = 0; i < n; ++i) {
        const tirenv_model_type *t = tirenv_model_types()[i];
        const char *name = tirenv_model_type_name(t);
        assert_true(name[0] != '\0');
        assert_ptr_equal(tirenv_model_type_find(name), t);
        for (size_t j = 0; j < i; ++j)
            assert_string_not_equal(name, tirenv_model_type_name(tirenv_model_types()[j]));
        const char *summary = tirenv_model_type_summary(t);
        assert_true(summary[0] != '\0' && strlen(summary) <= 48);
        size_t np, np_max;
        const tirenv_model_param *p = tirenv_model_type_params(t, &np, &np_max);
        const int fittable = (tirenv_model_type_flags(t) & TIRENV_MODEL_FITTABLE) != 0;
        assert_int_equal(fittable, p != NULL && np > 0);
        assert_true(np <= np_max && np_max <= TIRENV_FIT_MAX_PARAMS);
        for (size_t k = 0; k < np_max; ++k) {
            assert_true(p[k].offset + sizeof(double) <= sizeof(tirenv_tire));
            const double v = *(const double *)((const char *)&tire + p[k].offset);
            assert_true(v > p[k].lower);  /* the default tire is inside the fit's domain */
            /* The key sets the field it claims. */
            char assignment[96];
            snprintf(assignment, sizeof assignment, "%s=%.17g", p[k].key, v * 1.0625);
            tirenv_tire changed = tire;
            tirenv_diag d;
            assert_int_equal(tirenv_tir_set(&changed, assignment, &d), TIRENV_OK);
            assert_near(*(const double *)((const char *)&changed + p[k].offset), v * 1.0625,
                        0, 1e-15);
        }
    }
    assert_null(tirenv_model_type_find("no-such-model"));
    assert_null(tirenv_model_type_find(NULL));
    assert_ptr_equal(tirenv_model_type_find("nn"), tirenv_model_nn);
    assert_ptr_equal(tirenv_model_type_find("point"), tirenv_model_point);
    /* What tirenv fit identifies: the study's springs and cam, and the ring (its foundation
     * and tread; its belt's bending and tension as the optional ones). */
    assert_true(tirenv_model_type_flags(tirenv_model_springs) & TIRENV_MODEL_FITTABLE);
    assert_true(tirenv_model_type_flags(tirenv_model_cam) & TIRENV_MODEL_FITTABLE);
    assert_true(tirenv_model_type_flags(tirenv_model_ring) & TIRENV_MODEL_FITTABLE);
    size_t n_ring, n_ring_max;
    const tirenv_model_param *rp = tirenv_model_type_params(tirenv_model_ring, &n_ring,
                                                            &n_ring_max);
    assert_int_equal(n_ring, 2);
    assert_int_equal(n_ring_max, 4);
    assert_string_equal(rp[0].key, "FOUNDATION_STIFFNESS");
    assert_string_equal(rp[1].key, "TREAD_STIFFNESS");
    assert_true(tirenv_model_type_flags(tirenv_model_nn) & TIRENV_MODEL_NEEDS_NETWORK);
}

/* Each type's flags and tracks rule, those the driver derives from the record (FITTABLE,
 * NEEDS_NETWORK, EQUILIBRIUM) included, as docs/models.md sections 1.6 and 13 table them: a
 * deformable model, and only one, combines tracks by the equilibrium of its summed forces. */
static void test_record_flags(void **state)
{
    (void)state;
    enum {
        FIT = TIRENV_MODEL_FITTABLE,
        NET = TIRENV_MODEL_NEEDS_NETWORK,
        LC = TIRENV_MODEL_CONTACT_LENGTH,
        STREAM = TIRENV_MODEL_STREAMS,
        EQ = TIRENV_MODEL_EQUILIBRIUM
    };
    static const struct {
        const char *name;
        unsigned flags;
        tirenv_tracks_rule tracks;
    } want[] = {
        {"rigid", STREAM, TIRENV_TRACKS_HIGHEST},
        {"springs", FIT | LC | STREAM | EQ, TIRENV_TRACKS_EQUILIBRIUM},
        {"ring", FIT | LC | STREAM | EQ, TIRENV_TRACKS_EQUILIBRIUM},
        {"cam", FIT | LC | STREAM, TIRENV_TRACKS_MEAN},
        {"nn", NET | STREAM, TIRENV_TRACKS_MEAN},
        {"point", STREAM, TIRENV_TRACKS_MEAN},
    };
    const size_t n = sizeof want / sizeof want[0];
    assert_int_equal(n_types(), n);
    for (size_t i = 0; i < n; ++i) {
        const tirenv_model_type *t = tirenv_model_type_find(want[i].name);
        assert_non_null(t);
        assert_int_equal(tirenv_model_type_flags(t), want[i].flags);
        assert_int_equal(tirenv_model_type_tracks(t), want[i].tracks);
        assert_int_equal((tirenv_model_type_flags(t) & EQ) != 0,
                         tirenv_model_type_tracks(t) == TIRENV_TRACKS_EQUILIBRIUM);
    }
}

/* One style per model on every plot: each type has its own colour, none of them a spare, and
 * no two alike. */
static void test_plot_styles(void **state)
{
    (void)state;
    const size_t n = n_types();
    const tirenv_plot_style spare = tirenv_plot_style_of("no-such-model", 0);
    for (size_t i = 0; i < n; ++i) {
        const char *name = tirenv_model_type_name(tirenv_model_types()[i]);
        const tirenv_plot_style s = tirenv_plot_style_of(name, i);
        assert_string_not_equal(s.colour, spare.colour);
        assert_true(s.width > 0 && s.dash >= 1);
        /* The index only picks a spare: a model's own style does not depend on it. */
        assert_string_equal(tirenv_plot_style_of(name, i + 3).colour, s.colour);
        for (size_t j = 0; j < i; ++j)
            assert_string_not_equal(
                s.colour, tirenv_plot_style_of(tirenv_model_type_name(tirenv_model_types()[j]),
                                               j).colour);
    }
}

/* The flags hold when the models run: a type with its own contact length gives back the l_c
 * a load was made from; the equilibrium types iterate, the others do not; only the network
 * needs one. */
static void test_flags_hold(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_profile *cleat = tirenv_profile_cleat(0.2117, 0.0513);
    tirenv_nn *nn = tirenv_test_made_up_network(4242, 97);
    const double l_c = 0.3371, R0 = tire.springs.R0;
    for (size_t i = 0; i < n_types(); ++i) {
        const tirenv_model_type *t = tirenv_model_types()[i];
        const unsigned f = tirenv_model_type_flags(t);
        tirenv_model *m = tirenv_model_alloc(t, &tire);
        assert_non_null(m);
        tirenv_diag d;
        tirenv_diag_clear(&d);
        if (f & TIRENV_MODEL_NEEDS_NETWORK) {
            double load;
            assert_int_equal(tirenv_model_load_for_contact_length(m, l_c, &load, &d),
                             TIRENV_OK);
            assert_int_equal(tirenv_model_set(m, cleat, load, &d), TIRENV_EINVAL);
            assert_true(d.message[0] != '\0');
            assert_int_equal(tirenv_model_set_network(m, nn, R0, &d), TIRENV_OK);
        } else {
            /* Neither a network nor its tire's contact law for a model without one. */
            assert_int_equal(tirenv_model_set_network(m, nn, R0, &d), TIRENV_EINVAL);
            const tirenv_contact_law law = {.n = 2, .load = {1000.0, 9000.0},
                                            .l_c = {0.1, 0.4}};
            tirenv_diag_clear(&d);
            assert_int_equal(tirenv_model_set_contact_law(m, &law, &d), TIRENV_EINVAL);
            assert_string_equal(d.field, "contact law");
        }
        double load;
        assert_int_equal(tirenv_model_load_for_contact_length(m, l_c, &load, &d), TIRENV_OK);
        tirenv_flat flat;
        assert_int_equal(tirenv_model_flat(m, load, &flat, &d), TIRENV_OK);
        if (f & TIRENV_MODEL_CONTACT_LENGTH)
            assert_near(flat.contact_length, l_c, 1e-9, 0);
        else if (!(f & TIRENV_MODEL_NEEDS_NETWORK))
            assert_true(flat.contact_length == 0);
        else  /* the network's regime is the contact length itself: exactly */
            assert_true(flat.contact_length == l_c);
        assert_int_equal(tirenv_model_set(m, cleat, load, &d), TIRENV_OK);
        assert_true(tirenv_model_load(m) == load);
        tirenv_point pt;
        assert_int_equal(tirenv_model_eval(m, -0.0731, &pt, &d), TIRENV_OK);
        assert_true(pt.x == -0.0731 && isfinite(pt.h) && isfinite(pt.slope));
        assert_int_equal(pt.iterations > 0, (f & TIRENV_MODEL_EQUILIBRIUM) != 0);
        if (!(f & TIRENV_MODEL_NEEDS_NETWORK))  /* only the network warns or notes */
            assert_true(tirenv_model_warnings(m)[0] == '\0' && tirenv_model_note(m)[0] == '\0');
        /* A position that is not finite is refused by name, alone and within a sweep. */
        const double bad[] = {NAN, INFINITY, -INFINITY};
        for (size_t b = 0; b < 3; ++b) {
            tirenv_diag_clear(&d);
            assert_int_equal(tirenv_model_eval(m, bad[b], &pt, &d), TIRENV_EINVAL);
            assert_string_equal(d.field, "x");
            const double xs[] = {-0.0731, -0.05, bad[b], 0.01};
            tirenv_point pts[4];
            size_t failed = 99;
            assert_int_equal(tirenv_model_envelope(m, 4, xs, pts, &failed, &d), TIRENV_EINVAL);
            assert_int_equal(failed, 2);
            assert_non_null(strstr(d.message, "finite"));
        }
        print_message("%-8s flags %#04x: h(-0.0731 m) = %.6f m, %zu iterations\n",
                      tirenv_model_type_name(t), f, pt.h, pt.iterations);
        tirenv_model_free(m);
    }
    tirenv_nn_free(nn);
    tirenv_profile_free(cleat);
}

/* The point contact is the raw profile: h is the ground's height under the centre and the
 * ride's input equals the one without a model, bit for bit. */
static void test_point_is_the_profile(void **state)
{
    (void)state;
    const double x[] = {-0.8, -0.31, -0.31, 0.12, 0.12, 0.57, 1.3};
    const double z[] = {0.0, 0.013, 0.061, 0.047, -0.02, 0.0, 0.033};
    tirenv_profile *p = tirenv_profile_alloc(7, x, z);
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_point, &tire);
    assert_non_null(p);
    assert_non_null(m);
    enum { N = 613 };
    static double w_point[N], w_raw[N];
    tirenv_diag d;
    assert_int_equal(tirenv_ride_effective(m, p, 11234.5, -1.0317, 0.0041, N, w_point, &d),
                     TIRENV_OK);
    assert_int_equal(tirenv_ride_effective(NULL, p, 11234.5, -1.0317, 0.0041, N, w_raw, &d),
                     TIRENV_OK);
    for (size_t k = 0; k < N; ++k)
        assert_bits_equal(w_point[k], w_raw[k]);
    /* The slope is the segment's; the force leans with it. */
    tirenv_point pt;
    assert_int_equal(tirenv_model_set(m, p, 10000, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_eval(m, 0.3, &pt, &d), TIRENV_OK);
    assert_near(pt.slope, (0.0 - -0.02) / (0.57 - 0.12), 1e-15, 0);
    assert_near(pt.fx, -10000 * pt.slope, 1e-9, 0);
    assert_bits_equal(pt.h, tirenv_profile_height(p, 0.3));
    tirenv_model_free(m);
    tirenv_profile_free(p);
}

/* The network as a model: over the four corners of a centred cleat it is the paper's curve
 * (tirenv_nn_envelope) bit for bit, over anything else the road decomposition's, blocks of
 * the sweep included; a contact length made into a load reaches the network exactly. */
static void test_network_model(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    const double R0 = tire.springs.R0, l_c = 0.3313, L = 0.1873, H = 0.0617;
    tirenv_nn *nn = tirenv_test_made_up_network(4242, 97);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_nn, &tire);
    assert_non_null(m);
    tirenv_diag d;
    assert_int_equal(tirenv_model_set_network(m, nn, 0, &d), TIRENV_OK);
    enum { N = 700 };  /* more than one block of the network's batch */
    static double x[N], h[N];
    static tirenv_point pt[N];
    for (size_t k = 0; k < N; ++k)
        x[k] = -0.9 + 0.0026 * (double)k;
    double load;
    assert_int_equal(tirenv_model_load_for_contact_length(m, l_c, &load, &d), TIRENV_OK);
    tirenv_profile *cleat = tirenv_profile_cleat(L, H);
    assert_int_equal(tirenv_model_set(m, cleat, load, &d), TIRENV_OK);
    assert_non_null(strstr(tirenv_model_note(m), "cleat"));
    assert_int_equal(tirenv_model_envelope(m, N, x, pt, NULL, &d), TIRENV_OK);
    assert_int_equal(tirenv_nn_envelope(nn, R0, l_c, L, H, N, x, h, &d), TIRENV_OK);
    const double z_c = sqrt(R0 * R0 - 0.25 * l_c * l_c);
    size_t raised = 0;
    for (size_t k = 0; k < N; ++k) {
        assert_bits_equal(pt[k].h, h[k]);
        assert_bits_equal(pt[k].z, z_c + h[k]);
        assert_true(pt[k].fx == 0 && pt[k].fz == load && pt[k].iterations == 0);
        raised += h[k] > 1e-4;
        /* A single position's slope (a step of 1e-5 in x_N) against the sweep's (central
         * differences over 2 x 2.6 mm): they differ by the truncation of the wider step,
         * measured up to 1.6e-7 on this network; 1e-6 leaves room for the rounding of
         * another libm, not for a slope of the wrong curve or step. */
        if (k > 0 && k + 1 < N && k % 37 == 0) {
            tirenv_point one;
            assert_int_equal(tirenv_model_eval(m, x[k], &one, &d), TIRENV_OK);
            assert_bits_equal(one.h, h[k]);
            if (fabs(x[k]) > 0.02 && h[k] > 1e-3 && h[k - 1] > 1e-3 && h[k + 1] > 1e-3)
                assert_near(one.slope, pt[k].slope, 1e-6, 0);
        }
    }
    assert_true(raised > N / 10);

    /* A bump that is not the bare cleat: the decomposition. */
    const double bx[] = {-1.1, -0.0937, -0.0937, 0.0937, 0.0937, 1.2};
    const double bz[] = {0, 0, H, H, 0, 0};
    tirenv_profile *bump = tirenv_profile_alloc(6, bx, bz);
    assert_int_equal(tirenv_model_set(m, bump, load, &d), TIRENV_OK);
    assert_non_null(strstr(tirenv_model_note(m), "obstacles above a baseline"));
    assert_int_equal(tirenv_model_envelope(m, N, x, pt, NULL, &d), TIRENV_OK);
    tirenv_nn_road *road = NULL;
    static double slope[N];
    assert_int_equal(tirenv_nn_road_alloc(nn, R0, l_c, bump, NULL, &road, &d), TIRENV_OK);
    assert_int_equal(tirenv_nn_road_eval(road, N, x, h, slope, &d), TIRENV_OK);
    for (size_t k = 0; k < N; ++k) {
        assert_bits_equal(pt[k].h, h[k]);
        assert_bits_equal(pt[k].slope, slope[k]);
    }
    tirenv_nn_road_free(road);
    tirenv_profile_free(bump);
    tirenv_profile_free(cleat);
    tirenv_model_free(m);
    tirenv_nn_free(nn);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_records),
        cmocka_unit_test(test_record_flags),
        cmocka_unit_test(test_plot_styles),
        cmocka_unit_test(test_flags_hold),
        cmocka_unit_test(test_point_is_the_profile),
        cmocka_unit_test(test_network_model),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
