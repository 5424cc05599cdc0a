/* The .tir reader, --set and writer, and the all-or-nothing output file.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/cam.h"
#include "tirenv/model.h"
#include "tirenv/outfile.h"
#include "tirenv/tir.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- helpers ------------------------------------------------------------------------- */

static int file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static void assert_tire_identical(const tirenv_tire *a, const tirenv_tire *b)
{
    assert_bits_equal(a->springs.R0, b->springs.R0);
    assert_bits_equal(a->springs.c_r, b->springs.c_r);
    assert_bits_equal(a->springs.c_b, b->springs.c_b);
    assert_bits_equal(a->springs.phi, b->springs.phi);
    assert_bits_equal(a->springs.dphi, b->springs.dphi);
    assert_bits_equal(a->width, b->width);
    assert_bits_equal(a->k_z, b->k_z);
    assert_bits_equal(a->ring.t_r, b->ring.t_r);
    assert_bits_equal(a->ring.EI, b->ring.EI);
    assert_bits_equal(a->ring.T, b->ring.T);
    assert_bits_equal(a->ring.k_c, b->ring.k_c);
    assert_bits_equal(a->ring.k_t, b->ring.k_t);
    assert_bits_equal(a->ring.G_t, b->ring.G_t);
    assert_bits_equal(a->ring.dtheta, b->ring.dtheta);
    assert_bits_equal(a->ring.lug_count, b->ring.lug_count);
    assert_bits_equal(a->ring.lug_fraction, b->ring.lug_fraction);
    assert_bits_equal(a->ring.lug_ratio, b->ring.lug_ratio);
    assert_bits_equal(a->ring.b_p, b->ring.b_p);
    assert_bits_equal(a->ring.alpha_s, b->ring.alpha_s);
    assert_bits_equal(a->ring.p, b->ring.p);
    assert_bits_equal(a->ring.p_nom, b->ring.p_nom);
    assert_int_equal(a->ring.contact, b->ring.contact);
    assert_int_equal(a->eq.method, b->eq.method);
    assert_bits_equal(a->eq.eps_F, b->eq.eps_F);
    assert_bits_equal(a->eq.eps_z, b->eq.eps_z);
    assert_int_equal(a->eq.max_iter, b->eq.max_iter);
    assert_bits_equal(a->eq.secant_dz, b->eq.secant_dz);
    assert_bits_equal(a->cam.c_z, b->cam.c_z);
    assert_bits_equal(a->cam.fnomin, b->cam.fnomin);
    assert_bits_equal(a->cam.q_fz2, b->cam.q_fz2);
    assert_bits_equal(a->cam.q_fz1, b->cam.q_fz1);
    assert_bits_equal(a->cam.pfz1, b->cam.pfz1);
    assert_bits_equal(a->cam.q_ra1, b->cam.q_ra1);
    assert_bits_equal(a->cam.q_ra2, b->cam.q_ra2);
    assert_bits_equal(a->cam.shift, b->cam.shift);
    assert_bits_equal(a->cam.length, b->cam.length);
    assert_bits_equal(a->cam.height, b->cam.height);
    assert_bits_equal(a->cam.order, b->cam.order);
}

/* t written to name in the fixture's directory and read back over the default tire into
 * *back: the same tire, bit for bit. */
static void assert_round_trip(void *fx, const char *name, const tirenv_tire *t,
                              tirenv_tire *back)
{
    char path[600];
    tirenv_diag d;
    assert_int_equal(tirenv_tir_write(tirenv_test_path(fx, name, path), t, &d), TIRENV_OK);
    *back = tirenv_tire_default();
    assert_int_equal(tirenv_tir_read(path, back, &d), TIRENV_OK);
    assert_tire_identical(back, t);
}

/* Physical, but unlike the default in every field: a file read over it must set them all. */
static tirenv_tire entropic_tire(void)
{
    return (tirenv_tire){
        .springs = {.R0 = 0.6837, .c_r = 1.5831e6, .c_b = 8734.29, .phi = 2.9137,
                    .dphi = 0.0071893},
        .ring = {.t_r = 0.0417, .EI = 613.7, .T = 31872.5, .k_c = 1.0931e6, .k_t = 3.8317e6,
                 .G_t = 7.317e5, .dtheta = 0.0093731, .lug_count = 23, .lug_fraction = 0.4371,
                 .lug_ratio = 0.3119, .b_p = 0.3271, .alpha_s = 1.1173, .p = 137913.7,
                 .p_nom = 151374.9},
        .eq = {.method = TIRENV_EQ_BRENT, .eps_F = 3.7e-7, .eps_z = 2.9e-11, .max_iter = 73,
               .secant_dz = 7.31e-4},
        .cam = {.c_z = 413927.3, .fnomin = 4137.5, .q_fz2 = 13.71, .q_fz1 = 11.37,
                .pfz1 = 0.613, .q_ra1 = 0.7131, .q_ra2 = -0.2417, .shift = 0.7913,
                .length = 1.3171, .height = 0.8837, .order = 1.8131},
        .width = 0.3917,
    };
}

/* ---- reading ------------------------------------------------------------------------- */

static void test_default_file_matches_builtin(void **state)
{
    (void)state;
    tirenv_tire t = entropic_tire();
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const int status = tirenv_tir_read(TIRENV_DATA_DIR "/tires/default.tir", &t, &d);
    assert_int_equal(status, TIRENV_OK);
    const tirenv_tire def = tirenv_tire_default();
    assert_tire_identical(&t, &def);
}

/* An MF-Tyre file: extra sections, a [SHAPE] table, [DIMENSION], [VERTICAL] and
 * [CONTACT_PATCH] keys of other models, 'Newton' capitalised. Only UNLOADED_RADIUS,
 * VERTICAL_STIFFNESS, FNOMIN, VERTICAL_DAMPING, the cam keys present (Q_RA1, Q_RA2,
 * ELLIPS_SHIFT) and [OPERATING_CONDITIONS] INFLPRES and NOMPRES (the ring's air) are taken. */
static void test_mftyre_excerpt_loads(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const int status = tirenv_tir_read(TIRENV_TEST_DATA "/tir_mftyre.tir", &t, &d);
    assert_int_equal(status, TIRENV_OK);
    tirenv_tire expected = tirenv_tire_default();
    expected.springs.R0 = 0.7125;
    expected.width = 0.42;
    expected.cam.c_z = 520000;
    expected.cam.fnomin = 24000;
    expected.cam.q_fz2 = 0;  /* none in the file: a linear law, not the default tire's */
    expected.k_z = 2500;     /* its VERTICAL_DAMPING, the ride's c_t */
    expected.cam.q_ra1 = 0.6715;
    expected.cam.q_ra2 = 0.7308;
    expected.cam.shift = 0.8328;
    expected.ring.p = 140000;
    expected.ring.p_nom = 160000;
    assert_tire_identical(&t, &expected);
}

