/* tirenv_parallel_for (tirenv/parallel.h): every item once, the serial loop's failure whatever
 * the number of threads, done calls that never overlap, no thread for one job, signals left
 * to the caller's thread. SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/model.h"
#include "tirenv/parallel.h"

#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { N_ITEMS = 331 };

typedef struct {
    size_t n;
    size_t jobs;
    int *runs;               /* times each item ran */
    double *out;             /* each item's result */
    size_t *worker;          /* which worker ran it */
    size_t fail_from;        /* items >= this with (i % 3 == 1) fail; n: none */
    pthread_t caller;
    int *on_caller;          /* 1 if item ran on the calling thread */
    int in_done;             /* a done call in progress (must never overlap) */
    int overlap;
    size_t done_calls, last_done;
    int signals_blocked_ok;  /* every new thread blocks SIGINT and SIGTERM */
    int *started;            /* 1 once item i has recorded its worker */
} ctx_t;

/* Some arithmetic whose cost varies by item, so that workers interleave. */
static double busy(size_t i)
{
    double x = (double)i + 0.5;
    for (size_t k = 0; k < 2000 + 370 * (i % 11); ++k)
        x = x * 0.999 + 1.0 / (x + 1.0);
    return x;
}

static int item(void *vctx, size_t i, size_t worker, tirenv_diag *diag)
{
    ctx_t *c = vctx;
    __atomic_add_fetch(&c->runs[i], 1, __ATOMIC_RELAXED);
    c->out[i] = busy(i);
    c->worker[i] = worker;
    c->on_caller[i] = pthread_equal(pthread_self(), c->caller) != 0;
    __atomic_store_n(&c->started[i], 1, __ATOMIC_RELEASE);
    /* Item 0 waits (up to 10 s) until another worker has taken an item, so that even on a
     * loaded machine the threads are seen to share the work. */
    for (int k = 0; i == 0 && c->jobs > 1 && k < 10000; ++k) {
        int other = 0;
        for (size_t j = 1; j < c->n && !other; ++j)
            other = __atomic_load_n(&c->started[j], __ATOMIC_ACQUIRE) && c->worker[j] != worker;
        if (other)
            break;
        struct timespec ts = {0, 1000000};
        nanosleep(&ts, NULL);
    }
    if (!c->on_caller[i]) {
        sigset_t now;
        pthread_sigmask(SIG_BLOCK, NULL, &now);
        if (!sigismember(&now, SIGINT) || !sigismember(&now, SIGTERM))
            c->signals_blocked_ok = 0;
    }
    if (i >= c->fail_from && i % 3 == 1)
        return tirenv_error(diag, TIRENV_ERANGE, "item", i, "field", "item %zu failed", i);
    return TIRENV_OK;
}

static void done(void *vctx, size_t i, size_t n_done)
{
    ctx_t *c = vctx;
    (void)i;
    if (c->in_done)
        c->overlap = 1;
    c->in_done = 1;
    if (n_done % 64 == 0) {  /* now and then, widen the window an overlap would need */
        struct timespec ts = {0, 1000};
        nanosleep(&ts, NULL);
    }
    if (n_done != c->last_done + 1)
        c->overlap = 1;
    c->last_done = n_done;
    ++c->done_calls;
    c->in_done = 0;
}

static void ctx_init(ctx_t *c, size_t n, size_t jobs, size_t fail_from)
{
    memset(c, 0, sizeof *c);
    c->n = n;
    c->jobs = jobs;
    c->runs = calloc(n + 1, sizeof *c->runs);
    c->out = calloc(n + 1, sizeof *c->out);
    c->worker = calloc(n + 1, sizeof *c->worker);
    c->on_caller = calloc(n + 1, sizeof *c->on_caller);
    c->started = calloc(n + 1, sizeof *c->started);
    assert_non_null(c->started);
    assert_non_null(c->runs);
    assert_non_null(c->out);
    assert_non_null(c->worker);
    assert_non_null(c->on_caller);
    c->fail_from = fail_from;
    c->caller = pthread_self();
    c->signals_blocked_ok = 1;
}

