#include "testutil.h"

#include <math.h>
#include <stdio.h>

void tirenv_test_assert_near(double actual, double expected, double abs_tol, double rel_tol,
                             const char *expr, const char *file, int line)
{
    const double tol = abs_tol + rel_tol * fabs(expected);
    if (!(fabs(actual - expected) <= tol)) {
        print_error("%s = %.17g, expected %.17g within %.3g (off by %.3g)\n", expr, actual,
                    expected, tol, actual - expected);
        _fail(file, line);
    }
}
