/* A load that changes as the vehicle moves (tirenv_model_set_load) and a model a host can
 * rewind (tirenv_model_state_save / _restore), for every model type: set_load equals a model
 * set afresh at that load (bit for bit where the model has no equilibrium to solve, within
 * the solver's tolerances where it has), a failed set_load leaves the model as it was, and a
 * restored state replays the same evaluations bit for bit, in the same instance or in a twin.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/tirenv.h"
#include "tirenv/nn.h"
#include "tirenv/road.h"

static tirenv_nn *network;  /* for the nn model, made once */

static tirenv_model *model_of(const tirenv_model_type *type, const tirenv_tire *tire)
{
    tirenv_model *m = tirenv_model_alloc(type, tire);
    assert_non_null(m);
    tirenv_diag d;
    if (tirenv_model_type_flags(type) & TIRENV_MODEL_NEEDS_NETWORK) {
        if (!network)
            network = tirenv_test_made_up_network(4242, 97);
        assert_int_equal(tirenv_model_set_network(m, network, 0, &d), TIRENV_OK);
        /* The road's bumps are lower than the made-up network's cleats: what these tests
         * check of set_load holds outside its ranges too (test_set_load_errors: refused). */
        tirenv_model_set_extrapolate(m, 1);
    }
    return m;
}

/* A 12 m class D road (rough enough for the springs and the ring to work) with a cleat on it,
 * so that every model meets slopes, corners and a wall. */
static tirenv_profile *test_road(void)
{
    tirenv_road_settings rs = tirenv_road_default();
    rs.road_class = 'D';
    rs.length = 12.0;
    rs.dx = 0.02;
    rs.seed = 7;
    tirenv_profile *road = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_road_iso8608(&rs, &road, &d), TIRENV_OK);
    const size_t n = tirenv_profile_size(road);
    const double *x = tirenv_profile_x(road), *z = tirenv_profile_z(road);
    double *xs = malloc((n + 4) * sizeof *xs), *zs = malloc((n + 4) * sizeof *zs);
    assert_true(xs && zs);
    size_t m = 0;
    for (size_t k = 0; k < n; ++k) {
        if (x[k] > 6.0 && x[k] < 6.2) /* a 0.2 x 0.04 m cleat on the road at 6.05 .. 6.15 m */
            continue;
        xs[m] = x[k];
        zs[m++] = z[k];
        if (x[k] <= 6.0 && x[k + 1] > 6.0) {
            const double base = z[k];
            const double cx[4] = {6.05, 6.05, 6.15, 6.15};
            const double cz[4] = {base, base + 0.04, base + 0.04, base};
            for (int i = 0; i < 4; ++i) {
                xs[m] = cx[i];
                zs[m++] = cz[i];
            }
        }
    }
    tirenv_profile *p = tirenv_profile_alloc(m, xs, zs);
    assert_non_null(p);
    free(xs);
    free(zs);
    tirenv_profile_free(road);
    return p;
}

/* The model's load at step k of a sweep: a swing of +-25 % about G0 with a period of about
 * 0.9 m of travel, as a tire's load swings over a rough road. */
static double swing(double G0, size_t k)
{
    return G0 * (1.0 + 0.25 * sin(0.7 * (double)k + 0.3));
}

static int point_bits_equal(const tirenv_point *a, const tirenv_point *b)
{
    return memcmp(&a->x, &b->x, sizeof a->x) == 0 && memcmp(&a->z, &b->z, sizeof a->z) == 0 &&
           memcmp(&a->h, &b->h, sizeof a->h) == 0 &&
           memcmp(&a->slope, &b->slope, sizeof a->slope) == 0 &&
           memcmp(&a->fx, &b->fx, sizeof a->fx) == 0 &&
           memcmp(&a->fz, &b->fz, sizeof a->fz) == 0 && a->contacts == b->contacts &&
           a->iterations == b->iterations;
}

