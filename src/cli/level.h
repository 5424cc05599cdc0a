/* Private to the commands that write h: --relative-to, what h is measured from (the road's
 * local level is the library's: tirenv_profile_level, tirenv_level_stream).
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CLI_LEVEL_H
#define TIRENV_CLI_LEVEL_H

#include "cli/cli.h"

/* What h is relative to (--relative-to). */
typedef enum {
    CLI_RELATIVE_DATUM = 0, /* the profile's z = 0 (default): h as the models compute it */
    CLI_RELATIVE_GROUND     /* the road's local level under the centre */
} cli_relative_to;

/* --relative-to ground|datum, for a command's own option table (dst: cli_relative_to). */
int cli_parse_relative_to(void *dst, const char *arg);

/* The help text of --relative-to, indented for a usage message. */
void cli_help_relative_to(FILE *fp);

#endif
