/* The vehicle of the ride simulation: default, check, static tire loads, and its property
 * file (reader, --set, writer). SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/vehicle_file.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- helpers ------------------------------------------------------------------------- */

static void assert_axle_identical(const tirenv_axle *a, const tirenv_axle *b)
{
    assert_string_equal(a->tire_file, b->tire_file);
    assert_bits_equal(a->tires, b->tires);
    assert_bits_equal(a->k_t, b->k_t);
    assert_bits_equal(a->c_t, b->c_t);
    assert_bits_equal(a->k_s, b->k_s);
    assert_bits_equal(a->c_s, b->c_s);
    assert_bits_equal(a->m_a, b->m_a);
}

static void assert_vehicle_identical(const tirenv_vehicle *a, const tirenv_vehicle *b)
{
    assert_bits_equal(a->m, b->m);
    assert_bits_equal(a->I_y, b->I_y);
    assert_bits_equal(a->a, b->a);
    assert_bits_equal(a->b, b->b);
    assert_bits_equal(a->seat_x, b->seat_x);
    assert_bits_equal(a->seat_h, b->seat_h);
    assert_bits_equal(a->g, b->g);
    assert_axle_identical(&a->front, &b->front);
    assert_axle_identical(&a->rear, &b->rear);
}

/* Physical, but unlike the default in every field: a file read over it must set them all. */
static tirenv_vehicle entropic_vehicle(void)
{
    return (tirenv_vehicle){
        .m = 5283.7, .I_y = 6131.9, .a = 1.3717, .b = 1.0831, .seat_x = -0.6913,
        .seat_h = 1.3127, .g = 9.80665,
        .front = {.tire_file = "/srv/tires/front-11.2R24.tir", .tires = 4, .k_t = 283117.3,
                  .c_t = 2371.9, .k_s = 187313.7, .c_s = 7193.1, .m_a = 387.13},
        .rear = {.tire_file = "/srv/tires/rear-18.4R38.tir", .tires = 4, .k_t = 431873.9,
                 .c_t = 3917.3, .k_s = 0, .c_s = 0, .m_a = 611.7},
    };
}

/* ---- the default, the check, the loads ------------------------------------------------ */

static void test_default_file_matches_builtin(void **state)
{
    (void)state;
    tirenv_vehicle v = entropic_vehicle();
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const char *path = TIRENV_DATA_DIR "/vehicles/tractor.veh";
    const int status = tirenv_vehicle_read(path, &v, &d);
    char line[1200];
    print_message("%s\n", tirenv_diag_format(&d, line, sizeof line));
    assert_int_equal(status, TIRENV_OK);
    tirenv_vehicle expected = tirenv_vehicle_default();
    assert_string_equal(expected.front.tire_file, "");
    assert_string_equal(expected.rear.tire_file, "");
    /* The file's '../tires/default.tir', relative to the file, the file's directory first. */
    const char *tire = TIRENV_DATA_DIR "/vehicles/../tires/default.tir";
    snprintf(expected.front.tire_file, sizeof expected.front.tire_file, "%s", tire);
    snprintf(expected.rear.tire_file, sizeof expected.rear.tire_file, "%s", tire);
    assert_vehicle_identical(&v, &expected);
    FILE *fp = fopen(v.front.tire_file, "r"); /* and it names the shipped tire */
    assert_non_null(fp);
    fclose(fp);
    const tirenv_vehicle def = tirenv_vehicle_default();
    assert_int_equal(tirenv_vehicle_check(&def, &d), TIRENV_OK);
}

