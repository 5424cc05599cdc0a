/* Sweeps (tirenv/sweep.h): the grid's order and names, the split by exact counts and its
 * seed, the checks, and runs: the same bytes for any number of jobs, shards merged equal to
 * one run, a data set tirenv_dataset_read reads, a resumed run equal to an uninterrupted one,
 * and the refusals (another sweep in the way, incomplete or missing shards).
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/dataset.h"
#include "tirenv/sweep.h"
#include "tirenv/tir.h"
#include "sweep/sweep_impl.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const double lengths[] = {0.05, 0.2, 0.15};
static const double heights[] = {0.025, 0.075};
static const double contact_lengths[] = {0.30, 0.36};
static const double c_r[] = {1.4e6, 1.9e6};

/* 3 lengths x 2 heights x 2 contact lengths x 2 values of RADIAL_STIFFNESS = 24 cases of the
 * springs model (fast), 25 % validation and 12.5 % control. */
static tirenv_sweep_settings grid(void)
{
    tirenv_sweep_settings s = tirenv_sweep_default();
    s.type = tirenv_model_springs;
    s.lengths = lengths;
    s.n_lengths = 3;
    s.heights = heights;
    s.n_heights = 2;
    s.contact_lengths = contact_lengths;
    s.n_contact_lengths = 2;
    s.keys[0] = (tirenv_sweep_axis){"RADIAL_STIFFNESS", 2, c_r};
    s.n_keys = 1;
    s.validation_fraction = 0.25;
    s.control_fraction = 0.125;
    return s;
}

/* ---- the grid ------------------------------------------------------------------------- */

static void test_order_and_names(void **state)
{
    (void)state;
    tirenv_sweep_settings s = grid();
    assert_int_equal(tirenv_sweep_count(&s), 24);
    /* Heights fastest, then lengths, regimes, key values. */
    tirenv_sweep__coords c;
    tirenv_sweep__coords_of(&s, 0, &c);
    assert_true(c.height == 0 && c.length == 0 && c.regime == 0 && c.variant == 0);
    tirenv_sweep__coords_of(&s, 1, &c);
    assert_true(c.height == 1 && c.length == 0);
    tirenv_sweep__coords_of(&s, 2, &c);
    assert_true(c.height == 0 && c.length == 1);
    tirenv_sweep__coords_of(&s, 6, &c);
    assert_true(c.height == 0 && c.length == 0 && c.regime == 1 && c.variant == 0);
    tirenv_sweep__coords_of(&s, 23, &c);
    assert_true(c.height == 1 && c.length == 2 && c.regime == 1 && c.variant == 1 &&
                c.key_index[0] == 1);
    /* Every case at a distinct place. */
    int seen[24] = {0};
    for (size_t i = 0; i < 24; ++i) {
        tirenv_sweep__coords_of(&s, i, &c);
        ++seen[((c.variant * 2 + c.regime) * 3 + c.length) * 2 + c.height];
    }
    for (size_t i = 0; i < 24; ++i)
        assert_int_equal(seen[i], 1);
    char name[32];
    tirenv_sweep__case_name(&s, 7, name);
    assert_string_equal(name, "c0007");
    tirenv_sweep__name_of(123457, 42, name);
    assert_string_equal(name, "c000042");
    tirenv_sweep__name_of(10000, 9999, name);
    assert_string_equal(name, "c9999");
    tirenv_sweep__name_of(10001, 10000, name);
    assert_string_equal(name, "c10000");
}

