/* SPDX-License-Identifier: Apache-2.0 */
/* A road written a position at a time (tirenv_road_writer, profile_file.h; tirenv envelope
 * -o X.crg|X.rdf): read back, the heights are the ones given (KDBI and RDF exactly, KRBI to
 * float32); a wrong count or an abort leaves no file; a CRG of one position is refused; one
 * written over an OpenCRG road (on_crg) lies on it. */
#include "testutil.h"
#include "tirenv/tirenv.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

enum { N = 337 };
static const double x_from = -0.913, dx = 0.0071;

static double height(size_t k)
{
    const double x = x_from + dx * (double)k;
    return 0.0173 * sin(5.3 * x) + (k % 41 > 20 ? 0.0239 : 0.0);
}

/* Writes N positions to name in format f with encoding e, commits, reads the profile back. */
static tirenv_profile *write_and_read(const tirenv_test_dir *t, const char *name,
                                      tirenv_profile_format f, tirenv_crg_encoding e)
{
    char path[600];
    tirenv_test_path(t, name, path);
    const tirenv_road_writer_layout l = {.x_from = x_from, .dx = dx, .n = N, .half_width = 0.31,
                                         .encoding = e, .comment = "made by a test"};
    tirenv_road_writer *w = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_road_writer_open(path, f, &l, &w, &d), TIRENV_OK);
    for (size_t k = 0; k < N; ++k)
        assert_int_equal(tirenv_road_writer_add(w, x_from + dx * (double)k, height(k), &d), 0);
    assert_int_equal(tirenv_road_writer_commit(w, &d), TIRENV_OK);
    tirenv_profile *p = NULL;
    assert_int_equal(tirenv_profile_read_file(path, NULL, &p, &d), TIRENV_OK);
    assert_int_equal(tirenv_profile_size(p), N);
    return p;
}

static void test_round_trip(void **state)
{
    const tirenv_test_dir *t = *state;
    tirenv_profile *crg = write_and_read(t, "road.crg", TIRENV_PROFILE_CRG, TIRENV_CRG_KDBI);
    tirenv_profile *rdf = write_and_read(t, "road.rdf", TIRENV_PROFILE_RDF, TIRENV_CRG_KDBI);
    tirenv_profile *krbi = write_and_read(t, "krbi.crg", TIRENV_PROFILE_CRG, TIRENV_CRG_KRBI);
    const double *zc = tirenv_profile_z(crg), *zr = tirenv_profile_z(rdf);
    const double *zl = tirenv_profile_z(krbi), *xr = tirenv_profile_x(rdf);
    for (size_t k = 0; k < N; ++k) {
        assert_bits_equal(zc[k], height(k));
        assert_bits_equal(zr[k], height(k));
        assert_bits_equal(xr[k], x_from + dx * (double)k);
        assert_true(zl[k] == (double)(float)height(k));  /* KRBI: float32 */
    }
    tirenv_profile_free(crg);
    tirenv_profile_free(rdf);
    tirenv_profile_free(krbi);
}

/* One position too many or too few is an error naming the file, and nothing stays. */
static void test_counts_and_abort(void **state)
{
    const tirenv_test_dir *t = *state;
    char path[600];
    const tirenv_profile_format formats[2] = {TIRENV_PROFILE_CRG, TIRENV_PROFILE_RDF};
    const tirenv_road_writer_layout l = {.x_from = 0, .dx = 0.01, .n = 5, .half_width = 0.3};
    tirenv_diag d;
    for (size_t i = 0; i < 2; ++i) {
        tirenv_test_path(t, i ? "short.rdf" : "short.crg", path);
        tirenv_road_writer *w = NULL;
        assert_int_equal(tirenv_road_writer_open(path, formats[i], &l, &w, &d), TIRENV_OK);
        for (size_t k = 0; k < 4; ++k)
            assert_int_equal(tirenv_road_writer_add(w, 0.01 * (double)k, 0.0, &d), TIRENV_OK);
        assert_int_equal(tirenv_road_writer_commit(w, &d), TIRENV_EINVAL);
        assert_string_equal(d.file, path);
        assert_int_equal(access(path, F_OK), -1);

        assert_int_equal(tirenv_road_writer_open(path, formats[i], &l, &w, &d), TIRENV_OK);
        for (size_t k = 0; k < 5; ++k)
            assert_int_equal(tirenv_road_writer_add(w, 0.01 * (double)k, 0.0, &d), TIRENV_OK);
        assert_int_equal(tirenv_road_writer_add(w, 0.05, 0.0, &d), TIRENV_EINVAL);
        tirenv_road_writer_abort(w);
        assert_int_equal(access(path, F_OK), -1);
    }
    assert_int_equal(tirenv_test_count_entries(t, "short"), 0);
    tirenv_road_writer_abort(NULL);

    const tirenv_road_writer_layout one = {.x_from = 0, .dx = 0.01, .n = 1, .half_width = 0.3};
    tirenv_road_writer *w = (tirenv_road_writer *)&d;  /* set to NULL on failure */
    tirenv_test_path(t, "one.crg", path);
    assert_int_equal(tirenv_road_writer_open(path, TIRENV_PROFILE_CRG, &one, &w, &d),
                     TIRENV_EINVAL);
    assert_null(w);
    assert_int_equal(access(path, F_OK), -1);
}