/* By hand: 4500*9.81*0.95/2.4/2 = 8737.03125 N and 4500*9.81*1.45/2.4/2 = 13335.46875 N. */
static void test_tire_loads(void **state)
{
    (void)state;
    tirenv_vehicle v = tirenv_vehicle_default();
    assert_near(tirenv_vehicle_tire_load(&v, 0), 8737.03125, 0, 1e-14);
    assert_near(tirenv_vehicle_tire_load(&v, 1), 13335.46875, 0, 1e-14);
    assert_true(isnan(tirenv_vehicle_tire_load(&v, 2)));
    assert_true(isnan(tirenv_vehicle_tire_load(&v, -1)));
    /* A rigid axle's mass is inside m: changing it changes nothing. */
    v.front.m_a = 731.9;
    assert_near(tirenv_vehicle_tire_load(&v, 0), 8737.03125, 0, 1e-14);
    /* Suspended, as the file's comment suggests: body 4100 kg with its CG moved rearwards,
     * axle 400 kg; the same axle loads as the rigid tractor. */
    v = tirenv_vehicle_default();
    v.m = 4100;
    v.a = 4500 * 1.45 / 4100;
    v.b = 2.4 - v.a;
    v.front.k_s = 200000;
    v.front.c_s = 8000;
    assert_near(tirenv_vehicle_tire_load(&v, 0), (4100 * 9.81 * v.b / 2.4 + 400 * 9.81) / 2, 0,
                1e-14);
    assert_near(tirenv_vehicle_tire_load(&v, 0), 8737.03125, 0, 1e-12);
    assert_near(tirenv_vehicle_tire_load(&v, 1), 13335.46875, 0, 1e-12);
    /* Duals: the axle's load spreads over 4 tires; the loads add up to the weight. */
    v = entropic_vehicle();
    const double W = (v.m + v.front.m_a) * v.g;
    assert_near(4 * tirenv_vehicle_tire_load(&v, 0) + 4 * tirenv_vehicle_tire_load(&v, 1), W, 0,
                1e-14);
}

/* A change to one or two doubles of the default, by offset, that the check must refuse. */
typedef struct {
    size_t offset;
    double value;
    size_t offset2;  /* 0: no second change (offset 0 is m, never a second change here) */
    double value2;
    const char *field;
    const char *says;
} check_case;

#define AT(member) offsetof(tirenv_vehicle, member)

static const check_case check_cases[] = {
    {AT(m), -4500, 0, 0, "MASS", "must be positive (kg), got -4500"},
    {AT(m), 0, 0, 0, "MASS", "positive"},
    {AT(m), NAN, 0, 0, "MASS", "positive"},
    {AT(I_y), 0, 0, 0, "PITCH_INERTIA", "must be positive (kg*m^2)"},
    {AT(a), -1.45, 0, 0, "CG_TO_FRONT_AXLE", "positive (m)"},
    {AT(b), 0, 0, 0, "CG_TO_REAR_AXLE", "positive (m)"},
    {AT(g), INFINITY, 0, 0, "GRAVITY", "positive (m/s^2)"},
    {AT(seat_x), NAN, 0, 0, "SEAT_AHEAD_OF_CG", "finite"},
    {AT(seat_h), -INFINITY, 0, 0, "SEAT_ABOVE_CG", "finite"},
    {AT(front.tires), 0, 0, 0, "FRONT_AXLE.TIRES", "whole number of tires, at least 1"},
    {AT(rear.tires), 2.5, 0, 0, "REAR_AXLE.TIRES", "whole number"},
    {AT(front.k_t), 0, 0, 0, "FRONT_AXLE.TIRE_STIFFNESS", "must be positive (N/m)"},
    {AT(rear.c_t), -3000, 0, 0, "REAR_AXLE.TIRE_DAMPING", "zero or positive (N*s/m)"},
    {AT(front.k_s), -2e5, 0, 0, "FRONT_AXLE.SUSPENSION_STIFFNESS", "zero or positive (N/m)"},
    {AT(rear.k_s), 2e5, 0, 0, "REAR_AXLE.SUSPENSION_STIFFNESS", "must be 0: a tractor's rear"},
    {AT(front.k_s), 2e5, AT(front.c_s), -8000, "FRONT_AXLE.SUSPENSION_DAMPING",
     "zero or positive"},
    {AT(front.c_s), 8000, 0, 0, "FRONT_AXLE.SUSPENSION_DAMPING", "must be 0 on a rigid axle"},
    {AT(rear.c_s), 8000, 0, 0, "REAR_AXLE.SUSPENSION_DAMPING", "must be 0 on a rigid axle"},
    {AT(front.k_s), 2e5, AT(front.m_a), 0, "FRONT_AXLE.AXLE_MASS", "must be positive (kg)"},
    {AT(rear.m_a), -400, 0, 0, "REAR_AXLE.AXLE_MASS", "zero or positive (kg)"},
};