/* Exact counts, a function of the seed and the grid alone; another seed, another draw. */
static void test_split(void **state)
{
    (void)state;
    tirenv_sweep_settings s = grid();
    unsigned char *a, *b, *c;
    assert_int_equal(tirenv_sweep__splits(&s, &a, NULL), TIRENV_OK);
    size_t n[3] = {0};
    for (size_t i = 0; i < 24; ++i)
        ++n[a[i]];
    assert_int_equal(n[TIRENV_SPLIT_VALIDATION], 6);
    assert_int_equal(n[TIRENV_SPLIT_CONTROL], 3);
    assert_int_equal(n[TIRENV_SPLIT_TRAIN], 15);
    s.shard = 2;  /* the shard does not change the draw */
    s.shards = 3;
    assert_int_equal(tirenv_sweep__splits(&s, &b, NULL), TIRENV_OK);
    assert_memory_equal(a, b, 24);
    s.split_seed = 2;
    assert_int_equal(tirenv_sweep__splits(&s, &c, NULL), TIRENV_OK);
    assert_true(memcmp(a, c, 24) != 0);
    free(a);
    free(b);
    free(c);
    s = grid();
    s.validation_fraction = s.control_fraction = 0;
    s.split = TIRENV_SPLIT_CONTROL;
    assert_int_equal(tirenv_sweep__splits(&s, &a, NULL), TIRENV_OK);
    for (size_t i = 0; i < 24; ++i)
        assert_int_equal(a[i], TIRENV_SPLIT_CONTROL);
    free(a);
}

static void test_numbers_and_spec(void **state)
{
    (void)state;
    char buf[32];
    tirenv_sweep__number(0.1, buf);
    assert_string_equal(buf, "0.1");
    tirenv_sweep__number(1.0 / 3, buf);
    assert_true(strtod(buf, NULL) == 1.0 / 3);
    tirenv_sweep__number(1.6e6, buf);
    assert_string_equal(buf, "1600000");
    tirenv_sweep_settings s = grid();
    char *whole = tirenv_sweep__spec(&s);
    s.shard = 1;
    s.shards = 4;
    char *part = tirenv_sweep__spec(&s);
    size_t k, n, b, e;
    assert_int_equal(tirenv_sweep__spec_shard(whole, &k, &n, &b, &e), 0);
    assert_int_equal(tirenv_sweep__spec_shard(part, &k, &n, &b, &e), 1);
    assert_true(k == 1 && n == 4);
    /* Without its shard line, the part's description is the whole sweep's. */
    assert_int_equal(strlen(part) - (e - b), strlen(whole));
    assert_memory_equal(part, whole, b);
    assert_string_equal(part + e, whole + b);
    assert_non_null(strstr(whole, "set RADIAL_STIFFNESS = 1400000,1900000\n"));
    assert_non_null(strstr(whole, "cases = 24\n"));
    free(whole);
    free(part);
    assert_int_equal(tirenv_sweep__spec_shard("shard = 4/4\n", &k, &n, &b, &e), -1);
    assert_int_equal(tirenv_sweep__spec_shard("shard = x\n", &k, &n, &b, &e), -1);
}

