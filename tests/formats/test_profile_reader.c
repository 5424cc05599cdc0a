/* The tracks of a road file of any format (profile_file.h): read whole
 * (tirenv_profile_read_tracks) or a row at a time (tirenv_profile_file_reader), the same
 * numbers as tirenv_crg_track per track, a 2-D road's heights on every track, errors passed on;
 * and a streamed sweep from the reader equals the whole one.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/tirenv.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { ROWS = 3001, NV = 5 };
static const double vs[NV] = {-1.1, -0.35, 0.0, 0.4, 1.3};  /* m */

/* Heights that differ across and along: z(u, v) = 0.021 sin(3.1 u + v) + 0.004 v u. */
static double road_z(double u, double v)
{
    return 0.021 * sin(3.1 * u + v) + 0.004 * v * u;
}

/* A KDBI road of ROWS rows from u = -0.73 every 0.0071 m, NV long sections; one NaN at the
 * right border of row 2000 when nan_row. */
static void write_road(const char *path, int nan_row)
{
    const tirenv_crg_layout l = {.encoding = TIRENV_CRG_KDBI, .u_start = -0.73,
                                 .u_increment = 0.0071, .rows = ROWS, .long_sections = NV,
                                 .v = vs, .comment = "test_profile_reader"};
    tirenv_crg_writer *w = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_crg_writer_open(path, &l, &w, &d), TIRENV_OK);
    for (size_t i = 0; i < ROWS; ++i) {
        double z[NV];
        for (size_t j = 0; j < NV; ++j)
            z[j] = road_z(-0.73 + (double)i * 0.0071, vs[j]);
        if (nan_row && i == 2000)
            z[0] = NAN;
        assert_int_equal(tirenv_crg_writer_row(w, z, &d), TIRENV_OK);
    }
    assert_int_equal(tirenv_crg_writer_commit(w, &d), TIRENV_OK);
}

/* Three tracks between and on the long sections, read three ways: the same numbers. */
static void test_crg_tracks(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_path(fx, "road.crg", path);
    write_road(path, 0);
    const double v[3] = {-0.8123, 0.0, 1.2977};
    tirenv_diag d;
    tirenv_profile *whole[3];
    assert_int_equal(tirenv_profile_read_tracks(path, NULL, 3, v, whole, &d), TIRENV_OK);
    tirenv_crg *crg = NULL;
    assert_int_equal(tirenv_crg_open(path, &crg, &d), TIRENV_OK);
    tirenv_profile_file_reader *r = NULL;
    assert_int_equal(tirenv_profile_file_reader_open(path, NULL, 3, v, &r, &d), TIRENV_OK);
    assert_int_equal(tirenv_profile_file_reader_format(r), TIRENV_PROFILE_CRG);
    for (size_t k = 0; k < 3; ++k) {
        tirenv_crg_track_spec s = tirenv_crg_track_default();
        s.v = v[k];
        tirenv_profile *one = NULL;
        assert_int_equal(tirenv_crg_track(crg, &s, &one, &d), TIRENV_OK);
        assert_int_equal(tirenv_profile_size(whole[k]), ROWS);
        for (size_t i = 0; i < ROWS; ++i) {
            assert_bits_equal(tirenv_profile_x(whole[k])[i], tirenv_profile_x(one)[i]);
            assert_bits_equal(tirenv_profile_z(whole[k])[i], tirenv_profile_z(one)[i]);
        }
        tirenv_profile_free(one);
    }
    size_t rows = 0;
    int got = 1;
    while (got) {
        double x, z[3];
        assert_int_equal(tirenv_profile_file_reader_next(r, &x, z, &got, &d), TIRENV_OK);
        if (!got)
            break;
        for (size_t k = 0; k < 3; ++k) {
            assert_bits_equal(x, tirenv_profile_x(whole[k])[rows]);
            assert_bits_equal(z[k], tirenv_profile_z(whole[k])[rows]);
        }
        ++rows;
    }
    assert_int_equal(rows, ROWS);
    /* A track between long sections is their linear interpolation (formats.md section 5.1). */
    const double u = tirenv_profile_x(whole[0])[1234];
    const double t = (-0.8123 - -1.1) / (-0.35 - -1.1);
    assert_near(tirenv_profile_z(whole[0])[1234],
                (1 - t) * road_z(u, -1.1) + t * road_z(u, -0.35), 1e-16, 0);
    tirenv_profile_file_reader_free(r);
    tirenv_crg_free(crg);
    for (size_t k = 0; k < 3; ++k)
        tirenv_profile_free(whole[k]);
}

