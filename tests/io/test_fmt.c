/* The CSV number formatter against glibc's printf, byte for byte: random bit patterns (every
 * exponent, subnormals, inf and nan), values in the ranges tirenv writes, exact ties, the
 * digit-count and fixed/exponential boundaries, at the precisions in use (9, 10) and the
 * ends (1, 17). And the fast path must be what answers: a formatter that always called
 * snprintf would match byte for byte and gain nothing. SPDX-License-Identifier:
 * Apache-2.0 */
#include "testutil.h"
#include "tirenv/numtext.h"
#include "io/fmt.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* xorshift64*: fixed seeds, the same sequence everywhere. */
static uint64_t rng_next(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * 0x2545f4914f6cdd1dULL;
}

static double rng_uniform(uint64_t *s)  /* [0, 1) */
{
    return (double)(rng_next(s) >> 11) * 0x1.0p-53;
}

static double from_bits(uint64_t b)
{
    double x;
    memcpy(&x, &b, sizeof x);
    return x;
}

typedef struct {
    size_t checked, slow;  /* values compared; of them, answered by the snprintf fallback */
} tally;

/* Fails with both strings on the first difference. */
static void same_as_printf(double x, int p, tally *t)
{
    char want[64], got[TIRENV_FMT_G_SIZE + 8], fast[TIRENV_FMT_G_SIZE];
    memset(got, 'Z', sizeof got);
    const int n = snprintf(want, sizeof want, "%.*g", p, x);
    const size_t len = tirenv_fmt_g(x, p, got);
    if (len != (size_t)n || strcmp(got, want) != 0 || got[len] != '\0') {
        print_error("%%.%dg of %a: printf '%s', tirenv_fmt_g '%.*s' (length %zu)\n", p, x,
                    want, (int)len, got, len);
        fail();
    }
    t->checked++;
    if (!tirenv_fmt__g_fast(x, p, fast))
        t->slow++;
    else if (strcmp(fast, want) != 0) {
        print_error("fast path %%.%dg of %a: '%s', printf '%s'\n", p, x, fast, want);
        fail();
    }
}

static const int precisions[] = {9, 10, 1, 6, 17};
enum { N_PRECISIONS = sizeof precisions / sizeof precisions[0] };

static void test_edge_cases(void **state)
{
    (void)state;
    const double edge[] = {
        0.0, -0.0, INFINITY, -INFINITY, NAN, -NAN, DBL_MIN, -DBL_MIN, DBL_MAX, -DBL_MAX,
        DBL_TRUE_MIN, -DBL_TRUE_MIN, 0x1.fffffffffffffp-1023 /* largest subnormal */,
        0x1p-1060, 1, -1, 0.1, 0.5, 1.5, 2.5, -2.5, 0.125, 0.375, 1e-5, 1e-4, 9.9999e-5,
        123456789, 1234567890, 999999999, 999999999.5, 999999998.5, 999999999.49999994,
        9999999995.0, 9999999985.0, 1234567885.0, 1234567895.0, 0.9999999995, 99999.99995,
        9.9999999995e-5, 9.99999999949e-5, 9.9999999996e-5, 1e9, 1e16, 1e17, 1e22, 1e23,
        1e-300, 1e300, 1e308, 5e-324, 4.9406564584124654e-324, 2.2250738585072009e-308,
        0.001, -0.7, 0.641988304, 13000, 17860.4, 0.68, 1e100, 9007199254740993.0,
        18446744073709551616.0, 0.30102999566398120, 4.35, 4.45, 8.5, 0.0005, 0.00015,
    };
    tally t = {0};
    for (size_t i = 0; i < sizeof edge / sizeof edge[0]; ++i)
        for (int p = 1; p <= 17; ++p) {
            same_as_printf(edge[i], p, &t);
            same_as_printf(nextafter(edge[i], INFINITY), p, &t);
            same_as_printf(nextafter(edge[i], -INFINITY), p, &t);
        }
}

/* Exact ties: integers of p + 1 significant digits ending in 5 (representable exactly up to
 * 2^53), and binary fractions whose decimal expansion stops at the tie digit. Printf rounds
 * them half to even; the fast path must hand every one of them to it. */
