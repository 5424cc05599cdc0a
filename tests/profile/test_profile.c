/* Profile object and generators (docs/models.md section 2).
 * SPDX-License-Identifier: Apache-2.0
 *
 * Tolerances. Heights here are O(0.1 m); an interpolation is three or four rounded
 * operations, so it is within a few ulp (about 1e-17 m) of the formula evaluated in the test.
 * TOL = 1e-15 m leaves a margin of ~50 ulp without hiding a wrong segment or a wrong end
 * (those are off by millimetres). Vertex copies and generator corners must be exact. */
#include "testutil.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "profile/profile_impl.h"
#include "tirenv/profile.h"

#define TOL 1e-15

/* --- validation ---------------------------------------------------------------------- */

typedef struct {
    const char *what;
    size_t n;
    double x[5], z[5];
    int null_x;
    size_t line;       /* expected diag line (1-based vertex, 0 = none) */
    const char *field; /* expected diag field */
} invalid_case;

static void test_validate_errors(void **state)
{
    (void)state;
    const invalid_case cases[] = {
        {"no vertices", 0, {0}, {0}, 0, 0, ""},
        {"NULL x", 2, {0}, {0}, 1, 0, "x"},
        {"NaN x", 3, {-0.2137, NAN, 0.3319}, {0, 0.0412, 0}, 0, 2, "x"},
        {"infinite z", 4, {-0.2137, 0.0173, 0.3319, 0.4}, {0, 0.0412, INFINITY, 0}, 0, 3, "z"},
        {"-inf x first", 2, {-INFINITY, 0.1}, {0, 0}, 0, 1, "x"},
        {"x decreasing", 4, {-0.2137, 0.0173, 0.0172, 0.4}, {0, 0.0412, 0.05, 0}, 0, 3, "x"},
        {"three at one x", 5, {-0.2, 0.1, 0.1, 0.1, 0.3}, {0, 0.05, 0.07, 0.02, 0}, 0, 4, "x"},
        {"decrease after wall", 4, {0.1, 0.1, 0.0993, 0.2}, {0, 0.05, 0.05, 0}, 0, 3, "x"},
        /* Where the models lose their precision (docs/models.md 2.1): a ring over this hump
         * gave h 41 mm for 50, the springs model's walk overflows near 1e308 m. */
        {"a segment of 1e8 m", 3, {-1e8, 0, 1e8}, {0, 0.05, 0}, 0, 2, "x"},
        {"just beyond 1e7 m", 2, {0, 1e7 + 1e-6}, {0, 0}, 0, 2, "x"},
        {"x at 2e9 m", 3, {1e9 - 1, 1e9, 2e9}, {0, 0, 0}, 0, 3, "x"},
        {"z at -1.5e9 m", 2, {0, 1}, {0, -1.5e9}, 0, 2, "z"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const invalid_case *c = &cases[i];
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        print_message("case: %s\n", c->what);
        const int status =
            tirenv_profile_validate(c->n, c->null_x ? NULL : c->x, c->z, &diag);
        assert_int_equal(status, TIRENV_EINVAL);
        assert_int_equal(diag.line, c->line);
        assert_string_equal(diag.field, c->field);
        assert_non_null(strstr(diag.message, "expected")); /* says what was expected */
        assert_null(tirenv_profile_alloc(c->n, c->null_x ? NULL : c->x, c->z));
        if (c->null_x || c->n == 0)
            continue;
        /* A reader checking one vertex at a time stops at the same vertex, in the same words. */
        tirenv_diag one;
        size_t k = 0;
        while (k < c->n && tirenv_profile_check_vertex(k, c->x[k], c->z[k], k ? c->x[k - 1] : 0,
                                                       k > 1 ? c->x[k - 2] : 0, &one) == TIRENV_OK)
            k++;
        assert_int_equal(k + 1, c->line);
        assert_int_equal(one.line, diag.line);
        assert_string_equal(one.field, diag.field);
        assert_string_equal(one.message, diag.message);
    }
    /* A NULL diag is allowed. */
    assert_int_equal(tirenv_profile_validate(0, NULL, NULL, NULL), TIRENV_EINVAL);
}

static void test_validate_ok(void **state)
{
    (void)state;
    const double x[] = {-0.3817, -0.3817, 0.1, 0.1, 0.2291, 0.2291};
    const double z[] = {0.0, 0.0417, 0.0417, 0.1188, 0.0903, -0.0261};
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_profile_validate(6, x, z, &diag), TIRENV_OK);
    assert_int_equal(tirenv_profile_validate(1, x, z, &diag), TIRENV_OK);
    /* At the limits themselves: a 1e7 m segment, and 1e9 m from the origin. */
    const double xl[] = {-1e9, -1e9 + 1e7, 1e9 - 1e7, 1e9 - 1e7, 1e9};
    const double zl[] = {1e9, 0, 0, -1e9, 0};
    assert_int_equal(tirenv_profile_validate(2, xl, zl, &diag), TIRENV_OK);
    assert_int_equal(tirenv_profile_validate(1, xl + 4, zl + 3, &diag), TIRENV_OK);
    assert_int_equal(tirenv_profile_validate(2, xl + 3, zl + 3, &diag), TIRENV_OK);
}