/* A CSV and an RDF road are 2-D: every track gets the heights of the one profile. */
static void test_two_d_roads(void **state)
{
    tirenv_test_dir *fx = *state;
    char csv[600], rdf[600];
    tirenv_test_write_text(tirenv_test_path(fx, "p.csv", csv),
                           "# a road\nx_m,z_m\n0,0\n0.5,0.0127\n0.5,0.031\n1.75,0.031\n");
    tirenv_profile *p = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_profile_read_csv(csv, &p, &d), TIRENV_OK);
    assert_int_equal(tirenv_rdf_write(tirenv_test_path(fx, "p.rdf", rdf), p, NULL, NULL, &d),
                     TIRENV_OK);
    const char *paths[2] = {csv, rdf};
    const tirenv_profile_format formats[2] = {TIRENV_PROFILE_CSV, TIRENV_PROFILE_RDF};
    const double v[4] = {-3, 0.1, 7, 9};  /* no meaning on a 2-D road */
    for (size_t f = 0; f < 2; ++f) {
        tirenv_profile *t[4];
        assert_int_equal(tirenv_profile_read_tracks(paths[f], NULL, 4, v, t, &d), TIRENV_OK);
        tirenv_profile_file_reader *r = NULL;
        assert_int_equal(tirenv_profile_file_reader_open(paths[f], NULL, 4, v, &r, &d),
                         TIRENV_OK);
        assert_int_equal(tirenv_profile_file_reader_format(r), formats[f]);
        for (size_t i = 0; i < 4; ++i) {
            double x, z[4];
            int got;
            assert_int_equal(tirenv_profile_file_reader_source(r, &x, z, &got, &d), TIRENV_OK);
            assert_true(got);
            for (size_t k = 0; k < 4; ++k) {
                assert_ptr_not_equal(t[k], t[0 == k ? 1 : 0]);
                assert_bits_equal(tirenv_profile_z(t[k])[i], tirenv_profile_z(p)[i]);
                assert_bits_equal(z[k], tirenv_profile_z(p)[i]);
                assert_bits_equal(x, tirenv_profile_x(p)[i]);
            }
        }
        double x, z[4];
        int got = 1;
        assert_int_equal(tirenv_profile_file_reader_next(r, &x, z, &got, &d), TIRENV_OK);
        assert_false(got);
        tirenv_profile_file_reader_free(r);
        for (size_t k = 0; k < 4; ++k)
            tirenv_profile_free(t[k]);
    }
    tirenv_profile_free(p);
}

/* A track that needs a missing value fails in both readers naming the row; the whole reader
 * leaves nothing; a missing file and n = 0 are refused. */
static void test_errors(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600], missing[600];
    tirenv_test_path(fx, "nan.crg", path);
    write_road(path, 1);
    const double v[2] = {0.0, -1.0};
    tirenv_profile *t[2] = {NULL, NULL};
    tirenv_diag d;
    assert_int_equal(tirenv_profile_read_tracks(path, NULL, 2, v, t, &d), TIRENV_ERANGE);
    assert_null(t[0]);
    assert_null(t[1]);
    assert_non_null(strstr(d.message, "row 2001"));
    tirenv_profile_file_reader *r = NULL;
    assert_int_equal(tirenv_profile_file_reader_open(path, NULL, 2, v, &r, &d), TIRENV_OK);
    int status = TIRENV_OK, got = 1;
    size_t rows = 0;
    while (!status && got) {
        double x, z[2];
        status = tirenv_profile_file_reader_next(r, &x, z, &got, &d);
        rows += !status && got;
    }
    assert_int_equal(status, TIRENV_ERANGE);
    assert_int_equal(rows, 2000);
    assert_non_null(strstr(d.message, "row 2001"));
    tirenv_profile_file_reader_free(r);
    tirenv_profile_file_reader_free(NULL);
    tirenv_test_path(fx, "none.crg", missing);
    assert_int_equal(tirenv_profile_file_reader_open(missing, NULL, 1, NULL, &r, &d),
                     TIRENV_EIO);
    assert_null(r);
    assert_int_equal(tirenv_profile_file_reader_open(path, NULL, 0, NULL, &r, &d),
                     TIRENV_EINVAL);
    assert_int_equal(tirenv_profile_read_tracks(missing, NULL, 1, NULL, t, &d), TIRENV_EIO);
}

