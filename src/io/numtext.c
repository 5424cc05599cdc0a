/* Numbers as the shortest text that reads back to the same double, for files whose round
 * trip (read, convert, write, read) must give the same heights.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/numtext.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/io.h"

/* Reading back is monotonic in the precision (more correctly rounded digits stay within half
 * an ulp), so the shortest one is found by bisection: 4 or 5 tries instead of up to 17. */
size_t tirenv_fmt_shortest(double v, char *buf)
{
    TIRENV_NUMERIC_C();
    int lo = 1, hi = 17;
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        tirenv_fmt_g(v, mid, buf); /* the bytes of "%.*g", without printf's cost */
        if (strtod(buf, NULL) == v)
            hi = mid;
        else
            lo = mid + 1;
    }
    const size_t len = tirenv_fmt_g(v, lo, buf);
    /* "%g" writes -10000 as -1e+04: plain decimals read better wherever they are no longer.
     * Tried up to 1e17, where "%.17g" is plain itself: below it an exponent can make the
     * shortest "%.*g" longer ("-4.78003600647523e+15" for -4780036006475230). */
    if (!strchr(buf, 'e') || !(fabs(v) >= 1e-4 && fabs(v) < 1e17))
        return len;
    char plain[64];
    for (int d = 0; d <= 20; d++) {
        const int n = snprintf(plain, sizeof plain, "%.*f", d, v);
        if (strtod(plain, NULL) == v) {
            if (n < TIRENV_FMT_G_SIZE && (size_t)n <= len + 4) {
                memcpy(buf, plain, (size_t)n + 1);
                return (size_t)n;
            }
            return len;
        }
    }
    return len;
}
