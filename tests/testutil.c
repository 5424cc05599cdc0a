#include "testutil.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

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

void tirenv_test_check_bits(double a, double b, const char *expr, const char *file, int line)
{
    if (memcmp(&a, &b, sizeof a) != 0) {
        print_error("%s = %.17g (%a), expected exactly %.17g (%a)\n", expr, a, a, b, b);
        _fail(file, line);
    }
}

int tirenv_test_dir_setup(void **state)
{
    tirenv_test_dir *d = calloc(1, sizeof *d);
    if (!d)
        return -1;
    snprintf(d->dir, sizeof d->dir, "/tmp/tirenv_test_XXXXXX");
    if (!mkdtemp(d->dir)) {
        free(d);
        return -1;
    }
    *state = d;
    return 0;
}

int tirenv_test_dir_teardown(void **state)
{
    tirenv_test_dir *d = *state;
    DIR *dir = opendir(d->dir);
    if (dir) {
        const struct dirent *e;
        char path[600];
        while ((e = readdir(dir)) != NULL) {
            if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
                continue;
            snprintf(path, sizeof path, "%s/%s", d->dir, e->d_name);
            remove(path);
        }
        closedir(dir);
    }
    const int r = rmdir(d->dir);
    free(d);
    return r;
}

const char *tirenv_test_path(const tirenv_test_dir *d, const char *name, char buf[600])
{
    snprintf(buf, 600, "%s/%s", d->dir, name);
    return buf;
}

void tirenv_test_write_text(const char *path, const char *text)
{
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    assert_int_equal(fputs(text, fp) >= 0, 1);
    assert_int_equal(fclose(fp), 0);
}

size_t tirenv_test_count_entries(const tirenv_test_dir *d, const char *containing)
{
    DIR *dir = opendir(d->dir);
    assert_non_null(dir);
    size_t n = 0;
    const struct dirent *e;
    while ((e = readdir(dir)) != NULL)
        if (strstr(e->d_name, containing) && strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            n++;
    closedir(dir);
    return n;
}
