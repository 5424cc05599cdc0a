/* The TNO / Adams 2-D road reader and writer: the Simscape plateau sample, poly_line sides,
 * units, planks, flat roads, round trips and malformed files.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/profile_file.h"
#include "tirenv/rdf.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static tirenv_profile *read_text(const tirenv_test_dir *fx, const char *text,
                                 tirenv_rdf_side side)
{
    char path[600];
    tirenv_test_write_text(tirenv_test_path(fx, "road.rdf", path), text);
    tirenv_profile *p = NULL;
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const int status = tirenv_rdf_read(path, side, &p, &d);
    if (status) {
        char line[1200];
        print_error("%s\n", tirenv_diag_format(&d, line, sizeof line));
    }
    assert_int_equal(status, TIRENV_OK);
    return p;
}

static void assert_vertices(const tirenv_profile *p, size_t n, const double x[],
                            const double z[])
{
    assert_int_equal(tirenv_profile_size(p), n);
    for (size_t k = 0; k < n; k++) {
        assert_near(tirenv_profile_x(p)[k], x[k], 1e-12, 1e-15);
        assert_near(tirenv_profile_z(p)[k], z[k], 1e-12, 1e-15);
    }
}

/* The plateau: 46 rows from x = -10000 to 10000 m, up to 4.9 m between x = 110 and 130; the
 * same heights left and right. */
static void test_plateau(void **state)
{
    (void)state;
    char path[600];
    snprintf(path, sizeof path, "%s/rdf/plateau.rdf", TIRENV_SAMPLES);
    struct stat st;
    if (stat(path, &st) != 0) {
        print_error("sample file %s is missing\n", path);
        fail();
    }
    tirenv_profile *sides[3];
    for (int s = 0; s < 3; s++) {
        tirenv_diag d;
        assert_int_equal(tirenv_rdf_read(path, (tirenv_rdf_side)s, &sides[s], &d), TIRENV_OK);
    }
    const tirenv_profile *p = sides[TIRENV_RDF_MEAN];
    assert_int_equal(tirenv_profile_size(p), 46);
    assert_near(tirenv_profile_x(p)[0], -10000, 0, 0);
    assert_near(tirenv_profile_x(p)[45], 10000, 0, 0);
    assert_near(tirenv_profile_height(p, 120), 4.9, 1e-12, 0);
    assert_near(tirenv_profile_height(p, 43.5), 0.036, 1e-12, 0);
    assert_near(tirenv_profile_height(p, 45.25), 0.5 * (0.036 + 0.137), 1e-12, 0);
    assert_near(tirenv_profile_max_height(p, -1e4, 1e4), 4.9, 0, 0);
    for (int s = 1; s < 3; s++)
        for (size_t k = 0; k < 46; k++)
            assert_bits_equal(tirenv_profile_z(sides[s])[k], tirenv_profile_z(p)[k]);
    /* The content says RDF whatever the name. */
    tirenv_profile_format f;
    assert_int_equal(tirenv_profile_detect(path, &f, NULL), TIRENV_OK);
    assert_int_equal(f, TIRENV_PROFILE_RDF);
    for (int s = 0; s < 3; s++)
        tirenv_profile_free(sides[s]);
}

