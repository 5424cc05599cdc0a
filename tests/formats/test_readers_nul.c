/* A NUL byte in a text file ended the C string: the rest of the line was dropped without a
 * word. Every line reader refuses it with file, line and column (docs/formats.md section 1):
 * profiles, the streaming profile, curves, rig logs, manifests, .tir and .veh files.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <stdio.h>
#include <string.h>

#include "tirenv/tirenv.h"

/* Writes n bytes (NULs included) to dir/name; returns the path in buf. */
static const char *write_bytes(const tirenv_test_dir *d, const char *name, const char *bytes,
                               size_t n, char buf[600])
{
    tirenv_test_path(d, name, buf);
    FILE *fp = fopen(buf, "wb");
    assert_non_null(fp);
    assert_int_equal(fwrite(bytes, 1, n, fp), n);
    assert_int_equal(fclose(fp), 0);
    return buf;
}

static void expect_nul(const tirenv_diag *diag, const char *path, size_t line, size_t column)
{
    assert_string_equal(diag->file, path);
    assert_int_equal(diag->line, line);
    assert_int_equal(diag->column, column);
    assert_non_null(strstr(diag->message, "NUL byte"));
}

/* "-0.05,0.1\0junk": the NUL is column 10 of line 3; without the check the row read
 * "-0.05,0.1" and "junk" vanished. Also in the header, and for the streaming reader, which
 * meets it at its second vertex. */
static void test_profiles(void **state)
{
    const tirenv_test_dir *d = *state;
    static const char text[] = "x_m,z_m\n-0.05,0\n-0.05,0.1\0junk\n0.05,0.1\n0.05,0\n";
    char path[600];
    write_bytes(d, "p.csv", text, sizeof text - 1, path);
    tirenv_profile *p = NULL;
    tirenv_diag diag;
    assert_int_equal(tirenv_profile_read_csv(path, &p, &diag), TIRENV_EPARSE);
    assert_null(p);
    expect_nul(&diag, path, 3, 10);

    tirenv_profile_file_reader *r = NULL;
    assert_int_equal(tirenv_profile_file_reader_open(path, NULL, 1, NULL, &r, &diag), 0);
    assert_int_equal(tirenv_profile_file_reader_format(r), TIRENV_PROFILE_CSV);
    double x, z;
    int got;
    assert_int_equal(tirenv_profile_file_reader_next(r, &x, &z, &got, &diag), 0);
    assert_int_equal(got, 1);
    assert_int_equal(tirenv_profile_file_reader_next(r, &x, &z, &got, &diag), TIRENV_EPARSE);
    expect_nul(&diag, path, 3, 10);
    tirenv_profile_file_reader_free(r);

    static const char header[] = "x_m,z\0_m\n-0.05,0\n0.05,0\n";
    write_bytes(d, "h.csv", header, sizeof header - 1, path);
    assert_int_equal(tirenv_profile_read_csv(path, &p, &diag), TIRENV_EPARSE);
    expect_nul(&diag, path, 1, 6);
    assert_int_equal(tirenv_profile_file_reader_open(path, NULL, 1, NULL, &r, &diag),
                     TIRENV_EPARSE);
    expect_nul(&diag, path, 1, 6);
}

/* A curve, a rig log and a manifest: the NUL on a data row, at the end of the row or inside a
 * field. */
static void test_curve_log_manifest(void **state)
{
    const tirenv_test_dir *d = *state;
    char path[600];
    tirenv_diag diag;
    static const char curve[] = "x_N,x_m,h_m\n0,-0.5,0\n0.5,-0.25,0.01\0\n1,0,0.05\n";
    write_bytes(d, "c.csv", curve, sizeof curve - 1, path);
    tirenv_curve c = {0};
    assert_int_equal(tirenv_curve_read_csv(path, &c, &diag), TIRENV_EPARSE);
    expect_nul(&diag, path, 3, 15);

    static const char log[] = "t_s,x_m,z_m\n0,0,0.6\n0.01,0\0.001,0.6\n";
    write_bytes(d, "log.csv", log, sizeof log - 1, path);
    tirenv_import_settings s = tirenv_import_default();
    s.L = s.H = 0.1;
    s.R0 = 0.68;
    s.contact_length = 0.28;
    assert_int_equal(tirenv_rig_import(path, &s, &c, &diag), TIRENV_EPARSE);
    expect_nul(&diag, path, 3, 7);

    char dir[600];
    snprintf(dir, sizeof dir, "%s", d->dir);
    static const char manifest[] =
        "case,split,contact_length_m,load_N,obstacle_length_m,obstacle_height_m,log,curve\n"
        "A,train,0.28,1e4,0.1,0.1,,c.csv\0\n";
    write_bytes(d, "cases.csv", manifest, sizeof manifest - 1, path);
    tirenv_dataset ds;
    assert_int_equal(tirenv_dataset_read(dir, 0.68, &ds, &diag), TIRENV_EPARSE);
    expect_nul(&diag, path, 2, 32);
}

/* The property files: in a value (the rest of the line, "5", would be lost), a key, a
 * comment. */
static void test_property_files(void **state)
{
    const tirenv_test_dir *d = *state;
    char path[600];
    tirenv_diag diag;
    static const char tir[] = "[DIMENSION]\nUNLOADED_RADIUS = 0.6\0" "5\n";
    write_bytes(d, "t.tir", tir, sizeof tir - 1, path);
    tirenv_tire t = tirenv_tire_default();
    assert_int_equal(tirenv_tir_read(path, &t, &diag), TIRENV_EPARSE);
    expect_nul(&diag, path, 2, 22);
    assert_true(t.springs.R0 == tirenv_tire_default().springs.R0);  /* unchanged */

    static const char veh[] = "[BODY]\n$ a comment\0\nMASS = 4000\n";
    write_bytes(d, "v.veh", veh, sizeof veh - 1, path);
    tirenv_vehicle v = tirenv_vehicle_default();
    assert_int_equal(tirenv_vehicle_read(path, &v, &diag), TIRENV_EPARSE);
    expect_nul(&diag, path, 2, 12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_profiles, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_curve_log_manifest, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_property_files, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
