/* Decimal formatting for CSV output: the bytes of printf("%.*g"), about ten times faster.
 *
 * glibc's printf converts a double exactly with multiple-precision arithmetic, which is right
 * and slow (about 0.2 us a number); our CSV writers spend most of their time there. Here the
 * value is scaled to an integer of `precision` digits with one 64 x 64 -> 128-bit product:
 *
 *   x = m * 2^e (m in [2^63, 2^64) after normalising),  10^k = (P + d) * 2^q, 0 <= d < 1,
 *   P in [2^63, 2^64) from a table truncated downward (scripts/gen_pow10.py), so
 *   A = m * P * 2^(e + q) <= x * 10^k < A * (1 + 2^-63).
 *
 * With k chosen so that x * 10^k lies in [10^(p-1), 10^p), the exact value exceeds A by less
 * than 10^p * 2^-63, a tiny fraction of a unit of the last digit (2^-33 of it for p = 9). The
 * integer part of A and its fraction then decide the rounding, except when the fraction lies
 * within that bound below one half: the exact value may then be a tie or on either side of
 * it, and snprintf decides (glibc rounds ties to even). Random doubles reach that case about
 * once in 10^9 for p = 9; tests/io/test_fmt.c checks the bytes against snprintf.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/numtext.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "io/fmt.h"
#include "io/io.h"
#include "io/fmt_pow10.h"

__extension__ typedef unsigned __int128 fmt_u128;

static const uint64_t pow10_u64[] = {
    1u, 10u, 100u, 1000u, 10000u, 100000u, 1000000u, 10000000u, 100000000u, 1000000000u,
    10000000000u, 100000000000u, 1000000000000u, 10000000000000u, 100000000000000u,
    1000000000000000u, 10000000000000000u, 100000000000000000u, 1000000000000000000u,
};

/* ceil(p * log2(10)) - 63 for p = 0..17: the exact value exceeds A (above) by less than
 * 2^tol_exp[p] when A < 10^p. */
static const int tol_exp[] = {-63, -59, -56, -53, -49, -46, -43, -39, -36,
                              -33, -29, -26, -23, -19, -16, -13, -9,  -6};

static const char digit_pairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/* floor(v / 2^40) for any sign, without relying on the shift of a negative number. */
static int64_t floor_shift40(int64_t v)
{
    return v >= 0 ? v >> 40 : -((-v + ((int64_t)1 << 40) - 1) >> 40);
}

/* A lower bound of floor(log10(x)), at most one below it (x = m * 2^e, m in [2^63, 2^64)):
 * log2(1 + f) >= f on [0, 1] gives a lower bound of log2(x) in 20 fractional bits, and the
 * factor log10(2) is rounded down for positive and up for negative logarithms. */
static int decimal_exponent_estimate(uint64_t m, int e)
{
    const int64_t l2 = (int64_t)(e + 63) * (1 << 20) + (int64_t)((m >> 43) - (1u << 20));
    /* 315652 / 2^20 < log10(2) < 315653 / 2^20 */
    return (int)floor_shift40(l2 * (l2 >= 0 ? 315652 : 315653));
}

/* The p digits of n (10^(p-1) <= n < 10^p) into d[0..p-1], two at a time. Nine digits (the
 * CSV writers' precision) in groups by constant divisors, which compile to multiplications;
 * other precisions in a loop, in 32-bit arithmetic once n fits. */
static void digits(uint64_t n, int p, char *d)
{
    if (p == 9) {
        const uint32_t v = (uint32_t)n, lead = v / 100000000u, r = v - lead * 100000000u;
        const uint32_t hi = r / 10000u, lo = r - hi * 10000u;
        d[0] = (char)('0' + lead);
        memcpy(d + 1, digit_pairs + 2 * (hi / 100u), 2);
        memcpy(d + 3, digit_pairs + 2 * (hi % 100u), 2);
        memcpy(d + 5, digit_pairs + 2 * (lo / 100u), 2);
        memcpy(d + 7, digit_pairs + 2 * (lo % 100u), 2);
        return;
    }
    int i = p;
    while (n > UINT32_MAX) {
        const unsigned r = (unsigned)(n % 100);
        n /= 100;
        i -= 2;
        memcpy(d + i, digit_pairs + 2 * r, 2);
    }
    uint32_t v = (uint32_t)n;
    while (i >= 2) {
        const uint32_t r = v % 100;
        v /= 100;
        i -= 2;
        memcpy(d + i, digit_pairs + 2 * r, 2);
    }
    if (i == 1)
        d[0] = (char)('0' + v);
}

/* %g's layout of n * 10^(X - p + 1) (n with exactly p digits): exponential when X < -4 or
 * X >= p, else fixed; trailing zeros and a bare point removed. Composed in a scratch buffer
 * with copies of a fixed length (inlined, unlike copies of a variable length), then copied
 * whole: buf has TIRENV_FMT_G_SIZE bytes. */
