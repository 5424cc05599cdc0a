/* Streamed sweeps from a vertex source that is not a file (tirenv_vertex_source): the core
 * takes its ground through a callback, so a generator in memory streams as the CSV reader
 * does, and a source handing vertices out of order is stopped with the vertex named.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/tirenv.h"

#include <math.h>
#include <stdlib.h>

/* A source over arrays in memory: vertex k of n, then the end. */
typedef struct {
    const double *x, *z;
    size_t n, k;
    size_t calls;
} array_source;

static int array_next(void *ctx, double *x, double *z, int *got, tirenv_diag *diag)
{
    (void)diag;
    array_source *s = ctx;
    ++s->calls;
    *got = s->k < s->n;
    if (*got) {
        *x = s->x[s->k];
        *z = s->z[s->k];
        ++s->k;
    }
    return TIRENV_OK;
}

typedef tirenv_test_points collect;  /* the sink of the streamed points */

/* A bumpy stretch of 8 m every 7 mm: sums of sines, nothing level for long. */
enum { N_ROAD = 1143 };
static void bumpy(double x[], double z[])
{
    for (size_t k = 0; k < N_ROAD; ++k) {
        x[k] = 0.007 * (double)k;
        z[k] = 0.011 * sin(2.3 * x[k]) + 0.0047 * sin(11.9 * x[k] + 0.4);
    }
}

/* The springs model streamed from the n vertices x, z at the positions x_from:dx:x_to and the
 * load (N) against the whole profile's evaluations: the number of positions whose h, fx or
 * iterations differ (reported), and in *raised those with |h| > 1 mm; with check_reads, that
 * the source was read once. The stream must have rebuilt its window more than once, or
 * nothing was tested. */
static size_t stream_against_whole(const double x[], const double z[], size_t n, double x_from,
                                   double x_to, double dx, double load, int check_reads,
                                   size_t *raised)
{
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &tire);
    tirenv_profile *whole = tirenv_profile_alloc(n, x, z);
    assert_non_null(m);
    assert_non_null(whole);
    array_source src = {x, z, n, 0, 0};
    collect c = {0};
    tirenv_stream_stats st;
    tirenv_diag d;
    assert_int_equal(tirenv_model_stream(m, array_next, &src, x_from, x_to, dx, load,
                                         tirenv_test_keep_point, &c, &st, &d),
                     TIRENV_OK);
    if (check_reads) {  /* asked only for what it had plus the one "end" answer */
        assert_int_equal(st.vertices_read, n);
        assert_int_equal(src.calls, n + 1);
    }
    assert_true(st.rebuilds > 1);
    assert_int_equal(c.n, tirenv_positions_count(x_from, x_to, dx));
    assert_int_equal(tirenv_model_set(m, whole, load, &d), TIRENV_OK);
    size_t differ = 0;
    *raised = 0;
    for (size_t k = 0; k < c.n; ++k) {
        tirenv_point w;
        assert_int_equal(tirenv_model_eval(m, c.pt[k].x, &w, &d), TIRENV_OK);
        differ += !(c.pt[k].h == w.h && c.pt[k].fx == w.fx &&
                    c.pt[k].iterations == w.iterations);
        *raised += fabs(w.h) > 1e-3;
    }
    if (differ)
        print_message("%zu of %zu positions differ from the whole profile's\n", differ, c.n);
    assert_true(c.n > 0);
    free(c.pt);
    tirenv_profile_free(whole);
    tirenv_model_free(m);
    return differ;
}

/* The springs model streamed from memory equals the whole profile bit for bit, iterations
 * included, and the source was asked only for what it had plus the one "end" answer. */
static void test_memory_source_equals_whole(void **state)
{
    (void)state;
    static double x[N_ROAD], z[N_ROAD];
    bumpy(x, z);
    size_t raised;
    assert_int_equal(stream_against_whole(x, z, N_ROAD, -0.4173, 8.2917, 0.0113, 11234.5, 1,
                                          &raised),
                     0);
    const size_t n = tirenv_positions_count(-0.4173, 8.2917, 0.0113);
    assert_true(raised > n / 4);  /* the comparison is over ground that matters */
}

/* A wall (two vertices at one x), then 14.7 m of level ground: over the whole profile the
 * deformable models' level shortcut (no solve where the ground within reach is level) is off
 * while the wall's second vertex is the last one behind the reach, as the wall's first
 * vertex is higher. A window rebuilt there began at that second vertex and took the shortcut
 * (no evaluation, fx 0, z in its last bit): 323 of the 4,054 positions differed from the
 * whole profile's; the window keeps the wall's first vertex too. */
static void test_wall_behind_level_ground(void **state)
{
    (void)state;
    static const double x[] = {-1.0, 1.37, 1.37, 13.91, 16.03, 16.3, 16.3, 17.5};
    static const double z[] = {0.0431, 0.0431, 0.0127, 0.0127, 0.0127, 0.0219, 0.0058, 0.0058};
    size_t raised;
    assert_int_equal(stream_against_whole(x, z, sizeof x / sizeof x[0], -0.5173, 17.4, 0.00442,
                                          6123.5, 0, &raised),
                     0);
}

/* Sources that break a profile's order are stopped with TIRENV_EINVAL, the vertex's 1-based
 * index in diag's line and the field at fault: x going back, a third vertex at one x, a
 * number that is not finite. */
static void test_bad_sources(void **state)
{
    (void)state;
    static const struct {
        double x[5], z[5];
        size_t bad;             /* 1-based index of the vertex at fault */
        const char *field;
    } cases[] = {
        {{-1.0, -0.2, 0.3, 0.25, 2.0}, {0, 0, 0.01, 0, 0}, 4, "x"},
        {{-1.0, 0.1, 0.1, 0.1, 2.0}, {0, 0, 0.02, 0.01, 0}, 4, "x"},
        {{-1.0, 0.1, 0.2, 0.3, 2.0}, {0, 0, NAN, 0, 0}, 3, "z"},
        {{-1.0, 0.1, INFINITY, 0.3, 2.0}, {0, 0, 0, 0, 0}, 3, "x"},
    };
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_rigid, &tire);
    assert_non_null(m);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        array_source src = {cases[i].x, cases[i].z, 5, 0, 0};
        collect c = {0};
        tirenv_diag d;
        tirenv_diag_clear(&d);
        assert_int_equal(tirenv_model_stream(m, array_next, &src, -1.5, 2.5, 0.01, 10000,
                                             tirenv_test_keep_point, &c, NULL, &d),
                         TIRENV_EINVAL);
        assert_int_equal(d.line, cases[i].bad);
        assert_string_equal(d.field, cases[i].field);
        assert_true(d.message[0] != '\0');
        free(c.pt);
    }
    tirenv_model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_memory_source_equals_whole),
        cmocka_unit_test(test_wall_behind_level_ground),
        cmocka_unit_test(test_bad_sources),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
