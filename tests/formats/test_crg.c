/* The OpenCRG reader and writer: the ecosystem's sample files (ASAM's hand-made examples,
 * Chrono's binary half-round and Horstwalde), files the tests write in all four encodings,
 * windows of long roads, and malformed files.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/crg.h"
#include "tirenv/profile_file.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- helpers ------------------------------------------------------------------------- */

/* A sample file; the samples are part of the test set-up, so a missing one fails. */
static const char *sample(const char *name, char buf[600])
{
    snprintf(buf, 600, "%s/crg/%s", TIRENV_SAMPLES, name);
    struct stat st;
    if (stat(buf, &st) != 0) {
        print_error("sample file %s is missing (the samples are expected beside the "
                    "repository)\n", buf);
        fail();
    }
    return buf;
}

static tirenv_crg *open_ok(const char *path)
{
    tirenv_crg *c = NULL;
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const int status = tirenv_crg_open(path, &c, &d);
    if (status) {
        char line[1200];
        print_error("%s\n", tirenv_diag_format(&d, line, sizeof line));
    }
    assert_int_equal(status, TIRENV_OK);
    return c;
}

static tirenv_crg_track_spec spec_v(double v)
{
    tirenv_crg_track_spec s = tirenv_crg_track_default();
    s.v = v;
    return s;
}

static tirenv_profile *track_ok(const tirenv_crg *c, const tirenv_crg_track_spec *s)
{
    tirenv_profile *p = NULL;
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const int status = tirenv_crg_track(c, s, &p, &d);
    if (status) {
        char line[1200];
        print_error("%s\n", tirenv_diag_format(&d, line, sizeof line));
    }
    assert_int_equal(status, TIRENV_OK);
    assert_int_equal(tirenv_profile_size(p), tirenv_crg_rows(c));
    return p;
}

/* The height of the track at v at row i (a window of one row). */
static double z_at(const tirenv_crg *c, double v, size_t i)
{
    const tirenv_crg_track_spec s = spec_v(v);
    double u, z;
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const int status = tirenv_crg_track_rows(c, &s, i, 1, &u, &z, &d);
    if (status)
        print_error("%s\n", d.message);
    assert_int_equal(status, TIRENV_OK);
    assert_near(u, tirenv_crg_u_start(c) + (double)i * tirenv_crg_u_increment(c), 1e-12, 0);
    return z;
}

static void assert_same_tracks(const tirenv_profile *a, const tirenv_profile *b)
{
    assert_int_equal(tirenv_profile_size(a), tirenv_profile_size(b));
    for (size_t i = 0; i < tirenv_profile_size(a); i++) {
        assert_bits_equal(tirenv_profile_x(a)[i], tirenv_profile_x(b)[i]);
        assert_bits_equal(tirenv_profile_z(a)[i], tirenv_profile_z(b)[i]);
    }
}

/* ---- the hand-made examples ------------------------------------------------------------ */

/* Every readable hand-made example: its grid as its header and comments describe it. */
static void test_handmade_grids(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        tirenv_crg_encoding enc;
        size_t rows;
        double u_end, du;
        int curved, slope, bank;
    } cases[] = {
        {"handmade_straight.crg", TIRENV_CRG_LRFI, 23, 22, 1, 0, 0, 0},
        {"handmade_straight_minimalist.crg", TIRENV_CRG_LRFI, 23, 22, 1, 0, 0, 0},
        {"handmade_straight_double.crg", TIRENV_CRG_LDFI, 23, 22, 1, 0, 0, 0},
        {"handmade_vtest.crg", TIRENV_CRG_LRFI, 23, 22, 1, 0, 0, 0},
        {"handmade_curved.crg", TIRENV_CRG_LRFI, 23, 22, 1, 1, 0, 0},
        {"handmade_curved_minimalist.crg", TIRENV_CRG_LRFI, 23, 22, 1, 1, 0, 0},
        {"handmade_arc.crg", TIRENV_CRG_LRFI, 23, 88, 4, 1, 0, 0},
        {"handmade_circle.crg", TIRENV_CRG_LRFI, 25, 240, 10, 1, 0, 0},
        {"handmade_banked.crg", TIRENV_CRG_LRFI, 23, 22, 1, 0, 0, 1},
        {"handmade_sloped.crg", TIRENV_CRG_LRFI, 23, 22, 1, 0, 1, 0},
        {"handmade_sloped_opts.crg", TIRENV_CRG_LRFI, 23, 22, 1, 0, 1, 0},
        {"handmade_curved_banked_sloped.crg", TIRENV_CRG_LRFI, 23, 22, 1, 1, 1, 1},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char path[600];
        tirenv_crg *c = open_ok(sample(cases[k].name, path));
        print_message("%s\n", cases[k].name);
        assert_int_equal(tirenv_crg_encoding_of(c), cases[k].enc);
        assert_int_equal(tirenv_crg_rows(c), cases[k].rows);
        assert_near(tirenv_crg_u_start(c), 0, 0, 0);
        assert_near(tirenv_crg_u_end(c), cases[k].u_end, 1e-12, 0);
        assert_near(tirenv_crg_u_increment(c), cases[k].du, 0, 0);
        assert_int_equal(tirenv_crg_long_sections(c), 7);
        /* handmade_straight_minimalist states only V_INCREMENT: from v = 0, as OpenCRG */
        const double v0 = strcmp(cases[k].name, "handmade_straight_minimalist.crg") ? -1.5 : 0;
        assert_near(tirenv_crg_v(c, 0), v0, 1e-15, 0);
        assert_near(tirenv_crg_v(c, 6), v0 + 3, 1e-15, 0);
        assert_int_equal(tirenv_crg_is_curved(c), cases[k].curved);
        assert_int_equal(tirenv_crg_has_slope(c), cases[k].slope);
        assert_int_equal(tirenv_crg_has_banking(c), cases[k].bank);
        tirenv_crg_free(c);
    }
}

/* handmade_straight: a track on a long section is that column; between two it is their
 * linear interpolation (values read off the file). */
static void test_handmade_straight_heights(void **state)
{
    (void)state;
    char path[600];
    tirenv_crg *c = open_ok(sample("handmade_straight.crg", path));
    assert_near(tirenv_crg_v(c, 1), -1.0, 1e-15, 0);
    assert_near(tirenv_crg_v(c, 3), 0.0, 1e-15, 0);
    assert_near(z_at(c, 0, 1), 0.0111111, 1e-9, 0);
    assert_near(z_at(c, 0, 10), 0.0222222, 1e-9, 0);
    assert_near(z_at(c, 0, 19), 0.0333333, 1e-9, 0);
    assert_near(z_at(c, 1.0, 15), -0.0222222, 1e-9, 0);
    /* Row 12 has 0.0111111 at v = -1 and 0.0222222 at v = -0.5. */
    assert_near(z_at(c, -0.75, 11), 0.5 * (0.0111111 + 0.0222222), 1e-9, 0);
    /* Row 16 has -0.0222222 at v = 1 and -0.0333333 at v = 1.5; v = 1.2 is 0.4 of the way. */
    assert_near(z_at(c, 1.2, 15), 0.6 * -0.0222222 + 0.4 * -0.0333333, 1e-9, 0);
    const tirenv_crg_track_spec s = spec_v(0);
    tirenv_profile *p = track_ok(c, &s);
    for (size_t i = 0; i < 23; i++)
        assert_near(tirenv_profile_x(p)[i], (double)i, 1e-12, 0);
    tirenv_profile_free(p);
    tirenv_crg_free(c);
}

/* Rows 8 and 9 of handmade_straight miss their outer values: with GRID_NAN_MODE 0 a track
 * there is refused, naming the row; a NaN mode fills them (OpenCRG's GRID_NAN_MODE), and
 * the file, without a modifiers section, takes OpenCRG's default 2. */
static void test_handmade_nan_borders(void **state)
{
    (void)state;
    char path[600];
    tirenv_crg *c = open_ok(sample("handmade_straight.crg", path));
    tirenv_crg_track_spec s = spec_v(-1.5);
    tirenv_profile *p = track_ok(c, &s);
    assert_near(tirenv_profile_z(p)[7], 0.0111111, 1e-9, 0);
    assert_near(tirenv_profile_z(p)[8], 0.0111111, 1e-9, 0);
    tirenv_profile_free(p);
    p = NULL;
    s.grid_nan_mode = 0;
    tirenv_diag d;
    tirenv_diag_clear(&d);
    assert_int_equal(tirenv_crg_track(c, &s, &p, &d), TIRENV_ERANGE);
    assert_null(p);
    print_message("%s\n", d.message);
    assert_string_equal(d.field, "v");
    assert_non_null(strstr(d.message, "long section 1 (v = -1.5 m) at row 8 (u = 7 m)"));
    /* v = -1.25 needs v = -1.5 too; v = -1 does not. */
    s.v = -1.25;
    assert_int_equal(tirenv_crg_track(c, &s, &p, &d), TIRENV_ERANGE);
    s.v = -1.0; /* still mode 0, which refuses any missing value the track needs */
    p = track_ok(c, &s);
    assert_near(tirenv_profile_z(p)[8], 0.0111111, 1e-9, 0);
    tirenv_profile_free(p);
    /* Mode 2: the nearest valid value of the cross section (0.0111111 at v = -1 in both
     * rows); mode 1: zero. */
    s.v = -1.5;
    s.grid_nan_mode = 2;
    p = track_ok(c, &s);
    assert_near(tirenv_profile_z(p)[7], 0.0111111, 1e-9, 0);
    assert_near(tirenv_profile_z(p)[8], 0.0111111, 1e-9, 0);
    assert_near(tirenv_profile_z(p)[9], 0.0111111, 1e-9, 0);
    tirenv_profile_free(p);
    s.grid_nan_mode = 1;
    s.v = 1.25;
    p = track_ok(c, &s);
    assert_near(tirenv_profile_z(p)[7], 0.5 * 0.0222222, 1e-9, 0);
    assert_near(tirenv_profile_z(p)[8], 0.5 * (0.0111111 + 0.0222222), 1e-9, 0);
    tirenv_profile_free(p);
    tirenv_crg_free(c);
}