static void test_comments_and_case(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_write_text(tirenv_test_path(fx, "case.tir", path),
               "\xEF\xBB\xBF$ a BOM, a leading comment, then lower-case names\r\n"
               "  [ dimension ]  $ spaces inside the brackets\r\n"
               "unloaded_radius=0.6837$no space before the comment\r\n"
               "[ENVELOPING_SOLVER]\n"
               "METHOD = 'Secant' $ names are not case-sensitive\n"
               "! a bang comment inside a section\n"
               "MAX_ITERATIONS = 37\n"
               "[MODEL]\n"
               "this line is not KEY = value, but the section is not ours\n");
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
    assert_bits_equal(t.springs.R0, 0.6837);
    assert_bits_equal(t.width, 0);  /* no WIDTH in the file: none, not the tire's before */
    assert_int_equal(t.eq.method, TIRENV_EQ_SECANT);
    assert_int_equal(t.eq.max_iter, 37);
}

typedef tirenv_test_read_error read_error_case;

static const read_error_case read_errors[] = {
    /* typos in our own sections */
    {"[ENVELOPING_SPRINGS]\nRADIAL_STIFNESS = 1.6e6\n", TIRENV_EPARSE, 2, 1,
     "RADIAL_STIFNESS", "unknown key in [ENVELOPING_SPRINGS]; expected one of RADIAL_STIFFNESS"},
    {"[ENVELOPING_SOLVER]\nMETHOD = 'newton'\n  TOLERANCE = 1e-6\n", TIRENV_EPARSE, 3, 3,
     "TOLERANCE", "expected one of METHOD, FORCE_TOLERANCE"},
    {"[ENVELOPING_SPRING]\nRADIAL_STIFFNESS = 1.6e6\n", TIRENV_EPARSE, 1, 2,
     "ENVELOPING_SPRING", "unknown section"},
    /* numbers */
    {"[DIMENSION]\nUNLOADED_RADIUS = abc\n", TIRENV_EPARSE, 2, 19, "UNLOADED_RADIUS",
     "expected a number, got 'abc'"},
    {"[ENVELOPING_SPRINGS]\nRADIAL_STIFFNESS = 1.6e6x  $ comment\n", TIRENV_EPARSE, 2, 25,
     "RADIAL_STIFFNESS", "unexpected 'x' after the number 1.6e6"},
    {"[ENVELOPING_SPRINGS]\nRADIAL_STIFFNESS = 1.6e6 N/m/rad\n", TIRENV_EPARSE, 2, 26,
     "RADIAL_STIFFNESS", "after the number"},
    {"[ENVELOPING_SOLVER]\nFORCE_TOLERANCE = inf\n", TIRENV_EPARSE, 2, 19, "FORCE_TOLERANCE",
     "expected a finite number"},
    {"[ENVELOPING_SPRINGS]\nSEGMENT_ANGLE = nan\n", TIRENV_EPARSE, 2, 17, "SEGMENT_ANGLE",
     "expected a finite number"},
    {"[DIMENSION]\nUNLOADED_RADIUS = 1e999\n", TIRENV_EPARSE, 2, 19, "UNLOADED_RADIUS",
     "expected a finite number"},
    {"[DIMENSION]\nUNLOADED_RADIUS = '0.68'\n", TIRENV_EPARSE, 2, 19, "UNLOADED_RADIUS",
     "expected a number, got the string"},
    {"[DIMENSION]\nUNLOADED_RADIUS =   $ nothing\n", TIRENV_EPARSE, 2, 21, "UNLOADED_RADIUS",
     "missing value"},
    {"[ENVELOPING_SOLVER]\nMAX_ITERATIONS = 2.5\n", TIRENV_EPARSE, 2, 19, "MAX_ITERATIONS",
     "expected a positive integer"},
    {"[ENVELOPING_SOLVER]\nMAX_ITERATIONS = -3\n", TIRENV_EPARSE, 2, 18, "MAX_ITERATIONS",
     "expected a positive integer"},
    {"[ENVELOPING_SOLVER]\nMAX_ITERATIONS = 0\n", TIRENV_EPARSE, 2, 18, "MAX_ITERATIONS",
     "expected a positive integer"},
    {"[ENVELOPING_SOLVER]\nMETHOD = 'bisect'\n", TIRENV_EPARSE, 2, 11, "METHOD",
     "unknown method 'bisect'; expected 'newton', 'secant' or 'brent'"},
    /* structure */
    {"[ENVELOPING_SPRINGS]\nRADIAL_STIFFNESS = 1.6e6\nINTERRADIAL_STIFFNESS = 1e4\n"
     "RADIAL_STIFFNESS = 1.7e6\n", TIRENV_EPARSE, 4, 1, "RADIAL_STIFFNESS",
     "duplicate key (first set on line 2)"},
    {"[DIMENSION]\nUNLOADED_RADIUS = 0.7\n[VERTICAL]\nFNOMIN = 1\n[DIMENSION]\n"
     "unloaded_radius = 0.7\n", TIRENV_EPARSE, 6, 1, "UNLOADED_RADIUS", "duplicate key"},
    {"[ENVELOPING_SPRINGS]\nRADIAL_STIFFNESS 1.6e6\n", TIRENV_EPARSE, 2, 17,
     "RADIAL_STIFFNESS", "missing '='; expected KEY = value"},
    {"[DIMENSION]\n= 0.7\n", TIRENV_EPARSE, 2, 1, "", "missing key"},
    {"[MDI_HEADER]\nFILE_TYPE='tir'\n\n[ENVELOPING_SPRINGS\nRADIAL_STIFFNESS = 1e6\n",
     TIRENV_EPARSE, 4, 1, "", "unterminated section header; expected ']'"},
    {"[DIMENSION] UNLOADED_RADIUS = 0.7\n", TIRENV_EPARSE, 1, 13, "",
     "after the section header"},
    {"[]\n", TIRENV_EPARSE, 1, 1, "", "empty section name"},
    {"UNLOADED_RADIUS = 0.7\n[DIMENSION]\n", TIRENV_EPARSE, 1, 1, "",
     "before the first section"},
    /* units: the ones MF-Tyre and Adams files use, converted; others refused */
    {"[UNITS]\nLENGTH = 'meter'\nFORCE = 'kip'\n[DIMENSION]\nUNLOADED_RADIUS = 0.7\n",
     TIRENV_EPARSE, 3, 10, "FORCE", "unknown unit 'kip'; expected one of 'newtons'"},
    {"[UNITS]\nANGLE = 'gradians'\n", TIRENV_EPARSE, 2, 10, "ANGLE",
     "unknown unit 'gradians'; expected one of 'radians', 'degrees'"},
    {"[UNITS]\nLENGTH = 'meter\n", TIRENV_EPARSE, 2, 10, "LENGTH", "unterminated string"},
    {"[UNITS]\nSPEED = 'm/s'\n", TIRENV_EPARSE, 2, 1, "SPEED", "unknown key in [UNITS]"},
    {"[UNITS]\nLENGTH = 'mm'\n", TIRENV_EPARSE, 2, 0, "",
     "the file sets none of the keys tirenv reads; expected at least one, such as "
     "[DIMENSION] UNLOADED_RADIUS"},
    {"", TIRENV_EPARSE, 0, 0, "", "the empty file sets none of the keys tirenv reads"},
    {"$ nothing but comments\n\n! and more\n", TIRENV_EPARSE, 3, 0, "",
     "sets none of the keys"},
    {"[MDI_HEADER]\nFILE_TYPE = 'tir'\n[VERTICAL]\nQ_V2 = 0.04\n", TIRENV_EPARSE, 4, 0,
     "", "sets none of the keys"},
    /* a key tirenv reads, in another section tirenv reads: it would be ignored there */
    {"[DIMENSION]\nUNLOADED_RADIUS = 0.7\nRADIAL_STIFFNESS = 1.6e6\n", TIRENV_EPARSE, 3, 1,
     "RADIAL_STIFFNESS", "key of [ENVELOPING_SPRINGS] in [DIMENSION]; expected it in "
     "[ENVELOPING_SPRINGS]"},
    {"[VERTICAL]\nQ_RA1 = 0.7\n", TIRENV_EPARSE, 2, 1, "Q_RA1",
     "key of [CONTACT_PATCH] in [VERTICAL]"},
    {"[ENVELOPING_RING]\nUNLOADED_RADIUS = 0.7\n", TIRENV_EPARSE, 2, 1, "UNLOADED_RADIUS",
     "key of [DIMENSION] in [ENVELOPING_RING]"},
    /* parsed fine, but unphysical: the line of the key, no column */
    {"[MDI_HEADER]\nFILE_TYPE = 'tir'\n[ENVELOPING_SPRINGS]\nSEGMENT_ANGLE = 3.0\n"
     "RADIAL_STIFFNESS = -1.6e6 $ sign typo\n", TIRENV_EINVAL, 5, 0, "RADIAL_STIFFNESS",
     "must be positive"},
    {"[DIMENSION]\nUNLOADED_RADIUS = 0\n", TIRENV_EINVAL, 2, 0, "UNLOADED_RADIUS",
     "must be a positive length"},
    {"[ENVELOPING_SPRINGS]\nSEGMENT_ANGLE = 3.0\n\nELEMENT_ANGLE = 1.6\n", TIRENV_EINVAL, 4,
     0, "ELEMENT_ANGLE", "SEGMENT_ANGLE/2"},
    {"[ENVELOPING_SOLVER]\nMETHOD = 'secant'\nFORCE_TOLERANCE = -1e-6\n", TIRENV_EINVAL, 3, 0,
     "FORCE_TOLERANCE", "positive"},
    {"[ENVELOPING_SOLVER]\nMAX_ITERATIONS = 1\n", TIRENV_EINVAL, 2, 0, "MAX_ITERATIONS",
     "at least 2"},
    {"[ENVELOPING_SOLVER]\nSECANT_STEP = -1e-3\n", TIRENV_EINVAL, 2, 0, "SECANT_STEP",
     "positive"},
    {"[VERTICAL]\nFNOMIN = 4000\n\n[CONTACT_PATCH]\nQ_RB1 = 1\nELLIPS_ORDER = 0.9\n",
     TIRENV_EINVAL, 6, 0, "ELLIPS_ORDER", "greater than 1"},
    {"[CONTACT_PATCH]\nELLIPS_SHIFT = 0.8 mm\n", TIRENV_EPARSE, 2, 20, "ELLIPS_SHIFT",
     "after the number"},
};

