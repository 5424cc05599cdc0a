/* The signal handler that keeps an interrupted tirenv from leaving temporary files: a
 * killed write leaves the old output and nothing else. SIGKILL cannot be caught: what it
 * leaves is removed by the next run writing into the same directory (src/io/tmpfiles.c).
 * SPDX-License-Identifier: Apache-2.0 */
#include "cli/signals.h"

#include <errno.h>
#include <signal.h>
#include <string.h>
#include <sys/wait.h>

#include "tirenv/outfile.h"

static const int handled[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
enum { N_HANDLED = sizeof handled / sizeof handled[0] };

static volatile sig_atomic_t child;  /* cli_signals_child's */

void cli_signals_child(pid_t pid)
{
    child = (sig_atomic_t)pid;
}

/* Only async-signal-safe calls: kill and waitpid for the child, unlink, getdents64, rmdir,
 * close inside the cleanup, then signal and raise. The signal stays blocked until the
 * handler returns, and is then delivered with the default action: the exit status says what
 * killed the program. */
static void on_signal(int sig)
{
    const int saved = errno;  /* the interrupted code's, should raise return (a blocked sig) */
    const pid_t pid = (pid_t)child;
    if (pid > 0 && kill(pid, SIGTERM) == 0)
        while (waitpid(pid, NULL, 0) < 0 && errno == EINTR)
            ;
    tirenv_cleanup_on_signal();
    signal(sig, SIG_DFL);
    raise(sig);
    errno = saved;
}

void cli_signals_install(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    for (int i = 0; i < N_HANDLED; ++i)  /* no second handler in the middle of the first */
        sigaddset(&sa.sa_mask, handled[i]);
    for (int i = 0; i < N_HANDLED; ++i) {
        struct sigaction old;
        /* A signal ignored on entry (nohup, a shell's background job) stays ignored. */
        if (sigaction(handled[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
            continue;
        sigaction(handled[i], &sa, NULL);
    }
}