/* The minimalist files say they are "completely equivalent" to their commented versions, and
 * handmade_straight_double holds handmade_straight's numbers in LDFI. They are, 1.5 m apart:
 * the minimalist ones state only LONG_SECTION_V_INCREMENT, and OpenCRG's C API (which tirenv
 * follows) then puts the first long section at v = 0, where the commented ones say -1.5. */
static void test_handmade_equivalents(void **state)
{
    (void)state;
    static const char *const pairs[][2] = {
        {"handmade_straight.crg", "handmade_straight_minimalist.crg"},
        {"handmade_curved.crg", "handmade_curved_minimalist.crg"},
    };
    /* handmade_curved_minimalist names its long sections by v, so it lies where its twin does. */
    static const double shift[2] = {1.5, 0};
    for (size_t k = 0; k < 2; k++) {
        char pa[600], pb[600];
        tirenv_crg *a = open_ok(sample(pairs[k][0], pa)), *b = open_ok(sample(pairs[k][1], pb));
        assert_near(tirenv_crg_v(b, 0), -1.5 + shift[k], 1e-12, 0);
        assert_near(tirenv_crg_v(b, tirenv_crg_long_sections(b) - 1), 1.5 + shift[k], 1e-12, 0);
        for (double v = -1.5; v <= 1.5; v += 0.125) {
            tirenv_crg_track_spec s = spec_v(v), sb = spec_v(v + shift[k]);
            s.grid_nan_mode = sb.grid_nan_mode = 2;
            tirenv_profile *ta = track_ok(a, &s), *tb = track_ok(b, &sb);
            assert_same_tracks(ta, tb);
            tirenv_profile_free(ta);
            tirenv_profile_free(tb);
        }
        /* Without modifiers sections OpenCRG's defaults put the point (START_U,
         * LONG_SECTION_V_RIGHT) at the origin: v = -1.5 of the commented files, v = 0 of the
         * minimalist ones (no V_RIGHT: OpenCRG's loader takes 0, also for long sections at
         * given, unevenly spaced v). The straight twins then coincide on the ground (b's v is
         * a's plus 1.5), the curved ones lie 1.5 m apart, as OpenCRG places them. */
        const size_t n = tirenv_crg_rows(a);
        double xa[32], ya[32], xb[32], yb[32];
        assert_int_equal(tirenv_crg_refline(a, xa, ya, NULL, NULL), TIRENV_OK);
        assert_int_equal(tirenv_crg_refline(b, xb, yb, NULL, NULL), TIRENV_OK);
        for (size_t i = 0; i < n; i++) {
            assert_near(xa[i], xb[i], 1e-12, 0);
            assert_near(ya[i], yb[i] + 1.5, 1e-12, 0);
        }
        tirenv_crg_free(a);
        tirenv_crg_free(b);
    }
    /* LRFI 0.0111111 and LDFI 0.01111110000000000 are the same number. */
    char pa[600], pb[600];
    tirenv_crg *a = open_ok(sample("handmade_straight.crg", pa));
    tirenv_crg *b = open_ok(sample("handmade_straight_double.crg", pb));
    for (double v = -1.0; v <= 1.0; v += 0.25) {
        const tirenv_crg_track_spec s = spec_v(v);
        tirenv_profile *ta = track_ok(a, &s), *tb = track_ok(b, &s);
        assert_same_tracks(ta, tb);
        tirenv_profile_free(ta);
        tirenv_profile_free(tb);
    }
    tirenv_crg_free(a);
    tirenv_crg_free(b);
}

/* handmade_vtest: the same cross section in every row, 0, 0, 2.22, 3.33, 4.44, 5.55, 5.55 at
 * v = -1.5 ... 1.5. */
static void test_handmade_vtest(void **state)
{
    (void)state;
    char path[600];
    tirenv_crg *c = open_ok(sample("handmade_vtest.crg", path));
    static const struct { double v, z; } at[] = {
        {-1.5, 0}, {-1.25, 0}, {-0.75, 0.5 * 2.2222222}, {0, 3.3333333},
        {0.25, 0.5 * (3.3333333 + 4.4444444)}, {0.9, 0.2 * 4.4444444 + 0.8 * 5.5555555},
        {1.5, 5.5555555},
    };
    for (size_t k = 0; k < sizeof at / sizeof at[0]; k++) {
        const tirenv_crg_track_spec s = spec_v(at[k].v);
        tirenv_profile *p = track_ok(c, &s);
        for (size_t i = 0; i < 23; i++)
            assert_near(tirenv_profile_z(p)[i], at[k].z, 1e-9, 0);
        tirenv_profile_free(p);
    }
    tirenv_crg_free(c);
}

/* Banking adds b*v, slope adds the integrated reference line height: values worked out by
 * hand from the files' channels. */
static void test_handmade_banking_and_slope(void **state)
{
    (void)state;
    char path[600];
    /* Row 6 of handmade_banked: banking 0.044, 0.0111111 at v = -1.5, 0 and 1.5. */
    tirenv_crg *c = open_ok(sample("handmade_banked.crg", path));
    assert_near(z_at(c, 1.5, 5), 0.0111111 + 0.044 * 1.5, 1e-9, 0);
    assert_near(z_at(c, -1.5, 5), 0.0111111 - 0.044 * 1.5, 1e-9, 0);
    assert_near(z_at(c, 0, 5), 0.0111111, 1e-9, 0);
    assert_near(z_at(c, 0.5, 5), 0.5 * 0.0111111 + 0.044 * 0.5, 1e-9, 0);
    tirenv_crg_free(c);
    /* handmade_sloped: segment slopes 0, 0.011, ..., 0.11, 0.11, 0.099, ..., 0 (rows 1 to
     * 22), 1 m apart: the reference line rises 0.011*55 = 0.605 m by row 12 and 1.21 m by the
     * end; the grid adds 0.0222222 at row 12 and 0 at the end. The sum of 22 slopes is
     * off by rounding only (2.2e-16 measured here); 1e-12 leaves room for another order of
     * summation and still catches a slope missed or counted twice (0.011 m). */
    c = open_ok(sample("handmade_sloped.crg", path));
    assert_near(z_at(c, 0, 11), 0.605 + 0.0222222, 1e-12, 0);
    assert_near(z_at(c, 0, 22), 1.21, 1e-12, 0);
    assert_near(z_at(c, 0, 0), 0, 0, 0);
    tirenv_crg_free(c);
    /* handmade_curved_banked_sloped, row 6: slope sum 0.11, banking 0.044, grid 0.0111111. */
    c = open_ok(sample("handmade_curved_banked_sloped.crg", path));
    assert_near(z_at(c, 1.5, 5), 0.0111111 + 0.11 + 0.044 * 1.5, 1e-12, 0);
    assert_near(z_at(c, 0, 5), 0.0111111 + 0.11, 1e-12, 0);
    assert_near(z_at(c, 0, 22), 1.21, 1e-12, 0);
    tirenv_crg_free(c);
}

/* handmade_sloped_opts is handmade_sloped with BORDER_MODE_V = 2 (keep the last value):
 * the same tracks, and v beyond the road allowed; without the option it is refused. */
static void test_handmade_border_mode_v(void **state)
{
    (void)state;
    char pa[600], pb[600];
    tirenv_crg *a = open_ok(sample("handmade_sloped.crg", pa));
    tirenv_crg *b = open_ok(sample("handmade_sloped_opts.crg", pb));
    const tirenv_crg_track_spec s = spec_v(0.3), edge = spec_v(1.5), out = spec_v(2.0);
    tirenv_profile *ta = track_ok(a, &s), *tb = track_ok(b, &s);
    assert_same_tracks(ta, tb);
    tirenv_profile_free(ta);
    tirenv_profile_free(tb);
    ta = track_ok(b, &edge);
    tb = track_ok(b, &out);
    assert_same_tracks(ta, tb);
    tirenv_profile_free(ta);
    tirenv_profile_free(tb);
    tirenv_profile *p = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_crg_track(a, &out, &p, &d), TIRENV_ERANGE);
    assert_non_null(strstr(d.message, "beyond the road's long sections"));
    /* The caller may choose another mode: 1 sets zero, 3 repeats, 4 reflects. */
    tirenv_crg_track_spec m = spec_v(2.0);
    m.border_mode_v = 1;
    p = track_ok(a, &m);
    assert_near(tirenv_profile_z(p)[11], 0, 0, 0);
    tirenv_profile_free(p);
    m.border_mode_v = 3; /* 2.0 repeats as -1.0 (width 3 m) */
    p = track_ok(a, &m);
    assert_near(tirenv_profile_z(p)[11], z_at(a, -1.0, 11), 1e-15, 0);
    tirenv_profile_free(p);
    m.border_mode_v = 4; /* 2.0 reflects to 1.0 */
    p = track_ok(a, &m);
    assert_near(tirenv_profile_z(p)[11], z_at(a, 1.0, 11), 1e-15, 0);
    tirenv_profile_free(p);
    tirenv_crg_free(a);
    tirenv_crg_free(b);
}

/* The curved reference lines: every segment is u_increment long and has the heading of the
 * file's phi channel (handmade_arc: 0, 0.125, ... 1.0, then 2.125, ... 3.125). phi is the
 * file's value as read (exact here); the segments' directions from x and y are off by
 * rounding only (8.9e-16 rad measured), so 1e-14 rad. */