/* The types, their base load and whether set_load must give the fresh model's bits. */
static const struct {
    const char *name;
    double l_c;        /* the base load's contact length, m */
    int exact;
} cases[] = {
    {"rigid", 0.33, 1}, {"point", 0.33, 1}, {"cam", 0.33, 1},
    {"nn", 0.33, 1},    {"springs", 0.33, 0}, {"ring", 0.33, 0},
};
enum { N_CASES = sizeof cases / sizeof cases[0] };

/* Positions of the sweeps: over the road's rough part and the cleat. */
static double position(size_t k, size_t n)
{
    return 4.5 + 2.5 * (double)k / (double)(n - 1);
}

/* For each type: the same positions and loads, one model changing its load at every step,
 * and a model set afresh at each step's load. The springs and the ring solve their
 * equilibria from other starts (the fresh model from the rigid disc, the other from the
 * last position), so they agree within the solver's tolerances: the centre height within a
 * few eps_z (1e-10 m) plus eps_F/k (below 1e-11 m), forces within eps_F where F_z is smooth;
 * where a ray or a node sweeps over a corner F_z jumps, and the two may stop on either side
 * of the jump (section 11.3), so forces get a looser bound of 1 % of the load. */
static void test_set_load_equals_fresh(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_profile *road = test_road();
    enum { N = 41 };
    for (size_t c = 0; c < N_CASES; ++c) {
        const tirenv_model_type *type = tirenv_model_type_find(cases[c].name);
        const size_t n = strcmp(cases[c].name, "ring") == 0 ? 13 : N;
        tirenv_model *m = model_of(type, &tire), *fresh = model_of(type, &tire);
        tirenv_diag d;
        double G0;
        assert_int_equal(tirenv_model_load_for_contact_length(m, cases[c].l_c, &G0, &d), 0);
        assert_int_equal(tirenv_model_set(m, road, G0, &d), TIRENV_OK);
        size_t changed = 0;
        for (size_t k = 0; k < n; ++k) {
            const double x = position(k, n), G = swing(G0, k);
            tirenv_point a, b;
            if (tirenv_model_set_load(m, G, &d) || tirenv_model_eval(m, x, &a, &d))
                fail_msg("%s: set_load %g N, x %g m: %s", cases[c].name, G, x, d.message);
            if (tirenv_model_set(fresh, road, G, &d) || tirenv_model_eval(fresh, x, &b, &d))
                fail_msg("%s: fresh at %g N, x %g m: %s", cases[c].name, G, x, d.message);
            assert_true(tirenv_model_load(m) == G);
            if (cases[c].exact) {
                if (!point_bits_equal(&a, &b))
                    fail_msg("%s at x %g m, load %g N: h %.17g against %.17g, slope %.17g "
                             "against %.17g", cases[c].name, x, G, a.h, b.h, a.slope, b.slope);
            } else {
                assert_near(a.z, b.z, 5e-10, 0);
                assert_near(a.h, b.h, 1e-9, 0);
                assert_near(a.fz, b.fz, 0.01 * G, 0);
                assert_near(a.fx, b.fx, 0.01 * G, 0);
            }
            changed += k > 0 && a.h != 0;
        }
        assert_true(changed > n / 2);  /* the sweep met ground, not only level stretches */
        tirenv_model_free(m);
        tirenv_model_free(fresh);
    }
    tirenv_profile_free(road);
}

/* The load enters the curve: a set_load that did nothing would pass the test above only if
 * the fresh models did not depend on the load either. On the cleat's approach, 0.1 m before
 * its edge, the springs' and the cam's heights must differ between 60 % and 140 % of the base
 * load (5 mm for both with the default tire). */
