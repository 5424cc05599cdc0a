/* SPDX-License-Identifier: Apache-2.0 */
/* The embedded data sets as designed (docs/models.md section 5.8): the paper's design shape in
 * each, the 205/60R15 set within its cam's validated range; a built data set's record of its
 * source (source.txt, tire.tir, the manifest's count of cases) and its curves against the
 * simulating model's own. */
#define _XOPEN_SOURCE 700
#include <ftw.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "tirenv/tirenv.h"

/* ---- the designs --------------------------------------------------------------------------- */

static void test_designs_listed(void **state)
{
    (void)state;
    const tirenv_design *const *d = tirenv_designs();
    assert_non_null(d[0]);
    assert_string_equal(d[0]->name, "14.9R28");  /* the default first */
    assert_non_null(d[1]);
    assert_null(d[2]);
    for (size_t k = 0; d[k]; ++k) {
        assert_ptr_equal(tirenv_design_find(d[k]->name), d[k]);
        /* The simulating model is a physical model type. */
        const tirenv_model_type *t = tirenv_model_type_find(d[k]->model);
        assert_non_null(t);
        assert_false(tirenv_model_type_flags(t) & TIRENV_MODEL_NEEDS_NETWORK);
    }
    assert_string_equal(tirenv_design_find("205-60R15")->model, "cam");
    assert_string_equal(tirenv_design_find("14.9R28")->model, "ring");
    assert_null(tirenv_design_find("no-such-design"));
    assert_null(tirenv_design_find(NULL));
    /* The tractor design is the one the older call returns. */
    size_t n;
    assert_ptr_equal(tirenv_dataset_design(&n), tirenv_design_find("14.9R28")->cases);
    assert_ptr_equal(tirenv_dataset_design(NULL), tirenv_design_find("14.9R28")->cases);
    assert_int_equal(n, 28);
}

/* Sorted distinct values of one factor over the cases with `split` (or all, split < 0). */
static size_t factor_values(const tirenv_design *d, int split, int factor, double v[64])
{
    size_t n = 0;
    for (size_t i = 0; i < d->n_cases; ++i) {
        const tirenv_case_design *c = &d->cases[i];
        if (split >= 0 && c->split != (tirenv_split)split)
            continue;
        const double x = factor == 0 ? c->contact_length : factor == 1 ? c->L : c->H;
        size_t k = 0;
        while (k < n && v[k] != x)
            ++k;
        if (k == n)
            v[n++] = x;
    }
    return n;
}

/* The paper's design shape (its Table 2): 28 cases, 19 / 5 / 4, the validation cases F, J, R
 * and AB; every value of each factor in training; each validation case inside the training
 * ranges; no case twice. */
static void test_design_shape(void **state)
{
    (void)state;
    for (const tirenv_design *const *d = tirenv_designs(); *d; ++d) {
        const tirenv_design *des = *d;
        assert_int_equal(des->n_cases, 28);
        size_t count[3] = {0};
        for (size_t i = 0; i < des->n_cases; ++i) {
            const tirenv_case_design *c = &des->cases[i];
            ++count[c->split];
            for (size_t j = 0; j < i; ++j) {
                const tirenv_case_design *o = &des->cases[j];
                assert_string_not_equal(c->name, o->name);
                assert_false(c->contact_length == o->contact_length && c->L == o->L &&
                             c->H == o->H);
            }
        }
        assert_int_equal(count[TIRENV_SPLIT_TRAIN], 19);
        assert_int_equal(count[TIRENV_SPLIT_CONTROL], 5);
        assert_int_equal(count[TIRENV_SPLIT_VALIDATION], 4);
        const char *const validation[] = {"F", "J", "R", "AB"};
        size_t k = 0;
        for (size_t i = 0; i < des->n_cases; ++i)
            if (des->cases[i].split == TIRENV_SPLIT_VALIDATION)
                assert_string_equal(des->cases[i].name, validation[k++]);
        for (int f = 0; f < 3; ++f) {
            double all[64], train[64];
            const size_t n_all = factor_values(des, -1, f, all);
            assert_int_equal(factor_values(des, TIRENV_SPLIT_TRAIN, f, train), n_all);
        }
        /* R: the shortest-but-one cleat at its tallest, at the smallest contact length. */
        const tirenv_case_design *R = &des->cases[17];
        assert_string_equal(R->name, "R");
        double lc[64], H[64];
        const size_t n_lc = factor_values(des, -1, 0, lc), n_H = factor_values(des, -1, 2, H);
        double lc_min = INFINITY, H_max = 0;
        for (size_t i = 0; i < n_lc; ++i)
            lc_min = fmin(lc_min, lc[i]);
        for (size_t i = 0; i < n_H; ++i)
            H_max = fmax(H_max, H[i]);
        assert_true(R->contact_length == lc_min && R->H == H_max);
    }
}