static void set_double(tirenv_vehicle *v, size_t offset, double value)
{
    memcpy((unsigned char *)v + offset, &value, sizeof value);
}

static void test_check(void **state)
{
    (void)state;
    tirenv_diag d;
    for (size_t i = 0; i < sizeof check_cases / sizeof check_cases[0]; i++) {
        const check_case *k = &check_cases[i];
        tirenv_vehicle v = tirenv_vehicle_default();
        set_double(&v, k->offset, k->value);
        if (k->offset2)
            set_double(&v, k->offset2, k->value2);
        tirenv_diag_clear(&d);
        char line[1200];
        const int status = tirenv_vehicle_check(&v, &d);
        print_message("case %zu: %s\n", i, tirenv_diag_format(&d, line, sizeof line));
        assert_int_equal(status, TIRENV_EINVAL);
        assert_string_equal(d.field, k->field);
        assert_non_null(strstr(d.message, k->says));
    }
    /* Allowed: a rigid axle of mass 0 (its mass is the body's), any seat position, a
     * suspended front axle, one tire or six. */
    tirenv_vehicle v = tirenv_vehicle_default();
    v.front.m_a = v.rear.m_a = 0;
    v.seat_x = 0.3;
    v.seat_h = -0.2;
    v.front.tires = 1;
    v.rear.tires = 6;
    v.rear.c_t = 0;
    assert_int_equal(tirenv_vehicle_check(&v, &d), TIRENV_OK);
    v = entropic_vehicle();
    assert_int_equal(tirenv_vehicle_check(&v, &d), TIRENV_OK);
    /* A tire file name that fills its array without a terminator. */
    memset(v.rear.tire_file, 'x', sizeof v.rear.tire_file);
    assert_int_equal(tirenv_vehicle_check(&v, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "REAR_AXLE.TIRE_FILE");
}

/* ---- reading ------------------------------------------------------------------------- */

/* [UNITS] MASS and [BODY] MASS in one file; bare and quoted paths, relative ones taken from
 * the file's directory, absolute ones and '' (the built-in tire) kept; names in any case. */
static void test_read_paths_and_case(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_write_text(tirenv_test_path(fx, "v.veh", path),
               "\xEF\xBB\xBF$ a BOM first\r\n"
               "[units]\r\n"
               "mass = 'KG'\r\n"
               "[ BODY ]  $ spaces inside the brackets\n"
               "Mass=5283.7$no space before the comment\n"
               "[FRONT_AXLE]\n"
               "TIRE_FILE = tires/front.tir   $ bare: no quotes\n"
               "! a bang comment inside a section\n"
               "[REAR_AXLE]\n"
               "TIRE_FILE = '/abs/rear $1.tir'  $ '$' inside quotes is part of the path\n");
    tirenv_vehicle v = tirenv_vehicle_default();
    tirenv_diag d;
    assert_int_equal(tirenv_vehicle_read(path, &v, &d), TIRENV_OK);
    assert_bits_equal(v.m, 5283.7);
    char expected[600];
    snprintf(expected, sizeof expected, "%s/tires/front.tir", fx->dir);
    assert_string_equal(v.front.tire_file, expected);
    assert_string_equal(v.rear.tire_file, "/abs/rear $1.tir");

    tirenv_test_write_text(path, "[FRONT_AXLE]\nTIRE_FILE = ''\n[REAR_AXLE]\nTIRE_FILE = 'r.tir'\n");
    v = entropic_vehicle();
    assert_int_equal(tirenv_vehicle_read(path, &v, &d), TIRENV_OK);
    assert_string_equal(v.front.tire_file, "");
    snprintf(expected, sizeof expected, "%s/r.tir", fx->dir);
    assert_string_equal(v.rear.tire_file, expected);

    /* A file named without a directory: its relative paths stay as they are. */
    char cwd[512];
    assert_non_null(getcwd(cwd, sizeof cwd));
    assert_int_equal(chdir(fx->dir), 0);
    v = tirenv_vehicle_default();
    const int status = tirenv_vehicle_read("v.veh", &v, &d);
    assert_int_equal(chdir(cwd), 0);
    assert_int_equal(status, TIRENV_OK);
    assert_string_equal(v.rear.tire_file, "r.tir");
}

typedef tirenv_test_read_error read_error_case;

/* 600 characters: over the 511 a tire_file holds. */
#define X10 "xxxxxxxxxx"
#define X100 X10 X10 X10 X10 X10 X10 X10 X10 X10 X10
#define X500 X100 X100 X100 X100 X100

static const read_error_case read_errors[] = {
    {"[BODY]\nMASS = 4500\nWHEELBASE = 2.4\n", TIRENV_EPARSE, 3, 1, "WHEELBASE",
     "unknown key in [BODY]; expected one of MASS, PITCH_INERTIA, CG_TO_FRONT_AXLE, "
     "CG_TO_REAR_AXLE, GRAVITY"},
    {"[REAR_AXLE]\n  TIRE_STIFNESS = 3e5\n", TIRENV_EPARSE, 2, 3, "TIRE_STIFNESS",
     "expected one of TIRE_FILE, TIRES, TIRE_STIFFNESS, TIRE_DAMPING, SUSPENSION_STIFFNESS, "
     "SUSPENSION_DAMPING, AXLE_MASS"},
    {"[SEAT]\nSEAT_ABOVE_CG = 1.2\n\nSEAT_ABOVE_CG = 1.3\n", TIRENV_EPARSE, 4, 1,
     "SEAT_ABOVE_CG", "duplicate key (first set on line 2)"},
    {"[FRONT_AXLE]\nTIRES = 2\n[REAR_AXLE]\nTIRES = 2\n[FRONT_AXLE]\ntires = 4\n",
     TIRENV_EPARSE, 6, 1, "TIRES", "duplicate key (first set on line 2)"},
    {"[BODY]\nMASS = 4.5t\n", TIRENV_EPARSE, 2, 11, "MASS",
     "unexpected 't' after the number 4.5"},
    {"[BODY]\nGRAVITY = g\n", TIRENV_EPARSE, 2, 11, "GRAVITY", "expected a number, got 'g'"},
    {"[FRONT_AXLE]\nTIRE_DAMPING = '3000'\n", TIRENV_EPARSE, 2, 16, "TIRE_DAMPING",
     "expected a number, got the string"},
    {"[SEAT]\nSEAT_AHEAD_OF_CG -0.75\n", TIRENV_EPARSE, 2, 17, "SEAT_AHEAD_OF_CG",
     "missing '='; expected KEY = value"},
    {"[FRONT_AXLE]\nTIRE_FILE =\n", TIRENV_EPARSE, 2, 13, "TIRE_FILE",
     "missing value after '='; expected a path in quotes"},
    {"[FRONT_AXLE]\nTIRE_FILE = 'a.tir\n", TIRENV_EPARSE, 2, 13, "TIRE_FILE",
     "unterminated string"},
    {"[BODY]\nMASS = 4500\n[CHASSIS]\nMASS = 4500\n", TIRENV_EPARSE, 3, 2, "CHASSIS",
     "unknown section [CHASSIS]; expected [UNITS], [BODY], [SEAT], [FRONT_AXLE] or "
     "[REAR_AXLE]"},
    {"[MDI_HEADER]\nFILE_TYPE = 'veh'\n", TIRENV_EPARSE, 1, 2, "MDI_HEADER",
     "unknown section"},
    {"MASS = 4500\n[BODY]\n", TIRENV_EPARSE, 1, 1, "",
     "before the first section; expected a [SECTION] header such as [UNITS]"},
    {"[UNITS]\nMASS = 'tonne'\n", TIRENV_EPARSE, 2, 9, "MASS",
     "unit 'tonne' is not supported (tirenv reads SI only); expected 'kg'"},
    {"[REAR_AXLE]\nTIRE_FILE = '/" X500 X100 "'\n", TIRENV_EPARSE, 2, 14, "TIRE_FILE",
     "path of 601 characters is too long; expected at most 511"},
    /* 500 characters fit, but not once the file's directory comes before them. */
    {"[REAR_AXLE]\nTIRE_FILE = " X500 "\n", TIRENV_EPARSE, 2, 13, "TIRE_FILE",
     "(with the file's directory before it) is too long; expected at most 511"},
    /* parsed fine, but unphysical: the line of the key, no column */
    {"[UNITS]\nMASS = 'kg'\n[BODY]\nMASS = -4500 $ sign typo\n", TIRENV_EINVAL, 4, 0, "MASS",
     "must be positive (kg), got -4500"},
    {"[FRONT_AXLE]\nSUSPENSION_STIFFNESS = 2e5\n[REAR_AXLE]\nTIRES = 2\n"
     "SUSPENSION_STIFFNESS = 1.5e5\n", TIRENV_EINVAL, 5, 0, "REAR_AXLE.SUSPENSION_STIFFNESS",
     "must be 0: a tractor's rear axle is rigid here"},
    {"[FRONT_AXLE]\nSUSPENSION_STIFFNESS = 0 $ rigid\nSUSPENSION_DAMPING = 8000\n",
     TIRENV_EINVAL, 3, 0, "FRONT_AXLE.SUSPENSION_DAMPING", "must be 0 on a rigid axle"},
    {"[REAR_AXLE]\nTIRES = 3.5\n", TIRENV_EINVAL, 2, 0, "REAR_AXLE.TIRES", "whole number"},
};

static void test_read_errors(void **state)
{
    tirenv_test_dir *fx = *state;
    for (size_t i = 0; i < sizeof read_errors / sizeof read_errors[0]; i++) {
        const read_error_case *k = &read_errors[i];
        char path[600], name[32];
        snprintf(name, sizeof name, "err%02zu.veh", i);
        tirenv_test_write_text(tirenv_test_path(fx, name, path), k->text);
        const tirenv_vehicle before = entropic_vehicle();
        tirenv_vehicle v = before;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        const int status = tirenv_vehicle_read(path, &v, &d);
        tirenv_test_expect_diag(i, status, &d, k->status, path, k->line, k->column, k->field,
                                k->says);
        assert_vehicle_identical(&v, &before);
    }
}

/* The keys a file leaves out, named; a file with all of them names none, and the values read
 * are tirenv_vehicle_read's. */
static void test_read_unset(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600], unset[512];
    tirenv_diag d;
    tirenv_vehicle v = tirenv_vehicle_default(), w = tirenv_vehicle_default();
    const char *full = TIRENV_DATA_DIR "/vehicles/tractor.veh";
    assert_int_equal(tirenv_vehicle_read_unset(full, &v, unset, sizeof unset, &d), TIRENV_OK);
    assert_string_equal(unset, "");
    assert_int_equal(tirenv_vehicle_read(full, &w, &d), TIRENV_OK);
    assert_memory_equal(&v, &w, sizeof v);
    tirenv_test_write_text(tirenv_test_path(fx, "part.veh", path),
                           "[BODY]\nMASS = 5283.7\nCG_TO_FRONT_AXLE = 1.37\nCG_TO_REAR_AXLE = 1.08\n"
                           "GRAVITY = 9.81\n[SEAT]\nSEAT_AHEAD_OF_CG = 0.2\nSEAT_ABOVE_CG = 1.1\n"
                           "[FRONT_AXLE]\nTIRE_FILE = ''\nTIRES = 2\nSUSPENSION_STIFFNESS = 0\n"
                           "SUSPENSION_DAMPING = 0\nAXLE_MASS = 300\n[REAR_AXLE]\nTIRE_FILE = ''\n"
                           "SUSPENSION_STIFFNESS = 0\nSUSPENSION_DAMPING = 0\nAXLE_MASS = 400\n");
    v = tirenv_vehicle_default();
    assert_int_equal(tirenv_vehicle_read_unset(path, &v, unset, sizeof unset, &d), TIRENV_OK);
    assert_string_equal(unset, "BODY.PITCH_INERTIA, REAR_AXLE.TIRES");
    assert_bits_equal(v.m, 5283.7);
    assert_bits_equal(v.I_y, tirenv_vehicle_default().I_y);
    /* cut where it does not fit, and said so */
    char small[24];
    v = tirenv_vehicle_default();
    assert_int_equal(tirenv_vehicle_read_unset(path, &v, small, sizeof small, &d), TIRENV_OK);
    assert_string_equal(small, "BODY.PITCH_INERTIA, ...");
}