static void test_read_errors(void **state)
{
    tirenv_test_dir *fx = *state;
    for (size_t i = 0; i < sizeof read_errors / sizeof read_errors[0]; i++) {
        const read_error_case *k = &read_errors[i];
        char path[600], name[32];
        snprintf(name, sizeof name, "err%02zu.tir", i);
        tirenv_test_write_text(tirenv_test_path(fx, name, path), k->text);
        const tirenv_tire before = entropic_tire();
        tirenv_tire t = before;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        const int status = tirenv_tir_read(path, &t, &d);
        tirenv_test_expect_diag(i, status, &d, k->status, path, k->line, k->column, k->field,
                                k->says);
        assert_tire_identical(&t, &before);
    }
}

static void test_missing_file(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_path(fx, "no-such.tir", path);
    tirenv_tire t = entropic_tire();
    const tirenv_tire before = t;
    tirenv_diag d;
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_EIO);
    assert_string_equal(d.file, path);
    assert_non_null(strstr(d.message, strerror(ENOENT)));
    assert_tire_identical(&t, &before);
    /* A directory opens for reading on Linux; the error comes from the first read. */
    assert_int_equal(tirenv_tir_read(fx->dir, &t, &d), TIRENV_EIO);
    assert_string_equal(d.file, fx->dir);
    assert_tire_identical(&t, &before);
}

/* ---- --set ----------------------------------------------------------------------------- */

static void test_set_good(void **state)
{
    (void)state;
    const struct {
        const char *text;
        size_t offset; /* of the double it sets */
        double value;
    } reals[] = {
        {"RADIAL_STIFFNESS=1.5831e6", offsetof(tirenv_tire, springs.c_r), 1.5831e6},
        {"  UNLOADED_RADIUS = 0.6837 ", offsetof(tirenv_tire, springs.R0), 0.6837},
        {"ENVELOPING_SPRINGS.SEGMENT_ANGLE = 2.5", offsetof(tirenv_tire, springs.phi), 2.5},
        {"dimension.unloaded_radius=0.7125", offsetof(tirenv_tire, springs.R0), 0.7125},
        {"INTERRADIAL_STIFFNESS=0", offsetof(tirenv_tire, springs.c_b), 0.0},
        {"ELEMENT_ANGLE=0.0071893", offsetof(tirenv_tire, springs.dphi), 0.0071893},
        {"FORCE_TOLERANCE=3.7e-7", offsetof(tirenv_tire, eq.eps_F), 3.7e-7},
        {"STEP_TOLERANCE=2.9e-11", offsetof(tirenv_tire, eq.eps_z), 2.9e-11},
        {"SECANT_STEP=7.31e-4", offsetof(tirenv_tire, eq.secant_dz), 7.31e-4},
        {"VERTICAL_STIFFNESS=413927.3", offsetof(tirenv_tire, cam.c_z), 413927.3},
        {"vertical.vertical_stiffness=2.1e5", offsetof(tirenv_tire, cam.c_z), 2.1e5},
        {"FNOMIN=4137.5", offsetof(tirenv_tire, cam.fnomin), 4137.5},
        {"VERTICAL.Q_FZ2=13.71", offsetof(tirenv_tire, cam.q_fz2), 13.71},
        {"Q_RA1=0.7131", offsetof(tirenv_tire, cam.q_ra1), 0.7131},
        {"CONTACT_PATCH.Q_RA2 = -0.2417", offsetof(tirenv_tire, cam.q_ra2), -0.2417},
        {"ELLIPS_SHIFT=0.7913", offsetof(tirenv_tire, cam.shift), 0.7913},
        {"ELLIPS_LENGTH=1.3171", offsetof(tirenv_tire, cam.length), 1.3171},
        {"ELLIPS_HEIGHT=0.8837", offsetof(tirenv_tire, cam.height), 0.8837},
        {"ELLIPS_ORDER=1.8131", offsetof(tirenv_tire, cam.order), 1.8131},
    };
    for (size_t i = 0; i < sizeof reals / sizeof reals[0]; i++) {
        tirenv_tire t = tirenv_tire_default();
        tirenv_diag d;
        assert_int_equal(tirenv_tir_set(&t, reals[i].text, &d), TIRENV_OK);
        double got;
        memcpy(&got, (const unsigned char *)&t + reals[i].offset, sizeof got);
        assert_bits_equal(got, reals[i].value);
    }
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    assert_int_equal(tirenv_tir_set(&t, "METHOD=secant", &d), TIRENV_OK);
    assert_int_equal(t.eq.method, TIRENV_EQ_SECANT);
    assert_int_equal(tirenv_tir_set(&t, "METHOD = 'brent'", &d), TIRENV_OK);
    assert_int_equal(t.eq.method, TIRENV_EQ_BRENT);
    assert_int_equal(tirenv_tir_set(&t, "MAX_ITERATIONS=37", &d), TIRENV_OK);
    assert_int_equal(t.eq.max_iter, 37);
}

