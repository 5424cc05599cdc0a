/* Curves: storage, the normalised position x_N (docs/models.md section 1), the CSV format with its
 * errors, and data sets (manifest, curve files, logs imported on reading).
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/curve.h"
#include "tirenv/dataset.h"
#include "tirenv/rig.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- storage ------------------------------------------------------------------------------ */

static void test_alloc_free(void **state)
{
    (void)state;
    tirenv_curve c;
    assert_int_equal(tirenv_curve_alloc(&c, 37), TIRENV_OK);
    assert_int_equal(c.n, 37);
    for (size_t k = 0; k < c.n; k++)
        assert_true(c.x_N[k] == 0 && c.x[k] == 0 && c.h[k] == 0);
    tirenv_curve_free(&c);
    assert_int_equal(c.n, 0);
    assert_null(c.x_N);
    tirenv_curve_free(&c); /* twice */
    tirenv_curve_free(NULL);
    assert_int_equal(tirenv_curve_alloc(&c, 0), TIRENV_OK);
    assert_int_equal(c.n, 0);
    tirenv_curve_free(&c);
}

/* ---- the normalised position ------------------------------------------------------------ */

/* The paper's cases F and R with the default tire (R0 = 0.68 m), computed to 40 digits from
 * z_c = sqrt(R0^2 - (l_c/2)^2), x_0 = -L/2 - sqrt(R0^2 - (z_c - H)^2). */
static void test_xN_origin_closed_form(void **state)
{
    (void)state;
    assert_near(tirenv_xN_origin(0.68, 0.38, 0.30, 0.10), -0.54583242255182105110, 1e-15, 0);
    assert_near(tirenv_xN_origin(0.68, 0.28, 0.10, 0.10), -0.42773858431051626678, 1e-15, 0);
    /* What it means: the free circle of radius R0 centred at (x_0, z_c) passes through the
     * leading top corner (-L/2, H), with the corner ahead of the centre. */
    const double R0 = 0.7125, l_c = 0.3315, L = 0.2385, H = 0.0615;
    const double x_0 = tirenv_xN_origin(R0, l_c, L, H);
    const double z_c = sqrt(R0 * R0 - 0.25 * l_c * l_c);
    assert_near(hypot(-0.5 * L - x_0, H - z_c), R0, 1e-15, 0);
    assert_true(x_0 < -0.5 * L);
    /* On flat ground (H = 0) the circle's chord reaches the corner: x_0 = -L/2 - l_c/2. */
    assert_near(tirenv_xN_origin(R0, l_c, L, 0), -0.5 * L - 0.5 * l_c, 1e-15, 0);
}

static void test_xN_origin_invalid(void **state)
{
    (void)state;
    assert_true(isnan(tirenv_xN_origin(0.68, 1.36, 0.30, 0.10)));  /* l_c = 2 R0 */
    assert_true(isnan(tirenv_xN_origin(0.68, 0, 0.30, 0.10)));
    assert_true(isnan(tirenv_xN_origin(-0.68, 0.38, 0.30, 0.10)));
    assert_true(isnan(tirenv_xN_origin(0.68, 0.38, -0.30, 0.10)));
    assert_true(isnan(tirenv_xN_origin(0.68, 0.38, 0.30, NAN)));
    assert_true(isnan(tirenv_xN_origin(0.68, 0.38, 0.30, 1.5)));     /* corner out of reach */
}

static void test_xN(void **state)
{
    (void)state;
    const double x_0 = -0.5458324225518210;
    assert_true(tirenv_xN(x_0, x_0) == 0);
    assert_true(tirenv_xN(0, x_0) == 1);
    assert_near(tirenv_xN(0.5 * x_0, x_0), 0.5, 1e-15, 0);
    assert_near(tirenv_xN(1.25 * x_0, x_0), -0.25, 1e-15, 0);
    assert_near(tirenv_xN(-x_0, x_0), 2, 1e-15, 0); /* the mirror point of first contact */
}

