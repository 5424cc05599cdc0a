/* SPDX-License-Identifier: Apache-2.0 */
/* A road written a position at a time (tirenv_road_writer, profile_file.h; tirenv envelope
 * -o X.crg|X.rdf): read back, the heights are the ones given (KDBI and RDF exactly, KRBI to
 * float32); a wrong count or an abort leaves no file; a CRG of one position is refused. */
#include "testutil.h"
#include "tirenv/tirenv.h"

#include <math.h>
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_round_trip, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_counts_and_abort, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