/* The reader as the stream's row source over two tracks, and the CRG track reader as a vertex
 * source over one: each equals the whole sweep bit for bit. */
static void test_stream_from_file(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_path(fx, "road.crg", path);
    write_road(path, 0);
    tirenv_tire tire = tirenv_tire_default();
    const double load = 11903.6, v[2] = {-0.2, 0.9}, x_from = 1, x_to = 19, dx = 0.004;
    const size_t n = tirenv_positions_count(x_from, x_to, dx);
    double *x = malloc(n * sizeof *x);
    tirenv_point *whole = malloc(n * sizeof *whole), *got = malloc(n * sizeof *got);
    for (size_t k = 0; k < n; ++k)
        x[k] = x_from + (double)k * dx;
    tirenv_diag d;
    tirenv_profile *t[2];
    assert_int_equal(tirenv_profile_read_tracks(path, NULL, 2, v, t, &d), TIRENV_OK);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &tire);
    const tirenv_profile *tracks[2] = {t[0], t[1]};
    assert_int_equal(tirenv_model_set_tracks(m, 2, tracks, NULL, load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_envelope(m, n, x, whole, NULL, &d), TIRENV_OK);
    tirenv_profile_file_reader *r = NULL;
    assert_int_equal(tirenv_profile_file_reader_open(path, NULL, 2, v, &r, &d), TIRENV_OK);
    tirenv_test_points sb = {got, 0, n, 0};
    assert_int_equal(tirenv_model_stream_tracks(m, 2, NULL, tirenv_profile_file_reader_source,
                                                r, x_from, x_to, dx, load, tirenv_test_keep_point, &sb,
                                                NULL, &d),
                     TIRENV_OK);
    assert_int_equal(sb.n, n);
    for (size_t k = 0; k < n; ++k) {
        assert_bits_equal(got[k].h, whole[k].h);
        assert_bits_equal(got[k].slope, whole[k].slope);
        assert_int_equal(got[k].iterations, whole[k].iterations);
    }
    tirenv_profile_file_reader_free(r);
    /* One track through tirenv_crg_track_reader_source. */
    assert_int_equal(tirenv_model_set(m, t[1], load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_envelope(m, n, x, whole, NULL, &d), TIRENV_OK);
    tirenv_crg *crg = NULL;
    assert_int_equal(tirenv_crg_open(path, &crg, &d), TIRENV_OK);
    tirenv_crg_track_spec s = tirenv_crg_track_default();
    s.v = v[1];
    tirenv_crg_track_reader *tr = NULL;
    assert_int_equal(tirenv_crg_track_reader_open(crg, &s, &tr, &d), TIRENV_OK);
    sb.n = 0;
    assert_int_equal(tirenv_model_stream(m, tirenv_crg_track_reader_source, tr, x_from, x_to,
                                         dx, load, tirenv_test_keep_point, &sb, NULL, &d),
                     TIRENV_OK);
    assert_int_equal(sb.n, n);  /* then sb.pt is still got */
    for (size_t k = 0; k < n; ++k) {
        assert_bits_equal(got[k].h, whole[k].h);
        assert_int_equal(got[k].iterations, whole[k].iterations);
    }
    tirenv_crg_track_reader_free(tr);
    tirenv_crg_free(crg);
    tirenv_model_free(m);
    tirenv_profile_free(t[0]);
    tirenv_profile_free(t[1]);
    free(x);
    free(whole);
    free(got);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_crg_tracks, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_two_d_roads, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_errors, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_stream_from_file, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