static void test_handmade_curved_reflines(void **state)
{
    (void)state;
    char path[600];
    tirenv_crg *c = open_ok(sample("handmade_arc.crg", path));
    const size_t n = tirenv_crg_rows(c);
    double x[32], y[32], phi[32];
    assert_int_equal(tirenv_crg_refline(c, x, y, phi, NULL), TIRENV_OK);
    /* OpenCRG's defaults move the start of its right edge (v = -1.5) to the origin. */
    assert_near(x[0], 0, 1e-15, 0);
    assert_near(y[0], 1.5, 1e-15, 0);
    for (size_t i = 1; i < n; i++) {
        const double expected = i <= 9 ? 0.125 * (double)(i - 1)
                                : i <= 18 ? 2.125 + 0.125 * (double)(i - 10) : 3.125;
        assert_near(phi[i], expected, 0, 0);
        assert_near(hypot(x[i] - x[i - 1], y[i] - y[i - 1]), 4.0, 1e-12, 0);
        assert_near(atan2(y[i] - y[i - 1], x[i] - x[i - 1]), expected, 1e-14, 0);
    }
    tirenv_crg_free(c);
}

/* Files tirenv refuses: a malformed number in handmade_platform's modifiers
 * ("2.000000000+e00"), and a file reference. */
static void test_handmade_refused(void **state)
{
    (void)state;
    char path[600];
    tirenv_crg *c = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_crg_open(sample("handmade_platform.crg", path), &c, &d),
                     TIRENV_EPARSE);
    assert_null(c);
    assert_string_equal(d.file, path);
    assert_int_equal(d.line, 35);
    assert_int_equal(d.column, 28);
    assert_string_equal(d.field, "GRID_NAN_MODE");
    assert_non_null(strstr(d.message, "unexpected '+e00' after the number 2.000000000"));
    assert_int_equal(tirenv_crg_open(sample("testOptionBorderMode.crg", path), &c, &d),
                     TIRENV_EPARSE);
    assert_int_equal(d.line, 27);
    assert_string_equal(d.field, "ROAD_CRG_FILE");
    assert_non_null(strstr(d.message, "file references are not supported"));
}

/* ---- Chrono's binary files -------------------------------------------------------------- */

/* A traverse half-round of 6 inches (0.1524 m) radius on a 1 cm grid: every non-zero height
 * lies on that circle, to float32 precision, and its top is within half a grid step of it. */
static void test_halfround(void **state)
{
    (void)state;
    char path[600];
    tirenv_crg *c = open_ok(sample("halfround_6in.crg", path));
    assert_int_equal(tirenv_crg_encoding_of(c), TIRENV_CRG_KRBI);
    assert_int_equal(tirenv_crg_rows(c), 10001);
    assert_int_equal(tirenv_crg_long_sections(c), 3);
    assert_near(tirenv_crg_u_increment(c), 0.01, 1e-15, 0);
    const double R = 6 * 0.0254;
    for (double v = -3; v <= 3; v += 1.5) {
        const tirenv_crg_track_spec s = spec_v(v);
        tirenv_profile *p = track_ok(c, &s);
        const double *u = tirenv_profile_x(p), *z = tirenv_profile_z(p);
        size_t first = 0, last = 0, top = 0;
        for (size_t i = 0; i < 10001; i++)
            if (z[i] > 0) {
                first = first ? first : i;
                last = i;
                top = z[i] > z[top] ? i : top;
            }
        /* The centre from the first non-zero height, then every height against it. */
        const double uc = u[first] + sqrt(R * R - z[first] * z[first]);
        print_message("v = %g: bump from u = %.2f to %.2f m, centre %.5f m, top %.6f m\n", v,
                      u[first], u[last], uc, z[top]);
        assert_near(uc, 50 + R, 1e-4, 0);
        for (size_t i = first; i <= last; i++) {
            const double d = u[i] - uc;
            assert_near(z[i], sqrt(R * R - d * d), 2e-5, 0);
        }
        assert_true(z[top] <= R && z[top] >= sqrt(R * R - 0.005 * 0.005));
        assert_near(u[last] - u[first], 2 * R, 0.02, 0);
        tirenv_profile_free(p);
    }
    tirenv_crg_free(c);
}

/* Horstwalde: 250 m, 45 long sections 0.1 m apart, binary, heights up to about 1.65 m; every
 * long section is a full track (no missing values). */
static void test_horstwalde(void **state)
{
    (void)state;
    char path[600];
    tirenv_crg *c = open_ok(sample("Horstwalde.crg", path));
    assert_int_equal(tirenv_crg_rows(c), 2503);
    assert_near(tirenv_crg_u_end(c), 250.2, 1e-9, 0);
    assert_int_equal(tirenv_crg_long_sections(c), 45);
    assert_near(tirenv_crg_v(c, 0), -2.2, 1e-12, 0);
    assert_near(tirenv_crg_v(c, 44), 2.2, 1e-12, 0);
    double zmax = -INFINITY, zmin = INFINITY;
    for (size_t j = 0; j < 45; j++) {
        const tirenv_crg_track_spec s = spec_v(tirenv_crg_v(c, j));
        tirenv_profile *p = track_ok(c, &s);
        for (size_t i = 0; i < 2503; i++) {
            zmax = fmax(zmax, tirenv_profile_z(p)[i]);
            zmin = fmin(zmin, tirenv_profile_z(p)[i]);
        }
        tirenv_profile_free(p);
    }
    print_message("Horstwalde heights %.4f to %.4f m\n", zmin, zmax);
    assert_near(zmax, 1.8, 1e-6, 0);
    assert_near(zmin, 0, 0, 0);
    /* The whole grid at once equals the tracks. */
    double *g = malloc(2503 * 45 * sizeof *g);
    assert_int_equal(tirenv_crg_grid_rows(c, 0, 2503, g, NULL), TIRENV_OK);
    const tirenv_crg_track_spec s = spec_v(tirenv_crg_v(c, 30));
    tirenv_profile *p = track_ok(c, &s);
    for (size_t i = 0; i < 2503; i++)
        assert_bits_equal(g[i * 45 + 30], tirenv_profile_z(p)[i]);
    tirenv_profile_free(p);
    free(g);
    tirenv_crg_free(c);
}

/* ---- written files --------------------------------------------------------------------- */

/* A road with high-entropy heights: z(u, v) = 0.0371 sin(2.3 u) + 0.0113 v u - 0.0047 v^2. */
static double road_z(double u, double v)
{
    return 0.0371 * sin(2.3 * u) + 0.0113 * v * u - 0.0047 * v * v;
}

static void write_road(const char *path, tirenv_crg_encoding enc, size_t rows, size_t nv,
                       const double v[], int nan_corner)
{
    const tirenv_crg_layout l = {.encoding = enc, .u_start = -1.37, .u_increment = 0.013,
                                 .rows = rows, .long_sections = nv, .v = v,
                                 .comment = "a test road"};
    tirenv_crg_writer *w = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_crg_writer_open(path, &l, &w, &d), TIRENV_OK);
    double z[64];
    for (size_t i = 0; i < rows; i++) {
        for (size_t j = 0; j < nv; j++)
            z[j] = road_z(-1.37 + (double)i * 0.013, v[j]);
        if (nan_corner && i % 7 == 3)
            z[0] = NAN;
        assert_int_equal(tirenv_crg_writer_row(w, z, &d), TIRENV_OK);
    }
    assert_int_equal(tirenv_crg_writer_commit(w, &d), TIRENV_OK);
}

/* What a written value reads back as: KDBI exact, KRBI a float, the text encodings to their
 * digits. */
static double stored(tirenv_crg_encoding enc, double z)
{
    return enc == TIRENV_CRG_KRBI ? (double)(float)z : z;
}

static double tolerance(tirenv_crg_encoding enc)
{
    return enc == TIRENV_CRG_LRFI ? 5e-8 : enc == TIRENV_CRG_LDFI ? 1e-17 : 0;
}

/* Each encoding, written and read back, with row lengths that fill records exactly, wrap
 * over several records, or leave NaN padding; NaN at a border survives. */
static void test_write_read_encodings(void **state)
{
    tirenv_test_dir *fx = *state;
    static const size_t widths[] = {2, 3, 4, 9, 25};
    for (int enc = TIRENV_CRG_LRFI; enc <= TIRENV_CRG_KDBI; enc++)
        for (size_t k = 0; k < sizeof widths / sizeof widths[0]; k++) {
            const size_t nv = widths[k], rows = 37 + k;
            double v[32];
            for (size_t j = 0; j < nv; j++)
                v[j] = -0.61 + 0.173 * (double)j;
            char path[600], name[32];
            snprintf(name, sizeof name, "w%d_%zu.crg", enc, nv);
            tirenv_test_path(fx, name, path);
            write_road(path, (tirenv_crg_encoding)enc, rows, nv, v, nv > 2);
            tirenv_crg *c = open_ok(path);
            assert_int_equal(tirenv_crg_encoding_of(c), enc);
            assert_int_equal(tirenv_crg_rows(c), rows);
            assert_int_equal(tirenv_crg_long_sections(c), nv);
            for (size_t j = 0; j < nv; j++)
                assert_bits_equal(tirenv_crg_v(c, j), v[j]);
            double *g = malloc(rows * nv * sizeof *g);
            assert_int_equal(tirenv_crg_grid_rows(c, 0, rows, g, NULL), TIRENV_OK);
            for (size_t i = 0; i < rows; i++)
                for (size_t j = 0; j < nv; j++) {
                    const double want = road_z(-1.37 + (double)i * 0.013, v[j]);
                    if (nv > 2 && j == 0 && i % 7 == 3)
                        assert_true(isnan(g[i * nv + j]));
                    else
                        assert_near(g[i * nv + j], stored((tirenv_crg_encoding)enc, want),
                                    tolerance((tirenv_crg_encoding)enc), 0);
                }
            free(g);
            /* A track between the first two sections needs the NaN; one beside it not. */
            tirenv_crg_track_spec s = spec_v(0.5 * (v[0] + v[1]));
            tirenv_profile *p = NULL;
            assert_int_equal(tirenv_crg_track(c, &s, &p, NULL),
                             nv > 2 ? TIRENV_ERANGE : TIRENV_OK);
            tirenv_profile_free(p);
            s.v = v[1];
            p = track_ok(c, &s);
            tirenv_profile_free(p);
            tirenv_crg_free(c);
            unlink(path);
        }
}