static void test_set_errors(void **state)
{
    (void)state;
    const struct {
        const char *text;
        int status;
        const char *field;
        const char *says;
    } cases[] = {
        {"RADIAL_STIFFNESS", TIRENV_EPARSE, "", "expected KEY=VALUE, got 'RADIAL_STIFFNESS'"},
        {"RADIAL_STIFNESS=1e6", TIRENV_EPARSE, "RADIAL_STIFNESS", "unknown key; expected one of"},
        {"ASPECT_RATIO=0.85", TIRENV_EPARSE, "ASPECT_RATIO", "unknown key"},
        {"WIDTH=-0.42", TIRENV_EINVAL, "WIDTH", "length >= 0"},
        {"LENGTH=meter", TIRENV_EPARSE, "LENGTH", "unknown key"},
        {"DIMENSION.RADIAL_STIFFNESS=1e6", TIRENV_EPARSE, "RADIAL_STIFFNESS",
         "unknown key in section DIMENSION"},
        {"=5", TIRENV_EPARSE, "", "unknown key"},
        {"RADIAL_STIFFNESS=abc", TIRENV_EPARSE, "RADIAL_STIFFNESS", "expected a number"},
        {"RADIAL_STIFFNESS=1e6 N", TIRENV_EPARSE, "RADIAL_STIFFNESS", "after the number"},
        {"STEP_TOLERANCE=", TIRENV_EPARSE, "STEP_TOLERANCE", "missing value"},
        {"ELEMENT_ANGLE=nan", TIRENV_EPARSE, "ELEMENT_ANGLE", "finite"},
        {"METHOD=bisect", TIRENV_EPARSE, "METHOD", "unknown method"},
        {"MAX_ITERATIONS=1e3", TIRENV_EPARSE, "MAX_ITERATIONS", "positive integer"},
        {"RADIAL_STIFFNESS=-1e6", TIRENV_EINVAL, "RADIAL_STIFFNESS", "must be positive"},
        {"MAX_ITERATIONS=1", TIRENV_EINVAL, "MAX_ITERATIONS", "at least 2"},
        {"ELEMENT_ANGLE=3", TIRENV_EINVAL, "ELEMENT_ANGLE", "SEGMENT_ANGLE/2"},
        {"ELLIPS_ORDER=1", TIRENV_EINVAL, "ELLIPS_ORDER", "greater than 1"},
        {"VERTICAL_STIFFNESS=0", TIRENV_EINVAL, "VERTICAL_STIFFNESS", "must be positive"},
        {"DIMENSION.Q_RA1=0.7", TIRENV_EPARSE, "Q_RA1", "unknown key in section DIMENSION"},
        {"Q_V2=0.04", TIRENV_EPARSE, "Q_V2", "ELLIPS_ORDER"}, /* listed among the keys */
        {"FNOMIN=-4000", TIRENV_EINVAL, "FNOMIN", "zero (none) or positive"},
        {"Q_FZ2=inf", TIRENV_EPARSE, "Q_FZ2", "finite"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const tirenv_tire before = entropic_tire();
        tirenv_tire t = before;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        const int status = tirenv_tir_set(&t, cases[i].text, &d);
        tirenv_test_expect_diag(i, status, &d, cases[i].status, "--set", 0, 0, cases[i].field,
                                cases[i].says);
        assert_tire_identical(&t, &before);
    }
}

/* ---- writing --------------------------------------------------------------------------- */

/* Values that need all 17 digits, extremes of the ranges (the double range's where the
 * plausible range allows it: DBL_MIN, the smallest subnormal), and everyday values that
 * must come out short (0.68, not 0.68000000000000005). */
static void test_write_read_round_trip(void **state)
{
    tirenv_test_dir *fx = *state;
    tirenv_tire extreme = entropic_tire();
    extreme.springs.R0 = 0.1 + 0.2; /* 0.30000000000000004 */
    extreme.springs.c_r = nextafter(1e12, 0); /* the largest below the range's top */
    extreme.springs.c_b = 0.0;
    extreme.springs.phi = M_PI;
    extreme.springs.dphi = M_PI / 7.0;
    extreme.eq.method = TIRENV_EQ_SECANT;
    extreme.eq.eps_F = DBL_MIN;
    extreme.eq.eps_z = 4.9406564584124654e-324; /* the smallest subnormal */
    extreme.eq.max_iter = 2;
    extreme.eq.secant_dz = 0.1 / 3.0;
    const tirenv_tire tires[] = {entropic_tire(), tirenv_tire_default(), extreme};
    for (size_t i = 0; i < sizeof tires / sizeof tires[0]; i++) {
        char path[600];
        tirenv_test_path(fx, "rt.tir", path);
        tirenv_diag d;
        assert_int_equal(tirenv_tir_write(path, &tires[i], &d), TIRENV_OK);
        tirenv_tire back = i == 0 ? tirenv_tire_default() : entropic_tire();
        assert_int_equal(tirenv_tir_read(path, &back, &d), TIRENV_OK);
        assert_tire_identical(&back, &tires[i]);
    }
    assert_int_equal(tirenv_test_count_entries(fx, "tmp."), 0);

    char path[600], text[8192];
    tirenv_test_path(fx, "default.tir", path);
    tirenv_diag d;
    const tirenv_tire def = tirenv_tire_default();
    assert_int_equal(tirenv_tir_write(path, &def, &d), TIRENV_OK);
    tirenv_test_read_text(path, text, sizeof text);
    assert_non_null(strstr(text, "[MDI_HEADER]\nFILE_TYPE                = 'tir'\n"));
    assert_non_null(strstr(text, "\nUNLOADED_RADIUS          = 0.68 "));
    assert_non_null(strstr(text, "\nMETHOD                   = 'newton' "));
    assert_non_null(strstr(text, "\nLENGTH                   = 'meter' "));
    const char *line = strstr(text, "\nTREAD_SHEAR              = ");
    assert_non_null(line);
    assert_true(def.ring.G_t > 0); /* the default's 0.25 MPa */
    assert_true(strtod(line + 28, NULL) == def.ring.G_t);
    /* The Winkler tread's 0 is written as such. */
    tirenv_tire winkler = def;
    winkler.ring.G_t = 0;
    assert_int_equal(tirenv_tir_write(path, &winkler, &d), TIRENV_OK);
    tirenv_test_read_text(path, text, sizeof text);
    assert_non_null(strstr(text, "\nTREAD_SHEAR              = 0 "));
    const tirenv_tire sheared = entropic_tire();
    assert_int_equal(tirenv_tir_write(path, &sheared, &d), TIRENV_OK);
    tirenv_test_read_text(path, text, sizeof text);
    line = strstr(text, "\nTREAD_SHEAR              = ");
    assert_non_null(line);
    assert_true(strtod(line + 28, NULL) == sheared.ring.G_t);
}

static void test_write_refuses_unphysical(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_path(fx, "bad.tir", path);
    tirenv_tire t = tirenv_tire_default();
    t.springs.c_r = -1.6e6;
    tirenv_diag d;
    assert_int_equal(tirenv_tir_write(path, &t, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "RADIAL_STIFFNESS");
    assert_false(file_exists(path));
    assert_int_equal(tirenv_test_count_entries(fx, "tmp."), 0);
}

static void test_write_into_missing_dir(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_path(fx, "no-such-dir/x.tir", path);
    const tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    assert_int_equal(tirenv_tir_write(path, &t, &d), TIRENV_EIO);
    assert_string_equal(d.file, path);
    assert_non_null(strstr(d.message, strerror(ENOENT)));
}

/* ---- output files ---------------------------------------------------------------------- */

static void test_outfile_commit(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600], text[64];
    tirenv_test_path(fx, "out.csv", path);
    const mode_t old_mask = umask(027);
    tirenv_outfile *f;
    tirenv_diag d;
    assert_int_equal(tirenv_outfile_open(&f, path, &d), TIRENV_OK);
    fputs("x_m,z_m\n", tirenv_outfile_stream(f));
    /* Until commit, readers see no target, only the temporary file. */
    assert_false(file_exists(path));
    assert_int_equal(tirenv_test_count_entries(fx, ".out.csv.tirenv-tmp."), 1);
    assert_int_equal(tirenv_outfile_commit(f, &d), TIRENV_OK);
    umask(old_mask);
    tirenv_test_read_text(path, text, sizeof text);
    assert_string_equal(text, "x_m,z_m\n");
    assert_int_equal(tirenv_test_count_entries(fx, "tmp."), 0);
    /* mkstemp's 0600 would surprise; a new file gets 0666 minus the umask, like fopen. */
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    assert_int_equal(st.st_mode & 0777, 0640);
    assert_true(file_exists(path));
}

static void test_outfile_abort(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_path(fx, "out.csv", path);
    tirenv_outfile *f;
    tirenv_diag d;
    assert_int_equal(tirenv_outfile_open(&f, path, &d), TIRENV_OK);
    fputs("half a fi", tirenv_outfile_stream(f));
    tirenv_outfile_abort(f);
    tirenv_outfile_abort(NULL); /* a no-op, as after a failed open */
    assert_false(file_exists(path));
    assert_int_equal(tirenv_test_count_entries(fx, "tmp."), 0);
    assert_int_equal(tirenv_test_count_entries(fx, ""), 0);
    assert_int_equal(tirenv_outfile_commit(NULL, &d), TIRENV_EINVAL);
    assert_false(file_exists(path));
}

static void test_outfile_replaces_existing(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600], text[64];
    tirenv_test_path(fx, "out.csv", path);
    tirenv_test_write_text(path, "old contents, longer than the new ones\n");
    assert_int_equal(chmod(path, 0604), 0);
    tirenv_outfile *f;
    tirenv_diag d;
    assert_int_equal(tirenv_outfile_open(&f, path, &d), TIRENV_OK);
    fputs("new\n", tirenv_outfile_stream(f));
    tirenv_test_read_text(path, text, sizeof text); /* the old file is intact until commit */
    assert_string_equal(text, "old contents, longer than the new ones\n");
    assert_int_equal(tirenv_outfile_commit(f, &d), TIRENV_OK);
    tirenv_test_read_text(path, text, sizeof text);
    assert_string_equal(text, "new\n");
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    assert_int_equal(st.st_mode & 0777, 0604); /* the replaced file's mode is kept */
    assert_int_equal(tirenv_test_count_entries(fx, ""), 1);
}

