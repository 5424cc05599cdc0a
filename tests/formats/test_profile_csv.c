/* Profile CSV import: good files, and each malformed case with its line, column and field.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/profile_csv.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void assert_vertices(const tirenv_profile *p, size_t n, const double x[],
                            const double z[])
{
    assert_int_equal(tirenv_profile_size(p), n);
    /* strtod and the compiler round the same decimal text the same way: exact. */
    for (size_t k = 0; k < n; k++) {
        assert_true(tirenv_profile_x(p)[k] == x[k]);
        assert_true(tirenv_profile_z(p)[k] == z[k]);
    }
}

static void test_good_file(void **state)
{
    (void)state;
    tirenv_profile *p = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_profile_read_csv(TIRENV_TEST_DATA "/profile_good.csv", &p, &d),
                     TIRENV_OK);
    const double x[] = {-1.25, -0.125, 0.0, 0.0, 0.375, 1.5};
    const double z[] = {0.0, 0.0375, 0.0375, 0.0825, 0.0825, -2.5e-3};
    assert_vertices(p, 6, x, z);
    tirenv_profile_free(p);
}

static void test_crlf_file(void **state)
{
    (void)state;
    tirenv_profile *p = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_profile_read_csv(TIRENV_TEST_DATA "/profile_crlf.csv", &p, &d),
                     TIRENV_OK);
    const double x[] = {-0.5, -0.02, -0.02, 0.02, 0.02, 0.5};
    const double z[] = {0.0, 0.0, 0.04, 0.04, 0.0, 0.0};
    assert_vertices(p, 6, x, z);
    tirenv_profile_free(p);
}

/* A spreadsheet export: byte-order mark, CRLF, spaces and tabs around the fields. The same
 * file without its last line end is refused at that line: cut there, it could have been
 * "2.5,0.755" (docs/formats.md section 1); a comment or blank last line without one reads. */
static void test_bom_and_blanks(void **state)
{
    (void)state;
    static const char text[] =
        "\xEF\xBB\xBF x_m ,\tz_m \r\n\r\n 0.125 ,\t-0.0625\t\r\n   \r\n2.5,0.75\r\n";
    for (int k = 0; k < 3; k++) {
        char path[64], body[sizeof text + 16];
        snprintf(body, sizeof body, "%.*s%s", (int)(sizeof text - (k == 1 ? 3 : 1)), text,
                 k == 2 ? "# end" : "");
        tirenv_test_write_temp(path, "csv", body);
        tirenv_profile *p = NULL;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        const int status = tirenv_profile_read_csv(path, &p, &d);
        if (k == 1) {
            tirenv_test_expect_diag(k, status, &d, TIRENV_EPARSE, path, 5, 9, "",
                                    "the file ends inside this line, which has no line end");
            assert_null(p);
            remove(path);
            continue;
        }
        remove(path);
        assert_int_equal(status, TIRENV_OK);
        const double x[] = {0.125, 2.5};
        const double z[] = {-0.0625, 0.75};
        assert_vertices(p, 2, x, z);
        tirenv_profile_free(p);
    }
}

/* Many rows (the array grows) and a comment line as long as the line cap allows (65,536
 * characters, docs/formats.md section 1); one character more is an error at its line. */
static void test_large_file(void **state)
{
    (void)state;
    char path[64];
    tirenv_test_write_temp(path, "csv", "x_m,z_m\n0,0\n");
    FILE *fp = fopen(path, "a");
    assert_non_null(fp);
    fputc('#', fp);
    for (size_t k = 0; k < 65536; k++)
        fputc('-', fp);
    fputs("\n1,0\n", fp);
    assert_int_equal(fclose(fp), 0);
    tirenv_profile *q = NULL;
    tirenv_diag e;
    assert_int_equal(tirenv_profile_read_csv(path, &q, &e), TIRENV_EPARSE);
    assert_null(q);
    assert_int_equal(e.line, 3);
    assert_non_null(strstr(e.message, "line longer than 65536 characters"));
    fp = fopen(path, "w");
    assert_non_null(fp);
    fputc('#', fp);
    for (size_t k = 0; k < 65535; k++)
        fputc('-', fp);
    fputs("\nx_m,z_m\n", fp);
    const size_t n = 20001;
    for (size_t k = 0; k < n; k++)
        fprintf(fp, "%.17g,%.17g\n", 0.001 * (double)k, 0.01 * (double)(k % 7));
    assert_int_equal(fclose(fp), 0);
    tirenv_profile *p = NULL;
    tirenv_diag d;
    const int status = tirenv_profile_read_csv(path, &p, &d);
    remove(path);
    assert_int_equal(status, TIRENV_OK);
    assert_int_equal(tirenv_profile_size(p), n);
    assert_true(tirenv_profile_x(p)[n - 1] == 0.001 * (double)(n - 1));
    assert_true(tirenv_profile_z(p)[n - 1] == 0.01 * (double)((n - 1) % 7));
    tirenv_profile_free(p);
}