static void test_missing_file(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_vehicle v = entropic_vehicle();
    const tirenv_vehicle before = v;
    tirenv_diag d;
    assert_int_equal(tirenv_vehicle_read(tirenv_test_path(fx, "no-such.veh", path), &v, &d), TIRENV_EIO);
    assert_string_equal(d.file, path);
    assert_vehicle_identical(&v, &before);
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
        {"MASS=5283.7", AT(m), 5283.7},
        {" body.mass = 4100 ", AT(m), 4100},
        {"PITCH_INERTIA=6131.9", AT(I_y), 6131.9},
        {"CG_TO_FRONT_AXLE=1.3717", AT(a), 1.3717},
        {"CG_TO_REAR_AXLE=1.0831", AT(b), 1.0831},
        {"GRAVITY=9.80665", AT(g), 9.80665},
        {"SEAT_AHEAD_OF_CG=-0.6913", AT(seat_x), -0.6913},
        {"SEAT.SEAT_ABOVE_CG=1.3127", AT(seat_h), 1.3127},
        {"FRONT_AXLE.TIRES=4", AT(front.tires), 4},
        {"REAR_AXLE.TIRES=4", AT(rear.tires), 4},
        {"front_axle.tire_stiffness=283117.3", AT(front.k_t), 283117.3},
        {"REAR_AXLE.TIRE_STIFFNESS=431873.9", AT(rear.k_t), 431873.9},
        {"FRONT_AXLE.TIRE_DAMPING=2371.9", AT(front.c_t), 2371.9},
        {"REAR_AXLE.TIRE_DAMPING=0", AT(rear.c_t), 0},
        {"FRONT_AXLE.SUSPENSION_STIFFNESS=187313.7", AT(front.k_s), 187313.7},
        {"FRONT_AXLE.AXLE_MASS=387.13", AT(front.m_a), 387.13},
        {"REAR_AXLE.AXLE_MASS=611.7", AT(rear.m_a), 611.7},
    };
    for (size_t i = 0; i < sizeof reals / sizeof reals[0]; i++) {
        tirenv_vehicle v = tirenv_vehicle_default();
        tirenv_diag d;
        assert_int_equal(tirenv_vehicle_set(&v, reals[i].text, &d), TIRENV_OK);
        double got;
        memcpy(&got, (const unsigned char *)&v + reals[i].offset, sizeof got);
        assert_bits_equal(got, reals[i].value);
        /* and nothing else: the keys' bits of tirenv_vehicle_read_unset's record are not
         * written into a vehicle (they were OR-ed into MASS, the struct's first member) */
        if (reals[i].offset != AT(m))
            assert_bits_equal(v.m, tirenv_vehicle_default().m);
    }
    /* Damping on the front axle once it has a spring; a relative path stays relative (to the
     * working directory). */
    tirenv_vehicle v = tirenv_vehicle_default();
    tirenv_diag d;
    assert_int_equal(tirenv_vehicle_set(&v, "FRONT_AXLE.SUSPENSION_STIFFNESS=2e5", &d), 0);
    assert_int_equal(tirenv_vehicle_set(&v, "FRONT_AXLE.SUSPENSION_DAMPING=8000", &d), 0);
    assert_bits_equal(v.front.c_s, 8000);
    assert_int_equal(tirenv_vehicle_set(&v, "FRONT_AXLE.TIRE_FILE='tires/11.2R24.tir'", &d), 0);
    assert_string_equal(v.front.tire_file, "tires/11.2R24.tir");
    assert_int_equal(tirenv_vehicle_set(&v, "REAR_AXLE.TIRE_FILE=rear.tir", &d), 0);
    assert_string_equal(v.rear.tire_file, "rear.tir");
    assert_int_equal(tirenv_vehicle_set(&v, "REAR_AXLE.TIRE_FILE=''", &d), 0);
    assert_string_equal(v.rear.tire_file, "");
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
        {"MASS", TIRENV_EPARSE, "", "expected KEY=VALUE, got 'MASS'"},
        {"WHEELBASE=2.4", TIRENV_EPARSE, "WHEELBASE",
         "unknown key; expected one of MASS, PITCH_INERTIA, CG_TO_FRONT_AXLE, CG_TO_REAR_AXLE, "
         "GRAVITY, SEAT_AHEAD_OF_CG, SEAT_ABOVE_CG, TIRE_FILE, TIRES, TIRE_STIFFNESS, "
         "TIRE_DAMPING, SUSPENSION_STIFFNESS, SUSPENSION_DAMPING, AXLE_MASS"},
        {"TIRES=4", TIRENV_EPARSE, "TIRES",
         "key in more than one section; expected FRONT_AXLE.TIRES or REAR_AXLE.TIRES"},
        {"TIRE_FILE='x.tir'", TIRENV_EPARSE, "TIRE_FILE", "FRONT_AXLE.TIRE_FILE or"},
        {"UNITS.MASS=kg", TIRENV_EPARSE, "MASS", "unknown key in section UNITS"},
        {"LENGTH=meter", TIRENV_EPARSE, "LENGTH", "unknown key"},
        {"SEAT.MASS=4500", TIRENV_EPARSE, "MASS", "unknown key in section SEAT"},
        {"MASS=heavy", TIRENV_EPARSE, "MASS", "expected a number"},
        {"MASS=4500 kg", TIRENV_EPARSE, "MASS", "after the number"},
        {"GRAVITY=", TIRENV_EPARSE, "GRAVITY", "missing value"},
        {"FRONT_AXLE.TIRE_FILE='" X500 X100 "'", TIRENV_EPARSE, "TIRE_FILE", "too long"},
        {"MASS=-1", TIRENV_EINVAL, "MASS", "must be positive (kg), got -1"},
        {"REAR_AXLE.SUSPENSION_STIFFNESS=2e5", TIRENV_EINVAL, "REAR_AXLE.SUSPENSION_STIFFNESS",
         "rear axle is rigid"},
        {"REAR_AXLE.SUSPENSION_DAMPING=8000", TIRENV_EINVAL, "REAR_AXLE.SUSPENSION_DAMPING",
         "rigid axle"},
        {"FRONT_AXLE.TIRES=0", TIRENV_EINVAL, "FRONT_AXLE.TIRES", "at least 1"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const tirenv_vehicle before = entropic_vehicle();
        tirenv_vehicle v = before;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        const int status = tirenv_vehicle_set(&v, cases[i].text, &d);
        tirenv_test_expect_diag(i, status, &d, cases[i].status, "--set", 0, 0, cases[i].field,
                                cases[i].says);
        assert_vehicle_identical(&v, &before);
    }
}

