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

/* Fails unless a and b are the same double, bit for bit (exactness claims); prints both. */
#define assert_bits_equal(a, b) tirenv_test_check_bits((a), (b), #a, __FILE__, __LINE__)

void tirenv_test_check_bits(double a, double b, const char *expr, const char *file, int line);

/* A fresh scratch directory per test: cmocka setup and teardown (the teardown removes the
 * files left in it and fails if the directory itself cannot go). */
typedef struct {
    char dir[64];
} tirenv_test_dir;

int tirenv_test_dir_setup(void **state);
int tirenv_test_dir_teardown(void **state);

/* dir/name in buf. */
const char *tirenv_test_path(const tirenv_test_dir *d, const char *name, char buf[600]);
/* Writes text to path, asserting success. */
void tirenv_test_write_text(const char *path, const char *text);
/* Entries of the directory whose name contains the string. */
size_t tirenv_test_count_entries(const tirenv_test_dir *d, const char *containing);

#endif
