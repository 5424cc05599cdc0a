/* Private to the commands that write an effective road (tirenv envelope -o X.crg|X.rdf): the
 * hub's effective height h along x as a road file that a point-contact tire in another tool
 * can drive on. SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CLI_ROAD_OUT_H
#define TIRENV_CLI_ROAD_OUT_H

#include "cli/cli.h"

/* Whether path names a road file to write the effective road to (.crg or .rdf, any case), and
 * which; a CSV (or '-') is the curve itself, written by the command. */
int cli_road_out_wanted(const char *path, tirenv_profile_format *f);

/* --crg-encoding kdbi|krbi|ldfi|lrfi, for a command's own option table (dst:
 * tirenv_crg_encoding). */
int cli_parse_crg_encoding(void *dst, const char *arg);

/* What the file says and how it is laid out. */
typedef struct {
    double x_from, dx;           /* the positions x_k = x_from + k*dx, m */
    size_t n;                    /* how many */
    double half_width;           /* .crg: long sections at v = v_track -+ half_width, m */
    double v_track;              /* .crg: the track's lateral position on the input road, m */
    double x_start, y_start;     /* .crg: the reference line at x_from in the x/y plane, m */
    double phi_start;            /* .crg: its heading, rad */
    double z_start;              /* .crg: the road's height at x_from on the track, m */
    tirenv_crg_encoding encoding;/* .crg */
    const char *comment;         /* what it is, lines of at most 72 characters */
} cli_road_out_layout;

typedef struct cli_road_out cli_road_out;

/* Where the effective road of the road file path (read at lateral position v) goes: an
 * OpenCRG road's straight reference line at u = x_from, its heading, and v, into the layout
 * (0 for a road of another format: the reference line is x itself). A curved OpenCRG road
 * (a heading channel) is refused: its effective road written on a straight line would lie
 * beside the road. */
int cli_road_out_place(const char *path, tirenv_profile_format format, double v,
                       cli_road_out_layout *l, tirenv_diag *diag);

/* Opens path (format f) for the n positions of the layout. */
int cli_road_out_open(const char *path, tirenv_profile_format f, const cli_road_out_layout *l,
                      cli_road_out **out, tirenv_diag *diag);
/* The next position's point, in order: its h becomes the road's height at its x. */
int cli_road_out_add(cli_road_out *w, const tirenv_point *pt, tirenv_diag *diag);
/* Checks that all n came and puts the file in place (all or nothing); frees w. */
int cli_road_out_commit(cli_road_out *w, tirenv_diag *diag);
/* Removes what was written and frees w; NULL is a no-op. */
void cli_road_out_abort(cli_road_out *w);

#endif