/* --- storage ------------------------------------------------------------------------- */

static void test_alloc_copies(void **state)
{
    (void)state;
    double x[] = {-0.1523, 0.0377, 0.2291};
    double z[] = {0.0, 0.0903, 0.0117};
    tirenv_profile *p = tirenv_profile_alloc(3, x, z);
    assert_non_null(p);
    x[1] = 99.0; /* the profile owns a copy */
    z[1] = 99.0;
    assert_int_equal(tirenv_profile_size(p), 3);
    assert_true(tirenv_profile_x(p)[1] == 0.0377);
    assert_true(tirenv_profile_z(p)[1] == 0.0903);
    double a = 0.0, b = 0.0;
    tirenv_profile_extent(p, &a, &b);
    assert_true(a == -0.1523 && b == 0.2291);
    tirenv_profile_extent(p, NULL, NULL);
    tirenv_profile_free(p);
    tirenv_profile_free(NULL);
}

/* --- heights ------------------------------------------------------------------------- */

/* Walls at the start, in the middle and at the end, so every special case of the search is
 * visited: x = -0.3817 (0 -> 0.0417), 0.1 (0.0417 -> 0.1188), 0.4107 (0.0903 -> -0.0261). */
static const double wx[] = {-0.3817, -0.3817, 0.1, 0.1, 0.2291, 0.4107, 0.4107};
static const double wz[] = {0.0, 0.0417, 0.0417, 0.1188, 0.0903, 0.0903, -0.0261};

static double lerp(double xa, double za, double xb, double zb, double x)
{
    return za + (zb - za) * ((x - xa) / (xb - xa));
}

static void test_height(void **state)
{
    (void)state;
    tirenv_profile *p = tirenv_profile_alloc(7, wx, wz);
    assert_non_null(p);
    assert_true(tirenv_profile_height(p, -7.3) == 0.0);         /* left extension */
    assert_true(tirenv_profile_height(p, -0.38170001) == 0.0);  /* just before the wall */
    assert_true(tirenv_profile_height(p, -0.3817) == 0.0417);   /* wall: the higher */
    assert_near(tirenv_profile_height(p, -0.1234), 0.0417, TOL, 0);
    assert_true(tirenv_profile_height(p, 0.1) == 0.1188);       /* wall */
    assert_near(tirenv_profile_height(p, 0.0999), 0.0417, TOL, 0);
    assert_near(tirenv_profile_height(p, 0.1731), lerp(0.1, 0.1188, 0.2291, 0.0903, 0.1731),
                TOL, 0);
    assert_true(tirenv_profile_height(p, 0.2291) == 0.0903);    /* vertex */
    assert_near(tirenv_profile_height(p, 0.3011), 0.0903, TOL, 0);
    assert_true(tirenv_profile_height(p, 0.4107) == 0.0903);    /* end wall: the higher */
    assert_true(tirenv_profile_height(p, 0.41070001) == -0.0261); /* right extension */
    assert_true(tirenv_profile_height(p, 5.9) == -0.0261);
    assert_true(tirenv_profile_height(p, INFINITY) == -0.0261);
    assert_true(tirenv_profile_height(p, -INFINITY) == 0.0);
    tirenv_profile_free(p);

    const double x1 = 0.2719, z1 = 0.0531; /* one vertex: flat everywhere */
    p = tirenv_profile_alloc(1, &x1, &z1);
    assert_non_null(p);
    assert_true(tirenv_profile_height(p, -1.0) == z1);
    assert_true(tirenv_profile_height(p, x1) == z1);
    assert_true(tirenv_profile_height(p, 3.0) == z1);
    tirenv_profile_free(p);
}