/* Sides, units (mm here) and OFFSET; comments, a table header and odd spacing. */
static void test_poly_line(void **state)
{
    tirenv_test_dir *fx = *state;
    static const char text[] =
        "$ a road\n[MDI_HEADER]\nFILE_TYPE = 'rdf'  ! road\nFILE_VERSION = 5.0\n"
        "[UNITS]\nLENGTH = 'mm'\nFORCE = 'newton'\nANGLE = 'deg'\nMASS = 'kg'\nTIME = 'sec'\n"
        "[MODEL]\nMETHOD = '2D'\nROAD_TYPE = 'poly_line'\nFUNCTION_NAME = 'ARC904'\n"
        "[PARAMETERS]\nOFFSET = 10\nMU = 0.9\n(XZ_DATA)\n{ x z_l z_r }\n"
        "   0     0     2\n"
        "1000.5, 20 ,  40 $ a comment\n"
        "\t2000\t-10\t30\n"
        "[GRAPHICS]\nCOLOR = 'grey'\n1 2 3 4 5\n";
    static const double x[] = {0, 1.0005, 2.0};
    const double left[] = {0.010, 0.030, 0.000}, right[] = {0.012, 0.050, 0.040};
    const double mean[] = {0.011, 0.040, 0.020};
    tirenv_profile *p = read_text(fx, text, TIRENV_RDF_LEFT);
    assert_vertices(p, 3, x, left);
    tirenv_profile_free(p);
    p = read_text(fx, text, TIRENV_RDF_RIGHT);
    assert_vertices(p, 3, x, right);
    tirenv_profile_free(p);
    p = read_text(fx, text, TIRENV_RDF_MEAN);
    assert_vertices(p, 3, x, mean);
    tirenv_profile_free(p);
    /* Another sub-block's table is not tirenv's: the quoted lines of an Adams header's
     * (COMMENTS), even one that holds '=', are skipped, and the road reads as before
     * (the fuzz seed corpus/rdf/poly_line.rdf was refused at 'a road'). */
    static const char commented[] =
        "[MDI_HEADER]\nFILE_TYPE = 'rdf'\n(COMMENTS)\n{comment_string}\n'a road'\n"
        "'x = 1 is not a key'\n"
        "[UNITS]\nLENGTH = 'mm'\n[MODEL]\nMETHOD = '2D'\nROAD_TYPE = 'poly_line'\n"
        "[PARAMETERS]\nOFFSET = 10\n(XZ_DATA)\n0 0 2\n1000.5 20 40\n2000 -10 30\n";
    p = read_text(fx, commented, TIRENV_RDF_LEFT);
    assert_vertices(p, 3, x, left);
    tirenv_profile_free(p);
    /* A vertical wall (two rows at one x) is allowed, as in a tirenv profile. */
    p = read_text(fx, "[UNITS]\nLENGTH = 'meter'\n[MODEL]\nMETHOD = '2d'\n"
                      "ROAD_TYPE = 'POLY_LINE'\n[PARAMETERS]\n(XZ_DATA)\n0 0 0\n1 0 0\n"
                      "1 0.1 0.1\n2 0.1 0.1\n", TIRENV_RDF_MEAN);
    assert_int_equal(tirenv_profile_size(p), 4);
    tirenv_profile_free(p);
}

