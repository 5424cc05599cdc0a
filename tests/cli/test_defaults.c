/* The defaults the CLI and the Python module take from the library rather than keep copies
 * of: the curved generators' resolution (profile.h), tirenv envelope's sweep (stream.h) and
 * tirenv ride's span and input grid (ride.h). Their values and formulas, what the resolution
 * promises, and the CLI's outputs recomputed here through the public API alone: a CLI that
 * went back to a private value of its own would fail the last two tests.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tirenv/tirenv.h"

/* ---- the values and the formulas ---------------------------------------------------- */

static void test_resolution_default(void **state)
{
    (void)state;
    const tirenv_profile_resolution res = tirenv_profile_resolution_default();
    assert_int_equal(res.cylinder_segments, 180);  /* 1 degree chords */
    assert_int_equal(res.sine_points_per_period, 64);
}

/* What the resolution promises (src/profile/generators.c): chords of the half cylinder
 * within 0.004 % of r of the circle, those of the sine within 0.061 % of its height 2A,
 * measured along each chord; and a coarser polyline breaks both bounds, so they measure. */
static double cylinder_gap(double r, size_t segments)
{
    tirenv_profile *p = tirenv_profile_half_cylinder(r, segments);
    assert_non_null(p);
    const double *x = tirenv_profile_x(p), *z = tirenv_profile_z(p);
    double gap = 0;
    for (size_t k = 0; k + 1 < tirenv_profile_size(p); ++k)
        gap = fmax(gap, r - hypot(0.5 * (x[k] + x[k + 1]), 0.5 * (z[k] + z[k + 1])));
    tirenv_profile_free(p);
    return gap;
}

static double sine_gap(double A, double wl, size_t points_per_period)
{
    tirenv_profile *p = tirenv_profile_sine(A, wl, 1.0, points_per_period);
    assert_non_null(p);
    double gap = 0;
    for (size_t i = 0; i <= 20000; ++i) {
        const double x = wl * (double)i / 20000;
        gap = fmax(gap, fabs(tirenv_profile_height(p, x) - A * (1 - cos(2 * M_PI * x / wl))));
    }
    tirenv_profile_free(p);
    return gap;
}

static void test_resolution_keeps_its_promise(void **state)
{
    (void)state;
    const tirenv_profile_resolution res = tirenv_profile_resolution_default();
    const double r = 0.1173, A = 0.0213, wl = 0.4519;
    assert_true(cylinder_gap(r, res.cylinder_segments) <= 0.00004 * r);
    assert_true(cylinder_gap(r, res.cylinder_segments / 2) > 0.00004 * r);
    assert_true(sine_gap(A, wl, res.sine_points_per_period) <= 0.00061 * 2 * A);
    assert_true(sine_gap(A, wl, res.sine_points_per_period / 2) > 0.00061 * 2 * A);
}

static void test_positions_default(void **state)
{
    (void)state;
    const double first = -0.1466, last = 0.2391, R0 = 0.7173;
    const tirenv_positions s = tirenv_positions_default(first, last, R0);
    assert_bits_equal(s.x_from, first - R0 - 0.02);
    assert_bits_equal(s.x_to, last + R0 + 0.02);
    assert_bits_equal(s.dx, 0.001);
    /* 2 (R0 + 2 cm) + 0.3857 m = 1.8603 m at 1 mm: 1861 positions. */
    assert_int_equal(tirenv_positions_count(s.x_from, s.x_to, s.dx), 1861);
}

static void test_ride_span(void **state)
{
    (void)state;
    const tirenv_ride_span s = tirenv_ride_span_default();
    assert_bits_equal(s.run_in, 1.0);
    assert_bits_equal(s.settle_min, 3.0);
    assert_bits_equal(s.settle_time, 2.0);
    assert_bits_equal(s.grid_margin, 1.0);
    assert_bits_equal(s.dx, 0.005);
    tirenv_vehicle v = tirenv_vehicle_default();
    v.a = 1.4537;
    v.b = 0.9461;
    assert_bits_equal(tirenv_ride_span_start(&s, -0.1466), -0.1466 - 1.0);
    /* Slow: 3 m past; fast: 2 s of travel. The sums in the CLI's order, bit for bit. */
    assert_bits_equal(tirenv_ride_span_end(&s, &v, 0.2391, 1.1), 0.2391 + 1.4537 + 0.9461 + 3);
    assert_bits_equal(tirenv_ride_span_end(&s, &v, 0.2391, 2.3),
                      0.2391 + 1.4537 + 0.9461 + 2 * 2.3);
    double x0;
    const double n = tirenv_ride_span_grid(&s, &v, -1.1466, 7.1327, &x0);
    assert_bits_equal(x0, -1.1466 - (1.4537 + 0.9461) - 1.0);
    /* From -4.5464 to 8.1327 m: 12.6791 m, 2535.82 spacings, so 2536 of them, 2537 points. */
    assert_true(n == 2537);
    const tirenv_ride_span fine = {.run_in = 1, .settle_min = 3, .settle_time = 2,
                                   .grid_margin = 0.25, .dx = 0.001};
    assert_true(tirenv_ride_span_grid(&fine, &v, -1.1466, 7.1327, &x0) == 11181);
    assert_false(isfinite(tirenv_ride_span_grid(&(tirenv_ride_span){.dx = 0}, &v, 0, 1, &x0)));
}