static void test_segment_at(void **state)
{
    (void)state;
    tirenv_profile *p = tirenv_profile_alloc(7, wx, wz);
    assert_non_null(p);
    assert_int_equal(tirenv_profile__segment_at(p, -9.0), 0);
    assert_int_equal(tirenv_profile__segment_at(p, -0.3817), 1); /* wall's second vertex */
    assert_int_equal(tirenv_profile__segment_at(p, 0.0), 1);
    assert_int_equal(tirenv_profile__segment_at(p, 0.1), 3);
    assert_int_equal(tirenv_profile__segment_at(p, 0.2291), 4);
    assert_int_equal(tirenv_profile__segment_at(p, 0.3), 4);
    assert_int_equal(tirenv_profile__segment_at(p, 0.4107), 6);
    assert_int_equal(tirenv_profile__segment_at(p, 9.0), 6);
    tirenv_profile_free(p);
}

static void test_max_height(void **state)
{
    (void)state;
    tirenv_profile *p = tirenv_profile_alloc(7, wx, wz);
    assert_non_null(p);
    /* Inside one segment: the higher end of the interval. */
    assert_near(tirenv_profile_max_height(p, 0.1731, 0.2013),
                lerp(0.1, 0.1188, 0.2291, 0.0903, 0.1731), TOL, 0);
    /* Covering a wall's top vertex. */
    assert_true(tirenv_profile_max_height(p, 0.05, 0.17) == 0.1188);
    /* The wall lies exactly at either end of the interval. */
    assert_true(tirenv_profile_max_height(p, 0.1, 0.17) == 0.1188);
    assert_true(tirenv_profile_max_height(p, -0.2, 0.1) == 0.1188);
    assert_true(tirenv_profile_max_height(p, -0.5, -0.3817) == 0.0417);
    /* Only extensions. */
    assert_true(tirenv_profile_max_height(p, -3.1, -0.4) == 0.0);
    assert_true(tirenv_profile_max_height(p, 0.5, 2.7) == -0.0261);
    /* Right extension plus the last wall. */
    assert_true(tirenv_profile_max_height(p, 0.3, 1.0) == 0.0903);
    /* Degenerate and whole-line intervals. */
    assert_near(tirenv_profile_max_height(p, 0.1731, 0.1731),
                tirenv_profile_height(p, 0.1731), 0, 0);
    assert_true(tirenv_profile_max_height(p, -INFINITY, INFINITY) == 0.1188);
    assert_true(isnan(tirenv_profile_max_height(p, 0.2, 0.1)));
    assert_true(isnan(tirenv_profile_max_height(p, NAN, 0.1)));
    tirenv_profile_free(p);
}

/* A rough profile of n vertices with walls (equal x) and plateaus (equal z), from a fixed
 * linear congruential sequence: the block index and the searches meet every layout. */
static double lcg_unit(unsigned long *seed)
{
    *seed = *seed * 6364136223846793005UL + 1442695040888963407UL;
    return (double)(*seed >> 11) * 0x1p-53;
}

static tirenv_profile *rough_profile(size_t n, unsigned long seed)
{
    double *x = malloc(n * sizeof *x), *z = malloc(n * sizeof *z);
    assert_non_null(x);
    assert_non_null(z);
    double xk = -1.2345, zk = 0.0;
    for (size_t k = 0; k < n; k++) {
        const double r = lcg_unit(&seed);
        /* a wall's second vertex (never a third equal x), a plateau, or a random step */
        if (k > 0 && r < 0.1 && !(k > 1 && x[k - 2] == x[k - 1]))
            ;
        else
            xk += 0.0073 + 0.01 * lcg_unit(&seed);
        if (r >= 0.1 && r < 0.3)
            ; /* same height */
        else
            zk += 0.031 * (lcg_unit(&seed) - 0.5);
        x[k] = xk;
        z[k] = zk;
    }
    tirenv_profile *p = tirenv_profile_alloc(n, x, z);
    free(x);
    free(z);
    assert_non_null(p);
    return p;
}

/* tirenv_profile_max_height as a plain scan of every vertex in the interval, without the
 * block maxima: the block index must give the same value bit for bit. */
static double max_height_plain(const tirenv_profile *p, double x_lo, double x_hi)
{
    double z_max = fmax(tirenv_profile_height(p, x_lo), tirenv_profile_height(p, x_hi));
    for (size_t k = 0; k < p->n; k++)
        if (p->x[k] >= x_lo && p->x[k] <= x_hi)
            z_max = fmax(z_max, p->z[k]);
    return z_max;
}

