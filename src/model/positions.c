/* The positions of a sweep: how many, and tirenv envelope's by default (include/tirenv/stream.h).
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/stream.h"

#include <math.h>
#include <stdint.h>

/* Every bound is checked before the count is used, so no input loops or overflows: ends or a
 * step that are not finite (NaN compares false everywhere), a count past
 * TIRENV_POSITIONS_MAX (also what keeps (double)k exact and n within size_t), and a step
 * below the spacing of the doubles at the ends, where x + dx == x and the positions stop
 * moving (1e300 + 0.1). */
size_t tirenv_positions_count(double x_from, double x_to, double dx)
{
    if (!(isfinite(x_from) && isfinite(x_to) && isfinite(dx) && dx > 0 && x_to >= x_from))
        return 0;
    if (x_from + dx == x_from || x_to + dx == x_to)
        return 0;
    const double limit = x_to + dx * 1e-9;
    const double steps = floor((limit - x_from) / dx);
    if (!(steps < TIRENV_POSITIONS_MAX - 2 && steps < (double)SIZE_MAX - 2))
        return 0;
    size_t n = (size_t)steps + 1;
    /* The division can land one step off either way; the product decides. Each loop moves n
     * by a step or two at most: the bound only guards against a case not foreseen. */
    for (int i = 0; i < 4 && n > 1 && x_from + (double)(n - 1) * dx > limit; ++i)
        --n;
    for (int i = 0; i < 4 && x_from + (double)n * dx <= limit; ++i)
        ++n;
    if (x_from + (double)n * dx <= limit || (n > 1 && x_from + (double)(n - 1) * dx > limit))
        return 0;
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
