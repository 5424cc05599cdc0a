/* Numbers as the shortest text that reads back to the same double, for files whose round
 * trip (read, convert, write, read) must give the same heights.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "formats/numtext.h"

#include "tirenv/io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Reading back is monotonic in the precision (more correctly rounded digits stay within half
 * an ulp), so the shortest one is found by bisection: 4 or 5 tries instead of up to 17. */
void tirenv_numtext__shortest(char *buf, size_t n, double v)
{
    int lo = 1, hi = 17;
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        tirenv_fmt_g(v, mid, buf); /* the bytes of "%.*g", without printf's cost */
        if (strtod(buf, NULL) == v)
            hi = mid;
        else
            lo = mid + 1;
    }
    tirenv_fmt_g(v, lo, buf);
    /* "%g" writes -10000 as -1e+04: plain decimals read better wherever they are no longer. */
    if (!strchr(buf, 'e') || !(fabs(v) >= 1e-4 && fabs(v) < 1e15))
        return;
    char plain[64];
    for (int d = 0; d <= 20; d++) {
        snprintf(plain, sizeof plain, "%.*f", d, v);
        if (strtod(plain, NULL) == v) {
            if (strlen(plain) < n && strlen(plain) <= strlen(buf) + 4)
                snprintf(buf, n, "%s", plain);
            return;
        }
    }
}