static void test_load_matters(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_profile *cleat = tirenv_profile_cleat(0.2, 0.05);
    const char *names[] = {"springs", "cam"};
    for (size_t i = 0; i < 2; ++i) {
        tirenv_model *m = model_of(tirenv_model_type_find(names[i]), &tire);
        tirenv_diag d;
        double G0;
        assert_int_equal(tirenv_model_load_for_contact_length(m, 0.33, &G0, &d), 0);
        assert_int_equal(tirenv_model_set(m, cleat, 0.6 * G0, &d), TIRENV_OK);
        tirenv_point lo, hi;
        assert_int_equal(tirenv_model_eval(m, -0.2, &lo, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_set_load(m, 1.4 * G0, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_eval(m, -0.2, &hi, &d), TIRENV_OK);
        assert_true(fabs(lo.h - hi.h) > 1e-3);
        assert_true(hi.z < lo.z);
        tirenv_model_free(m);
    }
    tirenv_profile_free(cleat);
}

/* Refusals: no profile yet, a load that is not a force, a load the tire cannot carry (the
 * cam's contact law past its peak, the springs' flat ground bottoming out): the model stays
 * set at its previous load and evaluates as before, bit for bit. */
static void test_set_load_errors(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_test_tire_before_identify();
    tirenv_profile *cleat = tirenv_profile_cleat(0.2, 0.05);
    for (size_t c = 0; c < N_CASES; ++c) {
        const tirenv_model_type *type = tirenv_model_type_find(cases[c].name);
        tirenv_model *m = model_of(type, &tire);
        tirenv_diag d;
        assert_int_equal(tirenv_model_set_load(m, 5000, &d), TIRENV_EINVAL);
        double G0;
        assert_int_equal(tirenv_model_load_for_contact_length(m, 0.33, &G0, &d), 0);
        assert_int_equal(tirenv_model_set(m, cleat, G0, &d), TIRENV_OK);
        tirenv_point before, after;
        assert_int_equal(tirenv_model_eval(m, -0.3, &before, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_set_load(m, -1, &d), TIRENV_EINVAL);
        assert_string_equal(d.field, "load");
        assert_int_equal(tirenv_model_set_load(m, NAN, &d), TIRENV_EINVAL);
        /* An infinite load was taken by the models that solve nothing (rigid, point: fz inf,
         * fx and slope NaN, status OK) and misreported by the cam ("at most -13072 N"). */
        tirenv_flat flat;
        assert_int_equal(tirenv_model_set_load(m, INFINITY, &d), TIRENV_EINVAL);
        assert_string_equal(d.field, "load");
        assert_int_equal(tirenv_model_flat(m, INFINITY, &flat, &d), TIRENV_EINVAL);
        const int bounded = strcmp(cases[c].name, "cam") == 0 ||
                            strcmp(cases[c].name, "springs") == 0;
        if (bounded)
            assert_int_not_equal(tirenv_model_set_load(m, 1e9, &d), TIRENV_OK);
        if (strcmp(cases[c].name, "springs") == 0) {
            /* The warm start steps down the tangent below the ground and starts at z = 0,
             * where the tire's force is flat (dF/dz = 0): Newton took it for "no contact
             * yet" and stepped down from the ground 100 times, reporting no convergence in
             * [0, 0] m instead of the load the tire carries there. */
            assert_int_equal(tirenv_model_set_load(m, 1e9, &d), TIRENV_ENOBRACKET);
            assert_non_null(strstr(d.message, "the tire carries with its centre at the ground"));
        }
        if (strcmp(cases[c].name, "cam") == 0) {  /* beyond its valid range (docs section 1.3) */
            assert_int_equal(tirenv_model_set_load(m, 2e5, &d), TIRENV_ERANGE);
            assert_string_equal(d.field, "load");
        }
        if (tirenv_model_type_flags(type) & TIRENV_MODEL_NEEDS_NETWORK) {
            /* Three times the load: a contact length of about 0.57 m, beyond the network's
             * trained 0.28 to 0.38 m; refused unless extrapolation is allowed. */
            tirenv_model_set_extrapolate(m, 0);
            assert_int_equal(tirenv_model_set_load(m, 3 * G0, &d), TIRENV_ERANGE);
            assert_string_equal(d.field, "contact length");
            assert_true(tirenv_model_load(m) == G0);
            tirenv_model_set_extrapolate(m, 1);
        }
        assert_true(tirenv_model_load(m) == G0);
        assert_int_equal(tirenv_model_eval(m, -0.3, &after, &d), TIRENV_OK);
        if (cases[c].exact)
            assert_true(point_bits_equal(&before, &after));
        else
            assert_near(after.z, before.z, 5e-10, 0);
        assert_int_equal(tirenv_model_set(m, cleat, INFINITY, &d), TIRENV_EINVAL);
        assert_string_equal(d.field, "load");
        /* A load within the force tolerance of none: the springs model "converged" with F_z
         * 1.1e-5 N at 1e-319 N, and the cam's tandem base was 0 m (its slope NaN), status
         * OK. Just above the tolerance, taken. */
        const double eps_F = tirenv_model_tire(m)->eq.eps_F;
        assert_int_equal(tirenv_model_set(m, cleat, 1e-319, &d), TIRENV_EINVAL);
        assert_string_equal(d.field, "load");
        assert_int_equal(tirenv_model_flat(m, eps_F, &flat, &d), TIRENV_EINVAL);
        assert_int_equal(tirenv_model_set(m, cleat, 2 * eps_F, &d), TIRENV_OK);
        tirenv_model_free(m);
    }
    tirenv_profile_free(cleat);
}

/* Runs steps k0 .. k0 + n - 1 of a sweep with a changing load into out[]. */
static void run_steps(tirenv_model *m, double G0, size_t k0, size_t n, size_t n_all,
                      tirenv_point out[])
{
    tirenv_diag d;
    for (size_t k = k0; k < k0 + n; ++k)
        if (tirenv_model_set_load(m, swing(G0, k), &d) ||
            tirenv_model_eval(m, position(k, n_all), &out[k - k0], &d))
            fail_msg("%s at step %zu: %s", tirenv_model_name(m), k, d.message);
}

/* Save half-way through a sweep, go on, restore, go on again: the same points bit for bit,
 * iterations included; and the same from a twin set on the same road at another load and
 * given the state. The size of a state does not depend on what the model has done. */
static void test_state_replays(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_profile *road = test_road();
    enum { N_ALL = 40, HALF = 20 };
    for (size_t c = 0; c < N_CASES; ++c) {
        const tirenv_model_type *type = tirenv_model_type_find(cases[c].name);
        const size_t n_all = strcmp(cases[c].name, "ring") == 0 ? 12 : N_ALL;
        const size_t half = n_all / 2;
        tirenv_model *m = model_of(type, &tire), *twin = model_of(type, &tire);
        tirenv_diag d;
        double G0;
        assert_int_equal(tirenv_model_load_for_contact_length(m, 0.33, &G0, &d), 0);
        const size_t size = tirenv_model_state_size(m);
        assert_int_equal(tirenv_model_set(m, road, G0, &d), TIRENV_OK);
        tirenv_point first[HALF], again[HALF], twice[HALF], warm[HALF];
        run_steps(m, G0, 0, half, n_all, warm);
        assert_int_equal(tirenv_model_state_size(m), size);
        unsigned char *buf = malloc(size);
        assert_non_null(buf);
        assert_int_equal(tirenv_model_state_save(m, buf, size, &d), TIRENV_OK);
        run_steps(m, G0, half, half, n_all, first);
        assert_int_equal(tirenv_model_state_restore(m, buf, size, &d), TIRENV_OK);
        assert_true(tirenv_model_load(m) == swing(G0, half - 1));
        run_steps(m, G0, half, half, n_all, again);
        assert_int_equal(tirenv_model_set(twin, road, 0.8 * G0, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_state_restore(twin, buf, size, &d), TIRENV_OK);
        run_steps(twin, G0, half, half, n_all, twice);
        for (size_t k = 0; k < half; ++k)
            if (!point_bits_equal(&first[k], &again[k]) || !point_bits_equal(&first[k], &twice[k]))
                fail_msg("%s: step %zu after the restore differs: h %.17g, %.17g, %.17g; "
                         "iterations %zu, %zu, %zu", cases[c].name, half + k, first[k].h,
                         again[k].h, twice[k].h, first[k].iterations, again[k].iterations,
                         twice[k].iterations);
        /* The same state saved twice is the same bytes. */
        unsigned char *buf2 = malloc(size);
        assert_non_null(buf2);
        assert_int_equal(tirenv_model_state_restore(m, buf, size, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_state_save(m, buf2, size, &d), TIRENV_OK);
        assert_memory_equal(buf, buf2, size);
        free(buf2);
        free(buf);
        tirenv_model_free(m);
        tirenv_model_free(twin);
    }
    tirenv_profile_free(road);
}

/* What is not a state of this model is refused, naming "state", and leaves the model as it
 * was: the wrong size, the wrong type, another tire, damaged bytes, no profile to restore
 * onto. */
static void test_state_errors(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_tire other = tire;
    other.springs.R0 *= 1.01;
    tirenv_profile *cleat = tirenv_profile_cleat(0.2, 0.05);
    tirenv_model *cam = model_of(tirenv_model_cam, &tire);
    tirenv_model *rigid = model_of(tirenv_model_rigid, &tire);
    tirenv_model *cam_other = model_of(tirenv_model_cam, &other);
    tirenv_model *unset = model_of(tirenv_model_cam, &tire);
    tirenv_diag d;
    assert_int_equal(tirenv_model_set(cam, cleat, 12000, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set(rigid, cleat, 12000, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set(cam_other, cleat, 12000, &d), TIRENV_OK);
    const size_t size = tirenv_model_state_size(cam);
    unsigned char *buf = malloc(size + 8);
    assert_non_null(buf);
    assert_int_equal(tirenv_model_state_save(cam, buf, size - 1, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_state_save(cam, NULL, size, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_state_save(cam, buf, size, &d), TIRENV_OK);
    tirenv_point before, after;
    assert_int_equal(tirenv_model_eval(rigid, -0.1, &before, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_state_restore(cam, buf, size + 1, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "state");
    /* The rigid model's state is another size; a cam state in a rigid model is refused
     * whatever the size says. */
    assert_int_equal(tirenv_model_state_restore(rigid, buf, size, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_eval(rigid, -0.1, &after, &d), TIRENV_OK);
    assert_true(point_bits_equal(&before, &after));
    assert_int_equal(tirenv_model_state_restore(cam_other, buf, size, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "another tire"));
    assert_int_equal(tirenv_model_state_restore(unset, buf, size, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "no profile"));
    /* One bit changed anywhere past the header's checks (the flat-ground height, the type's
     * own bytes, the checksum itself) is refused by the checksum: the flat-ground height moved
     * within its range was restored, and shifted every h. */
    const size_t at[] = {8 + 8 + 16 + 8 + 8 + 3, 8 + 8 + 16 + 8 + 8 + 8 + 1 + 5, size - 1};
    assert_int_equal(tirenv_model_eval(cam, -0.1, &before, &d), TIRENV_OK);
    for (size_t k = 0; k < sizeof at / sizeof at[0]; ++k) {
        buf[at[k]] ^= 0x04;
        assert_int_equal(tirenv_model_state_restore(cam, buf, size, &d), TIRENV_EINVAL);
        assert_non_null(strstr(d.message, "changed since it was saved"));
        assert_int_equal(tirenv_model_eval(cam, -0.1, &after, &d), TIRENV_OK);
        assert_true(point_bits_equal(&before, &after));
        buf[at[k]] ^= 0x04;
    }
    assert_int_equal(tirenv_model_state_restore(cam, buf, size, &d), TIRENV_OK);
    buf[0] ^= 0x5a;
    assert_int_equal(tirenv_model_state_restore(cam, buf, size, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_eval(cam, -0.1, &after, &d), TIRENV_OK);
    free(buf);
    tirenv_model_free(cam);
    tirenv_model_free(rigid);
    tirenv_model_free(cam_other);
    tirenv_model_free(unset);
    tirenv_profile_free(cleat);
}

static int teardown(void **state)
{
    (void)state;
    tirenv_nn_free(network);
    network = NULL;
    return 0;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_set_load_equals_fresh),
        cmocka_unit_test(test_load_matters),
        cmocka_unit_test(test_set_load_errors),
        cmocka_unit_test(test_state_replays),
        cmocka_unit_test(test_state_errors),
    };
    return cmocka_run_group_tests(tests, NULL, teardown);
}
