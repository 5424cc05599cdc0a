/* SPDX-License-Identifier: Apache-2.0 */
/* Golden-section search (J. Kiefer, Sequential minimax search for a maximum, 1953): of the two
 * inner points at 0.382 and 0.618 of the bracket, the one of larger f bounds the new bracket,
 * and the other is the new bracket's inner point on its side, so that a step costs one
 * evaluation. The new point is placed from the bracket's ends (c = b - g (b - a), d = a +
 * g (b - a)), not from the kept point, the arithmetic the searches written before this one
 * used, so that their results are the same bits. */
#include "core/golden.h"

#include <math.h>

void tirenv_core__golden_set(tirenv_core__golden *s, const tirenv_core__golden_fn f,
                             void *params, const double a, const double b,
                             const tirenv_core__golden_ties ties)
{
    const double g = 0.5 * (sqrt(5.0) - 1);
    s->f = f;
    s->params = params;
    s->ties = ties;
    s->a = a;
    s->b = b;
    s->c = b - g * (b - a);
    s->d = a + g * (b - a);
    s->fc = f(s->c, params);
    s->fd = f(s->d, params);
}

void tirenv_core__golden_iterate(tirenv_core__golden *s)
{
    const double g = 0.5 * (sqrt(5.0) - 1);
    const int lower = s->ties == TIRENV_CORE__GOLDEN_TIES_LOWER ? s->fc <= s->fd
                                                                 : s->fc < s->fd;
    if (lower) {
        s->b = s->d, s->d = s->c, s->fd = s->fc;
        s->c = s->b - g * (s->b - s->a);
        s->fc = s->f(s->c, s->params);
    } else {
        s->a = s->c, s->c = s->d, s->fc = s->fd;
        s->d = s->a + g * (s->b - s->a);
        s->fd = s->f(s->d, s->params);
    }
}

double tirenv_core__golden_min(const tirenv_core__golden_fn f, void *params, const double a,
                               const double b, const int steps, double *f_min)
{
    tirenv_core__golden s;
    tirenv_core__golden_set(&s, f, params, a, b, TIRENV_CORE__GOLDEN_TIES_LOWER);
    for (int k = 0; k < steps; k++)
        tirenv_core__golden_iterate(&s);
    const double x = 0.5 * (s.a + s.b);
    if (f_min)
        *f_min = f(x, params);
    return x;
}
