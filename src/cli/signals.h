/* Private to the tirenv command-line tool: what a signal that ends the program cleans up.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CLI_SIGNALS_H
#define TIRENV_CLI_SIGNALS_H

#include <sys/types.h>

/* On SIGINT, SIGTERM, SIGHUP and SIGPIPE (those not ignored when tirenv starts): remove the
 * temporary files and staging directories of the outputs being written
 * (tirenv_cleanup_on_signal), then die of the same signal, as without the handler. */
void cli_signals_install(void);

/* The child process the program is waiting for (0: none), which such a signal ends first:
 * sent SIGTERM (its own handler removes its temporary files) and reaped, before this
 * program's temporaries are removed, so that the child writes nothing into them after. */
void cli_signals_child(pid_t pid);

#endif
