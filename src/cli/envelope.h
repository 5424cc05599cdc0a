/* Private to tirenv envelope and tirenv predict, which is envelope with the network.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CLI_ENVELOPE_H
#define TIRENV_CLI_ENVELOPE_H

#include "cli/cli.h"
#include "cli/level.h"
#include "cli/road_out.h"

/* How the curve is computed and written, besides the shared options. */
typedef struct {
    int stream;                    /* read the --profile file as the tire rolls */
    int detail;                    /* the ring's tread_max_m and belt_contacts columns */
    tirenv_crg_encoding encoding;  /* -o X.crg: the effective road's encoding */
    int have_encoding;             /* --crg-encoding given (refused without -o X.crg) */
    cli_relative_to relative;      /* h relative to the datum or to the road's local level */
    const char *plot;              /* --plot FILE.png (envelope's), or NULL */
} cli_envelope_opts;

/* Parses the options of tirenv CMD ("envelope", or "predict", which has no --stream and no
 * --detail) into *o and *e, its defaults KDBI, no stream, no detail, relative to the datum;
 * returns cli_parse's code. */
int cli_envelope_parse(const char *cmd, void (*usage)(FILE *fp), int argc, char *argv[],
                       cli_options *o, cli_envelope_opts *e);

/* The curve of a model of this type over the options' obstacle (its tracks: --track, --tracks)
 * at their load, as CSV to o->output (stdout if NULL), or as the effective road if o->output
 * names a .crg or .rdf file; the summary line starts "tirenv CMD:". Returns an exit code
 * after printing any error. */
int cli_envelope_run(const char *cmd, const cli_options *o, const tirenv_model_type *type,
                     const cli_envelope_opts *e);

/* The help text of -o and --crg-encoding for the commands that write the curve. */
void cli_help_envelope_output(FILE *fp);

#endif
