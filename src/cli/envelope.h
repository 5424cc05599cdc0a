/* Private to tirenv envelope and tirenv predict, which is envelope with the network.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TIRENV_CLI_ENVELOPE_H
#define TIRENV_CLI_ENVELOPE_H

#include "cli/cli.h"

/* The curve of a model of this type over the options' obstacle at their load, as CSV to
 * o->output (stdout if NULL), streamed from the --profile file if stream, with the ring's
 * tread_max_m and belt_contacts columns if detail; the summary line starts "tirenv CMD:".
 * Returns an exit code after printing any error. */
int cli_envelope_run(const char *cmd, const cli_options *o, const tirenv_model_type *type,
                     int stream, int detail);

#endif
