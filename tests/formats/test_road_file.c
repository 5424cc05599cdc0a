/* SPDX-License-Identifier: Apache-2.0 */
/* The one road reader (tirenv_road_file, profile_file.h): a road file opened once and its
 * format told once. Proved from outside by what a second open could not do: a FIFO, which a
 * writer fills once, read whole and by two row readers at once, each format giving the
 * regular file's profile bit for bit; and a regular file removed after the open and replaced
 * by another road, still read as it was. The open's errors keep the texts of
 * tirenv_profile_detect's. */
#include "testutil.h"
#include "tirenv/tirenv.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

/* A road with a wall and high-entropy heights, 2-D: written as CSV, RDF and CRG (whose two
 * long sections carry it across, so every track has its heights). */
static const char road_csv[] = "# test_road_file\nx_m,z_m\n-0.73,0\n-0.0137,0.00213\n"
                               "0.2385,0.0171\n0.2385,0.0418\n0.6,0.0418\n1.1113,-0.0029\n"
                               "2.5,0\n";
static const char *const names[3] = {"road.csv", "road.crg", "road.rdf"};

static void write_roads(const tirenv_test_dir *fx)
{
    char path[600];
    tirenv_test_write_text(tirenv_test_path(fx, names[0], path), road_csv);
    tirenv_profile *p = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_profile_read_csv(path, &p, &d), TIRENV_OK);
    /* The CRG resampled every 0.0125 m from the profile, with flat ground beyond its wall. */
    tirenv_profile_write_options o = tirenv_profile_write_default();
    o.crg_u_increment = 0.0125;
    for (size_t f = 1; f < 3; ++f)
        assert_int_equal(tirenv_profile_write_file(tirenv_test_path(fx, names[f], path), p, &o,
                                                   &d),
                         TIRENV_OK);
    tirenv_profile_free(p);
}

/* A child that opens fifo for writing and copies file into it once (alarm: it never waits
 * more than 30 s for a reader). */
static pid_t feed(const char *fifo, const char *file)
{
    const pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        alarm(30);
        const int in = open(file, O_RDONLY), out = open(fifo, O_WRONLY);
        char buf[4096];
        ssize_t n;
        while (in >= 0 && out >= 0 && (n = read(in, buf, sizeof buf)) > 0)
            if (write(out, buf, (size_t)n) != n)
                _exit(1);
        _exit(in >= 0 && out >= 0 ? 0 : 1);
    }
    return pid;
}

static void assert_same_profile(const tirenv_profile *a, const tirenv_profile *b)
{
    const size_t n = tirenv_profile_size(a);
    assert_int_equal(tirenv_profile_size(b), n);
    assert_true(n > 2);
    for (size_t i = 0; i < n; ++i) {
        assert_bits_equal(tirenv_profile_x(a)[i], tirenv_profile_x(b)[i]);
        assert_bits_equal(tirenv_profile_z(a)[i], tirenv_profile_z(b)[i]);
    }
}

/* The next row of r: x and the heights of n tracks, which must be vertex i of p. */
static void assert_row(tirenv_profile_file_reader *r, size_t n, const tirenv_profile *p,
                       size_t i)
{
    double x, z[2];
    int got = 0;
    tirenv_diag d;
    assert_int_equal(tirenv_profile_file_reader_next(r, &x, z, &got, &d), TIRENV_OK);
    assert_true(got);
    assert_bits_equal(x, tirenv_profile_x(p)[i]);
    for (size_t k = 0; k < n; ++k)
        assert_bits_equal(z[k], tirenv_profile_z(p)[i]);
}

/* Reads of f that a path read once could not give: the profile whole (twice, two tracks),
 * then two row readers interleaved, each the whole profile from its start. */
static void read_all_ways(tirenv_road_file *f, const tirenv_profile *want)
{
    tirenv_diag d;
    tirenv_profile *t[2] = {NULL, NULL};
    assert_int_equal(tirenv_road_file_read(f, NULL, 2, NULL, t, &d), TIRENV_OK);
    assert_same_profile(t[0], want);
    assert_same_profile(t[1], want);
    tirenv_profile_free(t[0]);
    tirenv_profile_free(t[1]);
    tirenv_profile_file_reader *a = NULL, *b = NULL;
    assert_int_equal(tirenv_road_file_reader(f, NULL, 2, NULL, &a, &d), TIRENV_OK);
    const size_t n = tirenv_profile_size(want), half = n / 2;
    for (size_t i = 0; i < half; ++i)
        assert_row(a, 2, want, i);
    assert_int_equal(tirenv_road_file_reader(f, NULL, 1, NULL, &b, &d), TIRENV_OK);
    for (size_t i = 0; i < n; ++i)
        assert_row(b, 1, want, i);
    for (size_t i = half; i < n; ++i)
        assert_row(a, 2, want, i);
    double x, z[2];
    int got = 1;
    assert_int_equal(tirenv_profile_file_reader_next(a, &x, z, &got, &d), TIRENV_OK);
    assert_false(got);
    tirenv_profile_file_reader_free(a);
    tirenv_profile_file_reader_free(b);
}

