/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the core: Brent's root finder on a bracket (R. P. Brent, Algorithms for
 * Minimization without Derivatives, 1973, chapter 4, procedure zero), split into set /
 * iterate like the equilibrium solvers, with the bracket kept after every step. */
#ifndef TIRENV_CORE_BRENT_H
#define TIRENV_CORE_BRENT_H

typedef double (*tirenv_core__brent_fn)(double x, void *params);

typedef struct {
    tirenv_core__brent_fn f;
    void *params;
    double a, b, c;        /* previous iterate, best iterate, contrapoint */
    double fa, fb, fc;
    double d, e;           /* the last step and the one before */
    double root;           /* the best estimate: b */
    double lo, hi;         /* the bracket, lo <= root <= hi */
} tirenv_core__brent;

/* Status of set and iterate: 0, or one of these. */
enum {
    TIRENV_CORE__BRENT_NO_BRACKET = 1,  /* f(lo) and f(hi) have the same strict sign */
    TIRENV_CORE__BRENT_NOT_FINITE       /* f returned a value that is not finite */
};

/* Evaluates f at lo and at hi (lo < hi) and starts from them; root = hi's side per Brent. */
int tirenv_core__brent_set(tirenv_core__brent *s, tirenv_core__brent_fn f, void *params,
                           double lo, double hi);
/* As _set, from values f_lo = f(lo) and f_hi = f(hi) the caller has already evaluated (no
 * evaluation here): the same start, bit for bit. */
int tirenv_core__brent_set_values(tirenv_core__brent *s, tirenv_core__brent_fn f, void *params,
                                  double lo, double f_lo, double hi, double f_hi);
/* One step: one evaluation of f (none when the root is already exact or within round-off of
 * b). Updates root, lo and hi. */
int tirenv_core__brent_iterate(tirenv_core__brent *s);
/* |hi - lo| < eps_abs: the interval test of the equilibrium and the ring's patch. */
int tirenv_core__brent_converged(const tirenv_core__brent *s, double eps_abs);
/* What a status means, for messages. */
const char *tirenv_core__brent_strerror(int status);

#endif