/* The car tire's set stays where TNO's cam was identified (ELLIPS_MAX_STEP 0.025 m), at loads
 * around the file's nominal 4 kN, and its contact lengths are the cam's at those loads. */
static void test_design_205_in_range(void **state)
{
    (void)state;
    const tirenv_design *d = tirenv_design_find("205-60R15");
    double lc[64];
    assert_int_equal(factor_values(d, -1, 0, lc), 3);  /* three loads */
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_tir_read(TIRENV_DATA_DIR "/tires/205-60R15-mfswift.tir", &t, &diag),
                     TIRENV_OK);
    tirenv_model *cam = tirenv_model_alloc(tirenv_model_cam, &t);
    assert_non_null(cam);
    for (size_t i = 0; i < d->n_cases; ++i) {
        const tirenv_case_design *c = &d->cases[i];
        assert_true(c->H > 0 && c->H <= 0.025);
        assert_true(c->L >= 0.01 && c->L <= 0.10);
        double load;
        assert_int_equal(tirenv_model_load_for_contact_length(cam, c->contact_length, &load,
                                                              &diag), TIRENV_OK);
        assert_true(load > 0.7 * 4000 && load < 1.3 * 4000);
    }
    tirenv_model_free(cam);
}

/* ---- source.txt -------------------------------------------------------------------------- */

