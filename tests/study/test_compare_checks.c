/* What compare refuses before it evaluates anything (docs/models.md section 8): a case listed
 * twice, which counted twice in the means, and a title with a control character, which broke
 * the report's Markdown heading. SPDX-License-Identifier: Apache-2.0 */
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
    DIR *dir = opendir(out);  /* the scratch teardown removes files, not directories */
    assert_non_null(dir);
    for (struct dirent *e; (e = readdir(dir));)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
            snprintf(file, sizeof file, "%s/%s", out, e->d_name);
            assert_int_equal(remove(file), 0);
        }
    closedir(dir);
    assert_int_equal(rmdir(out), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_refusals, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