static void test_outfile_errors(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_path(fx, "missing/out.csv", path);
    tirenv_outfile *f;
    tirenv_diag d;
    assert_int_equal(tirenv_outfile_open(&f, path, &d), TIRENV_EIO);
    assert_string_equal(d.file, path);
    assert_non_null(strstr(d.message, strerror(ENOENT)));
    assert_null(f);
    tirenv_outfile_abort(f); /* after a failed open: harmless */

    char long_path[1100];
    memset(long_path, 'a', sizeof long_path - 1);
    long_path[sizeof long_path - 1] = '\0';
    assert_int_equal(tirenv_outfile_open(&f, long_path, &d), TIRENV_EINVAL);
    assert_null(f);
    assert_int_equal(tirenv_outfile_open(&f, "", &d), TIRENV_EINVAL);
    assert_null(f);
}

static void test_outfile_stdout(void **state)
{
    (void)state;
    tirenv_outfile *f;
    tirenv_diag d;
    assert_int_equal(tirenv_outfile_open(&f, "-", &d), TIRENV_OK);
    assert_ptr_equal(tirenv_outfile_stream(f), stdout);
    assert_int_equal(tirenv_outfile_commit(f, &d), TIRENV_OK);
    assert_int_equal(fflush(stdout), 0); /* commit did not close stdout */
    assert_true(fcntl(STDOUT_FILENO, F_GETFD) >= 0);
}

/* ---- real MF-Tyre / PAC2002 files ------------------------------------------------------ */

/* Every sample .tir of the ecosystem loads unchanged: the radius and vertical stiffness are
 * the file's (in SI whatever [UNITS] says), the cam keys given where the file has them. */
