/* SPDX-License-Identifier: Apache-2.0 */
/* The one road reader (tirenv_road_file, profile_file.h): a road file opened once and its
 * format told once. Proved from outside by what a second open could not do: a FIFO, which a
 * writer fills once, read whole and by two row readers at once, each format giving the
 * regular file's profile bit for bit; and a regular file removed after the open and replaced
 * by another road, still read as it was. The open's errors keep the texts of
 * tirenv_profile_detect's. A road's ends (tirenv_road_file_extent) as its readers find them;
 * an OpenCRG or RDF road's without its rows, from what its readers then share. */
#include "testutil.h"
#include "tirenv/tirenv.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
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

/* The FIFO "fifo" in fx made afresh and fed file once by a child (*writer); opened. */
static tirenv_road_file *open_fed_fifo(const tirenv_test_dir *fx, const char *file,
                                       pid_t *writer)
{
    char fifo[600];
    tirenv_test_path(fx, "fifo", fifo);
    unlink(fifo);
    assert_int_equal(mkfifo(fifo, 0600), 0);
    *writer = feed(fifo, file);
    tirenv_road_file *f = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_road_file_open(fifo, &f, &d), TIRENV_OK);
    return f;
}

/* The feeding child gone, having written everything once. */
static void assert_fed(pid_t writer)
{
    int st = -1;
    assert_int_equal(waitpid(writer, &st, 0), writer);
    assert_true(WIFEXITED(st) && WEXITSTATUS(st) == 0);
}

/* Road k of write_roads read whole from its regular file; its path in path. */
static tirenv_profile *read_road(const tirenv_test_dir *fx, size_t k, char path[600])
{
    tirenv_test_path(fx, names[k], path);
    tirenv_profile *p = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_profile_read_file(path, NULL, &p, &d), TIRENV_OK);
    return p;
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
        tirenv_profile *want = read_road(fx, k, path);
        pid_t writer;
        tirenv_road_file *f = open_fed_fifo(fx, path, &writer);
        tirenv_diag d;
        assert_int_equal(tirenv_road_file_format(f), formats[k]);
        assert_string_equal(tirenv_road_file_name(f), tirenv_test_path(fx, "fifo", fifo));
        read_all_ways(f, want);
        if (formats[k] == TIRENV_PROFILE_CRG) {  /* the CRG handle, from the same copy */
            const tirenv_crg *crg = NULL, *again = NULL;
            assert_int_equal(tirenv_road_file_crg(f, &crg, &d), TIRENV_OK);
            assert_int_equal(tirenv_crg_long_sections(crg), 2);
            /* the file's one handle, its readers' too (its pass at open made once) */
            assert_int_equal(tirenv_road_file_crg(f, &again, &d), TIRENV_OK);
            assert_ptr_equal(again, crg);
        }
        tirenv_road_file_free(f);
        assert_fed(writer);
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
        tirenv_profile *want = read_road(fx, k, path);
        tirenv_diag d;
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

/* The extent of f: its first and last x, which must be want's ends, bit for bit. */
static void assert_extent(tirenv_road_file *f, const tirenv_profile *want)
{
    double first = NAN, last = NAN, a, b;
    tirenv_diag d;
    tirenv_profile_extent(want, &a, &b);
    for (int every_row = 0; every_row < 2; ++every_row) {
        assert_int_equal(tirenv_road_file_extent(f, NULL, 2, NULL, every_row, &first, &last, &d),
                         TIRENV_OK);
        assert_bits_equal(first, a);
        assert_bits_equal(last, b);
    }
}

/* tirenv_road_file_extent: each format's ends, from a regular file and from a FIFO; a CSV's
 * without its middle rows (one that does not parse there is a reader's to find, and is not
 * read), its last row found behind blank lines, comments, CRLF ends and more than the reader's
 * longest line of comments (then read from the start); where the last row cannot be told from
 * the end (it does not parse, lies before the first, or a NUL byte follows it) the first bad
 * row is named at its line, as a reader names it. */