/* ---- CSV ---------------------------------------------------------------------------------- */

/* Every double survives a write and a read bit for bit (%.17g). */
static void test_csv_round_trip(void **state)
{
    (void)state;
    tirenv_curve c, back;
    assert_int_equal(tirenv_curve_alloc(&c, 5), TIRENV_OK);
    const double x_0 = tirenv_xN_origin(0.68, 0.38, 0.30, 0.10);
    for (size_t k = 0; k < c.n; k++) {
        c.x_N[k] = -0.25 + 0.3125 * (double)k + 1e-17 * (double)k;
        c.x[k] = x_0 * (1 - c.x_N[k]);
        c.h[k] = 0.1 * pow(sin(0.385 * (double)k + 0.1), 2) + 2.385e-310 * (double)(k == 2);
    }
    char path[64];
    tirenv_test_write_temp(path, "curve", "");
    tirenv_diag d;
    assert_int_equal(tirenv_curve_write_csv(path, &c, NULL, &d), TIRENV_OK);
    assert_int_equal(tirenv_curve_read_csv(path, &back, &d), TIRENV_OK);
    assert_int_equal(back.n, c.n);
    for (size_t k = 0; k < c.n; k++)
        assert_true(back.x_N[k] == c.x_N[k] && back.x[k] == c.x[k] && back.h[k] == c.h[k]);
    tirenv_curve_free(&back);

    /* Nothing is written for a curve that is not finite, and the old file stays. */
    struct stat before, after;
    assert_int_equal(stat(path, &before), 0);
    c.h[3] = NAN;
    assert_int_equal(tirenv_curve_write_csv(path, &c, NULL, &d), TIRENV_EINVAL);
    assert_int_equal(stat(path, &after), 0);
    assert_int_equal(after.st_size, before.st_size);
    /* A directory that does not exist: an I/O error and no file. */
    assert_int_equal(tirenv_curve_write_csv("/nonexistent-dir/curve.csv", &back, NULL, &d),
                     TIRENV_EIO);
    tirenv_curve_free(&c);
    remove(path);
}

static void test_csv_crlf_and_comments(void **state)
{
    (void)state;
    char path[64];
    tirenv_test_write_temp(path, "curve",
                           "\xEF\xBB\xBFx_N,x_m,h_m\r\n# from a spreadsheet\r\n\r\n0, -0.5, 0\r\n"
                           "1,0,0.0875\r\n");
    tirenv_curve c;
    tirenv_diag d;
    assert_int_equal(tirenv_curve_read_csv(path, &c, &d), TIRENV_OK);
    assert_int_equal(c.n, 2);
    assert_true(c.x[0] == -0.5 && c.h[1] == 0.0875);
    tirenv_curve_free(&c);
    remove(path);
}

typedef struct {
    const char *name, *text;
    size_t line, column;
    const char *field, *message;
} bad_curve;

static const bad_curve bad_curves[] = {
    {"empty file", "", 1, 1, "", "no header"},
    {"missing header", "0,-0.5,0\n1,0,0.08\n", 1, 1, "x_N", "expected the header"},
    {"wrong header", "x_N,x_m,z_m\n", 1, 9, "h_m", "got 'z_m'"},
    {"short header", "x_N,x_m\n", 1, 8, "", "got 2 columns"},
    {"no rows", "x_N,x_m,h_m\n# nothing yet\n", 3, 1, "", "no data rows"},
    {"non-numeric", "x_N,x_m,h_m\n0,-0.5,0\n0.5,-0.25,4.2mm\n", 3, 11, "h_m",
     "expected a number, got '4.2mm'"},
    {"too few fields", "x_N,x_m,h_m\n0,-0.5\n", 2, 7, "h_m", "expected 3 fields, got 2"},
    {"too many fields", "x_N,x_m,h_m\n0,-0.5,0,1\n", 2, 10, "", "expected 3 fields, got 4"},
    {"NaN", "x_N,x_m,h_m\n0,-0.5,0\n0.5,NaN,0.02\n", 3, 5, "x_m", "finite"},
    {"x_N not increasing", "x_N,x_m,h_m\n0,-0.5,0\n0.5,-0.25,0.02\n0.5,-0.25,0.03\n", 4, 1,
     "x_N", "expected x_N to increase"},
};