static void ctx_free(ctx_t *c)
{
    free(c->runs);
    free(c->out);
    free(c->worker);
    free(c->on_caller);
    free(c->started);
}

/* Every item exactly once, results in their own slots, identical for 1, 2, 3 and 8 jobs. */
static void test_every_item_once(void **state)
{
    (void)state;
    ctx_t serial;
    ctx_init(&serial, N_ITEMS, 1, N_ITEMS);
    tirenv_diag d;
    tirenv_diag_clear(&d);
    assert_int_equal(tirenv_parallel_for(N_ITEMS, 1, item, done, &serial, &d), TIRENV_OK);
    for (size_t i = 0; i < N_ITEMS; ++i) {
        assert_int_equal(serial.runs[i], 1);
        assert_true(serial.on_caller[i]);
        assert_int_equal(serial.worker[i], 0);
    }
    assert_int_equal(serial.done_calls, N_ITEMS);
    const size_t jobs[] = {2, 3, 8};
    for (size_t k = 0; k < sizeof jobs / sizeof jobs[0]; ++k) {
        ctx_t c;
        ctx_init(&c, N_ITEMS, jobs[k], N_ITEMS);
        assert_int_equal(tirenv_parallel_for(N_ITEMS, jobs[k], item, done, &c, &d), TIRENV_OK);
        size_t others = 0;
        for (size_t i = 0; i < N_ITEMS; ++i) {
            assert_int_equal(c.runs[i], 1);
            assert_bits_equal(c.out[i], serial.out[i]);
            assert_true(c.worker[i] < jobs[k]);
            assert_int_equal(c.worker[i] == 0, c.on_caller[i]);
            others += !c.on_caller[i];
        }
        assert_true(others > 0);  /* the new threads did take items */
        assert_int_equal(c.done_calls, N_ITEMS);
        assert_false(c.overlap);
        assert_true(c.signals_blocked_ok);
        ctx_free(&c);
    }
    ctx_free(&serial);
}

/* The failure reported is the serial loop's: the lowest failing item, with its message, and
 * nothing after it started in the serial run. */
static void test_lowest_failure(void **state)
{
    (void)state;
    const size_t fail_from[] = {0, 5, 200, N_ITEMS - 4};
    for (size_t f = 0; f < sizeof fail_from / sizeof fail_from[0]; ++f) {
        size_t first = fail_from[f];
        while (first % 3 != 1)
            ++first;
        for (size_t jobs = 1; jobs <= 4; ++jobs) {
            ctx_t c;
            ctx_init(&c, N_ITEMS, jobs, fail_from[f]);
            tirenv_diag d;
            tirenv_diag_clear(&d);
            assert_int_equal(tirenv_parallel_for(N_ITEMS, jobs, item, NULL, &c, &d),
                             TIRENV_ERANGE);
            char expect[64];
            snprintf(expect, sizeof expect, "item %zu failed", first);
            assert_string_equal(d.message, expect);
            assert_int_equal(d.line, first);
            assert_string_equal(d.field, "field");
            for (size_t i = 0; i <= first; ++i)
                assert_int_equal(c.runs[i], 1);  /* all before it ran */
            if (jobs == 1)
                for (size_t i = first + 1; i < N_ITEMS; ++i)
                    assert_int_equal(c.runs[i], 0);
            ctx_free(&c);
        }
    }
}

/* No items, one item, jobs 0 (taken as 1): the caller's thread, in order. */
static void test_small(void **state)
{
    (void)state;
    ctx_t c;
    ctx_init(&c, 1, 0, 1);
    tirenv_diag d;
    tirenv_diag_clear(&d);
    assert_int_equal(tirenv_parallel_for(0, 4, item, done, &c, &d), TIRENV_OK);
    assert_int_equal(c.done_calls, 0);
    assert_int_equal(tirenv_parallel_for(1, 4, item, done, &c, &d), TIRENV_OK);
    assert_int_equal(c.runs[0], 1);
    assert_true(c.on_caller[0]);
    ctx_free(&c);
    ctx_init(&c, 50, 0, 50);
    assert_int_equal(tirenv_parallel_for(50, 0, item, done, &c, &d), TIRENV_OK);
    for (size_t i = 0; i < 50; ++i)
        assert_true(c.on_caller[i]);
    ctx_free(&c);
    assert_int_equal(tirenv_parallel_for(3, 2, NULL, NULL, NULL, &d), TIRENV_EINVAL);
}