static void test_extent(void **state)
{
    const tirenv_test_dir *fx = *state;
    write_roads(fx);
    for (size_t k = 0; k < 3; ++k) {
        char path[600];
        tirenv_profile *want = read_road(fx, k, path);
        tirenv_diag d;
        tirenv_road_file *f = NULL;
        assert_int_equal(tirenv_road_file_open(path, &f, &d), TIRENV_OK);
        assert_extent(f, want);
        tirenv_road_file_free(f);
        pid_t writer;
        f = open_fed_fifo(fx, path, &writer);
        assert_extent(f, want);
        read_all_ways(f, want);  /* the FIFO's bytes still all there for the readers */
        tirenv_road_file_free(f);
        assert_fed(writer);
        tirenv_profile_free(want);
    }
    /* Long comment tails: 3 lines of 65,000 characters after the last row. */
    static char tail[3 * 65002 + 1];
    for (size_t i = 0; i < 3; ++i) {
        char *line = tail + i * 65002;
        line[0] = '#';
        memset(line + 1, '-', 65000);
        line[65001] = '\n';
    }
    static char text[sizeof tail + 256];
    const struct {
        const char *head, *tail;
        double first, last;       /* NAN: an error */
        size_t line;
        const char *says;
    } cases[] = {
        {"x_m,z_m\n-0.125,0\n0.2385,abc\n7.125,0.5\n", "", -0.125, 7.125, 0, NULL},
        {"x_m,z_m\r\n-0.125,0\r\n0.5,0\r\n 7.125 , 0.5 \r\n", "\r\n  \r\n# end\r\n\n", -0.125,
         7.125, 0, NULL},
        /* A last row without a line end: the file may be cut inside it ("0.5" of "0.55"). */
        {"x_m,z_m\n-0.125,0\n0.5,0\n7.125,0.5", "", NAN, NAN, 4,
         "the file ends inside this line"},
        {"x_m,z_m\n-0.125,0\n0.5,0\n7.125,0.5\n", tail, -0.125, 7.125, 0, NULL},
        {"x_m,z_m\n-0.125,0\n0.2385,abc\n7.125,0.5\n", tail, NAN, NAN, 3,
         "expected a number, got 'abc'"},
        {"x_m,z_m\n-0.125,0\n0.5,0\n7.125,0.5x\n", "", NAN, NAN, 4,
         "expected a number, got '0.5x'"},
        {"x_m,z_m\n3.5,0\n4,0\n2.25,0.5\n", "# back\n", NAN, NAN, 4, "x_m decreases"},
        {"x_m,z_m\n3.5,0\n4,0\n", "# a NUL\0\n", NAN, NAN, 4, "a NUL byte"},
        {"x_m,z_m\n3.5,0\n", "", 3.5, 3.5, 0, NULL},
        {"x_m,z_m\n# nothing\n", "", NAN, NAN, 0, "no data rows"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; ++i) {
        char path[600];
        tirenv_test_path(fx, "extent.csv", path);
        const size_t nh = strlen(cases[i].head);
        const size_t nt = cases[i].tail == tail ? sizeof tail - 1
                          : i == 7              ? 9
                                                : strlen(cases[i].tail);
        memcpy(text, cases[i].head, nh);
        memcpy(text + nh, cases[i].tail, nt);
        FILE *fp = fopen(path, "wb");
        assert_non_null(fp);
        assert_int_equal(fwrite(text, 1, nh + nt, fp), nh + nt);
        assert_int_equal(fclose(fp), 0);
        tirenv_road_file *f = NULL;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        assert_int_equal(tirenv_road_file_open(path, &f, &d), TIRENV_OK);
        double first = NAN, last = NAN;
        const int status = tirenv_road_file_extent(f, NULL, 1, NULL, 0, &first, &last, &d);
        /* Every row read: the same, but case 0's middle row is found. */
        tirenv_diag e;
        double first_all = NAN, last_all = NAN;
        const int all = tirenv_road_file_extent(f, NULL, 1, NULL, 1, &first_all, &last_all, &e);
        tirenv_road_file_free(f);
        if (cases[i].says) {
            tirenv_test_expect_diag(i, status, &d, TIRENV_EPARSE, path, cases[i].line,
                                    d.column, d.field, cases[i].says);
            tirenv_test_expect_diag(i, all, &e, TIRENV_EPARSE, path, cases[i].line, d.column,
                                    d.field, cases[i].says);
        } else {
            assert_int_equal(status, TIRENV_OK);
            assert_bits_equal(first, cases[i].first);
            assert_bits_equal(last, cases[i].last);
            if (i == 0) {
                tirenv_test_expect_diag(i, all, &e, TIRENV_EPARSE, path, 3, 8, "z_m",
                                        "expected a number, got 'abc'");
            } else {
                assert_int_equal(all, TIRENV_OK);
                assert_bits_equal(first_all, first);
                assert_bits_equal(last_all, last);
            }
        }
    }
}

/* The left long section misses its value in row 3 (u = 0.5 m): a track at v = -1 needs it. */
static const char gap_crg[] =
    "$ROAD_CRG\n"
    "REFERENCE_LINE_START_U   = -0.5\n"
    "REFERENCE_LINE_END_U     = 1.5\n"
    "REFERENCE_LINE_INCREMENT = 0.5\n"
    "LONG_SECTION_V_RIGHT     = -1\n"
    "LONG_SECTION_V_LEFT      = 1\n"
    "$\n"
    "$ROAD_CRG_MODS\n"
    "* none\n"
    "$\n"
    "$KD_DEFINITION\n"
    "#:LRFI\n"
    "D:long section at v = -1,m\n"
    "D:long section at v = 1,m\n"
    "$\n"
    "$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$\n"
    "     0.010     0.030\n"
    "     0.011     0.031\n"
    "*missing*      0.032\n"
    "     0.013     0.033\n"
    "     0.014     0.034\n";

/* tirenv_road_file_extent without every row, for an OpenCRG or RDF road: the ends without the
 * rows, from what the file's readers share, so that the rows are read once more. An OpenCRG
 * track that needs a missing value: its ends (every row read: the error at the row); the
 * OpenCRG road's pass at open and the RDF road's scan are made once for the extent and every
 * reader: the file emptied after the extent, a reader still opens (a second pass or scan
 * would find no header); both readers read their rows from the file (neither road is kept in
 * memory), so find it emptied. */
static void test_extent_read_once(void **state)
{
    const tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_write_text(tirenv_test_path(fx, "gap.crg", path), gap_crg);
    tirenv_road_file *f = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_road_file_open(path, &f, &d), TIRENV_OK);
    tirenv_profile_source src = tirenv_profile_source_default();
    src.crg.v = -1;
    double first = NAN, last = NAN;
    assert_int_equal(tirenv_road_file_extent(f, &src, 1, NULL, 0, &first, &last, &d),
                     TIRENV_OK);
    assert_bits_equal(first, -0.5);
    assert_bits_equal(last, 1.5);
    tirenv_test_expect_diag(0, tirenv_road_file_extent(f, &src, 1, NULL, 1, &first, &last, &d),
                            &d, TIRENV_ERANGE, path, 0, 0, "v",
                            "the track at v = -1 m needs long section 1 (v = -1 m) at row 3 "
                            "(u = 0.5 m), where the road data has no value; expected a track "
                            "over the road's valid part (or GRID_NAN_MODE 1 or 2 in "
                            "$ROAD_CRG_MODS to fill missing values)");
    tirenv_road_file_free(f);
    write_roads(fx);
    for (size_t k = 1; k < 3; ++k) {
        tirenv_profile *want = read_road(fx, k, path);
        assert_int_equal(tirenv_road_file_open(path, &f, &d), TIRENV_OK);
        assert_extent(f, want);
        assert_int_equal(truncate(path, 0), 0);
        tirenv_profile_file_reader *r = NULL;
        assert_int_equal(tirenv_road_file_reader(f, NULL, 2, NULL, &r, &d), TIRENV_OK);
        double x, z[2];
        int got = 1;
        assert_int_equal(tirenv_profile_file_reader_next(r, &x, z, &got, &d), TIRENV_EIO);
        assert_false(got);
        tirenv_profile_file_reader_free(r);
        tirenv_road_file_free(f);
        tirenv_profile_free(want);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_fifo_read_once, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_regular_file_not_reopened, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_extent, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_extent_read_once, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_open_errors, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