static void test_exact_ties(void **state)
{
    (void)state;
    uint64_t s = 0x7ee5;
    tally t = {0};
    for (int p = 1; p <= 15; ++p) {
        const double lo = pow(10, p), hi = pow(10, p + 1);
        for (int i = 0; i < 20000; ++i) {
            const double x = floor(lo / 10 + rng_uniform(&s) * (hi - lo) / 10) * 10 + 5;
            if (x >= 0x1p53)
                continue;
            same_as_printf(x, p, &t);
            same_as_printf(-x, p, &t);
        }
    }
    /* 0.5, 0.25, 0.125, ...: the last significant digit is 5. */
    for (int j = 1; j < 60; ++j)
        for (int p = 1; p <= 17; ++p)
            same_as_printf(ldexp(1, -j), p, &t), same_as_printf(3 * ldexp(1, -j), p, &t);
    assert_true(t.slow > 0);  /* ties are exactly what the fast path must not decide */
}

/* Values drawn by each of the two random tests below. The sanitizer build (GCC's
 * __SANITIZE_ADDRESS__) draws a tenth: the same code over fewer values (the sanitizers look
 * for memory errors; the Release build compares every one of the 2,000,000 with snprintf). */
#ifdef __SANITIZE_ADDRESS__
enum { N_DRAWN = 200000 };
#else
enum { N_DRAWN = 2000000 };
#endif

/* Random bit patterns: every exponent, subnormals and non-finite values included. */
static void test_random_bits(void **state)
{
    (void)state;
    uint64_t s = 0x5eed;
    tally t = {0};
    const size_t n = N_DRAWN;
    for (size_t i = 0; i < n; ++i) {
        const double x = from_bits(rng_next(&s));
        same_as_printf(x, precisions[i % N_PRECISIONS], &t);
    }
    /* The fast path answers all but a handful (the bound leaves undecided about one in 10^9
     * at 9 digits, one in 100 at 17; the 17-digit fifth of the values dominates). */
    print_message("random bits: %zu values, %zu through snprintf\n", t.checked, t.slow);
    assert_true(t.slow * 100 < t.checked);
}

/* What tirenv writes: positions on a 1 mm grid, heights of millimetres, forces of kN,
 * accelerations, slopes near 0, integers; mostly at 9 digits. */
static void test_output_ranges(void **state)
{
    (void)state;
    uint64_t s = 0xc5f;
    tally t = {0};
    const size_t n = N_DRAWN;
    for (size_t i = 0; i < n; ++i) {
        const double u = rng_uniform(&s);
        double x;
        switch (i % 8) {
        case 0: x = -0.7 + 0.001 * (double)(i / 8 % 1000000); break;  /* sweep positions */
        case 1: x = 0.1 * (u - 0.5); break;                           /* h, z of a road, m */
        case 2: x = 2e4 * u; break;                                   /* forces, N */
        case 3: x = (u - 0.5) * 1e-6; break;                          /* slopes near flat */
        case 4: x = ldexp(u, (int)(rng_next(&s) % 80) - 40); break;   /* every decade */
        case 5: x = floor(1e6 * u); break;                            /* counts */
        case 6: x = 0.001 * (double)(i / 8); break;                   /* time steps, s */
        default: x = 0.68 - 0.03 * u; break;                          /* z_flat, m */
        }
        same_as_printf(x, (i / 8) % 4 == 3 ? 10 : 9, &t);
    }
    print_message("output ranges: %zu values, %zu through snprintf\n", t.checked, t.slow);
    assert_true(t.slow * 10000 < t.checked);
}

/* Neighbours of the places where the digit count changes: x * 10^k at 999999999.5 and its
 * neighbours for every decade, where rounding carries into a new digit. */
static void test_digit_boundaries(void **state)
{
    (void)state;
    tally t = {0};
    for (int p = 1; p <= 17; ++p)
        for (int k = -320; k <= 300; ++k) {
            const double b = (pow(10, p) - 0.5) * pow(10, k - p + 1);
            double x = b;
            for (int j = 0; j < 3; ++j)
                x = nextafter(x, 0);
            for (int j = 0; j < 7; ++j) {
                same_as_printf(x, p, &t);
                x = nextafter(x, INFINITY);
            }
            same_as_printf(pow(10, k), p, &t);
        }
}

static void test_bad_precision(void **state)
{
    (void)state;
    char buf[TIRENV_FMT_G_SIZE] = "x";
    assert_int_equal(tirenv_fmt_g(1.5, 0, buf), 0);
    assert_string_equal(buf, "");
    assert_int_equal(tirenv_fmt_g(1.5, 18, buf), 0);
}

