/* --relative-to for the commands that write h: what h_m is measured from.
 * SPDX-License-Identifier: Apache-2.0 */
#include <string.h>

#include "cli/level.h"

int cli_parse_relative_to(void *dst, const char *arg)
{
    cli_relative_to *r = dst;
    if (strcmp(arg, "datum") == 0) {
        *r = CLI_RELATIVE_DATUM;
    } else if (strcmp(arg, "ground") == 0) {
        *r = CLI_RELATIVE_GROUND;
    } else {
        cli_error("--relative-to expects ground or datum, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

void cli_help_relative_to(FILE *fp)
{
    fputs("  --relative-to R      what h_m is measured from: datum (default), the profile's\n"
          "                       z = 0, so that h is the effective road's own height, grade\n"
          "                       and elevation included, as a vehicle model driving on it\n"
          "                       needs; or ground, the road's local level under the centre\n"
          "                       (the opening of the ground by a level segment as long as\n"
          "                       the tire's diameter, docs/models.md section 2.6), which\n"
          "                       takes grade and long undulations out and leaves what the\n"
          "                       tire makes of obstacles, as the paper's h; the same on\n"
          "                       level ground at 0. z_m stays the centre's height\n",
          fp);
}
