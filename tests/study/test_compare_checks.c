/* What compare refuses before it evaluates anything (docs/models.md section 8): a case listed
 * twice, which counted twice in the means, a title with a control character, which broke
 * the report's Markdown heading, and two cases whose plot files would be the same, which
 * showed one case's figure under the other's name. SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <dirent.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "tirenv/tirenv.h"

static int run(const char *const cases[], size_t n, const char *title, const char *out_dir,
               tirenv_diag *diag)
{
    tirenv_dataset ds;
    assert_int_equal(tirenv_dataset_read(TIRENV_TEST_DATA "/dataset_good", 0.68, &ds, diag), 0);
    tirenv_compare_settings s = tirenv_compare_default();
    s.cases = cases;
    s.n_cases = n;
    s.title = title;
    s.out_dir = out_dir;
    s.images = 0;
    s.min_time = 0;
    const tirenv_tire t = tirenv_tire_default();
    tirenv_compare_result r;
    tirenv_diag_clear(diag);
    const int status = tirenv_compare(&ds, &t, NULL, &s, &r, diag);
    tirenv_compare_result_free(&r);
    tirenv_dataset_free(&ds);
    return status;
}

/* The scratch teardown removes files, not directories. */
static void remove_dir(const char *out)
{
    char file[900];
    DIR *dir = opendir(out);
    assert_non_null(dir);
    for (struct dirent *e; (e = readdir(dir));)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
            snprintf(file, sizeof file, "%s/%s", out, e->d_name);
            assert_int_equal(remove(file), 0);
        }
    closedir(dir);
    assert_int_equal(rmdir(out), 0);
}

static void test_refusals(void **state)
{
    const tirenv_test_dir *d = *state;
    char out[600];
    tirenv_test_path(d, "cmp", out);
    tirenv_diag diag;
    const char *const twice[] = {"J", "R", "J"};
    assert_int_equal(run(twice, 3, NULL, out, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "cases");
    assert_non_null(strstr(diag.message, "case 'J' is listed twice (cases 1 and 3"));
    assert_int_equal(access(out, F_OK), -1);  /* refused before anything is written */
    /* No data set, tire, settings or result: refused (they were dereferenced), the result
     * freeable. */
    tirenv_dataset ds;
    assert_int_equal(tirenv_dataset_read(TIRENV_TEST_DATA "/dataset_good", 0.68, &ds, &diag), 0);
    const tirenv_tire t = tirenv_tire_default();
    tirenv_compare_settings s = tirenv_compare_default();
    s.out_dir = out;
    tirenv_compare_result r;
    assert_int_equal(tirenv_compare(NULL, &t, NULL, &s, &r, &diag), TIRENV_EINVAL);
    tirenv_compare_result_free(&r);
    assert_int_equal(tirenv_compare(&ds, NULL, NULL, &s, &r, &diag), TIRENV_EINVAL);
    tirenv_compare_result_free(&r);
    assert_int_equal(tirenv_compare(&ds, &t, NULL, NULL, &r, &diag), TIRENV_EINVAL);
    tirenv_compare_result_free(&r);
    assert_int_equal(tirenv_compare(&ds, &t, NULL, &s, NULL, &diag), TIRENV_EINVAL);
    tirenv_dataset_free(&ds);
    assert_int_equal(access(out, F_OK), -1);
    const char *const once[] = {"J", "R"};
    assert_int_equal(run(once, 2, "two\nlines", out, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "title");
    assert_non_null(strstr(diag.message, "(0x0a) at position 4"));
    assert_int_equal(run(once, 2, "tab\there", out, &diag), TIRENV_EINVAL);
    assert_int_equal(access(out, F_OK), -1);
    /* The same cases once each, with a plain title (UTF-8 is fine): compared. */
    assert_int_equal(run(once, 2, "Fälle J und R", out, &diag), 0);
    char file[900];
    snprintf(file, sizeof file, "%s/errors.csv", out);
    assert_int_equal(access(file, F_OK), 0);
    remove_dir(out);
}

/* "x y" and "x_y" both draw into x_y.*: refused naming both, before anything is written;
 * "x.y" is another file and compares. */
static void test_plot_names(void **state)
{
    const tirenv_test_dir *d = *state;
    char out[600];
    tirenv_test_path(d, "cmp", out);
    tirenv_dataset ds;
    tirenv_diag diag;
    assert_int_equal(tirenv_dataset_read(TIRENV_TEST_DATA "/dataset_good", 0.68, &ds, &diag), 0);
    tirenv_compare_settings s = tirenv_compare_default();
    s.out_dir = out;
    s.images = 0;
    s.min_time = 0;
    const tirenv_tire t = tirenv_tire_default();
    tirenv_compare_result r;
    const char *const pair[] = {"J", "R"};
    size_t at[2] = {ds.n, ds.n};
    for (size_t i = 0; i < ds.n; ++i)
        for (size_t k = 0; k < 2; ++k)
            if (strcmp(ds.cases[i].name, pair[k]) == 0)
                at[k] = i;
    assert_true(at[0] < ds.n && at[1] < ds.n);
    snprintf(ds.cases[at[0]].name, sizeof ds.cases[at[0]].name, "x y");
    snprintf(ds.cases[at[1]].name, sizeof ds.cases[at[1]].name, "x_y");
    const char *const clash[] = {"x y", "x_y"};
    s.cases = clash;
    s.n_cases = 2;
    assert_int_equal(tirenv_compare(&ds, &t, NULL, &s, &r, &diag), TIRENV_EINVAL);
    tirenv_compare_result_free(&r);
    assert_string_equal(diag.field, "cases");
    assert_non_null(strstr(diag.message, "cases 'x y' and 'x_y' would share the plot files "
                                         "x_y.*"));
    assert_int_equal(access(out, F_OK), -1);
    snprintf(ds.cases[at[1]].name, sizeof ds.cases[at[1]].name, "x.y");
    const char *const apart[] = {"x y", "x.y"};
    s.cases = apart;
    assert_int_equal(tirenv_compare(&ds, &t, NULL, &s, &r, &diag), TIRENV_OK);
    tirenv_compare_result_free(&r);
    tirenv_dataset_free(&ds);
    remove_dir(out);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_refusals, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_plot_names, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