typedef struct {
    const char *text;
    size_t line, column;
    const char *field;
    const char *says; /* a phrase the message must contain */
} csv_error_case;

static const csv_error_case csv_errors[] = {
    {"0.0,0.0\n", 1, 1, "x_m", "expected the header 'x_m,z_m', got '0.0' for column 1"},
    {"# profile\n\nx,z\n0,0\n", 3, 1, "x_m", "got 'x' for column 1"},
    {"x_m, z_mm\n0,0\n", 1, 6, "z_m", "got 'z_mm' for column 2"},
    {"x_m,z_m,w_m\n0,0\n", 1, 9, "", "expected the header 'x_m,z_m' (2 columns), got 3"},
    {"x_m,z_m\n0.0,0.0\n0.1, abc\n", 3, 6, "z_m", "expected a number, got 'abc'"},
    {"x_m,z_m\n0.1x,0\n", 2, 1, "x_m", "expected a number, got '0.1x'"},
    {"x_m,z_m\n0.1,0 0\n", 2, 5, "z_m", "expected a number, got '0 0'"},
    {"x_m,z_m\n,0.0\n", 2, 1, "x_m", "expected a number, got an empty field"},
    {"x_m,z_m\n0.0,0.0, 0.0\n", 2, 10, "", "expected 2 fields, got 3"},
    {"x_m,z_m\n0.0;0.0\n", 2, 8, "z_m", "expected 2 fields, got 1"},
    {"x_m,z_m\n0.20,0\n\n# back\n0.10,0\n", 5, 1, "x_m", "x_m decreases (0.10 after 0.20)"},
    {"x_m,z_m\n0,inf\n", 2, 3, "z_m", "expected a finite number, got 'inf'"},
    {"x_m,z_m\r\n  nan,0\r\n", 2, 3, "x_m", "expected a finite number, got 'nan'"},
    {"x_m,z_m\n0,1e400\n", 2, 3, "z_m", "expected a finite number"},
    {"x_m,z_m\n0,0\n# a wall, then a third vertex at its x\n1,0\n1,0.1\n1,0.2\n", 6, 1,
     "x_m", "a third vertex at x_m = 1; expected at most two (a wall)"},
    {"# only a header\nx_m,z_m\n# nothing\n\n", 0, 0, "", "no data rows"},
    {"", 0, 0, "", "no header line"},
    {"# comments\n\n# only\n", 0, 0, "", "no header line"},
};

static void test_errors(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof csv_errors / sizeof csv_errors[0]; i++) {
        const csv_error_case *k = &csv_errors[i];
        char path[64];
        tirenv_test_write_temp(path, "csv", k->text);
        tirenv_profile *p = (tirenv_profile *)&p; /* must come back NULL */
        tirenv_diag d;
        tirenv_diag_clear(&d);
        const int status = tirenv_profile_read_csv(path, &p, &d);
        remove(path);
        char line[1200];
        print_message("case %zu: %s\n", i, tirenv_diag_format(&d, line, sizeof line));
        assert_int_equal(status, TIRENV_EPARSE);
        assert_null(p);
        assert_string_equal(d.file, path);
        assert_int_equal(d.line, k->line);
        assert_int_equal(d.column, k->column);
        assert_string_equal(d.field, k->field);
        assert_non_null(strstr(d.message, k->says));
    }
}

static void test_missing_file(void **state)
{
    (void)state;
    tirenv_profile *p = (tirenv_profile *)&p;
    tirenv_diag d;
    const char *path = TIRENV_TEST_DATA "/profile_no_such_file.csv";
    assert_int_equal(tirenv_profile_read_csv(path, &p, &d), TIRENV_EIO);
    assert_null(p);
    assert_string_equal(d.file, path);
    assert_non_null(strstr(d.message, strerror(ENOENT)));
    p = (tirenv_profile *)&p;
    assert_int_equal(tirenv_profile_read_csv(TIRENV_TEST_DATA, &p, &d), TIRENV_EIO);
    assert_null(p);
    assert_string_equal(d.file, TIRENV_TEST_DATA);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_good_file),    cmocka_unit_test(test_crlf_file),
        cmocka_unit_test(test_bom_and_blanks), cmocka_unit_test(test_large_file),
        cmocka_unit_test(test_errors),       cmocka_unit_test(test_missing_file),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
