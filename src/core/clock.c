/* The library's one clock. SPDX-License-Identifier: Apache-2.0 */
#include "core/clock.h"

#include <time.h>

double tirenv_core__wall_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}