/* A plank: 45-degree bevels at its top corners, LENGTH along x including them; inches here. */
static void test_plank(void **state)
{
    tirenv_test_dir *fx = *state;
    static const char head[] = "[UNITS]\nLENGTH = 'inch'\n[MODEL]\nMETHOD = '2D'\n"
                               "ROAD_TYPE = 'plank'\n[PARAMETERS]\n";
    const double in = 0.0254;
    struct {
        const char *params;
        size_t n;
        double x[6], z[6];
    } cases[] = {
        {"HEIGHT = 2\nSTART = 10\nLENGTH = 6\nBEVEL_EDGE_LENGTH = 0.5\nDIRECTION = 0\n", 6,
         {10, 10, 10.5, 15.5, 16, 16}, {0, 1.5, 2, 2, 1.5, 0}},
        {"HEIGHT = 2\nSTART = 10\nLENGTH = 6\n", 4, {10, 10, 16, 16}, {0, 2, 2, 0}},
        {"HEIGHT = 2\nSTART = 10\nLENGTH = 6\nBEVEL_EDGE_LENGTH = 2\n", 4, {10, 12, 14, 16},
         {0, 2, 2, 0}},
        {"HEIGHT = 3\nSTART = 10\nLENGTH = 6\nBEVEL_EDGE_LENGTH = 3\n", 3, {10, 13, 16},
         {0, 3, 0}},
        {"HEIGHT = -2\nSTART = 10\nLENGTH = 6\nBEVEL_EDGE_LENGTH = 0.5\n", 6,
         {10, 10, 10.5, 15.5, 16, 16}, {0, -1.5, -2, -2, -1.5, 0}},
        {"HEIGHT = 1\nSTART = 0\nLENGTH = 2\nOFFSET = 4\n", 4, {0, 0, 2, 2}, {4, 5, 5, 4}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char text[1024];
        snprintf(text, sizeof text, "%s%s", head, cases[k].params);
        for (size_t i = 0; i < cases[k].n; i++) {
            cases[k].x[i] *= in;
            cases[k].z[i] *= in;
        }
        tirenv_profile *p = read_text(fx, text, TIRENV_RDF_MEAN);
        assert_vertices(p, cases[k].n, cases[k].x, cases[k].z);
        tirenv_profile_free(p);
    }
}

/* A flat road: flat ground at OFFSET. */
static void test_flat(void **state)
{
    tirenv_test_dir *fx = *state;
    tirenv_profile *p = read_text(fx, "[UNITS]\nLENGTH = 'cm'\n[MODEL]\nMETHOD = '2D'\n"
                                      "ROAD_TYPE = 'flat'\n[PARAMETERS]\nOFFSET = -3\n",
                                  TIRENV_RDF_MEAN);
    assert_int_equal(tirenv_profile_size(p), 1);
    assert_near(tirenv_profile_height(p, -50), -0.03, 1e-15, 0);
    assert_near(tirenv_profile_height(p, 1e3), -0.03, 1e-15, 0);
    tirenv_profile_free(p);
}

/* RDF -> CSV -> RDF gives the same heights, exactly (numbers are written to read back). */
static void test_round_trip(void **state)
{
    tirenv_test_dir *fx = *state;
    char src[600], csv[600], rdf[600];
    snprintf(src, sizeof src, "%s/rdf/plateau.rdf", TIRENV_SAMPLES);
    tirenv_test_path(fx, "p.csv", csv);
    tirenv_test_path(fx, "p.rdf", rdf);
    tirenv_profile *a = NULL, *b = NULL, *c = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_profile_read_file(src, NULL, &a, &d), TIRENV_OK);
    assert_int_equal(tirenv_profile_write_file(csv, a, NULL, &d), TIRENV_OK);
    assert_int_equal(tirenv_profile_read_file(csv, NULL, &b, &d), TIRENV_OK);
    assert_int_equal(tirenv_profile_write_file(rdf, b, NULL, &d), TIRENV_OK);
    assert_int_equal(tirenv_profile_read_file(rdf, NULL, &c, &d), TIRENV_OK);
    for (size_t k = 0; k < 46; k++) {
        assert_bits_equal(tirenv_profile_x(c)[k], tirenv_profile_x(a)[k]);
        assert_bits_equal(tirenv_profile_z(c)[k], tirenv_profile_z(a)[k]);
    }
    /* Two tracks: left and right columns. */
    static const double x[3] = {0.1, 0.25, 0.4}, zl[3] = {0.01, 0.0137, -0.002},
                        zr[3] = {0.02, 0.0011, 0.0033};
    tirenv_profile *l = tirenv_profile_alloc(3, x, zl), *r = tirenv_profile_alloc(3, x, zr);
    assert_int_equal(tirenv_rdf_write(rdf, l, r, "two tracks\nof a test", &d), TIRENV_OK);
    tirenv_profile *back = NULL;
    assert_int_equal(tirenv_rdf_read(rdf, TIRENV_RDF_RIGHT, &back, &d), TIRENV_OK);
    assert_vertices(back, 3, x, zr);
    tirenv_profile_free(back);
    /* Tracks that do not share x are refused, and nothing is written. */
    static const double x2[3] = {0.1, 0.26, 0.4};
    tirenv_profile *r2 = tirenv_profile_alloc(3, x2, zr);
    assert_int_equal(tirenv_rdf_write(csv, l, r2, NULL, &d), TIRENV_EINVAL);
    /* A one-vertex profile is a flat road. */
    static const double x1 = 3, z1 = 0.25;
    tirenv_profile *flat = tirenv_profile_alloc(1, &x1, &z1);
    assert_int_equal(tirenv_rdf_write(rdf, flat, NULL, NULL, &d), TIRENV_OK);
    assert_int_equal(tirenv_rdf_read(rdf, TIRENV_RDF_MEAN, &back, &d), TIRENV_OK);
    assert_near(tirenv_profile_height(back, -7), 0.25, 0, 0);
    tirenv_profile_free(back);
    tirenv_profile_free(flat);
    tirenv_profile_free(l);
    tirenv_profile_free(r);
    tirenv_profile_free(r2);
    tirenv_profile_free(a);
    tirenv_profile_free(b);
    tirenv_profile_free(c);
}

