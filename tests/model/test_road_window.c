/* The road window (tirenv_road_window, stream.h) on its own: what a fill holds, the rows it
 * refuses, and its memory after a far jump. Both streams (tirenv_model_stream_tracks and the
 * CLI's parallel stream) read their ground through it.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/tirenv.h"

#include <math.h>
#include <stdlib.h>

/* Two tracks in memory: row k at x = 0.137 k - 3.1 m, heights from sines, n rows; or rows
 * from arrays when x is set. */
typedef struct {
    size_t n, k, calls;
    const double *x, *z0;  /* NULL: generated */
} rows;

static double row_x(size_t k)
{
    return 0.137 * (double)k - 3.1;
}

static int rows_next(void *ctx, double *x, double z[], int *got, tirenv_diag *diag)
{
    (void)diag;
    rows *r = ctx;
    ++r->calls;
    *got = r->k < r->n;
    if (*got) {
        *x = r->x ? r->x[r->k] : row_x(r->k);
        z[0] = r->z0 ? r->z0[r->k] : 0.013 * sin(1.7 * *x);
        z[1] = -0.0071 * cos(4.1 * *x);
        ++r->k;
    }
    return TIRENV_OK;
}

/* A fill holds the rows from the last before x_keep to the first after x_need, whole
 * segments across the stretch, each track's heights as the source gave them; covers says
 * when to read on. */
static void test_fill_holds_the_stretch(void **state)
{
    (void)state;
    rows src = {.n = 97};
    tirenv_road_window *w = tirenv_road_window_alloc(rows_next, &src, 2);
    assert_non_null(w);
    tirenv_diag d;
    tirenv_profile *p[2] = {NULL, NULL};
    /* The first fill reads one row: enough to set a model on. */
    assert_int_equal(tirenv_road_window_fill(w, -INFINITY, -INFINITY, &d), TIRENV_OK);
    assert_int_equal(src.k, 1);
    assert_true(tirenv_road_window_covers(w, -3.2));
    assert_false(tirenv_road_window_covers(w, row_x(0)));
    const double x_keep = 1.234, x_need = 4.567;
    assert_int_equal(tirenv_road_window_fill(w, x_keep, x_need, &d), TIRENV_OK);
    assert_true(tirenv_road_window_covers(w, x_need));
    assert_int_equal(tirenv_road_window_profiles(w, p, &d), TIRENV_OK);
    const size_t k_last = (size_t)ceil((x_need + 3.1) / 0.137);  /* first row beyond x_need */
    assert_true(row_x(k_last) > x_need && row_x(k_last - 1) <= x_need);
    assert_int_equal(src.k, k_last + 1);  /* read no further */
    for (size_t t = 0; t < 2; ++t) {
        const size_t n = tirenv_profile_size(p[t]);
        const double *x = tirenv_profile_x(p[t]), *z = tirenv_profile_z(p[t]);
        /* It starts at or before the last row before x_keep (rows behind x_keep go when
         * the arrays fill, so some may stay), and holds every row from there. */
        const size_t k_keep = (size_t)ceil((x_keep + 3.1) / 0.137) - 1;
        assert_true(row_x(k_keep) < x_keep && row_x(k_keep + 1) >= x_keep);
        assert_true(x[0] <= row_x(k_keep));
        const size_t i0 = k_last + 1 - n;  /* the source's index of x[0] */
        for (size_t i = 0; i < n; ++i)
            assert_true(x[i] == row_x(i0 + i));
        assert_true(x[n - 1] == row_x(k_last));
        const double z_want = t == 0 ? 0.013 * sin(1.7 * x[n - 1]) : -0.0071 * cos(4.1 * x[n - 1]);
        assert_true(z[n - 1] == z_want);
        tirenv_profile_free(p[t]);
    }
    /* To the end: covers everything after, and the source is asked once past its last row. */
    assert_int_equal(tirenv_road_window_fill(w, 5.0, 1e9, &d), TIRENV_OK);
    assert_true(tirenv_road_window_covers(w, 2e9));
    assert_int_equal(src.calls, src.n + 1);
    tirenv_road_window_free(w);
    tirenv_road_window_free(NULL);
    assert_null(tirenv_road_window_alloc(rows_next, &src, 0));
}

/* A far x_keep costs no memory: the rows behind it are dropped as they are read, so the
 * window after reading 20,000 rows holds a few hundred at most. */
static void test_far_jump_drops_as_it_reads(void **state)
{
    (void)state;
    rows src = {.n = 20000};
    tirenv_road_window *w = tirenv_road_window_alloc(rows_next, &src, 2);
    assert_non_null(w);
    tirenv_diag d;
    const double x_keep = row_x(19000) + 0.05;
    assert_int_equal(tirenv_road_window_fill(w, x_keep, x_keep + 1.0, &d), TIRENV_OK);
    assert_true(src.k > 19000);
    tirenv_profile *p[2] = {NULL, NULL};
    assert_int_equal(tirenv_road_window_profiles(w, p, &d), TIRENV_OK);
    assert_true(tirenv_profile_size(p[0]) < 600);
    assert_true(tirenv_profile_x(p[0])[0] < x_keep);
    tirenv_profile_free(p[0]);
    tirenv_profile_free(p[1]);
    tirenv_road_window_free(w);
}