/* Windows of a long road (text: past several checkpoints) equal the whole track, and so does
 * the block-by-block reader. */
static void test_windows(void **state)
{
    tirenv_test_dir *fx = *state;
    const double v[3] = {-0.4, 0.1, 0.45};
    for (int enc = TIRENV_CRG_LRFI; enc <= TIRENV_CRG_KDBI; enc += 2) {
        char path[600];
        tirenv_test_path(fx, enc == TIRENV_CRG_LRFI ? "long.crg" : "long-bin.crg", path);
        write_road(path, (tirenv_crg_encoding)enc, 5003, 3, v, 0);
        tirenv_crg *c = open_ok(path);
        const tirenv_crg_track_spec s = spec_v(0.2731);
        tirenv_profile *whole = track_ok(c, &s);
        const double *zw = tirenv_profile_z(whole), *uw = tirenv_profile_x(whole);
        static const size_t windows[][2] = {{0, 5003}, {0, 1}, {1023, 3}, {1024, 1}, {2047, 1100},
                                            {4990, 13}, {5002, 1}, {3333, 0}};
        for (size_t k = 0; k < sizeof windows / sizeof windows[0]; k++) {
            const size_t first = windows[k][0], n = windows[k][1];
            double u[5003], z[5003];
            assert_int_equal(tirenv_crg_track_rows(c, &s, first, n, u, z, NULL), TIRENV_OK);
            for (size_t i = 0; i < n; i++) {
                assert_bits_equal(u[i], uw[first + i]);
                assert_bits_equal(z[i], zw[first + i]);
            }
        }
        double u[2], z[2];
        assert_int_equal(tirenv_crg_track_rows(c, &s, 5000, 4, u, z, NULL), TIRENV_EINVAL);
        assert_int_equal(tirenv_crg_row_at(c, -5), 0);
        assert_int_equal(tirenv_crg_row_at(c, 1e9), 5002);
        assert_int_equal(tirenv_crg_row_at(c, uw[2100] + 0.001), 2100);
        tirenv_crg_track_reader *r;
        assert_int_equal(tirenv_crg_track_reader_open(c, &s, &r, NULL), TIRENV_OK);
        size_t i = 0;
        double ur, zr;
        int got;
        while (tirenv_crg_track_reader_next(r, &ur, &zr, &got, NULL) == TIRENV_OK && got) {
            assert_true(i < 5003);
            assert_bits_equal(ur, uw[i]);
            assert_bits_equal(zr, zw[i]);
            i++;
        }
        assert_int_equal(i, 5003);
        tirenv_crg_track_reader_free(r);
        tirenv_profile_free(whole);
        tirenv_crg_free(c);
    }
}

/* A profile written as a CRG (two equal long sections) reads back as itself: KDBI exactly,
 * and CRG -> CSV -> CRG gives the same heights (the sample Horstwalde, binary floats). */
static void test_round_trips(void **state)
{
    tirenv_test_dir *fx = *state;
    char src[600], csv[600], crg[600], csv2[600];
    tirenv_crg *h = open_ok(sample("Horstwalde.crg", src));
    const double v38 = tirenv_crg_v(h, 38); /* on a long section: float32 heights */
    tirenv_crg_free(h);
    tirenv_test_path(fx, "h.csv", csv);
    tirenv_test_path(fx, "h.crg", crg);
    tirenv_test_path(fx, "h2.csv", csv2);
    for (int enc = TIRENV_CRG_LRFI; enc <= TIRENV_CRG_KDBI; enc++) {
        tirenv_profile_source in = tirenv_profile_source_default();
        in.crg.v = v38;
        tirenv_profile *a = NULL, *b = NULL;
        tirenv_diag d;
        assert_int_equal(tirenv_profile_read_file(src, &in, &a, &d), TIRENV_OK);
        assert_int_equal(tirenv_profile_write_csv(csv, a, "test", &d), TIRENV_OK);
        tirenv_profile *from_csv = NULL;
        assert_int_equal(tirenv_profile_read_file(csv, NULL, &from_csv, &d), TIRENV_OK);
        assert_same_tracks(a, from_csv);
        tirenv_profile_write_options w = tirenv_profile_write_default();
        w.crg_encoding = (tirenv_crg_encoding)enc;
        assert_int_equal(tirenv_profile_write_file(crg, from_csv, &w, &d), TIRENV_OK);
        tirenv_profile_format f;
        assert_int_equal(tirenv_profile_detect(crg, &f, &d), TIRENV_OK);
        assert_int_equal(f, TIRENV_PROFILE_CRG);
        /* Any v across the written road gives the profile. */
        in.crg.v = 0.2;
        assert_int_equal(tirenv_profile_read_file(crg, &in, &b, &d), TIRENV_OK);
        assert_int_equal(tirenv_profile_size(b), tirenv_profile_size(a));
        for (size_t i = 0; i < tirenv_profile_size(a); i++) {
            assert_near(tirenv_profile_x(b)[i], tirenv_profile_x(a)[i], 1e-12, 0);
            /* Horstwalde's floats are exact in KRBI too. */
            assert_near(tirenv_profile_z(b)[i], tirenv_profile_z(a)[i],
                        tolerance((tirenv_crg_encoding)enc), 0);
        }
        /* And back to CSV: the same heights to the written precision. */
        assert_int_equal(tirenv_profile_write_csv(csv2, b, NULL, &d), TIRENV_OK);
        tirenv_profile *c = NULL;
        assert_int_equal(tirenv_profile_read_file(csv2, NULL, &c, &d), TIRENV_OK);
        assert_same_tracks(b, c);
        tirenv_profile_free(a);
        tirenv_profile_free(b);
        tirenv_profile_free(c);
        tirenv_profile_free(from_csv);
    }
}

/* A reference line of constant curvature: headings dphi apart on chords of du. Its vertices
 * lie on the circle of radius du / (2 sin(dphi/2)), the line's length (u's range) is the sum
 * of its chords, and the circle's arc through them is longer by (dphi/2)/sin(dphi/2). */
static void test_curved_refline_circle(void **state)
{
    tirenv_test_dir *fx = *state;
    const double du = 0.7, dphi = 0.0913;
    const size_t n = 41;
    char text[8192];
    int k = snprintf(text, sizeof text,
                     "$CT\ncircle\n$\n$ROAD_CRG\nREFERENCE_LINE_INCREMENT = 0.7\n"
                     "REFERENCE_LINE_START_X = 3.1\nREFERENCE_LINE_START_Y = -2.2\n"
                     "LONG_SECTION_V_RIGHT = -1\nLONG_SECTION_V_LEFT = 1\n$\n$ROAD_CRG_MODS\n$\n"
                     "$KD_DEFINITION\n#:LDFI\nD:reference line phi,rad\nD:long section 1,m\n"
                     "D:long section 2,m\n$\n$$$$\n");
    for (size_t i = 0; i < n; i++)
        k += snprintf(text + k, sizeof text - (size_t)k, "%20.16f%20.16f%20.16f\n",
                      i ? (double)i * dphi : 0.0, 0.01, 0.02);
    char path[600];
    tirenv_test_write_text(tirenv_test_path(fx, "circle.crg", path), text);
    tirenv_crg *c = open_ok(path);
    double x[41], y[41];
    assert_int_equal(tirenv_crg_refline(c, x, y, NULL, NULL), TIRENV_OK);
    const double R = du / (2 * sin(dphi / 2));
    /* The first chord has heading dphi; the centre is R from its middle, to the left. */
    const double mx = 0.5 * (x[0] + x[1]), my = 0.5 * (y[0] + y[1]);
    const double h = R * cos(dphi / 2);
    const double cx = mx - h * sin(dphi), cy = my + h * cos(dphi);
    double chords = 0;
    for (size_t i = 0; i < n; i++) {
        assert_near(hypot(x[i] - cx, y[i] - cy), R, 1e-9, 0);
        if (i)
            chords += hypot(x[i] - x[i - 1], y[i] - y[i - 1]);
    }
    assert_near(x[0], 3.1, 0, 0);
    assert_near(y[0], -2.2, 0, 0);
    const double length = tirenv_crg_u_end(c) - tirenv_crg_u_start(c);
    assert_near(chords, length, 1e-12, 0);
    assert_near(length, (double)(n - 1) * 2 * R * sin(dphi / 2), 1e-12, 0);
    const double arc = R * dphi * (double)(n - 1);
    assert_near(arc / length, (dphi / 2) / sin(dphi / 2), 1e-12, 0);
    /* The heights do not depend on the curvature: the track's abscissa is u. */
    assert_near(z_at(c, 0, 17), 0.015, 1e-15, 0);
    tirenv_crg_free(c);
}

/* Modifiers and options tirenv applies: NaN filled (mode and offset), the grid scaled, the
 * heights shifted, smoothing towards the reference line at the start. */
