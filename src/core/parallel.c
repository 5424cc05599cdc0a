/* Independent work items on several threads (tirenv/parallel.h): POSIX threads and one lock.
 *
 * Why threads and not OpenMP: the library must not start threads behind an embedder's back
 * nor change with OMP_NUM_THREADS, an embedder's own OpenMP regions must not nest ours, and a
 * static link of libtirenv.a must not need a compiler's runtime (libgomp) on its command
 * line; with glibc 2.34 and later the threads are in libc itself. The work items are coarse
 * (a case of a data set, a restart of a training, a model over a case: milliseconds to
 * seconds), so starting the threads per call costs nothing measurable.
 *
 * Determinism: items are handed out in increasing order, each writes only its own outputs,
 * and the caller combines them in item order afterwards; the only decision made here is which
 * failure to report, and that is the lowest failing item, as in the serial loop.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "tirenv/parallel.h"

#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    size_t n;
    tirenv_parallel_fn fn;
    tirenv_parallel_done_fn done;
    void *ctx;
    pthread_mutex_t lock;
    size_t next;          /* the next item to hand out */
    size_t failed;        /* the lowest failing item so far, or n */
    int status;           /* its status */
    tirenv_diag diag;     /* and its diag */
    size_t n_done;        /* items that succeeded */
} pool;

typedef struct {
    pool *p;
    size_t worker;
} worker_arg;

/* Takes items until none is left or an earlier one failed: an item after a failure would not
 * have run in the serial loop, while every item before it was handed out already (in order)
 * and will finish, so that a still earlier failure is found. */
static void work(pool *p, size_t worker)
{
    tirenv_diag d;
    for (;;) {
        pthread_mutex_lock(&p->lock);
        if (p->next >= p->n || p->next > p->failed) {
            pthread_mutex_unlock(&p->lock);
            return;
        }
        const size_t i = p->next++;
        pthread_mutex_unlock(&p->lock);
        tirenv_diag_clear(&d);
        const int status = p->fn(p->ctx, i, worker, &d);
        pthread_mutex_lock(&p->lock);
        if (status != TIRENV_OK) {
            if (i < p->failed) {
                p->failed = i;
                p->status = status;
                p->diag = d;
            }
        } else if (p->done) {
            p->done(p->ctx, i, ++p->n_done);
        }
        pthread_mutex_unlock(&p->lock);
    }
}

static void *thread_main(void *arg)
{
    const worker_arg *a = arg;
    work(a->p, a->worker);
    return NULL;
}

/* The serial loop itself, on the caller's thread and with the caller's diag. */
static int run_serial(size_t n, tirenv_parallel_fn fn, tirenv_parallel_done_fn done, void *ctx,
                      tirenv_diag *diag)
{
    for (size_t i = 0; i < n; ++i) {
        const int status = fn(ctx, i, 0, diag);
        if (status != TIRENV_OK)
            return status;
        if (done)
            done(ctx, i, i + 1);
    }
    return TIRENV_OK;
}

/* The asynchronous signals a program may handle: delivered to its own thread, never to ours
 * (a handler that cleans up and re-raises then acts for the whole process as it expects). */
static void async_signals(sigset_t *set)
{
    static const int signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT,
                                  SIGPIPE, SIGALRM, SIGUSR1, SIGUSR2};
    sigemptyset(set);
    for (size_t k = 0; k < sizeof signals / sizeof signals[0]; ++k)
        sigaddset(set, signals[k]);
}

int tirenv_parallel_for(size_t n, size_t jobs, tirenv_parallel_fn fn,
                        tirenv_parallel_done_fn done, void *ctx, tirenv_diag *diag)
{
    if (!fn)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "fn", "no work function");
    const size_t threads = jobs < n ? jobs : n;
    if (threads <= 1)
        return run_serial(n, fn, done, ctx, diag);

    pool p = {.n = n, .fn = fn, .done = done, .ctx = ctx, .next = 0, .failed = n,
              .status = TIRENV_OK, .n_done = 0};
    tirenv_diag_clear(&p.diag);
    if (pthread_mutex_init(&p.lock, NULL) != 0)
        return run_serial(n, fn, done, ctx, diag);
    pthread_t *tid = malloc((threads - 1) * sizeof *tid);
    worker_arg *args = malloc((threads - 1) * sizeof *args);
    size_t started = 0;
    if (tid && args) {
        sigset_t block, old;
        async_signals(&block);
        pthread_sigmask(SIG_BLOCK, &block, &old);  /* inherited by the new threads */
        for (size_t w = 1; w < threads; ++w) {
            args[started] = (worker_arg){&p, w};
            if (pthread_create(&tid[started], NULL, thread_main, &args[started]) != 0)
                break;  /* the workers running take its share */
            ++started;
        }
        pthread_sigmask(SIG_SETMASK, &old, NULL);
    }
    work(&p, 0);
    for (size_t k = 0; k < started; ++k)
        pthread_join(tid[k], NULL);
    free(tid);
    free(args);
    pthread_mutex_destroy(&p.lock);
    if (p.status != TIRENV_OK && diag)
        *diag = p.diag;
    return p.status;
}
