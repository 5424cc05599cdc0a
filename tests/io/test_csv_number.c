/* The CSV readers' number parser against strtod, bit for bit: what tirenv and spreadsheets
 * write (%.9g, %.17g, %.6f, fixed decimals), long digit strings, exponents beyond the fast
 * path, signed zeros, and text strtod refuses. SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "io/io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t rng_next(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * 0x2545f4914f6cdd1dULL;
}

/* strtod's verdict on the whole string against tirenv_csv__parse_double's. */
static void same_as_strtod(const char *s)
{
    char *end;
    const double want = strtod(s, &end);
    const int want_ok = end != s && *end == '\0';
    double got = 12345;
    const int ok = tirenv_csv__parse_double(s, &got) == 0;
    if (ok != want_ok || (ok && memcmp(&got, &want, sizeof got) != 0)) {
        print_error("'%s': strtod %s %a, parse %s %a\n", s, want_ok ? "accepts" : "refuses",
                    want, ok ? "accepts" : "refuses", got);
        fail();
    }
}

static void test_written_numbers(void **state)
{
    (void)state;
    uint64_t s = 0xdec;
    const char *const formats[] = {"%.9g", "%.17g", "%.6f", "%.3f", "%.10g", "%.15g", "%g"};
    char buf[64];
    for (size_t i = 0; i < 1000000; ++i) {
        double x;
        const uint64_t r = rng_next(&s);
        switch (i % 4) {
        case 0: x = (double)(r >> 11) * 0x1p-53 - 0.5; break;
        case 1: x = ldexp((double)(r >> 11) * 0x1p-53, (int)(r % 120) - 60); break;
        case 2: x = -0.7 + 0.001 * (double)(i / 4); break;
        default: memcpy(&x, &r, sizeof x); break;  /* any bit pattern, inf and nan too */
        }
        snprintf(buf, sizeof buf, formats[i % 7], x);
        same_as_strtod(buf);
    }
}

static void test_digit_strings(void **state)
{
    (void)state;
    uint64_t s = 0x5717;
    char buf[96];
    for (size_t i = 0; i < 300000; ++i) {
        const uint64_t r = rng_next(&s);
        const int n_int = (int)(r % 22), n_frac = (int)((r >> 8) % 22);
        size_t k = 0;
        if (r & (1u << 20))
            buf[k++] = (r & (1u << 21)) ? '-' : '+';
        for (int j = 0; j < n_int; ++j)
            buf[k++] = (char)('0' + rng_next(&s) % 10);
        if (r & (1u << 22))
            buf[k++] = '.';
        for (int j = 0; j < n_frac; ++j)
            buf[k++] = (char)('0' + rng_next(&s) % 10);
        if (r & (1u << 23))
            k += (size_t)sprintf(buf + k, "e%d", (int)((r >> 24) % 700) - 350);
        buf[k] = '\0';
        same_as_strtod(buf);
    }
}

static void test_edges(void **state)
{
    (void)state;
    const char *const cases[] = {
        "0", "-0", "+0", "0.0", "-0.0", "0e5", "-0e-5", ".5", "5.", "-.5", ".", "-", "+",
        "", "e5", "1e", "1e+", "1e-", "1.5e3x", "1,5", " 1", "1 ", "0x1p3", "inf", "-inf",
        "nan", "NaN", "infinity", "9007199254740992", "9007199254740993",
        "9007199254740993.0", "18446744073709551615", "99999999999999999999",
        "1e22", "1e23", "1e-22", "1e-23", "123456789e-30", "4.9406564584124654e-324",
        "2.2250738585072014e-308", "1.7976931348623157e308", "1e309", "1e-400",
        "0.000000000000000000000000001", "00000000000000000000000001.5", "1.79225626e-06",
        "-0.7", "13000", "0.641988304", "1E5", "1e+05", "1e0005", "1e99999999999",
        "0.1", "0.2", "0.3", "2.5", "-1e-5",
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i)
        same_as_strtod(cases[i]);
    double v;
    assert_int_equal(tirenv_csv__parse_double("-0", &v), 0);
    assert_true(v == 0 && signbit(v));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_written_numbers),
        cmocka_unit_test(test_digit_strings),
        cmocka_unit_test(test_edges),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
