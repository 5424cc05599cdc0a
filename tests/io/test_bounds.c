/* SPDX-License-Identifier: Apache-2.0 */
/* Counts and lines from input, bounded: tirenv_positions_count in constant time
 * for any doubles, 0 for what is no sweep; the capped line reader of src/io (io.h)
 * at, just past and far past its cap. */
#include "testutil.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io.h"
#include "tirenv/stream.h"

/* The count as it was (loops unbounded), for inputs where it terminated: the new one must
 * equal it there, bit for bit the CLI's sweeps. */
static size_t count_by_loops(double x_from, double x_to, double dx)
{
    const double limit = x_to + dx * 1e-9;
    size_t n = (size_t)floor((limit - x_from) / dx) + 1;
    while (n > 1 && x_from + (double)(n - 1) * dx > limit)
        --n;
    while (x_from + (double)n * dx <= limit)
        ++n;
    return n;
}

static void test_positions_ordinary(void **state)
{
    (void)state;
    assert_int_equal(tirenv_positions_count(0, 1, 0.1), 11);
    assert_int_equal(tirenv_positions_count(2.385, 2.385, 0.001), 1);
    /* A spread of ends and steps where round-off decides the last position. */
    unsigned long seed = 12345;
    for (int i = 0; i < 20000; ++i) {
        seed = seed * 6364136223846793005ul + 1442695040888963407ul;
        const double u = (double)(seed >> 11) / 9007199254740992.0;
        seed = seed * 6364136223846793005ul + 1442695040888963407ul;
        const double w = (double)(seed >> 11) / 9007199254740992.0;
        const double x_from = -50 + 100 * u, dx = pow(10, -4 + 3 * w);
        const double x_to = x_from + dx * floor(1000 * w) + (i % 3 ? 0 : dx * 1e-12);
        assert_int_equal(tirenv_positions_count(x_from, x_to, dx),
                         count_by_loops(x_from, x_to, dx));
    }
}

static void test_positions_refused(void **state)
{
    (void)state;
    const double bad[][3] = {
        {0, INFINITY, 0.1},   {0, NAN, 0.1},      {NAN, 1, 0.1},     {-INFINITY, 0, 0.1},
        {0, 1, 0},            {0, 1, -0.1},       {0, 1, NAN},       {0, 1, INFINITY},
        {1, 0, 0.1},          {0, 1e300, 0.1},    {-1e300, 1e300, 0.1},
        {1e300, 1e300, 0.1},  {0, 1, 1e-300},     {0, 1e9, 1e-3},    {0, DBL_MAX, DBL_MAX},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i)
        if (tirenv_positions_count(bad[i][0], bad[i][1], bad[i][2]) != 0)
            fail_msg("from %g to %g every %g: expected 0, got %zu", bad[i][0], bad[i][1],
                     bad[i][2], tirenv_positions_count(bad[i][0], bad[i][1], bad[i][2]));
    /* Just under the cap is a count; at it, none. */
    assert_int_equal(tirenv_positions_count(0, 0.999e12 - 10, 1), (size_t)(0.999e12 - 10) + 1);
    assert_int_equal(tirenv_positions_count(0, TIRENV_POSITIONS_MAX, 1), 0);
}

/* A file holding text, rewound for reading. */
static FILE *text_file(const char *text, size_t n)
{
    FILE *fp = tmpfile();
    assert_non_null(fp);
    assert_int_equal(fwrite(text, 1, n, fp), n);
    rewind(fp);
    return fp;
}

static void test_line_cap(void **state)
{
    (void)state;
    const size_t cap = TIRENV_TEXT__MAX_LINE;
    char *text = malloc(3 * cap + 16);
    assert_non_null(text);
    /* Line 1 exactly at the cap with CRLF, line 2 "ab" without an end, then the end. */
    memset(text, 'x', cap);
    memcpy(text + cap, "\r\nab", 4);
    FILE *fp = text_file(text, cap + 4);
    char *buf = NULL;
    size_t size = 0, len = 0;
    assert_int_equal(tirenv_text__getline(&buf, &size, fp, &len), TIRENV_TEXT__LINE);
    assert_int_equal(len, cap + 2);
    assert_int_equal(buf[cap], '\r');
    assert_int_equal(tirenv_text__getline(&buf, &size, fp, &len), TIRENV_TEXT__LINE);
    assert_int_equal(len, 2);
    assert_string_equal(buf, "ab");
    assert_int_equal(tirenv_text__getline(&buf, &size, fp, &len), TIRENV_TEXT__EOF);
    fclose(fp);
    /* One past the cap, then far past: too long, and the buffer stays within the cap. */
    for (size_t over = 1; over <= 2 * cap; over *= 2 * cap) {
        memset(text, 'y', cap + over);
        text[cap + over] = '\n';
        fp = text_file(text, cap + over + 1);
        assert_int_equal(tirenv_text__getline(&buf, &size, fp, &len), TIRENV_TEXT__LONG);
        assert_true(size <= cap + 3);
        fclose(fp);
    }
    /* NUL bytes are counted in len, for the callers' check. */
    fp = text_file("a\0b\n", 4);
    assert_int_equal(tirenv_text__getline(&buf, &size, fp, &len), TIRENV_TEXT__LINE);
    assert_int_equal(len, 4);
    assert_int_equal(buf[1], '\0');
    fclose(fp);
    free(buf);
    free(text);
}

/* A read failure is an error, never the end: a directory opened as a file fails to read. */
static void test_read_failure(void **state)
{
    (void)state;
    FILE *fp = fopen("/", "r");
    assert_non_null(fp);
    char *buf = NULL;
    size_t size = 0, len = 0;
    assert_int_equal(tirenv_text__getline(&buf, &size, fp, &len), TIRENV_TEXT__ERROR);
    fclose(fp);
    free(buf);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_positions_ordinary),
        cmocka_unit_test(test_positions_refused),
        cmocka_unit_test(test_line_cap),
        cmocka_unit_test(test_read_failure),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