static void test_source_read(void **state)
{
    const tirenv_test_dir *d = *state;
    char path[600];
    tirenv_dataset_source src;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    /* None: says nothing, and that is no error. */
    assert_int_equal(tirenv_dataset_source_read(d->dir, &src, &diag), TIRENV_OK);
    assert_int_equal(src.present, 0);
    assert_string_equal(src.model, "");
    tirenv_test_write_text(tirenv_test_path(d, "source.txt", path),
                           "# a comment\n\nformat = tirenv-dataset 1\n  design=205-60R15  \n"
                           "model = cam\ntire = tire.tir\n");
    assert_int_equal(tirenv_dataset_source_read(d->dir, &src, &diag), TIRENV_OK);
    assert_int_equal(src.present, 1);
    assert_string_equal(src.design, "205-60R15");
    assert_string_equal(src.model, "cam");
    char want[600];
    snprintf(want, sizeof want, "%s/tire.tir", d->dir);  /* relative to the data set */
    assert_string_equal(src.tire, want);
    tirenv_test_write_text(path, "format = tirenv-dataset 1\ntire = /abs/t.tir\n");
    assert_int_equal(tirenv_dataset_source_read(d->dir, &src, &diag), TIRENV_OK);
    assert_string_equal(src.tire, "/abs/t.tir");
    assert_string_equal(src.model, "");
    /* Refused, with the line and the key. */
    const struct {
        const char *text;
        size_t line;
        const char *field;
    } bad[] = {
        {"format = tirenv-dataset 1\nmodel = nn\n", 2, "model"},
        {"format = tirenv-dataset 1\nmodel = no-such-model\n", 2, "model"},
        {"format = tirenv-dataset 2\n", 1, "format"},
        {"format = tirenv-dataset 1\nmodel = cam\nmodel = ring\n", 3, "model"},
        {"format = tirenv-dataset 1\nsimulator = ring\n", 2, "simulator"},
        {"format = tirenv-dataset 1\nmodel =\n", 2, "model"},
        {"format = tirenv-dataset 1\njust words\n", 2, ""},
        {"model = cam\n", 1, "format"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        tirenv_test_write_text(path, bad[k].text);
        tirenv_diag_clear(&diag);
        assert_int_equal(tirenv_dataset_source_read(d->dir, &src, &diag), TIRENV_EPARSE);
        assert_int_equal(src.present, 0);
        assert_int_equal(diag.line, bad[k].line);
        assert_string_equal(diag.field, bad[k].field);
        assert_non_null(strstr(diag.file, "source.txt"));
    }
    remove(path);
}

/* source.txt's `cases` against the manifest. A manifest cut at a line end is whole rows, a
 * shorter data set that reads: with the count declared it is refused, at the manifest's end,
 * naming its count and the line of source.txt; the same count, or none, reads. */
static void test_source_cases(void **state)
{
    const tirenv_test_dir *d = *state;
    char manifest[600], source[600], rows[2000], message[1200];
    tirenv_test_path(d, "cases.csv", manifest);
    tirenv_test_path(d, "source.txt", source);
    /* Three cases on the fixture's curve; the manifest cut after the second row's line end. */
    const char *curve = TIRENV_TEST_DATA "/dataset_good/curves/J.csv";
    const int w = snprintf(rows, sizeof rows,
                           "# three cases\n"
                           "case,split,contact_length_m,load_N,obstacle_length_m,"
                           "obstacle_height_m,log,curve\n"
                           "A,train,0.33,13527.5,0.30,0.05,,%s\n"
                           "B,control,0.33,13527.5,0.30,0.05,,%s\n"
                           "C,validation,0.33,13527.5,0.30,0.05,,%s\n",
                           curve, curve, curve);
    assert_true(w > 0 && (size_t)w < sizeof rows);
    const char *third = strstr(rows, "C,validation");
    assert_non_null(third);
    char cut[2000];
    memcpy(cut, rows, (size_t)(third - rows));
    cut[third - rows] = '\0';
    tirenv_dataset ds;
    tirenv_dataset_source src;
    tirenv_diag diag;
    /* Read: no source.txt; one without the key; one declaring the manifest's count. */
    tirenv_test_write_text(manifest, rows);
    const char *reads[] = {NULL, "format = tirenv-dataset 1\nmodel = ring\n",
                           "format = tirenv-dataset 1\n# the manifest's rows\ncases = 3\n"};
    for (size_t k = 0; k < sizeof reads / sizeof reads[0]; ++k) {
        if (reads[k])
            tirenv_test_write_text(source, reads[k]);
        tirenv_diag_clear(&diag);
        assert_int_equal(tirenv_dataset_read(d->dir, 0.68, &ds, &diag), TIRENV_OK);
        assert_int_equal(ds.n, 3);
        assert_string_equal(ds.cases[2].name, "C");
        tirenv_dataset_free(&ds);
    }
    assert_int_equal(tirenv_dataset_source_read(d->dir, &src, &diag), TIRENV_OK);
    assert_int_equal(src.cases, 3);
    assert_int_equal(src.cases_line, 3);
    /* Cut: refused after its last line (4), naming its 2 cases and source.txt:3's 3. */
    tirenv_test_write_text(manifest, cut);
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_dataset_read(d->dir, 0.68, &ds, &diag), TIRENV_EPARSE);
    print_message("cut: %s\n", tirenv_diag_format(&diag, message, sizeof message));
    assert_int_equal(ds.n, 0);
    assert_null(ds.cases);
    assert_string_equal(diag.file, manifest);
    assert_int_equal(diag.line, 5);
    assert_non_null(strstr(diag.message, "2 cases"));
    char names[700];
    snprintf(names, sizeof names, "%s:3 declares cases = 3", source);
    assert_non_null(strstr(diag.message, names));
    /* One row more than declared: refused at that row (line 5). */
    tirenv_test_write_text(manifest, rows);
    tirenv_test_write_text(source, "format = tirenv-dataset 1\ncases = 2\n");
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_dataset_read(d->dir, 0.68, &ds, &diag), TIRENV_EPARSE);
    assert_int_equal(ds.n, 0);
    assert_string_equal(diag.file, manifest);
    assert_int_equal(diag.line, 5);
    assert_non_null(strstr(diag.message, "more than 2 cases"));
    assert_non_null(strstr(diag.message, "source.txt:2 declares cases = 2"));
    /* Values that are no count of a manifest: refused where source.txt is read, alone or with
     * the data set, at the key's line and value's column. */
    const char *bad[] = {"2.5", "-3", "+3", "3 cases", "0x3", "3e0", "0", "1000001",
                         "99999999999999999999", ""};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        char text[200];
        snprintf(text, sizeof text, "format = tirenv-dataset 1\ncases = %s\n", bad[k]);
        tirenv_test_write_text(source, text);
        tirenv_diag_clear(&diag);
        assert_int_equal(tirenv_dataset_source_read(d->dir, &src, &diag), TIRENV_EPARSE);
        assert_int_equal(src.cases, 0);
        assert_int_equal(diag.line, 2);
        assert_int_equal(diag.column, 9);
        assert_string_equal(diag.field, "cases");
        assert_string_equal(diag.file, source);
        assert_non_null(strstr(diag.message, "from 1 to 1000000"));
        tirenv_diag_clear(&diag);
        assert_int_equal(tirenv_dataset_read(d->dir, 0.68, &ds, &diag), TIRENV_EPARSE);
        assert_string_equal(diag.file, source);
        assert_int_equal(ds.n, 0);
    }
    /* The largest count a manifest may hold is a count (here not the manifest's). */
    tirenv_test_write_text(source, "format = tirenv-dataset 1\ncases = 1000000\n");
    assert_int_equal(tirenv_dataset_source_read(d->dir, &src, &diag), TIRENV_OK);
    assert_int_equal(src.cases, 1000000);
    remove(source);
    remove(manifest);
}