static void test_mods_and_opts(void **state)
{
    tirenv_test_dir *fx = *state;
    static const char head[] =
        "* a comment line\n$CT                ! comment text\nmods\n$\n"
        "$ROAD_CRG\nREFERENCE_LINE_INCREMENT = 1.0  ! 1 m\nREFERENCE_LINE_START_Z = 0.5\n"
        "REFERENCE_LINE_OFFSET_Z = 0.25\nLONG_SECTION_V_RIGHT = -1\nLONG_SECTION_V_LEFT = 1\n"
        "LONG_SECTION_V_INCREMENT = 1\n$\n";
    static const char kd[] = "$KD_DEFINITION\n#:LRFI\nU:reference line u,m,0,1\n"
                             "D:long section 1,m\nD:long section 2,m\nD:long section 3,m\n$\n";
    static const char data[] = "$$$$\n *missing* 0.0200000 0.0300000\n"
                               " 0.0400000 0.0500000 0.0600000\n"
                               " 0.0700000 0.0800000 *missing*\n"
                               " 0.1000000 0.1100000 0.1200000\n";
    static const struct {
        const char *sections;
        double v;
        double z[4];
    } cases[] = {
        /* an empty modifiers section: the offsets only (0.5 + 0.25) */
        {"$ROAD_CRG_MODS\n$\n", 0, {0.77, 0.80, 0.83, 0.86}},
        /* none: OpenCRG's defaults, GRID_NAN_MODE 2 and the road's height 0 at (START_U,
         * LONG_SECTION_V_RIGHT), where row 1's missing value takes 0.02 (+ 0.75) */
        {"", 0, {0.0, 0.03, 0.06, 0.09}},
        {"$ROAD_CRG_MODS\nGRID_NAN_MODE = 2\nGRID_NAN_OFFSET = 0.001\n$\n", -1,
         {0.771, 0.79, 0.82, 0.85}},
        {"$ROAD_CRG_MODS\nGRID_NAN_MODE = 1\n$\n", 1, {0.78, 0.81, 0.75, 0.87}},
        {"$ROAD_CRG_MODS\nSCALE_Z_GRID = 2\nREFLINE_OFFSET_Z = -0.75\n$\n", 0,
         {0.04, 0.10, 0.16, 0.22}},
        {"$ROAD_CRG_MODS\n$\n$ROAD_CRG_OPTS\nBORDER_SMOOTH_UBEG = 2\nLOG_EVAL = 20\n"
         "LOG_EVAL = 20\n$\n", 0,
         {0.75, 0.775, 0.83, 0.86}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char text[2048], path[600];
        snprintf(text, sizeof text, "%s%s%s%s", head, cases[k].sections, kd, data);
        tirenv_test_write_text(tirenv_test_path(fx, "mods.crg", path), text);
        tirenv_crg *c = open_ok(path);
        const tirenv_crg_track_spec s = spec_v(cases[k].v);
        tirenv_profile *p = track_ok(c, &s);
        for (size_t i = 0; i < 4; i++)
            assert_near(tirenv_profile_z(p)[i], cases[k].z[i], 1e-12, 0);
        tirenv_profile_free(p);
        tirenv_crg_free(c);
    }
}

/* Placement by reference point (REFPOINT_*), as OpenCRG applies it: the road turned about its
 * point (u_ref, v_ref) so that the reference line's heading there is REFPOINT_PHI, moved so
 * that the point is at (REFPOINT_X, _Y), its heights shifted so that the road's height there
 * is REFPOINT_Z; without a modifiers section, OpenCRG's defaults (all 0 at START_U and
 * LONG_SECTION_V_RIGHT). Known answers worked out by hand for a straight road at x = 2.25,
 * y = 1.5, heading 0.3, 0.4 m high, long sections at v = -1 and 1 holding 0.01 i and 0.02 i. */
static void test_refpoint(void **state)
{
    tirenv_test_dir *fx = *state;
    static const char head[] =
        "$CT\nplaced\n$\n$ROAD_CRG\nREFERENCE_LINE_INCREMENT = 1\n"
        "REFERENCE_LINE_START_X = 2.25\nREFERENCE_LINE_START_Y = 1.5\n"
        "REFERENCE_LINE_START_PHI = 0.3\nREFERENCE_LINE_END_PHI = 0.3\n"
        "REFERENCE_LINE_START_Z = 0.4\nLONG_SECTION_V_RIGHT = -1\nLONG_SECTION_V_LEFT = 1\n$\n";
    static const char tail[] = "$KD_DEFINITION\n#:LRFI\nD:long section 1,m\n"
                               "D:long section 2,m\n$\n$$$$\n"
                               " 0.0000000 0.0000000\n 0.0100000 0.0200000\n"
                               " 0.0200000 0.0400000\n 0.0300000 0.0600000\n";
    static const struct {
        const char *mods;
        double u_ref, x_ref, y_ref, phi_ref; /* the reference point and where it goes */
        double v_ref;
        double dz;                           /* the heights' shift, m */
    } cases[] = {
        /* REFPOINT_U = 2 on the reference line; z there 0.4 + 0.03, to 1.25 */
        {"$ROAD_CRG_MODS\nREFPOINT_U = 2\nREFPOINT_V = 0\nREFPOINT_X = 10\nREFPOINT_Y = -4\n"
         "REFPOINT_Z = 1.25\nREFPOINT_PHI = -0.5\n$\n", 2, 10, -4, -0.5, 0, 1.25 - 0.43},
        /* the same point by fraction (2 of 3 m) and offset v = -1 + 0.75 * 2 - 0.5 */
        {"$ROAD_CRG_MODS\nREFPOINT_U_FRACTION = 0.5\nREFPOINT_U_OFFSET = 0.5\n"
         "REFPOINT_V_FRACTION = 0.75\nREFPOINT_V_OFFSET = -0.5\nREFPOINT_X = 10\n"
         "REFPOINT_Y = -4\nREFPOINT_Z = 1.25\nREFPOINT_PHI = -0.5\n$\n", 2, 10, -4, -0.5, 0,
         1.25 - 0.43},
        /* before the road's start: the line goes on straight, the height is the first row's */
        {"$ROAD_CRG_MODS\nREFPOINT_U = -2\nREFPOINT_X = 10\nREFPOINT_Y = -4\n"
         "REFPOINT_Z = 1.25\nREFPOINT_PHI = -0.5\nREFPOINT_V = 0\n$\n", -2, 10, -4, -0.5, 0,
         1.25 - 0.4},
        /* no modifiers section: OpenCRG's defaults; z at (0, -1) is 0.4 */
        {"", 0, 0, 0, 0, -1, -0.4},
        /* an empty one: no placement at all */
        {"$ROAD_CRG_MODS\n$\n", 0, 2.25, 1.5, 0.3, 0, 0},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char text[2048], path[600];
        snprintf(text, sizeof text, "%s%s%s", head, cases[k].mods, tail);
        tirenv_test_write_text(tirenv_test_path(fx, "placed.crg", path), text);
        tirenv_crg *c = open_ok(path);
        double x[4], y[4], phi[4];
        assert_int_equal(tirenv_crg_refline(c, x, y, phi, NULL), TIRENV_OK);
        const double a = cases[k].phi_ref, vr = cases[k].v_ref;
        /* The point (u_ref, v_ref) is at (x_ref, y_ref): the line runs through it at a.
         * Tolerances: positions within 15 m of the origin, each a rotation (cos, sin within
         * 1 ulp) and a translation, a handful of roundings of 2e-15 m, so about 1e-14 m;
         * 1e-12 m leaves a factor 100. The heading is REFPOINT_PHI plus the file's heading
         * less its own, two roundings of angles below 1 rad: 2.2e-16, within 1e-15. Heights
         * below 2 m, the file's plus one shift: a few roundings of 4.4e-16 m, within
         * 1e-12 m. */
        for (size_t i = 0; i < 4; i++) {
            const double s_u = (double)i - cases[k].u_ref;
            assert_near(x[i], cases[k].x_ref + s_u * cos(a) + vr * sin(a), 1e-12, 0);
            assert_near(y[i], cases[k].y_ref + s_u * sin(a) - vr * cos(a), 1e-12, 0);
            assert_near(phi[i], a, 1e-15, 0);
        }
        for (size_t i = 0; i < 4; i++) {
            assert_near(z_at(c, 1, i), 0.4 + 0.02 * (double)i + cases[k].dz, 1e-12, 0);
            assert_near(z_at(c, 0, i), 0.4 + 0.015 * (double)i + cases[k].dz, 1e-12, 0);
        }
        tirenv_crg_free(c);
    }
    /* What OpenCRG's check refuses, refused naming the line and the modifier. */
    static const struct {
        const char *mods;
        size_t line;
        const char *field, *says;
    } refused[] = {
        {"$ROAD_CRG_MODS\nREFPOINT_U = 1\nREFPOINT_U_FRACTION = 0.5\n$\n", 16,
         "REFPOINT_U_FRACTION", "with REFPOINT_U (line 15)"},
        {"$ROAD_CRG_MODS\nREFPOINT_V_FRACTION = 0.5\nREFPOINT_V = 1\n$\n", 16, "REFPOINT_V",
         "OpenCRG refuses both"},
        {"$ROAD_CRG_MODS\nREFPOINT_X = 1\nREFLINE_OFFSET_Y = 2\n$\n", 16, "REFLINE_OFFSET_Y",
         "both by offset and by reference point"},
        {"$ROAD_CRG_MODS\nSCALE_WIDTH = 2\n$\n", 15, "SCALE_WIDTH", "not supported"},
    };
    for (size_t k = 0; k < sizeof refused / sizeof refused[0]; k++) {
        char text[2048], path[600];
        snprintf(text, sizeof text, "%s%s%s", head, refused[k].mods, tail);
        tirenv_test_write_text(tirenv_test_path(fx, "placed.crg", path), text);
        tirenv_crg *c = NULL;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        assert_int_equal(tirenv_crg_open(path, &c, &d), TIRENV_EPARSE);
        assert_null(c);
        print_message("%s:%zu: %s: %s\n", d.file, d.line, d.field, d.message);
        assert_int_equal(d.line, refused[k].line);
        assert_string_equal(d.field, refused[k].field);
        assert_non_null(strstr(d.message, refused[k].says));
    }
}

/* ---- malformed files -------------------------------------------------------------------- */

static const char base[] =
    "$CT\n"                                   /* 1 */
    "a small road\n"                          /* 2 */
    "$\n"                                     /* 3 */
    "$ROAD_CRG\n"                             /* 4 */
    "REFERENCE_LINE_INCREMENT = 0.5\n"        /* 5 */
    "REFERENCE_LINE_END_U = 1.5\n"            /* 6 */
    "LONG_SECTION_V_RIGHT = -1\n"             /* 7 */
    "LONG_SECTION_V_LEFT = 1\n"               /* 8 */
    "LONG_SECTION_V_INCREMENT = 1\n"          /* 9 */
    "$\n"                                     /* 10 */
    "$KD_DEFINITION\n"                        /* 11 */
    "#:LRFI\n"                                /* 12 */
    "D:long section 1,m\n"                    /* 13 */
    "D:long section 2,m\n"                    /* 14 */
    "D:long section 3,m\n"                    /* 15 */
    "$\n"                                     /* 16 */
    "$$$$\n"                                  /* 17 */
    " 0.0100000 0.0200000 0.0300000\n"        /* 18 */
    " 0.0400000 0.0500000 0.0600000\n"        /* 19 */
    " 0.0700000 0.0800000 0.0900000\n"        /* 20 */
    " 0.1000000 0.1100000 0.1200000\n";       /* 21 */

typedef struct {
    const char *find, *replace;   /* the change to base */
    int status;
    size_t line, column;          /* column 0: not checked */
    const char *field, *says;
} malformed;

static const malformed bad[] = {
    /* the encoding */
    {"#:LRFI", "#:XRBI", TIRENV_EPARSE, 12, 3, "#:", "unknown data format 'XRBI'; expected "
     "LRFI, LDFI, KRBI or KDBI"},
    {"#:LRFI\n", "#:LRFI\n#:LDFI\n", TIRENV_EPARSE, 13, 0, "#:", "data format given twice"},
    /* header keys */
    {"= 0.5\n", "= 0.5x\n", TIRENV_EPARSE, 5, 31, "REFERENCE_LINE_INCREMENT",
     "unexpected 'x' after the number 0.5"},
    {"= 0.5\n", "= 0.5 x\n", TIRENV_EPARSE, 5, 32, "REFERENCE_LINE_INCREMENT",
     "unexpected 'x' after the number 0.5"}, /* the column of the junk, not of the blank */
    {"= 0.5\n", "= nan\n", TIRENV_EPARSE, 5, 28, "REFERENCE_LINE_INCREMENT",
     "expected a finite number"},
    {"= 0.5\n", "= -0.5\n", TIRENV_EPARSE, 5, 0, "REFERENCE_LINE_INCREMENT",
     "expected a positive length"},
    {"REFERENCE_LINE_INCREMENT = 0.5\n", "", TIRENV_EPARSE, 4, 0, "REFERENCE_LINE_INCREMENT",
     "missing in $ROAD_CRG"},
    {"REFERENCE_LINE_END_U = 1.5\n", "REFERENCE_LINE_END_U = 1.5\nREFERENCE_LINE_END_U = 2\n",
     TIRENV_EPARSE, 7, 0, "REFERENCE_LINE_END_U", "set twice"},
    {"REFERENCE_LINE_END_U", "REFERENCE_LINE_FOO", TIRENV_EPARSE, 6, 1, "REFERENCE_LINE_FOO",
     "unknown key in $ROAD_CRG"},
    {"REFERENCE_LINE_END_U = 1.5", "REFERENCE_LINE_END_U 1.5", TIRENV_EPARSE, 6, 1,
     "REFERENCE_LINE_END_U", "missing '='"},
    {"= 1.5\n", "= 2\n", TIRENV_EPARSE, 6, 0, "REFERENCE_LINE_END_U",
     "means 5 rows from u = 0 every 0.5 m, but the road data has 4 rows"},
    {"= 1.5\n", "= 1.7\n", TIRENV_EPARSE, 6, 0, "REFERENCE_LINE_END_U",
     "expected a whole number"},
    /* a row count of 301 digits took the message, its reason cut off */
    {"= 1.5\n", "= 1e300\n", TIRENV_EPARSE, 6, 0, "REFERENCE_LINE_END_U",
     "means 2e+300 rows from u = 0 every 0.5 m, but the road data has 4 rows (truncated"},
    {"LONG_SECTION_V_LEFT = 1\n", "LONG_SECTION_V_LEFT = 2\n", TIRENV_EPARSE, 8, 0,
     "LONG_SECTION_V_LEFT", "long sections end at v = 1, not at 2"},
    /* lateral positions beyond a road's 1e9 m: +-1e308 spanned an infinite width and was
     * refused as the reference point's, "REFPOINT: (u, v) = (0, -nan)" */
    {"LONG_SECTION_V_RIGHT = -1\nLONG_SECTION_V_LEFT = 1\nLONG_SECTION_V_INCREMENT = 1\n",
     "LONG_SECTION_V_RIGHT = -1e308\nLONG_SECTION_V_LEFT = 1e308\n", TIRENV_EPARSE, 7, 0,
     "LONG_SECTION_V_RIGHT", "-1e+308 m is beyond +-1e+09 m"},
    {"LONG_SECTION_V_INCREMENT = 1\n", "LONG_SECTION_V_INCREMENT = 1e300\n", TIRENV_EPARSE, 8,
     0, "LONG_SECTION_V_LEFT", "long sections end at v"},
    {"LONG_SECTION_V_RIGHT = -1\nLONG_SECTION_V_LEFT = 1\nLONG_SECTION_V_INCREMENT = 1\n",
     "LONG_SECTION_V_INCREMENT = 1e300\n", TIRENV_EPARSE, 12, 0, "D",
     "long section 2 lies at v = 1.0000000000000001e+300 m (from LONG_SECTION_V_RIGHT"},
    {"LONG_SECTION_V_RIGHT = -1\nLONG_SECTION_V_LEFT = 1\nLONG_SECTION_V_INCREMENT = 1\n$\n"
     "$KD_DEFINITION\n#:LRFI\nD:long section 1,m\nD:long section 2,m\nD:long section 3,m",
     "$\n$KD_DEFINITION\n#:LRFI\nD:long section at v = -1,m\nD:long section at v = 0,m\n"
     "D:long section at v = 2e9,m", TIRENV_EPARSE, 12, 0, "D",
     "long section 3 lies at v = 2000000000 m, beyond +-1e+09 m"},
    {"REFERENCE_LINE_END_U = 1.5\n", "REFERENCE_LINE_END_U = 1.5\nREFERENCE_LINE_END_X = 1.6\n",
     TIRENV_EPARSE, 7, 0, "REFERENCE_LINE_END_X", "integrated from its start gives 1.5"},
    {"REFERENCE_LINE_END_U = 1.5\n", "REFERENCE_LINE_END_U = 1.5\nREFERENCE_LINE_END_PHI = 1\n",
     TIRENV_EPARSE, 7, 0, "REFERENCE_LINE_END_PHI", "without a heading channel"},
    {"REFERENCE_LINE_END_U = 1.5\n", "REFERENCE_LINE_END_U = 1.5\nREFERENCE_LINE_END_S = 0.1\n",
     TIRENV_EPARSE, 7, 0, "REFERENCE_LINE_END_S", "without a slope channel"},
    {"REFERENCE_LINE_END_U = 1.5\n", "REFERENCE_LINE_END_U = 1.5\nREFERENCE_LINE_START_S = "
     "0.1\nREFERENCE_LINE_END_Z = 0.1\n", TIRENV_EPARSE, 8, 0, "REFERENCE_LINE_END_Z",
     "0.10000000000000001, but REFERENCE_LINE_START_Z and _START_S gives 0.15"},
    /* sections */
    {"$ROAD_CRG\n", "$ROAD_CRGX\n", TIRENV_EPARSE, 4, 2, "ROAD_CRGX", "unknown section"},
    {"$\n$KD", "$\n$CT\n$\n$KD", TIRENV_EPARSE, 11, 2, "CT", "section given twice"},
    {"$\n$KD", "$\n$ROAD_CRG_FILE\n/x.crg\n$\n$KD", TIRENV_EPARSE, 11, 2, "ROAD_CRG_FILE",
     "file references are not supported"},
    {"$\n$KD", "$\n$ROAD_CRG_MODS\nSCALE_LENGTH = 2\n$\n$KD", TIRENV_EPARSE, 12, 1,
     "SCALE_LENGTH", "modifier not supported"},
    {"$\n$KD", "$\n$ROAD_CRG_MODS\nGRID_NAN_MODE = 3\n$\n$KD", TIRENV_EPARSE, 12, 17,
     "GRID_NAN_MODE", "expected 0, 1 or 2"},
    {"$\n$KD", "$\n$ROAD_CRG_OPTS\nBORDER_MODE_V = 5\n$\n$KD", TIRENV_EPARSE, 12, 17,
     "BORDER_MODE_V", "expected a whole number from 0 to 4"},
    {"$\n$KD", "$\n$ROAD_CRG_OPTS\nBORDER_MODES = 1\n$\n$KD", TIRENV_EPARSE, 12, 1,
     "BORDER_MODES", "unknown option"},
    {"$\n$ROAD_CRG\n", "$\ngarbage\n$ROAD_CRG\n", TIRENV_EPARSE, 4, 1, "",
     "text outside a section"},
    {"$ROAD_CRG\n", "$ROAD_CRG! comment\n", TIRENV_OK, 0, 0, "", ""},
    {"$$$$\n", "", TIRENV_EPARSE, 17, 1, "", "text outside a section"},
    {"$$$$\n 0.0100000 0.0200000 0.0300000\n 0.0400000 0.0500000 0.0600000\n 0.0700000 0.08"
     "00000 0.0900000\n 0.1000000 0.1100000 0.1200000\n", "", TIRENV_EPARSE, 16, 0, "$$$$",
     "no end of header"},
    {"$\n$ROAD_CRG\n", "$\n$ROAD\n", TIRENV_EPARSE, 4, 2, "ROAD", "unknown section"},
    /* channels */
    {"D:long section 3,m", "D:friction,-", TIRENV_EPARSE, 15, 3, "D", "unknown channel "
     "'friction'"},
    {"D:long section 3,m", "D:long section 3,mm", TIRENV_EPARSE, 15, 18, "D",
     "expected the unit 'm'"},
    {"D:long section 3,m", "D:long section 3", TIRENV_EPARSE, 15, 3, "D", "has no unit"},
    {"D:long section 1,m\nD:long section 2,m", "D:long section 2,m\nD:long section 1,m",
     TIRENV_EPARSE, 13, 0, "D", "long section 2 where 1 was expected"},
    {"D:long section 2,m\nD:long section 3,m\n", "", TIRENV_EPARSE, 11, 0, "D",
     "1 long section; expected at least two"},
    {"D:long section 1,m", "D:long section at v = -1,m", TIRENV_EPARSE, 14, 0, "D",
     "both numbered and at given v"},
    {"D:long section 1,m\nD:long section 2,m\nD:long section 3,m",
     "D:long section at v = -1,m\nD:long section at v = 1,m\nD:long section at v = 0,m",
     TIRENV_EPARSE, 15, 0, "D", "expected ascending v"},
    {"D:long section 3,m\n", "D:long section 3,m\nD:reference line phi,rad\n"
     "D:reference line phi,rad\n", TIRENV_EPARSE, 17, 0, "D", "defined twice"},
    {"D:long section 3,m\n", "D:long section 3,m\nD:x,m\n", TIRENV_EPARSE, 16, 3, "D",
     "unknown channel"},
    {"#:LRFI\n", "#:LRFI\nwhat\n", TIRENV_EPARSE, 13, 1, "", "unexpected 'what' in "
     "$KD_DEFINITION"},
    /* data: a channel count that does not match, truncation, bad numbers, NaN */
    {" 0.0400000 0.0500000 0.0600000\n", " 0.0400000 0.0500000\n", TIRENV_EPARSE, 19, 21,
     "data", "record of 2 numbers where 3 were expected"},
    {" 0.0400000 0.0500000 0.0600000\n", " 0.0400000 0.0500000 0.0600000 0.0700000\n",
     TIRENV_EPARSE, 19, 31, "data", "after 3 numbers"},
    {" 0.0400000 0.0500000 0.0600000\n", " 0.0400000 abc       0.0600000\n", TIRENV_EPARSE,
     19, 11, "data", "'abc' is not a number"},
    {" 0.0400000 0.0500000 0.0600000\n", " 0.0400000 *missing* 0.0600000\n", TIRENV_EPARSE,
     19, 11, "long section 2 (v = 0 m)", "row 2 (u = 0.5 m): missing value between values"},
    {" 0.0400000 0.0500000 0.0600000\n", " *missing* *missing* *missing*\n", TIRENV_EPARSE,
     19, 1, "long section 1 (v = -1 m)", "no long section has a value"},
    {" 0.0400000 0.0500000 0.0600000\n", " 0.0400000 0.0500000 0.0600000\n\n", TIRENV_EPARSE,
     20, 0, "data", "blank line inside the road data"},
    {" 0.0700000 0.0800000 0.0900000\n 0.1000000 0.1100000 0.1200000\n", "",
     TIRENV_EPARSE, 6, 0, "REFERENCE_LINE_END_U", "the road data has 2 rows"},
    {" 0.0100000 0.0200000 0.0300000\n 0.0400000 0.0500000 0.0600000\n 0.0700000 0.0800000 "
     "0.0900000\n 0.1000000 0.1100000 0.1200000\n", "", TIRENV_EPARSE, 17, 0, "data",
     "no road data after the header"},
    {" 0.1000000 0.1100000 0.1200000\n", " 0.1000000 0.1100000 0.1200000\n\n\n",
     TIRENV_OK, 0, 0, "", ""},
    {"a small road", "a small\x01road", TIRENV_OK, 0, 0, "", ""},
};

static void test_malformed(void **state)
{
    tirenv_test_dir *fx = *state;
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        const malformed *m = &bad[k];
        char text[4096];
        const char *at = strstr(base, m->find);
        assert_non_null(at);
        snprintf(text, sizeof text, "%.*s%s%s", (int)(at - base), base, m->replace,
                 at + strlen(m->find));
        char path[600], name[32];
        snprintf(name, sizeof name, "bad%02zu.crg", k);
        tirenv_test_write_text(tirenv_test_path(fx, name, path), text);
        tirenv_crg *c = NULL;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        const int status = tirenv_crg_open(path, &c, &d);
        char line[1200];
        print_message("case %zu: %s\n", k, tirenv_diag_format(&d, line, sizeof line));
        assert_int_equal(status, m->status);
        if (status == TIRENV_OK) {
            assert_non_null(c);
            tirenv_crg_free(c);
            continue;
        }
        assert_null(c);
        assert_string_equal(d.file, path);
        assert_int_equal(d.line, m->line);
        if (m->column)
            assert_int_equal(d.column, m->column);
        assert_string_equal(d.field, m->field);
        assert_non_null(strstr(d.message, m->says));
    }
}

