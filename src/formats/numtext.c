/* Numbers as the shortest text that reads back to the same double, for files whose round
 * trip (read, convert, write, read) must give the same heights.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "formats/numtext.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void tirenv_numtext__shortest(char *buf, size_t n, double v)
{
    int prec = 1;
    for (; prec < 17; prec++) {
        snprintf(buf, n, "%.*g", prec, v);
        if (strtod(buf, NULL) == v)
            break;
    }
    if (prec == 17)
        snprintf(buf, n, "%.17g", v);
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
