/* tirenv_test_shell_quote, which the tests use to put the clone's paths into system() lines:
 * whatever the string holds (blanks, single quotes, the shell's other specials), the shell
 * reads the quoted word back as that one string.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <stdio.h>
#include <string.h>

/* What /bin/sh makes of "printf %s WORD" (popen runs it through sh -c), into out. */
static void shell_echo(const char *word, char *out, size_t size)
{
    char cmd[1024];
    assert_true((size_t)snprintf(cmd, sizeof cmd, "printf %%s %s", word) < sizeof cmd);
    FILE *fp = popen(cmd, "r");
    assert_non_null(fp);
    const size_t n = fread(out, 1, size - 1, fp);
    out[n] = 0;
    assert_int_equal(pclose(fp), 0);
}

static void test_shell_reads_back_the_string(void **state)
{
    (void)state;
    static const char *const cases[] = {
        "/home/a user/my  clone/build/tirenv",  /* blanks, two in a row */
        "/srv/it's/data",                       /* a single quote mid-word */
        "'",                                    /* nothing but a quote */
        "'lead and trail'",
        "''two''",                              /* quotes side by side */
        "$HOME `id` $(id) \\ \" * ? ~ ; & | < > # !\t\n",
        "",                                     /* the empty string stays one (empty) word */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        char quoted[256], back[256];
        assert_ptr_equal(tirenv_test_shell_quote(cases[i], quoted, sizeof quoted), quoted);
        printf("# case %zu\n", i);
        shell_echo(quoted, back, sizeof back);
        assert_string_equal(back, cases[i]);
    }
}

/* Each ' becomes the four bytes '\'' inside the enclosing pair, and a buffer of exactly the
 * quoted length plus its NUL is enough. */
static void test_quote_is_written_as_four_bytes(void **state)
{
    (void)state;
    char quoted[10];
    tirenv_test_shell_quote("it's", quoted, sizeof quoted);
    assert_string_equal(quoted, "'it'\\''s'");
    assert_int_equal(strlen(quoted) + 1, sizeof quoted);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shell_reads_back_the_string),
        cmocka_unit_test(test_quote_is_written_as_four_bytes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