static void test_csv_errors(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof bad_curves / sizeof bad_curves[0]; i++) {
        const bad_curve *b = &bad_curves[i];
        char path[64];
        tirenv_test_write_temp(path, "curve", b->text);
        tirenv_curve c = {3, NULL, NULL, NULL};
        tirenv_diag d;
        tirenv_diag_clear(&d);
        print_message("%s\n", b->name);
        tirenv_test_expect_diag(i, tirenv_curve_read_csv(path, &c, &d), &d, TIRENV_EPARSE, path,
                                b->line, b->column, b->field, b->message);
        assert_int_equal(c.n, 0);
        assert_null(c.h);
        remove(path);
    }
    tirenv_curve c;
    tirenv_diag d;
    assert_int_equal(tirenv_curve_read_csv("/nonexistent-dir/curve.csv", &c, &d), TIRENV_EIO);
    assert_int_equal(c.n, 0);
}

/* ---- data sets ---------------------------------------------------------------------------- */

static void test_split_names(void **state)
{
    (void)state;
    assert_string_equal(tirenv_split_name(TIRENV_SPLIT_TRAIN), "train");
    assert_string_equal(tirenv_split_name(TIRENV_SPLIT_CONTROL), "control");
    assert_string_equal(tirenv_split_name(TIRENV_SPLIT_VALIDATION), "validation");
    assert_string_equal(tirenv_split_name((tirenv_split)7), "unknown");
}

/* The fixture: F from its log (imported on reading, and exactly as the import does it), J
 * from its curve, R from its curve although it names a log that is not there. */
static void test_dataset_good(void **state)
{
    (void)state;
    const char *dir = TIRENV_TEST_DATA "/dataset_good";
    tirenv_dataset ds;
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const int status = tirenv_dataset_read(dir, 0.68, &ds, &d);
    if (status)
        print_error("%s\n", d.message);
    assert_int_equal(status, TIRENV_OK);
    assert_string_equal(ds.dir, dir);
    assert_int_equal(ds.n, 3);
    const tirenv_case *F = &ds.cases[0], *J = &ds.cases[1], *R = &ds.cases[2];
    assert_string_equal(F->name, "F");
    assert_int_equal(F->split, TIRENV_SPLIT_VALIDATION);
    assert_true(F->contact_length == 0.38 && F->load == 17860.42 && F->L == 0.30
                && F->H == 0.10);
    assert_string_equal(F->log, TIRENV_TEST_DATA "/dataset_good/logs/F.csv");
    assert_string_equal(F->curve_path, "");
    assert_int_equal(J->split, TIRENV_SPLIT_TRAIN);
    assert_string_equal(J->log, "");
    assert_string_equal(J->curve_path, TIRENV_TEST_DATA "/dataset_good/curves/J.csv");
    assert_int_equal(J->curve.n, 5);
    assert_true(J->curve.h[4] == 0.0472895);
    assert_int_equal(R->split, TIRENV_SPLIT_CONTROL);
    assert_int_equal(R->curve.n, 3);

    tirenv_import_settings s = tirenv_import_default();
    s.R0 = 0.68;
    s.contact_length = 0.38;
    s.L = 0.30;
    s.H = 0.10;
    tirenv_curve direct;
    assert_int_equal(tirenv_rig_import(F->log, &s, &direct, &d), TIRENV_OK);
    assert_int_equal(F->curve.n, direct.n);
    for (size_t k = 0; k < direct.n; k++)
        assert_true(F->curve.h[k] == direct.h[k] && F->curve.x_N[k] == direct.x_N[k]);
    /* The springs model over case F peaks at the cleat's height (0.1 m). */
    assert_near(F->curve.h[F->curve.n - 1], 0.1, 1e-3, 0);
    tirenv_curve_free(&direct);
    tirenv_dataset_free(&ds);
    assert_int_equal(ds.n, 0);
    tirenv_dataset_free(&ds);
    tirenv_dataset_free(NULL);
}

