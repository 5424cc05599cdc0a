/* SPDX-License-Identifier: Apache-2.0 */
/* A forward speed as people write it (tirenv_ride_speed_parse): what 'tirenv ride --speed'
 * and the Python module's ride(speed="10km/h") both take. */
#include <errno.h>
#include <locale.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/ride.h"

/* The number is strtod's whole text, finite; km/h is converted by multiplying by 1/3.6, as
 * the CLI always has (not dividing by 3.6: the last bit can differ). */
int tirenv_ride_speed_parse(const char *text, double *v, tirenv_diag *diag)
{
    char buf[64];
    const size_t n = text ? strlen(text) : 0;
    double scale = 1;
    if (n == 0 || n >= sizeof buf)
        goto bad;
    memcpy(buf, text, n + 1);
    if (n > 4 && strcmp(buf + n - 4, "km/h") == 0) {
        buf[n - 4] = '\0';
        scale = 1 / 3.6;
    } else if (n > 3 && strcmp(buf + n - 3, "m/s") == 0) {
        buf[n - 3] = '\0';
    }
    /* '.' whatever the host's LC_NUMERIC (a comma locale read "2.5" as 2 and refused the
     * rest): strtod in the "C" locale, made for the call (a rare one; the auxiliary layer's
     * readers keep one, io/c_numeric.c, which the core cannot call). */
    const locale_t c = newlocale(LC_NUMERIC_MASK, "C", (locale_t)0);
    const locale_t before = c ? uselocale(c) : (locale_t)0;
    char *end;
    errno = 0;
    const double d = strtod(buf, &end);
    const int range = errno == ERANGE;
    if (c) {
        uselocale(before);
        freelocale(c);
    }
    if (end == buf || *end != '\0' || range || !isfinite(d) || !(d > 0))
        goto bad;
    *v = d * scale;
    return TIRENV_OK;
bad:
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, "speed",
                        "expected a speed > 0 in m/s or with the suffix km/h, got '%s'",
                        text ? text : "");
}