/* A stretch that starts behind the last one (or at no number) is refused: the rows behind it
 * were dropped and are not read again, so the window would flat-extend its first row over
 * ground it no longer holds (a fill at 1.0 m after one at 5.0 m said it covered, with
 * profiles from 4.98 m on). The window is left as it was. */
static void test_stretch_going_back(void **state)
{
    (void)state;
    rows src = {.n = 97};
    tirenv_road_window *w = tirenv_road_window_alloc(rows_next, &src, 2);
    assert_non_null(w);
    tirenv_diag d;
    assert_int_equal(tirenv_road_window_fill(w, 5.0, 6.0, &d), TIRENV_OK);
    const size_t read = src.k;
    assert_int_equal(tirenv_road_window_fill(w, 1.0, 6.0, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "x_keep");
    assert_int_equal(tirenv_road_window_fill(w, NAN, 6.0, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_road_window_fill(w, 5.0, NAN, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "x_need");
    assert_int_equal(src.k, read);
    assert_int_equal(tirenv_road_window_fill(w, 5.0, 6.0, &d), TIRENV_OK);  /* again: fine */
    assert_int_equal(tirenv_road_window_fill(w, 5.5, 9.0, &d), TIRENV_OK);
    tirenv_profile *p[2] = {NULL, NULL};
    assert_int_equal(tirenv_road_window_profiles(w, p, &d), TIRENV_OK);
    assert_true(tirenv_profile_x(p[0])[0] < 5.5 && tirenv_profile_x(p[0])[0] > 5.0);
    tirenv_profile_free(p[0]);
    tirenv_profile_free(p[1]);
    tirenv_road_window_free(w);
}

/* Rows out of a profile's order, or not finite, stop a fill with TIRENV_EINVAL, the row's
 * 1-based index in diag's line, the field at fault and the serial stream's message. */
/* NULL for the window or the profiles: refused, not dereferenced (diag NULL too). */
static void test_null_arguments(void **state)
{
    (void)state;
    tirenv_diag diag;
    tirenv_profile *p[1] = {NULL};
    assert_int_equal(tirenv_road_window_fill(NULL, 0, 1, &diag), TIRENV_EINVAL);
    assert_int_equal(tirenv_road_window_fill(NULL, 0, 1, NULL), TIRENV_EINVAL);
    assert_int_equal(tirenv_road_window_covers(NULL, 0), 0);
    assert_int_equal(tirenv_road_window_profiles(NULL, p, NULL), TIRENV_EINVAL);
    assert_null(p[0]);
    assert_null(tirenv_road_window_alloc(NULL, NULL, 1));
    tirenv_road_window_free(NULL);
}

static void test_bad_rows(void **state)
{
    (void)state;
    static const struct {
        double x[5], z[5];
        size_t bad;
        const char *field, *message;
    } cases[] = {
        {{-1.0, -0.2, 0.3, 0.25, 2.0}, {0, 0, 0.01, 0, 0}, 4, "x",
         "vertex 4 of the source goes back: x 0.25 m after 0.3 m"},
        {{-1.0, 0.1, 0.1, 0.1, 2.0}, {0, 0, 0.02, 0.01, 0}, 4, "x",
         "vertex 4 of the source is the third at x = 0.1 m (a wall has two)"},
        {{-1.0, 0.1, 0.2, 0.3, 2.0}, {0, 0, NAN, 0, 0}, 3, "z",
         "vertex 3 of the source is not finite (x 0.2 m, z nan m on one of its tracks)"},
        {{-1.0, 0.1, INFINITY, 0.3, 2.0}, {0, 0, 0, 0, 0}, 3, "x",
         "vertex 3 of the source is not finite (x inf m, z 0 m on one of its tracks)"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        rows src = {.n = 5, .x = cases[i].x, .z0 = cases[i].z};
        tirenv_road_window *w = tirenv_road_window_alloc(rows_next, &src, 2);
        assert_non_null(w);
        tirenv_diag d;
        tirenv_diag_clear(&d);
        assert_int_equal(tirenv_road_window_fill(w, -INFINITY, 10.0, &d), TIRENV_EINVAL);
        assert_int_equal(d.line, cases[i].bad);
        assert_string_equal(d.field, cases[i].field);
        assert_string_equal(d.message, cases[i].message);
        tirenv_road_window_free(w);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fill_holds_the_stretch),
        cmocka_unit_test(test_far_jump_drops_as_it_reads),
        cmocka_unit_test(test_bad_rows),
        cmocka_unit_test(test_stretch_going_back),
        cmocka_unit_test(test_null_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