/* ---- a built data set -------------------------------------------------------------------- */

static int remove_entry(const char *path, const struct stat *sb, int flag, struct FTW *ftw)
{
    (void)sb;
    (void)flag;
    (void)ftw;
    return remove(path);
}

/* The 205/60R15 set built afresh (the cam is quick): its record of its source reads back to
 * the design and the tire it was built from, and each curve, through the rig's noise and the
 * import, is the cam's own curve at the case's load within what the noise leaves. */
static void test_build_205(void **state)
{
    (void)state;
    char dir[] = "/tmp/tirenv-test-design-XXXXXX";
    assert_non_null(mkdtemp(dir));
    const tirenv_design *d = tirenv_design_find("205-60R15");
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_tir_read(TIRENV_DATA_DIR "/tires/205-60R15-mfswift.tir", &t, &diag),
                     TIRENV_OK);
    assert_int_equal(tirenv_dataset_build_design(dir, d, &t, NULL, &diag), TIRENV_OK);
    tirenv_dataset_source src;
    assert_int_equal(tirenv_dataset_source_read(dir, &src, &diag), TIRENV_OK);
    assert_string_equal(src.design, "205-60R15");
    assert_string_equal(src.model, "cam");
    assert_int_equal(src.cases, d->n_cases);  /* what the manifest holds, checked on reading */
    tirenv_tire back = tirenv_tire_default();
    assert_int_equal(tirenv_tir_read(src.tire, &back, &diag), TIRENV_OK);
    assert_memory_equal(&back.springs, &t.springs, sizeof t.springs);
    assert_memory_equal(&back.ring, &t.ring, sizeof t.ring);
    /* The cam's fields one by one: its struct ends in padding after `given`. */
    const double *bc = &back.cam.c_z, *tc = &t.cam.c_z;
    for (size_t k = 0; k < 7; ++k)
        assert_bits_equal(bc[k], tc[k]);
    assert_int_equal(back.cam.given, t.cam.given);
    tirenv_dataset ds;
    assert_int_equal(tirenv_dataset_read(dir, t.springs.R0, &ds, &diag), TIRENV_OK);
    assert_int_equal(ds.n, 28);
    tirenv_model *cam = tirenv_model_alloc(tirenv_model_cam, &t);
    assert_non_null(cam);
    double worst = 0;
    for (size_t i = 0; i < ds.n; ++i) {
        const tirenv_case *c = &ds.cases[i];
        assert_string_equal(c->name, d->cases[i].name);
        assert_true(c->split == d->cases[i].split);
        double h[256];
        assert_true(c->curve.n <= 256);
        assert_int_equal(tirenv_case_predict_model(cam, c, h, &diag), TIRENV_OK);
        double sum = 0;
        for (size_t k = 0; k < c->curve.n; ++k)
            sum += (h[k] - c->curve.h[k]) * (h[k] - c->curve.h[k]);
        worst = fmax(worst, sqrt(sum / (double)c->curve.n));
    }
    /* The import aims at 0.05 mm standard error from 0.2 mm sensor noise; 0.05-0.08 mm RMS
     * measured over the 28 cases. 0.15 mm would be a misplaced centre or a lost peak. */
    print_message("205/60R15 set: worst RMS of the imported curves against the cam %.3f mm\n",
                  worst * 1e3);
    assert_true(worst < 0.15e-3);
    tirenv_model_free(cam);
    tirenv_dataset_free(&ds);
    assert_int_equal(nftw(dir, remove_entry, 8, FTW_DEPTH | FTW_PHYS), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_designs_listed),
        cmocka_unit_test(test_design_shape),
        cmocka_unit_test(test_design_205_in_range),
        cmocka_unit_test_setup_teardown(test_source_read, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_source_cases, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test(test_build_205),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