/* Nested calls share the outer budget: with 3 jobs outside and 3 inside each item, never
 * more than 3 threads run inner items at once, and every inner item runs once. */
typedef struct {
    int running, max_running;
    int runs[6][40];
    double out[6][40];
} nested_ctx;

typedef struct {
    nested_ctx *c;
    size_t outer;
} inner_arg;

static int inner_item(void *vctx, size_t i, size_t worker, tirenv_diag *diag)
{
    const inner_arg *a = vctx;
    (void)worker;
    (void)diag;
    const int now = __atomic_add_fetch(&a->c->running, 1, __ATOMIC_SEQ_CST);
    int seen = __atomic_load_n(&a->c->max_running, __ATOMIC_SEQ_CST);
    while (now > seen &&
           !__atomic_compare_exchange_n(&a->c->max_running, &seen, now, 0, __ATOMIC_SEQ_CST,
                                        __ATOMIC_SEQ_CST))
        ;
    a->c->out[a->outer][i] = busy(i + 40 * a->outer);
    __atomic_add_fetch(&a->c->runs[a->outer][i], 1, __ATOMIC_SEQ_CST);
    __atomic_sub_fetch(&a->c->running, 1, __ATOMIC_SEQ_CST);
    return TIRENV_OK;
}

static int outer_item(void *vctx, size_t i, size_t worker, tirenv_diag *diag)
{
    inner_arg a = {vctx, i};
    (void)worker;
    return tirenv_parallel_for(40, 3, inner_item, NULL, &a, diag);
}

static void test_nested_budget(void **state)
{
    (void)state;
    nested_ctx *c = calloc(1, sizeof *c);
    assert_non_null(c);
    tirenv_diag d;
    tirenv_diag_clear(&d);
    assert_int_equal(tirenv_parallel_for(6, 3, outer_item, NULL, c, &d), TIRENV_OK);
    for (size_t o = 0; o < 6; ++o)
        for (size_t i = 0; i < 40; ++i) {
            assert_int_equal(c->runs[o][i], 1);
            assert_bits_equal(c->out[o][i], busy(i + 40 * o));
        }
    assert_true(c->max_running >= 1 && c->max_running <= 3);
    free(c);
}

/* The model table (tirenv_model_types, tirenv_model_type_find) looked up from several threads
 * at once: the same answers on each, and, in the ThreadSanitizer build, no data race (the
 * table was written on every call). */
static pthread_barrier_t lookup_start;
static void *lookup(void *arg)
{
    int *ok = arg;
    pthread_barrier_wait(&lookup_start);
    *ok = 1;
    for (int k = 0; k < 200; ++k) {
        const tirenv_model_type *const *t = tirenv_model_types();
        *ok &= t[0] == tirenv_model_rigid && tirenv_model_type_find("ring") == tirenv_model_ring &&
               tirenv_model_type_find("point") == tirenv_model_point;
    }
    return NULL;
}

static void test_model_table_threads(void **state)
{
    (void)state;
    enum { N = 4 };
    pthread_t th[N];
    int ok[N] = {0};
    assert_int_equal(pthread_barrier_init(&lookup_start, NULL, N), 0);
    for (int i = 0; i < N; ++i)
        assert_int_equal(pthread_create(&th[i], NULL, lookup, &ok[i]), 0);
    for (int i = 0; i < N; ++i) {
        pthread_join(th[i], NULL);
        assert_int_equal(ok[i], 1);
    }
    pthread_barrier_destroy(&lookup_start);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_item_once),
        cmocka_unit_test(test_lowest_failure),
        cmocka_unit_test(test_small),
        cmocka_unit_test(test_nested_budget),
        cmocka_unit_test(test_model_table_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