/* ---- writing --------------------------------------------------------------------------- */

/* Values that need all 17 digits, extremes of the plausible ranges (the double range's where
 * they allow it: DBL_MIN, the smallest subnormal), everyday ones; absolute and empty paths,
 * one with a '$' and spaces. */
static void test_write_read_round_trip(void **state)
{
    tirenv_test_dir *fx = *state;
    tirenv_vehicle extreme = entropic_vehicle();
    extreme.m = nextafter(4500, 5000); /* 4500.0000000000009: 17 digits */
    extreme.I_y = nextafter(1e8, 0);   /* the largest below the range's top */
    extreme.a = DBL_MIN;
    extreme.b = 4.9406564584124654e-324; /* the smallest subnormal */
    extreme.seat_x = -1.0 / 3.0;
    extreme.seat_h = -0.0;
    extreme.front.c_t = 0;
    extreme.front.k_s = M_PI;
    extreme.front.c_s = 1e7;   /* the plausible ranges' tops, docs/formats.md section 3 */
    extreme.rear.tires = 16;
    snprintf(extreme.front.tire_file, sizeof extreme.front.tire_file, "/a b/$c.tir");
    extreme.rear.tire_file[0] = '\0';
    const tirenv_vehicle vehicles[] = {entropic_vehicle(), tirenv_vehicle_default(), extreme};
    for (size_t i = 0; i < sizeof vehicles / sizeof vehicles[0]; i++) {
        char path[600];
        tirenv_test_path(fx, "rt.veh", path);
        tirenv_diag d;
        assert_int_equal(tirenv_vehicle_write(path, &vehicles[i], &d), TIRENV_OK);
        tirenv_vehicle back = i == 0 ? tirenv_vehicle_default() : entropic_vehicle();
        const int status = tirenv_vehicle_read(path, &back, &d);
        char line[1200];
        print_message("vehicle %zu: %s\n", i, tirenv_diag_format(&d, line, sizeof line));
        assert_int_equal(status, TIRENV_OK);
        assert_vehicle_identical(&back, &vehicles[i]);
    }
    assert_int_equal(tirenv_test_count_entries(fx, "tmp."), 0);

    char path[600], text[8192];
    tirenv_test_path(fx, "default.veh", path);
    tirenv_diag d;
    const tirenv_vehicle def = tirenv_vehicle_default();
    assert_int_equal(tirenv_vehicle_write(path, &def, &d), TIRENV_OK);
    tirenv_test_read_text(path, text, sizeof text);
    assert_non_null(strstr(text, "\n[UNITS]\nLENGTH                   = 'meter' "));
    assert_non_null(strstr(text, "\n[BODY]\nMASS                     = "));
    assert_non_null(strstr(text, "\nCG_TO_REAR_AXLE          = 0.95 "));
    assert_non_null(strstr(text, "\n[REAR_AXLE]\nTIRE_FILE                = ''  "));
}