static const char good[] = "[UNITS]\nLENGTH = 'meter'\n"      /* 1, 2 */
                           "[MODEL]\nMETHOD = '2D'\n"         /* 3, 4 */
                           "ROAD_TYPE = 'poly_line'\n"        /* 5 */
                           "[PARAMETERS]\n"                   /* 6 */
                           "(XZ_DATA)\n"                      /* 7 */
                           "0 0 0\n"                          /* 8 */
                           "1 0.1 0.1\n"                      /* 9 */
                           "2 0 0\n";                         /* 10 */

static const struct {
    const char *find, *replace;
    size_t line, column;
    const char *field, *says;
} bad[] = {
    {"'2D'", "'3D'", 4, 0, "METHOD", "'3D': tirenv reads 2-D roads"},
    {"'poly_line'", "'sine'", 5, 0, "ROAD_TYPE", "'sine' is not supported; expected "
     "'poly_line', 'plank' or 'flat'"},
    {"'poly_line'", "'pot_hole'", 5, 0, "ROAD_TYPE", "not supported"},
    {"'meter'", "'furlong'", 2, 11, "LENGTH", "unknown unit 'furlong'"},
    {"LENGTH = 'meter'\n", "FORCE = 'newton'\n", 0, 0, "LENGTH", "no [UNITS] LENGTH"},
    {"LENGTH = 'meter'\n", "LENGTH = 'meter'\nSPEED = 'km/h'\n", 3, 1, "SPEED",
     "unknown key in [UNITS]"},
    {"METHOD = '2D'\n", "", 4, 0, "METHOD", "missing in [MODEL]"},
    {"'2D'", "'2D", 4, 10, "METHOD", "unterminated string"},
    {"1 0.1 0.1\n", "1 0.1\n", 9, 6, "XZ_DATA", "missing z_right"},
    {"1 0.1 0.1\n", "1 0.1 0.1 7\n", 9, 11, "XZ_DATA", "after three numbers"},
    {"1 0.1 0.1\n", "1 0.1x 0.1\n", 9, 3, "XZ_DATA", "z_left: expected a finite number"},
    {"1 0.1 0.1\n", "1 inf 0.1\n", 9, 3, "XZ_DATA", "expected a finite number"},
    {"2 0 0\n", "0.5 0 0\n", 10, 0, "XZ_DATA", "less than the previous x"},
    {"2 0 0\n", "1 0 0\n1 1 1\n", 11, 0, "XZ_DATA", "shared by three vertices"},
    {"(XZ_DATA)\n0 0 0\n1 0.1 0.1\n2 0 0\n", "", 5, 0, "XZ_DATA",
     "without an (XZ_DATA) table"},
    {"0 0 0\n1 0.1 0.1\n2 0 0\n", "", 7, 0, "XZ_DATA", "without rows in (XZ_DATA)"},
    {"(XZ_DATA)\n", "(XZ_DATA)\nMU = 1\n", 8, 1, "MU", "inside (XZ_DATA)"},
    {"[PARAMETERS]\n", "[PARAMETERS]\nWIBBLE = 3\n", 7, 1, "WIBBLE",
     "unknown key in [PARAMETERS]"},
    {"[PARAMETERS]\n", "[PARAMETERS]\nOFFSET = 1\nOFFSET = 2\n", 8, 1, "OFFSET", "set twice"},
    {"[PARAMETERS]\n", "[PARAMETERS]\nOFFSET = 1 m\n", 7, 12, "OFFSET", "after the number"},
    {"[PARAMETERS]\n", "[PARAMETERS\n", 6, 1, "", "unterminated '['"},
    {"[PARAMETERS]\n", "[PARAMETERS] x\n", 6, 14, "", "unexpected 'x' after ']'"},
    {"(XZ_DATA)\n", "(XZ_DATA)\n(XZ_DATA)\n", 8, 2, "XZ_DATA", "given twice"},
    {"[UNITS]\n", "[MDI_HEADER]\nFILE_TYPE = 'tir'\n[UNITS]\n", 2, 14, "FILE_TYPE",
     "'tir' is not a road file"},
    {"'poly_line'", "'plank'", 5, 0, "HEIGHT", "needs HEIGHT in [PARAMETERS]"},
};

