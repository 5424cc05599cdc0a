/* One progress callback shared by trainings that run at once (tirenv_train_progress_gate):
 * its calls never overlap, and its request to stop holds for every later call.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <math.h>
#include <string.h>
#include <time.h>

#include "tirenv/tirenv.h"
#include "tirenv/parallel.h"

/* Written by the callback only; without the gate two workers would be inside at once. No
 * cmocka assertion runs on a worker thread: they are checked afterwards. */
typedef struct {
    size_t calls;        /* calls of the callback itself */
    int inside, overlap; /* callers inside now; set if ever more than one */
    size_t stop_at;      /* the one call that asks to stop (0: none) */
} counter;

static int count(const tirenv_train_progress *p, void *data)
{
    (void)p;
    counter *c = data;
    if (++c->inside > 1)
        c->overlap = 1;
    const struct timespec pause = {0, 100000};  /* 0.1 ms: long enough for others to arrive */
    nanosleep(&pause, NULL);
    const int stop = ++c->calls == c->stop_at;
    --c->inside;
    return stop;
}

enum { ITEMS = 16, CALLS = 20, STOP_AT = 100 };

typedef struct {
    const tirenv_train_settings *s;
    size_t stops[ITEMS];  /* calls of item k answered "stop" */
} calls_pass;

static int call_item(void *ctx, size_t k, size_t worker, tirenv_diag *diag)
{
    (void)worker;
    (void)diag;
    calls_pass *p = ctx;
    const tirenv_train_progress pr = {0};
    for (size_t i = 0; i < CALLS; ++i)
        p->stops[k] += p->s->progress(&pr, p->s->progress_data) != 0;
    return TIRENV_OK;
}

/* 16 items of 20 calls on 4 threads: no two calls of the callback overlap, it is called until
 * it asks to stop (its 100th call) and never after, and every call from then on says stop. */
static void test_gate(void **state)
{
    (void)state;
    counter c = {.stop_at = STOP_AT};
    tirenv_train_settings s = tirenv_train_default(NULL);
    s.progress = count;
    s.progress_data = &c;
    tirenv_train_progress_gate *g = tirenv_train_progress_gate_alloc(&s);
    assert_non_null(g);
    assert_true(s.progress != count);
    calls_pass p = {.s = &s};
    tirenv_diag diag;
    assert_int_equal(tirenv_parallel_for(ITEMS, 4, call_item, NULL, &p, &diag), TIRENV_OK);
    tirenv_train_progress_gate_free(g);
    assert_false(c.overlap);
    assert_int_equal(c.calls, STOP_AT);
    size_t stops = 0;
    for (size_t k = 0; k < ITEMS; ++k)
        stops += p.stops[k];
    assert_int_equal(stops, ITEMS * CALLS - (STOP_AT - 1));

    /* Settings without a callback are left as they are. */
    s = tirenv_train_default(NULL);
    assert_non_null(g = tirenv_train_progress_gate_alloc(&s));
    assert_null(s.progress);
    assert_null(s.progress_data);
    tirenv_train_progress_gate_free(g);
    tirenv_train_progress_gate_free(NULL);
}

enum { N = 64 };

/* A training's restarts on 2 threads, cancelled at the callback's 5th call: the restarts
 * running and those started after stop at their next epoch, without calling it again. */
static void test_train_cancel(void **state)
{
    (void)state;
    static double x[2][N * 4], y[2][N];
    for (size_t k = 0; k < 2 * N; ++k) {
        const double t = (double)k / (2.0 * N);
        double *xk = &x[k / N][4 * (k % N)];
        xk[0] = t;
        xk[1] = 0.28 + 0.15 * fmod(3.1 * t, 1);
        xk[2] = 0.025 + 0.075 * fmod(5.3 * t, 1);
        xk[3] = 0.05 + 0.25 * fmod(7.7 * t, 1);
        y[k / N][k % N] = xk[2] * sin(3 * t) * (1 + xk[1]);
    }
    const tirenv_samples tr = {.n = N, .n_in = 4, .x = x[0], .y = y[0]};
    const tirenv_samples co = {.n = N, .n_in = 4, .x = x[1], .y = y[1]};
    tirenv_train_settings s = tirenv_train_paper(tirenv_trainer_lm);
    s.restarts = 4;
    s.max_epochs = 200;
    s.patience = 0;
    s.jobs = 2;
    counter c = {.stop_at = 5};
    s.progress = count;
    s.progress_data = &c;
    tirenv_nn *nn = NULL;
    tirenv_train_report rep;
    tirenv_diag diag;
    assert_int_equal(tirenv_train(tirenv_trainer_lm, &s, &tr, &co, NULL, &nn, &rep, &diag),
                     TIRENV_OK);
    assert_non_null(nn);
    assert_false(c.overlap);
    assert_int_equal(c.calls, 5);
    assert_int_equal(rep.stop, TIRENV_TRAIN_CANCELLED);
    tirenv_nn_free(nn);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gate),
        cmocka_unit_test(test_train_cancel),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
