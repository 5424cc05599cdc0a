/* Shared test helpers: cmocka 1.1 has no floating-point comparison. */
#ifndef TIRENV_TESTUTIL_H
#define TIRENV_TESTUTIL_H

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

/* Fails unless |actual - expected| <= abs_tol + rel_tol*|expected|; prints both values. */
#define assert_near(actual, expected, abs_tol, rel_tol)                                      \
    tirenv_test_assert_near((actual), (expected), (abs_tol), (rel_tol), #actual, __FILE__,   \
                            __LINE__)

void tirenv_test_assert_near(double actual, double expected, double abs_tol, double rel_tol,
                             const char *expr, const char *file, int line);

#endif