static const struct {
    const char *params;
    const char *field, *says;
} bad_planks[] = {
    {"HEIGHT = 0.1\nSTART = 1\nLENGTH = 0.5\nDIRECTION = 30\n", "DIRECTION",
     "an oblique plank"},
    {"HEIGHT = 0.1\nSTART = 1\nLENGTH = 0\n", "LENGTH", "expected a positive length"},
    {"HEIGHT = 0.1\nSTART = 1\nLENGTH = 0.5\nBEVEL_EDGE_LENGTH = 0.3\n", "BEVEL_EDGE_LENGTH",
     "at most half of LENGTH"},
    {"HEIGHT = 0.1\nSTART = 1\nLENGTH = 0.5\nBEVEL_EDGE_LENGTH = 0.2\n", "BEVEL_EDGE_LENGTH",
     "at most |HEIGHT|"},
    {"HEIGHT = 0.1\nSTART = 1\nLENGTH = 0.5\nBEVEL_EDGE_LENGTH = -0.01\n",
     "BEVEL_EDGE_LENGTH", "a length >= 0"},
    {"HEIGHT = 0.1\nSTART = 1\nLENGTH = 0.5\nEDGE_ROUNDED = 1\n", "EDGE_ROUNDED",
     "rounded plank edges are not supported"},
    {"HEIGHT = 0.1\nLENGTH = 0.5\n", "START", "needs START"},
    /* keys that make no profile, named: these were "vertex 1: x = 1e+300 m" and "vertex 3: x
     * = 1 is shared by three vertices", vertices the file does not have, at no line */
    {"HEIGHT = 0.1\nSTART = 1e300\nLENGTH = 0.5\n", "START", "within +-1e+09 m"},
    {"HEIGHT = 0.1\nSTART = 1\nLENGTH = 1e300\n", "LENGTH", "ending within +-1e+09 m"},
    {"HEIGHT = 0.1\nSTART = 1\nLENGTH = 2e7\n", "LENGTH", "at most 1e+07 m"},
    {"HEIGHT = 0.1\nSTART = 1\nLENGTH = 1e-300\n", "LENGTH", "ends differ at START"},
    {"HEIGHT = 1e300\nSTART = 1\nLENGTH = 0.5\n", "HEIGHT", "within +-1e+09 m"},
    {"HEIGHT = 0.1\nSTART = 1\nLENGTH = 0.5\nOFFSET = -1e300\n", "OFFSET", "within +-1e+09 m"},
    {"HEIGHT = 0.1\nSTART = 1\nLENGTH = 0.5\nBEVEL_EDGE_LENGTH = 1e-17\n", "ROAD_TYPE",
     "the 'plank' road its keys describe is no profile: vertex 3"},
};