static size_t layout(int neg, uint64_t n, int X, int p, char *buf)
{
    char d[40] = {0}, w[64];  /* d: room for a 17-byte copy from any digit */
    digits(n, p, d);
    int nd = p;
    while (nd > 1 && d[nd - 1] == '0')
        --nd;
    char *o = w;
    *o = '-';
    o += neg;
    if (X < -4 || X >= p) {
        o[0] = d[0];
        o[1] = '.';
        memcpy(o + 2, d + 1, 16);
        o += nd > 1 ? nd + 1 : 1;
        *o++ = 'e';
        *o++ = X < 0 ? '-' : '+';
        unsigned a = (unsigned)(X < 0 ? -X : X);
        if (a >= 100) {
            *o++ = (char)('0' + a / 100);
            a %= 100;
        }
        memcpy(o, digit_pairs + 2 * a, 2);
        o += 2;
    } else if (X >= 0) {
        memcpy(o, d, 17);
        o += X + 1;
        if (nd > X + 1) {
            *o = '.';
            memcpy(o + 1, d + X + 1, 17);
            o += nd - X;
        }
    } else {
        memcpy(o, "0.0000", 7);
        o += 1 - X;
        memcpy(o, d, 17);
        o += nd;
    }
    *o = '\0';
    memcpy(buf, w, TIRENV_FMT_G_SIZE);
    return (size_t)(o - w);
}

/* The fast path: 1 with buf written, 0 when the bound cannot decide (the caller falls back). */
static int fmt_fast(double x, int p, char *buf, size_t *len)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    const int neg = (int)(bits >> 63);
    const int be = (int)((bits >> 52) & 0x7ff);
    uint64_t m = bits & (((uint64_t)1 << 52) - 1);
    int e;
    if (be == 0) {
        e = -1074;  /* subnormal; m != 0 since x != 0 */
    } else {
        m |= (uint64_t)1 << 52;
        e = be - 1075;
    }
    const int lz = __builtin_clzll(m);
    m <<= lz;
    e -= lz;

    int X = decimal_exponent_estimate(m, e);
    uint64_t n = 0;
    for (int tries = 0;; ++tries) {
        const int k = p - 1 - X;
        if (tries > 1 || k < FMT_POW10_MIN || k > FMT_POW10_MAX)
            return 0;
        const fmt_u128 prod = (fmt_u128)m * fmt_pow10[k - FMT_POW10_MIN].P;
        /* A = prod / 2^s with prod in [2^126, 2^128) and 1 <= A < 10^18: 64 < s < 128, so
         * A's integer part is in the high word and the rest can be done in 64 bits. */
        const int s = -(e + fmt_pow10[k - FMT_POW10_MIN].q);
        if (s <= 64 || s >= 128)
            return 0;
        const uint64_t hi = (uint64_t)(prod >> 64), lo = (uint64_t)prod;
        const int t = s - 64;
        const uint64_t n0 = hi >> t;
        if (n0 >= pow10_u64[p]) {  /* the exact value is at least as large: one decade up */
            ++X;
            continue;
        }
        if (n0 < pow10_u64[p - 1]) {  /* cannot happen with a lower-bound estimate */
            --X;
            continue;
        }
        /* The fraction of A in units of 2^-64: f, plus less than one unit from the bits
         * below, plus less than 2^u from the bound on A's error (u = 64 + tol_exp[p]). */
        const uint64_t f = (hi << (64 - t)) | (lo >> t);
        const uint64_t half = (uint64_t)1 << 63;
        const int u = 64 + tol_exp[p];
        const uint64_t tol = (u > 0 ? (uint64_t)1 << u : 1) + 1;
        if (f > half)               /* exact fraction > f >= 1/2 + 2^-64 */
            n = n0 + 1;
        else if (f <= half - tol)   /* exact fraction < f + tol <= 1/2 */
            n = n0;
        else
            return 0;
        break;
    }
    if (n == pow10_u64[p]) {  /* 9.999999996 -> 10.0000000 */
        n = pow10_u64[p - 1];
        ++X;
    }
    *len = layout(neg, n, X, p, buf);
    return 1;
}

size_t tirenv_fmt_g(double x, int precision, char *buf)
{
    if (precision < 1 || precision > 17) {
        buf[0] = '\0';
        return 0;
    }
    if (x == 0) {
        memcpy(buf, signbit(x) ? "-0" : "0", signbit(x) ? 3 : 2);
        return signbit(x) ? 2 : 1;
    }
    size_t len;
    if (isfinite(x) && fmt_fast(x, precision, buf, &len))
        return len;
    TIRENV_NUMERIC_C(); /* '.' as the fast path writes it, whatever the host's locale */
    const int n = snprintf(buf, TIRENV_FMT_G_SIZE, "%.*g", precision, x);
    return n > 0 ? (size_t)n : 0;
}

/* The same, and 0 instead of the snprintf fallback: for tests/io/test_fmt.c, which checks that
 * the fast path does the work. */
int tirenv_fmt__g_fast(double x, int precision, char *buf)
{
    size_t len;
    return precision >= 1 && precision <= 17 && isfinite(x) && x != 0 &&
           fmt_fast(x, precision, buf, &len);
}