/* A data set written into a fresh temporary directory: the manifest and extra files. */
typedef struct {
    char dir[64];
} temp_dataset;

static void put(const temp_dataset *t, const char *name, const char *text)
{
    char path[128];
    snprintf(path, sizeof path, "%s/%s", t->dir, name);
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    assert_true(fputs(text, fp) >= 0);
    assert_int_equal(fclose(fp), 0);
}

static void drop(const temp_dataset *t, const char *name)
{
    char path[128];
    snprintf(path, sizeof path, "%s/%s", t->dir, name);
    remove(path);
}

#define HEADER "case,split,contact_length_m,load_N,obstacle_length_m,obstacle_height_m,log,curve\n"
#define CURVE_OK "x_N,x_m,h_m\n0,-0.5,0\n1,0,0.08\n"

typedef struct {
    const char *name, *manifest;
    const char *extra_name, *extra_text;  /* one more file, or NULL */
    int status;
    const char *file;                     /* "cases.csv", the extra file, or "" */
    size_t line, column;
    const char *field, *message;
} bad_dataset;

static const bad_dataset bad_datasets[] = {
    {"no manifest", NULL, NULL, NULL, TIRENV_EIO, "cases.csv", 0, 0, "", "cannot open"},
    {"empty manifest", "", NULL, NULL, TIRENV_EPARSE, "cases.csv", 1, 1, "", "no header"},
    {"wrong header", "case,split,contact_length,load_N\n", NULL, NULL, TIRENV_EPARSE,
     "cases.csv", 1, 12, "contact_length_m", "got 'contact_length'"},
    {"no cases", HEADER, NULL, NULL, TIRENV_EPARSE, "cases.csv", 2, 1, "", "no cases"},
    {"unknown split", HEADER "A,test,0.38,17860,0.3,0.1,,a.csv\n", "a.csv", CURVE_OK,
     TIRENV_EPARSE, "cases.csv", 2, 3, "split", "expected train, control or validation"},
    {"duplicate case", HEADER "A,train,0.38,17860,0.3,0.1,,a.csv\nA,control,0.33,13500,0.3,"
     "0.05,,a.csv\n", "a.csv", CURVE_OK, TIRENV_EPARSE, "cases.csv", 3, 1, "case",
     "appears twice"},
    {"no name", HEADER " ,train,0.38,17860,0.3,0.1,,a.csv\n", "a.csv", CURVE_OK, TIRENV_EPARSE,
     "cases.csv", 2, 2, "case", "expected a case name"},
    {"long name", HEADER "A-case-name-of-thirty-two-chars!,train,0.38,17860,0.3,0.1,,a.csv\n",
     "a.csv", CURVE_OK, TIRENV_EPARSE, "cases.csv", 2, 1, "case", "at most 31"},
    {"neither log nor curve", HEADER "A,train,0.38,17860,0.3,0.1,,\n", NULL, NULL,
     TIRENV_EPARSE, "cases.csv", 2, 28, "log", "neither a log nor a curve"},
    {"negative load", HEADER "A,train,0.38,-17860,0.3,0.1,,a.csv\n", "a.csv", CURVE_OK,
     TIRENV_EPARSE, "cases.csv", 2, 14, "load_N", "positive"},
    {"non-numeric height", HEADER "A,train,0.38,17860,0.3,10cm,,a.csv\n", "a.csv", CURVE_OK,
     TIRENV_EPARSE, "cases.csv", 2, 24, "obstacle_height_m", "expected a number"},
    {"NaN length", HEADER "A,train,0.38,17860,nan,0.1,,a.csv\n", "a.csv", CURVE_OK,
     TIRENV_EPARSE, "cases.csv", 2, 20, "obstacle_length_m", "finite"},
    {"seven fields", HEADER "A,train,0.38,17860,0.3,0.1,a.csv\n", NULL, NULL, TIRENV_EPARSE,
     "cases.csv", 2, 33, "curve", "expected 8 fields, got 7"},
    {"missing curve file", HEADER "A,train,0.38,17860,0.3,0.1,,gone.csv\n", NULL, NULL,
     TIRENV_EIO, "gone.csv", 0, 0, "", "cannot open"},
    {"bad curve file", HEADER "A,train,0.38,17860,0.3,0.1,,a.csv\n", "a.csv",
     "x_N,x_m,h_m\n0,-0.5,0\n1,0,eight\n", TIRENV_EPARSE, "a.csv", 3, 5, "h_m",
     "expected a number"},
    {"bad log file", HEADER "A,train,0.38,17860,0.3,0.1,a.log,\n", "a.log",
     "t_s,x_m,z_m\n0,1.5,0.7\n0.04,1.5\n", TIRENV_EPARSE, "a.log", 3, 9, "z_m",
     "expected 3 fields"},
};