static void test_sample_tir_files(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        double R0, c_z;
        unsigned given;
    } cases[] = {
        {"335_65R22_5_G275MSA_60psi.tir", 0.4987, 5.6519e5, TIRENV_CAM_C_Z},
        {"HMMWV_Pac02Tire.tir", 0.4699, 1e6, TIRENV_CAM_C_Z},
        {"tractor_430_50R38.tir", 0.6731, 1e6, TIRENV_CAM_ALL},
        {"mf_185_80R14.tir", 0.376, 1.75e5, TIRENV_CAM_C_Z},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char path[600];
        snprintf(path, sizeof path, "%s/tir/%s", TIRENV_SAMPLES, cases[k].name);
        if (access(path, R_OK) != 0) {
            print_error("sample file %s is missing\n", path);
            fail();
        }
        tirenv_tire t = tirenv_tire_default();
        tirenv_diag d;
        tirenv_diag_clear(&d);
        const int status = tirenv_tir_read(path, &t, &d);
        char line[1200];
        print_message("%s: %s\n", cases[k].name,
                      status ? tirenv_diag_format(&d, line, sizeof line) : "ok");
        assert_int_equal(status, TIRENV_OK);
        assert_bits_equal(t.springs.R0, cases[k].R0);
        assert_bits_equal(t.cam.c_z, cases[k].c_z);
        assert_int_equal(t.cam.given, cases[k].given);
        assert_int_equal(tirenv_tire_check_cam_keys(&t, &d),
                         cases[k].given == TIRENV_CAM_ALL ? TIRENV_OK : TIRENV_EINVAL);
        if (cases[k].given != TIRENV_CAM_ALL) {
            assert_string_equal(d.field, "Q_RA1");
            assert_non_null(strstr(d.message, "Q_RA1, Q_RA2, ELLIPS_SHIFT, ELLIPS_LENGTH, "
                                              "ELLIPS_HEIGHT, ELLIPS_ORDER"));
        }
    }
}

/* Values in the file's [UNITS] come out in SI, whatever the order of the sections: each
 * factor worked out by hand from the unit's definition. */
static void test_units_converted(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_write_text(tirenv_test_path(fx, "units.tir", path),
                           "[DIMENSION]\nUNLOADED_RADIUS = 680\n"
                           "[VERTICAL]\nVERTICAL_STIFFNESS = 0.342  $ kN/mm\n"
                           "[ENVELOPING_SPRINGS]\nRADIAL_STIFFNESS = 27.925  $ kN/mm/deg\n"
                           "INTERRADIAL_STIFFNESS = 573  $ kN*deg/mm\n"
                           "SEGMENT_ANGLE = 180\nELEMENT_ANGLE = 0.5\n"
                           "[ENVELOPING_RING]\nBELT_BENDING_STIFFNESS = 5e5  $ kN*mm^2\n"
                           "FOUNDATION_STIFFNESS = 1.3e-3  $ kN/mm^2\nNODE_ANGLE = 1\n"
                           "[ENVELOPING_SOLVER]\nFORCE_TOLERANCE = 1e-9\n"
                           "STEP_TOLERANCE = 1e-7\n"
                           "[UNITS]\nLENGTH = 'mm'\nFORCE = 'KN'\nANGLE = 'Degrees'\n"
                           "MASS = 'tonne'\nTIME = 'milli'\nPRESSURE = 'psi'\n");
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const int status = tirenv_tir_read(path, &t, &d);
    char msg[1200];
    print_message("%s\n", tirenv_diag_format(&d, msg, sizeof msg));
    assert_int_equal(status, TIRENV_OK);
    const double deg = M_PI / 180;
    assert_near(t.springs.R0, 0.68, 1e-15, 0);
    assert_near(t.cam.c_z, 342e3, 0, 1e-15);
    assert_near(t.springs.c_r, 27.925e3 / 1e-3 / deg, 0, 1e-15);
    assert_near(t.springs.c_b, 573e3 * deg / 1e-3, 0, 1e-15);
    assert_near(t.springs.phi, M_PI, 0, 1e-15);
    assert_near(t.springs.dphi, M_PI / 360, 0, 1e-15);
    assert_near(t.ring.EI, 5e5 * 1e3 * 1e-6, 0, 1e-15);
    assert_near(t.ring.k_c, 1.3e-3 * 1e3 / 1e-6, 0, 1e-15);
    assert_near(t.ring.dtheta, deg, 0, 1e-15);
    assert_near(t.eq.eps_F, 1e-6, 0, 1e-15);
    assert_near(t.eq.eps_z, 1e-10, 0, 1e-15);
    /* Imperial units, and the spellings of the Adams documentation. */
    tirenv_test_write_text(path, "[UNITS]\nLENGTH = 'inch'\nFORCE = 'pound_force'\n"
                                 "ANGLE = 'rad'\nMASS = 'slug'\nTIME = 'sec'\n"
                                 "PRESSURE = 'bar'\n[DIMENSION]\nUNLOADED_RADIUS = 26.77\n"
                                 "[VERTICAL]\nVERTICAL_STIFFNESS = 1954\n");
    t = tirenv_tire_default();
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
    assert_near(t.springs.R0, 26.77 * 0.0254, 0, 1e-15);
    assert_near(t.cam.c_z, 1954 * 0.45359237 * 9.80665 / 0.0254, 0, 1e-15);
    /* --set is in SI, whatever units the file had. */
    assert_int_equal(tirenv_tir_set(&t, "UNLOADED_RADIUS=0.7", &d), TIRENV_OK);
    assert_bits_equal(t.springs.R0, 0.7);
}

/* Which cam keys a tire has of its own: a file sets the bits of the keys it holds and clears
 * the others; --set sets its key's. */