static void test_checks(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_diag d;
    tirenv_sweep_settings s = grid();
    assert_int_equal(tirenv_sweep_check(&s, &tire, &d), TIRENV_OK);
    s.n_lengths = 0;
    assert_int_equal(tirenv_sweep_check(&s, &tire, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "lengths");
    s = grid();
    const double twice[] = {0.1, 0.2, 0.1};
    s.lengths = twice;
    assert_int_equal(tirenv_sweep_check(&s, &tire, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "listed twice"));
    s = grid();
    s.loads = c_r;
    s.n_loads = 2;
    assert_int_equal(tirenv_sweep_check(&s, &tire, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "both"));
    s = grid();
    const double too_long[] = {0.3, 1.5};
    s.contact_lengths = too_long;
    assert_int_equal(tirenv_sweep_check(&s, &tire, &d), TIRENV_EINVAL);
    s = grid();
    s.keys[0].key = "NO_SUCH_KEY";
    assert_int_equal(tirenv_sweep_check(&s, &tire, &d), TIRENV_EINVAL);  /* was EPARSE */
    assert_string_equal(d.file, "");
    assert_string_equal(d.field, "NO_SUCH_KEY");
    assert_non_null(strstr(d.message, "swept tire key 1, value 1 ("));
    assert_non_null(strstr(d.message, "unknown key; expected one of"));
    s = grid();
    const double negative[] = {1.4e6, -1};
    s.keys[0].values = negative;
    assert_int_not_equal(tirenv_sweep_check(&s, &tire, &d), TIRENV_OK);
    s = grid();
    s.control_fraction = 0.8;
    assert_int_equal(tirenv_sweep_check(&s, &tire, &d), TIRENV_EINVAL);
    s = grid();
    s.shard = 3;
    s.shards = 3;
    assert_int_equal(tirenv_sweep_check(&s, &tire, &d), TIRENV_EINVAL);
    /* The cam on a tire without its own shape keys: refused, naming the first missing; the
     * springs model does not need them; a swept key counts as the tire's own. */
    tirenv_tire no_shift = tirenv_tire_default();
    no_shift.cam.given = TIRENV_CAM_ALL & ~TIRENV_CAM_SHIFT;
    s = grid();
    assert_int_equal(tirenv_sweep_check(&s, &no_shift, &d), TIRENV_OK);
    s.type = tirenv_model_cam;
    assert_int_equal(tirenv_sweep_check(&s, &tire, &d), TIRENV_OK);
    assert_int_equal(tirenv_sweep_check(&s, &no_shift, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "ELLIPS_SHIFT");
    assert_non_null(strstr(d.message, "cam keys ELLIPS_SHIFT ("));
    const double shifts[] = {0.8328, 0.7};
    s.keys[1] = (tirenv_sweep_axis){"ELLIPS_SHIFT", 2, shifts};
    s.n_keys = 2;
    assert_int_equal(tirenv_sweep_check(&s, &no_shift, &d), TIRENV_OK);
}

/* ---- runs -------------------------------------------------------------------------------- */

/* diff -r in a shell: the test is about bytes, and diff says where they differ. */
static int same_tree(const char *a, const char *b)
{
    char cmd[1400];
    snprintf(cmd, sizeof cmd, "diff -r '%s' '%s' >&2", a, b);
    return system(cmd) == 0;
}

/* The grid the runs use: one contact length, 12 cases (3 validation, round(1.5) = 2
 * control), so that the sanitizer build runs them in seconds. */
static tirenv_sweep_settings small_grid(void)
{
    tirenv_sweep_settings s = grid();
    s.n_contact_lengths = 1;
    return s;
}

static void run_ok(const char *dir, const tirenv_sweep_settings *s, tirenv_sweep_report *rep)
{
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const int status = tirenv_sweep_run(dir, &tire, s, rep, &d);
    if (status)
        fprintf(stderr, "sweep %s: %s\n", dir, d.message);
    assert_int_equal(status, TIRENV_OK);
}

static void test_runs(void **state)
{
    const tirenv_test_dir *t = *state;
    char one[600], three[600], parts[3][600], merged[600], path[700];
    tirenv_test_path(t, "one", one);
    tirenv_test_path(t, "three", three);
    tirenv_test_path(t, "merged", merged);
    tirenv_sweep_settings s = small_grid();
    tirenv_sweep_report rep;
    run_ok(one, &s, &rep);
    assert_int_equal(rep.cases, 12);
    assert_int_equal(rep.run, 12);
    assert_int_equal(rep.resumed, 0);
    /* Eight threads writing files at once: each gets the mode the umask gives, and the
     * umask stays what it was. */
    const mode_t old_mask = umask(027);
    s.jobs = 8;
    run_ok(three, &s, &rep);
    assert_int_equal(umask(old_mask), 027);
    assert_true(same_tree(one, three));
    for (size_t i = 0; i < 12; ++i) {
        char f[800];
        struct stat st;
        snprintf(f, sizeof f, "%s/curves/c%04zu.csv", three, i);
        assert_int_equal(stat(f, &st), 0);
        assert_int_equal(st.st_mode & 0777, 0640);
    }
    s.jobs = 3;
    /* Again: complete, nothing to do. */
    run_ok(three, &s, &rep);
    assert_true(rep.already_complete);

    /* Three shards, on two threads each, merged in another order. */
    const char *order[3];
    for (size_t k = 0; k < 3; ++k) {
        char name[16];
        snprintf(name, sizeof name, "part%zu", k);
        tirenv_test_path(t, name, parts[k]);
        s.shard = k;
        s.shards = 3;
        s.jobs = 2;
        run_ok(parts[k], &s, &rep);
        assert_int_equal(rep.part_cases, 4);
        order[(k + 1) % 3] = parts[k];
    }
    tirenv_diag d;
    tirenv_diag_clear(&d);
    assert_int_equal(tirenv_sweep_merge(merged, 2, order, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "missing"));
    assert_int_equal(tirenv_sweep_merge(merged, 3, order, &d), TIRENV_OK);
    assert_true(same_tree(one, merged));
    const char *dup[3] = {parts[0], parts[1], parts[1]};
    assert_int_equal(tirenv_sweep_merge(merged, 3, dup, &d), TIRENV_EINVAL);
    const char *whole[1] = {one};
    assert_int_equal(tirenv_sweep_merge(merged, 1, whole, &d), TIRENV_EINVAL);

    /* The data set reads, with the splits drawn. */
    tirenv_dataset ds;
    assert_int_equal(tirenv_dataset_read(one, 0.68, &ds, &d), TIRENV_OK);
    assert_int_equal(ds.n, 12);
    size_t n_val = 0;
    for (size_t i = 0; i < ds.n; ++i) {
        n_val += ds.cases[i].split == TIRENV_SPLIT_VALIDATION;
        assert_int_equal(ds.cases[i].curve.n, 101);
        double peak = 0;
        for (size_t k = 0; k < ds.cases[i].curve.n; ++k)
            peak = fmax(peak, ds.cases[i].curve.h[k]);
        /* The curve rises over the cleat, and never above it. */
        assert_true(peak > 0.2 * ds.cases[i].H && peak <= ds.cases[i].H + 1e-9);
    }
    assert_int_equal(n_val, 3);
    /* The swept key took effect: the stiffer variant (cases 6 to 11) needs more load for
     * the same contact length. */
    assert_string_equal(ds.cases[6].name, "c0006");
    assert_true(ds.cases[6].contact_length == ds.cases[0].contact_length);
    assert_true(ds.cases[6].load > 1.1 * ds.cases[0].load);
    tirenv_dataset_free(&ds);
    snprintf(path, sizeof path, "%s/sweep.csv", one);
    assert_int_equal(access(path, R_OK), 0);
}

/* An interrupted run: the cases a kill left behind are kept, what it left half-written is
 * removed, and the result is the uninterrupted run's bytes. */
static void test_resume(void **state)
{
    const tirenv_test_dir *t = *state;
    char one[600], two[600], cmd[8192];
    tirenv_test_path(t, "one", one);
    tirenv_test_path(t, "two", two);
    tirenv_sweep_settings s = small_grid();
    s.type = tirenv_model_cam;
    tirenv_sweep_report rep;
    run_ok(one, &s, &rep);
    /* What a killed run leaves: its description, its tire, some whole cases, a temporary
     * file and a manifest it was writing. */
    snprintf(cmd, sizeof cmd,
             "set -e; mkdir -p '%s.partial/curves'; cp '%s/sweep.txt' '%s/tire.tir' '%s.partial/';"
             "cp '%s/curves/c0003.csv' '%s/curves/c0009.csv' '%s.partial/curves/';"
             "echo half > '%s.partial/curves/c0004.csv.tmp.abc123';"
             "echo half > '%s.partial/curves/.c0005.csv.tirenv-tmp.0badcafe.999999.5eed5eed';"
             "echo half > '%s.partial/cases.csv.tmp.xyz'",
             two, one, one, two, one, one, two, two, two, two);
    assert_int_equal(system(cmd), 0);
    s.jobs = 2;
    run_ok(two, &s, &rep);
    assert_int_equal(rep.resumed, 2);
    assert_int_equal(rep.run, 10);
    assert_true(same_tree(one, two));
    char partial[700];
    snprintf(partial, sizeof partial, "%s.partial", two);
    assert_int_not_equal(access(partial, F_OK), 0);

    /* A file no run writes, in this sweep's partial directory (new, or resumed): refused and
     * kept, not removed as a run's leftover. */
    char four[600], notes[700];
    tirenv_test_path(t, "four", four);
    snprintf(notes, sizeof notes, "%s.partial/notes.txt", four);
    for (int resumed = 0; resumed < 2; ++resumed) {
        snprintf(cmd, sizeof cmd, "mkdir -p '%s.partial' && echo mine > '%s'", four, notes);
        assert_int_equal(system(cmd), 0);
        if (resumed) {
            snprintf(cmd, sizeof cmd, "cp '%s/sweep.txt' '%s/tire.tir' '%s.partial/'", one, one,
                     four);
            assert_int_equal(system(cmd), 0);
        }
        const tirenv_tire tire0 = tirenv_tire_default();
        tirenv_diag d0;
        assert_int_equal(tirenv_sweep_run(four, &tire0, &s, NULL, &d0), TIRENV_EIO);
        assert_string_equal(d0.file, notes);
        assert_non_null(strstr(d0.message, "an entry no sweep writes"));
        assert_int_equal(access(notes, F_OK), 0);
    }
    snprintf(cmd, sizeof cmd, "rm -rf '%s.partial'", four);
    assert_int_equal(system(cmd), 0);

    /* Another sweep's partial directory, or a foreign entry in it, is refused. */
    snprintf(cmd, sizeof cmd, "mkdir -p '%s.partial' && cp '%s/sweep.txt' '%s.partial/'", two,
             one, two);
    assert_int_equal(system(cmd), 0);
    tirenv_sweep_settings other = small_grid();
    other.type = tirenv_model_springs;
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_diag d;
    char three[600];
    tirenv_test_path(t, "three", three);
    snprintf(cmd, sizeof cmd, "mv '%s.partial' '%s.partial'", two, three);
    assert_int_equal(system(cmd), 0);
    assert_int_equal(tirenv_sweep_run(three, &tire, &other, NULL, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "another sweep"));
    /* And a target that holds something else. */
    assert_int_equal(tirenv_sweep_run(one, &tire, &other, NULL, &d), TIRENV_EINVAL);
    snprintf(cmd, sizeof cmd, "rm -rf '%s.partial'", three);
    assert_int_equal(system(cmd), 0);
}

/* Through the rig: each case's log too, the same bytes for 1 and 3 jobs. */
static void test_rig(void **state)
{
    const tirenv_test_dir *t = *state;
    char one[600], three[600], path[700];
    tirenv_test_path(t, "one", one);
    tirenv_test_path(t, "three", three);
    tirenv_sweep_settings s = grid();
    s.n_lengths = 1;
    s.n_keys = 0;
    s.type = tirenv_model_springs;
    s.rig = 1;
    s.validation_fraction = s.control_fraction = 0;
    tirenv_sweep_report rep;
    run_ok(one, &s, &rep);
    assert_int_equal(rep.cases, 4);
    s.jobs = 3;
    run_ok(three, &s, &rep);
    assert_true(same_tree(one, three));
    snprintf(path, sizeof path, "%s/logs/c0003.csv", one);
    assert_int_equal(access(path, R_OK), 0);
}

/* A whole file read up to a limit (tirenv_sweep__read_text, what sweep merge and resume read
 * their tables with): the buffer grows with the file, past its first 64 KiB, so the bytes of a
 * file of 200,000 come back whole; a file of exactly the limit is read, one byte more is
 * refused naming the limit; an empty file is an empty text. */
static void test_read_text(void **state)
{
    const tirenv_test_dir *t = *state;
    char path[600];
    tirenv_test_path(t, "text", path);
    enum { N = 200000 };
    char *want = malloc(N);
    assert_non_null(want);
    for (size_t i = 0; i < N; ++i)
        want[i] = (char)('a' + (i * 7 + i / 613) % 26);
    tirenv_diag d;
    char *got;
    size_t n;
    const size_t sizes[] = {0, 1, 65535, 65536, 65537, 131072, N};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; ++k) {
        FILE *fp = fopen(path, "wb");
        assert_non_null(fp);
        assert_int_equal(fwrite(want, 1, sizes[k], fp), sizes[k]);
        assert_int_equal(fclose(fp), 0);
        /* Limits below, at and above the size. */
        const size_t limits[] = {sizes[k], sizes[k] + 1, 4 * (size_t)N, sizes[k] - 1};
        for (size_t j = 0; j < 4; ++j) {
            if (j == 3 && sizes[k] == 0)
                break;
            tirenv_diag_clear(&d);
            const int status = tirenv_sweep__read_text(path, limits[j], &got, &n, &d);
            if (j < 3) {
                assert_int_equal(status, TIRENV_OK);
                assert_int_equal(n, sizes[k]);
                assert_int_equal(got[n], '\0');
                if (n)
                    assert_memory_equal(got, want, n);
                free(got);
            } else {
                assert_int_equal(status, TIRENV_EIO);
                assert_null(got);
                char msg[64];
                snprintf(msg, sizeof msg, "longer than %zu bytes", limits[j]);
                assert_non_null(strstr(d.message, msg));
            }
        }
    }
    free(want);
}

/* Two sweeps of one process into one parent at once, on two threads, each with its own tire:
 * each finishes, its tire.tir its own tire. The tire's scratch file was named by the process
 * alone, so one sweep read the other's tire (and wrote it, status OK) while the other failed.
 * A race, so a test that fails by chance: 40 rounds of a one-case rigid sweep failed 1 run of
 * the test in 5 before the fix (measured), 0 in 10 after. */
typedef struct {
    const tirenv_test_dir *t;
    int round, id, ok;
    pthread_barrier_t *start;
} twin;

static void *twin_run(void *arg)
{
    twin *w = arg;
    tirenv_tire tire = tirenv_tire_default();
    tire.springs.c_r *= w->id ? 1.4375 : 1.0;
    static const double L[] = {0.2385}, H[] = {0.0415}, l_c[] = {0.3315};
    tirenv_sweep_settings s = tirenv_sweep_default();
    s.type = tirenv_model_type_find("rigid");
    s.lengths = L;
    s.n_lengths = 1;
    s.heights = H;
    s.n_heights = 1;
    s.contact_lengths = l_c;
    s.n_contact_lengths = 1;
    char name[32], dir[600], path[700];
    snprintf(name, sizeof name, "twin%d-%d", w->round, w->id);
    tirenv_test_path(w->t, name, dir);
    pthread_barrier_wait(w->start);
    w->ok = tirenv_sweep_run(dir, &tire, &s, NULL, NULL) == TIRENV_OK;
    snprintf(path, sizeof path, "%s/tire.tir", dir);
    tirenv_tire back = tirenv_tire_default();
    w->ok = w->ok && tirenv_tir_read(path, &back, NULL) == TIRENV_OK &&
            back.springs.c_r == tire.springs.c_r;
    return NULL;
}

static void test_two_at_once(void **state)
{
    for (int round = 0; round < 40; ++round) {
        pthread_barrier_t start;
        assert_int_equal(pthread_barrier_init(&start, NULL, 2), 0);
        twin w[2] = {{*state, round, 0, 0, &start}, {*state, round, 1, 0, &start}};
        pthread_t th[2];
        for (int i = 0; i < 2; ++i)
            assert_int_equal(pthread_create(&th[i], NULL, twin_run, &w[i]), 0);
        for (int i = 0; i < 2; ++i)
            pthread_join(th[i], NULL);
        pthread_barrier_destroy(&start);
        assert_true(w[0].ok);
        assert_true(w[1].ok);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_order_and_names),
        cmocka_unit_test(test_split),
        cmocka_unit_test(test_numbers_and_spec),
        cmocka_unit_test(test_checks),
        cmocka_unit_test_setup_teardown(test_runs, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown_tree),
        cmocka_unit_test_setup_teardown(test_resume, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown_tree),
        cmocka_unit_test_setup_teardown(test_rig, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown_tree),
        cmocka_unit_test_setup_teardown(test_two_at_once, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown_tree),
        cmocka_unit_test_setup_teardown(test_read_text, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown_tree),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
