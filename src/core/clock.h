/* Private: the library's one clock, for the timings its reports carry.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CORE_CLOCK_H
#define TIRENV_CORE_CLOCK_H

/* Wall time since an arbitrary start (CLOCK_MONOTONIC), s. */
double tirenv_core__wall_seconds(void);

#endif