/* ---- the CLI's outputs ---------------------------------------------------------------- */

/* Runs a CLI command line (output to a file named in it); its exit status. */
static int run(const char *cmd)
{
    const int status = system(cmd);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* The file's lines, header included, into a malloc'd array of malloc'd strings. */
static char **read_lines(const char *path, size_t *n)
{
    FILE *fp = fopen(path, "r");
    assert_non_null(fp);
    char **lines = NULL, buf[1024];
    *n = 0;
    while (fgets(buf, sizeof buf, fp)) {
        buf[strcspn(buf, "\n")] = '\0';
        lines = realloc(lines, (*n + 1) * sizeof *lines);
        assert_non_null(lines);
        lines[(*n)++] = strdup(buf);
    }
    fclose(fp);
    return lines;
}

static void free_lines(char **lines, size_t n)
{
    for (size_t k = 0; k < n; ++k)
        free(lines[k]);
    free(lines);
}

/* The point model's curve at load over p, through tirenv_positions_default, as the rows
 * tirenv envelope writes; how many rows differ from lines[1..]. */
static size_t envelope_mismatches(const tirenv_profile *p, double load, char **lines,
                                  size_t n_lines)
{
    tirenv_tire tire = tirenv_test_default_tire();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_point, &tire);
    tirenv_diag diag;
    assert_non_null(m);
    assert_int_equal(tirenv_model_set(m, p, load, &diag), TIRENV_OK);
    double first, last;
    tirenv_profile_extent(p, &first, &last);
    const tirenv_positions s = tirenv_positions_default(first, last, tire.springs.R0);
    const size_t n = tirenv_positions_count(s.x_from, s.x_to, s.dx);
    size_t bad = n + 1 == n_lines ? 0 : n + 1;
    for (size_t k = 0; k < n && !bad; ++k) {
        tirenv_point pt;
        char row[512];
        assert_int_equal(tirenv_model_eval(m, s.x_from + (double)k * s.dx, &pt, &diag), 0);
        snprintf(row, sizeof row, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%zu,%zu", pt.x, pt.z, pt.h,
                 pt.slope, pt.fx, pt.fz, pt.contacts, pt.iterations);
        bad += strcmp(row, lines[k + 1]) != 0;
    }
    tirenv_model_free(m);
    return bad;
}

/* tirenv envelope --cylinder and --sine with the default sweep: the library's default
 * resolution and sweep, row for row; one chord more is another curve. */
static void test_cli_envelope_is_the_library_default(void **state)
{
    (void)state;
    const tirenv_profile_resolution res = tirenv_profile_resolution_default();
    const struct {
        const char *option;
        tirenv_profile *p, *other;
    } cases[] = {
        {"--cylinder 0.1173", tirenv_profile_half_cylinder(0.1173, res.cylinder_segments),
         tirenv_profile_half_cylinder(0.1173, res.cylinder_segments + 1)},
        {"--sine 0.0213,0.4519,1.5",
         tirenv_profile_sine(0.0213, 0.4519, 1.5, res.sine_points_per_period),
         tirenv_profile_sine(0.0213, 0.4519, 1.5, res.sine_points_per_period + 1)},
    };
    char path[] = "/tmp/tirenv_test_defaults_XXXXXX";
    const int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    char cli[1024], tir[1024];
    tirenv_test_shell_quote(TIRENV_CLI, cli, sizeof cli);
    tirenv_test_shell_quote(TIRENV_DATA_DIR "/tires/default.tir", tir, sizeof tir);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        char cmd[2560];
        snprintf(cmd, sizeof cmd,
                 "%s envelope --model point %s --load 10937 --tire %s -o %s 2>/dev/null", cli,
                 cases[i].option, tir, path);
        assert_int_equal(run(cmd), 0);
        size_t n;
        char **lines = read_lines(path, &n);
        assert_true(n > 1000);
        assert_int_equal(envelope_mismatches(cases[i].p, 10937, lines, n), 0);
        assert_true(envelope_mismatches(cases[i].other, 10937, lines, n) > 0);
        free_lines(lines, n);
        tirenv_profile_free(cases[i].p);
        tirenv_profile_free(cases[i].other);
    }
    remove(path);
}