static void test_max_height_blocks(void **state)
{
    (void)state;
    unsigned long seed = 2385;
    const size_t sizes[] = {1, 2, 15, 16, 17, 33, 500};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        tirenv_profile *p = rough_profile(sizes[s], 7 + s);
        const double x0 = p->x[0], span = p->x[p->n - 1] - x0;
        for (int q = 0; q < 400; q++) {
            double a = x0 - 0.1 + (span + 0.2) * lcg_unit(&seed);
            double b = a + (span + 0.2) * lcg_unit(&seed) * (q % 3 == 0 ? 1.0 : 0.05);
            if (q % 5 == 1) /* ends exactly on vertices, walls included */
                a = p->x[(size_t)(lcg_unit(&seed) * (double)p->n)];
            if (q % 7 == 2)
                b = p->x[(size_t)(lcg_unit(&seed) * (double)p->n)];
            if (b < a)
                b = a;
            assert_true(tirenv_profile_max_height(p, a, b) == max_height_plain(p, a, b));
        }
        tirenv_profile_free(p);
    }
}

static void test_segment_near(void **state)
{
    (void)state;
    unsigned long seed = 4357;
    tirenv_profile *p = rough_profile(300, 11);
    const double x0 = p->x[0], span = p->x[p->n - 1] - x0;
    for (int q = 0; q < 3000; q++) {
        double x = x0 - 0.05 + (span + 0.1) * lcg_unit(&seed);
        if (q % 3 == 0) /* exactly on a vertex, walls included */
            x = p->x[(size_t)(lcg_unit(&seed) * (double)p->n)];
        const size_t hint = (size_t)(lcg_unit(&seed) * (double)p->n);
        assert_int_equal(tirenv_profile__segment_near(p, hint, x),
                         tirenv_profile__segment_at(p, x));
    }
    for (size_t hint = 0; hint < p->n; hint++) { /* every hint, off both ends */
        assert_int_equal(tirenv_profile__segment_near(p, hint, x0 - 1.0), 0);
        assert_int_equal(tirenv_profile__segment_near(p, hint, x0 + span + 1.0), p->n - 1);
    }
    tirenv_profile_free(p);
}

/* --- generators ---------------------------------------------------------------------- */

static void assert_vertices(tirenv_profile *p, size_t n, const double x[], const double z[])
{
    assert_non_null(p);
    assert_int_equal(tirenv_profile_size(p), n);
    for (size_t k = 0; k < n; k++) {
        assert_true(tirenv_profile_x(p)[k] == x[k]);
        assert_true(tirenv_profile_z(p)[k] == z[k]);
    }
    tirenv_profile_free(p);
}

static void test_generators_shapes(void **state)
{
    (void)state;
    const double L = 0.2931, H = 0.0743;
    assert_vertices(tirenv_profile_cleat(L, H), 4, (double[]){-L / 2, -L / 2, L / 2, L / 2},
                    (double[]){0, H, H, 0});
    assert_vertices(tirenv_profile_step(0.1379, 0.0562), 2, (double[]){0.1379, 0.1379},
                    (double[]){0, 0.0562});
    assert_vertices(tirenv_profile_step(-0.1379, -0.0562), 2, (double[]){-0.1379, -0.1379},
                    (double[]){0, -0.0562});
    const double T = 0.1187, B = 0.3413;
    assert_vertices(tirenv_profile_trapezoid(T, B, H), 4,
                    (double[]){-B / 2, -T / 2, T / 2, B / 2}, (double[]){0, H, H, 0});
    assert_vertices(tirenv_profile_trapezoid(T, T, H), 4,
                    (double[]){-T / 2, -T / 2, T / 2, T / 2}, (double[]){0, H, H, 0});
    assert_vertices(tirenv_profile_triangle(B, H), 3, (double[]){-B / 2, 0, B / 2},
                    (double[]){0, H, 0});
}

/* Inscribed: every vertex on the circle x^2 + z^2 = r^2 (to round-off: cos, sin,
 * the products and hypot each round once, so 8 ulp of r), the
 * ends exactly on the ground at +-r, equal angles between vertices, exact mirror symmetry. */
static void test_generator_half_cylinder(void **state)
{
    (void)state;
    const double r = 0.2173;
    const size_t segs[] = {2, 7, 8, 61};
    for (size_t i = 0; i < sizeof segs / sizeof segs[0]; i++) {
        const size_t n = segs[i];
        tirenv_profile *p = tirenv_profile_half_cylinder(r, n);
        assert_non_null(p);
        assert_int_equal(tirenv_profile_size(p), n + 1);
        const double *x = tirenv_profile_x(p), *z = tirenv_profile_z(p);
        assert_true(x[0] == -r && z[0] == 0.0 && x[n] == r && z[n] == 0.0);
        for (size_t k = 0; k <= n; k++) {
            assert_near(hypot(x[k], z[k]), r, 8 * DBL_EPSILON * r, 0);
            assert_near(atan2(z[k], -x[k]), M_PI * (double)k / (double)n, 1e-15, 0);
            assert_true(x[n - k] == -x[k] && z[n - k] == z[k]);
            if (k > 0)
                assert_true(x[k] > x[k - 1]);
        }
        if (n % 2 == 0)
            assert_true(x[n / 2] == 0.0 && z[n / 2] == r);
        tirenv_profile_free(p);
    }
}