/* on_crg: an effective road written over an OpenCRG road lies where that road is: its
 * reference line goes on from the road's at x_from (the same heading), and its heights read
 * back as given. A curved road is refused, leaving no file. */
static void test_on_crg(void **state)
{
    const tirenv_test_dir *t = *state;
    char base[600], path[600];
    tirenv_test_path(t, "base.crg", base);
    const double x0 = 12.5, y0 = -3.25, phi = 0.6137;
    const tirenv_road_writer_layout lb = {.x_from = x_from, .dx = dx, .n = N, .half_width = 0.4,
                                          .x_start = x0, .y_start = y0, .phi_start = phi,
                                          .encoding = TIRENV_CRG_KDBI};
    tirenv_road_writer *w = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_road_writer_open(base, TIRENV_PROFILE_CRG, &lb, &w, &d), 0);
    for (size_t k = 0; k < N; ++k)
        assert_int_equal(tirenv_road_writer_add(w, x_from + dx * (double)k, height(k), &d), 0);
    assert_int_equal(tirenv_road_writer_commit(w, &d), TIRENV_OK);

    enum { K0 = 37, M = 11 };  /* the effective road starts at the base road's row K0 */
    const double u0 = x_from + dx * K0;
    tirenv_road_file *on = NULL;
    assert_int_equal(tirenv_road_file_open(base, &on, &d), TIRENV_OK);
    const tirenv_road_writer_layout l = {.x_from = u0, .dx = dx, .n = M, .half_width = 0.2,
                                         .encoding = TIRENV_CRG_KDBI, .on_crg = on};
    tirenv_test_path(t, "on.crg", path);
    assert_int_equal(tirenv_road_writer_open(path, TIRENV_PROFILE_CRG, &l, &w, &d), 0);
    for (size_t k = 0; k < M; ++k)
        assert_int_equal(tirenv_road_writer_add(w, u0 + dx * (double)k, height(K0 + k), &d), 0);
    assert_int_equal(tirenv_road_writer_commit(w, &d), TIRENV_OK);
    tirenv_road_file_free(on);
    tirenv_crg *crg = NULL;
    assert_int_equal(tirenv_crg_open(path, &crg, &d), TIRENV_OK);
    double x[M], y[M], h[M];
    assert_int_equal(tirenv_crg_refline(crg, x, y, h, &d), TIRENV_OK);
    /* 1e-12 m: the start is x0 + cos(phi) * K0 * dx, written in %.17g text or as doubles. */
    assert_near(x[0], x0 + cos(phi) * (u0 - x_from), 1e-12, 0);
    assert_near(y[0], y0 + sin(phi) * (u0 - x_from), 1e-12, 0);
    assert_near(h[0], phi, 1e-15, 0);
    tirenv_crg_free(crg);
    tirenv_profile *p = NULL;
    assert_int_equal(tirenv_profile_read_file(path, NULL, &p, &d), TIRENV_OK);
    assert_int_equal(tirenv_profile_size(p), M);
    for (size_t k = 0; k < M; ++k)  /* 1e-15 m: z less the road's z_start, then plus it */
        assert_near(tirenv_profile_z(p)[k], height(K0 + k), 1e-15, 0);
    tirenv_profile_free(p);

    char curved[600];
    snprintf(curved, sizeof curved, "%s/crg/handmade_curved.crg", TIRENV_SAMPLES);
    assert_int_equal(tirenv_road_file_open(curved, &on, &d), TIRENV_OK);
    const tirenv_road_writer_layout lc = {.x_from = 0, .dx = dx, .n = M, .on_crg = on};
    tirenv_test_path(t, "curved.crg", path);
    w = (tirenv_road_writer *)&d;  /* set to NULL on failure */
    assert_int_equal(tirenv_road_writer_open(path, TIRENV_PROFILE_CRG, &lc, &w, &d),
                     TIRENV_EINVAL);
    assert_null(w);
    tirenv_road_file_free(on);
    assert_string_equal(d.file, curved);
    assert_non_null(strstr(d.message, "curved reference line"));
    assert_int_equal(access(path, F_OK), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_round_trip, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_counts_and_abort, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_on_crg, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