static void test_dataset_errors(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof bad_datasets / sizeof bad_datasets[0]; i++) {
        const bad_dataset *b = &bad_datasets[i];
        temp_dataset t;
        snprintf(t.dir, sizeof t.dir, "/tmp/tirenv_test_dataset_XXXXXX");
        assert_non_null(mkdtemp(t.dir));
        if (b->manifest)
            put(&t, "cases.csv", b->manifest);
        if (b->extra_name)
            put(&t, b->extra_name, b->extra_text);
        tirenv_dataset ds;
        tirenv_diag d;
        tirenv_diag_clear(&d);
        char buf[1200], file[128];
        assert_int_equal(tirenv_dataset_read(t.dir, 0.68, &ds, &d), b->status);
        print_message("%-22s %s\n", b->name, tirenv_diag_format(&d, buf, sizeof buf));
        assert_int_equal(ds.n, 0);
        assert_null(ds.cases);
        snprintf(file, sizeof file, "%s/%s", t.dir, b->file);
        assert_string_equal(d.file, file);
        assert_int_equal(d.line, b->line);
        assert_int_equal(d.column, b->column);
        assert_string_equal(d.field, b->field);
        assert_non_null(strstr(d.message, b->message));
        drop(&t, "cases.csv");
        if (b->extra_name)
            drop(&t, b->extra_name);
        assert_int_equal(rmdir(t.dir), 0);
    }
}

/* Importing a log needs the tire radius; a data set of curves alone does not. */
static void test_dataset_needs_radius_for_logs(void **state)
{
    (void)state;
    tirenv_dataset ds;
    tirenv_diag d;
    assert_int_equal(tirenv_dataset_read(TIRENV_TEST_DATA "/dataset_good", NAN, &ds, &d),
                     TIRENV_EINVAL);
    assert_string_equal(d.field, "R0");
    assert_non_null(strstr(d.message, "case 'F'"));
    assert_int_equal(ds.n, 0);
    assert_int_equal(tirenv_dataset_read("", 0.68, &ds, &d), TIRENV_EINVAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_alloc_free),
        cmocka_unit_test(test_xN_origin_closed_form),
        cmocka_unit_test(test_xN_origin_invalid),
        cmocka_unit_test(test_xN),
        cmocka_unit_test(test_csv_round_trip),
        cmocka_unit_test(test_csv_crlf_and_comments),
        cmocka_unit_test(test_csv_errors),
        cmocka_unit_test(test_split_names),
        cmocka_unit_test(test_dataset_good),
        cmocka_unit_test(test_dataset_errors),
        cmocka_unit_test(test_dataset_needs_radius_for_logs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
