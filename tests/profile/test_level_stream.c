/* SPDX-License-Identifier: Apache-2.0 */
/* The road's local level along a sweep from a vertex source (tirenv_level_stream, stream.h):
 * the same bits as tirenv_profile_level over the whole profile, on a bumpy road with walls and
 * on one shorter than the window; the source's failure passes through; the level width. */
#include "testutil.h"
#include "tirenv/tirenv.h"

#include <math.h>
#include <stdlib.h>

/* A source over arrays in memory: vertex k of n, then the end; fails at vertex fail_at
 * (1-based) when nonzero. */
typedef struct {
    const double *x, *z;
    size_t n, k, fail_at;
} array_source;

static int array_next(void *ctx, double *x, double *z, int *got, tirenv_diag *diag)
{
    array_source *s = ctx;
    if (s->fail_at && s->k + 1 == s->fail_at)
        return tirenv_error(diag, TIRENV_EIO, "road.csv", s->k + 2, "z_m", "made-up failure");
    *got = s->k < s->n;
    if (*got) {
        *x = s->x[s->k];
        *z = s->z[s->k];
        ++s->k;
    }
    return TIRENV_OK;
}

/* A road of n vertices every 9.1 mm: sines, and a wall (two vertices at one x) every 97th,
 * starting at x0 (m). */
static void road(size_t n, double x0, double x[], double z[])
{
    for (size_t k = 0; k < n; ++k) {
        x[k] = k > 0 && k % 97 == 0 ? x[k - 1] : x0 + 0.0091 * (double)k;
        z[k] = 0.021 * sin(1.7 * x[k]) + 0.0063 * sin(13.1 * x[k] + 0.3) +
               (k % 97 >= 50 ? 0.043 : 0.0);
    }
}

/* The streamed level at positions in x order equals the level over the whole profile, bit for
 * bit, before, over and after the road, for two widths. */
static void check_equals_whole(size_t n, double x0, double width)
{
    double *x = malloc(n * sizeof *x), *z = malloc(n * sizeof *z);
    assert_non_null(x);
    assert_non_null(z);
    road(n, x0, x, z);
    tirenv_profile *whole = tirenv_profile_alloc(n, x, z);
    assert_non_null(whole);
    array_source src = {x, z, n, 0, 0};
    tirenv_level_stream *s = tirenv_level_stream_alloc(array_next, &src, width);
    assert_non_null(s);
    tirenv_diag d;
    size_t checked = 0;
    for (double at = x[0] - 1.3; at < x[n - 1] + 1.3; at += 0.0137) {
        double level = NAN;
        assert_int_equal(tirenv_level_stream_at(s, at, &level, &d), TIRENV_OK);
        assert_bits_equal(level, tirenv_profile_level(whole, width, at));
        ++checked;
    }
    assert_true(checked > 100);
    assert_int_equal(src.k, n);  /* read to the end, once */
    tirenv_level_stream_free(s);
    tirenv_profile_free(whole);
    free(x);
    free(z);
}

static void test_equals_whole(void **state)
{
    (void)state;
    check_equals_whole(2311, -3.217, 1.36);  /* about 21 m: many windows */
    check_equals_whole(2311, 0.0, 0.317);
    check_equals_whole(41, 1.5, 1.36);       /* shorter than one window */
}

/* A failing source stops the level with its code and message; no profile is not a level. */
static void test_errors(void **state)
{
    (void)state;
    double x[300], z[300];
    road(300, 0.0, x, z);
    array_source src = {x, z, 300, 0, 200};
    tirenv_level_stream *s = tirenv_level_stream_alloc(array_next, &src, 0.5);
    assert_non_null(s);
    tirenv_diag d;
    double level = 0;
    int status = TIRENV_OK;
    for (double at = 0; at < 2.7 && !status; at += 0.01)
        status = tirenv_level_stream_at(s, at, &level, &d);
    assert_int_equal(status, TIRENV_EIO);
    assert_string_equal(d.file, "road.csv");
    assert_int_equal(d.line, 201);
    tirenv_level_stream_free(s);

    array_source empty = {x, z, 0, 0, 0};
    s = tirenv_level_stream_alloc(array_next, &empty, 0.5);
    assert_non_null(s);
    assert_int_equal(tirenv_level_stream_at(s, 0.0, &level, &d), TIRENV_EINVAL);
    tirenv_level_stream_free(s);
    tirenv_level_stream_free(NULL);
}

/* A position behind the last one (or not a number) is refused: the window has dropped the
 * ground there (the level at 2 m after one at 15 m was the flat extension of the window's
 * first vertex, 13.6 m on, with status OK). */
static void test_going_back(void **state)
{
    (void)state;
    double x[2311], z[2311];
    road(2311, 0.0, x, z);
    array_source src = {x, z, 2311, 0, 0};
    tirenv_level_stream *s = tirenv_level_stream_alloc(array_next, &src, 1.36);
    assert_non_null(s);
    tirenv_diag d;
    double level = 0;
    assert_int_equal(tirenv_level_stream_at(s, 15.0, &level, &d), TIRENV_OK);
    assert_int_equal(tirenv_level_stream_at(s, 2.0, &level, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "x");
    assert_int_equal(tirenv_level_stream_at(s, NAN, &level, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_level_stream_at(s, 15.0, &level, &d), TIRENV_OK);  /* again */
    tirenv_profile *whole = tirenv_profile_alloc(2311, x, z);
    assert_non_null(whole);
    assert_bits_equal(level, tirenv_profile_level(whole, 1.36, 15.0));
    tirenv_profile_free(whole);
    tirenv_level_stream_free(s);
}

/* The width is the tire's free diameter. */
static void test_width(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    tire.springs.R0 = 0.6843;
    assert_true(tirenv_level_width(&tire) == 2 * 0.6843);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_equals_whole),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_going_back),
        cmocka_unit_test(test_width),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