/* A path relative to the working directory still names the same file once written into
 * another directory: it is written absolute there, and kept relative in the working one. */
static void test_write_relative_path(void **state)
{
    tirenv_test_dir *fx = *state;
    tirenv_vehicle v = tirenv_vehicle_default();
    snprintf(v.front.tire_file, sizeof v.front.tire_file, "tires/front.tir");
    char path[600], cwd[512], expected[600];
    assert_non_null(getcwd(cwd, sizeof cwd));
    tirenv_diag d;
    assert_int_equal(tirenv_vehicle_write(tirenv_test_path(fx, "rel.veh", path), &v, &d), TIRENV_OK);
    tirenv_vehicle back = entropic_vehicle();
    assert_int_equal(tirenv_vehicle_read(path, &back, &d), TIRENV_OK);
    snprintf(expected, sizeof expected, "%s/tires/front.tir", cwd);
    assert_string_equal(back.front.tire_file, expected);
    assert_string_equal(back.rear.tire_file, "");

    assert_int_equal(chdir(fx->dir), 0);
    int status = tirenv_vehicle_write("here.veh", &v, &d);
    back = entropic_vehicle();
    if (status == TIRENV_OK)
        status = tirenv_vehicle_read("here.veh", &back, &d);
    assert_int_equal(chdir(cwd), 0);
    assert_int_equal(status, TIRENV_OK);
    assert_string_equal(back.front.tire_file, "tires/front.tir");
}

