/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the core: golden-section search for the minimum of a function on a bracket
 * (Kiefer 1953), split into set / iterate like brent.h, with a driver for a fixed number of
 * steps. Each step narrows the bracket by (sqrt(5) - 1)/2 = 0.618 with one evaluation. */
#ifndef TIRENV_CORE_GOLDEN_H
#define TIRENV_CORE_GOLDEN_H

typedef double (*tirenv_core__golden_fn)(double x, void *params);

/* Which part of the bracket a step keeps when f(c) == f(d): the lower [a, d] or the upper
 * [c, b] (a NaN at either point keeps the upper with both). Where the minimum is flat, or the
 * function returns a constant after a failure, the two end at opposite sides. */
typedef enum {
    TIRENV_CORE__GOLDEN_TIES_LOWER,
    TIRENV_CORE__GOLDEN_TIES_UPPER
} tirenv_core__golden_ties;

typedef struct {
    tirenv_core__golden_fn f;
    void *params;
    tirenv_core__golden_ties ties;
    double a, b;           /* the bracket */
    double c, d;           /* its inner points, a < c < d < b */
    double fc, fd;         /* f there */
} tirenv_core__golden;

/* Evaluates f at the inner points of [a, b] (a < b), c first. */
void tirenv_core__golden_set(tirenv_core__golden *s, tirenv_core__golden_fn f, void *params,
                             double a, double b, tirenv_core__golden_ties ties);
/* One step: the part of the bracket beyond the inner point of larger f dropped, f evaluated
 * once at the new inner point. */
void tirenv_core__golden_iterate(tirenv_core__golden *s);
/* steps steps from [a, b] with ties kept lower: the middle of the last bracket, and f there
 * into *f_min unless NULL (one more evaluation). */
double tirenv_core__golden_min(tirenv_core__golden_fn f, void *params, double a, double b,
                               int steps, double *f_min);

#endif
