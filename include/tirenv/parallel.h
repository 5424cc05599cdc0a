/* tirenv: independent work items on several threads. The library starts a thread nowhere
 * else, and here only when a caller asks for more than one job: every settings struct that
 * parallelises (tirenv_dataset_build_settings, tirenv_fit_settings, tirenv_train_settings,
 * tirenv_compare_settings, tirenv_study_settings, tirenv_sweep_settings) has a `jobs` field
 * whose default is 1, which runs everything on the caller's thread as before.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_PARALLEL_H
#define TIRENV_PARALLEL_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"

TIRENV_BEGIN_DECLS

/* One work item: item in [0, n), worker in [0, jobs) names the thread running it (0 is the
 * caller's), so that a caller can keep one workspace per worker (a model instance is not
 * thread-safe: one per worker). Returns TIRENV_OK or a status with the reason in diag (a
 * diag of the worker's own). */
typedef int (*tirenv_parallel_fn)(void *ctx, size_t item, size_t worker, tirenv_diag *diag);

/* Called after each item that succeeded, with how many have succeeded so far; the calls
 * never overlap (they are made under a lock), but come from any worker and in any order. */
typedef void (*tirenv_parallel_done_fn)(void *ctx, size_t item, size_t n_done);

/* Runs fn for the items 0 .. n-1 on min(jobs, n) threads: the caller's thread and up to
 * jobs - 1 new ones, which end before this returns. Items are handed out in increasing order
 * as workers become free. jobs 0 is taken as 1; with jobs 1 (or n <= 1) no thread is started
 * and the items run in order on the caller's thread, stopping at the first failure.
 * Results are what the loop `for (i = 0; i < n; ++i) if ((s = fn(i))) return s;` gives, for
 * any jobs, provided each item writes only its own outputs (and per-worker scratch) and its
 * result does not depend on what ran before it in the same worker: when items fail, the one
 * with the lowest index is reported (its status, its diag copied into diag), and no item
 * after it is started. An item may call tirenv_parallel_for again: the inner call shares the
 * outer call's budget, so that at most the outer `jobs` threads run items at any moment
 * (the inner call's threads wait for a turn, using no processor). The new threads block
 * SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGALRM, SIGUSR1 and SIGUSR2, so that a
 * program's handlers for them run on its own thread. If a thread cannot be started the
 * others do its share. done may be NULL. */
int tirenv_parallel_for(size_t n, size_t jobs, tirenv_parallel_fn fn,
                        tirenv_parallel_done_fn done, void *ctx, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
