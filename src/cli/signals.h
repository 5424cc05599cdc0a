/* Private to the tirenv command-line tool: what a signal that ends the program cleans up.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CLI_SIGNALS_H
#define TIRENV_CLI_SIGNALS_H

/* On SIGINT, SIGTERM, SIGHUP and SIGPIPE (those not ignored when tirenv starts): remove the
 * temporary files and staging directories of the outputs being written
 * (tirenv_cleanup_on_signal), then die of the same signal, as without the handler. */
void cli_signals_install(void);

#endif
