/* The public API with diag NULL (and optional outputs NULL) on its failure paths: every
 * reader on a missing file, an invalid parameter, a model evaluation that fails, and the
 * calls that add context to a callee's message (the ride, a sweep's case, the contact law of
 * a data set), which must return the status and not dereference the missing diag. Run it in
 * the sanitizer build: a write through NULL is what it looks for.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/tirenv.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A path in the test's fresh, empty directory: no file is there. */
static const char *missing(void **state, const char *name, char buf[600])
{
    return tirenv_test_path(*state, name, buf);
}

static void test_readers_on_missing_files(void **state)
{
    char path[600];
    tirenv_tire tire = tirenv_tire_default();
    assert_int_equal(tirenv_tir_read(missing(state, "t.tir", path), &tire, NULL), TIRENV_EIO);
    tirenv_tir_origin origin;
    assert_int_equal(tirenv_tir_read_derive(path, &tire, TIRENV_TIR_RING, &origin, NULL),
                     TIRENV_EIO);
    tirenv_vehicle v = tirenv_vehicle_default();
    assert_int_equal(tirenv_vehicle_read(missing(state, "v.veh", path), &v, NULL), TIRENV_EIO);
    tirenv_profile *p = NULL;
    assert_int_equal(tirenv_profile_read_csv(missing(state, "p.csv", path), &p, NULL),
                     TIRENV_EIO);
    assert_null(p);
    assert_int_equal(tirenv_profile_read_file(path, NULL, &p, NULL), TIRENV_EIO);
    assert_null(p);
    tirenv_crg *crg = NULL;
    assert_int_equal(tirenv_crg_open(missing(state, "r.crg", path), &crg, NULL), TIRENV_EIO);
    assert_null(crg);
    assert_int_equal(tirenv_rdf_read(missing(state, "r.rdf", path), TIRENV_RDF_MEAN, &p, NULL),
                     TIRENV_EIO);
    assert_null(p);
    tirenv_nn *nn = NULL;
    assert_int_equal(tirenv_nn_read_json(missing(state, "n.json", path), &nn, NULL, NULL),
                     TIRENV_EIO);
    assert_null(nn);
    tirenv_curve curve;
    assert_int_equal(tirenv_curve_read_csv(missing(state, "c.csv", path), &curve, NULL),
                     TIRENV_EIO);
    tirenv_import_settings imp = tirenv_import_default();
    imp.L = 0.2931;
    imp.H = 0.0743;
    imp.R0 = 0.68;
    imp.contact_length = 0.3172;
    assert_int_equal(tirenv_rig_import_file(missing(state, "log.csv", path), &imp, &curve,
                                            NULL, NULL),
                     TIRENV_EIO);
    tirenv_dataset ds;
    assert_int_equal(tirenv_dataset_read(missing(state, "set", path), 0.68, &ds, NULL),
                     TIRENV_EIO);
    /* No path at all is an invalid argument, not an I/O error (fopen(NULL) gave EIO "Bad
     * address"); no place for the network, refused (it was written through). */
    tirenv_diag diag;
    assert_int_equal(tirenv_nn_read_json(NULL, &nn, NULL, &diag), TIRENV_EINVAL);
    assert_null(nn);
    assert_int_equal(tirenv_nn_read_json(path, NULL, NULL, &diag), TIRENV_EINVAL);
    assert_int_equal(tirenv_rig_import_file(NULL, &imp, &curve, NULL, &diag), TIRENV_EINVAL);
    assert_int_equal(tirenv_rig_import_file("", &imp, &curve, NULL, &diag), TIRENV_EINVAL);
}

static void test_invalid_parameters(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    assert_int_equal(tirenv_tir_set(&tire, "RADIAL_STIFFNESS=-2.385e5", NULL), TIRENV_EINVAL);
    assert_int_equal(tirenv_tir_set(&tire, "NO_SUCH_KEY=1", NULL), TIRENV_EPARSE);
    char buf[64];
    assert_int_equal(tirenv_tir_get(&tire, "NO_SUCH_KEY", buf, sizeof buf, NULL, NULL),
                     TIRENV_EINVAL);
    tire.springs.c_r = -2.385e5;
    assert_int_equal(tirenv_tire_check(&tire, NULL), TIRENV_EINVAL);
    tirenv_vehicle v = tirenv_vehicle_default();
    assert_int_equal(tirenv_vehicle_set(&v, "MASS=-5200", NULL), TIRENV_EINVAL);
    const double x[2] = {1.0, 0.5}, z[2] = {0, 0};  /* x descends */
    tirenv_profile *p = NULL;
    assert_int_equal(tirenv_profile_make(2, x, z, "made", &p, NULL), TIRENV_EINVAL);
    assert_null(p);
}

/* Evaluations that fail: a wall taller than the tire within R0 of the point contact's hub
 * (TIRENV_ERANGE: the hub must clear the ground), a needle between the springs model's rays
 * (TIRENV_ERANGE, its own refusal), a position that is no number (TIRENV_EINVAL), and a load
 * no tire carries on flat ground. */