static void test_write_refuses(void **state)
{
    tirenv_test_dir *fx = *state;
    char path[600];
    tirenv_test_path(fx, "bad.veh", path);
    tirenv_vehicle v = tirenv_vehicle_default();
    v.rear.k_s = 1e5;
    tirenv_diag d;
    assert_int_equal(tirenv_vehicle_write(path, &v, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "REAR_AXLE.SUSPENSION_STIFFNESS");
    v = tirenv_vehicle_default();
    snprintf(v.rear.tire_file, sizeof v.rear.tire_file, "/tires/o'brien.tir");
    assert_int_equal(tirenv_vehicle_write(path, &v, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "REAR_AXLE.TIRE_FILE");
    assert_non_null(strstr(d.message, "quote"));
    assert_int_equal(tirenv_test_count_entries(fx, ""), 0);
}

int main(void)
{
#define T(fn) cmocka_unit_test_setup_teardown(fn, tirenv_test_dir_setup, tirenv_test_dir_teardown)
    const struct CMUnitTest tests[] = {
        T(test_default_file_matches_builtin),
        T(test_tire_loads),
        T(test_check),
        T(test_read_paths_and_case),
        T(test_read_errors),
        T(test_read_unset),
        T(test_missing_file),
        T(test_set_good),
        T(test_set_errors),
        T(test_write_read_round_trip),
        T(test_write_relative_path),
        T(test_write_refuses),
    };
#undef T
    return cmocka_run_group_tests(tests, NULL, NULL);
}
