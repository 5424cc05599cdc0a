/* Independent work items on several threads (tirenv/parallel.h): POSIX threads, one lock and
 * a budget of running threads shared by nested calls.
 *
 * Why threads and not OpenMP: the library must not start threads behind an embedder's back
 * nor change with OMP_NUM_THREADS, an embedder's own OpenMP regions must not nest ours, and a
 * static link of libtirenv.a must not need a compiler's runtime (libgomp) on its command
 * line; with glibc 2.34 and later the threads are in libc itself. The work items are coarse
 * (a case of a data set, a restart of a training, a model over a case: milliseconds to
 * seconds), so starting the threads per call costs nothing measurable.
 *
 * The budget (a jobserver, as make's): the outermost call of a thread that runs no item has
 * `jobs` tokens, one of them the caller's own. Every thread it starts takes a token before
 * each item and gives it back after, so that at most `jobs` threads run items at once. An item
 * that calls tirenv_parallel_for again (a study running its comparisons side by side, each
 * with cases of its own) shares that budget: the caller keeps its token and works on the
 * inner items, and the inner threads wait for tokens the others give back. A caller with no
 * item left to take gives its token back while it waits for the items running, and takes
 * one again before it goes on. Waiting threads use no processor, and leave as soon as their
 * call has no item left.
 *
 * Determinism: items are handed out in increasing order, each writes only its own outputs,
 * and the caller combines them in item order afterwards; the only decision made here is which
 * failure to report, and that is the lowest failing item, as in the serial loop.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/parallel.h"

#include <locale.h>
#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>

/* The budget of an outermost call, shared by the calls nested in its items. Its lock also
 * guards every pool that draws on it. */
typedef struct {
    pthread_mutex_t lock;
    pthread_cond_t cond;  /* a token came back, or a pool ran out of items */
    size_t free;          /* tokens not held */
} jobserver;

/* The budget the calling thread draws on while it runs an item, or NULL. */
static _Thread_local jobserver *current;

typedef struct {
    jobserver *js;
    size_t n;
    tirenv_parallel_fn fn;
    tirenv_parallel_done_fn done;
    void *ctx;
    size_t next;          /* the next item to hand out */
    size_t failed;        /* the lowest failing item so far, or n */
    int status;           /* its status */
    tirenv_diag diag;     /* and its diag */
    size_t n_done;        /* items that succeeded */
    locale_t locale;      /* the caller's thread's locale, which its items run in */
} pool;

typedef struct {
    pool *p;
    size_t worker;
} worker_arg;

/* Items are left to hand out: none after a failure, which would not have run in the serial
 * loop, while every item before it was handed out already (in order) and will finish, so
 * that a still earlier failure is found. Under js->lock. */
static int has_work(const pool *p)
{
    return p->next < p->n && p->next <= p->failed;
}

/* Runs item i and records what came of it. Called without the lock. */
static void run_item(pool *p, size_t i, size_t worker, tirenv_diag *d)
{
    tirenv_diag_clear(d);
    jobserver *const outer = current;
    current = p->js;
    const int status = p->fn(p->ctx, i, worker, d);
    current = outer;
    pthread_mutex_lock(&p->js->lock);
    if (status != TIRENV_OK) {
        if (i < p->failed) {
            p->failed = i;
            p->status = status;
            p->diag = *d;
        }
        pthread_cond_broadcast(&p->js->cond);  /* waiting threads of this pool may leave */
    } else if (p->done) {
        p->done(p->ctx, i, ++p->n_done);
    }
    pthread_mutex_unlock(&p->js->lock);
}

/* The caller's share: it holds its token already. */
static void work_as_caller(pool *p)
{
    tirenv_diag d;
    for (;;) {
        pthread_mutex_lock(&p->js->lock);
        if (!has_work(p)) {
            pthread_cond_broadcast(&p->js->cond);
            pthread_mutex_unlock(&p->js->lock);
            return;
        }
        const size_t i = p->next++;
        pthread_mutex_unlock(&p->js->lock);
        run_item(p, i, 0, &d);
    }
}

/* A started thread's share: a token for each item. */
static void *thread_main(void *arg)
{
    const worker_arg *a = arg;
    pool *p = a->p;
    jobserver *js = p->js;
    /* As the caller's share runs: a file a work item writes keeps the '.' the caller's entry
     * chose for its numbers (the auxiliary layer's "C" locale), whatever the process's. */
    uselocale(p->locale);
    tirenv_diag d;
    for (;;) {
        pthread_mutex_lock(&js->lock);
        while (js->free == 0 && has_work(p))
            pthread_cond_wait(&js->cond, &js->lock);
        if (!has_work(p)) {
            pthread_mutex_unlock(&js->lock);
            return NULL;
        }
        --js->free;
        const size_t i = p->next++;
        pthread_mutex_unlock(&js->lock);
        run_item(p, i, a->worker, &d);
        pthread_mutex_lock(&js->lock);
        ++js->free;
        pthread_cond_broadcast(&js->cond);
        pthread_mutex_unlock(&js->lock);
    }
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

    /* The budget: the one this thread's item draws on, or a new one of `jobs` tokens, the
     * caller's among them. */
    jobserver own, *js = current;
    if (!js) {
        js = &own;
        own.free = jobs - 1;
        if (pthread_mutex_init(&own.lock, NULL) != 0)
            return run_serial(n, fn, done, ctx, diag);
        if (pthread_cond_init(&own.cond, NULL) != 0) {
            pthread_mutex_destroy(&own.lock);
            return run_serial(n, fn, done, ctx, diag);
        }
    }
    pool p = {.js = js, .n = n, .fn = fn, .done = done, .ctx = ctx, .next = 0, .failed = n,
              .status = TIRENV_OK, .n_done = 0, .locale = uselocale((locale_t)0)};
    tirenv_diag_clear(&p.diag);
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
    work_as_caller(&p);
    /* No item left to take: while the items running end, the caller's token works for the
     * others (the rest of an outer call, or another call sharing the budget); it is taken
     * back before the caller goes on. */
    pthread_mutex_lock(&js->lock);
    ++js->free;
    pthread_cond_broadcast(&js->cond);
    pthread_mutex_unlock(&js->lock);
    for (size_t k = 0; k < started; ++k)
        pthread_join(tid[k], NULL);
    pthread_mutex_lock(&js->lock);
    while (js->free == 0)
        pthread_cond_wait(&js->cond, &js->lock);
    --js->free;
    pthread_mutex_unlock(&js->lock);
    free(tid);
    free(args);
    if (js == &own) {
        pthread_cond_destroy(&own.cond);
        pthread_mutex_destroy(&own.lock);
    }
    if (p.status != TIRENV_OK && diag)
        *diag = p.diag;
    return p.status;
}
