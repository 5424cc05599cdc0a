/* The effective road's options: which -o names a road file, --crg-encoding (the writer is the
 * library's tirenv_road_writer). SPDX-License-Identifier: Apache-2.0 */
#include <string.h>
#include <strings.h>

#include "cli/road_out.h"

int cli_road_out_wanted(const char *path, tirenv_profile_format *f)
{
    return path && strcmp(path, "-") != 0 && tirenv_profile_format_of_name(path, f) == 0 &&
           *f != TIRENV_PROFILE_CSV;
}

int cli_parse_crg_encoding(void *dst, const char *arg)
{
    if (tirenv_crg_encoding_find(arg, dst)) {
        cli_error("--crg-encoding: expected kdbi, krbi, ldfi or lrfi, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}