/* Each format through a FIFO filled once: the format told, every read the regular file's. */
static void test_fifo_read_once(void **state)
{
    const tirenv_test_dir *fx = *state;
    write_roads(fx);
    const tirenv_profile_format formats[3] = {TIRENV_PROFILE_CSV, TIRENV_PROFILE_CRG,
                                              TIRENV_PROFILE_RDF};
    for (size_t k = 0; k < 3; ++k) {
        char path[600], fifo[600];
        tirenv_test_path(fx, names[k], path);
        tirenv_test_path(fx, "fifo", fifo);
        tirenv_diag d;
        tirenv_profile *want = NULL;
        assert_int_equal(tirenv_profile_read_file(path, NULL, &want, &d), TIRENV_OK);
        unlink(fifo);
        assert_int_equal(mkfifo(fifo, 0600), 0);
        const pid_t writer = feed(fifo, path);
        tirenv_road_file *f = NULL;
        assert_int_equal(tirenv_road_file_open(fifo, &f, &d), TIRENV_OK);
        assert_int_equal(tirenv_road_file_format(f), formats[k]);
        assert_string_equal(tirenv_road_file_name(f), fifo);
        read_all_ways(f, want);
        if (formats[k] == TIRENV_PROFILE_CRG) {  /* the CRG handle, from the same copy */
            tirenv_crg *crg = NULL;
            assert_int_equal(tirenv_road_file_crg(f, &crg, &d), TIRENV_OK);
            assert_int_equal(tirenv_crg_long_sections(crg), 2);
            tirenv_crg_free(crg);
        }
        tirenv_road_file_free(f);
        int st = -1;
        assert_int_equal(waitpid(writer, &st, 0), writer);
        assert_true(WIFEXITED(st) && WEXITSTATUS(st) == 0);  /* it wrote everything, once */
        tirenv_profile_free(want);
    }
}

/* A regular file removed after the open and another road put at its path: every read is
 * still the first file's, so none opens the path again. */
static void test_regular_file_not_reopened(void **state)
{
    const tirenv_test_dir *fx = *state;
    write_roads(fx);
    for (size_t k = 0; k < 3; ++k) {
        char path[600], other[600];
        tirenv_test_path(fx, names[k], path);
        tirenv_diag d;
        tirenv_profile *want = NULL;
        assert_int_equal(tirenv_profile_read_file(path, NULL, &want, &d), TIRENV_OK);
        tirenv_road_file *f = NULL;
        assert_int_equal(tirenv_road_file_open(path, &f, &d), TIRENV_OK);
        assert_int_equal(unlink(path), 0);
        tirenv_test_write_text(tirenv_test_path(fx, "other.csv", other),
                               "x_m,z_m\n0,0.5\n1,0.5\n");
        assert_int_equal(rename(other, path), 0);
        read_all_ways(f, want);
        tirenv_road_file_free(f);
        tirenv_profile_free(want);
    }
}

/* The open's errors: a missing file, a directory, with tirenv_profile_detect's texts; a
 * failed open leaves *out NULL. */
static void test_open_errors(void **state)
{
    const tirenv_test_dir *fx = *state;
    char missing[600];
    tirenv_test_path(fx, "none.crg", missing);
    tirenv_diag d;
    tirenv_road_file *f = (tirenv_road_file *)&d;
    assert_int_equal(tirenv_road_file_open(missing, &f, &d), TIRENV_EIO);
    assert_null(f);
    assert_string_equal(d.file, missing);
    assert_string_equal(d.message, "cannot open: No such file or directory");
    tirenv_profile_format format = TIRENV_PROFILE_RDF;
    assert_int_equal(tirenv_profile_detect(fx->dir, &format, &d), TIRENV_EIO);
    assert_int_equal(format, TIRENV_PROFILE_RDF);  /* untouched */
    assert_string_equal(d.message, "is a directory; expected a CSV, OpenCRG or RDF road file");
    tirenv_road_file_free(NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_fifo_read_once, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_regular_file_not_reopened, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_open_errors, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
