/* Numbers with '.' whatever the host's LC_NUMERIC (src/io/c_numeric.c, docs/formats.md
 * section 1): a host that set a locale whose decimal point is ',' (a GUI toolkit, Python's
 * locale.setlocale) read "0.68" as 0 and refused the rest, and wrote "0,68", a file no reader
 * takes. The locale is made here, with localedef into the scratch directory (LOCPATH), from a
 * source that changes LC_NUMERIC alone; the tests then read and write each kind of file under
 * it, and run a parallel loop under it, and check that the host's locale is the same
 * afterwards.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "io/io.h"
#include "tirenv/numtext.h"
#include "tirenv/parallel.h"
#include "tirenv/profile.h"
#include "tirenv/profile_csv.h"
#include "tirenv/profile_file.h"
#include "tirenv/ride.h"
#include "tirenv/tir.h"
#include "tirenv/tire.h"
#include "tirenv/vehicle.h"
#include "tirenv/vehicle_file.h"

#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const char comma_source[] =
    "comment_char %\nescape_char /\n"
    "LC_CTYPE\ncopy \"POSIX\"\nEND LC_CTYPE\n"
    "LC_NUMERIC\ndecimal_point \"<U002C>\"\nthousands_sep \"<U002E>\"\ngrouping 3;3\n"
    "END LC_NUMERIC\n"
    "LC_COLLATE\ncopy \"POSIX\"\nEND LC_COLLATE\n"
    "LC_MONETARY\ncopy \"POSIX\"\nEND LC_MONETARY\n"
    "LC_TIME\ncopy \"POSIX\"\nEND LC_TIME\n"
    "LC_MESSAGES\ncopy \"POSIX\"\nEND LC_MESSAGES\n";

/* The scratch directory, with the comma locale "comma" made in it and set on the process. */
static int setup(void **state)
{
    if (tirenv_test_dir_setup(state))
        return -1;
    const tirenv_test_dir *d = *state;
    char src[600], out[600], q_src[700], q_out[700], cmd[1600];
    tirenv_test_write_text(tirenv_test_path(d, "comma.src", src), comma_source);
    tirenv_test_path(d, "comma", out);
    snprintf(cmd, sizeof cmd, "localedef -i %s -f ANSI_X3.4-1968 %s >/dev/null 2>&1",
             tirenv_test_shell_quote(src, q_src, sizeof q_src),
             tirenv_test_shell_quote(out, q_out, sizeof q_out));
    const int rc = system(cmd);
    if (setenv("LOCPATH", d->dir, 1) || !setlocale(LC_ALL, "comma") ||
        strcmp(localeconv()->decimal_point, ",") != 0) {
        fprintf(stderr, "could not make a locale whose decimal point is ',' (localedef exit "
                        "%d; it needs the Debian package locales, which scripts/deps.sh "
                        "installs)\n", rc);
        return -1;
    }
    return 0;
}

static int teardown(void **state)
{
    setlocale(LC_ALL, "C");
    unsetenv("LOCPATH");
    return tirenv_test_dir_teardown_tree(state);
}

/* The host's locale after each call: still its own. */
static void assert_host_comma(void)
{
    char buf[16];
    snprintf(buf, sizeof buf, "%g", 0.5);
    assert_string_equal(buf, "0,5");
}

static void test_tire_file(void **state)
{
    const tirenv_test_dir *d = *state;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    char path[600], text[65536], value[64];
    const tirenv_tire t = tirenv_tire_default();
    assert_int_equal(tirenv_tir_write(tirenv_test_path(d, "t.tir", path), &t, &diag), TIRENV_OK);
    assert_host_comma();
    tirenv_test_read_text(path, text, sizeof text);
    assert_non_null(strstr(text, "= 0.68 "));
    assert_null(strstr(text, "0,68"));
    tirenv_tire back = tirenv_tire_default();
    back.springs.R0 = 1;
    assert_int_equal(tirenv_tir_read(path, &back, &diag), TIRENV_OK);
    assert_host_comma();
    assert_true(back.springs.R0 == 0.68 && back.springs.c_r == t.springs.c_r &&
                back.ring.k_c == t.ring.k_c);
    assert_int_equal(tirenv_tir_set(&back, "UNLOADED_RADIUS=0.705", &diag), TIRENV_OK);
    assert_true(back.springs.R0 == 0.705);
    assert_int_equal(tirenv_tir_get(&back, "UNLOADED_RADIUS", value, sizeof value, NULL, &diag),
                     TIRENV_OK);
    assert_string_equal(value, "0.705");
    assert_host_comma();
}