static void test_malformed(void **state)
{
    tirenv_test_dir *fx = *state;
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        char text[2048];
        const char *at = strstr(good, bad[k].find);
        assert_non_null(at);
        snprintf(text, sizeof text, "%.*s%s%s", (int)(at - good), good, bad[k].replace,
                 at + strlen(bad[k].find));
        char path[600];
        tirenv_test_write_text(tirenv_test_path(fx, "bad.rdf", path), text);
        tirenv_profile *p = NULL;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        const int status = tirenv_rdf_read(path, TIRENV_RDF_MEAN, &p, &d);
        tirenv_test_expect_diag(k, status, &d, TIRENV_EPARSE, path, bad[k].line, bad[k].column,
                                bad[k].field, bad[k].says);
        assert_null(p);
    }
    for (size_t k = 0; k < sizeof bad_planks / sizeof bad_planks[0]; k++) {
        char text[1024], path[600];
        snprintf(text, sizeof text, "[UNITS]\nLENGTH = 'meter'\nANGLE = 'degree'\n[MODEL]\n"
                                    "METHOD = '2D'\nROAD_TYPE = 'plank'\n[PARAMETERS]\n%s",
                 bad_planks[k].params);
        tirenv_test_write_text(tirenv_test_path(fx, "plank.rdf", path), text);
        tirenv_profile *p = NULL;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        assert_int_equal(tirenv_rdf_read(path, TIRENV_RDF_MEAN, &p, &d), TIRENV_EPARSE);
        print_message("plank %zu: %s: %s\n", k, d.field, d.message);
        assert_string_equal(d.field, bad_planks[k].field);
        assert_non_null(strstr(d.message, bad_planks[k].says));
        assert_true(d.line > 0);  /* the key's line, or ROAD_TYPE's */
    }
    /* A NUL byte, a missing file, a directory, a bad side. */
    char path[600];
    tirenv_test_path(fx, "nul.rdf", path);
    FILE *fp = fopen(path, "wb");
    assert_non_null(fp);
    fwrite(good, 1, 30, fp);
    fputc('\0', fp);
    fputs(good + 30, fp);
    fclose(fp);
    tirenv_profile *p = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_rdf_read(path, TIRENV_RDF_MEAN, &p, &d), TIRENV_EPARSE);
    assert_non_null(strstr(d.message, "NUL byte"));
    assert_int_equal(tirenv_rdf_read(fx->dir, TIRENV_RDF_MEAN, &p, &d), TIRENV_EIO);
    assert_int_equal(tirenv_rdf_read(tirenv_test_path(fx, "none.rdf", path), TIRENV_RDF_MEAN,
                                     &p, &d), TIRENV_EIO);
    assert_int_equal(tirenv_rdf_read_memory(good, strlen(good), "mem", (tirenv_rdf_side)7,
                                            &p, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_rdf_read_memory(good, strlen(good), "mem", TIRENV_RDF_LEFT, &p,
                                            &d), TIRENV_OK);
    tirenv_profile_free(p);
    tirenv_rdf_side s;
    assert_int_equal(tirenv_rdf_side_find("Left", &s), TIRENV_OK);
    assert_int_equal(s, TIRENV_RDF_LEFT);
    assert_int_equal(tirenv_rdf_side_find("middle", &s), TIRENV_EINVAL);
    assert_string_equal(tirenv_rdf_side_name(TIRENV_RDF_MEAN), "mean");
}

/* A poly_line's rows are checked as the reader passes them and are not kept (formats.md
 * section 5): the checks must be those of the rows gathered whole (tirenv_profile_validate),
 * also where [UNITS] LENGTH or OFFSET comes after the rows (the rows then checked again), and
 * per side (a mean that overflows where either side alone does not). Each road also read a
 * row at a time, the same vertices bit for bit. */
