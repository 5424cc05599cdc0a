/* Private to tirenv envelope and tirenv predict, which is envelope with the network.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TIRENV_CLI_ENVELOPE_H
#define TIRENV_CLI_ENVELOPE_H

#include "cli/cli.h"

/* How the curve is computed and written, besides the shared options. */
typedef struct {
    int stream;                    /* read the --profile file as the tire rolls */
    int detail;                    /* the ring's tread_max_m and belt_contacts columns */
    tirenv_crg_encoding encoding;  /* -o X.crg: the effective road's encoding */
} cli_envelope_opts;

/* KDBI, no stream, no detail. */
cli_envelope_opts cli_envelope_default(void);

/* The curve of a model of this type over the options' obstacle (its tracks: --track, --tracks)
 * at their load, as CSV to o->output (stdout if NULL), or as the effective road if o->output
 * names a .crg or .rdf file; the summary line starts "tirenv CMD:". Returns an exit code
 * after printing any error. */
int cli_envelope_run(const char *cmd, const cli_options *o, const tirenv_model_type *type,
                     const cli_envelope_opts *e);

/* The help text of -o and --crg-encoding for the commands that write the curve. */
void cli_help_envelope_output(FILE *fp);

#endif