static void test_roads(void **state)
{
    const tirenv_test_dir *d = *state;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    char path[600];
    tirenv_test_write_text(tirenv_test_path(d, "r.csv", path),
                           "x_m,z_m\n-1.5,0\n0.25,0.0125\n2.75,-0.5\n");
    tirenv_profile *p = NULL;
    assert_int_equal(tirenv_profile_read_csv(path, &p, &diag), TIRENV_OK);
    assert_host_comma();
    assert_true(tirenv_profile_x(p)[1] == 0.25 && tirenv_profile_z(p)[1] == 0.0125);
    /* Written as each format and read back: the same road. */
    static const char *const names[] = {"w.csv", "w.rdf", "w.crg"};
    for (size_t k = 0; k < 3; ++k) {
        tirenv_profile_write_options o = tirenv_profile_write_default();
        o.crg_u_increment = 0.25;
        assert_int_equal(tirenv_profile_write_file(tirenv_test_path(d, names[k], path), p, &o,
                                                   &diag),
                         TIRENV_OK);
        assert_host_comma();
        const tirenv_profile_source src = tirenv_profile_source_default();
        tirenv_profile *q = NULL;
        assert_int_equal(tirenv_profile_read_file(path, &src, &q, &diag), TIRENV_OK);
        assert_host_comma();
        for (double x = -1.5; x <= 2.75; x += 0.25)
            assert_true(fabs(tirenv_profile_height(q, x) - tirenv_profile_height(p, x)) <= 1e-12);
        tirenv_profile_free(q);
    }
    tirenv_profile_free(p);
}

static void test_vehicle_and_numbers(void **state)
{
    const tirenv_test_dir *d = *state;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    char path[600], buf[TIRENV_FMT_G_SIZE];
    tirenv_vehicle v = tirenv_vehicle_default();
    v.m = 4321.5;
    assert_int_equal(tirenv_vehicle_write(tirenv_test_path(d, "v.veh", path), &v, &diag),
                     TIRENV_OK);
    tirenv_vehicle back = tirenv_vehicle_default();
    assert_int_equal(tirenv_vehicle_read(path, &back, &diag), TIRENV_OK);
    assert_true(back.m == 4321.5);
    tirenv_fmt_shortest(0.1, buf);
    assert_string_equal(buf, "0.1");
    double speed = 0;
    assert_int_equal(tirenv_ride_speed_parse("2.5", &speed, &diag), TIRENV_OK);
    assert_true(speed == 2.5);
    assert_host_comma();
}

/* A work item of tirenv_parallel_for: 0.5 as printf writes it here, and on which worker. */
typedef struct {
    char text[16][16];
    size_t worker[16];
} halves;

static int write_half(void *ctx, size_t item, size_t worker, tirenv_diag *diag)
{
    (void)diag;
    halves *h = ctx;
    const struct timespec pause = {0, 2000000}; /* 2 ms: the other thread gets items too */
    nanosleep(&pause, NULL);
    snprintf(h->text[item], sizeof h->text[item], "%g", 0.5);
    h->worker[item] = worker;
    return TIRENV_OK;
}

/* The work items of an entry's tirenv_parallel_for (a sweep's cases, a study's comparisons)
 * run in the entry's locale on every thread, not in the process's: a started thread took the
 * global locale and wrote "0,5". */
static void test_threads_keep_the_entry_locale(void **state)
{
    (void)state;
    halves h = {{{0}}, {0}};
    {
        TIRENV_NUMERIC_C();
        assert_int_equal(tirenv_parallel_for(16, 2, write_half, NULL, &h, NULL), TIRENV_OK);
    }
    size_t on_other = 0;
    for (size_t i = 0; i < 16; ++i) {
        assert_string_equal(h.text[i], "0.5");
        on_other += h.worker[i] != 0;
    }
    assert_true(on_other > 0);
    assert_host_comma();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_tire_file, setup, teardown),
        cmocka_unit_test_setup_teardown(test_roads, setup, teardown),
        cmocka_unit_test_setup_teardown(test_vehicle_and_numbers, setup, teardown),
        cmocka_unit_test_setup_teardown(test_threads_keep_the_entry_locale, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
