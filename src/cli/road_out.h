/* Private to the commands that write an effective road (tirenv envelope -o X.crg|X.rdf): the
 * hub's effective height h along x as a road file that a point-contact tire in another tool
 * can drive on, written by the library's tirenv_road_writer (profile_file.h).
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CLI_ROAD_OUT_H
#define TIRENV_CLI_ROAD_OUT_H

#include "cli/cli.h"

/* Whether path names a road file to write the effective road to (.crg or .rdf, any case), and
 * which; a CSV (or '-') is the curve itself, written by the command. */
int cli_road_out_wanted(const char *path, tirenv_profile_format *f);

/* --crg-encoding kdbi|krbi|ldfi|lrfi, for a command's own option table (dst:
 * tirenv_crg_encoding). */
int cli_parse_crg_encoding(void *dst, const char *arg);

#endif
