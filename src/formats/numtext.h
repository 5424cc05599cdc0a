/* Private to src/formats: numbers written so that they read back exactly.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TIRENV_FORMATS_NUMTEXT_H
#define TIRENV_FORMATS_NUMTEXT_H

#include <stddef.h>

/* The shortest text that strtod reads back to v exactly: plain decimals where they are short
 * (0.1, 250.2, -10000), else the shortest "%.*g" (1e-07, 6.02e+23). n >= 32
 * (TIRENV_FMT_G_SIZE: all of it may be written). */
void tirenv_numtext__shortest(char *buf, size_t n, double v);

#endif
