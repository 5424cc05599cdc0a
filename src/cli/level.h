/* Private to the commands that write h: the road's local level (tirenv_profile_level,
 * docs/models.md section 2.6) along a sweep, over a whole profile or one read as it goes.
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

/* The level segment's length for a tire: its free diameter 2*R0 (m). */
double cli_level_width(const tirenv_tire *tire);

/* The level along a sweep in x order, its vertices taken from a source as the sweep needs
 * them (the whole profile never held): a window of the vertices within width of x, rebuilt
 * every few widths of travel, as tirenv_model_stream's. */
typedef struct cli_level_stream cli_level_stream;

cli_level_stream *cli_level_stream_alloc(tirenv_vertex_source source, void *ctx, double width);
void cli_level_stream_free(cli_level_stream *s);  /* NULL is a no-op */
/* The level at x (m), x not below the last call's; the source's errors pass through. */
int cli_level_stream_at(cli_level_stream *s, double x, double *level, tirenv_diag *diag);

#endif