static void test_checked_in_passing(void **state)
{
    tirenv_test_dir *fx = *state;
    /* The unit after the rows: checked with it, x in mm; with no unit yet (f unknown) the
     * four rows would have been taken at one x. */
    static const char late[] =
        "[MODEL]\nMETHOD = '2D'\nROAD_TYPE = 'poly_line'\n[PARAMETERS]\n(XZ_DATA)\n"
        "0 0 0\n1000 10 10\n1000 20 20\n2000 0 0\n[PARAMETERS]\nOFFSET = 5\n"
        "[UNITS]\nLENGTH = 'mm'\n";
    static const double x[] = {0, 1, 1, 2}, z[] = {0.005, 0.015, 0.025, 0.005};
    tirenv_profile *p = read_text(fx, late, TIRENV_RDF_MEAN);
    assert_vertices(p, 4, x, z);
    char path[600];
    tirenv_test_path(fx, "road.rdf", path);
    tirenv_profile_file_reader *r = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_profile_file_reader_open(path, NULL, 1, NULL, &r, &d), TIRENV_OK);
    for (size_t k = 0; k <= 4; k++) {
        double xk, zk;
        int got = 0;
        assert_int_equal(tirenv_profile_file_reader_next(r, &xk, &zk, &got, &d), TIRENV_OK);
        assert_int_equal(got, k < 4);
        if (got) {
            assert_bits_equal(xk, tirenv_profile_x(p)[k]);
            assert_bits_equal(zk, tirenv_profile_z(p)[k]);
        }
    }
    tirenv_profile_file_reader_free(r);
    tirenv_profile_free(p);
    static const char head[] = "[UNITS]\nLENGTH = '%s'\n[MODEL]\nMETHOD = '2D'\n"
                               "ROAD_TYPE = 'poly_line'\n[PARAMETERS]\n(XZ_DATA)\n%s";
    static const struct {
        const char *unit, *rows;
        size_t line[3];          /* mean, left, right: the failing row's line, 0: read */
        const char *says[3];
    } cases[] = {
        /* OFFSET after the rows makes the first row's height overflow on every side. */
        {"meter", "0 1e308 1e308\n1 0 0\n[PARAMETERS]\nOFFSET = 1e308\n", {8, 8, 8},
         {"vertex 1: z = inf is not finite; expected a finite number",
          "vertex 1: z = inf", "vertex 1: z = inf"}},
        /* Each side finite, their sum not: the mean is refused as not finite, each side as
         * beyond TIRENV_PROFILE_MAX_COORDINATE. */
        {"meter", "0 0 0\n1 1e308 1e308\n2 0 0\n", {9, 9, 9},
         {"vertex 2: z = inf is not finite; expected a finite number",
          "vertex 2: z = 1e+308 m is beyond", "vertex 2: z = 1e+308 m is beyond"}},
        /* Each side beyond TIRENV_PROFILE_MAX_COORDINATE, their mean 0: the mean is refused
         * with the left side (it was read as 0). */
        {"meter", "0 0 0\n1 1e308 -1e308\n2 0 0\n", {9, 9, 9},
         {"vertex 2: z = 1e+308 m is beyond", "vertex 2: z = 1e+308 m is beyond",
          "vertex 2: z = -1e+308 m is beyond"}},
        /* x finite in km, not in m. */
        {"km", "0 0 0\n1e306 0 0\n", {9, 9, 9},
         {"vertex 2: x = inf is not finite; expected a finite number", "x = inf",
          "x = inf"}},
        /* The left side's z overflows in m (the mean's is only far too large) before x
         * decreases: the left and the mean name their z, the right the x, each at its row. */
        {"km", "0 0 0\n1 2.5e305 0\n2 0 0\n0.5 0 0\n", {9, 9, 11},
         {"vertex 2: z = 1.25e+308 m is beyond", "vertex 2: z = inf is not finite",
          "vertex 4: x = 500 is less than the previous x = 2000; expected non-decreasing x"}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char text[1024];
        snprintf(text, sizeof text, head, cases[k].unit, cases[k].rows);
        tirenv_test_write_text(path, text);
        for (int side = 0; side < 3; side++) {
            p = NULL;
            tirenv_diag_clear(&d);
            const int status = tirenv_rdf_read(path, (tirenv_rdf_side)side, &p, &d);
            if (!cases[k].line[side]) {
                assert_int_equal(status, TIRENV_OK);
                tirenv_profile_free(p);
            } else {
                tirenv_test_expect_diag(k, status, &d, TIRENV_EPARSE, path,
                                        cases[k].line[side], 0, "XZ_DATA", cases[k].says[side]);
                assert_null(p);
            }
        }
    }
}

