/* SPDX-License-Identifier: Apache-2.0 */
/* Numbers in tirenv's files are written and read with '.' for the decimal point, whatever
 * LC_NUMERIC the host set: a GUI toolkit (Qt, GTK) or Python's locale.setlocale sets the
 * user's, where it may be ',', and strtod then stopped at the '.' of "0.68" while printf wrote
 * "0,68". The public entries that read or write numbers as text run in the "C" locale on
 * their own thread for their duration (uselocale; docs/formats.md section 1). */
#include <locale.h>
#include <pthread.h>

#include "io/io.h"

static locale_t c_locale;
static pthread_once_t c_made = PTHREAD_ONCE_INIT;

static void make_c_locale(void)
{
    c_locale = newlocale(LC_ALL_MASK, "C", (locale_t)0);
}

locale_t tirenv_numeric__enter(void)
{
    pthread_once(&c_made, make_c_locale);
    /* Without one (out of memory at the first call) the host's locale stays: no worse than
     * before, and "C" unless the host changed it. */
    return c_locale ? uselocale(c_locale) : (locale_t)0;
}

void tirenv_numeric__leave(locale_t *before)
{
    if (*before)
        uselocale(*before);
}