/* A NUL byte in the header, and a heading channel with a missing value where it is used. */
static void test_malformed_more(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_path(fx, "nul.crg", path);
    FILE *fp = fopen(path, "wb");
    assert_non_null(fp);
    fwrite(base, 1, 20, fp);
    fputc('\0', fp);
    fputs(base + 20, fp);
    fclose(fp);
    tirenv_crg *c = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_crg_open(path, &c, &d), TIRENV_EPARSE);
    assert_int_equal(d.line, 4);
    assert_non_null(strstr(d.message, "NUL byte"));
    static const char phi[] =
        "$CT\n$\n$ROAD_CRG\nREFERENCE_LINE_INCREMENT = 1\nLONG_SECTION_V_INCREMENT = 1\n$\n"
        "$KD_DEFINITION\n#:LRFI\nD:reference line phi,rad\nD:long section 1,m\n"
        "D:long section 2,m\n$\n$$$$\n"
        " *missing* 0.0100000 0.0200000\n"
        " 0.0000000 0.0100000 0.0200000\n"
        " *missing* 0.0100000 0.0200000\n";
    tirenv_test_write_text(tirenv_test_path(fx, "phi.crg", path), phi);
    assert_int_equal(tirenv_crg_open(path, &c, &d), TIRENV_EPARSE);
    assert_int_equal(d.line, 16);
    assert_int_equal(d.column, 1);
    assert_string_equal(d.field, "reference line phi");
    assert_non_null(strstr(d.message, "row 3 (u = 2 m): missing heading"));
    /* A directory and a missing file. */
    assert_int_equal(tirenv_crg_open(fx->dir, &c, &d), TIRENV_EIO);
    assert_int_equal(tirenv_crg_open(tirenv_test_path(fx, "none.crg", path), &c, &d),
                     TIRENV_EIO);
}