/* A road of 70,001 rows (three of the whole read's blocks of 32,768, the reader's 64 KB window
 * some forty times over) in mm with an OFFSET: read whole and a row at a time, both give
 * f (z + OFFSET) of each row, the side's, bit for bit. */
static void test_long_road(void **state)
{
    tirenv_test_dir *fx = *state;
    enum { N = 70001 };
    char path[600];
    FILE *fp = fopen(tirenv_test_path(fx, "long.rdf", path), "w");
    assert_non_null(fp);
    fputs("[UNITS]\nLENGTH = 'mm'\n[MODEL]\nMETHOD = '2D'\nROAD_TYPE = 'poly_line'\n"
          "[PARAMETERS]\nOFFSET = 2.5\n(XZ_DATA)\n", fp);
    for (int k = 0; k < N; k++) {
        if (k % 9000 == 0)
            fputs("$ a comment in the table\n\n", fp);
        fprintf(fp, "%d %.6f %.6f\n", k, 3.0 * sin(0.0137 * k), 2.0 * cos(0.0071 * k));
    }
    fclose(fp);
    for (int side = 0; side < 3; side++) {
        tirenv_profile *p = NULL;
        tirenv_diag d;
        assert_int_equal(tirenv_rdf_read(path, (tirenv_rdf_side)side, &p, &d), TIRENV_OK);
        assert_int_equal(tirenv_profile_size(p), N);
        tirenv_profile_source src = tirenv_profile_source_default();
        src.rdf_side = (tirenv_rdf_side)side;
        tirenv_profile_file_reader *r = NULL;
        assert_int_equal(tirenv_profile_file_reader_open(path, &src, 1, NULL, &r, &d),
                         TIRENV_OK);
        for (size_t k = 0; k < N; k++) {
            double x, z;
            int got = 0;
            assert_int_equal(tirenv_profile_file_reader_next(r, &x, &z, &got, &d), TIRENV_OK);
            assert_true(got);
            /* the row as the file has it, read back as strtod reads it */
            char zl[32], zr[32];
            snprintf(zl, sizeof zl, "%.6f", 3.0 * sin(0.0137 * (double)k));
            snprintf(zr, sizeof zr, "%.6f", 2.0 * cos(0.0071 * (double)k));
            const double l = strtod(zl, NULL), rr = strtod(zr, NULL);
            const double zs = side == TIRENV_RDF_LEFT ? l : side == TIRENV_RDF_RIGHT ? rr
                                                                                  : 0.5 * (l + rr);
            assert_bits_equal(x, 0.001 * (double)k);
            assert_bits_equal(z, 0.001 * (zs + 2.5));
            assert_bits_equal(tirenv_profile_x(p)[k], x);
            assert_bits_equal(tirenv_profile_z(p)[k], z);
        }
        double x, z;
        int got = 1;
        assert_int_equal(tirenv_profile_file_reader_next(r, &x, &z, &got, &d), TIRENV_OK);
        assert_false(got);
        tirenv_profile_file_reader_free(r);
        tirenv_profile_free(p);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plateau),
        cmocka_unit_test_setup_teardown(test_poly_line, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_plank, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_flat, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_round_trip, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_malformed, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_checked_in_passing, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_long_road, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
