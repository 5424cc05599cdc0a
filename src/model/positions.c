/* The positions of a sweep: how many, and tirenv envelope's by default (include/tirenv/stream.h).
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "tirenv/stream.h"

#include <math.h>

size_t tirenv_positions_count(double x_from, double x_to, double dx)
{
    const double limit = x_to + dx * 1e-9;
    size_t n = (size_t)floor((limit - x_from) / dx) + 1;
    /* The division can land one step off either way; the product decides. */
    while (n > 1 && x_from + (double)(n - 1) * dx > limit)
        --n;
    while (x_from + (double)n * dx <= limit)
        ++n;
    return n;
}

/* A free tire first reaches the ground's first vertex from R0 before it; 2 cm more, so the
 * curve starts and ends level. The sums stay in this order: the sweeps of the CLI and of the
 * Python module are these positions bit for bit, and were before the library had them. */
tirenv_positions tirenv_positions_default(double x_first, double x_last, double R0)
{
    const double margin = 0.02;  /* m */
    return (tirenv_positions){.x_from = x_first - R0 - margin, .x_to = x_last + R0 + margin,
                              .dx = 0.001};
}