/* Big-endian doubles, as KDBI stores them. */
static void put_be_double(FILE *fp, double v)
{
    unsigned char b[8];
    uint64_t u;
    memcpy(&u, &v, sizeof u);
    for (int k = 0; k < 8; k++)
        b[k] = (unsigned char)(u >> (56 - 8 * k));
    fwrite(b, 1, 8, fp);
}

/* Binary files cut short (not a whole record; records missing so that the data ends inside a
 * row), and a header whose channels do not match the data's rows. */
static void test_binary_truncated(void **state)
{
    tirenv_test_dir *fx = *state;
    const double v[3] = {-1, 0, 1};
    char path[600];
    tirenv_test_path(fx, "t.crg", path);
    write_road(path, TIRENV_CRG_KRBI, 101, 3, v, 0); /* 303 floats: 16 records, 17 NaN */
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    const off_t size = st.st_size;
    tirenv_crg *c = NULL;
    tirenv_diag d;
    assert_int_equal(truncate(path, size - 7), 0);
    assert_int_equal(tirenv_crg_open(path, &c, &d), TIRENV_EPARSE);
    print_message("%s\n", d.message);
    assert_string_equal(d.field, "data");
    assert_non_null(strstr(d.message, "truncated data"));
    assert_non_null(strstr(d.message, "not a whole number of 80-byte records"));
    /* Two records short: 280 values, 93 rows and one value of the next. */
    assert_int_equal(truncate(path, size - 160), 0);
    assert_int_equal(tirenv_crg_open(path, &c, &d), TIRENV_EPARSE);
    print_message("%s\n", d.message);
    assert_non_null(strstr(d.message, "the last 1 values"));
    assert_non_null(strstr(d.message, "are not a whole row of 3 channels nor NaN padding"));
    /* 40 rows of 3 channels (12 records) under headers that announce 4 or 2 channels. */
    for (size_t nch = 2; nch <= 4; nch += 2) {
        FILE *fp = fopen(path, "wb");
        assert_non_null(fp);
        fprintf(fp, "$CT\n$\n$ROAD_CRG\nREFERENCE_LINE_INCREMENT = 0.1\n"
                    "REFERENCE_LINE_END_U = 3.9\nLONG_SECTION_V_INCREMENT = 1\n$\n"
                    "$KD_DEFINITION\n#:KDBI\n");
        for (size_t j = 0; j < nch; j++)
            fprintf(fp, "D:long section %zu,m\n", j + 1);
        fputs("$\n$$$$\n", fp);
        for (size_t k = 0; k < 120; k++)
            put_be_double(fp, 0.001 * (double)k);
        fclose(fp);
        assert_int_equal(tirenv_crg_open(path, &c, &d), TIRENV_EPARSE);
        print_message("%s\n", d.message);
        assert_string_equal(d.field, "REFERENCE_LINE_END_U");
        assert_non_null(strstr(d.message, nch == 4 ? "the road data has 30 rows"
                                                   : "the road data has 60 rows"));
    }
}

