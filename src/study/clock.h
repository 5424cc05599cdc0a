/* Private to the study module: the wall clock of the timings its reports carry (fit time,
 * time per position). The auxiliary layer keeps its own: the core's clock is private to the
 * core. SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_STUDY_CLOCK_H
#define TIRENV_STUDY_CLOCK_H

#include <time.h>

/* Wall time since an arbitrary start (CLOCK_MONOTONIC), s. */
static inline double tirenv_study__wall_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

#endif