/* tirenv_fmt_shortest, the writers' numbers: x reads back bit for bit (-0 too), the text is
 * no longer than "%.17g", and it is the shortest "%.*g" that reads back, or plain decimals at
 * most 4 characters longer (-10000 for -1e+04), never plain decimals that an exponent would
 * beat by more. The answer "%.*g" is checked against is found here by trying every precision
 * from 1 up. */
static int shortest_ok(double x)  /* 1: written plain where "%.*g" has an exponent */
{
    char buf[TIRENV_FMT_G_SIZE + 8], want[64], g17[64];
    memset(buf, 'Z', sizeof buf);
    const size_t len = tirenv_fmt_shortest(x, buf);
    const double back = strtod(buf, NULL);
    int p = 1;
    while (p < 17 && (snprintf(want, sizeof want, "%.*g", p, x), strtod(want, NULL) != x))
        ++p;
    snprintf(want, sizeof want, "%.*g", p, x);
    snprintf(g17, sizeof g17, "%.17g", x);
    if (len != strlen(buf) || len >= TIRENV_FMT_G_SIZE || memcmp(&back, &x, sizeof x) != 0 ||
        len > strlen(g17) || len > strlen(want) + 4 ||
        (strcmp(buf, want) != 0 && (strchr(buf, 'e') || !strchr(want, 'e')))) {
        print_error("%a: tirenv_fmt_shortest '%s' (length %zu), shortest %%.*g '%s', %%.17g "
                    "'%s'\n", x, buf, len, want, g17);
        fail();
    }
    return strcmp(buf, want) != 0;
}

static void test_shortest(void **state)
{
    (void)state;
    const double edge[] = {
        0.0, -0.0, 0.1, -0.1, 1e300, -1e300, 1e-300, DBL_MAX, -DBL_MAX, DBL_MIN, -DBL_MIN,
        DBL_TRUE_MIN, -DBL_TRUE_MIN, 0x1.fffffffffffffp-1023, 0x1.234p-1060, 1, -10000, 1e5,
        123000, 1e-4, 9.9999999999999991e-5, 1e15, 999999999999999.9, 1e16, 0.68, 2.385,
        1.0 / 3, 9007199254740993.0, 5e-324, 17860.4, -0.7, 6.02e23, 1e-7, 1e22, 1e23,
    };
    for (size_t i = 0; i < sizeof edge / sizeof edge[0]; ++i)
        (void)shortest_ok(edge[i]);
    char buf[TIRENV_FMT_G_SIZE];
    const struct { double x; const char *text; } known[] = {
        {0.0, "0"}, {-0.0, "-0"}, {0.1, "0.1"}, {1e300, "1e+300"}, {-10000, "-10000"},
        {1e-7, "1e-07"}, {250.2, "250.2"}, {DBL_TRUE_MIN, "5e-324"},
        {INFINITY, "inf"}, {-INFINITY, "-inf"},
    };
    for (size_t i = 0; i < sizeof known / sizeof known[0]; ++i) {
        tirenv_fmt_shortest(known[i].x, buf);
        assert_string_equal(buf, known[i].text);
    }
    tirenv_fmt_shortest(NAN, buf);
    assert_true(isnan(strtod(buf, NULL)));
    /* High-entropy values: random bits (every exponent), subnormals alone, and every decade
     * tirenv writes at full precision. */
    uint64_t s = 0x5407;
    size_t plain = 0;
    for (size_t i = 0; i < 90000; ++i) {
        const uint64_t b = rng_next(&s);
        double x;
        switch (i % 3) {
        case 0: x = from_bits(b); break;
        case 1: x = from_bits(b & 0x800fffffffffffffULL); break;  /* subnormal (or +-0) */
        default: x = ldexp(rng_uniform(&s) - 0.5, (int)(b % 80) - 40); break;
        }
        if (isfinite(x))
            plain += (size_t)shortest_ok(x);
    }
    print_message("shortest: %zu values written plain instead of with an exponent\n", plain);
    assert_true(plain >= 20);  /* the plain branch is exercised */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_edge_cases),       cmocka_unit_test(test_exact_ties),
        cmocka_unit_test(test_random_bits),      cmocka_unit_test(test_output_ranges),
        cmocka_unit_test(test_digit_boundaries), cmocka_unit_test(test_bad_precision),
        cmocka_unit_test(test_shortest),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