/* Text rows wrapped over two records, one of which is missing at the end. */
static void test_text_truncated(void **state)
{
    tirenv_test_dir *fx = *state;
    double v[9];
    for (size_t j = 0; j < 9; j++)
        v[j] = -2 + 0.5 * (double)j;
    char path[600];
    tirenv_test_path(fx, "wrap.crg", path);
    write_road(path, TIRENV_CRG_LRFI, 11, 9, v, 0);
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    assert_int_equal(truncate(path, st.st_size - 11), 0); /* the last record: 1 number + LF */
    tirenv_crg *c = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_crg_open(path, &c, &d), TIRENV_EPARSE);
    print_message("%s:%zu: %s\n", d.file, d.line, d.message);
    assert_non_null(strstr(d.message, "truncated data: the last row has 1 of its 2 records"));
}

/* A text file cut inside the last number of its last record, with no line end after it: a
 * truncated file, refused at that line and column in both text encodings, where it read as
 * the cut number ("0.1" of "0.1200000"). The whole file without its last line end reads, and
 * so does a last field that ends early before a line end (trailing blanks stripped: OpenCRG's
 * MATLAB reader pads a short line to 80 characters), the rule for every record. */
static void test_text_cut_mid_number(void **state)
{
    tirenv_test_dir *fx = *state;
    for (int enc = TIRENV_CRG_LRFI; enc <= TIRENV_CRG_LDFI; enc++) {
        const size_t w = enc == TIRENV_CRG_LRFI ? 10 : 20;
        char text[4096];
        const char *data = strstr(base, "$$$$\n") + 5;
        int n = snprintf(text, sizeof text, "%.*s", (int)(data - base), base);
        if (enc == TIRENV_CRG_LDFI)
            memcpy(strstr(text, "#:LRFI"), "#:LDFI", 6);
        for (size_t i = 0; i < 4; i++) {
            for (size_t j = 0; j < 3; j++)
                n += snprintf(text + n, sizeof text - (size_t)n, "%*.7f", (int)w,
                              0.01 * (double)(3 * i + j + 1));
            n += snprintf(text + n, sizeof text - (size_t)n, "\n");
        }
        const size_t full = (size_t)n, last = full - 1 - 3 * w; /* start of line 21 */
        char path[600];
        tirenv_test_path(fx, "cut.crg", path);
        tirenv_crg *c = NULL;
        tirenv_diag d;
        /* Cut 1 to w - 1 characters into the last field: no line end after it. */
        for (size_t keep = 3 * w - 1; keep > 2 * w; keep--) {
            FILE *fp = fopen(path, "wb");
            assert_non_null(fp);
            fwrite(text, 1, last + keep, fp);
            fclose(fp);
            tirenv_diag_clear(&d);
            assert_int_equal(tirenv_crg_open(path, &c, &d), TIRENV_EPARSE);
            assert_null(c);
            assert_string_equal(d.file, path);
            assert_int_equal(d.line, 21);
            assert_int_equal(d.column, keep + 1);
            assert_string_equal(d.field, "data");
            assert_non_null(strstr(d.message, "truncated data: the file ends"));
        }
        print_message("%s:%zu:%zu: %s\n", d.file, d.line, d.column, d.message);
        /* The whole file without its last line end, and a last field stripped to " 0.12"
         * before the line end: both read as the whole file does. */
        tirenv_test_write_text(path, text);
        c = open_ok(path);
        const double z1 = z_at(c, 1, 3), z0 = z_at(c, 0, 3);
        tirenv_crg_free(c);
        for (int k = 0; k < 2; k++) {
            FILE *fp = fopen(path, "wb");
            assert_non_null(fp);
            if (k == 0) {
                fwrite(text, 1, full - 1, fp);
            } else {
                fwrite(text, 1, last + 2 * w, fp);
                fputs(" 0.12\n", fp);
            }
            fclose(fp);
            c = open_ok(path);
            assert_int_equal(tirenv_crg_rows(c), 4);
            assert_bits_equal(z_at(c, 1, 3), z1);
            assert_bits_equal(z_at(c, 0, 3), z0);
            tirenv_crg_free(c);
        }
    }
}

/* The writer refuses what it cannot write. */
static void test_writer_refuses(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_path(fx, "w.crg", path);
    const double v[3] = {-1, 0, 1}, down[2] = {1, 0};
    tirenv_crg_layout l = {.encoding = TIRENV_CRG_KDBI, .u_start = 0, .u_increment = 0.1,
                           .rows = 3, .long_sections = 3, .v = v};
    tirenv_crg_writer *w = NULL;
    tirenv_diag d;
    l.long_sections = 1;
    assert_int_equal(tirenv_crg_writer_open(path, &l, &w, &d), TIRENV_EINVAL);
    l.long_sections = 2;
    l.v = down;
    assert_int_equal(tirenv_crg_writer_open(path, &l, &w, &d), TIRENV_EINVAL);
    /* beyond a road's 1e9 m, which the reader refuses: convert --half-width 1e300 wrote it */
    const double wide[2] = {-1e300, 1e300};
    l.v = wide;
    assert_int_equal(tirenv_crg_writer_open(path, &l, &w, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "v");
    l.v = v;
    l.long_sections = 3;
    l.u_increment = 0;
    assert_int_equal(tirenv_crg_writer_open(path, &l, &w, &d), TIRENV_EINVAL);
    l.u_increment = 0.1;
    l.comment = "$ROAD_CRG\n";
    assert_int_equal(tirenv_crg_writer_open(path, &l, &w, &d), TIRENV_EINVAL);
    l.comment = NULL;
    assert_int_equal(tirenv_crg_writer_open(path, &l, &w, &d), TIRENV_OK);
    const double mid_nan[3] = {0, NAN, 0}, inf[3] = {0, INFINITY, 0}, ok[3] = {NAN, 1, 2};
    assert_int_equal(tirenv_crg_writer_row(w, mid_nan, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_crg_writer_row(w, inf, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_crg_writer_row(w, ok, &d), TIRENV_OK);
    /* Committed with 1 of 3 rows: refused, and nothing left behind. */
    assert_int_equal(tirenv_crg_writer_commit(w, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "1 rows written of the 3"));
    assert_int_equal(access(path, F_OK), -1);
    assert_int_equal(tirenv_test_count_entries(fx, ".tmp."), 0);
    /* Profiles that are not on one even grid need an increment. */
    const double x1[3] = {0, 0.1, 0.3}, z1[3] = {0, 0.01, 0.02};
    tirenv_profile *p = tirenv_profile_alloc(3, x1, z1);
    const tirenv_profile *const two[2] = {p, p};
    const double vv[2] = {-0.5, 0.5};
    assert_int_equal(tirenv_crg_write_profiles(path, TIRENV_CRG_KDBI, 2, vv, two, 0, NULL, &d),
                     TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "evenly spaced"));
    assert_int_equal(tirenv_crg_write_profiles(path, TIRENV_CRG_KDBI, 2, vv, two, 0.1, NULL, &d),
                     TIRENV_OK);
    tirenv_crg *c = open_ok(path);
    assert_int_equal(tirenv_crg_rows(c), 4);
    assert_near(z_at(c, 0, 2), 0.015, 1e-15, 0);
    tirenv_crg_free(c);
    tirenv_profile_free(p);
}

/* A buffer reads as the file does; errors name the buffer's label. */
static void test_memory(void **state)
{
    (void)state;
    tirenv_crg *c = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_crg_open_memory(base, strlen(base), "road", &c, &d), TIRENV_OK);
    /* 0.085 less 0.01, the height OpenCRG's default REFPOINT_Z = 0 takes off (at u = 0 on
     * the right edge, v = -1: base has no modifiers section). */
    assert_near(z_at(c, 0.5, 2), 0.075, 1e-12, 0);
    tirenv_crg_free(c);
    assert_int_equal(tirenv_crg_open_memory(base, 100, "road", &c, &d), TIRENV_EPARSE);
    assert_string_equal(d.file, "road");
    assert_int_equal(tirenv_profile_detect_memory(base, strlen(base)), TIRENV_PROFILE_CRG);
    assert_int_equal(tirenv_profile_detect_memory("* c\n$ROAD_CRG\n", 14), TIRENV_PROFILE_CRG);
    assert_int_equal(tirenv_profile_detect_memory("$ x\n[UNITS]\n", 12), TIRENV_PROFILE_RDF);
    assert_int_equal(tirenv_profile_detect_memory("# x\nx_m,z_m\n", 12), TIRENV_PROFILE_CSV);
    assert_int_equal(tirenv_profile_detect_memory("$Tire data\nx_m,z_m\n", 19),
                     TIRENV_PROFILE_CSV);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_handmade_grids),
        cmocka_unit_test(test_handmade_straight_heights),
        cmocka_unit_test(test_handmade_nan_borders),
        cmocka_unit_test(test_handmade_equivalents),
        cmocka_unit_test(test_handmade_vtest),
        cmocka_unit_test(test_handmade_banking_and_slope),
        cmocka_unit_test(test_handmade_border_mode_v),
        cmocka_unit_test(test_handmade_curved_reflines),
        cmocka_unit_test(test_handmade_refused),
        cmocka_unit_test(test_halfround),
        cmocka_unit_test(test_horstwalde),
        cmocka_unit_test_setup_teardown(test_write_read_encodings, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_windows, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_round_trips, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_curved_refline_circle, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_refpoint, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_mods_and_opts, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_malformed, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_malformed_more, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_binary_truncated, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_text_truncated, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_text_cut_mid_number, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_writer_refuses, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test(test_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