static void test_generator_sine(void **state)
{
    (void)state;
    const double A = 0.0237, lambda = 0.4519, periods = 2.5;
    const size_t ppp = 17;
    tirenv_profile *p = tirenv_profile_sine(A, lambda, periods, ppp);
    assert_non_null(p);
    const size_t m = 43; /* ceil(2.5 * 17) segments */
    assert_int_equal(tirenv_profile_size(p), m + 1);
    const double *x = tirenv_profile_x(p), *z = tirenv_profile_z(p);
    assert_true(x[0] == 0.0 && z[0] == 0.0); /* continuous with the flat ground */
    assert_true(x[m] == periods * lambda);
    for (size_t k = 0; k <= m; k++) {
        const double xk = periods * lambda * (double)k / (double)m;
        assert_near(x[k], xk, TOL, 0);
        assert_near(z[k], A * (1.0 - cos(2.0 * M_PI * xk / lambda)), TOL, 0);
    }
    /* Half a period past 2 periods ends at the crest, 2A; the ground stays there. */
    assert_near(z[m], 2.0 * A, TOL, 0);
    assert_near(tirenv_profile_height(p, 5.0), 2.0 * A, TOL, 0);
    tirenv_profile_free(p);
}

static void test_generators_invalid(void **state)
{
    (void)state;
    assert_null(tirenv_profile_cleat(0.0, 0.05));
    assert_null(tirenv_profile_cleat(-0.3, 0.05));
    assert_null(tirenv_profile_cleat(0.3, 0.0));
    assert_null(tirenv_profile_cleat(0.3, -0.05));
    assert_null(tirenv_profile_cleat(NAN, 0.05));
    assert_null(tirenv_profile_cleat(0.3, INFINITY));
    assert_null(tirenv_profile_step(0.1, 0.0));
    assert_null(tirenv_profile_step(NAN, 0.05));
    assert_null(tirenv_profile_step(0.1, -INFINITY));
    assert_null(tirenv_profile_trapezoid(0.2, 0.1, 0.05)); /* base shorter than top */
    assert_null(tirenv_profile_trapezoid(0.0, 0.3, 0.05));
    assert_null(tirenv_profile_trapezoid(0.1, 0.3, 0.0));
    assert_null(tirenv_profile_trapezoid(0.1, NAN, 0.05));
    assert_null(tirenv_profile_triangle(0.0, 0.05));
    assert_null(tirenv_profile_triangle(0.3, -0.05));
    assert_null(tirenv_profile_triangle(INFINITY, 0.05));
    assert_null(tirenv_profile_half_cylinder(0.2, 1));
    assert_null(tirenv_profile_half_cylinder(0.2, 0));
    assert_null(tirenv_profile_half_cylinder(0.0, 8));
    assert_null(tirenv_profile_half_cylinder(NAN, 8));
    assert_null(tirenv_profile_sine(0.0, 0.4, 2.0, 16));
    assert_null(tirenv_profile_sine(-0.02, 0.4, 2.0, 16));
    assert_null(tirenv_profile_sine(0.02, 0.0, 2.0, 16));
    assert_null(tirenv_profile_sine(0.02, 0.4, 0.0, 16));
    assert_null(tirenv_profile_sine(0.02, 0.4, INFINITY, 16));
    assert_null(tirenv_profile_sine(0.02, 0.4, 2.0, 1));
    assert_null(tirenv_profile_sine(0.02, 0.4, 1e300, 16)); /* too many points */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_validate_errors),
        cmocka_unit_test(test_validate_ok),
        cmocka_unit_test(test_alloc_copies),
        cmocka_unit_test(test_height),
        cmocka_unit_test(test_segment_at),
        cmocka_unit_test(test_max_height),
        cmocka_unit_test(test_max_height_blocks),
        cmocka_unit_test(test_segment_near),
        cmocka_unit_test(test_generators_shapes),
        cmocka_unit_test(test_generator_half_cylinder),
        cmocka_unit_test(test_generator_sine),
        cmocka_unit_test(test_generators_invalid),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
