/* The network over seeds (tirenv_nn_train_seeds): every seed is the plain training run of
 * that seed, each figure is recomputed here from the curves, the quartiles are R's type 7 of
 * the sorted figures, and the model handed back is the seed nearest the median.
 * SPDX-License-Identifier: Apache-2.0
 *
 * Data: the embedded data set's 28-case design, each case's curve the smooth function
 * h = H (1 + tanh(5(x_N - 0.55) + 4(L - 0.2) - 6(l_c - 0.355)))/2 at 21 x_N (as
 * test_train.c), short training runs (2 restarts, 30 epochs) so the seeds differ. Equalities
 * are exact where the same operations run in the same order (the training, the curve
 * errors), and 1e-15 m where a sum is taken again in another order. */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/study.h"

enum { POINTS = 21, N_SEEDS = 6 };

static const double R0 = 0.68;

static double known_h(double x_N, double l_c, double H, double L)
{
    return H * 0.5 * (1 + tanh(5 * (x_N - 0.55) + 4 * (L - 0.2) - 6 * (l_c - 0.355)));
}

static void make_dataset(tirenv_dataset *ds)
{
    size_t n;
    const tirenv_case_design *des = tirenv_dataset_design(&n);
    memset(ds, 0, sizeof *ds);
    snprintf(ds->dir, sizeof ds->dir, "synthetic");
    ds->cases = calloc(n, sizeof *ds->cases);
    assert_non_null(ds->cases);
    ds->n = n;
    for (size_t c = 0; c < n; ++c) {
        tirenv_case *cs = &ds->cases[c];
        snprintf(cs->name, sizeof cs->name, "%s", des[c].name);
        cs->split = des[c].split;
        cs->contact_length = des[c].contact_length;
        cs->L = des[c].L;
        cs->H = des[c].H;
        assert_int_equal(tirenv_curve_alloc(&cs->curve, POINTS), TIRENV_OK);
        const double x_0 = tirenv_xN_origin(R0, cs->contact_length, cs->L, cs->H);
        for (size_t k = 0; k < POINTS; ++k) {
            const double x_N = -0.1 + 1.1 * (double)k / (POINTS - 1);
            cs->curve.x_N[k] = x_N;
            cs->curve.x[k] = x_0 * (1 - x_N);
            cs->curve.h[k] = known_h(x_N, cs->contact_length, cs->H, cs->L);
        }
    }
}

