/* Private to src/io and the modules after it: the process's file-creation mask, read without changing it.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_DATA_UMASK_H
#define TIRENV_DATA_UMASK_H

#include <sys/types.h>

/* The umask, as open(2) applies it. Safe while other threads create files. */
mode_t tirenv_data__umask(void);

#endif
