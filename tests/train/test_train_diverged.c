/* Training that diverges is an error (docs/models.md section 6.4): backprop at a learning
 * rate of 1e6 used to return its initial weights as the model with TIRENV_OK.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <math.h>
#include <string.h>

#include "tirenv/tirenv.h"

enum { N = 64 };

/* A smooth function of four inputs on a grid: something a 4-8-1 network can learn. */
static void samples(double x[N * 4], double y[N], size_t offset)
{
    for (size_t k = 0; k < N; ++k) {
        const double t = (double)(k + offset) / (2.0 * N);
        x[4 * k] = t;
        x[4 * k + 1] = 0.28 + 0.15 * fmod(3.1 * t, 1);
        x[4 * k + 2] = 0.025 + 0.075 * fmod(5.3 * t, 1);
        x[4 * k + 3] = 0.05 + 0.25 * fmod(7.7 * t, 1);
        y[k] = x[4 * k + 2] * sin(3 * t) * (1 + x[4 * k + 1]);
    }
}

static int train(double learning_rate, tirenv_nn **nn, tirenv_train_report *rep,
                 tirenv_diag *diag)
{
    static double x[2][N * 4], y[2][N];
    samples(x[0], y[0], 0);
    samples(x[1], y[1], N);
    const tirenv_samples tr = {.n = N, .n_in = 4, .x = x[0], .y = y[0]};
    const tirenv_samples co = {.n = N, .n_in = 4, .x = x[1], .y = y[1]};
    /* The paper's setup: a loss over points, which ungrouped samples allow. */
    tirenv_train_settings s = tirenv_train_paper(tirenv_trainer_backprop);
    s.max_epochs = 30;
    s.backprop.learning_rate = learning_rate;
    tirenv_diag_clear(diag);
    return tirenv_train(tirenv_trainer_backprop, &s, &tr, &co, NULL, nn, rep, diag);
}

static void test_diverged(void **state)
{
    (void)state;
    tirenv_nn *nn = NULL;
    tirenv_train_report rep;
    tirenv_diag diag;
    assert_int_equal(train(1e6, &nn, &rep, &diag), TIRENV_ENOCONV);
    assert_null(nn);
    assert_string_equal(diag.field, "training");
    assert_non_null(strstr(diag.message, "diverged"));
    assert_non_null(strstr(diag.message, "learning rate (now 1e+06)"));
    /* The default rate trains: a model, stopped by its epochs. */
    assert_int_equal(train(0.01, &nn, &rep, &diag), TIRENV_OK);
    assert_non_null(nn);
    assert_int_equal(rep.stop, TIRENV_TRAIN_MAX_EPOCHS);
    tirenv_nn_free(nn);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_diverged),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