static void test_model_failures(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    const double xw[4] = {-5, 0, 0, 5}, zw[4] = {0, 0, 2.385, 2.385};
    tirenv_profile *wall = tirenv_profile_alloc(4, xw, zw);
    assert_non_null(wall);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_point, &tire);
    assert_non_null(m);
    assert_int_equal(tirenv_model_set(m, wall, 17900, NULL), TIRENV_OK);
    tirenv_point pt, out[2];
    assert_int_equal(tirenv_model_eval(m, -0.2, &pt, NULL), TIRENV_ERANGE);
    const double xs[2] = {-3.0, -0.2};
    assert_int_equal(tirenv_model_envelope(m, 2, xs, out, NULL, NULL), TIRENV_ERANGE);
    assert_int_equal(tirenv_model_eval(m, NAN, &pt, NULL), TIRENV_EINVAL);
    tirenv_model_free(m);
    tirenv_profile_free(wall);

    tire.springs.contact = TIRENV_SPRINGS_RAYS;
    tirenv_profile *needle = tirenv_profile_cleat(1e-9, 0.1);
    assert_non_null(needle);
    m = tirenv_model_alloc(tirenv_model_springs, &tire);
    assert_non_null(m);
    assert_int_equal(tirenv_model_set(m, needle, 13000, NULL), TIRENV_OK);
    assert_int_equal(tirenv_model_eval(m, 0.003, &pt, NULL), TIRENV_ERANGE);
    tirenv_flat flat;
    const int status = tirenv_model_flat(m, 2.385e9, &flat, NULL);
    assert_true(status == TIRENV_ENOBRACKET || status == TIRENV_ERANGE);
    tirenv_model_free(m);
    tirenv_profile_free(needle);
}

/* An axle input that fails beyond fail_after (m): at the static start or during the run. */
static int failing_input(void *ctx, double x, double load, double *w, double *dw_dx,
                         tirenv_diag *diag)
{
    (void)load;
    *w = 0;
    *dw_dx = 0;
    if (x > *(const double *)ctx)
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "test", "made to fail at %g m", x);
    return TIRENV_OK;
}

static void test_ride_input_fails(void **state)
{
    (void)state;
    tirenv_vehicle v = tirenv_vehicle_default();
    const tirenv_tire tire = tirenv_tire_default();
    assert_int_equal(tirenv_vehicle_tires(&v, &tire, &tire, NULL), TIRENV_OK);
    tirenv_ride_settings s = tirenv_ride_default();
    s.duration = 1.0;
    const size_t n = tirenv_ride_n_samples(&s);
    tirenv_ride_sample *out = malloc(n * sizeof *out);
    assert_non_null(out);
    double fail_after = -1e3;  /* both axles, at t = 0 */
    tirenv_ride_input in = {failing_input, &fail_after, 1000, 20000, 0.005};
    assert_int_equal(tirenv_ride_run_input(&v, &in, &in, &s, out, NULL), TIRENV_ENOCONV);
    fail_after = 0.25;  /* the front axle, 0.25 s into the run */
    assert_int_equal(tirenv_ride_run_input(&v, &in, &in, &s, out, NULL), TIRENV_ENOCONV);
    free(out);
}

/* A case whose load the springs model cannot carry: the sweep names the case in diag. */
static void test_sweep_case_fails(void **state)
{
    char dir[600];
    tirenv_test_path(*state, "sweep", dir);
    static const double side[1] = {0.1}, G[1] = {2.385e9};  /* a 0.1 x 0.1 m cleat */
    tirenv_sweep_settings s = tirenv_sweep_default();
    s.type = tirenv_model_springs;
    s.lengths = s.heights = side;
    s.n_lengths = s.n_heights = 1;
    s.loads = G;
    s.n_loads = 1;
    const tirenv_tire tire = tirenv_tire_default();
    const int status = tirenv_sweep_run(dir, &tire, &s, NULL, NULL);
    assert_true(status == TIRENV_ENOBRACKET || status == TIRENV_ERANGE);
}

/* Two cases whose contact lengths fall as the load rises: no law, and the message would
 * name the source model. */
static void test_contact_law_of_data_fails(void **state)
{
    (void)state;
    tirenv_case cases[2] = {{.name = "a", .load = 10000, .contact_length = 0.5},
                            {.name = "b", .load = 20000, .contact_length = 0.1}};
    const tirenv_dataset ds = {.dir = "", .n = 2, .cases = cases};
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_contact_law law;
    char what[128];
    assert_int_equal(tirenv_contact_law_of_data(&ds, tirenv_model_springs, &tire, &law, what,
                                                sizeof what, NULL),
                     TIRENV_EINVAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_readers_on_missing_files, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test(test_invalid_parameters),
        cmocka_unit_test(test_model_failures),
        cmocka_unit_test(test_ride_input_fails),
        cmocka_unit_test_setup_teardown(test_sweep_case_fails, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown_tree),
        cmocka_unit_test(test_contact_law_of_data_fails),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