static void test_cam_keys_given(void **state)
{
    tirenv_test_dir *fx = *state;
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    assert_int_equal(t.cam.given, TIRENV_CAM_ALL);
    assert_int_equal(tirenv_tire_check_cam_keys(&t, &d), TIRENV_OK);
    char path[600];
    tirenv_test_write_text(tirenv_test_path(fx, "cam.tir", path),
                           "[DIMENSION]\nUNLOADED_RADIUS = 0.5\n"
                           "[CONTACT_PATCH]\nQ_RA1 = 0.7\nELLIPS_ORDER = 1.7\n");
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
    assert_int_equal(t.cam.given, TIRENV_CAM_Q_RA1 | TIRENV_CAM_ORDER);
    assert_int_equal(tirenv_tire_check_cam_keys(&t, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "VERTICAL_STIFFNESS");
    assert_non_null(strstr(d.message, "VERTICAL_STIFFNESS, Q_RA2, ELLIPS_SHIFT, ELLIPS_LENGTH, "
                                      "ELLIPS_HEIGHT ("));
    static const char *const sets[] = {"VERTICAL_STIFFNESS=2e5", "Q_RA2=0.8",
                                       "ELLIPS_SHIFT=0.8", "ELLIPS_LENGTH=1.4",
                                       "ELLIPS_HEIGHT=0.9"};
    for (size_t k = 0; k < 5; k++) {
        assert_int_equal(tirenv_tire_check_cam_keys(&t, &d), TIRENV_EINVAL);
        assert_int_equal(tirenv_tir_set(&t, sets[k], &d), TIRENV_OK);
    }
    assert_int_equal(t.cam.given, TIRENV_CAM_ALL);
    assert_int_equal(tirenv_tire_check_cam_keys(&t, &d), TIRENV_OK);
    /* The file written from it has every key, so it reads back whole. */
    tirenv_test_path(fx, "all.tir", path);
    assert_int_equal(tirenv_tir_write(path, &t, &d), TIRENV_OK);
    tirenv_tire back = tirenv_tire_default();
    back.cam.given = 0;
    assert_int_equal(tirenv_tir_read(path, &back, &d), TIRENV_OK);
    assert_int_equal(back.cam.given, TIRENV_CAM_ALL);
}

/* MF-Tyre's Q_FZ1 and PFZ1 (docs/formats.md section 2, models.md 7.3): read from [VERTICAL],
 * written back only when not 0 (the default's file has neither line, so the files written
 * before read and write the same), and a file without them has none, whatever the tire it is
 * read over. Through the file, the cam's deflection at FNOMIN is the closed form's of the
 * file's Q_FZ1 (VERTICAL_STIFFNESS, which would give Q_FZ1 9.15, left inconsistent) and of
 * PFZ1's factor at INFLPRES 1.6 bar on NOMPRES 2 bar: f = 1 + 0.7*(-0.2) = 0.86; to 1e-12
 * relative (the textbook root against the cam's cancellation-free form). */
static void test_own_q_fz1_and_pfz1(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600], text[8192];
    tirenv_diag d;
    tirenv_test_write_text(tirenv_test_path(fx, "q.tir", path),
                           "[DIMENSION]\nUNLOADED_RADIUS = 0.68\n"
                           "[OPERATING_CONDITIONS]\nINFLPRES = 160000\nNOMPRES = 200000\n"
                           "[VERTICAL]\nFNOMIN = 17900\nVERTICAL_STIFFNESS = 371000\n"
                           "Q_FZ1 = 12.3\nQ_FZ2 = 28.7\nPFZ1 = 0.7\n");
    tirenv_tire t = tirenv_tire_default();
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
    assert_true(t.cam.q_fz1 == 12.3 && t.cam.pfz1 == 0.7);
    const double R0 = 0.68, F0 = 17900, q1 = 12.3, q2 = 28.7, f = 1 + 0.7 * (-0.2);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &t);
    assert_non_null(m);
    tirenv_flat fl;
    assert_int_equal(tirenv_model_flat(m, F0, &fl, &d), TIRENV_OK);
    tirenv_model_free(m);
    const double rho = R0 * (-q1 + sqrt(q1 * q1 + 4 * q2 / f)) / (2 * q2);
    print_message("cam at FNOMIN: %.4f mm (closed form %.4f mm; VERTICAL_STIFFNESS alone at "
                  "NOMPRES %.4f mm)\n", 1e3 * fl.deflection, 1e3 * rho,
                  1e3 * tirenv_cam_vertical_root(R0, tirenv_cam_q_fz1(371000, R0, F0, q2), q2,
                                                 1));
    assert_near(fl.deflection, rho, 0, 1e-12);
    /* Written with both, read back the same tire. */
    tirenv_tire back;
    assert_round_trip(fx, "back.tir", &t, &back);
    /* A file without them, read over that tire, has none. */
    tirenv_test_write_text(tirenv_test_path(fx, "none.tir", path),
                           "[VERTICAL]\nVERTICAL_STIFFNESS = 2e5\n");
    assert_int_equal(tirenv_tir_read(path, &back, &d), TIRENV_OK);
    assert_true(back.cam.q_fz1 == 0 && back.cam.pfz1 == 0);
    /* The default tire's file has no Q_FZ1 or PFZ1 line; --set gives them. */
    const tirenv_tire def = tirenv_tire_default();
    tirenv_test_path(fx, "def.tir", path);
    assert_int_equal(tirenv_tir_write(path, &def, &d), TIRENV_OK);
    tirenv_test_read_text(path, text, sizeof text);
    assert_null(strstr(text, "Q_FZ1 "));
    assert_null(strstr(text, "PFZ1 "));
    tirenv_tire set = def;
    assert_int_equal(tirenv_tir_set(&set, "Q_FZ1=10.5", &d), TIRENV_OK);
    assert_int_equal(tirenv_tir_set(&set, "VERTICAL.PFZ1=0.4", &d), TIRENV_OK);
    assert_true(set.cam.q_fz1 == 10.5 && set.cam.pfz1 == 0.4);
    assert_int_equal(tirenv_tir_set(&set, "Q_FZ1=-1", &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "Q_FZ1");
    /* A factor that leaves no load: refused with the file named. */
    tirenv_test_write_text(tirenv_test_path(fx, "bad.tir", path),
                           "[OPERATING_CONDITIONS]\nINFLPRES = 100000\nNOMPRES = 200000\n"
                           "[VERTICAL]\nPFZ1 = 2.5\n");
    assert_int_equal(tirenv_tir_read(path, &back, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "PFZ1");
    assert_non_null(strstr(d.file, "bad.tir"));
    /* PFZ1 without the NOMPRES it refers to: refused, not read against the tire's 1.2 bar it
     * was read over; and that tire's NOMPRES is still there after the refusal. */
    tirenv_test_write_text(tirenv_test_path(fx, "nonom.tir", path),
                           "[OPERATING_CONDITIONS]\nINFLPRES = 160000\n[VERTICAL]\nPFZ1 = 0.7\n");
    tirenv_tire over = tirenv_tire_default();
    const double p_nom = over.ring.p_nom;
    assert_true(p_nom > 0);
    assert_int_equal(tirenv_tir_read(path, &over, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "PFZ1");
    assert_non_null(strstr(d.message, "NOMPRES"));
    assert_true(over.ring.p_nom == p_nom);
}

/* [VERTICAL] VERTICAL_DAMPING, MF-Tyre's tire damping (the ride's c_t): read in the file's
 * units; a file without it has none (NAN), not the damping of the tire it is read over, and is
 * written without it; negative refused. */
static void test_vertical_damping(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600], text[8192];
    tirenv_diag d;
    tirenv_test_write_text(tirenv_test_path(fx, "k.tir", path),
                           "[UNITS]\nLENGTH = 'mm'\n[VERTICAL]\nVERTICAL_STIFFNESS = 371\n"
                           "VERTICAL_DAMPING = 2.3719\n");
    tirenv_tire t = tirenv_tire_default();
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_OK);
    assert_near(t.k_z, 2371.9, 0, 1e-15);  /* N*s/mm to N*s/m */
    tirenv_tire back;
    assert_round_trip(fx, "back.tir", &t, &back);

    tirenv_test_write_text(tirenv_test_path(fx, "none.tir", path),
                           "[VERTICAL]\nVERTICAL_STIFFNESS = 2e5\n");
    assert_int_equal(tirenv_tir_read(path, &back, &d), TIRENV_OK);
    assert_true(isnan(back.k_z));
    tirenv_test_path(fx, "none-back.tir", path);
    assert_int_equal(tirenv_tir_write(path, &back, &d), TIRENV_OK);
    tirenv_test_read_text(path, text, sizeof text);
    assert_null(strstr(text, "VERTICAL_DAMPING"));

    tirenv_test_write_text(tirenv_test_path(fx, "neg.tir", path),
                           "[VERTICAL]\nVERTICAL_DAMPING = -50\n");
    t = tirenv_tire_default();
    assert_int_equal(tirenv_tir_read(path, &t, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "VERTICAL_DAMPING");
    assert_bits_equal(t.k_z, 3000);  /* a failed read leaves it */
}

/* tirenv_tir_get gives each key as the writer writes it: set, got, set again from the text
 * gives the same tire; unknown keys, a small buffer and a section-qualified key. */
static void test_get_every_key(void **state)
{
    (void)state;
    tirenv_diag d;
    tirenv_tire t = tirenv_tire_default();
    assert_int_equal(tirenv_tir_set(&t, "RADIAL_STIFFNESS=1612345.678", &d), TIRENV_OK);
    assert_int_equal(tirenv_tir_set(&t, "MAX_ITERATIONS=37", &d), TIRENV_OK);
    assert_int_equal(tirenv_tir_set(&t, "METHOD=brent", &d), TIRENV_OK);
    char buf[64];
    tirenv_tir_kind kind;
    assert_int_equal(tirenv_tir_get(&t, "RADIAL_STIFFNESS", buf, sizeof buf, &kind, &d), 0);
    assert_string_equal(buf, "1612345.678");
    assert_int_equal(kind, TIRENV_TIR_REAL);
    assert_int_equal(tirenv_tir_get(&t, "enveloping_solver.max_iterations", buf, sizeof buf,
                                    &kind, &d), 0);
    assert_string_equal(buf, "37");
    assert_int_equal(kind, TIRENV_TIR_COUNT);
    assert_int_equal(tirenv_tir_get(&t, "METHOD", buf, sizeof buf, &kind, &d), 0);
    assert_string_equal(buf, "brent");
    assert_int_equal(kind, TIRENV_TIR_NAME);
    size_t n = 0;
    const char *section = NULL, *key;
    tirenv_tire copy = tirenv_tire_default();
    for (; (key = tirenv_tir_key(n, &section)) != NULL; ++n) {
        assert_non_null(section);
        char qualified[128];  /* CONTACT is in two sections */
        snprintf(qualified, sizeof qualified, "%s.%s", section, key);
        assert_int_equal(tirenv_tir_get(&t, qualified, buf, sizeof buf, NULL, &d), TIRENV_OK);
        char assignment[128];
        snprintf(assignment, sizeof assignment, "%s.%s=%s", section, key, buf);
        assert_int_equal(tirenv_tir_set(&copy, assignment, &d), TIRENV_OK);
    }
    assert_true(n >= 25);  /* every key of the .tir table but [UNITS] */
    assert_int_equal(tirenv_tir_get(&copy, "RADIAL_STIFFNESS", buf, sizeof buf, NULL, &d), 0);
    assert_string_equal(buf, "1612345.678");
    /* Every key of the copy is the original's, to the bit: the text reads back exactly. */
    for (size_t i = 0; (key = tirenv_tir_key(i, &section)) != NULL; ++i) {
        char a[64], b[64], qualified[128];
        snprintf(qualified, sizeof qualified, "%s.%s", section, key);
        assert_int_equal(tirenv_tir_get(&t, qualified, a, sizeof a, &kind, &d), TIRENV_OK);
        assert_int_equal(tirenv_tir_get(&copy, qualified, b, sizeof b, NULL, &d), TIRENV_OK);
        assert_string_equal(a, b);
        if (kind == TIRENV_TIR_REAL)
            assert_true(strtod(a, NULL) == strtod(b, NULL));
    }
    assert_true(copy.springs.c_r == t.springs.c_r && copy.ring.k_t == t.ring.k_t &&
                copy.eq.max_iter == t.eq.max_iter && copy.eq.method == t.eq.method);
    assert_int_equal(tirenv_tir_get(&t, "Q_FZ3", buf, sizeof buf, NULL, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "Q_FZ3");
    assert_non_null(strstr(d.message, "RADIAL_STIFFNESS"));
    assert_int_equal(tirenv_tir_get(&t, "LENGTH", buf, sizeof buf, NULL, &d), TIRENV_EINVAL);
    /* A refusal leaves buf empty: it kept what was there before ("1612345.678" here, or
     * uninitialised bytes), which a caller that printed it took for the value. */
    assert_int_equal(tirenv_tir_get(&t, "RADIAL_STIFFNESS", buf, 5, NULL, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "buffer"));
    assert_string_equal(buf, "");
    strcpy(buf, "stale");
    assert_int_equal(tirenv_tir_get(&t, "Q_FZ3", buf, sizeof buf, NULL, &d), TIRENV_EINVAL);
    assert_string_equal(buf, "");
    assert_int_equal(tirenv_tir_get(NULL, "METHOD", buf, sizeof buf, NULL, &d), TIRENV_EINVAL);
}

/* tirenv_tir_need: every model type of the table, alone and not, against what it computes
 * with (docs/models.md 14.2); a type added to the table without a row here fails. */
static void test_need_of_every_model(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        unsigned shared, alone; /* the need among other models, and alone */
    } rows[] = {
        {"rigid", 0, 0},
        {"springs", TIRENV_TIR_SPRINGS, TIRENV_TIR_SPRINGS},
        {"ring", TIRENV_TIR_RING, TIRENV_TIR_RING | TIRENV_TIR_ONLY},
        {"cam", TIRENV_TIR_CAM, TIRENV_TIR_CAM | TIRENV_TIR_ONLY},
        {"nn", 0, 0},  /* its load's contact length is its own file's law (14.3) */
        {"point", 0, 0},
    };
    const size_t n = sizeof rows / sizeof rows[0];
    size_t types = 0;
    for (const tirenv_model_type *const *t = tirenv_model_types(); *t; ++t, ++types) {
        size_t i = 0;
        while (i < n && strcmp(rows[i].name, tirenv_model_type_name(*t)) != 0)
            i++;
        assert_true(i < n);
        assert_int_equal(tirenv_tir_need(*t, 0), rows[i].shared);
        assert_int_equal(tirenv_tir_need(*t, 1), rows[i].alone);
    }
    assert_int_equal(types, n);
    assert_int_equal(tirenv_tir_need(NULL, 0), 0);
    assert_int_equal(tirenv_tir_need(NULL, 1), 0);
}

int main(void)
{
#define T(fn) cmocka_unit_test_setup_teardown(fn, tirenv_test_dir_setup, tirenv_test_dir_teardown)
    const struct CMUnitTest tests[] = {
        T(test_default_file_matches_builtin),
        T(test_mftyre_excerpt_loads),
        T(test_comments_and_case),
        T(test_read_errors),
        T(test_missing_file),
        T(test_set_good),
        T(test_set_errors),
        T(test_write_read_round_trip),
        T(test_write_refuses_unphysical),
        T(test_write_into_missing_dir),
        T(test_outfile_commit),
        T(test_outfile_abort),
        T(test_outfile_replaces_existing),
        T(test_outfile_errors),
        T(test_outfile_stdout),
        T(test_sample_tir_files),
        T(test_units_converted),
        T(test_cam_keys_given),
        T(test_own_q_fz1_and_pfz1),
        T(test_vertical_damping),
        T(test_get_every_key),
        cmocka_unit_test(test_need_of_every_model),
    };
#undef T
    return cmocka_run_group_tests(tests, NULL, NULL);
}