static int cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void test_seeds(void **state)
{
    (void)state;
    tirenv_dataset ds;
    make_dataset(&ds);
    tirenv_train_settings s = tirenv_train_default(tirenv_trainer_lm);
    s.restarts = 2;
    s.ensemble = 2;
    s.max_epochs = 30;
    s.seed = 40;
    tirenv_nn_seeds r;
    tirenv_nn *median = NULL;
    tirenv_train_report median_rep;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_nn_train_seeds(tirenv_trainer_lm, &s, &ds, &ds, R0, N_SEEDS, &r,
                                             &median, &median_rep, &diag);
    if (status)
        print_error("%s: %s\n", diag.field, diag.message);
    assert_int_equal(status, TIRENV_OK);
    assert_int_equal(r.n_seeds, N_SEEDS);
    assert_int_equal(r.n_cases, 4);  /* F, J, R, AB */
    assert_non_null(median);

    tirenv_samples set[3];
    double *x[3], *y[3], h[POINTS], sorted[N_SEEDS];
    for (int sp = 0; sp < 3; ++sp)
        assert_int_equal(tirenv_samples_from_dataset(&ds, (tirenv_split)sp, &set[sp], &x[sp],
                                                     &y[sp], NULL), TIRENV_OK);
    for (size_t k = 0; k < N_SEEDS; ++k) {
        assert_true(r.seed[k] == 40 + k);
        /* The seed's network is the plain training run of that seed. */
        tirenv_train_settings sk = s;
        sk.seed = r.seed[k];
        tirenv_nn *nn;
        tirenv_train_report rep;
        assert_int_equal(tirenv_train(tirenv_trainer_lm, &sk, &set[0], &set[1], &set[2], &nn,
                                      &rep, NULL), TIRENV_OK);
        double sum = 0, control = 0;
        size_t n_control = 0;
        for (size_t i = 0; i < ds.n; ++i) {
            const tirenv_case *c = &ds.cases[i];
            if (c->split == TIRENV_SPLIT_TRAIN)
                continue;
            tirenv_curve_errors e;
            assert_int_equal(tirenv_case_predict_nn(nn, R0, c, h, NULL), TIRENV_OK);
            assert_int_equal(tirenv_curve_errors_compute(POINTS, c->curve.x, c->curve.h, h,
                                                         1e-3, &e), TIRENV_OK);
            if (c->split == TIRENV_SPLIT_CONTROL) {
                control += e.rms;
                ++n_control;
                continue;
            }
            size_t col = 0;
            while (r.case_index[col] != i)
                ++col;
            assert_true(r.rms[k * r.n_cases + col] == e.rms);
            sum += e.rms;
        }
        assert_near(r.mean_rms[k], sum / 4, 1e-15, 0);
        assert_near(r.control_rms[k], control / (double)n_control, 1e-15, 0);
        if (k == r.median_seed) {
            assert_memory_equal(tirenv_nn_weights(nn), tirenv_nn_weights(median),
                                tirenv_nn_n_weights(nn) * sizeof(double));
            assert_true(rep.error[2].rms == median_rep.error[2].rms);
        }
        tirenv_nn_free(nn);
        sorted[k] = r.mean_rms[k];
    }
    qsort(sorted, N_SEEDS, sizeof sorted[0], cmp);
    print_message("validation over %d seeds: %.3f %.3f %.3f %.3f %.3f %.3f mm\n", N_SEEDS,
                  1e3 * sorted[0], 1e3 * sorted[1], 1e3 * sorted[2], 1e3 * sorted[3],
                  1e3 * sorted[4], 1e3 * sorted[5]);
    assert_true(sorted[0] < sorted[N_SEEDS - 1]);  /* the seeds do differ */
    /* Type 7 with n = 6: the quartiles at ranks 2.25 and 4.75 (1-based), the median at 3.5. */
    assert_near(r.q1, sorted[1] + 0.25 * (sorted[2] - sorted[1]), 1e-18, 0);
    assert_near(r.median, 0.5 * (sorted[2] + sorted[3]), 1e-18, 0);
    assert_near(r.q3, sorted[3] + 0.75 * (sorted[4] - sorted[3]), 1e-18, 0);
    assert_true(r.min == sorted[0] && r.max == sorted[N_SEEDS - 1]);
    for (size_t k = 0; k < N_SEEDS; ++k)
        assert_true(fabs(r.mean_rms[r.median_seed] - r.median) <=
                    fabs(r.mean_rms[k] - r.median));
    for (int sp = 0; sp < 3; ++sp) {
        free(x[sp]);
        free(y[sp]);
    }
    tirenv_nn_free(median);
    tirenv_nn_seeds_free(&r);
    tirenv_nn_seeds_free(&r);  /* twice is harmless */
    tirenv_nn_seeds_free(NULL);
    for (size_t i = 0; i < ds.n; ++i)
        tirenv_curve_free(&ds.cases[i].curve);
    free(ds.cases);

    /* No validation case, no spread. */
    tirenv_dataset empty = {.n = 0, .cases = NULL};
    snprintf(empty.dir, sizeof empty.dir, "empty");
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_nn_train_seeds(tirenv_trainer_lm, &s, &empty, &empty, R0, 3, &r,
                                           NULL, NULL, &diag), TIRENV_EINVAL);
    tirenv_nn_seeds_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_seeds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