/* tirenv ride --enveloping static with the point contact: its run starts, ends and samples
 * the ground on the library's span and grid, so the series' first columns (t, x_front,
 * w_front, w_rear, z) are tirenv_ride_run's on them. */
static void test_cli_ride_is_the_library_span(void **state)
{
    (void)state;
    const double V = 2.3;  /* m/s */
    char path[] = "/tmp/tirenv_test_defaults_XXXXXX", cmd[2560];
    const int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    char cli[1024], veh_arg[1024];
    snprintf(cmd, sizeof cmd,
             "%s ride --cleat 0.30,0.05 --speed %g --model point --enveloping static "
             "--vehicle %s -o %s >/dev/null 2>&1",
             tirenv_test_shell_quote(TIRENV_CLI, cli, sizeof cli), V,
             tirenv_test_shell_quote(TIRENV_DATA_DIR "/vehicles/tractor.veh", veh_arg,
                                     sizeof veh_arg), path);
    assert_int_equal(run(cmd), 0);
    size_t n_lines;
    char **lines = read_lines(path, &n_lines);

    tirenv_diag diag;
    tirenv_vehicle v = tirenv_vehicle_default();
    char veh[600];
    snprintf(veh, sizeof veh, "%s/vehicles/tractor.veh", TIRENV_DATA_DIR);
    assert_int_equal(tirenv_vehicle_read(veh, &v, &diag), TIRENV_OK);
    const tirenv_tire tire = tirenv_tire_default();  /* data/tires/default.tir's values */
    assert_int_equal(tirenv_vehicle_tires(&v, &tire, &tire, &diag), TIRENV_OK);
    tirenv_profile *p = tirenv_profile_cleat(0.30, 0.05);
    double first, last, x0;
    tirenv_profile_extent(p, &first, &last);
    const tirenv_ride_span span = tirenv_ride_span_default();
    tirenv_ride_settings s = tirenv_ride_default();
    s.speed = V;
    s.x_front0 = tirenv_ride_span_start(&span, first);
    s.duration = (tirenv_ride_span_end(&span, &v, last, V) - s.x_front0) / V;
    const size_t n = (size_t)tirenv_ride_span_grid(&span, &v, s.x_front0,
                                                  tirenv_ride_span_end(&span, &v, last, V), &x0);
    double *w = malloc(n * sizeof *w);
    const size_t n_samples = tirenv_ride_n_samples(&s);
    tirenv_ride_sample *out = malloc(n_samples * sizeof *out);
    assert_true(w && out);
    /* The point contact: the same input for both axles, whatever their loads. */
    assert_int_equal(tirenv_ride_effective(NULL, p, 1.0, x0, span.dx, n, w, &diag), 0);
    const tirenv_ride_track track = {.x0 = x0, .dx = span.dx, .n = n, .w = w};
    assert_int_equal(tirenv_ride_run(&v, &track, &track, &s, out, &diag), TIRENV_OK);

    assert_int_equal(n_lines, n_samples + 2);  /* a comment and the header first */
    size_t bad = 0;
    for (size_t k = 0; k < n_samples; ++k) {
        char row[512];
        const int len = snprintf(row, sizeof row, "%.9g,%.9g,%.9g,%.9g,%.9g,", out[k].t,
                                 out[k].x_front, out[k].w_front, out[k].w_rear, out[k].z);
        bad += strncmp(row, lines[k + 2], (size_t)len) != 0;
    }
    assert_int_equal(bad, 0);
    free(out);
    free(w);
    tirenv_profile_free(p);
    free_lines(lines, n_lines);
    remove(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_resolution_default),
        cmocka_unit_test(test_resolution_keeps_its_promise),
        cmocka_unit_test(test_positions_default),
        cmocka_unit_test(test_ride_span),
        cmocka_unit_test(test_cli_envelope_is_the_library_default),
        cmocka_unit_test(test_cli_ride_is_the_library_span),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
